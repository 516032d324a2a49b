/* fx: Q16.16 fixed-point scalars, the number format of fxrt.
 *
 * Format: fx_t is a signed 32-bit integer holding value * 65536, so the
 * range is [-32768, 32768 - 2^-16] with a step (1 LSB) of 2^-16 = 1.53e-5.
 * fxw_t is a signed 64-bit integer in Q32.32: the exact product of two fx_t,
 * used to accumulate dot products before rounding once.
 *
 * Rounding: every operation that drops bits rounds to nearest. Each
 * function below states its error bound and its tie rule: products and
 * Q32.32 -> Q16.16 roundings take ties toward +infinity (add half an LSB,
 * then floor); divisions take ties away from zero; square roots cannot
 * meet a tie. Bounds are also listed in docs/ACCURACY.md; tests/test_fx.c
 * checks each against long double (and the tie rules exactly), and
 * tests/fx_exhaustive.c checks the one-argument roots and sin/cos over every
 * input.
 *
 * Overflow policy: SATURATE. A result outside the range becomes FX_MAX or
 * FX_MIN; nothing wraps and no signed overflow happens in C. Division by
 * zero saturates by the dividend's sign (0/0 = 0). The square root of a
 * negative number is 0. A saturated result is a legal value, so callers
 * that must tell the difference compare with FX_MAX / FX_MIN (scene loaders
 * keep inputs inside a domain where the renderer never saturates except
 * for far hits, see docs/ACCURACY.md).
 */
#ifndef FXRT_FX_H
#define FXRT_FX_H

#include <stdbool.h>
#include <stdint.h>

#include "fxrt_config.h"
#include "port/asm.h"

typedef int32_t fx_t;  /* Q16.16 */
typedef int64_t fxw_t; /* Q32.32 */

#define FX_FRAC_BITS 16
#define FX_ONE ((fx_t)0x00010000)
#define FX_HALF ((fx_t)0x00008000)
#define FX_MAX ((fx_t)INT32_MAX)
#define FX_MIN ((fx_t)INT32_MIN)
#define FX_PI ((fx_t)205887) /* round(pi * 65536) */

/* Literal for constant initialisers only: F16(1.5). Rounds to nearest,
 * ties away from zero.
 * Never use it on run-time values (it is floating-point arithmetic). */
#define F16(x) ((fx_t)((x) >= 0 ? (x) * 65536.0 + 0.5 : (x) * 65536.0 - 0.5))

/* Exact conversions. fx_from_int saturates outside [-32768, 32767]. */
static inline fx_t fx_from_int(int32_t i)
{
    if (i > 32767)
        return FX_MAX;
    if (i < -32768)
        return FX_MIN;
    return (fx_t)((uint32_t)i << FX_FRAC_BITS);
}

/* Clamp a 64-bit intermediate to the fx_t range. */
static inline fx_t fx_sat64(int64_t v)
{
    /* In range when the high word is the low word's sign extension (one
     * compare on ARM, where two 64-bit range compares took six
     * instructions). The narrowing keeps the low 32 bits, as gcc and
     * clang define it. */
    fx_t lo = (fx_t)(uint32_t)(uint64_t)v;
    if ((int64_t)lo == v)
        return lo;
    return v < 0 ? FX_MIN : FX_MAX;
}

/* a + b, a - b, -a: exact, saturating. On Armv6-M (Thumb-1) gcc tests
 * the overflow with three logic operations on the signs; the ADDS/SUBS
 * there sets the V flag, and PORT_SAT_ASM (gcc only, as the other assembly
 * here; clang takes the C) branches on it: two instructions
 * when nothing saturates. Its rare path forms a < 0 ? FX_MIN : FX_MAX as
 * 2^31 + ~(a >> 31) (b's register is a scratch copy). The same values:
 * tests/onboard_main.c checks them on the M0 against 64-bit C. */
static inline fx_t fx_add(fx_t a, fx_t b)
{
    return port_add_sat32(a, b);
}
static inline fx_t fx_sub(fx_t a, fx_t b)
{
    return port_sub_sat32(a, b);
}
static inline fx_t fx_neg(fx_t a)
{
    return a == FX_MIN ? FX_MAX : -a;
}
static inline fx_t fx_abs(fx_t a)
{
    return a < 0 ? fx_neg(a) : a;
}
/* Magnitude of an int32 as uint32, defined for INT32_MIN too. */
static inline uint32_t fx_uabs32(int32_t v)
{
    return v < 0 ? 0u - (uint32_t)v : (uint32_t)v;
}

