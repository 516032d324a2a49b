/* setup: the visibility pass's per-frame set-up (render_vis_setup): every
 * object's records, its camera-space coverage forms, screen bounds and
 * depth range by its kind's set-up (vis/setup_KIND.c), the back faces of
 * closed meshes, the visiting order and the rows' object masks. See
 * docs/ARCHITECTURE.md for the method. */
#include "vis/setup.h"

/* Do N and D share one strict sign over columns x0..x1 of output rows
 * r0..r1? Both are linear in the pixel offsets, so their signs at the
 * rectangle's four corners (exact integer values) decide for every pixel
 * inside it. */
static bool render_flat_front(const cam_t *cam, const render_flat_t *f, int32_t x0, int32_t x1, int32_t r0, int32_t r1)
{
    if (FXRT_NO_BOUNDS || x0 > x1 || r0 > r1)
        return false; /* (without bounds every pixel is scanned) */
    int pos = 0, neg = 0;
    for (int k = 0; k < 4; k++) {
        int32_t ix = 2 * ((k & 1) ? x1 : x0) - cam->width + 1, iy = cam->height - 1 - 2 * ((k & 2) ? r1 : r0);
        render_k_t n = rlin_at(&f->n, ix, iy), d = rlin_at(&f->d, ix, iy);
        pos += n > 0 && d > 0;
        neg += n < 0 && d < 0;
    }
    return pos == 4 || neg == 4;
}

/* (Re)compute object i's forms and bounds from its world object. */
void render_setup_object(vis_t *r, uint16_t i)
{
    const world_t *w = r->world;
    const cam_t *cam = r->cam;
    rext_t ext = {(uint32_t)(cam->width - 1), (uint32_t)(cam->height - 1)};
    render_obj_t *o = &r->obj[i];
    vec3_t lo, hi;
    (void)ext, (void)w, (void)lo, (void)hi;
    switch (o->geom) {
/* A kind of the rays form has no set-up of its own: its box's bounds
 * (render_setup_rays). */
#define RENDER_SETUP_CASE(K, k, ks, cap, solid, bounded, form, ...) FXRT_IF_##K(case GEOM_##K: RENDER_SETUP_##form(k, ks); break;)
#define RENDER_SETUP_FLAT(k, ks) render_setup_##k(r, ext, &w->ks[o->index], o)
#define RENDER_SETUP_ROUND RENDER_SETUP_FLAT
#define RENDER_SETUP_FACES RENDER_SETUP_FLAT
#define RENDER_SETUP_RAYS(k, ks) (geom_##k##_bounds(&w->ks[o->index], &lo, &hi), render_setup_rays(r, lo, hi, o))
        FXRT_KINDS(RENDER_SETUP_CASE)
#undef RENDER_SETUP_CASE
    default: break;
    }
    FXRT_IF_MODEL(if (o->geom == GEOM_MODEL) render_setup_cut(r, o);)
    for (int k = 0; k < o->nflat && (render_kind(o) == RENDER_FLAT || render_kind(o) == RENDER_BOX); k++) {
        render_flat_t *f = render_face(o, k);
        f->front = false; /* (Q16.16 alone uses it) */
        if (NUM_EXACT && render_kind(o) == RENDER_FLAT)
            f->front = render_flat_front(cam, f, o->x0, o->x1, o->r0, o->r1);
        else if (NUM_EXACT)
            f->front = render_flat_front(cam, f, o->u.face[k].x0, o->u.face[k].x1, o->u.face[k].r0, o->u.face[k].r1);
    }
}

