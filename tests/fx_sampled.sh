#!/usr/bin/env bash
# Every 4099th input of the exhaustive fixed-point sweeps (tests/fx_exhaustive.c)
# plus its hard cases, for the host code paths and the Cortex-M0 ones.
# The full sweep is `make fx-exhaustive`.
set -u
BUILD=${BUILD:-build}
pass=0
fail=0
for b in fx_exhaustive fx_exhaustive_nohw; do
    echo "== $b --step 4099"
    out=$("$BUILD/tests/$b" --step 4099 --jobs 1 2>&1)
    rc=$?
    echo "$out"
    line=$(grep -E '[0-9]+ passed, [0-9]+ failed' <<<"$out" | tail -n 1)
    if [ -z "$line" ]; then
        fail=$((fail + 1))
        continue
    fi
    p=$(sed -E 's/.* ([0-9]+) passed, ([0-9]+) failed.*/\1/' <<<"$line")
    f=$(sed -E 's/.* ([0-9]+) passed, ([0-9]+) failed.*/\2/' <<<"$line")
    [ "$rc" -ne 0 ] && [ "$f" -eq 0 ] && f=1
    pass=$((pass + p))
    fail=$((fail + f))
done
echo "fx_sampled: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
