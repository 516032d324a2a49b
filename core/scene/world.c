/* world: nearest-hit search over the static object arrays. */
#include "scene/world.h"

/* Lighting's part of the world (FXRT_MAX_LIGHTS > 0): none of it, and
 * only a black ambient, when lighting is compiled out. */
#if FXRT_MAX_LIGHTS > 0
static void world_lights_init(world_t *w)
{
    w->ambient = color_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    w->n_lights = 0;
    w->n_lit = 0;
}
fxrt_err_t world_set_ambient(world_t *w, color_t ambient)
{
    fxrt_err_t e = light_check_fraction(ambient);
    if (e != FXRT_OK)
        return e;
    w->ambient = ambient;
    return FXRT_OK;
}
#else
static void world_lights_init(world_t *w)
{
    (void)w;
}
fxrt_err_t world_set_ambient(world_t *w, color_t ambient)
{
    fxrt_err_t e = light_check_fraction(ambient);
    if (e != FXRT_OK)
        return e;
    (void)w;
    return ambient.r == NUM_ZERO && ambient.g == NUM_ZERO && ambient.b == NUM_ZERO ? FXRT_OK : FXRT_ERR_MATERIAL;
}
#endif
/* Secondary rays' and the meshes' parts (below). */
static void world_bounce_init(world_t *w);
static void world_mesh_init(world_t *w);

void world_init(world_t *w, color_t background)
{
    w->background = background;
    w->background_rgb = color_to_rgb8(background);
    w->ready = WORLD_READY;
#define WORLD_EMPTY(K, k, ks, ...) FXRT_IF_##K(w->n_##ks = 0;)
    FXRT_KINDS(WORLD_EMPTY)
#undef WORLD_EMPTY
    world_mesh_init(w);
    world_lights_init(w);
    world_bounce_init(w);
    (void)world_set_samples(w, 1, false); /* (always accepted) */
}

/* Secondary rays' part of the world (FXRT_MAX_DEPTH > 0): the default
 * depth, and the bounds of the bounded objects. */
#if FXRT_MAX_DEPTH > 0
static void world_bounce_init(world_t *w)
{
    w->depth = FXRT_MAX_DEPTH < 4 ? FXRT_MAX_DEPTH : 4;
    w->n_bounce = 0;
    w->bounded = false;
}
static void world_depth_store(world_t *w, int32_t depth)
{
    w->depth = (uint8_t)depth;
}
/* Grow the bounds of the bounded objects by the box lo..hi. */
__attribute__((unused)) static void world_grow(world_t *w, vec3_t lo, vec3_t hi)
{
    if (!w->bounded) {
        w->bmin = lo;
        w->bmax = hi;
        w->bounded = true;
    } else {
        w->bmin = vec3_make(num_min(w->bmin.x, lo.x), num_min(w->bmin.y, lo.y), num_min(w->bmin.z, lo.z));
        w->bmax = vec3_make(num_max(w->bmax.x, hi.x), num_max(w->bmax.y, hi.y), num_max(w->bmax.z, hi.z));
    }
    /* The sphere through the box's corners, radius padded by one scene
     * unit: a kernel's hit may lie a little outside its object, and the
     * test's b = oc . d carries d's rounding times |oc| (at most 0.75 for
     * coordinates within +-8192 in Q16.16; trace.c). Half extents first:
     * the full extent may not fit Q16.16. */
    vec3_t h = vec3_make(num_half(num_sub(num_half(w->bmax.x), num_half(w->bmin.x))),
                         num_half(num_sub(num_half(w->bmax.y), num_half(w->bmin.y))),
                         num_half(num_sub(num_half(w->bmax.z), num_half(w->bmin.z))));
    w->bc = vec3_add(vec3_make(num_half(w->bmin.x), num_half(w->bmin.y), num_half(w->bmin.z)),
                     vec3_make(num_half(w->bmax.x), num_half(w->bmax.y), num_half(w->bmax.z)));
    num_t r = num_add(num_mul_int(numw_sqrt(vec3_dotw(h, h)), 2), NUM_ONE);
    w->br2 = numw_mul(r, r);
}
#else
static void world_bounce_init(world_t *w)
{
    (void)w;
}
static void world_depth_store(world_t *w, int32_t depth)
{
    (void)w, (void)depth;
}
__attribute__((unused)) static void world_grow(world_t *w, vec3_t lo, vec3_t hi)
{
    (void)w, (void)lo, (void)hi;
}
#endif

