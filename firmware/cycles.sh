#!/usr/bin/env bash
# Estimated cycles of a firmware run in QEMU: every executed instruction
# priced by its class with the cycle counts of its core's technical
# reference manual (firmware/cycles.awk; docs/BENCHMARKS.md, "Cycles").
#   firmware/cycles.sh ELF BOARD        one ELF (any program that exits)
#   firmware/cycles.sh SCENE BOARD NUMBER [SIZE]
#                                       a frame: make fw, then the ELF
# (make cycles SCENE=... BOARD=... NUMBER=... [CYCLES_SIZE=80x60])
# QEMU logs every translated block and every execution (-d
# in_asm,exec,nochain) into a pipe that cycles.awk reads as it runs, so no
# log is kept. The counts cover the whole run (boot, set-up, the frame,
# its dump), like make profile's. Prints the classes and
#   total instructions=N low=L high=H estimate=E cpi=C
# CYCLES_MARKS="ADDR ..." (marker functions' addresses) adds cycles.awk's
# segments. CYCLES_FRAME=1 (a firmware/main.c frame) marks counter_ticks
# instead, whose second and third calls bracket the frame (render set-up
# and rows, what -icount's instructions= counts), and adds
#   frame instructions=N low=L high=H estimate=E cpi=C
# FW_EXTRA and FW_TAG pass to make fw, as for make qemu, and CYCLES_FB
# as its FB (default: the board's). CYCLES_CPI=1
# (with CYCLES_FRAME=1) prints the frame's CPI alone.
set -euo pipefail
BUILD=${BUILD:-build}
case $2 in
microbit) core=m0 ;;
mps2-an386) core=m4 ;;
mps2-an385 | lm3s6965evb) core=m3 ;;
*) echo "cycles: unknown board '$2'" >&2; exit 2 ;;
esac
if [[ $1 == *.elf ]]; then
    elf=$1 board=$2
else
    scene=$1 board=$2 number=$3 size=${4:-80x60}
    fb=${CYCLES_FB:-full} # (the board's default frame mode, as firmware/firmware.mk's)
    [[ -z ${CYCLES_FB:-} && $board == microbit ]] && fb=stream
    # -o: make cycles built the scene compiler first; parallel callers
    # (make bench) must not relink it.
    make -s --no-print-directory BUILD="$BUILD" -o "$BUILD/fxrt-scenec" fw SCENE="$scene" BOARD="$board" NUMBER="$number" SIZE="$size" FB="$fb" \
        ${FW_TAG:+FW_EXTRA="${FW_EXTRA:-}" FW_TAG="$FW_TAG"} >&2
    name=$(basename "$scene" .scene)
    elf=$BUILD/fw/$board/${name// /_}-$number-$size-$fb${FW_TAG:+-$FW_TAG}/fxrt.elf
fi
[[ -f $elf ]] || { echo "cycles: no $elf" >&2; exit 1; }
elf=$(realpath "$elf")
marks=${CYCLES_MARKS:-}
if [[ ${CYCLES_FRAME:-0} == 1 ]]; then
    marks=$(arm-none-eabi-nm "$elf" | awk '$3 == "counter_ticks" { print "0x" $1 }')
    [[ -n $marks ]] || { echo "cycles: no counter_ticks in $elf (CYCLES_FRAME=1 needs a firmware/main.c frame)" >&2; exit 1; }
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkfifo "$tmp/log"
awk -v core=$core -v marks="$marks" -f "$(dirname "$0")/cycles.awk" "$tmp/log" >"$tmp/out" &
awkpid=$!
(cd "$tmp" && timeout 1200 qemu-system-arm -M "$board" -nographic -monitor none -serial none \
    -semihosting-config enable=on,target=native -icount shift=5 -d in_asm,exec,nochain -D "$tmp/log" \
    -kernel "$elf" </dev/null >"$tmp/run.out" 2>&1) || {
    cat "$tmp/run.out" >&2
    kill $awkpid 2>/dev/null # (it may still wait for the pipe to open)
    exit 1
}
wait $awkpid
[[ ${CYCLES_CPI:-0} == 1 ]] || sort "$tmp/out"
if [[ ${CYCLES_FRAME:-0} == 1 ]]; then
    awk '$1 == "segment=2" { split($2, n, "="); split($5, e, "=")
            sub(/^segment=2/, "frame"); printf "%s cpi=%.4f\n", $0, n[2] ? e[2] / n[2] : 0; f = 1 }
         END { if (!f) { print "cycles: no frame segment (counter_ticks ran fewer than 3 times)" > "/dev/stderr"; exit 1 } }' "$tmp/out" >"$tmp/frame"
    if [[ ${CYCLES_CPI:-0} == 1 ]]; then sed -nE 's/.* cpi=([0-9.]+)$/\1/p' "$tmp/frame"; exit 0; fi
    cat "$tmp/frame"
fi
