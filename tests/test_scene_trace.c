/* test_scene_trace: the reflection, refraction and supersampling part of a
 * scene's description (host/engine.c engine_describe, engine_build,
 * engine_render) in one number type (built once per type):
 *   - reflection is a fraction quantised to 2^-16 like specular (the
 *     description holds both in 1/255 units, the world the fraction), the index
 *     is quantised to 2^-16 too (never below FXRT_INDEX_MIN), so every
 *     build holds the same values, written here as hand-computed multiples
 *     of 2^-16; fields a material does not use are 0;
 *   - the world gets the materials, the depth and the samples;
 *   - a value the core refuses gives "PATH:LINE: ..." with its line; a
 *     depth the build cannot hold is an error only with a reflective or
 *     transparent object;
 *   - keys are those of one ray per pixel whatever the samples, and asking
 *     for them does not change the image. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../core/fxrt.h"
#include "check.h"
#include "engine.h"
#include "engine_build.h"

static double D(num_t a)
{
#if FXRT_NUMBER == FXRT_Q16
    return a / 65536.0;
#else
    return (double)a;
#endif
}

/* n / 65536 exactly: what a quantised value must be in every build. */
static int is_q(num_t v, long n)
{
    return D(v) == (double)n / 65536.0;
}

static int starts(const char *s, const char *prefix)
{
    return strncmp(s, prefix, strlen(prefix)) == 0;
}

static int color_q(color_t c, long r, long g, long b)
{
    return is_q(c.r, r) && is_q(c.g, g) && is_q(c.b, b);
}

static const char *trace =
    "camera perspective eye 8 8 8 gaze -1 -1 -1 up 0 1 0 fov 45\n" /* 1 */
    "ambient 0.25 0.25 0.25\n"                                    /* 2 */
    "light point position 8 8 0 color 1 1 1\n"                    /* 3 */
    "sphere center 0 1 0 radius 1 color 0 1 0 material reflective specular 1 0.3 0 exponent 64 "
    "reflection 0.5 0.999999 0.00002\n"                                                   /* 4 */
    "sphere center 0 2 1.5 radius 0.5 color 1 1 1 material transparent index 1.33\n"      /* 5 */
    "depth 6\n"                                                                           /* 6 */
    "samples 4 adaptive\n"                                                                /* 7 */
    "plane point 0 0 0 normal 0 1 0 color 0.1 0.1 0.1 material reflective specular 0 0 0 exponent 1 "
    "reflection 0.5 0.5 0.5\n"                                                            /* 8 */
    "box min -3 0 -3 max -2 1 -2 color 1 1 1 material transparent index 0.01\n"           /* 9 */
    "triangle a 3 0 0 b 4 0 0 c 3 1 0 color 1 0 0 material transparent index 100\n"       /* 10 */
    "sphere center 3 1 0 radius 1 color 0 0 1 material phong specular 1 1 1 exponent 8\n"; /* 11 */

static scene_t sc;
static engine_desc_t d;
static world_t w;

static void test_describe(void)
{
    char err[256];
    CHECK_MSG(scene_parse("t", trace, strlen(trace), &sc, err, sizeof err) == 0, "%s", err);
    memset(&d, 0xA5, sizeof d);
    CHECK(ENGINE_SYM(engine_describe)(&sc, 32, 24, &d) == 0);
    CHECK(d.count == 6 && d.depth == 6 && d.samples == 4 && d.adaptive && d.bounces);
    /* Reflective: specular 0.3 -> 19660.8 -> 19661; reflection 0.5 ->
     * 32768, 0.999999 -> 65535.93 -> 65536, 0.00002 -> 1.31 -> 1; no index. */
    const material_t *m = &d.obj[0].material;
    CHECK(m->kind == MATERIAL_REFLECTIVE && m->exponent == 64);
    CHECK(color_q(color_fractions(m->specular), 65536, 19661, 0) && color_q(color_fractions(m->reflection), 32768, 65536, 1) && is_q(m->index, 0));
    /* Transparent 1.33 -> 87162.88 -> 87163; no Phong terms, no reflection. */
    m = &d.obj[1].material;
    CHECK(m->kind == MATERIAL_TRANSPARENT && m->exponent == 0 && is_q(m->index, 87163));
    CHECK(color_q(color_fractions(m->specular), 0, 0, 0) && color_q(color_fractions(m->reflection), 0, 0, 0));
    /* The colour tints what it transmits: still in 1/255 units. */
    CHECK(D(d.obj[1].color.r) == 255.0);
    m = &d.obj[2].material;
    CHECK(m->kind == MATERIAL_REFLECTIVE && m->exponent == 1 && color_q(color_fractions(m->specular), 0, 0, 0));
    CHECK(color_q(color_fractions(m->reflection), 32768, 32768, 32768));
    /* 0.01 * 65536 = 655.36 would round to 655 (< 0.01): the smallest
     * multiple of 2^-16 not below 0.01 is 656. 100 is 6553600 exactly. */
    m = &d.obj[3].material;
    CHECK(m->kind == MATERIAL_TRANSPARENT && is_q(m->index, 656));
    CHECK(D(m->index) >= 0.01);
    m = &d.obj[4].material;
    CHECK(m->kind == MATERIAL_TRANSPARENT && is_q(m->index, 6553600));
    /* Phong keeps no reflection and no index. */
    m = &d.obj[5].material;
    CHECK(m->kind == MATERIAL_PHONG && m->exponent == 8 && color_q(color_fractions(m->reflection), 0, 0, 0) && is_q(m->index, 0));
    /* engine_index directly: ties and the clamp. 1.5 -> 98304; 0.010009 ->
     * 655.95 -> 656; 0.0100099 -> 656.01 -> 656; 0.0101 -> 661.9 -> 662. */
    CHECK(is_q(ENGINE_SYM(engine_index)(1.5), 98304));
    CHECK(is_q(ENGINE_SYM(engine_index)(0.010009), 656));
    CHECK(is_q(ENGINE_SYM(engine_index)(0.0101), 662));
    CHECK(is_q(ENGINE_SYM(engine_index)(1.0), 65536));
}

