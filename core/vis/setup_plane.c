/* setup_plane: a plane's forms (N, D), its rows and bounds for the
 * frame's camera. */
#include "vis/setup.h"

#if FXRT_MAX_PLANES > 0
/* Does plane f cover a pixel of the row of pixel offset iy? Along a row
 * N and D are linear, so their front test (one strict sign) holds on one
 * interval of columns, which is empty when it fails at both ends. */
__attribute__((noinline)) static bool render_plane_on_row(const cam_t *cam, const render_flat_t *f, int32_t iy)
{
    return render_flat_at(f, 1 - cam->width, iy) || render_flat_at(f, cam->width - 1, iy);
}

/* A plane's rows: those where it covers a pixel (render_plane_on_row),
 * exactly. One of N and D is constant (N in perspective, D in
 * orthographic views) and the other linear, with one slope down the rows
 * at both ends of a row, so the test holds at each end on a half-line of
 * rows pointing the same way, and on their union: a run of rows from the
 * top or the bottom, whose end a bisection finds. (A plane whose forms
 * both vary keeps every row.) */
static void render_plane_rows(const cam_t *cam, const render_flat_t *f, render_obj_t *o)
{
    if (!((f->n.x == 0 && f->n.y == 0) || (f->d.x == 0 && f->d.y == 0)))
        return;
    int32_t h = cam->height;
    bool top = render_plane_on_row(cam, f, h - 1), bottom = render_plane_on_row(cam, f, 1 - h);
    if (top && bottom)
        return;
    if (!top && !bottom) {
        render_set_empty(o);
        return;
    }
    int32_t lo = 0, hi = h - 1; /* rows: the test at lo is top's, at hi bottom's */
    while (hi - lo > 1) {
        int32_t mid = lo + (hi - lo) / 2;
        if (render_plane_on_row(cam, f, h - 1 - 2 * mid) == top)
            lo = mid;
        else
            hi = mid;
    }
    if (top)
        o->r1 = (int16_t)lo;
    else
        o->r0 = (int16_t)hi;
}

void render_setup_plane(vis_t *r, rext_t ext, const geom_plane_t *p, render_obj_t *o)
{
    o->kind = RENDER_FLAT;
    o->nflat = 1;
    render_flat_nd(r->cam, ext, render_dir_to_cam(r->cam, p->n), render_to_cam(r->cam, p->a), render_face(o, 0));
    render_set_full(r->cam, o);
    if (!render_flat_eye(r->cam, p->a, p->n, render_face(o, 0)))
        render_set_empty(o); /* the eye on the plane */
    else
        render_plane_rows(r->cam, render_face(o, 0), o); /* rows beyond the horizon left out */
}
#endif
