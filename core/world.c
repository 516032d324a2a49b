/* world: nearest-hit search over the static object arrays. */
#include "world.h"

void world_init(world_t *w, color_t background)
{
    w->background = background;
    w->background_rgb = color_to_rgb8(background);
#if FXRT_MAX_PLANES > 0
    w->n_planes = 0;
#endif
#if FXRT_MAX_SPHERES > 0
    w->n_spheres = 0;
#endif
#if FXRT_MAX_TRIANGLES > 0
    w->n_triangles = 0;
#endif
#if FXRT_MAX_BOXES > 0
    w->n_boxes = 0;
#endif
}

/* Keep candidate (t, obj) if it is nearer than the best so far, or as near
 * and earlier in the scene. */
static void world_consider(hit_t *best, bool *found, num_t t, geom_kind_t kind, uint16_t index,
                           const geom_common_t *obj)
{
    if (*found && (t > best->t || (t == best->t && obj->id > best->obj->id)))
        return;
    *found = true;
    best->t = t;
    best->kind = kind;
    best->index = index;
    best->obj = obj;
}

bool world_hit(const world_t *w, const ray_t *ray, hit_t *hit)
{
    bool found = false;
    num_t t;
#if FXRT_MAX_PLANES > 0
    for (uint16_t i = 0; i < w->n_planes; i++)
        if (geom_plane_hit(&w->planes[i], ray, &t))
            world_consider(hit, &found, t, GEOM_PLANE, i, &w->planes[i].obj);
#endif
#if FXRT_MAX_SPHERES > 0
    for (uint16_t i = 0; i < w->n_spheres; i++)
        if (geom_sphere_hit(&w->spheres[i], ray, &t))
            world_consider(hit, &found, t, GEOM_SPHERE, i, &w->spheres[i].obj);
#endif
#if FXRT_MAX_TRIANGLES > 0
    for (uint16_t i = 0; i < w->n_triangles; i++)
        if (geom_triangle_hit(&w->triangles[i], ray, &t))
            world_consider(hit, &found, t, GEOM_TRIANGLE, i, &w->triangles[i].obj);
#endif
#if FXRT_MAX_BOXES > 0
    for (uint16_t i = 0; i < w->n_boxes; i++)
        if (geom_box_hit(&w->boxes[i], ray, &t))
            world_consider(hit, &found, t, GEOM_BOX, i, &w->boxes[i].obj);
#endif
    if (found)
        hit->point = ray_at(ray, hit->t);
    return found;
}
