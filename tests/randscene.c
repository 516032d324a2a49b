/* randscene: random scene text for the oracle. Every parameter is drawn
 * from its whole accepted range (docs/ACCURACY.md, "The input domain"),
 * with extra weight where renderers break: large coordinates up to the
 * domain limit, radii down to a few Q16.16 steps, flat and point boxes,
 * slivers, grazing planes, the eye inside spheres and boxes, objects behind
 * the camera, both camera kinds, fov from the narrow limit to 179.99
 * degrees. Images are small (the oracle renders thousands of them).
 *
 * Numbers are written with %.8g (some in exponent notation, which the
 * parser accepts) and read back, so every check below is made on the
 * value the parser will see. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../core/fxrt_config.h"
#include "randscene.h"

#define RS_LIM ((double)FXRT_COORD_LIMIT)
#define RS_EPS (1.0 / 65536.0)
#define RS_PI 3.14159265358979323846

typedef struct {
    uint64_t s;
    char *buf;
    size_t len, n;
} rs_t;

typedef struct {
    double x, y, z;
} rs_vec_t;

static uint64_t rs_next(rs_t *r)
{
    /* xorshift64*, as tests/check.h */
    r->s ^= r->s >> 12;
    r->s ^= r->s << 25;
    r->s ^= r->s >> 27;
    return r->s * 2685821657736338717ull;
}

/* Uniform in [0, 1). */
static double rs_unit(rs_t *r)
{
    return (double)(rs_next(r) >> 11) * (1.0 / 9007199254740992.0);
}

static double rs_uniform(rs_t *r, double lo, double hi)
{
    return lo + (hi - lo) * rs_unit(r);
}

static int rs_int(rs_t *r, int lo, int hi)
{
    return lo + (int)(rs_next(r) % (uint64_t)(hi - lo + 1));
}

/* Log-uniform in [lo, hi], lo > 0. */
static double rs_log(rs_t *r, double lo, double hi)
{
    return exp(rs_uniform(r, log(lo), log(hi)));
}

static int rs_chance(rs_t *r, double p)
{
    return rs_unit(r) < p;
}

static void rs_out(rs_t *r, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int k = vsnprintf(r->buf + r->n, r->len - r->n, fmt, ap);
    va_end(ap);
    if (k > 0)
        r->n += (size_t)k < r->len - r->n ? (size_t)k : r->len - r->n - 1;
}

/* The value the parser will read for x written with %.8g, kept inside
 * [-lim, lim] and away from the magnitudes below 2^-16 that it rejects. */
static double rs_num(double x, double lim)
{
    char b[64];
    if (x > lim)
        x = lim;
    if (x < -lim)
        x = -lim;
    if (x != 0 && fabs(x) < RS_EPS)
        x = x < 0 ? -RS_EPS : RS_EPS;
    snprintf(b, sizeof b, "%.8g", x);
    x = strtod(b, NULL);
    if (x > lim || x < -lim || (x != 0 && fabs(x) < RS_EPS)) {
        /* %.8g rounded across a limit: step back inside by one digit. */
        x = x > 0 ? (x > lim ? lim * 0.9999999 : RS_EPS * 1.0000001) : (x < -lim ? -lim * 0.9999999 : -RS_EPS * 1.0000001);
        snprintf(b, sizeof b, "%.8g", x);
        x = strtod(b, NULL);
    }
    return x == 0 ? 0 : x;
}

static rs_vec_t rs_vnum(rs_vec_t v, double lim)
{
    rs_vec_t o = {rs_num(v.x, lim), rs_num(v.y, lim), rs_num(v.z, lim)};
    return o;
}

static void rs_put(rs_t *r, const char *key, rs_vec_t v)
{
    rs_out(r, " %s %.8g %.8g %.8g", key, v.x, v.y, v.z);
}

static rs_vec_t rs_add(rs_vec_t a, rs_vec_t b)
{
    rs_vec_t o = {a.x + b.x, a.y + b.y, a.z + b.z};
    return o;
}

static rs_vec_t rs_scale(rs_vec_t a, double s)
{
    rs_vec_t o = {a.x * s, a.y * s, a.z * s};
    return o;
}

