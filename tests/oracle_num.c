/* oracle_num: one frame of a parsed scene from the fast scanline renderer
 * (render_row) and from the per-pixel ray caster (raycast_row, with its
 * object-id map), in the including build's number type. Compiled once per
 * number type with FXRT_MULTI, like host/engine.c, so the symbols carry the
 * type's suffix (oracle_frame_q16, oracle_frame_double). */
#include <stdio.h>

#include "../core/frame/raycast.h"
#include "../core/vis/render.h"
#include "../host/engine_build.h"
#include "oracle.h"

int MULTI_SYM(oracle_frame)(const char *path, const scene_t *sc, int width, int height, uint8_t *fast,
                           uint8_t *ray, uint16_t *ids, char *err, size_t errlen)
{
    /* Static: the host world and render state are too big for a stack frame. */
    static world_t world;
    static render_t state;
    cam_t cam;
    if (ENGINE_SYM(engine_build)(path, sc, width, height, &world, &cam, err, errlen) != 0)
        return -1;
    if (fast != NULL) {
        if (!render_setup(&state, &world, &cam)) {
            snprintf(err, errlen, "%s: image wider than %d pixels", path, FXRT_RENDER_MAX_WIDTH);
            return -1;
        }
        for (int row = 0; row < height; row++)
            render_row(&state, row, fast + (size_t)3 * width * row);
    }
    for (int row = 0; row < height; row++)
        raycast_row(&world, &cam, row, ray + (size_t)3 * width * row, ids + (size_t)width * row);
    return 0;
}

/* Copy an object's 8-bit colour into rgb[3 * id]. */
static void oracle_put_rgb(uint8_t *rgb, int count, const geom_common_t *o)
{
    if (o->id < count) {
        rgb[3 * o->id + 0] = o->rgb.r;
        rgb[3 * o->id + 1] = o->rgb.g;
        rgb[3 * o->id + 2] = o->rgb.b;
    }
}

int MULTI_SYM(oracle_colors)(const char *path, const scene_t *sc, int width, int height, uint8_t *rgb,
                            char *err, size_t errlen)
{
    static world_t world;
    cam_t cam;
    if (ENGINE_SYM(engine_build)(path, sc, width, height, &world, &cam, err, errlen) != 0)
        return -1;
    for (int i = 0; i < 3 * sc->count; i++)
        rgb[i] = 0;
#if FXRT_MAX_PLANES > 0
    for (int i = 0; i < world.n_planes; i++)
        oracle_put_rgb(rgb, sc->count, &world.planes[i].obj);
#endif
#if FXRT_MAX_SPHERES > 0
    for (int i = 0; i < world.n_spheres; i++)
        oracle_put_rgb(rgb, sc->count, &world.spheres[i].obj);
#endif
#if FXRT_MAX_TRIANGLES > 0
    for (int i = 0; i < world.n_triangles; i++)
        oracle_put_rgb(rgb, sc->count, &world.triangles[i].obj);
#endif
#if FXRT_MAX_BOXES > 0
    for (int i = 0; i < world.n_boxes; i++)
        oracle_put_rgb(rgb, sc->count, &world.boxes[i].obj);
#endif
    rgb[3 * sc->count + 0] = world.background_rgb.r;
    rgb[3 * sc->count + 1] = world.background_rgb.g;
    rgb[3 * sc->count + 2] = world.background_rgb.b;
    return 0;
}
