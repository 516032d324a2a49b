/* (Over 1,000 lines: the exact and the float queries share the ray's mapping and the tree's walk, and the quick box test and the M0's edge filter lean on the exact ones.) */
/* bvh: the ray queries on a mesh in constant data (scene/bvh.h): the ray
 * mapped to mesh space once, then the tree walked nearer child first with
 * a fixed stack, and each leaf's triangles tested by their edges.
 *
 * Q16.16 works in integers, exactly (NUM_EXACT): the ray's origin in mesh
 * units of 2^-f (f = 8 .. 0, as many as keep |o| <= 2^30), its direction
 * scaled to a largest component in [2^29, 2^30], a vertex shifted by f.
 * Then for vertices a, b, c relative to the origin (below 2^31):
 *   edge values  E(p, q) = d . (p x q)   (p x q exact in 64 bits, the dot in 128)
 *   t            = a . n / d . n, n = (b - a) x (c - a) (exact in 64 bits)
 *   weights      w_a = E(b, c) / sum, ..., sum = E(b, c) + E(c, a) + E(a, b) (= d . n 2^2f)
 * and a box is hit where max over axes of the entry quotients is at most
 * the least exit quotient, compared by cross-multiplying (64 bits). Float
 * and double evaluate the same formulas in their own arithmetic, with the
 * boxes widened by a relative margin. */
#include "scene/bvh.h"
#include "scene/geom.h"

/* Only models walk a mesh: a build without them (a bare board's default)
 * compiles none of it. */
#if FXRT_MAX_MODELS > 0

/* ---- the ray in mesh space ------------------------------------------------ */

#define BVH_O_MAX ((int64_t)1 << 30) /* |origin| in units of 2^-f */
#define BVH_F_MAX 8
/* The boxes' quick test needs every |d_i| above this (bvh_box_quick). */
#define BVH_QUICK_MIN_D ((int32_t)1 << 22)

typedef struct {
    /* Q16.16 */
    int32_t o[3]; /* origin, mesh units of 2^-f (|o| <= 2^30) */
    int32_t d[3]; /* direction, largest |component| in [2^29, 2^30] */
    int f;
    int tshift;   /* world t = mesh t 2^tshift */
    /* The boxes' limit: the nearest hit so far or tmax, as a quotient
     * ln / ld of mesh t, both below 2^31 (ln rounded up, ld down: a box
     * beyond it is surely beyond the limit); ld 0: none. */
    int32_t ln, ld;
    /* The boxes' quick test (bvh_box_quick), where every |d_i| > 2^22
     * (quick, set by bvh_quick): rc[i] = 2^53 / d_i, its magnitude
     * rounded down, so that (v rc[i]) >> 32 is v / d_i in units of 2^-21
     * of mesh t within 1.5; lt, above the limit in those units
     * (INT32_MAX: none). */
    int32_t rc[3], lt;
#if !FX_HAVE_UMULL
    /* The M0's quotients (bvh_quot): rc 2^f / 2^16 = qh 2^16 + ql (ql in
     * 0..2^16), and floor(o rc / 2^32). */
    int32_t qh[3], ql[3], ko[3];
#endif
    uint8_t near[3], far[3]; /* the byte offsets in bvh_node_t of the slabs' entry and exit bounds */
    bool quick;
    /* float, double */
    num_t fo[3], fd[3];
    num_t ft;     /* the limit, NUM_MAX for none */
} bvh_ray_t;

/* v 2^s, s of either sign (right shifts round half up; |v| < 2^62, and
 * for s >= 0 the caller has shown that the product fits). */
static int64_t bvh_shift(int64_t v, int s)
{
    if (s >= 0)
        return (int64_t)((uint64_t)v << s);
    if (s <= -63)
        return 0;
    return (v + ((int64_t)1 << (-s - 1))) >> -s;
}

static int bvh_bits64(int64_t v)
{
    uint64_t u = v < 0 ? (uint64_t)0 - (uint64_t)v : (uint64_t)v;
    return u ? 64 - __builtin_clzll(u) : 0;
}

static void bvh_limit(bvh_ray_t *r, fx128_t n, fx128_t d);
static void bvh_limit64(bvh_ray_t *r, uint64_t n, uint64_t d);

/* The limit in the quick test's units: ln / ld 2^21 rounded down, plus 1,
 * so above it (saturated, or no limit: INT32_MAX). */
static void bvh_quick_limit(bvh_ray_t *r)
{
    r->lt = INT32_MAX;
    if (r->quick && r->ld != 0) {
        /* (ln 2^21 < 2^52; a quotient of 2^32 or more saturates) */
        uint64_t n = (uint64_t)r->ln << 21;
        uint32_t ld = (uint32_t)r->ld;
        uint64_t q = (n >> 32) < ld ? (uint64_t)fx_udiv64_32(n, ld) + 1 : (uint64_t)INT32_MAX;
        r->lt = q < INT32_MAX ? (int32_t)q : INT32_MAX;
    }
}

