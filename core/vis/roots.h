/* roots: where a form changes sign along a row (private to vis/): exact
 * splits of a linear form a + b k over a row's columns, by a division
 * (render_split_two) or from a guess (render_split_near), and an edge
 * form's column stepped from the row before's (render_split_edge). Used by
 * the flat pieces' runs (vis/flat.c) and the spheres' (vis/sphere.c). */
#ifndef FXRT_VIS_ROOTS_H
#define FXRT_VIS_ROOTS_H

#include "vis/scan.h"

RENDER_MAYBE_UNUSED static inline render_iv_t render_iv_and(render_iv_t a, render_iv_t b)
{
    render_iv_t r = {a.lo > b.lo ? a.lo : b.lo, a.hi < b.hi ? a.hi : b.hi};
    return r;
}

RENDER_MAYBE_UNUSED static inline int32_t render_kclamp(int64_t v, int32_t kmax) { return v < -1 ? -1 : (v > kmax + 1 ? kmax + 1 : (int32_t)v); }

/* render_split_two's and render_split_near's split of a constant form a
 * (b = 0): all columns or none on each side. */
static inline bool render_split_const(int64_t a, int32_t kmax, bool strict, int32_t *pr, int32_t *pl)
{
    *pr = (strict ? a > 0 : a >= 0) ? 0 : kmax + 1;
    *pl = (strict ? a < 0 : a <= 0) ? kmax : -1;
    return false;
}

/* A form a + b k on k = 0..kmax split where it changes sign: with b >= 0
 * it is > 0 (strict; else >= 0) exactly on [*pr, kmax] and < 0 (<= 0) on
 * [0, *pl]; the result (b < 0: it falls) swaps them: > 0 on [0, *pl],
 * < 0 on [*pr, kmax]. (An empty interval has *pr = kmax + 1 or *pl = -1
 * or either beyond the other.) One floor division locates the root, and
 * the remainder says whether the root is a column. */
static inline bool render_split_two(int64_t a, int64_t b, int32_t kmax, bool strict, int32_t *pr, int32_t *pl)
{
    if (b == 0)
        return render_split_const(a, kmax, strict, pr, pl);
    bool fall = b < 0; /* then work with -(a + b k), which rises */
    if (fall) {
        a = -a;
        b = -b;
    }
    int64_t q = -a / b, rem = -a % b; /* |a|, |b| < 2^62: no overflow */
    if (rem < 0)
        q--; /* floor(-a / b) */
    bool exact = rem == 0;
    int64_t hi = exact ? q : q + 1; /* the first k where it is >= 0 */
    *pr = render_kclamp(strict && exact ? hi + 1 : hi, kmax);
    *pl = render_kclamp(!strict && exact ? hi : hi - 1, kmax);
    return fall;
}

/* ub k for a column k in 0..kmax + 1 (< 2^15): fx_umul64_small, out of
 * line on the M0 (three 32-bit products instead of an __aeabi_lmul call;
 * inline, five forms' worth of them tripled render_runs_flat's frame). */
static FXRT_INLINE_WIDE uint64_t render_umul_k(uint64_t ub, int32_t k) { return fx_umul64_small(ub, k); }

/* Where 32-bit division and CLZ are instructions (RENDER_DIV_GUESS), a
 * flat piece's runs start from a quotient instead of the row before's
 * columns: within one column of the answer wherever it is on the row, so
 * one evaluation checks it. */
/* For ub > 0: a guess g of the first k in 0..kmax + 1 where ua + ub k
 * >= 0 (read as signed; kmax + 1: none on the row). Both are cut to the
 * 16 significant bits of ub (truncated by 2^s). With R = -ua / ub, the
 * cut numerator is at least floor(R) times the cut divisor, and the cut
 * divisor at least (2^15 - 1) / 2^15 of ub / 2^s, so g lies in
 * floor(R) .. floor(R + R / (2^15 - 1)): for R < 2^13, floor(R) or, when
 * R is not an integer, floor(R) + 1. The answer ceil(R) is then g or
 * g + 1 (render_split_near checks which; its other checks are guards for
 * wider rows). */
