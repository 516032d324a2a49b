#!/usr/bin/env python3
"""Two make bench runs side by side: per scene set, board, number type and
loop, the geometric mean and the worst change in instructions, and whether
any run's error figures (mismatched pixels, PSNR) differ.

  firmware/bench-diff.py OLD.csv NEW.csv [--limit PCT]

OLD.csv, NEW.csv: build/bench/bench.csv of two runs (docs/bench/bench.csv
is the committed one; git show REV:docs/bench/bench.csv gives an older
one). Prints a markdown table; with --limit, exits 1 when a group's
geometric mean moved by more than PCT per cent."""
import csv
import math
import sys


def load(path):
    with open(path) as f:
        return {(r['set'], r['scene'], r['board'], r['number'], r['loop']): r
                for r in csv.DictReader(f) if r['status'] == 'ok'}


def main(argv):
    args = [a for a in argv if not a.startswith('--')]
    limit = None
    if '--limit' in argv:
        limit = float(argv[argv.index('--limit') + 1])
        args.remove(argv[argv.index('--limit') + 1])
    if len(args) != 2:
        sys.exit(__doc__)
    old, new = load(args[0]), load(args[1])
    groups, worst, changed = {}, {}, 0
    for k, a in old.items():
        b = new.get(k)
        if b is None:
            continue
        ratio = int(b['instructions']) / int(a['instructions'])
        g = (k[0], k[2], k[3], k[4])
        groups.setdefault(g, []).append(math.log(ratio))
        if abs(ratio - 1) >= abs(worst.get(g, (0, ''))[0]):
            worst[g] = (ratio - 1, k[1])
        changed += a['mismatched_pct'] != b['mismatched_pct'] or a['psnr'] != b['psnr']
    print('%d runs in both; %d with other error figures' % (sum(map(len, groups.values())), changed))
    print()
    print('| set | board | number | loop | runs | mean change % | largest change % (scene) |')
    print('|---|---|---|---|---:|---:|---|')
    over = 0
    for g in sorted(groups):
        v = groups[g]
        mean = (math.exp(sum(v) / len(v)) - 1) * 100
        over += limit is not None and abs(mean) > limit
        w, scene = worst[g]
        print('| %s | %s | %s | %s | %d | %+.3f | %+.3f (%s) |' % (g + (len(v), mean, w * 100, scene)))
    return 1 if over or changed else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
