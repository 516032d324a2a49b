#!/usr/bin/env bash
# Tables, Pareto fronts and plots from build/frontier/frontier.csv (called by
# firmware/frontier.sh; environment from there: OUT SIZE BOARDS ELAPSED TOTAL
# JOBS BUILDS SAMPLES BOARD_INFO). Writes OUT/frontier.md (everything),
# OUT/section.md (the Frontier section of docs/BENCHMARKS.md),
# OUT/frontier-BOARD.png; with FRONTIER_UPDATE_DOCS=1 or BENCH_UPDATE_DOCS=1
# copies them to docs/frontier/ and docs/BENCHMARKS.md.
set -euo pipefail
csv=$OUT/frontier.csv
rev=${BENCH_REV:-$(git rev-parse --short HEAD 2>/dev/null || echo unknown)}
[[ -z ${BENCH_REV:-} && -n $(git status --porcelain --untracked-files=no 2>/dev/null) ]] && rev="$rev (with uncommitted changes)"
BUDGETS=${FRONTIER_BUDGETS:-"2 1 0.5 0.25"}

awk -F, -v out="$OUT" -v size="$SIZE" -v boards="$BOARDS" -v builds="$BUILDS" -v samples="$SAMPLES" -v budgets="$BUDGETS" '
function add(list, v) { if (!((list, v) in seen)) { seen[list, v] = 1; order[list, ++cnt[list]] = v } }
function sname(s) { return s ~ /a$/ ? substr(s, 1, length(s) - 1) " adaptive" : s }
function bname(n, l) { return n (l == "fast" ? "" : " " l) }
function psv(p) { return p == "inf" ? 99 : p + 0 }
NR == 1 { next }
{ kind = $1; sc = $2; sm = $3; b = $4; n = $6; l = $7; st = $8
  k = kind SUBSEP sc SUBSEP sm SUBSEP b SUBSEP n SUBSEP l
  S[k] = st; INS[k] = $9; IPP[k] = $10; MAE[k] = $11; PS[k] = $12; W1[k] = $13; ME[k] = $14
  SU[k] = $15; SS[k] = $16; ID[k] = $17; AK[k] = $18; NOTE[k] = $19; CPI[k] = $20; CPP[k] = $21; CPU[b] = $5
  if (kind == "frontier") add("s", sc); else add("st", sc)
  rows[++nr] = $0 }
