/* errf: formatted error messages into a caller's buffer, shared by the
 * host modules that report errors as text (image, scene). */
#ifndef FXRT_HOST_ERRF_H
#define FXRT_HOST_ERRF_H

#include <stddef.h>

#if defined(__GNUC__)
#define ERRF_PRINTF(fmt, args) __attribute__((format(printf, fmt, args)))
#else
#define ERRF_PRINTF(fmt, args)
#endif

/* printf into err (errlen bytes, truncated and NUL-terminated); does
 * nothing when err is NULL or errlen is 0, so callers may pass no buffer. */
void errf_set(char *err, size_t errlen, const char *fmt, ...) ERRF_PRINTF(3, 4);

#endif
