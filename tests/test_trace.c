/* The bounce model of issue 12 (core/light/trace.c) against an independent
 * oracle: a recursive double tracer written here from the issue's
 * formulas (its own intersections, with an epsilon for self-intersection
 * instead of the core's rule; its own Snell, Schlick, cut-off and depth),
 * built once per number type like test_shade. Only camera rays come from
 * the core (cam_ray). Worlds are built through the public API (fxrt.h).
 *
 * Checks (colours in 1/255 units; TOL below):
 *  - frames: the course's reflection scene and a glass scene at 64 x 48
 *    against the oracle: >= 97 % of pixels within 2/255, no pixel beyond
 *    2/255 unless a neighbour differs from it by more than 8/255 in the
 *    oracle (a discontinuity; a reflected or refracted silhouette moves
 *    with the rounding of the first hit);
 *  - hand-made rays through shade_object (the unclamped colour), each
 *    against a value computed here in closed form:
 *      a reflective plane under a flat sphere (reflected ray through the
 *      sphere's centre), and with the sphere moved off it (background);
 *      depth 0: the local colour only;
 *      the cut-off: reflection 1/1024 in every channel traces nothing,
 *      1/256 in one channel (1/1024 in the others) traces the ray and
 *      every channel gets its share;
 *      two facing mirrors: depth 1, 2 and 4 give the geometric sums
 *      truncated after 1, 2, 4 bounces;
 *      Schlick at normal incidence: R = R0 through a transparent plane,
 *      and the tint (1 - R0) c_d on the transmitted term;
 *      a glass sphere entered on its axis: the ray leaves at the far side
 *      (no self-hit near t = 0), the series of internal reflections is
 *      the closed form for depth 2;
 *      refraction off-axis (Snell): a small flat target on the double
 *      exit ray is seen through the sphere, and one moved off it is not;
 *      total internal reflection from inside a sphere: the colour is what
 *      the reflected ray sees (a flat target inside), black without it;
 *      a transparent sphere casts no shadow on a lit plane, the same
 *      sphere made phong does.
 * Tolerances: Q16.16 TOL 0.03 (1/255 units): each weight (c_r, R, 1 - R,
 * c_d) is a fraction rounded to 2^-16 (0.5 LSB each product), so a traced
 * term of colour up to 255 carries a few times 255 * 2^-16 = 0.0039; a
 * hit point off by a few LSB moves nothing here (flat targets, flat
 * mirrors, normal incidence). Float 2e-3 (24-bit fractions), double 1e-6. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../core/fxrt.h"
#include "check.h"

#if FXRT_NUMBER == FXRT_Q16
#define TOL 0.03
#elif FXRT_NUMBER == FXRT_FLOAT
#define TOL 2e-3
#else
#define TOL 1e-6
#endif

#include "ref_geom.h"

/* A fraction as the build stores it (Q16.16: rounded to 2^-16). */
static double frac(double x)
{
    return D(N(x));
}

/* ---- the scene, as data ---------------------------------------------------- */


typedef struct {
    double pos[3], color[3];
    bool shadows;
} lgt_t; /* point lights */

typedef struct {
    int n_obj, n_lights, depth;
    obj_t obj[10];
    lgt_t light[2];
    double ambient[3], background[3];
    double eye[3], gaze[3], up[3], fov;
} scene_t;

static void set3(double v[3], double x, double y, double z)
{
    v[0] = x;
    v[1] = y;
    v[2] = z;
}

/* ---- the oracle, in double -------------------------------------------------- */

/* Self-intersection, the oracle's way: an epsilon (scene units), not the
 * core's rule. */
#define EPS 1e-7
#define CUT (1.0 / 512)

static int ref_nearest(const scene_t *s, const double org[3], const double d[3], double *tb, double n[3])
{
    int best = -1;
    *tb = INFINITY;
    for (int j = 0; j < s->n_obj; j++) {
        double t, nn[3];
        if (ref_hit(&s->obj[j], org, d, EPS, &t, nn) && t < *tb) {
            *tb = t;
            best = j;
            memcpy(n, nn, sizeof nn);
        }
    }
    return best;
}

/* Phong local colour at p (n faces the ray; inside: the ray came from the
 * solid's inside); transparent objects cast no shadow. */
