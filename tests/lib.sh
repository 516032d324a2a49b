# Shared helpers for shell test suites: check/ok/bad count results, and
# report prints "NAME: N passed, N failed" and sets the exit status.
PASSED=0
FAILED=0
BUILD=${BUILD:-build}
FXRT=${FXRT:-$BUILD/fxrt}
# Firmware built by the tests carries no debug information (firmware.mk).
export FW_DEBUG=${FW_DEBUG-}
# Capacities for compiling the whole core for a bare board in the suites
# that read its code (norecurse.sh, freestanding.sh): the kinds a bare
# board leaves out by default (fxrt_config.h) are compiled in, so that
# their code, the mesh walk among it, is checked too.
BARE_ALL_KINDS=(-DFXRT_MAX_MODELS=4 -DFXRT_MAX_ELLIPSOIDS=4 -DFXRT_MAX_PARALLELEPIPEDS=4)

ok() { PASSED=$((PASSED + 1)); }
bad() {
    FAILED=$((FAILED + 1))
    echo "FAIL: $*" >&2
}
# check DESCRIPTION COMMAND...: passes when the command exits 0.
check() {
    local desc=$1
    shift
    if "$@"; then ok; else bad "$desc"; fi
}
# progress MESSAGE: one line on the terminal while the suite runs, when
# tests/run.sh passes a progress fd (PROGRESS_FD); silent otherwise.
progress() {
    [ -n "${PROGRESS_FD:-}" ] && { echo "  $*" >&"$PROGRESS_FD"; } 2>/dev/null
    return 0
}
report() {
    echo "$1: $PASSED passed, $FAILED failed"
    [ "$FAILED" -eq 0 ]
}
# generated GENERATOR OUT: the files GENERATOR writes into OUT are the
# committed ones beside it (one check per file; the generator's own
# failure is one failed check).
generated() {
    local gen=$1 dir f
    dir=$(dirname "$gen")
    if "$gen" "$2" 2>"$2.err"; then
        ok
        for f in "$2"/*; do
            check "$dir/$(basename "$f") equals $gen output" cmp -s "$f" "$dir/$(basename "$f")"
        done
    else
        bad "$gen failed: $(cat "$2.err")"
    fi
}
# full: true under make test-full (FXRT_TEST_FULL=1). make test runs each
# suite's quick scope; a suite puts its long sweeps behind `if full`.
full() { [ "${FXRT_TEST_FULL:-0}" = 1 ]; }
# scope FULL QUICK: prints FULL under make test-full, QUICK under make test.
scope() { if full; then echo "$1"; else echo "$2"; fi; }
# cfg_read FILE: each "#define NAME N" line of a generated header (N a
# decimal integer) becomes the variable CFG_NAME; earlier CFG_ variables
# are unset first. Bash builtins only: process start-up is the dearest
# part of these scripts (a sed per value cost qemu.sh thousands of them).
cfg_read() {
    local def k v
    unset "${!CFG_@}"
    while read -r def k v; do
        if [[ $def == "#define" && $v =~ ^[0-9]+$ ]]; then printf -v "CFG_$k" '%s' "$v"; fi
    done <"$1"
    return 0
}
# cfg_value FILE NAME: prints CFG_NAME of FILE (empty when not defined).
cfg_value() {
    cfg_read "$1"
    local v=CFG_$2
    echo "${!v:-}"
}
