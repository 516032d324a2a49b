/* fx: Q16.16 operations that are too large to inline. See fx.h for formats,
 * rounding and the overflow policy. */
#include "fx.h"

/* Magnitude of an int64 as uint64, defined for INT64_MIN too. */
static uint64_t fx_uabs64(int64_t v)
{
    return v < 0 ? (uint64_t)0 - (uint64_t)v : (uint64_t)v;
}

/* Apply a sign to a rounded magnitude and saturate to the fx_t range. */
static fx_t fx_signed_sat(uint64_t mag, bool negative)
{
    if (negative)
        return mag >= (uint64_t)1 << 31 ? FX_MIN : -(fx_t)mag;
    return mag > (uint64_t)INT32_MAX ? FX_MAX : (fx_t)mag;
}

/* round(num / den) for unsigned operands, den != 0, without overflowing
 * num + den / 2. */
static uint64_t fx_udiv_round(uint64_t num, uint64_t den)
{
    uint64_t q = num / den;
    uint64_t r = num - q * den;
    /* r >= den - r is r >= den/2 (ties up) computed without overflow. */
    return q + (r >= den - r ? 1u : 0u);
}

fx_t fx_div(fx_t a, fx_t b)
{
    if (b == 0)
        return a > 0 ? FX_MAX : (a < 0 ? FX_MIN : 0);
    bool neg = (a < 0) != (b < 0);
    uint64_t num = fx_uabs64(a) << FX_FRAC_BITS;
    return fx_signed_sat(fx_udiv_round(num, fx_uabs64(b)), neg);
}

fx_t fx_recip(fx_t a)
{
    return fx_div(FX_ONE, a);
}

uint32_t fx_isqrt64(uint64_t n)
{
    /* Digit-by-digit (restoring) square root, two bits of n per step: no
     * multiply, no divide, the same instruction count for every input. */
    uint64_t rem = 0, root = 0;
    for (int i = 0; i < 32; i++) {
        rem = (rem << 2) | (n >> 62);
        n <<= 2;
        root <<= 1;
        uint64_t trial = (root << 1) | 1u;
        if (rem >= trial) {
            rem -= trial;
            root |= 1u;
        }
    }
    return (uint32_t)root;
}

/* Round-to-nearest integer square root: floor root r rounds up when
 * n > r^2 + r, because (r + 1/2)^2 = r^2 + r + 1/4 and n is an integer. */
static uint64_t fx_isqrt64_round(uint64_t n)
{
    uint64_t r = fx_isqrt64(n);
    return n > r * r + r ? r + 1 : r;
}

fx_t fxw_sqrt(fxw_t w)
{
    /* sqrt(w * 2^-32) * 2^16 = sqrt(w): the Q32.32 integer's integer root is
     * the Q16.16 result directly. */
    if (w <= 0)
        return 0;
    return fx_signed_sat(fx_isqrt64_round((uint64_t)w), false);
}

fx_t fx_sqrt(fx_t a)
{
    if (a <= 0)
        return 0;
    return fxw_sqrt(fxw_from_fx(a));
}

/* Leading zero count of a non-zero uint64. */
static int fx_clz64(uint64_t v)
{
    return __builtin_clzll(v);
}

fx_t fxw_div(fxw_t a, fxw_t b)
{
    if (b == 0)
        return a > 0 ? FX_MAX : (a < 0 ? FX_MIN : 0);
    if (a == 0)
        return 0;
    bool neg = (a < 0) != (b < 0);
    uint64_t n = fx_uabs64(a), d = fx_uabs64(b);
    /* We want n * 2^16 / d. Shift n up as far as it goes (k <= 16) and take
     * the remaining 16 - k bits off d. When d must lose bits, the result is
     * either saturated anyway or d keeps >= 31 significant bits, so the
     * quotient stays within 1 LSB. */
    int k = fx_clz64(n) - 1; /* keep the top bit clear */
    if (k > FX_FRAC_BITS)
        k = FX_FRAC_BITS;
    int dshift = FX_FRAC_BITS - k;
    n <<= k;
    if (dshift > 0) {
        uint64_t dr = (d + ((uint64_t)1 << (dshift - 1))) >> dshift;
        if (dr == 0)
            return fx_signed_sat(UINT64_MAX, neg);
        d = dr;
    }
    return fx_signed_sat(fx_udiv_round(n, d), neg);
}

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
 * modulo 360 degrees, then to a quadrant q and a remainder r in [0, 90),
 * then to [0, 45] by sin(90 - r) = cos(r). Only the final [0, 45] angle is
 * converted to radians (Q2.30, error <= 0.5 LSB of Q30 = 4.7e-10) and fed
 * to Taylor polynomials in Q2.30 (sin to x^9, cos to x^10: the first
 * dropped terms are below 1.2e-9 at pi/4). All Q30 roundings together stay
 * below 1e-8, i.e. below 0.001 LSB of Q16.16, so after the final rounding
 * the result is within 0.5 + 0.001 LSB of the exact value. */
