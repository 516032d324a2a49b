/* Host image I/O: PNG through libpng, binary PPM (P6) by hand.
 *
 * Every failure path reports "PATH: what is wrong" and releases whatever it
 * acquired; on failure the image is left empty (safe to image_free). */
#include "image.h"

#include "errf.h"

#include <errno.h>
#include <png.h>
#include <setjmp.h>
#include <signal.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#if defined(__GNUC__)
#define IMAGE_PRINTF(fmt, args) __attribute__((format(printf, fmt, args)))
#else
#define IMAGE_PRINTF(fmt, args)
#endif

/* Length of a libpng error message we keep; libpng's own are short. */
#define IMAGE_PNG_MSG_LEN 200

static void image_path_err(char *err, size_t errlen, const char *path, const char *fmt, ...)
    IMAGE_PRINTF(4, 5);

/* All user-facing errors name the file first, so a batch run that touches
 * many images says which one is at fault. */
static void image_path_err(char *err, size_t errlen, const char *path, const char *fmt, ...)
{
    va_list ap;
    int n;

    if (err == NULL || errlen == 0)
        return;
    n = snprintf(err, errlen, "%s: ", path);
    if (n < 0 || (size_t)n >= errlen)
        return;
    va_start(ap, fmt);
    vsnprintf(err + n, errlen - (size_t)n, fmt, ap);
    va_end(ap);
}

static void image_clear(image_t *img)
{
    img->width = 0;
    img->height = 0;
    img->rgb = NULL;
}

/* Byte count of a width x height RGB image, or 0 when it would not fit in
 * a size_t (callers have already rejected non-positive sizes). */
static size_t image_byte_count(int width, int height)
{
    size_t w = (size_t)width;
    size_t h = (size_t)height;

    if (w > SIZE_MAX / 3 / h)
        return 0;
    return w * h * 3;
}

int image_alloc(image_t *img, int width, int height, char *err, size_t errlen)
{
    size_t bytes;

    image_clear(img);
    if (width <= 0 || height <= 0) {
        errf_set(err, errlen, "invalid image size %dx%d", width, height);
        return -1;
    }
    bytes = image_byte_count(width, height);
    if (bytes == 0) {
        errf_set(err, errlen, "image size %dx%d is too large", width, height);
        return -1;
    }
    img->rgb = calloc(bytes, 1);
    if (img->rgb == NULL) {
        errf_set(err, errlen, "out of memory allocating a %dx%d image", width, height);
        return -1;
    }
    img->width = width;
    img->height = height;
    return 0;
}

void image_free(image_t *img)
{
    if (img == NULL)
        return;
    free(img->rgb);
    image_clear(img);
}

/* ------------------------------------------------------------------ */
/* libpng glue shared by reading and writing                           */

/* libpng reports errors by longjmp; the handler first copies the message
 * here so the caller can build a "PATH: ..." error after the jump. */
typedef struct {
    FILE *fp;
    char msg[IMAGE_PNG_MSG_LEN];
} image_png_io_t;

static _Noreturn void image_png_error(png_structp png, png_const_charp msg)
{
    image_png_io_t *io = png_get_error_ptr(png);

    snprintf(io->msg, sizeof io->msg, "%s", msg);
    png_longjmp(png, 1);
}

/* Warnings (bad ancillary chunks, odd gamma) never make an image unusable
 * for us, and libpng's default would print them to stderr. */
static void image_png_warning(png_structp png, png_const_charp msg)
{
    (void)png;
    (void)msg;
}

/* Our own read callback so a short file is reported as truncation, and an
 * I/O error with its errno text, instead of libpng's generic "Read Error". */
static void image_png_read_fn(png_structp png, png_bytep data, size_t length)
{
    image_png_io_t *io = png_get_io_ptr(png);

    if (fread(data, 1, length, io->fp) != length) {
        if (ferror(io->fp))
            snprintf(io->msg, sizeof io->msg, "read error: %s", strerror(errno));
        else
            snprintf(io->msg, sizeof io->msg, "truncated PNG data");
        png_longjmp(png, 1);
    }
}

static void image_png_write_fn(png_structp png, png_bytep data, size_t length)
{
    image_png_io_t *io = png_get_io_ptr(png);

    if (fwrite(data, 1, length, io->fp) != length) {
        snprintf(io->msg, sizeof io->msg, "write error: %s", strerror(errno));
        png_longjmp(png, 1);
    }
}

/* Flushing is left to image_write, which must check fflush/fclose anyway. */
static void image_png_flush_fn(png_structp png)
{
    (void)png;
}

