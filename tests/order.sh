#!/usr/bin/env bash
# Nearest first (vis/order.c), the shadow rows (light/shadow.c, a
# plane's per-row masks of the objects that cannot block its shadow rays),
# the flat objects' hit numerators kept across pixels, with the runs of
# their pixels shaded at once (frame/render_shade.c, FXRT_SHADE_RUNS,
# which needs the numerators), a model's quick box test (scene/bvh.c: boxes
# by reciprocals, the walk's order by the exact quotients where those are
# too close) and the triangles' shadow edges (light/shadow.c) change the
# work, never a pixel: every scene in scenes/ and its subfolders at 96x72,
# in q16, float and double, with the host tool and with its build without
# all five (FXRT_ABLATE_ORDER, FXRT_ABLATE_SHADOW_ROWS,
# FXRT_ABLATE_FLAT_NUM, FXRT_ABLATE_BVH_QUICK; FXRT_SHADOW_EDGES 0;
# tests/order.mk), byte for byte. The lit scenes and two bench scenes
# are rendered again with `samples 2 adaptive` and lights on every
# object: the adaptive sampler's one ray per pixel takes the shading
# constants of the object it hits from the sorted records
# (render_obj_of), which these frames check. And 60 random scenes of
# shadows on planes (a floor or a tilted plane, 2 to 7 spheres, boxes and
# triangles, 1 or 2 lights with shadows: point or spot lights, some near
# the plane, some far, in the first 40; directional lights, some grazing
# the plane, in the last 20; a perspective camera of 10 to 150 degrees,
# seen from near or far): the rows' margins where shadows graze them. And
# 24 random planes under spot lights only: the runs' blocks that no spot
# reaches. And 40 random Phong planes under point lights: the runs' blocks
# without a specular term.
set -u
. "$(dirname "$0")/lib.sh"
NOORDER=${NOORDER:-$BUILD/ablated/fxrt}
out=$BUILD/tests/order
mkdir -p "$out"
check "the ablated build exists ($NOORDER)" test -x "$NOORDER"
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
# Random models (icospheres of 80 to 1,280 triangles, smooth or flat, in
# nodes that scale, unevenly too, turn and move them) on a floor under a
# point light with shadows, some of glass or a mirror, seen from random
# eyes, every fourth straight along an axis (a direction with components
# of 0, which the quick test leaves to the exact one), and a second model
# in front of the first in half of them: the quick test's walks and their
# ties, on camera, shadow and secondary rays.
scenes/models/mkmodels.sh "$out/models" 2 3 >/dev/null
cp scenes/models/ico80.obj "$out/models/"
for seed in $(seq 1 16); do
    name=mesh-$seed
    awk -v seed="$seed" 'function u(a, b) { return a + (b - a) * rand() }
        function place() {
            if (rand() < 0.4) printf "node scale %.3f %.3f %.3f", u(0.3, 1.6), u(0.3, 1.6), u(0.3, 1.6)
            else printf "node scale %.3f", u(0.4, 1.4)
            printf " rotate x %.1f rotate y %.1f rotate z %.1f translate %.3f %.3f %.3f\n", u(-180, 180), u(-180, 180), u(-180, 180), u(-1, 1), u(-0.3, 0.8), u(-1, 1)
        }
        function model() {
            m = int(rand() * 3); k = rand()
            mat = k < 0.6 ? " material phong specular 0.7 0.7 0.7 exponent 30" : k < 0.8 ? " material transparent index 1.5" : " material reflective specular 1 1 1 exponent 64 reflection 0.5 0.5 0.5"
            printf "  mesh file models/ico%d.obj shading %s color %.2f %.2f %.2f%s\nend\n", m == 0 ? 80 : m == 1 ? 320 : 1280, rand() < 0.7 ? "smooth" : "flat", u(0.2, 1), u(0.2, 1), u(0.2, 1), mat
        }
        BEGIN { srand(seed + 1000)
            print "image 96 72"
            print "background 0.1 0.1 0.2"
            if (seed % 4 == 0) print "camera perspective eye 0 0 " u(3, 6) " gaze 0 0 -1 up 0 1 0 fov " u(30, 60)
            else printf "camera perspective eye %.3f %.3f %.3f gaze 0 -0.2 -1 up 0 1 0 fov %.1f\n", u(-2, 2), u(0.5, 3), u(3, 6), u(25, 60)
            print "ambient 0.1 0.1 0.1"
            printf "light point position %.3f %.3f %.3f color 1 1 1 shadows on\n", u(-4, 4), u(2, 6), u(-1, 5)
            print "plane point 0 -1.5 0 normal 0 1 0 color 0.8 0.8 0.8 material lambert"
            place(); model()
            if (seed % 2 == 0) { place(); model() }
        }' >"$out/$name.scene"
    scenes+=("$out/$name.scene")
