/* shade: the lighting model (see shade.h). */
#include "light/shade_sum.h"

#if FXRT_MAX_LIGHTS > 0

/* What only the specular term needs (FXRT_PHONG): its code, or nothing. */
#if FXRT_PHONG
#define SHADE_IF_PHONG(...) __VA_ARGS__
#else
#define SHADE_IF_PHONG(...)
#endif

/* Colour arithmetic of the light sum. Every term is at most 255 (1/255
 * units) times fractions <= 1, and the sum of the ambient term and two
 * terms per light stays below 255 (1 + 2 FXRT_MAX_LIGHTS) = 4335, far
 * inside Q16.16: the products are fx_mul's rounding without its
 * saturation checks, and the sums plain additions. Identical values. */
static inline color_t shade_filter(color_t a, color_t f)
{
    return color_make(num_mul_fits(a.r, f.r), num_mul_fits(a.g, f.g), num_mul_fits(a.b, f.b));
}
/* c + a * s */
static inline color_t shade_madd(color_t c, color_t a, num_t s)
{
    return color_make(num_add_fits(c.r, num_mul_fits(a.r, s)), num_add_fits(c.g, num_mul_fits(a.g, s)),
                      num_add_fits(c.b, num_mul_fits(a.b, s)));
}

void shade_consts(const world_t *w, const geom_common_t *obj, shade_k_t *k)
{
    k->ambient = shade_filter(obj->color, w->ambient);
    SHADE_IF_CULL(k->cull = NULL;)
    for (uint8_t i = 0; i < w->n_lights; i++) {
        k->kd[i] = shade_filter(obj->color, w->lights[i].color);
        /* The specular colour (fractions) in 1/255 units: exact in Q16.16. */
        SHADE_IF_PHONG(color_t s = obj->mat.specular;
                       color_t s255 = color_make(num_mul_int(s.r, 255), num_mul_int(s.g, 255), num_mul_int(s.b, 255));
                       k->ks[i] = shade_filter(s255, w->lights[i].color);)
    }
}

/* Spot cone: (-l) . s >= cos(angle) for l = v / |v|, compared as
 * (-v) . s >= cos(angle) |v|: cosines, no acos, and no rounding of l. */
static bool shade_in_cone(const light_t *L, vec3_t v, num_t dist)
{
#if FXRT_NUMBER == FXRT_Q16
    /* Q16.16 x Q2.30 products (< 2^61 each), exact in int64. */
    int64_t lhs = -(fx_smul32(v.x, L->axis30[0]) + fx_smul32(v.y, L->axis30[1]) + fx_smul32(v.z, L->axis30[2]));
    return lhs >= fx_smul32(dist, L->cos30);
#else
    return vec3_dotw(vec3_neg(v), L->dir) >= numw_mul(L->cos_angle, dist);
#endif
}

#if FXRT_NUMBER == FXRT_Q16
/* a b for a, b < 2^64, as 128 bits (hi:lo): four 32x32->64 products.
 * fx128_mul's unsigned core, inline: with fx128_sqr and fx128_mul (out of
 * line, signed) the early spot test below costs as much as the
 * normalisation it saves (course-lambert-spot on the M3: 847.2 -> 899.3
 * instructions per pixel, against 897 without the test). */
static inline void shade_umul64(uint64_t a, uint64_t b, uint64_t *hi, uint64_t *lo)
{
    uint32_t a0 = (uint32_t)a, a1 = (uint32_t)(a >> 32), b0 = (uint32_t)b, b1 = (uint32_t)(b >> 32);
    uint64_t p00 = fx_umul32(a0, b0), p01 = fx_umul32(a0, b1), p10 = fx_umul32(a1, b0);
    uint64_t mid = (p00 >> 32) + (uint32_t)p01 + (uint32_t)p10; /* < 3 2^32 */
    *lo = (mid << 32) | (uint32_t)p00;
    *hi = fx_umul32(a1, b1) + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
}

/* (shade.h) Is p surely outside spot L's cone, v = position - p? Decided
 * without normalising v, and only where shade_in_cone with the distance
 * from fx_normalize3_len (within 0.5 LSB + 2^-24 |v| of the exact m = |v|)
 * would say outside too, so the frame is the same; a point close to the
 * cone's edge is left to that test. With lhs = (-v) . s (Q18.46, s in
 * Q2.30) and c = cos(angle) in Q2.30:
 *  - lhs < 0: outside (c dist >= 0);
 *  - else, with x = lhs + c and x' = x + x / 2^22 + 1 > x (1 + 2^-22):
 *    x'^2 < c^2 m^2 gives x < c m (1 - 2^-23), so lhs < c (m - 1 - 2^-23 m)
 *    <= c dist: outside. Both sides are exact 128-bit products.
 * Only for |v_i| < 2^30 LSB (16384; then v did not saturate, and m^2 <
 * 2^62); a farther light takes the full test. */
bool shade_spot_surely_out(const light_t *L, vec3_t v)
{
    const fx_t lim = (fx_t)1 << 30;
    if (v.x >= lim || v.x <= -lim || v.y >= lim || v.y <= -lim || v.z >= lim || v.z <= -lim)
        return false;
    int64_t lhs = -fx_smlal32(fx_smlal32(fx_smul32(v.x, L->axis30[0]), v.y, L->axis30[1]), v.z, L->axis30[2]);
    if (lhs < 0)
        return true;
    uint64_t x = (uint64_t)lhs + (uint64_t)L->cos30; /* < 3 2^60 + 2^30 */
    x += (x >> 22) + 1;
    uint64_t m2 = (uint64_t)fx_smlal32(fx_smlal32(fx_smul32(v.x, v.x), v.y, v.y), v.z, v.z); /* < 3 2^60 */
    uint64_t ahi, alo, bhi, blo;
    shade_umul64(x, x, &ahi, &alo);
    shade_umul64(fx_umul32((uint32_t)L->cos30, (uint32_t)L->cos30), m2, &bhi, &blo);
    return ahi < bhi || (ahi == bhi && alo < blo);
}

/* A point or spot light can be farther from a hit point than Q16.16
 * holds: the point up to 32767 from the origin (a plane seen far away),
 * the light up to FXRT_COORD_LIMIT. Then v = pos - p saturates (a
 * component beyond 32767) or fx_normalize3_len saturates its length, and
 * neither l nor the distance is right. Any such case has a computed
 * distance of at least SHADE_FAR_DIST (shade.h), and so does a light just
 * inside the range, for which this path is right too. shade_light_far
 * recomputes l from a quarter of the exact 64-bit difference (|v| / 4 <
 * 17,737: it fits) and makes a spot's cone test with that quarter and
 * its length; it returns l, or the zero vector when the spot does not
 * reach p. The caller then passes the distance SHADE_FAR_DIST, and
 * shadow_blocked casts the shadow ray from the light's end of the
 * segment (light/shadow.c). Rare, so out of line. */
static __attribute__((noinline)) vec3_t shade_light_far(const light_t *L, const vec3_t *p)
{
    vec3_t pos = L->position, l = vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    vec3_t v = vec3_make((fx_t)(((int64_t)pos.x - p->x) / 4), (fx_t)(((int64_t)pos.y - p->y) / 4),
                         (fx_t)(((int64_t)pos.z - p->z) / 4));
    num_t len;
    (void)vec3_unit_len(v, &l, &len); /* |v| > 8191: not zero */
    if (L->kind == LIGHT_SPOT && !shade_in_cone(L, v, len))
        return vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    return l;
}

/* (shade.h) Spot L and a block of a plane's run whose segment runs from
 * pa to pb. Every pixel of the block has its exact hit point on the
 * segment between the exact points of pa's and pb's pixels (the camera
 * ray is linear in the column and its plane denominator keeps one sign
 * over the run), so every computed hit point q of the block lies within
 * R = |pb - pa| / 2 + 3 e of the midpoint M of pa and pb, e the computed
 * points' error. With v = L - q, lhs = (-v) . s and G = c |v| - lhs (s
 * the cone's axis as the light keeps it, c its cosine), the pixel's cone
 * test says outside where G exceeds the test's own rounding. For q = M +
 * w, |w| <= R: lhs_q = lhs_M + w . s exactly, and |v_q| >= (q - L) . u
 * with u = (M - L) / |v_M| (Cauchy-Schwarz), so
 *   G_q >= G_M - w . (s - c u) >= G_M - R K,
 *   K^2 = |s - c u|^2 = |s|^2 - c^2 + 2 c G_M / |v_M|,
 * which is small near the cone's edge (K -> sin(angle) for a unit s):
 * the block is outside where G_M - R K exceeds the rounding's bound.
 *
 * Q16.16 (lengths in LSB, doubled: V = 2 v_M exact, |V| < 2^30 sqrt 3;
 * s and c in Q2.30): shade_flat_point's coordinates are within 0.5 +
 * 2^-29 |t r_i| <= 4.5 LSB of the exact point (|t r_i| < 2^31), so e <=
 * 4.5 sqrt 3 < 8 and 2 R <= R2 = |pb - pa|_1 + 256. The pixel's distance
 * is within 2^-24 |v| + 0.5 of |v| (fx_inv3, fx_normalize3_len), so the
 * pixel is outside where 2 G_q > 2^6 |V_q| + 2^30 (units 2^-30 LSB), and
 * |V_q| <= |V| + R2. With m = floor(sqrt(|V|^2)) (exact) and G2 = c |V|
 * + (V . s) = 2 G_M: G2 >= c m + V . s = g; G2 / |V| <= (c (m + 1) + V .
 * s) / m rounded up = q; |s|^2 <= 2^60 + 2^33. So the block is outside
 * where g - S > 0 and (g - S)^2 > R2^2 (2^60 + 2^33 - c^2 + 2 c q), S =
 * 2^6 (m + 1 + R2) + 2^30: exact 128-bit products. Only for |v_i| <
 * 2^29 at both ends (no point of the block takes the far path; every
 * value within 2^62.5), m >= 2^10 (q < 2^31.1) and c > 0.
 *
 * Float and double: the same test in their arithmetic, with R = |pb -
 * pa|_1 / 2 + 2^-14 (|pa|_1 + |pb|_1 + |o|_1 + |L|_1 + 1) and a margin
 * of 2^-14 (|lhs| + c |v_M| + R (1 + K) + 1) on G: against roundings near
 * 2^-18 relative at most in float (the point and the ray's sum, whose
 * terms can cancel in a wide view; the roots, the products) and far less
 * in double. */
