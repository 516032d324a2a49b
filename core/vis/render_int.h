/* render_int: what the visibility pass's files share (private to vis/;
 * the pass's own interface is vis/render.h): the number types of the
 * evaluation, 128-bit steps, sphere values and depths, the per-frame
 * set-up's entry points per kind, and the row loop's helpers. Which file
 * does what: docs/ARCHITECTURE.md. */
#ifndef FXRT_RENDER_INT_H
#define FXRT_RENDER_INT_H

#include <stddef.h>

#include "vis/render.h"

/* Set-up helpers that a build without some primitive kind does not call. */
#define RENDER_MAYBE_UNUSED __attribute__((unused))

/* Does the fast loop step forms along the row? Q16.16 always (exactly),
 * float and double with FXRT_FLOAT_STEP; never with FXRT_NO_STEP. */
#define RENDER_STEPPED (!FXRT_NO_STEP && (FXRT_NUMBER == FXRT_Q16 || FXRT_FLOAT_STEP))

/* Face i of a flat object (a box's faces carry a fourth edge). */
static inline render_flat_t *render_face(const render_obj_t *o, int i)
{
    return render_kind(o) == RENDER_FLAT ? o->u.flat : &o->u.face[i].f;
}

/* Edge form k of a flat piece; the fourth is a box face's. */
static inline const render_lin_t *render_edge_k(const render_flat_t *f, int k)
{
    return k < 3 ? &f->e[k] : &((const render_face_t *)(const void *)f)->e4;
}

#if RENDER_ESTEP
/* Edge k's row state (render_estep_t). */
static inline render_estep_t *render_estep_k(render_flat_t *f, int k) { return &f->es[k]; }
#endif

/* The shading pass (FXRT_MAX_LIGHTS > 0): the visibility pass records in
 * r->vis which object it painted last in each column when render_tracks
 * says so (some object is lit, or keys are wanted); render_shade_row then
 * shades those columns. */
#define RENDER_VIS_NONE 0xFFFFu
#if RENDER_VIS
static inline bool render_tracks(const vis_t *r) { return r->track || r->want_keys; }
/* Record object oi (RENDER_VIS_NONE: none) as column x's painter. */
static inline void render_mark(vis_t *r, int32_t x, uint16_t oi) { r->painted[x] = oi; }
/* Column x's painter so far on this row (RENDER_VIS_NONE: none). */
static inline uint16_t render_painter(const vis_t *r, int32_t x) { return r->painted[x]; }
/* Column x's model painter met triangle tri (vis/rays.c). */
FXRT_IF_MODEL(static inline void render_model_tri(vis_t *r, int32_t x, uint32_t tri) { r->model_tri[x] = tri; })
#else
static inline bool render_tracks(const vis_t *r)
{
    (void)r;
    return false;
}
static inline void render_mark(vis_t *r, int32_t x, uint16_t oi) { (void)r, (void)x, (void)oi; }
static inline uint16_t render_painter(const vis_t *r, int32_t x) { return (void)r, (void)x, RENDER_VIS_NONE; }
static inline void render_model_tri(vis_t *r, int32_t x, uint32_t tri) { (void)r, (void)x, (void)tri; }
#endif

/* The visibility pass alone (fast loop and reference loop): owners in
 * r->vis (when render_tracks), flat colours painted into rgb. */
void render_row_vis(vis_t *r, int32_t row, uint8_t *rgb);
void render_row_reference_vis(vis_t *r, int32_t row, uint8_t *rgb);
/* Start a row: a new owner stamp, vis cleared, the background painted. */
void render_begin_row(vis_t *r, uint8_t *rgb);

/* Fill pixels xa..xb of a row with colour c, in the pixel format. */
void render_fill_rgb(uint8_t *rgb, int32_t xa, int32_t xb, rgb8_t c);

/* Fine row `row` as runs of one owner each, when every object on it is
 * flat and alone on its row (render_row_vis would fill spans there): into
 * out[0 .. n-1], sorted, one object's runs merged; returns n, or -1 when
 * some object is lit or not alone, or there are more than cap runs. */
