/* engine: converts a parsed scene into the build's number type and renders
 * it. Compiled once per FXRT_NUMBER with FXRT_MULTI, so the core symbols it
 * calls carry the type's suffix. */
#include <math.h>
#include <stdio.h>

#include "../core/fxrt.h"
#include "../core/frame/raycast.h"
#include "engine.h"
#include "engine_build.h"

_Static_assert(ENGINE_KEY_MISS == RENDER_KEY_MISS, "engine.h's ENGINE_KEY_MISS must be the core's RENDER_KEY_MISS");

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
 * (core/math/color.h, docs/ACCURACY.md "Colour"). */
static num_t engine_channel(double x)
{
    return ENGINE_SYM(engine_num)(floor(x * (255.0 * 65536.0) + 0.5) / 65536.0);
}

static color_t engine_color(const double c[3])
{
    return color_make(engine_channel(c[0]), engine_channel(c[1]), engine_channel(c[2]));
}

/* The refraction index quantised like a fraction (round(x * 65536) /
 * 65536: at most 23 significant bits up to FXRT_INDEX_MAX = 100, so every
 * build holds it exactly), but not below FXRT_INDEX_MIN: 0.01 would round
 * to 655/65536 < 0.01, which the float and double builds' world_set_material
 * would refuse, so it becomes 656/65536 (ceil(0.01 * 65536) / 65536). */
num_t ENGINE_SYM(engine_index)(double x)
{
    double q = floor(x * 65536.0 + 0.5), lo = ceil(FXRT_INDEX_MIN * 65536.0);
    return ENGINE_SYM(engine_num)((q < lo ? lo : q) / 65536.0);
}

static material_t engine_material(const scene_obj_t *o)
{
    material_t m;
    color_t black = color_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    bool phong_terms = o->material == SCENE_MAT_PHONG || o->material == SCENE_MAT_REFLECTIVE;
    switch (o->material) {
    case SCENE_MAT_LAMBERT: m.kind = MATERIAL_LAMBERT; break;
    case SCENE_MAT_PHONG: m.kind = MATERIAL_PHONG; break;
    case SCENE_MAT_REFLECTIVE: m.kind = MATERIAL_REFLECTIVE; break;
    case SCENE_MAT_TRANSPARENT: m.kind = MATERIAL_TRANSPARENT; break;
    default: m.kind = MATERIAL_FLAT; break;
    }
    /* Fields a material does not use: zero, as world_set_material stores them. */
    m.exponent = (uint16_t)(phong_terms ? o->exponent : 0);
    m.specular = phong_terms ? engine_color(o->specular) : black;
    m.reflection = o->material == SCENE_MAT_REFLECTIVE ? engine_color(o->reflection) : black;
    m.index = o->material == SCENE_MAT_TRANSPARENT ? ENGINE_SYM(engine_index)(o->index) : NUM_ZERO;
    return m;
}

int ENGINE_SYM(engine_describe)(const scene_t *sc, int width, int height, engine_desc_t *d)
{
    const scene_camera_t *c = &sc->camera;
    d->camera.kind = c->kind == SCENE_CAM_PERSPECTIVE ? CAM_PERSPECTIVE : CAM_ORTHOGRAPHIC;
    d->camera.eye = engine_vec(c->eye);
    d->camera.gaze = engine_vec(c->gaze);
    d->camera.up = engine_vec(c->up);
    /* The unused one of fov and scale is 0 in the description. */
    d->camera.fov_deg = c->kind == SCENE_CAM_PERSPECTIVE ? ENGINE_SYM(engine_num)(c->fov_deg) : NUM_ZERO;
    d->camera.scale = c->kind == SCENE_CAM_PERSPECTIVE ? NUM_ZERO : ENGINE_SYM(engine_num)(c->scale);
    d->camera.width = width;
    d->camera.height = height;
    d->background = engine_color(sc->background);
    d->count = sc->count;
    d->bounces = false;
    FXRT_IF_MODEL(int nmodels = 0;)
    for (int i = 0; i < sc->count; i++) {
        const scene_obj_t *o = &sc->obj[i];
        fxrt_object_t *t = &d->obj[i];
        t->color = engine_color(o->color);
        t->radius = NUM_ZERO;
        for (int k = 0; k < 4; k++)
            t->p[k] = vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
        /* The parser keeps a kind's fields in p[] and radius as the
         * description does (scene/kinds.h), unused ones 0. */
        t->kind = (geom_kind_t)o->kind;
        for (int k = 0; k < 4; k++)
            t->p[k] = engine_vec(o->p[k]);
        t->radius = ENGINE_SYM(engine_num)(o->radius);
        t->material = engine_material(o);
        d->bounces |= material_bounces(t->material.kind);
        FXRT_IF_SMOOTH(t->smooth = o->smooth != 0;
                       for (int k = 0; k < 3; k++) t->vn[k] = o->smooth ? engine_vec(o->vn[k]) : vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);)
        FXRT_IF_MODEL(t->inst = NULL;
                      if (o->kind == SCENE_MODEL && nmodels < FXRT_MAX_MODELS) {
                          meshbuild_inst(&o->map, o->mesh, &d->inst[nmodels]);
                          t->inst = &d->inst[nmodels++];
                      })
    }
    d->depth = sc->depth;
    d->samples = sc->samples;
    d->adaptive = sc->adaptive != 0;
    d->ambient = engine_color(sc->ambient);
    d->nlights = sc->nlights;
    for (int i = 0; i < sc->nlights; i++) {
        const scene_light_t *l = &sc->light[i];
        fxrt_light_t *t = &d->lights[i];
        vec3_t zero = vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
        t->kind = l->kind == SCENE_LIGHT_SPOT ? LIGHT_SPOT : l->kind == SCENE_LIGHT_DIRECTIONAL ? LIGHT_DIRECTIONAL
                                                                                                : LIGHT_POINT;
        /* Fields a kind does not use are 0 in the description. */
        t->position = l->kind == SCENE_LIGHT_DIRECTIONAL ? zero : engine_vec(l->position);
        t->direction = l->kind == SCENE_LIGHT_POINT ? zero : engine_vec(l->direction);
        t->angle_deg = l->kind == SCENE_LIGHT_SPOT ? ENGINE_SYM(engine_num)(l->angle_deg) : NUM_ZERO;
        t->color = engine_color(l->color);
        t->shadows = l->shadows != 0;
    }
    return 0;
}

