/* Lit worlds built through the API (fxrt.h), rendered in full frames by the
 * build's number type (built once per type, like test_geom), against an
 * independent double implementation of the lighting model written
 * here: its own intersections, normals, light sum and shadow rays. Only
 * the camera rays come from the core (cam_ray, checked by test_diff and
 * test_geom). The sanitizer suite runs these binaries too, so ASan and
 * UBSan see the whole shading path (visibility pass, shade_object,
 * shade_point, shadow_blocked, world_occluded) in every number type.
 *
 * Checks:
 *  - the course scene (plane, sphere, box, triangle; lambert and phong,
 *    exponent 64; point light with shadows, directional, spot 180/14
 *    degrees; ambient 0.1) and a coloured-light scene with every material
 *    on every primitive: at least 98 % of pixels within 2/255 of the
 *    reference in every channel (the rest are silhouette, shadow-edge and
 *    cone-edge pixels, where the centre ray may fall on either side), and
 *    no pixel off by more than 2/255 unless a neighbour (8-neighbourhood)
 *    differs from it in the reference by more than 8/255 (a discontinuity);
 *  - single pixels with known values: a lit sphere's nearest point (no
 *    shadow acne with shadows on), a light inside a sphere (outside
 *    surface unlit), a sphere's shadow on a plane, a box seen from inside
 *    with the light outside it (blocked) and inside it (lit). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../core/fxrt.h"
#include "add.h"
#include "check.h"

#define W 64
#define H 48

/* ---- the scene, as data ---------------------------------------------------- */

#include "ref_geom.h"

typedef struct {
    light_kind_t kind;
    double pos[3], dir[3], angle, color[3];
    bool shadows;
} lgt_t;

typedef struct {
    int n_obj, n_lights;
    obj_t obj[96];
    bool smooth[96];      /* triangle j has vertex normals vn[j] (any length) */
    double vn[96][3][3];
    lgt_t light[4];
    double ambient[3];
    double eye[3], gaze[3], up[3], fov;
} scene_t;

/* ---- the reference, in double ------------------------------------------------ */

/* Strictly inside a solid (sphere, box)? */
static bool ref_inside(const obj_t *o, const double q[3])
{
    if (o->kind == GEOM_SPHERE) {
        double v[3] = {q[0] - o->p[0][0], q[1] - o->p[0][1], q[2] - o->p[0][2]};
        return dot(v, v) < o->radius * o->radius;
    }
    if (o->kind == GEOM_BOX)
        return q[0] > o->p[0][0] && q[0] < o->p[1][0] && q[1] > o->p[0][1] && q[1] < o->p[1][1] &&
               q[2] > o->p[0][2] && q[2] < o->p[1][2];
    return false;
}

static void cross3(const double a[3], const double b[3], double r[3])
{
    r[0] = a[1] * b[2] - a[2] * b[1];
    r[1] = a[2] * b[0] - a[0] * b[2];
    r[2] = a[0] * b[1] - a[1] * b[0];
}

/* The colour (1/255 units, clamped) of the ray's nearest hit; background 0. */
static void ref_shade(const scene_t *s, const double org[3], const double d[3], double out[3])
{
    double tbest = INFINITY, n[3] = {0, 0, 0};
    int best = -1;
    for (int j = 0; j < s->n_obj; j++) {
        double t, nn[3];
        if (ref_hit(&s->obj[j], org, d, 1e-9, &t, nn) && t < tbest) {
            tbest = t;
            best = j;
            memcpy(n, nn, sizeof nn);
        }
    }
    out[0] = out[1] = out[2] = 0;
    if (best < 0)
        return;
    const obj_t *o = &s->obj[best];
    double p[3], e[3], cd[3];
    for (int i = 0; i < 3; i++) {
        p[i] = org[i] + tbest * d[i];
        e[i] = -d[i];
        cd[i] = chan(o->color[i]);
    }
    bool inside = dot(n, d) > 0;
    if (inside)
        for (int i = 0; i < 3; i++)
            n[i] = -n[i];
    double nf[3] = {n[0], n[1], n[2]}; /* the flat face's normal, turned to the ray */
    if (s->smooth[best]) {
        /* Barycentric weights from 3D triple products (the core projects
         * onto a plane instead), then n = normalise(sum w_k n_k), turned
         * towards the ray on its own. */
        const double *a = o->p[0], *b = o->p[1], *c = o->p[2];
        double ab[3], ac[3], A[3], w[3];
        for (int i = 0; i < 3; i++)
            ab[i] = b[i] - a[i], ac[i] = c[i] - a[i];
        cross3(ab, ac, A);
        const double *q[3][2] = {{b, c}, {c, a}, {a, b}};
        for (int k = 0; k < 3; k++) {
            double u[3], v[3], x[3];
            for (int i = 0; i < 3; i++)
                u[i] = q[k][0][i] - p[i], v[i] = q[k][1][i] - p[i];
            cross3(u, v, x);
            w[k] = dot(x, A) / dot(A, A);
        }
        double ns[3] = {0, 0, 0};
        for (int k = 0; k < 3; k++) {
            double vk[3] = {s->vn[best][k][0], s->vn[best][k][1], s->vn[best][k][2]};
            unit(vk);
            for (int i = 0; i < 3; i++)
                ns[i] += w[k] * vk[i];
        }
        unit(ns);
        double sg = dot(ns, d) > 0 ? -1 : 1;
        for (int i = 0; i < 3; i++)
            n[i] = sg * ns[i];
    }
    if (o->material == MATERIAL_FLAT) {
        memcpy(out, cd, sizeof cd);
        return;
    }
    for (int i = 0; i < 3; i++)
        out[i] = cd[i] * s->ambient[i];
    for (int k = 0; k < s->n_lights; k++) {
        const lgt_t *L = &s->light[k];
        double l[3], dist = INFINITY;
        if (L->kind == LIGHT_DIRECTIONAL) {
            for (int i = 0; i < 3; i++)
                l[i] = -L->dir[i];
        } else {
            for (int i = 0; i < 3; i++)
                l[i] = L->pos[i] - p[i];
            dist = sqrt(dot(l, l));
        }
        unit(l);
        if (L->kind == LIGHT_SPOT) {
            double sd[3] = {L->dir[0], L->dir[1], L->dir[2]}, ml[3] = {-l[0], -l[1], -l[2]};
            unit(sd);
            if (dot(ml, sd) < cos(L->angle * 3.14159265358979323846 / 180))
                continue;
        }
        double ndl = dot(n, l);
        if (ndl <= 0)
            continue;
        if (s->smooth[best] && L->shadows && dot(nf, l) <= 0)
            continue; /* the terminator: behind the flat face */
        if (L->shadows) {
            bool blocked = false;
            bool solid = o->kind == GEOM_SPHERE || o->kind == GEOM_BOX;
            if (inside && solid && !(L->kind != LIGHT_DIRECTIONAL && ref_inside(o, L->pos)))
                blocked = true;
            for (int j = 0; j < s->n_obj && !blocked; j++) {
                double t, nn[3];
                if (j != best && ref_hit(&s->obj[j], p, l, 1e-9, &t, nn) && t < dist)
                    blocked = true;
            }
            if (blocked)
                continue;
        }
        for (int i = 0; i < 3; i++)
            out[i] += cd[i] * L->color[i] * ndl;
        if (o->material == MATERIAL_PHONG) {
            double r[3];
            for (int i = 0; i < 3; i++)
                r[i] = 2 * ndl * n[i] - l[i];
            double rde = dot(r, e);
            if (rde > 0)
                for (int i = 0; i < 3; i++)
                    out[i] += 255.0 * o->specular[i] * L->color[i] * pow(fmin(rde, 1.0), o->exponent);
        }
    }
    for (int i = 0; i < 3; i++)
        out[i] = fmin(255.0, fmax(0.0, out[i]));
}

/* ---- the core's render --------------------------------------------------------- */

static world_t world;
static render_t rnd;
static cam_t cam;
static uint8_t img[H][W][3];

/* A core bug found here, fixed: world_add_* did not reset an object's
 * material, so an object added to a re-initialised world kept the
 * material of the object that was in its slot before, and n_lit went
 * wrong. probe_material_reset checks the fix (SHADE_MAT_RESET_FIXED 0
 * would only report it). */
#ifndef SHADE_MAT_RESET_FIXED
#define SHADE_MAT_RESET_FIXED 1
#endif

static bool build(const scene_t *s, int w, int h)
{
    if (fxrt_world_init(&world, color_make(NUM_ZERO, NUM_ZERO, NUM_ZERO)) != FXRT_OK)
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
        fo.material.exponent = (uint16_t)o->exponent;
        fo.material.specular = color_make(N(chan(o->specular[0])), N(chan(o->specular[1])), N(chan(o->specular[2])));
        FXRT_IF_SMOOTH(fo.smooth = s->smooth[j]; for (int k = 0; k < 3; k++) fo.vn[k] = V(s->vn[j][k]);)
        if (fxrt_add(&world, &fo) != j)
            return false;
    }
    for (int k = 0; k < s->n_lights; k++) {
        const lgt_t *L = &s->light[k];
        fxrt_light_t fl = {L->kind, V(L->pos), V(L->dir), N(L->angle),
                           color_make(N(chan(L->color[0])), N(chan(L->color[1])), N(chan(L->color[2]))), L->shadows};
        if (fxrt_add_light(&world, &fl) != k)
            return false;
    }
    if (world_set_ambient(&world, color_make(N(s->ambient[0]), N(s->ambient[1]), N(s->ambient[2]))) != FXRT_OK)
        return false;
    if (fxrt_camera_perspective(&cam, V(s->eye), V(s->gaze), V(s->up), N(s->fov), w, h) != FXRT_OK)
        return false;
    return fxrt_render_setup(&rnd, &world, &cam) == FXRT_OK;
}

/* Render the scene at W x H; compare every pixel with the reference. */
static void check_frame(const char *name, const scene_t *s)
{
    CHECK_MSG(build(s, W, H), "%s: set-up refused (%s)", name, fxrt_render_error(&rnd) ? fxrt_render_error(&rnd) : "");
    for (int y = 0; y < H; y++)
        CHECK(fxrt_render_row(&rnd, y, &img[y][0][0], sizeof img[y]) == FXRT_OK);
    static double ref[H][W][3];
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            ray_t r;
            cam_ray(&cam, x, H - 1 - y, &r); /* row 0 is the top: cam_ray's y = H - 1 */
            double o[3] = {D(r.o.x), D(r.o.y), D(r.o.z)}, d[3] = {D(r.d.x), D(r.d.y), D(r.d.z)};
            unit(d);
            ref_shade(s, o, d, ref[y][x]);
        }
    int within = 0, lit = 0, bad = 0;
    double worst = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            double e = 0, jump = 0;
            for (int i = 0; i < 3; i++) {
                e = fmax(e, fabs(img[y][x][i] - ref[y][x][i]));
                if (ref[y][x][i] > 0)
                    lit++;
            }
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
            }
        }
    printf("%s (%s, %dx%d): %d of %d pixels within 2/255 of the double reference, %d smooth pixels beyond "
           "(worst %.0f/255)\n",
           name, NUM_NAME, W, H, within, W * H, bad, worst);
    CHECK_MSG(within >= W * H * 98 / 100, "%s: only %d of %d pixels within 2/255", name, within, W * H);
    CHECK_MSG(bad == 0, "%s: %d pixels away from discontinuities beyond 2/255 (worst %.0f)", name, bad, worst);
    CHECK_MSG(lit > W * H / 2, "%s: the frame is mostly black (%d lit channels)", name, lit);
}

