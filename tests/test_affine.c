/* test_affine: the kinds placed by an affine map (core/scene/affine.c),
 * ellipsoids and parallelepipeds, in one number type (one binary per
 * type).
 *
 *   - the oracle, another formula than the code's (a ray mapped into the
 *     unit shape's space, normals by A^-T): for the ellipsoid the implicit
 *     form (p - c)^T Q (p - c) = 1 with Q = (A A^T)^-1, solved in long
 *     double as a quadratic in t, its normal the gradient Q (p - c); for
 *     the parallelepiped three slabs bounded by planes whose normals are
 *     cross products of the axes. Random shapes (rotations, uneven
 *     scales, shears), random rays from outside and inside: hit or miss,
 *     t, the normal (off the parallelepiped's edges), the exit, the shadow
 *     test around t, containment, and the box around it;
 *   - frames: an ellipsoid whose axes are a sphere's (r times a random
 *     rotation) renders as the sphere kind does, and a parallelepiped
 *     whose half edges are a box's (permuted, signs drawn) as the box
 *     kind does (other visibility paths, other intersections), on a floor
 *     with a shadowing point light, lambert, phong, reflective and
 *     transparent;
 *   - every refusal of fxrt_add, each leaving the world unchanged. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "fxrt.h"
#include "frame.h"

#define PI_D 3.14159265358979323846
#define IMG_W 96
#define IMG_H 72

static uint64_t rng = 0x51ED2701A5C3F00Du;
static double urand(void) { return (double)(check_rng_next(&rng) >> 11) / 9007199254740992.0; }
static double srand_(double a, double b) { return a + (b - a) * urand(); }

static num_t num_d(double x) { return NUM_EXACT ? num_from_q16((int32_t)lrint(x * 65536)) : (num_t)x; }
static double d_num(num_t x) { return NUM_EXACT ? num_to_q16(x) / 65536.0 : (double)x; }
static vec3_t vec_d(const double v[3]) { return vec3_make(num_d(v[0]), num_d(v[1]), num_d(v[2])); }
static void d_vec(vec3_t v, long double o[3]) { o[0] = d_num(v.x), o[1] = d_num(v.y), o[2] = d_num(v.z); }

/* A random rotation (three angles about z, y, x) into r. */
static void rotation(double r[3][3])
{
    double a = srand_(-PI_D, PI_D), b = srand_(-PI_D, PI_D), c = srand_(-PI_D, PI_D);
    double z[3][3] = {{cos(a), -sin(a), 0}, {sin(a), cos(a), 0}, {0, 0, 1}};
    double y[3][3] = {{cos(b), 0, sin(b)}, {0, 1, 0}, {-sin(b), 0, cos(b)}};
    double x[3][3] = {{1, 0, 0}, {0, cos(c), -sin(c)}, {0, sin(c), cos(c)}};
    double t[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            t[i][j] = z[i][0] * y[0][j] + z[i][1] * y[1][j] + z[i][2] * y[2][j];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r[i][j] = t[i][0] * x[0][j] + t[i][1] * x[1][j] + t[i][2] * x[2][j];
}

/* The oracle's shape, from the build's own numbers (so that input
 * rounding is not counted): the centre; the ellipsoid's Q = (A A^T)^-1;
 * the parallelepiped's three slabs |n_k . (x - c)| <= h_k, n_k the cross
 * product of the other two axes (turned so that h_k = n_k . a_k > 0). */
typedef struct {
    bool box;
    long double c[3], q[3][3], n[3][3], h[3];
} oracle_t;

static void cross(const long double a[3], const long double b[3], long double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

static long double dot(const long double a[3], const long double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void oracle_make(const geom_affine_t *e, bool box, oracle_t *o)
{
    long double a[3][3], ax[3][3], g[3][3];
    o->box = box;
    d_vec(e->c, o->c);
    d_vec(e->u, ax[0]);
    d_vec(e->v, ax[1]);
    d_vec(e->w, ax[2]);
    for (int k = 0; k < 3; k++) {
        cross(ax[(k + 1) % 3], ax[(k + 2) % 3], o->n[k]);
        o->h[k] = dot(o->n[k], ax[k]);
        if (o->h[k] < 0) {
            for (int i = 0; i < 3; i++)
                o->n[k][i] = -o->n[k][i];
            o->h[k] = -o->h[k];
        }
    }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            a[i][j] = ax[j][i];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            g[i][j] = a[i][0] * a[j][0] + a[i][1] * a[j][1] + a[i][2] * a[j][2];
    /* the inverse of the symmetric G by its adjugate */
    long double cof[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            cof[i][j] = g[i1][j1] * g[i2][j2] - g[i1][j2] * g[i2][j1];
        }
    long double det = g[0][0] * cof[0][0] + g[0][1] * cof[0][1] + g[0][2] * cof[0][2];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            o->q[i][j] = cof[j][i] / det;
}

/* x^T Q y */
static long double qform(const oracle_t *o, const long double x[3], const long double y[3])
{
    long double s = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            s += x[i] * o->q[i][j] * y[j];
    return s;
}

static void unit(long double n[3])
{
    long double len = sqrtl(dot(n, n));
    for (int i = 0; i < 3; i++)
        n[i] /= len;
}

/* The ray's entry and exit t0 <= t1, their outward unit normals n0, n1,
 * the grazing margin (the half chord squared: t^2 units), and for the
 * parallelepiped whether the entry or the exit lies on an edge (another
 * face's t within 10^-3: its normal is either face's); false where it
 * misses. The ellipsoid's: the quadratic (p - c)^T Q (p - c) = 1, its
 * normal the gradient Q (p - c). */
static bool oracle_roots(const oracle_t *o, const long double p[3], const long double d[3], long double *t0,
                         long double *t1, long double n0[3], long double n1[3], long double *margin, bool *edge)
{
    long double oc[3] = {p[0] - o->c[0], p[1] - o->c[1], p[2] - o->c[2]};
    *edge = false;
    if (!o->box) {
        long double a = qform(o, d, d), b = qform(o, d, oc), c = qform(o, oc, oc) - 1;
        long double disc = b * b - a * c;
        *margin = disc / (a * a);
        if (disc < 0)
            return false;
        long double h = sqrtl(disc);
        *t0 = (-b - h) / a;
        *t1 = (-b + h) / a;
        long double *ns[2] = {n0, n1};
        const long double ts[2] = {*t0, *t1};
        for (int k = 0; k < 2; k++) {
            long double v[3] = {oc[0] + ts[k] * d[0], oc[1] + ts[k] * d[1], oc[2] + ts[k] * d[2]};
            for (int i = 0; i < 3; i++)
                ns[k][i] = o->q[i][0] * v[0] + o->q[i][1] * v[1] + o->q[i][2] * v[2];
            unit(ns[k]);
        }
        return true;
    }
    long double tn[3], tf[3];
    int kn = 0, kf = 0;
    for (int k = 0; k < 3; k++) {
        long double s = dot(o->n[k], oc), q = dot(o->n[k], d);
        if (fabsl(q) < 1e-30L) {
            if (fabsl(s) > o->h[k]) {
                *margin = -1;
                return false;
            }
            tn[k] = -INFINITY, tf[k] = INFINITY;
        } else {
            long double a = (-o->h[k] - s) / q, b = (o->h[k] - s) / q;
            tn[k] = a < b ? a : b;
            tf[k] = a < b ? b : a;
        }
        kn = tn[k] > tn[kn] ? k : kn;
        kf = tf[k] < tf[kf] ? k : kf;
    }
    *t0 = tn[kn];
    *t1 = tf[kf];
    long double gap = (*t1 - *t0) / 2;
    *margin = gap < 0 ? -gap * gap : gap * gap;
    if (*t0 > *t1)
        return false;
    for (int k = 0; k < 3; k++)
        *edge |= (k != kn && fabsl(tn[k] - *t0) < 1e-3L * (1 + fabsl(*t0))) ||
                 (k != kf && fabsl(tf[k] - *t1) < 1e-3L * (1 + fabsl(*t1)));
    /* entering face kn: outward is -n where the ray goes along n */
    long double sn = dot(o->n[kn], d) > 0 ? -1 : 1, sf = dot(o->n[kf], d) > 0 ? 1 : -1;
    for (int i = 0; i < 3; i++)
        n0[i] = sn * o->n[kn][i], n1[i] = sf * o->n[kf][i];
    unit(n0);
    unit(n1);
    return true;
}

/* Is p inside (value below 1: the implicit form, or the largest
 * |n_k . (p - c)| / h_k)? */
static long double oracle_inside(const oracle_t *o, const long double p[3])
{
    long double v[3] = {p[0] - o->c[0], p[1] - o->c[1], p[2] - o->c[2]};
    if (!o->box)
        return qform(o, v, v);
    long double m = 0;
    for (int k = 0; k < 3; k++) {
        long double r = fabsl(dot(o->n[k], v)) / o->h[k];
        m = r > m ? r : m;
    }
    return m;
}

/* The shape under test: an ellipsoid or a parallelepiped, and its
 * queries. */
typedef struct {
    bool box;
    geom_ellipsoid_t e;
    geom_parallelepiped_t b;
} shape_t;

static const geom_affine_t *shape_placement(const shape_t *s) { return s->box ? &s->b.a : &s->e.a; }
static bool shape_hit(const shape_t *s, const ray_t *r, num_t *t)
{
    return s->box ? geom_parallelepiped_hit(&s->b, r, t) : geom_ellipsoid_hit(&s->e, r, t);
}
static bool shape_occludes(const shape_t *s, const ray_t *r, num_t tmax)
{
    return s->box ? geom_parallelepiped_occludes(&s->b, r, tmax) : geom_ellipsoid_occludes(&s->e, r, tmax);
}
static void shape_surface(const shape_t *s, const ray_t *r, num_t *t, vec3_t *n)
{
    if (s->box)
        geom_parallelepiped_surface(&s->b, r, t, n);
    else
        geom_ellipsoid_surface(&s->e, r, t, n);
}
static bool shape_exit(const shape_t *s, const ray_t *r, num_t *t, vec3_t *n)
{
    return s->box ? geom_parallelepiped_exit(&s->b, r, t, n) : geom_ellipsoid_exit(&s->e, r, t, n);
}
static bool shape_contains(const shape_t *s, vec3_t p)
{
    return s->box ? geom_parallelepiped_contains(&s->b, p) : geom_ellipsoid_contains(&s->e, p);
}
static void shape_bounds(const shape_t *s, vec3_t *lo, vec3_t *hi)
{
    if (s->box)
        geom_parallelepiped_bounds(&s->b, lo, hi);
    else
        geom_ellipsoid_bounds(&s->e, lo, hi);
}

/* A random shape: A = R1 diag(s) R2 (a rotation, uneven scales in
 * [0.08, 3], and a second rotation: axes not orthogonal in general), or
 * every entry random (a shear) with a condition that the checks keep. */
static bool random_shape(shape_t *sh, double axes[3][3], double c[3])
{
    double r1[3][3], r2[3][3], s[3];
    rotation(r1);
    rotation(r2);
    for (int i = 0; i < 3; i++) {
        s[i] = exp(srand_(log(0.08), log(3.0)));
        c[i] = srand_(-4, 4);
    }
    bool shear = check_rng_next(&rng) % 4 == 0;
    for (int k = 0; k < 3; k++) /* axis k: column k of A */
        for (int i = 0; i < 3; i++) {
            double v = 0;
            for (int j = 0; j < 3; j++)
                v += r1[i][j] * s[j] * r2[j][k];
            axes[k][i] = shear ? srand_(-2, 2) : v;
        }
    color_t col = fxrt_color(num_from_int(200), num_from_int(100), num_from_int(50));
    vec3_t cv = vec_d(c), u = vec_d(axes[0]), v = vec_d(axes[1]), w = vec_d(axes[2]);
    return sh->box ? geom_parallelepiped_make(&sh->b, cv, u, v, w, col, 0) : geom_ellipsoid_make(&sh->e, cv, u, v, w, col, 0);
}

static void test_oracle(bool box)
{
    /* Tolerances: t within tol_t (1 + t), the normal within tol_n
     * (1 - cos of the angle), where the ray passes at least 10^-3 (in t^2)
     * from grazing; Q16.16 holds the local ray to 2^-16 of a unit at up to
     * 150 units (a thin axis of 0.08 seen from 12 away), and A^-T turns
     * that error by up to its condition (37): the ellipsoid's worst normal
     * is 1.3e-4 (0.9 degrees; float 1.4e-7, double 2.6e-16). */
    const long double tol_t = NUM_EXACT ? 3e-3L : (sizeof(num_t) == 4 ? 2e-5L : 1e-12L);
    const long double tol_n = NUM_EXACT ? 3e-4L : (sizeof(num_t) == 4 ? 1e-6L : 1e-14L);
    const long double graze = 1e-3L;
    const char *name = box ? "parallelepipeds" : "ellipsoids";
    long hits = 0, misses = 0, inside = 0, wrong = 0, made = 0, contained = 0, normals = 0;
    long double worst_t = 0, worst_n = 0;
    for (int iter = 0; iter < 600; iter++) {
        shape_t sh = {.box = box};
        double axes[3][3], c[3];
        if (!random_shape(&sh, axes, c))
            continue; /* (a shear too flat or thin: refused, test_refusals) */
        made++;
        oracle_t o;
        oracle_make(shape_placement(&sh), box, &o);
        vec3_t lo, hi;
        shape_bounds(&sh, &lo, &hi);
        long double blo[3], bhi[3];
        d_vec(lo, blo);
        d_vec(hi, bhi);
        for (int k = 0; k < 40; k++) {
            /* a ray from a random point (inside for some: near the centre)
             * towards a random point near the shape */
            bool from_in = k % 8 == 0;
            double p[3], tg[3], d[3], len = 0;
            double u[3] = {srand_(-1, 1), srand_(-1, 1), srand_(-1, 1)}, f = from_in ? 0.3 : 1.3;
            for (int i = 0; i < 3; i++) {
                p[i] = from_in ? c[i] + f * (axes[0][i] * u[0] + axes[1][i] * u[1] + axes[2][i] * u[2])
                               : c[i] + srand_(-12, 12);
                tg[i] = c[i] + 1.2 * (axes[0][i] * srand_(-1, 1) + axes[1][i] * srand_(-1, 1) + axes[2][i] * srand_(-1, 1));
                d[i] = tg[i] - p[i];
                len += d[i] * d[i];
            }
            if (len < 1e-6)
                continue;
            for (int i = 0; i < 3; i++)
                d[i] /= sqrt(len);
            ray_t ray = {.o = vec_d(p), .d = vec_d(d)};
            long double po[3], pd[3], t0 = 0, t1 = 0, margin = 0, n0[3], n1[3];
            bool edge;
            d_vec(ray.o, po);
            d_vec(ray.d, pd);
            bool met = oracle_roots(&o, po, pd, &t0, &t1, n0, n1, &margin, &edge);
            bool in = met && t0 < 0 && t1 > 0;
            num_t t;
            bool hit = shape_hit(&sh, &ray, &t);
            if (fabsl(margin) < graze) /* grazing: either answer */
                continue;
            long double want = !met ? -1 : (t0 > 0 ? t0 : t1);
            if (!met || want <= 0) {
                misses++;
                CHECK_SWEEP(!hit, "%s iter %d ray %d: a miss hit at t %g", name, iter, k, d_num(t));
                wrong += hit;
                continue;
            }
            hits++;
            inside += in;
            long double et = fabsl(d_num(t) - want) / (1 + want);
            worst_t = et > worst_t ? et : worst_t;
            CHECK_SWEEP(hit && et <= tol_t, "%s iter %d ray %d: t %g, oracle %Lg", name, iter, k, hit ? d_num(t) : -1.0,
                        want);
            wrong += !hit || et > tol_t;
            /* the surface: the same t, the oracle's normal there */
            vec3_t n;
            num_t ts;
            if (in) {
                long double po_in = oracle_inside(&o, po);
                CHECK_SWEEP(shape_contains(&sh, ray.o) || po_in > 0.95L, "%s iter %d: origin inside", name, iter);
                CHECK(shape_exit(&sh, &ray, &ts, &n));
            } else {
                shape_surface(&sh, &ray, &ts, &n);
            }
            CHECK_SWEEP(fabsl(d_num(ts) - want) <= tol_t * (1 + want), "%s iter %d ray %d: surface t %g (oracle %Lg)",
                        name, iter, k, d_num(ts), want);
            if (!edge) {
                long double gn[3];
                d_vec(n, gn);
                long double en = 1 - dot(in ? n1 : n0, gn);
                worst_n = en > worst_n ? en : worst_n;
                normals++;
                CHECK_SWEEP(en <= tol_n, "%s iter %d ray %d: 1 - n.n' %Lg", name, iter, k, en);
            }
            /* the shadow test around t (where it is not beyond Q16.16's t) */
            if (want < 1000) {
                num_t below = num_d((double)(want * 0.98L - 2e-3L)), above = num_d((double)(want * 1.02L + 2e-3L));
                CHECK_SWEEP(!shape_occludes(&sh, &ray, below) && shape_occludes(&sh, &ray, above),
                            "%s iter %d ray %d: occludes around t %Lg", name, iter, k, want);
            }
            /* the box holds the point met */
            for (int i = 0; i < 3; i++) {
                long double hp = po[i] + want * pd[i];
                CHECK_SWEEP(hp >= blo[i] - 1e-4L && hp <= bhi[i] + 1e-4L, "%s iter %d: point beyond its box", name, iter);
            }
        }
        /* containment of points well inside or outside (the oracle's
         * value below 0.95 or above 1.05) */
        for (int k = 0; k < 20; k++) {
            double p[3];
            for (int i = 0; i < 3; i++)
                p[i] = c[i] + 1.5 * (axes[0][i] * srand_(-1, 1) + axes[1][i] * srand_(-1, 1) + axes[2][i] * srand_(-1, 1));
            vec3_t pv = vec_d(p);
            long double pp[3];
            d_vec(pv, pp);
            long double fv = oracle_inside(&o, pp);
            if (fabsl(fv - 1) < 0.05L)
                continue;
            bool want = fv < 1;
            contained += want;
            CHECK_SWEEP(shape_contains(&sh, pv) == want, "%s iter %d: contains, oracle %Lg", name, iter, fv);
        }
    }
    printf("  %ld %s: %ld hits (%ld from inside), %ld misses, %ld points inside; worst t %.3Lg, "
           "worst 1 - n.n' %.3Lg (%ld normals off edges)\n",
           made, name, hits, inside, misses, contained, worst_t, worst_n, normals);
    CHECK_MSG(wrong == 0, "%s: %ld rays wrong", name, wrong);
    CHECK_MSG(made >= 500 && hits >= 5000 && misses >= 2000 && inside >= 500 && normals >= 4000,
              "%s: too few cases: %ld, %ld, %ld, %ld, %ld", name, made, hits, misses, inside, normals);
}

/* ---- frames ---------------------------------------------------------------- */

static fxrt_world_t world_a, world_b;
static fxrt_render_t render_a, render_b;
static uint8_t img_a[IMG_W * IMG_H * 3], img_b[IMG_W * IMG_H * 3];

static bool render(const fxrt_world_t *w, const fxrt_view_t *v, fxrt_render_t *r, uint8_t *img)
{
    return frame_render(w, v, r, img, IMG_W, IMG_H);
}

/* box false: an ellipsoid whose axes are a sphere's (r times a random
 * rotation) against the sphere; true: a parallelepiped whose half edges
 * are a box's (permuted, signs drawn) against the box. */
static void test_frames(bool box)
{
    /* Allowed: pixels off by more than 2 levels per scene of 6,912 (edges
     * that rounding moves by a pixel). */
    const long cap = NUM_EXACT ? 12 : 3;
    long worst = 0, covered = 0;
    for (int iter = 0; iter < 24; iter++) {
        double c[3] = {srand_(-1, 1), srand_(-0.5, 1), srand_(-1, 1)}, rad = srand_(0.4, 1.6), r[3][3];
        double half[3] = {srand_(0.3, 1.5), srand_(0.3, 1.5), srand_(0.3, 1.5)};
        int perm = (int)(check_rng_next(&rng) % 6), signs = (int)(check_rng_next(&rng) % 8);
        rotation(r);
        static const uint8_t kinds[4] = {MATERIAL_LAMBERT, MATERIAL_PHONG, MATERIAL_REFLECTIVE, MATERIAL_TRANSPARENT};
        material_t m = {.kind = kinds[iter % 4], .exponent = (uint16_t)(2 + check_rng_next(&rng) % 120)};
        m.specular = fxrt_color(num_d(srand_(25, 255)), num_d(srand_(25, 255)), num_d(srand_(25, 255)));
        m.reflection = fxrt_color(num_d(srand_(60, 200)), num_d(srand_(60, 200)), num_d(srand_(60, 200)));
        if (m.kind == MATERIAL_LAMBERT || m.kind == MATERIAL_TRANSPARENT)
            m.exponent = 0, m.specular = fxrt_color(NUM_ZERO, NUM_ZERO, NUM_ZERO);
        if (m.kind == MATERIAL_TRANSPARENT) /* (the exit and the inside: refraction through it) */
            m.index = num_d(srand_(1.1, 1.8));
        if (m.kind != MATERIAL_REFLECTIVE)
            m.reflection = fxrt_color(NUM_ZERO, NUM_ZERO, NUM_ZERO);
        color_t col = fxrt_color(num_d(srand_(30, 255)), num_d(srand_(30, 255)), num_d(srand_(30, 255)));
        fxrt_world_t *ws[2] = {&world_a, &world_b};
        double lp[3] = {srand_(-4, 4), srand_(3, 6), srand_(-4, 4)};
        fxrt_light_t L = {.kind = FXRT_LIGHT_POINT, .position = vec_d(lp), .shadows = true};
        L.color = fxrt_color(num_d(srand_(128, 255)), num_d(srand_(128, 255)), num_d(srand_(128, 255)));
        for (int k = 0; k < 2; k++) {
            fxrt_world_init(ws[k], fxrt_color(num_from_int(20), num_from_int(30), num_from_int(40)));
            fxrt_object_t fl = {.kind = FXRT_PLANE, .material = {.kind = MATERIAL_LAMBERT}};
            fl.p[0] = vec3_make(NUM_ZERO, num_from_int(-2), NUM_ZERO);
            fl.p[1] = vec3_make(NUM_ZERO, NUM_ONE, NUM_ZERO);
            fl.color = fxrt_color(num_from_int(200), num_from_int(190), num_from_int(180));
            CHECK(fxrt_add(ws[k], &fl) == 0);
            fxrt_object_t o = {.color = col, .material = m};
            o.kind = box ? (k == 0 ? FXRT_PARALLELEPIPED : FXRT_BOX) : (k == 0 ? FXRT_ELLIPSOID : FXRT_SPHERE);
            o.p[0] = vec_d(c);
            if (k == 0 && !box)
                for (int a = 0; a < 3; a++) {
                    double ax[3] = {rad * r[0][a], rad * r[1][a], rad * r[2][a]};
                    o.p[1 + a] = vec_d(ax);
                }
            else if (k == 0) {
                static const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
                for (int a = 0; a < 3; a++) {
                    int i = perms[perm][a];
                    double ax[3] = {0, 0, 0};
                    ax[i] = (signs >> a & 1) ? -half[i] : half[i];
                    o.p[1 + a] = vec_d(ax);
                }
            } else if (box) {
                double lo[3], hi[3];
                for (int i = 0; i < 3; i++)
                    lo[i] = c[i] - half[i], hi[i] = c[i] + half[i];
                o.p[0] = vec_d(lo);
                o.p[1] = vec_d(hi);
            } else
                o.radius = num_d(rad);
            CHECK(fxrt_add(ws[k], &o) == 1);
            CHECK(fxrt_add_light(ws[k], &L) >= 0);
            CHECK(fxrt_set_ambient(ws[k], fxrt_color(num_d(25.5), num_d(25.5), num_d(25.5))) == FXRT_OK);
        }
        double az = srand_(-PI_D, PI_D), el = srand_(0.05, 0.9), dist = srand_(6, 9);
        double eye[3] = {dist * cos(el) * sin(az), dist * sin(el), dist * cos(el) * cos(az)}, gz[3], up[3] = {0, 1, 0};
        for (int i = 0; i < 3; i++)
            gz[i] = -eye[i];
        fxrt_view_t view;
        CHECK(fxrt_camera_perspective(&view, vec_d(eye), vec_d(gz), vec_d(up), num_from_int(40), IMG_W, IMG_H) == FXRT_OK);
        if (!render(&world_a, &view, &render_a, img_a) || !render(&world_b, &view, &render_b, img_b)) {
            CHECK_MSG(0, "scene %d: not rendered", iter);
            continue;
        }
        long bad = 0;
        for (int p = 0; p < IMG_W * IMG_H; p++) {
            int d = 0;
            for (int ch = 0; ch < 3; ch++) {
                int e = abs((int)img_a[3 * p + ch] - (int)img_b[3 * p + ch]);
                d = e > d ? e : d;
            }
            bad += d > 2;
            covered += img_b[3 * p] != 20 || img_b[3 * p + 1] != 30 || img_b[3 * p + 2] != 40;
        }
        worst = bad > worst ? bad : worst;
        CHECK_SWEEP(bad <= cap, "scene %d: %ld pixels off by more than 2 levels (cap %ld)", iter, bad, cap);
    }
    printf("  24 scenes: %s against the %s: at most %ld pixels off by more than 2 levels (cap %ld); %ld pixels not "
           "background\n",
           box ? "a parallelepiped of a box's half edges" : "an ellipsoid of a sphere's axes", box ? "box" : "sphere",
           worst, cap, covered);
    CHECK(covered > 24 * 1000);
}

/* ---- refusals ------------------------------------------------------------- */

static void test_refusals(void)
{
    color_t col = fxrt_color(num_from_int(200), num_from_int(100), num_from_int(50));
    static const struct {
        const char *what;
        double c[3], u[3], v[3], w[3];
        fxrt_err_t want;
    } cases[] = {
        {"dependent axes", {0, 0, -5}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, FXRT_ERR_AXES},
        {"a zero axis", {0, 0, -5}, {1, 0, 0}, {0, 0, 0}, {0, 0, 1}, FXRT_ERR_DIRECTION},
        {"an axis thinner than 2^-13", {0, 0, -5}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0.0001}, FXRT_ERR_AXES},
        {"det beyond 2^30", {0, 0, 0}, {2000, 0, 0}, {0, 2000, 0}, {0, 0, 2000}, FXRT_ERR_AXES},
        {"its box beyond the coordinate limit", {8000, 0, 0}, {300, 0, 0}, {0, 1, 0}, {0, 0, 1}, FXRT_ERR_COORD},
        {"a centre beyond the coordinate limit", {9000, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, FXRT_ERR_COORD},
    };
    fxrt_world_init(&world_a, col);
    for (size_t i = 0; i < 2 * sizeof cases / sizeof cases[0]; i++) {
        bool box = i % 2;
        fxrt_object_t o = {.kind = box ? FXRT_PARALLELEPIPED : FXRT_ELLIPSOID, .color = col};
        o.p[0] = vec_d(cases[i / 2].c);
        o.p[1] = vec_d(cases[i / 2].u);
        o.p[2] = vec_d(cases[i / 2].v);
        o.p[3] = vec_d(cases[i / 2].w);
        int32_t got = fxrt_add(&world_a, &o);
        CHECK_MSG(got == cases[i / 2].want && world_count(&world_a) == 0, "%s %s: %d, want %d",
                  box ? "parallelepiped" : "ellipsoid", cases[i / 2].what, (int)got, (int)cases[i / 2].want);
    }
    /* a bad colour; then the capacity */
    fxrt_object_t o = {.kind = FXRT_ELLIPSOID, .color = fxrt_color(num_from_int(300), NUM_ZERO, NUM_ZERO)};
    o.p[1] = vec3_make(NUM_ONE, NUM_ZERO, NUM_ZERO);
    o.p[2] = vec3_make(NUM_ZERO, NUM_ONE, NUM_ZERO);
    o.p[3] = vec3_make(NUM_ZERO, NUM_ZERO, NUM_ONE);
    CHECK(fxrt_add(&world_a, &o) == FXRT_ERR_COLOR && world_a.n_ellipsoids == 0);
    o.kind = FXRT_PARALLELEPIPED;
    CHECK(fxrt_add(&world_a, &o) == FXRT_ERR_COLOR && world_a.n_parallelepipeds == 0);
    o.color = col;
    o.kind = FXRT_ELLIPSOID;
    for (int i = 0; i < FXRT_MAX_ELLIPSOIDS; i++)
        CHECK(fxrt_add(&world_a, &o) == i);
    CHECK(fxrt_add(&world_a, &o) == FXRT_ERR_FULL && world_a.n_ellipsoids == FXRT_MAX_ELLIPSOIDS);
    o.kind = FXRT_PARALLELEPIPED;
    for (int i = 0; i < FXRT_MAX_PARALLELEPIPEDS; i++)
        CHECK(fxrt_add(&world_a, &o) == FXRT_MAX_ELLIPSOIDS + i);
    CHECK(fxrt_add(&world_a, &o) == FXRT_ERR_FULL && world_a.n_parallelepipeds == FXRT_MAX_PARALLELEPIPEDS);
}

int main(void)
{
    test_refusals();
    test_oracle(false);
    test_oracle(true);
    test_frames(false);
    test_frames(true);
    return check_report("test_affine_" NUM_NAME);
}
