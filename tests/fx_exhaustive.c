/* Exhaustive checks of the Q16.16 roots and sin/cos.
 *
 *   fx_exhaustive [--step N] [--jobs J] [--only sqrt|sincos]
 *
 * With --step 1 (make fx-exhaustive): fx_sqrt against the correctly rounded
 * root for ALL 2^31 non-negative inputs, fx_rsqrt's worst error for all of
 * them, and fx_sin_deg / fx_cos_deg for every input of one full turn (and
 * their symmetry for the turn below zero). With --step N only every N-th
 * input of each sweep is checked (make test uses N = 4099), plus the hard
 * cases below, which are always checked. J worker processes share the
 * sweeps (default 2).
 *
 * The oracle never shares the algorithm under test: the integer root comes
 * from long double sqrtl and is then made exact with integer squares;
 * rsqrt and sin/cos are compared with long double. */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "../core/math/fx.h"
#include "check.h"

/* Stated bounds, asserted (fx.h). */
#define RSQRT_BOUND 0.502L
#define SINCOS_BOUND 0.502L

typedef struct {
    long sqrt_checked, sqrt_bad;
    long rsqrt_checked, rsqrt_bad;
    long sincos_checked, sincos_bad;
    double rsqrt_worst, sin_worst, cos_worst;
    int32_t sqrt_first_bad, rsqrt_worst_at;
} result_t;

/* round(sqrt(n)) exactly: ties cannot occur for integer n. */
static uint32_t oracle_sqrt(uint64_t n)
{
    uint64_t r = (uint64_t)sqrtl((long double)n);
    while (r * r > n)
        r--;
    while ((r + 1) * (r + 1) <= n)
        r++;
    return (uint32_t)(n > r * r + r ? r + 1 : r);
}

static void check_sqrt_one(result_t *res, int32_t a)
{
    uint32_t want = a <= 0 ? 0 : oracle_sqrt((uint64_t)a << 16);
    fx_t got = fx_sqrt(a);
    res->sqrt_checked++;
    if ((uint32_t)got != want) {
        if (res->sqrt_bad++ == 0)
            res->sqrt_first_bad = a;
    }
}

static void check_rsqrt_one(result_t *res, int32_t a)
{
    long double exact = 16777216.0L / sqrtl((long double)a);
    long double e = fabsl((long double)fx_rsqrt(a) - exact);
    res->rsqrt_checked++;
    if (e > res->rsqrt_worst) {
        res->rsqrt_worst = (double)e;
        res->rsqrt_worst_at = a;
    }
    if (e > RSQRT_BOUND)
        res->rsqrt_bad++;
}

static void check_sincos_one(result_t *res, fx_t deg)
{
    int64_t full = (int64_t)360 << 16, r = (int64_t)deg % full;
    if (r < 0)
        r += full;
    long double x = (long double)r / 65536.0L * 3.14159265358979323846264338327950288L / 180.0L;
    fx_t s = fx_sin_deg(deg), c = fx_cos_deg(deg);
    long double es = fabsl((long double)s - sinl(x) * 65536.0L);
    long double ec = fabsl((long double)c - cosl(x) * 65536.0L);
    res->sincos_checked++;
    if (es > res->sin_worst)
        res->sin_worst = (double)es;
    if (ec > res->cos_worst)
        res->cos_worst = (double)ec;
    bool bad = es > SINCOS_BOUND || ec > SINCOS_BOUND || s > FX_ONE || s < -FX_ONE || c > FX_ONE || c < -FX_ONE;
    if (deg != FX_MIN && (fx_sin_deg(-deg) != -s || fx_cos_deg(-deg) != c))
        bad = true;
    if (bad)
        res->sincos_bad++;
}

static bool do_roots = true, do_sincos = true;

/* Worker `job` of `jobs`: every step-th input, interleaved between jobs. */
static void run_slice(result_t *res, long step, int job, int jobs)
{
    long stride = step * jobs;
    for (int64_t a = (int64_t)job * step; do_roots && a <= INT32_MAX; a += stride) {
        check_sqrt_one(res, (int32_t)a);
        if (a > 0)
            check_rsqrt_one(res, (int32_t)a);
    }
    for (int64_t d = (int64_t)job * step; do_sincos && d < (int64_t)360 << 16; d += stride)
        check_sincos_one(res, (fx_t)d);
}

/* Inputs next to every kind of boundary, checked at any step. */
static void run_hard(result_t *res)
{
    uint64_t st = 0x243F6A8885A308D3ull;
    static const int32_t fixed[] = {INT32_MIN, -1, 0, 1, 2, 3, 4, 0x3fffffff, 0x40000000, 0x40000001,
                                    0x7ffffffe, INT32_MAX, 0x10000, 0xffff, 0x10001, 46340, 46341};
    for (size_t i = 0; i < sizeof fixed / sizeof fixed[0]; i++) {
        check_sqrt_one(res, fixed[i]);
        if (fixed[i] > 0)
            check_rsqrt_one(res, fixed[i]);
        check_sincos_one(res, fixed[i]);
    }
    for (int i = 0; i < 200000; i++) {
        /* A random root r and the inputs whose a 2^16 straddle r^2 (exact
         * squares) and r^2 + r (the rounding boundary). */
        uint64_t r = 1 + check_rng_next(&st) % 11863283u;
        uint64_t targets[2] = {r * r, r * r + r};
        for (int t = 0; t < 2; t++) {
            int64_t a0 = (int64_t)(targets[t] >> 16);
            for (int64_t a = a0 - 1; a <= a0 + 2; a++)
                if (a >= 0 && a <= INT32_MAX)
                    check_sqrt_one(res, (int32_t)a);
        }
        /* Every multiple of 45 degrees and its neighbours, any turn. */
        int32_t k = (int32_t)(check_rng_next(&st) % 1456) - 728;
        for (int32_t e = -2; e <= 2; e++)
            check_sincos_one(res, (fx_t)(k * (45 << 16) + e));
    }
}

