/* errf: see errf.h. A module of its own so that everything linking
 * image.c or scene.c (the host tool, unit tests, the scene fuzzer) gets
 * one copy. */
#include "errf.h"

#include <stdarg.h>
#include <stdio.h>

void errf_set(char *err, size_t errlen, const char *fmt, ...)
{
    va_list ap;

    if (err == NULL || errlen == 0)
        return;
    va_start(ap, fmt);
    vsnprintf(err, errlen, fmt, ap);
    va_end(ap);
}
