#!/usr/bin/env bash
# fxrt-scenec and issue 12's keywords: the configuration it emits
# (FXRT_MAX_DEPTH = the scene's depth when some object is reflective or
# transparent, else 0; FXRT_MAX_SAMPLES = the scene's samples; FXRT_ADAPTIVE
# 1 only for 'samples N adaptive'; FXRT_PHONG also for reflective objects;
# FXRT_RENDER_MAX_WIDTH = samples x width; beyond FXRT_MAX_DIM refused), and the
# emitted tables (materials' reflection and index, scene_depth,
# scene_samples, scene_adaptive) compile with the core's headers and hold
# the same values in q16, float and double (read back by a small host
# program per number type).
set -u
. "$(dirname "$0")/lib.sh"
SCENEC=${SCENEC:-$BUILD/fxrt-scenec}
CC=${CC:-gcc}
tmp=$BUILD/tests/scenec_trace
rm -rf "$tmp"
mkdir -p "$tmp"

cam="camera perspective eye 8 8 8 gaze -1 -1 -1 up 0 1 0 fov 45"
light="light point position 8 8 0 color 1 1 1"
sphere="sphere center 0 1 0 radius 1 color 0 1 0"
plane="plane point 0 0 0 normal 0 1 0 color 0.1 0.1 0.1"
refl="material reflective specular 1 1 1 exponent 64 reflection 0.5 0.5 0.5"
glass="material transparent index 1.33"

# cfg NAME MACRO: the value scenec wrote for MACRO.
cfg() { sed -nE "s/^#define $2 (-?[0-9]+)\$/\1/p" "$tmp/$1/scene_config.h"; }

# expect NAME SIZE SCENE_TEXT MAX_DEPTH MAX_SAMPLES ADAPTIVE PHONG RENDER_MAX_WIDTH
expect() {
    local name=$1 size=$2 text=$3
    mkdir -p "$tmp/$name"
    printf '%s\n' "$text" >"$tmp/$name.scene"
    if ! "$SCENEC" "$tmp/$name.scene" --number q16 --size "$size" --out "$tmp/$name" 2>"$tmp/$name.err"; then
        bad "$name: fxrt-scenec failed: $(cat "$tmp/$name.err")"
        return
    fi
    local got
    got="$(cfg "$name" FXRT_MAX_DEPTH) $(cfg "$name" FXRT_MAX_SAMPLES) $(cfg "$name" FXRT_ADAPTIVE)"
    got+=" $(cfg "$name" FXRT_PHONG) $(cfg "$name" FXRT_RENDER_MAX_WIDTH)"
    if [ "$got" = "$4 $5 $6 $7 $8" ]; then ok; else
        bad "$name: MAX_DEPTH MAX_SAMPLES ADAPTIVE PHONG RENDER_MAX_WIDTH = $got, want $4 $5 $6 $7 $8"
    fi
}

# No reflective or transparent object: bounces compiled out, whatever the depth.
expect flat 32x24 "$cam
$sphere" 0 1 0 0 32
expect flat-depth-samples 32x24 "$cam
depth 6
samples 4
$sphere" 0 4 0 0 128
expect lambert-depth 32x24 "$cam
$light
depth 16
$sphere material lambert" 0 1 0 0 32
expect phong-adaptive 32x24 "$cam
$light
samples 2 adaptive
$sphere material phong specular 1 1 1 exponent 8" 0 2 1 1 64
# Reflective or transparent: the scene's depth (default 4); reflective
# needs the Phong term, transparent alone does not.
expect reflective-default 32x24 "$cam
$light
$sphere $refl" 4 1 0 1 32
expect reflective-depth-6 32x24 "$cam
$light
depth 6
samples 4
$sphere $refl
$plane material lambert" 6 4 0 1 128
expect transparent-16 32x24 "$cam
depth 16
samples 16 adaptive
$sphere $glass" 16 16 1 0 512
expect transparent-depth-0 32x24 "$cam
depth 0
$sphere $glass
$plane $refl" 0 1 0 1 32
# samples x width up to FXRT_MAX_DIM (4096) is what the renderer holds;
# beyond it the scene is refused at its samples line, with no output (a
# board could not set the frame up).
expect wide 256x8 "$cam
samples 16
$sphere" 0 16 0 0 4096
mkdir -p "$tmp/too-wide"
printf '%s\nsamples 16\n%s\n' "$cam" "$sphere" >"$tmp/too-wide.scene"
if "$SCENEC" "$tmp/too-wide.scene" --number q16 --size 1024x8 --out "$tmp/too-wide" 2>"$tmp/too-wide.err"; then
    bad "too-wide: fxrt-scenec accepted samples 16 at width 1024"
else
    check "too-wide: FILE:LINE: samples x width ($(head -c 160 "$tmp/too-wide.err"))" \
        grep -q "^$tmp/too-wide.scene:2: samples 16 at width 1024: samples x width (16384) wider than FXRT_MAX_DIM (4096)" "$tmp/too-wide.err"
    check "too-wide: no output" test -z "$(ls -A "$tmp/too-wide")"
