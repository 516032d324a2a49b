/* fxrt: the host command-line tool. Renders scene files with any of the
 * three number builds and compares images. */
#include <errno.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "args.h"
#include "compare.h"
#include "engine.h"
#include "image.h"
#include "obj.h"
#include "scene.h"
#include "version.h"

#define ERR_LEN 512

#if defined(__GNUC__)
#define MAIN_PRINTF(fmt, args) __attribute__((format(printf, fmt, args)))
#else
#define MAIN_PRINTF(fmt, args)
#endif

static const char usage_main[] =
    "usage: fxrt COMMAND [ARGS]\n"
    "\n"
    "Fixed-point (Q16.16) ray tracer: host tool.\n"
    "\n"
    "commands:\n"
    "  render SCENE [-o OUT.png|OUT.ppm] [--size WxH] [--number q16|float|double]\n"
    "         [--renderer fast|reference|raycast] [--keys KEYS.png]\n"
    "                 render a scene file\n"
    "  compare A B [--scene SCENE] [--diff DIFF.png] [--max-pct P] [--max-interior N]\n"
    "                 compare two images and print metrics\n"
    "  sheet -o OUT IMAGE[=LABEL]... [--no-labels]\n"
    "                 place labelled images of equal height side by side\n"
    "  size SCENE     print the scene's image size as WxH (its 'image' line)\n"
    "  obj FILE       check an OBJ mesh and print what it holds\n"
    "\n"
    "  -h, --help     this text; 'fxrt COMMAND --help' for a command's options\n"
    "  --version      print the version\n"
    "\n"
    "Exit status: 0 success, 1 a compare threshold was exceeded, 2 bad input or\n"
    "usage (one line on stderr saying what is wrong; FILE:LINE: for scenes).\n";

static const char usage_render[] =
    "usage: fxrt render SCENE [-o OUT] [--size WxH] [--number q16|float|double]\n"
    "                         [--renderer fast|reference|raycast] [--keys KEYS]\n"
    "\n"
    "Render SCENE (scene format: docs/SCENES.md) and write the image.\n"
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
    "  --keys KEYS        also write a picture of the pixels' keys (.png or .ppm):\n"
    "                     one colour per key (object id and the set of lights\n"
    "                     that reach the hit point), black for the background;\n"
    "                     the ray caster writes no keys (all black)\n"
    "  -h, --help         this text\n"
    "Each option may be given once; '--' ends the options.\n"
    "Exit status: 0 written, 2 bad scene (FILE:LINE: message), unwritable output\n"
    "or bad arguments; nothing is written on failure.\n";

static const char usage_compare[] =
    "usage: fxrt compare A B [--scene SCENE] [--diff DIFF.png] [--max-pct P]\n"
    "                        [--max-interior N]\n"
    "\n"
    "Compare images A and B (PNG or PPM, same size) and print one line:\n"
    "  pixels= mismatched= mismatched_pct= max_err= psnr= edge_mismatched= interior_mismatched=\n"
    "  within1_pct= within2_pct= near_pixels= far_pixels= far_within1_pct= far_within2_pct=\n"
    "  far_max_err= near_max_err= near_within1_pct= near_within2_pct= mae=\n"
    "mae is the mean absolute error per channel over all pixels, in 1/255.\n"
    "A mismatch is a pixel whose RGB differs. It is interior when no pixel within\n"
    "1 px of it in A lies on an edge (a pixel of A whose 4-neighbour differs).\n"
    "A pixel's error is its largest channel difference in units of 1/255;\n"
    "withinK_pct is the share of pixels with error <= K (rounded down).\n"
    "near/far: with --scene, a pixel is near a discontinuity when one of its 8\n"
    "neighbours has another key (object, and lights reaching it) in the double\n"
    "render of SCENE; far_* and near_* count each set (a share of no pixels is\n"
    "100). Without --scene every pixel is far (near_pixels=0).\n"
    "\n"
    "  --scene SCENE      render SCENE in double (fast renderer) at the images'\n"
    "                     size for the key map; a bad SCENE is an error\n"
    "  --diff DIFF        write a heat map of the differences (.png or .ppm):\n"
    "                     black = equal; pixel error 1 = dark red (128,0,0),\n"
    "                     rising linearly to red at 6, yellow at 11 and white at\n"
    "                     16 and above. With --scene, equal pixels near a\n"
    "                     discontinuity are dark blue (0,0,72). For identical\n"
    "                     images it says 'identical'. DIFF must not be A, B or\n"
    "                     SCENE (same path or same file)\n"
    "  --max-pct P        exit 1 if mismatched_pct > P\n"
    "  --max-interior N   exit 1 if interior_mismatched > N\n"
    "  -h, --help         this text\n"
    "Each option may be given once; '--' ends the options.\n"
    "Exit status: 0 within thresholds, 1 threshold exceeded, 2 unreadable input,\n"
    "bad scene, size mismatch or bad arguments; nothing is written on error.\n";

