/* cam: orthographic and perspective cameras (the seed's formulas).
 *
 * Conventions (all of fxrt):
 *  - Right-handed scene coordinates in scene units; the camera looks along
 *    its gaze g, with up vector t. Basis: w = -g/|g|, u = t x w / |t x w|,
 *    v = w x u, so u points right, v up, and -w into the picture. cam_setup
 *    forms u's and v's directions as exact wide products of the raw g and
 *    t and normalises each once, so the basis is within 1 LSB per
 *    component for any accepted g and t (docs/ACCURACY.md, section 9).
 *    To look straight down use e.g. gaze (0, -1, 0) with up (0, 0, -1).
 *  - Pixel (x, y) is column x (0 = left) and row y counted from the BOTTOM
 *    (0 = bottom row); its centre sits at offsets x - (W-1)/2 and
 *    y - (H-1)/2 from the image centre. Images are stored top row first, so
 *    output row `row` is y = H - 1 - row.
 *  - Perspective: o = e, r = -w (H/2)/tan(a/2) + (x - (W-1)/2) u
 *    + (y - (H-1)/2) v, d = r / |r|, with a the full opening angle.
 *  - Orthographic: d = -w, o = e + A s (x - (W-1)/2)/(W-1) u
 *    + s (y - (H-1)/2)/(H-1) v, with A = W/H and s the scale (view height).
 */
#ifndef FXRT_CAM_H
#define FXRT_CAM_H

#include "math/ray.h"

/* Up must make an angle of at least asin(2^-6) = 0.895 degrees with the
 * gaze (and with its opposite): sin(up, gaze) >= 1/64. Closer, the roll of
 * the camera rests on the last bits of up and gaze as the user rounded
 * them, so no error cap can hold (docs/ACCURACY.md, "Camera"). */
#define CAM_UP_MIN_SIN_SHIFT 6

/* (The FXRT_ names are the public API's spelling, core/fxrt.h.) */
typedef enum {
    CAM_PERSPECTIVE,
    CAM_ORTHOGRAPHIC,
    FXRT_PERSPECTIVE = CAM_PERSPECTIVE,
    FXRT_ORTHOGRAPHIC = CAM_ORTHOGRAPHIC
} cam_kind_t;

typedef enum {
    CAM_OK = 0,
    CAM_ERR_SIZE = -1,     /* width or height outside 1..FXRT_MAX_DIM */
    CAM_ERR_GAZE = -2,     /* gaze is the zero vector */
    CAM_ERR_UP = -3,       /* up is zero, or within asin(2^-CAM_UP_MIN_SIN_SHIFT) of +-gaze */
    CAM_ERR_FOV = -4,      /* fov outside (0, 180) degrees */
    CAM_ERR_NARROW = -5,   /* H cot(fov/2) > 32767: rays unrepresentable in Q16.16 */
    CAM_ERR_SCALE = -6,    /* orthographic scale <= 0 */
    CAM_ERR_EXTENT = -7,   /* orthographic ray origins would leave +-FXRT_COORD_LIMIT */
    CAM_ERR_WIDE = -8,     /* H cot(fov/2) < 1: the pixel grid nearer than half a pixel */
    CAM_ERR_RANGE = -9,    /* an eye, gaze or up component beyond +-FXRT_COORD_LIMIT */
} cam_err_t;

/* Everything a frame's rays need, computed once per frame by cam_setup. */
typedef struct {
    cam_kind_t kind;
    int32_t width, height;
    vec3_t e;       /* eye */
    vec3_t u, v, w; /* unit basis */
    /* Perspective: r(x, y) = fwd + (2x - W + 1) u + (2y - H + 1) v is twice
     * the seed's r, exact in Q16.16 except for fwd = -w H cot(a/2) (the
     * integer multiples of u and v add no rounding). */
    vec3_t fwd;
    num_t focal; /* |fwd| = H cot(fov/2): the distance of the pixel grid in half pixels */
    /* Q16.16: every r(x, y) of the grid, and every partial sum of it, fits
     * int32 (per axis |fwd| + (W - 1) |u| + (H - 1) |v| < 2^31), so cam_ray
     * forms it in 32-bit arithmetic; else in 64 bits, halved when needed.
     * Always true in float and double. */
    bool small;
    /* Orthographic: per-pixel offsets along u and v are (2x - W + 1) *
     * step_u and (2y - H + 1) * step_v, kept wide so that no rounding
     * builds up across the image. */
    numw_t step_u, step_v;
} cam_t;

