/* light: the lights of a world (light/shade.c applies them).
 *
 * A light's colour, like the ambient colour and a material's specular
 * colour, is a fraction per channel: NUM_ONE is full intensity (a scaling
 * factor, not a colour in 1/255 units; color.h). Lights have no distance
 * attenuation. */
#ifndef FXRT_LIGHT_H
#define FXRT_LIGHT_H

#include "scene/geom.h"

/* (The FXRT_ names are the public API's spelling, core/fxrt.h.) */
typedef enum {
    LIGHT_POINT,
    LIGHT_DIRECTIONAL,
    LIGHT_SPOT,
    FXRT_LIGHT_POINT = LIGHT_POINT,
    FXRT_LIGHT_DIRECTIONAL = LIGHT_DIRECTIONAL,
    FXRT_LIGHT_SPOT = LIGHT_SPOT
} light_kind_t;

typedef struct {
    uint8_t kind;    /* light_kind_t */
    bool shadows;    /* cast shadow rays (FXRT_SHADOWS 1 only) */
    uint8_t axes[2]; /* directional: the two axes of its shadow rays'
                      * projections (light_dir_axes; light/shadow.c) */
    vec3_t position; /* point and spot: where it is */
    vec3_t dir;      /* directional: unit vector towards the light,
                      * -direction / |direction|, computed once (no
                      * per-pixel normalisation); spot: the unit cone
                      * axis s = direction / |direction| */
    num_t cos_angle; /* spot: cos(half-angle), computed once; a point p is
                      * in the cone when (-l) . s >= cos_angle */
    color_t color;   /* fractions 0..1 */
#if FXRT_NUMBER == FXRT_Q16
    /* Spot, Q16.16 build: the cone test (-v) . s >= cos(angle) |v| with s
     * and cos(angle) in Q2.30, so that their rounding (0.5 LSB of Q16.16
     * is 0.3 pixel-widths of bias on a typical cone edge) stays out of it. */
    int32_t axis30[3], cos30;
#endif
} light_t;

/* The axes k1 < k2 for a directional light's shadow-ray projections
 * (light/shadow.c): v . (l x e_k), largest where |l x e_k|^2 = 1 - l_k^2
 * is, so all but the axis of l's largest component. */
static inline void light_dir_axes(vec3_t l, uint8_t axes[2])
{
    num_t ax = num_abs(l.x), ay = num_abs(l.y), az = num_abs(l.z);
    int big = ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
    axes[0] = big == 0 ? 1 : 0;
    axes[1] = big == 2 ? 1 : 2;
}

/* A fraction colour (light, ambient, specular): each channel in 0..1 (NaN
 * fails): FXRT_OK or FXRT_ERR_COLOR (FXRT_ERR_TINY for a nonzero channel
 * below 2^-16 in float and double, as geom_check_color). */
fxrt_err_t light_check_fraction(color_t c);

#endif