bool shade_spot_block_out(const light_t *L, const vec3_t *o, const vec3_t *pa, const vec3_t *pb, num_t slack)
{
    (void)o;
    const int64_t lim = (int64_t)1 << 29;
    if (L->kind != LIGHT_SPOT || L->cos30 <= 0)
        return false;
    const fx_t P[3] = {L->position.x, L->position.y, L->position.z}, A[3] = {pa->x, pa->y, pa->z},
               B[3] = {pb->x, pb->y, pb->z};
    int32_t V[3];
    int64_t dl1 = 0;
    for (int j = 0; j < 3; j++) {
        int64_t va = (int64_t)P[j] - A[j], vb = (int64_t)P[j] - B[j], dj = (int64_t)B[j] - A[j];
        if (va >= lim || va <= -lim || vb >= lim || vb <= -lim)
            return false;
        V[j] = (int32_t)(va + vb);
        dl1 += dj < 0 ? -dj : dj; /* < 2^30 */
    }
    if (slack < 0 || slack >= (fx_t)1 << 28)
        return false;
    int64_t r2 = dl1 + 256 + 2 * (int64_t)slack;
    int64_t vs = fx_smlal32(fx_smlal32(fx_smul32(V[0], L->axis30[0]), V[1], L->axis30[1]), V[2], L->axis30[2]);
    uint64_t m2 = (uint64_t)fx_smlal32(fx_smlal32(fx_smul32(V[0], V[0]), V[1], V[1]), V[2], V[2]); /* < 3 2^60 */
    uint32_t m = fx_isqrt64(m2);
    if (m < 1024 || r2 >= lim)
        return false;
    int64_t c = L->cos30;
    int64_t g = c * m + vs - ((int64_t)(m + 1 + r2) << 6) - ((int64_t)1 << 30); /* g - S, |.| < 2^62.3 */
    if (g <= 0)
        return false;
    uint32_t q = fx_udiv64_32((uint64_t)(c * (m + 1) + vs), m) + 1u;
    uint64_t k2 = ((uint64_t)1 << 60) + ((uint64_t)1 << 33) - fx_umul32((uint32_t)c, (uint32_t)c) +
                  (fx_umul32((uint32_t)c, q) << 1); /* < 2^62.5 */
    uint64_t ahi, alo, bhi, blo;
    shade_umul64((uint64_t)g, (uint64_t)g, &ahi, &alo);
    shade_umul64((uint64_t)(r2 * r2), k2, &bhi, &blo);
    return ahi > bhi || (ahi == bhi && alo > blo);
}

/* A bound on how far the hit point of shade_flat_k's unit-direction path
 * (d normalised, then t = N / (d . n) and o + t d: in float and double a
 * plane that is not Lambert; never in Q16.16, where a Phong plane takes
 * shade_flat_point's point too) lies from the exact hit of the exact ray,
 * in num units, from the
 * point p, rn = d . n (d not normalised) that shade_flat_point gives for
 * the same ray; negative where the ray grazes the plane (|cos| below
 * 2^-8) or the values are out of range: no block there. With u the exact
 * unit direction, d' = u + eps the normalised one (|eps| <= 0.873 LSB in
 * Q16.16: fx_normalize3's 0.504 per component; below 2^-22 relative in
 * float) and a = u . n: the exact hit along d' lies within 2 |eps| t /
 * (|a| - |eps|) of the one along u (t = |p - o|), and its rounding (t's
 * quotient and the product) adds far less. |a| >= |rn| / |d|_1, so
 * float and double take 2^-18 |p - o|_1 |d|_1 / |rn|. Along a run |a| has no interior minimum
 * (the cosine of the angle to n along an arc of directions that keeps one
 * side), so the larger of a block's two ends bounds its pixels. */
static num_t shade_unit_point_slack(const ray_t *ray, const vec3_t *p, numw_t rn)
{
    (void)ray, (void)p, (void)rn;
    return NUM_ZERO; /* (not called: shade_flat_spot_blocks' unit is false in Q16.16) */
}
#else
/* (shade.h) shade_spot_block_out in float and double: the Q16.16 comment
 * above has the proof and this arithmetic's margins. */
bool shade_spot_block_out(const light_t *L, const vec3_t *o, const vec3_t *pa, const vec3_t *pb, num_t slack)
{
    if (L->kind != LIGHT_SPOT || !(L->cos_angle > NUM_ZERO))
        return false;
    const num_t eps = (num_t)(1.0 / 16384);
    vec3_t m = vec3_scale(vec3_add(*pa, *pb), (num_t)0.5), v = vec3_sub(L->position, m), dp = vec3_sub(*pb, *pa);
    num_t s = vec3_l1(*pa) + vec3_l1(*pb) + vec3_l1(*o) + vec3_l1(L->position) + NUM_ONE;
    if (!(slack >= NUM_ZERO))
        return false;
    num_t r = vec3_l1(dp) * (num_t)0.5 + eps * s + slack;
    num_t dist = num_sqrt(vec3_dot(v, v));
    if (!(dist > NUM_ZERO))
        return false;
    num_t lhs = -vec3_dot(v, L->dir), c = L->cos_angle, g = c * dist - lhs;
    num_t k2 = vec3_dot(L->dir, L->dir) - c * c + (c + c) * g / dist;
    num_t k = num_sqrt(k2 > NUM_ZERO ? k2 : NUM_ZERO);
    return g - r * k - eps * (num_abs(lhs) + c * dist + r * (NUM_ONE + k) + NUM_ONE) > NUM_ZERO;
}

/* (float and double: shade_unit_point_slack, the Q16.16 comment above) */
static num_t shade_unit_point_slack(const ray_t *ray, const vec3_t *p, numw_t rn)
{
    num_t d1 = vec3_l1(ray->d), t1 = vec3_l1(vec3_sub(*p, ray->o)), arn = num_abs(rn);
    if (!(arn >= d1 * (num_t)(1.0 / 256)))
        return -NUM_ONE;
    return t1 * d1 / arn * (num_t)(1.0 / 262144);
}
#endif


color_t shade_point(const world_t *w, geom_kind_t kind, uint16_t index GEOM_PART_PARAM, vec3_t p, vec3_t n_geo,
                    vec3_t d, uint8_t *mask)
{
    return shade_point_k(w, kind, index GEOM_PART_ARG(part), p, n_geo, d, NULL, mask);
}


/* shade_sum without per-frame constants (the ray caster, arbitrary rays):
 * they are computed here, off the renderer's stack path. It calls
 * shade_lights, not shade_sum: no cycle in the call graph
 * (tests/norecurse.sh). */
__attribute__((noinline)) color_t shade_sum_own(const world_t *w, const geom_common_t *obj, geom_kind_t kind,
                                                      uint16_t index GEOM_PART_PARAM, const vec3_t *p,
                                                      const vec3_t *n_geo, int8_t facing, const vec3_t *d,
                                                      uint8_t *mask)
{
    shade_k_t own;
    shade_consts(w, obj, &own);
    return shade_lights_of(w, obj, kind, index GEOM_PART_ARG(part), p, n_geo, facing, d, &own, mask);
}

/* Phong's r = 2 (n . l) n - l for unit n and l, ndl their product rounded
 * (0 < ndl <= 1: 2 ndl n fits without saturation): shade_specular's, and
 * shade_flat_phong_span's, the same value. */
static inline vec3_t shade_phong_r(const vec3_t *n, const vec3_t *l, num_t ndl)
{
    return vec3_sub(vec3_scale_unit_small(*n, num_add(ndl, ndl)), *l);
}

#if FXRT_PHONG
/* c plus Phong's term c_s (.) c_l (ks) max(0, r . e)^k for a = -(r . d)
 * (r . e, e = -d): x = a / |d| along a raw direction d (raw), x = a along
 * a unit one. In Q16.16 along a raw d, made only where the term may not be
 * 0: a > 0, and not where numw_pow_zero_at proves x^k 0 (most of a Phong
 * plane, away from its highlight: no root there); |a| < 2^49 (fx_mant64's
 * bound). Float and double along a raw d (the plane runs): a / |d|, the
 * root only where a > 0. */
static inline __attribute__((always_inline)) color_t shade_specular_at(color_t c, numw_t a, const vec3_t *d,
                                                                       const color_t *ks, uint16_t exponent, bool raw)
{
    if (a <= 0)
        return c;
    if (raw && NUM_EXACT) {
        num_t dv[3] = {d->x, d->y, d->z};
        num_inv3_t q;
        if (numw_pow_zero_at(a, vec3_dotw(*d, *d), exponent))
            return c;
        FXRT_COUNT(raw_roots);
        if (!num_inv3_only(dv, &q))
            return c;
        a = numw_from(num_inv3_mul(&q, numw_mant(a)));
    } else if (raw) {
        FXRT_COUNT(raw_roots);
        a = a / numw_sqrt(vec3_dotw(*d, *d)); /* (float and double; |d| > 0: a camera ray) */
    }
    return shade_madd(c, *ks, numw_pow_int(a, exponent));
}

/* c plus Phong's term for the light at l (shade_specular_at), r made from
 * n, l and ndl. Out of line on the M0 only (FXRT_INLINE_WIDE): there its
 * temporaries, inlined, made shade_lights' frame (the deepest on the
 * shading path) larger than the 16 KB boards' stack margin allows with
 * shadow-ray culling. Not cloned either: GCC's copy with raw constant
 * (float and double, where it is always false) took the M0's double build
 * 32 bytes deeper (course-phong-directional on the micro:bit: 1,552 of
 * 2,048 bytes, over FXRT_STACK_MARGIN; 1,528 without the copy). */
static FXRT_INLINE_WIDE FXRT_NOCLONE_WIDE color_t shade_specular(color_t c, const vec3_t *n, const vec3_t *l, const vec3_t *d, num_t ndl,
                                                const color_t *ks, uint16_t exponent, bool raw)
{
    vec3_t r = shade_phong_r(n, l, ndl);
    numw_t a = numw_neg_fits(raw ? vec3_dotw(r, *d) : vec3_dotw_units(r, *d)); /* r . e = -(r . d), e = -d */
    return shade_specular_at(c, a, d, ks, exponent, raw);
}
#endif

