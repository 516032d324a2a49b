#!/usr/bin/env bash
# Does a scene fit its board? The firmware's link step (firmware.mk) runs
# this instead of linking directly, so a scene too big for a board fails
# with a message that says what fits, not with the linker's "region 'RAM'
# overflowed", and leaves no ELF.
#
#   firmware/fit.sh link DIR ELF     check, then link ELF (make fw / make qemu)
#   firmware/fit.sh table            RAM per object of each kind and the most
#                                    objects that fit each board (make ram-table;
#                                    RAM_UPDATE_DOCS=1 also rewrites the table
#                                    in docs/BENCHMARKS.md)
#
# Nothing here knows a struct size. Every figure comes from the compiled
# firmware itself:
#  - need: the firmware is first linked against a copy of the board's
#    linker script whose memories are 256 MB long; RAM needed is _estack -
#    ORIGIN(RAM) of that ELF (.data, .bss, alignment and the reserved stack),
#    flash needed is the end of .text plus the .data image.
#  - per object: the sources that hold RAM (probe_sources below) compiled
#    again with one kind's capacity (FXRT_MAX_<KIND> in scene_config.h)
#    raised by 32 objects and linked the same way; RAM per object = the difference / 32, rounded up, from a
#    probe with the scene's own capacities. Probes are compiled without the
#    spheres' row-coherence state (a scene that does not fit with it is
#    built without it), so the figures are those of large scenes; a small
#    scene's sphere state counts in the part "without objects".
# So the figures follow whatever the core's records take today.
# A scene compiled with every sphere's row-coherence state (fxrt-scenec
# --sphere-rows, as make does on every board) that does not fit RAM is
# first compiled again without it (FXRT_COHERENT_SPHERES 0 in DIR's
# scene_config.h, the objects in DIR rebuilt): the state is an optimisation
# (same frames) that the micro:bit keeps only where RAM allows. The
# triangles' shadow edges (FXRT_SHADOW_EDGES) follow, in the same way.
#
# link mode reads what make wrote into DIR: fit-cflags (FW_CFLAGS), fit-src
# (the firmware sources), fit-ldflags (FW_LDFLAGS without -T and -Map), and
# the environment: BOARD, SCENE, ARM_CC, CPU (the board's -mcpu flags),
# FIT_REPORT=1 prints the analysis even when the scene fits; FIT_QUICK=1
# (make bench) only says whether it fits.
set -euo pipefail
BUILD=${BUILD:-build}
ARM_CC=${ARM_CC:-arm-none-eabi-gcc}
KINDS="planes spheres triangles boxes"

