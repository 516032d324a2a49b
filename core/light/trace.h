/* trace: secondary rays, reflection and refraction (issue 12), without
 * recursion.
 *
 * The colour seen along a ray is, at its nearest hit (material m, incoming
 * unit direction d, unit normal n turned towards the ray, e = -d):
 *   flat, lambert, phong   the local colour (core/shade.c)
 *   reflective             the Phong colour + c_r (.) trace(reflected)
 *   transparent            R trace(reflected) + (1 - R) c_d (.) trace(transmitted)
 *                          (no local term), or trace(reflected) alone under
 *                          total internal reflection
 * with reflected direction d - 2 (d.n) n; for glass the ratio q = 1/eta
 * entering (d . n_geometric < 0) and eta leaving, cos_i = -d.n,
 * cos2_t = 1 - q^2 (1 - cos_i^2) (< 0: total internal reflection),
 * transmitted direction q d + (q cos_i - cos_t) n, and Schlick's
 * R = R0 + (1 - R0)(1 - cos)^5, R0 = ((1 - eta)/(1 + eta))^2, cos = cos_i
 * entering and cos_t leaving. A miss sees the background.
 *
 * Bounces: the primary ray is bounce 0, a child has its parent's bounce + 1
 * and is traced only when that is at most the world's depth (else it
 * contributes black). A ray's weight is the product of the factors on its
 * path (c_r, R, (1 - R) c_d); a ray whose weight is below 1/512 in every
 * channel is not traced (black). Colours are summed unclamped; the
 * caller clamps the sample.
 *
 * No recursion: the tree is walked depth first with one explicit stack of
 * pending rays (origin, direction, weight, bounce and the medium: the
 * solid the ray travels inside, if any). A node pushes at most one sibling
 * and the entries on the stack have distinct bounces 1..depth, so
 * FXRT_MAX_DEPTH entries always suffice (asserted by construction: the
 * push is guarded).
 *
 * Self-intersection (no offset, no epsilon, as for shadow rays): a ray that
 * leaves a convex surface towards the side it came from, or any flat
 * surface, never meets that object again and does not test it; a ray that
 * goes into a solid (sphere, box) meets it only where it leaves it
 * (geom_<kind>_exit). Secondary rays use the world-space kernels; bounded
 * objects (spheres, triangles, boxes) are tested only when the ray meets
 * the sphere around their box (world_t.bc, br2, padded one unit; a
 * division-free test, FXRT_NO_BOUNDS turns it off).
 */
#ifndef FXRT_TRACE_H
#define FXRT_TRACE_H

#include "scene/world.h"

/* The colour of a primary (or any) ray whose nearest hit is object
 * (kind, index) at point p with geometric normal n_geo, given that hit's
 * local colour `local` (shade_point_k, already with the caller's per-frame
 * constants): local plus everything the bounces bring back. */
color_t trace_bounces(const world_t *w, geom_kind_t kind, uint16_t index, const ray_t *ray, vec3_t p, vec3_t n_geo,
                      color_t local);

/* Stack entries of the bounce loop (for the stack figures). */
#define TRACE_STACK_ENTRIES FXRT_MAX_DEPTH

#endif
