/* example_io: where the examples' frames go, and how they stop. io_host.c
 * writes PPM files with stdio; io_board.c streams them to the host over
 * semihosting and counts instructions per frame. */
#ifndef FXRT_EXAMPLE_IO_H
#define FXRT_EXAMPLE_IO_H

#include <stddef.h>
#include <stdint.h>

#include "fxrt.h"

/* Start frame n (width x height, RGB888 rows to follow, top row first). */
void example_frame_begin(int32_t n, int32_t width, int32_t height);
/* One output row of len bytes. */
void example_row(const uint8_t *row, size_t len);
/* Frame n is complete. */
void example_frame_end(int32_t n);
/* Report "what: msg" and end the program with a non-zero status. */
void example_fail(const char *what, const char *msg) __attribute__((noreturn));
/* Stop at an API call's refusal (r < 0), with the API's text for it. */
static inline void example_must(int32_t r, const char *what)
{
    if (r < 0)
        example_fail(what, fxrt_strerror(r));
}

/* The example itself (examples/orbit.c, examples/lit.c): its name (the
 * frames' file names, NAME-00.ppm ...) and its program. */
extern const char example_name[];
int example_main(void);

#endif