die() { echo "fit: $*" >&2; exit 2; }
macro() { case $1 in planes) echo PLANES ;; spheres) echo SPHERES ;; triangles) echo TRIANGLES ;; boxes) echo BOXES ;; esac; }
one() { case $1 in planes) echo plane ;; spheres) echo sphere ;; triangles) echo triangle ;; boxes) echo box ;; esac; }
bytes() { # 16K, 4M, 4096 -> bytes
    local v=$1
    case $v in
        *K) echo $((${v%K} * 1024)) ;;
        *M) echo $((${v%M} * 1024 * 1024)) ;;
        *) echo $((v)) ;;
    esac
}
# board_mem BOARD REGION FIELD(ORIGIN|LENGTH)
board_mem() {
    local v
    v=$(sed -nE "s/^[[:space:]]*$2[[:space:]]*\([a-z]+\)[[:space:]]*:.*$3[[:space:]]*=[[:space:]]*([0-9A-Fa-fxKM]+).*/\1/p" "linker/$1.ld")
    [[ -n $v ]] || die "linker/$1.ld: no $2 $3 in its MEMORY block"
    bytes "$v"
}
sym() { # ELF SYMBOL -> value (decimal)
    local v
    v=$(arm-none-eabi-nm "$1" | awk -v s="$2" '$3 == s { print $1 }')
    [[ -n $v ]] || die "$1: no symbol $2"
    echo $((16#$v))
}

# big_ld BOARD OUT: the board's script with 256 MB memories (same origins,
# same stack, same sections).
big_ld() {
    sed -E 's/LENGTH[[:space:]]*=[[:space:]]*[0-9A-Fa-fxKM]+/LENGTH = 256M/' "linker/$1.ld" >"$2"
}

# trial_link OBJDIR OUT.elf: link the objects of OBJDIR (where OBJDIR
# lacks one, DIR's) against the big script; prints "RAM FLASH" needed in
# bytes.
trial_link() {
    local objdir=$1 elf=$2 objs=() s
    for s in $SRC; do
        if [[ -f $objdir/${s%.c}.o ]]; then objs+=("$objdir/${s%.c}.o"); else objs+=("$DIR/${s%.c}.o"); fi
    done
    "$ARM_CC" $CPU -o "$elf" "${objs[@]}" "${LDFLAGS[@]}" -T"$WORK/big.ld" >"$elf.log" 2>&1 ||
        { cat "$elf.log" >&2; die "trial link of $elf failed"; }
    local estack sidata sdata edata
    estack=$(sym "$elf" _estack) sidata=$(sym "$elf" _sidata) sdata=$(sym "$elf" _sdata) edata=$(sym "$elf" _edata)
    echo "$((estack - RAM_ORIGIN)) $((sidata - FLASH_ORIGIN + edata - sdata))"
}

# compile_all OUTDIR WHAT FLAGS...: every firmware source ($SRC, or
# $ONLY where set) compiled with FLAGS into OUTDIR/<source>.o side by side
# (errors in OUTDIR/<source>.log); dies naming WHAT when one fails.
compile_all() {
    local out=$1 what=$2 s pids=()
    shift 2
    for s in ${ONLY:-$SRC}; do
        mkdir -p "$out/$(dirname "$s")"
        "$ARM_CC" "$@" -c "$s" -o "$out/${s%.c}.o" 2>"$out/${s%.c}.log" &
        pids+=($!)
    done
    for s in "${pids[@]}"; do wait "$s" || { cat "$out"/*/*.log >&2; die "$what failed"; }; done
}

# probe KIND CAP: compile every firmware source with FXRT_MAX_<KIND> = CAP
# (KIND base: the scene's capacities) into $WORK/KIND-CAP/, link it; prints
# "RAM FLASH". Probes keep no sphere row-coherence state
# (FXRT_COHERENT_SPHERES 0) and no shadow edges (FXRT_SHADOW_EDGES 0): a
# scene of many objects is built without them where they do not fit (link
# mode above), so the figures per object and the most objects that fit are
# those without them; its flat pieces keep their guesses.
probe() {
    local kind=$1 cap=$2 pdir=$WORK/$1-$2 s flags=()
    mkdir -p "$pdir"
    sed -E -e "s/^#define FXRT_MAX_$(macro "$kind") .*/#define FXRT_MAX_$(macro "$kind") $cap/" \
        -e '/^#define FXRT_(COHERENT_SPHERES |NO_COHERENCE |SHADOW_EDGES )/d' "$DIR/scene_config.h" >"$pdir/scene_config.h"
    printf '#define FXRT_COHERENT_SPHERES 0\n#define FXRT_SHADOW_EDGES 0\n' >>"$pdir/scene_config.h"
    # A box brings its faces: when the scene compiler sized the face pool
    # (FXRT_RENDER_BOX_FACES, the faces this camera needs), the extra boxes
    # get as many faces as the scene's boxes have on average, so the per-box
    # figure includes them.
    local faces nbox
    faces=$(sed -nE 's/^#define FXRT_RENDER_BOX_FACES ([0-9]+).*/\1/p' "$DIR/scene_config.h")
    nbox=$(sed -nE 's/^#define FXRT_MAX_BOXES ([0-9]+).*/\1/p' "$DIR/scene_config.h")
    if [[ $kind == boxes && -n $faces && ${nbox:-0} -gt 0 ]]; then
        local more=$((((cap - nbox) * faces + nbox - 1) / nbox))
        sed -i -E "s/^#define FXRT_RENDER_BOX_FACES .*/#define FXRT_RENDER_BOX_FACES $((faces + more))/" \
            "$pdir/scene_config.h"
    fi
    for s in "${CFLAGS[@]}"; do
        [[ $s == "$DIR/scene_config.h" ]] && s=$pdir/scene_config.h
        flags+=("$s")
    done
    ONLY=$PROBE_SRC compile_all "$pdir" "probe compile ($kind = $cap)" "${flags[@]}"
    trial_link "$pdir" "$pdir/probe.elf"
}

# probe_sources: sets PROBE_SRC, the sources a probe compiles again:
# firmware/main.c (the program's fxrt_t: the world's and the renderer's
# arrays, sized by the capacities), core/frame/api.c (the core's stack
# reservation and its capacity constants) and any other source whose
# object in DIR holds RAM. The core keeps no RAM of its own beyond those
# two (tests/freestanding.sh checks it with every kind compiled in), so
# the others' objects, whose code alone changes with a capacity, are
# DIR's. RAM figures are exact; flash per object counts main.c's and
# api.c's growth.
probe_sources() {
    local s
    PROBE_SRC="firmware/main.c core/frame/api.c"
    for s in $SRC; do
        [[ " $PROBE_SRC " == *" $s "* ]] && continue
        if arm-none-eabi-nm "$DIR/${s%.c}.o" | awk '$2 ~ /^[BbDdCcGgSs]$/ && $3 != "fxrt_stats" { f = 1 } END { exit !f }'; then
            PROBE_SRC+=" $s"
        fi
    done
}

# analyse: sets PER_<kind> (RAM bytes per object), FLASHPER_<kind>, COUNT_<kind>,
# FIXED (RAM for everything but the objects) from the scene in DIR.
analyse() {
    local k m n ra fa rb fb sum=0
    [[ -n ${PROBE_SRC:-} ]] || probe_sources # (link mode may have found them already)
    read -r rb fb < <(probe base 0) # the differences are taken without the spheres' row coherence
    for k in $KINDS; do
        m=$(macro "$k")
        n=$(sed -nE "s/^#define FXRT_MAX_$m ([0-9]+).*/\1/p" "$DIR/scene_config.h")
        [[ -n $n ]] || die "$DIR/scene_config.h: no FXRT_MAX_$m"
        read -r ra fa < <(probe "$k" $((n + 32)))
        printf -v "COUNT_$k" '%s' "$n"
        # rounded up: a kind the scene lacks also brings its array's alignment
        printf -v "PER_$k" '%s' "$(((ra - rb + 31) / 32))"
        printf -v "FLASHPER_$k" '%s' "$(((fa - fb + 31) / 32))"
        local per_var=PER_$k
        sum=$((sum + n * ${!per_var}))
    done
    FIXED=$((NEED_RAM - sum))
}

# setup DIR: read what make wrote, parse the board's memories.
setup() {
    DIR=$1
    [[ -n ${BOARD:-} ]] || die "BOARD is not set"
    [[ -f linker/$BOARD.ld ]] || die "no linker/$BOARD.ld"
    local f
    for f in fit-cflags fit-src fit-ldflags scene_config.h; do
        [[ -f $DIR/$f ]] || die "$DIR/$f is missing (written by the fw link rule in firmware/firmware.mk)"
    done
    eval "CFLAGS=($(cat "$DIR/fit-cflags"))"
    eval "LDFLAGS=($(cat "$DIR/fit-ldflags"))"
    SRC=$(cat "$DIR/fit-src")
    RAM_ORIGIN=$(board_mem "$BOARD" RAM ORIGIN) RAM_LEN=$(board_mem "$BOARD" RAM LENGTH)
    FLASH_ORIGIN=$(board_mem "$BOARD" FLASH ORIGIN) FLASH_LEN=$(board_mem "$BOARD" FLASH LENGTH)
    WORK=$DIR/fit
    rm -rf "$WORK"
    mkdir -p "$WORK"
    big_ld "$BOARD" "$WORK/big.ld"
}

# The most objects that fit: of one kind alone, and mixed (one plane and
# equal numbers of spheres, triangles and boxes).
alone() { local v=PER_$1; echo $(((RAM_LEN - FIXED) / ${!v})); }
mixed() {
    local m=$(((RAM_LEN - FIXED - PER_planes) / (PER_spheres + PER_triangles + PER_boxes)))
    [[ $m -lt 0 ]] && m=0
    echo $((1 + 3 * m))
}

# without ON OFF TAG WHAT MESSAGE (link mode): where the scene needs more
# RAM than the board has and DIR's scene_config.h says "#define ON", it
# says "#define OFF" instead (an optimisation that keeps the frames) and
# the scene is compiled again. RAM first, from the sources that hold it
# (probe_sources): a scene that does not fit without it either is not
# compiled again (its message gives that RAM, and the flash of the build
# with it). Updates NEED_RAM and NEED_FLASH.
without() {
    local on=$1 off=$2 tag=$3 what=$4 msg=$5
    [[ $NEED_RAM -gt $RAM_LEN ]] && grep -q "^#define $on\$" "$DIR/scene_config.h" || return 0
    sed -i -E "s|^#define $on\$|#define $off /* firmware/fit.sh: $what do not fit */|" "$DIR/scene_config.h"
    probe_sources
    ONLY=$PROBE_SRC compile_all "$WORK/$tag" "compile without $what" "${CFLAGS[@]}"
    read -r NEED_RAM _ < <(trial_link "$WORK/$tag" "$WORK/$tag.elf")
    if [[ $NEED_RAM -le $RAM_LEN ]]; then
        compile_all "$DIR" "compile without $what" "${CFLAGS[@]}" -MMD -MP
        read -r NEED_RAM NEED_FLASH < <(trial_link "$DIR" "$WORK/trial.elf")
    fi
    [[ ${FIT_REPORT:-0} == 1 ]] && echo "fit: $BOARD: $msg" >&2
    return 0
}

if [[ ${1:-} == link ]]; then
    [[ $# -eq 3 ]] || die "usage: firmware/fit.sh link DIR ELF"
    setup "$2"
    elf=$3
    rm -f "$elf"
    read -r NEED_RAM NEED_FLASH < <(trial_link "$DIR" "$WORK/trial.elf")
    # Sphere rows where RAM allows: a scene compiled with every sphere's
    # row-coherence state (fxrt-scenec --sphere-rows, which make passes on
    # every board) that does not fit RAM is compiled again without it
    # (FXRT_COHERENT_SPHERES 0: the frames are the same, the spheres find
    # their runs without the row before's), and everything below is decided
    # for that build. Then the same for the triangles' shadow edges
    # (FXRT_SHADOW_EDGES 0: the same frames, shadow rays in a triangle's
    # cone take its exact test).
    without 'FXRT_COHERENT_SPHERES FXRT_MAX_SPHERES' 'FXRT_COHERENT_SPHERES 0' norows \
        "sphere rows" "the spheres' row state does not fit; built without it"
    without 'FXRT_SHADOW_EDGES 1' 'FXRT_SHADOW_EDGES 0' noedges \
        "shadow edges" "the triangles' shadow edges do not fit; built without them"
    if [[ ${FIT_QUICK:-0} == 1 && ( $NEED_RAM -gt $RAM_LEN || $NEED_FLASH -gt $FLASH_LEN ) ]]; then
        # make bench: only the verdict, without the per-kind probes
        echo "${SCENE:-$DIR}: does not fit $BOARD ($RAM_LEN B RAM, $FLASH_LEN B flash): needs $NEED_RAM B RAM, $NEED_FLASH B flash (FIT_QUICK=1: no per-kind figures)" >&2
        rm -rf "$WORK"
        exit 1
    fi
    if [[ ${FIT_REPORT:-0} == 1 || $NEED_RAM -gt $RAM_LEN || $NEED_FLASH -gt $FLASH_LEN ]]; then
        analyse
        {
            printf 'FIT board=%s ram=%s flash=%s need_ram=%s need_flash=%s fixed=%s' \
                "$BOARD" "$RAM_LEN" "$FLASH_LEN" "$NEED_RAM" "$NEED_FLASH" "$FIXED"
            for k in $KINDS; do
                p=PER_$k f=FLASHPER_$k c=COUNT_$k
                printf ' %s=%s per_%s=%s flash_per_%s=%s alone_%s=%s' "$k" "${!c}" "$k" "${!p}" "$k" "${!f}" "$k" "$(alone "$k")"
            done
            printf ' mixed=%s\n' "$(mixed)"
        } >"$WORK/report"
        [[ ${FIT_REPORT:-0} == 1 ]] && cat "$WORK/report"
    fi
    if [[ $NEED_RAM -gt $RAM_LEN && $FIXED -ge $RAM_LEN ]]; then
        # What to change: the samples' width when there are samples, a
        # smaller frame, and streaming unless the build already streams.
        samples=$(sed -nE 's/^#define FXRT_MAX_SAMPLES ([0-9]+).*/\1/p' "$DIR/scene_config.h")
        width=$(sed -nE 's/^#define SCENE_WIDTH ([0-9]+).*/\1/p' "$DIR/scene_config.h")
        advice="a smaller frame (SIZE=WxH)"
        [[ ${samples:-1} -gt 1 ]] && advice="fewer samples or a narrower frame: with samples ${samples}, the renderer holds ${samples} x ${width} = $((samples * width)) columns; or $advice"
        grep -q -- '-DFXRT_FB_MODE=2' "$DIR/fit-cflags" || advice+=", or streaming mode (FB=stream)"
        echo "${SCENE:-$DIR}: does not fit $BOARD ($RAM_LEN B RAM): needs $NEED_RAM B; even without objects the frame, stack and renderer state take $FIXED B, so no object fits: use $advice." >&2
        rm -rf "$WORK"/*-*/
        exit 1
    fi
    if [[ $NEED_RAM -gt $RAM_LEN ]]; then
        what=""
        for k in $KINDS; do
            c=COUNT_$k p=PER_$k
            [[ ${!c} -gt 0 ]] && what+="${what:+, }${!c} $([[ ${!c} -eq 1 ]] && one "$k" || echo "$k") x ${!p} B"
        done
        {
            echo "${SCENE:-$DIR}: does not fit $BOARD ($RAM_LEN B RAM): needs $NEED_RAM B ($what; the frame, stack and renderer state without objects take $FIXED B);"
            echo "  at most $(alone spheres) spheres, or $(alone triangles) triangles, or $(alone boxes) boxes, or $(alone planes) planes fit (one kind alone),"
            echo "  or $(mixed) mixed objects (one plane and equal numbers of spheres, triangles and boxes)."
            echo "  RAM per object: plane $PER_planes B, sphere $PER_spheres B, triangle $PER_triangles B, box $PER_boxes B (measured from this build: firmware/fit.sh)."
        } >&2
        rm -rf "$WORK"/*-*/
        exit 1
    fi
    if [[ $NEED_FLASH -gt $FLASH_LEN ]]; then
        echo "${SCENE:-$DIR}: does not fit $BOARD ($FLASH_LEN B flash): needs $NEED_FLASH B of flash (code and the const scene; flash per object: plane $FLASHPER_planes B, sphere $FLASHPER_spheres B, triangle $FLASHPER_triangles B, box $FLASHPER_boxes B)." >&2
        exit 1
    fi
    # It fits: the real link, against the board's own script.
    "$ARM_CC" $CPU -o "$elf" $(for s in $SRC; do printf '%s ' "$DIR/${s%.c}.o"; done) "${LDFLAGS[@]}" \
        -Wl,-Map="$DIR/fxrt.map" -T"linker/$BOARD.ld"
    rm -rf "$WORK"
    exit 0
fi

# make ram-table: one probe scene (a plane, a sphere, a triangle and a box)
# at FIT_SIZE on every board in its default frame mode; a markdown table.
if [[ ${1:-} == table ]]; then
    size=${FIT_SIZE:-160x120}
    info=${BENCH_BOARD_INFO:-"mps2-an385:M3:full mps2-an386:M4F:full microbit:M0:stream"}
    mkdir -p "$BUILD/fit"
    # Two probe scenes, the same objects: unlit (flat colours, lighting
    # compiled out) and lit (one point light with shadows, Phong materials:
    # each object then also keeps its shading constants and its shadow-ray
    # culling entries). The box is in general position, so the eye sees
    # three of its faces, the most a box seen from outside in perspective
    # can need (an orthographic camera, or an eye inside the box, needs up
    # to six: a figure per box that such scenes exceed).
    probe_scene() { # FILE lit(0|1)
        local mat=""
        [[ $2 == 1 ]] && mat=" material phong specular 0.5 0.5 0.5 exponent 32"
        {
            echo "# firmware/fit.sh table: one object of each kind"
            echo "camera perspective eye 0 0 0 gaze 0 0 -1 up 0 1 0 fov 45"
            [[ $2 == 1 ]] && echo "light point position 2 4 1 color 1 1 1"
            echo "plane point 0 -2 0 normal 0 1 0 color 0.2 0.6 0.2$mat"
            echo "sphere center -1 0 -4 radius 0.5 color 0.9 0.2 0.2$mat"
            echo "triangle a 0 0 -4 b 1 0 -4 c 0.5 1 -4 color 0.2 0.2 0.9$mat"
            echo "box min 0.5 -1.5 -5 max 1.5 -0.5 -4 color 0.9 0.9 0.2$mat"
        } >"$1"
    }
    tab=$BUILD/fit/ram-table.md
    {
    echo "RAM per object and the most objects that fit, Q16.16 firmware at $size (\`make ram-table\`, measured by firmware/fit.sh from the compiled firmware; $(git rev-parse --short HEAD 2>/dev/null || echo unknown), $(date -u '+%Y-%m-%d'))."
    echo
    echo "| board | frame | scene | RAM | RAM without objects | plane | sphere | triangle | box | most planes | most spheres | most triangles | most boxes | most mixed |"
    echo "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
    for i in $info; do
        b=${i%%:*} cpu=$(cut -d: -f2 <<<"$i") fb=${i##*:}
        for lit in 0 1; do
            scene=$BUILD/fit/probe-$([[ $lit == 1 ]] && echo lit || echo unlit).scene
            probe_scene "$scene" $lit
            out=$(make -s --no-print-directory BUILD="$BUILD" fw SCENE="$scene" BOARD="$b" NUMBER=q16 SIZE="$size" FB="$fb" \
                FIT_REPORT=1 2>&1) || { echo "$out" >&2; die "make fw of $scene for $b failed"; }
            line=$(grep '^FIT ' <<<"$out" | tail -n 1)
            [[ -n $line ]] || { echo "$out" >&2; die "no FIT line for $b"; }
            g() { sed -nE "s/.*(^| )$1=([^ ]+).*/\2/p" <<<"$line"; }
            # (the probe's box must need its 3 faces, or its figure is not the worst case)
            faces=$(sed -nE 's/^#define FXRT_RENDER_BOX_FACES ([0-9]+).*/\1/p' \
                "$BUILD/fw/$b/$(basename "$scene" .scene)-q16-$size-$fb/scene_config.h")
            [[ $faces == 3 ]] || die "the probe's box needs ${faces:-no} faces, not 3"
            printf '| %s (%s) | %s | %s | %s | %s | %s B | %s B | %s B | %s B | %s | %s | %s | %s | %s |\n' "$b" "$cpu" "$fb" \
                "$([[ $lit == 1 ]] && echo "lit (1 point light, shadows, Phong)" || echo unlit)" \
                "$(g ram)" "$(g fixed)" "$(g per_planes)" "$(g per_spheres)" "$(g per_triangles)" "$(g per_boxes)" \
                "$(g alone_planes)" "$(g alone_spheres)" "$(g alone_triangles)" "$(g alone_boxes)" "$(g mixed)"
        done
    done
    echo
    echo "\"Most\" counts are of one kind alone (with the frame, stack and renderer state of a scene that uses every kind);"
    echo "\"mixed\" is one plane and equal numbers of spheres, triangles and boxes. A scene file also has the host's"
    echo "per-kind capacity (FXRT_MAX_* in core/fxrt_config.h), which fxrt-scenec applies when it reads the scene."
    } >"$tab"
    cat "$tab"
    if [[ ${RAM_UPDATE_DOCS:-0} == 1 ]]; then
        doc=docs/BENCHMARKS.md
        host/replace-block.sh --pad "$doc" ram:table "$tab" || exit 1
        echo "fit: updated the RAM table in $doc" >&2
    fi
    exit 0
fi

die "usage: firmware/fit.sh link DIR ELF (the fw link step) | firmware/fit.sh table"
