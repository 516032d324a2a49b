/* (Over 700 lines: the depth functions inline into the depth-range tests; apart, +0.6 % instructions.) */
/* depth: a covered pixel's depth from an object's forms; the nearest owner
 * of a column where two objects cover it (render_resolve: the depth
 * ranges first, the depths where they do not decide); bounds on an
 * object's depth over a stretch of a row, and its order against the
 * planes on a row. See docs/ARCHITECTURE.md for the rule.
 * (One unit of about 700 lines: the depth functions are inlined into the
 * range tests; apart, they cost 0.6 % more instructions on the bench set.) */
#include "vis/render_int.h"

/* ---- depth at pixels that several objects cover ------------------------
 * Depth is the ray parameter t of the camera-space ray r = (ix, iy, -F)
 * (orthographic: (0, 0, -1)), formed from the same forms that decide
 * coverage: a flat piece's t = N / D, a sphere's near root c / (b + s)
 * (s = sqrt(disc); the far root (b + s) / a from inside), so no ray is cast.
 * Q16.16: t is kept as n / d * 2^e with n and d normalised to 31 bits
 * (truncated: a deterministic function of the exact integer forms), and
 * two depths compare exactly by cross-multiplication in 64 bits. */

#if FXRT_NUMBER == FXRT_Q16
/* The top 24 bits of v > 0 (v < 2^128), their exponent added to *e. */
static uint32_t render_top24(uint64_t hi, uint64_t lo, int *e)
{
    int b = hi ? 128 - __builtin_clzll(hi) : (lo ? 64 - __builtin_clzll(lo) : 0);
    if (b == 0)
        return 0;
    *e += b - 24;
    if (b <= 24)
        return (uint32_t)(lo << (24 - b));
    int s = b - 24; /* truncating right shift by s (1..104) */
    if (s >= 64)
        return (uint32_t)(hi >> (s - 64));
    return (uint32_t)((lo >> s) | (hi << 1 << (63 - s)));
}

/* render_top24 of a 64-bit v, in 32-bit halves (most depths: a flat
 * piece's N and D, every denominator). */
static inline uint32_t render_top24_64(uint64_t v, int *e)
{
    uint32_t h = (uint32_t)(v >> 32), l = (uint32_t)v;
    int s; /* bits(v) - 24 */
    if (h) {
        s = 40 - __builtin_clz(h); /* 9..40 */
        *e += s;
        return s >= 32 ? h >> (s - 32) : l >> s | h << (32 - s);
    }
    if (!l)
        return 0;
    s = 8 - __builtin_clz(l); /* -23..8 */
    *e += s;
    return s >= 0 ? l >> s : l << -s;
}

static render_depth_t render_depth_pack(uint32_t n, uint32_t d, int e)
{
    e = e > RENDER_DEPTH_EMAX ? RENDER_DEPTH_EMAX : (e < -RENDER_DEPTH_EMAX ? -RENDER_DEPTH_EMAX : e);
    return RENDER_DEPTH(n, d, e);
}

/* t = n / d * 2^e for n >= 0 and d > 0 (d = 0 cannot occur at a covered
 * pixel; it would give the far depth), n's top 24 bits tn (exponent en)
 * already taken. */
static inline render_depth_t render_depth_over(uint32_t tn, int en, uint64_t d, int e)
{
    int ed = 0;
    uint32_t td = render_top24_64(d, &ed);
    if (td == 0)
        return render_depth_pack(RENDER_DEPTH_ONE, RENDER_DEPTH_ONE, RENDER_DEPTH_EMAX);
    if (tn == 0)
        return render_depth_pack(0, RENDER_DEPTH_ONE, 0);
    return render_depth_pack(tn, td, e + en - ed);
}

/* n below 2^64: inline for the flat pieces' depths. */
static inline render_depth_t render_depth_make64(uint64_t n, uint64_t d, int e)
{
    int en = 0;
    uint32_t tn = render_top24_64(n, &en);
    return render_depth_over(tn, en, d, e);
}

/* n = n_hi 2^64 + n_lo (a sphere's c). */
render_depth_t render_depth_make(uint64_t n_hi, uint64_t n_lo, uint64_t d, int e)
{
    int en = 0;
    uint32_t tn = n_hi ? render_top24(n_hi, n_lo, &en) : render_top24_64(n_lo, &en);
    return render_depth_over(tn, en, d, e);
}

static const render_depth_t render_depth_far = RENDER_DEPTH(RENDER_DEPTH_ONE, RENDER_DEPTH_ONE, RENDER_DEPTH_EMAX);

static uint64_t render_uabs(render_k_t v) { return v < 0 ? 0 - (uint64_t)v : (uint64_t)v; }

static render_depth_t render_flat_depth(const render_flat_t *f, render_k_t n, render_k_t d)
{
    return render_depth_make64(render_uabs(n), render_uabs(d), f->te);
}

