#!/usr/bin/env bash
# The renderer links only what a scene needs (issue 11): tests/skip_app.c
# built for the Cortex-M0 with --gc-sections in three configurations:
#   flat        FXRT_MAX_LIGHTS 0: no shading, shadow or key code at all
#   lit, no shadows   FXRT_SHADOWS 0: shading, but no shadow-ray code
#   lit, shadows      both (the control: the symbols exist and are found)
# and none of them links a libm function (pow, acos, cos, sqrt, ...). They
# are compiled with the firmware's warnings as errors: a lit scene whose
# lights all have "shadows off" once failed to build its firmware
# (an unused parameter with FXRT_SHADOWS 0).
# Issue 12, with the configuration the scene compiler emits for each case:
#   lit, no bounce    FXRT_MAX_DEPTH 0 (no reflective or transparent
#                     material), samples 1: no bounce code (trace_bounces,
#                     geom_sphere_exit, geom_box_exit), no supersampling
#                     (render_sample_row, cam_fine)
#   bounce            a reflective sphere and a transparent box, depth 2:
#                     the bounce code is there (the control)
#   samples 2         FXRT_MAX_SAMPLES 2, FXRT_ADAPTIVE 0: render_sample_row
#                     is there, the adaptive one-sample key pass is not
#                     (its ray caster world_hit: the fast renderer never
#                     casts a primary ray)
#   samples 2 adaptive  world_hit is there (the control)
#   run mode          samples 2 with one primitive kind at a time, M0 and
#                     M3, compiled with the firmware's -Werror warnings
#   ablation          each switch of make bench-ablation (FXRT_ABLATE), M0
#                     and M3, the renderer compiled with -Werror (make
#                     test-full only)
#                     (run mode, make test: each kind on one of the two
#                     cores in turn; make test-full: on both)
# Then the counters of tests/test_skip.c (built with FXRT_STATS 1) run.
set -u
. "$(dirname "$0")/lib.sh"
out=$BUILD/tests/skip
mkdir -p "$out"
CORE=$(cd core && ls */*.c | sed "s/\.c$//")
LIGHTING='^(shade_point|shade_point_k|shade_object|shade_object_k|shade_consts|render_shade_row|shadow_[a-z0-9_]+|world_occluded|world_set_material|world_add_light|geom_(plane|sphere|triangle|box)_surface)([.].*)?$'
SHADOW='^(shadow_[a-z0-9_]+|world_occluded)([.].*)?$' # all of core/light/shadow.c
LIBM='^(pow|powf|acos|acosf|cos|cosf|sin|sinf|sqrt|sqrtf|exp|log)$'

# NAME.elf: skip_app with the core, linked without a board's linker script
# (its symbols are all that is read), so without the core's stack
# reservation (FXRT_STACK_RESERVE 0), as a program that reserves its stack
# some other way. At -O1, not the firmware's -O2 (a third less compile
# time): what a build links follows the configuration's constants, which
# gcc folds at any level, and -O2 only removes more (it inlines more and
# deletes more dead code), so a function absent here is absent there.
build() { # NAME FLAGS...
    local name=$1
    shift
    local srcs=()
    for f in $CORE; do srcs+=(core/$f.c); done
    arm-none-eabi-gcc -std=c11 -Wall -Wextra -Wpedantic -Wshadow -Werror -O1 -mcpu=cortex-m0 -mthumb -ffreestanding -ffunction-sections -fdata-sections \
        -DFXRT_NUMBER=1 -DFXRT_MAX_PLANES=1 -DFXRT_MAX_SPHERES=1 -DFXRT_MAX_TRIANGLES=1 -DFXRT_MAX_BOXES=1 \
        -DFXRT_RENDER_MAX_WIDTH=32 -DFXRT_STACK_RESERVE=0 "$@" -Icore tests/skip_app.c "${srcs[@]}" \
        -nostartfiles --specs=nano.specs --specs=nosys.specs -Wl,--gc-sections -Wl,-e,main \
        -o "$out/$name.elf" 2>"$out/$name.log"
}
syms() { arm-none-eabi-nm "$out/$1.elf" | awk '$2 ~ /^[TtWw]$/ {print $3}' | sort -u; }

if ! command -v arm-none-eabi-gcc >/dev/null; then
    bad "arm-none-eabi-gcc not installed (run make deps)"
    report skip
    exit 1
fi
check "flat build links" build flat -DFXRT_MAX_LIGHTS=0 -DSKIP_LIT=0
check "lit build without shadows links" build noshadow -DFXRT_MAX_LIGHTS=1 -DFXRT_SHADOWS=0 -DFXRT_PHONG=0 -DSKIP_LIT=1
check "lit build with shadows links" build shadow -DFXRT_MAX_LIGHTS=1 -DFXRT_SHADOWS=1 -DFXRT_PHONG=0 -DSKIP_LIT=1
# issue 12 (render state for samples 2 needs 2 x 32 columns)
LIT12=(-DFXRT_MAX_LIGHTS=1 -DFXRT_SHADOWS=1 -DFXRT_PHONG=1 -DSKIP_LIT=1 -UFXRT_RENDER_MAX_WIDTH -DFXRT_RENDER_MAX_WIDTH=64)
# two builds at a time (two cores); each records its status
build_rc() { build "$@"; echo $? >"$out/$1.rc"; }
build_rc nobounce "${LIT12[@]}" -DFXRT_MAX_DEPTH=0 -DFXRT_MAX_SAMPLES=1 &
build_rc bounce "${LIT12[@]}" -DFXRT_MAX_DEPTH=2 -DFXRT_MAX_SAMPLES=1 -DSKIP_BOUNCE=1
wait
build_rc samples2 "${LIT12[@]}" -DFXRT_MAX_DEPTH=0 -DFXRT_MAX_SAMPLES=2 -DFXRT_ADAPTIVE=0 -DSKIP_SAMPLES=2 &
build_rc adaptive "${LIT12[@]}" -DFXRT_MAX_DEPTH=0 -DFXRT_MAX_SAMPLES=2 -DFXRT_ADAPTIVE=1 -DSKIP_SAMPLES=2 -DSKIP_ADAPTIVE=1
wait
for b in nobounce bounce samples2 adaptive; do
    check "$b build links ($(head -c 200 "$out/$b.log"))" test "$(cat "$out/$b.rc")" = 0
done
BOUNCE='^(trace_bounces|geom_sphere_exit|geom_box_exit)$'
SAMPLE='^(render_sample_row|cam_fine)$'
found=$(syms nobounce | grep -E "$BOUNCE" || true)
check "no reflective or transparent material links no bounce code (found: $found)" test -z "$found"
found=$(syms bounce | grep -cE "$BOUNCE")
check "the bounce build links trace_bounces, geom_sphere_exit and geom_box_exit (control; $found of 3)" test "$found" -eq 3
found=$(syms nobounce | grep -E "$SAMPLE" || true)
check "samples 1 links no supersampling code (found: $found)" test -z "$found"
found=$(syms bounce | grep -E "$SAMPLE" || true)
check "samples 1 with bounces links no supersampling code (found: $found)" test -z "$found"
found=$(syms samples2 | grep -cE "$SAMPLE")
check "samples 2 links render_sample_row and cam_fine (control; $found of 2)" test "$found" -eq 2
found=$(syms samples2 | grep -E '^world_hit$' || true)
check "samples 2 without adaptive links no one-sample key pass (found: $found)" test -z "$found"
check "samples 2 adaptive links the key pass's world_hit (control)" bash -c "arm-none-eabi-nm '$out/adaptive.elf' | grep -qw world_hit"
for b in nobounce bounce samples2 adaptive; do
    m=$(arm-none-eabi-nm "$out/$b.elf" | awk '{print $NF}' | grep -E "$LIBM" || true)
    check "$b: no libm function linked (found: $m)" test -z "$m"
done
# Run mode of the sampling pass (core/vis/ and core/frame/) with samples 2 and one primitive kind at a time (the
# scene compiler sets the other capacities to 0), on the M0 (no
# FXRT_SPHERE_SEARCH) and the M3: every helper is used or marked, as the
# firmware's -Wall -Wextra -Werror builds need (a plane-only scene once
# failed on the M0 with an unused sphere helper).
caps_dir=$out/runs-caps
mkdir -p "$caps_dir"
# wanted CPU_INDEX ITEM_INDEX: make test builds each item (kind, ablation
# switch) on one of the two cores, taken in turn; make test-full on both.
wanted() { full || [ $((($1 + $2) % 2)) -eq 0 ]; }
ci=0
for cpu in cortex-m0 cortex-m3; do
    ki=0
    for kind in PLANES SPHERES TRIANGLES BOXES; do
        ki=$((ki + 1))
        wanted $ci $ki || continue
        caps="-DFXRT_MAX_PLANES=0 -DFXRT_MAX_SPHERES=0 -DFXRT_MAX_TRIANGLES=0 -DFXRT_MAX_BOXES=0"
        caps=${caps/FXRT_MAX_$kind=0/FXRT_MAX_$kind=1}
        log=$caps_dir/$cpu-$kind.log
        # shellcheck disable=SC2086
        (cd "$caps_dir" && arm-none-eabi-gcc -std=c11 -Wall -Wextra -Wpedantic -Wshadow -Wmissing-prototypes -Werror -O2 \
            -mcpu=$cpu -mthumb -ffreestanding -c -DFXRT_NUMBER=1 $caps -DFXRT_MAX_LIGHTS=0 -DFXRT_MAX_SAMPLES=2 \
            -DFXRT_ADAPTIVE=0 -DFXRT_RENDER_MAX_WIDTH=64 -I"$OLDPWD/core" "$OLDPWD"/core/vis/*.c \
            "$OLDPWD"/core/frame/*.c) >"$log" 2>&1
        check "samples 2, only FXRT_MAX_$kind > 0, $cpu: run mode compiles with -Werror ($(grep -m1 error "$log"))" \
            test ! -s "$log"
    done
    ci=$((ci + 1))
done
# Every ablation switch of make bench-ablation (firmware/ablate.sh) compiles
# with the firmware's -Werror on the M0 and the M3 (FXRT_ABLATE_SPANS once left
# render_scan_flat's parameters unused and broke the ablation run). These
# are benchmark switches, not a user's configuration: make test-full
# checks them (make test's time), and layers.sh's q16-ablate build there.
abl_dir=$out/ablation-caps
mkdir -p "$abl_dir"
abl_switches="FXRT_ABLATE_BOUNDS FXRT_ABLATE_STEP FXRT_ABLATE_LONE FXRT_ABLATE_SPANS FXRT_ABLATE_ZRANGE FXRT_ABLATE_COHERENCE FXRT_ABLATE_HOIST FXRT_ABLATE_ORDER"
full || abl_switches=
ci=0
for cpu in cortex-m0 cortex-m3; do # the builds side by side (each in a directory of its own)
    si=0
    for sw in $abl_switches; do
        si=$((si + 1))
        wanted $ci $si || continue
        mkdir -p "$abl_dir/$cpu-$sw"
        (cd "$abl_dir/$cpu-$sw" && arm-none-eabi-gcc -std=c11 -Wall -Wextra -Wpedantic -Wshadow -Wmissing-prototypes \
            -Werror -O2 -mcpu=$cpu -mthumb -ffreestanding -c -DFXRT_NUMBER=1 -DFXRT_ABLATE=$sw -DFXRT_MAX_LIGHTS=0 \
            -I"$OLDPWD/core" "$OLDPWD"/core/vis/*.c) \
            >"$abl_dir/$cpu-$sw.log" 2>&1 &
    done
    ci=$((ci + 1))
done
wait
ci=0
for cpu in cortex-m0 cortex-m3; do
    si=0
    for sw in $abl_switches; do
        si=$((si + 1))
        wanted $ci $si || continue
        log=$abl_dir/$cpu-$sw.log
        check "FXRT_ABLATE=$sw, $cpu: the renderer compiles with -Werror ($(grep -m1 error "$log"))" test ! -s "$log"
    done
    ci=$((ci + 1))
done
flat=$(syms flat | grep -E "$LIGHTING" || true)
check "flat materials link no lighting code (found: $flat)" test -z "$flat"
noshadow=$(syms noshadow | grep -E "$SHADOW" || true)
check "no shadow-casting light links no shadow-ray code (found: $noshadow)" test -z "$noshadow"
check "the lit build links shade_object_k (control)" bash -c "arm-none-eabi-nm '$out/noshadow.elf' | grep -qw shade_object_k"
# (world_occluded itself is the bounce rays' entry: shadow_blocked calls
# the loops, shadow_occluded and its culling instances shadow_occluded_pt
# and _dir, which may be inlined, so this build drops it.)
check "the shadow build links shadow_blocked, a shadow_occluded loop and shadow_cull_setup (control)" \
    bash -c "arm-none-eabi-nm '$out/shadow.elf' | grep -qw shadow_blocked && arm-none-eabi-nm '$out/shadow.elf' | grep -q ' shadow_occluded' && arm-none-eabi-nm '$out/shadow.elf' | grep -qw shadow_cull_setup"
for b in flat noshadow shadow; do
    m=$(arm-none-eabi-nm "$out/$b.elf" | awk '{print $NF}' | grep -E "$LIBM" || true)
    check "$b: no libm function linked (found: $m)" test -z "$m"
done
for b in flat noshadow shadow nobounce bounce samples2 adaptive; do
    echo "$b: text $(arm-none-eabi-size "$out/$b.elf" | awk 'NR == 2 {print $1}') bytes"
done
for n in q16 double; do
    bin=$BUILD/tests/test_skip_$n
    if [ -x "$bin" ]; then
        "$bin" >"$out/counters-$n.log" 2>&1
        rc=$?
        line=$(tail -n 1 "$out/counters-$n.log")
        p=$(sed -nE 's/.*: ([0-9]+) passed, ([0-9]+) failed/\1/p' <<<"$line")
        f=$(sed -nE 's/.*: ([0-9]+) passed, ([0-9]+) failed/\2/p' <<<"$line")
        PASSED=$((PASSED + ${p:-0}))
        FAILED=$((FAILED + ${f:-1}))
        [ "$rc" -eq 0 ] || cat "$out/counters-$n.log" >&2
    else
        bad "$bin missing"
    fi
done
report skip