#define FX_DEG90 ((int32_t)90 << FX_FRAC_BITS)
#define FX_DEG45 ((int32_t)45 << FX_FRAC_BITS)
#define FX_Q30_ONE ((int64_t)1 << 30)

/* (a * b) / 2^30 rounded (ties toward +infinity), a, b in Q2.30. */
static int64_t fx_mul_q30(int64_t a, int64_t b)
{
    return (a * b + (FX_Q30_ONE >> 1)) >> 30;
}

/* sin (want_cos false) or cos (want_cos true) of r degrees in Q16.16,
 * 0 <= r <= 45 degrees, as Q16.16 in [0, 1]. */
static fx_t fx_sincos45(int32_t r, bool want_cos)
{
    /* pi/180 * 2^46: r (< 2^22) times it stays below 2^63. */
    const int64_t k = 1228166276394;
    int64_t x = ((int64_t)r * k + ((int64_t)1 << 31)) >> 32; /* radians, Q2.30 */
    int64_t x2 = fx_mul_q30(x, x);
    int64_t v;
    if (want_cos) {
        /* 1 - x^2/2! + x^4/4! - ... - x^10/10!, coefficients in Q30. */
        int64_t p = -296;
        p = 26631 + fx_mul_q30(p, x2);
        p = -1491308 + fx_mul_q30(p, x2);
        p = 44739243 + fx_mul_q30(p, x2);
        p = -536870912 + fx_mul_q30(p, x2);
        v = FX_Q30_ONE + fx_mul_q30(p, x2);
    } else {
        /* x (1 - x^2/3! + x^4/5! - x^6/7! + x^8/9!). */
        int64_t p = 2959;
        p = -213044 + fx_mul_q30(p, x2);
        p = 8947849 + fx_mul_q30(p, x2);
        p = -178956971 + fx_mul_q30(p, x2);
        v = fx_mul_q30(FX_Q30_ONE + fx_mul_q30(p, x2), x);
    }
    v = (v + ((int64_t)1 << 13)) >> 14; /* Q30 -> Q16, ties toward +inf */
    if (v > FX_ONE)
        v = FX_ONE; /* never above 1 (cannot happen by the bound, kept as a guard) */
    if (v < 0)
        v = 0;
    return (fx_t)v;
}

/* Shared body: quarter turns to add (1 for cosine), then the angle. */
static fx_t fx_sin_quarter(fx_t deg, int32_t quarter)
{
    /* deg mod 360 degrees, exact: 360 << 16 = 23592960 fits an int32. */
    const int32_t full = (int32_t)360 << FX_FRAC_BITS;
    int32_t a = deg % full;
    if (a < 0)
        a += full;
    int32_t q = a / FX_DEG90;
    int32_t r = a - q * FX_DEG90; /* [0, 90) degrees */
    q = (q + quarter) & 3;
    /* sin(q * 90 + r): q = 0 sin r, 1 cos r, 2 -sin r, 3 -cos r. */
    bool use_cos = (q & 1) != 0;
    if (r > FX_DEG45) {
        r = FX_DEG90 - r; /* sin(r) = cos(90 - r) and vice versa */
        use_cos = !use_cos;
    }
    fx_t v = fx_sincos45(r, use_cos);
    return q >= 2 ? -v : v;
}

fx_t fx_sin_deg(fx_t deg)
{
    return fx_sin_quarter(deg, 0);
}

fx_t fx_cos_deg(fx_t deg)
{
    return fx_sin_quarter(deg, 1);
}

