/* The number-generic core (camera, ray, geometry, world, render row)
 * against analytic values. Built once per number type (q16, float, double)
 * from this one file, so every check runs in all three arithmetics.
 *
 * Expected values are computed in double from the inputs as the build
 * represents them (D(N(x))), so input rounding is not counted as error.
 * Tolerances are in units of the build's precision (UNIT): 2^-16 for
 * Q16.16, 2.5e-6 for float, 2.5e-13 for double; "k units" below means
 * k * UNIT, relative to max(1, |expected|) unless a check says absolute.
 * Random sweeps use a fixed-seed xorshift, so a failure reproduces. */
#include <math.h>
#include <string.h>
#include <stdio.h>
#include <stdlib.h>

#include "../core/frame/render.h"
#include "../core/vis/render_int.h"
#include "add.h"
#include "check.h"

#if FXRT_NUMBER == FXRT_Q16
#define UNIT (1.0 / 65536.0)
#elif FXRT_NUMBER == FXRT_FLOAT
#define UNIT 2.5e-6
#else
#define UNIT 2.5e-13
#endif

#define PI 3.14159265358979323846

/* ---- numbers ------------------------------------------------------------ */

/* A run-time double as num_t (NUM() is for constants only). */
static num_t N(double x)
{
#if FXRT_NUMBER == FXRT_Q16
    double r = round(x * 65536.0);
    if (r >= 2147483647.0)
        return FX_MAX;
    if (r <= -2147483648.0)
        return FX_MIN;
    return (num_t)r;
#else
    return (num_t)x;
#endif
}

static double D(num_t a)
{
#if FXRT_NUMBER == FXRT_Q16
    return (double)a / 65536.0;
#else
    return (double)a;
#endif
}

/* Within k units, relative to max(1, |want|). */
static bool near_rel(double got, double want, double k)
{
    return fabs(got - want) <= k * UNIT * fmax(1.0, fabs(want));
}

/* Within k LSB absolute in Q16.16 (for results whose computation involves
 * no rounded direction); as near_rel in float and double. */
static bool near_abs(double got, double want, double k)
{
#if FXRT_NUMBER == FXRT_Q16
    return fabs(got - want) <= k * UNIT;
#else
    return near_rel(got, want, k);
#endif
}

#define CHECK_REL(got, want, k)                                                         \
    do {                                                                                \
        double g_ = D(got), w_ = (want);                                                \
        CHECK_MSG(near_rel(g_, w_, (k)), "%s = %.10g, want %.10g", #got, g_, w_);       \
    } while (0)
#define CHECK_ABS(got, want, k)                                                         \
    do {                                                                                \
        double g_ = D(got), w_ = (want);                                                \
        CHECK_MSG(near_abs(g_, w_, (k)), "%s = %.10g, want %.10g", #got, g_, w_);       \
    } while (0)

/* ---- double vectors ----------------------------------------------------- */

typedef struct {
    double x, y, z;
} dv_t;

static dv_t dv(double x, double y, double z)
{
    dv_t v = {x, y, z};
    return v;
}
static dv_t dadd(dv_t a, dv_t b) { return dv(a.x + b.x, a.y + b.y, a.z + b.z); }
static dv_t dsub(dv_t a, dv_t b) { return dv(a.x - b.x, a.y - b.y, a.z - b.z); }
static dv_t dscale(dv_t a, double s) { return dv(a.x * s, a.y * s, a.z * s); }
static double ddot(dv_t a, dv_t b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static dv_t dcross(dv_t a, dv_t b)
{
    return dv(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static double dlen(dv_t a) { return sqrt(ddot(a, a)); }
static dv_t dnorm(dv_t a) { return dscale(a, 1.0 / dlen(a)); }

static vec3_t V(dv_t a) { return vec3_make(N(a.x), N(a.y), N(a.z)); }
static vec3_t V3(double x, double y, double z) { return vec3_make(N(x), N(y), N(z)); }
static dv_t DV(vec3_t a) { return dv(D(a.x), D(a.y), D(a.z)); }
/* The value the build actually holds for a double vector. */
static dv_t RV(dv_t a) { return DV(V(a)); }

static bool dv_near_abs(dv_t got, dv_t want, double k)
{
    return near_abs(got.x, want.x, k) && near_abs(got.y, want.y, k) && near_abs(got.z, want.z, k);
}

#define CHECK_VEC_ABS(got, want, k)                                                      \
    do {                                                                                 \
        dv_t g_ = DV(got), w_ = (want);                                                  \
        CHECK_MSG(dv_near_abs(g_, w_, (k)), "%s = (%.9g %.9g %.9g), want (%.9g %.9g %.9g)", \
                  #got, g_.x, g_.y, g_.z, w_.x, w_.y, w_.z);                             \
    } while (0)

static bool vec3_eq(vec3_t a, vec3_t b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

/* A ray from o towards direction d (normalised in double, then rounded). */
static ray_t mkray(dv_t o, dv_t d)
{
    ray_t r;
    r.o = V(o);
    r.d = V(dnorm(d));
    return r;
}

/* A colour from intensity fractions, stored as the scene loader does (1/255 units). */
static color_t col(double r, double g, double b) { return color_make(N(255 * r), N(255 * g), N(255 * b)); }

static uint64_t rng_state = 0x2545F4914F6CDD1Dull;
static uint64_t rng(void) { return check_rng_next(&rng_state); }
/* Uniform in [lo, hi). */
static double urand(double lo, double hi)
{
    return lo + (hi - lo) * (double)(rng() >> 11) * (1.0 / 9007199254740992.0);
}
static dv_t urand_v(double lo, double hi) { return dv(urand(lo, hi), urand(lo, hi), urand(lo, hi)); }

/* ---- 1. camera ---------------------------------------------------------- */

typedef struct {
    cam_kind_t kind;
    dv_t e, g, up;
    double fov, scale;
    int32_t w, h;
} cam_case_t;

/* The exact basis of a camera. */
static void ideal_basis(dv_t g, dv_t up, dv_t *u, dv_t *v, dv_t *w)
{
    *w = dnorm(dscale(g, -1.0));
    *u = dnorm(dcross(up, *w));
    *v = dcross(*w, *u);
}

static void test_cam_basis_seed(void)
{
    cam_t c;
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, V3(0, 0, 0), V3(0, 0, -1), V3(0, 1, 0), NUM(90), NUM_ZERO,
                    5, 3) == CAM_OK);
    CHECK_VEC_ABS(c.u, dv(1, 0, 0), 1);
    CHECK_VEC_ABS(c.v, dv(0, 1, 0), 1);
    CHECK_VEC_ABS(c.w, dv(0, 0, 1), 1);
    CHECK(c.width == 5 && c.height == 3 && c.kind == CAM_PERSPECTIVE);

    /* Centre ray of an odd-sized image: straight along -z from e. */
    ray_t r;
    cam_ray(&c, 2, 1, &r);
    CHECK_VEC_ABS(r.o, dv(0, 0, 0), 0);
    CHECK_VEC_ABS(r.d, dv(0, 0, -1), 1);

    /* A longer gaze and up give the same basis. */
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, V3(1, 2, 3), V3(0, 0, -7), V3(0, 5, 0), NUM(45), NUM_ZERO,
                    7, 5) == CAM_OK);
    CHECK_VEC_ABS(c.u, dv(1, 0, 0), 1);
    CHECK_VEC_ABS(c.v, dv(0, 1, 0), 1);
    CHECK_VEC_ABS(c.w, dv(0, 0, 1), 1);
    cam_ray(&c, 3, 2, &r);
    CHECK_VEC_ABS(r.o, dv(1, 2, 3), 0);
    CHECK_VEC_ABS(r.d, dv(0, 0, -1), 1);

    /* An up that is not perpendicular to the gaze is made so. */
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, V3(0, 0, 0), V3(0, 0, -1), V3(0, 1, 1), NUM(90), NUM_ZERO,
                    5, 3) == CAM_OK);
    CHECK_VEC_ABS(c.u, dv(1, 0, 0), 1);
    CHECK_VEC_ABS(c.v, dv(0, 1, 0), 1);
}

/* Figure 7 of the seed report: e = (3,3,3), g = (-3,-3,-3), up = y. */
static void test_cam_basis_fig7(void)
{
    cam_t c;
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, V3(3, 3, 3), V3(-3, -3, -3), V3(0, 1, 0), NUM(45), NUM_ZERO,
                    640, 430) == CAM_OK);
    double s3 = 1 / sqrt(3.0), s2 = 1 / sqrt(2.0), s6 = 1 / sqrt(6.0);
    CHECK_VEC_ABS(c.w, dv(s3, s3, s3), 1);
    CHECK_VEC_ABS(c.u, dv(s2, 0, -s2), 2);
    CHECK_VEC_ABS(c.v, dv(-s6, 2 * s6, -s6), 2);
    dv_t u = DV(c.u), v = DV(c.v), w = DV(c.w);
    CHECK(c.u.y == NUM_ZERO); /* u = up x w has no y component, exactly */
    CHECK(v.y > 0);           /* v points up-ish */
    CHECK_MSG(near_abs(ddot(u, u), 1, 4) && near_abs(ddot(v, v), 1, 4) && near_abs(ddot(w, w), 1, 4),
              "|u|^2 %.9g |v|^2 %.9g |w|^2 %.9g", ddot(u, u), ddot(v, v), ddot(w, w));
    CHECK_MSG(near_abs(ddot(u, v), 0, 4) && near_abs(ddot(u, w), 0, 4) && near_abs(ddot(v, w), 0, 4),
              "u.v %.3g u.w %.3g v.w %.3g", ddot(u, v), ddot(u, w), ddot(v, w));
    /* Right-handed: u x v = w. */
    CHECK_MSG(dv_near_abs(dcross(u, v), w, 6), "u x v != w");
}

/* 0, s, 2s, ... and always n - 1, then n. */
static int32_t next_idx(int32_t i, int32_t n, int32_t s)
{
    if (i >= n - 1)
        return n;
    return i + s < n ? i + s : n - 1;
}

/* Every pixel's ray (or a stride of them for big images) against the
 * formulas of the conventions. */
static void check_cam_case(const cam_case_t *cc)
{
    cam_t c;
    cam_err_t err = cam_setup(&c, cc->kind, V(cc->e), V(cc->g), V(cc->up), N(cc->fov), N(cc->scale),
                              cc->w, cc->h);
    CHECK_MSG(err == CAM_OK, "%dx%d kind %d: %s", (int)cc->w, (int)cc->h, (int)cc->kind,
              cam_strerror(err));
    if (err != CAM_OK)
        return;
    dv_t u, v, w;
    ideal_basis(RV(cc->g), RV(cc->up), &u, &v, &w);
    CHECK_VEC_ABS(c.u, u, 2);
    CHECK_VEC_ABS(c.v, v, 2);
    CHECK_VEC_ABS(c.w, w, 2);
    dv_t e = RV(cc->e);
    double fov = D(N(cc->fov)), s = D(N(cc->scale));
    double A = (double)cc->w / cc->h;
    /* Origin tolerance: rounding of the offsets and of u, v times their size. */
    double ktol = 4 + 2 * (A + 1) * s;
    int32_t sx = cc->w > 64 ? cc->w / 16 : 1, sy = cc->h > 64 ? cc->h / 16 : 1;
    long bad = 0, n = 0;
    for (int32_t y = 0; y < cc->h; y = next_idx(y, cc->h, sy)) {
        for (int32_t x = 0; x < cc->w; x = next_idx(x, cc->w, sx)) {
            ray_t r;
            cam_ray(&c, x, y, &r);
            double ox = x - (cc->w - 1) / 2.0, oy = y - (cc->h - 1) / 2.0;
            dv_t wo, wd;
            bool ok;
            if (cc->kind == CAM_PERSPECTIVE) {
                double f = (cc->h / 2.0) / tan(fov / 2 * PI / 180);
                wo = e;
                wd = dnorm(dadd(dscale(w, -f), dadd(dscale(u, ox), dscale(v, oy))));
                ok = vec3_eq(r.o, V(e)) && dv_near_abs(DV(r.d), wd, 4);
            } else {
                double fu = cc->w > 1 ? A * s * ox / (cc->w - 1) : 0;
                double fv = cc->h > 1 ? s * oy / (cc->h - 1) : 0;
                wo = dadd(e, dadd(dscale(u, fu), dscale(v, fv)));
                wd = dscale(w, -1);
                ok = dv_near_abs(DV(r.o), wo, ktol) && vec3_eq(r.d, vec3_neg(c.w));
            }
            n++;
            if (!ok) {
                bad++;
                dv_t go = DV(r.o), gd = DV(r.d);
                CHECK_SWEEP(ok, "%dx%d pixel (%d,%d): o (%.7g %.7g %.7g) want (%.7g %.7g %.7g), "
                            "d (%.7g %.7g %.7g) want (%.7g %.7g %.7g)",
                            (int)cc->w, (int)cc->h, (int)x, (int)y, go.x, go.y, go.z, wo.x, wo.y, wo.z,
                            gd.x, gd.y, gd.z, wd.x, wd.y, wd.z);
            }
        }
    }
    CHECK_MSG(bad == 0 && n > 0, "%ld of %ld pixels wrong", bad, n);
}

