#!/usr/bin/env bash
# replace-block.sh [--pad] DOC NAME FILE [NAME FILE ...]: each FILE's lines
# become what stands between the lines "<!-- NAME -->" and "<!-- /NAME -->"
# of DOC (with --pad, between a blank line before and after). Every
# marker is checked first, so a missing one leaves DOC as it was; exit 2
# then, or when the rewrite fails. The docs' generated blocks are written
# through it (host/docblocks.sh, firmware/bench.sh, ...).
set -u
pad=0
if [ "${1:-}" = --pad ]; then
    pad=1
    shift
fi
if [ $# -lt 3 ] || [ $(($# % 2)) -ne 1 ]; then
    echo "usage: host/replace-block.sh [--pad] DOC NAME FILE [NAME FILE ...]" >&2
    exit 2
fi
doc=$1
shift
pairs=("$@")
for ((i = 0; i < ${#pairs[@]}; i += 2)); do
    name=${pairs[i]}
    grep -qxF "<!-- $name -->" "$doc" && grep -qxF "<!-- /$name -->" "$doc" ||
        { echo "replace-block: $doc lacks the <!-- $name --> ... <!-- /$name --> markers" >&2; exit 2; }
    [ -r "${pairs[i + 1]}" ] || { echo "replace-block: cannot read ${pairs[i + 1]}" >&2; exit 2; }
done
for ((i = 0; i < ${#pairs[@]}; i += 2)); do
    name=${pairs[i]} file=${pairs[i + 1]}
    awk -v f="$file" -v pad=$pad -v begin="<!-- $name -->" -v end="<!-- /$name -->" '
        $0 == begin { print; if (pad) print ""; while ((getline l < f) > 0) print l; close(f); if (pad) print ""; skip = 1; next }
        $0 == end { skip = 0 }
        !skip' "$doc" >"$doc.tmp" ||
        { rm -f "$doc.tmp"; echo "replace-block: $doc: rewriting <!-- $name --> failed" >&2; exit 2; }
    mv "$doc.tmp" "$doc"
done
