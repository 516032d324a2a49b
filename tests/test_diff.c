/* Differential tests: the Q16.16 kernels against the double build.
 *
 * For each primitive (plane, sphere, triangle, box) and for camera rays,
 * random cases are drawn across the documented input domain (README,
 * docs/ACCURACY.md), including log-scale extremes: object sizes from 0.01
 * to thousands, distances from 0.01 to 16000, grazing angles, rays starting
 * inside spheres and boxes or near a surface, objects behind the origin,
 * far plane hits beyond the Q16.16 range, narrow and wide cameras. Every
 * input is rounded to Q16.16 FIRST and both builds get the same rounded
 * values (tests/diffk.c), so the comparison measures arithmetic only.
 *
 * For each case (see docs/ACCURACY.md for the derivations):
 *  (a) hit/miss agree unless the case lies in the primitive's stated band
 *      (ray within the rounding error of the silhouette, of an edge, of
 *      being parallel, or of t = 0),
 *  (b) when both hit, |t_q16 - t_double| <= the primitive's stated bound,
 *      and a double hit beyond Q16.16 range is a q16 hit with t == FX_MAX,
 *  (c) cameras: both accept or both reject (unless within rounding of a
 *      limit); ray origins and directions within the stated bounds.
 * Lighting (issue 11; docs/ACCURACY.md, "Shading error"): surface normals
 * (normal), shade_point colours and light masks (shade, also against the
 * formula written out here in long double), numw_pow_int (pow), the spot
 * cone's decision (spot) and world_occluded (shadow), each within its
 * stated bound or band. Secondary rays (issue 12): the reflected and
 * transmitted directions and Schlick's R that core/light/trace.c makes
 * (reflect, refract, schlick), Q16.16 and float against double, over
 * indices 0.01..100 and every incidence, within the bounds stated at
 * eval_bounce; total internal reflection may differ only in its band.
 *
 * Usage: test_diff [CASES] [--seed N] [--jobs N] [--progress] [--only KIND]
 *        test_diff --replay KIND:INDEX [--seed N]
 * CASES (default 10^6, or $DIFF_CASES) is per primitive and for cameras.
 * Every case is a pure function of (seed, kind, index), so any case can be
 * replayed alone, and --jobs splits the indices across processes.
 *
 * tests/fuzz_kernels.c includes this file with DIFF_NO_MAIN, so the fuzzer
 * asserts exactly these bounds. */
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "diffk.h"

#define LSB DIFFK_LSB
#define TMAX DIFFK_Q16_TMAX
#define COORD 8192.0
#define RADIUS_MAX 4096.0
#define PI 3.14159265358979323846

/* ---- the stated bounds ---------------------------------------------------
 * Each bound is MARGIN times a first-order rounding analysis (the
 * constants below; docs/ACCURACY.md derives each term). The analysis is
 * tight: over 10^6 cases per kind its worst case uses 0.99 to 1.00 of it
 * (test_diff prints this as "max err/(base+cond)"), and the margin covers
 * second-order terms and the double build's own rounding. */
#define MARGIN 1.5
/* Per-component error of a Q16.16 unit vector (fx_normalize3): it works
 * with 30 or more significant bits and rounds once, so 0.5 LSB (README
 * documents 1 LSB; test_fx measures 0.500). */
#define NORM_ERR 0.5
/* Sphere: t = b - h (or b + h) with b = (c - o) . d rounded once (0.5)
 * and h = fxw_sqrt(disc) (0.5); disc itself is perturbed by E, see
 * eval_sphere. */
#define SPHERE_T0 1.0
/* Plane and triangle: t = fxw_div(N, D), 1 LSB (its documented bound;
 * general operands reach 0.8); the rounded normal adds the lever term. */
#define PLANE_T0 1.0
/* Triangle edge values: the cross product (q - o) x d rounds each
 * component by 0.5 LSB, so e = (p - o) . (...) moves by 0.5 LSB |p - o|_1. */
#define TRI_EDGE 0.5
/* Box: each slab t is one fx_div of exact operands, 0.5 LSB. */
#define BOX_T0 0.5
/* Camera CAPS: constant numbers of LSB that hold for every accepted camera,
 * however close up is to the gaze (down to the rejected 0.895 degrees),
 * however short or long gaze and up are, for any image size and fov
 * (docs/ACCURACY.md, "Camera", derives each):
 *  - basis u, v, w, per component: each is normalised once from an exact
 *    wide vector (0.5 LSB, plus 2^-13 from keeping 30 bits): cap 1 LSB;
 *  - perspective ray direction, per component: basis error through
 *    r = -F w + ix u + iy v (sqrt(3) x 0.87), fwd's rounding (0.87 / |r|,
 *    |r| >= F >= 1), focal (half its relative error, <= 1 LSB), the final
 *    normalisation (0.5): cap 4 LSB;
 *  - orthographic direction -w: cap 1 LSB (the basis cap);
 *  - orthographic origin e + ou u + ov v, per component: 4 roundings
 *    (2 LSB) and the step's wide rounding (0.1) plus the basis error times
 *    the offsets, 0.501 (|ou| + |ov|) LSB (0.5 + 2^-13 per basis component),
 *    |ou| + |ov| <= 8192
 *    in the domain: at most CAM_ORIGIN_CAP = 4110 LSB (0.063 units; the
 *    proportional form is asserted too);
 *  - focal F = H cot(fov/2): within 1 LSB + (2^-15 + 2e-7) F, so at most
 *    CAM_FOCAL_CAP = 66000 LSB (1.0 unit) at the narrow limit F = 32767. */
#define CAM_BASIS_CAP 1.0
#define CAM_DIR_CAP 4.0
#define CAM_ORIGIN_BASE 2.1
#define CAM_ORIGIN_PER_UNIT 0.501
#define CAM_ORIGIN_CAP 4110.0
#define CAM_FOCAL_REL (1.0 / 32768 + 2e-7)
#define CAM_FOCAL_CAP 66000.0

/* ---- random numbers ---------------------------------------------------- */

/* splitmix64 over a counter; the fuzzer feeds its input bytes instead
 * (bytes, while they last). */
typedef struct {
    uint64_t s;
    const uint8_t *bytes;
    size_t nbytes;
} rng_t;

