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

/* A colour from intensity fractions 0..1 (COLOR_FRAC: core/geom.h). */
#define RGB(r, g, b) color_make(COLOR_FRAC(r), COLOR_FRAC(g), COLOR_FRAC(b))

/* Static storage, not the stack: the micro:bit reserves 2 KB of stack for
 * the core's own use (docs/BENCHMARKS.md, "RAM"). */
static world_t world;              /* 5 objects: the capacities in examples.mk */
static render_t rs;                /* per-frame forms of every object */
static cam_t cam;                  /* set again for every frame */
static uint8_t row[FXRT_ROW_BYTES(ORBIT_W)];

static vec3_t v3(fx_t x, fx_t y, fx_t z)
{
    return vec3_make(x, y, z);
}

/* Stop at the first refusal, with the API's text. */
static void must(int32_t r, const char *what)
{
    if (r < 0)
        example_fail(what, fxrt_strerror(r));
}

/* One object of the world (fxrt_object_t: the kind's points in p[], a
 * sphere's radius). */
static void add(fxrt_object_t o, const char *what)
{
    must(fxrt_add(&world, &o), what);
}

/* Out of line: its objects then take stack only while it runs, not during
 * every frame's set-up as well. */
__attribute__((noinline)) static void build_world(void)
{
    must(fxrt_world_init(&world, RGB(0.05, 0.1, 0.2)), "world");
    add((fxrt_object_t){.kind = GEOM_PLANE, .p = {v3(0, F16(-1), 0), v3(0, F16(1), 0)}, .color = RGB(0.35, 0.55, 0.3)},
        "plane");
    add((fxrt_object_t){.kind = GEOM_SPHERE, .p = {v3(0, 0, 0)}, .radius = F16(0.9), .color = RGB(0.85, 0.3, 0.15)},
        "sphere");
    add((fxrt_object_t){.kind = GEOM_SPHERE, .p = {v3(F16(1.6), F16(-0.5), F16(0.8))}, .radius = F16(0.5),
                        .color = RGB(0.2, 0.45, 0.9)},
        "sphere");
    add((fxrt_object_t){.kind = GEOM_BOX, .p = {v3(F16(-2.2), F16(-1), F16(-0.6)), v3(F16(-1.2), F16(0.2), F16(0.4))},
                        .color = RGB(0.95, 0.8, 0.25)},
        "box");
    add((fxrt_object_t){.kind = GEOM_TRIANGLE,
                        .p = {v3(F16(-0.5), F16(-1), F16(-2.2)), v3(F16(1.5), F16(-1), F16(-1.8)),
                              v3(F16(0.4), F16(1.4), F16(-2))},
                        .color = RGB(0.6, 0.25, 0.7)},
        "triangle");
}

int orbit_main(void)
{
    build_world();
    const fx_t radius = F16(5.5), height = F16(1.8);
    for (int32_t f = 0; f < ORBIT_FRAMES; f++) {
        example_frame_begin(f, ORBIT_W, ORBIT_H);
        fx_t deg = fx_mul_int(F16(22.5), f); /* 360 / 16 per frame */
        vec3_t eye = v3(fx_mul(radius, fx_sin_deg(deg)), height, fx_mul(radius, fx_cos_deg(deg)));
        vec3_t gaze = vec3_sub(v3(0, F16(-0.3), 0), eye); /* at the big sphere */
        must(fxrt_camera_perspective(&cam, eye, gaze, v3(0, F16(1), 0), F16(50), ORBIT_W, ORBIT_H), "camera");
        must(fxrt_render_setup(&rs, &world, &cam), "render set-up");
        for (int32_t r = 0; r < ORBIT_H; r++) {
            fxrt_render_row(&rs, r, row);
            example_row(row, sizeof row);
        }
        example_frame_end(f);
    }
    return 0;
}
