/* Q16.16 scalar and vector maths against exact references: hard-case tables
 * plus FX_TEST_RANDOM (default 10^6) random inputs per function, drawn both
 * uniformly over all bit patterns and log-uniformly over magnitudes.
 * Errors are measured in LSB (2^-16) against __int128 / long double. */
#include <math.h>
#include <stdlib.h>

#include "../core/math/vec3.h"
#include "check.h"

#ifndef TEST_FX_NAME
#define TEST_FX_NAME "test_fx" /* test_fx_nohw: the same test on the M0 code paths */
#endif

static long n_random = 1000000;

static uint64_t rng_state = 0x9E3779B97F4A7C15ull;
static uint64_t rng(void) { return check_rng_next(&rng_state); }

/* A random fx_t: half uniform bit patterns, half log-uniform magnitudes
 * (2^-16 .. 2^15) with random sign, so small values get tested too. */
static fx_t rand_fx(void)
{
    uint64_t r = rng();
    if (r & 1)
        return (fx_t)(uint32_t)(r >> 32);
    int bits = (int)((r >> 1) % 32); /* magnitude below 2^bits LSB */
    uint32_t m = (uint32_t)(r >> 32);
    m = bits ? (m >> (32 - bits)) : 0;
    return (r & 2) ? -(fx_t)(m & 0x7fffffff) : (fx_t)(m & 0x7fffffff);
}

static const fx_t hard[] = {
    0, 1, -1, 2, -2, 0x7fff, 0x8000, 0x8001, -0x8000, -0x8001, 0xffff, 0x10000, 0x10001,
    -0x10000, -0x10001, 0x18000, -0x18000, 0x7fffffff, -0x7fffffff, INT32_MIN, 0x7ffffffe,
    0x40000000, -0x40000000, 0x00b504f3, 0x00b504f4, 0x01000000, 46341, 46340, 181 << 16,
    182 << 16, 3, 5, 0x12345678, -0x12345678,
};
#define N_HARD ((int)(sizeof hard / sizeof hard[0]))

static double max_err_ratio; /* fxw_ratio_mul, as a fraction of its bound */
static double max_err_mul, max_err_div, max_err_sqrt, max_err_wsqrt, max_err_wdiv, max_err_cot,
    max_err_norm, max_err_norm_len, max_err_inv3_mul, max_err_dot, max_err_cross,
    max_err_sin, max_err_cos, max_err_rsqrt, max_err_recip;

/* Saturate an exact value (in LSB) to the fx_t range. */
static long double sat(long double v)
{
    if (v > INT32_MAX)
        return INT32_MAX;
    if (v < INT32_MIN)
        return INT32_MIN;
    return v;
}

static void track(double *m, long double e)
{
    if (e > *m)
        *m = (double)e;
}

static void check_mul(fx_t a, fx_t b)
{
    /* a * b is exact in int64; long double (64-bit mantissa) holds it. */
    long double exact = sat((long double)((int64_t)a * b) / 65536.0L);
    long double e = fabsl((long double)fx_mul(a, b) - exact);
    track(&max_err_mul, e);
    CHECK_SWEEP(e <= 0.5L, "fx_mul(%d, %d) = %d, exact %.3Lf", a, b, fx_mul(a, b), exact);
}

/* The exact fx_div result by the hardware's 64-bit division (not the code
 * under test): round half away from zero, then saturate. */
static fx_t div_exact(fx_t a, fx_t b)
{
    if (b == 0)
        return a > 0 ? FX_MAX : (a < 0 ? FX_MIN : 0);
    int64_t n = (int64_t)a * 65536, q = n / b, r = n % b;
    int64_t ar = r < 0 ? -r : r, ab = b < 0 ? -(int64_t)b : b;
    if (2 * ar >= ab)
        q += (n < 0) != (b < 0) ? -1 : 1;
    return q > INT32_MAX ? FX_MAX : (q < INT32_MIN ? FX_MIN : (fx_t)q);
}

static void check_div(fx_t a, fx_t b)
{
    fx_t q = fx_div(a, b);
    long double exact;
    if (b == 0)
        exact = a > 0 ? INT32_MAX : (a < 0 ? INT32_MIN : 0);
    else
        exact = sat((long double)a * 65536.0L / (long double)b);
    long double e = fabsl((long double)q - exact);
    track(&max_err_div, e);
    CHECK_SWEEP(e <= 0.5L, "fx_div(%d, %d) = %d, exact %.3Lf", a, b, q, exact);
    CHECK_SWEEP(q == div_exact(a, b), "fx_div(%d, %d) = %d, correctly rounded %d", a, b, q, div_exact(a, b));
}

/* Exact ties: a 2^16 / b = k + 1/2 must round away from zero, to k + 1. */
static void check_div_ties(long n)
{
    for (long i = 0; i < n; i++) {
        /* b = 2^17 t, a = (2k + 1) t: a 2^16 / b = k + 1/2. */
        int32_t t = (int32_t)(1 + rng() % 16383);  /* b = t * 2^17 < 2^31 */
        int32_t kmax = (int32_t)((INT32_MAX / t - 1) / 2);
        int32_t k = (int32_t)(rng() % (uint64_t)(kmax + 1));
        fx_t a = (2 * k + 1) * t, b = t * (1 << 17);
        int sa = (rng() & 1) ? -1 : 1, sb = (rng() & 1) ? -1 : 1;
        fx_t q = fx_div(sa * a, sb * b);
        CHECK_SWEEP(q == sa * sb * (k + 1), "fx_div tie (%d, %d) = %d, want %d", sa * a, sb * b, q, sa * sb * (k + 1));
    }
}

static void check_sqrt(fx_t a)
{
    fx_t s = fx_sqrt(a);
    long double exact = a <= 0 ? 0 : sqrtl((long double)a * 65536.0L);
    long double e = fabsl((long double)s - exact);
    track(&max_err_sqrt, e);
    CHECK_SWEEP(e <= 0.5L, "fx_sqrt(%d) = %d, exact %.3Lf", a, s, exact);
}

#define RSQRT_BOUND 0.502L /* fx.h; tests/fx_exhaustive.c checks every input */
static void check_rsqrt(fx_t a)
{
    fx_t r = fx_rsqrt(a);
    if (a <= 0) {
        CHECK_SWEEP(r == FX_MAX, "fx_rsqrt(%d) = %d, want FX_MAX", a, r);
        return;
    }
    long double exact = 16777216.0L / sqrtl((long double)a);
    long double e = fabsl((long double)r - exact);
    track(&max_err_rsqrt, e);
    CHECK_SWEEP(e <= RSQRT_BOUND, "fx_rsqrt(%d) = %d, exact %.4Lf", a, r, exact);
}

static void check_recip(fx_t a)
{
    fx_t r = fx_recip(a);
    track(&max_err_recip, fabsl((long double)r - (a ? sat(4294967296.0L / (long double)a) : (long double)FX_MAX)));
    CHECK_SWEEP(r == div_exact(FX_ONE, a), "fx_recip(%d) = %d, want %d", a, r, div_exact(FX_ONE, a));
}

/* floor(sqrt(w)) exactly: long double, then integer squares in unsigned
 * __int128 (not the estimate and correction the library uses). */
__extension__ typedef unsigned __int128 u128_t;
__extension__ typedef __int128 s128_t;
static uint64_t oracle_floor_sqrt(uint64_t w)
{
    u128_t n = w, r = (u128_t)sqrtl((long double)w);
    while (r * r > n)
        r--;
    while ((r + 1) * (r + 1) <= n)
        r++;
    return (uint64_t)r;
}

/* round(sqrt(w)) exactly (no ties for an integer w). */
static uint64_t oracle_wsqrt(uint64_t w)
{
    u128_t r = oracle_floor_sqrt(w);
    return (uint64_t)(w > r * r + r ? r + 1 : r);
}

