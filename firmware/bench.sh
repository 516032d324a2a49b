#!/usr/bin/env bash
# make bench: run time against error, per scene set. For every scene of the
# seed set (scenes/abb*.scene), the bench set (scenes/bench/*.scene) and the
# lit set (scenes/lit/*.scene: lights, materials, shadows; issue 11) at
# BENCH_SIZE, on every board, for every build (a number type and a loop),
# run the firmware in QEMU (make qemu: instructions per frame and per pixel)
# and compare its frame with the host's double render (fxrt compare:
# mismatched %, PSNR, max error). The fast and step builds also get
# estimated cycles: the frame's cycles per instruction (CPI), priced by
# firmware/cycles.sh on the same build at BENCH_CYCLES_SIZE, times its
# instructions at BENCH_SIZE. The peer set (scenes/peer/: the scene the C
# port of tinyraytracer was measured on) holds issue 39's matched-scene
# targets. Summaries are per scene set, never mixed.
# Writes build/bench/bench.csv, bench.md (targets, best float builds, per
# board, float-step drift, per scene) and pareto-SET-BOARD.png; with
# BENCH_UPDATE_DOCS=1 also docs/BENCHMARKS.md and docs/bench/.
#
#   firmware/bench.sh            the benchmark (make bench)
#   firmware/bench.sh --host     host tool under callgrind (make bench-host)
#
# Builds (BENCH_BUILDS, "NUMBER:LOOP[@CPU,CPU...]", the @ list limits a
# build to some boards):
#   fast       the shipped scanline renderer (default firmware build)
#   step       the fast renderer with -DFXRT_FLOAT_STEP=1: float/double step
#              their forms by forward differences, restarted by a direct
#              evaluation at each row or span (the careful float programmer).
#              Reported "not available" when core/fxrt_config.h lacks it.
#   reference  -DFXRT_RENDERER=2: every object's forms at every pixel
#   raycast    -DFXRT_RENDERER=3: a camera ray and the nearest hit over all
#              objects per pixel (cam_ray + world_hit), the naive baseline
# A scene that does not fit a board (firmware/fit.sh) is reported as
# "does not fit" for that board, not as a failure.
#
# Environment (all optional):
#   BUILD              build directory (build)
#   BENCH_SIZE         frame size (160x120)
#   BENCH_BOARDS       boards (all three)
#   BENCH_BUILDS       builds (see above; default below)
#   BENCH_SETS         scene sets (seed bench lit nodes peer)
#   BENCH_CYCLES_SIZE  frame size of the cycle pricing (40x30; its CPI
#                      lies within about 1 % of BENCH_SIZE's, see
#                      docs/BENCHMARKS.md, "Cycles"); "none": no cycles
#   BENCH_SCENES       scene files instead of the sets' (each file's set is
#                      its directory: scenes/bench/ bench, scenes/lit/ lit,
#                      scenes/nodes/ nodes, scenes/peer/ peer, otherwise
#                      seed)
#   BENCH_JOBS         parallel runs (nproc); QEMU -icount counts do not
#                      depend on it
#   BENCH_UPDATE_DOCS  1: regenerate docs/BENCHMARKS.md and docs/bench/
#   BENCH_TABLES_ONLY  1: no runs; tables, plots (and docs) again from the
#                      last complete run's build/bench/bench.csv
#   BENCH_BOARD_INFO   "board:cpu:fb ..." (bench.mk passes it from firmware.mk)
#   BENCH_REV          the revision named in the header (git rev-parse HEAD)
# Counts are QEMU -icount instruction counts (deterministic); cycles are
# estimates (docs/BENCHMARKS.md, "Cycles").
set -euo pipefail
BUILD=${BUILD:-build}
FXRT=${FXRT:-$BUILD/fxrt}
SIZE=${BENCH_SIZE:-160x120}
BOARD_INFO=${BENCH_BOARD_INFO:-"mps2-an385:M3:full mps2-an386:M4F:full microbit:M0:stream"}
BOARDS=${BENCH_BOARDS:-$(for i in $BOARD_INFO; do printf '%s ' "${i%%:*}"; done)}
# The ray caster costs hundreds of times the fast renderer: soft float and
# double are limited to the M3 (and hard float to the M4F), q16 runs everywhere.
BUILDS=${BENCH_BUILDS:-"q16:fast float:fast float:step double:fast q16:reference q16:raycast float:raycast@M3,M4F double:raycast@M3"}
SETS=${BENCH_SETS:-seed bench lit nodes peer}
CSIZE=${BENCH_CYCLES_SIZE:-40x30}
JOBS=${BENCH_JOBS:-$(nproc 2>/dev/null || echo 2)}
OUT=$BUILD/bench
# The sub-makes are ours: no jobserver or command-line variables from a parent make.
unset MAKEFLAGS MFLAGS MAKELEVEL
# A scene too big for a board: only say so (no per-kind probes, firmware/fit.sh).
export FIT_QUICK=1
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
short() { local n; n=$(basename "$1" .scene); [[ $n == abb* ]] && n=${n%%-*}; echo "$n"; }
get() { sed -nE "s/.*(^| )$1=([^ ]+).*/\2/p" <<<"$2"; }
set_of() { case $1 in */bench/*) echo bench ;; */lit/*) echo lit ;; */nodes/*) echo nodes ;; */peer/*) echo peer ;; */stress/*) echo stress ;; *) echo seed ;; esac; }
set_scenes() {
    case $1 in
        seed) printf '%s\n' scenes/abb*.scene | sort -V ;;
        bench) printf '%s\n' scenes/bench/*.scene ;;
        lit) printf '%s\n' scenes/lit/*.scene ;;
        nodes) printf '%s\n' scenes/nodes/*.scene ;;
        peer) printf '%s\n' scenes/peer/*.scene ;;
        stress) printf '%s\n' scenes/stress/*.scene ;;
        *) die "unknown scene set '$1' (seed, bench, lit, nodes, peer, stress)" ;;
    esac
}
if [[ -n ${BENCH_SCENES:-} ]]; then
    SCENES=$BENCH_SCENES
else
    SCENES=$(for s in $SETS; do set_scenes "$s"; done)
fi
# Does the core have the stepping float build (wp-e, issue 9)?
step_ok() { grep -q 'FXRT_FLOAT_STEP' core/fxrt_config.h; }
# build flags: LOOP -> "FW_EXTRA FW_TAG" ("" for fast)
loop_extra() {
    case $1 in
        fast) echo "" ;;
        step) echo "-DFXRT_FLOAT_STEP=1 step" ;;
        reference) echo "-DFXRT_RENDERER=2 ref" ;;
        raycast) echo "-DFXRT_RENDERER=3 rc" ;;
        *) die "unknown loop '$1' in BENCH_BUILDS (fast, step, reference, raycast)" ;;
    esac
}
# builds for a board: "number:loop" words
board_builds() {
    local cpu b spec
    cpu=$(board_field "$1" 2)
    for b in $BUILDS; do
        spec=${b%%@*}
        if [[ $b == *@* ]]; then
            [[ ",${b#*@}," == *",$cpu,"* ]] || continue
        fi
        echo "$spec"
    done
}

# --- one unit: one (board, scene, number, loop) -----------------------------
# (make qemu writes NAME-NUMBER-SIZE[-FW_TAG].ppm; the frame is copied away.)
# A CSV row: set,scene,board,cpu,number,loop,status,instructions,
# instructions_per_pixel,mismatched_pct,psnr,max_err,text_bytes,within1_pct,
# within2_pct,cpi,cycles_per_pixel (status ok, nofit or n/a; the numbers are
# empty unless ok, and cpi and cycles_per_pixel are empty for the builds not
# priced: reference and raycast).
if [[ ${1:-} == --unit ]]; then
    idx=$2 total=$3 board=$4 scene=$5 number=$6 r=$7
    cpu=$(board_field "$board" 2) fb=$(board_field "$board" 3)
    name=$(basename "$scene" .scene) set=$(set_of "$scene")
    id=$(printf '%04d' "$idx")
    label="$(short "$scene") $cpu $number $r"
    echo "[$idx/$total] $label" >&2
    row() { echo "$set,$name,$board,$cpu,$number,$r,$1" >"$OUT/runs/$id.csv"; }
    if [[ $r == step ]] && ! step_ok; then
        row "n/a,,,,,,,,,,"
        exit 0
    fi
    read -r fwx tag < <(loop_extra "$r"; echo)
    # Scene names repeat across sets (bench/room, lit/room): the lit set's
    # firmware and frames get their own tag, references and frames the set.
    [[ $set == lit ]] && tag=${tag:+$tag-}lit
    extra=()
    [[ -n $tag ]] && extra=(FW_EXTRA="$fwx" FW_TAG="$tag")
    log=$OUT/runs/$id.log
    if ! $M qemu SCENE="$scene" BOARD="$board" NUMBER="$number" SIZE="$SIZE" FB="$fb" "${extra[@]}" >"$log" 2>&1; then
        if grep -q "^$scene: does not fit $board" "$log"; then
            row "nofit,,,,,,,,,,"
            exit 0
        fi
        { echo "$label: make qemu failed:"; sed 's/^/  | /' "$log"; } >"$OUT/runs/$id.err"
        exit 1
    fi
    line=$(grep '^board=' "$log" | tail -n 1 || true)
    ins=$(get instructions "$line") ipp=$(get instructions_per_pixel "$line") px=$(get pixels "$line")
    if [[ -z $ins || -z $ipp || $px != $((${SIZE%x*} * ${SIZE#*x})) ]]; then
        { echo "$label: no or bad 'board= instructions= ... pixels=' line from make qemu:"; sed 's/^/  | /' "$log"; } >"$OUT/runs/$id.err"
        exit 1
    fi
    frame=$OUT/frames/$board/$set-$name-$number-$r.ppm
    mkdir -p "$(dirname "$frame")"
    cp "$BUILD/qemu/$board/$name-$number-$SIZE${tag:+-$tag}.ppm" "$frame"
    if ! cmp=$("$FXRT" compare "$OUT/ref/$set-$name-double.ppm" "$frame" 2>&1); then
        echo "$label: fxrt compare $OUT/ref/$set-$name-double.ppm $frame failed: $cmp" >"$OUT/runs/$id.err"
        exit 1
    fi
    elf=$BUILD/fw/$board/$name-$number-$SIZE-$fb${tag:+-$tag}/fxrt.elf
    if ! text=$(arm-none-eabi-size "$elf" 2>&1 | awk 'END { print $1 }') || [[ ! $text =~ ^[0-9]+$ ]]; then
        echo "$label: cannot read the text size of $elf" >"$OUT/runs/$id.err"
        exit 1
    fi
    # Estimated cycles: the frame's CPI at CSIZE (the trace costs about
    # 20 times the -icount run), for the fast and step builds.
    cpi="" cpp=""
    if [[ $CSIZE != none && ($r == fast || $r == step) ]]; then
        if ! cpi=$(FW_EXTRA="$fwx" FW_TAG="$tag" CYCLES_FB="$fb" BUILD=$BUILD CYCLES_FRAME=1 CYCLES_CPI=1 \
            firmware/cycles.sh "$scene" "$board" "$number" "$CSIZE" 2>"$OUT/runs/$id.cycles") || [[ -z $cpi ]]; then
            { echo "$label: cycle pricing at $CSIZE failed:"; sed 's/^/  | /' "$OUT/runs/$id.cycles" | tail -n 25; } >"$OUT/runs/$id.err"
            exit 1
        fi
        cpp=$(awk -v a="$ipp" -v c="$cpi" 'BEGIN { printf "%.1f", a * c }')
    fi
    row "ok,$ins,$ipp,$(get mismatched_pct "$cmp"),$(get psnr "$cmp"),$(get max_err "$cmp"),$text,$(get within1_pct "$cmp"),$(get within2_pct "$cmp"),$cpi,$cpp"
    exit 0
fi

# --- make bench-host: the host tool under callgrind --------------------------
# Instructions (callgrind Ir) inside engine_render_NUMBER: render_setup and the
# row loop, as the firmware counts them, plus the small per-frame world and
# camera build the firmware does ahead of time (scenec).
#   BENCH_HOST_RENDERERS  loops (fast reference; raycast works too)
#   BENCH_NUMBERS         number types (q16 float double)
#   BENCH_PROFILE=SCENE   instead: a per-function profile (callgrind_annotate,
#                         exclusive Ir) of q16 fast (BENCH_PROFILE_NUMBER,
#                         BENCH_PROFILE_RENDERER) on that scene
if [[ ${1:-} == --host ]]; then
    command -v valgrind >/dev/null ||
        die "valgrind is not installed (apt-get install valgrind); make bench-host needs it"
    [[ -x $FXRT ]] || die "$FXRT not built (make)"
    fn=${BENCH_HOST_FN:-engine_render_*}
    tmp=$(mktemp -d)
    trap 'rm -rf "$tmp"' EXIT
    px=$((${SIZE%x*} * ${SIZE#*x}))
    if [[ -n ${BENCH_PROFILE:-} ]]; then
        pn=${BENCH_PROFILE_NUMBER:-q16} pr=${BENCH_PROFILE_RENDERER:-fast}
        [[ -f $BENCH_PROFILE ]] || die "BENCH_PROFILE=$BENCH_PROFILE: no such scene"
        valgrind --tool=callgrind --callgrind-out-file="$tmp/cg.out" "--toggle-collect=$fn" \
            "$FXRT" render "$BENCH_PROFILE" --number "$pn" --renderer "$pr" --size "$SIZE" -o "$tmp/f.ppm" >"$tmp/log" 2>&1 ||
            { sed 's/^/  | /' "$tmp/log" >&2; die "valgrind $FXRT render failed"; }
        echo "Profile: $BENCH_PROFILE, $pn $pr at $SIZE, host $(uname -m), callgrind Ir inside $fn (exclusive per function; per pixel = Ir / $px)."
        echo
        echo "| file:function (inlined code under its header) | Ir | Ir per pixel | share |"
        echo "|---|---:|---:|---:|"
        callgrind_annotate --inclusive=no "$tmp/cg.out" 2>/dev/null |
            awk -v px="$px" '
                /PROGRAM TOTALS/ { v = $1; gsub(",", "", v); tot = v + 0; next }
                /file:function/ { body = 1; next }
                body && /^-+$/ { body = body == 1 ? 2 : 0; next }
                body == 2 && $1 ~ /^[0-9,]+$/ { v = $1; gsub(",", "", v); v += 0; if (v == 0 || tot == 0) next
                    name = $0; sub(/^[[:space:]]*[0-9,]+[[:space:]]+\([^)]*\)[[:space:]]+/, "", name)
                    sub(/ \[.*\]$/, "", name); sub(/^.*\//, "", name)
                    if (++k <= 12) printf "| `%s` | %d | %.1f | %.1f %% |\n", name, v, v / px, 100 * v / tot }
                END { if (tot) printf "| all functions | %d | %.1f | 100 %% |\n", tot, tot / px }'
        exit 0
    fi
    HR=${BENCH_HOST_RENDERERS:-fast reference}
    NUMBERS=${BENCH_NUMBERS:-q16 float double}
    echo "Host tool ($FXRT, $(uname -m)) at $SIZE: valgrind --tool=callgrind instructions (Ir) inside $fn, per pixel."
    echo "A quick iteration aid only: host instructions, not the firmware figures (make bench)."
    [[ $(wc -w <<<"$HR") -eq 2 ]] && echo "ratio = ${HR##* } / ${HR%% *}."
    echo
    printf '%-6s %-24s %-7s' set scene number
    for r in $HR; do printf ' %12s' "$r"; done
    [[ $(wc -w <<<"$HR") -eq 2 ]] && printf ' %12s' "ratio"
    echo
    for scene in $SCENES; do
        name=$(basename "$scene" .scene)
        for n in $NUMBERS; do
            printf '%-6s %-24s %-7s' "$(set_of "$scene")" "$name" "$n"
            vals=()
            for r in $HR; do
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
for b in $BUILDS; do loop_extra "$(cut -d: -f2 <<<"${b%%@*}")" >/dev/null; done
if [[ ${BENCH_TABLES_ONLY:-0} == 1 ]]; then
    # Tables, plots and docs again from the last run's bench.csv (no runs).
    [[ -f $OUT/bench.csv && -f $OUT/elapsed ]] || die "BENCH_TABLES_ONLY=1: no $OUT/bench.csv or $OUT/elapsed from a complete run"
    total=$(($(wc -l <"$OUT/bench.csv") - 1)) elapsed=$(cat "$OUT/elapsed")
else
rm -rf "$OUT/runs" "$OUT/frames"
mkdir -p "$OUT/runs" "$OUT/ref"
step_ok || echo "bench: core/fxrt_config.h has no FXRT_FLOAT_STEP: the float-step build is reported as not available" >&2

# Host double references, one per scene.
for scene in $SCENES; do
    name=$(basename "$scene" .scene)
    "$FXRT" render "$scene" --number double --size "$SIZE" -o "$OUT/ref/$(set_of "$scene")-$name-double.ppm" ||
        die "$name: host double reference render failed"
done

# Units, one per (board, scene, build); the slow ones (ray caster, reference)
# first, so that the parallel runs end together.
units=() idx=1
for pass in slow quick; do
    for b in $BOARDS; do
        board_field "$b" 2 >/dev/null
        for scene in $SCENES; do
            for nb in $(board_builds "$b"); do
                r=${nb#*:}
                case $r in raycast | reference) [[ $pass == slow ]] || continue ;; *) [[ $pass == quick ]] || continue ;; esac
                units+=("$idx $b $scene ${nb%%:*} $r")
                idx=$((idx + 1))
            done
        done
    done
done
total=$((idx - 1))
echo "bench: $total runs at $SIZE, $JOBS in parallel" >&2
rc=0
printf '%s\n' "${units[@]}" |
    xargs -P "$JOBS" -L 1 sh -c 'exec "$0" --unit "$1" '"$total"' "$2" "$3" "$4" "$5"' "$0" || rc=$?
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
    echo "set,scene,board,cpu,number,loop,status,instructions,instructions_per_pixel,mismatched_pct,psnr,max_err,text_bytes,within1_pct,within2_pct,cpi,cycles_per_pixel"
    cat "$OUT"/runs/*.csv
} >"$OUT/bench.csv"
elapsed=$((SECONDS - start))
echo "$elapsed" >"$OUT/elapsed"
fi

# --- tables (markdown) and Pareto data -------------------------------------------
# Error "0 mismatched" is plotted at ZERO on the log axis.
ZERO=1e-4
awk -F, -v out="$OUT" -v zero=$ZERO -v size="$SIZE" -v csize="$CSIZE" -v sets="$SETS" -v builds="$BUILDS" -v boards="$BOARDS" '
function add(list, v) { if (!((list, v) in seen)) { seen[list, v] = 1; order[list, ++cnt[list]] = v } }
function ok(b, n, r, s) { return ((b, n, r, s) in st) && st[b, n, r, s] == "ok" }
# geometric mean of instructions per pixel over the set: G, G_k (scenes), also mean mismatch M
# and the geometric mean of estimated cycles per pixel GC ("" unless every scene was priced)
function summ(b, n, r, set,   i, s, sum, sc, kc) { G_k = 0; sum = 0; M = 0; sc = 0; kc = 0
    for (i = 1; i <= cnt["s"]; i++) { s = order["s", i]; if (sset[s] != set || !ok(b, n, r, s)) continue
        sum += log(ipp[b, n, r, s]); M += mm[b, n, r, s]; G_k++
        if (cpp[b, n, r, s] != "") { sc += log(cpp[b, n, r, s]); kc++ } }
    G = G_k ? exp(sum / G_k) : ""; M = G_k ? M / G_k : ""; GC = (G_k && kc == G_k) ? exp(sc / kc) : "" }
# ratio num/den of instructions per scene over the set, both ok: R_geo, R_min, R_max, R_n;
# also the mean mismatch of each over the same scenes: R_mn, R_md; and the ratio of
# estimated cycles R_cyc ("" unless every scene of both was priced)
function ratio(bn, nn, rn, bd, nd, rd, set,   i, s, x, sum, sc, kc) { R_n = 0; sum = 0; R_min = ""; R_max = ""; R_mn = 0; R_md = 0; sc = 0; kc = 0
    for (i = 1; i <= cnt["s"]; i++) { s = order["s", i]
        if (sset[s] != set || !ok(bn, nn, rn, s) || !ok(bd, nd, rd, s)) continue
        if (cpp[bn, nn, rn, s] != "" && cpp[bd, nd, rd, s] != "") { sc += log(cpp[bn, nn, rn, s] / cpp[bd, nd, rd, s]); kc++ }
        x = ins[bn, nn, rn, s] / ins[bd, nd, rd, s]; sum += log(x); R_n++
        R_mn += mm[bn, nn, rn, s]; R_md += mm[bd, nd, rd, s]
        if (R_min == "" || x < R_min) R_min = x; if (R_max == "" || x > R_max) R_max = x }
    R_geo = R_n ? exp(sum / R_n) : ""; if (R_n) { R_mn /= R_n; R_md /= R_n }; R_cyc = (R_n && kc == R_n) ? exp(sc / kc) : "" }
# the best float build on board b for the set: the float loop with the fewest
# instructions (relative to q16 fast, scene by scene) whose mean mismatch
# against double is at most q16 fast'"'"'s on the same scenes. Sets B_r (or ""),
# B_ratio (float / q16), B_cyc (the same in estimated cycles), B_n, B_note.
function best(b, set,   j, r, have) { B_r = ""; B_ratio = ""; B_n = 0; B_note = ""; B_cyc = ""; have = 0
    for (j = 1; j <= nloops; j++) { r = loops[j]
        ratio(b, "float", r, b, "q16", "fast", set); if (R_n == 0) continue
        have = 1
        if (R_mn > R_md + 1e-9) { B_note = B_note (B_note ? "; " : "") "float " r " has more error (" sprintf("%.4f", R_mn) " % > " sprintf("%.4f", R_md) " %)"; continue }
        if (B_r == "" || R_geo < B_ratio) { B_r = r; B_ratio = R_geo; B_n = R_n; B_cyc = R_cyc } }
    if (!have) B_note = "no float build ran" }
# The goal of a set: for seed and bench those of the first speed work (g),
# for lit those of lighting (glit), for peer issue 39'"'"'s matched-scene
# targets (gpeer); the nodes set (meshes and transformed objects) has none,
# its figures are for information.
function goalof(set, g, glit, gpeer) { return set == "nodes" ? "" : set == "lit" ? glit : set == "peer" ? gpeer : g }
# a measured figure with its estimated cycles beside it
function withc(v, f, c, cf) { return v == "" ? "n/a" : sprintf(f, v) (c == "" ? "" : "; cycles " sprintf(cf, c)) }
function verdict(m, goal, ge) {
    if (goal == "") return "(no goal)"
    if (m == "") return "n/a"
    if (ge) return m >= goal ? sprintf("**PASS** (%+.0f%%)", (m / goal - 1) * 100) : sprintf("**MISS**: needs %.2fx more", goal / m)
    return m <= goal ? sprintf("**PASS** (%.0f%% under)", (1 - m / goal) * 100) : sprintf("**MISS**: %.2fx over", m / goal) }
function fmt(x, f) { return x == "" ? "n/a" : sprintf(f, x) }
function bname(n, r) { return n " " r }
function cpuof(c) { return (c in board_of) ? board_of[c] : "" }
NR == 1 { next }
{ set = $1; s = $2; b = $3; n = $5; r = $6
  if ((s in sset) && sset[s] != set) s = set "/" s # a name another set has too (bench/room, lit/room)
  add("s", s); add("b", b); cpu[b] = $4; sset[s] = set; add("set" set, s)
  if (!(($4) in board_of)) board_of[$4] = b
  st[b, n, r, s] = $7; ins[b, n, r, s] = $8; ipp[b, n, r, s] = $9; mm[b, n, r, s] = $10; ps[b, n, r, s] = $11
  cpi[b, n, r, s] = $16; cpp[b, n, r, s] = $17
  me[b, n, r, s] = $12; tx[b, n, r, s] = $13; row[++rows] = $0 }
END {
  nloops = split("fast step raycast", loops, " ")
  nsets = split(sets, SET, " ")
  nbuilds = split(builds, BLD, " ")
  md = out "/tables.md"
  m3 = cpuof("M3"); m0 = cpuof("M0"); m4 = cpuof("M4F")

  # 1. targets, one column per scene set
  print "## TARGETS\n" > md
  printf "All from this run at %s, fast renderers, geometric means over each set'"'"'s scenes (ratios are taken per scene on instructions per frame, then averaged geometrically). The **best float build** of a board is its float build (fast = direct evaluation, step = forward differences restarted per row or span, raycast = per-pixel ray caster) with the fewest instructions whose mean mismatched %% against the double reference is at most q16'"'"'s on the same scenes (on the M4F: hard float). Scenes that do not fit a board are left out of that board'"'"'s figures (see the per-board tables). The seed and bench goals are those of the first speed work, the lit goals those of lighting (lights, materials, shadows) and, per pixel, of lit speed (issue 39), as are the peer set'"'"'s (the scene the C port of tinyraytracer was measured on); the nodes set (meshes, smooth normals, transformed objects) has none. \"-\": no goal for that set, the figure is for information. **Cycles** beside a figure are estimated (docs/BENCHMARKS.md, \"Cycles\"): each fast or step run'"'"'s CPI, priced at %s, times its instructions; verdicts are on instructions.\n\n", size, csize > md
  hdr = "| measure |"; sep = "|---|"
  for (k = 1; k <= nsets; k++) { hdr = hdr " " SET[k] ": goal | " SET[k] ": measured | " SET[k] ": result |"; sep = sep "---:|---:|---|" }
  print hdr > md; print sep > md
  pp("q16 on the M3 (" m3 "), instructions per pixel", m3, 0, 8, 60, 500, 600)
  pp("q16 on the M0 (" m0 "), instructions per pixel", m0, 0, "", "", 1450, 1650)
  pp("best build on the M4F (" m4 "), instructions per pixel: the fewer of q16 fast and the best hard-float build", m4, 1, "", "", 350, 310)
  tgt("q16 vs the best soft-float build, M3 (" m3 "): float / q16", m3, 8, 6, 1)
  tgt("q16 vs the best soft-float build, M0 (" m0 "): float / q16", m0, 10, 8, 1)
  tgt("q16 vs the best hard-float build, M4F (" m4 "): q16 / float", m4, 1.0, 1.5, 0)
  line = "| q16 vs the per-pixel ray caster in q16, M3 (" m3 "): raycast / fast |"
  for (k = 1; k <= nsets; k++) { ratio(m3, "q16", "raycast", m3, "q16", "fast", SET[k])
    goal = goalof(SET[k], 50, "", "")
    line = line " " (goal == "" ? "-" : ">= 50x") " | " fmt(R_geo, "%.1fx") " | " verdict(R_geo, goal, 1) " |" }
  print line > md
  print "" > md
  print "Extra rows, labelled for what they compare (not targets):\n" > md
  print hdr > md; print sep > md
  extra("q16 vs float fast (direct evaluation), M3: float / q16", m3, "float", "fast", "q16", "fast", 12, 1)
  extra("q16 vs float fast (direct evaluation), M0: float / q16", m0, "float", "fast", "q16", "fast", 8, 1)
  extra("q16 vs hard float fast (direct evaluation), M4F: q16 / float", m4, "q16", "fast", "float", "fast", 1.0, 0)
  extra("fast vs reference loop, q16 on the M3: reference / fast", m3, "q16", "reference", "q16", "fast", 5, 1)
  print "\nGoals of the extra rows are the first release'"'"'s (float fast: >= 12x M3, >= 8x M0, <= 1.0x M4F; reference / fast >= 5x).\n" > md

  # 2. best float build per board and set
  print "## Best float build per board\n" > md
  print "| set | board | float fast: instr/px, mismatched % | float step | float raycast | q16 fast | best float build | best / q16 (instructions) | best / q16 (estimated cycles) |" > md
  print "|---|---|---|---|---|---|---|---:|---:|" > md
  for (k = 1; k <= nsets; k++) for (i = 1; i <= cnt["b"]; i++) { b = order["b", i]; set = SET[k]
    line = "| " set " | " b " (" cpu[b] ") |"
    for (j = 1; j <= nloops; j++) line = line " " cell(b, "float", loops[j], set) " |"
    line = line " " cell(b, "q16", "fast", set) " |"
    best(b, set)
    if (B_r == "") line = line " none" (B_note ? " (" B_note ")" : "") " | n/a | n/a |"
    else line = line " float " B_r (B_note ? " (" B_note ")" : "") " | " sprintf("%.2fx (%d of %d scenes)", B_ratio, B_n, cnt["set" set]) " | " fmt(B_cyc, "%.2fx") " |"
    print line > md }
  print "" > md

  # 3. per set, per board
  for (k = 1; k <= nsets; k++) { set = SET[k]
    printf "## Scene set: %s (%d scenes)\n\n", set, cnt["set" set] > md
    sl = ""; for (q = 1; q <= cnt["set" set]; q++) sl = sl (q > 1 ? ", " : "") order["set" set, q]
    print "Scenes: " sl ".\n" > md
    print "Instructions per pixel and estimated cycles per pixel: geometric means over the scenes that ran (cycles for the fast and step builds). Error against the host double render: mean mismatched % (share of pixels whose RGB differs), worst (lowest) PSNR, largest channel error. Text: flash bytes of the ELF, smallest - largest.\n" > md
    for (i = 1; i <= cnt["b"]; i++) { b = order["b", i]
      printf "### %s: %s (Cortex-%s)\n\n", set, b, cpu[b] > md
      print "| build | scenes run | instr/pixel | cycles/pixel | instr/frame | mismatched % | worst PSNR dB | max_err | text bytes |" > md
      print "|---|---|---:|---:|---:|---:|---:|---:|---:|" > md
      dat = out "/pareto-" set "-" b ".dat"; printf "" > dat
      for (j = 1; j <= nbuilds; j++) { spec = BLD[j]; sub(/@.*/, "", spec); split(spec, nr, ":"); n = nr[1]; r = nr[2]
        tot = 0; nf = 0; na = 0; c = 0; sm = 0; wp = ""; mx = 0; tmin = ""; tmax = ""; gi = 0; gp = 0
        for (q = 1; q <= cnt["set" set]; q++) { s = order["set" set, q]; if (!((b, n, r, s) in st)) continue
          tot++; if (st[b, n, r, s] == "nofit") { nf++; continue } if (st[b, n, r, s] == "n/a") { na++; continue }
          c++; sm += mm[b, n, r, s]; gi += log(ins[b, n, r, s]); gp += log(ipp[b, n, r, s])
          p = ps[b, n, r, s]; pv = (p == "inf") ? 1e9 : p + 0; if (wp == "" || pv < wp) wp = pv
          if (me[b, n, r, s] + 0 > mx) mx = me[b, n, r, s] + 0
          t = tx[b, n, r, s] + 0; if (tmin == "" || t < tmin) tmin = t; if (tmax == "" || t > tmax) tmax = t }
        if (tot == 0) continue
        if (na == tot) { printf "| %s | not available (core/fxrt_config.h has no FXRT_FLOAT_STEP) | | | | | | | |\n", bname(n, r) > md; continue }
        if (c == 0) { printf "| %s | none: %d of %d do not fit | | | | | | | |\n", bname(n, r), nf, tot > md; continue }
        mean = sm / c; summ(b, n, r, set)
        printf "| %s | %d of %d%s | %.1f | %s | %.0f | %.4f | %s | %d | %s |\n", bname(n, r), c, tot, (nf ? sprintf(" (%d do not fit)", nf) : ""),
          exp(gp / c), fmt(GC, "%.1f"), exp(gi / c), mean, (wp == 1e9 ? "inf" : sprintf("%.2f", wp)), mx, (tmin == tmax ? tmin : tmin " - " tmax) > md
        printf "%s %s %.6g %.6g \"%s %s\"\n", n, r, exp(gp / c), (mean > 0 ? mean : zero), n, r > dat }
      print "" > md; close(dat) } }

  # 4. float-step drift
  print "## Drift of the stepping float build\n" > md
  print "Mismatched % against the double reference, float fast (direct evaluation) and float step (forward differences restarted at each row or span), every scene that ran:\n" > md
  print "| set | scene | board | float fast | float step |" > md
  print "|---|---|---|---:|---:|" > md
  for (k = 1; k <= nsets; k++) for (q = 1; q <= cnt["set" SET[k]]; q++) { s = order["set" SET[k], q]
    for (i = 1; i <= cnt["b"]; i++) { b = order["b", i]
      if (!((b, "float", "step", s) in st) && !((b, "float", "fast", s) in st)) continue
      printf "| %s | %s | %s (%s) | %s | %s |\n", SET[k], s, b, cpu[b], mcell(b, "float", "fast", s), mcell(b, "float", "step", s) > md } }
  print "" > md

  # 5. per scene
  print "## Per scene\n" > md
  print "Error against the host double render (fxrt compare): mismatched % = share of pixels whose RGB differs; within1 % = share whose largest channel error is at most 1/255.\n" > md
  print "| set | scene | board | build | instructions | instr/pixel | CPI | cycles/pixel | mismatched % | within1 % | PSNR dB | max_err | text bytes |" > md
  print "|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|" > md
  for (i = 1; i <= rows; i++) { split(row[i], f, ",")
    if (f[7] == "ok") printf "| %s | %s | %s (%s) | %s %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", f[1], f[2], f[3], f[4], f[5], f[6], f[8], f[9], (f[16] == "" ? "-" : f[16]), (f[17] == "" ? "-" : f[17]), f[10], (f[14] == "" ? "-" : f[14]), f[11], f[12], f[13] > md
    else printf "| %s | %s | %s (%s) | %s %s | %s | | | | | | | | |\n", f[1], f[2], f[3], f[4], f[5], f[6], (f[7] == "nofit" ? "does not fit" : "not available") > md }
  close(md)
}
function cell(b, n, r, set,   q, s, na, nf) { summ(b, n, r, set); if (G != "") return sprintf("%.1f, %.4f %%", G, M)
  na = 0; nf = 0
  for (q = 1; q <= cnt["set" set]; q++) { s = order["set" set, q]; if (!((b, n, r, s) in st)) continue
    if (st[b, n, r, s] == "n/a") na++; else if (st[b, n, r, s] == "nofit") nf++ }
  return na ? "not available" : nf ? "does not fit" : "not run" }
