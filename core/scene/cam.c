/* cam: camera set-up and primary rays. See cam.h for the conventions. */
#include "scene/cam.h"

const char *cam_strerror(cam_err_t err)
{
    switch (err) {
    case CAM_OK: return "ok";
    case CAM_ERR_SIZE: return "image size out of range";
    case CAM_ERR_GAZE: return "gaze has zero length";
    case CAM_ERR_UP:
        return "up is parallel to gaze or within 0.9 degrees of it (sin < 1/64); to look straight down use e.g. "
               "'gaze 0 -1 0 up 0 0 -1'";
    case CAM_ERR_WIDE: return "fov too wide for the image height (height * cot(fov/2) < 1; at 1 pixel high fov <= 90)";
    case CAM_ERR_RANGE: return "eye, gaze or up component beyond +-8192 (FXRT_COORD_LIMIT)";
    case CAM_ERR_FOV: return "fov must be inside (0, 180) degrees";
    case CAM_ERR_NARROW: return "fov too narrow for the image height in Q16.16 (height * cot(fov/2) > 32767)";
    case CAM_ERR_SCALE: return "scale must be > 0";
    case CAM_ERR_EXTENT: return "orthographic view reaches beyond the coordinate limit (|eye| + view half-size must be <= 8192 on every axis)";
    }
    return "unknown camera error";
}

/* The camera basis from the raw gaze g and up t, each vector formed from
 * exact products and normalised once (docs/ACCURACY.md, "Camera"):
 *   w = unit(-g),  u = unit(t x -g),  v = unit(t (g.g) - g (g.t)),
 * the last being (-g) x (t x -g) expanded, so no rounded vector is ever
 * crossed again. In Q16.16 the products are exact (t x -g in 64 bits, v's
 * direction in 128 bits) and each unit vector is within 0.5 LSB (plus
 * 2^-13 LSB from keeping 30 bits before normalising) per component of the
 * exact one, whatever the angle between up and gaze or their lengths.
 * Rejects (CAM_ERR_UP) up with sin(up, gaze) < 2^-CAM_UP_MIN_SIN_SHIFT. */
#if FXRT_NUMBER == FXRT_Q16
/* Round a 128-bit direction to 30 significant bits (the direction turns
 * by at most 2^-29 rad, 2^-13 LSB) and normalise it. */
static bool cam_unit128(const fx128_t c[3], vec3_t *out)
{
    int bits = 0;
    for (int i = 0; i < 3; i++) {
        int b = fx128_bits(c[i]);
        bits = b > bits ? b : bits;
    }
    int shift = bits > 30 ? bits - 30 : 0;
    fx_t v[3];
    for (int i = 0; i < 3; i++)
        v[i] = (fx_t)fx128_shr_round(c[i], shift); /* |v| <= 2^30 */
    if (!fx_normalize3(v))
        return false;
    *out = vec3_make(v[0], v[1], v[2]);
    return true;
}

