/* cam: camera set-up and primary rays. See cam.h for the conventions. */
#include "cam.h"

const char *cam_strerror(cam_err_t err)
{
    switch (err) {
    case CAM_OK: return "ok";
    case CAM_ERR_SIZE: return "image size out of range";
    case CAM_ERR_GAZE: return "gaze has zero length";
    case CAM_ERR_UP: return "up is parallel to gaze";
    case CAM_ERR_FOV: return "fov must be inside (0, 180) degrees";
    case CAM_ERR_NARROW: return "fov too narrow for the image height in Q16.16 (height * cot(fov/2) > 32767)";
    case CAM_ERR_SCALE: return "scale must be > 0";
    case CAM_ERR_EXTENT: return "orthographic view reaches beyond the coordinate limit (|eye| + view half-size must be <= 8192 on every axis)";
    }
    return "unknown camera error";
}

cam_err_t cam_setup(cam_t *cam, cam_kind_t kind, vec3_t eye, vec3_t gaze, vec3_t up,
                    num_t fov_deg, num_t scale, int32_t width, int32_t height)
{
    if (width < 1 || height < 1 || width > FXRT_MAX_DIM || height > FXRT_MAX_DIM)
        return CAM_ERR_SIZE;
    vec3_t w = vec3_neg(gaze);
    if (!vec3_normalize(&w))
        return CAM_ERR_GAZE;
    /* From the exact cross products: a short or nearly parallel up keeps
     * its direction; normalising v removes the rounding of |w| and |u|. */
    vec3_t u, v;
    if (!vec3_unit_cross(up, w, &u))
        return CAM_ERR_UP;
    if (!vec3_unit_cross(w, u, &v))
        return CAM_ERR_UP;

    cam->kind = kind;
    cam->width = width;
    cam->height = height;
    cam->e = eye;
    cam->u = u;
    cam->v = v;
    cam->w = w;
    cam->fwd = vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    cam->focal = NUM_ONE;
    cam->step_u = numw_from(NUM_ZERO);
    cam->step_v = numw_from(NUM_ZERO);

    if (kind == CAM_PERSPECTIVE) {
        if (!(fov_deg > NUM_ZERO && fov_deg < NUM(180)))
            return CAM_ERR_FOV;
        num_t cot = num_cot_deg(num_half(fov_deg));
        /* Just below 180 degrees the Q16.16 cotangent rounds to 0 and the
         * forward vector would vanish: no usable rays. */
        if (!(cot > NUM_ZERO))
            return CAM_ERR_FOV;
        /* |fwd| = H cot(fov/2) must fit Q16.16 in every build, so that all
         * three builds accept the same scenes. */
        if (cot > num_div(NUM(32767), num_from_int(height)))
            return CAM_ERR_NARROW;
        cam->focal = num_mul_int(cot, height);
        cam->fwd = vec3_scale(w, num_neg(cam->focal));
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
            cam->step_u = numw_muldiv_int(scale, width, 2 * height * (width - 1));
        if (height > 1)
            cam->step_v = numw_muldiv_int(scale, 1, 2 * (height - 1));
    }
    return CAM_OK;
}

void cam_ray(const cam_t *cam, int32_t x, int32_t y, ray_t *ray)
{
    int32_t ix = 2 * x - cam->width + 1;
    int32_t iy = 2 * y - cam->height + 1;
    if (cam->kind == CAM_PERSPECTIVE) {
#if FXRT_NUMBER == FXRT_Q16
        /* |r| may exceed the Q16.16 range (up to sqrt(32767^2 + 2 * 4095^2)):
         * form it in 64 bits and halve it when needed (only the direction
         * matters). */
        int64_t c[3] = {(int64_t)cam->fwd.x + (int64_t)cam->u.x * ix + (int64_t)cam->v.x * iy,
                        (int64_t)cam->fwd.y + (int64_t)cam->u.y * ix + (int64_t)cam->v.y * iy,
                        (int64_t)cam->fwd.z + (int64_t)cam->u.z * ix + (int64_t)cam->v.z * iy};
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
        vec3_normalize(&ray->d); /* r is never zero: |fwd| > 0 and u, v, w are orthogonal */
    } else {
        num_t ou = numw_round(numw_mul_int(cam->step_u, ix));
        num_t ov = numw_round(numw_mul_int(cam->step_v, iy));
        ray->o = vec3_add(cam->e, vec3_add(vec3_scale(cam->u, ou), vec3_scale(cam->v, ov)));
        ray->d = vec3_neg(cam->w);
    }
}