static void probe_material_reset(void)
{
    material_t m = {.kind = MATERIAL_PHONG, .exponent = 8, .specular = color_make(NUM_ONE, NUM_ONE, NUM_ONE)};
    color_t grey = color_make(N(chan(0.5)), N(chan(0.5)), N(chan(0.5)));
    fxrt_world_init(&world, grey);
    int32_t id = world_add_sphere(&world, vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO), NUM_ONE, grey);
    world_set_material(&world, id, &m);
    fxrt_world_init(&world, grey);
    id = world_add_sphere(&world, vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO), NUM_ONE, grey);
    bool flat = world_common(&world, GEOM_SPHERE, 0)->mat.kind == MATERIAL_FLAT && world.n_lit == 0;
    if (!flat)
        printf("KNOWN CORE BUG: an object added to a re-initialised world keeps the previous object's material "
               "(material %d, n_lit %d); world_add_* should set MATERIAL_FLAT\n",
               world_common(&world, GEOM_SPHERE, 0)->mat.kind, world.n_lit);
    if (SHADE_MAT_RESET_FIXED)
        CHECK_MSG(flat, "an added object is not flat");
}

/* The pixel at the image centre of a 1 x 1 render (the ray through the
 * centre is the gaze), against an expected colour. */
static void check_centre(const char *name, const scene_t *s, const double expect[3])
{
    CHECK_MSG(build(s, 1, 1), "%s: set-up refused", name);
    uint8_t px[3];
    CHECK(fxrt_render_row(&rnd, 0, px, sizeof px) == FXRT_OK);
    double e = 0;
    for (int i = 0; i < 3; i++)
        e = fmax(e, fabs(px[i] - expect[i]));
    CHECK_MSG(e <= 1.0, "%s: pixel %d %d %d, expected %.2f %.2f %.2f", name, px[0], px[1], px[2], expect[0],
              expect[1], expect[2]);
}

static void set3(double v[3], double x, double y, double z)
{
    v[0] = x;
    v[1] = y;
    v[2] = z;
}

static scene_t course(int material)
{
    scene_t s;
    memset(&s, 0, sizeof s);
    set3(s.eye, 4, 4, 4);
    set3(s.gaze, -1, -1, -1);
    set3(s.up, 0, 1, 0);
    s.fov = 45;
    set3(s.ambient, 0.1, 0.1, 0.1);
    obj_t *o = s.obj;
    o[0] = (obj_t){GEOM_PLANE, {{0, 0, 0}, {0, 1, 0}}, 0, {1, 0, 0}, 0, {0, 0, 0}, 0, {0, 0, 0}, 0};
    o[1] = (obj_t){GEOM_SPHERE, {{1, 1, 1}}, 0.5, {0, 1, 0}, 0, {0, 0, 0}, 0, {0, 0, 0}, 0};
    o[2] = (obj_t){GEOM_BOX, {{-1.5, 0.5, 0.5}, {-0.5, 1.5, 1.5}}, 0, {0, 0, 1}, 0, {0, 0, 0}, 0, {0, 0, 0}, 0};
    o[3] = (obj_t){GEOM_TRIANGLE, {{0, 0, -1}, {1, 0, -1}, {1, 1, -1}}, 0, {1, 1, 0}, 0, {0, 0, 0}, 0, {0, 0, 0}, 0};
    s.n_obj = 4;
    for (int j = 0; j < 4; j++) {
        o[j].material = material;
        set3(o[j].specular, 1, 1, 1);
        o[j].exponent = 64;
    }
    s.light[0] = (lgt_t){LIGHT_POINT, {4, 4, 4}, {0, 0, 0}, 0, {1, 1, 1}, true};
    s.light[1] = (lgt_t){LIGHT_DIRECTIONAL, {0, 0, 0}, {-1, -1, -1}, 0, {0.5, 0.5, 0.5}, false};
    s.light[2] = (lgt_t){LIGHT_SPOT, {4, 4, 4}, {-1, -1, -1}, 180.0 / 14, {0.7, 0.7, 0.7}, true};
    s.n_lights = 3;
    return s;
}

#include "../core/light/shade.h"

/* Random numbers for the sweeps below (deterministic). */
static uint64_t spot_rng_state = 0x9e3779b97f4a7c15u;
static double spot_rand(void)
{
    spot_rng_state = spot_rng_state * 6364136223846793005u + 1442695040888963407u;
    return (double)(spot_rng_state >> 11) / 9007199254740992.0; /* [0, 1) */
}
static void spot_unit(double u[3])
{
    double n;
    do {
        for (int i = 0; i < 3; i++)
            u[i] = 2 * spot_rand() - 1;
        n = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    } while (n < 0.1 || n > 1);
    for (int i = 0; i < 3; i++)
        u[i] /= n;
}

/* Lambert planes, whose light sum takes n . l from the light's height over
 * the plane (light/shade.c, shade_lights_plane): random planes (every
 * normal, through points near the origin), seen from either side, lit by
 * point, spot and directional lights on either side, with shadows on or off, a sphere
 * casting them, random colours and ambient; each frame against the
 * reference. The eye looks at the plane within 60 degrees of its normal,
 * so the plane fills the view. */
static void test_lambert_planes(void)
{
    long bad_frames = 0;
    int sides[2] = {0, 0}, kinds[2] = {0, 0};
    for (int view = 0; view < 24; view++) {
        scene_t m;
        memset(&m, 0, sizeof m);
        double n[3], e[3], c[3], l[3];
        spot_unit(n);
        do
            spot_unit(e);
        while (fabs(e[0] * n[0] + e[1] * n[1] + e[2] * n[2]) < 0.5);
        double dist = 4 + 2 * spot_rand(), off = spot_rand() - 0.5;
        set3(m.eye, e[0] * dist, e[1] * dist, e[2] * dist);
        set3(m.gaze, -m.eye[0], -m.eye[1], -m.eye[2]);
        set3(m.up, fabs(e[1]) > 0.9 ? 1 : 0, fabs(e[1]) > 0.9 ? 0 : 1, 0);
        m.fov = 40;
        set3(m.ambient, 0.3 * spot_rand(), 0.3 * spot_rand(), 0.3 * spot_rand());
        m.obj[0] = (obj_t){GEOM_PLANE, {{n[0] * off, n[1] * off, n[2] * off}, {n[0], n[1], n[2]}}, 0,
                           {0.05 + 0.95 * spot_rand(), 0.05 + 0.95 * spot_rand(), 0.05 + 0.95 * spot_rand()},
                           MATERIAL_LAMBERT, {0, 0, 0}, 0, {0, 0, 0}, 0};
        spot_unit(c);
        double rs = 0.2 + 0.3 * spot_rand(), cs = spot_rand();
        m.obj[1] = (obj_t){GEOM_SPHERE, {{c[0] * cs, c[1] * cs, c[2] * cs}}, rs,
                           {spot_rand(), spot_rand(), spot_rand()}, view % 3 ? MATERIAL_LAMBERT : MATERIAL_FLAT,
                           {0, 0, 0}, 0, {0, 0, 0}, 0};
        m.n_obj = 2;
        spot_unit(l);
        double ld = 1.5 + 3.5 * spot_rand();
        bool spot = view % 4 == 3, dir = view % 4 == 1;
        m.light[0] = (lgt_t){spot ? LIGHT_SPOT : dir ? LIGHT_DIRECTIONAL : LIGHT_POINT, {l[0] * ld, l[1] * ld, l[2] * ld},
                             {-l[0], -l[1], -l[2]}, spot ? 30 + 40 * spot_rand() : 0,
                             {0.3 + 0.7 * spot_rand(), 0.3 + 0.7 * spot_rand(), 0.3 + 0.7 * spot_rand()}, view % 5 != 4};
        m.n_lights = 1;
        /* the eye's side and the light's side of the plane, for the count */
        double he = 0, hl = 0;
        for (int i = 0; i < 3; i++) {
            he += n[i] * (m.eye[i] - n[i] * off);
            hl += n[i] * (dir ? l[i] : m.light[0].pos[i] - n[i] * off);
        }
        sides[he > 0]++;
        kinds[(he > 0) == (hl > 0)]++;
        long before = check_failed_count;
        char name[80];
        snprintf(name, sizeof name, "lambert plane %d (%s light, %s side)", view, spot ? "spot" : dir ? "directional" : "point",
                 (he > 0) == (hl > 0) ? "lit" : "dark");
        check_frame(name, &m);
        bad_frames += check_failed_count != before;
    }
    CHECK_MSG(bad_frames == 0, "%ld of 24 lambert planes off the reference", bad_frames);
    CHECK_MSG(sides[0] > 2 && sides[1] > 2 && kinds[0] > 2 && kinds[1] > 2,
              "the planes are seen from both sides (%d, %d) and lit from both (%d, %d)", sides[0], sides[1], kinds[0],
              kinds[1]);
}

/* Sweep k's random spot (the two spot sweeps below): at a scale of 8000,
 * 100 or 2 (*scale) from the origin (pos), aimed along unit s, of
 * half-angle 90 (every tenth) or from min_angle to 90 degrees (*angle),
 * in a world of its own; NULL where the world refuses it. */
static const light_t *spot_random(int k, double min_angle, double pos[3], double s[3], double *scale, double *angle)
{
    static world_t w;
    *scale = k % 3 == 0 ? 8000 : k % 3 == 1 ? 100 : 2;
    for (int i = 0; i < 3; i++)
        pos[i] = (2 * spot_rand() - 1) * *scale;
    spot_unit(s);
    *angle = k % 10 == 0 ? 90 : min_angle + (90 - min_angle) * spot_rand();
    fxrt_world_init(&w, color_make(NUM_ZERO, NUM_ZERO, NUM_ZERO));
    double dir[3] = {s[0] * 1000, s[1] * 1000, s[2] * 1000};
    int32_t li = world_add_light(&w, LIGHT_SPOT, V(pos), V(dir), N(*angle), color_make(NUM_ONE, NUM_ONE, NUM_ONE),
                                 false);
    return li < 0 ? NULL : &w.lights[li];
}

#if FXRT_NUMBER == FXRT_Q16
/* shade_spot_surely_out, the light loop's cheap early test for a spot's
 * cone, against the cone test it stands in front of: (-v) . s >= cos |v|
 * with |v| from fx_normalize3_len and s, cos in Q2.30, as shade_lights
 * makes it. Random spots (every direction, half-angles from 0.05 to 90
 * degrees) and points both anywhere and within 0.01 degree of the cone's
 * edge at every distance; the early test must never say "out" where the
 * full one says "in", and must catch the points well outside. */
