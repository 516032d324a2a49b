/* The renderer skips what a scene does not need (issue 11), proved by the
 * work counters of core/math/stats.h (this program and its core are built
 * with FXRT_STATS 1, once per number type, see tests/skip.mk):
 *   - a light behind a surface (n . l <= 0) sends no shadow ray;
 *   - a directional light's l is never normalised per pixel;
 *   - flat pieces' normals are constant (no per-pixel normalisation);
 *   - the Phong power takes O(log k) products (repeated squaring);
 *   - a spot light's cosine is computed once, at set-up;
 *   - flat materials cost no lighting at all;
 *   - a shadow ray tests a sphere's exact kernel only near the sphere's
 *     shadow (culling, core/light/shadow.c).
 * Issue 12 (secondary rays and supersampling):
 *   - secondary rays use the world-space kernels and the scene's bounds:
 *     reflected rays that miss the box around the bounded objects test no
 *     sphere (geom_sphere_hit and geom_sphere_occludes are wrapped at
 *     link time, -Wl,--wrap, and
 *     counted), the others test every sphere; the number of skips equals
 *     the number of mirrored rays that miss the padded box, computed here
 *     in double; primary rays never call the sphere kernel;
 *   - samples N reuses the per-frame set-up (render_setup, wrapped, runs
 *     once per frame, never per row or sample), and a pixel whose N x N
 *     samples fall on one flat object costs no shading and no secondary
 *     ray; the CPU time of samples 4 against samples 1 is printed.
 * Expected counts come from the scene's own geometry (pixel counts from
 * the keys, bit counts of the exponent), not from the renderer's output
 * values. tests/skip.sh checks the link-time side with nm. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "../core/fxrt.h"
#include "add.h"
#include "check.h"

#if FXRT_NUMBER == FXRT_Q16
#define V(x) ((fx_t)((x) * 65536.0 + ((x) < 0 ? -0.5 : 0.5)))
#else
#define V(x) ((num_t)(x))
#endif
#define P(x, y, z) vec3_make(V(x), V(y), V(z))
#define COL(r, g, b) color_make(COLOR_FRAC(r), COLOR_FRAC(g), COLOR_FRAC(b))
#define FRAC(r, g, b) color_make(V(r), V(g), V(b))

enum { W = 64, H = 48 };
static world_t world;
static render_t rs;
static uint8_t img[W * H * 3];
static uint32_t keys[W * H];

static void reset(void)
{
    memset(&fxrt_stats, 0, sizeof fxrt_stats);
}

/* Render the frame (fast renderer), with keys when want_keys. */
static void render(const cam_t *cam, bool want_keys)
{
    CHECK(fxrt_render_setup(&rs, &world, cam) == FXRT_OK);
    reset();
    for (int y = 0; y < H; y++) {
        render_set_keys(&rs, want_keys ? keys + W * y : NULL);
        render_row(&rs, y, img + 3 * W * y);
    }
}

static long count_id(uint16_t id)
{
    long n = 0;
    for (int i = 0; i < W * H; i++)
        n += (keys[i] >> 8) == id;
    return n;
}

static void lit(int32_t id, material_kind_t k, int exponent)
{
    material_t m = {0};
    m.kind = (uint8_t)k;
    m.exponent = (uint16_t)exponent;
    m.specular = FRAC(0.8, 0.6, 0.4);
    CHECK(world_set_material(&world, id, &m) == FXRT_OK);
}

/* A world of background bg and ambient amb with the floor y = 0 of colour
 * c, Lambert or Phong (exponent k); returns the floor's id. */
static int32_t lit_floor(bool phong, int k, color_t bg, color_t amb, color_t c)
{
    fxrt_world_init(&world, bg);
    world_set_ambient(&world, amb);
    int32_t pid = world_add_plane(&world, P(0, 0, 0), P(0, 1, 0), c);
    lit(pid, phong ? MATERIAL_PHONG : MATERIAL_LAMBERT, k);
    return pid;
}

static void camera(cam_t *cam)
{
    CHECK(fxrt_camera_perspective(cam, P(0, 4, 6), P(0, -4, -6), P(0, 1, 0), V(45), W, H) == FXRT_OK);
}

/* A plane lit from below sends no shadow ray; lit from above, one per
 * pixel it covers (every plane pixel faces the light), or none with shadow
 * rows (light/shade.h): alone in the world, nothing can block it. For a
 * point light and for a directional one. */
static void test_behind(void)
{
    cam_t cam;
    camera(&cam);
    for (int k = 0; k < 4; k++) {
        int above = k & 1;
        bool dirl = k >= 2;
        fxrt_world_init(&world, COL(0, 0, 0));
        int32_t id = world_add_plane(&world, P(0, 0, 0), P(0, 1, 0), COL(0.7, 0.3, 0.2));
        lit(id, MATERIAL_LAMBERT, 0);
        CHECK(world_add_light(&world, dirl ? LIGHT_DIRECTIONAL : LIGHT_POINT, P(0.3, above ? 5 : -5, 0.2),
                              P(0.2, above ? -1 : 1, -0.1), V(0), FRAC(1, 1, 1), true) == 0);
        render(&cam, true);
        long plane = count_id((uint16_t)id);
        CHECK_MSG(plane > W * H / 4, "plane covers %ld pixels", plane);
        if (above)
            CHECK_MSG(fxrt_stats.shadow_rays == (SHADOW_ROWS ? 0u : (uint32_t)plane),
                      "light above: %u shadow rays for %ld pixels", (unsigned)fxrt_stats.shadow_rays, plane);
        else
            CHECK_MSG(fxrt_stats.shadow_rays == 0, "light behind: %u shadow rays", (unsigned)fxrt_stats.shadow_rays);
    }
}

/* A scene of every kind: directional lights need no per-pixel
 * normalisation of l; point lights one per shaded pixel; a narrow spot
 * light only near its cone (float and double test the cone on |v| before
 * normalising; Q16.16 first rules out what is clearly outside with
 * shade_spot_surely_out, on cores with UMULL). Flat pieces normalise no
 * normal; spheres one per shaded pixel. */
