/* Tests for nodes and meshes in scene files (host/scene.c, host/xform.c;
 * docs/SCENES.md, "Nodes" and "Meshes"). Random nested nodes with random
 * steps hold random objects; each object the loader returns is checked
 * against the same object moved by an independent computation: every
 * step applied to the point in turn, innermost node first, by its own
 * formula (no matrices, no composition), a plane's normal from the cross
 * product of two moved tangents, a box from its moved corners. Meshes
 * come from generated OBJ files with degenerate triangles among them. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "check.h"
#include "models.h"
#include "scene.h"

#define CAM "camera perspective eye 0 0 9 gaze 0 0 -1 up 0 1 0 fov 45\n"

static scene_t g_scene;
static char g_err[1024];
static uint64_t g_rng = 0x9e3779b97f4a7c15u;

static uint64_t rnd(void)
{
    g_rng ^= g_rng << 13;
    g_rng ^= g_rng >> 7;
    g_rng ^= g_rng << 17;
    return g_rng;
}

/* Uniform in [lo, hi], written with 4 decimals and read back, so the
 * test's value is exactly the file's. */
static double draw(double lo, double hi, char *out, size_t size)
{
    double v = lo + (hi - lo) * (double)(rnd() >> 11) / 9007199254740992.0;
    snprintf(out, size, "%.4f", v);
    return strtod(out, NULL);
}

/* One step of a node, as the test applies it. */
typedef struct {
    int type; /* 0 scale, 1 rotate, 2 translate */
    int axis;
    double v[3];
} step_t;

typedef struct {
    int n;
    step_t s[5];
} node_t;

static void apply_step(const step_t *st, double p[3], int linear)
{
    if (st->type == 0) {
        for (int k = 0; k < 3; k++)
            p[k] *= st->v[k];
    } else if (st->type == 1) {
        /* counter-clockwise seen from +axis: about z, x goes to y */
        int i = (st->axis + 1) % 3, j = (st->axis + 2) % 3;
        double a = st->v[0] * (3.14159265358979323846 / 180.0), c = cos(a), s = sin(a);
        double pi = p[i], pj = p[j];
        p[i] = c * pi - s * pj;
        p[j] = s * pi + c * pj;
    } else if (!linear) {
        for (int k = 0; k < 3; k++)
            p[k] += st->v[k];
    }
}

/* Nodes nest[0] (outermost) .. nest[depth-1]: innermost first. */
static void apply_nodes(const node_t *nest, int depth, double p[3], int linear)
{
    for (int d = depth - 1; d >= 0; d--)
        for (int k = 0; k < nest[d].n; k++)
            apply_step(&nest[d].s[k], p, linear);
}

/* What a node's steps may be: kinds of scale and rotation allowed. */
enum { ANY, SIMILAR, AXES };

/* A random node line into buf. */
static void random_node(node_t *nd, int allowed, char *buf, size_t size)
{
    char t[3][32];
    size_t used = (size_t)snprintf(buf, size, "node");
    nd->n = (int)(rnd() % 4);
    for (int k = 0; k < nd->n; k++) {
        step_t *st = &nd->s[k];
        st->type = (int)(rnd() % 3);
        if (st->type == 0) {
            int three = allowed != SIMILAR && rnd() % 2;
            for (int a = 0; a < 3; a++) {
                st->v[a] = draw(0.2, 2.5, t[a], sizeof t[a]);
                if (rnd() % 4 == 0) {
                    st->v[a] = -st->v[a];
                    memmove(t[a] + 1, t[a], strlen(t[a]) + 1);
                    t[a][0] = '-';
                }
            }
            if (three)
                used += (size_t)snprintf(buf + used, size - used, " scale %s %s %s", t[0], t[1], t[2]);
            else {
                used += (size_t)snprintf(buf + used, size - used, " scale %s", t[0]);
                st->v[1] = st->v[2] = st->v[0];
            }
        } else if (st->type == 1) {
            st->axis = (int)(rnd() % 3);
            if (allowed == AXES || rnd() % 3 == 0) {
                st->v[0] = 90.0 * (double)((int)(rnd() % 9) - 4);
                snprintf(t[0], sizeof t[0], "%g", st->v[0]);
            } else {
                st->v[0] = draw(-400, 400, t[0], sizeof t[0]);
            }
            used += (size_t)snprintf(buf + used, size - used, " rotate %c %s", "xyz"[st->axis], t[0]);
        } else {
            for (int a = 0; a < 3; a++)
                st->v[a] = draw(-6, 6, t[a], sizeof t[a]);
            used += (size_t)snprintf(buf + used, size - used, " translate %s %s %s", t[0], t[1], t[2]);
        }
    }
    snprintf(buf + used, size - used, "\n");
}