static void test_cam_pixels(void)
{
    static const cam_case_t cases[] = {
        {CAM_PERSPECTIVE, {0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 90, 0, 8, 6},
        {CAM_PERSPECTIVE, {0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 45, 0, 5, 3},
        {CAM_PERSPECTIVE, {0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 1, 0, 64, 48},
        {CAM_PERSPECTIVE, {0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 170, 0, 9, 70},
        {CAM_PERSPECTIVE, {0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 179, 0, 5, 120},
        {CAM_PERSPECTIVE, {0.5, -1, 2}, {0.3, -1, 0.2}, {0.2, -0.99, 0.2}, 50, 0, 40, 30},
        {CAM_PERSPECTIVE, {0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 45, 0, 640, 430},
        {CAM_PERSPECTIVE, {3, 3, 3}, {-3, -3, -3}, {0, 1, 0}, 45, 0, 640, 430},
        {CAM_PERSPECTIVE, {-2, 1, 5}, {1, -0.5, -2}, {0.1, 1, 0.2}, 60, 0, 33, 17},
        {CAM_PERSPECTIVE, {0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 90, 0, 4096, 4096},
        {CAM_PERSPECTIVE, {0, 0, 0}, {1, 0, 0}, {0, 0, 1}, 15, 0, 4096, 4096},
        {CAM_PERSPECTIVE, {0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60, 0, 1, 1},
        {CAM_ORTHOGRAPHIC, {1, 2, 3}, {0, 0, -1}, {0, 1, 0}, 0, 3, 8, 6},
        {CAM_ORTHOGRAPHIC, {0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 0, 4, 640, 430},
        {CAM_ORTHOGRAPHIC, {3, 3, 3}, {-3, -3, -3}, {0, 1, 0}, 0, 2.5, 31, 17},
        {CAM_ORTHOGRAPHIC, {0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 0, 4, 1, 5},
        {CAM_ORTHOGRAPHIC, {0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 0, 4, 5, 1},
        {CAM_ORTHOGRAPHIC, {-1, 0.5, 7}, {0.3, -0.2, -1}, {0, 1, 0}, 0, 4096, 4096, 4096},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        check_cam_case(&cases[i]);
}

/* Q16.16: cam_ray's 32-bit path (cam_t.small) gives the rays of its
 * 64-bit one, pixel for pixel, on cameras at and near the bound; the
 * bound is what cam_setup says it is. */
static void test_cam_small(void)
{
#if FXRT_NUMBER == FXRT_Q16
    static const struct {
        double fov;
        int32_t w, h;
        double gx, gy, gz;
    } cases[] = {
        {45, 160, 120, -1, -1, -1}, {90, 640, 480, 0, 0, -1}, {1, 4096, 64, 0.3, -0.2, -1},
        {0.23, 4096, 64, 0, 0, -1}, {0.3, 2048, 64, 1, 2, 3}, {179, 4096, 4096, -0.5, 0.7, 0.1}, {60, 1, 1, 0, 1, 0.01},
        {14.3, 4096, 4096, 0.125, 0.125, -1}, {14.3, 4096, 4096, 0.1, -0.15, -1},
    };
    int small = 0, big = 0;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        cam_t c;
        cam_err_t err = cam_setup(&c, CAM_PERSPECTIVE, V3(0, 0, 0), V3(cases[i].gx, cases[i].gy, cases[i].gz),
                                  V3(0, 1, 0), N(cases[i].fov), NUM_ZERO, cases[i].w, cases[i].h);
        if (err != CAM_OK)
            continue;
        int64_t reach = 0;
        const fx_t *f = &c.fwd.x, *u = &c.u.x, *v = &c.v.x;
        for (int k = 0; k < 3; k++) {
            int64_t r = llabs((int64_t)f[k]) + llabs((int64_t)u[k]) * (c.width - 1) + llabs((int64_t)v[k]) * (c.height - 1);
            reach = r > reach ? r : reach;
        }
        CHECK_MSG(c.small == (reach <= INT32_MAX), "camera %zu: small %d, widest reach %lld", i, (int)c.small,
                  (long long)reach);
        if (!c.small) {
            big++;
            continue;
        }
        small++;
        cam_t wide = c;
        wide.small = false;
        int bad = 0;
        for (int32_t y = 0; y < c.height; y += (c.height > 64 ? 7 : 1))
            for (int32_t x = 0; x < c.width; x += (c.width > 64 ? 5 : 1)) {
                ray_t a, b;
                cam_ray(&c, x, y, &a);
                cam_ray(&wide, x, y, &b);
                bad += memcmp(&a, &b, sizeof a) != 0;
            }
        CHECK_MSG(bad == 0, "camera %zu: %d rays differ between the 32- and 64-bit paths", i, bad);
    }
    CHECK_MSG(small >= 3 && big >= 1, "the cases reach both paths (%d small, %d not)", small, big);
#endif
}

/* The shading pass's rays by rows (cam_row, cam_row_ray) are cam_ray_raw's,
 * byte for byte, in every number type: random cameras over the whole
 * domain (eye within the coordinate limit, any gaze and up, fov in (0,
 * 180), sizes 1 to 4096, both kinds), the pixels of a sample of rows; in
 * Q16.16 also cameras on both sides of cam_t.small's bound (the row form
 * only where it holds, cam_ray_raw's 64-bit path beyond). */
/* Row y of camera c, every step-th pixel: cam_row_ray against cam_ray_raw;
 * counts the row's path (*direct or *other) and returns the rays that
 * differ (the first few reported, named by `what` and case i). */
static int cam_rows_diff(const cam_t *c, int32_t y, int32_t step, const char *what, int i, int *direct, int *other)
{
    cam_row_t row;
    ray_t a; /* one ray for the row, as the shading pass keeps it */
    int bad = 0;
    memset(&a, 0, sizeof a);
    cam_row(c, y, &row, &a);
    *direct += row.direct;
    *other += !row.direct;
    for (int32_t x = 0; x < c->width; x += step) {
        ray_t b;
        memset(&b, 0, sizeof b);
        cam_row_ray(c, &row, x, &a);
        cam_ray_raw(c, x, y, &b);
        if (memcmp(&a, &b, sizeof a) != 0 && bad++ < 3)
            CHECK_MSG(0, "%s %d (%dx%d, %s): pixel (%d, %d): the row's ray differs from cam_ray_raw's", what, i,
                      (int)c->width, (int)c->height, c->kind == CAM_PERSPECTIVE ? "perspective" : "orthographic",
                      (int)x, (int)y);
    }
    return bad;
}

static void test_cam_rows(void)
{
    int cams = 0, direct = 0, other = 0, bad = 0;
    for (int i = 0; i < 400; i++) {
        cam_t c;
        double lim = FXRT_COORD_LIMIT * 0.99;
        dv_t e = i % 4 == 0 ? urand_v(-lim, lim) : urand_v(-20, 20);
        dv_t g = urand_v(-1, 1), up = urand_v(-1, 1);
        double fov = i % 5 == 0 ? urand(0.2, 179.8) : urand(20, 120);
        int32_t w = i % 7 == 0 ? 1 + (int32_t)(rng() % 4096) : 1 + (int32_t)(rng() % 320);
        int32_t h = i % 11 == 0 ? 1 + (int32_t)(rng() % 4096) : 1 + (int32_t)(rng() % 240);
        cam_kind_t kind = i % 6 == 5 ? CAM_ORTHOGRAPHIC : CAM_PERSPECTIVE;
        if (cam_setup(&c, kind, V(e), V(dscale(g, urand(0.01, 100))), V(up), N(fov), N(urand(0.5, 50)), w, h) != CAM_OK)
            continue;
        cams++;
        for (int32_t k = 0; k < 6; k++)
            bad += cam_rows_diff(&c, k < 2 ? k * (h - 1) : (int32_t)(rng() % (uint64_t)h), 1 + w / 97, "camera", i,
                                 &direct, &other);
    }
#if FXRT_NUMBER == FXRT_Q16
    /* Near the bound: 4096 x 4096 pixels, H cot(fov/2) close to the 32,767
     * cam_setup allows, a gaze a few degrees off the z axis: per axis the
     * reach |fwd| + (W - 1) |u| + (H - 1) |v| falls on either side of 2^31 LSB. */
    int near_small = 0, near_big = 0;
    for (int i = 0; i < 40; i++) {
        cam_t c;
        if (cam_setup(&c, CAM_PERSPECTIVE, V3(0, 0, 0), V3(urand(-0.2, 0.2), urand(-0.2, 0.2), -1), V3(0.3, 1, 0.1),
                      N(urand(14.25, 14.8)), NUM_ZERO, 4096, 4096) != CAM_OK)
            continue;
        near_small += c.small;
        near_big += !c.small;
        for (int32_t y = 0; y < c.height; y += 1 + c.height / 5) {
            int d = 0, o = 0;
            bad += cam_rows_diff(&c, y, 61, "camera near the bound", i, &d, &o);
            CHECK_MSG(d == c.small, "camera near the bound %d: row %d by the row form %d, small %d", i, (int)y, d,
                      (int)c.small);
            direct += d;
            other += o;
        }
    }
    CHECK_MSG(near_small > 0 && near_big > 0, "cameras near the bound on both sides: %d small, %d not", near_small,
              near_big);
#endif
    CHECK_MSG(bad == 0, "%d rays by rows differ from cam_ray_raw's", bad);
    CHECK_MSG(cams >= 300, "random cameras accepted: %d of 400", cams);
    CHECK_MSG(direct > 0 && other > 0, "both paths taken: %d rows by the row form, %d by cam_ray_raw", direct, other);
}

/* Angles of the perspective rays, row order, mirror symmetry. */
static void test_cam_perspective_angles(void)
{
    static const double fovs[] = {10, 30, 45, 60, 90, 120, 150};
    static const int32_t hs[] = {3, 6, 7, 430};
    for (size_t i = 0; i < sizeof fovs / sizeof fovs[0]; i++) {
        for (size_t j = 0; j < sizeof hs / sizeof hs[0]; j++) {
            int32_t W = 5, H = hs[j];
            double a = D(N(fovs[i]));
            cam_t c;
            cam_err_t err = cam_setup(&c, CAM_PERSPECTIVE, V3(0, 0, 0), V3(0, 0, -1), V3(0, 1, 0), N(fovs[i]),
                                      NUM_ZERO, W, H);
            if (H / tan(a / 2 * PI / 180) < 1) { /* the grid nearer than half a pixel */
                CHECK_MSG(err == CAM_ERR_WIDE, "fov %g H %d: %s", a, (int)H, cam_strerror(err));
                continue;
            }
            CHECK(err == CAM_OK);
            /* Middle of the top row: angle atan(((H-1)/2) / ((H/2) / tan(a/2))) with -w. */
            ray_t top, bottom;
            cam_ray(&c, 2, H - 1, &top);
            cam_ray(&c, 2, 0, &bottom);
            double want = atan(((H - 1) / 2.0) / ((H / 2.0) / tan(a / 2 * PI / 180)));
            dv_t d = DV(top.d);
            double got = atan2(sqrt(d.x * d.x + d.y * d.y), -d.z);
            CHECK_MSG(near_abs(got, want, 4), "fov %g H %d: top angle %.9g want %.9g", a, (int)H, got,
                      want);
            CHECK_MSG(top.d.y > NUM_ZERO && top.d.x == NUM_ZERO, "fov %g H %d: top row d.y %.9g", a,
                      (int)H, D(top.d.y));
            /* y = 0 is the bottom row: it looks down. */
            CHECK_MSG(bottom.d.y < NUM_ZERO, "fov %g H %d: bottom row d.y %.9g", a, (int)H,
                      D(bottom.d.y));
            /* Exact mirror images: up/down and left/right. */
            CHECK(bottom.d.y == num_neg(top.d.y) && bottom.d.z == top.d.z);
            ray_t l, rr;
            cam_ray(&c, 0, 0, &l);
            cam_ray(&c, W - 1, 0, &rr);
            CHECK(l.d.x < NUM_ZERO && rr.d.x > NUM_ZERO && l.d.x == num_neg(rr.d.x) && l.d.y == rr.d.y
                  && l.d.z == rr.d.z);
            /* Corner ray: half-diagonal angle. */
            cam_ray(&c, W - 1, H - 1, &rr);
            double f = (H / 2.0) / tan(a / 2 * PI / 180);
            want = atan(sqrt(2.0 * 2.0 + ((H - 1) / 2.0) * ((H - 1) / 2.0)) / f);
            d = DV(rr.d);
            got = atan2(sqrt(d.x * d.x + d.y * d.y), -d.z);
            CHECK_MSG(near_abs(got, want, 4), "fov %g H %d: corner angle %.9g want %.9g", a, (int)H,
                      got, want);
        }
    }
}

static void test_cam_orthographic(void)
{
    cam_t c;
    /* 8x6, scale 3: a = 4/3, corners at e + (+-2) u + (+-1.5) v. */
    CHECK(cam_setup(&c, CAM_ORTHOGRAPHIC, V3(1, 2, 3), V3(0, 0, -1), V3(0, 1, 0), NUM_ZERO, NUM(3),
                    8, 6) == CAM_OK);
    ray_t r;
    cam_ray(&c, 0, 0, &r);
    CHECK_VEC_ABS(r.o, dv(-1, 0.5, 3), 1);
    CHECK_VEC_ABS(r.d, dv(0, 0, -1), 0);
    cam_ray(&c, 7, 0, &r);
    CHECK_VEC_ABS(r.o, dv(3, 0.5, 3), 1);
    cam_ray(&c, 0, 5, &r);
    CHECK_VEC_ABS(r.o, dv(-1, 3.5, 3), 1);
    cam_ray(&c, 7, 5, &r);
    CHECK_VEC_ABS(r.o, dv(3, 3.5, 3), 1);
    CHECK_VEC_ABS(r.d, dv(0, 0, -1), 0);

    /* 1x1: its single ray starts at e. */
    CHECK(cam_setup(&c, CAM_ORTHOGRAPHIC, V3(1.25, -2, 3.5), V3(1, 2, 3), V3(0, 1, 0), NUM_ZERO,
                    NUM(10), 1, 1) == CAM_OK);
    cam_ray(&c, 0, 0, &r);
    CHECK(vec3_eq(r.o, V3(1.25, -2, 3.5)));
    CHECK(vec3_eq(r.d, vec3_neg(c.w)));

    /* 1x1 perspective: along the gaze. */
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, V3(0, 0, 0), V3(0, 0, -2), V3(0, 1, 0), NUM(60), NUM_ZERO,
                    1, 1) == CAM_OK);
    cam_ray(&c, 0, 0, &r);
    CHECK_VEC_ABS(r.d, dv(0, 0, -1), 1);
}

static void test_cam_errors(void)
{
    cam_t c;
    vec3_t o = V3(0, 0, 0), g = V3(0, 0, -1), up = V3(0, 1, 0);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, V3(0, 0, 0), up, NUM(45), NUM_ZERO, 8, 6) == CAM_ERR_GAZE);
    CHECK(cam_setup(&c, CAM_ORTHOGRAPHIC, o, V3(0, 0, 0), up, NUM_ZERO, NUM(1), 8, 6) == CAM_ERR_GAZE);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, V3(0, 0, 3), NUM(45), NUM_ZERO, 8, 6) == CAM_ERR_UP);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, V3(0, 0, -0.5), NUM(45), NUM_ZERO, 8, 6) == CAM_ERR_UP);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, V3(0, 0, 0), NUM(45), NUM_ZERO, 8, 6) == CAM_ERR_UP);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, V3(-3, -3, -3), V3(2, 2, 2), NUM(45), NUM_ZERO, 8, 6)
          == CAM_ERR_UP);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, up, NUM(0), NUM_ZERO, 8, 6) == CAM_ERR_FOV);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, up, NUM(180), NUM_ZERO, 8, 6) == CAM_ERR_FOV);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, up, NUM(-10), NUM_ZERO, 8, 6) == CAM_ERR_FOV);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, up, NUM(200), NUM_ZERO, 8, 6) == CAM_ERR_FOV);
    /* H cot(fov/2) > 32767. */
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, up, NUM(0.3), NUM_ZERO, 100, 100) == CAM_ERR_NARROW);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, up, NUM(0.4), NUM_ZERO, 100, 100) == CAM_OK);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, up, NUM(14), NUM_ZERO, 64, 4096) == CAM_ERR_NARROW);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, up, NUM(15), NUM_ZERO, 64, 4096) == CAM_OK);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, up, NUM(1), NUM_ZERO, 64, 48) == CAM_OK);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, up, NUM(1), NUM_ZERO, 4096, 4096) == CAM_ERR_NARROW);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, up, NUM(0.0001), NUM_ZERO, 1, 1) == CAM_ERR_NARROW);
    /* Orthographic scale. */
    CHECK(cam_setup(&c, CAM_ORTHOGRAPHIC, o, g, up, NUM_ZERO, NUM(0), 8, 6) == CAM_ERR_SCALE);
    CHECK(cam_setup(&c, CAM_ORTHOGRAPHIC, o, g, up, NUM_ZERO, NUM(-2), 8, 6) == CAM_ERR_SCALE);
    /* Each kind ignores the other's parameter. */
    CHECK(cam_setup(&c, CAM_ORTHOGRAPHIC, o, g, up, NUM(0), NUM(2), 8, 6) == CAM_OK);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, up, NUM(45), NUM(0), 8, 6) == CAM_OK);
    /* Size. */
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, up, NUM(45), NUM_ZERO, 0, 6) == CAM_ERR_SIZE);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, up, NUM(45), NUM_ZERO, 8, 0) == CAM_ERR_SIZE);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, up, NUM(45), NUM_ZERO, -8, 6) == CAM_ERR_SIZE);
    CHECK(cam_setup(&c, CAM_ORTHOGRAPHIC, o, g, up, NUM_ZERO, NUM(1), 0, 6) == CAM_ERR_SIZE);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, up, NUM(45), NUM_ZERO, FXRT_MAX_DIM + 1, 6)
          == CAM_ERR_SIZE);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, up, NUM(45), NUM_ZERO, 8, FXRT_MAX_DIM + 1)
          == CAM_ERR_SIZE);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, up, NUM(45), NUM_ZERO, FXRT_MAX_DIM, FXRT_MAX_DIM)
          == CAM_OK);
    /* H cot(fov/2) >= 1: at one pixel high fov <= 90 degrees, at 120
     * pixels fov <= 179.045 degrees. */
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, up, NUM(89.99), NUM_ZERO, 1, 1) == CAM_OK);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, up, NUM(90), NUM_ZERO, 1, 1) == CAM_OK); /* the limit itself */
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, up, NUM(90.01), NUM_ZERO, 1, 1) == CAM_ERR_WIDE);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, up, NUM(179.04), NUM_ZERO, 160, 120) == CAM_OK);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, up, NUM(179.05), NUM_ZERO, 160, 120) == CAM_ERR_WIDE);
    /* Up at least asin(1/64) = 0.8952 degrees from +-gaze: up = (0, s, -1)
     * with s = tan(angle). */
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, V3(0, 0.0157, -1), NUM(45), NUM_ZERO, 8, 6) == CAM_OK);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, V3(0, 0.0155, -1), NUM(45), NUM_ZERO, 8, 6) == CAM_ERR_UP);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, V3(0, -0.0157, 1), NUM(45), NUM_ZERO, 8, 6) == CAM_OK);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, g, V3(0, -0.0155, 1), NUM(45), NUM_ZERO, 8, 6) == CAM_ERR_UP);
    /* The same at any length of up and gaze (the test is scale-free). */
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, V3(0, 0, -8000), V3(0, 0.0157 * 0.25, -0.25), NUM(45), NUM_ZERO,
                    8, 6) == CAM_OK);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, V3(0, 0, -0.001), V3(0, 0.0155 * 8000, -8000), NUM(45), NUM_ZERO,
                    8, 6) == CAM_ERR_UP);
    /* Components beyond the coordinate domain. */
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, V3(8192.5, 0, 0), g, up, NUM(45), NUM_ZERO, 8, 6) == CAM_ERR_RANGE);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, V3(0, 0, -9000), up, NUM(45), NUM_ZERO, 8, 6) == CAM_ERR_RANGE);
    CHECK(cam_setup(&c, CAM_ORTHOGRAPHIC, o, g, V3(0, 9000, 0), NUM_ZERO, NUM(1), 8, 6) == CAM_ERR_RANGE);
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, V3(8192, -8192, 8192), V3(-8192, 8192, -8192), V3(8192, 8192, 0),
                    NUM(45), NUM_ZERO, 8, 6) == CAM_OK);
    /* Every code has its own text; the up message says how to look down. */
    CHECK(cam_strerror(CAM_ERR_NARROW) != cam_strerror(CAM_ERR_FOV));
    CHECK(cam_strerror(CAM_ERR_WIDE) != cam_strerror(CAM_ERR_FOV));
    {
        const char *m = cam_strerror(CAM_ERR_UP), *want = "'gaze 0 -1 0 up 0 0 -1'";
        bool found = false;
        for (const char *q = m; *q && !found; q++) {
            size_t k = 0;
            while (want[k] && q[k] == want[k])
                k++;
            found = want[k] == '\0';
        }
        CHECK_MSG(found, "CAM_ERR_UP text lacks the straight-down hint: %s", m);
    }
    /* Looking straight down with that hint works: u = +x, v = -z. */
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, o, V3(0, -1, 0), V3(0, 0, -1), NUM(45), NUM_ZERO, 8, 6) == CAM_OK);
    CHECK_VEC_ABS(c.u, dv(1, 0, 0), 0);
    CHECK_VEC_ABS(c.v, dv(0, 0, -1), 0);
    CHECK_VEC_ABS(c.w, dv(0, 1, 0), 0);
}

/* A fov the camera accepts must give rays that look forward: in particular
 * a fov just below 180 degrees, where cot(fov/2) is tiny (in Q16.16 it
 * rounds to 0 from 179.99913 degrees on, and cam_setup must then reject the
 * fov rather than build a zero forward vector). */
static void test_cam_wide_fov(void)
{
    static const double fovs[] = {175, 179, 179.9, 179.99, 179.999, 179.9991, 179.9999, 180 - 1.0 / 65536};
    for (size_t i = 0; i < sizeof fovs / sizeof fovs[0]; i++) {
        cam_t c;
        cam_err_t err = cam_setup(&c, CAM_PERSPECTIVE, V3(0, 0, 0), V3(0, 0, -1), V3(0, 1, 0),
                                  N(fovs[i]), NUM_ZERO, 5, 3);
        if (err != CAM_OK) {
            /* 3 rows: H cot(fov/2) < 1 from 143.1 degrees on. */
            CHECK(err == CAM_ERR_FOV || err == CAM_ERR_WIDE);
            continue;
        }
        ray_t r;
        cam_ray(&c, 2, 1, &r);
        CHECK_MSG(dv_near_abs(DV(r.d), dv(0, 0, -1), 1), "fov %.9g accepted, centre ray d = (%g %g %g)",
                  D(N(fovs[i])), D(r.d.x), D(r.d.y), D(r.d.z));
        cam_ray(&c, 4, 2, &r);
        dv_t d = DV(r.d);
        CHECK_MSG(near_abs(dlen(d), 1, 4) && d.z < 0,
                  "fov %.9g accepted, corner ray d = (%g %g %g) does not look forward",
                  D(N(fovs[i])), d.x, d.y, d.z);
    }
}

/* ---- 2. primitives hit from outside ------------------------------------- */

static color_t red(void) { return col(1, 0, 0); }

static void test_plane_outside(void)
{
    geom_plane_t p;
    num_t t = NUM(-1);
    CHECK(geom_plane_make(&p, V3(0, -1, 0), V3(0, 5, 0), red(), 0));
    CHECK_VEC_ABS(p.n, dv(0, 1, 0), 0);
    /* Straight down from 3 above: t = 3. */
    ray_t r = mkray(dv(0.25, 2, -7), dv(0, -1, 0));
    CHECK(geom_plane_hit(&p, &r, &t));
    CHECK_ABS(t, 3, 1);
    /* At an angle: cos = 0.8, t = 3 / 0.8. */
    r = mkray(dv(0, 2, 0), dv(3, -4, 0));
    t = NUM(-1);
    CHECK(geom_plane_hit(&p, &r, &t));
    CHECK_REL(t, 3.75, 4);
    /* From below (planes are two-sided). */
    r = mkray(dv(0, -3, 0), dv(0, 1, 0));
    CHECK(geom_plane_hit(&p, &r, &t));
    CHECK_ABS(t, 2, 1);
    /* Tilted plane x + y = 0: from (0,5,0) straight down the distance is
     * 5/sqrt2 and cos = 1/sqrt2, so t = 5. */
    CHECK(geom_plane_make(&p, V3(0, 0, 0), V3(1, 1, 0), red(), 0));
    r = mkray(dv(0, 5, 0), dv(0, -1, 0));
    CHECK(geom_plane_hit(&p, &r, &t));
    CHECK_REL(t, 5, 4);
    /* Pointing away: miss. */
    r = mkray(dv(0, 5, 0), dv(0, 1, 0));
    CHECK(!geom_plane_hit(&p, &r, &t));
}

static void test_sphere_outside(void)
{
    geom_sphere_t s;
    num_t t = NUM(-1);
    CHECK(geom_sphere_make(&s, V3(0, 0, -3), NUM(0.5), red(), 0));
    ray_t r = mkray(dv(0, 0, 0), dv(0, 0, -1));
    CHECK(geom_sphere_hit(&s, &r, &t));
    CHECK_ABS(t, 2.5, 1);
    /* Along each axis, from both sides: t = distance - r. */
    static const double dirs[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    CHECK(geom_sphere_make(&s, V3(1, -2, 0.5), NUM(1.5), red(), 0));
    for (int i = 0; i < 6; i++) {
        dv_t d = dv(dirs[i][0], dirs[i][1], dirs[i][2]);
        r = mkray(dsub(dv(1, -2, 0.5), dscale(d, 7)), d);
        CHECK(geom_sphere_hit(&s, &r, &t));
        CHECK_ABS(t, 5.5, 1);
    }
    /* Off-axis ray parallel to z: t = dz - sqrt(r^2 - offset^2). */
    CHECK(geom_sphere_make(&s, V3(0, 0, -3), NUM(0.5), red(), 0));
    r = mkray(dv(0.25, 0.125, 5), dv(0, 0, -1));
    CHECK(geom_sphere_hit(&s, &r, &t));
    CHECK_ABS(t, 8 - sqrt(0.25 - 0.25 * 0.25 - 0.125 * 0.125), 2);
    /* Oblique ray through the centre: t = |c - o| - r. */
    r = mkray(dv(2, 3, 1), dv(-2, -3, -4));
    CHECK(geom_sphere_hit(&s, &r, &t));
    CHECK_REL(t, sqrt(29.0) - 0.5, 4);
    /* Just missing the silhouette. */
    r = mkray(dv(0.501, 0, 5), dv(0, 0, -1));
    CHECK(!geom_sphere_hit(&s, &r, &t));
    r = mkray(dv(0.499, 0, 5), dv(0, 0, -1));
    CHECK(geom_sphere_hit(&s, &r, &t));
    CHECK_ABS(t, 8 - sqrt(0.25 - D(N(0.499)) * D(N(0.499))), 64); /* steep: sqrt of a small difference */
    /* Large sphere far away, near the domain limits. */
    CHECK(geom_sphere_make(&s, V3(0, 0, -8000), NUM(4096), red(), 0));
    r = mkray(dv(0, 0, 8000), dv(0, 0, -1));
    CHECK(geom_sphere_hit(&s, &r, &t));
    CHECK_ABS(t, 11904, 1);
    CHECK(geom_sphere_make(&s, V3(-8000, -8000, -8000), NUM(4096), red(), 0));
    r = mkray(dv(8000, 8000, 8000), dv(-1, -1, -1));
    CHECK(geom_sphere_hit(&s, &r, &t));
    CHECK_REL(t, 16000 * sqrt(3.0) - 4096, 4);
}

/* The test triangle (-1,-1,-3), (1,-1,-3), (0,1,-3) and rays along -z. */
static void test_triangle_outside(void)
{
    geom_triangle_t tr, tw;
    num_t t = NUM(-1);
    dv_t a = dv(-1, -1, -3), b = dv(1, -1, -3), c = dv(0, 1, -3);
    CHECK(geom_triangle_make(&tr, V(a), V(b), V(c), red(), 0));
    CHECK(geom_triangle_make(&tw, V(a), V(c), V(b), red(), 0)); /* other winding */
    CHECK(!tr.degenerate && !tw.degenerate);
    CHECK_VEC_ABS(tr.n, dv(0, 0, 1), 1);
    CHECK_VEC_ABS(tw.n, dv(0, 0, -1), 1);
    const geom_triangle_t *both[2] = {&tr, &tw};
    for (int k = 0; k < 2; k++) {
        const geom_triangle_t *T = both[k];
        ray_t r = mkray(dv(0, 0, 0), dv(0, 0, -1));
        t = NUM(-1);
        CHECK(geom_triangle_hit(T, &r, &t));
        CHECK_ABS(t, 3, 1);
        r = mkray(dv(0.2, 0.1, 2), dv(0, 0, -1));
        CHECK(geom_triangle_hit(T, &r, &t));
        CHECK_ABS(t, 5, 1);
        /* From behind (triangles are two-sided). */
        r = mkray(dv(0.2, -0.5, -7), dv(0, 0, 1));
        CHECK(geom_triangle_hit(T, &r, &t));
        CHECK_ABS(t, 4, 1);
        /* Just outside / inside each edge, at its midpoint, by 1e-3. */
        static const double mid[3][2] = {{0, -1}, {0.5, 0}, {-0.5, 0}};
        double out[3][2] = {{0, -1}, {2 / sqrt(5.0), 1 / sqrt(5.0)}, {-2 / sqrt(5.0), 1 / sqrt(5.0)}};
        for (int e = 0; e < 3; e++) {
            double px = mid[e][0] + 1e-3 * out[e][0], py = mid[e][1] + 1e-3 * out[e][1];
            r = mkray(dv(px, py, 0), dv(0, 0, -1));
            CHECK_MSG(!geom_triangle_hit(T, &r, &t), "winding %d edge %d: hit outside", k, e);
            px = mid[e][0] - 1e-3 * out[e][0], py = mid[e][1] - 1e-3 * out[e][1];
            r = mkray(dv(px, py, 0), dv(0, 0, -1));
            CHECK_MSG(geom_triangle_hit(T, &r, &t), "winding %d edge %d: missed inside", k, e);
            /* And obliquely from a point off to the side. */
            dv_t o = dv(4, 3, 2);
            r = mkray(o, dsub(dv(mid[e][0] + 1e-3 * out[e][0], mid[e][1] + 1e-3 * out[e][1], -3), o));
            CHECK_MSG(!geom_triangle_hit(T, &r, &t), "winding %d edge %d: oblique hit outside", k, e);
            dv_t p = dv(mid[e][0] - 1e-3 * out[e][0], mid[e][1] - 1e-3 * out[e][1], -3);
            r = mkray(o, dsub(p, o));
            CHECK_MSG(geom_triangle_hit(T, &r, &t), "winding %d edge %d: oblique miss inside", k, e);
            CHECK_REL(t, dlen(dsub(p, o)), 4);
        }
        /* Beyond each vertex. */
        r = mkray(dv(0, 1.01, 0), dv(0, 0, -1));
        CHECK(!geom_triangle_hit(T, &r, &t));
        r = mkray(dv(-1.01, -1, 0), dv(0, 0, -1));
        CHECK(!geom_triangle_hit(T, &r, &t));
    }
    /* Tilted: x + y + z = 1, from (-2,-2,-2) along (1,1,1): centroid at
     * t = 7/sqrt3. */
    CHECK(geom_triangle_make(&tr, V3(1, 0, 0), V3(0, 1, 0), V3(0, 0, 1), red(), 0));
    ray_t r = mkray(dv(-2, -2, -2), dv(1, 1, 1));
    CHECK(geom_triangle_hit(&tr, &r, &t));
    CHECK_REL(t, 7 / sqrt(3.0), 4);
    /* A triangle near the domain limits. */
    CHECK(geom_triangle_make(&tr, V3(-8000, -8000, -100), V3(8000, -8000, -100), V3(0, 8000, -100),
                             red(), 0));
    CHECK(!tr.degenerate);
    CHECK_VEC_ABS(tr.n, dv(0, 0, 1), 1);
    r = mkray(dv(0, 0, 0), dv(0, 0, -1));
    CHECK(geom_triangle_hit(&tr, &r, &t));
    CHECK_ABS(t, 100, 1);
    r = mkray(dv(3000, 0, 0), dv(0, 0, -1));
    CHECK(geom_triangle_hit(&tr, &r, &t));
    r = mkray(dv(5000, 1, 0), dv(0, 0, -1));
    CHECK(!geom_triangle_hit(&tr, &r, &t));
}

static void test_box_outside(void)
{
    geom_box_t b;
    num_t t = NUM(-1);
    dv_t lo = dv(-1, -2, -3), hi = dv(2, 3, 4), mid = dv(0.5, 0.5, 0.5);
    CHECK(geom_box_make(&b, V(lo), V(hi), red(), 0));
    /* Each face head-on from 4 units outside it. */
    for (int axis = 0; axis < 3; axis++) {
        for (int side = 0; side < 2; side++) {
            double l = axis == 0 ? lo.x : axis == 1 ? lo.y : lo.z;
            double h = axis == 0 ? hi.x : axis == 1 ? hi.y : hi.z;
            double face = side ? h : l, sgn = side ? 1 : -1;
            dv_t o = mid, d = dv(0, 0, 0);
            double *oc = axis == 0 ? &o.x : axis == 1 ? &o.y : &o.z;
            double *dc = axis == 0 ? &d.x : axis == 1 ? &d.y : &d.z;
            *oc = face + 4 * sgn;
            *dc = -sgn;
            ray_t r = mkray(o, d);
            t = NUM(-1);
            CHECK_MSG(geom_box_hit(&b, &r, &t), "axis %d side %d", axis, side);
            CHECK_ABS(t, 4, 0);
            /* Obliquely, entering through the same face at (face, 0.25 off). */
            dv_t p = mid;
            double *pc = axis == 0 ? &p.x : axis == 1 ? &p.y : &p.z;
            *pc = face;
            p = dadd(p, axis == 0 ? dv(0, 0.25, -0.5) : axis == 1 ? dv(0.25, 0, -0.5) : dv(0.25, -0.5, 0));
            dv_t o2 = dadd(p, dscale(dv(axis == 0 ? sgn : 0.5, axis == 1 ? sgn : 0.5, axis == 2 ? sgn : 0.5), 3));
            r = mkray(o2, dsub(p, o2));
            CHECK_MSG(geom_box_hit(&b, &r, &t), "oblique axis %d side %d", axis, side);
            CHECK_REL(t, dlen(dsub(p, o2)), 4);
        }
    }
    /* Misses beside the box, and pointing away. */
    ray_t r = mkray(dv(2.01, 0, 10), dv(0, 0, -1));
    CHECK(!geom_box_hit(&b, &r, &t));
    r = mkray(dv(0, 0, 10), dv(0, 0, 1));
    CHECK(!geom_box_hit(&b, &r, &t));
    r = mkray(dv(-5, 0, 0), dv(1, 2, 0)); /* passes above the +y face */
    CHECK(!geom_box_hit(&b, &r, &t));
    /* Box of figure 7, seen from (3,3,3), entering the top at (0.1,1,-0.2). */
    CHECK(geom_box_make(&b, V3(-0.5, 0, -0.5), V3(0.5, 1, 0.5), red(), 0));
    r = mkray(dv(3, 3, 3), dv(-2.9, -2, -3.2));
    CHECK(geom_box_hit(&b, &r, &t));
    CHECK_REL(t, sqrt(2.9 * 2.9 + 2 * 2 + 3.2 * 3.2), 4);
}

/* ---- 3. from inside ----------------------------------------------------- */

static void test_inside(void)
{
    num_t t = NUM(-1);
    geom_sphere_t s;
    CHECK(geom_sphere_make(&s, V3(0, 0, -3), NUM(2), red(), 0));
    ray_t r = mkray(dv(0, 0, -3.5), dv(0, 0, -1));
    CHECK(geom_sphere_hit(&s, &r, &t));
    CHECK_ABS(t, 1.5, 1);
    r = mkray(dv(0, 0, -3.5), dv(0, 0, 1));
    CHECK(geom_sphere_hit(&s, &r, &t));
    CHECK_ABS(t, 2.5, 1);
    CHECK(geom_sphere_make(&s, V3(0, 0, 0), NUM(5), red(), 0));
    r = mkray(dv(1, 0, 0), dv(0, 1, 0));
    CHECK(geom_sphere_hit(&s, &r, &t));
    CHECK_ABS(t, sqrt(24.0), 2);
    /* A camera at the centre sees the sphere at t = 5 in every pixel. */
    cam_t c;
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, V3(0, 0, 0), V3(1, -1, -2), V3(0, 1, 0), NUM(100), NUM_ZERO,
                    8, 6) == CAM_OK);
    long bad = 0;
    for (int32_t y = 0; y < 6; y++)
        for (int32_t x = 0; x < 8; x++) {
            cam_ray(&c, x, y, &r);
            bool h = geom_sphere_hit(&s, &r, &t);
            if (!h || !near_rel(D(t), 5, 4)) {
                bad++;
                CHECK_SWEEP(0, "pixel (%d,%d): hit %d t %.9g, want 5", (int)x, (int)y, (int)h, D(t));
            }
        }
    CHECK(bad == 0);

    geom_box_t b;
    CHECK(geom_box_make(&b, V3(-1, -2, -3), V3(2, 3, 4), red(), 0));
    static const double dirs[6][4] = {{1, 0, 0, 2}, {-1, 0, 0, 1}, {0, 1, 0, 3},
                                      {0, -1, 0, 2}, {0, 0, 1, 4}, {0, 0, -1, 3}};
    for (int i = 0; i < 6; i++) {
        r = mkray(dv(0, 0, 0), dv(dirs[i][0], dirs[i][1], dirs[i][2]));
        t = NUM(-1);
        CHECK_MSG(geom_box_hit(&b, &r, &t), "dir %d", i);
        CHECK_ABS(t, dirs[i][3], 0);
    }
    r = mkray(dv(0, 0, 0), dv(1, 1, 0));
    CHECK(geom_box_hit(&b, &r, &t));
    CHECK_REL(t, 2 * sqrt(2.0), 4);
    r = mkray(dv(0.5, 0.5, 0.5), dv(-1, -2, -2));
    CHECK(geom_box_hit(&b, &r, &t)); /* exits through y = -2 at (-0.75, -2, -2) */
    CHECK_REL(t, 1.25 * 3, 4);
}

