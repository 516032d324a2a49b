#!/usr/bin/env bash
# Extreme scenes (issue "numerical stability", part 3). Every scene in
# scenes/stress/ is rendered with --number double, q16 and float and checked
# against the expectations in its own header, one per line:
#
#   # expect: q16 vs double: mismatched_pct <= 0.05, interior_mismatched == 0
#       metrics of "fxrt compare DOUBLE-RENDER OTHER-RENDER" (q16 or float
#       against double); any key of the compare line, conditions joined by ","
#   # expect: all: background == all
#   # expect: q16,float: color 255 0 255 >= 100
#   # expect: all: holes == 0
#       pixel counts of the renders named before the colon ("all" = double,
#       q16 and float): background = pixels of the scene's background colour,
#       color R G B = pixels of that 8-bit colour, holes = background pixels
#       with a non-background pixel on both sides in their row or in their
#       column (a convex shape has none: a hole is a leak).
#       The right-hand side is a number or "all" (every pixel).
#   # expect: rejected: LINE: message fragment
#       every build refuses the scene: exit 2, "FILE:LINE: ..." containing
#       the fragment on stderr, nothing on stdout and no output file.
#
# Each threshold is explained next to it in the scene file. The suite prints
# each scene's compare lines and pixel counts, and ends with
# "stress_scenes: N passed, N failed".
set -u
. "$(dirname "$0")/lib.sh"
out=$BUILD/tests/stress
dir=${STRESS_DIR:-scenes/stress}
rm -rf "$out"
mkdir -p "$out"

# metric KEY LINE: value of KEY=... in a compare line (empty if absent)
metric() { sed -nE "s/.*(^| )$1=([^ ]+).*/\2/p" <<<"$2"; }

# cmp_num A OP B: numeric comparison (decimals allowed)
cmp_num() {
    awk -v a="$1" -v op="$2" -v b="$3" 'BEGIN {
        if (a !~ /^-?[0-9]+(\.[0-9]+)?$/ || b !~ /^-?[0-9]+(\.[0-9]+)?$/) exit 2
        a += 0; b += 0
        if (op == "==") exit !(a == b)
        if (op == "<=") exit !(a <= b)
        if (op == ">=") exit !(a >= b)
        if (op == "<") exit !(a < b)
        if (op == ">") exit !(a > b)
        exit 2 }'
}

# background_rgb SCENE: the 8-bit background colour, as the renderer
# rounds it (c * 255 + 0.5, truncated); black when there is no such line.
background_rgb() {
    awk '{ sub(/#.*/, "") } $1 == "background" { r = $2; g = $3; b = $4 }
        END {
            if (r == "") { print "0 0 0"; exit }
            printf "%d %d %d\n", int(r * 255 + 0.5), int(g * 255 + 0.5), int(b * 255 + 0.5)
        }' "$1"
}

# pixel_stats PPM BG_R BG_G BG_B > STATS: lines "pixels N", "background N",
# "holes N" and "color R G B N" for every colour present.
pixel_stats() {
    local ppm=$1 magic w h maxval
    {
        read -r magic
        read -r w h
        read -r maxval
    } <"$ppm"
    if [ "$magic" != P6 ] || [ "$maxval" != 255 ]; then
        echo "pixel_stats: $ppm is not an 8-bit binary PPM" >&2
        return 1
    fi
    tail -c $((w * h * 3)) "$ppm" | od -An -v -tu1 -w3 | awk -v W="$w" -v H="$h" -v bg="$2 $3 $4" '
        { i = NR - 1; x = i % W; y = int(i / W); key = $1 " " $2 " " $3
          hist[key]++; isbg[i] = (key == bg)
          if (!isbg[i]) {
              if (!(y in rmin) || x < rmin[y]) rmin[y] = x
              if (!(y in rmax) || x > rmax[y]) rmax[y] = x
              if (!(x in cmin) || y < cmin[x]) cmin[x] = y
              if (!(x in cmax) || y > cmax[x]) cmax[x] = y
          } }
        END {
            holes = 0
            for (i = 0; i < NR; i++) {
                if (!isbg[i]) continue
                x = i % W; y = int(i / W)
                if ((y in rmin && rmin[y] < x && x < rmax[y]) || (x in cmin && cmin[x] < y && y < cmax[x]))
                    holes++
            }
            print "pixels " NR
            print "background " (bg in hist ? hist[bg] : 0)
            print "holes " holes
            for (k in hist) print "color " k " " hist[k]
        }'
}

# stat_of STATS WHAT: the count of WHAT ("background", "holes", "color R G B")
stat_of() {
    awk -v what="$2" '{ v = $NF; $NF = ""; sub(/ $/, "") } $0 == what { print v; found = 1 }
        END { if (!found) print 0 }' "$1"
}

# numbers_of SPEC: "all" -> "double q16 float", "q16,float" -> "q16 float"
numbers_of() {
    if [ "$1" = all ]; then echo "double q16 float"; else tr ',' ' ' <<<"$1"; fi
}