END {
  nb = split(boards, B, " "); nbu = split(builds, BU, " "); nsm = split(samples, SM, " "); nbg = split(budgets, BG, " ")
  md = out "/frontier.md"; sec = out "/section.md"
  # per board: common scenes = ok for every build and sample setting
  for (i = 1; i <= nb; i++) { b = B[i]; cs = ""; ncs = 0; ex = ""
    for (q = 1; q <= cnt["s"]; q++) { sc = order["s", q]; good = 1; why = ""
      for (j = 1; j <= nbu; j++) { split(BU[j], nl, ":"); for (m = 1; m <= nsm; m++) {
        k = "frontier" SUBSEP sc SUBSEP SM[m] SUBSEP b SUBSEP nl[1] SUBSEP nl[2]
        if (!(k in S)) { good = 0; if (why == "") why = "not run" } else if (S[k] != "ok") { good = 0; w = bname(nl[1], nl[2]) " samples " sname(SM[m]) ": " S[k]; if (why !~ /^.*\(/) why = why (why ? "; " : "") w } } }
      if (good) { ncs++; common[b, ncs] = sc } else ex = ex (ex ? "; " : "") sc " (" why ")" }
    NCS[b] = ncs; EXCL[b] = ex }
  # aggregates
  for (i = 1; i <= nb; i++) { b = B[i]; np[b] = 0
    for (j = 1; j <= nbu; j++) { split(BU[j], nl, ":"); for (m = 1; m <= nsm; m++) {
      g = 0; gc = 0; kc = 0; ma = 0; mw = 0; wmae = 0; p = 0; w1 = 0; c = NCS[b]
      for (q = 1; q <= c; q++) { k = "frontier" SUBSEP common[b, q] SUBSEP SM[m] SUBSEP b SUBSEP nl[1] SUBSEP nl[2]
        g += log(IPP[k]); ma += MAE[k]; if (CPP[k] != "") { gc += log(CPP[k]); kc++ } if (MAE[k] + 0 > wmae) wmae = MAE[k] + 0; p += psv(PS[k]); w1 += W1[k] }
      if (c == 0) continue
      P = ++np[b]; PN[b, P] = nl[1]; PL[b, P] = nl[2]; PSM[b, P] = SM[m]
      PX[b, P] = exp(g / c); PC[b, P] = kc == c ? sprintf("%.0f", exp(gc / c)) : "n/a"; PY[b, P] = ma / c; PW[b, P] = wmae; PP[b, P] = p / c; P1[b, P] = w1 / c } }
    # Pareto front: no other point has <= instructions and <= error with one strictly less
    for (P = 1; P <= np[b]; P++) { fr[b, P] = 1
      for (Q = 1; Q <= np[b]; Q++) if (Q != P && PX[b, Q] <= PX[b, P] && PY[b, Q] <= PY[b, P] && (PX[b, Q] < PX[b, P] || PY[b, Q] < PY[b, P])) { fr[b, P] = 0; break } }
    dat = out "/frontier-" b ".dat"; fdat = out "/frontier-" b ".front"; printf "" > dat; printf "" > fdat
    for (P = 1; P <= np[b]; P++) { printf "%s %s %s %.6g %.6g \"%s s%s\"\n", PN[b, P], PL[b, P], PSM[b, P], PX[b, P], PY[b, P], PN[b, P], sname(PSM[b, P]) > dat
      if (fr[b, P]) printf "%s %s %s %.6g %.6g\n", PN[b, P], PL[b, P], PSM[b, P], PX[b, P], PY[b, P] > fdat }
    close(dat); close(fdat) }

  for (f = 1; f <= 2; f++) { o = f == 1 ? md : sec
    for (i = 1; i <= nb; i++) { b = B[i]
      printf "#### %s (Cortex-%s)\n\n", b, CPU[b] > o
      if (NCS[b] == 0) { printf "No scene ran in every configuration on this board.%s\n\n", (EXCL[b] ? " Left out: " EXCL[b] "." : "") > o; continue }
      sl = ""; for (q = 1; q <= NCS[b]; q++) sl = sl (q > 1 ? ", " : "") common[b, q]
      printf "Over %d scene(s): %s.%s\n\n", NCS[b], sl, (EXCL[b] ? " Left out (a configuration did not run): " EXCL[b] "." : "") > o
      print "| build | samples | instr/pixel (geo. mean) | est. cycles/pixel (geo. mean) | MAE /255 (mean) | MAE worst scene | PSNR dB (mean) | within 1/255 % (mean) | front |" > o
      print "|---|---|---:|---:|---:|---:|---:|---:|---|" > o
      for (P = 1; P <= np[b]; P++) printf "| %s | %s | %.0f | %s | %.3f | %.3f | %.2f | %.2f | %s |\n", bname(PN[b, P], PL[b, P]), sname(PSM[b, P]), PX[b, P], PC[b, P], PY[b, P], PW[b, P], PP[b, P], P1[b, P], fr[b, P] ? "**yes**" : "" > o
      print "" > o
      print "Pick for an error budget (mean MAE over these scenes, against the converged image; the cheapest measured configuration within it):\n" > o
      print "| MAE budget | pick | instr/pixel | est. cycles/pixel | MAE | cheapest q16 within | cheapest float within | cheapest double within |" > o
      print "|---|---|---:|---:|---:|---|---|---|" > o
      for (g = 1; g <= nbg; g++) { bud = BG[g] + 0; best = 0; delete bn
        for (P = 1; P <= np[b]; P++) if (PY[b, P] <= bud) {
          if (!best || PX[b, P] < PX[b, best]) best = P
          if (!(PN[b, P] in bn) || PX[b, P] < PX[b, bn[PN[b, P]]]) bn[PN[b, P]] = P }
        line = ""
        split("q16 float double", NN, " ")
        for (t = 1; t <= 3; t++) line = line " | " ((NN[t] in bn) ? sprintf("samples %s: %.0f (cycles %s)", sname(PSM[b, bn[NN[t]]]), PX[b, bn[NN[t]]], PC[b, bn[NN[t]]]) : "none")
        if (!best) printf "| <= %s | none measured | | | %s |\n", BG[g], line > o
        else printf "| <= %s | **%s, samples %s** | %.0f | %s | %.3f%s |\n", BG[g], bname(PN[b, best], PL[b, best]), sname(PSM[b, best]), PX[b, best], PC[b, best], PY[b, best], line > o }
      print "" > o } }

  # q16 identity, failures, stack -> both files
  for (f = 1; f <= 2; f++) { o = f == 1 ? md : sec
    print "#### Firmware q16 frame against the host q16 render (byte for byte)\n" > o
    print "| board | q16 runs | identical | DIFFERENT |" > o; print "|---|---:|---:|---|" > o
    for (i = 1; i <= nb; i++) { b = B[i]; t = 0; y = 0; dl = ""
      for (r = 1; r <= nr; r++) { split(rows[r], x, ","); if (x[4] != b || x[6] != "q16" || x[8] != "ok") continue
        t++; if (x[17] == "yes") y++; else dl = dl (dl ? ", " : "") x[2] " s" x[3] }
      printf "| %s | %d | %d | %s |\n", b, t, y, (dl == "" ? "none" : "**" dl "**") > o }
    print "" > o
    nf = 0; for (r = 1; r <= nr; r++) { split(rows[r], x, ","); if (x[8] != "ok") nf++ }
    print "#### Runs that did not complete\n" > o
    if (!nf) print "None.\n" > o
    else { print "| scene | samples | board | build | status | stack_used / size | note |" > o; print "|---|---|---|---|---|---|---|" > o
      for (r = 1; r <= nr; r++) { split(rows[r], x, ","); if (x[8] == "ok") continue
        printf "| %s%s | %s | %s | %s | %s | %s | %s |\n", x[1] == "stack" ? "" : "", x[2], sname(x[3]), x[4], bname(x[6], x[7]),
          (x[8] == "nofit" ? "does not fit" : x[8] == "stack" ? "stack margin exceeded" : x[8] == "fault" ? "HardFault" : "FAILED"),
          (x[15] == "" ? "-" : x[15] " / " x[16]), x[19] > o }
      print "" > o }
    print "#### Stack use (stack_used= of the firmware, bytes)\n" > o
    print "The deepest scenes at " size ", their own depth and samples. The stack is 8 KB on the MPS2 boards and 2 KB on the micro:bit (linker/*.ld); the firmware refuses a frame that leaves less than FXRT_STACK_MARGIN (512) bytes unused.\n" > o
    hdr = "| scene | build |"; sep = "|---|---|"
    for (i = 1; i <= nb; i++) { hdr = hdr " " B[i] " (" CPU[B[i]] ") |"; sep = sep "---:|" }
    print hdr > o; print sep > o
    for (q = 1; q <= cnt["st"]; q++) { sc = order["st", q]
      for (j = 1; j <= nbu; j++) { split(BU[j], nl, ":"); line = "| " substr(sc, 7) " | " bname(nl[1], nl[2]) " |"
        for (i = 1; i <= nb; i++) { k = "stack" SUBSEP sc SUBSEP "own" SUBSEP B[i] SUBSEP nl[1] SUBSEP nl[2]
          v = !(k in S) ? "-" : S[k] == "ok" ? SU[k] : S[k] == "stack" ? SU[k] " (margin exceeded)" : S[k] == "fault" ? "HardFault" SU[k] : S[k] == "nofit" ? "does not fit" : "failed"
          if ((k in S) && S[k] == "fault") v = "HardFault" (SU[k] != "" ? " (" SU[k] ")" : " (stack overflow?)")
          line = line " " v " |" }
        print line > o } }
    # glass at every sample setting, from the frontier runs
    for (m = 1; m <= nsm; m++) for (j = 1; j <= nbu; j++) { split(BU[j], nl, ":"); line = "| glass, samples " sname(SM[m]) " | " bname(nl[1], nl[2]) " |"; any = 0
      for (i = 1; i <= nb; i++) { k = "frontier" SUBSEP "glass" SUBSEP SM[m] SUBSEP B[i] SUBSEP nl[1] SUBSEP nl[2]
        v = !(k in S) ? "-" : S[k] == "ok" ? SU[k] : S[k] == "stack" ? SU[k] " (margin exceeded)" : S[k] == "fault" ? "HardFault" : S[k] == "nofit" ? "does not fit" : "failed"
        if (k in S) any = 1; line = line " " v " |" }
      if (any && f == 1) print line > o }
    print "" > o }

  # all runs (frontier.md only)
  print "#### Every run\n" > md
  print "| scene | samples | board | build | status | instructions | instr/pixel | CPI | est. cycles/pixel | MAE /255 | PSNR dB | within 1/255 % | max_err | stack_used | q16 == host | all-kinds |" > md
  print "|---|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---|" > md
  for (r = 1; r <= nr; r++) { split(rows[r], x, ",")
    printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", x[2], sname(x[3]), x[4], bname(x[6], x[7]), x[8], x[9], x[10], (x[20] == "" ? "-" : x[20]), (x[21] == "" ? "-" : x[21]), x[11], x[12], x[13], x[14], x[15], (x[17] == "NO" ? "**NO**" : x[17]), (x[18] == 1 ? "yes" : "") > md }
  print "" > md
}' "$csv"

# Plots
plots=()
for b in $BOARDS; do
    [[ -s $OUT/frontier-$b.dat ]] || continue
    cpu=$(for i in $BOARD_INFO; do [[ ${i%%:*} == "$b" ]] && cut -d: -f2 <<<"$i"; done; true)
    sort -t' ' -k4,4g "$OUT/frontier-$b.front" -o "$OUT/frontier-$b.front"
    gnuplot -e "data='$OUT/frontier-$b.dat'; front='$OUT/frontier-$b.front'; out='$OUT/frontier-$b.png'; board='$b (Cortex-$cpu)'; size='$SIZE'" \
        firmware/frontier.gp || { echo "frontier: gnuplot failed for $b" >&2; exit 1; }
    plots+=("frontier-$b.png")
done

intro() { # PLOTDIR
    echo "Regenerate with \`make frontier FRONTIER_UPDATE_DOCS=1\` (or \`make bench BENCH_UPDATE_DOCS=1\`). Last run"
    echo "$(date -u '+%Y-%m-%d %H:%M UTC'), commit $rev; $(qemu-system-arm --version | head -n 1), arm-none-eabi-gcc $(arm-none-eabi-gcc -dumpversion);"
    echo "$TOTAL runs in ${ELAPSED} s at $SIZE ($JOBS in parallel). Instructions are QEMU \`-icount\` counts; cycles are estimates:"
    if [[ ${CSIZE:-none} == none || ! -s $csv ]] || ! head -n 1 "$csv" | grep -q cycles_per_pixel; then echo "none in this run."
    else echo "each run's CPI, priced at $CSIZE by \`firmware/cycles.sh\` (docs/BENCHMARKS.md, \"Cycles\"), times its instructions."; fi
    echo
    echo "Error is against the **converged image**: the host double render of the same scene at $SIZE with"
    echo "\`samples 16\` (16x16 rays per pixel). MAE = mean absolute error per channel in 1/255 units (\`fxrt"
    echo "compare\`'s \`mae=\`), PSNR over all channels, within 1/255 = share of pixels whose every channel is within 1/255."
    echo "Per board the figures are averaged over the scenes that ran in every configuration on it (instructions"
    echo "per pixel: geometric mean; errors: arithmetic mean). The front: points no other point beats on both axes."
    echo
    local p
    for p in "${plots[@]}"; do echo "![${p%.png}]($1$p)"; done
    echo
}
{
    echo "# fxrt frontier ($SIZE)"
    echo
    intro ""
    cat "$OUT/frontier.md"
} >"$OUT/frontier-full.md"
{ intro "frontier/"; cat "$OUT/section.md"; echo "All runs: [docs/frontier/FRONTIER.md](frontier/FRONTIER.md)."; } >"$OUT/doc-section.md"

if [[ ${FRONTIER_UPDATE_DOCS:-${BENCH_UPDATE_DOCS:-0}} == 1 ]]; then
    doc=docs/BENCHMARKS.md
    host/replace-block.sh "$doc" frontier "$OUT/doc-section.md" || exit 1
    mkdir -p docs/frontier
    rm -f docs/frontier/frontier-*.png
    for p in "${plots[@]}"; do cp "$OUT/$p" docs/frontier/; done
    cp "$OUT/frontier.csv" docs/frontier/frontier.csv
    cp "$OUT/frontier-full.md" docs/frontier/FRONTIER.md
    echo "frontier: updated $doc and docs/frontier/" >&2
fi
grep -c ',NO,' "$csv" >/dev/null && echo "frontier: WARNING: a q16 firmware frame differs from the host q16 render (see the identity table)" >&2
echo "frontier: $TOTAL runs in $ELAPSED s; wrote $OUT/frontier.csv, $OUT/frontier-full.md, $OUT/frontier-*.png" >&2