static const char usage_sheet[] =
    "usage: fxrt sheet -o OUT.png|OUT.ppm IMAGE[=LABEL]... [--no-labels]\n"
    "\n"
    "Place the images (PNG or PPM, all of the same height, at most 16) left to\n"
    "right with 8-pixel grey gaps, each under a label, e.g. a Q16.16 render,\n"
    "its reference and their diff:\n"
    "  fxrt sheet -o s.png q.ppm='Q16.16 (QEMU)' d.png=double diff.png=diff\n"
    "\n"
    "  -o, --output OUT   the sheet (.png or .ppm); required, and it must not be\n"
    "                     one of the IMAGEs (same path or same file)\n"
    "  IMAGE=LABEL        the text above that image (printable ASCII; the text\n"
    "                     after the last '='); without one, the file's base name.\n"
    "                     A file whose name holds '=' is written 'NAME=' or\n"
    "                     'NAME=LABEL'\n"
    "  --no-labels        no label strip (one IMAGE converts PPM <-> PNG)\n"
    "  -h, --help         this text\n"
    "Each option may be given once; '--' ends the options.\n"
    "Exit status: 0 written, 2 unreadable input, heights differ or bad arguments.\n";

static const char usage_size[] =
    "usage: fxrt size SCENE\n"
    "\n"
    "Check SCENE and print its image size as WxH: the 'image' line, or 160x120\n"
    "without one (make qemu uses it when SIZE= is not given).\n"
    "Exit status: 0, or 2 for a bad scene (FILE:LINE: message).\n";

static const char usage_obj[] =
    "usage: fxrt obj FILE\n"
    "\n"
    "Read the Wavefront OBJ mesh FILE as a scene's mesh statement would\n"
    "(docs/SCENES.md, \"OBJ files\") and print one 'name value' line each: its\n"
    "faces, triangles (each face fanned from its first vertex), vertices,\n"
    "texture coordinates, normals, the triangle corners whose normal is the\n"
    "file's vn (the others take the smooth-shading normal), and the bounds.\n"
    "Exit status: 0, or 2 for a bad file (FILE:LINE: message).\n";

/* A usage error: one line "fxrt: [CMD: ]message" and a pointer to the help
 * on stderr; returns the exit status 2. cmd is NULL for the top level. */
static int usage_error(const char *cmd, const char *fmt, ...) MAIN_PRINTF(2, 3);
static int usage_error(const char *cmd, const char *fmt, ...)
{
    va_list ap;

    fputs("fxrt: ", stderr);
    if (cmd)
        fprintf(stderr, "%s: ", cmd);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    if (cmd)
        fprintf(stderr, "\nTry 'fxrt %s --help'.\n", cmd);
    else
        fputs("\nTry 'fxrt --help'.\n", stderr);
    return 2;
}

/* True when the arguments before any "--" ask for help. */
static bool wants_help(int argc, char **argv)
{
    for (int i = 0; i < argc && strcmp(argv[i], "--"); i++)
        if (!strcmp(argv[i], "-h") || !strcmp(argv[i], "--help"))
            return true;
    return false;
}

/* The value of the option at argv[*i] (advancing *i past it), or NULL after
 * a usage error: the option was already given (*seen holds its first
 * spelling) or has no value. */
static const char *opt_value(const char *cmd, int argc, char **argv, int *i, const char **seen)
{
    const char *name = argv[*i];
    if (*seen) {
        if (strcmp(*seen, name))
            usage_error(cmd, "%s given twice (also as %s)", name, *seen);
        else
            usage_error(cmd, "%s given twice", name);
        return NULL;
    }
    if (*i + 1 >= argc) {
        usage_error(cmd, "%s needs a value", name);
        return NULL;
    }
    if (!argv[*i + 1][0]) {
        usage_error(cmd, "%s needs a non-empty value", name);
        return NULL;
    }
    *seen = name;
    return argv[++*i];
}

