/* scenec: the scene compiler's per-number-type emitters. */
#ifndef FXRT_HOST_SCENEC_H
#define FXRT_HOST_SCENEC_H

#include <stdbool.h>
#include <stdio.h>
#include "scene.h"

/* Write the capacity/size macros to cfg and the scene's description (the
 * public API's fxrt_camera_t, background and fxrt_object_t table) to
 * data. Capacities are the scene's counts (an unused kind compiles out),
 * or at least 1 each with all_kinds. Returns 0, or -1 with
 * "PATH:LINE: ..." in err. */
int scenec_emit_q16(FILE *cfg, FILE *data, const char *path, const scene_t *sc, int width, int height,
                    bool all_kinds, char *err, size_t errlen);
int scenec_emit_float(FILE *cfg, FILE *data, const char *path, const scene_t *sc, int width, int height,
                      bool all_kinds, char *err, size_t errlen);
int scenec_emit_double(FILE *cfg, FILE *data, const char *path, const scene_t *sc, int width, int height,
                       bool all_kinds, char *err, size_t errlen);

#endif
