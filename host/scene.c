/* Scene files: a line-based text format, parsed and validated here so that
 * every renderer build (Q16.16, float, double) receives the same, already
 * checked values. The parser is meant to survive arbitrary bytes (it is
 * fuzzed): it never reads past len, never relies on a terminating NUL and
 * reports the first problem it finds as "NAME:LINE: message".
 *
 * Format, one statement per line, '#' starts a comment:
 *   image W H
 *   background R G B
 *   camera perspective  eye X Y Z gaze X Y Z up X Y Z fov DEGREES
 *   camera orthographic eye X Y Z gaze X Y Z up X Y Z scale HEIGHT
 *   plane    point X Y Z normal X Y Z color R G B
 *   sphere   center X Y Z radius R color R G B
 *   triangle a X Y Z b X Y Z c X Y Z color R G B
 *   box      min X Y Z max X Y Z color R G B
 *   ambient R G B
 *   light point       position X Y Z color R G B [shadows on|off]
 *   light directional direction X Y Z color R G B [shadows on|off]
 *   light spot        position X Y Z direction X Y Z angle DEGREES color R G B [shadows on|off]
 *   depth N
 *   samples N [adaptive]
 * and on any object: [material flat|lambert|phong|reflective|transparent]
 * (phong: specular R G B exponent N; reflective: the same and reflection
 * R G B; transparent: index ETA). Named fields may come in any order; each
 * is required exactly once, optional ones at most once. docs/SCENES.md has
 * the rules. */
#include "scene.h"

#include "decimal.h"
#include "errf.h"
#include "obj.h"
#include "xform.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Files above this size are refused before parsing: a scene of this format
 * is at most a few hundred lines, anything bigger is a mistake (wrong file)
 * and should not cost memory or time. */
#define SCENE_MAX_FILE_BYTES (1024L * 1024L)

/* A line of at most SCENE_MAX_LINE bytes holds at most this many tokens
 * (each token needs one byte plus one separator). */
#define SCENE_MAX_TOKENS (SCENE_MAX_LINE / 2 + 1)

/* Tokens quoted in messages are cut to this many bytes, so that a 1000-byte
 * token does not drown the message. */
#define SCENE_QUOTE_MAX 40

/* Smallest nonzero magnitude Q16.16 can hold; smaller values would silently
 * become 0 in the fixed-point build, so they are rejected for all builds. */
#define SCENE_Q16_EPS (1.0 / 65536.0)

/* Up must make an angle of at least asin(1/64) = 0.895 degrees with +-gaze:
 * |g x u| >= |g| |u| / 64, the same limit as cam_setup's
 * (CAM_UP_MIN_SIN_SHIFT in core/scene/cam.h). */
#define SCENE_UP_MIN_SIN (1.0 / 64.0)
#define SCENE_UP_HINT "to look straight down use e.g. 'gaze 0 -1 0 up 0 0 -1'"

/* A direction (gaze, normal) or the camera's right vector u = gaze x up
 * must not turn by more than this many LSB (2^-16 rad) when the scene's
 * values are rounded to Q16.16: the Q16.16 build sets up the camera and
 * planes from the rounded values themselves (docs/ACCURACY.md, "Camera"). */
#define SCENE_TURN_CAP 4.0

#if defined(__GNUC__) || defined(__clang__)
#define SCENE_PRINTF(f, a) __attribute__((format(printf, f, a)))
#else
#define SCENE_PRINTF(f, a)
#endif

/* A token is a view into the text (which is not NUL-terminated). */
typedef struct {
    const char *s;
    size_t n;
} scene_tok_t;

/* What kind of value a field holds; decides count and range checks. */
typedef enum {
    SCENE_F_POINT,  /* 3 coordinates, |v| <= FXRT_COORD_LIMIT */
    SCENE_F_DIR,    /* 3 components, |v| <= FXRT_COORD_LIMIT, nonzero length */
    SCENE_F_MAX,    /* a POINT not below the field before it on any axis (a box's max) */
    SCENE_F_AXIS,   /* 3 components, |v| <= FXRT_COORD_LIMIT, nonzero (an ellipsoid's semi-axis) */
    SCENE_F_COLOR,  /* 3 components in 0..1 */
    SCENE_F_RADIUS, /* 1 value in (0, FXRT_RADIUS_LIMIT] */
    SCENE_F_FOV,    /* 1 value in (0, 180) degrees */
    SCENE_F_SCALE,  /* 1 value in (0, FXRT_RADIUS_LIMIT] */
    SCENE_F_ANGLE,  /* 1 value in (0, 90] degrees (a spot light's half-angle) */
    SCENE_F_INDEX,  /* 1 value in [FXRT_INDEX_MIN, FXRT_INDEX_MAX] (refraction index) */
    SCENE_F_EXPONENT, /* 1 integer in 1..SCENE_MAX_EXPONENT */
    SCENE_F_MATERIAL, /* 1 word: flat, lambert, phong, reflective or transparent */
    SCENE_F_ONOFF,    /* 1 word: on or off */
    SCENE_F_SHADING   /* 1 word: smooth or flat (a mesh's) */
} scene_ftype_t;

typedef struct {
    const char *name;
    scene_ftype_t type;
    int optional; /* 0: required exactly once; 1: at most once */
} scene_field_t;

#define SCENE_MAX_FIELDS 10

/* The fields of one statement, in the order they are stored and in which
 * missing ones are reported. */
typedef struct {
    const char *label; /* used in messages: "sphere", "perspective camera" */
    int nfields;
    scene_field_t field[SCENE_MAX_FIELDS];
} scene_shape_t;

/* Every object ends with color and then its optional material fields
 * (scene_parse_object and scene_check_material rely on this order). */
#define SCENE_MATERIAL_FIELDS                                                                                 \
    {"material", SCENE_F_MATERIAL, 1}, {"specular", SCENE_F_COLOR, 1}, {"exponent", SCENE_F_EXPONENT, 1},     \
        {"reflection", SCENE_F_COLOR, 1}, { "index", SCENE_F_INDEX, 1 }
#define SCENE_N_MATERIAL_FIELDS 5
/* Each kind's statement, from the kinds table (scene/kinds.h): its fields
 * (unused ones, type NONE, left out), then color and the material ones. */
#define SCENE_NF_NONE 0
#define SCENE_NF_POINT 1
#define SCENE_NF_DIR 1
#define SCENE_NF_RADIUS 1
#define SCENE_NF_MAX 1
#define SCENE_NF_AXIS 1
#define SCENE_NF_INST 0
#define SCENE_FIELD(f, t) SCENE_FIELD_##t(f, t)
#define SCENE_FIELD_NONE(f, t)
#define SCENE_FIELD_POINT(f, t) {#f, SCENE_F_##t, 0},
#define SCENE_FIELD_DIR SCENE_FIELD_POINT
#define SCENE_FIELD_RADIUS SCENE_FIELD_POINT
#define SCENE_FIELD_MAX SCENE_FIELD_POINT
#define SCENE_FIELD_AXIS SCENE_FIELD_POINT
#define SCENE_FIELD_INST(f, t)
#define SCENE_SHAPE(K, k, ks, cap, solid, bounded, form, edges, f1, t1, f2, t2, f3, t3, f4, t4)              \
    {#k,                                                                                                      \
     SCENE_NF_##t1 + SCENE_NF_##t2 + SCENE_NF_##t3 + SCENE_NF_##t4 + 1 + SCENE_N_MATERIAL_FIELDS,             \
     {SCENE_FIELD(f1, t1) SCENE_FIELD(f2, t2) SCENE_FIELD(f3, t3) SCENE_FIELD(f4, t4){"color", SCENE_F_COLOR, 0}, \
      SCENE_MATERIAL_FIELDS}},
static const scene_shape_t scene_kind_shape[] = {FXRT_KINDS(SCENE_SHAPE)};
/* Lights: shadows is optional (default on). */
static const scene_shape_t scene_shape_point = {
    "point light", 3, {{"position", SCENE_F_POINT, 0}, {"color", SCENE_F_COLOR, 0}, {"shadows", SCENE_F_ONOFF, 1}}};
static const scene_shape_t scene_shape_directional = {
    "directional light", 3,
    {{"direction", SCENE_F_DIR, 0}, {"color", SCENE_F_COLOR, 0}, {"shadows", SCENE_F_ONOFF, 1}}};
static const scene_shape_t scene_shape_spot = {"spot light", 5,
                                               {{"position", SCENE_F_POINT, 0},
                                                {"direction", SCENE_F_DIR, 0},
                                                {"angle", SCENE_F_ANGLE, 0},
                                                {"color", SCENE_F_COLOR, 0},
                                                {"shadows", SCENE_F_ONOFF, 1}}};
static const scene_shape_t scene_shape_persp = {
    "perspective camera", 4,
    {{"eye", SCENE_F_POINT, 0}, {"gaze", SCENE_F_DIR, 0}, {"up", SCENE_F_DIR, 0}, {"fov", SCENE_F_FOV, 0}}};
static const scene_shape_t scene_shape_ortho = {
    "orthographic camera", 4,
    {{"eye", SCENE_F_POINT, 0}, {"gaze", SCENE_F_DIR, 0}, {"up", SCENE_F_DIR, 0}, {"scale", SCENE_F_SCALE, 0}}};

/* A mesh, after 'mesh file PATH': its shading (default smooth), colour
 * and material. */
static const scene_shape_t scene_shape_mesh = {
    "mesh", 2 + SCENE_N_MATERIAL_FIELDS, {{"shading", SCENE_F_SHADING, 1}, {"color", SCENE_F_COLOR, 0}, SCENE_MATERIAL_FIELDS}};

