/* fx: Q16.16 operations that are too large to inline. See fx.h for formats,
 * rounding and the overflow policy. */
#include <stddef.h>

#include "math/fx_int.h"

/* The leading zero count of a non-zero uint32 rounded down to an even
 * number, as a shift that brings the top set bit to bit 30 or 31. */
static inline __attribute__((always_inline)) int fx_clz_even(uint32_t v)
{
    return fx_clz32(v) & ~1;
}

/* round(2^23 / (i + 0.5)) for i = 128 .. 255: 2^31 / d1 for a 16-bit d1 in
 * [2^15, 2^16) indexed by its top 8 bits, within 2^-8 relative. */
static const uint16_t fx_recip_tab[128] = {
    65281, 64777, 64281, 63792, 63310, 62836, 62369, 61909, 61455, 61008, 60568, 60133, 59705,
    59283, 58867, 58457, 58053, 57654, 57260, 56872, 56489, 56111, 55738, 55370, 55007, 54649,
    54295, 53946, 53601, 53261, 52925, 52593, 52265, 51942, 51622, 51306, 50995, 50686, 50382,
    50081, 49784, 49490, 49200, 48913, 48630, 48349, 48072, 47798, 47528, 47260, 46995, 46733,
    46474, 46218, 45965, 45714, 45467, 45222, 44979, 44739, 44502, 44267, 44035, 43805, 43577,
    43352, 43129, 42908, 42690, 42474, 42260, 42048, 41838, 41631, 41425, 41222, 41020, 40820,
    40623, 40427, 40233, 40041, 39851, 39662, 39476, 39291, 39108, 38926, 38746, 38568, 38392,
    38217, 38044, 37872, 37702, 37533, 37366, 37200, 37036, 36873, 36712, 36552, 36393, 36236,
    36080, 35926, 35772, 35620, 35470, 35320, 35172, 35026, 34880, 34735, 34592, 34450, 34309,
    34169, 34031, 33893, 33757, 33622, 33487, 33354, 33222, 33091, 32961, 32832,
};

/* v ~ 2^31 / d1 for d1 in [2^15, 2^16): the table, then one Newton step
 * v += v (2^31 - d1 v) / 2^31, which leaves v at most 2^-15 below. */
static inline __attribute__((always_inline)) uint32_t fx_recip16(uint32_t d1)
{
    int32_t v = fx_recip_tab[(d1 >> 8) - 128];
    int32_t e = (int32_t)((1u << 31) - d1 * (uint32_t)v); /* |e| < 2^23 */
    return (uint32_t)(v + ((v * (e >> 8)) >> 23));
}

/* q = floor(u / d1) and *r = u - q d1, for d1 in [2^15, 2^16). v is
 * fx_recip16(d1) on targets without a divide instruction (unused else). */
static inline __attribute__((always_inline)) uint32_t fx_div32_16(uint32_t u, uint32_t d1, uint32_t v, uint32_t *r)
{
    if (FX_HAVE_UDIV) {
        uint32_t q = u / d1;
        *r = u - q * d1;
        return q;
    }
    /* u v / 2^31 in two 16-bit halves (no 64-bit product). It is at most a
     * few units below u / d1 (v is low by < 2^-15, and two truncations),
     * never above, so the exact remainder is small and non-negative. */
    uint32_t q = ((((u >> 16) * v) >> 1) + (((u & 0xffffu) * v) >> 17)) >> 14;
    uint32_t rem = u - q * d1;
    while (rem >= d1) {
        q++;
        rem -= d1;
    }
    *r = rem;
    return q;
}

/* One 16-bit quotient digit of Knuth's long division (TAOCP 4.3.1,
 * algorithm D) in base 2^16 with a normalised divisor D = d1 2^16 + d0
 * (d1 >= 2^15): floor((u 2^16 + un) / D) for u < D, un < 2^16. The
 * estimate floor(u / d1) is at most 2 too large; the d0 test brings it to
 * the exact digit. *rem gets u 2^16 + un - digit * D (< D: exact mod 2^32). */
static inline __attribute__((always_inline)) uint32_t fx_div_digit(uint32_t u, uint32_t un, uint32_t d, uint32_t v, uint32_t *rem)
{
    uint32_t d1 = d >> 16, d0 = d & 0xffffu, rhat;
    uint32_t q = fx_div32_16(u, d1, v, &rhat);
    while (q >= (1u << 16) || q * d0 > ((rhat << 16) | un)) {
        q--;
        rhat += d1;
        if (rhat >= (1u << 16))
            break;
    }
    *rem = (u << 16) + un - q * d;
    return q;
}

