/* geom: ray intersection tests. Only the kinds the build's world can hold
 * (FXRT_MAX_<KIND> > 0) are compiled, so a sphere-only firmware carries no
 * plane, triangle or box code. */
#include "scene/geom.h"

/* One value against |v| <= limit; NaN fails the comparison. */
static fxrt_err_t geom_check_num(num_t v, int32_t limit)
{
    if (!(num_abs(v) <= num_from_int(limit)))
        return FXRT_ERR_COORD;
#if FXRT_NUMBER != FXRT_Q16
    if (v != NUM_ZERO && num_abs(v) < NUM(1.0 / 65536.0))
        return FXRT_ERR_TINY;
#endif
    return FXRT_OK;
}

fxrt_err_t geom_check_point(vec3_t p)
{
    fxrt_err_t e = geom_check_num(p.x, FXRT_COORD_LIMIT);
    if (e == FXRT_OK)
        e = geom_check_num(p.y, FXRT_COORD_LIMIT);
    if (e == FXRT_OK)
        e = geom_check_num(p.z, FXRT_COORD_LIMIT);
    return e;
}

/* Only the direction of these matters, so a tiny component is harmless
 * (a value given in the build's number type is taken as it is; the scene
 * parser refuses decimal directions that rounding would turn): no TINY
 * check. */
fxrt_err_t geom_check_dir(vec3_t d)
{
    num_t lim = num_from_int(FXRT_COORD_LIMIT);
    if (!(num_abs(d.x) <= lim && num_abs(d.y) <= lim && num_abs(d.z) <= lim))
        return FXRT_ERR_COORD;
    if (d.x == NUM_ZERO && d.y == NUM_ZERO && d.z == NUM_ZERO)
        return FXRT_ERR_DIRECTION;
    return FXRT_OK;
}

fxrt_err_t geom_check_color(color_t c)
{
    /* Written so that NaN fails. */
    if (!(c.r >= NUM_ZERO && c.r <= COLOR_MAX && c.g >= NUM_ZERO && c.g <= COLOR_MAX && c.b >= NUM_ZERO &&
          c.b <= COLOR_MAX))
        return FXRT_ERR_COLOR;
#if FXRT_NUMBER != FXRT_Q16
    if (geom_check_num(c.r, FXRT_COORD_LIMIT) != FXRT_OK || geom_check_num(c.g, FXRT_COORD_LIMIT) != FXRT_OK ||
        geom_check_num(c.b, FXRT_COORD_LIMIT) != FXRT_OK)
        return FXRT_ERR_TINY;
#endif
    return FXRT_OK;
}

fxrt_err_t geom_plane_check(vec3_t point, vec3_t normal, color_t color)
{
    fxrt_err_t e = geom_check_point(point);
    if (e == FXRT_OK)
        e = geom_check_dir(normal);
    return e == FXRT_OK ? geom_check_color(color) : e;
}

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

fxrt_err_t geom_triangle_check(vec3_t a, vec3_t b, vec3_t c, color_t color)
{
    fxrt_err_t e = geom_check_point(a);
    if (e == FXRT_OK)
        e = geom_check_point(b);
    if (e == FXRT_OK)
        e = geom_check_point(c);
    return e == FXRT_OK ? geom_check_color(color) : e;
}

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

static void geom_common_init(geom_common_t *c, color_t color, uint16_t id)
{
#if FXRT_MAX_LIGHTS > 0 || FXRT_MAX_SAMPLES > 1
    c->color = color;
#endif
    c->rgb = color_to_rgb8(color);
    c->id = id;
#if FXRT_MAX_LIGHTS > 0
    c->mat.kind = MATERIAL_FLAT;
    c->mat.exponent = 0;
    c->mat.specular = color_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    c->mat.reflection = c->mat.specular;
    c->mat.index = NUM_ZERO;
#endif
}

/* Where the ray meets the plane through a with normal n: t = (a - o) . n /
 * (d . n). Both dot products stay wide, so the sign tests are exact and the
 * quotient is rounded once. Planes and triangles share it. */
__attribute__((unused)) static bool geom_flat_t(const vec3_t *a, const vec3_t *n, const ray_t *ray, num_t *t)
{
    numw_t den = vec3_dotw_units(ray->d, *n);
    numw_t num = vec3_dotw_unit(vec3_sub(*a, ray->o), *n);
    if (den == 0 || num == 0 || (num < 0) != (den < 0))
        return false;
    num_t tt = numw_div(num, den);
    if (!(tt > NUM_ZERO))
        return false;
    *t = tt;
    return true;
}

/* Shadow rays (any hit with 0 < t < tmax; tmax NUM_MAX: any t > 0)
 * without a division: t = num / den is in range when num and den have one
 * strict sign and |num| < tmax |den| (numw_lt_mul: exact in Q16.16). */
