/* num: the renderer's arithmetic, defined once per number type.
 *
 * The ray, camera, geometry, world and render code is written only in terms
 * of num_t and the operations below (the Opus/Speex fixed_generic model).
 * Building it with FXRT_NUMBER = FXRT_Q16, FXRT_FLOAT or FXRT_DOUBLE gives
 * the product, the float build a user would otherwise write, and the double
 * reference: the same algorithm, so their differences measure precision.
 *
 *   num_t    scalar: Q16.16 / float / double
 *   numw_t   wide accumulator: exact Q32.32 products / float / double
 *
 * Q16.16 operations round to nearest and saturate (see fx.h). Float and
 * double operations are plain IEEE arithmetic.
 */
#ifndef FXRT_NUM_H
#define FXRT_NUM_H

#include <stdbool.h>
#include <stdint.h>

#include "fxrt_config.h"
#include "math/fx.h"
#include "math/stats.h"

/* Q16.16's x^k is 0 where x <= 1 - NUM_POW_ZERO_K / k (numw_pow_int). */
#define NUM_POW_ZERO_K 12u

#if FXRT_NUMBER == FXRT_Q16

typedef fx_t num_t;
typedef fxw_t numw_t;
typedef int16_t num_q14_t; /* a value below 2 kept small: Q2.14 (light/shadow.c's edges) */
#define NUM_NAME "q16"
#define NUM(x) F16(x) /* constant literal */
#define NUM_ZERO 0
#define NUM_ONE FX_ONE
#define NUM_MAX FX_MAX
#define NUM_EXACT 1 /* integer arithmetic: exact sums and products, every rounding stated */

static inline num_t num_add(num_t a, num_t b) { return fx_add(a, b); }
static inline num_t num_sub(num_t a, num_t b) { return fx_sub(a, b); }
static inline num_t num_neg(num_t a) { return fx_neg(a); }
static inline num_t num_mul(num_t a, num_t b) { return fx_mul(a, b); }
static inline num_t num_div(num_t a, num_t b) { return fx_div(a, b); }
static inline num_t num_sqrt(num_t a) { return fx_sqrt(a); }
/* 1 / sqrt(a) for a > 0 (fx_rsqrt: within 0.502 LSB; a <= 0 gives NUM_MAX). */
static inline num_t num_rsqrt(num_t a) { return fx_rsqrt(a); }
static inline num_t num_from_int(int32_t i) { return fx_from_int(i); }
/* A value and its Q16.16 bits (identities here; float and double round
 * half up to 2^-16 and hold every Q16.16 value below 2^24 exactly). */
static inline int32_t num_to_q16(num_t a) { return a; }
static inline num_t num_from_q16(int32_t q) { return q; }
/* a * i, exact for Q16.16 (the integer factor adds no rounding). */
static inline num_t num_mul_int(num_t a, int32_t i) { return fx_mul_int(a, i); }
/* a / 2, rounded to nearest, ties toward +infinity. */
static inline num_t num_half(num_t a) { return (fx_t)(((int64_t)a + 1) >> 1); }
static inline num_t num_cot_deg(num_t deg) { return fx_cot_deg(deg); }
static inline num_t num_cos_deg(num_t deg)
{
    FXRT_COUNT(cosines);
    return fx_cos_deg(deg);
}

static inline numw_t numw_mul(num_t a, num_t b) { return fx_smul32(a, b); }
/* numw_mul with u a unit vector's component (the same value; faster on
 * the M0: fx_smul_unit). */
static inline numw_t numw_mul_unit(num_t a, num_t u) { return fx_smul_unit(a, u); }
static inline numw_t numw_add(numw_t a, numw_t b) { return fxw_add(a, b); }
static inline numw_t numw_sub(numw_t a, numw_t b) { return fxw_add(a, b == INT64_MIN ? INT64_MAX : -b); }
/* a + b and a - b where the caller has shown that the exact result fits
 * numw_t (the bound is stated at each call): numw_add's and numw_sub's
 * value without their saturation tests. Modulo 2^64, never undefined. */
