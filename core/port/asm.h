/* asm: the core's inline assembly, in one block per target (gcc on
 * Armv6-M, gcc on Armv7-M), used by math/fx.h (saturating additions,
 * products, linear forms, 128-bit carries) and vis/fill.c (the row fill).
 * Each block names every kernel: its assembly, or the C twin (defined
 * first) that other targets and compilers take. tests/onboard_main.c
 * checks the assembly against 64-bit C on every board.
 *
 *   port_add_sat32, port_sub_sat32  a + b, a - b saturating (int32)
 *   port_smul32, port_smlal32       a b, acc + a b (32 x 32 -> 64 bits)
 *   port_channel_q16                a colour channel's 8-bit value (Q16.16)
 *   port_channel_f32                the same for a float (hard float only)
 *   PORT_STORE3_LOOP(p, end, ...)   the row fill's three-word stores
 *   PORT_HAVE_LIN2                  1: port_lin2_small (Armv6-M, Armv7-M)
 *   PORT_HAVE_CHAIN128              1: PORT_CHAIN128 (Armv7-M)
 *   PORT_HAVE_ADD128_TO             1: PORT_ADD128_TO (Armv6-M) */
#ifndef FXRT_PORT_ASM_H
#define FXRT_PORT_ASM_H

#include <stdint.h>

#include "port/port.h"

/* The C twins. */
static inline int32_t port_add_sat32_c(int32_t a, int32_t b)
{
    int32_t s;
    if (__builtin_add_overflow(a, b, &s))
        return a < 0 ? INT32_MIN : INT32_MAX;
    return s;
}
static inline int32_t port_sub_sat32_c(int32_t a, int32_t b)
{
    int32_t s;
    if (__builtin_sub_overflow(a, b, &s))
        return a < 0 ? INT32_MIN : INT32_MAX;
    return s;
}
static inline int64_t port_smul32_c(int32_t a, int32_t b)
{
    return (int64_t)a * b;
}
/* Modulo 2^64 (the caller shows that the sum fits). */
static inline int64_t port_smlal32_c(int64_t acc, int32_t a, int32_t b)
{
    return (int64_t)((uint64_t)acc + (uint64_t)port_smul32_c(a, b));
}
/* A colour channel's 8-bit value (math/color.h, color_channel): c (in
 * 1/255 units) clamped to 0..255 and rounded half up, floor(c + 1/2), for
 * c in Q16.16 (any int32) or in float (any value: NaN gives 0). */
static inline uint8_t port_channel_q16_c(int32_t c)
{
    return c <= 0 ? 0 : c >= (255 << 16) ? 255 : (uint8_t)(((uint32_t)c + 0x8000u) >> 16);
}
static inline uint8_t port_channel_f32_c(float c)
{
    return !(c > 0.0f) ? 0 : c >= 255.0f ? 255 : (uint8_t)(uint32_t)(c + 0.5f);
}
/* Store words x0, x1, x2 at p, p + 1, p + 2, p + 3, ... until p reaches
 * end (p + 3 k); p is advanced to end. */
#define PORT_STORE3_LOOP_C(p, end, x0, x1, x2)                                                              \
    do {                                                                                                     \
        uint32_t w0_ = (x0), w1_ = (x1), w2_ = (x2);                                                          \
        for (__typeof__(p) end_ = (end); (p) != end_; (p) += 3) {                                            \
            (p)[0] = w0_;                                                                                    \
            (p)[1] = w1_;                                                                                    \
            (p)[2] = w2_;                                                                                    \
        }                                                                                                    \
    } while (0)

/* PORT_STORE3_LOOP_C in one STMIA per three words (render_fill_rgb: four
 * RGB888 pixels), where gcc's loop keeps the words in high registers on
 * the M0 (nine instructions). The register list stores in register order,
 * hence the fixed registers. Armv6-M and Armv7-M. */
#define PORT_STORE3_LOOP_THUMB(p, end, x0, x1, x2)                                                          \
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

#if FXRT_PORT_V6M_ASM
/* a op b (op: "adds" or "subs"), saturating on the V flag: two
 * instructions when nothing saturates (math/fx.h, fx_add). */
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
#define port_add_sat32(a, b) PORT_SAT_ASM("adds", a, b)
#define port_sub_sat32(a, b) PORT_SAT_ASM("subs", a, b)
#define port_smul32 port_smul32_c
#define port_smlal32 port_smlal32_c
#define port_channel_q16 port_channel_q16_c
#define port_channel_f32 port_channel_f32_c
#define PORT_STORE3_LOOP PORT_STORE3_LOOP_THUMB

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
#define PORT_HAVE_LIN2 1
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

/* *a += *b for two 128-bit integers in memory (four words each, lowest
 * first), as four ADD/ADC on the words: fx128_add_to (math/fx.h). */
#define PORT_HAVE_ADD128_TO 1
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
#define PORT_HAVE_CHAIN128 0

