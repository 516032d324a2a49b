/* sphere: a centre and a radius. */
#include "scene/kinds.h"

fxrt_err_t geom_sphere_check(vec3_t center, num_t radius, color_t color)
{
    fxrt_err_t e = geom_check_point(center);
    if (e != FXRT_OK)
        return e;
    if (!(radius > NUM_ZERO && radius <= num_from_int(FXRT_RADIUS_LIMIT)))
        return FXRT_ERR_RADIUS;
    if (geom_check_num(radius, FXRT_RADIUS_LIMIT) != FXRT_OK)
        return FXRT_ERR_TINY;
    return geom_check_color(color);
}

bool geom_sphere_make(geom_sphere_t *s, vec3_t center, num_t radius, color_t color, uint16_t id)
{
    s->center = center;
    s->radius = radius;
    s->radius2 = numw_mul(radius, radius);
    geom_common_init(&s->obj, color, id);
    return geom_sphere_check(center, radius, color) == FXRT_OK;
}

/* The sphere test's core for oc = c - o and unit d: b = oc . d (rounded),
 * the offset q = oc - b d of the closest point from the centre, and the
 * squared half chord r^2 - |q|^2 (returned; negative: the line misses). */
static inline __attribute__((always_inline)) numw_t geom_sphere_disc(vec3_t oc, vec3_t d, numw_t r2, num_t *b_out)
{
    num_t b = numw_round(vec3_dotw_unit(oc, d));
    vec3_t q = vec3_sub(oc, vec3_scale_unit(d, b));
    *b_out = b;
    return numw_sub(r2, vec3_dotw(q, q));
}

bool geom_sphere_hit(const geom_sphere_t *s, const ray_t *ray, num_t *t)
{
    /* Numerically stable form: b = (c - o) . d is the t of the point on the
     * ray closest to the centre, q = (c - o) - b d its offset from the
     * centre, and the half chord is sqrt(r^2 - |q|^2). This avoids b^2 - ac,
     * whose two large terms cancel for distant spheres. */
    num_t b;
    numw_t disc = geom_sphere_disc(vec3_sub(s->center, ray->o), ray->d, s->radius2, &b);
    if (disc < 0)
        return false;
    num_t h = numw_sqrt(disc);
    num_t t0 = num_sub(b, h);
    if (t0 > NUM_ZERO) {
        *t = t0;
        return true;
    }
    num_t t1 = num_add(b, h); /* origin inside the sphere */
    if (t1 > NUM_ZERO) {
        *t = t1;
        return true;
    }
    return false;
}

/* Shadow rays: a hit with 0 < t < tmax (tmax NUM_MAX: any t > 0). In
 * Q16.16 a shadow ray can start up to 32767 from the origin (a far floor)
 * and so more than 2^30 LSB (16384) from a centre along an axis; then
 * c - o and (c - o) . d would saturate (and the kernel see the sphere
 * moved towards o), so the test runs at a quarter of the scale: (c - o) /
 * 4 < 2^29.4 per axis, its length and b below 2^31, r^2 / 16 exact. Rays
 * from the eye (|c - o| <= 16384 per axis in the domain) take
 * geom_sphere_hit's own path. */
bool geom_sphere_occludes(const geom_sphere_t *s, const ray_t *ray, num_t tmax)
{
#if FXRT_NUMBER == FXRT_Q16
    int64_t dx = (int64_t)s->center.x - ray->o.x, dy = (int64_t)s->center.y - ray->o.y,
            dz = (int64_t)s->center.z - ray->o.z;
    const int64_t lim = (int64_t)1 << 30;
    if (dx > lim || dx < -lim || dy > lim || dy < -lim || dz > lim || dz < -lim) {
        num_t b;
        numw_t disc = geom_sphere_disc(vec3_make((fx_t)(dx >> 2), (fx_t)(dy >> 2), (fx_t)(dz >> 2)), ray->d,
                                       s->radius2 >> 4, &b);
        if (disc < 0)
            return false;
        num_t h = numw_sqrt(disc);
        num_t t0 = num_sub(b, h);
        num_t t = t0 > NUM_ZERO ? t0 : num_add(b, h); /* quarter scale */
        return t > NUM_ZERO && (tmax == NUM_MAX || 4 * (int64_t)t < tmax);
    }
#endif
    num_t t;
    return geom_sphere_hit(s, ray, &t) && (t < tmax || tmax == NUM_MAX);
}

/* Where the ray meets the sphere's surface and the outward unit normal
 * there: the near root when far is false and it is at t > 0, else the far
 * one. As geom_sphere_hit, with the discriminant clamped at 0 (the tangent
 * point for a ray that just misses). The normal (p - c) / r is formed as
 * p - c = -q -+ h d, the offset of the hit from the centre without
 * subtracting two large coordinates (o + t d - c cancels for a far
 * sphere), and normalised: on the sphere |p - c| = r, so this is
 * (p - c) / r, with the rounding of p kept out of the direction. */
static void geom_sphere_at(const geom_sphere_t *s, const ray_t *ray, bool far, num_t *t, vec3_t *n)
{
    vec3_t oc = vec3_sub(s->center, ray->o);
    num_t b = numw_round(vec3_dotw_unit(oc, ray->d));
    vec3_t q = vec3_sub(oc, vec3_scale_unit(ray->d, b));
    numw_t disc = numw_sub(s->radius2, vec3_dotw(q, q));
    num_t h = disc > 0 ? numw_sqrt(disc) : NUM_ZERO;
    num_t t0 = num_sub(b, h);
    bool near = !far && t0 > NUM_ZERO;
    *t = near ? t0 : num_add(b, h);
    vec3_t hd = vec3_scale_unit(ray->d, h);
    vec3_t v = near ? vec3_sub(vec3_neg(q), hd) : vec3_add(vec3_neg(q), hd);
    FXRT_COUNT(n_normalised);
    if (!vec3_normalize(&v))
        v = far ? ray->d : vec3_neg(ray->d); /* radius below 1 LSB: leave along / face the ray */
    *n = v;
}

void geom_sphere_surface(const geom_sphere_t *s, const ray_t *ray, num_t *t, vec3_t *n)
{
    geom_sphere_at(s, ray, false, t, n);
}

bool geom_sphere_exit(const geom_sphere_t *s, const ray_t *ray, num_t *t, vec3_t *n)
{
    geom_sphere_at(s, ray, true, t, n);
    return *t > NUM_ZERO;
}

void geom_sphere_bounds(const geom_sphere_t *s, vec3_t *lo, vec3_t *hi)
{
    vec3_t r = vec3_make(s->radius, s->radius, s->radius);
    *lo = vec3_sub(s->center, r);
    *hi = vec3_add(s->center, r);
}

bool geom_sphere_contains(const geom_sphere_t *s, vec3_t p)
{
    vec3_t v = vec3_sub(p, s->center);
    return vec3_dotw(v, v) < s->radius2;
}

void geom_sphere_around(const geom_sphere_t *s, vec3_t *c, num_t *r)
{
    *c = s->center;
    *r = s->radius;
}