int render_row_runs(vis_t *r, int32_t row, render_run_t *out, int cap);
/* Per frame, sphere object i (index < FXRT_COHERENT_SPHERES): its row
 * series starts afresh (r->srow). */
void render_srow_setup(vis_t *r, uint16_t i);


static inline bool render_ortho(const cam_t *cam) { return cam->kind == CAM_ORTHOGRAPHIC; }

/* ---- the forms' numbers --------------------------------------------------
 * Evaluation: Q16.16 in uint64, so that no intermediate can be signed
 * overflow; every final value is known to fit int64 (the scales above
 * guarantee it). ix and iy are pixel offsets, below 2^15 (fxrt_config.h
 * bounds FXRT_MAX_DIM): small factors for fx_umul64_small. The quadratic
 * in Horner form, c + x (fx + fxx x + fxy y) + y (fy + fyy y): five such
 * products, the same value modulo 2^64. A sphere's c and disc (render_wide_t):
 * 128-bit in Q16.16, num otherwise. */
#if FXRT_NUMBER == FXRT_Q16
#if FX_HAVE_UMULL
#define RENDER_EVAL static inline
#else
/* On the M0 the products are a dozen instructions each: out of line, so
 * that the callers' frames (16 KB boards) do not grow with them. */
#define RENDER_EVAL RENDER_MAYBE_UNUSED __attribute__((noinline)) static
#endif
_Static_assert(offsetof(render_lin_t, x) == 8 && offsetof(render_lin_t, y) == 16, "render_lin_t: c, x, y in a row");
_Static_assert(offsetof(render_quad_t, xx) == 8 && offsetof(render_quad_t, xy) == 16, "render_quad_t: x, xx, xy first");
RENDER_EVAL render_k_t rlin_at(const render_lin_t *f, int32_t ix, int32_t iy)
{
    return (render_k_t)fx_lin2_small((const int64_t *)(const void *)f, ix, iy); /* c, x, y */
}
RENDER_EVAL render_k_t rquad_at(const render_quad_t *f, int32_t ix, int32_t iy)
{
    int64_t g[3]; /* c, gx, gy */
    g[0] = f->c;
    g[1] = (int64_t)fx_lin2_small((const int64_t *)(const void *)f, ix, iy); /* x, xx, xy */
    g[2] = (int64_t)((uint64_t)f->y + fx_umul64_small((uint64_t)f->yy, iy));
    return (render_k_t)fx_lin2_small(g, ix, iy);
}
/* a * m exactly (mod 2^128, so exact whenever the product fits). By
 * pointer, like render_quad_k's: the M0 passes a 16-byte value partly on
 * the stack, copied with memcpy. */
RENDER_MAYBE_UNUSED static fx128_t render_mul128_small(const fx128_t *a, int32_t m)
{
    uint32_t um = m < 0 ? 0u - (uint32_t)m : (uint32_t)m;
    /* Without UMULL, 32 x 32 -> 64-bit products by fx_umul32 (four 16-bit
     * multiplies), not 64 x 64 library calls; the top word's only mod 2^64. */
    uint64_t p0 = fx_umul32((uint32_t)a->lo, um), p1 = fx_umul32((uint32_t)(a->lo >> 32), um);
    uint64_t ph = FX_HAVE_UMULL ? (uint64_t)a->hi * um
                                : fx_umul32((uint32_t)(uint64_t)a->hi, um) +
                                      ((uint64_t)((uint32_t)((uint64_t)a->hi >> 32) * um) << 32);
    fx128_t r;
    r.lo = p0 + (p1 << 32);
    r.hi = (int64_t)(ph + (p1 >> 32) + (r.lo < p0 ? 1u : 0u));
    return m < 0 ? fx128_neg(r) : r;
}

/* q(k) = v + d1 k + d2 k (k - 1) / 2: the value the forward differences
 * reach after k steps, evaluated directly (exact). k is a column offset on
 * a row, |k| <= FXRT_MAX_DIM + 1 <= 2^14 + 1 (fxrt_config.h), so
 * k (k - 1) fits int32: no 64-bit product (a library call on the M0). */
