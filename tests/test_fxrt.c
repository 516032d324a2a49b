/* test_fxrt: the public API (core/fxrt.h) in each number type: ids in
 * scene order, every error code, capacity, the configuration check, and a
 * random sweep in which an independent domain oracle (written here in
 * double, from the documented rules) decides accept or reject. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../core/fxrt.h"
#include "add.h"
#include "check.h"

static num_t N(double x)
{
#if FXRT_NUMBER == FXRT_Q16
    double s = x * 65536.0;
    if (s > 2147483647.0)
        return FX_MAX;
    if (s < -2147483647.0)
        return -FX_MAX;
    return (fx_t)(s >= 0 ? floor(s + 0.5) : -floor(-s + 0.5));
#else
    return (num_t)x;
#endif
}

static double D(num_t a)
{
#if FXRT_NUMBER == FXRT_Q16
    return a / 65536.0;
#else
    return (double)a;
#endif
}

static vec3_t V(double x, double y, double z)
{
    return vec3_make(N(x), N(y), N(z));
}

/* Colours from intensity fractions (1 = full = COLOR_MAX). */
static double full(void)
{
    return D(COLOR_MAX);
}
static color_t C(double r, double g, double b)
{
    return color_make(N(r * full()), N(g * full()), N(b * full()));
}

static world_t world; /* 64 of each kind on the host: static */
static render_t rs;

static void test_ids(void)
{
    CHECK(fxrt_world_init(&world, C(0.1, 0.2, 0.3)) == FXRT_OK);
    CHECK(world_count(&world) == 0);
    CHECK(world_add_sphere(&world, V(0, 0, -3), N(0.5), C(1, 0, 0)) == 0);
    CHECK(world_add_plane(&world, V(0, -1, 0), V(0, 2, 0), C(0.3, 0.7, 0.3)) == 1);
    CHECK(world_add_box(&world, V(-1, -1, -6), V(1, 1, -5), C(0, 0, 1)) == 2);
    CHECK(world_add_triangle(&world, V(0, 0, -2), V(1, 0, -2), V(0, 1, -2), C(0.5, 0.5, 0.5)) == 3);
    CHECK(world_add_sphere(&world, V(2, 0, -3), N(0.25), C(0, 1, 0)) == 4);
    CHECK(world_count(&world) == 5);
    /* The ids are stored where the renderer breaks ties. */
    CHECK(world.spheres[0].obj.id == 0 && world.planes[0].obj.id == 1 && world.boxes[0].obj.id == 2 &&
          world.triangles[0].obj.id == 3 && world.spheres[1].obj.id == 4);
    /* The plane's normal is normalised on the way in. */
    CHECK(world.planes[0].n.y == NUM_ONE);
    /* The descriptor path gives the same ids. */
    fxrt_object_t o = {.kind = GEOM_BOX, .p = {V(0, 0, 0), V(1, 1, 1)}, .color = C(1, 1, 1)};
    CHECK(fxrt_add(&world, &o) == 5);
    o.kind = (geom_kind_t)17;
    CHECK(fxrt_add(&world, &o) == FXRT_ERR_KIND);
    CHECK(world_count(&world) == 6);
}

/* Every add-object refusal leaves the world as it was. */
static void expect_refused(int32_t got, fxrt_err_t want, const char *what)
{
    CHECK_MSG(got == want, "%s: got %d (%s), want %d", what, (int)got, fxrt_strerror(got), (int)want);
}

static void test_object_errors(void)
{
    fxrt_world_init(&world, C(0, 0, 0));
    const double L = FXRT_COORD_LIMIT;
    expect_refused(world_add_sphere(&world, V(L + 1, 0, 0), N(1), C(1, 1, 1)), FXRT_ERR_COORD, "sphere x");
    expect_refused(world_add_sphere(&world, V(0, 0, -L - 0.5), N(1), C(1, 1, 1)), FXRT_ERR_COORD, "sphere z");
    expect_refused(world_add_sphere(&world, V(0, 0, 0), N(0), C(1, 1, 1)), FXRT_ERR_RADIUS, "radius 0");
    expect_refused(world_add_sphere(&world, V(0, 0, 0), N(-1), C(1, 1, 1)), FXRT_ERR_RADIUS, "radius < 0");
    expect_refused(world_add_sphere(&world, V(0, 0, 0), N(FXRT_RADIUS_LIMIT + 1), C(1, 1, 1)), FXRT_ERR_RADIUS,
                   "radius > limit");
    expect_refused(world_add_sphere(&world, V(0, 0, 0), N(1), C(1.01, 0, 0)), FXRT_ERR_COLOR, "colour > 1");
    expect_refused(world_add_sphere(&world, V(0, 0, 0), N(1), C(0, -0.01, 0)), FXRT_ERR_COLOR, "colour < 0");
    expect_refused(world_add_plane(&world, V(0, 0, 0), V(0, 0, 0), C(1, 1, 1)), FXRT_ERR_DIRECTION, "zero normal");
    expect_refused(world_add_plane(&world, V(0, L + 1, 0), V(0, 1, 0), C(1, 1, 1)), FXRT_ERR_COORD, "plane point");
    expect_refused(world_add_plane(&world, V(0, 0, 0), V(0, L * 2, 0), C(1, 1, 1)), FXRT_ERR_COORD,
                   "plane normal beyond the limit");
    expect_refused(world_add_triangle(&world, V(0, 0, 0), V(1, 0, 0), V(0, 0, -L - 1), C(1, 1, 1)), FXRT_ERR_COORD,
                   "triangle c");
    expect_refused(world_add_box(&world, V(1, 0, 0), V(0, 1, 1), C(1, 1, 1)), FXRT_ERR_BOX, "box x");
    expect_refused(world_add_box(&world, V(0, 1, 0), V(1, 0, 1), C(1, 1, 1)), FXRT_ERR_BOX, "box y");
    expect_refused(world_add_box(&world, V(0, 0, 1), V(1, 1, 0), C(1, 1, 1)), FXRT_ERR_BOX, "box z");
    expect_refused(world_add_box(&world, V(0, 0, 0), V(L + 1, 1, 1), C(1, 1, 1)), FXRT_ERR_COORD, "box max");
#if FXRT_NUMBER != FXRT_Q16
    /* Values Q16.16 would turn into 0 are refused by every build. */
    expect_refused(world_add_sphere(&world, V(1e-6, 0, 0), N(1), C(1, 1, 1)), FXRT_ERR_TINY, "tiny coordinate");
    expect_refused(world_add_sphere(&world, V(0, 0, 0), N(1e-6), C(1, 1, 1)), FXRT_ERR_TINY, "tiny radius");
#endif
    CHECK(world_count(&world) == 0);
    /* Limits themselves are inside the domain; a flat box and a collinear
     * triangle are accepted. */
    CHECK(world_add_sphere(&world, V(L, -L, L), N(FXRT_RADIUS_LIMIT), C(0, 1, 0)) == 0);
    CHECK(world_add_box(&world, V(0, 0, 0), V(0, 1, 1), C(1, 1, 1)) == 1);
    CHECK(world_add_triangle(&world, V(0, 0, 0), V(1, 1, 1), V(2, 2, 2), C(1, 1, 1)) == 2);
    CHECK(world_count(&world) == 3);
    CHECK(fxrt_world_init(&world, C(1.5, 0, 0)) == FXRT_ERR_COLOR);
}