__attribute__((noinline)) static bool bvh_ray_make(const bvh_inst_t *in, const ray_t *ray, num_t tmax, bvh_ray_t *r)
{
    const num_t o[3] = {ray->o.x, ray->o.y, ray->o.z}, d[3] = {ray->d.x, ray->d.y, ray->d.z},
                t[3] = {in->t.x, in->t.y, in->t.z};
    if (!NUM_EXACT) {
        num_t sc = bvh_unscale(in->e);
        for (int j = 0; j < 3; j++) {
            r->fo[j] = r->fd[j] = NUM_ZERO;
            for (int k = 0; k < 3; k++) {
                num_t mjk = (num_t)in->m[j][k] * sc; /* m 2^-e */
                r->fo[j] = r->fo[j] + mjk * (o[k] - t[k]);
                r->fd[j] = r->fd[j] + mjk * d[k];
            }
        }
        r->ft = tmax;
        return true;
    }
    int64_t po[3], pd[3], w[3];
    int bd = 0;
#pragma GCC unroll 3
    for (int k = 0; k < 3; k++) {
        w[k] = (int64_t)num_to_q16(o[k]) - num_to_q16(t[k]);
        if (w[k] >= INT32_MAX || w[k] <= -INT32_MAX)
            return false; /* (within FXRT_COORD_LIMIT of each other it is far below 2^31) */
    }
#pragma GCC unroll 3
    for (int j = 0; j < 3; j++) {
        po[j] = pd[j] = 0;
#pragma GCC unroll 3
        for (int k = 0; k < 3; k++) {
            /* |w| < 2^31, |m| < 2^30: |po| < 3 2^61, and its rounding below fits
             * (w as 32 bits: one 32 x 32 product, not a 64-bit one) */
            po[j] += fx_smul32(in->m[j][k], (int32_t)w[k]);
            pd[j] += fx_smul32(in->m[j][k], num_to_q16(d[k]));
        }
        int b = bvh_bits64(pd[j]);
        bd = b > bd ? b : bd;
    }
    if (bd == 0)
        return false;
    /* po is the origin in mesh units times 2^(16 + e). */
    int f = BVH_F_MAX;
    for (;; f--) {
        bool fits = true;
        for (int j = 0; j < 3; j++) {
            int64_t v = bvh_shift(po[j], f - 16 - in->e);
            fits = fits && v <= BVH_O_MAX && v >= -BVH_O_MAX;
            r->o[j] = (int32_t)v;
        }
        if (fits)
            break;
        if (f == 0)
            return false; /* farther than 2^30 mesh units: bvh.h */
    }
    int sd = 30 - bd;
    r->quick = false; /* (bvh_quick, once the root's box is met) */
    for (int j = 0; j < 3; j++)
        r->d[j] = (int32_t)bvh_shift(pd[j], sd);
    r->f = f;
    /* o + t d in mesh units 2^-f is r->o + t (pd 2^(f - 16 - e)) = r->o + t 2^(f - 16 - e - sd) r->d */
    r->tshift = in->e + 16 + sd - f;
    /* tmax as a quotient of mesh t: tmax_raw / 2^(16 + tshift) */
    r->ld = 0;
    if (tmax != NUM_MAX) {
        int s = 16 + r->tshift;
        int64_t tq = num_to_q16(tmax); /* (0, 2^31): the walk's caller has tmax > 0 */
        if (s >= -30 && s <= 61) { /* (both below 2^62: bvh_limit's work in 64 bits) */
            bvh_limit64(r, s >= 0 ? (uint64_t)tq : (uint64_t)tq << -s, s >= 0 ? (uint64_t)1 << s : 1);
            return true;
        }
        fx128_t ln = fx128_from64(tq), ld = fx128_from64(1);
        if (s >= 0)
            ld = fx128_shl(ld, s);
        else
            ln = fx128_shl(ln, -s);
        bvh_limit(r, ln, ld);
    }
    return true;
}

/* ---- 128-bit helpers ------------------------------------------------------- */

static bool bvh_lt128(fx128_t a, fx128_t b) { return a.hi != b.hi ? a.hi < b.hi : a.lo < b.lo; }
static int bvh_sign128(fx128_t a) { return a.hi < 0 ? -1 : (a.hi == 0 && a.lo == 0 ? 0 : 1); }

/* n / d 2^sh in Q16.16 (n >= 0, d > 0), saturating. */
static num_t bvh_ratio(fx128_t n, fx128_t d, int sh)
{
    if (sh >= 0) {
        if (fx128_bits(n) + sh > 126)
            return NUM_MAX;
        n = fx128_shl(n, sh);
    } else {
        if (fx128_bits(d) - sh > 126)
            return NUM_ZERO;
        d = fx128_shl(d, -sh);
    }
    int bn = fx128_bits(n), bdd = fx128_bits(d), s = (bn > bdd ? bn : bdd) - 62;
    if (s > 0) {
        n = fx128_shr128(n, s);
        d = fx128_shr128(d, s);
    }
    if (d.lo == 0)
        return NUM_MAX;
    return num_from_q16(fxw_div((int64_t)n.lo, (int64_t)d.lo));
}

/* (n, d) both shifted right until they fit 62 bits, d then at least 1. */
static void bvh_reduce(fx128_t n, fx128_t d, int64_t *rn, int64_t *rd)
{
    int bn = fx128_bits(n), bdd = fx128_bits(d), s = (bn > bdd ? bn : bdd) - 62;
    if (s > 0) {
        n = fx128_shr128(n, s);
        d = fx128_shr128(d, s);
    }
    *rn = (int64_t)n.lo;
    *rd = d.lo ? (int64_t)d.lo : 1;
}

/* The limit from n, d reduced to 31 bits (n rounded up). */
static void bvh_limit_to(bvh_ray_t *r, uint64_t n, uint64_t d)
{
    r->ln = n >= ((uint64_t)1 << 31) ? INT32_MAX : (int32_t)n;
    r->ld = (int32_t)(d & 0x7FFFFFFFu);
    if (n >= ((uint64_t)1 << 31))
        r->ld = 0; /* (n rounded up to 2^31: no limit rather than a wrong one) */
    bvh_quick_limit(r);
}

/* The boxes' limit from the quotient n / d (n, d > 0): both shifted right
 * until they fit 31 bits, n rounded up and d down, so that ln / ld >= n /
 * d; none where d vanishes. */
static void bvh_limit(bvh_ray_t *r, fx128_t n, fx128_t d)
{
    int bn = fx128_bits(n), bdd = fx128_bits(d), s = (bn > bdd ? bn : bdd) - 31;
    if (s > 0) {
        n = fx128_add(n, fx128_from64(((int64_t)1 << (s < 62 ? s : 62)) - 1)); /* (s < bn <= 127) */
        if (s >= 64) {
            n.lo = (uint64_t)n.hi >> (s - 64);
            d.lo = (uint64_t)d.hi >> (s - 64);
        } else {
            n.lo = (n.lo >> s) | ((uint64_t)n.hi << (64 - s));
            d.lo = (d.lo >> s) | ((uint64_t)d.hi << (64 - s));
        }
        n.lo += s >= 62 ? 1 : 0; /* (rounding up past 2^62 approximately: one more) */
    }
    bvh_limit_to(r, n.lo, d.lo);
}

/* bvh_limit for n, d below 2^62 (then its shift is below 62, and this is
 * its arithmetic in 64 bits). */
static void bvh_limit64(bvh_ray_t *r, uint64_t n, uint64_t d)
{
    int bn = bvh_bits64((int64_t)n), bdd = bvh_bits64((int64_t)d), s = (bn > bdd ? bn : bdd) - 31;
    if (s > 0) {
        n = (n + (((uint64_t)1 << s) - 1)) >> s;
        d >>= s;
    }
    bvh_limit_to(r, n, d);
}

/* ---- a box ---------------------------------------------------------------- */

