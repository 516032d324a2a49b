#!/usr/bin/env bash
# Firmware in QEMU (issue 3): every board renders every seed scene in Q16.16
# byte-identical to the host tool; the counter is calibrated; no ELF links a
# heap; a sphere-only image carries no other primitive's code; faults and
# hangs fail loudly; RGB565 and streaming modes work. make test runs the
# quick scope (each section says what it leaves to make test-full).
set -u
. "$(dirname "$0")/lib.sh"
out=$BUILD/tests/qemu
mkdir -p "$out"
BOARDS="mps2-an385 mps2-an386 microbit"
SIZE=160x120
M="make -s --no-print-directory BUILD=$BUILD"

# run_fw VARS...: make qemu with those variables; output in $out/run.log
runs=0
run_fw() {
    runs=$((runs + 1))
    progress "qemu.sh: run $runs: $*"
    $M qemu "$@" >"$out/run.log" 2>&1
}

progress "qemu.sh: counter calibration on $BOARDS"
for b in $BOARDS; do
    line=$($M calibrate BOARD=$b 2>&1 | grep instructions=)
    n=$(sed -nE 's/.*instructions=([0-9]+) .*/\1/p' <<<"$line")
    echo "$b calibration: $line"
    check "$b: counter calibration 2000000 +- 50 (got $n)" test -n "$n" -a "${n:-0}" -ge 2000000 -a "${n:-0}" -le 2000050
done

# make test: two seed scenes through the per-scene firmware (firmware/main.c)
# on the M3 (the checks below use their ELFs); every seed scene runs in one
# on-board batch per board below (the same core, set up from the same
# scenec output). make test-full: the per-scene firmware for every seed
# scene on every board.
SEED_BOARDS=$BOARDS SEED_SCENES=$(ls scenes/abb*.scene)
full || SEED_BOARDS=mps2-an385 SEED_SCENES="scenes/abb6-sphere.scene scenes/abb9-two-spheres.scene"
for b in $SEED_BOARDS; do
    for scene in $SEED_SCENES; do
        name=$(basename "$scene" .scene)
        "$FXRT" render "$scene" --number q16 --size $SIZE -o "$out/$name-host.ppm"
        if run_fw SCENE=$scene BOARD=$b NUMBER=q16 SIZE=$SIZE; then
            ok
            echo "$b $name: $(grep instructions= "$out/run.log")"
            check "$b $name: frame set up on the board byte-identical to the host q16 render" \
                cmp -s "$out/$name-host.ppm" "$BUILD/qemu/$b/$name-q16-$SIZE.ppm"
        else
            bad "$b $name: firmware run failed: $(tail -n 5 "$out/run.log")"
        fi
    done
done

# The world in flash (scene_world, host/scenec_world.c) against the same
# world built at boot through the API (SCENE_BOOT_WORLD): the same frame as
# the host's, a read-only scene_world in one and none in the other, and
# less RAM in the first (by at least the world's records). On the
# micro:bit, whose RAM it is for (every other run here renders from flash
# on every board).
for b in microbit; do
    name=abb9-two-spheres fm=full
    [[ $b == microbit ]] && fm=stream
    "$FXRT" render scenes/$name.scene --number q16 --size $SIZE -o "$out/$name-host.ppm"
    declare -A ram=()
    for tag in flash boot; do
        extra=() && [[ $tag == boot ]] && extra=(FW_TAG=boot FW_EXTRA=-DSCENE_BOOT_WORLD)
        suffix= && [[ $tag == boot ]] && suffix=-boot
        check "$b $name (world: $tag) run" run_fw SCENE=scenes/$name.scene BOARD=$b NUMBER=q16 SIZE=$SIZE "${extra[@]}"
        check "$b $name (world: $tag): frame byte-identical to the host q16 render" \
            cmp -s "$out/$name-host.ppm" "$BUILD/qemu/$b/$name-q16-$SIZE$suffix.ppm"
        ram[$tag]=$(sed -nE 's/.*ram_static=([0-9]+).*/\1/p' "$out/run.log")
    done
    flash=$BUILD/fw/$b/$name-q16-$SIZE-$fm/fxrt.elf boot=$BUILD/fw/$b/$name-q16-$SIZE-$fm-boot/fxrt.elf
    # (linker/sections.ld puts read-only data in .text, in flash)
    sec=$(arm-none-eabi-objdump -t "$flash" | awk '$NF == "scene_world" {print $(NF-2)}')
    check "$b: scene_world is in the flash build's .text, in flash (section: $sec)" test "$sec" = .text
    check "$b: no scene_world in the boot build" bash -c "! arm-none-eabi-nm '$boot' | grep -q scene_world"
    wsz=$(arm-none-eabi-nm -S "$flash" | awk '$NF == "scene_world" {print $2}')
    echo "$b $name: static RAM ${ram[flash]} B with the world in flash, ${ram[boot]} B built at boot (scene_world 0x${wsz:-?} B)"
    check "$b: the world in flash takes its size off RAM (${ram[flash]} + 0x${wsz:-?} <= ${ram[boot]})" \
        test -n "$wsz" -a -n "${ram[flash]}" -a -n "${ram[boot]}" -a "$((${ram[flash]:-0} + 16#${wsz:-0}))" -le "${ram[boot]:-0}"
