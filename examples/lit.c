/* lit: a lit world built in code with the public API (core/fxrt.h):
 * Lambert and Phong objects, a mirror sphere and a glass sphere, a point
 * light and a spot light casting shadows, bounces up to depth 4 and 2 x 2
 * adaptive supersampling. Two views of it, row by row into one row buffer
 * (example_io.h: PPM files on the host, semihosting on a board). Q16.16
 * throughout; the board's frames equal the host's byte for byte
 * (tests/examples.sh).
 *
 * Colours: every colour (objects, lights, the ambient, specular and
 * reflection) with FXRT_RGB, fractions of full intensity quantised as a
 * scene file's.
 *
 * Build (the capacities must be the same for the core and this file, see
 * docs/EMBEDDING.md): tests/examples.mk, or CMake (examples/cmake/). */
#include "example_io.h"
#include "fxrt.h"

#define LIT_W 48
#define LIT_H 36
#define LIT_FRAMES 2

static fxrt_world_t world; /* 5 objects and 2 lights: the capacities in examples.mk */
static fxrt_render_t rs;   /* with samples 2: 2 x LIT_W columns */
static fxrt_view_t view;
static uint8_t row[FXRT_ROW_BYTES(LIT_W)];

#define V3(x, y, z) fxrt_vec3(FXRT_NUM(x), FXRT_NUM(y), FXRT_NUM(z))

/* One object with its material. */
static void add(fxrt_object_t o, const char *what)
{
    example_must(fxrt_add(&world, &o), what);
}

__attribute__((noinline)) static void build_world(void)
{
    example_must(fxrt_world_init(&world, FXRT_RGB(0.08, 0.1, 0.2)), "world");
    example_must(fxrt_set_ambient(&world, FXRT_RGB(0.12, 0.12, 0.15)), "ambient");
    const fxrt_material_t lambert = {.kind = FXRT_MATERIAL_LAMBERT};
    const fxrt_material_t phong = {.kind = FXRT_MATERIAL_PHONG, .exponent = 40,
                                   .specular = FXRT_RGB(0.8, 0.8, 0.8)};
    add((fxrt_object_t){.kind = FXRT_PLANE, .p = {V3(0, -1, 0), V3(0, 1, 0)}, .color = FXRT_RGB(0.55, 0.6, 0.5),
                        .material = lambert},
        "floor");
    add((fxrt_object_t){.kind = FXRT_SPHERE, .p = {V3(-0.9, -0.2, -0.6)}, .radius = FXRT_NUM(0.8),
                        .color = FXRT_RGB(0.9, 0.9, 0.95),
                        .material = {.kind = FXRT_MATERIAL_REFLECTIVE, .exponent = 80,
                                     .specular = FXRT_RGB(1, 1, 1),
                                     .reflection = FXRT_RGB(0.7, 0.7, 0.7)}},
        "mirror sphere");
    add((fxrt_object_t){.kind = FXRT_SPHERE, .p = {V3(0.9, -0.4, 0.7)}, .radius = FXRT_NUM(0.6),
                        .color = FXRT_RGB(0.85, 0.95, 0.9),
                        .material = {.kind = FXRT_MATERIAL_TRANSPARENT, .index = FXRT_NUM(1.5)}},
        "glass sphere");
    add((fxrt_object_t){.kind = FXRT_BOX, .p = {V3(0.6, -1, -2.2), V3(1.6, 0.4, -1.2)},
                        .color = FXRT_RGB(0.9, 0.35, 0.2), .material = phong},
        "box");
    add((fxrt_object_t){.kind = FXRT_TRIANGLE, .p = {V3(-2.6, -1, -2.4), V3(-1.2, -1, -2.6), V3(-1.9, 1.2, -2.5)},
                        .color = FXRT_RGB(0.55, 0.3, 0.75), .material = lambert},
        "triangle");
    example_must(fxrt_add_light(&world, &(fxrt_light_t){.kind = FXRT_LIGHT_POINT, .position = V3(3, 4, 3),
                                               .color = FXRT_RGB(0.8, 0.8, 0.75), .shadows = true}),
         "point light");
    example_must(fxrt_add_light(&world, &(fxrt_light_t){.kind = FXRT_LIGHT_SPOT, .position = V3(-3, 5, 2),
                                               .direction = V3(0.6, -1, -0.5), .angle_deg = FXRT_NUM(30),
                                               .color = FXRT_RGB(0.6, 0.5, 0.3), .shadows = true}),
         "spot light");
    example_must(fxrt_set_depth(&world, 4), "depth");
    example_must(fxrt_set_samples(&world, 2, true), "samples");
}

const char example_name[] = "lit";

int example_main(void)
{
    build_world();
    static const struct {
        fxrt_num_t x, y, z;
    } eyes[LIT_FRAMES] = {{FXRT_NUM(0), FXRT_NUM(1.4), FXRT_NUM(5)}, {FXRT_NUM(3.5), FXRT_NUM(2), FXRT_NUM(3.5)}};
    for (int32_t f = 0; f < LIT_FRAMES; f++) {
        example_frame_begin(f, LIT_W, LIT_H);
        fxrt_vec3_t eye = fxrt_vec3(eyes[f].x, eyes[f].y, eyes[f].z);
        fxrt_vec3_t gaze = fxrt_vec3_sub(V3(0, -0.4, -0.5), eye);
        example_must(fxrt_camera_perspective(&view, eye, gaze, V3(0, 1, 0), FXRT_NUM(45), LIT_W, LIT_H), "camera");
        example_must(fxrt_render_setup(&rs, &world, &view), "render set-up");
        for (int32_t r = 0; r < LIT_H; r++) {
            example_must(fxrt_render_row(&rs, r, row, sizeof row), "row");
            example_row(row, sizeof row);
        }
        example_frame_end(f);
    }
    return 0;
}
