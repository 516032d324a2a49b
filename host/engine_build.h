/* engine_build: scene -> world and camera in the including file's number
 * type. Include after the core headers; used by engine.c and the scene
 * compiler. */
#ifndef FXRT_HOST_ENGINE_BUILD_H
#define FXRT_HOST_ENGINE_BUILD_H

#include "../core/cam.h"
#include "../core/world.h"
#include "scene.h"

#ifdef FXRT_MULTI
#define ENGINE_SYM(name) FXRT_SYM(name)
#else
#define ENGINE_SYM(name) name
#endif

/* A scene value in the build's number type (Q16.16: rounded to nearest). */
num_t ENGINE_SYM(engine_num)(double x);

/* Build the world and camera for a width x height frame. Returns 0, or -1
 * with "PATH:LINE: ..." in err. */
int ENGINE_SYM(engine_build)(const char *path, const scene_t *sc, int width, int height, world_t *w,
                             cam_t *cam, char *err, size_t errlen);

#endif