/* True when writing out would replace the input in: the same path, or the
 * same existing file (device and inode: ./a.png, a hard or symbolic link). */
static bool same_file(const char *out, const char *in)
{
    struct stat so, si;

    if (!strcmp(out, in))
        return true;
    return stat(out, &so) == 0 && stat(in, &si) == 0 && so.st_dev == si.st_dev && so.st_ino == si.st_ino;
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
    static const char cmd[] = "render";
    const char *scene_path = NULL, *out = NULL, *keys_path = NULL;
    const char *seen_out = NULL, *seen_size = NULL, *seen_number = NULL, *seen_renderer = NULL, *seen_keys = NULL;
    int w = 0, h = 0;
    engine_number_t num = ENGINE_Q16;
    engine_renderer_t renderer = ENGINE_FAST;
    bool opts = true;
    if (wants_help(argc, argv)) {
        fputs(usage_render, stdout);
        return 0;
    }
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i], *v;
        if (opts && !strcmp(a, "--")) {
            opts = false;
        } else if (opts && (!strcmp(a, "-o") || !strcmp(a, "--output"))) {
            if (!(out = opt_value(cmd, argc, argv, &i, &seen_out)))
                return 2;
        } else if (opts && !strcmp(a, "--size")) {
            if (!(v = opt_value(cmd, argc, argv, &i, &seen_size)))
                return 2;
            if (args_size(v, &w, &h))
                return usage_error(cmd, "bad --size '%s' (want WxH, each 1..%d)", v, FXRT_MAX_DIM);
        } else if (opts && !strcmp(a, "--number")) {
            if (!(v = opt_value(cmd, argc, argv, &i, &seen_number)))
                return 2;
            if (engine_number_parse(v, &num))
                return usage_error(cmd, "bad --number '%s' (want q16, float or double)", v);
        } else if (opts && !strcmp(a, "--renderer")) {
            if (!(v = opt_value(cmd, argc, argv, &i, &seen_renderer)))
                return 2;
            if (engine_renderer_parse(v, &renderer))
                return usage_error(cmd, "bad --renderer '%s' (want fast, reference or raycast)", v);
        } else if (opts && !strcmp(a, "--keys")) {
            if (!(keys_path = opt_value(cmd, argc, argv, &i, &seen_keys)))
                return 2;
        } else if (opts && a[0] == '-' && a[1]) {
            return usage_error(cmd, "unknown option '%s'", a);
        } else if (!scene_path) {
            scene_path = a;
        } else {
            return usage_error(cmd, "unexpected argument '%s' (one SCENE only)", a);
        }
    }
    if (!scene_path)
        return usage_error(cmd, "no SCENE given");

    char err[ERR_LEN];
    static scene_t scene; /* large: static, not on the stack */
    if (scene_load(scene_path, &scene, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        return 2;
    }
    if (scene.mesh_dropped > 0)
        fprintf(stderr, "%s: note: %ld zero-area mesh triangle%s left out\n", scene_path, scene.mesh_dropped,
                scene.mesh_dropped == 1 ? "" : "s");
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
    if (same_file(out, scene_path))
        return usage_error(cmd, "output '%s' is the scene file itself", out);
    if (keys_path && same_file(keys_path, scene_path))
        return usage_error(cmd, "--keys '%s' is the scene file itself", keys_path);
    if (keys_path && same_file(keys_path, out))
        return usage_error(cmd, "--keys '%s' is the output image too", keys_path);
    /* Output names that cannot be written fail before the render. */
    if (image_check_path(out, err, sizeof err) || (keys_path && image_check_path(keys_path, err, sizeof err))) {
        fprintf(stderr, "fxrt: render: %s\n", err);
        return 2;
    }
    image_t img = {0}, kimg = {0};
    uint32_t *keys = NULL;
    if (image_alloc(&img, w, h, err, sizeof err)) {
        fprintf(stderr, "fxrt: %s\n", err);
        return 2;
    }
    if (keys_path && !(keys = malloc(sizeof *keys * (size_t)w * (size_t)h))) {
        fprintf(stderr, "fxrt: render: out of memory for the key map\n");
        image_free(&img);
        return 2;
    }
    /* The key picture is made before either file is written, and both
     * are written to temporary files before either is renamed into place,
     * so a failure leaves neither. */
    int rc = 0;
    static char tmp_out[IMAGE_TMP_MAX], tmp_keys[IMAGE_TMP_MAX];
    if (engine_render(num, scene_path, &scene, w, h, renderer, img.rgb, keys, err, sizeof err) ||
        (keys && compare_keys_image(keys, w, h, ENGINE_KEY_MISS, &kimg, err, sizeof err)) ||
        image_write_tmp(out, &img, tmp_out, sizeof tmp_out, err, sizeof err) ||
        (keys && image_write_tmp(keys_path, &kimg, tmp_keys, sizeof tmp_keys, err, sizeof err)) ||
        image_write_commit(tmp_out, out, err, sizeof err) ||
        (keys && image_write_commit(tmp_keys, keys_path, err, sizeof err))) {
        image_write_abort(tmp_out);
        image_write_abort(tmp_keys);
        fprintf(stderr, "%s\n", err);
        rc = 2;
    }
    free(keys);
    image_free(&kimg);
    image_free(&img);
    return rc;
}

