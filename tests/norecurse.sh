#!/usr/bin/env bash
# Nothing in the core recurses (issue 12: "Nothing recurses in C"). Every
# core/*.c is compiled for the Cortex-M3 with GCC's -fcallgraph-info=su,
# which writes each translation unit's call graph and frame sizes (.ci,
# VCG text); tests/norecurse.py joins the units and fails on any cycle
# (self-edges included) and on any call through a function pointer (which
# the graph cannot follow). Each number type is checked twice (make test:
# Q16.16 at both levels, double at -O0):
#   -O0  the graph of the C source as written (no inlining, no tail calls
#        turned into loops: a recursive function shows as a cycle);
#   -O2  the graph of the code that runs on the board (the firmware's
#        level); its frame sizes give the worst-case static stack depth of
#        render_row and of trace_bounces, printed with the chain that makes
#        it up (libgcc helpers count 0 bytes).
# Default configuration (fxrt_config.h: FXRT_MAX_DEPTH 16, 8 lights,
# samples up to 16), with the kinds a bare board leaves out by default
# (models, ellipsoids, parallelepipeds: their code, the mesh walk
# scene/bvh.c among it, is in the graph). Negative controls: tests/norecurse_bad.c (self and
# mutual recursion, a call through a pointer) must be flagged at both
# levels. Ends with "norecurse: N passed, N failed".
set -u
. "$(dirname "$0")/lib.sh"
out=$BUILD/tests/norecurse
rm -rf "$out"
mkdir -p "$out"
CC_ARM=${ARM_CC:-arm-none-eabi-gcc}
if ! command -v "$CC_ARM" >/dev/null; then
    bad "$CC_ARM not installed (run make deps)"
    report norecurse
    exit 1
fi
major=$("$CC_ARM" -dumpversion | cut -d. -f1)
check "$CC_ARM is GCC 10 or later (-fcallgraph-info; got $("$CC_ARM" -dumpversion))" test "$major" -ge 10
FLAGS=(-std=c11 -mcpu=cortex-m3 -mthumb -ffreestanding -fcallgraph-info=su -Icore "${BARE_ALL_KINDS[@]}")

# graph DIR OPT NUMBER SOURCES...: compile each source into DIR (its .ci
# next to the .o); DIR/rc gets the status
graph() {
    local dir=$1 opt=$2 num=$3
    shift 3
    mkdir -p "$dir"
    local f rc=0
    for f in "$@"; do
        "$CC_ARM" "${FLAGS[@]}" "$opt" -DFXRT_NUMBER="$num" -c "$f" -o "$dir/$(tr / _ <<<"${f%.c}").o" \
            2>>"$dir/cc.log" || rc=1
    done
    echo $rc >"$dir/rc"
    return $rc
}

# Negative control: the checker finds the recursion it must find.
for opt in -O0 -O2; do
    d=$out/bad$opt
    if graph "$d" "$opt" 1 tests/norecurse_bad.c; then
        res=$(python3 tests/norecurse.py "$d"/*.ci)
        echo "control $opt:"
        sed 's/^/  /' <<<"$res"
        check "control $opt: the checker fails on tests/norecurse_bad.c" bash -c "! python3 tests/norecurse.py $d/*.ci >/dev/null"
        check "control $opt: self-recursion (bad_self) found" grep -q '^cycle: .*bad_self' <<<"$res"
        # (-O2 may inline one of the pair into the other: a self-cycle then)
        check "control $opt: mutual recursion (bad_even, bad_odd) found" grep -qE '^cycle: .*bad_(even|odd)' <<<"$res"
        check "control $opt: the call through a pointer found" grep -q '^indirect: bad_pointer' <<<"$res"
    else
        bad "control $opt: tests/norecurse_bad.c does not compile: $(head -c 300 "$d/cc.log")"
    fi
done

srcs=(core/*/*.c)
configs=()
# make test: Q16.16 at -O0 (the source as written) and at -O2, double at
# -O0 (the other side of every FXRT_NUMBER branch); make test-full: every
# number at both levels.
for name in q16 float double; do for opt in -O0 -O2; do
    ! full && [ $name:$opt != q16:-O0 ] && [ $name:$opt != q16:-O2 ] && [ $name:$opt != double:-O0 ] && continue
    configs+=("$name:$opt")
done; done
progress "norecurse: ${#configs[@]} builds of ${#srcs[@]} core sources"
# two configurations at a time (two cores)
i=0
for cfg in "${configs[@]}"; do
    name=${cfg%%:*} opt=${cfg#*:}
    num=$(case $name in q16) echo 1 ;; float) echo 2 ;; *) echo 3 ;; esac)
    graph "$out/$name$opt" "$opt" "$num" "${srcs[@]}" &
    i=$((i + 1))
    [ $((i % 2)) -eq 0 ] && wait
done
wait
for cfg in "${configs[@]}"; do
    name=${cfg%%:*} opt=${cfg#*:}
    d=$out/$name$opt
    if [ "$(cat "$d/rc" 2>/dev/null)" != 0 ]; then
        bad "$name $opt: core does not compile: $(head -c 300 "$d/cc.log")"
        continue
    fi
    n=$(ls "$d"/*.ci | wc -l)
    check "$name $opt: one call graph per core source ($n of ${#srcs[@]})" test "$n" -eq "${#srcs[@]}"
    res=$(python3 tests/norecurse.py --root render_row --root trace_bounces "$d"/*.ci)
    rc=$?
    cyc=$(grep -E '^(cycle|indirect):' <<<"$res")
    check "$name $opt: no cycle and no indirect call in the core's call graph${cyc:+ (found: $cyc)}" test "$rc" -eq 0
    nodes=$(cat "$d"/*.ci | grep -c '^node:')
    check "$name $opt: the graph is not empty ($nodes nodes)" test "$nodes" -gt 50
    check "$name $opt: the mesh walk is in the graph (bvh_nearest, bvh_any)" \
        bash -c "grep -q 'title: \"bvh_nearest\"' $d/*.ci && grep -q 'title: \"bvh_any\"' $d/*.ci"
    if [ "$opt" = -O2 ]; then
        grep '^stack:' <<<"$res" | sed "s/^/$name $opt /"
        check "$name $opt: render_row reaches trace_bounces (the bounce loop is in the graph)" \
            grep -qE '^stack: render_row .*trace_bounces' <<<"$res"
    fi
done
report norecurse
