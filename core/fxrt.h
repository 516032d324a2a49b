/* fxrt.h: the public API. Every name it gives an application starts with
 * fxrt_ or FXRT_; docs/EMBEDDING.md has the whole path from a world built
 * in code to a board's display, examples/orbit.c is a whole program.
 *
 *   static fxrt_world_t world;   // FXRT_MAX_<KIND> objects of each kind
 *   static fxrt_render_t rs;     // per-frame forms, one entry per object
 *   fxrt_view_t view;            // a camera, set up
 *   fxrt_world_init(&world, background);                  // once
 *   fxrt_add(&world, &(fxrt_object_t){.kind = FXRT_SPHERE, ...});  // ids 0, 1, ...
 *   per frame:
 *     fxrt_camera_perspective(&view, eye, gaze, up, fov, W, H);
 *     fxrt_render_setup(&rs, &world, &view);
 *     for (row = 0; row < H; row++) fxrt_render_row(&rs, row, buf, sizeof buf);
 *
 * Every call that can refuse its input returns FXRT_OK (0), an id (>= 0)
 * or a negative fxrt_err_t (fxrt_err.h), and a refused call changes
 * nothing; fxrt_strerror(code) gives the text. Pointers may be NULL
 * (FXRT_ERR_NULL), rows out of range (FXRT_ERR_ROW), a frame not set up
 * (FXRT_ERR_SETUP), a row buffer short (FXRT_ERR_BUFFER): no input
 * crashes the core. What C cannot check is left to the caller: a pointer
 * to memory that is not the object it claims to be. Values are checked against
 * the domain in which the Q16.16 renderer is exact (docs/ACCURACY.md).
 *
 * Numbers are fxrt_num_t: Q16.16 in the product build (constants:
 * FXRT_NUM(1.5)), float or double in the reference builds (FXRT_NUMBER).
 * Scene coordinates are right-handed; rows are numbered from the top.
 *
 * Configuration: the core and the application must be compiled with the
 * same FXRT_NUMBER, FXRT_MAX_<KIND>, FXRT_MAX_LIGHTS, FXRT_MAX_DEPTH,
 * FXRT_MAX_SAMPLES, FXRT_ADAPTIVE, FXRT_RENDER_MAX_WIDTH and FXRT_PIXEL
 * (they size fxrt_world_t and fxrt_render_t). fxrt_world_init refers to a
 * symbol whose name spells the application's configuration, and one per
 * kind for its capacity, e.g.
 *   undefined reference to `fxrt_capacity_spheres_8'
 * so a mismatch fails at link time, and should it link anyway,
 * fxrt_world_init returns FXRT_ERR_CONFIG. The macros must be plain
 * decimal integers for the name to form. */
#ifndef FXRT_H
#define FXRT_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "port/port.h"

FXRT_C_BEGIN /* C linkage in a C++ program (port/port.h) */

#include "scene/cam.h"
#include "fxrt_err.h"
#include "frame/render.h"
#include "scene/bvh.h"
#include "scene/world.h"

/* Bytes of one output row of `width` pixels: RGB888, 3 bytes per pixel,
 * or RGB565 (2 bytes) when the core is built with FXRT_PIXEL =
 * FXRT_RGB565. */
#define FXRT_ROW_BYTES(width) ((FXRT_PIXEL == FXRT_RGB565 ? 2 : 3) * (width))

/* --- types and constants ------------------------------------------------ */

typedef num_t fxrt_num_t;           /* Q16.16 (int32_t), float or double */
typedef vec3_t fxrt_vec3_t;         /* x, y, z */
typedef color_t fxrt_color_t;       /* r, g, b in 1/255 units: 0 off, 255 full (every colour) */
typedef world_t fxrt_world_t;       /* the objects, lights and settings */
typedef cam_t fxrt_view_t;          /* a camera, set up (fxrt_camera_*) */
typedef render_t fxrt_render_t;     /* a frame's state (fxrt_render_setup) */
typedef material_t fxrt_material_t; /* .kind, .exponent, .specular, .reflection, .index */
typedef bvh_mesh_t fxrt_mesh_t;     /* a mesh in constant data (docs/MESHES.md; fxrt-scenec --mesh writes one) */
typedef bvh_node_t fxrt_mesh_node_t;
typedef bvh_inst_t fxrt_instance_t; /* a mesh placed in the world: a model's .inst (docs/MESHES.md) */