/* 32 x 32 -> 64-bit products. The Cortex-M0 has no UMULL/SMULL, and
 * libgcc's __aeabi_lmul (what `(int64_t)a * b` becomes there) multiplies
 * 64 x 64 bits behind a call; four 16-bit products inline are cheaper.
 * FX_HAVE_UMULL (core/fxrt_config.h) selects the path.
 * Both are exact. */
static inline uint64_t fx_umul32(uint32_t a, uint32_t b)
{
    if (FX_HAVE_UMULL)
        return (uint64_t)a * b;
    uint32_t al = a & 0xffffu, ah = a >> 16, bl = b & 0xffffu, bh = b >> 16;
    uint32_t ll = al * bl, hh = ah * bh, lh = al * bh, hl = ah * bl;
    uint32_t mid = lh + hl;
    uint32_t hi = hh + (mid >> 16) + (mid < lh ? 0x10000u : 0u);
    uint32_t lo = ll + (mid << 16);
    hi += lo < ll ? 1u : 0u;
    return ((uint64_t)hi << 32) | lo;
}
/* a^2, exact: fx_umul32(a, a). On the M0 three 16-bit products instead of
 * four: with a = h 2^16 + l, a^2 = h^2 2^32 + h l 2^17 + l^2, where h l <
 * 2^32 splits into (h l) << 17 (mod 2^32) for the low word and (h l) >> 15
 * for the high one. */
static inline uint64_t fx_usqr32(uint32_t a)
{
    if (FX_HAVE_UMULL)
        return (uint64_t)a * a;
    uint32_t h = a >> 16, l = a & 0xffffu, m = h * l, ll = l * l;
    uint32_t lo = ll + (m << 17);
    uint32_t hi = h * h + (m >> 15) + (lo < ll ? 1u : 0u);
    return ((uint64_t)hi << 32) | lo;
}
/* Signed: the unsigned product of the two's-complement patterns, minus
 * b 2^32 when a < 0 and a 2^32 when b < 0 (modulo 2^64). */
static inline int64_t fx_smul32(int32_t a, int32_t b)
{
    if (FX_HAVE_UMULL)
        return port_smul32(a, b);
    uint64_t p = fx_umul32((uint32_t)a, (uint32_t)b);
    uint32_t hi = (uint32_t)(p >> 32);
    if (a < 0)
        hi -= (uint32_t)b;
    if (b < 0)
        hi -= (uint32_t)a;
    return (int64_t)(((uint64_t)hi << 32) | (uint32_t)p);
}
/* acc + a b, where the caller has shown that the sum fits int64 (modulo
 * 2^64 otherwise, never undefined): one SMLAL on Thumb-2. */
static inline int64_t fx_smlal32(int64_t acc, int32_t a, int32_t b)
{
    if (FX_HAVE_UMULL)
        return port_smlal32(acc, a, b);
    return (int64_t)((uint64_t)acc + (uint64_t)fx_smul32(a, b));
}
/* a * u, exact, for any a and u; fastest when |u| <= 2^16 = 1.0, a
 * component of a unit vector (normals, ray and light directions, 1.0
 * included: an axis-aligned plane's or box face's normal): on the M0 two
 * 16 x 16 -> 32-bit products (a's halves times |u|) instead of
 * fx_smul32's four and its sign corrections. Any other u takes fx_smul32. */
static inline int64_t fx_smul_unit(int32_t a, int32_t u)
{
    uint32_t ua = fx_uabs32(a), uu = fx_uabs32(u);
    if (FX_HAVE_UMULL || uu > 0x10000u)
        return fx_smul32(a, u);
    /* (ua >> 16) uu <= 2^15 2^16 and (ua & 0xffff) uu <= (2^16 - 1) 2^16:
     * both fit 32 bits, no overflow. */
    uint64_t p = ((uint64_t)((ua >> 16) * uu) << 16) + (uint64_t)((ua & 0xffffu) * uu);
    return (a < 0) != (u < 0) ? -(int64_t)p : (int64_t)p;
}

/* a . u for two vectors whose components lie in [-2^18, 2^18) (unit
 * vectors': normals, ray and light directions, Phong's r), exact, from
 * 32-bit products only, with no sign handling: a_i = h_i 2^8 + l_i with
 * h_i = a_i >> 8 (arithmetic, |h_i| <= 2^10) and l_i = a_i & 0xff, so
 * a . u = 2^8 sum h_i u_i + sum l_i u_i, the sums below 3 2^28 and
 * 3 2^26 in magnitude. The M0's unit dot products: six multiplies
 * instead of three products with their signs and 64-bit sums. */
