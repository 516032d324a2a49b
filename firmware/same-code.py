#!/usr/bin/env python3
"""Normalised disassembly of an ELF's functions, one file per function
(firmware/same-code.sh): addresses and literal-pool words removed; a
branch into the function itself becomes <.+OFFSET>, any other target the
name of the function that holds it (FUNC symbols only: objdump may name an
address after an absolute symbol such as STACK_SIZE).
  same-code.py ELF DIR [RENAMES]"""
import bisect, os, re, subprocess, sys

elf, out = sys.argv[1], sys.argv[2]
ren = {}
if len(sys.argv) > 3 and sys.argv[3]:
    for line in open(sys.argv[3]):
        w = line.split()
        if len(w) == 2:
            ren[w[0]] = w[1]
funcs = []  # (start, size, name)
for line in subprocess.run(['arm-none-eabi-readelf', '-sW', elf], capture_output=True, text=True).stdout.splitlines():
    w = line.split()
    if len(w) >= 8 and w[3] == 'FUNC':
        funcs.append(((int(w[1], 16) & ~1), int(w[2]), w[7]))
funcs.sort()
starts = [f[0] for f in funcs]
byname = {f[2]: f for f in funcs}

def holder(addr):
    i = bisect.bisect_right(starts, addr) - 1
    if i >= 0 and funcs[i][0] <= addr < funcs[i][0] + max(funcs[i][1], 1):
        return funcs[i]
    return None

os.makedirs(out, exist_ok=True)
cur, start, size, fh = None, 0, 0, None
body = []


def flush():
    """Write the function's lines, without the alignment padding at its end
    (zero halfwords, shown as movs r0, r0)."""
    while body and body[-1] in ('movs\tr0, r0', 'nop'):
        body.pop()
    if fh:
        fh.write(''.join(line + '\n' for line in body))
        fh.close()
    body.clear()


dis = subprocess.run(['arm-none-eabi-objdump', '-d', '--no-show-raw-insn', elf], capture_output=True, text=True).stdout
for line in dis.splitlines():
    m = re.match(r'^([0-9a-f]+) <([^>]+)>:$', line)
    if m:
        name = m.group(2)
        flush()
        fh = None
        if name in byname:
            cur, start, size = name, byname[name][0], byname[name][1]
            fh = open(os.path.join(out, ren.get(name, name)), 'w')
        continue
    m = re.match(r'^\s*[0-9a-f]+:\t(.*)$', line)
    if not m or not fh:
        continue
    ins = m.group(1)
    if re.match(r'\.(word|short|byte)', ins):
        continue
    ins = re.sub(r'\s*[;@].*$', '', ins)
    def target(mm):
        a = int(mm.group(1), 16)
        if start <= a < start + size:
            return '<.+0x%x>' % (a - start)
        h = holder(a)
        if h:
            return '<%s%s>' % (ren.get(h[2], h[2]), '' if a == h[0] else '+0x%x' % (a - h[0]))
        return '<?>'
    ins = re.sub(r'\b([0-9a-f]+) <[^>]*>', target, ins)
    body.append(ins)
flush()