/* A number literal: FXRT_NUM(0.5). */
#define FXRT_NUM(x) NUM(x)
/* A colour literal from intensity fractions 0..1, quantised as the scene
 * loader does (0.7 is 178.5 of 255 in every build). One unit serves every
 * colour: objects, the background, lights, the ambient, specular and
 * reflection colours. */
#define FXRT_RGB(r, g, b) fxrt_color(COLOR_FRAC(r), COLOR_FRAC(g), COLOR_FRAC(b))

/* The kinds (FXRT_PLANE, FXRT_SPHERE, FXRT_TRIANGLE, FXRT_BOX, FXRT_MODEL: one per row
 * of scene/kinds.h), materials (FXRT_MATERIAL_FLAT, _LAMBERT, _PHONG,
 * _REFLECTIVE, _TRANSPARENT), lights (FXRT_LIGHT_POINT, _DIRECTIONAL,
 * _SPOT) and cameras (FXRT_PERSPECTIVE, FXRT_ORTHOGRAPHIC) are the
 * constants of these enumerations. */
typedef geom_kind_t fxrt_kind_t;
typedef material_kind_t fxrt_material_kind_t;
typedef light_kind_t fxrt_light_kind_t;
typedef cam_kind_t fxrt_camera_kind_t;

/* Colours in 1/255 units (0..255 per channel, FXRT_ERR_COLOR outside; a
 * channel need not be a whole number: 178.5 is 0.7), vectors, and the arithmetic an animation needs,
 * in the build's number type. */
static inline fxrt_color_t fxrt_color(fxrt_num_t r, fxrt_num_t g, fxrt_num_t b) { return color_make(r, g, b); }
static inline fxrt_vec3_t fxrt_vec3(fxrt_num_t x, fxrt_num_t y, fxrt_num_t z) { return vec3_make(x, y, z); }
static inline fxrt_vec3_t fxrt_vec3_add(fxrt_vec3_t a, fxrt_vec3_t b) { return vec3_add(a, b); }
static inline fxrt_vec3_t fxrt_vec3_sub(fxrt_vec3_t a, fxrt_vec3_t b) { return vec3_sub(a, b); }
static inline fxrt_num_t fxrt_mul(fxrt_num_t a, fxrt_num_t b) { return num_mul(a, b); }
static inline fxrt_num_t fxrt_from_int(int32_t i) { return num_from_int(i); }

/* --- configuration check ------------------------------------------------ */
#define FXRT_CONFIG_CAT_(n, w, px, l, d, x, ad) fxrt_config_n##n##_w##w##_px##px##_l##l##_d##d##_x##x##a##ad
#define FXRT_CONFIG_CAT(n, w, px, l, d, x, ad) FXRT_CONFIG_CAT_(n, w, px, l, d, x, ad)
/* The configuration as link-time names: one for the number type and the
 * options, e.g. fxrt_config_n1_w4096_px1_l8_d16_x16a1 (n: FXRT_NUMBER, w:
 * FXRT_RENDER_MAX_WIDTH, px: FXRT_PIXEL, l: FXRT_MAX_LIGHTS, d:
 * FXRT_MAX_DEPTH, x: FXRT_MAX_SAMPLES, a: FXRT_ADAPTIVE), and one per kind
 * for its capacity, e.g. fxrt_capacity_spheres_64 (from the kinds table). */
#define FXRT_CONFIG_SYMBOL                                                                                    \
    FXRT_CONFIG_CAT(FXRT_NUMBER, FXRT_RENDER_MAX_WIDTH, FXRT_PIXEL, FXRT_MAX_LIGHTS, FXRT_MAX_DEPTH,           \
                    FXRT_MAX_SAMPLES, FXRT_ADAPTIVE)
#define FXRT_CAPACITY_CAT_(ks, cap) fxrt_capacity_##ks##_##cap
#define FXRT_CAPACITY_CAT(ks, cap) FXRT_CAPACITY_CAT_(ks, cap)
#define FXRT_CAPACITY_SYMBOL(ks, cap) FXRT_CAPACITY_CAT(ks, cap)
/* Defined once, in core/frame/api.c, for the configuration the core is
 * built with. */
extern const uint32_t FXRT_CONFIG_SYMBOL;
#define FXRT_CAPACITY_DECLARE(K, k, ks, cap, ...) extern const uint32_t FXRT_CAPACITY_SYMBOL(ks, cap);
FXRT_KINDS(FXRT_CAPACITY_DECLARE)
#undef FXRT_CAPACITY_DECLARE
#define FXRT_CAPACITY_ADDRESS(K, k, ks, cap, ...) &FXRT_CAPACITY_SYMBOL(ks, cap),

