/* fxrt-oled: the host side of the OLED work, on the same dithering code the
 * firmware runs (dither.c).
 *
 *   fxrt-oled grey IN -o OUT [--dither none|bayer4|bayer8|fs] [--scale N]
 *       IN (PNG or PPM, RGB) through dither.c, rows top first as the board
 *       does. OUT: .bin = the SSD0323's display RAM for the frame (per row
 *       (W + 1) / 2 bytes, the left pixel in the high nibble); .png/.ppm =
 *       the levels as greys (n * 17, QEMU's rendering), each pixel an N x N
 *       block (default 1).
 *   fxrt-oled ideal IN -o OUT.png|OUT.ppm [--scale N]
 *       the full-precision grey Y / 256 (dither.h), rounded to 8 bits: what
 *       the methods approximate, for viewing.
 *   fxrt-oled unscale DUMP -o OUT [--magnify M] [--scale N]
 *       a QEMU screendump of the SSD0323 (each pixel drawn as an M x M
 *       block, M = 4 in QEMU 7.2's hw/display/ssd0323.c) back to levels:
 *       every block must be one colour, a grey n * 17 (else exit 2 naming
 *       the first bad block). OUT as for grey.
 *   fxrt-oled magnify IN -o OUT.png|OUT.ppm --scale N
 *       IN with each pixel an N x N block (for sheets beside screendumps).
 *   fxrt-oled measure [--markdown] SET=IMAGE...
 *       each method's error against the ideal grey, in 8-bit grey units
 *       (display level n is 17 n, the ideal Y / 256): mean absolute error
 *       and PSNR (peak 255) of the picture as it is, and after a 3x3 and a
 *       5x5 box blur of both pictures (what the eye integrates at a
 *       distance; at the border the mean of the pixels inside), and the
 *       bias (mean signed error). Per image, and per SET over all its
 *       images' pixels.
 * Exit status: 0, or 2 for bad input or usage (one line on stderr). */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dither.h"
#include "image.h"

#define ERRLEN 512

static void die(const char *fmt, ...) __attribute__((format(printf, 1, 2), noreturn));
static void die(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fputs("fxrt-oled: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
    exit(2);
}

static void *xmalloc(size_t n)
{
    void *p = malloc(n ? n : 1);
    if (!p)
        die("out of memory");
    return p;
}

static void read_image(const char *path, image_t *img)
{
    char err[ERRLEN];
    if (image_read(path, img, err, sizeof err) != 0)
        die("%s", err);
}

static int ends_with(const char *s, const char *suffix)
{
    size_t n = strlen(s), m = strlen(suffix);
    return n >= m && strcmp(s + n - m, suffix) == 0;
}

/* Levels (one byte per pixel, 0..15) of a width x height frame. */
typedef struct {
    int width, height;
    uint8_t *level;
} levels_t;

/* Write levels as display RAM (.bin) or as a grey image magnified scale
 * times. */
static void write_levels(const char *path, const levels_t *lv, int scale)
{
    char err[ERRLEN];
    if (ends_with(path, ".bin")) {
        FILE *f = fopen(path, "wb");
        if (!f)
            die("%s: %s", path, strerror(errno));
        int rb = (lv->width + 1) / 2;
        uint8_t *row = xmalloc((size_t)rb);
        for (int y = 0; y < lv->height; y++) {
            memset(row, 0, (size_t)rb);
            for (int x = 0; x < lv->width; x++)
                row[x / 2] |= (uint8_t)(lv->level[(size_t)y * lv->width + x] << (x & 1 ? 0 : 4));
            if (fwrite(row, 1, (size_t)rb, f) != (size_t)rb)
                die("%s: write failed", path);
        }
        free(row);
        if (fclose(f) != 0)
            die("%s: write failed", path);
        return;
    }
    image_t img;
    if (image_alloc(&img, lv->width * scale, lv->height * scale, err, sizeof err) != 0)
        die("%s", err);
    for (int y = 0; y < img.height; y++)
        for (int x = 0; x < img.width; x++) {
            uint8_t v = (uint8_t)(17 * lv->level[(size_t)(y / scale) * lv->width + x / scale]);
            memset(&img.rgb[3 * ((size_t)y * img.width + x)], v, 3);
        }
    if (image_write(path, &img, err, sizeof err) != 0)
        die("%s", err);
    image_free(&img);
}

/* IN through dither.c with a method: levels. */
static void dither_image(const image_t *in, oled_dither_method_t m, levels_t *lv)
{
    lv->width = in->width;
    lv->height = in->height;
    lv->level = xmalloc((size_t)in->width * in->height);
    int32_t *err = xmalloc(sizeof(int32_t) * (size_t)in->width);
    int rb = (in->width + 1) / 2;
    uint8_t *packed = xmalloc((size_t)rb);
    oled_dither_t d;
    if (!oled_dither_begin(&d, m, in->width, err))
        die("dither: bad method");
    for (int y = 0; y < in->height; y++) {
        oled_dither_row(&d, y, &in->rgb[(size_t)3 * in->width * y], packed);
        for (int x = 0; x < in->width; x++)
            lv->level[(size_t)y * in->width + x] = (uint8_t)(x & 1 ? packed[x / 2] & 15 : packed[x / 2] >> 4);
    }
    free(packed);
    free(err);
}

static oled_dither_method_t method_named(const char *s)
{
    for (int m = 0; m < OLED_DITHER_METHODS; m++)
        if (strcmp(s, oled_dither_name((oled_dither_method_t)m)) == 0)
            return (oled_dither_method_t)m;
    die("unknown dither method '%s' (none, bayer4, bayer8, fs)", s);
}

static int positive(const char *opt, const char *s)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (errno || *end || v < 1 || v > 64)
        die("%s wants an integer 1..64, not '%s'", opt, s);
    return (int)v;
}

