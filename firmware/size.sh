#!/usr/bin/env bash
# make size: flash and RAM of the Q16.16 firmware for each seed scene on
# each board, plus the measured stack high-water mark (painted stack, read
# back after a QEMU run). Prints a markdown table and keeps it in
# BUILD/size.md; SIZE_UPDATE_DOCS=1 also rewrites the <!-- size --> block of
# docs/FIRMWARE.md from it (host/docblocks.sh).
set -euo pipefail
BUILD=${BUILD:-build}
SIZE=${SIZE:-160x120}
M="make -s --no-print-directory BUILD=$BUILD"
{
echo "Q16.16 firmware at $SIZE (full frame on the MPS2 boards, one-row streaming on the micro:bit)"
echo
echo "| board | scene | frame | text | text, all kinds linked | data | bss | stack reserved | stack used | RAM total |"
echo "|---|---|---|---:|---:|---:|---:|---:|---:|---:|"
for b in mps2-an385 mps2-an386 microbit; do
    for scene in scenes/abb*.scene; do
        name=$(basename "$scene" .scene)
        run=$($M qemu SCENE="$scene" BOARD=$b NUMBER=q16 SIZE="$SIZE" | grep instructions=)
        elf=$(ls -d "$BUILD"/fw/$b/"$name"-q16-"$SIZE"-*/fxrt.elf | grep -m1 -E -- '-(full|stream)/fxrt.elf$')
        mode=$(sed -E 's/.*-(full|stream)\/fxrt.elf$/\1/' <<<"$elf")
        read -r text data bss _ < <(arm-none-eabi-size "$elf" | tail -n 1)
        stack=$(sed -nE 's/.*stack_size=([0-9]+).*/\1/p' <<<"$run")
        used=$(sed -nE 's/.*stack_used=([0-9]+).*/\1/p' <<<"$run")
        # The same scene with every primitive kind compiled in: what
        # stripping the unused kinds saves.
        $M fw SCENE="$scene" BOARD=$b NUMBER=q16 SIZE="$SIZE" FW_ALL_KINDS=1 FW_TAG=allkinds >/dev/null
        all=$(arm-none-eabi-size "$BUILD/fw/$b/$name-q16-$SIZE-$mode-allkinds/fxrt.elf" | tail -n 1 | awk '{print $1}')
        # bss as printed by size includes the reserved stack section
        echo "| $b | $name | $mode | $text | $all | $data | $((bss - stack)) | $stack | $used | $((data + bss)) |"
    done
done
} | tee "$BUILD/size.md.tmp"
mv "$BUILD/size.md.tmp" "$BUILD/size.md"
if [ "${SIZE_UPDATE_DOCS:-0}" = 1 ]; then
    BUILD=$BUILD DOCS_UPDATE=1 host/docblocks.sh size >/dev/null
fi
