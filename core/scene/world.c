/* world: nearest-hit search over the static object arrays. */
#include "scene/world.h"

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
#if WORLD_MESH
    w->mesh_n = 0;
#endif
#if FXRT_MAX_BOXES > 0
    w->n_boxes = 0;
#endif
#if FXRT_MAX_LIGHTS > 0
    w->ambient = color_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    w->n_lights = 0;
    w->n_lit = 0;
#endif
#if FXRT_MAX_DEPTH > 0
    w->depth = FXRT_MAX_DEPTH < 4 ? FXRT_MAX_DEPTH : 4;
    w->n_bounce = 0;
    w->bounded = false;
#endif
#if FXRT_MAX_SAMPLES > 1
    w->samples = 1;
    w->adaptive = false;
#endif
}

/* Grow the bounds of the bounded objects by the box lo..hi. */
__attribute__((unused)) static void world_grow(world_t *w, vec3_t lo, vec3_t hi)
{
#if FXRT_MAX_DEPTH > 0
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
#else
    (void)w, (void)lo, (void)hi;
#endif
}

fxrt_err_t world_set_depth(world_t *w, int32_t depth)
{
    if (depth < 0 || depth > FXRT_MAX_DEPTH)
        return FXRT_ERR_DEPTH;
#if FXRT_MAX_DEPTH > 0
    w->depth = (uint8_t)depth;
#else
    (void)w;
#endif
    return FXRT_OK;
}

fxrt_err_t world_set_samples(world_t *w, int32_t samples, bool adaptive)
{
    if (samples < 1 || samples > FXRT_MAX_SAMPLES || (adaptive && (!FXRT_ADAPTIVE || samples < 2)))
        return FXRT_ERR_SAMPLES;
#if FXRT_MAX_SAMPLES > 1
    w->samples = (uint8_t)samples;
    w->adaptive = adaptive;
#else
    (void)w;
#endif
    return FXRT_OK;
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
    world_grow(w, vec3_sub(center, vec3_make(radius, radius, radius)),
               vec3_add(center, vec3_make(radius, radius, radius)));
    return id;
#else
    (void)w;
    (void)center, (void)radius, (void)color;
    return FXRT_ERR_FULL;
#endif
}

#if WORLD_MESH
/* Link triangles mesh_n .. n_triangles - 1 (up to WORLD_MESH_N) into the
 * meshes of those before them. */
static void world_mesh_link_rest(world_t *w)
{
    while (w->mesh_n < w->n_triangles && w->mesh_n < WORLD_MESH_N) {
        mesh_link(w->triangles, w->mesh_n, w->mesh_up, w->mesh_bits);
        w->mesh_n++;
    }
}
#endif

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
#if WORLD_MESH
    if (w->mesh_n == (uint16_t)(w->n_triangles - 1)) /* (else linked by world_mesh_update only) */
        world_mesh_link_rest(w);
#endif
    world_grow(w, vec3_make(num_min(a.x, num_min(b.x, c.x)), num_min(a.y, num_min(b.y, c.y)),
                            num_min(a.z, num_min(b.z, c.z))),
               vec3_make(num_max(a.x, num_max(b.x, c.x)), num_max(a.y, num_max(b.y, c.y)),
                         num_max(a.z, num_max(b.z, c.z))));
    return id;
#else
    (void)w;
    (void)a, (void)b, (void)c, (void)color;
    return FXRT_ERR_FULL;
#endif
}

