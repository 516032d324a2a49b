/* render_shade: the shading pass. The visibility pass (vis/) leaves in r->vis the object that owns each column of the
 * row; here each pixel owned by a lit object gets its colour from the
 * lighting model (light/shade.c): the pixel's camera ray (cam_ray), the
 * owner's surface point and normal (geom_<kind>_surface: one object, no
 * search; a model's from the triangle its visibility pass met), and the
 * light sum. Flat objects keep the colour the visibility
 * pass painted. With r->keys set, every pixel's key is written too. */
#include "frame/render.h"
#include "vis/render_int.h"

#if FXRT_MAX_LIGHTS > 0
void render_shade_setup(render_t *r, const world_t *w)
{
    render_shade_t *sh = &r->shade;
    sh->any_lit = w->n_lit > 0;
    unsigned dir = 0, spot = 0;
    for (unsigned i = 0; i < w->n_lights; i++) {
        dir += w->lights[i].kind == LIGHT_DIRECTIONAL;
        spot += w->lights[i].kind == LIGHT_SPOT;
    }
    sh->all_directional = dir == w->n_lights;
    sh->all_spots = spot > 0 && spot == w->n_lights;
    sh->no_directional = dir == 0;
    sh->flat_of = RENDER_VIS_NONE;
    SHADE_IF_CULL(if (sh->any_lit) shadow_cull_setup(w, &sh->cull), shade_plane_heights(w, &sh->cull);
                  shadow_rows_clear(&sh->cull);)
    for (uint16_t i = 0; sh->any_lit && i < r->vis.count; i++) {
        const geom_common_t *c = world_common(w, (geom_kind_t)r->vis.obj[i].geom, r->vis.obj[i].index);
        if (c->mat.kind != MATERIAL_FLAT) {
            shade_consts(w, c, &sh->k[i]);
            SHADE_IF_CULL(sh->k[i].cull = &sh->cull;)
        }
    }
}

/* A pinhole camera's rays all start at the eye e, so an object of a FLAT
 * form keeps its hit numerator (a - e) . n in r->shade.flat
 * (shade_flat_t) for the next pixel of vis object r->shade.flat_of.
 * render_flat_take makes vis object oi that object, when it is flat
 * (false: it is not). Out of line: its frame is not on the shading
 * path's stack. */
#define RENDER_FLAT_OF(K, k, ks, cap, solid, bounded, form, ...) RENDER_FLAT_OF_##form(K, ks)
#define RENDER_FLAT_OF_FLAT(K, ks)                                                                               \
    FXRT_IF_##K(case GEOM_##K:                                                                                  \
                num = geom_flat_num(&w->ks[o->index].a, &w->ks[o->index].n, &ray->o);                          \
                f->obj = &w->ks[o->index].obj;                                                                  \
                f->n = &w->ks[o->index].n;                                                                      \
                break;)
#define RENDER_FLAT_OF_ROUND(K, ks)
#define RENDER_FLAT_OF_FACES(K, ks)
#define RENDER_FLAT_OF_RAYS(K, ks)
static __attribute__((noinline)) bool render_flat_take(render_t *r, uint16_t oi, const ray_t *ray)
{
    const world_t *w = r->vis.world;
    const render_obj_t *o = &r->vis.obj[oi];
    shade_flat_t *f = &r->shade.flat;
    numw_t num;
    (void)w, (void)ray; /* (no kind of the FLAT form: unused) */
    switch (o->geom) {
        FXRT_KINDS(RENDER_FLAT_OF)
    default: return false; /* not flat */
    }
    FXRT_COUNT(flat_nums);
    f->num = numw_dividend(num);
    f->ratio = numw_ratio_num(num);
    f->index = o->index;
    f->kind = o->geom;
    shade_flat_prep(f, r->shade.all_directional, r->shade.all_spots, r->shade.no_directional,
                    o->flat ? NULL : &r->shade.k[oi]);
    r->shade.flat_of = oi;
    return true;
}
#undef RENDER_FLAT_OF_RAYS
#undef RENDER_FLAT_OF_FACES
#undef RENDER_FLAT_OF_ROUND
#undef RENDER_FLAT_OF_FLAT
#undef RENDER_FLAT_OF

