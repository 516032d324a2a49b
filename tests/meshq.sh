#!/usr/bin/env bash
# Meshes in constant data on the boards (docs/MESHES.md):
#   - fxrt-scenec --mesh: the C it writes, its summary line, and its
#     refusals (a bad OBJ with the OBJ's FILE:LINE, --max-bytes,
#     --index16, a bad --name, a bad --node), each with nothing written;
#     with --node, the mesh placed as the scene compiler places it, which
#     a program adds with fxrt_add and renders;
#   - instancing: the firmware of a scene with four models of one file
#     is larger than with one by their records, not by the mesh's data;
#   - firmware/meshq.c, built for the host and for the M3, M4F and M0
#     with a model in flash (the cube flat, an icosphere of 320 triangles
#     smooth), answers the same rays with byte-identical results (the
#     FNV hash of every triangle, t, weight and any-hit), and its RAM is
#     the same for both models (a mesh costs no RAM of its own).
set -u
cd "$(dirname "$0")/.."
. tests/lib.sh
M="make --no-print-directory -s BUILD=$BUILD"
SCENEC=$BUILD/fxrt-scenec
tmp=$BUILD/tests/meshq
rm -rf "$tmp"
mkdir -p "$tmp"

# --- fxrt-scenec --mesh ------------------------------------------------------
out=$("$SCENEC" --mesh scenes/models/ico80.obj --out "$tmp/ico80.c" 2>&1)
check "--mesh ico80 writes C" test -s "$tmp/ico80.c"
check "--mesh summary: $out" grep -q '^mesh=scenes/models/ico80.obj triangles=80 vertices=42 .* index_bits=16 dropped=0 normals=smooth$' <<<"$out"
check "--mesh C names ico80_mesh" grep -q '^const fxrt_mesh_t ico80_mesh = {42, 80, ' "$tmp/ico80.c"
check "--mesh C compiles" gcc -std=c11 -Wall -Wextra -Werror -Icore -c "$tmp/ico80.c" -o "$tmp/ico80.o"
out=$("$SCENEC" --mesh scenes/models/cube.obj --flat --name my_cube --out "$tmp/cube.c" 2>&1)
check "--flat --name: no normals, the name given" bash -c "grep -q 'normals=flat' <<<'$out' && grep -q '^const fxrt_mesh_t my_cube = {8, 12, [0-9]*, my_cube_v, NULL, my_cube_tri, NULL, my_cube_node};' '$tmp/cube.c'"
refuse() { # refuse DESCRIPTION EXPECTED-MESSAGE-REGEX ARGS...
    local desc=$1 want=$2 msg rc
    shift 2
    rm -f "$tmp/r.c"
    msg=$("$SCENEC" "$@" --out "$tmp/r.c" 2>&1)
    rc=$?
    check "$desc: exit 2 ($rc)" test $rc -eq 2
    check "$desc: message '$msg'" grep -qE "$want" <<<"$msg"
    check "$desc: nothing written" bash -c "! ls '$tmp' | grep -q '^r\\.c'"
}
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n' >"$tmp/bad.obj"
refuse "an index out of range" "^$tmp/bad.obj:4: " --mesh "$tmp/bad.obj"
refuse "--max-bytes" "^scenes/models/ico320.obj: the mesh needs [0-9]+ bytes of constant data, at most 1000 fit" \
    --mesh scenes/models/ico320.obj --max-bytes 1000
refuse "a bad --name" "bad --name" --mesh scenes/models/ico20.obj --name 9lives
refuse "a keyword as --name" "bad --name" --mesh scenes/models/ico20.obj --name int
# A degenerate triangle of vertices nobody else uses: left out with them (a
# smooth mesh kept a zero normal for them, which bvh_check refuses)
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 5 5 5\nv 6 6 6\nv 7 7 7\nf 1 2 3\nf 1 4 2\nf 5 6 7\n' >"$tmp/lone.obj"
out=$("$SCENEC" --mesh "$tmp/lone.obj" --out "$tmp/lone.c" 2>&1)
check "a dropped triangle's vertices left out: $out" grep -q 'triangles=2 vertices=4 .*dropped=1 normals=smooth' <<<"$out"
check "no zero normal written" bash -c "! grep -q '{0, 0, 0}' '$tmp/lone.c'"
out=$("$SCENEC" --mesh scenes/models/ico20.obj --name _ico_20 --out "$tmp/u.c" 2>&1)
check "--name _ico_20 (a leading underscore): $out" grep -q '^const fxrt_mesh_t _ico_20 = ' "$tmp/u.c"
# 257 x 256 vertices in strips: more than 16-bit indices hold
awk 'BEGIN { for (j = 0; j < 256; j++) for (i = 0; i < 257; i++) printf "v %d %d %d\n", i, j, (i * j) % 7
             for (j = 0; j < 255; j++) for (i = 0; i < 256; i++) { a = j * 257 + i + 1; printf "f %d %d %d\n", a, a + 1, a + 258 } }' >"$tmp/big.obj"
