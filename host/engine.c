/* engine: converts a parsed scene into the build's number type and renders
 * it. Compiled once per FXRT_NUMBER with FXRT_MULTI, so the core symbols it
 * calls carry the type's suffix. */
#include <math.h>
#include <stdio.h>

#include "../core/raycast.h"
#include "../core/render.h"
#include "engine.h"
#include "engine_build.h"

num_t ENGINE_SYM(engine_num)(double x)
{
#if FXRT_NUMBER == FXRT_Q16
    /* Round to nearest, ties away from zero, as the F16() literal does. The
     * scene loader keeps x inside the documented domain, far from overflow. */
    double s = x * 65536.0;
    return (fx_t)(s >= 0 ? floor(s + 0.5) : -floor(-s + 0.5));
#else
    return (num_t)x;
#endif
}

static vec3_t engine_vec(scene_vec_t v)
{
    return vec3_make(ENGINE_SYM(engine_num)(v.x), ENGINE_SYM(engine_num)(v.y), ENGINE_SYM(engine_num)(v.z));
}

/* A colour channel written as a fraction x in 0..1, stored in units of
 * 1/255 quantised to 2^-16 of that unit: round(x * 255 * 65536) / 65536,
 * the same value in every build (it has at most 24 significant bits, so
 * float holds it exactly). The 8-bit output is then its round-half-up
 * (core/color.h, docs/ACCURACY.md "Colour"). */
static num_t engine_channel(double x)
{
    return ENGINE_SYM(engine_num)(floor(x * (255.0 * 65536.0) + 0.5) / 65536.0);
}

static color_t engine_color(const double c[3])
{
    return color_make(engine_channel(c[0]), engine_channel(c[1]), engine_channel(c[2]));
}

int ENGINE_SYM(engine_build)(const char *path, const scene_t *sc, int width, int height, world_t *w,
                             cam_t *cam, char *err, size_t errlen)
{
    const scene_camera_t *c = &sc->camera;
    cam_err_t ce = cam_setup(cam, c->kind == SCENE_CAM_PERSPECTIVE ? CAM_PERSPECTIVE : CAM_ORTHOGRAPHIC,
                             engine_vec(c->eye), engine_vec(c->gaze), engine_vec(c->up),
                             ENGINE_SYM(engine_num)(c->fov_deg), ENGINE_SYM(engine_num)(c->scale), width,
                             height);
    if (ce != CAM_OK) {
        snprintf(err, errlen, "%s:%d: camera at %dx%d: %s", path, c->line, width, height, cam_strerror(ce));
        return -1;
    }
    world_init(w, engine_color(sc->background));
    for (int i = 0; i < sc->count; i++) {
        const scene_obj_t *o = &sc->obj[i];
        color_t col = engine_color(o->color);
        uint16_t id = (uint16_t)i;
        bool ok = false;
        const char *kind = "object";
        switch (o->kind) {
        case SCENE_PLANE:
            kind = "plane";
#if FXRT_MAX_PLANES > 0
            if (w->n_planes < FXRT_MAX_PLANES)
                ok = geom_plane_make(&w->planes[w->n_planes++], engine_vec(o->p[0]),
                                     engine_vec(o->p[1]), col, id);
#endif
            break;
        case SCENE_SPHERE:
            kind = "sphere";
#if FXRT_MAX_SPHERES > 0
            if (w->n_spheres < FXRT_MAX_SPHERES)
                ok = geom_sphere_make(&w->spheres[w->n_spheres++], engine_vec(o->p[0]),
                                      ENGINE_SYM(engine_num)(o->radius), col, id);
#endif
            break;
        case SCENE_TRIANGLE:
            kind = "triangle";
#if FXRT_MAX_TRIANGLES > 0
            if (w->n_triangles < FXRT_MAX_TRIANGLES)
                ok = geom_triangle_make(&w->triangles[w->n_triangles++], engine_vec(o->p[0]), engine_vec(o->p[1]),
                                        engine_vec(o->p[2]), col, id);
#endif
            break;
        case SCENE_BOX:
            kind = "box";
#if FXRT_MAX_BOXES > 0
            if (w->n_boxes < FXRT_MAX_BOXES)
                ok = geom_box_make(&w->boxes[w->n_boxes++], engine_vec(o->p[0]), engine_vec(o->p[1]), col, id);
#endif
            break;
        }
        if (!ok) {
            snprintf(err, errlen, "%s:%d: %s cannot be built in %s (degenerate, or over this build's capacity)",
                     path, o->line, kind, NUM_NAME);
            return -1;
        }
    }
    return 0;
}

int ENGINE_SYM(engine_render)(const char *path, const scene_t *sc, int width, int height,
                              engine_renderer_t renderer, uint8_t *rgb, char *err, size_t errlen)
{
    /* Static: the host world and render state hold up to 64 objects of each
     * kind, too big for a stack frame. The CLI renders one frame at a time. */
    static world_t world;
    static render_t state;
    cam_t cam;
    if (ENGINE_SYM(engine_build)(path, sc, width, height, &world, &cam, err, errlen) != 0)
        return -1;
    if (!render_setup(&state, &world, &cam)) {
        snprintf(err, errlen, "%s: image wider than %d pixels", path, FXRT_RENDER_MAX_WIDTH);
        return -1;
    }
    for (int row = 0; row < height; row++) {
        uint8_t *out = rgb + (size_t)3 * width * row;
        switch (renderer) {
        case ENGINE_FAST: render_row(&state, row, out); break;
        case ENGINE_REFERENCE: render_row_reference(&state, row, out); break;
        case ENGINE_RAYCAST: raycast_row(&world, &cam, row, out, NULL); break;
        }
    }
    return 0;
}
