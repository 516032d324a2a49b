/* render_row: the scanline loops (fast and reference), spans and the
 * pixel format. See render.h for the method. */
#include "vis/paint.h"

/* Start a row: a new stamp (so every column is uncovered) and the
 * background in every pixel, with word stores where the row is aligned. */
void render_begin_row(vis_t *r, uint8_t *rgb)
{
#if RENDER_VIS
    if (render_tracks(r))
        for (int32_t x = 0; x < r->cam->width; x++)
            r->painted[x] = RENDER_VIS_NONE;
#endif
    if (++r->stamp == RENDER_STAMP_LIMIT) {
        for (int32_t x = 0; x < r->cam->width; x++)
            r->owner[x] = 0;
        r->stamp = 1;
    }
#if FXRT_MAX_SAMPLES > 1
    if (r->sampled)
        return; /* the sampling pass reads vis, not the painted scratch row */
#endif
    render_fill_rgb(rgb, 0, r->cam->width - 1, r->world->background_rgb);
}

/* ---- the fast loop ------------------------------------------------------ */

/* ---- spans -------------------------------------------------------------- */

/* Fill pixels xa..xb of a row with colour c, in the pixel format, with
 * word stores where the row is aligned (RGB888: three words per four
 * pixels; RGB565: one word per two). */
#if FXRT_PIXEL != FXRT_RGB565
/* Pixel x of an RGB888 row, by byte stores (a 3-byte memcpy is a library
 * call on the Cortex-M0). */
static inline void render_put3(uint8_t *rgb, int32_t x, rgb8_t c)
{
    rgb[3 * x + 0] = c.r;
    rgb[3 * x + 1] = c.g;
    rgb[3 * x + 2] = c.b;
}
#endif

void render_fill_rgb(uint8_t *rgb, int32_t xa, int32_t xb, rgb8_t c)
{
    typedef uint32_t __attribute__((may_alias)) word_t;
    int32_t x = xa;
#if FXRT_PIXEL == FXRT_RGB565
    uint16_t v = render_565(c);
    render_px16_t *p16 = (render_px16_t *)(void *)rgb;
    if (((uintptr_t)rgb & 3u) == 0) {
        for (; x <= xb && (x & 1); x++)
            p16[x] = v;
        word_t two = (uint32_t)v * 0x10001u, *p = (word_t *)(void *)rgb + x / 2;
        for (; x + 1 <= xb; x += 2)
            *p++ = two;
    }
    for (; x <= xb; x++)
        p16[x] = v;
#else
    if (((uintptr_t)rgb & 3u) == 0) {
        /* Aligned rows (the firmware's framebuffer and bands). may_alias:
         * the buffer is bytes. */
        for (; x <= xb && (x & 3); x++)
            render_put3(rgb, x, c);
        if (x + 3 <= xb) {
            union {
                uint8_t b[12];
                uint32_t w[3];
            } pat;
            for (int i = 0; i < 4; i++) {
                pat.b[3 * i + 0] = c.r;
                pat.b[3 * i + 1] = c.g;
                pat.b[3 * i + 2] = c.b;
            }
            word_t *p = (word_t *)(void *)(rgb + 3 * x);
            int32_t groups = (xb - x + 1) / 4;
            x += 4 * groups;
#if FXRT_PORT_THUMB_ASM
            PORT_STORE3_LOOP(p, p + 3 * groups, pat.w[0], pat.w[1], pat.w[2]);
#else
            uint32_t w0 = pat.w[0], w1 = pat.w[1], w2 = pat.w[2];
            for (; groups > 0; groups--, p += 3) {
                p[0] = w0;
                p[1] = w1;
                p[2] = w2;
            }
#endif
        }
    }
    for (; x <= xb; x++)
        render_put3(rgb, x, c);
#endif
}

