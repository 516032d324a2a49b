/* api_lang: one program in the common subset of C11 and C++11 (no
 * designated initialisers, no compound literals) that uses the public API
 * (core/fxrt.h) as an application would. tests/examples.sh compiles it
 * twice, as C with cc and as C++ with clang++, links both against the
 * same C core (the orbit example's configuration, tests/examples.mk),
 * runs both, and compares their output byte for byte: a C++ program links
 * against the core without an extern "C" of its own and sees the same
 * API. It writes two lit frames (a Phong sphere, a box and a triangle on a
 * plane, a point light with shadows; two cameras) as one binary PPM to
 * the file named by its argument, and checks that refused calls return
 * their codes. Exit 0 when every check passed. */
#include <stdio.h>
#include <string.h>

#include "fxrt.h"

#define LANG_W 64
#define LANG_H 48

static fxrt_world_t world;
static fxrt_render_t rs;
static fxrt_view_t view;
static uint8_t frame[2][LANG_H][FXRT_ROW_BYTES(LANG_W)];
static int fails;

static void expect(int ok, const char *what, int32_t got)
{
    if (!ok) {
        fprintf(stderr, "api_lang: %s (got %ld: %s)\n", what, (long)got, fxrt_strerror(got));
        fails++;
    }
}

static fxrt_vec3_t v3(double x, double y, double z) { return fxrt_vec3(FXRT_NUM(x), FXRT_NUM(y), FXRT_NUM(z)); }

static int32_t add(fxrt_kind_t kind, fxrt_vec3_t a, fxrt_vec3_t b, fxrt_vec3_t c, double radius, fxrt_color_t color)
{
    fxrt_object_t o;
    memset(&o, 0, sizeof o);
    o.kind = kind;
    o.p[0] = a;
    o.p[1] = b;
    o.p[2] = c;
    o.radius = FXRT_NUM(radius);
    o.color = color;
    return fxrt_add(&world, &o);
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: api_lang OUT.ppm\n");
        return 2;
    }
    expect(fxrt_world_init(&world, FXRT_RGB(0.05, 0.1, 0.2)) == FXRT_OK, "world", 0);
    fxrt_vec3_t o = v3(0, 0, 0);
    int32_t plane = add(FXRT_PLANE, v3(0, -1, 0), v3(0, 1, 0), o, 0, FXRT_RGB(0.7, 0.7, 0.65));
    int32_t ball = add(FXRT_SPHERE, v3(0, 0, 0), o, o, 0.9, FXRT_RGB(0.85, 0.3, 0.15));
    int32_t box = add(FXRT_BOX, v3(-2.2, -1, -0.6), v3(-1.2, 0.2, 0.4), o, 0, FXRT_RGB(0.95, 0.8, 0.25));
    int32_t tri = add(FXRT_TRIANGLE, v3(-0.5, -1, -2.2), v3(1.5, -1, -1.8), v3(0.4, 1.4, -2), 0,
                      FXRT_RGB(0.6, 0.25, 0.7));
    expect(plane == 0 && ball == 1 && box == 2 && tri == 3, "ids 0..3 in the order added", tri);
    /* A refused object changes nothing: a sphere of radius 0. */
    expect(add(FXRT_SPHERE, o, o, o, 0, FXRT_RGB(1, 1, 1)) == FXRT_ERR_RADIUS, "radius 0 refused", 0);
    expect(fxrt_count(&world) == 4, "count after a refusal", fxrt_count(&world));

    fxrt_material_t m;
    memset(&m, 0, sizeof m);
    m.kind = FXRT_MATERIAL_LAMBERT;
    for (int32_t id = 0; id < 4; id++)
        expect(fxrt_set_material(&world, id, &m) == FXRT_OK, "lambert", id);
    m.kind = FXRT_MATERIAL_PHONG;
    m.exponent = 24;
    m.specular = FXRT_RGB(0.8, 0.8, 0.8);
    expect(fxrt_set_material(&world, ball, &m) == FXRT_OK, "phong", ball);
    expect(fxrt_set_material(&world, 99, &m) == FXRT_ERR_ID, "an unknown id refused", 0);
    expect(fxrt_set_ambient(&world, FXRT_RGB(0.15, 0.15, 0.15)) == FXRT_OK, "ambient", 0);
    fxrt_light_t l;
    memset(&l, 0, sizeof l);
    l.kind = FXRT_LIGHT_POINT;
    l.position = v3(-3, 5, 3);
    l.color = FXRT_RGB(1, 1, 1);
    l.shadows = true;
    expect(fxrt_add_light(&world, &l) == 0, "light 0", 0);

    for (int f = 0; f < 2; f++) {
        fxrt_vec3_t eye = f == 0 ? v3(4, 2.5, 5.5) : v3(-5, 1.5, 3);
        expect(fxrt_camera_perspective(&view, eye, fxrt_vec3_sub(v3(0, -0.3, 0), eye), v3(0, 1, 0), FXRT_NUM(50),
                                       LANG_W, LANG_H) == FXRT_OK,
               "camera", f);
        expect(fxrt_render_setup(&rs, &world, &view) == FXRT_OK, "render set-up", f);
        for (int32_t r = 0; r < LANG_H; r++)
            expect(fxrt_render_row(&rs, r, frame[f][r], sizeof frame[f][r]) == FXRT_OK, "row", r);
    }
    /* The embedder's mistakes come back as codes, with nothing written. */
    uint8_t guard[FXRT_ROW_BYTES(LANG_W)];
    memset(guard, 0xA5, sizeof guard);
    int32_t e = fxrt_render_row(&rs, -1, guard, sizeof guard);
    expect(e == FXRT_ERR_ROW, "row -1 refused", e);
    e = fxrt_render_row(&rs, LANG_H, guard, sizeof guard);
    expect(e == FXRT_ERR_ROW, "row H refused", e);
    e = fxrt_render_row(&rs, 0, guard, sizeof guard - 1);
    expect(e == FXRT_ERR_BUFFER, "a short buffer refused", e);
    e = fxrt_render_row(NULL, 0, guard, sizeof guard);
    expect(e == FXRT_ERR_NULL, "NULL refused", e);
    expect(guard[0] == 0xA5 && guard[sizeof guard - 1] == 0xA5, "nothing written by a refused row", 0);
    expect(fxrt_strerror(FXRT_ERR_ROW) != NULL && strlen(fxrt_strerror(FXRT_ERR_ROW)) > 0, "strerror", 0);

    FILE *out = fopen(argv[1], "wb");
    if (!out) {
        fprintf(stderr, "api_lang: cannot write %s\n", argv[1]);
        return 2;
    }
    fprintf(out, "P6\n%d %d\n255\n", LANG_W, 2 * LANG_H);
    fwrite(frame, 1, sizeof frame, out);
    if (fclose(out) != 0)
        fails++;
    return fails ? 1 : 0;
}