/* floor(u / d) for u < d 2^32 and d in [2^31, 2^32) (normalised): two
 * 16-bit digits of Knuth's division, 32-bit operations only. *rem gets
 * the remainder. */
static inline __attribute__((always_inline)) uint32_t fx_div64_32(uint64_t u, uint32_t d, uint32_t *rem)
{
    uint32_t v = FX_HAVE_UDIV ? 0 : fx_recip16(d >> 16);
    uint32_t u1 = (uint32_t)(u >> 32), u0 = (uint32_t)u, r;
    uint32_t q1 = fx_div_digit(u1, u0 >> 16, d, v, &r);
    uint32_t q0 = fx_div_digit(r, u0 & 0xffffu, d, v, &r);
    *rem = r;
    return (q1 << 16) + q0;
}

uint32_t fx_udiv64_32(uint64_t n, uint32_t d)
{
    /* n 2^s < d 2^s 2^32 <= 2^64: no bit is lost, and the digits' bound
     * u < D 2^32 holds. */
    int s = fx_clz32(d);
    uint32_t r;
    return fx_div64_32(n << s, d << s, &r);
}

/* a / b correctly rounded, ties away from zero, with 32-bit operations only
 * (no libgcc 64-bit division). The quotient magnitude q = |a| 2^16 / |b|
 * is tested for saturation first (q >= 2^31 iff |a| / 2^15 >= |b|); then
 * q < 2^31 and Knuth's division of the 63-bit numerator |a| 2^(16+s) by
 * the normalised divisor |b| 2^s gives two 16-bit digits and the exact
 * remainder r. Rounding compares 2r with the divisor (ties go up in
 * magnitude, i.e. away from zero). */
fx_t fx_div(fx_t a, fx_t b)
{
    if (b == 0)
        return a > 0 ? FX_MAX : (a < 0 ? FX_MIN : 0);
    bool neg = (a < 0) != (b < 0);
    uint32_t ua = fx_uabs32(a), ub = fx_uabs32(b);
    if ((ua >> 15) >= ub)
        return neg ? FX_MIN : FX_MAX;
    int s = fx_clz32(ub);
    uint32_t d = ub << s;
    uint32_t u1, u0; /* numerator ua 2^(16+s) = u1 2^32 + u0, u1 < d / 2 */
    if (s < 16) {
        u1 = ua >> (16 - s);
        u0 = ua << (16 + s);
    } else {
        u1 = ua << (s - 16);
        u0 = 0;
    }
    uint32_t r;
    uint32_t q = fx_div64_32(((uint64_t)u1 << 32) | u0, d, &r);
    q += r >= d - r ? 1u : 0u; /* 2r >= d without overflow */
    if (neg)
        return q >= (1u << 31) ? FX_MIN : -(fx_t)q;
    return q > (uint32_t)INT32_MAX ? FX_MAX : (fx_t)q;
}

/* round(n / d), ties up, for n < 2^63 and 0 < d <= 2^63, when the floor
 * of the quotient is below 2^31; 2^31 when it is not (the caller
 * saturates), for targets without a divide instruction (the M0: libgcc's
 * __udivmoddi4 costs about 300 instructions there). A divisor below 2^32 is
 * normalised and divides in two 16-bit digits as in fx_div; a larger one
 * takes the top 32 bits of the normalised divisor, a 64/32 quotient of
 * n / 2 by them, at most one too large after undoing the shifts, and one
 * exact correction (Hacker's Delight, 9-5). */
static uint32_t fx_udiv64_round_sat(uint64_t n, uint64_t d)
{
    uint32_t q;
    uint64_t r;
    if ((d >> 32) == 0) {
        uint32_t d32 = (uint32_t)d;
        if ((n >> 31) >= d32)
            return 1u << 31; /* floor(n / d) >= 2^31 */
        int s = fx_clz32(d32);
        uint32_t r32;
        /* n 2^s < d 2^(31 + s) < 2^63: the normalised quotient fits. */
        q = fx_div64_32(n << s, d32 << s, &r32);
        r = r32 >> s;
    } else {
        /* n < 2^63 and d >= 2^32: the quotient is below 2^31. */
        int s = fx_clz32((uint32_t)(d >> 32)); /* 0 .. 31 */
        uint32_t d1 = (uint32_t)((d << s) >> 32), r32;
        uint32_t q1 = fx_div64_32(n >> 1, d1, &r32); /* n / 2 < d1 2^32 */
        q = (uint32_t)(((uint64_t)q1 << s) >> 31);
        if (q != 0)
            q--; /* now exact or one too small */
        r = n - (fx_umul32(q, (uint32_t)d) + ((uint64_t)(q * (uint32_t)(d >> 32)) << 32));
        if (r >= d) {
            q++;
            r -= d;
        }
    }
    return q + (r >= d - r ? 1u : 0u); /* 2r >= d without overflow */
}

