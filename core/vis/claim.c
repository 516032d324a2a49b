/* claim: a run of columns of one object among the row's other objects:
 * free columns taken at once, stretches of one other owner settled by the
 * two objects' depth ranges, other columns each by its depths
 * (vis/depth.c). */
#include "vis/scan.h"

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

/* Columns of one other owner, this many or more in a row, are settled by
 * the two objects' depth ranges over stretches of them (render_claim_span),
 * which stop halving below RENDER_SPAN_LEAF columns (docs/BENCHMARKS.md
 * has the measurements that chose them). */
#define RENDER_SPAN_MIN 6
#define RENDER_SPAN_LEAF (2 * RENDER_SPAN_MIN)
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
void render_claim_run(vis_t *r, uint16_t oi, const render_flat_t *f, int32_t a, int32_t b, int32_t iy,
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