static void test_capacity(void)
{
    fxrt_world_init(&world, C(0, 0, 0));
    for (int i = 0; i < FXRT_MAX_SPHERES; i++)
        CHECK_SWEEP(world_add_sphere(&world, V(i, 0, -10), N(0.5), C(1, 0, 0)) == i, "sphere %d", i);
    expect_refused(world_add_sphere(&world, V(0, 0, -10), N(0.5), C(1, 0, 0)), FXRT_ERR_FULL, "sphere over capacity");
    CHECK(world.n_spheres == FXRT_MAX_SPHERES);
    /* Other kinds still have room, and take the next id. */
    CHECK(world_add_box(&world, V(0, 0, 0), V(1, 1, 1), C(1, 1, 1)) == FXRT_MAX_SPHERES);
}

static void test_camera(void)
{
    cam_t cam;
    vec3_t g = V(0, 0, -1), up = V(0, 1, 0);
    CHECK(fxrt_camera_perspective(&cam, V(0, 0, 0), g, up, N(45), 160, 120) == FXRT_OK);
    /* The trap: an eye at z = 30000 is representable in Q16.16 but
     * outside the domain (it rendered a sphere twice its size). */
    expect_refused(fxrt_camera_perspective(&cam, V(0, 0, 30000), g, up, N(45), 160, 120), FXRT_ERR_COORD,
                   "eye z = 30000");
    expect_refused(fxrt_camera_orthographic(&cam, V(0, 0, 30000), g, up, N(4), 160, 120), FXRT_ERR_COORD,
                   "ortho eye z = 30000");
    expect_refused(fxrt_camera_perspective(&cam, V(0, 0, 0), V(0, 0, 0), up, N(45), 160, 120), FXRT_ERR_DIRECTION,
                   "zero gaze");
    expect_refused(fxrt_camera_perspective(&cam, V(0, 0, 0), g, V(0, 0, 0), N(45), 160, 120), FXRT_ERR_DIRECTION,
                   "zero up");
    expect_refused(fxrt_camera_perspective(&cam, V(0, 0, 0), V(0, -1, 0), V(0, 1, 0), N(45), 160, 120), FXRT_ERR_UP,
                   "looking straight down with up 0 1 0");
    CHECK(fxrt_camera_perspective(&cam, V(0, 0, 0), V(0, -1, 0), V(0, 0, -1), N(45), 160, 120) == FXRT_OK);
    expect_refused(fxrt_camera_perspective(&cam, V(0, 0, 0), g, up, N(0), 160, 120), FXRT_ERR_FOV, "fov 0");
    expect_refused(fxrt_camera_perspective(&cam, V(0, 0, 0), g, up, N(180), 160, 120), FXRT_ERR_FOV, "fov 180");
    expect_refused(fxrt_camera_perspective(&cam, V(0, 0, 0), g, up, N(0.5), 160, 600), FXRT_ERR_NARROW, "narrow");
    expect_refused(fxrt_camera_perspective(&cam, V(0, 0, 0), g, up, N(45), 0, 120), FXRT_ERR_SIZE, "width 0");
    expect_refused(fxrt_camera_perspective(&cam, V(0, 0, 0), g, up, N(45), 160, FXRT_MAX_DIM + 1), FXRT_ERR_SIZE,
                   "height over FXRT_MAX_DIM");
    expect_refused(fxrt_camera_orthographic(&cam, V(0, 0, 0), g, up, N(0), 160, 120), FXRT_ERR_SCALE, "scale 0");
    expect_refused(fxrt_camera_orthographic(&cam, V(0, 0, 0), g, up, N(FXRT_RADIUS_LIMIT + 1), 160, 120),
                   FXRT_ERR_SCALE, "scale over the limit");
    expect_refused(fxrt_camera_orthographic(&cam, V(8000, 0, 0), g, up, N(1000), 160, 120), FXRT_ERR_EXTENT,
                   "ortho extent");
    fxrt_camera_t d = {.kind = CAM_ORTHOGRAPHIC, .eye = V(0, 0, 5), .gaze = g, .up = up, .scale = N(4),
                       .width = 32, .height = 24};
    CHECK(fxrt_camera_setup(&cam, &d) == FXRT_OK && cam.kind == CAM_ORTHOGRAPHIC && cam.width == 32);
    d.kind = (cam_kind_t)7;
    CHECK(fxrt_camera_setup(&cam, &d) == FXRT_ERR_CAMERA);
}

