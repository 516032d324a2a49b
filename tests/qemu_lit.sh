#!/usr/bin/env bash
# Firmware in QEMU, lit scenes (issue 11): every scene of scenes/lit/ runs on
# all three boards at 160x120, byte-identical to the host's Q16.16 render:
#   1. tests/onboard_main.c, one ELF per board holding every lit scene (the
#      world, materials, ambient and lights set up at run time through
#      core/fxrt.h as firmware/main.c does), frames streamed row by row;
#      on the micro:bit this is every lit scene in its 16 KB of RAM (a batch
#      that does not fit is halved until the halves fit: onb_fit, in
#      tests/onboard_lib.sh; a single scene must fit). make test runs the
#      batches on the M3 and the micro:bit: the M4F's q16 code is the M3's
#      Thumb-2 integer code (it runs in part 2 here and in tests/qemu.sh's
#      seed batch); make test-full runs its batch too;
#   2. the firmware itself (firmware/main.c, make qemu) in full-frame and
#      streaming modes (make test: the M3 full, the M4F streaming, the
#      micro:bit both; make test-full: both on every board), a different
#      lit scene per run; the micro:bit's full frame is 48x36 (160x120
#      needs 57 KB of frame).
# Stack use (stack_used= of the firmware and of the on-board batches) is
# printed per board and must stay below the board's stack.
set -u
. "$(dirname "$0")/lib.sh"
out=$BUILD/tests/qemu_lit
onb=$out/onboard
BOARDS="mps2-an385 mps2-an386 microbit"
ONB_BOARDS="mps2-an385 microbit"
full && ONB_BOARDS=$BOARDS
SIZE=160x120
# -o: fxrt-scenec was built by make test; parallel sub-makes must not relink it.
M="make -s --no-print-directory BUILD=$BUILD -o $BUILD/fxrt-scenec"
rm -rf "$out"
mkdir -p "$onb/scenes" "$onb/host"
. "$(dirname "$0")/onboard_lib.sh"
ONB_WHAT="qemu_lit.sh: lit scenes on board"

# (and five node scenes: three of models, their data in flash and a ray
# per pixel through each one's tree on the board, an ellipsoid and a
# parallelepiped; nodes are placed on the host; at 80x60, the icospheres
# at 40x30, for make test's time)
scenes=(scenes/lit/*.scene scenes/nodes/smooth.scene scenes/nodes/smooth-ico80.scene scenes/nodes/course-u5-ellipsoid.scene scenes/nodes/course-u5-box.scene scenes/nodes/glass-ico80.scene)
check "scenes/lit/ has lit scenes (${#scenes[@]})" test -e "${scenes[0]}"
[ -e "${scenes[0]}" ] || { report qemu_lit; exit; }

# Host q16 frames and the scenes compiled for the on-board program.
names=()
for scene in "${scenes[@]}"; do
    name=$(basename "$scene" .scene)
    mkdir -p "$onb/scenes/$name"
    sz=$SIZE
    # (a quarter of the pixels for make test's time; the two icospheres,
    # a ray per pixel through 80 triangles, a sixteenth: 48x36 at least
    # in make test-full)
    case $scene in scenes/nodes/*-ico80.scene) sz=40x30; full && sz=48x36 ;; scenes/nodes/*) sz=80x60 ;; esac
    if "$BUILD/fxrt-scenec" "$scene" --number q16 --size $sz --out "$onb/scenes/$name" 2>"$out/scenec.log" &&
        "$FXRT" render "$scene" --number q16 --size $sz -o "$onb/host/$name.ppm" 2>>"$out/scenec.log"; then
        names+=("$name")
    else
        bad "$scene: fxrt-scenec or host render failed: $(cat "$out/scenec.log")"
    fi
done

# 2. firmware/main.c: "BOARD FB SIZE" per run, scenes taken in turn.
# (make test: each board and each frame mode once; make test-full: both
# modes on every board)
fw_runs=("mps2-an385 full $SIZE" "mps2-an386 stream $SIZE" "microbit stream $SIZE" "microbit full 48x36")
full && fw_runs+=("mps2-an385 stream $SIZE" "mps2-an386 full $SIZE")
fw_run() { # I BOARD FB SIZE: build, run, compare; verdict lines in $out/fw-I.txt
    local i=$1 b=$2 fb=$3 size=$4 scene name log ppm
    scene=${scenes[$((i % ${#scenes[@]}))]}
    name=$(basename "$scene" .scene)
    log=$out/fw-$i.log
    progress "qemu_lit.sh: firmware $b FB=$fb $name $size"
    ppm=$BUILD/qemu/$b/$name-q16-$size-lit$fb.ppm
    rm -f "$ppm"
    if ! $M qemu SCENE="$scene" BOARD=$b NUMBER=q16 SIZE=$size FB=$fb FW_TAG=lit$fb >"$log" 2>&1; then
        echo "FAIL firmware $b FB=$fb $name $size: make qemu failed: $(tail -n 3 "$log" | tr '\n' ' ')"
        return
    fi
    "$FXRT" render "$scene" --number q16 --size $size -o "$out/fw-$i-host.ppm"
    local line used size_
    line=$(grep '^board=' "$log" | tail -n 1)
    used=$(sed -nE 's/.*stack_used=([0-9]+).*/\1/p' <<<"$line")
    size_=$(sed -nE 's/.*stack_size=([0-9]+).*/\1/p' <<<"$line")
    if ! cmp -s "$out/fw-$i-host.ppm" "$ppm"; then
        echo "FAIL firmware $b FB=$fb $name $size: frame differs from the host q16 render"
    elif [ -z "$used" ] || [ -z "$size_" ] || [ "$used" -ge "$size_" ]; then
        echo "FAIL firmware $b FB=$fb $name $size: stack_used=$used of stack_size=$size_"
    else
        echo "PASS firmware $b FB=$fb $name $size $line"
    fi
}