fx_t fx_recip(fx_t a)
{
    return fx_div(FX_ONE, a);
}

/* round(2^30 / sqrt((i + 0.5) * 2^25)) for i = 32 .. 127: 1/sqrt(m) for
 * m in [2^30, 2^32) indexed by m's top 7 bits, within 2^-7.4 relative. */
static const uint16_t fx_rsqrt_tab[96] = {
    32515, 32026, 31558, 31111, 30682, 30270, 29874, 29494, 29127, 28774, 28434, 28105,
    27787, 27480, 27183, 26895, 26617, 26346, 26084, 25830, 25583, 25342, 25109, 24882,
    24660, 24445, 24235, 24031, 23831, 23637, 23447, 23262, 23080, 22904, 22731, 22562,
    22396, 22235, 22077, 21922, 21770, 21621, 21476, 21333, 21193, 21056, 20921, 20789,
    20660, 20533, 20408, 20285, 20165, 20047, 19930, 19816, 19704, 19594, 19485, 19378,
    19273, 19170, 19068, 18968, 18870, 18773, 18677, 18583, 18490, 18399, 18309, 18220,
    18133, 18047, 17962, 17878, 17795, 17714, 17634, 17554, 17476, 17399, 17323, 17248,
    17174, 17100, 17028, 16957, 16886, 16817, 16748, 16680, 16613, 16546, 16481, 16416,
};

/* sqrt(m) and 1/sqrt(m) for m in [2^30, 2^32) with 32-bit multiplies only
 * (no divide, no 64-bit product, so also fast on the Cortex-M0):
 *  1. y0 ~ 2^30 / sqrt(m) from the table, s0 = m y0 / 2^30 ~ sqrt(m) (7 bits);
 *  2. s1 = s0 + (m - s0^2) y0 / 2^31, a Newton step on the exact residual
 *     (|m - s0^2| < 2^25 fits an int32): s1 ~ sqrt(m) within +-4;
 *  3. y1 = y0 (2 - s1 y0 / 2^30), a Newton step for 2^30 / s1 (14 bits).
 * *s gets s1 and *y gets y1. */
static inline __attribute__((always_inline)) void fx_sqrt_est(uint32_t m, int32_t *s, int32_t *y)
{
    int32_t y0 = fx_rsqrt_tab[(m >> 25) - 32];
    int32_t s0 = (int32_t)(((m >> 16) * (uint32_t)y0) >> 14);
    int32_t r = (int32_t)(m - (uint32_t)s0 * (uint32_t)s0);
    int32_t s1 = s0 + (((r >> 9) * y0) >> 22);
    int32_t t = (int32_t)(1u << 30) - (int32_t)((uint32_t)s1 * (uint32_t)y0);
    *y = y0 + ((y0 * (t >> 8)) >> 22);
    *s = s1;
}

/* Correctly rounded sqrt. The exact result is round(sqrt(n)) with
 * n = a 2^16 < 2^47; ties cannot happen (n is an integer, (r + 1/2)^2 is
 * not). With m = a 4^h in [2^30, 2^32), sqrt(n) = 256 sqrt(m) / 2^h:
 *  - fx_sqrt_est gives s1 ~ sqrt(m) and y1 ~ 2^30 / s1;
 *  - R = 256 s1 + (m - s1^2) 128 / s1 ~ 256 sqrt(m), within a unit or two;
 *  - q = R / 2^h rounded, then the exact test: with d = n - q^2 (exact in
 *    32-bit modular arithmetic, because |d| < 2^31 near the root), q is
 *    round(sqrt(n)) iff -q < d <= q; otherwise step q by one and retest
 *    (q is never more than one step off: tests/fx_exhaustive.c checks
 *    every input). */