static void test_render_and_config(void)
{
    cam_t cam;
    fxrt_world_init(&world, C(0, 0, 0));
    CHECK(world_add_sphere(&world, V(0, 0, -3), N(1), C(0.7, 0.9, 0.3)) == 0);
    CHECK(fxrt_camera_perspective(&cam, V(0, 0, 0), V(0, 0, -1), V(0, 1, 0), N(45), 8, 8) == FXRT_OK);
    CHECK(fxrt_render_setup(&rs, &world, &cam) == FXRT_OK);
    cam_t wide = cam;
    wide.width = FXRT_RENDER_MAX_WIDTH + 1;
    CHECK(fxrt_render_setup(&rs, &world, &wide) == FXRT_ERR_WIDTH);
    CHECK(fxrt_render_setup(&rs, &world, &cam) == FXRT_OK);
    uint8_t row[FXRT_ROW_BYTES(8)];
    CHECK(sizeof row == 3 * 8);
    CHECK(fxrt_render_row(&rs, 4, row, sizeof row) == FXRT_OK);
    rgb8_t want = world.spheres[0].obj.rgb;
    CHECK(row[3 * 4] == want.r && row[3 * 4 + 1] == want.g && row[3 * 4 + 2] == want.b); /* centre: the sphere */
    CHECK(row[0] == 0 && row[1] == 0 && row[2] == 0);                                      /* corner: background */

    /* The first-call check, for a program that links with the wrong layout
     * anyway: sizes and the configuration symbol must be the core's. */
    static const uint32_t *const caps[] = {FXRT_KINDS(FXRT_CAPACITY_ADDRESS)};
    CHECK(fxrt_world_init_checked(&world, C(0, 0, 0), (uint32_t)sizeof(world_t), (uint32_t)sizeof(render_t),
                                  &FXRT_CONFIG_SYMBOL, caps) == FXRT_OK);
    static const uint32_t other = 1;
    /* Another capacity for the last kind: its address is not the core's. */
    const uint32_t *wrong[GEOM_KINDS];
    for (int k = 0; k < GEOM_KINDS; k++)
        wrong[k] = caps[k];
    wrong[GEOM_KINDS - 1] = &other;
    CHECK(fxrt_world_init_checked(&world, C(0, 0, 0), (uint32_t)sizeof(world_t), (uint32_t)sizeof(render_t),
                                  &FXRT_CONFIG_SYMBOL, wrong) == FXRT_ERR_CONFIG);
    CHECK(fxrt_world_init_checked(&world, C(0, 0, 0), (uint32_t)sizeof(world_t), (uint32_t)sizeof(render_t),
                                  &FXRT_CONFIG_SYMBOL, NULL) == FXRT_ERR_CONFIG);
    CHECK(fxrt_world_init_checked(&world, C(0, 0, 0), (uint32_t)sizeof(world_t) - 8, (uint32_t)sizeof(render_t),
                                  &FXRT_CONFIG_SYMBOL, caps) == FXRT_ERR_CONFIG);
    CHECK(fxrt_world_init_checked(&world, C(0, 0, 0), (uint32_t)sizeof(world_t), (uint32_t)sizeof(render_t) + 4,
                                  &FXRT_CONFIG_SYMBOL, caps) == FXRT_ERR_CONFIG);
    CHECK(fxrt_world_init_checked(&world, C(0, 0, 0), (uint32_t)sizeof(world_t), (uint32_t)sizeof(render_t), &other,
                                  caps) == FXRT_ERR_CONFIG);
    CHECK(fxrt_render_setup_checked(&rs, &world, &cam, (uint32_t)sizeof(render_t) / 2) == FXRT_ERR_CONFIG);
    CHECK(strstr(fxrt_strerror(FXRT_ERR_CONFIG), "configuration") != NULL);
}

static void test_strerror(void)
{
    /* Every code has its own text; unknown codes say so. */
    for (int a = -1; a >= FXRT_ERR_AXES; a--) {
        const char *s = fxrt_strerror(a);
        CHECK_MSG(s && *s && strcmp(s, "unknown error") != 0, "code %d", a);
        for (int b = a - 1; b >= FXRT_ERR_AXES; b--)
            CHECK_MSG(strcmp(s, fxrt_strerror(b)) != 0, "codes %d and %d share a text", a, b);
    }
    CHECK(strcmp(fxrt_strerror(-1000), "unknown error") == 0);
    /* Camera codes beyond the named ones keep cam_setup's text. */
    CHECK(strcmp(fxrt_strerror(FXRT_ERR_CAM_BASE + CAM_ERR_UP), cam_strerror(CAM_ERR_UP)) == 0);
    CHECK(strcmp(fxrt_strerror(7), "ok") == 0);
}

/* --- random sweep against an independent domain oracle ---------------- */

static uint64_t rng = 0x5eed0f1a2b3c4d5eull;

/* Uniform in [lo, hi]. */
static double uni(double lo, double hi)
{
    return lo + (hi - lo) * (double)(check_rng_next(&rng) >> 11) / 9007199254740992.0;
}

/* A value drawn over the full range a parameter can be given: mostly
 * uniform over twice the limit, sometimes exactly 0, the limit, or (for
 * the float builds' tiny rule) a magnitude around 2^-16. */
static int wide; /* this case draws over twice the range (else inside it) */
static double draw(double limit)
{
    switch (check_rng_next(&rng) % (wide ? 16 : 64)) {
    case 0: return 0;
    case 1: return limit;
    case 2: return -limit;
    case 3: return ldexp(uni(0.5, 1), -(int)(14 + check_rng_next(&rng) % 6)) * (check_rng_next(&rng) & 1 ? 1 : -1);
    default: return wide ? uni(-2 * limit, 2 * limit) : uni(-limit, limit);
    }
}

