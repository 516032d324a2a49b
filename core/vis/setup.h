/* setup: what the per-frame set-up of the visibility pass shares between
 * vis/setup.c and each kind's set-up (vis/setup_KIND.c): the exact
 * coefficient arithmetic, camera space, screen bounds and depth ranges
 * (private to vis/). */
#ifndef FXRT_VIS_SETUP_H
#define FXRT_VIS_SETUP_H

#include "vis/render_int.h"

/* ---- set-up arithmetic ----------------------------------------------------
 * Coefficients are first formed exactly (Q16.16: as 128-bit integers in
 * Q80.48, so products of a Q16.16 and a Q32.32 value lose nothing), then
 * each form is scaled by a power of two so that its value over the whole
 * screen stays below 2^target, and rounded once to int64. */
#if FXRT_NUMBER == FXRT_Q16
typedef fx128_t rc_t;
/* v 2^s for a 64-bit v and 0 < s < 64, by word shifts (no fx128_shl or
 * fx128_mul call: on the M0 the set-up forms many of these). */
static inline rc_t rc_shl64(int64_t v, int s)
{
    rc_t r;
    r.lo = (uint64_t)v << s;
    r.hi = v >> (64 - s); /* arithmetic: the sign fills the top */
    return r;
}
/* Out of line (many callers), a copy in each set-up file that uses it:
 * static, so that gcc returns the 16-byte value without a copy (the M0
 * copies one with memcpy). */
__attribute__((noinline, unused)) static rc_t rc_from_num(num_t a) { return rc_shl64(a, 32); }
static inline rc_t rc_from_wide(numw_t w) { return rc_shl64(w, 16); }
__attribute__((noinline, unused)) static rc_t rc_mul(num_t a, num_t b) { return rc_shl64(fx_smul32(a, b), 16); }
static inline rc_t rc_mul_wide(num_t a, numw_t w) { return fx128_mul(a, w); }
static inline rc_t rc_add(rc_t a, rc_t b) { return fx128_add(a, b); }
static inline rc_t rc_neg(rc_t a) { return fx128_neg(a); }
static inline rc_t rc_zero(void) { return fx128_from64(0); }
static inline bool rc_is_neg(rc_t a) { return a.hi < 0; }
#else
typedef num_t rc_t;
static inline rc_t rc_from_num(num_t a) { return a; }
static inline rc_t rc_from_wide(numw_t w) { return w; }
static inline rc_t rc_mul(num_t a, num_t b) { return a * b; }
static inline rc_t rc_mul_wide(num_t a, numw_t w) { return a * w; }
static inline rc_t rc_add(rc_t a, rc_t b) { return a + b; }
static inline rc_t rc_neg(rc_t a) { return -a; }
static inline rc_t rc_zero(void) { return NUM_ZERO; }
static inline bool rc_is_neg(rc_t a) { return a < 0; }
#endif
static inline rc_t rc_sub(rc_t a, rc_t b) { return rc_add(a, rc_neg(b)); }

/* Forms under construction: exact coefficients. */
typedef struct {
    rc_t c, x, y;
} rclin_t;
typedef struct {
    rc_t c, x, y, xx, xy, yy;
} rcquad_t;

#if FXRT_NUMBER == FXRT_Q16
static inline int render_bits32(uint32_t v) { return v ? 32 - __builtin_clz(v) : 0; }

/* Bits of |coef| * mult (0 for a zero coefficient). */
static inline int rk_bits(const rc_t *coef, uint32_t mult)
{
    int b = fx128_bits(*coef);
    return b ? b + render_bits32(mult) : 0;
}
static inline int rk_max(int a, int b) { return a > b ? a : b; }
/* Smallest right shift that keeps a sum of at most 6 terms, each below
 * 2^need, below 2^target. */
static inline int rk_shift(int need, int target)
{
    need += 3;
    return need > target ? need - target : 0;
}
static inline render_k_t rk_round(const rc_t *c, int k) { return fx128_shr_round(*c, k); }
#else
static inline render_k_t rk_round(const rc_t *c, int k) { (void)k; return *c; }
#endif

/* The coefficients by pointer, the result into *r: on the M0 a 16-byte
 * value passed or returned by value is copied with memcpy. */
void rlin_scaled(render_lin_t *r, const rclin_t *f, int k);


/* Screen extents of ix and iy, for the scale bounds. */
typedef struct {
    uint32_t xm, ym;
} rext_t;

/* Smallest right shift that keeps the form's value over the screen below
 * 2^target (Q16.16; 0 in float and double). */
#if FXRT_NUMBER == FXRT_Q16
/* Bits of the largest of |c|, |x| xm and |y| ym: the linear terms. */
static inline int rk_lin_bits(const rc_t *c, const rc_t *x, const rc_t *y, rext_t ext)
{
    return rk_max(rk_bits(c, 1), rk_max(rk_bits(x, ext.xm), rk_bits(y, ext.ym)));
}
#endif

int rlin_need(const rclin_t *f, rext_t ext, int target);

/* Linear forms get 61 bits: values, steps and sums stay inside int64. */
#define RENDER_LIN_BITS 61
/* The sphere's pieces get 62 bits; b^2 - a c is formed in 128 bits. */
#define RENDER_SPHERE_BITS 62

