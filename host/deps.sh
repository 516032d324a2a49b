#!/usr/bin/env bash
# Install the Debian packages fxrt needs, if any are missing. Idempotent:
# when everything is installed it only asks dpkg and exits (well under a
# second). Usage: host/deps.sh   (make deps, make test and make demo run it)
set -euo pipefail

packages=(
    gcc make libpng-dev           # host build
    gcc-arm-none-eabi libnewlib-arm-none-eabi binutils-arm-none-eabi  # firmware
    qemu-system-arm               # runs the firmware
    gnuplot-nox                   # benchmark plots
    clang libclang-rt-14-dev      # sanitizers and libFuzzer
    valgrind                      # make bench-host (callgrind)
    cmake g++                     # the CMake package's test (tests/cmake.sh; its C++ consumer)
)

missing=()
for p in "${packages[@]}"; do
    status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
    [[ $status == "install ok installed" ]] || missing+=("$p")
done

if [[ ${#missing[@]} -eq 0 ]]; then
    exit 0
fi

echo "deps: missing Debian packages: ${missing[*]}"
if [[ $(id -u) -ne 0 ]]; then
    echo "deps: not running as root; install them with:" >&2
    echo "  sudo apt-get update && sudo apt-get install -y ${missing[*]}" >&2
    exit 1
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update -q
apt-get install -y -q --no-install-recommends "${missing[@]}"
echo "deps: installed ${missing[*]}"
