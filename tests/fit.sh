#!/usr/bin/env bash
# The bench scene set and the firmware fit check.
#  - scenes/bench/ and scenes/models/: the generated scenes and models
#    equal scenes/bench/mkscenes.sh's and scenes/models/mkmodels.sh's
#    output; every bench scene renders on the host with the fast renderer
#    byte-identical to the reference loop; the meshes and the 48-object
#    scene hold what their names promise.
#  - the 48+ mixed objects scene renders on the micro:bit (160x120,
#    streaming), byte-identical to the host's Q16.16 frame, leaving the
#    stack margin unused, built again without its spheres' row state
#    (which does not fit; mixed16's does, and is kept); the firmware's
#    stack check can fail a run. The triangles' shadow edges: kept where
#    they fit, left out without a point or spot light with shadows, and
#    built again without where they do not fit.
#  - firmware/fit.sh: a scene too big for the micro:bit fails at build time
#    with "does not fit" and what fits, a non-zero exit and no ELF; the
#    count it states is right: that many spheres build and render, one more
#    does not fit; a frame that alone overflows RAM says so.
set -u
. "$(dirname "$0")/lib.sh"
out=$BUILD/tests/fit
rm -rf "$out"
mkdir -p "$out"
unset MAKEFLAGS MFLAGS MAKELEVEL
M="make -s --no-print-directory BUILD=$BUILD"
SIZE=160x120

# --- generated scenes are the generator's output --------------------------
generated scenes/bench/mkscenes.sh "$out/gen"
generated scenes/models/mkmodels.sh "$out/models"

count() { grep -cE "^$1 " "$2"; }
check "mesh-cube has 12 triangles" test "$(count triangle scenes/bench/mesh-cube.scene)" -eq 12
check "mesh-ico80 has 80 triangles" test "$(count triangle scenes/bench/mesh-ico80.scene)" -eq 80
# a closed mesh: every edge is shared by exactly two faces
closed() {
    awk '/^triangle / { for (i = 0; i < 3; i++) { v[i] = $(3 + 4 * i) " " $(4 + 4 * i) " " $(5 + 4 * i) }
                        for (i = 0; i < 3; i++) { a = v[i]; b = v[(i + 1) % 3]; e[a < b ? a "|" b : b "|" a]++ } }
         END { n = 0; for (k in e) { n++; if (e[k] != 2) exit 1 } exit n == 0 }' "$1"
}
check "mesh-cube is closed (every edge in two faces)" closed scenes/bench/mesh-cube.scene
check "mesh-ico80 is closed (every edge in two faces)" closed scenes/bench/mesh-ico80.scene
m48=scenes/bench/mixed48.scene
n48=$(($(count plane $m48) + $(count sphere $m48) + $(count triangle $m48) + $(count box $m48)))
check "mixed48 has >= 48 objects ($n48) and a plane, spheres, triangles and boxes" \
    test "$n48" -ge 48 -a "$(count plane $m48)" -ge 1 -a "$(count sphere $m48)" -ge 1 \
    -a "$(count triangle $m48)" -ge 1 -a "$(count box $m48)" -ge 1

