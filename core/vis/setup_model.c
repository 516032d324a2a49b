/* setup_model: a model's bounds and depth range for the frame's camera:
 * those of its box in the world (its forms are rays: vis/model.c). */
#include "vis/setup.h"

#if FXRT_MAX_MODELS > 0
void render_setup_model(vis_t *r, rext_t ext, const geom_model_t *g, render_obj_t *o)
{
    (void)ext;
    o->kind = RENDER_RAYS;
    o->nflat = 0;
    vec3_t v[8];
    for (int c = 0; c < 8; c++)
        v[c] = render_to_cam(r->cam, vec3_make((c & 1) ? g->hi.x : g->lo.x, (c & 2) ? g->hi.y : g->lo.y,
                                               (c & 4) ? g->hi.z : g->lo.z));
    render_points_bounds(r->cam, v, 8, o);
}
#endif