/* Set up a camera for a width x height image. fov_deg (perspective) is the
 * full opening angle in degrees; scale (orthographic) the view height.
 * Returns CAM_OK or a cam_err_t; *cam is written only on CAM_OK. */
cam_err_t cam_setup(cam_t *cam, cam_kind_t kind, vec3_t eye, vec3_t gaze, vec3_t up,
                    num_t fov_deg, num_t scale, int32_t width, int32_t height);

/* Short English text for an error code. */
const char *cam_strerror(cam_err_t err);

/* Supersampling (samples N): the camera whose pixels are the N x N cells
 * of cam's pixels, so that fine pixel (x N + i, y N + j) has its centre at
 * the centre of cell (i, j) of cam's pixel (x, y): width and height times
 * N, the same eye and basis, fwd times N exactly (perspective: the same
 * rays, scaled), the orthographic steps divided by N (rounded to nearest
 * in Q16.16's wide steps). Returns CAM_OK, CAM_ERR_SIZE (N outside 1..16
 * or a dimension beyond FXRT_MAX_DIM) or CAM_ERR_NARROW (N H cot(fov/2)
 * beyond 32767, as cam_setup refuses it). */
cam_err_t cam_fine(const cam_t *cam, int32_t n, cam_t *fine);

/* The primary ray through pixel (x, y), y counted from the bottom:
 * cam_ray_raw, then cam_ray_unit. cam_ray_raw's direction is the
 * perspective ray's before normalisation (fwd + ix u + iy v, halved where
 * it would leave the range: only its direction matters), the
 * orthographic one's -w; cam_ray_unit normalises a perspective ray's in
 * place (an orthographic one's is unit already). */
void cam_ray(const cam_t *cam, int32_t x, int32_t y, ray_t *ray);
void cam_ray_raw(const cam_t *cam, int32_t x, int32_t y, ray_t *ray);
void cam_ray_unit(const cam_t *cam, ray_t *ray);

/* A row of camera rays (the shading pass): cam_row forms row y's part
 * (2y - H + 1) v once, and where the row is direct, the origin of the
 * ray `ray` the row's pixels use (the eye); cam_row_ray then gives
 * cam_ray_raw's ray for (x, y) in that ray, the same values: fwd + ((2x
 * - W + 1) u + (2y - H + 1) v), exact in Q16.16 where cam->small holds
 * (else, and for an orthographic camera, it calls cam_ray_raw, which
 * sets the whole ray). In Q16.16 the row keeps fwd + (2y - H + 1) v as
 * one vector: integer sums in any order are the same. */
typedef struct {
    vec3_t viy;   /* (2y - H + 1) v; in Q16.16 fwd + (2y - H + 1) v */
    int32_t y;
    bool direct;  /* a perspective camera with cam->small */
} cam_row_t;
void cam_row(const cam_t *cam, int32_t y, cam_row_t *row, ray_t *ray);
/* cam_row_ray's direction for a direct row from the camera's u and fwd,
 * given (a caller may keep copies of them in registers), and ix = 2x - W + 1. */
static inline void cam_row_dir(const cam_row_t *row, const vec3_t *u, const vec3_t *fwd, int32_t ix, ray_t *ray)
{
    if (NUM_EXACT)
        ray->d = vec3_make(num_add_fits(row->viy.x, num_mul_int_fits(u->x, ix)),
                           num_add_fits(row->viy.y, num_mul_int_fits(u->y, ix)),
                           num_add_fits(row->viy.z, num_mul_int_fits(u->z, ix)));
    else
        ray->d = vec3_make(num_add_fits(fwd->x, num_add_fits(num_mul_int_fits(u->x, ix), row->viy.x)),
                           num_add_fits(fwd->y, num_add_fits(num_mul_int_fits(u->y, ix), row->viy.y)),
                           num_add_fits(fwd->z, num_add_fits(num_mul_int_fits(u->z, ix), row->viy.z)));
}
static inline void cam_row_ray(const cam_t *cam, const cam_row_t *row, int32_t x, ray_t *ray)
{
    if (!row->direct) {
        cam_ray_raw(cam, x, row->y, ray);
        return;
    }
    cam_row_dir(row, &cam->u, &cam->fwd, 2 * x - cam->width + 1, ray);
}

#endif
