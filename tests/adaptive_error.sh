#!/usr/bin/env bash
# Adaptive supersampling against full N x N (docs/ACCURACY.md
# "Supersampling"): each scene at 320x240 with `samples 4` and with
# `samples 4 adaptive`, in double and Q16.16; prints the share of pixels
# that adaptive refines (the pixels near a key discontinuity: compare's
# near_pixels) and the adaptive image's error against the full one of the
# same build. Not part of make test: `make adaptive-error`.
set -eu
FXRT=${FXRT:-build/fxrt}
out=${BUILD:-build}/adaptive-error
mkdir -p "$out"
printf '| scene | build | refined %% | mismatched %% | beyond 1/255 %% | max | PSNR dB |\n'
printf '|---|---|---:|---:|---:|---:|---:|\n'
for scene in "${@:-scenes/trace/reflection.scene scenes/trace/glass.scene scenes/trace/supersample.scene scenes/lit/room.scene}"; do
    for sc in $scene; do
        name=$(basename "$sc" .scene)
        sed '/^samples /d' "$sc" >"$out/$name-full.scene"
        cp "$out/$name-full.scene" "$out/$name-adaptive.scene"
        echo "samples 4" >>"$out/$name-full.scene"
        echo "samples 4 adaptive" >>"$out/$name-adaptive.scene"
        for n in double q16; do
            for v in full adaptive; do
                "$FXRT" render "$out/$name-$v.scene" --size 320x240 --number $n -o "$out/$name-$v-$n.ppm" &
            done
        done
        wait
        for n in double q16; do
            line=$("$FXRT" compare "$out/$name-full-$n.ppm" "$out/$name-adaptive-$n.ppm" --scene "$out/$name-full.scene")
            get() { tr ' ' '\n' <<<"$line" | sed -n "s/^$1=//p"; }
            refined=$(awk -v a="$(get near_pixels)" -v p="$(get pixels)" 'BEGIN { printf "%.2f", 100 * a / p }')
            beyond=$(awk -v w="$(get within1_pct)" 'BEGIN { printf "%.4f", 100 - w }')
            printf '| %s | %s | %s | %s | %s | %s | %s |\n' "$name" "$n" "$refined" "$(get mismatched_pct)" "$beyond" \
                "$(get max_err)" "$(get psnr)"
        done
    done
done
