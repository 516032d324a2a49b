/* color: linear RGB in num_t, 0..1 per channel, and its 8-bit form. */
#ifndef FXRT_COLOR_H
#define FXRT_COLOR_H

#include "num.h"

typedef struct {
    num_t r, g, b;
} color_t;

/* 8-bit sRGB-free output pixel (the value is round(255 * clamp(c, 0, 1))). */
typedef struct {
    uint8_t r, g, b;
} rgb8_t;

static inline color_t color_make(num_t r, num_t g, num_t b)
{
    color_t c = {r, g, b};
    return c;
}
static inline color_t color_add(color_t a, color_t b)
{
    return color_make(num_add(a.r, b.r), num_add(a.g, b.g), num_add(a.b, b.b));
}
static inline color_t color_sub(color_t a, color_t b)
{
    return color_make(num_sub(a.r, b.r), num_sub(a.g, b.g), num_sub(a.b, b.b));
}
/* Component-wise product (filtering light by a surface colour). */
static inline color_t color_mul(color_t a, color_t b)
{
    return color_make(num_mul(a.r, b.r), num_mul(a.g, b.g), num_mul(a.b, b.b));
}
static inline color_t color_scale(color_t a, num_t s)
{
    return color_make(num_mul(a.r, s), num_mul(a.g, s), num_mul(a.b, s));
}

/* round(255 * clamp(c, 0, 1)) per channel. */
rgb8_t color_to_rgb8(color_t c);

#endif