static void ref_local(const scene_t *s, int j, const double p[3], const double n[3], const double d[3], bool inside,
                      double out[3])
{
    const obj_t *o = &s->obj[j];
    double cd[3];
    for (int i = 0; i < 3; i++)
        cd[i] = chan(o->color[i]);
    if (o->material == MATERIAL_FLAT) {
        memcpy(out, cd, sizeof cd);
        return;
    }
    out[0] = out[1] = out[2] = 0;
    if (o->material == MATERIAL_TRANSPARENT)
        return;
    for (int i = 0; i < 3; i++)
        out[i] = cd[i] * s->ambient[i];
    for (int k = 0; k < s->n_lights; k++) {
        const lgt_t *L = &s->light[k];
        double l[3];
        for (int i = 0; i < 3; i++)
            l[i] = L->pos[i] - p[i];
        double dist = sqrt(dot(l, l));
        unit(l);
        double ndl = dot(n, l);
        if (ndl <= 0)
            continue;
        if (L->shadows) {
            bool solid = o->kind == GEOM_SPHERE || o->kind == GEOM_BOX;
            bool blocked = false;
            if (inside && solid) {
                /* the light outside the solid: its own surface blocks it */
                double v[3] = {L->pos[0] - o->p[0][0], L->pos[1] - o->p[0][1], L->pos[2] - o->p[0][2]};
                bool light_in = o->kind == GEOM_SPHERE ? dot(v, v) < o->radius * o->radius
                                                       : L->pos[0] > o->p[0][0] && L->pos[0] < o->p[1][0] &&
                                                             L->pos[1] > o->p[0][1] && L->pos[1] < o->p[1][1] &&
                                                             L->pos[2] > o->p[0][2] && L->pos[2] < o->p[1][2];
                blocked = !light_in;
            }
            for (int q = 0; q < s->n_obj && !blocked; q++) {
                double t, nn[3];
                if (q != j && s->obj[q].material != MATERIAL_TRANSPARENT &&
                    ref_hit(&s->obj[q], p, l, EPS, &t, nn) && t < dist)
                    blocked = true;
            }
            if (blocked)
                continue;
        }
        for (int i = 0; i < 3; i++)
            out[i] += cd[i] * L->color[i] * ndl;
        if (o->material == MATERIAL_PHONG || o->material == MATERIAL_REFLECTIVE) {
            double r[3];
            for (int i = 0; i < 3; i++)
                r[i] = 2 * ndl * n[i] - l[i];
            double rde = -dot(r, d);
            if (rde > 0)
                for (int i = 0; i < 3; i++)
                    out[i] += 255.0 * o->specular[i] * L->color[i] * pow(fmin(rde, 1.0), o->exponent);
        }
    }
}

static bool cut(const double w[3])
{
    return w[0] < CUT && w[1] < CUT && w[2] < CUT;
}

/* The colour seen along (org, d) (unit), unclamped: issue 12's model,
 * written recursively (the oracle may recurse; the core may not). */
static void ref_trace(const scene_t *s, const double org[3], const double d[3], int bounce, const double w[3],
                      double out[3])
{
    double t, ng[3];
    int j = ref_nearest(s, org, d, &t, ng);
    if (j < 0) {
        for (int i = 0; i < 3; i++)
            out[i] = chan(s->background[i]);
        return;
    }
    const obj_t *o = &s->obj[j];
    double p[3], n[3];
    for (int i = 0; i < 3; i++)
        p[i] = org[i] + t * d[i];
    bool inside = dot(ng, d) > 0;
    for (int i = 0; i < 3; i++)
        n[i] = inside ? -ng[i] : ng[i];
    ref_local(s, j, p, n, d, inside, out);
    if (bounce >= s->depth || (o->material != MATERIAL_REFLECTIVE && o->material != MATERIAL_TRANSPARENT))
        return;
    double dn = dot(d, n), r[3], c[3], wc[3];
    for (int i = 0; i < 3; i++)
        r[i] = d[i] - 2 * dn * n[i];
    if (o->material == MATERIAL_REFLECTIVE) {
        for (int i = 0; i < 3; i++)
            wc[i] = w[i] * o->reflection[i];
        if (cut(wc))
            return;
        ref_trace(s, p, r, bounce + 1, wc, c);
        for (int i = 0; i < 3; i++)
            out[i] += o->reflection[i] * c[i];
        return;
    }
    /* transparent: eta1/eta2 = 1/eta entering, eta leaving */
    double q = inside ? o->index : 1.0 / o->index, ci = -dn;
    double c2t = 1 - q * q * (1 - ci * ci);
    if (c2t < 0) {
        if (cut(w))
            return;
        ref_trace(s, p, r, bounce + 1, w, c);
        for (int i = 0; i < 3; i++)
            out[i] += c[i];
        return;
    }
    double ct = sqrt(c2t), e1 = inside ? o->index : 1, e2 = inside ? 1 : o->index;
    double r0 = (e1 - e2) / (e1 + e2);
    r0 *= r0;
    double R = r0 + (1 - r0) * pow(1 - (inside ? ct : ci), 5), td[3], tint[3];
    for (int i = 0; i < 3; i++) {
        td[i] = q * d[i] + (q * ci - ct) * n[i];
        tint[i] = chan(o->color[i]) / 255.0;
        wc[i] = w[i] * R;
    }
    if (!cut(wc)) {
        ref_trace(s, p, r, bounce + 1, wc, c);
        for (int i = 0; i < 3; i++)
            out[i] += R * c[i];
    }
    for (int i = 0; i < 3; i++)
        wc[i] = w[i] * (1 - R) * tint[i];
    if (!cut(wc)) {
        unit(td);
        ref_trace(s, p, td, bounce + 1, wc, c);
        for (int i = 0; i < 3; i++)
            out[i] += (1 - R) * tint[i] * c[i];
    }
}

