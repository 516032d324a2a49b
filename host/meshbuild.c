/* meshbuild: OBJ to the core's mesh data (see meshbuild.h). */
#include "meshbuild.h"

#include "errf.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The tree: binned surface-area heuristic (MB_BINS bins per axis), a
 * triangle test costing MB_COST_TRI box tests; a leaf where no split is
 * cheaper or at most MB_LEAF_MIN triangles remain, at most BVH_LEAF_MAX. Near the depth cap a node is
 * split at its median instead, which keeps every leaf within the cap. */
#define MB_BINS 16
#define MB_COST_TRI 2.0
/* Nodes of at most this many triangles are leaves (nodes are 16 bytes,
 * triangles 6: fewer, fuller leaves keep the data near 20 bytes a
 * triangle). */
#define MB_LEAF_MIN 4
#define MB_FACE_DOT (1 - 1e-7)

typedef struct {
    int32_t lo[3], hi[3];
} mb_box_t;

typedef struct {
    uint32_t tri[3];   /* vertex indices (new) */
    uint32_t src;      /* OBJ triangle */
    mb_box_t box;
    int32_t cen2[3];   /* centroid, doubled: lo + hi */
} mb_tri_t;

typedef struct {
    meshbuild_t *mb;
    mb_tri_t *t;
    uint32_t n_nodes, cap_nodes;
    int depth;
} mb_ctx_t;

static void mb_box_empty(mb_box_t *b)
{
    for (int j = 0; j < 3; j++) {
        b->lo[j] = INT32_MAX;
        b->hi[j] = INT32_MIN;
    }
}

static void mb_box_grow(mb_box_t *b, const mb_box_t *c)
{
    for (int j = 0; j < 3; j++) {
        b->lo[j] = c->lo[j] < b->lo[j] ? c->lo[j] : b->lo[j];
        b->hi[j] = c->hi[j] > b->hi[j] ? c->hi[j] : b->hi[j];
    }
}

static double mb_area(const mb_box_t *b)
{
    if (b->lo[0] > b->hi[0])
        return 0;
    double x = b->hi[0] - b->lo[0], y = b->hi[1] - b->lo[1], z = b->hi[2] - b->lo[2];
    return 2 * (x * y + y * z + z * x);
}

static int mb_axis;
static int mb_cmp_cen(const void *pa, const void *pb)
{
    const mb_tri_t *a = pa, *b = pb;
    if (a->cen2[mb_axis] != b->cen2[mb_axis])
        return a->cen2[mb_axis] < b->cen2[mb_axis] ? -1 : 1;
    return a->src < b->src ? -1 : (a->src > b->src);
}

static int mb_ceil_log2(uint32_t n)
{
    int k = 0;
    while (((uint32_t)1 << k) < n)
        k++;
    return k;
}