static void test_normalisations(void)
{
    cam_t cam;
    camera(&cam);
    for (int kind = 0; kind < 3; kind++) {
        for (int with_sphere = 0; with_sphere < 2; with_sphere++) {
            fxrt_world_init(&world, COL(0.1, 0.2, 0.3));
            world_set_ambient(&world, FRAC(0.2, 0.1, 0.05));
            int32_t pid = world_add_plane(&world, P(0, 0, 0), P(0, 1, 0), COL(0.9, 0.1, 0.3));
            lit(pid, MATERIAL_LAMBERT, 0);
            lit(world_add_box(&world, P(-1.5, 0, -1), P(-0.5, 1, 0), COL(0.2, 0.3, 0.9)), MATERIAL_PHONG, 33);
            int32_t tid = world_add_triangle(&world, P(0.5, 0, -1), P(1.5, 0, -1), P(1, 1.2, -1), COL(0.6, 0.6, 0.1));
            lit(tid, MATERIAL_LAMBERT, 0);
            int32_t sid = -1;
            if (with_sphere) {
                sid = world_add_sphere(&world, P(0.2, 0.6, 0.8), V(0.6), COL(0.1, 0.8, 0.2));
                lit(sid, MATERIAL_PHONG, 64);
            }
            if (kind == 0)
                world_add_light(&world, LIGHT_DIRECTIONAL, P(0, 0, 0), P(-1, -2, -1.5), V(0), FRAC(1, 0.9, 0.8), true);
            else if (kind == 1)
                world_add_light(&world, LIGHT_POINT, P(2, 3, 2), P(0, 0, 0), V(0), FRAC(1, 0.9, 0.8), true);
            else
                world_add_light(&world, LIGHT_SPOT, P(0, 4, 0), P(0, -1, 0), V(10), FRAC(1, 0.9, 0.8), true);
            render(&cam, true);
            long covered = W * H - count_id(0xFFFF);
            CHECK_MSG(fxrt_stats.shaded == (uint32_t)covered, "shaded %u of %ld covered pixels",
                      (unsigned)fxrt_stats.shaded, covered);
            if (kind == 0)
                CHECK_MSG(fxrt_stats.l_normalised == 0, "directional: %u normalisations of l",
                          (unsigned)fxrt_stats.l_normalised);
            else if (kind == 1)
                CHECK_MSG(fxrt_stats.l_normalised == (uint32_t)covered, "point: %u normalisations of l for %ld",
                          (unsigned)fxrt_stats.l_normalised, covered);
            else
                CHECK_MSG(fxrt_stats.l_normalised > 0 && fxrt_stats.l_normalised < (uint32_t)covered / 4,
                          "spot, 10 degrees: %u normalisations of l for %ld pixels", (unsigned)fxrt_stats.l_normalised,
                          covered);
            long spheres = sid >= 0 ? count_id((uint16_t)sid) : 0;
            CHECK_MSG(fxrt_stats.n_normalised == (uint32_t)spheres, "%u normal normalisations, %ld sphere pixels",
                      (unsigned)fxrt_stats.n_normalised, spheres);
            /* A plane's or triangle's hit numerator (a - e) . n: once for
             * each change of flat owner in the frame's pixel order (rows
             * as rendered; other owners in between keep it), counted
             * from the keys. */
            long flat_px = 0, changes = 0;
            uint32_t last = 0xFFFF;
            for (int y = 0; y < H; y++) {
                for (int x = 0; x < W; x++) {
                    uint32_t id = keys[W * y + x] >> 8;
                    if (id != (uint32_t)pid && id != (uint32_t)tid)
                        continue;
                    flat_px++;
                    changes += id != last;
                    last = id;
                }
            }
            CHECK_MSG(flat_px > W * H / 4 && fxrt_stats.flat_nums == (uint32_t)changes,
                      "%u flat hit numerators, %ld owner changes on %ld flat pixels", (unsigned)fxrt_stats.flat_nums,
                      changes, flat_px);
            /* The lambert plane and triangle take their hit points from
             * the raw camera ray: only the phong box's and the sphere's
             * pixels normalise theirs. */
            CHECK_MSG(fxrt_stats.d_normalised == (uint32_t)(covered - flat_px),
                      "%u camera rays normalised, %ld pixels not on the lambert plane or triangle",
                      (unsigned)fxrt_stats.d_normalised, covered - flat_px);
        }
    }
}

/* Phong powers: products per power <= 2 * bits(k), for small and large k. */
static void test_pow(void)
{
    static const int ks[] = {1, 2, 3, 64, 100, 1000, 1023, 1024};
    for (size_t i = 0; i < sizeof ks / sizeof ks[0]; i++) {
        int k = ks[i], bits = 0;
        while ((k >> bits) > 0)
            bits++;
        reset();
        for (int j = 0; j <= 16; j++)
            (void)numw_pow_int(numw_mul(V(j / 16.0), NUM_ONE), (uint32_t)k);
        CHECK_MSG(fxrt_stats.phong == 17, "k=%d: %u powers", k, (unsigned)fxrt_stats.phong);
        CHECK_MSG(fxrt_stats.pow_products <= 17u * 2u * (unsigned)bits, "k=%d: %u products for 17 powers (cap %u)",
                  k, (unsigned)fxrt_stats.pow_products, 17u * 2u * (unsigned)bits);
        /* Q16.16 takes no product where x <= 1 - 12 / k (numw_pow_int's
         * shortcut: its value is 0 there) */
        unsigned looped = 0;
        for (int j = 0; j <= 16; j++)
            looped += !(FXRT_NUMBER == FXRT_Q16 && k > 12 && j * k <= (k - 12) * 16);
        CHECK_MSG(fxrt_stats.pow_products >= looped * (unsigned)(bits - 1), "k=%d: %u products for %u powers", k,
                  (unsigned)fxrt_stats.pow_products, looped);
        CHECK_MSG(FXRT_NUMBER != FXRT_Q16 || k <= 12 || looped < 17u, "k=%d: no power took the shortcut", k);
    }
}

/* Spot lights: the cosine is taken once per light, at world_add_light,
 * however many pixels the frame has. */
static void test_spot(void)
{
    cam_t cam;
    camera(&cam);
    fxrt_world_init(&world, COL(0, 0, 0));
    lit(world_add_plane(&world, P(0, 0, 0), P(0, 1, 0), COL(0.5, 0.5, 0.5)), MATERIAL_LAMBERT, 0);
    reset();
    world_add_light(&world, LIGHT_SPOT, P(0, 4, 0), P(0, -1, 0), V(20), FRAC(1, 1, 1), false);
    world_add_light(&world, LIGHT_SPOT, P(1, 4, 0), P(0, -1, 0.2), V(35.5), FRAC(0.5, 0.2, 1), false);
    CHECK_MSG(fxrt_stats.cosines == 2, "%u cosines at set-up", (unsigned)fxrt_stats.cosines);
    render(&cam, true);
    CHECK_MSG(fxrt_stats.cosines == 0, "%u cosines while rendering", (unsigned)fxrt_stats.cosines);
    CHECK(fxrt_stats.shaded > 0);
    long inside = 0;
    for (int i = 0; i < W * H; i++)
        inside += (keys[i] & 0xFF) != 0 && keys[i] != RENDER_KEY_MISS;
    CHECK_MSG(inside > 0 && inside < (long)fxrt_stats.shaded, "%ld of %u pixels inside a cone", inside,
              (unsigned)fxrt_stats.shaded);
}

/* A Lambert or Phong plane under spot lights only: in runs
 * (FXRT_SHADE_RUNS), blocks of pixels that no spot reaches take the
 * ambient term without a light sum (light/shade.c, shade_flat_spot_blocks):
 * they must cover most of the plane's pixels outside every cone, and each
 * such pixel is c_d (.) c_a, as computed here in double (+-1). */
