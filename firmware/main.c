/* Board main: set the compiled-in scene up through the public API
 * (core/fxrt.h: the camera and the renderer's forms, and where the world
 * is not in flash every object with its material, the ambient colour and
 * lights, the bounce depth and samples), render it and send it to the host as a binary PPM over semihosting, then report
 * instructions, RAM and stack. scene_data.h holds the scene's own values
 * (fxrt-scenec) and, in Q16.16, the world they make (SCENE_WORLD 1:
 * scene_world, constant, in flash, host/scenec_world.c); the camera, and
 * the float and double builds' world, are built here at boot through the
 * API.
 *
 * Frame modes (FXRT_FB_MODE):
 *   FXRT_FB_FULL    the whole frame in a static framebuffer, then one dump
 *   FXRT_FB_STREAM  FXRT_BAND_ROWS rows at a time, each band sent as soon
 *                   as it is rendered: RAM does not grow with image height
 * Pixel format of the framebuffer: FXRT_PIXEL (fxrt_config.h), the format
 * the core's render_row writes (full-frame mode): RGB888, or RGB565 as
 * uint16_t per pixel, expanded back to 8 bits for the PPM (lossy: low bits
 * replicated). The ray caster writes RGB888 only, so it is packed here.
 */
#include "fxrt.h"
#include "frame/raycast.h"
#include "scene_data.h"

#include "board.h"
#include "semihost.h"

/* FXRT_FB_MODE, FXRT_BAND_ROWS and their guards: core/fxrt_config.h. */
#ifndef FXRT_OUT_PATH
#error "FXRT_OUT_PATH (the host file for the frame, a build input set by firmware/firmware.mk) must be defined"
#endif

#define ROW_BYTES (3 * SCENE_WIDTH)

/* FXRT_RENDERER (fxrt_config.h) picks the loop: the fast renderer, the
 * reference loop or the per-pixel ray caster, for before/after and
 * baseline measurements. */
#if FXRT_RENDERER == FXRT_RENDERER_REFERENCE
#define RENDER_ROW(st, row, out) render_row_reference(st, row, out)
#elif FXRT_RENDERER == FXRT_RENDERER_RAYCAST
#define RENDER_ROW(st, row, out) raycast_row(world, &cam, row, out, NULL)
#else
#define RENDER_ROW(st, row, out) render_row(st, row, out)
#endif

/* The bounce loop's stack (FXRT_STACK_EXTRA) is the core's own
 * reservation (frame/api.c, FXRT_STACK_RESERVE), kept inside the stack by
 * linker/sections.ld. */

static render_t render_state;
#if defined(SCENE_WORLD) && SCENE_WORLD
/* The world as fxrt-scenec wrote it: its objects, lights and settings stay
 * in flash, and RAM holds only what a frame derives from them. */
static const world_t *const world = &scene_world;
#else
static world_t world_ram; /* built at boot from scene_objects */
static const world_t *const world = &world_ram;
#endif
static cam_t cam;

#if FXRT_FB_MODE == FXRT_FB_FULL
#if FXRT_PIXEL == FXRT_RGB888
static uint8_t framebuffer[SCENE_HEIGHT][ROW_BYTES] __attribute__((aligned(4)));
#else
static uint16_t framebuffer[SCENE_HEIGHT][SCENE_WIDTH] __attribute__((aligned(4)));
static uint8_t row_rgb[ROW_BYTES] __attribute__((aligned(4)));
#endif
#else
static uint8_t band[FXRT_BAND_ROWS][ROW_BYTES] __attribute__((aligned(4)));
#endif

static void fail2(const char *what, const char *msg)
{
    semihost_puts("fxrt firmware: ");
    semihost_puts(what);
    semihost_puts(msg);
    semihost_puts("\n");
    semihost_exit(2);
}

static void fail(const char *msg)
{
    fail2("", msg);
}

/* The camera, and where the world is not in flash its world, through the
 * public API, as the host tool builds them (host/engine.c engine_build):
 * same values, same order, so the object ids and every rounding agree. */
