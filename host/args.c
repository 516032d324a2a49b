/* args: strict parsing of command-line values. */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "../core/fxrt_config.h"
#include "args.h"

int args_int(const char *s, long lo, long hi, long *out)
{
    if (*s < '0' || *s > '9')
        return -1;
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (errno || *end || v < lo || v > hi)
        return -1;
    *out = v;
    return 0;
}

int args_size(const char *s, int *w, int *h)
{
    const char *x = strchr(s, 'x');
    if (!x || x == s)
        return -1;
    char wbuf[16];
    size_t n = (size_t)(x - s);
    if (n >= sizeof wbuf)
        return -1;
    memcpy(wbuf, s, n);
    wbuf[n] = 0;
    long lw, lh;
    if (args_int(wbuf, 1, FXRT_MAX_DIM, &lw) || args_int(x + 1, 1, FXRT_MAX_DIM, &lh))
        return -1;
    *w = (int)lw;
    *h = (int)lh;
    return 0;
}