static inline int64_t fx_dot3_small(int32_t a0, int32_t a1, int32_t a2, int32_t u0, int32_t u1, int32_t u2)
{
    int32_t hs = (a0 >> 8) * u0 + (a1 >> 8) * u1 + (a2 >> 8) * u2;
    int32_t ls = (a0 & 0xff) * u0 + (a1 & 0xff) * u1 + (a2 & 0xff) * u2;
    return (int64_t)((uint64_t)(int64_t)hs << 8) + ls;
}
/* Do a0..a2 and u0..u2 all lie in [-2^18, 2^18) (fx_dot3_small's range)?
 * x + 2^18 lies in [0, 2^19) exactly then, modulo 2^32; so does the OR of
 * six such values exactly when each does. */
static inline bool fx_dot3_small_ok(int32_t a0, int32_t a1, int32_t a2, int32_t u0, int32_t u1, int32_t u2)
{
    const uint32_t k = (uint32_t)1 << 18;
    return (((uint32_t)a0 + k) | ((uint32_t)a1 + k) | ((uint32_t)a2 + k) | ((uint32_t)u0 + k) | ((uint32_t)u1 + k) |
            ((uint32_t)u2 + k)) < 2 * k;
}

/* a . u for |a_i| < 2^28 (4096.0: a scene's differences of points) and
 * u_i in [-2^17, 2^17) (a unit vector), exact, from 32-bit products: as
 * fx_dot3_small with a_i = h_i 2^16 + m_i 2^8 + l_i (h_i = a_i >> 16,
 * |h_i| < 2^12; m_i, l_i bytes), three sums below 3 2^29 in magnitude. */
static inline int64_t fx_dot3_wide(int32_t a0, int32_t a1, int32_t a2, int32_t u0, int32_t u1, int32_t u2)
{
    int32_t hs = (a0 >> 16) * u0 + (a1 >> 16) * u1 + (a2 >> 16) * u2;
    int32_t ms = ((a0 >> 8) & 0xff) * u0 + ((a1 >> 8) & 0xff) * u1 + ((a2 >> 8) & 0xff) * u2;
    int32_t ls = (a0 & 0xff) * u0 + (a1 & 0xff) * u1 + (a2 & 0xff) * u2;
    return (int64_t)((uint64_t)(int64_t)hs << 16) + (int64_t)((uint64_t)(int64_t)ms << 8) + ls;
}
/* fx_dot3_wide's range: |a_i| < 2^28 and u_i in [-2^17, 2^17). */
static inline bool fx_dot3_wide_ok(int32_t a0, int32_t a1, int32_t a2, int32_t u0, int32_t u1, int32_t u2)
{
    const uint32_t ka = (uint32_t)1 << 28, ku = (uint32_t)1 << 17;
    return (((uint32_t)a0 + ka) | ((uint32_t)a1 + ka) | ((uint32_t)a2 + ka)) < 2 * ka &&
           (((uint32_t)u0 + ku) | ((uint32_t)u1 + ku) | ((uint32_t)u2 + ku)) < 2 * ku;
}

/* a * i modulo 2^64 for a small factor, |i| < 2^15 (pixel offsets): the
 * scanline forms' evaluation. On the M0 three 32-bit products (a's low word
 * in 16-bit halves, its high word modulo 2^32) instead of __aeabi_lmul. */
static inline uint64_t fx_umul64_small(uint64_t a, int32_t i)
{
    if (FX_HAVE_UMULL)
        return a * (uint64_t)(int64_t)i;
    uint32_t al = (uint32_t)a, ah = (uint32_t)(a >> 32);
    int32_t a1 = (int32_t)(al >> 16), a0 = (int32_t)(al & 0xffffu);
    uint64_t lo = ((uint64_t)(int64_t)(a1 * i) << 16) + (uint64_t)(int64_t)(a0 * i); /* al * i */
    return lo + ((uint64_t)(ah * (uint32_t)i) << 32);
}
/* w[0] + w[1] i + w[2] j modulo 2^64 for small factors, |i|, |j| < 2^15:
 * a linear form of the pixel offsets (the scanline loops' rlin_at). On
 * Armv6-M with gcc, 34 instructions of inline assembly: per factor, the
 * low word's 16-bit halves times it (each product below 2^31 in magnitude)
 * added with its sign into the 64-bit sum, and the high word times it
 * (modulo 2^32) into the sum's high word. gcc's code took about 70 (61
 * with these sums written in C), with high registers spilled. Armv7-M
 * (the M3, M4F) has its own below; other targets and compilers take the C
 * (fx_umul64_small). tests/onboard_main.c checks the assembly against
 * 64-bit C products on every board. */
