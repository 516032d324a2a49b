#!/usr/bin/env bash
# The LM3S6965 evaluation board and its OLED in QEMU (firmware/oled/,
# docs/OLED.md): the board port's counter and a frame byte-identical to the
# host's Q16.16 render; then the OLED firmware's frames, captured with QEMU
# screendumps (firmware/oled/oled-run.sh) and brought back to 4-bit levels,
# equal byte for byte the host's render put through the same dithering
# (build/fxrt-oled grey, dither.c) in every method, for a flat seed scene, a
# lit scene and eight frames of a turning camera (whose host frames come
# from the same program built for the host, frame 0 also from fxrt render).
# Ends with "oled: N passed, N failed".
set -u
. "$(dirname "$0")/lib.sh"
out=$BUILD/tests/oled
rm -rf "$out"
mkdir -p "$out"
TOOL=$BUILD/fxrt-oled
M="make -s --no-print-directory BUILD=$BUILD"
METHODS=(none bayer4 bayer8 fs)
DUMP_BYTES=$((15 + 512 * 256 * 3))

# cal_ok LINE: "instructions=N" within 50 of the loop's 2,000,000.
cal_ok() {
    local n
    n=$(sed -nE 's/.*instructions=([0-9]+) .*/\1/p' <<<"$1")
    [ -n "$n" ] && [ "$n" -ge 2000000 ] && [ "$n" -le 2000050 ]
}
# levels_used BIN: how many different bytes the display RAM holds.
levels_used() { od -An -v -tx1 "$1" | tr -s ' ' '\n' | sed '/^$/d' | sort -u | wc -l; }
# no_heap ELF: no allocator linked.
no_heap() { ! arm-none-eabi-nm "$1" | awk '{print $NF}' | grep -qxE 'malloc|_malloc_r|_sbrk|_sbrk_r|free|_free_r'; }
# stack_ok LOG: stack_used + FXRT_STACK_MARGIN <= stack_size in the report.
stack_ok() {
    local su ss sm
    su=$(sed -nE 's/.* stack_used=([0-9]+).*/\1/p' "$1" | tail -n 1)
    ss=$(sed -nE 's/.* stack_size=([0-9]+).*/\1/p' "$1" | tail -n 1)
    sm=$(sed -nE 's/^#define FXRT_STACK_MARGIN ([0-9]+).*/\1/p' core/fxrt_config.h)
    [ -n "$su" ] && [ -n "$ss" ] && [ -n "$sm" ] && [ $((su + sm)) -le "$ss" ]
}

# --- the board port (firmware/firmware.mk's lm3s6965evb) ------------------
progress "oled.sh: lm3s6965evb calibration and a frame"
line=$($M calibrate BOARD=lm3s6965evb 2>&1 | grep instructions=)
echo "lm3s6965evb calibration (reset clock, TICK_NS 80): $line"
check "lm3s6965evb: counter calibration 2000000 +- 50 ($line)" cal_ok "$line"
"$FXRT" render scenes/abb6-sphere.scene --number q16 --size 128x64 -o "$out/abb6-sphere-host.ppm"
if $M qemu SCENE=scenes/abb6-sphere.scene BOARD=lm3s6965evb NUMBER=q16 SIZE=128x64 >"$out/port.log" 2>&1; then
    ok
    grep instructions= "$out/port.log"
    check "lm3s6965evb abb6-sphere: frame byte-identical to the host q16 render" \
        cmp -s "$out/abb6-sphere-host.ppm" "$BUILD/qemu/lm3s6965evb/abb6-sphere-q16-128x64.ppm"
else
    bad "lm3s6965evb abb6-sphere: make qemu failed: $(tail -n 5 "$out/port.log")"
fi

