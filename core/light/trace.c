/* trace: the bounce loop (see trace.h). */
#include "light/trace.h"
#include "light/shade.h"

#if FXRT_MAX_DEPTH > 0

/* A pending ray: where it starts, where it goes, its weight, its bounce,
 * and the object it leaves (`from`, an id) with whether it goes into that
 * object (a solid's interior: the medium it travels in); leaving a model,
 * the triangle it leaves (from_tri), the only part of it not tested. */
typedef struct {
    ray_t ray;
    color_t w;
    uint16_t from;
    uint8_t bounce;
    bool inward;
    FXRT_IF_MODEL(uint32_t from_tri;)
} trace_ray_t;

/* The nearest hit of a secondary ray. */
typedef struct {
    num_t t;
    geom_kind_t kind;
    uint16_t index;
    uint16_t id;
    bool exit; /* the exit of the solid the ray starts in */
    FXRT_IF_MODEL(uint32_t tri;) /* a model's: the triangle met */
} trace_hit_t;

static void trace_consider(trace_hit_t *best, bool *found, num_t t, geom_kind_t kind, uint16_t index, uint16_t id,
                           bool exit)
{
    if (*found && (t > best->t || (t == best->t && id > best->id)))
        return;
    *found = true;
    best->t = t;
    best->kind = kind;
    best->index = index;
    best->id = id;
    best->exit = exit;
}

/* Could the ray meet a bounded object? It must meet the sphere around
 * their box (world_t.bc, br2) at some t >= 0 or start inside it: with
 * oc = c - o and b = oc . d, a miss is b < 0 with o outside, or a closest
 * approach |oc|^2 - b^2 beyond the radius. No division; the products are
 * exact in Q16.16's wide type, and the padding covers the rounding of b. */
static bool trace_in_bounds(const world_t *w, const ray_t *ray)
{
    if (!w->bounded)
        return false;
    if (FXRT_NO_BOUNDS)
        return true; /* every bounded object tested (the frames are the same) */
    vec3_t oc = vec3_sub(w->bc, ray->o);
    numw_t oc2 = vec3_dotw(oc, oc);
    if (oc2 <= w->br2)
        return true; /* starts inside */
    num_t b = vec3_dot(oc, ray->d);
    if (b < NUM_ZERO)
        return false; /* outside and moving away */
    return numw_sub(oc2, numw_mul(b, b)) <= w->br2;
}

/* Nearest object along a secondary ray, with the self-intersection rule of
 * trace.h. */