static void test_spot_blocks(void)
{
    cam_t cam;
    camera(&cam);
    for (int phong = 0; phong < 2; phong++) {
        lit_floor(phong, 20, COL(0, 0, 0), FRAC(0.3, 0.45, 0.2), COL(0.7, 0.55, 0.9));
        CHECK(world_add_light(&world, LIGHT_SPOT, P(0, 4, 0), P(0, -1, 0), V(20), FRAC(1, 1, 1), false) == 0);
        CHECK(world_add_light(&world, LIGHT_SPOT, P(1, 4, 0), P(0, -1, 0.2), V(12.5), FRAC(0.5, 0.2, 1), true) == 1);
        render(&cam, true);
        long dark = 0, right = 0;
        int want[3] = {(int)floor(255.0 * 0.7 * 0.3 + 0.5), (int)floor(255.0 * 0.55 * 0.45 + 0.5),
                       (int)floor(255.0 * 0.9 * 0.2 + 0.5)};
        static uint32_t dark_keys[W * H];
        memcpy(dark_keys, keys, sizeof dark_keys);
        render(&cam, false);
        for (int i = 0; i < W * H; i++) {
            if (dark_keys[i] != render_key(0, 0))
                continue;
            dark++;
            bool near = true;
            for (int c = 0; c < 3; c++)
                near &= abs(img[3 * i + c] - want[c]) <= 1;
            right += near;
        }
        const char *mat = phong ? "phong" : "lambert";
        CHECK_MSG(dark > W * H / 4 && right == dark, "%s under spots: %ld of %ld plane pixels outside the cones at c_d c_a",
                  mat, right, dark);
        if (FXRT_SHADE_RUNS)
            CHECK_MSG(fxrt_stats.spot_blocks * SHADE_SPOT_BLOCK >= (uint32_t)dark / 2,
                      "%s under spots: %u blocks of %d pixels for %ld pixels outside the cones", mat,
                      (unsigned)fxrt_stats.spot_blocks, SHADE_SPOT_BLOCK, dark);
    }
}

/* Flat materials: lights in the world, but nothing shaded and no pixel
 * differs from the world without lights. */
static void test_flat(void)
{
    cam_t cam;
    camera(&cam);
    static uint8_t ref[W * H * 3];
    for (int with_lights = 0; with_lights < 2; with_lights++) {
        fxrt_world_init(&world, COL(0.1, 0.1, 0.1));
        world_add_plane(&world, P(0, 0, 0), P(0, 1, 0), COL(0.7, 0.2, 0.1));
        world_add_sphere(&world, P(0, 1, 0), V(0.8), COL(0.3, 0.6, 0.9));
        if (with_lights) {
            world_set_ambient(&world, FRAC(0.3, 0.3, 0.3));
            world_add_light(&world, LIGHT_POINT, P(2, 3, 2), P(0, 0, 0), V(0), FRAC(1, 1, 1), true);
        }
        render(&cam, false);
        if (!with_lights)
            memcpy(ref, img, sizeof img);
        CHECK_MSG(fxrt_stats.shaded == 0 && fxrt_stats.shadow_rays == 0, "flat: %u shaded, %u shadow rays",
                  (unsigned)fxrt_stats.shaded, (unsigned)fxrt_stats.shadow_rays);
    }
    CHECK(memcmp(ref, img, sizeof img) == 0);
}

/* A world set up again in the same storage starts flat: a second lit
 * world is shaded like the first (a stale material once hid it). */
static void test_reuse(void)
{
    cam_t cam;
    camera(&cam);
    uint32_t shaded[2];
    for (int pass = 0; pass < 2; pass++) {
        fxrt_world_init(&world, COL(0, 0, 0));
        lit(world_add_plane(&world, P(0, 0, 0), P(0, 1, 0), COL(0.5, 0.5, 0.5)), MATERIAL_LAMBERT, 0);
        world_add_light(&world, LIGHT_POINT, P(0, 4, 0), P(0, 0, 0), V(0), FRAC(1, 1, 1), false);
        render(&cam, false);
        shaded[pass] = fxrt_stats.shaded;
    }
    CHECK_MSG(shaded[0] > 0 && shaded[1] == shaded[0], "shaded %u then %u", (unsigned)shaded[0],
              (unsigned)shaded[1]);
}

/* Link-time wrappers (tests/skip.mk: -Wl,--wrap=...): calls from other
 * translation units reach these, which count and pass on. */
bool __real_geom_sphere_hit(const geom_sphere_t *sp, const ray_t *ray, num_t *t);
bool __wrap_geom_sphere_hit(const geom_sphere_t *sp, const ray_t *ray, num_t *t);
bool __real_render_setup(render_t *r, const world_t *w, const cam_t *c);
bool __wrap_render_setup(render_t *r, const world_t *w, const cam_t *c);
static unsigned long sphere_calls, setup_calls;
bool __wrap_geom_sphere_hit(const geom_sphere_t *sp, const ray_t *ray, num_t *t)
{
    sphere_calls++;
    return __real_geom_sphere_hit(sp, ray, t);
}
/* Shadow rays' sphere kernel (it calls geom_sphere_hit inside geom.c,
 * which the wrap does not see: each shadow test counts once). */
bool __real_geom_sphere_occludes(const geom_sphere_t *sp, const ray_t *ray, num_t tmax);
bool __wrap_geom_sphere_occludes(const geom_sphere_t *sp, const ray_t *ray, num_t tmax);
bool __wrap_geom_sphere_occludes(const geom_sphere_t *sp, const ray_t *ray, num_t tmax)
{
    sphere_calls++;
    return __real_geom_sphere_occludes(sp, ray, tmax);
}
bool __wrap_render_setup(render_t *r, const world_t *w, const cam_t *c)
{
    setup_calls++;
    return __real_render_setup(r, w, c);
}

static double dbl(num_t x)
{
#if FXRT_NUMBER == FXRT_Q16
    return x / 65536.0;
#else
    return (double)x;
#endif
}

/* Pixel i's camera ray in double (raw: cam_ray_raw's direction, else
 * cam_ray's unit one), where the keys say it shows object id. */
static bool px_ray(const cam_t *cam, int i, int32_t id, bool raw, double o[3], double d[3])
{
    if ((keys[i] >> 8) != (uint32_t)id)
        return false;
    ray_t r;
    (raw ? cam_ray_raw : cam_ray)(cam, i % W, H - 1 - i / W, &r);
    o[0] = dbl(r.o.x), o[1] = dbl(r.o.y), o[2] = dbl(r.o.z);
    d[0] = dbl(r.d.x), d[1] = dbl(r.d.y), d[2] = dbl(r.d.z);
    return true;
}

/* A reflective plane with three flat spheres on it, depth 1: every plane
 * pixel sends one reflected ray; those that miss the sphere around the
 * spheres' box (padded by one unit, core/scene/world.c, core/light/trace.c) test no
 * sphere, the others all three. */
