/* render_row: the scanline loops (fast and reference), spans and the
 * pixel format. See render.h for the method. */
#include "render_int.h"
#include "shade.h"

/* Claim column x for object oi: free columns are taken at once, a column
 * owned by another object goes to the nearer (RESOLVE, which may use cur_),
 * and the pixel is painted when oi wins. */
#define RENDER_COVER(r, oi, x, rgb, RESOLVE)                                         \
    do {                                                                         \
        uint32_t tag_ = (uint32_t)(r)->stamp << RENDER_STAMP_SHIFT, cur_ = (r)->owner[x]; \
        if ((cur_ & ~0x1FFFFu) != tag_)                                          \
            (r)->owner[x] = tag_ | (oi);                                         \
        else if ((uint16_t)cur_ == (oi) || !(RESOLVE))                           \
            break;                                                               \
        render_paint(r, oi, x, rgb);                                             \
    } while (0)

/* Paint column x in object oi's colour (the row's pixel format). */
#if FXRT_PIXEL == FXRT_RGB565
typedef uint16_t __attribute__((may_alias)) render_px16_t;
static inline void render_paint(render_t *r, uint16_t oi, int32_t x, uint8_t *rgb)
{
#if RENDER_VIS
    r->vis[x] = oi;
#endif
    ((render_px16_t *)(void *)rgb)[x] = r->obj[oi].px;
}
#else
static inline void render_paint(render_t *r, uint16_t oi, int32_t x, uint8_t *rgb)
{
#if RENDER_VIS
    r->vis[x] = oi;
#endif
    rgb8_t c = r->obj[oi].rgb;
    rgb[3 * x + 0] = c.r;
    rgb[3 * x + 1] = c.g;
    rgb[3 * x + 2] = c.b;
}
#endif

/* Record that object oi covers column x and paint it if it is the nearest
 * so far. The result does not depend on the order of calls (depth, then
 * id, order objects totally), so both loops agree. */
static inline void render_cover(render_t *r, uint16_t oi, int32_t x, int32_t iy, uint8_t *rgb)
{
    RENDER_COVER(r, oi, x, rgb, render_resolve(r, cur_, oi, x, iy));
}

/* A hit at column x: paint directly when the object is alone on the row
 * (no other object's bounds reach it, so no bookkeeping). */
#define RENDER_HIT(r, oi, x, iy, rgb, lone)                                    \
    do {                                                                       \
        if (lone)                                                              \
            render_paint(r, oi, x, rgb);                                       \
        else                                                                   \
            render_cover(r, oi, x, iy, rgb);                                   \
    } while (0)

/* Start a row: a new stamp (so every column is uncovered) and the
 * background in every pixel, with word stores where the row is aligned. */
static void render_begin_row(render_t *r, uint8_t *rgb)
{
#if RENDER_VIS
    if (render_tracks(r))
        for (int32_t x = 0; x < r->cam->width; x++)
            r->vis[x] = RENDER_VIS_NONE;
#endif
    if (++r->stamp == RENDER_STAMP_LIMIT) {
        for (int32_t x = 0; x < r->cam->width; x++)
            r->owner[x] = 0;
        r->stamp = 1;
    }
#if FXRT_MAX_SAMPLES > 1
    if (r->samples > 1)
        return; /* the sampling pass reads vis, not the painted scratch row */
#endif
    rgb8_t bg = r->world->background_rgb;
    typedef uint32_t __attribute__((may_alias)) word_t;
#if FXRT_PIXEL == FXRT_RGB565
    uint16_t v = render_565(bg);
    int32_t n = r->cam->width, i = 0;
    render_px16_t *p16 = (render_px16_t *)(void *)rgb;
    if (((uintptr_t)rgb & 3u) == 0) {
        word_t two = (uint32_t)v * 0x10001u, *p = (word_t *)(void *)rgb;
        for (; i + 2 <= n; i += 2)
            *p++ = two;
    }
    for (; i < n; i++)
        p16[i] = v;
#else
    uint8_t pat[12];
    for (int i = 0; i < 4; i++) {
        pat[3 * i + 0] = bg.r;
        pat[3 * i + 1] = bg.g;
        pat[3 * i + 2] = bg.b;
    }
    int32_t n = 3 * r->cam->width, i = 0;
    if (((uintptr_t)rgb & 3u) == 0) {
        /* Aligned rows (the firmware's framebuffer and bands): three word
         * stores per four pixels. may_alias: the buffer is bytes. */
        word_t w[3];
        __builtin_memcpy(w, pat, 12);
        word_t *p = (word_t *)(void *)rgb;
        for (; i + 12 <= n; i += 12, p += 3) {
            p[0] = w[0];
            p[1] = w[1];
            p[2] = w[2];
        }
    } else {
        for (; i + 12 <= n; i += 12)
            __builtin_memcpy(rgb + i, pat, 12);
    }
    for (; i < n; i++)
        rgb[i] = pat[i % 3];
#endif
}

