# cycles.awk: estimated cycles of a QEMU run, from its log of translated
# blocks and executions (qemu-system-arm -d in_asm,exec,nochain), each
# instruction priced by its class with the cycle counts of the core's
# technical reference manual (docs/BENCHMARKS.md, "Cycles"). Each price is
# a range, low..high (a multiply's early termination, a branch's pipeline
# refill of 1 to 3 cycles, a load that pipelines after another); the
# estimate is the middle of the range.
#   awk -v core=m0|m3|m4 -f firmware/cycles.awk q.log
# Prints, one line per class and a total:
#   class=NAME count=N low=L high=H
#   total instructions=N low=L high=H estimate=E cpi=C
# A conditional branch is taken when the next block executed does not
# start right after it (the log holds every execution: nochain).
# With -v marks="ADDR ...", the addresses of marker functions (0x...), the
# counts are split into segments at each execution of a marker's first
# block: segment k runs from the k-th marker execution to the next, and
# each prints as
#   segment=K instructions=N low=L high=H estimate=E
# With -v blocks=FILE, FILE gets one line per translated block start,
#   ADDR instructions low high
# its executions' totals (firmware/profile.sh sums them per function).

function price(cls, kind) {
    # kind 0: low, 1: high
    return kind ? PH[cls] : PL[cls]
}
function set(cls, lo, hi) { PL[cls] = lo; PH[cls] = hi }
function hex(h,   i, v, c) {
    v = 0; h = tolower(h); sub(/^0x/, "", h)
    for (i = 1; i <= length(h); i++) { c = index("0123456789abcdef", substr(h, i, 1)) - 1; v = v * 16 + c }
    return v
}
function nregs(ops,   s, n, i, parts, a, b, ab, cnt) {
    # registers in a list {r4, r5, lr} or {r4-r7}
    s = ops; sub(/^[^{]*\{/, "", s); sub(/\}.*$/, "", s)
    n = split(s, parts, /, */)
    cnt = 0
    for (i = 1; i <= n; i++) {
        if (parts[i] ~ /-/) {
            split(parts[i], ab, "-"); a = ab[1]; b = ab[2]
            gsub(/[^0-9]/, "", a); gsub(/[^0-9]/, "", b)
            cnt += (b - a + 1)
        } else if (parts[i] != "") {
            cnt++
        }
    }
    return cnt
}
# The class of one instruction: its mnemonic (without condition and
# width suffixes where they do not change the price) and operands.
function classify(m, ops,   base) {
    base = m
    sub(/\.(w|n)$/, "", base)
    if (base ~ /^v/) {
        if (base ~ /^v(div|sqrt)/) return "fp_div"
        if (base ~ /^v(n?ml[as]|fn?m[as])/) return "fp_mac"
        if (base ~ /^v(ldm|stm|push|pop)/) return "fp_ldm"
        if (base ~ /^v(ldr|str)/) return "fp_ldr"
        return "fp"
    }
    if (base ~ /^(smull|umull)/) return "mull"
    if (base ~ /^(smlal|umlal)/) return "mlal"
    if (base ~ /^(sdiv|udiv)/) return "div"
    if (base ~ /^(mla|mls)/) return "mla"
    if (base ~ /^muls?$/ || base ~ /^mul(eq|ne|cs|cc|mi|pl|hs|lo|hi|ls|ge|lt|gt|le)$/) return "mul"
    if (base ~ /^pop/ && ops ~ /pc/) { NREG = nregs(ops); return "pop_pc" }
    if (base ~ /^(pop|ldm)/) { NREG = nregs(ops); return "ldm" }
    if (base ~ /^(push|stm)/) { NREG = nregs(ops); return "stm" }
    if (base ~ /^ldrd/ || base ~ /^strd/) return "ldrd"
    if (base ~ /^ldr/ && ops ~ /^pc,/) return "ldr_pc"
    if (base ~ /^ldr/) return "ldr"
    if (base ~ /^str/) return "str"
    if (base ~ /^(cbz|cbnz)$/) return "bcond"
    if (base ~ /^bl$/ || base ~ /^blx$/) return "bl"
    if (base ~ /^bx$/) return "bx"
    if (base ~ /^b$/) return "b"
    if (base ~ /^b(eq|ne|cs|cc|mi|pl|vs|vc|hi|ls|ge|lt|gt|le|hs|lo)$/) return "bcond"
    if (base ~ /^it/) return "it"
    if (base ~ /^tb[bh]$/) return "tb"
    if (base ~ /^(mov|add)/ && ops ~ /^pc,/) return "bx"
    return "alu"
}
BEGIN {
    # Per core: low and high cycles per class. ldm/stm/pop_pc and fp_ldm
    # add one per register (N) below.
    set("alu", 1, 1); set("it", 0, 1)
    set("ldr", 1, 2); set("str", 1, 2); set("ldrd", 3, 3); set("ldr_pc", 3, 5); set("tb", 3, 5)
    set("ldm", 1, 1); set("stm", 1, 1)
    set("b", 2, 4); set("bl", 2, 4); set("bx", 2, 4); set("pop_pc", 2, 4)
    set("bcond_taken", 2, 4); set("bcond_not", 1, 1)
    set("mul", 1, 1); set("mla", 2, 2); set("mull", 3, 5); set("mlal", 4, 7); set("div", 2, 12)
    set("fp", 1, 1); set("fp_mac", 3, 3); set("fp_div", 14, 14); set("fp_ldr", 2, 2); set("fp_ldm", 1, 1)
    if (core == "m0") {
        # Cortex-M0: no pipelined loads; a taken branch 3, BL 4, a pop
        # that loads pc 3 + N or 4 + N (N with pc or without: the manual's
        # count is read both ways); the nRF51's single-cycle multiplier.
        set("ldr", 2, 2); set("str", 2, 2); set("ldr_pc", 5, 5)
        set("b", 3, 3); set("bl", 4, 4); set("bx", 3, 3); set("pop_pc", 3, 4)
        set("bcond_taken", 3, 3); set("it", 1, 1)
    } else if (core == "m4") {
        # Cortex-M4: 64-bit products and accumulates in one cycle.
        set("mull", 1, 1); set("mlal", 1, 1); set("mla", 1, 1)
    } else if (core != "m3") {
        print "cycles.awk: core must be m0, m3 or m4" > "/dev/stderr"; exit 2
    }
    nm = split(marks, mk, " ")
    for (i = 1; i <= nm; i++) MARK[sprintf("0x%08x", hex(mk[i]))] = 1
}
# The counts so far: C (per class) and REGS (registers of ldm, stm,
# pop_pc, fp_ldm) hold the folded blocks; E[pc] counts the executions of
# block pc not folded yet. A block is folded (its executions times its
# per-class counts) when it is translated again, at a marker, and at the
# end, so that each execution line costs one counter.
function fold(pc,   j, c) {
    if (!E[pc]) return
    for (j = 1; j <= B_k[pc]; j++) {
        c = B_c[pc, j]
        C[c] += E[pc] * B_m[pc, j]
        REGS[c] += E[pc] * B_r[pc, j]
        if (blocks != "") {
            XN[pc] += E[pc] * B_m[pc, j]
            XL[pc] += E[pc] * (B_m[pc, j] * PL[c] + B_r[pc, j])
            XH[pc] += E[pc] * (B_m[pc, j] * PH[c] + B_r[pc, j])
        }
    }
    E[pc] = 0
}
# a conditional branch at the end of block pc, taken or not
function branch(pc, c) {
    C[c]++
    if (blocks != "") { XN[pc]++; XL[pc] += PL[c]; XH[pc] += PH[c] }
}
function fold_all(   pc) { for (pc in E) fold(pc) }
function sums(   cl) {
    fold_all(); SL = 0; SH = 0; SN = 0
    for (cl in C) { SL += C[cl] * PL[cl] + REGS[cl]; SH += C[cl] * PH[cl] + REGS[cl]; SN += C[cl] }
}
function seg_close() {
    if (seg == 0) return
    sums()
    printf "segment=%d instructions=%d low=%d high=%d estimate=%d\n", seg, SN - S_n, SL - S_lo, SH - S_hi, (SL - S_lo + SH - S_hi) / 2
}
function seg_open() { sums(); S_lo = SL; S_hi = SH; S_n = SN; seg++ }
# A block's instructions as per-class counts B_c/B_m/B_r (class, count,
# registers), k = 1..B_k; a conditional branch that ends the block is left
# out (B_end: taken or not is known at the next execution line), one inside
# it fell through.
function block_add(start, cls, nr,   j) {
    for (j = 1; j <= B_k[start]; j++) if (B_c[start, j] == cls) break
    if (j > B_k[start]) { B_k[start] = j; B_c[start, j] = cls; B_m[start, j] = 0; B_r[start, j] = 0 }
    B_m[start, j]++; B_r[start, j] += nr
}
/^IN:/ { inb = 1; start = ""; next }
inb && /^0x[0-9a-f]+:/ {
    addr = substr($1, 1, length($1) - 1)
    # the encoding: one or two groups of 4 hex digits
    size = 2; f = 3
    if ($3 ~ /^[0-9a-f][0-9a-f][0-9a-f][0-9a-f]$/) { size = 4; f = 4 }
    m = $f; ops = ""
    for (i = f + 1; i <= NF; i++) ops = ops (i > f + 1 ? " " : "") $i
    NREG = 0
    cls = classify(m, ops)
    if (start == "") {
        start = addr
        # translated again (QEMU may cut a block short): fold the old one
        if (start in B_k) fold(start)
        B_k[start] = 0
    }
    if (last_bc) block_add(start, "bcond_not", 0) # (not at the block's end: fell through)
    last_bc = 0
    if (cls == "bcond") last_bc = 1
    else block_add(start, cls, cls == "ldm" || cls == "stm" || cls == "pop_pc" || cls == "fp_ldm" ? NREG : 0)
    B_end[start] = last_bc
    B_next[start] = sprintf("0x%08x", hex(addr) + size)
    next
}
inb && /^$/ { inb = 0; last_bc = 0; next }
/^Trace / {
    i = index($4, "/"); pc = "0x" substr($4, i + 1, 8)
    # the block before: its conditional branch taken or not
    if (pend != "") {
        branch(pend, pc == pend_next ? "bcond_not" : "bcond_taken")
        pend = ""
    }
    if (nm && (pc in MARK)) { seg_close(); seg_open() }
    if (!(pc in B_k)) { unknown++; next }
    E[pc]++
    if (B_end[pc]) { pend = pc; pend_next = B_next[pc] }
    next
}
END {
    if (pend != "") branch(pend, "bcond_not")
    seg_close()
    fold_all()
    if (blocks != "") for (pc in XN) printf "%s %d %d %d\n", pc, XN[pc], XL[pc], XH[pc] > blocks
    tot = 0; lo = 0; hi = 0
    for (cl in C) {
        l = C[cl] * PL[cl] + REGS[cl]; h = C[cl] * PH[cl] + REGS[cl]
        printf "class=%s count=%d low=%d high=%d\n", cl, C[cl], l, h
        tot += C[cl]; lo += l; hi += h
    }
    est = (lo + hi) / 2
    printf "total instructions=%d low=%d high=%d estimate=%d cpi=%.3f\n", tot, lo, hi, est, tot ? est / tot : 0
    if (unknown) printf "cycles.awk: %d executions of blocks never translated in the log\n", unknown > "/dev/stderr"
}