static inline void rlin_make(render_lin_t *r, const rclin_t *f, rext_t ext)
{
    rlin_scaled(r, f, rlin_need(f, ext, RENDER_LIN_BITS));
}


/* ---- camera space and bounds (vis/setup_forms.c) -------------------------- */

/* World to camera space: v - *from (v itself where from is NULL) turned
 * by the camera's axes, one body for points and directions (its nine
 * products take 1.2 KB of text on the M0). */
vec3_t render_turn(const cam_t *cam, vec3_t v, const vec3_t *from);
static inline vec3_t render_to_cam(const cam_t *cam, vec3_t p) { return render_turn(cam, p, &cam->e); }
static inline vec3_t render_dir_to_cam(const cam_t *cam, vec3_t d) { return render_turn(cam, d, NULL); }
/* N = n.(A - o) and D = n.r for camera-space normal n and point a. */
void render_flat_nd(const cam_t *cam, rext_t ext, vec3_t n, vec3_t a, render_flat_t *f);
/* Perspective: N's sign from the kernels' n.(A - e); false (N = 0) when the
 * plane holds the eye. */
bool render_flat_eye(const cam_t *cam, vec3_t a, vec3_t n, render_flat_t *f);
/* Edge form r.((P - o) x (Q - o)), in canonical order (watertight). */
void render_edge(render_lin_t *e, const cam_t *cam, rext_t ext, vec3_t p, vec3_t q);

/* A camera-space point's projection, in pixel offsets. */
typedef struct {
    num_t ix, iy;
} rproj_t;

/* Indices 0..7: a point set taken whole. */
extern const uint8_t render_idx8[8];
/* The depth range of an object inside camera-space points p[idx[0..n-1]]. */
void render_set_zrange(const cam_t *cam, const vec3_t *p, const uint8_t *idx, int n, render_obj_t *o);
/* Bounds of camera-space points p[idx[0..n-1]] (at most 8); proj and
 * *have: the points' projections so far, shared by calls on one set. */
void render_idx_bounds(const cam_t *cam, const vec3_t *p, const uint8_t *idx, int n, rproj_t *proj, uint8_t *have,
                       render_obj_t *o);

static inline void render_set_full(const cam_t *cam, render_obj_t *o)
{
    o->x0 = 0;
    o->x1 = (int16_t)(cam->width - 1);
    o->r0 = 0;
    o->r1 = (int16_t)(cam->height - 1);
}

static inline void render_set_empty(render_obj_t *o)
{
    o->x0 = 1;
    o->x1 = 0;
    o->r0 = 1;
    o->r1 = 0;
}

/* Copy bounds to a box face. */
static inline void render_face_bounds_from(render_face_t *f, const render_obj_t *o)
{
    f->x0 = o->x0;
    f->x1 = o->x1;
    f->r0 = o->r0;
    f->r1 = o->r1;
}

/* Bounds and depth range of camera-space points p[0..n-1] (n <= 8). */
static inline void render_points_bounds(const cam_t *cam, const vec3_t *p, int n, render_obj_t *o)
{
    render_set_zrange(cam, p, render_idx8, n, o);
    rproj_t proj[8];
    uint8_t have = 0;
    render_idx_bounds(cam, p, render_idx8, n, proj, &have, o);
}

/* An object of the RAYS form (vis/rays.c): its bounds and depth range are
 * those of the world box lo..hi around it. */
static inline void render_setup_rays(vis_t *r, vec3_t lo, vec3_t hi, render_obj_t *o)
{
    o->kind = RENDER_RAYS;
    o->nflat = 0;
    vec3_t v[8];
    for (int c = 0; c < 8; c++)
        v[c] = render_to_cam(r->cam, vec3_make((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z));
    render_points_bounds(r->cam, v, 8, o);
}

/* Each kind's set-up (vis/setup_KIND.c): object o's forms and bounds from
 * its world record; a kind of the rays form has none (render_setup_rays,
 * from its box: vis/setup.c). */
#define RENDER_SETUP_KIND(K, k, ks, cap, solid, bounded, form, ...) RENDER_SETUP_DECL_##form(k)
#define RENDER_SETUP_DECL_FLAT(k) void render_setup_##k(vis_t *r, rext_t ext, const geom_##k##_t *g, render_obj_t *o);
#define RENDER_SETUP_DECL_ROUND RENDER_SETUP_DECL_FLAT
#define RENDER_SETUP_DECL_FACES RENDER_SETUP_DECL_FLAT
#define RENDER_SETUP_DECL_RAYS(k)
FXRT_KINDS(RENDER_SETUP_KIND)
#undef RENDER_SETUP_KIND

/* vis/rays.c: a model's footprint on the screen (r->model_cut), after its
 * bounds. */
FXRT_IF_MODEL(void render_setup_cut(vis_t *r, const render_obj_t *o);)
/* vis/cull.c: the back faces of closed meshes, per frame (RENDER_MESH). */
void render_cull_meshes(vis_t *r);
/* vis/order.c: nearest first (unless FXRT_NO_ORDER); the row blocks'
 * masks (RENDER_ROW_MASKS). */
void render_order(vis_t *r);
void render_row_masks(vis_t *r);

#endif
