/* test_ellipsoid: ellipsoids (core/scene/ellipsoid.c), in one number type
 * (one binary per type).
 *
 *   - the oracle: the implicit form (p - c)^T Q (p - c) = 1 with
 *     Q = (A A^T)^-1, solved in long double as a quadratic in t, its
 *     normal the gradient Q (p - c): another formula than the code's
 *     (a ray mapped into the unit sphere's space, normals by A^-T). Random
 *     ellipsoids (rotations, uneven scales, shears), random rays from
 *     outside and inside: hit or miss, t, the normal, the exit, the shadow
 *     test around t, containment, and the box around it;
 *   - frames: an ellipsoid whose axes are a sphere's (r times a random
 *     rotation) renders as the sphere kind does (another visibility path,
 *     another intersection), on a floor with a shadowing point light,
 *     lambert, phong, reflective and transparent;
 *   - every refusal of fxrt_add, each leaving the world unchanged. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "fxrt.h"

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

/* The oracle's ellipsoid: centre, Q = (A A^T)^-1, from the build's own
 * numbers (so that input rounding is not counted). */
typedef struct {
    long double c[3], q[3][3];
} oracle_t;

static void oracle_make(const geom_ellipsoid_t *e, oracle_t *o)
{
    long double a[3][3], ax[3][3], g[3][3];
    d_vec(e->c, o->c);
    d_vec(e->u, ax[0]);
    d_vec(e->v, ax[1]);
    d_vec(e->w, ax[2]);
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

/* The ray's roots t0 <= t1 and the grazing margin (the discriminant over
 * a, in units of t^2); false where it misses. */
static bool oracle_roots(const oracle_t *o, const long double p[3], const long double d[3], long double *t0,
                         long double *t1, long double *margin)
{
    long double oc[3] = {p[0] - o->c[0], p[1] - o->c[1], p[2] - o->c[2]};
    long double a = qform(o, d, d), b = qform(o, d, oc), c = qform(o, oc, oc) - 1;
    long double disc = b * b - a * c;
    *margin = disc / (a * a);
    if (disc < 0)
        return false;
    long double h = sqrtl(disc);
    *t0 = (-b - h) / a;
    *t1 = (-b + h) / a;
    return true;
}

/* The oracle's outward unit normal at p: Q (p - c), normalised. */
static void oracle_normal(const oracle_t *o, const long double p[3], long double n[3])
{
    long double v[3] = {p[0] - o->c[0], p[1] - o->c[1], p[2] - o->c[2]}, len = 0;
    for (int i = 0; i < 3; i++) {
        n[i] = o->q[i][0] * v[0] + o->q[i][1] * v[1] + o->q[i][2] * v[2];
        len += n[i] * n[i];
    }
    for (int i = 0; i < 3; i++)
        n[i] /= sqrtl(len);
}

/* A random ellipsoid: A = R1 diag(s) R2 (a rotation, uneven scales in
 * [0.08, 3], and a second rotation: axes not orthogonal in general), or
 * every entry random (a shear) with a condition that the checks keep. */
static bool random_ellipsoid(geom_ellipsoid_t *e, double axes[3][3], double c[3])
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
    return geom_ellipsoid_make(e, vec_d(c), vec_d(axes[0]), vec_d(axes[1]), vec_d(axes[2]), col, 0);
}

