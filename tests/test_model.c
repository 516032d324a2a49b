/* test_model: models, meshes placed in the world (core/scene/model.c),
 * through the public API, in one number type (one binary per type).
 *
 *   - the oracle: a scene with a model renders as the same scene with the
 *     model's triangles as triangle objects (the scanline renderer's flat
 *     pieces and its smooth triangles: another intersection, another
 *     normal, other shadow tests), vertices at the world positions the
 *     model's own map gives; icospheres (smooth and flat), a torus (it
 *     shadows itself) and a cube, under random placements (rotation,
 *     uneven scale, translation), random cameras, lights and materials;
 *   - the box around a model (geom_model_box) holds every vertex of it, over
 *     random placements;
 *   - its footprint on the screen (vis/rays.c) holds every pixel whose
 *     camera ray meets it, over random placements and cameras;
 *   - every refusal of fxrt_add for a model: no instance, a malformed
 *     mesh, maps that are not each other's inverse, a model beyond the
 *     coordinate limit, a full world; each leaves the world unchanged;
 *   - RAM: a model's record is the same for 12 triangles and for 1,280. */
#include "models.h"
#include "meshbuild.h"
#include "obj.h"
#include "fxrt.h"
#include "frame.h"

#define IMG_W 96
#define IMG_H 72

static fxrt_world_t world_a, world_b;
static fxrt_render_t render_a, render_b;
static uint8_t img_a[IMG_W * IMG_H * 3], img_b[IMG_W * IMG_H * 3];

/* (float, double: a value below 2^-16 is 0, as the API asks: a vertex
 * normal's component, say) */
static num_t num_d(double x)
{
    return NUM_EXACT ? num_from_q16((int32_t)lrint(x * 65536)) : fabs(x) < 1.0 / 65536 ? NUM_ZERO : (num_t)x;
}
static vec3_t vec_d(const double v[3]) { return vec3_make(num_d(v[0]), num_d(v[1]), num_d(v[2])); }

static bool render(const fxrt_world_t *w, const fxrt_view_t *v, fxrt_render_t *r, uint8_t *img)
{
    return frame_render(w, v, r, img, IMG_W, IMG_H);
}

