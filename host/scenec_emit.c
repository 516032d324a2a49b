/* scenec_emit: print a scene's description (camera, background, objects)
 * as C initialisers of the public API's types (core/fxrt.h) in the build's
 * number type. Compiled once per number type (FXRT_MULTI), like engine.c.
 * The values come from the same engine_describe that engine_build passes
 * to the API, so the firmware sets up exactly what the host renders. */
#include <inttypes.h>
#include <stdio.h>

#include "engine_build.h"
#include "meshemit.h"
#include "scenec.h"

static void emit_num(FILE *f, num_t v)
{
#if FXRT_NUMBER == FXRT_Q16
    fprintf(f, "%" PRId32, v);
#elif FXRT_NUMBER == FXRT_FLOAT
    fprintf(f, "%af", (double)v); /* hex float: exact */
#else
    fprintf(f, "%a", v);
#endif
}

/* "{a, b, c}": a vector or a colour. */
static void emit_num3(FILE *f, num_t a, num_t b, num_t c)
{
    fputs("{", f);
    emit_num(f, a);
    fputs(", ", f);
    emit_num(f, b);
    fputs(", ", f);
    emit_num(f, c);
    fputs("}", f);
}

static void emit_vec(FILE *f, vec3_t v)
{
    emit_num3(f, v.x, v.y, v.z);
}

static void emit_color(FILE *f, color_t c)
{
    emit_num3(f, c.r, c.g, c.b);
}

static const char *kind_name(geom_kind_t k)
{
    switch (k) {
#define EMIT_KIND_NAME(K, ...) case GEOM_##K: return "GEOM_" #K;
        FXRT_KINDS(EMIT_KIND_NAME)
#undef EMIT_KIND_NAME
    default: break;
    }
    return "?";
}

static const char *light_kind_name(light_kind_t k)
{
    switch (k) {
    case LIGHT_POINT: return "LIGHT_POINT";
    case LIGHT_DIRECTIONAL: return "LIGHT_DIRECTIONAL";
    case LIGHT_SPOT: return "LIGHT_SPOT";
    }
    return "?";
}

static const char *material_kind_name(unsigned k)
{
    switch (k) {
    case MATERIAL_LAMBERT: return "MATERIAL_LAMBERT";
    case MATERIAL_PHONG: return "MATERIAL_PHONG";
    case MATERIAL_REFLECTIVE: return "MATERIAL_REFLECTIVE";
    case MATERIAL_TRANSPARENT: return "MATERIAL_TRANSPARENT";
    }
    return "MATERIAL_FLAT";
}

#if FXRT_MAX_MODELS > 0
/* The name under which emit_models writes the mesh of model object i: its
 * file's k (in the order the scene first names each file), _flat for an
 * instance shaded flat. */
void ENGINE_SYM(scenec_mesh_name)(const scene_t *sc, int i, char *name, size_t len)
{
    const scene_obj_t *o = &sc->obj[i];
    /* k: the files the scene names first before this one's first model */
    int j0 = 0;
    while (!(sc->obj[j0].kind == SCENE_MODEL && sc->obj[j0].store == o->store))
        j0++;
    int k = 0;
    for (int j = 0; j < j0; j++) {
        if (sc->obj[j].kind != SCENE_MODEL)
            continue;
        bool first = true;
        for (int m = 0; m < j && first; m++)
            first = !(sc->obj[m].kind == SCENE_MODEL && sc->obj[m].store == sc->obj[j].store);
        k += first;
    }
    snprintf(name, len, "scene_mesh%d%s", k, o->mesh != &o->store->mb.mesh ? "_flat" : "");
}

