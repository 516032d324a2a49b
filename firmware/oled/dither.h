/* dither: RGB888 rows to 4-bit grey levels for the SSD0323 OLED, one row at
 * a time, top row first. One source for the firmware and the host tool
 * (firmware/oled/oled_tool.c, build/fxrt-oled), so the host's reference
 * frames go through the very code the board runs. Freestanding: stdint,
 * stddef, stdbool.
 *
 * Grey: Rec. 601 luma on the 8-bit (gamma-encoded) values in integers,
 *   Y = 77 R + 150 G + 29 B           (0 .. OLED_LUMA_MAX = 65280 = 255 * 256)
 * the weights 0.299, 0.587, 0.114 rounded to 1/256 (they sum to 256; each
 * is within 0.5/256 of the standard's). Y is exact, so the ideal grey of a
 * pixel is Y / 256 on the 0..255 scale, Y / OLED_LUMA_STEP = Y / 4352 in
 * display levels (0..15); level n shows grey n * 17 (QEMU's model draws it
 * so; a real panel's grey-scale table decides). The methods differ only in
 * how that level is chosen:
 *   OLED_DITHER_NONE    nearest level: (Y + 2176) / 4352 (ties up)
 *   OLED_DITHER_BAYER4  ordered, 4x4 Bayer matrix M(x mod 4, y mod 4) in
 *                       0..15: floor(Y / 4352 + (M + 0.5) / 16), that is
 *                       (Y + 136 (2M + 1)) / 4352, exact in integers; over
 *                       a 4x4 tile the levels average Y / 4352 within 1/32
 *   OLED_DITHER_BAYER8  the same with the 8x8 matrix (M 0..63, 34 (2M + 1))
 *   OLED_DITHER_FS      Floyd-Steinberg error diffusion, left to right on
 *                       every row: the pixel's Y plus the error it
 *                       inherited, rounded to the nearest level (clamped to
 *                       0..15); the error in luma units goes 7/16 right,
 *                       3/16 down-left, 5/16 down, 1/16 down-right (the
 *                       right share takes the division's remainder, so none
 *                       is lost inside the image; what would leave the
 *                       image is dropped). The row below's error lives in
 *                       one buffer of width int32_t that the caller owns.
 * The Bayer matrices come from the bit-interleaving rule, not a table:
 * M = reverse(interleave(x ^ y, y)) (tests/test_oled_dither.c checks it
 * against the recursive definition). */
#ifndef FXRT_OLED_DITHER_H
#define FXRT_OLED_DITHER_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#define OLED_LUMA_MAX 65280 /* luma of white, 255 * 256 */
#define OLED_LEVEL_MAX 15   /* brightest level */
#define OLED_LUMA_STEP 4352 /* luma units per level: OLED_LUMA_MAX / OLED_LEVEL_MAX */

typedef enum {
    OLED_DITHER_NONE = 0,
    OLED_DITHER_BAYER4 = 1,
    OLED_DITHER_BAYER8 = 2,
    OLED_DITHER_FS = 3,
    OLED_DITHER_METHODS = 4 /* how many */
} oled_dither_method_t;

/* A frame's dithering state; the caller owns it and the error row. */
typedef struct {
    oled_dither_method_t method;
    int32_t width;      /* pixels per row */
    int32_t *err;       /* OLED_DITHER_FS: the next row's inherited error, width entries */
} oled_dither_t;

/* Y of one RGB888 pixel, exact (0..OLED_LUMA_MAX). */
static inline int32_t oled_luma(const uint8_t *rgb)
{
    return 77 * (int32_t)rgb[0] + 150 * (int32_t)rgb[1] + 29 * (int32_t)rgb[2];
}

/* Bayer threshold M(x, y) of the 2^bits x 2^bits matrix (bits 2: 4x4,
 * values 0..15; bits 3: 8x8, 0..63). */
static inline uint32_t oled_bayer(uint32_t x, uint32_t y, uint32_t bits)
{
    uint32_t v = x ^ y, m = 0;
    /* Interleave (x ^ y) and y from the least significant bits up, each
     * pair landing in reverse order: bit i of x ^ y has weight
     * 2^(2 (bits - i) - 1), bit i of y weight 2^(2 (bits - i) - 2). */
    for (uint32_t i = 0; i < bits; i++) {
        m |= ((v >> i) & 1u) << (2 * (bits - i) - 1);
        m |= ((y >> i) & 1u) << (2 * (bits - i) - 2);
    }
    return m;
}

/* Start a frame of rows `width` pixels wide with a method. err: width
 * entries for OLED_DITHER_FS (zeroed here), unused (may be NULL) for the
 * others. Returns false for an unknown method, width < 1 or a missing
 * error row. */
bool oled_dither_begin(oled_dither_t *d, oled_dither_method_t method, int32_t width, int32_t *err);

/* Levels of row y (0 = top; rows in order, each once) from rgb (3 bytes a
 * pixel) into packed: (width + 1) / 2 bytes, two pixels a byte, the left
 * one in the high nibble (the SSD0323's order); an odd width leaves the
 * last low nibble 0. */
void oled_dither_row(oled_dither_t *d, int32_t y, const uint8_t *rgb, uint8_t *packed);

/* "none", "bayer4", "bayer8", "fs"; NULL for an unknown method. */
const char *oled_dither_name(oled_dither_method_t method);

#endif