enum { R_COORD = 1, R_TINY = 2, R_DIR = 4, R_RADIUS = 8, R_COLOR = 16, R_BOX = 32 };

static int rule_of(fxrt_err_t e)
{
    switch (e) {
    case FXRT_ERR_COORD: return R_COORD;
    case FXRT_ERR_TINY: return R_TINY;
    case FXRT_ERR_DIRECTION: return R_DIR;
    case FXRT_ERR_RADIUS: return R_RADIUS;
    case FXRT_ERR_COLOR: return R_COLOR;
    case FXRT_ERR_BOX: return R_BOX;
    default: return 0;
    }
}

/* The documented rules, on the values the build actually holds. */
static int tiny(double v)
{
#if FXRT_NUMBER == FXRT_Q16
    (void)v;
    return 0;
#else
    return v != 0 && fabs(v) < 1.0 / 65536.0;
#endif
}
static int o_point(vec3_t p)
{
    double c[3] = {D(p.x), D(p.y), D(p.z)};
    int r = 0;
    for (int i = 0; i < 3; i++) {
        if (fabs(c[i]) > FXRT_COORD_LIMIT)
            r |= R_COORD;
        if (tiny(c[i]))
            r |= R_TINY;
    }
    return r;
}
static int o_dir(vec3_t d)
{
    int r = 0;
    if (fabs(D(d.x)) > FXRT_COORD_LIMIT || fabs(D(d.y)) > FXRT_COORD_LIMIT || fabs(D(d.z)) > FXRT_COORD_LIMIT)
        r |= R_COORD;
    if (D(d.x) == 0 && D(d.y) == 0 && D(d.z) == 0)
        r |= R_DIR;
    return r;
}
static int o_color(color_t c)
{
    double v[3] = {D(c.r), D(c.g), D(c.b)};
    int r = 0;
    for (int i = 0; i < 3; i++) {
        if (v[i] < 0 || v[i] > full())
            r |= R_COLOR;
        if (tiny(v[i]))
            r |= R_TINY;
    }
    return r;
}

static void test_random(long n)
{
    long accepted = 0, refused = 0;
    for (long i = 0; i < n; i++) {
        fxrt_world_init(&world, C(0, 0, 0));
        wide = (int)(check_rng_next(&rng) % 2);
        vec3_t p[3];
        for (int k = 0; k < 3; k++) {
            /* Directions often short or zero, points across the range. */
            double s = check_rng_next(&rng) % 4 == 0 ? 0 : 1;
            p[k] = V(draw(FXRT_COORD_LIMIT) * s, draw(FXRT_COORD_LIMIT), draw(FXRT_COORD_LIMIT) * s);
            if (check_rng_next(&rng) % (wide ? 8 : 64) == 0)
                p[k] = V(0, 0, 0);
        }
        num_t radius = N(wide ? draw(FXRT_RADIUS_LIMIT) : fabs(draw(FXRT_RADIUS_LIMIT)));
        color_t col = !wide ? C(uni(0, 1), uni(0, 1), uni(0, 1))
                                               : C(uni(-0.5, 1.5), uni(-0.5, 1.5), uni(-0.5, 1.5));
        int kind = (int)(check_rng_next(&rng) % 4), want = 0;
        int32_t got = 0;
        switch (kind) {
        case 0:
            want = o_point(p[0]) | o_dir(p[1]) | o_color(col);
            got = world_add_plane(&world, p[0], p[1], col);
            break;
        case 1: {
            double r = D(radius);
            want = o_point(p[0]) | o_color(col) | (r <= 0 || r > FXRT_RADIUS_LIMIT ? R_RADIUS : 0) |
                   (tiny(r) ? R_TINY : 0);
            got = world_add_sphere(&world, p[0], radius, col);
            break;
        }
        case 2:
            want = o_point(p[0]) | o_point(p[1]) | o_point(p[2]) | o_color(col);
            got = world_add_triangle(&world, p[0], p[1], p[2], col);
            break;
        default:
            want = o_point(p[0]) | o_point(p[1]) | o_color(col) |
                   (D(p[0].x) > D(p[1].x) || D(p[0].y) > D(p[1].y) || D(p[0].z) > D(p[1].z) ? R_BOX : 0);
            got = world_add_box(&world, p[0], p[1], col);
            break;
        }
        if (want == 0) {
            accepted++;
            CHECK_SWEEP(got == 0 && world_count(&world) == 1, "case %ld kind %d: refused %d (%s)", i, kind, (int)got,
                        fxrt_strerror(got));
        } else {
            refused++;
            CHECK_SWEEP(got < 0 && (rule_of((fxrt_err_t)got) & want) && world_count(&world) == 0,
                        "case %ld kind %d: got %d, oracle's violated rules 0x%x", i, kind, (int)got, want);
        }
    }
    printf("random sweep: %ld cases, %ld accepted, %ld refused\n", n, accepted, refused);
    /* Both outcomes must be well represented for the sweep to mean anything. */
    CHECK(accepted > n / 20 && refused > n / 20);
}

/* --- calls that cannot crash ---------------------------------------------
 * NULL pointers, rows out of range, short buffers, rows before a set-up or
 * after a refused one: each refused with its code, nothing written. */

#define GUARD 0xA5
static bool untouched(const uint8_t *b, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (b[i] != GUARD)
            return false;
    return true;
}

