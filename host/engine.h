/* engine: the renderer in each number type, behind one double-based
 * interface. host/engine.c is compiled once per number type. */
#ifndef FXRT_HOST_ENGINE_H
#define FXRT_HOST_ENGINE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "scene.h"

typedef enum { ENGINE_Q16, ENGINE_FLOAT, ENGINE_DOUBLE } engine_number_t;

/* Which loop renders the frame:
 *   ENGINE_FAST       the scanline renderer (render_row), the product
 *   ENGINE_REFERENCE  every object's forms at every pixel (render_row_reference)
 *   ENGINE_RAYCAST    a camera ray and a nearest-hit search per pixel
 *                     (raycast_row): the oracle and the naive baseline */
typedef enum { ENGINE_FAST, ENGINE_REFERENCE, ENGINE_RAYCAST } engine_renderer_t;

/* "fast", "reference", "raycast" -> renderer; returns -1 for anything else. */
int engine_renderer_parse(const char *s, engine_renderer_t *out);

/* "q16", "float", "double" -> number type; returns -1 for anything else. */
int engine_number_parse(const char *s, engine_number_t *out);
const char *engine_number_name(engine_number_t n);

/* The key of a background pixel (core/frame/render.h RENDER_KEY_MISS, which
 * engine.c checks it against), for code that does not include the core. */
#define ENGINE_KEY_MISS 0xFFFF00u

/* Render the scene at width x height into rgb (3 * width * height bytes,
 * top row first) with the chosen renderer. When keys is not NULL it
 * receives each pixel's key (width * height entries, top row first; core/
 * render.h render_key: object id << 8 | mask of the lights that reach the
 * hit point, ENGINE_KEY_MISS for the background). The ray
 * caster (ENGINE_RAYCAST) writes no keys: its pixels stay ENGINE_KEY_MISS.
 * With rgb NULL (and keys not) only the keys are made, at one sample per
 * pixel, so the scene's samples x width need not fit. Returns 0, or -1
 * with "PATH: ..." in err (for example a camera that the number type
 * cannot represent at this size). */
int engine_render(engine_number_t n, const char *path, const scene_t *sc, int width, int height, engine_renderer_t renderer,
                  uint8_t *rgb, uint32_t *keys, char *err, size_t errlen);

/* The same, one build each (engine.c compiled three times). */
int engine_render_q16(const char *path, const scene_t *sc, int width, int height, engine_renderer_t renderer, uint8_t *rgb,
                      uint32_t *keys, char *err, size_t errlen);
int engine_render_float(const char *path, const scene_t *sc, int width, int height, engine_renderer_t renderer, uint8_t *rgb,
                        uint32_t *keys, char *err, size_t errlen);
int engine_render_double(const char *path, const scene_t *sc, int width, int height, engine_renderer_t renderer, uint8_t *rgb,
                         uint32_t *keys, char *err, size_t errlen);

#endif
