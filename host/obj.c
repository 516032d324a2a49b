/* obj: Wavefront OBJ meshes (see obj.h). */
#include "obj.h"

#include "decimal.h"
#include "errf.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

typedef struct {
    const char *s;
    size_t n;
} obj_tok_t;

typedef struct {
    const char *path;
    int line;
    char *err;
    size_t errlen;
} obj_ctx_t;

#define OBJ_MAX_FACE 4096 /* references on one 'f' line */

static int obj_fail(obj_ctx_t *c, const char *fmt, ...) ERRF_PRINTF(2, 3);
static int obj_fail(obj_ctx_t *c, const char *fmt, ...)
{
    char msg[256];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (c->line > 0)
        errf_set(c->err, c->errlen, "%s:%d: %s", c->path, c->line, msg);
    else
        errf_set(c->err, c->errlen, "%s: %s", c->path, msg);
    return -1;
}

/* A token, quoted in messages: at most 40 bytes of it, printable. */
static const char *obj_quote(obj_tok_t t, char buf[48])
{
    size_t n = t.n < 40 ? t.n : 40, k = 0;
    for (size_t i = 0; i < n; i++)
        buf[k++] = t.s[i] >= 32 && t.s[i] < 127 ? t.s[i] : '?';
    if (t.n > n) {
        buf[k++] = '.';
        buf[k++] = '.';
        buf[k++] = '.';
    }
    buf[k] = '\0';
    return buf;
}

/* Grow list `which` (0 v, 1 vt, 2 vn, 3 triangles) to hold one more. */
static int obj_grow(obj_ctx_t *c, obj_t *o, int which, void **p, size_t have, size_t size, const char *what)
{
    if (have < o->n_cap[which])
        return 0;
    if (have >= OBJ_MAX_ELEMENTS)
        return obj_fail(c, "more than %zu %s", OBJ_MAX_ELEMENTS, what);
    size_t cap = o->n_cap[which] ? 2 * o->n_cap[which] : 256;
    void *q = realloc(*p, cap * size);
    if (q == NULL)
        return obj_fail(c, "out of memory at %zu %s", have, what);
    *p = q;
    o->n_cap[which] = cap;
    return 0;
}

static int obj_number(obj_ctx_t *c, obj_tok_t t, const char *what, double *v)
{
    char q[48], buf[64];
    if (!decimal_is_plain(t.s, t.n)) {
        const char *why = decimal_why_not(t.s, t.n);
        if (why)
            return obj_fail(c, "%s: %s: '%s'", what, why, obj_quote(t, q));
        return obj_fail(c, "%s: '%s' is not a number", what, obj_quote(t, q));
    }
    if (t.n >= sizeof buf)
        return obj_fail(c, "%s: '%s' is too long for a number", what, obj_quote(t, q));
    memcpy(buf, t.s, t.n);
    buf[t.n] = '\0';
    errno = 0;
    char *end;
    double d = strtod(buf, &end);
    if (end != buf + t.n)
        return obj_fail(c, "%s: '%s' is not a number (check the C locale)", what, obj_quote(t, q));
    if (!isfinite(d))
        return obj_fail(c, "%s: '%s' is beyond the range of a double", what, obj_quote(t, q));
    *v = d == 0.0 ? 0.0 : d; /* no -0 */
    return 0;
}

/* The whitespace-separated tokens of one line (comment stripped). */
static size_t obj_split(const char *s, size_t n, obj_tok_t *tok, size_t max)
{
    size_t k = 0, i = 0;
    while (i < n) {
        while (i < n && (s[i] == ' ' || s[i] == '\t' || s[i] == '\v' || s[i] == '\f'))
            i++;
        if (i == n)
            break;
        size_t b = i;
        while (i < n && !(s[i] == ' ' || s[i] == '\t' || s[i] == '\v' || s[i] == '\f'))
            i++;
        if (k < max)
            tok[k] = (obj_tok_t){s + b, i - b};
        k++;
    }
    return k;
}

/* A vector line: v, vt or vn, with `min`..`max` numbers of which the first
 * up to 3 are kept. */
static int obj_vector(obj_ctx_t *c, const obj_tok_t *tok, size_t nt, size_t min, size_t max, const char *usage,
                      obj_vec_t *out)
{
    if (nt - 1 < min || nt - 1 > max)
        return obj_fail(c, "'%.*s' needs %s; got %zu number%s", (int)tok[0].n, tok[0].s, usage, nt - 1,
                        nt == 2 ? "" : "s");
    double x[3] = {0, 0, 0};
    for (size_t i = 1; i < nt; i++) {
        double d = 0;
        if (obj_number(c, tok[i], usage, &d))
            return -1;
        if (i <= 3)
            x[i - 1] = d;
    }
    *out = (obj_vec_t){x[0], x[1], x[2]};
    return 0;
}

