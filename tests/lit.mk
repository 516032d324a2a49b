# The lit scenes' accuracy suite (tests/lit.sh; issue 11): every scene of
# scenes/lit/ at 640x480 in double, Q16.16 and float, Q16.16 against double
# asserted, float reported. Included by the top Makefile.
#
#   make lit        run tests/lit.sh alone (through tests/run.sh)
#
# Part of `make test` (SUITES_EXTRA below).

lit: deps $(BUILD)/fxrt
	$(Q)BUILD=$(BUILD) tests/run.sh tests/lit.sh

.PHONY: lit
SUITES_EXTRA += tests/lit.sh

# The node and mesh scenes (scenes/nodes/) through the same checks with the
# mesh issue's accuracy figures: tests/nodes.sh.
#
#   make nodes      run tests/nodes.sh alone
nodes: deps $(BUILD)/fxrt
	$(Q)BUILD=$(BUILD) tests/run.sh tests/nodes.sh

.PHONY: nodes
SUITES_EXTRA += tests/nodes.sh