# 1. on-board batches. The three batches and the six firmware runs go two
# at a time (two cores): each job is a build of a few seconds and a short run.
# On the micro:bit the smooth scenes run in a batch of their own: smooth
# shading grows every triangle record of the batch it is in; the others do
# not fit one ELF either, and start as two halves (onb_fit_halves).
onb_board() { # BOARD: the lit scenes in as few ELFs as fit (onb_fit)
    local b=$1 n lit_names=() node_names=()
    for n in "${names[@]}"; do
        if [[ $n == smooth* ]] && [ "$b" = microbit ]; then node_names+=("$n"); else lit_names+=("$n"); fi
    done
    : >"$out/onb-$b.txt"
    [ ${#node_names[@]} -eq 0 ] || onb_fit "$b" nodes "${node_names[@]}" >>"$out/onb-$b.txt"
    if [ "$b" = microbit ]; then
        onb_fit_halves "$b" all "${lit_names[@]}" >>"$out/onb-$b.txt"
    else
        onb_fit "$b" all "${lit_names[@]}" >>"$out/onb-$b.txt"
    fi
}
jobs_=()
for b in $ONB_BOARDS; do jobs_+=("onb $b"); done
for i in "${!fw_runs[@]}"; do jobs_+=("fw $i ${fw_runs[$i]}"); done
for k in "${!jobs_[@]}"; do
    set -- ${jobs_[$k]}
    if [ "$1" = onb ]; then onb_board "$2" & else fw_run "$2" "$3" "$4" "$5" >"$out/fw-$2.txt" & fi
    [ $((k % 2)) -eq 1 ] && wait
done
wait

for b in $ONB_BOARDS; do
    echo "== on-board batch, $b: ${#names[@]} lit scenes at $SIZE (streamed rows)"
    cat "$out/onb-$b.txt"
    np=$(grep -c "^PASS $b " "$out/onb-$b.txt")
    check "$b: every lit scene ran on board byte-identical to the host q16 render ($np of ${#scenes[@]})" \
        test "$np" -eq "${#scenes[@]}"
    grep -E "^FAIL" "$out/onb-$b.txt" | while read -r l; do echo "  $l"; done
done
echo "== firmware (firmware/main.c, make qemu)"
for i in "${!fw_runs[@]}"; do
    v=$(cat "$out/fw-$i.txt" 2>/dev/null)
    echo "$v"
    case $v in PASS*) ok ;; *) bad "${v:-firmware run $i (${fw_runs[$i]}): no verdict}" ;; esac
done
echo "== stack use (bytes)"
for b in $BOARDS; do
    echo "$b: on-board batch $(grep -hos 'stack_used=[0-9]*' "$out/onb-$b.txt" | sort -t= -k2 -n | tail -n 1);" \
        "firmware $(grep -h "^PASS firmware $b " "$out"/fw-*.txt | sed -nE 's/.*FB=([a-z]+).* stack_used=([0-9]+) stack_size=([0-9]+).*/FB=\1 stack_used=\2 of \3;/p' | tr '\n' ' ')"
done
report qemu_lit
