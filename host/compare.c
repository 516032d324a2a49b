/* Image comparison metrics for fxrt compare and the golden tests.
 *
 * Edge/interior classification exists because fixed-point and floating
 * renderers legitimately disagree on which side of a silhouette a boundary
 * pixel falls; such mismatches are expected, interior ones are bugs.
 *
 * Shaded images differ by a unit or two almost everywhere, so for them the
 * counts that matter are the shares of pixels within 1/255 and 2/255 and
 * the split by a key map (which object, which lights) from the double
 * render: near a discontinuity in keys a pixel may legitimately change
 * object or light; away from one it must not. */
#include "compare.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

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

/* Ramp black -> dark red -> red -> yellow -> white over error 1..16 and
 * white beyond: the errors of a shaded fixed-point frame are 1..3 units,
 * so each unit below 16 gets its own clearly different colour (the first,
 * COMPARE_HEAT_MIN_RED, stands out against black on its own). */
static void compare_heat_table(uint8_t table[256][3])
{
    int e;

    memset(table[0], 0, 3);
    for (e = 1; e <= 255; e++) {
        int steps = COMPARE_HEAT_WHITE_ERR - 1; /* error 1 .. white */
        double t = 3.0 * (double)(e - 1 < steps ? e - 1 : steps) / (double)steps;
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

int compare_key_near(const uint32_t *keys, int width, int height, int x, int y)
{
    uint32_t k = keys[(size_t)y * (size_t)width + (size_t)x];
    int dx, dy;

    for (dy = -1; dy <= 1; dy++) {
        for (dx = -1; dx <= 1; dx++) {
            int nx = x + dx;
            int ny = y + dy;

            if (nx < 0 || ny < 0 || nx >= width || ny >= height)
                continue;
            if (keys[(size_t)ny * (size_t)width + (size_t)nx] != k)
                return 1;
        }
    }
    return 0;
}

/* 100 * n / of, and 100 for an empty set. */
static double compare_pct(long n, long of)
{
    return of > 0 ? 100.0 * (double)n / (double)of : 100.0;
}

static int compare_valid(const image_t *img)
{
    return img != NULL && img->rgb != NULL && img->width > 0 && img->height > 0;
}

int compare_images(const image_t *a, const image_t *b, compare_result_t *res,
                   image_t *diff, char *err, size_t errlen)
{
    return compare_images_keyed(a, b, NULL, res, diff, err, errlen);
}

int compare_images_keyed(const image_t *a, const image_t *b, const uint32_t *keys,
                         compare_result_t *res, image_t *diff, char *err, size_t errlen)
{
    uint8_t heat[256][3];
    uint64_t sq_sum = 0;
    uint64_t abs_sum = 0;
    long mismatched = 0, edge = 0, interior = 0;
    long within1 = 0, within2 = 0, near_px = 0;
    long near1 = 0, near2 = 0, far1 = 0, far2 = 0;
    int max_err = 0, near_max = 0, far_max = 0;
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
            int near = keys != NULL && compare_key_near(keys, a->width, a->height, x, y);
            int pixel_err = 0;
            int c;

            for (c = 0; c < 3; c++) {
                int d = abs((int)a->rgb[i + (size_t)c] - (int)b->rgb[i + (size_t)c]);

                sq_sum += (uint64_t)(d * d);
                abs_sum += (uint64_t)d;
                if (d > pixel_err)
                    pixel_err = d;
            }
            within1 += pixel_err <= 1;
            within2 += pixel_err <= 2;
            if (near) {
                near_px++;
                near1 += pixel_err <= 1;
                near2 += pixel_err <= 2;
                if (pixel_err > near_max)
                    near_max = pixel_err;
            } else {
                far1 += pixel_err <= 1;
                far2 += pixel_err <= 2;
                if (pixel_err > far_max)
                    far_max = pixel_err;
            }
            if (pixel_err == 0) {
                if (near && diff != NULL)
                    diff->rgb[i + 2] = COMPARE_HEAT_NEAR_B;
                continue;
            }
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
    res->mae = (double)abs_sum / (3.0 * (double)res->pixels);
    res->edge_mismatched = edge;
    res->interior_mismatched = interior;
    res->within1 = within1;
    res->within2 = within2;
    res->within1_pct = compare_pct(within1, res->pixels);
    res->within2_pct = compare_pct(within2, res->pixels);
    res->near_pixels = near_px;
    res->far_pixels = res->pixels - near_px;
    res->near_within1 = near1;
    res->near_within2 = near2;
    res->far_within1 = far1;
    res->far_within2 = far2;
    res->near_within1_pct = compare_pct(near1, near_px);
    res->near_within2_pct = compare_pct(near2, near_px);
    res->far_within1_pct = compare_pct(far1, res->far_pixels);
    res->far_within2_pct = compare_pct(far2, res->far_pixels);
    res->near_max_err = near_max;
    res->far_max_err = far_max;
    return 0;
}

int compare_keys_image(const uint32_t *keys, int width, int height, uint32_t miss_key,
                       image_t *out, char *err, size_t errlen)
{
    size_t n, i;

    if (image_alloc(out, width, height, err, errlen) != 0)
        return -1;
    n = (size_t)width * (size_t)height;
    for (i = 0; i < n; i++) {
        uint32_t h = keys[i];
        int c;

        if (h == miss_key)
            continue; /* image_alloc zeroes: black */
        /* A 32-bit integer mix (murmur3's finaliser): every key bit moves
         * every channel. The offset keeps key 0 (the first object, no
         * light) from mixing to 0, a dull grey. */
        h += 0x9e3779b9u;
        h ^= h >> 16;
        h *= 0x85ebca6bu;
        h ^= h >> 13;
        h *= 0xc2b2ae35u;
        h ^= h >> 16;
        for (c = 0; c < 3; c++)
            out->rgb[i * 3 + (size_t)c] = (uint8_t)(64 + (h >> (8 * c)) % 192);
    }
    return 0;
}

/* 100 * n / of rounded down to 4 decimals, in exact integer arithmetic
 * (a rounded 99.99996 would print as 100.0000), into buf. */
static const char *compare_pct_floor(char *buf, size_t len, long n, long of)
{
    long long q = of > 0 ? (long long)n * 1000000LL / (long long)of : 1000000LL;

    snprintf(buf, len, "%lld.%04lld", q / 10000, q % 10000);
    return buf;
}

void compare_print(FILE *out, const compare_result_t *res)
{
    char psnr[32], w1[24], w2[24], f1[24], f2[24], n1[24], n2[24];

    if (isinf(res->psnr))
        snprintf(psnr, sizeof psnr, "inf");
    else
        snprintf(psnr, sizeof psnr, "%.2f", res->psnr);
    fprintf(out,
            "pixels=%ld mismatched=%ld mismatched_pct=%.4f max_err=%d psnr=%s "
            "edge_mismatched=%ld interior_mismatched=%ld "
            "within1_pct=%s within2_pct=%s near_pixels=%ld far_pixels=%ld "
            "far_within1_pct=%s far_within2_pct=%s far_max_err=%d near_max_err=%d "
            "near_within1_pct=%s near_within2_pct=%s mae=%.4f\n",
            res->pixels, res->mismatched, res->mismatched_pct, res->max_err, psnr,
            res->edge_mismatched, res->interior_mismatched,
            compare_pct_floor(w1, sizeof w1, res->within1, res->pixels),
            compare_pct_floor(w2, sizeof w2, res->within2, res->pixels), res->near_pixels,
            res->far_pixels, compare_pct_floor(f1, sizeof f1, res->far_within1, res->far_pixels),
            compare_pct_floor(f2, sizeof f2, res->far_within2, res->far_pixels),
            res->far_max_err, res->near_max_err,
            compare_pct_floor(n1, sizeof n1, res->near_within1, res->near_pixels),
            compare_pct_floor(n2, sizeof n2, res->near_within2, res->near_pixels), res->mae);
}