/* Fill columns xa..xb with object oi's colour (and record it in vis). */
RENDER_MAYBE_UNUSED static void render_fill(vis_t *r, uint16_t oi, int32_t xa, int32_t xb, uint8_t *rgb)
{
#if RENDER_VIS
    if (render_tracks(r)) /* only the shading and sampling passes read vis */
        for (int32_t k = xa; k <= xb; k++)
            r->painted[k] = oi;
#endif
    render_fill_rgb(rgb, xa, xb, r->obj[oi].rgb);
}

#if FXRT_NUMBER == FXRT_Q16 && !FXRT_NO_STEP
/* Columns x0 + k, k in lo..hi (empty when lo > hi). */
typedef struct {
    int32_t lo, hi;
} render_iv_t;
#endif

#if FXRT_NUMBER == FXRT_Q16 && !FXRT_NO_STEP && !FXRT_NO_SPANS

static render_iv_t render_iv_and(render_iv_t a, render_iv_t b)
{
    render_iv_t r = {a.lo > b.lo ? a.lo : b.lo, a.hi < b.hi ? a.hi : b.hi};
    return r;
}

static int32_t render_kclamp(int64_t v, int32_t kmax) { return v < -1 ? -1 : (v > kmax + 1 ? kmax + 1 : (int32_t)v); }

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

#if RENDER_COHERENT
/* ub k for a column k in 0..kmax + 1 (< 2^15): fx_umul64_small, out of
 * line on the M0 (three 32-bit products instead of an __aeabi_lmul call;
 * inline, five forms' worth of them tripled render_runs_flat's frame). */
static FXRT_INLINE_WIDE uint64_t render_umul_k(uint64_t ub, int32_t k) { return fx_umul64_small(ub, k); }

/* Where 32-bit division and CLZ are instructions (RENDER_DIV_GUESS), a
 * flat piece's runs start from a quotient instead of the row before's
 * columns: within one column of the answer wherever it is on the row, so
 * one evaluation checks it. */
#if RENDER_DIV_GUESS
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
#endif

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
    int32_t lo, hi, s = 1;
    bool exact;
#if RENDER_DIV_GUESS
    /* The guess from a 32-bit division, checked by one evaluation: the
     * first k >= 0 is g (F(g) >= 0, F(g - 1) < 0) or g + 1; anything
     * else (rows of 2^13 columns or more) takes the search below. */
    (void)g;
    int32_t k = render_first_guess(ua, ub, kmax);
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
#else
    int32_t k = *g < 0 ? 0 : (*g > kmax + 1 ? kmax + 1 : *g);
#endif
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
#if RENDER_DIV_GUESS
found:;
#else
    *g = (int16_t)hi;