done
# Random shadows on planes (awk's rand with a fixed seed per scene: the
# same scenes on every run of this awk).
for seed in $(seq 1 60); do
    name=rows-$seed
    awk -v seed="$seed" 'function u(a, b) { return a + (b - a) * rand() }
        function p3(s) { return sprintf("%.4f %.4f %.4f", u(-s, s), u(-s, s), u(-s, s)) }
        BEGIN { srand(seed); s = seed % 4 == 0 ? 200 : 6
            print "image 96 72"
            print "background 0.1 0.1 0.2"
            h = u(0.5, 3) * s
            printf "camera perspective eye %.4f %.4f %.4f gaze %.4f %.4f %.4f up 0 1 0 fov %.2f\n", u(-s, s), h, u(-s, s), u(-1, 1), -u(0.2, 1), u(-1, 1), u(10, 150)
            print "ambient 0.2 0.2 0.2"
            nl = 1 + (seed % 3 == 0)
            for (i = 0; i < nl && seed > 40; i++)
                printf "light directional direction %.4f %.4f %.4f color 0.7 0.7 0.7 shadows on\n", u(-1, 1), rand() < 0.3 ? -u(0.02, 0.15) : -u(0.2, 1), u(-1, 1)
            for (i = 0; i < nl && seed <= 40; i++) {
                lh = rand() < 0.3 ? u(0.05, 0.5) : u(0.5, 3) * s
                if (rand() < 0.7) printf "light point position %.4f %.4f %.4f color 0.7 0.7 0.7 shadows on\n", u(-s, s), lh, u(-s, s)
                else printf "light spot position %.4f %.4f %.4f direction %.4f -1 %.4f angle %.1f color 0.7 0.7 0.7 shadows on\n", u(-s, s), lh, u(-s, s), u(-0.5, 0.5), u(-0.5, 0.5), u(20, 80)
            }
            printf "plane point 0 0 0 normal %.4f 1 %.4f color 0.8 0.7 0.6 material lambert\n", seed % 2 ? 0 : u(-0.3, 0.3), seed % 2 ? 0 : u(-0.3, 0.3)
            no = 2 + int(rand() * 6)
            for (i = 0; i < no; i++) {
                k = rand(); r = u(0.05, 0.6) * s / 6
                cx = u(-s, s) / 2; cy = u(0, 1.5) * s / 6 + r; cz = u(-s, s) / 2
                if (k < 0.5) printf "sphere center %.4f %.4f %.4f radius %.4f color 0.2 0.6 0.9 material lambert\n", cx, cy, cz, r
                else if (k < 0.8) printf "box min %.4f %.4f %.4f max %.4f %.4f %.4f color 0.9 0.3 0.2 material lambert\n", cx - r, cy - r, cz - r, cx + r, cy + r / 2, cz + r
                else printf "triangle a %.4f %.4f %.4f b %.4f %.4f %.4f c %.4f %.4f %.4f color 0.3 0.9 0.3 material lambert\n", cx - r, cy, cz, cx + r, cy + r, cz, cx, cy, cz + r
            }
        }' >"$out/$name.scene"
    scenes+=("$out/$name.scene")