done

# The world in flash with what the seed scenes lack: lights and
# materials, a glass model and bounces (nodes/glass-ico80), an ellipsoid
# and a parallelepiped (the course's exercise-5 scenes): each rendered on
# the M3 from its scene_world, at 40x30, against the host (supersampling's
# two fields: make bench's samples scenes). (The on-board batches below and in qemu_lit.sh
# and qemu_trace.sh build their worlds at boot.)
for scene in scenes/nodes/glass-ico80.scene scenes/nodes/course-u5-ellipsoid.scene scenes/nodes/course-u5-box.scene; do
    name=$(basename "$scene" .scene)
    "$FXRT" render "$scene" --number q16 --size 40x30 -o "$out/$name-host.ppm"
    check "mps2-an385 $name (world in flash) run" run_fw SCENE=$scene BOARD=mps2-an385 NUMBER=q16 SIZE=40x30
    check "mps2-an385 $name (world in flash): frame byte-identical to the host q16 render" \
        cmp -s "$out/$name-host.ppm" "$BUILD/qemu/mps2-an385/$name-q16-40x30.ppm"
done

# Every stress scene that is not meant to be rejected, set up on each board
# (camera, objects and forms built at run time from the scene's own values,
# as firmware/main.c does) and compared with the host's Q16.16 render at the
# scene's own size (64x48 when it has no image line). To keep this to a few
# builds, tests/onboard_main.c renders a batch of scenes per ELF: all of
# them on the MPS2 boards, batches that fit 16 KB on the micro:bit. A scene
# that does not fit the micro:bit's RAM on its own is skipped with the
# linker's reason, and counted.
onb=$out/onboard
rm -rf "$onb"
mkdir -p "$onb/scenes" "$onb/host"
# onb_prepare SCENE NAME SIZE: the scene compiled for the on-board program
# ($onb/scenes/NAME) and the host's q16 frame ($onb/host/NAME.ppm); fails
# with the reason counted.
onb_prepare() {
    mkdir -p "$onb/scenes/$2"
    if ! "$BUILD/fxrt-scenec" "$1" --number q16 --size $3 --out "$onb/scenes/$2" 2>"$onb/scenec.log"; then
        bad "fxrt-scenec $1: $(cat "$onb/scenec.log")"
        return 1
    fi
    "$FXRT" render "$1" --number q16 --size $3 -o "$onb/host/$2.ppm" || { bad "host render of $1"; return 1; }
}
stress=()
for scene in scenes/stress/*.scene; do
    grep -q '^# expect: rejected:' "$scene" && continue
    name=$(basename "$scene" .scene)
    # The trace stress scenes run on every board in tests/qemu_trace.sh.
    [[ $name == trace-* ]] && continue
    size=$(awk '$1 == "image" { print $2 "x" $3; exit }' "$scene")
    size=${size:-64x48}
    onb_prepare "$scene" "$name" $size && stress+=("$name")
done
seeds=()
if ! full; then
    for scene in scenes/abb*.scene; do
        name=$(basename "$scene" .scene)
        onb_prepare "$scene" "$name" $SIZE && seeds+=("$name")
    done
fi
# cfgv NAME MACRO: a value of the scene's compiled configuration (no
# process: tests/lib.sh cfg_read).
cfgv() { cfg_value "$onb/scenes/$1/scene_config.h" "$2"; }
. "$(dirname "$0")/onboard_lib.sh"
: >"$onb/verdicts.txt"
# The two MPS2 batches build and run side by side (two cores). make test
# runs the stress batch on the M3 and the micro:bit only (the M4F runs the
# same Thumb-2 integer code; make test-full runs it there too).
STRESS_BOARDS="mps2-an385 mps2-an386"
full || STRESS_BOARDS=mps2-an385
for b in $STRESS_BOARDS; do
    (onb_batch $b all "${stress[@]}" >"$onb/verdicts-$b.txt" || for n in "${stress[@]}"; do
        echo "FAIL $b $n: the batch does not fit the board" >>"$onb/verdicts-$b.txt"
    done) &
done
wait
for b in $STRESS_BOARDS; do cat "$onb/verdicts-$b.txt" >>"$onb/verdicts.txt"; done
# micro:bit: the stress scenes in as few ELFs as fit its 16 KB (onb_fit,
# tests/onboard_lib.sh: a batch that overflows is halved until the halves
# fit; the linker decides). The whole set (50 scenes) does not fit one ELF,
# so it starts as two halves (onb_fit_halves). A scene whose row buffers
# alone (at least 7 B per column) exceed 16 KB is not built; one that does
# not fit on its own is skipped with the linker's reason. Both are counted.
mb=()
for n in "${stress[@]}"; do
    w=$(cfgv $n FXRT_RENDER_MAX_WIDTH)
    if [ $((7 * w)) -gt 16384 ]; then
        echo "SKIP microbit $n: does not fit 16 KB of RAM ($w columns need more than $((7 * w)) B of row buffers; not built)" \
            >>"$onb/verdicts.txt"
    else
        mb+=("$n")
    fi
done
if [ ${#mb[@]} -gt 0 ]; then
    ONB_TOO_BIG=SKIP onb_fit_halves microbit b "${mb[@]}" >"$onb/batches-microbit.txt"
    grep -E '^(stack|batch) ' "$onb/batches-microbit.txt"
    grep -vE '^(stack|batch) ' "$onb/batches-microbit.txt" >>"$onb/verdicts.txt"
fi
if [ ${#seeds[@]} -gt 0 ]; then
    for b in $BOARDS; do
        onb_batch $b seeds "${seeds[@]}" >"$onb/seed-verdicts-$b.txt"
        rc=$?
        cat "$onb/seed-verdicts-$b.txt"
        check "$b: the six seed scenes fit one on-board batch" test $rc -eq 0
        check "$b: every seed scene at $SIZE set up on the board byte-identical to the host q16 render" \
            test "$(grep -c '^PASS ' "$onb/seed-verdicts-$b.txt")" -eq ${#seeds[@]}
    done
fi
sort -k2,3 "$onb/verdicts.txt"
while read -r verdict b name rest; do
    case $verdict in
    PASS) ok ;;
    SKIP) ;;
    *) bad "$b $name $rest" ;;
    esac
done <"$onb/verdicts.txt"
nb=$(($(wc -w <<<"$STRESS_BOARDS") + 1))
for b in $STRESS_BOARDS microbit; do
    echo "on-board set-up, ${#stress[@]} stress scenes on $b: $(grep -c "^PASS $b " "$onb/verdicts.txt") byte-identical," \
        "$(grep -c "^SKIP $b " "$onb/verdicts.txt") skipped (too large for the board)"
done
nv=$(grep -cE '^(PASS|SKIP) ' "$onb/verdicts.txt")
check "every (board, stress scene) pair has a verdict ($nv of $((nb * ${#stress[@]})))" test "$nv" -eq $((nb * ${#stress[@]}))
others=$(grep '^SKIP' "$onb/verdicts.txt" | grep -v '^SKIP microbit' || true)
check "only the micro:bit skips, and only for RAM ($others)" test -z "$others"
check "every non-rejected stress scene but trace-* was compiled ($(ls scenes/stress/*.scene | wc -l) scenes)" \
    test ${#stress[@]} -eq "$(grep -L '^# expect: rejected:' scenes/stress/*.scene | grep -vc '/trace-')"

# The straightforward reference loop on target gives the same frames as
# the fast renderer (the skipping and stepping change only the cost).
REF_SCENES=$(ls scenes/abb*.scene)
full || REF_SCENES="scenes/abb9-two-spheres.scene"
for scene in $REF_SCENES; do
    name=$(basename "$scene" .scene)
    check "mps2-an385 $name reference run" run_fw SCENE=$scene BOARD=mps2-an385 NUMBER=q16 SIZE=$SIZE \
        FW_TAG=ref FW_EXTRA=-DFXRT_RENDERER=2
    check "mps2-an385 $name: reference frame == fast frame" \
        cmp -s "$BUILD/qemu/mps2-an385/$name-q16-$SIZE.ppm" "$BUILD/qemu/mps2-an385/$name-q16-$SIZE-ref.ppm"
done

# One full-size frame on the default board. Without SIZE= make qemu takes
# the scene's own size (its image line, 640 430), as fxrt render does.
"$FXRT" render scenes/abb9-two-spheres.scene --number q16 -o "$out/big-host.ppm"
rm -f "$BUILD/qemu/mps2-an385/abb9-two-spheres-q16-640x430.ppm"
check "mps2-an385 640x430 run (size from the scene)" run_fw SCENE=scenes/abb9-two-spheres.scene BOARD=mps2-an385 NUMBER=q16
check "mps2-an385 640x430 byte-identical" cmp -s "$out/big-host.ppm" "$BUILD/qemu/mps2-an385/abb9-two-spheres-q16-640x430.ppm"

# A scene path with spaces and its own small size: the frame is
# NAME-q16-48x32.ppm, spaces in NAME as '_'; SIZE= still wins over the scene.
mkdir -p "$out/with space"
sed 's/^image .*/image 48 32/' scenes/abb8-triangle.scene >"$out/with space/tri angle.scene"
"$FXRT" render "$out/with space/tri angle.scene" -o "$out/space-host.ppm"
rm -f "$BUILD/qemu/mps2-an385/tri_angle-q16-48x32.ppm"
# (make test: only the SIZE= run below; the size from the scene is checked
# by the 640x430 run above)
if full; then
    check "scene path with spaces: make qemu runs" run_fw SCENE="$out/with space/tri angle.scene"
    check "scene path with spaces: frame named by the scene's size, identical to fxrt render" \
        cmp -s "$out/space-host.ppm" "$BUILD/qemu/mps2-an385/tri_angle-q16-48x32.ppm"
