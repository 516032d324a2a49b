/* Image comparison metrics for fxrt compare and the golden tests. */
#ifndef FXRT_HOST_COMPARE_H
#define FXRT_HOST_COMPARE_H

#include <stdio.h>
#include "image.h"

typedef struct {
    long pixels;              /* width * height */
    long mismatched;          /* pixels whose RGB differs in any channel */
    double mismatched_pct;    /* 100 * mismatched / pixels */
    int max_err;              /* largest absolute channel difference, 0..255 */
    double psnr;              /* dB over all channels; INFINITY when identical */
    long edge_mismatched;     /* mismatches near an edge in A */
    long interior_mismatched; /* mismatches with no edge pixel of A in their 3x3 */
} compare_result_t;

/* Compare A and B (same size required). A pixel of A is an edge pixel when
 * one of its 4-neighbours in A has a different colour. A mismatch is
 * interior when no pixel of its 3x3 neighbourhood in A is an edge pixel.
 * If diff is not NULL it receives a newly allocated heat map of the same
 * size (black = equal; mismatches shaded from dark red to yellow-white by
 * max channel error; always at least clearly visible).
 * Returns 0, or -1 with a message in err (size mismatch). */
int compare_images(const image_t *a, const image_t *b, compare_result_t *res,
                   image_t *diff, char *err, size_t errlen);

/* One line of key=value pairs, in this order:
 * pixels= mismatched= mismatched_pct= max_err= psnr= edge_mismatched= interior_mismatched=
 * mismatched_pct with 4 decimals, psnr with 2 decimals or "inf". */
void compare_print(FILE *out, const compare_result_t *res);

#endif
