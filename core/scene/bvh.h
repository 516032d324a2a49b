/* bvh: a triangle mesh as constant data (flash on a board) behind a
 * bounding-volume hierarchy, and the ray queries on it: the nearest hit
 * and any hit. The data is made on the host (host/meshbuild.c: quantised
 * vertices, vertex normals, a surface-area-heuristic tree); in RAM a mesh
 * costs only its instance (bvh_inst_t) and a query's fixed stack.
 * docs/MESHES.md has the layout and the arithmetic.
 *
 * Mesh space: vertices are int16 integers (the model's box quantised to
 * at most 65,535 steps on its longest axis, so a model 0.01 wide and one
 * 5,000 wide keep the same precision); an instance maps them to the
 * world, w = M q + T, and a query maps its ray the other way, with
 * M^-1 = m 2^-e (m: int32 mantissas below 2^30). The ray parameter t is
 * the world ray's: an affine map keeps it. In Q16.16 a query's origin must lie
 * within 2^30 mesh units of the model's centre (16,384 times the model's
 * longest side): a ray from farther misses (a model that small in the
 * view covers far less than a pixel).
 *
 * A triangle is hit where the ray passes on the inner side of its three
 * edges (Pluecker side tests, each edge evaluated in the order of its
 * vertex indices and negated for the other order, so the triangles on
 * either side of an edge see exactly opposite values: watertight; a ray
 * exactly on an edge hits both). Q16.16 evaluates them exactly in
 * integers; float and double in their own arithmetic, the same formulas. */
#ifndef FXRT_SCENE_BVH_H
#define FXRT_SCENE_BVH_H

#include <stddef.h>

#include "math/ray.h"

/* The tree's depth cap (the root is depth 0): a query's stack holds
 * BVH_MAX_DEPTH node indices. bvh_check refuses a deeper tree. */
#define BVH_MAX_DEPTH 40
/* The most triangles in a leaf (the count's 4 bits). */
#define BVH_LEAF_MAX 15
/* The quantised range: |q| <= BVH_Q_MAX on every axis. */
#define BVH_Q_MAX 32767
/* 2^-e as a number (float, double; exact: e <= 62). */
static inline num_t bvh_unscale(int e)
{
    num_t s = NUM_ONE;
    for (int i = 0; i < e; i++)
        s = s * (num_t)0.5;
    return s;
}

/* Unit vertex normals are stored as round(n * BVH_N_ONE). */
#define BVH_N_ONE 32767

/* A node: its box in mesh space (every vertex of every triangle below it
 * lies within lo..hi) and its link: a leaf holds link & 15 triangles
 * from link >> 4; an inner node (link & 15 == 0) has its children at
 * link >> 4 and (link >> 4) + 1. 16 bytes. */
typedef struct {
    int16_t lo[3], hi[3];
    uint32_t link;
} bvh_node_t;

/* A mesh: n_triangles triangles, in the tree's order, each three vertex
 * indices (tri16 where n_vertices <= 65,536, else tri32; the other NULL),
 * counter-clockwise seen from outside (the OBJ convention; the winding
 * normal (b - a) x (c - a) points out); vn, where not NULL, one unit
 * normal per vertex for smooth shading. Node 0 is the root. */
typedef struct {
    uint32_t n_vertices, n_triangles, n_nodes;
    const int16_t (*v)[3];
    const int16_t (*vn)[3];
    const uint16_t (*tri16)[3];
    const uint32_t (*tri32)[3];
    const bvh_node_t *node;
} bvh_mesh_t;

/* An instance: its mesh and the map from the world back to mesh space,
 * q = m 2^-e (w - T), which the queries use, and the forward map w = f
 * 2^-fe q + T, which gives the model's box in the world (geom_model_box,
 * scene/model.c).
 * host/meshbuild.c makes both from the node's transform and the
 * quantisation; bvh_check holds them to be each other's inverse. */
typedef struct {
    const bvh_mesh_t *mesh;
    int32_t m[3][3]; /* |m| < 2^30 */
    int32_t e;       /* 0 .. 62 */
    vec3_t t;
    int32_t f[3][3]; /* |f| < 2^30 */
    int32_t fe;      /* 0 .. 62 */
} bvh_inst_t;

/* A hit: the triangle (in tree order) and its world t; w, the weights of
 * its vertices a, b, c at the hit (barycentric, in Q16.16 within a few
 * LSB, summing to about 1). */
typedef struct {
    uint32_t tri;
    num_t t;
    num_t w[3];
} bvh_hit_t;

/* Is the mesh well formed: indices in range, leaves of 1..BVH_LEAF_MAX
 * triangles that together hold each triangle once (in order, depth
 * first), inner nodes' children after them, depth within BVH_MAX_DEPTH,
 * every box within its parent's and holding its leaf's vertices, vertices
 * within BVH_Q_MAX, no zero vertex normal? And is the instance's map in
 * range (|m| < 2^30, e in 0..62, t within FXRT_COORD_LIMIT)? Walks the
 * whole tree: once, when an instance is added. A query on a mesh that
 * passes reads no byte outside its arrays. */
bool bvh_check(const bvh_inst_t *in);

/* The nearest triangle along the ray with 0 < t < tmax (NUM_MAX: any t),
 * the triangle skip (BVH_NONE: none) left out. Ties in t go to the
 * triangle the walk meets first (the same on every target). */
#define BVH_NONE UINT32_MAX
bool bvh_nearest(const bvh_inst_t *in, const ray_t *ray, num_t tmax, uint32_t skip, bvh_hit_t *hit);
/* The same walk without the weights (hit->w is not written): the
 * triangle and t alone, for visibility. */
bool bvh_first(const bvh_inst_t *in, const ray_t *ray, num_t tmax, uint32_t skip, bvh_hit_t *hit);
/* Is some triangle other than skip hit with 0 < t < tmax? */
bool bvh_any(const bvh_inst_t *in, const ray_t *ray, num_t tmax, uint32_t skip);
/* Triangle tri alone (one that bvh_nearest found on this ray): the same t
 * and weights as bvh_nearest gives for it, without the walk. False when
 * the ray does not meet it in front (or tri is out of range). */
bool bvh_hit_tri(const bvh_inst_t *in, const ray_t *ray, uint32_t tri, bvh_hit_t *hit);

/* Triangle i's vertex indices. */
static inline void bvh_tri(const bvh_mesh_t *m, uint32_t i, uint32_t v[3])
{
    if (m->tri16)
        for (int k = 0; k < 3; k++)
            v[k] = m->tri16[i][k];
    else
        for (int k = 0; k < 3; k++)
            v[k] = m->tri32[i][k];
}

/* The world-space unit normal at a hit: the winding normal (flat), or
 * where smooth and the mesh has vertex normals, the weights' blend of
 * them; in both, not yet turned to face the ray. False when it vanishes. */
bool bvh_normal(const bvh_inst_t *in, const bvh_hit_t *hit, bool smooth, vec3_t *n);

#endif
