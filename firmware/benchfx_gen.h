/* benchfx: what firmware/benchfx.c (Q16.16) and firmware/benchfx_num.c
 * (float) share, written once for the number type of the file that
 * includes it: the vector operations' out-of-line wrappers and the empty
 * function of their signature (names v_* in benchfx.c, f_* in
 * benchfx_num.c: BENCHFX_VEC_PREFIX, so that benchfx.sh tells their
 * symbols apart), and the timed loops (BENCHFX_TIMERS). */
#ifndef FXRT_BENCHFX_GEN_H
#define FXRT_BENCHFX_GEN_H

#include "board.h"
#include "math/vec3.h"

#ifndef BENCHFX_VEC_PREFIX
#error "define BENCHFX_VEC_PREFIX (v_ or f_) before including benchfx_gen.h"
#endif
#define BV_CAT2(a, b) a##b
#define BV_CAT(a, b) BV_CAT2(a, b)
#define BV(name) BV_CAT(BENCHFX_VEC_PREFIX, name)

static __attribute__((noinline)) void BV(empty)(vec3_t *out, const vec3_t *a, const vec3_t *b)
{
    __asm__ volatile("" : : "r"(out), "r"(a), "r"(b) : "memory");
}
static __attribute__((noinline)) void BV(dot)(vec3_t *out, const vec3_t *a, const vec3_t *b)
{
    out->x = vec3_dot(*a, *b);
}
static __attribute__((noinline)) void BV(cross)(vec3_t *out, const vec3_t *a, const vec3_t *b)
{
    *out = vec3_cross(*a, *b);
}
static __attribute__((noinline)) void BV(len)(vec3_t *out, const vec3_t *a, const vec3_t *b)
{
    (void)b;
    out->x = vec3_len(*a);
}
static __attribute__((noinline)) void BV(normalize)(vec3_t *out, const vec3_t *a, const vec3_t *b)
{
    (void)b;
    *out = *a;
    vec3_normalize(out);
}
static __attribute__((noinline)) void BV(unit_len)(vec3_t *out, const vec3_t *a, const vec3_t *b)
{
    (void)b;
    num_t len = 0;
    vec3_unit_len(*a, out, &len);
    out->x += len;
}

/* The timed loops of one number type, noinline so that every loop is the
 * same code for every function of a signature (only the pointer differs):
 * name_1 (one scalar), name_2 (two), name_v (vectors; an unused one is
 * allowed), over n inputs; each result goes through word (its bits) into
 * the volatile sink, so that no call is optimised away. */
#define BENCHFX_TIMERS(name, scalar_t, fn1_t, fn2_t, fnv_t, n, word, sink)                                     \
    static __attribute__((noinline, unused)) uint64_t name##_1(fn1_t f, const scalar_t *x)                     \
    {                                                                                                         \
        uint32_t acc = 0;                                                                                     \
        uint64_t t0 = counter_ticks();                                                                        \
        for (int i = 0; i < (n); i++)                                                                         \
            acc += word(f(x[i]));                                                                             \
        uint64_t t = counter_ticks() - t0;                                                                    \
        sink = acc;                                                                                           \
        return t;                                                                                             \
    }                                                                                                         \
    static __attribute__((noinline, unused)) uint64_t name##_2(fn2_t f, const scalar_t *x, const scalar_t *y)  \
    {                                                                                                         \
        uint32_t acc = 0;                                                                                     \
        uint64_t t0 = counter_ticks();                                                                        \
        for (int i = 0; i < (n); i++)                                                                         \
            acc += word(f(x[i], y[i]));                                                                       \
        uint64_t t = counter_ticks() - t0;                                                                    \
        sink = acc;                                                                                           \
        return t;                                                                                             \
    }                                                                                                         \
    static __attribute__((noinline, unused)) uint64_t name##_v(fnv_t f, const vec3_t *x, const vec3_t *y)      \
    {                                                                                                         \
        vec3_t out = vec3_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);                                                 \
        uint32_t acc = 0;                                                                                     \
        uint64_t t0 = counter_ticks();                                                                        \
        for (int i = 0; i < (n); i++) {                                                                       \
            f(&out, &x[i], &y[i]);                                                                            \
            acc += word(out.x);                                                                               \
        }                                                                                                     \
        uint64_t t = counter_ticks() - t0;                                                                    \
        sink = acc;                                                                                           \
        return t;                                                                                             \
    }

#endif