/* floor(sqrt(v)) to about 32 significant bits, v >= 0 (v < 2^127). By
 * pointer, its halves read as integers, and its bit length (fx128_bits')
 * inline: the M0 copies a 16-byte value passed by value with memcpy. */
static uint64_t render_sqrt128(const fx128_t *vp)
{
    int64_t hi = vp->hi;
    uint64_t lo = vp->lo;
    if (hi < 0)
        return 0;
    int b = hi ? 128 - __builtin_clzll((uint64_t)hi) : (lo ? 64 - __builtin_clzll(lo) : 0);
    if (b <= 64)
        return fx_isqrt64(lo);
    int s = (b - 63) & ~1; /* even */
    s = s < b - 64 ? s + 2 : s;
    uint64_t top = s >= 64 ? (uint64_t)hi >> (s - 64) : (lo >> s) | ((uint64_t)hi << (64 - s));
    return (uint64_t)fx_isqrt64(top) << (s / 2);
}

/* c and disc by pointer: the M0 copies a 16-byte value with memcpy. */
static render_depth_t render_sphere_depth(const render_obj_t *o, int32_t ix, int32_t iy, render_k_t b, const render_wide_t *c,
                                          const render_wide_t *disc)
{
    uint64_t s = render_sqrt128(disc);
    if (!render_wide_neg(*c)) /* outside: the near root, b > 0 */
        return render_depth_make((uint64_t)c->hi, c->lo, (uint64_t)b + s, o->u.sphere->tc);
    if (b < 0) { /* inside, looking away from the centre: (-c) / (s - b) */
        fx128_t nc = fx128_neg(*c);
        return render_depth_make((uint64_t)nc.hi, nc.lo, s + (0 - (uint64_t)b), o->u.sphere->tc);
    }
    render_k_t a = o->u.sphere->ortho ? 1 : rquad_at(o->u.sphere->a, ix, iy);
    return render_depth_make(0, (uint64_t)b + s, (uint64_t)a, o->u.sphere->ta);
}

/* Sphere oi's forms on row iy where the row has them (r->sphere_cache: the
 * sphere scanned last among others; r->srow: its row state), with the
 * pixel offset *ix0 of their column k = 0; NULL when it has none, or they
 * are not the perspective disc from outside. */
static const render_srow_t *render_sphere_rowforms(const vis_t *r, uint16_t oi, int32_t iy, int32_t *ix0)
{
    const render_sphere_cache_t *sc = r->sphere_cache;
    const render_srow_t *q = NULL;
    if (!sc)
        return NULL;
    if (sc->oi == oi && sc->iy == iy) {
        q = &sc->s;
        *ix0 = sc->ix0;
    }
#if RENDER_SROWS
    const render_obj_t *o = &r->obj[oi];
    if (!q && o->index < FXRT_COHERENT_SPHERES && r->cam->height >= 3 &&
        r->srow[o->index].vrow == render_row_of(r->cam, iy)) {
        q = &r->srow[o->index].cur;
        *ix0 = 2 * o->x0 - r->cam->width + 1;
    }
#endif
    return q && !q->ortho && !q->inside ? q : NULL;
}

/* A sphere's disc at a pixel from its forms on this row, when it has them
 * (perspective; c is then the constant k): from r->sphere_cache (the sphere
 * scanned last among others on this row) or, with row state, from its
 * own (it was scanned on this row, as it covers the pixel). Owners are
 * asked about column after column, so the last column's value and step
 * give the next by two additions. False: no row forms. */
__attribute__((noinline)) static bool render_sphere_disc_row(const vis_t *r, uint16_t oi, int32_t ix, int32_t iy,
                                                             render_wide_t *disc)
{
    render_sphere_cache_t *sc = r->sphere_cache;
    int32_t ix0 = 0;
    const render_srow_t *q = render_sphere_rowforms(r, oi, iy, &ix0);
    if (!q)
        return false;
    int32_t k = (ix - ix0) / 2;
    if (sc->disc_obj == oi && k == sc->disc_k + 1) {
        if (!sc->disc_stepped) /* the step at lk, once a second column follows */
            sc->disc_step = fx128_add(q->d1, render_mul128_small(&q->d2, sc->disc_k));
        sc->disc = fx128_add(sc->disc, sc->disc_step);
        sc->disc_step = fx128_add(sc->disc_step, q->d2);
        sc->disc_stepped = true;
    } else if (!(sc->disc_obj == oi && k == sc->disc_k)) {
        sc->disc = render_quad_k(&q->v, &q->d1, &q->d2, k);
        sc->disc_obj = oi;
        sc->disc_stepped = false;
    }
    sc->disc_k = k;
    disc->lo = sc->disc.lo; /* (halves: a struct copy is a memcpy call on the M0) */
    disc->hi = sc->disc.hi;
    return true;
}

/* t scaled by about (1 + 2^-16) (up) or (1 - 2^-16): a margin for the
 * 24-bit truncation of depths between the ends of a segment. */
