/* affine: the placement the ellipsoid and the parallelepiped share
 * (scene/affine.h): A^-1, the world box, and a ray in the unit shape's
 * space. */
#include "scene/kinds.h"

#if FXRT_MAX_ELLIPSOIDS > 0 || FXRT_MAX_PARALLELEPIPEDS > 0

/* The largest entry of A^-1 (no axis thinner than about 2^-13), and the
 * largest det A (2^30: e.g. semi-axes of 1,024 each). */
#define GEOM_AFFINE_INV_MAX 8192
#define GEOM_AFFINE_DET_MAX ((int64_t)1 << 30)

/* What the number types do differently: the range of Q16.16.
 *
 * geom_affine_det: det A from its first row and cofactors, false beyond
 * GEOM_AFFINE_DET_MAX or 0. Q16.16 rounds it to Q32.32 from exact
 * products (each term below 2^60 there, else det's terms exceed the cap
 * by far).
 *
 * geom_affine_origin: the local origin A^-1 (o - c), and the scale:
 * Q16.16 forms it exactly in Q32.32 (o - c within 2^16 per axis, the
 * ray's origin within 2^15 and c within 2^13: each product below 2^29
 * 2^32, the sums below 2^63), then scales it by 2^-s to within 2^14 of
 * the centre (false beyond s = 8: 2^22 units of the shape). The local
 * direction's length is len 2^(sh - 16) (numw_direction_shift's sh).
 *
 * geom_affine_world_t: local t (scaled) to world t, t 2^k / len,
 * saturating; Q16.16 keeps the divisor len 2^-k wide (len holds 30
 * significant bits, k <= 24). */
#if NUM_EXACT
static bool geom_affine_det(const num_t a[3][3], numw_t cof[3][3], numw_t *det)
{
    int64_t dsum = 0;
    for (int j = 0; j < 3; j++) {
        fx128_t p = fx128_mul(a[0][j], cof[0][j]);
        if (fx128_bits(p) > 16 + 60)
            return false;
        dsum += fx128_shr_round(p, 16);
    }
    const numw_t det_max = GEOM_AFFINE_DET_MAX << 32;
    *det = dsum;
    return dsum != 0 && dsum <= det_max && dsum >= -det_max;
}