static void build_scene(void)
{
    int32_t e = fxrt_camera_setup(&cam, &scene_camera);
    if (e != FXRT_OK)
        fail2("camera: ", fxrt_strerror(e));
#if defined(SCENE_WORLD) && SCENE_WORLD
    /* The world is scene_world; the values it was made from are unused. */
    (void)scene_background;
    (void)scene_objects;
    (void)scene_ambient;
    (void)scene_lights;
    (void)scene_depth;
    (void)scene_samples;
    (void)scene_adaptive;
#else
    world_t *w = &world_ram;
    e = fxrt_world_init(w, scene_background);
    if (e != FXRT_OK)
        fail2("world: ", fxrt_strerror(e));
    for (int32_t i = 0; i < SCENE_OBJECTS; i++) {
        e = fxrt_add(w, &scene_objects[i]);
        if (e != i)
            fail2("object: ", e < 0 ? fxrt_strerror(e) : "id out of scene order");
    }
#if FXRT_MAX_LIGHTS > 0
    /* After the objects, as engine_build does: ambient, then the lights in
     * scene order (light i gets index i, its bit in a pixel's key). */
    e = fxrt_set_ambient(w, scene_ambient);
    if (e != FXRT_OK)
        fail2("ambient: ", fxrt_strerror(e));
    for (int32_t i = 0; i < SCENE_LIGHTS; i++) {
        e = fxrt_add_light(w, &scene_lights[i]);
        if (e != i)
            fail2("light: ", e < 0 ? fxrt_strerror(e) : "index out of scene order");
    }
#else
    /* Every material is flat (fxrt-scenec): no light changes a pixel and no
     * lighting code is linked; the (empty) tables stay unused. */
    (void)scene_ambient;
    (void)scene_lights;
#endif
    /* Then depth and samples, as engine_build does. fxrt-scenec compiles
     * bounces out (FXRT_MAX_DEPTH 0) when no object is reflective or
     * transparent, where the depth changes nothing, and supersampling
     * (FXRT_MAX_SAMPLES 1) for one sample per pixel, the world's default. */
#if FXRT_MAX_DEPTH > 0
    e = world_set_depth(w, scene_depth);
    if (e != FXRT_OK)
        fail2("depth: ", fxrt_strerror(e));
#else
    (void)scene_depth;
#endif
#if FXRT_MAX_SAMPLES > 1
    e = world_set_samples(w, scene_samples, scene_adaptive);
    if (e != FXRT_OK)
        fail2("samples: ", fxrt_strerror(e));
#else
    (void)scene_samples;
    (void)scene_adaptive;
#endif
#endif
}

static void send(int32_t fd, const void *buf, uint32_t len)
{
    if (semihost_write(fd, buf, len) != 0)
        fail("semihosting write failed");
}

/* "P6\n<w> <h>\n255\n" */
static void send_header(int32_t fd)
{
    char hdr[32];
    uint32_t n = 0;
    uint32_t vals[2] = {SCENE_WIDTH, SCENE_HEIGHT};
    hdr[n++] = 'P';
    hdr[n++] = '6';
    hdr[n++] = '\n';
    for (int i = 0; i < 2; i++) {
        char digits[8];
        int d = 0;
        uint32_t v = vals[i];
        do {
            digits[d++] = (char)('0' + v % 10);
            v /= 10;
        } while (v);
        while (d)
            hdr[n++] = digits[--d];
        hdr[n++] = i == 0 ? ' ' : '\n';
    }
    hdr[n++] = '2';
    hdr[n++] = '5';
    hdr[n++] = '5';
    hdr[n++] = '\n';
    send(fd, hdr, n);
}

#if FXRT_PIXEL == FXRT_RGB565
#if FXRT_RENDERER == FXRT_RENDERER_RAYCAST
static uint16_t pack565(const uint8_t *p)
{
    return (uint16_t)(((p[0] >> 3) << 11) | ((p[1] >> 2) << 5) | (p[2] >> 3));
}
#endif
static void unpack565(uint16_t c, uint8_t *p)
{
    uint8_t r = (uint8_t)(c >> 11), g = (uint8_t)((c >> 5) & 63), b = (uint8_t)(c & 31);
    p[0] = (uint8_t)((r << 3) | (r >> 2));
    p[1] = (uint8_t)((g << 2) | (g >> 4));
    p[2] = (uint8_t)((b << 3) | (b >> 2));
}
#endif

