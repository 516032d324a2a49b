#!/usr/bin/env bash
# host/multi-ld.sh OUT NUMBER OBJECT...: one relocatable object of a
# program's objects for one number type (the core's, built with
# FXRT_NUMBER for it, and the program's own per-number glue), in which every
# defined global symbol gets the suffix _NUMBER unless it already ends with
# it. A program links three of them side by side (q16, float, double): the
# core's names (render_row, world_hit, ...) no longer collide, and the glue
# names its entry points with the suffix itself (host/multi.h). Symbols the
# objects only use (fx_*, memcpy) stay as they are.
set -euo pipefail
out=$1 n=$2
shift 2
ld -r -o "$out.tmp" "$@"
nm -g --defined-only -P "$out.tmp" | awk -v s="_$n" '
    { if (length($1) <= length(s) || substr($1, length($1) - length(s) + 1) != s) print $1, $1 s }' >"$out.syms"
objcopy --redefine-syms="$out.syms" "$out.tmp" "$out"
rm -f "$out.tmp" "$out.syms"