static void check_wsqrt(fxw_t w)
{
    fx_t s = fxw_sqrt(w);
    long double exact = w <= 0 ? 0 : sat(sqrtl((long double)w));
    long double e = fabsl((long double)s - exact);
    track(&max_err_wsqrt, e);
    uint64_t want = w <= 0 ? 0 : oracle_wsqrt((uint64_t)w);
    CHECK_SWEEP(e <= 0.5L, "fxw_sqrt(%lld) = %d, exact %.3Lf", (long long)w, s, exact);
    CHECK_SWEEP(s == (want > INT32_MAX ? FX_MAX : (fx_t)want), "fxw_sqrt(%lld) = %d, want %llu", (long long)w, s,
                (unsigned long long)want);
}

static void check_isqrt64(uint64_t n)
{
    uint64_t r = oracle_floor_sqrt(n);
    uint32_t got = fx_isqrt64(n);
    CHECK_SWEEP(got == (uint32_t)r, "fx_isqrt64(%llu) = %u, want %llu", (unsigned long long)n, got,
                (unsigned long long)r);
}

static void check_wdiv(fxw_t a, fxw_t b)
{
    fx_t q = fxw_div(a, b);
    long double exact;
    if (b == 0)
        exact = a > 0 ? INT32_MAX : (a < 0 ? INT32_MIN : 0);
    else
        exact = sat((long double)a / (long double)b * 65536.0L);
    long double e = fabsl((long double)q - exact);
    track(&max_err_wdiv, e);
    CHECK_SWEEP(e <= 1.0L, "fxw_div(%lld, %lld) = %d, exact %.3Lf", (long long)a, (long long)b, q, exact);
    /* The same quotient with the dividend prepared once (the shading
     * pass's planes: one numerator, a divisor per pixel). */
    fxw_dividend_t pa = fxw_dividend(a);
    fx_t qb = fxw_div_by(&pa, b);
    CHECK_SWEEP(qb == q, "fxw_div_by(fxw_dividend(%lld), %lld) = %d, fxw_div %d", (long long)a, (long long)b, qb, q);
}

/* fxw_ratio_mul(fxw_ratio_by(fxw_ratio_num(a), b), x) = x a / b within
 * 0.5 LSB + 2^-29 |x a / b| (fx.h), saturated, against long double (64
 * significant bits: a, b and x exactly, the quotient within 2^-63). */
#define RATIO_REL 0x1p-29L
static void check_ratio(fxw_t a, fxw_t b, fx_t x)
{
    fxw_ratio_num_t num = fxw_ratio_num(a);
    fxw_ratio_t q = fxw_ratio_by(&num, b);
    fx_t got = fxw_ratio_mul(&q, x);
    long double exact;
    if (a == 0 || x == 0)
        exact = 0;
    else if (b == 0)
        exact = ((a < 0) != (x < 0)) ? INT32_MIN : INT32_MAX;
    else
        exact = (long double)x * ((long double)a / (long double)b);
    long double bound = 0.5L + RATIO_REL * fabsl(exact);
    long double e = fabsl((long double)got - sat(exact));
    track(&max_err_ratio, e / bound);
    CHECK_SWEEP(e <= bound, "fxw_ratio_mul(fxw_ratio(%lld, %lld), %d) = %d, exact %.3Lf", (long long)a, (long long)b,
                x, got, exact);
}

/* fxw_ratio_by's mantissas: 0, or in (2^29, 2^31] (math/fx.c) */
#define RATIO_M_MIN ((uint64_t)1 << 29 | 1)
#define RATIO_M_MAX ((uint64_t)1 << 31)
/* fxw_ratio_mul's rule, exactly (fx.h): for a quotient q = (m, e, neg),
 * x q is m |x| 2^-e rounded once, half up, given q's sign and x's, and
 * saturated; 0 for x = 0. Checked in 128-bit integers on quotients made
 * directly, over the exponents where the product is neither 0 nor
 * saturated by size alone (e in -31 .. 63), m over fxw_ratio_by's range, x of
 * every size: the inline path (e 33 .. 63) and fxw_ratio_mul_wide's. */
static long ratio_rule_e[3]; /* e < 1, 1 .. 32, 33 .. 63 */
static long ratio_rule_sat;
static void check_ratio_rule(uint32_t m, int e, bool qneg, fx_t x)
{
    fxw_ratio_t q = {m, (int16_t)e, qneg ? -1 : 0};
    fx_t got = fxw_ratio_mul(&q, x);
    u128_t p = (u128_t)m * (uint64_t)(x < 0 ? -(int64_t)x : (int64_t)x);
    u128_t mag = e >= 1 ? (p + ((u128_t)1 << (e - 1))) >> e : p << -e;
    bool neg = qneg != (x < 0);
    int64_t want;
    if (mag > (u128_t)INT32_MAX + (neg ? 1 : 0)) {
        want = neg ? INT32_MIN : INT32_MAX;
        ratio_rule_sat++;
    } else
        want = neg ? -(int64_t)mag : (int64_t)mag;
    ratio_rule_e[e < 1 ? 0 : e <= 32 ? 1 : 2]++;
    CHECK_SWEEP(got == want, "fxw_ratio_mul({m %u, e %d, %s}, %d) = %d, the rule gives %lld", m, e,
                qneg ? "negative" : "positive", x, got, (long long)want);
}

static void check_cot(fx_t deg)
{
    fx_t c = fx_cot_deg(deg);
    long double x = (long double)deg / 65536.0L * 3.14159265358979323846264338327950288L / 180.0L;
    long double exact = sat(cosl(x) / sinl(x) * 65536.0L);
    long double e = fabsl((long double)c - exact);
    long double bound = 1.0L + 1e-7L * fabsl(exact);
    track(&max_err_cot, e / bound);
    CHECK_SWEEP(e <= bound, "fx_cot_deg(%d) = %d, exact %.3Lf", deg, c, exact);
}

/* sin/cos of Q16.16 degrees against long double: the angle is reduced
 * modulo 360 exactly (in integers, as the oracle must not lose the low
 * bits of large angles) and then converted to radians in long double. */
#define SIN_BOUND 0.502L
static long double deg_to_rad_exact(fx_t deg)
{
    int64_t full = (int64_t)360 << 16;
    int64_t a = (int64_t)deg % full;
    if (a < 0)
        a += full;
    return (long double)a / 65536.0L * 3.14159265358979323846264338327950288L / 180.0L;
}

static void check_sincos(fx_t deg)
{
    long double x = deg_to_rad_exact(deg);
    fx_t s = fx_sin_deg(deg), c = fx_cos_deg(deg);
    long double es = fabsl((long double)s - sinl(x) * 65536.0L);
    long double ec = fabsl((long double)c - cosl(x) * 65536.0L);
    track(&max_err_sin, es);
    track(&max_err_cos, ec);
    CHECK_SWEEP(es <= SIN_BOUND, "fx_sin_deg(%d) = %d, exact %.4Lf", deg, s, sinl(x) * 65536.0L);
    CHECK_SWEEP(ec <= SIN_BOUND, "fx_cos_deg(%d) = %d, exact %.4Lf", deg, c, cosl(x) * 65536.0L);
    CHECK_SWEEP(s <= FX_ONE && s >= -FX_ONE && c <= FX_ONE && c >= -FX_ONE, "|sin|,|cos| <= 1 at %d", deg);
    if (deg != FX_MIN) {
        CHECK_SWEEP(fx_sin_deg(-deg) == -s, "sin odd at %d", deg);
        CHECK_SWEEP(fx_cos_deg(-deg) == c, "cos even at %d", deg);
    }
}

