#!/usr/bin/env bash
# The core is freestanding and allocation-free:
#  - it includes nothing but <stdint.h>, <stddef.h>, <stdbool.h> (checked in
#    the source, and by compiling with -nostdinc so that only the
#    compiler's own freestanding headers exist);
#  - the Q16.16 build compiled for Cortex-M0 and Cortex-M3 (every kind of
#    object compiled in, lib.sh's BARE_ALL_KINDS) references no
#    malloc/free, no stdio, and no soft-float helper (__aeabi_f*, __aeabi_d*).
set -u
. "$(dirname "$0")/lib.sh"
out=$BUILD/tests/freestanding
mkdir -p "$out"
# Every source file of the core, so that a new one is checked too.
CORE=$(cd core && ls */*.c | sed "s/\.c$//")

bad_includes=$(grep -hE '^\s*#\s*include\s*<' core/*.h core/*/*.c core/*/*.h | grep -vE '<(stdint|stddef|stdbool)\.h>' || true)
check "core includes only stdint/stddef/stdbool (found: $bad_includes)" test -z "$bad_includes"

if ! command -v arm-none-eabi-gcc >/dev/null; then
    bad "arm-none-eabi-gcc not installed (run make deps)"
    report freestanding
    exit 1
fi
inc=$(arm-none-eabi-gcc -print-file-name=include)
for cpu in cortex-m0 cortex-m3; do
    objs=()
    for f in $CORE; do
        o=$out/$cpu-${f//\//-}.o
        if arm-none-eabi-gcc -std=c11 -Wall -Wextra -Wpedantic -Wshadow -Wmissing-prototypes -Werror \
            -Os -mcpu=$cpu -mthumb -ffreestanding -nostdinc -isystem "$inc" -DFXRT_NUMBER=1 \
            "${BARE_ALL_KINDS[@]}" -Icore -c core/$f.c -o "$o"; then
            ok
            objs+=("$o")
        else
            bad "$cpu: core/$f.c does not compile freestanding"
        fi
    done
    arm-none-eabi-ld -r -o "$out/$cpu-core.o" "${objs[@]}"
    undef=$(arm-none-eabi-nm -u "$out/$cpu-core.o" | awk '$1 == "U" {print $2}' | sort -u)
    echo "$cpu undefined symbols:" $undef
    forbidden=$(grep -E '^(malloc|free|calloc|realloc|_sbrk|_malloc_r|printf|puts|putchar|__aeabi_[fd].*|__.*sf[0-9]|__.*df[0-9])$' <<<"$undef" || true)
    check "$cpu: no malloc/stdio/soft-float references (found: $forbidden)" test -z "$forbidden"
    check "$cpu: the mesh walk is compiled in (bvh_nearest defined)" \
        bash -c "arm-none-eabi-nm '$out/$cpu-core.o' | grep -q ' T bvh_nearest$'"
    # The core keeps no RAM of its own but its stack reservation
    # (frame/api.c) and the test counters: every other byte is the
    # caller's fxrt_t. firmware/fit.sh's probes rely on it (they compile
    # main.c and api.c again, not the rest).
    ram=$(arm-none-eabi-nm "$out/$cpu-core.o" | awk '$2 ~ /^[BbDdCcGgSs]$/ { print $3 }' | sort | tr '\n' ' ')
    check "$cpu: the core's only RAM is fxrt_stack_extra and fxrt_stats (found: $ram)" \
        test "$ram" = "fxrt_stack_extra fxrt_stats "
    # And the check itself must be able to fail: a float build does pull
    # soft-float helpers in on these cores.
    arm-none-eabi-gcc -std=c11 -Os -mcpu=$cpu -mthumb -ffreestanding -DFXRT_NUMBER=2 -Icore -c core/scene/geom.c -o "$out/$cpu-float-geom.o"
    check "$cpu: the nm check sees soft-float in a float build" \
        bash -c "arm-none-eabi-nm -u '$out/$cpu-float-geom.o' | grep -q __aeabi_f"
done
report freestanding