RENDER_MAYBE_UNUSED static fx128_t render_quad_k(const fx128_t *v, const fx128_t *d1, const fx128_t *d2, int32_t k)
{
    return fx128_add(fx128_add(*v, render_mul128_small(d1, k)), render_mul128_small(d2, k * (k - 1) / 2));
}
typedef fx128_t render_wide_t;
static inline bool render_wide_neg(render_wide_t v) { return v.hi < 0; }

static inline void render_sphere_cd(const render_obj_t *o, int32_t ix, int32_t iy, render_wide_t *c_out, render_wide_t *disc_out)
{
    render_k_t a = rquad_at(o->u.sphere->a, ix, iy);
    render_k_t px = rlin_at(&o->u.sphere->px, ix, iy), py = rlin_at(&o->u.sphere->py, ix, iy),
         pz = rlin_at(&o->u.sphere->pz, ix, iy);
    bool ortho = o->u.sphere->ortho;
    fx128_t sq = fx128_add(fx128_add(fx128_sqr(px), fx128_sqr(py)), fx128_sqr(pz));
    /* Orthographic: a = 1 exactly and r2 may use all 128 bits. */
    fx128_t r2a = ortho ? o->u.sphere->r2 : fx128_mul(a, fx128_shr_round(o->u.sphere->r2, 0));
    *disc_out = fx128_sub(r2a, sq);
    if (ortho)
        *c_out = fx128_add(o->u.sphere->k, sq);
    else
        fx128_copy(c_out, &o->u.sphere->k);
}
/* A row's sphere cache (render_sphere_cache_t) with nothing in it. */
static inline void render_sphere_cache_reset(render_sphere_cache_t *sc)
{
    sc->oi = sc->disc_obj = RENDER_VIS_NONE;
#if RENDER_DIV_GUESS
    sc->span_obj = RENDER_VIS_NONE;
#endif
}
/* vis/depth.c: the depth n / d * 2^e from a numerator (n_hi:n_lo >= 0)
 * and a denominator d > 0, truncated to 24 bits each. */
render_depth_t render_depth_make(uint64_t n_hi, uint64_t n_lo, uint64_t d, int e);

#define RENDER_DEPTH_ONE (1u << 23)
#define RENDER_DEPTH_EMAX 126 /* exponents clamp to +-126 (t beyond 2^+-126) */

#define RENDER_DEPTH(n, d, e) ((uint64_t)(d) << 32 | (uint64_t)(uint8_t)(int8_t)(e) << 24 | (uint64_t)(n))
static inline uint32_t render_depth_n(render_depth_t t) { return (uint32_t)t & 0xffffffu; }
static inline int render_depth_e(render_depth_t t) { return (int8_t)(uint8_t)((uint32_t)t >> 24); }
static inline uint32_t render_depth_d(render_depth_t t) { return (uint32_t)(t >> 32); }

/* Strictly nearer. n / d lies in (1/2, 2), so exponents two apart decide
 * alone; otherwise 24 x 24-bit products (below 2^49 after one doubling). */
static inline __attribute__((always_inline)) bool render_depth_less(render_depth_t a, render_depth_t b)
{
    uint32_t an = render_depth_n(a), bn = render_depth_n(b);
    if (an == 0 || bn == 0)
        return an == 0 && bn != 0;
    int32_t de = (int32_t)render_depth_e(a) - (int32_t)render_depth_e(b);
    if (de >= 2)
        return false;
    if (de <= -2)
        return true;
    /* No 32 x 32 -> 64 multiply (Armv6-M): first the top 15 bits of each
     * factor, whose products fit 32 bits; they bound the exact products
     * (l / 2^18 in [l1, l2), g / 2^18 in [g1, g2)) and decide unless the
     * two intervals meet. */
    if (!FX_HAVE_UMULL) {
        uint32_t a9 = an >> 9, b9 = bn >> 9, ad9 = render_depth_d(a) >> 9, bd9 = render_depth_d(b) >> 9;
        uint32_t l1 = a9 * bd9, g1 = b9 * ad9, l2 = l1 + a9 + bd9 + 1, g2 = g1 + b9 + ad9 + 1; /* < 2^30 */
        if (de == 1) {
            l1 <<= 1;
            l2 <<= 1;
        } else if (de == -1) {
            g1 <<= 1;
            g2 <<= 1;
        }
        if (l2 <= g1)
            return true;
        if (l1 >= g2)
            return false;
    }
    uint64_t l = fx_umul32(an, render_depth_d(b)), g = fx_umul32(bn, render_depth_d(a));
    if (de == 1)
        l <<= 1;
    else if (de == -1)
        g <<= 1;
    return l < g;
}
/* A 32-bit key that grows with depth t = r 2^e (r = n / d in (1/2, 2)),
 * for ordering objects: 2^16 (e + r), r to about 15 bits (n / d with d's
 * top 16 bits). It grows with r within one e; where t grows from
 * (e - 1, r') to (e, r), r > r' / 2 > r' - 1 (r' < 2), so e + r >
 * e - 1 + r', and more so across larger steps of e. Depths closer than
 * about 2^-14 of each other may come out in either order. t = 0 sorts
 * first. */