static void test_safety(void)
{
    static fxrt_render_t fresh; /* zeroed: never set up */
    fxrt_view_t view, zero_view;
    memset(&zero_view, 0, sizeof zero_view);
    uint8_t buf[FXRT_ROW_BYTES(8) + 8];
    memset(buf, GUARD, sizeof buf);
    CHECK(fxrt_render_row(&fresh, 0, buf, sizeof buf) == FXRT_ERR_SETUP && untouched(buf, sizeof buf));
    CHECK(fxrt_render_row(NULL, 0, buf, sizeof buf) == FXRT_ERR_NULL);
    CHECK(fxrt_render_row(&fresh, 0, NULL, 24) == FXRT_ERR_NULL);

    /* A world fxrt_world_init never set up: every call refuses it. */
    static fxrt_world_t raw;
    fxrt_object_t s0 = {.kind = FXRT_SPHERE, .p = {V(0, 0, -3)}, .radius = N(1), .color = C(0.5, 0.5, 0.5)};
    fxrt_material_t m0 = {.kind = FXRT_MATERIAL_FLAT};
    fxrt_light_t l0 = {.kind = FXRT_LIGHT_POINT, .position = V(0, 5, 0), .color = C(1, 1, 1)};
    CHECK(fxrt_add(&raw, &s0) == FXRT_ERR_INIT && fxrt_count(&raw) == 0);
    CHECK(fxrt_set_material(&raw, 0, &m0) == FXRT_ERR_INIT && fxrt_add_light(&raw, &l0) == FXRT_ERR_INIT);
    CHECK(fxrt_set_ambient(&raw, C(0, 0, 0)) == FXRT_ERR_INIT && fxrt_set_depth(&raw, 0) == FXRT_ERR_INIT);
    CHECK(fxrt_set_samples(&raw, 1, false) == FXRT_ERR_INIT);
    CHECK(fxrt_camera_perspective(&view, V(0, 0, 0), V(0, 0, -1), V(0, 1, 0), N(45), 8, 6) == FXRT_OK);
    CHECK(fxrt_render_setup(&rs, &raw, &view) == FXRT_ERR_INIT);
    CHECK(fxrt_world_init(&raw, C(2, 0, 0)) == FXRT_ERR_COLOR && fxrt_add(&raw, &s0) == FXRT_ERR_INIT);
    CHECK(fxrt_world_init(&raw, C(0, 0, 0)) == FXRT_OK && fxrt_add(&raw, &s0) == 0);

    CHECK(fxrt_world_init(NULL, C(0, 0, 0)) == FXRT_ERR_NULL);

    /* Specific codes: the exponent, the index, the lights' room, and a
     * view too wide for its samples. */
    fxrt_material_t bad = {.kind = FXRT_MATERIAL_PHONG, .exponent = 0, .specular = C(1, 1, 1)};
    CHECK(fxrt_set_material(&raw, 0, &bad) == FXRT_ERR_EXPONENT);
    bad.exponent = FXRT_PHONG_MAX_EXPONENT + 1;
    CHECK(fxrt_set_material(&raw, 0, &bad) == FXRT_ERR_EXPONENT);
    bad = (fxrt_material_t){.kind = FXRT_MATERIAL_TRANSPARENT, .index = N(FXRT_INDEX_MAX * 1.5)};
    CHECK(fxrt_set_material(&raw, 0, &bad) == FXRT_ERR_INDEX);
    bad.kind = 9;
    CHECK(fxrt_set_material(&raw, 0, &bad) == FXRT_ERR_MATERIAL && fxrt_set_material(&raw, 7, &m0) == FXRT_ERR_ID);
    for (int i = 0; i < FXRT_MAX_LIGHTS; i++)
        CHECK(fxrt_add_light(&raw, &l0) == i);
    CHECK(fxrt_add_light(&raw, &l0) == FXRT_ERR_LIGHTS);
#if FXRT_MAX_SAMPLES > 1
    CHECK(fxrt_set_samples(&raw, 2, false) == FXRT_OK);
    fxrt_view_t half;
    int32_t hw = FXRT_RENDER_MAX_WIDTH / 2 + 1;
    if (hw <= FXRT_MAX_DIM) {
        CHECK(fxrt_camera_perspective(&half, V(0, 0, 0), V(0, 0, -1), V(0, 1, 0), N(45), hw, 4) == FXRT_OK);
        CHECK(fxrt_render_setup(&rs, &raw, &half) == FXRT_ERR_WIDTH);
    }
#endif
    CHECK(fxrt_world_init(&world, C(0.2, 0.4, 0.6)) == FXRT_OK);
    fxrt_object_t o = {.kind = FXRT_SPHERE, .p = {V(0, 0, -3)}, .radius = N(1), .color = C(0.7, 0.2, 1)};
    CHECK(fxrt_add(NULL, &o) == FXRT_ERR_NULL && fxrt_add(&world, NULL) == FXRT_ERR_NULL && fxrt_count(&world) == 0);
    CHECK(fxrt_count(NULL) == 0);
    CHECK(fxrt_add(&world, &o) == 0 && fxrt_count(&world) == 1);
    fxrt_material_t m = {.kind = FXRT_MATERIAL_FLAT};
    CHECK(fxrt_set_material(NULL, 0, &m) == FXRT_ERR_NULL && fxrt_set_material(&world, 0, NULL) == FXRT_ERR_NULL);
    CHECK(fxrt_set_ambient(NULL, C(0, 0, 0)) == FXRT_ERR_NULL);
    CHECK(fxrt_set_depth(NULL, 0) == FXRT_ERR_NULL && fxrt_set_samples(NULL, 1, false) == FXRT_ERR_NULL);
    fxrt_light_t l = {.kind = FXRT_LIGHT_POINT, .position = V(0, 5, 0), .color = C(1, 1, 1)};
    CHECK(fxrt_add_light(NULL, &l) == FXRT_ERR_NULL && fxrt_add_light(&world, NULL) == FXRT_ERR_NULL);
    CHECK(fxrt_camera_perspective(NULL, V(0, 0, 0), V(0, 0, -1), V(0, 1, 0), N(45), 8, 8) == FXRT_ERR_NULL);
    CHECK(fxrt_camera_orthographic(NULL, V(0, 0, 0), V(0, 0, -1), V(0, 1, 0), N(4), 8, 8) == FXRT_ERR_NULL);
    CHECK(fxrt_camera_setup(&view, NULL) == FXRT_ERR_NULL);
    CHECK(fxrt_render_setup(NULL, &world, &view) == FXRT_ERR_NULL);
    CHECK(fxrt_render_setup(&rs, NULL, &view) == FXRT_ERR_NULL);
    CHECK(fxrt_render_setup(&rs, &world, NULL) == FXRT_ERR_NULL);
    CHECK(fxrt_render_setup(&rs, &world, &zero_view) == FXRT_ERR_SIZE); /* a view never set up */
    CHECK(fxrt_render_row(&rs, 0, buf, sizeof buf) == FXRT_ERR_SETUP && untouched(buf, sizeof buf));

    /* A good frame, then rows outside it and short buffers. */
    CHECK(fxrt_camera_perspective(&view, V(0, 0, 0), V(0, 0, -1), V(0, 1, 0), N(45), 8, 6) == FXRT_OK);
    CHECK(fxrt_render_setup(&rs, &world, &view) == FXRT_OK);
    const int32_t rows[] = {-1, 6, 7, INT32_MIN, INT32_MAX, -6};
    for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++)
        CHECK_MSG(fxrt_render_row(&rs, rows[i], buf, sizeof buf) == FXRT_ERR_ROW && untouched(buf, sizeof buf),
                  "row %ld", (long)rows[i]);
    CHECK(fxrt_render_row(&rs, 0, buf, FXRT_ROW_BYTES(8) - 1) == FXRT_ERR_BUFFER && untouched(buf, sizeof buf));
    CHECK(fxrt_render_row(&rs, 0, buf, 0) == FXRT_ERR_BUFFER && untouched(buf, sizeof buf));
    CHECK(fxrt_render_row(&rs, 5, buf, FXRT_ROW_BYTES(8)) == FXRT_OK);
    CHECK(untouched(buf + FXRT_ROW_BYTES(8), 8) && !untouched(buf, FXRT_ROW_BYTES(8)));

    /* A refused camera call leaves the view (and the frame on it) alone. */
    fxrt_view_t before = view;
    CHECK(fxrt_camera_perspective(&view, V(0, 0, 0), V(0, 0, -1), V(0, 1, 0), N(180), 8, 6) == FXRT_ERR_FOV);
    CHECK(fxrt_camera_orthographic(&view, V(0, 0, 0), V(0, 0, -1), V(0, 1, 0), N(-1), 8, 6) == FXRT_ERR_SCALE);
    CHECK(memcmp(&before, &view, sizeof view) == 0);
    /* The refusals that come after the basis is known (the camera's own
     * late checks: its focal length, its extent) leave it alone too. */
    CHECK(fxrt_camera_perspective(&view, V(1, 2, 3), V(0.3, -0.2, -1), V(0, 1, 0), N(1), 8, 4000) == FXRT_ERR_NARROW);
    CHECK(memcmp(&before, &view, sizeof view) == 0);
    CHECK(fxrt_camera_perspective(&view, V(1, 2, 3), V(0.3, -0.2, -1), V(0, 1, 0), N(179.9), 8, 1) < 0); /* (the grid nearer than half a pixel: a camera code without its own name) */
    CHECK(memcmp(&before, &view, sizeof view) == 0);
    CHECK(fxrt_camera_orthographic(&view, V(8000, 0, 0), V(0, 0, -1), V(0, 1, 0), N(1000), 8, 6) == FXRT_ERR_EXTENT);
    CHECK(memcmp(&before, &view, sizeof view) == 0);
    CHECK(fxrt_render_row(&rs, 3, buf, sizeof buf) == FXRT_OK);
    /* The view resized under a set-up frame: its rows are refused until the
     * next set-up (the forms and bounds are the old size's). */
    CHECK(fxrt_camera_perspective(&view, V(0, 0, 0), V(0, 0, -1), V(0, 1, 0), N(45), 4, 3) == FXRT_OK);
    memset(buf, GUARD, sizeof buf);
    CHECK(fxrt_render_row(&rs, 0, buf, sizeof buf) == FXRT_ERR_SETUP && untouched(buf, sizeof buf));
    CHECK(fxrt_render_setup(&rs, &world, &view) == FXRT_OK && fxrt_render_row(&rs, 2, buf, sizeof buf) == FXRT_OK);
    CHECK(untouched(buf + FXRT_ROW_BYTES(4), sizeof buf - FXRT_ROW_BYTES(4)));
    /* A refused set-up: no rows until one succeeds. */
    fxrt_view_t too_wide = view;
    too_wide.width = FXRT_RENDER_MAX_WIDTH + 1;
    CHECK(fxrt_render_setup(&rs, &world, &too_wide) == FXRT_ERR_WIDTH);
    CHECK(fxrt_render_row(&rs, 0, buf, sizeof buf) == FXRT_ERR_SETUP);
    CHECK(fxrt_render_error(NULL) == NULL);
