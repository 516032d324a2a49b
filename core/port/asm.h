/* asm: the core's inline assembly, one kernel per macro or function, each
 * chosen by port/port.h's target names and used by math/fx.h (saturating
 * additions, products, linear forms, 128-bit carries) and vis/render_row.c
 * (the row fill). Every kernel has a C twin that other targets and
 * compilers take; tests/onboard_main.c checks each against 64-bit C on
 * every board. */
#ifndef FXRT_PORT_ASM_H
#define FXRT_PORT_ASM_H

#include <stdint.h>

#include "port/port.h"

#if FXRT_PORT_V6M_ASM
/* a op b (op: "adds" or "subs"), saturating on the V flag: fx_add, fx_sub
 * (math/fx.h). */
#define PORT_SAT_ASM(op, a, b)                                                                                   \
    __extension__({                                                                                            \
        int32_t s_, t_ = (b);                                                                                     \
        __asm__(".syntax unified\n\t" op " %0, %2, %1\n\t"                                                    \
                   "bvc 1f\n\t"                                                                              \
                   "asrs %1, %2, #31\n\t"                                                                    \
                   "mvns %1, %1\n\t"                                                                         \
                   "movs %0, #1\n\t"                                                                         \
                   "lsls %0, %0, #31\n\t"                                                                    \
                   "adds %0, %0, %1\n"                                                                        \
                   "1:\n\t"                                                                                   \
                   ".syntax divided"                                                                         \
                : "=&l"(s_), "+l"(t_)                                                                          \
                : "l"(a)                                                                                       \
                : "cc");                                                                                       \
        s_;                                                                                                    \
    })
#endif

#if FXRT_PORT_THUMB2_GCC
/* lo:hi = a b (signed 32 x 32 -> 64 bits); lo:hi += a b. */
#define PORT_SMULL(lo, hi, a, b) __asm__("smull %0, %1, %2, %3" : "=&r"(lo), "=&r"(hi) : "r"(a), "r"(b))
#define PORT_SMLAL(lo, hi, a, b) __asm__("smlal %0, %1, %2, %3" : "+r"(lo), "+r"(hi) : "r"(a), "r"(b))
#endif

#if FXRT_PORT_V6M_ASM
#define PORT_LIN_TERM(lo_off, hi_off, f)                                                                   \
    "ldr %[t], [%[w], #" lo_off "]\n\t"                                                                    \
    "uxth %[u], %[t]\n\t"                                                                                \
    "mul %[u], %[" f "]\n\t"                                                                             \
    "asr %[t], %[u], #31\n\t"                                                                            \
    "add %[lo], %[lo], %[u]\n\t"                                                                         \
    "adc %[hi], %[t]\n\t"                                                                                \
    "ldr %[t], [%[w], #" lo_off "]\n\t"                                                                    \
    "lsr %[t], %[t], #16\n\t"                                                                            \
    "mul %[t], %[" f "]\n\t"                                                                             \
    "lsl %[u], %[t], #16\n\t"                                                                            \
    "asr %[t], %[t], #16\n\t"                                                                            \
    "add %[lo], %[lo], %[u]\n\t"                                                                         \
    "adc %[hi], %[t]\n\t"                                                                                \
    "ldr %[t], [%[w], #" hi_off "]\n\t"                                                                    \
    "mul %[t], %[" f "]\n\t"                                                                             \
    "add %[hi], %[hi], %[t]\n\t"
/* w[0] + w[1] i + w[2] j modulo 2^64 for |i|, |j| < 2^15: fx_lin2_small
 * (math/fx.h has the method). */
static inline __attribute__((always_inline)) uint64_t port_lin2_small(const int64_t w[3], int32_t i, int32_t j)
{
    uint32_t lo, hi, t, u;
    __asm__("ldr %[lo], [%[w], #0]\n\t"
            "ldr %[hi], [%[w], #4]\n\t" PORT_LIN_TERM("8", "12", "i") PORT_LIN_TERM("16", "20", "j")
            : [lo] "=&l"(lo), [hi] "=&l"(hi), [t] "=&l"(t), [u] "=&l"(u)
            : [w] "l"(w), [i] "l"(i), [j] "l"(j), "m"(*(const int64_t(*)[3])w)
            : "cc");
    return (uint64_t)hi << 32 | lo;
}
#undef PORT_LIN_TERM
#elif FXRT_PORT_V7M_ASM
/* Armv7-M: per factor f, the low word's product accumulated into the sum
 * by UMLAL, then the high word's (modulo 2^32) and the low word times f's
 * sign word (-1 or 0: f sign-extended to 64 bits) into its high word by
 * MLA: 11 instructions, where gcc's C takes 18. */
