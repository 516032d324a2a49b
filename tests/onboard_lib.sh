# Shared by tests/qemu.sh, qemu_lit.sh and qemu_trace.sh (sourced, after lib.sh):
# build tests/onboard_main.c for a batch of scenes compiled by fxrt-scenec
# into $onb/scenes/NAME (host q16 frames in $onb/host/NAME.ppm), run it in
# QEMU and give a verdict per scene. Needs $onb and $M (make command).
# onb_batch BOARD TAG NAME...: build and run one ELF; prints a verdict per
# scene (PASS/FAIL/SKIP) on stdout; returns 3 when the ELF overflows RAM.
onb_batch() {
    local b=$1 tag=$2 dir rc n t
    shift 2
    dir=$onb/$b-$tag
    progress "${ONB_WHAT:-qemu.sh: on-board set-up of stress scenes}: $b $tag ($# scenes)"
    tests/onboard_gen.sh "$dir" "${@/#/$onb/scenes/}"
    if ! $M onboard BOARD=$b ONB_DIR="$dir" >"$dir/build.log" 2>&1; then
        grep -q "region .RAM' overflowed" "$dir/build.log" && return 3
        for n in "$@"; do echo "FAIL $b $n: build failed: $(tail -n 2 "$dir/build.log" | tr '\n' ' ')"; done
        return 0
    fi
    (cd "$dir" && timeout "${FXRT_QEMU_TIMEOUT:-300}" qemu-system-arm -M "$(qemu_m $b)" -nographic -monitor none \
        -serial none -semihosting-config enable=on,target=native -icount shift=5 -kernel onboard.elf </dev/null) \
        >"$dir/run.log" 2>&1
    rc=$?
    # Each scene's tick count from the run's report, read once (no process
    # per scene: tests/lib.sh cfg_read). Instructions = ticks x tick period
    # / 2^5 ns (-icount shift=5), rounded half to even as printf does.
    local -A ticks=()
    local line ns2 q r
    while read -r line; do
        [[ $line =~ ^scene=([^ ]+)\ frame_tick_count=([0-9]+)$ ]] && ticks[${BASH_REMATCH[1]}]=${BASH_REMATCH[2]}
    done <"$dir/run.log"
    ns2=$(tick_ns2 $b)
    for n in "$@"; do
        t=${ticks[$n]:-}
        if [ -z "$t" ]; then
            echo "FAIL $b $n: $(grep "^scene=$n " "$dir/run.log" || echo "no report (exit $rc)")"
        elif mv "$dir/$n.ppm.part" "$dir/$n.ppm" && cmp -s "$onb/host/$n.ppm" "$dir/$n.ppm"; then
            q=$((t * ns2 / 64)) r=$((t * ns2 % 64))
            ((r > 32 || (r == 32 && q % 2 == 1))) && q=$((q + 1))
            echo "PASS $b $n instructions=$q"
        else
            echo "FAIL $b $n: frame differs from the host q16 render"
        fi
    done
    [ $rc -eq 0 ] || echo "FAIL $b batch $tag: exit $rc: $(tail -n 3 "$dir/run.log" | tr '\n' ' ')"
    return 0
}
# onb_fit BOARD TAG NAME...: the scenes in as few ELFs as fit the board's
# RAM: the whole batch, and where it overflows each half in turn (TAGa,
# TAGb; the names' order kept), down to single scenes. A build costs a
# few seconds and a failed one as much, so halves, not single scenes
# peeled off one at a time: on the micro:bit a batch typically overflows
# by a few hundred bytes (one feature's state with another's), and
# halving finds the batches that fit in two or three builds where peeling
# took ten. Prints the verdicts, and after each batch that ran
# "stack BOARD TAG ram_static=.. stack_used=.. stack_size=.." and
# "batch BOARD TAG: NAMES"; a single scene that overflows gets a FAIL
# (ONB_TOO_BIG=SKIP: a SKIP, where a scene may be too large for a board).
onb_fit() {
    local b=$1 t=$2 h
    shift 2
    if onb_batch "$b" "$t" "$@"; then
        [ -f "$onb/$b-$t/run.log" ] || return 0 # (a build that failed otherwise: FAIL lines printed)
        echo "stack $b $t $(grep -o 'ram_static=[0-9]* stack_used=[0-9]* stack_size=[0-9]*' "$onb/$b-$t/run.log")"
        echo "batch $b $t: $*"
    elif [ $# -eq 1 ]; then
        echo "${ONB_TOO_BIG:-FAIL} $b $1: does not fit the board's RAM: $(grep -o "region .RAM' overflowed by [0-9]* bytes" "$onb/$b-$t/build.log")"
    else
        h=$((($# + 1) / 2))
        onb_fit "$b" "${t}a" "${@:1:h}"
        onb_fit "$b" "${t}b" "${@:h+1}"
    fi
}
# onb_fit_halves BOARD TAG NAME...: onb_fit on each half (TAGa, TAGb), for
# a batch known not to fit one ELF: its build would fail as halving's first
# step, and a failed build costs as much as one that fits.
onb_fit_halves() {
    local b=$1 t=$2 h
    shift 2
    h=$((($# + 1) / 2))
    onb_fit "$b" "${t}a" "${@:1:h}"
    [ $# -lt 2 ] || onb_fit "$b" "${t}b" "${@:h+1}"
}
qemu_m() { echo "$1"; }
# twice the board's tick period in ns (firmware/firmware.mk TICK_NS_*)
tick_ns2() { case $1 in microbit) echo 125 ;; *) echo 80 ;; esac; }
