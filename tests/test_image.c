/* Tests for host/image.c: PNG/PPM round trips, PNG colour-type conversion,
 * rejection of malformed files, and the atomic-write guarantees. */
#include <dirent.h>
#include <errno.h>
#include <png.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "check.h"
#include "image.h"

static char g_dir[64];

static void tpath(char *buf, size_t n, const char *name)
{
    snprintf(buf, n, "%s/%s", g_dir, name);
}

static int starts_with(const char *s, const char *prefix)
{
    return strncmp(s, prefix, strlen(prefix)) == 0;
}

static int contains(const char *s, const char *needle)
{
    return strstr(s, needle) != NULL;
}

static int write_bytes(const char *path, const void *data, size_t len)
{
    FILE *fp = fopen(path, "wb");
    int ok;

    if (fp == NULL)
        return -1;
    ok = fwrite(data, 1, len, fp) == len;
    if (fclose(fp) != 0)
        ok = 0;
    return ok ? 0 : -1;
}

/* Whole file into a malloc'ed buffer (NULL on failure). */
static unsigned char *read_bytes(const char *path, size_t *len)
{
    FILE *fp = fopen(path, "rb");
    unsigned char *buf = NULL;
    size_t cap = 0, n = 0;

    if (fp == NULL)
        return NULL;
    for (;;) {
        size_t got;

        if (n == cap) {
            unsigned char *nb;

            cap = cap ? cap * 2 : 4096;
            nb = realloc(buf, cap);
            if (nb == NULL) {
                free(buf);
                fclose(fp);
                return NULL;
            }
            buf = nb;
        }
        got = fread(buf + n, 1, cap - n, fp);
        n += got;
        if (got == 0)
            break;
    }
    fclose(fp);
    *len = n;
    return buf;
}

/* Entries in the test directory other than . and .., so a test can prove
 * that a failed write left neither the target nor a temporary file. */
static int count_entries(void)
{
    DIR *d = opendir(g_dir);
    struct dirent *e;
    int n = 0;

    if (d == NULL)
        return -1;
    while ((e = readdir(d)) != NULL) {
        if (strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0)
            n++;
    }
    closedir(d);
    return n;
}

static int has_entry_containing(const char *needle)
{
    DIR *d = opendir(g_dir);
    struct dirent *e;
    int found = 0;

    if (d == NULL)
        return 0;
    while ((e = readdir(d)) != NULL) {
        if (strstr(e->d_name, needle) != NULL)
            found = 1;
    }
    closedir(d);
    return found;
}

static void remove_test_dir(void)
{
    DIR *d = opendir(g_dir);
    struct dirent *e;
    char p[512];

    if (d == NULL)
        return;
    while ((e = readdir(d)) != NULL) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        tpath(p, sizeof p, e->d_name);
        if (remove(p) != 0)
            fprintf(stderr, "cleanup: cannot remove %s: %s\n", p, strerror(errno));
    }
    closedir(d);
    if (rmdir(g_dir) != 0)
        fprintf(stderr, "cleanup: cannot remove %s: %s\n", g_dir, strerror(errno));
}

/* Deterministic content where neighbouring pixels and channels differ,
 * so swapped channels, rows or an off-by-one stride show up. */
static int make_pattern(image_t *img, int w, int h, unsigned seed)
{
    char err[256];
    size_t i;
    unsigned s = seed;

    if (image_alloc(img, w, h, err, sizeof err) != 0)
        return -1;
    for (i = 0; i < (size_t)w * (size_t)h * 3; i++) {
        s = s * 1103515245u + 12345u;
        img->rgb[i] = (uint8_t)(s >> 16);
    }
    return 0;
}

static int same_image(const image_t *a, const image_t *b)
{
    return a->width == b->width && a->height == b->height && a->rgb != NULL && b->rgb != NULL &&
           memcmp(a->rgb, b->rgb, (size_t)a->width * (size_t)a->height * 3) == 0;
}

/* A PNG written straight through libpng, for colour types and depths that
 * image_write never produces. data holds height rows of rowbytes each. */
typedef struct {
    int width, height, bit_depth, color_type, interlace;
    const unsigned char *data;
    size_t rowbytes;
    const png_color *palette;
    int npalette;
} raw_png_t;

