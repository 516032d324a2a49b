/* shadow: shadow rays (see shade.h for the self-shadowing policy). */
#include "light/shade.h"

#if FXRT_MAX_LIGHTS > 0 && FXRT_SHADOWS

/* Transparent objects cast no shadow (light/trace.h). */
#define SHADOW_CASTS(o) (FXRT_MAX_DEPTH == 0 || (o).mat.kind != MATERIAL_TRANSPARENT)

/* Is the light's position strictly inside solid (kind, index)? */
static bool shadow_light_inside(const world_t *w, geom_kind_t kind, uint16_t index, const light_t *l)
{
    if (l->kind == LIGHT_DIRECTIONAL)
        return false; /* at infinity */
    switch (kind) {
#define SHADOW_INSIDE(K, k, ks, cap, solid, ...)                                                              \
    FXRT_WHEN(solid, FXRT_IF_##K(case GEOM_##K: return geom_##k##_contains(&w->ks[index], l->position);))
        FXRT_KINDS(SHADOW_INSIDE)
#undef SHADOW_INSIDE
    default: break;
    }
    (void)w, (void)index;
    return false;
}

/* Shadow-ray culling (shade.h; docs/ACCURACY.md, "Shadow-ray culling",
 * derives the margins). The shadow ray from p along ldir (unit, rounded)
 * with t in (0, dist) ends at L' = p + dist ldir, within eps(dist) of the
 * light's position L: eps <= 2^-15 + dist 2^-13 in every build (Q16.16:
 * |ldir - v/|v||_2 <= 0.9 LSB = 2^-16.2 and |dist - |v|| <= 0.5 LSB +
 * 2^-24 |v|; float and double: a few ulp). A point x of the ray lies on
 * L' + s (-ldir), 0 < s < dist, so the ray from L along -ldir passes
 * within eps of x. If the exact test finds the object at x, x is within
 * R' of the bounding sphere's centre c, and the ray from L passes within
 * rho = R' + eps of c: the angle between -ldir and c - L is at most
 * asin(rho / |c - L|), and s + eps >= |x - L| >= |c - L| - R'. R' is the
 * bounding radius plus a margin for the kernels' own rounding (Q16.16: a
 * few LSB; float and double: a few ulp of the coordinates, CULL_REL).
 * Each entry holds for dist <= d_cap, where eps(dist) <= eps_cap. */
/* The M0 (no 32x32->64 multiply) makes the cone test in 32-bit products
 * (shadow_cone_out16, shade.h; tests/test_shade.c checks it on the host). */
#define SHADOW_CULL_DOT16 (FXRT_NUMBER == FXRT_Q16 && !FX_HAVE_UMULL)
/* Q16.16: none; float: 2^-18 (64 ulp); double: 2^-40. */
#define CULL_REL                                                                                             \
    (NUM_EXACT ? NUM_ZERO : FXRT_NUMBER == FXRT_FLOAT ? NUM(1.0 / 262144) : NUM(1.0 / 1099511627776.0))

/* Directional lights: v . (ldir x e_k) for the axis e_k, k = 0..2,
 * as one 2x2 determinant. ldir . (ldir x e_k) is exactly zero (the same
 * two products), so every point p + t ldir of a shadow ray has p's value:
 * an object whose bounding sphere (c, R') it meets has |value(p) -
 * value(c)| <= R' |ldir x e_k| <= R'. In Q16.16 vec3_det2w is exact. The
 * two axes used are the light's (light_dir_axes, scene/light.h), found
 * once in world_add_light. */
static numw_t shadow_proj(vec3_t v, vec3_t l, int k)
{
    return k == 0 ? vec3_det2w(v.y, l.z, v.z, l.y) : k == 1 ? vec3_det2w(v.z, l.x, v.x, l.z)
                                                           : vec3_det2w(v.x, l.y, v.y, l.x);
}

/* R' = r (1 + 2^-8) + 2^-10 + CULL_REL (|c|_1 + |L|_1): the bounding
 * radius r of an object centred on c with the margin for the kernels' own
 * rounding, seen from light L. */
static num_t shadow_bound(vec3_t c, num_t r, const light_t *L)
{
    num_t rr = num_add(num_add(r, num_mul(r, NUM(1.0 / 256))), NUM(1.0 / 1024));
    return num_add(rr, num_mul(CULL_REL, num_add(vec3_l1(c), vec3_l1(L->position))));
}

/* The entry for an object with bounding sphere (c, r) seen from L. */
__attribute__((unused)) static void shadow_cull_entry(shadow_cull_t *e, const light_t *L, vec3_t c, num_t r)
{
    num_t rr = shadow_bound(c, r, L);
    if (L->kind == LIGHT_DIRECTIONAL) {
        e->dir.c1 = shadow_proj(c, L->dir, L->axes[0]);
        e->dir.c2 = shadow_proj(c, L->dir, L->axes[1]);
        e->dir.r = numw_from(rr);
        return;
    }
    e->pt.u = vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    e->pt.lim = NUM_ZERO;
    e->pt.d_near = e->pt.d_cap = NUM(-1); /* culls nothing */
    vec3_t u;
    num_t len;
    if (!vec3_unit_len(vec3_sub(c, L->position), &u, &len))
        return; /* the light at the centre */
    num_t eps_cap = num_add(num_mul(rr, NUM(0.25)), num_mul(len, NUM(1.0 / 1024)));
    num_t rho = num_add(rr, eps_cap);
    if (rho >= len)
        return; /* the light is inside or near the bound */
    num_t ratio = num_div(rho, len);
    num_t s2 = num_mul(ratio, ratio);
    if (s2 > NUM(1.0 - 1.0 / 128))
        return; /* a cone of almost a half-space: no use */
    /* cos(asin(rho / |c - L|)) within a few LSB (the root's slope is at
     * most 8 here), less 2^-11 for that, u's and ldir's rounding and
     * |ldir| != 1. */
    num_t cosv = num_sub(num_sqrt(num_sub(NUM_ONE, s2)), NUM(1.0 / 2048));
    /* eps(dist) <= eps_cap for dist <= (eps_cap - 2^-15) 2^13. */
    num_t cap = num_mul_int(num_sub(eps_cap, NUM(1.0 / 32768)), 8192);
    if (NUM_EXACT && cap >= SHADE_FAR_DIST)
        cap = SHADE_FAR_DIST - 1; /* the far path (shade.h) is never culled */
    /* s + eps >= |c - L| - R' with s < dist |ldir| <= dist (1 + 2^-12). */
    num_t near = num_sub(num_mul(num_sub(len, rho), NUM(1.0 - 1.0 / 4096)), NUM(1.0 / 32768));
    /* Q16.16: u in Q2.30 (exact) and lim in Q18.14, rounded up (shade.h). */
    e->pt.u = NUM_EXACT ? vec3_make(u.x * (1 << 14), u.y * (1 << 14), u.z * (1 << 14)) : u;
    e->pt.lim = NUM_EXACT ? (num_t)(((int32_t)num_neg(cosv) + 3) >> 2) : num_neg(cosv);
    e->pt.d_cap = cap;
    e->pt.d_near = num_min(near, cap);
}

/* v as an edge entry keeps it (shade.h): in Q16.16, v (|v| < 2) in Q2.14
 * rounded to nearest (how 0) or up (1, and 1 LSB more for a division's
 * rounding), or v's whole units (how -1: 0 <= v < 2^15); in float and
 * double v itself, with the test's 2^-11 added for how 1. */
static num_q14_t shadow_q14(num_t v, int how)
{
    if (NUM_EXACT)
        return (num_q14_t)(how < 0 ? (int32_t)v >> 16 : how > 0 ? ((int32_t)v + 4) >> 2 : ((int32_t)v + 2) >> 2);
    return (num_q14_t)(how > 0 ? num_add(v, NUM(1.0 / 2048)) : v);
}

/* The shadow edges (shade.h) of triangle tr seen from point or spot light
 * L. A hit the exact test finds lies at a point x = p + t ldir of the
 * ray, 0 < t < dist, within mu of the triangle (the kernels' rounding:
 * mu = R' - r, shadow_bound), so m . (x - L) >= -mu for each edge's
 * plane through L (unit normal m facing the triangle). With L' = p + dist
 * ldir, |L' - L| <= eps = 2^-15 + cap 2^-13 for dist < cap (shadow_cull_entry's
 * bound), x - L = (L' - L) - s ldir with s = dist - t, and
 * s >= near = (|c - L| - R' - eps) (1 - 2^-12) (as in the cone's entry),
 * so m . (x - L) <= eps - s (m . ldir): a ray with m . ldir > (eps + mu)
 * / near finds no hit. lim adds 2^-13 for m's own rounding. cap: twice
 * the distance to the far side of the bound, and 16; never where the light
 * is near the bound or the triangle's plane (an edge plane's normal would
 * be noise), or a difference leaves 2^14 (P - L might saturate). */
__attribute__((unused)) static void shadow_edge_entry(shadow_edge_t *g, const light_t *L, const geom_triangle_t *tr)
{
    vec3_t m[3], u;
    num_t lim = NUM(2.5); /* (never) */
    const vec3_t *v[3] = {&tr->a, &tr->b, &tr->c};
    vec3_t c;
    num_t r, len;
    geom_triangle_around(tr, &c, &r);
    num_t rr = shadow_bound(c, r, L);
    bool ok = !tr->degenerate && vec3_unit_len(vec3_sub(c, L->position), &u, &len); /* (len only) */
    for (int j = 0; ok && j < 3; j++) {
        vec3_t a = v[j][0], pos = L->position;
        const num_t big = NUM(16384);
        ok = num_abs(num_sub(a.x, pos.x)) < big && num_abs(num_sub(a.y, pos.y)) < big &&
             num_abs(num_sub(a.z, pos.z)) < big;
    }
    /* (kept in whole units: dist below them) */
    num_t cap = ok ? num_min(num_add(num_mul_int(num_add(len, rr), 2), NUM(16)), NUM(16383)) : NUM_ZERO;
    num_t eps = num_add(NUM(1.0 / 32768), num_mul(cap, NUM(1.0 / 8192)));
    num_t near = ok ? num_mul(num_sub(num_sub(len, rr), eps), NUM(1.0 - 1.0 / 4096)) : NUM_ZERO;
    for (int j = 0; ok && j < 3; j++) {
        vec3_t a = vec3_sub(v[j][0], L->position), b = vec3_sub(v[(j + 1) % 3][0], L->position);
        vec3_t k = vec3_sub(v[(j + 2) % 3][0], L->position);
        ok = vec3_unit_cross(a, b, &m[j]);
        /* the third vertex clearly on one side: at least 2^-8 of |k|_1 */
        numw_t side = vec3_dotw_unit(k, m[j]);
        num_t sd = numw_round_fits(side < 0 ? numw_sub(numw_from(NUM_ZERO), side) : side);
        ok = ok && sd > num_mul(vec3_l1(k), NUM(1.0 / 256));
        if (ok && side < 0)
            m[j] = vec3_neg(m[j]);
    }
    if (ok && near > NUM(1.0 / 64))
        lim = num_add(num_div(num_add(eps, num_sub(rr, r)), near), NUM(1.0 / 8192));
    bool use = lim < NUM(1.5);
    g->cap = use ? shadow_q14(cap, -1) : 0;
    for (int j = 0; j < 3; j++) {
        for (int i = 0; i < 3; i++)
            g->m[j][i] = use ? shadow_q14((&m[j].x)[i], 0) : 0;
        g->lim[j] = use ? shadow_q14(lim, 1) : (num_q14_t)(NUM_EXACT ? INT16_MAX : 4);
    }
}

void shadow_cull_setup(const world_t *w, shadow_table_t *t)
{
    shadow_cull_t *table = t->cull;
    for (uint8_t li = 0; li < w->n_lights; li++) {
        const light_t *L = &w->lights[li];
        shadow_cull_t *row = table + (size_t)li * SHADOW_CULL_SLOTS;
        vec3_t c;
        num_t r;
#define SHADOW_CULL_ROW(K, k, ks, cap, solid, bounded, ...)                                                   \
    FXRT_WHEN(bounded, FXRT_IF_##K(for (uint16_t i = 0; i < w->n_##ks; i++) {                                \
        geom_##k##_around(&w->ks[i], &c, &r);                                                                 \
        shadow_cull_entry(&row[SHADOW_SLOT_##K + i], L, c, r);                                                \
    }))
        FXRT_KINDS(SHADOW_CULL_ROW)
#undef SHADOW_CULL_ROW
        (void)row, (void)c, (void)r, (void)L; /* (no bounded kind: no cull entry) */
        if (SHADOW_EDGES && L->kind != LIGHT_DIRECTIONAL) {
            FXRT_IF_TRIANGLE(for (uint16_t i = 0; i < w->n_triangles; i++) shadow_edge_entry(
                                 &t->edges[SHADOW_EDGES ? (size_t)li * FXRT_MAX_TRIANGLES + i : 0], L, &w->triangles[i]);)
        }
    }
}

/* The mask of one row, plane and light: bit s for slot s's object when
 * SHADOW_ROW_FAR(c, r, v) (its bounding sphere c, r, and v = c - ref, the
 * caller's reference point: the light, or the eye), SHADOW_ROW_CLEAR when every
 * bounded object is skipped (those past slot 30 too, which have no bit:
 * the same on the host, with its large capacities, as on a board) and
 * the plane is the world's only one (no other plane can block the light
 * either). */
#define SHADOW_ROW_MASK()                                                                                     \
    uint32_t mask = 0;                                                                                        \
    bool all = true;                                                                                          \
    vec3_t c;                                                                                                 \
    num_t r;                                                                                                  \
    FXRT_KINDS(SHADOW_ROW_SLOTS_OF)                                                                           \
    (void)c, (void)r, (void)ref;                                                                              \
    return mask | (all && (0 FXRT_IF_PLANE(+w->n_planes)) == 1 ? SHADOW_ROW_CLEAR : 0)
#define SHADOW_ROW_SLOTS_OF(K, k, ks, cap, solid, bounded, ...)                                               \
    FXRT_WHEN(bounded, FXRT_IF_##K(for (uint16_t i = 0; i < w->n_##ks; i++) {                                \
        int s = SHADOW_SLOT_##K + i;                                                                          \
        geom_##k##_around(&w->ks[i], &c, &r);                                                                 \
        vec3_t v = vec3_sub(c, ref);                                                                          \
        bool far = vec3_l1(v) < NUM(16384) && SHADOW_ROW_FAR(c, r, v);                                      \
        if (far && s < SHADOW_ROW_SLOTS)                                                                      \
            mask |= 1u << s;                                                                                  \
        all = all && far;                                                                                     \
    }))