fi

# The emitted tables, compiled per number type against the core's headers
# (so the emitted macros must pass core/fxrt_config.h's checks) and printed
# back: kinds, exponents, fractions, indices, depth and samples must agree
# exactly across the types.
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
    printf("depth %d samples %d adaptive %d\n", (int)scene_depth, (int)scene_samples, (int)scene_adaptive);
    printf("config depth %d samples %d adaptive %d\n", FXRT_MAX_DEPTH, FXRT_MAX_SAMPLES, FXRT_ADAPTIVE);
    for (int i = 0; i < SCENE_OBJECTS; i++) {
        const material_t *m = &scene_objects[i].material;
        printf("object %d material %d exponent %d specular %.17g %.17g %.17g reflection %.17g %.17g %.17g "
               "index %.17g\n",
               i, (int)m->kind, (int)m->exponent, D(m->specular.r), D(m->specular.g), D(m->specular.b),
               D(m->reflection.r), D(m->reflection.g), D(m->reflection.b), D(m->index));
    }
    return 0;
}
C
scene=$tmp/readback.scene
cat >"$scene" <<S
$cam
ambient 0.25 0.25 0.25
$light
depth 7
samples 3 adaptive
$sphere material reflective specular 1 0.3 0 exponent 64 reflection 0.5 0.999999 0.00002
$sphere $glass
box min -3 0 -3 max -2 1 -2 color 1 1 1 material transparent index 0.01
triangle a 3 0 0 b 4 0 0 c 3 1 0 color 1 0 0 material transparent index 100
$plane material phong specular 1 1 1 exponent 8
$sphere
S
for n in q16 float double; do
    id=$([ $n = q16 ] && echo 1 || { [ $n = float ] && echo 2 || echo 3; })
    mkdir -p "$tmp/rb-$n"
    if "$SCENEC" "$scene" --number $n --size 32x24 --out "$tmp/rb-$n" 2>"$tmp/rb-$n.err" &&
        $CC -std=c11 -Wall -Wextra -Werror -DFXRT_NUMBER=$id -include "$tmp/rb-$n/scene_config.h" -Icore -I"$tmp/rb-$n" \
            -o "$tmp/rb-$n/readback" "$tmp/readback.c" 2>>"$tmp/rb-$n.err" &&
        "$tmp/rb-$n/readback" >"$tmp/rb-$n.txt"; then
        ok
    else
        bad "readback ($n): emit, compile or run failed: $(head -c 600 "$tmp/rb-$n.err")"
    fi
done
check "readback: q16 and float tables agree" cmp -s "$tmp/rb-q16.txt" "$tmp/rb-float.txt"
check "readback: q16 and double tables agree" cmp -s "$tmp/rb-q16.txt" "$tmp/rb-double.txt"
check "depth, samples and adaptive read back" grep -qx "depth 7 samples 3 adaptive 1" "$tmp/rb-q16.txt"
check "config: depth 7, samples 3, adaptive" grep -qx "config depth 7 samples 3 adaptive 1" "$tmp/rb-float.txt"
q() { awk -v n="$1" 'BEGIN { printf "%.17g", n / 65536 }'; }
# Colours in 1/255 units, quantised to 2^-16 of a unit: round(x * 255 *
# 65536): 0.3 -> 5013504 (76.5); 0.5 -> 127.5; 0.999999 -> 16711663.29 ->
# 16711663; 0.00002 -> 334.23 -> 334.
check "reflective: kind, exponent, specular and reflection as multiples of 2^-16 of 1/255" \
    grep -qx "object 0 material 3 exponent 64 specular 255 76.5 0 reflection 127.5 $(q 16711663) $(q 334) index 0" "$tmp/rb-double.txt"
# 1.33 -> 87162.88 -> 87163/65536; 0.01 -> 656/65536 (655 is below 0.01); 100 exact.
check "transparent 1.33: index 87163/65536, nothing else" \
    grep -qx "object 1 material 4 exponent 0 specular 0 0 0 reflection 0 0 0 index $(q 87163)" "$tmp/rb-double.txt"
check "transparent 0.01: index 656/65536" grep -q "^object 2 material 4 .* index $(q 656)\$" "$tmp/rb-float.txt"
check "transparent 100: index 100" grep -q "^object 3 material 4 .* index 100\$" "$tmp/rb-q16.txt"
check "phong: no reflection, no index" \
    grep -qx "object 4 material 2 exponent 8 specular 255 255 255 reflection 0 0 0 index 0" "$tmp/rb-q16.txt"
check "flat: all zero" grep -qx "object 5 material 0 exponent 0 specular 0 0 0 reflection 0 0 0 index 0" "$tmp/rb-q16.txt"
# Defaults when the scene has no depth or samples line.
check "defaults: scene_depth 4, scene_samples 1, not adaptive" \
    grep -q "static const int32_t scene_depth = 4;.*static const int32_t scene_samples = 1;.*scene_adaptive = false;" \
    <(tr '\n' ' ' <"$tmp/flat/scene_data.h")

report scenec_trace