static void merge(result_t *into, const result_t *r)
{
    into->sqrt_checked += r->sqrt_checked;
    if (r->sqrt_bad && !into->sqrt_bad)
        into->sqrt_first_bad = r->sqrt_first_bad;
    into->sqrt_bad += r->sqrt_bad;
    into->rsqrt_checked += r->rsqrt_checked;
    into->rsqrt_bad += r->rsqrt_bad;
    if (r->rsqrt_worst > into->rsqrt_worst) {
        into->rsqrt_worst = r->rsqrt_worst;
        into->rsqrt_worst_at = r->rsqrt_worst_at;
    }
    into->sincos_checked += r->sincos_checked;
    into->sincos_bad += r->sincos_bad;
    if (r->sin_worst > into->sin_worst)
        into->sin_worst = r->sin_worst;
    if (r->cos_worst > into->cos_worst)
        into->cos_worst = r->cos_worst;
}

int main(int argc, char **argv)
{
    long step = 1;
    int jobs = 2;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--step") && i + 1 < argc)
            step = atol(argv[++i]);
        else if (!strcmp(argv[i], "--jobs") && i + 1 < argc)
            jobs = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--only") && i + 1 < argc && !strcmp(argv[i + 1], "sqrt")) {
            do_sincos = false;
            i++;
        } else if (!strcmp(argv[i], "--only") && i + 1 < argc && !strcmp(argv[i + 1], "sincos")) {
            do_roots = false;
            i++;
        }
        else {
            fprintf(stderr, "usage: fx_exhaustive [--step N] [--jobs J] [--only sqrt|sincos]\n");
            return 2;
        }
    }
    if (step < 1 || jobs < 1 || jobs > 64) {
        fprintf(stderr, "fx_exhaustive: --step must be >= 1 and --jobs in 1..64\n");
        return 2;
    }
    result_t total;
    memset(&total, 0, sizeof total);
    int fds[64];
    pid_t pids[64];
    for (int j = 0; j < jobs; j++) {
        int p[2];
        if (pipe(p) != 0) {
            perror("fx_exhaustive: pipe");
            return 1;
        }
        pids[j] = fork();
        if (pids[j] < 0) {
            perror("fx_exhaustive: fork");
            return 1;
        }
        if (pids[j] == 0) {
            close(p[0]);
            result_t r;
            memset(&r, 0, sizeof r);
            run_slice(&r, step, j, jobs);
            if (j == 0)
                run_hard(&r);
            ssize_t n = write(p[1], &r, sizeof r);
            _exit(n == (ssize_t)sizeof r ? 0 : 1);
        }
        close(p[1]);
        fds[j] = p[0];
    }
    int workers_ok = 1;
    for (int j = 0; j < jobs; j++) {
        result_t r;
        ssize_t n = read(fds[j], &r, sizeof r);
        int status = 0;
        waitpid(pids[j], &status, 0);
        if (n != (ssize_t)sizeof r || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
            workers_ok = 0;
        else
            merge(&total, &r);
    }
    CHECK_MSG(workers_ok, "a worker process failed");
    printf("fx_sqrt:    %ld inputs, %ld not correctly rounded%s\n", total.sqrt_checked, total.sqrt_bad,
           step == 1 ? " (all 2^31 non-negative inputs)" : "");
    if (total.sqrt_bad)
        printf("  first failure: fx_sqrt(%d)\n", total.sqrt_first_bad);
    printf("fx_rsqrt:   %ld inputs, worst error %.5f LSB at %d (bound %.4Lf), %ld over\n", total.rsqrt_checked,
           total.rsqrt_worst, total.rsqrt_worst_at, RSQRT_BOUND, total.rsqrt_bad);
    printf("fx_sin_deg: %ld angles, worst %.5f LSB; fx_cos_deg worst %.5f LSB (bound %.4Lf), %ld failing\n",
           total.sincos_checked, total.sin_worst, total.cos_worst, SINCOS_BOUND, total.sincos_bad);
    CHECK_MSG(total.sqrt_checked > 0 && total.sqrt_bad == 0, "fx_sqrt: %ld wrong", total.sqrt_bad);
    CHECK_MSG(total.rsqrt_checked > 0 && total.rsqrt_bad == 0, "fx_rsqrt: %ld over the bound", total.rsqrt_bad);
    CHECK_MSG(total.sincos_checked > 0 && total.sincos_bad == 0, "sin/cos: %ld failing", total.sincos_bad);
    if (!do_roots || !do_sincos)
        printf("(partial run: --only)\n");
    return check_report(step == 1 ? "fx_exhaustive" : "fx_sampled");
}
