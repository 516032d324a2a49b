/* hit: the colour seen along a ray at an object it meets: the surface
 * point and normal, the light sum (light/shade.c) and what the secondary
 * rays bring back (light/trace.c). */
#include "light/shade_sum.h"
#include "light/trace.h"

#if FXRT_MAX_LIGHTS > 0
color_t shade_object(const world_t *w, geom_kind_t kind, uint16_t index, ray_t *ray, const cam_t *cam,
                     uint8_t *mask)
{
    return shade_object_k(w, kind, index, ray, cam, NULL, mask);
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

/* shade_object_k on an object of a FLAT form that needs no unit direction. */
#define HIT_FLAT(K, k, ks, cap, solid, bounded, form, ...) HIT_FLAT_##form(K, ks)
#define HIT_FLAT_FLAT(K, ks)                                                                                     \
    FXRT_IF_##K(case GEOM_##K: {                                                                                \
        numw_ratio_num_t num = numw_ratio_num(geom_flat_num(&w->ks[index].a, &w->ks[index].n, &ray->o));       \
        numw_t rn;                                                                                              \
        vec3_t p = shade_flat_point(&num, &ray->o, &ray->d, &w->ks[index].n, &rn);                              \
        return shade_sum(w, obj, kind, index GEOM_PART_ARG(NULL), &p, &w->ks[index].n,                          \
                         (rn > 0) | SHADE_FACING_RAW, &ray->d, k, mask);                                        \
    })
#define HIT_FLAT_ROUND(K, ks)
#define HIT_FLAT_FACES(K, ks)
#define HIT_FLAT_RAYS(K, ks)

color_t shade_object_k(const world_t *w, geom_kind_t kind, uint16_t index, ray_t *ray, const cam_t *cam,
                       const shade_k_t *k, uint8_t *mask)
{
    const geom_common_t *obj = world_common(w, kind, index);
    if (obj->mat.kind == MATERIAL_FLAT && !mask)
        return obj->color;
    if (!shade_needs_unit(w, obj, kind, index)) {
        switch (kind) {
            FXRT_KINDS(HIT_FLAT)
        default: break;
        }
    }
    if (cam) {
        FXRT_COUNT(d_normalised);
        cam_ray_unit(cam, ray);
    }
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

#undef HIT_FLAT
#undef HIT_FLAT_FLAT
#undef HIT_FLAT_ROUND
#undef HIT_FLAT_FACES
#undef HIT_FLAT_RAYS

/* A plane under directional lights only, with no bounce, where no light
 * needs a shadow ray on this row, on the side dn > 0 says: the light sum
 * reads no hit point (light/shade_sum.h, shade_plane_row_unshadowed), so
 * shade_flat_k makes none. It passes the eye instead, a point all the
 * same: a world changed after the set-up (a light added) gives a wrong
 * pixel, not a fault. */
static inline __attribute__((always_inline)) bool shade_flat_eye(const world_t *w, const shade_flat_t *f, numw_t dn)
{
    return (f->flags & SHADE_FLAT_DIRECTIONAL) && !material_bounces(f->obj->mat.kind) &&
           shade_plane_row_unshadowed(w, f->pls, dn > 0);
}

color_t shade_flat_k(const world_t *w, const shade_flat_t *f, ray_t *ray, const shade_k_t *k, uint8_t *mask)
{
    if (f->obj->mat.kind == MATERIAL_FLAT && !mask)
        return f->obj->color;
    geom_kind_t kind = (geom_kind_t)f->kind;
    if (!shade_needs_unit(w, f->obj, kind, f->index)) {
        numw_t rn;
        /* (a Phong plane: the only one here with the flag) */
        if ((f->flags & SHADE_FLAT_DIRECTIONAL) &&
            shade_flat_eye(w, f, rn = vec3_dotw_unit(ray->d, *f->n)))
            return shade_sum(w, f->obj, kind, f->index GEOM_PART_ARG(NULL), &ray->o, f->n,
                             (rn > 0) | SHADE_FACING_RAW, &ray->d, k, mask);
        FXRT_COUNT(plane_points);
        vec3_t p = shade_flat_point(&f->ratio, &ray->o, &ray->d, f->n, &rn);
        return shade_sum(w, f->obj, kind, f->index GEOM_PART_ARG(NULL), &p, f->n, (rn > 0) | SHADE_FACING_RAW,
                         &ray->d, k, mask);
    }
    FXRT_COUNT(d_normalised);
    vec3_normalize(&ray->d); /* cam_ray_unit's, for a pinhole camera */
    /* d . n is the quotient's divisor and the light sum's side test. */
    numw_t dn = vec3_dotw_units(ray->d, *f->n);
    if (shade_flat_eye(w, f, dn))
        return shade_sum(w, f->obj, kind, f->index GEOM_PART_ARG(NULL), &ray->o, f->n, dn > 0, &ray->d, k, mask);
    FXRT_COUNT(plane_points);
    num_t t = numw_div_by(&f->num, dn);
    return shade_hit(w, f->obj, kind, f->index GEOM_PART_ARG(NULL), ray, t, f->n, dn > 0, k, mask);
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
