#!/usr/bin/env bash
# The oracle suite (docs/TESTING.md, "The oracle"):
#  - build/tests/oracle on every scene file (scenes/*.scene, scenes/*/*.scene)
#    and ORACLE_TEST_SCENES random scenes (default 1000, seeds from 1), fast
#    renderer against the per-pixel ray caster in Q16.16 and in double,
#    known findings listed in tests/oracle-known.txt;
#  - the generated "# expect:" lines of scenes/stress/*.scene (the unlit
#    ones) equal what `oracle --stress-expect` generates now (make
#    stress-expect rewrites them).
# Ends with "oracle: N passed, N failed".
set -u
. "$(dirname "$0")/lib.sh"
ORACLE=${ORACLE:-$BUILD/tests/oracle}
n=${ORACLE_TEST_SCENES:-1000}
scenes=()
for f in scenes/*.scene scenes/*/*.scene; do [ -f "$f" ] && scenes+=("$f"); done

# run_part NAME CMD...: runs CMD, shows its output, adds its result line.
run_part() {
    local name=$1 out rc line p f
    shift
    out=$("$@" 2>&1)
    rc=$?
    echo "$out" | grep -v '^  ' | grep -v '^KNOWN FINDING' || true
    line=$(grep -E '^[a-z-]+: [0-9]+ passed, [0-9]+ failed$' <<<"$out" | tail -n 1)
    if [ -z "$line" ]; then
        bad "$name: no result line (exit $rc)"
        return
    fi
    p=$(sed -E 's/.* ([0-9]+) passed.*/\1/' <<<"$line")
    f=$(sed -E 's/.* ([0-9]+) failed.*/\1/' <<<"$line")
    PASSED=$((PASSED + p))
    FAILED=$((FAILED + f))
    if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then bad "$name: exit $rc"; fi
    if [ "$f" -ne 0 ]; then echo "$out" | grep -E '^(FAIL|  )' | head -n 40; fi
}

check "scene files found" test "${#scenes[@]}" -gt 0
run_part oracle "$ORACLE" --known tests/oracle-known.txt --random "$n" --seed 1 "${scenes[@]}"
# Lit stress scenes (lights, ambient, lambert or phong) are left out of
# the generated colour counts: shading makes a colour per pixel, so their
# expectations are written by hand (tests/stress_scenes.sh).
flat_stress=()
for f in scenes/stress/*.scene; do
    grep -qE '^[[:space:]]*(light|ambient)[[:space:]]|[[:space:]]material[[:space:]]+(lambert|phong)' "$f" ||
        flat_stress+=("$f")
done
run_part stress-expect "$ORACLE" --stress-expect "${flat_stress[@]}"
report oracle
