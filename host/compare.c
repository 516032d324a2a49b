/* Image comparison metrics for fxrt compare and the golden tests.
 *
 * Edge/interior classification exists because fixed-point and floating
 * renderers legitimately disagree on which side of a silhouette a boundary
 * pixel falls; such mismatches are expected, interior ones are bugs. */
#include "compare.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Brightness of the weakest mismatch in the heat map: bright enough to
 * spot a single off-by-one pixel against black. */
#define COMPARE_HEAT_MIN_RED 96

static int compare_same_pixel(const image_t *img, size_t i, size_t j)
{
    const uint8_t *p = img->rgb + i * 3;
    const uint8_t *q = img->rgb + j * 3;

    return p[0] == q[0] && p[1] == q[1] && p[2] == q[2];
}

/* Image borders are not edges: a pixel has only its in-bounds neighbours. */
static int compare_is_edge(const image_t *img, int x, int y)
{
    size_t w = (size_t)img->width;
    size_t i = (size_t)y * w + (size_t)x;

    if (x > 0 && !compare_same_pixel(img, i, i - 1))
        return 1;
    if (x + 1 < img->width && !compare_same_pixel(img, i, i + 1))
        return 1;
    if (y > 0 && !compare_same_pixel(img, i, i - w))
        return 1;
    if (y + 1 < img->height && !compare_same_pixel(img, i, i + w))
        return 1;
    return 0;
}

/* Evaluated only for mismatched pixels, which are few in any comparison
 * worth looking at, so no edge map is allocated. */
static int compare_near_edge(const image_t *img, int x, int y)
{
    int dx, dy;

    for (dy = -1; dy <= 1; dy++) {
        for (dx = -1; dx <= 1; dx++) {
            int nx = x + dx;
            int ny = y + dy;

            if (nx < 0 || ny < 0 || nx >= img->width || ny >= img->height)
                continue;
            if (compare_is_edge(img, nx, ny))
                return 1;
        }
    }
    return 0;
}

/* Ramp black -> dark red -> red -> yellow -> white over error 1..255.
 * The square root spreads the small errors (1..16) that dominate
 * fixed-vs-float differences over a visible range of reds. */
static void compare_heat_table(uint8_t table[256][3])
{
    int e;

    memset(table[0], 0, 3);
    for (e = 1; e <= 255; e++) {
        double t = sqrt((double)(e - 1) / 254.0) * 3.0; /* 0..3, one unit per segment */
        double r, g, b;

        if (t <= 1.0) {
            r = COMPARE_HEAT_MIN_RED + (255.0 - COMPARE_HEAT_MIN_RED) * t;
            g = 0.0;
            b = 0.0;
        } else if (t <= 2.0) {
            r = 255.0;
            g = 255.0 * (t - 1.0);
            b = 0.0;
        } else {
            r = 255.0;
            g = 255.0;
            b = 255.0 * (t - 2.0);
        }
        table[e][0] = (uint8_t)lround(r);
        table[e][1] = (uint8_t)lround(g);
        table[e][2] = (uint8_t)lround(b);
    }
}

static int compare_valid(const image_t *img)
{
    return img != NULL && img->rgb != NULL && img->width > 0 && img->height > 0;
}

int compare_images(const image_t *a, const image_t *b, compare_result_t *res,
                   image_t *diff, char *err, size_t errlen)
{
    uint8_t heat[256][3];
    uint64_t sq_sum = 0;
    long mismatched = 0, edge = 0, interior = 0;
    int max_err = 0;
    int x, y;

    if (diff != NULL) {
        diff->width = 0;
        diff->height = 0;
        diff->rgb = NULL;
    }
    if (!compare_valid(a) || !compare_valid(b)) {
        if (err != NULL && errlen > 0)
            snprintf(err, errlen, "invalid image");
        return -1;
    }
    if (a->width != b->width || a->height != b->height) {
        if (err != NULL && errlen > 0)
            snprintf(err, errlen, "size mismatch: %dx%d vs %dx%d", a->width, a->height,
                     b->width, b->height);
        return -1;
    }
    /* Allocate before measuring so a failure leaves *res untouched. */
    if (diff != NULL) {
        if (image_alloc(diff, a->width, a->height, err, errlen) != 0)
            return -1;
        compare_heat_table(heat);
    }

    for (y = 0; y < a->height; y++) {
        for (x = 0; x < a->width; x++) {
            size_t i = ((size_t)y * (size_t)a->width + (size_t)x) * 3;
            int pixel_err = 0;
            int c;

            for (c = 0; c < 3; c++) {
                int d = abs((int)a->rgb[i + (size_t)c] - (int)b->rgb[i + (size_t)c]);

                sq_sum += (uint64_t)(d * d);
                if (d > pixel_err)
                    pixel_err = d;
            }
            if (pixel_err == 0)
                continue;
            mismatched++;
            if (pixel_err > max_err)
                max_err = pixel_err;
            if (compare_near_edge(a, x, y))
                edge++;
            else
                interior++;
            if (diff != NULL)
                memcpy(diff->rgb + i, heat[pixel_err], 3);
        }
    }

    res->pixels = (long)a->width * (long)a->height;
    res->mismatched = mismatched;
    res->mismatched_pct = 100.0 * (double)mismatched / (double)res->pixels;
    res->max_err = max_err;
    if (sq_sum == 0) {
        res->psnr = (double)INFINITY;
    } else {
        double mse = (double)sq_sum / (3.0 * (double)res->pixels);

        res->psnr = 10.0 * log10(255.0 * 255.0 / mse);
    }
    res->edge_mismatched = edge;
    res->interior_mismatched = interior;
    return 0;
}

void compare_print(FILE *out, const compare_result_t *res)
{
    char psnr[32];

    if (isinf(res->psnr))
        snprintf(psnr, sizeof psnr, "inf");
    else
        snprintf(psnr, sizeof psnr, "%.2f", res->psnr);
    fprintf(out,
            "pixels=%ld mismatched=%ld mismatched_pct=%.4f max_err=%d psnr=%s "
            "edge_mismatched=%ld interior_mismatched=%ld\n",
            res->pixels, res->mismatched, res->mismatched_pct, res->max_err, psnr,
            res->edge_mismatched, res->interior_mismatched);
}