/* Node ni over triangles [first, first + n), at depth. */
static void mb_build(mb_ctx_t *c, uint32_t ni, uint32_t first, uint32_t n, int depth)
{
    mb_tri_t *t = c->t + first;
    mb_box_t box, cbox;
    mb_box_empty(&box);
    mb_box_empty(&cbox);
    for (uint32_t i = 0; i < n; i++) {
        mb_box_grow(&box, &t[i].box);
        mb_box_t p = {{t[i].cen2[0], t[i].cen2[1], t[i].cen2[2]}, {t[i].cen2[0], t[i].cen2[1], t[i].cen2[2]}};
        mb_box_grow(&cbox, &p);
    }
    bvh_node_t *nd = &c->mb->node[ni];
    for (int j = 0; j < 3; j++) {
        nd->lo[j] = (int16_t)box.lo[j];
        nd->hi[j] = (int16_t)box.hi[j];
    }
    if (depth > c->depth)
        c->depth = depth;
    /* the best split by the heuristic: axis, bin boundary, cost */
    int best_axis = -1, best_bin = 0;
    double best = (double)n * MB_COST_TRI, area = mb_area(&box);
    bool median = depth + mb_ceil_log2((n + BVH_LEAF_MAX - 1) / BVH_LEAF_MAX) + 1 >= BVH_MAX_DEPTH;
    if (n <= MB_LEAF_MIN)
        best_axis = -2; /* a leaf */
    for (int a = 0; a < 3 && !median && best_axis != -2 && area > 0; a++) {
        int64_t lo = cbox.lo[a], ext = (int64_t)cbox.hi[a] - lo;
        if (ext == 0)
            continue;
        mb_box_t bb[MB_BINS];
        uint32_t cnt[MB_BINS] = {0};
        for (int k = 0; k < MB_BINS; k++)
            mb_box_empty(&bb[k]);
        for (uint32_t i = 0; i < n; i++) {
            int k = (int)(((int64_t)t[i].cen2[a] - lo) * MB_BINS / (ext + 1));
            cnt[k]++;
            mb_box_grow(&bb[k], &t[i].box);
        }
        /* sweep: left areas and counts, then right */
        double la[MB_BINS];
        uint32_t lc[MB_BINS];
        mb_box_t acc;
        mb_box_empty(&acc);
        uint32_t run = 0;
        for (int k = 0; k < MB_BINS; k++) {
            mb_box_grow(&acc, &bb[k]);
            run += cnt[k];
            la[k] = mb_area(&acc);
            lc[k] = run;
        }
        mb_box_empty(&acc);
        run = 0;
        for (int k = MB_BINS - 1; k > 0; k--) {
            mb_box_grow(&acc, &bb[k]);
            run += cnt[k];
            if (lc[k - 1] == 0 || run == 0)
                continue;
            double cost = 1.0 + MB_COST_TRI * (la[k - 1] * lc[k - 1] + mb_area(&acc) * run) / area;
            if (cost < best) {
                best = cost;
                best_axis = a;
                best_bin = k;
            }
        }
    }
    uint32_t nl;
    if (median || (best_axis < 0 && n > BVH_LEAF_MAX)) {
        /* the median along the longest centroid axis (all centroids equal: by order) */
        int a = 0;
        for (int j = 1; j < 3; j++)
            if ((int64_t)cbox.hi[j] - cbox.lo[j] > (int64_t)cbox.hi[a] - cbox.lo[a])
                a = j;
        if (n <= BVH_LEAF_MAX && median && n * MB_COST_TRI <= best)
            goto leaf;
        mb_axis = a;
        qsort(t, n, sizeof *t, mb_cmp_cen);
        nl = n / 2;
    } else if (best_axis < 0) {
        goto leaf;
    } else {
        int64_t lo = cbox.lo[best_axis], ext = (int64_t)cbox.hi[best_axis] - lo;
        uint32_t i = 0, j = n;
        while (i < j) {
            int k = (int)(((int64_t)t[i].cen2[best_axis] - lo) * MB_BINS / (ext + 1));
            if (k < best_bin) {
                i++;
            } else {
                mb_tri_t s = t[i];
                t[i] = t[--j];
                t[j] = s;
            }
        }
        nl = i;
    }
    uint32_t ch = c->n_nodes;
    c->n_nodes += 2;
    nd->link = ch << 4;
    mb_build(c, ch, first, nl, depth + 1);
    mb_build(c, ch + 1, first + nl, n - nl, depth + 1);
    return;
leaf:
    nd->link = first << 4 | n;
}

typedef struct {
    uint32_t v;
    int16_t n[3];
    uint32_t corner;
} mb_key_t;

static int mb_cmp_key(const void *pa, const void *pb)
{
    const mb_key_t *a = pa, *b = pb;
    if (a->v != b->v)
        return a->v < b->v ? -1 : 1;
    int c = memcmp(a->n, b->n, sizeof a->n);
    if (c)
        return c;
    return a->corner < b->corner ? -1 : (a->corner > b->corner);
}

static int16_t mb_q16(double x)
{
    double r = floor(x + 0.5);
    return (int16_t)(r > BVH_Q_MAX ? BVH_Q_MAX : (r < -BVH_Q_MAX ? -BVH_Q_MAX : r));
}

