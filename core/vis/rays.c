/* rays: the visibility pass of an object of the RAYS form (a model, an
 * ellipsoid, a parallelepiped): over the columns of its bounds on a row, each pixel's camera
 * ray meets it (render_rays_at, vis/depth.c); a hit claims the column at
 * its depth. */
#include "vis/paint.h"

#if RENDER_RAY_KINDS
void render_scan_rays(vis_t *r, uint16_t oi, int32_t x0, int32_t x1, int32_t iy, uint8_t *rgb, bool lone)
{
    for (int32_t x = x0, ix = 2 * x0 - r->cam->width + 1; x <= x1; x++, ix += 2) {
        render_depth_t t;
        uint32_t tri;
        if (!render_rays_at(r, oi, ix, iy, &t, &tri))
            continue;
        if (lone)
            render_paint(r, oi, x, rgb);
        else
            RENDER_COVER(r, oi, x, rgb, render_resolve_depth(r, cur_, oi, x, iy, t));
        FXRT_IF_MODEL(if (render_painter(r, x) == oi) /* (RENDER_VIS_NONE where no pass reads it) */
                          render_model_tri(r, x, tri);)
        (void)tri;
    }
}
#endif
