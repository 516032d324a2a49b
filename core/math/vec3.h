/* vec3: 3-vectors of num_t. Dot and cross products accumulate the exact
 * products in numw_t and round once, so in Q16.16 a dot product is within
 * 0.5 LSB and a cross product component within 0.5 LSB of exact. */
#ifndef FXRT_VEC3_H
#define FXRT_VEC3_H

#include "math/num.h"

typedef struct {
    num_t x, y, z;
} vec3_t;

static inline vec3_t vec3_make(num_t x, num_t y, num_t z)
{
    vec3_t v = {x, y, z};
    return v;
}
static inline vec3_t vec3_add(vec3_t a, vec3_t b)
{
    return vec3_make(num_add(a.x, b.x), num_add(a.y, b.y), num_add(a.z, b.z));
}
static inline vec3_t vec3_sub(vec3_t a, vec3_t b)
{
    return vec3_make(num_sub(a.x, b.x), num_sub(a.y, b.y), num_sub(a.z, b.z));
}
static inline vec3_t vec3_neg(vec3_t a)
{
    return vec3_make(num_neg(a.x), num_neg(a.y), num_neg(a.z));
}
/* a * s, each component within 0.5 LSB. */
static inline vec3_t vec3_scale(vec3_t a, num_t s)
{
    return vec3_make(num_mul(a.x, s), num_mul(a.y, s), num_mul(a.z, s));
}
/* u * s for u a unit vector: the value of vec3_scale (the same rounding
 * and saturation), with numw_mul_unit's products. */
static inline vec3_t vec3_scale_unit(vec3_t u, num_t s)
{
    return vec3_make(num_mul_unit(s, u.x), num_mul_unit(s, u.y), num_mul_unit(s, u.z));
}
/* u * s for u a unit vector (|u_i| <= 1.25) and |s| < 16384 (2^30 LSB in
 * Q16.16): vec3_scale_unit's value, which then always fits, without its
 * saturation tests (Phong's r = 2 (n . l) n - l). Not for bounce ray
 * directions: a refracted one is not renormalised (light/trace.c). */
static inline vec3_t vec3_scale_unit_small(vec3_t u, num_t s)
{
    return vec3_make(num_mul_unit_fits(s, u.x), num_mul_unit_fits(s, u.y), num_mul_unit_fits(s, u.z));
}
/* -u for u a unit vector (no component is the most negative num_t):
 * vec3_neg's value without its saturation tests. */
static inline vec3_t vec3_neg_unit(vec3_t u)
{
    return vec3_make(num_neg_fits(u.x), num_neg_fits(u.y), num_neg_fits(u.z));
}
/* a * i for an integer i, exact in Q16.16. */
static inline vec3_t vec3_scale_int(vec3_t a, int32_t i)
{
    return vec3_make(num_mul_int(a.x, i), num_mul_int(a.y, i), num_mul_int(a.z, i));
}
/* a . b, unrounded (Q32.32 in the fixed-point build). */
static inline numw_t vec3_dotw(vec3_t a, vec3_t b)
{
    return numw_add(numw_add(numw_mul(a.x, b.x), numw_mul(a.y, b.y)), numw_mul(a.z, b.z));
}
/* a . u for u a unit vector (|components| <= 1: normals, directions): the
 * value of vec3_dotw, with numw_mul_unit's products. Any |u_i| < 2^30 LSB
 * (16384.0) keeps each product below 2^61 and the sum below 2^63: the
 * additions cannot overflow and need no saturation test. */
static inline numw_t vec3_dotw_unit(vec3_t a, vec3_t u)
{
    return numw_dot3_unit(a.x, a.y, a.z, u.x, u.y, u.z);
}
/* u . v for two unit vectors (n . l, d . n): vec3_dotw_unit's value, with
 * exact products (on the M0 six 32-bit products: numw_dot3_units). */
