/* affine: what the kinds placed by an affine map share (the ellipsoid,
 * scene/ellipsoid.c, and the parallelepiped, scene/parallelepiped.c): a
 * unit shape (the unit sphere, the cube [-1, 1]^3) mapped to the world by
 * x -> c + A x, A the matrix of columns u, v, w. A query maps its ray
 * into the unit shape's space by A^-1 and meets the shape there; a normal
 * there maps back by A^-T, the inverse transpose, and is normalised. An
 * affine map keeps the ray parameter, so the world t is the local one
 * over the local direction's length. */
#ifndef FXRT_SCENE_AFFINE_H
#define FXRT_SCENE_AFFINE_H

#include "scene/geom.h"

/* The placement: c, u, v, w as given, A^-1's rows, the world box's half
 * extents around c and the radius of a sphere around c that holds it. */
typedef struct {
    vec3_t c, u, v, w;
    vec3_t inv[3];
    vec3_t half;
    num_t reach;
} geom_affine_t;

/* A ray in the unit shape's space, scaled by 2^-s so that its origin
 * stays within 2^14 of the centre in Q16.16: origin o, unit direction d
 * and the same direction dp before normalising (30 significant bits in
 * Q16.16), the shape's half size r (2^-s) and its square r2, and k, len
 * with world t = local t 2^k / len. */
typedef struct {
    vec3_t o, d, dp;
    num_t r;
    numw_t r2;
    num_t len;
    int k;
} geom_affine_ray_t;

/* The domain (geom.h's rules): c a point; u, v, w each a nonzero vector
 * within the coordinate limit; A^-1's entries below 8192 (no axis thinner
 * than about 2^-13) and 0 < |det A| <= 2^30 (FXRT_ERR_AXES); the box
 * within the coordinate limit (FXRT_ERR_COORD). box: the unit shape is
 * the cube (its box's half extents sum |A_ij| over j), else the sphere
 * (their root of the sum of squares). And the colour (geom_check_color). */
fxrt_err_t geom_affine_check(vec3_t c, vec3_t u, vec3_t v, vec3_t w, bool box, color_t color);
/* The placement from checked fields; false where geom_affine_check is not
 * FXRT_OK. */
bool geom_affine_make(geom_affine_t *a, vec3_t c, vec3_t u, vec3_t v, vec3_t w, bool box, color_t color);
/* The ray in the unit shape's space; false when its origin lies more than
 * 2^22 units of it away (Q16.16; the shape then spans less than 2^-21
 * radians from there): no hit. */
bool geom_affine_ray(const geom_affine_t *a, const ray_t *ray, geom_affine_ray_t *l);
/* The nearest of a shape's entry t0 and exit t1 (t0 <= t1) in front of
 * the ray (t > 0; the exit where the ray starts inside): false where
 * neither is. */
static inline bool geom_affine_first(num_t t0, num_t t1, num_t *t)
{
    *t = t0 > NUM_ZERO ? t0 : t1;
    return *t > NUM_ZERO;
}
/* A local t (scaled) as a world t, saturating. */
num_t geom_affine_world_t(const geom_affine_ray_t *l, num_t t);
/* The world t at which the local ray's coordinate on an axis whose
 * direction part (a component of dp) is dpi has moved by x: x 2^k / dpi,
 * from the unrounded direction (a slab's t: scene/parallelepiped.c). */
num_t geom_affine_axis_t(const geom_affine_ray_t *l, num_t x, num_t dpi);
/* The world unit normal for local normal p (any length): A^-T p, formed
 * wide and normalised; false when it vanishes. */
bool geom_affine_normal(const geom_affine_t *a, vec3_t p, vec3_t *n);
/* Point p in the unit shape's space, A^-1 (p - c), in x[]: false when a
 * component's magnitude is 1 or more (outside the cube and the sphere). */
bool geom_affine_local(const geom_affine_t *a, vec3_t p, num_t x[3]);
/* The box around it, lo <= hi; the sphere around it. */
void geom_affine_bounds(const geom_affine_t *a, vec3_t *lo, vec3_t *hi);
void geom_affine_around(const geom_affine_t *a, vec3_t *c, num_t *r);

#endif