int meshbuild(const obj_t *o, bool smooth, meshbuild_t *mb, char *err, size_t errlen)
{
    memset(mb, 0, sizeof *mb);
    /* the box of the vertices that triangles use */
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < o->ntri; i++) {
        obj_vec_t f = obj_face_normal(o, i);
        if (f.x == 0 && f.y == 0 && f.z == 0)
            continue; /* (dropped below: it must not widen the steps) */
        for (int k = 0; k < 3; k++) {
            const obj_vec_t *p = &o->v[o->tri[i].v[k]];
            double x[3] = {p->x, p->y, p->z};
            for (int j = 0; j < 3; j++) {
                lo[j] = fmin(lo[j], x[j]);
                hi[j] = fmax(hi[j], x[j]);
            }
        }
    }
    double ext = 0;
    for (int j = 0; j < 3; j++) {
        mb->origin[j] = 0.5 * (lo[j] + hi[j]);
        ext = fmax(ext, hi[j] - lo[j]);
    }
    if (!(ext > 0)) {
        errf_set(err, errlen, "the mesh has no triangle of nonzero area");
        return -1;
    }
    mb->step = ext / (2.0 * BVH_Q_MAX);
    obj_vec_t *cn = smooth ? malloc(3 * o->ntri * sizeof *cn) : NULL;
    mb_key_t *key = malloc(3 * o->ntri * sizeof *key);
    mb_tri_t *t = malloc(o->ntri * sizeof *t);
    uint32_t *corner_v = malloc(3 * o->ntri * sizeof *corner_v);
    if ((smooth && (!cn || obj_smooth_normals(o, cn, NULL) != 0)) || !key || !t || !corner_v)
        goto oom;
    /* corners: vertex index and quantised normal; equal pairs share a vertex */
    for (size_t c = 0; c < 3 * o->ntri; c++) {
        key[c].v = (uint32_t)o->tri[c / 3].v[c % 3];
        key[c].corner = (uint32_t)c;
        memset(key[c].n, 0, sizeof key[c].n);
        if (smooth) {
            double l = sqrt(cn[c].x * cn[c].x + cn[c].y * cn[c].y + cn[c].z * cn[c].z);
            if (l > 0) {
                key[c].n[0] = mb_q16(cn[c].x / l * BVH_N_ONE);
                key[c].n[1] = mb_q16(cn[c].y / l * BVH_N_ONE);
                key[c].n[2] = mb_q16(cn[c].z / l * BVH_N_ONE);
            }
        }
    }
    /* Normals that are their faces' own (a file whose vn repeat each
     * face's normal, as Spot's do, to its 6 decimals): within MB_FACE_DOT
     * (an angle of 4.5e-4: n . l moves by at most that, 0.11 of a level)
     * the same as a flat mesh, which needs no normals and no split
     * vertices. */
    if (smooth) {
        bool faces = true;
        for (size_t i = 0; i < o->ntri && faces; i++) {
            obj_vec_t f = obj_face_normal(o, i);
            double l = sqrt(f.x * f.x + f.y * f.y + f.z * f.z);
            if (!(l > 0))
                continue; /* dropped below */
            for (int k = 0; k < 3 && faces; k++) {
                const obj_vec_t *c = &cn[3 * i + k];
                double lc = sqrt(c->x * c->x + c->y * c->y + c->z * c->z);
                faces = lc > 0 && (f.x * c->x + f.y * c->y + f.z * c->z) / (l * lc) >= MB_FACE_DOT;
            }
        }
        if (faces) {
            smooth = false;
            mb->face_normals = true;
            for (size_t c = 0; c < 3 * o->ntri; c++)
                memset(key[c].n, 0, sizeof key[c].n);
        }
    }
    qsort(key, 3 * o->ntri, sizeof *key, mb_cmp_key);
    uint32_t nv = 0;
    for (size_t c = 0; c < 3 * o->ntri; c++) {
        if (c > 0 && (key[c].v != key[c - 1].v || memcmp(key[c].n, key[c - 1].n, sizeof key[c].n)))
            nv++;
        corner_v[key[c].corner] = nv;
    }
    nv++;
    mb->v = malloc(nv * sizeof *mb->v);
    mb->vn = smooth ? malloc(nv * sizeof *mb->vn) : NULL;
    if (!mb->v || (smooth && !mb->vn))
        goto oom;
    for (size_t c = 0; c < 3 * o->ntri; c++) {
        uint32_t k = corner_v[key[c].corner];
        const obj_vec_t *p = &o->v[key[c].v];
        double x[3] = {p->x, p->y, p->z};
        for (int j = 0; j < 3; j++)
            mb->v[k][j] = mb_q16((x[j] - mb->origin[j]) / mb->step);
        if (smooth)
            memcpy(mb->vn[k], key[c].n, sizeof key[c].n);
    }
    /* triangles of nonzero area once quantised (and, where smooth, with
     * nonzero normals at their corners) */
    uint32_t nt = 0;
    for (size_t i = 0; i < o->ntri; i++) {
        mb_tri_t *r = &t[nt];
        for (int k = 0; k < 3; k++)
            r->tri[k] = corner_v[3 * i + k];
        int64_t e1[3], e2[3];
        for (int j = 0; j < 3; j++) {
            e1[j] = (int64_t)mb->v[r->tri[1]][j] - mb->v[r->tri[0]][j];
            e2[j] = (int64_t)mb->v[r->tri[2]][j] - mb->v[r->tri[0]][j];
        }
        bool zero = e1[1] * e2[2] == e1[2] * e2[1] && e1[2] * e2[0] == e1[0] * e2[2] && e1[0] * e2[1] == e1[1] * e2[0];
        for (int k = 0; k < 3 && smooth && !zero; k++) {
            const int16_t *n = mb->vn[r->tri[k]];
            zero = n[0] == 0 && n[1] == 0 && n[2] == 0;
        }
        if (zero) {
            mb->dropped++;
            continue;
        }
        r->src = (uint32_t)i;
        mb_box_empty(&r->box);
        for (int k = 0; k < 3; k++) {
            mb_box_t p;
            for (int j = 0; j < 3; j++)
                p.lo[j] = p.hi[j] = mb->v[r->tri[k]][j];
            mb_box_grow(&r->box, &p);
        }
        for (int j = 0; j < 3; j++)
            r->cen2[j] = r->box.lo[j] + r->box.hi[j];
        nt++;
    }
    if (nt == 0) {
        errf_set(err, errlen, "the mesh has no triangle of nonzero area");
        goto fail;
    }
    /* Only the vertices the kept triangles use (a dropped triangle's may
     * have a zero normal, which bvh_check refuses, and cost bytes). */
    {
        uint32_t *map = corner_v; /* (reused: 3 ntri >= nv entries) */
        for (uint32_t k = 0; k < nv; k++)
            map[k] = UINT32_MAX;
        for (uint32_t i = 0; i < nt; i++)
            for (int k = 0; k < 3; k++)
                map[t[i].tri[k]] = 0; /* used */
        uint32_t used = 0;
        for (uint32_t k = 0; k < nv; k++) { /* in order: a vertex only moves down */
            if (map[k] == UINT32_MAX)
                continue;
            map[k] = used;
            memmove(mb->v[used], mb->v[k], sizeof mb->v[0]);
            if (smooth)
                memmove(mb->vn[used], mb->vn[k], sizeof mb->vn[0]);
            used++;
        }
        for (uint32_t i = 0; i < nt; i++)
            for (int k = 0; k < 3; k++)
                t[i].tri[k] = map[t[i].tri[k]];
        nv = used;
    }
    mb_ctx_t c = {mb, t, 1, 2 * nt, 0};
    mb->node = calloc(2 * nt, sizeof *mb->node);
    mb->src = malloc(nt * sizeof *mb->src);
    if (!mb->node || !mb->src)
        goto oom;
    mb_build(&c, 0, 0, nt, 0);
    mb->depth = c.depth;
    if (nv <= 65536u)
        mb->tri16 = malloc(nt * sizeof *mb->tri16);
    else
        mb->tri32 = malloc(nt * sizeof *mb->tri32);
    if (!mb->tri16 && !mb->tri32)
        goto oom;
    for (uint32_t i = 0; i < nt; i++) {
        mb->src[i] = t[i].src;
        for (int k = 0; k < 3; k++) {
            if (mb->tri16)
                mb->tri16[i][k] = (uint16_t)t[i].tri[k];
            else
                mb->tri32[i][k] = t[i].tri[k];
        }
    }
    mb->mesh = (bvh_mesh_t){nv, nt, c.n_nodes, (const int16_t(*)[3])mb->v, (const int16_t(*)[3])mb->vn,
                            (const uint16_t(*)[3])mb->tri16, (const uint32_t(*)[3])mb->tri32, mb->node};
    free(cn);
    free(key);
    free(t);
    free(corner_v);
    return 0;