static inline int32_t render_first_guess(uint64_t ua, uint64_t ub, int32_t kmax)
{
    if ((int64_t)ua >= 0)
        return 0;
    uint64_t num = -ua;
    uint32_t nl = (uint32_t)num, nh = (uint32_t)(num >> 32), bl = (uint32_t)ub, bh = (uint32_t)(ub >> 32);
    /* ub >> sh in [2^15, 2^16) (sh = bits(ub) - 16), in 32-bit halves */
    int sh = bh ? 48 - __builtin_clz(bh) : 16 - __builtin_clz(bl);
    if (sh >= 32) {
        bl = bh >> (sh - 32);
        nl = nh >> (sh - 32);
    } else if (sh > 0) {
        if (nh >> sh)
            return kmax + 1; /* num >> sh >= 2^32 */
        bl = bl >> sh | bh << (32 - sh);
        nl = nl >> sh | nh << (32 - sh);
    } else if (nh) {
        return kmax + 1; /* num >= 2^32 > ub 2^16 */
    }
    uint32_t q = nl / bl;
    return q > (uint32_t)kmax ? kmax + 1 : (int32_t)q;
}

/* render_split_two without a 64-bit division: from a guess of the first
 * column where the form, taken increasing (negated when b < 0), is >= 0,
 * by galloping and a binary search on that monotone predicate, with one
 * multiply-add per evaluation. The guess is render_first_guess's quotient
 * where RENDER_DIV_GUESS (one evaluation mostly settles it; g unused),
 * else *g, the row before's (updated). Any guess gives the exact answer. */
static inline __attribute__((always_inline)) bool render_split_near(int64_t a, int64_t b, int32_t kmax, int16_t *g,
                                                                     bool strict, int32_t *pr, int32_t *pl)
{
    if (b == 0)
        return render_split_const(a, kmax, strict, pr, pl);
    bool flip = b < 0;
    uint64_t ua = (uint64_t)(flip ? -a : a), ub = (uint64_t)(flip ? -b : b);
#define RENDER_GE(k) ((int64_t)(ua + render_umul_k(ub, k)) >= 0) /* k on the row: the value fits */
    int32_t lo, hi, s = 1, k;
    bool exact;
    if (RENDER_DIV_GUESS) {
        /* The guess from a 32-bit division, checked by one evaluation:
         * the first k >= 0 is g (F(g) >= 0, F(g - 1) < 0) or g + 1;
         * anything else (rows of 2^13 columns or more) takes the search
         * below. */
        k = render_first_guess(ua, ub, kmax);
        if (k <= kmax) {
            uint64_t v = ua + render_umul_k(ub, k);
            if ((int64_t)v >= 0) {
                if (k == 0 || (int64_t)(v - ub) < 0) {
                    hi = k;
                    exact = v == 0;
                    goto found;
                }
            } else if (k == kmax || (int64_t)(v + ub) >= 0) {
                hi = k + 1;
                exact = k < kmax && v + ub == 0;
                goto found;
            }
        } else if (!RENDER_GE(kmax)) {
            hi = kmax + 1;
            exact = false;
            goto found;
        }
    } else {
        k = *g < 0 ? 0 : (*g > kmax + 1 ? kmax + 1 : *g);
    }
    if (k <= kmax && !RENDER_GE(k)) { /* the first >= 0 is to the right (kmax + 1: none) */
        for (lo = k;; lo = hi, s *= 2) {
            hi = lo + s;
            if (hi > kmax) {
                hi = kmax + 1;
                break;
            }
            if (RENDER_GE(hi))
                break;
        }
    } else { /* at k or to its left (-1: none) */
        for (hi = k;; hi = lo, s *= 2) {
            lo = hi - s;
            if (lo < 0) {
                lo = -1;
                break;
            }
            if (!RENDER_GE(lo))
                break;
        }
    }
    while (hi - lo > 1) {
        int32_t mid = lo + (hi - lo) / 2;
        if (RENDER_GE(mid))
            hi = mid;
        else
            lo = mid;
    }
    exact = hi <= kmax && ua + render_umul_k(ub, hi) == 0;
    if (!RENDER_DIV_GUESS)
        *g = (int16_t)hi;
found:
#undef RENDER_GE
    /* The increasing form F is >= 0 on [hi, kmax] (> 0 from hi + 1 when
     * it is 0 at hi), < 0 on [0, hi - 1] (<= 0 up to hi then). */
    *pr = strict && exact ? hi + 1 : hi;
    *pl = !strict && exact ? hi : hi - 1;
    return flip;
}
/* The split of the scans: from a guess in the coherent loop, else by a
 * division. */