#if FXRT_MAX_SAMPLES > 1
    /* With samples the rows are the output image's, not the fine camera's. */
    CHECK(fxrt_set_samples(&world, 2, false) == FXRT_OK);
    CHECK(fxrt_render_setup(&rs, &world, &view) == FXRT_OK);
    CHECK(fxrt_render_row(&rs, 2, buf, sizeof buf) == FXRT_OK && fxrt_render_row(&rs, 3, buf, sizeof buf) == FXRT_ERR_ROW);
    CHECK(fxrt_set_samples(&world, 1, false) == FXRT_OK);
#endif
}

/* A random sequence of API calls, every argument drawn over more than its
 * range (NULL pointers, unknown kinds, ids and rows out of range, sizes
 * from 0, buffers short or long), run under ASan and UBSan by make test.
 * The model kept here (not the core's state) says what each row call
 * must return: whether the last set-up succeeded and the view's size has
 * not changed since, the row's range, the buffer's length. An accepted
 * row writes exactly its FXRT_ROW_BYTES; a refused one writes nothing. */
static long pick(long n)
{
    return (long)(check_rng_next(&rng) % (uint64_t)n);
}
static double unit_draw(void)
{
    return uni(-1.5, 1.5);
}

static void test_api_sequence(long n)
{
    static fxrt_render_t fr;
    static fxrt_world_t fw;
    fxrt_view_t view;
    memset(&view, 0, sizeof view);
    memset(&fr, 0, sizeof fr);
    bool ready = false;           /* the last set-up on fr succeeded */
    int32_t set_w = 0, set_h = 0; /* the view's size then */
    uint8_t buf[FXRT_ROW_BYTES(24) + 16];
    long ok_rows = 0, refused = 0;
    CHECK(fxrt_world_init(&fw, C(0, 0, 0)) == FXRT_OK);
    for (long i = 0; i < n; i++) {
        switch (pick(9)) {
        case 0: /* world again */
            fxrt_world_init(pick(16) ? &fw : NULL, C(uni(-0.2, 1.2), uni(0, 1), uni(0, 1)));
            break;
        case 1: { /* an object, any kind number, any material */
            fxrt_object_t o;
            memset(&o, 0, sizeof o);
            o.kind = (geom_kind_t)pick(GEOM_KINDS + 2);
            for (int k = 0; k < 3; k++)
                o.p[k] = V(uni(-8, 8), uni(-8, 8), uni(-12, 2));
            o.radius = N(uni(-0.5, 3));
            o.color = C(uni(-0.1, 1.1), uni(0, 1), uni(0, 1));
            o.material.kind = (uint8_t)pick(7);
            o.material.exponent = (uint16_t)pick(1100);
            o.material.specular = C(uni(0, 1), uni(0, 1), uni(0, 1));
            o.material.index = N(uni(0, 3));
            int32_t before = fxrt_count(&fw);
            int32_t id = fxrt_add(pick(16) ? &fw : NULL, pick(16) ? &o : NULL);
            CHECK_SWEEP(id < fxrt_count(&fw) || id < 0, "call %ld: id %ld of %ld", i, (long)id, (long)fxrt_count(&fw));
            CHECK_SWEEP(id >= 0 || fxrt_count(&fw) == before, "call %ld: refused (%ld) but the world grew", i, (long)id);
            break;
        }
        case 2: { /* a material for any id */
            fxrt_material_t m = {.kind = (uint8_t)pick(7), .exponent = (uint16_t)pick(1100),
                                 .specular = C(uni(0, 1.2), uni(0, 1), uni(0, 1)),
                                 .reflection = C(uni(0, 1), uni(0, 1), uni(0, 1)), .index = N(uni(-1, 120))};
            fxrt_set_material(&fw, (int32_t)pick(fxrt_count(&fw) + 4) - 2, pick(16) ? &m : NULL);
            break;
        }
        case 3: { /* a light of any kind number */
            fxrt_light_t l = {.kind = (light_kind_t)pick(5), .position = V(uni(-9, 9), uni(-9, 9), uni(-9, 9)),
                              .direction = V(unit_draw(), unit_draw(), unit_draw()), .angle_deg = N(uni(-10, 100)),
                              .color = C(uni(0, 1.1), uni(0, 1), uni(0, 1)), .shadows = pick(2) != 0};
            fxrt_add_light(&fw, &l);
            fxrt_set_ambient(&fw, C(uni(0, 1.1), uni(0, 1), uni(0, 1)));
            break;
        }
        case 4: /* depth and samples, in and out of range */
            fxrt_set_depth(&fw, (int32_t)pick(FXRT_MAX_DEPTH + 4) - 1);
            fxrt_set_samples(&fw, (int32_t)pick(5) - 1, pick(2) != 0);
            break;
        case 5: { /* a camera: sizes from 0, any fov and scale */
            int32_t w = (int32_t)pick(25), h = (int32_t)pick(26);
            fxrt_vec3_t eye = V(uni(-4, 4), uni(-4, 4), uni(0, 8)), gaze = V(unit_draw(), unit_draw(), -1),
                        up = V(unit_draw(), 1, unit_draw());
            fxrt_err_t e = pick(3) ? fxrt_camera_perspective(&view, eye, gaze, up, N(uni(-10, 200)), w, h)
                                   : fxrt_camera_orthographic(&view, eye, gaze, up, N(uni(-1, 20)), w, h);
            if (e == FXRT_OK)
                CHECK_SWEEP(view.width == w && view.height == h, "call %ld: camera %dx%d", i, (int)w, (int)h);
            break;
        }
        case 6: { /* the set-up */
            int z = (int)pick(24);
            fxrt_err_t e = fxrt_render_setup(z == 0 ? NULL : &fr, z == 1 ? NULL : &fw, z == 2 ? NULL : &view);
            if (z != 0) {
                ready = e == FXRT_OK;
                set_w = view.width;
                set_h = view.height;
            }
            CHECK_SWEEP((e == FXRT_ERR_NULL) == (z <= 2), "call %ld: set-up %d (%s)", i, (int)e, fxrt_strerror(e));
            CHECK_SWEEP(e != FXRT_OK || (view.width <= 24 && view.height <= 25), "call %ld", i);
            break;
        }
        default: { /* a row: any row, any buffer length */
            int32_t row = pick(8) == 0 ? (int32_t)(pick(2) ? INT32_MAX : INT32_MIN) : (int32_t)pick(30) - 2;
            size_t len = pick(2) && set_w > 0 ? (size_t)FXRT_ROW_BYTES(set_w) + (size_t)pick(3) - 1
                                            : (size_t)pick(FXRT_ROW_BYTES(24) + 1);
            bool null_out = pick(32) == 0;
            memset(buf, GUARD, sizeof buf);
            fxrt_err_t e = fxrt_render_row(&fr, row, null_out ? NULL : buf, len);
            fxrt_err_t want = null_out                                            ? FXRT_ERR_NULL
                              : !ready || view.width != set_w || view.height != set_h ? FXRT_ERR_SETUP
                              : row < 0 || row >= set_h                           ? FXRT_ERR_ROW
                              : len < (size_t)FXRT_ROW_BYTES(set_w)               ? FXRT_ERR_BUFFER
                                                                                  : FXRT_OK;
            CHECK_SWEEP(e == want, "call %ld: row %ld len %zu: got %d (%s), want %d", i, (long)row, len, (int)e,
                        fxrt_strerror(e), (int)want);
            size_t wrote = e == FXRT_OK ? (size_t)FXRT_ROW_BYTES(set_w) : 0;
            CHECK_SWEEP(untouched(buf + wrote, sizeof buf - wrote), "call %ld: wrote past its row", i);
            e == FXRT_OK ? ok_rows++ : refused++;
        }
        }
    }
    printf("api sequence: %ld calls, %ld rows rendered, %ld refused\n", n, ok_rows, refused);
    CHECK(ok_rows > n / 200 && refused > n / 200); /* both sides exercised */
}

