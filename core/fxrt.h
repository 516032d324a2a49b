/* fxrt.h: the public API for building a world and a camera in code and
 * rendering rows, for firmware authors. docs/EMBEDDING.md says which files
 * to compile and which macros must match; examples/orbit.c is a whole
 * program.
 *
 * Conventions (cam.h has them in full):
 *  - Right-handed scene coordinates in scene units. Every number is num_t:
 *    Q16.16 (fx_t, write constants as F16(1.5)) in the product build,
 *    float or double in the reference builds (FXRT_NUMBER).
 *  - The camera looks along gaze with up roughly up; up must not be
 *    parallel to gaze (to look straight down, gaze 0 -1 0, take up 0 0 -1).
 *  - Rows are numbered from the top (row 0 = top of the image); within a
 *    row, pixels go left to right.
 *
 * Life cycle, all memory owned by the caller (static arrays, no heap):
 *
 *   static world_t world;      // FXRT_MAX_<KIND> objects of each kind
 *   static render_t rs;        // per-frame forms, one entry per object
 *   cam_t cam;
 *   fxrt_world_init(&world, background);           // once
 *   world_add_sphere(&world, centre, radius, colour); ...  // ids 0, 1, ...
 *   per frame:
 *     fxrt_camera_perspective(&cam, eye, gaze, up, fov, W, H);
 *     fxrt_render_setup(&rs, &world, &cam);
 *     for (row = 0; row < H; row++) fxrt_render_row(&rs, row, buf);
 *
 * Every call that can refuse its input returns FXRT_OK (0) or an object
 * id (>= 0), or a negative fxrt_err_t (fxrt_err.h); fxrt_strerror(code)
 * gives the text. Values are checked against the domain in which the
 * Q16.16 renderer is exact (docs/ACCURACY.md): |coordinates| <=
 * FXRT_COORD_LIMIT, radius and orthographic scale in (0,
 * FXRT_RADIUS_LIMIT], colours 0..1, nonzero directions, box min <= max,
 * fov in (0, 180) degrees, image sides 1..FXRT_MAX_DIM. A value outside
 * it is refused, never rendered wrong.
 *
 * Configuration: the core and the application must be compiled with the
 * same FXRT_NUMBER, FXRT_MAX_<KIND>, FXRT_MAX_LIGHTS, FXRT_MAX_DEPTH,
 * FXRT_MAX_SAMPLES, FXRT_ADAPTIVE, FXRT_RENDER_MAX_WIDTH (and FXRT_PIXEL),
 * since they change world_t and render_t. fxrt_world_init
 * references a symbol whose name spells the application's configuration
 * (fxrt_config_n1_p4_s4_t4_b4_w64_px1_l0_d0_x1a0 ...); the core defines only the one
 * for its own, so a mismatch fails at link time with
 *   undefined reference to `fxrt_config_n1_p0_s8_t0_b0_w64_px1_l0_d0_x1a0'
 * and, should it link anyway, fxrt_world_init returns FXRT_ERR_CONFIG.
 * The macros must be plain decimal integers for the name to form.
 */
#ifndef FXRT_H
#define FXRT_H

#include <stddef.h>

#include "scene/cam.h"
#include "fxrt_err.h"
#include "frame/render.h"
#include "scene/world.h"

/* Bytes of one output row of `width` pixels: RGB888, 3 bytes per pixel,
 * or RGB565 (2 bytes) when the core is built with FXRT_PIXEL =
 * FXRT_RGB565. */
#define FXRT_ROW_BYTES(width) ((FXRT_PIXEL == FXRT_RGB565 ? 2 : 3) * (width))

/* --- configuration check ------------------------------------------------ */
#define FXRT_CONFIG_CAT_(n, p, s, t, b, w, px, l, d, x, ad)                                                    \
    fxrt_config_n##n##_p##p##_s##s##_t##t##_b##b##_w##w##_px##px##_l##l##_d##d##_x##x##a##ad
#define FXRT_CONFIG_CAT(n, p, s, t, b, w, px, l, d, x, ad) FXRT_CONFIG_CAT_(n, p, s, t, b, w, px, l, d, x, ad)
/* The configuration as a link-time name, e.g.
 * fxrt_config_n1_p64_s64_t64_b64_w4096_px1_l8_d16_x16a1 (l: FXRT_MAX_LIGHTS, d: FXRT_MAX_DEPTH,
 * x: FXRT_MAX_SAMPLES, a: FXRT_ADAPTIVE). */
#define FXRT_CONFIG_SYMBOL                                                                                    \
    FXRT_CONFIG_CAT(FXRT_NUMBER, FXRT_MAX_PLANES, FXRT_MAX_SPHERES, FXRT_MAX_TRIANGLES, FXRT_MAX_BOXES,       \
                    FXRT_RENDER_MAX_WIDTH, FXRT_PIXEL, FXRT_MAX_LIGHTS, FXRT_MAX_DEPTH, FXRT_MAX_SAMPLES,    \
                    FXRT_ADAPTIVE)
/* Defined once, in core/fxrt.c, for the configuration the core is built with. */
extern const uint32_t FXRT_CONFIG_SYMBOL;

/* The checked entry points behind the inline wrappers below: they compare
 * the sizes and configuration the application saw with the core's. */
fxrt_err_t fxrt_world_init_checked(world_t *w, color_t background, uint32_t world_size, uint32_t render_size,
                                   const uint32_t *config);
fxrt_err_t fxrt_render_setup_checked(render_t *r, const world_t *w, const cam_t *cam, uint32_t render_size);