static void ref_ray(const scene_t *s, const double org[3], const double d0[3], double out[3])
{
    double d[3] = {d0[0], d0[1], d0[2]}, w[3] = {1, 1, 1};
    unit(d);
    ref_trace(s, org, d, 0, w, out);
}

/* ---- the core ------------------------------------------------------------------ */

static world_t world;
static render_t rnd;
static cam_t cam;

static bool build(const scene_t *s, int w, int h)
{
    color_t bg = color_make(N(chan(s->background[0])), N(chan(s->background[1])), N(chan(s->background[2])));
    if (fxrt_world_init(&world, bg) != FXRT_OK)
        return false;
    for (int j = 0; j < s->n_obj; j++) {
        const obj_t *o = &s->obj[j];
        fxrt_object_t fo;
        memset(&fo, 0, sizeof fo);
        fo.kind = o->kind;
        for (int k = 0; k < 3; k++)
            fo.p[k] = V(o->p[k]);
        fo.radius = N(o->radius);
        fo.color = color_make(N(chan(o->color[0])), N(chan(o->color[1])), N(chan(o->color[2])));
        fo.material.kind = (uint8_t)o->material;
        fo.material.exponent = (uint16_t)(o->exponent ? o->exponent : 1);
        fo.material.specular = color_make(N(chan(o->specular[0])), N(chan(o->specular[1])), N(chan(o->specular[2])));
        fo.material.reflection = color_make(N(chan(o->reflection[0])), N(chan(o->reflection[1])), N(chan(o->reflection[2])));
        fo.material.index = N(o->index);
        int32_t id = fxrt_add(&world, &fo);
        if (id != j) {
            fprintf(stderr, "object %d refused: %d (%s)\n", j, (int)id, fxrt_strerror(id));
            return false;
        }
    }
    for (int k = 0; k < s->n_lights; k++) {
        const lgt_t *L = &s->light[k];
        fxrt_light_t fl = {LIGHT_POINT, V(L->pos), vec3_make(0, 0, 0), 0,
                           color_make(N(chan(L->color[0])), N(chan(L->color[1])), N(chan(L->color[2]))), L->shadows};
        if (fxrt_add_light(&world, &fl) != k)
            return false;
    }
    if (world_set_ambient(&world, color_make(N(s->ambient[0]), N(s->ambient[1]), N(s->ambient[2]))) != FXRT_OK)
        return false;
    if (world_set_depth(&world, s->depth) != FXRT_OK)
        return false;
    if (w == 0)
        return true;
    if (fxrt_camera_perspective(&cam, V(s->eye), V(s->gaze), V(s->up), N(s->fov), w, h) != FXRT_OK)
        return false;
    return fxrt_render_setup(&rnd, &world, &cam) == FXRT_OK;
}

/* shade_object for object j of the scene along a hand-made ray (which must
 * meet it), against expect (unclamped, 1/255 units), within tol. Returns
 * the core's colour. */