/* One colour unit: every colour the API takes is in 1/255 units. A
 * light's, the ambient's, a specular and a reflection colour given as the
 * level of a fraction x must be held as the fraction a scene file's x
 * gives, round(65536 x) / 65536, computed here from x directly (not via
 * levels), for x drawn over 0..1 with up to 5 decimals, and for every
 * whole level k / 255. */
static void test_color_unit(void)
{
    static fxrt_world_t cw;
    int checked = 0;
    for (int i = 0; i < 20000; i++) {
        double x[3];
        for (int k = 0; k < 3; k++)
            x[k] = i < 256 * 3 ? (double)((i + k * 97) % 256) / 255.0 : (double)pick(100001) / 100000.0;
        /* The level as the scene loader stores it (COLOR_FRAC). */
        color_t lv = color_make(N(floor(x[0] * 255 * 65536 + 0.5) / 65536), N(floor(x[1] * 255 * 65536 + 0.5) / 65536),
                                N(floor(x[2] * 255 * 65536 + 0.5) / 65536));
        CHECK_SWEEP(fxrt_world_init(&cw, C(0, 0, 0)) == FXRT_OK, "init");
        fxrt_object_t o = {.kind = FXRT_SPHERE, .p = {V(0, 0, -3)}, .radius = N(1), .color = lv};
        o.material = (fxrt_material_t){.kind = FXRT_MATERIAL_REFLECTIVE, .exponent = 8, .specular = lv, .reflection = lv};
        fxrt_light_t l = {.kind = FXRT_LIGHT_POINT, .position = V(0, 5, 0), .color = lv};
#if FXRT_MAX_LIGHTS > 0 && FXRT_PHONG
        CHECK_SWEEP(fxrt_add(&cw, &o) == 0 && fxrt_add_light(&cw, &l) == 0 && fxrt_set_ambient(&cw, lv) == FXRT_OK,
                    "x %.6f: refused", x[0]);
        checked++;
        const material_t *m = &world_common(&cw, GEOM_SPHERE, 0)->mat;
        for (int k = 0; k < 3; k++) {
            double want = floor(x[k] * 65536 + 0.5) / 65536;
            double got[4] = {D((&cw.lights[0].color.r)[k]), D((&cw.ambient.r)[k]), D((&m->specular.r)[k]),
                             D((&m->reflection.r)[k])};
            for (int j = 0; j < 4; j++)
                CHECK_SWEEP(got[j] == want, "x %.6f: colour %d channel %d holds %.9f, want %.9f", x[k], j, k, got[j],
                            want);
        }
#else
        (void)l;
        CHECK_SWEEP(fxrt_add(&cw, &o) == FXRT_ERR_MATERIAL && fxrt_count(&cw) == 0, "lighting compiled out");
        checked++;
#endif
    }
    CHECK(checked == 20000);
    /* Out of the unit: each refused with FXRT_ERR_COLOR, nothing added. */
    CHECK(fxrt_world_init(&cw, C(0, 0, 0)) == FXRT_OK);
    const double bad[] = {-0.5, 255.5, 1e6};
    for (size_t b = 0; b < sizeof bad / sizeof bad[0]; b++) {
        color_t c = color_make(N(0), N(bad[b]), N(0));
        fxrt_object_t o = {.kind = FXRT_SPHERE, .p = {V(0, 0, -3)}, .radius = N(1), .color = c};
        CHECK(fxrt_add(&cw, &o) == FXRT_ERR_COLOR);
        o.color = C(1, 1, 1);
        o.material = (fxrt_material_t){.kind = FXRT_MATERIAL_PHONG, .exponent = 8, .specular = c};
        fxrt_light_t l = {.kind = FXRT_LIGHT_POINT, .position = V(0, 5, 0), .color = c};
#if FXRT_MAX_LIGHTS > 0 && FXRT_PHONG
        CHECK(fxrt_add(&cw, &o) == FXRT_ERR_COLOR && fxrt_add_light(&cw, &l) == FXRT_ERR_COLOR);
        CHECK(fxrt_set_ambient(&cw, c) == FXRT_ERR_COLOR);
#else
        (void)l;
#endif
        CHECK(fxrt_count(&cw) == 0);
    }
}

int main(void)
{
    test_ids();
    test_object_errors();
    test_capacity();
    test_camera();
    test_render_and_config();
    test_strerror();
    test_random(200000);
    test_color_unit();
    test_safety();
    test_api_sequence(100000);
    return check_report("test_fxrt_" NUM_NAME);
}