/* ---- 4. behind the origin, parallel, in the plane of a face ------------- */

static void test_behind(void)
{
    num_t t = NUM(-1);
    ray_t r = mkray(dv(0, 0, 0), dv(0, 0, -1));
    geom_sphere_t s;
    geom_box_t b;
    geom_triangle_t tr;
    geom_plane_t p;
    CHECK(geom_sphere_make(&s, V3(0, 0, 3), NUM(1), red(), 0));
    CHECK(!geom_sphere_hit(&s, &r, &t));
    CHECK(geom_sphere_make(&s, V3(0, 0, 1.5), NUM(1.5), red(), 0)); /* touches the origin */
    CHECK(!geom_sphere_hit(&s, &r, &t));
    CHECK(geom_box_make(&b, V3(-1, -1, 1), V3(1, 1, 2), red(), 0));
    CHECK(!geom_box_hit(&b, &r, &t));
    CHECK(geom_box_make(&b, V3(-1, -1, 0), V3(1, 1, 2), red(), 0)); /* origin on its face */
    CHECK(!geom_box_hit(&b, &r, &t));
    CHECK(geom_triangle_make(&tr, V3(-1, -1, 3), V3(1, -1, 3), V3(0, 1, 3), red(), 0));
    CHECK(!geom_triangle_hit(&tr, &r, &t));
    CHECK(geom_plane_make(&p, V3(0, 0, 3), V3(0, 0, 1), red(), 0));
    CHECK(!geom_plane_hit(&p, &r, &t));
    CHECK(geom_plane_make(&p, V3(0, 0, 3), V3(0, 0, -1), red(), 0));
    CHECK(!geom_plane_hit(&p, &r, &t));
    /* Origin on the plane: t = 0 is not a hit. */
    CHECK(geom_plane_make(&p, V3(0, 0, 0), V3(0, 0, 1), red(), 0));
    CHECK(!geom_plane_hit(&p, &r, &t));
    /* Parallel to a plane: above it, and lying in it. */
    CHECK(geom_plane_make(&p, V3(0, -1, 0), V3(0, 1, 0), red(), 0));
    CHECK(!geom_plane_hit(&p, &r, &t));
    r = mkray(dv(0, -1, 0), dv(1, 0, 1));
    CHECK(!geom_plane_hit(&p, &r, &t));
    /* Parallel to a triangle's plane, through its interior: miss. */
    CHECK(geom_triangle_make(&tr, V3(-1, -1, -3), V3(1, -1, -3), V3(0, 1, -3), red(), 0));
    r = mkray(dv(-5, 0, -3), dv(1, 0, 0));
    CHECK(!geom_triangle_hit(&tr, &r, &t));

    /* In the plane of a box face (y = max.y, and an edge): no crash, the
     * same answer twice, and if a hit then at the face x = -1 (t = 4). */
    CHECK(geom_box_make(&b, V3(-1, -2, -3), V3(2, 3, 4), red(), 0));
    static const double os[3][3] = {{-5, 3, 0}, {-5, -2, 0}, {-5, 3, 4}};
    for (int i = 0; i < 3; i++) {
        r = mkray(dv(os[i][0], os[i][1], os[i][2]), dv(1, 0, 0));
        num_t t1 = NUM(-1), t2 = NUM(-2);
        bool h1 = geom_box_hit(&b, &r, &t1), h2 = geom_box_hit(&b, &r, &t2);
        CHECK(h1 == h2);
        CHECK(!h1 || (t1 == t2 && near_abs(D(t1), 4, 0)));
    }
}

/* ---- 5. degenerate inputs ----------------------------------------------- */

static void test_degenerate(void)
{
    geom_sphere_t s;
    geom_plane_t p;
    geom_box_t b;
    geom_triangle_t tr;
    num_t t = NUM(-1);
    CHECK(!geom_sphere_make(&s, V3(0, 0, -3), NUM(0), red(), 0));
    CHECK(!geom_sphere_make(&s, V3(0, 0, -3), NUM(-1), red(), 0));
    CHECK(geom_sphere_make(&s, V3(0, 0, -3), N(1e-3), red(), 0));
    CHECK(!geom_plane_make(&p, V3(0, 0, 0), V3(0, 0, 0), red(), 0));
    CHECK(geom_plane_make(&p, V3(0, 0, 0), V3(0, 0, 1e-3), red(), 0));
    CHECK_VEC_ABS(p.n, dv(0, 0, 1), 1);
    CHECK(!geom_box_make(&b, V3(1, 0, 0), V3(0, 1, 1), red(), 0));
    CHECK(!geom_box_make(&b, V3(0, 1, 0), V3(1, 0, 1), red(), 0));
    CHECK(!geom_box_make(&b, V3(0, 0, 1), V3(1, 1, 0), red(), 0));
    CHECK(geom_box_make(&b, V3(0, 0, 0), V3(0, 0, 0), red(), 0));

    /* Zero-thickness box (min.y == max.y == 0), from above and below. */
    CHECK(geom_box_make(&b, V3(-1, 0, -1), V3(1, 0, 1), red(), 0));
    ray_t r = mkray(dv(0.25, 5, 0.5), dv(0, -1, 0));
    CHECK(geom_box_hit(&b, &r, &t));
    CHECK_ABS(t, 5, 0);
    r = mkray(dv(0, 5, 0), dv(0.1, -1, 0.05));
    CHECK(geom_box_hit(&b, &r, &t));
    CHECK_REL(t, 5 * sqrt(1 + 0.01 + 0.0025), 4);
    r = mkray(dv(0.5, -2, 0), dv(0, 1, 0));
    CHECK(geom_box_hit(&b, &r, &t));
    CHECK_ABS(t, 2, 0);
    r = mkray(dv(1.5, 5, 0), dv(0, -1, 0));
    CHECK(!geom_box_hit(&b, &r, &t));

    /* Collinear triangles are accepted and never hit. */
    static const double tris[3][3][3] = {
        {{0, 0, -3}, {1, 1, -3}, {2, 2, -3}},
        {{0, 0, -3}, {1, 1, -3}, {0, 0, -3}},
        {{0.5, 0.5, -3}, {0.5, 0.5, -3}, {0.5, 0.5, -3}},
    };
    for (int i = 0; i < 3; i++) {
        CHECK(geom_triangle_make(&tr, V3(tris[i][0][0], tris[i][0][1], tris[i][0][2]),
                                 V3(tris[i][1][0], tris[i][1][1], tris[i][1][2]),
                                 V3(tris[i][2][0], tris[i][2][1], tris[i][2][2]), red(), 0));
        CHECK(tr.degenerate);
        int hits = 0;
        static const double dirs[4][3] = {{0, 0, -1}, {0.3, 0.2, -1}, {-1, 1, -0.5}, {1, -1, 0.1}};
        for (int k = 0; k < 4; k++)
            for (double sp = -0.5; sp <= 2.5; sp += 0.25) {
                dv_t p0 = dv(sp, sp, -3);
                dv_t d = dv(dirs[k][0], dirs[k][1], dirs[k][2]);
                r = mkray(dsub(p0, dscale(dnorm(d), 4)), d);
                hits += geom_triangle_hit(&tr, &r, &t);
            }
        CHECK_MSG(hits == 0, "collinear triangle %d hit %d times", i, hits);
    }
}

/* ---- 6. far hits -------------------------------------------------------- */

static void test_far(void)
{
    geom_plane_t p;
    num_t t = NUM(-1);
    CHECK(geom_plane_make(&p, V3(0, -1, 0), V3(0, 1, 0), red(), 0));
    /* d = (1, -eps, 0): t = 1/eps. eps = 2^-16 is beyond Q16.16 (t = 65536). */
    ray_t r;
    r.o = V3(0, 0, 0);
    r.d = vec3_make(NUM_ONE, N(-1.0 / 65536), NUM_ZERO);
    double dd = D(r.d.y);
    CHECK(geom_plane_hit(&p, &r, &t));
#if FXRT_NUMBER == FXRT_Q16
    CHECK_MSG(t == NUM_MAX, "t = %.9g, true t %.9g", D(t), -1 / dd);
#else
    CHECK_REL(t, -1 / dd, 4);
#endif
    /* Also with a normalised d (d.y rounds to -1 LSB in Q16.16), and a
     * far-away plane. */
    r = mkray(dv(0, 0, 0), dv(1, -1e-5, 0.5));
    CHECK(geom_plane_hit(&p, &r, &t));
#if FXRT_NUMBER == FXRT_Q16
    CHECK_MSG(t == NUM_MAX, "t = %.9g", D(t));
#else
    CHECK_REL(t, -1 / D(r.d.y), 4);
#endif
    CHECK(geom_plane_make(&p, V3(0, -8000, 0), V3(0, 1, 0), red(), 0));
    r = mkray(dv(0, 8000, 0), dv(1, -0.1, 0));
    CHECK(geom_plane_hit(&p, &r, &t));
#if FXRT_NUMBER == FXRT_Q16
    CHECK_MSG(t == NUM_MAX, "t = %.9g", D(t));
#else
    CHECK_REL(t, 16000 * sqrt(1.01) / 0.1, 4);
#endif
    /* Just inside the range: eps = 3 LSB, t = 21845.33. */
    r.o = V3(0, 0, 0);
    r.d = vec3_make(NUM_ONE, N(-3.0 / 65536), NUM_ZERO);
    CHECK(geom_plane_make(&p, V3(0, -1, 0), V3(0, 1, 0), red(), 0));
    CHECK(geom_plane_hit(&p, &r, &t));
    CHECK_REL(t, -1 / D(r.d.y), 2);
}

/* ---- 7. watertight shared edge ------------------------------------------ */

static long watertight(dv_t a, dv_t b, dv_t c, dv_t d, const dv_t *origins, int n_origins, long n_rays)
{
    geom_triangle_t t1, t2;
    CHECK(geom_triangle_make(&t1, V(a), V(b), V(c), red(), 1));
    CHECK(geom_triangle_make(&t2, V(c), V(b), V(d), red(), 2));
    dv_t B = RV(b), C = RV(c);
    long miss = 0;
    for (long i = 0; i < n_rays; i++) {
        dv_t o = origins[i % n_origins];
        double s = urand(0.01, 0.99);
        dv_t p = dadd(B, dscale(dsub(C, B), s));
        if (i % 4) /* three in four off the edge by up to 1e-6 */
            p = dadd(p, urand_v(-1e-6, 1e-6));
        ray_t r = mkray(o, dsub(p, o));
        num_t t;
        if (!geom_triangle_hit(&t1, &r, &t) && !geom_triangle_hit(&t2, &r, &t)) {
            miss++;
            CHECK_SWEEP(0, "ray %ld from (%g %g %g) to (%.12g %.12g %.12g) slips through", i, o.x, o.y,
                        o.z, p.x, p.y, p.z);
        }
    }
    return miss;
}

static void test_watertight(void)
{
    static const dv_t origins[] = {{0, 0, 0}, {0.7, -0.3, 1}, {-2, 1.5, -0.5}, {3, 3, 3},
                                   {0.2, 0.1, -8}, {-0.4, 0.3, 2000}};
    int no = (int)(sizeof origins / sizeof origins[0]);
    /* Square quad with the diagonal from (1,-1) to (-1,1). */
    long m = watertight(dv(-1, -1, -3), dv(1, -1, -3), dv(-1, 1, -3), dv(1, 1, -3), origins, no, 40000);
    CHECK_MSG(m == 0, "square quad: %ld rays slipped through", m);
    /* Irregular, non-planar quad. */
    m = watertight(dv(-1.3, -0.7, -3.1), dv(1.1, -0.9, -2.7), dv(-0.8, 1.2, -3.4), dv(1.4, 1.05, -2.9),
                   origins, no, 40000);
    CHECK_MSG(m == 0, "irregular quad: %ld rays slipped through", m);
    /* Long thin triangles with a long shared edge far from the origin. */
    m = watertight(dv(-3000, -7, -500), dv(2500, -6.5, -480), dv(-2800, 5.25, -510), dv(2900, 6, -490),
                   origins, no, 20000);
    CHECK_MSG(m == 0, "large quad: %ld rays slipped through", m);
}

/* ---- random cross-checks against double references ---------------------- */

/* Sphere and box reference t of the ray (o, d) with d as the build holds
 * it, renormalised. Returns false for a miss; *marginal when the answer
 * could go either way within the build's rounding. */
static bool ref_sphere(dv_t c, double rad, dv_t o, dv_t d, double *t, bool *marginal)
{
    dv_t oc = dsub(c, o);
    double b = ddot(oc, d);
    dv_t q = dsub(oc, dscale(d, b));
    double disc = rad * rad - ddot(q, q);
    double m = 100 * UNIT * (1 + dlen(oc)) * (1 + rad);
    *marginal = fabs(disc) < m;
    if (disc < 0)
        return false;
    double h = sqrt(disc);
    *marginal = *marginal || fabs(b - h) < m || fabs(b + h) < m;
    if (b - h > 0) {
        *t = b - h;
        return true;
    }
    if (b + h > 0) {
        *t = b + h;
        return true;
    }
    return false;
}

static bool ref_box(dv_t lo, dv_t hi, dv_t o, dv_t d, double *t, bool *marginal)
{
    double tn = -1e300, tf = 1e300;
    double ov[3] = {o.x, o.y, o.z}, dvv[3] = {d.x, d.y, d.z};
    double lv[3] = {lo.x, lo.y, lo.z}, hv[3] = {hi.x, hi.y, hi.z};
    for (int i = 0; i < 3; i++) {
        if (dvv[i] == 0) {
            if (ov[i] < lv[i] || ov[i] > hv[i])
                return *marginal = false, false;
            continue;
        }
        double t1 = (lv[i] - ov[i]) / dvv[i], t2 = (hv[i] - ov[i]) / dvv[i];
        if (t1 > t2) {
            double x = t1;
            t1 = t2;
            t2 = x;
        }
        tn = fmax(tn, t1);
        tf = fmin(tf, t2);
    }
    double m = 100 * UNIT * (1 + fabs(tn) + fabs(tf));
    *marginal = fabs(tn - tf) < m || fabs(tf) < m || fabs(tn) < m;
    if (tn > tf || !(tf > 0))
        return false;
    *t = tn > 0 ? tn : tf;
    return true;
}

/* Moller-Trumbore, two-sided. */
static bool ref_triangle(dv_t a, dv_t b, dv_t c, dv_t o, dv_t d, double *t, bool *marginal,
                         double *cosine)
{
    dv_t e1 = dsub(b, a), e2 = dsub(c, a);
    dv_t pv = dcross(d, e2);
    double det = ddot(e1, pv);
    *cosine = fabs(ddot(d, dnorm(dcross(e1, e2))));
    *marginal = *cosine < 1e-2;
    if (det == 0)
        return false;
    dv_t tv = dsub(o, a);
    double u = ddot(tv, pv) / det;
    dv_t qv = dcross(tv, e1);
    double v = ddot(d, qv) / det;
    double tt = ddot(e2, qv) / det;
    double m = 100 * UNIT * (1 + dlen(tv));
    *marginal = *marginal || fabs(u) < m || fabs(v) < m || fabs(1 - u - v) < m || fabs(tt) < m;
    if (u < 0 || v < 0 || u + v > 1 || !(tt > 0))
        return false;
    *t = tt;
    return true;
}

