/* geom: the primitives and their ray intersection tests.
 *
 * Each test returns true and the ray parameter t of the nearest hit with
 * t > 0 (in Q16.16: t >= 1 LSB), or false. d is unit length, so t is a
 * distance in scene units. A hit beyond the number range saturates to
 * NUM_MAX and still counts: it is a far hit, not a miss. Objects store
 * what the tests need precomputed (edges, squared radius) so that the
 * per-ray work is only per-ray work.
 */
#ifndef FXRT_GEOM_H
#define FXRT_GEOM_H

#include "math/color.h"
#include "fxrt_err.h"
#include "math/ray.h"

/* How a surface responds to light (light/shade.c and light/trace.c have
 * the formulas):
 *   MATERIAL_FLAT         its colour as is, whatever the lights (the default)
 *   MATERIAL_LAMBERT      ambient + diffuse
 *   MATERIAL_PHONG        ambient + diffuse + specular (specular, exponent)
 *   MATERIAL_REFLECTIVE   phong + reflection (.) the colour seen along the
 *                         mirrored ray
 *   MATERIAL_TRANSPARENT  no local term: Schlick-weighted reflected and
 *                         transmitted (refracted, tinted by the colour)
 *                         rays; casts no shadow */
typedef enum {
    MATERIAL_FLAT,
    MATERIAL_LAMBERT,
    MATERIAL_PHONG,
    MATERIAL_REFLECTIVE,
    MATERIAL_TRANSPARENT,
    FXRT_MATERIAL_FLAT = MATERIAL_FLAT, /* the public API's spelling (core/fxrt.h) */
    FXRT_MATERIAL_LAMBERT = MATERIAL_LAMBERT,
    FXRT_MATERIAL_PHONG = MATERIAL_PHONG,
    FXRT_MATERIAL_REFLECTIVE = MATERIAL_REFLECTIVE,
    FXRT_MATERIAL_TRANSPARENT = MATERIAL_TRANSPARENT
} material_kind_t;

typedef struct {
    uint8_t kind;       /* material_kind_t */
    uint16_t exponent;  /* phong, reflective: 1..FXRT_PHONG_MAX_EXPONENT */
    color_t specular;   /* phong, reflective: c_s, fractions 0..1 (NUM_ONE = full) */
    color_t reflection; /* reflective: c_r, fractions 0..1 */
    num_t index;        /* transparent: refraction index eta, FXRT_INDEX_MIN..MAX */
} material_t;

/* Does the material trace secondary rays (when FXRT_MAX_DEPTH > 0)? */
static inline bool material_bounces(uint8_t kind)
{
    return kind == MATERIAL_REFLECTIVE || kind == MATERIAL_TRANSPARENT;
}

/* What every object carries besides its shape. */
typedef struct {
    rgb8_t rgb;  /* color as output pixels, computed once */
    uint16_t id; /* position in the scene file: ties in t go to the lower id */
#if FXRT_MAX_LIGHTS > 0 || FXRT_MAX_SAMPLES > 1
    color_t color;  /* 1/255 units, for shading and sampling (a flat 1-sample build needs only rgb) */
#endif
    FXRT_IF_LIGHTS(material_t mat;) /* MATERIAL_FLAT unless world_set_material changed it */
} geom_common_t;

/* Is c's material lit (not MATERIAL_FLAT)? Always false without lights. */
static inline bool geom_lit(const geom_common_t *c)
{
    (void)c;
    return FXRT_IF_LIGHTS(c->mat.kind != MATERIAL_FLAT ||) false;
}

/* Component i (0 = x, 1 = y, 2 = z) of v. */
static inline num_t geom_axis(vec3_t v, int i)
{
    return i == 0 ? v.x : (i == 1 ? v.y : v.z);
}

/* Lexicographic order of points, to give each edge one canonical
 * direction (the kernels and the renderer's edge forms both use it, so
 * two faces sharing an edge get exactly opposite tests: watertight). */
static inline bool geom_point_less(vec3_t p, vec3_t q)
{
    if (p.x != q.x)
        return p.x < q.x;
    if (p.y != q.y)
        return p.y < q.y;
    return p.z < q.z;
}


/* Domain checks: FXRT_OK, or the fxrt_err_t (fxrt_err.h) that says why the
 * renderer cannot take the value. They are what the scene parser checks,
 * in the build's number type, so that objects built in code meet the
 * same domain (docs/ACCURACY.md):
 *   point   every |coordinate| <= FXRT_COORD_LIMIT (NaN fails)
 *   dir     components within the same limit, not the zero vector
 *   color   every channel in 0..COLOR_MAX (intensity 0..1)
 * and in the float and double builds a nonzero coordinate or colour below
 * 2^-16, which Q16.16 cannot hold, is refused too, so all three builds
 * accept the same input. */
fxrt_err_t geom_check_point(vec3_t p);
fxrt_err_t geom_check_dir(vec3_t d);
fxrt_err_t geom_check_color(color_t c);
/* One value against |v| <= limit (NaN fails): FXRT_OK, FXRT_ERR_COORD, or
 * in float and double FXRT_ERR_TINY for a nonzero |v| below 2^-16. */
fxrt_err_t geom_check_num(num_t v, int32_t limit);

/* Helpers of the kinds' files (scene/KIND.c; the kinds' interface is in
 * scene/kinds.h). geom_common_init: an object's shared part, flat
 * material. The flat pieces' plane through a with unit normal n:
 * geom_flat_t, the hit at t > 0 (false: none); geom_flat_occludes, a hit
 * in (0, tmax), no division; geom_flat_surface_t, the plane's t for any
 * ray (no side or sign test). */
void geom_common_init(geom_common_t *c, color_t color, uint16_t id);
bool geom_flat_t(const vec3_t *a, const vec3_t *n, const ray_t *ray, num_t *t);
bool geom_flat_occludes(const vec3_t *a, const vec3_t *n, const ray_t *ray, num_t tmax);
num_t geom_flat_surface_t(const vec3_t *a, const vec3_t *n, const ray_t *ray);
/* geom_flat_surface_t's numerator (a - o) . n for rays from o:
 * numw_div(num, d . n) is geom_flat_surface_t's value. */
numw_t geom_flat_num(const vec3_t *a, const vec3_t *n, const vec3_t *o);

#endif
