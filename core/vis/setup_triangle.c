/* setup_triangle: a triangle's forms (N, D and three edge forms), bounds
 * and depth range for the frame's camera. */
#include "vis/setup.h"

#if FXRT_MAX_TRIANGLES > 0
void render_setup_triangle(vis_t *r, rext_t ext, const geom_triangle_t *t, render_obj_t *o)
{
    const cam_t *cam = r->cam;
    o->kind = RENDER_FLAT;
    o->nflat = 1;
#if RENDER_MESH
    if (t->degenerate || render_mesh_culled(r, o->index)) { /* culled: a back face of a closed mesh */
#else
    if (t->degenerate) {
#endif
        o->nflat = 0;
        render_set_empty(o);
        return;
    }
    vec3_t v[3] = {render_to_cam(cam, t->a), render_to_cam(cam, t->b), render_to_cam(cam, t->c)};
    render_flat_t *f = render_face(o, 0);
    render_flat_nd(cam, ext, render_dir_to_cam(cam, t->n), v[0], f);
    for (int i = 0; i < 3; i++)
        render_edge(&f->e[i], cam, ext, v[i], v[(i + 1) % 3]);
    f->edges = 3;
    render_points_bounds(cam, v, 3, o);
    if (!render_flat_eye(cam, t->a, t->n, f))
        render_set_empty(o); /* the eye in the triangle's plane */
}
#endif
