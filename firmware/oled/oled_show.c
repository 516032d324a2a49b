/* oled_show: the compiled scene's frames, row by row, to a sink (see
 * oled_show.h). */
#include "oled_show.h"

#include "fxrt.h"
#include "scene_data.h"

#if FXRT_NUMBER != 1
#error "oled_show turns the camera in Q16.16 (fx_sin_deg): build with FXRT_NUMBER=1"
#endif
#if FXRT_PIXEL != FXRT_RGB888
#error "the sink takes RGB888 rows: build with FXRT_PIXEL=FXRT_RGB888"
#endif

static fxrt_world_t world;
static fxrt_render_t rs;
static fxrt_view_t cam;
static uint8_t row[FXRT_ROW_BYTES(SCENE_WIDTH)];

static void must(int32_t code, const char *what)
{
    if (code < 0)
        oled_sink_fail(what, fxrt_strerror(code));
}

/* The scene's world through the public API, as firmware/main.c and the
 * host tool (host/engine.c engine_build) build it: the same values in the
 * same order, so object ids and every rounding agree. */
static void build_scene(void)
{
    must(fxrt_world_init(&world, scene_background), "world");
    for (int32_t i = 0; i < SCENE_OBJECTS; i++) {
        int32_t id = fxrt_add(&world, &scene_objects[i]);
        must(id, "object");
        if (id != i)
            oled_sink_fail("object", "id out of scene order");
    }
#if FXRT_MAX_LIGHTS > 0
    must(fxrt_set_ambient(&world, scene_ambient), "ambient");
    for (int32_t i = 0; i < SCENE_LIGHTS; i++) {
        int32_t id = fxrt_add_light(&world, &scene_lights[i]);
        must(id, "light");
        if (id != i)
            oled_sink_fail("light", "index out of scene order");
    }
#else
    (void)scene_ambient; /* flat materials only: no lighting code linked */
    (void)scene_lights;
#endif
    /* Depth and samples after the lights, as engine_build; compiled out
     * (FXRT_MAX_DEPTH 0, FXRT_MAX_SAMPLES 1) where they change nothing. */
#if FXRT_MAX_DEPTH > 0
    must(fxrt_set_depth(&world, scene_depth), "depth");
#else
    (void)scene_depth;
#endif
#if FXRT_MAX_SAMPLES > 1
    must(fxrt_set_samples(&world, scene_samples, scene_adaptive), "samples");
#else
    (void)scene_samples;
    (void)scene_adaptive;
#endif
}

/* Frame f's camera (oled_show.h): the eye turned about the vertical
 * through pivot = eye + gaze, in Q16.16 (fx_sin_deg, fx_cos_deg: exact at
 * multiples of 90 degrees; the core's maths, below the public API, as
 * this program is Q16.16 only); gaze from the new eye back to the pivot. */
static fxrt_camera_t frame_camera(int32_t f)
{
    fxrt_camera_t c = scene_camera;
    if (OLED_TURN_DEG == 0 || f == 0)
        return c;
    fx_t a = fx_mul_int(F16(OLED_TURN_DEG), f);
    fx_t s = fx_sin_deg(a), k = fx_cos_deg(a);
    vec3_t pivot = vec3_add(c.eye, c.gaze);
    vec3_t d = vec3_neg(c.gaze); /* eye - pivot */
    vec3_t r = vec3_make(fx_add(fx_mul(d.x, k), fx_mul(d.z, s)), d.y, fx_sub(fx_mul(d.z, k), fx_mul(d.x, s)));
    c.eye = vec3_add(pivot, r);
    c.gaze = vec3_neg(r);
    return c;
}

int oled_show(void)
{
    build_scene();
    for (int32_t f = 0; f < OLED_FRAMES; f++) {
        oled_sink_begin(f, SCENE_WIDTH, SCENE_HEIGHT);
        fxrt_camera_t c = frame_camera(f);
        must(fxrt_camera_setup(&cam, &c), "camera");
        int32_t e = fxrt_render_setup(&rs, &world, &cam);
        if (e != FXRT_OK)
            oled_sink_fail("render set-up", e == FXRT_ERR_RENDER ? fxrt_render_error(&rs) : fxrt_strerror(e));
        for (int32_t r = 0; r < SCENE_HEIGHT; r++) {
            must(fxrt_render_row(&rs, r, row, sizeof row), "row");
            oled_sink_row(r, row);
        }
        oled_sink_end(f);
    }
    return 0;
}
