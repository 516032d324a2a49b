/* render: a frame's rows, the visibility pass then the shading or
 * sampling pass, and the colour along an arbitrary ray. */
#include "vis/render_int.h"
#include "light/shade.h"

void render_row_reference(render_t *r, int32_t row, uint8_t *rgb)
{
#if FXRT_MAX_SAMPLES > 1
    if (r->samples > 1) {
        render_sample_row(r, row, rgb, true);
        return;
    }
#endif
    render_row_reference_vis(r, row, rgb);
#if FXRT_MAX_LIGHTS > 0
    if (render_tracks(r))
        render_shade_row(r, row, rgb);
#endif
}

void render_row(render_t *r, int32_t row, uint8_t *rgb)
{
#if FXRT_MAX_SAMPLES > 1
    if (r->samples > 1) {
        render_sample_row(r, row, rgb, false);
        return;
    }
#endif
    render_row_vis(r, row, rgb);
#if FXRT_MAX_LIGHTS > 0
    if (render_tracks(r))
        render_shade_row(r, row, rgb);
#endif
}

/* ---- arbitrary rays ------------------------------------------------------ */

rgb8_t render_pixel(const world_t *w, const ray_t *ray)
{
    hit_t hit;
    if (!world_hit(w, ray, &hit))
        return w->background_rgb;
#if FXRT_MAX_LIGHTS > 0
    if (hit.obj->mat.kind != MATERIAL_FLAT)
        return color_to_rgb8(shade_object(w, hit.kind, hit.index, ray, NULL));
#endif
    return hit.obj->rgb;
}
