#!/usr/bin/env bash
# examples/ (issue 10, section 4): the orbit example built with the public
# API runs on the host and on the micro:bit in QEMU, every frame set up on
# the board, and the board's 16 frames equal the host build's byte for
# byte. Also: a configuration mismatch between the core and the
# application fails at link time with the configuration in the message.
set -u
. "$(dirname "$0")/lib.sh"
out=$BUILD/tests/examples
rm -rf "$out"
mkdir -p "$out/host" "$out/microbit"
FRAMES=16

# Host build: writes orbit-00.ppm ... orbit-15.ppm.
check "host orbit runs" "$BUILD/examples/host/orbit" "$out/host"
n=$(ls "$out/host"/orbit-*.ppm 2>/dev/null | wc -l)
check "host orbit wrote $FRAMES frames (found $n)" test "$n" -eq $FRAMES
# The camera moves: consecutive frames differ, and no frame is blank.
for f in $(seq 1 $((FRAMES - 1))); do
    a=$(printf '%s/host/orbit-%02d.ppm' "$out" $((f - 1)))
    b=$(printf '%s/host/orbit-%02d.ppm' "$out" $f)
    check "frames $((f - 1)) and $f differ" bash -c "! cmp -s '$a' '$b'"
done

# The micro:bit: same program, streamed over semihosting (-icount as
# firmware/qemu-run.sh, whose tick conversion this reuses).
elf=$BUILD/examples/microbit/orbit.elf
log=$out/microbit/qemu.log
(cd "$out/microbit" && timeout "${FXRT_QEMU_TIMEOUT:-300}" qemu-system-arm -M microbit -nographic -monitor none \
    -serial none -semihosting-config enable=on,target=native -icount shift=5 -kernel "$(realpath "$OLDPWD/$elf")" \
    </dev/null) >"$log" 2>&1
rc=$?
check "micro:bit orbit exits 0 (exit $rc: $(tail -n 2 "$log" | tr '\n' ' '))" test $rc -eq 0
# instructions = ticks * 62.5 ns / 32 ns (16 MHz SysTick, -icount shift=5)
awk '/frame=/ { for (i = 1; i <= NF; i++) if ($i ~ /^frame_tick_count=/) { split($i, a, "="); t = a[2] }
                printf "%s instructions=%.0f\n", $1, t * 62.5 / 32 }' "$log"
tail -n 1 "$log"
nf=$(grep -c 'frame_tick_count=' "$log")
check "micro:bit reported $FRAMES frames (got $nf)" test "$nf" -eq $FRAMES
for f in $(seq 0 $((FRAMES - 1))); do
    name=$(printf 'orbit-%02d.ppm' $f)
    if [ $rc -eq 0 ] && [ -f "$out/microbit/$name.part" ]; then
        mv "$out/microbit/$name.part" "$out/microbit/$name"
    fi
    check "micro:bit $name byte-identical to the host's" cmp -s "$out/host/$name" "$out/microbit/$name"
done
# The micro:bit's stack reservation is sized from measured use with
# FXRT_STACK_MARGIN to spare (docs/BENCHMARKS.md, "RAM"): the example too.
su=$(sed -nE 's/.* stack_used=([0-9]+).*/\1/p' "$log" | tail -n 1)
ss=$(sed -nE 's/.* stack_size=([0-9]+).*/\1/p' "$log" | tail -n 1)
sm=$(sed -nE 's/^#define FXRT_STACK_MARGIN ([0-9]+).*/\1/p' core/fxrt_config.h)
check "micro:bit orbit: stack used (${su:-?} B) + FXRT_STACK_MARGIN (${sm:-?} B) <= reserved (${ss:-?} B)" \
    test -n "$su" -a -n "$ss" -a -n "$sm" -a "$((${su:-0} + ${sm:-0}))" -le "${ss:-0}"
ticks=$(sed -nE 's/^ticks=([0-9]+) .*/\1/p' "$log")
if [ -n "$ticks" ]; then
    echo "micro:bit orbit: instructions_per_frame=$(awk -v t="$ticks" -v f=$FRAMES 'BEGIN { printf "%.0f", t * 62.5 / 32 / f }')" \
        "$(sed -nE 's/^ticks=[0-9]+ //p' "$log")"