/* Every field name of every statement. A run of values ends at any of
 * them, so "center 0 0 radius 1" reports "got 2" rather than trying to read
 * "radius" as a number. */
#define SCENE_KIND_FIELDS(K, k, ks, cap, solid, bounded, form, edges, f1, t1, f2, t2, f3, t3, f4, t4)       \
    SCENE_FIELD_NAME_##t1(f1) SCENE_FIELD_NAME_##t2(f2) SCENE_FIELD_NAME_##t3(f3) SCENE_FIELD_NAME_##t4(f4)
#define SCENE_FIELD_NAME_NONE(f)
#define SCENE_FIELD_NAME_POINT(f) #f,
#define SCENE_FIELD_NAME_DIR SCENE_FIELD_NAME_POINT
#define SCENE_FIELD_NAME_RADIUS SCENE_FIELD_NAME_POINT
#define SCENE_FIELD_NAME_MAX SCENE_FIELD_NAME_POINT
#define SCENE_FIELD_NAME_AXIS SCENE_FIELD_NAME_POINT
#define SCENE_FIELD_NAME_INST(f)
static const char *const scene_all_fields[] = {FXRT_KINDS(SCENE_KIND_FIELDS) "color",
                                                "eye",   "gaze",   "up",     "fov",    "scale",
                                                "material", "specular", "exponent", "position", "direction",
                                                "angle", "shadows", "reflection", "index", "shading", "file"};

/* Word values, indexed like scene_material_t. */
static const char *const scene_material_names[] = {"flat", "lambert", "phong", "reflective", "transparent"};
#define SCENE_N_MATERIALS ((int)(sizeof scene_material_names / sizeof scene_material_names[0]))
#define SCENE_MATERIAL_LIST "flat, lambert, phong, reflective or transparent"

/* Per object kind (indexed by scene_kind_t): names and capacities. */
#define SCENE_KIND_PLURAL(K, k, ks, ...) #ks,
#define SCENE_KIND_MACRO(K, k, ks, cap, ...) #cap,
#define SCENE_KIND_CAPACITY(K, k, ks, cap, ...) cap,
static const char *const scene_kind_plural[] = {FXRT_KINDS(SCENE_KIND_PLURAL)};
static const char *const scene_kind_macro[] = {FXRT_KINDS(SCENE_KIND_MACRO)};
static const int scene_kind_capacity[] = {FXRT_KINDS(SCENE_KIND_CAPACITY)};
/* Whether the kind has a statement of its own (a model comes from 'mesh'). */
#define SCENE_KIND_WORD(K, k, ks, cap, solid, bounded, form, edges, f1, t1, ...) SCENE_WORD_##t1,
#define SCENE_WORD_POINT 1
#define SCENE_WORD_INST 0
static const int scene_kind_word[] = {FXRT_KINDS(SCENE_KIND_WORD)};

/* Values read for one field, with their tokens so messages can quote what
 * the user wrote (e.g. "1e99999" rather than "inf"). */
typedef struct {
    int seen;
    double v[3];
    scene_tok_t t[3];
    int word; /* word fields: the index of the word (material: scene_material_t; on/off: 1/0) */
    long iv;  /* SCENE_F_EXPONENT: the integer */
} scene_fval_t;

typedef struct {
    const char *name; /* file name for messages */
    char *err;
    size_t errlen;
    int line; /* current line, 1-based */
    scene_t *out;
    int camera_line, image_line, background_line, ambient_line, depth_line, samples_line; /* 0 = not seen yet */
    int kind_count[SCENE_KINDS];
    /* Open nodes: node_xf[d] is the transform of depth d's contents (its
     * own after its parent's), node_xf[0] the identity; node_line[d] the
     * line of depth d's 'node'. */
    int node_depth;
    int node_line[SCENE_MAX_NODE_DEPTH + 1];
    xform_t node_xf[SCENE_MAX_NODE_DEPTH + 1];
    int ntok;
    scene_tok_t tok[SCENE_MAX_TOKENS];
} scene_parser_t;

/* A token copied for quoting in a message, shortened if very long. */
typedef struct {
    char s[SCENE_QUOTE_MAX + 4];
} scene_quote_t;

/* Write "NAME:LINE: message" and return -1, so callers can `return
 * scene_fail(...)`. */
SCENE_PRINTF(2, 3)
static int scene_fail(scene_parser_t *p, const char *fmt, ...)
{
    va_list ap;
    int n;

    if (p->err == NULL || p->errlen == 0)
        return -1;
    n = snprintf(p->err, p->errlen, "%s:%d: ", p->name, p->line);
    if (n < 0 || (size_t)n >= p->errlen)
        return -1;
    va_start(ap, fmt);
    vsnprintf(p->err + n, p->errlen - (size_t)n, fmt, ap);
    va_end(ap);
    return -1;
}

static scene_quote_t scene_quote(scene_tok_t t)
{
    scene_quote_t q;
    size_t n = t.n < SCENE_QUOTE_MAX ? t.n : SCENE_QUOTE_MAX;

    memcpy(q.s, t.s, n);
    if (t.n > SCENE_QUOTE_MAX) {
        memcpy(q.s + n, "...", 4);
    } else {
        q.s[n] = '\0';
    }
    return q;
}

static int scene_tok_is(scene_tok_t t, const char *word)
{
    size_t n = strlen(word);
    return t.n == n && memcmp(t.s, word, n) == 0;
}

static int scene_is_digit(char c)
{
    return c >= '0' && c <= '9';
}

/* Case-insensitive prefix test without <ctype.h> (whose functions are
 * locale-dependent and undefined for negative char values). */
static int scene_tok_starts_ci(scene_tok_t t, size_t from, const char *word)
{
    size_t i;

    for (i = 0; word[i] != '\0'; i++) {
        char c;
        if (from + i >= t.n)
            return 0;
        c = t.s[from + i];
        if (c >= 'A' && c <= 'Z')
            c = (char)(c - 'A' + 'a');
        if (c != word[i])
            return 0;
    }
    return 1;
}

static int scene_is_field_name(scene_tok_t t)
{
    size_t i;

    for (i = 0; i < sizeof scene_all_fields / sizeof scene_all_fields[0]; i++)
        if (scene_tok_is(t, scene_all_fields[i]))
            return 1;
    return 0;
}

/* Tokens that look like an attempt at a number: used only to count surplus
 * values ("'center' needs 3 numbers, got 4") instead of calling the surplus
 * an unexpected word. */
static int scene_looks_numeric(scene_tok_t t)
{
    size_t i = 0;

    if (t.n == 0)
        return 0;
    if (t.s[0] == '+' || t.s[0] == '-')
        i = 1;
    if (i < t.n && (scene_is_digit(t.s[i]) || t.s[i] == '.'))
        return 1;
    return scene_tok_starts_ci(t, i, "nan") || scene_tok_starts_ci(t, i, "inf");
}

/* Parse one number of field `what`. Range checks belong to the caller;
 * this rejects what no field accepts: non-numbers, NaN/infinity, hex, and
 * nonzero values too small for Q16.16. Overflow ("1e99999") comes back as
 * +-HUGE_VAL and is then rejected by every field's range check with the
 * user's own spelling in the message. */
static int scene_number(scene_parser_t *p, const char *what, scene_tok_t t, double *v)
{
    char buf[SCENE_MAX_LINE + 1];
    scene_quote_t q = scene_quote(t);
    char *end;
    double d;
    int range_err;

    if (!decimal_is_plain(t.s, t.n)) {
        const char *why = decimal_why_not(t.s, t.n);
        if (why == NULL)
            return scene_fail(p, "%s: '%s' is not a number", what, q.s);
        return scene_fail(p, "%s: %s: '%s'", what, why, q.s);
    }
    /* Cannot happen after the line length check; keeps buf safe regardless. */
    if (t.n > SCENE_MAX_LINE)
        return scene_fail(p, "%s: '%s' is not a number", what, q.s);
    memcpy(buf, t.s, t.n);
    buf[t.n] = '\0';
    errno = 0;
    d = strtod(buf, &end);
    range_err = errno == ERANGE;
    /* Only a locale whose decimal point is not '.' gets here. */
    if (end != buf + t.n)
        return scene_fail(p, "%s: '%s' is not a number (check the C locale)", what, q.s);
    /* ERANGE with a small result is underflow: "1e-400" reads as 0 or a
     * denormal, although the user wrote a nonzero value. */
    if ((range_err && fabs(d) < 1.0) || (d != 0.0 && fabs(d) < SCENE_Q16_EPS))
        return scene_fail(p, "%s: too small for Q16.16: %s (nonzero values need magnitude >= 1/65536)",
                          what, q.s);
    /* Store -0 as +0: the double reference renderer should not see signed
     * zeros that the fixed-point build cannot represent. */
    *v = d == 0.0 ? 0.0 : d;
    return 0;
}

