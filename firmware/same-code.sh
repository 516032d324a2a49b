#!/usr/bin/env bash
# The firmware's machine code before and after a change that must not
# change it (a refactor), function by function: make same-code BASE=REV.
#
# REV is exported into build/same/REV/src (git archive). For each firmware
# configuration below, both trees build the ELF (make fw) and every
# function's disassembly is compared after normalisation (addresses,
# literal-pool words and the comments that hold addresses removed; branch
# and call targets kept by symbol name). A function whose code differs is
# listed with its instruction counts before and after. Function names can
# change in a refactor: SAME_RENAMES=FILE holds "OLD NEW" lines applied to
# the base's names first. With SAME_RUN=1 both ELFs also run in QEMU and
# their instruction counts (-icount) are compared: a configuration passes
# when they agree within SAME_TOLERANCE per cent (default 0.5), else when
# every function's code is the same.
#   BASE          the revision to compare with (required)
#   SAME_CONFIGS  "SCENE:BOARD:NUMBER[:FW_EXTRA]" words (default below)
#   SAME_VERBOSE  1: the differing functions' normalised diff
# Ends with "same-code: N passed, N failed" (N: configurations).
set -u
BUILD=${BUILD:-build}
. tests/lib.sh
base=${BASE:?usage: BASE=REV firmware/same-code.sh}
rev=$(git rev-parse --short "$base^{commit}") || { echo "same-code: unknown revision '$base'" >&2; exit 2; }
root=$BUILD/same/$rev
out=$BUILD/same/code
mkdir -p "$root" "$out"
if [ ! -x "$root/src/build/fxrt-scenec" ]; then
    rm -rf "$root/src"
    mkdir -p "$root/src"
    git archive "$rev" | tar -x -C "$root/src" || exit 2
    make -C "$root/src" -s --no-print-directory -j"$(nproc)" build/fxrt build/fxrt-scenec >"$root/build.log" 2>&1 ||
        { echo "same-code: building $rev's host tools failed ($root/build.log)" >&2; exit 2; }
fi
make -s --no-print-directory "$BUILD/fxrt" "$BUILD/fxrt-scenec" || exit 2

default_configs="scenes/bench/mixed16.scene:microbit:q16 scenes/bench/mixed16.scene:mps2-an385:q16
scenes/bench/room.scene:microbit:q16 scenes/bench/room.scene:mps2-an385:q16
scenes/bench/cover.scene:mps2-an385:q16 scenes/abb6-sphere.scene:microbit:q16
scenes/lit/room.scene:microbit:q16 scenes/lit/room.scene:mps2-an385:q16 scenes/lit/room.scene:mps2-an386:q16
scenes/lit/shadows.scene:microbit:q16 scenes/lit/coloured-lights.scene:mps2-an385:q16
scenes/trace/glass.scene:microbit:q16 scenes/trace/reflection.scene:mps2-an385:q16
scenes/samples/face.scene:mps2-an385:q16 scenes/lit/room.scene:mps2-an385:float:-DFXRT_FLOAT_STEP=1
scenes/bench/mixed16.scene:microbit:float:-DFXRT_FLOAT_STEP=1 scenes/lit/shadows.scene:mps2-an386:float:-DFXRT_FLOAT_STEP=1"
configs=${SAME_CONFIGS:-$default_configs}

# The normalised disassembly of ELF, one file per function under DIR.
norm() {
    rm -rf "$2"
    python3 firmware/same-code.py "$1" "$2" "${SAME_RENAMES:-}"
}

# A board variable of firmware/firmware.mk (FB_microbit, TICK_NS_...).
mkvar() { sed -nE "s/^$1[[:space:]]*:=[[:space:]]*(.*)/\1/p" firmware/firmware.mk; }

