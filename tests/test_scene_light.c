/* test_scene_light: the lighting part of a scene's description
 * (host/engine.c engine_describe, engine_build) in one number type (built
 * once per type): light colours, ambient and specular are fractions
 * quantised to 2^-16, so every build holds the same values, written here
 * as hand-computed multiples of 2^-16; unused fields are 0; lights and
 * materials reach the world in scene order; a value the core refuses
 * gives "PATH:LINE: ..." with the line of its statement. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../core/fxrt.h"
#include "check.h"
#include "engine_build.h"

static double D(num_t a)
{
#if FXRT_NUMBER == FXRT_Q16
    return a / 65536.0;
#else
    return (double)a;
#endif
}

/* n / 65536 exactly: what a fraction must be in every build. */
static int is_q(num_t v, long n)
{
    return D(v) == (double)n / 65536.0;
}

static int vec_is(vec3_t v, double x, double y, double z)
{
    return D(v.x) == x && D(v.y) == y && D(v.z) == z;
}

static const char *lit =
    "camera perspective eye 4 4 4 gaze -1 -1 -1 up 0 1 0 fov 45\n"           /* 1 */
    "ambient 0.1 0.00002 1\n"                                                /* 2 */
    "light point position 4 3.5 -2 color 0.7 0.3 1\n"                        /* 3 */
    "light directional direction -1 -2 -2 color 0.00002 0 0.5 shadows off\n" /* 4 */
    "light spot position 4 4 4 direction -1 -1 -1 angle 12.86 color 1 1 1\n" /* 5 */
    "sphere center 1 1 1 radius 0.5 color 0 1 0 material phong specular 0.3 0.999999 0.1 exponent 64\n"
    "plane point 0 0 0 normal 0 1 0 color 1 0 0 material lambert\n"
    "box min 0 0 0 max 1 1 1 color 0 0 1\n";

static scene_t sc;
static engine_desc_t d;
static world_t w;

static void test_describe(void)
{
    char err[256];
    CHECK_MSG(scene_parse("t", lit, strlen(lit), &sc, err, sizeof err) == 0, "%s", err);
    CHECK(ENGINE_SYM(engine_describe)(&sc, 64, 48, &d) == 0);
    /* 0.1 * 65536 = 6553.6 -> 6554; 0.00002 * 65536 = 1.31 -> 1. */
    /* The description holds every colour in 1/255 units, as the API takes
     * it (0.1 -> 25.5); the world holds the fraction (color_fractions). */
    CHECK(D(d.ambient.r) == 25.5);
    color_t a = color_fractions(d.ambient);
    CHECK(is_q(a.r, 6554) && is_q(a.g, 1) && is_q(a.b, 65536));
    CHECK(d.nlights == 3);
    const fxrt_light_t *l = &d.lights[0];
    CHECK(l->kind == LIGHT_POINT && vec_is(l->position, 4, 3.5, -2) && vec_is(l->direction, 0, 0, 0));
    CHECK(l->angle_deg == NUM_ZERO && l->shadows);
    /* 0.7 -> 45875.2 -> 45875; 0.3 -> 19660.8 -> 19661. */
    color_t c = color_fractions(l->color);
    CHECK(is_q(c.r, 45875) && is_q(c.g, 19661) && is_q(c.b, 65536));
    l = &d.lights[1];
    CHECK(l->kind == LIGHT_DIRECTIONAL && vec_is(l->direction, -1, -2, -2) && vec_is(l->position, 0, 0, 0));
    CHECK(l->angle_deg == NUM_ZERO && !l->shadows);
    c = color_fractions(l->color);
    CHECK(is_q(c.r, 1) && is_q(c.g, 0) && is_q(c.b, 32768));
    l = &d.lights[2];
    CHECK(l->kind == LIGHT_SPOT && vec_is(l->position, 4, 4, 4) && vec_is(l->direction, -1, -1, -1));
    CHECK(l->shadows);
    /* The angle is a plain scene value like fov: within half an LSB of Q16.16. */
    CHECK_MSG(fabs(D(l->angle_deg) - 12.86) <= 0.5 / 65536.0, "angle %.9g", D(l->angle_deg));
    /* Materials: phong with specular 0.3 -> 19661, 0.999999 -> 65536 (rounds
     * up to full), 0.1 -> 6554; lambert and flat with zero extras. */
    const material_t *m = &d.obj[0].material;
    CHECK(m->kind == MATERIAL_PHONG && m->exponent == 64);
    c = color_fractions(m->specular);
    CHECK(is_q(c.r, 19661) && is_q(c.g, 65536) && is_q(c.b, 6554));
    m = &d.obj[1].material;
    CHECK(m->kind == MATERIAL_LAMBERT && m->exponent == 0 && is_q(m->specular.r, 0) && is_q(m->specular.b, 0));
    m = &d.obj[2].material;
    CHECK(m->kind == MATERIAL_FLAT && m->exponent == 0 && is_q(m->specular.g, 0));
    /* A flat-colour channel is still in 1/255 units (engine_channel). */
    CHECK(D(d.obj[0].color.g) == 255.0);
}

