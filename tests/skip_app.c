/* A small application for tests/skip.sh: a world with one object of each
 * kind, lit (SKIP_LIT 1) or flat, rendered row by row. Linked for the
 * Cortex-M0 with --gc-sections, its symbol table shows which parts of the
 * core a configuration pulls in. */
#include "fxrt.h"

#define P(x, y, z) vec3_make(F16(x), F16(y), F16(z))
#define COL(r, g, b) color_make(COLOR_FRAC(r), COLOR_FRAC(g), COLOR_FRAC(b))

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
#else
    (void)ids;
#endif
    fxrt_render_setup(&rs, &world, &cam);
    for (int y = 0; y < 24; y++) {
        fxrt_render_row(&rs, y, row);
        skip_sink += row[0];
    }
    return 0;
}