/* Where light L comes from, seen from p (shade_lights and
 * shade_lights_plane). SHADE_DARK: it does not reach p (it is at p, or p
 * lies outside a spot's cone). SHADE_DIR: *l is the unit direction to
 * the light and *dist the distance (NUM_MAX for a directional light).
 * SHADE_INV, only where iv is not NULL (a Lambert plane): *l is not made;
 * iv holds 1 / |v| for v = L - p, va holds v, and *dist = |v|
 * (shade_light_unit makes l from them). Inlined: with iv NULL, what
 * shade_lights always did. */
enum { SHADE_DARK, SHADE_DIR, SHADE_INV };
static inline __attribute__((always_inline)) int shade_light_dir(const light_t *L, const vec3_t *p, vec3_t *l, num_t *dist,
                                                                 num_inv3_t *iv, num_t va[3])
{
    *dist = NUM_MAX;
    if (L->kind == LIGHT_DIRECTIONAL) {
        *l = L->dir; /* normalised once, in world_add_light */
        va[0] = va[1] = va[2] = NUM_ZERO; /* (unused; shade_lights_plane takes these lights itself) */
        return SHADE_DIR;
    }
    vec3_t v = vec3_sub(L->position, *p);
    va[0] = v.x, va[1] = v.y, va[2] = v.z;
    /* Spot: (-l) . s >= cos(angle) with l = v / |v|, compared as
     * (-v) . s >= cos(angle) |v| (no rounding of l in the test). */
#if FXRT_NUMBER == FXRT_Q16
    /* One inverse square root gives l and |v| (fx_normalize3_len), or
     * 1 / |v| and |v| (fx_inv3); a point clearly outside a spot's cone
     * needs neither. Where the core has UMULL (M3, M4F) the early test's
     * products cost less than the normalisation: -5 % on the spot scenes;
     * the M0 pays +5 % for them, so it goes straight to the full test. */
    if (FX_HAVE_UMULL && L->kind == LIGHT_SPOT && shade_spot_surely_out(L, v))
        return SHADE_DARK; /* outside the cone */
    FXRT_COUNT(l_normalised);
    if (iv ? !num_inv3(va, iv, dist) : !num_normalize3_len(va, dist))
        return SHADE_DARK; /* the light is at p: no direction, no light */
    if (__builtin_expect(*dist >= SHADE_FAR_DIST, 0)) {
        *l = shade_light_far(L, p);
        if (l->x == NUM_ZERO && l->y == NUM_ZERO && l->z == NUM_ZERO)
            return SHADE_DARK; /* outside the cone */
        *dist = SHADE_FAR_DIST;
        FXRT_COUNT(l_units);
        return SHADE_DIR;
    }
    if (L->kind == LIGHT_SPOT && !shade_in_cone(L, v, *dist))
        return SHADE_DARK; /* outside the cone */
    if (iv)
        return SHADE_INV;
    FXRT_COUNT(l_units);
    *l = vec3_make(va[0], va[1], va[2]);
#else
    /* |v| first: a point outside a spot's cone costs no division. The
     * light at p (|v|^2 not above 0: v is zero, and so is |v|) has no
     * direction and gives no light, inside a cone or not. */
    numw_t v2 = vec3_dotw(v, v);
    if (!(v2 > 0))
        return SHADE_DARK;
    *dist = numw_sqrt(v2); /* vec3_len(v), above 0 */
    if (L->kind == LIGHT_SPOT && !shade_in_cone(L, v, *dist))
        return SHADE_DARK; /* outside the cone */
    FXRT_COUNT(l_normalised);
    num_t inv = NUM_ONE / *dist; /* vec3_normalize's value, without its second root (num_div's: |v| > 0) */
    if (iv) {
        iv->inv = inv;
        return SHADE_INV;
    }
    FXRT_COUNT(l_units);
    *l = vec3_scale(v, inv);
#endif
    return SHADE_DIR;
}

/* Plane `index`'s entries of the frame's tables (shade.h), from its
 * constants k, or NULL where the frame keeps none. */
static inline const shade_plane_light_t *shade_plane_entries(const shade_k_t *k, uint16_t index)
{
    SHADE_IF_CULL(if (SHADE_HEIGHTS && k && k->cull) return k->cull->pl + (size_t)index * FXRT_MAX_LIGHTS;)
    (void)k, (void)index;
    return NULL;
}

/* Is light i (L) blocked from p by an object (shadow_blocked), where the
 * frame's tables do not already say it is not? pls: the object's entries
 * of the frame's tables, a plane's (NULL: none), whose row masks say so.
 * For SHADE_INV (iv not NULL) the unit direction l is made here first,
 * for the shadow ray. */
static inline __attribute__((always_inline)) bool shade_shadowed(const world_t *w, geom_kind_t kind,
                                                                 uint16_t index GEOM_PART_PARAM,
                                                                 const geom_common_t *obj, bool inside,
                                                                 const vec3_t *p, const light_t *L, unsigned i,
                                                                 vec3_t *l, num_t dist, const shade_k_t *k,
                                                                 const shade_plane_light_t *pls, const num_inv3_t *iv,
                                                                 num_t va[3])
{
#if FXRT_SHADOWS
    uint32_t skip = SHADOW_ROWS && pls ? pls[i].row : 0; /* a plane's pixel: its row's mask (shade.h, shadow rows) */
    if (!L->shadows || (skip & SHADOW_ROW_CLEAR && (dist < SHADE_FAR_DIST || L->kind == LIGHT_DIRECTIONAL)))
        return false;
    const shadow_cull_row_t *cull = NULL;
    const shadow_edge_t *edges = NULL;
    SHADE_IF_CULL(if (k && k->cull) cull = k->cull->cull + (size_t)i * SHADOW_CULL_SLOTS,
                  edges = SHADOW_EDGES ? k->cull->edges + (size_t)i * FXRT_MAX_TRIANGLES : NULL;)
    if (iv) {
        FXRT_COUNT(l_units);
        num_inv3_unit(iv, va, va);
        *l = vec3_make(va[0], va[1], va[2]);
    }
    /* In float and double a copy of p: the callers' point does not
     * escape, and stays in registers where no shadow ray is cast (matched
     * scene, M4F float: -7 instructions per pixel; Q16.16 pays for the
     * copy: M3 +1.9, micro:bit +25). Not on Armv6-M, whose 2 KB stack
     * has no room for it (micro:bit, double: 32 bytes deeper). */
    vec3_t pc = *p;
    return shadow_blocked(w, kind, index GEOM_PART_ARG(part), obj, inside,
                          NUM_EXACT || FXRT_PORT_SMALL_ISA ? p : &pc, L, l, dist, cull, skip, edges);
#else
    (void)w, (void)kind, (void)index, (void)obj, (void)inside, (void)p, (void)L, (void)i, (void)l, (void)dist,
        (void)k, (void)pls, (void)iv, (void)va;
    FXRT_IF_MODEL((void)part;)
    return false;
#endif
}

/* The light loop of shade_sum (k not NULL when the material is lit and
 * not transparent). */
color_t shade_lights(const world_t *w, const geom_common_t *obj, geom_kind_t kind, uint16_t index GEOM_PART_PARAM,
                     const vec3_t *pp, const vec3_t *n_geo_p, int8_t facing, const vec3_t *dp, const shade_k_t *k,
                     uint8_t *mask)
{
    /* FXRT_BOUND_NO_LIGHT_SUM: a measurement (core/fxrt_config.h), no
     * light sum at all. */
    if (FXRT_BOUND_NO_LIGHT_SUM && !mask && obj->mat.kind != MATERIAL_TRANSPARENT)
        return obj->mat.kind == MATERIAL_FLAT || !k ? obj->color : k->ambient;
    vec3_t n_geo = *n_geo_p, d = *dp;
    const material_t *m = &obj->mat;
    bool lit = m->kind != MATERIAL_FLAT;
    bool clear = m->kind == MATERIAL_TRANSPARENT;
    /* Two-sided: n faces the incoming ray (d . n_geo <= 0), from the
     * caller's facing where it knows it. */
    bool inside = facing == SHADE_FACING_UNKNOWN ? vec3_dotw_units(d, n_geo) > 0 : (facing & 1) != 0;
    vec3_t n = inside ? vec3_neg_unit(n_geo) : n_geo;
    /* A smooth triangle (scene/smooth.c): the interpolated normal n_s,
     * turned towards the ray on its own; the flat face's normal, turned
     * towards the ray (n_face), keeps a light with shadows on that lies
     * behind the face from p (the terminator: the face blocks it). */
    FXRT_IF_SMOOTH(vec3_t n_face = n; vec3_t ns;
                   bool smooth = kind == GEOM_TRIANGLE && w->triangles[index].smooth &&
                                 geom_smooth_normal(&w->triangles[index], *pp, &ns);
                   if (smooth) n = vec3_dotw_units(d, ns) > 0 ? vec3_neg_unit(ns) : ns;)
    /* A smooth model: the same, with the normal its surface gave
     * (scene/model.c) and its triangle's winding normal as the face's. */
    FXRT_IF_MODEL(vec3_t n_wind = n; bool msmooth = part && part->smooth; (void)n_wind; /* (shadows only) */
                  if (msmooth) n = vec3_dotw_units(d, part->ns) > 0 ? vec3_neg_unit(part->ns) : part->ns;)
    color_t c = clear ? color_make(NUM_ZERO, NUM_ZERO, NUM_ZERO) : lit ? k->ambient : obj->color;
    /* a Phong plane or triangle in Q16.16 seen along a raw d (shade_specular) */
    bool raw = NUM_EXACT && FXRT_PHONG && facing > 1 && m->kind == MATERIAL_PHONG;
    (void)raw;
    unsigned bits = 0;
    (void)kind, (void)index; /* only shadow rays need to know the object */
    const shade_plane_light_t *pls = kind == GEOM_PLANE ? shade_plane_entries(k, index) : NULL;
    const light_t *L = w->lights;
    for (unsigned i = 0, n_lights = w->n_lights; i < n_lights; i++, L++) {
        vec3_t l;
        num_t dist, va[3];
        if (shade_light_dir(L, pp, &l, &dist, NULL, va) == SHADE_DARK)
            continue;
        numw_t ndlw = vec3_dotw_units(n, l);
        if (ndlw <= 0)
            continue; /* behind the surface: no shadow ray either */
        if (FXRT_SHADOWS) {
            FXRT_IF_SMOOTH(if (smooth && L->shadows && vec3_dotw_units(n_face, l) <= 0) continue;) /* the terminator */
            FXRT_IF_MODEL(if (msmooth && L->shadows && vec3_dotw_units(n_wind, l) <= 0) continue;)
        }
        if (shade_shadowed(w, kind, index GEOM_PART_ARG(part), obj, inside, pp, L, i, &l, dist, k, pls, NULL, va))
            continue;
        bits |= 1u << i;
        if (!lit || clear)
            continue;
        num_t ndl = numw_round_fits(ndlw); /* n, l unit: |n . l| < 2, no saturation */
        c = shade_madd(c, k->kd[i], ndl);
        SHADE_IF_PHONG(if (m->kind == MATERIAL_PHONG || m->kind == MATERIAL_REFLECTIVE) c =
                           shade_specular(c, &n, &l, &d, ndl, &k->ks[i], m->exponent, raw);)
    }
    if (mask)
        *mask = (uint8_t)bits;
    return c;
}