fi
"$FXRT" render "$out/with space/tri angle.scene" --size 20x10 -o "$out/space-host-20.ppm"
check "SIZE= overrides the scene's size" run_fw SCENE="$out/with space/tri angle.scene" SIZE=20x10
check "SIZE= frame identical to fxrt render --size" \
    cmp -s "$out/space-host-20.ppm" "$BUILD/qemu/mps2-an385/tri_angle-q16-20x10.ppm"
# Another scene whose name maps to the same build directory (tri_angle,
# as scenes/lit/room and scenes/bench/room share one): the firmware is
# rebuilt for it, not the previous scene's reused.
mkdir -p "$out/other"
cp scenes/abb6-sphere.scene "$out/other/tri_angle.scene"
"$FXRT" render "$out/other/tri_angle.scene" --size 20x10 -o "$out/other-host-20.ppm"
check "a scene with the same build name runs" run_fw SCENE="$out/other/tri_angle.scene" SIZE=20x10
check "a scene with the same build name: its own frame, not the previous scene's" \
    cmp -s "$out/other-host-20.ppm" "$BUILD/qemu/mps2-an385/tri_angle-q16-20x10.ppm"

# Float and double builds on target (the float frame is IEEE-exact too).
# The M4F's float run is a lit scene: its channels take every value, and
# its hard-float build rounds them with port_channel_f32's VCVT and USAT.
NUMBER_RUNS="mps2-an385:double:abb9-two-spheres mps2-an386:float:lit/shadows microbit:float:abb9-two-spheres"
full && NUMBER_RUNS="mps2-an385:float:abb9-two-spheres $NUMBER_RUNS"
for bns in $NUMBER_RUNS; do
    IFS=: read -r b n sc <<<"$bns"
    name=$(basename "$sc")
    "$FXRT" render scenes/$sc.scene --number $n --size $SIZE -o "$out/host-$n.ppm"
    check "$b $n $name run" run_fw SCENE=scenes/$sc.scene BOARD=$b NUMBER=$n SIZE=$SIZE
    echo "$b $n $name: $(grep instructions= "$out/run.log")"
    check "$b $n $name frame identical to the host $n render" cmp -s "$out/host-$n.ppm" "$BUILD/qemu/$b/$name-$n-$SIZE.ppm"
