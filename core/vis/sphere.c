/* sphere: a sphere's row forms and runs. Along a row its c and disc are
 * quadratic, stepped exactly by 128-bit forward differences; its run of
 * covered columns is found by a binary search (FXRT_SPHERE_SEARCH) or by
 * stepping, and, with row coherence (RENDER_SROWS), from the row before's
 * with the forms themselves stepped down the rows. */
#include "vis/roots.h"

#if FXRT_NUMBER == FXRT_Q16 && !FXRT_NO_STEP
/* The columns k in 0..kmax where q(k) >= 0, for d2 < 0 (one run or none):
 * q rises while its step d1 + d2 k is positive, then falls, so the peak
 * and both ends are binary searches on monotone predicates
 * (FXRT_SPHERE_SEARCH, with spans). */
RENDER_MAYBE_UNUSED static render_iv_t render_sphere_run(fx128_t v, fx128_t d1, fx128_t d2, int32_t kmax)
{
    render_iv_t none = {1, 0};
    int32_t lo = 0, hi = kmax; /* peak: first k whose step is <= 0 (or kmax) */
    while (lo < hi) {
        int32_t mid = lo + (hi - lo) / 2;
        fx128_t step = fx128_add(d1, render_mul128_small(&d2, mid));
        if (step.hi < 0 || (step.hi == 0 && step.lo == 0))
            hi = mid;
        else
            lo = mid + 1;
    }
    int32_t peak = lo;
    if (render_quad_k(&v, &d1, &d2, peak).hi < 0)
        return none;
    int32_t a = 0, b = peak; /* first k <= peak with q >= 0 */
    while (a < b) {
        int32_t mid = a + (b - a) / 2;
        if (render_quad_k(&v, &d1, &d2, mid).hi >= 0)
            b = mid;
        else
            a = mid + 1;
    }
    render_iv_t run;
    run.lo = a;
    a = peak, b = kmax; /* last k >= peak with q >= 0 */
    while (a < b) {
        int32_t mid = b - (b - a) / 2;
        if (render_quad_k(&v, &d1, &d2, mid).hi >= 0)
            a = mid;
        else
            b = mid - 1;
    }
    run.hi = a;
    return run;
}

/* render_sphere_cd out of line: render_sphere_row's three calls share it
 * (inline, its temporaries would grow render_sphere_row's frame). */
__attribute__((noinline)) static void render_sphere_cd_row(const render_obj_t *o, int32_t ix, int32_t iy, render_wide_t *c,
                                                           render_wide_t *disc)
{
    render_sphere_cd(o, ix, iy, c, disc);
}

/* A sphere's row from column x0 (ix0), render_srow_t (render.h): c and
 * disc are quadratic along the row, so their 128-bit forward differences
 * (second difference constant) give exactly the values render_sphere_cd
 * computes from scratch. (A frame of its own, not render_row_vis's.) */
__attribute__((noinline)) void render_sphere_row(const vis_t *r, const render_obj_t *o, int32_t ix0,
                                                        int32_t iy, render_srow_t *s)
{
    fx128_t c[3], q[3];
    for (int k = 0; k < 3; k++)
        render_sphere_cd_row(o, ix0 + 2 * k, iy, &c[k], &q[k]);
    s->ortho = render_ortho(r->cam);
    s->inside = !s->ortho && render_wide_neg(c[0]);
    s->use_c = s->ortho && !(o->u.sphere->b.c > 0);
    const fx128_t *f = s->use_c ? c : q;
    s->v = f[0];
    s->d1 = fx128_sub(f[1], f[0]);
    s->d2 = fx128_add(fx128_sub(f[2], fx128_add(f[1], f[1])), f[0]);
}

/* Where b > 0 (the centre's side of the eye) on columns k = 0..kmax
 * (spans, with FXRT_SPHERE_SEARCH or RENDER_SROWS). */
RENDER_MAYBE_UNUSED static render_iv_t render_sphere_front(const render_obj_t *o, int32_t ix0, int32_t iy, int32_t kmax)
{
    int32_t pr, pl;
    bool fall = render_split_two(rlin_at(&o->u.sphere->b, ix0, iy), 2 * o->u.sphere->b.x, kmax, true, &pr, &pl);
    render_iv_t pos = {fall ? 0 : pr, fall ? pl : kmax};
    return pos;
}

/* The runs of a sphere over columns x0..x1 (k from x0; the same columns
 * the per-column test covers). At most two: b > 0 is a half-line and disc
 * >= 0 one interval (disc concave along the row) or the outside of one
 * (convex); in orthographic views one interval. */
