/* shade: the lighting model (see shade.h). */
#include "shade.h"
#include "trace.h"

#if FXRT_STATS
fxrt_stats_t fxrt_stats;
#endif

#if FXRT_MAX_LIGHTS > 0

/* Colour arithmetic of the light sum. Every term is at most 255 (1/255
 * units) times fractions <= 1, and the sum of the ambient term and two
 * terms per light stays below 255 (1 + 2 FXRT_MAX_LIGHTS) = 4335, far
 * inside Q16.16: the products are fx_mul's rounding without its
 * saturation checks, and the sums plain additions. Identical values. */
#if FXRT_NUMBER == FXRT_Q16
static inline num_t shade_mul(num_t a, num_t b)
{
    return (fx_t)((fx_smul32(a, b) + FX_HALF) >> FX_FRAC_BITS);
}
static inline num_t shade_add(num_t a, num_t b)
{
    return (fx_t)((uint32_t)a + (uint32_t)b);
}
#else
static inline num_t shade_mul(num_t a, num_t b) { return a * b; }
static inline num_t shade_add(num_t a, num_t b) { return a + b; }
#endif
static inline color_t shade_filter(color_t a, color_t f)
{
    return color_make(shade_mul(a.r, f.r), shade_mul(a.g, f.g), shade_mul(a.b, f.b));
}
/* c + a * s */
static inline color_t shade_madd(color_t c, color_t a, num_t s)
{
    return color_make(shade_add(c.r, shade_mul(a.r, s)), shade_add(c.g, shade_mul(a.g, s)),
                      shade_add(c.b, shade_mul(a.b, s)));
}

void shade_consts(const world_t *w, const geom_common_t *obj, shade_k_t *k)
{
    k->ambient = shade_filter(obj->color, w->ambient);
    for (uint8_t i = 0; i < w->n_lights; i++) {
        k->kd[i] = shade_filter(obj->color, w->lights[i].color);
#if FXRT_PHONG
        /* The specular colour (fractions) in 1/255 units: exact in Q16.16. */
        color_t s = obj->mat.specular;
        color_t s255 = color_make(num_mul_int(s.r, 255), num_mul_int(s.g, 255), num_mul_int(s.b, 255));
        k->ks[i] = shade_filter(s255, w->lights[i].color);
#endif
    }
}

/* Spot cone: (-l) . s >= cos(angle) for l = v / |v|, compared as
 * (-v) . s >= cos(angle) |v|: cosines, no acos, and no rounding of l. */
static bool shade_in_cone(const light_t *L, vec3_t v, num_t dist)
{
#if FXRT_NUMBER == FXRT_Q16
    /* Q16.16 x Q2.30 products (< 2^61 each), exact in int64. */
    int64_t lhs = -(fx_smul32(v.x, L->axis30[0]) + fx_smul32(v.y, L->axis30[1]) + fx_smul32(v.z, L->axis30[2]));
    return lhs >= fx_smul32(dist, L->cos30);
#else
    return vec3_dotw(vec3_neg(v), L->dir) >= numw_mul(L->cos_angle, dist);
#endif
}

#if FXRT_NUMBER == FXRT_Q16
/* A point or spot light can be farther from a hit point than Q16.16
 * holds: the point up to 32767 from the origin (a plane seen far away),
 * the light up to FXRT_COORD_LIMIT. Then v = pos - p saturates (a
 * component beyond 32767) or fx_normalize3_len saturates its length, and
 * neither l nor the distance is right. Any such case has a computed
 * distance of at least SHADE_FAR_DIST (shade.h), and so does a light just
 * inside the range, for which this path is right too. shade_light_far
 * recomputes l from a quarter of the exact 64-bit difference (|v| / 4 <
 * 17,737: it fits) and makes a spot's cone test with that quarter and
 * its length; it returns l, or the zero vector when the spot does not
 * reach p. The caller then passes the distance SHADE_FAR_DIST, and
 * shadow_blocked casts the shadow ray from the light's end of the
 * segment (core/shadow.c). Rare, so out of line. */