fi
sz=$(arm-none-eabi-size -A "$elf" | awk '$1 == ".text" || $1 == ".rodata" { f += $2 } $1 == ".data" { f += $2; r += $2 }
    $1 == ".bss" { r += $2 } END { printf "flash=%d ram_static=%d", f, r }')
echo "micro:bit orbit.elf: $sz"
heap=$(arm-none-eabi-nm "$elf" | awk '{print $NF}' | grep -xE 'malloc|_malloc_r|_sbrk|_sbrk_r|free|_free_r' || true)
check "orbit.elf: no malloc/_sbrk (found: $heap)" test -z "$heap"

# A configuration mismatch: the application compiled with 8 spheres, the
# core with the example's 2. The link must fail and name the configuration.
mm=$out/mismatch
mkdir -p "$mm"
CFG_APP="-DFXRT_NUMBER=1 -DFXRT_MAX_PLANES=1 -DFXRT_MAX_SPHERES=8 -DFXRT_MAX_TRIANGLES=1 -DFXRT_MAX_BOXES=1 -DFXRT_RENDER_MAX_WIDTH=64 -DFXRT_MAX_DEPTH=0 -DFXRT_MAX_SAMPLES=1"
CC=${CC:-gcc}
$CC -std=c11 -O2 $CFG_APP -Icore -c examples/orbit.c -o "$mm/orbit.o"
$CC -std=c11 -O2 -c examples/io_host.c -Icore -o "$mm/io_host.o"
# The objects of the core's current sources (a stale object of a removed
# source must not be linked).
core=$(find "$BUILD/examples/host/core" -name '*.o' | while read -r o; do s=${o#"$BUILD/examples/host/"}; [ -f "${s%.o}.c" ] && echo "$o"; done)
if $CC -o "$mm/orbit" "$mm/orbit.o" "$mm/io_host.o" $core 2>"$mm/link.log"; then
    bad "a core with 2 spheres and an application with 8 must not link"
else
    ok
fi
sed 's/^/  link: /' "$mm/link.log" | grep -m2 fxrt_capacity
check "the link error names the application's sphere capacity (fxrt_capacity_spheres_8)" \
    grep -q "fxrt_capacity_spheres_8" "$mm/link.log"
check "the core defines its own (fxrt_capacity_spheres_2, fxrt_config_n1_w64_px1_l8_d0_x1a0)" \
    bash -c "nm '$BUILD/examples/host/core/frame/api.o' | grep -q ' R fxrt_capacity_spheres_2$' &&
             nm '$BUILD/examples/host/core/frame/api.o' | grep -q ' R fxrt_config_n1_w64_px1_l8_d0_x1a0$'"
# And the matching build links (the check above is not a link that always fails).
$CC -std=c11 -O2 $(sed 's/SPHERES=8/SPHERES=2/' <<<"$CFG_APP") -Icore -c examples/orbit.c -o "$mm/orbit-ok.o"
check "the same files with matching macros link" $CC -o "$mm/orbit-ok" "$mm/orbit-ok.o" "$mm/io_host.o" $core

# docs/EMBEDDING.md's dozen-line example compiles, links against the
# example's core and renders its 16 frames (48 rows of 192 bytes each).
awk '/^```c$/ { on = 1; next } /^```$/ { if (on) exit } on' docs/EMBEDDING.md >"$mm/snippet.c"
cat >"$mm/snippet_main.c" <<'C'
#include <stdio.h>
#include "fxrt.h"
void orbit(void);
void send(const uint8_t *row, size_t len);
static size_t rows;
void send(const uint8_t *row, size_t len) { rows += len == 192 && row; }
int main(void) { orbit(); printf("rows=%zu\n", rows); return rows == 16 * 48 ? 0 : 1; }
C
check "docs/EMBEDDING.md snippet extracted ($(wc -l <"$mm/snippet.c") lines)" grep -q fxrt_render_row "$mm/snippet.c"
ecfg="-DFXRT_NUMBER=1 -DFXRT_MAX_PLANES=1 -DFXRT_MAX_SPHERES=2 -DFXRT_MAX_TRIANGLES=1 -DFXRT_MAX_BOXES=1 -DFXRT_RENDER_MAX_WIDTH=64 -DFXRT_MAX_DEPTH=0 -DFXRT_MAX_SAMPLES=1"
check "docs/EMBEDDING.md snippet builds with -Wall -Wextra -Wpedantic -Werror" \
    $CC -std=c11 -Wall -Wextra -Wpedantic -Werror -O2 $ecfg -Icore -o "$mm/snippet" \
    "$mm/snippet.c" "$mm/snippet_main.c" $core
check "docs/EMBEDDING.md snippet renders 16 frames of 48 rows" "$mm/snippet"

# One prefix: what the example and the snippet take from the core are
# fxrt_ and FXRT_ names only. A word of theirs (with an underscore or a
# capital, outside comments and strings) that a core header also has must
# carry the prefix, unless it is C's own (stdint.h, stddef.h, stdbool.h).
for f in examples/orbit.c "$mm/snippet.c"; do
    words=$(sed -E 's://.*$::; s/"([^"\\]|\\.)*"/""/g' "$f" | perl -0pe 's{/\*.*?\*/}{}gs' |
        grep -oE '\b[A-Za-z_][A-Za-z0-9_]*\b' | grep -E '[_A-Z]' | sort -u |
        grep -vxE '(fxrt|FXRT)_[A-Za-z0-9_]*|u?int(8|16|32|64)_t|size_t|bool|NULL|__attribute__|noinline' || true)
    leaks=""
    for w in $words; do
        grep -qrw --include='*.h' -- "$w" core && leaks="$leaks $w"
    done
    check "$f uses only fxrt_/FXRT_ names of the core (others:${leaks:- none})" test -z "$leaks"
done
report examples
