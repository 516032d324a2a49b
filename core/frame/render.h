/* render: a frame, all passes (the frame layer's state and entry points).
 *
 * A frame is set up once (render_setup) and then rendered row by row
 * (render_row): the visibility pass (vis/) finds each column's nearest
 * object and paints the flat ones; the shading pass (frame/render_shade.c)
 * colours the lit ones with the light sum (light/); with samples N > 1 the
 * sampler (frame/render_sample.c) runs both on N fine rows per output row
 * and averages them. render_t holds each stage's part: the visibility
 * state, the shading constants, the sampler's sums. */
#ifndef FXRT_FRAME_RENDER_H
#define FXRT_FRAME_RENDER_H

#include "light/shade.h"
#include "vis/render.h"

#if FXRT_MAX_SAMPLES > 1
/* The sampler's state (samples > 1): vis.cam points to `fine`, the camera
 * of the N x N cells (cam_fine), and out_cam to the output camera; each
 * output row sums the clamped colours of its N fine rows in acc (Q16.16:
 * raw units, at most 255 * 2^16 * 256 < 2^32). */
typedef struct {
    uint8_t samples;
    bool adaptive;
    /* Per object (index into vis.obj): one sample of its colour (color_sum_add); flat ones only are read. */
    color_sum_t one[FXRT_RENDER_MAX_OBJECTS][3];
    color_sum_t bg_one[3]; /* one sample of the background */
    const cam_t *out_cam;
    cam_t fine;
    uint8_t fine_rgb[(FXRT_PIXEL == FXRT_RGB565 ? 2 : 3) * FXRT_RENDER_MAX_WIDTH] __attribute__((aligned(4)));
    color_sum_t acc[3 * RENDER_OUT_COLS];
    uint16_t sole_owner[RENDER_OUT_COLS]; /* render_sample.c: the one flat owner of a pixel's samples so far */
#if RENDER_RUNS
    /* Run mode: the runs of fine row j of the current output row are
     * runs[run_at[j] .. run_at[j + 1] - 1], sorted, not overlapping; gaps
     * are the background. */
    render_run_t runs[FXRT_SAMPLE_RUNS];
    uint16_t run_at[FXRT_MAX_SAMPLES + 1];
    /* run_cap: the runs an output row may use, FXRT_SAMPLE_RUNS after
     * render_setup (a test may lower it to force the per-sample pass);
     * run_rows: output rows rendered from runs so far (a statistic). */
    uint16_t run_cap;
    uint32_t run_rows;
#endif
#if FXRT_ADAPTIVE
    /* Adaptive: keys and colours of output rows at one sample per pixel
     * (a ring of three rows: slot row % 3 holds row coarse_row[row % 3]), and
     * per column whether the pixel takes the N x N rays. */
    uint32_t coarse_keys[3][RENDER_OUT_COLS];
    rgb8_t coarse_rgb[3][RENDER_OUT_COLS];
    int32_t coarse_row[3];
    bool need[RENDER_OUT_COLS];
#endif
} render_sample_t;
/* Are output rows sampled (render_sampled, below)? The output image's
 * camera (with samples, vis.cam is the fine one). */
#define RENDER_SAMPLED(r) ((r)->sample.samples > 1)
#define RENDER_OUT_CAM(r) (RENDER_SAMPLED(r) ? (r)->sample.out_cam : (r)->vis.cam)
#else
#define RENDER_SAMPLED(r) ((void)(r), false)
#define RENDER_OUT_CAM(r) ((r)->vis.cam)
#endif

#if FXRT_MAX_LIGHTS > 0
/* The shading pass's per-frame state. */
typedef struct {
    bool any_lit;
    bool all_directional; /* every light directional (shade_flat_prep), once per frame */
    bool all_spots;       /* every light a spot, and one at least (shade_flat_prep), once per frame */
    bool no_directional;  /* no light directional (shade_flat_prep), once per frame */
    /* Per object (index into vis.obj): its shading constants, once per frame. */
    shade_k_t k[FXRT_RENDER_MAX_OBJECTS];
    /* The flat object whose hit numerator the shading pass keeps (vis
     * index; RENDER_VIS_NONE: none yet), and that numerator:
     * frame/render_shade.c. */
    uint16_t flat_of;
    shade_flat_t flat;
    /* The current row's camera rays (scene/cam.h), and the current
     * pixel's: here, not on the stack (the shading path is the deepest a
     * 16 KB board's 2 KB stack holds). */
    cam_row_t row;
    ray_t ray;
#if SHADOW_CULL
    /* Shadow-ray culling, per light and bounded object, and the current
     * row's masks per plane and light (light/shadow.c). */
    shadow_table_t cull;
#endif
} render_shade_t;
/* Object oi's shading constants (NULL without lighting). */
#define RENDER_SHADE_K(r, oi) (&(r)->shade.k[oi])
#else
#define RENDER_SHADE_K(r, oi) ((void)(oi), (const shade_k_t *)NULL)
#endif

