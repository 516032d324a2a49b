/* raycast: the per-pixel ray caster that the seed report describes. For
 * every pixel it casts the camera ray (cam_ray) and takes the nearest hit
 * over all objects (world_hit). It shares nothing with the scanline
 * renderer's camera-space forms, so it serves two purposes:
 *  - the oracle the fast renderer is tested against (tests/oracle.c);
 *  - the baseline a user would otherwise write (make bench).
 * It needs no per-frame set-up and no state besides the world and camera. */
#ifndef FXRT_RAYCAST_H
#define FXRT_RAYCAST_H

#include "scene/cam.h"
#include "scene/world.h"

/* Value of ids[x] for a pixel whose ray hits nothing. */
#define RAYCAST_MISS 0xFFFFu

/* Render output row `row` (0 = top) into rgb (3 * width bytes, RGB888).
 * When ids is not NULL it receives, per column, the scene id of the
 * nearest object, or RAYCAST_MISS. */
void raycast_row(const world_t *w, const cam_t *cam, int32_t row, uint8_t *rgb, uint16_t *ids);

#endif