/* Is vis object oi of a FLAT form, and now r->shade.flat's? one_eye: a
 * pinhole camera, whose flat objects keep their hit numerators (only
 * ray->o is read). */
static inline __attribute__((always_inline)) bool render_flat_of(render_t *r, uint16_t oi, const ray_t *ray,
                                                                   bool one_eye)
{
    return one_eye && (r->shade.flat_of == oi || render_flat_take(r, oi, ray));
}

/* The colour of vis object oi along camera ray `ray` as cam_ray_raw makes
 * it (d not normalised; normalised here where it is needed). flat: the
 * object is r->shade.flat's (render_flat_of). */
static inline __attribute__((always_inline)) color_t render_shade_obj(render_t *r, uint16_t oi, ray_t *ray,
                                                                       uint8_t *mask, bool flat)
{
    const render_obj_t *o = &r->vis.obj[oi];
    const shade_k_t *k = o->flat ? NULL : &r->shade.k[oi];
    if (flat) {
        const shade_flat_t *f = &r->shade.flat;
        /* (a lambert plane under directional lights only: its own call,
         * which makes no hit point where it needs none) */
        if (f->flags == (SHADE_FLAT_LAMBERT | SHADE_FLAT_DIRECTIONAL))
            return shade_flat_plane_dir(r->vis.world, f, k, ray, mask);
        return f->flags & SHADE_FLAT_LAMBERT ? shade_flat_plane(r->vis.world, f, k, ray, mask)
                                             : shade_flat_k(r->vis.world, f, ray, k, mask);
    }
    return shade_object_k(r->vis.world, (geom_kind_t)o->geom, o->index, ray, r->vis.cam, k, mask);
}

color_t render_shade_object(render_t *r, uint16_t oi, ray_t *ray, uint8_t *mask)
{
    return render_shade_obj(r, oi, ray, mask,
                            render_flat_of(r, oi, ray, r->vis.cam->kind == CAM_PERSPECTIVE && !FXRT_NO_FLAT_NUM));
}

/* Pixel x of a run of object o (flat: a flat piece, r->shade.flat) on a
 * direct row of camera cam, w pixels wide. */
static inline __attribute__((always_inline)) void render_shade_run_px(render_t *r, const render_obj_t *o, bool flat,
                                                                      const shade_k_t *k, const cam_row_t *cr,
                                                                      const vec3_t *u, const vec3_t *fwd, const cam_t *cam,
                                                                      int32_t w, int32_t x, ray_t *ray, uint8_t *rgb)
{
    cam_row_dir(cr, u, fwd, 2 * x - w + 1, ray);
    color_t c = flat ? shade_flat_k(r->vis.world, &r->shade.flat, ray, k, NULL)
                     : shade_object_k(r->vis.world, (geom_kind_t)o->geom, o->index, ray, cam, k, NULL);
    color_put_pixel(rgb, x, color_to_rgb8(c));
}