bool fx_normalize3(fx_t v[3])
{
    uint64_t m = fx_uabs64(v[0]) | fx_uabs64(v[1]) | fx_uabs64(v[2]);
    if (m == 0)
        return false;
    /* Scale by a power of two so the largest magnitude lies in [2^29, 2^30):
     * the direction is unchanged, the squared length stays below 3 * 2^60,
     * and the length keeps 30 significant bits. */
    int shift = fx_clz64(m) - 34;
    int64_t s[3];
    for (int i = 0; i < 3; i++)
        s[i] = shift >= 0 ? v[i] * ((int64_t)1 << shift) : (int64_t)v[i] / ((int64_t)1 << -shift);
    uint64_t len2 = 0;
    for (int i = 0; i < 3; i++)
        len2 += (uint64_t)(s[i] * s[i]);
    uint64_t len = fx_isqrt64_round(len2); /* in [2^29, 2^31) */
    /* inv = 2^61 / len < 2^32 keeps 31+ significant bits, and s * inv stays
     * below 2^62; the component is then (s * inv) / 2^45 in Q16.16. */
    uint64_t inv = fx_udiv_round((uint64_t)1 << 61, len);
    for (int i = 0; i < 3; i++) {
        uint64_t p = fx_uabs64(s[i]) * inv + ((uint64_t)1 << 44);
        fx_t c = (fx_t)(p >> 45);
        v[i] = s[i] < 0 ? -c : c;
    }
    return true;
}

fx128_t fx128_mul(int64_t a, int64_t b)
{
    bool neg = (a < 0) != (b < 0);
    uint64_t x = fx_uabs64(a), y = fx_uabs64(b);
    uint64_t x0 = (uint32_t)x, x1 = x >> 32, y0 = (uint32_t)y, y1 = y >> 32;
    uint64_t p00 = x0 * y0, p01 = x0 * y1, p10 = x1 * y0, p11 = x1 * y1;
    uint64_t mid = (p00 >> 32) + (uint32_t)p01 + (uint32_t)p10;
    fx128_t r;
    r.lo = (mid << 32) | (uint32_t)p00;
    r.hi = (int64_t)(p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32));
    return neg ? fx128_neg(r) : r;
}

fx128_t fx128_shl(fx128_t a, int s)
{
    fx128_t r;
    if (s == 0)
        return a;
    if (s >= 64) {
        r.hi = (int64_t)(a.lo << (s - 64));
        r.lo = 0;
        return r;
    }
    r.hi = (int64_t)(((uint64_t)a.hi << s) | (a.lo >> (64 - s)));
    r.lo = a.lo << s;
    return r;
}

int fx128_bits(fx128_t a)
{
    if (a.hi < 0)
        a = fx128_neg(a);
    if (a.hi)
        return 128 - __builtin_clzll((uint64_t)a.hi);
    return a.lo ? 64 - __builtin_clzll(a.lo) : 0;
}

int64_t fx128_shr_round(fx128_t a, int s)
{
    bool neg = a.hi < 0;
    if (neg)
        a = fx128_neg(a);
    if (s > 0)
        a = fx128_add(a, fx128_shl(fx128_from64(1), s - 1));
    uint64_t hi = (uint64_t)a.hi, lo = a.lo, q;
    if (s == 0) {
        q = lo;
        if (hi)
            q = UINT64_MAX;
    } else if (s < 64) {
        q = (lo >> s) | (hi << (64 - s));
        if (hi >> s)
            q = UINT64_MAX;
    } else {
        q = hi >> (s - 64);
    }
    if (neg)
        return q > (uint64_t)INT64_MAX ? INT64_MIN : -(int64_t)q;
    return q > (uint64_t)INT64_MAX ? INT64_MAX : (int64_t)q;
}

fx128_t fx128_shr128(fx128_t a, int s)
{
    if (s == 0)
        return a;
    bool neg = a.hi < 0;
    if (neg)
        a = fx128_neg(a);
    a = fx128_add(a, fx128_shl(fx128_from64(1), s - 1));
    fx128_t r;
    if (s < 64) {
        r.lo = (a.lo >> s) | ((uint64_t)a.hi << (64 - s));
        r.hi = (int64_t)((uint64_t)a.hi >> s);
    } else {
        r.lo = (uint64_t)a.hi >> (s - 64);
        r.hi = 0;
    }
    return neg ? fx128_neg(r) : r;
}