static uint64_t splitmix64(uint64_t x)
{
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

static uint64_t rng_next(rng_t *r)
{
    r->s += 0x9E3779B97F4A7C15ull;
    if (r->nbytes >= 8) {
        uint64_t v = 0;
        for (int i = 0; i < 8; i++)
            v = v << 8 | r->bytes[i];
        r->bytes += 8;
        r->nbytes -= 8;
        return v;
    }
    return splitmix64(r->s);
}

/* Uniform in [0, 1). */
static double urand(rng_t *r)
{
    return (double)(rng_next(r) >> 11) * (1.0 / 9007199254740992.0);
}
static double uniform(rng_t *r, double lo, double hi)
{
    return lo + (hi - lo) * urand(r);
}
/* Log-uniform in [lo, hi], 0 < lo < hi. */
static double logu(rng_t *r, double lo, double hi)
{
    return exp(uniform(r, log(lo), log(hi)));
}
static int irand(rng_t *r, int n)
{
    return (int)(rng_next(r) % (uint64_t)n);
}
static double rsign(rng_t *r)
{
    return (rng_next(r) & 1) ? 1.0 : -1.0;
}

/* ---- small vector helpers (double) -------------------------------------- */

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
static double norm3(const double a[3])
{
    return sqrt(dot3(a, a));
}
static double norm1(const double a[3])
{
    return fabs(a[0]) + fabs(a[1]) + fabs(a[2]);
}
static void sub3(const double a[3], const double b[3], double out[3])
{
    for (int i = 0; i < 3; i++)
        out[i] = a[i] - b[i];
}
static void cross3(const double a[3], const double b[3], double out[3])
{
    double x = a[1] * b[2] - a[2] * b[1];
    double y = a[2] * b[0] - a[0] * b[2];
    double z = a[0] * b[1] - a[1] * b[0];
    out[0] = x;
    out[1] = y;
    out[2] = z;
}
static void scale3(double a[3], double s)
{
    for (int i = 0; i < 3; i++)
        a[i] *= s;
}
static void set3(double out[3], double x, double y, double z)
{
    out[0] = x;
    out[1] = y;
    out[2] = z;
}
static void copy3(double out[3], const double a[3])
{
    set3(out, a[0], a[1], a[2]);
}
/* out = a + s b */
static void axpy3(double out[3], const double a[3], double s, const double b[3])
{
    for (int i = 0; i < 3; i++)
        out[i] = a[i] + s * b[i];
}
static bool normalize3(double a[3])
{
    double n = norm3(a);
    if (!(n > 0))
        return false;
    scale3(a, 1.0 / n);
    return true;
}

static void rand_unit(rng_t *r, double v[3])
{
    for (;;) {
        set3(v, uniform(r, -1, 1), uniform(r, -1, 1), uniform(r, -1, 1));
        double n = dot3(v, v);
        if (n > 1e-6 && n <= 1.0) {
            scale3(v, 1.0 / sqrt(n));
            return;
        }
    }
}

/* A unit vector perpendicular to unit n. */
static void rand_perp(rng_t *r, const double n[3], double out[3])
{
    for (;;) {
        double v[3];
        rand_unit(r, v);
        cross3(n, v, out);
        if (normalize3(out))
            return;
    }
}

/* A random axis direction: +-e_k. */
static void rand_axis(rng_t *r, double v[3])
{
    set3(v, 0, 0, 0);
    v[irand(r, 3)] = rsign(r);
}

static double clampd(double x, double lo, double hi)
{
    return x < lo ? lo : (x > hi ? hi : x);
}

/* A point of the coordinate domain: uniform per axis, or at a log-uniform
 * distance 0.01 .. 8192 from the origin. */
static void rand_point(rng_t *r, double p[3])
{
    if (rng_next(r) & 1) {
        for (int i = 0; i < 3; i++)
            p[i] = uniform(r, -COORD, COORD);
    } else {
        rand_unit(r, p);
        scale3(p, logu(r, 0.01, COORD));
    }
}

/* The ray's origin: dist before target along d, pulled closer when that
 * would leave the coordinate domain (then clamped per axis). */
static void place_origin(const double target[3], const double d[3], double dist, double o[3])
{
    for (int i = 0; i < 3; i++) {
        if (d[i] > 0)
            dist = fmin(dist, (target[i] + COORD) / d[i]);
        else if (d[i] < 0)
            dist = fmin(dist, (target[i] - COORD) / d[i]);
    }
    if (dist < 0)
        dist = 0;
    for (int i = 0; i < 3; i++)
        o[i] = clampd(target[i] - dist * d[i], -COORD, COORD);
}

/* Round to Q16.16 exactly as the host does. */
static double rq(double x)
{
    return diffk_input_q16(x);
}
static void rq3(double v[3])
{
    for (int i = 0; i < 3; i++)
        v[i] = rq(v[i]);
}
static void rq_coord3(double v[3])
{
    for (int i = 0; i < 3; i++)
        v[i] = rq(clampd(v[i], -COORD, COORD));
}

/* ---- cases ---------------------------------------------------------------- */

/* The lighting kinds (issue 11) come after the others, so that the cases
 * of the first five stay what they were for a given seed. */
/* The secondary-ray kinds (issue 12) come last for the same reason. */
enum {
    K_PLANE, K_SPHERE, K_TRIANGLE, K_BOX, K_CAMERA, K_NORMAL, K_SHADE, K_POW, K_SPOT, K_SHADOW,
    K_REFLECT, K_REFRACT, K_SCHLICK, K_COUNT
};
static const char *const kind_name[K_COUNT] = {"plane",  "sphere", "triangle", "box",     "camera",
                                               "normal", "shade",  "pow",      "spot",    "shadow",
                                               "reflect", "refract", "schlick"};

#define SHADOW_OBJS 3

#define CAM_PIXELS 5

typedef struct {
    int kind;
    int mode;       /* which generator branch (for the record) */
    double p[3][3]; /* plane: point, normal; sphere: center; triangle: a, b, c; box: min, max */
    double radius;  /* sphere */
    diffk_ray_t ray;
    diffk_cam_t cam;
    int px[CAM_PIXELS], py[CAM_PIXELS];
    int sub;                         /* normal: object kind (0..3); shadow: number of objects */
    diffk_obj_t obj[SHADOW_OBJS];    /* shadow: the occluders */
    double tmax;                     /* shadow: the segment's length (< 0: NUM_MAX, directional) */
    diffk_shade_t sh;                /* shade, spot: material and lights */
    double sp[3], sn[3], sdir[3];    /* shade, spot: point, geometric normal, ray direction */
    long long xq;                    /* pow: x in Q32.32 */
    unsigned k;                      /* pow: the exponent */
} dcase_t;

/* A random unit direction, rounded to Q16.16 (|d| = 1 within ~1 LSB, like
 * the renderer's normalised rays). */
static void ray_dir_round(double d[3])
{
    rq3(d);
    if (d[0] == 0 && d[1] == 0 && d[2] == 0)
        d[2] = 1;
}

/* Direction making angle acos(c) with -n (toward the surface when c > 0). */
static void dir_with_cos(rng_t *r, const double n[3], double c, double d[3])
{
    double t[3];
    rand_perp(r, n, t);
    double s = sqrt(fmax(0.0, 1.0 - c * c));
    for (int i = 0; i < 3; i++)
        d[i] = -c * n[i] + s * t[i];
}

/* Cosine of incidence: mostly uniform, often grazing (log-scale down to 1e-6). */
static double rand_cos(rng_t *r)
{
    switch (irand(r, 3)) {
    case 0: return logu(r, 1e-6, 1.0);
    case 1: return uniform(r, 0.0, 1.0);
    default: return sqrt(urand(r));
    }
}

static double rand_dist(rng_t *r)
{
    return logu(r, 0.01, 16000.0);
}

static void gen_plane(rng_t *r, dcase_t *c)
{
    double *a = c->p[0], *n = c->p[1], nu[3], hit[3], tang[3], *o = c->ray.o, *d = c->ray.d;
    rand_point(r, a);
    rq_coord3(a);
    do {
        if (irand(r, 5) == 0)
            rand_axis(r, n);
        else
            rand_unit(r, n);
        scale3(n, logu(r, 1e-3, COORD));
        rq_coord3(n);
    } while (n[0] == 0 && n[1] == 0 && n[2] == 0);
    copy3(nu, n);
    normalize3(nu);
    rand_perp(r, nu, tang);
    /* A point on the plane near the stored point (lever arm 0 .. 16000). */
    axpy3(hit, a, irand(r, 4) == 0 ? 0.0 : logu(r, 0.01, 16000.0), tang);
    c->mode = irand(r, 8);
    switch (c->mode) {
    case 0: case 1: /* aimed at the plane, either side */
        dir_with_cos(r, nu, rsign(r) * rand_cos(r), d);
        place_origin(hit, d, rand_dist(r), o);
        break;
    case 2: /* nearly parallel */
        dir_with_cos(r, nu, rsign(r) * logu(r, 1e-9, 1e-3), d);
        place_origin(hit, d, rand_dist(r), o);
        break;
    case 3: { /* far hit: t beyond the Q16.16 range, origin in the domain */
        double h = logu(r, 0.01, 4096.0), t = logu(r, 20000.0, 1e7);
        double side = rsign(r);
        axpy3(o, hit, side * h, nu);
        dir_with_cos(r, nu, side * h / t, d);
        break;
    }
    case 4: /* plane behind the origin */
        dir_with_cos(r, nu, rsign(r) * rand_cos(r), d);
        place_origin(hit, d, rand_dist(r), o);
        scale3(d, -1.0);
        break;
    case 5: /* origin near the plane */
        axpy3(o, hit, rsign(r) * logu(r, 1e-7, 1e-2), nu);
        rand_unit(r, d);
        break;
    default: /* anything */
        rand_point(r, o);
        rand_unit(r, d);
        break;
    }
    rq_coord3(o);
    ray_dir_round(d);
}

static void gen_sphere(rng_t *r, dcase_t *c)
{
    double *ctr = c->p[0], *o = c->ray.o, *d = c->ray.d, perp[3], target[3];
    rand_point(r, ctr);
    rq_coord3(ctr);
    double rad = irand(r, 20) == 0 ? logu(r, 4.0 * LSB, 0.01) : logu(r, 0.01, RADIUS_MAX);
    rad = rq(rad);
    if (rad <= 0)
        rad = LSB;
    c->radius = rad;
    rand_unit(r, d);
    rand_perp(r, d, perp);
    c->mode = irand(r, 8);
    double q; /* distance of the ray from the centre */
    switch (c->mode) {
    case 0: case 1: /* through the disc */
        q = rad * sqrt(urand(r));
        axpy3(target, ctr, q, perp);
        place_origin(target, d, rand_dist(r) + rad, o);
        break;
    case 2: case 3: /* near the silhouette: relative or absolute offsets */
        if (rng_next(r) & 1)
            q = rad * (1.0 + rsign(r) * logu(r, 1e-12, 1e-2));
        else
            q = rad + rsign(r) * logu(r, 1e-9, 1e-2);
        axpy3(target, ctr, fmax(q, 0.0), perp);
        place_origin(target, d, rand_dist(r), o);
        break;
    case 4: { /* origin inside */
        double u[3];
        rand_unit(r, u);
        axpy3(o, ctr, rad * cbrt(urand(r)), u);
        break;
    }
    case 5: /* behind the origin */
        q = rad * sqrt(urand(r));
        axpy3(target, ctr, q, perp);
        place_origin(target, d, rand_dist(r) + rad, o);
        scale3(d, -1.0);
        break;
    case 6: { /* origin near the surface */
        double u[3];
        rand_unit(r, u);
        axpy3(o, ctr, rad + rsign(r) * fmin(rad, logu(r, 1e-8, 1e-2)), u);
        break;
    }
    default:
        rand_point(r, o);
        break;
    }
    rq_coord3(o);
    ray_dir_round(d);
}

static void gen_triangle(rng_t *r, dcase_t *c)
{
    double *A = c->p[0], *B = c->p[1], *C = c->p[2], *o = c->ray.o, *d = c->ray.d;
    double ctr[3], u[3], n[3], e1[3], e2[3], X[3];
    rand_point(r, ctr);
    double L = logu(r, 0.01, COORD);
    rand_unit(r, u);
    axpy3(A, ctr, L * uniform(r, 0.2, 1.0), u);
    rand_unit(r, u);
    axpy3(B, ctr, L * uniform(r, 0.2, 1.0), u);
    if (irand(r, 8) == 0) { /* sliver: C near the line AB */
        double ab[3], perp[3];
        sub3(B, A, ab);
        double s = uniform(r, -0.5, 1.5);
        axpy3(C, A, s, ab);
        rand_unit(r, perp);
        axpy3(C, C, logu(r, 1e-6, 1.0) * L, perp);
    } else {
        rand_unit(r, u);
        axpy3(C, ctr, L * uniform(r, 0.2, 1.0), u);
    }
    rq_coord3(A);
    rq_coord3(B);
    rq_coord3(C);
    sub3(B, A, e1);
    sub3(C, A, e2);
    cross3(e1, e2, n);
    if (!normalize3(n))
        rand_unit(r, n);
    /* A point of the plane: barycentric (inside, or outside when a weight is
     * negative), or on an edge with a small in-plane offset. */
    double w1 = urand(r), w2 = urand(r);
    if (w1 + w2 > 1) {
        w1 = 1 - w1;
        w2 = 1 - w2;
    }
    c->mode = irand(r, 8);
    if (c->mode == 2 || c->mode == 3) { /* near an edge */
        const double *P[3] = {A, B, C};
        int k = irand(r, 3);
        double pq[3], side[3], s = urand(r);
        if (irand(r, 4) == 0)
            s = rsign(r) * logu(r, 1e-9, 1e-2) + (rng_next(r) & 1); /* near a vertex */
        sub3(P[(k + 1) % 3], P[k], pq);
        axpy3(X, P[k], s, pq);
        cross3(n, pq, side);
        normalize3(side);
        double off = (rng_next(r) & 1) ? logu(r, 1e-9, 1e-2) * L : logu(r, LSB / 256, 1e-2);
        axpy3(X, X, rsign(r) * off, side);
    } else {
        for (int i = 0; i < 3; i++)
            X[i] = A[i] + w1 * e1[i] + w2 * e2[i];
    }
    switch (c->mode) {
    case 4: /* triangle behind the origin */
        dir_with_cos(r, n, rsign(r) * rand_cos(r), d);
        place_origin(X, d, rand_dist(r), o);
        scale3(d, -1.0);
        break;
    case 5: /* grazing */
        dir_with_cos(r, n, rsign(r) * logu(r, 1e-7, 1e-2), d);
        place_origin(X, d, rand_dist(r), o);
        break;
    case 6: /* anything */
        rand_point(r, o);
        rand_unit(r, d);
        break;
    default:
        dir_with_cos(r, n, rsign(r) * rand_cos(r), d);
        place_origin(X, d, rand_dist(r), o);
        break;
    }
    rq_coord3(o);
    ray_dir_round(d);
}

static void gen_box(rng_t *r, dcase_t *c)
{
    double *lo = c->p[0], *hi = c->p[1], *o = c->ray.o, *d = c->ray.d, ctr[3], X[3];
    rand_point(r, ctr);
    int flat = irand(r, 40);
    for (int i = 0; i < 3; i++) {
        double ext = logu(r, 0.01, 2 * COORD);
        if (flat == i || flat == 3)
            ext = 0; /* a rectangle (or, flat == 3, a point) */
        lo[i] = rq(clampd(ctr[i] - ext / 2, -COORD, COORD));
        hi[i] = rq(clampd(ctr[i] + ext / 2, -COORD, COORD));
    }
    /* A target: inside, on a face, or near an edge. */
    for (int i = 0; i < 3; i++)
        X[i] = uniform(r, lo[i], hi[i]);
    c->mode = irand(r, 8);
    if (c->mode <= 1) {
        int k = irand(r, 3);
        X[k] = (rng_next(r) & 1) ? lo[k] : hi[k];
    } else if (c->mode <= 3) { /* near an edge: two coordinates at a face, offset */
        int k = irand(r, 3), j = (k + 1 + irand(r, 2)) % 3;
        X[k] = ((rng_next(r) & 1) ? lo[k] : hi[k]) + rsign(r) * logu(r, LSB / 256, 1e-2);
        X[j] = ((rng_next(r) & 1) ? lo[j] : hi[j]) + rsign(r) * logu(r, LSB / 256, 1e-2);
    }
    switch (c->mode) {
    case 4: /* origin inside */
        copy3(o, X);
        rand_unit(r, d);
        break;
    case 5: /* box behind the origin */
        rand_unit(r, d);
        place_origin(X, d, rand_dist(r), o);
        scale3(d, -1.0);
        break;
    case 6: { /* grazing a face */
        int k = irand(r, 3);
        rand_unit(r, d);
        d[k] = rsign(r) * logu(r, 1e-7, 1e-2);
        normalize3(d);
        place_origin(X, d, rand_dist(r), o);
        break;
    }
    case 7:
        rand_point(r, o);
        rand_unit(r, d);
        break;
    default:
        rand_unit(r, d);
        place_origin(X, d, rand_dist(r), o);
        break;
    }
    rq_coord3(o);
    ray_dir_round(d);
}

static int rand_dim(rng_t *r)
{
    int v = (int)lround(logu(r, 1.0, 4096.0));
    return v < 1 ? 1 : (v > 4096 ? 4096 : v);
}

static void gen_camera(rng_t *r, dcase_t *c)
{
    diffk_cam_t *cam = &c->cam;
    cam->kind = (rng_next(r) & 1) ? DIFFK_ORTHOGRAPHIC : DIFFK_PERSPECTIVE;
    cam->width = rand_dim(r);
    cam->height = rand_dim(r);
    rand_point(r, cam->eye);
    double g[3], up[3];
    if (irand(r, 5) == 0)
        rand_axis(r, g);
    else
        rand_unit(r, g);
    c->mode = irand(r, 8);
    switch (c->mode) {
    case 0: case 1: /* the usual: up = an axis or a random vector */
        if (rng_next(r) & 1)
            rand_axis(r, up);
        else
            rand_unit(r, up);
        break;
    case 2: { /* up nearly parallel to gaze */
        double p[3];
        rand_perp(r, g, p);
        axpy3(up, g, rsign(r) * logu(r, 1e-4, 1e-1), p);
        scale3(up, rsign(r));
        break;
    }
    default:
        rand_unit(r, up);
        break;
    }
    scale3(g, logu(r, 1e-3, COORD));
    scale3(up, logu(r, 1e-2, COORD));
    cam->fov_deg = 0;
    cam->scale = 0;
    if (cam->kind == DIFFK_PERSPECTIVE) {
        /* fov: anywhere in (0, 180), or near the narrow limit
         * H cot(fov/2) <= 32767 where the rays are longest. */
        double F = 32767.0 * (1.0 - logu(r, 1e-7, 1.0));
        int pick = irand(r, 6);
        if (pick <= 1)
            cam->fov_deg = uniform(r, 0.5, 179.5);
        else if (pick == 2) /* near the wide limit H cot(fov/2) >= 1 */
            cam->fov_deg = 2.0 * atan(cam->height / logu(r, 0.5, 4.0)) * 180.0 / PI;
        else
            cam->fov_deg = 2.0 * atan(cam->height / fmax(F, 0.01)) * 180.0 / PI;
        if (c->mode == 7) {
            /* The longest rays along a coordinate axis: the corner ray of a
             * large image at the narrow limit. */
            cam->width = 4096 - irand(r, 64);
            cam->height = 4096 - irand(r, 2048);
            F = 32767.0 * (1.0 - logu(r, 1e-7, 1e-3));
            cam->fov_deg = 2.0 * atan(cam->height / F) * 180.0 / PI;
            double k[3] = {-(cam->width - 1.0), -(cam->height - 1.0), -F}, ex[3] = {1, 0, 0}, ax[3];
            normalize3(k);
            /* Rodrigues: the rotation taking k onto ex, applied to the
             * camera axes; R[i] is where axis i (u, v, w) goes. */
            cross3(k, ex, ax);
            double s = norm3(ax), cth = dot3(k, ex), R[3][3];
            if (s > 0)
                scale3(ax, 1.0 / s);
            for (int i = 0; i < 3; i++) {
                double e[3] = {0, 0, 0}, v1[3], v2[3];
                e[i] = 1;
                cross3(ax, e, v1);
                double kd = dot3(ax, e);
                for (int j = 0; j < 3; j++)
                    v2[j] = e[j] * cth + v1[j] * s + ax[j] * kd * (1 - cth);
                copy3(R[i], v2); /* R[i] = image of camera axis i */
            }
            for (int i = 0; i < 3; i++) {
                g[i] = -R[2][i];
                up[i] = R[1][i];
            }
            scale3(g, logu(r, 0.1, 100));
            scale3(up, logu(r, 0.1, 100));
        }
    } else {
        cam->scale = rq(logu(r, 0.01, RADIUS_MAX));
        /* Keep |eye| + reach inside the domain (cam_setup rejects it
         * otherwise), except in mode 6, which tests that rejection. */
        double reach = cam->scale / 2 * cam->width / cam->height + cam->scale / 2;
        if (c->mode == 6 && reach > COORD - 1)
            reach = 0;
        else if (reach > COORD - 1) {
            cam->scale *= (COORD - 1) / reach;
            cam->scale = rq(cam->scale);
            reach = cam->scale / 2 * cam->width / cam->height + cam->scale / 2;
        }
        for (int i = 0; i < 3; i++)
            cam->eye[i] = clampd(cam->eye[i], -(COORD - reach - 1e-3), COORD - reach - 1e-3);
    }
    rq_coord3(cam->eye);
    copy3(cam->gaze, g);
    copy3(cam->up, up);
    rq_coord3(cam->gaze);
    rq_coord3(cam->up);
    if (cam->gaze[0] == 0 && cam->gaze[1] == 0 && cam->gaze[2] == 0)
        cam->gaze[2] = -1;
    if (cam->up[0] == 0 && cam->up[1] == 0 && cam->up[2] == 0)
        cam->up[1] = 1;
    cam->fov_deg = rq(cam->fov_deg);
    int W = cam->width, H = cam->height;
    int xs[4] = {0, W - 1, 0, W - 1}, ys[4] = {0, 0, H - 1, H - 1};
    for (int i = 0; i < 4; i++) {
        c->px[i] = xs[i];
        c->py[i] = ys[i];
    }
    c->px[4] = irand(r, W);
    c->py[4] = irand(r, H);
}

/* ---- lighting cases (issue 11) -------------------------------------------- */

/* A fraction 0..1 over the full range, rounded to Q16.16; sometimes 0 or 1. */
static double rand_frac(rng_t *r)
{
    switch (irand(r, 10)) {
    case 0: return 0.0;
    case 1: return 1.0;
    default: return rq(urand(r));
    }
}

/* A surface colour channel, 0..255 (1/255 units). */
static double rand_chan(rng_t *r)
{
    switch (irand(r, 10)) {
    case 0: return 0.0;
    case 1: return 255.0;
    default: return rq(uniform(r, 0.0, 255.0));
    }
}

/* A Phong exponent 1..1024: uniform, log-uniform, powers of two and 2^j - 1. */
static int rand_exponent(rng_t *r)
{
    switch (irand(r, 4)) {
    case 0: return 1 + irand(r, 1024);
    case 1: return (int)fmin(1024.0, floor(logu(r, 1.0, 1025.0)));
    case 2: return 1 << irand(r, 11);
    default: { int k = (1 << (1 + irand(r, 10))) - 1; return k; }
    }
}

/* v rotated towards a random perpendicular by angle a (radians). */
static void rotate_away(rng_t *r, const double v[3], double a, double out[3])
{
    double t[3];
    rand_perp(r, v, t);
    for (int i = 0; i < 3; i++)
        out[i] = cos(a) * v[i] + sin(a) * t[i];
}

/* The object kinds of test_diff's generators (diffk_obj_t kinds match). */
static void gen_object(rng_t *r, int kind, dcase_t *tmp)
{
    memset(tmp, 0, sizeof *tmp);
    tmp->kind = kind;
    switch (kind) {
    case K_PLANE: gen_plane(r, tmp); break;
    case K_SPHERE: gen_sphere(r, tmp); break;
    case K_TRIANGLE: gen_triangle(r, tmp); break;
    default: gen_box(r, tmp); break;
    }
}

static void obj_from_case(const dcase_t *tmp, diffk_obj_t *o)
{
    memset(o, 0, sizeof *o);
    o->kind = tmp->kind;
    memcpy(o->p, tmp->p, sizeof o->p);
    o->radius = tmp->radius;
}

/* Normals: an object and a ray from the primitive's own generator. */
static void gen_normal(rng_t *r, dcase_t *c)
{
    dcase_t tmp;
    int sub = irand(r, 4);
    gen_object(r, sub, &tmp);
    memcpy(c->p, tmp.p, sizeof c->p);
    c->radius = tmp.radius;
    c->ray = tmp.ray;
    c->mode = tmp.mode;
    c->sub = sub;
}

/* A light at distance dist from p in direction l (point, spot), or
 * shining along -l (directional), inside the domain and rounded. */
static void place_light(rng_t *r, diffk_light_t *L, const double p[3], const double l[3])
{
    if (L->kind == DIFFK_LIGHT_DIRECTIONAL) {
        do {
            for (int i = 0; i < 3; i++)
                L->dir[i] = -l[i];
            scale3(L->dir, logu(r, 1e-3, COORD));
            rq_coord3(L->dir);
        } while (L->dir[0] == 0 && L->dir[1] == 0 && L->dir[2] == 0);
        return;
    }
    double dist = irand(r, 8) == 0 ? logu(r, 4 * LSB, 1e-3) : logu(r, 1e-3, 16000.0);
    axpy3(L->pos, p, dist, l);
    rq_coord3(L->pos);
}

/* A spot's axis and half-angle; the axis either random or at an angle
 * near the half-angle from the direction towards p (-l). */
static void aim_spot(rng_t *r, diffk_light_t *L, const double l[3], bool edge)
{
    L->angle = irand(r, 6) == 0 ? rq(logu(r, 1e-3, 1.0)) : rq(uniform(r, 0.0, 90.0));
    if (L->angle <= 0)
        L->angle = LSB;
    if (irand(r, 10) == 0)
        L->angle = 90.0;
    double s[3], ml[3] = {-l[0], -l[1], -l[2]};
    if (edge) {
        double a = L->angle * PI / 180;
        double f = irand(r, 2) ? 1.0 + rsign(r) * logu(r, 1e-9, 0.5) : uniform(r, 0.0, 1.5);
        rotate_away(r, ml, fmin(PI, a * f), s);
    } else {
        rand_unit(r, s);
    }
    do {
        copy3(L->dir, s);
        scale3(L->dir, logu(r, 1e-3, COORD));
        rq_coord3(L->dir);
    } while (L->dir[0] == 0 && L->dir[1] == 0 && L->dir[2] == 0);
}

/* Shading: a point, a normal, an incoming direction, a material (lambert
 * or phong with any exponent 1..1024) and 1..3 lights of any kind with
 * colours over the full range. The first light of a phong case is often
 * placed so that the eye is near its mirror direction (the highlight,
 * where the power amplifies errors most). */
static void gen_shade(rng_t *r, dcase_t *c)
{
    diffk_shade_t *sh = &c->sh;
    sh->material = irand(r, 3) == 0 ? DIFFK_LAMBERT : DIFFK_PHONG;
    sh->exponent = rand_exponent(r);
    for (int i = 0; i < 3; i++) {
        sh->color[i] = rand_chan(r);
        sh->specular[i] = rand_frac(r);
        sh->ambient[i] = irand(r, 2) ? rand_frac(r) : rq(0.1 * urand(r));
    }
    rand_point(r, c->sp);
    rq_coord3(c->sp);
    rand_unit(r, c->sn);
    ray_dir_round(c->sn);
    double n[3];
    copy3(n, c->sn);
    normalize3(n);
    c->mode = irand(r, 4);
    bool eye_set = false;
    sh->n_lights = 1 + irand(r, 3);
    for (int j = 0; j < sh->n_lights; j++) {
        diffk_light_t *L = &sh->lights[j];
        L->kind = irand(r, 3);
        for (int i = 0; i < 3; i++)
            L->color[i] = rand_frac(r);
        double l[3];
        if (irand(r, 4) == 0)
            rand_unit(r, l); /* anywhere, also behind the surface */
        else
            dir_with_cos(r, n, -rand_cos(r), l); /* in front, often grazing */
        if (j == 0 && c->mode <= 1) {
            /* e near r = 2 (n . l) n - l */
            double nl = dot3(n, l), rr[3], e[3];
            for (int i = 0; i < 3; i++)
                rr[i] = 2 * nl * n[i] - l[i];
            normalize3(rr);
            rotate_away(r, rr, c->mode == 0 ? logu(r, 1e-7, 0.5) : 0.0, e);
            for (int i = 0; i < 3; i++)
                c->sdir[i] = -e[i];
            eye_set = true;
        }
        place_light(r, L, c->sp, l);
        if (L->kind == DIFFK_LIGHT_SPOT)
            aim_spot(r, L, l, irand(r, 2));
    }
    if (!eye_set)
        rand_unit(r, c->sdir);
    if (irand(r, 8) == 0)
        scale3(c->sn, -1.0); /* seen from behind: two-sided */
    ray_dir_round(c->sdir);
}

/* Spot cone edge: one spot light, the point at an angle near the
 * half-angle from its axis, the surface facing the light (n = l), so that
 * the light reaches p exactly when p is in the cone. */
static void gen_spot(rng_t *r, dcase_t *c)
{
    diffk_shade_t *sh = &c->sh;
    sh->material = DIFFK_LAMBERT;
    sh->exponent = 1;
    set3(sh->color, 255, 255, 255);
    sh->n_lights = 1;
    diffk_light_t *L = &sh->lights[0];
    L->kind = DIFFK_LIGHT_SPOT;
    set3(L->color, 1, 1, 1);
    rand_point(r, c->sp);
    rq_coord3(c->sp);
    double l[3];
    rand_unit(r, l);
    c->mode = irand(r, 4);
    place_light(r, L, c->sp, l);
    aim_spot(r, L, l, c->mode != 0);
    /* n towards the light as placed (after rounding). */
    sub3(L->pos, c->sp, c->sn);
    if (!normalize3(c->sn))
        set3(c->sn, 0, 0, 1);
    ray_dir_round(c->sn);
    for (int i = 0; i < 3; i++)
        c->sdir[i] = -c->sn[i];
}

/* Shadow rays: 1..3 occluders of any kind; the segment is the first
 * object's test ray, with tmax NUM_MAX (directional), near that object's
 * hit, or anywhere. */
static void gen_shadow(rng_t *r, dcase_t *c)
{
    dcase_t tmp;
    c->sub = 1 + irand(r, SHADOW_OBJS);
    for (int j = 0; j < c->sub; j++) {
        gen_object(r, irand(r, 4), &tmp);
        obj_from_case(&tmp, &c->obj[j]);
        if (j == 0) {
            c->ray = tmp.ray;
            c->mode = tmp.mode;
        }
    }
    const diffk_obj_t *o = &c->obj[0];
    double t = -1;
    int s;
    switch (o->kind) {
    case K_PLANE: s = diffk_plane_double(o->p[0], o->p[1], &c->ray, &t); break;
    case K_SPHERE: s = diffk_sphere_double(o->p[0], o->radius, &c->ray, &t); break;
    case K_TRIANGLE: s = diffk_triangle_double(o->p[0], o->p[1], o->p[2], &c->ray, &t); break;
    default: s = diffk_box_double(o->p[0], o->p[1], &c->ray, &t); break;
    }
    switch (irand(r, 3)) {
    case 0: c->tmax = -1; break;
    case 1:
        c->tmax = s == DIFFK_HIT ? t * (1 + rsign(r) * logu(r, 1e-9, 1.0)) : logu(r, 0.01, 16000.0);
        break;
    default: c->tmax = logu(r, 0.01, 16000.0); break;
    }
    if (c->tmax >= 0)
        c->tmax = fmax(LSB, fmin(rq(c->tmax), TMAX));
}

/* Phong power: x in Q32.32 near 0, near 1, anywhere in [0, 1], or just
 * outside (clamped); k over 1..1024. */
static void gen_pow(rng_t *r, dcase_t *c)
{
    const double one = 4294967296.0;
    c->mode = irand(r, 8);
    switch (c->mode) {
    case 0: case 1: case 2: c->xq = (long long)(rng_next(r) % ((1ull << 32) + 1)); break;
    case 3: case 4: c->xq = (long long)(one - floor(logu(r, 1.0, one / 2))); break;
    case 5: c->xq = (long long)floor(logu(r, 1.0, one)); break;
    case 6: {
        static const long long special[] = {0, 1, 2, 0xffffffffLL, 0x100000000LL, 0x80000000LL, -1, -0x100000000LL,
                                            0x100000001LL, 0x7fffffffffffffffLL};
        c->xq = special[irand(r, 10)];
        break;
    }
    default: c->xq = (long long)(one - rng_next(r) % 65536); break;
    }
    c->k = irand(r, 4) == 0 ? (unsigned)rand_exponent(r) : 1u + (unsigned)irand(r, 1024);
}

/* Secondary rays (issue 12): a unit normal n (p[0]), a unit direction d
 * (ray.d), both rounded to Q16.16, and an index eta (radius) log-uniform
 * over the whole range 0.01..100, rounded. Modes: 0 entering at any
 * incidence (often grazing), 1 leaving, 2 near the critical angle (where
 * total internal reflection starts), 3 eta near 1, 4 normal incidence. */
static void gen_bounce(rng_t *r, dcase_t *c)
{
    double *n = c->p[0], *d = c->ray.d;
    c->mode = irand(r, 5);
    double eta = c->mode == 3 ? 1 + rsign(r) * logu(r, 1e-5, 0.1) : logu(r, 0.01, 100);
    bool leaving = c->mode == 1 || (c->mode >= 2 && irand(r, 2));
    double q = leaving ? eta : 1 / eta, cs;
    if (c->mode == 2 && q > 1)
        cs = fmin(1.0, sqrt(1 - 1 / (q * q)) * (1 + rsign(r) * logu(r, 1e-7, 1e-2)));
    else if (c->mode == 4)
        cs = 1;
    else
        cs = rand_cos(r);
    rand_unit(r, n);
    if (c->mode == 4 && irand(r, 2))
        set3(n, 0, 0, rsign(r)); /* exact */
    dir_with_cos(r, n, cs, d);
    if (leaving)
        scale3(n, -1); /* d . n > 0: the ray comes from the inside */
    rq3(n);
    ray_dir_round(d);
    c->radius = fmax(rq(eta), 0.01);
    c->radius = fmin(rq(c->radius), 100);
}

static void gen_case_rng(int kind, rng_t *r, dcase_t *c)
{
    memset(c, 0, sizeof *c);
    c->kind = kind;
    switch (kind) {
    case K_PLANE: gen_plane(r, c); break;
    case K_SPHERE: gen_sphere(r, c); break;
    case K_TRIANGLE: gen_triangle(r, c); break;
    case K_BOX: gen_box(r, c); break;
    case K_NORMAL: gen_normal(r, c); break;
    case K_SHADE: gen_shade(r, c); break;
    case K_POW: gen_pow(r, c); break;
    case K_SPOT: gen_spot(r, c); break;
    case K_SHADOW: gen_shadow(r, c); break;
    case K_REFLECT:
    case K_REFRACT:
    case K_SCHLICK: gen_bounce(r, c); break;
    default: gen_camera(r, c); break;
    }
}

#ifndef DIFF_NO_MAIN
static uint64_t diff_seed = 0x5EED0F0F1u;

/* Case `index` of `kind`: a pure function of (seed, kind, index). */
static void gen_case(int kind, long index, dcase_t *c)
{
    rng_t r = {splitmix64(diff_seed ^ splitmix64(((uint64_t)kind << 56) ^ (uint64_t)index)), NULL, 0};
    gen_case_rng(kind, &r, c);
}
#endif

/* Replay prints the evaluators' intermediate values. */
static bool diff_verbose;

/* ---- evaluation ------------------------------------------------------------ */

typedef struct {
    int sq, sd;        /* statuses: DIFFK_* (camera: cam_err_t) */
    double tq, td;     /* t of each build when it hits */
    bool rejected;     /* both builds refused the object or camera */
    bool disagree;     /* hit/miss (accept/reject) differ */
    bool band;         /* inside the stated band, where they may differ */
    bool compared;     /* both hit (camera: both accepted): t (rays) compared */
    bool far;          /* double hit beyond the Q16.16 range */
    /* How far the case is from the nearest decision boundary, in units of
     * the rounding analysis' half-width of the band: in the band iff
     * band_ratio <= MARGIN. */
    double band_ratio;
    /* The analysis' error terms in LSB: base (rounding of the last
     * operations) and cond (rounding amplified by the case's conditioning).
     * The stated bound is MARGIN * (base + cond). */
    double base, cond;
    double err, bound;               /* |t_q - t_d| (camera: worst direction component), LSB */
    double err2, base2, cond2, bound2; /* camera: worst origin component, LSB */
    double err_basis, err_focal;     /* camera: worst basis component, focal error (LSB) */
    double rel;                      /* |t_q - t_d| / max(t_d, 1) */
    const char *fail;                /* NULL, or what was violated */
} dres_t;

/* Compare t when both hit. ref is the double t; alt another acceptable
 * value (the other root, or NAN). */
static void compare_t(dres_t *res, double ref, double alt)
{
    double bound = MARGIN * (res->base + res->cond) * LSB;
    if (!(bound < INFINITY))
        return; /* parallel within rounding: t is not determined */
    res->compared = true;
    res->far = ref > TMAX;
    double tq = res->tq;
    double e = fabs(tq - fmin(ref, TMAX));
    if (alt == alt) {
        double e2 = fabs(tq - fmin(alt, TMAX));
        if (e2 < e)
            e = e2;
    }
    res->err = e / LSB;
    res->bound = bound / LSB;
    res->rel = e / fmax(ref, 1.0);
    if (!(e <= bound))
        res->fail = "t outside the bound";
    else if (ref > TMAX + bound && tq != TMAX)
        res->fail = "far hit not saturated to FX_MAX";
}

/* Hit/miss agreement; returns true when both hit (t to be compared). */
static bool agree(dres_t *res)
{
    bool hq = res->sq == DIFFK_HIT, hd = res->sd == DIFFK_HIT;
    res->band = res->band_ratio <= MARGIN;
    if (hq != hd) {
        res->disagree = true;
        if (!res->band)
            res->fail = "hit/miss differ outside the band";
        return false;
    }
    return hq;
}

static bool statuses(dres_t *res)
{
    if (res->sq == DIFFK_REJECTED || res->sd == DIFFK_REJECTED) {
        if (res->sq != res->sd)
            res->fail = "one build rejected the object";
        else
            res->rejected = true;
        return false;
    }
    return true;
}

/* x / unit, with 0 / 0 = 0. */
static double ratio(double x, double unit)
{
    return x == 0 ? 0.0 : fabs(x) / unit;
}

/* The plane part shared by planes and triangles: t = N / D with the unit
 * normal n (exact), the stored point a. The Q16.16 normal is within
 * NORM_ERR LSB per component, which moves D by |d|_1 NORM_ERR LSB, N by
 * |a - o|_1 NORM_ERR LSB, and t by (a - p) . dn / D_q16 (p the hit point):
 * |dt| <= |a - p|_1 NORM_ERR LSB / (|D| - |d|_1 NORM_ERR LSB). The
 * quotient itself (fxw_div) adds PLANE_T0. Returns the band ratio of the
 * plane's decisions (parallel, origin on the plane, t near 0). */
static double plane_terms(const double a[3], const double n[3], const diffk_ray_t *ray, dres_t *res, double *t_out,
                          double X[3])
{
    const double *o = ray->o, *d = ray->d;
    double ao[3], aX[3];
    sub3(a, o, ao);
    double D = dot3(d, n), N = dot3(ao, n), t = N / D;
    axpy3(X, o, t, d);
    sub3(a, X, aX);
    double dD = norm1(d) * NORM_ERR * LSB, dN = norm1(ao) * NORM_ERR * LSB;
    double den = fabs(D) - MARGIN * dD;
    res->base = PLANE_T0;
    res->cond = den > 0 ? norm1(aX) * NORM_ERR / den : INFINITY;
    *t_out = t;
    double r = fmin(ratio(D, dD), ratio(N, dN));
    return fmin(r, ratio(t, (res->base + res->cond) * LSB));
}

static void eval_plane(const dcase_t *c, dres_t *res)
{
    const double *a = c->p[0];
    res->sq = diffk_plane_q16(a, c->p[1], &c->ray, &res->tq);
    res->sd = diffk_plane_double(a, c->p[1], &c->ray, &res->td);
    if (!statuses(res))
        return;
    double n[3], t, X[3];
    copy3(n, c->p[1]);
    normalize3(n);
    res->band_ratio = plane_terms(a, n, &c->ray, res, &t, X);
    if (agree(res))
        compare_t(res, res->td, NAN);
}

/* Sphere: b = (c - o) . d, q = (c - o) - b d, disc = r^2 - |q|^2. The
 * Q16.16 disc differs by at most E = (|q|_1 + |b| |eps| + LSB) LSB
 * (scene units squared), eps = |d|^2 - 1: rounding b d moves q by 0.5 LSB
 * per component (2 q . dq <= |q|_1 LSB), rounding b by 0.5 LSB moves |q|^2
 * by 2 b eps 0.5 LSB when d is not exactly unit. The half chord
 * h = sqrt(disc) then moves by min(sqrt(E), E / h); b, the root and the
 * subtraction add SPHERE_T0. */
static void eval_sphere(const dcase_t *c, dres_t *res)
{
    const double *ctr = c->p[0], *o = c->ray.o, *d = c->ray.d;
    double rad = c->radius;
    res->sq = diffk_sphere_q16(ctr, rad, &c->ray, &res->tq);
    res->sd = diffk_sphere_double(ctr, rad, &c->ray, &res->td);
    if (!statuses(res))
        return;
    double oc[3], q[3];
    sub3(ctr, o, oc);
    double b = dot3(oc, d);
    axpy3(q, oc, -b, d);
    double eps = dot3(d, d) - 1.0;
    double disc = rad * rad - dot3(q, q);
    double E = (norm1(q) + fabs(b) * fabs(eps) + LSB) * LSB;
    double h = disc > 0 ? sqrt(disc) : 0.0;
    double t0 = b - h, t1 = b + h;
    res->base = SPHERE_T0;
    res->cond = (h > 0 ? fmin(sqrt(E), E / h) : sqrt(E)) / LSB;
    double tb = (res->base + res->cond) * LSB;
    res->band_ratio = ratio(disc, E);
    if (disc >= -MARGIN * E)
        res->band_ratio = fmin(res->band_ratio, fmin(ratio(t0, tb), ratio(t1, tb)));
    if (agree(res)) {
        /* Near t = 0 the builds may pick different roots. */
        bool near0 = fabs(t0) <= MARGIN * tb || fabs(t1) <= MARGIN * tb;
        double alt = near0 ? (fabs(res->td - t0) < fabs(res->td - t1) ? t1 : t0) : NAN;
        compare_t(res, res->td, alt);
    }
}

/* Triangle: the plane part, plus the edge tests. An edge value
 * e = (p - o) . ((q - o) x d) rounds the cross product (0.5 LSB per
 * component), so it moves by TRI_EDGE |p - o|_1 LSB; and e = D |pq| s,
 * with s the signed in-plane distance of the hit point X from the edge's
 * line, so s may change sign within TRI_EDGE |p - o|_1 LSB / (|D| |pq|). */
static void eval_triangle(const dcase_t *c, dres_t *res)
{
    const double *P[3] = {c->p[0], c->p[1], c->p[2]}, *o = c->ray.o, *d = c->ray.d;
    res->sq = diffk_triangle_q16(P[0], P[1], P[2], &c->ray, &res->tq);
    res->sd = diffk_triangle_double(P[0], P[1], P[2], &c->ray, &res->td);
    /* Exact cross product of the rounded edges (64-bit mantissas hold the
     * products of two Q16.16 numbers). */
    long double e1[3], e2[3], cr[3];
    for (int i = 0; i < 3; i++) {
        e1[i] = (long double)P[1][i] - P[0][i];
        e2[i] = (long double)P[2][i] - P[0][i];
    }
    cr[0] = e1[1] * e2[2] - e1[2] * e2[1];
    cr[1] = e1[2] * e2[0] - e1[0] * e2[2];
    cr[2] = e1[0] * e2[1] - e1[1] * e2[0];
    if (res->sq == DIFFK_DEGENERATE || res->sd == DIFFK_DEGENERATE) {
        /* Collinear in exact arithmetic: both say so. The double cross
         * product of nearly collinear large coordinates may cancel to 0. */
        double crmax = (double)fmaxl(fabsl(cr[0]), fmaxl(fabsl(cr[1]), fabsl(cr[2])));
        if (res->sq == res->sd || (res->sq != DIFFK_DEGENERATE && crmax < 1e-6))
            res->rejected = true;
        else
            res->fail = "one build calls the triangle degenerate";
        return;
    }
    if (!statuses(res))
        return;
    double n[3] = {(double)cr[0], (double)cr[1], (double)cr[2]}, t, X[3];
    normalize3(n);
    double br = plane_terms(P[0], n, &c->ray, res, &t, X);
    if (diff_verbose)
        printf("  plane decisions: ratio %.4g, t %.17g, D %.6g\n", br, t, dot3(d, n));
    double D = fabs(dot3(d, n));
    /* Edge k: s_k positive inside; its band is eps_k. Inside, one edge
     * near enough can flip to a miss. Outside, a hit needs all three signs
     * equal (the test accepts either winding): every edge the point is
     * outside of flips, or every edge it is inside of does. */
    double in_min = INFINITY, out_max = 0, pos_max = 0;
    for (int k = 0; k < 3; k++) {
        const double *p0 = P[k], *p1 = P[(k + 1) % 3];
        double pq[3], px[3], cx[3], po[3], qo[3];
        sub3(p1, p0, pq);
        sub3(X, p0, px);
        cross3(pq, px, cx);
        double len = norm3(pq);
        double s = dot3(cx, n) / len;
        sub3(p0, o, po);
        sub3(p1, o, qo);
        double eps = TRI_EDGE * LSB * fmax(norm1(po), norm1(qo)) / (len * D);
        double rk = ratio(s, eps);
        if (diff_verbose)
            printf("  edge %d: in-plane distance %.6g, band half-width %.6g (ratio %.4g)\n", k, s, eps, rk);
        in_min = fmin(in_min, rk);
        if (s < 0)
            out_max = fmax(out_max, rk);
        else
            pos_max = fmax(pos_max, rk);
    }
    double edge = out_max > 0 ? fmin(out_max, pos_max) : in_min;
    if (!(edge == edge))
        edge = 0; /* D == 0: parallel, the plane part decides */
    res->band_ratio = fmin(br, edge);
    if (agree(res))
        compare_t(res, res->td, NAN);
}

/* Box: each slab t is one rounded quotient of exact operands (BOX_T0), so
 * the entry/exit comparison can flip only when the chord through the box
 * (or the gap by which the ray misses it) is within 2 BOX_T0: the ray
 * passes that close to the edge where the entry and exit faces meet.
 * Near t = 0 (origin on the surface) the builds may pick different ends. */
static void eval_box(const dcase_t *c, dres_t *res)
{
    const double *lo = c->p[0], *hi = c->p[1], *o = c->ray.o, *d = c->ray.d;
    res->sq = diffk_box_q16(lo, hi, &c->ray, &res->tq);
    res->sd = diffk_box_double(lo, hi, &c->ray, &res->td);
    if (!statuses(res))
        return;
    double tnear = -INFINITY, tfar = INFINITY;
    for (int i = 0; i < 3; i++) {
        if (d[i] == 0) {
            if (o[i] < lo[i] || o[i] > hi[i])
                tfar = -INFINITY;
            continue;
        }
        double t1 = (lo[i] - o[i]) / d[i], t2 = (hi[i] - o[i]) / d[i];
        tnear = fmax(tnear, fmin(t1, t2));
        tfar = fmin(tfar, fmax(t1, t2));
    }
    res->base = BOX_T0;
    res->cond = 0;
    double tb = BOX_T0 * LSB;
    res->band_ratio = fmin(ratio(tfar - tnear, 2 * tb), fmin(ratio(tnear, tb), ratio(tfar, tb)));
    if (!(res->band_ratio == res->band_ratio))
        res->band_ratio = INFINITY; /* -inf - -inf: no slab at all */
    if (agree(res)) {
        double alt = fabs(tnear) <= MARGIN * tb ? (fabs(res->td - tnear) < fabs(res->td - tfar) ? tfar : tnear) : NAN;
        compare_t(res, res->td, alt);
    }
}

/* Camera: every quantity against its cap (see CAM_*_CAP above). Inputs
 * are the same rounded values in both builds. */
static void eval_camera(const dcase_t *c, dres_t *res)
{
    const diffk_cam_t *cam = &c->cam;
    diffk_ray_t rq16[CAM_PIXELS], rdbl[CAM_PIXELS];
    res->sq = diffk_cam_q16(cam, CAM_PIXELS, c->px, c->py, rq16);
    res->sd = diffk_cam_double(cam, CAM_PIXELS, c->px, c->py, rdbl);
    int H = cam->height, W = cam->width;
    double theta = cam->fov_deg / 2 * PI / 180, cot = 1 / tan(theta);
    if (res->sq != 0 || res->sd != 0) {
        if (res->sq == res->sd) {
            res->rejected = true;
            return;
        }
        res->disagree = true;
        /* Borderline, in units of the q16 test's rounding: H cot(fov/2)
         * near 32767 (narrow) or near 1 (wide), with cot within
         * CAM_FOCAL_REL; sin(up, gaze)^2 near 2^-12 (q16 decides exactly
         * on the same inputs, so only double's own rounding); the
         * orthographic extent within the rounding of its reach,
         * round(round(s/2) W / H) + round(s/2), i.e. 0.5 W/H + 1 LSB. */
        double br = INFINITY;
        if (cam->kind == DIFFK_PERSPECTIVE) {
            double F = H * cot;
            br = ratio(F - 32767, F * CAM_FOCAL_REL + LSB);
            br = fmin(br, ratio(F - 1, F * CAM_FOCAL_REL + LSB));
        }
        double cr[3];
        cross3(cam->gaze, cam->up, cr);
        double s2 = dot3(cr, cr) / (dot3(cam->gaze, cam->gaze) * dot3(cam->up, cam->up));
        br = fmin(br, ratio(s2 - 1.0 / 4096, 1e-12 / 4096));
        if (cam->kind == DIFFK_ORTHOGRAPHIC) {
            double hh = cam->scale / 2, reach = hh * W / H + hh;
            for (int i = 0; i < 3; i++)
                br = fmin(br, ratio(fabs(cam->eye[i]) - (COORD - reach), (0.5 * W / H + 1.0) * LSB));
        }
        res->band_ratio = br;
        res->band = br <= MARGIN;
        if (!res->band)
            res->fail = "one build rejected the camera";
        return;
    }
    res->band_ratio = INFINITY;
    res->compared = true;
    /* Basis and focal. */
    double bq[3][3], bd[3][3], fq = 0, fd = 0;
    if (diffk_cam_basis_q16(cam, bq, &fq) != 0 || diffk_cam_basis_double(cam, bd, &fd) != 0) {
        res->fail = "cam_setup differs between calls";
        return;
    }
    for (int k = 0; k < 3; k++)
        for (int i = 0; i < 3; i++)
            res->err_basis = fmax(res->err_basis, fabs(bq[k][i] - bd[k][i]) / LSB);
    res->err_focal = fabs(fq - fd) / LSB;
    double focal_bound = cam->kind == DIFFK_PERSPECTIVE ? 1.0 + CAM_FOCAL_REL * fd / LSB : 0.0;
    /* Rays. */
    double worst_o = -1;
    res->err = 0;
    res->base = cam->kind == DIFFK_PERSPECTIVE ? CAM_DIR_CAP : CAM_BASIS_CAP;
    res->cond = 0;
    for (int k = 0; k < CAM_PIXELS; k++) {
        double ix = 2.0 * c->px[k] - W + 1, iy = 2.0 * c->py[k] - H + 1;
        double co = 0;
        if (cam->kind == DIFFK_ORTHOGRAPHIC) {
            double ou = cam->scale * W / (2.0 * H * (W > 1 ? W - 1 : 1)) * ix;
            double ov = cam->scale / (2.0 * (H > 1 ? H - 1 : 1)) * iy;
            co = CAM_ORIGIN_PER_UNIT * (fabs(ou) + fabs(ov));
        }
        for (int i = 0; i < 3; i++) {
            res->err = fmax(res->err, fabs(rq16[k].d[i] - rdbl[k].d[i]) / LSB);
            double eo = fabs(rq16[k].o[i] - rdbl[k].o[i]) / LSB;
            double ro = eo / (CAM_ORIGIN_BASE + co);
            if (ro > worst_o) {
                worst_o = ro;
                res->err2 = eo;
                res->base2 = CAM_ORIGIN_BASE;
                res->cond2 = co;
            }
        }
    }
    res->bound = res->base;
    res->bound2 = res->base2 + res->cond2;
    if (!(res->err_basis <= CAM_BASIS_CAP))
        res->fail = "camera basis beyond its cap";
    else if (!(res->err_focal <= focal_bound && res->err_focal <= CAM_FOCAL_CAP))
        res->fail = "focal beyond its cap";
    else if (!(res->err <= res->bound))
        res->fail = "ray direction beyond its cap";
    else if (!(res->err2 <= res->bound2 && res->err2 <= CAM_ORIGIN_CAP))
        res->fail = "ray origin beyond its cap";
    else if (!(res->bound2 <= CAM_ORIGIN_CAP))
        res->fail = "orthographic offsets beyond the domain (cap would not hold)";
}

static void diff_eval(const dcase_t *c, dres_t *res);

/* ---- lighting (issue 11): normals, shading, the power, spot cones, shadow rays
 *
 * The bounds, in LSB (2^-16) unless said otherwise; docs/ACCURACY.md,
 * "Shading error", derives each:
 *  - NORM_Q: a Q16.16 unit vector from exact input (fx_normalize3), per
 *    component;
 *  - NL_ERR: n . l rounded once, l normalised in Q16.16: |n|_1 NORM_Q +
 *    0.5 <= sqrt(3) 0.504 + 0.5 for the same n in both builds;
 *  - R_ERR: r = 2 (n . l) n - l per component, besides 2 |n_i| NL_ERR:
 *    vec3_scale's rounding (0.5) and l's (NORM_Q);
 *  - POW_CAP: numw_pow_int against the exact x^k of its Q32.32 argument;
 *  - the spot cone's margin m = (-v) . s - cos(angle) |v| (scene units)
 *    changes sign in Q16.16 only when |m| <= |v|_1 SPOT_AXIS + |v|
 *    (SPOT_COS + SPOT_LEN cos(angle)) + 0.5 LSB cos(angle) (axis and
 *    cosine in Q2.30, |v| from fx_normalize3_len: within 0.5 LSB + 2^-24
 *    relative). */
#define NORM_Q 0.504
#define NL_ERR (1.7321 * NORM_Q + 0.5)
#define R_ERR (0.5 + NORM_Q)
/* 0.5 for the final rounding, plus k 2^-16 LSB for the argument's
 * truncation to Q1.31 (2^-32, times the slope k x^(k-1) <= k) and 2k
 * 2^-16 for the Q1.31 roundings of the products (each 2^-32 relative,
 * doubled by every later squaring). */
#define POW_CAP_K(k) (0.5 + 3.0 * (k) / 65536)
#define POW_CAP POW_CAP_K(1024)
#define SPOT_AXIS (1.0 / 536870912.0)             /* 2^-29 */
#define SPOT_COS (1.0 / 1073741824.0 + 1e-8)      /* 2^-30 + 1e-8 */
#define SPOT_LEN (1.0 / 16777216.0)               /* 2^-24: fx_normalize3_len */
/* Stated caps for one light in 1/255 units: the per-case bound below never
 * exceeds MARGIN (SHADE_A + SHADE_B k) per light that reaches p (and
 * MARGIN 0.5 LSB for the ambient term). */
#define SHADE_A ((255 * NL_ERR + 3.0 + 255 * POW_CAP) / 65536)
#define SHADE_B (255 * (2 * NL_ERR + 1.7321 * R_ERR) / 65536)

static double maxabs3(const double a[3], const double b[3])
{
    return fmax(fabs(a[0] - b[0]), fmax(fabs(a[1] - b[1]), fabs(a[2] - b[2])));
}

/* Angle between two vectors, radians (robust near 0). */
static double angle3(const double a[3], const double b[3])
{
    double c[3];
    cross3(a, b, c);
    return atan2(norm3(c), dot3(a, b));
}

/* Normals: the Q16.16 geom_<kind>_surface normal against the double
 * build's, and the double build's against an independent exact normal.
 *  plane     the stored normal: NORM_Q;
 *  triangle  normalised from the exact cross product: NORM_Q (+ 2^-13
 *            from keeping 30 bits); the double build's own cross product
 *            cancels for nearly collinear vertices, so its deviation from
 *            the exact normal (asserted separately) is added;
 *  sphere    v = -q -+ h d normalised: q per component 0.5 + 0.5 |d_i|,
 *            h d 0.5, h itself as in eval_sphere (+ 0.5 for the root), so
 *            |dv| <= 2.24 + dh LSB and the unit normal moves by |dv| / |v|;
 *            the root (near or far side) may differ when t0 is within the
 *            sphere's t bound of 0 (band);
 *  box       an axis: identical, unless two slabs' entry (or exit) t are
 *            within 2 BOX_T0 of each other or the ray starts within
 *            BOX_T0 of a face (band). */
static void eval_normal(const dcase_t *c, dres_t *res)
{
    diffk_obj_t o;
    memset(&o, 0, sizeof o);
    o.kind = c->sub;
    memcpy(o.p, c->p, sizeof o.p);
    o.radius = c->radius;
    double nq[3], nd[3], tq = 0, td = 0;
    res->sq = diffk_surface_q16(&o, &c->ray, &tq, nq);
    res->sd = diffk_surface_double(&o, &c->ray, &td, nd);
    if (res->sq == DIFFK_DEGENERATE || res->sd == DIFFK_DEGENERATE) {
        if (res->sq != res->sd && res->sd == DIFFK_DEGENERATE) {
            /* the double cross product of nearly collinear vertices may cancel */
            res->rejected = true;
            return;
        }
        if (res->sq != res->sd)
            res->fail = "one build calls the triangle degenerate";
        res->rejected = res->sq == res->sd;
        return;
    }
    if (!statuses(res))
        return;
    /* Invariants (the fuzzer relies on them): unit length within the
     * rounding, components in [-1, 1]. */
    double lq = norm3(nq);
    if (!(fabs(lq - 1) <= 4 * LSB) || fabs(nq[0]) > 1 || fabs(nq[1]) > 1 || fabs(nq[2]) > 1) {
        res->fail = "q16 normal not unit length";
        return;
    }
    const double *d = c->ray.d, *o3 = c->ray.o;
    double exact[3], dev_d = 0; /* the double build's deviation from exact, LSB */
    res->base = NORM_Q;
    res->cond = 0;
    res->band_ratio = INFINITY;
    switch (c->sub) {
    case K_PLANE:
        copy3(exact, c->p[1]);
        normalize3(exact);
        dev_d = maxabs3(nd, exact) / LSB;
        if (!(dev_d <= 1e-9))
            res->fail = "double plane normal differs from n / |n|";
        break;
    case K_TRIANGLE: {
        long double e1[3], e2[3], cr[3], len;
        for (int i = 0; i < 3; i++) {
            e1[i] = (long double)c->p[1][i] - c->p[0][i];
            e2[i] = (long double)c->p[2][i] - c->p[0][i];
        }
        cr[0] = e1[1] * e2[2] - e1[2] * e2[1];
        cr[1] = e1[2] * e2[0] - e1[0] * e2[2];
        cr[2] = e1[0] * e2[1] - e1[1] * e2[0];
        len = sqrtl(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]);
        long double l1 = sqrtl(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
        long double l2 = sqrtl(e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2]);
        for (int i = 0; i < 3; i++)
            exact[i] = (double)(cr[i] / len);
        dev_d = maxabs3(nd, exact) / LSB;
        /* double cross product: each component within 2^-52 |e1| |e2|. */
        double cap_d = (double)(8 * l1 * l2 / len) * 0x1p-53 / LSB + 1e-9;
        if (!(dev_d <= cap_d))
            res->fail = "double triangle normal differs from the exact one";
        res->base = NORM_Q + 1.0 / 8192;
        res->cond = dev_d;
        break;
    }
    case K_SPHERE: {
        const double *ctr = c->p[0];
        double rad = c->radius, oc[3], q[3];
        sub3(ctr, o3, oc);
        double b = dot3(oc, d);
        axpy3(q, oc, -b, d);
        double eps = dot3(d, d) - 1.0;
        double disc = rad * rad - dot3(q, q);
        double E = (norm1(q) + fabs(b) * fabs(eps) + LSB) * LSB;
        double h = disc > 0 ? sqrt(disc) : 0.0;
        double t0 = b - h;
        double dh = (h > 0 ? fmin(sqrt(E), E / h) : sqrt(E)) / LSB + 0.5;
        /* |v| is r only for a unit d: with |d|^2 = 1 + eps, q . d = -b eps,
         * so a far sphere (b eps comparable to r) has a much shorter v,
         * and the same |dv| turns the normal further. */
        double v[3];
        for (int i = 0; i < 3; i++)
            v[i] = -q[i] + (t0 > 0 ? -h : h) * d[i];
        double vlen = norm3(v);
        res->cond = (2.24 + dh) / fmax(vlen, LSB);
        double tb = (SPHERE_T0 + dh) * LSB;
        res->band_ratio = ratio(t0, tb);
        /* independent: p = o + t d from the double build's t, n = (p - c) / |p - c| */
        long double pc[3], pl = 0;
        for (int i = 0; i < 3; i++) {
            pc[i] = ((long double)o3[i] - ctr[i]) + (long double)td * d[i]; /* o - c exact */
            pl += pc[i] * pc[i];
        }
        pl = sqrtl(pl);
        for (int i = 0; i < 3; i++)
            exact[i] = (double)(pc[i] / pl);
        dev_d = maxabs3(nd, exact) / LSB;
        /* The double build's own rounding: q and b within dq = 2^-52 (|oc|
         * + r + t), disc within 2 |q| dq, so h within dh (as for Q16.16);
         * over |p - c|. */
        double dq = 0x1p-52 * (norm3(oc) + rad + fabs(td)), e2 = 2 * norm3(q) * dq + dq * dq;
        double dhd = h > 0 ? fmin(sqrt(e2), e2 / h) : sqrt(e2);
        double cap_d = 8 * (dq + dhd) / (double)pl / LSB + 1e-9;
        if (!(dev_d <= cap_d))
            res->fail = "double sphere normal differs from (p - c) / |p - c|";
        break;
    }
    default: {
        const double *lo = c->p[0], *hi = c->p[1];
        /* entry candidates per axis, saturated like Q16.16 */
        double tn[3], tf[3], tb = BOX_T0 * LSB, br = INFINITY, tnear = -TMAX, tfar = TMAX;
        int m = 0;
        bool outside = false;
        for (int i = 0; i < 3; i++) {
            if (d[i] == 0) {
                outside = outside || o3[i] < lo[i] || o3[i] > hi[i];
                continue;
            }
            double u1 = (lo[i] - o3[i]) / d[i], u2 = (hi[i] - o3[i]) / d[i];
            double t1 = clampd(u1, -TMAX, TMAX), t2 = clampd(u2, -TMAX, TMAX);
            /* Both ends of a slab beyond the range saturate to the same
             * value in Q16.16, which then cannot tell its two faces apart
             * (only rays that miss the box far away). */
            if (u1 != u2)
                br = fmin(br, ratio(t1 - t2, 2 * tb));
            tn[m] = fmin(t1, t2);
            tf[m] = fmax(t1, t2);
            m++;
        }
        for (int i = 0; i < m; i++) {
            tnear = fmax(tnear, tn[i]);
            tfar = fmin(tfar, tf[i]);
            for (int j = i + 1; j < m; j++)
                br = fmin(br, fmin(ratio(tn[i] - tn[j], 2 * tb), ratio(tf[i] - tf[j], 2 * tb)));
        }
        if (!outside)
            br = fmin(br, fmin(ratio(tnear, tb), ratio(tfar, tb)));
        /* exit/entry ties at the far corner only matter for the face chosen */
        res->band_ratio = br;
        copy3(exact, nd);
        res->base = 0;
        break;
    }
    }
    res->band = res->band_ratio <= MARGIN;
    res->err = maxabs3(nq, nd) / LSB;
    res->err2 = angle3(nq, nd) / LSB; /* radians, in units of 2^-16 */
    res->rel = dev_d;
    if (res->fail)
        return;
    if (c->sub == K_BOX) {
        res->disagree = res->err != 0;
        if (res->disagree && !res->band)
            res->fail = "box face differs outside the band";
        res->base = 0.5; /* for the table: the box error is 0 or 1 */
        res->bound = MARGIN * res->base;
        res->compared = !res->disagree;
        return;
    }
    if (res->band)
        return;
    res->compared = true;
    res->bound = MARGIN * (res->base + res->cond);
    if (!(res->err <= res->bound))
        res->fail = "normal beyond its bound";
}