void world_mesh_update(world_t *w)
{
#if WORLD_MESH
    w->mesh_n = 0;
    world_mesh_link_rest(w);
#else
    (void)w;
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
    world_grow(w, min, max);
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

const geom_common_t *world_common(const world_t *w, geom_kind_t kind, uint16_t index)
{
    switch (kind) {
#if FXRT_MAX_PLANES > 0
    case GEOM_PLANE: return &w->planes[index].obj;
#endif
#if FXRT_MAX_SPHERES > 0
    case GEOM_SPHERE: return &w->spheres[index].obj;
#endif
#if FXRT_MAX_TRIANGLES > 0
    case GEOM_TRIANGLE: return &w->triangles[index].obj;
#endif
#if FXRT_MAX_BOXES > 0
    case GEOM_BOX: return &w->boxes[index].obj;
#endif
    default: break;
    }
    return 0;
}

bool world_find(const world_t *w, uint16_t id, geom_kind_t *kind, uint16_t *index)
{
    static const geom_kind_t kinds[4] = {GEOM_PLANE, GEOM_SPHERE, GEOM_TRIANGLE, GEOM_BOX};
    uint16_t counts[4] = {0, 0, 0, 0};
#if FXRT_MAX_PLANES > 0
    counts[0] = w->n_planes;
#endif
#if FXRT_MAX_SPHERES > 0
    counts[1] = w->n_spheres;
#endif
#if FXRT_MAX_TRIANGLES > 0
    counts[2] = w->n_triangles;
#endif
#if FXRT_MAX_BOXES > 0
    counts[3] = w->n_boxes;
#endif
    /* Ids are assigned in order of addition across kinds, so search each
     * kind's array (ids within a kind increase). */
    for (int k = 0; k < 4; k++)
        for (uint16_t i = 0; i < counts[k]; i++)
            if (world_common(w, kinds[k], i)->id == id) {
                *kind = kinds[k];
                *index = i;
                return true;
            }
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

fxrt_err_t world_set_ambient(world_t *w, color_t ambient)
{
    fxrt_err_t e = light_check_fraction(ambient);
    if (e != FXRT_OK)
        return e;
#if FXRT_MAX_LIGHTS > 0
    w->ambient = ambient;
    return FXRT_OK;
#else
    (void)w;
    return ambient.r == NUM_ZERO && ambient.g == NUM_ZERO && ambient.b == NUM_ZERO ? FXRT_OK : FXRT_ERR_MATERIAL;
#endif
}

fxrt_err_t world_set_material(world_t *w, int32_t id, const material_t *m)
{
    geom_kind_t kind;
    uint16_t index;
    if (id < 0 || id > 0xFFFF || !world_find(w, (uint16_t)id, &kind, &index))
        return FXRT_ERR_ID;
    if (m->kind == MATERIAL_FLAT)
        ; /* always possible */
    else if (m->kind == MATERIAL_LAMBERT)
        ;
    else if (m->kind == MATERIAL_PHONG || m->kind == MATERIAL_REFLECTIVE) {
        if (!FXRT_PHONG || m->exponent < 1 || m->exponent > FXRT_PHONG_MAX_EXPONENT)
            return FXRT_ERR_MATERIAL;
        fxrt_err_t e = light_check_fraction(m->specular);
        if (e == FXRT_OK && m->kind == MATERIAL_REFLECTIVE)
            e = light_check_fraction(m->reflection);
        if (e != FXRT_OK)
            return e;
    } else if (m->kind == MATERIAL_TRANSPARENT) {
        /* (x >= lo && x <= hi) also refuses NaN */
        if (!(m->index >= NUM(FXRT_INDEX_MIN) && m->index <= NUM(FXRT_INDEX_MAX)))
            return FXRT_ERR_MATERIAL;
    } else
        return FXRT_ERR_MATERIAL;
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
#if FXRT_MAX_DEPTH > 0
    w->n_bounce = (uint16_t)(w->n_bounce + is_b - was_b);
#endif
    w->n_lit = (uint16_t)(w->n_lit + is - was);
    return FXRT_OK;
#else
    return m->kind == MATERIAL_FLAT ? FXRT_OK : FXRT_ERR_MATERIAL;
#endif
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
        return FXRT_ERR_FULL;
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
    return FXRT_ERR_FULL;
#endif
}