static void check_ray(const char *name, const scene_t *s, int j, const double org[3], const double d[3],
                      const double expect[3], double tol)
{
    CHECK_MSG(build(s, 0, 0), "%s: world refused", name);
    double du[3] = {d[0], d[1], d[2]};
    unit(du);
    ray_t ray = {V(org), V(du)};
    geom_kind_t kind;
    uint16_t index;
    if (!world_find(&world, (uint16_t)j, &kind, &index)) {
        CHECK_MSG(false, "%s: no object %d", name, j);
        return;
    }
    color_t c = shade_object(&world, kind, index, &ray, NULL, NULL);
    double got[3] = {D(c.r), D(c.g), D(c.b)}, e = 0;
    for (int i = 0; i < 3; i++)
        e = fmax(e, fabs(got[i] - expect[i]));
    printf("%-52s %s: got %9.4f %9.4f %9.4f expected %9.4f %9.4f %9.4f (err %.2g, tol %.2g)\n", name, NUM_NAME,
           got[0], got[1], got[2], expect[0], expect[1], expect[2], e, tol);
    CHECK_MSG(e <= tol, "%s: got %.5f %.5f %.5f, expected %.5f %.5f %.5f (err %.3g > %.3g)", name, got[0], got[1],
              got[2], expect[0], expect[1], expect[2], e, tol);
}

/* Render the scene at W x H; compare every pixel with the oracle. */
#define W 64
#define H 48
static uint8_t img[H][W][3];
static double ref[H][W][3];

static void check_frame(const char *name, const scene_t *s)
{
    CHECK_MSG(build(s, W, H), "%s: set-up refused", name);
    for (int y = 0; y < H; y++)
        CHECK(fxrt_render_row(&rnd, y, &img[y][0][0], sizeof img[y]) == FXRT_OK);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            ray_t r;
            cam_ray(&cam, x, H - 1 - y, &r);
            double o[3] = {D(r.o.x), D(r.o.y), D(r.o.z)}, d[3] = {D(r.d.x), D(r.d.y), D(r.d.z)};
            ref_ray(s, o, d, ref[y][x]);
            for (int i = 0; i < 3; i++)
                ref[y][x][i] = fmin(255.0, fmax(0.0, ref[y][x][i]));
        }
    int within = 0, bad = 0, coloured = 0;
    double worst = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            double e = 0, jump = 0;
            for (int i = 0; i < 3; i++)
                e = fmax(e, fabs(img[y][x][i] - ref[y][x][i]));
            coloured += ref[y][x][0] != ref[y][x][1] || ref[y][x][1] != ref[y][x][2];
            for (int dy = -1; dy <= 1; dy++)
                for (int dx = -1; dx <= 1; dx++) {
                    int yy = y + dy, xx = x + dx;
                    if (yy < 0 || yy >= H || xx < 0 || xx >= W)
                        continue;
                    for (int i = 0; i < 3; i++)
                        jump = fmax(jump, fabs(ref[yy][xx][i] - ref[y][x][i]));
                }
            if (e <= 2.0)
                within++;
            else if (jump <= 8.0) {
                bad++;
                worst = fmax(worst, e);
                if (bad <= 3)
                    fprintf(stderr, "%s: pixel %d,%d: %d %d %d, oracle %.2f %.2f %.2f\n", name, x, y, img[y][x][0],
                            img[y][x][1], img[y][x][2], ref[y][x][0], ref[y][x][1], ref[y][x][2]);
            }
        }
    printf("%s (%s, %dx%d): %d of %d pixels within 2/255 of the oracle, %d smooth pixels beyond (worst %.0f/255)\n",
           name, NUM_NAME, W, H, within, W * H, bad, worst);
    CHECK_MSG(within >= W * H * 97 / 100, "%s: only %d of %d pixels within 2/255", name, within, W * H);
    CHECK_MSG(bad == 0, "%s: %d pixels away from discontinuities beyond 2/255 (worst %.0f)", name, bad, worst);
    CHECK_MSG(coloured > W * H / 10, "%s: the frame is mostly grey (%d coloured pixels)", name, coloured);
}

/* ---- scenes -------------------------------------------------------------------- */

static obj_t sphere(double x, double y, double z, double r, double cr, double cg, double cb, int mat)
{
    obj_t o;
    memset(&o, 0, sizeof o);
    o.kind = GEOM_SPHERE;
    set3(o.p[0], x, y, z);
    o.radius = r;
    set3(o.color, cr, cg, cb);
    o.material = mat;
    o.exponent = 1;
    o.index = 1.5;
    return o;
}
static obj_t plane(double x, double y, double z, double nx, double ny, double nz, double c, int mat)
{
    obj_t o;
    memset(&o, 0, sizeof o);
    o.kind = GEOM_PLANE;
    set3(o.p[0], x, y, z);
    set3(o.p[1], nx, ny, nz);
    set3(o.color, c, c, c);
    o.material = mat;
    o.exponent = 1;
    o.index = 1.5;
    return o;
}
static scene_t empty(void)
{
    scene_t s;
    memset(&s, 0, sizeof s);
    s.depth = 4;
    set3(s.up, 0, 1, 0);
    s.fov = 45;
    return s;
}

