/* diffk: the core's intersection kernels and camera behind a double-based,
 * number-neutral interface, for differential tests (tests/test_diff.c) and
 * the kernel fuzzer (tests/fuzz_kernels.c).
 *
 * tests/diffk.c is compiled once per number type with -DFXRT_MULTI and
 * -DFXRT_NUMBER=1 (q16) or 3 (double); every function gets the build's
 * suffix (diffk_sphere_q16, diffk_sphere_double) like the core's own
 * symbols. Each function converts its double arguments exactly as the host
 * tool does (host/engine.c engine_num: Q16.16 rounds to nearest, ties away
 * from zero), builds the object with the real geom_*_make, runs the real
 * geom_*_hit or cam_setup + cam_ray, and returns the result as doubles.
 *
 * To compare number types on equal terms, round the inputs first with
 * diffk_input_q16 and give both builds the rounded values: the q16 build
 * then converts them exactly and only the arithmetic differs. */
#ifndef FXRT_TESTS_DIFFK_H
#define FXRT_TESTS_DIFFK_H

/* A ray: origin and direction (the core expects |d| = 1 up to rounding). */
typedef struct {
    double o[3];
    double d[3];
} diffk_ray_t;

/* Results of the primitive functions. */
enum {
    DIFFK_MISS = 0,
    DIFFK_HIT = 1,
    DIFFK_REJECTED = 2,  /* geom_*_make refused the object (zero normal, radius <= 0, min > max) */
    DIFFK_DEGENERATE = 3 /* triangle with collinear vertices (never hit) */
};

/* Camera kinds (cam_kind_t values). */
enum { DIFFK_PERSPECTIVE = 0, DIFFK_ORTHOGRAPHIC = 1 };

typedef struct {
    int kind; /* DIFFK_PERSPECTIVE or DIFFK_ORTHOGRAPHIC */
    double eye[3], gaze[3], up[3];
    double fov_deg; /* perspective: full opening angle, degrees */
    double scale;   /* orthographic: view height */
    int width, height;
} diffk_cam_t;

/* Lighting (issue 11): one object, its material and lights, for the
 * shading, spot and shadow cases. Object kinds as geom_kind_t: 0 plane
 * (p[0] point, p[1] normal), 1 sphere (p[0] centre, radius), 2 triangle
 * (p[0..2]), 3 box (p[0] min, p[1] max). */
typedef struct {
    int kind;
    double p[3][3];
    double radius;
} diffk_obj_t;

enum { DIFFK_LIGHT_POINT = 0, DIFFK_LIGHT_DIRECTIONAL = 1, DIFFK_LIGHT_SPOT = 2 };
enum { DIFFK_LAMBERT = 1, DIFFK_PHONG = 2 };
#define DIFFK_MAX_LIGHTS 4

typedef struct {
    int kind;        /* DIFFK_LIGHT_* */
    double pos[3];   /* point, spot */
    double dir[3];   /* directional, spot: the direction the light shines in */
    double angle;    /* spot: half-angle, degrees */
    double color[3]; /* fractions 0..1 */
} diffk_light_t;

typedef struct {
    int material;       /* DIFFK_LAMBERT or DIFFK_PHONG */
    int exponent;       /* phong, 1..1024 */
    double color[3];    /* the object's colour, 1/255 units (0..255) */
    double specular[3]; /* fractions */
    double ambient[3];  /* fractions */
    int n_lights;
    diffk_light_t lights[DIFFK_MAX_LIGHTS];
} diffk_shade_t;

/* The largest t a Q16.16 build can return (FX_MAX): a far hit. */
#define DIFFK_Q16_TMAX (2147483647.0 / 65536.0)
#define DIFFK_LSB (1.0 / 65536.0)

/* One set of prototypes per number type. In every function, *t (and rays)
 * are written only on DIFFK_HIT (resp. CAM_OK). */
#define DIFFK_DECLARE(S)                                                                          \
    /* x as the build stores it (Q16.16: rounded to nearest and saturated), as a double. */       \
    double diffk_input_##S(double x);                                                             \
    int diffk_plane_##S(const double point[3], const double normal[3], const diffk_ray_t *ray,    \
                        double *t);                                                               \
    int diffk_sphere_##S(const double center[3], double radius, const diffk_ray_t *ray, double *t); \
    int diffk_triangle_##S(const double a[3], const double b[3], const double c[3],               \
                           const diffk_ray_t *ray, double *t);                                    \
    int diffk_box_##S(const double min[3], const double max[3], const diffk_ray_t *ray, double *t); \
    /* The unit normal geom_*_make stores (plane: kind 0, triangle: kind 2), for diagnostics. */  \
    int diffk_normal_##S(int kind, const double p0[3], const double p1[3], const double p2[3],    \
                         double n[3]);                                                            \
    /* cam_setup once, then cam_ray for n pixels (xs[i], ys[i]) into rays[i]. Returns the         \
     * cam_err_t of cam_setup (0 = CAM_OK); rays are written only on success. */                  \
    int diffk_cam_##S(const diffk_cam_t *cam, int n, const int *xs, const int *ys, diffk_ray_t *rays); \
    /* cam_setup's basis (basis[0..2] = u, v, w) and focal (H cot(fov/2), 1 for orthographic);   \
     * returns the cam_err_t, and writes only on success. */                                      \
    int diffk_cam_basis_##S(const diffk_cam_t *cam, double basis[3][3], double *focal);           \
    /* geom_<kind>_surface for the ray: t and the unit geometric normal. DIFFK_HIT, or          \
     * DIFFK_REJECTED / DIFFK_DEGENERATE (the object cannot be built or is never hit). */       \
    int diffk_surface_##S(const diffk_obj_t *obj, const diffk_ray_t *ray, double *t, double n[3]); \
    /* shade_point at p with geometric normal n for a ray of direction d, in a world holding     \
     * one sphere with the case's material and lights (shadows off): the colour (1/255 units,   \
     * unclamped) and the mask of lights that reach p. 0, or the negative fxrt_err_t of the     \
     * set-up (world_add_light, world_set_material, world_set_ambient). */                      \
    int diffk_shade_##S(const diffk_shade_t *sh, const double p[3], const double n[3],          \
                        const double d[3], double rgb[3], int *mask);                             \
    /* world_occluded for a world of n objects (ids 0..n-1) and tmax (< 0: NUM_MAX, a           \
     * directional light), skipping no object: 1 blocked, 0 not, -1 an object was refused. */   \
    int diffk_occluded_##S(int n, const diffk_obj_t *objs, const diffk_ray_t *ray, double tmax); \
    /* numw_pow_int(x, k) with x given as Q32.32 (x_q32 / 2^32). */                              \
    double diffk_pow_##S(long long x_q32, unsigned k);                                            \
    /* The children core/light/trace.c makes at a hit with incoming direction d and geometric normal  \
     * n (weight 1): for a reflective material (reflection 1) the reflected direction; for a   \
     * clear transparent one of index eta: *tir, and unless total internal reflection, the     \
     * transmitted direction (*has_t: not cut off) and Schlick's R (from the reflected ray's    \
     * weight, or 1 - the transmitted one's when the reflected ray is cut off). */             \
    void diffk_bounce_##S(const double d[3], const double n[3], double eta, double refl[3],     \
                          int *tir, double trans[3], int *has_t, double *R);

DIFFK_DECLARE(q16)
DIFFK_DECLARE(float)
DIFFK_DECLARE(double)

#endif