static render_depth_t render_depth_widen(render_depth_t t, bool up)
{
    uint32_t n = render_depth_n(t);
    int e = render_depth_e(t);
    if (n == 0)
        return t;
    if (up) {
        n += (n >> 16) + 1;
        if (n >= 2 * RENDER_DEPTH_ONE) {
            n >>= 1;
            e++;
        }
    } else {
        n -= (n >> 16) + 1;
        if (n < RENDER_DEPTH_ONE) {
            n <<= 1;
            e--;
        }
    }
    return render_depth_pack(n, render_depth_d(t), e);
}

/* Linear form f at pixel offsets (ixb, iy), given its value va 2 dk
 * columns before: Q16.16 by one product (2 dk < 2 FXRT_MAX_DIM is a
 * small factor: the same value), float and double afresh. */
static inline render_k_t render_lin_from(const render_lin_t *f, render_k_t va, int32_t dk, int32_t ixb, int32_t iy)
{
    (void)ixb, (void)iy;
    return (render_k_t)((uint64_t)va + fx_umul64_small((uint64_t)f->x, 2 * dk));
}
#else
static bool render_sphere_disc_row(const vis_t *r, uint16_t oi, int32_t ix, int32_t iy, render_wide_t *disc)
{
    (void)r, (void)oi, (void)ix, (void)iy, (void)disc;
    return false; /* (Q16.16 alone keeps row forms) */
}
static render_depth_t render_depth_widen(render_depth_t t, bool up)
{
    t.t = up ? t.t * NUM(1.0001) : t.t * NUM(0.9999);
    return t;
}
static inline render_k_t render_lin_from(const render_lin_t *f, render_k_t va, int32_t dk, int32_t ixb, int32_t iy)
{
    (void)va, (void)dk;
    return rlin_at(f, ixb, iy);
}
static const render_depth_t render_depth_far = {NUM_MAX};
static render_depth_t render_flat_depth(const render_flat_t *f, render_k_t n, render_k_t d)
{
    (void)f;
    render_depth_t t = {num_div(n, d)};
    return t;
}
static render_depth_t render_sphere_depth(const render_obj_t *o, int32_t ix, int32_t iy, render_k_t b, const render_wide_t *cp,
                                          const render_wide_t *discp)
{
    render_wide_t c = *cp;
    num_t s = num_sqrt(*discp);
    render_depth_t t;
    if (!(c < 0))
        t.t = num_div(c, b + s);
    else if (b < 0)
        t.t = num_div(-c, s - b);
    else
        t.t = num_div(b + s, o->u.sphere->ortho ? NUM_ONE : rquad_at(o->u.sphere->a, ix, iy));
    return t;
}
#endif

/* Depth of box (or RENDER_INSIDE_BOX) o at a pixel it covers: the nearest of
 * its faces that cover it. known: a face known to cover it, with its N
 * and D there (NULL: none). A face's pixel rectangle rules most faces out
 * at once; since the box covers the pixel, when neither known nor an
 * earlier candidate face does, the last candidate must: its coverage is
 * not tested (a RENDER_INSIDE_BOX box's always is). */
#define RENDER_BOX_SIDES 6 /* faces a box can have set up */
__attribute__((noinline)) static render_depth_t render_box_depth(const vis_t *r, const render_obj_t *o, int32_t ix,
                                                                 int32_t iy, const render_flat_t *known, render_k_t kn,
                                                                 render_k_t kd)
{
    int32_t x = (ix + r->cam->width - 1) / 2, row = render_row_of(r->cam, iy);
    const render_face_t *cand[RENDER_BOX_SIDES];
    int nc = 0;
    for (int i = 0; i < o->nflat && nc < RENDER_BOX_SIDES; i++) {
        const render_face_t *fc = &o->u.face[i];
        if (&fc->f != known && x >= fc->x0 && x <= fc->x1 && row >= fc->r0 && row <= fc->r1)
            cand[nc++] = fc;
    }
    render_depth_t best = known ? render_flat_depth(known, kn, kd) : render_depth_far;
    bool any = known != NULL;
    for (int k = 0; k < nc; k++) {
        const render_flat_t *f = &cand[k]->f;
        bool test = any || k < nc - 1 || render_kind(o) == RENDER_INSIDE_BOX;
        if (test && !render_edges_in(f, ix, iy))
            continue;
        render_k_t n = rlin_at(&f->n, ix, iy), d = rlin_at(&f->d, ix, iy);
        if (test && !((n > 0 && d > 0) || (n < 0 && d < 0)))
            continue;
        any = true;
        render_depth_t t = render_flat_depth(f, n, d);
        if (render_depth_less(t, best))
            best = t;
    }
    return best;
}

/* render_sphere_cd in a frame of its own. */
__attribute__((noinline)) static void render_sphere_cd_full(const render_obj_t *o, int32_t ix, int32_t iy, render_wide_t *c,
                                                            render_wide_t *disc)
{
    render_sphere_cd(o, ix, iy, c, disc);
}


