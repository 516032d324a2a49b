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

uint16_t world_count(const world_t *w)
{
    uint32_t n = 0; /* below 65536: fxrt_config.h bounds the total capacity */
#if FXRT_MAX_PLANES > 0
    n += w->n_planes;
#endif
#if FXRT_MAX_SPHERES > 0
    n += w->n_spheres;
#endif
#if FXRT_MAX_TRIANGLES > 0
    n += w->n_triangles;
#endif
#if FXRT_MAX_BOXES > 0
    n += w->n_boxes;
#endif
    (void)w;
    return (uint16_t)n;
}

/* A kind with capacity 0 is compiled out: adding one reports FXRT_ERR_FULL
 * without referencing its checks or constructor, so none of its code is
 * linked. */
int32_t world_add_plane(world_t *w, vec3_t point, vec3_t normal, color_t color)
{
#if FXRT_MAX_PLANES > 0
    fxrt_err_t e = geom_plane_check(point, normal, color);
    if (e != FXRT_OK)
        return e;
    if (w->n_planes >= FXRT_MAX_PLANES)
        return FXRT_ERR_FULL;
    uint16_t id = world_count(w);
    if (!geom_plane_make(&w->planes[w->n_planes], point, normal, color, id))
        return FXRT_ERR_DIRECTION; /* a normal too short to normalise */
    w->n_planes++;
    return id;
#else
    (void)w;
    (void)point, (void)normal, (void)color;
    return FXRT_ERR_FULL;
#endif
}

int32_t world_add_sphere(world_t *w, vec3_t center, num_t radius, color_t color)
{
#if FXRT_MAX_SPHERES > 0
    fxrt_err_t e = geom_sphere_check(center, radius, color);
    if (e != FXRT_OK)
        return e;
    if (w->n_spheres >= FXRT_MAX_SPHERES)
        return FXRT_ERR_FULL;
    uint16_t id = world_count(w);
    geom_sphere_make(&w->spheres[w->n_spheres++], center, radius, color, id);
    return id;
#else
    (void)w;
    (void)center, (void)radius, (void)color;
    return FXRT_ERR_FULL;
#endif
}

int32_t world_add_triangle(world_t *w, vec3_t a, vec3_t b, vec3_t c, color_t color)
{
#if FXRT_MAX_TRIANGLES > 0
    fxrt_err_t e = geom_triangle_check(a, b, c, color);
    if (e != FXRT_OK)
        return e;
    if (w->n_triangles >= FXRT_MAX_TRIANGLES)
        return FXRT_ERR_FULL;
    uint16_t id = world_count(w);
    geom_triangle_make(&w->triangles[w->n_triangles++], a, b, c, color, id);
    return id;
#else
    (void)w;
    (void)a, (void)b, (void)c, (void)color;
    return FXRT_ERR_FULL;
#endif
}

int32_t world_add_box(world_t *w, vec3_t min, vec3_t max, color_t color)
{
#if FXRT_MAX_BOXES > 0
    fxrt_err_t e = geom_box_check(min, max, color);
    if (e != FXRT_OK)
        return e;
    if (w->n_boxes >= FXRT_MAX_BOXES)
        return FXRT_ERR_FULL;
    uint16_t id = world_count(w);
    geom_box_make(&w->boxes[w->n_boxes++], min, max, color, id);
    return id;
#else
    (void)w;
    (void)min, (void)max, (void)color;
    return FXRT_ERR_FULL;
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