/* For plane `index` (point a, unit normal n) and light L, as
 * shade_height_t: a point or spot light's h = n . (L - a), as numw_mant
 * (in Q16.16 exact: each dot product lies below 2^50, no saturation; in
 * float and double as written). On any point p of the plane
 * n . (L - p) = h, so the light sum's n . l there is h / |L - p|
 * (shade_lights_plane). A directional light's n . l is the same at every
 * point: kept as numw_sticky, which gives either side's value. */
shade_height_t shade_plane_height(const world_t *w, uint16_t index, const light_t *L)
{
    shade_height_t r = {0};
    FXRT_IF_PLANE(const geom_plane_t *pl = &w->planes[index];
                  if (L->kind == LIGHT_DIRECTIONAL) {
                      r.ndl = numw_sticky(vec3_dotw_units(pl->n, L->dir));
                      return r;
                  } r.h = numw_mant(NUM_EXACT ? numw_sub_exact(vec3_dotw_unit(L->position, pl->n),
                                                               vec3_dotw_unit(pl->a, pl->n))
                                              : vec3_dotw_unit(vec3_sub(L->position, pl->a), pl->n));)
    (void)w, (void)index, (void)L;
    return r;
}

void shade_plane_heights(const world_t *w, shadow_table_t *t)
{
    FXRT_IF_PLANE(for (uint16_t j = 0; SHADE_HEIGHTS && j < w->n_planes; j++) for (uint8_t i = 0; i < w->n_lights; i++)
                      t->pl[(size_t)j * FXRT_MAX_LIGHTS + i].h = shade_plane_height(w, j, &w->lights[i]);)
    (void)w, (void)t;
}

/* shade_phong_block_zero's factor s = sqrt(2 / (1 + c')) for exponent k
 * (once per call of shade_flat_phong_blocks: not kept in the frame's
 * state, which the micro:bit's RAM holds), rounded up: c' = c - 2^-8 in Q16.16, where the term
 * is 0 for x <= c = 1 - NUM_POW_ZERO_K / k (numw_pow_int; c = 0 for k <=
 * NUM_POW_ZERO_K, where only x <= 0 gives 0), and c' = -2^-12 in float and
 * double, where only x <= 0 does. */
static num_t shade_phong_factor(uint16_t k)
{
    num_t c = NUM_EXACT && k > NUM_POW_ZERO_K ? num_sub(NUM_ONE, num_div(num_from_int(NUM_POW_ZERO_K), num_from_int(k)))
                                               : NUM_ZERO;
    c = num_sub(c, NUM_EXACT ? NUM(1.0 / 256) : NUM(1.0 / 4096));
    num_t s = num_sqrt(num_div(NUM(2), num_add(NUM_ONE, c)));
    return num_add(s, NUM_EXACT ? (num_t)4 : num_mul(s, NUM(1.0 / 1048576)));
}

void shade_flat_prep(shade_flat_t *f, bool all_directional, bool all_spots, bool no_directional, const shade_k_t *k)
{
    bool plane = f->kind == GEOM_PLANE && k;
    uint8_t m = f->obj->mat.kind;
    bool phong_point = FXRT_PHONG && plane && no_directional && m == MATERIAL_PHONG;
    f->pls = plane ? shade_plane_entries(k, f->index) : NULL;
    f->flags = (uint8_t)((plane && m == MATERIAL_LAMBERT ? SHADE_FLAT_LAMBERT : 0) |
                         (plane && all_directional ? SHADE_FLAT_DIRECTIONAL : 0) |
                         (FXRT_PHONG && plane && all_directional && m == MATERIAL_PHONG &&
                                  (!NUM_EXACT || f->obj->mat.exponent > NUM_POW_ZERO_K)
                              ? SHADE_FLAT_PHONG_DIR
                              : 0) |
                         (plane && all_spots && (m == MATERIAL_LAMBERT || m == MATERIAL_PHONG) ? SHADE_FLAT_SPOTS : 0) |
                         (phong_point ? SHADE_FLAT_PHONG_POINT : 0));
}

/* shade_lights for Lambert or Phong plane `index` (obj) with constants k;
 * pls: its entries of the frame's tables (NULL: none); d: the ray's
 * direction, raw or unit (shade_specular_at), read for a Phong plane only
 * (phong: the caller knows it is one).
 * Lambert's term needs only n . l, and for a point or spot light that is
 * h / |v|, v = L - p, with h = n . (L - a) the same at every point of the
 * plane (shade_plane_height; once per frame in the frame's tables, where
 * it has them): one inverse square root and one product (fx_inv3,
 * fx_inv3_mul) instead of the unit vector l and a dot product; l is made
 * only for a shadow ray. A Phong plane's term needs l (Phong's r): made
 * from 1 / |v| too (fx_inv3_unit), before the shadow ray, which takes
 * it. */
static inline __attribute__((always_inline)) color_t shade_plane_sum(const world_t *w, const geom_common_t *obj,
                                                                     uint16_t index, const shade_k_t *k,
                                                                     const shade_plane_light_t *pls, const vec3_t *pp,
                                                                     bool inside, const vec3_t *d, bool raw,
                                                                     bool phong, uint8_t *mask)
{
    if (FXRT_BOUND_NO_LIGHT_SUM && !mask)
        return k->ambient;
    color_t c = k->ambient;
    unsigned bits = 0, n = w->n_lights;
    const light_t *L = w->lights;
    phong = FXRT_PHONG && phong;
    vec3_t nt = vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO); /* Phong: n turned to the ray's side */
    (void)d, (void)raw, (void)nt; /* (FXRT_PHONG 0) */
    FXRT_IF_PLANE(if (phong) nt = inside ? vec3_neg_unit(w->planes[index].n) : w->planes[index].n;)
    for (unsigned i = 0; i < n; i++, L++) {
        vec3_t l;
        num_t dist, va[3], ndl = NUM_ZERO;
        num_inv3_t iv;
        int how = SHADE_DIR;
        if (L->kind == LIGHT_DIRECTIONAL) {
            /* n . l, turned to the ray's side: no product at all. */
            numw_sticky_t s = pls ? pls[i].h.ndl : shade_plane_height(w, index, L).ndl;
            s = inside ? -s : s;
            if (s <= 0)
                continue; /* behind the surface: no shadow ray either */
            ndl = numw_sticky_round(s);
            l = L->dir, dist = NUM_MAX;
            va[0] = va[1] = va[2] = NUM_ZERO; /* (unused) */
        } else {
            how = shade_light_dir(L, pp, &l, &dist, &iv, va);
            if (how == SHADE_DARK)
                continue;
            if (how == SHADE_INV) {
                shade_height_t h = pls ? pls[i].h : shade_plane_height(w, index, L);
                if (!numw_mant_faces(h.h, inside))
                    continue; /* behind the surface: no shadow ray either */
                ndl = num_inv3_mul(&iv, h.h); /* |n . l| <= 1 + 1 LSB */
                ndl = inside ? num_neg_fits(ndl) : ndl;
                if (phong) { /* l for Phong's r, and for the shadow ray */
                    FXRT_COUNT(l_units);
                    num_inv3_unit(&iv, va, va);
                    l = vec3_make(va[0], va[1], va[2]);
                    how = SHADE_DIR;
                }
            } else {
                /* beyond SHADE_FAR_DIST (shade_light_far's l) */
                FXRT_IF_PLANE(const vec3_t *n_geo = &w->planes[index].n;
                              numw_t ndlw = vec3_dotw_units(inside ? vec3_neg_unit(*n_geo) : *n_geo, l);
                              if (ndlw <= 0) continue; ndl = numw_round_fits(ndlw);)
            }
        }
        if (shade_shadowed(w, GEOM_PLANE, index GEOM_PART_ARG(NULL), obj, inside, pp, L, i, &l, dist, k, pls,
                           how == SHADE_INV ? &iv : NULL, va))
            continue;
        bits |= 1u << i;
        c = shade_madd(c, k->kd[i], ndl);
        SHADE_IF_PHONG(if (phong) c = shade_specular(c, &nt, &l, d, ndl, &k->ks[i], obj->mat.exponent, raw);)
    }
    if (mask)
        *mask = (uint8_t)bits;
    return c;
}

/* shade_plane_sum where no light needs the point (directional lights
 * only, shade_plane_row_unshadowed): each light's stored n . l turned to
 * the ray's side, the same terms in the same order. A light that is not
 * directional (a world changed after the set-up) is left out: a wrong
 * pixel, not a fault. */
static inline __attribute__((always_inline)) color_t shade_plane_sum_dir(const world_t *w, uint16_t index,
                                                                         const shade_k_t *k,
                                                                         const shade_plane_light_t *pls, bool inside,
                                                                         uint8_t *mask)
{
    FXRT_COUNT(dir_sums);
    if (FXRT_BOUND_NO_LIGHT_SUM && !mask)
        return k->ambient;
    color_t c = k->ambient;
    unsigned bits = 0;
    const light_t *L = w->lights;
    for (unsigned i = 0, n = w->n_lights; i < n; i++, L++) {
        if (L->kind != LIGHT_DIRECTIONAL)
            continue;
        numw_sticky_t s = pls ? pls[i].h.ndl : shade_plane_height(w, index, L).ndl;
        if ((inside ? -s : s) <= 0)
            continue; /* behind the surface */
        bits |= 1u << i;
        c = shade_madd(c, k->kd[i], numw_sticky_round(inside ? -s : s));
    }
    if (mask)
        *mask = (uint8_t)bits;
    return c;
}

