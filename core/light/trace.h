/* trace: secondary rays, reflection and refraction, without recursion.
 *
 * At a ray's nearest hit (material m, unit direction d, unit normal n
 * turned towards the ray):
 *   flat, lambert, phong   the local colour (light/shade.c)
 *   reflective             the Phong colour + c_r (.) trace(reflected)
 *   transparent            R trace(reflected) + (1 - R) c_d (.) trace(transmitted),
 *                          or trace(reflected) alone under total internal reflection
 * reflected d - 2 (d.n) n; transmitted by Snell's law with q = 1/eta
 * entering and eta leaving; Schlick's R = R0 + (1 - R0)(1 - cos)^5. A ray
 * is traced while its bounce is at most the world's depth and some channel
 * of its weight (the product of c_r, R, (1 - R) c_d on its path) is at
 * least 1/512. The tree is walked depth first with one explicit stack of
 * at most FXRT_MAX_DEPTH pending rays. No offset and no epsilon: a ray
 * that leaves a surface does not test that object again, except a ray
 * into a solid, which meets it where it leaves (geom_<kind>_exit), and a
 * ray leaving a model, which leaves out only the triangle it starts on.
 * docs/TRACING.md, "The model" and "How it runs", has it in full. */
#ifndef FXRT_TRACE_H
#define FXRT_TRACE_H

#include "scene/world.h"

/* The colour of a primary (or any) ray whose nearest hit is object
 * (kind, index) at point p with geometric normal n_geo, given that hit's
 * local colour `local` (shade_point_k, already with the caller's per-frame
 * constants): local plus everything the bounces bring back. */
color_t trace_bounces(const world_t *w, geom_kind_t kind, uint16_t index GEOM_PART_PARAM, const ray_t *ray, vec3_t p,
                      vec3_t n_geo, color_t local);

/* Stack entries of the bounce loop (for the stack figures). */
#define TRACE_STACK_ENTRIES FXRT_MAX_DEPTH

#endif
