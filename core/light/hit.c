/* hit: the colour seen along a ray at an object it meets: the surface
 * point and normal, the light sum (light/shade.c) and what the secondary
 * rays bring back (light/trace.c). */
#include "light/shade_sum.h"
#include "light/trace.h"

#if FXRT_MAX_LIGHTS > 0
color_t shade_object(const world_t *w, geom_kind_t kind, uint16_t index, const ray_t *ray, uint8_t *mask)
{
    return shade_object_k(w, kind, index, ray, NULL, mask);
}

color_t shade_object_k(const world_t *w, geom_kind_t kind, uint16_t index, const ray_t *ray, const shade_k_t *k,
                       uint8_t *mask)
{
    const geom_common_t *obj = world_common(w, kind, index);
    if (obj->mat.kind == MATERIAL_FLAT && !mask)
        return obj->color;
    num_t t = NUM_ZERO;
    vec3_t n = vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    switch (kind) {
#define HIT_SURFACE(K, k, ks, ...) FXRT_IF_##K(case GEOM_##K: geom_##k##_surface(&w->ks[index], ray, &t, &n); break;)
        FXRT_KINDS(HIT_SURFACE)
#undef HIT_SURFACE
    default: break;
    }
    /* A camera ray (unit d, shade.h): in Q16.16, for |t| < 16384, t d
     * needs no saturation test (vec3_scale_unit_small, the same value;
     * -0.75 % on the lit set on the M3). */
    vec3_t p = NUM_EXACT && t < num_from_int(16384) && t > -num_from_int(16384)
                   ? vec3_add(ray->o, vec3_scale_unit_small(ray->d, t))
                   : ray_at(ray, t);
    color_t c = shade_sum(w, obj, kind, index, &p, &n, &ray->d, k, mask);
    if (FXRT_MAX_DEPTH > 0 && material_bounces(obj->mat.kind))
        c = trace_bounces(w, kind, index, ray, p, n, c);
    return c;
}
#endif
