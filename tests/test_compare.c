/* Tests for host/compare.c: counts, edge/interior split, max_err, PSNR,
 * the within-1/255 and 2/255 shares, the near/far split by a key map, the
 * diff heat map, the key picture and the printed line. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "compare.h"
#include "image.h"

static void make_flat(image_t *img, int w, int h, int r, int g, int b)
{
    char err[256];
    int i;

    if (image_alloc(img, w, h, err, sizeof err) != 0) {
        fprintf(stderr, "image_alloc: %s\n", err);
        exit(2);
    }
    for (i = 0; i < w * h; i++) {
        img->rgb[i * 3] = (uint8_t)r;
        img->rgb[i * 3 + 1] = (uint8_t)g;
        img->rgb[i * 3 + 2] = (uint8_t)b;
    }
}

static uint8_t *px(const image_t *img, int x, int y)
{
    return img->rgb + ((size_t)y * (size_t)img->width + (size_t)x) * 3;
}

static void set_px(image_t *img, int x, int y, int r, int g, int b)
{
    uint8_t *p = px(img, x, y);

    p[0] = (uint8_t)r;
    p[1] = (uint8_t)g;
    p[2] = (uint8_t)b;
}

static void copy_image(image_t *dst, const image_t *src)
{
    make_flat(dst, src->width, src->height, 0, 0, 0);
    memcpy(dst->rgb, src->rgb, (size_t)src->width * (size_t)src->height * 3);
}

static int is_black(const image_t *img, int x, int y)
{
    const uint8_t *p = px(img, x, y);

    return p[0] == 0 && p[1] == 0 && p[2] == 0;
}

/* Pixels of the diff that are non-black, to compare with the mismatches. */
static long count_non_black(const image_t *img)
{
    long n = 0;
    int x, y;

    for (y = 0; y < img->height; y++)
        for (x = 0; x < img->width; x++)
            n += !is_black(img, x, y);
    return n;
}

static int near(double got, double want)
{
    return fabs(got - want) <= 1e-9 * fmax(1.0, fabs(want));
}

static void test_identical(void)
{
    image_t a, b, diff;
    compare_result_t res;
    char err[256] = "";
    int x;

    make_flat(&a, 8, 6, 10, 20, 30);
    for (x = 0; x < 8; x++)
        set_px(&a, x, x % 6, x * 30, 255 - x, x);
    copy_image(&b, &a);

    CHECK_MSG(compare_images(&a, &b, &res, &diff, err, sizeof err) == 0, "%s", err);
    CHECK(res.pixels == 48);
    CHECK(res.mismatched == 0);
    CHECK(res.mismatched_pct == 0.0);
    CHECK(res.max_err == 0);
    CHECK_MSG(isinf(res.psnr) && res.psnr > 0, "psnr=%f", res.psnr);
    CHECK_MSG(res.mae == 0.0, "mae=%f", res.mae);
    CHECK(res.edge_mismatched == 0 && res.interior_mismatched == 0);
    CHECK(diff.width == 8 && diff.height == 6 && diff.rgb != NULL);
    if (diff.rgb != NULL)
        CHECK_MSG(count_non_black(&diff) == 0, "identical images need an all-black diff");

    image_free(&diff);
    image_free(&a);
    image_free(&b);
}

