/* flat: a flat piece (a plane, a triangle, a box face) along a row: its
 * runs found exactly from its forms (vis/roots.h) and filled or claimed,
 * or every column stepped; and a fine row put as runs of one object each
 * for the sampler's run mode. */
#include "vis/roots.h"

#if FXRT_NUMBER == FXRT_Q16 && !FXRT_NO_STEP
/* Runs (with spans, unless FXRT_ABLATE_SPANS). Inline into its callers (M3: 0.5 % fewer instructions on the bench
 * set), but out of line on Armv6-M, where it would grow
 * render_scan_flat's frame on the claiming path (the micro:bit's stack). */
#define RENDER_RUNS_INLINE static FXRT_INLINE_WIDE RENDER_MAYBE_UNUSED
/* A flat piece's hits on columns x0..x1 as at most four runs (k from
 * x0, possibly overlapping), found exactly from its forms: the same sign
 * tests as the stepping loop (N and D of one strict sign, edges all >= 0
 * or all <= 0). Returns the number of runs. hint: per form (N, D, the
 * edges) the guesses of render_split_near where the flat piece keeps them
 * (RENDER_HINTS), else NULL. */
RENDER_RUNS_INLINE int render_runs_flat(const vis_t *r, render_flat_t *f, int32_t x0, int32_t x1, int32_t iy,
                                        int16_t *hint, render_iv_t run[4])
{
    int32_t ix0 = 2 * x0 - r->cam->width + 1, kmax = x1 - x0, rk, lk;
    render_iv_t ge = {0, kmax}, le = {0, kmax}, front[2] = {{0, kmax}, {1, 0}};
    if (!f->front) { /* (front: N and D share a sign all over its bounds) */
        render_iv_t np, nn, dp, dn;
        RENDER_SIGNS(rlin_at(&f->n, ix0, iy), 2 * f->n.x, kmax, hint, true, &np, &nn);
        RENDER_SIGNS(rlin_at(&f->d, ix0, iy), 2 * f->d.x, kmax, hint ? hint + 1 : NULL, true, &dp, &dn);
        front[0] = render_iv_and(np, dp);
        front[1] = render_iv_and(nn, dn);
    }
#if RENDER_ESTEP
    /* (Unrolled: a triangle's three edges, then a box face's fourth.) */
    (void)hint;
    if (f->edges) {
        render_estep_t *es = f->es;
        for (int k = 0; k < 3; k++) {
            bool fall = render_split_edge(&es[k], &f->e[k], x0, ix0, iy, kmax, &rk, &lk);
            render_edge_runs(fall, rk, lk, &ge, &le);
        }
        if (f->edges == 4) {
            bool fall = render_split_edge(&es[3], render_edge_k(f, 3), x0, ix0, iy, kmax, &rk, &lk);
            render_edge_runs(fall, rk, lk, &ge, &le);
        }
    }
#else
    for (int k = 0; k < f->edges; k++) {
        const render_lin_t *ek = render_edge_k(f, k);
        bool fall = RENDER_SPLIT(rlin_at(ek, ix0, iy), 2 * ek->x, kmax, hint ? hint + 2 + k : NULL, false, &rk, &lk);
        render_edge_runs(fall, rk, lk, &ge, &le);
    }
#endif
    int nrun = 0;
    if (f->front) { /* the edges' two intervals as they are */
        if (ge.lo <= ge.hi)
            run[nrun++] = ge;
        if (le.lo <= le.hi && f->edges)
            run[nrun++] = le;
        return nrun;
    }
    for (int i = 0; i < 2; i++) {
        render_iv_t a = render_iv_and(front[i], ge), b = render_iv_and(front[i], le);
        if (a.lo <= a.hi)
            run[nrun++] = a;
        if (b.lo <= b.hi && f->edges)
            run[nrun++] = b;
    }
    return nrun;
}

/* A lone flat piece: its runs filled. */
RENDER_MAYBE_UNUSED static void render_span_flat(vis_t *r, uint16_t oi, render_flat_t *f, int32_t x0, int32_t x1, int32_t iy,
                             uint8_t *rgb)
{
    render_iv_t run[4];
    int nrun = render_runs_flat(r, f, x0, x1, iy, RENDER_HINT(f), run);
    for (int k = 0; k < nrun; k++)
        render_fill(r, oi, x0 + run[k].lo, x0 + run[k].hi, rgb);
}

bool render_split_test(int64_t a, int64_t b, int32_t kmax, int16_t *guess, bool strict, int32_t *pr, int32_t *pl)
{
    if (RENDER_COHERENT && guess)
        return render_split_near(a, b, kmax, guess, strict, pr, pl);
    return render_split_two(a, b, kmax, strict, pr, pl);
}

bool render_split_edge_test(render_estep_t *st, const render_lin_t *ek, int32_t x0, int32_t ix0, int32_t iy,
                            int32_t kmax, int32_t *pr, int32_t *pl)
{
    return render_split_edge(st, ek, x0, ix0, iy, kmax, pr, pl);
}

