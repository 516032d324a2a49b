#!/usr/bin/env bash
# The generated blocks of the documentation. A figure that a page quotes
# from a command (instructions, bytes, error figures, counts) sits between
# the lines <!-- NAME --> and <!-- /NAME --> and is written here from that
# command's output, never typed by hand.
#
#   host/docblocks.sh [NAME...]     print the blocks (every block without NAME)
#   host/docblocks.sh --list        name, page, source and command of each block
#   host/docblocks.sh --names       the names alone
#   host/docblocks.sh replace DOC NAME FILE
#                                   put FILE between DOC's markers of NAME
# Environment:
#   DOC_RUN=1      run each block's command first (else its last output is read)
#   DOCS_UPDATE=1  also rewrite each block in its page
#   BUILD          build directory (default build)
# make doc-blocks [DOC_BLOCKS="lit trace"] [DOC_RUN=1] [DOCS_UPDATE=1] runs it.
#
# A block whose source is missing is reported and left as it is; where a
# command is too long to run as a matter of course (make stress, make
# bench-ablation, make bench-lit-bound), the page's block says "not yet
# generated" and names the command. Other generators keep their own blocks:
# firmware/bench.sh (bench:header, bench:tables), firmware/bench-samples.sh
# (bench:samples), firmware/frontier-report.sh (frontier),
# firmware/benchfx.sh (benchfx:table, benchfx:versus), firmware/oled/oled-table.sh and
# oled-demo.sh (oled:table, oled:frames), firmware/fit.sh
# (ram:table), firmware/size.sh (size; through `replace` below).
set -euo pipefail
BUILD=${BUILD:-build}
L=$BUILD/tests/logs
die() { echo "docblocks: $*" >&2; exit 1; }

# name | page | source (the command's output) | command that writes the source
blocks=(
    "orbit|docs/EMBEDDING.md|$L/examples.sh.log|suite tests/examples.sh"
    "core|docs/ARCHITECTURE.md|$L/layers.sh.log|suite tests/layers.sh"
    "golden|docs/TESTING.md|$L/golden.sh.log|suite tests/golden.sh"
    "oracle|docs/ACCURACY.md|$L/oracle.sh.log|suite tests/oracle.sh"
    "oracle-sweep|docs/ACCURACY.md|$L/oracle-sweep.log|make oracle"
    "fx|docs/ACCURACY.md|$L/test_fx.log|suite $BUILD/tests/test_fx"
    "fx-exhaustive|docs/ACCURACY.md|$L/fx-exhaustive.log|make fx-exhaustive"
    "diff|docs/ACCURACY.md|$L/test_diff.log|suite $BUILD/tests/test_diff"
    "stress|docs/ACCURACY.md|$L/stress.log|make stress"
    "bounce-growth|docs/ACCURACY.md|$L/bounce-growth.log|make bounce-growth"
    "adaptive-error|docs/ACCURACY.md|$L/adaptive-error.log|make adaptive-error"
    "lit|docs/LIGHTING.md|$L/lit.sh.log|suite tests/lit.sh"
    "lit-stress|docs/LIGHTING.md|$L/stress_scenes.sh.log|suite tests/stress_scenes.sh"
    "trace|docs/TRACING.md|$L/trace.sh.log|suite tests/trace.sh"
    "trace-stress|docs/TRACING.md|$L/stress_scenes.sh.log|suite tests/stress_scenes.sh"
    "cutoff|docs/TRACING.md|$L/cutoff.sh.log|make cutoff"
    "norecurse|docs/TRACING.md|$L/norecurse.sh.log|suite tests/norecurse.sh"
    "size|docs/FIRMWARE.md|$BUILD/size.md|make size"
    "fit-message|docs/FIRMWARE.md|$L/fit-message.log|make fw SCENE=scenes/bench/mixed64.scene BOARD=microbit"
    "ablation|docs/BENCHMARKS.md|$BUILD/bench/ablation.md|make bench-ablation"
    "lit-bound|docs/BENCHMARKS.md|$BUILD/bench/lit-bound.md|make bench-lit-bound"
)