static void test_bounds(void)
{
    cam_t cam;
    camera(&cam);
    fxrt_world_init(&world, COL(0.2, 0.3, 0.4));
    world_set_ambient(&world, FRAC(0.5, 0.5, 0.5));
    int32_t pid = world_add_plane(&world, P(0, 0, 0), P(0, 1, 0), COL(0.3, 0.3, 0.3));
    material_t m = {0};
    m.kind = MATERIAL_REFLECTIVE;
    m.exponent = 1;
    m.reflection = FRAC(0.5, 0.5, 0.5);
    CHECK(world_set_material(&world, pid, &m) == FXRT_OK);
    const double cx[3] = {-1.5, 0, 1.5};
    for (int i = 0; i < 3; i++)
        world_add_sphere(&world, P(cx[i], 0.5, 0), V(0.5), COL(0.9, 0.1 + 0.3 * i, 0.2));
    for (int depth = 0; depth <= 1; depth++) {
        CHECK(world_set_depth(&world, depth) == FXRT_OK);
        sphere_calls = 0;
        render(&cam, true);
        long plane = count_id((uint16_t)pid);
        unsigned long sec = fxrt_stats.secondary_rays, skips = fxrt_stats.bounds_skips;
        if (depth == 0) {
            CHECK_MSG(sec == 0 && sphere_calls == 0, "depth 0: %lu secondary rays, %lu sphere kernel calls", sec,
                      sphere_calls);
            continue;
        }
        /* the mirrored rays that miss the bounds sphere, in double: the
         * sphere through the corners of the spheres' box [-2, 2] x [0, 1] x
         * [-0.5, 0.5], its radius padded by one unit (core/scene/world.c) */
        long miss = 0;
        const double c[3] = {0, 0.5, 0}, rad = sqrt(2.0 * 2.0 + 0.5 * 0.5 + 0.5 * 0.5) + 1.0;
        for (int i = 0; i < W * H; i++) {
            double o[3], d[3];
            if (!px_ray(&cam, i, pid, false, o, d))
                continue;
            double t = -o[1] / d[1], p[3] = {o[0] + t * d[0], 0, o[2] + t * d[2]};
            d[1] = -d[1];
            double oc[3] = {c[0] - p[0], c[1] - p[1], c[2] - p[2]};
            double oc2 = oc[0] * oc[0] + oc[1] * oc[1] + oc[2] * oc[2];
            double b = oc[0] * d[0] + oc[1] * d[1] + oc[2] * d[2];
            miss += oc2 > rad * rad && (b < 0 || oc2 - b * b > rad * rad);
        }
        printf("bounds (%s): %ld plane pixels, %lu reflected rays, %lu missed the bounds sphere (double: %ld), "
               "%lu sphere kernel calls = 3 x %lu rays inside the bounds\n",
               NUM_NAME, plane, sec, skips, miss, sphere_calls, sec - skips);
        CHECK_MSG(sec == (unsigned long)plane, "%lu reflected rays for %ld plane pixels", sec, plane);
        CHECK_MSG(skips > sec / 4 && skips < sec, "%lu of %lu rays skipped", skips, sec);
        CHECK_MSG(sphere_calls == 3 * (sec - skips), "%lu sphere kernel calls, %lu rays inside the box", sphere_calls,
                  sec - skips);
        CHECK_MSG(labs((long)skips - miss) <= 2 + plane / 200, "%lu skips, %ld misses in double", skips, miss);
    }
}

/* Shadow-ray culling (core/light/shadow.c): a sphere above a plane, a point
 * light above both. The sphere's exact kernel must run for every plane
 * pixel in its shadow (the light's bit clear in the key: those rays are
 * blocked, so they were tested) and, with the light's cone around the
 * sphere only a little wider than the shadow, for not many more: at most
 * twice as many plus a border, where without culling every lit-facing
 * plane pixel would test it (most of the frame). */
static void check_rows(int32_t pid, long plane, const char *what);
static void test_shadow_cull(void)
{
    cam_t cam;
    camera(&cam);
    fxrt_world_init(&world, COL(0, 0, 0));
    int32_t pid = world_add_plane(&world, P(0, 0, 0), P(0, 1, 0), COL(0.7, 0.3, 0.2));
    lit(pid, MATERIAL_LAMBERT, 0);
    lit(world_add_sphere(&world, P(0.3, 1.3, -0.4), V(0.7), COL(0.2, 0.5, 0.3)), MATERIAL_LAMBERT, 0);
    CHECK(world_add_light(&world, LIGHT_POINT, P(-0.4, 4.5, 0.6), P(0, 0, 0), V(0), FRAC(1, 1, 1), true) == 0);
    sphere_calls = 0;
    render(&cam, true);
    long plane = count_id((uint16_t)pid), shadow = 0;
    for (int i = 0; i < W * H; i++)
        shadow += (keys[i] >> 8) == (uint32_t)pid && !(keys[i] & 1u);
    printf("shadow culling (%s): %ld plane pixels, %ld in the sphere's shadow, %lu sphere kernel calls\n", NUM_NAME,
           plane, shadow, sphere_calls);
    CHECK_MSG(shadow > 40 && plane > 8 * shadow, "%ld plane pixels, %ld shadowed", plane, shadow);
    CHECK_MSG(sphere_calls >= (unsigned long)shadow && sphere_calls <= (unsigned long)(2 * shadow + 2 * W),
              "%lu sphere kernel calls for %ld shadowed plane pixels", sphere_calls, shadow);
    check_rows(pid, plane, "point");
    /* The same world under a directional light: its rows too. */
    fxrt_world_init(&world, COL(0, 0, 0));
    pid = world_add_plane(&world, P(0, 0, 0), P(0, 1, 0), COL(0.7, 0.3, 0.2));
    lit(pid, MATERIAL_LAMBERT, 0);
    lit(world_add_sphere(&world, P(0.3, 1.3, -0.4), V(0.7), COL(0.2, 0.5, 0.3)), MATERIAL_LAMBERT, 0);
    CHECK(world_add_light(&world, LIGHT_DIRECTIONAL, P(0, 0, 0), P(0.3, -1, -0.2), V(0), FRAC(1, 1, 1), true) == 0);
    render(&cam, true);
    check_rows(pid, count_id((uint16_t)pid), "directional");
}

/* Shadow rows: a plane pixel sends a shadow ray only on a row whose line
 * can see the sphere's shadow, which the rows of shadowed plane pixels,
 * and a few around them for the margins, hold; the sphere's own pixels
 * send theirs. */
static void check_rows(int32_t pid, long plane, const char *what)
{
    long sphere = 0, rows = 0;
    for (int y = 0; y < H; y++) {
        bool any = false;
        for (int x = 0; x < W; x++) {
            uint32_t k = keys[y * W + x];
            any |= (k >> 8) == (uint32_t)pid && !(k & 1u);
            sphere += (k >> 8) != (uint32_t)pid && (k >> 8) != 0xFFFFu;
        }
        rows += any;
    }
    printf("shadow rows (%s, %s light): %u shadow rays, %ld sphere pixels, %ld rows with a shadow\n", NUM_NAME, what,
           (unsigned)fxrt_stats.shadow_rays, sphere, rows);
    CHECK_MSG(rows > 4, "%s: %ld rows with a shadow", what, rows);
    if (SHADOW_ROWS)
        CHECK_MSG(fxrt_stats.shadow_rays <= (uint32_t)(sphere + (rows + 8) * W) && fxrt_stats.shadow_rays < (uint32_t)plane / 2,
                  "%s: %u shadow rays: %ld sphere pixels, %ld plane pixels, %ld rows with a shadow", what,
                  (unsigned)fxrt_stats.shadow_rays, sphere, plane, rows);
}