static void test_interior_pixel(void)
{
    image_t a, b, diff;
    compare_result_t res;
    char err[256] = "";
    int x, y, others_black = 1;

    make_flat(&a, 9, 9, 50, 60, 70);
    copy_image(&b, &a);
    set_px(&b, 4, 4, 50, 70, 70); /* G off by 10 */

    CHECK_MSG(compare_images(&a, &b, &res, &diff, err, sizeof err) == 0, "%s", err);
    CHECK(res.pixels == 81);
    CHECK(res.mismatched == 1);
    CHECK_MSG(near(res.mismatched_pct, 100.0 / 81.0), "pct=%f", res.mismatched_pct);
    CHECK_MSG(res.max_err == 10, "max_err=%d", res.max_err);
    CHECK_MSG(res.interior_mismatched == 1 && res.edge_mismatched == 0, "interior=%ld edge=%ld",
              res.interior_mismatched, res.edge_mismatched);
    /* By hand: MSE = 10^2 / (3 * 81) = 100/243, so
     * PSNR = 10 log10(65025 * 243 / 100) = 10 log10(158010.75) = 51.98686634... */
    CHECK_MSG(near(res.psnr, 51.98686634466222), "psnr=%.12f", res.psnr);

    /* Heat map: only the mismatch is lit. */
    CHECK(diff.rgb != NULL && diff.width == 9 && diff.height == 9);
    if (diff.rgb != NULL) {
        CHECK_MSG(!is_black(&diff, 4, 4), "mismatch must be visible in the diff");
        for (y = 0; y < 9; y++)
            for (x = 0; x < 9; x++)
                if ((x != 4 || y != 4) && !is_black(&diff, x, y))
                    others_black = 0;
        CHECK_MSG(others_black, "equal pixels must be black in the diff");
    }
    image_free(&diff);

    /* The edge is judged in A only: with the roles swapped, the odd pixel
     * is now in A and differs from its neighbours, so it is an edge. */
    CHECK(compare_images(&b, &a, &res, NULL, err, sizeof err) == 0);
    CHECK_MSG(res.edge_mismatched == 1 && res.interior_mismatched == 0, "swapped: edge=%ld",
              res.edge_mismatched);

    /* The image border is not an edge. */
    copy_image(&diff, &a); /* reuse as a second B */
    set_px(&diff, 0, 0, 51, 60, 70);
    set_px(&diff, 8, 8, 50, 60, 69);
    CHECK(compare_images(&a, &diff, &res, NULL, err, sizeof err) == 0);
    CHECK_MSG(res.mismatched == 2 && res.interior_mismatched == 2 && res.edge_mismatched == 0,
              "corners: mismatched=%ld interior=%ld", res.mismatched, res.interior_mismatched);
    image_free(&diff);

    image_free(&a);
    image_free(&b);
}

static void test_edges(void)
{
    image_t a, b;
    compare_result_t res;
    char err[256] = "";
    int x, y;

    /* Left half black, right half grey: the edge pixels of A are the
     * columns x = 4 and x = 5. */
    make_flat(&a, 10, 4, 0, 0, 0);
    for (y = 0; y < 4; y++)
        for (x = 5; x < 10; x++)
            set_px(&a, x, y, 200, 200, 200);
    copy_image(&b, &a);
    set_px(&b, 5, 2, 199, 200, 200); /* on the boundary */
    set_px(&b, 3, 1, 0, 0, 2);       /* next to it: 3x3 reaches x = 4 */
    set_px(&b, 2, 1, 0, 1, 0);       /* 3x3 spans x = 1..3: interior */
    set_px(&b, 8, 3, 200, 0, 200);   /* right side, far from it */

    CHECK_MSG(compare_images(&a, &b, &res, NULL, err, sizeof err) == 0, "%s", err);
    CHECK(res.mismatched == 4);
    CHECK_MSG(res.edge_mismatched == 2, "edge=%ld", res.edge_mismatched);
    CHECK_MSG(res.interior_mismatched == 2, "interior=%ld", res.interior_mismatched);
    CHECK_MSG(res.max_err == 200, "max_err=%d", res.max_err);
    CHECK(res.edge_mismatched + res.interior_mismatched == res.mismatched);

    image_free(&a);
    image_free(&b);

    /* Horizontal boundary (rows y = 4 and 5 are edges): the 3x3 window
     * must look at the rows above and below as well. */
    make_flat(&a, 6, 10, 0, 0, 0);
    for (y = 5; y < 10; y++)
        for (x = 0; x < 6; x++)
            set_px(&a, x, y, 90, 90, 90);
    copy_image(&b, &a);
    set_px(&b, 2, 3, 0, 0, 1);    /* edge row below */
    set_px(&b, 3, 6, 90, 90, 91); /* edge row above */
    set_px(&b, 2, 8, 90, 91, 90); /* rows 7..9: interior */
    set_px(&b, 4, 1, 1, 0, 0);    /* rows 0..2: interior */
    CHECK_MSG(compare_images(&a, &b, &res, NULL, err, sizeof err) == 0, "%s", err);
    CHECK(res.mismatched == 4);
    CHECK_MSG(res.edge_mismatched == 2 && res.interior_mismatched == 2, "rows: edge=%ld",
              res.edge_mismatched);
    image_free(&a);
    image_free(&b);

    /* A lone odd pixel at (5,5) makes it and its 4-neighbours edges, but
     * not its diagonal neighbours. */
    make_flat(&a, 11, 11, 30, 30, 30);
    set_px(&a, 5, 5, 31, 30, 30);
    copy_image(&b, &a);
    set_px(&b, 3, 4, 0, 30, 30); /* 3x3 reaches (4,5), a 4-neighbour: edge */
    set_px(&b, 7, 7, 0, 30, 30); /* 3x3 reaches (6,6), only diagonal: interior */
    set_px(&b, 7, 3, 0, 30, 30); /* 3x3 reaches (6,4), only diagonal: interior */
    CHECK_MSG(compare_images(&a, &b, &res, NULL, err, sizeof err) == 0, "%s", err);
    CHECK(res.mismatched == 3);
    CHECK_MSG(res.edge_mismatched == 1 && res.interior_mismatched == 2,
              "4-neighbour rule: edge=%ld interior=%ld", res.edge_mismatched,
              res.interior_mismatched);
    image_free(&a);
    image_free(&b);
}

