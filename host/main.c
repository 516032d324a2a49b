/* fxrt: the host command-line tool. Renders scene files with any of the
 * three number builds and compares images. */
#include <errno.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "compare.h"
#include "engine.h"
#include "image.h"
#include "scene.h"

#define ERR_LEN 512

static const char usage_main[] =
    "usage: fxrt COMMAND [ARGS]\n"
    "\n"
    "Fixed-point (Q16.16) ray tracer: host tool.\n"
    "\n"
    "commands:\n"
    "  render SCENE [-o OUT.png|OUT.ppm] [--size WxH] [--number q16|float|double]\n"
    "                 render a scene file\n"
    "  compare A B [--diff DIFF.png] [--max-pct P] [--max-interior N]\n"
    "                 compare two images and print metrics\n"
    "\n"
    "Run 'fxrt COMMAND --help' for a command's options.\n"
    "Exit status: 0 success, 1 a compare threshold was exceeded, 2 bad input or usage.\n";

static const char usage_render[] =
    "usage: fxrt render SCENE [-o OUT] [--size WxH] [--number q16|float|double]\n"
    "\n"
    "Render SCENE (see README: scene format) and write the image.\n"
    "\n"
    "  -o, --output OUT   output file; .png (libpng) or .ppm (binary P6), chosen\n"
    "                     by the extension. Written atomically (temporary file,\n"
    "                     then rename). Default: SCENE's base name + '-NUMBER.png'\n"
    "                     in the current directory.\n"
    "  --size WxH         image size in pixels, 1..4096 each; overrides the\n"
    "                     scene's 'image' line (default 160x120 without one)\n"
    "  --number TYPE      q16 (Q16.16 fixed point, the default), float, or\n"
    "                     double (the reference)\n"
    "  -h, --help         this text\n";

static const char usage_compare[] =
    "usage: fxrt compare A B [--diff DIFF.png] [--max-pct P] [--max-interior N]\n"
    "\n"
    "Compare images A and B (PNG or PPM, same size) and print one line:\n"
    "  pixels= mismatched= mismatched_pct= max_err= psnr= edge_mismatched= interior_mismatched=\n"
    "A mismatch is a pixel whose RGB differs. It is interior when no pixel within\n"
    "1 px of it in A lies on an edge (a pixel of A whose 4-neighbour differs).\n"
    "\n"
    "  --diff DIFF        write a heat map of the differences (.png or .ppm)\n"
    "  --max-pct P        exit 1 if mismatched_pct > P\n"
    "  --max-interior N   exit 1 if interior_mismatched > N\n"
    "  -h, --help         this text\n"
    "Exit status: 0 within thresholds, 1 threshold exceeded, 2 unreadable input,\n"
    "size mismatch or bad arguments.\n";

static int fail_usage(const char *usage, const char *fmt, const char *arg)
{
    fprintf(stderr, "fxrt: ");
    fprintf(stderr, fmt, arg);
    fprintf(stderr, "\n%s", usage);
    return 2;
}

/* Strict decimal integer in [lo, hi]. */
static int parse_int(const char *s, long lo, long hi, long *out)
{
    if (*s < '0' || *s > '9')
        return -1;
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (errno || *end || v < lo || v > hi)
        return -1;
    *out = v;
    return 0;
}

static int parse_size(const char *s, int *w, int *h)
{
    const char *x = strchr(s, 'x');
    if (!x || x == s)
        return -1;
    char wbuf[16];
    size_t n = (size_t)(x - s);
    if (n >= sizeof wbuf)
        return -1;
    memcpy(wbuf, s, n);
    wbuf[n] = 0;
    long lw, lh;
    if (parse_int(wbuf, 1, FXRT_MAX_DIM, &lw) || parse_int(x + 1, 1, FXRT_MAX_DIM, &lh))
        return -1;
    *w = (int)lw;
    *h = (int)lh;
    return 0;
}

static int parse_double(const char *s, double *out)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (errno || end == s || *end || v != v || v < 0 || v > 1e9)
        return -1;
    *out = v;
    return 0;
}

/* "dir/abb6-sphere.scene" -> "abb6-sphere" */
static void base_name(const char *path, char *out, size_t len)
{
    const char *b = strrchr(path, '/');
    b = b ? b + 1 : path;
    snprintf(out, len, "%s", b);
    char *dot = strrchr(out, '.');
    if (dot && dot != out)
        *dot = 0;
}

