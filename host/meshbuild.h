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

/* The instance of mb placed by the affine map world = a x + b (a model
 * point x): m, e and t of bvh_inst_t. 0, or -1 with the message in err
 * (a singular map; a model so small or so scaled that its steps need more
 * than 2^30 per world unit; a placement beyond the coordinate limit). */
int meshbuild_instance(const meshbuild_t *mb, double a[3][3], const double b[3], bvh_inst_t *in, char *err,
                       size_t errlen);

/* Vertex q's world position under the same map (for tests and tools). */
void meshbuild_world(const meshbuild_t *mb, double a[3][3], const double b[3], const int16_t q[3], double w[3]);

#endif