fx_t fx_sqrt(fx_t a)
{
    if (a <= 0)
        return 0;
    int e = fx_clz_even((uint32_t)a);
    uint32_t m = (uint32_t)a << e;
    int h = e >> 1;
    int32_t s, y;
    fx_sqrt_est(m, &s, &y);
    int32_t r = (int32_t)(m - (uint32_t)s * (uint32_t)s);
    int32_t R = (int32_t)((uint32_t)s << 8) + (((r >> 5) * y) >> 18);
    uint32_t q = h ? ((uint32_t)R + (1u << (h - 1))) >> h : (uint32_t)R;
    uint32_t n = (uint32_t)a << 16; /* n mod 2^32 */
    int32_t d = (int32_t)(n - q * q);
    while (d > (int32_t)q) { /* q too small: n >= q^2 + q + 1 */
        d -= (int32_t)(2 * q + 1);
        q++;
    }
    while (d <= -(int32_t)q) { /* q too large: n <= q^2 - q */
        q--;
        d += (int32_t)(2 * q + 1);
    }
    return (fx_t)q;
}

/* Leading zero count of a non-zero uint64. */
static inline int fx_clz64(uint64_t v)
{
    uint32_t hi = (uint32_t)(v >> 32);
    return hi ? fx_clz32(hi) : 32 + fx_clz32((uint32_t)v);
}

bool fx_ratio_len_below(fxw_t a, fxw_t d2, uint32_t num, uint32_t den)
{
    if (d2 <= 0 || den == 0 || den > 1024u || num > den)
        return false;
    if (a <= 0)
        return true;
    /* d2 2^-2s in [2^30, 2^32) (s in -15..16), and a 2^-(s + 16): then
     * x = a / (2^16 sqrt(d2)) = (a 2^-(s + 16)) / sqrt(d2 2^-2s), taken
     * at a's upper bound au over d2's lower bound dl. */
    uint64_t ud = (uint64_t)d2;
    int e = 64 - fx_clz64(ud);
    int s = e >= 31 ? (e - 31) >> 1 : -((32 - e) >> 1);
    uint64_t dl = s >= 0 ? ud >> (2 * s) : ud << (-2 * s);
    uint64_t au = ((uint64_t)a >> (s + 16)) + 1;
    if (au >= ((uint64_t)1 << 17))
        return false; /* x > 1.99: not below */
    /* 512 den^2 au^2 <= 511 num^2 dl, exact: each side below 2^63; then
     * x <= (num / den) sqrt(1 - 2^-9) <= (num / den)(1 - 2^-10). */
    return ((uint64_t)den * den * au * au << 9) <= (uint64_t)num * num * 511u * dl;
}

/* An estimate of sqrt(n), n > 0, within a few units: the top 32 bits m
 * of n (taken with an even shift, so sqrt(n) ~ sqrt(m) 2^k) give a 24-bit
 * root R ~ 256 sqrt(m) as in fx_sqrt; for n >= 2^48 one more Newton step
 * on the exact 64-bit residual. At most 2^32 (q^2 may wrap only there). */
static inline uint64_t fx_root64_est(uint64_t n)
{
    int e = fx_clz64(n) & ~1;
    uint32_t m = e >= 32 ? (uint32_t)(n << (e - 32)) : (uint32_t)(n >> (32 - e));
    int k = 16 - (e >> 1); /* sqrt(n) ~ sqrt(m) 2^k, k in [-15, 16] */
    int32_t s, y;
    fx_sqrt_est(m, &s, &y);
    int32_t r = (int32_t)(m - (uint32_t)s * (uint32_t)s);
    uint32_t R = (uint32_t)(((int32_t)((uint32_t)s << 8)) + (((r >> 5) * y) >> 18));
    if (k <= 8) {
        int sh = 8 - k;
        return sh ? (R + (1u << (sh - 1))) >> sh : R;
    }
    uint64_t q = (uint64_t)R << (k - 8); /* within 2^(k-7) + 2, below 2^32 */
    int64_t d = (int64_t)(n - fx_usqr32((uint32_t)q));
    /* d / (2q) with 1 / (2 sqrt(n)) ~ y 2^-31 2^-k. */
    return (uint64_t)((int64_t)q + ((d * y) >> (31 + k)));
}

/* floor(sqrt(n)), exact: the estimate, then d = n - q^2 (exact modulo 2^64
 * because q is within a few units of the root) and q steps until
 * 0 <= d <= 2q, i.e. q^2 <= n < (q + 1)^2. q is kept below 2^32, so q^2
 * never wraps. About 60 instructions on the Cortex-M3 (the digit-by-digit
 * loop it replaces took about 500); tests/test_fx.c checks it against a
 * long double and __int128 oracle. */