/* One index of a face reference: 0-based, or a failure. Positive indices
 * may name elements read later (checked at the end); negative ones count
 * back from the `have` read so far. */
static int obj_index(obj_ctx_t *c, obj_tok_t ref, const char *s, size_t n, size_t have, const char *what,
                     int32_t *out)
{
    char q[48];
    size_t i = 0;
    int neg = 0;
    if (i < n && (s[i] == '-' || s[i] == '+'))
        neg = s[i++] == '-';
    if (i == n)
        return obj_fail(c, "f: %s index missing in '%s'", what, obj_quote(ref, q));
    long long v = 0;
    for (; i < n; i++) {
        if (s[i] < '0' || s[i] > '9')
            return obj_fail(c, "f: '%s' is not a vertex reference (v, v/vt, v//vn or v/vt/vn, whole numbers)",
                            obj_quote(ref, q));
        v = v * 10 + (s[i] - '0');
        if (v > (long long)OBJ_MAX_ELEMENTS)
            return obj_fail(c, "f: %s index in '%s' is beyond %zu", what, obj_quote(ref, q), OBJ_MAX_ELEMENTS);
    }
    if (v == 0)
        return obj_fail(c, "f: %s index 0 in '%s' (OBJ indices start at 1; negative ones count back from the last)",
                        what, obj_quote(ref, q));
    if (neg) {
        if ((size_t)v > have)
            return obj_fail(c, "f: %s index -%lld in '%s' reaches before the first (%zu read so far)", what, v,
                            obj_quote(ref, q), have);
        *out = (int32_t)(have - (size_t)v);
    } else {
        *out = (int32_t)(v - 1);
    }
    return 0;
}

/* A face reference v, v/vt, v//vn or v/vt/vn. */
static int obj_ref(obj_ctx_t *c, const obj_t *o, obj_tok_t t, int32_t *v, int32_t *vt, int32_t *vn)
{
    char q[48];
    const char *s1 = memchr(t.s, '/', t.n);
    size_t n1 = s1 ? (size_t)(s1 - t.s) : t.n;
    *vt = *vn = -1;
    if (obj_index(c, t, t.s, n1, o->nv, "vertex", v))
        return -1;
    if (!s1)
        return 0;
    const char *r = s1 + 1, *e = t.s + t.n;
    const char *s2 = memchr(r, '/', (size_t)(e - r));
    size_t n2 = s2 ? (size_t)(s2 - r) : (size_t)(e - r);
    if (n2 > 0 && obj_index(c, t, r, n2, o->nvt, "texture coordinate", vt))
        return -1;
    if (!s2) {
        if (n2 == 0)
            return obj_fail(c, "f: '%s' ends in '/' (v, v/vt, v//vn or v/vt/vn)", obj_quote(t, q));
        return 0;
    }
    const char *r3 = s2 + 1;
    if (memchr(r3, '/', (size_t)(e - r3)))
        return obj_fail(c, "f: '%s' has more than two '/' (v, v/vt, v//vn or v/vt/vn)", obj_quote(t, q));
    if (r3 == e)
        return obj_fail(c, "f: '%s' ends in '/' (v, v/vt, v//vn or v/vt/vn)", obj_quote(t, q));
    return obj_index(c, t, r3, (size_t)(e - r3), o->nvn, "normal", vn);
}

static int obj_face(obj_ctx_t *c, obj_t *o, const obj_tok_t *tok, size_t nt)
{
    int32_t v[OBJ_MAX_FACE], vt[OBJ_MAX_FACE], vn[OBJ_MAX_FACE];
    size_t k = nt - 1;
    if (k < 3)
        return obj_fail(c, "f: a face needs at least 3 vertices; got %zu", k);
    if (k > OBJ_MAX_FACE)
        return obj_fail(c, "f: a face of %zu vertices (at most %d)", k, OBJ_MAX_FACE);
    for (size_t i = 0; i < k; i++)
        if (obj_ref(c, o, tok[i + 1], &v[i], &vt[i], &vn[i]))
            return -1;
    /* A fan from the first vertex: (1, 2, 3), (1, 3, 4), ... */
    for (size_t i = 1; i + 1 < k; i++) {
        if (obj_grow(c, o, 3, (void **)&o->tri, o->ntri, sizeof *o->tri, "triangles"))
            return -1;
        obj_tri_t *t = &o->tri[o->ntri++];
        const size_t at[3] = {0, i, i + 1};
        for (int j = 0; j < 3; j++) {
            t->v[j] = v[at[j]];
            t->vt[j] = vt[at[j]];
            t->vn[j] = vn[at[j]];
        }
        t->line = c->line;
    }
    o->nfaces++;
    return 0;
}

