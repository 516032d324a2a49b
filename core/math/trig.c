/* trig: sine, cosine and cotangent of angles in degrees, in integers
 * (Taylor series in Q1.31 and Q2.30; no tables). See fx.h for the bounds. */
#include "math/fx_int.h"

/* cos(x) and sin(x)/x for x (radians, Q2.30, 0 <= x <= pi/2) by Taylor
 * series in unsigned Q2.30. Terms shrink fast (x^2 / ((2k+1)(2k+2)) < 1.24,
 * then < 0.21), so the loop ends after at most 14 terms; each term is
 * rounded once. sin(x)/x rather than sin(x) keeps full relative precision
 * for tiny angles, where x itself has few significant bits in Q2.30. The
 * alternating partial sums may dip below zero; unsigned arithmetic is
 * modular, so the final sums are still exact. */
static void fx_cos_sinc_q30(uint32_t x, uint64_t *cos_out, uint64_t *sinc_out)
{
    const uint64_t one = (uint64_t)1 << 30;
    uint64_t x2 = ((uint64_t)x * x + (one >> 1)) >> 30;
    uint64_t c = 0, s = 0;
    uint64_t tc = one, ts = one;
    for (uint32_t k = 0; tc != 0 || ts != 0; k++) {
        if (k & 1u) {
            c -= tc;
            s -= ts;
        } else {
            c += tc;
            s += ts;
        }
        tc = fx_udiv_round(((tc * x2) + (one >> 1)) >> 30, (uint64_t)(2 * k + 1) * (2 * k + 2));
        ts = fx_udiv_round(((ts * x2) + (one >> 1)) >> 30, (uint64_t)(2 * k + 2) * (2 * k + 3));
    }
    *cos_out = c;
    *sinc_out = s;
}

/* pi / 180 in Q19.45 (about 2^39.2). */
#define FX_DEG_TO_RAD_Q45 ((uint64_t)(3.14159265358979323846 / 180.0 * 35184372088832.0 + 0.5))

fx_t fx_cot_deg(fx_t deg)
{
    if (deg <= 0)
        return FX_MAX;
    if (deg >= F16(90.0))
        return 0;
    /* x = deg * pi/180 in Q2.30 feeds the series only. */
    uint32_t x = (uint32_t)(((uint64_t)deg * FX_DEG_TO_RAD_Q45 + ((uint64_t)1 << 30)) >> 31);
    uint64_t c, sinc;
    fx_cos_sinc_q30(x, &c, &sinc);
    /* cot = cos / (sinc * k * deg) with k = pi/180 and deg in Q16.16:
     * y = sinc * k in Q45 (< 2^40), q = cos * 2^33 / y = cos / (sinc k) in
     * Q18 (24+ significant bits), then cot in Q16.16 = q * 2^14 / deg. */
    const uint64_t k_hi = FX_DEG_TO_RAD_Q45 >> 20, k_lo = FX_DEG_TO_RAD_Q45 & 0xfffff;
    uint64_t y = ((sinc * k_hi) >> 10) + ((sinc * k_lo + ((uint64_t)1 << 29)) >> 30); /* no 2^70 product */
    uint64_t q = fx_udiv_round(c << 33, y);
    return fx_signed_sat(fx_udiv_round(q << 14, (uint64_t)deg), false);
}

/* Sine and cosine of degrees. The angle is reduced exactly in integers:
 * |deg| modulo 360 degrees (sin is odd, cos even), then to a quadrant and
 * a remainder r in [0, 90), then to [0, 45] by sin(90 - r) = cos(r). Only
 * the final [0, 45] angle is converted to radians (Q1.31, error <= 1 unit
 * of Q31 = 4.7e-10) and fed to Taylor polynomials in unsigned Q1.31 (sin to
 * x^9, cos to x^10: the first dropped terms are below 1.8e-9 at pi/4).
 * Written as nested 1 - u (c - u (...)) with u = x^2, every partial value is
 * positive, so each step is one unsigned 32 x 32 -> 64-bit product (UMULL,
 * or four 16-bit products on the M0) and no division. All Q31 roundings
 * together stay below 1e-8, i.e. below 0.001 LSB of Q16.16, so after the
 * final rounding the result is within 0.5 + 0.001 LSB of the exact value. */
#define FX_DEG90 ((uint32_t)90 << FX_FRAC_BITS)
#define FX_DEG45 ((uint32_t)45 << FX_FRAC_BITS)
#define FX_DEG360 ((uint32_t)360 << FX_FRAC_BITS)
#define FX_Q31_ONE ((uint32_t)1 << 31)

