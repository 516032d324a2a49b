#!/usr/bin/env bash
# Run test suites (programs or scripts), each of which ends its output with
# "NAME: N passed, N failed". Sum them and end with the total line; exit
# non-zero if any check failed or any suite crashed.
set -u
BUILD=${BUILD:-build}
logdir=$BUILD/tests/logs
mkdir -p "$logdir"
total_pass=0
total_fail=0
for suite in "$@"; do
    name=$(basename "$suite")
    log=$logdir/$name.log
    start=$(date +%s)
    "$suite" >"$log" 2>&1
    rc=$?
    secs=$(($(date +%s) - start))
    line=$(grep -E '[0-9]+ passed, [0-9]+ failed' "$log" | tail -n 1)
    p=$(sed -E 's/.* ([0-9]+) passed, ([0-9]+) failed.*/\1/' <<<"$line")
    f=$(sed -E 's/.* ([0-9]+) passed, ([0-9]+) failed.*/\2/' <<<"$line")
    if [ -z "$line" ]; then
        p=0
        f=1
        echo "FAIL $name: no result line (exit $rc)"
    elif [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
        f=1
        echo "FAIL $name: exit $rc"
    fi
    if [ "$f" -ne 0 ]; then
        printf '%-22s %6d passed %4d FAILED (%ds)\n' "$name" "$p" "$f" "$secs"
        tail -n 30 "$log" | sed 's/^/    | /'
    else
        printf '%-22s %6d passed (%ds)\n' "$name" "$p" "$secs"
    fi
    total_pass=$((total_pass + p))
    total_fail=$((total_fail + f))
done
echo "total: $total_pass passed, $total_fail failed"
[ "$total_fail" -eq 0 ]