#if PORT_HAVE_LIN2
/* Armv6-M and Armv7-M: port/asm.h (port_lin2_small). */
static inline __attribute__((always_inline)) uint64_t fx_lin2_small(const int64_t w[3], int32_t i, int32_t j)
{
    return port_lin2_small(w, i, j);
}
#else
static inline uint64_t fx_lin2_small(const int64_t w[3], int32_t i, int32_t j)
{
    return (uint64_t)w[0] + fx_umul64_small((uint64_t)w[1], i) + fx_umul64_small((uint64_t)w[2], j);
}
#endif
/* a * i for a small factor, |i| < 2^15 (pixel offsets): exact. On the M0
 * two 32-bit products of a's halves (each below 2^31 in magnitude) instead
 * of four 16-bit ones. */
static inline int64_t fx_smul_small(int32_t a, int32_t i)
{
    if (FX_HAVE_UMULL)
        return (int64_t)a * i;
    int32_t hi = a >> 16; /* arithmetic shift: a = hi 2^16 + lo */
    int32_t lo = (int32_t)((uint32_t)a & 0xffffu);
    return (int64_t)((uint64_t)(int64_t)(hi * i) << 16) + lo * i;
}

/* a * b, |error| <= 0.5 LSB, ties toward +infinity (-0.5 LSB -> 0),
 * saturating. The 64-bit product is exact. */
static inline fx_t fx_mul(fx_t a, fx_t b)
{
    int64_t p = fx_smul32(a, b);
    /* >> of a negative int64 is an arithmetic shift on every compiler we
     * support (gcc, clang); it floors, and the +half turns that into
     * round-to-nearest. */
    return fx_sat64((p + FX_HALF) >> FX_FRAC_BITS);
}

/* a * i for an integer i: exact, saturating. */
static inline fx_t fx_mul_int(fx_t a, int32_t i)
{
    return fx_sat64(fx_smul32(a, i));
}

/* Q32.32 -> Q16.16, |error| <= 0.5 LSB, ties toward +infinity, saturating. */
static inline fx_t fxw_round(fxw_t w)
{
    /* floor((w + 1/2 LSB) / 2^16) without the addition's overflow: the
     * floor of w / 2^16 plus w's bit 15 (the fraction is >= 1/2). */
    return fx_sat64((w >> FX_FRAC_BITS) + ((w >> (FX_FRAC_BITS - 1)) & 1));
}

/* a * u rounded as fx_mul rounds (ties toward +infinity), for a result
 * the caller has shown to fit (no saturation test); fastest for |u| <=
 * 2^16, a unit vector's component: on the M0 the rounding is folded into
 * fx_smul_unit's two 32-bit products, A = (|a| >> 16) |u| and
 * B = (|a| & 0xffff) |u| (|a u| = A 2^16 + B, B + 2^15 < 2^32): the
 * magnitude rounds to A + (B + 2^15) / 2^16, or A + (B + 2^15 - 1) / 2^16
 * when the product is negative (then ties go toward zero in magnitude),
 * without 64-bit additions and shifts. */
static inline __attribute__((always_inline)) fx_t fx_mul_unit_impl(fx_t a, fx_t u, bool sat)
{
    uint32_t ua = fx_uabs32(a), uu = fx_uabs32(u);
    if (!FX_HAVE_UMULL && uu <= 0x10000u) {
        uint32_t neg = (a < 0) != (u < 0) ? 1u : 0u;
        /* A <= 2^31 and the fraction's carry < 2^16: q < 2^32. */
        uint32_t q = (ua >> 16) * uu + (((ua & 0xffffu) * uu + 0x8000u - neg) >> 16);
        if (sat && q > (uint32_t)INT32_MAX)
            return neg ? FX_MIN : FX_MAX; /* -2^31 itself is FX_MIN: no exception */
        return (fx_t)(neg ? 0u - q : q);
    }
    int64_t w = fx_smul32(a, u);
    return sat ? fxw_round(w) : (fx_t)((w + FX_HALF) >> FX_FRAC_BITS);
}
static inline fx_t fx_mul_unit_fits(fx_t a, fx_t u)
{
    return fx_mul_unit_impl(a, u, false);
}
/* a * u rounded and saturated as fx_mul, for any a and u; fastest for
 * |u| <= 2^16 (fx_mul_unit_fits' folded rounding, then the saturation
 * test on the magnitude). */