#define NORM_BOUND 0.504L /* fx.h */
#define NORM_LEN_REL 0x1p-24L /* fx.h: fx_normalize3_len */
static void check_norm(fx_t x, fx_t y, fx_t z)
{
    fx_t v[3] = {x, y, z};
    bool ok = fx_normalize3(v);
    if (x == 0 && y == 0 && z == 0) {
        CHECK_SWEEP(!ok && v[0] == 0 && v[1] == 0 && v[2] == 0, "zero vector");
        return;
    }
    long double len = sqrtl((long double)x * x + (long double)y * y + (long double)z * z);
    long double in[3] = {x, y, z};
    for (int i = 0; i < 3; i++) {
        long double e = fabsl((long double)v[i] - in[i] / len * 65536.0L);
        track(&max_err_norm, e);
        CHECK_SWEEP(ok && e <= NORM_BOUND, "fx_normalize3(%d,%d,%d)[%d] = %d, exact %.3Lf", x, y, z, i, v[i],
                  in[i] / len * 65536.0L);
    }
    /* fx_normalize3_len: the same direction, and the length within 2^-24
     * relative + 0.5 LSB (fx.h), saturated at FX_MAX. */
    fx_t u[3] = {x, y, z}, l = -1;
    bool okl = fx_normalize3_len(u, &l);
    CHECK_SWEEP(okl && u[0] == v[0] && u[1] == v[1] && u[2] == v[2], "fx_normalize3_len(%d,%d,%d): direction", x, y,
                z);
    long double want = len > (long double)FX_MAX ? (long double)FX_MAX : len;
    long double el = fabsl((long double)l - want), bound = NORM_LEN_REL * len + 0.5L;
    track(&max_err_norm_len, el / bound);
    CHECK_SWEEP(el <= bound, "fx_normalize3_len(%d,%d,%d) length %d, exact %.3Lf", x, y, z, l, len);
    /* Its two stages: fx_inv3 gives the same length, fx_inv3_unit the same
     * unit vector; fx_inv3_mul, H / |v| for a wide H of any size and sign
     * (the light sum's n . l on a plane), within 0.5 LSB + 2^-23 relative
     * of the exact quotient, saturated. */
    fx_inv3_t q;
    fx_t w[3] = {x, y, z}, u3[3] = {0, 0, 0}, l3 = -1;
    bool ok3 = fx_inv3(w, &q, &l3);
    if (ok3)
        fx_inv3_unit(&q, w, u3);
    CHECK_SWEEP(ok3 && l3 == l && u3[0] == v[0] && u3[1] == v[1] && u3[2] == v[2], "fx_inv3(%d,%d,%d)", x, y, z);
    int64_t H = (int64_t)(rng() >> 8 >> (rng() % 56)) * ((rng() & 1) ? 1 : -1); /* |H| < 2^56 */
    fx_mant_t hm = fx_mant64(H);
    long double hv = ldexpl((long double)fx_mant_m(hm), fx_mant_e(hm)), am = fabsl((long double)fx_mant_m(hm));
    CHECK_SWEEP(H == 0 ? fx_mant_m(hm) == 0
                       : (am >= 0x1p24L && am < 0x1p25L && (fx_mant_m(hm) < 0) == (H < 0) &&
                          fabsl(hv - (long double)H) <= fabsl((long double)H) * 0x1p-24L),
                "fx_mant64(%lld) = %d 2^%d", (long long)H, fx_mant_m(hm), fx_mant_e(hm));
    if (ok3) {
        long double exact = (long double)H / len, lim = (long double)FX_MAX;
        long double want_q = exact > lim ? lim : exact < -lim ? -lim : exact;
        fx_t got = fx_inv3_mul(&q, hm);
        long double eq = fabsl((long double)got - want_q), bq = 0.5L + 0x1p-23L * fabsl(want_q);
        track(&max_err_inv3_mul, eq / bq);
        CHECK_SWEEP(eq <= bq, "fx_inv3_mul(%d,%d,%d; H %lld) = %d, exact %.3Lf", x, y, z, (long long)H, got, exact);
    }
}

/* numw_sticky (a directional light's n . l on a plane, light/shade.c):
 * for wide x of every size below 2^44 and either sign, many of them on or
 * beside a tie of round half up, numw_sticky_round(s) and
 * numw_sticky_round(-s) are x's and -x's rounding, computed here by
 * floorl(x / 2^16 + 1/2), and s has x's sign. */
static void check_sticky(long n)
{
    long bad = 0;
    for (long i = 0; i < n; i++) {
        int64_t x;
        if (i % 3 == 0) /* a tie, or one LSB^2 beside it */
            x = (int64_t)(rng() % ((uint64_t)1 << 28)) * 65536 + 32768 + (int64_t)(rng() % 3) - 1;
        else if (i % 3 == 1)
            x = (int64_t)(rng() >> (20 + rng() % 44)); /* log-uniform, below 2^44 */
        else
            x = (int64_t)(rng() % 70000); /* around one LSB */
        x = rng() & 1 ? -x : x;
        numw_sticky_t s = numw_sticky(x);
        long double up = floorl((long double)x / 65536.0L + 0.5L), dn = floorl(-(long double)x / 65536.0L + 0.5L);
        if (((long double)numw_sticky_round(s) != up || (long double)numw_sticky_round(-s) != dn ||
             (s > 0) != (x > 0) || (s < 0) != (x < 0)) &&
            bad++ < 5)
            printf("numw_sticky(%lld) = %d: rounds to %d and %d, want %.0Lf and %.0Lf\n", (long long)x, s,
                   numw_sticky_round(s), numw_sticky_round(-s), up, dn);
    }
    CHECK_MSG(bad == 0, "numw_sticky: %ld of %ld values round wrong on one side", bad, n);
}

/* Random vector components inside the renderer's domain (|c| <= 2 *
 * FXRT_COORD_LIMIT, so a dot of three products cannot leave Q32.32). */
static fx_t rand_coord(void)
{
    fx_t v = rand_fx();
    return v / 2; /* |v| < 2^30 LSB = 16384 */
}

static void check_vec(void)
{
    vec3_t a = vec3_make(rand_coord(), rand_coord(), rand_coord());
    vec3_t b = vec3_make(rand_coord(), rand_coord(), rand_coord());
    long double exact = ((long double)a.x * b.x + (long double)a.y * b.y + (long double)a.z * b.z) / 65536.0L;
    long double e = fabsl((long double)vec3_dot(a, b) - sat(exact));
    track(&max_err_dot, e);
    CHECK_SWEEP(e <= 0.5L, "vec3_dot error %.3Lf", e);
    vec3_t c = vec3_cross(a, b);
    long double cx = sat(((long double)a.y * b.z - (long double)a.z * b.y) / 65536.0L);
    e = fabsl((long double)c.x - cx);
    track(&max_err_cross, e);
    CHECK_SWEEP(e <= 0.5L, "vec3_cross.x error %.3Lf", e);
}