total_diff=0
for c in $configs; do
    IFS=: read -r scene board number extra <<<"$c"
    tag=same
    [ -n "$extra" ] && tag=same$(echo "$extra" | tr -c 'A-Za-z0-9\n' '_' | tr 'A-Z' 'a-z')
    name=$(basename "$scene" .scene)
    vars=(SCENE="$scene" BOARD="$board" NUMBER="$number" SIZE=160x120 FW_TAG="$tag" FW_EXTRA="$extra" FW_DEBUG=)
    if ! make -s --no-print-directory -C "$root/src" fw "${vars[@]}" >"$out/build-a.log" 2>&1; then
        bad "$c: the base does not build it ($out/build-a.log)"
        continue
    fi
    if ! make -s --no-print-directory fw "${vars[@]}" >"$out/build-b.log" 2>&1; then
        bad "$c: this tree does not build it ($out/build-b.log)"
        continue
    fi
    rel=fw/$board/$name-$number-160x120-$(mkvar FB_"$board")-$tag/fxrt.elf
    a=$root/src/build/$rel b=$BUILD/$rel
    [ -f "$a" ] && [ -f "$b" ] || { bad "$c: no ELF ($a, $b)"; continue; }
    norm "$a" "$out/a"
    norm "$b" "$out/b"
    nd=0 ni=0 summary=""
    for f in $( (ls "$out/a"; ls "$out/b") | sort -u); do
        if [ ! -f "$out/a/$f" ]; then
            summary+="    only after:  $f ($(wc -l <"$out/b/$f") instructions)"$'\n'
            nd=$((nd + 1))
        elif [ ! -f "$out/b/$f" ]; then
            summary+="    only before: $f ($(wc -l <"$out/a/$f") instructions)"$'\n'
            nd=$((nd + 1))
        elif ! cmp -s "$out/a/$f" "$out/b/$f"; then
            summary+="    differs:     $f ($(wc -l <"$out/a/$f") -> $(wc -l <"$out/b/$f") instructions)"$'\n'
            [ "${SAME_VERBOSE:-0}" = 1 ] && summary+=$(diff "$out/a/$f" "$out/b/$f" | head -n 40 | sed 's/^/      /')$'\n'
            nd=$((nd + 1))
        else
            ni=$((ni + 1))
        fi
    done
    ta=$(arm-none-eabi-size "$a" | awk 'END { print $1 }') tb=$(arm-none-eabi-size "$b" | awk 'END { print $1 }')
    runs=""
    if [ "${SAME_RUN:-0}" = 1 ]; then
        tick=$(mkvar TICK_NS_"$board") qm=$(mkvar QEMU_M_"$board")
        ia=$(BOARD=$board QEMU_M=$qm TICK_NS=$tick firmware/qemu-run.sh "$a" "$out/run" - 2>&1 | sed -nE 's/.* instructions=([0-9]+).*/\1/p')
        ib=$(BOARD=$board QEMU_M=$qm TICK_NS=$tick firmware/qemu-run.sh "$b" "$out/run" - 2>&1 | sed -nE 's/.* instructions=([0-9]+).*/\1/p')
        runs=", instructions $ia -> $ib ($(awk -v a="$ia" -v b="$ib" 'BEGIN { printf "%+.3f %%", a ? (b - a) * 100 / a : 0 }'))"
    fi
    echo "$c: $ni functions identical, $nd differ; text $ta -> $tb bytes$runs"
    printf '%s' "$summary"
    if [ "${SAME_RUN:-0}" = 1 ]; then
        # A refactor's bound: the frame's instruction count within
        # SAME_TOLERANCE per cent (0.5), whatever the functions' code.
        if awk -v a="$ia" -v b="$ib" -v t="${SAME_TOLERANCE:-0.5}" 'BEGIN { d = (b - a) * 100 / a; exit !(a > 0 && d <= t && d >= -t) }'; then
            ok
        else
            bad "$c: instructions $ia -> $ib, beyond ${SAME_TOLERANCE:-0.5} %"
        fi
    elif [ $nd -eq 0 ]; then
        ok
    else
        bad "$c: $nd functions differ"
    fi
done
report same-code
