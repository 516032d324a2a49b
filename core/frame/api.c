/* fxrt: the public API's checked entry points (see fxrt.h). */
#include "fxrt.h"

/* The configuration this core is built with, as link-time names that
 * fxrt_world_init (inline, compiled in the application) refers to: the
 * options, and each kind's capacity. The values are the capacities; the
 * names are the check. */
const uint32_t FXRT_CONFIG_SYMBOL = 1;
#define FXRT_CAPACITY_DEFINE(K, k, ks, cap, ...) const uint32_t FXRT_CAPACITY_SYMBOL(ks, cap) = cap;
FXRT_KINDS(FXRT_CAPACITY_DEFINE)
/* The bounce loop's stack (FXRT_STACK_RESERVE, fxrt_config.h): reserved
 * here, placed by the linker script, which marks that it did. */
#if FXRT_STACK_RESERVE
uint8_t fxrt_stack_extra[FXRT_STACK_EXTRA] __attribute__((section(".stack_extra"), aligned(8)));
#endif
extern uint8_t fxrt_stack_extra[];
extern const uint8_t fxrt_stack_extra_needs_linker_script_keep[];

#define FXRT_CAPACITY_SAME(K, k, ks, cap, ...) &&capacities[GEOM_##K] == &FXRT_CAPACITY_SYMBOL(ks, cap)

fxrt_err_t fxrt_world_init_checked(world_t *w, color_t background, uint32_t world_size, uint32_t render_size,
                                   const uint32_t *config, const uint32_t *const *capacities)
{
    if (FXRT_STACK_RESERVE) {
        PORT_KEEP(fxrt_stack_extra);
        PORT_KEEP(fxrt_stack_extra_needs_linker_script_keep);
    }
    if (w == NULL)
        return FXRT_ERR_NULL;
    if (world_size != sizeof(world_t) || render_size != sizeof(render_t) || config != &FXRT_CONFIG_SYMBOL ||
        capacities == NULL || !(true FXRT_KINDS(FXRT_CAPACITY_SAME)))
        return FXRT_ERR_CONFIG;
    fxrt_err_t e = geom_check_color(background);
    if (e != FXRT_OK)
        return e;
    world_init(w, background);
    return FXRT_OK;
}

/* A world the caller may use, and (when not NULL already) the object a
 * call takes: FXRT_OK, FXRT_ERR_NULL, FXRT_ERR_INIT. */
static fxrt_err_t fxrt_world_ok_with(const world_t *w, const void *arg)
{
    if (w == NULL || arg == NULL)
        return FXRT_ERR_NULL;
    return w->ready == WORLD_READY ? FXRT_OK : FXRT_ERR_INIT;
}
static fxrt_err_t fxrt_world_ok(const world_t *w)
{
    return fxrt_world_ok_with(w, w);
}

/* The API's colours are all in 1/255 units; the world keeps a light's,
 * the ambient, specular and reflection colours as fractions
 * (color_fractions: exactly the fraction the scene loader would hold). A
 * colour outside 0..255 stays as it is, outside 0..1 too, for the world's
 * own checks to refuse in their order. */
static color_t fxrt_fractions(color_t c)
{
    return geom_check_color(c) == FXRT_OK ? color_fractions(c) : c;
}

static material_t fxrt_material(const material_t *m)
{
    material_t f = *m;
    if (FXRT_MAX_LIGHTS == 0)
        return f; /* refused as it is (world_check_material): nothing to convert */
    f.specular = fxrt_fractions(m->specular);
    f.reflection = fxrt_fractions(m->reflection);
    return f;
}

int32_t fxrt_add(world_t *w, const fxrt_object_t *o)
{
    fxrt_err_t ok = fxrt_world_ok_with(w, o);
    if (ok != FXRT_OK)
        return ok;
    /* The material is checked first: a refused object leaves the world
     * unchanged. */
    material_t m = fxrt_material(&o->material);
    fxrt_err_t e = world_check_material(&m);
    if (e != FXRT_OK)
        return e;
    int32_t id = world_add(w, o);
    if (id >= 0 && FXRT_MAX_LIGHTS > 0 && m.kind != MATERIAL_FLAT)
        (void)world_set_material(w, id, &m); /* checked above: FXRT_OK */
    return id;
}

