/* Image comparison metrics for fxrt compare and the golden tests. */
#ifndef FXRT_HOST_COMPARE_H
#define FXRT_HOST_COMPARE_H

#include <stdint.h>
#include <stdio.h>
#include "image.h"

/* A pixel's error is its largest absolute channel difference (0..255, in
 * units of 1/255). "Within k" means an error of at most k in every channel.
 * Percentages of an empty set (near_* without keys) are 100: every pixel
 * of the set, vacuously. */
typedef struct {
    long pixels;              /* width * height */
    long mismatched;          /* pixels whose RGB differs in any channel */
    double mismatched_pct;    /* 100 * mismatched / pixels */
    int max_err;              /* largest pixel error, 0..255 */
    double psnr;              /* dB over all channels; INFINITY when identical */
    long edge_mismatched;     /* mismatches near an edge in A */
    long interior_mismatched; /* mismatches with no edge pixel of A in their 3x3 */
    /* Shaded images differ a little everywhere: these count how much. */
    long within1, within2;    /* pixels with error <= 1, <= 2 */
    double within1_pct, within2_pct;
    /* Split by the key map (compare_images_keyed); without one every pixel
     * is far. */
    long near_pixels, far_pixels;
    long near_within1, near_within2, far_within1, far_within2;
    double near_within1_pct, near_within2_pct, far_within1_pct, far_within2_pct;
    int near_max_err, far_max_err;
    double mae; /* mean absolute error per channel, in 1/255 units (0 when identical) */
} compare_result_t;

/* Compare A and B (same size required). A pixel of A is an edge pixel when
 * one of its 4-neighbours in A has a different colour. A mismatch is
 * interior when no pixel of its 3x3 neighbourhood in A is an edge pixel.
 * If diff is not NULL it receives a newly allocated heat map of the same
 * size: black = equal, else a colour for the pixel error e (COMPARE_HEAT_*:
 * 1 dark red (128,0,0), 6 red, 11 yellow, 16 and more white).
 * Returns 0, or -1 with a message in err (size mismatch). */
int compare_images(const image_t *a, const image_t *b, compare_result_t *res,
                   image_t *diff, char *err, size_t errlen);

/* The same with a key map: keys[y * width + x] is the key of pixel (x, y)
 * (core/frame/render.h render_key: object id and lights reaching the hit point,
 * from the double render of the scene, never from A or B). A pixel is near
 * a discontinuity when a pixel of its 8-neighbourhood (clipped at the image
 * border) has another key (compare_key_near); the near_* and far_* fields
 * split the counts by it. In the heat map, equal pixels near a
 * discontinuity are dark blue (COMPARE_HEAT_NEAR) instead of black.
 * keys may be NULL (every pixel far): compare_images. */
int compare_images_keyed(const image_t *a, const image_t *b, const uint32_t *keys,
                         compare_result_t *res, image_t *diff, char *err, size_t errlen);

/* 1 when pixel (x, y) of a width x height key map has a pixel of another
 * key among its (in-bounds) 8 neighbours, else 0. */
int compare_key_near(const uint32_t *keys, int width, int height, int x, int y);

/* A picture of a key map (fxrt render --keys): black for miss_key, else a
 * colour from a hash of the key with every channel in 64..255, so that
 * neighbouring keys (one more light, the next object) look different.
 * Returns 0, or -1 with a message in err (allocation). */
int compare_keys_image(const uint32_t *keys, int width, int height, uint32_t miss_key,
                       image_t *out, char *err, size_t errlen);

/* The heat map's scale: error 1 is COMPARE_HEAT_MIN_RED red, the colour
 * rises linearly through red (to error 6), yellow (11) and white
 * (COMPARE_HEAT_WHITE_ERR and above). */
#define COMPARE_HEAT_MIN_RED 128
#define COMPARE_HEAT_WHITE_ERR 16
/* Heat-map colour of an equal pixel near a key discontinuity. */
#define COMPARE_HEAT_NEAR_B 72

/* One line of key=value pairs, in this order:
 * pixels= mismatched= mismatched_pct= max_err= psnr= edge_mismatched= interior_mismatched=
 * within1_pct= within2_pct= near_pixels= far_pixels= far_within1_pct= far_within2_pct=
 * far_max_err= near_max_err= near_within1_pct= near_within2_pct= mae=
 * mismatched_pct and mae with 4 decimals, psnr with 2 decimals or "inf"; the
 * *within*_pct with 4 decimals rounded down, so 100.0000 means every pixel
 * of the set and a threshold check on the printed value is never too kind. */
void compare_print(FILE *out, const compare_result_t *res);

#endif
