#!/usr/bin/env bash
# The cut-off's effect (issue 12: "its effect against no cut-off is
# measured and stated"): the scenes rendered by the normal host tool
# (BUILD/fxrt: rays whose weight is below 1/512 in every channel are not
# traced) and by one built with FXRT_ABLATE_CUTOFF (CUTOFF_FXRT, every ray
# traced up to the depth), in double and Q16.16, compared pixel by pixel
# with fxrt compare: pixels that differ, largest difference (1/255), PSNR.
# Checked: the no-cut-off tool renders; the largest difference stays
# within CUTOFF_MAX_ERR (default 2/255). A cut ray's weight is < 1/512 and
# the weights of its subtree sum to at most that per level (c_r <= 1, R +
# (1 - R) c_d <= 1), so it can bring at most depth x (largest unclamped
# local colour) / 512 per channel: about 0.5/255 per level for colours up
# to 255; a larger difference means the cut-off cuts more than it should. Run with make cutoff (not part of make test: it builds a
# second host tool).
set -u
. "$(dirname "$0")/lib.sh"
out=$BUILD/tests/cutoff
NOCUT=${CUTOFF_FXRT:-$BUILD/nocut/fxrt}
size=${CUTOFF_SIZE:-640x480}
max_allowed=${CUTOFF_MAX_ERR:-2}
scenes=${CUTOFF_SCENES:-"scenes/trace/reflection.scene scenes/trace/glass.scene scenes/stress/trace-mirrors.scene scenes/stress/trace-inside-glass.scene"}
rm -rf "$out"
mkdir -p "$out"
metric() { sed -nE "s/.*(^| )$1=([^ ]+).*/\2/p" <<<"$2"; }
check "$NOCUT exists (make cutoff builds it)" test -x "$NOCUT"
rows=()
for scene in $scenes; do
    name=$(basename "$scene" .scene)
    for n in double q16; do
        "$FXRT" render "$scene" --size "$size" --number $n -o "$out/$name-$n.ppm" 2>"$out/$name-$n.err" &
        "$NOCUT" render "$scene" --size "$size" --number $n -o "$out/$name-$n-nocut.ppm" 2>"$out/$name-$n-nocut.err"
        rc=$?
        wait $! || { bad "$name $n: render failed: $(head -c 200 "$out/$name-$n.err")"; continue; }
        [ $rc -eq 0 ] || { bad "$name $n: no-cut-off render failed: $(head -c 200 "$out/$name-$n-nocut.err")"; continue; }
        line=$("$FXRT" compare "$out/$name-$n-nocut.ppm" "$out/$name-$n.ppm")
        echo "$name $n, cut-off vs none: $line"
        m=$(metric max_err "$line")
        rows+=("$(printf '%-20s %-6s %10s %8s %10s %8s' "$name" "$n" "$(metric mismatched "$line")" \
            "$(metric mismatched_pct "$line")" "$m" "$(metric psnr "$line")")")
        check "$name $n: cut-off changes no pixel by more than $max_allowed/255 (got $m)" test "${m:-999}" -le "$max_allowed"
    done
done
echo
echo "cut-off (1/512) against no cut-off, $size (command: make cutoff)"
printf '%-20s %-6s %10s %8s %10s %8s\n' scene build differ differ% max_err psnr
for r in "${rows[@]}"; do echo "$r"; done
report cutoff