static const char *engine_kind_name(geom_kind_t k)
{
    switch (k) {
#define ENGINE_KIND_NAME(K, k, ...) case GEOM_##K: return #k;
        FXRT_KINDS(ENGINE_KIND_NAME)
#undef ENGINE_KIND_NAME
    default: break;
    }
    return "object";
}

int ENGINE_SYM(engine_build)(const char *path, const scene_t *sc, int width, int height, world_t *w,
                             cam_t *cam, char *err, size_t errlen)
{
    /* Through the public API (core/fxrt.h) with the description the scene
     * compiler emits for the firmware: the host and the boards set scenes
     * up from the same values along the same path. */
    static engine_desc_t d;
    ENGINE_SYM(engine_describe)(sc, width, height, &d);
    fxrt_err_t ce = fxrt_camera_setup(cam, &d.camera);
    if (ce != FXRT_OK) {
        snprintf(err, errlen, "%s:%d: camera at %dx%d: %s", path, sc->camera.line, width, height,
                 fxrt_strerror(ce));
        return -1;
    }
    fxrt_err_t we = fxrt_world_init(w, d.background);
    if (we != FXRT_OK) {
        snprintf(err, errlen, "%s: background: %s", path, fxrt_strerror(we));
        return -1;
    }
    for (int i = 0; i < d.count; i++) {
        int32_t id = fxrt_add(w, &d.obj[i]);
        if (id < 0) {
            /* fxrt_add also sets the material (FXRT_ERR_MATERIAL, ...). */
            snprintf(err, errlen, "%s:%d: %s cannot be built in %s: %s", path, sc->obj[i].line,
                     engine_kind_name(d.obj[i].kind), NUM_NAME, fxrt_strerror(id));
            return -1;
        }
    }
    /* Default ambient (black) is always accepted, also with lighting
     * compiled out. */
    fxrt_err_t ae = fxrt_set_ambient(w, d.ambient);
    if (ae != FXRT_OK) {
        snprintf(err, errlen, "%s:%d: ambient cannot be set in %s: %s", path, sc->ambient_line, NUM_NAME,
                 fxrt_strerror(ae));
        return -1;
    }
    for (int i = 0; i < d.nlights; i++) {
        int32_t li = fxrt_add_light(w, &d.lights[i]);
        if (li < 0) {
            snprintf(err, errlen, "%s:%d: light cannot be added in %s: %s", path, sc->light[i].line, NUM_NAME,
                     fxrt_strerror(li));
            return -1;
        }
    }
    /* The depth is set whenever the build can hold it; a refusal (more
     * than FXRT_MAX_DEPTH) only matters to reflective and transparent
     * objects, as on the board, where fxrt-scenec compiles bounces out
     * (FXRT_MAX_DEPTH 0) for a scene without them. The line is the
     * 'depth' line, or the first bouncing object's when the default is
     * too deep. */
    fxrt_err_t de = world_set_depth(w, d.depth);
    if (de != FXRT_OK && d.bounces) {
        int line = sc->depth_line;
        for (int i = 0; line == 0 && i < sc->count; i++)
            if (material_bounces(d.obj[i].material.kind))
                line = sc->obj[i].line;
        snprintf(err, errlen, "%s:%d: depth %d cannot be set in %s: %s", path, line, d.depth, NUM_NAME,
                 fxrt_strerror(de));
        return -1;
    }
    fxrt_err_t se = world_set_samples(w, d.samples, d.adaptive);
    if (se != FXRT_OK) {
        snprintf(err, errlen, "%s:%d: samples %d%s cannot be set in %s: %s", path, sc->samples_line, d.samples,
                 d.adaptive ? " adaptive" : "", NUM_NAME, fxrt_strerror(se));
        return -1;
    }
    return 0;
}