__attribute__((unused)) static bool geom_flat_occludes(const vec3_t *a, const vec3_t *n, const ray_t *ray, num_t tmax)
{
    numw_t den = vec3_dotw_units(ray->d, *n);
    numw_t num = vec3_dotw_unit(vec3_sub(*a, ray->o), *n);
    if (den == 0 || num == 0 || (num < 0) != (den < 0))
        return false;
    if (tmax == NUM_MAX)
        return true;
    return num > 0 ? numw_lt_mul(num, tmax, den) : numw_lt_mul(numw_sub(numw_from(NUM_ZERO), num), tmax,
                                                               numw_sub(numw_from(NUM_ZERO), den));
}

/* The plane's t for any ray (no side or sign test): shading's hit point
 * on a flat piece the renderer found the ray to cover. */
__attribute__((unused)) static num_t geom_flat_surface_t(const vec3_t *a, const vec3_t *n, const ray_t *ray)
{
    return numw_div(vec3_dotw_unit(vec3_sub(*a, ray->o), *n), vec3_dotw_units(ray->d, *n));
}

#if FXRT_MAX_PLANES > 0
bool geom_plane_make(geom_plane_t *p, vec3_t point, vec3_t normal, color_t color, uint16_t id)
{
    p->a = point;
    p->n = normal;
    geom_common_init(&p->obj, color, id);
    return vec3_normalize(&p->n) && geom_plane_check(point, normal, color) == FXRT_OK;
}

bool geom_plane_hit(const geom_plane_t *p, const ray_t *ray, num_t *t)
{
    return geom_flat_t(&p->a, &p->n, ray, t);
}

bool geom_plane_occludes(const geom_plane_t *p, const ray_t *ray, num_t tmax)
{
    return geom_flat_occludes(&p->a, &p->n, ray, tmax);
}

void geom_plane_surface(const geom_plane_t *p, const ray_t *ray, num_t *t, vec3_t *n)
{
    *t = geom_flat_surface_t(&p->a, &p->n, ray);
    *n = p->n;
}
#endif

#if FXRT_MAX_SPHERES > 0
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
#endif

#if FXRT_MAX_TRIANGLES > 0
bool geom_triangle_make(geom_triangle_t *tr, vec3_t a, vec3_t b, vec3_t c, color_t color, uint16_t id)
{
    tr->a = a;
    tr->b = b;
    tr->c = c;
    geom_common_init(&tr->obj, color, id);
    tr->degenerate = !vec3_unit_cross(vec3_sub(b, a), vec3_sub(c, a), &tr->n);
    return geom_triangle_check(a, b, c, color) == FXRT_OK;
}

/* Which side of the edge p -> q the ray passes: d . ((p - o) x (q - o)),
 * evaluated as (p - o) . ((q - o) x d). It is always computed with the edge
 * in canonical order and negated for the other order, so two triangles
 * sharing an edge see exactly opposite values: a ray cannot slip between
 * them (watertight), whatever the rounding. */
static numw_t geom_edge(vec3_t p, vec3_t q, const ray_t *ray)
{
    bool swap = geom_point_less(q, p);
    vec3_t first = swap ? q : p, second = swap ? p : q;
    numw_t e = vec3_dotw(vec3_sub(first, ray->o), vec3_cross_unit(vec3_sub(second, ray->o), ray->d));
    return swap ? numw_sub(numw_from(NUM_ZERO), e) : e;
}

/* Does the ray's line pass inside the triangle? When all three edge tests
 * agree in sign (either winding; a zero means the ray grazes that edge
 * and counts). */
static bool geom_triangle_inside(const geom_triangle_t *tr, const ray_t *ray)
{
    numw_t e0 = geom_edge(tr->a, tr->b, ray);
    numw_t e1 = geom_edge(tr->b, tr->c, ray);
    numw_t e2 = geom_edge(tr->c, tr->a, ray);
    bool neg = e0 < 0 || e1 < 0 || e2 < 0;
    bool pos = e0 > 0 || e1 > 0 || e2 > 0;
    return !(neg && pos);
}

bool geom_triangle_hit(const geom_triangle_t *tr, const ray_t *ray, num_t *t)
{
    if (tr->degenerate || !geom_triangle_inside(tr, ray))
        return false;
    return geom_flat_t(&tr->a, &tr->n, ray, t);
}

bool geom_triangle_occludes(const geom_triangle_t *tr, const ray_t *ray, num_t tmax)
{
    /* The plane first (two dot products): most shadow rays do not cross
     * it in (0, tmax), and then the edges are not needed. */
    return !tr->degenerate && geom_flat_occludes(&tr->a, &tr->n, ray, tmax) && geom_triangle_inside(tr, ray);
}

void geom_triangle_surface(const geom_triangle_t *tr, const ray_t *ray, num_t *t, vec3_t *n)
{
    *t = geom_flat_surface_t(&tr->a, &tr->n, ray);
    *n = tr->n;
}
#endif

#if FXRT_MAX_BOXES > 0
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
#endif