static void test_spot_early_out(void)
{
    long wrong = 0, far_out = 0, far_caught = 0, edge = 0, edge_out = 0;
    for (int k = 0; k < 200000; k++) {
        double pos[3], s[3], q[3], pp[3], scale, angle;
        const light_t *L = spot_random(k, 0.05, pos, s, &scale, &angle);
        if (!L) {
            wrong++;
            continue;
        }
        /* a point near the edge (theta = angle +- 0.01 degree) or anywhere */
        bool near_edge = k % 2 == 0;
        double dist = exp(log(1e-3) + spot_rand() * (log(20000.0) - log(1e-3)));
        if (near_edge) {
            spot_unit(q); /* q - (q . s) s: a direction across the axis */
            double qs = q[0] * s[0] + q[1] * s[1] + q[2] * s[2], n = 0;
            for (int i = 0; i < 3; i++)
                q[i] -= qs * s[i], n += q[i] * q[i];
            n = sqrt(n);
            double th = (angle + (2 * spot_rand() - 1) * 0.01) * (3.14159265358979323846 / 180);
            for (int i = 0; i < 3; i++)
                pp[i] = pos[i] + dist * (cos(th) * s[i] + sin(th) * q[i] / n);
        } else {
            spot_unit(q);
            for (int i = 0; i < 3; i++)
                pp[i] = pos[i] + dist * q[i];
        }
        if (fabs(pp[0]) > 32000 || fabs(pp[1]) > 32000 || fabs(pp[2]) > 32000)
            continue;
        vec3_t p = V(pp);
        vec3_t v = vec3_sub(L->position, p);
        bool early = shade_spot_surely_out(L, v);
        fx_t u[3] = {v.x, v.y, v.z}, len;
        if (!fx_normalize3_len(u, &len))
            continue;
        int64_t lhs = -((int64_t)v.x * L->axis30[0] + (int64_t)v.y * L->axis30[1] + (int64_t)v.z * L->axis30[2]);
        bool in = len < SHADE_FAR_DIST && lhs >= (int64_t)len * L->cos30;
        wrong += early && in;
        /* the exact angle of the point off the axis, in double */
        double vv[3] = {pp[0] - pos[0], pp[1] - pos[1], pp[2] - pos[2]};
        double vn = sqrt(vv[0] * vv[0] + vv[1] * vv[1] + vv[2] * vv[2]);
        double cosang = (vv[0] * s[0] + vv[1] * s[1] + vv[2] * s[2]) / vn;
        double off = acos(cosang > 1 ? 1 : cosang < -1 ? -1 : cosang) * (180 / 3.14159265358979323846);
        if (!near_edge && off > angle + 1 && vn > 0.05 && vn < 16000) {
            far_out++;
            far_caught += early;
        }
        if (near_edge) {
            edge++;
            edge_out += early;
        }
    }
    printf("spot early test: %ld of %ld points over 1 degree outside caught, %ld of %ld points within 0.01 degree "
           "of the edge (the full test decides the rest), %ld wrong\n",
           far_caught, far_out, edge_out, edge, wrong);
    CHECK_MSG(wrong == 0, "spot early test: %ld points it puts outside are inside the cone", wrong);
    CHECK_MSG(far_out > 10000 && far_caught == far_out, "spot early test caught %ld of %ld points over 1 degree outside",
              far_caught, far_out);
    CHECK_MSG(edge > 10000 && edge_out > 0 && edge_out < edge, "spot early test: %ld of %ld edge points out", edge_out, edge);
}
#endif

/* shade_spot_block_out, which lets a block of a plane's run skip every
 * pixel's spot cone test, against that test itself (the pixel's: in
 * Q16.16 (-v) . s >= cos |v| with |v| from fx_normalize3_len and s, cos
 * in Q2.30; in float and double (-v) . s >= cos |v| in their arithmetic).
 * Random spots (every direction, half-angles 1 to 90 degrees, at scales
 * 2, 100 and 8000), and segments from the light's distance 0.01 to 8000,
 * of lengths from 1e-4 to 10 units, placed anywhere or crossing the cone's
 * edge. Wherever the block test says "out", 33 points along the segment,
 * each moved by up to the computed points' error (4 LSB per coordinate in
 * Q16.16, 2^-22 of the scale in float and double), must be outside by the
 * pixel's test; and it must say "out" for most short segments far outside
 * (over 10 degrees off the cone, shorter than 1 % of the distance). */
static bool spot_pixel_in(const light_t *L, vec3_t p)
{
    vec3_t v = vec3_sub(L->position, p);
#if FXRT_NUMBER == FXRT_Q16
    fx_t u[3] = {v.x, v.y, v.z}, len;
    if (!fx_normalize3_len(u, &len))
        return false;
    int64_t lhs = -((int64_t)v.x * L->axis30[0] + (int64_t)v.y * L->axis30[1] + (int64_t)v.z * L->axis30[2]);
    return len < SHADE_FAR_DIST && lhs >= (int64_t)len * L->cos30;
#else
    numw_t v2 = vec3_dotw(v, v);
    if (!(v2 > 0))
        return false;
    return vec3_dotw(vec3_neg(v), L->dir) >= numw_mul(L->cos_angle, numw_sqrt(v2));
#endif
}
static void test_spot_block_out(void)
{
    long wrong = 0, said = 0, far = 0, far_caught = 0, tried = 0;
    for (int k = 0; k < 40000; k++) {
        double pos[3], s[3], q[3], pa[3], pb[3], o[3] = {0, 0, 0}, scale, angle;
        const light_t *L = spot_random(k, 1, pos, s, &scale, &angle);
        if (!L)
            continue; /* (a light the world refuses: none to test) */
        /* the segment's middle at an angle off the axis: near the edge
         * (within 5 degrees) or anywhere */
        double dist = exp(log(1e-2) + spot_rand() * (log(8000.0) - log(1e-2)));
        double len = exp(log(1e-4) + spot_rand() * (log(10.0) - log(1e-4)));
        spot_unit(q);
        double qs = q[0] * s[0] + q[1] * s[1] + q[2] * s[2], n = 0, m[3], t[3];
        for (int i = 0; i < 3; i++)
            q[i] -= qs * s[i], n += q[i] * q[i];
        n = sqrt(n);
        double th = (k % 2 ? angle + (2 * spot_rand() - 1) * 5 : 180 * spot_rand()) * (3.14159265358979323846 / 180);
        for (int i = 0; i < 3; i++)
            m[i] = pos[i] + dist * (cos(th) * s[i] + sin(th) * q[i] / n);
        spot_unit(t);
        for (int i = 0; i < 3; i++)
            pa[i] = m[i] - 0.5 * len * t[i], pb[i] = m[i] + 0.5 * len * t[i];
        bool range = true;
        for (int i = 0; i < 3; i++)
            range = range && fabs(pa[i]) < 16000 && fabs(pb[i]) < 16000;
        if (!range)
            continue;
        tried++;
        vec3_t A = V(pa), B = V(pb), O = V(o);
        bool out = shade_spot_block_out(L, &O, &A, &B, NUM_ZERO);
        if (out) {
            said++;
            for (int j = 0; j <= 32; j++) {
                double pp[3];
                for (int i = 0; i < 3; i++) {
                    double a = D(i == 0 ? A.x : i == 1 ? A.y : A.z);
                    double b = D(i == 0 ? B.x : i == 1 ? B.y : B.z);
#if FXRT_NUMBER == FXRT_Q16
                    double wob = (double)((int)(spot_rand() * 9) - 4) / 65536;
#else
                    double wob = (2 * spot_rand() - 1) * scale / 4194304;
#endif
                    pp[i] = a + (b - a) * j / 32 + wob;
                }
                wrong += spot_pixel_in(L, V(pp));
            }
        }
        /* the angle off the axis of the segment's two ends, in double */
        double off_min = 180;
        for (int e = 0; e < 2; e++) {
            const double *p = e ? pb : pa;
            double vv[3] = {p[0] - pos[0], p[1] - pos[1], p[2] - pos[2]};
            double vn = sqrt(vv[0] * vv[0] + vv[1] * vv[1] + vv[2] * vv[2]);
            double c = (vv[0] * s[0] + vv[1] * s[1] + vv[2] * s[2]) / vn;
            double off = acos(c > 1 ? 1 : c < -1 ? -1 : c) * (180 / 3.14159265358979323846);
            off_min = off < off_min ? off : off_min;
        }
        if (angle < 80 && off_min > angle + 10 && off_min < 170 && len < 0.01 * dist && dist > 0.05) {
            far++;
            far_caught += out;
        }
    }
    printf("spot block test: %ld of %ld segments said out (%ld of %ld short ones over 10 degrees outside), "
           "%ld points of them inside\n", said, tried, far_caught, far, wrong);
    CHECK_MSG(wrong == 0, "spot block test: %ld points of segments it puts outside are inside the cone", wrong);
    CHECK_MSG(far > 2000 && far_caught * 10 >= far * 9, "spot block test caught %ld of %ld short segments far outside",
              far_caught, far);
}

#if SHADOW_CULL
/* Shadow-ray culling (core/light/shadow.c) must change no decision of a right
 * kernel: for random occluders (a sphere, a triangle and a box at scales
 * 2, 64 and 8000), lights of every kind (a point light just outside the
 * sphere in every other world) and points both anywhere and placed so
 * that the shadow ray grazes an occluder's outline (within a few LSB of
 * Q16.16, up to 20,000 units beyond it), shadow_blocked with the frame's
 * cull row gives the answer it gives without one, except where the kernel
 * that found the hit is wrong: the ray passes, in double, outside that
 * object's bound (counted apart; docs/ACCURACY.md). l and the distance
 * are formed as shade_lights forms them.
 * The culling must also do its job: it must skip most exact tests of the
 * random points, and the grazing points must be blocked often enough
 * (both ways) for the check to mean something. */
static double cull_pick(double lo, double hi) { return lo + (hi - lo) * spot_rand(); }
/* The cone test of core/light/shadow.c as the host build makes it. */
static bool cone_out(const shadow_cull_t *e, const vec3_t *l)
{
#if FXRT_NUMBER == FXRT_Q16
    return shadow_cone_out64(e, l);
#else
    return vec3_dotw_unit(*l, e->pt.u) > numw_from(e->pt.lim);
#endif
}
/* The unit vector l towards point or spot light L from p and the
 * distance, as shade_lights forms them (light/shade.c); false where the
 * light loop casts no shadow ray from p (the light at p, or in Q16.16 on
 * the far path). */
static bool light_towards(const light_t *L, vec3_t p, vec3_t *l, num_t *dist)
{
    if (L->kind == LIGHT_DIRECTIONAL) {
        *l = L->dir; /* normalised once, in world_add_light */
        *dist = NUM_MAX;
        return true;
    }
    vec3_t v = vec3_sub(L->position, p);
#if FXRT_NUMBER == FXRT_Q16
    return vec3_unit_len(v, l, dist) && *dist < SHADE_FAR_DIST;
#else
    *dist = vec3_len(v);
    if (*dist == NUM_ZERO)
        return false;
    *l = vec3_scale(v, num_div(NUM_ONE, *dist));
    return true;
#endif
}