uint32_t fx_isqrt64(uint64_t n)
{
    if (n == 0)
        return 0;
    uint64_t q = fx_root64_est(n);
    uint32_t q32 = q > UINT32_MAX ? UINT32_MAX : (uint32_t)q;
    int64_t d = (int64_t)(n - fx_usqr32(q32));
    while (d < 0) { /* q^2 > n */
        q32--;
        d += 2 * (int64_t)q32 + 1;
    }
    while (d > 2 * (int64_t)q32) { /* (q + 1)^2 <= n */
        d -= 2 * (int64_t)q32 + 1;
        q32++;
    }
    return q32;
}

fx_t fxw_sqrt(fxw_t w)
{
    /* sqrt(w * 2^-32) * 2^16 = sqrt(w): the Q32.32 integer's rounded root
     * is the Q16.16 result. The estimate, then the exact test on
     * d = w - q^2 (exact mod 2^64 because it is small), stepping q until
     * -q < d <= q. */
    if (w <= 0)
        return 0;
    uint64_t n = (uint64_t)w;
    uint64_t q = fx_root64_est(n); /* below 2^32: n < 2^63 */
    int64_t d = (int64_t)(n - fx_usqr32((uint32_t)q)); /* q <= 2^32: q^2 mod 2^64 */
    while (d > (int64_t)q) {
        d -= (int64_t)(2 * q + 1);
        q++;
    }
    while (d <= -(int64_t)q) {
        q--;
        d += (int64_t)(2 * q + 1);
    }
    return q > (uint64_t)INT32_MAX ? FX_MAX : (fx_t)q;
}

/* Y ~ 2^46 / sqrt(m) for m in [2^30, 2^32), Y in [2^30, 2^31], within
 * 2^-25 relative: fx_sqrt_est's 14-bit y1, then one Newton step for the
 * inverse square root, Y' = Y (3 - m Y^2 / 2^92) / 2, in 64-bit products. */
static uint32_t fx_rsqrt_q46(uint32_t m)
{
    int32_t s, y;
    fx_sqrt_est(m, &s, &y);
    uint32_t Y = (uint32_t)y << 16;
    uint32_t t = (uint32_t)(fx_usqr32(Y) >> 32);       /* ~ 2^60 / m */
    uint64_t f = 3 * ((uint64_t)1 << 60) - fx_umul32(m, t); /* ~ 2^61 */
    return (uint32_t)(fx_umul32(Y, (uint32_t)(f >> 30)) >> 31);
}

/* 1 / sqrt(a) = 2^24 / sqrt(a_raw) in Q16.16. With m = a 4^h in
 * [2^30, 2^32): 2^24 / sqrt(a) = Y 2^h / 2^22, rounded once. */
fx_t fx_rsqrt(fx_t a)
{
    if (a <= 0)
        return FX_MAX;
    int e = fx_clz_even((uint32_t)a);
    int k = 22 - (e >> 1); /* 7 .. 22 */
    uint32_t Y = fx_rsqrt_q46((uint32_t)a << e);
    return (fx_t)((Y + (1u << (k - 1))) >> k);
}


int fx_bits64(int64_t v)
{
    uint64_t a = fx_uabs64(v);
    return a ? 64 - fx_clz64(a) : 0;
}

int64_t fx_shr_round64(int64_t v, int s)
{
    if (s <= 0)
        return v;
    int64_t h = (int64_t)1 << (s - 1);
    return v >= 0 ? (v + h) >> s : -((h - v) >> s);
}

/* round(a b 2^e / sqrt(P)) (fx.h): P = m 2^r with m in [2^30, 2^32) and
 * r even, 1 / sqrt(P) = Y 2^(-46 - r/2) (fx_rsqrt_q46; m keeps P's top
 * 32 bits: within 2^-31 relative), b shifted up into [2^30, 2^31) (e
 * down as much), hi = floor(b Y / 2^32) >= 2^28, and the
 * product a hi shifted by 14 + r/2 - e, rounded once, half up. */
fx_t fx_mul_rsqrt64(uint32_t a, uint32_t b, int e, uint64_t P)
{
    int r = 32 - fx_clz64(P);
    r += r & 1;
    uint32_t m = r >= 0 ? (uint32_t)(P >> r) : (uint32_t)(P << -r);
    if (b == 0)
        return 0;
    int z = fx_clz32(b) - 1; /* b in [2^30, 2^31): hi >= 2^28 */
    b <<= z;
    e -= z;
    uint32_t hi = (uint32_t)(fx_umul32(b, fx_rsqrt_q46(m)) >> 32);
    uint64_t p = fx_umul32(hi, a);
    int S = 14 + (r >> 1) - e;
    if (S >= 64)
        return 0;
    if (S <= 0)
        return p ? FX_MAX : 0;
    p = (p + ((uint64_t)1 << (S - 1))) >> S;
    return p > (uint64_t)FX_MAX ? FX_MAX : (fx_t)p;
}

