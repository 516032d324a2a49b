/* port: what the core needs to know of its target, and its inlining policy.
 * Every test of the compiler's architecture macros is here; the rest of the
 * core asks these names. port/asm.h has the inline assembly.
 *
 *   FXRT_PORT_SMALL_ISA  1 on Armv6-M (Cortex-M0): no 32-bit divide, no
 *                        CLZ, no 32 x 32 -> 64-bit multiply
 *                        (fxrt_config.h's FX_HAVE_* defaults follow it)
 *   FXRT_PORT_V6M_ASM    gcc on Armv6-M: Thumb-1 inline assembly
 *   FXRT_PORT_V7M_ASM    gcc on Armv7-M or Armv7E-M (Cortex-M3, M4):
 *                        Thumb-2 inline assembly
 * Assembly is gcc's only: clang rejects '.syntax divided', and takes the C. */
#ifndef FXRT_PORT_H
#define FXRT_PORT_H

/* Inlining policy: FXRT_INLINE_WIDE marks functions that are inlined into
 * their callers where the core has registers to spare (Armv7-M, the host)
 * and kept out of line on Armv6-M, where inlining them spilled registers
 * and grew their callers' frames beyond what the micro:bit's 2 KB stack
 * holds. Each use says what it measured. */
#if defined(__ARM_ARCH_6M__)
#define FXRT_PORT_SMALL_ISA 1
#define FXRT_INLINE_WIDE __attribute__((noinline))
/* ... and not cloned by GCC either, where a constant argument's copy
 * made a deeper frame (light/shade.c, shade_specular). */
#define FXRT_NOCLONE_WIDE __attribute__((noclone))
#else
#define FXRT_PORT_SMALL_ISA 0
#define FXRT_INLINE_WIDE inline __attribute__((always_inline))
#define FXRT_NOCLONE_WIDE
#endif

/* FXRT_PORT_BARE: a bare-metal Arm target (arm-none-eabi), where the
 * program's linker script owns the stack (fxrt_config.h's
 * FXRT_STACK_RESERVE). FXRT_PORT_HOSTED(n): n on a host, 0 on such a
 * target (a default that only hosts take; n a plain number, and so is the
 * result). PORT_KEEP(p): p is used (no code but its address in a
 * register), so that what it points to is linked in. */
#if defined(__arm__) && !defined(__linux__)
#define FXRT_PORT_BARE 1
#define FXRT_PORT_HOSTED(n) 0
#else
#define FXRT_PORT_BARE 0
#define FXRT_PORT_HOSTED(n) n
#endif
#define PORT_KEEP(p) __asm__ volatile("" : : "r"(p))
/* PORT_ASSUME(cond): the caller knows cond holds; the compiler may drop
 * the code that would run were it false (gcc and clang's
 * __builtin_unreachable; the sanitized build reports it, were it reached). */
#define PORT_ASSUME(cond) ((cond) ? (void)0 : __builtin_unreachable())

#if defined(__GNUC__) && !defined(__clang__) && defined(__ARM_ARCH_6M__)
#define FXRT_PORT_V6M_ASM 1
#else
#define FXRT_PORT_V6M_ASM 0
#endif
#if defined(__GNUC__) && !defined(__clang__) && (defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__))
#define FXRT_PORT_V7M_ASM 1
#else
#define FXRT_PORT_V7M_ASM 0
#endif
/* Armv7-M with single-precision VFP registers (the M4F): port/asm.h's
 * float kernels. */
#if FXRT_PORT_V7M_ASM && defined(__ARM_FP) && (__ARM_FP & 4)
#define FXRT_PORT_V7M_VFP 1
#else
#define FXRT_PORT_V7M_VFP 0
#endif
/* A compile-time check, in C11 and in a C++ program that includes fxrt.h;
 * and the C linkage that fxrt.h gives its declarations in a C++ program
 * (the core is C: tests/examples.sh links a C++ program against it). */
#ifdef __cplusplus
#define FXRT_STATIC_ASSERT(cond, msg) static_assert(cond, msg)
#define FXRT_C_BEGIN extern "C" {
#define FXRT_C_END }
#else
#define FXRT_STATIC_ASSERT(cond, msg) _Static_assert(cond, msg)
#define FXRT_C_BEGIN
#define FXRT_C_END
#endif
/* FXRT_IF_NONZERO(N, ...): its other arguments when N is a plain decimal
 * number other than 0, nothing when N is 0; FXRT_IF_ABOVE1(N, ...) the
 * same for N other than 0 and 1. N is a capacity or a limit from
 * fxrt_config.h, which fxrt.h also pastes into link names: a conditional
 * for a declaration, a field or a statement without #if. N pastes onto a
 * probe's prefix; where that names a probe (FXRT_ZERO_0, FXRT_ATMOST1_0,
 * FXRT_ATMOST1_1), FXRT_NONZERO_DROP moves into the second place,
 * otherwise FXRT_NONZERO_KEEP is there. fxrt_config.h and scene/kinds.h
 * assert that they agree with N's value. */
#define FXRT_IF_NONZERO(n, ...) FXRT_NONZERO_IF_(FXRT_ZERO_, n, __VA_ARGS__)
#define FXRT_IF_ABOVE1(n, ...) FXRT_NONZERO_IF_(FXRT_ATMOST1_, n, __VA_ARGS__)
#define FXRT_NONZERO_IF_(probe, n, ...) FXRT_NONZERO_IF__(probe, n, __VA_ARGS__)
#define FXRT_NONZERO_IF__(probe, n, ...) FXRT_NONZERO_SECOND(probe##n, FXRT_NONZERO_KEEP, ~)(__VA_ARGS__)
#define FXRT_ZERO_0 ~, FXRT_NONZERO_DROP
#define FXRT_ATMOST1_0 ~, FXRT_NONZERO_DROP
#define FXRT_ATMOST1_1 ~, FXRT_NONZERO_DROP
#define FXRT_NONZERO_SECOND(...) FXRT_NONZERO_SECOND_(__VA_ARGS__)
#define FXRT_NONZERO_SECOND_(a, b, ...) b
#define FXRT_NONZERO_KEEP(...) __VA_ARGS__
#define FXRT_NONZERO_DROP(...)


#endif
