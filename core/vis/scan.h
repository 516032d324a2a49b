/* scan: what the row loop (vis/row.c) and the scans of each form (flat
 * pieces: vis/flat.c; spheres: vis/sphere.c; columns claimed among
 * others: vis/claim.c) share (private to vis/). */
#ifndef FXRT_VIS_SCAN_H
#define FXRT_VIS_SCAN_H

#include "vis/paint.h"

/* Fill columns xa..xb with object oi's colour (and record it in vis). */
static inline void render_fill(vis_t *r, uint16_t oi, int32_t xa, int32_t xb, uint8_t *rgb)
{
    if (render_tracks(r)) /* only the shading and sampling passes read painted[] */
        for (int32_t k = xa; k <= xb; k++)
            render_mark(r, k, oi);
    render_fill_rgb(rgb, xa, xb, r->obj[oi].rgb);
}

/* Columns x0 + k, k in lo..hi (empty when lo > hi). */
typedef struct {
    int32_t lo, hi;
} render_iv_t;

/* A flat piece's guesses (render_split_near), where it keeps them. */
#if RENDER_HINTS
#define RENDER_HINT(f) ((f)->hint)
#else
#define RENDER_HINT(f) ((int16_t *)NULL)
#endif

/* Is object i the only one whose bounds reach columns x0..x1 on this row?
 * Then nothing can compete for its pixels. (Only checked for small worlds;
 * a large one simply takes the owner path.) */
static inline bool render_alone(const vis_t *r, uint16_t i, int32_t row)
{
    if (r->count > FXRT_LONE_MAX)
        return false;
    const render_obj_t *o = &r->obj[i];
    for (uint16_t j = 0; j < r->count; j++) {
        const render_obj_t *p = &r->obj[j];
        if (j != i && row >= p->r0 && row <= p->r1 && p->x0 <= o->x1 && p->x1 >= o->x0)
            return false;
    }
    return true;
}

/* The ray's row coordinate iy of fine row `row` (0 = top). */
RENDER_MAYBE_UNUSED static inline int32_t render_iy(const cam_t *cam, int32_t row)
{
    return 2 * (cam->height - 1 - row) - cam->height + 1;
}

/* The scans, each built where its loop is (Q16.16's exact steps, with or
 * without spans and row coherence; float's and double's restarted
 * differences with FXRT_FLOAT_STEP). vis/claim.c: columns a..b of object
 * oi, all covered by it (f: the flat piece, NULL for a sphere), claimed
 * among the row's other objects. */
void render_claim_run(vis_t *r, uint16_t oi, const render_flat_t *f, int32_t a, int32_t b, int32_t iy, uint8_t *rgb,
                      bool single);
/* vis/flat.c: a flat piece across columns x0..x1 by spans where it is wide
 * enough (true; false: the caller steps it with render_step_flat). */
bool render_scan_flat(vis_t *r, uint16_t oi, render_flat_t *f, int32_t x0, int32_t x1, int32_t iy, uint8_t *rgb,
                      bool lone);
void render_step_flat(vis_t *r, uint16_t oi, const render_flat_t *f, int32_t x0, int32_t x1, int32_t iy, uint8_t *rgb,
                      bool lone, bool single);
/* vis/sphere.c: a sphere's row forms from column x0 (ix0) on row iy; its
 * runs over columns x0..x1; a lone sphere's row (row state kept). */
void render_sphere_row(const vis_t *r, const render_obj_t *o, int32_t ix0, int32_t iy, render_srow_t *s);
int render_sphere_runs(const render_obj_t *o, const render_srow_t *s, int32_t x0, int32_t x1, int32_t ix0, int32_t iy,
                       render_iv_t run[2]);
/* ... with row coherence (RENDER_SROWS) */
void render_lone_sphere(vis_t *r, uint16_t oi, const render_obj_t *o, int32_t iy, uint8_t *rgb);
int render_sphere_runs_at(vis_t *r, const render_obj_t *o, int32_t row, const render_srow_t *s, render_iv_t run[2]);
void render_srow_start(vis_t *r, const render_obj_t *o, int32_t row);
/* vis/flat.c: the float stepped scan of a flat piece. */
void render_scan_flat_f(vis_t *r, uint16_t oi, const render_flat_t *f, int32_t x0, int32_t x1, int32_t iy, uint8_t *rgb,
                        bool lone);

#if RENDER_SROWS

/* One fine row down the series of render_sphere_row_at. */
static inline void render_srow_step(vis_t *r, uint16_t si)
{
    __typeof__(r->srow[0]) *q = &r->srow[si];
    q->cur.v = fx128_add(q->cur.v, q->dvk);
    q->dvk = fx128_add(q->dvk, q->ddv);
    q->cur.d1 = fx128_add(q->cur.d1, q->dd1);
    q->vrow++;
}

/* render_sphere_row on fine row `row`, a fine camera of at least three
 * rows: three additions after the row before. In place (no copies: on
 * the M0 a copy of 128-bit values is a memcpy call). */
static inline const render_srow_t *render_sphere_row_at(vis_t *r, const render_obj_t *o, int32_t row)
{
    if (row != r->srow[o->index].vrow + 1)
        render_srow_start(r, o, row);
    render_srow_step(r, o->index);
    return &r->srow[o->index].cur;
}

/* A lone sphere's runs on fine row `row` (k from its x0), from the row
 * before's. The row's forms first, then the search (two frames, not one
 * on top of the other: the micro:bit's stack). */
static inline __attribute__((always_inline)) int render_sphere_row_runs(vis_t *r, const render_obj_t *o, int32_t row,
                                                                    render_iv_t run[2])
{
    return render_sphere_runs_at(r, o, row, render_sphere_row_at(r, o, row), run);
}
#endif

#endif
