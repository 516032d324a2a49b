/* shade: the lighting model (see shade.h). */
#include "shade.h"

#if FXRT_STATS
fxrt_stats_t fxrt_stats;
#endif

#if FXRT_MAX_LIGHTS > 0

#if FXRT_PHONG
/* A specular colour (fractions) in 1/255 units: exact in Q16.16. */
static color_t shade_255(color_t f)
{
    return color_make(num_mul_int(f.r, 255), num_mul_int(f.g, 255), num_mul_int(f.b, 255));
}
#endif

/* Spot cone: (-l) . s >= cos(angle) for l = v / |v|, compared as
 * (-v) . s >= cos(angle) |v|: cosines, no acos, and no rounding of l. */
static bool shade_in_cone(const light_t *L, vec3_t v, num_t dist)
{
#if FXRT_NUMBER == FXRT_Q16
    /* Q16.16 x Q2.30 products (< 2^61 each), exact in int64. */
    int64_t lhs = -((int64_t)v.x * L->axis30[0] + (int64_t)v.y * L->axis30[1] + (int64_t)v.z * L->axis30[2]);
    return lhs >= (int64_t)dist * L->cos30;
#else
    return vec3_dotw(vec3_neg(v), L->dir) >= numw_mul(L->cos_angle, dist);
#endif
}

color_t shade_point(const world_t *w, geom_kind_t kind, uint16_t index, vec3_t p, vec3_t n_geo, vec3_t d,
                    uint8_t *mask)
{
    const geom_common_t *obj = world_common(w, kind, index);
    const material_t *m = &obj->mat;
    FXRT_COUNT(shaded);
    bool lit = m->kind != MATERIAL_FLAT;
    /* Two-sided: n faces the incoming ray. */
    bool inside = vec3_dotw(n_geo, d) > 0;
    vec3_t n = inside ? vec3_neg(n_geo) : n_geo;
    color_t cd = obj->color;
    color_t c = lit ? color_mul(cd, w->ambient) : cd;
    uint8_t bits = 0;
    for (uint8_t i = 0; i < w->n_lights; i++) {
        const light_t *L = &w->lights[i];
        vec3_t l;
        num_t dist = NUM_MAX;
        if (L->kind == LIGHT_DIRECTIONAL) {
            l = L->dir; /* normalised once, in world_add_light */
        } else {
            vec3_t v = vec3_sub(L->position, p);
            dist = vec3_len(v);
            /* Spot: (-l) . s >= cos(angle) with l = v / |v|, compared as
             * (-v) . s >= cos(angle) |v| (no rounding of l in the test). */
            if (L->kind == LIGHT_SPOT && !shade_in_cone(L, v, dist))
                continue; /* outside the cone */
            l = v;
            FXRT_COUNT(l_normalised);
            if (!vec3_normalize(&l))
                continue; /* the light is at p: no direction, no light */
        }
        numw_t ndlw = vec3_dotw(n, l);
        if (ndlw <= 0)
            continue; /* behind the surface: no shadow ray either */
#if FXRT_SHADOWS
        if (L->shadows && shadow_blocked(w, kind, index, inside, p, L, l, dist))
            continue;
#endif
        bits = (uint8_t)(bits | (1u << i));
        if (!lit)
            continue;
        num_t ndl = numw_round(ndlw);
        c = color_add(c, color_scale(color_mul(cd, L->color), ndl));
#if FXRT_PHONG
        if (m->kind == MATERIAL_PHONG) {
            vec3_t r = vec3_sub(vec3_scale(n, num_mul_int(ndl, 2)), l);
            numw_t rde = vec3_dotw(r, vec3_neg(d)); /* r . e, e = -d */
            if (rde > 0)
                c = color_add(c, color_scale(color_mul(shade_255(m->specular), L->color),
                                             numw_pow_int(rde, m->exponent)));
        }
#endif
    }
    if (mask)
        *mask = bits;
    return c;
}

color_t shade_object(const world_t *w, geom_kind_t kind, uint16_t index, const ray_t *ray, uint8_t *mask)
{
    const geom_common_t *obj = world_common(w, kind, index);
    if (obj->mat.kind == MATERIAL_FLAT && !mask)
        return obj->color;
    num_t t = NUM_ZERO;
    vec3_t n = vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    switch (kind) {
#if FXRT_MAX_PLANES > 0
    case GEOM_PLANE: geom_plane_surface(&w->planes[index], ray, &t, &n); break;
#endif
#if FXRT_MAX_SPHERES > 0
    case GEOM_SPHERE: geom_sphere_surface(&w->spheres[index], ray, &t, &n); break;
#endif
#if FXRT_MAX_TRIANGLES > 0
    case GEOM_TRIANGLE: geom_triangle_surface(&w->triangles[index], ray, &t, &n); break;
#endif
#if FXRT_MAX_BOXES > 0
    case GEOM_BOX: geom_box_surface(&w->boxes[index], ray, &t, &n); break;
#endif
    default: break;
    }
    return shade_point(w, kind, index, ray_at(ray, t), n, ray->d, mask);
}

#endif
