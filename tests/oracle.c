/* oracle: the fast scanline renderer (render_row: camera-space polynomial
 * forms stepped along rows) against the per-pixel ray caster (raycast_row:
 * cam_ray and world_hit at every pixel), which shares none of its
 * algorithm. Both run in Q16.16 and in double; each build is compared with
 * itself (fast q16 with raycast q16, fast double with raycast double).
 *
 * The silhouette band: a pixel is within 1 px of a silhouette when its
 * 3x3 neighbourhood (clipped at the image border) in the ray caster's id
 * map of the same build holds more than one id (a miss counts as an id).
 * Outside the band the two renderers must agree exactly (asserted); inside
 * it a mismatch only moves a silhouette (counted and reported, with one
 * stated cap per build, see ORACLE_BAND_CAP_Q16).
 *
 *   oracle [--random N] [--seed S] [--known FILE] [-v] [SCENE...]
 *       SCENE files at their own size (a file whose header says
 *       "# expect: rejected:" must be refused by both builds, any other
 *       must render), then N random scenes (tests/randscene.c) with the
 *       seeds S, S+1, ... S+N-1.
 *   oracle --print-scene SEED     the text of one random scene
 *   oracle --stress-expect [--write] SCENE...
 *       the generated "# expect:" lines of stress scenes, from the double
 *       ray caster (see stress_expect below); without --write it checks
 *       that the files hold exactly what it would write.
 *
 * Ends with "oracle: N passed, N failed" (or "stress-expect: ..."). */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../core/frame/raycast.h"
#include "oracle.h"
#include "randscene.h"

/* Largest frame the oracle renders (the largest scene in scenes/ is far
 * smaller; FXRT_MAX_DIM squared would not fit memory comfortably). */
#define ORACLE_MAX_PIXELS (4096 * 1024)

/* Stated caps on silhouette-band mismatches: at most this fraction of a
 * build's band pixels, summed over all scenes of a run (frames listed as
 * known findings excluded). The band holds the pixels whose centre lies
 * within about a pixel of an outline; the two renderers decide them by
 * different roundings (forms against rays), so a few may flip. Measured
 * over seeds 1..20000 outside the known-finding frames: Q16.16 0.45 %,
 * double 0.0002 % (docs/ACCURACY.md, section 10). A fast renderer that drew
 * an outline a pixel off would flip about half the band. */
#define ORACLE_BAND_CAP_Q16 0.02
#define ORACLE_BAND_CAP_DOUBLE 0.005

static long passed, failed;

static void ok(void)
{
    passed++;
}