/* The shading formula, straight from the issue's text in long double (not
 * the core's code): the independent check of the double build. Also the
 * per-light quantities the Q16.16 bound needs. */
typedef struct {
    long double rgb[3];
    int mask;
    double ndl[DIFFK_MAX_LIGHTS];  /* n . l (n turned towards the ray) */
    double rde[DIFFK_MAX_LIGHTS];  /* r . e */
    double spot_m[DIFFK_MAX_LIGHTS], spot_t[DIFFK_MAX_LIGHTS]; /* cone margin and its threshold (scene units) */
    bool present[DIFFK_MAX_LIGHTS]; /* the light has a direction at p (not at p itself) */
    double ne, e1;                  /* |n . e|, |e|_1 */
} oracle_t;

static void shade_oracle(const dcase_t *c, oracle_t *O)
{
    const diffk_shade_t *sh = &c->sh;
    memset(O, 0, sizeof *O);
    long double n[3], e[3], nd = 0;
    for (int i = 0; i < 3; i++)
        nd += (long double)c->sn[i] * c->sdir[i];
    for (int i = 0; i < 3; i++) {
        n[i] = nd > 0 ? -(long double)c->sn[i] : c->sn[i];
        e[i] = -(long double)c->sdir[i];
    }
    O->ne = fabs((double)(n[0] * e[0] + n[1] * e[1] + n[2] * e[2]));
    O->e1 = (double)(fabsl(e[0]) + fabsl(e[1]) + fabsl(e[2]));
    for (int i = 0; i < 3; i++)
        O->rgb[i] = (long double)sh->color[i] * sh->ambient[i];
    for (int j = 0; j < sh->n_lights; j++) {
        const diffk_light_t *L = &sh->lights[j];
        long double l[3], len = 0;
        O->spot_m[j] = INFINITY;
        for (int i = 0; i < 3; i++) {
            l[i] = L->kind == DIFFK_LIGHT_DIRECTIONAL ? -(long double)L->dir[i] : (long double)L->pos[i] - c->sp[i];
            len += l[i] * l[i];
        }
        len = sqrtl(len);
        if (L->kind == DIFFK_LIGHT_SPOT) {
            long double s[3], sl = sqrtl((long double)L->dir[0] * L->dir[0] + (long double)L->dir[1] * L->dir[1] +
                                         (long double)L->dir[2] * L->dir[2]);
            long double m = 0, v1 = 0, cs = cosl((long double)L->angle * 3.14159265358979323846264338327950288L / 180);
            for (int i = 0; i < 3; i++) {
                s[i] = L->dir[i] / sl;
                m -= l[i] * s[i];
                v1 += fabsl(l[i]);
            }
            m -= cs * len;
            O->spot_m[j] = (double)m;
            O->spot_t[j] = (double)(v1 * SPOT_AXIS + len * (SPOT_COS + SPOT_LEN * cs) + 0.5 * LSB * cs);
            if (m < 0)
                continue; /* outside the cone */
        }
        if (len == 0)
            continue; /* the light is at p */
        O->present[j] = true;
        long double ndl = 0, rde = 0;
        for (int i = 0; i < 3; i++) {
            l[i] /= len;
            ndl += n[i] * l[i];
        }
        O->ndl[j] = (double)ndl;
        if (ndl <= 0)
            continue;
        O->mask |= 1 << j;
        for (int i = 0; i < 3; i++)
            O->rgb[i] += (long double)sh->color[i] * L->color[i] * ndl;
        if (sh->material != DIFFK_PHONG)
            continue;
        for (int i = 0; i < 3; i++)
            rde += (2 * ndl * n[i] - l[i]) * e[i];
        O->rde[j] = (double)rde;
        if (rde <= 0)
            continue;
        /* r and e are unit vectors when n is: clamp the rounding of the
         * inputs' lengths, as the builds do */
        long double pw = powl(rde > 1 ? 1.0L : rde, sh->exponent);
        for (int i = 0; i < 3; i++)
            O->rgb[i] += 255.0L * sh->specular[i] * L->color[i] * pw;
    }
}