typedef struct {
    vis_t vis; /* first: the visibility pass's own */
    FXRT_IF_LIGHTS(render_shade_t shade;)
    FXRT_IF_SAMPLES(render_sample_t sample;)
    /* Optional, set with render_set_keys after render_setup: when not
     * NULL, render_row and render_row_reference also write each pixel's
     * key (render_key) into keys[0 .. width-1]. */
    uint32_t *keys;
    const char *error; /* why render_setup failed, or NULL */
    /* The output image's size at the last set-up through the API
     * (frame/api.c: fxrt_render_row refuses rows once the view has changed
     * under the frame, so a changed view cannot write past a row). */
    uint16_t out_width, out_height;
} render_t;

/* Per-frame set-up: camera-space forms and screen bounds of every object.
 * The world and camera must outlive r. Returns false (r->error says why)
 * when the camera is wider than FXRT_RENDER_MAX_WIDTH or the boxes need
 * more faces than FXRT_RENDER_BOX_FACES. */
bool render_setup(render_t *r, const world_t *w, const cam_t *cam);

/* A pixel's key: the nearest object's scene id and the set of lights that
 * reach its hit point (bit i for light i; light/shade.c), id << 8 | mask.
 * A pixel that shows the background has RENDER_KEY_MISS. Two neighbouring
 * pixels with different keys mark a discontinuity (silhouette, shadow
 * edge, spot-cone edge, terminator): host/compare.c. */
#define RENDER_KEY_MISS 0xFFFF00u
static inline uint32_t render_key(uint16_t id, uint8_t mask) { return (uint32_t)id << 8 | mask; }

/* With samples N > 1 (world_set_samples), render_row and
 * render_row_reference give each pixel the mean of its N x N cell-centre
 * rays, each clamped to [0, 1], rounded to 8 bits (core/frame/render_sample.c);
 * keys are then not written (they are defined at one sample per pixel). */

/* Render output row `row` (0 = top) into rgb in the FXRT_PIXEL format:
 * RGB888, 3 * width bytes; RGB565, width uint16_t values in native byte
 * order (rgb 2-byte aligned). */
void render_row(render_t *r, int32_t row, uint8_t *rgb);

/* The same image from the straightforward loop: every object's forms
 * evaluated from scratch at every pixel, no bounds, no stepping. The Q16.16
 * build's output is byte-identical to render_row (tests enforce it). */
void render_row_reference(render_t *r, int32_t row, uint8_t *rgb);

/* The colour seen along one arbitrary ray (world-space kernels). */
rgb8_t render_pixel(const world_t *w, const ray_t *ray);

/* Where render_row and render_row_reference write each pixel's key (NULL:
 * nowhere); see render_t's keys. */
static inline void render_set_keys(render_t *r, uint32_t *keys)
{
    r->keys = keys;
    r->vis.want_keys = keys != NULL;
}

/* The shading pass (frame/render_shade.c, FXRT_MAX_LIGHTS > 0): its
 * per-frame constants (after the visibility set-up) and a row. */
void render_shade_setup(render_t *r, const world_t *w);
void render_shade_row(render_t *r, int32_t row, uint8_t *rgb);
/* The colour of vis object oi along camera ray `ray` as cam_ray_raw makes
 * it, normalised in place where needed (shade_object_k with its
 * constants; a flat object's hit numerator is kept across pixels). */
color_t render_shade_object(render_t *r, uint16_t oi, ray_t *ray, uint8_t *mask);
/* The sampler (frame/render_sample.c, FXRT_MAX_SAMPLES > 1): its part of
 * render_setup before the visibility set-up (*cam becomes the fine camera
 * when the world's samples are more than 1; false, with r->error, when
 * the frame cannot be sampled), the objects' one-sample colours after it,
 * and an output row. */
bool render_sample_setup(render_t *r, const world_t *w, const cam_t **cam);
void render_sample_objects(render_t *r, const world_t *w);
void render_sample_row(render_t *r, int32_t row, uint8_t *rgb, bool reference);
/* Are output rows sampled (samples > 1)? */
static inline bool render_sampled(const render_t *r)
{
    return RENDER_SAMPLED(r);
}

/* The obj index of the world's object (kind, index): a search, as obj is
 * sorted nearest first each frame (render_setup); for the adaptive
 * sampler's one ray per pixel, whose world_hit costs far more. */
static inline uint16_t render_obj_of(const vis_t *r, geom_kind_t kind, uint16_t index)
{
    uint16_t i = 0;
    while (i + 1 < r->count && (r->obj[i].geom != kind || r->obj[i].index != index))
        i++;
    return i;
}

#endif