static inline fx_t fx_mul_unit(fx_t a, fx_t u)
{
    return fx_mul_unit_impl(a, u, true);
}

/* Q16.16 -> Q32.32, exact. */
static inline fxw_t fxw_from_fx(fx_t a)
{
    return (fxw_t)a * FX_ONE;
}

/* a + b in Q32.32, saturating at the int64 range. */
static inline fxw_t fxw_add(fxw_t a, fxw_t b)
{
    fxw_t s;
    if (__builtin_add_overflow(a, b, &s))
        return a < 0 ? INT64_MIN : INT64_MAX;
    return s;
}

/* a / b correctly rounded: |error| <= 0.5 LSB, ties away from zero
 * (1 LSB / 2.0 = 1 LSB, -1 LSB / 2.0 = -1 LSB), saturating; x/0 saturates
 * by sign, 0/0 = 0. 32-bit operations only (Knuth's long division in two
 * 16-bit digits; on the Cortex-M0 each digit is estimated by a reciprocal
 * from a 256-byte table, so no libgcc division is called). */
fx_t fx_div(fx_t a, fx_t b);

/* floor(n / d), exact, for d > 0 and n < d 2^32 (the quotient fits 32
 * bits; the caller checks n >> 32 < d): fx_div's two 16-bit digits of
 * Knuth's division on the divisor normalised, instead of libgcc's 64-bit
 * division (about 50 instructions on the M3, 300 on the M0). */
uint32_t fx_udiv64_32(uint64_t n, uint32_t d);

/* sqrt(a) correctly rounded, |error| <= 0.5 LSB (no ties are possible:
 * a 2^16 is an integer, (r + 1/2)^2 is not); sqrt of a negative value is 0.
 * Checked for all 2^31 non-negative inputs (make fx-exhaustive). 32-bit
 * multiplies only: a 192-byte table, two Newton steps, an exact residual
 * test. */
fx_t fx_sqrt(fx_t a);

/* 1 / sqrt(a) for a > 0, |error| <= 0.502 LSB (0.50094 LSB worst over
 * every input, make fx-exhaustive). Not always correctly rounded: the
 * result is the rounding (ties toward +infinity) of a value within 2^-25
 * relative, so a near-tie may round either way; exact ties cannot occur.
 * a <= 0 gives FX_MAX. Results lie in [362, 2^24] (362 for FX_MAX). The same table and
 * Newton steps as fx_sqrt plus one Newton step in three 32x32->64-bit
 * products; no division. */
fx_t fx_rsqrt(fx_t a);
/* Significant bits of |v| (0 for 0), and round(v / 2^s) for 0 <= s < 63,
 * ties away from zero (v itself for s <= 0; |v| < 2^62): fx128_bits and
 * fx128_shr_round for 64-bit values, without their 128-bit work (a plane
 * run's set-up, light/shade.c: through those, the M3's shadows scene took
 * 7 instructions per pixel more). */
int fx_bits64(int64_t v);
int64_t fx_shr_round64(int64_t v, int s);
/* round(a b 2^e / sqrt(P)) in raw units for P > 0, a < 2^26, b < 2^31,
 * saturated at FX_MAX: within 0.5 LSB + 2^-23 relative (the inverse
 * root's 2^-25, the 32 bits kept of P and of b Y). A plane's n . l along
 * a run (light/shade.c, shade_plane_forms): the height times |n . d| over
 * |W| = sqrt(P), P stepped exactly. One inverse root, two products. */
fx_t fx_mul_rsqrt64(uint32_t a, uint32_t b, int e, uint64_t P);

/* floor(sqrt(n)) for any 64-bit unsigned n (exact). */
uint32_t fx_isqrt64(uint64_t n);

/* sqrt of a non-negative Q32.32 value as Q16.16, correctly rounded
 * (|error| <= 0.5 LSB, no ties possible), saturating at FX_MAX; negative
 * input gives 0. */
fx_t fxw_sqrt(fxw_t w);

/* Q32.32 / Q32.32 as Q16.16, |error| <= 1 LSB (operands with more than 47
 * significant bits lose their low bits first; the final division rounds
 * ties away from zero), saturating; x/0 saturates by sign, 0/0 = 0. */