static void test_random(void)
{
    long bad = 0, hits = 0, n = 0;
    double worst[3] = {0, 0, 0};
    for (int i = 0; i < 20000; i++) {
        int kind = i % 3;
        dv_t o = urand_v(-10, 10);
        ray_t r;
        num_t t = NUM(-1);
        bool got, want, marginal;
        double tw = 0, cosine = 1, lever = 0;
        if (kind == 0) {
            geom_sphere_t s;
            dv_t c = RV(urand_v(-5, 5));
            double rad = D(N(urand(0.1, 3)));
            CHECK_SWEEP(geom_sphere_make(&s, V(c), N(rad), red(), 0), "random %d: make", i);
            dv_t aim = dadd(c, urand_v(-1.5 * rad, 1.5 * rad));
            r = mkray(o, dsub(aim, o));
            got = geom_sphere_hit(&s, &r, &t);
            want = ref_sphere(c, rad, DV(r.o), dnorm(DV(r.d)), &tw, &marginal);
        } else if (kind == 1) {
            geom_box_t b;
            dv_t p = RV(urand_v(-5, 5)), q = RV(urand_v(-5, 5));
            dv_t lo = dv(fmin(p.x, q.x), fmin(p.y, q.y), fmin(p.z, q.z));
            dv_t hi = dv(fmax(p.x, q.x), fmax(p.y, q.y), fmax(p.z, q.z));
            CHECK_SWEEP(geom_box_make(&b, V(lo), V(hi), red(), 0), "random %d: make", i);
            dv_t aim = dadd(dscale(dadd(lo, hi), 0.5), dscale(dsub(hi, lo), urand(-0.8, 0.8)));
            aim = dadd(aim, urand_v(-1, 1));
            r = mkray(o, dsub(aim, o));
            got = geom_box_hit(&b, &r, &t);
            /* The slab test divides by the components of d as held. */
            dv_t d = DV(r.d);
            want = ref_box(lo, hi, DV(r.o), d, &tw, &marginal);
        } else {
            geom_triangle_t tr;
            dv_t a = RV(urand_v(-5, 5)), b = RV(urand_v(-5, 5)), c = RV(urand_v(-5, 5));
            CHECK_SWEEP(geom_triangle_make(&tr, V(a), V(b), V(c), red(), 0), "random %d: make", i);
            double wa = urand(-0.3, 1), wb = urand(-0.3, 1), wc = urand(-0.3, 1);
            double ws = wa + wb + wc;
            if (fabs(ws) < 0.1)
                ws = 1, wa = 1, wb = wc = 0;
            dv_t aim = dscale(dadd(dadd(dscale(a, wa), dscale(b, wb)), dscale(c, wc)), 1 / ws);
            r = mkray(o, dsub(aim, o));
            got = geom_triangle_hit(&tr, &r, &t);
            want = ref_triangle(a, b, c, DV(r.o), dnorm(DV(r.d)), &tw, &marginal, &cosine);
            lever = dlen(dsub(a, DV(r.o)));
        }
        if (marginal)
            continue;
        n++;
        hits += want;
        bool ok = got == want;
        if (ok && got) {
            /* A triangle's t is ((a - o) . n) / (d . n) with n rounded: its
             * error grows with |a - o| and as 1 / cos of the angle of
             * incidence. */
            double err = fabs(D(t) - tw) * cosine / (UNIT * (fmax(1, tw) + lever));
            worst[kind] = fmax(worst[kind], err);
            ok = err <= 4;
        }
        if (!ok) {
            bad++;
            CHECK_SWEEP(ok, "random %d kind %d: got %d t %.10g, want %d t %.10g", i, kind, (int)got,
                        D(t), (int)want, tw);
        }
    }
    CHECK_MSG(bad == 0 && n > 15000 && hits > n / 4, "%ld bad of %ld (%ld hits)", bad, n, hits);
    if (getenv("TEST_GEOM_VERBOSE"))
        printf("random: %ld non-marginal rays, %ld hits, worst t error (units) sphere %.2f box %.2f "
               "triangle %.2f (x cos / (t + |a - o|))\n", n, hits, worst[0], worst[1], worst[2]);
}

/* ---- 8. world_hit ------------------------------------------------------- */

static world_t world; /* large: keep off the stack */

static void test_world(void)
{
    hit_t h;
    ray_t r = mkray(dv(0, 0, 0), dv(0, 0, -1));
    world_init(&world, col(0.2, 0.4, 0.6));
    CHECK(!world_hit(&world, &r, &h));
    CHECK(world.background_rgb.r == 51 && world.background_rgb.g == 102 && world.background_rgb.b == 153);
    rgb8_t px = render_pixel(&world, &r);
    CHECK(px.r == 51 && px.g == 102 && px.b == 153);

    /* Nearest wins, wherever it is in the arrays. */
    CHECK(geom_sphere_make(&world.spheres[0], V3(0, 0, -6), NUM(0.5), col(1, 0, 0), 0));
    CHECK(geom_sphere_make(&world.spheres[1], V3(0, 0, -3), NUM(0.5), col(0, 1, 0), 1));
    world.n_spheres = 2;
    CHECK(geom_box_make(&world.boxes[0], V3(-1, -1, -12), V3(1, 1, -10), col(0, 0, 1), 2));
    world.n_boxes = 1;
    CHECK(geom_plane_make(&world.planes[0], V3(0, -1, 0), V3(0, 1, 0), col(1, 1, 0), 3));
    world.n_planes = 1; /* parallel to the ray: never hit by it */
    CHECK(geom_triangle_make(&world.triangles[0], V3(-1, -1, -20), V3(1, -1, -20), V3(0, 1, -20),
                             col(1, 0, 1), 4));
    world.n_triangles = 1;
    CHECK(world_hit(&world, &r, &h));
    CHECK_ABS(h.t, 2.5, 1);
    CHECK(h.kind == GEOM_SPHERE && h.index == 1 && h.obj == &world.spheres[1].obj && h.obj->id == 1);
    CHECK(vec3_eq(h.point, ray_at(&r, h.t)));
    CHECK_VEC_ABS(h.point, dv(0, 0, -2.5), 1);
    px = render_pixel(&world, &r);
    CHECK(px.r == 0 && px.g == 255 && px.b == 0);

    /* Move each kind in front in turn. */
    CHECK(geom_box_make(&world.boxes[0], V3(-1, -1, -2), V3(1, 1, -1.5), col(0, 0, 1), 2));
    CHECK(world_hit(&world, &r, &h));
    CHECK(h.kind == GEOM_BOX && h.index == 0 && h.obj == &world.boxes[0].obj);
    CHECK_ABS(h.t, 1.5, 0);
    CHECK(geom_triangle_make(&world.triangles[0], V3(-1, -1, -1), V3(1, -1, -1), V3(0, 1, -1),
                             col(1, 0, 1), 4));
    CHECK(world_hit(&world, &r, &h));
    CHECK(h.kind == GEOM_TRIANGLE && h.index == 0 && h.obj == &world.triangles[0].obj);
    CHECK_ABS(h.t, 1, 1);
    CHECK(geom_plane_make(&world.planes[0], V3(0, 0, -0.75), V3(0, 0, 1), col(1, 1, 0), 3));
    CHECK(world_hit(&world, &r, &h));
    CHECK(h.kind == GEOM_PLANE && h.index == 0 && h.obj == &world.planes[0].obj);
    CHECK_ABS(h.t, 0.75, 1);
    /* An oblique ray: the point is o + t d and lies on the sphere. */
    world.n_planes = world.n_triangles = world.n_boxes = 0;
    r = mkray(dv(1, 2, 0.5), dv(-1, -2, -3.3));
    CHECK(world_hit(&world, &r, &h));
    CHECK(h.obj == &world.spheres[1].obj);
    CHECK(vec3_eq(h.point, ray_at(&r, h.t)));
    CHECK_REL(num_sub(vec3_len(vec3_sub(h.point, world.spheres[1].center)), NUM(0.5)), 0, 8);
    /* Everything behind: miss. */
    r = mkray(dv(0, 0, 0), dv(0, 0, 1));
    CHECK(!world_hit(&world, &r, &h));

    /* Exact ties go to the lower id, whatever the array order. */
    r = mkray(dv(0, 0, 0), dv(0, 0, -1));
    for (int order = 0; order < 2; order++) {
        world_init(&world, col(0, 0, 0));
        CHECK(geom_sphere_make(&world.spheres[order], V3(0, 0, -3), NUM(0.5), col(1, 0, 0), 3));
        CHECK(geom_sphere_make(&world.spheres[1 - order], V3(0, 0, -3), NUM(0.5), col(0, 0, 1), 7));
        world.n_spheres = 2;
        CHECK(world_hit(&world, &r, &h));
        CHECK_MSG(h.obj == &world.spheres[order].obj && h.obj->id == 3 && h.index == order,
                  "order %d: id %d", order, (int)h.obj->id);
        px = render_pixel(&world, &r);
        CHECK(px.r == 255 && px.b == 0);
    }
    /* Ties across kinds: box face, triangle and plane all at t = 3. */
    for (int lowest = 0; lowest < 3; lowest++) {
        world_init(&world, col(0, 0, 0));
        uint16_t ids[3] = {5, 6, 7};
        ids[lowest] = 1;
        CHECK(geom_box_make(&world.boxes[0], V3(-1, -1, -4), V3(1, 1, -3), col(0, 0, 1), ids[0]));
        CHECK(geom_triangle_make(&world.triangles[0], V3(-1, -1, -3), V3(1, -1, -3), V3(0, 1, -3),
                                 col(1, 0, 1), ids[1]));
        CHECK(geom_plane_make(&world.planes[0], V3(0, 0, -3), V3(0, 0, 1), col(1, 1, 0), ids[2]));
        world.n_boxes = world.n_triangles = world.n_planes = 1;
        CHECK(world_hit(&world, &r, &h));
        CHECK_ABS(h.t, 3, 0);
        static const geom_kind_t kinds[3] = {GEOM_BOX, GEOM_TRIANGLE, GEOM_PLANE};
        CHECK_MSG(h.kind == kinds[lowest] && h.obj->id == 1, "lowest %d: kind %d id %d", lowest,
                  (int)h.kind, (int)h.obj->id);
    }
}

/* ---- 9. render_row ------------------------------------------------------ */

#define RW 8
#define RH 6
#define CANARY 16

typedef struct {
    dv_t c;
    double r;
    rgb8_t rgb;
} ref_obj_t;

/* Render every row of the seed camera (fov 90, RW x RH) and compare each
 * pixel with the double reference of the spheres; returns the number of
 * object pixels per output row in rows[]. */
static void render_check(const ref_obj_t *objs, int n_objs, int rows[RH], int cols[RW])
{
    cam_t c;
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, V3(0, 0, 0), V3(0, 0, -1), V3(0, 1, 0), NUM(90), NUM_ZERO, RW,
                    RH) == CAM_OK);
    uint8_t buf[CANARY + 3 * RW + CANARY], ref[3 * RW];
    static render_t state;
    CHECK(render_setup(&state, &world, &c));
    long bad_px = 0, bad_canary = 0, bad_ref = 0;
    for (int x = 0; x < RW; x++)
        cols[x] = 0;
    for (int32_t row = 0; row < RH; row++) {
        for (size_t i = 0; i < sizeof buf; i++)
            buf[i] = 0xA5;
        render_row(&state, row, buf + CANARY);
        render_row_reference(&state, row, ref);
        if (memcmp(ref, buf + CANARY, sizeof ref) != 0)
            bad_ref++;
        for (size_t i = 0; i < sizeof buf; i++)
            if ((i < CANARY || i >= CANARY + 3 * RW) && buf[i] != 0xA5)
                bad_canary++;
        rows[row] = 0;
        for (int32_t x = 0; x < RW; x++) {
            /* Reference: the ideal ray through pixel (x, y), y from the bottom. */
            int32_t y = RH - 1 - row;
            dv_t d = dnorm(dv(x - (RW - 1) / 2.0, y - (RH - 1) / 2.0, -(RH / 2.0)));
            rgb8_t want = world.background_rgb;
            double best = 1e300;
            bool marginal = false, object = false;
            for (int k = 0; k < n_objs; k++) {
                double t;
                bool m;
                if (ref_sphere(objs[k].c, objs[k].r, dv(0, 0, 0), d, &t, &m) && t < best) {
                    best = t;
                    want = objs[k].rgb;
                    object = true;
                }
                /* A pixel ray within 1% of a silhouette could go either way. */
                dv_t q = dsub(objs[k].c, dscale(d, ddot(objs[k].c, d)));
                marginal = marginal || fabs(dlen(q) - objs[k].r) < 0.01 * objs[k].r;
            }
            const uint8_t *p = buf + CANARY + 3 * x;
            bool is_obj = !(p[0] == world.background_rgb.r && p[1] == world.background_rgb.g
                            && p[2] == world.background_rgb.b);
            rows[row] += is_obj;
            cols[x] += is_obj;
            /* Away from silhouettes: the same as render_pixel through
             * cam_ray (y counted from the bottom) and the ideal ray. */
            ray_t r;
            cam_ray(&c, x, y, &r);
            rgb8_t rp = render_pixel(&world, &r);
            bool ok = marginal || (p[0] == rp.r && p[1] == rp.g && p[2] == rp.b && p[0] == want.r &&
                                   p[1] == want.g && p[2] == want.b);
            if (!ok) {
                bad_px++;
                CHECK_SWEEP(ok, "row %d x %d: got %d %d %d, want %d %d %d (object %d)", (int)row, (int)x,
                            p[0], p[1], p[2], want.r, want.g, want.b, (int)object);
            }
        }
    }
    CHECK_MSG(bad_canary == 0, "%ld canary bytes overwritten", bad_canary);
    CHECK_MSG(bad_px == 0, "%ld pixels wrong", bad_px);
    CHECK_MSG(bad_ref == 0, "%ld rows differ between render_row and render_row_reference", bad_ref);
}

static void test_render(void)
{
    int rows[RH], cols[RW];
    ref_obj_t obj;

    /* A sphere in the middle: the four central pixels only. */
    world_init(&world, col(0.2, 0.4, 0.6));
    CHECK(geom_sphere_make(&world.spheres[0], V3(0, 0, -3), NUM(1), col(1, 0, 0), 0));
    world.n_spheres = 1;
    obj.c = dv(0, 0, -3);
    obj.r = 1;
    obj.rgb = world.spheres[0].obj.rgb;
    CHECK(obj.rgb.r == 255 && obj.rgb.g == 0 && obj.rgb.b == 0);
    render_check(&obj, 1, rows, cols);
    CHECK(rows[0] == 0 && rows[1] == 0 && rows[2] == 2 && rows[3] == 2 && rows[4] == 0 && rows[5] == 0);
    CHECK(cols[3] == 2 && cols[4] == 2 && cols[0] == 0 && cols[7] == 0);

    /* A sphere in the upper half shows in the first rows only (row 0 is the
     * top of the image). */
    CHECK(geom_sphere_make(&world.spheres[0], V3(0, 2, -3), NUM(0.8), col(0, 1, 0), 0));
    obj.c = dv(0, 2, -3);
    obj.r = D(NUM(0.8));
    obj.rgb = world.spheres[0].obj.rgb;
    render_check(&obj, 1, rows, cols);
    CHECK_MSG(rows[0] > 0 && rows[RH / 2] == 0 && rows[RH / 2 + 1] == 0 && rows[RH - 1] == 0,
              "rows %d %d %d %d %d %d", rows[0], rows[1], rows[2], rows[3], rows[4], rows[5]);
    /* ... and one to the right in the right-hand columns. */
    CHECK(geom_sphere_make(&world.spheres[0], V3(2.5, -0.5, -3), NUM(0.8), col(0, 0, 1), 0));
    obj.c = dv(2.5, -0.5, -3);
    obj.rgb = world.spheres[0].obj.rgb;
    render_check(&obj, 1, rows, cols);
    CHECK_MSG(cols[RW - 1] > 0 && cols[0] == 0 && cols[RW / 2 - 1] == 0 && rows[0] == 0,
              "cols %d %d %d %d %d %d %d %d", cols[0], cols[1], cols[2], cols[3], cols[4], cols[5],
              cols[6], cols[7]);
    /* An empty world is all background. */
    world.n_spheres = 0;
    render_check(&obj, 0, rows, cols);
    CHECK(rows[0] + rows[1] + rows[2] + rows[3] + rows[4] + rows[5] == 0);
}

/* ---- colour: representation and the 8-bit rule (docs/ACCURACY.md) ----- */

static void test_color_rule(void)
{
    /* The literal quantises as the loader does: 0.7 -> 178.5 exactly. */
    static const color_t lit = {COLOR_FRAC(0.7), COLOR_FRAC(0.9), COLOR_FRAC(0.3)};
    CHECK(lit.r == N(178.5) && lit.g == N(229.5) && D(lit.b) == floor(0.3 * 255 * 65536 + 0.5) / 65536);
    rgb8_t p = color_to_rgb8(lit);
    CHECK_MSG(p.r == 179 && p.g == 230 && p.b == 77, "0.7 0.9 0.3 -> %d %d %d", p.r, p.g, p.b);
    /* Round half up, exactly at the tie and one LSB below it, every k. */
    long bad = 0;
    for (int k = 0; k < 256; k++) {
        num_t at = N(k + 0.5), below = N(k + 0.5 - 1.0 / 65536);
        rgb8_t a = color_to_rgb8(color_make(at, below, N(k)));
        int want_a = k + 1 > 255 ? 255 : k + 1;
        if (a.r != want_a || a.g != k || a.b != k)
            bad++;
        CHECK_SWEEP(a.r == want_a && a.g == k && a.b == k, "k %d: tie -> %d, below -> %d, exact -> %d", k, a.r, a.g,
                    a.b);
    }
    CHECK_MSG(bad == 0, "%ld of 256 levels wrong", bad);
    /* Clamping, and exact 8-bit colours. */
    p = color_to_rgb8(color_make(N(-3), N(300), COLOR_MAX));
    CHECK(p.r == 0 && p.g == 255 && p.b == 255);
    for (int k = 0; k < 256; k++) {
        p = color_to_rgb8(color_from_rgb8((uint8_t)k, (uint8_t)(255 - k), (uint8_t)(k ^ 0x55)));
        CHECK_SWEEP(p.r == k && p.g == 255 - k && p.b == (k ^ 0x55), "rgb8 %d round trip", k);
    }
    /* A fraction keeps a colour in 1/255 units: 200 x 0.5 = 100. */
    p = color_to_rgb8(color_scale(color_from_rgb8(200, 100, 51), N(0.5)));
    CHECK(p.r == 100 && p.g == 50 && p.b == 26);
    p = color_to_rgb8(color_filter(color_from_rgb8(200, 100, 50), N(0.25), N(1), NUM_ZERO));
    CHECK(p.r == 50 && p.g == 100 && p.b == 0);
}

/* ---- 10. overlapping objects -------------------------------------------- */

#define OW 40
#define OH 30

static double orand(uint64_t *st, double lo, double hi)
{
    return lo + (hi - lo) * (double)(check_rng_next(st) >> 11) / 9007199254740992.0;
}

/* A random box added to the world: its min corner in [x0, x1] x [y0, y1]
 * x [z0, z1], each side in [s0, s1], a random colour; id counts it. */
static void add_random_box(uint64_t *st, double x0, double x1, double y0, double y1, double z0, double z1, double s0,
                           double s1, uint16_t *id)
{
    double bx = orand(st, x0, x1), by = orand(st, y0, y1), bz = orand(st, z0, z1);
    if (geom_box_make(&world.boxes[world.n_boxes], V3(bx, by, bz),
                      V3(bx + orand(st, s0, s1), by + orand(st, s0, s1), bz + orand(st, s0, s1)),
                      col(orand(st, 0, 1), orand(st, 0, 1), orand(st, 0, 1)), *id))
        world.n_boxes++, (*id)++;
}

/* Point (x, y, z) turned by ang about y, then tilted by tilt about x,
 * scaled and moved to c. */
static vec3_t turned(double x, double y, double z, double ang, double tilt, double scale, double cx, double cy,
                     double cz)
{
    double x1 = x * cos(ang) - z * sin(ang), z1 = x * sin(ang) + z * cos(ang);
    double y1 = y * cos(tilt) - z1 * sin(tilt), z2 = y * sin(tilt) + z1 * cos(tilt);
    return V3(cx + scale * x1, cy + scale * y1, cz + scale * z2);
}

/* Nearest and second-nearest hit over every object of the world, by the
 * world-space kernels (an algorithm independent of the renderer's
 * camera-space forms and depths). */
static int oracle_pixel(const ray_t *ray, num_t *t1, num_t *t2, rgb8_t *rgb)
{
    int best = -1;
    uint16_t best_id = 0;
    *t1 = *t2 = NUM_MAX;
    *rgb = world.background_rgb;
    for (int kind = 0; kind < 4; kind++) {
        int n = kind == 0 ? world.n_planes : kind == 1 ? world.n_spheres : kind == 2 ? world.n_triangles : world.n_boxes;
        for (int i = 0; i < n; i++) {
            num_t t;
            bool hit;
            const geom_common_t *o;
            if (kind == 0) {
                hit = geom_plane_hit(&world.planes[i], ray, &t);
                o = &world.planes[i].obj;
            } else if (kind == 1) {
                hit = geom_sphere_hit(&world.spheres[i], ray, &t);
                o = &world.spheres[i].obj;
            } else if (kind == 2) {
                hit = geom_triangle_hit(&world.triangles[i], ray, &t);
                o = &world.triangles[i].obj;
            } else {
                hit = geom_box_hit(&world.boxes[i], ray, &t);
                o = &world.boxes[i].obj;
            }
            if (!hit)
                continue;
            if (t < *t1 || (t == *t1 && o->id < best_id)) {
                *t2 = *t1;
                *t1 = t;
                best = o->id;
                best_id = o->id;
                *rgb = o->rgb;
            } else if (t < *t2) {
                *t2 = t;
            }
        }
    }
    return best;
}

/* Row `row` of state by render_row into fast[] (w pixels, at most OW)
 * and by render_row_reference beside it: byte for byte the same? */
static bool row_vs_reference(render_t *state, int32_t row, int32_t w, uint8_t fast[3 * OW])
{
    uint8_t ref[3 * OW];
    render_row(state, row, fast);
    render_row_reference(state, row, ref);
    return memcmp(fast, ref, 3 * (size_t)w) == 0;
}

/* The kernels' view of a w x h frame of camera c (at most OW x OH): per
 * pixel the nearest object's id (-1: none), its colour, and whether a
 * second hit is a near tie (within 1/1000). Returns the pixels with a
 * second hit. */
static long oracle_frame(const cam_t *c, int32_t w, int32_t h, int ids[OH][OW], rgb8_t want[OH][OW],
                         bool tie[OH][OW])
{
    long overlaps = 0;
    for (int32_t row = 0; row < h; row++)
        for (int32_t x = 0; x < w; x++) {
            ray_t r;
            num_t t1, t2;
            cam_ray(c, x, h - 1 - row, &r);
            ids[row][x] = oracle_pixel(&r, &t1, &t2, &want[row][x]);
            tie[row][x] = t2 != NUM_MAX && D(t2) - D(t1) <= 1e-3 * D(t1) + 1e-4;
            overlaps += t2 != NUM_MAX;
        }
    return overlaps;
}