fxrt_err_t world_set_depth(world_t *w, int32_t depth)
{
    if (depth < 0 || depth > FXRT_MAX_DEPTH)
        return FXRT_ERR_DEPTH;
    world_depth_store(w, depth);
    return FXRT_OK;
}

fxrt_err_t world_set_samples(world_t *w, int32_t samples, bool adaptive)
{
    if (samples < 1 || samples > FXRT_MAX_SAMPLES || (adaptive && (!FXRT_ADAPTIVE || samples < 2)))
        return FXRT_ERR_SAMPLES;
    (void)w;
    FXRT_IF_SAMPLES(w->samples = (uint8_t)samples; w->adaptive = adaptive;)
    return FXRT_OK;
}

uint16_t world_count(const world_t *w)
{
    uint32_t n = 0; /* below 65536: fxrt_config.h bounds the total capacity */
#define WORLD_COUNT(K, k, ks, ...) FXRT_IF_##K(n += w->n_##ks;)
    FXRT_KINDS(WORLD_COUNT)
#undef WORLD_COUNT
    (void)w;
    return (uint16_t)n;
}

/* The closed meshes of the triangles (WORLD_MESH). */
#if WORLD_MESH
static void world_mesh_init(world_t *w)
{
    w->mesh_n = 0;
}
/* Link triangles mesh_n .. n_triangles - 1 (up to WORLD_MESH_N) into the
 * meshes of those before them. */
static void world_mesh_link_rest(world_t *w)
{
    while (w->mesh_n < w->n_triangles && w->mesh_n < WORLD_MESH_N) {
        mesh_link(w->triangles, w->mesh_n, w->mesh_up, w->mesh_bits);
        w->mesh_n++;
    }
}
void world_mesh_update(world_t *w)
{
    w->mesh_n = 0;
    world_mesh_link_rest(w);
}
#else
static void world_mesh_init(world_t *w)
{
    (void)w;
}
void world_mesh_update(world_t *w)
{
    (void)w;
}
#endif


/* A kind with capacity 0 is compiled out: adding one reports FXRT_ERR_FULL
 * without referencing its checks or constructor, so none of its code is
 * linked. A bounded object grows the world's bounds (secondary rays). */