static double sign_det(const node_t *nest, int depth)
{
    double s = 1;
    for (int d = 0; d < depth; d++)
        for (int k = 0; k < nest[d].n; k++)
            if (nest[d].s[k].type == 0)
                s *= nest[d].s[k].v[0] * nest[d].s[k].v[1] * nest[d].s[k].v[2] < 0 ? -1 : 1;
    return s;
}

static int close_to(double got, double want, double scale)
{
    return fabs(got - want) <= 1e-9 * (1.0 + scale);
}

static int vec_close(scene_vec_t v, const double w[3], double scale)
{
    return close_to(v.x, w[0], scale) && close_to(v.y, w[1], scale) && close_to(v.z, w[2], scale);
}

/* A scene of nested random nodes around one object line; depth nodes. */
static void nest_scene(char *text, size_t size, node_t *nest, int depth, int allowed, const char *object)
{
    size_t used = (size_t)snprintf(text, size, "%s", CAM);
    for (int d = 0; d < depth; d++) {
        random_node(&nest[d], allowed, text + used, size - used);
        used += strlen(text + used);
    }
    used += (size_t)snprintf(text + used, size - used, "%s\n", object);
    for (int d = 0; d < depth; d++)
        used += (size_t)snprintf(text + used, size - used, "end\n");
}

/* Where a node takes normal n (not unit): the cross product of two moved
 * tangents, oriented by the sign of the linear part's determinant,
 * normalised. */
static void moved_normal(const node_t *nest, int depth, const double n_in[3], double m[3])
{
    double n[3] = {n_in[0], n_in[1], n_in[2]}, t1[3], t2[3];
    int ax = fabs(n[0]) < fabs(n[1]) ? (fabs(n[0]) < fabs(n[2]) ? 0 : 2) : (fabs(n[1]) < fabs(n[2]) ? 1 : 2);
    double e[3] = {0, 0, 0};
    e[ax] = 1;
    t1[0] = n[1] * e[2] - n[2] * e[1], t1[1] = n[2] * e[0] - n[0] * e[2], t1[2] = n[0] * e[1] - n[1] * e[0];
    t2[0] = n[1] * t1[2] - n[2] * t1[1], t2[1] = n[2] * t1[0] - n[0] * t1[2], t2[2] = n[0] * t1[1] - n[1] * t1[0];
    /* t1 x t2 points along n: (n x e) x (n x (n x e)) = |n x e|^2 n. */
    apply_nodes(nest, depth, t1, 1);
    apply_nodes(nest, depth, t2, 1);
    m[0] = t1[1] * t2[2] - t1[2] * t2[1], m[1] = t1[2] * t2[0] - t1[0] * t2[2], m[2] = t1[0] * t2[1] - t1[1] * t2[0];
    double len = sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]), sg = sign_det(nest, depth);
    for (int k = 0; k < 3; k++)
        m[k] *= sg / len;
}

static void test_triangles_and_planes(void)
{
    long bad = 0;
    for (int iter = 0; iter < 4000; iter++) {
        node_t nest[4];
        int depth = 1 + (int)(rnd() % 4);
        char text[4096], obj[512], t[9][32];
        double p[3][3];
        int plane = iter % 2;
        for (int k = 0; k < 9; k++)
            p[k / 3][k % 3] = draw(-4, 4, t[k], sizeof t[k]);
        if (plane)
            snprintf(obj, sizeof obj, "plane point %s %s %s normal %s %s %s color 0.3 0.5 0.7", t[0], t[1], t[2],
                     t[3], t[4], t[5]);
        else
            snprintf(obj, sizeof obj, "triangle a %s %s %s b %s %s %s c %s %s %s color 0.3 0.5 0.7", t[0], t[1],
                     t[2], t[3], t[4], t[5], t[6], t[7], t[8]);
        nest_scene(text, sizeof text, nest, depth, ANY, obj);
        if (scene_parse("t", text, strlen(text), &g_scene, g_err, sizeof g_err) != 0 || g_scene.count != 1) {
            CHECK_SWEEP(0, "%s: %s", text, g_err);
            bad++;
            continue;
        }
        const scene_obj_t *o = &g_scene.obj[0];
        int ok;
        if (plane) {
            double pt[3] = {p[0][0], p[0][1], p[0][2]}, m[3];
            apply_nodes(nest, depth, pt, 0);
            moved_normal(nest, depth, p[1], m);
            ok = o->kind == SCENE_PLANE && vec_close(o->p[0], pt, 100) && vec_close(o->p[1], m, 1);
        } else {
            ok = o->kind == SCENE_TRIANGLE;
            for (int v = 0; v < 3; v++) {
                apply_nodes(nest, depth, p[v], 0);
                ok = ok && vec_close(o->p[v], p[v], 100);
            }
        }
        ok = ok && o->color[0] == 0.3 && o->color[2] == 0.7;
        CHECK_SWEEP(ok, "%s", text);
        bad += !ok;
    }
    CHECK_MSG(bad == 0, "4000 triangles and planes in random nodes: %ld wrong", bad);
}