/* Register an object of the world in scene-array order. */
static void render_add(vis_t *r, geom_kind_t kind, uint16_t index, const geom_common_t *c)
{
    uint16_t i = r->count++;
    render_obj_t *o = &r->obj[i];
    o->geom = kind;
    o->index = index;
    o->id = c->id;
    o->rgb = c->rgb;
#if FXRT_PIXEL == FXRT_RGB565
    o->px = color_565(c->rgb);
#endif
    o->ranged = false;
    o->flat = !geom_lit(c);
    /* Its records, by the form its kind takes (scene/kinds.h): a flat
     * piece or a sphere's forms of their own, or box faces from the pool
     * (boxes come last: the rest of the pool). */
    switch (kind) {
#define RENDER_RECORDS(K, k, ks, cap, solid, bounded, form, ...) FXRT_IF_##K(case GEOM_##K: RENDER_RECORDS_##form; break;)
#define RENDER_RECORDS_FLAT o->u.flat = &r->flats[r->flats_used++]
#define RENDER_RECORDS_ROUND o->u.sphere = &r->spheres[r->spheres_used++]
#define RENDER_RECORDS_FACES o->u.face = &r->box_faces[r->box_used]
#define RENDER_RECORDS_RAYS o->u.flat = NULL /* (no records: vis/rays.c) */
        FXRT_KINDS(RENDER_RECORDS)
#undef RENDER_RECORDS
#undef RENDER_RECORDS_FLAT
#undef RENDER_RECORDS_ROUND
#undef RENDER_RECORDS_FACES
#undef RENDER_RECORDS_RAYS
    default: break;
    }
    render_setup_object(r, i);
    if (RENDER_SROWS && render_kind(o) == RENDER_SPHERE && index < RENDER_SROW_SLOTS)
        render_srow_setup(r, i);
#if RENDER_HINTS
    if (render_kind(o) == RENDER_FLAT || render_kind(o) == RENDER_BOX) /* row coherence's guesses: a fixed start each frame */
        for (int k = 0; k < o->nflat; k++)
            for (int j = 0; j < 6; j++)
                render_face(o, k)->hint[j] = 0;
#endif
#if RENDER_ESTEP && RENDER_EDGES > 0
    /* The edges' row states, without columns yet this frame. */
    if (render_kind(o) != RENDER_SPHERE)
        for (int k = 0; k < o->nflat; k++) {
            render_flat_t *f = render_face(o, k);
            f->es = f->edges ? &r->estep[r->estep_used] : NULL;
            for (int j = 0; j < f->edges; j++) {
                f->es[j].iy = RENDER_ESTEP_NONE;
                f->es[j].dk = RENDER_ESTEP_NONE;
                f->es[j].next = RENDER_ESTEP_NO_ROW;
            }
            r->estep_used = (uint16_t)(r->estep_used + f->edges);
        }
#endif
    if (render_kind(o) == RENDER_BOX || render_kind(o) == RENDER_INSIDE_BOX)
        r->box_used = (uint16_t)(r->box_used + o->nflat);
}

const char *render_vis_setup(vis_t *r, const world_t *w, const cam_t *cam)
{
    r->error = NULL;
    if (cam->width > FXRT_RENDER_MAX_WIDTH)
        return r->error = "image wider than FXRT_RENDER_MAX_WIDTH";
    r->flats_used = r->spheres_used = r->box_used = r->estep_used = 0;
    r->world = w;
    r->cam = cam;
    r->count = 0;
    r->row_win = 0;
#if FXRT_NUMBER == FXRT_Q16
    r->sphere_cache = NULL;
#endif
    r->want_keys = false;
    if (FXRT_MAX_SAMPLES > 1) /* (read only then) */
        r->sampled = world_samples(w) > 1;
#if RENDER_VIS
    r->track = world_samples(w) > 1;
    FXRT_IF_LIGHTS(r->track = r->track || w->n_lit > 0;)
#endif
    r->nplanes = 0 FXRT_IF_PLANE(+w->n_planes);
    for (int32_t x = 0; x < cam->width; x++)
        r->owner[x] = 0;
    r->stamp = 0;
    if (RENDER_MESH)
        render_cull_meshes(r); /* before the triangles are set up: culled ones are not */
#define RENDER_ADD_KIND(K, k, ks, ...) FXRT_IF_##K(for (uint16_t i = 0; i < w->n_##ks; i++) render_add(r, GEOM_##K, i, &w->ks[i].obj);)
    FXRT_KINDS(RENDER_ADD_KIND)
#undef RENDER_ADD_KIND
    if (!FXRT_NO_ORDER)
        render_order(r);
    if (RENDER_ROW_MASKS)
        render_row_masks(r);
    return r->error;
}
