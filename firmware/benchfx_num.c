/* benchfx_num: the float counterparts of benchfx.c's Q16.16 operations,
 * built with FXRT_NUMBER = FXRT_FLOAT: the renderer's own float
 * expressions (core/math/num.h, core/math/vec3.h), soft float on the M0 and M3
 * (libgcc's __aeabi_f* helpers), the FPU on the M4F. Timed like
 * benchfx.c: each through a function pointer, less the same loop around
 * an empty function of its signature, so a figure is one out-of-line
 * call. The inputs are benchfx.c's (BENCHFX_N of them), converted
 * from Q16.16 before timing. make bench-fx prints them
 * beside the Q16.16 figures (docs/BENCHMARKS.md, "Q16.16 against float,
 * operation by operation"). */
#include "math/vec3.h"

#include "benchfx.h"
#define BENCHFX_VEC_PREFIX f_
#include "benchfx_gen.h"
#include "board.h"

#if FXRT_NUMBER != FXRT_FLOAT
#error "benchfx_num.c is the float build: compile it with -DFXRT_NUMBER=2"
#endif

#define NOINLINE __attribute__((noinline))

static float f_a[BENCHFX_N], f_b[BENCHFX_N], f_pos[BENCHFX_N];
static vec3_t f_va[BENCHFX_N], f_vb[BENCHFX_N];
static volatile uint32_t fsink;

static float from_q16(int32_t v) { return (float)v / 65536.0f; }

/* The empty functions keep their arguments where the ABI passes them: FPU
 * registers ("t") with the hard-float ABI (M4F), core registers otherwise. */
#ifdef __ARM_PCS_VFP
#define FREG "+t"
#else
#define FREG "+r"
#endif
static NOINLINE float f_empty_1(float a)
{
    __asm__ volatile("" : FREG(a));
    return a;
}
static NOINLINE float f_empty_2(float a, float b)
{
    __asm__ volatile("" : FREG(a), FREG(b));
    return a;
}
static NOINLINE float f_add(float a, float b) { return num_add(a, b); }
static NOINLINE float f_mul(float a, float b) { return num_mul(a, b); }
static NOINLINE float f_div(float a, float b) { return num_div(a, b); }
static NOINLINE float f_sqrt(float a) { return num_sqrt(a); }
static NOINLINE float f_rsqrt(float a) { return num_rsqrt(a); }
typedef float (*ffn1_t)(float);
typedef float (*ffn2_t)(float, float);
typedef void (*ffnv_t)(vec3_t *, const vec3_t *, const vec3_t *);

/* The result's bits go to a volatile sink, so no call is optimised away. */
static uint32_t bits(float v)
{
    union {
        float f;
        uint32_t u;
    } c = {v};
    return c.u;
}
BENCHFX_TIMERS(f_time, float, ffn1_t, ffn2_t, ffnv_t, BENCHFX_N, bits, fsink)

void benchfx_float(const int32_t *a, const int32_t *b, const int32_t *pos, const int32_t *va, const int32_t *vb)
{
    for (int i = 0; i < BENCHFX_N; i++) {
        f_a[i] = from_q16(a[i]);
        f_b[i] = from_q16(b[i]);
        f_pos[i] = from_q16(pos[i]);
        f_va[i] = vec3_make(from_q16(va[3 * i]), from_q16(va[3 * i + 1]), from_q16(va[3 * i + 2]));
        f_vb[i] = vec3_make(from_q16(vb[3 * i]), from_q16(vb[3 * i + 1]), from_q16(vb[3 * i + 2]));
    }
    uint64_t e1 = f_time_1(f_empty_1, f_pos), e2 = f_time_2(f_empty_2, f_a, f_b);
    uint64_t ev = f_time_v(f_empty, f_va, f_vb);
    benchfx_report_empty("float_empty_1", e1);
    benchfx_report_empty("float_empty_2", e2);
    benchfx_report_empty("float_empty_v", ev);
    benchfx_report("float_add", f_time_2(f_add, f_a, f_b), e2);
    benchfx_report("float_mul", f_time_2(f_mul, f_a, f_b), e2);
    benchfx_report("float_div", f_time_2(f_div, f_a, f_b), e2);
    benchfx_report("float_sqrt", f_time_1(f_sqrt, f_pos), e1);
    benchfx_report("float_rsqrt", f_time_1(f_rsqrt, f_pos), e1);
    benchfx_report("float_vec3_dot", f_time_v(f_dot, f_va, f_vb), ev);
    benchfx_report("float_vec3_cross", f_time_v(f_cross, f_va, f_vb), ev);
    benchfx_report("float_vec3_len", f_time_v(f_len, f_va, f_vb), ev);
    benchfx_report("float_vec3_normalize", f_time_v(f_normalize, f_va, f_vb), ev);
    benchfx_report("float_vec3_unit_len", f_time_v(f_unit_len, f_va, f_vb), ev);
}