/* Range check of one value of a field; t is quoted in messages. */
static int scene_check_value(scene_parser_t *p, const char *what, scene_ftype_t type, scene_tok_t t,
                             double v)
{
    scene_quote_t q = scene_quote(t);

    switch (type) {
    case SCENE_F_POINT:
    case SCENE_F_MAX:
    case SCENE_F_AXIS:
        if (!(fabs(v) <= FXRT_COORD_LIMIT))
            return scene_fail(p, "%s: value %s out of range (|coordinate| <= %g)", what, q.s,
                              (double)FXRT_COORD_LIMIT);
        break;
    case SCENE_F_DIR:
        if (!(fabs(v) <= FXRT_COORD_LIMIT))
            return scene_fail(p, "%s: value %s out of range (|component| <= %g)", what, q.s,
                              (double)FXRT_COORD_LIMIT);
        break;
    case SCENE_F_COLOR:
        if (!(v >= 0.0 && v <= 1.0)) {
            /* "color" for objects, "background color" for the background */
            if (strcmp(what, "color") == 0)
                return scene_fail(p, "color component %s outside 0..1", q.s);
            return scene_fail(p, "%s color component %s outside 0..1", what, q.s);
        }
        break;
    case SCENE_F_RADIUS:
    case SCENE_F_SCALE:
        if (!(v > 0.0))
            return scene_fail(p, "%s must be > 0, got %s", what, q.s);
        if (!(v <= FXRT_RADIUS_LIMIT))
            return scene_fail(p, "%s %s exceeds limit %g", what, q.s, (double)FXRT_RADIUS_LIMIT);
        break;
    case SCENE_F_FOV:
        if (!(v > 0.0 && v < 180.0))
            return scene_fail(p, "%s must be inside (0, 180), got %s", what, q.s);
        break;
    case SCENE_F_ANGLE:
        if (!(v > 0.0 && v <= 90.0))
            return scene_fail(p, "%s must be inside (0, 90] degrees (the cone's half-angle), got %s", what, q.s);
        break;
    case SCENE_F_INDEX:
        if (!(v >= FXRT_INDEX_MIN && v <= FXRT_INDEX_MAX))
            return scene_fail(p, "%s must be inside [%g, %g], got %s", what, (double)FXRT_INDEX_MIN,
                              (double)FXRT_INDEX_MAX, q.s);
        break;
    case SCENE_F_EXPONENT:
    case SCENE_F_MATERIAL:
    case SCENE_F_ONOFF:
    case SCENE_F_SHADING:
        break; /* not numbers: scene_parse_word */
    }
    return 0;
}

static int scene_ftype_count(scene_ftype_t type)
{
    switch (type) {
    case SCENE_F_POINT:
    case SCENE_F_MAX:
    case SCENE_F_AXIS:
    case SCENE_F_DIR:
    case SCENE_F_COLOR:
        return 3;
    case SCENE_F_RADIUS:
    case SCENE_F_FOV:
    case SCENE_F_SCALE:
    case SCENE_F_ANGLE:
    case SCENE_F_INDEX:
    case SCENE_F_EXPONENT:
    case SCENE_F_MATERIAL:
    case SCENE_F_ONOFF:
    case SCENE_F_SHADING:
        break;
    }
    return 1;
}

static int scene_is_word_type(scene_ftype_t type)
{
    return type == SCENE_F_EXPONENT || type == SCENE_F_MATERIAL || type == SCENE_F_ONOFF ||
           type == SCENE_F_SHADING;
}

static int scene_parse_uint(scene_tok_t t, long *v);

/* The value of a one-token field that is not a decimal number: a material
 * name, on/off, or the exponent (an integer, so '64.0' is refused). */
static int scene_parse_word(scene_parser_t *p, const scene_field_t *fd, scene_tok_t t, scene_fval_t *fv)
{
    scene_quote_t q = scene_quote(t);
    int k;

    switch (fd->type) {
    case SCENE_F_MATERIAL:
        for (k = 0; k < SCENE_N_MATERIALS; k++)
            if (scene_tok_is(t, scene_material_names[k])) {
                fv->word = k;
                return 0;
            }
        return scene_fail(p, "unknown material '%s' (expected " SCENE_MATERIAL_LIST ")", q.s);
    case SCENE_F_ONOFF:
        if (scene_tok_is(t, "on") || scene_tok_is(t, "off")) {
            fv->word = scene_tok_is(t, "on");
            return 0;
        }
        return scene_fail(p, "%s must be on or off, got '%s'", fd->name, q.s);
    case SCENE_F_SHADING:
        if (scene_tok_is(t, "smooth") || scene_tok_is(t, "flat")) {
            fv->word = scene_tok_is(t, "smooth");
            return 0;
        }
        return scene_fail(p, "%s must be smooth or flat, got '%s'", fd->name, q.s);
    case SCENE_F_EXPONENT:
        if (scene_parse_uint(t, &fv->iv) != 0)
            return scene_fail(p, "%s must be an integer in 1..%d, got '%s'", fd->name, SCENE_MAX_EXPONENT, q.s);
        if (fv->iv < 1 || fv->iv > SCENE_MAX_EXPONENT)
            return scene_fail(p, "%s %s outside 1..%d", fd->name, q.s, SCENE_MAX_EXPONENT);
        return 0;
    default:
        break;
    }
    return scene_fail(p, "internal error: '%s' is not a word field", fd->name);
}

/* "center, radius, color": the field list used as a hint in messages. */
static void scene_field_list(const scene_shape_t *sh, char *buf, size_t size)
{
    size_t used = 0;
    int f;

    buf[0] = '\0';
    for (f = 0; f < sh->nfields; f++) {
        int n = snprintf(buf + used, size - used, "%s%s", f ? ", " : "", sh->field[f].name);
        if (n < 0 || (size_t)n >= size - used)
            return;
        used += (size_t)n;
    }
}

/* Read "name values name values ..." from token `first` to the end of the
 * line into vals (indexed like sh->field), checking counts, numbers,
 * per-value ranges, duplicates and missing fields. Cross-field checks
 * (zero length, parallel, min <= max) are the caller's. */
static int scene_parse_fields(scene_parser_t *p, const scene_shape_t *sh, int first,
                              scene_fval_t *vals)
{
    char list[128];
    int i = first;
    int f;

    memset(vals, 0, sizeof(scene_fval_t) * SCENE_MAX_FIELDS);
    while (i < p->ntok) {
        scene_tok_t t = p->tok[i];
        const scene_field_t *fd;
        int want, got, extra, k;

        for (f = 0; f < sh->nfields; f++)
            if (scene_tok_is(t, sh->field[f].name))
                break;
        if (f == sh->nfields) {
            scene_quote_t q = scene_quote(t);
            scene_field_list(sh, list, sizeof list);
            if (scene_is_field_name(t))
                return scene_fail(p, "%s has no field '%s' (fields: %s)", sh->label, q.s, list);
            return scene_fail(p, "unexpected '%s' after %s (fields: %s)", q.s, sh->label, list);
        }
        fd = &sh->field[f];
        if (vals[f].seen)
            return scene_fail(p, "duplicate field '%s' in %s", fd->name, sh->label);
        vals[f].seen = 1;
        want = scene_ftype_count(fd->type);
        i++;
        /* Count the values up to the next field name or the end of line. */
        got = 0;
        while (got < want && i + got < p->ntok && !scene_is_field_name(p->tok[i + got]))
            got++;
        /* Surplus numbers ("center 0 0 -3 4") are counted so the message
         * says how many were given; a surplus word is left for the loop
         * above to report as unexpected. */
        extra = 0;
        if (got == want)
            while (i + got + extra < p->ntok && !scene_is_field_name(p->tok[i + got + extra]) &&
                   scene_looks_numeric(p->tok[i + got + extra]))
                extra++;
        if (scene_is_word_type(fd->type)) {
            /* One word; a surplus token is left for the loop above. */
            if (got != 1)
                return scene_fail(p, "'%s' needs a value (%s)", fd->name,
                                  fd->type == SCENE_F_MATERIAL ? SCENE_MATERIAL_LIST
                                  : fd->type == SCENE_F_ONOFF  ? "on or off"
                                  : fd->type == SCENE_F_SHADING ? "smooth or flat"
                                                               : "an integer");
            vals[f].t[0] = p->tok[i];
            if (scene_parse_word(p, fd, p->tok[i], &vals[f]) != 0)
                return -1;
            i++;
            continue;
        }
        if (got != want || extra != 0)
            return scene_fail(p, "'%s' needs %d number%s, got %d", fd->name, want,
                              want == 1 ? "" : "s", got + extra);
        for (k = 0; k < want; k++) {
            vals[f].t[k] = p->tok[i + k];
            if (scene_number(p, fd->name, vals[f].t[k], &vals[f].v[k]) != 0)
                return -1;
            if (scene_check_value(p, fd->name, fd->type, vals[f].t[k], vals[f].v[k]) != 0)
                return -1;
        }
        i += want;
    }
    for (f = 0; f < sh->nfields; f++)
        if (!vals[f].seen && !sh->field[f].optional)
            return scene_fail(p, "missing field '%s' for %s", sh->field[f].name, sh->label);
    return 0;
}

static scene_vec_t scene_vec(const scene_fval_t *fv)
{
    scene_vec_t v;
    v.x = fv->v[0];
    v.y = fv->v[1];
    v.z = fv->v[2];
    return v;
}

/* Values are either 0 or at least 1/65536 in magnitude (scene_number), so
 * any nonzero component means a usable length. */
static int scene_is_zero(scene_vec_t v)
{
    return v.x == 0.0 && v.y == 0.0 && v.z == 0.0;
}

/* x rounded to Q16.16 as the fixed-point build stores it (host/engine.c:
 * to nearest, ties away from zero), as a double. */
static double scene_q16(double x)
{
    double sx = x * 65536.0;
    return (sx >= 0 ? floor(sx + 0.5) : -floor(-sx + 0.5)) / 65536.0;
}

static scene_vec_t scene_vq16(scene_vec_t v)
{
    scene_vec_t r = {scene_q16(v.x), scene_q16(v.y), scene_q16(v.z)};
    return r;
}

