/* color: conversion to output pixels. */
#include "math/color.h"

static num_t color_fraction(num_t c)
{
    int32_t q = num_to_q16(c); /* 0 .. 255 * 65536 */
    return num_from_q16((2 * q + 255) / 510);
}

color_t color_fractions(color_t c)
{
    return color_make(color_fraction(c.r), color_fraction(c.g), color_fraction(c.b));
}
