#!/usr/bin/env bash
# Firmware in QEMU (issue 3): every board renders every seed scene in Q16.16
# byte-identical to the host tool; the counter is calibrated; no ELF links a
# heap; a sphere-only image carries no other primitive's code; faults and
# hangs fail loudly; RGB565 and streaming modes work.
set -u
. "$(dirname "$0")/lib.sh"
out=$BUILD/tests/qemu
mkdir -p "$out"
BOARDS="mps2-an385 mps2-an386 microbit"
SIZE=160x120
M="make -s --no-print-directory BUILD=$BUILD"

# run_fw VARS...: make qemu with those variables; output in $out/run.log
run_fw() { $M qemu "$@" >"$out/run.log" 2>&1; }

for b in $BOARDS; do
    line=$($M calibrate BOARD=$b 2>&1 | grep instructions=)
    n=$(sed -nE 's/.*instructions=([0-9]+) .*/\1/p' <<<"$line")
    echo "$b calibration: $line"
    check "$b: counter calibration 2000000 +- 50 (got $n)" test -n "$n" -a "${n:-0}" -ge 2000000 -a "${n:-0}" -le 2000050
done

for b in $BOARDS; do
    for scene in scenes/abb*.scene; do
        name=$(basename "$scene" .scene)
        "$FXRT" render "$scene" --number q16 --size $SIZE -o "$out/$name-host.ppm"
        if run_fw SCENE=$scene BOARD=$b NUMBER=q16 SIZE=$SIZE; then
            ok
            echo "$b $name: $(grep instructions= "$out/run.log")"
            check "$b $name: frame byte-identical to the host q16 render" \
                cmp -s "$out/$name-host.ppm" "$BUILD/qemu/$b/$name-q16.ppm"
        else
            bad "$b $name: firmware run failed: $(tail -n 5 "$out/run.log")"
        fi
    done
done

# The straightforward reference loop on target gives the same frames as
# the fast renderer (the skipping and stepping change only the cost).
for scene in scenes/abb*.scene; do
    name=$(basename "$scene" .scene)
    check "mps2-an385 $name reference run" run_fw SCENE=$scene BOARD=mps2-an385 NUMBER=q16 SIZE=$SIZE \
        FW_TAG=ref FW_EXTRA=-DFXRT_RENDERER=2
    check "mps2-an385 $name: reference frame == fast frame" \
        cmp -s "$BUILD/qemu/mps2-an385/$name-q16.ppm" "$BUILD/qemu/mps2-an385/$name-q16-ref.ppm"
done

# One full-size frame on the default board.
"$FXRT" render scenes/abb9-two-spheres.scene --number q16 -o "$out/big-host.ppm"
check "mps2-an385 640x430 run" run_fw SCENE=scenes/abb9-two-spheres.scene BOARD=mps2-an385 NUMBER=q16 SIZE=640x430
check "mps2-an385 640x430 byte-identical" cmp -s "$out/big-host.ppm" "$BUILD/qemu/mps2-an385/abb9-two-spheres-q16.ppm"

# Float and double builds on target (the float frame is IEEE-exact too).
for bn in mps2-an385:float mps2-an385:double mps2-an386:float microbit:float; do
    b=${bn%:*} n=${bn#*:}
    "$FXRT" render scenes/abb9-two-spheres.scene --number $n --size $SIZE -o "$out/host-$n.ppm"
    check "$b $n run" run_fw SCENE=scenes/abb9-two-spheres.scene BOARD=$b NUMBER=$n SIZE=$SIZE
    echo "$b $n: $(grep instructions= "$out/run.log")"
    check "$b $n frame identical to the host $n render" cmp -s "$out/host-$n.ppm" "$BUILD/qemu/$b/abb9-two-spheres-$n.ppm"
done
check "M4F float build uses FPU instructions" \
    bash -c "arm-none-eabi-objdump -d $BUILD/fw/mps2-an386/abb9-two-spheres-float-$SIZE-full/fxrt.elf | grep -qE 'v(sqrt|mul|add)[a-z]*\.f32'"

# Streaming on the big boards and RGB565 full frames.
check "mps2-an385 streaming run" run_fw SCENE=scenes/abb7-box.scene BOARD=mps2-an385 FB=stream
"$FXRT" render scenes/abb7-box.scene --size $SIZE -o "$out/box-host.ppm"
check "streaming frame identical" cmp -s "$out/box-host.ppm" "$BUILD/qemu/mps2-an385/abb7-box-q16.ppm"
check "rgb565 run" run_fw SCENE=scenes/abb7-box.scene BOARD=mps2-an385 FW_TAG=rgb565 FW_EXTRA=-DFXRT_PIXEL=2
line=$("$FXRT" compare "$out/box-host.ppm" "$BUILD/qemu/mps2-an385/abb7-box-q16-rgb565.ppm")
echo "rgb565 vs rgb888: $line"
check "rgb565 frame: same pixels up to 565 quantisation" grep -qE 'max_err=[0-7] ' <<<"$line"

# No heap in any firmware ELF; every ELF built above is checked.
elfs=$(find "$BUILD/fw" -name '*.elf')
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
for k in abb6-sphere abb5-plane abb7-box; do
    check "$k all-kinds build" run_fw SCENE=scenes/$k.scene BOARD=mps2-an385 NUMBER=q16 SIZE=$SIZE \
        FW_ALL_KINDS=1 FW_TAG=allkinds
    one=$(text_of "$BUILD/fw/mps2-an385/$k-q16-$SIZE-full/fxrt.elf")
    all=$(text_of "$BUILD/fw/mps2-an385/$k-q16-$SIZE-full-allkinds/fxrt.elf")
    echo "$k: .text $one bytes (its kinds), $all bytes (every kind)"
    check "$k firmware is smaller than its every-kind build ($one < $all)" test "${one:-0}" -lt "${all:-0}"
done

# Faults and hangs fail the make target with a clear message, and no image.
for b in $BOARDS; do
    rm -f "$BUILD/qemu/$b/abb6-sphere-q16-fault.ppm"
    if run_fw SCENE=scenes/abb6-sphere.scene BOARD=$b FW_TAG=fault FW_EXTRA=-DFXRT_TEST_FAULT; then
        bad "$b: a faulting firmware must fail"
    else
        ok
    fi
    check "$b: fault reported ($(grep -m1 FAULT "$out/run.log"))" grep -q "FAULT: HardFault\|FAULT: UsageFault" "$out/run.log"
    check "$b: no image from a faulting run" test ! -e "$BUILD/qemu/$b/abb6-sphere-q16-fault.ppm"
done
if FXRT_QEMU_TIMEOUT=3 run_fw SCENE=scenes/abb6-sphere.scene FW_TAG=hang FW_EXTRA=-DFXRT_TEST_HANG; then
    bad "a hanging firmware must fail"
else
    ok
fi
check "hang reported as a timeout" grep -q "timed out" "$out/run.log"
report qemu