/* Shading: the Q16.16 colour against the double build's, per channel in
 * 1/255 units (err is in LSB = 2^-16 of a 1/255 unit), within the case's
 * bound MARGIN (A + B) with
 *   A = 0.5 (ambient product) + sum over lights of c_d c_l NL_ERR + 1.5
 *       + for phong 255 c_s c_l POW_CAP + 1.5,
 *   B = sum over phong lights of 255 c_s c_l k x^(k-1) DX,
 *       DX = 2 NL_ERR |n . e| + R_ERR |e|_1 (the error of r . e),
 *       x = min(1, r . e + DX): the power's slope over the error's reach.
 * Discontinuities are a band: a spot whose cone margin is within its
 * threshold, and for phong a light with |n . l| within NL_ERR (the
 * highlight appears at once when n . l > 0). The lights that reach p
 * (mask) must agree outside those bands. */
static void eval_shade(const dcase_t *c, dres_t *res)
{
    const diffk_shade_t *sh = &c->sh;
    double cq[3], cd[3];
    int mq = 0, md = 0;
    res->sq = diffk_shade_q16(sh, c->sp, c->sn, c->sdir, cq, &mq);
    res->sd = diffk_shade_double(sh, c->sp, c->sn, c->sdir, cd, &md);
    if (res->sq != 0 || res->sd != 0) {
        if (res->sq != res->sd)
            res->fail = "one build refused the material or a light";
        res->rejected = true;
        return;
    }
    /* invariant: channels in [0, 255 (1 + 2 lights)] */
    for (int i = 0; i < 3; i++)
        if (!(cq[i] >= 0 && cq[i] <= 255.0 * (1 + 2 * sh->n_lights)))
            res->fail = "q16 colour out of range";
    oracle_t O;
    shade_oracle(c, &O);
    /* the double build against the independent formula */
    double dev = 0;
    int omask_tol = 0; /* lights whose decision the oracle cannot make reliably */
    for (int j = 0; j < sh->n_lights; j++)
        if (fabs(O.spot_m[j]) <= 1e-9 * (1 + O.spot_t[j] / LSB) || (O.present[j] && fabs(O.ndl[j]) <= 1e-12))
            omask_tol |= 1 << j;
    for (int i = 0; i < 3; i++)
        dev = fmax(dev, fabs(cd[i] - (double)O.rgb[i]));
    res->rel = omask_tol ? NAN : dev; /* the statistics take only the asserted cases */
    if (!res->fail && ((O.mask ^ md) & ~omask_tol))
        res->fail = "double build's lights differ from the formula's";
    else if (!res->fail && !omask_tol && !(dev <= 1e-9 * (1 + sh->exponent)))
        res->fail = "double build's colour differs from the formula's";
    /* bands */
    double band_mask = INFINITY, band_col = INFINITY;
    for (int j = 0; j < sh->n_lights; j++) {
        if (sh->lights[j].kind == DIFFK_LIGHT_SPOT) {
            double rs = ratio(O.spot_m[j], O.spot_t[j]);
            band_mask = fmin(band_mask, rs);
            band_col = fmin(band_col, rs);
        }
        if (O.present[j]) {
            double rn = ratio(O.ndl[j], NL_ERR * LSB);
            band_mask = fmin(band_mask, rn);
            if (sh->material == DIFFK_PHONG)
                band_col = fmin(band_col, rn);
        }
    }
    res->band_ratio = band_mask;
    bool skip = band_col <= MARGIN; /* a discontinuity of the colour: not compared */
    res->band = skip || (mq != md && band_mask <= MARGIN);
    if (mq != md) {
        res->disagree = true;
        if (band_mask > MARGIN && !res->fail)
            res->fail = "lights reaching p differ outside the band";
    }
    if (skip || res->fail)
        return;
    /* the bound, per channel */
    double DX = 2 * NL_ERR * O.ne + R_ERR * O.e1;
    double worst = -1;
    for (int i = 0; i < 3; i++) {
        double A = 0.5, B = 0;
        for (int j = 0; j < sh->n_lights; j++) {
            const diffk_light_t *L = &sh->lights[j];
            if (!O.present[j])
                continue;
            A += sh->color[i] * L->color[i] * NL_ERR + 1.5;
            if (sh->material != DIFFK_PHONG || !(md & (1 << j)))
                continue;
            double S = 255 * sh->specular[i] * L->color[i];
            double x = fmin(1.0, fmax(O.rde[j], 0.0) + DX * LSB);
            A += S * POW_CAP_K(sh->exponent) + 1.5;
            B += S * sh->exponent * pow(x, sh->exponent - 1) * DX;
        }
        double e = fabs(cq[i] - cd[i]) * 65536;
        double rr = e / (MARGIN * (A + B));
        if (rr > worst) {
            worst = rr;
            res->err = e;
            res->base = A;
            res->cond = B;
        }
    }
    res->compared = true;
    res->bound = MARGIN * (res->base + res->cond);
    if (!(res->err <= res->bound))
        res->fail = "colour beyond its bound";
}