/* A sphere's depth at a pixel it covers. Its 128-bit forms in frames of
 * their own, one after the other: off the stack of the other kinds'
 * paths, and not on top of each other (the micro:bit's stack). */
__attribute__((noinline)) static render_depth_t render_sphere_depth_at(const vis_t *r, uint16_t oi, int32_t ix,
                                                                       int32_t iy)
{
    const render_obj_t *o = &r->obj[oi];
    render_wide_t c, disc;
    const render_wide_t *cp = &c;
    if (render_sphere_disc_row(r, oi, ix, iy, &disc))
        cp = &o->u.sphere->k;
    else
        render_sphere_cd_full(o, ix, iy, &c, &disc);
    return render_sphere_depth(o, ix, iy, rlin_at(&o->u.sphere->b, ix, iy), cp, &disc);
}

/* The depth of an object of the RAYS form at pixel offsets (ix, iy): its
 * camera ray (cam_ray, the ray the shading pass casts too) meets it (a
 * model's through the mesh's tree, scene/bvh.c; another kind's by its
 * geom_K_hit); false where it misses. The depth is the camera-space ray
 * parameter -z / f of the hit point, in which every other object's depth
 * is compared. */
#if RENDER_RAY_KINDS
bool render_rays_at(const vis_t *r, uint16_t oi, int32_t ix, int32_t iy, render_depth_t *t, uint32_t *tri)
{
    const cam_t *cam = r->cam;
    const world_t *w = r->world;
    const render_obj_t *o = &r->obj[oi];
    ray_t ray;
    num_t th = NUM_ZERO;
    uint32_t met = BVH_NONE;
    bool hit = false;
    cam_ray(cam, (ix + cam->width - 1) / 2, (iy + cam->height - 1) / 2, &ray);
    /* A model's hit also gives the triangle met; other kinds' by the table. */
    FXRT_IF_MODEL(if (o->geom == GEOM_MODEL) hit = geom_model_hit_from(&w->models[o->index], &ray, BVH_NONE, &th, &met);
                  else)
    switch (o->geom) {
#define RENDER_RAYS_HIT(K, k, ks, cap, solid, bounded, form, ...) RENDER_RAYS_HIT_##form(K, k, ks)
#define RENDER_RAYS_HIT_FLAT(K, k, ks)
#define RENDER_RAYS_HIT_ROUND(K, k, ks)
#define RENDER_RAYS_HIT_FACES(K, k, ks)
#define RENDER_RAYS_HIT_RAYS(K, k, ks) FXRT_IF_##K(case GEOM_##K: hit = geom_##k##_hit(&w->ks[o->index], &ray, &th); break;)
        FXRT_KINDS(RENDER_RAYS_HIT)
#undef RENDER_RAYS_HIT
    default:
        break;
    }
    if (!hit)
        return false;
    num_t z = vec3_dot(vec3_sub(ray_at(&ray, th), cam->e), cam->w);
    *t = render_depth_of(num_neg(z), render_ortho(cam) ? NUM_ONE : cam->focal);
    if (tri)
        *tri = met;
    return true;
}
#endif

/* Depth of object oi at a pixel it covers, from its forms evaluated there
 * (a sphere's from its row forms where it has them: the same value). */
static render_depth_t render_depth_at(const vis_t *r, uint16_t oi, int32_t ix, int32_t iy)
{
    const render_obj_t *o = &r->obj[oi];
    if (render_kind(o) == RENDER_SPHERE)
        return render_sphere_depth_at(r, oi, ix, iy);
#if RENDER_RAY_KINDS
    render_depth_t t;
    if (render_kind(o) == RENDER_RAYS) /* (the callers ask about a pixel it covers) */
        return render_rays_at(r, oi, ix, iy, &t, NULL) ? t : o->thi;
#endif
    /* A plane or triangle covers the pixel (every caller asks about an
     * object there); a box: the nearest face that covers it. */
    if (render_kind(o) == RENDER_FLAT) {
        const render_flat_t *f = render_face(o, 0);
        return render_flat_depth(f, rlin_at(&f->n, ix, iy), rlin_at(&f->d, ix, iy));
    }
    return render_box_depth(r, o, ix, iy, NULL, 0, 0);
}


/* Test hook: object i's depth at pixel offsets (ix, iy), which it covers. */
render_depth_t render_depth_test(const vis_t *r, uint16_t i, int32_t ix, int32_t iy)
{
    return render_depth_at(r, i, ix, iy);
}

/* Test hook: is object i's depth at pixel offsets (ix, iy), which it
 * covers, inside its depth range [tlo, thi]? (A depth outside would let
 * render_settle decide an overlap wrongly.) */
bool render_range_check(const vis_t *r, uint16_t i, int32_t ix, int32_t iy)
{
    const render_obj_t *o = &r->obj[i];
    render_depth_t t = render_depth_at(r, i, ix, iy);
    return !o->ranged || (!render_depth_less(t, o->tlo) && !render_depth_less(o->thi, t));
}