int render_sphere_runs(const render_obj_t *o, const render_srow_t *s, int32_t x0, int32_t x1, int32_t ix0,
                              int32_t iy, render_iv_t run[2])
{
    int32_t kmax = x1 - x0;
    if (s->inside) {
        run[0].lo = 0;
        run[0].hi = kmax;
        return 1;
    }
    if (!FXRT_NO_SPANS && FXRT_SPHERE_SEARCH && !s->ortho && s->d2.hi < 0) {
        /* Perspective, disc concave along the row: its run is located by
         * exact evaluations (binary searches on the monotone sides of the
         * quadratic) instead of stepping. */
        run[0] = render_iv_and(render_sphere_run(s->v, s->d1, s->d2, kmax), render_sphere_front(o, ix0, iy, kmax));
        return run[0].lo <= run[0].hi;
    }
    /* Stepping: one run when the covered set is an interval (orthographic,
     * or perspective with disc concave), then stop after it. */
    bool one_run = s->ortho || s->d2.hi < 0;
    fx128_t v, d1;
    fx128_copy(&v, &s->v);
    fx128_copy(&d1, &s->d1);
    uint64_t b = s->ortho ? 1 : (uint64_t)rlin_at(&o->u.sphere->b, ix0, iy), sb = s->ortho ? 0 : 2 * (uint64_t)o->u.sphere->b.x;
    int n = 0;
    int32_t start = -1, k;
    for (k = 0; k <= kmax; k++, b += sb, v = fx128_add(v, d1), d1 = fx128_add(d1, s->d2)) {
        bool hit = s->ortho ? (s->use_c ? v.hi < 0 : v.hi >= 0) : ((render_k_t)b > 0 && v.hi >= 0);
        if (hit) {
            if (start < 0)
                start = k;
        } else if (start >= 0) {
            run[n].lo = start;
            run[n++].hi = k - 1;
            start = -1;
            if (one_run || n == 2)
                return n;
        }
    }
    if (start >= 0) {
        run[n].lo = start;
        run[n++].hi = kmax;
    }
    return n;
}

#if RENDER_SROWS
/* A lone sphere on the row at iy (its bounds x0..x1): its forms stepped
 * from the row before and its runs searched from the row before's. */
__attribute__((noinline)) void render_lone_sphere(vis_t *r, uint16_t oi, const render_obj_t *o,
                                                         int32_t iy, uint8_t *rgb)
{
    int32_t row = render_row_of(r->cam, iy);
    render_iv_t run[2];
    int nrun = render_sphere_row_runs(r, o, row, run);
    for (int k = 0; k < nrun; k++)
        render_fill(r, oi, o->x0 + run[k].lo, o->x0 + run[k].hi, rgb);
}

void render_srow_setup(vis_t *r, uint16_t i)
{
    const render_obj_t *o = &r->obj[i];
    r->srow[o->index].vrow = r->srow[o->index].prow = -2;
    r->srow[o->index].pk = (int16_t)((o->x1 - o->x0) / 2);
}

/* The series on fine row `row` - 1, from the forms on three rows (on the
 * screen, where every form fits): their differences give it exactly.
 * One row's forms at a time (the micro:bit's stack). */
__attribute__((noinline)) void render_srow_start(vis_t *r, const render_obj_t *o, int32_t row)
{
    __typeof__(r->srow[0]) *q = &r->srow[o->index];
    int32_t h = r->cam->height, b = row + 2 < h ? row : h - 3, ix0 = 2 * o->x0 - r->cam->width + 1;
    render_srow_t f;
    render_sphere_row(r, o, ix0, render_iy(r->cam, b), &q->cur);
    render_sphere_row(r, o, ix0, render_iy(r->cam, b + 1), &f);
    q->dvk = fx128_sub(f.v, q->cur.v); /* v(b + 1) - v(b) */
    q->dd1 = fx128_sub(f.d1, q->cur.d1);
    render_sphere_row(r, o, ix0, render_iy(r->cam, b + 2), &f);
    q->ddv = fx128_sub(fx128_sub(fx128_sub(f.v, q->cur.v), q->dvk), q->dvk); /* v(b+2) - 2 v(b+1) + v(b) */
    /* Row b - 1, then down to row - 1. */
    q->dvk = fx128_sub(q->dvk, q->ddv);
    q->cur.v = fx128_sub(q->cur.v, q->dvk);
    q->cur.d1 = fx128_sub(q->cur.d1, q->dd1);
    q->vrow = b - 1;
    while (q->vrow < row - 1)
        render_srow_step(r, o->index);
}