static cam_err_t cam_basis(vec3_t g, vec3_t t, vec3_t *u, vec3_t *v, vec3_t *w)
{
    /* |components| <= 2^29 (checked by the caller): every product below
     * fits its integer. */
    int64_t gx = g.x, gy = g.y, gz = g.z, tx = t.x, ty = t.y, tz = t.z;
    *w = vec3_neg(g);
    if (!vec3_normalize(w))
        return CAM_ERR_GAZE;
    /* c = t x (-g) = g x t, exact: each product < 2^58. */
    int64_t c[3] = {gy * tz - gz * ty, gz * tx - gx * tz, gx * ty - gy * tx};
    /* The angle test |c|^2 >= sin^2 |t|^2 |g|^2, all in 128 bits (|c|^2 and
     * |t|^2 |g|^2 are below 2^122). */
    int64_t gg = gx * gx + gy * gy + gz * gz, tt = tx * tx + ty * ty + tz * tz, gt = gx * tx + gy * ty + gz * tz;
    fx128_t cc = fx128_add(fx128_add(fx128_mul(c[0], c[0]), fx128_mul(c[1], c[1])), fx128_mul(c[2], c[2]));
    fx128_t lim = fx128_shr128(fx128_mul(gg, tt), 2 * CAM_UP_MIN_SIN_SHIFT);
    if (tt == 0 || fx128_sub(cc, lim).hi < 0 || (cc.hi == 0 && cc.lo == 0))
        return CAM_ERR_UP;
    fx128_t cu[3] = {fx128_from64(c[0]), fx128_from64(c[1]), fx128_from64(c[2])};
    /* (-g) x c = t (g.g) - g (g.t): < 2^91 per term. */
    fx128_t cv[3] = {fx128_sub(fx128_mul(tx, gg), fx128_mul(gx, gt)), fx128_sub(fx128_mul(ty, gg), fx128_mul(gy, gt)),
                     fx128_sub(fx128_mul(tz, gg), fx128_mul(gz, gt))};
    if (!cam_unit128(cu, u) || !cam_unit128(cv, v))
        return CAM_ERR_UP;
    return CAM_OK;
}
#else
static cam_err_t cam_basis(vec3_t g, vec3_t t, vec3_t *u, vec3_t *v, vec3_t *w)
{
    *w = vec3_neg(g);
    if (!vec3_normalize(w))
        return CAM_ERR_GAZE;
    vec3_t c = vec3_cross(g, t);
    num_t gg = vec3_dot(g, g), tt = vec3_dot(t, t), gt = vec3_dot(g, t), cc = vec3_dot(c, c);
    num_t k = NUM(1.0 / (double)(1L << (2 * CAM_UP_MIN_SIN_SHIFT)));
    if (!(tt > NUM_ZERO) || !(cc > NUM_ZERO) || cc < gg * tt * k)
        return CAM_ERR_UP;
    *u = c;
    *v = vec3_sub(vec3_scale(t, gg), vec3_scale(g, gt));
    if (!vec3_normalize(u) || !vec3_normalize(v))
        return CAM_ERR_UP;
    return CAM_OK;
}
#endif

/* cot(a/2) for a in (0, 90] degrees, as cot(a) + sqrt(1 + cot(a)^2), so
 * that a/2 (half an LSB in Q16.16 when a is odd) is never rounded: the
 * result is within 2^-15 + 2e-7 relative (cot(a) within 1 LSB + 1e-7
 * relative, the square root rounded once from its exact wide argument). */
static num_t cam_cot_half(num_t a)
{
    num_t c = num_cot_deg(a);
    num_t s = numw_sqrt(numw_add(numw_mul(c, c), numw_from(NUM_ONE)));
    return num_add(c, s);
}

/* True when every component of a lies within +-FXRT_COORD_LIMIT. */
static bool cam_in_domain(vec3_t a)
{
    num_t lim = num_from_int(FXRT_COORD_LIMIT);
    return num_abs(a.x) <= lim && num_abs(a.y) <= lim && num_abs(a.z) <= lim;
}

/* cam_t.small for a perspective camera's fwd, u, v and size. */
static bool cam_grid_small(const cam_t *cam)
{
#if FXRT_NUMBER == FXRT_Q16
    const fx_t *f = &cam->fwd.x, *u = &cam->u.x, *v = &cam->v.x;
    for (int i = 0; i < 3; i++) {
        int64_t af = f[i] < 0 ? -(int64_t)f[i] : f[i], au = u[i] < 0 ? -(int64_t)u[i] : u[i];
        int64_t av = v[i] < 0 ? -(int64_t)v[i] : v[i];
        int64_t reach = af + au * (cam->width - 1) + av * (cam->height - 1);
        if (reach > INT32_MAX)
            return false;
    }
    return true;
#else
    (void)cam;
    return true; /* float and double hold every r(x, y) */
#endif
}