static void test_max_err_and_psnr(void)
{
    image_t a, b;
    compare_result_t res;
    char err[256] = "";

    make_flat(&a, 4, 4, 250, 10, 100);
    copy_image(&b, &a);
    set_px(&b, 0, 0, 50, 10, 100); /* B below A: the error is absolute */
    set_px(&b, 1, 0, 250, 10, 103);

    CHECK_MSG(compare_images(&a, &b, &res, NULL, err, sizeof err) == 0, "%s", err);
    CHECK_MSG(res.max_err == 200, "max_err=%d", res.max_err);
    CHECK(res.mismatched == 2);
    CHECK_MSG(near(res.mismatched_pct, 12.5), "pct=%f", res.mismatched_pct);
    /* By hand: MSE = (200^2 + 3^2) / (3 * 16) = 40009/48,
     * PSNR = 10 log10(65025 * 48 / 40009) = 18.92163901... */
    CHECK_MSG(near(res.psnr, 18.921639016485372), "psnr=%.12f", res.psnr);
    /* Mean absolute error per channel: (200 + 3) / (3 * 16) = 4.2291666... */
    CHECK_MSG(near(res.mae, 203.0 / 48.0), "mae=%.12f", res.mae);

    /* Worst case: every channel off by 255 gives MSE = 255^2, PSNR 0. */
    image_free(&a);
    image_free(&b);
    make_flat(&a, 3, 2, 0, 0, 0);
    make_flat(&b, 3, 2, 255, 255, 255);
    CHECK(compare_images(&a, &b, &res, NULL, err, sizeof err) == 0);
    CHECK_MSG(near(res.psnr, 0.0), "psnr=%f", res.psnr);
    CHECK_MSG(near(res.mae, 255.0), "mae=%f", res.mae);
    CHECK(res.max_err == 255 && res.mismatched == 6);
    CHECK(near(res.mismatched_pct, 100.0));

    image_free(&a);
    image_free(&b);
}

static void test_size_mismatch(void)
{
    image_t a, b, diff;
    compare_result_t res, before;
    char err[256] = "";

    make_flat(&a, 640, 430, 1, 2, 3);
    make_flat(&b, 160, 120, 1, 2, 3);
    memset(&res, 0x5a, sizeof res);
    before = res;
    diff.width = 77;
    diff.height = 77;
    diff.rgb = NULL;

    CHECK(compare_images(&a, &b, &res, &diff, err, sizeof err) == -1);
    CHECK_MSG(strcmp(err, "size mismatch: 640x430 vs 160x120") == 0, "got \"%s\"", err);
    CHECK_MSG(memcmp(&res, &before, sizeof res) == 0, "failed compare must not touch res");
    CHECK_MSG(diff.rgb == NULL && diff.width == 0 && diff.height == 0,
              "failed compare must leave diff empty");

    CHECK(compare_images(&b, &a, &res, NULL, err, sizeof err) == -1);
    CHECK_MSG(strcmp(err, "size mismatch: 160x120 vs 640x430") == 0, "got \"%s\"", err);

    /* Same pixel count, different shape, is still a mismatch. */
    image_free(&b);
    make_flat(&b, 430, 640, 1, 2, 3);
    CHECK(compare_images(&a, &b, &res, NULL, err, sizeof err) == -1);
    CHECK_MSG(strcmp(err, "size mismatch: 640x430 vs 430x640") == 0, "got \"%s\"", err);

    image_free(&a);
    image_free(&b);

    /* Only one dimension differs. */
    make_flat(&a, 10, 5, 0, 0, 0);
    make_flat(&b, 12, 5, 0, 0, 0);
    CHECK(compare_images(&a, &b, &res, NULL, err, sizeof err) == -1);
    CHECK_MSG(strcmp(err, "size mismatch: 10x5 vs 12x5") == 0, "got \"%s\"", err);
    image_free(&b);
    make_flat(&b, 10, 4, 0, 0, 0);
    CHECK(compare_images(&a, &b, &res, NULL, err, sizeof err) == -1);
    CHECK_MSG(strcmp(err, "size mismatch: 10x5 vs 10x4") == 0, "got \"%s\"", err);
    image_free(&a);
    image_free(&b);
}

