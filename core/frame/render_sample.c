/* render_sample: supersampling, samples N > 1.
 *
 * Each pixel's N x N rays go through the centres of the N x N equal cells
 * of the pixel square. Those are exactly the pixel centres of a camera N
 * times as wide and high (cam_fine), so the per-frame set-up is done once,
 * for that camera, and every output row is N rows of it: the visibility
 * pass (stepped forms, spans) over each fine row, then the sampling pass
 * below, which adds each fine pixel's colour, clamped to [0, 1], into its
 * output pixel's sum. The output pixel is the mean, rounded half up to 8
 * bits (as color_to_rgb8). Flat colours and the background are summed
 * unrounded; a lit sample is shaded along its fine camera ray.
 *
 * Cheap case: where the N fine columns of an output pixel have one flat
 * owner (or none), the fine row adds N times one colour, with no clamp
 * (a flat colour and the background are within [0, 1] already).
 *
 * Adaptive (samples N adaptive): the keys of one sample per pixel are cast
 * first, row by row (a ring of three output rows, computed once each when
 * rows come in order): the pixel-centre ray, its nearest object
 * (world_hit) and the lights that reach it. A pixel whose 3x3
 * neighbourhood (clipped at the border) has one key keeps that one-sample
 * colour; the others are summed from their N x N rays as above. When no
 * pixel of a row needs them, the row's fine rows are not rendered at all.
 */
#include "frame/render.h"
#include "vis/render_int.h"

#if FXRT_MAX_SAMPLES > 1

/* Adaptive sampling (FXRT_ADAPTIVE) and run mode (RENDER_RUNS), below:
 * their state's reset at set-up; stubs when compiled out. */
static void render_adaptive_reset(render_sample_t *s);
static void render_runs_reset(render_sample_t *s);

/* One sample of colour c, clamped, in the sampling pass's sum units. */
static void render_sum_one(color_sum_t one[3], color_t c)
{
    one[0] = one[1] = one[2] = 0;
    color_sum_add(&one[0], c.r, 1);
    color_sum_add(&one[1], c.g, 1);
    color_sum_add(&one[2], c.b, 1);
}

bool render_sample_setup(render_t *r, const world_t *w, const cam_t **cam)
{
    render_sample_t *s = &r->sample;
    s->samples = (uint8_t)world_samples(w);
    s->adaptive = world_adaptive(w);
    s->out_cam = *cam;
    if (s->samples > 1) {
        if ((*cam)->width > FXRT_RENDER_MAX_WIDTH / s->samples) {
            r->error = "samples x width wider than FXRT_RENDER_MAX_WIDTH";
            return false;
        }
        if (cam_fine(*cam, s->samples, &s->fine) != CAM_OK) {
            r->error = "samples x height beyond FXRT_MAX_DIM, or samples x height x cot(fov/2) beyond 32767";
            return false;
        }
        *cam = &s->fine;
        render_sum_one(s->bg_one, w->background);
        render_adaptive_reset(s);
        render_runs_reset(s);
    }
    return true;
}

void render_sample_objects(render_t *r, const world_t *w)
{
    render_sample_t *s = &r->sample;
    if (s->samples > 1)
        for (uint16_t i = 0; i < r->vis.count; i++)
            render_sum_one(s->one[i], world_common(w, (geom_kind_t)r->vis.obj[i].geom, r->vis.obj[i].index)->color);
}

/* The colour of fine column X's sample (owner oi) on fine row y (counted
 * from the bottom), unclamped. */
static color_t render_sample_color(render_t *r, uint16_t oi, int32_t X, int32_t y)
{
    if (oi == RENDER_VIS_NONE)
        return r->vis.world->background;
    const render_obj_t *o = &r->vis.obj[oi];
    if (FXRT_MAX_LIGHTS > 0 && !o->flat) {
        ray_t ray;
        cam_ray_raw(r->vis.cam, X, y, &ray);
        return render_shade_object(r, oi, &ray, NULL);
    }
    return world_common(r->vis.world, (geom_kind_t)o->geom, o->index)->color;
}

static inline bool render_sample_flat(const render_t *r, uint16_t oi)
{
    return oi == RENDER_VIS_NONE || r->vis.obj[oi].flat;
}