cam_err_t cam_setup(cam_t *cam, cam_kind_t kind, vec3_t eye, vec3_t gaze, vec3_t up,
                    num_t fov_deg, num_t scale, int32_t width, int32_t height)
{
    if (width < 1 || height < 1 || width > FXRT_MAX_DIM || height > FXRT_MAX_DIM)
        return CAM_ERR_SIZE;
    if (!cam_in_domain(eye) || !cam_in_domain(gaze) || !cam_in_domain(up))
        return CAM_ERR_RANGE;
    vec3_t u, v, w;
    cam_err_t be = cam_basis(gaze, up, &u, &v, &w);
    if (be != CAM_OK)
        return be;
    num_t focal = NUM_ONE;
    numw_t step_u = numw_from(NUM_ZERO), step_v = numw_from(NUM_ZERO);

    if (kind == CAM_PERSPECTIVE) {
        if (!(fov_deg > NUM_ZERO && fov_deg < NUM(180)))
            return CAM_ERR_FOV;
        if (fov_deg <= NUM(90)) {
            num_t cot = cam_cot_half(fov_deg); /* >= 1 */
            /* |fwd| = H cot(fov/2) must fit Q16.16 in every build, so that
             * all three builds accept the same scenes. */
            if (cot > num_div(NUM(32767), num_from_int(height)))
                return CAM_ERR_NARROW;
            focal = num_mul_int(cot, height);
        } else {
            /* cot(fov/2) = 1 / tan(fov/2) = 1 / cot((180 - fov)/2), the
             * latter >= 1: the same relative precision for wide angles,
             * where cot(fov/2) itself would keep only a few significant
             * bits in Q16.16. */
            focal = num_div(num_from_int(height), cam_cot_half(num_sub(NUM(180), fov_deg)));
        }
        /* The pixel grid at least one half pixel from the eye: below, the
         * rounding of fwd would turn the rays by more than the cap. */
        if (!(focal >= NUM_ONE))
            return CAM_ERR_WIDE;
    } else {
        if (!(scale > NUM_ZERO))
            return CAM_ERR_SCALE;
        /* Ray origins lie within e +- (A s / 2) u +- (s / 2) v; keep every
         * axis inside the coordinate domain so that no later difference
         * overflows (docs/ACCURACY.md). Bounded per axis by |e| + half
         * width + half height, since u and v are unit vectors. */
        num_t half_h = num_half(scale);
        num_t half_w = numw_round(numw_muldiv_int(half_h, width, height)); /* wide: no saturation */
        num_t reach = num_add(half_w, half_h);
        num_t limit = num_from_int(FXRT_COORD_LIMIT);
        if (num_abs(eye.x) > num_sub(limit, reach) || num_abs(eye.y) > num_sub(limit, reach) ||
            num_abs(eye.z) > num_sub(limit, reach))
            return CAM_ERR_EXTENT;
        /* Offset per half pixel: A s / (2 (W-1)) = s W / (2 H (W-1)) along u,
         * s / (2 (H-1)) along v. A one-pixel axis has only its centre, at
         * offset 0. */
        if (width > 1)
            step_u = numw_muldiv_int(scale, width, 2 * height * (width - 1));
        if (height > 1)
            step_v = numw_muldiv_int(scale, 1, 2 * (height - 1));
    }

    /* Every check has passed: *cam is written only now, so a refused call
     * leaves it as it was (the public API relies on it, frame/api.c). */
    cam->kind = kind;
    cam->width = width;
    cam->height = height;
    cam->e = eye;
    cam->u = u;
    cam->v = v;
    cam->w = w;
    cam->focal = focal;
    cam->fwd = kind == CAM_PERSPECTIVE ? vec3_scale(w, num_neg(focal)) : vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    cam->small = false;
    cam->step_u = step_u;
    cam->step_v = step_v;
    if (kind == CAM_PERSPECTIVE)
        cam->small = cam_grid_small(cam);
    return CAM_OK;
}

void cam_ray(const cam_t *cam, int32_t x, int32_t y, ray_t *ray)
{
    cam_ray_raw(cam, x, y, ray);
    cam_ray_unit(cam, ray);
}

void cam_row(const cam_t *cam, int32_t y, cam_row_t *row, ray_t *ray)
{
    int32_t iy = 2 * y - cam->height + 1;
    row->y = y;
    row->direct = cam->kind == CAM_PERSPECTIVE && cam->small;
    row->viy = vec3_make(num_mul_int_fits(cam->v.x, iy), num_mul_int_fits(cam->v.y, iy), num_mul_int_fits(cam->v.z, iy));
    if (NUM_EXACT) /* (cam_row_ray's sum, in another order: exact) */
        row->viy = vec3_make(num_add_fits(cam->fwd.x, row->viy.x), num_add_fits(cam->fwd.y, row->viy.y),
                             num_add_fits(cam->fwd.z, row->viy.z));
    if (row->direct)
        ray->o = cam->e;
}

