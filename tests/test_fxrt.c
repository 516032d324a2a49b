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
    fxrt_render_row(&rs, 4, row);
    rgb8_t want = world.spheres[0].obj.rgb;
    CHECK(row[3 * 4] == want.r && row[3 * 4 + 1] == want.g && row[3 * 4 + 2] == want.b); /* centre: the sphere */
    CHECK(row[0] == 0 && row[1] == 0 && row[2] == 0);                                      /* corner: background */

    /* The first-call check, for a program that links with the wrong layout
     * anyway: sizes and the configuration symbol must be the core's. */
    CHECK(fxrt_world_init_checked(&world, C(0, 0, 0), (uint32_t)sizeof(world_t), (uint32_t)sizeof(render_t),
                                  &FXRT_CONFIG_SYMBOL) == FXRT_OK);
    static const uint32_t other = 1;
    CHECK(fxrt_world_init_checked(&world, C(0, 0, 0), (uint32_t)sizeof(world_t) - 8, (uint32_t)sizeof(render_t),
                                  &FXRT_CONFIG_SYMBOL) == FXRT_ERR_CONFIG);
    CHECK(fxrt_world_init_checked(&world, C(0, 0, 0), (uint32_t)sizeof(world_t), (uint32_t)sizeof(render_t) + 4,
                                  &FXRT_CONFIG_SYMBOL) == FXRT_ERR_CONFIG);
    CHECK(fxrt_world_init_checked(&world, C(0, 0, 0), (uint32_t)sizeof(world_t), (uint32_t)sizeof(render_t), &other) ==
          FXRT_ERR_CONFIG);
    CHECK(fxrt_render_setup_checked(&rs, &world, &cam, (uint32_t)sizeof(render_t) / 2) == FXRT_ERR_CONFIG);
    CHECK(strstr(fxrt_strerror(FXRT_ERR_CONFIG), "configuration") != NULL);
}

static void test_strerror(void)
{
    /* Every code has its own text; unknown codes say so. */
    for (int a = -1; a >= FXRT_ERR_RENDER; a--) {
        const char *s = fxrt_strerror(a);
        CHECK_MSG(s && *s && strcmp(s, "unknown error") != 0, "code %d", a);
        for (int b = a - 1; b >= FXRT_ERR_RENDER; b--)
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

int main(void)
{
    test_ids();
    test_object_errors();
    test_capacity();
    test_camera();
    test_render_and_config();
    test_strerror();
    test_random(200000);
    return check_report("test_fxrt_" NUM_NAME);
}