for scene in scenes/bench/*.scene; do
    name=$(basename "$scene" .scene)
    if "$FXRT" render "$scene" -o "$out/$name-fast.ppm" 2>"$out/$name.err" &&
        "$FXRT" render "$scene" --renderer reference -o "$out/$name-ref.ppm" 2>>"$out/$name.err"; then
        check "$name: q16 fast == reference on the host" cmp -s "$out/$name-fast.ppm" "$out/$name-ref.ppm"
    else
        bad "$name: fxrt render failed: $(cat "$out/$name.err")"
    fi
done

# --- firmware: build on the micro:bit, expecting a fit or not -------------------
# fw SCENE [make vars...]: 0 when it builds; the output in $out/last.log
fw() {
    local scene=$1
    shift
    $M fw SCENE="$scene" BOARD=microbit NUMBER=q16 SIZE=$SIZE "$@" >"$out/last.log" 2>&1
}
elf_of() { echo "$BUILD/fw/microbit/$(basename "$1" .scene)-q16-$SIZE-${2:-stream}/fxrt.elf"; }
# expect_nofit SCENE DESC [make vars]: fails with the message, non-zero, no ELF
expect_nofit() {
    local scene=$1 desc=$2
    shift 2
    if fw "$scene" "$@"; then
        bad "$desc: built, expected 'does not fit'"
        return 1
    fi
    check "$desc: message names the scene and the board" grep -qE "^$scene: does not fit microbit \(16384 B RAM[^)]*\): needs [0-9]+ B" "$out/last.log"
    check "$desc: no raw linker error" bash -c "! grep -qiE 'overflowed|collect2|/ld: ' '$out/last.log'"
    check "$desc: no ELF" test ! -e "$(elf_of "$scene" "${FB_MODE:-stream}")"
    return 0
}
# render_same SCENE DESC: make qemu on the micro:bit equals the host's frame
render_same() {
    local scene=$1 desc=$2 name
    name=$(basename "$scene" .scene)
    if ! $M qemu SCENE="$scene" BOARD=microbit NUMBER=q16 SIZE=$SIZE >"$out/last.log" 2>&1; then
        bad "$desc: make qemu failed: $(tail -n 5 "$out/last.log")"
        return
    fi
    "$FXRT" render "$scene" --size $SIZE -o "$out/$name-host.ppm"
    check "$desc: micro:bit frame == host q16 frame" cmp -s "$BUILD/qemu/microbit/$name-q16-$SIZE.ppm" "$out/$name-host.ppm"
}

# The 48+ object scene (issue 9 sec. 3): it builds for the micro:bit and
# renders there byte-identical to the host (docs/BENCHMARKS.md, "RAM"),
# without its spheres' row state, which does not fit (firmware/fit.sh
# compiles it again without). So does mixed16, whose spheres keep their
# row state there (it fits: the deeper visibility paths of a sphere among
# others).
for scene in "$m48" scenes/bench/mixed16.scene; do
    name=$(basename "$scene" .scene)
    if fw "$scene"; then
        ok
        cfg=$(dirname "$(elf_of "$scene")")/scene_config.h
        if [ "$name" = mixed48 ]; then
            check "$name on the micro:bit: built without the spheres' row state (it does not fit)" \
                grep -q '^#define FXRT_COHERENT_SPHERES 0 /\* firmware/fit.sh' "$cfg"
        else
            check "$name on the micro:bit: every sphere keeps its row state (it fits)" \
                grep -q '^#define FXRT_COHERENT_SPHERES FXRT_MAX_SPHERES$' "$cfg"
        fi
        render_same "$scene" "$name on the micro:bit"
        # firmware/main.c fails a run that leaves less than FXRT_STACK_MARGIN
        # of the reserved stack unused; the report shows the figures
        used=$(sed -nE 's/.*stack_used=([0-9]+).*/\1/p' "$out/last.log")
        size=$(sed -nE 's/.*stack_size=([0-9]+).*/\1/p' "$out/last.log")
        margin=$(sed -nE 's/^#define FXRT_STACK_MARGIN ([0-9]+).*/\1/p' core/fxrt_config.h)
        echo "$name on the micro:bit: stack_used=$used of stack_size=$size (margin $margin)"
        check "$name on the micro:bit: stack used ($used B) + margin ($margin B) <= reserved ($size B)" \
            test -n "$used" -a -n "$size" -a -n "$margin" -a "$((${used:-0} + ${margin:-0}))" -le "${size:-0}"
    else
        bad "$name does not build for the micro:bit: $(grep -v 'make: \*\*\*' "$out/last.log" | head -n 5)"
    fi
done

# The triangles' shadow edges (light/shadow.c: 26 B per point or spot
# light and triangle): kept where they fit (the lit room), not emitted by
# the scene compiler where no point or spot light casts shadows (a
# directional light only), and a scene that fits only without them is
# built again without them (firmware/fit.sh) and renders as on the host:
# 41 triangles under two point lights.
edges_cfg() { echo "$(dirname "$(elf_of "$1")")/scene_config.h"; }
if fw scenes/lit/room.scene; then
    check "room on the micro:bit: keeps its shadow edges (they fit)" \
        grep -q '^#define FXRT_SHADOW_EDGES 1$' "$(edges_cfg scenes/lit/room.scene)"
else
    bad "room does not build for the micro:bit: $(head -n 5 "$out/last.log")"
fi
if fw scenes/lit/course-lambert-directional.scene; then
    check "course-lambert-directional (a directional light): no shadow edges" \
        grep -q '^#define FXRT_SHADOW_EDGES 0$' "$(edges_cfg scenes/lit/course-lambert-directional.scene)"
else
    bad "course-lambert-directional does not build for the micro:bit: $(head -n 5 "$out/last.log")"
fi
tris=$out/tris41.scene
{
    echo "# 41 triangles on a floor under two point lights (tests/fit.sh)"
    echo "camera perspective eye 0 3 8 gaze 0 -0.3 -1 up 0 1 0 fov 60"
    echo "ambient 0.1 0.1 0.1"
    echo "light point position 2 6 3 color 1 1 1"
    echo "light point position -3 5 2 color 0.5 0.5 0.5"
    echo "plane point 0 0 0 normal 0 1 0 color 0.8 0.8 0.8 material lambert"
    for i in $(seq 0 40); do
        awk -v i="$i" 'BEGIN { x = i % 7 - 3; z = -int(i / 7)
            printf "triangle a %g 0 %g b %g 0 %g c %g 0.8 %g color 0.9 0.3 0.2 material lambert\n", x, z, x + 0.6, z, x, z }'
    done
} >"$tris"
if fw "$tris"; then
    check "41 triangles, two point lights: built again without shadow edges (they do not fit)" \
        grep -q '^#define FXRT_SHADOW_EDGES 0 /\* firmware/fit.sh' "$(edges_cfg "$tris")"
    render_same "$tris" "41 triangles, two point lights, on the micro:bit"
