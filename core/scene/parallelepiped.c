/* parallelepiped: the points c + x u + y v + z w with |x|, |y|, |z| <= 1,
 * a box that a node turns or shears (docs/SCENES.md, "Nodes"): the cube
 * [-1, 1]^3 placed by scene/affine.h. A ray meets the cube's three slabs
 * in its space; the normal of the face x = +-1 is +-e_x there, mapped by
 * A^-T (row x of A^-1) and normalised. */
#include "scene/kinds.h"

#if FXRT_MAX_PARALLELEPIPEDS > 0
fxrt_err_t geom_parallelepiped_check(vec3_t center, vec3_t u, vec3_t v, vec3_t w, color_t color)
{
    return geom_affine_check(center, u, v, w, true, color);
}

bool geom_parallelepiped_make(geom_parallelepiped_t *b, vec3_t center, vec3_t u, vec3_t v, vec3_t w, color_t color, uint16_t id)
{
    geom_common_init(&b->obj, color, id);
    return geom_affine_make(&b->a, center, u, v, w, true, color);
}

/* Is x / d before y / e (d, e > 0)? Exact in Q16.16 (|x|, |y| < 2^31 LSB,
 * d, e < 2^30: products below 2^61). */
static bool geom_pp_before(num_t x, num_t d, num_t y, num_t e) { return numw_mul(x, e) < numw_mul(y, d); }

/* The local ray's entry and exit: the world t of the latest entry into a
 * slab and of the earliest exit from one (t0 <= t1), and their faces
 * (axis * 2, + 1 for the + side). Each slab's t is a fraction of the
 * unrounded local direction (x / |dp_i|); the faces are chosen by exact
 * comparisons of those fractions, and only the two chosen become world t
 * (geom_affine_axis_t). False where the slabs do not overlap (a miss;
 * with clamp, a near miss keeps its faces and t0 = t1 = the exit's). */
static bool geom_pp_slabs(const geom_affine_ray_t *l, bool clamp, num_t *t0, num_t *t1, int *f0, int *f1)
{
    const num_t o[3] = {l->o.x, l->o.y, l->o.z}, d[3] = {l->dp.x, l->dp.y, l->dp.z};
    num_t xn = NUM_ZERO, dn = NUM_ONE, xf = NUM_ZERO, df = NUM_ONE; /* the entry's and the exit's fractions */
    int fn = -1, ff = -1;
    bool met = true;
    for (int i = 0; i < 3; i++) {
        if (d[i] == NUM_ZERO) { /* parallel to the slab: inside it or not at all */
            met = met && o[i] >= num_neg(l->r) && o[i] <= l->r;
            continue;
        }
        /* entry and exit of slab i as x / e with e = |dp_i| > 0 */
        bool up = d[i] > NUM_ZERO;
        num_t e = up ? d[i] : num_neg(d[i]);
        num_t xa = up ? num_sub(num_neg(l->r), o[i]) : num_sub(o[i], l->r);
        num_t xb = up ? num_sub(l->r, o[i]) : num_add(o[i], l->r);
        if (fn < 0 || geom_pp_before(xn, dn, xa, e)) {
            xn = xa, dn = e;
            fn = 2 * i + !up;
        }
        if (ff < 0 || geom_pp_before(xb, e, xf, df)) {
            xf = xb, df = e;
            ff = 2 * i + up;
        }
    }
    /* (a unit direction has a nonzero component: fn, ff >= 0) */
    met = met && fn >= 0 && !geom_pp_before(xf, df, xn, dn);
    if ((!met && !clamp) || fn < 0)
        return false;
    *t1 = geom_affine_axis_t(l, xf, df);
    *t0 = met ? geom_affine_axis_t(l, xn, dn) : *t1;
    *f0 = fn;
    *f1 = ff;
    return met;
}

bool geom_parallelepiped_hit(const geom_parallelepiped_t *b, const ray_t *ray, num_t *t)
{
    geom_affine_ray_t l;
    num_t t0, t1;
    int f0, f1;
    if (!geom_affine_ray(&b->a, ray, &l) || !geom_pp_slabs(&l, false, &t0, &t1, &f0, &f1))
        return false;
    return geom_affine_first(t0, t1, t);
}

bool geom_parallelepiped_occludes(const geom_parallelepiped_t *b, const ray_t *ray, num_t tmax)
{
    num_t t;
    return geom_parallelepiped_hit(b, ray, &t) && (tmax == NUM_MAX || t < tmax);
}

/* The outward unit normal of face f. */
static void geom_pp_normal(const geom_parallelepiped_t *b, int f, const ray_t *ray, vec3_t *n)
{
    num_t s = (f & 1) ? NUM_ONE : num_neg(NUM_ONE);
    vec3_t p = vec3_make(f / 2 == 0 ? s : NUM_ZERO, f / 2 == 1 ? s : NUM_ZERO, f / 2 == 2 ? s : NUM_ZERO);
    if (!geom_affine_normal(&b->a, p, n))
        *n = vec3_neg(ray->d);
}

/* The entry point (far: the exit, a ray leaving from inside) and its
 * face's outward normal; a ray that just misses takes its entry face. */
static void geom_pp_at(const geom_parallelepiped_t *b, const ray_t *ray, bool far, num_t *t, vec3_t *n)
{
    geom_affine_ray_t l;
    num_t t0, t1;
    int f0, f1;
    if (!geom_affine_ray(&b->a, ray, &l)) {
        *t = NUM_ZERO;
        *n = vec3_neg(ray->d);
        return;
    }
    geom_pp_slabs(&l, true, &t0, &t1, &f0, &f1);
    bool near = !far && t0 > NUM_ZERO;
    *t = near ? t0 : t1;
    geom_pp_normal(b, near ? f0 : f1, ray, n);
}

void geom_parallelepiped_surface(const geom_parallelepiped_t *b, const ray_t *ray, num_t *t, vec3_t *n)
{
    geom_pp_at(b, ray, false, t, n);
}

bool geom_parallelepiped_exit(const geom_parallelepiped_t *b, const ray_t *ray, num_t *t, vec3_t *n)
{
    geom_pp_at(b, ray, true, t, n);
    return *t > NUM_ZERO;
}

bool geom_parallelepiped_contains(const geom_parallelepiped_t *b, vec3_t p)
{
    num_t x[3];
    return geom_affine_local(&b->a, p, x);
}

void geom_parallelepiped_bounds(const geom_parallelepiped_t *b, vec3_t *lo, vec3_t *hi)
{
    geom_affine_bounds(&b->a, lo, hi);
}

void geom_parallelepiped_around(const geom_parallelepiped_t *b, vec3_t *c, num_t *r) { geom_affine_around(&b->a, c, r); }
#endif
