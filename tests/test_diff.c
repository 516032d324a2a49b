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

enum { K_PLANE, K_SPHERE, K_TRIANGLE, K_BOX, K_CAMERA, K_COUNT };
static const char *const kind_name[K_COUNT] = {"plane", "sphere", "triangle", "box", "camera"};

#define CAM_PIXELS 5

typedef struct {
    int kind;
    int mode;       /* which generator branch (for the record) */
    double p[3][3]; /* plane: point, normal; sphere: center; triangle: a, b, c; box: min, max */
    double radius;  /* sphere */
    diffk_ray_t ray;
    diffk_cam_t cam;
    int px[CAM_PIXELS], py[CAM_PIXELS];
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

static void gen_case_rng(int kind, rng_t *r, dcase_t *c)
{
    memset(c, 0, sizeof *c);
    c->kind = kind;
    switch (kind) {
    case K_PLANE: gen_plane(r, c); break;
    case K_SPHERE: gen_sphere(r, c); break;
    case K_TRIANGLE: gen_triangle(r, c); break;
    case K_BOX: gen_box(r, c); break;
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

static void diff_eval(const dcase_t *c, dres_t *res)
{
    memset(res, 0, sizeof *res);
    switch (c->kind) {
    case K_PLANE: eval_plane(c, res); break;
    case K_SPHERE: eval_sphere(c, res); break;
    case K_TRIANGLE: eval_triangle(c, res); break;
    case K_BOX: eval_box(c, res); break;
    default: eval_camera(c, res); break;
    }
}

/* The case's inputs, exactly (%a), in a form that can be replayed. */
static void case_print(FILE *f, const dcase_t *c, const char *indent)
{
    const char *k = kind_name[c->kind];
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
        bool covered = s->cases == n_cases && (n_cases < 10000 || (s->compared > s->cases / 10 && s->band > 0 &&
                                                                   (k != K_PLANE || s->far > 0)));
        CHECK_MSG(s->fails == 0 && covered, "%s: %ld of %ld cases failed (%ld hit/miss outside the band); coverage %s",
                  kind_name[k], s->fails, s->cases, s->disagree_out, covered ? "ok" : "too low");
    }
    return check_report("test_diff");
}
#endif