/* Is the node's box met at a t in [0, the limit]? *en / *ed: its entry t
 * (Q16.16) or *fen (float, double), for the order of the walk. */
static bool bvh_box(const bvh_ray_t *r, const bvh_node_t *nd, int32_t *en, int32_t *ed, num_t *fen)
{
    if (!NUM_EXACT) {
        num_t lo = NUM_ZERO, hi = r->ft;
        for (int i = 0; i < 3; i++) {
            num_t a = (num_t)nd->lo[i], b = (num_t)nd->hi[i];
            if (r->fd[i] == NUM_ZERO) {
                if (r->fo[i] < a || r->fo[i] > b)
                    return false;
                continue;
            }
            num_t t0 = (a - r->fo[i]) / r->fd[i], t1 = (b - r->fo[i]) / r->fd[i];
            if (t0 > t1) {
                num_t s = t0;
                t0 = t1;
                t1 = s;
            }
            /* widened by a relative margin against the rounding of the quotients */
            num_t eps = (num_t)(sizeof(num_t) == sizeof(float) ? 1e-5 : 1e-13);
            t0 = t0 - (t0 > 0 ? t0 : -t0) * eps - eps;
            t1 = t1 + (t1 > 0 ? t1 : -t1) * eps + eps;
            lo = t0 > lo ? t0 : lo;
            hi = t1 < hi ? t1 : hi;
        }
        *fen = lo;
        return lo <= hi;
    }
    /* |lo, hi 2^f| <= 2^23 and |o| <= 2^30: every quotient's numerator
     * fits 31 bits, its denominator 30, each cross product 61 */
    int32_t n0 = 0, d0 = 1; /* entry, from t = 0 */
    int32_t n1 = 0, d1 = 0; /* exit (d1 0: none yet) */
#pragma GCC unroll 3
    for (int i = 0; i < 3; i++) {
        int32_t a = (int32_t)nd->lo[i] * (1 << r->f), b = (int32_t)nd->hi[i] * (1 << r->f), o = r->o[i], d = r->d[i];
        if (d == 0) {
            if (o < a || o > b)
                return false;
            continue;
        }
        int32_t ne = d > 0 ? a - o : o - b, nx = d > 0 ? b - o : o - a, ad = d > 0 ? d : -d;
        if (fx_smul32(ne, d0) > fx_smul32(n0, ad)) {
            n0 = ne;
            d0 = ad;
        }
        if (d1 == 0 || fx_smul32(nx, d1) < fx_smul32(n1, ad)) {
            n1 = nx;
            d1 = ad;
        }
    }
    if (d1 != 0 && fx_smul32(n0, d1) > fx_smul32(n1, d0))
        return false;
    if (r->ld != 0 && fx_smul32(r->ln, d0) < fx_smul32(n0, r->ld))
        return false; /* enters beyond the limit */
    *en = n0;
    *ed = d0;
    return true;
}

/* One bound's T: the int16_t at byte offset off of node bytes b, on axis i.
 * Where the target multiplies 32 x 32 bits (FX_HAVE_UMULL), T =
 * floor(Q) with Q = (b 2^f - o) rc / 2^32, one SMULL's high word. The M0
 * has no such multiply (fx_smul32 is four 16-bit products and their
 * carries), so it takes two products of the bound b, 16 bits: Q = b qh +
 * b ql / 2^16 + b r0 / 2^32 - o rc / 2^32, where rc 2^f = (qh 2^16 + ql)
 * 2^16 + r0 (r0 in 0..2^16), and its T' = b qh + floor(b ql / 2^16) - ko,
 * ko = floor(o rc / 2^32) once per ray (bvh_quick). The floor loses below
 * 1, b r0 / 2^32 lies within 0.5 and ko below 1: T' - Q lies in (-1.5,
 * 1.5), so T' is at most BVH_QUICK_LO = 1 below floor(Q) and at most
 * BVH_QUICK_HI = 2 above it. (|b qh| < 2^22 and |b ql| < 2^31: 32-bit
 * products.) */
#define BVH_QUICK_LO (FX_HAVE_UMULL ? 0 : 1)
#define BVH_QUICK_HI (FX_HAVE_UMULL ? 0 : 2)
static inline int32_t bvh_quot(const bvh_ray_t *r, const unsigned char *b, unsigned off, int i)
{
    int32_t v = *(const int16_t *)(b + off);
#if FX_HAVE_UMULL
    return (int32_t)(fx_smul32(v * (1 << r->f) - r->o[i], r->rc[i]) >> 32);
#else
    return v * r->qh[i] + ((v * r->ql[i]) >> 16) - r->ko[i];
#endif
}

/* Met, for entry E and exit X (bvh_box_quick's margins). */
static inline bool bvh_quick_met(const bvh_ray_t *r, int32_t e, int32_t x)
{
    return e - 2 - BVH_QUICK_LO - BVH_QUICK_HI <= x && e - 1 - BVH_QUICK_HI <= r->lt;
}

/* Q16.16, a ray with r->quick: bvh_box's question without its exact
 * quotients, answered yes wherever bvh_box says yes (and sometimes where
 * it says no). Per axis the slab's two values v = lo 2^f - o, hi 2^f - o
 * (|v| < 2^31) become quotients T = (v rc) >> 32: v / d 2^21, wrong by
 * less than 1.5 (rc's rounding, below 1, times |v| / 2^32 < 0.5, and the
 * floor's 1), and below 2^30 in size (|d| > 2^22). The entry E = max(0,
 * the slabs' lesser T) and the exit X = the least greater T are each within
 * 1.5 of the exact ones, whose test is entry <= exit and entry <= the
 * limit: so E <= X + 2 and E <= lt + 1 hold wherever it passes. On the
 * M0 each T' lies within BVH_QUICK_LO below and BVH_QUICK_HI above that T
 * (bvh_quot), so E' <= E + HI and X' >= X - LO: E' <= X' + 2 + LO + HI
 * and E' <= lt + 1 + HI hold. *te: E, for the walk's order (bvh_order). */
static __attribute__((noinline)) bool bvh_box_quick(const bvh_ray_t *r, const bvh_node_t *nd, int32_t *te)
{
    const unsigned char *b = (const unsigned char *)nd;
    int32_t e = 0, x = INT32_MAX;
#pragma GCC unroll 3
    for (int i = 0; i < 3; i++) {
        /* (the entry's bound is lo where d > 0, hi where d < 0: rc's sign
         * makes both quotients right) */
        int32_t tn = bvh_quot(r, b, r->near[i], i), tf = bvh_quot(r, b, r->far[i], i);
        e = tn > e ? tn : e;
        x = tf < x ? tf : x;
    }
    *te = e;
    return bvh_quick_met(r, e, x);
}