field() { # NAME INDEX: one field of a block's entry
    local b
    for b in "${blocks[@]}"; do
        IFS='|' read -r -a f <<<"$b"
        [[ ${f[0]} == "$1" ]] && { echo "${f[$2]}"; return 0; }
    done
    die "no block '$1' (host/docblocks.sh --names lists them)"
}
shown() { # the command as a reader types it, in markdown
    case $1 in
    "suite $BUILD/tests/test_diff") echo "\`make test\` (its suite test_diff)" ;;
    "suite $BUILD/tests/test_fx") echo "\`make test\` (its suite test_fx)" ;;
    "suite tests/lit.sh") echo "\`make lit\` (also in \`make test\`)" ;;
    "suite tests/trace.sh") echo "\`make trace\` (also in \`make test\`)" ;;
    "suite tests/norecurse.sh") echo "\`make norecurse\` (also in \`make test\`)" ;;
    suite*) echo "\`make test\` (its suite ${1#suite })" ;;
    *) echo "\`$1\`" ;;
    esac
}

# replace DOC NAME FILE: FILE between "<!-- NAME -->" and "<!-- /NAME -->";
# both markers are checked first, so a missing one leaves DOC as it was.
replace() {
    host/replace-block.sh "$1" "$2" "$3" || exit 2
}

run_source() { # NAME: run the command that writes its source
    local cmd src
    cmd=$(field "$1" 3) src=$(field "$1" 2)
    mkdir -p "$L"
    case $cmd in
    suite*) make -s --no-print-directory BUILD="$BUILD" test-build >/dev/null
        BUILD=$BUILD tests/run.sh ${cmd#suite } ;;
    "make size") make -s --no-print-directory BUILD="$BUILD" size >/dev/null ;;
    "make cutoff") make -s --no-print-directory BUILD="$BUILD" cutoff ;;
    "make bench-ablation" | "make bench-lit-bound")
        make -s --no-print-directory BUILD="$BUILD" "${cmd#make }" >/dev/null ;;
    "make stress") make -s --no-print-directory BUILD="$BUILD" stress >/dev/null ;;
    "make fw "*) # a scene that does not fit: the command fails, its message is the source
        read -r -a args <<<"${cmd#make fw }"
        make -s --no-print-directory BUILD="$BUILD" "$BUILD/fxrt" "$BUILD/fxrt-scenec" >/dev/null
        make -s --no-print-directory BUILD="$BUILD" fw "${args[@]}" >"$src" 2>&1 && die "$1: $cmd fitted" || true ;;
    "make oracle") make -s --no-print-directory BUILD="$BUILD" "$BUILD/tests/oracle" >/dev/null
        # make oracle lists findings and exits non-zero while there are any.
        make -s --no-print-directory BUILD="$BUILD" oracle >"$src" 2>&1 || true ;;
    make*) make -s --no-print-directory BUILD="$BUILD" "${cmd#make }" >"$src" 2>&1 ;;
    esac
}

# ---- formatters: each reads its source on stdin and prints markdown ----

# key=value fields of an `fxrt compare` line
kv() { awk -v k="$1" '{ for (i = 1; i <= NF; i++) if (index($i, k "=") == 1) { print substr($i, length(k) + 2); exit } }' <<<"$2"; }
commas() { awk -v n="$1" 'BEGIN { s = sprintf("%d", n); while (s ~ /[0-9][0-9][0-9][0-9]/) sub(/[0-9][0-9][0-9]([^0-9]|$)/, ",&", s); print s }'; }

