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
rawf=$out/raw-float.txt
: >"$raw"
: >"$rawf"
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
    # Estimated cycles (docs/BENCHMARKS.md, "Cycles"): the same ELF under
    # QEMU's execution trace, split at each call of counter_ticks. Timed
    # loop j (the j-th "bench" line of the log, empty or not) is segment
    # 2j+1: from the call that starts it to the one that ends it. Each
    # loop's traced instructions must match its ticks up to the few
    # instructions of counter_ticks and the blocks that -icount cut short
    # (the trace counts them whole: up to about 170 instructions in a
    # loop, 1.3 per call, 0.4 % of the loop at worst), else the pairing is
    # wrong: fail. A function's
    # cycles per call: its loop's less its empty loop's (the latest empty
    # of the same ticks), / calls.
    cyc=$out/$board/cycles.txt
    marks=$(arm-none-eabi-nm "$elf" | awk '$3 == "counter_ticks" { print "0x" $1 }')
    if ! CYCLES_MARKS=$marks BUILD=$BUILD firmware/cycles.sh "$elf" "$board" >"$out/$board/trace.txt"; then
        echo "bench-fx: $board: the cycles trace failed" >&2
        exit 1
    fi
    if ! awk -v ns="$tick_ns" -v s=$shift_ '
        FNR == NR { if ($1 ~ /^segment=/) { split($1, a, "="); split($2, b, "="); split($5, ce, "=")
                                            si[a[2]] = b[2]; se[a[2]] = ce[2] }
                    next }
        $1 == "bench" && ($2 ~ /^(empty|fn)=/) {
            seg = 2 * j++ + 1
            split($2, nm, "="); tk = $0; sub(/.* ticks=/, "", tk); sub(/ .*/, "", tk)
            if (!(seg in si)) { print "bench-fx: no trace segment for " nm[2] > "/dev/stderr"; bad = 1; exit }
            over = si[seg] - tk * ns / 2^s
            if (over < 0 || over > 200 + si[seg] / 200) {
                printf "bench-fx: %s: %d traced instructions against %d ticks\n", nm[2], si[seg], tk > "/dev/stderr"; bad = 1; exit }
            if (nm[1] == "empty") { ecyc[tk] = se[seg]; next }
            e = $0; sub(/.* empty_ticks=/, "", e); sub(/ .*/, "", e)
            c = $0; sub(/.* calls=/, "", c); sub(/ .*/, "", c)
            if (!(e in ecyc)) { print "bench-fx: no empty loop of " e " ticks for " nm[2] > "/dev/stderr"; bad = 1; exit }
            printf "%s %.1f\n", nm[2], (se[seg] - ecyc[e]) / c }
        END { if (bad || !j) exit 1 }
        ' "$out/$board/trace.txt" "$log" >"$cyc"; then
        echo "bench-fx: $board: cannot pair the trace with the loops" >&2
        exit 1
    fi
    # Text bytes per function: the sizes of the symbols that implement it
    # (the function, its out-of-line static helpers including .part/.constprop
    # clones, its tables), from nm; the out-of-line wrapper for the inline
    # ones. Shared tables count for every function that uses them. libgcc
    # helpers reached from the group are listed by name, not counted.
    nm_out=$out/$board/nm.txt
    dis=$out/$board/calls.txt
    arm-none-eabi-nm -S "$elf" | awk 'NF == 4 { print $4, $2 }' >"$nm_out"
    # "caller callee" for every bl in the program.
    arm-none-eabi-objdump -d --no-show-raw-insn "$elf" |
        awk '/^[0-9a-f]+ <.*>:$/ { f = $2; gsub(/[<>:]/, "", f) } /\tbl\t/ { c = $NF; gsub(/[<>]/, "", c); print f, c }' |
        sort -u >"$dis"
    sed -nE 's/^bench fn=([a-z0-9_]+) calls=([0-9]+) ticks=([0-9]+) empty_ticks=([0-9]+).*/\1 \2 \3 \4/p' "$log" |
        while read -r fn calls ticks empty; do
            case $fn in
            fx_add) group="w_fx_add" ;;
            fx_mul) group="w_fx_mul" ;;
            fx_div) group="fx_div fx_recip_tab" ;;
            fx_recip) group="fx_recip fx_div fx_recip_tab" ;;
            fx_sqrt) group="fx_sqrt fx_rsqrt_tab" ;;
            fxw_sqrt) group="fxw_sqrt fx_rsqrt_tab" ;;
            fxw_div) group="fxw_div fx_udiv_round" ;;
            fx_rsqrt) group="fx_rsqrt fx_rsqrt_q46 fx_rsqrt_tab" ;;
            fx_sin_deg) group="fx_sin_deg fx_sin_quarter fx_sincos45 fx_mul_q30" ;;
            fx_cos_deg) group="fx_cos_deg fx_sin_quarter fx_sincos45 fx_mul_q30" ;;
            fx_cot_deg) group="fx_cot_deg fx_cos_sinc_q30 fx_udiv_round" ;;
            vec3_dot) group="v_dot" ;;
            vec3_cross) group="v_cross" ;;
            vec3_len) group="v_len fxw_sqrt fx_rsqrt_tab" ;;
            vec3_normalize) group="v_normalize fx_normalize3 fx_rsqrt_q46 fx_rsqrt_tab" ;;
            vec3_unit_len) group="v_unit_len fx_normalize3_len fx_rsqrt_q46 fx_rsqrt_tab" ;;
            old_fx_div) group="w_old_fx_div" ;;
            old_fx_sqrt) group="w_old_fx_sqrt" ;;
            float_vec3_*) group="f_${fn#float_vec3_}" ;;
            float_*) group="f_${fn#float_}" ;;
            *) group=$fn ;;
            esac
            size=$(awk -v g="$group" 'BEGIN { n = split(g, a, " "); for (i = 1; i <= n; i++) want[a[i]] = 1 }
                { base = $1; sub(/\..*/, "", base) } (base in want) && !seen[$1]++ { s += strtonum_hex($2) }
                function strtonum_hex(h,   i, v, c) { v = 0; h = tolower(h)
                    for (i = 1; i <= length(h); i++) { c = index("0123456789abcdef", substr(h, i, 1)) - 1; v = v * 16 + c }
                    return v }
                END { print s + 0 }' "$nm_out")
            libgcc=$(awk -v g="$group" 'BEGIN { n = split(g, a, " "); for (i = 1; i <= n; i++) want[a[i]] = 1 }
                { base = $1; sub(/\..*/, "", base) } (base in want) && $2 ~ /^__|^sqrtf$/ { print $2 }' "$dis" | sort -u | paste -sd, -)
            instr=$(awk -v t="$ticks" -v e="$empty" -v ns="$tick_ns" -v s=$shift_ -v c="$calls" \
                'BEGIN { printf "%.1f", (t - e) * ns / 2^s / c }')
            cycles=$(awk -v f="$fn" '$1 == f { print $2 }' "$cyc")
            case $fn in
            float_*) echo "$fn $board $instr $size ${libgcc:--} ${cycles:--}" >>"$rawf" ;;
            *) echo "$fn $board $instr $size ${libgcc:--} ${cycles:--}" >>"$raw" ;;
            esac
        done