done
check "M4F float build uses FPU instructions" \
    bash -c "arm-none-eabi-objdump -d $BUILD/fw/mps2-an386/shadows-float-$SIZE-full/fxrt.elf | grep -qE 'v(sqrt|mul|add)[a-z]*\.f32'"
check "M4F float build rounds its channels with VCVT and USAT (port_channel_f32)" \
    bash -c "arm-none-eabi-objdump -d $BUILD/fw/mps2-an386/shadows-float-$SIZE-full/fxrt.elf | grep -A2 'vcvt.s32.f32' | grep -q usat"

# Streaming on the big boards and RGB565 full frames.
check "mps2-an385 streaming run" run_fw SCENE=scenes/abb7-box.scene BOARD=mps2-an385 SIZE=$SIZE FB=stream
"$FXRT" render scenes/abb7-box.scene --size $SIZE -o "$out/box-host.ppm"
check "streaming frame identical" cmp -s "$out/box-host.ppm" "$BUILD/qemu/mps2-an385/abb7-box-q16-$SIZE.ppm"
check "rgb565 run" run_fw SCENE=scenes/abb7-box.scene BOARD=mps2-an385 SIZE=$SIZE FW_TAG=rgb565 FW_EXTRA=-DFXRT_PIXEL=2
line=$("$FXRT" compare "$out/box-host.ppm" "$BUILD/qemu/mps2-an385/abb7-box-q16-$SIZE-rgb565.ppm")
echo "rgb565 vs rgb888: $line"
check "rgb565 frame: same pixels up to 565 quantisation" grep -qE 'max_err=[0-7] ' <<<"$line"