fmt_orbit() { # tests/examples.sh's log: each example's frames and report lines
    local log name what n sum min max x run elf
    log=$(cat)
    echo "| example on the micro:bit (Cortex-M0) | orbit | lit |"
    echo "|---|---:|---:|"
    declare -A row
    for name in orbit lit; do
        n=0 sum=0 min= max=
        while read -r x; do
            n=$((n + 1)) sum=$((sum + x))
            [[ -z $min || $x -lt $min ]] && min=$x
            [[ -z $max || $x -gt $max ]] && max=$x
        done < <(sed -nE "s/^$name frame=[0-9]+ instructions=([0-9]+)\$/\\1/p" <<<"$log")
        run=$(grep "^micro:bit $name: " <<<"$log" | tail -n 1)
        elf=$(grep "^micro:bit $name.elf: " <<<"$log" | tail -n 1)
        [[ $n -gt 0 && -n $run && -n $elf ]] || die "orbit: no frame counts or report lines for $name in the log"
        row[frames]+=" | $n"
        row[mean]+=" | $(commas "$(kv instructions_per_frame "$run")")"
        row[range]+=" | $(commas "$min") – $(commas "$max")"
        row[flash]+=" | $(commas "$(kv flash "$elf")") B"
        row[ram]+=" | $(commas "$(kv ram_static "$elf")") B"
        row[stack]+=" | $(commas "$(kv stack_used "$run")") of $(commas "$(kv stack_size "$run")") B"
    done
    echo "| frames${row[frames]} |"
    echo "| instructions per frame, mean (camera and render set-up included)${row[mean]} |"
    echo "| range over the frames${row[range]} |"
    echo "| flash (everything linked)${row[flash]} |"
    echo "| RAM, static (\`.data\` + \`.bss\`)${row[ram]} |"
    echo "| stack used (painted) of the reservation${row[stack]} |"
}

fmt_golden() {
    local log names name q f qc fc seed
    log=$(cat)
    names=$(sed -nE 's/^(abb[^ ]*) q16 vs double: .*/\1/p' <<<"$log" | grep -v -- '-colour$' | sort -V)
    [[ -n $names ]] || die "golden: no 'NAME q16 vs double:' lines in the log"
    echo "| scene | Q16.16 vs double: mismatched (interior) | float vs double | arbitrary colours: Q16.16 / float vs double | double vs the seed report's figure: mismatched % |"
    echo "|---|---:|---:|---:|---:|"
    for name in $names; do
        q=$(grep "^$name q16 vs double: " <<<"$log" | tail -n 1)
        f=$(grep "^$name float vs double: " <<<"$log" | tail -n 1)
        qc=$(grep "^$name-colour q16 vs double: " <<<"$log" | tail -n 1 || true)
        fc=$(grep "^$name-colour float vs double: " <<<"$log" | tail -n 1 || true)
        seed=$(grep "^$name double vs seed figure: " <<<"$log" | tail -n 1 || true)
        local colours=- fig=-
        [[ -n $qc && -n $fc ]] && colours="$(kv mismatched "$qc") / $(kv mismatched "$fc")"
        [[ -n $seed ]] && fig=$(kv mismatched_pct "$seed")
        echo "| $name | $(kv mismatched "$q") ($(kv interior_mismatched "$q")) | $(kv mismatched "$f") | $colours | $fig |"
    done
}

fmt_lit() {
    local log line n=0
    log=$(cat)
    echo "| scene | build | within 1/255 % | within 2/255 % | far within 2/255 % | far max | max | PSNR dB |"
    echo "|---|---|---:|---:|---:|---:|---:|---:|"
    while IFS= read -r line; do
        n=$((n + 1))
        set -- $line
        echo "| $1 | $2 | $(kv within1_pct "$line") | $(kv within2_pct "$line") | $(kv far_within2_pct "$line") |" \
            "$(kv far_max_err "$line") | $(kv max_err "$line") | $(kv psnr "$line") |"
    done < <(grep -E '^[^ ]+ (q16|float) vs double: ' <<<"$log")
    [[ $n -gt 0 ]] || die "lit: no 'NAME BUILD vs double:' lines in the log"
}