/* a * b / 2^31 (truncated) for Q1.31 values a, b <= 1. */
static inline uint32_t fx_mul_q31(uint32_t a, uint32_t b)
{
    return (uint32_t)(fx_umul32(a, b) >> 31);
}

/* sin (want_cos false) or cos (want_cos true) of r degrees (Q16.16),
 * 0 <= r <= 45 degrees, as Q1.31 in [0, 1], within 1e-8. */
static uint32_t fx_sincos45_q31(uint32_t r, bool want_cos)
{
    /* x = r pi/180 in Q31 = r * round(pi/180 2^37) / 2^22, r < 2^22. */
    uint32_t x = (uint32_t)(fx_umul32(r, 2398762259u) >> 22);
    uint32_t u = fx_mul_q31(x, x);
    uint32_t v;
    if (want_cos) {
        /* 1 - u (1/2! - u (1/4! - u (1/6! - u (1/8! - u / 10!)))), Q31. */
        v = 53261u - fx_mul_q31(u, 592u);
        v = 2982616u - fx_mul_q31(u, v);
        v = 89478485u - fx_mul_q31(u, v);
        v = 1073741824u - fx_mul_q31(u, v);
        v = FX_Q31_ONE - fx_mul_q31(u, v);
    } else {
        /* x (1 - u (1/3! - u (1/5! - u (1/7! - u / 9!)))). */
        v = 426088u - fx_mul_q31(u, 5918u);
        v = 17895697u - fx_mul_q31(u, v);
        v = 357913941u - fx_mul_q31(u, v);
        v = fx_mul_q31(x, FX_Q31_ONE - fx_mul_q31(u, v));
    }
    return v;
}

/* The same as Q16.16. */
static fx_t fx_sincos45(uint32_t r, bool want_cos)
{
    uint32_t v = fx_sincos45_q31(r, want_cos);
    v = (v + (1u << 14)) >> 15; /* Q31 -> Q16, ties toward +infinity */
    return v > (uint32_t)FX_ONE ? FX_ONE : (fx_t)v; /* a guard: the bound keeps v <= 1 */
}

/* sin(deg + quarter * 90 degrees), quarter 0 or 1. */
static fx_t fx_sin_quarter(fx_t deg, uint32_t quarter)
{
    bool neg = deg < 0;
    uint32_t a = neg ? 0u - (uint32_t)deg : (uint32_t)deg; /* |deg| <= 2^31 */
    /* a mod 360 degrees without a divide: 182 / 2^16 is just below
     * 1 / 360, so q is floor(a / 360 deg) or one less. */
    uint32_t q = ((a >> 16) * 182u) >> 16;
    a -= q * FX_DEG360;
    while (a >= FX_DEG360)
        a -= FX_DEG360;
    /* sin(-x) = sin(x + 180 degrees): negate by adding two quarters, and
     * cos(-x) = cos(x) = sin(x + 90): a cosine of a negative angle is the
     * cosine of |deg|. */
    uint32_t quad = 0;
    while (a >= FX_DEG90) {
        a -= FX_DEG90;
        quad++;
    }
    quad = (quad + quarter + (neg && !quarter ? 2u : 0u)) & 3u;
    /* sin(quad * 90 + r): quad 0 sin r, 1 cos r, 2 -sin r, 3 -cos r. */
    bool use_cos = (quad & 1u) != 0;
    if (a > FX_DEG45) {
        a = FX_DEG90 - a; /* sin(r) = cos(90 - r) and vice versa */
        use_cos = !use_cos;
    }
    fx_t v = fx_sincos45(a, use_cos);
    return quad >= 2 ? -v : v;
}

fx_t fx_sin_deg(fx_t deg)
{
    return fx_sin_quarter(deg, 0);
}

fx_t fx_cos_deg(fx_t deg)
{
    return fx_sin_quarter(deg, 1);
}

int32_t fx_cos_deg_q30(fx_t deg)
{
    if (deg <= 0)
        return (int32_t)1 << 30;
    if ((uint32_t)deg >= FX_DEG90)
        return 0;
    uint32_t a = (uint32_t)deg;
    uint32_t v = a > FX_DEG45 ? fx_sincos45_q31(FX_DEG90 - a, false) : fx_sincos45_q31(a, true);
    return (int32_t)((v + 1u) >> 1);
}