static int cmd_render(int argc, char **argv)
{
    const char *scene_path = NULL, *out = NULL;
    int w = 0, h = 0;
    engine_number_t num = ENGINE_Q16;
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            fputs(usage_render, stdout);
            return 0;
        }
        bool takes = !strcmp(a, "-o") || !strcmp(a, "--output") || !strcmp(a, "--size") || !strcmp(a, "--number");
        if (takes && i + 1 >= argc)
            return fail_usage(usage_render, "render: %s needs a value", a);
        if (!strcmp(a, "-o") || !strcmp(a, "--output")) {
            out = argv[++i];
        } else if (!strcmp(a, "--size")) {
            if (parse_size(argv[++i], &w, &h))
                return fail_usage(usage_render, "render: bad --size '%s' (want WxH, each 1..4096)", argv[i]);
        } else if (!strcmp(a, "--number")) {
            if (engine_number_parse(argv[++i], &num))
                return fail_usage(usage_render, "render: bad --number '%s' (want q16, float or double)", argv[i]);
        } else if (a[0] == '-' && a[1]) {
            return fail_usage(usage_render, "render: unknown option '%s'", a);
        } else if (!scene_path) {
            scene_path = a;
        } else {
            return fail_usage(usage_render, "render: unexpected argument '%s'", a);
        }
    }
    if (!scene_path)
        return fail_usage(usage_render, "render: %s", "no SCENE given");

    char err[ERR_LEN];
    static scene_t scene; /* large: static, not on the stack */
    if (scene_load(scene_path, &scene, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        return 2;
    }
    if (!w) {
        w = scene.width;
        h = scene.height;
    }
    char def_out[512];
    if (!out) {
        char base[256];
        base_name(scene_path, base, sizeof base);
        snprintf(def_out, sizeof def_out, "%s-%s.png", base, engine_number_name(num));
        out = def_out;
    }
    image_t img;
    if (image_alloc(&img, w, h, err, sizeof err)) {
        fprintf(stderr, "fxrt: %s\n", err);
        return 2;
    }
    int rc = 0;
    if (engine_render(num, scene_path, &scene, w, h, img.rgb, err, sizeof err) ||
        image_write(out, &img, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        rc = 2;
    }
    image_free(&img);
    return rc;
}

static int cmd_compare(int argc, char **argv)
{
    const char *pa = NULL, *pb = NULL, *diff_path = NULL;
    double max_pct = -1;
    long max_interior = -1;
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            fputs(usage_compare, stdout);
            return 0;
        }
        bool takes = !strcmp(a, "--diff") || !strcmp(a, "--max-pct") || !strcmp(a, "--max-interior");
        if (takes && i + 1 >= argc)
            return fail_usage(usage_compare, "compare: %s needs a value", a);
        if (!strcmp(a, "--diff")) {
            diff_path = argv[++i];
        } else if (!strcmp(a, "--max-pct")) {
            if (parse_double(argv[++i], &max_pct))
                return fail_usage(usage_compare, "compare: bad --max-pct '%s' (want a number >= 0)", argv[i]);
        } else if (!strcmp(a, "--max-interior")) {
            if (parse_int(argv[++i], 0, 1000000000L, &max_interior))
                return fail_usage(usage_compare, "compare: bad --max-interior '%s' (want an integer >= 0)", argv[i]);
        } else if (a[0] == '-' && a[1]) {
            return fail_usage(usage_compare, "compare: unknown option '%s'", a);
        } else if (!pa) {
            pa = a;
        } else if (!pb) {
            pb = a;
        } else {
            return fail_usage(usage_compare, "compare: unexpected argument '%s'", a);
        }
    }
    if (!pb)
        return fail_usage(usage_compare, "compare: %s", "needs two images A and B");

    char err[ERR_LEN];
    image_t a = {0}, b = {0}, diff = {0};
    int rc = 2;
    compare_result_t res;
    if (image_read(pa, &a, err, sizeof err) || image_read(pb, &b, err, sizeof err) ||
        compare_images(&a, &b, &res, diff_path ? &diff : NULL, err, sizeof err) ||
        (diff_path && image_write(diff_path, &diff, err, sizeof err))) {
        fprintf(stderr, "fxrt: compare: %s\n", err);
        goto done;
    }
    compare_print(stdout, &res);
    rc = 0;
    if (max_pct >= 0 && res.mismatched_pct > max_pct) {
        fprintf(stderr, "fxrt: compare: mismatched_pct %.4f > %.4f\n", res.mismatched_pct, max_pct);
        rc = 1;
    }
    if (max_interior >= 0 && res.interior_mismatched > max_interior) {
        fprintf(stderr, "fxrt: compare: interior_mismatched %ld > %ld\n", res.interior_mismatched, max_interior);
        rc = 1;
    }
done:
    image_free(&a);
    image_free(&b);
    image_free(&diff);
    return rc;
}

int main(int argc, char **argv)
{
    if (argc < 2)
        return fail_usage(usage_main, "%s", "missing command");
    const char *cmd = argv[1];
    if (!strcmp(cmd, "-h") || !strcmp(cmd, "--help") || !strcmp(cmd, "help")) {
        fputs(usage_main, stdout);
        return 0;
    }
    if (!strcmp(cmd, "render"))
        return cmd_render(argc - 2, argv + 2);
    if (!strcmp(cmd, "compare"))
        return cmd_compare(argc - 2, argv + 2);
    return fail_usage(usage_main, "unknown command '%s'", cmd);
}