/* The power: Q16.16 numw_pow_int against the exact x^k of its argument
 * (x clamped to [0, 1]), POW_CAP; the double build within (2k) 2^-53
 * relative (one rounding per product, doubled by each squaring). */
static void eval_pow(const dcase_t *c, dres_t *res)
{
    double pq = diffk_pow_q16(c->xq, c->k), pd = diffk_pow_double(c->xq, c->k);
    long double x = (long double)c->xq / 4294967296.0L;
    x = x < 0 ? 0 : (x > 1 ? 1 : x);
    long double pe = powl(x, (long double)c->k);
    res->sq = res->sd = DIFFK_HIT;
    res->compared = true;
    res->base = POW_CAP_K(c->k);
    res->bound = res->base;
    res->band_ratio = INFINITY;
    res->err = (double)(fabsl((long double)pq - pe) / LSB);
    /* below 1e-280 the double build underflows (gradually): absolute */
    res->rel = (double)(fabsl((long double)pd - pe) / (pe > 1e-280L ? pe : 1));
    if (!(res->err <= res->bound))
        res->fail = "q16 power beyond its cap";
    else if (!(res->rel <= (pe > 1e-280L ? 2.0 * c->k * 0x1p-53 : 1e-279)))
        res->fail = "double power differs from powl";
}

/* Spot cone: the light reaches p (mask bit 0) in both builds or in
 * neither, unless |m| is within the threshold (band). */
static void eval_spot(const dcase_t *c, dres_t *res)
{
    double cq[3], cd[3];
    int mq = 0, md = 0;
    res->sq = diffk_shade_q16(&c->sh, c->sp, c->sn, c->sdir, cq, &mq);
    res->sd = diffk_shade_double(&c->sh, c->sp, c->sn, c->sdir, cd, &md);
    if (res->sq != 0 || res->sd != 0) {
        if (res->sq != res->sd)
            res->fail = "one build refused the spot light";
        res->rejected = true;
        return;
    }
    oracle_t O;
    shade_oracle(c, &O);
    res->band_ratio = ratio(O.spot_m[0], O.spot_t[0]);
    if (O.present[0])
        res->band_ratio = fmin(res->band_ratio, ratio(O.ndl[0], NL_ERR * LSB));
    res->rel = O.spot_m[0];
    if ((O.mask ^ md) & 1 && fabs(O.spot_m[0]) > 1e-9 * (1 + O.spot_t[0] / LSB) &&
        !(O.present[0] && fabs(O.ndl[0]) <= 1e-12)) {
        res->fail = "double build's cone test differs from the formula's";
        return;
    }
    res->sq = (mq & 1) ? DIFFK_HIT : DIFFK_MISS;
    res->sd = (md & 1) ? DIFFK_HIT : DIFFK_MISS;
    agree(res);
}