# --- stills: each method in turn (OLED_METHOD=cycle: frame f in method f) --
# check_frame NAME DUMP HOSTRGB METHOD: the screendump, unscaled, against
# the host's RGB frame dithered.
check_frame() {
    local name=$1 dump=$2 host=$3 m=$4
    check "$name: screendump $dump is a full 512x256 PPM" test "$(stat -c %s "$dump" 2>/dev/null || echo 0)" -eq $DUMP_BYTES
    "$TOOL" grey "$host" --dither "$m" -o "$out/$name-host.bin"
    if "$TOOL" unscale "$dump" -o "$out/$name-board.bin" 2>"$out/unscale.log"; then
        ok
    else
        bad "$name: unscale: $(cat "$out/unscale.log")"
    fi
    check "$name: display RAM byte-identical to the host's frame dithered ($m)" \
        cmp -s "$out/$name-host.bin" "$out/$name-board.bin"
    check "$name: the frame is not blank ($(levels_used "$out/$name-board.bin") different bytes)" \
        test "$(levels_used "$out/$name-board.bin")" -ge 2
}
for scene in scenes/abb6-sphere.scene scenes/lit/shadows.scene; do
    name=$(basename "$scene" .scene)
    progress "oled.sh: $name, four methods"
    "$FXRT" render "$scene" --number q16 --size 128x64 -o "$out/$name-rgb.ppm"
    if $M oled-qemu OLED_SCENE="$scene" OLED_FRAMES=4 OLED_METHOD=cycle OLED_OUT="$out" OLED_PREFIX="$name" \
        >"$out/$name.log" 2>&1; then
        ok
    else
        bad "$name: make oled-qemu failed: $(tail -n 8 "$out/$name.log")"
    fi
    grep -E '^(calibration|frame|total)' "$out/$name.log" | sed "s/^/$name: /"
    check "$name: counter calibration at 50 MHz 2000000 +- 50" cal_ok "$(grep '^calibration:' "$out/$name.log")"
    check "$name: stack used + FXRT_STACK_MARGIN <= reserved" stack_ok "$out/$name.log"
    for f in 0 1 2 3; do
        check_frame "$name-${METHODS[$f]}" "$out/$name-0$f.ppm" "$out/$name-rgb.ppm" "${METHODS[$f]}"
    done
done
# On the lit scene's gradients every method gives its own frame.
for a in 0 1 2 3; do
    for b in $(seq $((a + 1)) 3); do
        check "shadows: ${METHODS[$a]} and ${METHODS[$b]} frames differ" \
            bash -c "! cmp -s '$out/shadows-${METHODS[$a]}-board.bin' '$out/shadows-${METHODS[$b]}-board.bin'"
    done
done

# The comparison can fail: a block that is not one grey is refused, and
# one block of another grey makes the frames differ.
# put_block DUMP X Y GREY [ROWS]: the dump's block (X, Y) painted GREY
# (ROWS of its 4 rows, default all).
put_block() {
    local r bytes
    bytes=$(printf '\\x%02x' "$4" | sed 's/.*/&&&&&&&&&&&&/')
    for ((r = 0; r < ${5:-4}; r++)); do
        printf "$bytes" | dd of="$1" bs=1 seek=$((15 + ((4 * $3 + r) * 512 + 4 * $2) * 3)) conv=notrunc status=none
    done
}
cp "$out/shadows-03.ppm" "$out/bad-block.ppm"
put_block "$out/bad-block.ppm" 5 7 17 2
if "$TOOL" unscale "$out/bad-block.ppm" -o "$out/bad-block.bin" 2>"$out/unscale.log"; then
    bad "unscale must refuse a block that is not one grey"
else
    ok
fi
check "unscale names the block ($(cat "$out/unscale.log"))" grep -q 'block (5, 7)' "$out/unscale.log"
cp "$out/shadows-03.ppm" "$out/other-level.ppm"
put_block "$out/other-level.ppm" 64 32 $((17 * 15))
put_block "$out/other-level.ppm" 65 32 0
check "a changed block unscales" "$TOOL" unscale "$out/other-level.ppm" -o "$out/other-level.bin"
check "a changed block makes the display RAM differ from the host's" \
    bash -c "! cmp -s '$out/shadows-fs-host.bin' '$out/other-level.bin'"

