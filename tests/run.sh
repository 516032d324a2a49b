#!/usr/bin/env bash
# Run test suites (programs or scripts), each of which ends its output with
# "NAME: N passed, N failed". Sum them and end with the total line, after
# a recap of the suites that failed; exit non-zero if any check failed or
# any suite crashed.
#
# Two lanes run side by side (the suites are single-threaded). The suites
# that build and run firmware in shared build/fw directories (qemu,
# qemu_lit, fit, examples, cli, whose make fw runs would race) run one
# after another in the first lane. Every other suite waits in a queue
# that both lanes take from (under flock): the second from the start, the
# first once its own are done, so that both lanes end at about the same
# time. The queue holds the long suites first (RUN_LONG, by their CPU
# seconds in a clean run: qemu_trace.sh builds only ELFs of its own,
# FW_TAG=trace*), then the rest in the order given. RUN_LANES=1 runs
# everything in one lane, in the order given. Each suite's line is printed
# when it ends; the total comes last.
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
lanes=${RUN_LANES:-2}
exec 3>&1
export PROGRESS_FD=3
results=$(mktemp -d)
queue=$(mktemp) # (the suites not yet taken: apart from the results)
trap 'rm -rf "$results" "$queue" "$queue.lock"' EXIT

# run_one SUITE: run it, print its line, record "PASSED FAILED" in $results.
run_one() {
    local suite=$1 name log start rc notice secs line p f
    name=$(basename "$suite")
    log=$logdir/$name.log
    start=$(date +%s)
    # The notice's sleep does not hold stdout, so killing the subshell ends it.
    (sleep "$notice_secs" >/dev/null 2>&1 && echo "$name: running (over ${notice_secs}s; log $log)") &
    notice=$!
    # CPU seconds (user + system, the suite and its children) as well as
    # wall time: make test's budget is two cores, and a lane's wall time
    # hides what the other lane takes from it.
    local TIMEFORMAT='%U %S' cpu
    cpu=$({ time "$suite" >"$log" 2>&1; } 2>&1)
    rc=$?
    cpu=$(awk '{printf "%d", $1 + $2 + 0.5}' <<<"$cpu")
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
        # one block per suite, so that the other lane's lines do not interleave
        { printf '%-22s %6d passed %4d FAILED (%ds, CPU %ss)\n' "$name" "$p" "$f" "$secs" "$cpu"
          tail -n 30 "$log" | sed 's/^/    | /'; } | cat
    else
        printf '%-22s %6d passed (%ds, CPU %ss)\n' "$name" "$p" "$secs" "$cpu"
    fi
    echo "$p $f $name $cpu" >"$results/$(printf '%03d' "$2")"
}

RUN_LONG=${RUN_LONG:-"qemu_trace.sh sanitize.sh skip.sh layers.sh cmake.sh test_diff meshq.sh fuzz-short.sh norecurse.sh"}
firmware=() long=() others=()
i=0
for suite in "$@"; do
    name=$(basename "$suite")
    case $name in
    qemu.sh | qemu_lit.sh | fit.sh | examples.sh | cli.sh) firmware+=("$i:$suite") ;;
    *) if [[ " $RUN_LONG " == *" $name "* ]]; then long+=("$i:$suite"); else others+=("$i:$suite"); fi ;;
    esac
    i=$((i + 1))
done
printf '%s\n' ${long[@]+"${long[@]}"} ${others[@]+"${others[@]}"} >"$queue"
# take: the queue's first item (empty when it is empty), under the lock.
take() {
    (
        flock 9
        head -n 1 "$queue"
        sed -i 1d "$queue"
    ) 9>"$queue.lock"
}
from_queue() {
    local item
    while item=$(take) && [ -n "$item" ]; do run_one "${item#*:}" "${item%%:*}"; done
}
if [ "$lanes" -ge 2 ]; then
    { for item in "${firmware[@]}"; do run_one "${item#*:}" "${item%%:*}"; done; from_queue; } &
    first=$!
    from_queue
    wait "$first"
else
    i=0
    for suite in "$@"; do
        run_one "$suite" "$i"
        i=$((i + 1))
    done
fi
total_pass=0
total_fail=0
total_cpu=0
n=0
failed=()
for r in "$results"/*; do
    [ -f "$r" ] || continue
    read -r p f name cpu <"$r"
    total_cpu=$((total_cpu + cpu))
    total_pass=$((total_pass + p))
    total_fail=$((total_fail + f))
    n=$((n + 1))
    [ "$f" -eq 0 ] || failed+=("$name")
done
# A recap next to the total: a CI page that shows only the end of the
# output still names what failed and its first failing checks.
for name in ${failed[@]+"${failed[@]}"}; do
    echo "FAILED: $name (log $logdir/$name.log)"
    { grep -E 'FAIL' "$logdir/$name.log" || tail -n 5 "$logdir/$name.log"; } | head -n 5 | sed 's/^/    | /'
done
if [ "$n" -ne "$#" ]; then
    echo "FAIL run.sh: $n of $# suites reported"
    total_fail=$((total_fail + 1))
fi
echo "suites: $n, CPU ${total_cpu}s (user + system)"
echo "total: $total_pass passed, $total_fail failed"
[ "$total_fail" -eq 0 ]