static void check_fixed_cases(void)
{
    /* Named constants and the literal macro. */
    CHECK(F16(1.5) == 0x18000);
    CHECK(F16(-1.5) == -0x18000);
    CHECK(F16(0.0000076) == 0); /* below half an LSB rounds to zero */
    CHECK(FX_PI == (fx_t)lround(3.14159265358979323846 * 65536));
    /* Saturation, never wrap-around. */
    CHECK(fx_add(FX_MAX, 1) == FX_MAX);
    CHECK(fx_add(FX_MIN, -1) == FX_MIN);
    CHECK(fx_sub(FX_MIN, 1) == FX_MIN);
    CHECK(fx_sub(FX_MAX, -1) == FX_MAX);
    CHECK(fx_neg(FX_MIN) == FX_MAX);
    CHECK(fx_mul(F16(200), F16(200)) == FX_MAX);
    CHECK(fx_mul(F16(-200), F16(200)) == FX_MIN);
    CHECK(fx_div(FX_ONE, 0) == FX_MAX);
    CHECK(fx_div(-FX_ONE, 0) == FX_MIN);
    CHECK(fx_div(0, 0) == 0);
    CHECK(fx_div(F16(30000), F16(0.5)) == FX_MAX);
    CHECK(fx_sqrt(-FX_ONE) == 0);
    CHECK(fx_from_int(40000) == FX_MAX);
    CHECK(fx_from_int(-40000) == FX_MIN);
    CHECK(fx_from_int(-3) == F16(-3.0));
    CHECK(fx_mul_int(F16(1000), 100) == FX_MAX);
    CHECK(fxw_round(INT64_MAX) == FX_MAX);
    CHECK(fxw_round(INT64_MIN) == FX_MIN);
    CHECK(fxw_add(INT64_MAX, 1) == INT64_MAX);
    CHECK(fxw_add(INT64_MIN, -1) == INT64_MIN);
    /* Exact values. */
    CHECK(fx_sqrt(F16(4)) == F16(2));
    CHECK(fx_sqrt(F16(2)) == 92682);
    CHECK(fx_div(FX_ONE, F16(3)) == 21845);
    /* fx_div ties go away from zero: 1 LSB / 2 = 0.5 LSB -> 1, -0.5 -> -1. */
    CHECK(fx_div(1, F16(2)) == 1);
    CHECK(fx_div(-1, F16(2)) == -1);
    CHECK(fx_div(3, F16(-2)) == -2);
    CHECK(fx_recip(F16(-2)) == -FX_HALF);
    CHECK(fx_div(FX_MIN, FX_ONE) == FX_MIN);
    CHECK(fx_div(FX_MIN, -FX_ONE) == FX_MAX);
    CHECK(fx_div(FX_MAX, FX_MAX) == FX_ONE);
    CHECK(fx_div(FX_MIN, FX_MIN) == FX_ONE);
    CHECK(fx_div(1, FX_MIN) == 0);
    CHECK(fx_div(-FX_HALF, FX_MIN) == 1);
    CHECK(fx_div(16384, FX_MIN) == -1); /* -0.5 LSB, away from zero */
    CHECK(fx_div(16383, FX_MIN) == 0);
    CHECK(fx_mul(F16(-0.5), 1) == 0); /* -0.5 LSB ties toward +inf */
    /* The other stated tie rules (fx.h): toward +infinity for products and
     * Q32.32 roundings, away from zero for F16 and the 128-bit shifts. */
    CHECK(fx_mul(F16(0.5), 1) == 1);
    CHECK(fxw_round(FX_HALF) == 1 && fxw_round(-FX_HALF) == 0);
    CHECK(fxw_round(3 * FX_HALF) == 2 && fxw_round(-3 * FX_HALF) == -1);
    CHECK(vec3_dot(vec3_make(1, 0, 0), vec3_make(FX_HALF, 0, 0)) == 1);
    CHECK(vec3_dot(vec3_make(-1, 0, 0), vec3_make(FX_HALF, 0, 0)) == 0);
    CHECK(vec3_cross(vec3_make(0, 1, 0), vec3_make(0, 0, -FX_HALF)).x == 0);
    CHECK(F16(1.5 / 65536.0) == 2 && F16(-1.5 / 65536.0) == -2);
    CHECK(fx128_shr_round(fx128_from64(3), 1) == 2 && fx128_shr_round(fx128_from64(-3), 1) == -2);
    CHECK(fx_cot_deg(F16(45)) == FX_ONE);
    CHECK(fx_cot_deg(0) == FX_MAX);
    CHECK(fx_cot_deg(F16(90)) == 0);
    CHECK(fx_isqrt64(UINT64_MAX) == 0xffffffffu);
    CHECK(fx_isqrt64(0) == 0);
    /* sin/cos exact at multiples of 90 degrees, over the whole range. */
    for (int32_t k = -364; k <= 364; k++) {
        fx_t d = (fx_t)(k * 90 * 65536);
        int32_t q = ((k % 4) + 4) % 4;
        CHECK_MSG(fx_sin_deg(d) == (q == 1 ? FX_ONE : q == 3 ? -FX_ONE : 0), "sin(%d*90)", k);
        CHECK_MSG(fx_cos_deg(d) == (q == 0 ? FX_ONE : q == 2 ? -FX_ONE : 0), "cos(%d*90)", k);
    }
    CHECK(fx_sin_deg(F16(30)) == FX_HALF);
    CHECK(fx_cos_deg(F16(60)) == FX_HALF);
    CHECK(fx_sin_deg(F16(-30)) == -FX_HALF);
    CHECK(fx_sin_deg(F16(45)) == fx_cos_deg(F16(45)));
    CHECK(fx_sin_deg(1) == 0); /* 2^-16 degree = 2.7e-7 rad = 0.017 LSB */
    CHECK(fx_sin_deg(F16(0.0286)) == 33); /* 0.0286 deg = 32.72 LSB of sine */
    fx_t unit[3] = {0, F16(-3), 0};
    CHECK(fx_normalize3(unit) && unit[0] == 0 && unit[1] == -FX_ONE && unit[2] == 0);
}

/* One case of numw_dot3_units (units) or numw_dot3_unit against the exact
 * sum in __int128: 1 when it differs. Counts the cases inside the M0's
 * 32-bit range (fx_dot3_small, fx_dot3_wide) in *in_range; a sum beyond
 * int64 (no dot product of the renderer's) is skipped. */
static long check_dot3(const int32_t a[3], const int32_t u[3], bool units, long *in_range)
{
    s128_t want = (s128_t)a[0] * u[0] + (s128_t)a[1] * u[1] + (s128_t)a[2] * u[2];
    if (want > INT64_MAX || want < INT64_MIN)
        return 0;
    if (units) {
        *in_range += fx_dot3_small_ok(a[0], a[1], a[2], u[0], u[1], u[2]);
        return numw_dot3_units(a[0], a[1], a[2], u[0], u[1], u[2]) != (int64_t)want;
    }
    *in_range += fx_dot3_wide_ok(a[0], a[1], a[2], u[0], u[1], u[2]);
    return numw_dot3_unit(a[0], a[1], a[2], u[0], u[1], u[2]) != (int64_t)want;
}

/* numw_pow_int's shortcut: 0 without the products where b k <= (k - 12)
 * 2^31 (b: x in Q1.31). The loop is monotone in b (each rounded product
 * of non-negative values is), so its value 0 at the largest such b, for
 * every exponent the scene format allows, proves the shortcut gives the
 * loop's value everywhere; sampled pairs check the monotony, and the
 * shortcut is checked not to fire just above that b. */
static void check_pow_zero(void)
{
    long bad = 0, bad_mono = 0;
    for (uint32_t k = NUM_POW_ZERO_K + 1; k <= FXRT_PHONG_MAX_EXPONENT; k++) {
        uint32_t bt = (uint32_t)((((uint64_t)(k - NUM_POW_ZERO_K)) << 31) / k);
        if (numw_pow_loop(bt, k) != 0 || numw_pow_int((numw_t)bt << 1, k) != 0)
            bad++;
        if (numw_pow_int(((numw_t)bt + 1) << 1, k) != numw_pow_loop(bt + 1, k))
            bad++;
        for (int i = 0; i < 64; i++) {
            uint32_t b1 = (uint32_t)(rng() >> 33), b2 = (uint32_t)(rng() >> 33);
            if (b1 > b2) {
                uint32_t t = b1;
                b1 = b2;
                b2 = t;
            }
            if (numw_pow_loop(b1, k) > numw_pow_loop(b2, k))
                bad_mono++;
        }
    }
    CHECK_MSG(bad == 0, "numw_pow_int: %ld exponents where the shortcut's region is not all 0", bad);
    CHECK_MSG(bad_mono == 0, "numw_pow_loop: %ld sampled pairs out of order", bad_mono);
}

/* fx_ratio_len_below and the specular term's shortcut (numw_pow_zero_at):
 * against x = a / (2^16 sqrt(d2)) in long double, for vectors v of
 * log-uniform components (2^-16 .. 2^8, d2 = |v|^2 exact) and a drawn
 * over [-0.25, 2] |v| and close to each exponent's bound. Sound: true
 * only where x <= (num / den)(1 - 2^-10); tight: true where x lies 2^-12
 * below that; and where numw_pow_zero_at says 0, the value the full path
 * would compute (num_inv3_only, num_inv3_mul, numw_pow_int) is 0. */