/* One sample of a flat owner or the background, clamped, in sum units. */
static inline const color_sum_t *render_sample_one(const render_t *r, uint16_t oi)
{
    return oi == RENDER_VIS_NONE ? r->sample.bg_one : r->sample.one[oi];
}

/* sole_owner[x] while an output pixel's samples so far all had one flat owner
 * (or the background): that owner; RENDER_OWNER_MIXED once they did not (its
 * sum is then in acc). A pixel that stays uniform is that owner's colour,
 * exactly what the mean of N x N equal samples rounds to, with no sums. */
#define RENDER_OWNER_MIXED 0xFFFEu

/* Fine row j of output row `row`: visibility, then each output pixel that
 * wants its samples (need == NULL: all) checks or adds them. */
static void render_sample_fine(render_t *r, int32_t row, int32_t j, bool reference, const bool *need)
{
    int32_t n = r->sample.samples, w = r->sample.out_cam->width, frow = row * n + j, y = r->vis.cam->height - 1 - frow;
    if (reference)
        render_row_reference_vis(&r->vis, frow, r->sample.fine_rgb);
    else
        render_row_vis(&r->vis, frow, r->sample.fine_rgb);
    for (int32_t x = 0, X0 = 0; x < w; x++, X0 += n) {
        if (need && !need[x])
            continue;
        const uint16_t *v = &r->vis.painted[X0];
        color_sum_t *a = &r->sample.acc[3 * x];
        uint16_t u = j == 0 ? v[0] : r->sample.sole_owner[x]; /* row 0 starts the pixel afresh */
        if (u != RENDER_OWNER_MIXED) {
            bool same = true;
            if (j == 0) {
                r->sample.sole_owner[x] = u;
                same = render_sample_flat(r, u); /* sole_owner holds flat owners only */
            }
            for (int32_t i = 0; i < n && same; i++)
                same = v[i] == u;
            if (same)
                continue;
            /* The first other sample: the rows so far into the sum (none
             * on row 0, where u may be a lit owner). */
            if (j == 0) {
                a[0] = a[1] = a[2] = 0;
            } else {
                const color_sum_t *c = render_sample_one(r, u), nj = (color_sum_t)j;
                a[0] = c[0] * (color_sum_t)n * nj;
                a[1] = c[1] * (color_sum_t)n * nj;
                a[2] = c[2] * (color_sum_t)n * nj;
            }
            r->sample.sole_owner[x] = RENDER_OWNER_MIXED;
        }
        uint16_t oi = v[0];
        bool one = true;
        for (int32_t i = 1; i < n && one; i++)
            one = v[i] == oi;
        if (one && render_sample_flat(r, oi)) {
            const color_sum_t *c = render_sample_one(r, oi);
            a[0] += c[0] * (color_sum_t)n;
            a[1] += c[1] * (color_sum_t)n;
            a[2] += c[2] * (color_sum_t)n;
            continue;
        }
        for (int32_t i = 0; i < n; i++) {
            color_t c = render_sample_color(r, v[i], X0 + i, y);
            color_sum_add(&a[0], c.r, 1);
            color_sum_add(&a[1], c.g, 1);
            color_sum_add(&a[2], c.b, 1);
        }
    }
}

static void render_sample_put(uint8_t *rgb, int32_t x, uint8_t cr, uint8_t cg, uint8_t cb)
{
    rgb8_t p = {cr, cg, cb};
    color_put_pixel(rgb, x, p);
}

#if FXRT_ADAPTIVE
static void render_adaptive_reset(render_sample_t *s)
{
    s->coarse_row[0] = s->coarse_row[1] = s->coarse_row[2] = -1;
}

/* One sample per pixel of output row `row` into ring slot row % 3: the
 * pixel-centre ray's key and colour. */