oom:
    errf_set(err, errlen, "out of memory");
fail:
    free(cn);
    free(key);
    free(t);
    free(corner_v);
    meshbuild_free(mb);
    return -1;
}

void meshbuild_free(meshbuild_t *mb)
{
    free(mb->v);
    free(mb->vn);
    free(mb->tri16);
    free(mb->tri32);
    free(mb->node);
    free(mb->src);
    memset(mb, 0, sizeof *mb);
}

size_t meshbuild_bytes(const meshbuild_t *mb)
{
    const bvh_mesh_t *m = &mb->mesh;
    return m->n_vertices * sizeof *m->v + (m->vn ? m->n_vertices * sizeof *m->vn : 0) +
           m->n_triangles * (m->tri16 ? sizeof *m->tri16 : sizeof *m->tri32) + m->n_nodes * sizeof *m->node;
}

static bool mb_invert(double a[3][3], double r[3][3])
{
    double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                 a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    if (!(fabs(det) > 0) || !isfinite(det))
        return false;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
            r[i][j] = (a[i1][j1] * a[i2][j2] - a[i1][j2] * a[i2][j1]) / det;
        }
    return true;
}

/* a 2^e below 2^30 - 1 on its largest entry: the most e (0..62) for
 * which that holds; -1 when none does. */