void cam_ray_unit(const cam_t *cam, ray_t *ray)
{
    if (cam->kind == CAM_PERSPECTIVE)
        vec3_normalize(&ray->d); /* never zero: |fwd| > 0 and u, v, w are orthogonal */
}

void cam_ray_raw(const cam_t *cam, int32_t x, int32_t y, ray_t *ray)
{
    int32_t ix = 2 * x - cam->width + 1;
    int32_t iy = 2 * y - cam->height + 1;
    if (cam->kind == CAM_PERSPECTIVE) {
#if FXRT_NUMBER == FXRT_Q16
        if (cam->small) { /* the same values in 32-bit arithmetic */
            ray->o = cam->e;
            ray->d = vec3_make(cam->fwd.x + cam->u.x * ix + cam->v.x * iy, cam->fwd.y + cam->u.y * ix + cam->v.y * iy,
                               cam->fwd.z + cam->u.z * ix + cam->v.z * iy);
            return;
        }
        /* |r| may exceed the Q16.16 range (up to sqrt(32767^2 + 2 * 4095^2)):
         * form it in 64 bits and halve it when needed (only the direction
         * matters). */
        int64_t c[3] = {(int64_t)cam->fwd.x + fx_smul_small(cam->u.x, ix) + fx_smul_small(cam->v.x, iy),
                        (int64_t)cam->fwd.y + fx_smul_small(cam->u.y, ix) + fx_smul_small(cam->v.y, iy),
                        (int64_t)cam->fwd.z + fx_smul_small(cam->u.z, ix) + fx_smul_small(cam->v.z, iy)};
        bool big = false;
        for (int i = 0; i < 3; i++)
            big |= c[i] > INT32_MAX || c[i] < -INT32_MAX;
        vec3_t r = big ? vec3_make((fx_t)(c[0] / 2), (fx_t)(c[1] / 2), (fx_t)(c[2] / 2))
                       : vec3_make((fx_t)c[0], (fx_t)c[1], (fx_t)c[2]);
#else
        vec3_t r = vec3_add(cam->fwd, vec3_add(vec3_scale_int(cam->u, ix), vec3_scale_int(cam->v, iy)));
#endif
        ray->o = cam->e;
        ray->d = r;
    } else {
        num_t ou = numw_round(numw_mul_int(cam->step_u, ix));
        num_t ov = numw_round(numw_mul_int(cam->step_v, iy));
        ray->o = vec3_add(cam->e, vec3_add(vec3_scale(cam->u, ou), vec3_scale(cam->v, ov)));
        ray->d = vec3_neg(cam->w);
    }
}

cam_err_t cam_fine(const cam_t *cam, int32_t n, cam_t *fine)
{
    if (n < 1 || n > 16 || cam->width > FXRT_MAX_DIM / n || cam->height > FXRT_MAX_DIM / n)
        return CAM_ERR_SIZE;
    *fine = *cam;
    fine->width = cam->width * n;
    fine->height = cam->height * n;
    if (cam->kind == CAM_PERSPECTIVE) {
        if (cam->focal > num_div(NUM(32767), num_from_int(n)))
            return CAM_ERR_NARROW;
        fine->focal = num_mul_int(cam->focal, n);
        fine->fwd = vec3_scale_int(cam->fwd, n);
        fine->small = cam_grid_small(fine);
    } else {
#if FXRT_NUMBER == FXRT_Q16
        int64_t h = n / 2;
        fine->step_u = (cam->step_u + h) / n; /* steps are >= 0 */
        fine->step_v = (cam->step_v + h) / n;
#else
        fine->step_u = cam->step_u / (num_t)n;
        fine->step_v = cam->step_v / (num_t)n;
#endif
    }
    return CAM_OK;
}
