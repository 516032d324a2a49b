#!/usr/bin/env bash
# The pictures in docs/, drawn by the project's own tools (make doc-images):
#   docs/img/demo-course-phong-point.png  make demo's sheet of the course's
#       Phong scene: Q16.16 on the Cortex-M3 in QEMU | the host's double
#       render | their difference (build/demo/course-phong-point-sheet.png)
#   docs/img/demo-reflection.png          the same for the reflection scene
#   docs/img/oled-shadows-sheet.png       make demo's OLED sheet of lit/shadows:
#       host | host dithered | QEMU's display (firmware/oled/oled-demo.sh)
#   docs/lit/*.png, docs/trace/*.png      Q16.16 host renders at 320x240,
#       side by side under their names (fxrt render, fxrt sheet)
# DOC_IMAGES_NO_DEMO=1 skips make demo (the lit and trace sheets only).
set -euo pipefail
BUILD=${BUILD:-build}
FXRT=${FXRT:-$BUILD/fxrt}
out=$BUILD/docimages
mkdir -p "$out" docs/img docs/lit docs/trace

if [[ ${DOC_IMAGES_NO_DEMO:-0} != 1 ]]; then
    make -s --no-print-directory BUILD="$BUILD" demo
    cp "$BUILD/demo/course-phong-point-sheet.png" docs/img/demo-course-phong-point.png
    cp "$BUILD/demo/reflection-sheet.png" docs/img/demo-reflection.png
    cp "$BUILD/demo/oled-shadows-sheet.png" docs/img/oled-shadows-sheet.png
fi

# sheet OUT SCENE[=LABEL]...: each scene rendered in Q16.16 at 320x240
sheet() {
    local dst=$1 arg scene label args=()
    shift
    for arg in "$@"; do
        scene=${arg%%=*} label=${arg#*=}
        [[ $arg == *=* ]] || label=$(basename "$scene" .scene)
        "$FXRT" render "$scene" --size 320x240 -o "$out/$(basename "$scene" .scene).png"
        args+=("$out/$(basename "$scene" .scene).png=$label")
    done
    "$FXRT" sheet -o "$dst" "${args[@]}"
}
sheet docs/lit/course.png scenes/lit/course-lambert-point.scene=lambert-point \
    scenes/lit/course-lambert-directional.scene=lambert-directional scenes/lit/course-lambert-spot.scene=lambert-spot
sheet docs/lit/course-phong.png scenes/lit/course-phong-point.scene=phong-point \
    scenes/lit/course-phong-directional.scene=phong-directional scenes/lit/course-phong-spot.scene=phong-spot
sheet docs/lit/more.png scenes/lit/shadows.scene scenes/lit/coloured-lights.scene scenes/lit/room.scene
sheet docs/trace/scenes.png scenes/trace/reflection.scene scenes/trace/glass.scene "scenes/trace/supersample.scene=supersample (4x4)"
sheet docs/trace/stress.png scenes/stress/trace-mirrors.scene scenes/stress/trace-tir-graze.scene \
    scenes/stress/trace-inside-glass.scene
echo "doc-images: wrote docs/img/, docs/lit/ and docs/trace/"