static double cpu_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* samples N: one set-up per frame; a flat object under every sample costs
 * no shading and no secondary ray. Times: the best of a few frames. */
static void test_samples(void)
{
    cam_t cam;
    CHECK(fxrt_camera_perspective(&cam, P(0, 0, 5), P(0, 0, -1), P(0, 1, 0), V(45), W, H) == FXRT_OK);
    double best[2][2];
    for (int litm = 0; litm < 2; litm++) {
        fxrt_world_init(&world, COL(0, 0, 0));
        world_set_ambient(&world, FRAC(0.3, 0.3, 0.3));
        world_add_light(&world, LIGHT_POINT, P(1, 2, 3), P(0, 0, 0), V(0), FRAC(1, 1, 1), false);
        int32_t id = world_add_plane(&world, P(0, 0, 0), P(0, 0, 1), COL(0.6, 0.5, 0.4));
        if (litm)
            lit(id, MATERIAL_LAMBERT, 0);
        for (int si = 0; si < 2; si++) {
            int n = si ? 4 : 1;
            CHECK(world_set_samples(&world, n, false) == FXRT_OK);
            best[litm][si] = 1e9;
            for (int rep = 0; rep < 5; rep++) {
                setup_calls = 0;
                double t0 = cpu_s();
                render(&cam, false);
                double t = cpu_s() - t0;
                best[litm][si] = fmin(best[litm][si], t);
                CHECK_MSG(setup_calls == 1, "samples %d: %lu set-ups for one frame", n, setup_calls);
                /* render() resets the counters after set-up: rows only */
                unsigned long shaded = fxrt_stats.shaded;
                if (!litm)
                    CHECK_MSG(shaded == 0 && fxrt_stats.secondary_rays == 0, "flat, samples %d: %lu shaded", n, shaded);
                else
                    CHECK_MSG(shaded == (unsigned long)(W * H * n * n), "lambert, samples %d: %lu shaded of %d", n,
                              shaded, W * H * n * n);
            }
        }
        printf("samples (%s, %s plane filling %dx%d): samples 1 %.3f ms, samples 4 %.3f ms per frame (x %.1f; "
               "16 samples per pixel)\n",
               NUM_NAME, litm ? "lambert" : "flat", W, H, best[litm][0] * 1e3, best[litm][1] * 1e3,
               best[litm][1] / best[litm][0]);
    }
}

/* A lambert plane takes n . l from the light's height over it
 * (light/shade.c, shade_lights_plane): under a point light it makes the
 * unit vector l only for its shadow rays. A phong plane makes one at every
 * pixel that its specular term needs, but not in the blocks of its runs
 * where the term is surely 0 (shade_flat_phong_blocks: the Lambert sum
 * there). Every pixel still takes the light vector's length. A flat
 * sphere above casts the shadow; without keys its pixels are not shaded,
 * so every count below is the plane's. */
static void test_plane_heights(void)
{
    cam_t cam;
    camera(&cam);
    for (int phong = 0; phong < 2; phong++) {
        int32_t pid = lit_floor(phong, 16, COL(0.1, 0.1, 0.1), FRAC(0.3, 0.2, 0.1), COL(0.5, 0.6, 0.7));
        CHECK(world_add_sphere(&world, P(0.3, 1.0, 0.2), V(0.5), COL(0.9, 0.2, 0.1)) >= 0);
        CHECK(world_add_light(&world, LIGHT_POINT, P(1, 4, 1.5), P(0, 0, 0), V(0), FRAC(1, 0.9, 0.8), true) == 0);
        render(&cam, true);
        long plane = count_id((uint16_t)pid);
        CHECK_MSG(plane > W * H / 4, "plane covers %ld pixels", plane);
        render(&cam, false);
        uint32_t rays = fxrt_stats.shadow_rays;
        /* a pixel from its run's forms (light/shade.c, shade_plane_forms)
         * takes no light vector, and there are some */
        CHECK_MSG(fxrt_stats.l_normalised + fxrt_stats.plane_forms == (uint32_t)plane &&
                      fxrt_stats.plane_forms > (uint32_t)plane / 8,
                  "%s plane: %u light vectors and %u pixels from forms for %ld pixels", phong ? "phong" : "lambert",
                  (unsigned)fxrt_stats.l_normalised, (unsigned)fxrt_stats.plane_forms, plane);
        CHECK_MSG(rays > 0 && rays < (uint32_t)plane / 2, "%u shadow rays for %ld plane pixels", (unsigned)rays, plane);
        if (phong) {
            /* each pixel outside the blocks makes l once, with or without a shadow ray */
            uint32_t in_blocks = fxrt_stats.phong_blocks * SHADE_SPOT_BLOCK;
            CHECK_MSG(fxrt_stats.phong_blocks > 0 && in_blocks < (uint32_t)plane &&
                          fxrt_stats.l_units >= (uint32_t)plane - in_blocks &&
                          fxrt_stats.l_units <= (uint32_t)plane - in_blocks + rays,
                      "phong plane: %u unit vectors l for %ld pixels, %u in blocks without a term, %u shadow rays",
                      (unsigned)fxrt_stats.l_units, plane, (unsigned)in_blocks, (unsigned)rays);
        }
        else
            CHECK_MSG(fxrt_stats.l_units == rays, "lambert plane: %u unit vectors l for %u shadow rays",
                      (unsigned)fxrt_stats.l_units, (unsigned)rays);
    }
}

/* A plane under directional lights only (light/shade_sum.h,
 * shade_plane_row_unshadowed): where no light needs a shadow ray on the
 * row (shadows off, the row's mask clear, or the light behind the side
 * seen) nothing in the light sum depends on the point, so the pixel's
 * hit point is not made: counted (plane_points) against the plane's
 * pixels and shadow rays, for a lambert and a phong plane. The frame is
 * checked against the general path, which the same world takes with a
 * black spot light added (it adds exactly 0 to every channel): the
 * same pixels, and a hit point at every plane pixel; the lambert plane's
 * colour and mask also against their value computed here in double. */