/* bvh_box_quick for both children of an inner node (nd[0], nd[1]), in
 * one call that reads the ray's values once for the two: bit 0 set where
 * the first is met (e[0] its E), bit 1 where the second is. */
static __attribute__((noinline)) unsigned bvh_pair_quick(const bvh_ray_t *r, const bvh_node_t *nd, int32_t e[2])
{
    const unsigned char *b0 = (const unsigned char *)&nd[0], *b1 = (const unsigned char *)&nd[1];
    int32_t e0 = 0, x0 = INT32_MAX, e1 = 0, x1 = INT32_MAX;
#pragma GCC unroll 3
    for (int i = 0; i < 3; i++) {
        int32_t t0n = bvh_quot(r, b0, r->near[i], i), t0f = bvh_quot(r, b0, r->far[i], i);
        int32_t t1n = bvh_quot(r, b1, r->near[i], i), t1f = bvh_quot(r, b1, r->far[i], i);
        e0 = t0n > e0 ? t0n : e0;
        x0 = t0f < x0 ? t0f : x0;
        e1 = t1n > e1 ? t1n : e1;
        x1 = t1f < x1 ? t1f : x1;
    }
    e[0] = e0;
    e[1] = e1;
    return (unsigned)bvh_quick_met(r, e0, x0) | (unsigned)bvh_quick_met(r, e1, x1) << 1;
}

/* Q16.16: the quick test's data (bvh_box_quick), where every |d_i| is
 * above BVH_QUICK_MIN_D: set up after the root's box is met, so that a
 * ray that misses the model does not pay its three divisions. */
static void bvh_quick(bvh_ray_t *r)
{
    if (FXRT_NO_BVH_QUICK)
        return; /* (a measurement: the walk is the same) */
    for (int j = 0; j < 3; j++) {
        int32_t ad = r->d[j] < 0 ? -r->d[j] : r->d[j];
        if (ad <= BVH_QUICK_MIN_D)
            return;
    }
    for (int j = 0; j < 3; j++) {
        bool neg = r->d[j] < 0;
        /* below 2^31 (|d| > 2^22 > 2^53 / 2^32: fx_udiv64_32's bound) */
        int32_t q = (int32_t)fx_udiv64_32((uint64_t)1 << 53, (uint32_t)(neg ? -r->d[j] : r->d[j]));
        r->rc[j] = neg ? -q : q;
#if !FX_HAVE_UMULL
        int32_t q16 = (int32_t)(((int64_t)r->rc[j] * (1 << r->f)) >> 16); /* |rc 2^f| < 2^39 */
        r->qh[j] = q16 >> 16;
        r->ql[j] = q16 & 0xffff;
        r->ko[j] = (int32_t)(fx_smul32(r->o[j], r->rc[j]) >> 32);
#endif
        r->near[j] = (uint8_t)((neg ? offsetof(bvh_node_t, hi) : offsetof(bvh_node_t, lo)) + 2 * j);
        r->far[j] = (uint8_t)((neg ? offsetof(bvh_node_t, lo) : offsetof(bvh_node_t, hi)) + 2 * j);
    }
    r->quick = true;
    bvh_quick_limit(r);
}

/* A box met (a node popped from the walk's stack): bvh_box's, or
 * bvh_box_quick's where the ray has it (then *ed = 0 marks *en as its E). */
static FXRT_INLINE_WIDE bool bvh_box_met(const bvh_ray_t *r, const bvh_node_t *nd, int32_t *en, int32_t *ed, num_t *fen)
{
    if (NUM_EXACT && r->quick) {
        *ed = 0;
        return bvh_box_quick(r, nd, en);
    }
    return bvh_box(r, nd, en, ed, fen);
}

/* Is box entry 1 before entry 2? 1 or 0; -1: entries of bvh_box_quick
 * too close to tell (each within 1.5 of its exact value: a difference of
 * 3 or more decides; on the M0, whose entries E' lie within BVH_QUICK_LO
 * below and BVH_QUICK_HI above, 3 + LO + HI: then E1 <= E1' + LO <= E2' -
 * 3 - HI <= E2 - 3), for which the caller asks bvh_box again. */
static int bvh_order(int32_t n1, int32_t d1, num_t f1, int32_t n2, int32_t d2, num_t f2)
{
    if (!NUM_EXACT)
        return f1 < f2;
    if (d1 == 0 || d2 == 0)
        return n1 <= n2 - 3 - BVH_QUICK_LO - BVH_QUICK_HI ? 1 : n2 <= n1 - 3 - BVH_QUICK_LO - BVH_QUICK_HI ? 0 : -1;
    return fx_smul32(n1, d2) < fx_smul32(n2, d1);
}

/* ---- a triangle ----------------------------------------------------------- */

typedef struct {
    fx128_t tn, det;        /* Q16.16: t's numerator and denominator (det > 0) */
    num_t fe[3], ftn, fdet; /* float, double: the edge values (for their signs), t's numerator and denominator */
} bvh_cand_t;

/* p x q exactly (|p|, |q| < 2^31: each product below 2^62, each
 * difference below 2^63). */
static FXRT_INLINE_WIDE void bvh_cross32(const int32_t p[3], const int32_t q[3], int64_t c[3])
{
    c[0] = fx_smul32(p[1], q[2]) - fx_smul32(p[2], q[1]);
    c[1] = fx_smul32(p[2], q[0]) - fx_smul32(p[0], q[2]);
    c[2] = fx_smul32(p[0], q[1]) - fx_smul32(p[1], q[0]);
}

/* The high part of d . c: with c = h 2^32 + l (l in [0, 2^32)), the sum of
 * d h. d . c = that 2^32 + the sum of d l, whose size is below
 * 3 2^30 2^32 (|d| < 2^30). */
static int64_t bvh_dot_high(const int32_t d[3], const int64_t c[3])
{
    return fx_smul32(d[0], (int32_t)(c[0] >> 32)) + fx_smul32(d[1], (int32_t)(c[1] >> 32)) +
           fx_smul32(d[2], (int32_t)(c[2] >> 32));
}

/* d . c exactly, for |d| <= 2^30 (any c) or |c| < 2^62 (|d| < 2^31): the
 * high part's sum must fit 64 bits. */