/* The models' data (see the call). */
static int emit_models(FILE *data, const scene_t *sc, const engine_desc_t *d)
{
    const meshstore_entry_t *seen[FXRT_MAX_MODELS];
    int nseen = 0;
    bool smooth_used[FXRT_MAX_MODELS] = {false}, flat_used[FXRT_MAX_MODELS] = {false};
    for (int pass = 0; pass < 2; pass++) {
        for (int i = 0; i < sc->count; i++) {
            const scene_obj_t *o = &sc->obj[i];
            if (o->kind != SCENE_MODEL)
                continue;
            int k = 0;
            while (k < nseen && seen[k] != o->store)
                k++;
            if (pass == 0 && k == nseen) {
                seen[nseen++] = o->store;
                char name[32];
                snprintf(name, sizeof name, "scene_mesh%d", k);
                fprintf(data, "/* %s: %s, %u triangles, %zu bytes */\n", name, o->store->path,
                        o->store->mb.mesh.n_triangles, meshbuild_bytes(&o->store->mb));
                meshemit_arrays(data, &o->store->mb, name);
            }
            bool flat = o->mesh != &o->store->mb.mesh;
            if (pass == 0) {
                char name[32], header[40];
                snprintf(name, sizeof name, "scene_mesh%d", k);
                snprintf(header, sizeof header, "scene_mesh%d%s", k, flat ? "_flat" : "");
                bool *used = flat ? &flat_used[k] : &smooth_used[k];
                if (!*used)
                    meshemit_header(data, &o->store->mb, name, header, !flat, "static ");
                *used = true;
                continue;
            }
            char inst[32], mesh[40];
            snprintf(inst, sizeof inst, "scene_inst%d", (int)(d->obj[i].inst - d->inst));
            snprintf(mesh, sizeof mesh, "scene_mesh%d%s", k, flat ? "_flat" : "");
            fprintf(data, "/* %s: line %d */\n", inst, o->line);
            meshemit_instance(data, "static ", inst, mesh, &o->map);
        }
    }
    return ferror(data) ? -1 : 0;
}
#endif

static unsigned scenec_cap(unsigned n, bool all_kinds)
{
    return all_kinds && n == 0 ? 1 : n;
}