done
# Worst errors from the host test (FX_TEST_RANDOM random inputs per function).
errs=$("$BUILD/tests/test_fx" 2>&1 | sed -nE 's/^ERR ([a-z0-9_]+) ([0-9.]+).*/\1 \2/p')
{
    echo "| function | board | instructions per call | est. cycles per call | text bytes | libgcc calls | worst error (LSB, host test) |"
    echo "|---|---|---:|---:|---:|---|---:|"
    awk -v errs="$errs" 'BEGIN { n = split(errs, e, "\n"); for (i = 1; i <= n; i++) { split(e[i], f, " "); err[f[1]] = f[2] } }
        { printf "| %s | %s | %s | %s | %s | %s | %s |\n", $1, $2, $3, $6, $4, $5, ($1 in err) ? err[$1] : (($1 ~ /^old_/) ? "0.5 (before)" : "-") }' "$raw"
} >"$out/benchfx-long.md"
# The same numbers with one row per function (instructions and estimated
# cycles per call on each board, text bytes on the M3 and the M0).
boards=$(for spec in $BENCHFX_TICKS; do echo "${spec%%:*}"; done | paste -sd' ' -)
{
    awk -v boards="$boards" -v errs="$errs" '
        BEGIN { nb = split(boards, b, " "); n = split(errs, e, "\n")
                for (i = 1; i <= n; i++) { split(e[i], f, " "); err[f[1]] = f[2] }
                printf "| function |"; for (i = 1; i <= nb; i++) printf " %s instr. |", b[i]
                for (i = 1; i <= nb; i++) printf " %s est. cycles |", b[i]
                printf " text bytes (%s / %s) | libgcc calls (%s) | worst error, LSB |\n", b[1], b[nb], b[nb]
                printf "|---|"; for (i = 1; i <= 2 * nb; i++) printf "---:|"; printf "---|---|---:|\n" }
        { if (!($1 in seen)) { seen[$1] = 1; order[++no] = $1 } ins[$1, $2] = $3; sz[$1, $2] = $4; lg[$1, $2] = $5; cy[$1, $2] = $6 }
        END { for (k = 1; k <= no; k++) { fn = order[k]; printf "| %s |", fn
                for (i = 1; i <= nb; i++) printf " %s |", ins[fn, b[i]]
                for (i = 1; i <= nb; i++) printf " %s |", cy[fn, b[i]]
                printf " %s / %s | %s | %s |\n", sz[fn, b[1]], sz[fn, b[nb]], lg[fn, b[nb]],
                    (fn in err) ? err[fn] : ((fn ~ /^old_/) ? "0.5 (before)" : "-") } }' "$raw"
} >"$out/benchfx.md"
# Q16.16 against float, operation by operation (benchfx_num.c): the same
# operation's instructions per call in each build, and their ratio
# (float / q16: how many times fewer instructions Q16.16 takes); then the
# same in estimated cycles.
{
    awk -v boards="$boards" -v rawf="$rawf" '
        BEGIN { nb = split(boards, b, " ")
                while ((getline l < rawf) > 0) { split(l, f, " "); fl[f[1], f[2]] = f[3]; lg[f[1], f[2]] = f[5]; fc[f[1], f[2]] = f[6] }
                np = split("add:fx_add:float_add mul:fx_mul:float_mul div:fx_div:float_div sqrt:fx_sqrt:float_sqrt " \
                           "1/sqrt:fx_rsqrt:float_rsqrt dot:vec3_dot:float_vec3_dot cross:vec3_cross:float_vec3_cross " \
                           "length:vec3_len:float_vec3_len normalise:vec3_normalize:float_vec3_normalize " \
                           "unit+length:vec3_unit_len:float_vec3_unit_len", pairs, " ")
                printf "| operation | Q16.16 function |"; for (i = 1; i <= nb; i++) printf " %s: q16 / float instr. (float ÷ q16) |", b[i]
                for (i = 1; i <= nb; i++) printf " %s: q16 / float est. cycles (float ÷ q16) |", b[i]
                printf " float calls (%s) |\n", b[nb]
                printf "|---|---|"; for (i = 1; i <= 2 * nb; i++) printf "---:|"; printf "---|\n" }
        { q[$1, $2] = $3; qc[$1, $2] = $6 }
        END { for (k = 1; k <= np; k++) { split(pairs[k], f, ":"); op = f[1]; gsub(/\+/, " and ", op)
                printf "| %s | %s |", op, f[2]
                for (i = 1; i <= nb; i++) { a = q[f[2], b[i]]; c = fl[f[3], b[i]]
                    printf " %s / %s (%s) |", a, c, (a > 0 && c != "") ? sprintf("%.1f×", c / a) : "-" }
                for (i = 1; i <= nb; i++) { a = qc[f[2], b[i]]; c = fc[f[3], b[i]]
                    printf " %s / %s (%s) |", a, c, (a > 0 && c != "" && c != "-") ? sprintf("%.1f×", c / a) : "-" }
                printf " %s |\n", lg[f[3], b[nb]] } }' "$raw"
} >"$out/benchfx-versus.md"
cat "$out/benchfx.md"
echo
cat "$out/benchfx-versus.md"
# BENCHFX_UPDATE_DOCS=1: replace the table between the benchfx markers in
# docs/BENCHMARKS.md (the rest of the file is left as it is).
if [ "${BENCHFX_UPDATE_DOCS:-0}" = 1 ]; then
    doc=docs/BENCHMARKS.md
    host/replace-block.sh "$doc" benchfx:table "$out/benchfx.md" benchfx:versus "$out/benchfx-versus.md" || exit 1
    echo "bench-fx: updated $doc"
fi
echo
echo "(per-board rows: $out/benchfx-long.md; text bytes are the function's own symbols,"
echo " static helpers and tables; libgcc helpers are listed, not counted)"