static fx128_t bvh_dot_wide(const int32_t d[3], const int64_t c[3])
{
    int64_t h = bvh_dot_high(d, c);
    fx128_t s = {(uint64_t)h << 32, h >> 32}; /* h 2^32: its words moved up (no general shift) */
    for (int j = 0; j < 3; j++) {
        uint64_t u = fx_umul32(fx_uabs32(d[j]), (uint32_t)c[j]); /* below 2^63 */
        s = fx128_add(s, fx128_from64(d[j] < 0 ? -(int64_t)u : (int64_t)u));
    }
    return s;
}

/* The sign of d . c (|d| < 2^30): the high part alone decides unless it is
 * within 3 2^30 of zero (bvh_dot_high), then the exact sum. */
static int bvh_dot_sign(const int32_t d[3], const int64_t c[3])
{
    int64_t h = bvh_dot_high(d, c);
    if (h > 3 * ((int64_t)1 << 30))
        return 1;
    if (h < -3 * ((int64_t)1 << 30))
        return -1;
    return bvh_sign128(bvh_dot_wide(d, c));
}

static void bvh_crossf(const num_t p[3], const num_t q[3], num_t c[3])
{
    c[0] = p[1] * q[2] - p[2] * q[1];
    c[1] = p[2] * q[0] - p[0] * q[2];
    c[2] = p[0] * q[1] - p[1] * q[0];
}

/* Vertex k's opposite edge runs from vertex bvh_next[k] to bvh_next[k + 1]. */
static const uint8_t bvh_next[4] = {1, 2, 0, 1};

/* Q16.16: triangle i's vertices relative to the origin, in units of 2^-f
 * (|v 2^f| <= 2^23, |o| <= 2^30: below 2^31), and its vertex indices. */
static void bvh_rel(const bvh_mesh_t *m, const bvh_ray_t *r, uint32_t i, int32_t p[3][3], uint32_t vi[3])
{
    bvh_tri(m, i, vi);
    /* (unrolled: the loops' counting cost as much as their work; the
     * origin, shift and vertex rows in locals, which the stores to p
     * would otherwise make the compiler load again each time) */
    const int32_t o[3] = {r->o[0], r->o[1], r->o[2]}, f = r->f;
    const int16_t *v[3] = {m->v[vi[0]], m->v[vi[1]], m->v[vi[2]]};
#pragma GCC unroll 3
    for (int k = 0; k < 3; k++)
#pragma GCC unroll 3
        for (int j = 0; j < 3; j++)
            p[k][j] = (int32_t)v[k][j] * (1 << f) - o[j];
}

/* Q16.16: the cross product of edge k (the edge opposite vertex k), in
 * the order of its vertex indices, and whether that order is reversed. */
static FXRT_INLINE_WIDE bool bvh_edge_cross(int32_t p[3][3], const uint32_t vi[3], int k, int64_t x[3])
{
    int a = bvh_next[k], b = bvh_next[k + 1];
    bool swap = vi[b] < vi[a];
    bvh_cross32(p[swap ? b : a], p[swap ? a : b], x);
    return swap;
}

/* The M0's edge filter (bvh_triangle). Edge k's value d . (pa x pb)
 * equals d . (pa x e), e = pb - pa = (vb - va) 2^f: exact and below 2^24,
 * its size the edge's, not the origin's distance. With pa = pa' 2^sp + a
 * and e = e' 2^se + b (floors: a, b in 0..2^s; |pa'|, |e'| < 2^14, one
 * shift each for the triangle's three), c' = pa' x e' (16-bit products),
 * c'' = c' >> 15 (|c''| <= 2^14) and d' = d >> 15 (|d'| <= 2^15): then
 * with U = 2^(sp + se), pa x e / U = 2^15 c'' + w, |w| < 2^17 (pa' x b
 * and a x e' each below 2^15 an axis, a x b / U below 2, c' - 2^15 c''
 * below 2^15), and d . (pa x e) / U = 2^30 (d' . c'') + 2^15 (d - 2^15 d')
 * . c'' + d . w, the last two below 3 2^44 + 3 2^47 = 27 2^44 in size. So
 * d' . c'' (each product below 2^29: 32 bits) has the sign of the edge's
 * value wherever its size exceeds 27 2^14 = BVH_EDGE_SLACK; else the
 * exact test decides. */
#define BVH_EDGE_SLACK (27 * ((int32_t)1 << 14))

/* The shift that brings magnitude m below 2^14. */
static int bvh_shift14(uint32_t m)
{
    int s = 0;
    if (m >> 16) {
        m >>= 16;
        s = 16;
    }
    if (m >> 8) {
        m >>= 8;
        s += 8;
    }
    while (m) {
        m >>= 1;
        s++;
    }
    return s > 14 ? s - 14 : 0;
}

/* Edge k's sign by the filter, from the triangle's vertices p relative to
 * the origin, their shift sp, the edges' se and the direction's d' (dq):
 * 1, -1, or 0 where it cannot tell. */
static inline __attribute__((always_inline)) int bvh_edge_filter(int32_t p[3][3], int k, int sp, int se,
                                                                 int32_t dq0, int32_t dq1, int32_t dq2)
{
    const int32_t *pa = p[bvh_next[k]], *pb = p[bvh_next[k + 1]];
    int32_t a0 = pa[0] >> sp, a1 = pa[1] >> sp, a2 = pa[2] >> sp;
    int32_t e0 = (pb[0] - pa[0]) >> se, e1 = (pb[1] - pa[1]) >> se, e2 = (pb[2] - pa[2]) >> se;
    int32_t v = dq0 * ((a1 * e2 - a2 * e1) >> 15) + dq1 * ((a2 * e0 - a0 * e2) >> 15) +
                dq2 * ((a0 * e1 - a1 * e0) >> 15);
    return v > BVH_EDGE_SLACK ? 1 : v < -BVH_EDGE_SLACK ? -1 : 0;
}

/* Does the ray's line pass through triangle i (its edges, either winding,
 * a zero on an edge counting), in front of the origin? c: t's quotient,
 * with det > 0. */