/* Render every row with the renderer; keys (when not NULL) receives each
 * pixel's key, rgb (when NULL) goes to a scratch row that is thrown away. */
static void engine_pass(render_t *state, const world_t *world, const cam_t *cam, int width, int height,
                        engine_renderer_t renderer, uint8_t *rgb, uint32_t *keys)
{
    static uint8_t scratch[3 * FXRT_MAX_DIM];
    for (int row = 0; row < height; row++) {
        uint8_t *out = rgb != NULL ? rgb + (size_t)3 * width * row : scratch;
        /* The renderers write a key only where they paint an object (or
         * not at all, the ray caster), so every row starts as background. */
        render_set_keys(state, NULL);
        if (keys != NULL) {
            render_set_keys(state, keys + (size_t)width * row);
            for (int x = 0; x < width; x++)
                state->keys[x] = RENDER_KEY_MISS;
        }
        switch (renderer) {
        case ENGINE_FAST: render_row(state, row, out); break;
        case ENGINE_REFERENCE: render_row_reference(state, row, out); break;
        case ENGINE_RAYCAST: raycast_row(world, cam, row, out, NULL); break;
        }
    }
    render_set_keys(state, NULL); /* state outlives the caller's buffer */
}

/* render_setup refused the frame: say why, with the samples line when
 * the scene's samples are what made it too wide (samples x width). */
static int engine_setup_error(fxrt_err_t e, const render_t *state, const char *path, const scene_t *sc, int width,
                              int32_t samples, char *err, size_t errlen)
{
    const char *why = e == FXRT_ERR_RENDER && state->error ? state->error : fxrt_strerror(e);
    bool too_wide = samples > 1 && (int64_t)samples * width > FXRT_RENDER_MAX_WIDTH;
    if ((e == FXRT_ERR_RENDER || e == FXRT_ERR_WIDTH) && too_wide && sc->samples_line > 0) {
        snprintf(err, errlen, "%s:%d: samples %d at width %d: samples x width wider than FXRT_RENDER_MAX_WIDTH (%d)",
                 path, sc->samples_line, (int)samples, width, FXRT_RENDER_MAX_WIDTH);
    } else if (e == FXRT_ERR_RENDER && samples > 1 && sc->samples_line > 0) {
        snprintf(err, errlen, "%s:%d: samples %d: %s", path, sc->samples_line, (int)samples, why);
    } else if (e == FXRT_ERR_RENDER) {
        snprintf(err, errlen, "%s: %s", path, why);
    } else {
        snprintf(err, errlen, "%s: %s (%d)", path, why, FXRT_RENDER_MAX_WIDTH);
    }
    return -1;
}

int ENGINE_SYM(engine_render)(const char *path, const scene_t *sc, int width, int height,
                              engine_renderer_t renderer, uint8_t *rgb, uint32_t *keys, char *err,
                              size_t errlen)
{
    /* Static: the host world and render state hold up to 64 objects of each
     * kind, too big for a stack frame. The CLI renders one frame at a time. */
    static world_t world;
    static render_t state;
    cam_t cam;
    if (ENGINE_SYM(engine_build)(path, sc, width, height, &world, &cam, err, errlen) != 0)
        return -1;
    int32_t samples = world_samples(&world);
    bool adaptive = world_adaptive(&world);
    if (keys != NULL && samples > 1) {
        /* A key is that of one ray through the pixel centre (render_key),
         * whatever the samples: a pass at one sample per pixel writes the
         * keys, its colours are thrown away, and the image is rendered
         * after it with the scene's samples and no keys. */
        if (world_set_samples(&world, 1, false) != FXRT_OK) {
            snprintf(err, errlen, "%s:%d: samples 1 cannot be set in %s", path, sc->samples_line, NUM_NAME);
            return -1;
        }
        fxrt_err_t e = fxrt_render_setup(&state, &world, &cam);
        if (e != FXRT_OK)
            return engine_setup_error(e, &state, path, sc, width, 1, err, errlen);
        engine_pass(&state, &world, &cam, width, height, renderer, NULL, keys);
        if (rgb == NULL)
            return 0; /* the keys were all the caller wanted */
        keys = NULL;
        if (world_set_samples(&world, samples, adaptive) != FXRT_OK) {
            snprintf(err, errlen, "%s:%d: samples %d cannot be set in %s", path, sc->samples_line, (int)samples,
                     NUM_NAME);
            return -1;
        }
    }
    fxrt_err_t e = fxrt_render_setup(&state, &world, &cam);
    if (e != FXRT_OK)
        return engine_setup_error(e, &state, path, sc, width, samples, err, errlen);
    engine_pass(&state, &world, &cam, width, height, renderer, rgb, keys);
    return 0;
}
