#!/usr/bin/env bash
# Run test suites (programs or scripts), each of which ends its output with
# "NAME: N passed, N failed". Sum them and end with the total line; exit
# non-zero if any check failed or any suite crashed.
#
# Progress: a suite's output goes to its log, but a long suite may print
# progress lines to the terminal with `progress` (tests/lib.sh), which
# writes to fd $PROGRESS_FD: run.sh's own stdout, opened as fd 3. A suite
# still running after RUN_NOTICE_SECONDS (default 10) is announced.
set -u
BUILD=${BUILD:-build}
logdir=$BUILD/tests/logs
mkdir -p "$logdir"
notice_secs=${RUN_NOTICE_SECONDS:-10}
exec 3>&1
export PROGRESS_FD=3
total_pass=0
total_fail=0
for suite in "$@"; do
    name=$(basename "$suite")
    log=$logdir/$name.log
    start=$(date +%s)
    # The notice's sleep does not hold stdout, so killing the subshell ends it.
    (sleep "$notice_secs" >/dev/null 2>&1 && echo "$name: running (over ${notice_secs}s; log $log)") &
    notice=$!
    "$suite" >"$log" 2>&1
    rc=$?
    kill "$notice" 2>/dev/null
    wait "$notice" 2>/dev/null
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