__attribute__((noinline)) static bool bvh_triangle(const bvh_mesh_t *m, const bvh_ray_t *r, uint32_t i, bvh_cand_t *c)
{
    uint32_t vi[3];
    if (!NUM_EXACT) {
        bvh_tri(m, i, vi);
        num_t p[3][3], x[3][3];
        for (int k = 0; k < 3; k++)
            for (int j = 0; j < 3; j++)
                p[k][j] = (num_t)m->v[vi[k]][j] - r->fo[j];
        for (int k = 0; k < 3; k++) { /* edge (k+1, k+2): weight of vertex k */
            int a = bvh_next[k], b = bvh_next[k + 1];
            bool swap = vi[b] < vi[a];
            bvh_crossf(p[swap ? b : a], p[swap ? a : b], x[k]);
            num_t e = r->fd[0] * x[k][0] + r->fd[1] * x[k][1] + r->fd[2] * x[k][2];
            c->fe[k] = swap ? -e : e;
        }
        bool neg = c->fe[0] < 0 || c->fe[1] < 0 || c->fe[2] < 0, pos = c->fe[0] > 0 || c->fe[1] > 0 || c->fe[2] > 0;
        if (neg && pos)
            return false;
        num_t sum = c->fe[0] + c->fe[1] + c->fe[2], e1[3], e2[3], n[3];
        for (int j = 0; j < 3; j++) {
            e1[j] = (num_t)m->v[vi[1]][j] - (num_t)m->v[vi[0]][j];
            e2[j] = (num_t)m->v[vi[2]][j] - (num_t)m->v[vi[0]][j];
        }
        bvh_crossf(e1, e2, n);
        c->fdet = r->fd[0] * n[0] + r->fd[1] * n[1] + r->fd[2] * n[2];
        c->ftn = p[0][0] * n[0] + p[0][1] * n[1] + p[0][2] * n[2];
        if (sum == NUM_ZERO || c->fdet == NUM_ZERO)
            return false;
        return c->ftn / c->fdet > 0;
    }
    int32_t p[3][3];
    int64_t x[3];
    bvh_rel(m, r, i, p, vi);
    int pos = 0, neg = 0;
    /* The M0 (no 32 x 32 -> 64-bit multiply): the filter above first, the
     * exact test only where it cannot tell; elsewhere the exact test. */
    int sp = 0, se = 0;
    int32_t dq0 = 0, dq1 = 0, dq2 = 0;
    if (!FX_HAVE_UMULL) {
        uint32_t mp = 0, me = 0;
        for (int j = 0; j < 3; j++) {
            mp |= fx_uabs32(p[0][j]) | fx_uabs32(p[1][j]) | fx_uabs32(p[2][j]);
            me |= fx_uabs32(p[1][j] - p[0][j]) | fx_uabs32(p[2][j] - p[1][j]) | fx_uabs32(p[0][j] - p[2][j]);
        }
        sp = bvh_shift14(mp);
        se = bvh_shift14(me);
        dq0 = r->d[0] >> 15;
        dq1 = r->d[1] >> 15;
        dq2 = r->d[2] >> 15;
    }
#pragma GCC unroll 3
    for (int k = 0; k < 3; k++) {
        int sg = FX_HAVE_UMULL ? 0 : bvh_edge_filter(p, k, sp, se, dq0, dq1, dq2);
        if (sg == 0) {
            bool swap = bvh_edge_cross(p, vi, k, x);
            sg = bvh_dot_sign(r->d, x);
            sg = swap ? -sg : sg;
        }
        pos |= sg > 0;
        neg |= sg < 0;
        if (pos && neg)
            return false;
    }
    /* the plane: n = (b - a) x (c - a) in mesh units (exact, below 2^34);
     * E(b, c) + E(c, a) + E(a, b) = d . n 2^2f exactly */
    int32_t e1[3], e2[3];
    int64_t n[3];
    const int16_t *va = m->v[vi[0]], *vb = m->v[vi[1]], *vc = m->v[vi[2]];
#pragma GCC unroll 3
    for (int j = 0; j < 3; j++) {
        e1[j] = (int32_t)vb[j] - va[j];
        e2[j] = (int32_t)vc[j] - va[j];
    }
    bvh_cross32(e1, e2, n);
    c->det = bvh_dot_wide(r->d, n);
    int sd = bvh_sign128(c->det);
    if (sd == 0)
        return false;
    c->tn = bvh_dot_wide(p[0], n);
    if (sd < 0) {
        c->det = fx128_neg(c->det);
        c->tn = fx128_neg(c->tn);
    }
    return bvh_sign128(c->tn) > 0;
}

/* Q16.16: the weights of the hit in triangle i, its exact edge values over
 * their sum. */
__attribute__((noinline)) static void bvh_weights_q(const bvh_mesh_t *m, const bvh_ray_t *r, uint32_t i, num_t w[3])
{
    int32_t p[3][3];
    int64_t x[3];
    uint32_t vi[3];
    fx128_t e[3];
    bvh_rel(m, r, i, p, vi);
    for (int k = 0; k < 3; k++) {
        bool swap = bvh_edge_cross(p, vi, k, x);
        e[k] = bvh_dot_wide(r->d, x);
        if (swap)
            e[k] = fx128_neg(e[k]);
    }
    fx128_t sum = fx128_add(fx128_add(e[0], e[1]), e[2]);
    bool neg = bvh_sign128(sum) < 0;
    if (neg)
        sum = fx128_neg(sum);
    for (int k = 0; k < 3; k++)
        w[k] = bvh_ratio(neg ? fx128_neg(e[k]) : e[k], sum, 0);
}

/* Float, double: the weights of the hit point p = o + t d in triangle i,
 * from its own edges: w_a = n . ((c - b) x (p - b)) / n . n, ... (the
 * edge values, relative to a distant origin, carry too much rounding). */
static void bvh_weights_f(const bvh_mesh_t *m, const bvh_ray_t *r, uint32_t i, num_t t, num_t w[3])
{
    uint32_t vi[3];
    bvh_tri(m, i, vi);
    num_t v[3][3], e1[3], e2[3], n[3], p[3];
    for (int k = 0; k < 3; k++)
        for (int j = 0; j < 3; j++)
            v[k][j] = (num_t)m->v[vi[k]][j];
    for (int j = 0; j < 3; j++) {
        e1[j] = v[1][j] - v[0][j];
        e2[j] = v[2][j] - v[0][j];
        p[j] = r->fo[j] + t * r->fd[j];
    }
    bvh_crossf(e1, e2, n);
    num_t nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    for (int k = 0; k < 3; k++) {
        const num_t *a = v[bvh_next[k]], *b = v[bvh_next[k + 1]];
        num_t ab[3], ap[3], x[3];
        for (int j = 0; j < 3; j++) {
            ab[j] = b[j] - a[j];
            ap[j] = p[j] - a[j];
        }
        bvh_crossf(ab, ap, x);
        w[k] = (n[0] * x[0] + n[1] * x[1] + n[2] * x[2]) / nn;
    }
}