static __attribute__((noinline)) vec3_t shade_light_far(const light_t *L, vec3_t p)
{
    vec3_t pos = L->position, l = vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    vec3_t v = vec3_make((fx_t)(((int64_t)pos.x - p.x) / 4), (fx_t)(((int64_t)pos.y - p.y) / 4),
                         (fx_t)(((int64_t)pos.z - p.z) / 4));
    num_t len;
    (void)vec3_unit_len(v, &l, &len); /* |v| > 8191: not zero */
    if (L->kind == LIGHT_SPOT && !shade_in_cone(L, v, len))
        return vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    return l;
}
#endif

color_t shade_point(const world_t *w, geom_kind_t kind, uint16_t index, vec3_t p, vec3_t n_geo, vec3_t d,
                    uint8_t *mask)
{
    return shade_point_k(w, kind, index, p, n_geo, d, NULL, mask);
}

static color_t shade_lights(const world_t *w, const geom_common_t *obj, geom_kind_t kind, uint16_t index, vec3_t p,
                            vec3_t n_geo, vec3_t d, const shade_k_t *k, uint8_t *mask);

/* shade_sum without per-frame constants (the ray caster, arbitrary rays):
 * they are computed here, off the renderer's stack path. It calls
 * shade_lights, not shade_sum: no cycle in the call graph
 * (tests/norecurse.sh). */
static __attribute__((noinline)) color_t shade_sum_own(const world_t *w, const geom_common_t *obj, geom_kind_t kind,
                                                      uint16_t index, vec3_t p, vec3_t n_geo, vec3_t d, uint8_t *mask)
{
    shade_k_t own;
    shade_consts(w, obj, &own);
    return shade_lights(w, obj, kind, index, p, n_geo, d, &own, mask);
}

/* The light sum for object obj (= world_common(w, kind, index)), looked
 * up once by the caller. Inlined into its two callers where the core has
 * 32x32->64-bit multiplies (the M3 and M4F: one call and its copies of
 * three vectors fewer per pixel, about -1 % on the lit scenes); the M0
 * keeps the call (inlined, its callers' register pressure cost it +1 %). */
#if FX_HAVE_UMULL
#define SHADE_SUM_INLINE inline __attribute__((always_inline))
#else
#define SHADE_SUM_INLINE
#endif
static SHADE_SUM_INLINE color_t shade_sum(const world_t *w, const geom_common_t *obj, geom_kind_t kind, uint16_t index, vec3_t p,
                         vec3_t n_geo, vec3_t d, const shade_k_t *k, uint8_t *mask)
{
    const material_t *m = &obj->mat;
    FXRT_COUNT(shaded);
    bool lit = m->kind != MATERIAL_FLAT;
    /* Transparent: no local term (core/trace.c adds what it transmits and
     * reflects); the light loop runs only for a pixel's key. */
    bool clear = m->kind == MATERIAL_TRANSPARENT;
    if ((!lit || clear) && !mask)
        return clear ? color_make(NUM_ZERO, NUM_ZERO, NUM_ZERO) : obj->color;
    if (lit && !clear && !k)
        return shade_sum_own(w, obj, kind, index, p, n_geo, d, mask); /* computes k on its own frame */
    return shade_lights(w, obj, kind, index, p, n_geo, d, k, mask);
}

/* The light loop of shade_sum (k not NULL when the material is lit and
 * not transparent). */
