/* scenec: the scene compiler's per-number-type emitters. */
#ifndef FXRT_HOST_SCENEC_H
#define FXRT_HOST_SCENEC_H

#include <stdbool.h>
#include <stdio.h>
#include "scene.h"

/* Options (or-ed): every primitive kind compiled in (capacity at least 1,
 * --all-kinds); every sphere keeps its row-coherence state
 * (FXRT_COHERENT_SPHERES FXRT_MAX_SPHERES, --sphere-rows; else only in
 * worlds of at most FXRT_LONE_MAX objects). */
#define SCENEC_ALL_KINDS 1u
#define SCENEC_SPHERE_ROWS 2u

/* Write the capacity/size macros to cfg and the scene's description (the
 * public API's fxrt_camera_t, background and fxrt_object_t table) to
 * data. Capacities are the scene's counts (an unused kind compiles out),
 * or at least 1 each with SCENEC_ALL_KINDS. Returns 0, or -1 with
 * "PATH:LINE: ..." in err. */
int scenec_emit_q16(FILE *cfg, FILE *data, const char *path, const scene_t *sc, int width, int height,
                    unsigned opts, char *err, size_t errlen);
int scenec_emit_float(FILE *cfg, FILE *data, const char *path, const scene_t *sc, int width, int height,
                      unsigned opts, char *err, size_t errlen);
int scenec_emit_double(FILE *cfg, FILE *data, const char *path, const scene_t *sc, int width, int height,
                       unsigned opts, char *err, size_t errlen);

#endif