static void test_heat_ramp(void)
{
    image_t a, b, diff, b2, diff2;
    compare_result_t res;
    char err[256] = "";
    int x, monotonic = 1, same_by_channel = 1, steps_distinct = 1;

    /* Error x in the red channel at column x. */
    make_flat(&a, 256, 1, 0, 0, 0);
    copy_image(&b, &a);
    for (x = 0; x < 256; x++)
        set_px(&b, x, 0, x, 0, 0);
    CHECK_MSG(compare_images(&a, &b, &res, &diff, err, sizeof err) == 0, "%s", err);
    CHECK(res.mismatched == 255 && res.max_err == 255);
    CHECK(diff.rgb != NULL);
    if (diff.rgb == NULL) {
        image_free(&a);
        image_free(&b);
        return;
    }
    CHECK(is_black(&diff, 0, 0));
    /* The documented scale (fxrt compare --help, docs/ACCURACY.md): 1 dark
     * red (128,0,0), 6 red, 11 yellow, 16 and above white; linear between,
     * so error 2 is 128 + 127/5 = 153.4 -> 153 and error 8 has green
     * 255 * 2/5 = 102. */
    {
        static const struct { int e, r, g, b; } want[] = {
            {1, 128, 0, 0}, {2, 153, 0, 0}, {6, 255, 0, 0}, {8, 255, 102, 0},
            {11, 255, 255, 0}, {13, 255, 255, 102}, {16, 255, 255, 255}, {17, 255, 255, 255},
            {255, 255, 255, 255},
        };
        size_t k;

        for (k = 0; k < sizeof want / sizeof want[0]; k++) {
            const uint8_t *p = px(&diff, want[k].e, 0);

            CHECK_MSG(p[0] == want[k].r && p[1] == want[k].g && p[2] == want[k].b,
                      "error %d -> (%d,%d,%d), want (%d,%d,%d)", want[k].e, p[0], p[1], p[2],
                      want[k].r, want[k].g, want[k].b);
        }
    }
    for (x = 2; x < 256; x++) {
        const uint8_t *p = px(&diff, x, 0);
        const uint8_t *q = px(&diff, x - 1, 0);

        /* Each channel only ever rises: red, then yellow, then white. */
        if (p[0] < q[0] || p[1] < q[1] || p[2] < q[2])
            monotonic = 0;
        /* Up to white, every unit of error has a colour of its own that
         * differs clearly (by 25 or more in a channel) from the last. */
        if (x <= 16 && abs(p[0] - q[0]) + abs(p[1] - q[1]) + abs(p[2] - q[2]) < 25)
            steps_distinct = 0;
    }
    CHECK_MSG(monotonic, "heat ramp must rise with the error");
    CHECK_MSG(steps_distinct, "errors 1..16 must each look clearly different");

    /* The colour depends on the largest channel error, not on which
     * channel it is in, and smaller errors in other channels do not add. */
    copy_image(&b2, &a);
    for (x = 0; x < 256; x++)
        set_px(&b2, x, 0, x / 2, 0, x);
    CHECK(compare_images(&b2, &a, &res, &diff2, err, sizeof err) == 0);
    CHECK(diff2.rgb != NULL);
    if (diff2.rgb != NULL)
        for (x = 0; x < 256; x++)
            if (memcmp(px(&diff, x, 0), px(&diff2, x, 0), 3) != 0)
                same_by_channel = 0;
    CHECK_MSG(same_by_channel, "heat colour must follow the max channel error");

    image_free(&diff2);
    image_free(&b2);
    image_free(&diff);
    image_free(&a);
    image_free(&b);
}

/* The 5x4 key map used below, A = 7 and B = 9 (key values are arbitrary):
 *   A A A B B
 *   A A A B B
 *   A A A A A
 *   A A A A A
 * Near pixels, by the definition (an 8-neighbour, inside the image, with
 * another key), worked out by hand:
 *   . . N N .     (4,0) is B with only B neighbours once the border clips
 *   . . N N N     its window: far
 *   . . N N N     (2,2) sees B only diagonally, at (3,1): near
 *   . . . . .
 * 8 near, 12 far. */