/* The course's reflection scene (scenes/trace/reflection.scene). */
static scene_t course(void)
{
    scene_t s = empty();
    set3(s.eye, 8, 8, 8);
    set3(s.gaze, -1, -1, -1);
    set3(s.ambient, 0.25, 0.25, 0.25);
    s.light[0] = (lgt_t){{8, 8, 0}, {1, 1, 1}, true};
    s.n_lights = 1;
    s.obj[0] = plane(0, 0, 0, 0, 1, 0, 0.1, MATERIAL_REFLECTIVE);
    set3(s.obj[0].reflection, 0.5, 0.5, 0.5);
    static const double col[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int k = 0; k < 3; k++) {
        obj_t *o = &s.obj[1 + k];
        *o = sphere(-3 + 3 * k, 1, 0, 1, col[k][0], col[k][1], col[k][2], MATERIAL_REFLECTIVE);
        set3(o->specular, 1, 1, 1);
        o->exponent = 64;
        set3(o->reflection, 0.5, 0.5, 0.5);
    }
    s.n_obj = 4;
    return s;
}

/* Glass in front of coloured objects (like scenes/trace/glass.scene). */
static scene_t glass(void)
{
    scene_t s = empty();
    s.depth = 6;
    set3(s.eye, 0, 3, 9);
    set3(s.gaze, 0, -0.3, -1);
    set3(s.background, 0.2, 0.3, 0.5);
    set3(s.ambient, 0.2, 0.2, 0.2);
    s.light[0] = (lgt_t){{4, 8, 6}, {1, 1, 1}, true};
    s.n_lights = 1;
    obj_t *o = s.obj;
    o[0] = plane(0, 0, 0, 0, 1, 0, 0.85, MATERIAL_LAMBERT);
    o[1] = sphere(0, 1.5, -4, 1.5, 0.2, 1, 0.2, MATERIAL_PHONG);
    set3(o[1].specular, 1, 1, 1);
    o[1].exponent = 32;
    memset(&o[2], 0, sizeof o[2]);
    o[2].kind = GEOM_BOX;
    set3(o[2].p[0], -4, 0, -4);
    set3(o[2].p[1], -2, 3, -3);
    set3(o[2].color, 1, 0.2, 0.2);
    o[2].material = MATERIAL_LAMBERT;
    o[3] = sphere(-1.5, 1, 1, 1, 1, 1, 1, MATERIAL_TRANSPARENT);
    o[3].index = 1.33;
    o[4] = sphere(1.6, 0.8, 1.5, 0.8, 1, 0.85, 0.6, MATERIAL_TRANSPARENT);
    o[4].index = 1.5;
    memset(&o[5], 0, sizeof o[5]);
    o[5].kind = GEOM_BOX;
    set3(o[5].p[0], -0.6, 0, 2.5);
    set3(o[5].p[1], 0.6, 1.2, 3.5);
    set3(o[5].color, 1, 1, 1);
    o[5].material = MATERIAL_TRANSPARENT;
    o[5].index = 1.33;
    s.n_obj = 6;
    return s;
}

/* ---- closed forms ------------------------------------------------------------- */

/* A reflective plane y = 0 (colour 0.4, no light: local = c_d c_a), a flat
 * sphere on the mirrored ray, background 0.1. */
static void test_mirror(void)
{
    scene_t s = empty();
    set3(s.ambient, 0.5, 0.5, 0.5);
    set3(s.background, 0.1, 0.2, 0.3);
    s.obj[0] = plane(0, 0, 0, 0, 1, 0, 0.4, MATERIAL_REFLECTIVE);
    set3(s.obj[0].reflection, 0.5, 0.25, 0.75);
    /* the ray from (0, 2, 2) along (0, -1, -1) meets the plane at the
     * origin and leaves along (0, 1, -1): through (0, 3, -3) */
    s.obj[1] = sphere(0, 3, -3, 1, 0.2, 0.6, 1.0, MATERIAL_FLAT);
    s.n_obj = 2;
    double o[3] = {0, 2, 2}, d[3] = {0, -1, -1}, e[3];
    double local = chan(0.4) * 0.5;
    for (int i = 0; i < 3; i++)
        e[i] = local + frac(s.obj[0].reflection[i]) * chan(s.obj[1].color[i]);
    check_ray("mirror plane, flat sphere on the reflected ray", &s, 0, o, d, e, TOL);
    /* the sphere off the mirrored ray: the background */
    set3(s.obj[1].p[0], 3, 3, -3);
    for (int i = 0; i < 3; i++)
        e[i] = local + frac(s.obj[0].reflection[i]) * chan(s.background[i]);
    check_ray("mirror plane, sphere off the ray: background", &s, 0, o, d, e, TOL);
    /* depth 0: the local colour only */
    set3(s.obj[1].p[0], 0, 3, -3);
    s.depth = 0;
    for (int i = 0; i < 3; i++)
        e[i] = local;
    check_ray("mirror plane, depth 0: local colour only", &s, 0, o, d, e, TOL);
    /* the cut-off: 1/1024 in every channel is below 1/512: not traced */
    s.depth = 4;
    set3(s.obj[0].reflection, 1.0 / 1024, 1.0 / 1024, 1.0 / 1024);
    check_ray("mirror plane, reflection 1/1024: cut off", &s, 0, o, d, e, TOL);
    /* 1/256 in blue alone: traced, and every channel gets its share */
    set3(s.obj[0].reflection, 1.0 / 1024, 1.0 / 1024, 1.0 / 256);
    for (int i = 0; i < 3; i++)
        e[i] = local + s.obj[0].reflection[i] * chan(s.obj[1].color[i]);
    check_ray("mirror plane, reflection 1/256 in blue: traced", &s, 0, o, d, e, TOL);
    CHECK(fabs(e[2] - local) > 0.003 && fabs(e[0] - local) > 0.00003); /* the check can see the difference */
}

