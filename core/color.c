/* color: conversion to output pixels. */
#include "color.h"

static uint8_t color_channel(num_t c)
{
    if (!(c > NUM_ZERO))
        return 0;
    if (c >= NUM_ONE)
        return 255;
#if FXRT_NUMBER == FXRT_Q16
    return (uint8_t)(((uint32_t)c * 255u + FX_HALF) >> FX_FRAC_BITS);
#else
    return (uint8_t)(c * NUM(255) + NUM(0.5));
#endif
}

rgb8_t color_to_rgb8(color_t c)
{
    rgb8_t p = {color_channel(c.r), color_channel(c.g), color_channel(c.b)};
    return p;
}
