/* raycast: one camera ray and one nearest-hit search per pixel. */
#include "raycast.h"
#include "shade.h"

void raycast_row(const world_t *w, const cam_t *cam, int32_t row, uint8_t *rgb, uint16_t *ids)
{
    int32_t y = cam->height - 1 - row;
    for (int32_t x = 0; x < cam->width; x++) {
        ray_t ray;
        hit_t hit;
        cam_ray(cam, x, y, &ray);
        bool found = world_hit(w, &ray, &hit);
        rgb8_t c = found ? hit.obj->rgb : w->background_rgb;
#if FXRT_MAX_LIGHTS > 0
        if (found && hit.obj->mat.kind != MATERIAL_FLAT)
            c = color_to_rgb8(shade_object(w, hit.kind, hit.index, &ray, NULL));
#endif
        rgb[3 * x + 0] = c.r;
        rgb[3 * x + 1] = c.g;
        rgb[3 * x + 2] = c.b;
        if (ids)
            ids[x] = found ? hit.obj->id : (uint16_t)RAYCAST_MISS;
    }
}
