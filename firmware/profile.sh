#!/usr/bin/env bash
# Per-function instruction profile of a firmware run in QEMU (the target's
# own code: soft-float and libgcc helpers show up under their names).
#   firmware/profile.sh SCENE BOARD NUMBER [SIZE] [FW_EXTRA]
# (make profile SCENE=... BOARD=... NUMBER=... [PROFILE_SIZE=80x60] [FW_EXTRA=...])
# Builds the firmware (make fw, FW_TAG=prof when FW_EXTRA is given), runs it
# once under qemu-system-arm -d in_asm,exec,nochain (every executed
# translation block is logged; its instruction count comes from its latest
# translation) and sums the instructions per function of the ELF's symbol
# table. Counts cover the whole run (boot, set-up, frame dump), so they are
# a little above make qemu's instructions=, which counts the render only.
# Calls per pixel count the executions of the block that starts at a
# function's first instruction (a loop back to that instruction would count
# as a call too; the soft-float helpers and the renderer's functions begin
# with their prologue), so "per call" is its instructions per call.
# Estimated cycles per function come from firmware/cycles.awk on the same
# log (each block's executions priced by class, docs/BENCHMARKS.md,
# "Cycles"; the middle of the low..high range).
# SIZE defaults to 80x60: the log grows with the instructions (about one
# line per 5), so keep frames small.
set -euo pipefail
scene=$1 board=$2 number=$3 size=${4:-80x60} extra=${5:-}
BUILD=${BUILD:-build}
M="make -s --no-print-directory BUILD=$BUILD"
# The board's default frame mode (firmware/firmware.mk: FB_BOARD).
fb=full
[[ $board == microbit ]] && fb=stream
tagargs=()
[[ -n $extra ]] && tagargs=(FW_EXTRA="$extra" FW_TAG=prof)
$M fw SCENE="$scene" BOARD="$board" NUMBER="$number" SIZE="$size" FB="$fb" "${tagargs[@]}" >&2
name=$(basename "$scene" .scene)
elf=$BUILD/fw/$board/${name// /_}-$number-$size-$fb${extra:+-prof}/fxrt.elf
[[ -f $elf ]] || { echo "profile: no $elf" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
(cd "$tmp" && timeout 600 qemu-system-arm -M "$board" -nographic -monitor none -serial none \
    -semihosting-config enable=on,target=native -icount shift=5 -d in_asm,exec,nochain -D "$tmp/q.log" \
    -kernel "$(realpath "$OLDPWD/$elf")" </dev/null >"$tmp/run.out" 2>&1) || { cat "$tmp/run.out" >&2; exit 1; }
# Code symbols by address; a symbol without a size (libgcc's assembly)
# ends where the next one starts.
arm-none-eabi-nm -n --defined-only "$elf" | awk '$2 ~ /^[tTwW]$/ { print $1, $3 }' >"$tmp/syms"
px=$((${size%x*} * ${size#*x}))
case $board in microbit) core=m0 ;; mps2-an386) core=m4 ;; *) core=m3 ;; esac
awk -v core=$core -v blocks="$tmp/blocks" -f "$(dirname "$0")/cycles.awk" "$tmp/q.log" >/dev/null
echo "Profile: $scene on $board ($number${extra:+, $extra}) at $size, QEMU instructions per function over the whole run (per pixel = / $px), and estimated cycles (firmware/cycles.awk)."
echo
echo "| function | instructions | per pixel | share | est. cycles per pixel | CPI | calls per pixel | per call |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|"
awk -v px="$px" -v syms="$tmp/syms" -v blocks="$tmp/blocks" '
function hex(s,   i, c, v) { v = 0; s = tolower(s); sub(/^0x/, "", s)
    for (i = 1; i <= length(s); i++) { c = index("0123456789abcdef", substr(s, i, 1)) - 1; v = v * 16 + c } return v }
BEGIN { n = 0
    while ((getline l < syms) > 0) { split(l, f, " "); a = hex(f[1]); a -= a % 2; lo[++n] = a; nm[n] = f[2] }
    while ((getline l < blocks) > 0) { split(l, f, " "); cyc[hex(f[1])] = (f[3] + f[4]) / 2 } }
/^IN:/ { inb = 1; pc = ""; cnt = 0; next }
inb && /^0x[0-9a-f]+:/ { if (pc == "") pc = hex(substr($1, 1, length($1) - 1)); cnt++; next }
inb && /^$/ { if (pc != "") size[pc] = cnt; inb = 0; next }
/^Trace / { s = $0; sub(/^[^[]*\[/, "", s); split(s, f, "/"); p = hex(f[2]); execd[p] += size[p]; runs[p]++; if (NF >= 5) qn[p] = $NF }
END {
    tot = 0
    for (ps in execd) { # function by binary search (p numeric: a key is a string)
        p = ps + 0; l = 1; h = n; k = 0
        while (l <= h) { m = int((l + h) / 2); if (lo[m] <= p) { k = m; l = m + 1 } else h = m - 1 }
        fn = (ps in qn) ? qn[ps] : k ? nm[k] : "?"
        by[fn] += execd[ps]; tot += execd[ps]; cby[fn] += cyc[p]; ctot += cyc[p]
        if (k && lo[k] == p) calls[fn] += runs[ps] } # a block at the entry: a call
    for (fnm in by) printf "%d %s %d %d\n", by[fnm], fnm, calls[fnm], cby[fnm]
    printf "%d TOTAL 0 %d\n", tot, ctot }' "$tmp/q.log" >"$tmp/by"
tot=$(awk '$2 == "TOTAL" { print $1 }' "$tmp/by") ctot=$(awk '$2 == "TOTAL" { print $4 }' "$tmp/by")
grep -v ' TOTAL ' "$tmp/by" | sort -k1,1nr | head -n ${PROFILE_TOP:-15} |
    awk -v px="$px" -v tot="$tot" '{ printf "| `%s` | %d | %.1f | %.1f %% | %.1f | %.2f | %.2f | %s |\n", $2, $1, $1 / px, 100 * $1 / tot,
        $4 / px, $1 ? $4 / $1 : 0, $3 / px, $3 ? sprintf("%.1f", $1 / $3) : "-" }'
awk -v px="$px" -v tot="$tot" -v ctot="$ctot" 'BEGIN { printf "| all functions | %d | %.1f | 100 %% | %.1f | %.2f | | |\n", tot, tot / px, ctot / px, tot ? ctot / tot : 0 }'
