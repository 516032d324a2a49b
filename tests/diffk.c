/* diffk: see diffk.h. Compiled once per number type (FXRT_MULTI). */
#ifndef FXRT_MULTI
#error "tests/diffk.c is built with -DFXRT_MULTI -DFXRT_NUMBER=1, 2 or 3"
#endif
#include <math.h>
#include <string.h>

#include "../core/scene/cam.h"
#include "../core/scene/kinds.h"
#include "../host/multi.h"
#include "add.h"
#include "diffk.h"

#define DIFFK_SYM(name) MULTI_SYM(name)

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

/* ---- lighting (issue 11) --------------------------------------------------- */
#include "../core/light/shade.h"
#include "../core/scene/world.h"

static color_t diffk_col(const double c[3])
{
    return color_make(diffk_num(c[0]), diffk_num(c[1]), diffk_num(c[2]));
}

/* A world_add_<kind> for a diffk_obj_t: the id, or a negative fxrt_err_t. */
static int32_t diffk_add(world_t *w, const diffk_obj_t *o)
{
    color_t col = diffk_col((const double[3]){128, 128, 128});
    switch (o->kind) {
    case 0: return world_add_plane(w, diffk_vec(o->p[0]), diffk_vec(o->p[1]), col);
    case 1: return world_add_sphere(w, diffk_vec(o->p[0]), diffk_num(o->radius), col);
    case 2: return world_add_triangle(w, diffk_vec(o->p[0]), diffk_vec(o->p[1]), diffk_vec(o->p[2]), col);
    default: return world_add_box(w, diffk_vec(o->p[0]), diffk_vec(o->p[1]), col);
    }
}

int DIFFK_SYM(diffk_surface)(const diffk_obj_t *o, const diffk_ray_t *ray, double *t, double n[3])
{
    ray_t r = diffk_ray(ray);
    num_t tt = NUM_ZERO;
    vec3_t nn = vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    color_t col = diffk_color();
    switch (o->kind) {
    case 0: {
        geom_plane_t p;
        if (!geom_plane_make(&p, diffk_vec(o->p[0]), diffk_vec(o->p[1]), col, 0))
            return DIFFK_REJECTED;
        geom_plane_surface(&p, &r, &tt, &nn);
        break;
    }
    case 1: {
        geom_sphere_t s;
        if (!geom_sphere_make(&s, diffk_vec(o->p[0]), diffk_num(o->radius), col, 0))
            return DIFFK_REJECTED;
        geom_sphere_surface(&s, &r, &tt, &nn);
        break;
    }
    case 2: {
        geom_triangle_t tr;
        if (!geom_triangle_make(&tr, diffk_vec(o->p[0]), diffk_vec(o->p[1]), diffk_vec(o->p[2]), col, 0))
            return DIFFK_REJECTED;
        if (tr.degenerate)
            return DIFFK_DEGENERATE;
        geom_triangle_surface(&tr, &r, &tt, &nn);
        break;
    }
    default: {
        geom_box_t b;
        if (!geom_box_make(&b, diffk_vec(o->p[0]), diffk_vec(o->p[1]), col, 0))
            return DIFFK_REJECTED;
        geom_box_surface(&b, &r, &tt, &nn);
        break;
    }
    }
    *t = diffk_dbl(tt);
    diffk_out(nn, n);
    return DIFFK_HIT;
}

/* world_t holds every kind's capacity: static, not on the stack. */
static world_t diffk_world;

int DIFFK_SYM(diffk_shade)(const diffk_shade_t *sh, const double p[3], const double n[3], const double d[3],
                           double rgb[3], int *mask)
{
    world_t *w = &diffk_world;
    world_init(w, color_make(NUM_ZERO, NUM_ZERO, NUM_ZERO));
    int32_t id = world_add_sphere(w, vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO), NUM_ONE, diffk_col(sh->color));
    if (id < 0)
        return (int)id;
    material_t m;
    m.kind = (uint8_t)(sh->material == DIFFK_PHONG ? MATERIAL_PHONG : MATERIAL_LAMBERT);
    m.exponent = (uint16_t)sh->exponent;
    m.specular = diffk_col(sh->specular);
    fxrt_err_t e = world_set_material(w, id, &m);
    if (e == FXRT_OK)
        e = world_set_ambient(w, diffk_col(sh->ambient));
    if (e != FXRT_OK)
        return (int)e;
    for (int i = 0; i < sh->n_lights; i++) {
        const diffk_light_t *L = &sh->lights[i];
        int32_t r = world_add_light(w, (light_kind_t)L->kind, diffk_vec(L->pos), diffk_vec(L->dir),
                                    diffk_num(L->angle), diffk_col(L->color), false);
        if (r < 0)
            return (int)r;
    }
    uint8_t bits = 0;
    color_t c = shade_point(w, GEOM_SPHERE, 0 GEOM_PART_ARG(NULL), diffk_vec(p), diffk_vec(n), diffk_vec(d), &bits);
    rgb[0] = diffk_dbl(c.r);
    rgb[1] = diffk_dbl(c.g);
    rgb[2] = diffk_dbl(c.b);
    *mask = bits;
    return 0;
}