/* A point or spot light's test: |g' . (c - L)|, less 2^-12 of itself and
 * 2^-14, beyond R' + eps + delta (lim). */
static inline bool shadow_row_far_pt(num_t dc, num_t lim)
{
    return num_sub(num_sub(dc, num_mul(dc, NUM(1.0 / 4096))), NUM(1.0 / 16384)) > lim;
}

/* A directional light's limit for |S(c)|: (R' + delta) (|g| + 2^-13)
 * (rd = R' + delta) and S's own error, 2^-13 (|v|_1 + |F(e)|) + 2^-14 (v = c - e),
 * with CULL_REL 4 (|c|_1 + |e|_1 + |F(e)|) for float and double. */
static inline num_t shadow_row_lim_dir(vec3_t c, vec3_t v, num_t fa, num_t el, num_t rd, num_t gup)
{
    num_t own = num_add(num_mul(num_add(vec3_l1(v), fa), NUM(1.0 / 8192)), NUM(1.0 / 16384));
    num_t rel = num_mul(num_mul_int(CULL_REL, 4), num_add(num_add(vec3_l1(c), el), fa));
    return num_add(num_add(num_mul(rd, gup), own), rel);
}

/* Shadow rows (shade.h). On row y of a perspective view, pixel x's
 * camera ray is along r(x) = f + ix u with f = fwd + iy v (cam.h), so the
 * rays of the row lie in the plane P through the eye e with normal
 * m = u x f, and a plane's points on the row on its line l = plane ∩ P.
 * For a point or spot light (shadow_row_mask; a directional light's is
 * shadow_row_mask_dir, below), S is the plane through the light's
 * position L that holds l: with
 * F(x) = n . (x - a) (the plane's point a, unit normal n) and R(x) =
 * m' . (x - e) (m' = m / |m|), S(x) = R(L) F(x) - F(L) R(x), normal g =
 * R(L) n - F(L) m' (formed divided by sc = max(|R(L)|, |F(L)|)), unit g'
 * (rounded); S' is the plane through L with normal g'. Slot s's object (bounding sphere c,
 * R' = shadow_bound) is skipped when its distance from S,
 * |g' . (c - L)|, less 2^-12 of it and 2^-14 for g' and the product's
 * rounding, exceeds R' + eps + delta, where for every shading point p'
 * the renderer computes on the row:
 *  - every point of the shadow ray from p' lies within max(D(p'), eps)
 *    of S (D: the distance from S; S holds L, and the ray ends within
 *    eps(dist) <= 2^-15 + dist 2^-13 of L, as for the cones above);
 *  - D(p') <= delta (D: now from S'). p' is within 2^-15.5 of the exact
 *    hit of its rounded ray (d' within 2^-15.2 of r / |r|), a point of the
 *    plane at most t 2^-15.2 from P, so at most kappa t 2^-15.2 from l
 *    (kappa = 1 / sin of the angle between the plane and P, taken from
 *    the rounded m' less 2^-12) and from S. S' turns about L away from S
 *    by at most ang = 2^-14 (|L - e|_1 + |L - a|_1 + 2) / (sc |g / sc|) +
 *    2^-14 (the errors of R(L) and F(L), m''s rounding among them, and
 *    g''s own), so a point x near l is within ang |x - L| more of S'.
 *    With t <= t_max (the row's two ends, whose rays meet the plane in
 *    front: the hits between lie on the segment, |p - e| convex along it)
 *    and dist <= t_max + |L - e|_1 = d_max: delta = (kappa (t_max + 1) +
 *    1) 2^-13 + ang d_max + CULL_REL 4 (|e|_1 + t_max + |L|_1), four times
 *    the Q16.16 bound of the first terms; float and double have ulps, far
 *    below it.
 * No mask where the row's rays do not all meet the plane in front (the
 * horizon crosses the row), where the row lies within 1/64 rad of the
 * plane (kappa), the light within 1/64 of it, or |g / sc| < 1/64, or
 * (Q16.16) where e's coordinates plus t_max reach 16384 (a hit point that
 * may saturate) or the camera is not small (cam.h). Once per row: a few
 * roots and a product per object. */
