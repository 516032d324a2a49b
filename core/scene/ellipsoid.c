/* ellipsoid: the points c + x u + y v + z w with x^2 + y^2 + z^2 <= 1, a
 * sphere that a node scales unevenly (docs/SCENES.md, "Nodes"). Every
 * query maps its ray into the unit sphere's space by the inverse of the
 * matrix A of columns u, v, w and meets the unit sphere there; the normal
 * is the unit sphere's (the point itself) mapped by A^-T, the inverse
 * transpose, and normalised. An affine map keeps the ray parameter, so
 * the world t is the local one over the local direction's length. */
#include "scene/kinds.h"

#if FXRT_MAX_ELLIPSOIDS > 0

/* The largest entry of A^-1 (its axes no thinner than about 2^-13), and
 * the largest det A (2^30: e.g. semi-axes of 1,024 each). */
#define GEOM_ELL_INV_MAX 8192
#define GEOM_ELL_DET_MAX ((int64_t)1 << 30)

/* What the number types do differently: the range of Q16.16.
 *
 * geom_ell_det: det A from its first row and cofactors, false beyond
 * GEOM_ELL_DET_MAX or 0. Q16.16 rounds it to Q32.32 from exact products
 * (each term below 2^60 there, else det's terms exceed the cap by far).
 *
 * geom_ell_origin: the local origin A^-1 (o - c), and the scale: Q16.16
 * forms it exactly in Q32.32 (o - c within 2^16 per axis, the ray's
 * origin within 2^15 and c within 2^13: each product below 2^29 2^32, the
 * sums below 2^63), then scales it by 2^-s to within 2^14 of the centre
 * (false beyond s = 8: 2^22 radii). The local direction's length is len
 * 2^(sh - 16) (numw_direction_shift's sh).
 *
 * geom_ell_world_t: local t (scaled) to world t, t 2^k / len, saturating;
 * Q16.16 keeps the divisor len 2^-k wide (len holds 30 significant bits,
 * k <= 24).
 *
 * geom_ell_ray_t: a ray in the unit sphere's space, scaled by 2^-s so
 * that its origin stays within 2^14 of the centre in Q16.16: origin o,
 * unit direction d, the sphere's squared radius r2 (2^-2s), and k, len
 * with world t = local t 2^k / len. */
typedef struct {
    vec3_t o, d;
    numw_t r2;
    num_t len;
    int k;
} geom_ell_ray_t;

#if NUM_EXACT
static bool geom_ell_det(const num_t a[3][3], numw_t cof[3][3], numw_t *det)
{
    int64_t dsum = 0;
    for (int j = 0; j < 3; j++) {
        fx128_t p = fx128_mul(a[0][j], cof[0][j]);
        if (fx128_bits(p) > 16 + 60)
            return false;
        dsum += fx128_shr_round(p, 16);
    }
    const numw_t det_max = GEOM_ELL_DET_MAX << 32;
    *det = dsum;
    return dsum != 0 && dsum <= det_max && dsum >= -det_max;
}

static bool geom_ell_origin(const geom_ellipsoid_t *e, const ray_t *ray, int sh, geom_ell_ray_t *l)
{
    const int64_t oc[3] = {(int64_t)ray->o.x - e->c.x, (int64_t)ray->o.y - e->c.y, (int64_t)ray->o.z - e->c.z};
    int64_t ol[3];
    uint64_t m = 0;
    for (int i = 0; i < 3; i++) {
        ol[i] = (int64_t)e->inv[i].x * oc[0] + (int64_t)e->inv[i].y * oc[1] + (int64_t)e->inv[i].z * oc[2];
        m |= ol[i] < 0 ? (uint64_t)0 - (uint64_t)ol[i] : (uint64_t)ol[i];
    }
    int s = 0;
    while ((m >> s) >= ((uint64_t)1 << 46))
        s++;
    if (s > 8)
        return false;
    num_t o[3];
    for (int i = 0; i < 3; i++)
        o[i] = (num_t)((ol[i] + ((int64_t)1 << (15 + s))) >> (16 + s));
    l->o = vec3_make(o[0], o[1], o[2]);
    l->r2 = (numw_t)1 << (32 - 2 * s);
    l->k = s + 16 - sh;
    return true;
}