static uint8_t img_general[W * H * 3];
static void directional_world(int phong, int mode, bool black_point)
{
    fxrt_world_init(&world, COL(0.1, 0.1, 0.1));
    world_set_ambient(&world, FRAC(0.25, 0.3, 0.35));
    int32_t pid = world_add_plane(&world, P(0, 0, 0), P(0, 1, 0), COL(0.55, 0.7, 0.35));
    lit(pid, phong ? MATERIAL_PHONG : MATERIAL_LAMBERT, 24);
    CHECK(world_add_sphere(&world, P(0.3, 1.0, 0.2), V(0.5), COL(0.9, 0.2, 0.1)) >= 0);
    /* light 0 from above (shadows on in mode 1), light 1 from below
     * (shadows on, but it lights the other side: no shadow ray) */
    CHECK(world_add_light(&world, LIGHT_DIRECTIONAL, P(0, 0, 0), P(-0.3, -1, -0.2), V(0), FRAC(0.9, 0.8, 0.6),
                          mode > 0) == 0);
    CHECK(world_add_light(&world, LIGHT_DIRECTIONAL, P(0, 0, 0), P(0.2, 1, 0.1), V(0), FRAC(1, 1, 1), true) == 1);
    if (mode == 2)
        CHECK(world_add_light(&world, LIGHT_POINT, P(-3, 5, 2), P(0, 0, 0), V(0), FRAC(0.3, 0.3, 0.3), false) == 2);
    if (black_point) /* a spot: no run's forms either (shade_plane_forms) */
        CHECK(world_add_light(&world, LIGHT_SPOT, P(2, 6, -1), P(0, -1, 0), V(80), FRAC(0, 0, 0), false) >= 2);
}
static void test_directional_plane(void)
{
    cam_t cam;
    camera(&cam);
    for (int phong = 0; phong < 2; phong++)
        for (int mode = 0; mode < 3; mode++) { /* shadows off; shadows on; and a point light */
            const char *mat = phong ? "phong" : "lambert";
            directional_world(phong, mode, true);
            render(&cam, false);
            memcpy(img_general, img, sizeof img);
            uint32_t general_pts = fxrt_stats.plane_points;
            directional_world(phong, mode, false);
            render(&cam, true);
            long plane = count_id(0), lit0 = 0, same = 0;
            CHECK_MSG(plane > W * H / 4, "plane covers %ld pixels", plane);
            CHECK_MSG(general_pts == (uint32_t)plane, "%s, with a black spot light: %u hit points for %ld pixels",
                      mat, (unsigned)general_pts, plane);
            /* Light 0 alone, without shadows: c_d (.) (c_a + c_l n . l) per channel, l = -dir unit. */
            double ndl = 1.0 / sqrt(0.09 + 1.0 + 0.04), cd[3] = {0.55, 0.7, 0.35}, ca[3] = {0.25, 0.3, 0.35},
                   cl[3] = {0.9, 0.8, 0.6};
            int want[3];
            for (int c = 0; c < 3; c++)
                want[c] = (int)floor(255.0 * cd[c] * (ca[c] + cl[c] * ndl) + 0.5);
            for (int i = 0; i < W * H; i++) {
                if ((keys[i] >> 8) != 0u)
                    continue;
                lit0 += (keys[i] & 0xFF) == 1u;
                bool near = true;
                for (int c = 0; c < 3; c++)
                    near &= abs(img[3 * i + c] - want[c]) <= 1;
                same += near;
            }
            if (mode == 0) {
                CHECK_MSG(lit0 == plane, "%s, directional, shadows off: %ld of %ld plane pixels lit by light 0 alone",
                          mat, lit0, plane);
                if (!phong)
                    CHECK_MSG(same == plane, "lambert, directional, shadows off: %ld of %ld plane pixels at (%d, %d, %d) +- 1",
                              same, plane, want[0], want[1], want[2]);
            }
            render(&cam, false);
            CHECK_MSG(memcmp(img, img_general, sizeof img) == 0, "%s, mode %d: the frame differs from the general path's",
                      mat, mode);
            uint32_t pts = fxrt_stats.plane_points, rays = fxrt_stats.shadow_rays;
            if (mode == 0)
                CHECK_MSG(pts == 0 && rays == 0, "%s, directional, shadows off: %u hit points, %u shadow rays", mat,
                          (unsigned)pts, (unsigned)rays);
            else if (mode == 1)
                CHECK_MSG(lit0 < plane && rays > 0 && pts >= rays && pts < (uint32_t)plane / 2,
                          "%s, directional, shadows on: %u hit points for %u shadow rays, %ld plane pixels (%ld lit)",
                          mat, (unsigned)pts, (unsigned)rays, plane, lit0);
            else /* (a lambert plane's runs from their forms: no hit point) */
                CHECK_MSG(pts + fxrt_stats.plane_forms == (uint32_t)plane && (phong || fxrt_stats.plane_forms > 0),
                          "%s, and a point light: %u hit points and %u pixels from forms for %ld plane pixels", mat,
                          (unsigned)pts, (unsigned)fxrt_stats.plane_forms, plane);
            /* In runs (FXRT_SHADE_RUNS), a lambert plane's run under
             * directional lights with no shadow ray on its row takes one
             * light sum, not one per pixel: at most a few per row. */
            if (mode == 0 && !phong && FXRT_SHADE_RUNS)
                CHECK_MSG(fxrt_stats.dir_sums <= 3u * H && fxrt_stats.dir_sums < (uint32_t)plane / 4,
                          "lambert, directional, shadows off: %u light sums for %ld plane pixels on %d rows",
                          (unsigned)fxrt_stats.dir_sums, plane, H);
        }
}

/* A Phong plane seen along raw camera rays (light/hit.c, shade_needs_unit;
 * light/shade.c, shade_specular): in Q16.16, for an exponent k > 12, its
 * pixels normalise no camera ray, and the specular term takes 1 / |d|
 * only where it may not be 0. Under a directional light whose mirror
 * point is in view, x = r . e at each plane pixel is computed here in
 * double from the camera ray cam_ray_raw gives: the roots must cover the
 * pixels with x > 1 - 12/k + 2^-10 (a term there) and lie within those
 * with x > (1 - 12/k)(1 - 2^-10) - 2^-12. Float and double normalise
 * every plane pixel's ray and take no such root. */