static uint32_t shadow_row_mask(const world_t *w, const light_t *L, vec3_t e, vec3_t n, vec3_t a, vec3_t m1,
                                num_t t_max)
{
    vec3_t pos = L->position;
    num_t fl = vec3_dot(n, vec3_sub(pos, a)), rl = vec3_dot(m1, vec3_sub(pos, e));
    num_t sc = num_max(num_abs(fl), num_abs(rl)); /* g / sc: no saturation */
    num_t sine = vec3_len(vec3_cross(n, m1));
    if (num_abs(fl) < NUM(1.0 / 64) || sine < NUM(1.0 / 64))
        return 0; /* the light (almost) on the plane, or a row (almost) in it */
    vec3_t g = vec3_sub(vec3_scale(n, num_div(rl, sc)), vec3_scale(m1, num_div(fl, sc)));
    num_t gl = vec3_len(g);
    if (gl < NUM(1.0 / 64) || !vec3_normalize(&g))
        return 0;
    num_t kappa = num_div(NUM_ONE, num_sub(sine, NUM(1.0 / 4096)));
    num_t le = vec3_l1(vec3_sub(pos, e));
    /* g''s direction error: rl's and fl's (m''s rounding and the
     * products': at most 2^-14 (|L - e|_1 + |L - a|_1 + 2)) over sc |g|,
     * and g''s own rounding. */
    num_t ang = num_mul(num_add(num_add(le, vec3_l1(vec3_sub(pos, a))), NUM(2)), NUM(1.0 / 16384));
    ang = num_add(num_div(ang, num_mul(sc, gl)), NUM(1.0 / 16384));
    num_t d_max = num_add(t_max, le);
    num_t eps = num_add(NUM(1.0 / 32768), num_mul(d_max, NUM(1.0 / 8192)));
    num_t delta = num_mul(num_add(num_mul(kappa, num_add(t_max, NUM_ONE)), NUM_ONE), NUM(1.0 / 8192));
    delta = num_add(num_add(delta, num_mul(ang, d_max)),
                    num_mul(num_mul_int(CULL_REL, 4), num_add(num_add(vec3_l1(e), t_max), vec3_l1(pos))));
    num_t margin = num_add(eps, delta);
    vec3_t ref = pos;
#define SHADOW_ROW_FAR(c, r, v) shadow_row_far_pt(num_abs(vec3_dot(g, v)), num_add(shadow_bound(c, r, L), margin))
    SHADOW_ROW_MASK();
#undef SHADOW_ROW_FAR
}

