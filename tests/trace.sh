#!/usr/bin/env bash
# Reflection and refraction accuracy (issue 12, "Accuracy, asserted in make
# test"): scenes/trace/reflection.scene and scenes/trace/glass.scene at
# 640x480 (TRACE_SIZE), each at samples 1 and samples 2 (a copy of the scene
# with its samples line replaced), rendered in double, Q16.16 and float.
# "fxrt compare DOUBLE OTHER --scene SCENE" measures each against the
# double render at the same samples. Asserted for Q16.16, per scene and
# samples:
#   - within1_pct >= 99.5 (pixels within 1/255 in every channel);
#   - far_within2_pct >= 99.9 (pixels away from discontinuities, i.e.
#     whose 8-neighbourhood holds one key at one sample per pixel in the
#     double render, within 2/255);
#   - psnr >= 45 dB.
# Float is printed, not asserted. The renders run two at a time (two
# cores). Ends with the table and "trace: N passed, N failed".
set -u
. "$(dirname "$0")/lib.sh"
out=$BUILD/tests/trace
size=${TRACE_SIZE:-640x480}
scenes=${TRACE_SCENES:-"scenes/trace/reflection.scene scenes/trace/glass.scene"}
rm -rf "$out"
mkdir -p "$out"

metric() { sed -nE "s/.*(^| )$1=([^ ]+).*/\2/p" <<<"$2"; }
# cmp_num A OP B (psnr=inf counts as larger than any number)
cmp_num() {
    awk -v a="$1" -v op="$2" -v b="$3" 'BEGIN {
        if (a == "inf") a = "1e300"
        if (a !~ /^-?[0-9]+(\.[0-9]+)?(e[0-9]+)?$/ || b !~ /^-?[0-9]+(\.[0-9]+)?$/) exit 2
        a += 0; b += 0
        if (op == ">=") exit !(a >= b)
        if (op == "<=") exit !(a <= b)
        exit 2 }'
}
check_metric() { # NAME LINE KEY OP VALUE
    local got
    got=$(metric "$3" "$2")
    if [ -z "$got" ]; then
        bad "$1: no '$3' in the compare line: $2"
        return
    fi
    check "$1: $3 $4 $5 (got $got)" cmp_num "$got" "$4" "$5"
}

# with_samples SCENE N > COPY: the scene with its samples line set to N
with_samples() {
    awk -v n="$2" '{ line = $0; sub(/#.*/, "", line) }
        line ~ /^[ \t]*samples([ \t]|$)/ { next } { print } END { print "samples " n }' "$1"
}

# Render jobs, two at a time: NAME SCENE NUMBER
jobs_list=()
for scene in $scenes; do
    name=$(basename "$scene" .scene)
    for s in 1 2; do
        with_samples "$scene" $s >"$out/$name-s$s.scene"
        for n in double q16 float; do jobs_list+=("$name-s$s $n"); done
    done
done
render_one() { # STEM NUMBER
    "$FXRT" render "$out/$1.scene" --size "$size" --number "$2" -o "$out/$1-$2.ppm" 2>"$out/$1-$2.err"
    echo $? >"$out/$1-$2.rc"
}
progress "trace: ${#jobs_list[@]} renders at $size"
i=0
for job in "${jobs_list[@]}"; do
    render_one $job &
    i=$((i + 1))
    [ $((i % 2)) -eq 0 ] && wait
done
wait

table=()
for scene in $scenes; do
    name=$(basename "$scene" .scene)
    for s in 1 2; do
        stem=$name-s$s
        ok_all=1
        for n in double q16 float; do
            if [ "$(cat "$out/$stem-$n.rc" 2>/dev/null)" != 0 ]; then
                bad "$stem: render --number $n failed: $(head -c 300 "$out/$stem-$n.err" 2>/dev/null)"
                ok_all=0
            fi
        done
        [ $ok_all -eq 1 ] || continue
        for n in q16 float; do
            line=$("$FXRT" compare "$out/$stem-double.ppm" "$out/$stem-$n.ppm" --scene "$out/$stem.scene" \
                --diff "$out/$stem-$n-diff.png" 2>"$out/$stem-$n-compare.err")
            rc=$?
            if [ $rc -ne 0 ] || [ -z "$line" ]; then
                bad "$stem $n: fxrt compare --scene failed (exit $rc): $(head -c 300 "$out/$stem-$n-compare.err")"
                continue
            fi
            echo "$name samples $s $n vs double: $line"
            table+=("$(printf '%-12s %-6s %7s' "$name" "$n" "$s")$(for k in within1_pct within2_pct far_within2_pct max_err psnr; do
                printf ' %10s' "$(metric $k "$line")"; done)")
            [ $n = q16 ] || continue
            check_metric "$name samples $s q16" "$line" within1_pct ">=" 99.5
            check_metric "$name samples $s q16" "$line" far_within2_pct ">=" 99.9
            check_metric "$name samples $s q16" "$line" psnr ">=" 45
        done
    done
done
echo
echo "against double at the same samples, $size (command: make trace; log build/tests/logs/trace.sh.log)"
printf '%-12s %-6s %7s %10s %10s %10s %10s %10s\n' scene build samples within1% within2% far_w2% max_err psnr
for row in "${table[@]}"; do echo "$row"; done
report trace