static inline __attribute__((always_inline)) color_t shade_flat_plane_at(const world_t *w, const shade_flat_t *f,
                                                                          const shade_k_t *k, const ray_t *ray,
                                                                          uint8_t *mask)
{
    numw_t rn;
    FXRT_COUNT(shaded);
    FXRT_COUNT(plane_points);
    vec3_t p = shade_flat_point(&f->ratio, &ray->o, &ray->d, f->n, &rn);
    return shade_plane_sum(w, f->obj, f->index, k, f->pls, &p, rn > 0, &ray->d, true, false, mask);
}

color_t shade_flat_plane(const world_t *w, const shade_flat_t *f, const shade_k_t *k, const ray_t *ray,
                         uint8_t *mask)
{
    return shade_flat_plane_at(w, f, k, ray, mask);
}

color_t shade_flat_plane_dir(const world_t *w, const shade_flat_t *f, const shade_k_t *k, const ray_t *ray,
                             uint8_t *mask)
{
    numw_t rn = vec3_dotw_unit(ray->d, *f->n); /* (the side: shade_flat_point's rn) */
    if (!shade_plane_row_unshadowed(w, f->pls, rn > 0))
        return shade_flat_plane(w, f, k, ray, mask);
    FXRT_COUNT(shaded);
    return shade_plane_sum_dir(w, f->index, k, f->pls, rn > 0, mask);
}

/* Does every pixel of columns x..end-1 see plane normal n from one side
 * (shade_flat_plane_dir's rn > 0 at all of them, or at none)? 0 (and
 * ray holds the first column's ray) when it does, -1 when it may not. In
 * Q16.16 rn is exact and linear in the column (the ray's direction is
 * row + u ix, exactly), so the two ends decide; in float and double each
 * end must also lie beyond 2^-12 of its |d|_1, far above the rounding of
 * d and of the dot product between them. */
static int shade_plane_run_side(const cam_row_t *row, const vec3_t *u, const vec3_t *fwd, const vec3_t *n,
                                int32_t width, int32_t x, int32_t end, ray_t *ray)
{
    cam_row_dir(row, u, fwd, 2 * (end - 1) - width + 1, ray);
    numw_t r1 = vec3_dotw_unit(ray->d, *n);
    num_t m1 = vec3_l1(ray->d);
    cam_row_dir(row, u, fwd, 2 * x - width + 1, ray);
    numw_t r0 = vec3_dotw_unit(ray->d, *n);
    if ((r0 > 0) != (r1 > 0))
        return -1;
    if (!NUM_EXACT) {
        num_t m0 = vec3_l1(ray->d);
        num_t m = num_mul(m0 > m1 ? m0 : m1, (num_t)(1.0 / 4096));
        if (!(num_abs((num_t)r0) > m && num_abs((num_t)r1) > m))
            return -1;
    }
    return 0;
}


/* Plane f's hit point at column x (shade_flat_point's; ray: its camera
 * ray), and with unit, shade_unit_point_slack's bound in *slack (else 0). */
static vec3_t shade_plane_point_at(const shade_flat_t *f, const cam_row_t *row, const vec3_t *u, const vec3_t *fwd,
                                   int32_t width, int32_t x, bool unit, num_t *slack, ray_t *ray)
{
    numw_t rn;
    cam_row_dir(row, u, fwd, 2 * x - width + 1, ray);
    vec3_t p = shade_flat_point(&f->ratio, &ray->o, &ray->d, f->n, &rn);
    *slack = unit ? shade_unit_point_slack(ray, &p, rn) : NUM_ZERO;
    return p;
}

/* Pixels x..end-1 of a run on Lambert plane f, one by one (dir: every
 * light is directional). */
static inline __attribute__((always_inline)) void shade_plane_pixels(const world_t *w, const shade_flat_t *f,
                                                                     const shade_k_t *k, const cam_row_t *row,
                                                                     const vec3_t *u, const vec3_t *fwd, int32_t width,
                                                                     int32_t x, int32_t end, ray_t *ray, uint8_t *rgb,
                                                                     bool dir)
{
    for (; x < end; x++) {
        cam_row_dir(row, u, fwd, 2 * x - width + 1, ray);
        color_t c;
        /* (shade_flat_plane_dir's value, inline: no frame deeper) */
        numw_t rn = dir ? vec3_dotw_unit(ray->d, *f->n) : 0;
        if (dir && shade_plane_row_unshadowed(w, f->pls, rn > 0)) {
            FXRT_COUNT(shaded);
            c = shade_plane_sum_dir(w, f->index, k, f->pls, rn > 0, NULL);
        } else
            c = shade_flat_plane_at(w, f, k, ray, NULL);
        color_put_pixel(rgb, x, color_to_rgb8(c));
    }
}

/* A plane's n . l along a run (shade_plane_forms). On a run the camera
 * ray is d(k) = d_0 + 2 k u at the run's k-th pixel (cam_row_dir), and
 * its hit point is p = e + t d with t = h_e / q, h_e = n . (a - e), q = n
 * . d. A point light at L then has L - p = W / q with W = g q - d h_e
 * (g = L - e): linear in k, since q is. So n . l = h_L / |L - p| = |h_L|
 * |q| / |W| (h_L = n . (L - a), turned to the side seen), with no hit
 * point, and |W|^2 is a quadratic in k. Q16.16: q and h_e (exact wide
 * dot products) are scaled by one 2^-rho into 31 bits, q stepped as q0 +
 * k dq (both rounded: within (1 + k) / 2 of the exact q 2^-rho); W, formed
 * from those in exact 64-bit products, is linear in k, and scaled by
 * 2^-sigma into 30 bits: W~(k) = W~0 + k D~ (each rounded: within (1 + k)
 * / 2 per component), whose |W~|^2 = P is stepped exactly by its
 * differences; n . l = |h_L| |q| 2^-sigma / sqrt(P) in raw units
 * (fx_mul_rsqrt64). The point W / q stands for lies on the camera ray at
 * t = h_e' / q', off p by |p - e| (r_q + r_h) (their relative errors);
 * the set-up asks that this be below 2^-14 |h_L|, and that W~'s own
 * error be below 2^-16 |W~| (|W| >= |q| |h_L| (1 - 2^-14)): n . l within
 * a few LSB (delta, per light and run). Float and double make q and W at
 * each pixel from its ray (no stepping).
 * The frame stays the one the hit point's path gives (pixel by pixel,
 * shade_plane_sum): the two values of n . l lie within delta of each
 * other, so the colours within sum kd delta (and the products' rounding)
 * per channel; a pixel whose colour lies that near a step of its 8-bit
 * value (c + 1/2 an integer) is made again on that path (a few % of
 * them). Runs where a light needs a shadow ray (a point or directional
 * light with shadows, off the row's SHADOW_ROW_CLEAR), a spot,
 * coordinates of 4096 or more, or (Q16.16) any bound fails go pixel by
 * pixel. */
enum { SHADE_FORM_NONE, SHADE_FORM_CONST, SHADE_FORM_POINT };

/* The plane's point a, or NULL (no planes). */
static const vec3_t *shade_plane_a(const world_t *w, uint16_t index)
{
    FXRT_IF_PLANE(return &w->planes[index].a;)
    (void)w, (void)index;
    return NULL;
}

/* Per number type: shade_form_t (a light's form), shade_form_run_t (the
 * run's), shade_forms_begin (the set-up for pixels x..end-1, from the
 * first pixel's ray; false where a bound fails), shade_forms_at (pixel
 * x's values), shade_form_ndl (a point light's n . l there, and its step
 * to the next pixel) and shade_forms_next (the run's step). */
#if FXRT_NUMBER == FXRT_Q16
typedef struct {
    uint8_t how;        /* SHADE_FORM_ */
    int8_t e;           /* |h_L|'s exponent less sigma */
    uint32_t hm;        /* |h_L|'s mantissa (fx_mant_t) */
    num_t ndl;          /* SHADE_FORM_CONST: a directional light's n . l */
    num_t delta;        /* SHADE_FORM_POINT: bound on |n . l - the hit point's| */
    int64_t P, dP, ddP; /* |W~(k)|^2 and its differences */
} shade_form_t;
typedef struct {
    int32_t q, dq; /* |q'| at the current pixel, and its step */
} shade_form_run_t;

static int shade_bits_linf(vec3_t v) { return fx_bits64(vec3_linf(v)); }