static inline numw_t numw_add_exact(numw_t a, numw_t b) { return (numw_t)((uint64_t)a + (uint64_t)b); }
static inline numw_t numw_sub_exact(numw_t a, numw_t b) { return (numw_t)((uint64_t)a - (uint64_t)b); }
/* acc + a u (numw_mul_unit's product), where the caller has shown that the
 * sum fits numw_t: no saturation test (numw_add_exact's rule). */
static inline numw_t numw_mla_unit(numw_t acc, num_t a, num_t u)
{
    if (FX_HAVE_UMULL)
        return fx_smlal32(acc, a, u);
    return numw_add_exact(acc, fx_smul_unit(a, u));
}
/* a . u for a unit vector u, given by components: numw_dot3_unit
 * (vec3_dotw_unit, any a) and numw_dot3_units (vec3_dotw_units, a unit
 * too). On the M0 a within |a_i| < 2^28 (fx_dot3_wide), or both within
 * [-2^18, 2^18) (fx_dot3_small), take 32-bit products with no signs: the
 * same exact value. Anything else takes numw_mul_unit's products. */
static inline __attribute__((always_inline)) numw_t numw_dot3_with(num_t ax, num_t ay, num_t az, num_t ux, num_t uy,
                                                                   num_t uz, bool units)
{
    if (!FX_HAVE_UMULL &&
        (units ? fx_dot3_small_ok(ax, ay, az, ux, uy, uz) : fx_dot3_wide_ok(ax, ay, az, ux, uy, uz)))
        return units ? fx_dot3_small(ax, ay, az, ux, uy, uz) : fx_dot3_wide(ax, ay, az, ux, uy, uz);
    return numw_mla_unit(numw_mla_unit(numw_mul_unit(ax, ux), ay, uy), az, uz);
}
static inline numw_t numw_dot3_unit(num_t ax, num_t ay, num_t az, num_t ux, num_t uy, num_t uz)
{
    return numw_dot3_with(ax, ay, az, ux, uy, uz, false);
}
static inline numw_t numw_dot3_units(num_t ax, num_t ay, num_t az, num_t ux, num_t uy, num_t uz)
{
    return numw_dot3_with(ax, ay, az, ux, uy, uz, true);
}
static inline numw_t numw_from(num_t a) { return fxw_from_fx(a); }
static inline num_t numw_round(numw_t w) { return fxw_round(w); }
/* numw_round for a value whose rounding the caller has shown to fit
 * num_t: the same value without the saturation tests. */
static inline num_t numw_round_fits(numw_t w) { return (fx_t)((w + FX_HALF) >> FX_FRAC_BITS); }
/* numw_round_fits(numw_mul_unit(a, u)), the same value (fx_mul_unit_fits). */
static inline num_t num_mul_unit_fits(num_t a, num_t u) { return fx_mul_unit_fits(a, u); }
/* numw_round(numw_mul_unit(a, u)), the same value (fx_mul_unit). */
static inline num_t num_mul_unit(num_t a, num_t u) { return fx_mul_unit(a, u); }
/* -a for a != the most negative num_t: num_neg's value, no test. */
static inline num_t num_neg_fits(num_t a) { return (fx_t)(0u - (uint32_t)a); }
/* -w for w > INT64_MIN: numw_sub(0, w) without its tests. */
static inline numw_t numw_neg_fits(numw_t w) { return numw_sub_exact(0, w); }
static inline num_t numw_sqrt(numw_t w) { return fxw_sqrt(w); }
static inline num_t numw_div(numw_t a, numw_t b) { return fxw_div(a, b); }
/* numw_div(a, b) for one a and many b (fxw_dividend_t). */
typedef fxw_dividend_t numw_dividend_t;
static inline numw_dividend_t numw_dividend(numw_t a) { return fxw_dividend(a); }
static inline num_t numw_div_by(const numw_dividend_t *a, numw_t b) { return fxw_div_by(a, b); }
/* a / b to scale several values by it, for one a and many b
 * (fxw_ratio_t): num_ratio_mul(&q, x) = x a / b within 0.5 LSB +
 * 2^-29 |x a / b|, with q = numw_ratio_by(&num, b), num = numw_ratio_num(a). */
