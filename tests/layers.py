#!/usr/bin/env python3
"""The core's layers, checked from its #include lines and from its object
files' symbols (tests/layers.sh). docs/ARCHITECTURE.md has the picture.

  layers.py CORE_DIR [OBJ_DIR]

Layers, lowest first: the configuration and error codes (fxrt_config.h,
fxrt_err.h) with port/ (the target), math/, scene/, then vis/ and light/ side by side, then
frame/ with the public API (fxrt.h). A file may include, and a translation
unit may call into, its own layer and the layers below it; vis/ and light/
may not use each other. No two headers include each other, directly or
through others, and no two translation units call each other, directly or
through others (OBJ_DIR holds one .o per core source, named as the source
with '/' turned into '_': nm's defined and undefined symbols give the
calls).

Prints one line per violation ("include: A -> B (why)", "call: A -> B
(symbol)", "cycle: A -> B -> ... -> A") and a summary; exits 1 on any."""
import os
import re
import subprocess
import sys

RANK = {'': 0, 'port': 0, 'math': 2, 'scene': 3, 'vis': 4, 'light': 4, 'frame': 5}
SIBLINGS = {('vis', 'light'), ('light', 'vis')}


def layer_of(rel):
    """'vis/forms.h' -> 'vis'; 'fxrt_config.h' -> ''; 'fxrt.h' -> 'api'."""
    if '/' in rel:
        return rel.split('/')[0]
    return 'api' if rel == 'fxrt.h' else ''


def rank(layer):
    return 5 if layer == 'api' else RANK.get(layer, -1)


def allowed(src, dst):
    ls, ld = layer_of(src), layer_of(dst)
    if ls == ld:
        return None
    if (ls, ld) in SIBLINGS:
        return 'sideways: %s and %s are siblings' % (ls, ld)
    if rank(ls) < 0 or rank(ld) < 0:
        return 'unknown layer'
    if rank(ld) > rank(ls):
        return 'upward: %s is above %s' % (ld or 'the top', ls or 'the configuration')
    return None


def cycles(graph):
    """Every elementary cycle's first appearance, by depth-first search
    (Tarjan's strongly connected components; one cycle per component)."""
    index, low, onstack, stack, out = {}, {}, set(), [], []
    counter = [0]

    def strong(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        onstack.add(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                strong(w)
                low[v] = min(low[v], low[w])
            elif w in onstack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                onstack.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1 or v in graph.get(v, ()):
                out.append(sorted(comp))

    sys.setrecursionlimit(10000)
    for v in sorted(graph):
        if v not in index:
            strong(v)
    return out


def main():
    core = sys.argv[1]
    objdir = sys.argv[2] if len(sys.argv) > 2 else None
    bad = 0
    files = []
    for d, _, fs in os.walk(core):
        for f in fs:
            if f.endswith(('.c', '.h')):
                files.append(os.path.relpath(os.path.join(d, f), core))
    files.sort()
    inc = {}
    nincl = 0
    for f in files:
        inc[f] = set()
        for line in open(os.path.join(core, f), encoding='utf-8'):
            m = re.match(r'\s*#\s*include\s+"([^"]+)"', line)
            if not m:
                continue
            target = m.group(1)
            if target not in files:
                print('include: %s -> %s (not a core file: write paths from core/, e.g. "math/fx.h")' % (f, target))
                bad += 1
                continue
            nincl += 1
            inc[f].add(target)
            why = allowed(f, target)
            if why:
                print('include: %s -> %s (%s)' % (f, target, why))
                bad += 1
    for comp in cycles({f: {t for t in ts if t.endswith('.h')} for f, ts in inc.items()}):
        print('cycle: includes among %s' % ' '.join(comp))
        bad += 1
    ncalls = 0
    units = []
    if objdir:
        defs, uses = {}, {}
        for f in files:
            if not f.endswith('.c'):
                continue
            obj = os.path.join(objdir, f[:-2].replace('/', '_') + '.o')
            if not os.path.exists(obj):
                print('call: no object %s for %s' % (obj, f))
                bad += 1
                continue
            units.append(f)
            out = subprocess.run([os.environ.get('NM', 'nm'), obj], capture_output=True, text=True, check=True).stdout
            for line in out.splitlines():
                w = line.split()
                if len(w) == 2 and w[0] == 'U':
                    uses.setdefault(f, set()).add(w[1])
                elif len(w) == 3 and w[1] in 'TDRBCGSVW':
                    defs[w[2]] = f
        graph = {}
        for f in units:
            for sym in sorted(uses.get(f, ())):
                g = defs.get(sym)
                if not g or g == f:
                    continue
                ncalls += 1
                graph.setdefault(f, set()).add(g)
                why = allowed(f, g)
                if why:
                    print('call: %s -> %s (%s; %s)' % (f, g, sym, why))
                    bad += 1
        for comp in cycles(graph):
            print('cycle: translation units %s' % ' '.join(comp))
            bad += 1
    print('layers: %d files, %d includes, %d translation units, %d cross-unit references; %d violations'
          % (len(files), nincl, len(units), ncalls, bad))
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
