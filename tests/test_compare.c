/* Tests for host/compare.c: counts, edge/interior split, max_err, PSNR,
 * the diff heat map and the printed line. */
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

    /* Worst case: every channel off by 255 gives MSE = 255^2, PSNR 0. */
    image_free(&a);
    image_free(&b);
    make_flat(&a, 3, 2, 0, 0, 0);
    make_flat(&b, 3, 2, 255, 255, 255);
    CHECK(compare_images(&a, &b, &res, NULL, err, sizeof err) == 0);
    CHECK_MSG(near(res.psnr, 0.0), "psnr=%f", res.psnr);
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
    int x, monotonic = 1, all_visible = 1, same_by_channel = 1;

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
    CHECK_MSG(px(&diff, 1, 0)[0] == 96 && px(&diff, 1, 0)[1] == 0 && px(&diff, 1, 0)[2] == 0,
              "error 1 -> (%d,%d,%d), want (96,0,0)", px(&diff, 1, 0)[0], px(&diff, 1, 0)[1],
              px(&diff, 1, 0)[2]);
    CHECK_MSG(px(&diff, 255, 0)[0] == 255 && px(&diff, 255, 0)[1] == 255 &&
                  px(&diff, 255, 0)[2] == 255,
              "error 255 must be white");
    for (x = 1; x < 256; x++) {
        const uint8_t *p = px(&diff, x, 0);

        if (p[0] < 96)
            all_visible = 0;
        if (x > 1) {
            const uint8_t *q = px(&diff, x - 1, 0);

            /* Each channel only ever rises: red, then yellow, then white. */
            if (p[0] < q[0] || p[1] < q[1] || p[2] < q[2])
                monotonic = 0;
        }
    }
    CHECK_MSG(all_visible, "every mismatch needs at least a dark red");
    CHECK_MSG(monotonic, "heat ramp must rise with the error");
    /* Small errors must be told apart, not all drawn the same dark red. */
    CHECK_MSG(px(&diff, 4, 0)[0] > px(&diff, 1, 0)[0] + 30, "error 4 too close to error 1");
    /* Midway the ramp has passed through red into yellow. */
    CHECK_MSG(px(&diff, 128, 0)[0] == 255 && px(&diff, 128, 0)[1] > 128,
              "error 128 -> (%d,%d,%d)", px(&diff, 128, 0)[0], px(&diff, 128, 0)[1],
              px(&diff, 128, 0)[2]);

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

    res.pixels = 19200;
    res.mismatched = 12;
    res.mismatched_pct = 0.0625;
    res.max_err = 3;
    res.psnr = 48.126;
    res.edge_mismatched = 10;
    res.interior_mismatched = 2;
    s = print_to_string(&res);
    CHECK(s != NULL);
    if (s != NULL)
        CHECK_MSG(strcmp(s, "pixels=19200 mismatched=12 mismatched_pct=0.0625 max_err=3 "
                            "psnr=48.13 edge_mismatched=10 interior_mismatched=2\n") == 0,
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
                            "psnr=inf edge_mismatched=0 interior_mismatched=0\n") == 0,
                  "got \"%s\"", s);
    free(s);

    /* And a real comparison, end to end. */
    set_px(&b, 80, 60, 9, 19, 9);
    CHECK(compare_images(&a, &b, &res, NULL, err, sizeof err) == 0);
    s = print_to_string(&res);
    CHECK(s != NULL);
    /* MSE = 100 / 57600, PSNR = 10 log10(65025 * 576) = 75.7350... */
    if (s != NULL)
        CHECK_MSG(strcmp(s, "pixels=19200 mismatched=1 mismatched_pct=0.0052 max_err=10 "
                            "psnr=75.74 edge_mismatched=0 interior_mismatched=1\n") == 0,
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
    test_print();
    return check_report("test_compare");
}