static void test_build(void)
{
    char err[256];
    cam_t cam;
    CHECK_MSG(ENGINE_SYM(engine_build)("t", &sc, 32, 24, &w, &cam, err, sizeof err) == 0, "%s", err);
#if FXRT_MAX_DEPTH >= 6
    CHECK(world_depth(&w) == 6);
#endif
    CHECK(world_samples(&w) == (FXRT_MAX_SAMPLES >= 4 ? 4 : 1));
    CHECK(world_adaptive(&w) == (FXRT_MAX_SAMPLES >= 4 && FXRT_ADAPTIVE));
#if FXRT_MAX_DEPTH > 0
    CHECK(w.n_bounce == 5);
#endif
#if FXRT_MAX_LIGHTS > 0
    CHECK(w.n_lit == 6);
    geom_kind_t k;
    uint16_t idx;
    for (int i = 0; i < d.count; i++) {
        CHECK(world_find(&w, i, &k, &idx));
        /* The world holds the description's colours (1/255 units) as fractions. */
        const material_t *a = &world_common(&w, k, idx)->mat, *b = &d.obj[i].material;
        color_t br = color_fractions(b->reflection), bs = color_fractions(b->specular);
        CHECK_MSG(a->kind == b->kind && a->exponent == b->exponent && a->index == b->index &&
                      a->reflection.r == br.r && a->reflection.g == br.g && a->reflection.b == br.b &&
                      a->specular.g == bs.g,
                  "object %d", i);
    }
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
    bad.depth = 17;
    CHECK(ENGINE_SYM(engine_build)("t", &bad, 32, 24, &w, &cam, err, sizeof err) == -1);
    CHECK_MSG(starts(err, "t:6: depth 17 cannot be set in " NUM_NAME ": ") && strstr(err, "FXRT_MAX_DEPTH"),
              "%s", err);
    /* Without a 'depth' line: the first reflective or transparent object's. */
    bad.depth_line = 0;
    CHECK(ENGINE_SYM(engine_build)("t", &bad, 32, 24, &w, &cam, err, sizeof err) == -1);
    CHECK_MSG(starts(err, "t:4: depth 17 cannot be set"), "%s", err);
    bad.depth = -1;
    CHECK(ENGINE_SYM(engine_build)("t", &bad, 32, 24, &w, &cam, err, sizeof err) == -1);
    CHECK_MSG(starts(err, "t:4: depth -1 cannot be set"), "%s", err);
    /* Without such objects the depth changes nothing: not an error, and
     * the world keeps its default. */
    bad.count = 0;
    CHECK_MSG(ENGINE_SYM(engine_build)("t", &bad, 32, 24, &w, &cam, err, sizeof err) == 0, "%s", err);
    CHECK(world_depth(&w) == (FXRT_MAX_DEPTH < 4 ? FXRT_MAX_DEPTH : 4));
    bad = sc;
    bad.samples = 17;
    CHECK(ENGINE_SYM(engine_build)("t", &bad, 32, 24, &w, &cam, err, sizeof err) == -1);
    CHECK_MSG(starts(err, "t:7: samples 17 adaptive cannot be set in " NUM_NAME ": "), "%s", err);
    bad = sc;
    bad.samples = 1;
    CHECK(ENGINE_SYM(engine_build)("t", &bad, 32, 24, &w, &cam, err, sizeof err) == -1);
    CHECK_MSG(starts(err, "t:7: samples 1 adaptive cannot be set") && strstr(err, "adaptive"), "%s", err);
    bad = sc;
    bad.obj[0].reflection[1] = 1.5;
    CHECK(ENGINE_SYM(engine_build)("t", &bad, 32, 24, &w, &cam, err, sizeof err) == -1);
    CHECK_MSG(starts(err, "t:4: sphere cannot be built in " NUM_NAME ": "), "%s", err);
    bad = sc;
    bad.obj[1].index = 101;
    CHECK(ENGINE_SYM(engine_build)("t", &bad, 32, 24, &w, &cam, err, sizeof err) == -1);
    CHECK_MSG(starts(err, "t:5: sphere cannot be built in"), "%s", err);
    bad = sc;
    bad.obj[3].index = 0.005;
    CHECK(ENGINE_SYM(engine_build)("t", &bad, 32, 24, &w, &cam, err, sizeof err) == 0);
    CHECK(is_q(ENGINE_SYM(engine_index)(0.005), 656)); /* clamped: the parser refuses 0.005 before */
}