static color_t shade_lights(const world_t *w, const geom_common_t *obj, geom_kind_t kind, uint16_t index, vec3_t p,
                            vec3_t n_geo, vec3_t d, const shade_k_t *k, uint8_t *mask)
{
    const material_t *m = &obj->mat;
    bool lit = m->kind != MATERIAL_FLAT;
    bool clear = m->kind == MATERIAL_TRANSPARENT;
    /* Two-sided: n faces the incoming ray. */
    bool inside = vec3_dotw_unit(d, n_geo) > 0;
    vec3_t n = inside ? vec3_neg_unit(n_geo) : n_geo;
    color_t c = clear ? color_make(NUM_ZERO, NUM_ZERO, NUM_ZERO) : lit ? k->ambient : obj->color;
    uint8_t bits = 0;
#if !FXRT_SHADOWS
    (void)kind, (void)index; /* only shadow rays need to know the object */
#endif
    for (uint8_t i = 0; i < w->n_lights; i++) {
        const light_t *L = &w->lights[i];
        vec3_t l;
        num_t dist = NUM_MAX;
        if (L->kind == LIGHT_DIRECTIONAL) {
            l = L->dir; /* normalised once, in world_add_light */
        } else {
            /* Spot: (-l) . s >= cos(angle) with l = v / |v|, compared as
             * (-v) . s >= cos(angle) |v| (no rounding of l in the test). */
#if FXRT_NUMBER == FXRT_Q16
            /* One inverse square root gives l and |v| (fx_normalize3_len). */
            FXRT_COUNT(l_normalised);
            vec3_t v = vec3_sub(L->position, p);
            if (!vec3_unit_len(v, &l, &dist))
                continue; /* the light is at p: no direction, no light */
            if (__builtin_expect(dist >= SHADE_FAR_DIST, 0)) {
                l = shade_light_far(L, p);
                if (l.x == NUM_ZERO && l.y == NUM_ZERO && l.z == NUM_ZERO)
                    continue; /* outside the cone */
                dist = SHADE_FAR_DIST;
            } else if (L->kind == LIGHT_SPOT && !shade_in_cone(L, v, dist)) {
                continue; /* outside the cone */
            }
#else
            vec3_t v = vec3_sub(L->position, p);
            /* |v| first: a point outside a spot's cone costs no division. */
            dist = vec3_len(v);
            if (L->kind == LIGHT_SPOT && !shade_in_cone(L, v, dist))
                continue; /* outside the cone */
            FXRT_COUNT(l_normalised);
            if (dist == NUM_ZERO)
                continue; /* the light is at p: no direction, no light */
            l = vec3_scale(v, num_div(NUM_ONE, dist)); /* vec3_normalize's value, without its second root */
#endif
        }
        numw_t ndlw = vec3_dotw_unit(n, l);
        if (ndlw <= 0)
            continue; /* behind the surface: no shadow ray either */
#if FXRT_SHADOWS
        if (L->shadows && shadow_blocked(w, kind, index, inside, p, L, l, dist))
            continue;
#endif
        bits = (uint8_t)(bits | (1u << i));
        if (!lit || clear)
            continue;
        num_t ndl = numw_round(ndlw);
        c = shade_madd(c, k->kd[i], ndl);
#if FXRT_PHONG
        if (m->kind == MATERIAL_PHONG || m->kind == MATERIAL_REFLECTIVE) {
            /* 0 < n.l <= 1: 2 (n.l) n fits without saturation. */
            vec3_t r = vec3_sub(vec3_scale_unit_small(n, num_add(ndl, ndl)), l);
            numw_t rde = numw_neg_fits(vec3_dotw_unit(r, d)); /* r . e = -(r . d), e = -d */
            if (rde > 0)
                c = shade_madd(c, k->ks[i], numw_pow_int(rde, m->exponent));
        }
#endif
    }
    if (mask)
        *mask = bits;
    return c;
}

color_t shade_point_k(const world_t *w, geom_kind_t kind, uint16_t index, vec3_t p, vec3_t n_geo, vec3_t d,
                      const shade_k_t *k, uint8_t *mask)
{
    const geom_common_t *obj = world_common(w, kind, index);
    /* Without the caller's constants (the bounce loop, the ray caster), a
     * lit opaque material goes straight to shade_sum_own, so that one
     * shade_sum frame, not two, is on the stack (16 KB boards). */
    if (!k && obj->mat.kind != MATERIAL_FLAT && obj->mat.kind != MATERIAL_TRANSPARENT)
        return shade_sum_own(w, obj, kind, index, p, n_geo, d, mask);
    return shade_sum(w, obj, kind, index, p, n_geo, d, k, mask);
}

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
    vec3_t p = ray_at(ray, t);
    color_t c = shade_sum(w, obj, kind, index, p, n, ray->d, k, mask);
#if FXRT_MAX_DEPTH > 0
    if (material_bounces(obj->mat.kind))
        c = trace_bounces(w, kind, index, ray, p, n, c);
#endif
    return c;
}

#endif
