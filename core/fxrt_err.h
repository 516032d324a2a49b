/* fxrt_err: the error codes of the public API (core/fxrt.h). Every call
 * that can refuse its input returns FXRT_OK (0), a non-negative result
 * (an object id), or one of these negative codes; fxrt_strerror gives the
 * text. Kept in its own header because the geometry constructors (geom.c)
 * and the world (world.c) return them too. */
#ifndef FXRT_ERR_H
#define FXRT_ERR_H

#include "fxrt_config.h"

typedef enum {
    FXRT_OK = 0,
    FXRT_ERR_FULL = -1,      /* this kind's capacity (FXRT_MAX_<KIND>) is used up, or 0 */
    FXRT_ERR_COORD = -2,     /* a coordinate beyond +-FXRT_COORD_LIMIT (or NaN) */
    FXRT_ERR_TINY = -3,      /* float/double: a nonzero value below 2^-16, 0 in Q16.16 */
    FXRT_ERR_DIRECTION = -4, /* a zero normal, gaze or up vector */
    FXRT_ERR_RADIUS = -5,    /* sphere radius outside (0, FXRT_RADIUS_LIMIT] */
    FXRT_ERR_COLOR = -6,     /* a colour channel outside 0..255 (1/255 units) */
    FXRT_ERR_BOX = -7,       /* box min > max on some axis */
    FXRT_ERR_SIZE = -8,      /* image width or height outside 1..FXRT_MAX_DIM */
    FXRT_ERR_UP = -9,        /* up parallel to the gaze */
    FXRT_ERR_FOV = -10,      /* fov outside (0, 180) degrees */
    FXRT_ERR_NARROW = -11,   /* height * cot(fov/2) > 32767: rays do not fit Q16.16 */
    FXRT_ERR_SCALE = -12,    /* orthographic scale outside (0, FXRT_RADIUS_LIMIT] */
    FXRT_ERR_EXTENT = -13,   /* orthographic ray origins would leave +-FXRT_COORD_LIMIT */
    FXRT_ERR_CAMERA = -14,   /* a camera description of unknown kind */
    FXRT_ERR_WIDTH = -15,    /* image wider than FXRT_RENDER_MAX_WIDTH */
    FXRT_ERR_KIND = -16,     /* an fxrt_object_t with an unknown kind */
    FXRT_ERR_CONFIG = -17,   /* core and application built with different configurations */
    FXRT_ERR_RENDER = -18,   /* render_setup refused the frame for another reason (render_t capacity) */
    FXRT_ERR_ANGLE = -19,    /* spot light half-angle outside (0, 90] degrees */
    FXRT_ERR_MATERIAL = -20, /* unknown material, or its lighting compiled out (FXRT_MAX_LIGHTS 0, FXRT_PHONG 0) */
    FXRT_ERR_ID = -21,       /* no object with this id */
    FXRT_ERR_LIGHT = -22,    /* unknown light kind */
    FXRT_ERR_DEPTH = -23,    /* bounce depth outside 0..FXRT_MAX_DEPTH */
    FXRT_ERR_SAMPLES = -24,  /* samples outside 1..FXRT_MAX_SAMPLES, or adaptive compiled out */
    FXRT_ERR_NULL = -25,     /* a NULL pointer where the call needs an object */
    FXRT_ERR_ROW = -26,      /* a row outside 0..height-1 */
    FXRT_ERR_SETUP = -27,    /* fxrt_render_row before a successful fxrt_render_setup, or after the view changed */
    FXRT_ERR_BUFFER = -28,   /* a row buffer smaller than FXRT_ROW_BYTES(width), or RGB565 rows not 2-byte aligned */
    FXRT_ERR_INIT = -29,     /* a world that fxrt_world_init has not set up */
    FXRT_ERR_EXPONENT = -30, /* phong or reflective exponent outside 1..FXRT_PHONG_MAX_EXPONENT */
    FXRT_ERR_INDEX = -31,    /* refraction index outside FXRT_INDEX_MIN..FXRT_INDEX_MAX */
    FXRT_ERR_LIGHTS = -32,   /* FXRT_MAX_LIGHTS lights are there already */
    FXRT_ERR_MESH = -33,     /* a model whose mesh data or placement is malformed (bvh_check, geom_model_box) */
    FXRT_ERR_AXES = -34,     /* an ellipsoid's or parallelepiped's axes flat (dependent), thinner than 2^-13, or det beyond 2^30 */
    /* Camera errors without a name above (cam_setup codes added later)
     * come back as FXRT_ERR_CAM_BASE + their cam_err_t, so the caller and
     * fxrt_strerror still tell them apart. */
    FXRT_ERR_CAM_BASE = -100,
} fxrt_err_t;

#endif