/* Write "identical" across the middle of a diff map (which is all black
 * when the images are equal), as large as fits in 3/4 of its width. */
static void mark_identical(image_t *diff)
{
    static const char text[] = "identical";
    static const uint8_t grey[3] = {200, 200, 200};
    int scale = 1;
    while (image_text_width(text, scale + 1) <= diff->width * 3 / 4 &&
           (scale + 1) * IMAGE_GLYPH_H <= diff->height / 2)
        scale++;
    int x = (diff->width - image_text_width(text, scale)) / 2;
    int y = (diff->height - (IMAGE_GLYPH_H - 1) * scale) / 2;
    image_draw_text(diff, x < 0 ? 0 : x, y < 0 ? 0 : y, scale, text, grey);
}

static int cmd_compare(int argc, char **argv)
{
    static const char cmd[] = "compare";
    const char *pa = NULL, *pb = NULL, *diff_path = NULL, *scene_path = NULL;
    const char *seen_diff = NULL, *seen_pct = NULL, *seen_interior = NULL, *seen_scene = NULL;
    double max_pct = -1;
    long max_interior = -1;
    bool opts = true;
    if (wants_help(argc, argv)) {
        fputs(usage_compare, stdout);
        return 0;
    }
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i], *v;
        if (opts && !strcmp(a, "--")) {
            opts = false;
        } else if (opts && !strcmp(a, "--diff")) {
            if (!(diff_path = opt_value(cmd, argc, argv, &i, &seen_diff)))
                return 2;
        } else if (opts && !strcmp(a, "--scene")) {
            if (!(scene_path = opt_value(cmd, argc, argv, &i, &seen_scene)))
                return 2;
        } else if (opts && !strcmp(a, "--max-pct")) {
            if (!(v = opt_value(cmd, argc, argv, &i, &seen_pct)))
                return 2;
            if (parse_double(v, &max_pct))
                return usage_error(cmd, "bad --max-pct '%s' (want a number >= 0)", v);
        } else if (opts && !strcmp(a, "--max-interior")) {
            if (!(v = opt_value(cmd, argc, argv, &i, &seen_interior)))
                return 2;
            if (args_int(v, 0, 1000000000L, &max_interior))
                return usage_error(cmd, "bad --max-interior '%s' (want an integer >= 0)", v);
        } else if (opts && a[0] == '-' && a[1]) {
            return usage_error(cmd, "unknown option '%s'", a);
        } else if (!pa) {
            pa = a;
        } else if (!pb) {
            pb = a;
        } else {
            return usage_error(cmd, "unexpected argument '%s' (two images A and B only)", a);
        }
    }
    if (!pb)
        return usage_error(cmd, "needs two images A and B");
    if (diff_path && (same_file(diff_path, pa) || same_file(diff_path, pb)))
        return usage_error(cmd, "--diff '%s' would overwrite the input '%s'", diff_path,
                           same_file(diff_path, pa) ? pa : pb);
    if (diff_path && scene_path && same_file(diff_path, scene_path))
        return usage_error(cmd, "--diff '%s' would overwrite the input '%s'", diff_path, scene_path);

    char err[ERR_LEN];
    image_t a = {0}, b = {0}, diff = {0};
    uint32_t *keys = NULL;
    static scene_t scene; /* large: static, not on the stack */
    int rc = 2;
    compare_result_t res;
    if (image_read(pa, &a, err, sizeof err) || image_read(pb, &b, err, sizeof err)) {
        fprintf(stderr, "fxrt: compare: %s\n", err);
        goto done;
    }
    if (scene_path) {
        /* The key map: the double render of the scene (fast renderer) at
         * the images' size, never the images under test. */
        if (a.width != b.width || a.height != b.height) {
            fprintf(stderr, "fxrt: compare: size mismatch: %dx%d vs %dx%d\n", a.width, a.height, b.width, b.height);
            goto done;
        }
        if (a.width > FXRT_MAX_DIM || a.height > FXRT_MAX_DIM) {
            fprintf(stderr, "fxrt: compare: --scene: images of %dx%d are larger than a render (at most %dx%d)\n",
                    a.width, a.height, FXRT_MAX_DIM, FXRT_MAX_DIM);
            goto done;
        }
        /* Scene errors as `render` prints them: FILE:LINE: first. */
        if (scene_load(scene_path, &scene, err, sizeof err)) {
            fprintf(stderr, "%s\n", err);
            goto done;
        }
        keys = malloc(sizeof *keys * (size_t)a.width * (size_t)a.height);
        if (!keys) {
            fprintf(stderr, "fxrt: compare: out of memory for the key map\n");
            goto done;
        }
        /* The keys only (no image): at one sample per pixel whatever the
         * scene's samples, so a scene whose samples x width is too wide to
         * render still gives them. */
        if (engine_render(ENGINE_DOUBLE, scene_path, &scene, a.width, a.height, ENGINE_FAST, NULL, keys, err,
                          sizeof err)) {
            fprintf(stderr, "%s\n", err);
            goto done;
        }
    }
    if (compare_images_keyed(&a, &b, keys, &res, diff_path ? &diff : NULL, err, sizeof err)) {
        fprintf(stderr, "fxrt: compare: %s\n", err);
        goto done;
    }
    if (diff_path && res.mismatched == 0)
        mark_identical(&diff);
    if (diff_path && image_write(diff_path, &diff, err, sizeof err)) {
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
    free(keys);
    image_free(&a);
    image_free(&b);
    image_free(&diff);
    return rc;
}