/* ------------------------------------------------------------------ */
/* PNG reading                                                          */

/* State that must survive a longjmp lives in the caller's frame, not in
 * locals of the function that calls setjmp: those would be indeterminate
 * after the jump unless volatile. */
typedef struct {
    image_png_io_t io;
    png_structp png;
    png_infop info;
    uint8_t *rgb;
    png_bytep *rows;
    int width;
    int height;
    int too_large; /* set instead of calling png_error, for a clearer message */
} image_png_reader_t;

static int image_png_read_body(image_png_reader_t *r)
{
    png_uint_32 w, h, y;
    int bit_depth, color_type;

    if (setjmp(png_jmpbuf(r->png)))
        return -1;

    png_set_read_fn(r->png, &r->io, image_png_read_fn);
    png_set_sig_bytes(r->png, 8);
    png_read_info(r->png, r->info);
    png_get_IHDR(r->png, r->info, &w, &h, &bit_depth, &color_type, NULL, NULL, NULL);
    if (w > IMAGE_MAX_DIM || h > IMAGE_MAX_DIM) {
        r->too_large = 1;
        r->width = (int)(w > INT32_MAX ? INT32_MAX : w);
        r->height = (int)(h > INT32_MAX ? INT32_MAX : h);
        return -1;
    }

    /* Normalise every colour type and depth to 8-bit RGB. */
    png_set_expand(r->png);
#ifdef PNG_READ_SCALE_16_TO_8_SUPPORTED
    png_set_scale_16(r->png); /* rounds, unlike strip_16 which truncates */
#else
    png_set_strip_16(r->png);
#endif
    png_set_strip_alpha(r->png);
    png_set_gray_to_rgb(r->png);
    png_set_interlace_handling(r->png);
    png_read_update_info(r->png, r->info);

    if (png_get_channels(r->png, r->info) != 3 || png_get_bit_depth(r->png, r->info) != 8 ||
        png_get_rowbytes(r->png, r->info) != (size_t)w * 3)
        png_error(r->png, "unexpected pixel layout after conversion to RGB8");

    r->width = (int)w;
    r->height = (int)h;
    r->rgb = malloc((size_t)w * h * 3);
    r->rows = malloc(sizeof *r->rows * h);
    if (r->rgb == NULL || r->rows == NULL)
        png_error(r->png, "out of memory");
    for (y = 0; y < h; y++)
        r->rows[y] = r->rgb + (size_t)y * w * 3;
    png_read_image(r->png, r->rows);
    /* Reading to IEND catches files cut off after the pixel data and
     * verifies the remaining chunks' CRCs. */
    png_read_end(r->png, NULL);
    return 0;
}

static int image_read_png(const char *path, FILE *fp, image_t *img, char *err, size_t errlen)
{
    image_png_reader_t r;
    int rc;

    memset(&r, 0, sizeof r);
    r.io.fp = fp;
    r.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &r.io, image_png_error,
                                   image_png_warning);
    if (r.png != NULL)
        r.info = png_create_info_struct(r.png);
    if (r.png == NULL || r.info == NULL) {
        png_destroy_read_struct(r.png ? &r.png : NULL, NULL, NULL);
        image_path_err(err, errlen, path, "out of memory initialising libpng");
        return -1;
    }

    rc = image_png_read_body(&r);
    png_destroy_read_struct(&r.png, &r.info, NULL);
    free(r.rows);
    if (rc != 0) {
        free(r.rgb);
        if (r.too_large)
            image_path_err(err, errlen, path, "image too large (%dx%d, limit is %d per side)",
                           r.width, r.height, IMAGE_MAX_DIM);
        else
            image_path_err(err, errlen, path, "invalid PNG: %s", r.io.msg);
        return -1;
    }
    img->width = r.width;
    img->height = r.height;
    img->rgb = r.rgb;
    return 0;
}

/* ------------------------------------------------------------------ */
/* PPM reading                                                          */

