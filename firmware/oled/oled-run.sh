#!/usr/bin/env bash
# Run an OLED firmware ELF (firmware/oled/oled_board.c) on QEMU's
# lm3s6965evb without a window and take a screendump of the display after
# every frame.
#   firmware/oled/oled-run.sh ELF OUTDIR PREFIX FRAMES
# writes OUTDIR/PREFIX-FF.ppm (FF = 00 .. FRAMES-1), the display as QEMU
# draws it (512x256: each of the 128x64 pixels a 4x4 block), and prints the
# firmware's report with ticks turned into instructions and milliseconds
# at 50 MHz. Exit 0 when every frame was captured and the firmware exited 0.
#
# How: QEMU runs with -display none, its monitor on a pair of FIFOs
# (-monitor pipe:OUTDIR/PREFIX-mon: QEMU reads .in and writes .out), and
# -icount shift=5 as firmware/qemu-run.sh. After frame F the firmware
# prints "oled: frame=F ..." (semihosting) and polls for the file
# oled-ack-FF in its working directory (OUTDIR); this script waits for that
# line, sends "screendump OUTDIR/PREFIX-FF.ppm" to the monitor, waits until
# the monitor has answered and the file is complete, then creates the ack,
# and the firmware goes on. The SysTick runs at 20 ns (the firmware sets 50
# MHz), so instructions = ticks * 20 / 32 (firmware/counter.c).
# FXRT_QEMU_TIMEOUT (default 300 s) bounds the whole run.
set -u
elf=$1 outdir=$2 prefix=$3 frames=$4
timeout_s=${FXRT_QEMU_TIMEOUT:-300}
TICK_NS=20 SHIFT=5
DUMP_BYTES=$((15 + 512 * 256 * 3)) # "P6\n512 256\n255\n" and the pixels
mkdir -p "$outdir"
outdir=$(realpath "$outdir")
abs_elf=$(realpath "$elf")
log=$outdir/$prefix-qemu.log
mon=$outdir/$prefix-mon
rm -f "$log" "$mon.in" "$mon.out" "$mon.log" "$outdir"/oled-ack-?? "$outdir/$prefix"-??.ppm
mkfifo "$mon.in" "$mon.out"
(cd "$outdir" && exec timeout "$timeout_s" qemu-system-arm -M lm3s6965evb -display none -serial none \
    -monitor "pipe:$mon" -semihosting-config enable=on,target=native -icount shift=$SHIFT \
    -kernel "$abs_elf" </dev/null >"$log" 2>&1) &
qemu=$!
# QEMU opens both FIFOs read-write, so neither side blocks on open.
cat "$mon.out" >"$mon.log" &
reader=$!
exec 9>"$mon.in"
cleanup() {
    exec 9>&-
    kill "$qemu" "$reader" 2>/dev/null
    wait "$qemu" "$reader" 2>/dev/null
    rm -f "$mon.in" "$mon.out" "$outdir"/oled-ack-??
}
trap cleanup EXIT
fail() {
    echo "oled-run: $elf: $*" >&2
    sed 's/^/  | /' "$log" >&2
    exit 1
}
deadline=$((SECONDS + timeout_s))
# wait_for TEST...: poll until the command succeeds; fail if QEMU ends or time runs out.
wait_for() {
    until "$@"; do
        kill -0 "$qemu" 2>/dev/null || { "$@" && return 0; fail "QEMU ended while waiting for: $*"; }
        [ $SECONDS -lt $deadline ] || fail "timed out after ${timeout_s}s waiting for: $*"
        sleep 0.02
    done
}
prompts() { grep -o '(qemu)' "$mon.log" 2>/dev/null | wc -l; }
dump_done() { [ -f "$1" ] && [ "$(stat -c %s "$1")" -eq $DUMP_BYTES ] && [ "$(prompts)" -gt "$2" ]; }
wait_for grep -q '(qemu)' "$mon.log" # the monitor is up
for ((f = 0; f < frames; f++)); do
    ff=$(printf '%02d' $f)
    wait_for grep -q "^oled: frame=$f " "$log"
    dump=$outdir/$prefix-$ff.ppm
    n=$(prompts)
    echo "screendump $dump" >&9
    wait_for dump_done "$dump" "$n"
    : >"$outdir/oled-ack-$ff"
done
wait "$qemu"
rc=$?
[ $rc -eq 0 ] || fail "exit status $rc"
# The report, ticks as instructions (20/32 per tick) and time at 50 MHz
# (one instruction a cycle: an estimate, QEMU counts instructions).
awk -v ns=$TICK_NS -v sh=$SHIFT '
    function instr(t) { return t * ns / 2 ^ sh }
    /^oled: frame=/ {
        for (i = 1; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] }
        fi = instr(v["frame_tick_count"]); di = instr(v["display_tick_count"])
        printf "frame=%s method=%s instructions=%.0f display_instructions=%.0f ms_at_50MHz=%.2f\n",
            v["frame"], v["method"], fi, di, fi / 50e3
    }
    /cal_tick_count=/ {
        for (i = 1; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] }
        printf "calibration: instructions=%.0f expected_instructions=2000000 init_instructions=%.0f\n",
            instr(v["cal_tick_count"]), instr(v["init_tick_count"])
    }
    /^ticks=/ { line = $0; sub(/^ticks=[0-9]+ /, "", line)
        split($1, kv, "="); printf "total instructions=%.0f %s\n", instr(kv[2]), line }
' "$log"
grep -v '^oled: \|^ticks=\|^Timer with period zero, disabling$' "$log" | sed 's/^/qemu: /'
for ((f = 0; f < frames; f++)); do echo "wrote $outdir/$prefix-$(printf '%02d' $f).ppm"; done
exit 0
