#!/usr/bin/env bash
# make bench-samples (also part of make bench): issue 12's cheap case of
# supersampling, "all N x N samples in one object, no secondary rays".
# Two groups of scenes, each with its samples line set to 1, 2 and 4,
# Q16.16, the fast renderer, at BENCH_SIZE on every board, in QEMU
# (-icount instructions per output pixel), and each frame's estimated
# cycles per output pixel (the same ELF under QEMU's execution trace,
# firmware/cycles.sh CYCLES_FRAME=1: these frames are short enough to trace
# whole, so no CPI is carried over from another size). Every firmware frame must be
# byte-identical to the host's q16 render of the same copy (the script
# fails otherwise); a scene that does not fit a board is reported as such.
#
#   cheap (scenes/samples/*.scene, SAMPLES_CHEAP): one flat object fills
#     the view, so every pixel is the cheap case. Targets (our reading of
#     "costs little more than one sample": the sampling pass works from
#     runs, core/frame/render_sample.c, and does nothing per sample):
#       - per scene, samples N costs at most N times samples 1 per output
#         pixel: ratio <= 2 at N = 2, <= 4 at N = 4;
#       - geometric mean <= 1.5x at N = 2, <= 2.5x at N = 4.
#   seed (scenes/abb*.scene, SAMPLES_SCENES): objects with silhouettes; a
#     pixel a silhouette crosses is not the cheap case, and each of the N
#     fine rows of an output row locates its own silhouette ends. Reported
#     with the same ratios, for information. (Until one sample per pixel
#     got row coherence, the targets above were checked on this group;
#     since then samples 1 costs half as much on the sphere scenes while
#     samples N is unchanged, so its ratios are about N.)
# Before run mode the M3 took 6.6x (N = 2) and 16.5x (N = 4) on abb9.
#
# Writes build/bench/samples.csv and samples.md; BENCH_UPDATE_DOCS=1 also
# replaces the block between <!-- bench:samples --> and <!-- /bench:samples -->
# in docs/BENCHMARKS.md. Environment: BUILD, BENCH_SIZE (160x120),
# BENCH_BOARD_INFO ("board:cpu:fb ..."), SAMPLES_CHEAP, SAMPLES_SCENES,
# SAMPLES_JOBS (nproc).
set -euo pipefail
BUILD=${BUILD:-build}
FXRT=${FXRT:-$BUILD/fxrt}
SIZE=${BENCH_SIZE:-160x120}
BOARD_INFO=${BENCH_BOARD_INFO:-"mps2-an385:M3:full mps2-an386:M4F:full microbit:M0:stream"}
CHEAP=${SAMPLES_CHEAP:-$(ls scenes/samples/*.scene)}
SEED=${SAMPLES_SCENES:-$(ls scenes/abb*.scene)}
JOBS=${SAMPLES_JOBS:-$(nproc 2>/dev/null || echo 2)}
OUT=$BUILD/bench/samples
unset MAKEFLAGS MFLAGS MAKELEVEL
M="make -s --no-print-directory BUILD=$BUILD -o $BUILD/fxrt-scenec"
rm -rf "$OUT"
mkdir -p "$OUT/scenes" "$OUT/host" "$OUT/runs"
start=$(date +%s)

# The copies and their host frames.
names=()
for sc in $CHEAP $SEED; do
    b=$(basename "$sc" .scene)
    for n in 1 2 4; do
        name=$b-s$n
        { grep -vE '^[[:space:]]*samples[[:space:]]' "$sc"; [ $n -gt 1 ] && echo "samples $n"; } >"$OUT/scenes/$name.scene"
        "$FXRT" render "$OUT/scenes/$name.scene" --size "$SIZE" --number q16 -o "$OUT/host/$name.ppm"
        names+=("$name")
    done
done

# One run: BOARD NAME -> runs/BOARD-NAME.txt: "ok IPP CPP" (instructions
# and estimated cycles per output pixel), "nofit", or "FAIL why".
run_one() {
    local b=$1 name=$2 log line ipp fb frame cpp
    fb=$(tr ' ' '\n' <<<"$BOARD_INFO" | sed -n "s/^$b:[^:]*:\(.*\)/\1/p")
    log=$OUT/runs/$b-$name.log
    if ! $M qemu SCENE="$OUT/scenes/$name.scene" BOARD="$b" SIZE="$SIZE" FB="$fb" >"$log" 2>&1; then
        if grep -q "does not fit\|region .RAM' overflowed" "$log"; then
            echo nofit >"$OUT/runs/$b-$name.txt"
        else
            echo "FAIL make qemu: $(tail -n 3 "$log" | tr '\n' ' ')" >"$OUT/runs/$b-$name.txt"
        fi
        return 0
    fi
    line=$(grep -o 'instructions_per_pixel=[0-9.]*' "$log" | tail -n 1)
    ipp=${line#*=}
    if ! cmp -s "$BUILD/qemu/$b/$name-q16-$SIZE.ppm" "$OUT/host/$name.ppm"; then
        echo "FAIL frame differs from the host q16 render" >"$OUT/runs/$b-$name.txt"
        return 0
    fi
    if ! frame=$(CYCLES_FRAME=1 BUILD=$BUILD firmware/cycles.sh "$BUILD/fw/$b/$name-q16-$SIZE-$fb/fxrt.elf" "$b" 2>>"$log" |
                 grep '^frame '); then
        echo "FAIL firmware/cycles.sh: $(tail -n 2 "$log" | tr '\n' ' ')" >"$OUT/runs/$b-$name.txt"
        return 0
    fi
    cpp=$(awk -v s="$SIZE" '{ split(s, wh, "x"); sub(/.*estimate=/, ""); sub(/ .*/, ""); printf "%.1f", $0 / (wh[1] * wh[2]) }' <<<"$frame")
    echo "ok $ipp $cpp" >"$OUT/runs/$b-$name.txt"
}
export -f run_one
export OUT M SIZE BUILD BOARD_INFO
for i in $BOARD_INFO; do
    for name in "${names[@]}"; do echo "${i%%:*} $name"; done
