/* benchfx: instructions per call of every Q16.16 scalar and vector function,
 * on the board, in QEMU with -icount (see counter.c).
 *
 * Every function runs over the same BENCHFX_N pseudo-random inputs on every
 * board (xorshift32 with a fixed seed, generated before timing). Each is
 * called through a function pointer of its signature, and the same loop
 * around an empty function of that signature is timed too: the difference,
 * divided by BENCHFX_N, is the cost of one call from the caller's side
 * (call, body, return). Functions that are inline in the headers (fx_mul,
 * vec3_dot, ...) get an out-of-line wrapper here, so they count as one
 * out-of-line call. Output, one line per function:
 *   bench fn=NAME calls=N ticks=T empty_ticks=E
 * firmware/benchfx.sh turns ticks into instructions.
 *
 * firmware/benchfx_num.c times the same operations in float (float_NAME
 * lines), for the table of Q16.16 against float operation by operation.
 *
 * old_fx_div and old_fx_sqrt are the implementations before issue 9
 * (64-bit division by libgcc; a digit-by-digit 64-bit root), kept here only
 * for the before/after comparison. */
#include "math/vec3.h"

#include "benchfx.h"
#define BENCHFX_VEC_PREFIX v_
#include "benchfx_gen.h"
#include "board.h"
#include "semihost.h"


static fx_t in_a[BENCHFX_N], in_b[BENCHFX_N], in_pos[BENCHFX_N], in_deg[BENCHFX_N], in_cot[BENCHFX_N];
static fxw_t in_wa[BENCHFX_N], in_wb[BENCHFX_N], in_wpos[BENCHFX_N];
static vec3_t in_va[BENCHFX_N], in_vb[BENCHFX_N];
static volatile uint32_t sink;

static uint32_t rng_state = 0x2545F491u;
static uint32_t rng(void) { return board_xorshift32(&rng_state); }

/* Half uniform bit patterns, half log-uniform magnitudes with random sign. */
static fx_t rand_fx(void)
{
    uint32_t r = rng();
    if (r & 1)
        return (fx_t)rng();
    int bits = (int)((r >> 1) % 32);
    uint32_t m = bits ? rng() >> (32 - bits) : 0;
    m &= 0x7fffffffu;
    return (r & 2) ? -(fx_t)m : (fx_t)m;
}
static fxw_t rand_w(void)
{
    uint64_t v = ((uint64_t)rng() << 32 | rng()) >> 1;
    return (fxw_t)(v >> (rng() % 63));
}

static void make_inputs(void)
{
    for (int i = 0; i < BENCHFX_N; i++) {
        in_a[i] = rand_fx();
        in_b[i] = rand_fx();
        fx_t p = rand_fx();
        in_pos[i] = p < 0 ? (p == FX_MIN ? FX_MAX : -p) : p;
        in_deg[i] = rand_fx();
        in_cot[i] = (fx_t)(rng() % (uint32_t)F16(90)) + 1; /* cot's domain (0, 90] */
        in_wa[i] = (rng() & 1) ? rand_w() : -rand_w();
        in_wb[i] = rand_w();
        in_wpos[i] = rand_w();
        /* Vector components within the renderer's domain (|c| < 2^30). */
        in_va[i] = vec3_make(rand_fx() / 2, rand_fx() / 2, rand_fx() / 2);
        in_vb[i] = vec3_make(rand_fx() / 2, rand_fx() / 2, rand_fx() / 2);
    }
}

/* ---- the old implementations (before issue 9), for comparison -------- */
static uint64_t old_udiv_round(uint64_t num, uint64_t den)
{
    uint64_t q = num / den;
    uint64_t r = num - q * den;
    return q + (r >= den - r ? 1u : 0u);
}
static fx_t old_signed_sat(uint64_t mag, bool negative)
{
    if (negative)
        return mag >= (uint64_t)1 << 31 ? FX_MIN : -(fx_t)mag;
    return mag > (uint64_t)INT32_MAX ? FX_MAX : (fx_t)mag;
}
static uint64_t old_uabs64(int64_t v)
{
    return v < 0 ? (uint64_t)0 - (uint64_t)v : (uint64_t)v;
}
static fx_t old_fx_div(fx_t a, fx_t b)
{
    if (b == 0)
        return a > 0 ? FX_MAX : (a < 0 ? FX_MIN : 0);
    bool neg = (a < 0) != (b < 0);
    uint64_t num = old_uabs64(a) << FX_FRAC_BITS;
    return old_signed_sat(old_udiv_round(num, old_uabs64(b)), neg);
}
static fx_t old_fx_sqrt(fx_t a)
{
    if (a <= 0)
        return 0;
    uint64_t n = (uint64_t)a << 16, rem = 0, root = 0;
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
    return (fx_t)(n > root * root + root ? root + 1 : root);
}