/* How to get a newcomer's depth when it is needed: from the values the
 * scanline loop stepped (a flat piece's N and D, a sphere's b, c, disc) or
 * from its forms evaluated at the pixel. */
typedef struct {
    enum { RENDER_RAW_AT, RENDER_RAW_FLAT, RENDER_RAW_BOX, RENDER_RAW_SPHERE, RENDER_RAW_KNOWN } how;
    const render_flat_t *f;
    render_k_t n, d, b;
    const render_wide_t *c, *disc;
    FXRT_IF_MODEL(render_depth_t t;) /* RENDER_RAW_KNOWN: a model's, from its ray */
} render_raw_t;

static render_depth_t render_raw_depth(const vis_t *r, uint16_t oi, int32_t ix, int32_t iy, const render_raw_t *raw)
{
    if (RENDER_STEPPED && raw->how == RENDER_RAW_FLAT)
        return render_flat_depth(raw->f, raw->n, raw->d);
    if (RENDER_STEPPED && raw->how == RENDER_RAW_BOX)
        return render_box_depth(r, &r->obj[oi], ix, iy, raw->f, raw->n, raw->d);
    if (RENDER_STEPPED && raw->how == RENDER_RAW_SPHERE)
        return render_sphere_depth(&r->obj[oi], ix, iy, raw->b, raw->c, raw->disc);
    FXRT_IF_MODEL(if (raw->how == RENDER_RAW_KNOWN) return raw->t;)
    return render_depth_at(r, oi, ix, iy);
}

/* The depth ranges' part of render_settle, which the render_resolve
 * functions try first, ahead of render_settle's set-up: object oi also
 * covers column x, owned by the entry cur. Returns 1 when oi's range lies
 * wholly in front of the owner's (range, or depth when it is known) and
 * oi has taken the column, 0 when wholly behind, -1 when the ranges do
 * not decide. Inline in each of them; on Armv6-M a frame of its own, gone
 * before render_settle's (their frames with it inline would stack under
 * it: the micro:bit's 2 KB stack). */
static FXRT_INLINE_WIDE int render_settle_quick(vis_t *r, uint32_t cur, uint16_t oi, int32_t x)
{
    const render_obj_t *a = &r->obj[(uint16_t)cur], *b = &r->obj[oi];
    if (FXRT_NO_ZRANGE || !b->ranged)
        return -1;
    render_depth_t alo, ahi;
    if (cur & RENDER_DEPTH_KNOWN)
        alo = ahi = r->depth[x];
    else if (a->ranged)
        alo = a->tlo, ahi = a->thi;
    else
        return -1;
    if (render_depth_less(ahi, b->tlo))
        return 0;
    if (render_depth_less(b->thi, alo)) {
        r->owner[x] = (cur & ~0x1FFFFu) | oi;
        return 1;
    }
    return -1;
}

/* Object oi also covers column x, owned so far by the entry cur: the
 * nearer keeps it (ties: lower scene id). A depth, once computed, is kept
 * next to the owner. Depths are only computed when the objects' depth
 * ranges (render_setup: from their camera-space z, with a margin) do not
 * already decide; render_settle_quick has already tried the ranges
 * against the owner's range or known depth. Returns true when oi wins. */
static __attribute__((noinline)) bool render_settle(vis_t *r, uint32_t cur, uint16_t oi, int32_t x, int32_t iy,
                                                    const render_raw_t *raw)
{
    uint16_t ci = (uint16_t)cur;
    const render_obj_t *a = &r->obj[ci], *b = &r->obj[oi];
    int32_t ix = 2 * x - r->cam->width + 1;
    uint32_t stamp = cur & ~0x1FFFFu;
    bool known = (cur & RENDER_DEPTH_KNOWN) != 0;
    render_depth_t ta, tb;
    if (known || FXRT_NO_ZRANGE || !a->ranged) {
        ta = known ? r->depth[x] : render_depth_at(r, ci, ix, iy);
        if (!FXRT_NO_ZRANGE && !known && b->ranged) { /* (known: render_settle_quick has compared) */
            if (render_depth_less(ta, b->tlo)) {
                r->depth[x] = ta;
                r->owner[x] = stamp | RENDER_DEPTH_KNOWN | ci;
                return false;
            }
            if (render_depth_less(b->thi, ta)) {
                r->owner[x] = stamp | oi;
                return true;
            }
        }
        tb = render_raw_depth(r, oi, ix, iy, raw);
    } else {
        tb = render_raw_depth(r, oi, ix, iy, raw);
        if (render_depth_less(a->thi, tb))
            return false;
        if (render_depth_less(tb, a->tlo)) {
            r->depth[x] = tb;
            r->owner[x] = stamp | RENDER_DEPTH_KNOWN | oi;
            return true;
        }
        ta = render_depth_at(r, ci, ix, iy);
    }
    bool win = render_depth_less(tb, ta) || (!render_depth_less(ta, tb) && b->id < a->id);
    r->depth[x] = win ? tb : ta;
    r->owner[x] = stamp | RENDER_DEPTH_KNOWN | (win ? oi : ci);
    return win;
}

