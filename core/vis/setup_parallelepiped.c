/* setup_parallelepiped: a parallelepiped's bounds and depth range for the
 * frame's camera: those of its box in the world (its form is rays:
 * vis/rays.c). */
#include "vis/setup.h"

#if FXRT_MAX_PARALLELEPIPEDS > 0
void render_setup_parallelepiped(vis_t *r, rext_t ext, const geom_parallelepiped_t *g, render_obj_t *o)
{
    (void)ext;
    vec3_t lo, hi;
    geom_parallelepiped_bounds(g, &lo, &hi);
    render_setup_rays(r, lo, hi, o);
}
#endif