#if RENDER_COHERENT
#define RENDER_SPLIT(a, b, kmax, hint, strict, pr, pl) render_split_near(a, b, kmax, hint, strict, pr, pl)
#else
#define RENDER_SPLIT(a, b, kmax, hint, strict, pr, pl) ((void)(hint), render_split_two(a, b, kmax, strict, pr, pl))
#endif
/* The first k >= -RENDER_ESTEP_REACH with ua + ub k >= 0 (read as signed;
 * ub > 0) when it is at most RENDER_ESTEP_REACH, into *pk, and the form's
 * value there into *pv; false otherwise (the caller searches). From
 * render_first_guess's quotient (for ua >= 0 that of ua / ub, the columns
 * to the left), checked by one evaluation: within that reach the guess is
 * the answer or one column off, on the side tested. */
#define RENDER_ESTEP_REACH ((1 << 13) - 2)
static inline bool render_edge_root(uint64_t ua, uint64_t ub, int32_t *pk, uint64_t *pv)
{
    int32_t k;
    uint64_t v;
    if ((int64_t)ua < 0) {
        k = render_first_guess(ua, ub, RENDER_ESTEP_REACH); /* floor or ceil of -ua / ub */
        if (k > RENDER_ESTEP_REACH)
            return false;
        v = ua + ub * (uint64_t)k;
        if ((int64_t)v < 0) {
            v += ub;
            k++;
        }
    } else {
        k = render_first_guess(0 - ua, ub, RENDER_ESTEP_REACH); /* floor or ceil of ua / ub */
        if (k > RENDER_ESTEP_REACH)
            return false;
        v = ua - ub * (uint64_t)k;
        if ((int64_t)v < 0) {
            v += ub;
            k--;
        }
        k = -k;
    }
    if ((int64_t)v < 0 || (int64_t)(v - ub) >= 0)
        return false; /* (not the first k: outside the guess's reach) */
    *pk = k;
    *pv = v;
    return true;
}

/* render_split_near's split of edge form ek (not strict) on columns
 * x0..x0 + kmax of row iy, from its row state st (render_estep_t), where
 * the row before's column cannot simply be stepped (render_split_edge
 * steps it whenever st->next is this row, which the state sets once dk
 * and jump hold): the same row's taken as it is, else located by
 * render_edge_root, which also gives dk and jump when the row before had
 * a column. Out of line: render_runs_flat keeps few registers for the
 * stepped path. */