void render_row_reference(render_t *r, int32_t row, uint8_t *rgb)
{
#if FXRT_MAX_SAMPLES > 1
    if (r->samples > 1) {
        render_sample_row(r, row, rgb, true);
        return;
    }
#endif
    render_row_reference_vis(r, row, rgb);
#if FXRT_MAX_LIGHTS > 0
    if (render_tracks(r))
        render_shade_row(r, row, rgb);
#endif
}

void render_row_reference_vis(render_t *r, int32_t row, uint8_t *rgb)
{
    int32_t w = r->cam->width, y = r->cam->height - 1 - row;
    int32_t iy = 2 * y - r->cam->height + 1;
    render_begin_row(r, rgb);
    r->row_win = 0;
    for (int32_t x = 0; x < w; x++) {
        int32_t ix = 2 * x - w + 1;
        for (uint16_t i = 0; i < r->count; i++) {
            if (FXRT_NO_HOIST)
                render_setup_object(r, i);
            if (render_covers(&r->obj[i], ix, iy))
                render_cover(r, i, x, iy, rgb);
        }
    }
}

/* ---- the fast loop ------------------------------------------------------ */

/* ---- spans -------------------------------------------------------------- */

/* Fill columns xa..xb with object oi's colour, with word stores where the
 * row is aligned (RGB888: three words per four pixels; RGB565: one word
 * per two). */
RENDER_MAYBE_UNUSED static void render_fill(render_t *r, uint16_t oi, int32_t xa, int32_t xb, uint8_t *rgb)
{
    typedef uint32_t __attribute__((may_alias)) word_t;
    int32_t x = xa;
#if RENDER_VIS
    if (render_tracks(r)) /* only the shading and sampling passes read vis */
        for (int32_t k = xa; k <= xb; k++)
            r->vis[k] = oi;
#endif
#if FXRT_PIXEL == FXRT_RGB565
    if (((uintptr_t)rgb & 3u) == 0) {
        for (; x <= xb && (x & 1); x++)
            render_paint(r, oi, x, rgb);
        word_t two = (uint32_t)r->obj[oi].px * 0x10001u, *p = (word_t *)(void *)rgb + x / 2;
        for (; x + 1 <= xb; x += 2)
            *p++ = two;
    }
#else
    if (((uintptr_t)rgb & 3u) == 0) {
        for (; x <= xb && (x & 3); x++)
            render_paint(r, oi, x, rgb);
        if (x + 3 <= xb) {
            rgb8_t c = r->obj[oi].rgb;
            uint8_t pat[12];
            for (int i = 0; i < 4; i++) {
                pat[3 * i + 0] = c.r;
                pat[3 * i + 1] = c.g;
                pat[3 * i + 2] = c.b;
            }
            word_t w[3], *p = (word_t *)(void *)(rgb + 3 * x);
            __builtin_memcpy(w, pat, 12);
            for (; x + 3 <= xb; x += 4, p += 3) {
                p[0] = w[0];
                p[1] = w[1];
                p[2] = w[2];
            }
        }
    }
#endif
    for (; x <= xb; x++)
        render_paint(r, oi, x, rgb);
}

#if FXRT_NUMBER == FXRT_Q16 && !FXRT_NO_STEP && !FXRT_NO_SPANS
/* Columns x0 + k, k in lo..hi (empty when lo > hi). */
typedef struct {
    int32_t lo, hi;
} render_iv_t;

static render_iv_t render_iv_and(render_iv_t a, render_iv_t b)
{
    render_iv_t r = {a.lo > b.lo ? a.lo : b.lo, a.hi < b.hi ? a.hi : b.hi};
    return r;
}

static int32_t render_kclamp(int64_t v, int32_t kmax) { return v < -1 ? -1 : (v > kmax + 1 ? kmax + 1 : (int32_t)v); }

