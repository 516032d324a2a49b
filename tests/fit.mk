# tests/fit.sh: the bench scenes (generator output, host renders) and the
# firmware fit check (firmware/fit.sh) on the micro:bit. Included by the
# top Makefile.
SUITES_EXTRA += tests/fit.sh
