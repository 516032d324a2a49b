/* rays: the visibility pass of an object of the RAYS form (a model, an
 * ellipsoid, a parallelepiped): over the columns of its bounds on a row
 * (a model's: of its footprint, set up here), each pixel's camera ray
 * meets it (render_rays_at, vis/depth.c); a hit claims the column at its
 * depth. */
#include "vis/paint.h"
#include "vis/setup.h"

#if RENDER_RAY_KINDS
/* A model's footprint (r->model_cut): the bounds of the nodes of its cut,
 * each a box's as render_setup_rays makes them (one whose box fails: the
 * model's). */
FXRT_IF_MODEL(void render_setup_cut(vis_t *r, const render_obj_t *o) {
    const geom_model_t *g = &r->world->models[o->index];
    render_rect_t *rc = r->model_cut[o->index];
    uint32_t node[RENDER_CUT];
    int n = geom_model_cut(g, node, RENDER_CUT);
    for (int k = 0; k < RENDER_CUT; k++) {
        render_obj_t b = *o;
        vec3_t lo, hi;
        if (k >= n)
            render_set_empty(&b);
        else if (geom_model_cut_box(g, node[k], &lo, &hi))
            render_setup_rays(r, lo, hi, &b);
        rc[k] = (render_rect_t){b.x0, b.x1, b.r0, b.r1};
    }
})

void render_scan_rays(vis_t *r, uint16_t oi, int32_t x0, int32_t x1, int32_t iy, uint8_t *rgb, bool lone)
{
    /* A model: only the columns of its footprint's bounds that hold the
     * row (render_setup_cut), from the first to the last. */
    FXRT_IF_MODEL(if (!FXRT_NO_BOUNDS && r->obj[oi].geom == GEOM_MODEL) {
        const render_rect_t *rc = r->model_cut[r->obj[oi].index];
        int32_t row = render_row_of(r->cam, iy), lo = x1 + 1, hi = x0 - 1;
        for (int k = 0; k < RENDER_CUT; k++)
            if (row >= rc[k].r0 && row <= rc[k].r1 && rc[k].x0 <= rc[k].x1) {
                lo = rc[k].x0 < lo ? rc[k].x0 : lo;
                hi = rc[k].x1 > hi ? rc[k].x1 : hi;
            }
        x0 = lo > x0 ? lo : x0;
        x1 = hi < x1 ? hi : x1;
    })
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