static scene_vec_t scene_cross(scene_vec_t a, scene_vec_t b)
{
    scene_vec_t r = {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
    return r;
}

static double scene_len(scene_vec_t v)
{
    return sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
}

/* The angle between a and b (both nonzero), in LSB of 2^-16 rad. */
static double scene_turn(scene_vec_t a, scene_vec_t b)
{
    double la = scene_len(a), lb = scene_len(b);
    scene_vec_t d = {a.x / la - b.x / lb, a.y / la - b.y / lb, a.z / la - b.z / lb};
    return scene_len(d) * 65536.0;
}

static int scene_parse_camera(scene_parser_t *p)
{
    const scene_shape_t *sh;
    scene_fval_t vals[SCENE_MAX_FIELDS];
    scene_camera_t *cam = &p->out->camera;
    scene_vec_t g, u, x;
    double gl, ul, xl;

    if (p->camera_line)
        return scene_fail(p, "second camera (first on line %d)", p->camera_line);
    if (p->ntok < 2)
        return scene_fail(p, "camera needs a type: perspective or orthographic");
    if (scene_tok_is(p->tok[1], "perspective")) {
        sh = &scene_shape_persp;
        cam->kind = SCENE_CAM_PERSPECTIVE;
    } else if (scene_tok_is(p->tok[1], "orthographic")) {
        sh = &scene_shape_ortho;
        cam->kind = SCENE_CAM_ORTHOGRAPHIC;
    } else {
        scene_quote_t q = scene_quote(p->tok[1]);
        return scene_fail(p, "unknown camera type '%s' (expected perspective or orthographic)", q.s);
    }
    if (scene_parse_fields(p, sh, 2, vals) != 0)
        return -1;
    g = scene_vec(&vals[1]);
    u = scene_vec(&vals[2]);
    if (scene_is_zero(g))
        return scene_fail(p, "gaze has zero length");
    if (scene_is_zero(u))
        return scene_fail(p, "up has zero length");
    /* Relative test, so the answer does not depend on the vectors' scale. */
    x.x = g.y * u.z - g.z * u.y;
    x.y = g.z * u.x - g.x * u.z;
    x.z = g.x * u.y - g.y * u.x;
    gl = sqrt(g.x * g.x + g.y * g.y + g.z * g.z);
    ul = sqrt(u.x * u.x + u.y * u.y + u.z * u.z);
    xl = sqrt(x.x * x.x + x.y * x.y + x.z * x.z);
    if (!(xl >= SCENE_UP_MIN_SIN * gl * ul))
        return scene_fail(p, "up is parallel to gaze (or within 0.9 degrees of it); " SCENE_UP_HINT);
    {
        /* Rounding to Q16.16 must not turn the view (w = -gaze) or its
         * roll (u = up x w) by more than the cap. */
        scene_vec_t gq = scene_vq16(g), uq = scene_vq16(u), xq;
        double tw, tu;
        xq = scene_cross(gq, uq);
        tw = scene_len(gq) > 0 ? scene_turn(g, gq) : INFINITY;
        tu = scene_len(xq) > 0 ? scene_turn(x, xq) : INFINITY;
        if (!(tw <= SCENE_TURN_CAP))
            return scene_fail(p, "gaze is too short for Q16.16: rounding it to 1/65536 turns the view by %.3g LSB "
                                 "(more than %g); directions are scale-free, so multiply it by e.g. 1000",
                              tw, SCENE_TURN_CAP);
        if (!(tu <= SCENE_TURN_CAP))
            return scene_fail(p, "up is too short or too close to gaze for Q16.16: rounding turns the camera's roll "
                                 "by %.3g LSB (more than %g); make up longer or further from the gaze",
                              tu, SCENE_TURN_CAP);
    }
    cam->eye = scene_vec(&vals[0]);
    cam->gaze = g;
    cam->up = u;
    cam->fov_deg = cam->kind == SCENE_CAM_PERSPECTIVE ? vals[3].v[0] : 0.0;
    cam->scale = cam->kind == SCENE_CAM_ORTHOGRAPHIC ? vals[3].v[0] : 0.0;
    cam->line = p->line;
    p->camera_line = p->line;
    return 0;
}

/* The material fields of an object, in SCENE_MATERIAL_FIELDS order (m[0]
 * material, m[1] specular, m[2] exponent, m[3] reflection, m[4] index):
 * each of the others belongs to some materials, which need it. */
static int scene_check_material(scene_parser_t *p, const scene_shape_t *sh, const scene_fval_t *m)
{
    /* Per field: the materials it belongs to (bit per scene_material_t),
     * how messages name them, and what to add when no material is given. */
    static const struct {
        const char *name;
        unsigned owners;
        const char *owned_by, *hint;
    } own[SCENE_N_MATERIAL_FIELDS] = {
        {"material", 0, "", ""},
        {"specular", 1u << SCENE_MAT_PHONG | 1u << SCENE_MAT_REFLECTIVE, "material phong or reflective",
         "add 'material phong' or 'material reflective'"},
        {"exponent", 1u << SCENE_MAT_PHONG | 1u << SCENE_MAT_REFLECTIVE, "material phong or reflective",
         "add 'material phong' or 'material reflective'"},
        {"reflection", 1u << SCENE_MAT_REFLECTIVE, "material reflective", "add 'material reflective'"},
        {"index", 1u << SCENE_MAT_TRANSPARENT, "material transparent", "add 'material transparent'"},
    };
    int mat = m[0].seen ? m[0].word : SCENE_MAT_FLAT;
    int k;

    for (k = 1; k < SCENE_N_MATERIAL_FIELDS; k++) {
        int owns = (own[k].owners >> mat) & 1u;
        if (owns && !m[k].seen)
            return scene_fail(p, "missing field '%s' for %s with material %s", own[k].name, sh->label,
                              scene_material_names[mat]);
        if (!owns && m[k].seen) {
            if (m[0].seen) {
                scene_quote_t q = scene_quote(m[0].t[0]);
                return scene_fail(p, "'%s' is only for %s, not %s", own[k].name, own[k].owned_by, q.s);
            }
            return scene_fail(p, "'%s' is only for %s (%s)", own[k].name, own[k].owned_by, own[k].hint);
        }
    }
    return 0;
}

/* A direction whose Q16.16 rounding would turn it by more than the cap. */
static int scene_check_turn(scene_parser_t *p, const char *what, scene_vec_t v)
{
    scene_vec_t vq = scene_vq16(v);
    double t = scene_len(vq) > 0 ? scene_turn(v, vq) : INFINITY;

    if (!(t <= SCENE_TURN_CAP))
        return scene_fail(p, "%s is too short for Q16.16: rounding it to 1/65536 turns it by %.3g LSB "
                             "(more than %g); directions are scale-free, so multiply it by e.g. 1000",
                          what, t, SCENE_TURN_CAP);
    return 0;
}

static int scene_parse_light(scene_parser_t *p)
{
    const scene_shape_t *sh;
    scene_fval_t vals[SCENE_MAX_FIELDS];
    scene_light_t l;
    int f;

    memset(&l, 0, sizeof l);
    if (p->ntok < 2)
        return scene_fail(p, "light needs a type: point, directional or spot");
    if (scene_tok_is(p->tok[1], "point")) {
        sh = &scene_shape_point;
        l.kind = SCENE_LIGHT_POINT;
    } else if (scene_tok_is(p->tok[1], "directional")) {
        sh = &scene_shape_directional;
        l.kind = SCENE_LIGHT_DIRECTIONAL;
    } else if (scene_tok_is(p->tok[1], "spot")) {
        sh = &scene_shape_spot;
        l.kind = SCENE_LIGHT_SPOT;
    } else {
        scene_quote_t q = scene_quote(p->tok[1]);
        return scene_fail(p, "unknown light type '%s' (expected point, directional or spot)", q.s);
    }
    if (SCENE_MAX_LIGHTS <= 0)
        return scene_fail(p, "lights are not in this build (FXRT_MAX_LIGHTS is 0)");
    if (p->out->nlights >= SCENE_MAX_LIGHTS)
        return scene_fail(p, "too many lights (at most %d; the first is on line %d)", SCENE_MAX_LIGHTS,
                          p->out->light[0].line);
    if (scene_parse_fields(p, sh, 2, vals) != 0)
        return -1;
    l.line = p->line;
    l.shadows = 1;
    for (f = 0; f < sh->nfields; f++) {
        const scene_fval_t *v = &vals[f];
        const char *name = sh->field[f].name;
        if (strcmp(name, "position") == 0) {
            l.position = scene_vec(v);
        } else if (strcmp(name, "direction") == 0) {
            l.direction = scene_vec(v);
            if (scene_is_zero(l.direction))
                return scene_fail(p, "direction has zero length");
            if (scene_check_turn(p, "direction", l.direction) != 0)
                return -1;
        } else if (strcmp(name, "angle") == 0) {
            l.angle_deg = v->v[0];
        } else if (strcmp(name, "color") == 0) {
            memcpy(l.color, v->v, sizeof l.color);
        } else if (strcmp(name, "shadows") == 0) {
            if (v->seen)
                l.shadows = v->word;
        }
    }
    p->out->light[p->out->nlights++] = l;
    return 0;
}

/* An object's colour and material from its fields: vals[color_field] is
 * its colour, the material fields follow it. Fields a material does not
 * use stay 0 (scene_check_material has refused them). */
static void scene_set_surface(scene_obj_t *o, const scene_fval_t *vals, int color_field)
{
    const scene_fval_t *m = &vals[color_field + 1];

    for (int k = 0; k < 3; k++)
        o->color[k] = vals[color_field].v[k];
    o->material = m[0].seen ? (scene_material_t)m[0].word : SCENE_MAT_FLAT;
    if (o->material == SCENE_MAT_PHONG || o->material == SCENE_MAT_REFLECTIVE) {
        for (int k = 0; k < 3; k++)
            o->specular[k] = m[1].v[k];
        o->exponent = (int)m[2].iv;
    }
    if (o->material == SCENE_MAT_REFLECTIVE)
        for (int k = 0; k < 3; k++)
            o->reflection[k] = m[3].v[k];
    if (o->material == SCENE_MAT_TRANSPARENT)
        o->index = m[4].v[0];
}

/* Object o (its kind's fields in p[] and radius, as read) through the
 * open nodes' transform, then checked against the domain again. Points
 * map as points; a DIR field is a normal (inverse transpose, normalised);
 * an AXIS maps by the linear part; a sphere (its RADIUS) in a node that
 * is not a similarity becomes the ellipsoid c' = M c + t, u = r M e_x,
 * v = r M e_y, w = r M e_z; a MAX point and the point before it are a
 * box's corners, which need a transform that maps axes onto axes (else
 * the box would turn: a parallelepiped, centre M (min + max) / 2 + t and
 * half edges M e_k (max - min)_k / 2). where
 * names a mesh triangle's face ("PATH:LINE") in messages, or is NULL.
 * Outside nodes nothing moves, and only a mesh's vertices need the range
 * check. */
static int scene_place(scene_parser_t *p, scene_obj_t *o, const char *where)
{
    static const char axis[3] = {'x', 'y', 'z'};
    const scene_shape_t *sh = &scene_kind_shape[o->kind];
    int nf = sh->nfields - 1 - SCENE_N_MATERIAL_FIELDS, d = p->node_depth, nl = p->node_line[d];
    const xform_t *x = &p->node_xf[d];
    char at[600] = "", after[64] = "";

    if (d == 0 && where == NULL)
        return 0;
    if (where != NULL)
        snprintf(at, sizeof at, " (face %s)", where);
    if (d > 0)
        snprintf(after, sizeof after, " after the node on line %d", nl);
    for (int f = 0; d > 0 && f < nf; f++) {
        scene_ftype_t type = sh->field[f].type;
        if (type == SCENE_F_POINT && f + 1 < nf && sh->field[f + 1].type == SCENE_F_MAX)
            continue; /* with the MAX after it */
        if (type == SCENE_F_POINT) {
            o->p[f] = xform_point(x, o->p[f]);
        } else if (type == SCENE_F_AXIS) {
            o->p[f] = xform_vector(x, o->p[f]);
        } else if (type == SCENE_F_DIR) {
            if (xform_normal(x, o->p[f], &o->p[f]) != 0)
                return scene_fail(p, "%s %s cannot be transformed by the node on line %d (its scales underflow)",
                                  sh->label, sh->field[f].name, nl);
            if (scene_check_turn(p, sh->field[f].name, o->p[f]) != 0)
                return -1;
        } else if (type == SCENE_F_RADIUS) {
            double sc;
            if (!xform_similar(x, &sc)) {
                int cap = scene_kind_capacity[SCENE_ELLIPSOID];
                if (p->kind_count[SCENE_ELLIPSOID] >= cap)
                    return scene_fail(p, "a %s in a node that scales unevenly (node on line %d) is an ellipsoid: "
                                         "too many ellipsoids (capacity %d, %s)",
                                      sh->label, nl, cap, scene_kind_macro[SCENE_ELLIPSOID]);
                const scene_vec_t e[3] = {{o->radius, 0, 0}, {0, o->radius, 0}, {0, 0, o->radius}};
                for (int k = 0; k < 3; k++)
                    o->p[1 + k] = xform_vector(x, e[k]);
                o->kind = SCENE_ELLIPSOID;
                o->radius = 0.0;
                sh = &scene_kind_shape[o->kind];
                nf = sh->nfields - 1 - SCENE_N_MATERIAL_FIELDS;
                break; /* (its centre is placed: the field before) */
            }
            o->radius *= sc;
            if (!(o->radius >= SCENE_Q16_EPS && o->radius <= FXRT_RADIUS_LIMIT))
                return scene_fail(p, "%s %s is %g after the node on line %d: outside [1/65536, %g]", sh->label,
                                  sh->field[f].name, o->radius, nl, (double)FXRT_RADIUS_LIMIT);
        } else if (type == SCENE_F_MAX) {
            scene_vec_t lo = o->p[f - 1], hi = o->p[f], a, b;
            if (!xform_axis_aligned(x)) {
                /* a parallelepiped: the centre placed, the half edges by
                 * the linear part */
                int cap = scene_kind_capacity[SCENE_PARALLELEPIPED];
                const double half[3] = {(hi.x - lo.x) / 2, (hi.y - lo.y) / 2, (hi.z - lo.z) / 2};
                if (p->kind_count[SCENE_PARALLELEPIPED] >= cap)
                    return scene_fail(p, "a %s in a node that turns it (node on line %d) is a parallelepiped: too many "
                                         "parallelepipeds (capacity %d, %s)",
                                      sh->label, nl, cap, scene_kind_macro[SCENE_PARALLELEPIPED]);
                for (int k = 0; k < 3; k++)
                    if (!(half[k] > 0))
                        return scene_fail(p, "a %s flat on %c (%s = %s) cannot be turned by the node on line %d: it "
                                             "would be a flat parallelepiped",
                                          sh->label, axis[k], sh->field[f - 1].name, sh->field[f].name, nl);
                const scene_vec_t mid = {(lo.x + hi.x) / 2, (lo.y + hi.y) / 2, (lo.z + hi.z) / 2};
                const scene_vec_t e[3] = {{half[0], 0, 0}, {0, half[1], 0}, {0, 0, half[2]}};
                o->p[0] = xform_point(x, mid);
                for (int k = 0; k < 3; k++)
                    o->p[1 + k] = xform_vector(x, e[k]);
                o->kind = SCENE_PARALLELEPIPED;
                sh = &scene_kind_shape[o->kind];
                nf = sh->nfields - 1 - SCENE_N_MATERIAL_FIELDS;
                break;
            }
            /* The corners' images, per axis their least and greatest. */
            for (int c = 0; c < 8; c++) {
                scene_vec_t q = {(c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z};
                q = xform_point(x, q);
                if (c == 0) {
                    a = b = q;
                    continue;
                }
                a.x = fmin(a.x, q.x), a.y = fmin(a.y, q.y), a.z = fmin(a.z, q.z);
                b.x = fmax(b.x, q.x), b.y = fmax(b.y, q.y), b.z = fmax(b.z, q.z);
            }
            o->p[f - 1] = a;
            o->p[f] = b;
        }
    }
    for (int f = 0; f < nf; f++) {
        scene_ftype_t type = sh->field[f].type;
        if (d > 0 && type != SCENE_F_RADIUS) {
            /* What Q16.16 rounds to 0 is 0 in every build (a rotation's
             * rounding leaves values like 1e-17 where 0 is meant), and
             * never -0. */
            double *c[3] = {&o->p[f].x, &o->p[f].y, &o->p[f].z};
            for (int k = 0; k < 3; k++)
                if (fabs(*c[k]) < SCENE_Q16_EPS / 2)
                    *c[k] = 0.0;
        }
        if (type != SCENE_F_POINT && type != SCENE_F_MAX && type != SCENE_F_AXIS)
            continue;
        double v[3] = {o->p[f].x, o->p[f].y, o->p[f].z};
        for (int k = 0; k < 3; k++)
            if (!(fabs(v[k]) <= FXRT_COORD_LIMIT))
                return scene_fail(p, "%s %s%s is %g on %c%s: out of range (|coordinate| <= %g)", sh->label,
                                  sh->field[f].name, at, v[k], axis[k], after, (double)FXRT_COORD_LIMIT);
    }
    return 0;
}

static int scene_parse_object(scene_parser_t *p, scene_kind_t kind, const scene_shape_t *sh)
{
    scene_fval_t vals[SCENE_MAX_FIELDS];
    scene_obj_t *o;
    int f, color_field, mat_field;

    if (scene_kind_capacity[kind] <= 0)
        return scene_fail(p, "%s are not in this build (%s is 0)", scene_kind_plural[kind],
                          scene_kind_macro[kind]);
    if (p->kind_count[kind] >= scene_kind_capacity[kind])
        return scene_fail(p, "too many %s (capacity %d)", scene_kind_plural[kind],
                          scene_kind_capacity[kind]);
    if (scene_parse_fields(p, sh, 1, vals) != 0)
        return -1;
    mat_field = sh->nfields - SCENE_N_MATERIAL_FIELDS;
    if (scene_check_material(p, sh, &vals[mat_field]) != 0)
        return -1;
    /* The kind's fields by type: a direction nonzero and not turned by
     * Q16.16's rounding, a MAX point not below the field before it. */
    for (f = 0; f < sh->nfields - 1 - SCENE_N_MATERIAL_FIELDS; f++) {
        const char *name = sh->field[f].name;
        if (sh->field[f].type == SCENE_F_AXIS && scene_is_zero(scene_vec(&vals[f])))
            return scene_fail(p, "%s %s has zero length", sh->label, name);
        if (sh->field[f].type == SCENE_F_DIR) {
            scene_vec_t n = scene_vec(&vals[f]), nq = scene_vq16(n);
            if (scene_is_zero(n))
                return scene_fail(p, "%s has zero length", name);
            double tn = scene_len(nq) > 0 ? scene_turn(n, nq) : INFINITY;
            if (!(tn <= SCENE_TURN_CAP))
                return scene_fail(p, "%s is too short for Q16.16: rounding it to 1/65536 turns it by %.3g LSB "
                                     "(more than %g); directions are scale-free, so multiply it by e.g. 1000",
                                  name, tn, SCENE_TURN_CAP);
        }
        if (sh->field[f].type == SCENE_F_MAX) {
            static const char axis[3] = {'x', 'y', 'z'};
            for (int k = 0; k < 3; k++) {
                if (vals[f - 1].v[k] > vals[f].v[k]) {
                    scene_quote_t lo = scene_quote(vals[f - 1].t[k]);
                    scene_quote_t hi = scene_quote(vals[f].t[k]);
                    return scene_fail(p, "%s %s exceeds %s on %c (%s > %s)", sh->label, sh->field[f - 1].name, name,
                                      axis[k], lo.s, hi.s);
                }
            }
        }
    }
    /* Semi-axes (an ellipsoid's, a parallelepiped's) span space:
     * |det [u v w]| above 10^-9 of |u| |v| |w| (else the shape is flat;
     * the build's own limits on thin axes are fxrt_add's, reported when
     * the world is built). */
    if (sh->nfields > 3 && sh->field[1].type == SCENE_F_AXIS) {
        scene_vec_t a = scene_vec(&vals[1]), b = scene_vec(&vals[2]), c = scene_vec(&vals[3]);
        double det = a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x);
        if (!(fabs(det) > 1e-9 * scene_len(a) * scene_len(b) * scene_len(c)))
            return scene_fail(p, "%s u, v and w are dependent: it would be flat", sh->label);
    }
    /* Per-kind capacities sum to SCENE_MAX_OBJECTS, so this cannot
     * overflow obj[]; checked anyway because the array is the last line of
     * defence against a miscounted kind. */
    if (p->out->count >= SCENE_MAX_OBJECTS)
        return scene_fail(p, "too many objects (capacity %d)", SCENE_MAX_OBJECTS);
    o = &p->out->obj[p->out->count];
    memset(o, 0, sizeof *o);
    o->kind = kind;
    o->line = p->line;
    /* Color is the last field before the material ones; the others map in
     * order onto p[] (sphere: center -> p[0], radius -> radius, p[1] stays
     * zero). */
    color_field = sh->nfields - 1 - SCENE_N_MATERIAL_FIELDS;
    for (f = 0; f < color_field; f++) {
        if (sh->field[f].type == SCENE_F_RADIUS)
            o->radius = vals[f].v[0];
        else
            o->p[f] = scene_vec(&vals[f]);
    }
    scene_set_surface(o, vals, color_field);
    if (scene_place(p, o, NULL) != 0)
        return -1;
    p->out->count++;
    p->kind_count[o->kind]++; /* (a sphere that a node made an ellipsoid counts as one) */
    return 0;
}

/* ---- nodes and meshes ---------------------------------------------------- */

/* Token i of a node line as a number in [-limit, limit] (what names it in
 * messages); 0 for a scale is refused. */
static int scene_node_number(scene_parser_t *p, const char *what, int i, double limit, double *v)
{
    scene_quote_t q;

    if (i >= p->ntok || !scene_looks_numeric(p->tok[i]))
        return scene_fail(p, "'%s' needs %s", what,
                          strcmp(what, "scale") == 0 ? "1 or 3 numbers" : strcmp(what, "rotate") == 0 ? "x, y or z and an angle in degrees" : "3 numbers");
    if (scene_number(p, what, p->tok[i], v) != 0)
        return -1;
    q = scene_quote(p->tok[i]);
    if (!(fabs(*v) <= limit))
        return scene_fail(p, "%s %s out of range (|value| <= %g)", what, q.s, limit);
    if (*v == 0.0 && strcmp(what, "scale") == 0)
        return scene_fail(p, "scale %s: a node may not scale by 0 (it would flatten its contents)", q.s);
    return 0;
}

/* 'node [scale S | scale SX SY SZ] [rotate x|y|z DEG] [translate X Y Z] ...':
 * opens a node whose contents are transformed by its steps in the order
 * written, then by its parent's. */
static int scene_parse_node(scene_parser_t *p)
{
    xform_t own, step;
    int i = 1;

    if (p->node_depth >= SCENE_MAX_NODE_DEPTH)
        return scene_fail(p, "nodes nested deeper than %d (the outermost open one is on line %d)",
                          SCENE_MAX_NODE_DEPTH, p->node_line[1]);
    xform_identity(&own);
    while (i < p->ntok) {
        scene_tok_t t = p->tok[i++];
        double v[3];
        if (scene_tok_is(t, "scale")) {
            int n = 0;
            while (n < 3 && i + n < p->ntok && scene_looks_numeric(p->tok[i + n]))
                n++;
            if (n == 2)
                return scene_fail(p, "'scale' needs 1 or 3 numbers, got 2");
            for (int k = 0; k < (n == 3 ? 3 : 1); k++)
                if (scene_node_number(p, "scale", i + k, FXRT_COORD_LIMIT, &v[k]) != 0)
                    return -1;
            if (n != 3)
                v[1] = v[2] = v[0];
            i += n == 3 ? 3 : 1;
            xform_scale(&step, v[0], v[1], v[2]);
        } else if (scene_tok_is(t, "rotate")) {
            int axis = i >= p->ntok                     ? -1
                       : scene_tok_is(p->tok[i], "x") ? 0
                       : scene_tok_is(p->tok[i], "y") ? 1
                       : scene_tok_is(p->tok[i], "z") ? 2
                                                        : -1;
            if (axis < 0) {
                if (i >= p->ntok)
                    return scene_fail(p, "'rotate' needs x, y or z and an angle in degrees");
                scene_quote_t q = scene_quote(p->tok[i]);
                return scene_fail(p, "'rotate' needs an axis x, y or z, got '%s'", q.s);
            }
            if (scene_node_number(p, "rotate", i + 1, SCENE_MAX_ROTATE, &v[0]) != 0)
                return -1;
            i += 2;
            xform_rotate(&step, axis, v[0]);
        } else if (scene_tok_is(t, "translate")) {
            for (int k = 0; k < 3; k++)
                if (scene_node_number(p, "translate", i + k, FXRT_COORD_LIMIT, &v[k]) != 0)
                    return -1;
            if (i + 3 < p->ntok && scene_looks_numeric(p->tok[i + 3]))
                return scene_fail(p, "'translate' needs 3 numbers, got more");
            i += 3;
            xform_translate(&step, v[0], v[1], v[2]);
        } else {
            scene_quote_t q = scene_quote(t);
            return scene_fail(p, "unexpected '%s' in node (expected scale, rotate or translate)", q.s);
        }
        xform_after(&own, &step, &own);
    }
    p->node_depth++;
    xform_after(&p->node_xf[p->node_depth], &p->node_xf[p->node_depth - 1], &own);
    p->node_line[p->node_depth] = p->line;
    return 0;
}

static int scene_parse_end(scene_parser_t *p)
{
    if (p->node_depth == 0)
        return scene_fail(p, "'end' without 'node'");
    if (p->ntok != 1) {
        scene_quote_t q = scene_quote(p->tok[1]);
        return scene_fail(p, "unexpected '%s' after end ('end' stands alone)", q.s);
    }
    p->node_depth--;
    return 0;
}

/* The most triangles of a mesh made triangle objects (scene.h). */
static int scene_mesh_inline = FXRT_MESH_INLINE;

void scene_set_mesh_inline(int n) { scene_mesh_inline = n < 0 ? 0 : n; }

/* A mesh statement's triangles as triangle objects (FXRT_MESH_INLINE):
 * each with the mesh's colour and material, through the open nodes'
 * transform, smooth ones with their vertex normals moved by the nodes.
 * Zero-area triangles are left out and counted. 0, 1 when the triangles
 * do not fit the capacity (nothing added), or -1 with the message. */
static int scene_mesh_triangles(scene_parser_t *p, const char *path, const scene_fval_t *vals, int smooth)
{
    enum { MESH_SHADING, MESH_COLOR, MESH_MATERIAL };
    char err[1024];
    obj_t m;
    size_t keep = 0, dropped = 0, i;
    int cap = scene_kind_capacity[SCENE_TRIANGLE], rc = 0;

    if (obj_load(path, &m, err, sizeof err) != 0) {
        /* The scene's FILE:LINE first, then the OBJ's own: a message cut
         * short by a small buffer keeps the scene's line (a long path once
         * pushed it out of a message written the other way round). */
        scene_fail(p, "%s", err);
        return -1;
    }
    for (i = 0; i < m.ntri; i++) {
        obj_vec_t n = obj_face_normal(&m, i);
        if (n.x == 0.0 && n.y == 0.0 && n.z == 0.0)
            dropped++;
        else
            keep++;
    }
    obj_vec_t *vn = NULL;
    if (keep > (size_t)(cap - p->kind_count[SCENE_TRIANGLE]) ||
        keep > (size_t)(SCENE_MAX_OBJECTS - p->out->count)) {
        rc = 1; /* no room: the caller makes a model */
        goto done;
    }
    if (smooth) {
        vn = malloc(sizeof *vn * 3 * (m.ntri ? m.ntri : 1));
        if (vn == NULL || obj_smooth_normals(&m, vn, NULL) != 0) {
            rc = scene_fail(p, "out of memory for the mesh's normals");
            goto done;
        }
    }
    for (i = 0, keep = 0; i < m.ntri; i++) {
        const obj_tri_t *tr = &m.tri[i];
        obj_vec_t n = obj_face_normal(&m, i);
        scene_obj_t *o = &p->out->obj[p->out->count + keep];
        char where[4200];
        if (n.x == 0.0 && n.y == 0.0 && n.z == 0.0)
            continue;
        memset(o, 0, sizeof *o);
        o->kind = SCENE_TRIANGLE;
        o->line = p->line;
        for (int k = 0; k < 3; k++) {
            const obj_vec_t *v = &m.v[tr->v[k]];
            o->p[k].x = v->x;
            o->p[k].y = v->y;
            o->p[k].z = v->z;
        }
        scene_set_surface(o, vals, MESH_COLOR);
        snprintf(where, sizeof where, "%s:%ld", path, (long)tr->line);
        for (int k = 0; smooth && k < 3; k++) {
            /* Normals move by the nodes' inverse transpose, normalised;
             * outside nodes they are normalised as they are. */
            const obj_vec_t *c = &vn[3 * i + k];
            scene_vec_t v = {c->x, c->y, c->z};
            double len = sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
            if (!(len > 0.0) || !isfinite(len) ||
                (p->node_depth > 0 && xform_normal(&p->node_xf[p->node_depth], v, &v) != 0)) {
                rc = scene_fail(p, "mesh: the normal of corner %d of face %s is zero", k + 1, where);
                goto done;
            }
            if (p->node_depth == 0)
                v.x /= len, v.y /= len, v.z /= len;
            o->vn[k] = v;
        }
        o->smooth = smooth;
        if ((rc = scene_place(p, o, where)) != 0)
            goto done;
        keep++;
    }
    p->out->count += (int)keep;
    p->kind_count[SCENE_TRIANGLE] += (int)keep;
    p->out->mesh_dropped += (long)dropped;
done:
    free(vn);
    obj_free(&m);
    return rc;
}

/* 'mesh file PATH [shading smooth|flat] color R G B [material ...]': a
 * model (scene/model.c): the OBJ file (PATH relative to the scene file's
 * folder) built once into constant mesh data (host/meshstore.c: every
 * mesh statement naming the same file shares it), placed by the open
 * nodes' transform, with the mesh's colour and material. Zero-area
 * triangles are left out and counted. */
static int scene_parse_mesh(scene_parser_t *p)
{
    enum { MESH_SHADING, MESH_COLOR, MESH_MATERIAL };
    scene_fval_t vals[SCENE_MAX_FIELDS];
    char path[4096], err[1024];
    int cap = scene_kind_capacity[SCENE_MODEL];

    if (p->ntok < 3 || !scene_tok_is(p->tok[1], "file"))
        return scene_fail(p, "'mesh' needs 'file PATH' first: mesh file PATH [shading smooth|flat] color R G B");
    if (scene_parse_fields(p, &scene_shape_mesh, 3, vals) != 0)
        return -1;
    if (scene_check_material(p, &scene_shape_mesh, &vals[MESH_MATERIAL]) != 0)
        return -1;
    bool smooth = !vals[MESH_SHADING].seen || vals[MESH_SHADING].word == 1;
    {
        /* The folder of the scene file's name, up to its last '/'. */
        const char *slash = strrchr(p->name, '/');
        scene_tok_t t = p->tok[2];
        int dir = t.s[0] == '/' || slash == NULL ? 0 : (int)(slash - p->name) + 1;
        if ((size_t)dir + t.n >= sizeof path) {
            scene_quote_t q = scene_quote(t);
            return scene_fail(p, "mesh file path too long: '%s'", q.s);
        }
        memcpy(path, p->name, (size_t)dir);
        memcpy(path + dir, t.s, t.n);
        path[(size_t)dir + t.n] = '\0';
    }
    const bvh_mesh_t *mesh;
    const meshstore_entry_t *e = meshstore_get(path, smooth, &mesh, err, sizeof err);
    if (e == NULL) /* The scene's FILE:LINE first, then the OBJ's own: a message cut short
                    * by a small buffer keeps the scene's line (a long path once pushed it
                    * out of a message written the other way round). */
        return scene_fail(p, "%s", err);
    /* A small mesh: triangle objects, where they fit and smooth ones can be */
    if (e->mb.mesh.n_triangles <= (uint32_t)scene_mesh_inline && (FXRT_SMOOTH || !smooth)) {
        int rc = scene_mesh_triangles(p, path, vals, smooth); /* (the shading asked, not the shared build's) */
        if (rc <= 0)
            return rc;
    }
    if (cap <= 0)
        return scene_fail(p, "this mesh must be a model (more than %d triangles, or no room for them as triangles%s), "
                             "and models are not in this build (%s is 0)",
                          scene_mesh_inline, FXRT_SMOOTH ? "" : ", or smooth without FXRT_SMOOTH",
                          scene_kind_macro[SCENE_MODEL]);
    if (p->kind_count[SCENE_MODEL] >= cap)
        return scene_fail(p, "too many meshes (capacity %d, %s)", cap, scene_kind_macro[SCENE_MODEL]);
    if (p->out->count >= SCENE_MAX_OBJECTS)
        return scene_fail(p, "too many objects (capacity %d)", SCENE_MAX_OBJECTS);
    scene_obj_t *o = &p->out->obj[p->out->count];
    memset(o, 0, sizeof *o);
    o->kind = SCENE_MODEL;
    o->line = p->line;
    scene_set_surface(o, vals, MESH_COLOR);
    o->store = e;
    o->mesh = mesh;
    const xform_t *x = &p->node_xf[p->node_depth];
    double a[3][3];
    memcpy(a, x->m, sizeof a);
    if (meshbuild_map(&e->mb, a, x->t, &o->map, err, sizeof err) != 0) {
        if (p->node_depth > 0)
            return scene_fail(p, "mesh %s, after the node on line %d: %s", path, p->node_line[p->node_depth], err);
        return scene_fail(p, "mesh %s: %s", path, err);
    }
    p->out->count++;
    p->kind_count[SCENE_MODEL]++;
    p->out->mesh_dropped += (long)e->mb.dropped;
    return 0;
}

/* Non-negative decimal integer without sign; saturates so that absurdly
 * long digit strings still compare as "too big". */
static int scene_parse_uint(scene_tok_t t, long *v)
{
    size_t i;
    long n = 0;

    if (t.n == 0)
        return -1;
    for (i = 0; i < t.n; i++) {
        if (!scene_is_digit(t.s[i]))
            return -1;
        if (n < 100000000L) /* keeps n below 2^31 for 32-bit long */
            n = n * 10 + (t.s[i] - '0');
    }
    *v = n;
    return 0;
}

static int scene_parse_image(scene_parser_t *p)
{
    long size[2] = {0, 0};
    int k;

    if (p->image_line)
        return scene_fail(p, "duplicate 'image' line (first on line %d)", p->image_line);
    if (p->ntok != 3)
        return scene_fail(p, "'image' needs 2 integers, got %d value%s", p->ntok - 1,
                          p->ntok == 2 ? "" : "s");
    for (k = 0; k < 2; k++) {
        if (scene_parse_uint(p->tok[k + 1], &size[k]) != 0) {
            scene_quote_t q = scene_quote(p->tok[k + 1]);
            return scene_fail(p, "'image' needs 2 integers, got '%s'", q.s);
        }
    }
    if (size[0] < 1 || size[0] > FXRT_MAX_DIM || size[1] < 1 || size[1] > FXRT_MAX_DIM) {
        scene_quote_t qw = scene_quote(p->tok[1]);
        scene_quote_t qh = scene_quote(p->tok[2]);
        return scene_fail(p, "image size must be 1..%d x 1..%d, got %sx%s", FXRT_MAX_DIM,
                          FXRT_MAX_DIM, qw.s, qh.s);
    }
    p->out->width = (int)size[0];
    p->out->height = (int)size[1];
    p->image_line = p->line;
    return 0;
}

/* The integer of 'depth N' or 'samples N' (token 1), in lo..hi. */
static int scene_parse_count(scene_parser_t *p, const char *what, long lo, long hi, long *v)
{
    scene_quote_t q = scene_quote(p->tok[1]);

    if (scene_parse_uint(p->tok[1], v) != 0)
        return scene_fail(p, "'%s' needs an integer in %ld..%ld, got '%s'", what, lo, hi, q.s);
    if (*v < lo || *v > hi)
        return scene_fail(p, "%s %s outside %ld..%ld", what, q.s, lo, hi);
    return 0;
}

/* 'depth N': bounces per primary ray, 0..SCENE_MAX_DEPTH, at most once. */
static int scene_parse_depth(scene_parser_t *p)
{
    long v;

    if (p->depth_line)
        return scene_fail(p, "duplicate 'depth' line (first on line %d)", p->depth_line);
    if (p->ntok != 2)
        return scene_fail(p, "'depth' needs 1 integer, got %d values", p->ntok - 1);
    if (scene_parse_count(p, "depth", 0, SCENE_MAX_DEPTH, &v) != 0)
        return -1;
    p->out->depth = (int)v;
    p->depth_line = p->out->depth_line = p->line;
    return 0;
}

/* 'samples N [adaptive]': N x N rays per pixel, 1..SCENE_MAX_SAMPLES, at
 * most once; adaptive needs N >= 2 (with one ray per pixel there is
 * nothing to leave out). */
static int scene_parse_samples(scene_parser_t *p)
{
    long v;

    if (p->samples_line)
        return scene_fail(p, "duplicate 'samples' line (first on line %d)", p->samples_line);
    if (p->ntok < 2 || p->ntok > 3)
        return scene_fail(p, "'samples' needs 1 integer and optionally 'adaptive', got %d values", p->ntok - 1);
    if (scene_parse_count(p, "samples", 1, SCENE_MAX_SAMPLES, &v) != 0)
        return -1;
    if (p->ntok == 3) {
        if (!scene_tok_is(p->tok[2], "adaptive")) {
            scene_quote_t q = scene_quote(p->tok[2]);
            return scene_fail(p, "unexpected '%s' after samples (only 'adaptive' may follow the number)", q.s);
        }
        if (v < 2)
            return scene_fail(p, "'samples %ld adaptive': adaptive needs samples 2 or more", v);
        p->out->adaptive = 1;
    }
    p->out->samples = (int)v;
    p->samples_line = p->out->samples_line = p->line;
    return 0;
}

/* 'background R G B' and 'ambient R G B': one colour, at most once. */
static int scene_parse_colour_line(scene_parser_t *p, const char *what, int *seen_line, double *out)
{
    double c[3];
    int k;

    if (*seen_line)
        return scene_fail(p, "duplicate '%s' line (first on line %d)", what, *seen_line);
    if (p->ntok != 4)
        return scene_fail(p, "'%s' needs 3 numbers, got %d", what, p->ntok - 1);
    for (k = 0; k < 3; k++) {
        if (scene_number(p, what, p->tok[k + 1], &c[k]) != 0)
            return -1;
        if (scene_check_value(p, what, SCENE_F_COLOR, p->tok[k + 1], c[k]) != 0)
            return -1;
    }
    memcpy(out, c, sizeof c);
    *seen_line = p->line;
    return 0;
}

/* Split [s, s+n) (comment already removed) at spaces and tabs. */
static int scene_tokenize(scene_parser_t *p, const char *s, size_t n)
{
    size_t i = 0;

    p->ntok = 0;
    while (i < n) {
        size_t start;
        while (i < n && (s[i] == ' ' || s[i] == '\t'))
            i++;
        if (i == n)
            break;
        start = i;
        while (i < n && s[i] != ' ' && s[i] != '\t')
            i++;
        /* Unreachable with lines <= SCENE_MAX_LINE bytes. */
        if (p->ntok == SCENE_MAX_TOKENS)
            return scene_fail(p, "too many words on one line");
        p->tok[p->ntok].s = s + start;
        p->tok[p->ntok].n = i - start;
        p->ntok++;
    }
    return 0;
}

/* Reject bytes that cannot belong to a scene file before looking at
 * words, so a binary file gets one clear message instead of a confusing
 * syntax error. UTF-8 is allowed in comments only, where it is harmless. */
static int scene_check_bytes(scene_parser_t *p, const char *s, size_t n)
{
    int in_comment = 0;
    size_t i;

    for (i = 0; i < n; i++) {
        unsigned char c = (unsigned char)s[i];
        if (c == '#') {
            in_comment = 1;
        } else if (c == '\r') {
            /* CRLF is fine; a lone CR (old Mac line ending) would otherwise
             * glue lines together into one puzzling line. */
            if (i + 1 != n)
                return scene_fail(p, "carriage return inside a line at column %zu "
                                     "(only LF or CRLF line endings are accepted)", i + 1);
        } else if ((c < 0x20 && c != '\t') || c == 0x7f) {
            return scene_fail(p, "binary data (byte 0x%02x) at column %zu", c, i + 1);
        } else if (c >= 0x80 && !in_comment) {
            return scene_fail(p, "non-ASCII byte 0x%02x at column %zu (only comments may contain it)",
                              c, i + 1);
        }
    }
    return 0;
}

static int scene_parse_line(scene_parser_t *p, const char *s, size_t n)
{
    const char *hash;
    scene_tok_t kw;

    if (scene_check_bytes(p, s, n) != 0)
        return -1;
    if (n > 0 && s[n - 1] == '\r')
        n--;
    if (n > SCENE_MAX_LINE)
        return scene_fail(p, "line longer than %d bytes (%zu bytes)", SCENE_MAX_LINE, n);
    hash = memchr(s, '#', n);
    if (hash != NULL)
        n = (size_t)(hash - s);
    if (scene_tokenize(p, s, n) != 0)
        return -1;
    if (p->ntok == 0)
        return 0;
    kw = p->tok[0];
    if (scene_tok_is(kw, "node"))
        return scene_parse_node(p);
    if (scene_tok_is(kw, "end"))
        return scene_parse_end(p);
    if (scene_tok_is(kw, "mesh"))
        return scene_parse_mesh(p);
    if (p->node_depth > 0) {
        static const char *const global[] = {"image", "background", "ambient", "light", "depth", "samples", "camera"};
        for (size_t k = 0; k < sizeof global / sizeof global[0]; k++)
            if (scene_tok_is(kw, global[k]))
                return scene_fail(p, "'%s' is not allowed inside a node (node on line %d): image, background, "
                                     "ambient, camera, lights, depth and samples belong to the whole scene",
                                  global[k], p->node_line[p->node_depth]);
    }
    if (scene_tok_is(kw, "image"))
        return scene_parse_image(p);
    if (scene_tok_is(kw, "background"))
        return scene_parse_colour_line(p, "background", &p->background_line, p->out->background);
    if (scene_tok_is(kw, "ambient")) {
        if (scene_parse_colour_line(p, "ambient", &p->ambient_line, p->out->ambient) != 0)
            return -1;
        p->out->ambient_line = p->ambient_line;
        return 0;
    }
    if (scene_tok_is(kw, "light"))
        return scene_parse_light(p);
    if (scene_tok_is(kw, "depth"))
        return scene_parse_depth(p);
    if (scene_tok_is(kw, "samples"))
        return scene_parse_samples(p);
    if (scene_tok_is(kw, "camera"))
        return scene_parse_camera(p);
    for (int k = 0; k < SCENE_KINDS; k++)
        if (scene_kind_word[k] && scene_tok_is(kw, scene_kind_shape[k].label))
            return scene_parse_object(p, (scene_kind_t)k, &scene_kind_shape[k]);
    {
        /* "..., samples, plane, sphere, triangle or box": the kinds' words. */
        char kinds[256] = "";
        int nw = 0, iw = 0;
        for (int k = 0; k < SCENE_KINDS; k++)
            nw += scene_kind_word[k];
        for (int k = 0; k < SCENE_KINDS; k++) {
            if (!scene_kind_word[k])
                continue;
            strcat(kinds, iw == 0 ? "" : iw == nw - 1 ? " or " : ", ");
            strcat(kinds, scene_kind_shape[k].label);
            iw++;
        }
        scene_quote_t q = scene_quote(kw);
        return scene_fail(p, "unknown keyword '%s' (expected image, background, ambient, camera, "
                             "light, depth, samples, node, end, mesh, %s)", q.s, kinds);
    }
}

int scene_parse(const char *name, const char *text, size_t len, scene_t *out, char *err,
                size_t errlen)
{
    scene_parser_t p;
    size_t pos = 0;

    memset(&p, 0, sizeof p);
    xform_identity(&p.node_xf[0]);
    p.name = name != NULL ? name : "<scene>";
    p.err = err;
    p.errlen = errlen;
    p.out = out;
    if (err != NULL && errlen > 0)
        err[0] = '\0';
    if (out == NULL) {
        p.line = 0;
        return scene_fail(&p, "no output scene given");
    }
    if (text == NULL)
        len = 0;

    memset(out, 0, sizeof *out);
    out->width = SCENE_DEFAULT_WIDTH;
    out->height = SCENE_DEFAULT_HEIGHT;
    out->depth = SCENE_DEFAULT_DEPTH;
    out->samples = 1;

    /* A UTF-8 byte-order mark (EF BB BF), which some editors put at the
     * start of a file, is skipped there only; anywhere else its bytes are
     * non-ASCII like any other. Columns on line 1 count from after it. */
    if (text != NULL && len >= 3 && memcmp(text, "\xef\xbb\xbf", 3) == 0)
        pos = 3;

    while (pos < len) {
        const char *s = text + pos;
        const char *nl = memchr(s, '\n', len - pos);
        size_t n = nl != NULL ? (size_t)(nl - s) : len - pos;

        /* Lines are counted in an int; 1 MiB files have far fewer lines
         * than INT_MAX, and direct callers with bigger texts simply stop
         * being counted accurately rather than overflowing. */
        if (p.line < 2147483647)
            p.line++;
        pos += n + (nl != NULL ? 1 : 0);
        if (scene_parse_line(&p, s, n) != 0)
            return -1;
    }

    if (p.node_depth > 0) {
        p.line = p.node_line[p.node_depth];
        return scene_fail(&p, "'node' without 'end'");
    }
    if (!p.camera_line) {
        /* Whole-file problem: reported at the last line, where the reader
         * would have added the missing statement. */
        if (p.line == 0) {
            p.line = 1;
            return scene_fail(&p, "no camera in scene (the file is empty)");
        }
        return scene_fail(&p, "no camera in scene");
    }
    return 0;
}

int scene_load(const char *path, scene_t *out, char *err, size_t errlen)
{
    FILE *f;
    char *buf;
    size_t len;
    int rc;

    if (err != NULL && errlen > 0)
        err[0] = '\0';
    f = fopen(path, "rb");
    if (f == NULL) {
        int e = errno;
        errf_set(err, errlen, "%s: cannot open: %s", path, strerror(e));
        return -1;
    }
    /* One byte more than allowed, so "exactly 1 MiB" and "larger" differ. */
    buf = malloc((size_t)SCENE_MAX_FILE_BYTES + 1);
    if (buf == NULL) {
        fclose(f);
        errf_set(err, errlen, "%s: out of memory", path);
        return -1;
    }
    len = fread(buf, 1, (size_t)SCENE_MAX_FILE_BYTES + 1, f);
    if (ferror(f)) {
        int e = errno;
        fclose(f);
        free(buf);
        errf_set(err, errlen, "%s: cannot read: %s", path, strerror(e));
        return -1;
    }
    fclose(f);
    if (len > (size_t)SCENE_MAX_FILE_BYTES) {
        free(buf);
        errf_set(err, errlen, "%s: file too large (over 1 MiB)", path);
        return -1;
    }
    rc = scene_parse(path, buf, len, out, err, errlen);
    free(buf);
    return rc;
}
