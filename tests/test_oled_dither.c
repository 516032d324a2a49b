/* Tests for firmware/oled/dither.c (the OLED's RGB -> 4-bit grey
 * conversion, shared by the firmware and build/fxrt-oled): every expected
 * value is computed here another way (doubles, the Bayer recursion, a
 * textbook two-row Floyd-Steinberg). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "dither.h"

#define W 128
#define H 64

/* Rec. 601 in doubles; the integer weights are within 0.46 grey units of
 * it (255 * (77/256 - 0.299) = 0.454 at pure red), checked exhaustively. */
static void test_luma(void)
{
    double worst = 0;
    for (int r = 0; r < 256; r++)
        for (int g = 0; g < 256; g++)
            for (int b = 0; b < 256; b++) {
                uint8_t p[3] = {(uint8_t)r, (uint8_t)g, (uint8_t)b};
                double e = fabs(oled_luma(p) / 256.0 - (0.299 * r + 0.587 * g + 0.114 * b));
                if (e > worst)
                    worst = e;
                CHECK_SWEEP(oled_luma(p) >= 0 && oled_luma(p) <= OLED_LUMA_MAX, "luma(%d,%d,%d)", r, g, b);
            }
    CHECK_MSG(worst < 0.455, "worst luma error %.4f grey units", worst);
    for (int v = 0; v < 256; v++) {
        uint8_t p[3] = {(uint8_t)v, (uint8_t)v, (uint8_t)v};
        CHECK_SWEEP(oled_luma(p) == 256 * v, "grey %d", v);
    }
    CHECK(OLED_LUMA_STEP * OLED_LEVEL_MAX == OLED_LUMA_MAX);
}

/* M_1 = [0], M_2n(x, y) = 4 M_n(x mod n, y mod n) + M_2(x div n, y div n)
 * with M_2 = [[0, 2], [3, 1]] (rows y). */
static uint32_t bayer_rec(uint32_t x, uint32_t y, uint32_t n)
{
    static const uint32_t m2[2][2] = {{0, 2}, {3, 1}};
    if (n == 1)
        return 0;
    uint32_t h = n / 2;
    return 4 * bayer_rec(x % h, y % h, h) + m2[y / h][x / h];
}

static void test_bayer(void)
{
    for (uint32_t bits = 1; bits <= 3; bits++) {
        uint32_t n = 1u << bits, seen[64] = {0}, bad = 0;
        for (uint32_t y = 0; y < n; y++)
            for (uint32_t x = 0; x < n; x++) {
                uint32_t m = oled_bayer(x, y, bits);
                bad += m != bayer_rec(x, y, n) || m >= n * n;
                if (m < 64)
                    seen[m]++;
            }
        uint32_t perm = 1;
        for (uint32_t i = 0; i < n * n; i++)
            perm &= seen[i] == 1;
        CHECK_MSG(bad == 0, "%ux%u matrix: %u entries differ from the recursion", n, n, bad);
        CHECK_MSG(perm, "%ux%u matrix is not a permutation of 0..%u", n, n, n * n - 1);
    }
    /* The 4x4 matrix as the literature prints it (row 0: 0 8 2 10). */
    CHECK(oled_bayer(1, 0, 2) == 8 && oled_bayer(0, 1, 2) == 12 && oled_bayer(3, 3, 2) == 5);
}

static uint8_t level_at(const uint8_t *packed, int x)
{
    return (uint8_t)(x & 1 ? packed[x / 2] & 15 : packed[x / 2] >> 4);
}

/* Dither a whole frame of rgb (W x H) into lv (one level per pixel). */
static void frame(oled_dither_method_t m, const uint8_t *rgb, int w, int h, uint8_t *lv)
{
    static int32_t err[W];
    uint8_t packed[(W + 1) / 2];
    oled_dither_t d;
    CHECK(oled_dither_begin(&d, m, w, err));
    for (int y = 0; y < h; y++) {
        oled_dither_row(&d, y, rgb + 3 * w * y, packed);
        for (int x = 0; x < w; x++)
            lv[y * w + x] = level_at(packed, x);
    }
}