static const uint32_t keys54[20] = {
    7, 7, 7, 9, 9,
    7, 7, 7, 9, 9,
    7, 7, 7, 7, 7,
    7, 7, 7, 7, 7,
};
static const char near54[4][6] = {"..NN.", "..NNN", "..NNN", "....."};

static void test_key_near(void)
{
    int x, y, agree = 1;
    uint32_t one = 5, row[4] = {1, 1, 2, 2}, col[3] = {4, 4, 4};

    for (y = 0; y < 4; y++)
        for (x = 0; x < 5; x++)
            if (compare_key_near(keys54, 5, 4, x, y) != (near54[y][x] == 'N')) {
                agree = 0;
                CHECK_MSG(0, "(%d,%d): near=%d, by hand %c", x, y, compare_key_near(keys54, 5, 4, x, y),
                          near54[y][x]);
            }
    CHECK_MSG(agree, "5x4 near map");

    /* Degenerate sizes: one pixel has no neighbours; a row of 4 with a
     * boundary between columns 1 and 2 has its two middle pixels near. */
    CHECK(compare_key_near(&one, 1, 1, 0, 0) == 0);
    CHECK(compare_key_near(row, 4, 1, 0, 0) == 0);
    CHECK(compare_key_near(row, 4, 1, 1, 0) == 1);
    CHECK(compare_key_near(row, 4, 1, 2, 0) == 1);
    CHECK(compare_key_near(row, 4, 1, 3, 0) == 0);
    CHECK(compare_key_near(col, 1, 3, 0, 1) == 0);
    /* The background key is a key like any other. */
    col[2] = 0xFFFF00u;
    CHECK(compare_key_near(col, 1, 3, 0, 0) == 0);
    CHECK(compare_key_near(col, 1, 3, 0, 1) == 1);
    CHECK(compare_key_near(col, 1, 3, 0, 2) == 1);
}

/* The split on the 5x4 map, every expected value counted by hand. */
static void test_keyed_split(void)
{
    image_t a, b, diff;
    compare_result_t res;
    char err[256] = "";

    make_flat(&a, 5, 4, 100, 100, 100);
    copy_image(&b, &a);
    set_px(&b, 0, 0, 101, 100, 100); /* far, error 1 */
    set_px(&b, 1, 3, 100, 98, 100);  /* far, error 2 (B below A) */
    set_px(&b, 4, 0, 100, 100, 103); /* far (the clipped corner), error 3 */
    set_px(&b, 2, 2, 105, 100, 100); /* near (diagonal only), error 5 */
    set_px(&b, 3, 0, 100, 99, 100);  /* near, error 1 */

    CHECK_MSG(compare_images_keyed(&a, &b, keys54, &res, &diff, err, sizeof err) == 0, "%s", err);
    CHECK(res.pixels == 20 && res.mismatched == 5 && res.max_err == 5);
    /* within 1: all but the errors 2, 3, 5 -> 17 of 20; within 2: 18. */
    CHECK_MSG(res.within1 == 17 && res.within2 == 18, "within1=%ld within2=%ld", res.within1, res.within2);
    CHECK(near(res.within1_pct, 85.0) && near(res.within2_pct, 90.0));
    CHECK_MSG(res.near_pixels == 8 && res.far_pixels == 12, "near=%ld far=%ld", res.near_pixels, res.far_pixels);
    /* far: 12 pixels with errors 1, 2, 3 -> within1 10, within2 11, max 3 */
    CHECK_MSG(res.far_within1 == 10 && res.far_within2 == 11 && res.far_max_err == 3,
              "far: %ld %ld %d", res.far_within1, res.far_within2, res.far_max_err);
    CHECK(near(res.far_within1_pct, 1000.0 / 12.0) && near(res.far_within2_pct, 1100.0 / 12.0));
    /* near: 8 pixels with errors 5, 1 -> within1 7, within2 7, max 5 */
    CHECK_MSG(res.near_within1 == 7 && res.near_within2 == 7 && res.near_max_err == 5,
              "near: %ld %ld %d", res.near_within1, res.near_within2, res.near_max_err);
    CHECK(near(res.near_within1_pct, 87.5) && near(res.near_within2_pct, 87.5));
    /* Sum of squares 1 + 4 + 9 + 25 + 1 = 40 over 60 channels:
     * PSNR = 10 log10(65025 * 60 / 40) = 10 log10(97537.5) = 49.8917161992... */
    CHECK_MSG(near(res.psnr, 49.891716199235915), "psnr=%.12f", res.psnr);
    /* The keys do not change the old fields: the same as without them. */
    {
        compare_result_t plain;

        CHECK(compare_images(&a, &b, &plain, NULL, err, sizeof err) == 0);
        CHECK(plain.mismatched == res.mismatched && plain.edge_mismatched == res.edge_mismatched &&
              plain.interior_mismatched == res.interior_mismatched && plain.psnr == res.psnr);
        CHECK(plain.within1 == 17 && plain.within2 == 18);
        /* Without keys every pixel is far, and the near set is empty. */
        CHECK(plain.near_pixels == 0 && plain.far_pixels == 20);
        CHECK(plain.far_within1 == 17 && plain.far_within2 == 18 && plain.far_max_err == 5);
        CHECK(plain.near_max_err == 0 && plain.near_within1_pct == 100.0);
    }
    /* Heat map: equal near pixels dark blue, equal far pixels black,
     * mismatches their heat colour wherever they are. */
    CHECK(diff.rgb != NULL);
    if (diff.rgb != NULL) {
        int x, y, ok = 1;

        for (y = 0; y < 4; y++) {
            for (x = 0; x < 5; x++) {
                const uint8_t *p = px(&diff, x, y);
                const uint8_t *q = px(&b, x, y);
                int changed = q[0] != 100 || q[1] != 100 || q[2] != 100;

                if (changed)
                    ok &= p[0] >= COMPARE_HEAT_MIN_RED;
                else if (near54[y][x] == 'N')
                    ok &= p[0] == 0 && p[1] == 0 && p[2] == COMPARE_HEAT_NEAR_B;
                else
                    ok &= is_black(&diff, x, y);
            }
        }
        CHECK_MSG(ok, "keyed heat map");
        CHECK(px(&diff, 3, 0)[0] == 128 && px(&diff, 3, 0)[2] == 0); /* near, error 1 */
    }
    image_free(&diff);
    image_free(&a);
    image_free(&b);
}