int32_t fxrt_count(const world_t *w)
{
    return fxrt_world_ok(w) == FXRT_OK ? world_count(w) : 0;
}

fxrt_err_t fxrt_set_material(world_t *w, int32_t id, const material_t *m)
{
    fxrt_err_t ok = fxrt_world_ok_with(w, m);
    if (ok != FXRT_OK)
        return ok;
    material_t f = fxrt_material(m);
    return world_set_material(w, id, &f);
}

fxrt_err_t fxrt_set_ambient(world_t *w, color_t ambient)
{
    fxrt_err_t ok = fxrt_world_ok(w);
    return ok != FXRT_OK ? ok : world_set_ambient(w, fxrt_fractions(ambient));
}

fxrt_err_t fxrt_set_depth(world_t *w, int32_t depth)
{
    fxrt_err_t ok = fxrt_world_ok(w);
    return ok != FXRT_OK ? ok : world_set_depth(w, depth);
}

fxrt_err_t fxrt_set_samples(world_t *w, int32_t samples, bool adaptive)
{
    fxrt_err_t ok = fxrt_world_ok(w);
    return ok != FXRT_OK ? ok : world_set_samples(w, samples, adaptive);
}

int32_t fxrt_add_light(world_t *w, const fxrt_light_t *l)
{
    fxrt_err_t ok = fxrt_world_ok_with(w, l);
    if (ok != FXRT_OK)
        return ok;
    return world_add_light(w, l->kind, l->position, l->direction, l->angle_deg, fxrt_fractions(l->color),
                           l->shadows);
}

/* cam_setup's codes in the API's terms. */
static fxrt_err_t fxrt_cam_err(cam_err_t e)
{
    switch (e) {
    case CAM_OK: return FXRT_OK;
    case CAM_ERR_SIZE: return FXRT_ERR_SIZE;
    case CAM_ERR_GAZE: return FXRT_ERR_DIRECTION;
    case CAM_ERR_UP: return FXRT_ERR_UP;
    case CAM_ERR_FOV: return FXRT_ERR_FOV;
    case CAM_ERR_NARROW: return FXRT_ERR_NARROW;
    case CAM_ERR_SCALE: return FXRT_ERR_SCALE;
    case CAM_ERR_EXTENT: return FXRT_ERR_EXTENT;
    default: break; /* codes cam.h adds later */
    }
    return (fxrt_err_t)(FXRT_ERR_CAM_BASE + (int)e);
}

/* cam_setup writes the view only when it succeeds (scene/cam.c): a
 * refused camera leaves the caller's view as it was (a frame set up with
 * it still renders), with no copy of the view on the stack. */
static fxrt_err_t fxrt_cam_set(cam_t *cam, cam_kind_t kind, vec3_t eye, vec3_t gaze, vec3_t up, num_t fov_deg,
                               num_t scale, int32_t width, int32_t height)
{
    return fxrt_cam_err(cam_setup(cam, kind, eye, gaze, up, fov_deg, scale, width, height));
}

/* What both camera kinds check before cam_setup: the image size, and eye,
 * gaze and up inside the domain. */
static fxrt_err_t fxrt_camera_common(vec3_t eye, vec3_t gaze, vec3_t up, int32_t width, int32_t height)
{
    if (width < 1 || height < 1 || width > FXRT_MAX_DIM || height > FXRT_MAX_DIM)
        return FXRT_ERR_SIZE;
    fxrt_err_t e = geom_check_point(eye);
    if (e == FXRT_OK)
        e = geom_check_dir(gaze);
    if (e == FXRT_OK)
        e = geom_check_dir(up);
    return e;
}

fxrt_err_t fxrt_camera_perspective(cam_t *cam, vec3_t eye, vec3_t gaze, vec3_t up, num_t fov_deg,
                                   int32_t width, int32_t height)
{
    if (cam == NULL)
        return FXRT_ERR_NULL;
    fxrt_err_t e = fxrt_camera_common(eye, gaze, up, width, height);
    if (e != FXRT_OK)
        return e;
    if (!(fov_deg > NUM_ZERO && fov_deg < NUM(180)))
        return FXRT_ERR_FOV;
    return fxrt_cam_set(cam, CAM_PERSPECTIVE, eye, gaze, up, fov_deg, NUM_ONE, width, height);
}