refuse "--index16 on 65,791 vertices" "needs 32-bit indices: 657[0-9]{2} vertices" --mesh "$tmp/big.obj" --flat --index16
out=$("$SCENEC" --mesh "$tmp/big.obj" --flat --out "$tmp/big.c" 2>&1)
check "32-bit indices where 16 do not hold: $out" grep -q 'vertices=657[0-9][0-9] .*index_bits=32' <<<"$out"

# --node: the mesh placed as a scene's node places it (the instance's maps
# equal the scene compiler's for the same node), in every number type,
# and added by the public API it renders where it should
node="scale 2 1 1.5 rotate y 30 rotate x -20 translate 0.5 1 -5"
out=$("$SCENEC" --mesh scenes/models/cube.obj --flat --out "$tmp/placed.c" --node "$node" 2>&1)
check "--node writes cube_mesh_at: $out" grep -q '^const fxrt_instance_t cube_mesh_at = {&cube_mesh,$' "$tmp/placed.c"
for n in 1 2 3; do
    check "--node C compiles (FXRT_NUMBER $n)" gcc -std=c11 -Wall -Wextra -Werror -DFXRT_NUMBER=$n -Icore -c "$tmp/placed.c" -o "$tmp/placed$n.o"
done
mkdir -p "$tmp/sc" "$tmp/scd"
# (a mesh of more than FXRT_MESH_INLINE triangles: a scene makes a model of it)
"$SCENEC" --mesh scenes/models/ico80.obj --out "$tmp/placed80.c" --node "$node" >/dev/null 2>&1
printf 'camera perspective eye 0 0 1 gaze 0 0 -1 up 0 1 0 fov 45\nnode %s\n  mesh file ../../../../scenes/models/ico80.obj color 1 1 1\nend\n' "$node" >"$tmp/sc/p.scene"
"$SCENEC" "$tmp/sc/p.scene" --number q16 --size 32x24 --out "$tmp/scd" >/dev/null 2>&1
maps() { tr -d ' \n' <"$1" | grep -oE '\{\{-?[0-9]+,-?[0-9]+,-?[0-9]+\},\{-?[0-9]+,-?[0-9]+,-?[0-9]+\},\{-?[0-9]+,-?[0-9]+,-?[0-9]+\}\},-?[0-9]+' | tr '\n' ' '; }
# (the instance's maps, before the world in flash, whose model record
# holds the same maps: both must be the tool's)
sed '/^#ifdef SCENE_BOOT_WORLD/,$d' "$tmp/scd/scene_data.h" >"$tmp/scd/inst.h"
sed -n '/^#ifdef SCENE_BOOT_WORLD/,$p' "$tmp/scd/scene_data.h" >"$tmp/scd/world.h"
check "--node's maps are the scene compiler's ($(maps "$tmp/placed80.c"))" test -n "$(maps "$tmp/placed80.c")" -a "$(maps "$tmp/placed80.c")" = "$(maps "$tmp/scd/inst.h")"
check "--node's maps are the world's in flash ($(maps "$tmp/scd/world.h"))" test "$(maps "$tmp/placed80.c")" = "$(maps "$tmp/scd/world.h")"
# Two files and a flat instance, interleaved (A, B, A flat, A): the world's
# model records name the meshes their instances do, and the M3 renders the
# scene from flash as the host does.
mkdir -p "$tmp/sc2"
m=../../../../scenes/models
cat >"$tmp/sc/q.scene" <<EOF2
camera perspective eye 0 1 7 gaze 0 -0.15 -1 up 0 1 0 fov 50
node translate -2.2 0 0
  mesh file $m/ico80.obj color 0.8 0.3 0.2
