#!/usr/bin/env bash
# make frontier (also part of make bench): the run-time-against-error
# frontier of issue 12. Every board runs every number build (q16, the best
# float build, double) at samples 1, 2, 4 and "4 adaptive" on the frontier
# scenes, in QEMU (-icount instructions). Each frame is compared with the
# CONVERGED image: the host double render of the same scene at the same size
# with `samples 16` (16x16 rays per pixel). Reported per run: mean absolute
# error per channel (mae, 1/255 units), PSNR, share of pixels within 1/255,
# instructions per pixel, estimated cycles per pixel (the frame's CPI priced
# by firmware/cycles.sh at FRONTIER_CYCLES_SIZE, times its instructions),
# stack_used; for q16 whether the firmware frame is
# byte-identical to the host's q16 render of the same scene, size and samples.
# Per board: a table (averaged over the scenes), the Pareto front and a plot
# (firmware/frontier.gp), and which build to pick for each error budget.
# Also the stack figures of the deepest scenes (trace-mirrors, depth 16, and
# glass) per board and build.
#
# Writes build/frontier/: frontier.csv, frontier.md, frontier-BOARD.png,
# stack.csv. FRONTIER_UPDATE_DOCS=1 (or BENCH_UPDATE_DOCS=1 through make
# bench) also writes docs/frontier/ and the Frontier section of
# docs/BENCHMARKS.md (between <!-- frontier --> and <!-- /frontier -->).
#
# Environment (all optional):
#   BUILD               build directory (build)
#   FRONTIER_SIZE       frame size (64x48)
#   FRONTIER_SCENES     scene files (default below: three lit scenes, the
#                       reflection and the glass scene)
#   FRONTIER_SAMPLES    sample settings (1 2 4 4a; "Na" = N adaptive)
#   FRONTIER_BUILDS     NUMBER:LOOP words (q16:fast float:step double:fast)
#   FRONTIER_BOARDS     boards (all three)
#   FRONTIER_STACK_SCENES  scenes for the stack figures
#   FRONTIER_JOBS       parallel runs (nproc)
#   FRONTIER_CYCLES_SIZE  frame size of the cycle pricing (16x12; "none":
#                       no cycles)
#   FRONTIER_TABLES_ONLY  1: no runs; tables and plots from the last CSV
#   BENCH_BOARD_INFO    "board:cpu:fb ..." (bench.mk passes it)
set -euo pipefail
BUILD=${BUILD:-build}
FXRT=${FXRT:-$BUILD/fxrt}
SIZE=${FRONTIER_SIZE:-64x48}
BOARD_INFO=${BENCH_BOARD_INFO:-"mps2-an385:M3:full mps2-an386:M4F:full microbit:M0:stream"}
BOARDS=${FRONTIER_BOARDS:-$(for i in $BOARD_INFO; do printf '%s ' "${i%%:*}"; done)}
# Three of the nine lit scenes (see docs/BENCHMARKS.md, "Frontier"): the
# course's phong scene with a point light, shadows, and coloured lights.
SCENES=${FRONTIER_SCENES:-"scenes/lit/course-phong-point.scene scenes/lit/shadows.scene scenes/lit/coloured-lights.scene scenes/trace/reflection.scene scenes/trace/glass.scene"}
SAMPLES=${FRONTIER_SAMPLES:-"1 2 4 4a"}
# float:step is what firmware/bench.sh names the best float build on every
# board and set (fewest instructions at no more error than q16).
BUILDS=${FRONTIER_BUILDS:-"q16:fast float:step double:fast"}
STACK_SCENES=${FRONTIER_STACK_SCENES:-"scenes/stress/trace-mirrors.scene scenes/trace/glass.scene"}
JOBS=${FRONTIER_JOBS:-$(nproc 2>/dev/null || echo 2)}
CSIZE=${FRONTIER_CYCLES_SIZE:-16x12}
OUT=$BUILD/frontier
unset MAKEFLAGS MFLAGS MAKELEVEL
export FIT_QUICK=1
M="make -s --no-print-directory BUILD=$BUILD -o $BUILD/fxrt-scenec"

die() { echo "frontier: $*" >&2; exit 1; }
board_field() {
    local i
    for i in $BOARD_INFO; do
        [[ ${i%%:*} == "$1" ]] && { cut -d: -f"$2" <<<"$i"; return; }
    done
    die "unknown board '$1'"
}
get() { sed -nE "s/.*(^| )$1=([^ ]+).*/\2/p" <<<"$2" | tail -n 1; }