fmt_stress() { # PREFIX: the stress scenes PREFIX-*, q16 and float side by side
    local log names name q f
    log=$(cat)
    names=$(sed -nE "s/^($1-[^ ]*) q16 vs double: .*/\1/p" <<<"$log")
    [[ -n $names ]] || die "$1-stress: no '$1-* q16 vs double:' lines in the log"
    echo "| scene | q16 within 1/255 % | q16 far max | q16 PSNR dB | float within 1/255 % | float far max | float PSNR dB |"
    echo "|---|---:|---:|---:|---:|---:|---:|"
    for name in $names; do
        q=$(grep "^$name q16 vs double: " <<<"$log" | tail -n 1)
        f=$(grep "^$name float vs double: " <<<"$log" | tail -n 1 || true)
        local fl="- | - | -"
        [[ -n $f ]] && fl="$(kv within1_pct "$f") | $(kv far_max_err "$f") | $(kv psnr "$f")"
        echo "| $name | $(kv within1_pct "$q") | $(kv far_max_err "$q") | $(kv psnr "$q") | $fl |"
    done
}

fmt_trace() {
    local log line n=0
    log=$(cat)
    echo "| scene | build | samples | within 1/255 % | within 2/255 % | far within 2/255 % | max | PSNR dB |"
    echo "|---|---|---:|---:|---:|---:|---:|---:|"
    while IFS= read -r line; do
        n=$((n + 1))
        set -- $line
        echo "| $1 | $4 | $3 | $(kv within1_pct "$line") | $(kv within2_pct "$line") | $(kv far_within2_pct "$line") |" \
            "$(kv max_err "$line") | $(kv psnr "$line") |"
    done < <(grep -E '^[^ ]+ samples [0-9]+ (q16|float) vs double: ' <<<"$log")
    [[ $n -gt 0 ]] || die "trace: no 'NAME samples N BUILD vs double:' lines in the log"
}

fmt_cutoff() {
    local log line n=0
    log=$(cat)
    echo "| scene | build | pixels that differ | % | max (1/255) | PSNR dB |"
    echo "|---|---|---:|---:|---:|---:|"
    while IFS= read -r line; do
        n=$((n + 1))
        set -- $line
        echo "| $1 | ${2%,} | $(kv mismatched "$line") | $(kv mismatched_pct "$line") | $(kv max_err "$line") | $(kv psnr "$line") |"
    done < <(grep -E '^[^ ]+ [a-z0-9]+, cut-off vs none: ' <<<"$log")
    [[ $n -gt 0 ]] || die "cutoff: no 'NAME BUILD, cut-off vs none:' lines in the log"
}

fmt_norecurse() {
    local log
    log=$(cat)
    grep -qE '^[a-z0-9]+ -O[0-9s] stack: ' <<<"$log" || die "norecurse: no stack lines in the log"
    echo "| build | function | worst static stack | deepest chain (bytes per frame) |"
    echo "|---|---|---:|---|"
    sed -nE 's/^([a-z0-9]+ -O[0-9s]) stack: ([A-Za-z0-9_]+) ([0-9]+) (.*)$/| \1 | `\2` | \3 B | \4 |/p' <<<"$log"
}

fmt_oracle() {
    local log cover
    log=$(cat)
    cover=$(sed -nE 's/^oracle: random scenes: (.*)$/\1/p' <<<"$log" | tail -n 1)
    grep -qE '^oracle (q16|double): ' <<<"$log" || die "oracle: no 'oracle BUILD:' lines in the log"
    sed -nE 's/^oracle: ([0-9]+ scene files, .*)$/Run: \1./p' <<<"$log" | head -n 1
    echo
    echo "| build | frames | pixels compared | interior mismatches | band pixels | band mismatches |"
    echo "|---|---:|---:|---|---:|---|"
    sed -nE 's/^oracle (q16|double): ([0-9]+) frames, ([0-9]+) pixels compared, ([0-9]+) interior mismatches( \(not counting ([^)]*)\))?, ([0-9]+) band pixels, ([0-9]+) band mismatches \((.*)\)$/| \1 | \2 | \3 | \4 (not counted: \6) | \7 | \8 (\9) |/p' <<<"$log" | sed 's/ (not counted: )//' 
    [[ -z $cover ]] || { echo; echo "Random scenes drawn: $cover."; }
    grep -E '^oracle: [0-9]+ frames are known findings' <<<"$log" | sed -E 's/^oracle: /Known findings: /; s/$/./' | head -n 1 || true
}

