#!/usr/bin/env bash
# Sanitizer suite (make sanitize; make test). Runs every suite that runs C
# code, with what `make san-build` built with clang
# -fsanitize=address,undefined -fno-sanitize-recover=all into $BUILD/san/:
#   - every unit test binary (list in $BUILD/san/tests.list: test_fx,
#     test_image, test_compare, test_scene, test_geom_q16/float/double,
#     test_shade_q16/float/double: lit worlds built through the API);
#   - test_diff with SAN_DIFF_CASES cases per kind (default 50000);
#   - tests/cli.sh against $BUILD/san/fxrt, with its outputs under
#     $BUILD/san/tests/ (the normal ones are not touched); make test-full
#     also runs golden.sh, stress_scenes.sh and renderers.sh so; make test
#     renders every stress scene (but lit and trace ones, below) in q16,
#     float and double;
#   Figures below in the form "N (quick M)": make test-full uses N, make
#   test M (tests/lib.sh: full).
#   - every lit scene (scenes/lit/*.scene, or any scene with a light or
#     ambient line) rendered by $BUILD/san/fxrt in q16, float and double
#     with both renderers (quick: the reference one in q16 only) at
#     SAN_LIT_SIZE (default 160x120, quick 64x48);
#   - every trace scene (scenes/trace/, scenes/stress/trace-*,
#     tests/scenes/trace-keywords.scene), as written and at samples 2,
#     samples 2 adaptive and samples 3 adaptive (quick: as written and
#     samples 2 adaptive), in q16, float and double
#     with both renderers (quick: the reference one in q16 only) at
#     SAN_TRACE_SIZE (default 48x36);
#   - tests/oracle.sh with $BUILD/san/tests/oracle (make test-full only: the
#     oracle is test code, which make test runs unsanitized): every scene
#     file and SAN_ORACLE_SCENES random scenes (default 300), and the stress
#     expectations check;
#   - the fuzz harnesses (already sanitized) over their corpora and the
#     scene seeds, and SAN_KERNEL_RUNS fixed-seed kernel inputs (the kernel
#     harness: make test-full only);
#   - "no partial output": 200 (quick 80) scenes (a sample of the fuzzer's corpus
#     $BUILD/fuzz/scene-corpus when there is one, the rest deterministic
#     mutations of the seed scenes) through `fxrt render FILE -o OUT.png`:
#     exit 0 and an image, or exit 2, one "FILE:LINE: message" line on
#     stderr, no image and no *.tmp.* file.
# Sanitizer reports are written to files (log_path), so a report counts
# even when a suite swallows the program's stderr, and abort_on_error makes
# the exit status 134, which no suite accepts as an expected failure. Any
# report (UB such as signed overflow, memory error, leak) fails the check.
# Reports and logs: $BUILD/san/logs/.
set -u
. "$(dirname "$0")/lib.sh"
san=$BUILD/san
sfxrt=$san/fxrt
logs=$san/logs
partial=$san/partial
# make test takes the quick defaults (scope's second figure), make test-full the first.
PARTIAL_FILES=${PARTIAL_FILES:-$(scope 200 80)}
PARTIAL_SIZE=${PARTIAL_SIZE:-24x16}
SAN_DIFF_CASES=${SAN_DIFF_CASES:-50000}
SAN_ORACLE_SCENES=${SAN_ORACLE_SCENES:-300}
SAN_KERNEL_RUNS=${SAN_KERNEL_RUNS:-20000}

# san_env DIR: sanitizer options for a run whose reports go to DIR/.
san_env() {
    mkdir -p "$1"
    export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:abort_on_error=1:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1:strict_string_checks=1:disable_coredump=1:log_path=$1/asan"
    export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:abort_on_error=1:log_path=$1/ubsan"
}