#define SHEET_GAP 8
#define SHEET_MAX 16
#define SHEET_LABEL_MAX 200

/* The label strip: text at SHEET_SCALE(h) font pixels per glyph pixel
 * (2 for panels 300 px high or more, else 1), with a margin of 3 font
 * pixels above and below. */
#define SHEET_SCALE(h) ((h) >= 300 ? 2 : 1)
#define SHEET_STRIP(scale) ((IMAGE_GLYPH_H + 6) * (scale))

static int cmd_sheet(int argc, char **argv)
{
    static const char cmd[] = "sheet";
    static const uint8_t ink[3] = {255, 255, 255};
    const char *out_path = NULL, *seen_out = NULL, *seen_nolabels = NULL;
    char paths[SHEET_MAX][ERR_LEN], labels[SHEET_MAX][SHEET_LABEL_MAX + 1];
    int n = 0;
    bool opts = true, with_labels = true;
    if (wants_help(argc, argv)) {
        fputs(usage_sheet, stdout);
        return 0;
    }
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        if (opts && !strcmp(a, "--")) {
            opts = false;
        } else if (opts && (!strcmp(a, "-o") || !strcmp(a, "--output"))) {
            if (!(out_path = opt_value(cmd, argc, argv, &i, &seen_out)))
                return 2;
        } else if (opts && !strcmp(a, "--no-labels")) {
            if (seen_nolabels)
                return usage_error(cmd, "%s given twice", a);
            seen_nolabels = a;
            with_labels = false;
        } else if (opts && a[0] == '-' && a[1]) {
            return usage_error(cmd, "unknown option '%s'", a);
        } else if (n == SHEET_MAX) {
            return usage_error(cmd, "at most %d images", SHEET_MAX);
        } else {
            /* IMAGE[=LABEL]: the label is what follows the last '='. */
            const char *eq = strrchr(a, '=');
            size_t plen = eq ? (size_t)(eq - a) : strlen(a);
            if (plen == 0)
                return usage_error(cmd, "'%s' has no image before the '='", a);
            if (plen >= sizeof paths[n])
                return usage_error(cmd, "image path too long");
            memcpy(paths[n], a, plen);
            paths[n][plen] = 0;
            if (eq && eq[1]) {
                if (strlen(eq + 1) > SHEET_LABEL_MAX)
                    return usage_error(cmd, "label '%.20s...' longer than %d characters", eq + 1, SHEET_LABEL_MAX);
                for (const char *c = eq + 1; *c; c++)
                    if ((unsigned char)*c < 0x20 || (unsigned char)*c > 0x7e)
                        return usage_error(cmd, "label '%s' is not printable ASCII", eq + 1);
                snprintf(labels[n], sizeof labels[n], "%s", eq + 1);
            } else {
                const char *b = strrchr(paths[n], '/');
                snprintf(labels[n], sizeof labels[n], "%s", b ? b + 1 : paths[n]);
            }
            n++;
        }
    }
    if (!out_path)
        return usage_error(cmd, "no output given (-o OUT; the images follow)");
    if (n == 0)
        return usage_error(cmd, "no IMAGE given");
    for (int i = 0; i < n; i++)
        if (same_file(out_path, paths[i]))
            return usage_error(cmd, "output '%s' would overwrite the input '%s'", out_path, paths[i]);

    char err[ERR_LEN];
    image_t in[SHEET_MAX] = {{0}}, out = {0};
    int width = 0, rc = 2;
    for (int i = 0; i < n; i++) {
        if (image_read(paths[i], &in[i], err, sizeof err)) {
            fprintf(stderr, "fxrt: sheet: %s\n", err);
            goto done;
        }
        if (in[i].height != in[0].height) {
            fprintf(stderr, "fxrt: sheet: %s: height %d differs from %d\n", paths[i], in[i].height,
                    in[0].height);
            goto done;
        }
        width += in[i].width + (i ? SHEET_GAP : 0);
    }
    int scale = SHEET_SCALE(in[0].height);
    int strip = with_labels ? SHEET_STRIP(scale) : 0;
    if (width > IMAGE_MAX_DIM || in[0].height + strip > IMAGE_MAX_DIM) {
        fprintf(stderr, "fxrt: sheet: combined size %dx%d too large\n", width, in[0].height + strip);
        goto done;
    }
    if (image_alloc(&out, width, in[0].height + strip, err, sizeof err)) {
        fprintf(stderr, "fxrt: sheet: %s\n", err);
        goto done;
    }
    memset(out.rgb, 96, (size_t)3 * out.width * out.height);
    for (int i = 0, x0 = 0; i < n; x0 += in[i].width + SHEET_GAP, i++) {
        for (int y = 0; y < in[i].height; y++)
            memcpy(out.rgb + 3 * ((size_t)(y + strip) * out.width + x0), in[i].rgb + (size_t)3 * y * in[i].width,
                   (size_t)3 * in[i].width);
        if (!with_labels)
            continue;
        /* Centred over its panel; a label wider than the panel loses the
         * characters that do not fit whole. */
        size_t fit = (size_t)((in[i].width + (IMAGE_GLYPH_ADVANCE - IMAGE_GLYPH_W) * scale) /
                              (IMAGE_GLYPH_ADVANCE * scale));
        if (strlen(labels[i]) > fit)
            labels[i][fit] = 0;
        int tx = x0 + (in[i].width - image_text_width(labels[i], scale)) / 2;
        image_draw_text(&out, tx, 3 * scale, scale, labels[i], ink);
    }
    if (image_write(out_path, &out, err, sizeof err)) {
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

/* A command's one path argument (named `what` in messages) into *path:
 * 0, or the exit status of a usage error. --help prints `usage` and
 * leaves *path NULL (exit 0). */
static int one_path(const char *cmd, const char *what, const char *usage, int argc, char **argv, const char **path)
{
    bool opts = true;
    *path = NULL;
    if (wants_help(argc, argv)) {
        fputs(usage, stdout);
        return 0;
    }
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        if (opts && !strcmp(a, "--"))
            opts = false;
        else if (opts && a[0] == '-' && a[1])
            return usage_error(cmd, "unknown option '%s'", a);
        else if (!*path)
            *path = a;
        else
            return usage_error(cmd, "unexpected argument '%s' (one %s only)", a, what);
    }
    if (!*path)
        return usage_error(cmd, "no %s given", what);
    return 0;
}