static void test_build(void)
{
    char err[256];
    cam_t cam;
    CHECK_MSG(ENGINE_SYM(engine_build)("t", &sc, 64, 48, &w, &cam, err, sizeof err) == 0, "%s", err);
#if FXRT_MAX_LIGHTS > 0
    CHECK(w.n_lights == 3 && w.n_lit == 2);
    color_t a = color_fractions(d.ambient);
    CHECK(w.ambient.r == a.r && w.ambient.g == a.g && w.ambient.b == a.b);
    for (int i = 0; i < 3; i++) {
        CHECK(w.lights[i].kind == (uint8_t)d.lights[i].kind && w.lights[i].shadows == d.lights[i].shadows);
        color_t c = color_fractions(d.lights[i].color);
        CHECK(w.lights[i].color.r == c.r && w.lights[i].color.b == c.b);
    }
    /* Directional: the unit vector towards the light, (1, 2, 2) / 3. */
    CHECK_MSG(fabs(D(w.lights[1].dir.x) - 1.0 / 3) < 1e-4 && fabs(D(w.lights[1].dir.y) - 2.0 / 3) < 1e-4 &&
                  fabs(D(w.lights[1].dir.z) - 2.0 / 3) < 1e-4,
              "dir %g %g %g", D(w.lights[1].dir.x), D(w.lights[1].dir.y), D(w.lights[1].dir.z));
    /* Spot: cos(12.86 degrees). */
    CHECK_MSG(fabs(D(w.lights[2].cos_angle) - cos(12.86 * 3.14159265358979323846 / 180)) < 1e-4, "cos %g",
              D(w.lights[2].cos_angle));
    geom_kind_t k;
    uint16_t idx;
    CHECK(world_find(&w, 0, &k, &idx) && k == GEOM_SPHERE);
    const geom_common_t *c = world_common(&w, k, idx);
    CHECK(c->mat.kind == MATERIAL_PHONG && c->mat.exponent == 64 && c->mat.specular.r == color_fractions(d.obj[0].material.specular).r);
#endif
}

/* Values the parser never lets through, put into a scene_t by hand: the
 * core refuses them and the message names the statement's line. */
static void test_refusals(void)
{
    char err[256];
    cam_t cam;
    static scene_t bad;

    bad = sc;
    bad.light[1].color[2] = 1.5;
    CHECK(ENGINE_SYM(engine_build)("t", &bad, 64, 48, &w, &cam, err, sizeof err) == -1);
    CHECK_MSG(strncmp(err, "t:4: light cannot be added in " NUM_NAME ": ", 30) == 0, "%s", err);
    bad = sc;
    bad.light[2].angle_deg = 95;
    CHECK(ENGINE_SYM(engine_build)("t", &bad, 64, 48, &w, &cam, err, sizeof err) == -1);
    CHECK_MSG(strncmp(err, "t:5: light cannot be added", 26) == 0 && strstr(err, "half-angle"), "%s", err);
    bad = sc;
    bad.ambient[0] = 2;
    CHECK(ENGINE_SYM(engine_build)("t", &bad, 64, 48, &w, &cam, err, sizeof err) == -1);
    CHECK_MSG(strncmp(err, "t:2: ambient cannot be set in " NUM_NAME ": ", 30) == 0, "%s", err);
    bad = sc;
    bad.obj[0].exponent = 2000;
    CHECK(ENGINE_SYM(engine_build)("t", &bad, 64, 48, &w, &cam, err, sizeof err) == -1);
    CHECK_MSG(strncmp(err, "t:6: sphere cannot be built in", 30) == 0, "%s", err);
}

/* Scenes without the new keywords: every object flat, no lights, black
 * ambient, in the description and the world. */
static void test_flat(void)
{
    static const char *flat = "camera perspective eye 0 0 0 gaze 0 0 -1 up 0 1 0 fov 45\n"
                              "sphere center 0 0 -3 radius 0.5 color 1 0 0\n";
    char err[256];
    cam_t cam;
    CHECK_MSG(scene_parse("t", flat, strlen(flat), &sc, err, sizeof err) == 0, "%s", err);
    memset(&d, 0xA5, sizeof d);
    ENGINE_SYM(engine_describe)(&sc, 16, 16, &d);
    CHECK(d.nlights == 0 && d.obj[0].material.kind == MATERIAL_FLAT && d.obj[0].material.exponent == 0);
    CHECK(is_q(d.ambient.r, 0) && is_q(d.ambient.g, 0) && is_q(d.ambient.b, 0));
    CHECK_MSG(ENGINE_SYM(engine_build)("t", &sc, 16, 16, &w, &cam, err, sizeof err) == 0, "%s", err);
#if FXRT_MAX_LIGHTS > 0
    CHECK(w.n_lights == 0 && w.n_lit == 0);
#endif
}

int main(void)
{
    test_describe();
    test_build();
    test_refusals();
    test_flat();
    return check_report("test_scene_light_" NUM_NAME);
}