/* grey, ideal, unscale, magnify: IN -o OUT and options. */
static int cmd_convert(const char *cmd, int argc, char **argv)
{
    const char *in = NULL, *out = NULL;
    oled_dither_method_t m = OLED_DITHER_FS;
    int scale = 1, magnify = 4;
    for (int i = 0; i < argc; i++) {
        int more = i + 1 < argc;
        if ((!strcmp(argv[i], "-o") || !strcmp(argv[i], "--output")) && more)
            out = argv[++i];
        else if (!strcmp(argv[i], "--dither") && more && !strcmp(cmd, "grey"))
            m = method_named(argv[++i]);
        else if (!strcmp(argv[i], "--scale") && more)
            scale = positive("--scale", argv[++i]);
        else if (!strcmp(argv[i], "--magnify") && more && !strcmp(cmd, "unscale"))
            magnify = positive("--magnify", argv[++i]);
        else if (argv[i][0] == '-' || in)
            die("%s: unexpected argument '%s' (see fxrt-oled --help)", cmd, argv[i]);
        else
            in = argv[i];
    }
    if (!in || !out)
        die("%s: needs an input and -o OUT (see fxrt-oled --help)", cmd);
    image_t img;
    read_image(in, &img);
    levels_t lv = {0, 0, NULL};
    if (!strcmp(cmd, "magnify")) {
        char err[ERRLEN];
        image_t big;
        if (image_alloc(&big, img.width * scale, img.height * scale, err, sizeof err) != 0)
            die("%s", err);
        for (int y = 0; y < big.height; y++)
            for (int x = 0; x < big.width; x++)
                memcpy(&big.rgb[3 * ((size_t)y * big.width + x)],
                       &img.rgb[3 * ((size_t)(y / scale) * img.width + x / scale)], 3);
        if (image_write(out, &big, err, sizeof err) != 0)
            die("%s", err);
        image_free(&big);
        image_free(&img);
        return 0;
    }
    if (!strcmp(cmd, "grey")) {
        dither_image(&img, m, &lv);
    } else if (!strcmp(cmd, "unscale")) {
        if (img.width % magnify || img.height % magnify)
            die("%s: size not a multiple of the magnification", in);
        lv.width = img.width / magnify;
        lv.height = img.height / magnify;
        lv.level = xmalloc((size_t)lv.width * lv.height);
        for (int y = 0; y < img.height; y++)
            for (int x = 0; x < img.width; x++) {
                const uint8_t *p = &img.rgb[3 * ((size_t)y * img.width + x)];
                const uint8_t *c = &img.rgb[3 * ((size_t)(y - y % magnify) * img.width + (x - x % magnify))];
                if (p[0] != c[0] || p[1] != c[1] || p[2] != c[2] || p[0] != p[1] || p[1] != p[2] || p[0] % 17) {
                    char where[96];
                    snprintf(where, sizeof where, "pixel (%d, %d) of block (%d, %d)", x, y, x / magnify, y / magnify);
                    die("%s: %s is not the block's grey n * 17", in, where);
                }
                lv.level[(size_t)(y / magnify) * lv.width + x / magnify] = (uint8_t)(p[0] / 17);
            }
    } else { /* ideal: Y / 256 rounded, written as an image */
        char err[ERRLEN];
        image_t g;
        if (image_alloc(&g, img.width * scale, img.height * scale, err, sizeof err) != 0)
            die("%s", err);
        for (int y = 0; y < g.height; y++)
            for (int x = 0; x < g.width; x++) {
                int32_t lum = oled_luma(&img.rgb[3 * ((size_t)(y / scale) * img.width + x / scale)]);
                memset(&g.rgb[3 * ((size_t)y * g.width + x)], (lum + 128) >> 8, 3);
            }
        if (image_write(out, &g, err, sizeof err) != 0)
            die("%s", err);
        image_free(&g);
        image_free(&img);
        return 0;
    }
    write_levels(out, &lv, scale);
    free(lv.level);
    image_free(&img);
    return 0;
}