typedef fxw_ratio_num_t numw_ratio_num_t;
typedef fxw_ratio_t numw_ratio_t;
static inline numw_ratio_num_t numw_ratio_num(numw_t a) { return fxw_ratio_num(a); }
static inline numw_ratio_t numw_ratio_by(const numw_ratio_num_t *a, numw_t b) { return fxw_ratio_by(a, b); }
static inline num_t num_ratio_mul(const numw_ratio_t *q, num_t x) { return fxw_ratio_mul(q, x); }
/* a * m / d kept wide (Q32.32, |error| <= 0.5 LSB of Q32.32), d > 0. Used
 * for per-pixel steps that must not accumulate rounding across a row. */
static inline numw_t numw_muldiv_int(num_t a, int32_t m, int32_t d)
{
    int64_t n = (int64_t)a * m * FX_ONE; /* |a| < 2^31, |m| <= 2^13: fits */
    int64_t h = d / 2;
    return (n >= 0 ? n + h : n - h) / d;
}
/* w * i, exact, saturating. */
static inline numw_t numw_mul_int(numw_t w, int32_t i)
{
    numw_t p;
    if (__builtin_mul_overflow(w, (int64_t)i, &p))
        return (w < 0) != (i < 0) ? INT64_MIN : INT64_MAX;
    return p;
}

/* a < t * b for wide a, b and a scalar t, exactly: a * 2^16 < t * b in
 * 128-bit integers (shadow rays' "t < tmax" without a division), compared
 * word by word (a * 2^16 needs no call: its words are a >> 48 and
 * a << 16). */
static inline bool numw_lt_mul(numw_t a, num_t t, numw_t b)
{
    fx128_t m = fx128_mul(t, b);
    int64_t hi = a >> 48; /* arithmetic shift: gcc and clang */
    uint64_t lo = (uint64_t)a << 16;
    return hi < m.hi || (hi == m.hi && lo < m.lo);
}

/* x^k for x in [0, 1] (given wide, clamped to [0, 1]) and an integer k
 * >= 1, by repeated squaring (no pow): Q16.16 works in unsigned Q1.31
 * with 32 x 32 -> 64-bit products rounded to nearest, so the ~log2(k)
 * roundings add below 2^-22 in all and the result is x^k within 0.51 LSB
 * of Q16.16 for the given x. */
static inline num_t numw_pow_loop(uint32_t b, uint32_t k)
{
    uint32_t acc = 0x80000000u; /* 1.0 in Q1.31 */
    while (k) {
        if (k & 1u) {
            acc = (uint32_t)((fx_umul32(acc, b) + 0x40000000u) >> 31);
            FXRT_COUNT(pow_products);
        }
        k >>= 1;
        if (k) {
            b = (uint32_t)((fx_usqr32(b) + 0x40000000u) >> 31);
            FXRT_COUNT(pow_products);
        }
    }
    return (fx_t)((acc + 0x4000u) >> 15);
}
/* The same, 0 without the products where x <= 1 - NUM_POW_ZERO_K / k: there
 * x^k <= e^-12 < 2^-17.3, and the loop's value is 0 too (tests/test_fx.c
 * proves it for every k up to FXRT_PHONG_MAX_EXPONENT at the largest such
 * x, and the loop is monotone in x). Most of a Phong surface lies there,
 * away from its highlight. */