/* A pixel is within k only when every channel is: errors of exactly 1, 2
 * and 3 in different channels of one pixel. */
static void test_thresholds(void)
{
    image_t a, b;
    compare_result_t res;
    char err[256] = "";

    make_flat(&a, 6, 1, 50, 50, 50);
    copy_image(&b, &a);
    set_px(&b, 0, 0, 51, 49, 51); /* 1, 1, 1: within 1 */
    set_px(&b, 1, 0, 52, 50, 51); /* 2, 0, 1: within 2 only */
    set_px(&b, 2, 0, 50, 48, 48); /* 0, 2, 2: within 2 only */
    set_px(&b, 3, 0, 50, 50, 53); /* 0, 0, 3: neither */
    set_px(&b, 4, 0, 49, 52, 47); /* 1, 2, 3: neither */
    /* (5,0) equal: within both */
    CHECK_MSG(compare_images(&a, &b, &res, NULL, err, sizeof err) == 0, "%s", err);
    CHECK_MSG(res.within1 == 2 && res.within2 == 4, "within1=%ld within2=%ld", res.within1, res.within2);
    CHECK(res.max_err == 3 && res.mismatched == 5);
    /* Sum of squares 3 + 5 + 8 + 9 + 14 = 39 over 18 channels:
     * PSNR = 10 log10(65025 * 18 / 39) = 44.7718... */
    CHECK_MSG(near(res.psnr, 10.0 * log10(65025.0 * 18.0 / 39.0)), "psnr=%f", res.psnr);
    /* Absolute errors 3 + 3 + 4 + 3 + 6 = 19 over 18 channels. */
    CHECK_MSG(near(res.mae, 19.0 / 18.0), "mae=%f", res.mae);
    image_free(&a);
    image_free(&b);
}

/* Random key maps and images against a second, differently organised
 * computation: every pair of 8-adjacent pixels with different keys makes
 * both near; then the counts from plain loops. */
