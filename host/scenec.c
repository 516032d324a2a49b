/* fxrt-scenec: compile a .scene file into C for the firmware: a header of
 * capacity macros (FXRT_MAX_<KIND> = the scene's own counts, so unused
 * kinds compile out; FXRT_MAX_LIGHTS, FXRT_SHADOWS, FXRT_PHONG from the
 * scene's materials and lights; FXRT_MAX_DEPTH, FXRT_MAX_SAMPLES,
 * FXRT_ADAPTIVE from its depth, samples and materials) and a header with
 * the scene's own values (camera, background, objects, ambient, lights,
 * depth, samples) in the chosen number type, which the firmware passes to
 * the public API (core/fxrt.h) at boot. */
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "args.h"
#include "engine.h"
#include "meshbuild.h"
#include "meshemit.h"
#include "scenec.h"

static const char usage[] =
    "usage: fxrt-scenec SCENE --number q16|float|double --size WxH --out DIR [--all-kinds]\n"
    "                   [--sphere-rows]\n"
    "       fxrt-scenec --mesh OBJ --out FILE.c [--name NAME] [--flat] [--max-bytes N]\n"
    "                   [--index16] [--node STEPS]\n"
    "\n"
    "--mesh writes the OBJ model as constant data in C (docs/MESHES.md): quantised\n"
    "vertices, vertex normals (not with --flat), triangles and a BVH, and\n"
    "`const fxrt_mesh_t NAME` (default: the file's name, then _mesh). It prints\n"
    "one line: triangles, vertices, nodes, depth, bytes, bytes per triangle. It\n"
    "refuses a mesh of more than N bytes (--max-bytes) or, with --index16, one\n"
    "whose vertices need 32-bit indices. It also writes `const fxrt_instance_t\n"
    "NAME_at`, the mesh placed where the node STEPS put it (a scene's node line\n"
    "without 'node': --node \"scale 2 rotate y 30 translate 0 1 -5\"; without\n"
    "--node, where the file's coordinates are), for fxrt_add's .inst.\n"
    "\n"
    "Writes DIR/scene_config.h (FXRT_MAX_* capacities, SCENE_WIDTH/HEIGHT/OBJECTS/LIGHTS,\n"
    "FXRT_SHADOWS, FXRT_PHONG, FXRT_MAX_DEPTH, FXRT_MAX_SAMPLES, FXRT_ADAPTIVE) and\n"
    "DIR/scene_data.h (the scene's own values: fxrt_camera_t scene_camera, color_t\n"
    "scene_background, fxrt_object_t scene_objects[] with materials, color_t\n"
    "scene_ambient, fxrt_light_t scene_lights[], int32_t scene_depth and\n"
    "scene_samples, bool scene_adaptive), which the firmware sets up at boot\n"
    "through core/fxrt.h.\n"
    "FXRT_MAX_LIGHTS is 0 (lighting compiled out) when every material is flat,\n"
    "else max(1, lights); FXRT_SHADOWS 1 only if a light casts shadows; FXRT_PHONG\n"
    "1 only if an object is phong or reflective; FXRT_MAX_DEPTH is the scene's\n"
    "depth if an object is reflective or transparent, else 0; FXRT_MAX_SAMPLES is\n"
    "the scene's samples N (FXRT_RENDER_MAX_WIDTH N x width); FXRT_ADAPTIVE 1 only\n"
    "for 'samples N adaptive'. FXRT_COHERENT_SPHERES is the scene's spheres, or 0\n"
    "when the scene has more than FXRT_LONE_MAX objects (none is ever alone on\n"
    "its row, so the spheres keep no row-coherence state, 120 B each).\n"
    "--all-kinds keeps every primitive kind compiled in (capacity >= 1), to\n"
    "measure what stripping the unused ones saves.\n"
    "--sphere-rows keeps every sphere's row-coherence state whatever the scene's\n"
    "size (FXRT_COHERENT_SPHERES FXRT_MAX_SPHERES): a sphere among other objects\n"
    "then steps its row forms down the rows (the firmware's make passes it on\n"
    "every board; firmware/fit.sh drops the state where it does not fit).\n";

static int fail(const char *msg, const char *arg)
{
    fprintf(stderr, "fxrt-scenec: %s%s\n%s", msg, arg, usage);
    return 2;
}

/* The instance of mesh NAME from OBJ placed by the node steps (NULL:
 * none), as the scene language places it: a scene of that node and mesh,
 * parsed, gives its maps, checked against mb's quantisation. Writes
 * `const fxrt_instance_t NAME_at` into f (T in Q16.16, exactly, as
 * FXRT_NUM of hexadecimal literals). 0, or -1 with the message on stderr. */