/* A directional light's mask (docs/ACCURACY.md, "Shadow rows"). Its
 * shadow rays run along the light's unit direction l itself, and
 * S(x) = (m' . l) F(x) - (n . l) R(x) is constant along each of them
 * (its gradient g = (m' . l) n - (n . l) m' is orthogonal to l) and zero
 * on the row's line: every point of the ray from p' has p''s distance
 * from S, |S(p')| / |g| <= delta (the hit point's term of the point
 * light's delta), however far it goes. S(c) = g . (c - e) + (m' . l) F(e),
 * formed in wide products from g unnormalised (|g| <= 2: nothing
 * saturates), is within 2^-13 (|c - e|_1 + |F(e)|) + 2^-14 of the exact
 * value (g within 2^-13.8: m''s and the two dot products' rounding), so
 * the object is skipped when |S(c)| exceeds that, plus the float and
 * double rounding, plus (R' + delta) (|g| + 2^-13). */
static uint32_t shadow_row_mask_dir(const world_t *w, const light_t *L, vec3_t e, num_t fe, vec3_t n, vec3_t m1,
                                    num_t t_max)
{
    vec3_t l = L->dir;
    num_t a1 = vec3_dot(m1, l), b1 = vec3_dot(n, l);
    num_t sine = vec3_len(vec3_cross(n, m1));
    if (sine < NUM(1.0 / 64))
        return 0; /* a row (almost) in the plane */
    vec3_t g = vec3_sub(vec3_scale(n, a1), vec3_scale(m1, b1));
    num_t gup = num_add(vec3_len(g), NUM(1.0 / 8192));
    num_t kappa = num_div(NUM_ONE, num_sub(sine, NUM(1.0 / 4096)));
    num_t el = vec3_l1(e), fa = num_abs(fe);
    num_t delta = num_add(num_mul(num_add(num_mul(kappa, num_add(t_max, NUM_ONE)), NUM_ONE), NUM(1.0 / 8192)),
                          num_mul(num_mul_int(CULL_REL, 4), num_add(el, t_max)));
    numw_t off = numw_mul(a1, fe); /* (m' . l) F(e) */
    vec3_t ref = e;
#define SHADOW_ROW_FAR(c, r, v)                                                                               \
    numw_abs_gt(numw_add(vec3_dotw(g, v), off),                                                               \
                numw_from(shadow_row_lim_dir(c, v, fa, el, num_add(shadow_bound(c, r, L), delta), gup)))
    SHADOW_ROW_MASK();
#undef SHADOW_ROW_FAR
}
#undef SHADOW_ROW_MASK
#undef SHADOW_ROW_SLOTS_OF