static void test_raw_phong(void)
{
    cam_t cam;
    camera(&cam);
    static const int ks[] = {13, 24, 64, 300, 1024};
    for (int ki = 0; ki < 5; ki++) {
        int k = ks[ki];
        int32_t pid = lit_floor(true, k, COL(0.1, 0.1, 0.1), FRAC(0.2, 0.2, 0.2), COL(0.6, 0.5, 0.4));
        /* l towards (0, 4, -6) mirrors to the eye (0, 4, 6) at the origin; a little off it */
        const double dir[3] = {0.3, -4, 6.2};
        CHECK(world_add_light(&world, LIGHT_DIRECTIONAL, P(0, 0, 0), P(dir[0], dir[1], dir[2]), V(0), FRAC(1, 1, 1),
                              false) == 0);
        /* The general path first: a black point light added (it adds 0)
         * keeps the plane's pixels off the directional runs. */
        CHECK(world_add_light(&world, LIGHT_POINT, P(2, 6, -1), P(0, 0, 0), V(0), FRAC(0, 0, 0), false) == 1);
        render(&cam, false);
        memcpy(img_general, img, sizeof img);
        world.n_lights = 1;
        render(&cam, false);
        CHECK_MSG(memcmp(img, img_general, sizeof img) == 0, "k %d: the directional runs' frame differs from the general path's", k);
        uint32_t sums = fxrt_stats.dir_sums;
        render(&cam, true);
        long plane = count_id((uint16_t)pid), must = 0, may = 0, pos = 0, may_pos = 0;
        double ll = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]), l[3], r[3];
        for (int c = 0; c < 3; c++)
            l[c] = -dir[c] / ll;
        for (int c = 0; c < 3; c++)
            r[c] = 2 * l[1] * (c == 1) - l[c]; /* 2 (n . l) n - l, n = (0, 1, 0) */
        double zero = 1.0 - 12.0 / k;
        for (int i = 0; i < W * H; i++) {
            double o[3], d[3];
            if (!px_ray(&cam, i, pid, true, o, d))
                continue;
            double xe = -(r[0] * d[0] + r[1] * d[1] + r[2] * d[2]) / sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            must += xe > zero + 1.0 / 1024;
            may += xe > zero * (1.0 - 1.0 / 1024) - 1.0 / 4096;
            pos += xe > 1.0 / 4096;
            may_pos += xe > -1.0 / 4096;
        }
        uint32_t roots = fxrt_stats.raw_roots, units = fxrt_stats.d_normalised;
        CHECK_MSG(plane > W * H / 2 && must > 0 && (k < 300 || may < plane / 2),
                  "k %d: %ld plane pixels, %ld with a term, %ld near one", k, plane, must, may);
        /* In runs (Q16.16, FXRT_SHADE_RUNS), the stretches with no term
         * take one light sum each: a few per row. */
        if (NUM_EXACT && FXRT_SHADE_RUNS && k >= 300)
            CHECK_MSG(sums > 0 && sums <= 3u * H, "k %d: %u light sums by the run for %ld plane pixels on %d rows", k,
                      (unsigned)sums, plane, H);
        if (NUM_EXACT)
            CHECK_MSG(units == 0 && roots >= (uint32_t)must && roots <= (uint32_t)may,
                      "k %d: %u camera rays normalised, %u roots for %ld pixels with a term and %ld near one", k,
                      (unsigned)units, (unsigned)roots, must, may);
        else /* the raw direction too: its root where r . d < 0 (shade_specular_at) */
            CHECK_MSG(units == 0 && roots >= (uint32_t)pos && roots <= (uint32_t)may_pos,
                      "k %d: %u camera rays normalised, %u roots for %ld pixels with r . e > 0 and %ld near it", k,
                      (unsigned)units, (unsigned)roots, pos, may_pos);
    }
}

/* Which pixels the runs shade with the Lambert sum on a Phong plane
 * (shade_flat_phong_blocks' blocks without a specular term): recorded by
 * the wrapped shade_flat_plane_pixels, called from frame/render_shade.c. */
static uint8_t lambert_px[W * H];
__typeof__(shade_flat_plane_pixels) __real_shade_flat_plane_pixels, __wrap_shade_flat_plane_pixels;
void __wrap_shade_flat_plane_pixels(const world_t *w, const shade_flat_t *f, const shade_k_t *k, const cam_row_t *row,
                                    const vec3_t *u, const vec3_t *fwd, int32_t width, int32_t x, int32_t end, ray_t *ray,
                                    uint8_t *rgb)
{
    for (int32_t i = x; i < end && row->y >= 0 && row->y < H && i >= 0 && i < W; i++)
        lambert_px[(H - 1 - row->y) * W + i] = 1;
    __real_shade_flat_plane_pixels(w, f, k, row, u, fwd, width, x, end, ray, rgb);
}

static uint32_t rng_state = 12345u;
static double rnd(double a, double b)
{
    rng_state = rng_state * 1664525u + 1013904223u;
    return a + (b - a) * (double)(rng_state >> 8) / 16777216.0;
}

/* A random view of a random plane (test_phong_blocks, test_plane_forms):
 * the eye within reach in x and z, at a height up to high (low_lo to
 * low_hi for every low_every-th seed), looking down within 2 of the
 * origin with a field of view in fov_lo..fov_hi degrees; the plane near y
 * = 0 of any colour, tilted by up to tilt in x and z for every third
 * seed, in a world of ambient amb. Returns the plane's id. */
typedef struct {
    double reach;
    int low_every;
    double low_lo, low_hi, high, fov_lo, fov_hi, tilt;
} plane_view_t;
static int32_t random_plane(int seed, const plane_view_t *v, color_t amb, cam_t *cam)
{
    double ex = rnd(-v->reach, v->reach), ey = seed % v->low_every == 0 ? rnd(v->low_lo, v->low_hi) : rnd(1, v->high),
           ez = rnd(-v->reach, v->reach);
    CHECK(fxrt_camera_perspective(cam, P(ex, ey, ez), P(rnd(-2, 2) - ex, -ey, rnd(-2, 2) - ez), P(0, 1, 0),
                                  V(rnd(v->fov_lo, v->fov_hi)), W, H) == FXRT_OK);
    fxrt_world_init(&world, COL(0.1, 0.1, 0.2));
    world_set_ambient(&world, amb);
    bool tilt = seed % 3 == 0;
    return world_add_plane(&world, P(0, rnd(-0.5, 0.5), 0),
                           P(tilt ? rnd(-v->tilt, v->tilt) : 0, 1, tilt ? rnd(-v->tilt, v->tilt) : 0),
                           COL(rnd(0, 1), rnd(0, 1), rnd(0, 1)));
}

/* A Phong plane under point lights (light/shade.c,
 * shade_flat_phong_blocks): the runs shade the blocks where every light's
 * specular term is surely 0 with the Lambert sum. An oracle that shares
 * nothing with the blocks' ellipsoid bound: at every such pixel, from
 * the plane's and the lights' stored values in double, the exact hit
 * point of the pixel's camera ray, and there x = r . e with r = 2 (n . l)
 * n - l (n turned to the ray), for each light in front of that side. Its
 * term must be 0: x at most 1 - 12/k less 2^-9 in Q16.16 for k > 12, where
 * numw_pow_int gives 0, and x below -2^-13 otherwise (float and double,
 * and Q16.16 for k <= 12: only x <= 0 gives no term). 40 random scenes:
 * exponents 1 to 1000, tilted planes, one or two point lights (some
 * below the plane), cameras near and far. The blocks must take a fair
 * share of the plane (30 % in Q16.16, 20 % in double, whose bound is x <=
 * 0), and some plane pixels must have a term (the test is not empty). */