static inline num_t numw_pow_int(numw_t x, uint32_t k)
{
    uint32_t b = x <= 0 ? 0u : (x >= ((int64_t)1 << 32) ? 0x80000000u : (uint32_t)((uint64_t)x >> 1));
    FXRT_COUNT(phong);
    if (k > NUM_POW_ZERO_K && fx_umul32(b, k) <= (uint64_t)(k - NUM_POW_ZERO_K) << 31)
        return 0;
    return numw_pow_loop(b, k);
}
/* Is numw_pow_int(x, k) surely 0 at x = a / |d|, for a wide a > 0 and
 * d2 = |d|^2 wide (the specular term's r . e along a raw direction d,
 * light/shade.c)? It is where x <= 1 - NUM_POW_ZERO_K / k;
 * fx_ratio_len_below proves x <= (1 - NUM_POW_ZERO_K / k)(1 - 2^-10) in
 * integers, which leaves room for the rounding of the x num_inv3_mul
 * would make from num_inv3_only's 1 / |d| (2 LSB, below the margin, which is above 2^-14 for every k
 * > NUM_POW_ZERO_K). false: not sure, or k too small to have such x. */
static inline bool numw_pow_zero_at(numw_t a, numw_t d2, uint32_t k)
{
    return k > NUM_POW_ZERO_K && fx_ratio_len_below(a, d2, k - NUM_POW_ZERO_K, k);
}

/* a b and a + b for a result that fits (the caller's bound): num_mul's
 * rounding without its saturation test, and a plain sum. On the M0 a
 * product a b with a >= 0 and 0 <= b <= 1 (a colour times a fraction)
 * takes two 32-bit products: (a_hi b) 2^16 + a_lo b with a_hi < 2^15 and
 * a_lo b <= (2^16 - 1) 2^16, so a_lo b + 2^15 fits 32 bits and the
 * rounding is fx_smul32's. */
static inline num_t num_mul_fits(num_t a, num_t b)
{
    if (!FX_HAVE_UMULL && a >= 0 && (uint32_t)b <= 0x10000u)
        return (fx_t)(((uint32_t)a >> 16) * (uint32_t)b + (((uint32_t)a & 0xffffu) * (uint32_t)b + 0x8000u) / 0x10000u);
    return (fx_t)((fx_smul32(a, b) + FX_HALF) >> FX_FRAC_BITS);
}
static inline num_t num_add_fits(num_t a, num_t b) { return (fx_t)((uint32_t)a + (uint32_t)b); }
/* a i for a result that fits (the caller's bound): the exact product, no
 * saturation test. */
static inline num_t num_mul_int_fits(num_t a, int32_t i) { return (fx_t)((uint32_t)a * (uint32_t)i); }
/* |d| > lim for 0 <= lim, |d| < 2^62: in one unsigned comparison (d + lim
 * lies in [0, 2 lim] exactly when |d| <= lim). */
static inline bool numw_abs_gt(numw_t d, numw_t lim) { return (uint64_t)d + (uint64_t)lim > 2 * (uint64_t)lim; }
/* c clamped to 0..255 and rounded half up (math/color.h, color_channel). */
static inline uint8_t num_channel8(num_t c) { return port_channel_q16(c); }
/* v / |v| in place, each component within 0.504 LSB (fx_normalize3: no
 * division, no 64-bit root), or false (v unchanged) for the zero vector;
 * num_normalize3_len also gives |v| within 2^-24 relative + 0.5 LSB
 * (fx_normalize3_len: no second root). */
static inline bool num_normalize3(num_t v[3]) { return fx_normalize3(v); }
static inline bool num_normalize3_len(num_t v[3], num_t *len) { return fx_normalize3_len(v, len); }
/* num_normalize3_len in two stages (fx_inv3_t): v's inverse length and
 * |v| (num_inv3), then the unit vector (num_inv3_unit) or a quotient
 * h / |v| for a wide h taken as numw_mant (num_inv3_mul). */