static void test_oracle(void)
{
    /* Tolerances: t within tol_t (1 + t), the normal within tol_n
     * (1 - cos of the angle), where the ray passes at least 10^-3 (in t^2)
     * from grazing. Q16.16 holds the local ray to 2^-16 of a radius at
     * up to 150 radii (a thin axis of 0.08 seen from 12 away), and A^-T
     * turns that error by up to its condition (37): its worst normal is
     * 1.3e-4 (0.9 degrees; float 1.4e-7, double 2.6e-16). */
    const long double tol_t = NUM_EXACT ? 3e-3L : (sizeof(num_t) == 4 ? 2e-5L : 1e-12L);
    const long double tol_n = NUM_EXACT ? 3e-4L : (sizeof(num_t) == 4 ? 1e-6L : 1e-14L);
    const long double graze = 1e-3L;
    long hits = 0, misses = 0, inside = 0, wrong = 0, made = 0, contained = 0;
    long double worst_t = 0, worst_n = 0;
    for (int iter = 0; iter < 600; iter++) {
        geom_ellipsoid_t e;
        double axes[3][3], c[3];
        if (!random_ellipsoid(&e, axes, c))
            continue; /* (a shear too flat or thin: refused, test_refusals) */
        made++;
        oracle_t o;
        oracle_make(&e, &o);
        vec3_t lo, hi;
        geom_ellipsoid_bounds(&e, &lo, &hi);
        long double blo[3], bhi[3];
        d_vec(lo, blo);
        d_vec(hi, bhi);
        for (int k = 0; k < 40; k++) {
            /* a ray from a random point (inside for some: near the centre)
             * towards a random point near the ellipsoid */
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
            long double po[3], pd[3], t0, t1, margin;
            d_vec(ray.o, po);
            d_vec(ray.d, pd);
            bool met = oracle_roots(&o, po, pd, &t0, &t1, &margin);
            bool in = met && t0 < 0 && t1 > 0;
            num_t t;
            bool hit = geom_ellipsoid_hit(&e, &ray, &t);
            if (fabsl(margin) < graze) /* grazing: either answer */
                continue;
            long double want = !met ? -1 : (t0 > 0 ? t0 : t1);
            if (!met || want <= 0) {
                misses++;
                CHECK_SWEEP(!hit, "iter %d ray %d: a miss hit at t %g", iter, k, d_num(t));
                wrong += hit;
                continue;
            }
            hits++;
            inside += in;
            long double et = fabsl(d_num(t) - want) / (1 + want);
            worst_t = et > worst_t ? et : worst_t;
            CHECK_SWEEP(hit && et <= tol_t, "iter %d ray %d: t %g, oracle %Lg", iter, k, hit ? d_num(t) : -1.0, want);
            wrong += !hit || et > tol_t;
            /* the surface: the same t, the oracle's normal there */
            vec3_t n;
            num_t ts;
            if (in) {
                CHECK_SWEEP(geom_ellipsoid_contains(&e, ray.o) || margin < 0.05L, "iter %d: origin inside", iter);
                CHECK(geom_ellipsoid_exit(&e, &ray, &ts, &n));
            } else {
                geom_ellipsoid_surface(&e, &ray, &ts, &n);
            }
            long double hp[3], on[3], gn[3];
            for (int i = 0; i < 3; i++)
                hp[i] = po[i] + want * pd[i];
            oracle_normal(&o, hp, on);
            d_vec(n, gn);
            long double dot = on[0] * gn[0] + on[1] * gn[1] + on[2] * gn[2];
            long double en = 1 - dot;
            worst_n = en > worst_n ? en : worst_n;
            CHECK_SWEEP(fabsl(d_num(ts) - want) <= tol_t * (1 + want) && en <= tol_n,
                        "iter %d ray %d: surface t %g (oracle %Lg), 1 - n.n' %Lg", iter, k, d_num(ts), want, en);
            /* the shadow test around t (where it is not beyond Q16.16's t) */
            if (want < 1000) {
                num_t below = num_d((double)(want * 0.98L - 2e-3L)), above = num_d((double)(want * 1.02L + 2e-3L));
                CHECK_SWEEP(!geom_ellipsoid_occludes(&e, &ray, below) && geom_ellipsoid_occludes(&e, &ray, above),
                            "iter %d ray %d: occludes around t %Lg", iter, k, want);
            }
            /* the box holds the point met */
            for (int i = 0; i < 3; i++)
                CHECK_SWEEP(hp[i] >= blo[i] - 1e-4L && hp[i] <= bhi[i] + 1e-4L, "iter %d: point beyond its box", iter);
        }
        /* containment of points well inside or outside (f below 0.95 or
         * above 1.05 in the implicit form) */
        for (int k = 0; k < 20; k++) {
            double p[3];
            for (int i = 0; i < 3; i++)
                p[i] = c[i] + 1.5 * (axes[0][i] * srand_(-1, 1) + axes[1][i] * srand_(-1, 1) + axes[2][i] * srand_(-1, 1));
            vec3_t pv = vec_d(p);
            long double pp[3], v[3];
            d_vec(pv, pp);
            for (int i = 0; i < 3; i++)
                v[i] = pp[i] - o.c[i];
            long double fv = qform(&o, v, v);
            if (fabsl(fv - 1) < 0.05L)
                continue;
            bool want = fv < 1;
            contained += want;
            CHECK_SWEEP(geom_ellipsoid_contains(&e, pv) == want, "iter %d: contains, implicit %Lg", iter, fv);
        }
    }
    printf("  %ld ellipsoids: %ld hits (%ld from inside), %ld misses, %ld points inside; worst t %.3Lg, "
           "worst 1 - n.n' %.3Lg\n",
           made, hits, inside, misses, contained, worst_t, worst_n);
    CHECK_MSG(wrong == 0, "%ld rays wrong", wrong);
    CHECK_MSG(made >= 500 && hits >= 5000 && misses >= 2000 && inside >= 500, "too few cases: %ld, %ld, %ld, %ld",
              made, hits, misses, inside);
}