void render_shade_row(render_t *r, int32_t row, uint8_t *rgb)
{
    const cam_t *cam = r->vis.cam;
    int32_t w = cam->width, y = cam->height - 1 - row;
    /* The row's shadow masks for planes (light/shade.h), cleared after it:
     * they hold for this row's camera rays only. */
    SHADE_IF_CULL(if (SHADOW_ROWS && r->shade.any_lit) shadow_rows_setup(r->vis.world, cam, y, &r->shade.cull);)
    bool one_eye = cam->kind == CAM_PERSPECTIVE && !FXRT_NO_FLAT_NUM;
    cam_row(cam, y, &r->shade.row, &r->shade.ray);
    uint32_t *keys = r->keys; /* (read once: the loop does not change it) */
    ray_t *ray = &r->shade.ray;
    /* Where registers are many (not Armv6-M), the row and the camera's u
     * and fwd in locals, which the calls below cannot change: no reload
     * per pixel. Armv6-M reads them from the frame (its 2 KB stack). */
    struct {
        cam_row_t row;
        vec3_t u, fwd;
    } own = {r->shade.row, cam->u, cam->fwd};
    const cam_row_t *cr = FXRT_PORT_SMALL_ISA ? &r->shade.row : &own.row;
    const vec3_t *u = FXRT_PORT_SMALL_ISA ? &cam->u : &own.u, *fwd = FXRT_PORT_SMALL_ISA ? &cam->fwd : &own.fwd;
    for (int32_t x = 0; x < w; x++) {
        uint16_t oi = r->vis.painted[x];
        if (oi == RENDER_VIS_NONE) {
            if (keys)
                keys[x] = RENDER_KEY_MISS;
            continue;
        }
        const render_obj_t *o = &r->vis.obj[oi];
        bool lit = !o->flat;
        if (!lit && !keys)
            continue;
        bool flat = FXRT_IF_MODEL(o->geom != GEOM_MODEL &&) render_flat_of(r, oi, ray, one_eye);
        /* A run of pixels of one lit object (no keys, a direct row): a
         * Lambert plane's in one call (light/shade.c), another's in a
         * loop without the tests above. */
        if (FXRT_SHADE_RUNS && lit && !keys && cr->direct FXRT_IF_MODEL(&&o->geom != GEOM_MODEL)) {
            int32_t end = x + 1;
            while (end < w && r->vis.painted[end] == oi)
                end++;
            const shade_k_t *k = &r->shade.k[oi];
            if (flat && (r->shade.flat.flags & SHADE_FLAT_LAMBERT))
                shade_flat_plane_run(r->vis.world, &r->shade.flat, k, cr, u, fwd, w, x, end, ray, rgb);
            else if (flat && (r->shade.flat.flags & SHADE_FLAT_PHONG_POINT))
                /* a Phong plane under point and spot lights: the blocks
                 * that no light reaches, those without a specular term
                 * (the Lambert sum), and each other pixel */
                for (int32_t i = x, stop; i < end; i = stop) {
                    bool lambert;
                    i = shade_flat_phong_blocks(r->vis.world, &r->shade.flat, k, cr, u, fwd, w, i, end, ray, rgb,
                                                &stop, &lambert);
                    if (lambert)
                        shade_flat_plane_pixels(r->vis.world, &r->shade.flat, k, cr, u, fwd, w, i, stop, ray, rgb);
                    else
                        for (; i < stop; i++)
                            render_shade_run_px(r, o, true, k, cr, u, fwd, cam, w, i, ray, rgb);
                }
            else if (flat && (r->shade.flat.flags & (SHADE_FLAT_PHONG_DIR | SHADE_FLAT_SPOTS)))
                /* a Phong plane under directional lights (its stretches
                 * with no specular term) or under spots (the blocks that
                 * no spot reaches) at once, then each other pixel */
                for (int32_t i = x, stop; i < end;)
                    for (i = r->shade.flat.flags & SHADE_FLAT_PHONG_DIR /* (direct calls: tests/norecurse.sh) */
                                 ? shade_flat_phong_span(r->vis.world, &r->shade.flat, k, cr, u, fwd, w, i, end, ray,
                                                         rgb, &stop)
                                 : shade_flat_spot_blocks(r->vis.world, &r->shade.flat, k, cr, u, fwd, w, i, end, ray,
                                                          rgb, &stop);
                         i < stop; i++)
                        render_shade_run_px(r, o, true, k, cr, u, fwd, cam, w, i, ray, rgb);
            else
                for (int32_t i = x; i < end; i++)
                    render_shade_run_px(r, o, flat, k, cr, u, fwd, cam, w, i, ray, rgb);
            x = end - 1;
            continue;
        }
        uint8_t mask = 0;
        if (cr->direct)
            cam_row_dir(cr, u, fwd, 2 * x - w + 1, ray);
        else
            cam_ray_raw(cam, x, cr->y, ray);
        color_t c;
        FXRT_IF_MODEL(if (o->geom == GEOM_MODEL) /* its triangle: the visibility pass's (vis/rays.c) */
                      c = (cam_ray_unit(cam, ray), shade_model_k(r->vis.world, o->index, ray, r->vis.model_tri[x], lit ? &r->shade.k[oi] : NULL,
                                        keys ? &mask : NULL));
                      else)
        c = render_shade_obj(r, oi, ray, keys ? &mask : NULL, flat);
        if (keys)
            keys[x] = render_key(o->id, mask);
        if (!lit)
            continue;
        rgb8_t p = color_to_rgb8(c);
        color_put_pixel(rgb, x, p);
    }
    SHADE_IF_CULL(if (SHADOW_ROWS && r->shade.any_lit) shadow_rows_clear(&r->shade.cull);)
}
#endif
