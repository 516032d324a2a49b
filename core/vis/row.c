/* row: the visibility pass of one row (render_row_vis): every object on
 * the row, nearest first, scanned by its form (vis/flat.c, vis/sphere.c
 * here: a sphere's scan is inlined into the row loop), the row's start
 * and the fill of the row buffer in the pixel format. */
#include "vis/scan.h"

/* Start a row: a new stamp (so every column is uncovered) and the
 * background in every pixel, with word stores where the row is aligned. */
void render_begin_row(vis_t *r, uint8_t *rgb)
{
    if (render_tracks(r))
        for (int32_t x = 0; x < r->cam->width; x++)
            render_mark(r, x, RENDER_VIS_NONE);
    if (++r->stamp == RENDER_STAMP_LIMIT) {
        for (int32_t x = 0; x < r->cam->width; x++)
            r->owner[x] = 0;
        r->stamp = 1;
    }
    if (FXRT_MAX_SAMPLES > 1 && r->sampled)
        return; /* the sampling pass reads vis, not the painted scratch row */
    render_fill_rgb(rgb, 0, r->cam->width - 1, r->world->background_rgb);
}

#if FXRT_NUMBER == FXRT_Q16 && !FXRT_NO_STEP
/* Orthographic sphere: c + disc = k + r2 (kr) along every ray, and v is
 * the one of them that was stepped (c when use_c). */
static bool render_resolve_ortho(vis_t *r, uint32_t cur, uint16_t oi, int32_t x, int32_t iy, render_k_t b,
                                 const fx128_t *kr, const fx128_t *v, bool use_c)
{
    fx128_t other = fx128_sub(*kr, *v);
    return render_resolve_sphere(r, cur, oi, x, iy, b, use_c ? v : &other, use_c ? &other : v);
}

/* Step a sphere over columns x0..x1: a lone one fills its runs, others
 * claim each covered column. */
static void render_scan_sphere(vis_t *r, uint16_t oi, const render_obj_t *o, int32_t x0, int32_t x1, int32_t iy,
                               uint8_t *rgb, bool lone)
{
    if (RENDER_SROWS && lone && r->cam->height >= 3 &&
        o->index < RENDER_SROW_SLOTS) { /* the series needs three rows */
        render_lone_sphere(r, oi, o, iy, rgb);
        return;
    }
    int32_t ix0 = 2 * x0 - r->cam->width + 1;
    /* The row's forms, in r->sphere_cache (render_row_vis's): kept for
     * render_depth_at while this row lasts (a lone sphere owns no column). */
    render_srow_t *sp = &r->sphere_cache->s;
    r->sphere_cache->ix0 = ix0;
    r->sphere_cache->iy = iy;
    r->sphere_cache->oi = lone ? RENDER_VIS_NONE : oi;
#if RENDER_SROWS
    if (!lone && r->cam->height >= 3 && o->index < FXRT_COHERENT_SPHERES) /* stepped from the row before */
        *sp = *render_sphere_row_at(r, o, render_row_of(r->cam, iy));
    else
#endif
        render_sphere_row(r, o, ix0, iy, sp);
    if (lone) {
        render_iv_t run[2];
        int nrun = render_sphere_runs(o, sp, x0, x1, ix0, iy, run);
        for (int k = 0; k < nrun; k++)
            render_fill(r, oi, x0 + run[k].lo, x0 + run[k].hi, rgb);
        return;
    }
    if (sp->inside) { /* eye inside: every pixel */
        for (int32_t x = x0; x <= x1; x++)
            render_cover(r, oi, x, iy, rgb);
        return;
    }
    bool rows = RENDER_SROWS && r->cam->height >= 3 && o->index < RENDER_SROW_SLOTS;
    if (!FXRT_NO_SPANS && (FXRT_SPHERE_SEARCH || RENDER_SROWS) && !sp->ortho && (rows || FXRT_SPHERE_SEARCH)) {
        /* Perspective: its runs located exactly (from the row before's
         * where it keeps row state, else by render_sphere_runs' search),
         * then claimed like a flat piece's; a depth, where an owner needs
         * one, comes from r->sphere_cache. */
        render_iv_t run[2];
        int nrun;
        if (rows)
            nrun = render_sphere_runs_at(r, o, render_row_of(r->cam, iy), sp, run);
        else
            nrun = render_sphere_runs(o, sp, x0, x1, ix0, iy, run);
        for (int k = 0; k < nrun; k++)
            render_claim_run(r, oi, NULL, x0 + run[k].lo, x0 + run[k].hi, iy, rgb, true);
        return;
    }
    bool ortho = sp->ortho, use_c = sp->use_c;
    fx128_t v, d1, d2;
    fx128_copy(&v, &sp->v);
    fx128_copy(&d1, &sp->d1);
    fx128_copy(&d2, &sp->d2);
    if (ortho) {
        /* c + disc = k + r2 along every ray (a = 1), and b is constant. */
        fx128_t kr = fx128_add(o->u.sphere->k, o->u.sphere->r2);
        render_k_t b = o->u.sphere->b.c;
        for (int32_t x = x0; x <= x1; x++, fx128_add_to(&v, &d1), fx128_add_to(&d1, &d2)) {
            if (!(use_c ? v.hi < 0 : v.hi >= 0))
                continue;
            RENDER_COVER(r, oi, x, rgb, render_resolve_ortho(r, cur_, oi, x, iy, b, &kr, &v, use_c));
        }
        return;
    }
    uint64_t b = (uint64_t)rlin_at(&o->u.sphere->b, ix0, iy), sb = 2 * (uint64_t)o->u.sphere->b.x;
    fx128_t k;
    fx128_copy(&k, &o->u.sphere->k);
    for (int32_t x = x0; x <= x1; x++, b += sb, fx128_add_to(&v, &d1), fx128_add_to(&d1, &d2)) {
        if (!((render_k_t)b > 0 && v.hi >= 0))
            continue;
        RENDER_COVER(r, oi, x, rgb, render_resolve_sphere(r, cur_, oi, x, iy, (render_k_t)b, &k, &v));
    }
}
#endif