int32_t world_add(world_t *w, const geom_desc_t *d)
{
    uint16_t id = world_count(w);
    fxrt_err_t e;
    vec3_t lo, hi;
    (void)lo, (void)hi, (void)id, (void)e;
    FXRT_IF_SMOOTH(if ((e = geom_smooth_check(d)) != FXRT_OK) return e;)
    switch (d->kind) {
#define WORLD_ADD(K, k, ks, cap, solid, bounded, form, edges, f1, t1, f2, t2, f3, t3, f4, t4)                         \
    case GEOM_##K:                                                                                            \
        FXRT_IF_##K(e = geom_##k##_check(GEOM_FIELDS(d, t1, t2, t3, t4) d->color);                                \
                    if (e != FXRT_OK) return e;                                                               \
                    if (w->n_##ks >= cap) return FXRT_ERR_FULL;                                               \
                    if (!geom_##k##_make(&w->ks[w->n_##ks], GEOM_FIELDS(d, t1, t2, t3, t4) d->color, id))         \
                        return FXRT_ERR_DIRECTION; /* a plane's normal too short to normalise */              \
                    FXRT_WHEN(bounded, if (FXRT_MAX_DEPTH > 0) {                                           \
                        geom_##k##_bounds(&w->ks[w->n_##ks], &lo, &hi);                                   \
                        world_grow(w, lo, hi);                                                             \
                    })                                                                                     \
                    w->n_##ks++;                                                                              \
                    break;)                                                                                   \
        return FXRT_ERR_FULL;
        FXRT_KINDS(WORLD_ADD)
#undef WORLD_ADD
    default:
        return FXRT_ERR_KIND;
    }
    FXRT_IF_SMOOTH(if (d->kind == GEOM_TRIANGLE) geom_smooth_set(&w->triangles[w->n_triangles - 1], d);)
#if WORLD_MESH
    if (d->kind == GEOM_TRIANGLE && w->mesh_n == (uint16_t)(w->n_triangles - 1)) /* (else linked by world_mesh_update only) */
        world_mesh_link_rest(w);
#endif
    return id;
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
#define WORLD_HIT(K, k, ks, ...)                                                                              \
    FXRT_IF_##K(for (uint16_t i = 0; i < w->n_##ks; i++) if (geom_##k##_hit(&w->ks[i], ray, &t))             \
                    world_consider(hit, &found, t, GEOM_##K, i, &w->ks[i].obj);)
    FXRT_KINDS(WORLD_HIT)
#undef WORLD_HIT
    if (found)
        hit->point = ray_at(ray, hit->t);
    return found;
}

const geom_common_t *world_common(const world_t *w, geom_kind_t kind, uint16_t index)
{
    switch (kind) {
#define WORLD_COMMON(K, k, ks, ...) FXRT_IF_##K(case GEOM_##K: return &w->ks[index].obj;)
        FXRT_KINDS(WORLD_COMMON)
#undef WORLD_COMMON
    default: break;
    }
    return 0;
}

bool world_find(const world_t *w, uint16_t id, geom_kind_t *kind, uint16_t *index)
{
    /* Ids are assigned in order of addition across kinds, so search each
     * kind's array (ids within a kind increase). */
#define WORLD_FIND(K, k, ks, ...)                                                                             \
    FXRT_IF_##K(for (uint16_t i = 0; i < w->n_##ks; i++) if (w->ks[i].obj.id == id) {                        \
        *kind = GEOM_##K;                                                                                     \
        *index = i;                                                                                           \
        return true;                                                                                          \
    })
    FXRT_KINDS(WORLD_FIND)
#undef WORLD_FIND
    (void)w, (void)id, (void)kind, (void)index;
    return false;
}

fxrt_err_t light_check_fraction(color_t c)
{
    /* A fraction colour is a colour with NUM_ONE as full intensity. */
    if (!(c.r >= NUM_ZERO && c.r <= NUM_ONE && c.g >= NUM_ZERO && c.g <= NUM_ONE && c.b >= NUM_ZERO &&
          c.b <= NUM_ONE))
        return FXRT_ERR_COLOR;
    return geom_check_color(c);
}


fxrt_err_t world_check_material(const material_t *m)
{
    if (m->kind == MATERIAL_FLAT)
        return FXRT_OK; /* always possible */
    if (FXRT_MAX_LIGHTS == 0)
        return FXRT_ERR_MATERIAL; /* lighting compiled out */
    if (m->kind == MATERIAL_LAMBERT)
        return FXRT_OK;
    if (m->kind == MATERIAL_PHONG || m->kind == MATERIAL_REFLECTIVE) {
        if (!FXRT_PHONG)
            return FXRT_ERR_MATERIAL;
        if (m->exponent < 1 || m->exponent > FXRT_PHONG_MAX_EXPONENT)
            return FXRT_ERR_EXPONENT;
        fxrt_err_t e = light_check_fraction(m->specular);
        if (e == FXRT_OK && m->kind == MATERIAL_REFLECTIVE)
            e = light_check_fraction(m->reflection);
        return e;
    }
    if (m->kind == MATERIAL_TRANSPARENT)
        /* (x >= lo && x <= hi) also refuses NaN */
        return m->index >= NUM(FXRT_INDEX_MIN) && m->index <= NUM(FXRT_INDEX_MAX) ? FXRT_OK : FXRT_ERR_INDEX;
    return FXRT_ERR_MATERIAL;
}

