/* render: a frame's set-up and rows (the visibility pass, then the shading
 * or sampling pass) and the colour along an arbitrary ray. */
#include "frame/render.h"
#include "vis/render_int.h"

#if FXRT_MAX_SAMPLES > 1
/* One sample of colour c, clamped, in the sampling pass's sum units. */
static void render_sum_one(color_sum_t one[3], color_t c)
{
    one[0] = one[1] = one[2] = 0;
    color_sum_add(&one[0], c.r, 1);
    color_sum_add(&one[1], c.g, 1);
    color_sum_add(&one[2], c.b, 1);
}
#endif

bool render_setup(render_t *r, const world_t *w, const cam_t *cam)
{
    r->error = NULL;
    r->keys = NULL;
#if FXRT_MAX_SAMPLES > 1
    /* Supersampling: the forms and bounds are those of the fine camera. */
    render_sample_t *s = &r->sample;
    s->samples = (uint8_t)world_samples(w);
    s->adaptive = world_adaptive(w);
    s->out_cam = cam;
    if (s->samples > 1) {
        if (cam->width > FXRT_RENDER_MAX_WIDTH / s->samples) {
            r->error = "samples x width wider than FXRT_RENDER_MAX_WIDTH";
            return false;
        }
        if (cam_fine(cam, s->samples, &s->fine) != CAM_OK) {
            r->error = "samples x height beyond FXRT_MAX_DIM, or samples x height x cot(fov/2) beyond 32767";
            return false;
        }
        cam = &s->fine;
        render_sum_one(s->bg_one, w->background);
#if FXRT_ADAPTIVE
        s->arow[0] = s->arow[1] = s->arow[2] = -1;
#endif
#if RENDER_RUNS
        s->run_cap = FXRT_SAMPLE_RUNS;
        s->run_rows = 0;
#endif
    }
#endif
    r->error = render_vis_setup(&r->vis, w, cam);
#if FXRT_MAX_SAMPLES > 1
    if (s->samples > 1)
        for (uint16_t i = 0; i < r->vis.count; i++)
            render_sum_one(s->one[i], world_common(w, (geom_kind_t)r->vis.obj[i].geom, r->vis.obj[i].index)->color);
#endif
#if FXRT_MAX_LIGHTS > 0
    render_shade_t *sh = &r->shade;
    sh->any_lit = w->n_lit > 0;
#if SHADOW_CULL
    if (sh->any_lit)
        shadow_cull_setup(w, sh->cull);
#endif
    for (uint16_t i = 0; sh->any_lit && i < r->vis.count; i++) {
        const geom_common_t *c = world_common(w, (geom_kind_t)r->vis.obj[i].geom, r->vis.obj[i].index);
        if (c->mat.kind != MATERIAL_FLAT) {
            shade_consts(w, c, &sh->k[i]);
#if SHADOW_CULL
            sh->k[i].cull = sh->cull;
#endif
        }
    }
#endif
    return r->error == NULL;
}

void render_row_reference(render_t *r, int32_t row, uint8_t *rgb)
{
#if FXRT_MAX_SAMPLES > 1
    if (r->sample.samples > 1) {
        render_sample_row(r, row, rgb, true);
        return;
    }
#endif
    render_row_reference_vis(&r->vis, row, rgb);
#if FXRT_MAX_LIGHTS > 0
    if (render_tracks(&r->vis))
        render_shade_row(r, row, rgb);
#endif
}

void render_row(render_t *r, int32_t row, uint8_t *rgb)
{
#if FXRT_MAX_SAMPLES > 1
    if (r->sample.samples > 1) {
        render_sample_row(r, row, rgb, false);
        return;
    }
#endif
    render_row_vis(&r->vis, row, rgb);
#if FXRT_MAX_LIGHTS > 0
    if (render_tracks(&r->vis))
        render_shade_row(r, row, rgb);
#endif
}

/* ---- arbitrary rays ------------------------------------------------------ */

rgb8_t render_pixel(const world_t *w, const ray_t *ray)
{
    hit_t hit;
    if (!world_hit(w, ray, &hit))
        return w->background_rgb;
    if (FXRT_MAX_LIGHTS > 0 && geom_lit(hit.obj))
        return color_to_rgb8(shade_object(w, hit.kind, hit.index, ray, NULL));
    return hit.obj->rgb;
}
