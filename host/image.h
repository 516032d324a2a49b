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

void image_free(image_t *img);

#endif
