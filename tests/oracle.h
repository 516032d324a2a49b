/* oracle: the fast renderer against the per-pixel ray caster (tests/oracle.c).
 * oracle_num.c is compiled once per number type. */
#ifndef FXRT_TESTS_ORACLE_H
#define FXRT_TESTS_ORACLE_H

#include <stddef.h>
#include <stdint.h>
#include "../host/scene.h"

/* Render sc at width x height with render_row into fast (3 * width * height
 * bytes, may be NULL to skip it) and with raycast_row into ray, with the
 * ray caster's object ids (scene index, or RAYCAST_MISS) in ids. Returns 0,
 * or -1 with "PATH:LINE: ..." in err when the scene cannot be set up. */
int oracle_frame_q16(const char *path, const scene_t *sc, int width, int height, uint8_t *fast, uint8_t *ray,
                     uint16_t *ids, char *err, size_t errlen);
int oracle_frame_double(const char *path, const scene_t *sc, int width, int height, uint8_t *fast,
                        uint8_t *ray, uint16_t *ids, char *err, size_t errlen);

/* The 8-bit colour of every object, by scene index, into rgb[3 * i], and
 * the background's into rgb[3 * sc->count] (3 * (count + 1) bytes), as
 * the build rounds them. Returns 0, or -1 with a message in err. */
int oracle_colors_q16(const char *path, const scene_t *sc, int width, int height, uint8_t *rgb, char *err,
                      size_t errlen);
int oracle_colors_double(const char *path, const scene_t *sc, int width, int height, uint8_t *rgb, char *err,
                         size_t errlen);

#endif