fxrt_err_t fxrt_camera_orthographic(cam_t *cam, vec3_t eye, vec3_t gaze, vec3_t up, num_t scale, int32_t width,
                                    int32_t height)
{
    if (cam == NULL)
        return FXRT_ERR_NULL;
    fxrt_err_t e = fxrt_camera_common(eye, gaze, up, width, height);
    if (e != FXRT_OK)
        return e;
    if (!(scale > NUM_ZERO && scale <= num_from_int(FXRT_RADIUS_LIMIT)))
        return FXRT_ERR_SCALE;
    if (!NUM_EXACT && scale < NUM(1.0 / 65536.0))
        return FXRT_ERR_TINY; /* (float and double: below Q16.16's step) */
    return fxrt_cam_set(cam, CAM_ORTHOGRAPHIC, eye, gaze, up, NUM(90), scale, width, height);
}

fxrt_err_t fxrt_camera_setup(cam_t *cam, const fxrt_camera_t *c)
{
    if (c == NULL)
        return FXRT_ERR_NULL;
    if (c->kind == CAM_PERSPECTIVE)
        return fxrt_camera_perspective(cam, c->eye, c->gaze, c->up, c->fov_deg, c->width, c->height);
    if (c->kind == CAM_ORTHOGRAPHIC)
        return fxrt_camera_orthographic(cam, c->eye, c->gaze, c->up, c->scale, c->width, c->height);
    return FXRT_ERR_CAMERA;
}

fxrt_err_t fxrt_render_setup_checked(render_t *r, const world_t *w, const cam_t *cam, uint32_t render_size)
{
    if (r == NULL)
        return FXRT_ERR_NULL;
    r->vis.world = NULL; /* not set up until render_setup succeeds */
    r->error = NULL;
    if (w == NULL || cam == NULL)
        return FXRT_ERR_NULL;
    if (w->ready != WORLD_READY)
        return FXRT_ERR_INIT;
    if (render_size != sizeof(render_t))
        return FXRT_ERR_CONFIG;
    if ((int64_t)cam->width * world_samples(w) > FXRT_RENDER_MAX_WIDTH)
        return FXRT_ERR_WIDTH; /* (the renderer holds samples x width columns) */
    if (cam->width < 1 || cam->height < 1 || cam->height > FXRT_MAX_DIM)
        return FXRT_ERR_SIZE; /* a view the camera calls never set up */
    if (render_setup(r, w, cam)) {
        r->out_width = (uint16_t)cam->width;
        r->out_height = (uint16_t)cam->height;
        return FXRT_OK;
    }
    r->vis.world = NULL; /* (r->error keeps render_setup's reason) */
    return FXRT_ERR_RENDER;
}

const char *fxrt_render_error(const render_t *r)
{
    return r == NULL ? NULL : r->error;
}

fxrt_err_t fxrt_render_row(render_t *r, int32_t row, uint8_t *out, size_t out_bytes)
{
    if (r == NULL || out == NULL)
        return FXRT_ERR_NULL;
    if (r->vis.world == NULL || r->error != NULL)
        return FXRT_ERR_SETUP;
    const cam_t *cam = RENDER_OUT_CAM(r);
    if (cam->width != r->out_width || cam->height != r->out_height)
        return FXRT_ERR_SETUP; /* the view changed since the set-up */
    if (row < 0 || row >= cam->height)
        return FXRT_ERR_ROW;
    if (out_bytes < (size_t)FXRT_ROW_BYTES(cam->width) || (FXRT_PIXEL == FXRT_RGB565 && ((uintptr_t)out & 1u)))
        return FXRT_ERR_BUFFER;
    render_row(r, row, out);
    return FXRT_OK;
}