static int cmd_size(int argc, char **argv)
{
    const char *scene_path;
    int u = one_path("size", "SCENE", usage_size, argc, argv, &scene_path);
    if (u || !scene_path)
        return u;
    char err[ERR_LEN];
    static scene_t scene;
    if (scene_load(scene_path, &scene, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        return 2;
    }
    printf("%dx%d\n", scene.width, scene.height);
    return 0;
}

static int cmd_obj(int argc, char **argv)
{
    const char *path;
    int u = one_path("obj", "FILE", usage_obj, argc, argv, &path);
    if (u || !path)
        return u;
    char err[ERR_LEN];
    obj_t o;
    if (obj_load(path, &o, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        obj_free(&o);
        return 2;
    }
    obj_vec_t *n = malloc(sizeof *n * 3 * o.ntri);
    size_t from_file = 0;
    if (n == NULL || obj_smooth_normals(&o, n, &from_file)) {
        fprintf(stderr, "%s: out of memory\n", path);
        free(n);
        obj_free(&o);
        return 2;
    }
    obj_vec_t lo = o.v[o.tri[0].v[0]], hi = lo;
    for (size_t i = 0; i < o.ntri; i++)
        for (int k = 0; k < 3; k++) {
            obj_vec_t p = o.v[o.tri[i].v[k]];
            lo = (obj_vec_t){p.x < lo.x ? p.x : lo.x, p.y < lo.y ? p.y : lo.y, p.z < lo.z ? p.z : lo.z};
            hi = (obj_vec_t){p.x > hi.x ? p.x : hi.x, p.y > hi.y ? p.y : hi.y, p.z > hi.z ? p.z : hi.z};
        }
    printf("faces %zu\ntriangles %zu\nvertices %zu\ntexcoords %zu\nnormals %zu\n", o.nfaces, o.ntri, o.nv, o.nvt,
           o.nvn);
    size_t zero = 0;
    for (size_t i = 0; i < o.ntri; i++) {
        obj_vec_t c = obj_face_normal(&o, i);
        zero += c.x == 0.0 && c.y == 0.0 && c.z == 0.0;
    }
    printf("zero_area %zu\n", zero);
    printf("corners_with_vn %zu of %zu\n", from_file, 3 * o.ntri);
    printf("bounds %.9g %.9g %.9g %.9g %.9g %.9g\n", lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
    free(n);
    obj_free(&o);
    return 0;
}

int main(int argc, char **argv)
{
    image_cleanup_signals();
    if (argc < 2)
        return usage_error(NULL, "missing command (render, compare, sheet, size or obj)");
    const char *cmd = argv[1];
    if (!strcmp(cmd, "-h") || !strcmp(cmd, "--help") || !strcmp(cmd, "help")) {
        fputs(usage_main, stdout);
        return 0;
    }
    if (!strcmp(cmd, "--version")) {
        if (argc > 2)
            return usage_error(NULL, "unexpected argument '%s' after --version", argv[2]);
#ifdef FXRT_GIT_DESCRIBE
        printf("fxrt %s (git %s)\n", FXRT_VERSION, FXRT_GIT_DESCRIBE);
#else
        printf("fxrt %s\n", FXRT_VERSION);
#endif
        return 0;
    }
    if (!strcmp(cmd, "render"))
        return cmd_render(argc - 2, argv + 2);
    if (!strcmp(cmd, "compare"))
        return cmd_compare(argc - 2, argv + 2);
    if (!strcmp(cmd, "sheet"))
        return cmd_sheet(argc - 2, argv + 2);
    if (!strcmp(cmd, "size"))
        return cmd_size(argc - 2, argv + 2);
    if (!strcmp(cmd, "obj"))
        return cmd_obj(argc - 2, argv + 2);
    if (cmd[0] == '-')
        return usage_error(NULL, "unknown option '%s'", cmd);
    return usage_error(NULL, "unknown command '%s'", cmd);
}