typedef fx_inv3_t num_inv3_t;
typedef fx_mant_t numw_mant_t;
static inline bool num_inv3(const num_t v[3], num_inv3_t *q, num_t *len) { return fx_inv3(v, q, len); }
/* num_inv3 without the length: 1 / |v| for num_inv3_mul. */
static inline bool num_inv3_only(const num_t v[3], num_inv3_t *q) { return fx_inv3(v, q, (fx_t *)0); }
static inline void num_inv3_unit(const num_inv3_t *q, const num_t v[3], num_t u[3]) { fx_inv3_unit(q, v, u); }
static inline numw_mant_t numw_mant(numw_t h) { return fx_mant64(h); }
/* Has h the sign of the side seen, negative for the back (inside), else
 * positive? (m's sign: fx_mant_t) */
static inline bool numw_mant_faces(numw_mant_t h, bool inside) { return inside ? h < 0 : h > 63; }
static inline num_t num_inv3_mul(const num_inv3_t *q, numw_mant_t h) { return fx_inv3_mul(q, h); }
/* A wide x (|x| < 2^44 LSB^2, so that (x >> 14) * 2 fits) kept to
 * 2^-3 LSB with a sticky bit (x's lower bits not all zero):
 * numw_sticky_round(s) = numw_round_fits(x), s has x's sign, and -s is
 * numw_sticky(-x), so one value serves either side of a plane, ties of
 * round half up included (light/shade.c). */
typedef int32_t numw_sticky_t;
static inline numw_sticky_t numw_sticky(numw_t x)
{
    return (numw_sticky_t)((x >> 14) * 2 + ((x & 0x3fff) != 0));
}
static inline num_t numw_sticky_round(numw_sticky_t s) { return (num_t)((s + 4) >> 3); }
/* A direction from an exact wide vector c (Q32.32): its components
 * divided by 2^shift (numw_direction_part), shift from
 * numw_direction_shift, scaled to 30 significant bits, so that a long c
 * (beyond the Q16.16 range) and a short one (a few LSB) both keep their
 * direction for normalising. */
static inline int numw_direction_shift(const numw_t c[3])
{
    uint64_t m = 0;
    for (int i = 0; i < 3; i++)
        m |= c[i] < 0 ? (uint64_t)0 - (uint64_t)c[i] : (uint64_t)c[i];
    int shift = 0;
    while ((m >> shift) >= ((uint64_t)1 << 30))
        shift++;
    return shift;
}
static inline num_t numw_direction_part(numw_t c, int shift) { return (fx_t)(c / ((int64_t)1 << shift)); }

#else /* float or double */

#if FXRT_NUMBER == FXRT_FLOAT
typedef float num_t;
#define NUM_NAME "float"
#define NUM(x) ((float)(x))
#define NUM_MAX __FLT_MAX__
static inline num_t num_sqrt(num_t a) { return a > 0 ? __builtin_sqrtf(a) : 0.0f; }
static inline uint8_t num_channel8(num_t c) { return port_channel_f32(c); }
/* A 32-bit key that grows with a > 0: the bits of a positive IEEE number
 * grow with it (a double's top 32 of them). */
static inline int32_t num_order_key(num_t a)
{
    union {
        float f;
        int32_t i;
    } u;
    u.f = a;
    return u.i;
}
#else
typedef double num_t;
#define NUM_NAME "double"
#define NUM(x) ((double)(x))
#define NUM_MAX __DBL_MAX__
static inline num_t num_sqrt(num_t a) { return a > 0 ? __builtin_sqrt(a) : 0.0; }
static inline uint8_t num_channel8(num_t c) { return !(c > 0.0) ? 0 : c >= 255.0 ? 255 : (uint8_t)(uint32_t)(c + 0.5); }
static inline int32_t num_order_key(num_t a)
{
    union {
        double f;
        int64_t i;
    } u;
    u.f = a;
    return (int32_t)(u.i >> 32);
}
#endif
typedef num_t numw_t;
typedef num_t num_q14_t; /* (Q16.16: Q2.14; here the value itself) */
#define NUM_ZERO NUM(0)
#define NUM_ONE NUM(1)
#define NUM_EXACT 0
/* 1 / sqrt(a), with the Q16.16 rule for a <= 0 (NUM_MAX). */
static inline num_t num_rsqrt(num_t a) { return a > NUM_ZERO ? NUM_ONE / num_sqrt(a) : NUM_MAX; }