/* Shadow rays: world_occluded is the OR of its kernels' decisions (hit
 * with t < tmax; any hit for NUM_MAX) in each build, and the two builds
 * agree unless no object blocks clearly and some object's decision is
 * ambiguous: its hit/miss in the kernel's band (eval_<kind>), or its t
 * within the kernel's t bound of tmax. */
static void eval_shadow(const dcase_t *c, dres_t *res)
{
    int oq = diffk_occluded_q16(c->sub, c->obj, &c->ray, c->tmax);
    int od = diffk_occluded_double(c->sub, c->obj, &c->ray, c->tmax);
    if (oq < 0 || od < 0) {
        if (oq != od)
            res->fail = "one build refused an occluder";
        res->rejected = true;
        return;
    }
    bool any_q = false, any_d = false, clear = false, far = false;
    double amb = INFINITY;
    for (int j = 0; j < c->sub; j++) {
        dcase_t cj;
        dres_t rj;
        memset(&cj, 0, sizeof cj);
        cj.kind = c->obj[j].kind;
        memcpy(cj.p, c->obj[j].p, sizeof cj.p);
        cj.radius = c->obj[j].radius;
        cj.ray = c->ray;
        diff_eval(&cj, &rj);
        if (rj.fail) {
            res->fail = rj.fail;
            return;
        }
        bool hq = rj.sq == DIFFK_HIT && (c->tmax < 0 ? rj.tq < TMAX : rj.tq < c->tmax);
        bool hd = rj.sd == DIFFK_HIT && (c->tmax < 0 || rj.td < c->tmax);
        any_q = any_q || hq;
        any_d = any_d || hd;
        double rr = rj.band_ratio;
        if (rj.sd == DIFFK_HIT && c->tmax >= 0)
            rr = fmin(rr, ratio(rj.td - c->tmax, (rj.base + rj.cond) * LSB));
        if (diff_verbose)
            printf("  occluder %d (%s): q16 %s t=%.17g, double %s t=%.17g, ratio %.4g\n", j, kind_name[cj.kind],
                   rj.sq == DIFFK_HIT ? "hit" : "miss", rj.tq, rj.sd == DIFFK_HIT ? "hit" : "miss", rj.td, rr);
        if (c->tmax < 0 && rj.sd == DIFFK_HIT && (rj.td > TMAX || (rj.sq == DIFFK_HIT && rj.tq >= TMAX)))
            far = true; /* see below */
        else if (hd && rr > MARGIN)
            clear = true;
        else
            amb = fmin(amb, rr);
    }
    /* world_occluded decides planes, triangles and boxes without a
     * division (core/scene/geom.c, geom_<kind>_occludes: the bounds compared as
     * fractions), so it may differ from "the hit kernel's rounded t <
     * tmax" only where that decision is itself ambiguous. */
    /* tmax at the top of the Q16.16 range is NUM_MAX there, which
     * world_occluded reads as "no limit" (directional lights). */
    if (c->tmax >= 32767.0)
        far = true;
    bool ambiguous = far || amb <= MARGIN;
    if (!ambiguous && ((oq != 0) != any_q || (od != 0) != any_d)) {
        res->fail = "world_occluded differs from its kernels";
        return;
    }
    res->sq = oq ? DIFFK_HIT : DIFFK_MISS;
    res->sd = od ? DIFFK_HIT : DIFFK_MISS;
    res->band_ratio = clear ? INFINITY : amb;
    /* A known difference (docs/ACCURACY.md, "Shading error"): with tmax =
     * NUM_MAX (a directional light) world_occluded should count any hit,
     * but a Q16.16 hit beyond the range saturates to t = FX_MAX = NUM_MAX
     * and fails t < tmax, so a plane met beyond 32768 units does not
     * block in Q16.16 and does in double. Counted as "far", not failed. */
    if (far && !clear) {
        res->far = true;
        if (oq != od) {
            res->disagree = true;
            res->band = true; /* counted in the band column too */
            return;
        }
    }
    agree(res);
}

/* ---- secondary rays (issue 12): reflected and transmitted directions and
 * Schlick's R from core/light/trace.c's trace_children (tests/diffk.c), Q16.16
 * and float against double from the same rounded d, n and eta.
 *
 * Error analysis, in LSB (2^-16), one rounding per operation: rd(v) is
 * 0.5 in Q16.16 and |v| 2^-24 / 2^-16 in float (|v| the operation's
 * result); the double build's own rounding (2^-53) is below both. With
 * ci = |d . n|, q = 1/eta entering (fx_div, correctly rounded) and eta
 * leaving (exact), s2 = 1 - ci^2:
 *   ci      dci = rd(1) (the exact wide dot product rounded once; float:
 *           three products and two sums, 3 rd(1))
 *   reflected r_i = d_i - 2 (d.n) n_i: rd(r_i) + 2 |n_i| dci
 *   cos2_t = 1 - q^2 s2: E2 = rd(q^2 s2) + s2 (rd(q^2) + 2 q dq) + q^2
 *           (rd(s2) + 2 ci dci); total internal reflection (cos2_t < 0)
 *           may differ when |cos2_t| <= MARGIN E2 (the band)
 *   cos_t = sqrt(cos2_t): Ect = rd(ct) + the larger change of sqrt over
 *           cos2_t -+ MARGIN E2 (about E2 / (2 ct) away from the critical
 *           angle, up to sqrt(MARGIN E2) near it)
 *   transmitted t_i = q d_i + (q ci - ct) n_i: rd(q d_i) + |d_i| dq +
 *           rd(k n_i) + |n_i| (rd(q ci) + ci dq + q dci + Ect)
 *   Schlick R = r0 + (1 - r0) x^5, r0 = ((1 - eta)/(1 + eta))^2, x =
 *           1 - ci entering, 1 - ct leaving: the rounding of each step
 *           propagated to first order (bounce_bounds).
 * The stated bound is MARGIN times that. The double build is also checked
 * against the issue's formulas written here (1e-9). */
typedef struct {
    double refl[3], trans[3], R;
    int tir, has_t;
} bres_t;

static double rd_of(bool flt, double v)
{
    return flt ? fabs(v) * 0x1p-24 * 65536.0 : 0.5;
}
/* A sum or difference: exact in Q16.16, rounded in float. */
static double rs_of(bool flt, double v)
{
    return flt ? rd_of(flt, v) : 0;
}

typedef struct {
    double er[3], et[3], eR, e2, cos2t;
} bbound_t;

static void bounce_bounds(const dcase_t *c, bool flt, bbound_t *b)
{
    const double *d = c->ray.d, *n = c->p[0];
    double eta = c->radius, dn = dot3(d, n), ci = fabs(dn);
    bool inside = dn > 0;
    double q = inside ? eta : 1 / eta, dq = inside ? 0 : rd_of(flt, q);
    double dci = flt ? 3 * rd_of(flt, 1) : 0.5;
    for (int i = 0; i < 3; i++)
        b->er[i] = rs_of(flt, d[i] + 2 * ci * n[i]) + rd_of(flt, 2 * ci * n[i]) + 2 * fabs(n[i]) * dci;
    double s2 = 1 - ci * ci, ds2 = rd_of(flt, ci * ci) + 2 * ci * dci;
    double dq2 = rd_of(flt, q * q) + 2 * q * dq;
    ds2 += rs_of(flt, s2);
    b->e2 = rd_of(flt, q * q * s2) + s2 * dq2 + q * q * ds2;
    b->cos2t = 1 - q * q * s2;
    double ct = sqrt(fmax(b->cos2t, 0));
    /* the root's slope is unbounded at 0: the exact change of sqrt over
     * cos2_t - MARGIN E2 .. cos2_t (concave: the larger side) */
    double ect = rd_of(flt, ct) + fmax(ct - sqrt(fmax(0, b->cos2t - MARGIN * b->e2 * LSB)),
                                       sqrt(fmax(0, b->cos2t) + MARGIN * b->e2 * LSB) - ct) / LSB;
    double k = q * ci - ct, dk = rd_of(flt, q * ci) + ci * dq + q * dci + ect;
    for (int i = 0; i < 3; i++)
        b->et[i] = rd_of(flt, q * d[i]) + fabs(d[i]) * dq + rd_of(flt, k * n[i]) + fabs(n[i]) * dk +
                   rs_of(flt, q * d[i] + k * n[i]);
    double r = (1 - eta) / (1 + eta), r0 = r * r;
    double dr0 = rd_of(flt, r0) + 2 * fabs(r) * (rd_of(flt, r) + (flt ? 2 * rd_of(flt, 1 + eta) / (1 + eta) : 0));
    double x = 1 - (inside ? ct : ci), dx = (inside ? ect : dci) + rs_of(flt, x);
    /* x^5 by three products: their roundings, and x's error carried
     * through exactly (not to first order: near the critical angle dx is
     * not small) */
    double x2 = x * x, x4 = x2 * x2, x5 = x4 * x;
    double dx5 = rd_of(flt, x5) + x * rd_of(flt, x4) + 2 * x * x2 * rd_of(flt, x2) +
                 (pow(x + dx * LSB, 5) - x5) / LSB;
    double t = (1 - r0) * x5, dt = rd_of(flt, t) + x5 * dr0 + (1 - r0) * dx5;
    /* + 1 - (1 - R) when the reflected ray is cut off (diffk_bounce reads
     * R from the transmitted weight then): exact in Q16.16 */
    b->eR = dr0 + dt + rs_of(flt, r0 + t) + rs_of(flt, 1);
}

static void bounce_run(const dcase_t *c, int which, bres_t *o)
{
    void (*f)(const double *, const double *, double, double *, int *, double *, int *, double *) =
        which == 0 ? diffk_bounce_q16 : which == 1 ? diffk_bounce_float : diffk_bounce_double;
    f(c->ray.d, c->p[0], c->radius, o->refl, &o->tir, o->trans, &o->has_t, &o->R);
}

/* The issue's formulas in double, for the double build. */
static void bounce_formula(const dcase_t *c, bres_t *o)
{
    const double *d = c->ray.d;
    double n[3], eta = c->radius;
    copy3(n, c->p[0]);
    double dn = dot3(d, n);
    bool inside = dn > 0;
    if (inside) {
        scale3(n, -1);
        dn = -dn;
    }
    for (int i = 0; i < 3; i++)
        o->refl[i] = d[i] - 2 * dn * n[i];
    double q = inside ? eta : 1 / eta, ci = -dn, c2 = 1 - q * q * (1 - ci * ci);
    o->tir = c2 < 0;
    o->R = 1;
    o->has_t = 0;
    if (o->tir)
        return;
    double ct = sqrt(c2), r0 = pow((1 - eta) / (1 + eta), 2);
    for (int i = 0; i < 3; i++)
        o->trans[i] = q * d[i] + (q * ci - ct) * n[i];
    o->R = r0 + (1 - r0) * pow(1 - (inside ? ct : ci), 5);
    o->has_t = 1 - o->R >= 1.0 / 512;
}

static void eval_bounce(const dcase_t *c, dres_t *res)
{
    bres_t b[3], f;
    for (int w = 0; w < 3; w++)
        bounce_run(c, w, &b[w]);
    bounce_formula(c, &f);
    const bres_t *dd = &b[2];
    double dn = fabs(dot3(c->ray.d, c->p[0]));
    /* the double build against the formulas (away from the decisions) */
    res->sq = res->sd = DIFFK_HIT;
    res->band_ratio = INFINITY;
    for (int w = 0; w < 2; w++) {
        bbound_t bb;
        bounce_bounds(c, w == 1, &bb);
        const bres_t *x = &b[w];
        double ratio_tir = ratio(bb.cos2t, MARGIN * bb.e2 * LSB) * MARGIN;
        if (w == 0)
            res->band_ratio = ratio_tir;
        double err = 0, bound = 0, base = 0;
        if (c->kind == K_REFLECT) {
            for (int i = 0; i < 3; i++) {
                double e = fabs(x->refl[i] - dd->refl[i]) / LSB;
                err = fmax(err, e);
                base = fmax(base, bb.er[i]);
                if (!(e <= MARGIN * bb.er[i]))
                    res->fail = w ? "float reflected direction beyond its bound" : "q16 reflected direction beyond its bound";
            }
            bound = MARGIN * base;
        } else {
            if (x->tir != dd->tir) {
                if (w == 0)
                    res->disagree = true;
                /* R rounding to 1 at grazing incidence looks like TIR */
                if (!(ratio_tir <= MARGIN) && !(dd->R > 1 - 1e-4 || x->R > 1 - 1e-4))
                    res->fail = w ? "float total internal reflection differs outside the band"
                                  : "q16 total internal reflection differs outside the band";
                if (w == 0)
                    res->band = true;
                continue;
            }
            if (dd->tir)
                continue;
            if (c->kind == K_REFRACT) {
                if (!x->has_t || !dd->has_t)
                    continue; /* cut off (1 - R < 1/512) */
                for (int i = 0; i < 3; i++) {
                    double e = fabs(x->trans[i] - dd->trans[i]) / LSB;
                    err = fmax(err, e);
                    base = fmax(base, bb.et[i]);
                    if (!(e <= MARGIN * bb.et[i] + 1e-9))
                        res->fail = w ? "float transmitted direction beyond its bound"
                                      : "q16 transmitted direction beyond its bound";
                }
                bound = MARGIN * base;
            } else {
                err = fabs(x->R - dd->R) / LSB;
                base = bb.eR;
                bound = MARGIN * base;
                if (!(err <= bound))
                    res->fail = w ? "float Schlick R beyond its bound" : "q16 Schlick R beyond its bound";
            }
        }
        if (w == 0) {
            res->compared = bound > 0;
            res->err = err;
            res->bound = bound;
            res->base = base;
            /* "well conditioned" (the tables' cond <= base): cos2_t >= 0.01,
             * away from the critical angle */
            res->cond = c->kind != K_REFLECT && fabs(bb.cos2t) < 0.01 ? 1e3 * base : 0;
            res->tq = err;
        } else {
            res->err2 = err;
            res->bound2 = bound;
        }
    }
    (void)dn;
    if (res->fail)
        return;
    /* the double build against the formulas written here */
    double e = 0;
    if (c->kind == K_REFLECT)
        e = maxabs3(dd->refl, f.refl);
    else if (dd->tir != f.tir)
        e = res->band_ratio <= MARGIN || f.R > 1 - 1e-4 ? 0 : 1; /* R = 1 reads as TIR */
    else if (!f.tir && c->kind == K_REFRACT && dd->has_t && f.has_t)
        e = maxabs3(dd->trans, f.trans);
    else if (!f.tir && c->kind == K_SCHLICK)
        e = fabs(dd->R - f.R);
    res->rel = e;
    if (!(e <= 1e-9))
        res->fail = "double build differs from the formula";
}

static void diff_eval(const dcase_t *c, dres_t *res)
{
    memset(res, 0, sizeof *res);
    switch (c->kind) {
    case K_PLANE: eval_plane(c, res); break;
    case K_SPHERE: eval_sphere(c, res); break;
    case K_TRIANGLE: eval_triangle(c, res); break;
    case K_BOX: eval_box(c, res); break;
    case K_NORMAL: eval_normal(c, res); break;
    case K_SHADE: eval_shade(c, res); break;
    case K_POW: eval_pow(c, res); break;
    case K_SPOT: eval_spot(c, res); break;
    case K_SHADOW: eval_shadow(c, res); break;
    case K_REFLECT:
    case K_REFRACT:
    case K_SCHLICK: eval_bounce(c, res); break;
    default: eval_camera(c, res); break;
    }
}

static void obj_print(FILE *f, const diffk_obj_t *o, const char *indent)
{
    int np = o->kind == K_TRIANGLE ? 3 : (o->kind == K_SPHERE ? 1 : 2);
    fprintf(f, "%s%s", indent, kind_name[o->kind]);
    for (int i = 0; i < np; i++)
        fprintf(f, " %a %a %a%s", o->p[i][0], o->p[i][1], o->p[i][2], i + 1 < np ? " |" : "");
    if (o->kind == K_SPHERE)
        fprintf(f, " r %a", o->radius);
    fprintf(f, "\n");
}