/* The distance from triangle tv to the point where the line o + t d
 * crosses its plane (double; a line parallel to it: infinity). */
static double tri_dist(const double *tv[3], const double o[3], const double d[3])
{
    double e1[3], e2[3], n[3], ao[3];
    for (int i = 0; i < 3; i++)
        e1[i] = tv[1][i] - tv[0][i], e2[i] = tv[2][i] - tv[0][i], ao[i] = tv[0][i] - o[i];
    n[0] = e1[1] * e2[2] - e1[2] * e2[1], n[1] = e1[2] * e2[0] - e1[0] * e2[2], n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    double dn = dot(d, n);
    if (dn == 0)
        return INFINITY;
    double t = dot(ao, n) / dn, x[3], best = INFINITY;
    for (int i = 0; i < 3; i++)
        x[i] = o[i] + t * d[i];
    bool in = true;
    for (int e = 0; e < 3; e++) {
        const double *a = tv[e], *b = tv[(e + 1) % 3];
        double ab[3], ax[3], c[3], ab2, s;
        for (int i = 0; i < 3; i++)
            ab[i] = b[i] - a[i], ax[i] = x[i] - a[i];
        c[0] = ab[1] * ax[2] - ab[2] * ax[1], c[1] = ab[2] * ax[0] - ab[0] * ax[2], c[2] = ab[0] * ax[1] - ab[1] * ax[0];
        in = in && dot(c, n) >= 0;
        ab2 = dot(ab, ab);
        s = ab2 > 0 ? fmin(fmax(dot(ax, ab) / ab2, 0), 1) : 0;
        double q[3] = {ax[0] - s * ab[0], ax[1] - s * ab[1], ax[2] - s * ab[2]};
        best = fmin(best, sqrt(dot(q, q)));
    }
    return in ? 0 : best;
}

static void test_shadow_cull(long cases)
{
    static world_t w;
    static shadow_table_t tab;
    const shadow_cull_t *table = tab.cull;
    long differ = 0, blocked = 0, graze = 0, graze_blocked = 0, tests = 0, skipped = 0, edge_skips = 0, tri_left = 0;
    long dot16_out = 0, dot16_exact = 0, dot16_wrong = 0, kernel_wrong = 0, kernel_wrong_by[3] = {0, 0, 0};
    long per_world = 200;
    for (long k = 0; k < cases; k += per_world) {
        double scale = (k / per_world) % 3 == 0 ? 2 : (k / per_world) % 3 == 1 ? 64 : 8000;
        double lim = scale > 2000 ? 8000 : scale;
        fxrt_world_init(&w, color_make(NUM_ZERO, NUM_ZERO, NUM_ZERO));
        /* the receiver: a plane (never culled, never its own occluder) */
        double pa[3] = {0, -lim, 0}, pn[3] = {0, 1, 0};
        world_add_plane(&w, V(pa), V(pn), color_make(NUM_ONE, NUM_ONE, NUM_ONE));
        double c[3][3], r[3];
        for (int o = 0; o < 3; o++) {
            r[o] = scale * exp(cull_pick(log(1e-3), log(0.25)));
            for (int i = 0; i < 3; i++)
                c[o][i] = cull_pick(-lim + r[o], lim - r[o]);
        }
        world_add_sphere(&w, V(c[0]), N(r[0]), color_make(NUM_ONE, NUM_ONE, NUM_ONE));
        double ta[3], tb[3], tc[3], bmin[3], bmax[3];
        for (int i = 0; i < 3; i++) {
            ta[i] = c[1][i] + cull_pick(-r[1], r[1]);
            tb[i] = c[1][i] + cull_pick(-r[1], r[1]);
            tc[i] = c[1][i] + cull_pick(-r[1], r[1]);
            double h = r[2] * cull_pick(0.05, 1);
            bmin[i] = c[2][i] - h;
            bmax[i] = c[2][i] + h;
        }
        world_add_triangle(&w, V(ta), V(tb), V(tc), color_make(NUM_ONE, NUM_ONE, NUM_ONE));
        world_add_box(&w, V(bmin), V(bmax), color_make(NUM_ONE, NUM_ONE, NUM_ONE));
        /* Every other world: the point light just outside the sphere (a
         * wide cone, where the distance-dependent margin matters most),
         * and points up to 20,000 units beyond the occluders. */
        bool close = (k / per_world) % 2 == 1, refused[3] = {false, false, false};
        for (int li = 0; li < 3; li++) {
            double pos[3], dir[3];
            for (int i = 0; i < 3; i++)
                pos[i] = cull_pick(-lim, lim);
            spot_unit(dir);
            if (close && li == 0) {
                double gap = r[0] * (1.001 + 0.05 * spot_rand()), u[3];
                spot_unit(u);
                for (int i = 0; i < 3; i++)
                    pos[i] = c[0][i] + u[i] * gap;
                if (fabs(pos[0]) > 8000 || fabs(pos[1]) > 8000 || fabs(pos[2]) > 8000)
                    for (int i = 0; i < 3; i++)
                        pos[i] = c[0][i] - u[i] * gap;
            }
            light_kind_t kind = li == 0 ? LIGHT_POINT : li == 1 ? LIGHT_DIRECTIONAL : LIGHT_SPOT;
            /* (float and double refuse a coordinate below 2^-16 that is
             * not 0, FXRT_ERR_TINY: that light's rays are left out, as
             * w.lights[li] and its cull slots would be another world's) */
            refused[li] = world_add_light(&w, kind, V(pos), V(dir), N(90), color_make(NUM_ONE, NUM_ONE, NUM_ONE), true) != li;
        }
        shadow_cull_setup(&w, &tab);
        for (long j = 0; j < per_world && k + j < cases; j++) {
            int li = (int)(j % 3);
            if (refused[li])
                continue;
            const light_t *L = &w.lights[li];
            bool grazing = j % 2 == 0;
            double pp[3];
            if (grazing) {
                /* a point x on an occluder's outline as seen from the
                 * light (a sphere's tangent circle, a triangle's edge, a
                 * box's edge), moved by up to 2^-14 (a few LSB at most,
                 * often less), and p beyond it as seen from the light */
                int o = (int)((j / 2) % 3);
                double x[3], g[3], gn = 0;
                for (int i = 0; i < 3; i++)
                    g[i] = L->kind == LIGHT_DIRECTIONAL ? -D(geom_axis(L->dir, i))
                                                        : c[o][i] - D(geom_axis(L->position, i));
                if (o == 0) {
                    double u[3], ug = 0, un = 0, gg = g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
                    spot_unit(u);
                    for (int i = 0; i < 3; i++)
                        ug += u[i] * g[i];
                    for (int i = 0; i < 3; i++)
                        u[i] -= ug / gg * g[i], un += u[i] * u[i];
                    for (int i = 0; i < 3; i++)
                        x[i] = c[0][i] + u[i] / sqrt(un) * r[0];
                } else if (o == 1) {
                    const double *vs[3] = {ta, tb, tc};
                    int e = (int)(spot_rand() * 3) % 3;
                    double a = spot_rand();
                    for (int i = 0; i < 3; i++)
                        x[i] = vs[e][i] + a * (vs[(e + 1) % 3][i] - vs[e][i]);
                } else {
                    int ax = (int)(spot_rand() * 3) % 3;
                    for (int i = 0; i < 3; i++)
                        x[i] = i == ax ? cull_pick(bmin[i], bmax[i]) : spot_rand() < 0.5 ? bmin[i] : bmax[i];
                }
                double nudge = ldexp(1, -14 - (int)(spot_rand() * 12));
                for (int i = 0; i < 3; i++)
                    x[i] += cull_pick(-1, 1) * nudge;
                for (int i = 0; i < 3; i++) {
                    g[i] = L->kind == LIGHT_DIRECTIONAL ? -D(geom_axis(L->dir, i)) : x[i] - D(geom_axis(L->position, i));
                    gn += g[i] * g[i];
                }
                gn = sqrt(gn);
                double along = close ? exp(cull_pick(log(1e-3), log(20000.0)))
                                     : scale * exp(cull_pick(log(1e-4), log(4.0)));
                for (int i = 0; i < 3; i++)
                    pp[i] = x[i] + g[i] / gn * along;
            } else {
                for (int i = 0; i < 3; i++)
                    pp[i] = cull_pick(-2 * lim, 2 * lim);
            }
            if (fabs(pp[0]) > 30000 || fabs(pp[1]) > 30000 || fabs(pp[2]) > 30000)
                continue;
            vec3_t p = V(pp), l;
            num_t dist;
            if (!light_towards(L, p, &l, &dist))
                continue;
            const shadow_cull_t *row = table + (size_t)li * SHADOW_CULL_SLOTS;
            const shadow_edge_t *edges = SHADOW_EDGES ? tab.edges + (size_t)li * FXRT_MAX_TRIANGLES : NULL;
            bool full = shadow_blocked(&w, GEOM_PLANE, 0 GEOM_PART_ARG(NULL), &w.planes[0].obj, false, &p, L, &l, dist, NULL, 0, NULL);
            bool culled = shadow_blocked(&w, GEOM_PLANE, 0 GEOM_PART_ARG(NULL), &w.planes[0].obj, false, &p, L, &l, dist, row, 0, edges);
            tests++;
            if (full != culled) {
                /* Culling may only skip an occluder whose bounding sphere
                 * the ray misses. When the exact kernel finds a hit
                 * although the ray, in double, passes more than R' (the
                 * cull's own bound, shadow.c) from every bounding sphere,
                 * the kernel is wrong and culling right: counted apart
                 * (docs/ACCURACY.md: saturation and rounding noise of the
                 * exact kernels far from the object). */
                double o[3] = {D(p.x), D(p.y), D(p.z)}, d[3] = {D(l.x), D(l.y), D(l.z)};
                double tm = L->kind == LIGHT_DIRECTIONAL ? 1e30 : D(dist), dd = dot(d, d);
                bool near = false;
                ray_t sray = {p, l};
                bool kernel_hit[3] = {
                    geom_sphere_occludes(&w.spheres[0], &sray, dist),
                    geom_triangle_occludes(&w.triangles[0], &sray, dist),
                    geom_box_occludes(&w.boxes[0], &sray, dist),
                };
                for (int ob = 0; ob < 3; ob++) {
                    if (!kernel_hit[ob])
                        continue; /* only an occluder its kernel finds can be culled wrongly */
                    double bc[3], br = 0;
                    const double *tv[3] = {ta, tb, tc};
                    for (int i = 0; i < 3; i++) {
                        if (ob == 0) {
                            bc[i] = D(geom_axis(w.spheres[0].center, i));
                        } else if (ob == 1) {
                            double lo = fmin(fmin(tv[0][i], tv[1][i]), tv[2][i]), hi = fmax(fmax(tv[0][i], tv[1][i]), tv[2][i]);
                            bc[i] = (lo + hi) / 2;
                        } else {
                            bc[i] = (D(geom_axis(w.boxes[0].min, i)) + D(geom_axis(w.boxes[0].max, i))) / 2;
                        }
                    }
                    if (ob == 0) {
                        br = D(w.spheres[0].radius);
                    } else if (ob == 1) {
                        for (int v = 0; v < 3; v++) {
                            double e[3] = {tv[v][0] - bc[0], tv[v][1] - bc[1], tv[v][2] - bc[2]};
                            br = fmax(br, sqrt(dot(e, e)));
                        }
                    } else {
                        double e[3] = {D(w.boxes[0].max.x) - bc[0], D(w.boxes[0].max.y) - bc[1], D(w.boxes[0].max.z) - bc[2]};
                        br = sqrt(dot(e, e));
                    }
                    double oc[3] = {bc[0] - o[0], bc[1] - o[1], bc[2] - o[2]};
                    double t = fmin(fmax(dot(oc, d) / dd, 0), tm), q[3];
                    for (int i = 0; i < 3; i++)
                        q[i] = oc[i] - t * d[i];
                    double mu = br / 256 + 1.0 / 1024 + 1e-9 * (fabs(bc[0]) + fabs(bc[1]) + fabs(bc[2]));
                    /* The triangle's shadow edges cull inside its bound: there
                     * the kernel is right where its hit, the ray's crossing
                     * of the triangle's plane, lies within mu of the triangle. */
                    if (ob == 1 && SHADOW_EDGES && L->kind != LIGHT_DIRECTIONAL)
                        near = near || tri_dist(tv, o, d) <= mu;
                    else
                        near = near || sqrt(dot(q, q)) <= br + mu;
                }
                if (near || culled) {
                    differ++;
                    CHECK_SWEEP(full == culled, "light kind %d at scale %g, p (%.9g, %.9g, %.9g): blocked %d, culled %d",
                                L->kind, scale, pp[0], pp[1], pp[2], full, culled);
                } else {
                    kernel_wrong++;
                    for (int ob = 0; ob < 3; ob++)
                        kernel_wrong_by[ob] += kernel_hit[ob];
                }
            }
            blocked += full;
            graze += grazing;
            graze_blocked += grazing && full;
            /* how many of the random points' exact tests the row skips */
            if (!grazing) {
                uint16_t slots[3] = {0, FXRT_MAX_SPHERES, FXRT_MAX_SPHERES + FXRT_MAX_TRIANGLES};
                for (int o = 0; o < 3; o++) {
                    const shadow_cull_t *e = &row[slots[o]];
                    bool skip;
                    if (L->kind == LIGHT_DIRECTIONAL)
                        skip = false; /* counted for point and spot lights only */
                    else
                        skip = dist <= e->pt.d_cap && (dist <= e->pt.d_near || cone_out(e, &l));
                    skipped += skip;
                    /* and of the triangle's tests its cone leaves, how many
                     * its edges skip (from the table's numbers, in double) */
                    if (o == 1 && !skip && SHADOW_EDGES && L->kind != LIGHT_DIRECTIONAL) {
                        const shadow_edge_t *g = &edges[0];
                        bool eskip = false;
                        for (int jj = 0; jj < 3; jj++) {
                            /* (Q16.16: Q2.14 and whole units; the test adds 2^-11) */
                            double q = NUM_EXACT ? 1.0 / 16384 : 1, cap = NUM_EXACT ? (double)g->cap : D(g->cap);
                            double dv = (D(l.x) * g->m[jj][0] + D(l.y) * g->m[jj][1] + D(l.z) * g->m[jj][2]) * q;
                            eskip = eskip || (D(dist) < cap && dv > g->lim[jj] * q + (NUM_EXACT ? 1.0 / 2048 : 0));
                        }
                        tri_left++;
                        edge_skips += eskip;
                    }
                }
            }
#if FXRT_NUMBER == FXRT_Q16
            /* The M0's 32-bit cone test: out only where the exact one is. */
            if (L->kind != LIGHT_DIRECTIONAL) {
                uint16_t slots[3] = {0, FXRT_MAX_SPHERES, FXRT_MAX_SPHERES + FXRT_MAX_TRIANGLES};
                for (int o = 0; o < 3; o++) {
                    const shadow_cull_t *e = &row[slots[o]];
                    /* ldir . u > lim14 2^-14, exactly: u in Q2.30, lim in Q18.14 */
                    int64_t S = (int64_t)l.x * e->pt.u.x + (int64_t)l.y * e->pt.u.y + (int64_t)l.z * e->pt.u.z;
                    bool exact = S > (int64_t)e->pt.lim * ((int64_t)1 << 32);
                    bool out16 = shadow_cone_out16(e, &l);
                    CHECK_SWEEP(!shadow_cone_out64(e, &l) || exact, "64-bit cone test out, exact test in (p %.9g %.9g %.9g)",
                                pp[0], pp[1], pp[2]);
                    dot16_out += out16;
                    if (out16 && !exact) {
                        dot16_wrong++;
                        CHECK_SWEEP(!out16 || exact, "32-bit cone test out, exact test in (p %.9g %.9g %.9g)", pp[0],
                                    pp[1], pp[2]);
                    }
                    dot16_exact += exact;
                }
            }
#endif
        }
    }
    long random_pt = (tests - graze) * 2 / 3; /* random points with a point or spot light, about */
    printf("shadow culling: %ld shadow rays (%ld grazing an occluder, %ld of them blocked; %ld blocked in all), %ld "
           "with another answer when culled; %ld of about %ld exact tests of random points skipped (point and spot); "
           "%ld rays blocked by an exact kernel although they pass outside every bound (culling corrects them)\n",
           tests, graze, graze_blocked, blocked, differ, skipped, 3 * random_pt, kernel_wrong);
    CHECK_MSG(differ == 0, "shadow culling changed %ld of %ld decisions", differ, tests);
    /* Only the triangle's edge test decides tiny triangles far away on
     * rounding (docs/ACCURACY.md); the sphere and box kernels must never
     * report a hit outside the bound. */
    CHECK_MSG(kernel_wrong * 1000 < tests && kernel_wrong_by[0] == 0 && kernel_wrong_by[2] == 0,
              "kernel errors in %ld rays: %ld (sphere %ld, triangle %ld, box %ld)", tests, kernel_wrong,
              kernel_wrong_by[0], kernel_wrong_by[1], kernel_wrong_by[2]);
#if FXRT_NUMBER == FXRT_Q16
    printf("shadow culling, the M0's 32-bit cone test: %ld cones ruled out, the exact test %ld, %ld wrongly\n",
           dot16_out, dot16_exact, dot16_wrong);
    CHECK_MSG(dot16_wrong == 0 && dot16_out > dot16_exact * 9 / 10, "32-bit cone test: %ld out (exact %ld), %ld wrong",
              dot16_out, dot16_exact, dot16_wrong);
#else
    (void)dot16_out, (void)dot16_exact, (void)dot16_wrong;
#endif
    CHECK_MSG(graze_blocked > graze / 10 && graze_blocked < graze * 9 / 10,
              "grazing rays: %ld of %ld blocked (the check needs both answers often)", graze_blocked, graze);
    CHECK_MSG(skipped > 3 * random_pt / 2, "culling skipped only %ld of about %ld exact tests", skipped, 3 * random_pt);
    printf("shadow edges: %ld of the %ld triangle tests the cones leave (random points) skipped\n", edge_skips, tri_left);
    CHECK_MSG(!SHADOW_EDGES || edge_skips * 4 > tri_left, "shadow edges skipped only %ld of %ld triangle tests", edge_skips,
              tri_left);
}
#endif