# check_rejected SCENE NAME LINE FRAGMENT
check_rejected() {
    local scene=$1 name=$2 line=$3 frag=$4 n rc err
    for n in double q16 float; do
        rm -f "$out/$name-$n.ppm"
        "$FXRT" render "$scene" --number $n -o "$out/$name-$n.ppm" >"$out/$name-$n.stdout" 2>"$out/$name-$n.stderr"
        rc=$?
        err=$(head -c 300 "$out/$name-$n.stderr")
        [ $n = q16 ] && echo "$name: rejected (exit $rc): $err"
        check "$name $n: exit status 2 (got $rc)" test "$rc" -eq 2
        check "$name $n: message starts '$scene:$line: ' (got: $err)" grep -qF -- "$scene:$line: " "$out/$name-$n.stderr"
        check "$name $n: message says '$frag' (got: $err)" grep -qF -- "$frag" "$out/$name-$n.stderr"
        check "$name $n: nothing on stdout" test ! -s "$out/$name-$n.stdout"
        check "$name $n: no output file" test ! -e "$out/$name-$n.ppm"
    done
}

# check_conditions NAME WHAT LINE CONDS: CONDS = "key op value, ..." on a
# compare line
check_conditions() {
    local name=$1 what=$2 line=$3 conds=$4 cond key op val got
    IFS=',' read -ra parts <<<"$conds"
    for cond in "${parts[@]}"; do
        read -r key op val rest <<<"$cond"
        got=$(metric "$key" "$line")
        if [ -z "$got" ] || [ -n "${rest:-}" ]; then
            bad "$name: unusable condition '$cond' (metric '$key' not in: $line)"
            continue
        fi
        check "$name $what: $key $op $val (got $got)" cmp_num "$got" "$op" "$val"
    done
}

nscenes=0
for scene in "$dir"/*.scene; do
    [ -e "$scene" ] || continue
    nscenes=$((nscenes + 1))
    name=$(basename "$scene" .scene)
    mapfile -t expects < <(sed -n 's/^# expect: //p' "$scene" | tr -d '\r')
    if [ "${#expects[@]}" -eq 0 ]; then
        bad "$name: no '# expect:' line in $scene"
        continue
    fi

    # Rejected scenes: no render, only the refusal.
    rejected=0
    for e in "${expects[@]}"; do
        if [[ $e =~ ^rejected:\ ([0-9]+):\ (.+)$ ]]; then
            rejected=1
            check_rejected "$scene" "$name" "${BASH_REMATCH[1]}" "${BASH_REMATCH[2]}"
        fi
    done
    if [ $rejected -eq 1 ]; then
        [ "${#expects[@]}" -eq 1 ] || bad "$name: a rejected scene has no other expectations"
        continue
    fi

    bg=$(background_rgb "$scene")
    rendered=1
    for n in double q16 float; do
        if ! "$FXRT" render "$scene" --number $n -o "$out/$name-$n.ppm" 2>"$out/$name-$n.stderr"; then
            bad "$name: render --number $n failed: $(head -c 300 "$out/$name-$n.stderr")"
            rendered=0
            continue
        fi
        # shellcheck disable=SC2086
        pixel_stats "$out/$name-$n.ppm" $bg >"$out/$name-$n.stats"
    done
    [ $rendered -eq 1 ] || continue
    for n in q16 float; do
        line=$("$FXRT" compare "$out/$name-double.ppm" "$out/$name-$n.ppm" --diff "$out/$name-$n-diff.png")
        echo "$line" >"$out/$name-$n.compare"
        echo "$name $n vs double: $line"
    done
    for n in double q16 float; do
        echo "$name $n: background=$(stat_of "$out/$name-$n.stats" background)" \
            "holes=$(stat_of "$out/$name-$n.stats" holes)" \
            "colors=$(grep -c '^color ' "$out/$name-$n.stats")"
    done

    for e in "${expects[@]}"; do
        if [[ $e =~ ^(q16|float)\ vs\ double:\ (.+)$ ]]; then
            n=${BASH_REMATCH[1]}
            check_conditions "$name" "$n vs double" "$(cat "$out/$name-$n.compare")" "${BASH_REMATCH[2]}"
        elif [[ $e =~ ^([a-z0-9,]+):\ (background|holes|color\ [0-9]+\ [0-9]+\ [0-9]+)\ (==|<=|>=|<|>)\ ([0-9]+|all)$ ]]; then
            what=${BASH_REMATCH[2]} op=${BASH_REMATCH[3]} val=${BASH_REMATCH[4]}
            for n in $(numbers_of "${BASH_REMATCH[1]}"); do
                if [ ! -f "$out/$name-$n.stats" ]; then
                    bad "$name: unknown number '$n' in '$e'"
                    continue
                fi
                v=$val
                [ "$v" = all ] && v=$(stat_of "$out/$name-$n.stats" pixels)
                got=$(stat_of "$out/$name-$n.stats" "$what")
                check "$name $n: $what $op $val (got $got)" cmp_num "$got" "$op" "$v"
            done
        else
            bad "$name: cannot parse expectation '$e'"
        fi
    done
done
check "scenes found in $dir" test "$nscenes" -gt 0
report stress_scenes