/* --- measure ---------------------------------------------------------- */

/* Box mean of radius r (a (2r + 1)^2 square, fewer pixels at the border)
 * of a w x h picture of doubles, by summed-area table. */
static void box_blur(const double *in, double *out, int w, int h, int r)
{
    double *sat = xmalloc(sizeof(double) * (size_t)(w + 1) * (h + 1));
    for (int x = 0; x <= w; x++)
        sat[x] = 0;
    for (int y = 1; y <= h; y++) {
        double run = 0;
        sat[(size_t)y * (w + 1)] = 0;
        for (int x = 1; x <= w; x++) {
            run += in[(size_t)(y - 1) * w + x - 1];
            sat[(size_t)y * (w + 1) + x] = sat[(size_t)(y - 1) * (w + 1) + x] + run;
        }
    }
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            int x0 = x - r < 0 ? 0 : x - r, x1 = x + r + 1 > w ? w : x + r + 1;
            int y0 = y - r < 0 ? 0 : y - r, y1 = y + r + 1 > h ? h : y + r + 1;
            double s = sat[(size_t)y1 * (w + 1) + x1] - sat[(size_t)y0 * (w + 1) + x1] -
                       sat[(size_t)y1 * (w + 1) + x0] + sat[(size_t)y0 * (w + 1) + x0];
            out[(size_t)y * w + x] = s / ((x1 - x0) * (y1 - y0));
        }
    free(sat);
}

#define BLURS 3 /* radius 0 (none), 1 (3x3), 2 (5x5) */

typedef struct {
    double abs[BLURS], sq[BLURS], sum; /* sums over pixels */
    double n;
} acc_t;

static void accumulate(const image_t *img, oled_dither_method_t m, acc_t *a)
{
    size_t n = (size_t)img->width * img->height;
    levels_t lv;
    dither_image(img, m, &lv);
    double *ideal = xmalloc(sizeof(double) * n), *shown = xmalloc(sizeof(double) * n);
    double *bi = xmalloc(sizeof(double) * n), *bs = xmalloc(sizeof(double) * n);
    for (size_t i = 0; i < n; i++) {
        ideal[i] = oled_luma(&img->rgb[3 * i]) / 256.0;
        shown[i] = 17.0 * lv.level[i];
        a->sum += shown[i] - ideal[i];
    }
    for (int r = 0; r < BLURS; r++) {
        box_blur(ideal, bi, img->width, img->height, r);
        box_blur(shown, bs, img->width, img->height, r);
        for (size_t i = 0; i < n; i++) {
            double e = bs[i] - bi[i];
            a->abs[r] += fabs(e);
            a->sq[r] += e * e;
        }
    }
    a->n += (double)n;
    free(lv.level);
    free(ideal);
    free(shown);
    free(bi);
    free(bs);
}

static void fmt_psnr(char *buf, size_t len, double sq, double n)
{
    if (sq == 0)
        snprintf(buf, len, "inf");
    else
        snprintf(buf, len, "%.2f", 10.0 * log10(255.0 * 255.0 / (sq / n)));
}

static void print_row(int markdown, const char *set, const char *image, oled_dither_method_t m, const acc_t *a)
{
    char p[BLURS][16];
    for (int r = 0; r < BLURS; r++)
        fmt_psnr(p[r], sizeof p[r], a->sq[r], a->n);
    if (markdown)
        printf("| %s | %s | %.2f | %s | %.2f | %s | %.2f | %s | %+.2f |\n", image ? image : set,
               oled_dither_name(m), a->abs[0] / a->n, p[0], a->abs[1] / a->n, p[1], a->abs[2] / a->n, p[2],
               a->sum / a->n);
    else
        printf("set=%s image=%s method=%s pixels=%.0f mae=%.4f psnr=%s mae3=%.4f psnr3=%s mae5=%.4f psnr5=%s "
               "bias=%.4f\n",
               set, image ? image : "all", oled_dither_name(m), a->n, a->abs[0] / a->n, p[0], a->abs[1] / a->n, p[1],
               a->abs[2] / a->n, p[2], a->sum / a->n);
}