static void test_spheres(void)
{
    long bad = 0, ellipsoids = 0;
    for (int iter = 0; iter < 3000; iter++) {
        node_t nest[4];
        int depth = 1 + (int)(rnd() % 4), uneven = iter % 3 == 0;
        char text[4096], obj[256], t[4][32];
        double c[3], r = draw(0.1, 3, t[3], sizeof t[3]);
        for (int k = 0; k < 3; k++)
            c[k] = draw(-3, 3, t[k], sizeof t[k]);
        /* (uneven: inside one more node, that scales by 1, 1.5, 1) */
        snprintf(obj, sizeof obj, "%ssphere center %s %s %s radius %s color 1 0.5 0%s", uneven ? "node scale 1 1.5 1\n" : "",
                 t[0], t[1], t[2], t[3], uneven ? "\nend" : "");
        nest_scene(text, sizeof text, nest, depth, SIMILAR, obj);
        int rc = scene_parse("t", text, strlen(text), &g_scene, g_err, sizeof g_err);
        if (uneven) {
            /* an ellipsoid: the centre placed, each semi-axis r e_k by the
             * linear parts, the inner node's (1, 1.5, 1) first */
            double cc[3] = {c[0], 1.5 * c[1], c[2]};
            apply_nodes(nest, depth, cc, 0);
            int ok = rc == 0 && g_scene.count == 1 && g_scene.obj[0].kind == SCENE_ELLIPSOID &&
                     vec_close(g_scene.obj[0].p[0], cc, 100) && g_scene.obj[0].radius == 0.0;
            for (int k = 0; k < 3 && ok; k++) {
                double a[3] = {0, 0, 0};
                a[k] = r * (k == 1 ? 1.5 : 1.0);
                apply_nodes(nest, depth, a, 1);
                ok = vec_close(g_scene.obj[0].p[1 + k], a, 100);
            }
            CHECK_SWEEP(ok, "%s: %s", text, rc ? g_err : "");
            ellipsoids += ok;
            continue;
        }
        double s = 1;
        for (int d = 0; d < depth; d++)
            for (int k = 0; k < nest[d].n; k++)
                if (nest[d].s[k].type == 0)
                    s *= fabs(nest[d].s[k].v[0]);
        apply_nodes(nest, depth, c, 0);
        int ok = rc == 0 && g_scene.count == 1 && g_scene.obj[0].kind == SCENE_SPHERE &&
                 vec_close(g_scene.obj[0].p[0], c, 100) && close_to(g_scene.obj[0].radius, r * s, r * s);
        CHECK_SWEEP(ok, "%s: %s", text, rc ? g_err : "");
        bad += !ok;
    }
    CHECK_MSG(bad == 0, "2000 spheres in similar nodes: %ld wrong", bad);
    CHECK_MSG(ellipsoids == 1000, "1000 spheres in an uneven node made ellipsoids: %ld right", ellipsoids);
}

