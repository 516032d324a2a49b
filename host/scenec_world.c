/* scenec_world: the world the host built, written as one constant C
 * initialiser (`static const world_t scene_world`), so that a Q16.16 board
 * keeps its objects, lights and settings in flash: RAM then holds only
 * what a frame derives from them (the renderer's records, vis/render.h).
 * A board built with SCENE_BOOT_WORLD defined builds the world at boot
 * through the API instead (SCENE_WORLD 0), as the float and double
 * builds do.
 *
 * Q16.16 only: its world is the same integers on the host and on every
 * board (the values come from the same world_add, world_set_material,
 * world_add_light, ... that engine_build runs), so a board that reads this
 * world renders what one that built it at boot would. The float and double
 * firmware, which are baselines, keep building theirs at boot (their
 * arithmetic may round differently on a board: the M4F fuses multiplies
 * and adds).
 *
 * Every initialiser is positional, in the order of the struct it fills,
 * and a field that a configuration leaves out is guarded by the same
 * condition as in its struct (`#if` lines, read by the board's
 * preprocessor with its own scene_config.h). A field left out here fails
 * the board's compile: -Wextra's -Wmissing-field-initializers under
 * -Werror, or a type that does not match. Each kind's record is written
 * from its field list in scene/kinds.h (GEOM_KIND_FIELDS), an empty
 * kind's array as one zero record. */
#include <inttypes.h>
#include <stdio.h>

#include "engine_build.h"
#include "scenec.h"

#if FXRT_NUMBER == FXRT_Q16
static void w_num(FILE *f, num_t v)
{
    fprintf(f, "%" PRId32, v);
}

static void w_wide(FILE *f, numw_t v)
{
    fprintf(f, "INT64_C(%" PRId64 ")", (int64_t)v);
}

static void w_vec(FILE *f, vec3_t v)
{
    fprintf(f, "{%" PRId32 ", %" PRId32 ", %" PRId32 "}", v.x, v.y, v.z);
}

/* Vectors, each followed by ", ". */
static void w_vecs(FILE *f, int n, const vec3_t *const v[])
{
    for (int i = 0; i < n; i++) {
        w_vec(f, *v[i]);
        fputs(", ", f);
    }
}

static void w_color(FILE *f, color_t c)
{
    fprintf(f, "{%" PRId32 ", %" PRId32 ", %" PRId32 "}", c.r, c.g, c.b);
}

static void w_common(FILE *f, const geom_common_t *c)
{
    fprintf(f, "{{%u, %u, %u}, %u,\n", c->rgb.r, c->rgb.g, c->rgb.b, c->id);
    fputs("#if FXRT_MAX_LIGHTS > 0 || FXRT_MAX_SAMPLES > 1\n", f);
    w_color(f, c->color);
    fputs(",\n#endif\n#if FXRT_MAX_LIGHTS > 0\n", f);
    fprintf(f, "{%u, %u, ", c->mat.kind, c->mat.exponent);
    w_color(f, c->mat.specular);
    fputs(", ", f);
    w_color(f, c->mat.reflection);
    fputs(", ", f);
    w_num(f, c->mat.index);
    fputs("},\n#endif\n}", f);
}

static void w_rows(FILE *f, const int32_t m[3][3])
{
    fputs("{", f);
    for (int r = 0; r < 3; r++)
        fprintf(f, "%s{%" PRId32 ", %" PRId32 ", %" PRId32 "}", r ? ", " : "", m[r][0], m[r][1], m[r][2]);
    fputs("}", f);
}

/* A model's placement. Its mesh is the one scenec_emit wrote for the
 * model's object, by the same name (scenec_mesh_name); NULL in the zero
 * record of an empty array. */
static void w_inst(FILE *f, const bvh_inst_t *in, const scene_t *sc, uint16_t id)
{
    char mesh[48] = "NULL";
    if (in->mesh) {
        mesh[0] = '&';
        ENGINE_SYM(scenec_mesh_name)(sc, id, mesh + 1, sizeof mesh - 1);
    }
    fprintf(f, "{%s, ", mesh);
    w_rows(f, in->m);
    fprintf(f, ", %" PRId32 ", ", in->e);
    w_vec(f, in->t);
    fputs(", ", f);
    w_rows(f, in->f);
    fprintf(f, ", %" PRId32 "}", in->fe);
}

static void w_affine(FILE *f, const geom_affine_t *a)
{
    fputs("{", f);
    w_vecs(f, 4, (const vec3_t *const[]){&a->c, &a->u, &a->v, &a->w});
    fputs("{", f);
    for (int k = 0; k < 3; k++) {
        fputs(k ? ", " : "", f);
        w_vec(f, a->inv[k]);
    }
    fputs("}, ", f);
    w_vec(f, a->half);
    fputs(", ", f);
    w_num(f, a->reach);
    fputs("}", f);
}

/* A triangle's smooth and vn, which a board has where its FXRT_SMOOTH
 * is 1 (the host tool always has them). */
#if !FXRT_SMOOTH
#error "the host tool is built with FXRT_SMOOTH, which a board's scene may use"
#endif
static void w_smooth(FILE *f, bool smooth, const vec3_t vn[3])
{
    fprintf(f, "\n#if FXRT_SMOOTH\n%d, {", smooth);
    for (int k = 0; k < 3; k++) {
        fputs(k ? ", " : "", f);
        w_vec(f, vn[k]);
    }
    fputs("},\n#endif\n", f);
}