fx_t fxw_div(fxw_t a, fxw_t b);
/* fxw_div(a, b) for one a and many b: fxw_div_by(&q, b) with
 * q = fxw_dividend(a) has the same value, without a's share of the work
 * (its magnitude's normalisation) at every division. */
typedef struct {
    uint64_t n;     /* |a| shifted up by k <= 16 (2^62 for a = INT64_MIN) */
    int8_t dshift;  /* 16 - k: the bits the divisor loses */
    int8_t sign;    /* of a: -1, 0 or 1 */
} fxw_dividend_t;
fxw_dividend_t fxw_dividend(fxw_t a);
fx_t fxw_div_by(const fxw_dividend_t *a, fxw_t b);

/* a / b as a binary float, to scale several values by it (light/hit.c: a
 * camera ray's point on a plane), for one a and many b:
 * q = fxw_ratio_by(&num, b) with num = fxw_ratio_num(a) holds |a / b| as
 * m 2^-e, m in [2^29, 2^31] within 1.5 2^-30 relative (the divisor's top 32
 * bits, the quotient rounded), and fxw_ratio_mul(&q, x) is round(m |x|
 * 2^-e) (ties up in magnitude) with the sign of x a / b, saturating: within
 * 0.5 LSB + 2^-29 |x a / b|. b = 0 saturates every non-zero product by
 * sign; a = 0 gives 0. */
typedef struct {
    uint64_t n;    /* |a| 2^s, in [2^61, 2^62) */
    int16_t s;     /* -1 .. 62 */
    int8_t sign;   /* of a: -1, 0 or 1 */
} fxw_ratio_num_t;
typedef struct {
    uint32_t m;
    int16_t e;     /* -33 .. 93, or FXW_RATIO_INF (b = 0) */
    int32_t neg;   /* 0, or -1 when a / b < 0 */
} fxw_ratio_t;
#define FXW_RATIO_INF INT16_MIN
fxw_ratio_num_t fxw_ratio_num(fxw_t a);
fxw_ratio_t fxw_ratio_by(const fxw_ratio_num_t *a, fxw_t b);
fx_t fxw_ratio_mul_wide(const fxw_ratio_t *q, fx_t x);
/* Inline where e is 33 .. 63 (the rounding bit in the product's high
 * word, as in fx_normalize3): one 32 x 32 product; otherwise
 * fxw_ratio_mul_wide, the same rule. */
static inline fx_t fxw_ratio_mul(const fxw_ratio_t *q, fx_t x)
{
    uint32_t k = (uint32_t)(q->e - 33);
    if (k > 30u)
        return fxw_ratio_mul_wide(q, x);
    uint32_t hi = (uint32_t)(fx_umul32(q->m, fx_uabs32(x)) >> 32); /* < 2^30 */
    uint32_t v = (hi + ((uint32_t)1 << k)) >> (k + 1);
    uint32_t s = (uint32_t)(q->neg ^ (x < 0 ? -1 : 0));
    return (fx_t)((v ^ s) - s);
}

/* 1 / a = fx_div(FX_ONE, a): correctly rounded (|error| <= 0.5 LSB; a tie
 * would need a to divide 2^33 oddly, which no fx_t does), saturating
 * (1/0 = FX_MAX). */
fx_t fx_recip(fx_t a);

/* cot(deg degrees) for deg in (0, 90]: |error| <= 1 LSB + 1e-7 relative
 * (the rounding of an approximate quotient: no tie rule applies).
 * Outside (0, 90] it saturates: deg <= 0 gives FX_MAX, deg > 90 gives 0.
 * Computed from sine and cosine series in Q2.30, so it needs no tables. */
fx_t fx_cot_deg(fx_t deg);

/* sin and cos of an angle in degrees (Q16.16, any value: it is reduced
 * exactly modulo 360 in integers), as Q16.16. |error| <= 0.502 LSB: the
 * rounding (ties toward +infinity) of a value accurate to 1e-8, so a
 * near-tie may round either way; the worst over every input of a full turn
 * is 0.50011 LSB (make fx-exhaustive). Exact at multiples of 90 degrees
 * (0, 1, -1), never above 1.0 in magnitude, and odd/even exactly:
 * fx_sin_deg(-d) = -fx_sin_deg(d), fx_cos_deg(-d) = fx_cos_deg(d).
 * Integer-only, no tables, no division (unsigned Q1.31 Taylor polynomials
 * on [0, 45] degrees, 32x32->64-bit products). */
fx_t fx_sin_deg(fx_t deg);
fx_t fx_cos_deg(fx_t deg);