/* --- world ---------------------------------------------------------------- */

/* Empty world with a background colour (0..1 per channel). Returns FXRT_OK,
 * FXRT_ERR_COLOR, or FXRT_ERR_CONFIG when the core was built with another
 * configuration (see above; normally the link fails first). */
static inline fxrt_err_t fxrt_world_init(world_t *w, color_t background)
{
    return fxrt_world_init_checked(w, background, (uint32_t)sizeof(world_t), (uint32_t)sizeof(render_t),
                                   &FXRT_CONFIG_SYMBOL);
}

/* Adding objects: fxrt_add (below) returns the object's id (0, 1, 2, ...
 * in the order added, across all kinds; nearer wins, equal depth goes to
 * the lower id) or a negative fxrt_err_t: FXRT_ERR_FULL when
 * FXRT_MAX_<KIND> objects of that kind are there already (a kind with
 * capacity 0 is compiled out), FXRT_ERR_COORD, FXRT_ERR_DIRECTION,
 * FXRT_ERR_RADIUS, FXRT_ERR_COLOR, FXRT_ERR_BOX, FXRT_ERR_TINY. A refused
 * object leaves the world unchanged. A plane's normal need not be unit
 * length. A collinear triangle is accepted and never hit. */

/* One object as data, for tables of objects (the scene compiler emits
 * them): scene/kinds.h's geom_desc_t. p[] holds: plane point, normal;
 * sphere centre; triangle a, b, c; box min, max. radius: spheres only. */
typedef geom_desc_t fxrt_object_t;

/* world_add for o, then world_set_material when the material
 * is not flat. Returns the id or a negative fxrt_err_t (FXRT_ERR_KIND for
 * an unknown kind; a refused material removes nothing but leaves the
 * object flat, so check the code). */
int32_t fxrt_add(world_t *w, const fxrt_object_t *o);

/* --- lights ---------------------------------------------------------------
 * (world.h: world_set_ambient, world_set_material, world_add_light.) A
 * light as data, what the scene compiler emits: position for point and
 * spot, direction for directional and spot, angle_deg (the cone's
 * half-angle) for spot. */
typedef struct {
    light_kind_t kind;
    vec3_t position, direction;
    num_t angle_deg;
    color_t color; /* fractions 0..1 */
    bool shadows;
} fxrt_light_t;

/* world_add_light for a description: the light's index or a negative
 * fxrt_err_t. */
int32_t fxrt_add_light(world_t *w, const fxrt_light_t *l);

/* --- camera --------------------------------------------------------------- */

/* Perspective camera for a width x height image: fov_deg is the full
 * vertical opening angle in degrees, in (0, 180). eye within
 * +-FXRT_COORD_LIMIT, gaze and up nonzero, not parallel. Returns FXRT_OK or
 * FXRT_ERR_SIZE, _COORD, _DIRECTION, _UP, _FOV, _NARROW (height *
 * cot(fov/2) > 32767: the rays would not fit Q16.16), _TINY; a camera
 * error cam.h has no FXRT_ERR_ name for comes back as FXRT_ERR_CAM_BASE +
 * its cam_err_t (fxrt_strerror gives cam_strerror's text). */
fxrt_err_t fxrt_camera_perspective(cam_t *cam, vec3_t eye, vec3_t gaze, vec3_t up, num_t fov_deg,
                                   int32_t width, int32_t height);

/* Orthographic camera: scale is the view height in scene units, in (0,
 * FXRT_RADIUS_LIMIT]; the view must stay inside +-FXRT_COORD_LIMIT
 * (FXRT_ERR_EXTENT). Other codes as for the perspective camera. */
fxrt_err_t fxrt_camera_orthographic(cam_t *cam, vec3_t eye, vec3_t gaze, vec3_t up, num_t scale, int32_t width,
                                    int32_t height);

/* A camera as data (what the scene compiler emits). */
typedef struct {
    cam_kind_t kind; /* CAM_PERSPECTIVE or CAM_ORTHOGRAPHIC */
    vec3_t eye, gaze, up;
    num_t fov_deg; /* perspective only */
    num_t scale;   /* orthographic only */
    int32_t width, height;
} fxrt_camera_t;

/* fxrt_camera_perspective or _orthographic from a description. */
fxrt_err_t fxrt_camera_setup(cam_t *cam, const fxrt_camera_t *c);

/* --- rendering ------------------------------------------------------------ */

/* Per-frame set-up: the camera-space forms and screen bounds of every
 * object. Call it again after moving the camera or changing the world;
 * world and camera must stay alive and unchanged while rows are rendered.
 * Returns FXRT_OK, FXRT_ERR_WIDTH (camera wider than
 * FXRT_RENDER_MAX_WIDTH), FXRT_ERR_RENDER (render_setup refused the frame
 * otherwise) or FXRT_ERR_CONFIG. */
static inline fxrt_err_t fxrt_render_setup(render_t *r, const world_t *w, const cam_t *cam)
{
    return fxrt_render_setup_checked(r, w, cam, (uint32_t)sizeof(render_t));
}

/* Render output row `row` (0 = top, < height) into out, which holds
 * FXRT_ROW_BYTES(width) bytes. Rows may come in any order. */
static inline void fxrt_render_row(render_t *r, int32_t row, uint8_t *out)
{
    render_row(r, row, out);
}

/* Short English text for an fxrt_err_t (or "ok" for any value >= 0). */
const char *fxrt_strerror(int32_t err);

#endif