const char *fxrt_strerror(int32_t err)
{
    if (err >= 0)
        return "ok";
    if (err < FXRT_ERR_CAM_BASE && err > FXRT_ERR_CAM_BASE - 100)
        return cam_strerror((cam_err_t)(err - FXRT_ERR_CAM_BASE));
    switch ((fxrt_err_t)err) {
    case FXRT_OK: return "ok";
    case FXRT_ERR_FULL: return "no room for another object of this kind (its FXRT_MAX_<KIND>; 0 compiles the kind out)";
    case FXRT_ERR_COORD: return "coordinate beyond +-FXRT_COORD_LIMIT";
    case FXRT_ERR_TINY: return "nonzero value below 2^-16 (it would be 0 in Q16.16)";
    case FXRT_ERR_DIRECTION: return "direction (normal, gaze, up or light direction) has zero length";
    case FXRT_ERR_RADIUS: return "radius must be in (0, FXRT_RADIUS_LIMIT]";
    case FXRT_ERR_COLOR: return "colour channel outside 0..255 (1/255 units; 0..1 in a scene file)";
    case FXRT_ERR_BOX: return "box min > max on some axis";
    /* The camera's texts are cam_setup's, so the host tool's messages do
     * not depend on which layer refused. */
    case FXRT_ERR_SIZE: return cam_strerror(CAM_ERR_SIZE);
    case FXRT_ERR_UP: return cam_strerror(CAM_ERR_UP);
    case FXRT_ERR_FOV: return cam_strerror(CAM_ERR_FOV);
    case FXRT_ERR_NARROW: return cam_strerror(CAM_ERR_NARROW);
    case FXRT_ERR_SCALE: return "orthographic scale must be in (0, FXRT_RADIUS_LIMIT]";
    case FXRT_ERR_EXTENT: return cam_strerror(CAM_ERR_EXTENT);
    case FXRT_ERR_CAMERA: return "unknown camera kind (FXRT_PERSPECTIVE or FXRT_ORTHOGRAPHIC)";
    case FXRT_ERR_CAM_BASE: break;
    case FXRT_ERR_WIDTH:
        return "image wider than FXRT_RENDER_MAX_WIDTH columns (with samples N, the renderer holds N x width "
               "columns)";
    case FXRT_ERR_KIND: return "unknown object kind (FXRT_PLANE, FXRT_SPHERE, FXRT_TRIANGLE or FXRT_BOX)";
    case FXRT_ERR_CONFIG:
        return "core and application built with different configurations (FXRT_NUMBER, FXRT_MAX_*, "
               "FXRT_RENDER_MAX_WIDTH, FXRT_PIXEL must match)";
    case FXRT_ERR_RENDER: return "the frame needs more than fxrt_render_t holds (fxrt_render_error says what)";
    case FXRT_ERR_ANGLE: return "spot light half-angle must be in (0, 90] degrees";
    case FXRT_ERR_MATERIAL:
        return "unknown material kind, or its lighting compiled out (FXRT_MAX_LIGHTS 0; phong and reflective: "
               "FXRT_PHONG 0)";
    case FXRT_ERR_ID: return "no object with this id (ids run from 0 to fxrt_count() - 1)";
    case FXRT_ERR_LIGHT: return "unknown light kind (FXRT_LIGHT_POINT, _DIRECTIONAL or _SPOT)";
    case FXRT_ERR_INIT: return "the world was not set up with fxrt_world_init";
    case FXRT_ERR_NULL: return "a NULL pointer where an object is needed";
    case FXRT_ERR_ROW: return "row outside 0..height-1";
    case FXRT_ERR_SETUP: return "no successful fxrt_render_setup on this fxrt_render_t since its view last changed";
    case FXRT_ERR_BUFFER: return "row buffer smaller than FXRT_ROW_BYTES(width) (or, RGB565, not 2-byte aligned)";
    case FXRT_ERR_EXPONENT: return "phong exponent outside 1..FXRT_PHONG_MAX_EXPONENT (1024)";
    case FXRT_ERR_INDEX: return "refraction index outside FXRT_INDEX_MIN..FXRT_INDEX_MAX (0.01..100)";
    case FXRT_ERR_LIGHTS: return "no room for another light (FXRT_MAX_LIGHTS; 0 compiles lighting out)";
    case FXRT_ERR_MESH: return "a model's mesh data or placement is malformed, or its box reaches beyond the coordinate limit";
    case FXRT_ERR_AXES: return "an ellipsoid's or parallelepiped's axes are dependent (it would be flat), too thin, or span too much volume";
    case FXRT_ERR_DEPTH: return "depth outside 0..FXRT_MAX_DEPTH (largest number of bounces)";
    case FXRT_ERR_SAMPLES:
        return "samples outside 1..FXRT_MAX_SAMPLES, or adaptive with fewer than 2 samples or compiled out "
               "(FXRT_ADAPTIVE 0)";
    }
    return "unknown error";
}