/* Does light L get row masks (a light with shadows)? */
__attribute__((unused)) static bool shadow_rows_light(const light_t *L)
{
    return L->shadows;
}

/* Plane pl's masks on the row of rays f + ix u (|ix| <= ixe), one per light
 * (pls[i].row). */
__attribute__((unused)) static void shadow_rows_plane(const world_t *w, const cam_t *cam, vec3_t f, int32_t ixe,
                                                      vec3_t m1, const geom_plane_t *pl, shade_plane_light_t *pls)
{
    /* The farthest hit of the row: at an end, each in front. */
    vec3_t e = cam->e;
    num_t fe = vec3_dot(pl->n, vec3_sub(e, pl->a)), t_max = NUM_ZERO;
    bool ok = fe != NUM_ZERO;
    for (int end = 0; end < 2 && ok; end++) {
        vec3_t r = vec3_add(f, vec3_scale_int(cam->u, end ? ixe : -ixe));
        num_t den = vec3_dot(pl->n, r);
        ok = den != NUM_ZERO && (den < NUM_ZERO) != (fe < NUM_ZERO);
        if (ok) { /* the distance -fe |r| / den */
            num_t te = num_abs(numw_div(numw_mul(fe, vec3_len(r)), numw_from(den)));
            t_max = num_max(t_max, num_add(num_add(te, num_mul(te, NUM(1.0 / 64))), NUM_ONE));
        }
    }
    if (!ok || num_add(t_max, num_max(num_max(num_abs(e.x), num_abs(e.y)), num_abs(e.z))) >= NUM(16384))
        return;
    for (uint8_t i = 0; i < w->n_lights; i++) {
        const light_t *L = &w->lights[i];
        if (shadow_rows_light(L))
            pls[i].row = L->kind == LIGHT_DIRECTIONAL ? shadow_row_mask_dir(w, L, e, fe, pl->n, m1, t_max)
                                                   : shadow_row_mask(w, L, e, pl->n, pl->a, m1, t_max);
    }
}