#elif FXRT_PORT_V7M_ASM
#define port_add_sat32 port_add_sat32_c
#define port_sub_sat32 port_sub_sat32_c
/* a b in one SMULL; acc + a b in one SMLAL. */
static inline __attribute__((always_inline)) int64_t port_smul32(int32_t a, int32_t b)
{
    int32_t lo, hi;
    __asm__("smull %0, %1, %2, %3" : "=&r"(lo), "=&r"(hi) : "r"(a), "r"(b));
    return (int64_t)(((uint64_t)(uint32_t)hi << 32) | (uint32_t)lo);
}
static inline __attribute__((always_inline)) int64_t port_smlal32(int64_t acc, int32_t a, int32_t b)
{
    uint32_t lo = (uint32_t)acc, hi = (uint32_t)((uint64_t)acc >> 32);
    __asm__("smlal %0, %1, %2, %3" : "+r"(lo), "+r"(hi) : "r"(a), "r"(b));
    return (int64_t)(((uint64_t)hi << 32) | lo);
}
#define PORT_STORE3_LOOP PORT_STORE3_LOOP_THUMB

/* port_channel_q16 without a branch: with q = floor(c / 2^15) (no
 * overflow, unlike c + 2^15), floor((q + 1) / 2) = floor((c + 2^15) /
 * 2^16), and USAT clamps it to 0..255; 3 instructions, where gcc's C
 * takes 6 with two branches. */
static inline __attribute__((always_inline)) uint8_t port_channel_q16(int32_t c)
{
    int32_t t;
    __asm__("asr %0, %1, #15\n\t"
            "add %0, %0, #1\n\t"
            "usat %0, #8, %0, asr #1"
            : "=&r"(t)
            : "r"(c));
    return (uint8_t)t;
}
#if FXRT_PORT_V7M_VFP
/* port_channel_f32 with single-precision VFP (the M4F): c + 1/2 as the
 * twin adds it, then VCVT.S32 truncates towards zero and saturates (NaN
 * gives 0) and USAT clamps to 0..255; 4 instructions, where gcc's C takes
 * 12 with two compares and branches. The same value for every c: c <= 0
 * or NaN gives 0 both ways, c >= 255 gives 255, and in between both
 * truncate c + 1/2. */
static inline __attribute__((always_inline)) uint8_t port_channel_f32(float c)
{
    float t = c + 0.5f;
    uint32_t u;
    __asm__("vcvt.s32.f32 %1, %1\n\t"
            "vmov %0, %1\n\t"
            "usat %0, #8, %0"
            : "=r"(u), "+t"(t));
    return (uint8_t)u;
}
#else
#define port_channel_f32 port_channel_f32_c
#endif

/* port_lin2_small: per factor f, the low word's product accumulated into
 * the sum by UMLAL, then the high word's (modulo 2^32) and the low word
 * times f's sign word (-1 or 0: f sign-extended to 64 bits) into its high
 * word by MLA: 11 instructions, where gcc's C takes 18. */
#define PORT_HAVE_LIN2 1
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

/* r = a op b for 128-bit {lo, hi} structs as a carry (borrow) chain on
 * the four words: `first` on the low words, `next` twice, `last` on the
 * high words, where gcc's C builds the carry from a compare.
 * (Early-clobber: no input may share a register with a word written
 * before the last input is read.) */
#define PORT_HAVE_CHAIN128 1
#define PORT_CHAIN128(r, a, b, first, next, last)                                                                \
    do {                                                                                                       \
        uint32_t w0 = (uint32_t)(a).lo, w1 = (uint32_t)((a).lo >> 32), w2 = (uint32_t)(a).hi,                  \
                 w3 = (uint32_t)((uint64_t)(a).hi >> 32);                                                      \
        __asm__(first " %[w0], %[w0], %[b0]\n\t" next " %[w1], %[w1], %[b1]\n\t" next                          \
                      " %[w2], %[w2], %[b2]\n\t" last " %[w3], %[w3], %[b3]"                                   \
                : [w0] "+&r"(w0), [w1] "+&r"(w1), [w2] "+&r"(w2), [w3] "+&r"(w3)                               \
                : [b0] "r"((uint32_t)(b).lo), [b1] "r"((uint32_t)((b).lo >> 32)), [b2] "r"((uint32_t)(b).hi),   \
                  [b3] "r"((uint32_t)((uint64_t)(b).hi >> 32))                                                 \
                : "cc");                                                                                       \
        (r).lo = (uint64_t)w1 << 32 | w0;                                                                      \
        (r).hi = (int64_t)((uint64_t)w3 << 32 | w2);                                                           \
    } while (0)
#define PORT_HAVE_ADD128_TO 0

#else
#define port_add_sat32 port_add_sat32_c
#define port_sub_sat32 port_sub_sat32_c
#define port_smul32 port_smul32_c
#define port_smlal32 port_smlal32_c
#define port_channel_q16 port_channel_q16_c
#define port_channel_f32 port_channel_f32_c
#define PORT_STORE3_LOOP PORT_STORE3_LOOP_C
#define PORT_HAVE_LIN2 0
#define PORT_HAVE_CHAIN128 0
#define PORT_HAVE_ADD128_TO 0
#endif

#endif