/* The checked entry points behind the inline wrappers below: they compare
 * the sizes and configuration the application saw with the core's
 * (capacities: one address per kind, in the table's order). */
fxrt_err_t fxrt_world_init_checked(world_t *w, color_t background, uint32_t world_size, uint32_t render_size,
                                   const uint32_t *config, const uint32_t *const *capacities);
fxrt_err_t fxrt_render_setup_checked(render_t *r, const world_t *w, const cam_t *cam, uint32_t render_size);

/* --- world ---------------------------------------------------------------- */

/* Empty world with a background colour. Returns FXRT_OK,
 * FXRT_ERR_NULL, FXRT_ERR_COLOR, or FXRT_ERR_CONFIG when the core was
 * built with another configuration (see above; normally the link fails
 * first). */
static inline fxrt_err_t fxrt_world_init(fxrt_world_t *w, fxrt_color_t background)
{
    static const uint32_t *const capacities[] = {FXRT_KINDS(FXRT_CAPACITY_ADDRESS)};
    return fxrt_world_init_checked(w, background, (uint32_t)sizeof(world_t), (uint32_t)sizeof(render_t),
                                   &FXRT_CONFIG_SYMBOL, capacities);
}

/* One object as data (the scene compiler emits tables of them): .kind
 * (FXRT_PLANE ...), .p[] (plane: point, normal; sphere: centre; triangle:
 * a, b, c; box: min, max), .radius (spheres), .inst (a model's placed mesh,
 * copied when added: docs/MESHES.md), .color, and .material (flat when
 * left zero). */
typedef geom_desc_t fxrt_object_t;

/* Adds o and returns its id (0, 1, 2, ... in the order added, across all
 * kinds; nearer wins, equal depth goes to the lower id) or a negative
 * fxrt_err_t: FXRT_ERR_NULL, FXRT_ERR_KIND, FXRT_ERR_FULL when
 * FXRT_MAX_<KIND> objects of that kind are there already (a kind with
 * capacity 0 is compiled out), FXRT_ERR_COORD, _DIRECTION, _RADIUS,
 * _COLOR, _BOX, _TINY, _MESH (a model's mesh or placement malformed, or
 * its box beyond the coordinate limit), and the material's codes (fxrt_set_material's
 * but _ID), checked before the object is added. A refused object leaves the world
 * unchanged. A plane's normal need not be unit length; a collinear
 * triangle is accepted and never hit. */
int32_t fxrt_add(fxrt_world_t *w, const fxrt_object_t *o);

/* The number of objects: the id the next one gets (0 for NULL). */
int32_t fxrt_count(const fxrt_world_t *w);

/* The material of object id (default flat): FXRT_OK, FXRT_ERR_NULL,
 * FXRT_ERR_ID, FXRT_ERR_MATERIAL (unknown kind, lighting or phong compiled
 * out), FXRT_ERR_EXPONENT (outside 1..FXRT_PHONG_MAX_EXPONENT),
 * FXRT_ERR_INDEX (outside FXRT_INDEX_MIN..FXRT_INDEX_MAX), FXRT_ERR_COLOR
 * (the specular or reflection colour). */
fxrt_err_t fxrt_set_material(fxrt_world_t *w, int32_t id, const fxrt_material_t *m);

/* The ambient colour (only black with FXRT_MAX_LIGHTS 0). */
fxrt_err_t fxrt_set_ambient(fxrt_world_t *w, fxrt_color_t ambient);

/* The largest bounce of reflection and refraction, 0..FXRT_MAX_DEPTH
 * (FXRT_ERR_DEPTH), and N x N rays per pixel, 1..FXRT_MAX_SAMPLES, adaptive
 * only with FXRT_ADAPTIVE and N > 1 (FXRT_ERR_SAMPLES). */
fxrt_err_t fxrt_set_depth(fxrt_world_t *w, int32_t depth);
fxrt_err_t fxrt_set_samples(fxrt_world_t *w, int32_t samples, bool adaptive);

/* --- lights ---------------------------------------------------------------
 * A light as data: .kind (FXRT_LIGHT_POINT, _DIRECTIONAL, _SPOT),
 * .position (point, spot), .direction (directional, spot), .angle_deg (a
 * spot's half-angle, (0, 90]), .color, .shadows. */