static int mesh_instance(FILE *f, const meshbuild_t *mb, const char *obj, bool smooth, const char *steps,
                         const char *name)
{
    static scene_t sc;
    static char text[4096];
    char err[1024];
    int n = snprintf(text, sizeof text, "camera perspective eye 0 0 1 gaze 0 0 -1 up 0 1 0 fov 45\n%s%s%s"
                     "mesh file %s shading %s color 1 1 1\n%s",
                     steps ? "node " : "", steps ? steps : "", steps ? "\n" : "", obj, smooth ? "smooth" : "flat",
                     steps ? "end\n" : "");
    if (n < 0 || (size_t)n >= sizeof text || strpbrk(obj, " \t\r\n") || (steps && strpbrk(steps, "\r\n"))) {
        fprintf(stderr, "fxrt-scenec: --node or the OBJ path too long, or with a space or line break\n");
        return -1;
    }
    scene_set_mesh_inline(0); /* (a model, whatever its size) */
    if (scene_parse("--node", text, (size_t)n, &sc, err, sizeof err) != 0) {
        /* "--node:2: what": the steps' own message */
        const char *why = strchr(err, ' ');
        fprintf(stderr, "fxrt-scenec: --node: %s\n", why ? why + 1 : err);
        return -1;
    }
    const scene_obj_t *o = &sc.obj[0];
    if (sc.count != 1 || o->kind != SCENE_MODEL || o->store->mb.step != mb->step ||
        memcmp(o->store->mb.origin, mb->origin, sizeof mb->origin) != 0) {
        fprintf(stderr, "fxrt-scenec: %s: the placed mesh is not the one written\n", obj);
        return -1;
    }
    char inst[300];
    snprintf(inst, sizeof inst, "%s_at", name);
    fprintf(f, "/* %s placed by \"%s\": w = f 2^-fe q + T, q = m 2^-e (w - T) (docs/MESHES.md). */\n", name,
            steps ? steps : "");
    meshemit_instance(f, "", inst, name, &o->map);
    return ferror(f) ? -1 : 0;
}

/* fxrt-scenec --mesh OBJ --out FILE.c [--name NAME] [--flat] [--max-bytes N] [--index16] [--node STEPS] */
static int mesh_main(int argc, char **argv)
{
    const char *obj = NULL, *out = NULL, *name = NULL, *steps = NULL;
    bool smooth = true, index16 = false;
    long long max_bytes = -1;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        bool value = !strcmp(a, "--mesh") || !strcmp(a, "--out") || !strcmp(a, "--name") || !strcmp(a, "--max-bytes") ||
                     !strcmp(a, "--node");
        if (value && i + 1 >= argc)
            return fail("missing value for ", a);
        if (!strcmp(a, "--mesh")) {
            obj = argv[++i];
        } else if (!strcmp(a, "--out")) {
            out = argv[++i];
        } else if (!strcmp(a, "--name")) {
            name = argv[++i];
            bool ok = name[0] == '_' || ((name[0] | 32) >= 'a' && (name[0] | 32) <= 'z');
            for (const char *c = name; *c && ok; c++)
                ok = *c == '_' || (*c >= '0' && *c <= '9') || ((*c | 32) >= 'a' && (*c | 32) <= 'z');
            static const char *const keywords[] = {
                "auto", "break", "case", "char", "const", "continue", "default", "do", "double", "else", "enum",
                "extern", "float", "for", "goto", "if", "inline", "int", "long", "register", "restrict", "return",
                "short", "signed", "sizeof", "static", "struct", "switch", "typedef", "union", "unsigned", "void",
                "volatile", "while", "_Bool", "_Complex", "_Imaginary", "_Alignas", "_Alignof", "_Atomic",
                "_Generic", "_Noreturn", "_Static_assert", "_Thread_local"};
            for (size_t k = 0; ok && k < sizeof keywords / sizeof keywords[0]; k++)
                ok = strcmp(name, keywords[k]) != 0;
            if (!ok)
                return fail("bad --name (a C identifier, not a keyword) ", name);
        } else if (!strcmp(a, "--max-bytes")) {
            char *end;
            max_bytes = strtoll(argv[++i], &end, 10);
            if (*argv[i] == 0 || *end || max_bytes < 0)
                return fail("bad --max-bytes ", argv[i]);
        } else if (!strcmp(a, "--node")) {
            steps = argv[++i];
        } else if (!strcmp(a, "--flat")) {
            smooth = false;
        } else if (!strcmp(a, "--index16")) {
            index16 = true;
        } else {
            return fail("unexpected argument ", a);
        }
    }
    if (!obj || !out)
        return fail("--mesh needs OBJ and --out", "");
    char defname[256];
    if (!name) {
        const char *base = strrchr(obj, '/');
        base = base ? base + 1 : obj;
        size_t k = 0;
        if (*base >= '0' && *base <= '9')
            defname[k++] = '_';
        for (; *base && *base != '.' && k + 6 < sizeof defname; base++)
            defname[k++] = (char)((*base >= '0' && *base <= '9') || ((*base | 32) >= 'a' && (*base | 32) <= 'z') ? *base : '_');
        snprintf(defname + k, sizeof defname - k, "_mesh");
        name = defname;
    }
    static obj_t o;
    static meshbuild_t mb;
    char err[512];
    if (obj_load(obj, &o, err, sizeof err) || meshbuild(&o, smooth, &mb, err, sizeof err)) {
        fprintf(stderr, "%s%s%s\n", strncmp(err, obj, strlen(obj)) ? obj : "", strncmp(err, obj, strlen(obj)) ? ": " : "", err);
        return 2;
    }
    obj_free(&o);
    size_t bytes = meshbuild_bytes(&mb);
    if (index16 && !mb.mesh.tri16) {
        fprintf(stderr, "%s: the mesh needs 32-bit indices: %u vertices, at most 65,536 with 16-bit ones (--index16)\n",
                obj, mb.mesh.n_vertices);
        return 2;
    }
    if (max_bytes >= 0 && (long long)bytes > max_bytes) {
        fprintf(stderr, "%s: the mesh needs %zu bytes of constant data, at most %lld fit (--max-bytes)\n", obj, bytes,
                max_bytes);
        return 2;
    }
    char tmp[1100];
    if (strlen(out) > 1000)
        return fail("--out path too long (at most 1,000 characters): ", out);
    snprintf(tmp, sizeof tmp, "%s.tmp.%ld", out, (long)getpid());
    FILE *f = fopen(tmp, "w");
    int placed = 0; /* -1: the placement was refused (mesh_instance said why) */
    int rc = !f || meshemit_c(f, &mb, name, obj) != 0 || (placed = mesh_instance(f, &mb, obj, smooth, steps, name)) != 0;
    if (f && fclose(f))
        rc = 1;
    if (!rc && rename(tmp, out))
        rc = 1;
    if (rc) {
        remove(tmp);
        if (placed == 0)
            fprintf(stderr, "fxrt-scenec: cannot write %s\n", out);
        meshbuild_free(&mb);
        return 2;
    }
    meshemit_summary(stdout, &mb, obj);
    meshbuild_free(&mb);
    return 0;
}

