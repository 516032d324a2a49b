/* frame: what the tests that render through the public API share: a whole
 * frame, row by row, into an RGB888 image of width x height. */
#ifndef FXRT_TESTS_FRAME_H
#define FXRT_TESTS_FRAME_H

#include <stddef.h>

#include "fxrt.h"

/* False when the set-up or a row is refused. */
static inline bool frame_render(const fxrt_world_t *w, const fxrt_view_t *v, fxrt_render_t *r, uint8_t *img,
                                int32_t width, int32_t height)
{
    if (fxrt_render_setup(r, w, v) != FXRT_OK)
        return false;
    for (int32_t row = 0; row < height; row++)
        if (fxrt_render_row(r, row, img + (size_t)row * (size_t)width * 3, width * 3) != FXRT_OK)
            return false;
    return true;
}

#endif
