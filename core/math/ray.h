/* ray: origin o and unit direction d, points o + t d for t > 0. */
#ifndef FXRT_RAY_H
#define FXRT_RAY_H

#include "math/vec3.h"

typedef struct {
    vec3_t o; /* origin, scene units */
    vec3_t d; /* direction, unit length (within 1 LSB per component in Q16.16;
               * a refracted bounce ray's is not renormalised and may be
               * longer: light/trace.c bounds it, trace_dir_ok) */
} ray_t;

/* The point o + t d. */
static inline vec3_t ray_at(const ray_t *r, num_t t)
{
    return vec3_add(r->o, vec3_scale_unit(r->d, t));
}

/* The t at which the ray is closest to p: (p - o) . d (d is unit length). */
static inline num_t ray_t_of(const ray_t *r, vec3_t p)
{
    return vec3_dot(vec3_sub(p, r->o), r->d);
}

#endif