function mcell(b, n, r, s) { if (!((b, n, r, s) in st)) return "-"; if (st[b, n, r, s] == "nofit") return "does not fit"
  if (st[b, n, r, s] == "n/a") return "not available"; return sprintf("%.4f", mm[b, n, r, s]) }
function tgt(label, b, goal9, goal11, ge,   k, line, set, goal, vc) { line = "| " label " |"
  for (k = 1; k <= nsets; k++) { set = SET[k]; best(b, set); v = ""; goal = goalof(set, goal9, goal11)
    if (B_r != "") v = ge ? B_ratio : 1 / B_ratio
    vc = B_cyc == "" ? "" : ge ? B_cyc : 1 / B_cyc
    line = line " " (goal == "" ? "-" : ge ? ">= " goal "x" : "<= " sprintf("%.1f", goal) "x") " | " (B_r == "" ? "n/a" : sprintf("%.2fx (float %s%s)", v, B_r, B_n < cnt["set" set] ? sprintf(", %d of %d scenes", B_n, cnt["set" set]) : "") (vc == "" ? "" : sprintf("; cycles %.2fx", vc))) " | " verdict(v, goal, ge) " |" }
  print line > md }
function extra(label, b, nn, rn, nd, rd, goal9, ge,   k, line, goal) { line = "| " label " |"
  for (k = 1; k <= nsets; k++) { ratio(b, nn, rn, b, nd, rd, SET[k]); goal = goalof(SET[k], goal9, "", "")
    line = line " " (goal == "" ? "-" : ge ? ">= " goal "x" : "<= " sprintf("%.1f", goal) "x") " | " withc(R_geo, "%.2fx", R_cyc, "%.2fx") " | " verdict(R_geo, goal, ge) " |" }
  print line > md }
