/* color: conversion to output pixels. */
#include "math/color.h"

/* floor(c + 1/2) clamped to 0..255. Exact in every build: in Q16.16 it is
 * an integer shift; in float and double, c + 0.5 is exact for any value
 * the loader stores (a multiple of 2^-16 below 256 has at most 24
 * significant bits), and the conversion truncates a non-negative value. */
static uint8_t color_channel(num_t c)
{
    if (!(c > NUM_ZERO))
        return 0;
    if (c >= COLOR_MAX)
        return 255;
    return (uint8_t)num_round_uint(c);
}

rgb8_t color_to_rgb8(color_t c)
{
    rgb8_t p = {color_channel(c.r), color_channel(c.g), color_channel(c.b)};
    return p;
}

static num_t color_fraction(num_t c)
{
    int32_t q = num_to_q16(c); /* 0 .. 255 * 65536 */
    return num_from_q16((2 * q + 255) / 510);
}

color_t color_fractions(color_t c)
{
    return color_make(color_fraction(c.r), color_fraction(c.g), color_fraction(c.b));
}
