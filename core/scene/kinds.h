/* kinds: the kinds of object a world holds. One row of FXRT_KINDS per
 * kind, and its record below: every per-kind array, loop and switch of
 * the core (the world, shadows, secondary rays, shading, set-up, the API)
 * and of the host tools (the scene language, the scene compiler) is made
 * from this table. docs/ARCHITECTURE.md, "A new kind", has the steps.
 *
 * X(KIND, kind, kinds, CAPACITY, SOLID, BOUNDED, FORM, EDGES, F1, T1, F2, T2, F3, T3, F4, T4):
 *   KIND      the enum name's suffix: GEOM_KIND
 *   kind      the infix of its functions (geom_kind_hit, render_setup_kind)
 *             and its scene keyword
 *   kinds     the world's array (w->kinds) and count (w->n_kinds)
 *   CAPACITY  its capacity (fxrt_config.h); 0 compiles the kind out
 *   SOLID     1: it has an inside (geom_kind_exit, geom_kind_contains)
 *   BOUNDED   1: it is finite (secondary rays' bounds, shadow culling)
 *   FORM      what the visibility pass makes of it (vis/render.h):
 *             FLAT one flat piece (N, D and its edge forms), ROUND a
 *             sphere's forms, FACES flat pieces from the box-face pool,
 *             RAYS none: a ray per pixel of its bounds through its _hit
 *             (a model's BVH, an affine kind's unit shape)
 *   EDGES     a FLAT piece's edge forms (0..3)
 *   Fi Ti     its fields, in the scene language's words and in the order
 *             of geom_desc_t's p[] (a RADIUS field is its radius): name
 *             and type (POINT, DIR nonzero, RADIUS, MAX a point not below
 *             the field before on any axis, AXIS a semi-axis (a vector a
 *             node maps by its linear part), INST a model's placed mesh,
 *             geom_desc_t's inst; _ NONE for an unused one)
 * In world order: planes first (the renderer's planes lead its objects). */
#ifndef FXRT_SCENE_KINDS_H
#define FXRT_SCENE_KINDS_H

#include "scene/affine.h"
#include "scene/bvh.h"
#include "scene/geom.h"

/*  X(KIND,      kind,      kinds,      CAPACITY,            SOLID BOUNDED FORM   EDGES  fields ...) */
#define FXRT_KINDS(X)                                                                                          \
    X(PLANE,     plane,     planes,     FXRT_MAX_PLANES,     0,    0,      FLAT,  0,     point, POINT, normal, DIR, _, NONE, _, NONE) \
    X(SPHERE,    sphere,    spheres,    FXRT_MAX_SPHERES,    1,    1,      ROUND, 0,     center, POINT, radius, RADIUS, _, NONE, _, NONE) \
    X(TRIANGLE,  triangle,  triangles,  FXRT_MAX_TRIANGLES,  0,    1,      FLAT,  3,     a, POINT, b, POINT, c, POINT, _, NONE) \
    X(BOX,       box,       boxes,      FXRT_MAX_BOXES,      1,    1,      FACES, 0,     min, POINT, max, MAX, _, NONE, _, NONE) \
    X(MODEL,     model,     models,     FXRT_MAX_MODELS,     0,    1,      RAYS,  0,     mesh, INST, _, NONE, _, NONE, _, NONE) \
    X(ELLIPSOID, ellipsoid, ellipsoids, FXRT_MAX_ELLIPSOIDS, 1,    1,      RAYS,  0,     center, POINT, u, AXIS, v, AXIS, w, AXIS) \
    X(PARALLELEPIPED, parallelepiped, parallelepipeds, FXRT_MAX_PARALLELEPIPEDS, 1, 1, RAYS, 0, center, POINT, u, AXIS, v, AXIS, w, AXIS)

/* FXRT_IF_KIND(...): its arguments where the kind is compiled in, nothing
 * where its capacity is 0 (port/port.h's FXRT_IF_NONZERO; the assertion
 * below checks each capacity is a plain number, which it needs). */