# no_reports DIR: true when DIR holds no sanitizer report; prints them if so.
no_reports() {
    local f found=0
    for f in "$1"/asan.* "$1"/ubsan.*; do
        [ -e "$f" ] || continue
        found=1
        echo "--- sanitizer report $f"
        head -n 40 "$f"
    done
    [ $found -eq 0 ]
}

# --- one input of the partial-output check (run in parallel, see below) ---
# sanitize.sh --one FILE DIR: prints "ok FILE" or "FAIL FILE: why".
if [ "${1:-}" = --one ]; then
    f=$2 dir=$3
    rm -rf "$dir"
    mkdir -p "$dir/out"
    san_env "$dir/rep"
    why=
    "$sfxrt" render "$f" -o "$dir/out/out.png" --size "$PARTIAL_SIZE" 2>"$dir/err.txt"
    rc=$?
    msg=$(head -n 1 "$dir/err.txt")
    rest=${msg#"$f:"}
    if [ $rc -eq 0 ]; then
        [ -s "$dir/out/out.png" ] || why="exit 0 but no image"
        # (A mesh's note on the zero-area triangles it left out is fine.)
        grep -qv "^$f: note: " "$dir/err.txt" && why="exit 0 with stderr: $msg"
        # Accepted scenes also go through the float and double builds.
        for n in float double; do
            "$sfxrt" render "$f" -o "$dir/out/out-$n.ppm" --size "$PARTIAL_SIZE" --number $n \
                2>>"$dir/err.txt" || why="exit $? with --number $n: $(tail -n 1 "$dir/err.txt")"
        done
    elif [ $rc -eq 2 ]; then
        # (A mesh's OBJ error too: the OBJ's own FILE:LINE follows the scene's.)
        { [ "$rest" != "$msg" ] && [[ $rest =~ ^[0-9]+:\ .+ ]]; } ||
            why="message is not '$f:LINE: ...': $msg"
        [ "$(wc -l <"$dir/err.txt")" -eq 1 ] || why="more than one line on stderr"
        [ -e "$dir/out/out.png" ] && why="rejected but $dir/out/out.png exists"
    else
        why="exit status $rc: $msg"
    fi
    leftover=$(ls -A "$dir/out" | grep -F '.tmp.')
    [ -n "$leftover" ] && why="temporary file left: $leftover"
    no_reports "$dir/rep" >"$dir/reports.txt" || why="sanitizer report: $(grep -m1 -E 'ERROR|runtime error' "$dir/reports.txt")"
    if [ -z "$why" ]; then
        echo "ok $f $([ $rc -eq 0 ] && echo accepted || echo rejected)"
        rm -rf "$dir"
    else
        cp "$f" "$dir/input.scene"
        echo "FAIL $f: $why (kept in $dir)"
    fi
    exit 0
fi

# Deterministic mutations of a scene (mawk/gawk): SEED selects 1..2 edits.
# Half of them put an edge value into a field, mostly one the field accepts
# (coordinates of +-8192, 2^-16, fov 179.999, radius 4096, ...) so that
# many mutants parse and reach the renderers; the others drop or insert a
# word, duplicate, drop or truncate lines, add a stray byte, swap the
# camera type, set an odd image size, or overflow a kind's capacity.
mutate() { # mutate SEED FILE
    awk -v seed="$1" '
    { line[NR] = $0 }
    END {
        srand(seed); n = NR; if (n == 0) { n = 1; line[1] = "" }
        nwild = split("8192.0001 -8192.00001 4096.0001 -0 1e-5 0.0000152 1e99999 -1e99999 " \
                      "1e-400 180 32767 2 -1 1. .5 +1 1e 0x10 nan inf 100000 65536 3.4e38", wild, " ")
        ncoord = split("8192 -8192 8191.99999 0 -0.0000152587890625 0.0000152587890625 1e3 " \
                       "-4096.5 0.1 1e-4 3", coord, " ")
        ncolor = split("0 1 0.5 0.0000152587890625 1.0 0.99999", color, " ")
        nfov = split("0.001 0.01 1 90 179.999 179.9999999 0.0000152587890625", fov, " ")
        nrad = split("4096 0.0000152587890625 0.001 1000 4095.99999", rad, " ")
        nword = split("image background camera perspective orthographic plane sphere triangle " \
                      "box point normal center radius a b c min max color eye gaze up fov scale # " \
                      "material reflective transparent reflection index depth samples adaptive",
                      word, " ")
        byte[1] = "\001"; byte[2] = "\177"; byte[3] = "\200"; byte[4] = "\r"
        byte[5] = "\t"; byte[6] = "\033"; byte[7] = "\303\251"
        edits = 1 + int(rand() * 2)
        for (e = 0; e < edits; e++) {
            op = int(rand() * 18); i = 1 + int(rand() * n)
            nt = split(line[i], t, /[ \t]+/)
            if (op < 9 && nt > 1) {           # a value becomes an edge case
                k = 2 + int(rand() * (nt - 1))
                for (f = k; f > 1 && t[f] !~ /^[a-z]+$/; f--) ;
                if (rand() < 0.2) v = wild[1 + int(rand() * nwild)]
                else if (t[f] == "color" || t[1] == "background") v = color[1 + int(rand() * ncolor)]
                else if (t[f] == "fov") v = fov[1 + int(rand() * nfov)]
                else if (t[f] == "radius" || t[f] == "scale") v = rad[1 + int(rand() * nrad)]
                else v = coord[1 + int(rand() * ncoord)]
                t[k] = v
                line[i] = join(t, nt)
            } else if (op == 9 && nt > 0) {   # drop a word
                k = 1 + int(rand() * nt); s = ""
                for (j = 1; j <= nt; j++) if (j != k) s = s (s == "" ? "" : " ") t[j]
                line[i] = s
            } else if (op == 10 && nt > 0) {  # insert a word
                k = 1 + int(rand() * nt); t[k] = t[k] " " word[1 + int(rand() * nword)]
                line[i] = join(t, nt)
            } else if (op == 11) {            # duplicate a line
                for (j = n; j >= i; j--) line[j + 1] = line[j]; n++
            } else if (op == 12 && n > 1) {   # drop a line
                for (j = i; j < n; j++) line[j] = line[j + 1]; n--
            } else if (op == 13) {            # a stray byte
                p = int(rand() * (length(line[i]) + 1))
                line[i] = substr(line[i], 1, p) byte[1 + int(rand() * 7)] substr(line[i], p + 1)
            } else if (op == 14) {            # swap the camera type
                for (j = 1; j <= n; j++) {
                    if (line[j] ~ /perspective/) { sub(/perspective/, "orthographic", line[j]) }
                    else if (line[j] ~ /orthographic/) { sub(/orthographic/, "perspective", line[j]) }
                    if (rand() < 0.5) { sub(/ fov /, " scale ", line[j]) } else { sub(/ scale /, " fov ", line[j]) }
                }
            } else if (op == 15) {            # an odd image size
                if (rand() < 0.7) line[i] = "image " (1 + int(rand() * 4096)) " " (1 + int(rand() * 4096))
                else line[i] = "image " int(rand() * 5000) " " (rand() < 0.5 ? "0" : int(rand() * 5000))
            } else if (op == 16 && line[i] ~ /^(plane|sphere|triangle|box) /) {  # capacity
                m = 63 + int(rand() * 3)
                for (j = 1; j <= m; j++) line[n + j] = line[i]
                n += m
            } else if (op == 17) {            # truncate
                n = i
            }
        }
        for (j = 1; j <= n; j++) print line[j]
    }
    function join(t, nt,   s, j) { s = t[1]; for (j = 2; j <= nt; j++) s = s " " t[j]; return s }
    ' "$2"
}

rm -rf "$logs"
mkdir -p "$logs"

# The tool and tests must really be instrumented (an unsanitized build
# would pass everything below without proving anything).
if [ ! -x "$sfxrt" ] || [ ! -f "$san/tests.list" ]; then
    bad "sanitized build missing: run 'make san-build' (or make sanitize)"
    report sanitize
    exit 1
fi
check "fxrt has ASan" bash -c "nm '$sfxrt' | grep -q __asan_init"
check "fxrt has UBSan" bash -c "nm '$sfxrt' | grep -q __ubsan_handle"

# run_suite NAME CMD...: passes when CMD exits 0, its last result line says
# "0 failed" (if it prints one) and no sanitizer report was written.
run_suite() {
    local name=$1
    shift
    run_quiet "$name" "$@"
    judge_suite "$name"
}

# run_quiet NAME CMD...: runs CMD with the sanitizer options, its output in
# $logs/NAME.log, its exit status and time in $logs/NAME.rc and .secs.
run_quiet() {
    local name=$1 start
    shift
    progress "sanitize.sh: $name"
    start=$(date +%s)
    (san_env "$logs/$name" && exec "$@") >"$logs/$name.log" 2>&1
    echo $? >"$logs/$name.rc"
    echo $(($(date +%s) - start)) >"$logs/$name.secs"
}

# judge_suite NAME: the result of a run_quiet.
judge_suite() {
    local name=$1 rc line
    rc=$(cat "$logs/$name.rc")
    line=$(grep -E '[0-9]+ passed, [0-9]+ failed' "$logs/$name.log" | tail -n 1)
    echo "$name: exit $rc, $(cat "$logs/$name.secs") s${line:+, $line}"
    if no_reports "$logs/$name" >"$logs/$name.reports" && [ $rc -eq 0 ] &&
        { [ -z "$line" ] || [[ $line =~ \ 0\ failed ]]; }; then
        ok
    else
        bad "$name (exit $rc; log $logs/$name.log)"
        tail -n 15 "$logs/$name.log" | sed 's/^/    | /'
        sed 's/^/    | /' "$logs/$name.reports"
    fi
}

# make test-full: the two longest suites (mostly shell work around the
# sanitized fxrt) run in the background on the second core; they are
# judged after the rest. make test renders every stress scene through the
# sanitized fxrt instead (section "stress scenes" below); the unsanitized
# suites check their expectations.
if full; then
    {
        run_quiet stress_scenes.sh env BUILD="$san" FXRT="$sfxrt" tests/stress_scenes.sh
        run_quiet renderers.sh env BUILD="$san" FXRT="$sfxrt" tests/renderers.sh
    } &
    lane=$!
fi
while read -r t; do
    [ -n "$t" ] || continue
    run_suite "$(basename "$t")" "$t"
done <"$san/tests.list"
run_suite test_diff "$san/tests/test_diff" "$SAN_DIFF_CASES"
run_suite cli.sh env BUILD="$san" FXRT="$sfxrt" tests/cli.sh
full && run_suite golden.sh env BUILD="$san" FXRT="$sfxrt" tests/golden.sh
# The oracle is test code, run unsanitized by make test (oracle.sh): its
# sanitized run is part of the full scope.
full && run_suite oracle.sh env BUILD="$san" ORACLE="$san/tests/oracle" ORACLE_TEST_SCENES="$SAN_ORACLE_SCENES" tests/oracle.sh

# trace_scene FILE / lit_scene FILE: the scenes of the trace and lit
# sections below (a trace scene is not also a lit one).
trace_scene() { [[ $1 == scenes/trace/* || $1 == scenes/stress/trace-* ]]; }
lit_scene() {
    ! trace_scene "$1" && { [[ $1 == scenes/lit/* || $1 == *lit* ]] ||
        grep -qE '^[[:space:]]*(light|ambient)[[:space:]]' "$1"; }
}

# san_render DESC NAME OUT FXRT-RENDER-ARGS...: one render through the
# sanitized fxrt (log $logs/NAME.log): ok with exit 0, an image and no
# sanitizer report; otherwise bad, the reports printed, and status 1.
san_render() {
    local desc=$1 name=$2 out=$3 rc
    shift 3
    rm -f "$out"
    (san_env "$logs/$name" && exec "$sfxrt" render "$@" -o "$out") >"$logs/$name.log" 2>&1
    rc=$?
    if [ $rc -eq 0 ] && [ -s "$out" ] && no_reports "$logs/$name" >"$logs/$name.reports"; then
        ok
        return 0
    fi
    bad "$desc: exit $rc$([ -s "$out" ] || echo ', no image') (log $logs/$name.log)"
    sed 's/^/    | /' "$logs/$name.reports" | head -n 20
    return 1
}

# --- stress scenes (make test; make test-full runs stress_scenes.sh above) ---
# Every stress scene that is not meant to be rejected through the sanitized
# fxrt in q16, float and double at its own size: exit 0, an image, no
# sanitizer report. (Rejected ones are refused by cli.sh's checks and the
# no-partial-output section below.)
if ! full; then
    progress "sanitize.sh: stress scenes"
    start=$(date +%s)
    n_st=0 n_st_bad=0
    mkdir -p "$san/tests/stress"
    for f in scenes/stress/*.scene; do
        grep -q '^# expect: rejected:' "$f" && continue
        # lit and trace stress scenes: their own sections below
        trace_scene "$f" || lit_scene "$f" && continue
        for n in q16 float double; do
            name=stress-$(basename "${f%.scene}")-$n
            n_st=$((n_st + 1))
            san_render "stress scene $f ($n)" "$name" "$san/tests/stress/$name.png" "$f" --number $n ||
                n_st_bad=$((n_st_bad + 1))
        done
    done
    echo "stress scenes: $n_st renders (3 numbers), $n_st_bad failed, $(($(date +%s) - start)) s"
fi

# --- lit scenes (issue 11) ----------------------------------------------------
# Every lit scene (scenes/lit/, and any scene elsewhere whose name says lit
# or that has a light line) through the sanitized fxrt in q16, float and
# double at SAN_LIT_SIZE, with every renderer the tool has: exit 0, an
# image, no sanitizer report. (The lighting code itself is also exercised
# by the sanitized test_shade_* and test_diff binaries above, which build
# lit worlds through the API, whether or not lit scene files exist yet.)
SAN_LIT_SIZE=${SAN_LIT_SIZE:-$(scope 160x120 64x48)}
lit=()
for f in scenes/lit/*.scene scenes/*.scene scenes/stress/*.scene scenes/*/*.scene; do
    [ -f "$f" ] || continue
    case " ${lit[*]:-} " in *" $f "*) continue ;; esac
    # (trace scenes: their own section below, small size, samples variants)
    lit_scene "$f" && lit+=("$f")
done
if [ ${#lit[@]} -eq 0 ]; then
    echo "lit scenes: none yet (scenes/lit/*.scene); lighting covered by test_shade_* and test_diff only"
else
    progress "sanitize.sh: ${#lit[@]} lit scenes"
    start=$(date +%s)
    n_lit_bad=0
    for f in "${lit[@]}"; do
        for n in q16 float double; do
            for rr in fast reference; do
                # make test: the reference renderer in Q16.16 only
                ! full && [ $rr = reference ] && [ $n != q16 ] && continue
                name=lit-$(printf '%s' "${f%.scene}" | tr / _)-$n-$rr
                mkdir -p "$san/tests/lit"
                san_render "lit scene $f ($n, $rr)" "$name" "$san/tests/lit/$name.png" \
                    "$f" --size "$SAN_LIT_SIZE" --number $n --renderer $rr || n_lit_bad=$((n_lit_bad + 1))
            done
        done
    done
    echo "lit scenes: ${#lit[@]} scenes x 3 numbers, fast and reference renderers ($(scope "both in every number" "reference: q16 only")) at $SAN_LIT_SIZE, $n_lit_bad failed," \
        "$(($(date +%s) - start)) s"
fi

# --- trace scenes (issue 12) -------------------------------------------------
# Every scenes/trace/ and scenes/stress/trace-* scene (and
# tests/scenes/trace-keywords.scene) through the sanitized fxrt in q16,
# float and double with the fast and reference renderers at SAN_TRACE_SIZE
# (default 48x36: deep bounces under ASan are slow), each as written and in
# three variants made here: `samples 2`, `samples 2 adaptive` and
# `samples 3 adaptive` (make test: only `samples 2 adaptive`; the scene's
# own samples line replaced): exit 0, an
# image, no sanitizer report.
SAN_TRACE_SIZE=${SAN_TRACE_SIZE:-48x36}
trace=()
for f in scenes/trace/*.scene scenes/stress/trace-*.scene tests/scenes/trace-keywords.scene; do
    [ -f "$f" ] && trace+=("$f")
done
if [ ${#trace[@]} -eq 0 ]; then
    bad "trace scenes: none found (scenes/trace/*.scene)"
else
    settings=("samples 2 adaptive")
    full && settings=("samples 2" "samples 2 adaptive" "samples 3 adaptive")
    nset=$((${#settings[@]} + 1))
    progress "sanitize.sh: ${#trace[@]} trace scenes x $nset sample settings"
    start=$(date +%s)
    n_tr_bad=0 n_tr=0
    mkdir -p "$san/tests/trace/scenes"
    for f in "${trace[@]}"; do
        base=$(printf '%s' "${f%.scene}" | tr / _)
        variants=("$f")
        for v in "${settings[@]}"; do
            vf=$san/tests/trace/scenes/$base-$(tr ' ' - <<<"$v").scene
            { grep -vE '^[[:space:]]*samples[[:space:]]' "$f"; echo "$v"; } >"$vf"
            variants+=("$vf")
        done
        for vf in "${variants[@]}"; do
            for n in q16 float double; do
                for rr in fast reference; do
                    ! full && [ $rr = reference ] && [ $n != q16 ] && continue
                    name=trace-$(basename "${vf%.scene}")-$n-$rr
                    [ "$vf" = "$f" ] && name=trace-$base-$n-$rr
                    n_tr=$((n_tr + 1))
                    san_render "trace scene $vf ($n, $rr)" "$name" "$san/tests/trace/$name.png" \
                        "$vf" --size "$SAN_TRACE_SIZE" --number $n --renderer $rr || n_tr_bad=$((n_tr_bad + 1))
                done
            done
        done
    done
    echo "trace scenes: ${#trace[@]} scenes x $nset sample settings x 3 numbers, fast and reference renderers$(scope "" " (reference: q16 only)") = $n_tr renders at" \
        "$SAN_TRACE_SIZE, $n_tr_bad failed, $(($(date +%s) - start)) s"
fi

# --- fuzz corpora -------------------------------------------------------------
# Every input of the fuzzers' corpora (and the scene seeds) once more through
# the sanitized harnesses, which check their own invariants: -runs=0 runs the
# initial corpus and stops. New inputs would go to the first directory, a
# scratch one, so the corpora are not touched. The kernel harness also runs
# SAN_KERNEL_RUNS fixed-seed mutations, so it runs even before any corpus.
rm -rf "$san/fuzz"
mkdir -p "$san/fuzz/scene-seeds" "$san/fuzz/scene-new" "$san/fuzz/kernels-new"
for f in scenes/*.scene scenes/*/*.scene tests/bad-scenes/*.scene tests/scenes/*.scene; do
    [ -f "$f" ] && cp "$f" "$san/fuzz/scene-seeds/$(printf '%s' "$f" | tr / _)"
done
scene_dirs=("$san/fuzz/scene-seeds")
[ -d "$BUILD/fuzz/scene-corpus" ] && scene_dirs+=("$BUILD/fuzz/scene-corpus")
kernel_dirs=()
[ -d "$BUILD/fuzz/kernels-corpus" ] && kernel_dirs+=("$BUILD/fuzz/kernels-corpus")
echo "fuzz corpora: scene inputs from ${scene_dirs[*]}; kernel inputs from ${kernel_dirs[*]:-no corpus yet (make fuzz-kernels)} and $SAN_KERNEL_RUNS mutations"
run_suite fuzz_scene-corpus "$BUILD/fuzz/fuzz_scene" -runs=0 -max_len=4096 -artifact_prefix="$san/fuzz/scene-" \
    "$san/fuzz/scene-new" "${scene_dirs[@]}"
if full; then
    run_suite fuzz_kernels-corpus "$BUILD/fuzz/fuzz_kernels" -runs="$SAN_KERNEL_RUNS" -seed=1 \
        -artifact_prefix="$san/fuzz/kernels-" "$san/fuzz/kernels-new" "${kernel_dirs[@]}"
fi

if full; then
    wait "$lane"
    judge_suite stress_scenes.sh
    judge_suite renderers.sh
fi

# --- no partial output ------------------------------------------------------
rm -rf "$partial"
mkdir -p "$partial/in" "$partial/run"
corpus=$BUILD/fuzz/scene-corpus
n_corpus=0
if [ -d "$corpus" ]; then
    # An even sample of at most half the inputs, by name (SHA-1 for
    # libFuzzer's finds, so effectively random but stable for a corpus).
    total=$(find "$corpus" -maxdepth 1 -type f | wc -l)
    half=$((PARTIAL_FILES / 2))
    while read -r f; do
        n_corpus=$((n_corpus + 1))
        cp "$f" "$partial/in/corpus-$(printf %03d $n_corpus).scene"
    done < <(find "$corpus" -maxdepth 1 -type f | LC_ALL=C sort | awk -v t="$total" -v m=$half 'c < m && NR >= int(c * t / m) + 1 { print; c++ }')
fi
# Three in four mutants start from a good scene, the rest from a bad one.
good=()
for f in scenes/*.scene scenes/stress/*.scene scenes/trace/*.scene tests/scenes/*.scene; do [ -f "$f" ] && good+=("$f"); done
bads=(tests/bad-scenes/*.scene)
for ((i = n_corpus + 1; i <= PARTIAL_FILES; i++)); do
    if [ $((i % 4)) -ne 0 ]; then
        seed=${good[$((i % ${#good[@]}))]}
    else
        seed=${bads[$((i / 4 % ${#bads[@]}))]}
    fi
    mutate "$i" "$seed" >"$partial/in/mut-$(printf %03d $i).scene"
done
start=$(date +%s)
progress "sanitize.sh: partial output, $PARTIAL_FILES scenes"
jobs=$(nproc 2>/dev/null || echo 2)
export BUILD PARTIAL_SIZE
ls "$partial/in" | LC_ALL=C sort |
    xargs -P "$jobs" -I{} bash "$0" --one "$partial/in/{}" "$partial/run/{}" >"$logs/partial.log" 2>&1
n_in=$(ls "$partial/in" | wc -l)
n_ok=$(grep -c '^ok ' "$logs/partial.log")
n_acc=$(grep -c '^ok .* accepted$' "$logs/partial.log")
PASSED=$((PASSED + n_ok))
while read -r l; do bad "partial output: ${l#FAIL }"; done < <(grep -v '^ok ' "$logs/partial.log")
[ "$(wc -l <"$logs/partial.log")" -eq "$n_in" ] ||
    bad "partial output: $n_in inputs but $(wc -l <"$logs/partial.log") result lines"
echo "partial output: $n_in inputs ($n_corpus from the fuzz corpus), $n_acc rendered," \
    "$((n_ok - n_acc)) rejected cleanly, $((n_in - n_ok)) failed, $(($(date +%s) - start)) s"

report sanitize