/* Two facing mirrors z = 0 (A) and z = 4 (B), no light (local = c_d c_a):
 * the ray along -z from (0, 0, 2) bounces A, B, A, ...; with depth k the
 * colour is the sum of the first k + 1 terms of LA + rA LB + rA rB LA +
 * ... A bounce beyond depth contributes black. */
static void test_mirrors(void)
{
    scene_t s = empty();
    set3(s.ambient, 1, 1, 1);
    set3(s.background, 1, 1, 1);
    s.obj[0] = plane(0, 0, 0, 0, 0, 1, 0.2, MATERIAL_REFLECTIVE);
    s.obj[1] = plane(0, 0, 4, 0, 0, -1, 0.6, MATERIAL_REFLECTIVE);
    set3(s.obj[0].reflection, 0.5, 0.5, 0.5);
    set3(s.obj[1].reflection, 0.75, 0.75, 0.75);
    s.n_obj = 2;
    double o[3] = {0, 0, 2}, d[3] = {0, 0, -1};
    double L[2] = {chan(0.2), chan(0.6)}, rf[2] = {0.5, 0.75};
    double prev = -1;
    for (int depth = 0; depth <= 4; depth++) {
        s.depth = depth;
        double sum = 0, wgt = 1;
        for (int b = 0; b <= depth; b++) {
            sum += wgt * L[b % 2];
            wgt *= rf[b % 2];
        }
        double e[3] = {sum, sum, sum};
        char name[64];
        snprintf(name, sizeof name, "two facing mirrors, depth %d", depth);
        check_ray(name, &s, 0, o, d, e, TOL);
        CHECK(sum > prev + 1); /* each depth adds a visible term */
        prev = sum;
    }
}

/* A clear transparent plane z = 0 (index eta) hit at normal incidence:
 * R = R0, the transmitted ray goes straight on to a flat sphere behind
 * (z = -3), the reflected one back to a flat sphere in front (z = 5):
 * colour R0 C_front + (1 - R0) c_d C_back. */
static void test_schlick_normal(void)
{
    static const double etas[] = {1.5, 1.33, 2.4, 0.5, 0.01, 100};
    for (size_t k = 0; k < sizeof etas / sizeof etas[0]; k++) {
        for (int tinted = 0; tinted < 2; tinted++) {
            scene_t s = empty();
            s.obj[0] = plane(0, 0, 0, 0, 0, 1, 1, MATERIAL_TRANSPARENT);
            if (tinted)
                set3(s.obj[0].color, 1, 0.5, 0.25);
            double eta = frac(etas[k]);
            s.obj[0].index = etas[k];
            s.obj[1] = sphere(0, 0, -3, 1, 0.9, 0.5, 0.1, MATERIAL_FLAT);
            s.obj[2] = sphere(0, 0, 5, 1, 0.1, 0.3, 0.7, MATERIAL_FLAT);
            s.n_obj = 3;
            double r0 = (1 - eta) / (1 + eta), e[3];
            r0 *= r0;
            for (int i = 0; i < 3; i++)
                e[i] = r0 * chan(s.obj[2].color[i]) +
                       (1 - r0) * chan(s.obj[0].color[i]) / 255 * chan(s.obj[1].color[i]);
            char name[80];
            snprintf(name, sizeof name, "transparent plane, normal incidence, eta %g%s: R = R0", etas[k],
                     tinted ? ", tinted" : "");
            double o[3] = {0, 0, 2}, d[3] = {0, 0, -1};
            check_ray(name, &s, 0, o, d, e, TOL);
        }
    }
}

