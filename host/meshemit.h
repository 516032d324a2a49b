/* meshemit: a mesh built by host/meshbuild.c written as C: const arrays
 * (flash on a board) and a const fxrt_mesh_t that names them, for a
 * user's firmware or the scene compiler (docs/MESHES.md). */
#ifndef FXRT_HOST_MESHEMIT_H
#define FXRT_HOST_MESHEMIT_H

#include <stdio.h>

#include "meshbuild.h"

/* Write mb as C into f: NAME_v, NAME_vn (smooth), NAME_tri, NAME_node and
 * `const fxrt_mesh_t NAME`, with a comment naming src and the sizes. 0, or
 * -1 on a write error. */
int meshemit_c(FILE *f, const meshbuild_t *mb, const char *name, const char *src);

/* The parts of meshemit_c: mb's arrays, static, named NAME_v, NAME_vn,
 * NAME_tri and NAME_node; and a `STORAGE const fxrt_mesh_t HEADER` that
 * names them, with the vertex normals where normals (and mb has them). */
void meshemit_arrays(FILE *f, const meshbuild_t *mb, const char *name);
void meshemit_header(FILE *f, const meshbuild_t *mb, const char *name, const char *header, bool normals,
                     const char *storage);

/* `STORAGE const fxrt_instance_t NAME`: mesh header MESH placed by map m
 * (T in Q16.16, exactly, as FXRT_NUM of hexadecimal literals: the same
 * value in every number type as the host's num_from_q16). */
void meshemit_instance(FILE *f, const char *storage, const char *name, const char *mesh, const meshbuild_map_t *m);

/* One line about mb: triangles, vertices, nodes, depth, bytes, bytes per
 * triangle, triangles dropped. */
void meshemit_summary(FILE *f, const meshbuild_t *mb, const char *src);

#endif