/* Scenes without the new keywords: depth 4 and one sample, in the
 * description and the world. */
static void test_defaults(void)
{
    static const char *flat = "camera perspective eye 0 0 0 gaze 0 0 -1 up 0 1 0 fov 45\n"
                              "sphere center 0 0 -3 radius 0.5 color 1 0 0 material lambert\n";
    static scene_t s;
    char err[256];
    cam_t cam;
    CHECK_MSG(scene_parse("t", flat, strlen(flat), &s, err, sizeof err) == 0, "%s", err);
    memset(&d, 0xA5, sizeof d);
    ENGINE_SYM(engine_describe)(&s, 16, 16, &d);
    CHECK(d.depth == 4 && d.samples == 1 && !d.adaptive && !d.bounces);
    CHECK(color_q(d.obj[0].material.reflection, 0, 0, 0) && is_q(d.obj[0].material.index, 0));
    CHECK_MSG(ENGINE_SYM(engine_build)("t", &s, 16, 16, &w, &cam, err, sizeof err) == 0, "%s", err);
    CHECK(world_depth(&w) == (FXRT_MAX_DEPTH < 4 ? FXRT_MAX_DEPTH : 4));
    CHECK(world_samples(&w) == 1 && !world_adaptive(&w));
}

/* Keys are one ray's per pixel (at the centre) at any samples, so they do
 * not change with 'samples'; and the key pass leaves the image as it is
 * without keys. */
static void test_keys(void)
{
    enum { W = 40, H = 30 };
    static const char *variants[] = {"", "samples 4\n", "samples 3 adaptive\n"};
    static uint8_t rgb[3 * W * H], rgb2[3 * W * H];
    static uint32_t keys1[W * H], keys[W * H];
    static char text[4096];
    static scene_t s;
    char err[256];
    /* The trace scene without its samples line (line 7). */
    const char *cut = strstr(trace, "samples 4 adaptive\n");
    for (size_t v = 0; v < sizeof variants / sizeof variants[0]; v++) {
        snprintf(text, sizeof text, "%.*s%s%s", (int)(cut - trace), trace, variants[v],
                 cut + strlen("samples 4 adaptive\n"));
        CHECK_MSG(scene_parse("t", text, strlen(text), &s, err, sizeof err) == 0, "%s", err);
        uint32_t *k = v == 0 ? keys1 : keys;
        memset(k, 0xA5, sizeof keys);
        CHECK_MSG(ENGINE_SYM(engine_render)("t", &s, W, H, ENGINE_FAST, rgb, k, err, sizeof err) == 0, "%s", err);
        int objects = 0;
        for (int i = 0; i < W * H; i++)
            objects += k[i] != ENGINE_KEY_MISS;
        CHECK_MSG(objects > W * H / 10, "variant %zu: %d object pixels", v, objects);
        if (v > 0)
            CHECK_MSG(memcmp(keys, keys1, sizeof keys) == 0, "variant %zu: keys differ from one sample's", v);
        CHECK_MSG(ENGINE_SYM(engine_render)("t", &s, W, H, ENGINE_FAST, rgb2, NULL, err, sizeof err) == 0, "%s", err);
        CHECK_MSG(memcmp(rgb, rgb2, sizeof rgb) == 0, "variant %zu: image with keys differs from without", v);
    }
}

int main(void)
{
    test_describe();
    test_build();
    test_refusals();
    test_defaults();
    test_keys();
    return check_report("test_scene_trace_" NUM_NAME);
}
