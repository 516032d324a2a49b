/* reference: the visibility pass as a straightforward loop, every
 * object's forms evaluated at every pixel (render_row_reference). */
#include "vis/paint.h"

void render_row_reference_vis(vis_t *r, int32_t row, uint8_t *rgb)
{
    int32_t w = r->cam->width, y = r->cam->height - 1 - row;
    int32_t iy = 2 * y - r->cam->height + 1;
    render_begin_row(r, rgb);
    r->row_win = 0;
    for (int32_t x = 0; x < w; x++) {
        int32_t ix = 2 * x - w + 1;
        for (uint16_t i = 0; i < r->count; i++) {
            if (FXRT_NO_HOIST)
                render_setup_object(r, i);
            if (RENDER_RAY_KINDS && render_kind(&r->obj[i]) == RENDER_RAYS)
                render_scan_rays(r, i, x, x, iy, rgb, false);
            else if (render_covers(&r->obj[i], ix, iy))
                render_cover(r, i, x, iy, rgb);
        }
    }
}