static int obj_is(obj_tok_t t, const char *w)
{
    size_t n = strlen(w);
    return t.n == n && memcmp(t.s, w, n) == 0;
}

/* One line (without its end and comment). */
static int obj_line(obj_ctx_t *c, obj_t *o, const char *s, size_t n)
{
    obj_tok_t tok[OBJ_MAX_FACE + 2];
    size_t nt = obj_split(s, n, tok, sizeof tok / sizeof tok[0]);
    if (nt == 0)
        return 0;
    if (nt > sizeof tok / sizeof tok[0])
        return obj_fail(c, "%zu words on one line (at most %zu)", nt, sizeof tok / sizeof tok[0]);
    obj_tok_t k = tok[0];
    obj_vec_t x;
    if (obj_is(k, "v")) {
        if (obj_vector(c, tok, nt, 3, 6, "x y z (an optional w, or r g b)", &x) ||
            (nt - 1 == 5 && obj_fail(c, "'v' needs x y z, x y z w or x y z r g b; got 5 numbers")) ||
            obj_grow(c, o, 0, (void **)&o->v, o->nv, sizeof *o->v, "vertices"))
            return -1;
        o->v[o->nv++] = x;
    } else if (obj_is(k, "vt")) {
        if (obj_vector(c, tok, nt, 1, 3, "u [v [w]]", &x) ||
            obj_grow(c, o, 1, (void **)&o->vt, o->nvt, sizeof *o->vt, "texture coordinates"))
            return -1;
        o->vt[o->nvt++] = x;
    } else if (obj_is(k, "vn")) {
        if (obj_vector(c, tok, nt, 3, 3, "x y z", &x) ||
            obj_grow(c, o, 2, (void **)&o->vn, o->nvn, sizeof *o->vn, "normals"))
            return -1;
        o->vn[o->nvn++] = x;
    } else if (obj_is(k, "f")) {
        return obj_face(c, o, tok, nt);
    } else if (!(obj_is(k, "o") || obj_is(k, "g") || obj_is(k, "s") || obj_is(k, "usemtl") || obj_is(k, "mtllib"))) {
        char q[48];
        return obj_fail(c, "unknown statement '%s' (read: v, vt, vn, f; ignored: o, g, s, usemtl, mtllib)",
                        obj_quote(k, q));
    }
    return 0;
}

void obj_free(obj_t *o)
{
    free(o->v);
    free(o->vt);
    free(o->vn);
    free(o->tri);
    memset(o, 0, sizeof *o);
}

static int obj_parse_lists(const char *path, const char *buf, size_t len, obj_t *o, char *err, size_t errlen)
{
    obj_ctx_t c = {path, 0, err, errlen};
    if (len == 0)
        return obj_fail(&c, "empty file");
    size_t i = 0;
    while (i < len) {
        c.line++;
        size_t b = i;
        while (i < len && buf[i] != '\n')
            i++;
        size_t e = i;
        if (i < len)
            i++; /* the '\n' */
        const char *hash = memchr(buf + b, '#', e - b);
        if (hash)
            e = (size_t)(hash - buf);
        else if (e > b && buf[e - 1] == '\r')
            e--;
        if (memchr(buf + b, '\0', e - b))
            return obj_fail(&c, "a NUL byte: not a text file");
        if (obj_line(&c, o, buf + b, e - b))
            return -1;
    }
    c.line = 0;
    if (o->ntri == 0)
        return obj_fail(&c, "no faces ('f' lines): nothing to render");
    /* Positive indices against the whole file's lists. */
    for (size_t t = 0; t < o->ntri; t++) {
        const obj_tri_t *r = &o->tri[t];
        c.line = r->line;
        for (int j = 0; j < 3; j++) {
            if ((size_t)r->v[j] >= o->nv)
                return obj_fail(&c, "f: vertex %ld of a file with %zu vertices", (long)r->v[j] + 1, o->nv);
            if (r->vt[j] >= 0 && (size_t)r->vt[j] >= o->nvt)
                return obj_fail(&c, "f: texture coordinate %ld of a file with %zu", (long)r->vt[j] + 1, o->nvt);
            if (r->vn[j] >= 0 && (size_t)r->vn[j] >= o->nvn)
                return obj_fail(&c, "f: normal %ld of a file with %zu normals", (long)r->vn[j] + 1, o->nvn);
        }
    }
    return 0;
}

