/* setup_model: a model's bounds and depth range for the frame's camera:
 * those of its box in the world (its form is rays: vis/rays.c). */
#include "vis/setup.h"

#if FXRT_MAX_MODELS > 0
void render_setup_model(vis_t *r, rext_t ext, const geom_model_t *g, render_obj_t *o)
{
    (void)ext;
    render_setup_rays(r, g->lo, g->hi, o);
}
#endif