static bool shade_forms_begin(const world_t *w, const shade_plane_light_t *pls, const vec3_t *n, const vec3_t *a,
                              const cam_row_t *row, const vec3_t *u, const vec3_t *fwd, int32_t width, int32_t x,
                              int32_t end, const ray_t *ray, shade_form_t *fm, shade_form_run_t *run)
{
    const vec3_t *d0 = &ray->d, *e = &ray->o;
    ray_t r1;
    cam_row_dir(row, u, fwd, 2 * (end - 1) - width + 1, &r1);
    const vec3_t *de = &r1.d;
    int32_t K = end - x;
    int64_t Q0 = vec3_dotw_unit(*d0, *n), Qe = vec3_dotw_unit(*de, *n), Qs = 2 * vec3_dotw_unit(*u, *n);
    int64_t He = vec3_dotw_unit(vec3_sub(*a, *e), *n);
    if (Q0 == 0 || Qe == 0 || (Q0 < 0) != (Qe < 0) || He == 0 || (He < 0) != (Q0 < 0))
        return false;
    int b0 = fx_bits64(Q0), be = fx_bits64(Qe), bh = fx_bits64(He);
    int rho = (b0 > be ? b0 : be) > bh ? (b0 > be ? b0 : be) : bh;
    rho = rho > 30 ? rho - 30 : 0;
    int64_t q = fx_shr_round64(Q0, rho), s = fx_shr_round64(Qs, rho), h = fx_shr_round64(He, rho);
    int64_t qe = q + (int64_t)(K - 1) * s;
    if (q == 0 || qe == 0 || (q < 0) != (qe < 0) || (qe < 0 ? -qe : qe) >= ((int64_t)1 << 31))
        return false;
    int bq = fx_bits64((q < 0 ? -q : q) < (qe < 0 ? -qe : qe) ? q : qe), bK = fx_bits64(K + 1);
    /* |p - e| < 2^lpe at both ends (|d|_inf |h_e| / |q| 2^-16, and sqrt(3)) */
    int l0 = shade_bits_linf(*d0) + bh - b0, l1 = shade_bits_linf(*de) + bh - be;
    int lpe = (l0 > l1 ? l0 : l1) + 2 - 16;
    int rq = bK - bq > 1 - fx_bits64(h) ? bK - bq : 1 - fx_bits64(h); /* log2 of r_q + r_h, less 1 */
    if (lpe > 12)
        return false;
    for (unsigned i = 0; i < w->n_lights; i++) {
        if (fm[i].how != SHADE_FORM_POINT)
            continue;
        int32_t hm = fx_mant_m(pls[i].h.h);
        int eh = fx_mant_e(pls[i].h.h);
        /* |h_L| >= 2^(eh - 8) units (|hm| >= 2^24, Q32.32) */
        if (eh - 8 < -4 || rq + 1 + lpe > eh - 8 - 14)
            return false;
        vec3_t g = vec3_sub(w->lights[i].position, *e);
        const int32_t G[3] = {g.x, g.y, g.z}, D0[3] = {d0->x, d0->y, d0->z}, De[3] = {de->x, de->y, de->z},
                      U[3] = {u->x, u->y, u->z};
        int64_t W0[3], Wd[3];
        int bw = 0;
        for (int c = 0; c < 3; c++) {
            W0[c] = (int64_t)G[c] * q - (int64_t)D0[c] * h;
            int64_t We = (int64_t)G[c] * qe - (int64_t)De[c] * h;
            Wd[c] = (int64_t)G[c] * s - 2 * ((int64_t)U[c] * h);
            int b = fx_bits64(W0[c]) > fx_bits64(We) ? fx_bits64(W0[c]) : fx_bits64(We);
            bw = b > bw ? b : bw;
        }
        int sigma = bw > 29 ? bw - 29 : 0;
        /* |W~(k)| >= 2^(bq - 1 + 24 + eh - 16 - 1 - sigma); its error < 2^bK */
        if (bq + eh + 6 - sigma < bK + 16)
            return false;
        int64_t P = 0, dP = 0, dd = 0;
        for (int c = 0; c < 3; c++) {
            int64_t w0 = fx_shr_round64(W0[c], sigma), wd = fx_shr_round64(Wd[c], sigma);
            P += w0 * w0;
            dP += 2 * w0 * wd + wd * wd;
            dd += 2 * wd * wd;
        }
        fm[i].P = P, fm[i].dP = dP, fm[i].ddP = dd;
        fm[i].hm = fx_uabs32(hm);
        fm[i].e = (int8_t)(eh - sigma);
        /* Here 0.6 LSB and 2^16 (2^ef + 2^ew) (ef, ew: the two relative
         * bounds above); the hit point's path 0.5 LSB + 2^-23 relative
         * (fx_inv3_mul) and n . l / |L - p| <= 1 / |h_L| LSB for its point
         * (within 0.5 LSB + 2^-29 |p - e| per component of the exact
         * hit, shade_flat_point: 1 LSB here), doubled. */
        int ef = rq + 1 + lpe - (eh - 8) + 16, ew = bK - (bq + eh + 6 - sigma) + 16;
        fm[i].delta = 2 + (ef > 0 ? (num_t)1 << ef : 1) + (ew > 0 ? (num_t)1 << ew : 1) +
                      (eh < 9 ? (num_t)1 << (9 - eh) : 1);
    }
    run->q = (int32_t)(q < 0 ? -q : q);
    run->dq = (int32_t)(q < 0 ? -s : s);
    return true;
}
static inline void shade_forms_at(shade_form_run_t *run, int32_t x) { (void)run, (void)x; }
static inline num_t shade_form_ndl(shade_form_t *m, const shade_form_run_t *run)
{
    num_t ndl = fx_mul_rsqrt64(m->hm, (uint32_t)run->q, m->e, (uint64_t)m->P);
    m->P += m->dP;
    m->dP += m->ddP;
    return ndl;
}
static inline void shade_forms_next(shade_form_run_t *run) { run->q += run->dq; }
/* Lies channel value c within lim of a step of color_channel (c + 1/2 an
 * integer)? */
static inline bool shade_form_near(num_t c, num_t lim)
{
    uint32_t t = ((uint32_t)c + 0x8000u) & 0xffffu;
    return (num_t)(t < 0x8000u ? t : 0x10000u - t) <= lim;
}
/* A light's share of the colour's bound: kd delta, and the product's
 * rounding (1 LSB in the two paths). */
static inline num_t shade_form_share(num_t kd, num_t delta) { return kd ? (num_t)(((int64_t)kd * delta) >> 16) + 2 : 0; }
#else
/* Float and double: each path's n . l = h / |v| (v = L - p, |v| >= h =
 * |h_L| and |v| >= r - B, r = |p - e|, B = |L - e|) within K h (A + 2 r)
 * / |v|^2 of the exact value, A = |e|_1 + |L|_1 + 1 (the products' and
 * sums' rounding, 2^-24 or 2^-53 of the magnitudes they take, many times
 * over: K = SHADE_FORM_K). Over r that is largest at r = B + h: delta =
 * K ((A + 2 B + 2 h) / h + 1), whatever the run's length; h >= 1/16. */
#define SHADE_FORM_K (FXRT_NUMBER == FXRT_FLOAT ? (num_t)(1.0 / 131072) : (num_t)(1.0 / 1099511627776.0))
typedef struct {
    uint8_t how; /* SHADE_FORM_ */
    num_t ndl;   /* SHADE_FORM_CONST: a directional light's n . l */
    num_t delta; /* SHADE_FORM_POINT: bound on |n . l - the hit point's| */
    vec3_t g;    /* L - e */
    num_t h;     /* |h_L| */
} shade_form_t;
typedef struct {
    const cam_row_t *row;
    const vec3_t *u, *fwd, *n;
    ray_t *ray;
    int32_t width;
    num_t he, q, aq; /* h_e, and the current pixel's q and |q| */
} shade_form_run_t;

static bool shade_forms_begin(const world_t *w, const shade_plane_light_t *pls, const vec3_t *n, const vec3_t *a,
                              const cam_row_t *row, const vec3_t *u, const vec3_t *fwd, int32_t width, int32_t x,
                              int32_t end, ray_t *ray, shade_form_t *fm, shade_form_run_t *run)
{
    run->row = row, run->u = u, run->fwd = fwd, run->n = n, run->ray = ray, run->width = width;
    run->he = numw_round_fits(vec3_dotw_unit(vec3_sub(*a, ray->o), *n));
    (void)x, (void)end;
    num_t el = vec3_l1(ray->o);
    for (unsigned i = 0; i < w->n_lights; i++)
        if (fm[i].how == SHADE_FORM_POINT) {
            const vec3_t *L = &w->lights[i].position;
            fm[i].g = vec3_sub(*L, ray->o);
            fm[i].h = num_abs(pls[i].h.h);
            if (!(fm[i].h > NUM(1.0 / 16)))
                return false;
            num_t b = vec3_l1(fm[i].g);
            fm[i].delta = SHADE_FORM_K * ((el + vec3_l1(*L) + b + b + fm[i].h + fm[i].h + NUM_ONE) / fm[i].h + NUM_ONE);
        }
    return true;
}
static inline void shade_forms_at(shade_form_run_t *run, int32_t x)
{
    cam_row_dir(run->row, run->u, run->fwd, 2 * x - run->width + 1, run->ray);
    run->q = numw_round_fits(vec3_dotw_unit(run->ray->d, *run->n));
    run->aq = num_abs(run->q);
}
static inline num_t shade_form_ndl(shade_form_t *m, const shade_form_run_t *run)
{
    vec3_t W = vec3_sub(vec3_scale(m->g, run->q), vec3_scale(run->ray->d, run->he));
    return m->h * run->aq / num_sqrt(vec3_dot(W, W));
}
static inline void shade_forms_next(shade_form_run_t *run) { (void)run; }
static inline bool shade_form_near(num_t c, num_t lim)
{
    num_t f = c + (num_t)0.5;
    num_t t = f - (num_t)(int32_t)f;
    return !(f >= NUM_ZERO && f < (num_t)65536) || (t < (num_t)0.5 ? t : NUM_ONE - t) <= lim;
}
static inline num_t shade_form_share(num_t kd, num_t delta) { return kd != NUM_ZERO ? kd * delta + 256 * SHADE_FORM_K : NUM_ZERO; }
#endif

/* Plane f's pixels x..end-1 from the run's forms (above): true where it
 * wrote them, false (nothing written) where the run does not qualify. */
static __attribute__((noinline)) bool shade_plane_forms(const world_t *w, const shade_flat_t *f, const shade_k_t *k,
                                                        const cam_row_t *row, const vec3_t *u, const vec3_t *fwd,
                                                        int32_t width, int32_t x, int32_t end, ray_t *ray,
                                                        uint8_t *rgb)
{
    const shade_plane_light_t *pls = f->pls;
    const vec3_t *a = shade_plane_a(w, f->index);
    const num_t lim = NUM(4096);
    const unsigned nl = w->n_lights;
    /* First what needs no point: a spot, or a light that needs a shadow
     * ray on this row (a light behind the side seen would not: rare,
     * and left to the pixels), or far away. */
    for (unsigned i = 0; pls && i < nl; i++) {
        const light_t *L = &w->lights[i];
        if (L->kind == LIGHT_SPOT || (FXRT_SHADOWS && L->shadows && !(SHADOW_ROWS && (pls[i].row & SHADOW_ROW_CLEAR))) ||
            (L->kind == LIGHT_POINT && !(vec3_linf(L->position) < lim)))
            return false;
    }
    if (FXRT_BOUND_NO_LIGHT_SUM || !pls || !a || end - x < 2 || !(vec3_linf(*a) < lim) ||
        shade_plane_run_side(row, u, fwd, f->n, width, x, end, ray) < 0 || !(vec3_linf(ray->o) < lim))
        return false;
    const bool inside = vec3_dotw_unit(ray->d, *f->n) > 0; /* (ray: column x's) */
    shade_form_t fm[FXRT_MAX_LIGHTS] = {{0}};
    shade_form_run_t run;
    bool any = false;
    for (unsigned i = 0; i < nl; i++) {
        if (w->lights[i].kind == LIGHT_DIRECTIONAL) {
            numw_sticky_t sd = inside ? -pls[i].h.ndl : pls[i].h.ndl;
            if (sd <= 0)
                continue; /* behind the side seen */
            fm[i].how = SHADE_FORM_CONST;
            fm[i].ndl = numw_sticky_round(sd);
        } else if (numw_mant_faces(pls[i].h.h, inside)) { /* (else behind the side seen) */
            fm[i].how = SHADE_FORM_POINT;
            any = true;
        }
    }
    if (!any || !shade_forms_begin(w, pls, f->n, a, row, u, fwd, width, x, end, ray, fm, &run))
        return false;
    /* How far the colour may lie from the hit point's path's, per channel */
    color_t near = color_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
    for (unsigned i = 0; i < nl; i++)
        if (fm[i].how == SHADE_FORM_POINT)
            near = color_make(near.r + shade_form_share(k->kd[i].r, fm[i].delta),
                              near.g + shade_form_share(k->kd[i].g, fm[i].delta),
                              near.b + shade_form_share(k->kd[i].b, fm[i].delta));
    for (; x < end; x++) {
        shade_forms_at(&run, x);
        color_t c = k->ambient;
        for (unsigned i = 0; i < nl; i++) {
            shade_form_t *m = &fm[i];
            if (m->how != SHADE_FORM_NONE)
                c = shade_madd(c, k->kd[i], m->how == SHADE_FORM_CONST ? m->ndl : shade_form_ndl(m, &run));
        }
        shade_forms_next(&run);
        if ((near.r > NUM_ZERO && shade_form_near(c.r, near.r)) || (near.g > NUM_ZERO && shade_form_near(c.g, near.g)) ||
            (near.b > NUM_ZERO && shade_form_near(c.b, near.b))) {
            /* near a step of the 8-bit value: the hit point's path, whose
             * value this is (the frame is the same either way) */
            cam_row_dir(row, u, fwd, 2 * x - width + 1, ray);
            c = shade_flat_plane_at(w, f, k, ray, NULL);
        } else {
            FXRT_COUNT(shaded);
            FXRT_COUNT(plane_forms);
        }
        color_put_pixel(rgb, x, color_to_rgb8(c));
    }
    return true;
}

