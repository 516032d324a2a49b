/* ellipsoid: the points c + x u + y v + z w with x^2 + y^2 + z^2 <= 1, a
 * sphere that a node scales unevenly (docs/SCENES.md, "Nodes"): the unit
 * sphere placed by scene/affine.h. A ray meets the unit sphere in its
 * space; the normal is the unit sphere's there (the point itself) mapped
 * by A^-T and normalised. */
#include "scene/kinds.h"

#if FXRT_MAX_ELLIPSOIDS > 0
fxrt_err_t geom_ellipsoid_check(vec3_t center, vec3_t u, vec3_t v, vec3_t w, color_t color)
{
    return geom_affine_check(center, u, v, w, false, color);
}

bool geom_ellipsoid_make(geom_ellipsoid_t *e, vec3_t center, vec3_t u, vec3_t v, vec3_t w, color_t color, uint16_t id)
{
    geom_common_init(&e->obj, color, id);
    return geom_affine_make(&e->a, center, u, v, w, false, color);
}

/* The unit sphere met along the local ray: the closest point's offset -q
 * from the centre (the sphere test's stable form, scene/sphere.c), the
 * half chord h, and the world t of the near and far points (t0 <= t1).
 * False where the line misses (disc < 0; silhouettes: h = 0 when
 * clamp). */
static bool geom_ell_meet(const geom_affine_ray_t *l, bool clamp, vec3_t *q, num_t *h, num_t *t0, num_t *t1)
{
    vec3_t oc = vec3_neg(l->o);
    num_t b = numw_round(vec3_dotw_unit(oc, l->d));
    *q = vec3_sub(oc, vec3_scale_unit(l->d, b));
    numw_t disc = numw_sub(l->r2, vec3_dotw(*q, *q));
    if (disc < 0 && !clamp)
        return false;
    *h = disc > 0 ? numw_sqrt(disc) : NUM_ZERO;
    *t0 = geom_affine_world_t(l, num_sub(b, *h));
    *t1 = geom_affine_world_t(l, num_add(b, *h));
    return true;
}

bool geom_ellipsoid_hit(const geom_ellipsoid_t *e, const ray_t *ray, num_t *t)
{
    geom_affine_ray_t l;
    vec3_t q;
    num_t h, t0, t1;
    if (!geom_affine_ray(&e->a, ray, &l) || !geom_ell_meet(&l, false, &q, &h, &t0, &t1))
        return false;
    return geom_affine_first(t0, t1, t);
}

bool geom_ellipsoid_occludes(const geom_ellipsoid_t *e, const ray_t *ray, num_t tmax)
{
    num_t t;
    return geom_ellipsoid_hit(e, ray, &t) && (tmax == NUM_MAX || t < tmax);
}

/* The near point (far: the far one, a ray leaving from inside) and its
 * outward normal; at a silhouette the closest point. */
static void geom_ell_at(const geom_ellipsoid_t *e, const ray_t *ray, bool far, num_t *t, vec3_t *n)
{
    geom_affine_ray_t l;
    vec3_t q;
    num_t h, t0, t1;
    if (!geom_affine_ray(&e->a, ray, &l)) {
        *t = NUM_ZERO;
        *n = vec3_neg(ray->d);
        return;
    }
    geom_ell_meet(&l, true, &q, &h, &t0, &t1);
    bool near = !far && t0 > NUM_ZERO;
    *t = near ? t0 : t1;
    vec3_t hd = vec3_scale_unit(l.d, h);
    vec3_t p = near ? vec3_sub(vec3_neg(q), hd) : vec3_add(vec3_neg(q), hd);
    if (!geom_affine_normal(&e->a, p, n))
        *n = far ? ray->d : vec3_neg(ray->d);
}

void geom_ellipsoid_surface(const geom_ellipsoid_t *e, const ray_t *ray, num_t *t, vec3_t *n)
{
    geom_ell_at(e, ray, false, t, n);
}

bool geom_ellipsoid_exit(const geom_ellipsoid_t *e, const ray_t *ray, num_t *t, vec3_t *n)
{
    geom_ell_at(e, ray, true, t, n);
    return *t > NUM_ZERO;
}

bool geom_ellipsoid_contains(const geom_ellipsoid_t *e, vec3_t p)
{
    num_t x[3];
    if (!geom_affine_local(&e->a, p, x))
        return false;
    vec3_t xl = vec3_make(x[0], x[1], x[2]);
    return vec3_dotw(xl, xl) < numw_from(NUM_ONE);
}

void geom_ellipsoid_bounds(const geom_ellipsoid_t *e, vec3_t *lo, vec3_t *hi) { geom_affine_bounds(&e->a, lo, hi); }

void geom_ellipsoid_around(const geom_ellipsoid_t *e, vec3_t *c, num_t *r) { geom_affine_around(&e->a, c, r); }
#endif