#define FXRT_IF_PLANE(...) FXRT_IF_NONZERO(FXRT_MAX_PLANES, __VA_ARGS__)
#define FXRT_IF_SPHERE(...) FXRT_IF_NONZERO(FXRT_MAX_SPHERES, __VA_ARGS__)
#define FXRT_IF_TRIANGLE(...) FXRT_IF_NONZERO(FXRT_MAX_TRIANGLES, __VA_ARGS__)
#define FXRT_IF_BOX(...) FXRT_IF_NONZERO(FXRT_MAX_BOXES, __VA_ARGS__)
#define FXRT_IF_MODEL(...) FXRT_IF_NONZERO(FXRT_MAX_MODELS, __VA_ARGS__)
#define FXRT_IF_ELLIPSOID(...) FXRT_IF_NONZERO(FXRT_MAX_ELLIPSOIDS, __VA_ARGS__)
#define FXRT_IF_PARALLELEPIPED(...) FXRT_IF_NONZERO(FXRT_MAX_PARALLELEPIPEDS, __VA_ARGS__)
#define FXRT_KIND_CAP_PLAIN(K, k, ks, cap, ...) \
    FXRT_STATIC_ASSERT((cap > 0) == (0 FXRT_IF_NONZERO(cap, +1)), "the capacity of " #ks " must be a plain decimal number");
FXRT_KINDS(FXRT_KIND_CAP_PLAIN)
#undef FXRT_KIND_CAP_PLAIN

/* FXRT_IF_SMOOTH(...): its arguments where smooth shading is compiled in
 * (FXRT_SMOOTH, fxrt_config.h); FXRT_IF_NORMALS(...) where a surface may
 * have a normal other than its face's: smooth triangles or models (whose
 * meshes may carry vertex normals whatever FXRT_SMOOTH says). */
#if FXRT_SMOOTH
#define FXRT_IF_SMOOTH(...) __VA_ARGS__
#define FXRT_IF_NORMALS(...) __VA_ARGS__
#else
#define FXRT_IF_SMOOTH(...)
#define FXRT_IF_NORMALS(...) FXRT_IF_MODEL(__VA_ARGS__)
#endif

/* Helpers for the tables' users: FXRT_WHEN(FLAG, ...) keeps its
 * arguments when FLAG is 1 (a SOLID or BOUNDED column), drops them when 0. */
#define FXRT_WHEN(flag, ...) FXRT_WHEN_##flag(__VA_ARGS__)
#define FXRT_WHEN_0(...)
#define FXRT_WHEN_1(...) __VA_ARGS__
#define FXRT_UNLESS(flag, ...) FXRT_WHEN_##flag##_NOT(__VA_ARGS__)
#define FXRT_WHEN_0_NOT(...) __VA_ARGS__
#define FXRT_WHEN_1_NOT(...)

#define GEOM_KIND_ENUM(K, ...) GEOM_##K,
/* GEOM_PLANE ..., and the public API's spelling FXRT_PLANE ... (fxrt.h). */
#define GEOM_KIND_PUBLIC(K, ...) FXRT_##K = GEOM_##K,
typedef enum { FXRT_KINDS(GEOM_KIND_ENUM) GEOM_KINDS, FXRT_KINDS(GEOM_KIND_PUBLIC) } geom_kind_t;
#undef GEOM_KIND_PUBLIC
#undef GEOM_KIND_ENUM

/* The capacities: each >= 0, their sum FXRT_RENDER_MAX_OBJECTS
 * (fxrt_config.h) in 1..65535: ids are uint16_t and 0xFFFF is the "no
 * object" sentinel. */
#define FXRT_KIND_CAPACITY(K, k, ks, cap, ...) +(cap)
#define FXRT_KIND_CAPACITY_OK(K, k, ks, cap, ...) &&(cap) >= 0
FXRT_STATIC_ASSERT(1 FXRT_KINDS(FXRT_KIND_CAPACITY_OK), "FXRT_MAX_<KIND> capacities must be >= 0");
FXRT_STATIC_ASSERT(FXRT_RENDER_MAX_OBJECTS >= 1, "the world must be able to hold at least one object");
FXRT_STATIC_ASSERT(FXRT_RENDER_MAX_OBJECTS <= 65535, "total object capacity (the FXRT_MAX_<KIND> summed) must be <= 65535: ids are uint16_t and 0xFFFF is the no-object sentinel");

/* Bit GEOM_KIND is set for each solid kind. */
#define GEOM_SOLID_BIT(K, k, ks, cap, solid, ...) | (solid << GEOM_##K)
#define GEOM_SOLID_KINDS (0u FXRT_KINDS(GEOM_SOLID_BIT))
/* Bit GEOM_KIND is set for each kind of the FLAT form (a plane, a
 * triangle: one flat piece, whose hit point the light sum can take from a
 * ratio along the ray's raw direction, light/hit.c). */
#define GEOM_FORM_FLAT_FLAT 1u
#define GEOM_FORM_FLAT_ROUND 0u
#define GEOM_FORM_FLAT_FACES 0u
#define GEOM_FORM_FLAT_RAYS 0u
#define GEOM_FLAT_BIT(K, k, ks, cap, solid, bounded, form, ...) | (GEOM_FORM_FLAT_##form << GEOM_##K)
#define GEOM_FLAT_KINDS (0u FXRT_KINDS(GEOM_FLAT_BIT))

/* One object as data (the public API's fxrt_object_t): p[] holds its
 * kind's fields in table order (plane point, normal; sphere centre;
 * triangle a, b, c; box min, max; ellipsoid centre, u, v, w), radius a
 * RADIUS field. */
typedef struct {
    geom_kind_t kind;
    vec3_t p[4];
    num_t radius;
    color_t color;
    material_t material; /* all zero: MATERIAL_FLAT */
    /* A triangle's vertex normals (any nonzero length; normalised when
     * added) where smooth is true: it is shaded smooth (scene/smooth.c). */
    FXRT_IF_SMOOTH(bool smooth; vec3_t vn[3];)
    /* A model's mesh and placement (copied when added; the mesh data it
     * points to must outlive the world). */
    FXRT_IF_MODEL(const bvh_inst_t *inst;)
} geom_desc_t;

/* ---- the records --------------------------------------------------------- */

/* After each record, GEOM_KIND_FIELDS(F): its fields in order, as
 * F(TYPE, field), from which the scene compiler writes a world as a
 * constant initialiser for a board's flash (host/scenec_world.c). TYPE
 * is VEC, NUM, WIDE (numw_t), BOOL, COMMON (geom_common_t), INST
 * (bvh_inst_t), AFFINE (geom_affine_t) or SMOOTH (a triangle's
 * FXRT_IF_SMOOTH fields, smooth and vn). */

typedef struct {
    vec3_t a; /* a point on the plane */
    vec3_t n; /* unit normal */
    geom_common_t obj;
} geom_plane_t;
#define GEOM_PLANE_FIELDS(F) F(VEC, a) F(VEC, n) F(COMMON, obj)

typedef struct {
    vec3_t center;
    num_t radius;
    numw_t radius2; /* radius^2, exact (Q32.32) */
    geom_common_t obj;
} geom_sphere_t;
#define GEOM_SPHERE_FIELDS(F) F(VEC, center) F(NUM, radius) F(WIDE, radius2) F(COMMON, obj)

typedef struct {
    vec3_t a, b, c;  /* vertices (edge tests use them directly, see triangle.c) */
    vec3_t n;        /* unit normal, zero when degenerate */
    bool degenerate; /* collinear vertices: never hit */
    geom_common_t obj;
    FXRT_IF_SMOOTH(bool smooth; vec3_t vn[3];) /* unit vertex normals, where smooth */
} geom_triangle_t;
#define GEOM_TRIANGLE_FIELDS(F) F(VEC, a) F(VEC, b) F(VEC, c) F(VEC, n) F(BOOL, degenerate) F(COMMON, obj) F(SMOOTH, smooth)

typedef struct {
    vec3_t min, max; /* lbf and run corners, min <= max per axis */
    geom_common_t obj;
} geom_box_t;
#define GEOM_BOX_FIELDS(F) F(VEC, min) F(VEC, max) F(COMMON, obj)

/* A model: a mesh in constant data placed in the world (scene/model.c).
 * lo, hi: a box around it in world space (from the placement's forward
 * map, padded). */
typedef struct {
    bvh_inst_t in;
    vec3_t lo, hi;
    geom_common_t obj;
} geom_model_t;
#define GEOM_MODEL_FIELDS(F) F(INST, in) F(VEC, lo) F(VEC, hi) F(COMMON, obj)

/* Where a ray met a model (its parts are triangles): the triangle, and
 * the shading normal there (unit, not yet turned towards the ray) where
 * smooth. Shadow and secondary rays leave that triangle out, not the
 * model (light/shadow.c, light/trace.c). Other kinds have no parts: the
 * shading path passes NULL. GEOM_PART_PARAM and GEOM_PART_ARG add the
 * argument to a parameter list where models are compiled in. */
typedef struct {
    uint32_t tri;
    bool smooth;
    vec3_t ns;
} geom_part_t;
/* An ellipsoid: the points c + x u + y v + z w with x^2 + y^2 + z^2 <= 1
 * (scene/ellipsoid.c), a sphere a node scales unevenly; a parallelepiped:
 * those with |x|, |y|, |z| <= 1 (scene/parallelepiped.c), a box a node
 * turns. Both are a unit shape placed by an affine map (scene/affine.h). */
typedef struct {
    geom_affine_t a;
    geom_common_t obj;
} geom_ellipsoid_t;
#define GEOM_ELLIPSOID_FIELDS(F) F(AFFINE, a) F(COMMON, obj)
typedef struct {
    geom_affine_t a;
    geom_common_t obj;
} geom_parallelepiped_t;
#define GEOM_PARALLELEPIPED_FIELDS(F) F(AFFINE, a) F(COMMON, obj)

#define GEOM_PART_PARAM FXRT_IF_MODEL(, const geom_part_t *part)
#define GEOM_PART_ARG(x) FXRT_IF_MODEL(, x)

/* Each kind's constructor and domain check, on its fields as written. */
bool geom_plane_make(geom_plane_t *p, vec3_t point, vec3_t normal, color_t color, uint16_t id);
bool geom_sphere_make(geom_sphere_t *s, vec3_t center, num_t radius, color_t color, uint16_t id);
bool geom_triangle_make(geom_triangle_t *t, vec3_t a, vec3_t b, vec3_t c, color_t color, uint16_t id);
bool geom_box_make(geom_box_t *b, vec3_t min, vec3_t max, color_t color, uint16_t id);
fxrt_err_t geom_plane_check(vec3_t point, vec3_t normal, color_t color);
fxrt_err_t geom_sphere_check(vec3_t center, num_t radius, color_t color);
fxrt_err_t geom_triangle_check(vec3_t a, vec3_t b, vec3_t c, color_t color);
fxrt_err_t geom_box_check(vec3_t min, vec3_t max, color_t color);
bool geom_ellipsoid_make(geom_ellipsoid_t *e, vec3_t center, vec3_t u, vec3_t v, vec3_t w, color_t color,
                         uint16_t id);
fxrt_err_t geom_ellipsoid_check(vec3_t center, vec3_t u, vec3_t v, vec3_t w, color_t color);
bool geom_parallelepiped_make(geom_parallelepiped_t *b, vec3_t center, vec3_t u, vec3_t v, vec3_t w, color_t color,
                              uint16_t id);
fxrt_err_t geom_parallelepiped_check(vec3_t center, vec3_t u, vec3_t v, vec3_t w, color_t color);
bool geom_model_make(geom_model_t *m, const bvh_inst_t *inst, color_t color, uint16_t id);
fxrt_err_t geom_model_check(const bvh_inst_t *inst, color_t color);
/* A model's box in world space, lo <= hi: every point of the mesh as the
 * queries place it lies inside (the forward map's corners of the root
 * box, padded by what the two maps may disagree). False when the box
 * reaches beyond FXRT_COORD_LIMIT, or the two maps are not each other's
 * inverse within 2^-12. Call after bvh_check. */
bool geom_model_box(const bvh_inst_t *in, vec3_t *lo, vec3_t *hi);
/* A model's footprint: at most n nodes of its tree (node[], the widest
 * split first; returns how many) that together hold every triangle, and
 * a node's box in world space, as geom_model_box's (false: none). */
int geom_model_cut(const geom_model_t *o, uint32_t node[], int n);
bool geom_model_cut_box(const geom_model_t *o, uint32_t node, vec3_t *lo, vec3_t *hi);
/* A model's nearest hit and its surface with the part met (*part): the
 * triangle known (BVH_NONE: none, the walk finds it) intersected alone;
 * its nearest hit with the triangle skip (BVH_NONE: none) left out, and
 * the triangle met (*tri, when not NULL); its shadow test the same way. */
void geom_model_surface_part(const geom_model_t *o, const ray_t *ray, uint32_t known, num_t *t, vec3_t *n,
                             geom_part_t *part);
bool geom_model_hit_from(const geom_model_t *o, const ray_t *ray, uint32_t skip, num_t *t, uint32_t *tri);
bool geom_model_occludes_from(const geom_model_t *o, const ray_t *ray, num_t tmax, uint32_t skip);
/* Smooth triangles (scene/smooth.c; called only where FXRT_SMOOTH):
 *   geom_smooth_check  d's vertex normals, where d->smooth: FXRT_OK,
 *                      FXRT_ERR_KIND (smooth on another kind),
 *                      FXRT_ERR_COORD or FXRT_ERR_DIRECTION (a zero normal)
 *   geom_smooth_set    t's normals from d (checked), normalised
 *   geom_smooth_normal the shading normal at p, a point of t's plane:
 *                      normalise(w_a n_a + w_b n_b + w_c n_c), w the
 *                      barycentric weights of p; false (n unchanged) when
 *                      t is not smooth or the sum is zero */
fxrt_err_t geom_smooth_check(const geom_desc_t *d);
void geom_smooth_set(geom_triangle_t *t, const geom_desc_t *d);
bool geom_smooth_normal(const geom_triangle_t *t, vec3_t p, vec3_t *n);
/* geom_box_hit that also gives the face hit: axis * 2 + (1 for the max
 * side), 0..5. */
bool geom_box_hit_face(const geom_box_t *b, const ray_t *ray, num_t *t, uint8_t *face);

/* ---- every kind's interface (scene/KIND.c) --------------------------------
 *   geom_K_check     its fields (in table order) and colour against the
 *                    domain (geom.h): FXRT_OK or the fxrt_err_t that refuses
 *                    them
 *   geom_K_make      the record from checked fields, colour and scene id:
 *                    false for a plane whose normal is too short to
 *                    normalise
 *   geom_K_hit       the nearest hit with t > 0 (in Q16.16 t >= 1 LSB), or
 *                    false; d is unit length, so t is a distance. A hit
 *                    beyond the number range saturates to NUM_MAX and still
 *                    counts (a far hit, not a miss)
 *   geom_K_occludes  shadow rays: any hit with 0 < t < tmax (tmax NUM_MAX:
 *                    any t > 0), no division, exact in Q16.16
 *   geom_K_surface   shading: where a ray that the renderer found to meet
 *                    the object meets its surface, and the unit geometric
 *                    normal there (outward for solids; not yet turned
 *                    towards the ray). Never misses: at a silhouette the
 *                    nearest surface point the ray comes to
 * for a bounded kind:
 *   geom_K_bounds    a box around it: lo <= hi on every axis
 *   geom_K_around    a sphere around it, centre c and radius r (shadow-ray
 *                    culling: light/shadow.c)
 * and for a solid:
 *   geom_K_exit      a secondary ray that starts on the surface and goes
 *                    in: where it leaves, and the outward normal there;
 *                    false when that is not at t > 0
 *   geom_K_contains  is point p strictly inside? */
#define GEOM_KIND_API(K, k, ...)                                                                              \
    bool geom_##k##_hit(const geom_##k##_t *o, const ray_t *ray, num_t *t);                                   \
    bool geom_##k##_occludes(const geom_##k##_t *o, const ray_t *ray, num_t tmax);                            \
    void geom_##k##_surface(const geom_##k##_t *o, const ray_t *ray, num_t *t, vec3_t *n);
#define GEOM_SOLID_API(K, k, ks, cap, solid, bounded, ...)                                                    \
    FXRT_WHEN(bounded, void geom_##k##_bounds(const geom_##k##_t *o, vec3_t *lo, vec3_t *hi);                 \
              void geom_##k##_around(const geom_##k##_t *o, vec3_t *c, num_t *r);)                            \
    FXRT_WHEN(solid, bool geom_##k##_exit(const geom_##k##_t *o, const ray_t *ray, num_t *t, vec3_t *n);      \
              bool geom_##k##_contains(const geom_##k##_t *o, vec3_t p);)
FXRT_KINDS(GEOM_KIND_API)
FXRT_KINDS(GEOM_SOLID_API)
#undef GEOM_KIND_API
#undef GEOM_SOLID_API

/* GEOM_FIELDS(d, T1, T2, T3, T4): description d's fields as the arguments
 * of its kind's geom_K_check and geom_K_make (each followed by a comma):
 * p[] in order for points, directions, MAX points and axes, radius for a
 * RADIUS. */
#define GEOM_FIELDS(d, t1, t2, t3, t4)                                                                       \
    GEOM_ARG_##t1(d, 0) GEOM_ARG_##t2(d, GEOM_NP_##t1) GEOM_ARG_##t3(d, GEOM_NP_##t1 + GEOM_NP_##t2)         \
        GEOM_ARG_##t4(d, GEOM_NP_##t1 + GEOM_NP_##t2 + GEOM_NP_##t3)
#define GEOM_ARG_NONE(d, i)
#define GEOM_ARG_POINT(d, i) (d)->p[i],
#define GEOM_ARG_DIR GEOM_ARG_POINT
#define GEOM_ARG_MAX GEOM_ARG_POINT
#define GEOM_ARG_AXIS GEOM_ARG_POINT
#define GEOM_ARG_RADIUS(d, i) (d)->radius,
#define GEOM_ARG_INST(d, i) (d)->inst,
#define GEOM_NP_NONE 0
#define GEOM_NP_POINT 1
#define GEOM_NP_DIR 1
#define GEOM_NP_MAX 1
#define GEOM_NP_AXIS 1
#define GEOM_NP_RADIUS 0
#define GEOM_NP_INST 0

#endif