# A per-pixel target row: q16 fast on board b, or (best = 1) the fewer
# instructions of q16 fast and the best float build; goals per set.
function pp(label, b, bst, gseed, gbench, glit, gpeer,   k, line, goal, v, vc, what) { line = "| " label " |"
  for (k = 1; k <= nsets; k++) { summ(b, "q16", "fast", SET[k]); v = G; vc = GC; what = ""
    if (bst) { best(b, SET[k])
      if (B_r != "") { summ(b, "float", B_r, SET[k]); if (v == "" || (G != "" && G < v)) { v = G; vc = GC; what = "float " B_r } else what = "q16" } }
    goal = goalof(SET[k], SET[k] == "seed" ? gseed : gbench, glit, gpeer)
    line = line " " (goal == "" ? "-" : "<= " goal) " | " withc(v, "%.1f", vc, "%.1f") (what == "" ? "" : " (" what ")") " | " verdict(v, goal, 0) " |" }
  print line > md }
' "$OUT/bench.csv"

# Pareto front per set and board: sort by x, keep points with a lower y than all faster ones.
plots_made=()
for set in $SETS; do
    for b in $BOARDS; do
        dat=$OUT/pareto-$set-$b.dat
        [[ -s $dat ]] || continue
        sort -t' ' -k3,3g -k4,4g "$dat" | awk '{ y = $4 + 0 } NR == 1 || y < best { print; best = y }' >"$OUT/pareto-$set-$b.front"
        cpu=$(board_field "$b" 2)
        gnuplot -e "data='$dat'; front='$OUT/pareto-$set-$b.front'; out='$OUT/pareto-$set-$b.png'; board='$b (Cortex-$cpu), $set scenes'; size='$SIZE'; zero=$ZERO" \
            firmware/bench.gp || die "gnuplot failed for $set $b"
        plots_made+=("pareto-$set-$b.png")
    done