static void test_phong_blocks(void)
{
    long plane_px = 0, taken = 0, with_term = 0, bad_px = 0, not_plane = 0;
    double worst = -2;
    for (int seed = 0; seed < 40; seed++) {
        cam_t cam;
        static const plane_view_t view = {6, 8, 0.2, 0.6, 7, 30, 120, 0.5};
        int32_t pid = random_plane(seed, &view, FRAC(0.1, 0.1, 0.1), &cam);
        int k = seed % 5 == 0 ? 1 + (int)rnd(0, 12) : (int)exp(rnd(log(13.0), log(1000.0)));
        material_t m = {0};
        m.kind = MATERIAL_PHONG;
        m.exponent = (uint16_t)k;
        m.specular = FRAC(rnd(0.1, 1), rnd(0.1, 1), rnd(0.1, 1));
        CHECK(world_set_material(&world, pid, &m) == FXRT_OK);
        int nl = 1 + seed % 2;
        for (int i = 0; i < nl; i++)
            CHECK(world_add_light(&world, LIGHT_POINT, P(rnd(-6, 6), seed % 7 == 3 ? -rnd(0.5, 3) : rnd(0.2, 6), rnd(-6, 6)),
                                  P(0, 0, 0), V(0), FRAC(rnd(0.3, 1), rnd(0.3, 1), rnd(0.3, 1)), seed % 4 == 0) == i);
        render(&cam, true);
        memset(lambert_px, 0, sizeof lambert_px);
        render(&cam, false);
        const geom_plane_t *pl = &world.planes[pid];
        double a[3] = {dbl(pl->a.x), dbl(pl->a.y), dbl(pl->a.z)}, n0[3] = {dbl(pl->n.x), dbl(pl->n.y), dbl(pl->n.z)};
        double c = NUM_EXACT && k > 12 ? 1.0 - 12.0 / k - 1.0 / 512 : -1.0 / 8192;
        for (int i = 0; i < W * H; i++) {
            double o[3], d[3];
            if (!px_ray(&cam, i, pid, true, o, d)) {
                not_plane += lambert_px[i];
                continue;
            }
            plane_px++;
            taken += lambert_px[i];
            double dn = d[0] * n0[0] + d[1] * n0[1] + d[2] * n0[2], s = dn > 0 ? -1 : 1;
            double t = ((a[0] - o[0]) * n0[0] + (a[1] - o[1]) * n0[1] + (a[2] - o[2]) * n0[2]) / dn;
            double p[3], dl = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), xmax = -2;
            for (int j = 0; j < 3; j++)
                p[j] = o[j] + t * d[j];
            for (unsigned li = 0; li < world.n_lights; li++) {
                const vec3_t *q = &world.lights[li].position;
                double l[3] = {dbl(q->x) - p[0], dbl(q->y) - p[1], dbl(q->z) - p[2]};
                double ll = sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]), ndl = 0, x = 0;
                for (int j = 0; j < 3; j++)
                    ndl += s * n0[j] * l[j] / ll;
                if (ndl <= 0)
                    continue; /* behind the side seen: no term */
                for (int j = 0; j < 3; j++)
                    x -= (2 * ndl * s * n0[j] - l[j] / ll) * d[j] / dl;
                xmax = x > xmax ? x : xmax;
            }
            with_term += xmax > (NUM_EXACT && k > 12 ? 1.0 - 12.0 / k : 0) + 1.0 / 512;
            if (lambert_px[i]) {
                worst = xmax - c > worst ? xmax - c : worst;
                bad_px += xmax > c;
            }
        }
    }
    CHECK_MSG(bad_px == 0 && not_plane == 0,
              "phong blocks: %ld pixels of the blocks with a term (the largest x lies %.3g above its bound), %ld not "
              "the plane's", bad_px, worst, not_plane);
    CHECK_MSG(taken * 10 > plane_px * (NUM_EXACT ? 3 : 2) && with_term > 0,
              "phong blocks: %ld of %ld plane pixels in blocks without a term, %ld plane pixels with one", taken,
              plane_px, with_term);
    printf("phong blocks (%s): %ld of %ld plane pixels in blocks without a term (%.0f %%), %ld with a term; the "
           "blocks' largest x lies %.3g below its bound\n",
           NUM_NAME, taken, plane_px, 100.0 * taken / plane_px, with_term, -worst);
}

/* A Lambert plane's run under point (and directional) lights that need no
 * shadow ray takes n . l from the run's forms, without a hit point
 * (light/shade.c, shade_plane_forms), and a pixel whose colour lies near
 * a step of its 8-bit value from the hit point's path: the frame must be
 * the one the pixel-by-pixel path gives (the same world rendered with
 * keys, which takes no runs), byte for byte, over 60 random scenes
 * (tilted planes of any colour, 1 to 3 point lights near, far, low and
 * below the plane, with shadows on or off, a directional light in some, a
 * sphere in some: rows that need shadow rays; cameras near and far). And
 * the forms must take most of the plane: the guard's band is narrow. */
static uint8_t img_pixels[W * H * 3];
static void test_plane_forms(void)
{
    long plane_px = 0, formed = 0, diff = 0;
    for (int seed = 0; seed < 60; seed++) {
        cam_t cam;
        static const plane_view_t view = {8, 6, 0.3, 1, 9, 25, 110, 0.6};
        color_t amb = FRAC(rnd(0, 0.3), rnd(0, 0.3), rnd(0, 0.3));
        int32_t pid = random_plane(seed, &view, amb, &cam);
        lit(pid, MATERIAL_LAMBERT, 1);
        int nl = 1 + seed % 3;
        for (int i = 0; i < nl; i++) {
            double h = seed % 7 == 3 && i == 0 ? -rnd(0.5, 3) : seed % 5 == 1 ? rnd(0.1, 0.5) : rnd(0.5, 12);
            CHECK(world_add_light(&world, LIGHT_POINT, P(rnd(-9, 9), h, rnd(-9, 9)), P(0, 0, 0), V(0),
                                  FRAC(rnd(0.1, 1), rnd(0.1, 1), rnd(0.1, 1)), seed % 4 == 0) == i);
        }
        if (seed % 3 == 1)
            CHECK(world_add_light(&world, LIGHT_DIRECTIONAL, P(0, 0, 0), P(rnd(-1, 1), -1, rnd(-1, 1)), V(0),
                                  FRAC(rnd(0.1, 0.6), rnd(0.1, 0.6), rnd(0.1, 0.6)), seed % 2 == 0) == nl);
        if (seed % 5 == 2)
            CHECK(world_add_sphere(&world, P(rnd(-2, 2), rnd(0.5, 2), rnd(-2, 2)), V(rnd(0.3, 1)),
                                   COL(0.5, 0.5, 0.5)) >= 0);
        render(&cam, true);
        memcpy(img_pixels, img, sizeof img);
        long px = count_id((uint16_t)pid);
        plane_px += px;
        render(&cam, false);
        formed += fxrt_stats.plane_forms;
        CHECK_MSG(fxrt_stats.plane_forms <= (uint32_t)px, "plane forms, seed %d: %u pixels from forms of %ld", seed,
                  (unsigned)fxrt_stats.plane_forms, px);
        for (int i = 0; i < W * H * 3; i++)
            diff += img[i] != img_pixels[i];
    }
    CHECK_MSG(diff == 0, "plane forms: %ld channels differ from the pixel-by-pixel path", diff);
    CHECK_MSG(formed * 2 > plane_px, "plane forms: %ld of %ld plane pixels from forms", formed, plane_px);
    printf("plane forms (%s): %ld of %ld plane pixels from the runs' forms (%.0f %%); %ld channels differ from "
           "pixel by pixel\n", NUM_NAME, formed, plane_px, 100.0 * formed / plane_px, diff);
}

int main(void)
{
    test_bounds();
    test_samples();
    test_reuse();
    test_behind();
    test_shadow_cull();
    test_normalisations();
    test_plane_heights();
    test_directional_plane();
    test_raw_phong();
    test_pow();
    test_spot();
    test_spot_blocks();
    test_phong_blocks();
    test_plane_forms();
    test_flat();
    return check_report("test_skip_" NUM_NAME);
}
