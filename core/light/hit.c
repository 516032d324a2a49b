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

/* The colour at the ray's t on object obj (kind, index), whose geometric
 * normal there is n: the light sum and the bounces. */
static inline __attribute__((always_inline)) color_t shade_hit(const world_t *w, const geom_common_t *obj,
                                                               geom_kind_t kind, uint16_t index GEOM_PART_PARAM,
                                                               const ray_t *ray, num_t t, const vec3_t *n,
                                                               int8_t facing, const shade_k_t *k, uint8_t *mask)
{
    /* A camera ray (unit d, shade.h): in Q16.16, for |t| < 16384, t d
     * needs no saturation test (vec3_scale_unit_small, the same value;
     * -0.75 % on the lit set on the M3). */
    vec3_t p = NUM_EXACT && t < num_from_int(16384) && t > -num_from_int(16384)
                   ? vec3_add(ray->o, vec3_scale_unit_small(ray->d, t))
                   : ray_at(ray, t);
    color_t c = shade_sum(w, obj, kind, index GEOM_PART_ARG(part), &p, n, facing, &ray->d, k, mask);
    if (FXRT_MAX_DEPTH > 0 && material_bounces(obj->mat.kind))
        c = trace_bounces(w, kind, index GEOM_PART_ARG(part), ray, p, *n, c);
    return c;
}

color_t shade_object_k(const world_t *w, geom_kind_t kind, uint16_t index, const ray_t *ray, const shade_k_t *k,
                       uint8_t *mask)
{
    const geom_common_t *obj = world_common(w, kind, index);
    if (obj->mat.kind == MATERIAL_FLAT && !mask)
        return obj->color;
    num_t t = NUM_ZERO;
    vec3_t n = vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    /* A model's surface names the part met (scene/kinds.h, geom_part_t). */
    FXRT_IF_MODEL(geom_part_t part_met; const geom_part_t *part = NULL;
                  if (kind == GEOM_MODEL) {
                      geom_model_surface_part(&w->models[index], ray, BVH_NONE, &t, &n, &part_met);
                      part = &part_met;
                  } else)
    switch (kind) {
#define HIT_SURFACE(K, k, ks, ...) FXRT_IF_##K(case GEOM_##K: geom_##k##_surface(&w->ks[index], ray, &t, &n); break;)
        FXRT_KINDS(HIT_SURFACE)
#undef HIT_SURFACE
    default: break;
    }
    return shade_hit(w, obj, kind, index GEOM_PART_ARG(part), ray, t, &n, SHADE_FACING_UNKNOWN, k, mask);
}

color_t shade_flat_k(const world_t *w, const shade_flat_t *f, const ray_t *ray, const shade_k_t *k, uint8_t *mask)
{
    if (f->obj->mat.kind == MATERIAL_FLAT && !mask)
        return f->obj->color;
    /* d . n is the quotient's divisor and the light sum's side test. */
    numw_t dn = vec3_dotw_units(ray->d, *f->n);
    num_t t = numw_div_by(&f->num, dn);
    return shade_hit(w, f->obj, (geom_kind_t)f->kind, f->index GEOM_PART_ARG(NULL), ray, t, f->n, dn > 0, k, mask);
}

#if FXRT_MAX_MODELS > 0
color_t shade_model_k(const world_t *w, uint16_t index, const ray_t *ray, uint32_t tri, const shade_k_t *k,
                      uint8_t *mask)
{
    const geom_common_t *obj = &w->models[index].obj;
    if (obj->mat.kind == MATERIAL_FLAT && !mask)
        return obj->color;
    num_t t;
    vec3_t n;
    geom_part_t part;
    geom_model_surface_part(&w->models[index], ray, tri, &t, &n, &part);
    return shade_hit(w, obj, GEOM_MODEL, index, &part, ray, t, &n, SHADE_FACING_UNKNOWN, k, mask);
}
#endif
#endif
