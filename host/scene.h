/* Scene files: parsing and validation on the host. The parsed scene keeps
 * the file's values as doubles; each renderer build converts them to its
 * own number type (host/engine.c, host/scenec.c). */
#ifndef FXRT_HOST_SCENE_H
#define FXRT_HOST_SCENE_H

#include <stddef.h>
#include "../core/scene/kinds.h" /* the kinds of object and their fields */
#include "meshstore.h"

#define SCENE_MAX_OBJECTS FXRT_RENDER_MAX_OBJECTS
#define SCENE_MAX_LINE 1024 /* longest accepted line, in bytes, without newline */
#define SCENE_DEFAULT_WIDTH 160
#define SCENE_DEFAULT_HEIGHT 120

typedef struct {
    double x, y, z;
} scene_vec_t;

/* Lights a scene may hold: the build's capacity (the format allows 8). */
#define SCENE_MAX_LIGHTS FXRT_MAX_LIGHTS
/* Largest Phong exponent ('exponent' is an integer in 1..this). */
#define SCENE_MAX_EXPONENT FXRT_PHONG_MAX_EXPONENT

/* The kinds of object (scene/kinds.h), in the table's order: SCENE_PLANE, ... */
#define SCENE_KIND_ENUM(K, ...) SCENE_##K,
typedef enum { FXRT_KINDS(SCENE_KIND_ENUM) SCENE_KINDS } scene_kind_t;
#undef SCENE_KIND_ENUM

/* 'material flat|lambert|phong|reflective|transparent' on an object; flat
 * (the default) is the colour as is, unaffected by lights. */
typedef enum {
    SCENE_MAT_FLAT,
    SCENE_MAT_LAMBERT,
    SCENE_MAT_PHONG,
    SCENE_MAT_REFLECTIVE, /* specular, exponent and reflection all required */
    SCENE_MAT_TRANSPARENT /* index required */
} scene_material_t;

/* 'node ... end' nests at most this deep; 'rotate AXIS DEG' takes |DEG|
 * up to SCENE_MAX_ROTATE. */
#define SCENE_MAX_NODE_DEPTH 16
#define SCENE_MAX_ROTATE 36000

/* 'depth N' (bounces per primary ray) and 'samples N [adaptive]'. */
#define SCENE_DEFAULT_DEPTH 4
#define SCENE_MAX_DEPTH 16
#define SCENE_MAX_SAMPLES 16

typedef struct {
    scene_kind_t kind;
    int line;          /* 1-based line of the file it came from */
    double color[3];   /* 0..1 */
    scene_vec_t p[4];  /* its kind's fields in table order (plane: point, normal; ...) */
    double radius;     /* a RADIUS field (sphere), else 0 */
    scene_material_t material;
    double specular[3]; /* phong, reflective: fractions 0..1, else 0 */
    int exponent;       /* phong, reflective: 1..SCENE_MAX_EXPONENT, else 0 */
    double reflection[3]; /* reflective only: fractions 0..1, else 0 */
    double index;       /* transparent only: FXRT_INDEX_MIN..FXRT_INDEX_MAX, else 0 */
    int smooth;         /* a smooth triangle: vn[] holds its unit vertex normals */
    scene_vec_t vn[3];
    /* a model ('mesh file'): its mesh, the header its instance uses
     * (without vertex normals for 'shading flat'), and its placement */
    const meshstore_entry_t *store;
    const bvh_mesh_t *mesh;
    meshbuild_map_t map;
} scene_obj_t;

typedef enum { SCENE_LIGHT_POINT, SCENE_LIGHT_DIRECTIONAL, SCENE_LIGHT_SPOT } scene_light_kind_t;

typedef struct {
    scene_light_kind_t kind;
    int line;              /* line of its 'light' keyword */
    scene_vec_t position;  /* point, spot; else 0 */
    scene_vec_t direction; /* directional, spot: nonzero; else 0 */
    double angle_deg;      /* spot: half-angle of the cone, (0, 90]; else 0 */
    double color[3];       /* fractions 0..1 */
    int shadows;           /* 1 (default) or 0 ('shadows off') */
} scene_light_t;

typedef enum { SCENE_CAM_PERSPECTIVE, SCENE_CAM_ORTHOGRAPHIC } scene_cam_kind_t;

typedef struct {
    scene_cam_kind_t kind;
    int line; /* line of the 'camera' keyword */
    scene_vec_t eye, gaze, up;
    double fov_deg; /* perspective: full opening angle, (0, 180) */
    double scale;   /* orthographic: height of the view in scene units */
} scene_camera_t;

typedef struct {
    int width, height;     /* from 'image', else the defaults above */
    double background[3];  /* 0..1, default black */
    double ambient[3];     /* fractions 0..1, default 0 0 0 */
    int ambient_line;      /* line of 'ambient', 0 when absent */
    scene_camera_t camera;
    int count;
    scene_obj_t obj[SCENE_MAX_OBJECTS]; /* in file order */
    int depth;             /* 'depth', 0..SCENE_MAX_DEPTH, default SCENE_DEFAULT_DEPTH */
    int depth_line;        /* line of 'depth', 0 when absent */
    int samples;           /* 'samples', 1..SCENE_MAX_SAMPLES, default 1 */
    int adaptive;          /* 1 for 'samples N adaptive' */
    int samples_line;      /* line of 'samples', 0 when absent */
    int nlights;
    long mesh_dropped;     /* zero-area triangles the meshes' files held, left out */
    scene_light_t light[SCENE_MAX_LIGHTS > 0 ? SCENE_MAX_LIGHTS : 1]; /* in file order */
} scene_t;

/* Parse scene text (len bytes, need not be NUL-terminated). name is used in
 * messages. Returns 0, or -1 with "NAME:LINE: what is wrong" in err. */
int scene_parse(const char *name, const char *text, size_t len, scene_t *out,
                char *err, size_t errlen);

/* Meshes of at most n triangles become triangle objects (default
 * FXRT_MESH_INLINE; 0: every mesh a model), for the parses that follow
 * in this process (fxrt-scenec --mesh --node places a model). */
void scene_set_mesh_inline(int n);

/* Read and parse a file. Returns 0, or -1 with "PATH:LINE: ..." (or
 * "PATH: ..." when the file cannot be read) in err. */
int scene_load(const char *path, scene_t *out, char *err, size_t errlen);

#endif
