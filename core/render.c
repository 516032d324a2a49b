/* render: scanlines of primary rays. */
#include "render.h"

rgb8_t render_pixel(const world_t *w, const ray_t *ray)
{
    hit_t hit;
    if (world_hit(w, ray, &hit))
        return hit.obj->rgb;
    return w->background_rgb;
}

void render_row(const world_t *w, const cam_t *cam, int32_t row, uint8_t *rgb)
{
    int32_t y = cam->height - 1 - row; /* the seed counts rows from the bottom */
    for (int32_t x = 0; x < cam->width; x++) {
        ray_t ray;
        cam_ray(cam, x, y, &ray);
        rgb8_t c = render_pixel(w, &ray);
        rgb[3 * x + 0] = c.r;
        rgb[3 * x + 1] = c.g;
        rgb[3 * x + 2] = c.b;
    }
}