/* One OW x OH frame of state against the kernels: render_row must equal
 * render_row_reference byte for byte, and every pixel off the border, not
 * marked in skip (may be NULL) and whose 8 neighbours see the same object
 * (ids) must show want. what names the frame in failure messages. */
typedef struct {
    long rows_bad, interior, interior_bad, id0_px;
} frame_tally_t;

static void check_frame(render_t *state, int ids[OH][OW], rgb8_t want[OH][OW], bool skip[OH][OW],
                        const char *what, frame_tally_t *t)
{
    for (int32_t row = 0; row < OH; row++) {
        uint8_t fast[3 * OW];
        if (!row_vs_reference(state, row, OW, fast)) {
            t->rows_bad++;
            CHECK_SWEEP(false, "%s row %d: fast != reference", what, (int)row);
        }
        for (int32_t x = 1; x + 1 < OW; x++) {
            if (row == 0 || row + 1 == OH || (skip && skip[row][x]))
                continue;
            bool edge = false;
            for (int dy = -1; dy <= 1; dy++)
                for (int dx = -1; dx <= 1; dx++)
                    edge |= ids[row + dy][x + dx] != ids[row][x];
            if (edge)
                continue;
            t->interior++;
            t->id0_px += ids[row][x] == 0;
            const uint8_t *p = &fast[3 * x];
            rgb8_t w = want[row][x];
            if (p[0] != w.r || p[1] != w.g || p[2] != w.b) {
                t->interior_bad++;
                CHECK_SWEEP(false, "%s row %d x %d: got %d %d %d, want %d %d %d (object %d)", what, (int)row,
                            (int)x, p[0], p[1], p[2], w.r, w.g, w.b, ids[row][x]);
            }
        }
    }
}

/* Random worlds whose objects overlap on screen (planes, spheres,
 * triangles, boxes in one region; both camera kinds; arbitrary colours):
 * render_row must equal render_row_reference byte for byte, and every
 * pixel away from silhouettes (its 8 neighbours see the same object) and
 * from near ties (second hit within 1/1000 of the first) must show the
 * nearest object of the world-space kernels. Cap: 0 such pixels wrong. */
static void test_render_overlap(void)
{
    uint64_t st = 0x5eed0ffe12ull;
    static int ids[OH][OW];
    static rgb8_t want[OH][OW];
    static bool tie[OH][OW];
    long overlaps = 0;
    frame_tally_t tally = {0, 0, 0, 0};
    for (int it = 0; it < 120; it++) {
        world_init(&world, col(orand(&st, 0, 1), orand(&st, 0, 1), orand(&st, 0, 1)));
        uint16_t id = 0;
        int np = (int)(check_rng_next(&st) % 3), ns = (int)(check_rng_next(&st) % 5),
            nt = (int)(check_rng_next(&st) % 4), nb = (int)(check_rng_next(&st) % 3);
        for (int i = 0; i < np; i++) {
            vec3_t n = V3(orand(&st, -0.5, 0.5), orand(&st, 0.2, 1), orand(&st, -0.3, 1));
            if (geom_plane_make(&world.planes[world.n_planes], V3(0, orand(&st, -3, -1), orand(&st, -12, -6)), n,
                                col(orand(&st, 0, 1), orand(&st, 0, 1), orand(&st, 0, 1)), id))
                world.n_planes++, id++;
        }
        for (int i = 0; i < ns; i++)
            if (geom_sphere_make(&world.spheres[world.n_spheres],
                                 V3(orand(&st, -2, 2), orand(&st, -1.5, 1.5), orand(&st, -7, -3)),
                                 N(orand(&st, 0.3, 1.5)), col(orand(&st, 0, 1), orand(&st, 0, 1), orand(&st, 0, 1)),
                                 id))
                world.n_spheres++, id++;
        for (int i = 0; i < nt; i++) {
            double x = orand(&st, -2, 2), y = orand(&st, -1.5, 1.5), z = orand(&st, -7, -3);
            if (geom_triangle_make(&world.triangles[world.n_triangles], V3(x, y, z),
                                   V3(x + orand(&st, -2, 2), y + orand(&st, 0.5, 2), z + orand(&st, -2, 2)),
                                   V3(x + orand(&st, 0.5, 2), y + orand(&st, -2, 2), z + orand(&st, -2, 2)),
                                   col(orand(&st, 0, 1), orand(&st, 0, 1), orand(&st, 0, 1)), id))
                world.n_triangles++, id++;
        }
        world_mesh_update(&world); /* written directly: link the triangles (world_add_triangle would) */
        for (int i = 0; i < nb; i++)
            add_random_box(&st, -2, 2, -1.5, 1.5, -7, -3, 0.2, 2, &id);
        cam_t c;
        bool ortho = it % 3 == 2;
        vec3_t eye = V3(orand(&st, -1, 1), orand(&st, -0.5, 1.5), orand(&st, 0, 2));
        vec3_t gaze = V3(orand(&st, -0.2, 0.2), orand(&st, -0.3, 0.1), -1);
        CHECK(cam_setup(&c, ortho ? CAM_ORTHOGRAPHIC : CAM_PERSPECTIVE, eye, gaze, V3(0, 1, 0),
                        N(orand(&st, 30, 90)), N(orand(&st, 4, 10)), OW, OH) == CAM_OK);
        static render_t state;
        CHECK(render_setup(&state, &world, &c));
        overlaps += oracle_frame(&c, OW, OH, ids, want, tie);
        char what[64];
        snprintf(what, sizeof what, "scene %d (%s)", it, ortho ? "ortho" : "persp");
        check_frame(&state, ids, want, tie, what, &tally);
    }
    printf("overlap: %ld interior pixels checked, %ld with two or more hits, %ld wrong, %ld rows fast != reference\n",
           tally.interior, overlaps, tally.interior_bad, tally.rows_bad);
    CHECK_MSG(tally.interior > 20000 && overlaps > 5000, "too few pixels exercised: %ld interior, %ld overlaps",
              tally.interior, overlaps);
    CHECK_MSG(tally.interior_bad == 0, "%ld interior pixels differ from the kernels' nearest object",
              tally.interior_bad);
    CHECK_MSG(tally.rows_bad == 0, "%ld rows differ between render_row and render_row_reference", tally.rows_bad);
}

/* The eye exactly on a box's surface: on a face, an edge or a corner (the
 * eye's coordinates on those axes are the box's own min or max, in the
 * build's numbers; on the other axes strictly inside), random box, gaze,
 * up and fov, and a plane behind. The kernels' rule: a hit needs t > 0, so
 * a ray that leaves the box at once misses it and one that enters it hits
 * its far face. render_row must equal render_row_reference byte for byte,
 * and every pixel away from silhouettes (its 8 neighbours see the same
 * object) must show what the world-space kernels see. Cap: 0 wrong. */
static void test_render_eye_on_box(void)
{
    uint64_t st = 0xb0c5eed1ull;
    static int ids[OH][OW];
    static rgb8_t want[OH][OW];
    frame_tally_t tally = {0, 0, 0, 0};
    for (int it = 0; it < 90; it++) {
        world_init(&world, col(orand(&st, 0, 1), orand(&st, 0, 1), orand(&st, 0, 1)));
        double lo[3], hi[3];
        for (int a = 0; a < 3; a++) {
            lo[a] = orand(&st, -3, 1);
            hi[a] = lo[a] + orand(&st, 0.5, 3);
        }
        CHECK(geom_box_make(&world.boxes[0], V3(lo[0], lo[1], lo[2]), V3(hi[0], hi[1], hi[2]),
                            col(orand(&st, 0, 1), orand(&st, 0, 1), orand(&st, 0, 1)), 0));
        world.n_boxes = 1;
        dv_t pn = dnorm(dv(orand(&st, -1, 1), orand(&st, -1, 1), orand(&st, -1, 1)));
        CHECK(geom_plane_make(&world.planes[0], V3(pn.x * -12, pn.y * -12, pn.z * -12), V3(pn.x, pn.y, pn.z),
                              col(orand(&st, 0, 1), orand(&st, 0, 1), orand(&st, 0, 1)), 1));
        world.n_planes = 1;
        /* it % 3 + 1 axes on the surface: a face, an edge, a corner. */
        int on = it % 3 + 1, first = (int)(check_rng_next(&st) % 3);
        num_t e[3];
        for (int a = 0; a < 3; a++) {
            int k = (a - first + 3) % 3;
            if (k < on)
                e[a] = geom_axis((check_rng_next(&st) & 1) ? world.boxes[0].max : world.boxes[0].min, a);
            else
                e[a] = N(orand(&st, lo[a] + 0.1, hi[a] - 0.1));
        }
        cam_t c;
        vec3_t gaze = V3(orand(&st, -1, 1), orand(&st, -1, 1), orand(&st, -1, 1));
        vec3_t up = V3(orand(&st, -1, 1), orand(&st, -1, 1), orand(&st, -1, 1));
        if (cam_setup(&c, CAM_PERSPECTIVE, vec3_make(e[0], e[1], e[2]), gaze, up, N(orand(&st, 30, 150)),
                      NUM_ZERO, OW, OH) != CAM_OK)
            continue; /* up nearly parallel to the gaze */
        static render_t state;
        CHECK(render_setup(&state, &world, &c));
        for (int32_t row = 0; row < OH; row++)
            for (int32_t x = 0; x < OW; x++) {
                ray_t r;
                hit_t h;
                cam_ray(&c, x, OH - 1 - row, &r);
                bool found = world_hit(&world, &r, &h);
                ids[row][x] = found ? h.obj->id : -1;
                want[row][x] = found ? h.obj->rgb : world.background_rgb;
            }
        char what[64];
        snprintf(what, sizeof what, "eye on box %d (%d axes on the surface)", it, on);
        check_frame(&state, ids, want, NULL, what, &tally);
    }
    /* The box is object 0 (its scene id), the plane object 1. */
    long box_px = tally.id0_px, other_px = tally.interior - tally.id0_px;
    printf("eye on box: %ld interior pixels checked (%ld box, %ld not), %ld wrong, %ld rows fast != reference\n",
           tally.interior, box_px, other_px, tally.interior_bad, tally.rows_bad);
    CHECK_MSG(box_px > 10000 && other_px > 10000, "too few pixels exercised: %ld box, %ld not", box_px, other_px);
    CHECK_MSG(tally.interior_bad == 0, "%ld interior pixels differ from the kernels", tally.interior_bad);
    CHECK_MSG(tally.rows_bad == 0, "%ld rows differ between render_row and render_row_reference", tally.rows_bad);
}

/* Object i at column x of row `row`: -1 when it does not cover the pixel
 * or has no depth range, else whether its depth lies inside the range. */
static int range_check(const render_t *rs, uint16_t i, int32_t x, int32_t row)
{
    const vis_t *r = &rs->vis;
    int32_t ix = 2 * x - r->cam->width + 1, iy = 2 * (r->cam->height - 1 - row) - r->cam->height + 1;
    if (!r->obj[i].ranged || !render_covers(&r->obj[i], ix, iy))
        return -1;
    return render_range_check(r, i, ix, iy);
}

#if FXRT_NUMBER == FXRT_Q16
/* render_depth_less (render_int.h), the strict order of two packed depths
 * n / d * 2^e, against the exact order of the rationals in 128-bit
 * integers (cross-multiplied, shifted by the exponent difference). This
 * binary's build decides which code path is checked: test_geom_q16 the
 * 64-bit products, test_geom_q16_nohw the Cortex-M0's (15-bit products
 * first, then the exact ones). Inputs: every field from its full range,
 * and near ties (b from a by a few units of n or d, or with n and d
 * scaled alike to within a unit, at the edges of the M0 path's
 * first bounds, across exponent boundaries, equal values in another
 * representation), 10^6 pairs. */
static int depth_exact_cmp(render_depth_t a, render_depth_t b)
{
    uint32_t an = (uint32_t)a & 0xffffffu, bn = (uint32_t)b & 0xffffffu;
    int ea = (int8_t)(uint8_t)((uint32_t)a >> 24), eb = (int8_t)(uint8_t)((uint32_t)b >> 24);
    uint32_t ad = (uint32_t)(a >> 32), bd = (uint32_t)(b >> 32);
    if (an == 0 || bn == 0)
        return an == bn ? 0 : (an == 0 ? -1 : 1);
    /* a vs b: an bd 2^ea vs bn ad 2^eb; the ratios lie in (1/2, 2) */
    if (ea - eb > 8)
        return 1;
    if (eb - ea > 8)
        return -1;
    __extension__ typedef unsigned __int128 u128;
    u128 l = (u128)an * bd, g = (u128)bn * ad;
    if (ea > eb)
        l <<= ea - eb;
    else
        g <<= eb - ea;
    return l < g ? -1 : (l > g ? 1 : 0);
}

/* v clamped to a packed depth's n or d range, [2^23, 2^24). */
static uint32_t depth_part(uint32_t v) { return v < (1u << 23) ? (1u << 23) : (v >= (1u << 24) ? (1u << 24) - 1 : v); }

static void test_render_depth_less(void)
{
    uint64_t st = 0x5eed0000ull + 77;
    long pairs = 0, ties = 0, wrong = 0;
    for (long k = 0; k < 1000000; k++) {
        uint64_t r1 = check_rng_next(&st), r2 = check_rng_next(&st);
        uint32_t an = (uint32_t)(1u << 23 | (r1 & 0x7fffffu)), ad = (uint32_t)(1u << 23 | ((r1 >> 23) & 0x7fffffu));
        int ea = (int)((r1 >> 46) % 253) - 126;
        uint32_t bn, bd;
        int eb;
        switch (k % 6) {
        case 0: /* independent */
            bn = (uint32_t)(1u << 23 | (r2 & 0x7fffffu));
            bd = (uint32_t)(1u << 23 | ((r2 >> 23) & 0x7fffffu));
            eb = ea + (int)((r2 >> 46) % 5) - 2;
            break;
        case 1: { /* a few units away in n or d */
            int dn = (int)(r2 % 33) - 16, dd = (int)((r2 >> 8) % 33) - 16;
            bn = an + (uint32_t)dn;
            bd = ad + (uint32_t)dd;
            bn = depth_part(bn);
            bd = depth_part(bd);
            eb = ea;
            break;
        }
        case 2: { /* across an exponent boundary: n / d near 1 against 2 n' / d' near 2 */
            bn = (uint32_t)(1u << 23 | (r2 & 0x7fffffu));
            bd = (uint32_t)(1u << 23 | (r2 & 0x7fffffu)) + (uint32_t)((r2 >> 30) % 9) - 4;
            bd = depth_part(bd);
            an = (1u << 24) - 1 - (uint32_t)((r2 >> 40) % 64);
            ad = 1u << 23 | (uint32_t)((r2 >> 50) % 64);
            eb = ea + ((r2 >> 60) & 1 ? 1 : -1);
            break;
        }
        case 3: { /* nearly the same value: d scaled with n, then a unit or two off */
            bn = an + (uint32_t)((int)(r2 % 2001) - 1000);
            bn = depth_part(bn);
            uint64_t q = ((uint64_t)ad * bn + an / 2) / an;
            bd = (uint32_t)q + (uint32_t)((r2 >> 16) % 5) - 2;
            bd = depth_part(bd);
            eb = ea;
            break;
        }
        case 4: { /* at the edges of the top-15-bit bounds: a's products at the top of theirs, b's at the bottom */
            uint32_t a9 = an >> 9, ad9 = ad >> 9, bd9 = (uint32_t)(1u << 14 | (r2 & 0x3fffu));
            uint64_t target = (uint64_t)a9 * bd9 + a9 + bd9 + 1 + (uint64_t)((r2 >> 14) % 2049) - 1024;
            uint32_t b9 = (uint32_t)(target / ad9);
            b9 = b9 < (1u << 14) ? (1u << 14) : (b9 >= (1u << 15) ? (1u << 15) - 1 : b9);
            an = a9 << 9 | 511;
            bd = bd9 << 9 | 511;
            bn = b9 << 9;
            ad = ad9 << 9 | (uint32_t)((r2 >> 30) & 1);
            eb = ea;
            break;
        }
        default: { /* the same value as another fraction: p s / q s against p t / q t */
            uint32_t p = 2048 + (uint32_t)(r2 % 848), q = 2048 + (uint32_t)((r2 >> 10) % 848);
            uint32_t s1 = 4096 + (uint32_t)((r2 >> 20) % 1696), t1 = 4096 + (uint32_t)((r2 >> 32) % 1696);
            an = p * s1;
            ad = q * s1;
            bn = p * t1;
            bd = q * t1;
            eb = ea;
            break;
        }
        }
        if (ea < -126 || ea > 126)
            ea = 0;
        eb = eb < -126 ? -126 : (eb > 126 ? 126 : eb);
        render_depth_t a = RENDER_DEPTH(an, ad, ea), b = RENDER_DEPTH(bn, bd, eb);
        if (k % 1000 == 0)
            a = RENDER_DEPTH(0, ad, 0); /* t = 0 */
        int c = depth_exact_cmp(a, b);
        bool lt = render_depth_less(a, b), gt = render_depth_less(b, a);
        pairs++;
        ties += c == 0;
        if (lt != (c < 0) || gt != (c > 0)) {
            wrong++;
            CHECK_SWEEP(false, "n %u d %u e %d against n %u d %u e %d: less %d/%d, exact %d", (unsigned)(a & 0xffffff),
                        (unsigned)(a >> 32), (int)(int8_t)(a >> 24), bn, bd, eb, lt, gt, c);
        }
    }
    printf("render_depth_less: %ld pairs (%ld exact ties), %ld wrong\n", pairs, ties, wrong);
    CHECK_MSG(wrong == 0 && ties > 1000, "%ld wrong of %ld, %ld ties", wrong, pairs, ties);
}
#else
static void test_render_depth_less(void) {}
#endif

/* An empty world (black background) for random scene it; true when its
 * camera is to be orthographic (every fourth scene). */
static bool random_world_begin(int it)
{
    world_init(&world, col(0, 0, 0));
    return it % 4 == 3;
}

/* Depth ranges (render_setup: from the camera-space z of an object's
 * points; a sphere seen from outside, from the cap that faces the eye; a
 * box, from the corners of the faces set up): render_settle decides an
 * overlap from them without a depth, so every depth the forms give must
 * lie inside. Random spheres from far away to just outside (R / L up to
 * 0.999, where the cap is nearly a point) and around the view, tiny and
 * large ones, boxes with the eye outside on every side, triangles, both
 * camera kinds: every covered pixel of every object checked
 * (render_range_check). Cap: 0 outside. */
static void test_render_ranges(void)
{
    uint64_t st = 0x7a4e9e5ull;
    long checked = 0, outside = 0, spheres_near = 0, zoomed_px = 0;
    for (int it = 0; it < 400; it++) {
        bool ortho = random_world_begin(it);
        uint16_t id = 0;
        vec3_t eye = V3(orand(&st, -2, 2), orand(&st, -2, 2), orand(&st, -2, 2));
        for (int i = 0; i < 4; i++) {
            /* Direction from the eye within about 40 degrees of the gaze
             * (-z), distance L = R / rho. */
            double dx = orand(&st, -0.8, 0.8), dy = orand(&st, -0.6, 0.6), dl = sqrt(dx * dx + dy * dy + 1);
            double rad = exp(orand(&st, log(0.01), log(20)));
            double rho = it % 2 ? orand(&st, 0.9, 0.999) : orand(&st, 0.01, 0.9);
            double l = rad / rho;
            if (l > 3000)
                continue;
            spheres_near += rho > 0.98;
            if (geom_sphere_make(&world.spheres[world.n_spheres],
                                 V3(D(eye.x) + l * dx / dl, D(eye.y) + l * dy / dl,
                                    D(eye.z) - l / dl),
                                 N(rad), col(orand(&st, 0, 1), orand(&st, 0, 1), orand(&st, 0, 1)), id))
                world.n_spheres++, id++;
        }
        for (int i = 0; i < 2; i++)
            add_random_box(&st, -4, 4, -4, 4, -8, 1, 0.1, 4, &id);
        double x = orand(&st, -3, 3), y = orand(&st, -3, 3), z = orand(&st, -9, -1);
        if (geom_triangle_make(&world.triangles[0], V3(x, y, z),
                               V3(x + orand(&st, -3, 3), y + orand(&st, 0.5, 3), z + orand(&st, -3, 3)),
                               V3(x + orand(&st, 0.5, 3), y + orand(&st, -3, 3), z + orand(&st, -3, 3)),
                               col(orand(&st, 0, 1), orand(&st, 0, 1), orand(&st, 0, 1)), id))
            world.n_triangles = 1, id++;
        cam_t c;
        vec3_t gaze = V3(orand(&st, -0.1, 0.1), orand(&st, -0.1, 0.1), -1);
        if (cam_setup(&c, ortho ? CAM_ORTHOGRAPHIC : CAM_PERSPECTIVE, eye, gaze, V3(0, 1, 0),
                      N(orand(&st, 20, 100)), N(orand(&st, 2, 20)), OW, OH) != CAM_OK)
            continue;
        static render_t state;
        if (!render_setup(&state, &world, &c))
            continue;
        for (uint16_t i = 0; i < state.vis.count; i++)
            for (int32_t row = 0; row < OH; row++)
                for (int32_t px = 0; px < OW; px++) {
                    int k = range_check(&state, i, px, row);
                    checked += k >= 0;
                    if (k == 0) {
                        outside++;
                        CHECK_SWEEP(false, "scene %d (%s) object %d: depth at column %d row %d outside its range",
                                    it, ortho ? "ortho" : "persp", (int)i, (int)px, (int)row);
                    }
                }
    }
    /* The cap's deepest point is a silhouette point: a camera zoomed in
     * (fov 0.2 to 5 degrees) on a random tangent point q = c + R m,
     * m = rho w + sqrt(1 - rho^2) v (v a random unit vector normal to w),
     * gazing just inside it, puts pixel centres within a small fraction of
     * a pixel of q, where the depth is within a hair of the range's end. */
    for (int it = 0; it < 300; it++) {
        world_init(&world, col(0, 0, 0));
        double e[3] = {orand(&st, -5, 5), orand(&st, -5, 5), orand(&st, -5, 5)};
        double rad = exp(orand(&st, log(0.01), log(20))), rho = orand(&st, 0.01, 0.999), l = rad / rho;
        double w[3] = {orand(&st, -1, 1), orand(&st, -1, 1), orand(&st, -1, 1)}, a[3] = {0, 0, 0};
        double wl = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
        if (wl < 0.1 || l > 3000)
            continue;
        for (int k = 0; k < 3; k++)
            w[k] /= wl; /* from the centre towards the eye */
        a[fabs(w[0]) < 0.5 ? 0 : 2] = 1; /* v: a unit vector normal to w */
        double v[3] = {w[1] * a[2] - w[2] * a[1], w[2] * a[0] - w[0] * a[2], w[0] * a[1] - w[1] * a[0]};
        double vl = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), ang = orand(&st, 0, 2 * PI);
        double u[3] = {w[1] * v[2] - w[2] * v[1], w[2] * v[0] - w[0] * v[2], w[0] * v[1] - w[1] * v[0]};
        double cc[3], g[3];
        for (int k = 0; k < 3; k++) {
            double vk = (cos(ang) * v[k] + sin(ang) * u[k]) / vl;
            cc[k] = e[k] - l * w[k];
            g[k] = cc[k] + 0.99999 * rad * (rho * w[k] + sqrt(1 - rho * rho) * vk) - e[k];
        }
        if (!geom_sphere_make(&world.spheres[0], V3(cc[0], cc[1], cc[2]), N(rad), col(0.5, 0.25, 0.75), 0))
            continue;
        world.n_spheres = 1;
        cam_t c;
        if (cam_setup(&c, CAM_PERSPECTIVE, V3(e[0], e[1], e[2]), V3(g[0], g[1], g[2]),
                      fabs(g[1]) < 0.9 * sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]) ? V3(0, 1, 0) : V3(1, 0, 0),
                      N(orand(&st, 0.2, 5)), NUM_ZERO, OW, OH) != CAM_OK)
            continue;
        static render_t zoomed;
        if (!render_setup(&zoomed, &world, &c))
            continue;
        for (int32_t row = 0; row < OH; row++)
            for (int32_t px = 0; px < OW; px++) {
                int k = range_check(&zoomed, 0, px, row);
                checked += k >= 0;
                zoomed_px += k >= 0;
                if (k == 0) {
                    outside++;
                    CHECK_SWEEP(false, "zoomed scene %d: depth at column %d row %d outside the sphere's range", it,
                                (int)px, (int)row);
                }
            }
    }
    printf("ranges: %ld covered pixels checked (%ld spheres with R / L > 0.98, %ld pixels zoomed in on a "
           "silhouette), %ld outside their object's range\n",
           checked, spheres_near, zoomed_px, outside);
    CHECK_MSG(checked > 100000 && spheres_near > 50 && zoomed_px > 50000,
              "too few pixels exercised: %ld, %ld near spheres, %ld zoomed", checked, spheres_near, zoomed_px);
    CHECK_MSG(outside == 0, "%ld depths outside their object's range", outside);
}

