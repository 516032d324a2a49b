#!/usr/bin/env bash
# Run one firmware ELF in QEMU and turn its report into instructions.
#   firmware/qemu-run.sh ELF OUTDIR NAME.ppm|-
# Environment: QEMU_M (machine), TICK_NS (SysTick period in ns), BOARD.
# QEMU runs with -icount shift=5 (each instruction is 32 ns of virtual time),
# so instructions = ticks * TICK_NS / 32: a resolution of 1.25 instructions
# on the 25 MHz MPS2 boards and 1.95 on the 16 MHz micro:bit. The firmware
# writes NAME.ppm.part, renamed only after a clean exit: a failed run
# leaves no image; with FXRT (the host tool) set, NAME.png is written
# beside it. A run over 10 s prints a progress line every 10 s on stderr.
# A hang hits the timeout (FXRT_QEMU_TIMEOUT, default 300 s).
set -u
elf=$1 outdir=$2 out=$3
shift_=5
timeout_s=${FXRT_QEMU_TIMEOUT:-300}
mkdir -p "$outdir"
log=$(mktemp)
trap 'rm -f "$log"' EXIT
[ "$out" != - ] && rm -f "$outdir/$out.part"
abs_elf=$(realpath "$elf")
(cd "$outdir" && exec timeout "$timeout_s" qemu-system-arm -M "$QEMU_M" -nographic -monitor none -serial none \
    -semihosting-config enable=on,target=native -icount shift=$shift_ -kernel "$abs_elf" </dev/null) >"$log" 2>&1 &
pid=$!
# The progress lines come from a ticker beside QEMU, so a short run ends
# as soon as QEMU does (no polling).
(trap 'kill $s 2>/dev/null; exit 0' TERM
 t=0
 while sleep 10 & s=$!; wait $s; do
     t=$((t + 10))
     echo "qemu: $BOARD: $(basename "$elf"): running, ${t} s" >&2
 done) &
ticker=$!
wait "$pid"
rc=$?
kill "$ticker" 2>/dev/null
wait "$ticker" 2>/dev/null
if [ $rc -eq 124 ]; then
    echo "qemu: $BOARD: $elf: timed out after ${timeout_s}s (hang?)" >&2
elif [ $rc -ne 0 ]; then
    echo "qemu: $BOARD: $elf: exit status $rc" >&2
    sed 's/^/  | /' "$log" >&2
fi
ticks=$(sed -nE 's/.*ticks=([0-9]+).*/\1/p' "$log" | tail -n 1)
if [ $rc -eq 0 ] && [ -z "$ticks" ]; then
    echo "qemu: $BOARD: $elf: no ticks= report from the firmware" >&2
    sed 's/^/  | /' "$log" >&2
    rc=1
fi
if [ $rc -ne 0 ]; then
    [ "$out" != - ] && rm -f "$outdir/$out.part"
    exit 1
fi
[ "$out" != - ] && mv "$outdir/$out.part" "$outdir/$out"
instr=$(awk -v t="$ticks" -v ns="$TICK_NS" -v s=$shift_ 'BEGIN { printf "%.0f", t * ns / 2^s }')
rest=$(sed -nE 's/.*ticks=[0-9]+ ?//p' "$log" | tail -n 1)
pixels=$(sed -nE 's/.*pixels=([0-9]+).*/\1/p' <<<"$rest")
per_px=""
[ -n "$pixels" ] && per_px=" instructions_per_pixel=$(awk -v i="$instr" -v p="$pixels" 'BEGIN { printf "%.1f", i / p }')"
echo "board=$BOARD instructions=$instr$per_px $rest"
if [ "$out" != - ]; then
    echo "wrote $outdir/$out"
    if [ -n "${FXRT:-}" ] && [[ $out == *.ppm ]]; then
        "$FXRT" sheet -o "$outdir/${out%.ppm}.png" "$outdir/$out" --no-labels && echo "wrote $outdir/${out%.ppm}.png"
    fi
fi
exit 0
