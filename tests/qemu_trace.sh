#!/usr/bin/env bash
# Firmware in QEMU, trace scenes (issue 12: reflection, refraction,
# supersampling), Q16.16 byte-identical to the host's `fxrt render
# --number q16` at the same size:
#   1. tests/onboard_main.c, one ELF per board (mps2-an385, mps2-an386,
#      microbit) holding every scenes/trace/ scene, every
#      scenes/stress/trace-* scene and two variants made here, the
#      reflection scene at `samples 2` and the glass scene at
#      `samples 2 adaptive`, and seed scenes supersampled (abb9 at
#      samples 4, abb10 and abb8 at 2, abb7 at 2 adaptive: the sampling
#      pass from runs), at $SIZE, frames streamed row by row. On the
#      micro:bit (16 KB) the scenes at samples 3 or more have ELFs of
#      their own (one per render width); a batch that still overflows is
#      halved until the halves fit (tests/onboard_lib.sh, onb_fit; the
#      scenes heaviest first: the widest render state, then the deepest),
#      and a single scene must fit. Both micro:bit batches overflow one
#      ELF whole, so they start as two halves (onb_fit_halves). make test
#      runs the batches on the M3 and the micro:bit: the M4F's q16 code is
#      the M3's Thumb-2 integer code (part 2 runs it on the M4F); make
#      test-full runs its batch too;
#   2. the firmware itself (firmware/main.c, make qemu):
#      - the deepest scene, scenes/stress/trace-mirrors.scene (depth 16),
#        on every board (make test: the M3 and the micro:bit; full frame
#        on the MPS2 boards, streaming on the micro:bit): its stack_used
#        must leave FXRT_STACK_MARGIN of the reservation (stack_size)
#        unused; the figures are printed;
#      - the micro:bit requirement: the reflection scene at 160x120 with
#        samples 2, streaming: it builds (fits 16 KB), runs and equals
#        the host; ram_static, stack_used and instructions per pixel;
#      - float on the Cortex-M4F (mps2-an386, hard float, full frame) for
#        the glass scene at samples 2 adaptive against the host's
#        `--number float` render (byte-identical too: same IEEE single
#        operations in the same order, no contraction under -std=c11).
# QEMU_TRACE_SIZE (default 64x48) keeps the suite short.
set -u
. "$(dirname "$0")/lib.sh"
out=$BUILD/tests/qemu_trace
onb=$out/onboard
BOARDS="mps2-an385 mps2-an386 microbit"
ONB_BOARDS="mps2-an385 microbit"
full && ONB_BOARDS=$BOARDS
SIZE=${QEMU_TRACE_SIZE:-64x48}
MB_SIZE=160x120
# -o: fxrt-scenec was built by make test; parallel sub-makes must not relink it.
M="make -s --no-print-directory BUILD=$BUILD -o $BUILD/fxrt-scenec"
rm -rf "$out"
mkdir -p "$onb/scenes" "$onb/host" "$out/variants"
. "$(dirname "$0")/onboard_lib.sh"
ONB_WHAT="qemu_trace.sh: trace scenes on board"
margin=$(sed -nE 's/^#define FXRT_STACK_MARGIN ([0-9]+).*/\1/p' core/fxrt_config.h)