int ENGINE_SYM(scenec_emit)(FILE *cfg, FILE *data, const char *path, const scene_t *sc, int width,
                            int height, unsigned opts, char *err, size_t errlen)
{
    bool all_kinds = (opts & SCENEC_ALL_KINDS) != 0;
    /* Build once here as the host does, so that a scene the core refuses
     * fails now, with its line, and to count the objects per kind. */
    static world_t w;
    static engine_desc_t d;
    cam_t cam;
    if (ENGINE_SYM(engine_build)(path, sc, width, height, &w, &cam, err, errlen) != 0)
        return -1;
    ENGINE_SYM(engine_describe)(sc, width, height, &d);
    /* Supersampling renders samples x width columns: a board holds at
     * most FXRT_MAX_DIM of them. Refused here, at the samples line, rather
     * than by the board at its first frame. */
    if ((long)width * d.samples > FXRT_MAX_DIM) {
        snprintf(err, errlen, "%s:%d: samples %d at width %d: samples x width (%ld) wider than FXRT_MAX_DIM (%d)", path,
                 sc->samples_line, d.samples, width, (long)width * d.samples, FXRT_MAX_DIM);
        return -1;
    }

    fprintf(cfg, "/* Generated by fxrt-scenec from %s (%dx%d, %s): do not edit. */\n", path, width, height,
            NUM_NAME);
    /* Each kind's capacity: its count in the scene (one line per row of
     * the kinds table). */
#define SCENEC_CAPACITY(K, k, ks, cap, ...) fprintf(cfg, "#define %s %u\n", #cap, scenec_cap(w.n_##ks, all_kinds));
    FXRT_KINDS(SCENEC_CAPACITY)
#undef SCENEC_CAPACITY
    fprintf(cfg, "#define SCENE_WIDTH %d\n#define SCENE_HEIGHT %d\n", width, height);
    fprintf(cfg, "#define SCENE_OBJECTS %d\n", d.count);
    /* Smooth shading only where a triangle has vertex normals. */
    int smooth = 0;
    for (int i = 0; i < sc->count; i++)
        smooth |= sc->obj[i].smooth;
    fprintf(cfg, "#define FXRT_SMOOTH %d\n", smooth);
    /* A sphere's row-coherence state (120 B) steps its row forms down the
     * rows; where RAM is short, only in a world of at most FXRT_LONE_MAX
     * objects, where a sphere can be alone on its row and gain most. The
     * flat pieces' guesses serve every flat piece that locates its runs. */
    if (opts & SCENEC_SPHERE_ROWS)
        fprintf(cfg, "#define FXRT_COHERENT_SPHERES FXRT_MAX_SPHERES\n");
    else if (d.count > FXRT_LONE_MAX)
        fprintf(cfg, "#define FXRT_COHERENT_SPHERES 0\n");
    else
        fprintf(cfg, "#define FXRT_COHERENT_SPHERES %u\n", (unsigned)w.n_spheres);
    /* Supersampling runs the visibility pass on a camera N times as wide
     * (core/fxrt_config.h FXRT_MAX_SAMPLES), so the render state needs N *
     * width columns (never more than FXRT_MAX_DIM: a frame beyond it is
     * refused by render set-up on the host and the board alike). */
    long cols = (long)width * d.samples;
    fprintf(cfg, "#define FXRT_RENDER_MAX_WIDTH %ld\n", cols < FXRT_MAX_DIM ? cols : (long)FXRT_MAX_DIM);
    /* Lighting: compiled out entirely (FXRT_MAX_LIGHTS 0) when every
     * material is flat, since no light then changes a pixel; else room for
     * the scene's lights (at least 1). Shadow rays and the specular term
     * only when something uses them. */
    int lit = 0, phong = 0, shadows = 0;
    for (int i = 0; i < d.count; i++) {
        lit |= d.obj[i].material.kind != MATERIAL_FLAT;
        /* Reflective materials have the Phong term too. */
        phong |= d.obj[i].material.kind == MATERIAL_PHONG || d.obj[i].material.kind == MATERIAL_REFLECTIVE;
    }
    for (int i = 0; i < d.nlights; i++)
        shadows |= d.lights[i].shadows;
    int max_lights = lit ? (d.nlights > 1 ? d.nlights : 1) : 0;
    int n_lights = lit ? d.nlights : 0;
    fprintf(cfg, "#define FXRT_MAX_LIGHTS %d\n#define FXRT_SHADOWS %d\n#define FXRT_PHONG %d\n", max_lights,
            lit && shadows, lit && phong);
    fprintf(cfg, "#define SCENE_LIGHTS %d\n", n_lights);
    /* A triangle's shadow edges only where a point or spot light casts
     * shadows on a scene with triangles (light/shadow.c): else their RAM
     * would buy nothing. */
    int edges = 0;
    for (int i = 0; i < d.nlights; i++)
        edges |= d.lights[i].shadows && d.lights[i].kind != FXRT_LIGHT_DIRECTIONAL;
    fprintf(cfg, "#define FXRT_SHADOW_EDGES %d\n", lit && edges && w.n_triangles > 0);
    /* Secondary rays: the bounce stack holds the scene's depth when some
     * object is reflective or transparent, else bounces are compiled out
     * (FXRT_MAX_DEPTH 0: no bounce code is linked). Supersampling: the
     * scene's N (1 compiles it out), adaptive only when asked for. Such an
     * object is never flat, so FXRT_MAX_DEPTH > 0 implies lighting. */
    fprintf(cfg, "#define FXRT_MAX_DEPTH %d\n#define FXRT_MAX_SAMPLES %d\n#define FXRT_ADAPTIVE %d\n",
            d.bounces ? d.depth : 0, d.samples, d.adaptive ? 1 : 0);
#if FXRT_MAX_BOXES > 0
    /* The box-face pool holds what this camera needs (3 faces for a box
     * seen from outside in perspective, up to 6 otherwise), counted by the
     * same render_setup the board runs on the same values, so the board
     * never runs short and RAM is not spent on faces no ray can cross. */
    if (w.n_boxes > 0 && !all_kinds) {
        static render_t rs;
        if (!render_setup(&rs, &w, &cam)) {
            snprintf(err, errlen, "%s: %s", path, rs.error ? rs.error : "render set-up failed");
            return -1;
        }
        fprintf(cfg, "#define FXRT_RENDER_BOX_FACES %u\n", rs.vis.box_used > 0 ? (unsigned)rs.vis.box_used : 1u);
    }
#endif

    /* The scene's own values, each rounded once to the number type (Q16.16:
     * integers; float and double: exact hex literals). The firmware sets the
     * camera and world up from them at boot through core/fxrt.h. */
    fprintf(data, "/* Generated by fxrt-scenec from %s (%dx%d, %s): do not edit. */\n", path, width,
            height, NUM_NAME);
    const fxrt_camera_t *c = &d.camera;
    fprintf(data, "static const fxrt_camera_t scene_camera = {\n    .kind = %s,\n    .eye = ",
            c->kind == CAM_PERSPECTIVE ? "CAM_PERSPECTIVE" : "CAM_ORTHOGRAPHIC");
    emit_vec(data, c->eye);
    fputs(",\n    .gaze = ", data);
    emit_vec(data, c->gaze);
    fputs(",\n    .up = ", data);
    emit_vec(data, c->up);
    fputs(",\n    .fov_deg = ", data);
    emit_num(data, c->fov_deg);
    fputs(",\n    .scale = ", data);
    emit_num(data, c->scale);
    fprintf(data, ",\n    .width = %d,\n    .height = %d,\n};\n", (int)c->width, (int)c->height);
    fputs("static const color_t scene_background = ", data);
    emit_color(data, d.background);
    fputs(";\n", data);
    /* Models: each mesh file's arrays once (instancing), a header for its
     * smooth and one for its flat instances as they are used, and each
     * model's placement (the instance its object points to). */
    FXRT_IF_MODEL(if (emit_models(data, sc, &d) != 0) {
        snprintf(err, errlen, "%s: cannot write the meshes", path);
        return -1;
    })
    /* One entry at least: C has no empty arrays (SCENE_OBJECTS says how
     * many are real). */
    fprintf(data, "static const fxrt_object_t scene_objects[%d] = {\n", d.count ? d.count : 1);
    for (int i = 0; i < d.count; i++) {
        const fxrt_object_t *o = &d.obj[i];
        /* Its points (POINT, DIR and MAX fields), then its radius if any. */
#define EMIT_NP_NONE 0
#define EMIT_NP_POINT 1
#define EMIT_NP_DIR 1
#define EMIT_NP_MAX 1
#define EMIT_NP_RADIUS 0
#define EMIT_NP_INST 0
#define EMIT_NP_AXIS 1
#define EMIT_NR_NONE 0
#define EMIT_NR_POINT 0
#define EMIT_NR_DIR 0
#define EMIT_NR_MAX 0
#define EMIT_NR_RADIUS 1
#define EMIT_NR_INST 0
#define EMIT_NR_AXIS 0
#define EMIT_POINTS(K, k, ks, cap, solid, bounded, form, edges, f1, t1, f2, t2, f3, t3, f4, t4)              \
    EMIT_NP_##t1 + EMIT_NP_##t2 + EMIT_NP_##t3 + EMIT_NP_##t4,
#define EMIT_RADIUS(K, k, ks, cap, solid, bounded, form, edges, f1, t1, f2, t2, f3, t3, f4, t4)              \
    EMIT_NR_##t1 + EMIT_NR_##t2 + EMIT_NR_##t3 + EMIT_NR_##t4,
        static const int points[] = {FXRT_KINDS(EMIT_POINTS)}, radius[] = {FXRT_KINDS(EMIT_RADIUS)};
        int np = points[o->kind];
        fprintf(data, "    {.kind = %s, ", kind_name(o->kind));
        if (np > 0) {
            fputs(".p = {", data);
            for (int k = 0; k < np; k++) {
                if (k)
                    fputs(", ", data);
                emit_vec(data, o->p[k]);
            }
            fputs("}, ", data);
        }
        FXRT_IF_MODEL(if (o->kind == GEOM_MODEL) fprintf(data, ".inst = &scene_inst%d, ", (int)(o->inst - d.inst));)
        if (radius[o->kind]) {
            fputs(".radius = ", data);
            emit_num(data, o->radius);
            fputs(", ", data);
        }
        fputs(".color = ", data);
        emit_color(data, o->color);
        /* Flat objects leave .material zero (MATERIAL_FLAT). */
        if (o->material.kind != MATERIAL_FLAT) {
            fprintf(data, ", .material = {.kind = %s", material_kind_name(o->material.kind));
            if (o->material.kind == MATERIAL_PHONG || o->material.kind == MATERIAL_REFLECTIVE) {
                fprintf(data, ", .exponent = %u, .specular = ", (unsigned)o->material.exponent);
                emit_color(data, o->material.specular);
            }
            if (o->material.kind == MATERIAL_REFLECTIVE) {
                fputs(", .reflection = ", data);
                emit_color(data, o->material.reflection);
            }
            if (o->material.kind == MATERIAL_TRANSPARENT) {
                fputs(", .index = ", data);
                emit_num(data, o->material.index);
            }
            fputs("}", data);
        }
        /* (A smooth triangle makes FXRT_SMOOTH 1 in this scene's
         * configuration, above; the parser refuses one where it is 0.) */
        FXRT_IF_SMOOTH(if (o->smooth) {
            fputs(", .smooth = true, .vn = {", data);
            for (int k = 0; k < 3; k++) {
                fputs(k ? ", " : "", data);
                emit_vec(data, o->vn[k]);
            }
            fputs("}", data);
        })
        fprintf(data, "}, /* id %d, line %d */\n", i, sc->obj[i].line);
    }
    if (d.count == 0)
        fputs("    {.kind = GEOM_SPHERE},\n", data);
    fputs("};\n", data);

    /* Ambient and lights (1/255 units), which the firmware adds with fxrt_set_ambient
     * and fxrt_add_light when FXRT_MAX_LIGHTS > 0 (SCENE_LIGHTS of them;
     * none when lighting is compiled out, where they change no pixel). */
    fputs("static const color_t scene_ambient = ", data);
    emit_color(data, lit ? d.ambient : color_make(NUM_ZERO, NUM_ZERO, NUM_ZERO));
    fputs(";\n", data);
    fprintf(data, "static const fxrt_light_t scene_lights[%d] = {\n", n_lights ? n_lights : 1);
    for (int i = 0; i < n_lights; i++) {
        const fxrt_light_t *l = &d.lights[i];
        fprintf(data, "    {.kind = %s, .position = ", light_kind_name(l->kind));
        emit_vec(data, l->position);
        fputs(", .direction = ", data);
        emit_vec(data, l->direction);
        fputs(", .angle_deg = ", data);
        emit_num(data, l->angle_deg);
        fputs(", .color = ", data);
        emit_color(data, l->color);
        fprintf(data, ", .shadows = %s}, /* light %d, line %d */\n", l->shadows ? "true" : "false", i,
                sc->light[i].line);
    }
    if (n_lights == 0)
        fputs("    {.kind = LIGHT_POINT},\n", data);
    fputs("};\n", data);

    /* Depth and samples, which the firmware sets with world_set_depth
     * (when FXRT_MAX_DEPTH > 0) and world_set_samples (when
     * FXRT_MAX_SAMPLES > 1) after the lights, as engine_build does. */
    fprintf(data, "static const int32_t scene_depth = %d; /* line %d */\n", d.depth, sc->depth_line);
    fprintf(data, "static const int32_t scene_samples = %d; /* line %d */\n", d.samples, sc->samples_line);
    fprintf(data, "static const bool scene_adaptive = %s;\n", d.adaptive ? "true" : "false");
    /* And, in Q16.16, the world these values make (host/scenec_world.c). */
    if (ENGINE_SYM(scenec_world)(data, &w, sc) != 0) {
        snprintf(err, errlen, "%s: cannot write the world", path);
        return -1;
    }
    return 0;
}
