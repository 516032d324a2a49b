/* render: the scanline renderer. The caller owns every buffer: it asks for
 * one row at a time and gets width RGB888 pixels (3 bytes each), so a whole
 * frame buffer is optional. */
#ifndef FXRT_RENDER_H
#define FXRT_RENDER_H

#include "cam.h"
#include "world.h"

/* The colour seen along one ray: the nearest object's, else the
 * background. */
rgb8_t render_pixel(const world_t *w, const ray_t *ray);

/* Render output row `row` (0 = top of the image) into rgb, which holds
 * 3 * cam->width bytes. */
void render_row(const world_t *w, const cam_t *cam, int32_t row, uint8_t *rgb);

#endif