# The variants: the scene with its samples line replaced.
variant() { # SCENE SAMPLES-LINE OUT
    { grep -vE '^[[:space:]]*samples[[:space:]]' "$1"; echo "$2"; } >"$3"
}
variant scenes/trace/reflection.scene "samples 2" "$out/variants/reflection-s2.scene"
variant scenes/trace/glass.scene "samples 2 adaptive" "$out/variants/glass-s2a.scene"
# Seed scenes supersampled: every object alone on its rows, so the
# sampling pass works from runs (spheres in perspective and orthographic
# views, a box, a triangle; adaptive too).
variant scenes/abb9-two-spheres.scene "samples 4" "$out/variants/abb9-s4.scene"
variant scenes/abb10-two-spheres-ortho.scene "samples 2" "$out/variants/abb10-s2.scene"
variant scenes/abb7-box.scene "samples 2 adaptive" "$out/variants/abb7-s2a.scene"
variant scenes/abb8-triangle.scene "samples 2" "$out/variants/abb8-s2.scene"
scenes=(scenes/trace/*.scene scenes/stress/trace-*.scene "$out/variants/reflection-s2.scene"
    "$out/variants/glass-s2a.scene" "$out"/variants/abb*.scene)
check "scenes/trace/ has the reflection, glass and supersample scenes" \
    test -f scenes/trace/reflection.scene -a -f scenes/trace/glass.scene -a -f scenes/trace/supersample.scene
check "scenes/stress/ has trace-* scenes, trace-mirrors among them" test -f scenes/stress/trace-mirrors.scene
check "the variants have samples 2 / samples 2 adaptive" \
    grep -qx "samples 2 adaptive" "$out/variants/glass-s2a.scene"

# Host q16 frames and the scenes compiled for the on-board program.
names=()
for scene in "${scenes[@]}"; do
    name=$(basename "$scene" .scene)
    mkdir -p "$onb/scenes/$name"
    if "$BUILD/fxrt-scenec" "$scene" --number q16 --size $SIZE --out "$onb/scenes/$name" 2>"$out/scenec.log" &&
        "$FXRT" render "$scene" --number q16 --size $SIZE -o "$onb/host/$name.ppm" 2>>"$out/scenec.log"; then
        names+=("$name")
    else
        bad "$scene: fxrt-scenec or host render failed: $(cat "$out/scenec.log")"
    fi
done
cfg() { cfg_value "$onb/scenes/$1/scene_config.h" "$2"; }
for n in reflection-s2 glass-s2a supersample; do
    check "$n: compiled with FXRT_MAX_SAMPLES > 1" test "$(cfg $n FXRT_MAX_SAMPLES)" -gt 1
done
check "glass-s2a: compiled with FXRT_ADAPTIVE 1" test "$(cfg glass-s2a FXRT_ADAPTIVE)" = 1
check "trace-mirrors: compiled with FXRT_MAX_DEPTH 16" test "$(cfg trace-mirrors FXRT_MAX_DEPTH)" = 16

# 1. on-board batches, scenes heaviest first (render width, then depth),
# so that halving a batch that overflows (onb_fit, tests/onboard_lib.sh)
# keeps the heavy scenes together and the light half fits.
sorted=($(for n in "${names[@]}"; do
    echo "$(cfg "$n" FXRT_RENDER_MAX_WIDTH) $(cfg "$n" FXRT_MAX_DEPTH) $n"
done | sort -k1,1nr -k2,2nr -k3 | awk '{ print $3 }'))

# 2. firmware/main.c: "BOARD FB NUMBER SIZE SCENE" per run.
V=$out/variants
# (make test-full also runs the M4F's q16 build: its integer code is the
# M3's Thumb-2, and it runs the seed batch in make test)
fw_runs=("mps2-an385 full q16 $SIZE scenes/stress/trace-mirrors.scene"
    "microbit stream q16 $SIZE scenes/stress/trace-mirrors.scene"
    "microbit stream q16 $MB_SIZE $V/reflection-s2.scene"
    "mps2-an386 full float $SIZE $V/glass-s2a.scene")
full && fw_runs+=("mps2-an386 full q16 $SIZE scenes/stress/trace-mirrors.scene")
fw_run() { # I BOARD FB NUMBER SIZE SCENE: build, run, compare; verdict line in $out/fw-I.txt
    local i=$1 b=$2 fb=$3 num=$4 size=$5 scene=$6 name log ppm line used size_
    name=$(basename "$scene" .scene)
    log=$out/fw-$i.log
    progress "qemu_trace.sh: firmware $b FB=$fb $num $name $size"
    ppm=$BUILD/qemu/$b/$name-$num-$size-trace$fb.ppm
    rm -f "$ppm"
    if ! $M qemu SCENE="$scene" BOARD=$b NUMBER=$num SIZE=$size FB=$fb FW_TAG=trace$fb >"$log" 2>&1; then
        echo "FAIL firmware $b FB=$fb $num $name $size: make qemu failed: $(grep -v '^make' "$log" | tail -n 4 | tr '\n' ' ')"
        return
    fi
    "$FXRT" render "$scene" --number $num --size $size -o "$out/fw-$i-host.ppm"
    line=$(grep '^board=' "$log" | tail -n 1)
    used=$(sed -nE 's/.*stack_used=([0-9]+).*/\1/p' <<<"$line")
    size_=$(sed -nE 's/.*stack_size=([0-9]+).*/\1/p' <<<"$line")
    if ! cmp -s "$out/fw-$i-host.ppm" "$ppm"; then
        cp "$ppm" "$out/fw-$i-board.ppm" 2>/dev/null
        echo "FAIL firmware $b FB=$fb $num $name $size: frame differs from the host $num render" \
            "($("$FXRT" compare "$out/fw-$i-host.ppm" "$out/fw-$i-board.ppm" 2>&1 | head -n 1)) $line"
    elif [ -z "$used" ] || [ -z "$size_" ] || [ $((used + margin)) -gt "$size_" ]; then
        echo "FAIL firmware $b FB=$fb $num $name $size: stack_used=$used + margin $margin > stack_size=$size_"
    else
        echo "PASS firmware $b FB=$fb $num $name $size $line"
    fi
}