# No heap in any firmware ELF; every ELF built above is checked.
elfs=$(find "$BUILD/fw" "$onb" -name '*.elf')
check "found firmware ELFs" test -n "$elfs"
for e in $elfs; do
    heap=$(arm-none-eabi-nm "$e" | awk '{print $NF}' | grep -xE 'malloc|_malloc_r|_sbrk|_sbrk_r|free|_free_r' || true)
    check "$e: no malloc/_sbrk (found: $heap)" test -z "$heap"
done

# Unused primitive kinds are not linked. The fast renderer no longer calls
# the world-space kernels (depth comes from its own forms), so the check is
# on size: each single-kind image is smaller than the same scene built for
# every kind (scenec --all-kinds), and has no other kind's kernel.
syms() { arm-none-eabi-nm "$BUILD/fw/mps2-an385/$1-q16-$SIZE-full/fxrt.elf" | awk '{print $NF}'; }
others=$(syms abb6-sphere | grep -E '^geom_(plane|triangle|box)_' || true)
check "sphere-only firmware has no plane/triangle/box code (found: $others)" test -z "$others"
text_of() { arm-none-eabi-size -A "$1" | awk '$1 == ".text" {print $2}'; }
KIND_SCENES=abb6-sphere
full && KIND_SCENES="abb6-sphere abb5-plane abb7-box"
for k in $KIND_SCENES; do
    check "$k all-kinds build" run_fw SCENE=scenes/$k.scene BOARD=mps2-an385 NUMBER=q16 SIZE=$SIZE \
        FW_ALL_KINDS=1 FW_TAG=allkinds
    one=$(text_of "$BUILD/fw/mps2-an385/$k-q16-$SIZE-full/fxrt.elf")
    all=$(text_of "$BUILD/fw/mps2-an385/$k-q16-$SIZE-full-allkinds/fxrt.elf")
    echo "$k: .text $one bytes (its kinds), $all bytes (every kind)"
    check "$k firmware is smaller than its every-kind build ($one < $all)" test "${one:-0}" -lt "${all:-0}"
done

# Faults and hangs fail the make target with a clear message, and no image
# (make test: the M3 and the M0; make test-full: every board).
FAULT_BOARDS="mps2-an385 microbit"
full && FAULT_BOARDS=$BOARDS
for b in $FAULT_BOARDS; do
    rm -f "$BUILD/qemu/$b/abb6-sphere-q16-$SIZE-fault.ppm"
    if run_fw SCENE=scenes/abb6-sphere.scene BOARD=$b SIZE=$SIZE FW_TAG=fault FW_EXTRA=-DFXRT_TEST_FAULT; then
        bad "$b: a faulting firmware must fail"
    else
        ok
    fi
    check "$b: fault reported ($(grep -m1 FAULT "$out/run.log"))" grep -q "FAULT: HardFault\|FAULT: UsageFault" "$out/run.log"
    check "$b: no image from a faulting run" test ! -e "$BUILD/qemu/$b/abb6-sphere-q16-$SIZE-fault.ppm"
done
if FXRT_QEMU_TIMEOUT=3 run_fw SCENE=scenes/abb6-sphere.scene SIZE=$SIZE FW_TAG=hang FW_EXTRA=-DFXRT_TEST_HANG; then
    bad "a hanging firmware must fail"
else
    ok
fi
check "hang reported as a timeout" grep -q "timed out" "$out/run.log"
report qemu
