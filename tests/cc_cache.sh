#!/usr/bin/env bash
# The firmware object cache (firmware/cc-cache.sh, FW_CACHE=1): an object
# served from the cache is byte-identical to a fresh compile; a different
# preprocessor input (a -D flag, an -include file's content) or a
# different code-generation flag (-O1, another CPU) misses; the
# dependency file names this build's own headers; -g is not cached.
set -u
. "$(dirname "$0")/lib.sh"
out=$BUILD/tests/cc_cache
rm -rf "$out"
mkdir -p "$out/cache" "$out/a" "$out/b"
CC=arm-none-eabi-gcc
if ! command -v $CC >/dev/null; then
    bad "$CC not installed (run make deps)"
    report cc_cache
    exit
fi
base=(-std=c11 -Wall -Wextra -Werror -O2 -mcpu=cortex-m3 -mthumb -ffreestanding -ffunction-sections
    -fdata-sections -fstack-usage -Icore)
printf '#define FXRT_MAX_SPHERES 2\n' >"$out/a/cfg.h"
printf '#define FXRT_MAX_SPHERES 2\n' >"$out/b/cfg.h"
# cached DIR OBJ ARGS...: compile core/geom.c through the cache
cached() {
    local dir=$1 obj=$2
    shift 2
    firmware/cc-cache.sh "$out/cache" $CC "${base[@]}" -include "$dir/cfg.h" "$@" -MMD -MP -c core/geom.c -o "$obj"
}
nobj() { find "$out/cache" -name '*.o' | wc -l; }

check "first compile through the cache" cached "$out/a" "$out/a/geom.o"
check "one object stored" test "$(nobj)" -eq 1
$CC "${base[@]}" -include "$out/a/cfg.h" -c core/geom.c -o "$out/fresh.o"
check "stored object equals a plain compile" cmp -s "$out/a/geom.o" "$out/fresh.o"
check "-fstack-usage file written" test -s "$out/a/geom.su"
check "dependency file names the build's own -include" grep -q "$out/a/cfg.h" "$out/a/geom.d"
# The same preprocessed source from another directory: a hit.
check "same input from another directory" cached "$out/b" "$out/b/geom.o"
check "a hit stores nothing new" test "$(nobj)" -eq 1
check "the hit's object equals the plain compile" cmp -s "$out/b/geom.o" "$out/fresh.o"
check "the hit's -fstack-usage file equals the first" cmp -s "$out/b/geom.su" "$out/a/geom.su"
check "the hit's dependency file names its own -include" grep -q "$out/b/cfg.h" "$out/b/geom.d"
# Misses: another capacity in the -include file, a -D flag (float), -O1,
# another CPU.
printf '#define FXRT_MAX_SPHERES 0\n' >"$out/b/cfg.h" # no sphere code
check "changed -include content compiles" cached "$out/b" "$out/b/geom3.o"
check "changed -include content: a miss" test "$(nobj)" -eq 2
check "a -D flag compiles" cached "$out/a" "$out/a/geomd.o" -DFXRT_NUMBER=2
check "a -D flag: a miss" test "$(nobj)" -eq 3
check "-O1 compiles" cached "$out/a" "$out/a/geomo1.o" -O1
check "-O1: a miss" test "$(nobj)" -eq 4
$CC "${base[@]}" -include "$out/a/cfg.h" -O1 -c core/geom.c -o "$out/fresh-o1.o"
check "-O1 object equals a plain -O1 compile" cmp -s "$out/a/geomo1.o" "$out/fresh-o1.o"
check "-mcpu=cortex-m0 compiles" cached "$out/a" "$out/a/geomm0.o" -mcpu=cortex-m0
check "another CPU: a miss" test "$(nobj)" -eq 5
# -g: compiled, not cached.
check "-g compiles" cached "$out/a" "$out/a/geomg.o" -g
check "-g: nothing stored" test "$(nobj)" -eq 5
# A compile error fails, stores nothing and leaves no object.
printf 'syntax error\n' >"$out/a/cfg.h"
rm -f "$out/a/bad.o"
check "a compile error fails" bash -c "! firmware/cc-cache.sh '$out/cache' $CC ${base[*]} -include '$out/a/cfg.h' -c core/geom.c -o '$out/a/bad.o' 2>/dev/null"
check "a compile error: no object" test ! -e "$out/a/bad.o"
check "a compile error: nothing stored, no temporary left" test "$(nobj)" -eq 5 -a -z "$(ls -A "$out/cache" | grep tmp)"
report cc_cache