end
mesh file $m/ico320.obj color 0.2 0.8 0.3
node translate 2.2 0 0
  mesh file $m/ico80.obj shading flat color 0.3 0.2 0.8
end
node translate 0 2 0
  mesh file $m/ico80.obj color 0.9 0.8 0.2
end
EOF2
if "$SCENEC" "$tmp/sc/q.scene" --number q16 --size 64x48 --out "$tmp/sc2" >"$tmp/sc2.log" 2>&1; then
    inst=$(sed '/^#ifdef SCENE_BOOT_WORLD/,$d' "$tmp/sc2/scene_data.h" | grep -oE '^const fxrt_instance_t scene_inst[0-9]+ = \{&[a-z0-9_]+|^static const fxrt_instance_t scene_inst[0-9]+ = \{&[a-z0-9_]+' | sed 's/.*&//' | tr '\n' ' ')
    world=$(sed -n '/^#ifdef SCENE_BOOT_WORLD/,$p' "$tmp/sc2/scene_data.h" | grep -oE '\{\{&scene_mesh[0-9a-z_]+' | sed 's/.*&//' | tr '\n' ' ')
    check "interleaved files: the world's models name their instances' meshes (instances: $inst; world: $world)" \
        test "$inst" = "scene_mesh0 scene_mesh1 scene_mesh0_flat scene_mesh0 " -a "$world" = "$inst"
else
    bad "fxrt-scenec $tmp/sc/q.scene: $(cat "$tmp/sc2.log")"
fi
"$BUILD/fxrt" render "$tmp/sc/q.scene" --number q16 --size 64x48 -o "$tmp/q-host.ppm"
check "interleaved files: M3 run" $M qemu SCENE="$tmp/sc/q.scene" BOARD=mps2-an385 SIZE=64x48
check "interleaved files: the M3's frame (world in flash) is the host's" cmp -s "$tmp/q-host.ppm" "$BUILD/qemu/mps2-an385/q-q16-64x48.ppm"