void shadow_rows_clear(shadow_table_t *t)
{
    for (size_t i = 0; i < sizeof t->pl / sizeof t->pl[0]; i++)
        t->pl[i].row = 0;
}

void shadow_rows_setup(const world_t *w, const cam_t *cam, int32_t y, shadow_table_t *t)
{
    shadow_rows_clear(t);
    bool any = false; /* (a world without shadows pays nothing per row) */
    for (uint8_t i = 0; i < w->n_lights; i++)
        any = any || shadow_rows_light(&w->lights[i]);
    if (!SHADOW_ROWS || !any || cam->kind != CAM_PERSPECTIVE || (NUM_EXACT && !cam->small))
        return;
    int32_t iy = 2 * y - cam->height + 1, ixe = cam->width - 1;
    vec3_t f = vec3_add(cam->fwd, vec3_scale_int(cam->v, iy));
    vec3_t m1 = vec3_cross(cam->u, f);
    if (!vec3_normalize(&m1))
        return;
    FXRT_IF_PLANE(for (uint16_t j = 0; j < w->n_planes && SHADOW_ROWS; j++)
                      shadow_rows_plane(w, cam, f, ixe, m1, &w->planes[j], t->pl + (size_t)j * FXRT_MAX_LIGHTS);)
    (void)w, (void)ixe;
}

/* One shadow ray's view of the cull row: the light's row, the ray's ldir
 * and dist, and for a directional light the point's projections (with,
 * in float and double, a margin for their rounding: CULL_REL |p|_1). */
typedef struct {
    const shadow_cull_t *row;
    const shadow_edge_t *edges; /* the light's shadow edges (NULL: none) */
    vec3_t ldir;
    num_t dist;
    numw_t p1, p2;
#if FXRT_NUMBER != FXRT_Q16
    numw_t slack;
#endif
} shadow_ray_cull_t;

/* Can the object of cull entry e not block the ray? One test per kind of
 * light, each inlined where products are cheap (32x32->64 in one
 * instruction, or floating point); out of line on the M0, where inlined
 * three times into the loop their products took its frame from 40 to 312
 * bytes (16 KB boards). */
#if FX_HAVE_UMULL || FXRT_NUMBER != FXRT_Q16
#define SHADOW_CULLED_INLINE inline __attribute__((always_inline))
#else
#define SHADOW_CULLED_INLINE __attribute__((noinline, unused))
#endif
/* A point or spot light: the cone and the distances. */
static SHADOW_CULLED_INLINE bool shadow_culled_pt(const shadow_ray_cull_t *rc, const shadow_cull_t *e)
{
    if (rc->dist > e->pt.d_cap)
        return false;
    if (rc->dist <= e->pt.d_near)
        return true;
#if SHADOW_CULL_DOT16
    return shadow_cone_out16(e, &rc->ldir);
#elif FXRT_NUMBER == FXRT_Q16
    return shadow_cone_out64(e, &rc->ldir);
#else
    return vec3_dotw_unit(rc->ldir, e->pt.u) > numw_from(e->pt.lim);
#endif
}
/* A directional light: the point's projections against the object's. */
static SHADOW_CULLED_INLINE bool shadow_culled_dir(const shadow_ray_cull_t *rc, const shadow_cull_t *e)
{
#if FXRT_NUMBER != FXRT_Q16
    numw_t lim = numw_add(e->dir.r, rc->slack);
#else
    numw_t lim = e->dir.r;
#endif
    return numw_abs_gt(numw_sub_exact(rc->p1, e->dir.c1), lim) ||
           numw_abs_gt(numw_sub_exact(rc->p2, e->dir.c2), lim);
}

/* A triangle's shadow edges (shade.h), for a ray its cone did not skip
 * (i: its index). */
static SHADOW_CULLED_INLINE bool shadow_edge_out(const shadow_edge_t *g, int j, const vec3_t *l)
{
    const num_q14_t *m = g->m[j];
    if (NUM_EXACT) { /* Q4.28 */
        int32_t dot = ((int32_t)l->x >> 2) * m[0] + ((int32_t)l->y >> 2) * m[1] + ((int32_t)l->z >> 2) * m[2];
        return dot > (int32_t)g->lim[j] * 16384 + (1 << 17);
    }
    return vec3_dotw_unit(*l, vec3_make((num_t)m[0], (num_t)m[1], (num_t)m[2])) > numw_from((num_t)g->lim[j]);
}
static SHADOW_CULLED_INLINE bool shadow_edges_out(const shadow_ray_cull_t *rc, ptrdiff_t i)
{
    if (!rc->edges)
        return false;
    const shadow_edge_t *g = rc->edges + i;
    if (NUM_EXACT ? (int32_t)rc->dist >> 16 >= g->cap : !(rc->dist < (num_t)g->cap))
        return false;
    return shadow_edge_out(g, 0, &rc->ldir) || shadow_edge_out(g, 1, &rc->ldir) || shadow_edge_out(g, 2, &rc->ldir);
}

