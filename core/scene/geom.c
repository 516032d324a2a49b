/* geom: what every kind of object shares: the domain checks, an object's
 * shared part, and the flat pieces' plane tests (scene/plane.c and
 * scene/triangle.c). */
#include "scene/kinds.h"

/* One value against |v| <= limit; NaN fails the comparison. */
fxrt_err_t geom_check_num(num_t v, int32_t limit)
{
    if (!(num_abs(v) <= num_from_int(limit)))
        return FXRT_ERR_COORD;
    if (!NUM_EXACT && v != NUM_ZERO && num_abs(v) < NUM(1.0 / 65536.0))
        return FXRT_ERR_TINY; /* (float and double: below Q16.16's step) */
    return FXRT_OK;
}

fxrt_err_t geom_check_point(vec3_t p)
{
    fxrt_err_t e = geom_check_num(p.x, FXRT_COORD_LIMIT);
    if (e == FXRT_OK)
        e = geom_check_num(p.y, FXRT_COORD_LIMIT);
    if (e == FXRT_OK)
        e = geom_check_num(p.z, FXRT_COORD_LIMIT);
    return e;
}

/* Only the direction of these matters, so a tiny component is harmless
 * (a value given in the build's number type is taken as it is; the scene
 * parser refuses decimal directions that rounding would turn): no TINY
 * check. */
fxrt_err_t geom_check_dir(vec3_t d)
{
    num_t lim = num_from_int(FXRT_COORD_LIMIT);
    if (!(num_abs(d.x) <= lim && num_abs(d.y) <= lim && num_abs(d.z) <= lim))
        return FXRT_ERR_COORD;
    if (d.x == NUM_ZERO && d.y == NUM_ZERO && d.z == NUM_ZERO)
        return FXRT_ERR_DIRECTION;
    return FXRT_OK;
}

fxrt_err_t geom_check_color(color_t c)
{
    /* Written so that NaN fails. */
    if (!(c.r >= NUM_ZERO && c.r <= COLOR_MAX && c.g >= NUM_ZERO && c.g <= COLOR_MAX && c.b >= NUM_ZERO &&
          c.b <= COLOR_MAX))
        return FXRT_ERR_COLOR;
    if (!NUM_EXACT && (geom_check_num(c.r, FXRT_COORD_LIMIT) != FXRT_OK || geom_check_num(c.g, FXRT_COORD_LIMIT) != FXRT_OK ||
                       geom_check_num(c.b, FXRT_COORD_LIMIT) != FXRT_OK))
        return FXRT_ERR_TINY;
    return FXRT_OK;
}

void geom_common_init(geom_common_t *c, color_t color, uint16_t id)
{
#if FXRT_MAX_LIGHTS > 0 || FXRT_MAX_SAMPLES > 1
    c->color = color;
#endif
    c->rgb = color_to_rgb8(color);
    c->id = id;
    FXRT_IF_LIGHTS(c->mat.kind = MATERIAL_FLAT; c->mat.exponent = 0;
                   c->mat.specular = color_make(NUM_ZERO, NUM_ZERO, NUM_ZERO);
                   c->mat.reflection = c->mat.specular; c->mat.index = NUM_ZERO;)
}

/* Where the ray meets the plane through a with normal n: t = (a - o) . n /
 * (d . n). Both dot products stay wide, so the sign tests are exact and the
 * quotient is rounded once. Planes and triangles share it. */
bool geom_flat_t(const vec3_t *a, const vec3_t *n, const ray_t *ray, num_t *t)
{
    numw_t den = vec3_dotw_units(ray->d, *n);
    numw_t num = vec3_dotw_unit(vec3_sub(*a, ray->o), *n);
    if (den == 0 || num == 0 || (num < 0) != (den < 0))
        return false;
    num_t tt = numw_div(num, den);
    if (!(tt > NUM_ZERO))
        return false;
    *t = tt;
    return true;
}

/* Shadow rays (any hit with 0 < t < tmax; tmax NUM_MAX: any t > 0)
 * without a division: t = num / den is in range when num and den have one
 * strict sign and |num| < tmax |den| (numw_lt_mul: exact in Q16.16). */
bool geom_flat_occludes(const vec3_t *a, const vec3_t *n, const ray_t *ray, num_t tmax)
{
    numw_t den = vec3_dotw_units(ray->d, *n);
    numw_t num = vec3_dotw_unit(vec3_sub(*a, ray->o), *n);
    if (den == 0 || num == 0 || (num < 0) != (den < 0))
        return false;
    if (tmax == NUM_MAX)
        return true;
    return num > 0 ? numw_lt_mul(num, tmax, den) : numw_lt_mul(numw_sub(numw_from(NUM_ZERO), num), tmax,
                                                               numw_sub(numw_from(NUM_ZERO), den));
}

/* The plane's t for any ray (no side or sign test): shading's hit point
 * on a flat piece the renderer found the ray to cover. Its numerator
 * (a - o) . n depends on the ray's origin only: geom_flat_num, which the
 * shading pass keeps for the camera rays of a pinhole camera (one eye). */
static inline __attribute__((always_inline)) numw_t geom_flat_num_at(const vec3_t *a, const vec3_t *n,
                                                                      const vec3_t *o)
{
    return vec3_dotw_unit(vec3_sub(*a, *o), *n);
}
numw_t geom_flat_num(const vec3_t *a, const vec3_t *n, const vec3_t *o)
{
    return geom_flat_num_at(a, n, o);
}
num_t geom_flat_surface_t(const vec3_t *a, const vec3_t *n, const ray_t *ray)
{
    return numw_div(geom_flat_num_at(a, n, &ray->o), vec3_dotw_units(ray->d, *n));
}