/* Where along a row segment k = 0..kmax a linear form a + b k is > 0,
 * >= 0, < 0 and <= 0 (iv[0..3]), exactly: one floor division locates its
 * root, and the remainder says whether the root is a column. */
static void render_signs(int64_t a, int64_t b, int32_t kmax, render_iv_t iv[4])
{
    render_iv_t all = {0, kmax}, none = {1, 0};
    if (b == 0) {
        iv[0] = a > 0 ? all : none;
        iv[1] = a >= 0 ? all : none;
        iv[2] = a < 0 ? all : none;
        iv[3] = a <= 0 ? all : none;
        return;
    }
    bool flip = b < 0; /* then work with -(a + b k) */
    if (flip) {
        a = -a;
        b = -b;
    }
    int64_t q = -a / b, rem = -a % b; /* |a|, |b| < 2^62: no overflow */
    if (rem < 0)
        q--; /* floor(-a / b) */
    bool exact = rem == 0;
    render_iv_t pos = {render_kclamp(q + 1, kmax), kmax}, nonneg = {render_kclamp(exact ? q : q + 1, kmax), kmax};
    render_iv_t neg = {0, render_kclamp(exact ? q - 1 : q, kmax)}, nonpos = {0, render_kclamp(q, kmax)};
    iv[0] = flip ? neg : pos;
    iv[1] = flip ? nonpos : nonneg;
    iv[2] = flip ? pos : neg;
    iv[3] = flip ? nonneg : nonpos;
}

/* A flat piece's hits on columns x0..x1 as at most four runs (k from
 * x0, possibly overlapping), found exactly from its forms: the same sign
 * tests as the stepping loop (N and D of one strict sign, edges all >= 0
 * or all <= 0). Returns the number of runs. */
