#!/usr/bin/env python3
"""Call-graph checks on GCC's -fcallgraph-info=su output (tests/norecurse.sh).

usage: norecurse.py [--root FN] [--allow-external] FILE.ci...

Reads the VCG graphs (one per translation unit), joins them by node title
(a global function is `name` in every unit; a static one `file.c:name`),
and prints, one per line:
  cycle: A -> B -> ... -> A     for every cycle (self-edges included)
  indirect: A                   for every function that calls through a pointer
  stack: ROOT BYTES PATH        the worst-case static stack of ROOT (--root),
                                the sum of the frames along its deepest call
                                chain (only when there is no cycle)
  dynamic: A                    a frame whose size is not static
  external: A                   a callee with no graph of its own (libgcc,
                                libc: its frame is counted as 0 bytes)
Exit status: 1 when there is a cycle or an indirect call, else 0.
"""
import re
import sys

node_re = re.compile(r'node: \{ title: "([^"]+)" label: "([^"]*)"(.*)\}')
edge_re = re.compile(r'edge: \{ sourcename: "([^"]+)" targetname: "([^"]+)"')


def main(argv):
    roots, files = [], []
    it = iter(argv)
    for a in it:
        if a == "--root":
            roots.append(next(it))
        else:
            files.append(a)
    size, kind, edges = {}, {}, {}
    for f in files:
        for line in open(f):
            m = node_re.search(line)
            if m:
                title, label, rest = m.groups()
                s = re.search(r"\\n(\d+) bytes \((\w+)", label)
                if s:
                    size[title] = int(s.group(1))
                    kind[title] = s.group(2)
                elif title not in size:
                    size.setdefault(title, None)
                continue
            m = edge_re.search(line)
            if m:
                edges.setdefault(m.group(1), set()).add(m.group(2))
                edges.setdefault(m.group(2), set())
    status = 0
    for a, k in sorted(kind.items()):
        if k != "static":
            print("dynamic: %s (%s)" % (a, k))
    for a in sorted(edges):
        if "__indirect_call" in edges[a]:
            print("indirect: %s" % a)
            status = 1
    # Cycles: Tarjan's strongly connected components (iterative).
    index, low, onstack, stack, comps = {}, {}, set(), [], []
    counter = [0]
    for v0 in sorted(edges):
        if v0 in index:
            continue
        work = [(v0, iter(sorted(edges[v0])))]
        index[v0] = low[v0] = counter[0]
        counter[0] += 1
        stack.append(v0)
        onstack.add(v0)
        while work:
            v, children = work[-1]
            for w in children:
                if w not in index:
                    index[w] = low[w] = counter[0]
                    counter[0] += 1
                    stack.append(w)
                    onstack.add(w)
                    work.append((w, iter(sorted(edges[w]))))
                    break
                if w in onstack:
                    low[v] = min(low[v], index[w])
            else:
                work.pop()
                if work:
                    low[work[-1][0]] = min(low[work[-1][0]], low[v])
                if low[v] == index[v]:
                    comp = []
                    while True:
                        w = stack.pop()
                        onstack.discard(w)
                        comp.append(w)
                        if w == v:
                            break
                    if len(comp) > 1 or v in edges[v]:
                        comps.append(sorted(comp))
    for comp in comps:
        print("cycle: " + " -> ".join(comp + [comp[0]]))
        status = 1
    for a in sorted(x for x in size if size[x] is None and x != "__indirect_call"):
        print("external: %s" % a)
    if comps:
        return status
    memo = {}

    def deepest(v):  # the graph is acyclic here
        if v in memo:
            return memo[v]
        best, path = 0, []
        for w in edges.get(v, ()):
            d, p = deepest(w)
            if d > best or not path:
                best, path = d, p
        memo[v] = ((size.get(v) or 0) + best, [v] + path)
        return memo[v]

    sys.setrecursionlimit(100000)
    for r in roots:
        if r not in edges and r not in size:
            print("stack: %s not found" % r)
            status = 1
            continue
        d, p = deepest(r)
        print("stack: %s %d %s" % (r, d, " > ".join("%s(%s)" % (x.split(":")[-1], size.get(x)) for x in p)))
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