/* ---- frames ---------------------------------------------------------------- */

static fxrt_world_t world_a, world_b;
static fxrt_render_t render_a, render_b;
static uint8_t img_a[IMG_W * IMG_H * 3], img_b[IMG_W * IMG_H * 3];

static bool render(const fxrt_world_t *w, const fxrt_view_t *v, fxrt_render_t *r, uint8_t *img)
{
    if (fxrt_render_setup(r, w, v) != FXRT_OK)
        return false;
    for (int32_t row = 0; row < IMG_H; row++)
        if (fxrt_render_row(r, row, img + (size_t)row * IMG_W * 3, IMG_W * 3) != FXRT_OK)
            return false;
    return true;
}

static void test_frames(void)
{
    /* Allowed: pixels off by more than 2 levels per scene of 6,912 (edges
     * that rounding moves by a pixel). */
    const long cap = NUM_EXACT ? 12 : 3;
    long worst = 0, covered = 0;
    for (int iter = 0; iter < 24; iter++) {
        double c[3] = {srand_(-1, 1), srand_(-0.5, 1), srand_(-1, 1)}, rad = srand_(0.4, 1.6), r[3][3];
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
            fxrt_object_t o = {.kind = k == 0 ? FXRT_ELLIPSOID : FXRT_SPHERE, .color = col, .material = m};
            o.p[0] = vec_d(c);
            if (k == 0)
                for (int a = 0; a < 3; a++) {
                    double ax[3] = {rad * r[0][a], rad * r[1][a], rad * r[2][a]};
                    o.p[1 + a] = vec_d(ax);
                }
            else
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
    printf("  24 scenes: an ellipsoid of a sphere's axes against the sphere: at most %ld pixels off by more than 2 "
           "levels (cap %ld); %ld pixels not background\n",
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
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        fxrt_object_t o = {.kind = FXRT_ELLIPSOID, .color = col};
        o.p[0] = vec_d(cases[i].c);
        o.p[1] = vec_d(cases[i].u);
        o.p[2] = vec_d(cases[i].v);
        o.p[3] = vec_d(cases[i].w);
        int32_t got = fxrt_add(&world_a, &o);
        CHECK_MSG(got == cases[i].want && world_a.n_ellipsoids == 0, "%s: %d, want %d", cases[i].what, (int)got,
                  (int)cases[i].want);
    }
    /* a bad colour; then the capacity */
    fxrt_object_t o = {.kind = FXRT_ELLIPSOID, .color = fxrt_color(num_from_int(300), NUM_ZERO, NUM_ZERO)};
    o.p[1] = vec3_make(NUM_ONE, NUM_ZERO, NUM_ZERO);
    o.p[2] = vec3_make(NUM_ZERO, NUM_ONE, NUM_ZERO);
    o.p[3] = vec3_make(NUM_ZERO, NUM_ZERO, NUM_ONE);
    CHECK(fxrt_add(&world_a, &o) == FXRT_ERR_COLOR && world_a.n_ellipsoids == 0);
    o.color = col;
    for (int i = 0; i < FXRT_MAX_ELLIPSOIDS; i++)
        CHECK(fxrt_add(&world_a, &o) == i);
    CHECK(fxrt_add(&world_a, &o) == FXRT_ERR_FULL && world_a.n_ellipsoids == FXRT_MAX_ELLIPSOIDS);
}

int main(void)
{
    test_refusals();
    test_oracle();
    test_frames();
    return check_report("test_ellipsoid_" NUM_NAME);
}
