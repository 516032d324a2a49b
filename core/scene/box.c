/* box: axis-aligned, between its min and max corners (a flat box, min =
 * max on an axis, is a rectangle). */
#include "scene/kinds.h"

fxrt_err_t geom_box_check(vec3_t min, vec3_t max, color_t color)
{
    fxrt_err_t e = geom_check_point(min);
    if (e == FXRT_OK)
        e = geom_check_point(max);
    if (e != FXRT_OK)
        return e;
    if (!(min.x <= max.x && min.y <= max.y && min.z <= max.z))
        return FXRT_ERR_BOX;
    return geom_check_color(color);
}

bool geom_box_make(geom_box_t *b, vec3_t min, vec3_t max, color_t color, uint16_t id)
{
    b->min = min;
    b->max = max;
    geom_common_init(&b->obj, color, id);
    return geom_box_check(min, max, color) == FXRT_OK;
}

/* Slabs: the ray is inside the box for t in [tnear, tfar], entering
 * through face fnear and leaving through ffar (axis * 2 + 1 for the max
 * side). A direction component of zero cannot divide: the ray is then
 * inside that slab for all t or for none (*outside: it misses). Near-zero
 * components saturate the quotients to +-NUM_MAX, which orders correctly. */
static void geom_box_slabs(const geom_box_t *b, const ray_t *ray, num_t *tnear_out, num_t *tfar_out,
                           uint8_t *fnear, uint8_t *ffar, bool *outside)
{
    num_t tnear = num_neg(NUM_MAX), tfar = NUM_MAX;
    uint8_t fn = 0, ff = 0;
    *outside = false;
    for (int i = 0; i < 3; i++) {
        num_t o = geom_axis(ray->o, i), d = geom_axis(ray->d, i);
        num_t lo = geom_axis(b->min, i), hi = geom_axis(b->max, i);
        if (d == NUM_ZERO) {
            if (o < lo || o > hi)
                *outside = true;
            continue;
        }
        num_t t1 = num_div(num_sub(lo, o), d);
        num_t t2 = num_div(num_sub(hi, o), d);
        uint8_t f1 = (uint8_t)(2 * i), f2 = (uint8_t)(2 * i + 1);
        /* Entering through the min face when d > 0 and the max face when
         * d < 0 (then t1 >= t2: the rounding is monotone). By d's sign,
         * not by t1 > t2: a flat box (lo == hi) has t1 == t2 and would
         * otherwise always be entered through its min face, its normal
         * facing away from a ray coming from above, as if from inside. */
        if (d < NUM_ZERO) {
            num_t tmp = t1;
            t1 = t2;
            t2 = tmp;
            f1 = (uint8_t)(2 * i + 1);
            f2 = (uint8_t)(2 * i);
        }
        if (t1 > tnear) {
            tnear = t1;
            fn = f1;
        }
        if (t2 < tfar) {
            tfar = t2;
            ff = f2;
        }
    }
    *tnear_out = tnear;
    *tfar_out = tfar;
    *fnear = fn;
    *ffar = ff;
}

bool geom_box_hit_face(const geom_box_t *b, const ray_t *ray, num_t *t, uint8_t *face)
{
    num_t tnear, tfar;
    uint8_t fn, ff;
    bool outside;
    geom_box_slabs(b, ray, &tnear, &tfar, &fn, &ff, &outside);
    if (outside || tnear > tfar || !(tfar > NUM_ZERO))
        return false;
    bool in = !(tnear > NUM_ZERO); /* tnear <= 0: origin inside */
    *t = in ? tfar : tnear;
    *face = in ? ff : fn;
    return true;
}

bool geom_box_hit(const geom_box_t *b, const ray_t *ray, num_t *t)
{
    uint8_t face;
    return geom_box_hit_face(b, ray, t, &face);
}

/* n1 / d1 < n2 / d2 for d1, d2 > 0: exact in Q16.16 (64-bit products).
 * The denominators are a ray direction's components (or 1). */
static bool geom_frac_less(num_t n1, num_t d1, num_t n2, num_t d2)
{
    return numw_mul_unit(n1, d2) < numw_mul_unit(n2, d1);
}

