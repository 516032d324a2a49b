/* Host image I/O: 8-bit RGB images, PNG (libpng) and binary PPM (P6). */
#ifndef FXRT_HOST_IMAGE_H
#define FXRT_HOST_IMAGE_H

#include <stddef.h>
#include <stdint.h>

/* Row-major, top row first, 3 bytes per pixel (R, G, B). */
typedef struct {
    int width;
    int height;
    uint8_t *rgb;
} image_t;

/* Largest accepted width or height when reading (protects against
 * absurd headers). */
#define IMAGE_MAX_DIM 16384

/* Allocate a zeroed width x height image. Returns 0, or -1 with a message. */
int image_alloc(image_t *img, int width, int height, char *err, size_t errlen);

/* Read a PNG or PPM (P6, maxval 255), chosen by the file's magic bytes,
 * not its name. PNGs of any colour type are converted to RGB8 (alpha is
 * dropped). Returns 0, or -1 with "PATH: what is wrong" in err. */
int image_read(const char *path, image_t *img, char *err, size_t errlen);

/* Write PNG or PPM, chosen by the extension (.png / .ppm, case-insensitive).
 * Atomic: writes PATH.tmp.PID then renames, so a failure leaves no partial
 * file at PATH. Returns 0, or -1 with a message in err. */
int image_write(const char *path, const image_t *img, char *err, size_t errlen);

/* image_write in two steps, for a command that writes several files and
 * must leave none when one fails: image_write_tmp writes PATH.tmp.PID
 * (its name in tmp, IMAGE_TMP_MAX bytes are enough) with image_write's checks;
 * image_write_commit renames it to PATH; image_write_abort removes it (a
 * no-op for an empty tmp). Each returns 0, or -1 with a message in err
 * and the temporary file removed. */
#define IMAGE_TMP_MAX 4096
int image_write_tmp(const char *path, const image_t *img, char *tmp, size_t tmplen, char *err, size_t errlen);
int image_write_commit(char *tmp, const char *path, char *err, size_t errlen);
void image_write_abort(char *tmp);

/* 0 when PATH names a format image_write can write (.png, .ppm) and is
 * not an existing directory, else -1 with a message: for checking outputs
 * before the work. */
int image_check_path(const char *path, char *err, size_t errlen);

/* SIGINT, SIGTERM and SIGHUP remove the temporary files being written,
 * then end the process as the signal would: an interrupted command leaves
 * no PATH.tmp.PID behind. A signal ignored when the process starts (nohup)
 * stays ignored. */
void image_cleanup_signals(void);

void image_free(image_t *img);

/* Text in a built-in 5x8 bitmap font (printable ASCII; any other byte is
 * drawn as '?'). A character takes IMAGE_GLYPH_ADVANCE columns (5 of ink, 1
 * of space) and IMAGE_GLYPH_H rows (7 above the baseline, 1 descender),
 * each font pixel a scale x scale square. */
#define IMAGE_GLYPH_W 5
#define IMAGE_GLYPH_H 8
#define IMAGE_GLYPH_ADVANCE 6

/* 1 when column col, row row (0 = top) of c's glyph is ink, else 0. */
int image_glyph_ink(char c, int col, int row);
/* Width in pixels of text drawn at scale (no trailing space); 0 for "". */
int image_text_width(const char *text, int scale);
/* Draw text with its top-left corner at (x, y) in colour rgb, clipped to
 * the image; only ink pixels are written. */
void image_draw_text(image_t *img, int x, int y, int scale, const char *text, const uint8_t rgb[3]);

#endif
