#!/usr/bin/env bash
# make bench-lit-bound: how far the lit set's soft-float ratio can go on a
# board (default microbit, Cortex-M0, where issue 11 asks >= 8x) without
# changing how a lit pixel finds its hit point. Per lit scene at 160x120,
# side by side in one run (QEMU -icount, instructions per pixel):
#   float step          the best soft-float build (-DFXRT_FLOAT_STEP=1)
#   q16                 the fast renderer
#   q16, no light sum   the same with -DFXRT_ABLATE=FXRT_ABLATE_LIGHT_SUM: camera
#                       ray, hit point and normal at every lit pixel, the
#                       light sum stopped before its first light (no light
#                       vector, n . l, Phong term or shadow ray)
#   float step, no light sum   the same switch in the float build
# float step / (q16, no light sum) bounds float / q16 for any light sum,
# however cheap, on top of this visibility pass and hit point: the float
# build keeps its light sum. The light sums' own costs are the
# differences (float step - its no-light-sum build, q16 - its), and the
# last column is what q16's may cost for 8x: float step / 8 - (q16, no
# light sum). The no-light-sum builds' frames must differ from the
# renderer's (the light sum really went); the script exits non-zero if not.
# float / q16 is also given in estimated cycles: each build's frame CPI,
# priced by firmware/cycles.sh at LIT_BOUND_CYCLES_SIZE (40x30; "none":
# no cycles), times its instructions (docs/BENCHMARKS.md, "Cycles").
# The table is also kept in BUILD/bench/lit-bound.md (the <!-- lit-bound -->
# block of docs/BENCHMARKS.md: make doc-blocks DOC_BLOCKS=lit-bound
# DOCS_UPDATE=1).
set -euo pipefail
BUILD=${BUILD:-build}
BOARD=${BOARD:-microbit}
SIZE=${LIT_BOUND_SIZE:-160x120}
CSIZE=${LIT_BOUND_CYCLES_SIZE:-40x30}
M="make -s --no-print-directory BUILD=$BUILD -o $BUILD/fxrt-scenec"
builds=(
    "float step|float|step|-DFXRT_FLOAT_STEP=1"
    "q16|q16||"
    "q16, no light sum|q16|bound|-DFXRT_ABLATE=FXRT_ABLATE_LIGHT_SUM"
    "float step, no light sum|float|stepbound|-DFXRT_FLOAT_STEP=1 -DFXRT_ABLATE=FXRT_ABLATE_LIGHT_SUM"
)
declare -A ipp cpi
fail=0
scenes=(scenes/lit/*.scene)
for s in "${scenes[@]}"; do
    name=$(basename "$s" .scene)
    for b in "${builds[@]}"; do
        IFS='|' read -r label number tag flags <<<"$b"
        echo "[lit-bound] $name: $label" >&2
        args=(SCENE="$s" BOARD="$BOARD" NUMBER="$number" SIZE="$SIZE")
        [ -n "$tag" ] && args+=(FW_TAG="$tag" FW_EXTRA="$flags")
        line=$($M qemu "${args[@]}" | grep instructions=) || {
            echo "lit-bound: $name: $label: make qemu failed or printed no count" >&2
            exit 1
        }
        ipp["$label|$name"]=$(sed -nE 's/.*instructions_per_pixel=([0-9.]+).*/\1/p' <<<"$line")
        if [ -z "${ipp["$label|$name"]}" ]; then
            echo "lit-bound: $name: $label: no instructions_per_pixel in: $line" >&2
            exit 1
        fi
        cpi["$label|$name"]=1
        if [[ $CSIZE != none && ($label == "float step" || $label == q16) ]]; then
            cpi["$label|$name"]=$(FW_EXTRA="$flags" FW_TAG="$tag" BUILD=$BUILD CYCLES_FRAME=1 CYCLES_CPI=1 \
                firmware/cycles.sh "$s" "$BOARD" "$number" "$CSIZE") && [[ -n ${cpi["$label|$name"]} ]] || {
                echo "lit-bound: $name: $label: the cycle pricing at $CSIZE failed" >&2
                exit 1
            }
        fi
    done
    for pair in "q16-$SIZE-bound q16-$SIZE" "float-$SIZE-stepbound float-$SIZE-step"; do
        read -r a b <<<"$pair"
        if cmp -s "$BUILD/qemu/$BOARD/$name-$a.ppm" "$BUILD/qemu/$BOARD/$name-$b.ppm"; then
            echo "lit-bound: $name: the no-light-sum frame $a equals $b (the switch did nothing)" >&2
            fail=1
        fi
    done
done
mkdir -p "$BUILD/bench"
{
echo "Lit scenes on $BOARD at $SIZE, instructions per pixel (QEMU -icount), one run; float / q16 also in estimated cycles ($([[ $CSIZE == none ]] && echo "not priced: LIT_BOUND_CYCLES_SIZE=none" || echo "each build's frame CPI at $CSIZE times its instructions"))."
echo
echo "| scene | float step | q16 | float / q16 | float / q16, est. cycles | float, no light sum | q16, no light sum | float / (q16, no light sum) | light sum: float | light sum: q16 | light sums: float / q16 | q16 light sum for 8x |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for s in "${scenes[@]}"; do
    name=$(basename "$s" .scene)
    f=${ipp["float step|$name"]} q=${ipp["q16|$name"]} z=${ipp["q16, no light sum|$name"]}
    fz=${ipp["float step, no light sum|$name"]}
    echo "$name $f $q $z $fz ${cpi["float step|$name"]} ${cpi["q16|$name"]}"
done | awk -v priced=$([[ $CSIZE == none ]] && echo 0 || echo 1) 'function row(nm, f, q, z, fz, rc) {
                printf "| %s | %.1f | %.1f | %.2fx | %s | %.1f | %.1f | %.2fx | %.1f | %.1f | %.2fx | %.1f |\n", nm, f, q, f / q,
                    priced ? sprintf("%.2fx", rc) : "n/a", fz, z, f / z, f - fz, q - z, (f - fz) / (q - z), f / 8 - z }
            { row($1, $2, $3, $4, $5, $2 * $6 / ($3 * $7)); lf += log($2); lq += log($3); lz += log($4); lfz += log($5); lc += log($2 * $6 / ($3 * $7)); n++ }
            END { row("geometric mean", exp(lf / n), exp(lq / n), exp(lz / n), exp(lfz / n), exp(lc / n)) }'
} | tee "$BUILD/bench/lit-bound.md"
exit $fail
