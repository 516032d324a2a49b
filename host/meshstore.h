/* meshstore: the meshes one process has loaded, each built once from its
 * OBJ file (host/meshbuild.c) and shared by every model that names the
 * same file with the same contents: instancing (docs/SCENES.md,
 * "Meshes"). A file whose contents changed is built again. Entries live
 * until the process ends. */
#ifndef FXRT_HOST_MESHSTORE_H
#define FXRT_HOST_MESHSTORE_H

#include "meshbuild.h"

typedef struct {
    char *path;       /* as resolved (relative to the scene's folder) */
    uint64_t hash;    /* FNV-1a of the file's bytes */
    size_t len;       /* and their count */
    bool smooth;      /* built with vertex normals (smooth asked, and not face_normals) */
    meshbuild_t mb;
    bvh_mesh_t flat;  /* mb's mesh without its vertex normals: a flat instance of a smooth build */
} meshstore_entry_t;

/* The mesh of the OBJ file at path with the shading asked for; the
 * header its instances use in *mesh (the build's, or its flat copy).
 * NULL with the message in err: the OBJ's own "PATH:LINE: ..." for a
 * malformed file or a zero vertex normal of a smooth one ("mesh: the
 * normal of corner K of face PATH:LINE is zero"), "PATH: ..." where it
 * cannot be read or built. A flat request shares a smooth build of the
 * same contents. */
const meshstore_entry_t *meshstore_get(const char *path, bool smooth, const bvh_mesh_t **mesh, char *err,
                                       size_t errlen);

#endif
