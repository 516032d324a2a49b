/* test_obj: the OBJ reader (host/obj.c) and its smooth-shading normals.
 *
 * - Generated files: vertices of every magnitude (1e-6 .. 1e4, written
 *   in fixed and exponent notation), faces of 3..9 vertices in all four
 *   reference forms, positive (also forward) and negative indices,
 *   comments, CRLF, tabs, blank lines and the ignored statements. The
 *   expected triangles are this test's own fans of the faces it wrote.
 * - Bad input: each case refused with "t.obj:LINE: " and its reason.
 * - The real models in ../shared/models (FXRT_MODELS overrides): counts.
 * - Normals against geometry, not against the reader's sums: the vertices
 *   of a regular octahedron point along their axis; every corner of a
 *   planar polygon, turned at random, takes the plane's normal; a file's
 *   vn is taken as written. */
#include <math.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "obj.h"

static uint64_t rng = 0x9E3779B97F4A7C15u;
static uint32_t draw(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (uint32_t)(rng >> 16);
}
static long pick(long n)
{
    return (long)(draw() % (uint32_t)n);
}
static double uni(double a, double b)
{
    return a + (b - a) * (draw() / 4294967296.0);
}

/* A growing text buffer. */
typedef struct {
    char *s;
    size_t n, cap;
} text_t;
static void put(text_t *t, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void put(text_t *t, const char *fmt, ...)
{
    va_list ap;
    if (t->cap == 0) {
        t->cap = 4096;
        if (!(t->s = malloc(t->cap)))
            abort();
    }
    for (;;) {
        va_start(ap, fmt);
        int k = vsnprintf(t->s + t->n, t->cap - t->n, fmt, ap);
        va_end(ap);
        if (k >= 0 && (size_t)k < t->cap - t->n) {
            t->n += (size_t)k;
            return;
        }
        t->cap = 2 * t->cap + (size_t)k;
        t->s = realloc(t->s, t->cap);
        if (!t->s)
            abort();
    }
}

/* A value of any magnitude, written so that strtod gives it back. */
static double any_value(void)
{
    double m = uni(1, 10) * pow(10, (double)pick(11) - 6);
    return pick(2) ? -m : m;
}
static void put_value(text_t *t, double x)
{
    put(t, pick(2) ? " %.17g" : " %.17e", x);
}
static const char *space(void)
{
    static const char *const s[] = {" ", "  ", "\t", " \t "};
    return s[pick(4)];
}
static const char *eol(void)
{
    return pick(3) ? "\n" : "\r\n";
}

#define GEN_MAX 600

typedef struct {
    int v, vt, vn; /* 0-based, -1 none */
} ref_t;

static void test_generated(void)
{
    static obj_vec_t v[GEN_MAX], vt[GEN_MAX], vn[GEN_MAX];
    static ref_t face[GEN_MAX][9];
    static int fk[GEN_MAX], fline[GEN_MAX];
    long tris_checked = 0;
    for (int trial = 0; trial < 200; trial++) {
        text_t t = {0};
        int nv = 3 + (int)pick(60), nvt = (int)pick(20), nvn = (int)pick(20), nf = 0;
        /* The lists first, written in a random interleaving with the faces:
         * element i of each list is line-ordered; faces refer back with
         * negative indices only to what was already written. */
        int wv = 0, wvt = 0, wvn = 0, line = 0;
        int form_of_file = (int)pick(5); /* 0..3 one form, 4 mixed per face */
        while (wv < nv || wvt < nvt || wvn < nvn || nf < 40) {
            int what = (int)pick(8);
            line++;
            if (what == 0 && wv < nv) {
                v[wv] = (obj_vec_t){any_value(), any_value(), any_value()};
                put(&t, "v");
                put_value(&t, v[wv].x);
                put_value(&t, v[wv].y);
                put_value(&t, v[wv].z);
                if (pick(4) == 0)
                    put(&t, " 1.0"); /* w */
                put(&t, "%s", eol());
                wv++;
            } else if (what == 1 && wvt < nvt) {
                vt[wvt] = (obj_vec_t){uni(0, 1), uni(0, 1), 0};
                put(&t, "vt %.17g %.17g%s", vt[wvt].x, vt[wvt].y, eol());
                wvt++;
            } else if (what == 2 && wvn < nvn) {
                vn[wvn] = (obj_vec_t){any_value(), any_value(), any_value()};
                put(&t, "vn %.17g %.17g %.17g%s", vn[wvn].x, vn[wvn].y, vn[wvn].z, eol());
                wvn++;
            } else if (what == 3) {
                static const char *const ign[] = {"o body", "g a b", "s 1", "s off", "usemtl red", "mtllib m.mtl",
                                                  "# a comment", "", "   "};
                put(&t, "%s%s", ign[pick(9)], eol());
            } else if (what >= 4 && wv >= 1 && nf < GEN_MAX - 1) {
                int k = 3 + (int)pick(7), form = form_of_file < 4 ? form_of_file : (int)pick(4);
                if ((form & 1) && nvt == 0)
                    form &= ~1;
                if ((form & 2) && nvn == 0)
                    form &= ~2;
                put(&t, "f");
                for (int j = 0; j < k; j++) {
                    ref_t r = {-1, -1, -1};
                    int sign_v = pick(3) == 0 && wv > 0;
                    r.v = sign_v ? wv - 1 - (int)pick(wv) : (int)pick(nv);
                    put(&t, "%s%d", space(), sign_v ? r.v - wv : r.v + 1);
                    if (form & 1) {
                        int s = pick(3) == 0 && wvt > 0;
                        r.vt = s ? wvt - 1 - (int)pick(wvt) : (int)pick(nvt);
                        put(&t, "/%d", s ? r.vt - wvt : r.vt + 1);
                    } else if (form & 2) {
                        put(&t, "/");
                    }
                    if (form & 2) {
                        int s = pick(3) == 0 && wvn > 0;
                        r.vn = s ? wvn - 1 - (int)pick(wvn) : (int)pick(nvn);
                        put(&t, "/%d", s ? r.vn - wvn : r.vn + 1);
                    }
                    face[nf][j] = r;
                }
                if (pick(4) == 0)
                    put(&t, " # trailing comment");
                put(&t, "%s", eol());
                fk[nf] = k;
                fline[nf] = line;
                nf++;
            } else {
                put(&t, "%s", eol()); /* a blank line */
            }
        }
        obj_t o;
        char err[256];
        int rc = obj_parse("gen.obj", t.s, t.n, &o, err, sizeof err);
        CHECK_MSG(rc == 0, "trial %d: %s", trial, err);
        if (rc == 0) {
            CHECK(o.nv == (size_t)nv && o.nvt == (size_t)nvt && o.nvn == (size_t)nvn && o.nfaces == (size_t)nf);
            size_t want = 0;
            for (int f = 0; f < nf; f++)
                want += (size_t)fk[f] - 2;
            CHECK_MSG(o.ntri == want, "trial %d: %zu triangles, want %zu", trial, o.ntri, want);
            for (int i = 0; i < nv && i < (int)o.nv; i++)
                CHECK_SWEEP(o.v[i].x == v[i].x && o.v[i].y == v[i].y && o.v[i].z == v[i].z, "trial %d v %d", trial, i);
            for (int i = 0; i < nvn && i < (int)o.nvn; i++)
                CHECK_SWEEP(o.vn[i].x == vn[i].x && o.vn[i].z == vn[i].z, "trial %d vn %d", trial, i);
            size_t ti = 0;
            for (int f = 0; f < nf && o.ntri == want; f++)
                for (int j = 1; j + 1 < fk[f]; j++, ti++) {
                    const ref_t *c[3] = {&face[f][0], &face[f][j], &face[f][j + 1]};
                    const obj_tri_t *tr = &o.tri[ti];
                    bool same = tr->line == fline[f];
                    for (int q = 0; q < 3; q++)
                        same = same && tr->v[q] == c[q]->v && tr->vt[q] == c[q]->vt && tr->vn[q] == c[q]->vn;
                    CHECK_SWEEP(same, "trial %d face %d (line %d) triangle %d", trial, f, fline[f], j);
                    tris_checked++;
                }
        }
        obj_free(&o);
        free(t.s);
    }
    CHECK_MSG(tris_checked > 20000, "%ld triangles checked", tris_checked);
    printf("generated: 200 files, %ld triangles checked\n", tris_checked);
}

/* Mutants of valid files (bytes flipped, inserted, deleted, cut): each
 * must either read, with every index inside its list, or be refused with
 * "mut.obj:LINE: " or "mut.obj: " and nothing kept. Run under ASan and
 * UBSan by the sanitizer suite. */
static void test_mutants(void)
{
    static const char *const base[] = {
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1 4/1/1\nf -1 -2 -3\n",
        "# c\r\no x\r\nv 1e-3 2.5 -7\r\nv 4 5 6 1\r\nv 7 8 9\r\ns 1\r\nf 1//1 2//1 3//1\r\nvn 1 0 0\r\n",
        "v -1 -1 -1\nv 1 -1 -1\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 2 3 4\nf 3 1 4\ng g\nusemtl m\n",
    };
    char buf[512], err[256];
    long read = 0, refused_n = 0;
    for (int i = 0; i < 30000; i++) {
        const char *b = base[pick(3)];
        size_t n = strlen(b);
        memcpy(buf, b, n);
        for (int m = 1 + (int)pick(4); m > 0; m--) {
            size_t at = (size_t)pick((long)n + 1);
            static const char pool[] = "0123456789-+./ \t\r\n#vfnte\0x";
            char c = pick(4) ? pool[pick(sizeof pool - 1)] : (char)pick(256);
            switch (pick(4)) {
            case 0: if (at < n) buf[at] = c; break;
            case 1: if (n < sizeof buf - 1) { memmove(buf + at + 1, buf + at, n - at); buf[at] = c; n++; } break;
            case 2: if (at < n) { memmove(buf + at, buf + at + 1, n - at - 1); n--; } break;
            default: n = at; break;
            }
        }
        obj_t o;
        int rc = obj_parse("mut.obj", buf, n, &o, err, sizeof err);
        if (rc == 0) {
            bool ok = o.ntri > 0;
            for (size_t t = 0; t < o.ntri && ok; t++)
                for (int k = 0; k < 3; k++)
                    ok = ok && o.tri[t].v[k] >= 0 && (size_t)o.tri[t].v[k] < o.nv &&
                         (o.tri[t].vt[k] < 0 || (size_t)o.tri[t].vt[k] < o.nvt) &&
                         (o.tri[t].vn[k] < 0 || (size_t)o.tri[t].vn[k] < o.nvn);
            CHECK_SWEEP(ok, "mutant %d read with an index out of range", i);
            read++;
        } else {
            int line = 0, used = 0;
            bool ok = sscanf(err, "mut.obj:%d: %n", &line, &used) == 1 ? used > 0 && line >= 1
                                                                       : strncmp(err, "mut.obj: ", 9) == 0;
            CHECK_SWEEP(rc == -1 && ok && o.ntri == 0 && o.v == NULL, "mutant %d: rc %d, '%s'", i, rc, err);
            refused_n++;
        }
        obj_free(&o);
    }
    CHECK_MSG(read > 1000 && refused_n > 1000, "%ld read, %ld refused", read, refused_n);
    printf("mutants: 30000, %ld read, %ld refused\n", read, refused_n);
}

/* Bad input: refused, at line `line` (0: "t.obj: " with no line). */
static void refused(const char *text, int line, const char *reason)
{
    obj_t o;
    char err[256], want[32];
    int rc = obj_parse("t.obj", text, strlen(text), &o, err, sizeof err);
    obj_free(&o);
    if (line > 0)
        snprintf(want, sizeof want, "t.obj:%d: ", line);
    else
        snprintf(want, sizeof want, "t.obj: ");
    CHECK_MSG(rc == -1 && strncmp(err, want, strlen(want)) == 0 && strstr(err, reason) != NULL,
              "'%s': got '%s', want '%s...%s'", text, err, want, reason);
}

static void test_bad(void)
{
    /* Each case: after three vertices (1) or alone (0), its text, the line
     * it must be refused at (0: no line), and the reason's words. */
    static const struct {
        int after_tri;
        const char *text;
        int line;
        const char *reason;
    } bad[] = {
        {0, "", 0, "empty file"},
        {0, "v 0 0 0\nv 1 0 0\n# no faces\n", 0, "no faces"},
        {1, "f 0 1 2\n", 4, "index 0"},
        {1, "f 1 2 4\n", 4, "vertex 4 of a file with 3 vertices"},
        {1, "f 1 2 -4\n", 4, "reaches before the first"},
        {1, "f 1 2\n", 4, "at least 3 vertices; got 2"},
        {1, "f\n", 4, "at least 3 vertices; got 0"},
        {1, "f 1 2 3/1\n", 4, "texture coordinate 1 of a file with 0"},
        {1, "f 1//1 2//1 3//1\n", 4, "normal 1 of a file with 0 normals"},
        {1, "f 1 2 3.5\n", 4, "is not a vertex reference"},
        {1, "f 1 2 3/\n", 4, "ends in '/'"},
        {1, "f 1 2 3//\n", 4, "ends in '/'"},
        {1, "f 1 2 3/1/1/1\n", 4, "more than two '/'"},
        {1, "f 1 2 99999999999\n", 4, "beyond"},
        {1, "f 1 2 /1\n", 4, "vertex index missing"},
        {0, "v 0 0 nan\n", 1, "NaN or infinity"},
        {0, "v 0 0 -inf\n", 1, "NaN or infinity"},
        {0, "v 0 0 0x10\n", 1, "hexadecimal"},
        {0, "v 0 0 1e999\n", 1, "beyond the range of a double"},
        {0, "v 0 0 abc\n", 1, "'abc' is not a number"},
        {0, "v 0 0\n", 1, "'v' needs x y z"},
        {0, "v 0 0 0 1 1\n", 1, "got 5 numbers"},
        {0, "v 0 0 0 1 1 1 1\n", 1, "got 7 numbers"},
        {0, "vn 0 0\n", 1, "'vn' needs x y z"},
        {0, "vt\n", 1, "'vt' needs u [v [w]]"},
        {0, "vt 0 0 0 0\n", 1, "got 4 numbers"},
        {1, "l 1 2\n", 4, "unknown statement 'l'"},
        {1, "F 1 2 3\n", 4, "unknown statement 'F'"},
        {0, "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\nf 1 2 x\r\n", 5, "is not a vertex reference"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char buf[512];
        snprintf(buf, sizeof buf, "%s%s", bad[i].after_tri ? "v 0 0 0\nv 1 0 0\nv 0 1 0\n" : "", bad[i].text);
        refused(buf, bad[i].line, bad[i].reason);
    }
    static const char nul[] = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\0003\n";
    obj_t o;
    char err[256];
    CHECK(obj_parse("t.obj", nul, sizeof nul - 1, &o, err, sizeof err) == -1 && strstr(err, "t.obj:4: ") &&
          strstr(err, "NUL"));
    obj_free(&o);
    /* Accepted: a vertex with w, with r g b; vt with 1..3 values; forward
     * references; a face of 4 is two triangles (1 2 3), (1 3 4). */
    const char *ok = "f 1 2 3 4\nv 0 0 0 1\nv 1 0 0 0.5 0.5 0.5\nv 1 1 0\nv 0 1 0\nvt 0.5\nvt 0.5 1 0\n";
    CHECK(obj_parse("t.obj", ok, strlen(ok), &o, err, sizeof err) == 0 && o.ntri == 2 && o.nvt == 2);
    CHECK(o.ntri == 2 && o.tri[0].v[0] == 0 && o.tri[0].v[1] == 1 && o.tri[0].v[2] == 2 && o.tri[1].v[0] == 0 &&
          o.tri[1].v[1] == 2 && o.tri[1].v[2] == 3 && o.tri[1].line == 1);
    obj_free(&o);
    /* Files: missing; over the size limit is stated in MiB. */
    CHECK(obj_load("/nonexistent/x.obj", &o, err, sizeof err) == -1 && strstr(err, "/nonexistent/x.obj: cannot open"));
    obj_free(&o);
    /* One byte over the limit (a sparse file: no disk used): refused by
     * its size, with the limit in MiB. */
    char big[] = "/tmp/fxrt-test-obj-XXXXXX";
    int fd = mkstemp(big);
    CHECK(fd >= 0 && ftruncate(fd, (off_t)OBJ_MAX_FILE_BYTES + 1) == 0);
    if (fd >= 0) {
        close(fd);
        CHECK(obj_load(big, &o, err, sizeof err) == -1 && strstr(err, "file too large (over 64 MiB)"));
        obj_free(&o);
        unlink(big);
    }
}

static const char *models(void)
{
    const char *m = getenv("FXRT_MODELS");
    return m && *m ? m : "../shared/models";
}

static void test_models(void)
{
    static const struct {
        const char *file;
        size_t tris, verts, normals;
        int err_line;
    } m[] = {
        {"spot_low_resolution.obj", 1654, 829, 1654, 0},
        {"spot.obj", 23062, 11533, 23062, 0},
        {"course-cube-v.obj", 12, 8, 0, 0},
        {"course-cube-v-vt.obj", 12, 8, 0, 0},
        {"course-cube-v-vn.obj", 12, 8, 6, 0},
        {"course-cube-v-vt-vn.obj", 12, 8, 6, 0},
        {"course-cube-v-vt-vn-comments.obj", 12, 8, 6, 0},
        {"course-cube-v-blocks-weird-indices.obj", 0, 0, 0, 12},
    };
    for (size_t i = 0; i < sizeof m / sizeof m[0]; i++) {
        char path[512], err[512];
        snprintf(path, sizeof path, "%s/%s", models(), m[i].file);
        obj_t o;
        int rc = obj_load(path, &o, err, sizeof err);
        if (m[i].err_line) {
            char want[600];
            snprintf(want, sizeof want, "%s:%d: f: vertex index 0", path, m[i].err_line);
            CHECK_MSG(rc == -1 && strncmp(err, want, strlen(want)) == 0, "%s: got '%s'", m[i].file, err);
        } else {
            CHECK_MSG(rc == 0 && o.ntri == m[i].tris && o.nv == m[i].verts && o.nvn == m[i].normals,
                      "%s: rc %d (%s), %zu triangles, %zu vertices, %zu normals", m[i].file, rc, err, o.ntri, o.nv,
                      o.nvn);
        }
        obj_free(&o);
    }
}

static double len3(obj_vec_t a)
{
    return sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
}

static void test_normals(void)
{
    /* The octahedron, faces counter-clockwise seen from outside. */
    const char *oct = "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n"
                      "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n";
    obj_t o;
    char err[256];
    CHECK(obj_parse("oct.obj", oct, strlen(oct), &o, err, sizeof err) == 0);
    obj_vec_t n[24];
    size_t from_file = 99;
    CHECK(o.ntri == 8 && obj_smooth_normals(&o, n, &from_file) == 0 && from_file == 0);
    for (size_t i = 0; i < 24; i++) {
        obj_vec_t p = o.v[o.tri[i / 3].v[i % 3]]; /* the vertex is its own axis direction */
        CHECK_MSG(fabs(n[i].x - p.x) < 1e-12 && fabs(n[i].y - p.y) < 1e-12 && fabs(n[i].z - p.z) < 1e-12,
                  "corner %zu: (%g %g %g)", i, n[i].x, n[i].y, n[i].z);
    }
    obj_free(&o);

    /* Planar convex polygons, counter-clockwise about +z, turned by a
     * random rotation: every corner takes the turned +z. */
    for (int trial = 0; trial < 300; trial++) {
        int k = 3 + (int)pick(12);
        double a = uni(0, 6.283185307179586), b = uni(-1.5, 1.5), s = pow(10, uni(-5, 4));
        /* Rotation: about z by a, then about x by b. */
        double ca = cos(a), sa = sin(a), cb = cos(b), sb = sin(b);
        obj_vec_t zn = {0, -sb, cb};
        text_t t = {0};
        double phase = uni(0, 1);
        for (int j = 0; j < k; j++) {
            double th = 6.283185307179586 * (j + phase) / k, x = s * cos(th), y = s * sin(th);
            double x1 = ca * x - sa * y, y1 = sa * x + ca * y; /* z = 0 */
            put(&t, "v %.17g %.17g %.17g\n", x1, cb * y1, sb * y1);
        }
        put(&t, "f");
        for (int j = 0; j < k; j++)
            put(&t, " %d", j + 1);
        put(&t, "\n");
        CHECK(obj_parse("poly.obj", t.s, t.n, &o, err, sizeof err) == 0);
        obj_vec_t pn[3 * 16];
        CHECK(o.ntri == (size_t)(k - 2) && obj_smooth_normals(&o, pn, NULL) == 0);
        for (size_t i = 0; i < 3 * o.ntri; i++)
            CHECK_SWEEP(fabs(pn[i].x - zn.x) < 1e-9 && fabs(pn[i].y - zn.y) < 1e-9 && fabs(pn[i].z - zn.z) < 1e-9 &&
                            fabs(len3(pn[i]) - 1) < 1e-12,
                        "polygon %d corner %zu", trial, i);
        obj_free(&o);
        free(t.s);
    }

    /* A file's vn as written (not normalised), beside computed corners;
     * a degenerate triangle alone gives (0, 0, 0). */
    const char *mixed = "v 0 0 0\nv 2 0 0\nv 0 2 0\nv 5 5 5\nvn 0 0 3\nf 1//1 2//1 3\nf 4 4 4\n";
    CHECK(obj_parse("mixed.obj", mixed, strlen(mixed), &o, err, sizeof err) == 0);
    CHECK(obj_smooth_normals(&o, n, &from_file) == 0 && from_file == 2);
    CHECK(n[0].z == 3 && n[1].z == 3 && n[2].x == 0 && n[2].y == 0 && n[2].z == 1);
    CHECK(len3(n[3]) == 0 && len3(n[4]) == 0 && len3(n[5]) == 0);
    obj_free(&o);
}

int main(void)
{
    test_generated();
    test_bad();
    test_mutants();
    test_models();
    test_normals();
    return check_report("test_obj");
}