static int mb_exponent(double x[3][3])
{
    double big = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            big = fmax(big, fabs(x[i][j]));
    int e = 0;
    /* (one below 2^30: entries are rounded to integers after) */
    while (e < 62 && big * ldexp(1, e + 1) < (double)(1 << 30) - 1)
        e++;
    return big * ldexp(1, e) < (double)(1 << 30) - 1 ? e : -1;
}

int meshbuild_map(const meshbuild_t *mb, double a[3][3], const double b[3], meshbuild_map_t *map, char *err,
                  size_t errlen)
{
    /* world = a (origin + step q) + b = (a step) q + (a origin + b) */
    double aq[3][3], inv[3][3], t[3];
    for (int i = 0; i < 3; i++) {
        t[i] = b[i];
        for (int j = 0; j < 3; j++) {
            aq[i][j] = a[i][j] * mb->step;
            t[i] += a[i][j] * mb->origin[j];
        }
    }
    if (!mb_invert(aq, inv)) {
        errf_set(err, errlen, "the mesh's transform is singular");
        return -1;
    }
    int e = mb_exponent(inv), fe = mb_exponent(aq);
    if (e < 0) {
        errf_set(err, errlen, "the mesh's steps are too fine for its transform (more than 2^30 per world unit)");
        return -1;
    }
    if (fe < 0) {
        errf_set(err, errlen, "the mesh's steps are too coarse for its transform (more than 2^30 world units)");
        return -1;
    }
    map->e = e;
    map->fe = fe;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            map->m[i][j] = (int32_t)lrint(ldexp(inv[i][j], e));
            map->f[i][j] = (int32_t)lrint(ldexp(aq[i][j], fe));
        }
    for (int i = 0; i < 3; i++) {
        if (!(fabs(t[i]) <= FXRT_COORD_LIMIT)) {
            errf_set(err, errlen, "the mesh's placement is beyond the coordinate limit (%g, at most %d)", t[i],
                     FXRT_COORD_LIMIT);
            return -1;
        }
        map->t16[i] = (int32_t)lrint(t[i] * 65536);
    }
    /* The box the core makes of it (geom_model_box): the root box's corners
     * through the forward map, padded by 2^-10 of the sum of |f q|. */
    const bvh_node_t *root = &mb->node[0];
    static const char axis[3] = {'x', 'y', 'z'};
    for (int i = 0; i < 3; i++) {
        double lo = 0, hi = 0, pad = 0;
        for (int j = 0; j < 3; j++) {
            double p = ldexp(map->f[i][j], -fe) * root->lo[j], q = ldexp(map->f[i][j], -fe) * root->hi[j];
            lo += fmin(p, q);
            hi += fmax(p, q);
            pad += fmax(fabs(p), fabs(q));
        }
        pad = pad / 1024 + 2.0 / 65536;
        map->lo[i] = t[i] + lo - pad;
        map->hi[i] = t[i] + hi + pad;
        if (!(map->lo[i] >= -FXRT_COORD_LIMIT && map->hi[i] <= FXRT_COORD_LIMIT)) {
            double at = map->lo[i] < -FXRT_COORD_LIMIT ? t[i] + lo : t[i] + hi;
            if (fabs(at) > FXRT_COORD_LIMIT)
                errf_set(err, errlen, "it reaches %g on %c, beyond the coordinate limit (%d)", at, axis[i],
                         FXRT_COORD_LIMIT);
            else
                errf_set(err, errlen, "it reaches %g on %c, within %g of the coordinate limit (%d), its box's margin",
                         at, axis[i], pad, FXRT_COORD_LIMIT);
            return -1;
        }
    }
    return 0;
}

int meshbuild_instance(const meshbuild_t *mb, double a[3][3], const double b[3], bvh_inst_t *in, char *err,
                       size_t errlen)
{
    meshbuild_map_t map;
    if (meshbuild_map(mb, a, b, &map, err, errlen) != 0)
        return -1;
    meshbuild_inst(&map, &mb->mesh, in);
    return 0;
}

void meshbuild_world(const meshbuild_t *mb, double a[3][3], const double b[3], const int16_t q[3], double w[3])
{
    for (int i = 0; i < 3; i++) {
        w[i] = b[i];
        for (int j = 0; j < 3; j++)
            w[i] += a[i][j] * (mb->origin[j] + mb->step * q[j]);
    }
}