/* The newcomer's depth from its forms evaluated at the pixel. */
bool render_resolve(vis_t *r, uint32_t cur, uint16_t oi, int32_t x, int32_t iy)
{
    int q = render_settle_quick(r, cur, oi, x);
    if (q >= 0)
        return q != 0;
    render_raw_t raw;
    raw.how = RENDER_RAW_AT;
    return render_settle(r, cur, oi, x, iy, &raw);
}

bool render_resolve_depth(vis_t *r, uint32_t cur, uint16_t oi, int32_t x, int32_t iy, render_depth_t t)
{
    int q = render_settle_quick(r, cur, oi, x);
    if (q >= 0)
        return q != 0;
    render_raw_t raw;
    raw.how = RENDER_RAW_KNOWN;
    FXRT_IF_MODEL(raw.t = t;)
    (void)t;
    return render_settle(r, cur, oi, x, iy, &raw);
}

#if RENDER_STEPPED
/* The newcomer's depth from the values the scanline loop stepped: a flat
 * piece's N and D (its own piece, or the face f of a box). */
static inline __attribute__((always_inline)) bool render_resolve_nd(vis_t *r, uint32_t cur, uint16_t oi, int32_t x,
                                                                    int32_t iy, const render_flat_t *f, render_k_t n,
                                                                    render_k_t d, bool box)
{
    int q = render_settle_quick(r, cur, oi, x);
    if (q >= 0)
        return q != 0;
    render_raw_t raw;
    raw.how = box ? RENDER_RAW_BOX : RENDER_RAW_FLAT;
    raw.f = f;
    raw.n = n;
    raw.d = d;
    return render_settle(r, cur, oi, x, iy, &raw);
}
bool render_resolve_flat(vis_t *r, uint32_t cur, uint16_t oi, int32_t x, int32_t iy, const render_flat_t *f,
                         render_k_t n, render_k_t d)
{
    return render_resolve_nd(r, cur, oi, x, iy, f, n, d, false);
}
bool render_resolve_box(vis_t *r, uint32_t cur, uint16_t oi, int32_t x, int32_t iy, const render_flat_t *f,
                        render_k_t n, render_k_t d)
{
    return render_resolve_nd(r, cur, oi, x, iy, f, n, d, true);
}
bool render_resolve_sphere(vis_t *r, uint32_t cur, uint16_t oi, int32_t x, int32_t iy, render_k_t b, const render_wide_t *c,
                           const render_wide_t *disc)
{
    int q = render_settle_quick(r, cur, oi, x);
    if (q >= 0)
        return q != 0;
    render_raw_t raw;
    raw.how = RENDER_RAW_SPHERE;
    raw.b = b;
    raw.c = c; /* pointers: valid for the call */
    raw.disc = disc;
    return render_settle(r, cur, oi, x, iy, &raw);
}
#endif


/* Depth range of flat piece f over columns x0..x1 of row iy: 1 when it
 * is in front at both ends (N and D of one strict sign), so all along
 * (both are linear), where t = N / D is monotone; 0 when it is behind at
 * both ends (opposite strict signs, so all along); -1 otherwise. */
static int render_flat_range(const vis_t *r, const render_flat_t *f, int32_t x0, int32_t x1, int32_t iy,
                             render_depth_t *lo, render_depth_t *hi)
{
    int32_t w = r->cam->width;
    render_k_t na = rlin_at(&f->n, 2 * x0 - w + 1, iy), da = rlin_at(&f->d, 2 * x0 - w + 1, iy);
    /* The far end from the near one (render_lin_from). */
    render_k_t nb = render_lin_from(&f->n, na, x1 - x0, 2 * x1 - w + 1, iy);
    render_k_t db = render_lin_from(&f->d, da, x1 - x0, 2 * x1 - w + 1, iy);
    if (!((na > 0 && da > 0 && nb > 0 && db > 0) || (na < 0 && da < 0 && nb < 0 && db < 0)))
        return (na > 0 && da < 0 && nb > 0 && db < 0) || (na < 0 && da > 0 && nb < 0 && db > 0) ? 0 : -1;
    render_depth_t ta = render_flat_depth(f, na, da), tb = render_flat_depth(f, nb, db);
    bool a_first = render_depth_less(ta, tb);
    *lo = render_depth_widen(a_first ? ta : tb, false);
    *hi = render_depth_widen(a_first ? tb : ta, true);
    return 1;
}

/* Depth range of plane p over columns x0..x1 of row iy when it covers both
 * ends with one sign of N and D: then it covers the whole segment and its
 * t = N / D is monotone there. */
static bool render_plane_range(const vis_t *r, const render_obj_t *p, int32_t x0, int32_t x1, int32_t iy,
                               render_depth_t *lo, render_depth_t *hi)
{
    return render_flat_range(r, render_face(p, 0), x0, x1, iy, lo, hi) == 1;
}