static inline num_t num_add(num_t a, num_t b) { return a + b; }
static inline num_t num_sub(num_t a, num_t b) { return a - b; }
static inline num_t num_neg(num_t a) { return -a; }
static inline num_t num_mul(num_t a, num_t b) { return a * b; }
/* Division by zero follows the Q16.16 rule (saturate by sign, 0/0 = 0) so
 * that all three builds agree on degenerate input, and no build makes NaN. */
static inline num_t num_div(num_t a, num_t b)
{
    if (b == 0)
        return a > 0 ? NUM_MAX : (a < 0 ? -NUM_MAX : NUM_ZERO);
    return a / b;
}
static inline num_t num_from_int(int32_t i) { return (num_t)i; }
static inline int32_t num_to_q16(num_t a)
{
    num_t t = a * NUM(65536); /* exact: a power of two */
    int32_t i = (int32_t)t;
    if ((num_t)i > t)
        i--; /* floor */
    return t - (num_t)i >= NUM(0.5) ? i + 1 : i;
}
static inline num_t num_from_q16(int32_t q) { return (num_t)q * NUM(1.0 / 65536); }
static inline num_t num_mul_int(num_t a, int32_t i) { return a * (num_t)i; }
static inline num_t num_half(num_t a) { return a * NUM(0.5); }
num_t num_cot_deg(num_t deg);
num_t num_cos_deg(num_t deg); /* deg in [0, 90] */

static inline numw_t numw_mul(num_t a, num_t b) { return a * b; }
static inline numw_t numw_mul_unit(num_t a, num_t u) { return a * u; }
static inline numw_t numw_mla_unit(numw_t acc, num_t a, num_t u) { return acc + a * u; }
static inline numw_t numw_dot3_unit(num_t ax, num_t ay, num_t az, num_t ux, num_t uy, num_t uz)
{
    return ax * ux + ay * uy + az * uz;
}
static inline numw_t numw_dot3_units(num_t ax, num_t ay, num_t az, num_t ux, num_t uy, num_t uz)
{
    return numw_dot3_unit(ax, ay, az, ux, uy, uz);
}
static inline numw_t numw_add(numw_t a, numw_t b) { return a + b; }
static inline numw_t numw_sub(numw_t a, numw_t b) { return a - b; }
static inline numw_t numw_add_exact(numw_t a, numw_t b) { return a + b; }
static inline numw_t numw_sub_exact(numw_t a, numw_t b) { return a - b; }
static inline numw_t numw_from(num_t a) { return a; }
static inline num_t numw_round(numw_t w) { return w; }
static inline num_t numw_round_fits(numw_t w) { return w; }
static inline num_t num_mul_unit_fits(num_t a, num_t u) { return a * u; }
static inline num_t num_mul_unit(num_t a, num_t u) { return a * u; }
static inline num_t num_neg_fits(num_t a) { return -a; }
static inline numw_t numw_neg_fits(numw_t w) { return -w; }
static inline num_t numw_sqrt(numw_t w) { return num_sqrt(w); }
static inline num_t numw_div(numw_t a, numw_t b) { return num_div(a, b); }
typedef struct {
    numw_t a;
} numw_dividend_t;
static inline numw_dividend_t numw_dividend(numw_t a) { return (numw_dividend_t){a}; }
static inline num_t numw_div_by(const numw_dividend_t *a, numw_t b) { return num_div(a->a, b); }
typedef numw_t numw_ratio_num_t;
typedef num_t numw_ratio_t;
static inline numw_ratio_num_t numw_ratio_num(numw_t a) { return a; }
static inline numw_ratio_t numw_ratio_by(const numw_ratio_num_t *a, numw_t b) { return num_div(*a, b); }
static inline num_t num_ratio_mul(const numw_ratio_t *q, num_t x) { return *q * x; }
static inline numw_t numw_muldiv_int(num_t a, int32_t m, int32_t d) { return a * (num_t)m / (num_t)d; }
static inline numw_t numw_mul_int(numw_t w, int32_t i) { return w * (num_t)i; }
static inline bool numw_lt_mul(numw_t a, num_t t, numw_t b) { return a < t * b; }
static inline bool numw_abs_gt(numw_t d, numw_t lim) { return d > lim || d < -lim; }
static inline num_t num_mul_fits(num_t a, num_t b) { return a * b; }
static inline num_t num_add_fits(num_t a, num_t b) { return a + b; }
static inline num_t num_mul_int_fits(num_t a, int32_t i) { return a * (num_t)i; }
/* v / |v| in place (one square root, one division), or false for the
 * zero vector; with |v| into *len. */