/* Columns render_gallop walks by forward differences before it gallops:
 * a run's end mostly moves a few columns from one row to the next, and a
 * step is two 128-bit additions where a jump is render_quad_k's two
 * 128-bit products. */
#define RENDER_GALLOP_WALK 8

/* From column `from`, where (q(k) >= 0) == want and q(from) = *qf,
 * towards `limit` (dir = +1 or -1): the last column k before the
 * predicate first fails, or limit. It must be monotone over from..limit.
 * The first RENDER_GALLOP_WALK columns are stepped from q(from) (exact:
 * the same values as render_quad_k's), then steps double from the last
 * column where it held (galloping), then a binary search between that
 * column and the first where it failed. */
static int32_t render_gallop(const render_srow_t *s, int32_t from, const fx128_t *qf, int32_t dir, int32_t limit,
                             bool want)
{
    int32_t good = from;
    if (good == limit)
        return good;
    /* q(k + dir) - q(k): d1 + d2 k going right, -(d1 + d2 (k - 1)) going
     * left; either changes by d2 per column. */
    fx128_t q, st = fx128_add(s->d1, render_mul128_small(&s->d2, dir > 0 ? from : from - 1));
    fx128_copy(&q, qf);
    if (dir < 0)
        st = fx128_neg(st);
    for (int i = 0; i < RENDER_GALLOP_WALK; i++) {
        fx128_add_to(&q, &st); /* q(good + dir) */
        if ((q.hi >= 0) != want)
            return good;
        good += dir;
        if (good == limit)
            return good;
        fx128_add_to(&st, &s->d2);
    }
    int32_t bad = good, step = 1;
    bool failed = false;
    while (!failed && good != limit) {
        int32_t k = (limit - good) * dir > step ? good + dir * step : limit;
        if ((render_quad_k(&s->v, &s->d1, &s->d2, k).hi >= 0) == want) {
            good = k;
            step *= 2;
        } else {
            bad = k;
            failed = true;
        }
    }
    if (!failed)
        return good; /* held up to limit */
    while ((bad - good) * dir > 1) {
        int32_t mid = good + (bad - good) / 2;
        if ((render_quad_k(&s->v, &s->d1, &s->d2, mid).hi >= 0) == want)
            good = mid;
        else
            bad = mid;
    }
    return good;
}

/* Is the step q(k + 1) - q(k) = d1 + d2 k <= 0 (k at or past the peak)? */
static bool render_sphere_down(const render_srow_t *s, int32_t k)
{
    fx128_t step = fx128_add(s->d1, render_mul128_small(&s->d2, k));
    return step.hi < 0 || (step.hi == 0 && step.lo == 0);
}

/* The peak of q on the row (d2 < 0): the first k in 0..kmax - 1 whose
 * step is <= 0, kmax when none (render_sphere_run's), by galloping from
 * the guess p on that monotone predicate, then a binary search. */
static int32_t render_sphere_peak(const render_srow_t *s, int32_t kmax, int32_t p)
{
    int32_t lo, hi, st = 1;
    p = p < 0 ? 0 : (p > kmax ? kmax : p);
    if (p < kmax && !render_sphere_down(s, p)) {
        for (lo = p;; lo = hi, st *= 2) {
            hi = lo + st;
            if (hi >= kmax) {
                hi = kmax;
                break;
            }
            if (render_sphere_down(s, hi))
                break;
        }
    } else {
        for (hi = p;; hi = lo, st *= 2) {
            lo = hi - st;
            if (lo < 0) {
                lo = -1;
                break;
            }
            if (!render_sphere_down(s, lo))
                break;
        }
    }
    while (hi - lo > 1) {
        int32_t mid = lo + (hi - lo) / 2;
        if (mid < kmax && !render_sphere_down(s, mid))
            lo = mid;
        else
            hi = mid;
    }
    return hi;
}

/* render_sphere_run (disc concave along the row: its run of q >= 0 is
 * one interval, around the peak) from guesses, the row before's run g
 * (empty when lo > hi) and peak *pk: an end of g still in the run gallops
 * outwards, an end out of it inwards (q is monotone on either side of the
 * peak, so any column there is a valid start); when neither end nor the
 * middle of g is in the run, from the peak (found from *pk, updated). */
