/* obj: Wavefront OBJ meshes, read on the host (docs/SCENES.md, "OBJ
 * files"). The file's values stay doubles, as a scene's do; its polygons
 * become triangles, fanned from their first vertex.
 *
 * Read: v (x y z, an optional w or r g b ignored), vt (u [v [w]]), vn
 * (x y z), f with v, v/vt, v//vn or v/vt/vn references (1-based; negative
 * ones count back from the last element read: -1 is the last), '#'
 * comments, CRLF line ends. Ignored: o, g, s, usemtl, mtllib. Anything
 * else, a malformed line, index 0, an index out of range, a face of fewer
 * than 3 vertices, a value that is not a plain decimal (NaN, infinity, hex,
 * beyond double), a missing or empty file, one without faces, or one over
 * OBJ_MAX_FILE_BYTES, is refused with "PATH:LINE: message" (the OBJ's own
 * line) or "PATH: message". */
#ifndef FXRT_HOST_OBJ_H
#define FXRT_HOST_OBJ_H

#include <stddef.h>
#include <stdint.h>

/* The largest file read, and the most elements of each list (vertices,
 * texture coordinates, normals, triangles). */
#define OBJ_MAX_FILE_BYTES ((size_t)64 << 20)
#define OBJ_MAX_ELEMENTS ((size_t)1 << 24)

typedef struct {
    double x, y, z;
} obj_vec_t;

typedef struct {
    int32_t v[3];  /* 0-based vertex indices, in the face's order */
    int32_t vt[3]; /* 0-based texture coordinate indices, -1 where the face gives none */
    int32_t vn[3]; /* 0-based normal indices, -1 where the face gives none */
    int32_t line;  /* the 'f' line it comes from */
} obj_tri_t;

typedef struct {
    obj_vec_t *v, *vt, *vn; /* vt: (u, v, w), missing ones 0 */
    size_t nv, nvt, nvn;
    obj_tri_t *tri;
    size_t ntri;
    size_t nfaces;       /* 'f' lines */
    size_t n_cap[4];     /* (allocation sizes) */
} obj_t;

/* Read PATH into o (freed with obj_free). 0, or -1 with the message in
 * err and o empty. */
int obj_load(const char *path, obj_t *o, char *err, size_t errlen);
/* PATH's bytes, by obj_load's rules (a regular file, at most
 * OBJ_MAX_FILE_BYTES): *buf (freed by the caller) and *len. 0, or -1 with
 * the message in err. */
int obj_read(const char *path, char **buf, size_t *len, char *err, size_t errlen);
/* The same from len bytes at buf, PATH naming them in messages. */
int obj_parse(const char *path, const char *buf, size_t len, obj_t *o, char *err, size_t errlen);
void obj_free(obj_t *o);

/* Triangle i's winding normal (b - a) x (c - a), not normalised. */
obj_vec_t obj_face_normal(const obj_t *o, size_t i);

/* The smooth-shading normal at each triangle corner, n[3 i + k] for corner
 * k of triangle i: the file's vn where the face gives one (as written),
 * else the normalised sum of the winding normals of every triangle that
 * uses that vertex index. A vertex whose sum is zero (only degenerate
 * triangles, or faces that cancel) gets its triangle's normalised winding
 * normal, or (0, 0, 0) for a degenerate triangle. n holds 3 * o->ntri
 * vectors; *from_file (if not NULL) counts the corners that took the
 * file's vn. 0, or -1 when out of memory. */
int obj_smooth_normals(const obj_t *o, obj_vec_t *n, size_t *from_file);

#endif