/* A block x..last that no light reaches: the ambient term, the light
 * sum's value there, to each pixel (shade_flat_spot_blocks,
 * shade_flat_phong_blocks); returns last + 1. */
static inline int32_t shade_block_ambient(const shade_k_t *k, uint8_t *rgb, int32_t x, int32_t last)
{
    FXRT_COUNT(spot_blocks);
    rgb8_t v = color_to_rgb8(k->ambient);
    for (; x <= last; x++) {
        FXRT_COUNT(shaded);
        color_put_pixel(rgb, x, v);
    }
    return x;
}

int32_t shade_flat_spot_blocks(const world_t *w, const shade_flat_t *f, const shade_k_t *k, const cam_row_t *row,
                               const vec3_t *u, const vec3_t *fwd, int32_t width, int32_t x, int32_t end, ray_t *ray,
                               uint8_t *rgb, int32_t *stop)
{
    /* A block x..last is tested on the segment from x's hit point to the
     * next block's first pixel's (last + 1, in the run: the exact points
     * of x..last lie on it), so each block makes one new point; the run's
     * last block ends on its own last pixel. */
    const bool unit = shade_needs_unit(w, f->obj, GEOM_PLANE, f->index);
    num_t sa, sb;
    vec3_t pa = shade_plane_point_at(f, row, u, fwd, width, x, unit, &sa, ray);
    while (x < end) {
        int32_t last = end - x > SHADE_SPOT_BLOCK ? x + SHADE_SPOT_BLOCK - 1 : end - 1;
        int32_t e = last + 1 < end ? last + 1 : last;
        bool out = e > x;
        if (out) {
            vec3_t pb = shade_plane_point_at(f, row, u, fwd, width, e, unit, &sb, ray);
            num_t slack = sa < NUM_ZERO || sb < NUM_ZERO ? -NUM_ONE : sa > sb ? sa : sb;
            for (unsigned i = 0; out && i < w->n_lights; i++)
                out = shade_spot_block_out(&w->lights[i], &ray->o, &pa, &pb, slack);
            pa = pb;
            sa = sb;
        }
        if (!out) {
            *stop = last + 1;
            return x;
        }
        x = shade_block_ambient(k, rgb, x, last);
    }
    *stop = end;
    return end;
}

/* shade_flat_plane_run under spots only (SHADE_FLAT_SPOTS): the blocks
 * that no spot reaches, then each other block pixel by pixel. */
static __attribute__((noinline)) void shade_plane_spot_run(const world_t *w, const shade_flat_t *f, const shade_k_t *k,
                                                           const cam_row_t *row, const vec3_t *u, const vec3_t *fwd,
                                                           int32_t width, int32_t x, int32_t end, ray_t *ray,
                                                           uint8_t *rgb)
{
    while (x < end) {
        int32_t stop;
        x = shade_flat_spot_blocks(w, f, k, row, u, fwd, width, x, end, ray, rgb, &stop);
        shade_plane_pixels(w, f, k, row, u, fwd, width, x, stop, ray, rgb, false);
        x = stop;
    }
}

void shade_flat_plane_pixels(const world_t *w, const shade_flat_t *f, const shade_k_t *k, const cam_row_t *row,
                             const vec3_t *u, const vec3_t *fwd, int32_t width, int32_t x, int32_t end, ray_t *ray,
                             uint8_t *rgb)
{
    if (shade_plane_forms(w, f, k, row, u, fwd, width, x, end, ray, rgb))
        return;
    shade_plane_pixels(w, f, k, row, u, fwd, width, x, end, ray, rgb, false);
}

/* Phong on a plane under a point or spot light L, seen from the eye o.
 * With L' = L - 2 h n, the light's mirror image in the plane (h = n . (L -
 * a)), the reflected direction at a point p of the plane is r = (p - L')
 * / |p - L'|, and with e = (o - p) / |o - p| the term's x = r . e is the
 * cosine of the outer angle phi of the triangle L', p, o at p. By the law
 * of cosines D^2 = A^2 + B^2 + 2 A B x (D = |L' - o|, A = |p - L'|, B =
 * |p - o|), and 2 A B <= (A + B)^2 / 2, so x > c' gives A + B < D sqrt(2 /
 * (1 + c')) = D s: every point where x > c' lies inside the ellipsoid
 * with foci L' and o and that sum. shade_phong_mirror makes L' and the
 * bound S = D s + 2^-11 |h| (the mirror's rounding: n is unit within
 * 2^-15, so L' lies within 2^-13 |h| of the exact image, and A and D each
 * move by that) for shade_phong_block_zero; false where a coordinate of
 * L, o, the plane's point a or L' is 4096 or more (then no block is
 * skipped: every value below stays far inside Q16.16). */
static bool shade_phong_mirror(const world_t *w, uint16_t index, const light_t *L, const vec3_t *o, num_t fs,
                               vec3_t *lm, num_t *bound)
{
    FXRT_IF_PLANE(const geom_plane_t *pl = &w->planes[index];
                  const num_t lim = NUM(4096);
                  if (L->kind == LIGHT_DIRECTIONAL || !(vec3_linf(L->position) < lim) || !(vec3_linf(*o) < lim) ||
                      !(vec3_linf(pl->a) < lim)) return false;
                  num_t h = numw_round_fits(vec3_dotw_unit(vec3_sub(L->position, pl->a), pl->n));
                  if (!(num_abs(h) < NUM(8192))) return false; /* (2 h: vec3_scale_unit_small's bound) */
                  *lm = vec3_sub(L->position, vec3_scale_unit_small(pl->n, num_add(h, h)));
                  if (!(vec3_linf(*lm) < lim)) return false;
                  *bound = num_add(num_mul(numw_sqrt(vec3_dotw(vec3_sub(*lm, *o), vec3_sub(*lm, *o))), fs),
                                   num_mul(num_abs(h), NUM(1.0 / 2048)));
                  return true;)
    (void)w, (void)index, (void)L, (void)o, (void)fs, (void)lm, (void)bound;
    return false;
}

/* Is the term of the light with mirror image lm and bound S
 * (shade_phong_mirror) surely 0 at every pixel of a block whose segment
 * runs from pa to pb (as shade_spot_block_out's: every computed hit point
 * of the block lies within R of the midpoint M, 2 R <= |pb - pa|_1 + 256
 * LSB in Q16.16, + 2^-14 (|pa|_1 + |pb|_1 + |o|_1 + 1) in float and
 * double)? A and B move by at most R each from M to such a point, so the
 * block lies outside the ellipsoid where A_M + B_M - 2 R > S, with a
 * margin of 2^-10 (A_M + B_M + S) + 2^-8 for the roots and the midpoint.
 * Then x <= c' at every pixel, for the exact point and eye direction.
 * The light sum takes x from the computed point p and the ray's direction
 * d: p lies within 8 LSB of the exact point (shade_flat_point) and B_M -
 * 2 R > 1/8 is asked, so d and o - p differ by less than 2^-10 in angle
 * (float: 2^-14 |p|_1 over the same B), and l, r and the quotient round
 * within 2^-13: x rises by less than 2^-8 over c' (Q16.16: to at most c,
 * where numw_pow_int is 0) and by less than 2^-12 in float and double (to
 * at most 0: no term). Coordinates below 4096, as shade_phong_mirror's. */
static bool shade_phong_block_zero(const vec3_t *lm, num_t bound, const vec3_t *o, const vec3_t *pa, const vec3_t *pb)
{
    const num_t lim = NUM(4096);
    if (!(vec3_linf(*pa) < lim) || !(vec3_linf(*pb) < lim))
        return false;
    vec3_t m = vec3_make(num_half(num_add(pa->x, pb->x)), num_half(num_add(pa->y, pb->y)),
                         num_half(num_add(pa->z, pb->z)));
    vec3_t va = vec3_sub(m, *lm), vb = vec3_sub(m, *o);
    num_t r2 = num_add(vec3_l1(vec3_sub(*pb, *pa)),
                       NUM_EXACT ? (num_t)256
                                 : num_mul(NUM(1.0 / 16384), vec3_l1(*pa) + vec3_l1(*pb) + vec3_l1(*o) + NUM_ONE));
    num_t a = numw_sqrt(vec3_dotw(va, va)), b = numw_sqrt(vec3_dotw(vb, vb)), f = num_add(a, b);
    num_t margin = num_add(num_mul(num_add(f, bound), NUM(1.0 / 1024)), NUM(1.0 / 256));
    return num_sub(b, r2) > NUM(1.0 / 8) && num_sub(num_sub(f, r2), margin) > bound;
}