fxrt_err_t world_set_material(world_t *w, int32_t id, const material_t *m)
{
    geom_kind_t kind;
    uint16_t index;
    if (id < 0 || id > 0xFFFF || !world_find(w, (uint16_t)id, &kind, &index))
        return FXRT_ERR_ID;
    fxrt_err_t e = world_check_material(m);
    if (e != FXRT_OK)
        return e;
#if FXRT_MAX_LIGHTS > 0
    geom_common_t *c = (geom_common_t *)world_common(w, kind, index);
    bool was = c->mat.kind != MATERIAL_FLAT, is = m->kind != MATERIAL_FLAT;
    bool was_b = material_bounces(c->mat.kind), is_b = material_bounces(m->kind);
    (void)was_b, (void)is_b;
    c->mat = *m;
    /* Fields the kind does not use are stored as zero. */
    color_t black = color_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    if (m->kind != MATERIAL_PHONG && m->kind != MATERIAL_REFLECTIVE) {
        c->mat.exponent = 0;
        c->mat.specular = black;
    }
    if (m->kind != MATERIAL_REFLECTIVE)
        c->mat.reflection = black;
    if (m->kind != MATERIAL_TRANSPARENT)
        c->mat.index = NUM_ZERO;
    FXRT_IF_DEPTH(w->n_bounce = (uint16_t)(w->n_bounce + is_b - was_b);)
    w->n_lit = (uint16_t)(w->n_lit + is - was);
#else
    (void)kind, (void)index; /* flat: nothing to store */
#endif
    return FXRT_OK;
}

int32_t world_add_light(world_t *w, light_kind_t kind, vec3_t position, vec3_t direction, num_t angle_deg,
                        color_t color, bool shadows)
{
    if (kind != LIGHT_POINT && kind != LIGHT_DIRECTIONAL && kind != LIGHT_SPOT)
        return FXRT_ERR_LIGHT;
    fxrt_err_t e = FXRT_OK;
    if (kind != LIGHT_DIRECTIONAL)
        e = geom_check_point(position);
    if (e == FXRT_OK && kind != LIGHT_POINT)
        e = geom_check_dir(direction);
    if (e == FXRT_OK && kind == LIGHT_SPOT && !(angle_deg > NUM_ZERO && angle_deg <= num_from_int(90)))
        e = FXRT_ERR_ANGLE;
    if (e == FXRT_OK)
        e = light_check_fraction(color);
    if (e != FXRT_OK)
        return e;
#if FXRT_MAX_LIGHTS > 0
    if (w->n_lights >= FXRT_MAX_LIGHTS)
        return FXRT_ERR_LIGHTS;
    light_t *l = &w->lights[w->n_lights];
    l->kind = (uint8_t)kind;
    l->shadows = shadows;
    l->position = kind == LIGHT_DIRECTIONAL ? vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO) : position;
    l->dir = vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    l->cos_angle = NUM_ZERO;
    l->color = color;
    l->axes[0] = 0;
    l->axes[1] = 0;
    if (kind != LIGHT_POINT) {
        /* The direction is normalised once, here: a directional light's l
         * (towards the light) is -direction / |direction| at every pixel. */
        vec3_t d = kind == LIGHT_DIRECTIONAL ? vec3_neg(direction) : direction;
        if (!vec3_normalize(&d))
            return FXRT_ERR_DIRECTION;
        l->dir = d;
        light_dir_axes(d, l->axes);
    }
    if (kind == LIGHT_SPOT) {
        l->cos_angle = num_cos_deg(angle_deg);
#if FXRT_NUMBER == FXRT_Q16
        fx_t s[3] = {direction.x, direction.y, direction.z};
        fx_unit30(s, l->axis30);
        l->cos30 = fx_cos_deg_q30(angle_deg);
#endif
    }
    return w->n_lights++;
#else
    (void)w, (void)shadows;
    return FXRT_ERR_LIGHTS;
#endif
}
