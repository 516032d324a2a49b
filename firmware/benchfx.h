/* benchfx: shared by firmware/benchfx.c (Q16.16) and firmware/benchfx_num.c
 * (the same operations in float). */
#ifndef FXRT_BENCHFX_H
#define FXRT_BENCHFX_H

#include <stdint.h>

/* One "bench fn=NAME calls=N ticks=T empty_ticks=E" line (N = BENCHFX_N). */
void benchfx_report(const char *name, uint64_t ticks, uint64_t empty);
/* One "bench empty=NAME ticks=T" line: an empty function's timed loop. */
void benchfx_report_empty(const char *name, uint64_t ticks);

/* Inputs per function, the same for both number types (they fit the
 * micro:bit's 16 KB RAM). */
#define BENCHFX_N 128

/* Time the float counterparts of the Q16.16 operations over benchfx.c's
 * BENCHFX_N inputs (raw Q16.16 values, converted to float before timing): scalars a, b, pos (pos >= 0) and vectors va, vb
 * (three components each), and report each as float_NAME. */
void benchfx_float(const int32_t *a, const int32_t *b, const int32_t *pos, const int32_t *va, const int32_t *vb);

#endif