/* Each record from its fields (scene/kinds.h, GEOM_KIND_FIELDS): w_KIND. */
#define W_VEC(r, x) w_vec(f, r->x)
#define W_NUM(r, x) w_num(f, r->x)
#define W_WIDE(r, x) w_wide(f, r->x)
#define W_BOOL(r, x) fprintf(f, "%d", r->x)
#define W_COMMON(r, x) w_common(f, &r->x)
#define W_INST(r, x) w_inst(f, &r->x, sc, r->obj.id)
#define W_AFFINE(r, x) w_affine(f, &r->x)
#define W_SMOOTH(r, x) w_smooth(f, r->smooth, r->vn)
/* Each field then ", ", but SMOOTH, which writes its own inside its #if. */
#define W_FIELD(T, x) W_##T(r, x); fputs(W_SEP_##T, f);
#define W_SEP_VEC ", "
#define W_SEP_NUM ", "
#define W_SEP_WIDE ", "
#define W_SEP_BOOL ", "
#define W_SEP_COMMON ", "
#define W_SEP_INST ", "
#define W_SEP_AFFINE ", "
#define W_SEP_SMOOTH ""
#define W_RECORD(K, k, ...)                                                          \
    FXRT_IF_##K(static void w_##k(FILE *f, const geom_##k##_t *r, const scene_t *sc) \
                {                                                                    \
                    (void)sc;                                                        \
                    fputs("{", f);                                                   \
                    GEOM_##K##_FIELDS(W_FIELD)                                       \
                    fputs("}", f);                                                   \
                })
FXRT_KINDS(W_RECORD)
#undef W_RECORD

static void w_light(FILE *f, const light_t *l)
{
    fprintf(f, "{%u, %d, {%u, %u}, ", l->kind, l->shadows, l->axes[0], l->axes[1]);
    w_vecs(f, 2, (const vec3_t *const[]){&l->position, &l->dir});
    w_num(f, l->cos_angle);
    fputs(", ", f);
    w_color(f, l->color);
    fprintf(f, ", {%" PRId32 ", %" PRId32 ", %" PRId32 "}, %" PRId32 "}", l->axis30[0], l->axis30[1], l->axis30[2],
            l->cos30);
}

static void w_bytes(FILE *f, const uint8_t *b, unsigned n)
{
    fputs("{", f);
    for (unsigned i = 0; i < n; i++)
        fprintf(f, "%s%u", i ? (i % 24 ? ", " : ",\n ") : "", b[i]);
    fputs(n ? "}" : "0}", f); /* (an array of bytes: {0} is complete) */
}
#endif

int ENGINE_SYM(scenec_world)(FILE *f, const world_t *w, const scene_t *sc)
{
#if FXRT_NUMBER == FXRT_Q16
    fputs("/* The world in flash (host/scenec_world.c): what engine_build made of\n"
          " * the objects above, field by field. */\n",
          f);
    fputs("#ifdef SCENE_BOOT_WORLD /* (the board builds it at boot through the API) */\n#define SCENE_WORLD 0\n"
          "#else\n#define SCENE_WORLD 1\nstatic const world_t scene_world = {\n",
          f);
    w_color(f, w->background);
    fprintf(f, ", {%u, %u, %u}, %u,\n", w->background_rgb.r, w->background_rgb.g, w->background_rgb.b, w->ready);
    /* Per kind: its count and its records. */
#define W_KIND(K, k, ks, cap, ...)                                                \
    FXRT_IF_##K(fprintf(f, "#if " #cap " > 0\n%u, {\n", (unsigned)w->n_##ks);       \
                static const geom_##k##_t zero_##k;                                \
                for (unsigned i = 0; i < (w->n_##ks ? w->n_##ks : 1u); i++) {      \
                    fputs("  ", f);                                                \
                    w_##k(f, w->n_##ks ? &w->ks[i] : &zero_##k, sc);               \
                    fputs(",\n", f);                                               \
                } fputs("},\n#endif\n", f);)
    FXRT_KINDS(W_KIND)
#undef W_KIND
    fputs("#if WORLD_MESH\n", f);
#if WORLD_MESH
    fprintf(f, "%u, ", (unsigned)w->mesh_n);
    w_bytes(f, w->mesh_up, w->n_triangles);
    fputs(", ", f);
    w_bytes(f, w->mesh_bits, w->n_triangles);
    fputs(",\n", f);
#else
#error "the host tool links closed meshes, which a board's scene may use"
#endif
    fputs("#endif\n#if FXRT_MAX_LIGHTS > 0\n", f);
    w_color(f, w->ambient);
    fprintf(f, ", %u, %u, {", w->n_lights, w->n_lit);
    static const light_t zero_light;
    for (unsigned i = 0; i < (w->n_lights ? w->n_lights : 1u); i++) {
        w_light(f, w->n_lights ? &w->lights[i] : &zero_light);
        fputs(", ", f);
    }
    fputs("},\n#endif\n", f);
    fputs("#if FXRT_MAX_DEPTH > 0\n", f);
    fprintf(f, "%u, %u, %d, ", w->depth, w->n_bounce, w->bounded);
    w_vecs(f, 3, (const vec3_t *const[]){&w->bmin, &w->bmax, &w->bc});
    w_wide(f, w->br2);
    fputs(",\n#endif\n#if FXRT_MAX_SAMPLES > 1\n", f);
    fprintf(f, "%u, %d,\n#endif\n};\n#endif\n", w->samples, w->adaptive);
#else
    (void)w;
    (void)sc;
    fputs("#define SCENE_WORLD 0 /* built at boot: Q16.16 only (host/scenec_world.c) */\n", f);
#endif
    return ferror(f) ? -1 : 0;
}