static num_t geom_ell_world_t(const geom_ell_ray_t *l, num_t t)
{
    numw_t lw = numw_from(l->len);
    lw = l->k >= 0 ? lw >> l->k : lw * ((numw_t)1 << -l->k);
    return numw_div(numw_from(t), lw);
}
#else
static bool geom_ell_det(const num_t a[3][3], numw_t cof[3][3], numw_t *det)
{
    *det = a[0][0] * cof[0][0] + a[0][1] * cof[0][1] + a[0][2] * cof[0][2];
    return *det != 0 && *det <= (numw_t)GEOM_ELL_DET_MAX && *det >= -(numw_t)GEOM_ELL_DET_MAX;
}

static bool geom_ell_origin(const geom_ellipsoid_t *e, const ray_t *ray, int sh, geom_ell_ray_t *l)
{
    vec3_t oc = vec3_sub(ray->o, e->c);
    l->o = vec3_make(vec3_dot(e->inv[0], oc), vec3_dot(e->inv[1], oc), vec3_dot(e->inv[2], oc));
    l->r2 = NUM_ONE;
    l->k = sh;
    return true;
}

static num_t geom_ell_world_t(const geom_ell_ray_t *l, num_t t) { return num_div(t, l->len); }
#endif

/* det A and A^-1's rows for columns u, v, w: false when A is singular or
 * beyond the two caps above. Q16.16 forms the cofactors exactly in Q32.32
 * and det A from them rounded to Q32.32 (each product below 2^88). */
static bool geom_ell_inverse(vec3_t u, vec3_t v, vec3_t w, vec3_t inv[3])
{
    /* Cofactor (i, j) of A = [u v w]: cof[i][j], and A^-1 = cof^T / det. */
    const num_t a[3][3] = {{u.x, v.x, w.x}, {u.y, v.y, w.y}, {u.z, v.z, w.z}};
    numw_t cof[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            cof[i][j] = numw_sub(numw_mul(a[i1][j1], a[i2][j2]), numw_mul(a[i1][j2], a[i2][j1]));
        }
    numw_t det;
    if (!geom_ell_det(a, cof, &det))
        return false;
    const num_t lim = num_from_int(GEOM_ELL_INV_MAX);
    num_t r[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            r[i][j] = numw_div(cof[j][i], det);
            if (!(r[i][j] < lim && r[i][j] > num_neg(lim)))
                return false;
        }
    for (int i = 0; i < 3; i++)
        inv[i] = vec3_make(r[i][0], r[i][1], r[i][2]);
    return true;
}

/* The box's half extents: sqrt(u_i^2 + v_i^2 + w_i^2) per axis, and the
 * reach sqrt(|u|^2 + |v|^2 + |w|^2) (at least the largest semi-axis),
 * each padded by 2^-20 of itself and 2 LSB of Q16.16 for the roots'
 * rounding. */
static num_t geom_ell_pad(numw_t sq)
{
    num_t r = numw_sqrt(sq);
    return num_add(num_add(r, num_mul(r, NUM(1.0 / 1048576))), NUM(2.0 / 65536));
}

static void geom_ell_extent(vec3_t u, vec3_t v, vec3_t w, vec3_t *half, num_t *reach)
{
    numw_t hx = numw_add(numw_add(numw_mul(u.x, u.x), numw_mul(v.x, v.x)), numw_mul(w.x, w.x));
    numw_t hy = numw_add(numw_add(numw_mul(u.y, u.y), numw_mul(v.y, v.y)), numw_mul(w.y, w.y));
    numw_t hz = numw_add(numw_add(numw_mul(u.z, u.z), numw_mul(v.z, v.z)), numw_mul(w.z, w.z));
    *half = vec3_make(geom_ell_pad(hx), geom_ell_pad(hy), geom_ell_pad(hz));
    *reach = geom_ell_pad(numw_add(numw_add(hx, hy), hz));
}

