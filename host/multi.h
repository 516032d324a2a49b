/* multi: the suffix of a host program's per-number-type symbols.
 *
 * The host tool and several tests link the renderer three times, once per
 * number type. Each number's objects are joined into one relocatable
 * object whose global symbols get the type's suffix (host/multi-ld.sh:
 * render_row -> render_row_q16), so the core itself needs no renaming.
 * Glue compiled once per number type (host/engine.c, tests/diffk.c, ...)
 * names its entry points with MULTI_SYM, so that the other files can call
 * them by their suffixed names. */
#ifndef FXRT_HOST_MULTI_H
#define FXRT_HOST_MULTI_H

#include "../core/fxrt_config.h"

#if FXRT_NUMBER == FXRT_Q16
#define MULTI_SYM(name) name##_q16
#elif FXRT_NUMBER == FXRT_FLOAT
#define MULTI_SYM(name) name##_float
#else
#define MULTI_SYM(name) name##_double
#endif

#endif