static void test_boxes(void)
{
    long bad = 0, turned_ok = 0;
    for (int iter = 0; iter < 3000; iter++) {
        node_t nest[4];
        int depth = 1 + (int)(rnd() % 4), turned = iter % 3 == 0;
        char text[4096], obj[256], t[6][32];
        double lo[3], hi[3];
        for (int k = 0; k < 3; k++) {
            lo[k] = draw(-3, 0, t[k], sizeof t[k]);
            hi[k] = draw(0, 3, t[k + 3], sizeof t[k + 3]);
        }
        /* (turned: inside one more node, that turns it by 30 degrees) */
        char turn[32] = "";
        if (turned)
            snprintf(turn, sizeof turn, "node rotate %c 30\n", "xyz"[iter % 3]);
        snprintf(obj, sizeof obj, "%sbox min %s %s %s max %s %s %s color 0 0 1%s", turn, t[0], t[1], t[2], t[3], t[4],
                 t[5], turned ? "\nend" : "");
        nest_scene(text, sizeof text, nest, depth, AXES, obj);
        int rc = scene_parse("t", text, strlen(text), &g_scene, g_err, sizeof g_err);
        if (turned) {
            /* a parallelepiped: the centre placed, each half edge by the
             * linear parts, the inner node's turn first */
            const step_t turn30 = {1, iter % 3, {30, 0, 0}};
            double mid[3];
            for (int k = 0; k < 3; k++)
                mid[k] = (lo[k] + hi[k]) / 2;
            apply_step(&turn30, mid, 0);
            apply_nodes(nest, depth, mid, 0);
            int ok = rc == 0 && g_scene.count == 1 && g_scene.obj[0].kind == SCENE_PARALLELEPIPED &&
                     vec_close(g_scene.obj[0].p[0], mid, 100);
            for (int k = 0; k < 3 && ok; k++) {
                double e[3] = {0, 0, 0};
                e[k] = (hi[k] - lo[k]) / 2;
                apply_step(&turn30, e, 1);
                apply_nodes(nest, depth, e, 1);
                ok = vec_close(g_scene.obj[0].p[1 + k], e, 100);
            }
            CHECK_SWEEP(ok, "%s: %s", text, rc ? g_err : "");
            turned_ok += ok;
            continue;
        }
        double a[3] = {INFINITY, INFINITY, INFINITY}, b[3] = {-INFINITY, -INFINITY, -INFINITY};
        for (int c = 0; c < 8; c++) {
            double q[3] = {(c & 1) ? hi[0] : lo[0], (c & 2) ? hi[1] : lo[1], (c & 4) ? hi[2] : lo[2]};
            apply_nodes(nest, depth, q, 0);
            for (int k = 0; k < 3; k++)
                a[k] = fmin(a[k], q[k]), b[k] = fmax(b[k], q[k]);
        }
        int ok = rc == 0 && g_scene.count == 1 && g_scene.obj[0].kind == SCENE_BOX &&
                 vec_close(g_scene.obj[0].p[0], a, 100) && vec_close(g_scene.obj[0].p[1], b, 100);
        CHECK_SWEEP(ok, "%s: %s", text, rc ? g_err : "");
        bad += !ok;
    }
    CHECK_MSG(bad == 0, "2000 boxes in nodes that keep axes: %ld wrong", bad);
    CHECK_MSG(turned_ok == 1000, "1000 boxes turned by 30 degrees made parallelepipeds: %ld right", turned_ok);
}

/* The README's example order: scale, then rotate, then translate; and a
 * nested node's transform first, then its parent's. Exact values. */
static void test_order(void)
{
    const char *s = CAM "node translate 0 1 -5\nnode rotate z 90\nnode scale 2 1 1\n"
                        "triangle a 1 0 0 b 0 1 0 c 0 0 1 color 1 1 1\nend\nend\nend\n";
    const char *f = CAM "node scale 2 1 1 rotate z 90 translate 0 1 -5\n"
                        "triangle a 1 0 0 b 0 1 0 c 0 0 1 color 1 1 1\nend\n";
    for (int k = 0; k < 2; k++) {
        const char *text = k ? s : f;
        int rc = scene_parse("t", text, strlen(text), &g_scene, g_err, sizeof g_err);
        /* a = (1,0,0): scaled (2,0,0), turned (0,2,0), moved (0,3,-5);
         * b = (0,1,0): (0,1,0), (-1,0,0), (-1,1,-5); c: (0,0,1) -> (0,1,-4). */
        const scene_obj_t *o = &g_scene.obj[0];
        CHECK_MSG(rc == 0 && o->p[0].x == 0 && o->p[0].y == 3 && o->p[0].z == -5 && o->p[1].x == -1 &&
                      o->p[1].y == 1 && o->p[1].z == -5 && o->p[2].x == 0 && o->p[2].y == 1 && o->p[2].z == -4,
                  "%s: %s", k ? "nested" : "one line", g_err);
    }
}

static void test_depth_cap(void)
{
    char text[4096];
    for (int depth = SCENE_MAX_NODE_DEPTH; depth <= SCENE_MAX_NODE_DEPTH + 1; depth++) {
        size_t used = (size_t)snprintf(text, sizeof text, "%s", CAM);
        for (int d = 0; d < depth; d++)
            used += (size_t)snprintf(text + used, sizeof text - used, "node translate 0 0 -0.1\n");
        used += (size_t)snprintf(text + used, sizeof text - used, "sphere center 0 0 0 radius 1 color 1 1 1\n");
        for (int d = 0; d < depth; d++)
            used += (size_t)snprintf(text + used, sizeof text - used, "end\n");
        int rc = scene_parse("t", text, used, &g_scene, g_err, sizeof g_err);
        if (depth == SCENE_MAX_NODE_DEPTH)
            CHECK_MSG(rc == 0 && fabs(g_scene.obj[0].p[0].z + 0.1 * depth) < 1e-12, "%s", g_err);
        else
            CHECK_MSG(rc != 0 && strstr(g_err, "nested deeper than") != NULL, "%s", g_err);
    }
}