static void check_ratio_below(void)
{
    long n = n_random / 4 + 1000, unsound = 0, loose = 0, e2e = 0, said = 0;
    for (long i = 0; i < n; i++) {
        fx_t v[3];
        int64_t d2 = 0;
        for (int j = 0; j < 3; j++) {
            uint64_t r = rng();
            int bits = (int)(r % 25); /* |v_j| below 2^bits LSB: up to 256.0 */
            fx_t m = bits ? (fx_t)((r >> 32) >> (32 - bits)) : 0;
            v[j] = (r & 64) ? -m : m;
            d2 += (int64_t)v[j] * v[j];
        }
        if (d2 == 0)
            continue;
        uint32_t k = NUM_POW_ZERO_K + 1 + (uint32_t)(rng() % (FXRT_PHONG_MAX_EXPONENT - NUM_POW_ZERO_K));
        long double bound = (long double)(k - NUM_POW_ZERO_K) / k * (1.0L - 1.0L / 1024);
        long double len = sqrtl((long double)d2) * 65536.0L; /* |v| in Q32.32 units of a */
        uint64_t r = rng();
        long double x = (r & 1) ? -0.25L + 2.25L * (long double)(r >> 11) / 9007199254740992.0L
                                : bound + ((long double)(r >> 11) / 9007199254740992.0L - 0.5L) / 1024;
        fxw_t a = (fxw_t)llroundl(x * len);
        long double xt = (long double)a / len;
        bool below = fx_ratio_len_below(a, d2, k - NUM_POW_ZERO_K, k);
        said += below;
        if (below && xt > bound * (1.0L + 1e-15L))
            unsound++;
        if (!below && xt <= bound - 1.0L / 4096)
            loose++;
        num_inv3_t q;
        if (numw_pow_zero_at(a, d2, k) &&
            (!num_inv3_only(v, &q) || numw_pow_int(numw_from(num_inv3_mul(&q, numw_mant(a))), k) != 0))
            e2e++;
    }
    CHECK_MSG(unsound == 0, "fx_ratio_len_below: %ld of %ld said below where x is above the bound", unsound, n);
    CHECK_MSG(loose == 0, "fx_ratio_len_below: %ld of %ld not said below 2^-12 under the bound", loose, n);
    CHECK_MSG(e2e == 0, "numw_pow_zero_at: %ld of %ld said 0 where the full path gives a term", e2e, n);
    CHECK_MSG(said > n / 8 && said < n - n / 8, "fx_ratio_len_below: said below %ld times of %ld (draws one-sided)", said, n);
    CHECK(fx_ratio_len_below(-5, 1, 1, 2) && fx_ratio_len_below(0, 1, 1, 2));
    CHECK(!fx_ratio_len_below(1, 0, 1, 2) && !fx_ratio_len_below(1, -1, 1, 2) && !fx_ratio_len_below(1, 1, 1, 1025) &&
          !fx_ratio_len_below(1, 1, 3, 2));
    /* x = 0.5 exactly (a = 2^31 for |v| = 1.0, d2 = 2^32): below 0.51, not below 0.5 (1 - 2^-10) */
    CHECK(fx_ratio_len_below((fxw_t)1 << 31, (fxw_t)1 << 32, 51, 100) &&
          !fx_ratio_len_below((fxw_t)1 << 31, (fxw_t)1 << 32, 1, 2));
}

