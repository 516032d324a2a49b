/* num: the few number-type operations that are not inline. */
#include "math/num.h"

fxrt_stats_t fxrt_stats; /* math/stats.h */

#if FXRT_NUMBER != FXRT_Q16
/* cot(deg degrees) from sine and cosine Taylor series in num_t, the same
 * method as the Q16.16 fx_cot_deg; for deg in (0, 90]. At 90 the series
 * leave a few ulp (float: -4e-8), which made a 90-degree camera one pixel
 * high "too wide" in float alone; cot 90 = 0 exactly, as in Q16.16. */
num_t num_cot_deg(num_t deg)
{
    if (deg == NUM(90))
        return NUM_ZERO;
    num_t x = deg * NUM(3.14159265358979323846 / 180.0);
    num_t x2 = x * x;
    num_t s = NUM_ZERO, c = NUM_ZERO, ts = x, tc = NUM_ONE;
    for (int k = 0; k < 14; k++) {
        s = (k & 1) ? s - ts : s + ts;
        c = (k & 1) ? c - tc : c + tc;
        ts = ts * x2 / (num_t)((2 * k + 2) * (2 * k + 3));
        tc = tc * x2 / (num_t)((2 * k + 1) * (2 * k + 2));
    }
    return num_div(c, s);
}

/* cos(deg degrees) for deg in [0, 90] by the same series (the spot
 * light's cone, once per light at set-up). */
num_t num_cos_deg(num_t deg)
{
    FXRT_COUNT(cosines);
    num_t x = deg * NUM(3.14159265358979323846 / 180.0);
    num_t x2 = x * x;
    num_t c = NUM_ZERO, tc = NUM_ONE;
    for (int k = 0; k < 14; k++) {
        c = (k & 1) ? c - tc : c + tc;
        tc = tc * x2 / (num_t)((2 * k + 1) * (2 * k + 2));
    }
    return c;
}
#endif
