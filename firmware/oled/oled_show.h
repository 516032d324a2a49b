/* oled_show: the compiled scene (fxrt-scenec's scene_data.h, Q16.16) as
 * OLED_FRAMES frames, row by row into one RGB888 row buffer, each row
 * handed to a sink as it is rendered. One source for the board (sink:
 * oled_board.c, dithering onto the SSD0323) and the host (oled_host.c, PPM
 * files), so the host's frames are the board's, turned camera included.
 *
 * Frame f's camera is the scene's turned f * OLED_TURN_DEG degrees about
 * the vertical axis through eye + gaze (the point the scene's camera looks
 * at when, as in scenes/lit, gaze is written as target - eye): the eye
 * circles that point at its own height and keeps looking at it. Frame 0,
 * and every frame when OLED_TURN_DEG is 0, is the scene's own camera,
 * the frame `fxrt render SCENE --size WxH` gives. */
#ifndef FXRT_OLED_SHOW_H
#define FXRT_OLED_SHOW_H

#include <stdint.h>

#include "dither.h"

/* Frames shown; the program ends after the last. */
#ifndef OLED_FRAMES
#define OLED_FRAMES 1
#endif
/* Integer degrees the camera turns per frame (0: a still scene). */
#ifndef OLED_TURN_DEG
#define OLED_TURN_DEG 0
#endif
/* Dithering (dither.h): one oled_dither_method_t for every frame, or -1:
 * frame f uses method f mod OLED_DITHER_METHODS (none, bayer4, bayer8,
 * fs, none, ...), the same picture in every method. */
#ifndef OLED_METHOD
#define OLED_METHOD 3
#endif
#if OLED_FRAMES < 1 || OLED_METHOD < -1 || OLED_METHOD > 3
#error "OLED_FRAMES must be >= 1 and OLED_METHOD -1 (cycle) or 0..3 (dither.h)"
#endif

static inline oled_dither_method_t oled_frame_method(int32_t frame)
{
    return OLED_METHOD < 0 ? (oled_dither_method_t)(frame % OLED_DITHER_METHODS) : (oled_dither_method_t)OLED_METHOD;
}

/* The sink: frame `frame` starts (width x height pixels), then its rows
 * come top first (rgb: 3 * width bytes, valid during the call), then it
 * ends. */
void oled_sink_begin(int32_t frame, int32_t width, int32_t height);
void oled_sink_row(int32_t row, const uint8_t *rgb);
void oled_sink_end(int32_t frame);
/* Report "what: msg" and end the program with a non-zero status. */
void oled_sink_fail(const char *what, const char *msg) __attribute__((noreturn));

/* Build the world, show every frame; returns 0. */
int oled_show(void);

#endif
