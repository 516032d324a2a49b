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

#if FXRT_NUMBER == FXRT_Q16

typedef fx_t num_t;
typedef fxw_t numw_t;
#define NUM_NAME "q16"
#define NUM(x) F16(x) /* constant literal */
#define NUM_ZERO 0
#define NUM_ONE FX_ONE
#define NUM_MAX FX_MAX

static inline num_t num_add(num_t a, num_t b) { return fx_add(a, b); }
static inline num_t num_sub(num_t a, num_t b) { return fx_sub(a, b); }
static inline num_t num_neg(num_t a) { return fx_neg(a); }
static inline num_t num_mul(num_t a, num_t b) { return fx_mul(a, b); }
static inline num_t num_div(num_t a, num_t b) { return fx_div(a, b); }
static inline num_t num_sqrt(num_t a) { return fx_sqrt(a); }
/* 1 / sqrt(a) for a > 0 (fx_rsqrt: within 0.502 LSB; a <= 0 gives NUM_MAX). */
static inline num_t num_rsqrt(num_t a) { return fx_rsqrt(a); }
static inline num_t num_from_int(int32_t i) { return fx_from_int(i); }
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
static inline num_t numw_pow_int(numw_t x, uint32_t k)
{
    uint32_t b = x <= 0 ? 0u : (x >= ((int64_t)1 << 32) ? 0x80000000u : (uint32_t)((uint64_t)x >> 1));
    uint32_t acc = 0x80000000u; /* 1.0 in Q1.31 */
    FXRT_COUNT(phong);
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

#else /* float or double */

#if FXRT_NUMBER == FXRT_FLOAT
typedef float num_t;
#define NUM_NAME "float"
#define NUM(x) ((float)(x))
#define NUM_MAX __FLT_MAX__
static inline num_t num_sqrt(num_t a) { return a > 0 ? __builtin_sqrtf(a) : 0.0f; }
#else
typedef double num_t;
#define NUM_NAME "double"
#define NUM(x) ((double)(x))
#define NUM_MAX __DBL_MAX__
static inline num_t num_sqrt(num_t a) { return a > 0 ? __builtin_sqrt(a) : 0.0; }
#endif
typedef num_t numw_t;
#define NUM_ZERO NUM(0)
#define NUM_ONE NUM(1)
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
static inline numw_t numw_muldiv_int(num_t a, int32_t m, int32_t d) { return a * (num_t)m / (num_t)d; }
static inline numw_t numw_mul_int(numw_t w, int32_t i) { return w * (num_t)i; }
static inline bool numw_lt_mul(numw_t a, num_t t, numw_t b) { return a < t * b; }
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

#endif

static inline num_t num_abs(num_t a) { return a < NUM_ZERO ? num_neg(a) : a; }
static inline num_t num_min(num_t a, num_t b) { return a < b ? a : b; }
static inline num_t num_max(num_t a, num_t b) { return a > b ? a : b; }

#endif