/* cos(deg degrees) for deg in [0, 90] (clamped) in Q2.30, within 2^-30 +
 * 1e-8: the spot light's cone test, which needs more than Q16.16. */
int32_t fx_cos_deg_q30(fx_t deg);

/* v / |v| in Q2.30 (each component within ~2^-29), or false for the zero
 * vector. Set-up only: a 64-bit division per component. */
bool fx_unit30(const fx_t v[3], int32_t out[3]);

/* A signed 128-bit integer for exact set-up arithmetic on 32-bit targets
 * (which have no __int128): two's complement, hi:lo. */
typedef struct {
    uint64_t lo;
    int64_t hi;
} fx128_t;

static inline fx128_t fx128_from64(int64_t v)
{
    fx128_t r = {(uint64_t)v, v < 0 ? -1 : 0};
    return r;
}
/* *dst = *src field by field: gcc copies a whole 16-byte struct with a
 * memcpy call on Armv6-M. */
static inline void fx128_copy(fx128_t *dst, const fx128_t *src)
{
    dst->lo = src->lo;
    dst->hi = src->hi;
}
#if PORT_HAVE_CHAIN128
static inline __attribute__((always_inline)) fx128_t fx128_add(fx128_t a, fx128_t b)
{
    fx128_t r;
    PORT_CHAIN128(r, a, b, "adds", "adcs", "adc");
    return r;
}
#else
static inline fx128_t fx128_add(fx128_t a, fx128_t b)
{
    fx128_t r;
    r.lo = a.lo + b.lo;
    r.hi = (int64_t)((uint64_t)a.hi + (uint64_t)b.hi + (r.lo < a.lo ? 1u : 0u));
    return r;
}
#endif
/* *a += *b (mod 2^128). On Armv6-M four ADD/ADC on the words in memory
 * (gcc builds the carries of fx128_add from compares there, with spills:
 * about twice the instructions in a sphere's per-column stepping loop).
 * gcc assembles Thumb-1 inline assembly in divided syntax (unless given
 * -masm-syntax-unified), where ADD of three low registers and ADC set the
 * flags; other compilers take the C. */
static inline __attribute__((always_inline)) void fx128_add_to(fx128_t *a, const fx128_t *b)
{
#if PORT_HAVE_ADD128_TO
    PORT_ADD128_TO(a, b);
#else
    *a = fx128_add(*a, *b);
#endif
}
static inline fx128_t fx128_neg(fx128_t a)
{
    fx128_t r;
    r.lo = ~a.lo + 1u;
    r.hi = (int64_t)(~(uint64_t)a.hi + (r.lo == 0 ? 1u : 0u));
    return r;
}
#if PORT_HAVE_CHAIN128
static inline __attribute__((always_inline)) fx128_t fx128_sub(fx128_t a, fx128_t b)
{
    fx128_t r;
    PORT_CHAIN128(r, a, b, "subs", "sbcs", "sbc");
    return r;
}
#else
static inline fx128_t fx128_sub(fx128_t a, fx128_t b)
{
    return fx128_add(a, fx128_neg(b));
}
#endif
/* a * b, exact. */
fx128_t fx128_mul(int64_t a, int64_t b);
fx128_t fx128_sqr(int64_t a); /* a * a */
/* a * 2^s for 0 <= s < 128, exact when the result fits. */
fx128_t fx128_shl(fx128_t a, int s);
/* round(a / 2^s) for 0 <= s < 127, ties away from zero, saturated to the
 * int64 range. */
int64_t fx128_shr_round(fx128_t a, int s);
/* round(a / 2^s) as a 128-bit value, ties away from zero, 0 <= s < 127. */
fx128_t fx128_shr128(fx128_t a, int s);
/* Number of significant bits of |a| (0 for 0). */
int fx128_bits(fx128_t a);

/* Scale (x, y, z) to unit length in place, each component within
 * 0.504 LSB of the exact result for any non-zero input (0.5 for the final
 * rounding, ties away from zero, plus 2^-9 for the inverse square root).
 * The vector is first shifted to use 30 bits, so short vectors normalise
 * as well as long ones. No division and no 64-bit root: fx_rsqrt's
 * Newton steps on the top 32 bits of the squared length.
 * Returns false and leaves the vector unchanged when it is zero. */
bool fx_normalize3(fx_t v[3]);
/* The same, and *len = |(x, y, z)| (saturated at FX_MAX) from the same
 * inverse square root: within 2^-24 relative plus 0.5 LSB (the inverse
 * root's error, not a correctly rounded fxw_sqrt), for shading's light
 * distance. len must not be NULL; *len is not written when the vector is
 * zero. */
