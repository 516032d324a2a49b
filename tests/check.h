/* Tiny test harness: CHECK counts, the program ends with check_report(),
 * which prints "N passed, N failed" and returns the exit status. */
#ifndef FXRT_TESTS_CHECK_H
#define FXRT_TESTS_CHECK_H

#include <stdint.h>
#include <stdio.h>

static long check_passed_count;
static long check_failed_count;

/* Print at most this many failure lines per program, so a broken build
 * does not flood the log; every failure is still counted. */
#define CHECK_MAX_REPORTS 20

#define CHECK_MSG(cond, ...)                                                   \
    do {                                                                       \
        if (cond) {                                                            \
            check_passed_count++;                                              \
        } else {                                                               \
            if (check_failed_count++ < CHECK_MAX_REPORTS) {                    \
                fprintf(stderr, "%s:%d: FAIL: %s: ", __FILE__, __LINE__, #cond); \
                fprintf(stderr, __VA_ARGS__);                                  \
                fputc('\n', stderr);                                           \
            }                                                                  \
        }                                                                      \
    } while (0)

#define CHECK(cond) CHECK_MSG(cond, "%s", "")

/* For sweeps over millions of inputs: a failure counts and prints, a pass
 * is not counted (the sweep ends with one CHECK on its summary instead). */
#define CHECK_SWEEP(cond, ...)                                                 \
    do {                                                                       \
        if (!(cond) && check_failed_count++ < CHECK_MAX_REPORTS) {             \
            fprintf(stderr, "%s:%d: FAIL: %s: ", __FILE__, __LINE__, #cond);   \
            fprintf(stderr, __VA_ARGS__);                                      \
            fputc('\n', stderr);                                               \
        }                                                                      \
    } while (0)

/* xorshift64*: a deterministic generator for random sweeps, so that a
 * failure reproduces. Each test keeps its own state (and seed). */
static inline uint64_t check_rng_next(uint64_t *state)
{
    *state ^= *state >> 12;
    *state ^= *state << 25;
    *state ^= *state >> 27;
    return *state * 2685821657736338717ull;
}

static inline int check_report(const char *name)
{
    printf("%s: %ld passed, %ld failed\n", name, check_passed_count, check_failed_count);
    return check_failed_count ? 1 : 0;
}

#endif
