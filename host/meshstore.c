/* meshstore: see meshstore.h. */
#include "meshstore.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "errf.h"

static meshstore_entry_t **meshstore;
static size_t meshstore_n, meshstore_cap;

static uint64_t meshstore_hash(const char *buf, size_t len)
{
    uint64_t h = 0xcbf29ce484222325u;
    for (size_t i = 0; i < len; i++)
        h = (h ^ (uint8_t)buf[i]) * 0x100000001b3u;
    return h;
}

static const meshstore_entry_t *meshstore_find(const char *path, uint64_t hash, size_t len, bool smooth,
                                               const bvh_mesh_t **mesh)
{
    for (size_t i = 0; i < meshstore_n; i++) {
        const meshstore_entry_t *e = meshstore[i];
        if (e->hash != hash || e->len != len || strcmp(e->path, path) != 0)
            continue;
        if (e->smooth == smooth || (smooth && e->mb.face_normals)) {
            *mesh = &e->mb.mesh;
            return e;
        }
        if (!smooth) { /* a smooth build serves a flat instance without its normals */
            *mesh = &e->flat;
            return e;
        }
    }
    return NULL;
}

/* A smooth mesh's corner normals (the file's vn, or the sum of the faces'
 * at a vertex) must not be zero: the first that is, as the scene
 * language's message. */
static int meshstore_normals(const obj_t *o, const char *path, char *err, size_t errlen)
{
    obj_vec_t *vn = malloc(sizeof *vn * 3 * (o->ntri ? o->ntri : 1));
    if (vn == NULL || obj_smooth_normals(o, vn, NULL) != 0) {
        free(vn);
        errf_set(err, errlen, "%s: out of memory for the mesh's normals", path);
        return -1;
    }
    for (size_t i = 0; i < o->ntri; i++) {
        obj_vec_t fn = obj_face_normal(o, i);
        if (fn.x == 0.0 && fn.y == 0.0 && fn.z == 0.0)
            continue; /* (left out anyway) */
        for (int k = 0; k < 3; k++) {
            const obj_vec_t *c = &vn[3 * i + k];
            double len = sqrt(c->x * c->x + c->y * c->y + c->z * c->z);
            if (!(len > 0.0) || !isfinite(len)) {
                errf_set(err, errlen, "mesh: the normal of corner %d of face %s:%ld is zero", k + 1, path,
                         (long)o->tri[i].line);
                free(vn);
                return -1;
            }
        }
    }
    free(vn);
    return 0;
}

const meshstore_entry_t *meshstore_get(const char *path, bool smooth, const bvh_mesh_t **mesh, char *err,
                                       size_t errlen)
{
    char *buf;
    size_t len;
    if (obj_read(path, &buf, &len, err, errlen) != 0)
        return NULL;
    uint64_t hash = meshstore_hash(buf, len);
    const meshstore_entry_t *found = meshstore_find(path, hash, len, smooth, mesh);
    if (found) {
        free(buf);
        return found;
    }
    obj_t o;
    int rc = obj_parse(path, buf, len, &o, err, errlen);
    free(buf);
    if (rc != 0)
        return NULL;
    meshstore_entry_t *e = calloc(1, sizeof *e);
    if (meshstore_n == meshstore_cap) {
        size_t cap = meshstore_cap ? 2 * meshstore_cap : 16;
        meshstore_entry_t **grown = realloc(meshstore, cap * sizeof *grown);
        if (grown) {
            meshstore = grown;
            meshstore_cap = cap;
        }
    }
    if (e == NULL || meshstore_n == meshstore_cap || (e->path = strdup(path)) == NULL) {
        free(e);
        obj_free(&o);
        errf_set(err, errlen, "%s: out of memory", path);
        return NULL;
    }
    rc = smooth ? meshstore_normals(&o, path, err, errlen) : 0;
    if (rc == 0 && meshbuild(&o, smooth, &e->mb, err, errlen) != 0) {
        char why[512];
        snprintf(why, sizeof why, "%s", err);
        errf_set(err, errlen, "%s: %s", path, why);
        rc = -1;
    }
    obj_free(&o);
    if (rc != 0) {
        free(e->path);
        free(e);
        return NULL;
    }
    e->hash = hash;
    e->len = len;
    e->smooth = smooth && !e->mb.face_normals;
    e->flat = e->mb.mesh;
    e->flat.vn = NULL;
    meshstore[meshstore_n++] = e;
    *mesh = &e->mb.mesh;
    return e;
}
