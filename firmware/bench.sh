#!/usr/bin/env bash
# make bench: run time against error. For every seed scene at BENCH_SIZE on
# every board, every number build and both renderers ("fast", the default
# build, and "reference", -DFXRT_RENDERER=2), run the firmware in
# QEMU (make qemu: instructions per frame and per pixel) and compare its
# frame with the host's double render (fxrt compare: mismatched %, PSNR,
# max error). Writes build/bench/bench.csv, bench.md (per-board summary,
# TARGETS with PASS/FAIL, per-scene table) and pareto-BOARD.png; with
# BENCH_UPDATE_DOCS=1 also docs/BENCHMARKS.md and docs/bench/.
#
#   firmware/bench.sh            the benchmark (make bench)
#   firmware/bench.sh --host     host tool under callgrind (make bench-host)
#
# Environment (all optional):
#   BUILD              build directory (build)
#   BENCH_SIZE         frame size (160x120)
#   BENCH_BOARDS       boards (all three)
#   BENCH_NUMBERS      number builds (q16 float double)
#   BENCH_RENDERERS    fast reference
#   BENCH_SCENES       scene files (scenes/abb*.scene)
#   BENCH_JOBS         parallel runs (nproc); QEMU -icount counts do not
#                      depend on it
#   BENCH_UPDATE_DOCS  1: regenerate docs/BENCHMARKS.md and docs/bench/
#   BENCH_BOARD_INFO   "board:cpu:fb ..." (bench.mk passes it from firmware.mk)
#   BENCH_REV          the revision named in the header (git rev-parse HEAD)
# Counts are QEMU -icount instruction counts (deterministic), not cycles.
set -euo pipefail
BUILD=${BUILD:-build}
FXRT=${FXRT:-$BUILD/fxrt}
SIZE=${BENCH_SIZE:-160x120}
BOARD_INFO=${BENCH_BOARD_INFO:-"mps2-an385:M3:full mps2-an386:M4F:full microbit:M0:stream"}
BOARDS=${BENCH_BOARDS:-$(for i in $BOARD_INFO; do printf '%s ' "${i%%:*}"; done)}
NUMBERS=${BENCH_NUMBERS:-q16 float double}
RENDERERS=${BENCH_RENDERERS:-fast reference}
SCENES=${BENCH_SCENES:-$(printf '%s\n' scenes/abb*.scene | sort -V)}
JOBS=${BENCH_JOBS:-$(nproc 2>/dev/null || echo 2)}
OUT=$BUILD/bench
REF_FLAGS="-DFXRT_RENDERER=2"
# The sub-makes are ours: no jobserver or command-line variables from a parent make.
unset MAKEFLAGS MFLAGS MAKELEVEL
# -o: the scene compiler was built before the runs; parallel sub-makes must
# not relink it (a source edited during the run would make them race).
M="make -s --no-print-directory BUILD=$BUILD -o $BUILD/fxrt-scenec"

die() { echo "bench: $*" >&2; exit 1; }
board_field() { # BOARD FIELD(2=cpu 3=fb)
    local i
    for i in $BOARD_INFO; do
        [[ ${i%%:*} == "$1" ]] && { cut -d: -f"$2" <<<"$i"; return; }
    done
    die "unknown board '$1' (BENCH_BOARD_INFO: $BOARD_INFO)"
}
short() { local n; n=$(basename "$1" .scene); echo "${n%%-*}"; }
get() { sed -nE "s/.*(^| )$1=([^ ]+).*/\2/p" <<<"$2"; }