# The jobs, two at a time (two cores): each is a build of a few seconds
# and a short run. On the micro:bit (16 KB), the scenes whose render state
# is more than twice as wide as the frame (samples 3 and more) get one
# batch per render width, the others one batch.
jobs_=()
for b in $ONB_BOARDS; do
    if [ "$b" = microbit ]; then
        wide=$((2 * ${SIZE%x*}))
        for w in $(for n in "${sorted[@]}"; do cfg "$n" FXRT_RENDER_MAX_WIDTH; done | sort -nru); do
            [ "$w" -gt $wide ] &&
                jobs_+=("onb $b w$w $(for n in "${sorted[@]}"; do [ "$(cfg "$n" FXRT_RENDER_MAX_WIDTH)" = "$w" ] && echo "$n"; done | tr '\n' ' ')")
        done
        jobs_+=("onb $b n $(for n in "${sorted[@]}"; do [ "$(cfg "$n" FXRT_RENDER_MAX_WIDTH)" -le $wide ] && echo "$n"; done | tr '\n' ' ')")
    else
        jobs_+=("onb $b all ${sorted[*]}")
    fi
done
for i in "${!fw_runs[@]}"; do jobs_+=("fw $i ${fw_runs[$i]}"); done
running=0
for k in "${!jobs_[@]}"; do
    set -- ${jobs_[$k]}
    if [ "$1" = onb ]; then
        b=$2 t=$3
        shift 3
        if [ "$b" = microbit ]; then
            onb_fit_halves "$b" "$t" "$@" >"$out/onb-$b-$k.txt" &
        else
            onb_fit "$b" "$t" "$@" >"$out/onb-$b-$k.txt" &
        fi
    else
        fw_run "$2" "$3" "$4" "$5" "$6" "$7" >"$out/fw-$2.txt" &
    fi
    running=$((running + 1))
    if [ $running -ge 2 ]; then
        wait -n
        running=$((running - 1))
    fi
done
wait
for b in $ONB_BOARDS; do cat "$out"/onb-$b-*.txt >"$out/onb-$b.txt" 2>/dev/null; done

for b in $ONB_BOARDS; do
    echo "== on-board batches, $b: ${#names[@]} trace scenes at $SIZE (streamed rows)"
    cat "$out/onb-$b.txt"
    np=$(grep -c "^PASS $b " "$out/onb-$b.txt")
    check "$b: every trace scene ran on board byte-identical to the host q16 render ($np of ${#scenes[@]})" \
        test "$np" -eq "${#scenes[@]}"
    check "$b: no batch failed (exit status, stack margin)" test "$(grep -c "^FAIL $b batch" "$out/onb-$b.txt")" -eq 0
    for n in reflection-s2 glass-s2a abb9-s4 abb10-s2 abb7-s2a abb8-s2; do
        check "$b: $n ($(tail -n 1 "$out/variants/$n.scene")) on board == host" \
            grep -q "^PASS $b $n " "$out/onb-$b.txt"
    done
done
echo "== firmware (firmware/main.c, make qemu)"
for i in "${!fw_runs[@]}"; do
    v=$(cat "$out/fw-$i.txt" 2>/dev/null)
    echo "$v"
    case $v in PASS*) ok ;; *) bad "${v:-firmware run $i (${fw_runs[$i]}): no verdict}" ;; esac
done
get() { sed -nE "s/.*(^| )$1=([^ ]+).*/\2/p" <<<"$2"; }
echo "== stack, deepest scene (trace-mirrors, depth 16), firmware/main.c at $SIZE (bytes; margin $margin)"
for b in $BOARDS; do
    l=$(grep -h "^PASS firmware $b .* trace-mirrors " "$out"/fw-*.txt) || continue
    echo "$b: stack_used=$(get stack_used "$l") stack_size=$(get stack_size "$l") ram_static=$(get ram_static "$l")"
done
echo "== micro:bit, reflection at $MB_SIZE, samples 2, streaming"
l=$(grep -h "^PASS firmware microbit .* reflection-s2 $MB_SIZE " "$out"/fw-*.txt)
echo "ram_static=$(get ram_static "$l") stack_used=$(get stack_used "$l") stack_size=$(get stack_size "$l")" \
    "instructions=$(get instructions "$l") instructions_per_pixel=$(get instructions_per_pixel "$l")"
report qemu_trace
