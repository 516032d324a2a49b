/* render: a frame's set-up and rows (the visibility pass, then the shading
 * or sampling pass) and the colour along an arbitrary ray. */
#include "frame/render.h"
#include "vis/render_int.h"

bool render_setup(render_t *r, const world_t *w, const cam_t *cam)
{
    r->error = NULL;
    r->keys = NULL;
    /* Supersampling: the forms and bounds are those of the fine camera. */
    if (FXRT_MAX_SAMPLES > 1 && !render_sample_setup(r, w, &cam))
        return false;
    r->error = render_vis_setup(&r->vis, w, cam);
    if (FXRT_MAX_SAMPLES > 1)
        render_sample_objects(r, w);
    if (FXRT_MAX_LIGHTS > 0)
        render_shade_setup(r, w);
    return r->error == NULL;
}

void render_row_reference(render_t *r, int32_t row, uint8_t *rgb)
{
    if (FXRT_MAX_SAMPLES > 1 && render_sampled(r)) {
        render_sample_row(r, row, rgb, true);
        return;
    }
    render_row_reference_vis(&r->vis, row, rgb);
    if (FXRT_MAX_LIGHTS > 0 && render_tracks(&r->vis))
        render_shade_row(r, row, rgb);
}

void render_row(render_t *r, int32_t row, uint8_t *rgb)
{
    if (FXRT_MAX_SAMPLES > 1 && render_sampled(r)) {
        render_sample_row(r, row, rgb, false);
        return;
    }
    render_row_vis(&r->vis, row, rgb);
    if (FXRT_MAX_LIGHTS > 0 && render_tracks(&r->vis))
        render_shade_row(r, row, rgb);
}

/* ---- arbitrary rays ------------------------------------------------------ */

rgb8_t render_pixel(const world_t *w, const ray_t *ray)
{
    hit_t hit;
    if (!world_hit(w, ray, &hit))
        return w->background_rgb;
    if (FXRT_MAX_LIGHTS > 0 && geom_lit(hit.obj)) {
        ray_t u = *ray; /* (shade_object may normalise its ray in place; this one is unit) */
        return color_to_rgb8(shade_object(w, hit.kind, hit.index, &u, NULL, NULL));
    }
    return hit.obj->rgb;
}