#if FXRT_NUMBER == FXRT_Q16 && RENDER_STEPPED && !FXRT_NO_SPANS
/* Sphere sp's near root k / g, in perspective (c is the constant k). */
static render_depth_t render_sphere_near(const render_sphere_t *sp, uint64_t g)
{
    return render_depth_make((uint64_t)sp->k.hi, sp->k.lo, g, sp->tc);
}

/* Depth range of sphere oi over columns p..q of row iy, all of which it
 * covers, from its row forms (perspective, eye outside, disc concave
 * along the row). There t = k / g with g = b + sqrt(disc) concave (b
 * linear, disc concave): t is largest at an end (!low: *hi, and *lo the
 * smaller end, returning 2: not a bound), and smallest where g is, which
 * is at most max(b) + sqrt of a bound on disc (low: *lo alone, returning
 * 1): each tangent line of the concave disc lies above it, so
 * disc(p + j) <= disc(p) + j * step(p) and disc(q - j) <= disc(q) - j *
 * step(q - 1) (a step counted only where it rises). Both ends widened by
 * render_depth_widen: the keys' 24-bit truncations and sqrt's 32 bits stay
 * far inside that. 0: no range. */
__attribute__((noinline)) static int render_sphere_span(const vis_t *r, uint16_t oi, int32_t p, int32_t q,
                                                        int32_t iy, render_depth_t *lo, render_depth_t *hi, bool low)
{
    const render_obj_t *o = &r->obj[oi];
    const render_sphere_t *sp = o->u.sphere;
    int32_t ix0 = 0;
    const render_srow_t *s = render_sphere_rowforms(r, oi, iy, &ix0);
    if (!s || s->d2.hi >= 0 || sp->k.hi < 0 || (sp->k.hi == 0 && sp->k.lo == 0))
        return 0;
    int32_t ixp = 2 * p - r->cam->width + 1, ixq = 2 * q - r->cam->width + 1;
    int32_t kp = (ixp - ix0) / 2, kq = (ixq - ix0) / 2, len = kq - kp;
    fx128_t dq = render_quad_k(&s->v, &s->d1, &s->d2, kq), dp = {0, 0};
    if (dq.hi < 0)
        return 0; /* (not covered at an end) */
    uint64_t bq = (uint64_t)rlin_at(&sp->b, ixq, iy), bp = 0;
#if RENDER_DIV_GUESS
    /* The depth at p kept from the range before (which found p covered). */
    render_sphere_cache_t *sc = r->sphere_cache;
    bool kept = !low && sc->span_obj == oi && sc->span_x == p;
#else
    bool kept = false;
#endif
    if (!kept) {
        dp = render_quad_k(&s->v, &s->d1, &s->d2, kp);
        if (dp.hi < 0)
            return 0;
        bp = (uint64_t)rlin_at(&sp->b, ixp, iy);
    }
    if (!low) {
        render_depth_t tp, tq = render_sphere_near(sp, bq + render_sqrt128(&dq));
#if RENDER_DIV_GUESS
        if (kept) {
            tp = sc->span_t;
        } else {
            tp = render_sphere_near(sp, bp + render_sqrt128(&dp));
            sc->span_obj = oi;
            sc->span_x = p;
            sc->span_t = tp;
        }
#else
        tp = render_sphere_near(sp, bp + render_sqrt128(&dp));
#endif
        bool p_first = render_depth_less(tp, tq);
        *hi = render_depth_widen(p_first ? tq : tp, true);
        *lo = render_depth_widen(p_first ? tp : tq, false);
        return 2;
    }
    fx128_t up = fx128_add(s->d1, render_mul128_small(&s->d2, kp));            /* disc(p + 1) - disc(p) */
    fx128_t down = fx128_neg(fx128_add(s->d1, render_mul128_small(&s->d2, kq - 1))); /* disc(q - 1) - disc(q) */
    fx128_t u1 = up.hi < 0 ? dp : fx128_add(dp, render_mul128_small(&up, len));
    fx128_t u2 = down.hi < 0 ? dq : fx128_add(dq, render_mul128_small(&down, len));
    fx128_t ub = fx128_sub(u1, u2).hi < 0 ? u1 : u2;
    if (ub.hi >= (int64_t)1 << 60)
        return 0; /* (too large a bound to add b to) */
    uint64_t bmax = (int64_t)bp > (int64_t)bq ? bp : bq;
    *lo = render_depth_widen(render_sphere_near(sp, bmax + render_sqrt128(&ub)), false);
    return 1;
}

/* Depth range of box o over columns p..q of row iy, all of which it
 * covers: its depth at a column is that of a face covering it there, and
 * every face that can (its pixel bounds reach the column) has a range on
 * its part of p..q, or is behind all along it. */