#endif
#undef RENDER_GE
    /* The increasing form F is >= 0 on [hi, kmax] (> 0 from hi + 1 when
     * it is 0 at hi), < 0 on [0, hi - 1] (<= 0 up to hi then). */
    *pr = strict && exact ? hi + 1 : hi;
    *pl = !strict && exact ? hi : hi - 1;
    return flip;
}
#define RENDER_SPLIT(a, b, kmax, hint, strict, pr, pl) render_split_near(a, b, kmax, hint, strict, pr, pl)
#else
#define RENDER_SPLIT(a, b, kmax, hint, strict, pr, pl) ((void)(hint), render_split_two(a, b, kmax, strict, pr, pl))
#endif
#if RENDER_ESTEP
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
__attribute__((noinline)) static bool render_split_edge_at(render_estep_t *st, const render_lin_t *ek, int32_t x0,
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
#endif

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
bool render_split_test(int64_t a, int64_t b, int32_t kmax, int16_t *guess, bool strict, int32_t *pr, int32_t *pl)
{
#if RENDER_COHERENT
    if (guess)
        return render_split_near(a, b, kmax, guess, strict, pr, pl);
#else
    (void)guess;
#endif
    return render_split_two(a, b, kmax, strict, pr, pl);
}

#if RENDER_ESTEP
bool render_split_edge_test(render_estep_t *st, const render_lin_t *ek, int32_t x0, int32_t ix0, int32_t iy,
                            int32_t kmax, int32_t *pr, int32_t *pl)
{
    return render_split_edge(st, ek, x0, ix0, iy, kmax, pr, pl);
}
#endif

/* A flat piece's guesses (render_split_near), where it keeps them. */
#if RENDER_HINTS
#define RENDER_HINT(f) ((f)->hint)
#else
#define RENDER_HINT(f) ((int16_t *)NULL)
#endif

/* Inline into its callers (M3: 0.5 % fewer instructions on the bench
 * set), but out of line on Armv6-M, where it would grow
 * render_scan_flat's frame on the claiming path (the micro:bit's stack). */
#define RENDER_RUNS_INLINE static FXRT_INLINE_WIDE
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

#if FXRT_SPHERE_SEARCH
/* The columns k in 0..kmax where q(k) >= 0, for d2 < 0 (one run or none):
 * q rises while its step d1 + d2 k is positive, then falls, so the peak
 * and both ends are binary searches on monotone predicates. */
static render_iv_t render_sphere_run(fx128_t v, fx128_t d1, fx128_t d2, int32_t kmax)
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

#endif

/* A lone flat piece: its runs filled. */
static void render_span_flat(vis_t *r, uint16_t oi, render_flat_t *f, int32_t x0, int32_t x1, int32_t iy,
                             uint8_t *rgb)
{
    render_iv_t run[4];
    int nrun = render_runs_flat(r, f, x0, x1, iy, RENDER_HINT(f), run);
    for (int k = 0; k < nrun; k++)
        render_fill(r, oi, x0 + run[k].lo, x0 + run[k].hi, rgb);
}
#endif

#if FXRT_NUMBER == FXRT_Q16 && !FXRT_NO_STEP && !FXRT_NO_SPANS
/* Columns a..b go to object oi. */
static void render_claim_all(vis_t *r, uint16_t oi, int32_t a, int32_t b, uint8_t *rgb)
{
    uint32_t tag = (uint32_t)r->stamp << RENDER_STAMP_SHIFT | oi, *p = &r->owner[a], *e = &r->owner[b];
    for (; p + 3 <= e; p += 4) { /* four at a time: fewer loop instructions */
        p[0] = tag;
        p[1] = tag;
        p[2] = tag;
        p[3] = tag;
    }
    if (p < e) { /* two or three left */
        p[0] = tag;
        p[1] = tag;
        p += 2;
    }
    if (p == e)
        *p = tag;
    render_fill(r, oi, a, b, rgb);
}

/* Columns *a..*b, all covered by object oi: those no object has reached
 * yet on this row (outside r->dirty_lo..dirty_hi) are claimed and filled
 * without looking; *a..*b becomes the rest (false when empty). */
static bool render_claim_free(vis_t *r, uint16_t oi, int32_t *pa, int32_t *pb, uint8_t *rgb)
{
    int32_t a = *pa, b = *pb;
    int32_t fb = b < r->dirty_lo ? b : r->dirty_lo - 1;
    if (a <= fb) {
        render_claim_all(r, oi, a, fb, rgb);
        a = fb + 1;
    }
    int32_t fa = a > r->dirty_hi + 1 ? a : r->dirty_hi + 1;
    if (fa <= b) {
        render_claim_all(r, oi, fa, b, rgb);
        b = fa - 1;
    }
    *pa = a;
    *pb = b;
    return a <= b;
}
#endif

/* A flat piece among others locates its runs from this many columns on;
 * below, stepping is as cheap. With the quotient's guesses (division and
 * CLZ instructions: the M3, M4F) 4 and 6 are 0.4 % fewer instructions
 * than 8 on the bench set; on the M0, 6 and 8 measure alike (0 to 16 did
 * before). */
#define RENDER_CLAIM_MIN (RENDER_DIV_GUESS ? 6 : 8)
/* Columns of one other owner, this many or more in a row, are settled by
 * the two objects' depth ranges over stretches of them (render_claim_span),
 * which stop halving below RENDER_SPAN_LEAF columns. Measured on the bench
 * set (make qemu): 3 to 8 and leaves of 8 to 16; 4 is 0.2 % fewer
 * instructions than 6 on the M3 but 1.5 % more on the M0 in cover and
 * room, 8 is 1.6 % more on the M3, leaves of 8 or 16 0.2 % and 0.7 % more. */
#ifndef RENDER_SPAN_MIN
#define RENDER_SPAN_MIN 6
#endif
#ifndef RENDER_SPAN_LEAF
#define RENDER_SPAN_LEAF (2 * RENDER_SPAN_MIN)
#endif
#if FXRT_NUMBER == FXRT_Q16 && !FXRT_NO_STEP && !FXRT_NO_SPANS
/* Columns a..b, all covered by object oi, each settled on its own: a flat
 * piece f's depth from N and D stepped along them (single: f is its
 * object's only piece; a box's depth is the nearest of its faces there,
 * f's among them: render_resolve_box), a sphere's (f NULL) from its forms. */
__attribute__((noinline)) static void render_claim_px(vis_t *r, uint16_t oi, const render_flat_t *f, int32_t a,
                                                      int32_t b, int32_t iy, uint8_t *rgb, bool single)
{
    if (!f) {
        for (int32_t x = a; x <= b; x++)
            render_cover(r, oi, x, iy, rgb);
        return;
    }
    int32_t ix = 2 * a - r->cam->width + 1;
    uint64_t n = (uint64_t)rlin_at(&f->n, ix, iy), d = (uint64_t)rlin_at(&f->d, ix, iy);
    uint64_t sn = 2 * (uint64_t)f->n.x, sd = 2 * (uint64_t)f->d.x;
    if (single) {
        for (int32_t x = a; x <= b; x++, n += sn, d += sd)
            RENDER_COVER(r, oi, x, rgb, render_resolve_flat(r, cur_, oi, x, iy, f, (render_k_t)n, (render_k_t)d));
    } else {
        for (int32_t x = a; x <= b; x++, n += sn, d += sd)
            RENDER_COVER(r, oi, x, rgb, render_resolve_box(r, cur_, oi, x, iy, f, (render_k_t)n, (render_k_t)d));
    }
}

/* Columns a..b, all covered by object oi (a plane, triangle, sphere, or a
 * box by one of its faces) and all owned by object ci: first the objects'
 * own depth ranges, then, from column a, stretches of *len columns (the
 * last one's length, doubled after a decision, halved after none) are
 * settled by the two objects' depth ranges over them (render_span_range)
 * where these do not meet: the whole stretch goes to one object. The
 * ranges bound every depth of the stretch, so each column goes where
 * render_settle would send it. Returns how many columns from a were
 * settled; where it stops before b (an object without ranges, or a
 * stretch shorter than RENDER_SPAN_LEAF undecided), the caller settles
 * the next *len columns one by one. (A frame of its own, gone before the
 * columns' own settling: the micro:bit's stack.) */
__attribute__((noinline)) static int32_t render_claim_span(vis_t *r, uint16_t oi, uint16_t ci, int32_t a, int32_t b,
                                                           int32_t iy, int32_t *len, uint8_t *rgb)
{
    const render_obj_t *no = &r->obj[oi], *co = &r->obj[ci];
    if (!FXRT_NO_ZRANGE && no->ranged && co->ranged) { /* the objects' own ranges first */
        if (render_depth_less(co->thi, no->tlo))
            return b - a + 1;
        if (render_depth_less(no->thi, co->tlo)) {
            render_claim_all(r, oi, a, b, rgb);
            return b - a + 1;
        }
    }
    int32_t x = a, n = *len;
    while (x <= b) {
        int32_t q = x + n - 1 > b ? b : x + n - 1;
        render_depth_t nlo, nhi, olo, ohi;
        int kn = render_span_range(r, oi, x, q, iy, &nlo, &nhi, false);
        int ko = kn ? render_span_range(r, ci, x, q, iy, &olo, &ohi, false) : 0;
        if (!kn || !ko) {
            *len = b - x + 1;
            break;
        }
        /* (A sphere's bound below is worked out only where its smaller end
         * says it could decide: it lies below that end.) */
        if (render_depth_less(nhi, olo) &&
            (ko == 1 || (render_span_range(r, ci, x, q, iy, &olo, &ohi, true) && render_depth_less(nhi, olo)))) {
            render_claim_all(r, oi, x, q, rgb); /* oi nearer all along */
        } else if (!(render_depth_less(ohi, nlo) &&
                     (kn == 1 || (render_span_range(r, oi, x, q, iy, &nlo, &nhi, true) && render_depth_less(ohi, nlo))))) {
            /* not behind all along either */
            if (q - x + 1 < RENDER_SPAN_LEAF) {
                *len = q - x + 1;
                break;
            }
            n = (q - x + 2) / 2;
            continue;
        }
        x = q + 1;
        n *= 2;
        *len = n;
    }
    return x - a;
}

/* Columns a..b of object oi, all covered by it (located exactly; f: the
 * flat piece, NULL for a sphere): columns no object has reached yet are
 * claimed and filled without looking (render_claim_free); of the rest,
 * stretches of one other owner settle by ranges (render_claim_span), and
 * other columns on their own (render_claim_px). */
static void render_claim_run(vis_t *r, uint16_t oi, const render_flat_t *f, int32_t a, int32_t b, int32_t iy,
                             uint8_t *rgb, bool single)
{
    if (!render_claim_free(r, oi, &a, &b, rgb))
        return;
    if (b - a + 1 < RENDER_SPAN_MIN) {
        render_claim_px(r, oi, f, a, b, iy, rgb, single);
        return;
    }
    /* One stretch at a time: columns free on this row (or owned by a plane
     * that oi is nearer than all along it) are taken, stretches of one
     * other owner settled, oi's own (a box's other face) kept. */
    uint32_t tag = (uint32_t)r->stamp << RENDER_STAMP_SHIFT;
    int32_t fa = -1; /* free columns fa..x-1 wait to be claimed together */
    /* Column b + 1 holds, while this runs, an entry no column has (object
     * RENDER_VIS_NONE), so a stretch's scan needs no bound test. Only
     * columns a..b are written below. */
    uint32_t after = r->owner[b + 1];
    r->owner[b + 1] = RENDER_VIS_NONE;
    for (int32_t x = a; x <= b;) {
        uint32_t cur = r->owner[x] & ~RENDER_DEPTH_KNOWN;
        uint16_t ci = (uint16_t)cur;
        const uint32_t *p = &r->owner[x + 1];
        while ((*p & ~RENDER_DEPTH_KNOWN) == cur) /* (stale entries come in stretches too) */
            p++;
        int32_t y = (int32_t)(p - r->owner) - 1;
        if (render_free(r, tag, cur)) {
            if (fa < 0)
                fa = x;
            x = y + 1;
            continue;
        }
        if (fa >= 0) {
            render_claim_all(r, oi, fa, x - 1, rgb);
            fa = -1;
        }
        if (ci == oi) {
            x = y + 1;
        } else if (y - x + 1 < RENDER_SPAN_MIN) {
            render_claim_px(r, oi, f, x, y, iy, rgb, single);
            x = y + 1;
        } else {
            /* Settled by ranges where they decide, else column by column. */
            for (int32_t len = y - x + 1; x <= y;) {
                x += render_claim_span(r, oi, ci, x, y, iy, &len, rgb);
                if (x <= y) {
                    int32_t e = x + len - 1;
                    render_claim_px(r, oi, f, x, e, iy, rgb, single);
                    x = e + 1;
                    len = RENDER_SPAN_MIN; /* then ranges again from a short stretch */
                }
            }
        }
    }
    r->owner[b + 1] = after;
    if (fa >= 0)
        render_claim_all(r, oi, fa, b, rgb);
}
#endif

#if FXRT_NUMBER == FXRT_Q16 && !FXRT_NO_STEP
__attribute__((noinline)) static void render_step_flat(vis_t *r, uint16_t oi, const render_flat_t *f, int32_t x0,
                                                       int32_t x1, int32_t iy, uint8_t *rgb, bool lone, bool single);

/* A flat piece across columns x0..x1, by spans where it is wide enough
 * (true); false: the caller steps it (render_step_flat), each form linear,
 * so one exact 64-bit addition per form and pixel. */
static bool render_scan_flat(vis_t *r, uint16_t oi, render_flat_t *f, int32_t x0, int32_t x1, int32_t iy,
                             uint8_t *rgb, bool lone)
{
    bool single = r->obj[oi].kind == RENDER_FLAT;
#if !FXRT_NO_SPANS
    /* Alone on the row and wide: runs located exactly, filled by words
     * (a division per form pays off from about 4 columns per form on the M3). */
    if (lone && x1 - x0 >= 4 * (1 + f->edges)) {
        render_span_flat(r, oi, f, x0, x1, iy, rgb);
        return true;
    }
    /* Among others and wide: its runs located the same way, then each
     * covered column claimed (render_claim_run). */
    if (x1 - x0 >= RENDER_CLAIM_MIN) {
        render_iv_t iv[4];
        int nrun = render_runs_flat(r, f, x0, x1, iy, RENDER_HINT(f), iv);
        for (int k = 0; k < nrun; k++)
            render_claim_run(r, oi, f, x0 + iv[k].lo, x0 + iv[k].hi, iy, rgb, single);
        return true;
    }
#else
    (void)r, (void)oi, (void)f, (void)x0, (void)x1, (void)iy, (void)rgb, (void)lone, (void)single;
#endif
    return false;
}

/* Narrow: every column stepped and tested. (A frame of its own, apart
 * from the claiming path's: the micro:bit's stack.) */
__attribute__((noinline)) static void render_step_flat(vis_t *r, uint16_t oi, const render_flat_t *f, int32_t x0,
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

/* A sphere's row from column x0 (ix0), render_srow_t (render.h): c and
 * disc are quadratic along the row, so their 128-bit forward differences
 * (second difference constant) give exactly the values render_sphere_cd
 * computes from scratch. (A frame of its own, not render_row_vis's.) */
/* render_sphere_cd out of line: render_sphere_row's three calls share it
 * (inline, its temporaries would grow render_sphere_row's frame). */
__attribute__((noinline)) static void render_sphere_cd_row(const render_obj_t *o, int32_t ix, int32_t iy, rsw_t *c,
                                                           rsw_t *disc)
{
    render_sphere_cd(o, ix, iy, c, disc);
}

__attribute__((noinline)) static void render_sphere_row(const vis_t *r, const render_obj_t *o, int32_t ix0,
                                                        int32_t iy, render_srow_t *s)
{
    fx128_t c[3], q[3];
    for (int k = 0; k < 3; k++)
        render_sphere_cd_row(o, ix0 + 2 * k, iy, &c[k], &q[k]);
    s->ortho = render_ortho(r->cam);
    s->inside = !s->ortho && rsw_neg(c[0]);
    s->use_c = s->ortho && !(o->u.sphere->b.c > 0);
    const fx128_t *f = s->use_c ? c : q;
    s->v = f[0];
    s->d1 = fx128_sub(f[1], f[0]);
    s->d2 = fx128_add(fx128_sub(f[2], fx128_add(f[1], f[1])), f[0]);
}

#if !FXRT_NO_SPANS && (FXRT_SPHERE_SEARCH || RENDER_SROWS)
/* Where b > 0 (the centre's side of the eye) on columns k = 0..kmax. */
RENDER_MAYBE_UNUSED static render_iv_t render_sphere_front(const render_obj_t *o, int32_t ix0, int32_t iy, int32_t kmax)
{
    int32_t pr, pl;
    bool fall = render_split_two(rlin_at(&o->u.sphere->b, ix0, iy), 2 * o->u.sphere->b.x, kmax, true, &pr, &pl);
    render_iv_t pos = {fall ? 0 : pr, fall ? pl : kmax};
    return pos;
}
#endif

/* The runs of a sphere over columns x0..x1 (k from x0; the same columns
 * the per-column test covers). At most two: b > 0 is a half-line and disc
 * >= 0 one interval (disc concave along the row) or the outside of one
 * (convex); in orthographic views one interval. */
static int render_sphere_runs(const render_obj_t *o, const render_srow_t *s, int32_t x0, int32_t x1, int32_t ix0,
                              int32_t iy, render_iv_t run[2])
{
    int32_t kmax = x1 - x0;
    if (s->inside) {
        run[0].lo = 0;
        run[0].hi = kmax;
        return 1;
    }
#if !FXRT_NO_SPANS && FXRT_SPHERE_SEARCH
    if (!s->ortho && s->d2.hi < 0) {
        /* Perspective, disc concave along the row: its run is located by
         * exact evaluations (binary searches on the monotone sides of the
         * quadratic) instead of stepping. */
        run[0] = render_iv_and(render_sphere_run(s->v, s->d1, s->d2, kmax), render_sphere_front(o, ix0, iy, kmax));
        return run[0].lo <= run[0].hi;
    }
#endif
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
static inline int render_sphere_row_runs(vis_t *r, const render_obj_t *o, int32_t row, render_iv_t run[2]);
static const render_srow_t *render_sphere_row_at(vis_t *r, const render_obj_t *o, int32_t row);
static int render_sphere_runs_at(vis_t *r, const render_obj_t *o, int32_t row, const render_srow_t *s,
                                 render_iv_t run[2]);

/* A lone sphere on the row at iy (its bounds x0..x1): its forms stepped
 * from the row before and its runs searched from the row before's. */
__attribute__((noinline)) static void render_lone_sphere(vis_t *r, uint16_t oi, const render_obj_t *o,
                                                         int32_t iy, uint8_t *rgb)
{
    int32_t row = render_row_of(r->cam, iy);
    render_iv_t run[2];
    int nrun = render_sphere_row_runs(r, o, row, run);
    for (int k = 0; k < nrun; k++)
        render_fill(r, oi, o->x0 + run[k].lo, o->x0 + run[k].hi, rgb);
}
#endif

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
#if RENDER_SROWS
    if (lone && r->cam->height >= 3 && o->index < FXRT_COHERENT_SPHERES) { /* the series needs three rows */
        render_lone_sphere(r, oi, o, iy, rgb);
        return;
    }
#endif
    int32_t ix0 = 2 * x0 - r->cam->width + 1;
    /* The row's forms, in r->scache (render_row_vis's): kept for
     * render_depth_at while this row lasts (a lone sphere owns no column). */
    render_srow_t *sp = &r->scache->s;
    r->scache->ix0 = ix0;
    r->scache->iy = iy;
    r->scache->oi = lone ? RENDER_VIS_NONE : oi;
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
#if !FXRT_NO_SPANS && (FXRT_SPHERE_SEARCH || RENDER_SROWS)
#if RENDER_SROWS
    bool rows = r->cam->height >= 3 && o->index < FXRT_COHERENT_SPHERES;
#else
    bool rows = false;
#endif
    if (!sp->ortho && (rows || FXRT_SPHERE_SEARCH)) {
        /* Perspective: its runs located exactly (from the row before's
         * where it keeps row state, else by render_sphere_runs' search),
         * then claimed like a flat piece's; a depth, where an owner needs
         * one, comes from r->scache. */
        render_iv_t run[2];
        int nrun;
#if RENDER_SROWS
        if (rows)
            nrun = render_sphere_runs_at(r, o, render_row_of(r->cam, iy), sp, run);
        else
#endif
            nrun = render_sphere_runs(o, sp, x0, x1, ix0, iy, run);
        for (int k = 0; k < nrun; k++)
            render_claim_run(r, oi, NULL, x0 + run[k].lo, x0 + run[k].hi, iy, rgb, true);
        return;
    }
#endif
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
/* FXRT_FLOAT_STEP: the float programmer's scanline. Each linear form is
 * evaluated directly at the segment's first pixel and then stepped by one
 * addition per pixel (the quadratic a by forward differences); rounding
 * accumulates along the segment, unlike the exact Q16.16 steps. */
static void render_scan_flat_f(vis_t *r, uint16_t oi, const render_flat_t *f, int32_t x0, int32_t x1, int32_t iy,
                               uint8_t *rgb, bool lone)
{
    bool single = r->obj[oi].kind == RENDER_FLAT;
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
            (render_step_flat(r, oi, f, x0, x1, iy, rgb, lone, (r)->obj[oi].kind == RENDER_FLAT), false)))
#else
#define RENDER_SCAN_SPHERE render_scan_sphere_f
#define RENDER_SCAN_FLAT render_scan_flat_f
#endif

/* Is object i the only one whose bounds reach columns x0..x1 on this row?
 * Then nothing can compete for its pixels. (Only checked for small worlds;
 * a large one simply takes the owner path.) */
static bool render_alone(const vis_t *r, uint16_t i, int32_t row)
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

#if RENDER_COHERENT
/* The ray's row coordinate iy of fine row `row` (0 = top). */
RENDER_MAYBE_UNUSED static int32_t render_iy(const cam_t *cam, int32_t row)
{
    return 2 * (cam->height - 1 - row) - cam->height + 1;
}

#if RENDER_SROWS

void render_srow_setup(vis_t *r, uint16_t i)
{
    const render_obj_t *o = &r->obj[i];
    r->srow[o->index].vrow = r->srow[o->index].prow = -2;
    r->srow[o->index].pk = (int16_t)((o->x1 - o->x0) / 2);
}

/* One fine row down the series of render_sphere_row_at. */
static inline void render_srow_step(vis_t *r, uint16_t si)
{
    __typeof__(r->srow[0]) *q = &r->srow[si];
    q->cur.v = fx128_add(q->cur.v, q->dvk);
    q->dvk = fx128_add(q->dvk, q->ddv);
    q->cur.d1 = fx128_add(q->cur.d1, q->dd1);
    q->vrow++;
}

/* The series on fine row `row` - 1, from the forms on three rows (on the
 * screen, where every form fits): their differences give it exactly.
 * One row's forms at a time (the micro:bit's stack). */
__attribute__((noinline)) static void render_srow_start(vis_t *r, const render_obj_t *o, int32_t row)
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

/* render_sphere_row on fine row `row`, a fine camera of at least three
 * rows: three additions after the row before. In place (no copies: on
 * the M0 a copy of 128-bit values is a memcpy call). */
static const render_srow_t *render_sphere_row_at(vis_t *r, const render_obj_t *o, int32_t row)
{
    if (row != r->srow[o->index].vrow + 1)
        render_srow_start(r, o, row);
    render_srow_step(r, o->index);
    return &r->srow[o->index].cur;
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
__attribute__((noinline)) static int render_sphere_runs_at(vis_t *r, const render_obj_t *o, int32_t row,
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
        switch (o->kind) {
        case RENDER_ALL:
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
    render_scache_t scache;
    render_scache_reset(&scache);
    r->scache = &scache;
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
        switch (o->kind) {
        case RENDER_ALL:
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
                if (FXRT_NO_BOUNDS || o->kind == RENDER_FLAT)
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
                if (render_covers(o, ix, iy))
                    RENDER_HIT(r, i, x, iy, rgb, lone);
            break;
#endif
        }
        r->dirty_lo = x0 < dlo ? x0 : dlo;
        r->dirty_hi = x1 > dhi ? x1 : dhi;
    }
#if FXRT_NUMBER == FXRT_Q16 && !FXRT_NO_STEP
    r->scache = NULL;
#endif
}