# --- one unit: one (board, scene, number), both renderers in turn ----------
# (make qemu writes NAME-NUMBER-SIZE[-FW_TAG].ppm; the frame is copied away.)
if [[ ${1:-} == --unit ]]; then
    idx=$2 total=$3 board=$4 scene=$5 number=$6
    cpu=$(board_field "$board" 2) fb=$(board_field "$board" 3)
    name=$(basename "$scene" .scene)
    for r in $RENDERERS; do
        id=$(printf '%04d' "$idx")
        label="$(short "$scene") $cpu $number $r"
        echo "[$idx/$total] $label" >&2
        case $r in
            fast) extra=() tag="" ;;
            reference) extra=(FW_EXTRA="$REF_FLAGS" FW_TAG=ref) tag=-ref ;;
            *) echo "$label: unknown renderer '$r'" >"$OUT/runs/$id.err"; exit 1 ;;
        esac
        log=$OUT/runs/$id.log
        if ! $M qemu SCENE="$scene" BOARD="$board" NUMBER="$number" SIZE="$SIZE" FB="$fb" "${extra[@]}" >"$log" 2>&1; then
            { echo "$label: make qemu failed:"; sed 's/^/  | /' "$log"; } >"$OUT/runs/$id.err"
            exit 1
        fi
        line=$(grep '^board=' "$log" | tail -n 1 || true)
        ins=$(get instructions "$line") ipp=$(get instructions_per_pixel "$line") px=$(get pixels "$line")
        if [[ -z $ins || -z $ipp || $px != $((${SIZE%x*} * ${SIZE#*x})) ]]; then
            { echo "$label: no or bad 'board= instructions= ... pixels=' line from make qemu:"; sed 's/^/  | /' "$log"; } >"$OUT/runs/$id.err"
            exit 1
        fi
        frame=$OUT/frames/$board/$name-$number-$r.ppm
        mkdir -p "$(dirname "$frame")"
        cp "$BUILD/qemu/$board/$name-$number-$SIZE$tag.ppm" "$frame"
        if ! cmp=$("$FXRT" compare "$OUT/ref/$name-double.ppm" "$frame" 2>&1); then
            echo "$label: fxrt compare $OUT/ref/$name-double.ppm $frame failed: $cmp" >"$OUT/runs/$id.err"
            exit 1
        fi
        elf=$BUILD/fw/$board/$name-$number-$SIZE-$fb$tag/fxrt.elf
        if ! text=$(arm-none-eabi-size "$elf" 2>&1 | awk 'END { print $1 }') || [[ ! $text =~ ^[0-9]+$ ]]; then
            echo "$label: cannot read the text size of $elf" >"$OUT/runs/$id.err"
            exit 1
        fi
        echo "$name,$board,$cpu,$number,$r,$ins,$ipp,$(get mismatched_pct "$cmp"),$(get psnr "$cmp"),$(get max_err "$cmp"),$text" \
            >"$OUT/runs/$id.csv"
        idx=$((idx + 1))
    done
    exit 0
fi

# --- make bench-host: the host tool under callgrind --------------------------
# Instructions (callgrind Ir) inside engine_render_NUMBER: render_setup and the
# row loop, as the firmware counts them, plus the small per-frame world and
# camera build the firmware does ahead of time (scenec).
if [[ ${1:-} == --host ]]; then
    command -v valgrind >/dev/null ||
        die "valgrind is not installed (apt-get install valgrind); make bench-host needs it"
    [[ -x $FXRT ]] || die "$FXRT not built (make)"
    fn=${BENCH_HOST_FN:-engine_render_*}
    tmp=$(mktemp -d)
    trap 'rm -rf "$tmp"' EXIT
    px=$((${SIZE%x*} * ${SIZE#*x}))
    echo "Host tool ($FXRT, $(uname -m)) at $SIZE: valgrind --tool=callgrind instructions (Ir) inside $fn, per pixel."
    echo "A quick iteration aid only: host instructions, not the firmware figures (make bench)."
    [[ $(wc -w <<<"$RENDERERS") -eq 2 ]] && echo "ratio = ${RENDERERS##* } / ${RENDERERS%% *}."
    echo
    printf '%-24s %-7s' scene number
    for r in $RENDERERS; do printf ' %12s' "$r"; done
    [[ $(wc -w <<<"$RENDERERS") -eq 2 ]] && printf ' %12s' "ratio"
    echo
    for scene in $SCENES; do
        name=$(basename "$scene" .scene)
        for n in $NUMBERS; do
            printf '%-24s %-7s' "$name" "$n"
            vals=()
            for r in $RENDERERS; do
                if ! valgrind --tool=callgrind --callgrind-out-file=/dev/null "--toggle-collect=$fn" \
                        "$FXRT" render "$scene" --number "$n" --renderer "$r" --size "$SIZE" -o "$tmp/f.ppm" >"$tmp/log" 2>&1; then
                    echo; sed 's/^/  | /' "$tmp/log" >&2
                    die "$name $n $r: valgrind $FXRT render failed"
                fi
                ir=$(sed -nE 's/^==[0-9]+== Collected : ([0-9]+).*/\1/p' "$tmp/log" | tail -n 1)
                [[ -n $ir ]] || { echo; sed 's/^/  | /' "$tmp/log" >&2; die "$name $n $r: no 'Collected :' line from callgrind"; }
                [[ $ir -gt 0 ]] || { echo; die "$name $n $r: nothing collected in $fn (renamed? set BENCH_HOST_FN)"; }
                vals+=("$ir")
                printf ' %12.1f' "$(awk -v i="$ir" -v p="$px" 'BEGIN { print i / p }')"
            done
            [[ ${#vals[@]} -eq 2 ]] && printf ' %11.2fx' "$(awk -v a="${vals[1]}" -v b="${vals[0]}" 'BEGIN { print a / b }')"
            echo
        done
    done
    exit 0
fi

# --- make bench ----------------------------------------------------------------
start=$SECONDS
[[ -x $FXRT ]] || die "$FXRT not built (make)"
command -v gnuplot >/dev/null || die "gnuplot is not installed (make deps)"
rm -rf "$OUT/runs" "$OUT/frames"
mkdir -p "$OUT/runs" "$OUT/ref"

# Host double references, one per scene.
for scene in $SCENES; do
    name=$(basename "$scene" .scene)
    "$FXRT" render "$scene" --number double --size "$SIZE" -o "$OUT/ref/$name-double.ppm" ||
        die "$name: host double reference render failed"
done

# Units in board, scene, number order; each unit runs every renderer.
nr=$(wc -w <<<"$RENDERERS")
units=() idx=1
for b in $BOARDS; do
    board_field "$b" 2 >/dev/null
    for scene in $SCENES; do
        for n in $NUMBERS; do
            units+=("$idx $b $scene $n")
            idx=$((idx + nr))
        done
    done
done
total=$((idx - 1))
echo "bench: $total runs (${#units[@]} ELF pairs) at $SIZE, $JOBS in parallel" >&2
rc=0
printf '%s\n' "${units[@]}" |
    xargs -P "$JOBS" -L 1 sh -c 'exec "$0" --unit "$1" '"$total"' "$2" "$3" "$4"' "$0" || rc=$?
if compgen -G "$OUT/runs/*.err" >/dev/null || [[ $rc -ne 0 ]]; then
    echo >&2
    k=0
    for e in "$OUT"/runs/*.err; do
        [[ -e $e ]] || continue
        k=$((k + 1))
        if [[ $k -le 3 ]]; then # the first three in full (their last 25 lines)
            { echo "bench: FAILED: $(head -n 1 "$e")"; tail -n +2 "$e" | tail -n 25; echo; } >&2
        else
            echo "bench: FAILED: $(head -n 1 "$e")" >&2
        fi
    done
    nerr=$(find "$OUT/runs" -name '*.err' | wc -l)
    die "$([[ $nerr -gt 0 ]] && echo "$nerr run(s)" || echo "a run") failed (xargs status $rc); logs in $OUT/runs/"
fi
n_csv=$(find "$OUT/runs" -name '*.csv' | wc -l)
[[ $n_csv -eq $total ]] || die "expected $total results, found $n_csv in $OUT/runs/"
{
    echo "scene,board,cpu,number,renderer,instructions,instructions_per_pixel,mismatched_pct,psnr,max_err,text_bytes"
    cat "$OUT"/runs/*.csv
} >"$OUT/bench.csv"
elapsed=$((SECONDS - start))

# --- tables (markdown) and Pareto data -------------------------------------------
# Error "0 mismatched" is plotted at ZERO on the log axis (one differing pixel
# in one of six 160x120 scenes averages to 8.7e-4 %, well above it).
ZERO=1e-4
awk -F, -v out="$OUT" -v zero=$ZERO -v size="$SIZE" '
function add(list, v, key) { if (!((list, v) in seen)) { seen[list, v] = 1; order[list, ++cnt[list]] = v } }
function geo(b, n, r,   s, i, k, sum) { sum = 0; k = 0
    for (i = 1; i <= cnt["s"]; i++) { s = order["s", i]; if ((b, n, r, s) in ipp) { sum += log(ipp[b, n, r, s]); k++ } }
    return k ? exp(sum / k) : "" }
function geoins(b, n, r,   s, i, k, sum) { sum = 0; k = 0
    for (i = 1; i <= cnt["s"]; i++) { s = order["s", i]; if ((b, n, r, s) in ins) { sum += log(ins[b, n, r, s]); k++ } }
    return k ? exp(sum / k) : "" }
# Ratio num/den of instructions per scene: sets R_geo, R_min, R_max, R_n.
function ratio(bn, nn, rn, bd, nd, rd,   i, s, x, sum) { R_n = 0; sum = 0; R_min = ""; R_max = ""
    for (i = 1; i <= cnt["s"]; i++) { s = order["s", i]
        if (!((bn, nn, rn, s) in ins) || !((bd, nd, rd, s) in ins)) continue
        x = ins[bn, nn, rn, s] / ins[bd, nd, rd, s]; sum += log(x); R_n++
        if (R_min == "" || x < R_min) R_min = x; if (R_max == "" || x > R_max) R_max = x }
    R_geo = R_n ? exp(sum / R_n) : "" }
function verdict(m, goal, ge) {
    if (m == "") return "n/a (not measured)"
    if (ge) return m >= goal ? sprintf("**PASS**, %+.0f%%", (m / goal - 1) * 100) : sprintf("**FAIL**, needs %.2fx more", goal / m)
    return m <= goal ? sprintf("**PASS**, %.0f%% under", (1 - m / goal) * 100) : sprintf("**FAIL**, %.2fx over", m / goal) }
function rng(a, b, f) { return a == "" ? "" : sprintf(f " - " f, a, b) }
function fmt(x, f) { return x == "" ? "n/a" : sprintf(f, x) }
NR == 1 { next }
{ s = $1; b = $2; n = $4; r = $5
  add("s", s); add("b", b); add("n", n); add("r", r); cpu[b] = $3
  if (!(($3) in board_of)) board_of[$3] = b
  ins[b, n, r, s] = $6; ipp[b, n, r, s] = $7; mm[b, n, r, s] = $8; ps[b, n, r, s] = $9
  me[b, n, r, s] = $10; tx[b, n, r, s] = $11; row[++rows] = $0 }
END {
  md = out "/tables.md"
  # 1. per board
  print "## Per board: each build over the " cnt["s"] " scenes\n" > md
  print "Instructions per pixel: geometric mean over the scenes. Error against the host double render: mean mismatched % (share of pixels whose RGB differs), worst (lowest) PSNR, largest channel error. Text: flash bytes of the ELF (code and the const scene), smallest - largest.\n" > md
  for (i = 1; i <= cnt["b"]; i++) { b = order["b", i]
    printf "### %s (Cortex-%s)\n\n", b, cpu[b] > md
    print "| number | renderer | instr/pixel | instr/frame | mismatched % | worst PSNR dB | max_err | text bytes |" > md
    print "|---|---|---:|---:|---:|---:|---:|---:|" > md
    dat = out "/pareto-" b ".dat"; printf "" > dat
    for (j = 1; j <= cnt["n"]; j++) { n = order["n", j]
      for (k = 1; k <= cnt["r"]; k++) { r = order["r", k]
        g = geo(b, n, r); if (g == "") continue
        sm = 0; c = 0; wp = ""; mx = 0; tmin = ""; tmax = ""
        for (q = 1; q <= cnt["s"]; q++) { s = order["s", q]; if (!((b, n, r, s) in ins)) continue
          sm += mm[b, n, r, s]; c++; p = ps[b, n, r, s]; pv = (p == "inf") ? 1e9 : p + 0
          if (wp == "" || pv < wp) wp = pv; if (me[b, n, r, s] + 0 > mx) mx = me[b, n, r, s] + 0
          t = tx[b, n, r, s] + 0; if (tmin == "" || t < tmin) tmin = t; if (tmax == "" || t > tmax) tmax = t }
        mean = sm / c
        printf "| %s | %s | %.1f | %.0f | %.4f | %s | %d | %s |\n", n, r, g, geoins(b, n, r), mean,
          (wp == 1e9 ? "inf" : sprintf("%.2f", wp)), mx, (tmin == tmax ? tmin : tmin " - " tmax) > md
        printf "%s %s %.6g %.6g \"%s %s\"\n", n, r, g, (mean > 0 ? mean : zero), n, (r == "reference" ? "ref" : r) > dat
      } }
    print "" > md; close(dat) }

  # 2. targets
  print "## TARGETS\n" > md
  printf "Same run, same %d scenes at %s. Ratios are taken per scene (instructions per frame) and combined by geometric mean; the range is over the scenes. Targets 1, 2, 3 and 5 use the fast (default) renderer.\n\n", cnt["s"], size > md
  print "| # | target | measured | per scene | goal | result |" > md
  print "|---|---|---:|---:|---:|---|" > md
  m3 = ("M3" in board_of) ? board_of["M3"] : "not run"
  m0 = ("M0" in board_of) ? board_of["M0"] : "not run"
  m4 = ("M4F" in board_of) ? board_of["M4F"] : "not run"
  ratio(m3, "float", "fast", m3, "q16", "fast")
  printf "| 1 | q16 vs float, Cortex-M3 (%s): float / q16 instructions | %s | %s | >= 12x | %s |\n", m3, fmt(R_geo, "%.2fx"), rng(R_min, R_max, "%.2f"), verdict(R_geo, 12, 1) > md
  ratio(m0, "float", "fast", m0, "q16", "fast")
  printf "| 2 | q16 vs float, Cortex-M0 (%s): float / q16 instructions | %s | %s | >= 8x | %s |\n", m0, fmt(R_geo, "%.2fx"), rng(R_min, R_max, "%.2f"), verdict(R_geo, 8, 1) > md
  ratio(m4, "q16", "fast", m4, "float", "fast")
  printf "| 3 | q16 vs hard float, Cortex-M4F (%s): q16 / float instructions | %s | %s | <= 1.0x | %s |\n", m4, fmt(R_geo, "%.2fx"), rng(R_min, R_max, "%.2f"), verdict(R_geo, 1, 0) > md
  ratio(m3, "q16", "reference", m3, "q16", "fast")
  printf "| 4 | fast vs reference renderer, q16 on Cortex-M3 (%s): reference / fast instructions | %s | %s | >= 5x | %s |\n", m3, fmt(R_geo, "%.2fx"), rng(R_min, R_max, "%.2f"), verdict(R_geo, 5, 1) > md
  sm = 0; c = 0; mn = ""; mxv = ""
  for (q = 1; q <= cnt["s"]; q++) { s = order["s", q]; if (!((m3, "q16", "fast", s) in ipp)) continue
    v = ipp[m3, "q16", "fast", s]; sm += v; c++; if (mn == "" || v < mn) mn = v; if (mxv == "" || v > mxv) mxv = v }
  av = c ? sm / c : ""
  printf "| 5 | q16 on Cortex-M3 (%s): mean instructions per pixel | %s | %s | <= 40 | %s |\n\n", m3, fmt(av, "%.1f"), rng(mn, mxv, "%.1f"), verdict(av, 40, 0) > md
  print "Target 4 for every board and number build (the goal applies to q16 on Cortex-M3; the other rows are for information):\n" > md
  print "| board | number | reference / fast | per scene | >= 5x |" > md
  print "|---|---|---:|---:|---|" > md
  for (i = 1; i <= cnt["b"]; i++) { b = order["b", i]
    for (j = 1; j <= cnt["n"]; j++) { n = order["n", j]
      ratio(b, n, "reference", b, n, "fast"); if (R_geo == "") continue
      printf "| %s (%s) | %s | %.2fx | %s | %s |\n", b, cpu[b], n, R_geo, rng(R_min, R_max, "%.2f"), verdict(R_geo, 5, 1) > md } }
  print "" > md

  # 3. per scene
  print "## Per scene\n" > md
  print "| scene | board | number | renderer | instructions | instr/pixel | mismatched % | PSNR dB | max_err | text bytes |" > md
  print "|---|---|---|---|---:|---:|---:|---:|---:|---:|" > md
  for (i = 1; i <= rows; i++) { split(row[i], f, ",")
    printf "| %s | %s (%s) | %s | %s | %s | %s | %s | %s | %s | %s |\n", f[1], f[2], f[3], f[4], f[5], f[6], f[7], f[8], f[9], f[10], f[11] > md }
  close(md)
}' "$OUT/bench.csv"

# Pareto front per board: sort by x, keep points with a lower y than all faster ones.
for b in $BOARDS; do
    dat=$OUT/pareto-$b.dat
    sort -t' ' -k3,3g -k4,4g "$dat" | awk '{ y = $4 + 0 } NR == 1 || y < best { print; best = y }' >"$OUT/pareto-$b.front"
    cpu=$(board_field "$b" 2)
    gnuplot -e "data='$dat'; front='$OUT/pareto-$b.front'; out='$OUT/pareto-$b.png'; board='$b (Cortex-$cpu)'; size='$SIZE'; zero=$ZERO" \
        firmware/bench.gp || die "gnuplot failed for $b"
done

# bench.md and, with BENCH_UPDATE_DOCS=1, docs/.
if [[ -n ${BENCH_REV:-} ]]; then # e.g. when run in an exported tree
    rev=$BENCH_REV
else
    rev=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
    [[ -n $(git status --porcelain --untracked-files=no 2>/dev/null) ]] && rev="$rev (with uncommitted changes)"
fi
header() { # PLOTDIR
    echo "Regenerate with \`make bench BENCH_UPDATE_DOCS=1\`. Last run $(date -u '+%Y-%m-%d %H:%M UTC'), commit $rev;"
    echo "$(qemu-system-arm --version | head -n 1), arm-none-eabi-gcc $(arm-none-eabi-gcc -dumpversion);"
    echo "$total runs in ${elapsed} s. Counts are QEMU \`-icount\` instruction counts (deterministic), not cycles."
}
plots() { # DIR
    echo "## Run time against error (Pareto plots)"
    echo
    echo "x: instructions per pixel (geometric mean over the scenes, log scale); y: mean mismatched % against"
    echo "the host double render (log scale; 0 is drawn at $ZERO). The line joins the Pareto front: builds no other"
    echo "build beats on both axes."
    echo
    for b in $BOARDS; do echo "![$b]($1pareto-$b.png)"; done
    echo
}
{
    echo "# fxrt benchmarks ($SIZE)"
    echo
    header
    echo
    plots ""
    cat "$OUT/tables.md"
} >"$OUT/bench.md"

if [[ ${BENCH_UPDATE_DOCS:-0} == 1 ]]; then
    doc=docs/BENCHMARKS.md
    [[ -f $doc ]] || die "$doc is missing: it holds the hand-written template around the generated blocks"
    for m in header tables; do
        grep -q "^<!-- bench:$m -->" "$doc" && grep -q "^<!-- /bench:$m -->" "$doc" ||
            die "$doc lacks the <!-- bench:$m --> ... <!-- /bench:$m --> markers"
    done
    header >"$OUT/doc-header.md"
    { plots "bench/"; cat "$OUT/tables.md"; } >"$OUT/doc-tables.md"
    awk -v h="$OUT/doc-header.md" -v t="$OUT/doc-tables.md" '
        /^<!-- bench:header -->/ { print; while ((getline l < h) > 0) print l; skip = 1; next }
        /^<!-- bench:tables -->/ { print; while ((getline l < t) > 0) print l; skip = 1; next }
        /^<!-- \/bench:(header|tables) -->/ { skip = 0 }
        !skip' "$doc" >"$doc.tmp" && mv "$doc.tmp" "$doc"
    mkdir -p docs/bench
    rm -f docs/bench/pareto-*.png
    for b in $BOARDS; do cp "$OUT/pareto-$b.png" docs/bench/; done
    cp "$OUT/bench.csv" docs/bench/bench.csv
    echo "bench: updated $doc and docs/bench/" >&2
fi

echo
sed -n '/^## TARGETS/,/^Target 4 for every/p' "$OUT/tables.md" | sed '$d'
echo "bench: $total runs in ${elapsed} s; wrote $OUT/bench.csv, $OUT/bench.md, $OUT/pareto-*.png"
