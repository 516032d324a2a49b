/* fx_int: helpers the Q16.16 sources share (math/fx.c, math/trig.c,
 * math/fx128.c; private to math/). */
#ifndef FXRT_MATH_FX_INT_H
#define FXRT_MATH_FX_INT_H

#include "math/fx.h"

/* Magnitude of an int64 as uint64, defined for INT64_MIN too. */
static inline uint64_t fx_uabs64(int64_t v)
{
    return v < 0 ? (uint64_t)0 - (uint64_t)v : (uint64_t)v;
}

/* Apply a sign to a rounded magnitude and saturate to the fx_t range. */
static inline fx_t fx_signed_sat(uint64_t mag, bool negative)
{
    if (negative)
        return mag >= (uint64_t)1 << 31 ? FX_MIN : -(fx_t)mag;
    return mag > (uint64_t)INT32_MAX ? FX_MAX : (fx_t)mag;
}

/* round(num / den) for unsigned operands, den != 0, without overflowing
 * num + den / 2. */
static inline uint64_t fx_udiv_round(uint64_t num, uint64_t den)
{
    uint64_t q = num / den;
    uint64_t r = num - q * den;
    /* r >= den - r is r >= den/2 (ties up) computed without overflow. */
    return q + (r >= den - r ? 1u : 0u);
}

/* Leading zero count of a non-zero uint32. Hardware CLZ where the target
 * has it; a five-step binary search on the Cortex-M0 (whose libgcc
 * __clzsi2 costs more). FX_HAVE_CLZ in core/fxrt_config.h. */
static inline __attribute__((always_inline)) int fx_clz32(uint32_t v)
{
    if (FX_HAVE_CLZ)
        return __builtin_clz(v);
    int e = 0;
    if (v < (1u << 16)) {
        v <<= 16;
        e += 16;
    }
    if (v < (1u << 24)) {
        v <<= 8;
        e += 8;
    }
    if (v < (1u << 28)) {
        v <<= 4;
        e += 4;
    }
    if (v < (1u << 30)) {
        v <<= 2;
        e += 2;
    }
    if (v < (1u << 31))
        e += 1;
    return e;
}

#endif