fxrt_err_t geom_ellipsoid_check(vec3_t center, vec3_t u, vec3_t v, vec3_t w, color_t color)
{
    fxrt_err_t e = geom_check_point(center);
    const vec3_t ax[3] = {u, v, w};
    for (int i = 0; i < 3 && e == FXRT_OK; i++)
        e = geom_check_dir(ax[i]);
    if (e != FXRT_OK)
        return e;
    vec3_t inv[3], half;
    num_t reach;
    if (!geom_ell_inverse(u, v, w, inv))
        return FXRT_ERR_AXES;
    geom_ell_extent(u, v, w, &half, &reach);
    /* its box within the coordinate limit (hence the reach within 2^15) */
    const num_t lim = num_from_int(FXRT_COORD_LIMIT);
    const num_t c[3] = {center.x, center.y, center.z}, h[3] = {half.x, half.y, half.z};
    for (int i = 0; i < 3; i++)
        if (!(h[i] <= lim && num_sub(c[i], h[i]) >= num_neg(lim) && num_add(c[i], h[i]) <= lim))
            return FXRT_ERR_COORD;
    return geom_check_color(color);
}

bool geom_ellipsoid_make(geom_ellipsoid_t *e, vec3_t center, vec3_t u, vec3_t v, vec3_t w, color_t color,
                         uint16_t id)
{
    e->c = center;
    e->u = u;
    e->v = v;
    e->w = w;
    geom_common_init(&e->obj, color, id);
    if (geom_ellipsoid_check(center, u, v, w, color) != FXRT_OK || !geom_ell_inverse(u, v, w, e->inv))
        return false;
    geom_ell_extent(u, v, w, &e->half, &e->reach);
    return true;
}

/* The ray in the unit sphere's space (geom_ell_ray_t). False when its
 * origin lies more than 2^22 radii away (Q16.16; the ellipsoid then spans
 * less than 2^-21 radians from there): no hit. */
static bool geom_ell_ray(const geom_ellipsoid_t *e, const ray_t *ray, geom_ell_ray_t *l)
{
    numw_t dl[3];
    for (int i = 0; i < 3; i++)
        dl[i] = vec3_dotw_unit(e->inv[i], ray->d);
    int sh = numw_direction_shift(dl);
    vec3_t part = vec3_make(numw_direction_part(dl[0], sh), numw_direction_part(dl[1], sh),
                            numw_direction_part(dl[2], sh));
    if (!vec3_unit_len(part, &l->d, &l->len))
        return false; /* (A^-1 is regular: not for a unit d) */
    return geom_ell_origin(e, ray, sh, l);
}


/* The unit sphere met along the local ray: the closest point's offset -q
 * from the centre (the sphere test's stable form, scene/sphere.c), the
 * half chord h, and the world t of the near and far points (t0 <= t1).
 * False where the line misses (disc < 0; silhouettes: h = 0 when
 * clamp). */
static bool geom_ell_meet(const geom_ell_ray_t *l, bool clamp, vec3_t *q, num_t *h, num_t *t0, num_t *t1)
{
    vec3_t oc = vec3_neg(l->o);
    num_t b = numw_round(vec3_dotw_unit(oc, l->d));
    *q = vec3_sub(oc, vec3_scale_unit(l->d, b));
    numw_t disc = numw_sub(l->r2, vec3_dotw(*q, *q));
    if (disc < 0 && !clamp)
        return false;
    *h = disc > 0 ? numw_sqrt(disc) : NUM_ZERO;
    *t0 = geom_ell_world_t(l, num_sub(b, *h));
    *t1 = geom_ell_world_t(l, num_add(b, *h));
    return true;
}

