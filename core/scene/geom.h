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

typedef enum { GEOM_PLANE, GEOM_SPHERE, GEOM_TRIANGLE, GEOM_BOX } geom_kind_t;

/* How a surface responds to light (core/shade.c and core/trace.c have
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
    MATERIAL_TRANSPARENT
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
#if FXRT_MAX_LIGHTS > 0
    material_t mat; /* MATERIAL_FLAT unless world_set_material changed it */
#endif
} geom_common_t;

typedef struct {
    vec3_t a; /* a point on the plane */
    vec3_t n; /* unit normal */
    geom_common_t obj;
} geom_plane_t;

typedef struct {
    vec3_t center;
    num_t radius;
    numw_t radius2; /* radius^2, exact (Q32.32) */
    geom_common_t obj;
} geom_sphere_t;

typedef struct {
    vec3_t a, b, c;  /* vertices (edge tests use them directly, see geom.c) */
    vec3_t n;        /* unit normal, zero when degenerate */
    bool degenerate; /* collinear vertices: never hit */
    geom_common_t obj;
} geom_triangle_t;

typedef struct {
    vec3_t min, max; /* lbf and run corners, min <= max per axis */
    geom_common_t obj;
} geom_box_t;

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

/* Colour channels: COLOR_MAX is full intensity and COLOR_FRAC(x) the
 * channel for an intensity fraction x in 0..1 (a constant initialiser).
 * Here a channel is the fraction itself; color.h may define both for
 * another representation, which then wins. */
#ifndef COLOR_MAX
#define COLOR_MAX NUM_ONE
#endif
#ifndef COLOR_FRAC
#define COLOR_FRAC(x) NUM(x)
#endif

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
/* Per kind: the checks above, plus radius in (0, FXRT_RADIUS_LIMIT] and
 * min <= max per axis. A degenerate (collinear) triangle is in the domain:
 * it is accepted and never hit. */
fxrt_err_t geom_plane_check(vec3_t point, vec3_t normal, color_t color);
fxrt_err_t geom_sphere_check(vec3_t center, num_t radius, color_t color);
fxrt_err_t geom_triangle_check(vec3_t a, vec3_t b, vec3_t c, color_t color);
fxrt_err_t geom_box_check(vec3_t min, vec3_t max, color_t color);

/* Constructors fill the precomputed fields. They return false when the
 * input fails its domain check above (so code that bypasses the world's
 * add functions cannot build an object the renderer would get wrong); a
 * degenerate (collinear) triangle is accepted and never hit. */
bool geom_plane_make(geom_plane_t *p, vec3_t point, vec3_t normal, color_t color, uint16_t id);
bool geom_sphere_make(geom_sphere_t *s, vec3_t center, num_t radius, color_t color, uint16_t id);
bool geom_triangle_make(geom_triangle_t *t, vec3_t a, vec3_t b, vec3_t c, color_t color, uint16_t id);
bool geom_box_make(geom_box_t *b, vec3_t min, vec3_t max, color_t color, uint16_t id);

bool geom_plane_hit(const geom_plane_t *p, const ray_t *ray, num_t *t);
bool geom_sphere_hit(const geom_sphere_t *s, const ray_t *ray, num_t *t);
bool geom_triangle_hit(const geom_triangle_t *tr, const ray_t *ray, num_t *t);
bool geom_box_hit(const geom_box_t *b, const ray_t *ray, num_t *t);
/* geom_box_hit that also gives the face hit: axis * 2 + (1 for the max
 * side), 0..5. */
bool geom_box_hit_face(const geom_box_t *b, const ray_t *ray, num_t *t, uint8_t *face);

/* Shadow rays: is the object hit at some t with 0 < t < tmax (tmax =
 * NUM_MAX: any t > 0)? Any hit, not the nearest, and no division: the
 * bounds are compared as fractions, exactly in Q16.16 (a sphere's own
 * kernel has no division, world_occluded uses it). */
bool geom_plane_occludes(const geom_plane_t *p, const ray_t *ray, num_t tmax);
bool geom_sphere_occludes(const geom_sphere_t *s, const ray_t *ray, num_t tmax);
bool geom_triangle_occludes(const geom_triangle_t *tr, const ray_t *ray, num_t tmax);
bool geom_box_occludes(const geom_box_t *b, const ray_t *ray, num_t tmax);

/* Shading: where a ray that the renderer has already found to meet the
 * object meets its surface, and the unit geometric normal there (outward
 * for a sphere and a box, the stored normal for a plane and a triangle;
 * not yet turned towards the ray). Unlike the hit tests these never miss:
 * at a silhouette pixel, whose centre ray may pass just outside the
 * object, they return the nearest surface point the ray comes to (a
 * sphere's tangent point: the root with the discriminant clamped at 0; a
 * flat piece's plane ignoring its edges; a box's entry face by the slab
 * test ignoring the miss). *t may be 0 or negative only for a ray that
 * starts behind or on the surface. */
void geom_plane_surface(const geom_plane_t *p, const ray_t *ray, num_t *t, vec3_t *n);
void geom_sphere_surface(const geom_sphere_t *s, const ray_t *ray, num_t *t, vec3_t *n);
void geom_triangle_surface(const geom_triangle_t *tr, const ray_t *ray, num_t *t, vec3_t *n);
void geom_box_surface(const geom_box_t *b, const ray_t *ray, num_t *t, vec3_t *n);

/* Secondary rays that start on a solid's surface and go into it
 * (core/trace.c): where the ray leaves it, and the outward unit normal
 * there. The far root of a sphere (the discriminant clamped at 0), the far
 * slab of a box. False when that exit is not at t > 0 (a ray that only
 * grazes the surface it starts on). */
bool geom_sphere_exit(const geom_sphere_t *s, const ray_t *ray, num_t *t, vec3_t *n);
bool geom_box_exit(const geom_box_t *b, const ray_t *ray, num_t *t, vec3_t *n);

#endif
