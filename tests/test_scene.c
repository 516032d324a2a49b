/* Tests for the scene parser (host/scene.c): good scenes parse into the
 * expected values, every kind of bad input fails with "NAME:LINE: message",
 * and the files in tests/bad-scenes fail as their "# expect:" line says.
 * Run from the repository root (the bad-scene files are found from cwd). */
#include <dirent.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "scene.h"

#define BAD_SCENES_DIR "tests/bad-scenes"

/* Turn a numeric config macro into a string for expected messages, so the
 * tests still match when limits are overridden with -D. */
#define STR_(x) #x
#define STR(x) STR_(x)

#define CAM "camera perspective eye 0 0 0 gaze 0 0 -1 up 0 1 0 fov 45\n"

/* Shared by all tests: scene_t is tens of KiB, too big to want on the stack
 * of every helper. */
static scene_t g_scene;
static char g_err[512];

/* Parse through an exactly-sized heap copy without a terminating NUL, so
 * ASan flags any read past len. */
static int parse_len(const char *text, size_t len)
{
    char *buf = malloc(len ? len : 1);
    int rc;

    if (buf == NULL) {
        fprintf(stderr, "out of memory\n");
        exit(2);
    }
    memcpy(buf, text, len);
    memset(g_err, 'x', sizeof g_err);
    g_err[sizeof g_err - 1] = '\0';
    rc = scene_parse("t", buf, len, &g_scene, g_err, sizeof g_err);
    free(buf);
    return rc;
}

static int parse_str(const char *text)
{
    return parse_len(text, strlen(text));
}

/* Check that text fails on `line` with a message containing frag. */
static void expect_error_len(const char *text, size_t len, int line, const char *frag,
                             const char *where)
{
    char prefix[32];
    int rc = parse_len(text, len);

    snprintf(prefix, sizeof prefix, "t:%d: ", line);
    CHECK_MSG(rc == -1, "%s: rc %d, expected -1", where, rc);
    CHECK_MSG(strncmp(g_err, prefix, strlen(prefix)) == 0,
              "%s: err \"%s\" does not start with \"%s\"", where, g_err, prefix);
    CHECK_MSG(strstr(g_err, frag) != NULL, "%s: err \"%s\" lacks \"%s\"", where,
              g_err, frag);
}

#define HERE "line " STR(__LINE__)
#define EXPECT_ERROR(text, line, frag) expect_error_len(text, strlen(text), line, frag, HERE)

static int near(double a, double b)
{
    return fabs(a - b) <= 1e-12;
}

static int vec_is(scene_vec_t v, double x, double y, double z)
{
    return near(v.x, x) && near(v.y, y) && near(v.z, z);
}

static int color_is(const double *c, double r, double g, double b)
{
    return near(c[0], r) && near(c[1], g) && near(c[2], b);
}

static const char *good_scene =
    "# comment\n"
    "image 640 430                     # default size\n"
    "background 0 0 0                  # default black\n"
    "camera perspective eye 0 0 0 gaze 0 0 -1 up 0 1 0 fov 45\n"
    "plane point 0 -1 0 normal 0 1 0 color 0 1 0\n"
    "sphere center 0 0 -3 radius 0.5 color 1 0 0\n"
    "triangle a -0.5 0.5 -3 b 0.5 0.5 -3 c 0.5 -0.5 -3 color 1 0 1\n"
    "box min -0.5 0 -0.5 max 0.5 1 0.5 color 0 0 1\n";

/* The values of good_scene, whatever line endings or layout it came in. */
static void check_good_values(const scene_t *s, const char *where)
{
    CHECK_MSG(s->width == 640 && s->height == 430, "from %s", where);
    CHECK_MSG(color_is(s->background, 0, 0, 0), "from %s", where);
    CHECK_MSG(s->camera.kind == SCENE_CAM_PERSPECTIVE, "from %s", where);
    CHECK_MSG(vec_is(s->camera.eye, 0, 0, 0), "from %s", where);
    CHECK_MSG(vec_is(s->camera.gaze, 0, 0, -1), "from %s", where);
    CHECK_MSG(vec_is(s->camera.up, 0, 1, 0), "from %s", where);
    CHECK_MSG(near(s->camera.fov_deg, 45), "from %s", where);
    CHECK_MSG(s->count == 4, "from %s: count %d", where, s->count);
    if (s->count != 4)
        return;
    CHECK_MSG(s->obj[0].kind == SCENE_PLANE && s->obj[0].line == 5, "from %s", where);
    CHECK_MSG(vec_is(s->obj[0].p[0], 0, -1, 0), "from %s", where);
    CHECK_MSG(vec_is(s->obj[0].p[1], 0, 1, 0), "from %s", where);
    CHECK_MSG(color_is(s->obj[0].color, 0, 1, 0), "from %s", where);

    CHECK_MSG(s->obj[1].kind == SCENE_SPHERE && s->obj[1].line == 6, "from %s", where);
    CHECK_MSG(vec_is(s->obj[1].p[0], 0, 0, -3), "from %s", where);
    CHECK_MSG(near(s->obj[1].radius, 0.5), "from %s", where);
    CHECK_MSG(color_is(s->obj[1].color, 1, 0, 0), "from %s", where);

    CHECK_MSG(s->obj[2].kind == SCENE_TRIANGLE && s->obj[2].line == 7, "from %s", where);
    CHECK_MSG(vec_is(s->obj[2].p[0], -0.5, 0.5, -3), "from %s", where);
    CHECK_MSG(vec_is(s->obj[2].p[1], 0.5, 0.5, -3), "from %s", where);
    CHECK_MSG(vec_is(s->obj[2].p[2], 0.5, -0.5, -3), "from %s", where);
    CHECK_MSG(color_is(s->obj[2].color, 1, 0, 1), "from %s", where);

    CHECK_MSG(s->obj[3].kind == SCENE_BOX && s->obj[3].line == 8, "from %s", where);
    CHECK_MSG(vec_is(s->obj[3].p[0], -0.5, 0, -0.5), "from %s", where);
    CHECK_MSG(vec_is(s->obj[3].p[1], 0.5, 1, 0.5), "from %s", where);
    CHECK_MSG(color_is(s->obj[3].color, 0, 0, 1), "from %s", where);
}

static void test_good_scene(void)
{
    CHECK_MSG(parse_str(good_scene) == 0, "%s", g_err);
    check_good_values(&g_scene, HERE);
}

static void test_crlf(void)
{
    char buf[2048];
    size_t i, n = 0;

    for (i = 0; good_scene[i] != '\0' && n + 2 < sizeof buf; i++) {
        if (good_scene[i] == '\n')
            buf[n++] = '\r';
        buf[n++] = good_scene[i];
    }
    CHECK_MSG(parse_len(buf, n) == 0, "%s", g_err);
    check_good_values(&g_scene, HERE);
    /* An error in a CRLF file still reports the right line. */
    EXPECT_ERROR("# x\r\n" CAM "sphere center 0 0 -3 radius -1 color 0 0 0\r\n", 3,
                 "radius must be > 0, got -1");
    /* A CR just before the end of text (no final LF) is a line ending too. */
    CHECK_MSG(parse_str("camera orthographic eye 0 0 0 gaze 0 0 -1 up 0 1 0 scale 4\r") == 0,
              "%s", g_err);
}

static void test_orthographic_and_defaults(void)
{
    CHECK_MSG(parse_str("camera orthographic eye 1 2 3 gaze 0 0 -1 up 0 1 0 scale 4\n") == 0,
              "%s", g_err);
    CHECK(g_scene.camera.kind == SCENE_CAM_ORTHOGRAPHIC);
    CHECK(near(g_scene.camera.scale, 4));
    CHECK(vec_is(g_scene.camera.eye, 1, 2, 3));
    CHECK(g_scene.width == SCENE_DEFAULT_WIDTH && g_scene.height == SCENE_DEFAULT_HEIGHT);
    CHECK(color_is(g_scene.background, 0, 0, 0));
    CHECK(g_scene.count == 0);
}