bool geom_ellipsoid_hit(const geom_ellipsoid_t *e, const ray_t *ray, num_t *t)
{
    geom_ell_ray_t l;
    vec3_t q;
    num_t h, t0, t1;
    if (!geom_ell_ray(e, ray, &l) || !geom_ell_meet(&l, false, &q, &h, &t0, &t1))
        return false;
    if (t0 > NUM_ZERO) {
        *t = t0;
        return true;
    }
    if (t1 > NUM_ZERO) { /* origin inside */
        *t = t1;
        return true;
    }
    return false;
}

bool geom_ellipsoid_occludes(const geom_ellipsoid_t *e, const ray_t *ray, num_t tmax)
{
    num_t t;
    return geom_ellipsoid_hit(e, ray, &t) && (tmax == NUM_MAX || t < tmax);
}

/* The world normal at local point p (on the unit sphere, scaled): A^-T p,
 * formed wide and normalised; false when it vanishes. */
static bool geom_ell_normal(const geom_ellipsoid_t *e, vec3_t p, vec3_t *n)
{
    const num_t pc[3] = {p.x, p.y, p.z};
    numw_t c[3] = {0, 0, 0};
    for (int i = 0; i < 3; i++) {
        c[0] = numw_add(c[0], numw_mul(e->inv[i].x, pc[i]));
        c[1] = numw_add(c[1], numw_mul(e->inv[i].y, pc[i]));
        c[2] = numw_add(c[2], numw_mul(e->inv[i].z, pc[i]));
    }
    int sh = numw_direction_shift(c);
    *n = vec3_make(numw_direction_part(c[0], sh), numw_direction_part(c[1], sh), numw_direction_part(c[2], sh));
    FXRT_COUNT(n_normalised);
    return vec3_normalize(n);
}

/* The near point (far: the far one, a ray leaving from inside) and its
 * outward normal; at a silhouette the closest point. */
static void geom_ell_at(const geom_ellipsoid_t *e, const ray_t *ray, bool far, num_t *t, vec3_t *n)
{
    geom_ell_ray_t l;
    vec3_t q;
    num_t h, t0, t1;
    if (!geom_ell_ray(e, ray, &l)) {
        *t = NUM_ZERO;
        *n = vec3_neg(ray->d);
        return;
    }
    geom_ell_meet(&l, true, &q, &h, &t0, &t1);
    bool near = !far && t0 > NUM_ZERO;
    *t = near ? t0 : t1;
    vec3_t hd = vec3_scale_unit(l.d, h);
    vec3_t p = near ? vec3_sub(vec3_neg(q), hd) : vec3_add(vec3_neg(q), hd);
    if (!geom_ell_normal(e, p, n))
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
    /* |A^-1 (p - c)| < 1; a component of magnitude 1 or more is outside */
    vec3_t d = vec3_sub(p, e->c);
    num_t x[3];
    for (int i = 0; i < 3; i++) {
        numw_t v = vec3_dotw(e->inv[i], d);
        if (!(v < numw_from(NUM_ONE) && v > numw_from(num_neg(NUM_ONE))))
            return false;
        x[i] = numw_round(v);
    }
    vec3_t xl = vec3_make(x[0], x[1], x[2]);
    return vec3_dotw(xl, xl) < numw_from(NUM_ONE);
}

void geom_ellipsoid_bounds(const geom_ellipsoid_t *e, vec3_t *lo, vec3_t *hi)
{
    *lo = vec3_sub(e->c, e->half);
    *hi = vec3_add(e->c, e->half);
}

void geom_ellipsoid_around(const geom_ellipsoid_t *e, vec3_t *c, num_t *r)
{
    *c = e->c;
    *r = e->reach;
}
#endif
