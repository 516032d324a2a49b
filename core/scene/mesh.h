/* mesh: which triangles of a world form closed meshes, worked out once
 * when the triangles are added (world_add_triangle), so that a frame's
 * set-up (render_cull_meshes in vis/cull.c) only has to ask
 * which of a closed mesh's triangles face away from the eye.
 *
 * "Closed mesh": a connected set of triangles (sharing edges with the
 * exact same vertices) in which every directed edge a -> b is matched by
 * exactly one b -> a of another triangle and none appears twice, whose
 * edges are all convex (each neighbour's far vertex on the inner side of
 * a triangle's plane, or on it: no self-intersection). Per triangle the
 * world keeps a union-find parent (its component) and the bits below:
 * both depend on the triangles alone, never on the camera.
 */
#ifndef FXRT_MESH_H
#define FXRT_MESH_H

#include "scene/kinds.h"

#define MESH_EDGES 0x07u /* matched edges (saturating at 7) */
#define MESH_POS 0x08u   /* a neighbour's far vertex on the positive side */
#define MESH_NEG 0x10u   /* ... on the negative side */
#define MESH_BAD 0x20u   /* degenerate, or a directed edge twice */
#define MESH_FLAT 0x40u  /* ... on its plane (within mesh_side's flat margin) */

#if FXRT_NUMBER == FXRT_Q16
typedef fx128_t mesh_vol_t;
#define MESH_VOL_ZERO fx128_from64(0)
static inline int mesh_vol_sign(const mesh_vol_t *v) { return v->hi < 0 ? -1 : (v->hi == 0 && v->lo == 0 ? 0 : 1); }
#else
typedef num_t mesh_vol_t;
#define MESH_VOL_ZERO NUM_ZERO
static inline int mesh_vol_sign(const mesh_vol_t *v) { return *v < 0 ? -1 : (*v > 0 ? 1 : 0); }
#endif

/* The side of p against the plane of (a, b, c): the sign of
 * d = det[b - a, c - a, p - a] (positive on the side (b - a) x (c - a)
 * points to), d added to *acc (NULL: not wanted). With flat, 0 also where
 * |d| is at most 2^-13 of |b - a x c - a| |p - a| (an angle of about
 * 10^-4: a dihedral that rounding of the vertices may have bent either
 * way). Q16.16: exact (coordinates within FXRT_COORD_LIMIT, 2^13:
 * differences below 2^31, cross products below 2^62, d in 128 bits).
 * Float and double: in num_t, and 0 where its rounding could decide the
 * sign. */
int mesh_side(const vec3_t *a, const vec3_t *b, const vec3_t *c, const vec3_t *p, mesh_vol_t *acc, bool flat);

/* Triangle j of t[0..j] joins the meshes of t[0..j-1]: its bits, its
 * matched edges with each earlier triangle (which adds to both sides'
 * bits) and the union of their components in up[]. */
void mesh_link(const geom_triangle_t *t, uint16_t j, uint8_t *up, uint8_t *bits);

/* The component (root) of triangle i, without changing up[]. */
static inline uint8_t mesh_root(const uint8_t *up, uint8_t i)
{
    while (up[i] != i)
        i = up[i];
    return i;
}

#endif
