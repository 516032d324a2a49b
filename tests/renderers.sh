#!/usr/bin/env bash
# The fast scanline renderer must give byte-identical Q16.16 frames to the
# straightforward reference loop (every object at every pixel): skipping,
# stepping and bounds may change the cost, never a pixel. Checked on every
# scene in scenes/ and scenes/stress/ that renders, at its own size or
# capped to 320 pixels wide to keep the reference loop quick.
set -u
. "$(dirname "$0")/lib.sh"
out=$BUILD/tests/renderers
mkdir -p "$out"
for scene in scenes/*.scene scenes/stress/*.scene; do
    name=$(basename "$scene" .scene)
    size=$(sed -nE 's/^image +([0-9]+) +([0-9]+).*/\1x\2/p' "$scene" | head -n 1)
    size=${size:-160x120}
    w=${size%x*} h=${size#*x}
    if [ "$w" -gt 320 ]; then
        h=$(((h * 320 + w - 1) / w))
        w=320
    fi
    if ! "$FXRT" render "$scene" --size "${w}x$h" -o "$out/$name-fast.ppm" 2>/dev/null; then
        continue # scenes that are rejected on purpose
    fi
    "$FXRT" render "$scene" --size "${w}x$h" --renderer reference -o "$out/$name-ref.ppm"
    check "$name (${w}x$h): q16 fast == reference" cmp -s "$out/$name-fast.ppm" "$out/$name-ref.ppm"
done
report renderers