done | xargs -P "$JOBS" -n 2 bash -c 'run_one "$0" "$1"'

# Tables and verdicts.
fails=0
csv=$OUT/../samples.csv
md=$OUT/../samples.md
echo "board,scene,samples,instructions_per_pixel,cycles_per_pixel,status" >"$csv"
{
    echo "Regenerate with \`make bench-samples BENCH_UPDATE_DOCS=1\` (also part of \`make bench\`). Last run"
    echo "$(date -u '+%Y-%m-%d %H:%M UTC'), commit ${BENCH_REV:-$(git rev-parse --short HEAD 2>/dev/null || echo unknown)$(git diff --quiet HEAD 2>/dev/null || echo ' (with uncommitted changes)')},"
    echo "$(( $(date +%s) - start )) s at $SIZE. Q16.16, fast renderer, instructions per output pixel (QEMU \`-icount\`)"
    echo "and estimated cycles per output pixel (each frame's execution trace, priced as in \"Cycles\");"
    echo "every frame byte-identical to the host's q16 render of the same scene copy. The targets are on instructions."
    echo
} >"$md"
gm() { printf '%s\n' "$@" | awk 'NF { s += log($1); n++ } END { if (n) printf "%.2f", exp(s / n); else printf "-" }'; }
mx() { printf '%s\n' "$@" | awk 'NF { if (!n++ || $1 > m) m = $1 } END { if (n) printf "%.2f", m; else printf "-" }'; }
verdict() { awk -v x="$1" -v g="$2" 'BEGIN { if (x == "-") print "- (no scene fits)"; else if (x <= g) print "**PASS**"; else printf "**MISS** (%.2fx over)\n", x / g }'; }
x() { [ "$1" = - ] && echo - || echo "$1x"; }
# group BOARD LABEL TARGETS SCENE...: one table of a board's group; with
# TARGETS 1 the verdicts, else the same figures for information.
group() {
    local b=$1 label=$2 targets=$3 sc s n r r2 r4 c2 c4 g2 g4 m2 m4 cg2 cg4 cm2 cm4
    shift 3
    local l2=() l4=() k2=() k4=()
    {
        echo "$label"
        echo
        echo "| scene | samples 1 | samples 2 | samples 4 | samples 2 / 1 | samples 4 / 1 | est. cycles/px: samples 1 | samples 2 | samples 4 | samples 2 / 1 | samples 4 / 1 |"
        echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
    } >>"$md"
    for sc in "$@"; do
        s=$(basename "$sc" .scene)
        declare -A v=() cy=()
        for n in 1 2 4; do
            r=$(cat "$OUT/runs/$b-$s-s$n.txt" 2>/dev/null || echo "FAIL no result")
            case $r in
            ok*) read -r _ v[$n] cy[$n] <<<"$r" ;;
            nofit) v[$n]=nofit cy[$n]=nofit ;;
            *) v[$n]=FAIL cy[$n]=FAIL; fails=$((fails + 1)); echo "bench-samples: $b $s samples $n: $r" >&2 ;;
            esac
            echo "$b,$s,$n,${v[$n]},${cy[$n]},${r%% *}" >>"$csv"
        done
        cell() { case ${v[$1]} in nofit) echo "does not fit" ;; FAIL) echo "FAIL" ;; *) echo "${v[$1]}" ;; esac; }
        ccell() { case ${cy[$1]} in nofit) echo "does not fit" ;; FAIL) echo "FAIL" ;; *) echo "${cy[$1]}" ;; esac; }
        ratio() { # ratio N ARRAY
            local -n a=$2
            case ${a[1]}${a[$1]} in *nofit* | *FAIL*) echo "-" ;; *) awk -v x="${a[$1]}" -v y="${a[1]}" 'BEGIN { printf "%.2fx", x / y }' ;; esac
        }
        r2=$(ratio 2 v) r4=$(ratio 4 v) c2=$(ratio 2 cy) c4=$(ratio 4 cy)
        echo "| $s | $(cell 1) | $(cell 2) | $(cell 4) | $r2 | $r4 | $(ccell 1) | $(ccell 2) | $(ccell 4) | $c2 | $c4 |" >>"$md"
        [ "$r2" != - ] && l2+=("${r2%x}") && k2+=("${c2%x}")
        [ "$r4" != - ] && l4+=("${r4%x}") && k4+=("${c4%x}")
        unset v cy
    done
    g2=$(gm "${l2[@]}") g4=$(gm "${l4[@]}") m2=$(mx "${l2[@]}") m4=$(mx "${l4[@]}")
    cg2=$(gm "${k2[@]}") cg4=$(gm "${k4[@]}") cm2=$(mx "${k2[@]}") cm4=$(mx "${k4[@]}")
    if [ "$targets" = 1 ]; then
        {
            echo
            echo "| target ($b) | goal | measured | result | in est. cycles |"
            echo "|---|---:|---:|---|---:|"
            echo "| worst scene, samples 2 / 1 | <= 2x | $(x "$m2") | $(verdict "$m2" 2) | $(x "$cm2") |"
            echo "| worst scene, samples 4 / 1 | <= 4x | $(x "$m4") | $(verdict "$m4" 4) | $(x "$cm4") |"
            echo "| geometric mean, samples 2 / 1 | <= 1.5x | $(x "$g2") (${#l2[@]} scenes) | $(verdict "$g2" 1.5) | $(x "$cg2") |"
            echo "| geometric mean, samples 4 / 1 | <= 2.5x | $(x "$g4") (${#l4[@]} scenes) | $(verdict "$g4" 2.5) | $(x "$cg4") |"
            echo
        } >>"$md"
    else
        {
            echo
            echo "Geometric mean $(x "$g2") at samples 2, $(x "$g4") at samples 4 (worst $(x "$m2"), $(x "$m4"); information, no target);"
            echo "in estimated cycles $(x "$cg2") and $(x "$cg4") (worst $(x "$cm2"), $(x "$cm4"))."
            echo
        } >>"$md"
    fi
}
for i in $BOARD_INFO; do
    b=${i%%:*} cpu=$(cut -d: -f2 <<<"$i")
    group "$b" "**$b ($cpu): the cheap case, every pixel (scenes/samples/)**" 1 $CHEAP
    group "$b" "**$b ($cpu): seed scenes, with silhouettes (information)**" 0 $SEED
done
cat "$md"
if [ "${BENCH_UPDATE_DOCS:-0}" = 1 ]; then
    doc=docs/BENCHMARKS.md
    host/replace-block.sh "$doc" bench:samples "$md" || exit 1
    echo "bench-samples: updated $doc"
fi
[ "$fails" -eq 0 ] || { echo "bench-samples: $fails runs failed (see above)" >&2; exit 1; }
