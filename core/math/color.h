/* color: RGB in num_t, in units of 1/255 of full intensity, and its 8-bit
 * form.
 *
 * Representation (the same in every build; docs/ACCURACY.md, "Colour"):
 * a channel holds 255 * x for an intensity x in 0..1, so 255 is full
 * intensity and the 8-bit output is the channel rounded half up. The scene
 * loader stores a written fraction x as round(x * 255 * 65536) / 65536: a
 * Q16.16 value, exact in float (at most 24 significant bits) and in
 * double, so all three builds hold the identical number and give the
 * identical pixel. For x written with up to 4 decimals the pixel is
 * floor(255 x + 1/2) of the decimal itself (ties, such as 0.7 -> 178.5,
 * go up: 179).
 *
 * Scaling factors (light intensities, filters) stay fractions in 0..1:
 * color_scale and color_filter keep a colour in 1/255 units. */
#ifndef FXRT_COLOR_H
#define FXRT_COLOR_H

#include "math/num.h"

typedef struct {
    num_t r, g, b; /* 1/255 units: 0 = off, 255 = full */
} color_t;

/* 8-bit sRGB-free output pixel. */
typedef struct {
    uint8_t r, g, b;
} rgb8_t;

/* RGB565 of an 8-bit colour: each channel's top bits. */
static inline uint16_t color_565(rgb8_t c)
{
    return (uint16_t)(((c.r >> 3) << 11) | ((c.g >> 2) << 5) | (c.b >> 3));
}
/* Pixel x of a row in the pixel format (FXRT_PIXEL); RGB888 by byte
 * stores (a 3-byte memcpy is a library call on the Cortex-M0). */
typedef uint16_t __attribute__((may_alias)) color_px16_t;
static inline void color_put_pixel(uint8_t *rgb, int32_t x, rgb8_t c)
{
    if (FXRT_PIXEL == FXRT_RGB565) {
        ((color_px16_t *)(void *)rgb)[x] = color_565(c);
        return;
    }
    rgb[3 * x + 0] = c.r;
    rgb[3 * x + 1] = c.g;
    rgb[3 * x + 2] = c.b;
}

/* Full intensity, 255 in 1/255 units. */
#define COLOR_MAX NUM(255)

/* A channel literal from an intensity fraction in 0..1, for constant
 * initialisers only, quantised exactly as the scene loader does:
 * COLOR_FRAC(0.7) is 178.5 in every build. */
#define COLOR_FRAC(x) NUM((double)(long long)((x) * (255.0 * 65536.0) + 0.5) / 65536.0)

/* Channels in 1/255 units (0..255). */
static inline color_t color_make(num_t r, num_t g, num_t b)
{
    color_t c = {r, g, b};
    return c;
}
/* An 8-bit colour, exactly. */
static inline color_t color_from_rgb8(uint8_t r, uint8_t g, uint8_t b)
{
    return color_make(num_from_int(r), num_from_int(g), num_from_int(b));
}
static inline color_t color_add(color_t a, color_t b)
{
    return color_make(num_add(a.r, b.r), num_add(a.g, b.g), num_add(a.b, b.b));
}
static inline color_t color_sub(color_t a, color_t b)
{
    return color_make(num_sub(a.r, b.r), num_sub(a.g, b.g), num_sub(a.b, b.b));
}
/* Component-wise filter: colour a (1/255 units) times fractions f (0..1
 * per channel), e.g. a surface lit by a coloured light. Q16.16: each
 * channel within 0.5 LSB (2^-17 of a 1/255 unit). */
static inline color_t color_filter(color_t a, num_t fr, num_t fg, num_t fb)
{
    return color_make(num_mul(a.r, fr), num_mul(a.g, fg), num_mul(a.b, fb));
}
/* color_filter with the fractions given as a color_t (channels 0..1, not
 * 1/255 units): a light's or a filter's colour. */
static inline color_t color_mul(color_t a, color_t f)
{
    return color_filter(a, f.r, f.g, f.b);
}
/* Colour a times a fraction s (0..1), within 0.5 LSB per channel. */
static inline color_t color_scale(color_t a, num_t s)
{
    return color_make(num_mul(a.r, s), num_mul(a.g, s), num_mul(a.b, s));
}

/* The 8-bit pixel: each channel clamped to 0..255 and rounded half up,
 * floor(c + 1/2), exactly in every build: in Q16.16 an integer shift; in
 * float and double, c + 0.5 is exact for any value the loader stores (a
 * multiple of 2^-16 below 256 has at most 24 significant bits), and the
 * conversion truncates a non-negative value. Inline: once per pixel. */
static inline uint8_t color_channel(num_t c)
{
    return num_channel8(c); /* (port/asm.h: without branches on the M3 and M4F) */
}
static inline rgb8_t color_to_rgb8(color_t c)
{
    rgb8_t p = {color_channel(c.r), color_channel(c.g), color_channel(c.b)};
    return p;
}

/* The fractions a colour in 1/255 units stands for (lights, ambient,
 * specular and reflection colours are kept as fractions, NUM_ONE full):
 * c / 255 per channel, quantised as the scene loader quantises a written
 * fraction, round(65536 c / 255) / 65536 of c taken to 2^-16 first, in
 * every build. For c = COLOR_FRAC(x) it is round(65536 x) / 65536, the
 * fraction x itself as the loader holds it (255 is odd: no tie moves).
 * Channels 0..255 only (geom_check_color). */
color_t color_fractions(color_t c);

/* Supersampling: the sum of a pixel's samples, one channel, each sample
 * clamped to 0..255 (1/255 units) first; the output is the mean rounded
 * half up, floor(sum / n2 + 1/2), as color_to_rgb8 rounds one sample.
 * Q16.16 sums raw units in uint32: at most 255 * 2^16 * 256 plus half a
 * unit per sample, below 2^32, so 16 x 16 samples never overflow. */
#if FXRT_NUMBER == FXRT_Q16
typedef uint32_t color_sum_t;
FXRT_STATIC_ASSERT((uint64_t)255 * 65536 * 256 + 256 * 32768 < ((uint64_t)1 << 32),
               "a pixel's sum of 16 x 16 clamped samples, plus half a unit each, fits uint32");
/* Add channel c, clamped, n times. */
static inline void color_sum_add(color_sum_t *a, num_t c, uint32_t n)
{
    uint32_t v = c <= 0 ? 0u : c >= (255 << 16) ? (255u << 16) : (uint32_t)c;
    *a += v * n;
}
static inline uint8_t color_sum_out(color_sum_t a, uint32_t n2)
{
    if ((n2 & (n2 - 1)) == 0) { /* N a power of two: a shift, the same value */
        int sh = __builtin_ctz(n2) + 16;
        return (uint8_t)((a + (1u << (sh - 1))) >> sh);
    }
    return (uint8_t)((a + n2 * 32768u) / (n2 << 16));
}
#else
typedef num_t color_sum_t;
static inline void color_sum_add(color_sum_t *a, num_t c, uint32_t n)
{
    num_t v = !(c > NUM_ZERO) ? NUM_ZERO : c >= NUM(255) ? NUM(255) : c;
    *a += v * (num_t)n;
}
static inline uint8_t color_sum_out(color_sum_t a, uint32_t n2)
{
    num_t m = a / (num_t)n2 + NUM(0.5);
    return m >= NUM(255) ? 255 : !(m > NUM_ZERO) ? 0 : (uint8_t)m;
}
#endif

#endif