#if FXRT_NUMBER != FXRT_Q16 && FXRT_FLOAT_STEP && !FXRT_NO_STEP
static void render_scan_sphere_f(vis_t *r, uint16_t oi, const render_obj_t *o, int32_t x0, int32_t x1, int32_t iy,
                                 uint8_t *rgb, bool lone)
{
    const render_sphere_t *sp = o->u.sphere;
    int32_t ix0 = 2 * x0 - r->cam->width + 1;
    render_k_t b = rlin_at(&sp->b, ix0, iy), px = rlin_at(&sp->px, ix0, iy), py = rlin_at(&sp->py, ix0, iy),
         pz = rlin_at(&sp->pz, ix0, iy);
    render_k_t sb = 2 * sp->b.x, spx = 2 * sp->px.x, spy = 2 * sp->py.x, spz = 2 * sp->pz.x;
    render_k_t a0 = rquad_at(sp->a, ix0, iy), a1 = rquad_at(sp->a, ix0 + 2, iy), a2 = rquad_at(sp->a, ix0 + 4, iy);
    render_k_t a = a0, da = a1 - a0, dda = a2 - 2 * a1 + a0;
    for (int32_t x = x0; x <= x1; x++) {
        render_k_t sq = px * px + py * py + pz * pz;
        render_k_t disc = sp->r2 * (sp->ortho ? NUM_ONE : a) - sq;
        render_k_t c = sp->ortho ? sp->k + sq : sp->k;
        if (render_sphere_vals(b, c, disc)) {
            if (lone)
                render_paint(r, oi, x, rgb);
            else
                RENDER_COVER(r, oi, x, rgb, render_resolve_sphere(r, cur_, oi, x, iy, b, &c, &disc));
        }
        b += sb;
        px += spx;
        py += spy;
        pz += spz;
        a += da;
        da += dda;
    }
}
#endif

/* The stepping scanlines of this build: exact integer steps in Q16.16,
 * the float programmer's restarted forward differences otherwise. */
#if FXRT_NUMBER == FXRT_Q16
#define RENDER_SCAN_SPHERE render_scan_sphere
#define RENDER_SCAN_FLAT(r, oi, f, x0, x1, iy, rgb, lone)                                                            \
    ((void)(render_scan_flat(r, oi, f, x0, x1, iy, rgb, lone) ||                                                   \
            (render_step_flat(r, oi, f, x0, x1, iy, rgb, lone, render_kind(&(r)->obj[oi]) == RENDER_FLAT), false)))
#else
#define RENDER_SCAN_SPHERE render_scan_sphere_f
#define RENDER_SCAN_FLAT render_scan_flat_f
#endif

#if !RENDER_ROW_MASKS
/* The first object from i on whose rows include row (r->count: none); a
 * loop of its own, with few registers, as most objects of a large world
 * are off most rows. (Where CLZ is an instruction the rows' object masks
 * do this: render_row_vis.) */
__attribute__((noinline)) static uint16_t render_next_on_row(const vis_t *r, uint16_t i, int32_t row)
{
    if (FXRT_NO_BOUNDS)
        return i;
    const render_obj_t *o = &r->obj[i], *end = &r->obj[r->count];
    while (o < end && (row < o->r0 || row > o->r1))
        o++;
    return (uint16_t)(o - r->obj);
}
#endif