__attribute__((noinline)) static bool trace_nearest(const world_t *w, const trace_ray_t *tr, trace_hit_t *hit)
{
    bool found = false;
    num_t t;
    vec3_t n;
    const ray_t *ray = &tr->ray;
    FXRT_IF_MODEL(uint32_t tri = BVH_NONE;)
    FXRT_COUNT(secondary_rays);
    /* The unbounded kinds first; the bounded ones only when the ray
     * meets their bounds. A solid the ray starts in is met where the ray
     * leaves it (its exit), any other object the ray leaves is not met,
     * but for a model only the triangle it leaves. */
#define TRACE_KIND(K, k, ks, cap, solid, form)                                                                \
    for (uint16_t i = 0; i < w->n_##ks; i++) {                                                                \
        const geom_##k##_t *o = &w->ks[i];                                                                    \
        TRACE_KIND_##solid(K, k, form)                                                                        \
    }
#define TRACE_KIND_0(K, k, form)                                                                              \
    if (TRACE_HITS_##form(k)) {                                                                               \
        trace_consider(hit, &found, t, GEOM_##K, i, o->obj.id, false);                                        \
        TRACE_TRI_##form(K)                                                                                   \
    }
#define TRACE_TRI_FLAT(K)
#define TRACE_TRI_ROUND(K)
#define TRACE_TRI_FACES(K)
#define TRACE_TRI_RAYS(K)                                                                                     \
    if (hit->kind == GEOM_##K && hit->index == i) /* (taken: the nearest so far) */                          \
        hit->tri = tri;
#define TRACE_HITS_FLAT(k) (o->obj.id != tr->from && geom_##k##_hit(o, ray, &t))
#define TRACE_HITS_ROUND TRACE_HITS_FLAT
#define TRACE_HITS_FACES TRACE_HITS_FLAT
#define TRACE_HITS_RAYS(k) geom_##k##_hit_from(o, ray, o->obj.id == tr->from ? tr->from_tri : BVH_NONE, &t, &tri)
#define TRACE_KIND_1(K, k, form)                                                                                  \
    if (o->obj.id == tr->from) {                                                                              \
        if (tr->inward && geom_##k##_exit(o, ray, &t, &n))                                                    \
            trace_consider(hit, &found, t, GEOM_##K, i, o->obj.id, true);                                     \
    } else if (geom_##k##_hit(o, ray, &t))                                                                    \
        trace_consider(hit, &found, t, GEOM_##K, i, o->obj.id, false);
#define TRACE_UNBOUNDED(K, k, ks, cap, solid, bounded, form, ...)                                            \
    FXRT_UNLESS(bounded, FXRT_IF_##K(TRACE_KIND(K, k, ks, cap, solid, form)))
#define TRACE_BOUNDED(K, k, ks, cap, solid, bounded, form, ...)                                              \
    FXRT_WHEN(bounded, FXRT_IF_##K(TRACE_KIND(K, k, ks, cap, solid, form)))
    FXRT_KINDS(TRACE_UNBOUNDED)
    if (!trace_in_bounds(w, ray)) {
        FXRT_COUNT(bounds_skips);
        return found;
    }
    FXRT_KINDS(TRACE_BOUNDED)
#undef TRACE_UNBOUNDED
#undef TRACE_BOUNDED
    (void)n;
    return found;
}

/* The hit point's t and geometric normal (as the kernels give them).
 * trace_nearest, trace_surface and trace_children are kept out of line so
 * that their temporaries are not all in trace_bounces' frame at once while
 * it shades (the 2 KB stack of the micro:bit). */
__attribute__((noinline)) static void trace_surface(const world_t *w, const trace_hit_t *h, const ray_t *ray, num_t *t,
                                                    vec3_t *n FXRT_IF_MODEL(, geom_part_t *part))
{
    FXRT_IF_MODEL(part->tri = BVH_NONE; part->smooth = false;
                  if (h->kind == GEOM_MODEL) {
                      geom_model_surface_part(&w->models[h->index], ray, h->tri, t, n, part);
                      return;
                  })
    switch (h->kind) {
#define TRACE_SURFACE(K, k, ks, cap, solid, ...)                                                              \
    FXRT_IF_##K(case GEOM_##K:                                                                                \
                FXRT_WHEN(solid, if (h->exit) (void)geom_##k##_exit(&w->ks[h->index], ray, t, n); else)       \
                geom_##k##_surface(&w->ks[h->index], ray, t, n);                                              \
                break;)
        FXRT_KINDS(TRACE_SURFACE)
#undef TRACE_SURFACE
    default: break;
    }
}

/* Is a weight below the cut-off, 1/512, in every channel? */
static bool trace_cut(color_t wt)
{
    num_t c = NUM(1.0 / 512);
    /* FXRT_NO_CUTOFF: a measurement build, no cut-off (fxrt_config.h). */
    return !FXRT_NO_CUTOFF && wt.r < c && wt.g < c && wt.b < c;
}

/* Can a bounce ray with direction v be traced? Q16.16: the kernels'
 * products with a ray's direction (vec3_dotw_unit, ray.h) need |v_i| <
 * 2^30 LSB (16384.0). A refracted direction is not renormalised and its
 * length error grows by about q^2 per refraction, so at extreme index
 * contrasts it can reach that (a direction 16384 times too long: nothing
 * left of the ray); such a ray is not traced. Float and double trace
 * every ray, as the model says. */
static bool trace_dir_ok(vec3_t v)
{
    const num_t lim = (num_t)((fx_t)1 << 30);
    return !NUM_EXACT || (v.x < lim && v.x > -lim && v.y < lim && v.y > -lim && v.z < lim && v.z > -lim);
}

/* One node of the tree: a hit and the ray that reached it. */
typedef struct {
    const geom_common_t *obj;
    vec3_t p, n_geo, d;
    color_t w;
    uint8_t bounce;
    FXRT_IF_MODEL(geom_part_t part;) /* a model's part met (tri BVH_NONE: another kind) */
    FXRT_IF_NORMALS(vec3_t n_side;) /* the flat face's normal (n_geo: the smooth one, where smooth) */
} trace_node_t;
/* The ray's triangle left out: a child ray leaves the node's. */
#define TRACE_FROM(nd) FXRT_IF_MODEL(, (nd)->part.tri)

/* The children of a node (at most two): their rays, the first in *out0,
 * the second in *out1 (returns how many, 0..2). */
__attribute__((noinline)) static int trace_children(const trace_node_t *nd, trace_ray_t *out0, trace_ray_t *out1)
{
    const material_t *m = &nd->obj->mat;
    vec3_t ng = nd->n_geo;
    /* Glass: the face's winding normal decides entering or leaving (a
     * mesh is not a solid of the table). A smooth face refracts about its
     * smooth normal where that agrees, else about the flat one. */
    FXRT_IF_NORMALS(if (m->kind == MATERIAL_TRANSPARENT &&
                        (vec3_dotw_units(nd->d, nd->n_side) > 0) != (vec3_dotw_units(nd->d, ng) > 0)) ng = nd->n_side;)
    numw_t dnw = vec3_dotw_units(nd->d, ng);
    bool inside = dnw > 0;                 /* the ray comes from the solid's inside */
    vec3_t n = inside ? vec3_neg_unit(ng) : ng; /* faces the incoming ray */
    num_t dn = numw_round(inside ? -dnw : dnw);               /* d . n <= 0 */
    /* Saturating products: a refracted d is not renormalised, and in
     * Q16.16 its length error grows by about q^2 at each refraction, so d
     * . n and q d are not bounded here (trace_dir_ok cuts the worst). */
    vec3_t r = vec3_sub(nd->d, vec3_scale_unit(n, num_mul_int(dn, 2)));
    uint8_t b = (uint8_t)(nd->bounce + 1);
    int k = 0;
    if (m->kind == MATERIAL_REFLECTIVE) {
        color_t wr = color_mul(nd->w, m->reflection);
        if (!trace_cut(wr) && trace_dir_ok(r))
            *(k++ == 0 ? out0 : out1) = (trace_ray_t){{nd->p, r}, wr, nd->obj->id, b, inside TRACE_FROM(nd)};
        return k;
    }
    /* Transparent. */
    num_t eta = m->index;
    num_t q = inside ? eta : num_div(NUM_ONE, eta);
    num_t cos_i = num_neg(dn);
    num_t sin2_i = num_sub(NUM_ONE, num_mul(cos_i, cos_i));
    num_t cos2_t = num_sub(NUM_ONE, num_mul(num_mul(q, q), sin2_i));
    if (cos2_t < NUM_ZERO) {
        /* Total internal reflection: the reflected ray with the full weight. */
        if (!trace_cut(nd->w) && trace_dir_ok(r))
            *(k++ == 0 ? out0 : out1) = (trace_ray_t){{nd->p, r}, nd->w, nd->obj->id, b, inside TRACE_FROM(nd)};
        return k;
    }
    num_t cos_t = num_sqrt(cos2_t);
    vec3_t td = vec3_add(vec3_scale_unit(nd->d, q), vec3_scale_unit(n, num_sub(num_mul(q, cos_i), cos_t)));
    num_t r0 = num_div(num_sub(NUM_ONE, eta), num_add(NUM_ONE, eta));
    r0 = num_mul(r0, r0);
    num_t x = num_sub(NUM_ONE, inside ? cos_t : cos_i);
    num_t x2 = num_mul(x, x);
    num_t x5 = num_mul(num_mul(x2, x2), x);
    num_t R = num_add(r0, num_mul(num_sub(NUM_ONE, r0), x5));
    color_t wr = color_scale(nd->w, R);
    /* The tint c_d as fractions: the colour is in 1/255 units. */
    num_t k255 = num_from_int(255);
    color_t c = nd->obj->color;
    color_t tint = color_make(num_div(c.r, k255), num_div(c.g, k255), num_div(c.b, k255));
    color_t wt = color_scale(color_mul(nd->w, tint), num_sub(NUM_ONE, R));
    if (!trace_cut(wr) && trace_dir_ok(r))
        *(k++ == 0 ? out0 : out1) = (trace_ray_t){{nd->p, r}, wr, nd->obj->id, b, inside TRACE_FROM(nd)};
    if (!trace_cut(wt) && trace_dir_ok(td))
        *(k++ == 0 ? out0 : out1) = (trace_ray_t){{nd->p, td}, wt, nd->obj->id, b, !inside TRACE_FROM(nd)};
    return k;
}

/* A smooth triangle (scene/smooth.c) reflects about its interpolated
 * normal at p; *n keeps the flat face's where there is none. */
FXRT_IF_SMOOTH(static void trace_smooth(const world_t *w, geom_kind_t kind, uint16_t index, vec3_t p, vec3_t *n) {
    if (kind == GEOM_TRIANGLE && w->triangles[index].smooth) /* (no call for a flat one) */
        (void)geom_smooth_normal(&w->triangles[index], p, n);
})

color_t trace_bounces(const world_t *w, geom_kind_t kind, uint16_t index GEOM_PART_PARAM, const ray_t *ray, vec3_t p,
                      vec3_t n_geo, color_t local)
{
    trace_ray_t stack[TRACE_STACK_ENTRIES], spare;
    int sp = 0;
    color_t acc = local; /* the primary hit's weight is 1 */
    trace_node_t nd = {world_common(w, kind, index), p, n_geo, ray->d,
                       color_make(NUM_ONE, NUM_ONE, NUM_ONE), 0 FXRT_IF_MODEL(, {BVH_NONE, false, {NUM_ZERO, NUM_ZERO, NUM_ZERO}}),
                       FXRT_IF_NORMALS(n_geo)};
    FXRT_IF_SMOOTH(trace_smooth(w, kind, index, p, &nd.n_geo);)
    /* A smooth model reflects about its smooth normal too. */
    FXRT_IF_MODEL(if (part) nd.part = *part; if (nd.part.smooth) nd.n_geo = nd.part.ns;)
    bool have = true; /* nd holds a node whose children are still to be made */
    for (;;) {
        trace_ray_t next;
        bool go = false;
        if (have && material_bounces(nd.obj->mat.kind) && nd.bounce < w->depth) {
            /* The first child goes to next, the second (if any) onto the
             * stack: always room (see trace.h); no copy on the stack. */
            int nk = trace_children(&nd, &next, sp < TRACE_STACK_ENTRIES ? &stack[sp] : &spare);
            go = nk > 0;
            if (nk > 1 && sp < TRACE_STACK_ENTRIES)
                sp++;
        }
        have = false;
        if (!go) {
            if (sp == 0)
                break;
            next = stack[--sp];
        }
        trace_hit_t h = {NUM_ZERO, GEOM_PLANE, 0, 0, false FXRT_IF_MODEL(, BVH_NONE)};
        if (!trace_nearest(w, &next, &h)) {
            acc = color_add(acc, color_mul(w->background, next.w));
            continue;
        }
        num_t t;
        vec3_t n;
        trace_surface(w, &h, &next.ray, &t, &n FXRT_IF_MODEL(, &nd.part));
        nd.obj = world_common(w, h.kind, h.index);
        nd.p = ray_at(&next.ray, t);
        nd.n_geo = n;
        nd.d = next.ray.d;
        nd.w = next.w;
        nd.bounce = next.bounce;
        color_t c = shade_point_k(w, h.kind, h.index GEOM_PART_ARG(&nd.part), nd.p, n, nd.d, NULL, NULL);
        FXRT_IF_NORMALS(nd.n_side = n;)
        FXRT_IF_SMOOTH(trace_smooth(w, h.kind, h.index, nd.p, &nd.n_geo);)
        FXRT_IF_MODEL(if (nd.part.smooth) nd.n_geo = nd.part.ns;)
        acc = color_add(acc, color_mul(c, nd.w));
        have = true;
    }
    return acc;
}

#endif
