/* cull: the back faces of closed meshes, left out of a frame.
 *
 * A ray from an eye outside a closed surface enters it before it can leave
 * it, and it leaves through the triangles that face away from the eye: a
 * triangle whose plane has the eye on its inner side is never the first
 * hit (except where it ties with the front face it meets on a silhouette
 * edge). So such triangles of a closed mesh (scene/mesh.h; the world links
 * them as they are added) are left out of the frame: of a mesh that is
 * closed, convex, whose outside is known, and seen in perspective from
 * outside its bounding box. Both loops (fast and reference) and every
 * number type use the same objects, so they still agree. Per frame: one
 * exact side test per triangle of a closed mesh (the eye's), and a second
 * only in a mesh with an edge within mesh_side's flat margin (its volume). */
#include "vis/setup.h"

#if RENDER_MESH
/* The side of component k's triangles (mesh.h) that the sum of the sides
 * of one of its vertices takes: -1, 0 or 1. For a closed mesh this is the
 * sign of its signed volume. */
static int render_mesh_volume(const world_t *w, uint16_t k)
{
    mesh_vol_t vol = MESH_VOL_ZERO;
    const vec3_t *ref = &w->triangles[k].a;
    for (uint16_t i = 0; i < w->n_triangles; i++) {
        const geom_triangle_t *t = &w->triangles[i];
        if (mesh_root(w->mesh_up, (uint8_t)i) == k)
            (void)mesh_side(&t->a, &t->b, &t->c, ref, &vol, false);
    }
    return mesh_vol_sign(&vol);
}

void render_cull_meshes(vis_t *r)
{
    const world_t *w = r->world;
    uint16_t n = w->n_triangles;
    const uint8_t *up = w->mesh_up, *bits = w->mesh_bits;
    for (uint16_t i = 0; i < (FXRT_MAX_TRIANGLES + 7) / 8; i++)
        r->mesh_culled[i] = 0;
    if (n < 4 || n > FXRT_MESH_MAX || w->mesh_n != n || render_ortho(r->cam))
        return;
    const vec3_t *e = &r->cam->e;
    for (uint16_t k = 0; k < n; k++) {
        if (up[k] != k || (bits[k] & MESH_EDGES) != 3)
            continue; /* not a root, or its own edges are not matched once each */
        /* One component: closed, convex, its outside, its bounding box. */
        bool closed = true;
        uint8_t sides = 0;
        vec3_t lo = w->triangles[k].a, hi = lo;
        for (uint16_t i = 0; i < n && closed; i++) {
            if (mesh_root(up, (uint8_t)i) != k)
                continue;
            const geom_triangle_t *t = &w->triangles[i];
            closed = (bits[i] & (MESH_EDGES | MESH_BAD)) == 3;
            sides |= bits[i] & (MESH_POS | MESH_NEG | MESH_FLAT);
            const vec3_t *v[3] = {&t->a, &t->b, &t->c};
            for (int m = 0; m < 3; m++) {
                lo = vec3_make(num_min(lo.x, v[m]->x), num_min(lo.y, v[m]->y), num_min(lo.z, v[m]->z));
                hi = vec3_make(num_max(hi.x, v[m]->x), num_max(hi.y, v[m]->y), num_max(hi.z, v[m]->z));
            }
        }
        /* The outside. Where every neighbour's far vertex lies strictly on
         * one side of each triangle's plane, that side is the inner one: the
         * mesh is the boundary of a convex body, which holds its vertices.
         * Otherwise (an edge within mesh_side's flat margin) the signed
         * volume decides: a reference point on the inner side of every face
         * of an outward-wound mesh makes the sum of sides negative. */
        int out = sides == MESH_NEG ? -1 : (sides == MESH_POS ? 1 : 0);
        if (closed && out == 0 && !(sides & MESH_POS && sides & MESH_NEG))
            out = render_mesh_volume(w, k);
        bool outside = e->x < lo.x || e->x > hi.x || e->y < lo.y || e->y > hi.y || e->z < lo.z || e->z > hi.z;
        uint8_t convex = out < 0 ? MESH_POS : MESH_NEG; /* the side no far vertex may be on */
        if (!closed || out == 0 || (sides & convex) || !outside)
            continue;
        for (uint16_t i = 0; i < n; i++) {
            if (mesh_root(up, (uint8_t)i) != k)
                continue;
            const geom_triangle_t *t = &w->triangles[i];
            if (mesh_side(&t->a, &t->b, &t->c, e, NULL, false) == out) /* the eye on its inner side */
                r->mesh_culled[i >> 3] |= (uint8_t)(1u << (i & 7));
        }
    }
}
#endif