/* The lighting kinds' inputs, exactly (%a). */
static bool case_print_light(FILE *f, const dcase_t *c, const char *indent)
{
    static const char *const lk[] = {"point", "directional", "spot"};
    switch (c->kind) {
    case K_NORMAL: {
        diffk_obj_t o;
        memset(&o, 0, sizeof o);
        o.kind = c->sub;
        memcpy(o.p, c->p, sizeof o.p);
        o.radius = c->radius;
        obj_print(f, &o, indent);
        break;
    }
    case K_SHADOW:
        for (int j = 0; j < c->sub; j++)
            obj_print(f, &c->obj[j], indent);
        fprintf(f, "%stmax %a%s\n", indent, c->tmax, c->tmax < 0 ? " (NUM_MAX)" : "");
        break;
    case K_POW:
        fprintf(f, "%sx %lld / 2^32 (%.17g), k %u\n", indent, c->xq, c->xq / 4294967296.0, c->k);
        return true;
    case K_SHADE: case K_SPOT: {
        const diffk_shade_t *sh = &c->sh;
        fprintf(f, "%s%s exponent %d color %a %a %a specular %a %a %a ambient %a %a %a\n", indent,
                sh->material == DIFFK_PHONG ? "phong" : "lambert", sh->exponent, sh->color[0], sh->color[1],
                sh->color[2], sh->specular[0], sh->specular[1], sh->specular[2], sh->ambient[0], sh->ambient[1],
                sh->ambient[2]);
        for (int j = 0; j < sh->n_lights; j++) {
            const diffk_light_t *L = &sh->lights[j];
            fprintf(f, "%slight %s position %a %a %a direction %a %a %a angle %a color %a %a %a\n", indent,
                    lk[L->kind], L->pos[0], L->pos[1], L->pos[2], L->dir[0], L->dir[1], L->dir[2], L->angle,
                    L->color[0], L->color[1], L->color[2]);
        }
        fprintf(f, "%sp %a %a %a n %a %a %a d %a %a %a\n", indent, c->sp[0], c->sp[1], c->sp[2], c->sn[0], c->sn[1],
                c->sn[2], c->sdir[0], c->sdir[1], c->sdir[2]);
        return true;
    }
    default: return false;
    }
    fprintf(f, "%sray o %a %a %a d %a %a %a\n", indent, c->ray.o[0], c->ray.o[1], c->ray.o[2], c->ray.d[0],
            c->ray.d[1], c->ray.d[2]);
    return true;
}

static bool result_print_light(FILE *f, const dcase_t *c, const dres_t *r)
{
    switch (c->kind) {
    case K_NORMAL:
        fprintf(f, "  normal err %.3f LSB per component, angle %.3f x 2^-16 rad (bound %.3f = %.2f x (%.3f + %.3g)); "
                   "double vs exact %.3g LSB; band ratio %.3g\n",
                r->err, r->err2, r->bound, MARGIN, r->base, r->cond, r->rel, r->band_ratio);
        break;
    case K_SHADE:
        fprintf(f, "  colour err %.4f/255 (%.1f LSB; bound %.1f = %.2f x (%.1f + %.1f)); double vs formula %.3g/255; "
                   "mask band ratio %.3g%s%s\n",
                r->err / 65536, r->err, r->bound, MARGIN, r->base, r->cond, r->rel, r->band_ratio,
                r->band ? " (discontinuity band: colours not compared)" : "", r->disagree ? "; masks differ" : "");
        break;
    case K_POW:
        fprintf(f, "  q16 err %.4f LSB (cap %.4f); double rel err %.3g\n", r->err, r->bound, r->rel);
        break;
    case K_SPOT:
        fprintf(f, "  q16 %s, double %s; cone margin %.6g (band ratio %.3g, in band iff <= %.2f)\n",
                r->sq == DIFFK_HIT ? "lit" : "unlit", r->sd == DIFFK_HIT ? "lit" : "unlit", r->rel, r->band_ratio,
                MARGIN);
        break;
    case K_SHADOW:
        fprintf(f, "  q16 %s, double %s; band ratio %.3g (in band iff <= %.2f)\n",
                r->sq == DIFFK_HIT ? "blocked" : "clear", r->sd == DIFFK_HIT ? "blocked" : "clear", r->band_ratio,
                MARGIN);
        break;
    default: return false;
    }
    if (r->fail)
        fprintf(f, "  FAIL: %s\n", r->fail);
    return true;
}

/* The case's inputs, exactly (%a), in a form that can be replayed. */
static void case_print(FILE *f, const dcase_t *c, const char *indent)
{
    const char *k = kind_name[c->kind];
    if (c->kind >= K_REFLECT) {
        fprintf(f, "%s%s d %a %a %a n %a %a %a eta %a (%.6g), d.n %.17g\n", indent, k, c->ray.d[0], c->ray.d[1],
                c->ray.d[2], c->p[0][0], c->p[0][1], c->p[0][2], c->radius, c->radius, dot3(c->ray.d, c->p[0]));
        if (diff_verbose) {
            static const char *const nm[3] = {"q16", "float", "double"};
            for (int w = 0; w < 3; w++) {
                bres_t b;
                bounce_run(c, w, &b);
                fprintf(f, "%s  %-6s refl %.9f %.9f %.9f tir %d trans(%d) %.9f %.9f %.9f R %.9f\n", indent, nm[w],
                        b.refl[0], b.refl[1], b.refl[2], b.tir, b.has_t, b.trans[0], b.trans[1], b.trans[2], b.R);
            }
            bbound_t bb;
            bounce_bounds(c, false, &bb);
            fprintf(f, "%s  q16 bounds: refl %.3f %.3f %.3f trans %.3f %.3f %.3f R %.3f; cos2_t %.9g, E2 %.3f LSB\n",
                    indent, bb.er[0], bb.er[1], bb.er[2], bb.et[0], bb.et[1], bb.et[2], bb.eR, bb.cos2t, bb.e2);
        }
        return;
    }
    if (case_print_light(f, c, indent))
        return;
    if (c->kind == K_CAMERA) {
        const diffk_cam_t *m = &c->cam;
        fprintf(f, "%scamera %s %dx%d eye %a %a %a gaze %a %a %a up %a %a %a %s %a\n", indent,
                m->kind == DIFFK_PERSPECTIVE ? "perspective" : "orthographic", m->width, m->height, m->eye[0],
                m->eye[1], m->eye[2], m->gaze[0], m->gaze[1], m->gaze[2], m->up[0], m->up[1], m->up[2],
                m->kind == DIFFK_PERSPECTIVE ? "fov" : "scale", m->kind == DIFFK_PERSPECTIVE ? m->fov_deg : m->scale);
        fprintf(f, "%spixels", indent);
        for (int i = 0; i < CAM_PIXELS; i++)
            fprintf(f, " (%d,%d)", c->px[i], c->py[i]);
        fprintf(f, "\n");
        return;
    }
    fprintf(f, "%s%s", indent, k);
    int np = c->kind == K_TRIANGLE ? 3 : (c->kind == K_SPHERE ? 1 : 2);
    for (int i = 0; i < np; i++)
        fprintf(f, " %a %a %a%s", c->p[i][0], c->p[i][1], c->p[i][2], i + 1 < np ? " |" : "");
    if (c->kind == K_SPHERE)
        fprintf(f, " r %a", c->radius);
    fprintf(f, "\n%sray o %a %a %a d %a %a %a\n", indent, c->ray.o[0], c->ray.o[1], c->ray.o[2], c->ray.d[0],
            c->ray.d[1], c->ray.d[2]);
}

static void result_print(FILE *f, const dcase_t *c, const dres_t *r)
{
    if (result_print_light(f, c, r))
        return;
    if (c->kind >= K_REFLECT) {
        fprintf(f, "  q16 err %.3f LSB (bound %.3f), float err %.3f LSB (bound %.3f), TIR band ratio %.3g%s\n",
                r->err, r->bound, r->err2, r->bound2, r->band_ratio, r->disagree ? " (TIR differs)" : "");
        if (r->fail)
            fprintf(f, "  FAIL: %s\n", r->fail);
        return;
    }
    if (c->kind == K_CAMERA) {
        fprintf(f, "  cam_setup q16 %d, double %d", r->sq, r->sd);
        if (r->compared)
            fprintf(f, "; basis err %.3f LSB (cap %.1f), focal err %.3f LSB (cap %.0f), direction err %.3f LSB "
                       "(cap %.1f), origin err %.3f LSB (bound %.3f = %.1f + %.3f, cap %.0f)",
                    r->err_basis, CAM_BASIS_CAP, r->err_focal, CAM_FOCAL_CAP, r->err, r->bound, r->err2, r->bound2,
                    r->base2, r->cond2, CAM_ORIGIN_CAP);
        else if (r->disagree)
            fprintf(f, "; band ratio %.3g (in band iff <= %.2f)", r->band_ratio, MARGIN);
        fprintf(f, "\n");
    } else {
        fprintf(f, "  q16 %s t=%.17g, double %s t=%.17g; band ratio %.3g (in band iff <= %.2f)",
                r->sq == DIFFK_HIT ? "hit" : "miss", r->sq == DIFFK_HIT ? r->tq : 0.0,
                r->sd == DIFFK_HIT ? "hit" : "miss", r->sd == DIFFK_HIT ? r->td : 0.0, r->band_ratio, MARGIN);
        if (r->compared)
            fprintf(f, "; err %.3f LSB (bound %.3f = %.2f x (%.3f + %.3g))", r->err, r->bound, MARGIN, r->base,
                    r->cond);
        fprintf(f, "\n");
    }
    if (r->fail)
        fprintf(f, "  FAIL: %s\n", r->fail);
}

#ifndef DIFF_NO_MAIN
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

/* Per-kind statistics; plain data, so worker processes can send them
 * through a pipe and the parent merges them. */
typedef struct {
    double worst;     /* the largest value seen */
    long index;       /* its case index + 1 (0: none yet) */
} dmax_t;

typedef struct {
    long cases, rejected, hits_q, compared, disagree, disagree_out, band, far, fails;
    dmax_t err;        /* |dt| (camera: direction), LSB */
    dmax_t err_wc;     /* the same where cond <= base (well conditioned) */
    dmax_t rel;        /* |dt| / max(t, 1) where cond <= base */
    dmax_t ratio;      /* err / stated bound */
    dmax_t theory;     /* err / (base + cond): the analysis' own ratio */
    dmax_t base_only;  /* err where cond < base / 100 */
    dmax_t cond_use;   /* (err - base) / cond where cond > 10 base */
    dmax_t band_use;   /* band_ratio of cases where the builds differ */
    dmax_t err2, err2_wc, ratio2; /* camera origins */
    dmax_t basis, focal;          /* camera basis component, focal (LSB) */
    dmax_t kerr[12], kratio[12]; /* shade, pow: worst err and err/bound per exponent bucket
                                  * (0: lambert; j: k in [2^(j-1), 2^j)) */
    uint64_t kseen[16];          /* pow: the exponents seen */
    dmax_t oracle;               /* shade: the double build against the formula (1/255 units) */
    dcase_t worst_c;   /* the case of the worst ratio */
    dres_t worst_r;
    dcase_t worst_err_c; /* the case of the worst err */
    dres_t worst_err_r;
} dstat_t;

static bool dmax(dmax_t *m, double v, long i)
{
    if (v == v && (m->index == 0 || v > m->worst)) {
        m->worst = v;
        m->index = i + 1;
        return true;
    }
    return false;
}

static void stat_add(dstat_t *s, long i, const dcase_t *c, const dres_t *r)
{
    s->cases++;
    if (r->rejected)
        s->rejected++;
    if (r->sq == DIFFK_HIT || (c->kind == K_CAMERA && r->sq == 0))
        s->hits_q++;
    if (r->band)
        s->band++;
    if (r->disagree) {
        s->disagree++;
        if (!r->band)
            s->disagree_out++;
        dmax(&s->band_use, r->band_ratio, i);
    }
    if (r->far)
        s->far++;
    if (r->fail)
        s->fails++;
    if (c->kind == K_SHADE && !r->rejected)
        dmax(&s->oracle, r->rel, i);
    if (c->kind == K_POW)
        s->kseen[(c->k - 1) / 64 % 16] |= 1ull << ((c->k - 1) % 64);
    if (r->compared && (c->kind == K_SHADE || c->kind == K_POW)) {
        unsigned k = c->kind == K_POW ? c->k : (unsigned)c->sh.exponent;
        int b = 1;
        while (b < 11 && (1u << b) <= k)
            b++;
        if (c->kind == K_SHADE && c->sh.material != DIFFK_PHONG)
            b = 0;
        dmax(&s->kerr[b], r->err, i);
        /* shade: the tightness of the k term, where it dominates */
        if (c->kind == K_POW || b == 0 || r->cond > 10 * r->base)
            dmax(&s->kratio[b], c->kind == K_POW || b == 0 ? r->err / r->bound : (r->err - r->base) / r->cond, i);
    }
    if (!r->compared)
        return;
    s->compared++;
    double ratio_v = r->err / r->bound;
    if (dmax(&s->err, r->err, i)) {
        s->worst_err_c = *c;
        s->worst_err_r = *r;
    }
    if (r->cond <= r->base) {
        dmax(&s->err_wc, r->err, i);
        dmax(&s->rel, r->rel, i);
    }
    dmax(&s->theory, r->err / (r->base + r->cond), i);
    if (r->cond < r->base / 100)
        dmax(&s->base_only, r->err, i);
    if (r->cond > 10 * r->base)
        dmax(&s->cond_use, (r->err - r->base) / r->cond, i);
    if (c->kind >= K_REFLECT) {
        dmax(&s->err2, r->err2, i);
        if (r->bound2 > 0)
            dmax(&s->ratio2, r->err2 / r->bound2, i);
    }
    if (c->kind == K_CAMERA) {
        dmax(&s->basis, r->err_basis, i);
        dmax(&s->focal, r->err_focal, i);
        dmax(&s->err2, r->err2, i);
        if (r->cond2 <= r->base2)
            dmax(&s->err2_wc, r->err2, i);
        double r2 = r->bound2 > 0 ? r->err2 / r->bound2 : 0;
        dmax(&s->ratio2, r2, i);
        ratio_v = fmax(ratio_v, r2);
    }
    if (dmax(&s->ratio, ratio_v, i)) {
        s->worst_c = *c;
        s->worst_r = *r;
    }
}

static void dmax_merge(dmax_t *a, const dmax_t *b)
{
    if (b->index)
        dmax(a, b->worst, b->index - 1);
}

