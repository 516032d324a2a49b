/* shade_sum: the light sum of one hit, shared by the local shading
 * (light/shade.c) and the colour of a hit (light/hit.c); private to light/. */
#ifndef FXRT_LIGHT_SHADE_SUM_H
#define FXRT_LIGHT_SHADE_SUM_H

#include "light/shade.h"

#if FXRT_MAX_LIGHTS > 0
/* Does the light sum at a point of obj (kind, index) need the ray's unit
 * direction? Not for a flat or lambert material (no specular term, no
 * bounce), nor in Q16.16 for a Phong one of exponent k > NUM_POW_ZERO_K
 * on a piece of the FLAT form (a plane, a triangle): shade_lights takes
 * its specular term's r . e from the raw direction (shade_specular),
 * which skips the root where numw_pow_zero_at proves the term 0, and its
 * hit point comes from a ratio (light/hit.c). With k <= NUM_POW_ZERO_K
 * there is no such skip, and a root per light costs more than one unit
 * direction per pixel. Float and double keep the unit direction: their
 * raw path measured 1-2 % dearer on the M4F (a root and a division are
 * an instruction each there, and x^k never underflows to 0). A smooth
 * triangle needs it (its normal's side test). A Phong plane does not, in
 * any number type: its light sum (shade_lights_plane) takes the raw
 * direction, and its hit point is the one shade_flat_point makes for the
 * plane's runs (light/shade.c, shade_flat_phong_blocks), so that a run's
 * pixels and one pixel at a time agree. */
static inline __attribute__((always_inline)) bool shade_needs_unit(const world_t *w, const geom_common_t *obj,
                                                                   geom_kind_t kind, uint16_t index)
{
    FXRT_IF_SMOOTH(FXRT_IF_TRIANGLE(if (kind == GEOM_TRIANGLE && w->triangles[index].smooth) return true;))
    (void)w, (void)index;
    uint8_t m = obj->mat.kind;
    if (kind == GEOM_PLANE && m == MATERIAL_PHONG)
        return false;
    return m != MATERIAL_FLAT && m != MATERIAL_LAMBERT &&
           !(NUM_EXACT && m == MATERIAL_PHONG && obj->mat.exponent > NUM_POW_ZERO_K && ((GEOM_FLAT_KINDS >> kind) & 1u));
}

/* The light loop (k not NULL when the material is lit and not transparent). */
color_t shade_lights(const world_t *w, const geom_common_t *obj, geom_kind_t kind, uint16_t index GEOM_PART_PARAM,
                     const vec3_t *p, const vec3_t *n_geo, int8_t facing, const vec3_t *d, const shade_k_t *k,
                     uint8_t *mask);
/* The light loop of a Lambert or Phong plane (light/shade.c): n . l from
 * the plane's height over it, and a Phong term's l from the same 1 / |v|. */
color_t shade_lights_plane(const world_t *w, const geom_common_t *obj, uint16_t index, const vec3_t *p,
                           const vec3_t *n_geo, int8_t facing, const vec3_t *d, const shade_k_t *k, uint8_t *mask);
/* shade_lights, or shade_lights_plane for a Lambert or Phong plane (k not
 * NULL). */
static inline __attribute__((always_inline)) color_t shade_lights_of(const world_t *w, const geom_common_t *obj,
                                                                     geom_kind_t kind, uint16_t index GEOM_PART_PARAM,
                                                                     const vec3_t *p, const vec3_t *n_geo,
                                                                     int8_t facing, const vec3_t *d,
                                                                     const shade_k_t *k, uint8_t *mask)
{
    if (kind == GEOM_PLANE && k &&
        (obj->mat.kind == MATERIAL_LAMBERT || (FXRT_PHONG && obj->mat.kind == MATERIAL_PHONG)))
        return shade_lights_plane(w, obj, index, p, n_geo, facing, d, k, mask);
    return shade_lights(w, obj, kind, index GEOM_PART_ARG(part), p, n_geo, facing, d, k, mask);
}
/* Under directional lights only (SHADE_FLAT_DIRECTIONAL), does no light
 * need a shadow ray from the points of the plane with entries pls, on the
 * current row and on the ray's side (inside: the back)? A light does not
 * when its shadows are off, when its row mask is SHADOW_ROW_CLEAR, or
 * when it lies behind that side. Then the light sum never reads the hit
 * point: a directional light's l is its direction, a Lambert plane's
 * n . l the plane's (pls[i].h.ndl), and shade_shadowed returns false
 * before it looks at p (light/shade.c, shade_flat_plane; light/hit.c,
 * shade_flat_k). */