fmt_diff() { # the summary tables test_diff prints, without its replay details
    awk '/^differential test/ { on = 1 }
         /^worst cases \(replay/ { exit }
         / passed, [0-9]+ failed$/ { exit }
         on { sub(/, [0-9.]+ s$/, ""); print }' | sed -e :a -e '/^\n*$/{$d;N;ba' -e '}'
}

fmt_fx() { # the worst error of each maths function, from test_fx's ERR lines
    local log
    log=$(cat)
    grep -q '^ERR ' <<<"$log" || die "fx: no 'ERR FUNCTION WORST' lines in the log"
    echo "| function | worst error measured (LSB) |"
    echo "|---|---|"
    sed -nE 's/^ERR ([a-z0-9_]+) (.*)$/\1 \2/p' <<<"$log" |
        sed -E 's/_of_\(1\+1e-7\|x\|\)/ of its bound (1 LSB + 1e-7 relative)/' |
        awk '{ f = $1; sub(/^[^ ]+ /, ""); gsub(/\|/, "\\|"); printf "| `%s` | %s |\n", f, $0 }'
}

fmt_fx_exhaustive() { # fx_exhaustive's summary lines, per code path
    local log
    log=$(cat)
    grep -qE '^fx_(sqrt|rsqrt|sin_deg):' <<<"$log" || die "fx-exhaustive: no summary lines in the log"
    echo '```'
    awk '/^  EXHAUST .*fx_exhaustive_nohw / { print "Cortex-M0 code path (no UDIV, CLZ or UMULL):"; next }
         /^  EXHAUST .*fx_exhaustive / { print "host and Armv7-M code path (UDIV, CLZ, UMULL):"; next }
         /^fx_exhaustive/ { next }
         /^(fx_|  first failure)/ { print "  " $0 }' <<<"$log"
    echo '```'
}

fmt_fit_message() { # the fit check's message, as the terminal shows it
    local log
    log=$(grep -vE '^(make|  [A-Z]+  )' || true)
    grep -q 'does not fit' <<<"$log" || die "fit-message: no 'does not fit' message in the log"
    echo '```'
    echo "\$ $(field fit-message 3)"
    sed -n '/does not fit/,$p' <<<"$log" | grep -E '^(scenes/|  )'
    echo '```'
}

fmt_core() { # tests/layers.sh's core-stats lines: the folders' table
    local log
    log=$(cat)
    grep -q '^core-stats: folder=' <<<"$log" || die "core: no core-stats lines in the log"
    echo "| folder | layer | files | lines | largest file | \`#if\` lines |"
    echo "|---|---|---:|---:|---|---:|"
    awk -v q='`' '
        BEGIN {
            what["."] = "configuration, error codes, public API header"
            what["port"] = "the target: architecture tests, inline assembly"
            what["math"] = "Q16.16, the number types, vectors, colours"
            what["scene"] = "cameras, the kinds of object, meshes, the world"
            what["vis"] = "the visibility pass"
            what["light"] = "the light sum, shadow rays, secondary rays"
            what["frame"] = "a frame'"'"'s passes, the public API'"'"'s entry points"
        }
        function commas(n,  s) { s = sprintf("%d", n); while (s ~ /[0-9][0-9][0-9][0-9]/) sub(/[0-9][0-9][0-9]($|,)/, ",&", s); return s }
        /^core-stats: folder=/ {
            for (i = 2; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] }
            name = v["folder"] == "." ? q "core/" q " (top)" : q "core/" v["folder"] "/" q
            big = v["largest"]; sub(/\(/, " (", big)
            printf "| %s | %s | %d | %s | %s | %d |\n", name, what[v["folder"]], v["files"], commas(v["lines"]), big, v["if_lines"]
            files += v["files"]; lines += v["lines"]; ifs += v["if_lines"]
        }
        /^core-stats: total_if_lines=/ { split($2, kv, "="); total = kv[2]; split($3, c, "="); cap = c[2] }
        END {
            printf "| all | | %d | %s | | %d |\n", files, commas(lines), ifs
            printf "\n%s lines count %s, %s, %s and %s, include guards among them; make test fails above %d.\n", q "#if" q, q "#if" q, q "#ifdef" q, q "#ifndef" q, q "#elif" q, cap
        }' <<<"$log"
}

fmt_table() { # the markdown table a command printed (its | lines, and the line before it)
    awk '/^\|/ { if (!t && prev != "") print prev "\n"; t = 1; print; next } { prev = $0 }' | grep -v '^\[' || true
}

format() { # NAME < source
    case $1 in
    orbit) fmt_orbit ;;
    core) fmt_core ;;
    golden) fmt_golden ;;
    oracle | oracle-sweep) fmt_oracle ;;
    diff | stress) fmt_diff ;;
    bounce-growth | adaptive-error) fmt_table ;;
    lit) fmt_lit ;;
    lit-stress) fmt_stress lit ;;
    trace) fmt_trace ;;
    trace-stress) fmt_stress trace ;;
    cutoff) fmt_cutoff ;;
    norecurse) fmt_norecurse ;;
    size | ablation | lit-bound) cat ;;
    fit-message) fmt_fit_message ;;
    fx) fmt_fx ;;
    fx-exhaustive) fmt_fx_exhaustive ;;
    *) die "no formatter for $1" ;;
    esac
}

