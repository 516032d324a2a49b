#!/usr/bin/env bash
# make demo: render the six seed scenes in Q16.16 and in double (the
# reference) into build/demo/, and print each scene's comparison metrics.
set -eu
BUILD=${BUILD:-build}
FXRT=${FXRT:-$BUILD/fxrt}
out=$BUILD/demo
mkdir -p "$out"
printf '%-26s %9s %8s %7s %8s %9s\n' scene mismatched pct max_err psnr interior
for scene in scenes/abb*.scene; do
    name=$(basename "$scene" .scene)
    "$FXRT" render "$scene" --number q16 -o "$out/$name-q16.png"
    "$FXRT" render "$scene" --number double -o "$out/$name-double.png"
    line=$("$FXRT" compare "$out/$name-double.png" "$out/$name-q16.png" --diff "$out/$name-diff.png")
    get() { sed -E "s/.*(^| )$1=([^ ]+).*/\2/" <<<"$line"; }
    printf '%-26s %9s %8s %7s %8s %9s\n' "$name" "$(get mismatched)" "$(get mismatched_pct)" \
        "$(get max_err)" "$(get psnr)" "$(get interior_mismatched)"
done
echo "images: $out/*-q16.png (Q16.16), *-double.png (reference), *-diff.png (differences)"
