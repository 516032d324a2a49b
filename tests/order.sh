#!/usr/bin/env bash
# Nearest first (core/render_setup.c, render_order) changes the work, never
# a pixel: every scene in scenes/ and its subfolders at 96x72, in q16,
# float and double, with the host tool and with its FXRT_ABLATE_ORDER build
# (tests/order.mk), byte for byte. The lit scenes and two bench scenes
# are rendered again with `samples 2 adaptive` and lights on every
# object: the adaptive sampler's one ray per pixel takes the shading
# constants of the object it hits from the sorted records
# (render_obj_of), which these frames check.
set -u
. "$(dirname "$0")/lib.sh"
NOORDER=${NOORDER:-$BUILD/noorder/fxrt}
out=$BUILD/tests/order
mkdir -p "$out"
check "the FXRT_ABLATE_ORDER build exists ($NOORDER)" test -x "$NOORDER"
scenes=()
for f in scenes/*.scene scenes/*/*.scene; do
    [ -f "$f" ] && ! grep -q '^# expect: rejected:' "$f" && scenes+=("$f")
done
for f in scenes/lit/*.scene; do
    name=adaptive-$(basename "$f" .scene)
    { sed '/^samples /d' "$f"; echo "samples 2 adaptive"; } >"$out/$name.scene"
    scenes+=("$out/$name.scene")
done
for f in scenes/bench/mixed16.scene scenes/bench/cover.scene; do
    name=adaptive-lit-$(basename "$f" .scene)
    { sed -E 's/^((sphere|box|triangle|plane) .* color [0-9.]+ [0-9.]+ [0-9.]+)$/\1 material phong specular 1 1 1 exponent 16/' "$f"
      echo "ambient 0.1 0.1 0.1"
      echo "light point position 2 3 4 color 0.8 0.8 0.8"
      echo "samples 2 adaptive"; } >"$out/$name.scene"
    check "$name: every object lit" test "$(grep -c 'material phong' "$out/$name.scene")" -ge 6
    scenes+=("$out/$name.scene")
done
n=0 refused=0
for scene in "${scenes[@]}"; do
    name=$(basename "$scene" .scene)
    for num in q16 float double; do
        n=$((n + 1))
        "$FXRT" render "$scene" --size 96x72 --number $num -o "$out/$name-$num-a.ppm" 2>"$out/$name-a.err"
        ra=$?
        "$NOORDER" render "$scene" --size 96x72 --number $num -o "$out/$name-$num-b.ppm" 2>"$out/$name-b.err"
        rb=$?
        if [ $ra -ne 0 ] || [ $rb -ne 0 ]; then
            # (A scene that cannot be set up at this size: both refuse it alike.)
            check "$scene ($num): both refuse it alike (exit $ra and $rb)" \
                test $ra -eq 2 -a $rb -eq 2 -a "$(cat "$out/$name-a.err")" = "$(cat "$out/$name-b.err")"
            refused=$((refused + 1))
            continue
        fi
        check "$scene ($num): nearest first == scene order" cmp -s "$out/$name-$num-a.ppm" "$out/$name-$num-b.ppm"
    done
done
echo "order: $n frames, $refused refused by both at 96x72"
check "frames compared" test $((n - refused)) -gt 250
report order.sh
