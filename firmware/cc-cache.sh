#!/usr/bin/env bash
# A compile cache for firmware objects (FW_CACHE=1, firmware/firmware.mk).
#   firmware/cc-cache.sh CACHE_DIR CC ARGS... -c SRC.c -o OBJ.o
# Every ELF is built from the same core sources, and each object depends on
# its scene only through what the preprocessor makes of it (scene_config.h,
# -D flags): most objects of two ELFs are byte-identical. The key is the
# SHA-1 of the preprocessed source (-P: no line markers, so the ELF
# directory's own paths do not enter it) and of the remaining compiler
# arguments (those that are not preprocessor options: -O2, -mcpu, -W...).
# On a hit the object and its -fstack-usage file are copied from the cache;
# on a miss the source is compiled as make would and both are stored
# (written to a temporary name, then renamed: parallel builds may share
# the cache). The dependency file (-MMD) is always written by the
# preprocessor run itself, so it names this ELF's own headers.
# Builds with -g are not cached (debug information names the directory's
# files); they compile as without the cache.
set -u
cache=$1 cc=$2
shift 2
args=("$@")
out= src= keep=() pre=() debug=0 deps=0
i=0
while [ $i -lt ${#args[@]} ]; do
    a=${args[$i]}
    case $a in
    -o) out=${args[$((i + 1))]}; i=$((i + 2)); continue ;;
    -MMD | -MP) deps=1 ;;
    -include | -I | -D)
        pre+=("$a" "${args[$((i + 1))]}"); i=$((i + 2)); continue ;;
    -I* | -D*) pre+=("$a") ;;
    -c) ;;
    *.c) src=$a ;;
    -g*) debug=1; keep+=("$a") ;;
    *) keep+=("$a") ;;
    esac
    i=$((i + 1))
done
if [ -z "$out" ] || [ -z "$src" ] || [ $debug -eq 1 ]; then
    exec "$cc" "$@"
fi
mkdir -p "$cache"
tmp=$(mktemp "$cache/.tmp.XXXXXX")
trap 'rm -f "$tmp" "$tmp".*' EXIT
# Preprocess (and write the dependency file, as -MMD -MP would).
depargs=()
[ $deps -eq 1 ] && depargs=(-MMD -MP -MF "${out%.o}.d" -MT "$out")
"$cc" "${keep[@]}" "${pre[@]}" "${depargs[@]}" -E -P "$src" -o "$tmp.i" || exit 1
key=$({ printf '%s\n' "$cc" "${keep[@]}" "$src"; cat "$tmp.i"; } | sha1sum | cut -c1-40)
obj=$cache/$key.o su=$cache/$key.su
# -fstack-usage (in the key) writes OBJ's .su next to it: cached with it.
stack=0
for a in "${keep[@]}"; do [ "$a" = -fstack-usage ] && stack=1; done
if [ -f "$obj" ]; then
    if [ $stack -eq 0 ]; then
        cp "$obj" "$out"
        exit
    fi
    cp "$obj" "$out" && cp "$su" "${out%.o}.su"
    exit
fi
"$cc" "${keep[@]}" "${pre[@]}" -c "$src" -o "$out" || exit 1
# The .su first: an object in the cache implies its .su.
if [ $stack -eq 1 ]; then
    cp "${out%.o}.su" "$tmp.su" && mv -f "$tmp.su" "$su"
fi
cp "$out" "$tmp.o" && mv -f "$tmp.o" "$obj"
exit 0
