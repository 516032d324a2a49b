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
report cli