#if FXRT_NUMBER == FXRT_Q16
/* A flat piece marked front (render_setup_object: N and D of one strict
 * sign at the four corners of its pixel bounds) has its coverage decided
 * by its edges alone (render_runs_flat skips N and D). Checked at every
 * pixel of its bounds, not just the corners: triangles and boxes anywhere
 * around the eye, straddling its plane, nearly edge-on, tiny and huge,
 * and a plane in every direction, both camera kinds. Also that the flag
 * is set often enough to matter and not always. */
static void test_render_front(void)
{
    uint64_t st = 0xf407e11ull;
    long pieces = 0, front = 0, pixels = 0, wrong = 0;
    for (int it = 0; it < 600; it++) {
        bool ortho = random_world_begin(it);
        uint16_t id = 0;
        double size = exp(orand(&st, log(0.05), log(50)));
        for (int i = 0; i < 2; i++) {
            double x = orand(&st, -6, 6), y = orand(&st, -6, 6), z = orand(&st, -12, 3), sk = it % 5 == 0 ? 0.02 : 1;
            if (geom_triangle_make(&world.triangles[world.n_triangles], V3(x, y, z),
                                   V3(x + size * orand(&st, -1, 1), y + size * orand(&st, -1, 1), z + sk * size * orand(&st, -1, 1)),
                                   V3(x + size * orand(&st, -1, 1), y + size * orand(&st, -1, 1), z + sk * size * orand(&st, -1, 1)),
                                   col(orand(&st, 0, 1), orand(&st, 0, 1), orand(&st, 0, 1)), id))
                world.n_triangles++, id++;
        }
        world_mesh_update(&world); /* written directly: link the triangles (world_add_triangle would) */
        double bx = orand(&st, -6, 6), by = orand(&st, -6, 6), bz = orand(&st, -12, 3);
        if (geom_box_make(&world.boxes[0], V3(bx, by, bz),
                          V3(bx + size * orand(&st, 0.01, 1), by + size * orand(&st, 0.01, 1), bz + size * orand(&st, 0.01, 1)),
                          col(orand(&st, 0, 1), orand(&st, 0, 1), orand(&st, 0, 1)), id))
            world.n_boxes = 1, id++;
        if (geom_plane_make(&world.planes[0], V3(orand(&st, -5, 5), orand(&st, -5, 5), orand(&st, -5, 5)),
                            V3(orand(&st, -1, 1), orand(&st, -1, 1), orand(&st, -1, 1)),
                            col(orand(&st, 0, 1), orand(&st, 0, 1), orand(&st, 0, 1)), id))
            world.n_planes = 1, id++;
        cam_t c;
        vec3_t gaze = V3(orand(&st, -0.3, 0.3), orand(&st, -0.3, 0.3), -1);
        if (cam_setup(&c, ortho ? CAM_ORTHOGRAPHIC : CAM_PERSPECTIVE, V3(0, 0, 0), gaze, V3(0, 1, 0),
                      N(orand(&st, 20, 120)), N(orand(&st, 2, 20)), OW, OH) != CAM_OK)
            continue;
        static render_t state;
        if (!render_setup(&state, &world, &c))
            continue;
        for (uint16_t i = 0; i < state.vis.count; i++) {
            const render_obj_t *o = &state.vis.obj[i];
            if (o->kind != RENDER_FLAT && o->kind != RENDER_BOX)
                continue;
            for (int k = 0; k < o->nflat; k++) {
                const render_flat_t *f = render_face(o, k);
                bool box = o->kind == RENDER_BOX;
                int32_t x0 = box ? o->u.face[k].x0 : o->x0, x1 = box ? o->u.face[k].x1 : o->x1;
                int32_t r0 = box ? o->u.face[k].r0 : o->r0, r1 = box ? o->u.face[k].r1 : o->r1;
                pieces++;
                if (!f->front)
                    continue;
                front++;
                for (int32_t row = r0; row <= r1; row++)
                    for (int32_t x = x0; x <= x1; x++) {
                        int32_t ix = 2 * x - OW + 1, iy = OH - 1 - 2 * row;
                        render_k_t n = rlin_at(&f->n, ix, iy), d = rlin_at(&f->d, ix, iy);
                        pixels++;
                        if (!((n > 0 && d > 0) || (n < 0 && d < 0))) {
                            wrong++;
                            CHECK_SWEEP(false, "scene %d object %d piece %d: front, but N %lld D %lld at column %d row %d",
                                        it, (int)i, k, (long long)n, (long long)d, (int)x, (int)row);
                        }
                    }
            }
        }
    }
    printf("front pieces: %ld of %ld flat pieces, %ld pixels of their bounds checked, %ld without one sign of N and D\n",
           front, pieces, pixels, wrong);
    CHECK_MSG(front > pieces / 5 && front < pieces - pieces / 10 && pixels > 100000,
              "too little exercised: %ld front of %ld, %ld pixels", front, pieces, pixels);
    CHECK_MSG(wrong == 0, "%ld pixels of front pieces without one strict sign of N and D", wrong);
}
#else
static void test_render_front(void) {}
#endif

#if FXRT_NUMBER == FXRT_Q16
/* A plane's rows (render_setup: render_plane_rows bisects for the rows
 * beyond its horizon once per frame, from the front test at the ends of
 * a row): a row must lie in r0..r1 exactly when some pixel of it passes
 * the plane's front test (N and D of one strict sign), each pixel's forms
 * evaluated from scratch. Random planes (any point and normal, some
 * through the eye's height, some nearly edge-on), eyes and gazes up and
 * down (horizons across the frame, above it, below it), both camera
 * kinds, frames from 1 to 200 rows. Cap: 0 rows wrong. */
static void test_render_plane_rows(void)
{
    uint64_t st = 0x91a4e50ull;
    long rows = 0, covered = 0, wrong = 0, cut = 0, planes = 0;
    for (int it = 0; it < 3000; it++) {
        bool ortho = random_world_begin(it);
        double ey = orand(&st, -3, 3);
        vec3_t eye = V3(orand(&st, -3, 3), ey, orand(&st, -3, 3));
        vec3_t n = it % 7 == 0 ? V3(orand(&st, -0.01, 0.01), 1, orand(&st, -0.01, 0.01))
                               : V3(orand(&st, -1, 1), orand(&st, -1, 1), orand(&st, -1, 1));
        vec3_t a = it % 5 == 0 ? V3(orand(&st, -5, 5), ey + orand(&st, -1e-3, 1e-3), orand(&st, -5, 5))
                               : V3(orand(&st, -8, 8), orand(&st, -8, 8), orand(&st, -8, 8));
        if (!geom_plane_make(&world.planes[0], a, n, col(orand(&st, 0, 1), orand(&st, 0, 1), orand(&st, 0, 1)), 0))
            continue;
        world.n_planes = 1;
        int32_t w = 1 + (int32_t)(rng() % 160), h = 1 + (int32_t)(rng() % 200);
        vec3_t gaze = V3(orand(&st, -1, 1), orand(&st, -1.5, 1.5), orand(&st, -1, 1));
        cam_t c;
        if (cam_setup(&c, ortho ? CAM_ORTHOGRAPHIC : CAM_PERSPECTIVE, eye, gaze, V3(0, 1, 0), N(orand(&st, 10, 150)),
                      N(orand(&st, 0.5, 20)), w, h) != CAM_OK)
            continue;
        static render_t state;
        if (!render_setup(&state, &world, &c) || state.vis.count != 1)
            continue;
        const render_obj_t *o = &state.vis.obj[0];
        const render_flat_t *f = render_face(o, 0);
        planes++;
        cut += o->r0 <= o->r1 && (o->r0 > 0 || o->r1 < h - 1);
        for (int32_t row = 0; row < h; row++) {
            bool any = false;
            for (int32_t x = 0; x < w && !any; x++) {
                render_k_t nv = rlin_at(&f->n, 2 * x - w + 1, h - 1 - 2 * row);
                render_k_t dv = rlin_at(&f->d, 2 * x - w + 1, h - 1 - 2 * row);
                any = (nv > 0 && dv > 0) || (nv < 0 && dv < 0);
            }
            bool in = row >= o->r0 && row <= o->r1;
            rows++;
            covered += any;
            if (in != any) {
                wrong++;
                CHECK_SWEEP(false, "frame %d (%s, %dx%d): row %d %s the plane's rows %d..%d, but %s pixel passes", it,
                            ortho ? "ortho" : "persp", (int)w, (int)h, (int)row, in ? "in" : "not in", (int)o->r0,
                            (int)o->r1, any ? "a" : "no");
            }
        }
    }
    printf("plane rows: %ld planes (%ld with a horizon inside the frame), %ld rows (%ld covered), %ld wrong\n", planes,
           cut, rows, covered, wrong);
    CHECK_MSG(planes > 2000 && cut > planes / 10 && covered > rows / 5 && covered < rows - rows / 5,
              "too little exercised: %ld planes, %ld cut, %ld of %ld rows covered", planes, cut, covered, rows);
    CHECK_MSG(wrong == 0, "%ld rows in or out of a plane's rows against its pixels", wrong);
}
#else
static void test_render_plane_rows(void) {}
#endif

#if FXRT_NUMBER == FXRT_Q16 && RENDER_STEPPED && !FXRT_NO_SPANS
/* Depth ranges over stretches of a row (render_span_range: render_row's
 * claiming settles a whole stretch of one owner from them): every column
 * of a stretch that the object covers must have its depth (from its forms
 * at the pixel) inside the range. Random scenes of spheres (tiny to
 * large, from far to nearly touching the eye), boxes, triangles and a
 * plane; every row rendered first (a sphere's range needs the row forms
 * render_row leaves), then every covered run of every object on it,
 * whole and as random stretches, checked column by column. */
static void test_render_span_ranges(void)
{
    uint64_t st = 0x5b4ae11ull;
    long ranged[4] = {0, 0, 0, 0}, cols = 0, wrong = 0, cached_bad = 0;
    static uint8_t rgb[OW * 3];
    for (int it = 0; it < 150; it++) {
        world_init(&world, col(0, 0, 0));
        uint16_t id = 0;
        bool ortho = it % 5 == 4;
        bool axis = it % 3 == 0; /* the first sphere straight ahead: b constant along the rows */
        for (int i = 0; i < 5; i++) {
            double rad = exp(orand(&st, log(0.05), log(6)));
            if (geom_sphere_make(&world.spheres[world.n_spheres],
                                 V3(axis && i == 0 ? 0 : orand(&st, -4, 4), orand(&st, -3, 3),
                                    orand(&st, -14, -1 - rad * (it % 2 ? 1.02 : 3))),
                                 N(rad), col(orand(&st, 0, 1), orand(&st, 0, 1), orand(&st, 0, 1)), id))
                world.n_spheres++, id++;
        }
        for (int i = 0; i < 2; i++) {
            /* The second box mostly beside the eye, reaching behind it:
             * faces seen at grazing angles, their planes' horizons on screen. */
            bool beside = i == 1 && it % 2;
            double bx = beside ? orand(&st, 0.5, 3) * (it % 4 == 1 ? -1 : 1) : orand(&st, -5, 4), by = orand(&st, -4, 3);
            double bz = beside ? orand(&st, -6, -1) : orand(&st, -12, -2), dz = beside ? orand(&st, 1.5, 8) : orand(&st, 0.1, 5);
            if (it % 4 == 1 && beside)
                bx -= 5;
            if (geom_box_make(&world.boxes[world.n_boxes], V3(bx, by, bz),
                              V3(bx + orand(&st, 0.1, 5), by + orand(&st, 0.1, 5), bz + dz),
                              col(orand(&st, 0, 1), orand(&st, 0, 1), orand(&st, 0, 1)), id))
                world.n_boxes++, id++;
            double x = orand(&st, -5, 5), y = orand(&st, -4, 4), z = orand(&st, -12, -1);
            if (geom_triangle_make(&world.triangles[world.n_triangles], V3(x, y, z),
                                   V3(x + orand(&st, -6, 6), y + orand(&st, 0.5, 6), z + orand(&st, -4, 4)),
                                   V3(x + orand(&st, 0.5, 6), y + orand(&st, -6, 6), z + orand(&st, -4, 4)),
                                   col(orand(&st, 0, 1), orand(&st, 0, 1), orand(&st, 0, 1)), id))
                world.n_triangles++, id++;
        }
        world_mesh_update(&world); /* written directly: link the triangles (world_add_triangle would) */
        if (geom_plane_make(&world.planes[0], V3(0, orand(&st, -4, -1), 0),
                            V3(orand(&st, -0.3, 0.3), 1, orand(&st, -0.3, 0.3)), col(orand(&st, 0, 1), 0.5, 0.5), id))
            world.n_planes = 1, id++;
        cam_t c;
        double gx = orand(&st, -0.2, 0.2), gy = orand(&st, -0.2, 0.2);
        if (cam_setup(&c, ortho ? CAM_ORTHOGRAPHIC : CAM_PERSPECTIVE, V3(0, 0, 0),
                      V3(axis ? 0 : gx, axis ? 0 : gy, -1), V3(0, 1, 0), N(orand(&st, 30, 100)),
                      N(orand(&st, 5, 20)), OW, OH) != CAM_OK)
            continue;
        static render_t state;
        if (!render_setup(&state, &world, &c))
            continue;
        for (int32_t row = 0; row < OH; row++) {
            render_row(&state, row, rgb);
            render_sphere_cache_t sc; /* none: the spheres' ranges come from their row state */
            render_sphere_cache_reset(&sc);
            state.vis.sphere_cache = &sc;
            int32_t iy = OH - 1 - 2 * row;
            for (uint16_t i = 0; i < state.vis.count; i++) {
                const render_obj_t *o = &state.vis.obj[i];
                int kind = o->kind == RENDER_SPHERE ? 0 : o->kind == RENDER_BOX ? 1 : render_face(o, 0)->edges ? 2 : 3;
                for (int32_t a = 0; a < OW;) {
                    if (!render_covers(o, 2 * a - OW + 1, iy)) {
                        a++;
                        continue;
                    }
                    int32_t b = a;
                    while (b + 1 < OW && render_covers(o, 2 * (b + 1) - OW + 1, iy))
                        b++;
                    for (int k = 0; k < 6; k++) { /* the run, its halves, its last quarter, random stretches */
                        int32_t p = k == 1 || k == 3 ? a + (b - a) * (k == 1 ? 2 : 3) / 4 : a, q = k == 2 ? a + (b - a) / 2 : b;
                        if (k > 3) {
                            p = a + (int32_t)orand(&st, 0, b - a + 0.999);
                            q = p + (int32_t)orand(&st, 0, b - p + 0.999);
                        }
                        render_depth_t lo, hi, lo2, hi2;
                        int got = render_span_range(&state.vis, i, p, q, iy, &lo, &hi, false);
                        /* The same from an empty cache (a sphere's range
                         * reuses the depth of the stretch before's first
                         * column): the cache must not change a range. */
                        render_sphere_cache_reset(&sc);
                        int got2 = render_span_range(&state.vis, i, p, q, iy, &lo2, &hi2, false);
                        if (got2 != got || (got && (render_depth_less(lo, lo2) || render_depth_less(lo2, lo) ||
                                                    render_depth_less(hi, hi2) || render_depth_less(hi2, hi)))) {
                            cached_bad++;
                            CHECK_SWEEP(false, "scene %d object %d row %d: range of columns %d..%d differs after the "
                                        "cache is emptied", it, (int)i, (int)row, (int)p, (int)q);
                        }
                        if (got == 2 && !render_span_range(&state.vis, i, p, q, iy, &lo, &hi, true))
                            got = 0; /* a sphere: its bound below apart */
                        if (!got)
                            continue;
                        ranged[kind]++;
                        for (int32_t x = p; x <= q; x++) {
                            render_depth_t t = render_depth_test(&state.vis, i, 2 * x - OW + 1, iy);
                            cols++;
                            if (render_depth_less(t, lo) || render_depth_less(hi, t)) {
                                wrong++;
                                CHECK_SWEEP(false, "scene %d object %d row %d: depth at column %d outside the range of "
                                            "columns %d..%d", it, (int)i, (int)row, (int)x, (int)p, (int)q);
                            }
                        }
                    }
                    a = b + 1;
                }
            }
            state.vis.sphere_cache = NULL;
        }
    }
    printf("stretch ranges: %ld spheres, %ld boxes, %ld triangles, %ld planes; %ld columns checked, %ld outside\n",
           ranged[0], ranged[1], ranged[2], ranged[3], cols, wrong);
    CHECK_MSG(ranged[0] > 2000 && ranged[1] > 2000 && ranged[2] > 2000 && ranged[3] > 500,
              "too few stretches ranged: %ld %ld %ld %ld", ranged[0], ranged[1], ranged[2], ranged[3]);
    CHECK_MSG(wrong == 0, "%ld depths outside their stretch's range", wrong);
    CHECK_MSG(cached_bad == 0, "%ld ranges changed by the cache", cached_bad);
}
#else
static void test_render_span_ranges(void) {}
#endif

/* Closed meshes (render_cull_meshes): an octahedron, an icosahedron and a
 * cube of 12 triangles, randomly scaled, turned and placed, wound outward
 * or inward, in front of a plane; some with one triangle dropped (open),
 * one triangle's winding flipped (inconsistent) or the octahedron's top
 * pushed below its waist (closed but not convex); the eye outside the
 * mesh's box, or at its centre; both camera kinds. render_row must equal
 * render_row_reference byte for byte and every pixel away from silhouettes
 * and near ties must show the kernels' nearest object (which never leave
 * a triangle out). Culling must happen exactly where the rule allows it:
 * some back faces in every closed convex mesh seen in perspective from
 * outside its box, none anywhere else. Cap: 0 wrong. */