static inline int32_t render_depth_key(render_depth_t t)
{
    uint32_t n = render_depth_n(t);
    if (n == 0)
        return INT32_MIN;
    uint32_t r = (n << 8) / (render_depth_d(t) >> 8); /* r 2^16, in (2^15, 2^17) */
    return render_depth_e(t) * (1 << 16) + (int32_t)r;
}
/* The depth n / f of a camera-space distance n (0 where n <= 0) and a
 * focal length f > 0. */
static inline render_depth_t render_depth_of(num_t n, num_t f)
{
    return render_depth_make(0, n > 0 ? (uint64_t)n : 0, (uint64_t)f, 0);
}
#else
static inline render_k_t rlin_at(const render_lin_t *f, int32_t ix, int32_t iy)
{
    return f->c + f->x * (num_t)ix + f->y * (num_t)iy;
}
static inline render_k_t rquad_at(const render_quad_t *f, int32_t ix, int32_t iy)
{
    num_t x = (num_t)ix, y = (num_t)iy;
    return f->c + f->x * x + f->y * y + f->xx * x * x + f->xy * x * y + f->yy * y * y;
}
typedef render_k_t render_wide_t;
static inline bool render_wide_neg(render_wide_t v) { return v < 0; }

static inline void render_sphere_cd(const render_obj_t *o, int32_t ix, int32_t iy, render_wide_t *c_out, render_wide_t *disc_out)
{
    render_k_t a = rquad_at(o->u.sphere->a, ix, iy);
    render_k_t px = rlin_at(&o->u.sphere->px, ix, iy), py = rlin_at(&o->u.sphere->py, ix, iy),
         pz = rlin_at(&o->u.sphere->pz, ix, iy);
    bool ortho = o->u.sphere->ortho;
    render_k_t sq = px * px + py * py + pz * pz;
    *disc_out = o->u.sphere->r2 * a - sq;
    *c_out = ortho ? o->u.sphere->k + sq : o->u.sphere->k;
}
static inline bool render_depth_less(render_depth_t a, render_depth_t b) { return a.t < b.t; }
static inline render_depth_t render_depth_of(num_t n, num_t f)
{
    render_depth_t t = {n > NUM_ZERO ? n / f : NUM_ZERO};
    return t;
}
/* (Float and double: num_order_key.) */
static inline int32_t render_depth_key(render_depth_t t)
{
    if (!(t.t > NUM_ZERO))
        return INT32_MIN;
    return num_order_key(t.t);
}
#endif



static inline bool render_sphere_vals(render_k_t b, render_wide_t c, render_wide_t disc)
{
    return render_wide_neg(c) || (b > 0 && !render_wide_neg(disc));
}

/* c = k + px^2 + py^2 and disc = b^2 - a c at one pixel, exactly (Q16.16:
 * a is 1 in orthographic views and c is the constant k in perspective, so
 * a c is a single 64 x 64 product or none). */

static inline bool render_flat_vals(render_k_t n, render_k_t d, const render_k_t *e, int edges)
{
    if (!((n > 0 && d > 0) || (n < 0 && d < 0)))
        return false;
    bool pos = false, neg = false;
    for (int i = 0; i < edges; i++) {
        pos |= e[i] > 0;
        neg |= e[i] < 0;
    }
    return !(pos && neg);
}