/* ---- meshes ---- */

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "wb");
    if (f == NULL || fputs(text, f) < 0 || fclose(f) != 0) {
        fprintf(stderr, "cannot write %s\n", path);
        exit(2);
    }
}

/* A random triangle (corners in [-2, 2]) and a random normal per corner
 * (components in [-1, 1], none near zero), drawn as written (vs, ns) and
 * read back (v, n); c, its winding normal. False when it is degenerate. */
static bool smooth_corners(double v[3][3], double n[3][3], char vs[3][3][32], char ns[3][3][32], double c[3])
{
    for (int i = 0; i < 3; i++) {
        for (int k = 0; k < 3; k++)
            v[i][k] = draw(-2, 2, vs[i][k], sizeof vs[i][k]);
        for (int k = 0; k < 3; k++)
            n[i][k] = draw(-1, 1, ns[i][k], sizeof ns[i][k]);
        if (fabs(n[i][0]) + fabs(n[i][1]) + fabs(n[i][2]) < 0.1)
            n[i][2] = 1, snprintf(ns[i][2], sizeof ns[i][2], "1");
    }
    double u[3], w[3];
    for (int k = 0; k < 3; k++)
        u[k] = v[1][k] - v[0][k], w[k] = v[2][k] - v[0][k];
    c[0] = u[1] * w[2] - u[2] * w[1], c[1] = u[2] * w[0] - u[0] * w[2], c[2] = u[0] * w[1] - u[1] * w[0];
    return c[0] != 0 || c[1] != 0 || c[2] != 0;
}

