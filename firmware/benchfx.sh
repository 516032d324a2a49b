#!/usr/bin/env bash
# Run build/benchfx/BOARD/benchfx.elf on every board in QEMU (-icount shift=5)
# and print the fixed-point maths table (see firmware/benchfx.c).
# Environment: BUILD, BENCHFX_TICKS ("board:qemu-machine:tick-ns ...").
# instructions per call = (ticks - empty_ticks) * tick_ns / 32 / calls.
set -u
BUILD=${BUILD:-build}
out=$BUILD/benchfx
mkdir -p "$out"
shift_=5
raw=$out/raw.txt
: >"$raw"
for spec in $BENCHFX_TICKS; do
    IFS=: read -r board machine tick_ns <<<"$spec"
    elf=$out/$board/benchfx.elf
    log=$out/$board/run.log
    if ! timeout 300 qemu-system-arm -M "$machine" -nographic -monitor none -serial none \
        -semihosting-config enable=on,target=native -icount shift=$shift_ -kernel "$elf" </dev/null >"$log" 2>&1; then
        echo "bench-fx: $board: QEMU failed" >&2
        sed 's/^/  | /' "$log" >&2
        exit 1
    fi
    grep -q 'done' "$log" || { echo "bench-fx: $board: no report" >&2; exit 1; }
    # Text bytes per function: the symbol's size in the ELF (wrappers for the
    # inline ones; fx_sqrt/fx_rsqrt add their 192-byte table).
    syms=$(arm-none-eabi-nm -S --size-sort "$elf")
    sed -nE 's/^bench fn=([a-z0-9_]+) calls=([0-9]+) ticks=([0-9]+) empty_ticks=([0-9]+).*/\1 \2 \3 \4/p' "$log" |
        while read -r fn calls ticks empty; do
            sym=$fn
            case $fn in
            fx_mul) sym=w_fx_mul ;;
            old_fx_div) sym=w_old_fx_div ;;
            old_fx_sqrt) sym=w_old_fx_sqrt ;;
            vec3_dot) sym=v_dot ;;
            vec3_cross) sym=v_cross ;;
            vec3_len) sym=v_len ;;
            vec3_normalize) sym=v_normalize ;;
            esac
            hex=$(awk -v s="$sym" '$4 == s { print $2; exit }' <<<"$syms")
            size=?
            [ -n "$hex" ] && size=$((16#$hex))
            instr=$(awk -v t="$ticks" -v e="$empty" -v ns="$tick_ns" -v s=$shift_ -v c="$calls" \
                'BEGIN { printf "%.1f", (t - e) * ns / 2^s / c }')
            echo "$fn $board $instr $size" >>"$raw"
        done
done
# Worst errors from the host test (FX_TEST_RANDOM random inputs per function).
errs=$("$BUILD/tests/test_fx" 2>&1 | sed -nE 's/^ERR ([a-z0-9_]+) ([0-9.]+).*/\1 \2/p')
{
    echo "| function | board | instructions per call | text bytes | worst error (LSB, host test) |"
    echo "|---|---|---:|---:|---:|"
    awk -v errs="$errs" 'BEGIN { n = split(errs, e, "\n"); for (i = 1; i <= n; i++) { split(e[i], f, " "); err[f[1]] = f[2] } }
        { printf "| %s | %s | %s | %s | %s |\n", $1, $2, $3, $4, ($1 in err) ? err[$1] : "-" }' "$raw"
} >"$out/benchfx.md"
cat "$out/benchfx.md"
