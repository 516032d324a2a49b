/* args: strict parsing of command-line values shared by the host tools. */
#ifndef FXRT_HOST_ARGS_H
#define FXRT_HOST_ARGS_H

/* Decimal integer in [lo, hi], nothing else on the string. 0 or -1. */
int args_int(const char *s, long lo, long hi, long *out);
/* "WxH", each 1..FXRT_MAX_DIM. 0 or -1. */
int args_size(const char *s, int *w, int *h);

#endif