static int render_runs_flat(const render_t *r, const render_flat_t *f, int32_t x0, int32_t x1, int32_t iy,
                            render_iv_t run[4])
{
    int32_t ix0 = 2 * x0 - r->cam->width + 1, kmax = x1 - x0;
    render_iv_t n[4], d[4], e[4], ge = {0, kmax}, le = {0, kmax};
    render_signs(rlin_at(&f->n, ix0, iy), 2 * f->n.x, kmax, n);
    render_signs(rlin_at(&f->d, ix0, iy), 2 * f->d.x, kmax, d);
    render_iv_t front[2] = {render_iv_and(n[0], d[0]), render_iv_and(n[2], d[2])};
    for (int k = 0; k < f->edges; k++) {
        const render_lin_t *ek = render_edge_k(f, k);
        render_signs(rlin_at(ek, ix0, iy), 2 * ek->x, kmax, e);
        ge = render_iv_and(ge, e[1]);
        le = render_iv_and(le, e[3]);
    }
    int nrun = 0;
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
/* a * m exactly (mod 2^128, so exact whenever the product fits). */
static fx128_t render_mul128_small(fx128_t a, int32_t m)
{
    uint32_t um = m < 0 ? 0u - (uint32_t)m : (uint32_t)m;
    uint64_t p0 = (uint64_t)(uint32_t)a.lo * um, p1 = (a.lo >> 32) * um;
    fx128_t r;
    r.lo = p0 + (p1 << 32);
    r.hi = (int64_t)((uint64_t)a.hi * um + (p1 >> 32) + (r.lo < p0 ? 1u : 0u));
    return m < 0 ? fx128_neg(r) : r;
}

/* q(k) = v + d1 k + d2 k (k - 1) / 2: the value the forward differences
 * reach after k steps, evaluated directly (exact). */
static fx128_t render_quad_k(fx128_t v, fx128_t d1, fx128_t d2, int32_t k)
{
    return fx128_add(fx128_add(v, render_mul128_small(d1, k)), render_mul128_small(d2, (int32_t)((int64_t)k * (k - 1) / 2)));
}

/* The columns k in 0..kmax where q(k) >= 0, for d2 < 0 (one run or none):
 * q rises while its step d1 + d2 k is positive, then falls, so the peak
 * and both ends are binary searches on monotone predicates. */
static render_iv_t render_sphere_run(fx128_t v, fx128_t d1, fx128_t d2, int32_t kmax)
{
    render_iv_t none = {1, 0};
    int32_t lo = 0, hi = kmax; /* peak: first k whose step is <= 0 (or kmax) */
    while (lo < hi) {
        int32_t mid = lo + (hi - lo) / 2;
        fx128_t step = fx128_add(d1, render_mul128_small(d2, mid));
        if (step.hi < 0 || (step.hi == 0 && step.lo == 0))
            hi = mid;
        else
            lo = mid + 1;
    }
    int32_t peak = lo;
    if (render_quad_k(v, d1, d2, peak).hi < 0)
        return none;
    int32_t a = 0, b = peak; /* first k <= peak with q >= 0 */
    while (a < b) {
        int32_t mid = a + (b - a) / 2;
        if (render_quad_k(v, d1, d2, mid).hi >= 0)
            b = mid;
        else
            a = mid + 1;
    }
    render_iv_t run;
    run.lo = a;
    a = peak, b = kmax; /* last k >= peak with q >= 0 */
    while (a < b) {
        int32_t mid = b - (b - a) / 2;
        if (render_quad_k(v, d1, d2, mid).hi >= 0)
            a = mid;
        else
            b = mid - 1;
    }
    run.hi = a;
    return run;
}

#endif

/* A lone flat piece: its runs filled. */
static void render_span_flat(render_t *r, uint16_t oi, const render_flat_t *f, int32_t x0, int32_t x1, int32_t iy,
                             uint8_t *rgb)
{
    render_iv_t run[4];
    int nrun = render_runs_flat(r, f, x0, x1, iy, run);
    for (int k = 0; k < nrun; k++)
        render_fill(r, oi, x0 + run[k].lo, x0 + run[k].hi, rgb);
}
#endif

#if FXRT_NUMBER == FXRT_Q16 && !FXRT_NO_STEP
/* Step a flat piece across columns x0..x1: each form is linear, so one
 * exact 64-bit addition per form and pixel. */
static void render_scan_flat(render_t *r, uint16_t oi, const render_flat_t *f, int32_t x0, int32_t x1, int32_t iy,
                             uint8_t *rgb, bool lone)
{
    bool single = r->obj[oi].kind == RENDER_FLAT;
#if !FXRT_NO_SPANS
    /* Alone on the row and wide: runs located exactly, filled by words
     * (a division per form pays off from about 4 columns per form on the M3). */
    if (lone && x1 - x0 >= 4 * (1 + f->edges)) {
        render_span_flat(r, oi, f, x0, x1, iy, rgb);
        return;
    }
    /* A plane among others: its run located the same way, then each
     * column claimed (a depth, where one is needed, from the forms). */
    if (f->edges == 0 && x1 - x0 >= 8) {
        render_iv_t iv[4];
        int nrun = render_runs_flat(r, f, x0, x1, iy, iv);
        uint32_t tag = (uint32_t)r->stamp << RENDER_STAMP_SHIFT | oi;
        for (int k = 0; k < nrun; k++) {
            int32_t a = x0 + iv[k].lo, b = x0 + iv[k].hi;
            /* Columns no object has reached yet on this row: claimed and
             * filled without looking. */
            int32_t fa = a, fb = b < r->dirty_lo ? b : r->dirty_lo - 1;
            if (fa <= fb) {
                for (int32_t x = fa; x <= fb; x++)
                    r->owner[x] = tag;
                render_fill(r, oi, fa, fb, rgb);
                a = fb + 1;
            }
            fa = a > r->dirty_hi + 1 ? a : r->dirty_hi + 1;
            if (fa <= b) {
                for (int32_t x = fa; x <= b; x++)
                    r->owner[x] = tag;
                render_fill(r, oi, fa, b, rgb);
                b = fa - 1;
            }
            for (int32_t x = a; x <= b; x++)
                RENDER_COVER(r, oi, x, rgb, render_resolve(r, cur_, oi, x, iy));
        }
        return;
    }
#endif
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
            else if (single) /* a box's depth is the nearest of its faces there */
                RENDER_COVER(r, oi, x, rgb, render_resolve_flat(r, cur_, oi, x, iy, f, (render_k_t)n, (render_k_t)d));
            else
                render_cover(r, oi, x, iy, rgb);
        }
        n += sn;
        d += sd;
        e[0] += se[0];
        e[1] += se[1];
        e[2] += se[2];
        e[3] += se[3];
    }
}

/* Step a sphere, exactly: c and disc are quadratic along the row, so
 * their 128-bit forward differences (second difference constant) give
 * exactly the values render_sphere_cd computes from scratch. The test
 * c < 0 || (b > 0 && disc >= 0) splits by what is constant along the row:
 * in perspective c is, in orthographic b is, and c < 0 implies disc > 0. */