static void bad(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static void bad(const char *fmt, ...)
{
    va_list ap;
    failed++;
    fputs("FAIL: ", stdout);
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    fputc('\n', stdout);
}

typedef int (*frame_fn)(const char *, const scene_t *, int, int, uint8_t *, uint8_t *, uint16_t *, char *, size_t);

enum { NQ16, NDOUBLE, NNUM };
static const char *const num_name[NNUM] = {"q16", "double"};
static const frame_fn frame_of[NNUM] = {oracle_frame_q16, oracle_frame_double};

typedef struct {
    long frames, pixels, band, interior, band_mis, foreign;
    long known_frames, known_interior; /* frames listed by --known, and their interior mismatches */
} tally_t;

static tally_t tally[NNUM];
static uint8_t *buf_fast, *buf_ray;
static uint16_t *buf_ids;
static int verbose;

static int same_rgb(const uint8_t *a, const uint8_t *b)
{
    return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

/* Compare one frame; returns the number of interior mismatches and prints
 * the first few. */
static long compare_frame(const char *what, int n, int w, int h, tally_t *t)
{
    long interior = 0;
    for (int y = 0; y < h; y++) {
        for (int x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            int band = 0, foreign = 1;
            for (int dy = -1; dy <= 1; dy++) {
                for (int dx = -1; dx <= 1; dx++) {
                    int xx = x + dx, yy = y + dy;
                    if (xx < 0 || yy < 0 || xx >= w || yy >= h)
                        continue;
                    size_t j = (size_t)yy * w + xx;
                    if (buf_ids[j] != buf_ids[i])
                        band = 1;
                    if (same_rgb(buf_fast + 3 * i, buf_ray + 3 * j))
                        foreign = 0;
                }
            }
            int mis = !same_rgb(buf_fast + 3 * i, buf_ray + 3 * i);
            t->band += band;
            if (!mis)
                continue;
            if (band) {
                t->band_mis++;
                t->foreign += foreign;
            } else {
                if (interior < 5) {
                    char who[32] = "a miss";
                    if (buf_ids[i] != RAYCAST_MISS)
                        snprintf(who, sizeof who, "object %d of the file", buf_ids[i] + 1);
                    printf("  %s %s: interior mismatch at column %d, row %d (top = 0): fast %d %d %d, "
                           "raycast %d %d %d (%s)\n",
                           what, num_name[n], x, y, buf_fast[3 * i], buf_fast[3 * i + 1], buf_fast[3 * i + 2],
                           buf_ray[3 * i], buf_ray[3 * i + 1], buf_ray[3 * i + 2], who);
                }
                interior++;
            }
        }
    }
    t->frames++;
    t->pixels += (long)w * h;
    t->interior += interior;
    return interior;
}

/* Known findings (--known FILE): random seeds where the fast renderer
 * disagrees with the ray caster away from silhouettes, reported and not
 * yet fixed. Such a frame is listed as a known finding, neither passed nor
 * failed; any other disagreement fails. */
#define ORACLE_MAX_KNOWN 1024
static struct {
    uint64_t seed;
    int num;
    int seen;
} known[ORACLE_MAX_KNOWN];
static int nknown;
static long known_hit, known_gone;

static int load_known(const char *path)
{
    FILE *f = fopen(path, "r");
    char line[512];
    if (!f) {
        fprintf(stderr, "oracle: %s: %s\n", path, strerror(errno));
        return -1;
    }
    int lineno = 0;
    while (fgets(line, sizeof line, f)) {
        unsigned long long sd;
        char num[16];
        lineno++;
        if (line[0] == '#' || line[0] == '\n')
            continue;
        if (sscanf(line, "%llu %15s", &sd, num) != 2 || (strcmp(num, "q16") != 0 && strcmp(num, "double") != 0) ||
            nknown == ORACLE_MAX_KNOWN) {
            fprintf(stderr, "oracle: %s:%d: expected 'SEED q16|double WHY'\n", path, lineno);
            fclose(f);
            return -1;
        }
        known[nknown].seed = sd;
        known[nknown].num = strcmp(num, "q16") == 0 ? 0 : 1;
        nknown++;
    }
    fclose(f);
    return 0;
}

static int find_known(int random, uint64_t seed, int n)
{
    for (int i = 0; random && i < nknown; i++)
        if (known[i].seed == seed && known[i].num == n)
            return i;
    return -1;
}

/* Render and compare one scene in both builds. rerun is how to repeat it. */
static void oracle_scene(const char *what, const char *path, const scene_t *sc, int w, int h, const char *rerun,
                         int random, uint64_t seed)
{
    char err[512];
    for (int n = 0; n < NNUM; n++) {
        tally_t before = tally[n];
        if (frame_of[n](path, sc, w, h, buf_fast, buf_ray, buf_ids, err, sizeof err) != 0) {
            bad("%s %s: does not render: %s (%s)", what, num_name[n], err, rerun);
            continue;
        }
        long interior = compare_frame(what, n, w, h, &tally[n]);
        int k = find_known(random, seed, n);
        if (k >= 0) {
            known[k].seen = 1;
            /* its band figures stay out of the totals too */
            tally[n].interior = before.interior;
            tally[n].band = before.band;
            tally[n].band_mis = before.band_mis;
            tally[n].foreign = before.foreign;
            tally[n].known_frames++;
            tally[n].known_interior += interior;
            if (interior) {
                known_hit++;
                printf("KNOWN FINDING: %s %s (%dx%d): %ld interior mismatches (%s)\n", what, num_name[n], w, h,
                       interior, rerun);
            } else {
                known_gone++;
                printf("note: known finding %s %s no longer reproduces: remove it from the list\n", what,
                       num_name[n]);
            }
        } else if (interior == 0)
            ok();
        else
            bad("%s %s (%dx%d): %ld interior mismatches, fast renderer against ray caster (%s)", what,
                num_name[n], w, h, interior, rerun);
        if (verbose)
            printf("%s %s %dx%d: band %ld, band mismatches %ld (not a neighbour's colour: %ld), interior %ld\n",
                   what, num_name[n], w, h, tally[n].band - before.band, tally[n].band_mis - before.band_mis,
                   tally[n].foreign - before.foreign, interior);
    }
}

/* The whole file, NUL-terminated, or NULL. */
static char *read_text(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    size_t cap = 4096, n = 0;
    char *s = malloc(cap);
    for (;;) {
        if (s && n + 1 >= cap) {
            char *t = realloc(s, cap *= 2);
            if (!t)
                free(s);
            s = t;
        }
        if (!s) {
            fclose(f);
            return NULL;
        }
        size_t k = fread(s + n, 1, cap - n - 1, f);
        if (k == 0)
            break;
        n += k;
    }
    fclose(f);
    s[n] = '\0';
    if (len)
        *len = n;
    return s;
}

static int expects_rejection(const char *text)
{
    return strstr(text, "\n# expect: rejected:") != NULL || strncmp(text, "# expect: rejected:", 19) == 0;
}

static scene_t scene; /* large: static */

static void oracle_file(const char *path)
{
    char err[512];
    char *text = read_text(path, NULL);
    if (!text) {
        bad("%s: cannot read: %s", path, strerror(errno));
        return;
    }
    int rejected = expects_rejection(text);
    free(text);
    int loaded = scene_load(path, &scene, err, sizeof err) == 0;
    if (rejected) {
        /* Refused at load, or at set-up by both builds. */
        for (int n = 0; n < NNUM; n++) {
            if (loaded && frame_of[n](path, &scene, scene.width, scene.height, NULL, buf_ray, buf_ids, err,
                                      sizeof err) == 0)
                bad("%s %s: renders, but its header says it is rejected", path, num_name[n]);
            else
                ok();
        }
        if (verbose)
            printf("%s: rejected as its header says: %s\n", path, err);
        return;
    }
    if (!loaded) {
        bad("%s: %s", path, err);
        return;
    }
    if ((long)scene.width * scene.height > ORACLE_MAX_PIXELS) {
        bad("%s: %dx%d is larger than the oracle's %d pixels", path, scene.width, scene.height, ORACLE_MAX_PIXELS);
        return;
    }
    /* The oracle checks visibility, one ray per pixel against one nearest
     * hit: a supersampled scene is checked at one sample (the ray caster's
     * sampled frames carry no ids to tell silhouettes from interiors;
     * tests/renderers.sh checks the sampling sums against it in double). */
    scene.samples = 1;
    scene.adaptive = 0;
    oracle_scene(path, path, &scene, scene.width, scene.height, path, 0, 0);
}

/* What the random scenes covered (printed at the end of a run). */
static struct {
    long scenes, ortho, objects, kind[4], eye_in_sphere, eye_in_box, behind, far, tiny;
} cover;

static void cover_scene(const scene_t *sc)
{
    const scene_vec_t e = sc->camera.eye, g = sc->camera.gaze;
    int in_sphere = 0, in_box = 0, behind = 0, far = 0, tiny = 0;
    cover.scenes++;
    cover.ortho += sc->camera.kind == SCENE_CAM_ORTHOGRAPHIC;
    for (int i = 0; i < sc->count; i++) {
        const scene_obj_t *o = &sc->obj[i];
        const scene_vec_t p = o->p[0];
        cover.objects++;
        cover.kind[o->kind]++;
        if ((p.x - e.x) * g.x + (p.y - e.y) * g.y + (p.z - e.z) * g.z < 0)
            behind = 1;
        for (int k = 0; k < (o->kind == SCENE_TRIANGLE ? 3 : o->kind == SCENE_BOX ? 2 : 1); k++)
            if (fabs(o->p[k].x) > 4096 || fabs(o->p[k].y) > 4096 || fabs(o->p[k].z) > 4096)
                far = 1;
        if (o->kind == SCENE_SPHERE) {
            double dx = p.x - e.x, dy = p.y - e.y, dz = p.z - e.z;
            in_sphere |= dx * dx + dy * dy + dz * dz < o->radius * o->radius;
            tiny |= o->radius < 0.01;
        }
        if (o->kind == SCENE_BOX)
            in_box |= o->p[0].x <= e.x && e.x <= o->p[1].x && o->p[0].y <= e.y && e.y <= o->p[1].y &&
                      o->p[0].z <= e.z && e.z <= o->p[1].z;
    }
    cover.eye_in_sphere += in_sphere;
    cover.eye_in_box += in_box;
    cover.behind += behind;
    cover.far += far;
    cover.tiny += tiny;
}

/* Random scenes reach the edges of the domain the parser accepts, whose
 * direction rules (rounding may turn a gaze, normal or the camera's roll
 * by at most 4 LSB) depend on several values together. A draw the parser
 * rejects is replaced by the next variant of the same seed; how many were
 * replaced is counted and bounded (RANDOM_MAX_REDRAW_PCT). */
#define RANDOM_VARIANTS 16
#define RANDOM_MAX_REDRAW_PCT 10
static unsigned long random_redrawn, random_drawn;

static uint64_t random_variant(uint64_t seed, int k)
{
    return k == 0 ? seed : seed ^ ((uint64_t)k << 56);
}

/* The scene text of seed's first variant the parser accepts (into scene);
 * returns its length, or 0 with err set when none of them is accepted. */
static size_t random_scene(uint64_t seed, char *text, size_t cap, char *err, size_t errlen)
{
    char name[64];
    snprintf(name, sizeof name, "random-%llu", (unsigned long long)seed);
    for (int k = 0; k < RANDOM_VARIANTS; k++) {
        size_t len = randscene_text(random_variant(seed, k), text, cap);
        if (scene_parse(name, text, len, &scene, err, errlen) == 0)
            return len;
    }
    return 0;
}

static void oracle_random(uint64_t seed)
{
    char text[RANDSCENE_MAX_TEXT], err[512], name[64], rerun[128];
    snprintf(name, sizeof name, "random-%llu", (unsigned long long)seed);
    snprintf(rerun, sizeof rerun, "rerun: build/tests/oracle --random 1 --seed %llu -v; scene: --print-scene %llu",
             (unsigned long long)seed, (unsigned long long)seed);
    random_drawn++;
    if (randscene_text(seed, text, sizeof text) && scene_parse(name, text, strlen(text), &scene, err, sizeof err) != 0)
        random_redrawn++;
    if (random_scene(seed, text, sizeof text, err, sizeof err) == 0) {
        bad("random scene %llu: no variant is valid input: %s (%s)", (unsigned long long)seed, err, rerun);
        return;
    }
    cover_scene(&scene);
    oracle_scene(name, name, &scene, scene.width, scene.height, rerun, 1, seed);
}

/* --- stress-scene expectations ---------------------------------------------
 * For a stress scene (not a rejected one), from the double ray caster's
 * frame at the scene's size: for the background colour and every object
 * colour c (8-bit, as the double build rounds it),
 *   LO = pixels whose whole 3x3 neighbourhood has colour c,
 *   HI = pixels with colour c anywhere in their 3x3 neighbourhood,
 * written as "# expect: all: color R G B in LO..HI" ("background" for the
 * background's colour). A renderer whose silhouettes are within a pixel of
 * the ray caster's lands inside every range; stress_scenes.sh checks the
 * double, Q16.16 and float renders of `fxrt render`. Colours match within
 * 1 per channel there (a build may round a colour 1 apart), so the tool
 * requires the scene's colours to differ by at least 3 in some channel. */

#define SE_MARKER "# oracle: the expect lines below come from make stress-expect (double ray caster, tests/oracle.c)"
#define SE_MAX_COLORS (SCENE_MAX_OBJECTS + 1)

static int rgb_index(const uint8_t (*list)[3], int n, const uint8_t *c)
{
    for (int i = 0; i < n; i++)
        if (same_rgb(list[i], c))
            return i;
    return -1;
}

/* The generated block for one scene into out; returns 0, or -1. */
static int stress_lines(const char *path, char *out, size_t outlen)
{
    char err[512];
    static uint8_t rgb[3 * SE_MAX_COLORS], rgbq[3 * SE_MAX_COLORS];
    static uint8_t colors[SE_MAX_COLORS][3];
    static long lo[SE_MAX_COLORS], hi[SE_MAX_COLORS];
    if (scene_load(path, &scene, err, sizeof err) != 0) {
        bad("%s", err);
        return -1;
    }
    int w = scene.width, h = scene.height;
    if ((long)w * h > ORACLE_MAX_PIXELS) {
        bad("%s: too large for the oracle", path);
        return -1;
    }
    if (oracle_frame_double(path, &scene, w, h, NULL, buf_ray, buf_ids, err, sizeof err) != 0 ||
        oracle_colors_double(path, &scene, w, h, rgb, err, sizeof err) != 0) {
        bad("%s", err);
        return -1;
    }
    int nc = 0;
    memcpy(colors[nc++], rgb + 3 * scene.count, 3); /* the background first */
    for (int i = 0; i < scene.count; i++)
        if (rgb_index((const uint8_t(*)[3])colors, nc, rgb + 3 * i) < 0)
            memcpy(colors[nc++], rgb + 3 * i, 3);
    for (int a = 0; a < nc; a++) {
        for (int b = a + 1; b < nc; b++) {
            int d = 0;
            for (int k = 0; k < 3; k++) {
                int e = abs(colors[a][k] - colors[b][k]);
                d = e > d ? e : d;
            }
            if (d < 3) {
                bad("%s: colours %d %d %d and %d %d %d differ by less than 3 in every channel", path, colors[a][0],
                    colors[a][1], colors[a][2], colors[b][0], colors[b][1], colors[b][2]);
                return -1;
            }
        }
    }
    if (oracle_colors_q16(path, &scene, w, h, rgbq, err, sizeof err) == 0 &&
        memcmp(rgb, rgbq, 3 * (size_t)(scene.count + 1)) != 0)
        printf("note: %s: some colour rounds differently in Q16.16 and double\n", path);
    for (int c = 0; c < nc; c++)
        lo[c] = hi[c] = 0;
    for (int y = 0; y < h; y++) {
        for (int x = 0; x < w; x++) {
            uint8_t seen[SE_MAX_COLORS] = {0};
            int nseen = 0;
            for (int dy = -1; dy <= 1; dy++) {
                for (int dx = -1; dx <= 1; dx++) {
                    int xx = x + dx, yy = y + dy;
                    if (xx < 0 || yy < 0 || xx >= w || yy >= h)
                        continue;
                    int c = rgb_index((const uint8_t(*)[3])colors, nc, buf_ray + 3 * ((size_t)yy * w + xx));
                    if (c < 0) {
                        bad("%s: the ray caster drew a colour that is not the scene's", path);
                        return -1;
                    }
                    if (!seen[c]++)
                        nseen++;
                }
            }
            for (int c = 0; c < nc; c++) {
                if (seen[c])
                    hi[c]++;
                if (seen[c] && nseen == 1)
                    lo[c]++;
            }
        }
    }
    size_t n = (size_t)snprintf(out, outlen, "%s\n", SE_MARKER);
    for (int c = 0; c < nc && n < outlen; c++) {
        if (c == 0)
            n += (size_t)snprintf(out + n, outlen - n, "# expect: all: background in %ld..%ld\n", lo[c], hi[c]);
        else
            n += (size_t)snprintf(out + n, outlen - n, "# expect: all: color %d %d %d in %ld..%ld\n", colors[c][0],
                                  colors[c][1], colors[c][2], lo[c], hi[c]);
    }
    return 0;
}

static int is_generated_expect(const char *line)
{
    static const char bg[] = "# expect: all: background in ", col[] = "# expect: all: color ";
    const char *end = strchr(line, '\n');
    size_t n = end ? (size_t)(end - line) : strlen(line);
    if (strncmp(line, bg, strlen(bg)) == 0)
        return 1;
    if (strncmp(line, col, strlen(col)) != 0)
        return 0;
    for (const char *q = line; q + 4 <= line + n; q++)
        if (memcmp(q, " in ", 4) == 0)
            return 1;
    return 0;
}

/* The file with its generated block replaced (or inserted before the first
 * line that is not a comment). Returns a malloc'd string. */
static char *stress_rewrite(const char *text, const char *block)
{
    size_t tl = strlen(text), bl = strlen(block);
    char *out = malloc(tl + bl + 1);
    size_t n = 0;
    if (!out) {
        fprintf(stderr, "oracle: out of memory\n");
        exit(2);
    }
    int placed = 0, skipping = 0;
    const char *p = text;
    while (*p) {
        const char *e = strchr(p, '\n');
        size_t ll = e ? (size_t)(e - p) + 1 : strlen(p);
        if (strncmp(p, SE_MARKER, strlen(SE_MARKER)) == 0 && (p[strlen(SE_MARKER)] == '\n' || p[strlen(SE_MARKER)] == '\r')) {
            skipping = 1;
        } else if (skipping && is_generated_expect(p)) {
            /* old generated line: dropped */
        } else {
            if (skipping && !placed) {
                memcpy(out + n, block, bl);
                n += bl;
                placed = 1;
            }
            skipping = 0;
            if (!placed && p[0] != '#') {
                memcpy(out + n, block, bl);
                n += bl;
                placed = 1;
            }
            memcpy(out + n, p, ll);
            n += ll;
        }
        p += ll;
    }
    if (!placed) {
        memcpy(out + n, block, bl);
        n += bl;
    }
    out[n] = '\0';
    return out;
}

static void stress_expect(const char *path, int write)
{
    static char block[64 * 1024];
    size_t len;
    char *text = read_text(path, &len);
    if (!text) {
        bad("%s: cannot read: %s", path, strerror(errno));
        return;
    }
    if (expects_rejection(text)) {
        if (strstr(text, SE_MARKER))
            bad("%s: a rejected scene has a generated block", path);
        else
            ok();
        free(text);
        return;
    }
    if (stress_lines(path, block, sizeof block) != 0) {
        free(text);
        return;
    }
    char *updated = stress_rewrite(text, block);
    if (strcmp(updated, text) == 0) {
        ok();
    } else if (write) {
        char tmp[4096];
        snprintf(tmp, sizeof tmp, "%s.tmp", path);
        FILE *f = fopen(tmp, "wb");
        if (!f || fwrite(updated, 1, strlen(updated), f) != strlen(updated) || fclose(f) != 0 ||
            rename(tmp, path) != 0) {
            bad("%s: cannot write: %s", path, strerror(errno));
        } else {
            printf("%s: expectations updated\n", path);
            ok();
        }
    } else {
        bad("%s: its '# expect:' lines differ from what the oracle generates (run make stress-expect):\n%s", path,
            block);
    }
    free(updated);
    free(text);
}

static void usage(void)
{
    fprintf(stderr, "usage: oracle [--random N] [--seed S] [--known FILE] [-v] [SCENE...]\n"
                    "       oracle --print-scene SEED\n"
                    "       oracle --stress-expect [--write] SCENE...\n");
}

static int parse_u64(const char *s, uint64_t *v)
{
    char *end;
    errno = 0;
    unsigned long long x = strtoull(s, &end, 10);
    if (errno || end == s || *end || s[0] == '-')
        return -1;
    *v = x;
    return 0;
}

int main(int argc, char **argv)
{
    uint64_t nrandom = 0, seed = 1;
    int stress = 0, write = 0, nfiles = 0;
    const char **files = calloc((size_t)argc, sizeof *files);
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--random") == 0 && i + 1 < argc) {
            if (parse_u64(argv[++i], &nrandom) != 0) {
                usage();
                free(files);
                return 2;
            }
        } else if (strcmp(a, "--seed") == 0 && i + 1 < argc) {
            if (parse_u64(argv[++i], &seed) != 0) {
                usage();
                free(files);
                return 2;
            }
        } else if (strcmp(a, "--print-scene") == 0 && i + 1 < argc) {
            char text[RANDSCENE_MAX_TEXT];
            if (parse_u64(argv[++i], &seed) != 0) {
                usage();
                free(files);
                return 2;
            }
            char perr[512];
            if (random_scene(seed, text, sizeof text, perr, sizeof perr) == 0) {
                fprintf(stderr, "oracle: %s\n", perr);
                free(files);
                return 2;
            }
            fputs(text, stdout);
            free(files);
            return 0;
        } else if (strcmp(a, "--known") == 0 && i + 1 < argc) {
            if (load_known(argv[++i]) != 0) {
                free(files);
                return 2;
            }
        } else if (strcmp(a, "--stress-expect") == 0) {
            stress = 1;
        } else if (strcmp(a, "--write") == 0) {
            write = 1;
        } else if (strcmp(a, "-v") == 0) {
            verbose = 1;
        } else if (a[0] == '-') {
            usage();
            free(files);
            return 2;
        } else {
            files[nfiles++] = a;
        }
    }
    buf_fast = malloc((size_t)3 * ORACLE_MAX_PIXELS);
    buf_ray = malloc((size_t)3 * ORACLE_MAX_PIXELS);
    buf_ids = malloc(sizeof *buf_ids * (size_t)ORACLE_MAX_PIXELS);
    if (!buf_fast || !buf_ray || !buf_ids) {
        fprintf(stderr, "oracle: out of memory\n");
        return 2;
    }
    int rc;
    if (stress) {
        for (int i = 0; i < nfiles; i++)
            stress_expect(files[i], write);
        printf("stress-expect: %d scenes\n", nfiles);
        printf("stress-expect: %ld passed, %ld failed\n", passed, failed);
        rc = failed != 0;
    } else {
        for (int i = 0; i < nfiles; i++)
            oracle_file(files[i]);
        for (uint64_t k = 0; k < nrandom; k++)
            oracle_random(seed + k);
        printf("oracle: %d scene files, %llu random scenes (seeds %llu..%llu)\n", nfiles,
               (unsigned long long)nrandom, (unsigned long long)seed, (unsigned long long)(seed + nrandom - 1));
        if (random_drawn) {
            printf("oracle: %lu of %lu random draws were outside the parser's domain and redrawn (cap %d %%)\n",
                   random_redrawn, random_drawn, RANDOM_MAX_REDRAW_PCT);
            if (random_redrawn * 100 > (unsigned long)RANDOM_MAX_REDRAW_PCT * random_drawn)
                bad("the random generator drew %lu invalid scenes out of %lu (over %d %%)", random_redrawn,
                    random_drawn, RANDOM_MAX_REDRAW_PCT);
            else
                ok();
        }
        if (cover.scenes)
            printf("oracle: random scenes: %ld orthographic, %ld perspective; %ld objects (%ld planes, %ld spheres, "
                   "%ld triangles, %ld boxes); scenes with the eye inside a sphere %ld, inside a box (or on it) %ld, "
                   "an object behind the camera %ld, a coordinate beyond 4096 %ld, a radius below 0.01 %ld\n",
                   cover.ortho, cover.scenes - cover.ortho, cover.objects, cover.kind[SCENE_PLANE],
                   cover.kind[SCENE_SPHERE], cover.kind[SCENE_TRIANGLE], cover.kind[SCENE_BOX], cover.eye_in_sphere,
                   cover.eye_in_box, cover.behind, cover.far, cover.tiny);
        for (int n = 0; n < NNUM; n++) {
            const tally_t *t = &tally[n];
            printf("oracle %s: %ld frames, %ld pixels compared, %ld interior mismatches (not counting %ld in %ld "
                   "known-finding frames), %ld band pixels, %ld band mismatches (%.3f %% of the band; %ld not a "
                   "neighbour's colour)\n",
                   num_name[n], t->frames, t->pixels, t->interior, t->known_interior, t->known_frames, t->band,
                   t->band_mis, t->band ? 100.0 * t->band_mis / t->band : 0.0, t->foreign);
            double cap = n == NQ16 ? ORACLE_BAND_CAP_Q16 : ORACLE_BAND_CAP_DOUBLE;
            if (t->band_mis <= cap * t->band)
                ok();
            else
                bad("%s: band mismatches %ld exceed %.1f %% of %ld band pixels", num_name[n], t->band_mis,
                    100 * cap, t->band);
        }
        if (nknown)
            printf("oracle: %ld frames are known findings (--known), %ld known findings no longer reproduce\n",
                   known_hit, known_gone);
        printf("oracle: %ld passed, %ld failed\n", passed, failed);
        rc = failed != 0;
    }
    free(buf_fast);
    free(buf_ray);
    free(buf_ids);
    free(files);
    return rc;
}