int main(int argc, char **argv)
{
    for (int i = 1; i < argc; i++)
        if (!strcmp(argv[i], "--mesh"))
            return mesh_main(argc, argv);
    const char *path = NULL, *out = NULL;
    engine_number_t num = ENGINE_Q16;
    int w = 0, h = 0;
    unsigned opts = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            fputs(usage, stdout);
            return 0;
        }
        if ((!strcmp(a, "--number") || !strcmp(a, "--size") || !strcmp(a, "--out")) && i + 1 >= argc)
            return fail("missing value for ", a);
        if (!strcmp(a, "--number")) {
            if (engine_number_parse(argv[++i], &num))
                return fail("bad --number ", argv[i]);
        } else if (!strcmp(a, "--size")) {
            if (args_size(argv[++i], &w, &h))
                return fail("bad --size ", argv[i]);
        } else if (!strcmp(a, "--out")) {
            out = argv[++i];
        } else if (!strcmp(a, "--all-kinds")) {
            opts |= SCENEC_ALL_KINDS;
        } else if (!strcmp(a, "--sphere-rows")) {
            opts |= SCENEC_SPHERE_ROWS;
        } else if (a[0] == '-') {
            return fail("unknown option ", a);
        } else if (!path) {
            path = a;
        } else {
            return fail("unexpected argument ", a);
        }
    }
    if (!path || !out)
        return fail("needs SCENE and --out", "");

    static scene_t sc;
    char err[512];
    if (scene_load(path, &sc, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        return 2;
    }
    if (!w) {
        w = sc.width;
        h = sc.height;
    }
    char cfg_path[1024], data_path[1024], cfg_tmp[1100], data_tmp[1100];
    snprintf(cfg_path, sizeof cfg_path, "%s/scene_config.h", out);
    snprintf(data_path, sizeof data_path, "%s/scene_data.h", out);
    snprintf(cfg_tmp, sizeof cfg_tmp, "%s.tmp.%ld", cfg_path, (long)getpid());
    snprintf(data_tmp, sizeof data_tmp, "%s.tmp.%ld", data_path, (long)getpid());
    FILE *cfg = fopen(cfg_tmp, "w"), *data = fopen(data_tmp, "w");
    int rc = 0;
    if (!cfg || !data) {
        fprintf(stderr, "fxrt-scenec: cannot write into %s\n", out);
        rc = 2;
    } else {
        int e = num == ENGINE_Q16     ? scenec_emit_q16(cfg, data, path, &sc, w, h, opts, err, sizeof err)
                : num == ENGINE_FLOAT ? scenec_emit_float(cfg, data, path, &sc, w, h, opts, err, sizeof err)
                                      : scenec_emit_double(cfg, data, path, &sc, w, h, opts, err, sizeof err);
        if (e) {
            fprintf(stderr, "%s\n", err);
            rc = 2;
        }
    }
    if (cfg && fclose(cfg))
        rc = 2;
    if (data && fclose(data))
        rc = 2;
    if (rc == 0 && (rename(cfg_tmp, cfg_path) || rename(data_tmp, data_path))) {
        fprintf(stderr, "fxrt-scenec: cannot write into %s\n", out);
        rc = 2;
    }
    if (rc) {
        remove(cfg_tmp);
        remove(data_tmp);
    }
    return rc;
}