/* A clear glass sphere (radius 1, eta 1.5) entered on its axis: the ray
 * enters at z = 1, leaves at z = -1 (not at t = 0 from its entry point)
 * and meets a flat target behind. Depth 2, closed form: entry R0 B (the
 * reflection sees the background) + (1 - R0)[R0 X + (1 - R0) T], where X
 * is what the internal reflection at the exit sees: it travels back to
 * the entry point's inside at bounce 2, whose children are beyond depth:
 * the glass has no local term, so X = 0. */
static void test_sphere_axis(void)
{
    scene_t s = empty();
    s.depth = 2;
    set3(s.background, 0.2, 0.4, 0.6);
    s.obj[0] = sphere(0, 0, 0, 1, 1, 1, 1, MATERIAL_TRANSPARENT);
    s.obj[1] = sphere(0, 0, -4, 1, 0.9, 0.6, 0.3, MATERIAL_FLAT);
    s.n_obj = 2;
    double eta = frac(1.5), r0 = (1 - eta) / (1 + eta), e[3];
    r0 *= r0;
    for (int i = 0; i < 3; i++)
        e[i] = r0 * chan(s.background[i]) + (1 - r0) * (1 - r0) * chan(s.obj[1].color[i]);
    double o[3] = {0, 0, 5}, d[3] = {0, 0, -1}, oracle[3];
    ref_ray(&s, o, d, oracle);
    for (int i = 0; i < 3; i++)
        CHECK_MSG(fabs(oracle[i] - e[i]) < 1e-9, "oracle %.9f, closed form %.9f", oracle[i], e[i]);
    check_ray("glass sphere on its axis, depth 2 (leaves at the far side)", &s, 0, o, d, e, TOL);
    /* depth 6: the oracle's series (X no longer 0) */
    s.depth = 6;
    ref_ray(&s, o, d, e);
    check_ray("glass sphere on its axis, depth 6, oracle", &s, 0, o, d, e, TOL);
}

/* Off-axis refraction (Snell): the exit ray of a glass sphere computed
 * here, a small flat target placed on it and then beside it. */
static void test_snell(void)
{
    scene_t s = empty();
    s.depth = 2;
    set3(s.background, 0, 0, 0);
    s.obj[0] = sphere(0, 0, 0, 1, 1, 1, 1, MATERIAL_TRANSPARENT);
    s.obj[0].index = 1.5;
    s.n_obj = 2;
    double eta = frac(1.5);
    double o[3] = {0.5, 0, 5}, d[3] = {0, 0, -1};
    /* entry: p1 = (0.5, 0, sqrt(0.75)), n = p1; Snell with q = 1/eta */
    double p1[3] = {0.5, 0, sqrt(0.75)}, ci = p1[2], q = 1 / eta;
    double ct = sqrt(1 - q * q * (1 - ci * ci)), t1[3];
    for (int i = 0; i < 3; i++)
        t1[i] = q * d[i] + (q * ci - ct) * p1[i];
    /* exit: p2 = p1 + s t1 with |p2| = 1 (s = -2 p1 . t1), leaving with q = eta */
    double sl = -2 * dot(p1, t1), p2[3], n2[3], t2[3];
    for (int i = 0; i < 3; i++) {
        p2[i] = p1[i] + sl * t1[i];
        n2[i] = -p2[i]; /* faces the ray, which comes from inside */
    }
    double ci2 = -dot(t1, n2), ct2 = sqrt(1 - eta * eta * (1 - ci2 * ci2));
    for (int i = 0; i < 3; i++)
        t2[i] = eta * t1[i] + (eta * ci2 - ct2) * n2[i];
    CHECK_MSG(fabs(dot(t2, t2) - 1) < 1e-12 && t2[0] < -0.1, "exit direction %.6f %.6f %.6f", t2[0], t2[1], t2[2]);
    double r1 = pow((1 - eta) / (1 + eta), 2), R1 = r1 + (1 - r1) * pow(1 - ci, 5), R2 = r1 + (1 - r1) * pow(1 - ct2, 5);
    /* a flat target of radius 0.3 centred 4 units along the exit ray */
    s.obj[1] = sphere(p2[0] + 4 * t2[0], p2[1] + 4 * t2[1], p2[2] + 4 * t2[2], 0.3, 0.8, 0.4, 0.2, MATERIAL_FLAT);
    double e[3];
    /* depth 2: entry reflection sees the background (0), the internal
     * reflection at the exit (bounce 2) sees only the glass (no local
     * term, children beyond depth): 0 */
    for (int i = 0; i < 3; i++)
        e[i] = (1 - R1) * (1 - R2) * chan(s.obj[1].color[i]);
    double oracle[3];
    ref_ray(&s, o, d, oracle);
    for (int i = 0; i < 3; i++)
        CHECK_MSG(fabs(oracle[i] - e[i]) < 1e-9, "oracle %.9f, closed form %.9f", oracle[i], e[i]);
    check_ray("glass sphere off axis: target on the Snell exit ray", &s, 0, o, d, e, TOL);
    /* the target moved 0.5 across the exit ray: not seen */
    s.obj[1].p[0][1] += 0.5;
    e[0] = e[1] = e[2] = 0;
    check_ray("glass sphere off axis: target beside the exit ray", &s, 0, o, d, e, TOL);
}