/* render_flat_vals' edge test at a pixel, each edge evaluated only while
 * the ones before leave it open (a face's box neighbours mostly fail at
 * the first or second). */
static inline bool render_edges_in(const render_flat_t *f, int32_t ix, int32_t iy)
{
    bool pos = false, neg = false;
    for (int i = 0; i < f->edges; i++) {
        render_k_t e = rlin_at(render_edge_k(f, i), ix, iy);
        pos |= e > 0;
        neg |= e < 0;
        if (pos && neg)
            return false;
    }
    return true;
}

static inline bool render_flat_at(const render_flat_t *f, int32_t ix, int32_t iy)
{
    render_k_t e[4];
    for (int i = 0; i < f->edges; i++)
        e[i] = rlin_at(render_edge_k(f, i), ix, iy);
    return render_flat_vals(rlin_at(&f->n, ix, iy), rlin_at(&f->d, ix, iy), e, f->edges);
}



/* The output row (0 = top) of the pixel-offset row iy (ray rows are
 * iy = 2 y - height + 1, y from the bottom). */
static inline int32_t render_row_of(const cam_t *cam, int32_t iy)
{
    return cam->height - 1 - (iy + cam->height - 1) / 2;
}

/* render_sphere_cd out of line for render_covers in Q16.16 (the reference
 * loop): inlined, it grows the loop's frame and slows every other kind's
 * pixels (the plane's reference rows by 12 % on the M4F). The float rows
 * keep it inline (out of line they take 9 % more on the M4F). */
__attribute__((noinline, unused)) static void render_sphere_cd_call(const render_obj_t *o, int32_t ix, int32_t iy,
                                                                  render_wide_t *c, render_wide_t *disc)
{
    render_sphere_cd(o, ix, iy, c, disc);
}

/* Does object o cover the pixel? Every form evaluated from scratch. */
static inline bool render_covers(const render_obj_t *o, int32_t ix, int32_t iy)
{
    switch (render_kind(o)) {
    case RENDER_INSIDE_BOX:
        return true;
    case RENDER_SPHERE: {
        render_k_t b = rlin_at(&o->u.sphere->b, ix, iy);
        render_wide_t c, disc;
        if (NUM_EXACT)
            render_sphere_cd_call(o, ix, iy, &c, &disc);
        else
            render_sphere_cd(o, ix, iy, &c, &disc);
        return render_sphere_vals(b, c, disc);
    }
    case RENDER_FLAT:
    case RENDER_BOX:
        for (int i = 0; i < o->nflat; i++)
            if (render_flat_at(render_face(o, i), ix, iy))
                return true;
        return false;
    }
    return false;
}

/* render_covers in a frame of its own, for the float rows' per-pixel loop
 * (vis/row.c): inlined there, it changes the float builds' instruction
 * counts by 6 % on the M4F (they are the comparison builds: kept as they
 * were measured). */
__attribute__((noinline, unused)) static bool render_covers_call(const render_obj_t *o, int32_t ix, int32_t iy)
{
    return render_covers(o, ix, iy);
}

/* Owner entries: stamp (15 bits) << 17 | depth-known bit << 16 | object. */
#define RENDER_DEPTH_KNOWN 0x10000u
#define RENDER_STAMP_SHIFT 17
#define RENDER_STAMP_LIMIT 0x8000u

/* vis/setup.c: (re)compute object i's forms and bounds. */
void render_setup_object(vis_t *r, uint16_t i);



/* vis/depth.c, for tests: object i's depth at pixel offsets (ix, iy),
 * which it covers. */
render_depth_t render_depth_test(const vis_t *r, uint16_t i, int32_t ix, int32_t iy);

/* vis/flat.c, for tests (Q16.16 with steps and spans): where a + b k (k = 0..kmax) is > 0 and < 0
 * (strict; else >= 0 and <= 0), as a flat piece's run search finds it:
 * the split *pr, *pl of render_split_two (guess NULL) or, in the coherent
 * loop, of render_split_near from the guess *guess. Returns true when the
 * form falls (> 0 on [0, *pl], < 0 on [*pr, kmax]; else the other way). */
