/* fxrt: the host command-line tool. Renders scene files with any of the
 * three number builds and compares images. */
#include <errno.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
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
    "         [--renderer fast|reference|raycast]\n"
    "                 render a scene file\n"
    "  compare A B [--diff DIFF.png] [--max-pct P] [--max-interior N]\n"
    "                 compare two images and print metrics\n"
    "  sheet OUT IMAGE...\n"
    "                 place images of equal height side by side (8 px gaps)\n"
    "\n"
    "Run 'fxrt COMMAND --help' for a command's options.\n"
    "Exit status: 0 success, 1 a compare threshold was exceeded, 2 bad input or usage.\n";

static const char usage_render[] =
    "usage: fxrt render SCENE [-o OUT] [--size WxH] [--number q16|float|double]\n"
    "                         [--renderer fast|reference|raycast]\n"
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
    "  --renderer R       fast (the scanline renderer, the default), reference\n"
    "                     (every object's forms tested at every pixel; Q16.16\n"
    "                     output is byte-identical, it only takes longer) or\n"
    "                     raycast (a camera ray and a nearest-hit search per\n"
    "                     pixel: the independent oracle and naive baseline)\n"
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
    engine_renderer_t renderer = ENGINE_FAST;
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            fputs(usage_render, stdout);
            return 0;
        }
        bool takes = !strcmp(a, "-o") || !strcmp(a, "--output") || !strcmp(a, "--size") || !strcmp(a, "--number") ||
                     !strcmp(a, "--renderer");
        if (takes && i + 1 >= argc)
            return fail_usage(usage_render, "render: %s needs a value", a);
        if (!strcmp(a, "-o") || !strcmp(a, "--output")) {
            out = argv[++i];
        } else if (!strcmp(a, "--size")) {
            if (args_size(argv[++i], &w, &h))
                return fail_usage(usage_render, "render: bad --size '%s' (want WxH, each 1..4096)", argv[i]);
        } else if (!strcmp(a, "--number")) {
            if (engine_number_parse(argv[++i], &num))
                return fail_usage(usage_render, "render: bad --number '%s' (want q16, float or double)", argv[i]);
        } else if (!strcmp(a, "--renderer")) {
            const char *v = argv[++i];
            if (engine_renderer_parse(v, &renderer))
                return fail_usage(usage_render, "render: bad --renderer '%s' (want fast, reference or raycast)", v);
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
    if (engine_render(num, scene_path, &scene, w, h, renderer, img.rgb, err, sizeof err) ||
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
            if (args_int(argv[++i], 0, 1000000000L, &max_interior))
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

static const char usage_sheet[] =
    "usage: fxrt sheet OUT.png|OUT.ppm IMAGE...\n"
    "\n"
    "Place the images (PNG or PPM, all of the same height) left to right with\n"
    "8-pixel grey gaps, e.g. a Q16.16 render, its reference and their diff.\n";

#define SHEET_GAP 8
#define SHEET_MAX 16

static int cmd_sheet(int argc, char **argv)
{
    if (argc >= 1 && (!strcmp(argv[0], "-h") || !strcmp(argv[0], "--help"))) {
        fputs(usage_sheet, stdout);
        return 0;
    }
    if (argc < 2)
        return fail_usage(usage_sheet, "sheet: %s", "needs OUT and at least one IMAGE");
    if (argc - 1 > SHEET_MAX)
        return fail_usage(usage_sheet, "sheet: %s", "at most 16 images");
    char err[ERR_LEN];
    image_t in[SHEET_MAX] = {{0}}, out = {0};
    int n = argc - 1, width = 0, rc = 2;
    for (int i = 0; i < n; i++) {
        if (image_read(argv[1 + i], &in[i], err, sizeof err)) {
            fprintf(stderr, "fxrt: sheet: %s\n", err);
            goto done;
        }
        if (in[i].height != in[0].height) {
            fprintf(stderr, "fxrt: sheet: %s: height %d differs from %d\n", argv[1 + i], in[i].height,
                    in[0].height);
            goto done;
        }
        width += in[i].width + (i ? SHEET_GAP : 0);
    }
    if (width > IMAGE_MAX_DIM) {
        fprintf(stderr, "fxrt: sheet: combined width %d too large\n", width);
        goto done;
    }
    if (image_alloc(&out, width, in[0].height, err, sizeof err)) {
        fprintf(stderr, "fxrt: sheet: %s\n", err);
        goto done;
    }
    memset(out.rgb, 96, (size_t)3 * out.width * out.height);
    for (int i = 0, x0 = 0; i < n; x0 += in[i].width + SHEET_GAP, i++)
        for (int y = 0; y < in[i].height; y++)
            memcpy(out.rgb + 3 * ((size_t)y * out.width + x0), in[i].rgb + (size_t)3 * y * in[i].width,
                   (size_t)3 * in[i].width);
    if (image_write(argv[0], &out, err, sizeof err)) {
        fprintf(stderr, "fxrt: sheet: %s\n", err);
        goto done;
    }
    rc = 0;
done:
    for (int i = 0; i < n; i++)
        image_free(&in[i]);
    image_free(&out);
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
    if (!strcmp(cmd, "sheet"))
        return cmd_sheet(argc - 2, argv + 2);
    return fail_usage(usage_main, "unknown command '%s'", cmd);
}