static void test_random_split(void)
{
    uint64_t rng = 0x9e3779b97f4a7c15ull;
    int iter, bad = 0;

    for (iter = 0; iter < 300; iter++) {
        int w = 1 + (int)(check_rng_next(&rng) % 9), h = 1 + (int)(check_rng_next(&rng) % 9);
        int nkeys = 1 + (int)(check_rng_next(&rng) % 3);
        uint32_t keys[81];
        unsigned char nearm[81];
        image_t a, b;
        compare_result_t res;
        char err[256] = "";
        long n_near = 0, w1 = 0, w2 = 0, f1 = 0, f2 = 0, n1 = 0, n2 = 0;
        int fmax = 0, nmax = 0, i, j;

        for (i = 0; i < w * h; i++) {
            keys[i] = (uint32_t)(check_rng_next(&rng) % (uint64_t)nkeys) << 8;
            nearm[i] = 0;
        }
        for (i = 0; i < w * h; i++)
            for (j = 0; j < w * h; j++) {
                int dx = i % w - j % w, dy = i / w - j / w;

                if (i != j && abs(dx) <= 1 && abs(dy) <= 1 && keys[i] != keys[j])
                    nearm[i] = nearm[j] = 1;
            }
        make_flat(&a, w, h, 0, 0, 0);
        make_flat(&b, w, h, 0, 0, 0);
        for (i = 0; i < w * h * 3; i++) {
            a.rgb[i] = (uint8_t)(check_rng_next(&rng) % 256);
            b.rgb[i] = (uint8_t)(a.rgb[i] ^ (uint8_t)(check_rng_next(&rng) % 4)); /* differences 0..3 */
            if (a.rgb[i] == 255 && b.rgb[i] < 252)
                b.rgb[i] = 255;
        }
        for (i = 0; i < w * h; i++) {
            int e = 0, c;

            for (c = 0; c < 3; c++)
                e = abs(a.rgb[i * 3 + c] - b.rgb[i * 3 + c]) > e ? abs(a.rgb[i * 3 + c] - b.rgb[i * 3 + c]) : e;
            w1 += e <= 1;
            w2 += e <= 2;
            if (nearm[i]) {
                n_near++;
                n1 += e <= 1;
                n2 += e <= 2;
                nmax = e > nmax ? e : nmax;
            } else {
                f1 += e <= 1;
                f2 += e <= 2;
                fmax = e > fmax ? e : fmax;
            }
        }
        if (compare_images_keyed(&a, &b, keys, &res, NULL, err, sizeof err) != 0 ||
            res.near_pixels != n_near || res.far_pixels != w * h - n_near || res.within1 != w1 ||
            res.within2 != w2 || res.far_within1 != f1 || res.far_within2 != f2 || res.near_within1 != n1 ||
            res.near_within2 != n2 || res.far_max_err != fmax || res.near_max_err != nmax) {
            if (bad++ < 3)
                CHECK_MSG(0, "random %dx%d case %d: near %ld/%ld", w, h, iter, res.near_pixels, n_near);
        }
        image_free(&a);
        image_free(&b);
    }
    CHECK_MSG(bad == 0, "%d of 300 random key maps disagree", bad);
}

/* fxrt render --keys: the background black, other keys never black, and a
 * key differing by one light or one object id looks different. */
static void test_keys_image(void)
{
    static uint32_t keys[64 * 256 + 1];
    image_t img;
    char err[256] = "";
    int i, visible = 1, differ = 1;

    for (i = 0; i < 64 * 256; i++)
        keys[i] = (uint32_t)i; /* id = i >> 8, mask = i & 255 */
    keys[64 * 256] = 0xFFFF00u;
    CHECK_MSG(compare_keys_image(keys, 64 * 256 + 1, 1, 0xFFFF00u, &img, err, sizeof err) == 0, "%s", err);
    CHECK(img.width == 64 * 256 + 1 && img.height == 1);
    CHECK(is_black(&img, 64 * 256, 0));
    for (i = 0; i < 64 * 256; i++) {
        const uint8_t *p = px(&img, i, 0);
        int bit;

        if (p[0] < 64 || p[1] < 64 || p[2] < 64)
            visible = 0;
        for (bit = 0; bit < 14; bit++) {
            int j = i ^ (1 << bit);

            if (memcmp(p, px(&img, j, 0), 3) == 0)
                differ = 0;
        }
    }
    CHECK_MSG(visible, "every key's colour has each channel >= 64");
    CHECK_MSG(differ, "keys one light or one id bit apart must differ in colour");
    image_free(&img);
}

static char *print_to_string(const compare_result_t *res)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *fp = open_memstream(&buf, &len);

    if (fp == NULL)
        return NULL;
    compare_print(fp, res);
    if (fclose(fp) != 0) {
        free(buf);
        return NULL;
    }
    return buf;
}