static int write_raw_png_body(png_structp png, png_infop info, FILE *fp, const raw_png_t *r,
                              png_bytep *rows)
{
    if (setjmp(png_jmpbuf(png)))
        return -1;
    png_init_io(png, fp);
    png_set_IHDR(png, info, (png_uint_32)r->width, (png_uint_32)r->height, r->bit_depth,
                 r->color_type, r->interlace, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    if (r->palette != NULL)
        png_set_PLTE(png, info, r->palette, r->npalette);
    png_write_info(png, info);
    png_write_image(png, rows);
    png_write_end(png, NULL);
    return 0;
}

static int write_raw_png(const char *path, const raw_png_t *r)
{
    png_structp png;
    png_infop info;
    png_bytep *rows;
    FILE *fp;
    int y, rc;

    rows = malloc(sizeof *rows * (size_t)r->height);
    if (rows == NULL)
        return -1;
    for (y = 0; y < r->height; y++)
        rows[y] = (png_bytep)(uintptr_t)(r->data + (size_t)y * r->rowbytes);
    fp = fopen(path, "wb");
    if (fp == NULL) {
        free(rows);
        return -1;
    }
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    info = png ? png_create_info_struct(png) : NULL;
    rc = (png && info) ? write_raw_png_body(png, info, fp, r, rows) : -1;
    png_destroy_write_struct(png ? &png : NULL, info ? &info : NULL);
    if (fclose(fp) != 0)
        rc = -1;
    free(rows);
    return rc;
}

/* Expect image_read to fail with exactly "PATH: " + msg. */
static void expect_read_error(const char *name, const char *msg)
{
    char p[512], err[512], want[1024];
    image_t img;
    int rc;

    tpath(p, sizeof p, name);
    snprintf(want, sizeof want, "%s: %s", p, msg);
    err[0] = '\0';
    rc = image_read(p, &img, err, sizeof err);
    CHECK_MSG(rc == -1, "%s: rc=%d", name, rc);
    CHECK_MSG(strcmp(err, want) == 0, "got \"%s\", want \"%s\"", err, want);
    CHECK_MSG(img.rgb == NULL && img.width == 0 && img.height == 0,
              "%s: failed read must leave an empty image", name);
    image_free(&img);
}

/* Expect failure whose message names the file and contains needle. */
static void expect_read_error_containing(const char *name, const char *needle)
{
    char p[512], err[512];
    image_t img;
    int rc;

    tpath(p, sizeof p, name);
    err[0] = '\0';
    rc = image_read(p, &img, err, sizeof err);
    CHECK_MSG(rc == -1, "%s: rc=%d", name, rc);
    CHECK_MSG(starts_with(err, p) && starts_with(err + strlen(p), ": "),
              "%s: error \"%s\" must start with the path", name, err);
    CHECK_MSG(contains(err, needle), "%s: error \"%s\" lacks \"%s\"", name, err, needle);
    CHECK(img.rgb == NULL);
    image_free(&img);
}

static void write_ppm_file(const char *name, const char *header, const void *pixels,
                           size_t npixels_bytes)
{
    char p[512];
    size_t hl = strlen(header);
    unsigned char *buf = malloc(hl + npixels_bytes + 1);

    tpath(p, sizeof p, name);
    CHECK(buf != NULL);
    if (buf == NULL)
        return;
    memcpy(buf, header, hl);
    if (npixels_bytes > 0)
        memcpy(buf + hl, pixels, npixels_bytes);
    CHECK_MSG(write_bytes(p, buf, hl + npixels_bytes) == 0, "cannot write %s", p);
    free(buf);
}

/* ------------------------------------------------------------------ */

static void test_alloc(void)
{
    char err[256];
    image_t img;
    size_t i, zeros = 0;

    CHECK(image_alloc(&img, 7, 5, err, sizeof err) == 0);
    CHECK(img.width == 7 && img.height == 5 && img.rgb != NULL);
    for (i = 0; i < 7 * 5 * 3; i++)
        zeros += img.rgb[i] == 0;
    CHECK_MSG(zeros == 7 * 5 * 3, "image_alloc must zero the pixels");
    image_free(&img);
    CHECK(img.rgb == NULL && img.width == 0);
    image_free(&img); /* freeing twice is harmless */

    err[0] = '\0';
    CHECK(image_alloc(&img, 0, 5, err, sizeof err) == -1);
    CHECK_MSG(err[0] != '\0', "zero width needs a message");
    CHECK(img.rgb == NULL);
    CHECK(image_alloc(&img, 5, -1, err, sizeof err) == -1);
    CHECK(img.rgb == NULL);
}

static void round_trip(const char *name, int w, int h, unsigned seed)
{
    char p[512], err[512];
    image_t src, got;
    int rc;

    tpath(p, sizeof p, name);
    CHECK(make_pattern(&src, w, h, seed) == 0);
    err[0] = '\0';
    rc = image_write(p, &src, err, sizeof err);
    CHECK_MSG(rc == 0, "write %s: %s", name, err);
    rc = image_read(p, &got, err, sizeof err);
    CHECK_MSG(rc == 0, "read %s: %s", name, err);
    CHECK_MSG(same_image(&src, &got), "%s: pixels differ after round trip", name);
    image_free(&src);
    image_free(&got);
}

static void test_round_trips(void)
{
    char p[512], q[512], err[512];
    unsigned char *bytes;
    size_t len = 0;
    image_t src, got;

    round_trip("rt.png", 37, 23, 1);
    round_trip("rt.ppm", 37, 23, 2);
    round_trip("one.png", 1, 1, 3);
    round_trip("one.ppm", 1, 1, 4);
    round_trip("tall.png", 1, 300, 5);
    round_trip("upper.PNG", 5, 4, 6);
    round_trip("mixed.Ppm", 5, 4, 7);

    /* The extension picks the written format, whatever its case. */
    tpath(p, sizeof p, "upper.PNG");
    bytes = read_bytes(p, &len);
    CHECK(bytes != NULL && len > 8 && png_sig_cmp(bytes, 0, 8) == 0);
    free(bytes);

    /* PPM layout exactly as P6 readers expect it. */
    CHECK(make_pattern(&src, 3, 2, 8) == 0);
    tpath(p, sizeof p, "exact.ppm");
    CHECK_MSG(image_write(p, &src, err, sizeof err) == 0, "%s", err);
    bytes = read_bytes(p, &len);
    CHECK(bytes != NULL);
    if (bytes != NULL) {
        const char *hdr = "P6\n3 2\n255\n";
        size_t hl = strlen(hdr);

        CHECK_MSG(len == hl + 18, "ppm size %zu", len);
        CHECK(len >= hl && memcmp(bytes, hdr, hl) == 0);
        CHECK(len == hl + 18 && memcmp(bytes + hl, src.rgb, 18) == 0);
    }
    free(bytes);

    /* The reader trusts magic bytes, not names: a PNG called .ppm. */
    tpath(p, sizeof p, "rt.png");
    tpath(q, sizeof q, "disguised.ppm");
    CHECK(rename(p, q) == 0);
    CHECK_MSG(image_read(q, &got, err, sizeof err) == 0, "%s", err);
    CHECK(got.width == 37 && got.height == 23);
    image_free(&got);

    /* Overwriting an existing file replaces it. */
    tpath(p, sizeof p, "exact.ppm");
    src.rgb[0] ^= 0xff;
    CHECK_MSG(image_write(p, &src, err, sizeof err) == 0, "%s", err);
    CHECK_MSG(image_read(p, &got, err, sizeof err) == 0, "%s", err);
    CHECK(same_image(&src, &got));
    image_free(&got);
    image_free(&src);

    CHECK_MSG(!has_entry_containing(".tmp."), "a successful write left a temporary file");
}

static void test_png_colour_types(void)
{
    char p[512], err[512];
    image_t img;
    int x, y, ok;

    /* RGBA: alpha is dropped, not composited. */
    {
        static const unsigned char rgba[2 * 3 * 4] = {
            10, 20, 30, 255, 40, 50, 60, 0,  70, 80, 90, 128,
            1,  2,  3,  7,   250, 251, 252, 255, 0, 0, 0, 0,
        };
        raw_png_t r = {3, 2, 8, PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE, rgba, 12, NULL, 0};

        tpath(p, sizeof p, "rgba.png");
        CHECK(write_raw_png(p, &r) == 0);
        CHECK_MSG(image_read(p, &img, err, sizeof err) == 0, "rgba: %s", err);
        CHECK(img.width == 3 && img.height == 2);
        ok = img.rgb != NULL;
        for (y = 0; ok && y < 2; y++)
            for (x = 0; x < 3; x++)
                if (memcmp(img.rgb + (y * 3 + x) * 3, rgba + (y * 3 + x) * 4, 3) != 0)
                    ok = 0;
        CHECK_MSG(ok, "RGBA pixels must keep their RGB and lose alpha");
        image_free(&img);
    }

    /* 8-bit grey: each value becomes R = G = B. */
    {
        unsigned char grey[4 * 3];
        raw_png_t r = {4, 3, 8, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE, grey, 4, NULL, 0};

        for (x = 0; x < 12; x++)
            grey[x] = (unsigned char)(x * 21 + 3);
        tpath(p, sizeof p, "grey.png");
        CHECK(write_raw_png(p, &r) == 0);
        CHECK_MSG(image_read(p, &img, err, sizeof err) == 0, "grey: %s", err);
        CHECK(img.width == 4 && img.height == 3);
        ok = img.rgb != NULL;
        for (x = 0; ok && x < 12; x++)
            if (img.rgb[x * 3] != grey[x] || img.rgb[x * 3 + 1] != grey[x] ||
                img.rgb[x * 3 + 2] != grey[x])
                ok = 0;
        CHECK_MSG(ok, "grey pixels must expand to R=G=B");
        image_free(&img);
    }

    /* 1-bit grey: packed bits expand to 0 and 255. */
    {
        static const unsigned char bits[2 * 2] = {0xA5, 0x80, 0x0F, 0x40}; /* 10 px wide */
        raw_png_t r = {10, 2, 1, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE, bits, 2, NULL, 0};

        tpath(p, sizeof p, "grey1.png");
        CHECK(write_raw_png(p, &r) == 0);
        CHECK_MSG(image_read(p, &img, err, sizeof err) == 0, "grey1: %s", err);
        CHECK(img.width == 10 && img.height == 2);
        ok = img.rgb != NULL;
        for (y = 0; ok && y < 2; y++)
            for (x = 0; x < 10; x++) {
                int bit = (bits[y * 2 + x / 8] >> (7 - x % 8)) & 1;

                if (img.rgb[(y * 10 + x) * 3 + 1] != (bit ? 255 : 0))
                    ok = 0;
            }
        CHECK_MSG(ok, "1-bit grey must expand to 0/255");
        image_free(&img);
    }

    /* Palette. */
    {
        static const png_color pal[3] = {{255, 0, 0}, {0, 128, 0}, {12, 34, 56}};
        static const unsigned char idx[3 * 1] = {2, 0, 1};
        static const unsigned char want[9] = {12, 34, 56, 255, 0, 0, 0, 128, 0};
        raw_png_t r = {3, 1, 8, PNG_COLOR_TYPE_PALETTE, PNG_INTERLACE_NONE, idx, 3, pal, 3};

        tpath(p, sizeof p, "pal.png");
        CHECK(write_raw_png(p, &r) == 0);
        CHECK_MSG(image_read(p, &img, err, sizeof err) == 0, "palette: %s", err);
        CHECK(img.width == 3 && img.height == 1 && img.rgb != NULL &&
              memcmp(img.rgb, want, 9) == 0);
        image_free(&img);
    }

    /* 16-bit RGB: big-endian samples reduced to 8 bits. */
    {
        static const unsigned char rgb16[2 * 6] = {0xFF, 0xFF, 0x00, 0x00, 0x80, 0x80,
                                                   0x12, 0x34, 0xFF, 0x00, 0x00, 0x01};
        raw_png_t r = {2, 1, 16, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, rgb16, 12, NULL, 0};

        tpath(p, sizeof p, "rgb16.png");
        CHECK(write_raw_png(p, &r) == 0);
        CHECK_MSG(image_read(p, &img, err, sizeof err) == 0, "rgb16: %s", err);
        CHECK(img.width == 2 && img.height == 1 && img.rgb != NULL);
        if (img.rgb != NULL) {
            CHECK(img.rgb[0] == 255 && img.rgb[1] == 0 && img.rgb[2] == 128);
            CHECK(img.rgb[3] == 18 && img.rgb[5] == 0);
            CHECK(img.rgb[4] == 254 || img.rgb[4] == 255); /* 0xFF00: scaled or stripped */
        }
        image_free(&img);
    }

    /* Adam7 interlacing is undone. */
    {
        image_t src;
        raw_png_t r;

        CHECK(make_pattern(&src, 13, 11, 9) == 0);
        r.width = 13;
        r.height = 11;
        r.bit_depth = 8;
        r.color_type = PNG_COLOR_TYPE_RGB;
        r.interlace = PNG_INTERLACE_ADAM7;
        r.data = src.rgb;
        r.rowbytes = 13 * 3;
        r.palette = NULL;
        r.npalette = 0;
        tpath(p, sizeof p, "adam7.png");
        CHECK(write_raw_png(p, &r) == 0);
        CHECK_MSG(image_read(p, &img, err, sizeof err) == 0, "adam7: %s", err);
        CHECK_MSG(same_image(&src, &img), "interlaced PNG decoded wrongly");
        image_free(&img);
        image_free(&src);
    }
}

static void test_ppm_header(void)
{
    char p[512], err[512];
    image_t img;

    /* Comments anywhere between fields; pixel bytes that look like
     * whitespace or '#' right after the single separator are data. */
    {
        static const unsigned char px[6] = {'\n', ' ', '#', '\t', 200, '\r'};

        write_ppm_file("comment.ppm", "P6\n# made by hand\n2 # width\n#another\n 1\n255\n", px, 6);
        tpath(p, sizeof p, "comment.ppm");
        CHECK_MSG(image_read(p, &img, err, sizeof err) == 0, "comment: %s", err);
        CHECK(img.width == 2 && img.height == 1 && img.rgb != NULL &&
              memcmp(img.rgb, px, 6) == 0);
        image_free(&img);
    }
    /* Tabs, CRs and runs of whitespace as separators. */
    {
        static const unsigned char px[3] = {1, 2, 3};

        write_ppm_file("ws.ppm", "P6\t\r\n 1  \t1\r\n255 ", px, 3);
        tpath(p, sizeof p, "ws.ppm");
        CHECK_MSG(image_read(p, &img, err, sizeof err) == 0, "ws: %s", err);
        CHECK(img.width == 1 && img.height == 1 && img.rgb != NULL && memcmp(img.rgb, px, 3) == 0);
        image_free(&img);
    }
    /* Trailing data after the raster is ignored (multi-image P6 streams). */
    {
        static const unsigned char px[6] = {9, 8, 7, 6, 5, 4};

        write_ppm_file("trail.ppm", "P6 1 1 255\n", px, 6);
        tpath(p, sizeof p, "trail.ppm");
        CHECK_MSG(image_read(p, &img, err, sizeof err) == 0, "trail: %s", err);
        CHECK(img.width == 1 && img.rgb != NULL && img.rgb[0] == 9 && img.rgb[2] == 7);
        image_free(&img);
    }
    /* The largest accepted size is accepted. */
    {
        size_t n = (size_t)IMAGE_MAX_DIM * 3;
        unsigned char *px = calloc(n, 1);
        char hdr[64];

        CHECK(px != NULL);
        if (px != NULL) {
            px[n - 1] = 77;
            snprintf(hdr, sizeof hdr, "P6 %d 1 255\n", IMAGE_MAX_DIM);
            write_ppm_file("maxdim.ppm", hdr, px, n);
            tpath(p, sizeof p, "maxdim.ppm");
            CHECK_MSG(image_read(p, &img, err, sizeof err) == 0, "maxdim: %s", err);
            CHECK(img.width == IMAGE_MAX_DIM && img.height == 1 && img.rgb != NULL &&
                  img.rgb[n - 1] == 77);
            image_free(&img);
            free(px);
        }
    }
}

static void test_read_rejects(void)
{
    static const unsigned char px[10] = {0};
    char p[512], big[64];
    unsigned char garbage[300];
    unsigned s = 99;
    size_t i;

    tpath(p, sizeof p, "garbage.png");
    for (i = 0; i < sizeof garbage; i++) {
        s = s * 1103515245u + 12345u;
        garbage[i] = (unsigned char)(s >> 16);
    }
    garbage[0] = 'G'; /* not 'P', not 0x89 */
    CHECK(write_bytes(p, garbage, sizeof garbage) == 0);
    expect_read_error("garbage.png", "not a PNG or PPM file");

    write_ppm_file("text.ppm", "hello, this is not an image\n", NULL, 0);
    expect_read_error("text.ppm", "not a PNG or PPM file");
    write_ppm_file("empty.png", "", NULL, 0);
    expect_read_error("empty.png", "not a PNG or PPM file");
    write_ppm_file("short.png", "\x89PN", NULL, 0);
    expect_read_error("short.png", "not a PNG or PPM file");

    {
        char want[128];

        snprintf(want, sizeof want, "cannot open: %s", strerror(ENOENT));
        expect_read_error("does-not-exist.png", want);
    }

    write_ppm_file("trunc.ppm", "P6\n4 4\n255\n", px, sizeof px);
    expect_read_error("trunc.ppm", "truncated pixel data");
    write_ppm_file("nopix.ppm", "P6 4 4 255", NULL, 0);
    expect_read_error("nopix.ppm", "truncated pixel data");
    write_ppm_file("trunchdr.ppm", "P6 4", NULL, 0);
    expect_read_error_containing("trunchdr.ppm", "truncated PPM header");

    write_ppm_file("max16.ppm", "P6\n2 2\n65535\n", px, sizeof px);
    expect_read_error("max16.ppm", "unsupported PPM maxval 65535 (only 255 is supported)");
    write_ppm_file("max15.ppm", "P6 1 1 15\n", px, 3);
    expect_read_error_containing("max15.ppm", "maxval 15");
    write_ppm_file("max0.ppm", "P6 1 1 0\n", px, 3);
    expect_read_error_containing("max0.ppm", "maxval 0");

    write_ppm_file("alpha.ppm", "P6\nabc 2\n255\n", px, sizeof px);
    expect_read_error_containing("alpha.ppm", "width is not a number");
    write_ppm_file("suffix.ppm", "P6 12abc 3 255\n", px, sizeof px);
    expect_read_error_containing("suffix.ppm", "width is not a number");
    write_ppm_file("neg.ppm", "P6 2 -3 255\n", px, sizeof px);
    expect_read_error_containing("neg.ppm", "height is not a number");
    write_ppm_file("maxtext.ppm", "P6 1 1 ff\n", px, 3);
    expect_read_error_containing("maxtext.ppm", "maxval is not a number");
    write_ppm_file("hashmax.ppm", "P6 1 1 255#abc", NULL, 0);
    expect_read_error("hashmax.ppm", "invalid PPM header: no whitespace after maxval");
    write_ppm_file("nosep.ppm", "P61 1 255\n", px, 3);
    expect_read_error_containing("nosep.ppm", "invalid PPM header");

    write_ppm_file("zero.ppm", "P6 0 3 255\n", px, sizeof px);
    expect_read_error("zero.ppm", "invalid image size 0x3");
    write_ppm_file("huge.ppm", "P6 100000 100000 255\n", px, sizeof px);
    expect_read_error_containing("huge.ppm", "image too large");
    snprintf(big, sizeof big, "P6 1 %d 255\n", IMAGE_MAX_DIM + 1);
    write_ppm_file("toolong.ppm", big, px, sizeof px);
    expect_read_error_containing("toolong.ppm", "image too large");
    write_ppm_file("overflow.ppm", "P6 99999999999999999999999999 1 255\n", px, sizeof px);
    expect_read_error_containing("overflow.ppm", "image too large");

    write_ppm_file("p3.ppm", "P3\n1 1\n255\n0 0 0\n", NULL, 0);
    expect_read_error_containing("p3.ppm", "unsupported Netpbm format P3");
}

static void test_png_rejects(void)
{
    char p[512], q[512], err[512];
    unsigned char *good, *bad;
    size_t len = 0, cut, pos;
    image_t src, img;
    int not_rejected = 0, bad_success = 0;

    /* Noise compresses badly, so the IDAT is long enough to cut inside. */
    CHECK(make_pattern(&src, 40, 30, 11) == 0);
    tpath(p, sizeof p, "good.png");
    CHECK_MSG(image_write(p, &src, err, sizeof err) == 0, "%s", err);
    good = read_bytes(p, &len);
    CHECK(good != NULL && len > 1000);
    if (good == NULL) {
        image_free(&src);
        return;
    }

    tpath(q, sizeof q, "cut.png");
    CHECK(write_bytes(q, good, len / 2) == 0);
    expect_read_error("cut.png", "invalid PNG: truncated PNG data");

    /* Every possible truncation point after the signature, including one
     * that only loses IEND, must fail cleanly (ASan reports any leak). */
    for (cut = 8; cut < len; cut++) {
        if (write_bytes(q, good, cut) != 0) {
            not_rejected++;
            continue;
        }
        if (image_read(q, &img, err, sizeof err) != -1) {
            not_rejected++;
            image_free(&img);
        } else if (!starts_with(err, q)) {
            not_rejected++;
        }
    }
    CHECK_MSG(not_rejected == 0, "%d truncated PNGs were not rejected properly", not_rejected);

    /* Damaged IDAT: the chunk CRC no longer matches. */
    bad = malloc(len);
    CHECK(bad != NULL);
    if (bad != NULL) {
        memcpy(bad, good, len);
        bad[len / 2] ^= 0x5a;
        CHECK(write_bytes(q, bad, len) == 0);
        expect_read_error_containing("cut.png", "invalid PNG");

        /* Flip one byte at a time across the headers and the start of the
         * data: anything may be reported, but nothing may crash or leak,
         * and a success must be a sane image. */
        for (pos = 8; pos < len && pos < 200; pos++) {
            memcpy(bad, good, len);
            bad[pos] ^= 0xff;
            if (write_bytes(q, bad, len) != 0) {
                bad_success++;
                continue;
            }
            if (image_read(q, &img, err, sizeof err) == 0) {
                if (img.width <= 0 || img.height <= 0 || img.rgb == NULL)
                    bad_success++;
                image_free(&img);
            }
        }
        CHECK_MSG(bad_success == 0, "%d damaged PNGs produced an invalid image", bad_success);
        free(bad);
    }
    free(good);
    image_free(&src);

    /* A PNG wider than IMAGE_MAX_DIM is refused before allocating. */
    {
        size_t w = IMAGE_MAX_DIM + 1;
        unsigned char *row = calloc(w, 1);
        raw_png_t r = {(int)w, 1, 8, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE, row, w, NULL, 0};

        CHECK(row != NULL);
        if (row != NULL) {
            tpath(p, sizeof p, "wide.png");
            CHECK(write_raw_png(p, &r) == 0);
            expect_read_error_containing("wide.png", "image too large");
            free(row);
        }
    }
}

static void test_write_errors(void)
{
    char p[512], want[1024], err[512];
    image_t img, bogus;
    int before;
    struct stat st;

    CHECK(make_pattern(&img, 4, 4, 12) == 0);
    before = count_entries();

    tpath(p, sizeof p, "picture.bmp");
    err[0] = '\0';
    CHECK(image_write(p, &img, err, sizeof err) == -1);
    snprintf(want, sizeof want, "%s: unknown image extension (use .png or .ppm)", p);
    CHECK_MSG(strcmp(err, want) == 0, "got \"%s\"", err);

    tpath(p, sizeof p, "noextension");
    CHECK(image_write(p, &img, err, sizeof err) == -1);
    CHECK(contains(err, "unknown image extension"));
    tpath(p, sizeof p, "looks.png/inside");
    CHECK(image_write(p, &img, err, sizeof err) == -1);
    CHECK_MSG(contains(err, "unknown image extension"), "a dot in a directory is no extension");
    tpath(p, sizeof p, "x.png.bak");
    CHECK(image_write(p, &img, err, sizeof err) == -1);
    CHECK(contains(err, "unknown image extension"));
    CHECK_MSG(count_entries() == before, "a rejected extension created a file");

    tpath(p, sizeof p, "missing-dir/x.png");
    err[0] = '\0';
    CHECK(image_write(p, &img, err, sizeof err) == -1);
    snprintf(want, sizeof want, "%s: cannot open for writing: %s", p, strerror(ENOENT));
    CHECK_MSG(strcmp(err, want) == 0, "got \"%s\", want \"%s\"", err, want);
    CHECK_MSG(count_entries() == before, "write into a missing directory left a file");

    /* Target is a directory: the temp file is written, rename() fails, and
     * the temp file must be gone afterwards. */
    tpath(p, sizeof p, "isdir.ppm");
    CHECK(mkdir(p, 0700) == 0);
    err[0] = '\0';
    CHECK(image_write(p, &img, err, sizeof err) == -1);
    CHECK_MSG(starts_with(err, p) && contains(err, "rename"), "got \"%s\"", err);
    CHECK_MSG(count_entries() == before + 1, "failed rename left a temporary file");
    CHECK(!has_entry_containing(".tmp."));
    CHECK(stat(p, &st) == 0 && S_ISDIR(st.st_mode));
    CHECK(rmdir(p) == 0);

    bogus.width = 4;
    bogus.height = 4;
    bogus.rgb = NULL;
    tpath(p, sizeof p, "bogus.png");
    CHECK(image_write(p, &bogus, err, sizeof err) == -1);
    CHECK(starts_with(err, p));
    CHECK(count_entries() == before);

    image_free(&img);
}

/* Lit pixels (any channel non-zero) of img. */
static long count_lit(const image_t *img)
{
    long n = 0;
    for (size_t i = 0; i < (size_t)img->width * (size_t)img->height; i++)
        n += img->rgb[3 * i] || img->rgb[3 * i + 1] || img->rgb[3 * i + 2];
    return n;
}

/* The label font: every printable glyph distinct and inked within its
 * cell, descenders only where letters have them, widths, drawing and
 * clipping against hand-counted pixels. */
static void test_font(void)
{
    static const uint8_t white[3] = {255, 255, 255};
    char err[256];
    int distinct = 1, space_blank = 1, all_inked = 1, desc_ok = 1;

    for (int c = 0x20; c <= 0x7e; c++) {
        int ink = 0, low = 0;
        for (int r = 0; r < IMAGE_GLYPH_H; r++)
            for (int x = 0; x < IMAGE_GLYPH_W; x++) {
                ink += image_glyph_ink((char)c, x, r);
                low += r == IMAGE_GLYPH_H - 1 && image_glyph_ink((char)c, x, r);
            }
        if (c == ' ')
            space_blank = ink == 0;
        else if (ink == 0)
            all_inked = 0;
        /* Row 7 is for descenders only. */
        if ((low != 0) != (strchr("gjpqy,;", c) != NULL)) {
            desc_ok = 0;
            fprintf(stderr, "glyph '%c': descender row %s\n", c, low ? "inked" : "empty");
        }
        for (int d = 0x20; d < c; d++) {
            int same = 1;
            for (int r = 0; r < IMAGE_GLYPH_H && same; r++)
                for (int x = 0; x < IMAGE_GLYPH_W; x++)
                    if (image_glyph_ink((char)c, x, r) != image_glyph_ink((char)d, x, r))
                        same = 0;
            if (same) {
                distinct = 0;
                fprintf(stderr, "glyphs '%c' and '%c' are the same\n", d, c);
            }
        }
    }
    CHECK(space_blank);
    CHECK(all_inked);
    CHECK(distinct);
    CHECK(desc_ok);

    /* Bytes outside printable ASCII draw as '?'; outside the cell is blank. */
    int q_same = 1;
    for (int r = 0; r < IMAGE_GLYPH_H; r++)
        for (int x = 0; x < IMAGE_GLYPH_W; x++)
            q_same &= image_glyph_ink('\t', x, r) == image_glyph_ink('?', x, r) &&
                      image_glyph_ink((char)0xc3, x, r) == image_glyph_ink('?', x, r);
    CHECK(q_same);
    CHECK(image_glyph_ink('A', -1, 3) == 0 && image_glyph_ink('A', IMAGE_GLYPH_W, 3) == 0);
    CHECK(image_glyph_ink('A', 4, -1) == 0 && image_glyph_ink('A', 4, IMAGE_GLYPH_H) == 0);
    CHECK(image_glyph_ink('A', 0, 1) == 1 && image_glyph_ink('A', 0, 0) == 0);

    CHECK(image_text_width("", 1) == 0);
    CHECK(image_text_width("a", 1) == 5);
    CHECK(image_text_width("ab", 1) == 11);
    CHECK(image_text_width("ab", 2) == 22);
    CHECK(image_text_width("identical", 3) == (9 * 6 - 1) * 3);

    /* 'A' has 18 ink pixels (3+2+2+5+2+2+2, counted by hand); at scale 2
     * each is a 2x2 square, all inside the 10x16 box at (1, 1). */
    image_t img;
    CHECK(image_alloc(&img, 20, 20, err, sizeof err) == 0);
    image_draw_text(&img, 1, 1, 2, "A", white);
    CHECK_MSG(count_lit(&img) == 72, "lit %ld", count_lit(&img));
    int outside = 0;
    for (int y = 0; y < 20; y++)
        for (int x = 0; x < 20; x++)
            if ((x < 1 || x >= 11 || y < 1 || y >= 17) && img.rgb[3 * (y * 20 + x)])
                outside++;
    CHECK(outside == 0);
    CHECK(img.rgb[3 * (3 * 20 + 1)] == 255 && img.rgb[3 * (3 * 20 + 1) + 1] == 255); /* row 1 col 0 at (1,3) */
    image_free(&img);

    /* Clipping: 'A' at x = -3 on a 5x8 image shows its columns 3 and 4:
     * 2 + 6 ink pixels. Far outside, nothing is drawn (and nothing breaks). */
    CHECK(image_alloc(&img, 5, 8, err, sizeof err) == 0);
    image_draw_text(&img, -3, 0, 1, "A", white);
    CHECK_MSG(count_lit(&img) == 8, "lit %ld", count_lit(&img));
    memset(img.rgb, 0, 5 * 8 * 3);
    image_draw_text(&img, 100, 0, 1, "AAAA", white);
    image_draw_text(&img, -1000, -1000, 3, "AAAA", white);
    image_draw_text(&img, 0, 8, 1, "A", white);
    CHECK(count_lit(&img) == 0);
    /* A second character starts IMAGE_GLYPH_ADVANCE columns on: "AA" at
     * x = -6 shows exactly the second 'A' (its 5 columns, 18 pixels). */
    image_draw_text(&img, -6, 0, 1, "AA", white);
    CHECK_MSG(count_lit(&img) == 18, "lit %ld", count_lit(&img));
    image_free(&img);
}

int main(void)
{
    snprintf(g_dir, sizeof g_dir, "/tmp/fxrt_test_image.XXXXXX");
    if (mkdtemp(g_dir) == NULL) {
        perror("mkdtemp");
        return 1;
    }

    test_alloc();
    test_round_trips();
    test_png_colour_types();
    test_ppm_header();
    test_read_rejects();
    test_png_rejects();
    test_write_errors();
    test_font();

    remove_test_dir();
    return check_report("test_image");
}
