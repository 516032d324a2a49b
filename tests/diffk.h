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
    int diffk_cam_basis_##S(const diffk_cam_t *cam, double basis[3][3], double *focal);

DIFFK_DECLARE(q16)
DIFFK_DECLARE(double)

#endif