int obj_parse(const char *path, const char *buf, size_t len, obj_t *o, char *err, size_t errlen)
{
    memset(o, 0, sizeof *o);
    if (err && errlen)
        err[0] = '\0';
    if (obj_parse_lists(path, buf, len, o, err, errlen) == 0)
        return 0;
    obj_free(o); /* a refused file leaves nothing */
    return -1;
}

int obj_read(const char *path, char **buf_out, size_t *len_out, char *err, size_t errlen)
{
    obj_ctx_t c = {path, 0, err, errlen};
    *buf_out = NULL;
    *len_out = 0;
    FILE *f = fopen(path, "rb");
    if (f == NULL)
        return obj_fail(&c, "cannot open: %s", strerror(errno));
    /* A device or pipe ("/dev/zero", "/dev/stdin") could block or never
     * end: only regular files are read. */
    struct stat st;
    if (fstat(fileno(f), &st) != 0 || !S_ISREG(st.st_mode)) {
        fclose(f);
        return obj_fail(&c, "not a regular file");
    }
    /* The buffer is the file's size (plus the terminating byte the parser
     * may look at), not the limit: a model of a few KB does not reserve
     * 64 MiB (under AddressSanitizer that reservation cost a page fault
     * per 4 KB on every load). One byte more is read than the file had
     * when it was measured, so a file that grows meanwhile is refused,
     * not cut short. */
    if (st.st_size < 0 || (uintmax_t)st.st_size > OBJ_MAX_FILE_BYTES) {
        fclose(f);
        return obj_fail(&c, "file too large (over %zu MiB)", OBJ_MAX_FILE_BYTES >> 20);
    }
    size_t size = (size_t)st.st_size;
    char *buf = malloc(size + 1);
    if (buf == NULL) {
        fclose(f);
        return obj_fail(&c, "out of memory");
    }
    size_t len = fread(buf, 1, size + 1, f);
    int rd = ferror(f);
    fclose(f);
    if (rd || len > size) {
        free(buf);
        return rd ? obj_fail(&c, "cannot read") : obj_fail(&c, "the file changed while it was read");
    }
    *buf_out = buf;
    *len_out = len;
    return 0;
}

int obj_load(const char *path, obj_t *o, char *err, size_t errlen)
{
    char *buf;
    size_t len;
    memset(o, 0, sizeof *o);
    if (obj_read(path, &buf, &len, err, errlen) != 0)
        return -1;
    int rc = obj_parse(path, buf, len, o, err, errlen);
    free(buf);
    return rc;
}

static obj_vec_t obj_sub(obj_vec_t a, obj_vec_t b)
{
    return (obj_vec_t){a.x - b.x, a.y - b.y, a.z - b.z};
}

obj_vec_t obj_face_normal(const obj_t *o, size_t i)
{
    const obj_tri_t *t = &o->tri[i];
    obj_vec_t a = o->v[t->v[0]], u = obj_sub(o->v[t->v[1]], a), w = obj_sub(o->v[t->v[2]], a);
    return (obj_vec_t){u.y * w.z - u.z * w.y, u.z * w.x - u.x * w.z, u.x * w.y - u.y * w.x};
}

static obj_vec_t obj_unit(obj_vec_t v)
{
    double l = sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    return l > 0 ? (obj_vec_t){v.x / l, v.y / l, v.z / l} : (obj_vec_t){0, 0, 0};
}

int obj_smooth_normals(const obj_t *o, obj_vec_t *n, size_t *from_file_out)
{
    obj_vec_t *sum = calloc(o->nv ? o->nv : 1, sizeof *sum);
    size_t from_file = 0;
    if (sum == NULL)
        return -1;
    for (size_t i = 0; i < o->ntri; i++) {
        obj_vec_t f = obj_face_normal(o, i);
        for (int k = 0; k < 3; k++) {
            obj_vec_t *s = &sum[o->tri[i].v[k]];
            *s = (obj_vec_t){s->x + f.x, s->y + f.y, s->z + f.z};
        }
    }
    for (size_t i = 0; i < o->ntri; i++)
        for (int k = 0; k < 3; k++) {
            const obj_tri_t *t = &o->tri[i];
            obj_vec_t *out = &n[3 * i + k];
            if (t->vn[k] >= 0) {
                *out = o->vn[t->vn[k]];
                from_file++;
                continue;
            }
            *out = obj_unit(sum[t->v[k]]);
            if (out->x == 0 && out->y == 0 && out->z == 0)
                *out = obj_unit(obj_face_normal(o, i));
        }
    free(sum);
    if (from_file_out)
        *from_file_out = from_file;
    return 0;
}
