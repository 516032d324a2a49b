/* libFuzzer harness for scene_parse (host/scene.c), built by `make
 * fuzz-scene` with -fsanitize=fuzzer,address,undefined (tests/sanitize.mk).
 *
 * Any input must either parse or be rejected with one line
 * "NAME:LINE: message". A parse that succeeds must satisfy what the README
 * and host/scene.h promise: exactly one camera, on the line of a 'camera'
 * statement; objects in file order on lines starting with their keyword,
 * per-kind counts within the capacities; lights likewise on 'light' lines
 * (at most SCENE_MAX_LIGHTS), the ambient colour on its 'ambient' line;
 * materials consistent (specular and exponent for phong and reflective
 * only, reflection for reflective only, an index in [FXRT_INDEX_MIN,
 * FXRT_INDEX_MAX] for transparent only); depth and samples from their
 * one line each or the defaults (4, 1), adaptive only with samples >= 2;
 * every value inside the documented
 * domain (core/fxrt_config.h) and either 0 or at least 2^-16 in magnitude;
 * no -0. Rejections must not depend on the size of the error buffer: a
 * short buffer gets a prefix of the same message. Any violation aborts,
 * which libFuzzer reports as a crash with the input saved as an artifact. */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define FUZZ_NAME "fuzz.scene"
#define FUZZ_ERR_LEN 512

static scene_t fuzz_scene_a, fuzz_scene_b; /* large: static */

static _Noreturn void fuzz_fail(const char *what, const char *err)
{
    fprintf(stderr, "fuzz_scene: invariant violated: %s\n", what);
    if (err != NULL)
        fprintf(stderr, "fuzz_scene: message: \"%s\"\n", err);
    abort();
}