static void render_scan_sphere(render_t *r, uint16_t oi, const render_obj_t *o, int32_t x0, int32_t x1, int32_t iy,
                               uint8_t *rgb, bool lone)
{
    int32_t ix0 = 2 * x0 - r->cam->width + 1;
    fx128_t c[3], q[3];
    for (int k = 0; k < 3; k++)
        render_sphere_cd(o, ix0 + 2 * k, iy, &c[k], &q[k]);
    bool ortho = render_ortho(r->cam);
    if (!ortho && rsw_neg(c[0])) { /* eye inside: every pixel */
        for (int32_t x = x0; x <= x1; x++)
            RENDER_HIT(r, oi, x, iy, rgb, lone);
        return;
    }
    bool use_c = ortho && !(o->u.sphere->b.c > 0);
    fx128_t *f = use_c ? c : q;
    fx128_t v = f[0], d1 = fx128_sub(f[1], f[0]), d2 = fx128_add(fx128_sub(f[2], fx128_add(f[1], f[1])), f[0]);
#if !FXRT_NO_SPANS && FXRT_SPHERE_SEARCH
    if (lone && !ortho && d2.hi < 0) {
        /* Alone, in perspective, disc concave along the row: its run is
         * located by exact evaluations (binary searches on the monotone
         * sides of the quadratic) instead of stepping, then filled. */
        render_iv_t bi[4];
        render_signs(rlin_at(&o->u.sphere->b, ix0, iy), 2 * o->u.sphere->b.x, x1 - x0, bi);
        render_iv_t run = render_sphere_run(v, d1, d2, x1 - x0);
        run = render_iv_and(run, bi[0]);
        if (run.lo <= run.hi)
            render_fill(r, oi, x0 + run.lo, x0 + run.hi, rgb);
        return;
    }
#endif
    if (lone) {
        /* Alone on the row: find each run by stepping and fill it. The
         * covered set is one run when it is an interval: orthographic
         * (c < 0 and disc >= 0 are convex and concave in x), perspective
         * when disc is concave (d2 < 0) - then stop after it. */
        bool one_run = ortho || d2.hi < 0;
        uint64_t b = ortho ? 1 : (uint64_t)rlin_at(&o->u.sphere->b, ix0, iy), sb = ortho ? 0 : 2 * (uint64_t)o->u.sphere->b.x;
        int32_t start = -1, x;
        for (x = x0; x <= x1; x++, b += sb, v = fx128_add(v, d1), d1 = fx128_add(d1, d2)) {
            bool hit = ortho ? (use_c ? v.hi < 0 : v.hi >= 0) : ((render_k_t)b > 0 && v.hi >= 0);
            if (hit) {
                if (start < 0)
                    start = x;
            } else if (start >= 0) {
                render_fill(r, oi, start, x - 1, rgb);
                start = -1;
                if (one_run)
                    return;
            }
        }
        if (start >= 0)
            render_fill(r, oi, start, x1, rgb);
        return;
    }
    if (ortho) {
        /* c + disc = k + r2 along every ray (a = 1), and b is constant. */
        fx128_t kr = fx128_add(o->u.sphere->k, o->u.sphere->r2);
        render_k_t b = o->u.sphere->b.c;
        for (int32_t x = x0; x <= x1; x++, v = fx128_add(v, d1), d1 = fx128_add(d1, d2)) {
            if (!(use_c ? v.hi < 0 : v.hi >= 0))
                continue;
            if (lone)
                render_paint(r, oi, x, rgb);
            else
                RENDER_COVER(r, oi, x, rgb,
                             render_resolve_sphere(r, cur_, oi, x, iy, b, use_c ? v : fx128_sub(kr, v),
                                                   use_c ? fx128_sub(kr, v) : v));
        }
        return;
    }
    uint64_t b = (uint64_t)rlin_at(&o->u.sphere->b, ix0, iy), sb = 2 * (uint64_t)o->u.sphere->b.x;
    fx128_t k = o->u.sphere->k;
    for (int32_t x = x0; x <= x1; x++, b += sb, v = fx128_add(v, d1), d1 = fx128_add(d1, d2)) {
        if (!((render_k_t)b > 0 && v.hi >= 0))
            continue;
        if (lone)
            render_paint(r, oi, x, rgb);
        else
            RENDER_COVER(r, oi, x, rgb, render_resolve_sphere(r, cur_, oi, x, iy, (render_k_t)b, k, v));
    }
}
#endif