static inline __attribute__((always_inline)) uint64_t port_lin2_small(const int64_t w[3], int32_t i, int32_t j)
{
    uint32_t lo, hi, a, b, t;
    __asm__("ldrd %[lo], %[hi], [%[w]]\n\t"
            "ldrd %[a], %[b], [%[w], #8]\n\t"
            "umlal %[lo], %[hi], %[a], %[i]\n\t"
            "mla %[hi], %[b], %[i], %[hi]\n\t"
            "asr %[t], %[i], #31\n\t"
            "mla %[hi], %[a], %[t], %[hi]\n\t"
            "ldrd %[a], %[b], [%[w], #16]\n\t"
            "umlal %[lo], %[hi], %[a], %[j]\n\t"
            "mla %[hi], %[b], %[j], %[hi]\n\t"
            "asr %[t], %[j], #31\n\t"
            "mla %[hi], %[a], %[t], %[hi]"
            : [lo] "=&r"(lo), [hi] "=&r"(hi), [a] "=&r"(a), [b] "=&r"(b), [t] "=&r"(t)
            : [w] "r"(w), [i] "r"(i), [j] "r"(j), "m"(*(const int64_t(*)[3])w));
    return (uint64_t)hi << 32 | lo;
}
#endif

#if FXRT_PORT_V7M_ASM
/* Armv7-M: a op b as a carry (borrow) chain on the four words: `first`
 * on the low words, `next` twice, `last` on the high words, where gcc's C
 * builds the carry from a compare. (Early-clobber: no input may share a
 * register with a word written before the last input is read.) */
#define PORT_CHAIN128(a, b, first, next, last)                                                                   \
    uint32_t w0 = (uint32_t)(a).lo, w1 = (uint32_t)((a).lo >> 32), w2 = (uint32_t)(a).hi,                      \
             w3 = (uint32_t)((uint64_t)(a).hi >> 32);                                                          \
    __asm__(first " %[w0], %[w0], %[b0]\n\t" next " %[w1], %[w1], %[b1]\n\t" next " %[w2], %[w2], %[b2]\n\t" last \
                  " %[w3], %[w3], %[b3]"                                                                       \
            : [w0] "+&r"(w0), [w1] "+&r"(w1), [w2] "+&r"(w2), [w3] "+&r"(w3)                                   \
            : [b0] "r"((uint32_t)(b).lo), [b1] "r"((uint32_t)((b).lo >> 32)), [b2] "r"((uint32_t)(b).hi),       \
              [b3] "r"((uint32_t)((uint64_t)(b).hi >> 32))                                                     \
            : "cc");                                                                                           \
    fx128_t r = {(uint64_t)w1 << 32 | w0, (int64_t)((uint64_t)w3 << 32 | w2)};                                 \
    return r
#endif

#if FXRT_PORT_THUMB_ASM
/* Store words x0, x1, x2 at p, p + 1, p + 2, p + 3, ... until p reaches end
 * (p + 3 k): one STMIA per three words (render_fill_rgb: four RGB888
 * pixels), where gcc's loop keeps the words in high registers on the M0
 * (nine instructions). The register list stores in register order, hence
 * the fixed registers. p is advanced to end. */
#define PORT_STORE3_LOOP(p, end, x0, x1, x2)                                                                \
    do {                                                                                                     \
        register uint32_t w0_ __asm__("r4") = (x0), w1_ __asm__("r5") = (x1), w2_ __asm__("r6") = (x2);       \
        __typeof__(p) end_ = (end);                                                                            \
        __asm__ volatile("1:\n\t"                                                                            \
                         "stmia %[p]!, {%[a], %[b], %[c]}\n\t"                                              \
                         "cmp %[p], %[e]\n\t"                                                               \
                         "bne 1b"                                                                            \
                         : [p] "+l"(p)                                                                       \
                         : [a] "l"(w0_), [b] "l"(w1_), [c] "l"(w2_), [e] "l"(end_)                           \
                         : "cc", "memory");                                                                  \
    } while (0)
#endif

#if FXRT_PORT_V6M_ASM
/* *a += *b for two 128-bit integers in memory (four words each, lowest
 * first), as four ADD/ADC on the words: fx128_add_to (math/fx.h). */
#define PORT_ADD128_TO(a, b)                                                                                  \
    do {                                                                                                      \
        uint32_t x_, y_;                                                                                      \
        __asm__ volatile("ldr %[x], [%[a], #0]\n\t"                                                           \
                         "ldr %[y], [%[b], #0]\n\t"                                                           \
                         "add %[x], %[x], %[y]\n\t"                                                           \
                         "str %[x], [%[a], #0]\n\t"                                                           \
                         "ldr %[x], [%[a], #4]\n\t"                                                           \
                         "ldr %[y], [%[b], #4]\n\t"                                                           \
                         "adc %[x], %[y]\n\t"                                                                 \
                         "str %[x], [%[a], #4]\n\t"                                                           \
                         "ldr %[x], [%[a], #8]\n\t"                                                           \
                         "ldr %[y], [%[b], #8]\n\t"                                                           \
                         "adc %[x], %[y]\n\t"                                                                 \
                         "str %[x], [%[a], #8]\n\t"                                                           \
                         "ldr %[x], [%[a], #12]\n\t"                                                          \
                         "ldr %[y], [%[b], #12]\n\t"                                                          \
                         "adc %[x], %[y]\n\t"                                                                 \
                         "str %[x], [%[a], #12]"                                                              \
                         : [x] "=&l"(x_), [y] "=&l"(y_)                                                       \
                         : [a] "l"(a), [b] "l"(b)                                                             \
                         : "cc", "memory");                                                                   \
    } while (0)
#endif

#endif
