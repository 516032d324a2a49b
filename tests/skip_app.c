/* A small application for tests/skip.sh: a world with one object of each
 * kind, lit (SKIP_LIT 1) or flat, rendered row by row. SKIP_BOUNCE 1 makes
 * the sphere reflective and the box transparent (issue 12; needs
 * FXRT_MAX_DEPTH > 0); SKIP_SAMPLES N > 1 asks for N x N samples
 * (FXRT_MAX_SAMPLES >= N), adaptive with SKIP_ADAPTIVE 1. Linked for the
 * Cortex-M0 with --gc-sections, its symbol table shows which parts of the
 * core a configuration pulls in. */
#include "fxrt.h"

#include "add.h"

#define P(x, y, z) vec3_make(F16(x), F16(y), F16(z))
#define COL(r, g, b) color_make(COLOR_FRAC(r), COLOR_FRAC(g), COLOR_FRAC(b))
#define FR(r, g, b) color_make(F16(r), F16(g), F16(b)) /* fractions */
#ifndef SKIP_BOUNCE
#define SKIP_BOUNCE 0
#endif
#ifndef SKIP_SAMPLES
#define SKIP_SAMPLES 1
#endif
#ifndef SKIP_ADAPTIVE
#define SKIP_ADAPTIVE 0
#endif

static world_t world;
static render_t rs;
static uint8_t row[3 * 32];
volatile uint32_t skip_sink;

int main(void)
{
    cam_t cam;
    fxrt_camera_perspective(&cam, P(0, 4, 6), P(0, -4, -6), P(0, 1, 0), F16(45), 32, 24);
    fxrt_world_init(&world, COL(0, 0, 0));
    int32_t ids[4];
    ids[0] = world_add_plane(&world, P(0, 0, 0), P(0, 1, 0), COL(0.7, 0.2, 0.1));
    ids[1] = world_add_sphere(&world, P(0, 1, 0), F16(0.8), COL(0.3, 0.6, 0.9));
    ids[2] = world_add_box(&world, P(-2, 0, -1), P(-1, 1, 0), COL(0.2, 0.3, 0.9));
    ids[3] = world_add_triangle(&world, P(1, 0, -1), P(2, 0, -1), P(1.5, 1, -1), COL(0.6, 0.6, 0.1));
#if SKIP_LIT
    material_t m = {.kind = MATERIAL_LAMBERT};
    for (int i = 0; i < 4; i++)
        world_set_material(&world, ids[i], &m);
    world_set_ambient(&world, COL(0.1, 0.1, 0.1));
    world_add_light(&world, LIGHT_POINT, P(2, 3, 2), P(0, 0, 0), 0, color_make(FX_ONE, FX_ONE, FX_ONE), true);
#if SKIP_BOUNCE
    material_t mr = {.kind = MATERIAL_REFLECTIVE, .exponent = 8, .specular = FR(1, 1, 1), .reflection = FR(0.5, 0.5, 0.5)};
    world_set_material(&world, ids[1], &mr);
    material_t mt = {.kind = MATERIAL_TRANSPARENT, .index = F16(1.5), .specular = FR(0, 0, 0), .reflection = FR(0, 0, 0)};
    world_set_material(&world, ids[2], &mt);
    world_set_depth(&world, 2);
#endif
#else
    (void)ids;
#endif
#if SKIP_SAMPLES > 1
    world_set_samples(&world, SKIP_SAMPLES, SKIP_ADAPTIVE);
#endif
    fxrt_render_setup(&rs, &world, &cam);
    for (int y = 0; y < 24; y++) {
        fxrt_render_row(&rs, y, row, sizeof row);
        skip_sink += row[0];
    }
    return 0;
}