/* ---- out-of-line wrappers and empty functions of each signature ------- */
#define NOINLINE __attribute__((noinline))
static NOINLINE fx_t w_old_fx_div(fx_t a, fx_t b) { return old_fx_div(a, b); }
static NOINLINE fx_t w_old_fx_sqrt(fx_t a) { return old_fx_sqrt(a); }
static NOINLINE fx_t w_fx_add(fx_t a, fx_t b) { return fx_add(a, b); }
static NOINLINE fx_t w_fx_mul(fx_t a, fx_t b) { return fx_mul(a, b); }
static NOINLINE fx_t empty_1(fx_t a)
{
    __asm__ volatile("" : "+r"(a));
    return a;
}
static NOINLINE fx_t empty_2(fx_t a, fx_t b)
{
    __asm__ volatile("" : "+r"(a), "+r"(b));
    return a;
}
static NOINLINE fx_t empty_w1(fxw_t a)
{
    __asm__ volatile("" : "+r"(a));
    return (fx_t)a;
}
static NOINLINE fx_t empty_w2(fxw_t a, fxw_t b)
{
    __asm__ volatile("" : "+r"(a), "+r"(b));
    return (fx_t)a;
}
typedef fx_t (*fn1_t)(fx_t);
typedef fx_t (*fn2_t)(fx_t, fx_t);
typedef fx_t (*fnw1_t)(fxw_t);
typedef fx_t (*fnw2_t)(fxw_t, fxw_t);
typedef void (*fnv_t)(vec3_t *, const vec3_t *, const vec3_t *);

/* The timed loops (benchfx_gen.h): time_1, time_2, time_v over the fx_t
 * and vector inputs, timew_1, timew_2 over the wide ones. */
static uint32_t fx_word(fx_t v) { return (uint32_t)v; }
BENCHFX_TIMERS(time, fx_t, fn1_t, fn2_t, fnv_t, BENCHFX_N, fx_word, sink)
BENCHFX_TIMERS(timew, fxw_t, fnw1_t, fnw2_t, fnv_t, BENCHFX_N, fx_word, sink)

void benchfx_report(const char *name, uint64_t ticks, uint64_t empty)
{
    semihost_puts("bench fn=");
    semihost_puts(name);
    semihost_puts(" calls=");
    semihost_put_u64(BENCHFX_N);
    semihost_puts(" ticks=");
    semihost_put_u64(ticks);
    semihost_puts(" empty_ticks=");
    semihost_put_u64(empty);
    semihost_puts("\n");
}

/* "bench empty=NAME ticks=T": an empty function's loop, one line per timed
 * loop in the order they ran (firmware/benchfx.sh pairs each loop with its
 * segment of the execution trace for the estimated cycles). */
void benchfx_report_empty(const char *name, uint64_t ticks)
{
    semihost_puts("bench empty=");
    semihost_puts(name);
    semihost_puts(" ticks=");
    semihost_put_u64(ticks);
    semihost_puts("\n");
}

int main(void);
int main(void)
{
    make_inputs();
    counter_start();
    uint64_t e1 = time_1(empty_1, in_pos), e2 = time_2(empty_2, in_a, in_b);
    uint64_t ew1 = timew_1(empty_w1, in_wpos), ew2 = timew_2(empty_w2, in_wa, in_wb);
    uint64_t ev = time_v(v_empty, in_va, in_vb);
    benchfx_report_empty("empty_1", e1);
    benchfx_report_empty("empty_2", e2);
    benchfx_report_empty("empty_w1", ew1);
    benchfx_report_empty("empty_w2", ew2);
    benchfx_report_empty("empty_v", ev);
    benchfx_report("fx_add", time_2(w_fx_add, in_a, in_b), e2);
    benchfx_report("fx_mul", time_2(w_fx_mul, in_a, in_b), e2);
    benchfx_report("fx_div", time_2(fx_div, in_a, in_b), e2);
    benchfx_report("fx_recip", time_1(fx_recip, in_a), e1);
    benchfx_report("fx_sqrt", time_1(fx_sqrt, in_pos), e1);
    benchfx_report("fxw_sqrt", timew_1(fxw_sqrt, in_wpos), ew1);
    benchfx_report("fxw_div", timew_2(fxw_div, in_wa, in_wb), ew2);
    benchfx_report("fx_rsqrt", time_1(fx_rsqrt, in_pos), e1);
    benchfx_report("fx_sin_deg", time_1(fx_sin_deg, in_deg), e1);
    benchfx_report("fx_cos_deg", time_1(fx_cos_deg, in_deg), e1);
    benchfx_report("fx_cot_deg", time_1(fx_cot_deg, in_cot), e1);
    benchfx_report("vec3_dot", time_v(v_dot, in_va, in_vb), ev);
    benchfx_report("vec3_cross", time_v(v_cross, in_va, in_vb), ev);
    benchfx_report("vec3_len", time_v(v_len, in_va, in_vb), ev);
    benchfx_report("vec3_normalize", time_v(v_normalize, in_va, in_vb), ev);
    benchfx_report("vec3_unit_len", time_v(v_unit_len, in_va, in_vb), ev);
    benchfx_report("old_fx_div", time_2(w_old_fx_div, in_a, in_b), e2);
    benchfx_report("old_fx_sqrt", time_1(w_old_fx_sqrt, in_pos), e1);
    _Static_assert(sizeof(vec3_t) == 3 * sizeof(int32_t), "vec3_t is three int32_t");
    benchfx_float(in_a, in_b, in_pos, (const int32_t *)(const void *)in_va, (const int32_t *)(const void *)in_vb);
    semihost_puts("ticks=0 done\n");
    return 0;
}
