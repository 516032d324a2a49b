#!/usr/bin/env bash
# The CMake package (CMakeLists.txt, cmake/arm-none-eabi.cmake): a user's
# project (examples/cmake/: add_subdirectory, the configuration as cache
# values, target_link_libraries) configures and builds the lit example
# for the host and, with the toolchain file, for the Cortex-M3
# (mps2-an385); both run (the M3 in QEMU), and their frames equal the
# Makefile's host build of the same example byte for byte. On the host
# the project also builds tests/api_lang.c as C and as C++ (a C++
# application on the same C library): both run, equal frames. Also: a
# configuration value that is not a plain integer is refused at configure
# time, with its name.
set -u
. "$(dirname "$0")/lib.sh"
out=$BUILD/tests/cmake
rm -rf "$out"
mkdir -p "$out"
ref=$out/make-frames   # the Makefile's host build of the example
mkdir -p "$ref"
check "the Makefile's host lit runs" "$BUILD/examples/host/lit" "$ref"

# build NAME ARGS...: configure examples/cmake into $out/NAME and build it.
build() {
    local name=$1
    shift
    check "cmake configures $name" cmake -S examples/cmake -B "$out/$name" -DCMAKE_BUILD_TYPE=Release "$@" \
        >"$out/$name.configure.log" 2>&1
    check "cmake builds $name" cmake --build "$out/$name" -j "${TEST_JOBS:-2}" >"$out/$name.build.log" 2>&1
}

build host
mkdir -p "$out/host-frames"
check "host lit (CMake) runs" "$out/host/lit" "$out/host-frames"
for f in lit-00 lit-01; do
    check "host $f.ppm (CMake) equals the Makefile build's" cmp -s "$out/host-frames/$f.ppm" "$ref/$f.ppm"
done

# A C++ consumer of the same library: tests/api_lang.c built as C and as
# C++ by the project; both pass their checks and write the same frames.
for lang in c cxx; do
    check "api_lang_$lang (CMake) runs and its checks pass" "$out/host/api_lang_$lang" "$out/api_lang_$lang.ppm"
done
check "api_lang (CMake): the C++ build's frames equal the C build's" \
    cmp -s "$out/api_lang_c.ppm" "$out/api_lang_cxx.ppm"
check "api_lang (CMake): the C++ build is C++ (its object compiled by a C++ compiler)" \
    grep -q 'Building CXX object .*api_lang.cpp' "$out/host.build.log"

build m3 -DCMAKE_TOOLCHAIN_FILE="$PWD/cmake/arm-none-eabi.cmake"
check "the M3 build is an Arm ELF" bash -c "arm-none-eabi-readelf -h '$out/m3/lit.elf' | grep -q 'Machine:.*ARM'"
heap=$(arm-none-eabi-nm "$out/m3/lit.elf" 2>/dev/null | awk '{print $NF}' | grep -xE 'malloc|_malloc_r|_sbrk|_sbrk_r' || true)
check "the M3 build links no allocator (found: ${heap:-none})" test -z "$heap"
mkdir -p "$out/m3-frames"
(cd "$out/m3-frames" && timeout "${FXRT_QEMU_TIMEOUT:-300}" qemu-system-arm -M mps2-an385 -nographic -monitor none \
    -serial none -semihosting-config enable=on,target=native -icount shift=5 \
    -kernel "$(realpath "$OLDPWD/$out/m3/lit.elf")" </dev/null) >"$out/m3-qemu.log" 2>&1
rc=$?
check "M3 lit (CMake) exits 0 in QEMU (exit $rc)" test $rc -eq 0
for f in lit-00 lit-01; do
    [ -f "$out/m3-frames/$f.ppm.part" ] && mv "$out/m3-frames/$f.ppm.part" "$out/m3-frames/$f.ppm"
    check "M3 $f.ppm (CMake, QEMU) equals the host's" cmp -s "$out/m3-frames/$f.ppm" "$ref/$f.ppm"
done
grep -E '^ticks=' "$out/m3-qemu.log" | sed 's/^/  M3: /'

# A bad configuration value: refused when configuring, by name.
if cmake -S examples/cmake -B "$out/bad" -DFXRT_MAX_SPHERES="(8)" >"$out/bad.log" 2>&1; then
    bad "cmake accepted FXRT_MAX_SPHERES=(8)"
else
    check "cmake names the bad value" grep -q "FXRT_MAX_SPHERES=(8): must be a plain decimal integer" "$out/bad.log"
fi
report cmake