static bool geom_affine_origin(const geom_affine_t *a, const ray_t *ray, int sh, geom_affine_ray_t *l)
{
    const int64_t oc[3] = {(int64_t)ray->o.x - a->c.x, (int64_t)ray->o.y - a->c.y, (int64_t)ray->o.z - a->c.z};
    int64_t ol[3];
    uint64_t m = 0;
    for (int i = 0; i < 3; i++) {
        ol[i] = (int64_t)a->inv[i].x * oc[0] + (int64_t)a->inv[i].y * oc[1] + (int64_t)a->inv[i].z * oc[2];
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
    l->r = (num_t)1 << (16 - s);
    l->r2 = (numw_t)1 << (32 - 2 * s);
    l->k = s + 16 - sh;
    return true;
}

num_t geom_affine_world_t(const geom_affine_ray_t *l, num_t t)
{
    numw_t lw = numw_from(l->len);
    lw = l->k >= 0 ? lw >> l->k : lw * ((numw_t)1 << -l->k);
    return numw_div(numw_from(t), lw);
}

num_t geom_affine_axis_t(const geom_affine_ray_t *l, num_t x, num_t dpi)
{
    /* x 2^k / dpi in Q16.16: fxw_div(x 2^k, dpi) (|x| < 2^31 LSB, k <= 24) */
    return l->k >= 0 ? numw_div((numw_t)x * ((numw_t)1 << l->k), (numw_t)dpi)
                     : numw_div((numw_t)x, (numw_t)dpi * ((numw_t)1 << -l->k));
}
#else
static bool geom_affine_det(const num_t a[3][3], numw_t cof[3][3], numw_t *det)
{
    *det = a[0][0] * cof[0][0] + a[0][1] * cof[0][1] + a[0][2] * cof[0][2];
    return *det != 0 && *det <= (numw_t)GEOM_AFFINE_DET_MAX && *det >= -(numw_t)GEOM_AFFINE_DET_MAX;
}

static bool geom_affine_origin(const geom_affine_t *a, const ray_t *ray, int sh, geom_affine_ray_t *l)
{
    vec3_t oc = vec3_sub(ray->o, a->c);
    l->o = vec3_make(vec3_dot(a->inv[0], oc), vec3_dot(a->inv[1], oc), vec3_dot(a->inv[2], oc));
    l->r = NUM_ONE;
    l->r2 = NUM_ONE;
    l->k = sh;
    return true;
}

num_t geom_affine_world_t(const geom_affine_ray_t *l, num_t t) { return num_div(t, l->len); }

num_t geom_affine_axis_t(const geom_affine_ray_t *l, num_t x, num_t dpi)
{
    (void)l;
    return num_div(x, dpi);
}
#endif

/* A^-1's rows for columns u, v, w: false when A is singular or beyond the
 * two caps above. Q16.16 forms the cofactors exactly in Q32.32. */
static bool geom_affine_inverse(vec3_t u, vec3_t v, vec3_t w, vec3_t inv[3])
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
    if (!geom_affine_det(a, cof, &det))
        return false;
    const num_t lim = num_from_int(GEOM_AFFINE_INV_MAX);
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

/* A length from its square, padded by 2^-20 of itself and 2 LSB of
 * Q16.16 for the root's rounding; and a sum of magnitudes, padded the
 * same way for the sums' rounding. */
static num_t geom_affine_pad(num_t r) { return num_add(num_add(r, num_mul(r, NUM(1.0 / 1048576))), NUM(2.0 / 65536)); }

/* The box's half extents and the reach: for the sphere, per axis i
 * sqrt(u_i^2 + v_i^2 + w_i^2) and sqrt(|u|^2 + |v|^2 + |w|^2) (at least
 * the largest semi-axis); for the cube, |u_i| + |v_i| + |w_i| and
 * |u| + |v| + |w|. */
static void geom_affine_extent(vec3_t u, vec3_t v, vec3_t w, bool box, vec3_t *half, num_t *reach)
{
    const num_t a[3][3] = {{u.x, v.x, w.x}, {u.y, v.y, w.y}, {u.z, v.z, w.z}};
    num_t h[3];
    numw_t all = 0;
    for (int i = 0; i < 3; i++) {
        numw_t sq = numw_add(numw_add(numw_mul(a[i][0], a[i][0]), numw_mul(a[i][1], a[i][1])), numw_mul(a[i][2], a[i][2]));
        all = numw_add(all, sq);
        h[i] = geom_affine_pad(box ? num_add(num_add(num_abs(a[i][0]), num_abs(a[i][1])), num_abs(a[i][2])) : numw_sqrt(sq));
    }
    *half = vec3_make(h[0], h[1], h[2]);
    *reach = geom_affine_pad(box ? num_add(num_add(vec3_len(u), vec3_len(v)), vec3_len(w)) : numw_sqrt(all));
}

/* The placement and its domain check in one pass: *a filled as far as
 * the check got (the inverse and the box once, for check and make). */
static fxrt_err_t geom_affine_build(geom_affine_t *a, vec3_t c, vec3_t u, vec3_t v, vec3_t w, bool box, color_t color)
{
    a->c = c;
    a->u = u;
    a->v = v;
    a->w = w;
    fxrt_err_t e = geom_check_point(c);
    const vec3_t ax[3] = {u, v, w};
    for (int i = 0; i < 3 && e == FXRT_OK; i++)
        e = geom_check_dir(ax[i]);
    if (e != FXRT_OK)
        return e;
    if (!geom_affine_inverse(u, v, w, a->inv))
        return FXRT_ERR_AXES;
    geom_affine_extent(u, v, w, box, &a->half, &a->reach);
    /* its box within the coordinate limit (hence the reach within 2^15) */
    const num_t lim = num_from_int(FXRT_COORD_LIMIT);
    const num_t cc[3] = {c.x, c.y, c.z}, h[3] = {a->half.x, a->half.y, a->half.z};
    for (int i = 0; i < 3; i++)
        if (!(h[i] <= lim && num_sub(cc[i], h[i]) >= num_neg(lim) && num_add(cc[i], h[i]) <= lim))
            return FXRT_ERR_COORD;
    return geom_check_color(color);
}

fxrt_err_t geom_affine_check(vec3_t c, vec3_t u, vec3_t v, vec3_t w, bool box, color_t color)
{
    geom_affine_t a;
    return geom_affine_build(&a, c, u, v, w, box, color);
}

bool geom_affine_make(geom_affine_t *a, vec3_t c, vec3_t u, vec3_t v, vec3_t w, bool box, color_t color)
{
    return geom_affine_build(a, c, u, v, w, box, color) == FXRT_OK;
}

bool geom_affine_ray(const geom_affine_t *a, const ray_t *ray, geom_affine_ray_t *l)
{
    numw_t dl[3];
    for (int i = 0; i < 3; i++)
        dl[i] = vec3_dotw_unit(a->inv[i], ray->d);
    int sh = numw_direction_shift(dl);
    l->dp = vec3_make(numw_direction_part(dl[0], sh), numw_direction_part(dl[1], sh), numw_direction_part(dl[2], sh));
    if (!vec3_unit_len(l->dp, &l->d, &l->len))
        return false; /* (A^-1 is regular: not for a unit d) */
    return geom_affine_origin(a, ray, sh, l);
}

bool geom_affine_normal(const geom_affine_t *a, vec3_t p, vec3_t *n)
{
    const num_t pc[3] = {p.x, p.y, p.z};
    numw_t c[3] = {0, 0, 0};
    for (int i = 0; i < 3; i++) {
        c[0] = numw_add(c[0], numw_mul(a->inv[i].x, pc[i]));
        c[1] = numw_add(c[1], numw_mul(a->inv[i].y, pc[i]));
        c[2] = numw_add(c[2], numw_mul(a->inv[i].z, pc[i]));
    }
    int sh = numw_direction_shift(c);
    *n = vec3_make(numw_direction_part(c[0], sh), numw_direction_part(c[1], sh), numw_direction_part(c[2], sh));
    FXRT_COUNT(n_normalised);
    return vec3_normalize(n);
}

bool geom_affine_local(const geom_affine_t *a, vec3_t p, num_t x[3])
{
    vec3_t d = vec3_sub(p, a->c);
    for (int i = 0; i < 3; i++) {
        numw_t v = vec3_dotw(a->inv[i], d);
        if (!(v < numw_from(NUM_ONE) && v > numw_from(num_neg(NUM_ONE))))
            return false;
        x[i] = numw_round(v);
    }
    return true;
}

void geom_affine_bounds(const geom_affine_t *a, vec3_t *lo, vec3_t *hi)
{
    *lo = vec3_sub(a->c, a->half);
    *hi = vec3_add(a->c, a->half);
}
void geom_affine_around(const geom_affine_t *a, vec3_t *c, num_t *r)
{
    *c = a->c;
    *r = a->reach;
}
#endif