static void render_adaptive_row(render_t *r, int32_t row)
{
    int32_t s = row % 3;
    if (r->sample.coarse_row[s] == row)
        return;
    const cam_t *cam = r->sample.out_cam;
    const world_t *w = r->vis.world;
    int32_t y = cam->height - 1 - row;
    for (int32_t x = 0; x < cam->width; x++) {
        ray_t ray;
        hit_t hit;
        cam_ray_raw(cam, x, y, &ray);
        ray_t unit = ray;
        cam_ray_unit(cam, &unit);
        uint32_t key = RENDER_KEY_MISS;
        rgb8_t c = w->background_rgb;
        if (world_hit(w, &unit, &hit)) {
            uint8_t mask = 0;
            if (FXRT_MAX_LIGHTS > 0) {
                uint16_t oi = render_obj_of(&r->vis, hit.kind, hit.index);
                bool lit = geom_lit(hit.obj);
                c = color_to_rgb8(
                    shade_object_k(w, hit.kind, hit.index, &ray, cam, lit ? RENDER_SHADE_K(r, oi) : NULL, &mask));
            } else {
                c = hit.obj->rgb;
            }
            key = render_key(hit.obj->id, mask);
        }
        r->sample.coarse_keys[s][x] = key;
        r->sample.coarse_rgb[s][x] = c;
    }
    r->sample.coarse_row[s] = row;
}

/* Which pixels of output row `row` take N x N rays; false when none. */
static bool render_adaptive_need(render_t *r, int32_t row)
{
    const cam_t *cam = r->sample.out_cam;
    int32_t h = cam->height, w = cam->width;
    int32_t r0 = row > 0 ? row - 1 : row, r1 = row < h - 1 ? row + 1 : row;
    for (int32_t q = r0; q <= r1; q++)
        render_adaptive_row(r, q);
    bool any = false;
    const uint32_t *mid = r->sample.coarse_keys[row % 3];
    for (int32_t x = 0; x < w; x++) {
        uint32_t k = mid[x];
        int32_t x0 = x > 0 ? x - 1 : x, x1 = x < w - 1 ? x + 1 : x;
        bool differ = false;
        for (int32_t q = r0; q <= r1 && !differ; q++)
            for (int32_t xx = x0; xx <= x1; xx++)
                differ |= r->sample.coarse_keys[q % 3][xx] != k;
        r->sample.need[x] = differ;
        any |= differ;
    }
    return any;
}
#else
static void render_adaptive_reset(render_sample_t *s)
{
    (void)s;
}
#endif

#if RENDER_RUNS
static void render_runs_reset(render_sample_t *s)
{
    s->run_cap = FXRT_SAMPLE_RUNS;
    s->run_rows = 0;
}

/* Run mode (the fast Q16.16 loop, when every object on the N fine rows of
 * output row `row` is flat and alone on its row): each fine row as runs
 * of one owner (render_row_runs), no per-column owners. Walking the N
 * rows' runs together splits the fine columns into intervals on which
 * every fine row has one owner. An output pixel inside an interval whose
 * N owners are one object (or the background) is that colour, filled with
 * word stores; every other pixel sums m times each row's colour for each
 * interval of m columns it meets. The sums are those of the per-sample
 * pass, so the image is the same. Returns false (nothing written) when a
 * fine row cannot be put as runs. Lit objects take the per-sample pass:
 * their N x N shadings cost far more than the visibility, and that pass
 * keeps the shading's stack off this one's. */