#if SHADOW_CULL
/* geom_sphere_occludes, the shadow rays' sphere kernel, against double,
 * for origins anywhere a shadow ray can start (hit points up to 32,000
 * from the world's origin; in Q16.16 beyond 16,384 from the centre on an
 * axis it works at a quarter of the scale), towards the sphere (through
 * it, grazing it, missing it), away from it, with a limit before, inside
 * or beyond it, or none (NUM_MAX). The kernel takes d as unit, and a
 * rounded unit d is not, so far from the sphere it may miss a ray that
 * passes within |c - o| 2^-14 of the surface (never a false hit): within
 * that band, and within 2^-12 of t's ends, either answer passes. */
static void test_sphere_occludes(long cases)
{
    static world_t w;
    long wrong = 0, hits = 0, misses = 0, far = 0, undecided = 0;
    for (long k = 0; k < cases; k++) {
        fxrt_world_init(&w, color_make(NUM_ZERO, NUM_ZERO, NUM_ZERO));
        double c[3], r = exp(cull_pick(log(0.01), log(4096.0))), o[3], u[3], aim[3];
        for (int i = 0; i < 3; i++)
            c[i] = cull_pick(-8192 + r, 8192 - r);
        double span = k % 2 ? 32000 : 2000;
        for (int i = 0; i < 3; i++)
            o[i] = cull_pick(-span, span);
        bool across = k % 16 == 5;
        if (across) {
            /* a large sphere and an origin at opposite ends of an axis:
             * c - o beyond Q16.16 (where the unscaled kernel saturates
             * and sees the sphere nearer), the limit just before it */
            int ax = (int)(k / 16 % 3);
            double sg = k / 48 % 2 ? 1 : -1;
            r = cull_pick(1024, 4096);
            for (int i = 0; i < 3; i++)
                c[i] = cull_pick(-8192 + r, 8192 - r), o[i] = cull_pick(-2000, 2000);
            c[ax] = sg * cull_pick(6000, 8192 - r);
            o[ax] = -sg * cull_pick(26000, 32000);
        }
        if (world_add_sphere(&w, V(c), N(r), color_make(NUM_ONE, NUM_ONE, NUM_ONE)) < 0) {
            wrong++;
            CHECK_SWEEP(false, "sphere r %.6g at (%.6g, %.6g, %.6g) refused", r, c[0], c[1], c[2]);
            continue;
        }
        /* aim at a point around the sphere: inside, near its surface, or
         * beside it; every eighth ray points away */
        spot_unit(u);
        double at = r * (k % 3 == 0 ? cull_pick(0, 1) : k % 3 == 1 ? 1 + cull_pick(-1e-3, 1e-3) : cull_pick(1, 3));
        for (int i = 0; i < 3; i++)
            aim[i] = c[i] + u[i] * at - o[i];
        if (k % 8 == 7 && !across)
            for (int i = 0; i < 3; i++)
                aim[i] = -aim[i];
        double an = sqrt(dot(aim, aim));
        if (an == 0)
            continue;
        for (int i = 0; i < 3; i++)
            aim[i] /= an;
        vec3_t dv = V(aim);
        if (!vec3_normalize(&dv))
            continue;
        double oo[3] = {D(N(o[0])), D(N(o[1])), D(N(o[2]))}, dd[3] = {D(dv.x), D(dv.y), D(dv.z)};
        double cc[3] = {D(w.spheres[0].center.x), D(w.spheres[0].center.y), D(w.spheres[0].center.z)};
        double rr = D(w.spheres[0].radius);
        int lim_kind = (int)(k % 4); /* 0: none, 1: before, 2: inside, 3: beyond */
        double oc[3] = {cc[0] - oo[0], cc[1] - oo[1], cc[2] - oo[2]}, ocn = sqrt(dot(oc, oc));
        double tmax = lim_kind == 0 ? 1e30 : ocn * (lim_kind == 1 ? 0.5 : lim_kind == 2 ? 1 : 1.5);
        if (across)
            lim_kind = 1, tmax = cull_pick(ocn - rr - 3000, ocn - rr - 10);
        if (lim_kind != 0 && tmax > 32000)
            tmax = 32000;
        num_t tm = lim_kind == 0 ? NUM_MAX : N(tmax);
        ray_t ray = {V(oo), dv};
        bool got = geom_sphere_occludes(&w.spheres[0], &ray, tm);
        /* double: the ray o + t d (d as the kernel takes it, |d| ~ 1) */
        double dd2 = dot(dd, dd), b = dot(oc, dd) / dd2, q[3];
        for (int i = 0; i < 3; i++)
            q[i] = oc[i] - b * dd[i];
        double dist = sqrt(dot(q, q)), band = ocn * (1.0 / 16384) + 1.0 / 4096;
        double tmx = lim_kind == 0 ? 1e30 : D(tm) / sqrt(dd2);
        bool inside_band = fabs(dist - rr) <= band;
        double h = dist < rr ? sqrt(rr * rr - dist * dist) / sqrt(dd2) : 0;
        double t0 = b - h, t1 = b + h, t = t0 > 0 ? t0 : t1;
        bool want = dist < rr && t > 0 && t < tmx;
        bool edge = inside_band || fabs(t0) <= band || fabs(t1) <= band || (lim_kind != 0 && fabs(t - tmx) <= band);
        far += ocn > 16384;
        if (edge) {
            undecided++;
            continue;
        }
        hits += want;
        misses += !want;
        if (got != want) {
            wrong++;
            CHECK_SWEEP(got == want, "sphere r %.6g at (%.6g, %.6g, %.6g), o (%.6g, %.6g, %.6g), |c - o| %.6g, "
                        "line %.6g from the centre, limit %d: kernel %d, double %d", rr, cc[0], cc[1], cc[2], oo[0], oo[1],
                        oo[2], ocn, dist, lim_kind, got, want);
        }
    }
    printf("geom_sphere_occludes: %ld rays (%ld from more than 16,384 away), %ld hits and %ld misses decided, %ld within "
           "the band, %ld wrong\n", cases, far, hits, misses, undecided, wrong);
    CHECK_MSG(wrong == 0 && hits > cases / 10 && misses > cases / 10 && far > cases / 4,
              "geom_sphere_occludes: %ld wrong (%ld hits, %ld misses, %ld far)", wrong, hits, misses, far);
}
#endif

