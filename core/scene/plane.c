/* plane: an infinite plane through a point, with a normal (any length;
 * stored unit). */
#include "scene/kinds.h"

fxrt_err_t geom_plane_check(vec3_t point, vec3_t normal, color_t color)
{
    fxrt_err_t e = geom_check_point(point);
    if (e == FXRT_OK)
        e = geom_check_dir(normal);
    return e == FXRT_OK ? geom_check_color(color) : e;
}

bool geom_plane_make(geom_plane_t *p, vec3_t point, vec3_t normal, color_t color, uint16_t id)
{
    p->a = point;
    p->n = normal;
    geom_common_init(&p->obj, color, id);
    return vec3_normalize(&p->n) && geom_plane_check(point, normal, color) == FXRT_OK;
}

bool geom_plane_hit(const geom_plane_t *p, const ray_t *ray, num_t *t)
{
    return geom_flat_t(&p->a, &p->n, ray, t);
}

bool geom_plane_occludes(const geom_plane_t *p, const ray_t *ray, num_t tmax)
{
    return geom_flat_occludes(&p->a, &p->n, ray, tmax);
}

void geom_plane_surface(const geom_plane_t *p, const ray_t *ray, num_t *t, vec3_t *n)
{
    *t = geom_flat_surface_t(&p->a, &p->n, ray);
    *n = p->n;
}