/* A flat piece among others locates its runs from this many columns on;
 * below, stepping is as cheap. With the quotient's guesses (division and
 * CLZ instructions: the M3, M4F) 4 and 6 are 0.4 % fewer instructions
 * than 8 on the bench set; on the M0, 6 and 8 measure alike. */
#define RENDER_CLAIM_MIN (RENDER_DIV_GUESS ? 6 : 8)

/* A flat piece across columns x0..x1, by spans where it is wide enough
 * (true); false: the caller steps it (render_step_flat), each form linear,
 * so one exact 64-bit addition per form and pixel. */
bool render_scan_flat(vis_t *r, uint16_t oi, render_flat_t *f, int32_t x0, int32_t x1, int32_t iy,
                             uint8_t *rgb, bool lone)
{
    bool single = render_kind(&r->obj[oi]) == RENDER_FLAT;
    /* Alone on the row and wide: runs located exactly, filled by words
     * (a division per form pays off from about 4 columns per form on the M3). */
    if (!FXRT_NO_SPANS && lone && x1 - x0 >= 4 * (1 + f->edges)) {
        render_span_flat(r, oi, f, x0, x1, iy, rgb);
        return true;
    }
    /* Among others and wide: its runs located the same way, then each
     * covered column claimed (render_claim_run). */
    if (!FXRT_NO_SPANS && x1 - x0 >= RENDER_CLAIM_MIN) {
        render_iv_t iv[4];
        int nrun = render_runs_flat(r, f, x0, x1, iy, RENDER_HINT(f), iv);
        for (int k = 0; k < nrun; k++)
            render_claim_run(r, oi, f, x0 + iv[k].lo, x0 + iv[k].hi, iy, rgb, single);
        return true;
    }
    return false;
}

/* Narrow: every column stepped and tested. (A frame of its own, apart
 * from the claiming path's: the micro:bit's stack.) */
__attribute__((noinline)) void render_step_flat(vis_t *r, uint16_t oi, const render_flat_t *f, int32_t x0,
                                                       int32_t x1, int32_t iy, uint8_t *rgb, bool lone, bool single)
{
    int32_t ix0 = 2 * x0 - r->cam->width + 1;
    uint64_t n = (uint64_t)rlin_at(&f->n, ix0, iy), d = (uint64_t)rlin_at(&f->d, ix0, iy);
    uint64_t sn = 2 * (uint64_t)f->n.x, sd = 2 * (uint64_t)f->d.x;
    int edges = f->edges;
    if (edges == 0) { /* a plane */
        for (int32_t x = x0; x <= x1; x++) {
            if (((render_k_t)n > 0 && (render_k_t)d > 0) || ((render_k_t)n < 0 && (render_k_t)d < 0)) {
                if (lone)
                    render_paint(r, oi, x, rgb);
                else
                    RENDER_COVER(r, oi, x, rgb, render_resolve_flat(r, cur_, oi, x, iy, f, (render_k_t)n, (render_k_t)d));
            }
            n += sn;
            d += sd;
        }
        return;
    }
    /* Three or four edges; a triangle's missing fourth edge is a zero form
     * (it never has a strict sign, so it changes nothing). Inside means no
     * two edges of opposite strict sign: all >= 0 (the sign bits of their
     * OR are clear) or all <= 0. */
    uint64_t e[4] = {0, 0, 0, 0}, se[4] = {0, 0, 0, 0};
    for (int k = 0; k < edges; k++) {
        const render_lin_t *ek = render_edge_k(f, k);
        e[k] = (uint64_t)rlin_at(ek, ix0, iy);
        se[k] = 2 * (uint64_t)ek->x;
    }
    for (int32_t x = x0; x <= x1; x++) {
        bool in = (render_k_t)(e[0] | e[1] | e[2] | e[3]) >= 0 ||
                  ((render_k_t)e[0] <= 0 && (render_k_t)e[1] <= 0 && (render_k_t)e[2] <= 0 && (render_k_t)e[3] <= 0);
        if (in && (((render_k_t)n > 0 && (render_k_t)d > 0) || ((render_k_t)n < 0 && (render_k_t)d < 0))) {
            if (lone)
                render_paint(r, oi, x, rgb);
            else if (single)
                RENDER_COVER(r, oi, x, rgb, render_resolve_flat(r, cur_, oi, x, iy, f, (render_k_t)n, (render_k_t)d));
            else /* a box's depth is the nearest of its faces there */
                RENDER_COVER(r, oi, x, rgb, render_resolve_box(r, cur_, oi, x, iy, f, (render_k_t)n, (render_k_t)d));
        }
        n += sn;
        d += sd;
        e[0] += se[0];
        e[1] += se[1];
        e[2] += se[2];
        e[3] += se[3];
    }
}
#endif

#if FXRT_NUMBER != FXRT_Q16 && FXRT_FLOAT_STEP && !FXRT_NO_STEP
/* FXRT_FLOAT_STEP: the float programmer's scanline. Each linear form is
 * evaluated directly at the segment's first pixel and then stepped by one
 * addition per pixel (the quadratic a by forward differences); rounding
 * accumulates along the segment, unlike the exact Q16.16 steps. */
