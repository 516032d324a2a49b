#!/usr/bin/env bash
# The documentation's links and generated blocks (README.md and every
# docs/**/*.md). Checked, one check each:
#   - every markdown link and image outside code blocks resolves: the file
#     or directory exists (relative to the page), and a #anchor names a
#     heading of the target page (GitHub's slugs: lower case, punctuation
#     dropped, spaces to hyphens, -1, -2 ... for repeats);
#   - every generated block <!-- NAME --> ... <!-- /NAME --> is closed,
#     not nested, has a known generator (host/docblocks.sh --names, or the
#     firmware scripts' own blocks) and is not empty.
#   - every path to a project file a page names exists (docs/HISTORY.md
#     excepted: it keeps the names of their time).
# A link to a page in DOCLINKS_PENDING (default none) passes with a note
# while the page is missing. Part of make test.
set -u
. "$(dirname "$0")/lib.sh"
cd "$(dirname "$0")/.." || exit 1
pending=${DOCLINKS_PENDING-}
known="$(host/docblocks.sh --names) bench:header bench:tables bench:samples frontier benchfx:table benchfx:versus ram:table oled:table oled:frames"
pages=(README.md)
while IFS= read -r f; do pages+=("$f"); done < <(find docs -name '*.md' | sort)

while IFS= read -r line; do
    case $line in
    ok*) ok ;;
    note*) echo "$line" ;;
    *) bad "${line#FAIL }" ;;
    esac
done < <(KNOWN="$known" PENDING="$pending" python3 - "${pages[@]}" <<'PY'
import os, re, sys, unicodedata
known = set(os.environ["KNOWN"].split())
pending = set(os.environ["PENDING"].split())

def slug(text):
    text = re.sub(r"`", "", text.strip().lower())
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", text)  # a link's text
    out = []
    for ch in text:
        cat = unicodedata.category(ch)
        if ch in " -_" or cat[0] in "LN":
            out.append("-" if ch == " " else ch)
    return "".join(out)

def headings(path, cache={}):
    if path not in cache:
        seen, slugs, fence = {}, set(), False
        for line in open(path, encoding="utf-8"):
            if line.startswith("```"):
                fence = not fence
                continue
            m = None if fence else re.match(r"#{1,6}\s+(.*?)\s*#*\s*$", line)
            if m:
                s = slug(m.group(1))
                n = seen.get(s, 0)
                seen[s] = n + 1
                slugs.add(s if n == 0 else "%s-%d" % (s, n))
        cache[path] = slugs
    return cache[path]

link_re = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
for page in sys.argv[1:]:
    base = os.path.dirname(page)
    fence = False
    stack = []
    for no, line in enumerate(open(page, encoding="utf-8"), 1):
        where = "%s:%d" % (page, no)
        if line.startswith("```"):
            fence = not fence
            continue
        m = re.match(r"<!-- (/?)([A-Za-z0-9:_-]+) -->\s*$", line)
        if m and not fence:
            closing, name = m.group(1) == "/", m.group(2)
            if not closing:
                if stack:
                    print("FAIL %s: block <!-- %s --> opens inside <!-- %s -->" % (where, name, stack[-1][0]))
                stack.append((name, no, 0))
            elif not stack or stack[-1][0] != name:
                print("FAIL %s: <!-- /%s --> closes no open block" % (where, name))
            else:
                _, start, lines = stack.pop()
                if name not in known:
                    print("FAIL %s:%d: block <!-- %s --> has no known generator" % (page, start, name))
                elif lines == 0:
                    print("FAIL %s:%d: block <!-- %s --> is empty (make doc-blocks DOC_BLOCKS=%s DOCS_UPDATE=1)" % (page, start, name, name))
                else:
                    print("ok block %s %s" % (page, name))
            continue
        if stack and line.strip():
            n, s, c = stack[-1]
            stack[-1] = (n, s, c + 1)
        if fence:
            continue
        for target in link_re.findall(re.sub(r"`[^`]*`", "", line)):
            if re.match(r"[a-z]+:", target):
                print("ok external %s" % target)
                continue
            path, _, anchor = target.partition("#")
            dest = os.path.normpath(os.path.join(base, path)) if path else page
            if path and not os.path.exists(dest):
                if dest in pending:
                    print("note %s: %s is pending (added by another change)" % (where, dest))
                    print("ok pending")
                else:
                    print("FAIL %s: %s does not exist" % (where, target))
                continue
            if anchor:
                if not dest.endswith(".md") or anchor not in headings(dest):
                    print("FAIL %s: %s has no heading #%s" % (where, dest, anchor))
                    continue
            print("ok %s" % target)
    for name, start, _ in stack:
        print("FAIL %s:%d: block <!-- %s --> is never closed" % (page, start, name))
PY
)

# Every path to a project file that a page names (core/vis/row.c,
# tests/layers.sh, ...) exists: a file moved or renamed must take its
# mentions along. docs/HISTORY.md is history and keeps the old names;
# placeholders (KIND, <...>, *) are not paths.
for page in "${pages[@]}"; do
    [ "$page" = docs/HISTORY.md ] && continue
    while IFS= read -r path; do
        case $path in *KIND* | *BOARD* | *'<'* | *'*'*) continue ;; esac
        if [ -e "$path" ]; then ok; else bad "$page names $path, which does not exist"; fi
    done < <(grep -oP '(?<![/\w.-])(core|host|firmware|tests|examples|linker|scenes|docs)/[\w./-]+\.(c|h|sh|py|mk|ld|scene|md)\b' "$page" | sort -u)
done
# The growth plot of make bench-models (docs/bench/models.png) is drawn
# from its table (docs/bench/models.md) by firmware/models-plot.sh: drawn
# again here, it must take every instr/px figure of the table's first
# table (found here by column name, in python, not by the script's awk)
# and give the committed image byte for byte (else: make models-plot).
mp=$BUILD/tests/doclinks
mkdir -p "$mp"
if firmware/models-plot.sh docs/bench/models.md "$mp/models.png" "$mp/models.dat" 2>"$mp/models.log"; then
    ok
    check "models-plot: every instr/px figure of docs/bench/models.md is drawn, and only those" python3 - "$mp/models.dat" <<'PY'
import sys
rows, head = [], None
for line in open("docs/bench/models.md"):
    if line.startswith("| model | triangles"):
        head = [c.strip() for c in line.strip().strip("|").split("|")]
        continue
    if head is None or line.startswith("|---"):
        continue
    if not line.startswith("|"):
        break
    cells = [c.strip() for c in line.strip().strip("|").split("|")]
    for name, cell in zip(head, cells):
        if name.endswith(" instr/px"):
            try:
                rows.append((cells[0], int(cells[1]), name[:-len(" instr/px")], cells[3], float(cell)))
            except ValueError:
                pass  # "does not fit"
drawn = [(m, int(t), b, s, float(v)) for m, t, b, s, v in (l.split() for l in open(sys.argv[1]))]
print(f"  models-plot: {len(drawn)} figures drawn, {len(rows)} in the table")
sys.exit(0 if sorted(drawn) == sorted(rows) and len(rows) >= 30 else 1)
PY
    check "docs/bench/models.png is what firmware/models-plot.sh draws from docs/bench/models.md (make models-plot)" \
        cmp -s "$mp/models.png" docs/bench/models.png
else
    bad "firmware/models-plot.sh failed: $(tail -n 2 "$mp/models.log")"
fi
report doclinks.sh
