#!/usr/bin/env bash
# Every frame the host tool renders, before and after a change that must
# not change one (a refactor): make same-frames BASE=REV.
#
# The revision REV is exported into build/same/REV/src (git archive) and its
# host tool built there; then every scene in scenes/ and its subfolders,
# plus the lit and bench scenes again with `samples 2 adaptive` and
# `samples 3`, is rendered by both tools in q16, float and double at
# 160x120 and 64x48 with the fast loop, and at 64x48 with the reference
# loop and the ray caster, and the two files compared byte for byte. A
# scene that one tool refuses must be refused by the other with the same
# message. Ends with "same-frames: N passed, N failed" (N: frames).
#   BASE          the revision to compare with (required)
#   SAME_JOBS     parallel renders (nproc)
set -u
. "$(dirname "$0")/lib.sh"
base=${BASE:?usage: BASE=REV tests/same-frames.sh}
rev=$(git rev-parse --short "$base^{commit}") || { echo "same-frames: unknown revision '$base'" >&2; exit 2; }
jobs=${SAME_JOBS:-$(nproc 2>/dev/null || echo 2)}
root=$BUILD/same/$rev
out=$BUILD/same/frames
mkdir -p "$root" "$out"
if [ ! -x "$root/src/build/fxrt" ]; then
    rm -rf "$root/src"
    mkdir -p "$root/src"
    git archive "$rev" | tar -x -C "$root/src" || exit 2
    make -C "$root/src" -s --no-print-directory -j"$jobs" build/fxrt >"$root/build.log" 2>&1 ||
        { echo "same-frames: building $rev's host tool failed ($root/build.log)" >&2; exit 2; }
fi
OLD=$root/src/build/fxrt

scenes=()
for f in scenes/*.scene scenes/*/*.scene; do
    [ -f "$f" ] && scenes+=("$f")
done
for f in scenes/lit/*.scene scenes/bench/*.scene; do
    for s in "2 adaptive" 3; do
        name=$(basename "$(dirname "$f")")-$(basename "$f" .scene)-s${s// /}
        { sed '/^samples /d' "$f"; echo "samples $s"; } >"$out/$name.scene"
        scenes+=("$out/$name.scene")
    done
done

# one SCENE SIZE NUMBER RENDERER: prints "ok", "refused" or "FAIL: why".
one() {
    local scene=$1 size=$2 num=$3 ren=$4 tag
    tag=$(echo "$scene" | tr '/ ' '__')-$size-$num-$ren
    "$OLD" render "$scene" --size "$size" --number "$num" --renderer "$ren" -o "$out/$tag-a.ppm" 2>"$out/$tag-a.err"
    local ra=$?
    "$FXRT" render "$scene" --size "$size" --number "$num" --renderer "$ren" -o "$out/$tag-b.ppm" 2>"$out/$tag-b.err"
    local rb=$?
    if [ $ra -ne 0 ] || [ $rb -ne 0 ]; then
        if [ $ra -eq $rb ] && cmp -s "$out/$tag-a.err" "$out/$tag-b.err"; then
            echo "refused $scene $size $num $ren"
        else
            echo "FAIL: $scene $size $num $ren: exit $ra before, $rb after"
        fi
    elif cmp -s "$out/$tag-a.ppm" "$out/$tag-b.ppm"; then
        echo "ok"
    else
        echo "FAIL: $scene $size $num $ren: frames differ ($out/$tag-a.ppm $out/$tag-b.ppm)"
    fi
    rm -f "$out/$tag-a.ppm" "$out/$tag-b.ppm" "$out/$tag-a.err" "$out/$tag-b.err"
}
export -f one
export OLD FXRT out

list=$(mktemp)
trap 'rm -f "$list"' EXIT
for scene in "${scenes[@]}"; do
    for num in q16 float double; do
        echo "$scene 160x120 $num fast"
        echo "$scene 64x48 $num fast"
        echo "$scene 64x48 $num reference"
        echo "$scene 64x48 $num raycast"
    done
done >"$list"
progress "same-frames: $(wc -l <"$list") renders in both tools, against $rev"
refused=0
while read -r res; do
    case $res in
        ok) ok ;;
        refused*) refused=$((refused + 1)); ok ;;
        *) bad "${res#FAIL: }" ;;
    esac
done < <(tr ' ' '\t' <"$list" | xargs -P "$jobs" -L 1 -d '\n' bash -c 'IFS=$'"'"'\t'"'"' read -r a b c d <<<"$0"; one "$a" "$b" "$c" "$d"')
echo "same-frames: $((PASSED + FAILED)) frames against $rev ($refused refused by both alike)"
report same-frames