cat >"$tmp/embed.c" <<'EOF'
#include <stdio.h>
#include "fxrt.h"
extern const fxrt_instance_t cube_mesh_at;
static fxrt_world_t world;
static fxrt_render_t rs;
int main(void)
{
    fxrt_view_t view;
    uint8_t row[FXRT_ROW_BYTES(32)];
    int red = 0;
    fxrt_world_init(&world, FXRT_RGB(0, 0, 0));
    int32_t id = fxrt_add(&world, &(fxrt_object_t){.kind = FXRT_MODEL, .inst = &cube_mesh_at, .color = FXRT_RGB(1, 0, 0)});
    if (id != 0 || fxrt_camera_perspective(&view, fxrt_vec3(0, 0, 0), fxrt_vec3(FXRT_NUM(0.5), FXRT_NUM(1), FXRT_NUM(-5)),
                                           fxrt_vec3(0, FXRT_NUM(1), 0), FXRT_NUM(60), 32, 24) != FXRT_OK ||
        fxrt_render_setup(&rs, &world, &view) != FXRT_OK)
        return 1;
    for (int y = 0; y < 24; y++) {
        if (fxrt_render_row(&rs, y, row, sizeof row) != FXRT_OK)
            return 1;
        for (int x = 0; x < 32; x++)
            red += row[3 * x] == 255 && row[3 * x + 1] == 0;
    }
    printf("red=%d\n", red);
    return red > 0 && red < 32 * 24 ? 0 : 1;
}
EOF
out=$(gcc -std=c11 -O1 -Wall -Wextra -Werror -DFXRT_NUMBER=1 -DFXRT_MULTI -Icore -o "$tmp/embed" "$tmp/embed.c" "$tmp/placed.c" \
    $(for c in core/*/*.c; do r=${c#core/}; r=${r%.c}; case $r in math/fx | math/fx128 | math/trig) ;; *) echo "$BUILD/host/q16/$r.o" ;; esac; done) \
    "$BUILD/host/fx.o" -lm 2>&1 && "$tmp/embed")
check "a program adds cube_mesh_at with fxrt_add and sees it ($out)" grep -qE '^red=[1-9][0-9]*$' <<<"$out"
refuse "--node scale 0" "^fxrt-scenec: --node: scale 0: a node may not scale by 0" --mesh scenes/models/cube.obj --node "scale 0"
refuse "--node beyond the coordinate limit" "^fxrt-scenec: --node: mesh scenes/models/cube.obj, after the node on line 2: it reaches 8192.25 on x, beyond" \
    --mesh scenes/models/cube.obj --node "scale 0.5 translate 8192 0 0"

# Instancing: a scene with four models of one file holds its data once.
# The M3's firmware (text and data) for it is larger than for one model by
# three instances and objects (and the code for four), less than one copy
# of the mesh (1,864 B of ico80), where three copies would be 5,592 B.
mkdir -p "$tmp/inst"
for n in 1 4; do
    {
        echo "camera perspective eye 0 1 6 gaze 0 -0.2 -1 up 0 1 0 fov 40"
        for i in $(seq 1 $n); do
            echo "node scale 0.5 translate $((i - 2)) 0 0"
            echo "  mesh file ../../../../scenes/models/ico80.obj color 0.8 0.2 0.$i"
            echo "end"
        done
    } >"$tmp/inst/i$n.scene"
    $M fw SCENE="$tmp/inst/i$n.scene" BOARD=mps2-an385 NUMBER=q16 SIZE=32x24 >"$tmp/inst/i$n.log" 2>&1
    eval "text$n=\$(arm-none-eabi-size \"$BUILD/fw/mps2-an385/i$n-q16-32x24-full/fxrt.elf\" 2>/dev/null | awk 'NR == 2 { print \$1 + \$2 }')"
done
grow=$((${text4:-0} - ${text1:-0}))
check "four instances of ico80 hold its data once: flash $text1 B with one, $text4 B with four (+$grow B, under 1,864)" \
    test -n "$text1" -a -n "$text4" -a "$grow" -gt 0 -a "$grow" -lt 1864

# --- the same queries on the host and the boards -----------------------------
for spec in t-cube:scenes/models/cube.obj:--flat t-ico320:scenes/models/ico320.obj:; do
    IFS=: read -r name obj flat <<<"$spec"
    args=(MESHQ_OBJ="$obj" MESHQ_RAYS=300 MESHQ_FLAT="$flat")
    progress "meshq.sh: $name on the host"
    if ! $M "$BUILD/meshq/$name/host" "${args[@]}" >"$tmp/$name-build.log" 2>&1; then
        bad "$name: host build: $(tail -n 3 "$tmp/$name-build.log")"
        continue
    fi
    want=$("$BUILD/meshq/$name/host")
    check "$name: the host's queries ($want)" grep -qE '^meshq rays=300 hits=[1-9][0-9]* anys=[1-9][0-9]* fnv=[0-9a-f]{16}$' <<<"$want"
    for b in mps2-an385 mps2-an386 microbit; do
        progress "meshq.sh: $name on $b"
        if ! $M "$BUILD/meshq/$name/$b.elf" "${args[@]}" >"$tmp/$name-$b-build.log" 2>&1; then
            bad "$name $b: build: $(tail -n 3 "$tmp/$name-$b-build.log")"
            continue
        fi
        got=$(timeout 300 qemu-system-arm -M "$b" -nographic -monitor none -serial none \
            -semihosting-config enable=on,target=native -icount shift=5 -kernel "$BUILD/meshq/$name/$b.elf" </dev/null 2>&1)
        check "$name $b: the same results as the host (${got%%$'\n'*})" test "${got%%$'\n'*}" = "$want"
        ram=$(sed -nE 's/.* ram=([0-9]+)$/\1/p' <<<"$got")
        eval "ram_${name//-/_}_${b//-/_}=\${ram:-x}"
        echo "meshq: $name $b ${got#*$'\n'}"
    done
done
for b in mps2-an385 mps2-an386 microbit; do
    v1=ram_t_cube_${b//-/_} v2=ram_t_ico320_${b//-/_}
    check "$b: RAM the same for 12 and 320 triangles (${!v1:-?} B, ${!v2:-?} B)" test "${!v1:-x}" = "${!v2:-y}"
done
report meshq.sh