__attribute__((noinline)) static bool render_sample_runs(render_t *r, int32_t row, uint8_t *rgb, const bool *need)
{
    int32_t n = r->sample.samples, W = r->vis.cam->width;
    int used = 0, cap = r->sample.run_cap < FXRT_SAMPLE_RUNS ? r->sample.run_cap : FXRT_SAMPLE_RUNS;
    r->sample.run_at[0] = 0;
    for (int32_t j = 0; j < n; j++) {
        int k = render_row_runs(&r->vis, row * n + j, r->sample.runs + used, cap - used);
        if (k < 0)
            return false;
        used += k;
        r->sample.run_at[j + 1] = (uint16_t)used;
    }
    /* Per fine row j: the run at or after the current column (at), the
     * owner from the current column (u) and the column where that changes
     * (nb); f sums one sample of each row's owner. Every row starts in a
     * gap that ends at column 0. */
    uint16_t at[FXRT_MAX_SAMPLES], u[FXRT_MAX_SAMPLES];
    int32_t nb[FXRT_MAX_SAMPLES];
    color_sum_t f[3] = {0, 0, 0};
    for (int32_t j = 0; j < n; j++) {
        at[j] = r->sample.run_at[j];
        u[j] = RENDER_VIS_NONE;
        nb[j] = 0;
        f[0] += r->sample.bg_one[0];
        f[1] += r->sample.bg_one[1];
        f[2] += r->sample.bg_one[2];
    }
    uint32_t n2 = (uint32_t)(n * n);
    for (int32_t a = 0, b; a < W; a = b) {
        /* The rows that change at a: leave a run (to the gap or the next
         * run, which may start at a) or enter one. */
        for (int32_t j = 0; j < n; j++) {
            if (nb[j] != a)
                continue;
            const color_sum_t *c = render_sample_one(r, u[j]);
            f[0] -= c[0];
            f[1] -= c[1];
            f[2] -= c[2];
            if (u[j] != RENDER_VIS_NONE)
                at[j]++;
            const render_run_t *q = &r->sample.runs[at[j]];
            bool more = at[j] < r->sample.run_at[j + 1];
            if (more && q->a == a) {
                u[j] = q->oi;
                nb[j] = q->b + 1;
            } else {
                u[j] = RENDER_VIS_NONE;
                nb[j] = more ? q->a : W;
            }
            c = render_sample_one(r, u[j]);
            f[0] += c[0];
            f[1] += c[1];
            f[2] += c[2];
        }
        /* The interval a..b-1, up to the first change in any row; whether
         * its rows have one owner matters only when it holds a whole pixel. */
        b = nb[0];
        for (int32_t j = 1; j < n; j++)
            b = nb[j] < b ? nb[j] : b;
        bool one = false;
        if (b - a >= n) {
            one = true;
            for (int32_t j = 1; j < n && one; j++)
                one = u[j] == u[0];
        }
        for (int32_t x = a / n, X0 = x * n; X0 < b; x++, X0 += n) {
            int32_t c0 = a > X0 ? a : X0, c1 = b < X0 + n ? b : X0 + n;
            if (need && !need[x])
                continue;
            if (one && c0 == X0 && c1 == X0 + n) {
                /* Whole pixels of one owner: x .. xe at once. */
                int32_t xe = need ? x : b / n - 1;
                render_fill_rgb(rgb, x, xe, u[0] == RENDER_VIS_NONE ? r->vis.world->background_rgb : r->vis.obj[u[0]].rgb);
                x = xe;
                X0 = xe * n;
                continue;
            }
            color_sum_t *s = &r->sample.acc[3 * x], m = (color_sum_t)(c1 - c0);
            if (c0 == X0)
                s[0] = s[1] = s[2] = 0;
            s[0] += f[0] * m;
            s[1] += f[1] * m;
            s[2] += f[2] * m;
            if (c1 == X0 + n)
                render_sample_put(rgb, x, color_sum_out(s[0], n2), color_sum_out(s[1], n2), color_sum_out(s[2], n2));
        }
    }
    r->sample.run_rows++;
    return true;
}
#else
static void render_runs_reset(render_sample_t *s)
{
    (void)s;
}
static bool render_sample_runs(render_t *r, int32_t row, uint8_t *rgb, const bool *need)
{
    (void)r, (void)row, (void)rgb, (void)need;
    return false;
}
#endif

void render_sample_row(render_t *r, int32_t row, uint8_t *rgb, bool reference)
{
    int32_t n = r->sample.samples, w = r->sample.out_cam->width;
    const bool *need = NULL;
#if FXRT_ADAPTIVE
    if (r->sample.adaptive) {
        bool any = render_adaptive_need(r, row);
        const rgb8_t *one = r->sample.coarse_rgb[row % 3];
        for (int32_t x = 0; x < w; x++)
            render_sample_put(rgb, x, one[x].r, one[x].g, one[x].b);
        if (!any)
            return;
        need = r->sample.need;
    }
#endif
    if (!reference && render_sample_runs(r, row, rgb, need))
        return;
    for (int32_t j = 0; j < n; j++)
        render_sample_fine(r, row, j, reference, need);
    uint32_t n2 = (uint32_t)(n * n);
    for (int32_t x = 0; x < w; x++) {
        if (need && !need[x])
            continue;
        uint16_t u = r->sample.sole_owner[x];
        if (u != RENDER_OWNER_MIXED) {
            rgb8_t c = u == RENDER_VIS_NONE ? r->vis.world->background_rgb : r->vis.obj[u].rgb;
            render_sample_put(rgb, x, c.r, c.g, c.b);
            continue;
        }
        const color_sum_t *a = &r->sample.acc[3 * x];
        render_sample_put(rgb, x, color_sum_out(a[0], n2), color_sum_out(a[1], n2), color_sum_out(a[2], n2));
    }
}

#endif