else
    bad "41 triangles, two point lights: does not build for the micro:bit: $(head -n 5 "$out/last.log")"
fi

# The stack check can fail: a margin as large as the whole reservation
# leaves no run passing, with the check's message and a non-zero exit.
if $M qemu SCENE=scenes/abb5-plane.scene BOARD=microbit NUMBER=q16 SIZE=16x12 FW_TAG=stackcheck \
    FW_EXTRA=-DFXRT_STACK_MARGIN=65536 >"$out/last.log" 2>&1; then
    bad "FXRT_STACK_MARGIN=65536: the run passed, expected the stack check to fail it"
else
    check "FXRT_STACK_MARGIN=65536: the run fails with the stack message" \
        grep -q "fxrt firmware: stack: the run left less than FXRT_STACK_MARGIN" "$out/last.log"
fi

# Far too big: every kind at the host's capacity. Whatever a record takes,
# 320 objects do not fit 16 KB.
big=$out/toobig.scene
awk 'BEGIN {
    print "image 160 120"
    print "camera perspective eye 0 0 6 gaze 0 0 -1 up 0 1 0 fov 50"
    for (i = 0; i < 64; i++) {
        x = i % 8 - 4; y = int(i / 8) - 4
        printf "plane point 0 0 %d normal 0 0 1 color 0.5 0.5 0.5\n", -10 - i
        printf "sphere center %g %g -3 radius 0.3 color 0.9 0.2 0.2\n", x, y
        printf "box min %g %g -5 max %g %g -4.5 color 0.2 0.2 0.9\n", x, y, x + 0.5, y + 0.5
        printf "triangle a %g %g -2 b %g %g -2 c %g %g -2 color 0.2 0.9 0.2\n", x, y, x + 0.5, y, x, y + 0.5
        printf "triangle a %g %g -2.5 b %g %g -2.5 c %g %g -2.5 color 0.9 0.9 0.2\n", x, y + 0.5, x + 0.5, y, x + 0.5, y + 0.5
    } }' >"$big"
if expect_nofit "$big" "320 objects"; then
    check "320 objects: message gives counts per kind" \
        grep -qE "at most [0-9]+ spheres, or [0-9]+ triangles, or [0-9]+ boxes, or [0-9]+ planes fit" "$out/last.log"
    ns=$(sed -nE 's/.*at most ([0-9]+) spheres.*/\1/p' "$out/last.log")
    if [ -n "$ns" ] && [ "$ns" -ge 1 ]; then
        # the stated count is right: ns spheres fit (and render), ns + 1 do not
        mk() {
            echo "camera perspective eye 0 0 8 gaze 0 0 -1 up 0 1 0 fov 60"
            awk -v n="$1" 'BEGIN { for (i = 1; i <= n; i++)
                printf "sphere center %d %d %d radius 0.4 color 0.%d 0.5 0.5\n", i % 9 - 4, int(i / 9) % 7 - 3, -int(i / 63), i % 9 + 1 }'
        }
        if [ "$ns" -le 64 ]; then
            mk "$ns" >"$out/fit-spheres.scene"
            render_same "$out/fit-spheres.scene" "$ns spheres (the stated maximum)"
        fi
        if [ $((ns + 1)) -le 64 ]; then
            mk $((ns + 1)) >"$out/over-spheres.scene"
            # make test: the verdict alone (FIT_QUICK=1, no per-kind probes)
            FIT_QUICK=$(scope 0 1) expect_nofit "$out/over-spheres.scene" \
                "$((ns + 1)) spheres (one over the stated maximum)" >/dev/null || true
        fi
    else
        bad "320 objects: no sphere count in the message"
    fi
fi

# A full 160x120 RGB888 frame (57600 B) cannot fit 16 KB whatever the scene.
# (make test: the verdict alone, FIT_QUICK=1; make test-full: the analysis)
if full; then
    FB_MODE=full expect_nofit scenes/abb6-sphere.scene "abb6 full frame on the micro:bit" FB=full &&
        check "full frame on the micro:bit: says no object fits" grep -q "so no object fits" "$out/last.log"
else
    FIT_QUICK=1 FB_MODE=full expect_nofit scenes/abb6-sphere.scene "abb6 full frame on the micro:bit" FB=full
fi

report fit