/* Which culling a loop makes: a constant in each instance of
 * shadow_occluded_loop, so that each has its test inlined and no test of
 * the light's kind or of a missing table per object. */
enum { SHADOW_CULL_NONE, SHADOW_CULL_PT, SHADOW_CULL_DIR };
/* SHADOW_CULL as a constant for the per-kind loops (the macro expands the
 * kinds table, which cannot be expanded inside itself). */
enum { SHADOW_CULLS = SHADOW_CULL };
#define SHADOW_ROW(base) (SHADOW_CULLS && mode != SHADOW_CULL_NONE ? rc->row + (base) : NULL)
#define SHADOW_SKIP(e)                                                                                                 \
    (SHADOW_CULLS && (mode == SHADOW_CULL_PT    ? shadow_culled_pt(rc, e)                                              \
                     : mode == SHADOW_CULL_DIR ? shadow_culled_dir(rc, e)                                             \
                                               : false))
/* A triangle's shadow edges, for a point or spot light. */
enum { SHADOW_EDGES_ON = SHADOW_EDGES }; /* (as SHADOW_CULLS) */
#define SHADOW_EDGE_SKIP(K, i) (SHADOW_EDGES_ON && GEOM_##K == GEOM_TRIANGLE && mode == SHADOW_CULL_PT && shadow_edges_out(rc, i))
/* The next object's cull entry. */
#define SHADOW_NEXT(e) ((e) = mode != SHADOW_CULL_NONE ? (e) + 1 : (e))
/* The light's row mask (shade.h, row_skip) from a kind's first slot on
 * (bit 0: that slot), zero for the loop without culling. */
enum { SHADOW_ROWS_ON = SHADOW_ROWS }; /* (as SHADOW_CULLS) */
#define SHADOW_ROW_SKIP(base)                                                                                 \
    (SHADOW_ROWS_ON && mode != SHADOW_CULL_NONE && (base) < SHADOW_ROW_SLOTS ? row_skip >> ((base) & 31) : 0u)

/* world_occluded, skipping what rc rules out (mode: how). An object's cull
 * entry is read before the object (the table is small and contiguous);
 * the object itself is skipped by its id when its entry did not cull it,
 * but a model (its field an INST: a kind of parts) only leaves out its
 * triangle skip_tri (all of it where skip_tri is BVH_NONE:
 * world_occluded). */
