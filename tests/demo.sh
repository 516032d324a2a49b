#!/usr/bin/env bash
# make demo: render the six seed scenes in Q16.16 in QEMU on the default
# board (firmware, semihosting frame dump), render the double reference on
# the host, write PNGs and a sheet (Q16.16 | double | diff) per scene to
# build/demo/, and print instructions and the mismatch against double.
set -eu
BUILD=${BUILD:-build}
FXRT=${FXRT:-$BUILD/fxrt}
BOARD=${BOARD:-mps2-an385}
SIZE=${DEMO_SIZE:-640x430}
out=$BUILD/demo
mkdir -p "$out"
rows=()
for scene in scenes/abb*.scene; do
    name=$(basename "$scene" .scene)
    echo "[$name] QEMU $BOARD q16 $SIZE"
    run=$(make -s --no-print-directory BUILD="$BUILD" qemu SCENE="$scene" BOARD="$BOARD" NUMBER=q16 SIZE="$SIZE" | grep instructions=)
    # A one-image sheet converts the firmware's PPM to PNG.
    "$FXRT" sheet --no-labels -o "$out/$name-q16.png" "$BUILD/qemu/$BOARD/$name-q16-$SIZE.ppm"
    "$FXRT" render "$scene" --number double --size "$SIZE" -o "$out/$name-double.png"
    line=$("$FXRT" compare "$out/$name-double.png" "$out/$name-q16.png" --diff "$out/$name-diff.png")
    "$FXRT" sheet -o "$out/$name-sheet.png" "$out/$name-q16.png=Q16.16 (QEMU)" "$out/$name-double.png=double" "$out/$name-diff.png=diff"
    get() { sed -E "s/.*(^| )$1=([^ ]+).*/\2/" <<<"$2"; }
    rows+=("$(printf '%-24s %-11s %12s %8s %9s %7s %8s %8s' "$name" "$BOARD" "$(get instructions "$run")" \
        "$(get instructions_per_pixel "$run")" "$(get mismatched "$line")" "$(get mismatched_pct "$line")" \
        "$(get interior_mismatched "$line")" "$(get psnr "$line")")")
done
echo
printf '%-24s %-11s %12s %8s %9s %7s %8s %8s\n' scene board instructions instr/px mismatch "%" interior psnr
printf '%s\n' "${rows[@]}"
echo
echo "frames: $out/NAME-q16.png (QEMU, Q16.16), NAME-double.png (host reference), NAME-diff.png,"
echo "        NAME-sheet.png (the three side by side); size $SIZE, mismatch = Q16.16 vs double"