/* fxw_div in two steps: the dividend's magnitude shifted up as far as it
 * goes (k <= 16) and the bits the divisor must lose, 16 - k; then the
 * division. When d must lose bits, the result is either saturated anyway
 * or d keeps >= 31 significant bits, so the quotient stays within 1 LSB. */
static inline __attribute__((always_inline)) fxw_dividend_t fxw_dividend_of(fxw_t a)
{
    fxw_dividend_t q = {0, 0, (int8_t)(a > 0 ? 1 : a < 0 ? -1 : 0)};
    if (a == 0)
        return q;
    uint64_t n = fx_uabs64(a);
    int k = fx_clz64(n) - 1; /* keep the top bit clear */
    if (k > FX_FRAC_BITS)
        k = FX_FRAC_BITS;
    q.dshift = (int8_t)(FX_FRAC_BITS - k);
    q.n = k < 0 ? n >> 1 : n << k; /* n = 2^63 (a = INT64_MIN): exact, and d loses 17 bits */
    return q;
}

static inline __attribute__((always_inline)) fx_t fxw_div_of(const fxw_dividend_t *a, fxw_t b)
{
    if (b == 0)
        return a->sign > 0 ? FX_MAX : (a->sign < 0 ? FX_MIN : 0);
    if (a->sign == 0)
        return 0;
    bool neg = (a->sign < 0) != (b < 0);
    uint64_t d = fx_uabs64(b);
    int dshift = a->dshift;
    if (dshift > 0) {
        uint64_t dr = (d + ((uint64_t)1 << (dshift - 1))) >> dshift;
        if (dr == 0)
            return fx_signed_sat(UINT64_MAX, neg);
        d = dr;
    }
    /* With UDIV, libgcc's 64-bit division is a little faster here than
     * fx_udiv64_round_sat (make bench-fx). */
    return fx_signed_sat(FX_HAVE_UDIV ? fx_udiv_round(a->n, d) : fx_udiv64_round_sat(a->n, d), neg);
}

fx_t fxw_div(fxw_t a, fxw_t b)
{
    fxw_dividend_t q = fxw_dividend_of(a);
    return fxw_div_of(&q, b);
}

fxw_dividend_t fxw_dividend(fxw_t a)
{
    return fxw_dividend_of(a);
}

fx_t fxw_div_by(const fxw_dividend_t *a, fxw_t b)
{
    return fxw_div_of(a, b);
}

fxw_ratio_num_t fxw_ratio_num(fxw_t a)
{
    fxw_ratio_num_t q = {0, 0, (int8_t)(a > 0 ? 1 : a < 0 ? -1 : 0)};
    if (a == 0)
        return q;
    uint64_t u = fx_uabs64(a);
    int s = fx_clz64(u) - 1; /* -1 for a = INT64_MIN */
    q.s = (int16_t)s;
    q.n = s < 0 ? u >> 2 : (u << s) >> 1;
    return q;
}

fxw_ratio_t fxw_ratio_by(const fxw_ratio_num_t *a, fxw_t b)
{
    fxw_ratio_t q = {0, 40, 0}; /* 0 (inline path) */
    if (a->sign == 0)
        return q;
    q.neg = (a->sign < 0) != (b < 0) ? -1 : 0;
    if (b == 0) {
        q.e = FXW_RATIO_INF;
        return q;
    }
    /* d: the top 32 bits of |b| 2^sb (32-bit shifts only), in [2^31, 2^32) */
    uint64_t ub = fx_uabs64(b);
    uint32_t hi = (uint32_t)(ub >> 32), lo = (uint32_t)ub, d;
    int sb;
    if (hi) {
        sb = fx_clz32(hi);
        d = sb ? (hi << sb) | (lo >> (32 - sb)) : hi;
    } else {
        sb = 32 + fx_clz32(lo);
        d = lo << (sb - 32);
    }
    /* |a| / |b| ~ (a->n 2^(1 - s)) / (d 2^(32 - sb)): a->n / d lies in
     * (2^29, 2^31) */
    uint32_t r, m = fx_div64_32(a->n, d, &r);
    q.m = m + (r >= d - r ? 1u : 0u);
    q.e = (int16_t)(31 + a->s - sb);
    return q;
}