int DIFFK_SYM(diffk_occluded)(int n, const diffk_obj_t *objs, const diffk_ray_t *ray, double tmax)
{
    world_t *w = &diffk_world;
    world_init(w, color_make(NUM_ZERO, NUM_ZERO, NUM_ZERO));
    for (int i = 0; i < n; i++)
        if (diffk_add(w, &objs[i]) < 0)
            return -1;
    ray_t r = diffk_ray(ray);
    /* skip_id = n: no object has it. */
    return world_occluded(w, &r, tmax < 0 ? NUM_MAX : diffk_num(tmax), (uint16_t)n) ? 1 : 0;
}

double DIFFK_SYM(diffk_pow)(long long x_q32, unsigned k)
{
#if FXRT_NUMBER == FXRT_Q16
    return diffk_dbl(numw_pow_int((numw_t)x_q32, k));
#else
    return diffk_dbl(numw_pow_int((numw_t)x_q32 / (numw_t)4294967296.0, k));
#endif
}

/* ---- secondary rays (issue 12) ----------------------------------------------
 * trace.c's helpers are static: its source is compiled into this file, with
 * its one external function renamed (diffk_trace_copy_<number>) so that it
 * does not clash with the core's trace_bounces. The static trace_children
 * then makes the same children as in the renderer. */
#include "../core/light/trace.h"
#undef trace_bounces
#define trace_bounces MULTI_SYM(diffk_trace_copy)
color_t trace_bounces(const world_t *w, geom_kind_t kind, uint16_t index GEOM_PART_PARAM, const ray_t *ray, vec3_t p,
                      vec3_t n_geo, color_t local);
#include "../core/light/trace.c"

void DIFFK_SYM(diffk_bounce)(const double d[3], const double n[3], double eta, double refl[3], int *tir,
                             double trans[3], int *has_t, double *R)
{
    geom_common_t obj;
    memset(&obj, 0, sizeof obj);
    obj.color = color_make(COLOR_MAX, COLOR_MAX, COLOR_MAX);
    trace_node_t nd;
    memset(&nd, 0, sizeof nd);
    nd.obj = &obj;
    nd.p = vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    nd.n_geo = diffk_vec(n);
    nd.n_side = nd.n_geo; /* (a flat surface: the same normal) */
    nd.d = diffk_vec(d);
    nd.w = color_make(NUM_ONE, NUM_ONE, NUM_ONE);
    trace_ray_t out[2];
    obj.mat.kind = MATERIAL_REFLECTIVE;
    obj.mat.reflection = color_make(NUM_ONE, NUM_ONE, NUM_ONE);
    int k = trace_children(&nd, &out[0], &out[1]);
    refl[0] = refl[1] = refl[2] = 0;
    if (k == 1)
        diffk_out(out[0].ray.d, refl);
    obj.mat.kind = MATERIAL_TRANSPARENT;
    obj.mat.index = diffk_num(eta);
    bool inside = vec3_dotw(nd.d, nd.n_geo) > 0;
    k = trace_children(&nd, &out[0], &out[1]);
    *tir = 0;
    *has_t = 0;
    *R = 0;
    trans[0] = trans[1] = trans[2] = 0;
    /* total internal reflection: one child, the reflected ray with the full weight */
    if (k == 1 && out[0].inward == inside && out[0].w.r == NUM_ONE) {
        *tir = 1;
        *R = 1;
        return;
    }
    for (int i = 0; i < k; i++) {
        if (out[i].inward == inside) { /* reflected: weight R */
            *R = diffk_dbl(out[i].w.r);
        } else {
            *has_t = 1;
            diffk_out(out[i].ray.d, trans);
            if (k == 1)
                *R = 1 - diffk_dbl(out[i].w.r);
        }
    }
}