static render_iv_t render_sphere_run_near(const render_srow_t *s, int32_t kmax, render_iv_t g, int16_t *pk)
{
    render_iv_t run, none = {1, 0};
    fx128_t qlo, qhi; /* q at g's ends, which the galloping steps from */
    if (g.lo <= g.hi) {
        qlo = render_quad_k(&s->v, &s->d1, &s->d2, g.lo);
        qhi = g.hi == g.lo ? qlo : render_quad_k(&s->v, &s->d1, &s->d2, g.hi);
        bool in_lo = qlo.hi >= 0, in_hi = qhi.hi >= 0;
        if (in_lo || in_hi) {
            run.lo = in_lo ? render_gallop(s, g.lo, &qlo, -1, 0, true) : render_gallop(s, g.lo, &qlo, 1, g.hi, false) + 1;
            run.hi = in_hi ? render_gallop(s, g.hi, &qhi, 1, kmax, true) : render_gallop(s, g.hi, &qhi, -1, g.lo, false) - 1;
            return run;
        }
        /* Shrunk from both sides: from its middle when that is still in it. */
        int32_t mid = g.lo + (g.hi - g.lo) / 2;
        if (render_quad_k(&s->v, &s->d1, &s->d2, mid).hi >= 0) {
            run.lo = render_gallop(s, g.lo, &qlo, 1, mid, false) + 1;
            run.hi = render_gallop(s, g.hi, &qhi, -1, mid, false) - 1;
            return run;
        }
    }
    int32_t peak = render_sphere_peak(s, kmax, *pk);
    *pk = (int16_t)peak;
    fx128_t qp = render_quad_k(&s->v, &s->d1, &s->d2, peak);
    if (qp.hi < 0)
        return none;
    bool glo = g.lo <= g.hi && g.lo < peak, ghi = g.lo <= g.hi && g.hi > peak; /* q < 0 there (tested above) */
    run.lo = glo ? render_gallop(s, g.lo, &qlo, 1, peak, false) + 1 : render_gallop(s, peak, &qp, -1, 0, true);
    run.hi = ghi ? render_gallop(s, g.hi, &qhi, -1, peak, false) - 1 : render_gallop(s, peak, &qp, 1, kmax, true);
    return run;
}

/* A lone sphere's runs on fine row `row` (k from its x0), its forms there
 * s (render_sphere_row_at): where the deciding form is concave along the
 * row, one run, found from the row before's (render_sphere_run_near);
 * otherwise by stepping. */
__attribute__((noinline)) int render_sphere_runs_at(vis_t *r, const render_obj_t *o, int32_t row,
                                                          const render_srow_t *s, render_iv_t run[2])
{
    int32_t ix0 = 2 * o->x0 - r->cam->width + 1, iy = render_iy(r->cam, row);
    int32_t kmax = o->x1 - o->x0;
    __typeof__(r->srow[0]) *q = &r->srow[o->index];
    bool guess = q->prow == row - 1;
    /* The search wants the form as f >= 0, f concave along the row. In
     * orthographic views decided by c < 0, f = -c - 1 (integers), which is
     * ~c in two's complement, concave where c is convex. */
    fx128_t d2 = s->use_c ? fx128_neg(s->d2) : s->d2;
    if (!s->inside && d2.hi < 0) {
        render_srow_t neg;
        const render_srow_t *f = s;
        if (s->use_c) {
            neg.v.lo = ~s->v.lo;
            neg.v.hi = ~s->v.hi;
            neg.d1 = fx128_neg(s->d1);
            neg.d2 = d2;
            f = &neg;
        }
        render_iv_t g = {guess ? q->plo : 1, guess ? q->phi : 0};
        render_iv_t disc = render_sphere_run_near(f, kmax, g, &q->pk);
        q->prow = row;
        q->plo = (int16_t)disc.lo;
        q->phi = (int16_t)disc.hi;
        if (disc.lo > disc.hi)
            return 0;
        /* Perspective also needs b > 0. b is linear along the row: > 0 at
         * both ends of the run, > 0 on all of it (no division needed). In
         * orthographic views f decides alone. */
        const render_lin_t *b = &o->u.sphere->b;
        if (s->ortho || (rlin_at(b, ix0 + 2 * disc.lo, iy) > 0 && rlin_at(b, ix0 + 2 * disc.hi, iy) > 0)) {
            run[0] = disc;
            return 1;
        }
        run[0] = render_iv_and(disc, render_sphere_front(o, ix0, iy, kmax));
        return run[0].lo <= run[0].hi;
    }
    return render_sphere_runs(o, s, o->x0, o->x1, ix0, iy, run);
}

#endif
#endif