static inline numw_t vec3_dotw_units(vec3_t u, vec3_t v)
{
    return numw_dot3_units(u.x, u.y, u.z, v.x, v.y, v.z);
}
/* |a.x| + (|a.y| + |a.z|), the 1-norm (saturating in Q16.16). */
static inline num_t vec3_l1(vec3_t a)
{
    return num_add(num_abs(a.x), num_add(num_abs(a.y), num_abs(a.z)));
}
/* max(|a.x|, |a.y|, |a.z|), the largest magnitude (saturating in Q16.16). */
static inline num_t vec3_linf(vec3_t a)
{
    num_t x = num_abs(a.x), y = num_abs(a.y), z = num_abs(a.z);
    x = x > y ? x : y;
    return x > z ? x : z;
}
/* a . b rounded once. */
static inline num_t vec3_dot(vec3_t a, vec3_t b)
{
    return numw_round(vec3_dotw(a, b));
}
/* p q - r s for 32-bit factors, exact: each product lies in
 * [-2^62 + 2^31, 2^62], so the difference is below 2^63 in magnitude and
 * needs no saturation test. */
static inline numw_t vec3_det2w(num_t p, num_t q, num_t r, num_t s)
{
    return numw_sub_exact(numw_mul(p, q), numw_mul(r, s));
}
/* a x b, each component rounded once. */
static inline vec3_t vec3_cross(vec3_t a, vec3_t b)
{
    return vec3_make(numw_round(vec3_det2w(a.y, b.z, a.z, b.y)), numw_round(vec3_det2w(a.z, b.x, a.x, b.z)),
                     numw_round(vec3_det2w(a.x, b.y, a.y, b.x)));
}
/* a x u for u a unit vector: the value of vec3_cross, with numw_mul_unit
 * (its products are vec3_det2w's, so the same bound holds). */
static inline vec3_t vec3_cross_unit(vec3_t a, vec3_t u)
{
    return vec3_make(numw_round(numw_sub_exact(numw_mul_unit(a.y, u.z), numw_mul_unit(a.z, u.y))),
                     numw_round(numw_sub_exact(numw_mul_unit(a.z, u.x), numw_mul_unit(a.x, u.z))),
                     numw_round(numw_sub_exact(numw_mul_unit(a.x, u.y), numw_mul_unit(a.y, u.x))));
}
/* |a|, within 0.5 LSB (the squared length is exact before the root). */
static inline num_t vec3_len(vec3_t a)
{
    return numw_sqrt(vec3_dotw(a, a));
}
/* a / |a| (num_normalize3: within 0.504 LSB per component in Q16.16).
 * Returns false (and leaves *a unchanged) for the zero vector. */
static inline bool vec3_normalize(vec3_t *a)
{
    num_t v[3] = {a->x, a->y, a->z};
    if (!num_normalize3(v))
        return false;
    *a = vec3_make(v[0], v[1], v[2]);
    return true;
}

/* *u = a / |a| and *len = |a| in one go, or false (nothing written) for
 * the zero vector: a point light's direction and distance
 * (num_normalize3_len). */
static inline bool vec3_unit_len(vec3_t a, vec3_t *u, num_t *len)
{
    num_t v[3] = {a.x, a.y, a.z};
    if (!num_normalize3_len(v, len))
        return false;
    *u = vec3_make(v[0], v[1], v[2]);
    return true;
}

/* a x b / |a x b|, or false when a and b are parallel: the cross product
 * formed exactly (Q32.32 in Q16.16) and made a direction
 * (numw_direction_shift) before normalising. */
static inline bool vec3_unit_cross(vec3_t a, vec3_t b, vec3_t *n)
{
    numw_t c[3] = {vec3_det2w(a.y, b.z, a.z, b.y), vec3_det2w(a.z, b.x, a.x, b.z), vec3_det2w(a.x, b.y, a.y, b.x)};
    int shift = numw_direction_shift(c);
    *n = vec3_make(numw_direction_part(c[0], shift), numw_direction_part(c[1], shift),
                   numw_direction_part(c[2], shift));
    return vec3_normalize(n);
}

#endif
