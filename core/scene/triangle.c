/* triangle: three vertices, hit from either side; collinear ones are
 * degenerate and never hit. */
#include "scene/kinds.h"

fxrt_err_t geom_triangle_check(vec3_t a, vec3_t b, vec3_t c, color_t color)
{
    fxrt_err_t e = geom_check_point(a);
    if (e == FXRT_OK)
        e = geom_check_point(b);
    if (e == FXRT_OK)
        e = geom_check_point(c);
    return e == FXRT_OK ? geom_check_color(color) : e;
}

bool geom_triangle_make(geom_triangle_t *tr, vec3_t a, vec3_t b, vec3_t c, color_t color, uint16_t id)
{
    tr->a = a;
    tr->b = b;
    tr->c = c;
    geom_common_init(&tr->obj, color, id);
    tr->degenerate = !vec3_unit_cross(vec3_sub(b, a), vec3_sub(c, a), &tr->n);
    return geom_triangle_check(a, b, c, color) == FXRT_OK;
}

/* Which side of the edge p -> q the ray passes: d . ((p - o) x (q - o)),
 * evaluated as (p - o) . ((q - o) x d). It is always computed with the edge
 * in canonical order and negated for the other order, so two triangles
 * sharing an edge see exactly opposite values: a ray cannot slip between
 * them (watertight), whatever the rounding. */
static numw_t geom_edge(vec3_t p, vec3_t q, const ray_t *ray)
{
    bool swap = geom_point_less(q, p);
    vec3_t first = swap ? q : p, second = swap ? p : q;
    numw_t e = vec3_dotw(vec3_sub(first, ray->o), vec3_cross_unit(vec3_sub(second, ray->o), ray->d));
    return swap ? numw_sub(numw_from(NUM_ZERO), e) : e;
}

/* Does the ray's line pass inside the triangle? When all three edge tests
 * agree in sign (either winding; a zero means the ray grazes that edge
 * and counts). Two of opposite strict signs decide it without the third. */
static bool geom_triangle_inside(const geom_triangle_t *tr, const ray_t *ray)
{
    numw_t e0 = geom_edge(tr->a, tr->b, ray);
    numw_t e1 = geom_edge(tr->b, tr->c, ray);
    if ((e0 < 0 && e1 > 0) || (e0 > 0 && e1 < 0))
        return false;
    numw_t e2 = geom_edge(tr->c, tr->a, ray);
    bool neg = e0 < 0 || e1 < 0 || e2 < 0;
    bool pos = e0 > 0 || e1 > 0 || e2 > 0;
    return !(neg && pos);
}

bool geom_triangle_hit(const geom_triangle_t *tr, const ray_t *ray, num_t *t)
{
    if (tr->degenerate || !geom_triangle_inside(tr, ray))
        return false;
    return geom_flat_t(&tr->a, &tr->n, ray, t);
}

bool geom_triangle_occludes(const geom_triangle_t *tr, const ray_t *ray, num_t tmax)
{
    /* The plane first (two dot products): most shadow rays do not cross
     * it in (0, tmax), and then the edges are not needed. */
    return !tr->degenerate && geom_flat_occludes(&tr->a, &tr->n, ray, tmax) && geom_triangle_inside(tr, ray);
}

void geom_triangle_surface(const geom_triangle_t *tr, const ray_t *ray, num_t *t, vec3_t *n)
{
    *t = geom_flat_surface_t(&tr->a, &tr->n, ray);
    *n = tr->n;
}

void geom_triangle_bounds(const geom_triangle_t *t, vec3_t *lo, vec3_t *hi)
{
    vec3_t a = t->a, b = t->b, c = t->c;
    *lo = vec3_make(num_min(a.x, num_min(b.x, c.x)), num_min(a.y, num_min(b.y, c.y)), num_min(a.z, num_min(b.z, c.z)));
    *hi = vec3_make(num_max(a.x, num_max(b.x, c.x)), num_max(a.y, num_max(b.y, c.y)), num_max(a.z, num_max(b.z, c.z)));
}

void geom_triangle_around(const geom_triangle_t *t, vec3_t *c, num_t *r)
{
    vec3_t lo, hi;
    geom_triangle_bounds(t, &lo, &hi);
    *c = vec3_make(num_half(num_add(lo.x, hi.x)), num_half(num_add(lo.y, hi.y)), num_half(num_add(lo.z, hi.z)));
    *r = num_max(num_max(vec3_len(vec3_sub(t->a, *c)), vec3_len(vec3_sub(t->b, *c))), vec3_len(vec3_sub(t->c, *c)));
}