static void report(const char *key, uint64_t v)
{
    semihost_puts(key);
    semihost_put_u64(v);
    semihost_puts(" ");
}

int main(void)
{
#if defined(FXRT_TEST_FAULT)
    /* Test hook: an undefined instruction must end in the fault handler's
     * report and a non-zero exit. */
    __asm__ volatile("udf #0");
#elif defined(FXRT_TEST_HANG)
    /* Test hook: the QEMU runner's timeout must catch a hang. */
    for (volatile int spin = 1; spin;)
        ;
#endif
    int32_t fd = semihost_open_write(FXRT_OUT_PATH);
    if (fd < 0)
        fail("cannot open " FXRT_OUT_PATH " on the host");
    send_header(fd);

    counter_start();
    /* Counted apart: building the world and camera once at boot, and the
     * frame (render_setup and the rows) as before. */
    uint64_t tb = counter_ticks();
    build_scene();
    uint64_t t0 = counter_ticks();
    uint64_t build_ticks = t0 - tb;
    int32_t se = fxrt_render_setup(&render_state, world, &cam);
    if (se != FXRT_OK)
        fail2("render set-up: ", se == FXRT_ERR_RENDER && render_state.error ? render_state.error : fxrt_strerror(se));
#if FXRT_FB_MODE == FXRT_FB_FULL
#if FXRT_PIXEL == FXRT_RGB888
    for (int32_t row = 0; row < SCENE_HEIGHT; row++)
        RENDER_ROW(&render_state, row, framebuffer[row]);
#elif FXRT_RENDERER == FXRT_RENDERER_RAYCAST
    for (int32_t row = 0; row < SCENE_HEIGHT; row++) {
        RENDER_ROW(&render_state, row, row_rgb);
        for (int32_t x = 0; x < SCENE_WIDTH; x++)
            framebuffer[row][x] = pack565(&row_rgb[3 * x]);
    }
#else
    for (int32_t row = 0; row < SCENE_HEIGHT; row++) /* the core writes RGB565 */
        RENDER_ROW(&render_state, row, (uint8_t *)framebuffer[row]);
#endif
    uint64_t ticks = counter_ticks() - t0;
#if FXRT_PIXEL == FXRT_RGB888
    send(fd, framebuffer, sizeof framebuffer);
#else
    for (int32_t row = 0; row < SCENE_HEIGHT; row++) {
        for (int32_t x = 0; x < SCENE_WIDTH; x++)
            unpack565(framebuffer[row][x], &row_rgb[3 * x]);
        send(fd, row_rgb, ROW_BYTES);
    }
#endif
#else
    /* One span over the whole loop keeps the counter's resolution for the
     * frame; it includes the few guest instructions of each semihosting
     * call (the host side of the call costs the guest nothing). */
    for (int32_t row = 0; row < SCENE_HEIGHT; row += FXRT_BAND_ROWS) {
        int32_t n = SCENE_HEIGHT - row < FXRT_BAND_ROWS ? SCENE_HEIGHT - row : FXRT_BAND_ROWS;
        for (int32_t i = 0; i < n; i++)
            RENDER_ROW(&render_state, row + i, band[i]);
        send(fd, band, (uint32_t)(n * ROW_BYTES));
    }
    uint64_t ticks = counter_ticks() - t0;
#endif
    if (semihost_close(fd) != 0)
        fail("semihosting close failed");

    report("ticks=", ticks);
    /* SysTick ticks like ticks= (named so that qemu-run.sh's ticks= match
     * does not take it); tests/qemu.sh converts it to instructions. */
    report("build_tick_count=", build_ticks);
    report("pixels=", (uint64_t)SCENE_WIDTH * SCENE_HEIGHT);
    report("ram_static=", board_ram_static());
    report("stack_used=", board_stack_used());
    report("stack_size=", board_stack_size());
    semihost_puts("\n");
    if (board_stack_used() + FXRT_STACK_MARGIN > board_stack_size())
        fail("stack: the run left less than FXRT_STACK_MARGIN bytes of the reserved stack unused "
             "(stack_used= above; STACK_SIZE in linker/BOARD.ld)");
    return 0;
}