static void test_meshes(const char *dir)
{
    char objpath[512], scpath[512], sub[512];
    long bad = 0;
    snprintf(sub, sizeof sub, "%s/scenes", dir);
    snprintf(objpath, sizeof objpath, "%s/m.obj", dir);
    snprintf(scpath, sizeof scpath, "%s/scenes/s.scene", dir);
    if (mkdir(sub, 0700) != 0) {
        CHECK_MSG(0, "mkdir %s failed", sub);
        return;
    }
    for (int iter = 0; iter < 300; iter++) {
        /* nv vertices, nt triangles, some of them degenerate (a repeated
         * vertex index, or three collinear vertices). */
        static char obj[1 << 16], text[8192];
        double v[40][3];
        int nv = 3 + (int)(rnd() % 30), nt = 1 + (int)(rnd() % 80), tri[80][3], zero = 0;
        size_t used = 0;
        char t[3][32];
        for (int i = 0; i < nv; i++) {
            for (int k = 0; k < 3; k++)
                v[i][k] = draw(-2, 2, t[k], sizeof t[k]);
            used += (size_t)snprintf(obj + used, sizeof obj - used, "v %s %s %s\n", t[0], t[1], t[2]);
        }
        for (int i = 0; i < nt; i++) {
            for (int k = 0; k < 3; k++)
                tri[i][k] = (int)(rnd() % (uint64_t)nv);
            double u[3], w[3];
            for (int k = 0; k < 3; k++)
                u[k] = v[tri[i][1]][k] - v[tri[i][0]][k], w[k] = v[tri[i][2]][k] - v[tri[i][0]][k];
            double c[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
            zero += c[0] == 0 && c[1] == 0 && c[2] == 0;
            used += (size_t)snprintf(obj + used, sizeof obj - used, "f %d %d %d\n", tri[i][0] + 1, tri[i][1] + 1,
                                     tri[i][2] + 1);
        }
        write_text(objpath, obj);
        node_t nest[3];
        int depth = (int)(rnd() % 4);
        nest_scene(text, sizeof text, nest, depth, ANY,
                   "mesh file ../m.obj shading flat color 0.2 0.4 0.6 material phong specular 0.5 0.5 0.5 "
                   "exponent 20");
        write_text(scpath, text);
        int rc = scene_load(scpath, &g_scene, g_err, sizeof g_err);
        int ok;
        if (zero == nt) {
            /* nothing left to draw: refused */
            ok = rc != 0 && strstr(g_err, "no triangle of nonzero area") != NULL;
        } else if (nt - zero <= FXRT_MESH_INLINE) {
            /* a small mesh: its triangles as triangle objects, each where
             * the nodes move the file's vertices */
            ok = rc == 0 && g_scene.count == nt - zero && g_scene.mesh_dropped == zero;
            for (int i = 0, j = 0; ok && i < nt; i++) {
                double c[3][3], u[3], w[3];
                for (int k = 0; k < 3; k++)
                    memcpy(c[k], v[tri[i][k]], sizeof c[k]);
                for (int k = 0; k < 3; k++)
                    u[k] = c[1][k] - c[0][k], w[k] = c[2][k] - c[0][k];
                if (u[1] * w[2] - u[2] * w[1] == 0 && u[2] * w[0] - u[0] * w[2] == 0 && u[0] * w[1] - u[1] * w[0] == 0)
                    continue; /* degenerate */
                const scene_obj_t *o = &g_scene.obj[j++];
                ok = o->kind == SCENE_TRIANGLE && o->material == SCENE_MAT_PHONG && o->exponent == 20 &&
                     o->specular[1] == 0.5 && o->color[1] == 0.4;
                for (int k = 0; k < 3; k++) {
                    apply_nodes(nest, depth, c[k], 0);
                    ok = ok && vec_close(o->p[k], c[k], 100);
                }
            }
        } else {
            /* a larger one: a model */
            const scene_obj_t *o = &g_scene.obj[0];
            ok = rc == 0 && g_scene.count == 1 && o->kind == SCENE_MODEL && o->material == SCENE_MAT_PHONG &&
                 o->exponent == 20 && o->specular[1] == 0.5 && o->color[1] == 0.4 && o->mesh->vn == NULL;
            /* the model's triangles: the file's, less the degenerate ones
             * (and any that quantising made so, counted as dropped) */
            ok = ok && (long)o->mesh->n_triangles + (long)g_scene.mesh_dropped == nt && g_scene.mesh_dropped >= zero;
            /* every vertex of the model where the nodes move one of the
             * file's, within the quantisation: half a step on each axis
             * of the model's box, through the nodes' scale */
            bvh_inst_t in;
            meshbuild_inst(&o->map, o->mesh, &in);
            double gain = 1; /* the nodes' largest stretch: the product of their scales' largest factors */
            for (int d = 0; d < depth; d++)
                for (int k = 0; k < nest[d].n; k++)
                    if (nest[d].s[k].type == 0)
                        gain *= fmax(fabs(nest[d].s[k].v[0]), fmax(fabs(nest[d].s[k].v[1]), fabs(nest[d].s[k].v[2])));
            double tol = o->store->mb.step * 2 * gain + 1e-6;
            double moved[40][3];
            for (int i = 0; i < nv; i++) {
                memcpy(moved[i], v[i], sizeof moved[i]);
                apply_nodes(nest, depth, moved[i], 0);
            }
            for (uint32_t i = 0; ok && i < o->mesh->n_vertices; i++) {
                double q[3] = {o->mesh->v[i][0], o->mesh->v[i][1], o->mesh->v[i][2]}, w[3], best = 1e30;
                model_world(&in, q, w);
                for (int j = 0; j < nv; j++) {
                    double dx = w[0] - moved[j][0], dy = w[1] - moved[j][1], dz = w[2] - moved[j][2];
                    best = fmin(best, sqrt(dx * dx + dy * dy + dz * dz));
                }
                ok = best <= tol;
            }
        }
        CHECK_SWEEP(ok, "mesh %d: %s", iter, rc ? g_err : text);
        bad += !ok;
    }
    CHECK_MSG(bad == 0, "300 generated meshes in random nodes (1 to 80 triangles): %ld wrong", bad);

    /* Smooth meshes: the file's vn per corner, moved by the nodes as
     * normals; without vn, a lone triangle's corners take its own normal.
     * Each random triangle twice: alone, a smooth triangle object with its
     * vertex normals; and FXRT_MESH_INLINE + 1 copies of it (each moved
     * along x, the same normals), a model whose vertex normals turn
     * through its own map (M^-T n, normalised), built flat without vn. */
    long bad_tri = 0, bad_vn = 0;
    for (int iter = 0; iter < 500; iter++) {
        static char obj[8192], text[8192];
        double v[3][3], n[3][3], c[3], nt[3][3];
        char vs[3][3][32], ns[3][3][32];
        size_t used = 0;
        int given = iter % 4 != 0;
        if (!smooth_corners(v, n, vs, ns, c))
            continue;
        for (int i = 0; i < 3; i++) {
            used += (size_t)snprintf(obj + used, sizeof obj - used, "v %s %s %s\nvn %s %s %s\n", vs[i][0], vs[i][1],
                                     vs[i][2], ns[i][0], ns[i][1], ns[i][2]);
            memcpy(nt[i], given ? n[i] : c, sizeof nt[i]);
        }
        snprintf(obj + used, sizeof obj - used, given ? "f 1//1 2//2 3//3\n" : "f 1 2 3\n");
        write_text(objpath, obj);
        node_t nest[3];
        int depth = (int)(rnd() % 4);
        nest_scene(text, sizeof text, nest, depth, ANY, "mesh file ../m.obj color 0.2 0.4 0.6 material lambert");
        write_text(scpath, text);
        int rc = scene_load(scpath, &g_scene, g_err, sizeof g_err);
        const scene_obj_t *o = &g_scene.obj[0];
        int ok = rc == 0 && g_scene.count == 1 && o->kind == SCENE_TRIANGLE && o->smooth;
        for (int i = 0; ok && i < 3; i++) {
            double m[3];
            moved_normal(nest, depth, nt[i], m);
            ok = vec_close(o->vn[i], m, 1);
        }
        CHECK_SWEEP(ok, "smooth triangle %d: %s", iter, rc ? g_err : text);
        bad_tri += !ok;

        used = 0;
        for (int i = 0; i < 3; i++)
            used += (size_t)snprintf(obj + used, sizeof obj - used, "vn %s %s %s\n", ns[i][0], ns[i][1], ns[i][2]);
        for (int r = 0; r <= FXRT_MESH_INLINE; r++) {
            for (int i = 0; i < 3; i++)
                used += (size_t)snprintf(obj + used, sizeof obj - used, "v %.4f %.4f %.4f\n", v[i][0] + 5 * r, v[i][1], v[i][2]);
            int b = 3 * r + 1;
            used += (size_t)(given ? snprintf(obj + used, sizeof obj - used, "f %d//1 %d//2 %d//3\n", b, b + 1, b + 2)
                                   : snprintf(obj + used, sizeof obj - used, "f %d %d %d\n", b, b + 1, b + 2));
        }
        write_text(objpath, obj);
        depth = (int)(rnd() % 4);
        nest_scene(text, sizeof text, nest, depth, ANY, "mesh file ../m.obj color 0.2 0.4 0.6 material lambert");
        write_text(scpath, text);
        rc = scene_load(scpath, &g_scene, g_err, sizeof g_err);
        o = &g_scene.obj[0];
        ok = rc == 0 && g_scene.count == 1 && o->kind == SCENE_MODEL;
        if (ok && !given) {
            ok = o->mesh->vn == NULL && o->store->mb.face_normals;
        } else if (ok) {
            /* each model vertex is one of the file's (no splits: each
             * corner has one normal); its normal as the model shades it */
            bvh_inst_t in;
            meshbuild_inst(&o->map, o->mesh, &in);
            ok = o->mesh->vn != NULL && o->mesh->n_vertices == 3 * (FXRT_MESH_INLINE + 1);
            for (uint32_t i = 0; ok && i < o->mesh->n_vertices; i++) {
                double q[3] = {o->mesh->v[i][0], o->mesh->v[i][1], o->mesh->v[i][2]}, wv[3], best = 1e30;
                int which = 0;
                model_world(&in, q, wv);
                for (int j = 0; j < 3 * (FXRT_MESH_INLINE + 1); j++) {
                    double p[3] = {v[j % 3][0] + 5 * (j / 3), v[j % 3][1], v[j % 3][2]};
                    apply_nodes(nest, depth, p, 0);
                    double d = fabs(p[0] - wv[0]) + fabs(p[1] - wv[1]) + fabs(p[2] - wv[2]);
                    if (d < best)
                        best = d, which = j % 3;
                }
                double want[3], got[3], len = 0;
                moved_normal(nest, depth, n[which], want);
                for (int k = 0; k < 3; k++) {
                    got[k] = ldexp(in.m[0][k], -in.e) * o->mesh->vn[i][0] + ldexp(in.m[1][k], -in.e) * o->mesh->vn[i][1] +
                             ldexp(in.m[2][k], -in.e) * o->mesh->vn[i][2];
                    len += got[k] * got[k];
                }
                for (int k = 0; k < 3; k++)
                    ok = ok && fabs(got[k] / sqrt(len) - want[k]) <= 2e-4;
            }
        }
        CHECK_SWEEP(ok, "smooth model %d: %s", iter, rc ? g_err : text);
        bad_vn += !ok;
    }
    CHECK_MSG(bad_tri == 0, "500 smooth one-triangle meshes in random nodes: %ld with wrong vertex normals", bad_tri);
    CHECK_MSG(bad_vn == 0, "500 smooth models in random nodes: %ld with wrong vertex normals", bad_vn);

    /* Capacity: a mesh of any size is one model (here 1,000 triangles,
     * far past the triangle kind's capacity); FXRT_MAX_MODELS mesh
     * statements fit, then one more is refused with the count. */
    {
        static char obj[1 << 20];
        size_t used = 0;
        for (int i = 0; i < 1000; i++)
            used += (size_t)snprintf(obj + used, sizeof obj - used, "v %d 0 0\nv %d 1 0\nv %d 0 1\nf -3 -2 -1\n", i,
                                     i, i);
        write_text(objpath, obj);
        write_text(scpath, CAM "mesh file ../m.obj shading flat color 1 1 1\n");
        int rc = scene_load(scpath, &g_scene, g_err, sizeof g_err);
        CHECK_MSG(rc == 0 && g_scene.count == 1 && g_scene.obj[0].mesh->n_triangles == 1000, "1,000 triangles: %s",
                  g_err);
    }
    {
        /* cubes (12 triangles) fill the triangle capacity as triangles; the
         * one that no longer fits is a model */
        static char text[1 << 16];
        char cubepath[600];
        snprintf(cubepath, sizeof cubepath, "%s/c.obj", dir);
        write_text(cubepath, cube_obj);
        int fit = FXRT_MAX_TRIANGLES / 12;
        size_t used = (size_t)snprintf(text, sizeof text, CAM);
        for (int i = 0; i <= fit; i++)
            used += (size_t)snprintf(text + used, sizeof text - used, "mesh file ../c.obj shading flat color 1 1 1\n");
        write_text(scpath, text);
        int rc = scene_load(scpath, &g_scene, g_err, sizeof g_err);
        CHECK_MSG(rc == 0 && g_scene.count == 12 * fit + 1 && g_scene.obj[12 * fit].kind == SCENE_MODEL &&
                      g_scene.obj[0].kind == SCENE_TRIANGLE,
                  "%d cubes as triangles, then a model: %s (%d objects)", fit, rc ? g_err : "", g_scene.count);
        unlink(cubepath);
    }
    for (int extra = 0; extra < 2; extra++) {
        static char text[1 << 16];
        size_t used = (size_t)snprintf(text, sizeof text, CAM);
        for (int i = 0; i < FXRT_MAX_MODELS + extra; i++)
            used += (size_t)snprintf(text + used, sizeof text - used, "mesh file ../m.obj shading flat color 1 1 1\n");
        write_text(scpath, text);
        int rc = scene_load(scpath, &g_scene, g_err, sizeof g_err);
        if (extra == 0)
            CHECK_MSG(rc == 0 && g_scene.count == FXRT_MAX_MODELS, "%d meshes fit: %s", FXRT_MAX_MODELS, g_err);
        else
            CHECK_MSG(rc != 0 && strstr(g_err, "too many meshes") != NULL, "%s", g_err);
    }
    /* An OBJ error names the scene's file and line first, then the OBJ's own. */
    write_text(objpath, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n");
    write_text(scpath, CAM "mesh file ../m.obj shading flat color 1 1 1\n");
    char named[1200];
    snprintf(named, sizeof named, "%s:2: %s/../m.obj:4: ", scpath, sub);
    CHECK_MSG(scene_load(scpath, &g_scene, g_err, sizeof g_err) != 0 && strncmp(g_err, named, strlen(named)) == 0,
              "%s (want %s...)", g_err, named);
    unlink(objpath);
    unlink(scpath);
    rmdir(sub);
}

/* A mesh whose path is long enough to fill the message: at every message
 * size from 64 bytes up, the message still starts with the scene's line,
 * and is the full message cut short (the scene fuzzer found a message
 * that put the scene's line last lose it). */
static void test_long_mesh_path(void)
{
    static char text[2200], err[2048];
    int n = snprintf(text, sizeof text, "camera perspective eye 0 0 5 gaze 0 0 -1 up 0 1 0 fov 45\nmesh file ");
    for (int i = 0; i < 950; i++) /* (a line holds at most 1,024 bytes) */
        text[n++] = (char)('a' + i % 26);
    snprintf(text + n, sizeof text - (size_t)n, ".obj color 1 0 0\n");
    static char full[4096];
    int bad = scene_parse("t", text, strlen(text), &g_scene, full, sizeof full) == 0;
    for (size_t len = 64; len <= sizeof err; len += 61) {
        int rc = scene_parse("t", text, strlen(text), &g_scene, err, len);
        size_t l = strlen(err);
        bad += rc == 0 || strncmp(err, "t:2: ", 5) != 0 || l >= len || strncmp(err, full, l) != 0;
    }
    CHECK_MSG(bad == 0, "%d message sizes lost the scene's line", bad);
}

int main(void)
{
    char dir[] = "/tmp/fxrt-test-node-XXXXXX";
    test_long_mesh_path();
    test_order();
    test_triangles_and_planes();
    test_spheres();
    test_boxes();
    test_depth_cap();
    if (mkdtemp(dir) == NULL) {
        CHECK_MSG(0, "mkdtemp failed");
    } else {
        test_meshes(dir);
        rmdir(dir);
    }
    return check_report("test_node");
}