fx_t fxw_ratio_mul_wide(const fxw_ratio_t *q, fx_t x)
{
    bool neg = (q->neg != 0) != (x < 0);
    if (x == 0)
        return 0;
    if (q->e == FXW_RATIO_INF)
        return fx_signed_sat(UINT64_MAX, neg);
    uint64_t p = fx_umul32(q->m, fx_uabs32(x)); /* <= 2^62 */
    int e = q->e;
    if (e >= 1 && e <= 32) {
        /* The usual case here (a plane's point beyond t = 1): the rounded
         * (p + 2^(e-1)) >> e in 32-bit words, the same value. It is at
         * least 2^31, and saturates, exactly when hi >> (e - 1) is not 0. */
        uint32_t lo = (uint32_t)p, hi = (uint32_t)(p >> 32), half = (uint32_t)1 << (e - 1);
        lo += half;
        hi += lo < half ? 1u : 0u; /* <= 2^30 + 1 (m <= 2^31) */
        if (hi >> (e - 1))
            return neg ? FX_MIN : FX_MAX;
        uint32_t r = (hi << (32 - e)) | (lo >> (e - 1) >> 1);
        return neg ? -(fx_t)r : (fx_t)r;
    }
    if (e >= 64)
        return 0; /* p 2^-e < 1/4 */
    if (e >= 1)
        return fx_signed_sat((p + ((uint64_t)1 << (e - 1))) >> e, neg);
    if (p == 0)
        return 0;
    if (e < -31 || (p >> (63 + e)) != 0)
        return fx_signed_sat(UINT64_MAX, neg);
    return fx_signed_sat(p << -e, neg);
}

bool fx_unit30(const fx_t v[3], int32_t out[3])
{
    uint32_t m = 0;
    for (int i = 0; i < 3; i++)
        m |= fx_uabs32(v[i]);
    if (m == 0)
        return false;
    /* Scale the largest magnitude into [2^29, 2^30): the root of the
     * squared length then has at least 29 bits. */
    int sh = 0;
    while ((m << sh) < ((uint32_t)1 << 29))
        sh++;
    int shr = 0;
    while ((m >> shr) >= ((uint32_t)1 << 30))
        shr++;
    int64_t w[3];
    uint64_t len2 = 0;
    for (int i = 0; i < 3; i++) {
        w[i] = shr ? (int64_t)v[i] / ((int64_t)1 << shr) : (int64_t)v[i] * ((int64_t)1 << sh);
        len2 += (uint64_t)(w[i] * w[i]); /* < 3 * 2^60 */
    }
    uint64_t r = fx_isqrt64(len2); /* >= 2^29 */
    for (int i = 0; i < 3; i++) {
        uint64_t mag = (uint64_t)(w[i] < 0 ? -w[i] : w[i]) << 30; /* < 2^60 */
        uint64_t q = (mag + r / 2) / r;
        out[i] = w[i] < 0 ? -(int32_t)q : (int32_t)q;
    }
    return true;
}

/* fx_normalize3_len in two stages (fx_inv3_t, fx.h): fx_inv3_len, the
 * inverse length (and the length when len is not NULL); fx_inv3_dir, the
 * unit vector from it. fx_normalize3 and fx_normalize3_len inline both,
 * so their code is what it was in one piece. */
