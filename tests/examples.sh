#!/usr/bin/env bash
# examples/: the orbit example (flat, 16 frames) and the lit example
# (lights, a mirror and a glass sphere, depth 4, 2 x 2 adaptive samples)
# built with the public API run on the host and on the micro:bit in QEMU,
# every frame set up on the board, and the board's frames equal the host
# build's byte for byte. Also: a configuration mismatch between the core
# and the application fails at link time with the configuration in the
# message; a linker script without the stack's .stack_extra fails by name;
# the examples and docs/EMBEDDING.md's snippet use the fxrt_ names only.
set -u
. "$(dirname "$0")/lib.sh"
out=$BUILD/tests/examples
rm -rf "$out"
mkdir -p "$out"

# example NAME FRAMES: the host build writes NAME-00.ppm ...; the
# micro:bit build streams the same frames over semihosting (-icount as
# firmware/qemu-run.sh, whose tick conversion this reuses); every board
# frame must equal the host's byte for byte, and the board's stack use
# must leave FXRT_STACK_MARGIN of its reservation.
example() {
    local name=$1 frames=$2 f n a b elf log rc nf su ss sm ticks sz heap
    mkdir -p "$out/$name/host" "$out/$name/microbit"
    check "host $name runs" "$BUILD/examples/host/$name" "$out/$name/host"
    n=$(ls "$out/$name/host"/"$name"-*.ppm 2>/dev/null | wc -l)
    check "host $name wrote $frames frames (found $n)" test "$n" -eq "$frames"
    # The camera moves: consecutive frames differ.
    for f in $(seq 1 $((frames - 1))); do
        a=$(printf '%s/%s/host/%s-%02d.ppm' "$out" "$name" "$name" $((f - 1)))
        b=$(printf '%s/%s/host/%s-%02d.ppm' "$out" "$name" "$name" $f)
        check "$name: frames $((f - 1)) and $f differ" bash -c "! cmp -s '$a' '$b'"
    done
    elf=$BUILD/examples/microbit/$name.elf
    log=$out/$name/microbit/qemu.log
    (cd "$out/$name/microbit" && timeout "${FXRT_QEMU_TIMEOUT:-300}" qemu-system-arm -M microbit -nographic \
        -monitor none -serial none -semihosting-config enable=on,target=native -icount shift=5 \
        -kernel "$(realpath "$OLDPWD/$elf")" </dev/null) >"$log" 2>&1
    rc=$?
    check "micro:bit $name exits 0 (exit $rc: $(tail -n 2 "$log" | tr '\n' ' '))" test $rc -eq 0
    # instructions = ticks * 62.5 ns / 32 ns (16 MHz SysTick, -icount shift=5)
    awk -v name="$name" '/frame=/ { for (i = 1; i <= NF; i++) if ($i ~ /^frame_tick_count=/) { split($i, a, "="); t = a[2] }
                    printf "%s %s instructions=%.0f\n", name, $1, t * 62.5 / 32 }' "$log"
    tail -n 1 "$log"
    nf=$(grep -c 'frame_tick_count=' "$log")
    check "micro:bit $name reported $frames frames (got $nf)" test "$nf" -eq "$frames"
    for f in $(seq 0 $((frames - 1))); do
        a=$(printf '%s-%02d.ppm' "$name" $f)
        if [ $rc -eq 0 ] && [ -f "$out/$name/microbit/$a.part" ]; then
            mv "$out/$name/microbit/$a.part" "$out/$name/microbit/$a"
        fi
        check "micro:bit $a byte-identical to the host's" cmp -s "$out/$name/host/$a" "$out/$name/microbit/$a"
    done
    su=$(sed -nE 's/.* stack_used=([0-9]+).*/\1/p' "$log" | tail -n 1)
    ss=$(sed -nE 's/.* stack_size=([0-9]+).*/\1/p' "$log" | tail -n 1)
    sm=$(sed -nE 's/^#define FXRT_STACK_MARGIN ([0-9]+).*/\1/p' core/fxrt_config.h)
    check "micro:bit $name: stack used (${su:-?} B) + FXRT_STACK_MARGIN (${sm:-?} B) <= reserved (${ss:-?} B)" \
        test -n "$su" -a -n "$ss" -a -n "$sm" -a "$((${su:-0} + ${sm:-0}))" -le "${ss:-0}"
    ticks=$(sed -nE 's/^ticks=([0-9]+) .*/\1/p' "$log")
    if [ -n "$ticks" ]; then
        echo "micro:bit $name: instructions_per_frame=$(awk -v t="$ticks" -v f="$frames" 'BEGIN { printf "%.0f", t * 62.5 / 32 / f }')" \
            "$(sed -nE 's/^ticks=[0-9]+ //p' "$log")"
    fi
    sz=$(arm-none-eabi-size -A "$elf" | awk '$1 == ".text" || $1 == ".rodata" { f += $2 } $1 == ".data" { f += $2; r += $2 }
        $1 == ".bss" { r += $2 } END { printf "flash=%d ram_static=%d", f, r }')
    echo "micro:bit $name.elf: $sz"
    heap=$(arm-none-eabi-nm "$elf" | awk '{print $NF}' | grep -xE 'malloc|_malloc_r|_sbrk|_sbrk_r|free|_free_r' || true)
    check "$name.elf: no malloc/_sbrk (found: $heap)" test -z "$heap"
}
example orbit 16
example lit 2
# The lit example's bounce stack is the core's own reservation
# (FXRT_STACK_RESERVE), inside the stack: fxrt_stack_extra lies between
# _sstack and _estack.
stack_syms=$(arm-none-eabi-nm "$BUILD/examples/microbit/lit.elf" | awk '$3 == "_sstack" || $3 == "_estack" || $3 == "fxrt_stack_extra" { print $3 "=" $1 }')
sstack=$(sed -n 's/^_sstack=//p' <<<"$stack_syms") estack=$(sed -n 's/^_estack=//p' <<<"$stack_syms")
extra=$(sed -n 's/^fxrt_stack_extra=//p' <<<"$stack_syms")
check "lit.elf: fxrt_stack_extra (0x${extra:-?}) inside the stack (0x${sstack:-?}..0x${estack:-?})" \
    test -n "$extra" -a -n "$sstack" -a -n "$estack" -a $((16#${extra:-0})) -ge $((16#${sstack:-1})) -a $((16#${extra:-0})) -lt $((16#${estack:-0}))

# A firmware whose linker script does not keep the core's .stack_extra in
# the stack (its own script, written without docs/EMBEDDING.md's lines):
# the link fails and names what to add.
ls_dir=$out/nostack
mkdir -p "$ls_dir"
grep -v -e 'fxrt_stack_extra_needs_linker_script_keep' -e 'KEEP(\*(.stack_extra))' linker/sections.ld >"$ls_dir/sections.ld"
sed 's/^INCLUDE sections.ld/INCLUDE nostack-sections.ld/' linker/microbit.ld >"$ls_dir/board.ld"
mv "$ls_dir/sections.ld" "$ls_dir/nostack-sections.ld"
lit_objs=$(find "$BUILD/examples/obj/microbit-lit" -name '*.o' | while read -r o; do s=${o#"$BUILD/examples/obj/microbit-lit/"};
    case $s in core/*) [ -f "${s%.o}.c" ] && echo "$o" ;; fw/*) [ -f "firmware/${s#fw/}" ] || [ -f "firmware/$(basename "${s%.o}").c" ] && echo "$o" ;; *) echo "$o" ;; esac; done)
if arm-none-eabi-gcc -mcpu=cortex-m0 -mthumb -o "$ls_dir/lit.elf" $lit_objs -nostartfiles --specs=nano.specs \
    --specs=nosys.specs -Wl,--gc-sections -L"$ls_dir" -T"$ls_dir/board.ld" 2>"$ls_dir/link.log"; then
    bad "lit linked with a script that does not keep .stack_extra"
else
    ok
fi
check "the link error names fxrt_stack_extra_needs_linker_script_keep" \
    grep -q "undefined reference to .fxrt_stack_extra_needs_linker_script_keep" "$ls_dir/link.log"

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
core=$(find "$BUILD/examples/obj/host-orbit/core" -name '*.o' | while read -r o; do s=${o#"$BUILD/examples/obj/host-orbit/"}; [ -f "${s%.o}.c" ] && echo "$o"; done)
if $CC -o "$mm/orbit" "$mm/orbit.o" "$mm/io_host.o" $core 2>"$mm/link.log"; then
    bad "a core with 2 spheres and an application with 8 must not link"
else
    ok
fi
sed 's/^/  link: /' "$mm/link.log" | grep -m2 fxrt_capacity
check "the link error names the application's sphere capacity (fxrt_capacity_spheres_8)" \
    grep -q "fxrt_capacity_spheres_8" "$mm/link.log"
check "the core defines its own (fxrt_capacity_spheres_2, fxrt_config_n1_w64_px1_l8_d0_x1a0)" \
    bash -c "nm '$BUILD/examples/obj/host-orbit/core/frame/api.o' | grep -q ' R fxrt_capacity_spheres_2$' &&
             nm '$BUILD/examples/obj/host-orbit/core/frame/api.o' | grep -q ' R fxrt_config_n1_w64_px1_l8_d0_x1a0$'"
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

# A C++ program: tests/api_lang.c, in the common subset of C11 and C++11,
# compiled as C (cc) and as C++ (clang++, from the clang package), each
# linked against the orbit example's C core objects. Both must link (fxrt.h
# gives its declarations C linkage in C++), pass their own checks of the
# refused calls' codes, and write the same two lit frames byte for byte.
CXX=${CXX:-clang++}
for lang in c cxx; do
    if [ $lang = c ]; then comp=($CC -std=c11); else comp=($CXX -x c++ -std=c++11); fi
    check "tests/api_lang.c builds as $lang with -Wall -Wextra -Wpedantic -Werror against the C core" \
        "${comp[@]}" -Wall -Wextra -Wpedantic -Werror -O2 $ecfg -Icore -c tests/api_lang.c -o "$mm/api_lang_$lang.o"
    check "api_lang ($lang) links" "${comp[0]}" -o "$mm/api_lang_$lang" "$mm/api_lang_$lang.o" $core
    check "api_lang ($lang) runs and its checks pass" "$mm/api_lang_$lang" "$mm/api_lang_$lang.ppm"
done
check "api_lang: the C++ build's frames equal the C build's byte for byte" \
    cmp -s "$mm/api_lang_c.ppm" "$mm/api_lang_cxx.ppm"
check "api_lang: the frames are not blank (more than 100 distinct byte values)" \
    test "$(tail -c +14 "$mm/api_lang_c.ppm" | od -An -v -tu1 | tr -s ' ' '\n' | sort -u | wc -l)" -gt 100

# One prefix: what the example and the snippet take from the core are
# fxrt_ and FXRT_ names only. A word of theirs (with an underscore or a
# capital, outside comments and strings) that a core header also has must
# carry the prefix, unless it is C's own (stdint.h, stddef.h, stdbool.h).
for f in examples/orbit.c "$mm/snippet.c" tests/api_lang.c; do
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