static int cmd_measure(int argc, char **argv)
{
    int markdown = 0, nin = 0;
    char **set = xmalloc(sizeof(char *) * (size_t)(argc + 1)), **path = xmalloc(sizeof(char *) * (size_t)(argc + 1));
    for (int i = 0; i < argc; i++) {
        char *eq = strchr(argv[i], '=');
        if (!strcmp(argv[i], "--markdown"))
            markdown = 1;
        else if (argv[i][0] == '-' || !eq || eq == argv[i] || !eq[1])
            die("measure: expected SET=IMAGE, not '%s'", argv[i]);
        else {
            *eq = 0;
            set[nin] = argv[i];
            path[nin++] = eq + 1;
        }
    }
    if (!nin)
        die("measure: no images (SET=IMAGE...)");
    const char *hdr = "| %s | method | MAE | PSNR dB | MAE 3x3 | PSNR 3x3 | MAE 5x5 | PSNR 5x5 | bias |\n"
                      "|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
    /* Per set: the sets in order of first appearance, summed over their images. */
    if (markdown)
        printf(hdr, "set");
    for (int i = 0; i < nin; i++) {
        int first = 1;
        for (int j = 0; j < i; j++)
            first &= strcmp(set[i], set[j]) != 0;
        if (!first)
            continue;
        for (int m = 0; m < OLED_DITHER_METHODS; m++) {
            acc_t a;
            memset(&a, 0, sizeof a);
            for (int j = i; j < nin; j++) {
                if (strcmp(set[i], set[j]))
                    continue;
                image_t img;
                read_image(path[j], &img);
                accumulate(&img, (oled_dither_method_t)m, &a);
                image_free(&img);
            }
            print_row(markdown, set[i], NULL, (oled_dither_method_t)m, &a);
        }
    }
    if (markdown)
        printf("\n");
    if (markdown)
        printf(hdr, "image");
    for (int i = 0; i < nin; i++) {
        image_t img;
        read_image(path[i], &img);
        /* The file's base name without its extension names the row. */
        const char *slash = strrchr(path[i], '/');
        char base[256];
        snprintf(base, sizeof base, "%s", slash ? slash + 1 : path[i]);
        char *dot = strrchr(base, '.');
        if (dot && dot != base)
            *dot = 0;
        for (int m = 0; m < OLED_DITHER_METHODS; m++) {
            acc_t a;
            memset(&a, 0, sizeof a);
            accumulate(&img, (oled_dither_method_t)m, &a);
            print_row(markdown, set[i], base, (oled_dither_method_t)m, &a);
        }
        image_free(&img);
    }
    free(set);
    free(path);
    return 0;
}

static const char usage[] =
    "usage: fxrt-oled grey IN -o OUT.bin|OUT.png|OUT.ppm [--dither none|bayer4|bayer8|fs] [--scale N]\n"
    "       fxrt-oled ideal IN -o OUT.png|OUT.ppm [--scale N]\n"
    "       fxrt-oled unscale DUMP -o OUT.bin|OUT.png|OUT.ppm [--magnify M] [--scale N]\n"
    "       fxrt-oled magnify IN -o OUT.png|OUT.ppm --scale N\n"
    "       fxrt-oled measure [--markdown] SET=IMAGE...\n"
    "RGB images to the SSD0323's 4-bit greys with the firmware's dithering (firmware/oled/dither.c),\n"
    "QEMU screendumps of the display back to levels, and each method's error against the ideal grey.\n"
    "OUT.bin is the display RAM: (W + 1) / 2 bytes a row, the left pixel in the high nibble.\n";

int main(int argc, char **argv)
{
    if (argc < 2 || !strcmp(argv[1], "-h") || !strcmp(argv[1], "--help")) {
        fputs(usage, argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    if (!strcmp(argv[1], "grey") || !strcmp(argv[1], "ideal") || !strcmp(argv[1], "unscale") ||
        !strcmp(argv[1], "magnify"))
        return cmd_convert(argv[1], argc - 2, argv + 2);
    if (!strcmp(argv[1], "measure"))
        return cmd_measure(argc - 2, argv + 2);
    die("unknown command '%s' (grey, ideal, unscale, magnify, measure)", argv[1]);
}
