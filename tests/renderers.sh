#!/usr/bin/env bash
# The fast scanline renderer must give byte-identical Q16.16 frames to the
# straightforward reference loop (every object at every pixel): skipping,
# stepping and bounds may change the cost, never a pixel. Checked on every
# scene in scenes/ and its subfolders, at its own size or capped to 320
# pixels wide to keep the reference loop quick.
#
# A scene whose header says "# expect: rejected:" must be refused by both
# loops (exit 2, no output file); every other scene must render. Nothing
# is skipped: a render that fails is a failed check.
set -u
. "$(dirname "$0")/lib.sh"
out=$BUILD/tests/renderers
mkdir -p "$out"
n=0
for scene in scenes/*.scene scenes/*/*.scene; do
    [ -f "$scene" ] || continue
    n=$((n + 1))
    name=$(basename "$(dirname "$scene")")-$(basename "$scene" .scene)
    size=$(sed -nE 's/^image +([0-9]+) +([0-9]+).*/\1x\2/p' "$scene" | head -n 1)
    size=${size:-160x120}
    w=${size%x*} h=${size#*x}
    if [ "$w" -gt 320 ]; then
        h=$(((h * 320 + w - 1) / w))
        w=320
    fi
    rm -f "$out/$name-fast.ppm" "$out/$name-ref.ppm"
    if grep -q '^# expect: rejected:' "$scene"; then
        for r in fast reference; do
            "$FXRT" render "$scene" --size "${w}x$h" --renderer $r -o "$out/$name-$r.ppm" 2>"$out/$name-$r.err"
            rc=$?
            check "$scene: $r refuses it as its header says (exit $rc, want 2)" test $rc -eq 2
            check "$scene: $r writes nothing" test ! -e "$out/$name-$r.ppm"
        done
        continue
    fi
    if ! "$FXRT" render "$scene" --size "${w}x$h" -o "$out/$name-fast.ppm" 2>"$out/$name-fast.err"; then
        bad "$scene (${w}x$h): fast render failed: $(head -c 300 "$out/$name-fast.err")"
        continue
    fi
    if ! "$FXRT" render "$scene" --size "${w}x$h" --renderer reference -o "$out/$name-ref.ppm" 2>"$out/$name-ref.err"; then
        bad "$scene (${w}x$h): reference render failed: $(head -c 300 "$out/$name-ref.err")"
        continue
    fi
    check "$scene (${w}x$h): q16 fast == reference" cmp -s "$out/$name-fast.ppm" "$out/$name-ref.ppm"
done
echo "renderers: $n scenes"
check "scenes found" test "$n" -gt 0

# Supersampling (samples N): the scanline renderer's sums (core/
# render_sample.c: fine visibility pass, per-pixel sums, uniform-owner
# shortcut) against the ray caster's (one world_hit per cell ray, its own
# loop), in double, where the two differ only where a cell ray grazes a
# silhouette: such a ray changes its pixel by at most the contrast / N^2.
# N = 2, 3 (not a power of two: a division, not a shift) and 4, flat and
# lit scenes.
for scene in scenes/abb9-two-spheres.scene scenes/abb8-triangle.scene scenes/lit/room.scene scenes/trace/reflection.scene; do
    for ns in 2 3 4; do
        name=ss$ns-$(basename "$scene" .scene)
        sed '/^samples /d' "$scene" >"$out/$name.scene"
        echo "samples $ns" >>"$out/$name.scene"
        for r in fast raycast; do
            "$FXRT" render "$out/$name.scene" --size 96x72 --number double --renderer $r -o "$out/$name-$r.ppm" ||
                bad "$name: $r render failed"
        done
        line=$("$FXRT" compare "$out/$name-fast.ppm" "$out/$name-raycast.ppm")
        max=$(tr ' ' '\n' <<<"$line" | sed -n 's/^max_err=//p')
        w1=$(tr ' ' '\n' <<<"$line" | sed -n 's/^within1_pct=//p')
        check "$name: double fast vs ray caster: max error $max <= 255 / $ns^2 + 1" test "${max:-999}" -le $((255 / (ns * ns) + 1))
        check "$name: double fast vs ray caster: $w1 % within 1/255 >= 99.5" awk -v w="${w1:-0}" 'BEGIN { exit !(w >= 99.5) }'
    done
done
report renderers