bool fx_normalize3_len(fx_t v[3], fx_t *len) __attribute__((nonnull));

/* fx_normalize3_len in two stages, for a caller that may not need the
 * unit vector: fx_inv3 keeps v's inverse length (and gives *len when len
 * is not NULL, fx_normalize3_len's value); fx_inv3_unit then gives
 * fx_normalize3's unit vector into u, and fx_inv3_mul a quotient
 * H / |v| in Q16.16 for a wide H (fx_mant64), without the unit vector:
 * shading's n . l = n . (L - p) / |L - p| on a plane (light/shade.c).
 * fx_inv3 returns false, q unset, for the zero vector. */
typedef struct {
    uint32_t s[3]; /* |v_i| 2^shift, the largest in [2^29, 2^30) */
    uint32_t Y;    /* ~ 2^(61 or 60) / |s| (big or not) */
    int8_t shift;
    bool big;
} fx_inv3_t;
bool fx_inv3(const fx_t v[3], fx_inv3_t *q, fx_t *len);
/* Is x = a / sqrt(d2) at most (num / den)(1 - 2^-10), surely? a and d2
 * are wide values with d2 > 0 (Q32.32: a dot product a . v and |v|^2, so
 * x = a . v / |v|), num <= den <= 1024. Exact integer bounds on the top
 * bits of a and d2: true only where it holds; false where it may not
 * (within a relative 2^-14 or so of the bound) or the arguments are out
 * of range. a <= 0 is below. */
bool fx_ratio_len_below(fxw_t a, fxw_t d2, uint32_t num, uint32_t den);
void fx_inv3_unit(const fx_inv3_t *q, const fx_t v[3], fx_t u[3]);
/* A 64-bit integer H, |H| < 2^56, as m 2^e in 32 bits (4 bytes of RAM
 * per plane and light where the frame keeps it): bits 31..6 the signed
 * mantissa m, |m| in [2^24, 2^25) (truncated: within 2^-24 relative) or 0
 * for H = 0, bits 5..0 e + 32. */
typedef int32_t fx_mant_t;
fx_mant_t fx_mant64(int64_t h);
static inline int32_t fx_mant_m(fx_mant_t h) { return (h - (h & 63)) / 64; } /* (exact) */
static inline int fx_mant_e(fx_mant_t h) { return (int)((uint32_t)h & 63u) - 32; }
/* round(H / |v_raw|) for H = fx_mant_m(h) 2^fx_mant_e(h) and v_raw the raw
 * integers of fx_inv3's vector, saturated: with H in Q32.32 units, the
 * Q16.16 value of H / |v|, within 0.5 LSB + 2^-23 relative (m's 2^-24
 * and Y's 2^-25). 1 / |v_raw| = 2^shift / |s| = Y 2^(shift - 46 - k),
 * k = 15 (big) or 14 (fx.c, fx_inv3_len), so H / |v_raw| = |m| Y 2^-E
 * with E = 46 + k - e - shift, and |m| Y < 2^25 2^31. Rounded once, half
 * away from zero, like the unit vector's components: for E >= 33 the
 * rounding bit lies in the high word, which the low word cannot carry
 * into. Inline: one product. */
static inline fx_t fx_inv3_mul(const fx_inv3_t *q, fx_mant_t h)
{
    int32_t hm = fx_mant_m(h);
    uint32_t r, m = fx_uabs32(hm);
    uint64_t p = fx_umul32(m, q->Y);
    int E = (q->big ? 61 : 60) - fx_mant_e(h) - q->shift;
    if (__builtin_expect(E >= 33 && E < 64, 1)) {
        uint32_t hi = (uint32_t)(p >> 32);
        r = (hi + ((uint32_t)1 << (E - 33))) >> (E - 32);
    } else if (E >= 64) {
        r = 0; /* p 2^-E < 2^-2 (and m = 0 gives 0) */
    } else if (E >= 1) {
        uint64_t r64 = (p + ((uint64_t)1 << (E - 1))) >> E;
        r = r64 > (uint64_t)FX_MAX ? (uint32_t)FX_MAX : (uint32_t)r64;
    } else {
        r = m ? (uint32_t)FX_MAX : 0; /* at least 2^24 2^30: saturated */
    }
    return hm < 0 ? -(fx_t)r : (fx_t)r;
}

#endif
