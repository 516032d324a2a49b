/* fill: runs of pixels of one colour into a row buffer, in the pixel
 * format (FXRT_PIXEL), with word stores where the row is aligned: the
 * background at a row's start, and the runs the scans fill. */
#include "vis/paint.h"

/* Fill pixels xa..xb of a row with colour c, in the pixel format, with
 * word stores where the row is aligned (RGB888: three words per four
 * pixels; RGB565: one word per two). */

void render_fill_rgb(uint8_t *rgb, int32_t xa, int32_t xb, rgb8_t c)
{
    typedef uint32_t __attribute__((may_alias)) word_t;
    int32_t x = xa;
#if FXRT_PIXEL == FXRT_RGB565
    uint16_t v = color_565(c);
    color_px16_t *p16 = (color_px16_t *)(void *)rgb;
    if (((uintptr_t)rgb & 3u) == 0) {
        for (; x <= xb && (x & 1); x++)
            p16[x] = v;
        word_t two = (uint32_t)v * 0x10001u, *p = (word_t *)(void *)rgb + x / 2;
        for (; x + 1 <= xb; x += 2)
            *p++ = two;
    }
    for (; x <= xb; x++)
        p16[x] = v;
#else
    if (((uintptr_t)rgb & 3u) == 0) {
        /* Aligned rows (the firmware's framebuffer and bands). may_alias:
         * the buffer is bytes. */
        for (; x <= xb && (x & 3); x++)
            color_put_pixel(rgb, x, c);
        if (x + 3 <= xb) {
            union {
                uint8_t b[12];
                uint32_t w[3];
            } pat;
            for (int i = 0; i < 4; i++) {
                pat.b[3 * i + 0] = c.r;
                pat.b[3 * i + 1] = c.g;
                pat.b[3 * i + 2] = c.b;
            }
            word_t *p = (word_t *)(void *)(rgb + 3 * x);
            int32_t groups = (xb - x + 1) / 4;
            x += 4 * groups;
            PORT_STORE3_LOOP(p, p + 3 * groups, pat.w[0], pat.w[1], pat.w[2]);
        }
    }
    for (; x <= xb; x++)
        color_put_pixel(rgb, x, c);
#endif
}