static void test_comments_order_layout(void)
{
    /* Comments: whole-line, trailing, glued to a token, with UTF-8;
     * blank and whitespace-only lines; tabs; fields in any order. */
    const char *text = "\n"
                       "   \t \n"
                       "# caf\xc3\xa9 \xff comment\n"
                       "background 0.25 0.5 1# glued\n"
                       "camera\tperspective fov 60 up 0 1 0\t\tgaze 0 0 -1 eye 1 2 3 # trailing\n"
                       "sphere color 1 0 0 radius 0.5 center 0 0 -3\n"
                       "box max 1 1 1 color 0 0 1 min 0 0 0\n"
                       "triangle color 1 1 1 c 0 1 0 b 1 0 0 a 0 0 0\n"
                       "plane color 0 1 0 normal 0 2 0 point 0 -1 0\n"
                       "# the end";
    CHECK_MSG(parse_str(text) == 0, "%s", g_err);
    CHECK(color_is(g_scene.background, 0.25, 0.5, 1));
    CHECK(near(g_scene.camera.fov_deg, 60) && vec_is(g_scene.camera.eye, 1, 2, 3));
    CHECK(g_scene.count == 4);
    CHECK(g_scene.obj[0].kind == SCENE_SPHERE && vec_is(g_scene.obj[0].p[0], 0, 0, -3));
    CHECK(near(g_scene.obj[0].radius, 0.5) && g_scene.obj[0].line == 6);
    CHECK(vec_is(g_scene.obj[1].p[0], 0, 0, 0) && vec_is(g_scene.obj[1].p[1], 1, 1, 1));
    CHECK(vec_is(g_scene.obj[2].p[0], 0, 0, 0) && vec_is(g_scene.obj[2].p[1], 1, 0, 0));
    CHECK(vec_is(g_scene.obj[2].p[2], 0, 1, 0));
    /* The normal is stored as given, not normalised. */
    CHECK(vec_is(g_scene.obj[3].p[1], 0, 2, 0));

    /* No trailing newline on the last (statement) line. */
    CHECK_MSG(parse_str(CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0") == 0, "%s", g_err);
    CHECK(g_scene.count == 1 && g_scene.obj[0].line == 2 && near(g_scene.obj[0].radius, 0.5));
    /* An error on a last line without newline. */
    EXPECT_ERROR(CAM "sphere center 0 0 -3 radius 0.5 color 1 0 2", 2,
                 "color component 2 outside 0..1");
}


/* Lighting: the example lines, then every field in another order,
 * defaults and the values as stored. */
static const char *lit_scene =
    "camera perspective eye 4 4 4 gaze -1 -1 -1 up 0 1 0 fov 45\n"
    "ambient 0.1 0.2 0.3\n"
    "light point position 4 4 4 color 1 1 1\n"
    "light directional direction -1 -1 -1 color 1 0.5 0 shadows off\n"
    "light spot position 4 4 4 direction -1 -1 -1 angle 12.86 color 0.25 1 1 shadows on\n"
    "sphere center 1 1 1 radius 0.5 color 0 1 0 material phong specular 1 0.5 0 exponent 64\n"
    "plane point 0 0 0 normal 0 1 0 color 1 0 0 material lambert\n"
    "box min -1.5 0.5 0.5 max -0.5 1.5 1.5 color 0 0 1 material flat\n"
    "triangle a 0 0 -1 b 1 0 -1 c 1 1 -1 color 1 1 0\n"
    "light shadows off color 0 0 1 angle 90 direction 0 -1 0 position 0 5 0 spot\n";

static void test_lights_materials(void)
{
    const scene_light_t *l;

    /* 'spot' after the fields is not a light type: the type comes second. */
    EXPECT_ERROR(lit_scene, 10, "unknown light type 'shadows'");
    CHECK_MSG(parse_len(lit_scene, strlen(lit_scene) - strlen("light shadows off color 0 0 1 angle 90 "
                                                               "direction 0 -1 0 position 0 5 0 spot\n")) == 0,
              "%s", g_err);
    CHECK(color_is(g_scene.ambient, 0.1, 0.2, 0.3) && g_scene.ambient_line == 2);
    CHECK(g_scene.nlights == 3);
    l = &g_scene.light[0];
    CHECK(l->kind == SCENE_LIGHT_POINT && l->line == 3 && vec_is(l->position, 4, 4, 4));
    CHECK(vec_is(l->direction, 0, 0, 0) && l->angle_deg == 0 && color_is(l->color, 1, 1, 1));
    CHECK(l->shadows == 1); /* default on */
    l = &g_scene.light[1];
    CHECK(l->kind == SCENE_LIGHT_DIRECTIONAL && l->line == 4 && vec_is(l->direction, -1, -1, -1));
    CHECK(vec_is(l->position, 0, 0, 0) && color_is(l->color, 1, 0.5, 0) && l->shadows == 0);
    l = &g_scene.light[2];
    CHECK(l->kind == SCENE_LIGHT_SPOT && l->line == 5 && vec_is(l->position, 4, 4, 4));
    CHECK(vec_is(l->direction, -1, -1, -1) && near(l->angle_deg, 12.86) && l->shadows == 1);
    CHECK(color_is(l->color, 0.25, 1, 1));
    CHECK(g_scene.count == 4);
    CHECK(g_scene.obj[0].material == SCENE_MAT_PHONG && g_scene.obj[0].exponent == 64);
    CHECK(color_is(g_scene.obj[0].specular, 1, 0.5, 0));
    CHECK(g_scene.obj[1].material == SCENE_MAT_LAMBERT && g_scene.obj[1].exponent == 0);
    CHECK(color_is(g_scene.obj[1].specular, 0, 0, 0));
    CHECK(g_scene.obj[2].material == SCENE_MAT_FLAT && g_scene.obj[3].material == SCENE_MAT_FLAT);

    /* Fields in any order, for lights and for the material fields. */
    CHECK_MSG(parse_str(CAM "light spot shadows off color 0 0 1 angle 90 direction 0 -1 0 position 0 5 0\n"
                            "sphere exponent 1024 material phong color 1 1 1 specular 0 0 0 radius 1 "
                            "center 0 0 -3\n"
                            "triangle material lambert color 1 1 1 c 0 1 0 b 1 0 0 a 0 0 0\n"
                            "light directional color 0 0 0 direction 0 0.00002 0\n") == 0,
              "%s", g_err);
    CHECK(g_scene.nlights == 2 && g_scene.light[0].kind == SCENE_LIGHT_SPOT && g_scene.light[0].line == 2);
    CHECK(g_scene.light[0].angle_deg == 90 && g_scene.light[0].shadows == 0);
    CHECK(vec_is(g_scene.light[0].position, 0, 5, 0) && vec_is(g_scene.light[0].direction, 0, -1, 0));
    CHECK(g_scene.obj[0].material == SCENE_MAT_PHONG && g_scene.obj[0].exponent == 1024);
    CHECK(g_scene.obj[1].kind == SCENE_TRIANGLE && g_scene.obj[1].material == SCENE_MAT_LAMBERT);
    /* Exponent 1, spot angle just above 0, lights before the camera. */
    CHECK_MSG(parse_str("light spot position 0 0 0 direction 1 0 0 angle 0.001 color 1 1 1\n" CAM
                        "box min 0 0 0 max 1 1 1 color 1 1 1 material phong exponent 1 specular 1 1 1\n") == 0,
              "%s", g_err);
    CHECK(g_scene.obj[0].exponent == 1 && g_scene.light[0].line == 1);
    /* Without the new keywords: flat, no lights, black ambient. */
    CHECK_MSG(parse_str(good_scene) == 0, "%s", g_err);
    CHECK(g_scene.nlights == 0 && g_scene.ambient_line == 0 && color_is(g_scene.ambient, 0, 0, 0));
    for (int i = 0; i < g_scene.count; i++)
        CHECK(g_scene.obj[i].material == SCENE_MAT_FLAT && g_scene.obj[i].exponent == 0);
}

/* Reflection, refraction and supersampling: the example lines,
 * fields in any order, the limits, defaults and the values as stored. */
static const char *trace_scene =
    "camera perspective eye 8 8 8 gaze -1 -1 -1 up 0 1 0 fov 45\n"
    "sphere center 0 1 0 radius 1 color 0 1 0 material reflective specular 1 1 1 exponent 64 reflection 0.5 0.5 0.5\n"
    "sphere center 0 2 1.5 radius 0.5 color 1 1 1 material transparent index 1.33\n"
    "depth 6            # largest number of bounces\n"
    "samples 4          # N x N rays per pixel\n"
    "plane point 0 0 0 normal 0 1 0 color 0.1 0.1 0.1 material reflective specular 0 0 0 exponent 1 reflection 0.5 0.25 1\n"
    "box reflection 0 0.75 1 exponent 1024 max 1 1 1 material reflective color 1 0 0 specular 0.5 0 1 min 0 0 0\n"
    "triangle index 100 a 0 0 0 b 1 0 0 c 0 1 0 material transparent color 1 1 1\n"
    "sphere material transparent center 0 0 0 index 0.01 radius 1 color 0 0 1\n";

static void test_trace_keywords(void)
{
    const scene_obj_t *o;

    CHECK_MSG(parse_str(trace_scene) == 0, "%s", g_err);
    CHECK(g_scene.count == 6);
    o = &g_scene.obj[0];
    CHECK(o->material == SCENE_MAT_REFLECTIVE && o->exponent == 64 && color_is(o->specular, 1, 1, 1));
    CHECK(color_is(o->reflection, 0.5, 0.5, 0.5) && o->index == 0);
    o = &g_scene.obj[1];
    CHECK(o->material == SCENE_MAT_TRANSPARENT && o->index == 1.33 && o->exponent == 0);
    CHECK(color_is(o->specular, 0, 0, 0) && color_is(o->reflection, 0, 0, 0) && color_is(o->color, 1, 1, 1));
    o = &g_scene.obj[2];
    CHECK(o->kind == SCENE_PLANE && o->material == SCENE_MAT_REFLECTIVE && o->exponent == 1);
    CHECK(color_is(o->specular, 0, 0, 0) && color_is(o->reflection, 0.5, 0.25, 1) && o->line == 6);
    o = &g_scene.obj[3];
    CHECK(o->kind == SCENE_BOX && o->material == SCENE_MAT_REFLECTIVE && o->exponent == 1024);
    CHECK(color_is(o->specular, 0.5, 0, 1) && color_is(o->reflection, 0, 0.75, 1));
    CHECK(vec_is(o->p[0], 0, 0, 0) && vec_is(o->p[1], 1, 1, 1) && color_is(o->color, 1, 0, 0));
    o = &g_scene.obj[4];
    CHECK(o->kind == SCENE_TRIANGLE && o->material == SCENE_MAT_TRANSPARENT && o->index == 100);
    CHECK(vec_is(o->p[2], 0, 1, 0));
    o = &g_scene.obj[5];
    CHECK(o->kind == SCENE_SPHERE && o->material == SCENE_MAT_TRANSPARENT && o->index == 0.01 && o->line == 9);
    CHECK(g_scene.depth == 6 && g_scene.depth_line == 4);
    CHECK(g_scene.samples == 4 && g_scene.adaptive == 0 && g_scene.samples_line == 5);

    /* Defaults: depth 4, one sample, not adaptive, no lines. */
    CHECK_MSG(parse_str(good_scene) == 0, "%s", g_err);
    CHECK(g_scene.depth == SCENE_DEFAULT_DEPTH && g_scene.depth == 4 && g_scene.depth_line == 0);
    CHECK(g_scene.samples == 1 && g_scene.adaptive == 0 && g_scene.samples_line == 0);
    for (int i = 0; i < g_scene.count; i++)
        CHECK(color_is(g_scene.obj[i].reflection, 0, 0, 0) && g_scene.obj[i].index == 0);
    /* Limits, adaptive, leading zeros, anywhere in the file (also before
     * the camera), with comments and tabs. */
    CHECK_MSG(parse_str("depth 0\nsamples\t16   adaptive # full grid where keys differ\n" CAM) == 0, "%s", g_err);
    CHECK(g_scene.depth == 0 && g_scene.depth_line == 1 && g_scene.samples == 16 && g_scene.adaptive == 1);
    CHECK(g_scene.samples_line == 2);
    CHECK_MSG(parse_str(CAM "depth 16\nsamples 1\n") == 0, "%s", g_err);
    CHECK(g_scene.depth == 16 && g_scene.samples == 1 && g_scene.adaptive == 0);
    CHECK_MSG(parse_str(CAM "samples 2 adaptive\ndepth 007\n") == 0, "%s", g_err);
    CHECK(g_scene.samples == 2 && g_scene.adaptive == 1 && g_scene.depth == 7 && g_scene.depth_line == 3);
    /* Explicit 'depth 4' and 'samples 1' store the defaults with their lines. */
    CHECK_MSG(parse_str(CAM "depth 4\nsamples 1\n") == 0, "%s", g_err);
    CHECK(g_scene.depth == 4 && g_scene.depth_line == 2 && g_scene.samples == 1 && g_scene.samples_line == 3);
    /* Index written in other spellings; reflection 0 0 0 is allowed. */
    CHECK_MSG(parse_str(CAM "sphere center 0 0 -3 radius 1 color 1 1 1 material transparent index 1e2\n"
                            "sphere center 0 0 -3 radius 1 color 1 1 1 material transparent index .01\n"
                            "sphere center 0 0 -3 radius 1 color 1 1 1 material reflective reflection 0 0 0 "
                            "specular 0 0 0 exponent 1\n") == 0,
              "%s", g_err);
    CHECK(g_scene.obj[0].index == 100 && g_scene.obj[1].index == 0.01);
    CHECK(g_scene.obj[2].material == SCENE_MAT_REFLECTIVE && color_is(g_scene.obj[2].reflection, 0, 0, 0));
}

static void test_light_capacity(void)
{
    static char buf[4096];
    size_t n = 0;
    int i;

    n += (size_t)snprintf(buf + n, sizeof buf - n, "%s", CAM);
    for (i = 0; i < SCENE_MAX_LIGHTS; i++)
        n += (size_t)snprintf(buf + n, sizeof buf - n, "light point position %d 0 0 color 1 1 1\n", i);
    CHECK_MSG(parse_len(buf, n) == 0, "%s", g_err);
    CHECK(g_scene.nlights == SCENE_MAX_LIGHTS);
    for (i = 0; i < g_scene.nlights; i++)
        CHECK(g_scene.light[i].line == i + 2 && g_scene.light[i].position.x == i);
    n += (size_t)snprintf(buf + n, sizeof buf - n, "light directional direction 0 -1 0 color 1 1 1\n");
    if (SCENE_MAX_LIGHTS > 0)
        expect_error_len(buf, n, SCENE_MAX_LIGHTS + 2,
                         "too many lights (at most " STR(SCENE_MAX_LIGHTS) "; the first is on line 2)", HERE);
    else
        expect_error_len(buf, n, 2, "lights are not in this build", HERE);
}

static void test_limits_accepted(void)
{
    /* Values exactly at the documented limits are inside the domain. */
    CHECK_MSG(parse_str("image 4096 1\n"
                        "camera orthographic eye -8192 8192 0 gaze 8192 0 -8192 up 0 1 0 "
                        "scale " STR(FXRT_RADIUS_LIMIT) "\n"
                        "sphere center 8192 -8192 8192 radius 4096 color 1 1 1\n"
                        "sphere center 0.0000152587890625 0 -0 radius 0.0000152587890625 "
                        "color 0 0.0000152587890625 1\n"
                        "box min 1 1 1 max 1 1 1 color 0 0 0\n") == 0,
              "%s", g_err);
    CHECK(g_scene.width == 4096 && g_scene.height == 1);
    CHECK(g_scene.count == 3);
    CHECK(near(g_scene.obj[1].p[0].x, 1.0 / 65536));
    /* -0 is stored as +0. */
    CHECK(g_scene.obj[1].p[0].z == 0.0 && !signbit(g_scene.obj[1].p[0].z));
    /* Spellings strtod and the grammar both accept. */
    CHECK_MSG(parse_str("camera perspective eye +1. .5 1e2 gaze 0 0 -1E+0 up 0 1 0 fov 179.9\n") ==
                  0,
              "%s", g_err);
    CHECK(vec_is(g_scene.camera.eye, 1, 0.5, 100));
    /* Up 0.91 degrees from the gaze (sin 0.0159 >= 1/64), and the
     * straight-down camera the rejection message suggests. */
    CHECK_MSG(parse_str("camera perspective eye 0 0 0 gaze 0 0 -1 up 0 0.0159 1 fov 45\n") == 0,
              "%s", g_err);
    CHECK_MSG(parse_str("camera perspective eye 0 5 0 gaze 0 -1 0 up 0 0 -1 fov 45\n") == 0, "%s", g_err);
    /* Short directions whose components Q16.16 holds exactly are fine. */
    CHECK_MSG(parse_str("camera perspective eye 0 0 0 gaze 0 0 -0.0001 up 0.0000152587890625 0.0001220703125 0 fov 45\n"
                        "plane point 0 0 0 normal 0 0.00002 0 color 0 1 0\n") == 0,
              "%s", g_err);
    /* Leading zeros in image size. */
    CHECK_MSG(parse_str("image 0640 0480\n" CAM) == 0, "%s", g_err);
    CHECK(g_scene.width == 640 && g_scene.height == 480);
}

struct error_case {
    const char *text;
    int line;
    const char *frag;
};

#define SPHERE_OK "sphere center 0 0 -3 radius 0.5 color 1 0 0\n"

static const struct error_case error_cases[] = {
    /* keywords and structure */
    {CAM "sphre center 0 0 -3 radius 0.5 color 1 0 0\n", 2, "unknown keyword 'sphre'"},
    {"center 0 0 0\n", 1, "unknown keyword 'center'"},
    {CAM "sphere center 0 0 radius 0.5 color 1 0 0\n", 2, "'center' needs 3 numbers, got 2"},
    {CAM "sphere center 0 0\n", 2, "'center' needs 3 numbers, got 2"},
    {CAM "sphere center 0 0 -3 4 radius 0.5 color 1 0 0\n", 2, "'center' needs 3 numbers, got 4"},
    {CAM "sphere center 0 0 -3 radius color 1 0 0\n", 2, "'radius' needs 1 number, got 0"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 foo\n", 2, "unexpected 'foo' after sphere"},
    {CAM "sphere foo center 0 0 -3 radius 0.5 color 1 0 0\n", 2, "unexpected 'foo' after sphere"},
    {CAM "sphere center 0 0 -3 normal 0 1 0 radius 0.5 color 1 0 0\n", 2,
     "sphere has no field 'normal'"},
    {CAM "sphere center 0 0 -3 radius 0.5 radius 1 color 1 0 0\n", 2, "duplicate field 'radius'"},
    {CAM "sphere center 0 0 -3 color 1 0 0\n", 2, "missing field 'radius' for sphere"},
    {CAM "sphere\n", 2, "missing field 'center' for sphere"},
    {CAM "triangle a 0 0 0 b 1 0 0 color 1 1 1\n", 2, "missing field 'c' for triangle"},
    {"camera perspective eye 0 0 0 gaze 0 0 -1 up 0 1 0\n", 1,
     "missing field 'fov' for perspective camera"},
    {"camera perspective eye 0 0 0 gaze 0 0 -1 up 0 1 0 scale 4\n", 1,
     "perspective camera has no field 'scale'"},
    {"camera fisheye eye 0 0 0 gaze 0 0 -1 up 0 1 0 fov 45\n", 1, "unknown camera type 'fisheye'"},
    {"camera\n", 1, "camera needs a type"},
    /* numbers */
    {CAM "sphere center 0 abc -3 radius 0.5 color 1 0 0\n", 2, "'abc' is not a number"},
    {CAM "sphere center 0 1.2.3 -3 radius 0.5 color 1 0 0\n", 2, "'1.2.3' is not a number"},
    {CAM "sphere center 0 1e -3 radius 0.5 color 1 0 0\n", 2, "'1e' is not a number"},
    {CAM "sphere center 0 . -3 radius 0.5 color 1 0 0\n", 2, "'.' is not a number"},
    {CAM "sphere center 0 --1 -3 radius 0.5 color 1 0 0\n", 2, "'--1' is not a number"},
    {CAM "sphere center 0 1,5 -3 radius 0.5 color 1 0 0\n", 2, "'1,5' is not a number"},
    {CAM "sphere center 0 nan -3 radius 0.5 color 1 0 0\n", 2, "NaN or infinity not allowed: 'nan'"},
    {CAM "sphere center 0 -Infinity -3 radius 0.5 color 1 0 0\n", 2,
     "NaN or infinity not allowed: '-Infinity'"},
    {CAM "sphere center 0 0 -3 radius INF color 1 0 0\n", 2, "NaN or infinity not allowed: 'INF'"},
    {CAM "sphere center 0 0x1p3 -3 radius 0.5 color 1 0 0\n", 2,
     "hexadecimal numbers not allowed: '0x1p3'"},
    {CAM "sphere center 0 1e99999 -3 radius 0.5 color 1 0 0\n", 2,
     "value 1e99999 out of range (|coordinate| <= " STR(FXRT_COORD_LIMIT) ")"},
    {CAM "sphere center 0 0 -3 radius 1e99999 color 1 0 0\n", 2, "radius 1e99999 exceeds limit"},
    {CAM "sphere center 0 1e-9 -3 radius 0.5 color 1 0 0\n", 2, "too small for Q16.16: 1e-9"},
    {CAM "sphere center 0 -1e-400 -3 radius 0.5 color 1 0 0\n", 2,
     "too small for Q16.16: -1e-400"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 0.00001 0 0\n", 2,
     "too small for Q16.16: 0.00001"},
    /* ranges */
    {CAM "sphere center 0 40000 -3 radius 0.5 color 1 0 0\n", 2,
     "value 40000 out of range (|coordinate| <= " STR(FXRT_COORD_LIMIT) ")"},
    {CAM "sphere center 0 -8192.5 -3 radius 0.5 color 1 0 0\n", 2,
     "value -8192.5 out of range"},
    {"camera perspective eye 0 0 0 gaze 0 0 -40000 up 0 1 0 fov 45\n", 1,
     "value -40000 out of range (|component| <= " STR(FXRT_COORD_LIMIT) ")"},
    {CAM "sphere center 0 0 -3 radius -1 color 1 0 0\n", 2, "radius must be > 0, got -1"},
    {CAM "sphere center 0 0 -3 radius 0 color 1 0 0\n", 2, "radius must be > 0, got 0"},
    {CAM "sphere center 0 0 -3 radius 5000 color 1 0 0\n", 2,
     "radius 5000 exceeds limit " STR(FXRT_RADIUS_LIMIT)},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 1.5 0\n", 2, "color component 1.5 outside 0..1"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 -0.5 0\n", 2,
     "color component -0.5 outside 0..1"},
    {"background 0 2 0\n" CAM, 1, "background color component 2 outside 0..1"},
    {"background 0 0\n" CAM, 1, "'background' needs 3 numbers, got 2"},
    {"background 0 0 0\nbackground 1 1 1\n" CAM, 2, "duplicate 'background' line (first on line 1)"},
    /* camera geometry */
    {"camera perspective eye 0 0 0 gaze 0 0 0 up 0 1 0 fov 45\n", 1, "gaze has zero length"},
    {"camera perspective eye 0 0 0 gaze 0 0 -1 up 0 0 0 fov 45\n", 1, "up has zero length"},
    {"camera perspective eye 0 0 0 gaze 0 0 -1 up 0 0 -2 fov 45\n", 1, "up is parallel to gaze"},
    {"camera perspective eye 0 0 0 gaze 0 0 -1 up 0 0 3 fov 45\n", 1, "up is parallel to gaze"},
    {"camera perspective eye 0 0 0 gaze 0 0 -1 up 0.001 0 -1000 fov 45\n", 1,
     "up is parallel to gaze"},
    /* Looking straight down with up along y: the message says what to write. */
    {"camera perspective eye 0 5 0 gaze 0 -1 0 up 0 1 0 fov 45\n", 1,
     "up is parallel to gaze (or within 0.9 degrees of it); to look straight down use e.g. "
     "'gaze 0 -1 0 up 0 0 -1'"},
    /* 0.88 degrees (sin 0.01536 < 1/64) is rejected, 0.91 degrees accepted (below). */
    {"camera perspective eye 0 0 0 gaze 0 0 -1 up 0 0.01536 1 fov 45\n", 1, "up is parallel to gaze"},
    /* Directions whose Q16.16 rounding would turn them by more than 4 LSB. */
    {"camera perspective eye 0 1 4 gaze 0.00002 -0.00003 -0.00011 up 0 1 0 fov 40\n", 1,
     "gaze is too short for Q16.16: rounding it to 1/65536 turns the view by"},
    {"camera perspective eye 0 0 0 gaze 0 0 -1 up 0.00003 0.0002 0 fov 40\n", 1,
     "up is too short or too close to gaze for Q16.16: rounding turns the camera's roll by"},
    {"camera perspective eye 0 0 0 gaze 1 2 3 up 0.1 0.2 0.33 fov 40\n", 1,
     "up is too short or too close to gaze for Q16.16"},
    {CAM "plane point 0 0 0 normal 0.00002 0.00011 0.00003 color 0 1 0\n", 2,
     "normal is too short for Q16.16: rounding it to 1/65536 turns it by"},
    {"camera perspective eye 0 0 0 gaze 0 0 -1 up 0 1 0 fov 180\n", 1,
     "fov must be inside (0, 180), got 180"},
    {"camera perspective eye 0 0 0 gaze 0 0 -1 up 0 1 0 fov 0\n", 1,
     "fov must be inside (0, 180), got 0"},
    {"camera perspective eye 0 0 0 gaze 0 0 -1 up 0 1 0 fov -10\n", 1,
     "fov must be inside (0, 180), got -10"},
    {"camera orthographic eye 0 0 0 gaze 0 0 -1 up 0 1 0 scale 0\n", 1, "scale must be > 0"},
    {"camera orthographic eye 0 0 0 gaze 0 0 -1 up 0 1 0 scale 5000\n", 1,
     "scale 5000 exceeds limit " STR(FXRT_RADIUS_LIMIT)},
    /* objects */
    {CAM "plane point 0 -1 0 normal 0 0 0 color 0 1 0\n", 2, "normal has zero length"},
    {CAM "box min 2 0 0 max 1 1 1 color 0 0 1\n", 2, "box min exceeds max on x (2 > 1)"},
    {CAM "box min 0 0 5.5 max 1 1 -1 color 0 0 1\n", 2, "box min exceeds max on z (5.5 > -1)"},
    /* ambient */
    {"ambient 0 2 0\n" CAM, 1, "ambient color component 2 outside 0..1"},
    {CAM "ambient 0 -0.1 0\n", 2, "ambient color component -0.1 outside 0..1"},
    {"ambient 0 0\n" CAM, 1, "'ambient' needs 3 numbers, got 2"},
    {"ambient 0 0 0 0\n" CAM, 1, "'ambient' needs 3 numbers, got 4"},
    {"ambient 0.1 0.1 0.1\n" CAM "ambient 0 0 0\n", 3, "duplicate 'ambient' line (first on line 1)"},
    {"ambient 0 nan 0\n" CAM, 1, "ambient: NaN or infinity not allowed: 'nan'"},
    {"ambient 0 0.000001 0\n" CAM, 1, "ambient: too small for Q16.16: 0.000001"},
    /* lights */
    {CAM "light\n", 2, "light needs a type: point, directional or spot"},
    {CAM "light laser position 0 0 0 color 1 1 1\n", 2, "unknown light type 'laser'"},
    {CAM "light point color 1 1 1\n", 2, "missing field 'position' for point light"},
    {CAM "light point position 0 0 0\n", 2, "missing field 'color' for point light"},
    {CAM "light directional color 1 1 1\n", 2, "missing field 'direction' for directional light"},
    {CAM "light spot position 0 0 0 direction 0 -1 0 color 1 1 1\n", 2, "missing field 'angle' for spot light"},
    {CAM "light spot position 0 0 0 angle 10 color 1 1 1\n", 2, "missing field 'direction' for spot light"},
    {CAM "light spot direction 0 -1 0 angle 10 color 1 1 1\n", 2, "missing field 'position' for spot light"},
    {CAM "light point position 0 0 0 direction 0 -1 0 color 1 1 1\n", 2, "point light has no field 'direction'"},
    {CAM "light directional position 0 0 0 direction 0 -1 0 color 1 1 1\n", 2,
     "directional light has no field 'position'"},
    {CAM "light point position 0 0 0 angle 10 color 1 1 1\n", 2, "point light has no field 'angle'"},
    {CAM "light point position 0 0 0 color 1 1 1 material lambert\n", 2, "point light has no field 'material'"},
    {CAM "light point position 0 0 0 color 1 1 1 position 1 1 1\n", 2, "duplicate field 'position' in point light"},
    {CAM "light point position 0 0 0 color 1 1 1 shadows on shadows off\n", 2,
     "duplicate field 'shadows' in point light"},
    {CAM "light point position 0 0 0 color 1 1 1 shadows\n", 2, "'shadows' needs a value (on or off)"},
    {CAM "light point position 0 0 0 color 1 1 1 shadows yes\n", 2, "shadows must be on or off, got 'yes'"},
    {CAM "light point position 0 0 0 color 1 1 1 shadows ON\n", 2, "shadows must be on or off, got 'ON'"},
    {CAM "light point position 0 0 0 color 1 1 1 shadows on off\n", 2, "unexpected 'off' after point light"},
    {CAM "light point position 0 0 color 1 1 1\n", 2, "'position' needs 3 numbers, got 2"},
    {CAM "light point position 0 0 9000 color 1 1 1\n", 2, "value 9000 out of range (|coordinate| <= "},
    {CAM "light point position 0 0 0 color 1 1.5 1\n", 2, "color component 1.5 outside 0..1"},
    {CAM "light point position 0 0 0 color 1 1 -1\n", 2, "color component -1 outside 0..1"},
    {CAM "light directional direction 0 0 0 color 1 1 1\n", 2, "direction has zero length"},
    {CAM "light spot position 0 0 0 direction 0 0 0 angle 10 color 1 1 1\n", 2, "direction has zero length"},
    {CAM "light directional direction 0.00002 0.00011 0.00003 color 1 1 1\n", 2,
     "direction is too short for Q16.16: rounding it to 1/65536 turns it by"},
    {CAM "light directional direction 0 -9000 0 color 1 1 1\n", 2, "value -9000 out of range (|component| <= "},
    {CAM "light spot position 0 0 0 direction 0 -1 0 angle 0 color 1 1 1\n", 2,
     "angle must be inside (0, 90] degrees (the cone's half-angle), got 0"},
    {CAM "light spot position 0 0 0 direction 0 -1 0 angle 90.001 color 1 1 1\n", 2,
     "angle must be inside (0, 90] degrees (the cone's half-angle), got 90.001"},
    {CAM "light spot position 0 0 0 direction 0 -1 0 angle -5 color 1 1 1\n", 2, "got -5"},
    {CAM "light spot position 0 0 0 direction 0 -1 0 angle 1e999 color 1 1 1\n", 2, "got 1e999"},
    {CAM "light spot position 0 0 0 direction 0 -1 0 angle ten color 1 1 1\n", 2, "angle: 'ten' is not a number"},
    /* materials */
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material\n", 2,
     "'material' needs a value (flat, lambert, phong, reflective or transparent)"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material metal\n", 2,
     "unknown material 'metal' (expected flat, lambert, phong, reflective or transparent)"},
    {CAM "plane point 0 0 0 normal 0 1 0 color 1 0 0 material Phong specular 1 1 1 exponent 2\n", 2,
     "unknown material 'Phong'"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material flat material lambert\n", 2,
     "duplicate field 'material' in sphere"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material lambert flat\n", 2, "unexpected 'flat' after sphere"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material phong exponent 8\n", 2,
     "missing field 'specular' for sphere with material phong"},
    {CAM "box min 0 0 0 max 1 1 1 color 1 0 0 material phong specular 1 1 1\n", 2,
     "missing field 'exponent' for box with material phong"},
    {CAM "triangle a 0 0 0 b 1 0 0 c 0 1 0 color 1 0 0 material lambert specular 1 1 1\n", 2,
     "'specular' is only for material phong or reflective, not lambert"},
    {CAM "plane point 0 0 0 normal 0 1 0 color 1 0 0 material flat exponent 3\n", 2,
     "'exponent' is only for material phong or reflective, not flat"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 specular 1 1 1 exponent 3\n", 2,
     "'specular' is only for material phong or reflective (add 'material phong' or 'material reflective')"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 exponent 3\n", 2,
     "'exponent' is only for material phong or reflective (add 'material phong' or 'material reflective')"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material phong specular 1 1 1 exponent 0\n", 2,
     "exponent 0 outside 1..1024"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material phong specular 1 1 1 exponent 1025\n", 2,
     "exponent 1025 outside 1..1024"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material phong specular 1 1 1 exponent 99999999999999\n", 2,
     "exponent 99999999999999 outside 1..1024"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material phong specular 1 1 1 exponent 64.5\n", 2,
     "exponent must be an integer in 1..1024, got '64.5'"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material phong specular 1 1 1 exponent 1e2\n", 2,
     "exponent must be an integer in 1..1024, got '1e2'"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material phong specular 1 1 1 exponent -3\n", 2,
     "exponent must be an integer in 1..1024, got '-3'"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material phong specular 1 1 1 exponent\n", 2,
     "'exponent' needs a value (an integer)"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material phong specular 1 1 exponent 4\n", 2,
     "'specular' needs 3 numbers, got 2"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material phong specular 1 2 1 exponent 4\n", 2,
     "specular color component 2 outside 0..1"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material phong specular 1 1 1 specular 1 1 1 exponent 4\n", 2,
     "duplicate field 'specular' in sphere"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material phong specular 1 1 1 exponent 4 exponent 5\n", 2,
     "duplicate field 'exponent' in sphere"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 shadows off\n", 2, "sphere has no field 'shadows'"},
    {CAM "sphere center 0 0 -3 radius 0.5 material lambert\n", 2, "missing field 'color' for sphere"},
    {"ambiant 0 0 0\n" CAM, 1, "unknown keyword 'ambiant' (expected image, background, ambient, camera, light"},
    /* reflective and transparent */
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material reflective specular 1 1 1 exponent 8\n", 2,
     "missing field 'reflection' for sphere with material reflective"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material reflective exponent 8 reflection 1 1 1\n", 2,
     "missing field 'specular' for sphere with material reflective"},
    {CAM "box min 0 0 0 max 1 1 1 color 1 0 0 material reflective specular 1 1 1 reflection 1 1 1\n", 2,
     "missing field 'exponent' for box with material reflective"},
    {CAM "plane point 0 0 0 normal 0 1 0 color 1 0 0 material reflective\n", 2,
     "missing field 'specular' for plane with material reflective"},
    {CAM "triangle a 0 0 0 b 1 0 0 c 0 1 0 color 1 0 0 material transparent\n", 2,
     "missing field 'index' for triangle with material transparent"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material transparent index 1.5 specular 1 1 1\n", 2,
     "'specular' is only for material phong or reflective, not transparent"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material transparent index 1.5 exponent 3\n", 2,
     "'exponent' is only for material phong or reflective, not transparent"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material transparent index 1.5 reflection 1 1 1\n", 2,
     "'reflection' is only for material reflective, not transparent"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material phong specular 1 1 1 exponent 3 reflection 1 1 1\n", 2,
     "'reflection' is only for material reflective, not phong"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 reflection 0.5 0.5 0.5\n", 2,
     "'reflection' is only for material reflective (add 'material reflective')"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material lambert index 1.5\n", 2,
     "'index' is only for material transparent, not lambert"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 index 1.5\n", 2,
     "'index' is only for material transparent (add 'material transparent')"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material reflective specular 1 1 1 exponent 3 "
         "reflection 1 1 1 index 1.5\n", 2,
     "'index' is only for material transparent, not reflective"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material reflective specular 1 1 1 exponent 3 "
         "reflection 1 1.5 1\n", 2,
     "reflection color component 1.5 outside 0..1"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material reflective specular 1 1 1 exponent 3 "
         "reflection 1 -0.5 1\n", 2,
     "reflection color component -0.5 outside 0..1"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material reflective specular 1 1 1 exponent 3 reflection 1 1\n", 2,
     "'reflection' needs 3 numbers, got 2"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material reflective specular 1 1 1 exponent 3 "
         "reflection 1 1 1 reflection 1 1 1\n", 2,
     "duplicate field 'reflection' in sphere"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material reflective specular 1 1 1 exponent 0 reflection 1 1 1\n", 2,
     "exponent 0 outside 1..1024"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material reflective specular 1 1 1 exponent 1025 "
         "reflection 1 1 1\n", 2,
     "exponent 1025 outside 1..1024"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material reflective specular 1 1 1 exponent 6.4 "
         "reflection 1 1 1\n", 2,
     "exponent must be an integer in 1..1024, got '6.4'"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material transparent index 0.00999\n", 2,
     "index must be inside [0.01, 100], got 0.00999"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material transparent index 100.001\n", 2,
     "index must be inside [0.01, 100], got 100.001"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material transparent index 0\n", 2,
     "index must be inside [0.01, 100], got 0"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material transparent index -1.5\n", 2,
     "index must be inside [0.01, 100], got -1.5"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material transparent index 1e999\n", 2,
     "index must be inside [0.01, 100], got 1e999"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material transparent index nan\n", 2,
     "index: NaN or infinity not allowed: 'nan'"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material transparent index glass\n", 2,
     "index: 'glass' is not a number"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material transparent index 0.000001\n", 2,
     "index: too small for Q16.16: 0.000001"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material transparent index\n", 2,
     "'index' needs 1 number, got 0"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material transparent index 1.3 1.4\n", 2,
     "'index' needs 1 number, got 2"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material transparent index 1.3 index 1.4\n", 2,
     "duplicate field 'index' in sphere"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material Transparent index 1.3\n", 2,
     "unknown material 'Transparent' (expected flat, lambert, phong, reflective or transparent)"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 material mirror\n", 2, "unknown material 'mirror'"},
    {CAM "light point position 0 0 0 color 1 1 1 index 1.5\n", 2, "point light has no field 'index'"},
    {CAM "light point position 0 0 0 color 1 1 1 reflection 1 1 1\n", 2, "point light has no field 'reflection'"},
    {"camera perspective eye 0 0 0 gaze 0 0 -1 up 0 1 0 fov 45 index 2\n", 1,
     "perspective camera has no field 'index'"},
    /* depth and samples */
    {CAM "depth 17\n", 2, "depth 17 outside 0..16"},
    {CAM "depth 99999999999999999999\n", 2, "depth 99999999999999999999 outside 0..16"},
    {CAM "depth -1\n", 2, "'depth' needs an integer in 0..16, got '-1'"},
    {CAM "depth +2\n", 2, "'depth' needs an integer in 0..16, got '+2'"},
    {CAM "depth 4.0\n", 2, "'depth' needs an integer in 0..16, got '4.0'"},
    {CAM "depth 1e1\n", 2, "'depth' needs an integer in 0..16, got '1e1'"},
    {CAM "depth six\n", 2, "'depth' needs an integer in 0..16, got 'six'"},
    {CAM "depth\n", 2, "'depth' needs 1 integer, got 0 values"},
    {CAM "depth 4 5\n", 2, "'depth' needs 1 integer, got 2 values"},
    {CAM "depth 4 adaptive\n", 2, "'depth' needs 1 integer, got 2 values"},
    {"depth 4\n" CAM "depth 4\n", 3, "duplicate 'depth' line (first on line 1)"},
    {"depth 4\n" CAM "depth 5\n", 3, "duplicate 'depth' line (first on line 1)"},
    {CAM "samples 0\n", 2, "samples 0 outside 1..16"},
    {CAM "samples 17\n", 2, "samples 17 outside 1..16"},
    {CAM "samples 17 adaptive\n", 2, "samples 17 outside 1..16"},
    {CAM "samples -4\n", 2, "'samples' needs an integer in 1..16, got '-4'"},
    {CAM "samples 2.5\n", 2, "'samples' needs an integer in 1..16, got '2.5'"},
    {CAM "samples adaptive\n", 2, "'samples' needs an integer in 1..16, got 'adaptive'"},
    {CAM "samples adaptive 4\n", 2, "'samples' needs an integer in 1..16, got 'adaptive'"},
    {CAM "samples\n", 2, "'samples' needs 1 integer and optionally 'adaptive', got 0 values"},
    {CAM "samples 4 adaptive adaptive\n", 2, "'samples' needs 1 integer and optionally 'adaptive', got 3 values"},
    {CAM "samples 4 4\n", 2, "unexpected '4' after samples (only 'adaptive' may follow the number)"},
    {CAM "samples 4 Adaptive\n", 2, "unexpected 'Adaptive' after samples (only 'adaptive' may follow the number)"},
    {CAM "samples 1 adaptive\n", 2, "'samples 1 adaptive': adaptive needs samples 2 or more"},
    {CAM "samples 01 adaptive\n", 2, "'samples 1 adaptive': adaptive needs samples 2 or more"},
    {"samples 2\n" CAM "samples 2\n", 3, "duplicate 'samples' line (first on line 1)"},
    {"samples 2 adaptive\n# x\n" CAM "samples 4\n", 4, "duplicate 'samples' line (first on line 1)"},
    {CAM "deph 4\n", 2, "unknown keyword 'deph' (expected image, background, ambient, camera, light, depth, samples, "
                        "node, end, mesh, plane, sphere, triangle, box, ellipsoid or parallelepiped)"},
    /* image */
    {"image 0 5\n" CAM, 1, "image size must be 1..4096 x 1..4096, got 0x5"},
    {"image 4097 5\n" CAM, 1, "got 4097x5"},
    {"image 5 99999999999999999999999\n" CAM, 1, "got 5x99999999999999999999999"},
    {"image 640.5 480\n" CAM, 1, "'image' needs 2 integers"},
    {"image +640 480\n" CAM, 1, "'image' needs 2 integers, got '+640'"},
    {"image 640 -480\n" CAM, 1, "'image' needs 2 integers, got '-480'"},
    {"image 640\n" CAM, 1, "'image' needs 2 integers, got 1 value"},
    {"image 640 480 3\n" CAM, 1, "'image' needs 2 integers, got 3 values"},
    {"image 640 480\n" CAM "image 640 480\n", 3, "duplicate 'image' line (first on line 1)"},
    /* whole statements */
    {"# a\n# b\n" CAM SPHERE_OK CAM, 5, "second camera (first on line 3)"},
    {"# only\n" SPHERE_OK, 2, "no camera in scene"},
    {"# only\n" SPHERE_OK "# last, no newline", 3, "no camera in scene"},
    {"", 1, "no camera in scene"},
    {"\n\n\n", 3, "no camera in scene"},
    /* bytes */
    {CAM "sphere center 0 0 -3 \x01 radius 0.5 color 1 0 0\n", 2, "binary data (byte 0x01)"},
    {CAM "# comment with \x7f\n", 2, "binary data (byte 0x7f)"},
    {CAM "sphere center 0 0 -3 radius 0.5 color 1 0 0 \xff\n", 2, "non-ASCII byte 0xff"},
    {CAM "sphere center 0 0 \xc3\xa9 radius 0.5 color 1 0 0\n", 2, "non-ASCII byte 0xc3"},
    {"image 640 480\r" CAM, 1, "carriage return inside a line"},
};

static void test_error_table(void)
{
    size_t i;

    for (i = 0; i < sizeof error_cases / sizeof error_cases[0]; i++) {
        char where[64];
        snprintf(where, sizeof where, "error_cases[%zu]", i);
        expect_error_len(error_cases[i].text, strlen(error_cases[i].text), error_cases[i].line,
                         error_cases[i].frag, where);
    }
}

static void test_embedded_nul(void)
{
    static const char text[] = CAM "sphere center 0 0 -3\0 radius 0.5 color 1 0 0\n";

    expect_error_len(text, sizeof text - 1, 2, "binary data (byte 0x00)", HERE);
    /* A NUL as the very last byte, with no newline after it. */
    expect_error_len(CAM "\0", strlen(CAM) + 1, 2, "binary data (byte 0x00)", HERE);
}

static void test_long_lines(void)
{
    static char buf[4096];
    size_t n;

    /* A 2000-byte line. */
    n = (size_t)snprintf(buf, sizeof buf, "%s# ", CAM);
    memset(buf + n, 'x', 2000 - 2);
    n += 2000 - 2;
    buf[n++] = '\n';
    expect_error_len(buf, n, 2, "line longer than " STR(SCENE_MAX_LINE) " bytes", HERE);

    /* Exactly SCENE_MAX_LINE bytes is fine, also with a CR before the LF;
     * one more is not. */
    n = (size_t)snprintf(buf, sizeof buf, "%s# ", CAM);
    memset(buf + n, 'x', SCENE_MAX_LINE - 2);
    n += SCENE_MAX_LINE - 2;
    buf[n] = '\n';
    CHECK_MSG(parse_len(buf, n + 1) == 0, "%s", g_err);
    buf[n] = '\r';
    buf[n + 1] = '\n';
    CHECK_MSG(parse_len(buf, n + 2) == 0, "%s", g_err);
    buf[n] = 'x';
    buf[n + 1] = '\n';
    expect_error_len(buf, n + 2, 2, "line longer than", HERE);

    /* A long token is shortened when quoted in a message. */
    n = (size_t)snprintf(buf, sizeof buf, "%s", CAM);
    memset(buf + n, 'q', 900);
    n += 900;
    expect_error_len(buf, n, 2, "unknown keyword 'qqqq", HERE);
    CHECK(strstr(g_err, "...'") != NULL && strlen(g_err) < 256);
}

static void test_capacity(void)
{
    static char buf[64 * 1024];
    size_t n = 0;
    int i;

    n += (size_t)snprintf(buf + n, sizeof buf - n, "%s", CAM);
    for (i = 0; i < FXRT_MAX_SPHERES; i++)
        n += (size_t)snprintf(buf + n, sizeof buf - n, "%s", SPHERE_OK);
    CHECK_MSG(parse_len(buf, n) == 0, "%s", g_err);
    CHECK(g_scene.count == FXRT_MAX_SPHERES);
    /* One more sphere than the capacity. */
    n += (size_t)snprintf(buf + n, sizeof buf - n, "%s", SPHERE_OK);
    if (FXRT_MAX_SPHERES > 0)
        expect_error_len(buf, n, FXRT_MAX_SPHERES + 2,
                         "too many spheres (capacity " STR(FXRT_MAX_SPHERES) ")", HERE);
    else
        expect_error_len(buf, n, 2, "spheres are not in this build", HERE);
}

/* The err contract must hold for tiny or missing buffers too. */
static void test_err_buffers(void)
{
    char small[8];

    CHECK(scene_parse("t", "bogus", 5, &g_scene, NULL, 0) == -1);
    CHECK(scene_parse("t", "bogus", 5, &g_scene, small, 0) == -1);
    memset(small, 'x', sizeof small);
    CHECK(scene_parse("a-long-scene-name", "bogus", 5, &g_scene, small, sizeof small) == -1);
    CHECK(memchr(small, '\0', sizeof small) != NULL && strncmp(small, "a-long-", 7) == 0);
    CHECK(scene_parse("t", NULL, 0, &g_scene, g_err, sizeof g_err) == -1);
    CHECK(strstr(g_err, "no camera") != NULL);
}

/* Cheap in-process mutation run: the real fuzzing is libFuzzer's job, but
 * under ASan/UBSan this catches the obvious crashes on every test run. */
static void test_mutations_of(const char *scene)
{
    static char buf[2048];
    size_t base = strlen(scene);
    uint32_t state = 12345;
    int iter, bad_rc = 0, bad_err = 0;

    for (iter = 0; iter < 20000; iter++) {
        size_t n = base;
        int k, edits;
        memcpy(buf, scene, base);
        state = state * 1664525u + 1013904223u;
        edits = 1 + (int)((state >> 24) % 4);
        for (k = 0; k < edits; k++) {
            size_t at;
            state = state * 1664525u + 1013904223u;
            at = (state >> 8) % n;
            switch ((state >> 28) % 4) {
            case 0: /* random byte */
                buf[at] = (char)(state >> 16);
                break;
            case 1: /* a byte from the scene's alphabet */
                buf[at] = "0123456789.-+e #\n\r\tnax"[(state >> 16) % 23];
                break;
            case 2: /* truncate */
                n = at + 1;
                break;
            default: /* delete one byte */
                memmove(buf + at, buf + at + 1, n - at - 1);
                n = n > 1 ? n - 1 : n;
                break;
            }
        }
        {
            int rc = parse_len(buf, n);
            if (rc != 0 && rc != -1)
                bad_rc++;
            if (rc == -1 && strncmp(g_err, "t:", 2) != 0)
                bad_err++;
            if (rc == 0 && (g_scene.count < 0 || g_scene.count > SCENE_MAX_OBJECTS))
                bad_rc++;
            if (rc == 0 && (g_scene.nlights < 0 || g_scene.nlights > SCENE_MAX_LIGHTS))
                bad_rc++;
            if (rc == 0 && (g_scene.depth < 0 || g_scene.depth > SCENE_MAX_DEPTH || g_scene.samples < 1 ||
                            g_scene.samples > SCENE_MAX_SAMPLES || (g_scene.adaptive && g_scene.samples < 2)))
                bad_rc++;
        }
    }
    CHECK_MSG(bad_rc == 0, "%d bad results", bad_rc);
    CHECK_MSG(bad_err == 0, "%d bad messages, last \"%s\"", bad_err, g_err);
}

static void test_mutations(void)
{
    test_mutations_of(good_scene);
    test_mutations_of(lit_scene);
    test_mutations_of(trace_scene);
}

static int write_file(const char *path, const char *data, size_t len)
{
    FILE *f = fopen(path, "wb");
    size_t w;

    if (f == NULL)
        return -1;
    w = fwrite(data, 1, len, f);
    if (fclose(f) != 0 || w != len)
        return -1;
    return 0;
}

static void test_load(void)
{
    char dir[] = "/tmp/test_scene.XXXXXX";
    char path[256];
    char *big;
    size_t i;

    CHECK(scene_load("tests/bad-scenes/no-such-file.scene", &g_scene, g_err, sizeof g_err) == -1);
    CHECK_MSG(strcmp(g_err, "tests/bad-scenes/no-such-file.scene: cannot open: "
                            "No such file or directory") == 0,
              "%s", g_err);

    if (mkdtemp(dir) == NULL) {
        CHECK_MSG(0, "mkdtemp failed");
        return;
    }
    snprintf(path, sizeof path, "%s/good.scene", dir);
    CHECK(write_file(path, good_scene, strlen(good_scene)) == 0);
    CHECK_MSG(scene_load(path, &g_scene, g_err, sizeof g_err) == 0, "%s", g_err);
    check_good_values(&g_scene, HERE);
    remove(path);

    /* Exactly 1 MiB of comment lines loads; one byte more is refused. */
    big = malloc(1024 * 1024 + 1);
    if (big != NULL) {
        char want[300];
        for (i = 0; i < 1024 * 1024; i++)
            big[i] = (i % 64 == 63) ? '\n' : '#';
        memcpy(big, CAM, strlen(CAM));
        snprintf(path, sizeof path, "%s/big.scene", dir);
        CHECK(write_file(path, big, 1024 * 1024) == 0);
        CHECK_MSG(scene_load(path, &g_scene, g_err, sizeof g_err) == 0, "%s", g_err);
        big[1024 * 1024] = '\n';
        CHECK(write_file(path, big, 1024 * 1024 + 1) == 0);
        CHECK(scene_load(path, &g_scene, g_err, sizeof g_err) == -1);
        snprintf(want, sizeof want, "%s: file too large", path);
        CHECK_MSG(strncmp(g_err, want, strlen(want)) == 0, "%s", g_err);
        remove(path);
        free(big);
    }

    /* A directory opens but cannot be read. */
    CHECK(scene_load(dir, &g_scene, g_err, sizeof g_err) == -1);
    CHECK_MSG(strstr(g_err, "cannot") != NULL, "%s", g_err);
    rmdir(dir);
}

/* Read "LINE: fragment" from the first line of the file (after "# expect: ")
 * or from the sidecar NAME.expect. Returns 0 on success. */
static int read_expectation(const char *path, int *line, char *frag, size_t fragsize)
{
    char sidecar[512];
    char first[1200];
    const char *p;
    char *end;
    size_t n;
    FILE *f;
    long v;

    n = strlen(path);
    if (n < 6 || n + 1 > sizeof sidecar)
        return -1;
    snprintf(sidecar, sizeof sidecar, "%.*s.expect", (int)(n - 6), path);
    f = fopen(sidecar, "rb");
    if (f != NULL) {
        n = fread(first, 1, sizeof first - 1, f);
        fclose(f);
        first[n] = '\0';
        p = first;
    } else {
        static const char tag[] = "# expect: ";
        f = fopen(path, "rb");
        if (f == NULL)
            return -1;
        n = fread(first, 1, sizeof first - 1, f);
        fclose(f);
        first[n] = '\0';
        if (strncmp(first, tag, sizeof tag - 1) != 0)
            return -1;
        p = first + sizeof tag - 1;
    }
    v = strtol(p, &end, 10);
    if (end == p || strncmp(end, ": ", 2) != 0 || v < 0)
        return -1;
    *line = (int)v;
    p = end + 2;
    n = strcspn(p, "\r\n");
    if (n == 0 || n >= fragsize)
        return -1;
    memcpy(frag, p, n);
    frag[n] = '\0';
    return 0;
}

static void test_bad_scene_files(void)
{
    DIR *d = opendir(BAD_SCENES_DIR);
    struct dirent *e;
    int files = 0;

    CHECK_MSG(d != NULL, "cannot open %s (run from the repository root)", BAD_SCENES_DIR);
    if (d == NULL)
        return;
    while ((e = readdir(d)) != NULL) {
        char path[512], prefix[600], frag[1024];
        size_t n = strlen(e->d_name);
        int line, rc;

        if (n < 7 || strcmp(e->d_name + n - 6, ".scene") != 0)
            continue;
        files++;
        snprintf(path, sizeof path, "%s/%s", BAD_SCENES_DIR, e->d_name);
        if (read_expectation(path, &line, frag, sizeof frag) != 0) {
            CHECK_MSG(0, "%s: no '# expect: LINE: message' line and no .expect file", path);
            continue;
        }
        rc = scene_load(path, &g_scene, g_err, sizeof g_err);
        snprintf(prefix, sizeof prefix, "%s:%d: ", path, line);
        CHECK_MSG(rc == -1, "%s: loaded, expected an error", path);
        CHECK_MSG(strncmp(g_err, prefix, strlen(prefix)) == 0 && strstr(g_err, frag) != NULL,
                  "%s: got \"%s\", expected \"%s...%s\"", path, g_err, prefix, frag);
    }
    closedir(d);
    CHECK_MSG(files >= 12, "only %d .scene files in %s", files, BAD_SCENES_DIR);
}

int main(void)
{
    test_good_scene();
    test_crlf();
    test_orthographic_and_defaults();
    test_comments_order_layout();
    test_limits_accepted();
    test_error_table();
    test_embedded_nul();
    test_long_lines();
    test_capacity();
    test_lights_materials();
    test_light_capacity();
    test_trace_keywords();
    test_err_buffers();
    test_mutations();
    test_load();
    test_bad_scene_files();
    return check_report("test_scene");
}
