#!/usr/bin/env bash
# The growth curve of make bench-models as a log-log plot: instructions per
# pixel against the triangle count, lit and flat, one line per board, for
# the icospheres (Spot as single points), with the issue's two targets at
# 5,120 triangles on the M3 marked. Its only input is the table that
# firmware/models.sh generated, so the plot shows exactly its figures.
#   firmware/models-plot.sh TABLE.md OUT.png [DATA.dat]
# (make models-plot redraws docs/bench/models.png from docs/bench/models.md.)
# DATA.dat (default OUT.png with .dat): one row per drawn value,
# "model triangles board mode instr_per_px".
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: firmware/models-plot.sh TABLE.md OUT.png [DATA.dat]" >&2; exit 2; }
table=$1 png=$2 dat=${3:-${2%.png}.dat}
[ -f "$table" ] || { echo "models-plot: no $table" >&2; exit 2; }
# The first table of the file: its header names each board's "B instr/px"
# column; a row is "| model | triangles | bytes | scene | B instr/px | B RAM | ... |".
awk -F'|' '
    function trim(s) { gsub(/^[ \t]+|[ \t]+$/, "", s); return s }
    !head && /^\| model \| triangles/ {
        for (i = 2; i < NF; i++) { h = trim($i); if (h ~ / instr\/px$/) { sub(/ instr\/px$/, "", h); board[i] = h } }
        head = 1; next }
    head && /^\|---/ { next }
    head && /^\|/ {
        m = trim($2); t = trim($3); mode = trim($5)
        for (i = 2; i < NF; i++) if (i in board) { v = trim($i); if (v ~ /^[0-9]+(\.[0-9]+)?$/) print m, t, board[i], mode, v }
        next }
    head { exit }' "$table" >"$dat.tmp"
[ -s "$dat.tmp" ] || { echo "models-plot: no figures in $table" >&2; rm -f "$dat.tmp"; exit 1; }
mv "$dat.tmp" "$dat"
# gnuplot's input: one block per board and scene (icospheres, by triangle
# count), blocks two blank lines apart, and their names in the same order.
series=$dat.series names=""
: >"$series"
for b in $(awk '{ print $3 }' "$dat" | awk '!seen[$0]++'); do
    for mode in lit flat; do
        rows=$(awk -v b="$b" -v m="$mode" '$3 == b && $4 == m && $1 ~ /^ico/ { print $2, $5 }' "$dat" | sort -n)
        [ -n "$rows" ] || continue
        printf '%s\n\n\n' "$rows" >>"$series"
        names+="$b,$mode "
    done
done
gnuplot -e "series='$series'; data='$dat'; names='$names'; out='$png.tmp'" "$(dirname "$0")/models.gp"
rm -f "$series"
mv "$png.tmp" "$png"