static double rs_dot(rs_vec_t a, rs_vec_t b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

static rs_vec_t rs_cross(rs_vec_t a, rs_vec_t b)
{
    rs_vec_t o = {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
    return o;
}

static double rs_len(rs_vec_t a)
{
    return sqrt(rs_dot(a, a));
}

/* Three draws, in order (C leaves the order of the arguments of one call
 * open, so no expression here makes two draws). */
static rs_vec_t rs_box3(rs_t *r, double lo, double hi)
{
    rs_vec_t o;
    o.x = rs_uniform(r, lo, hi);
    o.y = rs_uniform(r, lo, hi);
    o.z = rs_uniform(r, lo, hi);
    return o;
}

static rs_vec_t rs_log3(rs_t *r, double lo, double hi)
{
    rs_vec_t o;
    o.x = rs_log(r, lo, hi);
    o.y = rs_log(r, lo, hi);
    o.z = rs_log(r, lo, hi);
    return o;
}

/* A random unit vector (uniform on the sphere). */
static rs_vec_t rs_sphere(rs_t *r)
{
    double z = rs_uniform(r, -1, 1), a = rs_uniform(r, 0, 2 * RS_PI), s = sqrt(1 - z * z);
    rs_vec_t o = {s * cos(a), s * sin(a), z};
    return o;
}

/* A direction as a file would state it: often axis-aligned or with some
 * zero components, any length the parser accepts (from 0.25, below which
 * rounding the components to Q16.16 may turn it by more than the 4 LSB
 * cam_setup and the parser allow, to 8192), and sometimes with tiny
 * components next to large ones. */
static rs_vec_t rs_direction(rs_t *r)
{
    rs_vec_t d;
    for (;;) {
        int mode = rs_int(r, 0, 9);
        if (mode == 0) {
            int axis = rs_int(r, 0, 2);
            double s = rs_chance(r, 0.5) ? 1 : -1;
            d.x = axis == 0 ? s : 0;
            d.y = axis == 1 ? s : 0;
            d.z = axis == 2 ? s : 0;
        } else {
            d = rs_sphere(r);
            if (mode == 1)
                d.x = 0;
            else if (mode == 2)
                d.y *= rs_log(r, 1e-5, 1e-2);
        }
        d = rs_vnum(rs_scale(d, rs_log(r, 0.25, RS_LIM)), RS_LIM);
        if (rs_len(d) > 0)
            return d;
    }
}

/* A colour component: the whole 0..1 range with up to 4 decimals, with
 * the ends 0 and 1 now and then. */
static double rs_color_value(rs_t *r)
{
    int k = rs_int(r, 0, 10000);
    if (rs_chance(r, 0.1))
        k = rs_chance(r, 0.5) ? 0 : 10000;
    return k / 10000.0;
}

static void rs_color(rs_t *r, const char *key)
{
    double c[3];
    for (int i = 0; i < 3; i++)
        c[i] = rs_color_value(r);
    rs_out(r, " %s %.4f %.4f %.4f", key, c[0], c[1], c[2]);
}

/* A point at distance ~dist from the eye around the view direction (in
 * front, beside, or behind the camera), or anywhere in the domain. */
static rs_vec_t rs_anchor(rs_t *r, rs_vec_t eye, rs_vec_t fwd, double spread, double dist)
{
    if (rs_chance(r, 0.08)) {
        return rs_box3(r, -RS_LIM, RS_LIM);
    }
    double along = rs_chance(r, 0.15) ? -rs_uniform(r, 0, 1.5) : rs_uniform(r, 0, 1.5);
    rs_vec_t side = rs_sphere(r);
    side = rs_scale(side, rs_uniform(r, 0, spread));
    return rs_add(eye, rs_scale(rs_add(rs_scale(fwd, along), side), dist));
}

static void rs_sphere_obj(rs_t *r, rs_vec_t eye, rs_vec_t fwd, double spread, double dist)
{
    rs_vec_t c;
    double rad;
    if (rs_chance(r, 0.1)) { /* around the eye */
        rs_vec_t off = rs_sphere(r);
        off = rs_scale(off, rs_log(r, 1e-3, 100));
        c = rs_vnum(rs_add(eye, off), RS_LIM);
        rad = rs_num(rs_len(rs_add(c, rs_scale(eye, -1))) * rs_uniform(r, 1.01, 3) + 1e-3, FXRT_RADIUS_LIMIT);
    } else {
        c = rs_vnum(rs_anchor(r, eye, fwd, spread, dist), RS_LIM);
        rad = rs_chance(r, 0.1) ? rs_log(r, 4 * RS_EPS, 0.01) : rs_log(r, 0.01, FXRT_RADIUS_LIMIT);
        if (rs_chance(r, 0.6))
            rad = dist * rs_log(r, 1e-3, 0.5); /* a size that shows */
        rad = rs_num(rad < 4 * RS_EPS ? 4 * RS_EPS : rad, FXRT_RADIUS_LIMIT);
    }
    if (rad <= 0)
        rad = 4 * RS_EPS;
    rs_out(r, "sphere");
    rs_put(r, "center", c);
    rs_out(r, " radius %.8g", rad);
}

static void rs_box_obj(rs_t *r, rs_vec_t eye, rs_vec_t fwd, double spread, double dist)
{
    rs_vec_t c, h;
    int around = rs_chance(r, 0.1);
    if (around) {
        c = rs_sphere(r);
        c = rs_add(eye, rs_scale(c, rs_log(r, 1e-3, 10)));
    } else {
        c = rs_anchor(r, eye, fwd, spread, dist);
    }
    double size = around ? rs_log(r, 1e-2, 200) : dist * rs_log(r, 1e-3, 0.5);
    if (rs_chance(r, 0.1))
        size = rs_log(r, 1e-3, 2 * RS_LIM);
    h.x = size * rs_log(r, 0.1, 1);
    h.y = size * rs_log(r, 0.1, 1);
    h.z = size * rs_log(r, 0.1, 1);
    if (rs_chance(r, 0.1))
        h.y = 0; /* flat */
    if (rs_chance(r, 0.03))
        h.x = h.z = 0; /* a segment, or a point with h.y = 0 */
    rs_vec_t lo = rs_vnum(rs_add(c, rs_scale(h, -1)), RS_LIM), hi = rs_vnum(rs_add(c, h), RS_LIM);
    if (around) {
        /* The eye inside: each face 1e-3..1 box sizes away from it, and
         * now and then one face exactly through the eye (on the boundary). */
        rs_vec_t a = rs_scale(rs_log3(r, 1e-3, 1), size);
        rs_vec_t b = rs_scale(rs_log3(r, 1e-3, 1), size);
        if (rs_chance(r, 0.2))
            a.x = 0;
        lo = rs_vnum(rs_add(eye, rs_scale(a, -1)), RS_LIM);
        hi = rs_vnum(rs_add(eye, b), RS_LIM);
    }
    rs_vec_t mn = {fmin(lo.x, hi.x), fmin(lo.y, hi.y), fmin(lo.z, hi.z)};
    rs_vec_t mx = {fmax(lo.x, hi.x), fmax(lo.y, hi.y), fmax(lo.z, hi.z)};
    rs_out(r, "box");
    rs_put(r, "min", mn);
    rs_put(r, "max", mx);
}

static void rs_triangle_obj(rs_t *r, rs_vec_t eye, rs_vec_t fwd, double spread, double dist)
{
    rs_vec_t c = rs_anchor(r, eye, fwd, spread, dist);
    double size = rs_chance(r, 0.1) ? rs_log(r, 1e-2, 2 * RS_LIM) : dist * rs_log(r, 1e-3, 1);
    rs_vec_t p[3];
    for (int i = 0; i < 3; i++)
        p[i] = rs_vnum(rs_add(c, rs_scale(rs_sphere(r), size)), RS_LIM);
    if (rs_chance(r, 0.05)) /* a sliver: the third corner near the first edge */
        p[2] = rs_vnum(rs_add(rs_scale(rs_add(p[0], p[1]), 0.5), rs_scale(rs_sphere(r), size * 1e-4)), RS_LIM);
    if (rs_chance(r, 0.02))
        p[2] = p[1]; /* degenerate: invisible */
    rs_out(r, "triangle");
    rs_put(r, "a", p[0]);
    rs_put(r, "b", p[1]);
    rs_put(r, "c", p[2]);
}

static void rs_plane_obj(rs_t *r, rs_vec_t eye, rs_vec_t fwd, double spread, double dist)
{
    rs_vec_t p = rs_vnum(rs_anchor(r, eye, fwd, spread, dist), RS_LIM);
    rs_vec_t n = rs_direction(r);
    if (rs_chance(r, 0.15)) {
        /* Grazing: the normal nearly across the view, the plane close to the eye. */
        rs_vec_t a = rs_cross(fwd, rs_sphere(r));
        double la = rs_len(a);
        if (la > 1e-3)
            n = rs_vnum(rs_add(rs_scale(a, 1 / la), rs_scale(fwd, rs_log(r, 1e-5, 1e-1))), RS_LIM);
        p = rs_vnum(rs_add(eye, rs_scale(n, rs_log(r, 1e-3, 1) / fmax(rs_len(n), 1e-9))), RS_LIM);
        if (rs_len(n) == 0)
            n = (rs_vec_t){0, 1, 0};
    }
    rs_out(r, "plane");
    rs_put(r, "point", p);
    rs_put(r, "normal", n);
}

size_t randscene_text(uint64_t seed, char *buf, size_t len)
{
    rs_t r = {seed * 0x9E3779B97F4A7C15ull + 0x2545F4914F6CDD1Dull, buf, len, 0};
    for (int i = 0; i < 4; i++)
        rs_next(&r);
    buf[0] = '\0';

    int width = rs_int(&r, 32, 96), height = rs_int(&r, 24, 72);
    if (rs_chance(&r, 0.05))
        width = rs_int(&r, 1, 4);
    if (rs_chance(&r, 0.05))
        height = rs_int(&r, 1, 4);
    rs_out(&r, "# random scene, seed %llu (tests/randscene.c)\n", (unsigned long long)seed);
    rs_out(&r, "image %d %d\n", width, height);
    if (rs_chance(&r, 0.8)) {
        rs_color(&r, "background");
        rs_out(&r, "\n");
    }

    /* The scene's size: how far objects are from the eye. */
    double dist = rs_log(&r, 1e-2, 4096);
    int ortho = rs_chance(&r, 0.5);
    double scale = 0, fov = 0, spread;
    rs_vec_t eye;
    int mode = rs_int(&r, 0, 2);
    if (mode == 0)
        eye = rs_box3(&r, -2, 2);
    else if (mode == 1) {
        eye = rs_sphere(&r);
        eye = rs_scale(eye, rs_log(&r, 1e-3, RS_LIM * 1.7));
    }
    else
        eye = rs_box3(&r, -RS_LIM, RS_LIM);
    if (ortho) {
        /* View height s; the view must stay inside the domain:
         * |eye_i| + s W / (2 H) + s / 2 <= 8192 (with a margin for rounding). */
        double aspect = (double)width / height;
        double smax = fmin((double)FXRT_RADIUS_LIMIT, (RS_LIM - 2) / (aspect / 2 + 0.5));
        scale = rs_num(fmin(dist * rs_log(&r, 0.1, 4), smax), smax);
        if (rs_chance(&r, 0.05))
            scale = rs_num(rs_log(&r, 1e-3, smax), smax);
        if (scale <= 0)
            scale = 1;
        double reach = scale * (aspect / 2 + 0.5) + 1;
        double elim = RS_LIM - reach;
        eye = rs_vnum(eye, elim);
        spread = scale / dist;
    } else {
        /* fov in (0, 180) with H cot(fov/2) <= 32767 (with a margin). */
        double fmin_deg = 2 * atan(height / 32000.0) * 180 / RS_PI;
        int fm = rs_int(&r, 0, 4);
        fov = fm == 0 ? rs_log(&r, fmin_deg, 10) : fm == 1 ? rs_uniform(&r, 150, 179.99) : rs_uniform(&r, 10, 150);
        /* cam_setup needs H cot(fov/2) >= 1 (CAM_ERR_WIDE): the widest
         * fov a height-H image accepts is 2 atan(H). */
        double fmax_deg = fmin(179.99, 2 * atan((double)height) * 180 / RS_PI * 0.9999);
        fov = rs_num(fmin(fmax(fov, fmin_deg * 1.001), fmax_deg), 179.99);
        spread = tan(fov * RS_PI / 360) * 1.5;
        eye = rs_vnum(eye, RS_LIM);
    }
    rs_vec_t gaze = rs_direction(&r), up;
    for (;;) {
        up = rs_direction(&r);
        if (rs_chance(&r, 0.05)) {
            /* Nearly parallel to the gaze: just over the 0.9 degrees that
             * cam_setup requires, and long enough that its part across
             * the gaze survives rounding (the parser's 4-LSB roll rule). */
            double a = rs_log(&r, 0.02, 0.1);
            rs_vec_t off = rs_scale(rs_sphere(&r), a);
            double ul = rs_log(&r, fmax(1.0, 1.0 / a), RS_LIM / 2);
            up = rs_vnum(rs_scale(rs_add(rs_scale(gaze, 1 / rs_len(gaze)), off), ul), RS_LIM);
        }
        /* Accepted when up is over 1 degree from the gaze and its part
         * across the gaze is at least 0.25 long (see rs_direction). */
        double s = rs_len(rs_cross(gaze, up)), g = rs_len(gaze), u = rs_len(up);
        if (u > 0 && s > 0.0175 * g * u && s > 0.25 * g)
            break;
    }
    rs_out(&r, "camera %s", ortho ? "orthographic" : "perspective");
    rs_put(&r, "eye", eye);
    rs_put(&r, "gaze", gaze);
    rs_put(&r, "up", up);
    if (ortho)
        rs_out(&r, " scale %.8g\n", scale);
    else
        rs_out(&r, " fov %.8g\n", fov);

    rs_vec_t fwd = rs_scale(gaze, 1 / rs_len(gaze));
    int count = rs_chance(&r, 0.7) ? rs_int(&r, 1, 8) : rs_int(&r, 1, 20);
    for (int i = 0; i < count; i++) {
        switch (rs_int(&r, 0, 9)) {
        case 0:
        case 1: rs_plane_obj(&r, eye, fwd, spread, dist); break;
        case 2:
        case 3:
        case 4: rs_sphere_obj(&r, eye, fwd, spread, dist); break;
        case 5:
        case 6: rs_triangle_obj(&r, eye, fwd, spread, dist); break;
        default: rs_box_obj(&r, eye, fwd, spread, dist); break;
        }
        rs_color(&r, "color");
        rs_out(&r, "\n");
    }
    return r.n;
}
