#!/usr/bin/env bash
# make bench-lit-profile: where a lit pixel's instructions and estimated
# cycles go, for the lit-speed targets that are missed (docs/BENCHMARKS.md,
# "Lit scenes"). For each configuration below, firmware/profile.sh (QEMU's
# execution log, every function's instructions and its cycles priced by
# firmware/cycles.awk) at LITPROF_SIZE, then:
#   - the layers: the instructions and cycles of the functions of each core
#     folder (core/math, core/vis, ...; inlined code counts to the function
#     it was inlined into), of the firmware and of libgcc (no source file);
#   - the dearest functions (LITPROF_TOP).
# Writes build/bench/lit-profile.md; with BENCH_UPDATE_DOCS=1 also
# docs/bench/lit-profile.md.
#   LITPROF_SIZE  frame size (80x60: the log grows with the instructions)
#   LITPROF_TOP   functions per configuration (12)
#   BENCH_REV     the revision named in the header (git rev-parse HEAD)
set -euo pipefail
BUILD=${BUILD:-build}
SIZE=${LITPROF_SIZE:-80x60}
TOP=${LITPROF_TOP:-12}
OUT=$BUILD/bench
mkdir -p "$OUT"
unset MAKEFLAGS MFLAGS MAKELEVEL
# SCENE BOARD NUMBER FW_EXTRA ("-": none): the peer scene on each board
# with the build each target names, and the lit set's dearest scene.
CONFIGS=(
    "scenes/peer/matched.scene mps2-an385 q16 -"
    "scenes/peer/matched.scene microbit q16 -"
    "scenes/peer/matched.scene mps2-an386 float -DFXRT_FLOAT_STEP=1"
    "scenes/peer/matched.scene mps2-an386 q16 -"
    "scenes/lit/room.scene mps2-an385 q16 -"
    "scenes/lit/room.scene microbit q16 -"
)
px=$((${SIZE%x*} * ${SIZE#*x}))
rev=${BENCH_REV:-$(git rev-parse --short HEAD 2>/dev/null || echo unknown)}
md=$OUT/lit-profile.md
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
{
    echo "# Where a lit pixel goes: instructions and estimated cycles"
    echo
    echo "Regenerate with \`make bench-lit-profile BENCH_UPDATE_DOCS=1\`. Last run $(date -u '+%Y-%m-%d %H:%M UTC'), commit $rev;"
    echo "$(qemu-system-arm --version | head -n 1), arm-none-eabi-gcc $(arm-none-eabi-gcc -dumpversion)."
    echo "Each profile is one run at $SIZE under QEMU's execution log (\`firmware/profile.sh\`): the"
    echo "whole run (boot, set-up, frame, dump), per pixel = / $px, so a little above \`make bench\`'s"
    echo "figures at 160x120. Cycles are estimates (\`firmware/cycles.awk\`, docs/BENCHMARKS.md, \"Cycles\")."
    echo "Layers: the functions of each core folder; inlined code counts to the function it was inlined"
    echo "into; libgcc: the compiler's helpers (soft float, 64-bit division); newlib: the C library (memcpy)."
    echo
} >"$md"
for cfg in "${CONFIGS[@]}"; do
    read -r scene board number extra <<<"$cfg"
    [[ $extra == - ]] && extra=""
    echo "bench-lit-profile: $scene $board $number $extra" >&2
    PROFILE_TOP=100000 BUILD=$BUILD firmware/profile.sh "$scene" "$board" "$number" "$SIZE" "$extra" >"$tmp/p" ||
        { echo "bench-lit-profile: firmware/profile.sh failed for $cfg" >&2; exit 1; }
    name=$(basename "$scene" .scene)
    fb=full
    [[ $board == microbit ]] && fb=stream
    elf=$BUILD/fw/$board/$name-$number-$SIZE-$fb${extra:+-prof}/fxrt.elf
    # function -> layer, from the ELF's line table
    arm-none-eabi-nm -l --defined-only "$elf" | awk '$2 ~ /^[tTwW]$/ {
        f = $4; l = "libgcc"
        if (f ~ /\/libgcc\//) l = "libgcc"
        else if (f ~ /newlib/) l = "newlib"
        else if (f ~ /\/core\/[a-z]+\//) { l = f; sub(/.*\/core\//, "core/", l); sub(/\/[^\/]*$/, "", l) }
        else if (f ~ /\/core\//) l = "core"
        else if (f ~ /\/(firmware|tests)\//) l = "firmware"
        else if (f ~ /\/build\/fw\//) l = "firmware (scene data)"
        print $3, l }' >"$tmp/layers"
    {
        echo "## $name on $board ($number${extra:+, $extra})"
        echo
        echo "| layer | instructions per pixel | share | est. cycles per pixel | share | CPI |"
        echo "|---|---:|---:|---:|---:|---:|"
        awk -F'|' -v layers="$tmp/layers" -v px="$px" '
            BEGIN { while ((getline l < layers) > 0) { split(l, f, " "); L[f[1]] = f[2] } }
            $2 ~ /`/ { fn = $2; gsub(/[ `]/, "", fn); i = $3 + 0; c = $6 * px
                ly = (fn in L) ? L[fn] : "libgcc"; I[ly] += i; C[ly] += c; ti += i; tc += c }
            END { for (ly in I) printf "%s\t%.0f\t%.0f\n", ly, I[ly], C[ly]
                  printf "TOTAL\t%.0f\t%.0f\n", ti, tc }' "$tmp/p" >"$tmp/l"
        tot=$(awk -F'\t' '$1 == "TOTAL" { print $2, $3 }' "$tmp/l")
        grep -v '^TOTAL' "$tmp/l" | sort -t$'\t' -k2,2nr |
            awk -F'\t' -v px="$px" -v t="$tot" 'BEGIN { split(t, T, " ") }
                { printf "| %s | %.1f | %.1f %% | %.1f | %.1f %% | %.2f |\n", $1, $2 / px, 100 * $2 / T[1], $3 / px, 100 * $3 / T[2], $2 ? $3 / $2 : 0 }'
        awk -v px="$px" -v t="$tot" 'BEGIN { split(t, T, " "); printf "| all | %.1f | 100 %% | %.1f | 100 %% | %.2f |\n\n", T[1] / px, T[2] / px, T[1] ? T[2] / T[1] : 0 }'
        echo "The $TOP dearest functions:"
        echo
        awk -v n=$((TOP + 2)) '/^\| function/ { on = 1 } on && k < n { print; k++ }' "$tmp/p"
        echo
    } >>"$md"
done
if [[ ${BENCH_UPDATE_DOCS:-0} == 1 ]]; then
    mkdir -p docs/bench
    cp "$md" docs/bench/lit-profile.md
    echo "bench-lit-profile: updated docs/bench/lit-profile.md" >&2
fi
echo "bench-lit-profile: wrote $md" >&2
