/* dither: RGB888 rows to 4-bit grey levels (see dither.h). */
#include "dither.h"

#define HALF_STEP (OLED_LUMA_STEP / 2) /* 2176: rounds to the nearest level */

bool oled_dither_begin(oled_dither_t *d, oled_dither_method_t method, int32_t width, int32_t *err)
{
    if ((uint32_t)method >= OLED_DITHER_METHODS || width < 1 ||
        (method == OLED_DITHER_FS && !err))
        return false;
    d->method = method;
    d->width = width;
    d->err = err;
    if (method == OLED_DITHER_FS)
        for (int32_t x = 0; x < width; x++)
            err[x] = 0;
    return true;
}

static inline void put(uint8_t *packed, int32_t x, uint32_t level)
{
    if (x & 1)
        packed[x >> 1] = (uint8_t)(packed[x >> 1] | level);
    else
        packed[x >> 1] = (uint8_t)(level << 4);
}

/* Rounding and the ordered methods have no state between pixels: two
 * pixels a step, one output byte each. off[] holds the luma offset added
 * to column x before truncating (off[x & mask]): half a step for rounding;
 * for a Bayer matrix, matrix row y mod n's thresholds M as unit (2M + 1)
 * with unit = step / (2 n^2), hoisted out of the pixel loop. Every offset
 * stays below one step, so no level exceeds 15; the sums are unsigned, so
 * the constant division is a multiply and a shift. */
static void row_offsets(const oled_dither_t *d, const uint8_t *rgb, uint8_t *packed, const uint32_t *off, uint32_t mask)
{
    const int32_t width = d->width; /* in a register: the byte stores could alias d */
    int32_t x = 0;
    for (; x + 1 < width; x += 2, rgb += 6) {
        uint32_t hi = ((uint32_t)oled_luma(rgb) + off[(uint32_t)x & mask]) / OLED_LUMA_STEP;
        uint32_t lo = ((uint32_t)oled_luma(rgb + 3) + off[(uint32_t)(x + 1) & mask]) / OLED_LUMA_STEP;
        *packed++ = (uint8_t)(hi << 4 | lo);
    }
    if (x < width) /* odd width: the last pixel alone in the high nibble */
        *packed = (uint8_t)((((uint32_t)oled_luma(rgb) + off[(uint32_t)x & mask]) / OLED_LUMA_STEP) << 4);
}

static void row_ordered(const oled_dither_t *d, int32_t y, const uint8_t *rgb, uint8_t *packed, uint32_t bits)
{
    const uint32_t n = 1u << bits, unit = OLED_LUMA_STEP >> (2 * bits + 1); /* 136 (4x4), 34 (8x8): exact */
    uint32_t off[8];
    for (uint32_t i = 0; i < n; i++)
        off[i] = unit * (2 * oled_bayer(i, (uint32_t)y & (n - 1), bits) + 1);
    row_offsets(d, rgb, packed, off, n - 1);
}

/* Floyd-Steinberg on one row with one error buffer: err[x] holds the error
 * pixel x of this row inherited from the row above until x is reached;
 * from then on err[x - 1] is rewritten with what row below inherits.
 * Shares still being summed are kept in three variables: `right` for
 * (x + 1, y), `below` for (x, y + 1) and `below_right` for (x + 1, y + 1). */
static void row_fs(const oled_dither_t *d, const uint8_t *rgb, uint8_t *packed)
{
    int32_t *err = d->err;
    const int32_t width = d->width;
    int32_t right = 0, below = 0, below_right = 0;
    for (int32_t x = 0; x < width; x++, rgb += 3) {
        int32_t want = oled_luma(rgb) + err[x] + right;
        /* want > 0 there: an unsigned division, a multiply and a shift */
        int32_t level = want <= 0 ? 0 : (int32_t)((uint32_t)(want + HALF_STEP) / OLED_LUMA_STEP);
        if (level > OLED_LEVEL_MAX)
            level = OLED_LEVEL_MAX;
        put(packed, x, (uint32_t)level);
        /* |e| <= half a step (2176): the four shares a pixel inherits are
         * parts of its neighbours' errors of their signs, summing to at
         * most one whole error, so want stays within half a step of
         * 0..65280, and so does the clamped level's error (by induction
         * from the first pixel). C's division truncates toward zero, the
         * same for both signs. */
        int32_t e = want - level * OLED_LUMA_STEP;
        int32_t e3 = e * 3 / 16, e5 = e * 5 / 16, e1 = e / 16;
        if (x > 0)
            err[x - 1] = below + e3; /* (x - 1, y + 1) is complete */
        below = below_right + e5;
        below_right = e1;
        right = e - e3 - e5 - e1; /* 7/16 and the remainders */
    }
    err[width - 1] = below; /* the last pixel's down-right share leaves the image */
}

void oled_dither_row(oled_dither_t *d, int32_t y, const uint8_t *rgb, uint8_t *packed)
{
    switch (d->method) {
    case OLED_DITHER_NONE: {
        static const uint32_t half[1] = {HALF_STEP};
        row_offsets(d, rgb, packed, half, 0);
        break;
    }
    case OLED_DITHER_BAYER4:
        row_ordered(d, y, rgb, packed, 2);
        break;
    case OLED_DITHER_BAYER8:
        row_ordered(d, y, rgb, packed, 3);
        break;
    case OLED_DITHER_FS:
        row_fs(d, rgb, packed);
        break;
    default:
        break;
    }
}

const char *oled_dither_name(oled_dither_method_t method)
{
    static const char *const names[OLED_DITHER_METHODS] = {"none", "bayer4", "bayer8", "fs"};
    /* One unsigned comparison covers negative values too (the enum's
     * type is unsigned on some ABIs, signed on others). */
    return (uint32_t)method < OLED_DITHER_METHODS ? names[method] : 0;
}