static void fill_random(uint8_t *rgb, int n, uint64_t *s)
{
    for (int i = 0; i < 3 * n; i++)
        rgb[i] = (uint8_t)(check_rng_next(s) >> 56);
}

/* Rounding and the ordered methods pixel by pixel against their formulas
 * in doubles (exact here: every value is a ratio of small integers). */
static void test_pointwise(void)
{
    static uint8_t rgb[3 * W * H], lv[W * H];
    uint64_t s = 0x6f6c6564u;
    for (int round = 0; round < 20; round++) {
        fill_random(rgb, W * H, &s);
        for (int m = OLED_DITHER_NONE; m <= OLED_DITHER_BAYER8; m++) {
            frame((oled_dither_method_t)m, rgb, W, H, lv);
            int bad = 0;
            for (int y = 0; y < H; y++)
                for (int x = 0; x < W; x++) {
                    double v = oled_luma(&rgb[3 * (y * W + x)]) / (double)OLED_LUMA_STEP, want;
                    if (m == OLED_DITHER_NONE) {
                        want = floor(v + 0.5);
                    } else {
                        uint32_t bits = m == OLED_DITHER_BAYER4 ? 2 : 3, n = 1u << bits;
                        want = floor(v + (bayer_rec((uint32_t)x % n, (uint32_t)y % n, n) + 0.5) / (n * n));
                    }
                    bad += lv[y * W + x] != want || want > OLED_LEVEL_MAX;
                }
            CHECK_MSG(bad == 0, "%s: %d pixels differ from the formula", oled_dither_name((oled_dither_method_t)m), bad);
        }
    }
}

/* A flat field of every luma value a grey can have: the ordered methods'
 * tiles average to Y / 4352 within half a threshold step (1/32, 1/128);
 * the displayable greys (17 n) come out as exactly n by every method. */
static void test_flat(void)
{
    static uint8_t rgb[3 * W * H], lv[W * H];
    int bad_tile = 0, bad_exact = 0;
    double fs_worst = 0;
    for (int v = 0; v < 256; v++) {
        memset(rgb, v, sizeof rgb);
        double want = 256.0 * v / OLED_LUMA_STEP;
        for (int m = 0; m < OLED_DITHER_METHODS; m++) {
            frame((oled_dither_method_t)m, rgb, W, H, lv);
            double sum = 0;
            int tile = m == OLED_DITHER_BAYER8 ? 8 : 4, exact = 1;
            for (int i = 0; i < W * H; i++) {
                sum += lv[i];
                exact &= lv[i] == v / 17;
            }
            if (v % 17 == 0)
                bad_exact += !exact;
            if (m == OLED_DITHER_BAYER4 || m == OLED_DITHER_BAYER8) {
                double t = 0;
                for (int y = 0; y < tile; y++)
                    for (int x = 0; x < tile; x++)
                        t += lv[y * W + x];
                bad_tile += fabs(t / (tile * tile) - want) > 0.5 / (tile * tile) + 1e-12;
            }
            if (m == OLED_DITHER_FS && fabs(sum / (W * H) - want) > fs_worst)
                fs_worst = fabs(sum / (W * H) - want);
        }
    }
    CHECK_MSG(bad_tile == 0, "%d flat fields whose Bayer tile mean is off", bad_tile);
    CHECK_MSG(bad_exact == 0, "%d (method, display grey) pairs not shown exactly", bad_exact);
    /* Error diffusion keeps the mean but for what leaves at the edges:
     * at most half a step per row, 1/256 of a level over 128 columns. */
    CHECK_MSG(fs_worst <= 1.0 / 256, "Floyd-Steinberg flat-field mean off by %.5f levels", fs_worst);
}

/* The largest |error| fs_reference saw: dither.c's bound is half a step. */
static int32_t fs_worst_err;

/* Textbook Floyd-Steinberg over the whole frame with a full error array,
 * in the same integer shares (3/16, 5/16, 1/16 truncated toward zero, the
 * rest to the right), against the one-row-buffer version. */