#if FXRT_NUMBER != FXRT_Q16 && FXRT_FLOAT_STEP && !FXRT_NO_STEP
/* FXRT_FLOAT_STEP: the float programmer's scanline. Each linear form is
 * evaluated directly at the segment's first pixel and then stepped by one
 * addition per pixel (the quadratic a by forward differences); rounding
 * accumulates along the segment, unlike the exact Q16.16 steps. */
static void render_scan_flat_f(render_t *r, uint16_t oi, const render_flat_t *f, int32_t x0, int32_t x1, int32_t iy,
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

static void render_scan_sphere_f(render_t *r, uint16_t oi, const render_obj_t *o, int32_t x0, int32_t x1, int32_t iy,
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
                RENDER_COVER(r, oi, x, rgb, render_resolve_sphere(r, cur_, oi, x, iy, b, c, disc));
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
#define RENDER_SCAN_FLAT render_scan_flat
#else
#define RENDER_SCAN_SPHERE render_scan_sphere_f
#define RENDER_SCAN_FLAT render_scan_flat_f
#endif

/* Is object i the only one whose bounds reach columns x0..x1 on this row?
 * Then nothing can compete for its pixels. (Only checked for small worlds;
 * a large one simply takes the owner path.) */
static bool render_alone(const render_t *r, uint16_t i, int32_t row)
{
    if (r->count > 16)
        return false;
    const render_obj_t *o = &r->obj[i];
    for (uint16_t j = 0; j < r->count; j++) {
        const render_obj_t *p = &r->obj[j];
        if (j != i && row >= p->r0 && row <= p->r1 && p->x0 <= o->x1 && p->x1 >= o->x0)
            return false;
    }
    return true;
}

/* The visibility pass of one row: every object's coverage, the nearest
 * owner of each column, flat colours painted (and r->vis recorded for the
 * shading pass). Out of line so that its frame is gone before the shading
 * pass runs (stack depth on the micro:bit). */
__attribute__((noinline)) void render_row_vis(render_t *r, int32_t row, uint8_t *rgb)
{
    const cam_t *cam = r->cam;
    int32_t w = cam->width, y = cam->height - 1 - row;
    int32_t iy = 2 * y - cam->height + 1;
    render_begin_row(r, rgb);
    r->dirty_lo = (int16_t)w;
    r->dirty_hi = -1;
    for (uint16_t i = 0; i < r->count; i++) {
        const render_obj_t *o = &r->obj[i];
        if (!FXRT_NO_BOUNDS && (row < o->r0 || row > o->r1))
            continue;
        int32_t x0 = FXRT_NO_BOUNDS ? 0 : o->x0, x1 = FXRT_NO_BOUNDS ? w - 1 : o->x1;
        if (x0 > x1)
            continue;
        if (!FXRT_NO_BOUNDS && o->kind == RENDER_FLAT && render_face(o, 0)->edges == 0) {
            /* A plane: along a row its front test is one interval, so if
             * it fails at both ends the row is beyond the horizon. */
            if (!render_flat_at(render_face(o, 0), 2 * x0 - w + 1, iy) &&
                !render_flat_at(render_face(o, 0), 2 * x1 - w + 1, iy))
                continue;
        }
        bool lone = !FXRT_NO_LONE && render_alone(r, i, row);
        r->row_win = 0;
        if (!FXRT_NO_ZRANGE && !lone && r->nplanes && !render_row_order(r, i, x0, x1, iy))
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
                const render_flat_t *f = render_face(o, k);
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
}

void render_row(render_t *r, int32_t row, uint8_t *rgb)
{
#if FXRT_MAX_SAMPLES > 1
    if (r->samples > 1) {
        render_sample_row(r, row, rgb, false);
        return;
    }
#endif
    render_row_vis(r, row, rgb);
#if FXRT_MAX_LIGHTS > 0
    if (render_tracks(r))
        render_shade_row(r, row, rgb);
#endif
}

/* ---- arbitrary rays ------------------------------------------------------ */

rgb8_t render_pixel(const world_t *w, const ray_t *ray)
{
    hit_t hit;
    if (!world_hit(w, ray, &hit))
        return w->background_rgb;
#if FXRT_MAX_LIGHTS > 0
    if (hit.obj->mat.kind != MATERIAL_FLAT)
        return color_to_rgb8(shade_object(w, hit.kind, hit.index, ray, NULL));
#endif
    return hit.obj->rgb;
}