int main(int argc, char **argv)
{
    if (argc > 1)
        n_random = atol(argv[1]);
    else if (getenv("FX_TEST_RANDOM"))
        n_random = atol(getenv("FX_TEST_RANDOM"));

    check_fixed_cases();
    check_pow_zero();
    check_ratio_below();
    for (int i = 0; i < N_HARD; i++) {
        check_sqrt(hard[i]);
        check_rsqrt(hard[i]);
        check_recip(hard[i]);
        check_wsqrt((fxw_t)hard[i] * ((fxw_t)1 << 24));
        for (int j = 0; j < N_HARD; j++) {
            check_mul(hard[i], hard[j]);
            check_div(hard[i], hard[j]);
            check_wdiv((fxw_t)hard[i] * ((fxw_t)1 << 20), (fxw_t)hard[j] * ((fxw_t)1 << 12));
            check_norm(hard[i], hard[j], hard[(i + j) % N_HARD]);
        }
    }
    /* fxw_div at the ends of the 64-bit range (INT64_MIN's magnitude is
     * 2^63, one more than any positive value). */
    {
        static const fxw_t wide[] = {INT64_MIN, INT64_MIN + 1, INT64_MAX, -1, 1, (fxw_t)1 << 40, -((fxw_t)1 << 40),
                                     (fxw_t)1 << 62, -((fxw_t)1 << 62), 3, -65536};
        for (size_t i = 0; i < sizeof wide / sizeof wide[0]; i++)
            for (size_t j = 0; j < sizeof wide / sizeof wide[0]; j++) {
                check_wdiv(wide[i], wide[j]);
                for (int k = 0; k < N_HARD; k++)
                    check_ratio(wide[i], wide[j], hard[k]);
            }
    }
    /* Every cot in steps of 1/16 degree, plus the smallest angles. */
    for (fx_t d = 1; d < F16(90); d += 4096)
        check_cot(d);
    for (fx_t d = 1; d < 64; d++)
        check_cot(d);
    /* sin/cos: the hard table, the extremes, near each quarter turn, and
     * every 1/256 degree of a full turn. */
    for (int i = 0; i < N_HARD; i++)
        check_sincos(hard[i]);
    static const fx_t sc_hard[] = {FX_MAX, FX_MIN, FX_MIN + 1, FX_MAX - 1, 1, -1, 2, -2, F16(45), F16(-45),
                                   F16(135), F16(225), F16(315), F16(360) - 1, F16(360) + 1, F16(32767),
                                   F16(-32768) + 1, F16(30), F16(60), F16(0.5)};
    for (int i = 0; i < (int)(sizeof sc_hard / sizeof sc_hard[0]); i++)
        check_sincos(sc_hard[i]);
    for (int32_t k = -8; k <= 8; k++)
        for (int32_t e = -3; e <= 3; e++)
            check_sincos((fx_t)(k * 90 * 65536) + e);
    for (fx_t d = 0; d <= F16(360); d += 256)
        check_sincos(d);

    check_div_ties(n_random / 10 + 1000);
    check_sticky(n_random / 10 + 1000);
    /* fx_udiv64_32: floor(n / d) for every n < d 2^32, against the
     * compiler's 64-bit division: the ends of the range, the walk's
     * reciprocals 2^53 / d (d above 2^22), and random divisors of every
     * bit length with random numerators. */
    {
        static const uint32_t dh[] = {1, 2, 3, 0xffffu, 0x10000u, 0x10001u, 0x7fffffffu, 0x80000000u,
                                      0x80000001u, 0xffffffffu, 0xfffffffeu, (1u << 22) + 1, 12345679u};
        long bad = 0;
        for (size_t i = 0; i < sizeof dh / sizeof dh[0]; i++) {
            uint64_t top = ((uint64_t)dh[i] << 32) - 1;
            const uint64_t nh[] = {0, 1, dh[i] - 1u, dh[i], top, top - dh[i], top / 2, (uint64_t)1 << 53};
            for (size_t j = 0; j < sizeof nh / sizeof nh[0]; j++)
                if (nh[j] <= top && fx_udiv64_32(nh[j], dh[i]) != nh[j] / dh[i]) {
                    if (bad++ < 5)
                        printf("fx_udiv64_32(%llu, %u) = %u, want %llu\n", (unsigned long long)nh[j], dh[i],
                               fx_udiv64_32(nh[j], dh[i]), (unsigned long long)(nh[j] / dh[i]));
                }
        }
        for (long i = 0; i < n_random; i++) {
            int bits = 1 + (int)(rng() % 32);
            uint32_t d = (uint32_t)(rng() >> (64 - bits)) | (1u << (bits - 1));
            uint64_t n = i & 1 ? rng() % ((uint64_t)d << 32) : ((uint64_t)1 << 53) + (rng() & 0xffff);
            if (!(i & 1))
                d = (uint32_t)((1u << 22) + 1 + rng() % (0x80000000u - (1u << 22)));
            if (fx_udiv64_32(n, d) != n / d && bad++ < 5)
                printf("fx_udiv64_32(%llu, %u) = %u, want %llu\n", (unsigned long long)n, d, fx_udiv64_32(n, d),
                       (unsigned long long)(n / d));
        }
        CHECK_MSG(bad == 0, "fx_udiv64_32: %ld quotients differ from the 64-bit division", bad);
    }
    /* fx_smul_unit: the exact product for every a and a unit vector's
     * component u (|u| <= 2^16: the two-product path and, at 2^16, the
     * fallback), and for u outside that range (the fallback). */
    {
        static const int32_t ua[] = {INT32_MIN, INT32_MIN + 1, INT32_MAX, -1, 0, 1, 65535, 65536, -65536, -65537,
                                     0x7fff0000, -0x7fff0000, 0x12345678};
        static const int32_t uu[] = {-65536, -65535, -1, 0, 1, 32768, 65535, 65536, 65537, -65537, INT32_MIN, INT32_MAX};
        long bad = 0;
        for (size_t i = 0; i < sizeof ua / sizeof ua[0]; i++)
            for (size_t j = 0; j < sizeof uu / sizeof uu[0]; j++)
                bad += fx_smul_unit(ua[i], uu[j]) != (int64_t)ua[i] * uu[j];
        for (long i = 0; i < n_random; i++) {
            int32_t a = (int32_t)(uint32_t)rng();
            int32_t u = (int32_t)(rng() % 131073) - 65536;
            if (i & 1)
                a >>= rng() % 31; /* every magnitude */
            bad += fx_smul_unit(a, u) != (int64_t)a * u;
        }
        CHECK_MSG(bad == 0, "fx_smul_unit: %ld products differ from the exact one", bad);
    }
    /* fx_usqr32 (the M0: three 16-bit products, the middle one's 2^17
     * split across the words): a^2 exactly, for hard cases (each half 0,
     * 1 or 2^16 - 1, where the carries are) and random a of every
     * magnitude, from their own generator (the shared one's sequence
     * stays that of the checks after this one). */
    {
        uint64_t sq_state = 0x243F6A8885A308D3ull;
        static const uint32_t sq[] = {0, 1, 0xffffu, 0x10000u, 0x1ffffu, 0x7fffffffu, 0x80000000u, 0xffffffffu,
                                      0xffff0000u, 0xffff0001u, 0x0001ffffu, 0x8000ffffu, 0x40000000u, 0x3fffffffu};
        long bad = 0;
        for (size_t i = 0; i < sizeof sq / sizeof sq[0]; i++)
            bad += fx_usqr32(sq[i]) != (uint64_t)sq[i] * sq[i];
        for (long i = 0; i < n_random; i++) {
            uint64_t r = check_rng_next(&sq_state);
            uint32_t a = (uint32_t)(r >> 32) >> (i & 1 ? r % 32 : 0);
            bad += fx_usqr32(a) != (uint64_t)a * a;
        }
        CHECK_MSG(bad == 0, "fx_usqr32: %ld squares differ from the exact one", bad);
    }
    /* numw_dot3_units (the M0: fx_dot3_small within [-2^18, 2^18), the
     * product sum outside): the exact a . u for unit vectors' components,
     * the range's ends, and components beyond it in either vector. */
    {
        static const int32_t ev[] = {-131072, -131071, -65536, -65535, -256, -255, -1, 0, 1, 255, 256, 65535, 65536,
                                     131071, 131072, -131073, -262144, 262143, INT32_MAX, INT32_MIN + 1};
        const size_t ne = sizeof ev / sizeof ev[0];
        long bad = 0, small = 0;
        for (long i = 0; i < n_random + (long)(3 * ne * ne * ne); i++) {
            int32_t c[6];
            if (i < (long)(3 * ne * ne * ne)) {
                /* every triple of ends in a, against three choices of u */
                size_t x = (size_t)i / 3 % ne, y = (size_t)i / 3 / ne % ne, z = (size_t)i / 3 / ne / ne, v = (size_t)i % 3;
                c[0] = ev[x], c[1] = ev[y], c[2] = ev[z];
                c[3] = ev[(x + y + v) % ne], c[4] = ev[(y + z + 2 * v) % ne], c[5] = ev[(x + z + 3 * v) % ne];
            } else {
                /* mostly within 2^17; one in 16 with all six up to 2^19
                 * (partly outside the range), one in 16 with one of any
                 * magnitude */
                for (int k = 0; k < 6; k++)
                    c[k] = i % 16 == 15 && k == (int)(i / 16 % 6) ? (int32_t)(uint32_t)rng() >> (rng() % 31)
                           : i % 16 == 14                          ? (int32_t)(rng() % 1048576) - 524288
                                                                   : (int32_t)(rng() % 262144) - 131072;
            }
            bad += check_dot3(c, c + 3, true, &small);
        }
        CHECK_MSG(bad == 0 && small > n_random / 2, "numw_dot3_units: %ld wrong (%ld in the small range)", bad, small);
        /* numw_dot3_unit (the M0: fx_dot3_wide for |a_i| < 2^28): a of
         * every magnitude, the ends 2^28 - 1 and -2^28 against u at its
         * range's ends, and u beyond it */
        static const int32_t ea[] = {-(1 << 29), -(1 << 28) - 1, -(1 << 28), -(1 << 28) + 1, -65536, -255, 0, 255,
                                     65535, (1 << 28) - 1, 1 << 28, (1 << 29) - 1, INT32_MAX, INT32_MIN};
        const size_t na = sizeof ea / sizeof ea[0];
        long wide = 0;
        bad = 0;
        for (long i = 0; i < n_random + (long)(na * na * na * ne); i++) {
            int32_t a[3], u[3];
            if (i < (long)(na * na * na * ne)) {
                size_t q = (size_t)i;
                a[0] = ea[q % na], a[1] = ea[q / na % na], a[2] = ea[q / na / na % na];
                u[0] = ev[q / na / na / na], u[1] = ev[(q + 5) % ne], u[2] = ev[(q / 7 + 11) % ne];
                if (q < na * ne) /* equal components: every product at once at its extreme */
                    a[0] = a[1] = a[2] = ea[q % na], u[0] = u[1] = u[2] = ev[q / na];
            } else {
                for (int k = 0; k < 3; k++) {
                    a[k] = (int32_t)(uint32_t)rng() >> (rng() % 31);
                    u[k] = i % 16 == 15 ? (int32_t)(rng() % 1048576) - 524288 : (int32_t)(rng() % 262144) - 131072;
                }
            }
            bad += check_dot3(a, u, false, &wide);
        }
        CHECK_MSG(bad == 0 && wide > n_random / 8, "numw_dot3_unit: %ld wrong (%ld in the wide range)", bad, wide);
    }
    /* fx_mul_unit_fits: fx_mul's rounding of a u (floor((a u + 2^15) /
     * 2^16), ties toward +infinity) wherever the result fits: |u| <= 2^16
     * (the M0's folded rounding, both signs, ties included) and larger u. */
    {
        static const int32_t av[] = {INT32_MIN + 1, -0x40000000, -98304, -32768, -32769, -1, 0, 1, 32767, 32768, 98304,
                                     0x7fff8000, INT32_MAX};
        static const int32_t uvv[] = {-65536, -65535, -32768, -2, -1, 0, 1, 2, 32768, 65535, 65536, 65537, -98304};
        long bad = 0, n = 0;
        for (size_t i = 0; i < sizeof av / sizeof av[0]; i++)
            for (size_t j = 0; j < sizeof uvv / sizeof uvv[0]; j++) {
                int64_t w = ((int64_t)av[i] * uvv[j] + 32768) >> 16;
                if (w < INT32_MIN || w > INT32_MAX)
                    continue;
                n++;
                bad += fx_mul_unit_fits(av[i], uvv[j]) != (fx_t)w;
            }
        for (long i = 0; i < n_random; i++) {
            int32_t a = (int32_t)(uint32_t)rng() >> (rng() % 31);
            int32_t u = (int32_t)(rng() % 131073) - 65536;
            if (i % 4 == 3)
                a = (a & ~0xffff) | 0x8000 | (int32_t)(rng() % 2); /* ties and their neighbours */
            int64_t w = ((int64_t)a * u + 32768) >> 16;
            if (w < INT32_MIN || w > INT32_MAX)
                continue;
            n++;
            bad += fx_mul_unit_fits(a, u) != (fx_t)w;
        }
        CHECK_MSG(bad == 0 && n > n_random / 2, "fx_mul_unit_fits: %ld of %ld products rounded differently", bad, n);
    }
    /* fx_mul_unit: fx_mul's value (rounded, saturated) for every a and u,
     * the saturating ends included (2^31 after rounding, both signs). */
    {
        static const int32_t av[] = {INT32_MIN, INT32_MIN + 1, -0x7fff8000, -0x7fff7fff, -98304, -32769, -1, 0, 1,
                                     32768, 0x7fff7fff, 0x7fff8000, INT32_MAX};
        static const int32_t uvv[] = {-65537, -65536, -65535, -32768, -1, 0, 1, 32768, 65535, 65536, 65537, INT32_MAX};
        long bad = 0;
        for (size_t i = 0; i < sizeof av / sizeof av[0]; i++)
            for (size_t j = 0; j < sizeof uvv / sizeof uvv[0]; j++)
                bad += fx_mul_unit(av[i], uvv[j]) != fx_mul(av[i], uvv[j]);
        for (long i = 0; i < n_random; i++) {
            int32_t a = (int32_t)(uint32_t)rng() >> (rng() % 31);
            int32_t u = i % 8 == 7 ? (int32_t)(uint32_t)rng() : (int32_t)(rng() % 131073) - 65536;
            bad += fx_mul_unit(a, u) != fx_mul(a, u);
        }
        CHECK_MSG(bad == 0, "fx_mul_unit: %ld products differ from fx_mul's", bad);
    }
    /* The unsaturated helpers: within their stated ranges each equals the
     * saturating operation it replaces (and the exact value), at the range
     * ends and for random operands of every magnitude. */
    {
        long bad = 0;
        static const int32_t ea[] = {INT32_MIN, INT32_MIN + 1, INT32_MAX, -1, 0, 1, 65536, -65536, 0x12345678};
        for (size_t i = 0; i < sizeof ea / sizeof ea[0]; i++)
            for (size_t j = 0; j < sizeof ea / sizeof ea[0]; j++) {
                int64_t p = (int64_t)ea[i] * ea[j];
                bad += fx_smul32(ea[i], ea[j]) != p;
                /* acc + a b for accumulators that keep the sum in range */
                int64_t acc = p >= 0 ? -((int64_t)1 << 62) : ((int64_t)1 << 62) - 1;
                bad += fx_smlal32(acc, ea[i], ea[j]) != acc + p;
                /* p q - r s: every product pair, the extremes included */
                for (size_t k = 0; k < sizeof ea / sizeof ea[0]; k++)
                    bad += vec3_det2w(ea[i], ea[j], ea[k], ea[i]) != p - (int64_t)ea[k] * ea[i];
            }
        for (long i = 0; i < n_random; i++) {
            int32_t a = (int32_t)(uint32_t)rng() >> (rng() % 31), b = (int32_t)(uint32_t)rng() >> (rng() % 31);
            int32_t c = (int32_t)(uint32_t)rng() >> (rng() % 31);
            int32_t u = (int32_t)(rng() % 131073) - 65536; /* a unit vector's component */
            int64_t acc = (int64_t)(rng() >> 2) - ((int64_t)1 << 61);
            bad += fx_smlal32(acc, a, b) != acc + (int64_t)a * b;
            bad += numw_mla_unit(acc, a, u) != acc + (int64_t)a * u;
            bad += numw_add_exact(acc, (int64_t)a * b) != numw_add(acc, (int64_t)a * b);
            bad += numw_sub_exact(acc, (int64_t)a * b) != numw_sub(acc, (int64_t)a * b);
            bad += vec3_det2w(a, b, c, u) != numw_sub(numw_mul(a, b), numw_mul(c, u));
            /* a . u and the unsaturated negation against the saturating forms */
            vec3_t va = vec3_make(a, b, c), vu = vec3_make(u, -u / 2, (u / 3) | 1);
            numw_t dsat = numw_add(numw_add(numw_mul(a, vu.x), numw_mul(b, vu.y)), numw_mul(c, vu.z));
            bad += vec3_dotw_unit(va, vu) != dsat;
            bad += numw_neg_fits(dsat) != numw_sub(0, dsat);
            vec3_t n1 = vec3_neg_unit(vu), n2 = vec3_neg(vu);
            bad += n1.x != n2.x || n1.y != n2.y || n1.z != n2.z;
            /* |s| < 2^30 LSB: the rounding fits, as vec3_scale_unit's */
            fx_t s = (fx_t)((int32_t)(uint32_t)rng() >> (1 + rng() % 31));
            vec3_t r1 = vec3_scale_unit_small(vu, s), r2 = vec3_scale_unit(vu, s);
            bad += r1.x != r2.x || r1.y != r2.y || r1.z != r2.z;
            bad += numw_round_fits((int64_t)s * u) != numw_round((int64_t)s * u);
        }
        /* the ends of vec3_scale_unit_small's range: |s| just below 2^30 LSB, |u| = 1.25 */
        static const fx_t es[] = {(1 << 30) - 1, -(1 << 30) + 1, 1, -1, 0};
        static const fx_t eu[] = {81920, -81920, 65536, -65536, 1, -1, 0};
        for (size_t i = 0; i < sizeof es / sizeof es[0]; i++)
            for (size_t j = 0; j < sizeof eu / sizeof eu[0]; j++) {
                vec3_t u = vec3_make(eu[j], eu[j], eu[j]);
                bad += vec3_scale_unit_small(u, es[i]).x != vec3_scale_unit(u, es[i]).x;
            }
        CHECK_MSG(bad == 0, "unsaturated helpers: %ld results differ from the saturating ones", bad);
    }
    /* fxw_sqrt next to exact squares and rounding boundaries, all sizes. */
    for (long i = 0; i < n_random / 10 + 1000; i++) {
        uint64_t r = (rng() >> 32) >> (rng() % 32);
        uint64_t base[2] = {r * r, r * r + r};
        for (int t = 0; t < 2; t++)
            for (int dd = -1; dd <= 1; dd++)
                if (base[t] + (uint64_t)dd <= (uint64_t)INT64_MAX)
                    check_wsqrt((fxw_t)(base[t] + (uint64_t)dd));
    }
    /* fx_isqrt64 at q^2 - 1, q^2 and q^2 + 2q = (q + 1)^2 - 1 for roots of
     * every size up to 2^32 - 1, and the ends of the range. */
    for (long i = 0; i < n_random / 10 + 1000; i++) {
        uint64_t q = (rng() >> 32) >> (rng() % 32);
        uint64_t sq = q * q;
        check_isqrt64(sq);
        check_isqrt64(sq + 2 * q);
        if (sq)
            check_isqrt64(sq - 1);
    }
    static const uint64_t isq_hard[] = {0, 1, 2, 3, 4, UINT64_MAX, UINT64_MAX - 1, (uint64_t)1 << 63, ((uint64_t)1 << 63) - 1,
                                        (uint64_t)1 << 62, ((uint64_t)1 << 48) - 1, (uint64_t)1 << 48, ((uint64_t)1 << 32) - 1,
                                        (uint64_t)1 << 32, 0xFFFFFFFE00000001ull, 0xFFFFFFFE00000000ull};
    for (int i = 0; i < (int)(sizeof isq_hard / sizeof isq_hard[0]); i++)
        check_isqrt64(isq_hard[i]);
    {
        static const int64_t sq_hard[] = {INT64_MIN, INT64_MIN + 1, INT64_MAX, -1, 0, 1, (int64_t)1 << 32, -((int64_t)1 << 32),
                                          ((int64_t)1 << 32) - 1, (int64_t)0xFFFFFFFF80000000ll};
        for (int i = 0; i < (int)(sizeof sq_hard / sizeof sq_hard[0]); i++) {
            s128_t want = (s128_t)sq_hard[i] * sq_hard[i];
            fx128_t q = fx128_sqr(sq_hard[i]), m = fx128_mul(sq_hard[i], sq_hard[i]);
            CHECK_MSG(q.lo == (uint64_t)want && q.hi == (int64_t)(want >> 64), "fx128_sqr(%lld)", (long long)sq_hard[i]);
            CHECK_MSG(m.lo == (uint64_t)want && m.hi == (int64_t)(want >> 64), "fx128_mul(%lld, same)", (long long)sq_hard[i]);
        }
    }
    check_wsqrt(INT64_MAX);
    check_wsqrt(INT64_MAX - 1);
    check_wsqrt((fxw_t)1 << 62);
    for (long i = 0; i < n_random; i++) {
        fx_t a = rand_fx(), b = rand_fx();
        check_mul(a, b);
        check_div(a, b);
        check_sqrt(a);
        check_wsqrt((fxw_t)(rng() >> 1) >> (rng() % 63));
        check_isqrt64(rng() >> (rng() % 64));
        {
            /* fx_smul_small over its whole domain (|i| < 2^15), against the
             * plain 64-bit product. */
            int32_t k = (int32_t)(rng() % 65535) - 32767;
            CHECK_SWEEP(fx_smul_small(a, k) == (int64_t)a * k, "fx_smul_small(%d, %d)", a, k);
            /* fx128_mul and fx128_sqr against the compiler's __int128. */
            int64_t x = (int64_t)rng() >> (rng() % 64), y = (int64_t)rng() >> (rng() % 64);
            s128_t px = (s128_t)x * y, sx = (s128_t)x * x;
            fx128_t m = fx128_mul(x, y), q = fx128_sqr(x);
            CHECK_SWEEP(m.lo == (uint64_t)px && m.hi == (int64_t)(px >> 64), "fx128_mul(%lld, %lld)", (long long)x,
                        (long long)y);
            CHECK_SWEEP(q.lo == (uint64_t)sx && q.hi == (int64_t)(sx >> 64), "fx128_sqr(%lld)", (long long)x);
            uint64_t w = rng() >> (rng() % 64);
            CHECK_SWEEP(fx_umul64_small(w, k) == w * (uint64_t)(int64_t)k, "fx_umul64_small(%llu, %d)",
                        (unsigned long long)w, k);
            /* numw_lt_mul (shadow rays' t < tmax): a 2^16 < t b, exactly;
             * y also made equal to a multiple of t to hit the ties. */
            fx_t t = (fx_t)(rng() >> (rng() % 33));
            int64_t tie = t ? (int64_t)(((s128_t)x * 65536) / t) : y;
            for (int j = 0; j < 2; j++) {
                int64_t bb = j ? tie : y;
                bool want_lt = (s128_t)x * 65536 < (s128_t)t * bb;
                CHECK_SWEEP(numw_lt_mul(x, t, bb) == want_lt, "numw_lt_mul(%lld, %d, %lld)", (long long)x, t,
                            (long long)bb);
            }
        }
        check_wdiv(((fxw_t)(rng() >> 1) >> (rng() % 63)) * ((rng() & 1) ? 1 : -1),
                   (fxw_t)(rng() >> 1) >> (rng() % 63));
        /* ratios of every size, x of every size (its magnitude drawn by
         * its bit length, so that small values are as likely as large) */
        check_ratio(((fxw_t)(rng() >> 1) >> (rng() % 63)) * ((rng() & 1) ? 1 : -1),
                    ((fxw_t)(rng() >> 1) >> (rng() % 63)) * ((rng() & 1) ? 1 : -1),
                    (fx_t)((int32_t)(uint32_t)rng() >> (rng() % 32)));
        check_ratio_rule(rng() % 16 == 0 ? 0 : (uint32_t)(RATIO_M_MIN + rng() % (RATIO_M_MAX - RATIO_M_MIN + 1)),
                         -31 + (int)(rng() % 95), rng() & 1,
                         (fx_t)((int32_t)(uint32_t)rng() >> (rng() % 32)));
        check_norm(rand_fx(), rand_fx(), rand_fx());
        check_vec();
        check_sincos(rand_fx());
        check_rsqrt(a);
        check_recip(b);
        if (i % 16 == 0)
            check_cot((fx_t)(rng() % (uint64_t)F16(90)));
    }
    /* every path of the rule, and its saturation, met often */
    CHECK_MSG(ratio_rule_e[0] > 1000 && ratio_rule_e[1] > 1000 && ratio_rule_e[2] > 1000 && ratio_rule_sat > 1000,
              "fxw_ratio_mul's rule met on every path: e < 1 %ld, 1..32 %ld, 33..63 %ld times, saturated %ld",
              ratio_rule_e[0], ratio_rule_e[1], ratio_rule_e[2], ratio_rule_sat);
    for (int e = 1; e <= 32; e++) /* and at each edge of the 32-bit path: the largest m and x, the smallest */
        for (int k = 0; k < 4; k++)
            check_ratio_rule(k & 1 ? RATIO_M_MAX : RATIO_M_MIN, e, k & 2, k & 2 ? INT32_MIN : INT32_MAX);
    printf("worst error in LSB over %ld random inputs each:\n", n_random);
    printf("  fx_mul %.3f  fx_div %.3f  fx_sqrt %.3f  fxw_sqrt %.3f  fxw_div %.3f\n", max_err_mul,
           max_err_div, max_err_sqrt, max_err_wsqrt, max_err_wdiv);
    printf("  fx_normalize3 %.3f  vec3_dot %.3f  vec3_cross %.3f  fx_cot_deg %.3f of its bound\n",
           max_err_norm, max_err_dot, max_err_cross, max_err_cot);
    printf("  fx_sin_deg %.4f  fx_cos_deg %.4f  fx_rsqrt %.4f  fx_recip %.3f\n", max_err_sin, max_err_cos,
           max_err_rsqrt, max_err_recip);
    printf("  fx_normalize3_len: length error %.3f of its bound (2^-24 relative + 0.5 LSB)\n", max_err_norm_len);
    printf("  fxw_ratio_mul: %.3f of its bound (0.5 LSB + 2^-29 relative)\n", max_err_ratio);
    printf("  fx_inv3_mul: %.3f of its bound (0.5 LSB + 2^-23 relative)\n", max_err_inv3_mul);
    /* Machine-readable worst errors for make bench-fx (firmware/benchfx.sh). */
    printf("ERR fx_mul %.3f\nERR fx_div %.3f\nERR fx_recip %.3f\nERR fx_sqrt %.3f\nERR fxw_sqrt %.3f\n", max_err_mul,
           max_err_div, max_err_recip, max_err_sqrt, max_err_wsqrt);
    printf("ERR fxw_div %.3f\nERR fx_rsqrt %.4f\nERR fx_sin_deg %.4f\nERR fx_cos_deg %.4f\n", max_err_wdiv,
           max_err_rsqrt, max_err_sin, max_err_cos);
    printf("ERR fx_cot_deg %.3f_of_(1+1e-7|x|)\nERR vec3_dot %.3f\nERR vec3_cross %.3f\nERR vec3_normalize %.3f\n",
           max_err_cot, max_err_dot, max_err_cross, max_err_norm);
    printf("ERR vec3_len %.3f\n", max_err_wsqrt); /* the Q32.32 root of an exact dot product */
    /* The direction is fx_normalize3's; the length, as a fraction of its bound. */
    printf("ERR vec3_unit_len %.3f (direction; length %.3f of 0.5 LSB + 2^-24 |v|)\n", max_err_norm,
           max_err_norm_len);
    /* One check per function on the sweep's worst case (the sweep itself
     * has already counted every single failure). */
    CHECK(max_err_mul <= 0.5);
    CHECK(max_err_div <= 0.5);
    CHECK(max_err_sqrt <= 0.5);
    CHECK(max_err_wsqrt <= 0.5);
    CHECK(max_err_wdiv <= 1.0);
    CHECK(max_err_ratio <= 1.0);
    CHECK(max_err_norm <= NORM_BOUND);
    CHECK(max_err_norm_len <= 1.0);
    CHECK(max_err_inv3_mul <= 1.0);
    CHECK(max_err_dot <= 0.5);
    CHECK(max_err_cross <= 0.5);
    CHECK(max_err_cot <= 1.0);
    CHECK(max_err_sin <= SIN_BOUND);
    CHECK(max_err_rsqrt <= RSQRT_BOUND);
    CHECK(max_err_recip <= 0.5);
    CHECK(max_err_cos <= SIN_BOUND);
    return check_report(TEST_FX_NAME);
}