static void fs_reference(const uint8_t *rgb, int w, int h, uint8_t *lv)
{
    int32_t *e = calloc((size_t)(w + 2) * (h + 1), sizeof *e); /* column x at x + 1 */
#define E(x, y) e[(size_t)(y) * (w + 2) + (x) + 1]
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            int32_t want = oled_luma(&rgb[3 * (y * w + x)]) + E(x, y);
            int32_t n = (int32_t)floor(want / (double)OLED_LUMA_STEP + 0.5);
            n = n < 0 ? 0 : n > OLED_LEVEL_MAX ? OLED_LEVEL_MAX : n;
            lv[y * w + x] = (uint8_t)n;
            int32_t err = want - n * OLED_LUMA_STEP;
            if (abs(err) > fs_worst_err)
                fs_worst_err = abs(err);
            int32_t e3 = err * 3 / 16, e5 = err * 5 / 16, e1 = err / 16;
            if (x + 1 < w)
                E(x + 1, y) += err - e3 - e5 - e1;
            if (x > 0)
                E(x - 1, y + 1) += e3;
            E(x, y + 1) += e5;
            if (x + 1 < w)
                E(x + 1, y + 1) += e1;
        }
#undef E
    free(e);
}

static void test_fs(void)
{
    static uint8_t rgb[3 * W * H], lv[W * H], ref[W * H];
    uint64_t s = 0x46532d31u;
    int bad = 0;
    for (int round = 0; round < 50; round++) {
        int w = round < 10 ? 1 + round : W; /* narrow frames too: a one-pixel row has no neighbours */
        fill_random(rgb, w * H, &s);
        if (round % 3 == 1) /* smooth gradients, where the error runs long */
            for (int y = 0; y < H; y++)
                for (int x = 0; x < w; x++)
                    memset(&rgb[3 * (y * w + x)], (x * 255) / (w > 1 ? w - 1 : 1), 3);
        frame(OLED_DITHER_FS, rgb, w, H, lv);
        fs_reference(rgb, w, H, ref);
        bad += memcmp(lv, ref, (size_t)(w * H)) != 0;
    }
    CHECK_MSG(bad == 0, "%d of 50 frames differ from the textbook Floyd-Steinberg", bad);
    CHECK_MSG(fs_worst_err <= OLED_LUMA_STEP / 2, "an error of %d luma units (bound %d)", (int)fs_worst_err,
              OLED_LUMA_STEP / 2);
}

static void test_api(void)
{
    oled_dither_t d;
    int32_t err[3];
    CHECK(!oled_dither_begin(&d, OLED_DITHER_FS, 3, NULL));
    CHECK(!oled_dither_begin(&d, OLED_DITHER_NONE, 0, err));
    CHECK(!oled_dither_begin(&d, (oled_dither_method_t)4, 3, err));
    CHECK(!oled_dither_begin(&d, (oled_dither_method_t)-1, 3, err));
    CHECK(oled_dither_begin(&d, OLED_DITHER_NONE, 3, NULL));
    /* Three pixels, white, black, white: bytes 0xF0, 0xF0 (the last low
     * nibble empty), the left pixel in the high nibble. */
    const uint8_t rgb[9] = {255, 255, 255, 0, 0, 0, 255, 255, 255};
    uint8_t packed[2] = {0xAA, 0xAA};
    oled_dither_row(&d, 0, rgb, packed);
    CHECK_MSG(packed[0] == 0xF0 && packed[1] == 0xF0, "packed %02x %02x", packed[0], packed[1]);
    CHECK(oled_dither_name(OLED_DITHER_FS) && !strcmp(oled_dither_name(OLED_DITHER_FS), "fs"));
    CHECK(oled_dither_name(OLED_DITHER_METHODS) == NULL);
}

int main(void)
{
    test_luma();
    test_bayer();
    test_pointwise();
    test_flat();
    test_fs();
    test_api();
    return check_report("test_oled_dither");
}
