/* shadow: shadow rays (see shade.h for the self-shadowing policy). */
#include "shade.h"

#if FXRT_MAX_LIGHTS > 0 && FXRT_SHADOWS

/* Transparent objects cast no shadow (core/trace.h). */
#if FXRT_MAX_DEPTH > 0
#define SHADOW_CASTS(o) ((o).mat.kind != MATERIAL_TRANSPARENT)
#else
#define SHADOW_CASTS(o) true
#endif

/* Is the light's position strictly inside solid (kind, index)? */
static bool shadow_light_inside(const world_t *w, geom_kind_t kind, uint16_t index, const light_t *l)
{
    if (l->kind == LIGHT_DIRECTIONAL)
        return false; /* at infinity */
#if FXRT_MAX_SPHERES > 0
    if (kind == GEOM_SPHERE) {
        const geom_sphere_t *s = &w->spheres[index];
        vec3_t v = vec3_sub(l->position, s->center);
        return vec3_dotw(v, v) < s->radius2;
    }
#endif
#if FXRT_MAX_BOXES > 0
    if (kind == GEOM_BOX) {
        const geom_box_t *b = &w->boxes[index];
        vec3_t q = l->position;
        return q.x > b->min.x && q.x < b->max.x && q.y > b->min.y && q.y < b->max.y && q.z > b->min.z &&
               q.z < b->max.z;
    }
#endif
    (void)w, (void)kind, (void)index;
    return false;
}

bool shadow_blocked(const world_t *w, geom_kind_t kind, uint16_t index, bool inside, vec3_t p, const light_t *l,
                    vec3_t ldir, num_t dist)
{
    FXRT_COUNT(shadow_rays);
    bool solid = kind == GEOM_SPHERE || kind == GEOM_BOX;
    if (inside && solid && SHADOW_CASTS(*world_common(w, kind, index)) && !shadow_light_inside(w, kind, index, l))
        return true;
    ray_t ray = {p, ldir};
#if FXRT_NUMBER == FXRT_Q16
    if (dist >= SHADE_FAR_DIST && l->kind != LIGHT_DIRECTIONAL) {
        /* The light may be beyond the range from p (shade.h): the same
         * segment from the light's end. */
        ray.o = l->position;
        ray.d = vec3_neg(ldir);
        dist = NUM_MAX - 1;
    }
#endif
    return world_occluded(w, &ray, dist, world_common(w, kind, index)->id);
}

bool world_occluded(const world_t *w, const ray_t *ray, num_t tmax, uint16_t skip_id)
{
#if FXRT_MAX_PLANES > 0
    for (uint16_t i = 0; i < w->n_planes; i++)
        if (w->planes[i].obj.id != skip_id && SHADOW_CASTS(w->planes[i].obj) && geom_plane_occludes(&w->planes[i], ray, tmax))
            return true;
#endif
#if FXRT_MAX_SPHERES > 0
    for (uint16_t i = 0; i < w->n_spheres; i++) {
        num_t t;
        if (w->spheres[i].obj.id != skip_id && SHADOW_CASTS(w->spheres[i].obj) && geom_sphere_hit(&w->spheres[i], ray, &t) &&
            (t < tmax || tmax == NUM_MAX))
            return true;
    }
#endif
#if FXRT_MAX_TRIANGLES > 0
    for (uint16_t i = 0; i < w->n_triangles; i++)
        if (w->triangles[i].obj.id != skip_id && SHADOW_CASTS(w->triangles[i].obj) &&
            geom_triangle_occludes(&w->triangles[i], ray, tmax))
            return true;
#endif
#if FXRT_MAX_BOXES > 0
    for (uint16_t i = 0; i < w->n_boxes; i++)
        if (w->boxes[i].obj.id != skip_id && SHADOW_CASTS(w->boxes[i].obj) && geom_box_occludes(&w->boxes[i], ray, tmax))
            return true;
#endif
    return false;
}

#endif
