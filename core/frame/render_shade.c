/* render_shade: the shading pass. The visibility pass (vis/) leaves in r->vis the object that owns each column of the
 * row; here each pixel owned by a lit object gets its colour from the
 * lighting model (light/shade.c): the pixel's camera ray (cam_ray), the
 * owner's surface point and normal (geom_<kind>_surface: one object, no
 * search; a model's from the triangle its visibility pass met), and the
 * light sum. Flat objects keep the colour the visibility
 * pass painted. With r->keys set, every pixel's key is written too. */
#include "frame/render.h"
#include "vis/render_int.h"

#if FXRT_MAX_LIGHTS > 0
void render_shade_setup(render_t *r, const world_t *w)
{
    render_shade_t *sh = &r->shade;
    sh->any_lit = w->n_lit > 0;
    SHADE_IF_CULL(if (sh->any_lit) shadow_cull_setup(w, sh->cull.cull); shadow_rows_clear(&sh->cull);)
    for (uint16_t i = 0; sh->any_lit && i < r->vis.count; i++) {
        const geom_common_t *c = world_common(w, (geom_kind_t)r->vis.obj[i].geom, r->vis.obj[i].index);
        if (c->mat.kind != MATERIAL_FLAT) {
            shade_consts(w, c, &sh->k[i]);
            SHADE_IF_CULL(sh->k[i].cull = &sh->cull;)
        }
    }
}

void render_shade_row(render_t *r, int32_t row, uint8_t *rgb)
{
    const cam_t *cam = r->vis.cam;
    int32_t w = cam->width, y = cam->height - 1 - row;
    /* The row's shadow masks for planes (light/shade.h), cleared after it:
     * they hold for this row's camera rays only. */
    SHADE_IF_CULL(if (SHADOW_ROWS && r->shade.any_lit) shadow_rows_setup(r->vis.world, cam, y, &r->shade.cull);)
    for (int32_t x = 0; x < w; x++) {
        uint16_t oi = r->vis.painted[x];
        if (oi == RENDER_VIS_NONE) {
            if (r->keys)
                r->keys[x] = RENDER_KEY_MISS;
            continue;
        }
        const render_obj_t *o = &r->vis.obj[oi];
        bool lit = !o->flat;
        if (!lit && !r->keys)
            continue;
        ray_t ray;
        uint8_t mask = 0;
        cam_ray(cam, x, y, &ray);
        color_t c;
        FXRT_IF_MODEL(if (o->geom == GEOM_MODEL) /* its triangle: the visibility pass's (vis/rays.c) */
                      c = shade_model_k(r->vis.world, o->index, &ray, r->vis.model_tri[x], lit ? &r->shade.k[oi] : NULL,
                                        r->keys ? &mask : NULL);
                      else)
        c = shade_object_k(r->vis.world, (geom_kind_t)o->geom, o->index, &ray, lit ? &r->shade.k[oi] : NULL,
                           r->keys ? &mask : NULL);
        if (r->keys)
            r->keys[x] = render_key(o->id, mask);
        if (!lit)
            continue;
        rgb8_t p = color_to_rgb8(c);
        render_put_pixel(rgb, x, p);
    }
    SHADE_IF_CULL(if (SHADOW_ROWS && r->shade.any_lit) shadow_rows_clear(&r->shade.cull);)
}
#endif