int32_t shade_flat_phong_blocks(const world_t *w, const shade_flat_t *f, const shade_k_t *k, const cam_row_t *row,
                                const vec3_t *u, const vec3_t *fwd, int32_t width, int32_t x, int32_t end, ray_t *ray,
                                uint8_t *rgb, int32_t *stop, bool *lambert)
{
    enum { BLOCK_NEED, BLOCK_ZERO, BLOCK_OUT };
    vec3_t lm[FXRT_MAX_LIGHTS] = {{NUM_ZERO, NUM_ZERO, NUM_ZERO}};
    num_t bound[FXRT_MAX_LIGHTS] = {NUM_ZERO}, sa;
    uint32_t ok = 0;
    unsigned n = w->n_lights;
    num_t fs = shade_phong_factor(f->obj->mat.exponent);
    cam_row_dir(row, u, fwd, 2 * x - width + 1, ray); /* (ray->o: the eye) */
    for (unsigned i = 0; i < n; i++)
        ok |= (uint32_t)shade_phong_mirror(w, f->index, &w->lights[i], &ray->o, fs, &lm[i], &bound[i]) << i;
    vec3_t pa = shade_plane_point_at(f, row, u, fwd, width, x, false, &sa, ray);
    int32_t start = x;
    int kind = BLOCK_NEED;
    while (x < end) {
        int32_t last = end - x > SHADE_SPOT_BLOCK ? x + SHADE_SPOT_BLOCK - 1 : end - 1;
        int32_t e = last + 1 < end ? last + 1 : last;
        int b = BLOCK_NEED;
        if (e > x) {
            vec3_t pb = shade_plane_point_at(f, row, u, fwd, width, e, false, &sa, ray);
            bool out = true, zero = true;
            for (unsigned i = 0; i < n && (out || zero); i++) {
                bool o = shade_spot_block_out(&w->lights[i], &ray->o, &pa, &pb, NUM_ZERO);
                out = out && o;
                zero = zero && (o || ((ok >> i & 1u) && shade_phong_block_zero(&lm[i], bound[i], &ray->o, &pa, &pb)));
            }
            b = out ? BLOCK_OUT : zero ? BLOCK_ZERO : BLOCK_NEED;
            pa = pb;
        }
        if (start == x && b == BLOCK_OUT) { /* nothing pending: the ambient term at once */
            start = x = shade_block_ambient(k, rgb, x, last);
            continue;
        }
        if (start < x && b != kind)
            break;
        kind = b;
        x = last + 1;
        if (b == BLOCK_ZERO)
            FXRT_COUNT(phong_blocks);
    }
    *stop = x;
    *lambert = kind == BLOCK_ZERO;
    return start;
}

void shade_flat_plane_run(const world_t *w, const shade_flat_t *f, const shade_k_t *k, const cam_row_t *row,
                          const vec3_t *u, const vec3_t *fwd, int32_t width, int32_t x, int32_t end, ray_t *ray,
                          uint8_t *rgb)
{
    const bool dir = f->flags & SHADE_FLAT_DIRECTIONAL;
    if (dir && end - x > 1 && shade_plane_run_side(row, u, fwd, f->n, width, x, end, ray) >= 0) {
        /* One side of the plane over the whole run: where no light needs
         * a shadow ray there, every pixel has the same colour. */
        bool inside = vec3_dotw_unit(ray->d, *f->n) > 0;
        if (shade_plane_row_unshadowed(w, f->pls, inside)) {
            rgb8_t v = color_to_rgb8(shade_plane_sum_dir(w, f->index, k, f->pls, inside, NULL));
            for (; x < end; x++) {
                FXRT_COUNT(shaded);
                color_put_pixel(rgb, x, v);
            }
            return;
        }
    }
    if (f->flags & SHADE_FLAT_SPOTS) {
        shade_plane_spot_run(w, f, k, row, u, fwd, width, x, end, ray, rgb);
        return;
    }
    if (!dir && shade_plane_forms(w, f, k, row, u, fwd, width, x, end, ray, rgb))
        return;
    shade_plane_pixels(w, f, k, row, u, fwd, width, x, end, ray, rgb, dir);
}

/* The lights a Phong run tests at each pixel (shade_flat_phong_span): more
 * reaching its side, and the run goes pixel by pixel. */
#define SHADE_PHONG_RUN_LIGHTS 2

/* Float and double (shade_flat_phong_span): is the specular term of r
 * surely 0 at the pixel of raw direction d, whose light sum takes a =
 * -(r . d) along the same d (shade_flat_k, shade_specular_at)? Where
 * -(r . d) lies below -2^-16 |r|_1 |d|_1: the light sum's r is this r
 * (the same n . l), and its dot product the same value, so a < 0 there
 * and shade_specular adds nothing; the margin keeps the test from
 * hanging on the dot product's rounding. */
static inline bool shade_phong_none(const vec3_t *r, const vec3_t *d)
{
    return -vec3_dot(*r, *d) < -(num_t)(1.0 / 65536) * vec3_l1(*r) * vec3_l1(*d);
}

int32_t shade_flat_phong_span(const world_t *w, const shade_flat_t *f, const shade_k_t *k, const cam_row_t *row,
                              const vec3_t *u, const vec3_t *fwd, int32_t width, int32_t x, int32_t end, ray_t *ray,
                              uint8_t *rgb, int32_t *stop)
{
    /* Q16.16: each light's a = -(r . d) (shade_specular_raw's) and |d|^2
     * along the run, exactly: d moves by 2u per column (cam_row_dir, exact
     * in Q16.16), so a steps by -2 r . u, and |d|^2 by 4 d . u + 4 |u|^2,
     * which steps by 8 |u|^2. Float and double: r, and a made at each
     * pixel (shade_phong_none). */
    numw_t a[SHADE_PHONG_RUN_LIGHTS], da[SHADE_PHONG_RUN_LIGHTS];
    vec3_t rs[SHADE_PHONG_RUN_LIGHTS];
    unsigned m = 0;
    *stop = end;
    bool fast = end - x > 1 && shade_plane_run_side(row, u, fwd, f->n, width, x, end, ray) >= 0;
    bool inside = fast && vec3_dotw_unit(ray->d, *f->n) > 0; /* (ray: column x's) */
    fast = fast && shade_plane_row_unshadowed(w, f->pls, inside);
    vec3_t n = inside ? vec3_neg_unit(*f->n) : *f->n;
    const light_t *L = w->lights;
    for (unsigned i = 0; fast && i < w->n_lights; i++, L++) {
        numw_t ndlw = vec3_dotw_units(n, L->dir);
        if (L->kind != LIGHT_DIRECTIONAL || (ndlw > 0 && m == SHADE_PHONG_RUN_LIGHTS))
            fast = false;
        else if (ndlw > 0) { /* (a light behind the side adds no term) */
            vec3_t r = shade_phong_r(&n, &L->dir, numw_round_fits(ndlw));
            if (NUM_EXACT) {
                a[m] = numw_neg_fits(vec3_dotw(r, ray->d));
                da[m] = numw_neg_fits(numw_mul_int(vec3_dotw(r, *u), 2));
            } else {
                rs[m] = r;
            }
            m++;
        }
    }
    if (!fast)
        return x;
    numw_t uu = vec3_dotw(*u, *u), d2 = vec3_dotw(ray->d, ray->d);
    numw_t g = numw_mul_int(numw_add(vec3_dotw(ray->d, *u), uu), 4), h = numw_mul_int(uu, 8);
    uint16_t e = f->obj->mat.exponent;
    rgb8_t v = {0, 0, 0};
    int32_t first = end; /* the first column with a term, if any */
    for (int32_t i = x; i < end; i++) {
        bool zero = true;
        if (!NUM_EXACT)
            cam_row_dir(row, u, fwd, 2 * i - width + 1, ray);
        for (unsigned j = 0; j < m; j++) {
            zero = zero && (NUM_EXACT ? a[j] <= 0 || numw_pow_zero_at(a[j], d2, e) : shade_phong_none(&rs[j], &ray->d));
            if (NUM_EXACT)
                a[j] = numw_add(a[j], da[j]);
        }
        if (NUM_EXACT) {
            d2 = numw_add(d2, g);
            g = numw_add(g, h);
        }
        if (first == end && !zero) {
            first = i;
        } else if (first < end && zero) {
            *stop = i;
            break;
        }
    }
    if (first > x)
        v = color_to_rgb8(shade_plane_sum_dir(w, f->index, k, f->pls, inside, NULL));
    for (int32_t i = x; i < first; i++) {
        FXRT_COUNT(shaded);
        color_put_pixel(rgb, i, v);
    }
    return first;
}

/* (shade_sum.h) For a Lambert or Phong plane with constants k. */
color_t shade_lights_plane(const world_t *w, const geom_common_t *obj, uint16_t index, const vec3_t *pp,
                           const vec3_t *n_geo_p, int8_t facing, const vec3_t *dp, const shade_k_t *k, uint8_t *mask)
{
    const shade_plane_light_t *pls = shade_plane_entries(k, index);
    bool inside = facing == SHADE_FACING_UNKNOWN ? vec3_dotw_units(*dp, *n_geo_p) > 0 : (facing & 1) != 0;
    return shade_plane_sum(w, obj, index, k, pls, pp, inside, dp, facing > 1, obj->mat.kind == MATERIAL_PHONG, mask);
}

#if !FX_HAVE_UMULL
color_t shade_sum(const world_t *w, const geom_common_t *obj, geom_kind_t kind, uint16_t index GEOM_PART_PARAM,
                  const vec3_t *p, const vec3_t *n_geo, int8_t facing, const vec3_t *d, const shade_k_t *k,
                  uint8_t *mask)
{
    return shade_sum_inline(w, obj, kind, index GEOM_PART_ARG(part), p, n_geo, facing, d, k, mask);
}
#endif

color_t shade_point_k(const world_t *w, geom_kind_t kind, uint16_t index GEOM_PART_PARAM, vec3_t p, vec3_t n_geo,
                      vec3_t d, const shade_k_t *k, uint8_t *mask)
{
    const geom_common_t *obj = world_common(w, kind, index);
    /* Without the caller's constants (the bounce loop, the ray caster), a
     * lit opaque material goes straight to shade_sum_own, so that one
     * shade_sum frame, not two, is on the stack (16 KB boards). */
    if (!k && obj->mat.kind != MATERIAL_FLAT && obj->mat.kind != MATERIAL_TRANSPARENT)
        return shade_sum_own(w, obj, kind, index GEOM_PART_ARG(part), &p, &n_geo, SHADE_FACING_UNKNOWN, &d, mask);
    return shade_sum(w, obj, kind, index GEOM_PART_ARG(part), &p, &n_geo, SHADE_FACING_UNKNOWN, &d, k, mask);
}

#endif