/* The visibility pass of one row: every object's coverage, the nearest
 * owner of each column, flat colours painted (and r->vis recorded for the
 * shading pass). Out of line so that its frame is gone before the shading
 * pass runs (stack depth on the micro:bit). */
__attribute__((noinline)) void render_row_vis(vis_t *r, int32_t row, uint8_t *rgb)
{
    const cam_t *cam = r->cam;
    int32_t w = cam->width, y = cam->height - 1 - row;
    int32_t iy = 2 * y - cam->height + 1;
#if FXRT_NUMBER == FXRT_Q16 && !FXRT_NO_STEP
    /* (Only spheres use it: a build without them keeps none.) */
    render_sphere_cache_t sphere_cache;
    if (RENDER_ROUNDS > 0) {
        render_sphere_cache_reset(&sphere_cache);
        r->sphere_cache = &sphere_cache;
    }
#endif
    render_prow_t prow;
    for (int j = 0; j < RENDER_ROW_PLANES; j++)
        prow.state[j] = 0;
    render_begin_row(r, rgb);
    r->dirty_lo = (int16_t)w;
    r->dirty_hi = -1;
#if RENDER_ROW_MASKS
    /* The objects of the row's block (r->row_mask), in index order. */
    const uint32_t *mask = r->row_mask[row >> r->row_shift];
    for (uint16_t word = 0, nw = (uint16_t)((r->count + 31) >> 5); word < nw; word++)
        for (uint32_t bits = mask[word]; bits; bits &= bits - 1) {
            uint16_t i = (uint16_t)(word << 5 | (uint16_t)__builtin_ctz(bits));
            if (row < r->obj[i].r0 || row > r->obj[i].r1)
                continue;
#else
    for (uint16_t i = render_next_on_row(r, 0, row); i < r->count; i = render_next_on_row(r, i + 1, row)) {
#endif
        const render_obj_t *o = &r->obj[i];
        int32_t x0 = FXRT_NO_BOUNDS ? 0 : o->x0, x1 = FXRT_NO_BOUNDS ? w - 1 : o->x1;
        if (x0 > x1)
            continue;
        bool lone = !FXRT_NO_LONE && render_alone(r, i, row);
        r->row_win = 0;
        if (!FXRT_NO_ZRANGE && !lone && r->nplanes && !render_row_order(r, i, x0, x1, iy, &prow))
            continue;
        /* After this object, columns x0..x1 may be claimed (the hull of
         * every object's columns so far on this row). */
        int32_t dlo = r->dirty_lo, dhi = r->dirty_hi;
        if (RENDER_RAY_KINDS && render_kind(o) == RENDER_RAYS)
            render_scan_rays(r, i, x0, x1, iy, rgb, lone);
        else
        switch (render_kind(o)) {
        case RENDER_INSIDE_BOX:
            for (int32_t x = x0; x <= x1; x++)
                RENDER_HIT(r, i, x, iy, rgb, lone);
            break;
#if RENDER_STEPPED
        case RENDER_SPHERE:
            RENDER_SCAN_SPHERE(r, i, o, x0, x1, iy, rgb, lone);
            break;
        case RENDER_FLAT:
        case RENDER_BOX:
            for (int k = 0; k < o->nflat; k++) {
                render_flat_t *f = render_face(o, k);
                if (FXRT_NO_BOUNDS || render_kind(o) == RENDER_FLAT)
                    RENDER_SCAN_FLAT(r, i, f, x0, x1, iy, rgb, lone); /* a plane's or triangle's bounds are its object's */
                else if (row >= o->u.face[k].r0 && row <= o->u.face[k].r1)
                    RENDER_SCAN_FLAT(r, i, f, o->u.face[k].x0, o->u.face[k].x1, iy, rgb, lone);
            }
            break;
#else
        default:
            /* Float and double (and FXRT_NO_STEP) evaluate every form directly: stepping by
             * additions would accumulate rounding error across the row. */
            for (int32_t x = x0, ix = 2 * x0 - w + 1; x <= x1; x++, ix += 2)
                if (render_covers_call(o, ix, iy))
                    RENDER_HIT(r, i, x, iy, rgb, lone);
            break;
#endif
        }
        r->dirty_lo = x0 < dlo ? x0 : dlo;
        r->dirty_hi = x1 > dhi ? x1 : dhi;
    }
#if FXRT_NUMBER == FXRT_Q16 && !FXRT_NO_STEP
    r->sphere_cache = NULL;
#endif
}