#define SHADOW_HITS(k, t1, o) SHADOW_HITS_##t1(k, o)
#define SHADOW_HITS_POINT(k, o) ((o)->obj.id != skip_id && SHADOW_CASTS((o)->obj) && geom_##k##_occludes(o, ray, tmax))
#define SHADOW_HITS_INST(k, o)                                                                                \
    (((o)->obj.id != skip_id || skip_tri != BVH_NONE) && SHADOW_CASTS((o)->obj) &&                           \
     geom_##k##_occludes_from(o, ray, tmax, (o)->obj.id == skip_id ? skip_tri : BVH_NONE))
static inline __attribute__((always_inline)) bool shadow_occluded_loop(const world_t *w, const ray_t *ray, num_t tmax,
                                                                      uint16_t skip_id FXRT_IF_MODEL(, uint32_t skip_tri), const shadow_ray_cull_t *rc,
                                                                      uint32_t row_skip, int mode)
{
    (void)rc, (void)row_skip, (void)mode;
    /* A directional light's: a copy that no call can change, so that its
     * fields may stay in registers (0.5 % fewer instructions on the M3's
     * directional scenes; a point light's copy costs more than it saves;
     * on the M0 the test is a call, and the copy only costs). */
    shadow_ray_cull_t own;
    if (SHADOW_CULL && mode == SHADOW_CULL_DIR && !SHADOW_CULL_DOT16) {
        own = *rc;
        rc = &own;
    }
    /* Per kind, its objects: an unbounded kind's have no cull entry. */
#define SHADOW_LOOP(K, k, ks, cap, solid, bounded, form, edges, f1, t1, ...) FXRT_IF_##K(SHADOW_LOOP_##bounded(K, k, ks, t1))
#define SHADOW_LOOP_0(K, k, ks, t1)                                                                         \
    for (uint16_t i = 0; i < w->n_##ks; i++)                                                                  \
        if (SHADOW_HITS(k, t1, &w->ks[i]))                                                                  \
            return true;
#define SHADOW_LOOP_1(K, k, ks, t1)                                                                         \
    {                                                                                                         \
        const shadow_cull_t *e = SHADOW_ROW(SHADOW_SLOT_##K);                                                 \
        const geom_##k##_t *o = w->ks;                                                                        \
        uint32_t sk = SHADOW_ROW_SKIP(SHADOW_SLOT_##K);                                                       \
        for (uint16_t n = w->n_##ks; n > 0; n--, o++) {                                                       \
            if (!(sk & 1) && !SHADOW_SKIP(e) && !SHADOW_EDGE_SKIP(K, o - w->ks) && SHADOW_HITS(k, t1, o))  \
                return true;                                                                                  \
            SHADOW_NEXT(e);                                                                                   \
            sk >>= 1;                                                                                         \
        }                                                                                                     \
    }
    FXRT_KINDS(SHADOW_LOOP)
#undef SHADOW_LOOP
#undef SHADOW_LOOP_0
#undef SHADOW_LOOP_1
    return false;
}

/* The loop without culling (world_occluded, and shadow rays without a
 * table) and, with SHADOW_CULL, one instance per kind of light. */
static bool shadow_occluded(const world_t *w, const ray_t *ray, num_t tmax, uint16_t skip_id FXRT_IF_MODEL(, uint32_t skip_tri))
{
    return shadow_occluded_loop(w, ray, tmax, skip_id FXRT_IF_MODEL(, skip_tri), NULL, 0, SHADOW_CULL_NONE);
}
static bool shadow_occluded_pt(const world_t *w, const ray_t *ray, num_t tmax, uint16_t skip_id FXRT_IF_MODEL(, uint32_t skip_tri),
                               const shadow_ray_cull_t *rc, uint32_t row_skip)
{
    return shadow_occluded_loop(w, ray, tmax, skip_id FXRT_IF_MODEL(, skip_tri), rc, row_skip, SHADOW_CULL_PT);
}
static bool shadow_occluded_dir(const world_t *w, const ray_t *ray, num_t tmax, uint16_t skip_id FXRT_IF_MODEL(, uint32_t skip_tri),
                                const shadow_ray_cull_t *rc, uint32_t row_skip)
{
    return shadow_occluded_loop(w, ray, tmax, skip_id FXRT_IF_MODEL(, skip_tri), rc, row_skip, SHADOW_CULL_DIR);
}

/* A directional light's ray: its projections (out of line: shadow_blocked's
 * frame stays small on the M0). */
static __attribute__((noinline)) bool shadow_blocked_dir(const world_t *w, const ray_t *ray, num_t tmax,
                                                        uint16_t skip_id FXRT_IF_MODEL(, uint32_t skip_tri), shadow_ray_cull_t *rc,
                                                        const vec3_t *p, const uint8_t axes[2], uint32_t row_skip)
{
    rc->p1 = shadow_proj(*p, rc->ldir, axes[0]);
    rc->p2 = shadow_proj(*p, rc->ldir, axes[1]);
#if FXRT_NUMBER != FXRT_Q16
    rc->slack = num_mul(CULL_REL, vec3_l1(*p));
#endif
    return shadow_occluded_dir(w, ray, tmax, skip_id FXRT_IF_MODEL(, skip_tri), rc, row_skip);
}

bool shadow_blocked(const world_t *w, geom_kind_t kind, uint16_t index GEOM_PART_PARAM, const geom_common_t *obj,
                    bool inside, const vec3_t *p, const light_t *l, const vec3_t *ldir, num_t dist, const shadow_cull_row_t *cull,
                    uint32_t skip, const shadow_edge_t *edges)
{
    FXRT_COUNT(shadow_rays);
    bool solid = (GEOM_SOLID_KINDS >> kind) & 1u;
    if (inside && solid && SHADOW_CASTS(*obj) && !shadow_light_inside(w, kind, index, l))
        return true;
    ray_t ray = {*p, *ldir};
    num_t tmax = dist;
    if (NUM_EXACT && dist >= SHADE_FAR_DIST && l->kind != LIGHT_DIRECTIONAL) {
        /* The light may be beyond the range from p (shade.h): the same
         * segment from the light's end (never culled: d_cap is below). */
        ray.o = l->position;
        ray.d = vec3_neg(*ldir);
        tmax = NUM_MAX - 1;
        skip = 0; /* (the masks hold for rays from p) */
    }
    uint16_t id = obj->id;
    FXRT_IF_MODEL(uint32_t skip_tri = part ? part->tri : BVH_NONE;)
    if (SHADOW_CULL && cull) {
        shadow_ray_cull_t rc;
        rc.row = cull;
        rc.edges = SHADOW_EDGES ? edges : NULL;
        rc.ldir = *ldir;
        rc.dist = dist;
        if (l->kind == LIGHT_DIRECTIONAL)
            return shadow_blocked_dir(w, &ray, tmax, id FXRT_IF_MODEL(, skip_tri), &rc, p, l->axes, skip);
        return shadow_occluded_pt(w, &ray, tmax, id FXRT_IF_MODEL(, skip_tri), &rc, skip);
    }
    return shadow_occluded(w, &ray, tmax, id FXRT_IF_MODEL(, skip_tri));
}

bool world_occluded(const world_t *w, const ray_t *ray, num_t tmax, uint16_t skip_id)
{
    FXRT_IF_MODEL(const uint32_t skip_tri = BVH_NONE;) /* (a model skip_id: all of it, as any object) */
    return shadow_occluded(w, ray, tmax, skip_id FXRT_IF_MODEL(, skip_tri));
}

#endif
