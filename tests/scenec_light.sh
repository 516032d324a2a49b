#!/usr/bin/env bash
# fxrt-scenec and lighting: the configuration it emits (FXRT_MAX_LIGHTS 0
# when every material is flat, else max(1, lights); FXRT_SHADOWS 1 only
# when a light casts shadows; FXRT_PHONG 1 only with a phong object), and
# the emitted tables compile and hold the same fractions in q16, float and
# double (read back by a small host program per number type).
set -u
. "$(dirname "$0")/lib.sh"
SCENEC=${SCENEC:-$BUILD/fxrt-scenec}
CC=${CC:-gcc}
tmp=$BUILD/tests/scenec_light
rm -rf "$tmp"
mkdir -p "$tmp"

cam="camera perspective eye 4 4 4 gaze -1 -1 -1 up 0 1 0 fov 45"
sphere="sphere center 1 1 1 radius 0.5 color 0 1 0"
plane="plane point 0 0 0 normal 0 1 0 color 1 0 0"

# cfg NAME MACRO: the value scenec wrote for MACRO.
cfg() { sed -nE "s/^#define $2 (-?[0-9]+)\$/\1/p" "$tmp/$1/scene_config.h"; }

# expect NAME SCENE_TEXT MAX_LIGHTS SHADOWS PHONG SCENE_LIGHTS
expect() {
    local name=$1 text=$2
    mkdir -p "$tmp/$name"
    printf '%s\n' "$text" >"$tmp/$name.scene"
    if ! "$SCENEC" "$tmp/$name.scene" --number q16 --size 32x24 --out "$tmp/$name" 2>"$tmp/$name.err"; then
        bad "$name: fxrt-scenec failed: $(cat "$tmp/$name.err")"
        return
    fi
    local got
    got="$(cfg "$name" FXRT_MAX_LIGHTS) $(cfg "$name" FXRT_SHADOWS) $(cfg "$name" FXRT_PHONG) $(cfg "$name" SCENE_LIGHTS)"
    if [ "$got" = "$3 $4 $5 $6" ]; then ok; else bad "$name: MAX_LIGHTS SHADOWS PHONG LIGHTS = $got, want $3 $4 $5 $6"; fi
}

expect flat-no-lights "$cam
$sphere" 0 0 0 0
# Lights and ambient, but every material flat: lighting compiled out.
expect flat-with-lights "$cam
ambient 0.2 0.2 0.2
light point position 4 4 4 color 1 1 1
light spot position 4 4 4 direction -1 -1 -1 angle 10 color 1 1 1
$sphere material flat
$plane" 0 0 0 0
expect lambert-no-lights "$cam
$sphere material lambert" 1 0 0 0
expect lambert-no-shadows "$cam
light point position 4 4 4 color 1 1 1 shadows off
light directional direction -1 -1 -1 color 1 1 1 shadows off
$sphere material lambert
$plane" 2 0 0 2
expect lambert-shadows "$cam
light point position 4 4 4 color 1 1 1 shadows off
light directional direction -1 -1 -1 color 1 1 1
$plane material lambert" 2 1 0 2
expect phong-shadows "$cam
light point position 4 4 4 color 1 1 1
light directional direction -1 -1 -1 color 1 1 1 shadows off
light spot position 4 4 4 direction -1 -1 -1 angle 12.86 color 1 1 1 shadows off
$sphere material phong specular 1 1 1 exponent 64
$plane" 3 1 1 3
expect phong-no-shadows "$cam
light point position 4 4 4 color 1 1 1 shadows off
$plane material phong specular 0.5 0.5 0.5 exponent 1" 1 0 1 1
lights8=""
for i in 1 2 3 4 5 6 7 8; do lights8+="light point position $i 4 4 color 0.1 0.1 0.1 shadows off"$'\n'; done
expect eight-lights "$cam
$lights8$sphere material lambert" 8 0 0 8

# The emitted tables, compiled per number type and printed back: kinds,
# flags, exponents and fractions must agree exactly across the types.
cat >"$tmp/readback.c" <<'C'
#include <stdio.h>
#include "fxrt.h"
#include "scene_data.h"
static double D(num_t v)
{
#if FXRT_NUMBER == FXRT_Q16
    return v / 65536.0;
#else
    return (double)v;
#endif
}
int main(void)
{
    printf("ambient %.17g %.17g %.17g\n", D(scene_ambient.r), D(scene_ambient.g), D(scene_ambient.b));
    for (int i = 0; i < SCENE_LIGHTS; i++) {
        const fxrt_light_t *l = &scene_lights[i];
        printf("light %d pos %.17g %.17g %.17g dir %.17g %.17g %.17g angle %.4f color %.17g %.17g %.17g shadows %d\n",
               (int)l->kind, D(l->position.x), D(l->position.y), D(l->position.z), D(l->direction.x),
               D(l->direction.y), D(l->direction.z), D(l->angle_deg), D(l->color.r), D(l->color.g), D(l->color.b),
               (int)l->shadows);
    }
    for (int i = 0; i < SCENE_OBJECTS; i++) {
        const material_t *m = &scene_objects[i].material;
        printf("object %d material %d exponent %d specular %.17g %.17g %.17g\n", i, (int)m->kind, (int)m->exponent,
               D(m->specular.r), D(m->specular.g), D(m->specular.b));
    }
    return 0;
}
C
scene=tests/scenes/lit-keywords.scene
for n in q16 float double; do
    id=$([ $n = q16 ] && echo 1 || { [ $n = float ] && echo 2 || echo 3; })
    mkdir -p "$tmp/rb-$n"
    if "$SCENEC" "$scene" --number $n --out "$tmp/rb-$n" 2>"$tmp/rb-$n.err" &&
        $CC -std=c11 -Wall -Wextra -Werror -DFXRT_NUMBER=$id -include "$tmp/rb-$n/scene_config.h" -Icore -I"$tmp/rb-$n" \
            -o "$tmp/rb-$n/readback" "$tmp/readback.c" 2>>"$tmp/rb-$n.err" &&
        "$tmp/rb-$n/readback" >"$tmp/rb-$n.txt"; then
        ok
    else
        bad "$scene ($n): emit, compile or run failed: $(head -c 600 "$tmp/rb-$n.err")"
    fi
done
check "lit-keywords: 3 lights and 4 materials read back" test "$(grep -c '^light' "$tmp/rb-q16.txt") $(grep -c '^object' "$tmp/rb-q16.txt")" = "3 4"
check "lit-keywords: q16 and float tables agree" cmp -s "$tmp/rb-q16.txt" "$tmp/rb-float.txt"
check "lit-keywords: q16 and double tables agree" cmp -s "$tmp/rb-q16.txt" "$tmp/rb-double.txt"
# Every colour is emitted in 1/255 units, as the API takes it (the world
# holds a light's or the ambient's as a fraction: tests/test_fxrt.c,
# test_scene_light.c). 0.1 is round(0.1 * 255 * 65536) / 65536 = 25.5 in
# every type.
check "ambient 0.1 is 25.5 of 255" grep -qx "ambient 25.5 25.5 25.5" "$tmp/rb-double.txt"
check "phong exponent and white specular on the sphere" grep -qx "object 1 material 2 exponent 64 specular 255 255 255" "$tmp/rb-float.txt"

report scenec_light