static inline bool num_normalize3_len(num_t v[3], num_t *len)
{
    num_t l = num_sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (l == 0)
        return false;
    num_t inv = num_div(NUM_ONE, l);
    v[0] *= inv;
    v[1] *= inv;
    v[2] *= inv;
    *len = l;
    return true;
}
static inline bool num_normalize3(num_t v[3])
{
    num_t len;
    return num_normalize3_len(v, &len);
}
/* The two stages of num_normalize3_len (the Q16.16 build's num_inv3_t):
 * the caller sets inv = 1 / |v| (light/shade.c). */
typedef struct {
    num_t inv;
} num_inv3_t;
typedef numw_t numw_mant_t;
static inline void num_inv3_unit(const num_inv3_t *q, const num_t v[3], num_t u[3])
{
    u[0] = v[0] * q->inv;
    u[1] = v[1] * q->inv;
    u[2] = v[2] * q->inv;
}
static inline numw_mant_t numw_mant(numw_t h) { return h; }
static inline bool numw_mant_faces(numw_mant_t h, bool inside) { return inside ? h < 0 : h > 0; }
static inline num_t num_inv3_mul(const num_inv3_t *q, numw_mant_t h) { return h * q->inv; }
/* 1 / |v| (false for the zero vector), as written: one root, one division. */
static inline bool num_inv3_only(const num_t v[3], num_inv3_t *q)
{
    num_t l2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    if (!(l2 > NUM_ZERO))
        return false;
    q->inv = NUM_ONE / num_sqrt(l2);
    return true;
}
typedef numw_t numw_sticky_t;
static inline numw_sticky_t numw_sticky(numw_t x) { return x; }
static inline num_t numw_sticky_round(numw_sticky_t s) { return s; }
static inline int numw_direction_shift(const numw_t c[3])
{
    (void)c;
    return 0;
}
static inline num_t numw_direction_part(numw_t c, int shift)
{
    (void)shift;
    return c;
}
/* x^k for x clamped to [0, 1], k >= 1, by repeated squaring (no pow). */
static inline num_t numw_pow_int(numw_t x, uint32_t k)
{
    num_t b = x <= NUM_ZERO ? NUM_ZERO : (x >= NUM_ONE ? NUM_ONE : x), acc = NUM_ONE;
    FXRT_COUNT(phong);
    while (k) {
        if (k & 1u) {
            acc = acc * b;
            FXRT_COUNT(pow_products);
        }
        k >>= 1;
        if (k) {
            b = b * b;
            FXRT_COUNT(pow_products);
        }
    }
    return acc;
}
/* Never sure: x^k is 0 nowhere in (0, 1] here. */
static inline bool numw_pow_zero_at(numw_t a, numw_t d2, uint32_t k)
{
    (void)a, (void)d2, (void)k;
    return false;
}

#endif

static inline num_t num_abs(num_t a) { return a < NUM_ZERO ? num_neg(a) : a; }
static inline num_t num_min(num_t a, num_t b) { return a < b ? a : b; }
static inline num_t num_max(num_t a, num_t b) { return a > b ? a : b; }

#endif