void render_scan_flat_f(vis_t *r, uint16_t oi, const render_flat_t *f, int32_t x0, int32_t x1, int32_t iy,
                               uint8_t *rgb, bool lone)
{
    bool single = render_kind(&r->obj[oi]) == RENDER_FLAT;
    int32_t ix0 = 2 * x0 - r->cam->width + 1;
    render_k_t n = rlin_at(&f->n, ix0, iy), d = rlin_at(&f->d, ix0, iy), sn = 2 * f->n.x, sd = 2 * f->d.x;
    render_k_t e[4] = {0, 0, 0, 0}, se[4] = {0, 0, 0, 0};
    int edges = f->edges;
    for (int k = 0; k < edges; k++) {
        const render_lin_t *ek = render_edge_k(f, k);
        e[k] = rlin_at(ek, ix0, iy);
        se[k] = 2 * ek->x;
    }
    for (int32_t x = x0; x <= x1; x++) {
        if (render_flat_vals(n, d, e, edges)) {
            if (lone)
                render_paint(r, oi, x, rgb);
            else if (single)
                RENDER_COVER(r, oi, x, rgb, render_resolve_flat(r, cur_, oi, x, iy, f, n, d));
            else
                render_cover(r, oi, x, iy, rgb);
        }
        n += sn;
        d += sd;
        for (int k = 0; k < edges; k++)
            e[k] += se[k];
    }
}
#endif

#if RENDER_RUNS
/* Append the non-empty runs iv[0..k-1] (k from x0) of object oi to
 * out[0..n-1]; -1 when that would pass cap. */
static int render_runs_push(render_run_t *out, int n, int cap, int32_t x0, const render_iv_t *iv, int k, uint16_t oi)
{
    for (int i = 0; i < k && n >= 0; i++) {
        if (iv[i].lo > iv[i].hi)
            continue;
        if (n == cap)
            return -1;
        out[n].a = (int16_t)(x0 + iv[i].lo);
        out[n].b = (int16_t)(x0 + iv[i].hi);
        out[n++].oi = oi;
    }
    return n;
}

int render_row_runs(vis_t *r, int32_t row, render_run_t *out, int cap)
{
    int32_t iy = render_iy(r->cam, row);
    int n = 0;
    if (r->cam->height < 3)
        return -1; /* the spheres' row series need three rows */
    for (uint16_t i = 0; i < r->count && n >= 0; i++) {
        const render_obj_t *o = &r->obj[i];
        if (row < o->r0 || row > o->r1 || o->x0 > o->x1)
            continue;
        if (!o->flat || !render_alone(r, i, row))
            return -1;
        render_iv_t iv[4];
        switch (render_kind(o)) {
        case RENDER_INSIDE_BOX:
            iv[0].lo = 0;
            iv[0].hi = o->x1 - o->x0;
            n = render_runs_push(out, n, cap, o->x0, iv, 1, i);
            break;
        case RENDER_SPHERE:
#if RENDER_SROWS
            if (o->index < FXRT_COHERENT_SPHERES) {
                n = render_runs_push(out, n, cap, o->x0, iv, render_sphere_row_runs(r, o, row, iv), i);
                break;
            }
#endif
            return -1; /* no row series: the per-sample pass */
        case RENDER_RAYS:
            return -1; /* rays: the per-sample pass */
        case RENDER_FLAT:
            n = render_runs_push(out, n, cap, o->x0, iv, render_runs_flat(r, o->u.flat, o->x0, o->x1, iy, RENDER_HINT(o->u.flat), iv), i);
            break;
        case RENDER_BOX:
            for (int k = 0; k < o->nflat && n >= 0; k++) {
                render_face_t *fc = &o->u.face[k];
                if (row < fc->r0 || row > fc->r1 || fc->x0 > fc->x1)
                    continue;
                n = render_runs_push(out, n, cap, fc->x0, iv,
                                     render_runs_flat(r, &fc->f, fc->x0, fc->x1, iy, RENDER_HINT(&fc->f), iv), i);
            }
            break;
        }
    }
    if (n <= 0)
        return n;
    /* In column order (insertion: few runs), one object's overlapping or
     * touching runs (a box's faces) merged. Lone objects' columns do not
     * meet, so runs of two objects never overlap. */
    for (int i = 1; i < n; i++) {
        render_run_t t = out[i];
        int j = i;
        for (; j > 0 && out[j - 1].a > t.a; j--)
            out[j] = out[j - 1];
        out[j] = t;
    }
    int m = 0;
    for (int i = 1; i < n; i++) {
        if (out[i].oi == out[m].oi && out[i].a <= out[m].b + 1) {
            if (out[i].b > out[m].b)
                out[m].b = out[i].b;
        } else {
            out[++m] = out[i];
        }
    }
    return m + 1;
}
#endif
