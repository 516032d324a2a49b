#!/usr/bin/env bash
# make bench-ablation: what each optimisation of the scanline renderer
# saves, in Q16.16 instructions per frame on one board (default
# mps2-an385, Cortex-M3) at 160x120, with every variant's frame required
# to be byte-identical to the fast renderer's. Rows:
#   reference, no hoisting  every object's forms recomputed at every pixel
#   reference               forms once per frame, every object every pixel
#   fast, no bounds         stepping, but over the whole screen
#   fast, no stepping       bounds, but every form evaluated from scratch
#   fast, no lone painting  every hit through the owner bookkeeping
#   fast, no spans          lone flat pieces stepped pixel by pixel
#   fast, no depth ranges   every overlap decided by computing both depths
#                           (no z ranges, no per-row order against planes)
#   fast, no row coherence  a lone object's runs found from scratch on each
#                           row (no sphere forms stepped down the rows, no
#                           search from the row before's runs)
#   fast, scene order       objects visited in scene order (kind after
#                           kind), not sorted nearest first per frame
#   fast                    the default build
# Scenes: the seed scenes and, when present, scenes/bench/ (ABLATE_SCENES
# overrides the list).
# Prints a markdown table and keeps it in BUILD/bench/ablation.md (the
# <!-- ablation --> block of docs/BENCHMARKS.md: make doc-blocks
# DOC_BLOCKS=ablation DOCS_UPDATE=1); exits non-zero if a frame differs.
set -eu
BUILD=${BUILD:-build}
BOARD=${BOARD:-mps2-an385}
SIZE=${ABLATE_SIZE:-160x120}
M="make -s --no-print-directory BUILD=$BUILD -o $BUILD/fxrt-scenec"
variants=(
    "reference, no hoisting|ablnohoist|-DFXRT_RENDERER=2 -DFXRT_ABLATE=FXRT_ABLATE_HOIST"
    "reference|ablref|-DFXRT_RENDERER=2"
    "fast, no bounds|ablnobounds|-DFXRT_ABLATE=FXRT_ABLATE_BOUNDS"
    "fast, no stepping|ablnostep|-DFXRT_ABLATE=FXRT_ABLATE_STEP"
    "fast, no lone painting|ablnolone|-DFXRT_ABLATE=FXRT_ABLATE_LONE"
    "fast, no spans|ablnospans|-DFXRT_ABLATE=FXRT_ABLATE_SPANS"
    "fast, no depth ranges|ablnozrange|-DFXRT_ABLATE=FXRT_ABLATE_ZRANGE"
    "fast, no row coherence|ablnocoh|-DFXRT_ABLATE=FXRT_ABLATE_COHERENCE"
    "fast, scene order|ablnoorder|-DFXRT_ABLATE=FXRT_ABLATE_ORDER"
    "fast||"
)
if [ -n "${ABLATE_SCENES:-}" ]; then
    read -r -a scenes <<<"$ABLATE_SCENES"
else
    scenes=(scenes/abb*.scene)
    for s in scenes/bench/*.scene; do
        [ -e "$s" ] && scenes+=("$s")
    done
fi
header="| variant |"
rule="|---|"
for s in "${scenes[@]}"; do
    n=$(basename "$s" .scene); [[ $n == abb* ]] && n=${n%%-*}; header+=" $n |"
    rule+="---:|"
done
declare -A ipp
fail=0
for v in "${variants[@]}"; do
    IFS='|' read -r label tag flags <<<"$v"
    for s in "${scenes[@]}"; do
        name=$(basename "$s" .scene)
        echo "[ablation] $label: $name" >&2
        args=(SCENE="$s" BOARD="$BOARD" NUMBER=q16 SIZE="$SIZE")
        [ -n "$tag" ] && args+=(FW_TAG="$tag" FW_EXTRA="$flags")
        line=$($M qemu "${args[@]}" | grep instructions=)
        ipp["$label|$name"]=$(sed -nE 's/.*instructions_per_pixel=([0-9.]+).*/\1/p' <<<"$line")
    done
done
# The fast frames come last; every other variant must match them.
for v in "${variants[@]}"; do
    IFS='|' read -r label tag flags <<<"$v"
    [ -z "$tag" ] && continue
    for s in "${scenes[@]}"; do
        name=$(basename "$s" .scene)
        if ! cmp -s "$BUILD/qemu/$BOARD/$name-q16-$SIZE-$tag.ppm" "$BUILD/qemu/$BOARD/$name-q16-$SIZE.ppm"; then
            echo "ablation: $label changes the frame of $name" >&2
            fail=1
        fi
    done
done
mkdir -p "$BUILD/bench"
{
echo "Q16.16 instructions per pixel on $BOARD at $SIZE (QEMU -icount); every variant's frame is byte-identical to the fast one."
echo
echo "$header geo. mean |"
echo "$rule---:|"
for v in "${variants[@]}"; do
    IFS='|' read -r label tag flags <<<"$v"
    row="| $label |"
    vals=()
    for s in "${scenes[@]}"; do
        x=${ipp["$label|$(basename "$s" .scene)"]}
        row+=" $x |"
        vals+=("$x")
    done
    gm=$(printf '%s\n' "${vals[@]}" | awk '{ s += log($1); n++ } END { printf "%.1f", exp(s / n) }')
    echo "$row $gm |"
done
} | tee "$BUILD/bench/ablation.md"
exit $fail
