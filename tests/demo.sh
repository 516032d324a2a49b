#!/usr/bin/env bash
# make demo: render the six seed scenes in Q16.16 in QEMU on the default
# board (firmware, semihosting frame dump), render the double reference on
# the host, write PNGs and a sheet (Q16.16 | double | diff) per scene to
# build/demo/, and print instructions and the mismatch against double.
# Then the same for the lit course scenes (scenes/lit/course-*.scene, issue
# 11) at DEMO_LIT_SIZE (default 320x240, a quarter of their 640x480, to keep
# the demo quick), with fxrt compare --scene's metrics against double
# (within 1/255, within 2/255, far from discontinuities, PSNR). Then the
# trace scenes (scenes/trace/reflection and glass, issue 12) at
# DEMO_TRACE_SIZE (default 320x240), each board frame checked to exist and
# to be byte-identical to the host Q16.16 render (else exit 1).
#   DEMO_SIZE (640x430), DEMO_LIT_SIZE (320x240), DEMO_LIT_SCENES (files),
#   DEMO_TRACE_SIZE (320x240), DEMO_TRACE_SCENES (files)
set -eu
BUILD=${BUILD:-build}
FXRT=${FXRT:-$BUILD/fxrt}
BOARD=${BOARD:-mps2-an385}
SIZE=${DEMO_SIZE:-640x430}
out=$BUILD/demo
mkdir -p "$out"
get() { sed -E "s/.*(^| )$1=([^ ]+).*/\2/" <<<"$2"; }
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

# Lit course scenes: the same, with the lighting metrics.
LSIZE=${DEMO_LIT_SIZE:-320x240}
LSCENES=${DEMO_LIT_SCENES:-$(printf '%s ' scenes/lit/course-*.scene)}
lrows=()
for scene in $LSCENES; do
    name=$(basename "$scene" .scene)
    echo "[$name] QEMU $BOARD q16 $LSIZE"
    run=$(make -s --no-print-directory BUILD="$BUILD" qemu SCENE="$scene" BOARD="$BOARD" NUMBER=q16 SIZE="$LSIZE" | grep instructions=)
    "$FXRT" sheet --no-labels -o "$out/$name-q16.png" "$BUILD/qemu/$BOARD/$name-q16-$LSIZE.ppm"
    "$FXRT" render "$scene" --number double --size "$LSIZE" -o "$out/$name-double.png"
    line=$("$FXRT" compare "$out/$name-double.png" "$out/$name-q16.png" --scene "$scene" --diff "$out/$name-diff.png")
    "$FXRT" sheet -o "$out/$name-sheet.png" "$out/$name-q16.png=Q16.16 (QEMU)" "$out/$name-double.png=double" "$out/$name-diff.png=diff"
    lrows+=("$(printf '%-28s %-11s %11s %8s %8s %8s %8s %9s %7s %7s' "$name" "$BOARD" "$(get instructions "$run")" \
        "$(get instructions_per_pixel "$run")" "$(get mismatched_pct "$line")" "$(get within1_pct "$line")" \
        "$(get within2_pct "$line")" "$(get far_within1_pct "$line")" "$(get max_err "$line")" "$(get psnr "$line")")")
done
if [ ${#lrows[@]} -gt 0 ]; then
    echo
    echo "lit course scenes at $LSIZE, Q16.16 on $BOARD (QEMU) against the host double render (fxrt compare --scene):"
    printf '%-28s %-11s %11s %8s %8s %8s %8s %9s %7s %7s\n' scene board instructions instr/px "mism %" "<=1 %" "<=2 %" "far<=1 %" max_err psnr
    printf '%s\n' "${lrows[@]}"
    echo
    echo "frames: $out/NAME-{q16,double,diff,sheet}.png as above; <=K % = pixels within K/255 of double,"
    echo "        far = away from object and shadow edges (see fxrt compare --help)"
fi

# Trace scenes (issue 12): the reflection and glass scenes at
# DEMO_TRACE_SIZE (default 320x240) in Q16.16 on the board, the same
# lighting metrics against the host double render, and a check that each
# board frame exists and is byte-identical to the host's Q16.16 render.
TSIZE=${DEMO_TRACE_SIZE:-320x240}
TSCENES=${DEMO_TRACE_SCENES:-scenes/trace/reflection.scene scenes/trace/glass.scene}
trows=()
tbad=0
for scene in $TSCENES; do
    name=$(basename "$scene" .scene)
    echo "[$name] QEMU $BOARD q16 $TSIZE"
    ppm=$BUILD/qemu/$BOARD/$name-q16-$TSIZE.ppm
    rm -f "$ppm"
    run=$(make -s --no-print-directory BUILD="$BUILD" qemu SCENE="$scene" BOARD="$BOARD" NUMBER=q16 SIZE="$TSIZE" | grep instructions=)
    "$FXRT" render "$scene" --number q16 --size "$TSIZE" -o "$out/$name-host-q16.ppm"
    if [ ! -s "$ppm" ]; then
        echo "FAIL $name: no frame from the board ($ppm)" >&2
        tbad=$((tbad + 1))
        continue
    elif ! cmp -s "$ppm" "$out/$name-host-q16.ppm"; then
        echo "FAIL $name: the board's frame differs from the host's Q16.16 render" >&2
        tbad=$((tbad + 1))
    fi
    "$FXRT" sheet --no-labels -o "$out/$name-q16.png" "$ppm"
    "$FXRT" render "$scene" --number double --size "$TSIZE" -o "$out/$name-double.png"
    line=$("$FXRT" compare "$out/$name-double.png" "$out/$name-q16.png" --scene "$scene" --diff "$out/$name-diff.png")
    "$FXRT" sheet -o "$out/$name-sheet.png" "$out/$name-q16.png=Q16.16 (QEMU)" "$out/$name-double.png=double" "$out/$name-diff.png=diff"
    trows+=("$(printf '%-28s %-11s %11s %8s %8s %8s %8s %9s %7s %7s %s' "$name" "$BOARD" "$(get instructions "$run")" \
        "$(get instructions_per_pixel "$run")" "$(get mismatched_pct "$line")" "$(get within1_pct "$line")" \
        "$(get within2_pct "$line")" "$(get far_within1_pct "$line")" "$(get max_err "$line")" "$(get psnr "$line")" \
        "$(cmp -s "$ppm" "$out/$name-host-q16.ppm" && echo yes || echo NO)")")
done
if [ ${#trows[@]} -gt 0 ]; then
    echo
    echo "trace scenes at $TSIZE, Q16.16 on $BOARD (QEMU) against the host double render (fxrt compare --scene):"
    printf '%-28s %-11s %11s %8s %8s %8s %8s %9s %7s %7s %s\n' scene board instructions instr/px "mism %" "<=1 %" "<=2 %" \
        "far<=1 %" max_err psnr "board==host q16"
    printf '%s\n' "${trows[@]}"
    echo
    echo "frames: $out/NAME-{q16,double,diff,sheet}.png as above; board==host q16: the board's frame is"
    echo "        byte-identical to \`fxrt render --number q16\` at the same size ($out/NAME-host-q16.ppm)"
fi
[ "$tbad" -eq 0 ] || { echo "demo: $tbad trace frame(s) missing or different from the host's Q16.16 render" >&2; exit 1; }