done
# The random plane scenes' awk: u(a, b) uniform, and no spheres on the
# plane (radius up to a tenth of the scale s, within s / 2 of the origin).
AWK_PLANES='function u(a, b) { return a + (b - a) * rand() }
function spheres(no, s,   i, r) {
    for (i = 0; i < no; i++) {
        r = u(0.05, 0.6) * s / 6
        printf "sphere center %.4f %.4f %.4f radius %.4f color 0.2 0.6 0.9 material lambert\n", u(-s, s) / 2, u(0, 1.5) * s / 6 + r, u(-s, s) / 2, r
    }
}'
# Random planes under spot lights only (1 or 2 spots of 3 to 80 degrees,
# near the plane or far, aimed down at random; a Lambert or a Phong
# plane, level or tilted; a camera of 10 to 150 degrees, near or far):
# the runs' blocks that no spot reaches (light/shade.c,
# shade_flat_spot_blocks) against the pixel-by-pixel light sum.
for seed in $(seq 1 24); do
    name=spots-$seed
    awk -v seed="$seed" "$AWK_PLANES"'
        BEGIN { srand(seed + 500); s = seed % 4 == 0 ? 200 : 6
            print "image 96 72"
            print "background 0.1 0.1 0.2"
            h = u(0.3, 3) * s
            printf "camera perspective eye %.4f %.4f %.4f gaze %.4f %.4f %.4f up 0 1 0 fov %.2f\n", u(-s, s), h, u(-s, s), u(-1, 1), -u(0.1, 1), u(-1, 1), u(10, 150)
            printf "ambient %.3f %.3f %.3f\n", u(0.05, 0.4), u(0.05, 0.4), u(0.05, 0.4)
            nl = 1 + (seed % 3 == 0)
            for (i = 0; i < nl; i++)
                printf "light spot position %.4f %.4f %.4f direction %.4f -1 %.4f angle %.1f color %.2f %.2f %.2f shadows %s\n", u(-s, s), rand() < 0.3 ? u(0.05, 0.5) : u(0.5, 3) * s, u(-s, s), u(-1, 1), u(-1, 1), u(3, 80), u(0.3, 1), u(0.3, 1), u(0.3, 1), rand() < 0.5 ? "on" : "off"
            mat = seed % 2 ? "material lambert" : sprintf("material phong specular %.2f %.2f %.2f exponent %d", u(0, 1), u(0, 1), u(0, 1), int(u(1, 200)))
            printf "plane point 0 0 0 normal %.4f 1 %.4f color %.3f %.3f %.3f %s\n", seed % 3 ? 0 : u(-0.4, 0.4), seed % 3 ? 0 : u(-0.4, 0.4), u(0, 1), u(0, 1), u(0, 1), mat
            no = 1 + int(rand() * 4)
            spheres(no, s)
        }' >"$out/$name.scene"
    scenes+=("$out/$name.scene")
done
# Random Phong planes under point lights, with a spot in some (1 to 3
# lights, some near the plane, some far, some behind it; exponents 1 to
# 1000, every specular colour; level or tilted; a camera of 10 to 150
# degrees, near the plane or far, some looking along it): the runs'
# blocks without a specular term (light/shade.c, shade_flat_phong_blocks,
# the Lambert sum there) against the pixel-by-pixel Phong sum.
for seed in $(seq 1 40); do
    name=phong-points-$seed
    awk -v seed="$seed" "$AWK_PLANES"'
        BEGIN { srand(seed + 900); s = seed % 5 == 0 ? 300 : 6
            print "image 96 72"
            print "background 0.1 0.1 0.2"
            h = seed % 7 == 0 ? u(0.01, 0.2) : u(0.3, 3) * s
            printf "camera perspective eye %.4f %.4f %.4f gaze %.4f %.4f %.4f up 0 1 0 fov %.2f\n", u(-s, s), h, u(-s, s), u(-1, 1), seed % 7 == 0 ? -u(0, 0.1) : -u(0.1, 1), u(-1, 1), u(10, 150)
            printf "ambient %.3f %.3f %.3f\n", u(0, 0.4), u(0, 0.4), u(0, 0.4)
            nl = 1 + int(rand() * 3)
            for (i = 0; i < nl; i++) {
                lh = rand() < 0.2 ? -u(0.1, 2) * s : rand() < 0.3 ? u(0.05, 0.5) : u(0.5, 3) * s
                if (i == 1 && seed % 3 == 0)
                    printf "light spot position %.4f %.4f %.4f direction %.4f -1 %.4f angle %.1f color %.2f %.2f %.2f shadows %s\n", u(-s, s), lh, u(-s, s), u(-1, 1), u(-1, 1), u(3, 80), u(0, 1), u(0, 1), u(0, 1), rand() < 0.5 ? "on" : "off"
                else
                    printf "light point position %.4f %.4f %.4f color %.2f %.2f %.2f shadows %s\n", u(-s, s), lh, u(-s, s), u(0, 1), u(0, 1), u(0, 1), rand() < 0.5 ? "on" : "off"
            }
            k = rand() < 0.2 ? 1 + int(rand() * 12) : int(u(13, 1000))
            printf "plane point 0 %.4f 0 normal %.4f 1 %.4f color %.3f %.3f %.3f material phong specular %.2f %.2f %.2f exponent %d\n", seed % 4 ? 0 : u(-1, 1), seed % 3 ? 0 : u(-0.6, 0.6), seed % 3 ? 0 : u(-0.6, 0.6), u(0, 1), u(0, 1), u(0, 1), u(0, 1), u(0, 1), u(0, 1), k
            no = int(rand() * 4)
            spheres(no, s)
        }' >"$out/$name.scene"
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
        check "$scene ($num): the default build == without nearest first and shadow rows" cmp -s "$out/$name-$num-a.ppm" "$out/$name-$num-b.ppm"
    done
done
echo "order: $n frames, $refused refused by both at 96x72"
check "frames compared" test $((n - refused)) -gt 250
report order.sh