/* The candidate's world t (Q16.16: from its quotient; 0 for one below
 * 1 LSB, which is no hit). */
static num_t bvh_cand_t_world(const bvh_ray_t *r, const bvh_cand_t *c)
{
    return NUM_EXACT ? bvh_ratio(c->tn, c->det, r->tshift) : c->ftn / c->fdet;
}

/* ---- the walk --------------------------------------------------------------- */

/* The walk, for the nearest hit (nearest) or any (!nearest). */
static bool bvh_walk(const bvh_inst_t *in, const ray_t *ray, num_t tmax, uint32_t skip, bool nearest, bool weights,
                     bvh_hit_t *hit)
{
    const bvh_mesh_t *m = in->mesh;
    bvh_ray_t r;
    if (!(tmax > NUM_ZERO) || !bvh_ray_make(in, ray, tmax, &r))
        return false;
    uint32_t stack[BVH_MAX_DEPTH];
    int sp = 0;
    uint32_t ni = 0;
    int32_t en0 = 0, ed0 = 1, en1 = 0, ed1 = 1;
    num_t fe0 = NUM_ZERO, fe1 = NUM_ZERO;
    bool found = false;
    bvh_cand_t c;
    num_t best_t = NUM_MAX;
    int64_t bn = 0, bd = 1; /* Q16.16: the nearest so far, t's quotient reduced to 62 bits */
    if (!bvh_box(&r, &m->node[0], &en0, &ed0, &fe0))
        return false;
    if (NUM_EXACT)
        bvh_quick(&r);
    for (;;) {
        const bvh_node_t *nd = &m->node[ni];
        uint32_t cnt = nd->link & 15u, first = nd->link >> 4;
        if (cnt) {
            for (uint32_t i = first; i < first + cnt; i++) {
                if (i == skip || !bvh_triangle(m, &r, i, &c))
                    continue;
                int64_t cn = 0, cd = 1;
                if (NUM_EXACT && nearest) /* (any-hit needs no order) */
                    bvh_reduce(c.tn, c.det, &cn, &cd);
                if (NUM_EXACT && found && !bvh_lt128(fx128_mul(cn, bd), fx128_mul(bn, cd)))
                    continue; /* not before the nearest so far (to 2^-60) */
                num_t t = bvh_cand_t_world(&r, &c);
                if (!NUM_EXACT && !(t < r.ft))
                    continue;
                if (NUM_EXACT && (t <= NUM_ZERO || !(t < tmax)))
                    continue; /* below 1 LSB, or at tmax after rounding */
                if (!nearest)
                    return true;
                found = true;
                best_t = t;
                hit->tri = i;
                if (NUM_EXACT) {
                    bn = cn;
                    bd = cd;
                    bvh_limit(&r, c.tn, c.det);
                } else {
                    r.ft = t;
                }
            }
        } else if (first + 1 < m->n_nodes) {
            bool h0, h1;
            if (NUM_EXACT && r.quick) {
                int32_t te[2];
                unsigned met = bvh_pair_quick(&r, &m->node[first], te);
                h0 = met & 1u;
                h1 = met >> 1;
                en0 = te[0];
                en1 = te[1];
                ed0 = ed1 = 0;
            } else {
                h0 = bvh_box(&r, &m->node[first], &en0, &ed0, &fe0);
                h1 = bvh_box(&r, &m->node[first + 1], &en1, &ed1, &fe1);
            }
            int second = h0 && h1 ? bvh_order(en1, ed1, fe1, en0, ed0, fe0) : 0;
            if (second < 0) {
                /* the quick entries are too close to order: the exact
                 * test's, so that the walk's order (and with it the
                 * nearest of equal hits) is the exact test's */
                h0 = bvh_box(&r, &m->node[first], &en0, &ed0, &fe0);
                h1 = bvh_box(&r, &m->node[first + 1], &en1, &ed1, &fe1);
                second = h0 && h1 && bvh_order(en1, ed1, fe1, en0, ed0, fe0);
            }
            if (h0 && h1 && sp < BVH_MAX_DEPTH) {
                stack[sp++] = second ? first : first + 1;
                ni = second ? first + 1 : first;
                continue;
            }
            if (h0 || h1) {
                ni = h0 ? first : first + 1;
                continue;
            }
        }
        /* the next node on the stack whose box is still met */
        for (;;) {
            if (sp == 0) {
                if (found) {
                    hit->t = best_t;
                    if (!weights)
                        return true;
                    if (NUM_EXACT)
                        bvh_weights_q(m, &r, hit->tri, hit->w);
                    else
                        bvh_weights_f(m, &r, hit->tri, best_t, hit->w);
                }
                return found;
            }
            ni = stack[--sp];
            if (bvh_box_met(&r, &m->node[ni], &en0, &ed0, &fe0))
                break;
        }
    }
}

bool bvh_nearest(const bvh_inst_t *in, const ray_t *ray, num_t tmax, uint32_t skip, bvh_hit_t *hit)
{
    return bvh_walk(in, ray, tmax, skip, true, true, hit);
}

bool bvh_first(const bvh_inst_t *in, const ray_t *ray, num_t tmax, uint32_t skip, bvh_hit_t *hit)
{
    return bvh_walk(in, ray, tmax, skip, true, false, hit);
}

bool bvh_any(const bvh_inst_t *in, const ray_t *ray, num_t tmax, uint32_t skip)
{
    bvh_hit_t unused;
    return bvh_walk(in, ray, tmax, skip, false, false, &unused);
}

bool bvh_hit_tri(const bvh_inst_t *in, const ray_t *ray, uint32_t tri, bvh_hit_t *hit)
{
    bvh_ray_t r;
    bvh_cand_t c;
    if (tri >= in->mesh->n_triangles || !bvh_ray_make(in, ray, NUM_MAX, &r) || !bvh_triangle(in->mesh, &r, tri, &c))
        return false;
    num_t t = bvh_cand_t_world(&r, &c); /* (the walk's value for it) */
    if (!(t > NUM_ZERO))
        return false;
    hit->tri = tri;
    hit->t = t;
    if (NUM_EXACT)
        bvh_weights_q(in->mesh, &r, tri, hit->w);
    else
        bvh_weights_f(in->mesh, &r, tri, t, hit->w);
    return true;
}

/* ---- normals ---------------------------------------------------------------- */

