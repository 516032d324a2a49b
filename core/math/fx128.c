/* fx128: the 128-bit integer operations too large to inline (exact
 * set-up arithmetic and the spheres' forms). See fx.h. */
#include "math/fx_int.h"

fx128_t fx128_mul(int64_t a, int64_t b)
{
    bool neg = (a < 0) != (b < 0);
    uint64_t x = fx_uabs64(a), y = fx_uabs64(b);
    if ((x >> 32) != 0) { /* (swapped so that a factor below 2^32 comes first) */
        uint64_t t = x;
        x = y;
        y = t;
    }
    uint32_t x0 = (uint32_t)x, x1 = (uint32_t)(x >> 32), y0 = (uint32_t)y, y1 = (uint32_t)(y >> 32);
    fx128_t r;
    if (x1 == 0) {
        /* A factor below 2^32 (the set-up's products of a Q16.16 value
         * with another or with a 64-bit one): two pieces, not four. */
        uint64_t p00 = fx_umul32(x0, y0), p01 = fx_umul32(x0, y1);
        uint64_t mid = (p00 >> 32) + (uint32_t)p01;
        r.lo = (mid << 32) | (uint32_t)p00;
        r.hi = (int64_t)((p01 >> 32) + (mid >> 32));
        return neg ? fx128_neg(r) : r;
    }
    /* 32 x 32 -> 64-bit pieces: UMULL, or inline 16-bit products on the
     * M0 (a plain 64-bit product there is a __aeabi_lmul call). */
    uint64_t p00 = fx_umul32(x0, y0), p01 = fx_umul32(x0, y1), p10 = fx_umul32(x1, y0), p11 = fx_umul32(x1, y1);
    uint64_t mid = (p00 >> 32) + (uint32_t)p01 + (uint32_t)p10;
    r.lo = (mid << 32) | (uint32_t)p00;
    r.hi = (int64_t)(p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32));
    return neg ? fx128_neg(r) : r;
}

/* a^2: fx128_mul(a, a) with three pieces instead of four (the cross
 * products are equal) and no sign. */
fx128_t fx128_sqr(int64_t a)
{
    uint64_t x = fx_uabs64(a);
    uint32_t x0 = (uint32_t)x, x1 = (uint32_t)(x >> 32);
    uint64_t p00 = fx_usqr32(x0), p01 = fx_umul32(x0, x1), p11 = fx_usqr32(x1);
    uint64_t mid = (p00 >> 32) + 2 * (uint64_t)(uint32_t)p01;
    fx128_t r;
    r.lo = (mid << 32) | (uint32_t)p00;
    r.hi = (int64_t)(p11 + 2 * (p01 >> 32) + (mid >> 32));
    return r;
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