bool render_split_test(int64_t a, int64_t b, int32_t kmax, int16_t *guess, bool strict, int32_t *pr, int32_t *pl);
/* vis/flat.c, for tests (RENDER_ESTEP): render_split_edge, edge form ek's split (not
 * strict, as render_split_test's) on columns x0..x0 + kmax of row iy (ix0:
 * column x0's pixel offset), from and into its row state *st. */
bool render_split_edge_test(render_estep_t *st, const render_lin_t *ek, int32_t x0, int32_t ix0, int32_t iy,
                            int32_t kmax, int32_t *pr, int32_t *pl);

/* vis/depth.c, for tests: is object i's depth at pixel offsets (ix, iy),
 * which it covers (render_covers), inside its range (or has it none)? */
bool render_range_check(const vis_t *r, uint16_t i, int32_t ix, int32_t iy);

/* vis/depth.c: object oi also covers column x, owned so far by the owner
 * entry cur; returns true when oi is nearer (or ties with a lower id) and
 * has taken the column. The newcomer's depth comes from its forms at the
 * pixel (render_resolve) or from values the scanline stepped. */
bool render_resolve(vis_t *r, uint32_t cur, uint16_t oi, int32_t x, int32_t iy);
/* The same with values the stepped loop has (RENDER_STEPPED). */
bool render_resolve_flat(vis_t *r, uint32_t cur, uint16_t oi, int32_t x, int32_t iy, const render_flat_t *f,
                         render_k_t n, render_k_t d);
/* A box, found covering the pixel by its face f, with f's N and D there. */
bool render_resolve_box(vis_t *r, uint32_t cur, uint16_t oi, int32_t x, int32_t iy, const render_flat_t *f,
                        render_k_t n, render_k_t d);
bool render_resolve_sphere(vis_t *r, uint32_t cur, uint16_t oi, int32_t x, int32_t iy, render_k_t b, const render_wide_t *c,
                           const render_wide_t *disc);
/* An object of the RAYS form, whose depth t at the pixel its ray gave
 * (vis/rays.c). */
bool render_resolve_depth(vis_t *r, uint32_t cur, uint16_t oi, int32_t x, int32_t iy, render_depth_t t);

/* vis/rays.c (RENDER_RAY_KINDS): object oi's scan over columns x0..x1
 * of row iy, a ray per column; where a model paints a column, the
 * triangle its ray met goes to r->model_tri for the shading pass.
 * vis/depth.c: its depth at pixel offsets (ix, iy) into *t and a model's
 * triangle met into *tri (when not NULL; BVH_NONE for other kinds), or
 * false where its ray misses. */
void render_scan_rays(vis_t *r, uint16_t oi, int32_t x0, int32_t x1, int32_t iy, uint8_t *rgb, bool lone);
bool render_rays_at(const vis_t *r, uint16_t oi, int32_t ix, int32_t iy, render_depth_t *t, uint32_t *tri);

/* vis/depth.c (Q16.16 with steps and spans): bounds lo, hi on object oi's depth at every column p..q of
 * row iy, all of which it covers (planes, triangles, boxes, spheres with
 * row forms): 1 both bounds, 2 (a sphere) only hi, with lo its smaller
 * end (its bound below, from low, lies lower), 0 none; with low, a
 * sphere's bound below alone, into lo (1) or none (0). */
int render_span_range(const vis_t *r, uint16_t oi, int32_t p, int32_t q, int32_t iy, render_depth_t *lo,
                      render_depth_t *hi, bool low);

/* The first planes' depth ranges over the whole of the current row, each
 * worked out once, when render_row_order first needs it (render_row_vis
 * keeps them on its stack and clears state at each row). */
#define RENDER_ROW_PLANES 4
typedef struct {
    render_depth_t lo[RENDER_ROW_PLANES], hi[RENDER_ROW_PLANES];
    uint8_t state[RENDER_ROW_PLANES]; /* 0: not yet; 1: lo, hi hold; 2: the plane does not cover the row with one sign */
} render_prow_t;

/* vis/depth.c: object i's depth order against the planes on row iy over
 * columns x0..x1 (sets r->row_win); false when a plane hides it there. */
bool render_row_order(vis_t *r, uint16_t i, int32_t x0, int32_t x1, int32_t iy, render_prow_t *pr);

#endif