static void test_print(void)
{
    compare_result_t res;
    image_t a, b;
    char err[256] = "";
    char *s;

    memset(&res, 0, sizeof res);
    res.pixels = 19200;
    res.mismatched = 12;
    res.mismatched_pct = 0.0625;
    res.max_err = 3;
    res.psnr = 48.126;
    res.mae = 0.041666; /* printed to 4 decimals: 0.0417 */
    res.edge_mismatched = 10;
    res.interior_mismatched = 2;
    res.within1 = 19195;
    res.within2 = 19199;
    res.near_pixels = 300;
    res.far_pixels = 18900;
    res.far_within1 = 18897;
    res.far_within2 = 18900;
    res.far_max_err = 2;
    res.near_max_err = 3;
    res.near_within1 = 298;
    res.near_within2 = 299;
    s = print_to_string(&res);
    CHECK(s != NULL);
    /* 19195/19200 = 99.973958..%, 19199/19200 = 99.994791..%,
     * 18897/18900 = 99.984126..%, 298/300 = 99.3333..%, 299/300 = 99.6666..%
     * (rounded down, not to nearest) */
    if (s != NULL)
        CHECK_MSG(strcmp(s, "pixels=19200 mismatched=12 mismatched_pct=0.0625 max_err=3 "
                            "psnr=48.13 edge_mismatched=10 interior_mismatched=2 "
                            "within1_pct=99.9739 within2_pct=99.9947 near_pixels=300 far_pixels=18900 "
                            "far_within1_pct=99.9841 far_within2_pct=100.0000 far_max_err=2 near_max_err=3 "
                            "near_within1_pct=99.3333 near_within2_pct=99.6666 mae=0.0417\n") == 0,
                  "got \"%s\"", s);
    free(s);

    /* Identical images print psnr=inf. */
    make_flat(&a, 160, 120, 9, 9, 9);
    make_flat(&b, 160, 120, 9, 9, 9);
    CHECK(compare_images(&a, &b, &res, NULL, err, sizeof err) == 0);
    s = print_to_string(&res);
    CHECK(s != NULL);
    if (s != NULL)
        CHECK_MSG(strcmp(s, "pixels=19200 mismatched=0 mismatched_pct=0.0000 max_err=0 "
                            "psnr=inf edge_mismatched=0 interior_mismatched=0 "
                            "within1_pct=100.0000 within2_pct=100.0000 near_pixels=0 far_pixels=19200 "
                            "far_within1_pct=100.0000 far_within2_pct=100.0000 far_max_err=0 near_max_err=0 "
                            "near_within1_pct=100.0000 near_within2_pct=100.0000 mae=0.0000\n") == 0,
                  "got \"%s\"", s);
    free(s);

    /* And a real comparison, end to end. */
    set_px(&b, 80, 60, 9, 19, 9);
    CHECK(compare_images(&a, &b, &res, NULL, err, sizeof err) == 0);
    s = print_to_string(&res);
    CHECK(s != NULL);
    /* MSE = 100 / 57600, PSNR = 10 log10(65025 * 576) = 75.7350...;
     * 19199/19200 = 99.99479..% */
    if (s != NULL)
        CHECK_MSG(strcmp(s, "pixels=19200 mismatched=1 mismatched_pct=0.0052 max_err=10 "
                            "psnr=75.74 edge_mismatched=0 interior_mismatched=1 "
                            "within1_pct=99.9947 within2_pct=99.9947 near_pixels=0 far_pixels=19200 "
                            "far_within1_pct=99.9947 far_within2_pct=99.9947 far_max_err=10 near_max_err=0 "
                            "near_within1_pct=100.0000 near_within2_pct=100.0000 mae=0.0002\n") == 0,
                  "got \"%s\"", s);
    free(s);
    image_free(&a);
    image_free(&b);

    /* One pixel off in two million: 99.99995 %, which %.4f would round to
     * 100.0000; rounded down it is 99.9999. */
    make_flat(&a, 2000, 1000, 9, 9, 9);
    make_flat(&b, 2000, 1000, 9, 9, 9);
    set_px(&b, 1999, 999, 9, 9, 12);
    CHECK(compare_images(&a, &b, &res, NULL, err, sizeof err) == 0);
    s = print_to_string(&res);
    CHECK(s != NULL);
    if (s != NULL)
        CHECK_MSG(strstr(s, " within1_pct=99.9999 within2_pct=99.9999 ") != NULL &&
                      strstr(s, " far_within2_pct=99.9999 ") != NULL,
                  "got \"%s\"", s);
    free(s);
    image_free(&a);
    image_free(&b);
}

int main(void)
{
    test_identical();
    test_interior_pixel();
    test_edges();
    test_max_err_and_psnr();
    test_size_mismatch();
    test_heat_ramp();
    test_key_near();
    test_keyed_split();
    test_thresholds();
    test_random_split();
    test_keys_image();
    test_print();
    return check_report("test_compare");
}