done

# bench.md and, with BENCH_UPDATE_DOCS=1, docs/.
if [[ -n ${BENCH_REV:-} ]]; then # e.g. when run in an exported tree
    rev=$BENCH_REV
else
    rev=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
    [[ -n $(git status --porcelain --untracked-files=no 2>/dev/null) ]] && rev="$rev (with uncommitted changes)"
fi
header() {
    echo "Regenerate with \`make bench BENCH_UPDATE_DOCS=1\`. Last run $(date -u '+%Y-%m-%d %H:%M UTC'), commit $rev;"
    echo "$(qemu-system-arm --version | head -n 1), arm-none-eabi-gcc $(arm-none-eabi-gcc -dumpversion);"
    echo "$total runs in ${elapsed} s at $SIZE ($JOBS in parallel). Counts are QEMU \`-icount\` instruction counts (deterministic);"
    if [[ $CSIZE == none ]]; then echo "no cycles were estimated (BENCH_CYCLES_SIZE=none)."
    else echo "cycles are estimates: each fast and step run's CPI, priced at $CSIZE by \`firmware/cycles.sh\`, times its instructions."; fi
    step_ok || echo "The stepping float build (\`-DFXRT_FLOAT_STEP=1\`) is not in this core: reported as not available."
}
plots() { # DIR
    echo "## Run time against error (Pareto plots)"
    echo
    echo "One plot per scene set and board. x: instructions per pixel (geometric mean over the set's scenes, log"
    echo "scale); y: mean mismatched % against the host double render (log scale; 0 is drawn at $ZERO). The line"
    echo "joins the Pareto front: builds no other build beats on both axes."
    echo
    local p
    for p in "${plots_made[@]}"; do echo "![${p%.png}]($1$p)"; done
    echo
}
{
    echo "# fxrt benchmarks ($SIZE)"
    echo
    header
    echo
    cat "$OUT/tables.md"
    plots ""
} >"$OUT/bench.md"

if [[ ${BENCH_UPDATE_DOCS:-0} == 1 ]]; then
    doc=docs/BENCHMARKS.md
    [[ -f $doc ]] || die "$doc is missing: it holds the hand-written template around the generated blocks"
    header >"$OUT/doc-header.md"
    { cat "$OUT/tables.md"; plots "bench/"; } >"$OUT/doc-tables.md"
    host/replace-block.sh "$doc" bench:header "$OUT/doc-header.md" bench:tables "$OUT/doc-tables.md" || exit 1
    mkdir -p docs/bench
    rm -f docs/bench/pareto-*.png
    for p in "${plots_made[@]}"; do cp "$OUT/$p" docs/bench/; done
    cp "$OUT/bench.csv" docs/bench/bench.csv
    echo "bench: updated $doc and docs/bench/" >&2
fi

echo
sed -n '/^## TARGETS/,/^## Best float build/p' "$OUT/tables.md" | sed '$d'
echo "bench: $total runs in ${elapsed} s; wrote $OUT/bench.csv, $OUT/bench.md, $OUT/pareto-*.png"
