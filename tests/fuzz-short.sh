#!/usr/bin/env bash
# Short fuzzing run for make test: `make fuzz-scene` (libFuzzer over
# scene_parse, tests/fuzz_scene.c) for FUZZ_CI_SECONDS (default 10), and
# `make fuzz-kernels` for the same time under make test-full. A run
# passes when the fuzzer stops at its time limit without a crash, timeout,
# leak or sanitizer report; the make targets print the executions and the
# artifacts ($BUILD/fuzz/) of a failure. The corpus in $BUILD/fuzz/ is kept
# between runs, so coverage accumulates.
set -u
. "$(dirname "$0")/lib.sh"
FUZZ_CI_SECONDS=${FUZZ_CI_SECONDS:-10}
MAKE=${MAKE:-make}
# Under make -jN the parent's jobserver is not passed to this script; drop
# it from MAKEFLAGS so the sub-make does not warn about it.
if [ -n "${MAKEFLAGS:-}" ]; then
    MAKEFLAGS=$(sed -E 's/ ?--jobserver-(auth|fds)=[^ ]*//g' <<<"$MAKEFLAGS")
    export MAKEFLAGS
fi
logdir=$BUILD/fuzz
mkdir -p "$logdir"

# fuzz TARGET: run `make TARGET` for FUZZ_CI_SECONDS, show its summary.
fuzz() {
    local target=$1 log=$logdir/$1-short.log rc
    $MAKE --no-print-directory "$target" BUILD="$BUILD" FUZZ_SECONDS="$FUZZ_CI_SECONDS" >"$log" 2>&1
    rc=$?
    if [ $rc -eq 0 ]; then
        ok
        grep -iE 'exec' "$log" | tail -n 5
        grep -iqE 'exec' "$log" || tail -n 3 "$log"
    else
        bad "$target: exit $rc (log $log)"
        tail -n 60 "$log"
    fi
}

fuzz fuzz-scene
# The kernel harness builds the core three more times: make test-full only.
if full; then
    fuzz fuzz-kernels
else
    echo "fuzz-kernels: make test-full (and make fuzz-kernels) only"
fi
report fuzz-short