# --- fxrt-oled measure (the error table's command) --------------------------
# A picture of display greys (17 n: a dithered frame) has no error in any
# method; a flat field of grey 8 rounds to level 0 (8 < 17 / 2), so its
# error is -8 everywhere: MAE 8, bias -8, PSNR 10 log10(255^2 / 64) by awk.
"$TOOL" grey "$out/shadows-rgb.ppm" --dither fs -o "$out/levels-only.ppm"
"$TOOL" measure "exact=$out/levels-only.ppm" >"$out/measure-exact.txt"
check "measure: a picture of display greys has no error in any method" \
    test "$(grep -c 'image=all .*mae=0.0000 psnr=inf mae3=0.0000 psnr3=inf mae5=0.0000 psnr5=inf bias=0.0000' "$out/measure-exact.txt")" -eq 4
{ printf 'P6\n16 16\n255\n'; head -c 768 /dev/zero | tr '\0' '\010'; } >"$out/flat8.ppm"
line=$("$TOOL" measure "flat=$out/flat8.ppm" | grep 'image=all method=none ')
want=$(awk 'BEGIN { printf "mae=8.0000 psnr=%.2f mae3=8.0000 psnr3=%.2f mae5=8.0000 psnr5=%.2f bias=-8.0000", \
    10 * log(255 * 255 / 64) / log(10), 10 * log(255 * 255 / 64) / log(10), 10 * log(255 * 255 / 64) / log(10) }')
check "measure: flat grey 8 without dithering: $want (got: ${line#*pixels=256 })" grep -q -- "$want" <<<"$line"

# --- a turning camera: eight frames, 45 degrees apart ---------------------
TURN_SCENE=scenes/lit/coloured-lights.scene TURN_FRAMES=8 TURN_DEG=45 TURN_METHOD=fs
progress "oled.sh: turntable, $TURN_FRAMES frames"
tv=(OLED_SCENE=$TURN_SCENE OLED_FRAMES=$TURN_FRAMES OLED_TURN=$TURN_DEG OLED_METHOD=$TURN_METHOD)
if $M oled-qemu "${tv[@]}" OLED_OUT="$out" OLED_PREFIX=turn >"$out/turn.log" 2>&1; then
    ok
else
    bad "turntable: make oled-qemu failed: $(tail -n 8 "$out/turn.log")"
fi
grep -E '^(frame|total)' "$out/turn.log" | sed 's/^/turntable: /'
check "turntable: the host build of the same program runs" \
    bash -c '"$@" >"$0" 2>&1' "$out/turn-host.log" $M oled-host "${tv[@]}" OLED_OUT="$out/turn-host"
"$FXRT" render "$TURN_SCENE" --number q16 --size 128x64 -o "$out/turn-rgb-00.ppm"
check "turntable: the host program's frame 0 equals fxrt render's (the scene's own camera)" \
    cmp -s "$out/turn-rgb-00.ppm" "$out/turn-host/frame-00.ppm"
for ((f = 0; f < TURN_FRAMES; f++)); do
    ff=$(printf '%02d' $f)
    check_frame "turn-$ff" "$out/turn-$ff.ppm" "$out/turn-host/frame-$ff.ppm" $TURN_METHOD
    [ $f -gt 0 ] && check "turntable: frames $((f - 1)) and $f differ" \
        bash -c "! cmp -s '$out/turn-$(printf '%02d' $((f - 1)))-board.bin' '$out/turn-$ff-board.bin'"
done
check "turntable: stack used + FXRT_STACK_MARGIN <= reserved" stack_ok "$out/turn.log"

# --- no allocator in any ELF built here ------------------------------------
elfs=$(find "$BUILD/oled/fw" -name oled.elf -newer "$out/abb6-sphere-host.ppm" 2>/dev/null)
elfs="$elfs $(ls "$BUILD"/fw/lm3s6965evb/abb6-sphere-q16-128x64-*/fxrt.elf 2>/dev/null)"
check "found the ELFs ($(wc -w <<<"$elfs"))" test "$(wc -w <<<"$elfs")" -ge 1
for e in $elfs; do
    check "$e: no malloc/_sbrk" no_heap "$e"
done
report oled