static inline bool shade_plane_row_unshadowed(const world_t *w, const shade_plane_light_t *pls, bool inside)
{
    const light_t *L = w->lights;
    for (unsigned i = 0, n = w->n_lights; i < n; i++, L++) {
        if (!FXRT_SHADOWS || !L->shadows || (SHADOW_ROWS && pls && pls[i].row & SHADOW_ROW_CLEAR))
            continue;
        if (!pls || (inside ? -pls[i].h.ndl : pls[i].h.ndl) > 0)
            return false;
    }
    return true;
}

/* shade_sum without per-frame constants (the ray caster, arbitrary rays):
 * they are computed on its own frame. It calls shade_lights, not
 * shade_sum: no cycle in the call graph (tests/norecurse.sh). */
color_t shade_sum_own(const world_t *w, const geom_common_t *obj, geom_kind_t kind, uint16_t index GEOM_PART_PARAM,
                      const vec3_t *p, const vec3_t *n_geo, int8_t facing, const vec3_t *d, uint8_t *mask);

/* The light sum for object obj (= world_common(w, kind, index)), looked
 * up once by the caller. Inlined into its two callers where the core has
 * 32x32->64-bit multiplies (the M3 and M4F: one call fewer per pixel,
 * about -1 % on the lit scenes); the M0
 * keeps the call (inlined, its callers' register pressure cost it +1 %). */
static inline __attribute__((always_inline)) color_t shade_sum_inline(const world_t *w, const geom_common_t *obj,
                                                                    geom_kind_t kind, uint16_t index GEOM_PART_PARAM,
                                                                    const vec3_t *p, const vec3_t *n_geo, int8_t facing,
                                                                    const vec3_t *d, const shade_k_t *k, uint8_t *mask)
{
    const material_t *m = &obj->mat;
    FXRT_COUNT(shaded);
    bool lit = m->kind != MATERIAL_FLAT;
    /* Transparent: no local term (light/trace.c adds what it transmits and
     * reflects); the light loop runs only for a pixel's key. */
    bool clear = m->kind == MATERIAL_TRANSPARENT;
    if ((!lit || clear) && !mask)
        return clear ? color_make(NUM_ZERO, NUM_ZERO, NUM_ZERO) : obj->color;
    if (lit && !clear && !k)
        return shade_sum_own(w, obj, kind, index GEOM_PART_ARG(part), p, n_geo, facing, d, mask); /* computes k on its own frame */
    return shade_lights_of(w, obj, kind, index GEOM_PART_ARG(part), p, n_geo, facing, d, k, mask);
}
#if FX_HAVE_UMULL
static inline __attribute__((always_inline)) color_t shade_sum(const world_t *w, const geom_common_t *obj,
                                                               geom_kind_t kind, uint16_t index GEOM_PART_PARAM,
                                                               const vec3_t *p, const vec3_t *n_geo, int8_t facing,
                                                               const vec3_t *d, const shade_k_t *k, uint8_t *mask)
{
    return shade_sum_inline(w, obj, kind, index GEOM_PART_ARG(part), p, n_geo, facing, d, k, mask);
}
#else
color_t shade_sum(const world_t *w, const geom_common_t *obj, geom_kind_t kind, uint16_t index GEOM_PART_PARAM,
                  const vec3_t *p, const vec3_t *n_geo, int8_t facing, const vec3_t *d, const shade_k_t *k,
                  uint8_t *mask);
#endif
#endif

#endif
