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

/* Inside a number type's scene compiler (host/scenec_emit.c and
 * host/scenec_world.c, compiled per number type with engine_build.h):
 * scenec_world writes the world w as `static const world_t scene_world`
 * in Q16.16 (SCENE_WORLD 1), else only SCENE_WORLD 0 (the board builds
 * it at boot); 0, or -1 on a write error. scenec_mesh_name: the name of
 * the mesh scenec_emit writes for model object i. */
#ifdef ENGINE_SYM
int ENGINE_SYM(scenec_world)(FILE *f, const world_t *w, const scene_t *sc);
void ENGINE_SYM(scenec_mesh_name)(const scene_t *sc, int i, char *name, size_t len);
#endif

#endif