block() { # NAME: the block's whole text
    local name=$1 src cmd body
    src=$(field "$name" 2) cmd=$(shown "$(field "$name" 3)")
    body=$(format "$name" <"$src") || return 1
    [[ -n $body ]] || die "$name: nothing to show from $src"
    echo "Generated from the output of $cmd by \`make doc-blocks DOC_BLOCKS=$name DOCS_UPDATE=1\`"
    echo "(host/docblocks.sh), at commit $rev. Do not edit by hand."
    echo
    echo "$body"
}

case ${1:-} in
--list) for b in "${blocks[@]}"; do IFS='|' read -r n p s c <<<"$b"; printf '%-15s %-18s %-36s %s\n' "$n" "$p" "$s" "$(shown "$c")"; done; exit 0 ;;
--names) for b in "${blocks[@]}"; do echo "${b%%|*}"; done; exit 0 ;;
replace) [[ $# -eq 4 ]] || die "usage: host/docblocks.sh replace DOC NAME FILE"; replace "$2" "$3" "$4"; exit 0 ;;
-*) die "unknown option $1" ;;
esac

# The commit the blocks are generated at, taken once, before any page is
# rewritten (the rewrites themselves would mark the tree as changed).
rev=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
[[ -n $(git status --porcelain --untracked-files=no 2>/dev/null) ]] && rev="$rev (with uncommitted changes)"

names=("$@")
[[ ${#names[@]} -gt 0 ]] || mapfile -t names < <(for b in "${blocks[@]}"; do echo "${b%%|*}"; done)
missing=0
tmp=$(mktemp)
trap 'rm -f "$tmp"' EXIT
for name in "${names[@]}"; do
    field "$name" 1 >/dev/null
    [[ ${DOC_RUN:-0} == 1 ]] && run_source "$name"
    src=$(field "$name" 2)
    if [[ ! -s $src ]]; then
        echo "docblocks: $name: no $src; run $(shown "$(field "$name" 3)" | tr -d '\`') (or DOC_RUN=1) first; block left as it is" >&2
        missing=$((missing + 1))
        continue
    fi
    block "$name" >"$tmp"
    echo "<!-- $name -->"
    cat "$tmp"
    echo "<!-- /$name -->"
    echo
    if [[ ${DOCS_UPDATE:-0} == 1 ]]; then
        replace "$(field "$name" 1)" "$name" "$tmp"
        echo "docblocks: updated $name in $(field "$name" 1)" >&2
    fi
done
[[ $missing -eq 0 ]] || echo "docblocks: $missing block(s) without a source" >&2