static inline __attribute__((always_inline)) bool fx_inv3_len(const fx_t v[3], fx_inv3_t *q, fx_t *len)
{
    /* Straight-line code, constant 64-bit shifts only (a variable one is
     * a dozen instructions on the M3 and more on the M0). */
    uint32_t s0 = fx_uabs32(v[0]), s1 = fx_uabs32(v[1]), s2 = fx_uabs32(v[2]);
    uint32_t m = s0 | s1 | s2;
    if (m == 0)
        return false;
    /* Scale by a power of two so the largest magnitude lies in [2^29, 2^30):
     * the direction is unchanged (a right shift truncates toward zero, a
     * relative change below 2^-29), the squared length lies in
     * [2^58, 3 * 2^60), and the length keeps 30 significant bits. */
    int shift = fx_clz32(m) - 2;
    if (shift >= 0) {
        s0 <<= shift;
        s1 <<= shift;
        s2 <<= shift;
    } else {
        s0 >>= -shift;
        s1 >>= -shift;
        s2 >>= -shift;
    }
    uint64_t len2 = fx_usqr32(s0) + fx_usqr32(s1) + fx_usqr32(s2);
    /* The top 32 bits of len2 with an even shift: len2 ~ top 2^(32 - e)
     * with top in [2^30, 2^32), so |s| ~ sqrt(top) 2^k with k = 16 - e/2,
     * 1 / |s| ~ Y 2^-46 / 2^k, and each component in Q16.16 is
     * s Y / 2^(30 + k), rounded once (fx_inv3_dir). Dropping len2's low
     * bits costs at most 2^-30 relative. len2 >> 32 lies in
     * [2^26, 3 * 2^28): e is 2 (k = 15) or 4 (k = 14). */
    bool big = (uint32_t)(len2 >> 32) >= ((uint32_t)1 << 28);
    uint32_t top = big ? (uint32_t)(len2 >> 30) : (uint32_t)(len2 >> 28);
    uint32_t Y = fx_rsqrt_q46(top);
    q->s[0] = s0, q->s[1] = s1, q->s[2] = s2;
    q->Y = Y;
    q->shift = (int8_t)shift;
    q->big = big;
    if (len) {
        /* |v| = |s| 2^-shift = sqrt(top) 2^(k - shift) = top Y 2^(k - 46 - shift),
         * a shift by 31 + shift (k = 15) or 32 + shift (k = 14), which lies
         * in [29, 61]; rounded once, saturated like fxw_sqrt. */
        int sq = (big ? 31 : 32) + shift;
        uint64_t prod = fx_umul32(top, Y); /* < 2^63 */
        if (sq >= 33) {
            /* The usual case (v below 2^29 LSB): the rounding bit 2^(sq-1)
             * lies in the high word, so the low word cannot carry into
             * the rounded quotient (as for fx_inv3_dir's components), and
             * the quotient, below 2^31 / 2, fits: 32-bit operations only,
             * without the 64-bit variable shift. The same value. */
            uint32_t hi = (uint32_t)(prod >> 32);
            *len = (fx_t)((hi + ((uint32_t)1 << (sq - 33))) >> (sq - 32));
        } else {
            uint64_t r = (prod + ((uint64_t)1 << (sq - 1))) >> sq;
            *len = r > (uint64_t)FX_MAX ? FX_MAX : (fx_t)r;
        }
    }
    return true;
}

/* The rounding bit 2^(29 + k) of s Y / 2^(30 + k) lies in the product's
 * high word, so the rounded quotient is (high word + 2^(k - 3)) >> (k - 2):
 * the low word cannot carry into it. */
static inline __attribute__((always_inline)) void fx_inv3_dir(const fx_inv3_t *q, const fx_t v[3], fx_t u[3])
{
    int sh = q->big ? 13 : 12;
    uint32_t half = (uint32_t)1 << (sh - 1);
    fx_t c0 = (fx_t)(((uint32_t)(fx_umul32(q->s[0], q->Y) >> 32) + half) >> sh);
    fx_t c1 = (fx_t)(((uint32_t)(fx_umul32(q->s[1], q->Y) >> 32) + half) >> sh);
    fx_t c2 = (fx_t)(((uint32_t)(fx_umul32(q->s[2], q->Y) >> 32) + half) >> sh);
    u[0] = v[0] < 0 ? -c0 : c0;
    u[1] = v[1] < 0 ? -c1 : c1;
    u[2] = v[2] < 0 ? -c2 : c2;
}

static inline __attribute__((always_inline)) bool fx_normalize3_impl(fx_t v[3], fx_t *len)
{
    fx_inv3_t q;
    if (!fx_inv3_len(v, &q, len))
        return false;
    fx_inv3_dir(&q, v, v);
    return true;
}

bool fx_inv3(const fx_t v[3], fx_inv3_t *q, fx_t *len)
{
    return fx_inv3_len(v, q, len);
}

void fx_inv3_unit(const fx_inv3_t *q, const fx_t v[3], fx_t u[3])
{
    fx_inv3_dir(q, v, u);
}

fx_mant_t fx_mant64(int64_t h)
{
    if (h == 0)
        return 32; /* m = 0 (e = 0) */
    uint64_t u = fx_uabs64(h);
    int b = 64 - fx_clz64(u); /* 1 .. 56 */
    uint32_t m = b > 25 ? (uint32_t)(u >> (b - 25)) : (uint32_t)u << (25 - b); /* [2^24, 2^25) */
    int32_t sm = h < 0 ? -(int32_t)m : (int32_t)m;
    return (fx_mant_t)((uint32_t)sm * 64u + (uint32_t)(b - 25 + 32));
}

bool fx_normalize3(fx_t v[3])
{
    return fx_normalize3_impl(v, NULL);
}

bool fx_normalize3_len(fx_t v[3], fx_t *len)
{
    return fx_normalize3_impl(v, len);
}
