/* raycast: one camera ray and one nearest-hit search per pixel. */
#include "frame/raycast.h"
#include "light/shade.h"

#if FXRT_MAX_SAMPLES > 1
/* samples N > 1: the N x N rays of each pixel (the fine camera's pixels,
 * cam_fine), each colour clamped, averaged, rounded (color_sum_*). */
static void raycast_row_samples(const world_t *w, const cam_t *cam, int32_t row, uint8_t *rgb, uint16_t *ids)
{
    int32_t n = world_samples(w);
    cam_t fine;
    if (cam_fine(cam, n, &fine) != CAM_OK) {
        for (int32_t i = 0; i < 3 * cam->width; i++)
            rgb[i] = 0; /* render_setup refuses this frame; the caller was told there */
        return;
    }
    int32_t y0 = (cam->height - 1 - row) * n;
    for (int32_t x = 0; x < cam->width; x++) {
        color_sum_t a[3] = {0, 0, 0};
        for (int32_t j = 0; j < n; j++)
            for (int32_t i = 0; i < n; i++) {
                ray_t ray;
                hit_t hit;
                cam_ray_raw(&fine, x * n + i, y0 + j, &ray);
                ray_t unit = ray;
                cam_ray_unit(&fine, &unit);
                color_t c = w->background;
                if (world_hit(w, &unit, &hit)) {
                    c = hit.obj->color;
                    if (FXRT_MAX_LIGHTS > 0 && geom_lit(hit.obj))
                        c = shade_object(w, hit.kind, hit.index, &ray, &fine, NULL);
                }
                color_sum_add(&a[0], c.r, 1);
                color_sum_add(&a[1], c.g, 1);
                color_sum_add(&a[2], c.b, 1);
            }
        uint32_t n2 = (uint32_t)(n * n);
        rgb[3 * x + 0] = color_sum_out(a[0], n2);
        rgb[3 * x + 1] = color_sum_out(a[1], n2);
        rgb[3 * x + 2] = color_sum_out(a[2], n2);
        if (ids)
            ids[x] = (uint16_t)RAYCAST_MISS; /* ids are one-sample data */
    }
}
#endif

void raycast_row(const world_t *w, const cam_t *cam, int32_t row, uint8_t *rgb, uint16_t *ids)
{
    FXRT_IF_SAMPLES(if (world_samples(w) > 1) {
        raycast_row_samples(w, cam, row, rgb, ids);
        return;
    })
    int32_t y = cam->height - 1 - row;
    for (int32_t x = 0; x < cam->width; x++) {
        ray_t ray;
        hit_t hit;
        cam_ray_raw(cam, x, y, &ray);
        ray_t unit = ray;
        cam_ray_unit(cam, &unit);
        bool found = world_hit(w, &unit, &hit);
        rgb8_t c = found ? hit.obj->rgb : w->background_rgb;
        if (FXRT_MAX_LIGHTS > 0 && found && geom_lit(hit.obj))
            c = color_to_rgb8(shade_object(w, hit.kind, hit.index, &ray, cam, NULL));
        rgb[3 * x + 0] = c.r;
        rgb[3 * x + 1] = c.g;
        rgb[3 * x + 2] = c.b;
        if (ids)
            ids[x] = found ? hit.obj->id : (uint16_t)RAYCAST_MISS;
    }
}
