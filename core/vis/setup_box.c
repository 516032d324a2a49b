/* setup_box: a box's faces (each a flat piece with four edges, from the
 * box-face pool), bounds and depth range for the frame's camera. */
#include "vis/setup.h"

#if FXRT_MAX_BOXES > 0
void render_setup_box(vis_t *r, rext_t ext, const geom_box_t *b, render_obj_t *o)
{
    const cam_t *cam = r->cam;
    bool ortho = render_ortho(cam);
    vec3_t corner[8]; /* bit i of the index: max on axis i */
    for (int i = 0; i < 8; i++)
        corner[i] = render_to_cam(cam, vec3_make((i & 1) ? b->max.x : b->min.x, (i & 2) ? b->max.y : b->min.y,
                                                 (i & 4) ? b->max.z : b->min.z));
    /* A ray covers the box when it crosses one of its faces at t > 0 (the
     * entry face from outside, the exit face from inside), so the box's
     * coverage is the union of its faces' coverage, each with its own
     * front test. A perspective eye strictly outside can only reach the
     * faces turned towards it; strictly inside, every ray hits. */
    bool inside = !ortho, outside = false;
    int side_of[3];
    for (int axis = 0; axis < 3; axis++) {
        num_t e = geom_axis(cam->e, axis);
        num_t lo = geom_axis(b->min, axis), hi = geom_axis(b->max, axis);
        if (!(e > lo && e < hi))
            inside = false;
        side_of[axis] = e < lo ? 0 : (e > hi ? 1 : -1);
        if (side_of[axis] >= 0)
            outside = true;
    }
    o->kind = RENDER_BOX;
    o->nflat = 0;
    unsigned used = 0; /* bit i: corner i belongs to a face set up */
    rproj_t proj[8]; /* corner i's projection, once bit i of have is set */
    uint8_t have = 0;
    for (int axis = 0; axis < 3; axis++) {
        int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
        /* A face of zero area (a flat box seen from its side) covers
         * nothing: its edge forms would describe a line or the whole
         * screen instead. */
        if (geom_axis(b->min, a1) == geom_axis(b->max, a1) || geom_axis(b->min, a2) == geom_axis(b->max, a2))
            continue;
        for (int side = 0; side < 2; side++) {
            if (!ortho && outside && side != side_of[axis])
                continue; /* turned away from an eye outside */
            if ((ortho || !outside) && side == 1 && geom_axis(b->min, axis) == geom_axis(b->max, axis))
                continue; /* a flat box: both faces are one rectangle, keep one */
            if (!ortho && geom_axis(cam->e, axis) == geom_axis(side ? b->max : b->min, axis))
                continue; /* the eye on this face's plane: no ray crosses it at t > 0 (the
                           * kernels' rule; rays that leave the box at once miss it) */
            vec3_t nw = vec3_make(axis == 0 ? NUM_ONE : NUM_ZERO, axis == 1 ? NUM_ONE : NUM_ZERO,
                                  axis == 2 ? NUM_ONE : NUM_ZERO);
            if (side == 0)
                nw = vec3_neg(nw);
            vec3_t nc = render_dir_to_cam(cam, nw);
            if (ortho && nc.z == NUM_ZERO)
                continue; /* parallel to every ray */
            /* The face's four corners, in order around it. */
            int base = side << axis;
            uint8_t idx[4] = {(uint8_t)base, (uint8_t)(base | (1 << a1)), (uint8_t)(base | (1 << a1) | (1 << a2)),
                              (uint8_t)(base | (1 << a2))};
            for (int k = 0; k < 4; k++)
                used |= 1u << idx[k];
            if (o->u.face + o->nflat >= r->box_faces + FXRT_RENDER_BOX_FACES) {
                r->error = "more box faces than FXRT_RENDER_BOX_FACES";
                continue;
            }
            render_face_t *bf = &o->u.face[o->nflat++];
            render_flat_t *f = &bf->f;
            render_flat_nd(cam, ext, nc, corner[idx[0]], f);
            for (int k = 0; k < 4; k++)
                render_edge(k < 3 ? &f->e[k] : &bf->e4, cam, ext, corner[idx[k]], corner[idx[(k + 1) % 4]]);
            f->edges = 4;
            /* Each face gets its own bounds, so a pixel is mostly stepped
             * for one face rather than all of them; each corner is
             * projected once for the faces and the box. */
            render_obj_t tmp;
            render_idx_bounds(cam, corner, idx, 4, proj, &have, &tmp);
            render_face_bounds_from(bf, &tmp);
        }
    }
    if (inside) {
        /* Every ray covers the box; its faces (all of them, from inside)
         * give the depth of the exit point. */
        o->kind = RENDER_INSIDE_BOX;
        render_set_full(cam, o);
        return;
    }
    if (o->nflat == 0) {
        render_set_empty(o);
        return;
    }
    /* Bounds and depth range of the faces set up: from outside in
     * perspective the front faces, whose corners leave out the far ones. */
    uint8_t pidx[8];
    int n = 0;
    for (int i = 0; i < 8; i++)
        if (used & (1u << i))
            pidx[n++] = (uint8_t)i;
    render_set_zrange(cam, corner, pidx, n, o);
    render_idx_bounds(cam, corner, pidx, n, proj, &have, o);
}
#endif