RENDER_MAYBE_UNUSED __attribute__((noinline)) static bool render_split_edge_at(render_estep_t *st, const render_lin_t *ek, int32_t x0,
                                                           int32_t ix0, int32_t iy, int32_t kmax, int32_t *pr,
                                                           int32_t *pl)
{
    int64_t b = 2 * ek->x;
    if (b == 0)
        return render_split_const(rlin_at(ek, ix0, iy), kmax, false, pr, pl);
    bool fall = b < 0;
    uint64_t ub = (uint64_t)(fall ? -b : b), v;
    int32_t col;
    if (st->iy == iy) {
        v = (uint64_t)st->val;
        col = st->col;
    } else {
        int64_t a = rlin_at(ek, ix0, iy);
        int32_t k;
        if (!render_edge_root((uint64_t)(fall ? -a : a), ub, &k, &v)) {
            st->iy = RENDER_ESTEP_NONE;
            st->next = RENDER_ESTEP_NO_ROW;
            return render_split_near(a, b, kmax, NULL, false, pr, pl);
        }
        col = x0 + k;
        if (st->iy == iy + 2) { /* two rows in a row: the step */
            int64_t diff = (int64_t)(v - (uint64_t)st->val); /* in (-step, step) */
            st->dk = diff <= 0 ? col - st->col : col - st->col - 1;
            st->jump = diff <= 0 ? diff : (int64_t)((uint64_t)diff - ub);
        }
    }
    st->iy = iy;
    st->col = col;
    st->val = (int64_t)v;
    st->fall = fall;
    st->next = (int16_t)(st->dk != RENDER_ESTEP_NONE ? iy - 2 : RENDER_ESTEP_NO_ROW);
    int32_t hi = col - x0;
    bool exact = v == 0 && hi >= 0 && hi <= kmax;
    hi = hi < 0 ? 0 : (hi > kmax ? kmax + 1 : hi);
    *pr = hi;
    *pl = exact ? hi : hi - 1;
    return fall;
}

/* render_split_near's split of edge form ek (not strict) on columns
 * x0..x0 + kmax of row iy, from its row state st: mostly the row
 * before's column, stepped by dk and jump (two additions and a compare),
 * else render_split_edge_at. *pr and *pl may lie beyond 0..kmax (an
 * interval of columns bounded by them means the same there). */
static inline __attribute__((always_inline)) bool render_split_edge(render_estep_t *st, const render_lin_t *ek,
                                                                     int32_t x0, int32_t ix0, int32_t iy, int32_t kmax,
                                                                     int32_t *pr, int32_t *pl)
{
    if (st->next != iy)
        return render_split_edge_at(st, ek, x0, ix0, iy, kmax, pr, pl);
    uint64_t v = (uint64_t)st->val + (uint64_t)st->jump;
    int32_t col = st->col + st->dk;
    if ((int64_t)v < 0) { /* one column more: + step = 2 |x| */
        uint64_t b = 2 * (uint64_t)ek->x;
        v += st->fall ? 0 - b : b;
        col++;
    }
    st->iy = iy;
    st->next = (int16_t)(iy - 2);
    st->col = col;
    st->val = (int64_t)v;
    *pr = col - x0;
    *pl = v == 0 ? col - x0 : col - x0 - 1;
    return st->fall;
}

/* The > 0 and < 0 (strict; else >= 0 and <= 0) intervals of a form from
 * its split. */
#define RENDER_SIGNS(a, b, kmax, hint, strict, up, down)                                               \
    do {                                                                                               \
        int32_t r_, l_;                                                                                \
        render_iv_t right_, left_;                                                                     \
        bool fall_ = RENDER_SPLIT(a, b, kmax, hint, strict, &r_, &l_);                                 \
        right_.lo = r_;                                                                                \
        right_.hi = kmax;                                                                              \
        left_.lo = 0;                                                                                  \
        left_.hi = l_;                                                                                 \
        *(up) = fall_ ? left_ : right_;                                                                \
        *(down) = fall_ ? right_ : left_;                                                              \
    } while (0)

/* Each edge's split (rk, lk; fall: it falls along the row) moves one end
 * of ge (where every edge is >= 0) and one of le (<= 0). */
static inline __attribute__((always_inline)) void render_edge_runs(bool fall, int32_t rk, int32_t lk, render_iv_t *ge,
                                                                    render_iv_t *le)
{
    if (fall) {
        ge->hi = lk < ge->hi ? lk : ge->hi;
        le->lo = rk > le->lo ? rk : le->lo;
    } else {
        ge->lo = rk > ge->lo ? rk : ge->lo;
        le->hi = lk < le->hi ? lk : le->hi;
    }
}

#endif