bool geom_box_occludes(const geom_box_t *b, const ray_t *ray, num_t tmax)
{
    /* The slab test with each bound kept as a fraction num / |d_i|: the
     * ray is in the box for t in [near, far], and meets its surface at
     * near (or at far when it starts inside, near <= 0), as
     * geom_box_hit does; that t must be in (0, tmax). */
    num_t nn = num_neg(NUM_MAX), nd = NUM_ONE; /* near = -infinity */
    num_t fn = NUM_MAX, fd = NUM_ONE;          /* far = +infinity */
    for (int i = 0; i < 3; i++) {
        num_t o = geom_axis(ray->o, i), d = geom_axis(ray->d, i);
        num_t lo = geom_axis(b->min, i), hi = geom_axis(b->max, i);
        if (d == NUM_ZERO) {
            if (o < lo || o > hi)
                return false;
            continue;
        }
        num_t a0 = num_sub(lo, o), a1 = num_sub(hi, o);
        num_t in = d > NUM_ZERO ? a0 : num_neg(a1), out = d > NUM_ZERO ? a1 : num_neg(a0);
        num_t ad = num_abs(d);
        if (geom_frac_less(nn, nd, in, ad)) {
            nn = in;
            nd = ad;
        }
        if (geom_frac_less(out, ad, fn, fd)) {
            fn = out;
            fd = ad;
        }
    }
    if (geom_frac_less(fn, fd, nn, nd))
        return false; /* the slabs do not overlap: a miss */
    bool starts_inside = !geom_frac_less(NUM_ZERO, NUM_ONE, nn, nd); /* near <= 0 */
    num_t hn = starts_inside ? fn : nn, hd = starts_inside ? fd : nd;
    if (!geom_frac_less(NUM_ZERO, NUM_ONE, hn, hd))
        return false; /* the surface is met at t <= 0 */
    return tmax == NUM_MAX || geom_frac_less(hn, hd, tmax, NUM_ONE);
}

/* The outward unit normal of face f (axis f / 2, max side when f is odd). */
static vec3_t geom_box_normal(uint8_t f)
{
    num_t s = (f & 1) ? NUM_ONE : num_neg(NUM_ONE);
    return vec3_make(f / 2 == 0 ? s : NUM_ZERO, f / 2 == 1 ? s : NUM_ZERO, f / 2 == 2 ? s : NUM_ZERO);
}

void geom_box_surface(const geom_box_t *b, const ray_t *ray, num_t *t, vec3_t *n)
{
    num_t tnear, tfar;
    uint8_t fn, ff;
    bool outside;
    geom_box_slabs(b, ray, &tnear, &tfar, &fn, &ff, &outside);
    /* A ray that just misses still takes its entry face; a ray from inside
     * leaves through the far face. */
    bool in = !outside && !(tnear > NUM_ZERO) && tfar > NUM_ZERO;
    *t = in ? tfar : tnear;
    *n = geom_box_normal(in ? ff : fn);
}

bool geom_box_exit(const geom_box_t *b, const ray_t *ray, num_t *t, vec3_t *n)
{
    num_t tnear, tfar;
    uint8_t fn, ff;
    bool outside;
    geom_box_slabs(b, ray, &tnear, &tfar, &fn, &ff, &outside);
    (void)tnear, (void)fn;
    if (outside || !(tfar > NUM_ZERO))
        return false;
    *t = tfar;
    *n = geom_box_normal(ff);
    return true;
}

void geom_box_bounds(const geom_box_t *b, vec3_t *lo, vec3_t *hi)
{
    *lo = b->min;
    *hi = b->max;
}

bool geom_box_contains(const geom_box_t *b, vec3_t q)
{
    return q.x > b->min.x && q.x < b->max.x && q.y > b->min.y && q.y < b->max.y && q.z > b->min.z && q.z < b->max.z;
}

void geom_box_around(const geom_box_t *b, vec3_t *c, num_t *r)
{
    *c = vec3_make(num_half(num_add(b->min.x, b->max.x)), num_half(num_add(b->min.y, b->max.y)),
                   num_half(num_add(b->min.z, b->max.z)));
    *r = num_max(vec3_len(vec3_sub(b->max, *c)), vec3_len(vec3_sub(*c, b->min)));
}
