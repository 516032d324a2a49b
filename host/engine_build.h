/* engine_build: scene -> world and camera in the including file's number
 * type. Include after the core headers; used by engine.c and the scene
 * compiler. */
#ifndef FXRT_HOST_ENGINE_BUILD_H
#define FXRT_HOST_ENGINE_BUILD_H

#include "../core/fxrt.h"
#include "multi.h"
#include "scene.h"

#ifdef FXRT_MULTI
#define ENGINE_SYM(name) MULTI_SYM(name)
#else
#define ENGINE_SYM(name) name
#endif

/* A scene value in the build's number type (Q16.16: rounded to nearest). */
num_t ENGINE_SYM(engine_num)(double x);

/* A scene in the build's number type, as the public API takes it: what
 * fxrt-scenec emits for the firmware and what engine_build passes to
 * fxrt_camera_setup, fxrt_world_init and fxrt_add. */
typedef struct {
    fxrt_camera_t camera;
    color_t background;
    int count;
    fxrt_object_t obj[SCENE_MAX_OBJECTS]; /* scene order: object i gets id i; .material set */
    color_t ambient; /* fractions (NUM_ONE = full), quantised to 2^-16 */
    int nlights;
    fxrt_light_t lights[SCENE_MAX_LIGHTS > 0 ? SCENE_MAX_LIGHTS : 1]; /* scene order */
    int depth;     /* the scene's 'depth' (world_set_depth) */
    int samples;   /* the scene's 'samples' N (world_set_samples) */
    bool adaptive; /* 'samples N adaptive' */
    bool bounces;  /* some object is reflective or transparent */
    /* The models' instances (obj[i].inst points here), in scene order. */
    FXRT_IF_MODEL(bvh_inst_t inst[FXRT_MAX_MODELS];)
} engine_desc_t;

/* A refraction index x in [FXRT_INDEX_MIN, FXRT_INDEX_MAX] as the build
 * stores it: round(x * 65536) / 65536, but at least the smallest multiple
 * of 2^-16 that is >= FXRT_INDEX_MIN (0.01 -> 656/65536, since 655/65536
 * is below 0.01); the same value in every build. */
num_t ENGINE_SYM(engine_index)(double x);

/* Convert the parsed scene (doubles) into d, rounding each value once
 * (engine_num). Returns 0. */
int ENGINE_SYM(engine_describe)(const scene_t *sc, int width, int height, engine_desc_t *d);

/* Build the world and camera for a width x height frame: camera, world,
 * objects with their materials (fxrt_add), ambient (world_set_ambient),
 * lights (fxrt_add_light), depth (world_set_depth: a refusal is an error
 * only when some object is reflective or transparent, since the depth
 * changes nothing else) and samples (world_set_samples). Returns 0, or -1
 * with "PATH:LINE: ..." in err. */
int ENGINE_SYM(engine_build)(const char *path, const scene_t *sc, int width, int height, world_t *w,
                             cam_t *cam, char *err, size_t errlen);

#endif
