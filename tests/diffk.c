/* diffk: see diffk.h. Compiled once per number type (FXRT_MULTI). */
#ifndef FXRT_MULTI
#error "tests/diffk.c is built with -DFXRT_MULTI -DFXRT_NUMBER=1 or 3"
#endif
#include <math.h>

#include "../core/cam.h"
#include "../core/geom.h"
#include "diffk.h"

#define DIFFK_SYM(name) FXRT_SYM(name)

/* host/engine.c engine_num, plus saturation so that out-of-range input
 * (only the fuzzer produces it) is not undefined behaviour. */
static num_t diffk_num(double x)
{
#if FXRT_NUMBER == FXRT_Q16
    double s = x * 65536.0;
    if (!(s == s))
        return 0;
    if (s >= 2147483647.0)
        return FX_MAX;
    if (s <= -2147483648.0)
        return FX_MIN;
    return (fx_t)(s >= 0 ? floor(s + 0.5) : -floor(-s + 0.5));
#else
    return (num_t)x;
#endif
}

static double diffk_dbl(num_t x)
{
#if FXRT_NUMBER == FXRT_Q16
    return (double)x / 65536.0;
#else
    return (double)x;
#endif
}

static vec3_t diffk_vec(const double v[3])
{
    return vec3_make(diffk_num(v[0]), diffk_num(v[1]), diffk_num(v[2]));
}

static void diffk_out(vec3_t v, double out[3])
{
    out[0] = diffk_dbl(v.x);
    out[1] = diffk_dbl(v.y);
    out[2] = diffk_dbl(v.z);
}

static ray_t diffk_ray(const diffk_ray_t *r)
{
    ray_t ray;
    ray.o = diffk_vec(r->o);
    ray.d = diffk_vec(r->d);
    return ray;
}

static color_t diffk_color(void)
{
    return color_make(COLOR_MAX, NUM_ZERO, NUM_ZERO);
}

static int diffk_result(bool hit, num_t tt, double *t)
{
    if (!hit)
        return DIFFK_MISS;
    *t = diffk_dbl(tt);
    return DIFFK_HIT;
}

double DIFFK_SYM(diffk_input)(double x)
{
    return diffk_dbl(diffk_num(x));
}

int DIFFK_SYM(diffk_plane)(const double point[3], const double normal[3], const diffk_ray_t *ray, double *t)
{
    geom_plane_t p;
    if (!geom_plane_make(&p, diffk_vec(point), diffk_vec(normal), diffk_color(), 0))
        return DIFFK_REJECTED;
    ray_t r = diffk_ray(ray);
    num_t tt = NUM_ZERO;
    bool hit = geom_plane_hit(&p, &r, &tt);
    return diffk_result(hit, tt, t);
}

int DIFFK_SYM(diffk_sphere)(const double center[3], double radius, const diffk_ray_t *ray, double *t)
{
    geom_sphere_t s;
    if (!geom_sphere_make(&s, diffk_vec(center), diffk_num(radius), diffk_color(), 0))
        return DIFFK_REJECTED;
    ray_t r = diffk_ray(ray);
    num_t tt = NUM_ZERO;
    bool hit = geom_sphere_hit(&s, &r, &tt);
    return diffk_result(hit, tt, t);
}

int DIFFK_SYM(diffk_triangle)(const double a[3], const double b[3], const double c[3], const diffk_ray_t *ray,
                              double *t)
{
    geom_triangle_t tr;
    if (!geom_triangle_make(&tr, diffk_vec(a), diffk_vec(b), diffk_vec(c), diffk_color(), 0))
        return DIFFK_REJECTED;
    if (tr.degenerate)
        return DIFFK_DEGENERATE;
    ray_t r = diffk_ray(ray);
    num_t tt = NUM_ZERO;
    bool hit = geom_triangle_hit(&tr, &r, &tt);
    return diffk_result(hit, tt, t);
}

int DIFFK_SYM(diffk_box)(const double min[3], const double max[3], const diffk_ray_t *ray, double *t)
{
    geom_box_t b;
    if (!geom_box_make(&b, diffk_vec(min), diffk_vec(max), diffk_color(), 0))
        return DIFFK_REJECTED;
    ray_t r = diffk_ray(ray);
    num_t tt = NUM_ZERO;
    bool hit = geom_box_hit(&b, &r, &tt);
    return diffk_result(hit, tt, t);
}

int DIFFK_SYM(diffk_normal)(int kind, const double p0[3], const double p1[3], const double p2[3], double n[3])
{
    if (kind == 0) {
        geom_plane_t p;
        if (!geom_plane_make(&p, diffk_vec(p0), diffk_vec(p1), diffk_color(), 0))
            return DIFFK_REJECTED;
        diffk_out(p.n, n);
        return DIFFK_HIT;
    }
    geom_triangle_t tr;
    if (!geom_triangle_make(&tr, diffk_vec(p0), diffk_vec(p1), diffk_vec(p2), diffk_color(), 0))
        return DIFFK_REJECTED;
    diffk_out(tr.n, n);
    return tr.degenerate ? DIFFK_DEGENERATE : DIFFK_HIT;
}

static cam_err_t diffk_cam_setup(const diffk_cam_t *c, cam_t *cam)
{
    return cam_setup(cam, c->kind == DIFFK_ORTHOGRAPHIC ? CAM_ORTHOGRAPHIC : CAM_PERSPECTIVE, diffk_vec(c->eye),
                     diffk_vec(c->gaze), diffk_vec(c->up), diffk_num(c->fov_deg), diffk_num(c->scale), c->width,
                     c->height);
}

int DIFFK_SYM(diffk_cam_basis)(const diffk_cam_t *c, double basis[3][3], double *focal)
{
    cam_t cam;
    cam_err_t err = diffk_cam_setup(c, &cam);
    if (err != CAM_OK)
        return (int)err;
    diffk_out(cam.u, basis[0]);
    diffk_out(cam.v, basis[1]);
    diffk_out(cam.w, basis[2]);
    *focal = diffk_dbl(cam.focal);
    return 0;
}

int DIFFK_SYM(diffk_cam)(const diffk_cam_t *c, int n, const int *xs, const int *ys, diffk_ray_t *rays)
{
    cam_t cam;
    cam_err_t err = diffk_cam_setup(c, &cam);
    if (err != CAM_OK)
        return (int)err;
    for (int i = 0; i < n; i++) {
        ray_t r;
        cam_ray(&cam, xs[i], ys[i], &r);
        diffk_out(r.o, rays[i].o);
        diffk_out(r.d, rays[i].d);
    }
    return 0;
}