/* The world direction of mesh-space normal v (M^-T v = m^T v 2^-e; the
 * power of two goes with the normalisation), normalised. */
static bool bvh_world_normal(const bvh_inst_t *in, const int64_t v[3], const num_t fv[3], vec3_t *n)
{
    num_t out[3];
    if (!NUM_EXACT) {
        for (int j = 0; j < 3; j++)
            out[j] = (num_t)in->m[0][j] * fv[0] + (num_t)in->m[1][j] * fv[1] + (num_t)in->m[2][j] * fv[2];
    } else {
        int b = 0;
        for (int j = 0; j < 3; j++)
            b = bvh_bits64(v[j]) > b ? bvh_bits64(v[j]) : b;
        int64_t s[3], w[3];
        for (int j = 0; j < 3; j++)
            s[j] = bvh_shift(v[j], b > 30 ? 30 - b : 0); /* |s| <= 2^30, |m| < 2^30: the sums fit */
        b = 0;
        for (int j = 0; j < 3; j++) { /* (s as 32 bits: 32 x 32 products) */
            w[j] = fx_smul32(in->m[0][j], (int32_t)s[0]) + fx_smul32(in->m[1][j], (int32_t)s[1]) +
                   fx_smul32(in->m[2][j], (int32_t)s[2]);
            b = bvh_bits64(w[j]) > b ? bvh_bits64(w[j]) : b;
        }
        for (int j = 0; j < 3; j++)
            out[j] = num_from_q16((int32_t)bvh_shift(w[j], 30 - b)); /* direction only: any scale */
    }
    if (!num_normalize3(out))
        return false;
    *n = vec3_make(out[0], out[1], out[2]);
    return true;
}

bool bvh_normal(const bvh_inst_t *in, const bvh_hit_t *hit, bool smooth, vec3_t *n)
{
    const bvh_mesh_t *m = in->mesh;
    uint32_t vi[3];
    bvh_tri(m, hit->tri, vi);
    int64_t v[3];
    num_t fv[3];
    if (!smooth || !m->vn) {
        /* (b - a) x (c - a), exact in 64 bits */
        int32_t e1[3], e2[3];
        for (int j = 0; j < 3; j++) {
            e1[j] = (int32_t)m->v[vi[1]][j] - m->v[vi[0]][j];
            e2[j] = (int32_t)m->v[vi[2]][j] - m->v[vi[0]][j];
        }
        bvh_cross32(e1, e2, v);
        for (int j = 0; j < 3; j++)
            fv[j] = (num_t)v[j];
        return bvh_world_normal(in, v, fv, n);
    }
    /* smooth: each vertex normal to the world, normalised, then blended by
     * the weights and normalised (docs/LIGHTING.md) */
    vec3_t sum = vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    for (int k = 0; k < 3; k++) {
        vec3_t nk;
        for (int j = 0; j < 3; j++) {
            v[j] = m->vn[vi[k]][j];
            fv[j] = (num_t)v[j];
        }
        if (!bvh_world_normal(in, v, fv, &nk))
            return false;
        sum = vec3_add(sum, vec3_scale_unit(nk, hit->w[k]));
    }
    num_t s[3] = {sum.x, sum.y, sum.z};
    if (!num_normalize3(s))
        return false;
    *n = vec3_make(s[0], s[1], s[2]);
    return true;
}

/* ---- the check -------------------------------------------------------------- */

static bool bvh_in_box(const bvh_node_t *nd, const int16_t p[3])
{
    for (int j = 0; j < 3; j++)
        if (p[j] < nd->lo[j] || p[j] > nd->hi[j])
            return false;
    return true;
}

bool bvh_check(const bvh_inst_t *in)
{
    if (!in || !in->mesh || in->e < 0 || in->e > 62 || in->fe < 0 || in->fe > 62)
        return false;
    for (int j = 0; j < 3; j++)
        for (int k = 0; k < 3; k++)
            if (in->m[j][k] >= (1 << 30) || in->m[j][k] <= -(1 << 30) || in->f[j][k] >= (1 << 30) ||
                in->f[j][k] <= -(1 << 30))
                return false;
    if (geom_check_point(in->t) != FXRT_OK)
        return false;
    const bvh_mesh_t *m = in->mesh;
    if (!m->v || !m->node || m->n_nodes == 0 || m->n_triangles == 0 || m->n_vertices == 0 ||
        (m->tri16 ? m->tri32 != NULL || m->n_vertices > 65536u : m->tri32 == NULL))
        return false;
    for (uint32_t i = 0; i < m->n_vertices; i++)
        for (int j = 0; j < 3; j++)
            if (m->v[i][j] < -BVH_Q_MAX || (m->vn && m->vn[i][0] == 0 && m->vn[i][1] == 0 && m->vn[i][2] == 0))
                return false;
    /* depth first, left child first: the leaves' triangles must follow
     * one another from 0, each once */
    uint32_t stack[BVH_MAX_DEPTH + 1], next = 0;
    uint8_t depth[BVH_MAX_DEPTH + 1];
    int sp = 0;
    stack[sp] = 0;
    depth[sp++] = 0;
    while (sp > 0) {
        sp--;
        uint32_t ni = stack[sp];
        uint8_t dp = depth[sp];
        const bvh_node_t *nd = &m->node[ni];
        for (int j = 0; j < 3; j++)
            if (nd->lo[j] > nd->hi[j])
                return false;
        uint32_t cnt = nd->link & 15u, first = nd->link >> 4;
        if (cnt) {
            if (first != next || cnt > m->n_triangles - next)
                return false;
            for (uint32_t i = first; i < first + cnt; i++) {
                uint32_t vi[3];
                bvh_tri(m, i, vi);
                for (int k = 0; k < 3; k++)
                    if (vi[k] >= m->n_vertices || !bvh_in_box(nd, m->v[vi[k]]))
                        return false;
            }
            next += cnt;
            continue;
        }
        if (first <= ni || first >= m->n_nodes - 1 || dp >= BVH_MAX_DEPTH)
            return false;
        for (uint32_t c = first; c <= first + 1; c++)
            for (int j = 0; j < 3; j++)
                if (m->node[c].lo[j] < nd->lo[j] || m->node[c].hi[j] > nd->hi[j])
                    return false;
        stack[sp] = first + 1; /* right after left */
        depth[sp++] = (uint8_t)(dp + 1);
        stack[sp] = first;
        depth[sp++] = (uint8_t)(dp + 1);
    }
    return next == m->n_triangles;
}
#endif