static bool build(const char *text, bool smooth, meshbuild_t *mb)
{
    obj_t o;
    char err[256];
    if (obj_parse("gen.obj", text, strlen(text), &o, err, sizeof err) != 0 || meshbuild(&o, smooth, mb, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return false;
    }
    obj_free(&o);
    return true;
}

/* A random placement of a model about 2 units wide at the origin's
 * neighbourhood: rotation, uneven scale, translation. */
static bool place(const meshbuild_t *mb, double a[3][3], double b[3], bvh_inst_t *in)
{
    double r[3][3], sc[3];
    char err[256];
    rot(r, srand_(-FX_PI_D, FX_PI_D), srand_(-FX_PI_D, FX_PI_D), srand_(-FX_PI_D, FX_PI_D));
    double size = mb->step * 65534;
    for (int j = 0; j < 3; j++) {
        sc[j] = srand_(1.2, 2.4) / size;
        b[j] = srand_(-0.3, 0.3);
    }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            a[i][j] = r[i][j] * sc[j];
    if (meshbuild_instance(mb, a, b, in, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return false;
    }
    return true;
}

/* The scene both worlds share: a floor, a point light with shadows (and
 * sometimes a directional one), a random camera; the model's material. */
static void common(fxrt_world_t *w, const material_t *floor_m)
{
    fxrt_world_init(w, fxrt_color(num_from_int(20), num_from_int(30), num_from_int(40)));
    fxrt_object_t fl = {.kind = FXRT_PLANE};
    fl.p[0] = vec3_make(NUM_ZERO, num_from_int(-2), NUM_ZERO);
    fl.p[1] = vec3_make(NUM_ZERO, NUM_ONE, NUM_ZERO);
    fl.color = fxrt_color(num_from_int(200), num_from_int(190), num_from_int(180));
    fl.material = *floor_m;
    CHECK(fxrt_add(w, &fl) == 0);
}

/* One scene as a model and as triangles; the count of pixels whose
 * channels differ by more than tol. */
/* Both worlds lit alike (a random point light with shadows, ambient),
 * seen by one random camera: the count of pixels whose channels differ
 * by more than tol (-1: not rendered). */
static long light_view_compare(fxrt_light_t *L, color_t *amb, fxrt_view_t *view, int tol)
{
    double lp[3] = {srand_(-4, 4), srand_(3, 6), srand_(-4, 4)};
    *L = (fxrt_light_t){.kind = FXRT_LIGHT_POINT, .position = vec_d(lp), .shadows = true};
    L->color = fxrt_color(num_d(srand_(128, 255)), num_d(srand_(128, 255)), num_d(srand_(128, 255)));
    CHECK(fxrt_add_light(&world_a, L) >= 0 && fxrt_add_light(&world_b, L) >= 0);
    *amb = fxrt_color(num_d(25.5), num_d(25.5), num_d(25.5)); /* (colours in 1/255 units) */
    CHECK(fxrt_set_ambient(&world_a, *amb) == FXRT_OK && fxrt_set_ambient(&world_b, *amb) == FXRT_OK);
    double az = srand_(-FX_PI_D, FX_PI_D), el = srand_(0.05, 0.9), dist = srand_(5, 8);
    double eye[3] = {dist * cos(el) * sin(az), dist * sin(el), dist * cos(el) * cos(az)}, gz[3], up[3] = {0, 1, 0};
    for (int i = 0; i < 3; i++)
        gz[i] = -eye[i];
    CHECK(fxrt_camera_perspective(view, vec_d(eye), vec_d(gz), vec_d(up), num_from_int(40), IMG_W, IMG_H) == FXRT_OK);
    if (!render(&world_a, view, &render_a, img_a) || !render(&world_b, view, &render_b, img_b))
        return -1;
    long bad = 0;
    for (int p = 0; p < IMG_W * IMG_H; p++) {
        int d = 0;
        for (int c = 0; c < 3; c++) {
            int e = abs((int)img_a[3 * p + c] - (int)img_b[3 * p + c]);
            d = e > d ? e : d;
        }
        bad += d > tol;
    }
    return bad;
}

/* The model's material: phong, reflective (rays from the model to its
 * other triangles: a torus sees itself) or glass (rays through it: the
 * winding normal says entering or leaving). */
enum { SURF_PHONG, SURF_MIRROR, SURF_GLASS };
static long compare_one(const meshbuild_t *mb, bool smooth_tris, int surf, int tol, long *covered)
{
    double a[3][3], b[3];
    bvh_inst_t in;
    if (!place(mb, a, b, &in))
        return -1;
    material_t floor_m = {.kind = MATERIAL_LAMBERT};
    material_t m = {.kind = MATERIAL_PHONG, .exponent = (uint16_t)(2 + check_rng_next(&rng) % 120)};
    m.specular = fxrt_color(num_d(srand_(25, 255)), num_d(srand_(25, 255)), num_d(srand_(25, 255)));
    if (surf == SURF_MIRROR) {
        m.kind = MATERIAL_REFLECTIVE;
        m.reflection = fxrt_color(num_d(srand_(100, 255)), num_d(srand_(100, 255)), num_d(srand_(100, 255)));
    }
    if (surf == SURF_GLASS)
        m = (material_t){.kind = MATERIAL_TRANSPARENT, .index = num_d(srand_(1.1, 1.9))};
    color_t col = fxrt_color(num_d(srand_(30, 255)), num_d(srand_(30, 255)), num_d(srand_(30, 255)));
    common(&world_a, &floor_m);
    common(&world_b, &floor_m);
    fxrt_object_t o = {.kind = FXRT_MODEL, .color = col, .material = m, .inst = &in};
    if (fxrt_add(&world_a, &o) < 0)
        return -1;
    /* the triangles at the world vertices the model's map gives */
    const bvh_mesh_t *mesh = in.mesh;
    double mi[3][3]; /* M^-T = m^T 2^-e, for the normals (normalised after) */
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            mi[i][j] = ldexp(in.m[j][i], -in.e);
    for (uint32_t t = 0; t < mesh->n_triangles; t++) {
        uint32_t vi[3];
        bvh_tri(mesh, t, vi);
        fxrt_object_t tri = {.kind = FXRT_TRIANGLE, .color = col, .material = m};
        for (int k = 0; k < 3; k++) {
            double q[3] = {mesh->v[vi[k]][0], mesh->v[vi[k]][1], mesh->v[vi[k]][2]}, w[3];
            model_world(&in, q, w);
            tri.p[k] = vec_d(w);
            if (smooth_tris && mesh->vn) {
                double n[3], len = 0;
                for (int i = 0; i < 3; i++) {
                    n[i] = mi[i][0] * mesh->vn[vi[k]][0] + mi[i][1] * mesh->vn[vi[k]][1] + mi[i][2] * mesh->vn[vi[k]][2];
                    len += n[i] * n[i];
                }
                for (int i = 0; i < 3; i++)
                    n[i] /= sqrt(len);
                tri.smooth = true;
                tri.vn[k] = vec_d(n);
            }
        }
        if (fxrt_add(&world_b, &tri) < 0)
            return -1;
    }
    fxrt_light_t L;
    fxrt_view_t view;
    color_t amb;
    long bad = light_view_compare(&L, &amb, &view, tol);
    if (bad < 0)
        return -1;
    /* what the model changes: the pixels of the floor alone that differ */
    common(&world_b, &floor_m);
    CHECK(fxrt_add_light(&world_b, &L) >= 0 && fxrt_set_ambient(&world_b, amb) == FXRT_OK);
    if (!render(&world_b, &view, &render_b, img_b))
        return -1;
    for (int p = 0; p < IMG_W * IMG_H; p++)
        *covered += memcmp(img_a + 3 * p, img_b + 3 * p, 3) != 0;
    if (getenv("TEST_MODEL_PPM")) {
        FILE *f = fopen(getenv("TEST_MODEL_PPM"), "wb");
        fprintf(f, "P6\n%d %d\n255\n", IMG_W, IMG_H);
        fwrite(img_a, 1, sizeof img_a, f);
        fclose(f);
    }
    return bad;
}

static void test_oracle(void)
{
    static const struct {
        const char *name;
        int kind; /* 0 icosphere level 1, 1 torus 10 x 6, 2 cube, 3 icosphere level 1 flat */
        bool smooth;
        int surf;
    } cases[] = {{"icosphere 80 smooth", 0, true, SURF_PHONG},     {"icosphere 80 flat", 3, false, SURF_PHONG},
                 {"torus 120 flat", 1, false, SURF_PHONG},         {"torus 120 smooth", 1, true, SURF_PHONG},
                 {"cube 12", 2, false, SURF_PHONG},                {"torus 120 reflective", 1, false, SURF_MIRROR},
                 {"torus 120 smooth reflective", 1, true, SURF_MIRROR}, {"icosphere 80 glass", 3, false, SURF_GLASS},
                 {"icosphere 80 smooth glass", 0, true, SURF_GLASS},    {"torus 120 smooth glass", 1, true, SURF_GLASS}};
    /* Allowed: pixels off by more than 2 levels, of 96 x 72 = 6,912 per
     * scene (edges and shadow boundaries that rounding moves by a pixel:
     * Q16.16 has at most 2 in these scenes, float and double none). A
     * model that shadowed nothing of itself fails the torus (up to 117
     * pixels), one shaded flat where smooth the smooth cases (up to 866). */
    const long cap = NUM_EXACT ? 8 : 2;
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        buf_t text = {0};
        if (cases[c].kind == 1)
            torus(&text, 10, 6);
        else if (cases[c].kind == 2)
            bprintf(&text, "%s", cube_obj);
        else
            icosphere(&text, 1, 1.0);
        meshbuild_t mb;
        CHECK(build(text.s, cases[c].smooth, &mb));
        long worst = 0, total = 0, covered = 0;
        int scenes = 24, failed = 0;
        for (int s = 0; s < scenes; s++) {
            long bad = compare_one(&mb, cases[c].smooth, cases[c].surf, 2, &covered);
            CHECK_SWEEP(bad >= 0 && bad <= cap, "%s, scene %d: %ld pixels differ by more than 2 levels (cap %ld)",
                        cases[c].name, s, bad, cap);
            failed += bad < 0 || bad > cap;
            worst = bad > worst ? bad : worst;
            total += bad;
        }
        printf("model vs triangles, %s: %d scenes, worst %ld, mean %.1f pixels off by more than 2 levels; the model "
               "changes %.1f %% of the pixels\n",
               cases[c].name, scenes, worst, (double)total / scenes, 100.0 * covered / scenes / (IMG_W * IMG_H));
        /* the scenes show the model: it and its shadow change a twentieth
         * of the frame (glass, which casts none, a thirtieth) */
        CHECK_MSG(covered > scenes * IMG_W * IMG_H / (cases[c].surf == SURF_GLASS ? 30 : 20),
                  "%s: the model changes only %ld pixels in %d scenes", cases[c].name, covered, scenes);
        CHECK_MSG(failed == 0, "%s: %d of %d scenes over the cap", cases[c].name, failed, scenes);
        meshbuild_free(&mb);
        free(text.s);
    }
}

/* Glass: a cube mesh placed without turning (a scale per axis, a
 * translation) against the box kind at its corners, both transparent. The
 * box is a solid of the table (its exit decides where a ray leaves); the
 * mesh is not: each face's winding normal says whether a ray enters or
 * leaves. Another algorithm, the same frame but for edge pixels. */
static void test_glass_box(void)
{
    meshbuild_t mb;
    CHECK(build(cube_obj, false, &mb));
    const long cap = NUM_EXACT ? 8 : 2;
    long worst = 0, covered = 0;
    for (int s = 0; s < 24; s++) {
        double a[3][3] = {{0}}, b[3], size = mb.step * 65534;
        for (int j = 0; j < 3; j++) {
            a[j][j] = srand_(0.8, 2.4) / size;
            b[j] = srand_(-0.5, 0.5);
        }
        bvh_inst_t in;
        char err[256];
        CHECK(meshbuild_instance(&mb, a, b, &in, err, sizeof err) == 0);
        material_t floor_m = {.kind = MATERIAL_LAMBERT};
        material_t m = {.kind = MATERIAL_TRANSPARENT, .index = num_d(srand_(1.1, 1.9))};
        color_t col = fxrt_color(num_d(srand_(120, 255)), num_d(srand_(120, 255)), num_d(srand_(120, 255)));
        common(&world_a, &floor_m);
        common(&world_b, &floor_m);
        /* something to see through it: a lambert sphere beside */
        fxrt_object_t ball = {.kind = FXRT_SPHERE, .radius = num_d(0.7), .color = fxrt_color(num_from_int(40), num_from_int(90), num_from_int(230)),
                              .material = {.kind = MATERIAL_LAMBERT}};
        double bc[3] = {srand_(-3, 3), -1.3, srand_(-3, 3)};
        ball.p[0] = vec_d(bc);
        fxrt_object_t o = {.kind = FXRT_MODEL, .color = col, .material = m, .inst = &in};
        CHECK(fxrt_add(&world_a, &o) >= 0 && fxrt_add(&world_a, &ball) >= 0);
        /* the box at the corners the model's map gives */
        double lo[3], hi[3], qlo[3], qhi[3];
        for (int k = 0; k < 3; k++)
            qlo[k] = mb.mesh.node[0].lo[k], qhi[k] = mb.mesh.node[0].hi[k];
        model_world(&in, qlo, lo);
        model_world(&in, qhi, hi);
        fxrt_object_t bx = {.kind = FXRT_BOX, .color = col, .material = m};
        bx.p[0] = vec_d(lo);
        bx.p[1] = vec_d(hi);
        CHECK(fxrt_add(&world_b, &bx) >= 0 && fxrt_add(&world_b, &ball) >= 0);
        fxrt_light_t L;
        fxrt_view_t view;
        color_t amb;
        long bad = light_view_compare(&L, &amb, &view, 2);
        CHECK_SWEEP(bad >= 0 && bad <= cap, "glass cube %d: %ld pixels differ by more than 2 levels (cap %ld)", s, bad, cap);
        worst = bad > worst ? bad : worst;
        for (int p = 0; p < IMG_W * IMG_H; p++) /* (the pixels the glass tints: not the floor's grey) */
            covered += img_a[3 * p] != img_a[3 * p + 1] || img_a[3 * p + 1] != img_a[3 * p + 2];
    }
    printf("glass cube mesh vs glass box: 24 scenes, worst %ld pixels off by more than 2 levels (cap %ld); %ld "
           "coloured pixels\n",
           worst, cap, covered);
    CHECK(covered > 24 * 300);
    meshbuild_free(&mb);
}

static void test_bounds(void)
{
    buf_t text = {0};
    torus(&text, 24, 12);
    meshbuild_t mb;
    CHECK(build(text.s, false, &mb));
    long outside = 0;
    for (int s = 0; s < 500; s++) {
        double a[3][3], b[3];
        bvh_inst_t in;
        CHECK(place(&mb, a, b, &in));
        vec3_t lo, hi;
        if (!bvh_check(&in) || !geom_model_box(&in, &lo, &hi)) {
            outside++;
            continue;
        }
        double l[3] = {(double)num_to_q16(lo.x) / 65536, (double)num_to_q16(lo.y) / 65536, (double)num_to_q16(lo.z) / 65536};
        double h[3] = {(double)num_to_q16(hi.x) / 65536, (double)num_to_q16(hi.y) / 65536, (double)num_to_q16(hi.z) / 65536};
        if (!NUM_EXACT) {
            l[0] = (double)lo.x, l[1] = (double)lo.y, l[2] = (double)lo.z;
            h[0] = (double)hi.x, h[1] = (double)hi.y, h[2] = (double)hi.z;
        }
        for (uint32_t i = 0; i < mb.mesh.n_vertices; i++) {
            double q[3] = {mb.mesh.v[i][0], mb.mesh.v[i][1], mb.mesh.v[i][2]}, w[3];
            model_world(&in, q, w);
            for (int k = 0; k < 3; k++)
                outside += w[k] < l[k] || w[k] > h[k];
        }
    }
    CHECK_MSG(outside == 0, "500 placements of a torus: %ld vertex coordinates outside the model's box", outside);
    meshbuild_free(&mb);
    free(text.s);
}

/* A model's footprint (vis/rays.c): over random placements of a torus and
 * random cameras, near and far, every pixel whose camera ray meets the
 * model (the walk alone, bvh_first) lies between the first and last
 * column its footprint gives on that row; and the footprint leaves out a
 * good part of the model's screen box (else it would do nothing). */
static void test_footprint(void)
{
    buf_t text = {0};
    torus(&text, 24, 12);
    meshbuild_t mb;
    CHECK(build(text.s, false, &mb));
    long missed = 0, hits = 0, in_box = 0, in_cut = 0;
    for (int s = 0; s < 200; s++) {
        double a[3][3], b[3];
        bvh_inst_t in;
        CHECK(place(&mb, a, b, &in));
        fxrt_world_init(&world_a, fxrt_color(NUM_ZERO, NUM_ZERO, NUM_ZERO));
        fxrt_object_t o = {.kind = FXRT_MODEL, .color = fxrt_color(num_from_int(200), NUM_ZERO, NUM_ZERO), .inst = &in};
        if (fxrt_add(&world_a, &o) != 0)
            continue;
        double az = srand_(-FX_PI_D, FX_PI_D), el = srand_(-1.2, 1.2), dist = srand_(2.5, 12);
        double eye[3] = {dist * cos(el) * sin(az), dist * sin(el), dist * cos(el) * cos(az)}, gz[3], up[3] = {0, 1, 0};
        for (int i = 0; i < 3; i++)
            gz[i] = srand_(-0.8, 0.8) - eye[i]; /* (the model off the centre too, or partly off the screen) */
        fxrt_view_t view;
        if (fxrt_camera_perspective(&view, vec_d(eye), vec_d(gz), vec_d(up), num_d(srand_(20, 90)), IMG_W, IMG_H) !=
                FXRT_OK ||
            fxrt_render_setup(&render_a, &world_a, &view) != FXRT_OK)
            continue;
        const vis_t *r = &render_a.vis;
        const render_obj_t *ro = &r->obj[render_obj_of(r, GEOM_MODEL, 0)];
        const render_rect_t *rc = r->model_cut[0];
        for (int row = 0; row < IMG_H; row++) {
            int lo = IMG_W, hi = -1;
            for (int k = 0; k < RENDER_CUT; k++)
                if (row >= rc[k].r0 && row <= rc[k].r1 && rc[k].x0 <= rc[k].x1) {
                    lo = rc[k].x0 < lo ? rc[k].x0 : lo;
                    hi = rc[k].x1 > hi ? rc[k].x1 : hi;
                }
            for (int x = 0; x < IMG_W; x++) {
                bool box = row >= ro->r0 && row <= ro->r1 && x >= ro->x0 && x <= ro->x1, cut = box && x >= lo && x <= hi;
                in_box += box;
                in_cut += cut;
                ray_t ray;
                cam_ray(r->cam, x, IMG_H - 1 - row, &ray);
                bvh_hit_t h;
                if (!bvh_first(&world_a.models[0].in, &ray, NUM_MAX, BVH_NONE, &h))
                    continue;
                hits++;
                missed += !cut;
            }
        }
    }
    CHECK_MSG(hits > 50000 && missed == 0, "footprint: %ld of %ld pixels met outside it", missed, hits);
    CHECK_MSG(in_cut < in_box * 3 / 4, "footprint: %ld of the boxes' %ld pixels (%.0f %%)", in_cut, in_box,
              100.0 * (double)in_cut / (double)(in_box ? in_box : 1));
    printf("footprint: %ld pixels met, %ld of them outside it; it holds %.1f %% of the boxes' pixels\n", hits, missed,
           100.0 * (double)in_cut / (double)(in_box ? in_box : 1));
    meshbuild_free(&mb);
    free(text.s);
}

static void test_refusals(void)
{
    buf_t text = {0};
    icosphere(&text, 1, 1.0);
    meshbuild_t mb;
    CHECK(build(text.s, true, &mb));
    double a[3][3], b[3];
    bvh_inst_t in;
    CHECK(place(&mb, a, b, &in));
    color_t col = fxrt_color(num_from_int(100), num_from_int(100), num_from_int(100));
    fxrt_world_init(&world_a, col);
    fxrt_object_t o = {.kind = FXRT_MODEL, .color = col, .inst = NULL};
    CHECK(fxrt_add(&world_a, &o) == FXRT_ERR_NULL);
    /* the forward map off by 2^-10 in one entry: not the inverse */
    bvh_inst_t bad = in;
    bad.f[1][2] += (bad.f[1][2] >= 0 ? 1 : -1) * (1 << 20);
    o.inst = &bad;
    CHECK(fxrt_add(&world_a, &o) == FXRT_ERR_MESH);
    /* moved beyond the coordinate limit */
    bad = in;
    bad.t = vec3_make(num_from_int(FXRT_COORD_LIMIT), NUM_ZERO, NUM_ZERO);
    CHECK(fxrt_add(&world_a, &o) == FXRT_ERR_MESH);
    /* a malformed mesh: a triangle index out of range */
    bvh_mesh_t m2 = mb.mesh;
    uint16_t (*tri)[3] = malloc(m2.n_triangles * sizeof *tri);
    memcpy(tri, m2.tri16, m2.n_triangles * sizeof *tri);
    tri[m2.n_triangles / 2][1] = (uint16_t)m2.n_vertices;
    m2.tri16 = (const uint16_t(*)[3])tri;
    bad = in;
    bad.mesh = &m2;
    CHECK(fxrt_add(&world_a, &o) == FXRT_ERR_MESH);
    /* a bad colour, as for any kind */
    o.inst = &in;
    o.color = fxrt_color(num_from_int(256), NUM_ZERO, NUM_ZERO);
    CHECK(fxrt_add(&world_a, &o) == FXRT_ERR_COLOR);
    CHECK_MSG(world_count(&world_a) == 0, "refused models changed the world (%u objects)", world_count(&world_a));
    /* capacity: exactly FXRT_MAX_MODELS, then full */
    o.color = col;
    int added = 0;
    while (fxrt_add(&world_a, &o) >= 0)
        added++;
    CHECK_MSG(added == FXRT_MAX_MODELS, "%d models fit, capacity %d", added, FXRT_MAX_MODELS);
    CHECK(fxrt_add(&world_a, &o) == FXRT_ERR_FULL);
    free(tri);
    meshbuild_free(&mb);
    free(text.s);
}

/* What RAM a model takes is its record, whatever its triangles: the
 * record holds no triangle, and the same world holds a cube or an
 * icosphere of 1,280 (the frame's state, render_t, has one entry per
 * object either way). */
static void test_ram(void)
{
    CHECK_MSG(sizeof(geom_model_t) <= 256, "a model's record is %zu bytes", sizeof(geom_model_t));
    buf_t t1 = {0}, t2 = {0};
    bprintf(&t1, "%s", cube_obj);
    icosphere(&t2, 3, 1.0);
    meshbuild_t m1, m2;
    CHECK(build(t1.s, false, &m1) && build(t2.s, true, &m2));
    CHECK(m1.mesh.n_triangles == 12 && m2.mesh.n_triangles == 1280);
    double a[3][3], b[3];
    bvh_inst_t i1, i2;
    CHECK(place(&m1, a, b, &i1) && place(&m2, a, b, &i2));
    color_t col = fxrt_color(num_from_int(100), num_from_int(100), num_from_int(100));
    fxrt_world_init(&world_a, col);
    fxrt_object_t o = {.kind = FXRT_MODEL, .color = col, .inst = &i1};
    CHECK(fxrt_add(&world_a, &o) == 0);
    o.inst = &i2;
    CHECK(fxrt_add(&world_a, &o) == 1);
    CHECK(world_a.n_models == 2 && world_a.models[1].in.mesh == &m2.mesh);
    meshbuild_free(&m1);
    meshbuild_free(&m2);
    free(t1.s);
    free(t2.s);
}

int main(void)
{
    test_refusals();
    test_bounds();
    test_footprint();
    test_ram();
    test_oracle();
    test_glass_box();
    return check_report("test_model_" NUM_NAME);
}