#define FUZZ_CHECK(cond, err)                                                                      \
    do {                                                                                           \
        if (!(cond))                                                                               \
            fuzz_fail(#cond, err);                                                                 \
    } while (0)

/* Lines as scene_parse counts them: pieces separated by '\n', a final
 * piece only when the text does not end in '\n'; at least 1 (the message
 * for an empty file is on line 1). */
static long fuzz_line_count(const uint8_t *d, size_t n)
{
    long lines = 0;
    size_t i;

    for (i = 0; i < n; i++)
        if (d[i] == '\n')
            lines++;
    if (n > 0 && d[n - 1] != '\n')
        lines++;
    return lines > 0 ? lines : 1;
}

/* What statement each line holds, by its first word, with the parser's
 * separators: space and tab split words, '#' starts a comment, a CR before
 * LF is dropped. kinds[l] for line l = 1..lines: a scene_kind_t, or
 * FUZZ_LINE_CAMERA, or FUZZ_LINE_OTHER. One pass, so that checking a
 * 4 KiB input of empty lines stays linear. */
#define FUZZ_LINE_CAMERA 4
#define FUZZ_LINE_LIGHT 5
#define FUZZ_LINE_AMBIENT 6
#define FUZZ_LINE_DEPTH 7
#define FUZZ_LINE_SAMPLES 8
#define FUZZ_LINE_MESH 9
#define FUZZ_LINE_OTHER 10
#define FUZZ_LINE_ELLIPSOID 11
#define FUZZ_LINE_PARALLELEPIPED 12
/* Added to a line's kind when it lies inside a node (between 'node' and
 * its 'end'). */
#define FUZZ_IN_NODE 16

static void fuzz_line_kinds(const uint8_t *d, size_t n, unsigned char *kinds, long lines)
{
    static const char *const kw[] = {"plane", "sphere",  "triangle", "box",     "camera", "light",
                                     "ambient", "depth", "samples",  "mesh",    "",       "ellipsoid",
                                     "parallelepiped"};
    int depth = 0;
    /* scene_parse skips a UTF-8 byte-order mark at the start of the text
     * (line 1's keyword follows it); so does this. */
    size_t i = n >= 3 && memcmp(d, "\xef\xbb\xbf", 3) == 0 ? 3 : 0;
    long l;

    for (l = 1; l <= lines; l++) {
        size_t start, len;
        int k;

        while (i < n && (d[i] == ' ' || d[i] == '\t'))
            i++;
        start = i;
        while (i < n && d[i] != ' ' && d[i] != '\t' && d[i] != '#' && d[i] != '\n' && d[i] != '\r')
            i++;
        len = i - start;
        kinds[l] = FUZZ_LINE_OTHER;
        for (k = 0; k < (int)(sizeof kw / sizeof kw[0]); k++)
            if (len > 0 && len == strlen(kw[k]) && memcmp(d + start, kw[k], len) == 0)
                kinds[l] = (unsigned char)k;
        if (depth > 0 && kinds[l] != FUZZ_LINE_OTHER)
            kinds[l] |= FUZZ_IN_NODE;
        if (len == 4 && memcmp(d + start, "node", 4) == 0)
            depth++;
        else if (len == 3 && memcmp(d + start, "end", 3) == 0 && depth > 0)
            depth--;
        while (i < n && d[i] != '\n')
            i++;
        if (i < n)
            i++; /* past the '\n' */
    }
}

/* "NAME:LINE: message", one line of printable ASCII, LINE in 1..lines
 * (an error in a mesh's OBJ file too: its own "OBJ:LINE: " follows). */
static void fuzz_check_error(const char *err, long lines)
{
    size_t nl = strlen(FUZZ_NAME), i;
    const char *s;
    long line = 0;

    FUZZ_CHECK(memchr(err, '\0', FUZZ_ERR_LEN) != NULL, NULL);
    FUZZ_CHECK(strncmp(err, FUZZ_NAME ":", nl + 1) == 0, err);
    s = err + nl + 1;
    FUZZ_CHECK(*s >= '1' && *s <= '9', err);
    while (*s >= '0' && *s <= '9') {
        FUZZ_CHECK(line < 100000000L, err);
        line = line * 10 + (*s - '0');
        s++;
    }
    FUZZ_CHECK(line >= 1 && line <= lines, err);
    FUZZ_CHECK(s[0] == ':' && s[1] == ' ', err);
    s += 2;
    FUZZ_CHECK(*s != '\0' && *s != ' ', err);
    for (i = 0; err[i] != '\0'; i++)
        FUZZ_CHECK(err[i] >= 0x20 && err[i] < 0x7f, err);
}

/* 0, or a finite value of magnitude in [2^-16, limit]; never -0. */
static void fuzz_check_num(double v, double limit)
{
    FUZZ_CHECK(isfinite(v), NULL);
    FUZZ_CHECK(!(v == 0.0 && signbit(v)), NULL);
    FUZZ_CHECK(v == 0.0 || fabs(v) >= 1.0 / 65536.0, NULL);
    FUZZ_CHECK(fabs(v) <= limit, NULL);
}

static void fuzz_check_vec(scene_vec_t v)
{
    fuzz_check_num(v.x, FXRT_COORD_LIMIT);
    fuzz_check_num(v.y, FXRT_COORD_LIMIT);
    fuzz_check_num(v.z, FXRT_COORD_LIMIT);
}

/* A value a node's transform made (host/scene.c, scene_place): finite,
 * within the limit, 0 or at least half of 2^-16 (what Q16.16 does not
 * round to 0), never -0. */
static void fuzz_check_placed(scene_vec_t v)
{
    double c[3] = {v.x, v.y, v.z};
    for (int k = 0; k < 3; k++) {
        FUZZ_CHECK(isfinite(c[k]) && fabs(c[k]) <= FXRT_COORD_LIMIT, NULL);
        FUZZ_CHECK(!(c[k] == 0.0 && signbit(c[k])), NULL);
        FUZZ_CHECK(c[k] == 0.0 || fabs(c[k]) >= 0.5 / 65536.0, NULL);
    }
}

static void fuzz_check_color(const double *c)
{
    int k;

    for (k = 0; k < 3; k++) {
        fuzz_check_num(c[k], 1.0);
        FUZZ_CHECK(c[k] >= 0.0, NULL);
    }
}

static int fuzz_is_zero(scene_vec_t v)
{
    return v.x == 0.0 && v.y == 0.0 && v.z == 0.0;
}

static void fuzz_check_scene(const scene_t *s, const uint8_t *d, size_t n, long lines)
{
    static const int cap[] = {FXRT_MAX_PLANES, FXRT_MAX_SPHERES, FXRT_MAX_TRIANGLES, FXRT_MAX_BOXES};
    int ellipsoids = 0, file_ellipsoids = 0, pps = 0, file_pps = 0;
    const scene_camera_t *cam = &s->camera;
    unsigned char *kinds = malloc((size_t)lines + 1);
    long l, cameras = 0;
    int kind_count[4] = {0, 0, 0, 0};
    int file_count[4] = {0, 0, 0, 0};
    int meshes = 0;
    int i, k, prev_line = 0;

    FUZZ_CHECK(kinds != NULL, NULL);
    fuzz_line_kinds(d, n, kinds, lines);
    FUZZ_CHECK(s->width >= 1 && s->width <= FXRT_MAX_DIM, NULL);
    FUZZ_CHECK(s->height >= 1 && s->height <= FXRT_MAX_DIM, NULL);
    fuzz_check_color(s->background);

    /* Exactly one camera, and it is the statement on its line. */
    for (l = 1; l <= lines; l++) {
        if (kinds[l] == FUZZ_LINE_CAMERA)
            cameras++;
        else if ((kinds[l] & ~FUZZ_IN_NODE) < 4)
            file_count[kinds[l] & ~FUZZ_IN_NODE]++;
        else if ((kinds[l] & ~FUZZ_IN_NODE) == FUZZ_LINE_MESH)
            meshes++;
        else if ((kinds[l] & ~FUZZ_IN_NODE) == FUZZ_LINE_ELLIPSOID)
            file_ellipsoids++;
        else if ((kinds[l] & ~FUZZ_IN_NODE) == FUZZ_LINE_PARALLELEPIPED)
            file_pps++;
    }
    FUZZ_CHECK(cameras == 1, NULL);
    FUZZ_CHECK(cam->line >= 1 && cam->line <= lines, NULL);
    FUZZ_CHECK(kinds[cam->line] == FUZZ_LINE_CAMERA, NULL);
    FUZZ_CHECK(cam->kind == SCENE_CAM_PERSPECTIVE || cam->kind == SCENE_CAM_ORTHOGRAPHIC, NULL);
    fuzz_check_vec(cam->eye);
    fuzz_check_vec(cam->gaze);
    fuzz_check_vec(cam->up);
    FUZZ_CHECK(!fuzz_is_zero(cam->gaze) && !fuzz_is_zero(cam->up), NULL);
    {
        /* Not parallel: the parser's relative test, with slack for rounding. */
        scene_vec_t g = cam->gaze, u = cam->up;
        double x = g.y * u.z - g.z * u.y, y = g.z * u.x - g.x * u.z, z = g.x * u.y - g.y * u.x;
        double gl = sqrt(g.x * g.x + g.y * g.y + g.z * g.z);
        double ul = sqrt(u.x * u.x + u.y * u.y + u.z * u.z);
        FUZZ_CHECK(sqrt(x * x + y * y + z * z) > 0.5e-6 * gl * ul, NULL);
    }
    if (cam->kind == SCENE_CAM_PERSPECTIVE) {
        FUZZ_CHECK(cam->fov_deg > 0.0 && cam->fov_deg < 180.0, NULL);
        fuzz_check_num(cam->fov_deg, 180.0);
        FUZZ_CHECK(cam->scale == 0.0, NULL);
    } else {
        FUZZ_CHECK(cam->scale > 0.0, NULL);
        fuzz_check_num(cam->scale, FXRT_RADIUS_LIMIT);
        FUZZ_CHECK(cam->fov_deg == 0.0, NULL);
    }

    /* Objects: within capacity, in file order, one per statement line. */
    FUZZ_CHECK(s->count >= 0 && s->count <= SCENE_MAX_OBJECTS, NULL);
    for (i = 0; i < s->count; i++) {
        const scene_obj_t *o = &s->obj[i];
        /* the four kinds of the lines above, ellipsoids (an ellipsoid
         * line's, or a sphere's that a node scales unevenly) and
         * parallelepipeds (a line's, or a box's that a node turns) */
        FUZZ_CHECK((o->kind >= SCENE_PLANE && o->kind <= SCENE_BOX) || o->kind == SCENE_ELLIPSOID ||
                       o->kind == SCENE_PARALLELEPIPED,
                   NULL);
        FUZZ_CHECK(o->line >= 1 && o->line <= lines, NULL);
        int placed = (kinds[o->line] & FUZZ_IN_NODE) != 0, base = kinds[o->line] & ~FUZZ_IN_NODE;
        /* A mesh's triangles share its line. */
        if (base == FUZZ_LINE_MESH)
            FUZZ_CHECK(o->line >= prev_line && o->kind == SCENE_TRIANGLE, NULL);
        else if (o->kind == SCENE_ELLIPSOID)
            FUZZ_CHECK(o->line > prev_line && (base == FUZZ_LINE_ELLIPSOID || (placed && base == SCENE_SPHERE)), NULL);
        else if (o->kind == SCENE_PARALLELEPIPED)
            FUZZ_CHECK(o->line > prev_line && (base == FUZZ_LINE_PARALLELEPIPED || (placed && base == SCENE_BOX)), NULL);
        else
            FUZZ_CHECK(o->line > prev_line && base == (int)o->kind, NULL);
        prev_line = o->line;
        if (o->kind == SCENE_ELLIPSOID)
            ellipsoids++;
        else if (o->kind == SCENE_PARALLELEPIPED)
            pps++;
        else
            kind_count[o->kind]++;
        fuzz_check_color(o->color);
        for (k = 0; k < 4; k++) {
            if (placed || base == FUZZ_LINE_MESH)
                fuzz_check_placed(o->p[k]);
            else
                fuzz_check_vec(o->p[k]);
        }
        switch (o->kind) {
        case SCENE_PLANE:
            FUZZ_CHECK(!fuzz_is_zero(o->p[1]), NULL);
            FUZZ_CHECK(fuzz_is_zero(o->p[2]) && o->radius == 0.0, NULL);
            break;
        case SCENE_SPHERE:
            FUZZ_CHECK(o->radius > 0.0, NULL);
            fuzz_check_num(o->radius, FXRT_RADIUS_LIMIT);
            FUZZ_CHECK(fuzz_is_zero(o->p[1]) && fuzz_is_zero(o->p[2]), NULL);
            break;
        case SCENE_TRIANGLE:
            FUZZ_CHECK(o->radius == 0.0, NULL);
            break;
        case SCENE_BOX:
            FUZZ_CHECK(o->p[0].x <= o->p[1].x && o->p[0].y <= o->p[1].y && o->p[0].z <= o->p[1].z,
                       NULL);
            FUZZ_CHECK(fuzz_is_zero(o->p[2]) && o->radius == 0.0, NULL);
            break;
        case SCENE_ELLIPSOID:
        case SCENE_PARALLELEPIPED:
            FUZZ_CHECK(!fuzz_is_zero(o->p[1]) && !fuzz_is_zero(o->p[2]) && !fuzz_is_zero(o->p[3]) && o->radius == 0.0,
                       NULL);
            break;
        default: break;
        }
    }
    FUZZ_CHECK(ellipsoids <= FXRT_MAX_ELLIPSOIDS && pps <= FXRT_MAX_PARALLELEPIPEDS, NULL);
    for (k = 0; k < 4; k++) {
        FUZZ_CHECK(kind_count[k] <= cap[k], NULL);
        if (k == SCENE_TRIANGLE && meshes > 0)
            FUZZ_CHECK(kind_count[k] >= file_count[k], NULL);
        else if (k == SCENE_SPHERE) /* (some may be ellipsoids now) */
            FUZZ_CHECK(kind_count[k] + ellipsoids == file_count[k] + file_ellipsoids && ellipsoids >= file_ellipsoids,
                       NULL);
        else if (k == SCENE_BOX) /* (some may be parallelepipeds now) */
            FUZZ_CHECK(kind_count[k] + pps == file_count[k] + file_pps && pps >= file_pps, NULL);
        else
            FUZZ_CHECK(kind_count[k] == file_count[k], NULL);
    }

    /* Materials: flat by default; specular and exponent only for phong
     * and reflective, reflection only for reflective, index only for
     * transparent. */
    for (i = 0; i < s->count; i++) {
        const scene_obj_t *o = &s->obj[i];
        FUZZ_CHECK(o->material == SCENE_MAT_FLAT || o->material == SCENE_MAT_LAMBERT ||
                       o->material == SCENE_MAT_PHONG || o->material == SCENE_MAT_REFLECTIVE ||
                       o->material == SCENE_MAT_TRANSPARENT,
                   NULL);
        fuzz_check_color(o->specular);
        fuzz_check_color(o->reflection);
        if (o->material == SCENE_MAT_PHONG || o->material == SCENE_MAT_REFLECTIVE) {
            FUZZ_CHECK(o->exponent >= 1 && o->exponent <= SCENE_MAX_EXPONENT, NULL);
        } else {
            FUZZ_CHECK(o->exponent == 0, NULL);
            FUZZ_CHECK(o->specular[0] == 0.0 && o->specular[1] == 0.0 && o->specular[2] == 0.0, NULL);
        }
        if (o->material != SCENE_MAT_REFLECTIVE)
            FUZZ_CHECK(o->reflection[0] == 0.0 && o->reflection[1] == 0.0 && o->reflection[2] == 0.0, NULL);
        if (o->material == SCENE_MAT_TRANSPARENT) {
            FUZZ_CHECK(o->index >= FXRT_INDEX_MIN && o->index <= FXRT_INDEX_MAX, NULL);
            fuzz_check_num(o->index, FXRT_INDEX_MAX);
        } else {
            FUZZ_CHECK(o->index == 0.0, NULL);
        }
    }

    /* Depth and samples: at most one line each, the stored line is it,
     * the defaults (4; 1, not adaptive) without one. */
    {
        long depths = 0, samples = 0;
        for (l = 1; l <= lines; l++) {
            depths += kinds[l] == FUZZ_LINE_DEPTH;
            samples += kinds[l] == FUZZ_LINE_SAMPLES;
        }
        FUZZ_CHECK(depths <= 1 && samples <= 1, NULL);
        FUZZ_CHECK(s->depth >= 0 && s->depth <= SCENE_MAX_DEPTH, NULL);
        if (depths == 0)
            FUZZ_CHECK(s->depth_line == 0 && s->depth == SCENE_DEFAULT_DEPTH, NULL);
        else
            FUZZ_CHECK(s->depth_line >= 1 && s->depth_line <= lines && kinds[s->depth_line] == FUZZ_LINE_DEPTH, NULL);
        FUZZ_CHECK(s->samples >= 1 && s->samples <= SCENE_MAX_SAMPLES, NULL);
        FUZZ_CHECK(s->adaptive == 0 || (s->adaptive == 1 && s->samples >= 2), NULL);
        if (samples == 0)
            FUZZ_CHECK(s->samples_line == 0 && s->samples == 1 && s->adaptive == 0, NULL);
        else
            FUZZ_CHECK(s->samples_line >= 1 && s->samples_line <= lines &&
                           kinds[s->samples_line] == FUZZ_LINE_SAMPLES,
                       NULL);
    }

    /* Ambient: at most one line, and the stored line is it. */
    {
        long ambients = 0;
        for (l = 1; l <= lines; l++)
            ambients += kinds[l] == FUZZ_LINE_AMBIENT;
        FUZZ_CHECK(ambients <= 1, NULL);
        FUZZ_CHECK(ambients == 0 ? s->ambient_line == 0 : kinds[s->ambient_line] == FUZZ_LINE_AMBIENT, NULL);
        fuzz_check_color(s->ambient);
        if (ambients == 0)
            FUZZ_CHECK(s->ambient[0] == 0.0 && s->ambient[1] == 0.0 && s->ambient[2] == 0.0, NULL);
    }

    /* Lights: within capacity, in file order, one per 'light' line, each
     * kind with exactly its own fields. */
    {
        long light_lines = 0;
        for (l = 1; l <= lines; l++)
            light_lines += kinds[l] == FUZZ_LINE_LIGHT;
        FUZZ_CHECK(s->nlights >= 0 && s->nlights <= SCENE_MAX_LIGHTS, NULL);
        FUZZ_CHECK(s->nlights == light_lines, NULL);
        prev_line = 0;
        for (i = 0; i < s->nlights; i++) {
            const scene_light_t *lt = &s->light[i];
            FUZZ_CHECK(lt->line > prev_line && lt->line <= lines, NULL);
            prev_line = lt->line;
            FUZZ_CHECK(kinds[lt->line] == FUZZ_LINE_LIGHT, NULL);
            fuzz_check_vec(lt->position);
            fuzz_check_vec(lt->direction);
            fuzz_check_color(lt->color);
            FUZZ_CHECK(lt->shadows == 0 || lt->shadows == 1, NULL);
            switch (lt->kind) {
            case SCENE_LIGHT_POINT:
                FUZZ_CHECK(fuzz_is_zero(lt->direction) && lt->angle_deg == 0.0, NULL);
                break;
            case SCENE_LIGHT_DIRECTIONAL:
                FUZZ_CHECK(!fuzz_is_zero(lt->direction), NULL);
                FUZZ_CHECK(fuzz_is_zero(lt->position) && lt->angle_deg == 0.0, NULL);
                break;
            case SCENE_LIGHT_SPOT:
                FUZZ_CHECK(!fuzz_is_zero(lt->direction), NULL);
                FUZZ_CHECK(lt->angle_deg > 0.0 && lt->angle_deg <= 90.0, NULL);
                fuzz_check_num(lt->angle_deg, 90.0);
                break;
            default:
                FUZZ_CHECK(0 && "light kind", NULL);
            }
        }
    }
    free(kinds);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static char err[FUZZ_ERR_LEN], err_short[FUZZ_ERR_LEN];
    long lines = fuzz_line_count(data, size);
    size_t short_len;
    int rc, rc2;

    /* libFuzzer's buffer is exactly `size` bytes on the heap, so ASan
     * catches any read past the end; it is not NUL-terminated. */
    memset(err, 'x', sizeof err);
    rc = scene_parse(FUZZ_NAME, (const char *)data, size, &fuzz_scene_a, err, sizeof err);
    FUZZ_CHECK(rc == 0 || rc == -1, NULL);
    if (rc == 0) {
        FUZZ_CHECK(err[0] == '\0', err);
        fuzz_check_scene(&fuzz_scene_a, data, size, lines);
    } else {
        fuzz_check_error(err, lines);
    }

    /* Same input, small error buffer (1..64 bytes, from the input's
     * length): same outcome, the message truncated to a prefix. */
    short_len = 1 + size % 64;
    memset(err_short, 'x', sizeof err_short);
    rc2 = scene_parse(FUZZ_NAME, (const char *)data, size, &fuzz_scene_b, err_short, short_len);
    FUZZ_CHECK(rc2 == rc, err);
    FUZZ_CHECK(memchr(err_short, '\0', short_len) != NULL, err);
    FUZZ_CHECK(err_short[short_len] == 'x', err); /* nothing written past errlen */
    FUZZ_CHECK(strncmp(err_short, err, strlen(err_short)) == 0, err);
    FUZZ_CHECK(strlen(err_short) == (strlen(err) < short_len - 1 ? strlen(err) : short_len - 1), err);

    /* And without an error buffer at all. */
    rc2 = scene_parse(FUZZ_NAME, (const char *)data, size, &fuzz_scene_b, NULL, 0);
    FUZZ_CHECK(rc2 == rc, err);
    if (rc == 0) {
        FUZZ_CHECK(fuzz_scene_b.count == fuzz_scene_a.count, NULL);
        FUZZ_CHECK(fuzz_scene_b.camera.line == fuzz_scene_a.camera.line, NULL);
        FUZZ_CHECK(fuzz_scene_b.nlights == fuzz_scene_a.nlights, NULL);
    }
    return 0;
}