static void stat_merge(dstat_t *a, const dstat_t *b)
{
    a->cases += b->cases;
    a->rejected += b->rejected;
    a->hits_q += b->hits_q;
    a->compared += b->compared;
    a->disagree += b->disagree;
    a->disagree_out += b->disagree_out;
    a->band += b->band;
    a->far += b->far;
    a->fails += b->fails;
    if (b->err.index && (!a->err.index || b->err.worst > a->err.worst)) {
        a->worst_err_c = b->worst_err_c;
        a->worst_err_r = b->worst_err_r;
    }
    if (b->ratio.index && (!a->ratio.index || b->ratio.worst > a->ratio.worst)) {
        a->worst_c = b->worst_c;
        a->worst_r = b->worst_r;
    }
    dmax_merge(&a->err, &b->err);
    dmax_merge(&a->err_wc, &b->err_wc);
    dmax_merge(&a->rel, &b->rel);
    dmax_merge(&a->ratio, &b->ratio);
    dmax_merge(&a->theory, &b->theory);
    dmax_merge(&a->base_only, &b->base_only);
    dmax_merge(&a->cond_use, &b->cond_use);
    dmax_merge(&a->band_use, &b->band_use);
    dmax_merge(&a->err2, &b->err2);
    dmax_merge(&a->err2_wc, &b->err2_wc);
    dmax_merge(&a->ratio2, &b->ratio2);
    dmax_merge(&a->basis, &b->basis);
    dmax_merge(&a->focal, &b->focal);
    dmax_merge(&a->oracle, &b->oracle);
    for (int j = 0; j < 12; j++) {
        dmax_merge(&a->kerr[j], &b->kerr[j]);
        dmax_merge(&a->kratio[j], &b->kratio[j]);
    }
    for (int j = 0; j < 16; j++)
        a->kseen[j] |= b->kseen[j];
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

static long n_cases = 1000000;
static int n_jobs = 1;
static bool progress;
static int only_kind = -1;

/* Run indices job, job + jobs, ... of every kind into st[]. */
static void run_worker(int job, dstat_t st[K_COUNT])
{
    double t0 = now_s(), last = t0;
    long total = n_cases * K_COUNT, done = 0;
    for (int k = 0; k < K_COUNT; k++) {
        if (only_kind >= 0 && k != only_kind)
            continue;
        for (long i = job; i < n_cases; i += n_jobs) {
            dcase_t c;
            dres_t r;
            gen_case(k, i, &c);
            diff_eval(&c, &r);
            stat_add(&st[k], i, &c, &r);
            CHECK_SWEEP(r.fail == NULL, "%s case %ld: %s; replay: test_diff --replay %s:%ld --seed %#llx", kind_name[k], i,
                        r.fail, kind_name[k], i, (unsigned long long)diff_seed);
            if (progress && job == 0 && (++done & 0xffff) == 0) {
                double t = now_s();
                if (t - last >= 5.0) {
                    last = t;
                    long all = done * n_jobs;
                    fprintf(stderr, "test_diff: %5.1f%% (%s, %ld of %ld cases), %.0f s elapsed, ~%.0f s left\n",
                            100.0 * all / total, kind_name[k], all, total, t - t0,
                            (t - t0) * ((double)total / all - 1));
                }
            }
        }
    }
}

static int replay(const char *spec)
{
    char name[32];
    long idx;
    if (sscanf(spec, "%31[a-z]:%ld", name, &idx) != 2) {
        fprintf(stderr, "test_diff: --replay KIND:INDEX\n");
        return 2;
    }
    for (int k = 0; k < K_COUNT; k++) {
        if (strcmp(name, kind_name[k]) != 0)
            continue;
        dcase_t c;
        dres_t r;
        gen_case(k, idx, &c);
        diff_verbose = true;
        diff_eval(&c, &r);
        printf("%s case %ld (mode %d, seed %#llx):\n", kind_name[k], idx, c.mode, (unsigned long long)diff_seed);
        case_print(stdout, &c, "  ");
        result_print(stdout, &c, &r);
        return r.fail ? 1 : 0;
    }
    fprintf(stderr, "test_diff: unknown kind '%s'\n", name);
    return 2;
}

/* Shading, power, spot and shadow summaries (docs/ACCURACY.md, "Shading error"). */
static void print_light_tables(dstat_t st[K_COUNT])
{
    const dstat_t *sh = &st[K_SHADE], *pw = &st[K_POW], *sp = &st[K_SPOT], *sd = &st[K_SHADOW], *nm = &st[K_NORMAL];
    if (nm->cases)
        printf("\nnormals (geom_*_surface), per component in LSB: worst %.3f where compared outside the band "
               "(worst err/bound %.3f), %ld box faces or sphere sides differ, all in the band\n",
               nm->err.worst, nm->ratio.worst, nm->disagree);
    if (sh->cases) {
        printf("\nshading (shade_point), colour channels in 1/255 units; cap per light = %.2f x (%.5f + %.6f k) "
               "(+ %.2f x 0.5 LSB ambient); double build against the formula: worst %.3g\n\n",
               MARGIN, SHADE_A, SHADE_B, MARGIN, sh->oracle.worst);
        printf("| material, exponent k | worst err (1/255) | cap for one light at the largest k | lambert: worst err/bound; "
               "phong: worst (err - A)/B where B > 10 A |\n");
        printf("|---|---:|---:|---:|\n");
        for (int b = 0; b < 12; b++) {
            if (!sh->kerr[b].index)
                continue;
            int kmax = b == 0 ? 0 : (b == 11 ? 1024 : (1 << b) - 1);
            if (b == 0)
                printf("| lambert | %.5f | %.5f | %.3f |\n", sh->kerr[b].worst / 65536, MARGIN * (255 * NL_ERR + 1.5) / 65536,
                       sh->kratio[b].worst);
            else
                printf("| phong, k %d..%d | %.5f | %.4f | %.3f |\n", b == 11 ? 1024 : 1 << (b - 1), kmax,
                       sh->kerr[b].worst / 65536, MARGIN * (SHADE_A + SHADE_B * kmax), sh->kratio[b].worst);
        }
        printf("\n%ld cases compared, %ld in a band (a spot edge, or n . l within NL_ERR: for phong the colour is "
               "not compared there), %ld with different light masks (all in the band)\n",
               sh->compared, sh->band, sh->disagree);
    }
    if (pw->cases) {
        int seen = 0;
        for (int j = 0; j < 16; j++)
            seen += __builtin_popcountll(pw->kseen[j]);
        printf("\nPhong power numw_pow_int against powl, LSB (%d of the 1024 exponents seen); cap 0.5 + 3 k 2^-16\n\n",
               seen);
        printf("| k | worst err | cap at the largest k | worst err/cap |\n|---|---:|---:|---:|\n");
        for (int b = 1; b < 12; b++)
            if (pw->kerr[b].index) {
                int kmax = b == 11 ? 1024 : (1 << b) - 1;
                printf("| %d..%d | %.4f | %.4f | %.3f |\n", b == 11 ? 1024 : 1 << (b - 1), kmax, pw->kerr[b].worst,
                       POW_CAP_K(kmax), pw->kratio[b].worst);
            }
        printf("\ndouble build against powl: worst relative error %.3g\n", pw->rel.worst);
    }
    if (sp->cases)
        printf("\nspot cone: %ld cases, %ld lit in Q16.16, %ld within the threshold |m| <= %.1f x (|v|_1 2^-29 + |v| "
               "(2^-30 + 1e-8 + 2^-24 cos) + 0.5 LSB cos), %ld decisions differ, %ld outside it; largest |m|/threshold where they "
               "differ: %.3f\n",
               sp->cases, sp->hits_q, sp->band, MARGIN, sp->disagree, sp->disagree_out, sp->band_use.worst);
    if (sd->cases)
        printf("\nshadow rays: %ld cases, %ld blocked in Q16.16, %ld ambiguous (an occluder's hit/miss in its "
               "kernel's band or its t within the kernel's bound of tmax), %ld decisions differ, %ld outside the band; "
               "%ld with a hit beyond the Q16.16 range and tmax = NUM_MAX (known difference, counted in the band)\n",
               sd->cases, sd->hits_q, sd->band, sd->disagree, sd->disagree_out, sd->far);
}

static void print_table(dstat_t st[K_COUNT], double secs)
{
    const dstat_t *camera_caps = NULL;
    printf("\ndifferential test, Q16.16 against double: %ld cases per kind, seed %#llx, %d job%s, %.1f s\n", n_cases,
           (unsigned long long)diff_seed, n_jobs, n_jobs == 1 ? "" : "s", secs);
    printf("errors in LSB (2^-16); \"cond <= base\": cases whose conditioning term is at most the base term\n\n");
    printf("| kind | cases | q16 hits | in band | hit/miss differ | outside band | far hits | worst err, cond <= base "
           "| worst err | worst rel err, cond <= base | worst err/bound |\n");
    printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (int k = 0; k < K_COUNT; k++) {
        dstat_t *s = &st[k];
        if (!s->cases)
            continue;
        if (k == K_CAMERA) {
            printf("| camera, %d rays each | %ld | %ld accepted | %ld | %ld accept/reject | %ld | - | direction %.3f | "
                   "direction %.3f | - | %.3f |\n",
                   CAM_PIXELS, s->cases, s->hits_q, s->band, s->disagree, s->disagree_out, s->err_wc.worst,
                   s->err.worst, s->ratio.worst);
            printf("| | | | | | | | origin %.3f | origin %.3f | | |\n", s->err2_wc.worst, s->err2.worst);
            camera_caps = s;
        } else {
            printf("| %s | %ld | %ld | %ld | %ld | %ld | %ld | %.3f | %.4g | %.3g | %.3f |\n", kind_name[k], s->cases,
                   s->hits_q, s->band, s->disagree, s->disagree_out, s->far, s->err_wc.worst, s->err.worst,
                   s->rel.worst, s->ratio.worst);
        }
    }
    if (camera_caps) {
        const dstat_t *s = camera_caps;
        printf("\ncamera caps (LSB, per component; both builds from the same rounded inputs):\n\n");
        printf("| quantity | cap | worst measured |\n|---|---:|---:|\n");
        printf("| basis u, v, w | %.1f | %.3f |\n", CAM_BASIS_CAP, s->basis.worst);
        printf("| ray direction (perspective; orthographic: basis cap) | %.1f | %.3f |\n", CAM_DIR_CAP, s->err.worst);
        printf("| orthographic origin | %.0f (%.1f + %.4f per unit of offset) | %.3f |\n", CAM_ORIGIN_CAP,
               CAM_ORIGIN_BASE, CAM_ORIGIN_PER_UNIT, s->err2.worst);
        printf("| focal H cot(fov/2) | %.0f (1 + %.3g F) | %.3f |\n", CAM_FOCAL_CAP, CAM_FOCAL_REL * 65536,
               s->focal.worst);
    }
    print_light_tables(st);
    if (st[K_REFLECT].cases + st[K_REFRACT].cases + st[K_SCHLICK].cases) {
        printf("\nsecondary rays (core/light/trace.c trace_children), Q16.16 and float against double from the same "
               "rounded d, n, eta (0.01..100); bound = %.2f x the first-order analysis (eval_bounce):\n\n", MARGIN);
        printf("| quantity | cases | compared | TIR decisions differ (all in the band) | q16 worst err (LSB) | q16 worst "
               "err, cos2_t >= 0.01 | q16 worst err/bound | float worst err (LSB) | float worst err/bound |\n"
               "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
        for (int k = K_REFLECT; k <= K_SCHLICK; k++) {
            const dstat_t *b = &st[k];
            if (b->cases)
                printf("| %s | %ld | %ld | %ld | %.4g | %.4g | %.3f | %.4g | %.3f |\n",
                       k == K_REFLECT ? "reflected direction" : k == K_REFRACT ? "transmitted direction" : "Schlick R",
                       b->cases, b->compared, b->disagree, b->err.worst, b->err_wc.worst, b->ratio.worst,
                       b->err2.worst, b->ratio2.worst);
        }
    }
    printf("\ntightness of the analysis (bound = %.2f x (base + cond); band = %.2f x the rounding's reach):\n\n", MARGIN,
           MARGIN);
    printf("| kind | max err/(base+cond) (case) | max err where cond < base/100 | max (err-base)/cond where cond > 10 "
           "base | max band ratio where the builds differ |\n");
    printf("|---|---:|---:|---:|---:|\n");
    for (int k = 0; k < K_COUNT; k++) {
        dstat_t *s = &st[k];
        if (!s->cases)
            continue;
        printf("| %s | %.3f (%ld) | %.3f (%ld) | %.3f (%ld) | %.3f (%ld) |\n", kind_name[k], s->theory.worst,
               s->theory.index - 1, s->base_only.worst, s->base_only.index - 1, s->cond_use.worst,
               s->cond_use.index - 1, s->band_use.worst, s->band_use.index - 1);
    }
    printf("\nworst cases (replay: test_diff --replay KIND:INDEX --seed %#llx):\n", (unsigned long long)diff_seed);
    for (int k = 0; k < K_COUNT; k++) {
        dstat_t *s = &st[k];
        if (!s->ratio.index)
            continue;
        printf("%s:%ld, worst err/bound (generator mode %d):\n", kind_name[k], s->ratio.index - 1, s->worst_c.mode);
        case_print(stdout, &s->worst_c, "  ");
        result_print(stdout, &s->worst_c, &s->worst_r);
        if (s->err.index != s->ratio.index) {
            printf("%s:%ld, worst err (generator mode %d):\n", kind_name[k], s->err.index - 1, s->worst_err_c.mode);
            case_print(stdout, &s->worst_err_c, "  ");
            result_print(stdout, &s->worst_err_c, &s->worst_err_r);
        }
    }
}

/* The generator reached what each kind is about (10^4 cases or more). */
static bool coverage_ok(int k, const dstat_t *s)
{
    switch (k) {
    case K_NORMAL: return s->compared > s->cases / 2 && s->band > 0;
    case K_SHADE: return s->compared > s->cases / 4 && s->band > 0 && s->disagree > 0;
    case K_POW: {
        int seen = 0;
        for (int j = 0; j < 16; j++)
            seen += __builtin_popcountll(s->kseen[j]);
        return s->compared == s->cases && (s->cases < 100000 || seen == 1024);
    }
    case K_SPOT: return s->band > 0 && s->disagree > 0 && s->hits_q > s->cases / 10 && s->hits_q < s->cases * 9 / 10;
    case K_SHADOW: return s->band > 0 && s->hits_q > s->cases / 10 && s->hits_q < s->cases * 9 / 10;
    case K_REFLECT: return s->compared == s->cases;
    case K_REFRACT:
    case K_SCHLICK: return s->compared > s->cases / 4 && s->disagree > 0;
    default:
        return s->compared > s->cases / 10 && s->band > 0 && (k != K_PLANE || s->far > 0);
    }
}

int main(int argc, char **argv)
{
    const char *replay_spec = NULL;
    if (getenv("DIFF_CASES"))
        n_cases = atol(getenv("DIFF_CASES"));
    if (getenv("DIFF_JOBS"))
        n_jobs = atoi(getenv("DIFF_JOBS"));
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--seed") == 0 && i + 1 < argc)
            diff_seed = strtoull(argv[++i], NULL, 0);
        else if (strcmp(argv[i], "--jobs") == 0 && i + 1 < argc)
            n_jobs = atoi(argv[++i]);
        else if (strcmp(argv[i], "--progress") == 0)
            progress = true;
        else if (strcmp(argv[i], "--replay") == 0 && i + 1 < argc)
            replay_spec = argv[++i];
        else if (strcmp(argv[i], "--only") == 0 && i + 1 < argc) {
            const char *name = argv[++i];
            for (int k = 0; k < K_COUNT; k++)
                if (strcmp(name, kind_name[k]) == 0)
                    only_kind = k;
            if (only_kind < 0) {
                fprintf(stderr, "test_diff: unknown kind '%s'\n", name);
                return 2;
            }
        } else if (argv[i][0] >= '0' && argv[i][0] <= '9')
            n_cases = strtol(argv[i], NULL, 10);
        else {
            fprintf(stderr, "usage: test_diff [CASES] [--seed N] [--jobs N] [--progress] [--only KIND]\n"
                            "       test_diff --replay KIND:INDEX [--seed N]\n");
            return 2;
        }
    }
    if (replay_spec)
        return replay(replay_spec);
    if (n_jobs < 1)
        n_jobs = 1;
    if (n_cases < 1)
        n_cases = 1;

    static dstat_t st[K_COUNT];
    double t0 = now_s();
    if (n_jobs == 1) {
        run_worker(0, st);
    } else {
        /* One process per job; each sends its statistics back through a pipe. */
        int fds[64][2];
        pid_t pids[64];
        if (n_jobs > 64)
            n_jobs = 64;
        fflush(NULL);
        for (int j = 0; j < n_jobs; j++) {
            if (pipe(fds[j]) != 0 || (pids[j] = fork()) < 0) {
                perror("test_diff: pipe/fork");
                return 2;
            }
            if (pids[j] == 0) {
                static dstat_t mine[K_COUNT];
                close(fds[j][0]);
                run_worker(j, mine);
                const char *p = (const char *)mine;
                size_t left = sizeof mine;
                while (left > 0) {
                    ssize_t w = write(fds[j][1], p, left);
                    if (w <= 0)
                        _exit(3);
                    p += w;
                    left -= (size_t)w;
                }
                _exit(0);
            }
            close(fds[j][1]);
        }
        for (int j = 0; j < n_jobs; j++) {
            static dstat_t part[K_COUNT];
            char *p = (char *)part;
            size_t left = sizeof part;
            while (left > 0) {
                ssize_t r = read(fds[j][0], p, left);
                if (r <= 0)
                    break;
                p += r;
                left -= (size_t)r;
            }
            close(fds[j][0]);
            int status = 0;
            waitpid(pids[j], &status, 0);
            if (left > 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
                fprintf(stderr, "test_diff: job %d failed\n", j);
                check_failed_count++;
                continue;
            }
            for (int k = 0; k < K_COUNT; k++) {
                stat_merge(&st[k], &part[k]);
                check_failed_count += part[k].fails;
            }
        }
    }
    double secs = now_s() - t0;
    print_table(st, secs);
    for (int k = 0; k < K_COUNT; k++) {
        dstat_t *s = &st[k];
        if (only_kind >= 0 && k != only_kind)
            continue;
        /* One check per kind: no case failed, and (for 10^4 cases or more)
         * the generator reached hits, the band and, for planes, far hits. */
        bool covered = s->cases == n_cases && (n_cases < 10000 || coverage_ok(k, s));
        CHECK_MSG(s->fails == 0 && covered, "%s: %ld of %ld cases failed (%ld hit/miss outside the band); coverage %s",
                  kind_name[k], s->fails, s->cases, s->disagree_out, covered ? "ok" : "too low");
    }
    return check_report("test_diff");
}
#endif