static void test_render_meshes(void)
{
    static const double ico_v[12][3] = {
        {-1, 1.618, 0}, {1, 1.618, 0}, {-1, -1.618, 0}, {1, -1.618, 0}, {0, -1, 1.618}, {0, 1, 1.618},
        {0, -1, -1.618}, {0, 1, -1.618}, {1.618, 0, -1}, {1.618, 0, 1}, {-1.618, 0, -1}, {-1.618, 0, 1}};
    static const uint8_t ico_f[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                         {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                         {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                         {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7}, {9, 8, 1}};
    static const double oct_v[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    static const uint8_t oct_f[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                        {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    static const double cube_v[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                        {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    static const uint8_t cube_f[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                                          {2, 3, 7}, {2, 7, 6}, {1, 2, 6}, {1, 6, 5}, {0, 4, 7}, {0, 7, 3}};
    uint64_t st = 0x3e5ec0117ull;
    static int ids[OH][OW];
    static rgb8_t want[OH][OW];
    static bool tie[OH][OW];
    frame_tally_t tally = {0, 0, 0, 0};
    long culled_ok = 0, culled_bad = 0, convex_views = 0, mesh_orders = 0;
    for (int it = 0; it < 240; it++) {
        int shape = it % 3, variant = (it / 3) % 5; /* 0, 1: closed; 2 open; 3 inconsistent; 4 not convex */
        const double(*v)[3] = shape == 0 ? oct_v : (shape == 1 ? ico_v : cube_v);
        const uint8_t(*f)[3] = shape == 0 ? oct_f : (shape == 1 ? ico_f : cube_f);
        int nv = shape == 0 ? 6 : (shape == 1 ? 12 : 8), nf = shape == 0 ? 8 : (shape == 1 ? 20 : 12);
        if (variant == 4 && shape != 0)
            variant = 0;
        double scale = orand(&st, 0.5, 2), cx = orand(&st, -1, 1), cy = orand(&st, -1, 1), cz = orand(&st, -9, -5);
        double ang = orand(&st, 0, 2 * PI), tilt = orand(&st, -1, 1);
        vec3_t pv[12];
        for (int k = 0; k < nv; k++) {
            double x = v[k][0], y = v[k][1], z = v[k][2];
            if (variant == 4 && k == 4)
                z = -0.5; /* the top below the waist: a closed bowl */
            pv[k] = turned(x, y, z, ang, tilt, scale, cx, cy, cz); /* shared vertices: the same numbers */
        }
        world_init(&world, col(orand(&st, 0, 1), orand(&st, 0, 1), orand(&st, 0, 1)));
        uint16_t id = 0;
        if (geom_plane_make(&world.planes[0], V3(0, 0, -20), V3(0, 0.2, 1), col(0.3, 0.4, 0.5), id))
            world.n_planes = 1, id++;
        bool inward = check_rng_next(&st) % 2;
        int drop = variant == 2 ? (int)(check_rng_next(&st) % (uint64_t)nf) : -1;
        int flip = variant == 3 ? (int)(check_rng_next(&st) % (uint64_t)nf) : -1;
        for (int k = 0; k < nf; k++) {
            if (k == drop)
                continue;
            bool rev = inward != (k == flip);
            vec3_t a = pv[f[k][0]], b = pv[f[k][rev ? 2 : 1]], c = pv[f[k][rev ? 1 : 2]];
            if (geom_triangle_make(&world.triangles[world.n_triangles], a, b, c,
                                   col(orand(&st, 0, 1), orand(&st, 0, 1), orand(&st, 0, 1)), id))
                world.n_triangles++, id++;
        }
        world_mesh_update(&world); /* written directly: link the triangles (world_add_triangle would) */
        bool ortho = it % 7 == 6, eye_in = it % 11 == 10;
        vec3_t eye = eye_in ? V3(cx, cy, cz) : V3(orand(&st, -1, 1), orand(&st, -1, 1), orand(&st, 0, 2));
        vec3_t gaze = eye_in ? V3(orand(&st, -1, 1), orand(&st, -1, 1), orand(&st, -1, 1))
                             : V3(cx - D(eye.x), cy - D(eye.y), cz - D(eye.z));
        cam_t c;
        if (cam_setup(&c, ortho ? CAM_ORTHOGRAPHIC : CAM_PERSPECTIVE, eye, gaze, V3(0, 1, 0), N(orand(&st, 30, 70)),
                      N(orand(&st, 4, 8)), OW, OH) != CAM_OK)
            continue;
        static render_t state;
        CHECK(render_setup(&state, &world, &c));
        int culled = 0;
#if RENDER_MESH
        for (int k = 0; k < world.n_triangles; k++)
            culled += render_mesh_culled(&state.vis, (uint16_t)k);
        /* The same triangles added through world_add_triangle, last first:
         * the links (per triangle its bits, and which triangles share a
         * mesh) and the culled set do not depend on the order. */
        static world_t rev;
        static render_t rstate;
        int nt = world.n_triangles;
        bool added = true;
        world_init(&rev, world.background);
        for (int k = nt - 1; k >= 0 && added; k--) {
            const geom_triangle_t *t = &world.triangles[k];
            added = world_add_triangle(&rev, t->a, t->b, t->c, t->obj.color) >= 0;
        }
        CHECK_MSG(added && rev.mesh_n == nt, "mesh %d: %d triangles added, %d linked", it, rev.n_triangles, rev.mesh_n);
        if (added && rev.mesh_n == nt && world.mesh_n == nt) {
            int diff = 0;
            for (int k = 0; k < nt; k++) {
                diff += world.mesh_bits[k] != rev.mesh_bits[nt - 1 - k];
                for (int m = 0; m < nt; m++)
                    diff += (mesh_root(world.mesh_up, (uint8_t)k) == mesh_root(world.mesh_up, (uint8_t)m)) !=
                            (mesh_root(rev.mesh_up, (uint8_t)(nt - 1 - k)) == mesh_root(rev.mesh_up, (uint8_t)(nt - 1 - m)));
            }
            CHECK(render_setup(&rstate, &rev, &c));
            for (int k = 0; k < nt; k++)
                diff += render_mesh_culled(&state.vis, (uint16_t)k) != render_mesh_culled(&rstate.vis, (uint16_t)(nt - 1 - k));
            mesh_orders++;
            CHECK_SWEEP(diff == 0, "mesh %d: %d differences between the two orders of adding", it, diff);
            /* As if written directly and not linked again: nothing is culled. */
            rev.mesh_n = 0;
            CHECK(render_setup(&rstate, &rev, &c));
            int stale = 0;
            for (int k = 0; k < nt; k++)
                stale += render_mesh_culled(&rstate.vis, (uint16_t)k);
            CHECK_SWEEP(stale == 0, "mesh %d: %d triangles culled from links that are out of date", it, stale);
        }
#endif
        bool may = variant <= 1 && !ortho && !eye_in; /* closed, convex, seen from outside its box */
        if (may) {
            convex_views++;
            culled_ok += culled > 0;
        }
        if (!may && culled) {
            culled_bad++;
            CHECK_SWEEP(false, "mesh %d (shape %d, variant %d, %s%s): %d triangles culled, none allowed", it, shape,
                        variant, ortho ? "ortho" : "persp", eye_in ? ", eye inside" : "", culled);
        }
        oracle_frame(&c, OW, OH, ids, want, tie);
        char what[64];
        snprintf(what, sizeof what, "mesh %d (shape %d, variant %d)", it, shape, variant);
        check_frame(&state, ids, want, tie, what, &tally);
    }
    printf("meshes: %ld closed convex views from outside, %ld with back faces culled; %ld other meshes culled; "
           "%ld interior pixels checked, %ld wrong, %ld rows fast != reference\n",
           convex_views, culled_ok, culled_bad, tally.interior, tally.interior_bad, tally.rows_bad);
#if RENDER_MESH
    CHECK_MSG(convex_views > 50 && culled_ok == convex_views, "back faces culled in %ld of %ld closed convex views",
              culled_ok, convex_views);
#endif
    CHECK_MSG(culled_bad == 0, "%ld meshes culled that the rule excludes", culled_bad);
#if RENDER_MESH
    CHECK_MSG(mesh_orders > 200, "only %ld meshes added in both orders", mesh_orders);
#endif
    CHECK_MSG(tally.interior > 20000, "too few pixels exercised: %ld", tally.interior);
    CHECK_MSG(tally.interior_bad == 0, "%ld interior pixels differ from the kernels' nearest object",
              tally.interior_bad);
    CHECK_MSG(tally.rows_bad == 0, "%ld rows differ between render_row and render_row_reference", tally.rows_bad);
}

/* A random world for the row tests: 1 to 6 objects of every kind spread
 * across the view (so that on most rows each is alone; some overlap),
 * arbitrary colours, a plane in every fifth (it % 5 == 4). */
static void spread_world(uint64_t *st, int it)
{
    world_init(&world, col(orand(st, 0, 1), orand(st, 0, 1), orand(st, 0, 1)));
    uint16_t id = 0;
    int nobj = 1 + (int)(check_rng_next(st) % 6);
    double spread = orand(st, 0.7, 1.3); /* below 1: objects more likely to overlap */
    for (int i = 0; i < nobj; i++) {
        double x = -3.2 + 6.4 * (i + 0.5) / nobj * spread, y = orand(st, -1.5, 1.5), z = orand(st, -8, -4);
        double s = orand(st, 0.2, 1.4) * 3 / (nobj + 1);
        color_t cc = col(orand(st, 0, 1), orand(st, 0, 1), orand(st, 0, 1));
        switch (check_rng_next(st) % 3) {
        case 0:
            if (geom_sphere_make(&world.spheres[world.n_spheres], V3(x, y, z), N(s), cc, id))
                world.n_spheres++, id++;
            break;
        case 1:
            if (geom_triangle_make(&world.triangles[world.n_triangles], V3(x - s, y - s, z),
                                   V3(x + s * orand(st, -1, 1), y + s, z + orand(st, -1, 1)),
                                   V3(x + s, y + s * orand(st, -1, 1), z + orand(st, -1, 1)), cc, id))
                world.n_triangles++, id++;
            break;
        default:
            if (geom_box_make(&world.boxes[world.n_boxes], V3(x - s, y - s, z - s),
                              V3(x + s * orand(st, 0.2, 1), y + s * orand(st, 0.2, 1), z + s * orand(st, 0.2, 1)),
                              cc, id))
                world.n_boxes++, id++;
            break;
        }
    }
    if (it % 5 == 4 && geom_plane_make(&world.planes[0], V3(0, orand(st, -4, -2), 0),
                                       V3(orand(st, -0.2, 0.2), 1, orand(st, -0.2, 0.2)),
                                       col(orand(st, 0, 1), orand(st, 0, 1), orand(st, 0, 1)), id))
        world.n_planes = 1, id++;
}

/* An eye for spread_world's world: near the origin, or at the centre of
 * its first sphere when `inside` and it has one. */
static vec3_t spread_eye(uint64_t *st, bool inside)
{
    vec3_t eye = V3(orand(st, -0.5, 0.5), orand(st, -0.5, 0.5), orand(st, 0, 1));
    return inside && world.n_spheres > 0 ? world.spheres[0].center : eye;
}

#if !FXRT_NO_ORDER
/* A depth as a double (n / d * 2^e in Q16.16). */
static double depth_value(render_depth_t t)
{
#if FXRT_NUMBER == FXRT_Q16
    return render_depth_n(t) == 0 ? 0.0 : ldexp((double)render_depth_n(t) / render_depth_d(t), render_depth_e(t));
#else
    return (double)t.t;
#endif
}

#define ORDER_TOL (1.0 / 4096)

static bool on_some_row(const render_obj_t *o) { return o->r0 <= o->r1 && o->x0 <= o->x1; }

/* The visiting order (render_setup sorts the objects nearest first each
 * frame; the image does not depend on it, make bench measures what it
 * saves). Random worlds of planes, spheres, boxes, loose triangles and a
 * closed octahedron, seen from outside and from inside a sphere, both
 * camera kinds. The objects must be the world's, each once; the planes
 * first in scene order; among the objects on some row, those without a
 * depth range before the ranged ones; ranged objects outside meshes in
 * order of their near bound (to ORDER_TOL: the sort key keeps n / d to
 * about 2^-14 in Q16.16, t's float bits, a double's top 32); a mesh's triangles in scene order, placed by the
 * nearest of them. A world of more objects than FXRT_ORDER_MAX keeps
 * scene order (kind after kind). Cap: 0 of each. */
static void test_render_order(void)
{
    static const double oct_v[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    static const uint8_t oct_f[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                        {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    uint64_t st = 0x0bde5a11ull;
    long pairs = 0, bad_pairs = 0, mesh_seen = 0, bad_mesh = 0, bad_set = 0, moved = 0, unranged_seen = 0;
    for (int it = 0; it < 300; it++) {
        bool ortho = random_world_begin(it);
        uint16_t id = 0;
        int np = (int)(check_rng_next(&st) % 3), ns = (int)(check_rng_next(&st) % 8);
        int nb = (int)(check_rng_next(&st) % 4), nt = (int)(check_rng_next(&st) % 5);
        bool mesh = it % 2 == 0;
        for (int k = 0; k < np; k++)
            if (geom_plane_make(&world.planes[world.n_planes], V3(0, orand(&st, -3, 0), orand(&st, -40, -10)),
                                V3(orand(&st, -0.3, 0.3), orand(&st, 0.2, 1), orand(&st, 0.2, 1)),
                                col(orand(&st, 0, 1), orand(&st, 0, 1), orand(&st, 0, 1)), id))
                world.n_planes++, id++;
        vec3_t eye = V3(orand(&st, -1, 1), orand(&st, -1, 1), orand(&st, 0, 2));
        for (int k = 0; k < ns; k++) {
            bool around = k == 0 && it % 5 == 4; /* the eye inside: no depth range */
            vec3_t c = around ? eye : V3(orand(&st, -4, 4), orand(&st, -3, 3), orand(&st, -20, -2));
            if (geom_sphere_make(&world.spheres[world.n_spheres], c, N(around ? 1.5 : orand(&st, 0.1, 2)),
                                 col(orand(&st, 0, 1), orand(&st, 0, 1), orand(&st, 0, 1)), id))
                world.n_spheres++, id++;
        }
        for (int k = 0; k < nt; k++) {
            double x = orand(&st, -4, 4), y = orand(&st, -3, 3), z = orand(&st, -20, -2);
            if (geom_triangle_make(&world.triangles[world.n_triangles], V3(x, y, z),
                                   V3(x + orand(&st, 0.3, 2), y + orand(&st, -1, 1), z + orand(&st, -1, 1)),
                                   V3(x + orand(&st, -1, 1), y + orand(&st, 0.3, 2), z + orand(&st, -1, 1)),
                                   col(orand(&st, 0, 1), orand(&st, 0, 1), orand(&st, 0, 1)), id))
                world.n_triangles++, id++;
        }
        int mesh_first = world.n_triangles;
        if (mesh) {
            double cx = orand(&st, -3, 3), cy = orand(&st, -2, 2), cz = orand(&st, -15, -4), sc = orand(&st, 0.5, 2);
            double ang = orand(&st, 0, 2 * PI), tilt = orand(&st, -1, 1);
            vec3_t pv[6]; /* turned about y, then tilted about x: faces at different depths */
            for (int k = 0; k < 6; k++)
                pv[k] = turned(oct_v[k][0], oct_v[k][1], oct_v[k][2], ang, tilt, sc, cx, cy, cz);
            for (int k = 0; k < 8; k++)
                if (geom_triangle_make(&world.triangles[world.n_triangles], pv[oct_f[k][0]], pv[oct_f[k][1]],
                                       pv[oct_f[k][2]], col(orand(&st, 0, 1), orand(&st, 0, 1), orand(&st, 0, 1)), id))
                    world.n_triangles++, id++;
        }
        for (int k = 0; k < nb; k++)
            add_random_box(&st, -4, 4, -3, 3, -20, -2, 0.1, 2, &id);
#if RENDER_MESH
        world_mesh_update(&world);
#endif
        cam_t c;
        if (cam_setup(&c, ortho ? CAM_ORTHOGRAPHIC : CAM_PERSPECTIVE, eye, V3(orand(&st, -0.2, 0.2), orand(&st, -0.2, 0.2), -1),
                      V3(0, 1, 0), N(orand(&st, 30, 70)), N(orand(&st, 4, 12)), OW, OH) != CAM_OK)
            continue;
        static render_t state;
        CHECK(render_setup(&state, &world, &c));
        /* The world's objects, each once. */
        int total = world.n_planes + world.n_spheres + world.n_triangles + world.n_boxes, seen[4][128];
        memset(seen, 0, sizeof seen);
        for (uint16_t i = 0; i < state.vis.count; i++)
            seen[state.vis.obj[i].geom][state.vis.obj[i].index]++;
        int once = 0;
        for (int k = 0; k < 4; k++)
            for (int m = 0; m < 128; m++)
                once += seen[k][m] == 1;
        bad_set += state.vis.count != total || once != total;
        CHECK_SWEEP(state.vis.count == total && once == total, "scene %d: %d objects, %d of the world's %d once", it,
                    (int)state.vis.count, once, total);
        for (uint16_t i = 0; i < state.vis.count; i++) {
            const render_obj_t *a = &state.vis.obj[i];
            bool kind_order = i == 0 || a->geom > state.vis.obj[i - 1].geom ||
                              (a->geom == state.vis.obj[i - 1].geom && a->index > state.vis.obj[i - 1].index);
            moved += !kind_order;
            if (i < world.n_planes) {
                bad_set += a->geom != GEOM_PLANE || a->index != i;
                CHECK_SWEEP(a->geom == GEOM_PLANE && a->index == i, "scene %d: object %d is not plane %d", it, (int)i,
                            (int)i);
                continue;
            }
            if (!on_some_row(a))
                continue;
            bool am = a->geom == GEOM_TRIANGLE && a->index >= mesh_first;
            unranged_seen += !a->ranged;
            for (uint16_t j = (uint16_t)(i + 1); j < state.vis.count; j++) {
                const render_obj_t *b = &state.vis.obj[j];
                bool bm = b->geom == GEOM_TRIANGLE && b->index >= mesh_first;
                if (!on_some_row(b))
                    continue;
                pairs++;
                bool ok = true;
                if (a->ranged && !b->ranged)
                    ok = false; /* an object without a range after a ranged one */
                else if (am && bm)
                    ok = a->index < b->index, mesh_seen++; /* a mesh in scene order */
                else if (a->ranged && b->ranged && !am && !bm)
                    ok = depth_value(b->tlo) >= depth_value(a->tlo) * (1 - ORDER_TOL);
                bad_pairs += !ok;
                CHECK_SWEEP(ok, "scene %d: object %d (kind %d #%d, near %.6g) before object %d (kind %d #%d, near %.6g)",
                            it, (int)i, a->geom, a->index, depth_value(a->tlo), (int)j, b->geom, b->index,
                            depth_value(b->tlo));
            }
        }
        /* The mesh by its nearest visible triangle. */
        double mnear = -1;
        int mfirst = -1, mlast = -1;
        for (uint16_t i = 0; i < state.vis.count; i++) {
            const render_obj_t *a = &state.vis.obj[i];
            if (a->geom == GEOM_TRIANGLE && a->index >= mesh_first && on_some_row(a) && a->ranged) {
                double t = depth_value(a->tlo);
                mnear = mnear < 0 || t < mnear ? t : mnear;
                mlast = i;
                mfirst = mfirst < 0 ? i : mfirst;
            }
        }
        for (uint16_t i = 0; i < state.vis.count && mnear >= 0; i++) {
            const render_obj_t *a = &state.vis.obj[i];
            if (i < world.n_planes || !on_some_row(a) || !a->ranged || (a->geom == GEOM_TRIANGLE && a->index >= mesh_first))
                continue;
            double t = depth_value(a->tlo);
            bool ok = (i < mfirst && t <= mnear * (1 + ORDER_TOL)) || (i > mlast && t >= mnear * (1 - ORDER_TOL)) ||
                      (i > mfirst && i < mlast && fabs(t - mnear) <= mnear * ORDER_TOL);
            bad_mesh += !ok;
            CHECK_SWEEP(ok, "scene %d: object %d (near %.6g) misplaced against the mesh at %d..%d (near %.6g)", it,
                        (int)i, t, mfirst, mlast, mnear);
        }
    }
    printf("order: %ld pairs compared (%ld in a mesh), %ld objects out of scene order, %ld without a range; "
           "%ld wrong\n", pairs, mesh_seen, moved, unranged_seen, bad_set + bad_pairs + bad_mesh);
    CHECK_MSG(pairs > 5000 && mesh_seen > 500 && moved > 100 && unranged_seen > 10,
              "the sweep compared %ld pairs, %ld in a mesh, %ld objects out of scene order, %ld without a range", pairs,
              mesh_seen, moved, unranged_seen);
    CHECK_MSG(bad_set == 0 && bad_pairs == 0 && bad_mesh == 0,
              "%ld sets, %ld pairs and %ld mesh placements wrong (cap 0)", bad_set, bad_pairs, bad_mesh);
#if FXRT_ORDER_MAX < FXRT_RENDER_MAX_OBJECTS && FXRT_MAX_PLANES >= 1 && FXRT_MAX_SPHERES >= 64 && \
    FXRT_MAX_BOXES >= 64 && FXRT_MAX_TRIANGLES >= 128 && FXRT_ORDER_MAX < 257
    /* More objects than FXRT_ORDER_MAX: scene order, kind after kind. */
    world_init(&world, col(0, 0, 0));
    uint16_t id = 0;
    int want = FXRT_ORDER_MAX + 1;
    if (geom_plane_make(&world.planes[0], V3(0, -3, 0), V3(0, 1, 0), col(0.5, 0.5, 0.5), id))
        world.n_planes = 1, id++;
    for (int k = 0; id < want && k < 64; k++)
        if (geom_sphere_make(&world.spheres[world.n_spheres], V3(orand(&st, -4, 4), orand(&st, -3, 3), orand(&st, -20, -2)),
                             N(orand(&st, 0.1, 1)), col(0.5, 0.5, 0.5), id))
            world.n_spheres++, id++;
    for (int k = 0; id < want && k < 128; k++) {
        double x = orand(&st, -4, 4), y = orand(&st, -3, 3), z = orand(&st, -20, -2);
        if (geom_triangle_make(&world.triangles[world.n_triangles], V3(x, y, z), V3(x + 1, y, z), V3(x, y + 1, z + 0.5),
                               col(0.5, 0.5, 0.5), id))
            world.n_triangles++, id++;
    }
    for (int k = 0; id < want && k < 64; k++) {
        double bx = orand(&st, -4, 4), by = orand(&st, -3, 3), bz = orand(&st, -20, -2);
        if (geom_box_make(&world.boxes[world.n_boxes], V3(bx, by, bz), V3(bx + 0.5, by + 0.5, bz + 0.5),
                          col(0.5, 0.5, 0.5), id))
            world.n_boxes++, id++;
    }
    cam_t c;
    static render_t big;
    CHECK(cam_setup(&c, CAM_PERSPECTIVE, V3(0, 0, 0), V3(0, 0, -1), V3(0, 1, 0), N(50), N(4), OW, OH) == CAM_OK);
    CHECK_MSG(id == want, "%d of %d objects made", (int)id, want);
    CHECK_MSG(render_setup(&big, &world, &c), "set-up: %s", big.error ? big.error : "");
    int out_of_order = 0;
    for (uint16_t i = 1; i < big.vis.count; i++)
        out_of_order += !(big.vis.obj[i].geom > big.vis.obj[i - 1].geom ||
                          (big.vis.obj[i].geom == big.vis.obj[i - 1].geom && big.vis.obj[i].index > big.vis.obj[i - 1].index));
    CHECK_MSG(big.vis.count == want && out_of_order == 0, "%d objects (FXRT_ORDER_MAX %d): %d out of scene order",
              (int)big.vis.count, FXRT_ORDER_MAX, out_of_order);
#endif
}
#else
static void test_render_order(void) {}
#endif

/* Row coherence (RENDER_COHERENT: a lone sphere's forms stepped down the
 * rows and its run searched from the row before's; a flat piece's sign
 * changes searched from the row before's): random worlds (spread_world),
 * both camera kinds, the eye inside a sphere in some, sizes 1..40 x
 * 1..30, one sample per pixel, and the rows asked for in every order a
 * caller may use: top down, bottom up, shuffled, random rows with
 * repeats, and a second top-down pass over the same set-up (the guesses
 * then come from the frame before). Each row must equal
 * render_row_reference byte for byte, and each pixel away from
 * silhouettes and near ties must show the nearest object of the
 * world-space kernels. In Q16.16 the coherent search must run in at
 * least a quarter of the frames with a sphere (the others: no sphere
 * alone on a row, the eye inside, or a row where disc is convex). Cap: 0
 * wrong. */
static void test_render_coherent(void)
{
    uint64_t st = 0xc04e7e17ull;
    static int ids[OH][OW];
    static bool tie[OH][OW];
    static rgb8_t want[OH][OW];
    long rows = 0, rows_bad = 0, interior = 0, interior_bad = 0, objects_px = 0;
    int sphere_frames = 0, coherent_frames = 0;
    for (int it = 0; it < 240; it++) {
        spread_world(&st, it);
        bool ortho = it % 4 == 3;
        vec3_t eye = spread_eye(&st, it % 13 == 5);
        int32_t w = 1 + (int32_t)(check_rng_next(&st) % OW), h = 1 + (int32_t)(check_rng_next(&st) % OH);
        if (it % 3 != 0) { /* mostly frames of useful size, some tiny */
            w = w < 8 ? w + 8 : w;
            h = h < 6 ? h + 6 : h;
        }
        cam_t c;
        CHECK(cam_setup(&c, ortho ? CAM_ORTHOGRAPHIC : CAM_PERSPECTIVE, eye, V3(orand(&st, -0.1, 0.1), 0, -1),
                        V3(0, 1, 0), N(orand(&st, 40, 80)), N(orand(&st, 6, 10)), w, h) == CAM_OK);
        static render_t state;
        CHECK(render_setup(&state, &world, &c));
        oracle_frame(&c, w, h, ids, want, tie);
        int order = it % 5, n_ask = order == 3 ? 2 * h : (order == 4 ? 2 * h : h);
        int32_t perm[OH];
        for (int32_t i = 0; i < h; i++)
            perm[i] = i;
        if (order == 2)
            for (int32_t i = h - 1; i > 0; i--) {
                int32_t j = (int32_t)(check_rng_next(&st) % (uint64_t)(i + 1)), t = perm[i];
                perm[i] = perm[j];
                perm[j] = t;
            }
        for (int k = 0; k < n_ask; k++) {
            int32_t row = order == 0 || order == 4 ? k % h
                          : order == 1 ? h - 1 - k
                          : order == 2 ? perm[k]
                                       : (int32_t)(check_rng_next(&st) % (uint64_t)h);
            uint8_t fast[3 * OW];
            rows++;
            if (!row_vs_reference(&state, row, w, fast)) {
                rows_bad++;
                CHECK_SWEEP(false, "coherent %d (%s, %dx%d, order %d) row %d: fast != reference", it,
                            ortho ? "ortho" : "persp", (int)w, (int)h, order, (int)row);
            }
            for (int32_t x = 0; x < w; x++) {
                bool same = !tie[row][x];
                for (int32_t y = row - 1; y <= row + 1 && same; y++)
                    for (int32_t xx = x - 1; xx <= x + 1 && same; xx++)
                        if (y >= 0 && y < h && xx >= 0 && xx < w)
                            same = ids[y][xx] == ids[row][x] && !tie[y][xx];
                if (!same)
                    continue;
                interior++;
                objects_px += ids[row][x] >= 0;
                const uint8_t *p = &fast[3 * x];
                rgb8_t wt = want[row][x];
                if (p[0] != wt.r || p[1] != wt.g || p[2] != wt.b) {
                    interior_bad++;
                    CHECK_SWEEP(false, "coherent %d row %d x %d: got %d %d %d, want %d %d %d (object %d)", it,
                                (int)row, (int)x, p[0], p[1], p[2], wt.r, wt.g, wt.b, ids[row][x]);
                }
            }
        }
        sphere_frames += world.n_spheres > 0;
#if RENDER_SROWS
        bool searched = false; /* some sphere's run was searched from a row before's */
        for (uint16_t i = 0; i < world.n_spheres && i < FXRT_COHERENT_SPHERES; i++)
            searched |= state.vis.srow[i].prow >= 0;
        coherent_frames += searched;
#endif
    }
    printf("coherent: %ld rows, %ld interior pixels checked (%ld on objects), %ld wrong, %ld rows fast != reference; "
           "%d of %d frames with a sphere searched from the row before\n",
           rows, interior, objects_px, interior_bad, rows_bad, coherent_frames, sphere_frames);
    CHECK_MSG(interior > 40000 && objects_px > 8000, "too few pixels exercised: %ld interior, %ld on objects", interior,
              objects_px);
    CHECK_MSG(interior_bad == 0, "%ld interior pixels differ from the kernels' nearest object", interior_bad);
    CHECK_MSG(rows_bad == 0, "%ld rows differ between render_row and render_row_reference", rows_bad);
#if RENDER_SROWS
    CHECK_MSG(coherent_frames * 4 >= sphere_frames, "the coherent path ran in %d of %d frames with a sphere",
              coherent_frames, sphere_frames);
#endif
}

/* Supersampling from runs (core/frame/render_sample.c, run mode): random worlds
 * of 1 to 6 objects of every kind spread across the view (so that on most
 * rows each is alone; some overlap, which takes the per-sample pass), a
 * plane in some, both camera kinds, the eye inside a sphere in some,
 * arbitrary colours, output sizes 9..40 x 7..30, samples 2..5, adaptive in
 * some, and in some frames a run cap of 1..6 (the pass gives up part-way
 * through a row and the per-sample pass takes it). render_row must equal
 * render_row_reference byte for byte; an output pixel whose N x N fine
 * rays and their fine neighbours all see one object through the
 * world-space kernels (cam_fine rays, no near ties) must show that
 * object's colour (the background where they see none). In Q16.16 the
 * run mode must take at least a third of the output rows and the
 * per-sample pass some. Cap: 0 wrong. */
static void test_render_runs(void)
{
#if FXRT_MAX_SAMPLES > 1
    uint64_t st = 0x52554e53ull;
    enum { FW = 5 * OW + 2, FH = 5 * OH + 2 };
    static int fid[FH][FW]; /* fine ids, with a border of -2 (matches nothing but is skipped) */
    static bool ftie[FH][FW];
    static rgb8_t fwant[FH][FW];
    long rows = 0, rows_bad = 0, interior = 0, interior_bad = 0, objects_px = 0;
    unsigned long run_rows = 0;
    for (int it = 0; it < 160; it++) {
        spread_world(&st, it);
        bool ortho = it % 4 == 3;
        vec3_t eye = spread_eye(&st, it % 11 == 5);
        int32_t ow = 9 + (int32_t)(check_rng_next(&st) % (OW - 8)), oh = 7 + (int32_t)(check_rng_next(&st) % (OH - 6));
        int32_t n = 2 + (int32_t)(check_rng_next(&st) % 4);
        if (n > FXRT_MAX_SAMPLES)
            n = FXRT_MAX_SAMPLES;
        bool adaptive = FXRT_ADAPTIVE && it % 3 == 1;
        CHECK(world_set_samples(&world, n, adaptive) == FXRT_OK);
        cam_t c, fine;
        CHECK(cam_setup(&c, ortho ? CAM_ORTHOGRAPHIC : CAM_PERSPECTIVE, eye, V3(orand(&st, -0.1, 0.1), 0, -1),
                        V3(0, 1, 0), N(orand(&st, 40, 80)), N(orand(&st, 6, 10)), ow, oh) == CAM_OK);
        CHECK(cam_fine(&c, n, &fine) == CAM_OK);
        static render_t state;
        CHECK(render_setup(&state, &world, &c));
#if RENDER_RUNS
        if (it % 7 == 6)
            state.sample.run_cap = (uint16_t)(1 + check_rng_next(&st) % 6);
#endif
        int32_t fw = n * ow, fh = n * oh;
        for (int32_t Y = -1; Y <= fh; Y++)
            for (int32_t X = -1; X <= fw; X++) {
                int *id_out = &fid[Y + 1][X + 1];
                if (Y < 0 || X < 0 || Y == fh || X == fw) {
                    *id_out = -2;
                    continue;
                }
                ray_t r;
                num_t t1, t2;
                cam_ray(&fine, X, fh - 1 - Y, &r);
                *id_out = oracle_pixel(&r, &t1, &t2, &fwant[Y + 1][X + 1]);
                ftie[Y + 1][X + 1] = t2 != NUM_MAX && D(t2) - D(t1) <= 1e-3 * D(t1) + 1e-4;
            }
        for (int32_t row = 0; row < oh; row++) {
            uint8_t fast[3 * OW];
            rows++;
            if (!row_vs_reference(&state, row, ow, fast)) {
                rows_bad++;
                CHECK_SWEEP(false, "runs %d (%s, samples %d%s, %dx%d) row %d: fast != reference", it,
                            ortho ? "ortho" : "persp", (int)n, adaptive ? " adaptive" : "", (int)ow, (int)oh, (int)row);
            }
            /* Pixels whose fine rays and their neighbours agree. */
            for (int32_t x = 0; x < ow; x++) {
                int k = fid[row * n + 1][x * n + 1];
                bool same = true;
                for (int32_t Y = row * n; Y <= row * n + n + 1 && same; Y++)
                    for (int32_t X = x * n; X <= x * n + n + 1 && same; X++)
                        same = (fid[Y][X] == k || fid[Y][X] == -2) && !ftie[Y][X];
                if (!same)
                    continue;
                interior++;
                objects_px += k >= 0;
                rgb8_t w = fwant[row * n + 1][x * n + 1];
                const uint8_t *p = &fast[3 * x];
                if (p[0] != w.r || p[1] != w.g || p[2] != w.b) {
                    interior_bad++;
                    CHECK_SWEEP(false, "runs %d row %d x %d: got %d %d %d, want %d %d %d (object %d)", it, (int)row,
                                (int)x, p[0], p[1], p[2], w.r, w.g, w.b, k);
                }
            }
        }
#if RENDER_RUNS
        run_rows += state.sample.run_rows;
#endif
    }
    printf("runs: %ld rows (%lu from runs), %ld interior pixels checked (%ld on objects), %ld wrong, %ld rows fast != "
           "reference\n",
           rows, run_rows, interior, objects_px, interior_bad, rows_bad);
    CHECK_MSG(interior > 20000 && objects_px > 5000, "too few pixels exercised: %ld interior, %ld on objects", interior,
              objects_px);
    CHECK_MSG(interior_bad == 0, "%ld interior pixels differ from the kernels' nearest object", interior_bad);
    CHECK_MSG(rows_bad == 0, "%ld rows differ between render_row and render_row_reference", rows_bad);
#if RENDER_RUNS
    CHECK_MSG(run_rows * 3 >= (unsigned long)rows && run_rows < (unsigned long)rows,
              "run mode took %lu of %ld rows (want at least a third, not all)", run_rows, rows);
#endif
#endif
}

#if FXRT_NUMBER == FXRT_Q16 && defined(__SIZEOF_INT128__)
/* The scanline forms' integer helpers (rlin_at, rquad_at, the 128-bit
 * render_mul128_small and render_quad_k; in the nohw build their Cortex-M0
 * C paths) against the compiler's 128-bit integers, an independent
 * computation: every coefficient drawn from all 64 bits (half of them
 * from edge patterns), offsets over the whole |k| < 2^15 range, and the
 * multiplier of render_mul128_small over 32 bits (k (k - 1) / 2 of
 * render_quad_k). */
static uint64_t arith_word(void)
{
    static const uint64_t edge[] = {0, 1, 0xFFFFu, 0x10000u, 0x7FFFFFFFull, 0x80000000ull, 0xFFFFFFFFull,
                                    0x7FFFFFFFFFFFFFFFull, 0x8000000000000000ull, UINT64_MAX};
    uint64_t r = rng();
    return (r & 1) ? edge[(r >> 1) % 10] : rng();
}
static int32_t arith_small(void) { return (int32_t)(rng() % 65535u) - 32767; }
static void test_render_forms_arith(void)
{
    __extension__ typedef unsigned __int128 u128;
    __extension__ typedef __int128 s128;
    long bad_lin = 0, bad_quad = 0, bad_mul = 0, bad_k = 0;
    for (int n = 0; n < 200000; n++) {
        render_lin_t f = {(int64_t)arith_word(), (int64_t)arith_word(), (int64_t)arith_word()};
        render_quad_t q = {(int64_t)arith_word(), (int64_t)arith_word(), (int64_t)arith_word(),
                           (int64_t)arith_word(), (int64_t)arith_word(), (int64_t)arith_word()};
        int32_t ix = arith_small(), iy = arith_small();
        uint64_t x = (uint64_t)(int64_t)ix, y = (uint64_t)(int64_t)iy;
        uint64_t want = (uint64_t)f.c + (uint64_t)f.x * x + (uint64_t)f.y * y; /* (mod 2^64) */
        bad_lin += (uint64_t)rlin_at(&f, ix, iy) != want;
        uint64_t wq = (uint64_t)q.c + (uint64_t)q.x * x + (uint64_t)q.y * y + (uint64_t)q.xx * x * x +
                      (uint64_t)q.xy * x * y + (uint64_t)q.yy * y * y;
        bad_quad += (uint64_t)rquad_at(&q, ix, iy) != wq;
        fx128_t a = {arith_word(), (int64_t)arith_word()}, v = {arith_word(), (int64_t)arith_word()},
                d2 = {arith_word(), (int64_t)arith_word()};
        int32_t m = (n & 1) ? arith_small() : (int32_t)(rng() >> 32);
        u128 ua = (u128)a.lo | (u128)(uint64_t)a.hi << 64, um = (u128)(s128)m;
        u128 p = ua * um;
        fx128_t got = render_mul128_small(&a, m);
        bad_mul += got.lo != (uint64_t)p || (uint64_t)got.hi != (uint64_t)(p >> 64);
        int32_t k = arith_small() / 2; /* |k| <= 2^14: k (k - 1) / 2 fits int32 */
        u128 uv = (u128)v.lo | (u128)(uint64_t)v.hi << 64, ud2 = (u128)d2.lo | (u128)(uint64_t)d2.hi << 64;
        u128 wk = uv + ua * (u128)(s128)k + ud2 * (u128)(s128)((int64_t)k * (k - 1) / 2);
        fx128_t gk = render_quad_k(&v, &a, &d2, k);
        bad_k += gk.lo != (uint64_t)wk || (uint64_t)gk.hi != (uint64_t)(wk >> 64);
    }
    CHECK_MSG(bad_lin == 0, "rlin_at: %ld of 200000 differ from 64-bit products", bad_lin);
    CHECK_MSG(bad_quad == 0, "rquad_at: %ld of 200000 differ", bad_quad);
    CHECK_MSG(bad_mul == 0, "render_mul128_small: %ld of 200000 differ from __int128", bad_mul);
    CHECK_MSG(bad_k == 0, "render_quad_k: %ld of 200000 differ from __int128", bad_k);
}

/* A flat piece's run search (render_split_test: the division of the
 * non-coherent loop, and the coherent loop's search from a guess, which is
 * the 32-bit quotient where the target divides and the row before's column
 * in the nohw build) against the form's sign at every column, evaluated in
 * __int128: roots drawn on, between and beyond the columns (exact zeros
 * among them), slopes from 1 to 2^50 and 0, guesses anywhere. */
static void test_render_split(void)
{
    __extension__ typedef __int128 s128;
    long bad = 0, zeros = 0, cases = 0;
    for (int n = 0; n < 60000; n++) {
        int32_t kmax = (int32_t)(rng() % 300);
        int bits = (int)(rng() % 51);
        int64_t b = (n % 50 == 0) ? 0 : (int64_t)((rng() >> (63 - bits)) | 1) * ((rng() & 1) ? 1 : -1);
        int64_t k0 = (int64_t)(rng() % (uint64_t)(3 * kmax + 9)) - kmax - 4; /* the root's column */
        int64_t ab = b < 0 ? -b : b;
        int64_t delta = (rng() & 3) == 0 ? 0 : (ab ? (int64_t)(rng() % (uint64_t)ab) : (int64_t)(rng() >> 40) - (1ll << 23));
        int64_t a = -b * k0 + ((rng() & 1) ? delta : -delta);
        bool strict = rng() & 1;
        for (int path = 0; path < 2; path++) {
            int16_t guess = (int16_t)((int32_t)(rng() % (uint32_t)(kmax + 11)) - 5);
            int32_t pr, pl;
            bool fall = render_split_test(a, b, kmax, path ? &guess : NULL, strict, &pr, &pl);
            cases++;
            for (int32_t k = 0; k <= kmax; k++) {
                s128 v = (s128)a + (s128)b * k;
                zeros += v == 0;
                bool pos = strict ? v > 0 : v >= 0, neg = strict ? v < 0 : v <= 0;
                bool in_r = k >= pr, in_l = k <= pl;
                bool got_pos = fall ? in_l : in_r, got_neg = fall ? in_r : in_l;
                if (got_pos != pos || got_neg != neg) {
                    if (bad < 5)
                        printf("split: a=%lld b=%lld kmax=%d strict=%d path=%d: k=%d pos %d/%d neg %d/%d\n", (long long)a,
                               (long long)b, (int)kmax, strict, path, (int)k, got_pos, pos, got_neg, neg);
                    bad++;
                    break;
                }
            }
        }
    }
    printf("split: %ld searches, %ld exact zeros on columns\n", cases, zeros);
    CHECK_MSG(zeros > 1000, "too few exact zeros exercised: %ld", zeros);
    CHECK_MSG(bad == 0, "render_split: %ld of %ld searches differ from the signs in __int128", bad, cases);
}

#if RENDER_ESTEP
/* The edges' row steps (render_split_edge_test) against the form's sign
 * at every column, in __int128: per edge a frame's rows top to bottom,
 * with rows skipped (the state starts again), rows asked twice, column
 * ranges that move from row to row, crossings on, between and far beyond
 * the columns (beyond the guess's reach too), steep and shallow edges and
 * slopes of 0 along the row or down it. Every kind of answer (stepped,
 * the same row's, located) must occur. Cap: 0 wrong. */
static void test_render_edge_steps(void)
{
    __extension__ typedef __int128 s128;
    long bad = 0, calls = 0, stepped = 0, zeros = 0, far = 0;
    for (int n = 0; n < 3000; n++) {
        int32_t w = 1 + (int32_t)(rng() % 700), h = 2 + (int32_t)(rng() % 120);
        int bx = (int)(rng() % 46), by = (int)(rng() % 50);
        render_lin_t e;
        e.x = (n % 37 == 0) ? 0 : (int64_t)((rng() >> (63 - bx)) | 1) * ((rng() & 1) ? 1 : -1);
        e.y = (n % 41 == 0) ? 0 : (int64_t)(rng() >> (63 - by)) * ((rng() & 1) ? 1 : -1);
        /* zero on a column of a row in the frame (exact zeros where the
         * slopes allow), then moved by a fraction of a column or more */
        int64_t kx = (int64_t)(rng() % (uint64_t)(3 * w + 2)) - w, ky = (int64_t)(rng() % (uint64_t)h);
        int64_t ix = 2 * kx - w + 1, iyr = h - 1 - 2 * ky;
        int64_t ax = e.x < 0 ? -e.x : e.x;
        int64_t shift = (rng() & 3) == 0 ? 0 : (int64_t)(rng() % (uint64_t)(2 * ax + 2)) - ax - 1;
        e.c = -(e.x * ix + e.y * iyr) + shift;
        render_estep_t st;
        st.iy = RENDER_ESTEP_NONE;
        st.dk = RENDER_ESTEP_NONE;
        st.next = RENDER_ESTEP_NO_ROW;
        for (int32_t row = 0; row < h; row++) {
            if (rng() % 16 == 0)
                continue; /* a row without this edge */
            int32_t iy = h - 1 - 2 * row;
            for (int again = 0; again < 1 + (rng() % 8 == 0); again++) {
                int32_t x0 = (int32_t)(rng() % (uint64_t)w), x1 = x0 + (int32_t)(rng() % (uint64_t)(w - x0));
                int32_t kmax = x1 - x0, ix0 = 2 * x0 - w + 1, pr, pl;
                stepped += st.iy == iy + 2 && st.dk != RENDER_ESTEP_NONE;
                bool fall = render_split_edge_test(&st, &e, x0, ix0, iy, kmax, &pr, &pl);
                calls++;
                far += st.iy == RENDER_ESTEP_NONE; /* no column within the guess's reach: searched */
                for (int32_t k = 0; k <= kmax; k++) {
                    s128 v = (s128)e.c + (s128)e.x * (2 * (x0 + k) - w + 1) + (s128)e.y * iy;
                    zeros += v == 0;
                    bool in_r = k >= pr, in_l = k <= pl;
                    if ((fall ? in_l : in_r) != (v >= 0) || (fall ? in_r : in_l) != (v <= 0)) {
                        if (bad < 5)
                            printf("edge steps: x=%lld y=%lld c=%lld w=%d row=%d x0=%d kmax=%d: k=%d wrong\n",
                                   (long long)e.x, (long long)e.y, (long long)e.c, (int)w, (int)row, (int)x0,
                                   (int)kmax, (int)k);
                        bad++;
                        break;
                    }
                }
            }
        }
    }
    printf("edge steps: %ld splits, %ld stepped from the row before, %ld searched, %ld exact zeros on columns\n",
           calls, stepped, far, zeros);
    CHECK_MSG(stepped > calls / 3 && stepped < calls, "edge steps: %ld of %ld splits stepped", stepped, calls);
    CHECK_MSG(far > 100, "edge steps: only %ld splits beyond the guess's reach", far);
    CHECK_MSG(zeros > 500, "edge steps: too few exact zeros exercised: %ld", zeros);
    CHECK_MSG(bad == 0, "render_split_edge: %ld of %ld splits differ from the signs in __int128", bad, calls);
}
#else
static void test_render_edge_steps(void) {}
#endif
#else
static void test_render_forms_arith(void) {}
static void test_render_split(void) {}
static void test_render_edge_steps(void) {}
#endif

int main(void)
{
    test_color_rule();
    test_render_forms_arith();
    test_render_split();
    test_render_edge_steps();
    test_cam_basis_seed();
    test_cam_basis_fig7();
    test_cam_pixels();
    test_cam_perspective_angles();
    test_cam_small();
    test_cam_rows();
    test_cam_orthographic();
    test_cam_errors();
    test_cam_wide_fov();
    test_plane_outside();
    test_sphere_outside();
    test_triangle_outside();
    test_box_outside();
    test_inside();
    test_behind();
    test_degenerate();
    test_far();
    test_watertight();
    test_random();
    test_world();
    test_render();
    test_render_overlap();
    test_render_depth_less();
    test_render_ranges();
    test_render_front();
    test_render_plane_rows();
    test_render_span_ranges();
    test_render_meshes();
    test_render_order();
    test_render_eye_on_box();
    test_render_coherent();
    test_render_runs();
#ifdef TEST_GEOM_NAME
    return check_report(TEST_GEOM_NAME);
#else
    return check_report("test_geom_" NUM_NAME);
#endif
}