/* Total internal reflection inside a glass sphere (radius 1, eta 1.5):
 * from (0, 0.9, 0) along +x the ray meets the surface at cos_i = 0.436 <
 * sqrt(1 - 1/eta^2) = 0.745: the colour is what the reflected ray sees, a
 * flat target inside the sphere on the mirrored ray with full weight
 * (its colour exactly); with the target off that ray, every further hit
 * is the glass again (equal chords of a circle: TIR at each) until depth:
 * black. */
static void test_tir(void)
{
    scene_t s = empty();
    set3(s.background, 0.5, 0.5, 0.5);
    s.obj[0] = sphere(0, 0, 0, 1, 1, 1, 1, MATERIAL_TRANSPARENT);
    double x = sqrt(1 - 0.81), p[3] = {x, 0.9, 0}, d[3] = {1, 0, 0}, r[3];
    double dn = dot(d, p); /* n = -p faces the ray: d - 2 (d . n) n = d - 2 (d . p) p */
    for (int i = 0; i < 3; i++)
        r[i] = d[i] - 2 * dn * p[i];
    s.obj[1] = sphere(p[0] + 0.5 * r[0], p[1] + 0.5 * r[1], p[2] + 0.5 * r[2], 0.08, 0.3, 0.6, 0.9, MATERIAL_FLAT);
    s.n_obj = 2;
    double o[3] = {0, 0.9, 0}, e[3];
    for (int i = 0; i < 3; i++)
        e[i] = chan(s.obj[1].color[i]);
    check_ray("total internal reflection inside a sphere: flat target", &s, 0, o, d, e, TOL);
    s.obj[1].p[0][2] += 0.5;
    e[0] = e[1] = e[2] = 0;
    check_ray("total internal reflection, target off the ray: black", &s, 0, o, d, e, TOL);
}

/* A lambert plane under a point light; a sphere between them: phong, it
 * shadows the plane's point (ambient only); transparent, it does not. */
static void test_no_shadow(void)
{
    scene_t s = empty();
    set3(s.ambient, 0.2, 0.2, 0.2);
    s.obj[0] = plane(0, 0, 0, 0, 1, 0, 0.5, MATERIAL_LAMBERT);
    s.obj[1] = sphere(0, 2, 0, 0.5, 1, 1, 1, MATERIAL_PHONG);
    set3(s.obj[1].specular, 1, 1, 1);
    s.n_obj = 2;
    s.light[0] = (lgt_t){{0, 4, 0}, {1, 1, 1}, true};
    s.n_lights = 1;
    double o[3] = {0, 1, 3}, d[3] = {0, -1, -3}, e[3];
    for (int i = 0; i < 3; i++)
        e[i] = chan(0.5) * 0.2;
    check_ray("plane under an opaque sphere: in shadow", &s, 0, o, d, e, TOL);
    s.obj[1].material = MATERIAL_TRANSPARENT;
    for (int i = 0; i < 3; i++)
        e[i] = chan(0.5) * (0.2 + 1.0);
    check_ray("plane under a transparent sphere: no shadow", &s, 0, o, d, e, TOL);
}

int main(void)
{
    setvbuf(stdout, NULL, _IOLBF, 0);
    test_mirror();
    test_mirrors();
    test_schlick_normal();
    test_sphere_axis();
    test_snell();
    test_tir();
    test_no_shadow();
    scene_t s = course();
    check_frame("course reflection scene", &s);
    s = glass();
    check_frame("glass scene", &s);
    return check_report("test_trace_" NUM_NAME);
}