__attribute__((noinline)) static bool render_box_span(const vis_t *r, const render_obj_t *o, int32_t p, int32_t q,
                                                      int32_t iy, render_depth_t *lo, render_depth_t *hi)
{
    int32_t row = render_row_of(r->cam, iy);
    bool any = false;
    for (int i = 0; i < o->nflat; i++) {
        const render_face_t *fc = &o->u.face[i];
        int32_t a = p > fc->x0 ? p : fc->x0, b = q < fc->x1 ? q : fc->x1;
        render_depth_t flo, fhi;
        if (row < fc->r0 || row > fc->r1 || a > b)
            continue;
        int k = render_flat_range(r, &fc->f, a, b, iy, &flo, &fhi);
        if (k < 0)
            return false;
        if (k == 0)
            continue;
        if (!any || render_depth_less(flo, *lo))
            *lo = flo;
        if (!any || render_depth_less(*hi, fhi))
            *hi = fhi;
        any = true;
    }
    return any;
}

/* Bounds on object oi's depth over columns p..q of row iy, all of which
 * it covers (a plane or triangle: N / D is monotone there; a sphere:
 * render_sphere_span; a box: render_box_span): 1, both ends bounds; 2
 * (a sphere, !low), *hi a bound and *lo not (its smaller end: its bound
 * below, from low, can only be lower); 0, none. low: a sphere's bound
 * below alone, into *lo. */
int render_span_range(const vis_t *r, uint16_t oi, int32_t p, int32_t q, int32_t iy, render_depth_t *lo,
                      render_depth_t *hi, bool low)
{
    const render_obj_t *o = &r->obj[oi];
    if (render_kind(o) == RENDER_FLAT) /* a plane or a triangle */
        return render_flat_range(r, render_face(o, 0), p, q, iy, lo, hi) == 1;
    if (render_kind(o) == RENDER_SPHERE)
        return render_sphere_span(r, oi, p, q, iy, lo, hi, low);
    if (render_kind(o) == RENDER_BOX)
        return render_box_span(r, o, p, q, iy, lo, hi) ? 1 : 0;
    return 0;
}
#endif

static bool render_is_plane(const render_obj_t *o) { return render_kind(o) == RENDER_FLAT && render_face(o, 0)->edges == 0; }

/* Plane p's (object j's) depth range over the whole of row iy, once per
 * row for the first RENDER_ROW_PLANES planes (pr); false when it does not
 * cover the row with one sign of N and D. */
__attribute__((noinline)) static bool render_prow_range(const vis_t *r, const render_obj_t *p, uint16_t j,
                                                        int32_t iy, render_prow_t *pr, render_depth_t *lo,
                                                        render_depth_t *hi)
{
    if (j >= RENDER_ROW_PLANES)
        return render_plane_range(r, p, 0, r->cam->width - 1, iy, lo, hi);
    if (pr->state[j] == 0)
        pr->state[j] = render_plane_range(r, p, 0, r->cam->width - 1, iy, &pr->lo[j], &pr->hi[j]) ? 1 : 2;
    if (pr->state[j] != 1)
        return false; /* (lo, hi not set: the caller reads them only on true) */
    *lo = pr->lo[j];
    *hi = pr->hi[j];
    return true;
}

/* Depth order against the planes on this row, for object i over its
 * columns x0..x1: r->row_win gets bit j when i is nearer than plane j
 * wherever both cover (no depth needed there); returns false when a plane
 * covers the whole segment nearer than i (i is hidden on this row). */
bool render_row_order(vis_t *r, uint16_t i, int32_t x0, int32_t x1, int32_t iy, render_prow_t *pr)
{
    const render_obj_t *o = &r->obj[i];
    render_depth_t blo, bhi;
    r->row_win = 0;
    if (o->ranged) {
        blo = o->tlo;
        bhi = o->thi;
    } else if (!render_is_plane(o) || r->nplanes < 2 || !render_prow_range(r, o, i, iy, pr, &blo, &bhi)) {
        return true; /* (a plane, i < nplanes: its own range over the row, which its columns span) */
    }
    uint16_t n = r->nplanes < 32 ? r->nplanes : 32;
    for (uint16_t j = 0; j < n; j++) {
        render_depth_t plo, phi;
        const render_obj_t *p = &r->obj[j];
        if (j == i || p->r0 > p->r1)
            continue;
        if (j < RENDER_ROW_PLANES) {
            /* Its range over the whole row, when it covers all of it, is
             * wider than over x0..x1, but found once per row, and mostly
             * decides alone. */
            if (pr->state[j] == 0)
                pr->state[j] = render_plane_range(r, p, 0, r->cam->width - 1, iy, &pr->lo[j], &pr->hi[j]) ? 1 : 2;
            if (pr->state[j] == 1) {
                if (render_depth_less(bhi, pr->lo[j])) {
                    r->row_win |= 1u << j;
                    continue;
                }
                if (render_depth_less(pr->hi[j], blo))
                    return false;
            }
        }
        if (!render_plane_range(r, p, x0, x1, iy, &plo, &phi))
            continue;
        if (render_depth_less(bhi, plo))
            r->row_win |= 1u << j;
        else if (render_depth_less(phi, blo))
            return false;
    }
    return true;
}