#if SHADOW_CULL && FXRT_NUMBER == FXRT_Q16
/* The cone tests at their boundary (core/light/shade.h): with u along x in
 * Q2.30 and l = (x, 0, 0), ldir . u = x 2^-16 exactly, and the limit is
 * lim14 2^-14. The high-word test culls only when the dot is strictly
 * above the limit by at least 2^-14, so never at equality; the 32-bit
 * test also keeps its 2^-11 margin. */
static void test_cone_boundary(void)
{
    shadow_cull_t e;
    memset(&e, 0, sizeof e);
    e.pt.u = vec3_make((fx_t)1 << 30, 0, 0);
    long wrong = 0, n = 0;
    for (int32_t lim14 = -16384; lim14 <= 16000; lim14 += 37) {
        e.pt.lim = lim14;
        for (int32_t dx = -8; dx <= 8 + 4 * 8; dx++) {
            int32_t x = 4 * lim14 + dx; /* l.x in Q16.16: the dot is x 2^-16 */
            vec3_t l = vec3_make(x, 0, 0);
            bool want64 = x >= 4 * lim14 + 4; /* floor(x / 4) > lim14 */
            bool out64 = shadow_cone_out64(&e, &l), out16 = shadow_cone_out16(&e, &l);
            wrong += out64 != want64;
            wrong += out16 && x <= 4 * lim14 + 32; /* within the 2^-11 margin: never out */
            n++;
        }
    }
    printf("cone test boundary: %ld cases, %ld wrong\n", n, wrong);
    CHECK_MSG(wrong == 0, "cone test boundary: %ld of %ld wrong", wrong, n);
}
#endif

/* The single-pixel tests' view: the camera on +z at 5 looking at the
 * origin, a narrow fov, ambient 0.1, nothing else yet. */
static scene_t centre_scene(void)
{
    scene_t b;
    memset(&b, 0, sizeof b);
    set3(b.eye, 0, 0, 5);
    set3(b.gaze, 0, 0, -1);
    set3(b.up, 0, 1, 0);
    b.fov = 10;
    set3(b.ambient, 0.1, 0.1, 0.1);
    return b;
}

#if FXRT_SMOOTH
/* Smooth triangles (scene/smooth.c, light/shade.c): an icosahedron whose
 * vertex normals point away from its centre, on a floor, under a point
 * light with shadows and a directional one without, in Phong, against the
 * reference's own interpolation and terminator; then single pixels. */