# --- one unit: one (board, scene copy, build) ---------------------------------
# CSV row: kind,scene,samples,board,cpu,number,loop,status,instructions,
# instructions_per_pixel,mae,psnr,within1_pct,max_err,stack_used,stack_size,
# q16_identical,all_kinds,note,cpi,cycles_per_pixel
# status: ok; nofit (RAM/flash, fit.sh); stack (the run left less than
# FXRT_STACK_MARGIN of the stack: the firmware refuses the frame); fault
# (HardFault, e.g. a stack overflow into .bss); fail (anything else).
if [[ ${1:-} == --unit ]]; then
    id=$2 board=$3 kind=$4 scene=$5 base=$6 smp=$7 spec=$8
    number=${spec%%:*} loop=${spec#*:}
    cpu=$(board_field "$board" 2) fb=$(board_field "$board" 3)
    name=$(basename "$scene" .scene)
    echo "[$id] $kind $base s$smp $cpu $number $loop" >&2
    extra=() tag=""
    [[ $loop == step ]] && { extra+=(FW_EXTRA=-DFXRT_FLOAT_STEP=1); tag=step; }
    # ak: the run used FW_ALL_KINDS=1 (scenec --all-kinds); no longer
    # needed (a tracing scene without a box links since core/light/trace.c has its
    # own bounds test), kept as a CSV column for older runs.
    ak=0
    [[ -n $tag ]] && extra+=(FW_TAG="$tag")
    log=$OUT/runs/$id.log
    row() { echo "$kind,$base,$smp,$board,$cpu,$number,$loop,$1,$ak,$2,${3:-}" >"$OUT/runs/$id.csv"; }
    rc=0
    $M qemu SCENE="$scene" BOARD="$board" NUMBER="$number" SIZE="$SIZE" FB="$fb" "${extra[@]}" >"$log" 2>&1 || rc=$?
    line=$(grep 'stack_used=[0-9]' "$log" | tail -n 1 || true)
    su=$(get stack_used "$line") ss=$(get stack_size "$line")
    if [[ $rc -ne 0 ]]; then
        if grep -q "does not fit $board" "$log"; then
            note=$(grep -o "does not fit $board.*needs [0-9]* B[^;,(]*" "$log" | head -n 1 | tr ',' ' ')
            row "nofit,,,,,,,$su,$ss," "$note"
        elif grep -q 'FXRT_STACK_MARGIN' "$log"; then
            row "stack,,,,,,,$su,$ss," "stack_used=$su of $ss (margin FXRT_STACK_MARGIN)"
        elif grep -q 'HardFault' "$log"; then
            row "fault,,,,,,,$su,$ss," "HardFault"
        else
            row "fail,,,,,,,$su,$ss," "$(grep -m1 -i 'error' "$log" | tr ',' ' ' | cut -c1-120)"
        fi
        exit 0
    fi
    ins=$(get instructions "$line") ipp=$(get instructions_per_pixel "$line")
    frame=$BUILD/qemu/$board/$name-$number-$SIZE${tag:+-$tag}.ppm
    [[ -n $ins && -f $frame ]] || { row "fail,,,,,,,$su,$ss," "no instructions= line or frame"; exit 0; }
    mkdir -p "$OUT/frames/$board"
    cp "$frame" "$OUT/frames/$board/$base-s$smp-$number-$loop.ppm"
    cmp=$("$FXRT" compare "$OUT/ref/$base-converged.ppm" "$frame" 2>&1) || { row "fail,,,,,,,$su,$ss," "fxrt compare failed"; exit 0; }
    ident=""
    if [[ $number == q16 ]]; then
        if cmp -s "$frame" "$OUT/ref/$name-q16.ppm"; then ident=yes; else ident=NO; fi
    fi
    # Estimated cycles: the frame's CPI at CSIZE (the frontier's frames are
    # small already; the trace costs about 20 times the -icount run).
    cyc=","
    if [[ $CSIZE != none && $kind == frontier ]]; then
        clog=$OUT/runs/$id.cycles
        if cpi=$(FW_EXTRA="${tag:+-DFXRT_FLOAT_STEP=1}" FW_TAG="$tag" CYCLES_FB="$fb" BUILD=$BUILD CYCLES_FRAME=1 CYCLES_CPI=1 \
            firmware/cycles.sh "$scene" "$board" "$number" "$CSIZE" 2>"$clog") && [[ -n $cpi ]]; then
            cyc="$cpi,$(awk -v a="$ipp" -v c="$cpi" 'BEGIN { printf "%.1f", a * c }')"
        else
            row "fail,,,,,,,$su,$ss," "cycle pricing at $CSIZE failed (see $clog)"
            exit 0
        fi
    fi
    row "ok,$ins,$ipp,$(get mae "$cmp"),$(get psnr "$cmp"),$(get within1_pct "$cmp"),$(get max_err "$cmp"),$su,$ss,$ident" "" "$cyc"
    exit 0
fi

start=$SECONDS
mkdir -p "$OUT"
if [[ ${FRONTIER_TABLES_ONLY:-0} != 1 ]]; then
    [[ -x $FXRT ]] || die "$FXRT not built"
    rm -rf "$OUT/runs" "$OUT/ref" "$OUT/scenes" "$OUT/frames"
    mkdir -p "$OUT/runs" "$OUT/ref" "$OUT/scenes"
    units=()
    idx=1
    # A copy of SCENE with its samples line replaced: fr-BASE-sS.scene.
    copy() { # SCENE SAMPLES(1, 4a, 16) -> path
        local n=${2%a} a="" dst
        [[ $2 == *a ]] && a=" adaptive"
        dst=$OUT/scenes/fr-$(basename "$1" .scene)-s$2.scene
        { sed '/^[[:space:]]*samples[[:space:]]/d' "$1"; echo "samples $n$a"; } >"$dst"
        echo "$dst"
    }
    for scene in $SCENES; do
        [[ -f $scene ]] || die "no such scene: $scene"
        base=$(basename "$scene" .scene)
        conv=$(copy "$scene" 16)
        "$FXRT" render "$conv" --number double --size "$SIZE" -o "$OUT/ref/$base-converged.ppm" >/dev/null ||
            die "host render of $conv failed"
        for s in $SAMPLES; do
            c=$(copy "$scene" "$s")
            "$FXRT" render "$c" --number q16 --size "$SIZE" -o "$OUT/ref/$(basename "$c" .scene)-q16.ppm" >/dev/null ||
                die "host q16 render of $c failed"
            for b in $BOARDS; do
                for spec in $BUILDS; do
                    units+=("$(printf '%04d' $idx) $b frontier $c $base $s $spec")
                    idx=$((idx + 1))
                done
            done
        done
    done
    # Stack figures: the deepest scenes at their own samples.
    for scene in $STACK_SCENES; do
        [[ -f $scene ]] || die "no such scene: $scene"
        base=$(basename "$scene" .scene)
        c=$OUT/scenes/fr-stack-$base.scene
        cp "$scene" "$c"
        # The error of these runs is against the double render at the
        # scene's own samples (not a converged image): they are for the stack.
        "$FXRT" render "$c" --number double --size "$SIZE" -o "$OUT/ref/stack-$base-converged.ppm" >/dev/null ||
            die "host render of $c failed"
        "$FXRT" render "$c" --number q16 --size "$SIZE" -o "$OUT/ref/fr-stack-$base-q16.ppm" >/dev/null ||
            die "host q16 render of $c failed"
        for b in $BOARDS; do
            for spec in $BUILDS; do
                units+=("$(printf '%04d' $idx) $b stack $c stack-$base own $spec")
                idx=$((idx + 1))
            done
        done
    done
    total=$((idx - 1))
    echo "frontier: $total runs at $SIZE, $JOBS in parallel" >&2
    printf '%s\n' "${units[@]}" |
        xargs -P "$JOBS" -L 1 sh -c 'exec "$0" --unit "$@"' "$0" || die "a run failed (logs in $OUT/runs/)"
    n_csv=$(find "$OUT/runs" -name '*.csv' | wc -l)
    [[ $n_csv -eq $total ]] || die "expected $total results, found $n_csv in $OUT/runs/"
    {
        echo "kind,scene,samples,board,cpu,number,loop,status,instructions,instructions_per_pixel,mae,psnr,within1_pct,max_err,stack_used,stack_size,q16_identical,all_kinds,note,cpi,cycles_per_pixel"
        cat "$OUT"/runs/*.csv
    } >"$OUT/frontier.csv"
    echo $((SECONDS - start)) >"$OUT/elapsed"
fi
[[ -f $OUT/frontier.csv ]] || die "no $OUT/frontier.csv (run without FRONTIER_TABLES_ONLY first)"
elapsed=$(cat "$OUT/elapsed" 2>/dev/null || echo "?")
total=$(($(wc -l <"$OUT/frontier.csv") - 1))
exec env OUT="$OUT" SIZE="$SIZE" BOARDS="$BOARDS" ELAPSED="$elapsed" TOTAL="$total" JOBS="$JOBS" \
    BUILDS="$BUILDS" SAMPLES="$SAMPLES" BOARD_INFO="$BOARD_INFO" CSIZE="$CSIZE" firmware/frontier-report.sh
