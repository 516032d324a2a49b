/* meshbuild: an OBJ mesh (host/obj.h) made into the core's constant mesh
 * data (core/scene/bvh.h): vertices quantised on the model's box, vertex
 * normals for smooth shading, triangles reordered behind a tree built
 * with the surface-area heuristic; and an instance's map from a node's
 * transform. docs/MESHES.md has the layout. */
#ifndef FXRT_HOST_MESHBUILD_H
#define FXRT_HOST_MESHBUILD_H

#include "obj.h"
#include "scene/bvh.h"

#include <stdbool.h>
#include <stddef.h>

typedef struct {
    bvh_mesh_t mesh;  /* points into the arrays below */
    int16_t (*v)[3];
    int16_t (*vn)[3]; /* NULL for a flat mesh */
    uint16_t (*tri16)[3];
    uint32_t (*tri32)[3];
    bvh_node_t *node;
    double origin[3]; /* a model point x is origin + step q */
    double step;
    size_t dropped;   /* triangles left out: zero area (in the file, or once quantised), or
                       * (smooth) a zero normal at a corner; their vertices are left out too */
    bool face_normals; /* smooth asked, but every corner's normal was its face's (within a
                        * stored step): built flat, which shades the same */
    int depth;        /* the tree's depth (the root 0) */
    uint32_t *src;    /* src[i]: the OBJ triangle that tree triangle i comes from */
} meshbuild_t;

/* Build mb from o (freed with meshbuild_free): smooth keeps vertex
 * normals (the file's vn where a face gives one, else the normalised sum
 * of the winding normals at that vertex index). 0, or -1 with the message
 * in err (no triangle of nonzero area; out of memory). */
int meshbuild(const obj_t *o, bool smooth, meshbuild_t *mb, char *err, size_t errlen);
void meshbuild_free(meshbuild_t *mb);

/* The mesh's bytes of constant data (vertices, normals, indices, nodes). */
size_t meshbuild_bytes(const meshbuild_t *mb);

/* An instance's maps in integers, the same in every number type: the
 * inverse q = m 2^-e (w - T) and the forward w = f 2^-fe q + T of
 * bvh_inst_t, T in Q16.16 (t16), and the box the core will make of it
 * (lo, hi: geom_model_box' padding, in doubles). */
typedef struct {
    int32_t m[3][3], e, f[3][3], fe, t16[3];
    double lo[3], hi[3];
} meshbuild_map_t;

/* The maps of mb placed by the affine map world = a x + b (a model point
 * x). 0, or -1 with the message in err (a singular map; a model so small
 * or so scaled that its steps need more than 2^30 per world unit, or more
 * than 2^30 world units each; a placement or a box beyond the coordinate
 * limit). */
int meshbuild_map(const meshbuild_t *mb, double a[3][3], const double b[3], meshbuild_map_t *map, char *err,
                  size_t errlen);

/* The instance of mesh (mb's, or a copy of its header) with map, in the
 * includer's number type. */
static inline void meshbuild_inst(const meshbuild_map_t *map, const bvh_mesh_t *mesh, bvh_inst_t *in)
{
    in->mesh = mesh;
    in->e = map->e;
    in->fe = map->fe;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            in->m[i][j] = map->m[i][j];
            in->f[i][j] = map->f[i][j];
        }
    in->t = vec3_make(num_from_q16(map->t16[0]), num_from_q16(map->t16[1]), num_from_q16(map->t16[2]));
}

/* meshbuild_map, then meshbuild_inst with mb's mesh. */
int meshbuild_instance(const meshbuild_t *mb, double a[3][3], const double b[3], bvh_inst_t *in, char *err,
                       size_t errlen);

/* Vertex q's world position under the same map (for tests and tools). */
void meshbuild_world(const meshbuild_t *mb, double a[3][3], const double b[3], const int16_t q[3], double w[3]);

#endif
