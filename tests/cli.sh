#!/usr/bin/env bash
# The host tool's interface: every bad scene in tests/bad-scenes is rejected
# with "FILE:LINE: message" on stderr, a non-zero exit and no output file;
# bad arguments and bad images fail clearly; good runs write what they say.
set -u
. "$(dirname "$0")/lib.sh"
out=$BUILD/tests/cli
rm -rf "$out"
mkdir -p "$out"

# expectation of a bad scene: "# expect: LINE: fragment" or NAME.expect
expect_of() {
    local f=$1 side=${1%.scene}.expect
    if [ -f "$side" ]; then cat "$side"; else sed -n '1s/^# expect: //p' "$f"; fi
}

for f in tests/bad-scenes/*.scene; do
    name=$(basename "$f" .scene)
    exp=$(expect_of "$f")
    line=${exp%%:*}
    frag=${exp#*: }
    frag=${frag%$'\r'}
    rm -f "$out/bad.png"
    "$FXRT" render "$f" -o "$out/bad.png" 2>"$out/err.txt"
    rc=$?
    err=$(head -c 400 "$out/err.txt")
    check "$name: exit status 2 (got $rc)" test "$rc" -eq 2
    check "$name: message starts '$f:$line: ' (got: $err)" grep -qF -- "$f:$line: " "$out/err.txt"
    check "$name: message says '$frag' (got: $err)" grep -qF -- "$frag" "$out/err.txt"
    check "$name: no output file" test ! -e "$out/bad.png"
    check "$name: no temporary file left" bash -c "! ls '$out' | grep -q tmp"
done

# fails CMD...: exits non-zero, says why on stderr, nothing on stdout
fails() {
    "$@" >"$out/stdout.txt" 2>"$out/stderr.txt"
    local rc=$?
    [ $rc -ne 0 ] && [ $rc -lt 128 ] && [ -s "$out/stderr.txt" ] && [ ! -s "$out/stdout.txt" ]
}
good=scenes/abb6-sphere.scene
check "no arguments" fails "$FXRT"
check "unknown command" fails "$FXRT" paint
check "render without scene" fails "$FXRT" render
check "render missing file" fails "$FXRT" render "$out/nope.scene"
check "render directory" fails "$FXRT" render "$out"
check "render bad --size" fails "$FXRT" render $good --size 0x10 -o "$out/x.png"
check "render bad --size 2" fails "$FXRT" render $good --size 10x -o "$out/x.png"
check "render bad --size 3" fails "$FXRT" render $good --size 5000x10 -o "$out/x.png"
check "render bad --size 4" fails "$FXRT" render $good --size -3x10 -o "$out/x.png"
check "render bad --number" fails "$FXRT" render $good --number int8 -o "$out/x.png"
check "render --number without value" fails "$FXRT" render $good --number
check "render unknown option" fails "$FXRT" render $good --fast
check "render two scenes" fails "$FXRT" render $good $good
check "render bad extension" fails "$FXRT" render $good -o "$out/x.jpg"
check "render into missing dir" fails "$FXRT" render $good -o "$out/no/such/dir/x.png"
check "no file from failed renders" bash -c "! ls '$out' | grep -qE '^x\\.|tmp'"
check "camera too narrow for the size" fails "$FXRT" render tests/scenes/narrow-fov.scene --size 64x4096 -o "$out/x.png"
check "narrow camera message has FILE:LINE" grep -q "tests/scenes/narrow-fov.scene:3: " "$out/stderr.txt"

# samples x width beyond the row buffer: refused at set-up, with the
# samples line and the reason (not "image wider than", which it is not).
{ grep -v '^samples' scenes/trace/glass.scene; echo "samples 7"; } >"$out/samples7.scene"
s7line=$(grep -n '^samples' "$out/samples7.scene" | cut -d: -f1)
check "samples 7 at 640 wide: refused" fails "$FXRT" render "$out/samples7.scene" -o "$out/s7.png"
check "samples 7 at 640 wide: FILE:LINE: and the reason ($(head -c 200 "$out/stderr.txt"))" \
    grep -q "^$out/samples7.scene:$s7line: samples 7 at width 640: samples x width wider than" "$out/stderr.txt"
check "samples 7 at 640 wide: no image" test ! -e "$out/s7.png"
# The scene compiler refuses it too, at the samples line, before the
# board would (a firmware's renderer holds at most FXRT_MAX_DIM columns).
mkdir -p "$out/s7fw"
scenec=$BUILD/fxrt-scenec # (the sanitized run's BUILD has no scene compiler: the plain one)
[ -x "$scenec" ] || scenec=$(dirname "$BUILD")/fxrt-scenec
check "fxrt-scenec: samples 7 at 640 wide refused" fails "$scenec" "$out/samples7.scene" --number q16 \
    --size 640x8 --out "$out/s7fw"
check "fxrt-scenec: samples 7 at 640 wide: FILE:LINE: ($(head -c 200 "$out/stderr.txt"))" \
    grep -q "^$out/samples7.scene:$s7line: samples 7 at width 640: samples x width (4480) wider than FXRT_MAX_DIM" "$out/stderr.txt"
check "fxrt-scenec: no half-written output" test -z "$(ls -A "$out/s7fw")"
check "samples 7 at 580 wide renders" "$FXRT" render "$out/samples7.scene" --size 580x20 -o "$out/s7.png"
check "samples 7 at 600 high: refused" fails "$FXRT" render "$out/samples7.scene" --size 100x600 -o "$out/s7h.png"
check "samples 7 at 600 high: the samples line and the height reason ($(head -c 200 "$out/stderr.txt"))" \
    grep -q "^$out/samples7.scene:$s7line: samples 7: samples x height beyond" "$out/stderr.txt"
# compare --scene needs only the keys (one sample per pixel): it works where
# the scene's samples x width is too wide to render.
"$FXRT" render "$out/samples7.scene" --size 640x8 --number q16 -o "$out/s7q.ppm" 2>/dev/null
check "samples 7 at 640 wide: no render at that width" test ! -e "$out/s7q.ppm"
{ grep -v '^samples' "$out/samples7.scene"; } >"$out/samples1.scene"
"$FXRT" render "$out/samples1.scene" --size 640x8 --number q16 -o "$out/s1q.ppm"
"$FXRT" render "$out/samples1.scene" --size 640x8 --number double -o "$out/s1d.ppm"
check "compare --scene with samples 7 at 640 wide: the keys' split" \
    bash -c "'$FXRT' compare '$out/s1d.ppm' '$out/s1q.ppm' --scene '$out/samples7.scene' | grep -q 'near_pixels=[1-9]'"
check "--help" bash -c "'$FXRT' --help | grep -q 'render SCENE'"
check "render --help lists options" bash -c "'$FXRT' render --help | grep -q -- '--number'"
check "compare --help lists options" bash -c "'$FXRT' compare --help | grep -q -- '--diff'"

# Good renders: PNG and PPM, sizes, default output name.
check "render png" "$FXRT" render $good -o "$out/a.png" --size 32x24
check "render ppm" "$FXRT" render $good -o "$out/a.ppm" --size 32x24
check "ppm header" bash -c "head -c 2 '$out/a.ppm' | grep -q P6"
check "ppm size" test "$(stat -c %s "$out/a.ppm")" -eq $((32 * 24 * 3 + 13))
check "png and ppm identical pixels" bash -c "'$FXRT' compare '$out/a.png' '$out/a.ppm' | grep -q ' mismatched=0 '"
(cd "$out" && "$OLDPWD/$FXRT" render "$OLDPWD/$good" --number float --size 8x8) && ok || bad "default output"
check "default output name" test -f "$out/abb6-sphere-float.png"

# compare: errors and thresholds.
"$FXRT" render $good -o "$out/b.png" --size 16x12
check "compare size mismatch" fails "$FXRT" compare "$out/a.png" "$out/b.png"
printf 'garbage' >"$out/garbage.png"
check "compare garbage image" fails "$FXRT" compare "$out/a.png" "$out/garbage.png"
check "compare missing image" fails "$FXRT" compare "$out/a.png" "$out/none.png"
check "compare one argument" fails "$FXRT" compare "$out/a.png"
"$FXRT" render scenes/abb9-two-spheres.scene -o "$out/q.png" --size 320x215
"$FXRT" render scenes/abb9-two-spheres.scene -o "$out/d.png" --size 320x215 --number double
"$FXRT" render scenes/abb6-sphere.scene -o "$out/s.png" --size 320x215
check "compare within threshold" "$FXRT" compare "$out/d.png" "$out/q.png" --max-pct 0.01 --max-interior 0
"$FXRT" compare "$out/d.png" "$out/s.png" --max-pct 0.01 --diff "$out/diff.png" >/dev/null 2>&1
check "compare over threshold exits 1" test $? -eq 1
check "diff image written" test -s "$out/diff.png"

# --- usage errors: one line saying what is wrong, a pointer to --help, exit 2
# usage_err DESC EXPECTED-FIRST-LINE CMD...: exit 2, nothing on stdout,
# stderr exactly that line and "Try 'fxrt [CMD ]--help'." (no usage text).
usage_err() {
    local desc=$1 want=$2 rc
    shift 2
    "$@" >"$out/stdout.txt" 2>"$out/stderr.txt"
    rc=$?
    local try="Try 'fxrt --help'."
    case ${2:-} in render | compare | sheet | size | obj) try="Try 'fxrt $2 --help'." ;; esac
    check "$desc: exit 2 (got $rc)" test $rc -eq 2
    check "$desc: nothing on stdout" test ! -s "$out/stdout.txt"
    check "$desc: stderr is '$want' + '$try' (got: $(head -c 300 "$out/stderr.txt"))" \
        test "$(cat "$out/stderr.txt")" = "$want"$'\n'"$try"
}
usage_err "no command" "fxrt: missing command (render, compare, sheet, size or obj)" "$FXRT"
usage_err "unknown command" "fxrt: unknown command 'paint'" "$FXRT" paint
usage_err "unknown top option" "fxrt: unknown option '--fast'" "$FXRT" --fast
usage_err "render bad --size" "fxrt: render: bad --size 'x' (want WxH, each 1..4096)" "$FXRT" render $good --size x
usage_err "render bad --number" "fxrt: render: bad --number 'int8' (want q16, float or double)" \
    "$FXRT" render $good --number int8
usage_err "render --number without value" "fxrt: render: --number needs a value" "$FXRT" render $good --number
usage_err "render no scene" "fxrt: render: no SCENE given" "$FXRT" render
usage_err "render unknown option" "fxrt: render: unknown option '--fast'" "$FXRT" render $good --fast
usage_err "compare bad --max-pct" "fxrt: compare: bad --max-pct 'lots' (want a number >= 0)" \
    "$FXRT" compare "$out/a.png" "$out/a.ppm" --max-pct lots
usage_err "compare one image" "fxrt: compare: needs two images A and B" "$FXRT" compare "$out/a.png"
usage_err "sheet no image" "fxrt: sheet: no IMAGE given" "$FXRT" sheet -o "$out/s.png"
usage_err "size no scene" "fxrt: size: no SCENE given" "$FXRT" size
usage_err "obj no file" "fxrt: obj: no FILE given" "$FXRT" obj
usage_err "obj two files" "fxrt: obj: unexpected argument 'b.obj' (one FILE only)" "$FXRT" obj a.obj b.obj

# --- a repeated option is an error (also under its other spelling)
usage_err "render --size twice" "fxrt: render: --size given twice" \
    "$FXRT" render $good --size 8x8 --size 8x8 -o "$out/rep.png"
usage_err "render -o twice" "fxrt: render: -o given twice" "$FXRT" render $good -o "$out/rep.png" -o "$out/rep.png"
usage_err "render -o and --output" "fxrt: render: --output given twice (also as -o)" \
    "$FXRT" render $good -o "$out/rep.png" --output "$out/rep2.png"
usage_err "render --number twice" "fxrt: render: --number given twice" \
    "$FXRT" render $good --number q16 --number double -o "$out/rep.png"
usage_err "render --renderer twice" "fxrt: render: --renderer given twice" \
    "$FXRT" render $good --renderer fast --renderer fast -o "$out/rep.png"
usage_err "compare --diff twice" "fxrt: compare: --diff given twice" \
    "$FXRT" compare "$out/a.png" "$out/a.ppm" --diff "$out/rd.png" --diff "$out/rd.png"
usage_err "compare --max-pct twice" "fxrt: compare: --max-pct given twice" \
    "$FXRT" compare "$out/a.png" "$out/a.ppm" --max-pct 1 --max-pct 2
usage_err "compare --max-interior twice" "fxrt: compare: --max-interior given twice" \
    "$FXRT" compare "$out/a.png" "$out/a.ppm" --max-interior 1 --max-interior 1
usage_err "sheet -o twice" "fxrt: sheet: -o given twice" "$FXRT" sheet -o "$out/rs.png" -o "$out/rs.png" "$out/a.png"
usage_err "sheet --no-labels twice" "fxrt: sheet: --no-labels given twice" \
    "$FXRT" sheet --no-labels --no-labels -o "$out/rs.png" "$out/a.png"
check "no output from rejected repeats" bash -c "! ls '$out' | grep -qE '^(rep|rep2|rd|rs)\\.png'"
check "'--' ends the options" "$FXRT" render -o "$out/dd.png" --size 8x8 -- $good
check "'--' output written" test -s "$out/dd.png"

# --- --version: one line, the version from host/version.h
ver=$(sed -nE 's/^#define FXRT_VERSION "(.*)"$/\1/p' host/version.h)
check "FXRT_VERSION found in host/version.h ($ver)" test -n "$ver"
"$FXRT" --version >"$out/version.txt" 2>&1
check "--version exits 0" test $? -eq 0
check "--version prints 'fxrt $ver' (got: $(cat "$out/version.txt"))" \
    grep -qxE "fxrt $ver( \\(git [A-Za-z0-9._+-]+\\))?" "$out/version.txt"
check "--version is one line" test "$(wc -l <"$out/version.txt")" -eq 1
check "--help mentions --version" bash -c "'$FXRT' --help | grep -q -- '--version'"
usage_err "--version with an argument" "fxrt: unexpected argument 'extra' after --version" "$FXRT" --version extra
usage_err "render -o ''" "fxrt: render: -o needs a non-empty value" "$FXRT" render scenes/abb6-sphere.scene -o ""
usage_err "compare --diff ''" "fxrt: compare: --diff needs a non-empty value" "$FXRT" compare a.png b.png --diff ""

# --- compare --diff and sheet -o never write over an input
cp "$out/q.png" "$out/q-orig.png"
cp "$out/d.png" "$out/d-orig.png"
ln -f "$out/q.png" "$out/q-link.png"
# refuses DESC CMD...: exit 2, one "would overwrite" line, q.png and d.png untouched, no temporary file
refuses() {
    local desc=$1 rc
    shift
    "$@" >"$out/stdout.txt" 2>"$out/stderr.txt"
    rc=$?
    check "$desc: exit 2 (got $rc)" test $rc -eq 2
    check "$desc: says why (got: $(head -n 1 "$out/stderr.txt"))" grep -q "would overwrite the input" "$out/stderr.txt"
    check "$desc: q.png untouched" cmp -s "$out/q.png" "$out/q-orig.png"
    check "$desc: d.png untouched" cmp -s "$out/d.png" "$out/d-orig.png"
    check "$desc: no temporary file" bash -c "! ls '$out' | grep -q tmp"
}
refuses "compare --diff A" "$FXRT" compare "$out/q.png" "$out/d.png" --diff "$out/q.png"
refuses "compare --diff B" "$FXRT" compare "$out/q.png" "$out/d.png" --diff "$out/d.png"
(cd "$out" && "$OLDPWD/$FXRT" compare q.png d.png --diff ./d.png) >"$out/stdout.txt" 2>"$out/stderr.txt"
check "compare --diff ./B (same file, other path): exit 2" test $? -eq 2
check "compare --diff ./B: d.png untouched" cmp -s "$out/d.png" "$out/d-orig.png"
refuses "compare --diff a hard link to A" "$FXRT" compare "$out/q.png" "$out/d.png" --diff "$out/q-link.png"
refuses "sheet -o an input" "$FXRT" sheet -o "$out/d.png" "$out/q.png" "$out/d.png"
refuses "sheet -o an input with a label" "$FXRT" sheet -o "$out/q.png" "$out/q.png=Q16.16" "$out/d.png=double"
refuses "sheet -o ./input" "$FXRT" sheet -o "$out/./q.png" "$out/d.png" "$out/q.png"
# The mistake of issue 10: OUT typed last. Without -o nothing is written.
"$FXRT" sheet "$out/q.png" "$out/d.png" "$out/new-sheet.png" >"$out/stdout.txt" 2>"$out/stderr.txt"
check "sheet without -o: exit 2" test $? -eq 2
check "sheet without -o: says so" grep -q "no output given (-o OUT" "$out/stderr.txt"
check "sheet without -o: q.png untouched" cmp -s "$out/q.png" "$out/q-orig.png"
check "sheet without -o: nothing written" test ! -e "$out/new-sheet.png"
check "render -o SCENE refused" fails "$FXRT" render "$out/q.png" -o "$out/q.png"

# --- sheet labels (5x8 font, a strip above each panel) and the identical diff map
# ppm_dims FILE: "W H" from a P6 header written by fxrt (no comments)
ppm_dims() { head -c 40 "$1" | sed -n 2p; }
"$FXRT" render $good --size 40x30 -o "$out/p1.ppm"
"$FXRT" render scenes/abb7-box.scene --size 30x30 -o "$out/p2.ppm"
check "sheet with labels" "$FXRT" sheet -o "$out/sheet.ppm" "$out/p1.ppm=Q16.16 (QEMU)" "$out/p2.ppm=double"
check "labelled sheet: width 40+8+30, height 30 + a 14 px strip (got $(ppm_dims "$out/sheet.ppm"))" \
    test "$(ppm_dims "$out/sheet.ppm")" = "78 44"
check "sheet --no-labels" "$FXRT" sheet --no-labels -o "$out/sheet-nl.ppm" "$out/p1.ppm" "$out/p2.ppm"
check "sheet --no-labels: no strip (got $(ppm_dims "$out/sheet-nl.ppm"))" test "$(ppm_dims "$out/sheet-nl.ppm")" = "78 30"
"$FXRT" sheet --no-labels -o "$out/one.ppm" "$out/p1.ppm"
check "one-image sheet without labels is the image itself" cmp -s "$out/one.ppm" "$out/p1.ppm"
"$FXRT" sheet -o "$out/one-l.ppm" "$out/p1.ppm=abc"
hdr=$(head -c 40 "$out/p1.ppm" | head -n 3 | wc -c)
check "labelled panel: the image's pixels under the strip" \
    cmp -s <(tail -c $((40 * 30 * 3)) "$out/one-l.ppm") <(tail -c $((40 * 30 * 3)) "$out/p1.ppm")
strip=$(head -c $((hdr + 40 * 14 * 3)) "$out/one-l.ppm" | tail -c $((40 * 14 * 3)) | od -An -v -tu1 | tr -s ' ' '\n' | grep -v '^$' | sort -u | tr '\n' ' ')
check "label strip holds only background 96 and ink 255 (got: $strip)" test "$strip" = "255 96 "
ink=$(head -c $((hdr + 40 * 14 * 3)) "$out/one-l.ppm" | tail -c $((40 * 14 * 3)) | od -An -v -tu1 | tr -s ' ' '\n' | grep -c '^255$')
check "label 'abc' inks 40 font pixels (14 + 16 + 10, counted by hand; got $((ink / 3)))" test $((ink / 3)) -eq 40
"$FXRT" sheet -o "$out/one-d.ppm" "$out/p1.ppm"
"$FXRT" sheet -o "$out/one-e.ppm" "$out/p1.ppm=p1.ppm"
check "default label is the file's base name" cmp -s "$out/one-d.ppm" "$out/one-e.ppm"
check "different labels draw differently" bash -c "! cmp -s '$out/one-d.ppm' '$out/one-l.ppm'"
usage_err "sheet label with a control byte" "fxrt: sheet: label 'a"$'\t'"b' is not printable ASCII" \
    "$FXRT" sheet -o "$out/lab.ppm" "$out/p1.ppm=a"$'\t'"b"
cp "$out/p1.ppm" "$out/x=y.ppm"
check "an image name with '=' given as 'NAME='" "$FXRT" sheet -o "$out/eq.ppm" "$out/x=y.ppm="
check "large panels get a 2x label strip (height 300 + 28)" \
    bash -c "'$FXRT' render $good --size 20x300 -o '$out/tall.ppm' && '$FXRT' sheet -o '$out/tall-s.ppm' '$out/tall.ppm' && test \"\$(head -c 40 '$out/tall-s.ppm' | sed -n 2p)\" = '20 328'"

# A diff map of identical images says so; of images that differ in one pixel, shows that pixel only.
"$FXRT" compare "$out/p1.ppm" "$out/one.ppm" --diff "$out/same-diff.ppm" >"$out/same.txt"
check "identical images: mismatched=0" grep -q ' mismatched=0 ' "$out/same.txt"
lit=$(tail -c $((40 * 30 * 3)) "$out/same-diff.ppm" | od -An -v -tu1 | tr -s ' ' '\n' | grep -cvE '^(0|)$')
check "identical images: the diff map has 'identical' written on it ($lit lit bytes)" test "$lit" -gt 30
{ head -c "$hdr" "$out/p1.ppm"; tail -c $((40 * 30 * 3)) "$out/p1.ppm" | head -c $((40 * 30 * 3 - 3)); printf '\001\002\003'; } >"$out/p1x.ppm"
"$FXRT" compare "$out/p1.ppm" "$out/p1x.ppm" --diff "$out/one-diff.ppm" >"$out/one.txt"
check "one changed pixel: mismatched=1" grep -q ' mismatched=1 ' "$out/one.txt"
lit=$(tail -c $((40 * 30 * 3)) "$out/one-diff.ppm" | od -An -v -tu1 | tr -s ' ' '\n' | grep -cvE '^(0|)$')
check "one changed pixel: the diff map lights 1..3 bytes, no text (got $lit)" test "$lit" -ge 1 -a "$lit" -le 3

# --- compare --scene: the near/far split from the double render's keys
# ppm_bytes FILE W H: the pixel bytes of a P6 file written by fxrt, one per line
ppm_bytes() { tail -c $(($2 * $3 * 3)) "$1" | od -An -v -tu1 | tr -s ' ' '\n' | grep -v '^$'; }
sc=scenes/abb9-two-spheres.scene
"$FXRT" render $sc --size 32x24 --number double -o "$out/kd.ppm"
"$FXRT" render $sc --size 32x24 --number float -o "$out/kf.ppm"
check "render --keys writes the key picture" "$FXRT" render $sc --size 32x24 --number double -o "$out/kd2.ppm" --keys "$out/keys.ppm"
check "render --keys: the image is the same as without" cmp -s "$out/kd.ppm" "$out/kd2.ppm"
check "render --keys: key picture has the image's size" test "$(ppm_dims "$out/keys.ppm")" = "32 24"
line=$("$FXRT" compare "$out/kd.ppm" "$out/kf.ppm" --scene $sc 2>"$out/stderr.txt")
check "compare --scene: exit 0 (stderr: $(head -c 200 "$out/stderr.txt"))" test -n "$line"
for k in within1_pct within2_pct near_pixels far_pixels far_within1_pct far_within2_pct far_max_err near_max_err; do
    check "compare --scene prints $k= (got: $line)" grep -qE "(^| )$k=[0-9.]+( |\$)" <<<"$line"
done
np=$(sed -nE 's/.* near_pixels=([0-9]+) .*/\1/p' <<<"$line")
fp=$(sed -nE 's/.* far_pixels=([0-9]+) .*/\1/p' <<<"$line")
check "compare --scene: near_pixels + far_pixels = 768 (got $np + $fp)" test "$((np + fp))" -eq 768
# The near count again, independently: from the key picture (one colour per
# key) with the 8-neighbourhood rule, in awk.
want=$(ppm_bytes "$out/keys.ppm" 32 24 | awk -v W=32 -v H=24 '
    { v[int((NR - 1) / 3)] = v[int((NR - 1) / 3)] "," $1 }
    END {
        for (y = 0; y < H; y++) for (x = 0; x < W; x++) {
            near = 0
            for (dy = -1; dy <= 1; dy++) for (dx = -1; dx <= 1; dx++) {
                nx = x + dx; ny = y + dy
                if (nx >= 0 && ny >= 0 && nx < W && ny < H && v[ny * W + nx] != v[y * W + x]) near = 1
            }
            n += near
        }
        print n + 0
    }')
check "compare --scene: near_pixels=$np is the count from the key picture ($want)" test "$np" = "$want"
if grep -q 'keys\[' core/*/*.c; then
    # Once the core writes keys, the two spheres' silhouettes are near pixels.
    check "compare --scene: the silhouettes are near pixels (near_pixels=$np)" test "$np" -gt 0
    lit=$(ppm_bytes "$out/keys.ppm" 32 24 | grep -cv '^0$')
    check "render --keys: the spheres show in the key picture ($lit lit bytes)" test "$lit" -gt 0
fi
noscene=$("$FXRT" compare "$out/kd.ppm" "$out/kf.ppm")
check "compare without --scene: near_pixels=0 far_pixels=768" grep -q ' near_pixels=0 far_pixels=768 ' <<<"$noscene"
check "compare without --scene: the same all-pixel metrics" \
    test "$(cut -d' ' -f1-9 <<<"$noscene")" = "$(cut -d' ' -f1-9 <<<"$line")"
check "compare --help documents --scene and the heat scale" \
    bash -c "'$FXRT' compare --help | grep -q -- '--scene SCENE' && '$FXRT' compare --help | grep -q 'dark red (128,0,0)'"
# scene_fails DESC WANT CMD...: exit 2, nothing on stdout, stderr says WANT, no diff written
scene_fails() {
    local desc=$1 want=$2 rc
    shift 2
    rm -f "$out/sdiff.png"
    "$@" >"$out/stdout.txt" 2>"$out/stderr.txt"
    rc=$?
    check "$desc: exit 2 (got $rc)" test $rc -eq 2
    check "$desc: nothing on stdout" test ! -s "$out/stdout.txt"
    local got
    got=$(head -c 300 "$out/stderr.txt")
    check "$desc: stderr starts with '$want' (got: $got)" test "${got:0:${#want}}" = "$want"
    check "$desc: no diff file" test ! -e "$out/sdiff.png"
    check "$desc: no temporary file" bash -c "! ls '$out' | grep -q tmp"
}
scene_fails "compare --scene missing file" "$out/none.scene: " \
    "$FXRT" compare "$out/kd.ppm" "$out/kf.ppm" --scene "$out/none.scene" --diff "$out/sdiff.png"
badsc=tests/bad-scenes/bad-color.scene
badline=$(expect_of $badsc)
scene_fails "compare --scene bad scene" "$badsc:${badline%%:*}: " \
    "$FXRT" compare "$out/kd.ppm" "$out/kf.ppm" --scene $badsc --diff "$out/sdiff.png"
scene_fails "compare --scene a directory" "$out" \
    "$FXRT" compare "$out/kd.ppm" "$out/kf.ppm" --scene "$out" --diff "$out/sdiff.png"
usage_err "compare --scene twice" "fxrt: compare: --scene given twice" \
    "$FXRT" compare "$out/kd.ppm" "$out/kf.ppm" --scene $sc --scene $sc
usage_err "compare --scene without value" "fxrt: compare: --scene needs a value" \
    "$FXRT" compare "$out/kd.ppm" "$out/kf.ppm" --scene
cp $sc "$out/sc-copy.scene"
"$FXRT" compare "$out/kd.ppm" "$out/kf.ppm" --scene "$out/sc-copy.scene" --diff "$out/sc-copy.scene" >"$out/stdout.txt" 2>"$out/stderr.txt"
check "compare --diff SCENE: exit 2" test $? -eq 2
check "compare --diff SCENE: says why" grep -q "would overwrite the input" "$out/stderr.txt"
check "compare --diff SCENE: scene untouched" cmp -s $sc "$out/sc-copy.scene"
rm -f "$out/kbad.png" "$out/kbad-keys.png"
"$FXRT" render $badsc -o "$out/kbad.png" --keys "$out/kbad-keys.png" 2>/dev/null
check "render --keys of a bad scene: exit 2, neither file" \
    bash -c "test $? -eq 2 && test ! -e '$out/kbad.png' && test ! -e '$out/kbad-keys.png'"
# A --keys file that cannot be written (bad extension, missing directory)
# leaves no image either: both are written to temporary files first.
mkdir -p "$out/kdir.png"
for kb in "$out/kbad.jpg" "$out/no/such/dir/k.png" "$out/kdir.png"; do
    rm -f "$out/kgood.png"
    "$FXRT" render $sc --size 16x12 -o "$out/kgood.png" --keys "$kb" 2>"$out/stderr.txt"
    check "render --keys $kb: exit 2, no image, no temporary file" \
        bash -c "test $? -eq 2 && test ! -e '$out/kgood.png' && ! ls '$out' | grep -q 'kgood.*tmp'"
done
# An interrupted render leaves no temporary file: SIGINT removes the files
# being written (FXRT_TEST_SIGINT_PENDING raises it once the image's
# temporary file is written, before its rename). SIGINT's default action
# is restored first: a shell starts background jobs (make test &, some CI
# runners) with it ignored, and an ignored SIGINT stays ignored (below).
rm -f "$out/kint.png" "$out"/kint.png.tmp.*
FXRT_TEST_SIGINT_PENDING=1 env --default-signal=INT "$FXRT" render $sc --size 16x12 -o "$out/kint.png" 2>/dev/null
rc=$?
check "render interrupted by SIGINT: ends by it (exit $rc), no image, no temporary file" \
    bash -c "test $rc -eq 130 && test ! -e '$out/kint.png' && ! ls '$out' | grep -q 'kint.*tmp'"
# A signal ignored by the parent (nohup, trap '' INT) stays ignored.
(trap '' INT; FXRT_TEST_SIGINT_PENDING=1 "$FXRT" render $sc --size 16x12 -o "$out/kign.png" 2>/dev/null)
rc=$?
check "render with SIGINT ignored by its parent: not ended by it (exit $rc), image written" \
    bash -c "test $rc -eq 0 && test -s '$out/kign.png'"
usage_err "render --keys = -o" "fxrt: render: --keys '$out/kk.png' is the output image too" \
    "$FXRT" render $sc -o "$out/kk.png" --keys "$out/kk.png"
check "compare --scene --diff writes the heat map" \
    bash -c "'$FXRT' compare '$out/kd.ppm' '$out/kf.ppm' --scene $sc --diff '$out/sdiff.png' >/dev/null && test -s '$out/sdiff.png'"
# Heat scale end to end: a pixel off by 1 is dark red (128,0,0).
{ head -c $(($(stat -c %s "$out/kd.ppm") - 32 * 24 * 3)) "$out/kd.ppm"; tail -c $((32 * 24 * 3)) "$out/kd.ppm" | head -c 3 | od -An -v -tu1 |
    awk '{ printf "%c%c%c", ($1 < 255 ? $1 + 1 : 254), $2, $3 }'; tail -c $((32 * 24 * 3 - 3)) "$out/kd.ppm"; } >"$out/kd1.ppm"
"$FXRT" compare "$out/kd.ppm" "$out/kd1.ppm" --diff "$out/kd1-diff.ppm" >"$out/kd1.txt"
check "one pixel off by 1: max_err=1 within1_pct=100.0000" grep -q ' max_err=1 .* within1_pct=100.0000 ' "$out/kd1.txt"
check "one pixel off by 1: the diff's first pixel is (128,0,0)" \
    test "$(ppm_bytes "$out/kd1-diff.ppm" 32 24 | head -n 3 | tr '\n' ' ')" = "128 0 0 "

# --- paths with spaces, and fxrt size
mkdir -p "$out/dir with space"
cp $good "$out/dir with space/a scene.scene"
check "render a scene path with spaces" "$FXRT" render "$out/dir with space/a scene.scene" --size 16x12 -o "$out/dir with space/out put.png"
check "spaced output written" test -s "$out/dir with space/out put.png"
(cd "$out/dir with space" && "$OLDPWD/$FXRT" render "a scene.scene" --size 16x12) && ok || bad "default output from a spaced name"
check "default output name keeps the space" test -s "$out/dir with space/a scene-q16.png"
check "compare and sheet with spaced paths" bash -c "'$FXRT' compare '$out/dir with space/out put.png' '$out/dir with space/a scene-q16.png' --diff '$out/dir with space/d i.png' >/dev/null && '$FXRT' sheet -o '$out/dir with space/s s.png' '$out/dir with space/out put.png=a b'"
check "fxrt size prints the image line" test "$("$FXRT" size "$out/dir with space/a scene.scene")" = 640x430
printf 'camera perspective eye 0 0 0 gaze 0 0 -1 up 0 1 0 fov 45\n' >"$out/noimage.scene"
check "fxrt size without an image line: 160x120" test "$("$FXRT" size "$out/noimage.scene")" = 160x120
check "fxrt size of a bad scene fails with FILE:LINE" bash -c "! '$FXRT' size tests/bad-scenes/$(ls tests/bad-scenes | grep -m1 '\.scene$') 2>&1 | grep -q '^[0-9]*x[0-9]*\$'"

# --- a UTF-8 byte-order mark is skipped at the very start of a scene only
bom=$'\xef\xbb\xbf'
{ printf '%s' "$bom"; cat $good; } >"$out/bom.scene"
check "scene starting with a BOM renders" "$FXRT" render "$out/bom.scene" --size 32x24 -o "$out/bom.ppm"
"$FXRT" render $good --size 32x24 -o "$out/nobom.ppm"
check "BOM scene renders as without it" cmp -s "$out/bom.ppm" "$out/nobom.ppm"
check "BOM scene: fxrt size reads its image line" test "$("$FXRT" size "$out/bom.scene")" = 640x430
{ printf '%s\r\n' "${bom}image 20 10"; printf 'camera perspective eye 0 0 0 gaze 0 0 -1 up 0 1 0 fov 45\r\n'; } >"$out/bomcrlf.scene"
check "BOM + CRLF scene: image line read" test "$("$FXRT" size "$out/bomcrlf.scene")" = 20x10

# host/replace-block.sh: the docs' generated blocks are written through it.
printf 'top\n<!-- a -->\nold a\n<!-- /a -->\nmid\n<!-- b -->\nold b\n<!-- /b -->\nend\n' >"$out/doc.md"
printf 'new a 1\nnew a 2\n' >"$out/a.txt"
printf 'new b\n' >"$out/b.txt"
cp "$out/doc.md" "$out/doc0.md"
check "replace-block: a missing marker exits 2" bash -c "! host/replace-block.sh '$out/doc.md' a '$out/a.txt' c '$out/b.txt' 2>/dev/null"
check "replace-block: ... and leaves the doc as it was, also its other blocks" cmp -s "$out/doc.md" "$out/doc0.md"
host/replace-block.sh "$out/doc.md" a "$out/a.txt" b "$out/b.txt"
check "replace-block: two blocks replaced, the rest kept" test "$(tr '\n' '|' <"$out/doc.md")" = \
    "top|<!-- a -->|new a 1|new a 2|<!-- /a -->|mid|<!-- b -->|new b|<!-- /b -->|end|"
host/replace-block.sh --pad "$out/doc.md" b "$out/b.txt"
check "replace-block --pad: a blank line before and after" test "$(tr '\n' '|' <"$out/doc.md")" = \
    "top|<!-- a -->|new a 1|new a 2|<!-- /a -->|mid|<!-- b -->||new b||<!-- /b -->|end|"

# fxrt obj: an OBJ mesh's counts, and its errors with the OBJ's FILE:LINE.
printf 'v 0 0 0\r\nv 1 0 0\r\nv 1 1 0\r\nv 0 1 0\r\nvn 0 0 1\r\nf 1//1 2//1 3//1 4//1\r\n' >"$out/quad.obj"
"$FXRT" obj "$out/quad.obj" >"$out/quad.txt"
check "fxrt obj: exit 0" test $? -eq 0
check "fxrt obj: a quad is one face, two triangles" bash -c "grep -qx 'faces 1' '$out/quad.txt' && grep -qx 'triangles 2' '$out/quad.txt'"
check "fxrt obj: corners with the file's normal" grep -qx "corners_with_vn 6 of 6" "$out/quad.txt"
check "fxrt obj: bounds" grep -qx "bounds 0 0 0 1 1 0" "$out/quad.txt"
check "fxrt obj: no zero-area triangle in a quad" grep -qx "zero_area 0" "$out/quad.txt"
printf 'v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\nf 4 4 2\n' >"$out/flat.obj"
"$FXRT" obj "$out/flat.obj" >"$out/flat.txt"
check "fxrt obj: collinear and repeated corners are zero-area" grep -qx "zero_area 2" "$out/flat.txt"
# A scene's mesh: zero-area triangles left out, with a note on stderr.
printf '%s\n' "camera perspective eye 0 0 5 gaze 0 0 -1 up 0 1 0 fov 45" \
    "node translate 0 0 -1" "mesh file flat.obj shading flat color 1 0 0" "end" >"$out/mesh.scene"
"$FXRT" render "$out/mesh.scene" -o "$out/mesh.png" 2>"$out/mesh.err"
check "fxrt render: a mesh with zero-area triangles renders (exit 0)" test $? -eq 0
check "fxrt render: ... and notes the two left out" grep -qx "$out/mesh.scene: note: 2 zero-area mesh triangles left out" "$out/mesh.err"
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 0\n' >"$out/zero.obj"
"$FXRT" obj "$out/zero.obj" >"$out/zero.txt" 2>"$out/zero.err"
check "fxrt obj: index 0 exits 2" test $? -eq 2
check "fxrt obj: index 0 names FILE:LINE" grep -q "^$out/zero.obj:4: f: vertex index 0" "$out/zero.err"
check "fxrt obj: nothing on stdout after an error" test ! -s "$out/zero.txt"
check "fxrt obj: a missing file exits 2" fails "$FXRT" obj "$out/none.obj"
check "fxrt obj --help" bash -c "'$FXRT' obj --help | grep -q '^usage: fxrt obj FILE'"
{ head -n 2 $good; printf '%s' "$bom"; tail -n +3 $good; } >"$out/bom3.scene"
"$FXRT" render "$out/bom3.scene" -o "$out/bom3.png" 2>"$out/stderr.txt"
check "BOM on line 3: exit 2" test $? -eq 2
check "BOM on line 3: FILE:3: non-ASCII (got: $(cat "$out/stderr.txt"))" \
    grep -qF "$out/bom3.scene:3: non-ASCII byte 0xef at column 1" "$out/stderr.txt"
check "BOM on line 3: no image" test ! -e "$out/bom3.png"
{ printf '%s%s' "$bom" "$bom"; cat $good; } >"$out/bom2.scene"
"$FXRT" render "$out/bom2.scene" -o "$out/bom2.png" 2>"$out/stderr.txt"
check "two BOMs: the second is an error at 1:1 (got: $(cat "$out/stderr.txt"))" \
    grep -qF "$out/bom2.scene:1: non-ASCII byte 0xef at column 1" "$out/stderr.txt"
{ printf '# comment\n%s' "$bom"; cat $good; } >"$out/bom-late.scene"
check "BOM after a first line is an error" fails "$FXRT" render "$out/bom-late.scene" -o "$out/bl.png"

# --- make qemu/fw variables are checked before anything is built. -o: make
# must not rebuild the host tool here (under sanitize.sh, BUILD is the
# sanitized build, which the normal rules would overwrite).
MK="make -s --no-print-directory BUILD=$BUILD -o $BUILD/fxrt"
$MK fw FB=bad >"$out/stdout.txt" 2>"$out/stderr.txt"
check "make fw FB=bad fails" test $? -ne 0
check "FB=bad: clear message (got: $(head -c 200 "$out/stderr.txt"))" grep -q "unknown FB 'bad' (one of: full stream" "$out/stderr.txt"
$MK fw FB= >/dev/null 2>"$out/stderr.txt"
check "make fw FB= (empty) fails clearly" grep -q "unknown FB ''" "$out/stderr.txt"
$MK fw FB="full stream" >/dev/null 2>"$out/stderr.txt"
check "make fw FB='full stream' fails clearly" grep -q "unknown FB 'full stream'" "$out/stderr.txt"
$MK fw SIZE= >/dev/null 2>"$out/stderr.txt"
check "make fw SIZE= (empty) fails clearly" grep -q "bad SIZE '' (want WxH" "$out/stderr.txt"
$MK fw SIZE=160 >/dev/null 2>"$out/stderr.txt"
check "make fw SIZE=160 fails clearly" grep -q "bad SIZE '160' (want WxH" "$out/stderr.txt"
for sz in 0x5 4097x1 10x 12x12x3 '1x1"'; do
    $MK fw SIZE=$sz >/dev/null 2>"$out/stderr.txt"
    check "make fw SIZE=$sz fails before building" grep -q "bad SIZE '$sz' (want WxH, each 1..4096" "$out/stderr.txt"
done
$MK fw BOARD=nrf99 >/dev/null 2>"$out/stderr.txt"
check "make fw BOARD=nrf99 fails clearly" grep -q "unknown BOARD 'nrf99'" "$out/stderr.txt"
$MK fw SCENE="it's.scene" >/dev/null 2>"$out/stderr.txt"
check "make fw with a quote in SCENE fails clearly" grep -q "quotes and '\\$' in the scene path are not supported" "$out/stderr.txt"
check "make fw with a bad scene and no SIZE fails with FILE:LINE" \
    bash -c "! $MK fw SCENE='$out/bom3.scene' >/dev/null 2>'$out/stderr.txt' && grep -qF '$out/bom3.scene:3: ' '$out/stderr.txt'"

# --- tests/run.sh passes progress lines through while a suite's output goes to its log
mkdir -p "$out/runner"
cat >"$out/runner/slow.sh" <<'EOS'
#!/usr/bin/env bash
. tests/lib.sh
echo "to the log only"
progress "slow.sh: step 1/2"
progress "slow.sh: step 2/2"
ok
report slow
EOS
chmod +x "$out/runner/slow.sh"
BUILD="$out/runner" RUN_NOTICE_SECONDS=100 tests/run.sh "$out/runner/slow.sh" >"$out/runner/out.txt" 2>&1
check "run.sh with a progress suite: exit 0" test $? -eq 0
check "run.sh shows the suite's progress lines" grep -qx "  slow.sh: step 2/2" "$out/runner/out.txt"
check "run.sh keeps the suite's output in its log" bash -c "! grep -q 'to the log only' '$out/runner/out.txt' && grep -q 'to the log only' '$out/runner/tests/logs/slow.sh.log'"
check "run.sh still ends 'total: N passed, N failed'" test "$(tail -n 1 "$out/runner/out.txt")" = "total: 1 passed, 0 failed"
check "progress is silent outside run.sh" bash -c "cd '$PWD' && unset PROGRESS_FD && '$out/runner/slow.sh' 2>&1 | grep -qv step"
report cli
