/* orbit: a small world built in code with the public API (core/fxrt.h),
 * seen by a camera that circles it in ORBIT_FRAMES steps. Each frame sets
 * its camera and the renderer's forms up on the spot, then renders row by
 * row into one row buffer and hands every row to the output (example_io.h:
 * PPM files on the host, semihosting on a board). Q16.16 throughout.
 *
 * Build (the capacities must be the same for the core and this file, see
 * docs/EMBEDDING.md): tests/examples.mk. */
#include "example_io.h"
#include "fxrt.h"

#define ORBIT_W 64
#define ORBIT_H 48
#define ORBIT_FRAMES 16

/* Static storage, not the stack: the micro:bit reserves 2 KB of stack for
 * the core's own use (docs/EMBEDDING.md, "Stack"). */
static fxrt_world_t world;         /* 5 objects: the capacities in examples.mk */
static fxrt_render_t rs;           /* per-frame forms of every object */
static fxrt_view_t view;           /* set again for every frame */
static uint8_t row[FXRT_ROW_BYTES(ORBIT_W)];

#define V3(x, y, z) fxrt_vec3(FXRT_NUM(x), FXRT_NUM(y), FXRT_NUM(z))

/* sin(k * 22.5 degrees) for k = 0..4; the others by symmetry. */
static const fxrt_num_t sin_step[5] = {FXRT_NUM(0), FXRT_NUM(0.38268343), FXRT_NUM(0.70710678),
                                       FXRT_NUM(0.92387953), FXRT_NUM(1)};

static fxrt_num_t orbit_sin(int32_t k) /* sin(k * 22.5 degrees), any k >= 0 */
{
    k %= 16;
    fxrt_num_t s = sin_step[k <= 4 ? k : k <= 8 ? 8 - k : k <= 12 ? k - 8 : 16 - k];
    return k > 8 ? -s : s;
}

/* One object of the world (fxrt_object_t: the kind's points in p[], a
 * sphere's radius). */
static void add(fxrt_object_t o, const char *what)
{
    example_must(fxrt_add(&world, &o), what);
}

/* Out of line: its objects then take stack only while it runs, not during
 * every frame's set-up as well. */
__attribute__((noinline)) static void build_world(void)
{
    example_must(fxrt_world_init(&world, FXRT_RGB(0.05, 0.1, 0.2)), "world");
    add((fxrt_object_t){.kind = FXRT_PLANE, .p = {V3(0, -1, 0), V3(0, 1, 0)}, .color = FXRT_RGB(0.35, 0.55, 0.3)},
        "plane");
    add((fxrt_object_t){.kind = FXRT_SPHERE, .p = {V3(0, 0, 0)}, .radius = FXRT_NUM(0.9),
                        .color = FXRT_RGB(0.85, 0.3, 0.15)},
        "sphere");
    add((fxrt_object_t){.kind = FXRT_SPHERE, .p = {V3(1.6, -0.5, 0.8)}, .radius = FXRT_NUM(0.5),
                        .color = FXRT_RGB(0.2, 0.45, 0.9)},
        "sphere");
    add((fxrt_object_t){.kind = FXRT_BOX, .p = {V3(-2.2, -1, -0.6), V3(-1.2, 0.2, 0.4)},
                        .color = FXRT_RGB(0.95, 0.8, 0.25)},
        "box");
    add((fxrt_object_t){.kind = FXRT_TRIANGLE, .p = {V3(-0.5, -1, -2.2), V3(1.5, -1, -1.8), V3(0.4, 1.4, -2)},
                        .color = FXRT_RGB(0.6, 0.25, 0.7)},
        "triangle");
}

const char example_name[] = "orbit";

int example_main(void)
{
    build_world();
    const fxrt_num_t radius = FXRT_NUM(5.5);
    for (int32_t f = 0; f < ORBIT_FRAMES; f++) {
        example_frame_begin(f, ORBIT_W, ORBIT_H);
        /* 360 / 16 degrees per frame */
        fxrt_vec3_t eye = fxrt_vec3(fxrt_mul(radius, orbit_sin(f)), FXRT_NUM(1.8), fxrt_mul(radius, orbit_sin(f + 4)));
        fxrt_vec3_t gaze = fxrt_vec3_sub(V3(0, -0.3, 0), eye); /* at the big sphere */
        example_must(fxrt_camera_perspective(&view, eye, gaze, V3(0, 1, 0), FXRT_NUM(50), ORBIT_W, ORBIT_H), "camera");
        example_must(fxrt_render_setup(&rs, &world, &view), "render set-up");
        for (int32_t r = 0; r < ORBIT_H; r++) {
            example_must(fxrt_render_row(&rs, r, row, sizeof row), "row");
            example_row(row, sizeof row);
        }
        example_frame_end(f);
    }
    return 0;
}
