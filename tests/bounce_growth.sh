#!/usr/bin/env bash
# How Q16.16's error grows with each bounce (docs/ACCURACY.md "Secondary
# rays"): scenes/stress/trace-mirrors.scene (two parallel mirrors,
# reflection 0.9) rendered at depth 0, 1, ..., 16 in Q16.16, float and
# double at its own size; each against the double render of the same depth.
# Prints one table row per depth: mismatched pixels, pixels beyond 1/255,
# max error, RMS error (from the PSNR) and PSNR. Not part of make test:
# `make bounce-growth` (about a minute).
set -eu
FXRT=${FXRT:-build/fxrt}
scene=${1:-scenes/stress/trace-mirrors.scene}
out=${BUILD:-build}/bounce-growth
mkdir -p "$out"
printf '| depth | build | mismatched %% | beyond 1/255 %% | max | RMS (1/255) | PSNR dB |\n'
printf '|---:|---|---:|---:|---:|---:|---:|\n'
for d in 0 1 2 3 4 6 8 12 16; do
    s=$out/depth$d.scene
    sed '/^depth /d' "$scene" >"$s"
    echo "depth $d" >>"$s"
    for n in double q16 float; do
        "$FXRT" render "$s" --number $n -o "$out/d$d-$n.ppm" &
    done
    wait
    for n in q16 float; do
        line=$("$FXRT" compare "$out/d$d-double.ppm" "$out/d$d-$n.ppm")
        get() { tr ' ' '\n' <<<"$line" | sed -n "s/^$1=//p"; }
        psnr=$(get psnr)
        rms=$(awk -v p="$psnr" 'BEGIN { if (p == "inf") print "0"; else printf "%.4f", 255 / exp(log(10) * p / 20) }')
        w1=$(get within1_pct)
        beyond=$(awk -v w="$w1" 'BEGIN { printf "%.4f", 100 - w }')
        printf '| %d | %s | %s | %s | %s | %s | %s |\n' "$d" "$n" "$(get mismatched_pct)" "$beyond" "$(get max_err)" \
            "$rms" "$psnr"
    done
done