typedef struct {
    fxrt_light_kind_t kind;
    fxrt_vec3_t position, direction;
    fxrt_num_t angle_deg;
    fxrt_color_t color;
    bool shadows;
} fxrt_light_t;

/* The light's index (0..FXRT_MAX_LIGHTS - 1, its bit in a pixel's key) or
 * a negative fxrt_err_t: FXRT_ERR_NULL, _FULL, _COORD, _DIRECTION, _ANGLE,
 * _COLOR, _LIGHT. */
int32_t fxrt_add_light(fxrt_world_t *w, const fxrt_light_t *l);

/* --- camera --------------------------------------------------------------- */

/* Perspective camera for a width x height image: fov_deg is the full
 * vertical opening angle in degrees, in (0, 180). eye within
 * +-FXRT_COORD_LIMIT, gaze and up nonzero, not parallel. Returns FXRT_OK or
 * FXRT_ERR_NULL, _SIZE, _COORD, _DIRECTION, _UP, _FOV, _NARROW (height *
 * cot(fov/2) > 32767: the rays would not fit Q16.16), _TINY; a camera
 * error without an FXRT_ERR_ name comes back as FXRT_ERR_CAM_BASE minus
 * its number (fxrt_strerror has its text). */
fxrt_err_t fxrt_camera_perspective(fxrt_view_t *view, fxrt_vec3_t eye, fxrt_vec3_t gaze, fxrt_vec3_t up,
                                   fxrt_num_t fov_deg, int32_t width, int32_t height);

/* Orthographic camera: scale is the view height in scene units, in (0,
 * FXRT_RADIUS_LIMIT]; the view must stay inside +-FXRT_COORD_LIMIT
 * (FXRT_ERR_EXTENT). Other codes as for the perspective camera. */
fxrt_err_t fxrt_camera_orthographic(fxrt_view_t *view, fxrt_vec3_t eye, fxrt_vec3_t gaze, fxrt_vec3_t up,
                                    fxrt_num_t scale, int32_t width, int32_t height);

/* A camera as data (what the scene compiler emits). */
typedef struct {
    fxrt_camera_kind_t kind; /* FXRT_PERSPECTIVE or FXRT_ORTHOGRAPHIC */
    fxrt_vec3_t eye, gaze, up;
    fxrt_num_t fov_deg; /* perspective only */
    fxrt_num_t scale;   /* orthographic only */
    int32_t width, height;
} fxrt_camera_t;

/* fxrt_camera_perspective or _orthographic from a description
 * (FXRT_ERR_CAMERA for an unknown kind). */
fxrt_err_t fxrt_camera_setup(fxrt_view_t *view, const fxrt_camera_t *c);

/* --- rendering ------------------------------------------------------------ */

/* Per-frame set-up: the camera-space forms and screen bounds of every
 * object. Call it again after moving the camera or changing the world;
 * world and view must stay alive and unchanged while rows are rendered.
 * Returns FXRT_OK, FXRT_ERR_NULL, FXRT_ERR_SIZE (a view never set up),
 * FXRT_ERR_WIDTH (wider than FXRT_RENDER_MAX_WIDTH), FXRT_ERR_RENDER (the
 * frame needs more than fxrt_render_t holds; fxrt_render_error says
 * what) or FXRT_ERR_CONFIG. After a refusal, fxrt_render_row refuses
 * every row until a set-up succeeds. */
static inline fxrt_err_t fxrt_render_setup(fxrt_render_t *r, const fxrt_world_t *w, const fxrt_view_t *view)
{
    return fxrt_render_setup_checked(r, w, view, (uint32_t)sizeof(render_t));
}

/* Why the last fxrt_render_setup returned FXRT_ERR_RENDER (NULL if not). */
const char *fxrt_render_error(const fxrt_render_t *r);

/* Render output row `row` (0 = top, < height) into out, out_bytes long
 * (at least FXRT_ROW_BYTES(width); RGB565 rows 2-byte aligned). Rows may
 * come in any order. FXRT_OK, or nothing written and FXRT_ERR_NULL,
 * FXRT_ERR_SETUP (no successful fxrt_render_setup on r, or the view's size
 * changed since), FXRT_ERR_ROW (row outside 0..height-1), FXRT_ERR_BUFFER. */
fxrt_err_t fxrt_render_row(fxrt_render_t *r, int32_t row, uint8_t *out, size_t out_bytes);

/* Short English text for an fxrt_err_t (or "ok" for any value >= 0). */
const char *fxrt_strerror(int32_t err);

FXRT_C_END

#endif