static void test_smooth(void)
{
    static const int face[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                    {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                    {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                    {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    double g = (1 + sqrt(5.0)) / 2, v[12][3] = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0},
                                                {0, -1, g}, {0, 1, g}, {0, -1, -g}, {0, 1, -g},
                                                {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
    for (int material = MATERIAL_LAMBERT; material <= MATERIAL_PHONG; material++) {
        scene_t s = course(material);
        s.obj[0].material = MATERIAL_LAMBERT;
        s.n_obj = 1;
        for (int f = 0; f < 20; f++) {
            int j = s.n_obj++;
            obj_t *o = &s.obj[j];
            *o = s.obj[1]; /* the sphere's colour and material */
            o->kind = GEOM_TRIANGLE;
            s.smooth[j] = true;
            for (int k = 0; k < 3; k++)
                for (int i = 0; i < 3; i++) {
                    double c[3] = {0.6, 1.2, 0.4};
                    o->p[k][i] = c[i] + 0.6 * v[face[f][k]][i] / sqrt(1 + g * g);
                    s.vn[j][k][i] = v[face[f][k]][i]; /* not unit: the core normalises */
                }
        }
        s.n_lights = 2;
        check_frame(material == MATERIAL_PHONG ? "smooth icosahedron, phong" : "smooth icosahedron, lambert", &s);
    }
    /* A closed mesh's own triangles (an icosphere of 80, flat and smooth)
     * from 24 viewpoints around it, lit from above with shadows (so its
     * triangles shadow each other and the floor): no pixel away from a
     * discontinuity off (check_frame). */
    {
        double vv[42][3];
        int nv = 12, tri[80][3], nt = 0;
        for (int i = 0; i < 12; i++) {
            double l = sqrt(1 + g * g);
            for (int k = 0; k < 3; k++)
                vv[i][k] = v[i][k] / l;
        }
        int mids[12][12];
        memset(mids, -1, sizeof mids);
        for (int f = 0; f < 20; f++) {
            int m[3];
            for (int e = 0; e < 3; e++) {
                int a = face[f][e], b = face[f][(e + 1) % 3], lo = a < b ? a : b, hi = a < b ? b : a;
                if (mids[lo][hi] < 0) {
                    double q[3], l = 0;
                    for (int k = 0; k < 3; k++)
                        q[k] = (vv[a][k] + vv[b][k]) / 2, l += q[k] * q[k];
                    for (int k = 0; k < 3; k++)
                        vv[nv][k] = q[k] / sqrt(l);
                    mids[lo][hi] = nv++;
                }
                m[e] = mids[lo][hi];
            }
            int sub[4][3] = {{face[f][0], m[0], m[2]}, {face[f][1], m[1], m[0]}, {face[f][2], m[2], m[1]}, {m[0], m[1], m[2]}};
            memcpy(tri[nt], sub, sizeof sub);
            nt += 4;
        }
        long bad_frames = 0;
        for (int view = 0; view < 24; view++) {
            scene_t m;
            memset(&m, 0, sizeof m);
            double az = 0.1 + view * 0.2618, el = 0.3 + 0.05 * (view % 5); /* (no coordinate below 2^-16) */
            set3(m.eye, 3.2 * cos(el) * sin(az), 3.2 * sin(el), 3.2 * cos(el) * cos(az));
            set3(m.gaze, -m.eye[0], -m.eye[1] + 0.3, -m.eye[2]);
            set3(m.up, 0, 1, 0);
            m.fov = 40;
            set3(m.ambient, 0.1, 0.1, 0.1);
            m.obj[0] = (obj_t){GEOM_PLANE, {{0, -1.2, 0}, {0, 1, 0}}, 0, {0.8, 0.8, 0.8}, MATERIAL_LAMBERT, {0, 0, 0}, 0, {0, 0, 0}, 0};
            m.n_obj = 1;
            for (int f = 0; f < nt; f++) {
                int j = m.n_obj++;
                m.obj[j] = (obj_t){GEOM_TRIANGLE, {{0}}, 0, {0.9, 0.4, 0.3}, MATERIAL_PHONG, {0.6, 0.6, 0.6}, 30, {0, 0, 0}, 0};
                m.smooth[j] = view % 2 == 1;
                for (int k = 0; k < 3; k++)
                    for (int i = 0; i < 3; i++)
                        m.obj[j].p[k][i] = m.vn[j][k][i] = vv[tri[f][k]][i];
            }
            m.light[0] = (lgt_t){LIGHT_POINT, {2.5, 4, 1.5 + 0.2 * view}, {0, 0, 0}, 0, {1, 1, 1}, true};
            m.n_lights = 1;
            long before = check_failed_count;
            char name[64];
            snprintf(name, sizeof name, "icosphere of 80, %s, view %d", m.smooth[1] ? "smooth" : "flat", view);
            check_frame(name, &m);
            bad_frames += check_failed_count != before;
        }
        CHECK_MSG(bad_frames == 0, "%ld of 24 icosphere views off the reference", bad_frames);
    }
    /* A triangle facing the camera (+z) at the origin; the centre pixel
     * has weights (1/4, 1/4, 1/2): with normals (0,0,1), (0,0,1),
     * (0,1,1)/sqrt 2 its normal is (0, 0.38268, 0.92388). */
    scene_t b = centre_scene();
    b.obj[0] = (obj_t){GEOM_TRIANGLE, {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}}, 0, {0.5, 0.5, 0.5}, MATERIAL_LAMBERT,
                       {0, 0, 0}, 0, {0, 0, 0}, 0};
    b.smooth[0] = true;
    set3(b.vn[0][0], 0, 0, 1);
    set3(b.vn[0][1], 0, 0, 2);
    set3(b.vn[0][2], 0, 1, 1);
    b.n_obj = 1;
    b.n_lights = 1;
    double c = chan(0.5), e3[3], k = 0.1 + 0.92387953;
    b.light[0] = (lgt_t){LIGHT_DIRECTIONAL, {0, 0, 0}, {0, 0, -1}, 0, {1, 1, 1}, true};
    set3(e3, c * k, c * k, c * k);
    check_centre("smooth triangle, interpolated normal", &b, e3);
    /* Normals all (1, 0, 1): a point light at (10, 0, -2) is in front of
     * them (n . l = 8 / sqrt 208) but behind the face: with shadows on the
     * face blocks it (the terminator), with shadows off it lights p. */
    for (int j = 0; j < 3; j++)
        set3(b.vn[0][j], 1, 0, 1);
    b.light[0] = (lgt_t){LIGHT_POINT, {10, 0, -2}, {0, 0, 0}, 0, {1, 1, 1}, true};
    set3(e3, c * 0.1, c * 0.1, c * 0.1);
    check_centre("smooth triangle, light behind its face, shadows on", &b, e3);
    b.light[0].shadows = false;
    k = 0.1 + 8 / sqrt(208.0);
    set3(e3, c * k, c * k, c * k);
    check_centre("the same, shadows off", &b, e3);
    /* The API: normals only on triangles, and nonzero; a refusal adds nothing. */
    fxrt_world_init(&world, color_make(NUM_ZERO, NUM_ZERO, NUM_ZERO));
    fxrt_object_t fo = {.kind = FXRT_SPHERE, .radius = NUM_ONE, .smooth = true};
    fo.vn[0] = fo.vn[1] = fo.vn[2] = vec3_make(NUM_ONE, NUM_ZERO, NUM_ZERO);
    CHECK(fxrt_add(&world, &fo) == FXRT_ERR_KIND && fxrt_count(&world) == 0);
    fo.kind = FXRT_TRIANGLE;
    fo.p[1] = vec3_make(NUM_ONE, NUM_ZERO, NUM_ZERO);
    fo.p[2] = vec3_make(NUM_ZERO, NUM_ONE, NUM_ZERO);
    fo.vn[2] = vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    CHECK(fxrt_add(&world, &fo) == FXRT_ERR_DIRECTION && fxrt_count(&world) == 0);
    fo.vn[2] = vec3_make(NUM_ZERO, NUM_ZERO, N(3));
    CHECK(fxrt_add(&world, &fo) == 0 && world.triangles[0].smooth && world.triangles[0].vn[2].z == NUM_ONE);
}
#endif

#if SHADOW_ROWS
/* Shadow rows (light/shadow.c, shadow_rows_setup): a row's mask may skip a
 * sphere only where no shadow ray from the plane's pixels on that row can
 * meet it. Random worlds: a plane (tilted up to 0.3), a point light above
 * it (every third a few hundredths to tenths above), three spheres and a
 * perspective camera (10 to 150 degrees) at scales 2, 20 and 400. Each
 * sphere is placed against the plane S through the light and the plane's
 * line on one random row, in double (a point between that line and the
 * light, moved off S by the radius plus 2^-6 to 2^-26 of the radius), so
 * that it grazes the rays of that row and of the rows around it. For every
 * pixel of every row whose ray meets the plane in front, the hit point and
 * the shadow ray are those the renderer forms (cam_ray,
 * geom_plane_surface, shade_hit's p, shade_lights' l and dist); wherever
 * the mask skips a sphere that faces the point's light, the sphere's exact
 * kernel must find no hit, unless the ray, in double, passes more than R'
 * (the culls' bound) from it: then the kernel is wrong (counted apart). */
static void rows_cross(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1], c[1] = a[2] * b[0] - a[0] * b[2], c[2] = a[0] * b[1] - a[1] * b[0];
}
static void test_shadow_rows(long worlds)
{
    static world_t w;
    static shadow_table_t tab;
    enum { RW = 48, RH = 36 };
    long masked = 0, checked = 0, kernel_wrong = 0, grazing = 0, masked_dir = 0, grazing_dir = 0;
    double closest = 1e30; /* the least miss / scale of a masked test */
    for (long k = 0; k < worlds; k++) {
        double scale = k % 3 == 0 ? 2 : k % 3 == 1 ? 20 : 400;
        fxrt_world_init(&w, color_make(NUM_ZERO, NUM_ZERO, NUM_ZERO));
        double pa[3] = {0, 0, 0}, pn[3] = {cull_pick(-0.3, 0.3), 1, cull_pick(-0.3, 0.3)};
        world_add_plane(&w, V(pa), V(pn), color_make(NUM_ONE, NUM_ONE, NUM_ONE));
        double eye[3] = {cull_pick(-scale, scale), scale * cull_pick(0.3, 2), cull_pick(-scale, scale)};
        double gaze[3] = {cull_pick(-1, 1), -cull_pick(0.2, 1), cull_pick(-1, 1)}, up[3] = {0, 1, 0};
        cam_t rcam;
        if (cam_setup(&rcam, CAM_PERSPECTIVE, V(eye), V(gaze), V(up), N(cull_pick(10, 150)), NUM_ONE, RW, RH) != CAM_OK)
            continue;
        /* Every fourth world a directional light (every third of those
         * grazing the plane), the others a point light. */
        bool dirl = k % 4 == 3;
        double pos[3] = {cull_pick(-scale, scale), k % 3 == 2 ? scale * cull_pick(0.0002, 0.002) : scale * cull_pick(0.1, 2),
                         cull_pick(-scale, scale)},
               dir[3] = {cull_pick(-1, 1), k % 3 == 2 ? -cull_pick(0.01, 0.1) : -cull_pick(0.2, 1), cull_pick(-1, 1)};
        if (world_add_light(&w, dirl ? LIGHT_DIRECTIONAL : LIGHT_POINT, V(pos), V(dir), N(90),
                            color_make(NUM_ONE, NUM_ONE, NUM_ONE), true) != 0)
            continue; /* (refused, FXRT_ERR_TINY in float and double: w.lights[0] would be another world's) */
        double n[3] = {0}, a[3] = {0}, L[3] = {0}, ld[3] = {0}, e[3] = {0}, fw[3] = {0}, u[3] = {0}, v[3] = {0};
        for (int i = 0; i < 3; i++) {
            n[i] = D(geom_axis(w.planes[0].n, i)), a[i] = D(geom_axis(w.planes[0].a, i));
            L[i] = D(geom_axis(w.lights[0].position, i)), e[i] = D(geom_axis(rcam.e, i));
            ld[i] = D(geom_axis(w.lights[0].dir, i)); /* (towards the light) */
            fw[i] = D(geom_axis(rcam.fwd, i)), u[i] = D(geom_axis(rcam.u, i)), v[i] = D(geom_axis(rcam.v, i));
        }
        double r[3], c[3][3];
        for (int o = 0; o < 3; o++) {
            /* the row's plane P (normal m), a point q of the plane's line
             * on it (a random pixel's hit), and S's normal g */
            int iy = 2 * (int)(spot_rand() * RH) - RH + 1, ix = 2 * (int)(spot_rand() * RW) - RW + 1;
            double f[3], m[3], rr[3], g[3];
            for (int i = 0; i < 3; i++)
                f[i] = fw[i] + iy * v[i], rr[i] = f[i] + ix * u[i];
            rows_cross(u, f, m);
            double mm = sqrt(dot(m, m)), ea[3] = {e[0] - a[0], e[1] - a[1], e[2] - a[2]};
            double den = dot(n, rr), s = -dot(n, ea) / den, q[3], le[3] = {L[0] - e[0], L[1] - e[1], L[2] - e[2]};
            double la[3] = {L[0] - a[0], L[1] - a[1], L[2] - a[2]};
            for (int i = 0; i < 3; i++)
                q[i] = e[i] + s * rr[i], m[i] /= mm;
            /* S: through L and the line (a point light); through the line
             * along ld (a directional one) */
            double rl = dirl ? dot(m, ld) : dot(m, le), fl = dirl ? dot(n, ld) : dot(n, la);
            for (int i = 0; i < 3; i++)
                g[i] = rl * n[i] - fl * m[i];
            double gg = sqrt(dot(g, g));
            r[o] = scale * exp(cull_pick(log(0.005), log(0.1)));
            double t = cull_pick(0.2, 0.9), off = r[o] * (1 + ldexp(1, -6 - (int)(spot_rand() * 21))) * (spot_rand() < 0.5 ? 1 : -1);
            double toward = scale * cull_pick(0.05, 2); /* (directional: along the ray from q) */
            for (int i = 0; i < 3; i++)
                c[o][i] = (dirl ? q[i] + toward * ld[i] : L[i] + t * (q[i] - L[i])) + (gg > 0 ? g[i] / gg * off : 0);
            if (!(s > 0) || fabs(c[o][0]) > 8000 || fabs(c[o][1]) > 8000 || fabs(c[o][2]) > 8000)
                for (int i = 0; i < 3; i++)
                    c[o][i] = L[i] + (i == 1 ? 2 * scale : 0); /* (no use: far above) */
            world_add_sphere(&w, V(c[o]), N(r[o]), color_make(NUM_ONE, NUM_ONE, NUM_ONE));
        }
        for (int y = 0; y < RH; y++) {
            shadow_rows_setup(&w, &rcam, y, &tab);
            uint32_t mask = tab.pl[0].row;
            if (!(mask & (7u << SHADOW_SLOT_SPHERE)))
                continue;
            for (int x = 0; x < RW; x++) {
                ray_t ray;
                num_t t;
                vec3_t nv;
                cam_ray(&rcam, x, y, &ray);
                geom_plane_surface(&w.planes[0], &ray, &t, &nv);
                if (t <= NUM_ZERO)
                    continue;
                vec3_t p = NUM_EXACT && t < num_from_int(16384) ? vec3_add(ray.o, vec3_scale_unit_small(ray.d, t))
                                                                 : ray_at(&ray, t);
                vec3_t l;
                num_t dist;
                if (!light_towards(&w.lights[0], p, &l, &dist))
                    continue;
                bool inside = vec3_dotw_units(ray.d, nv) > 0;
                if ((vec3_dotw_units(inside ? vec3_neg_unit(nv) : nv, l) <= 0))
                    continue; /* the renderer casts no shadow ray there */
                ray_t sray = {p, l};
                for (int o = 0; o < 3; o++) {
                    if (!(mask >> (SHADOW_SLOT_SPHERE + o) & 1))
                        continue;
                    masked++;
                    masked_dir += dirl;
                    double po[3] = {D(p.x), D(p.y), D(p.z)}, d[3] = {D(l.x), D(l.y), D(l.z)};
                    double oc[3] = {c[o][0] - po[0], c[o][1] - po[1], c[o][2] - po[2]};
                    double tt = fmin(fmax(dot(oc, d) / dot(d, d), 0), D(dist)), qd[3];
                    for (int i = 0; i < 3; i++)
                        qd[i] = oc[i] - tt * d[i];
                    double miss = sqrt(dot(qd, qd)) - r[o];
                    grazing += miss < scale / 64;
                    grazing_dir += dirl && miss < scale / 64;
                    closest = fmin(closest, miss / scale);
                    if (!geom_sphere_occludes(&w.spheres[o], &sray, dist))
                        continue;
                    checked++;
                    bool near = miss <= r[o] / 256 + 1.0 / 1024 + 1e-9 * (fabs(c[o][0]) + fabs(c[o][1]) + fabs(c[o][2]));
                    kernel_wrong += !near;
                    CHECK_SWEEP(!near, "shadow rows skip a sphere a ray meets: scale %g, pixel (%d, %d), miss %g", scale, x, y,
                                miss);
                }
            }
        }
    }
    printf("shadow rows (%s): %ld worlds, %ld masked sphere tests (%ld within 1/64 of the scale, the closest %.3g of "
           "it; of a directional light: %ld, %ld within 1/64), %ld kernel hits among them (all far from the sphere: "
           "kernel errors)\n",
           NUM_NAME, worlds, masked, grazing, closest, masked_dir, grazing_dir, checked);
    CHECK_MSG(masked > worlds * 100 && grazing > worlds / 4, "%ld masked tests, %ld grazing", masked, grazing);
    CHECK_MSG(masked_dir > worlds * 25 && grazing_dir > worlds / 16, "directional: %ld masked tests, %ld grazing",
              masked_dir, grazing_dir);
    (void)kernel_wrong;
}
#endif

int main(void)
{
    probe_material_reset();
#if SHADOW_CULL && FXRT_NUMBER == FXRT_Q16
    test_cone_boundary();
#endif
#if FXRT_NUMBER == FXRT_Q16
    test_spot_early_out();
#endif
#if SHADOW_CULL
    test_shadow_cull(getenv("FXRT_TEST_FULL") ? 3000000 : 300000);
    test_sphere_occludes(getenv("FXRT_TEST_FULL") ? 2000000 : 200000);
#endif
#if SHADOW_ROWS
    test_shadow_rows(getenv("FXRT_TEST_FULL") ? 30000 : 3000);
#endif
    scene_t s = course(MATERIAL_LAMBERT);
    check_frame("course, lambert", &s);
    s = course(MATERIAL_PHONG);
    check_frame("course, phong 64", &s);

    /* Coloured lights, mixed materials, exponents 1 and 1024, shadows. */
    s = course(MATERIAL_PHONG);
    s.obj[0].material = MATERIAL_LAMBERT;
    s.obj[1].exponent = 1024;
    set3(s.obj[1].specular, 0.3, 0.6, 0.9);
    s.obj[2].exponent = 1;
    s.obj[3].material = MATERIAL_FLAT;
    s.light[0] = (lgt_t){LIGHT_POINT, {-3, 5, 2}, {0, 0, 0}, 0, {0.9, 0.2, 0.1}, true};
    s.light[1] = (lgt_t){LIGHT_DIRECTIONAL, {0, 0, 0}, {1, -2, -0.5}, 0, {0.1, 0.8, 0.2}, true};
    s.light[2] = (lgt_t){LIGHT_SPOT, {1, 4, 1}, {0, -1, 0}, 30, {0.2, 0.3, 0.9}, true};
    s.light[3] = (lgt_t){LIGHT_POINT, {0.2, 0.3, 3}, {0, 0, 0}, 0, {0.4, 0.4, 0.4}, false};
    s.n_lights = 4;
    set3(s.ambient, 0.05, 0.1, 0.15);
    check_frame("coloured lights", &s);
    test_lambert_planes();

#if FXRT_SMOOTH
    test_smooth();
#endif

    /* Single pixels. A grey lambert sphere (0.5: 127.5) at the origin,
     * radius 1, camera on +z looking at it, ambient 0.1. */
    scene_t b = centre_scene();
    b.obj[0] = (obj_t){GEOM_SPHERE, {{0, 0, 0}}, 1, {0.5, 0.5, 0.5}, MATERIAL_LAMBERT, {0, 0, 0}, 0, {0, 0, 0}, 0};
    b.n_obj = 1;
    b.n_lights = 1;
    double c = chan(0.5), e3[3];
    /* light straight above the nearest point, shadows on: n . l = 1, no acne */
    b.light[0] = (lgt_t){LIGHT_POINT, {0, 0, 3}, {0, 0, 0}, 0, {1, 1, 1}, true};
    set3(e3, c * 1.1, c * 1.1, c * 1.1);
    check_centre("lit sphere, shadows on", &b, e3);
    /* the light inside the sphere: the outside surface faces away */
    set3(b.light[0].pos, 0, 0, 0);
    set3(e3, c * 0.1, c * 0.1, c * 0.1);
    check_centre("light inside the sphere", &b, e3);
    /* a sphere between the light and a plane: the plane's pixel is in shadow */
    scene_t p = b;
    p.obj[0] = (obj_t){GEOM_PLANE, {{0, 0, 0}, {0, 0, 1}}, 0, {0.5, 0.5, 0.5}, MATERIAL_LAMBERT, {0, 0, 0}, 0, {0, 0, 0}, 0};
    p.obj[1] = (obj_t){GEOM_SPHERE, {{3, 0, 1}}, 0.5, {1, 1, 1}, MATERIAL_FLAT, {0, 0, 0}, 0, {0, 0, 0}, 0};
    p.n_obj = 2;
    p.light[0] = (lgt_t){LIGHT_POINT, {6, 0, 2}, {0, 0, 0}, 0, {1, 1, 1}, true};
    check_centre("shadow of a sphere", &p, e3);
    p.light[0].shadows = false; /* n . l = 2 / sqrt(40) */
    double ndl = 2 / sqrt(40.0);
    set3(e3, c * (0.1 + ndl), c * (0.1 + ndl), c * (0.1 + ndl));
    check_centre("same, shadows off", &p, e3);
    /* the camera inside a box, looking at its far wall (normal turned to
     * the eye): a light outside is blocked by the box itself, one inside
     * reaches the wall */
    scene_t x = b;
    set3(x.eye, 0, 0, 0);
    x.obj[0] = (obj_t){GEOM_BOX, {{-2, -2, -2}, {2, 2, 2}}, 0, {0.5, 0.5, 0.5}, MATERIAL_LAMBERT, {0, 0, 0}, 0, {0, 0, 0}, 0};
    x.light[0] = (lgt_t){LIGHT_POINT, {0, 0, 5}, {0, 0, 0}, 0, {1, 1, 1}, true};
    set3(e3, c * 0.1, c * 0.1, c * 0.1);
    check_centre("inside a box, light outside", &x, e3);
    set3(x.light[0].pos, 0, 0, 1);
    set3(e3, c * 1.1, c * 1.1, c * 1.1);
    check_centre("inside a box, light inside", &x, e3);
    /* A flat box (min y == max y) lit from above, shadows on: seen from
     * above its top side is lit (n . l = 1), seen from below its underside
     * is not. Both builds once entered a flat box through its min face
     * whatever the ray's direction, so from above the hit looked like the
     * inside of a solid and the box shadowed itself. */
    scene_t fb = b;
    set3(fb.eye, 0, 3, 0);
    set3(fb.gaze, 0, -1, 0);
    set3(fb.up, 0, 0, -1);
    fb.obj[0] = (obj_t){GEOM_BOX, {{-1, 0, -1}, {1, 0, 1}}, 0, {0.5, 0.5, 0.5}, MATERIAL_LAMBERT, {0, 0, 0}, 0, {0, 0, 0}, 0};
    fb.light[0] = (lgt_t){LIGHT_DIRECTIONAL, {0, 0, 0}, {0, -1, 0}, 0, {1, 1, 1}, true};
    set3(e3, c * 1.1, c * 1.1, c * 1.1);
    check_centre("flat box lit from above, seen from above", &fb, e3);
    set3(fb.eye, 0, -3, 0);
    set3(fb.gaze, 0, 1, 0);
    set3(e3, c * 0.1, c * 0.1, c * 0.1);
    check_centre("flat box lit from above, seen from below", &fb, e3);
    /* A point light farther from the lit point than Q16.16 holds: the eye
     * 8000 above a lambert floor looks at (26666.7, 0, 0) (t = 27,841),
     * the light is at (-8000, 4000, 0), 34,897 away (n . l = 4000 /
     * 34897). A wall behind the light (x = -8100) is not between them; a
     * small sphere on the segment is. */
    scene_t f = b;
    set3(f.eye, 0, 8000, 0);
    set3(f.gaze, 1, -0.3, 0);
    f.obj[0] = (obj_t){GEOM_PLANE, {{0, 0, 0}, {0, 1, 0}}, 0, {0.5, 0.5, 0.5}, MATERIAL_LAMBERT, {0, 0, 0}, 0, {0, 0, 0}, 0};
    f.obj[1] = (obj_t){GEOM_PLANE, {{-8100, 0, 0}, {1, 0, 0}}, 0, {1, 1, 1}, MATERIAL_FLAT, {0, 0, 0}, 0, {0, 0, 0}, 0};
    f.n_obj = 2;
    f.light[0] = (lgt_t){LIGHT_POINT, {-8000, 4000, 0}, {0, 0, 0}, 0, {1, 1, 1}, true};
    double far_ndl = 4000 / sqrt(pow(8000 + 8000 / 0.3, 2) + 4000.0 * 4000.0);
    set3(e3, c * (0.1 + far_ndl), c * (0.1 + far_ndl), c * (0.1 + far_ndl));
    check_centre("point light 34,897 away, a wall behind it", &f, e3);
    f.obj[2] = (obj_t){GEOM_SPHERE, {{8000, 4000 * (1 - 16000 / (8000 + 8000 / 0.3)), 0}}, 100, {1, 1, 1}, MATERIAL_FLAT,
                       {0, 0, 0}, 0, {0, 0, 0}, 0};
    f.n_obj = 3;
    set3(e3, c * 0.1, c * 0.1, c * 0.1);
    check_centre("point light 34,897 away, a sphere between", &f, e3);
    /* The same far light as a spot (its cone test takes the far path's
     * quarter vector): aimed at p with a 5-degree cone it lights p, aimed
     * 5.1 degrees away it does not, 4.9 degrees away it does. */
    f.n_obj = 2;
    double lp[3] = {-8000, 4000, 0}, pp[3] = {8000 / 0.3, 0, 0}, ax[3];
    for (int i = 0; i < 3; i++)
        ax[i] = pp[i] - lp[i];
    double axl = sqrt(ax[0] * ax[0] + ax[1] * ax[1]);
    for (int k = 0; k < 3; k++) {
        double off = (double[]){0, 5.1, 4.9}[k] * 3.14159265358979323846 / 180; /* turn the axis in the x-y plane */
        double dx = (ax[0] * cos(off) - ax[1] * sin(off)) / axl, dy = (ax[0] * sin(off) + ax[1] * cos(off)) / axl;
        f.light[0] = (lgt_t){LIGHT_SPOT, {-8000, 4000, 0}, {dx, dy, 0}, 5, {1, 1, 1}, true};
        double lit = k == 1 ? 0 : far_ndl;
        set3(e3, c * (0.1 + lit), c * (0.1 + lit), c * (0.1 + lit));
        check_centre((const char *[]){"far spot aimed at p", "far spot 5.1 degrees off", "far spot 4.9 degrees off"}[k],
                     &f, e3);
    }
    test_spot_block_out(); /* (last: the sweeps above keep their random numbers) */
    return check_report("test_shade_" NUM_NAME);
}