static int image_ppm_is_space(int c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

/* Skip whitespace and '#' comments (to end of line) between header fields.
 * Returns the first character of the next field, or EOF. */
static int image_ppm_skip(FILE *fp)
{
    int c = getc(fp);

    for (;;) {
        if (c == '#') {
            while (c != '\n' && c != '\r' && c != EOF)
                c = getc(fp);
        } else if (image_ppm_is_space(c)) {
            c = getc(fp);
        } else {
            return c;
        }
    }
}

/* Parse one decimal header field. Values are clamped just above any limit
 * we accept, so a 30-digit width cannot overflow but is still rejected.
 * On success *term is the character that ended the number. */
static int image_ppm_number(FILE *fp, const char *path, const char *what, long *out, int *term,
                            char *err, size_t errlen)
{
    const long clamp = 1000000L;
    long v = 0;
    int c = image_ppm_skip(fp);

    if (c == EOF) {
        image_path_err(err, errlen, path, "truncated PPM header (missing %s)", what);
        return -1;
    }
    if (c < '0' || c > '9') {
        image_path_err(err, errlen, path, "invalid PPM header: %s is not a number", what);
        return -1;
    }
    while (c >= '0' && c <= '9') {
        if (v < clamp)
            v = v * 10 + (c - '0');
        c = getc(fp);
    }
    /* "12abc" must not parse as 12: fields end in whitespace or a comment. */
    if (c != EOF && !image_ppm_is_space(c) && c != '#') {
        image_path_err(err, errlen, path, "invalid PPM header: %s is not a number", what);
        return -1;
    }
    *out = v;
    *term = c;
    return 0;
}

static int image_read_ppm(const char *path, FILE *fp, image_t *img, char *err, size_t errlen)
{
    long w, h, maxval;
    int term;
    size_t bytes, got;

    /* The two magic bytes have been consumed by the caller. */
    term = getc(fp);
    if (term != '#' && !image_ppm_is_space(term)) {
        image_path_err(err, errlen, path, "invalid PPM header after P6 magic");
        return -1;
    }
    ungetc(term, fp);
    if (image_ppm_number(fp, path, "width", &w, &term, err, errlen) != 0)
        return -1;
    ungetc(term, fp);
    if (image_ppm_number(fp, path, "height", &h, &term, err, errlen) != 0)
        return -1;
    ungetc(term, fp);
    if (image_ppm_number(fp, path, "maxval", &maxval, &term, err, errlen) != 0)
        return -1;

    if (w <= 0 || h <= 0) {
        image_path_err(err, errlen, path, "invalid image size %ldx%ld", w, h);
        return -1;
    }
    if (w > IMAGE_MAX_DIM || h > IMAGE_MAX_DIM) {
        image_path_err(err, errlen, path, "image too large (%ldx%ld, limit is %d per side)", w, h,
                       IMAGE_MAX_DIM);
        return -1;
    }
    if (maxval != 255) {
        image_path_err(err, errlen, path, "unsupported PPM maxval %ld (only 255 is supported)",
                       maxval);
        return -1;
    }
    /* Exactly one whitespace byte separates maxval from the raster; the
     * raster itself may start with bytes that look like whitespace or '#'. */
    if (!image_ppm_is_space(term)) {
        if (term == EOF)
            image_path_err(err, errlen, path, "truncated pixel data");
        else
            image_path_err(err, errlen, path, "invalid PPM header: no whitespace after maxval");
        return -1;
    }

    if (image_alloc(img, (int)w, (int)h, NULL, 0) != 0) {
        image_path_err(err, errlen, path, "out of memory for a %ldx%ld image", w, h);
        return -1;
    }
    bytes = image_byte_count(img->width, img->height);
    got = fread(img->rgb, 1, bytes, fp);
    if (got != bytes) {
        if (ferror(fp))
            image_path_err(err, errlen, path, "read error: %s", strerror(errno));
        else
            image_path_err(err, errlen, path, "truncated pixel data");
        image_free(img);
        return -1;
    }
    /* Trailing bytes are ignored: P6 allows several images per file. */
    return 0;
}

int image_read(const char *path, image_t *img, char *err, size_t errlen)
{
    unsigned char magic[8];
    size_t n;
    FILE *fp;
    int rc;

    image_clear(img);
    fp = fopen(path, "rb");
    if (fp == NULL) {
        image_path_err(err, errlen, path, "cannot open: %s", strerror(errno));
        return -1;
    }

    n = fread(magic, 1, 2, fp);
    if (n == 2 && magic[0] == 'P' && magic[1] == '6') {
        rc = image_read_ppm(path, fp, img, err, errlen);
    } else if (n == 2 && magic[0] == 'P' && magic[1] >= '1' && magic[1] <= '5') {
        image_path_err(err, errlen, path,
                       "unsupported Netpbm format P%c (only binary PPM, P6, is supported)",
                       magic[1]);
        rc = -1;
    } else if (n == 2 && fread(magic + 2, 1, 6, fp) == 6 && png_sig_cmp(magic, 0, 8) == 0) {
        rc = image_read_png(path, fp, img, err, errlen);
    } else if (ferror(fp)) {
        image_path_err(err, errlen, path, "read error: %s", strerror(errno));
        rc = -1;
    } else {
        image_path_err(err, errlen, path, "not a PNG or PPM file");
        rc = -1;
    }
    fclose(fp); /* read-only: a close error cannot lose data */
    return rc;
}

/* ------------------------------------------------------------------ */
/* Writing                                                              */

typedef enum { IMAGE_FMT_UNKNOWN, IMAGE_FMT_PNG, IMAGE_FMT_PPM } image_format_t;

static int image_ascii_lower(int c)
{
    return (c >= 'A' && c <= 'Z') ? c - 'A' + 'a' : c;
}

/* ASCII-only so the result does not depend on the user's locale. */
static int image_ext_is(const char *ext, const char *want)
{
    while (*ext != '\0' && *want != '\0') {
        if (image_ascii_lower((unsigned char)*ext) != *want)
            return 0;
        ext++;
        want++;
    }
    return *ext == '\0' && *want == '\0';
}

/* No need to split off the directory first: if the last dot is in a
 * directory name, the "extension" contains a '/' and matches nothing. */
static image_format_t image_format_from_path(const char *path)
{
    const char *dot = strrchr(path, '.');

    if (dot == NULL)
        return IMAGE_FMT_UNKNOWN;
    if (image_ext_is(dot, ".png"))
        return IMAGE_FMT_PNG;
    if (image_ext_is(dot, ".ppm"))
        return IMAGE_FMT_PPM;
    return IMAGE_FMT_UNKNOWN;
}

typedef struct {
    image_png_io_t io;
    png_structp png;
    png_infop info;
} image_png_writer_t;

static int image_png_write_body(image_png_writer_t *wr, const image_t *img)
{
    int y;

    if (setjmp(png_jmpbuf(wr->png)))
        return -1;
    png_set_write_fn(wr->png, &wr->io, image_png_write_fn, image_png_flush_fn);
    png_set_IHDR(wr->png, wr->info, (png_uint_32)img->width, (png_uint_32)img->height, 8,
                 PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_write_info(wr->png, wr->info);
    /* Row by row from the image buffer: no row-pointer array to allocate
     * and therefore nothing to leak if libpng jumps out. */
    for (y = 0; y < img->height; y++)
        png_write_row(wr->png, img->rgb + (size_t)y * (size_t)img->width * 3);
    png_write_end(wr->png, NULL);
    return 0;
}

static int image_write_png(FILE *fp, const image_t *img, char *msg, size_t msglen)
{
    image_png_writer_t wr;
    int rc;

    memset(&wr, 0, sizeof wr);
    wr.io.fp = fp;
    wr.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &wr.io, image_png_error,
                                     image_png_warning);
    if (wr.png != NULL)
        wr.info = png_create_info_struct(wr.png);
    if (wr.png == NULL || wr.info == NULL) {
        png_destroy_write_struct(wr.png ? &wr.png : NULL, NULL);
        snprintf(msg, msglen, "out of memory initialising libpng");
        return -1;
    }
    rc = image_png_write_body(&wr, img);
    png_destroy_write_struct(&wr.png, &wr.info);
    if (rc != 0)
        snprintf(msg, msglen, "%s", wr.io.msg);
    return rc;
}

static int image_write_ppm(FILE *fp, const image_t *img, char *msg, size_t msglen)
{
    size_t bytes = image_byte_count(img->width, img->height);

    if (fprintf(fp, "P6\n%d %d\n255\n", img->width, img->height) < 0 ||
        fwrite(img->rgb, 1, bytes, fp) != bytes) {
        snprintf(msg, msglen, "write error: %s", strerror(errno));
        return -1;
    }
    return 0;
}

/* Temporary files not yet renamed into place, for image_cleanup_signals:
 * fixed buffers, so that the handler only reads memory and calls unlink
 * (async-signal-safe). A slot's name is complete before its busy flag is
 * set and stays until the flag is cleared, so the handler never sees a
 * half-copied name (which could be the output's own name). */
#define IMAGE_PENDING_MAX 4
static char image_pending[IMAGE_PENDING_MAX][IMAGE_TMP_MAX];
static volatile sig_atomic_t image_pending_busy[IMAGE_PENDING_MAX];

static void image_pending_drop(const char *tmp)
{
    for (int i = 0; i < IMAGE_PENDING_MAX; i++)
        if (image_pending_busy[i] && !strcmp(image_pending[i], tmp))
            image_pending_busy[i] = 0;
}

static void image_on_signal(int sig)
{
    for (int i = 0; i < IMAGE_PENDING_MAX; i++)
        if (image_pending_busy[i])
            unlink(image_pending[i]);
    signal(sig, SIG_DFL);
    raise(sig);
}

void image_cleanup_signals(void)
{
    static const int sigs[] = {SIGINT, SIGTERM, SIGHUP};
    for (size_t i = 0; i < sizeof sigs / sizeof sigs[0]; i++) {
        /* A signal the parent ignores (nohup, a background job of a
         * non-interactive shell) stays ignored. */
        struct sigaction old;
        if (sigaction(sigs[i], NULL, &old) == 0 && old.sa_handler == SIG_IGN)
            continue;
        struct sigaction sa;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = image_on_signal;
        sigemptyset(&sa.sa_mask);
        sigaction(sigs[i], &sa, NULL);
    }
}

int image_write_tmp(const char *path, const image_t *img, char *tmp, size_t tmplen, char *err, size_t errlen)
{
    char msg[IMAGE_PNG_MSG_LEN + 32];
    image_format_t fmt = image_format_from_path(path);
    FILE *fp;
    int rc, slot = -1;

    tmp[0] = '\0';
    if (fmt == IMAGE_FMT_UNKNOWN) {
        image_path_err(err, errlen, path, "unknown image extension (use .png or .ppm)");
        return -1;
    }
    if (img == NULL || img->rgb == NULL || img->width <= 0 || img->height <= 0 ||
        image_byte_count(img->width, img->height) == 0) {
        image_path_err(err, errlen, path, "refusing to write an empty or invalid image");
        return -1;
    }
    /* The PID keeps concurrent writers (parallel test runs) from sharing a
     * temporary file; the same directory keeps rename() atomic. */
    int n = snprintf(tmp, tmplen, "%s.tmp.%ld", path, (long)getpid());
    if (n < 0 || (size_t)n >= tmplen || n >= IMAGE_TMP_MAX) {
        tmp[0] = '\0';
        image_path_err(err, errlen, path, "path too long");
        return -1;
    }
    for (int i = 0; i < IMAGE_PENDING_MAX && slot < 0; i++)
        if (!image_pending_busy[i])
            slot = i;
    if (slot < 0) {
        tmp[0] = '\0';
        image_path_err(err, errlen, path, "too many images being written at once");
        return -1;
    }
    /* Registered before the file exists: a signal in between unlinks
     * nothing that matters. */
    memcpy(image_pending[slot], tmp, strlen(tmp) + 1);
    image_pending_busy[slot] = 1;
    fp = fopen(tmp, "wb");
    if (fp == NULL) {
        image_path_err(err, errlen, path, "cannot open for writing: %s", strerror(errno));
        image_pending_busy[slot] = 0;
        tmp[0] = '\0';
        return -1;
    }

    msg[0] = '\0';
    if (fmt == IMAGE_FMT_PNG)
        rc = image_write_png(fp, img, msg, sizeof msg);
    else
        rc = image_write_ppm(fp, img, msg, sizeof msg);

    /* Buffered data may only fail to reach the disk (ENOSPC, EIO) at
     * flush or close time, so both results decide success. */
    if (rc == 0 && fflush(fp) != 0) {
        snprintf(msg, sizeof msg, "write error: %s", strerror(errno));
        rc = -1;
    }
    if (fclose(fp) != 0 && rc == 0) {
        snprintf(msg, sizeof msg, "write error: %s", strerror(errno));
        rc = -1;
    }
    if (rc != 0) {
        image_write_abort(tmp);
        image_path_err(err, errlen, path, "%s", msg);
        return rc;
    }
    /* Test hook (tests/cli.sh): an interrupt while the file is pending. */
    if (getenv("FXRT_TEST_SIGINT_PENDING"))
        raise(SIGINT);
    return 0;
}

int image_write_commit(char *tmp, const char *path, char *err, size_t errlen)
{
    if (rename(tmp, path) != 0) {
        int saved = errno;
        image_write_abort(tmp);
        image_path_err(err, errlen, path, "cannot rename temporary file into place: %s", strerror(saved));
        return -1;
    }
    image_pending_drop(tmp);
    tmp[0] = '\0';
    return 0;
}

void image_write_abort(char *tmp)
{
    if (!tmp[0])
        return;
    remove(tmp);
    image_pending_drop(tmp);
    tmp[0] = '\0';
}

int image_write(const char *path, const image_t *img, char *err, size_t errlen)
{
    char tmp[IMAGE_TMP_MAX];
    if (image_write_tmp(path, img, tmp, sizeof tmp, err, errlen))
        return -1;
    return image_write_commit(tmp, path, err, errlen);
}

int image_check_path(const char *path, char *err, size_t errlen)
{
    struct stat st;
    if (image_format_from_path(path) == IMAGE_FMT_UNKNOWN) {
        image_path_err(err, errlen, path, "unknown image extension (use .png or .ppm)");
        return -1;
    }
    /* The one rename that would fail after the files are written. */
    if (stat(path, &st) == 0 && S_ISDIR(st.st_mode)) {
        image_path_err(err, errlen, path, "is a directory");
        return -1;
    }
    return 0;
}

/* ------------------------------------------------------------------ */
/* Text: a built-in 5x8 bitmap font for labels on sheets and diff maps */

/* One glyph per printable ASCII character (0x20 space .. 0x7e '~'), 8 rows of
 * 5 columns, top row first: '#' is ink. Rows 0..6 hold capitals and digits
 * (baseline under row 6); row 7 is for descenders (g j p q y , ;). */
static const char image_font[95][IMAGE_GLYPH_H][IMAGE_GLYPH_W + 1] = {
    /*   */ {".....", ".....", ".....", ".....", ".....", ".....", ".....", "....."},
    /* ! */ {"..#..", "..#..", "..#..", "..#..", "..#..", ".....", "..#..", "....."},
    /* " */ {".#.#.", ".#.#.", ".....", ".....", ".....", ".....", ".....", "....."},
    /* # */ {".#.#.", ".#.#.", "#####", ".#.#.", "#####", ".#.#.", ".#.#.", "....."},
    /* $ */ {"..#..", ".####", "#.#..", ".###.", "..#.#", "####.", "..#..", "....."},
    /* % */ {"##...", "##..#", "...#.", "..#..", ".#...", "#..##", "...##", "....."},
    /* & */ {".##..", "#..#.", "#.#..", ".#...", "#.#.#", "#..#.", ".##.#", "....."},
    /* ' */ {"..#..", "..#..", ".....", ".....", ".....", ".....", ".....", "....."},
    /* ( */ {"...#.", "..#..", ".#...", ".#...", ".#...", "..#..", "...#.", "....."},
    /* ) */ {".#...", "..#..", "...#.", "...#.", "...#.", "..#..", ".#...", "....."},
    /* * */ {".....", "..#..", "#.#.#", ".###.", "#.#.#", "..#..", ".....", "....."},
    /* + */ {".....", "..#..", "..#..", "#####", "..#..", "..#..", ".....", "....."},
    /* , */ {".....", ".....", ".....", ".....", ".....", "..#..", "..#..", ".#..."},
    /* - */ {".....", ".....", ".....", "#####", ".....", ".....", ".....", "....."},
    /* . */ {".....", ".....", ".....", ".....", ".....", ".....", "..#..", "....."},
    /* / */ {".....", "....#", "...#.", "..#..", ".#...", "#....", ".....", "....."},
    /* 0 */ {".###.", "#...#", "#..##", "#.#.#", "##..#", "#...#", ".###.", "....."},
    /* 1 */ {"..#..", ".##..", "..#..", "..#..", "..#..", "..#..", ".###.", "....."},
    /* 2 */ {".###.", "#...#", "....#", "...#.", "..#..", ".#...", "#####", "....."},
    /* 3 */ {"#####", "...#.", "..#..", "...#.", "....#", "#...#", ".###.", "....."},
    /* 4 */ {"...#.", "..##.", ".#.#.", "#..#.", "#####", "...#.", "...#.", "....."},
    /* 5 */ {"#####", "#....", "####.", "....#", "....#", "#...#", ".###.", "....."},
    /* 6 */ {"..##.", ".#...", "#....", "####.", "#...#", "#...#", ".###.", "....."},
    /* 7 */ {"#####", "....#", "...#.", "..#..", ".#...", ".#...", ".#...", "....."},
    /* 8 */ {".###.", "#...#", "#...#", ".###.", "#...#", "#...#", ".###.", "....."},
    /* 9 */ {".###.", "#...#", "#...#", ".####", "....#", "...#.", ".##..", "....."},
    /* : */ {".....", ".....", "..#..", ".....", ".....", "..#..", ".....", "....."},
    /* ; */ {".....", ".....", "..#..", ".....", ".....", "..#..", "..#..", ".#..."},
    /* < */ {"...#.", "..#..", ".#...", "#....", ".#...", "..#..", "...#.", "....."},
    /* = */ {".....", ".....", "#####", ".....", "#####", ".....", ".....", "....."},
    /* > */ {".#...", "..#..", "...#.", "....#", "...#.", "..#..", ".#...", "....."},
    /* ? */ {".###.", "#...#", "....#", "...#.", "..#..", ".....", "..#..", "....."},
    /* @ */ {".###.", "#...#", "....#", ".##.#", "#.#.#", "#.#.#", ".###.", "....."},
    /* A */ {".###.", "#...#", "#...#", "#####", "#...#", "#...#", "#...#", "....."},
    /* B */ {"####.", "#...#", "#...#", "####.", "#...#", "#...#", "####.", "....."},
    /* C */ {".###.", "#...#", "#....", "#....", "#....", "#...#", ".###.", "....."},
    /* D */ {"###..", "#..#.", "#...#", "#...#", "#...#", "#..#.", "###..", "....."},
    /* E */ {"#####", "#....", "#....", "####.", "#....", "#....", "#####", "....."},
    /* F */ {"#####", "#....", "#....", "####.", "#....", "#....", "#....", "....."},
    /* G */ {".###.", "#...#", "#....", "#.###", "#...#", "#...#", ".####", "....."},
    /* H */ {"#...#", "#...#", "#...#", "#####", "#...#", "#...#", "#...#", "....."},
    /* I */ {".###.", "..#..", "..#..", "..#..", "..#..", "..#..", ".###.", "....."},
    /* J */ {"..###", "...#.", "...#.", "...#.", "...#.", "#..#.", ".##..", "....."},
    /* K */ {"#...#", "#..#.", "#.#..", "##...", "#.#..", "#..#.", "#...#", "....."},
    /* L */ {"#....", "#....", "#....", "#....", "#....", "#....", "#####", "....."},
    /* M */ {"#...#", "##.##", "#.#.#", "#.#.#", "#...#", "#...#", "#...#", "....."},
    /* N */ {"#...#", "#...#", "##..#", "#.#.#", "#..##", "#...#", "#...#", "....."},
    /* O */ {".###.", "#...#", "#...#", "#...#", "#...#", "#...#", ".###.", "....."},
    /* P */ {"####.", "#...#", "#...#", "####.", "#....", "#....", "#....", "....."},
    /* Q */ {".###.", "#...#", "#...#", "#...#", "#.#.#", "#..#.", ".##.#", "....."},
    /* R */ {"####.", "#...#", "#...#", "####.", "#.#..", "#..#.", "#...#", "....."},
    /* S */ {".####", "#....", "#....", ".###.", "....#", "....#", "####.", "....."},
    /* T */ {"#####", "..#..", "..#..", "..#..", "..#..", "..#..", "..#..", "....."},
    /* U */ {"#...#", "#...#", "#...#", "#...#", "#...#", "#...#", ".###.", "....."},
    /* V */ {"#...#", "#...#", "#...#", "#...#", "#...#", ".#.#.", "..#..", "....."},
    /* W */ {"#...#", "#...#", "#...#", "#.#.#", "#.#.#", "#.#.#", ".#.#.", "....."},
    /* X */ {"#...#", "#...#", ".#.#.", "..#..", ".#.#.", "#...#", "#...#", "....."},
    /* Y */ {"#...#", "#...#", ".#.#.", "..#..", "..#..", "..#..", "..#..", "....."},
    /* Z */ {"#####", "....#", "...#.", "..#..", ".#...", "#....", "#####", "....."},
    /* [ */ {".###.", ".#...", ".#...", ".#...", ".#...", ".#...", ".###.", "....."},
    /* \ */ {".....", "#....", ".#...", "..#..", "...#.", "....#", ".....", "....."},
    /* ] */ {".###.", "...#.", "...#.", "...#.", "...#.", "...#.", ".###.", "....."},
    /* ^ */ {"..#..", ".#.#.", "#...#", ".....", ".....", ".....", ".....", "....."},
    /* _ */ {".....", ".....", ".....", ".....", ".....", ".....", "#####", "....."},
    /* ` */ {".#...", "..#..", ".....", ".....", ".....", ".....", ".....", "....."},
    /* a */ {".....", ".....", ".###.", "....#", ".####", "#...#", ".####", "....."},
    /* b */ {"#....", "#....", "#.##.", "##..#", "#...#", "#...#", "####.", "....."},
    /* c */ {".....", ".....", ".###.", "#....", "#....", "#...#", ".###.", "....."},
    /* d */ {"....#", "....#", ".##.#", "#..##", "#...#", "#...#", ".####", "....."},
    /* e */ {".....", ".....", ".###.", "#...#", "#####", "#....", ".###.", "....."},
    /* f */ {"..##.", ".#..#", ".#...", "###..", ".#...", ".#...", ".#...", "....."},
    /* g */ {".....", ".....", ".####", "#...#", "#...#", ".####", "....#", ".###."},
    /* h */ {"#....", "#....", "#.##.", "##..#", "#...#", "#...#", "#...#", "....."},
    /* i */ {"..#..", ".....", ".##..", "..#..", "..#..", "..#..", ".###.", "....."},
    /* j */ {"...#.", ".....", "..##.", "...#.", "...#.", "...#.", "#..#.", ".##.."},
    /* k */ {"#....", "#....", "#..#.", "#.#..", "##...", "#.#..", "#..#.", "....."},
    /* l */ {".##..", "..#..", "..#..", "..#..", "..#..", "..#..", ".###.", "....."},
    /* m */ {".....", ".....", "##.#.", "#.#.#", "#.#.#", "#...#", "#...#", "....."},
    /* n */ {".....", ".....", "#.##.", "##..#", "#...#", "#...#", "#...#", "....."},
    /* o */ {".....", ".....", ".###.", "#...#", "#...#", "#...#", ".###.", "....."},
    /* p */ {".....", ".....", "####.", "#...#", "#...#", "####.", "#....", "#...."},
    /* q */ {".....", ".....", ".####", "#...#", "#...#", ".####", "....#", "....#"},
    /* r */ {".....", ".....", "#.##.", "##..#", "#....", "#....", "#....", "....."},
    /* s */ {".....", ".....", ".###.", "#....", ".###.", "....#", "####.", "....."},
    /* t */ {".#...", ".#...", "###..", ".#...", ".#...", ".#..#", "..##.", "....."},
    /* u */ {".....", ".....", "#...#", "#...#", "#...#", "#..##", ".##.#", "....."},
    /* v */ {".....", ".....", "#...#", "#...#", "#...#", ".#.#.", "..#..", "....."},
    /* w */ {".....", ".....", "#...#", "#...#", "#.#.#", "#.#.#", ".#.#.", "....."},
    /* x */ {".....", ".....", "#...#", ".#.#.", "..#..", ".#.#.", "#...#", "....."},
    /* y */ {".....", ".....", "#...#", "#...#", "#...#", ".####", "....#", ".###."},
    /* z */ {".....", ".....", "#####", "...#.", "..#..", ".#...", "#####", "....."},
    /* { */ {"...#.", "..#..", "..#..", ".#...", "..#..", "..#..", "...#.", "....."},
    /* | */ {"..#..", "..#..", "..#..", "..#..", "..#..", "..#..", "..#..", "....."},
    /* } */ {".#...", "..#..", "..#..", "...#.", "..#..", "..#..", ".#...", "....."},
    /* ~ */ {".....", ".....", ".#...", "#.#.#", "...#.", ".....", ".....", "....."},
};

int image_glyph_ink(char c, int col, int row)
{
    unsigned char u = (unsigned char)c;

    if (col < 0 || col >= IMAGE_GLYPH_W || row < 0 || row >= IMAGE_GLYPH_H)
        return 0;
    if (u < 0x20 || u > 0x7e)
        u = '?';
    return image_font[u - 0x20][row][col] == '#';
}

int image_text_width(const char *text, int scale)
{
    size_t n = strlen(text);

    if (n == 0 || scale < 1)
        return 0;
    if (n > (size_t)(INT32_MAX / IMAGE_GLYPH_ADVANCE / 16))
        n = (size_t)(INT32_MAX / IMAGE_GLYPH_ADVANCE / 16);
    return (int)n * IMAGE_GLYPH_ADVANCE * scale - (IMAGE_GLYPH_ADVANCE - IMAGE_GLYPH_W) * scale;
}

void image_draw_text(image_t *img, int x, int y, int scale, const char *text, const uint8_t rgb[3])
{
    if (img == NULL || img->rgb == NULL || text == NULL || scale < 1)
        return;
    for (size_t i = 0; text[i] != '\0'; i++) {
        long gx = (long)x + (long)i * IMAGE_GLYPH_ADVANCE * scale;
        if (gx >= img->width)
            break;
        for (int row = 0; row < IMAGE_GLYPH_H; row++)
            for (int col = 0; col < IMAGE_GLYPH_W; col++) {
                if (!image_glyph_ink(text[i], col, row))
                    continue;
                for (int dy = 0; dy < scale; dy++)
                    for (int dx = 0; dx < scale; dx++) {
                        long px = gx + (long)col * scale + dx, py = (long)y + (long)row * scale + dy;
                        if (px < 0 || py < 0 || px >= img->width || py >= img->height)
                            continue;
                        memcpy(img->rgb + 3 * ((size_t)py * (size_t)img->width + (size_t)px), rgb, 3);
                    }
            }
    }
}
