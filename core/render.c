/* render: per-frame set-up of camera-space coverage forms, and the two
 * scanline loops (fast and reference). See render.h for the method. */
#include <stddef.h>

#include "render.h"


#if FXRT_NUMBER == FXRT_Q16
static render_depth_t render_depth_make(uint64_t n_hi, uint64_t n_lo, uint64_t d, int e);
#endif

/* Set-up helpers that a build without some primitive kind does not call. */
#define RENDER_MAYBE_UNUSED __attribute__((unused))

/* Does the fast loop step forms along the row? Q16.16 always (exactly),
 * float and double with FXRT_FLOAT_STEP; never with FXRT_NO_STEP. */
#define RENDER_STEPPED (!FXRT_NO_STEP && (FXRT_NUMBER == FXRT_Q16 || FXRT_FLOAT_STEP))

/* RGB565 of an 8-bit colour: each channel's top bits. */
RENDER_MAYBE_UNUSED static uint16_t render_565(rgb8_t c)
{
    return (uint16_t)(((c.r >> 3) << 11) | ((c.g >> 2) << 5) | (c.b >> 3));
}

/* Face i of a flat object (a box's faces carry a fourth edge). */
static inline render_flat_t *render_face(const render_obj_t *o, int i)
{
    return o->kind == RENDER_FLAT ? o->u.flat : &o->u.face[i].f;
}

/* Edge form k of a flat piece; the fourth is a box face's. */
static inline const render_lin_t *render_edge_k(const render_flat_t *f, int k)
{
    return k < 3 ? &f->e[k] : &((const render_face_t *)(const void *)f)->e4;
}

/* ---- set-up arithmetic ----------------------------------------------------
 * Coefficients are first formed exactly (Q16.16: as 128-bit integers in
 * Q80.48, so products of a Q16.16 and a Q32.32 value lose nothing), then
 * each form is scaled by a power of two so that its value over the whole
 * screen stays below 2^target, and rounded once to int64. */
#if FXRT_NUMBER == FXRT_Q16
typedef fx128_t rc_t;
RENDER_MAYBE_UNUSED static rc_t rc_n(num_t a) { return fx128_shl(fx128_from64(a), 32); }
RENDER_MAYBE_UNUSED static rc_t rc_w(numw_t w) { return fx128_shl(fx128_from64(w), 16); }
RENDER_MAYBE_UNUSED static rc_t rc_nn(num_t a, num_t b) { return fx128_shl(fx128_mul(a, b), 16); }
RENDER_MAYBE_UNUSED static rc_t rc_nw(num_t a, numw_t w) { return fx128_mul(a, w); }
RENDER_MAYBE_UNUSED static rc_t rc_add(rc_t a, rc_t b) { return fx128_add(a, b); }
RENDER_MAYBE_UNUSED static rc_t rc_neg(rc_t a) { return fx128_neg(a); }
RENDER_MAYBE_UNUSED static rc_t rc_zero(void) { return fx128_from64(0); }
RENDER_MAYBE_UNUSED static bool rc_is_neg(rc_t a) { return a.hi < 0; }
#else
typedef num_t rc_t;
RENDER_MAYBE_UNUSED static rc_t rc_n(num_t a) { return a; }
RENDER_MAYBE_UNUSED static rc_t rc_w(numw_t w) { return w; }
RENDER_MAYBE_UNUSED static rc_t rc_nn(num_t a, num_t b) { return a * b; }
RENDER_MAYBE_UNUSED static rc_t rc_nw(num_t a, numw_t w) { return a * w; }
RENDER_MAYBE_UNUSED static rc_t rc_add(rc_t a, rc_t b) { return a + b; }
RENDER_MAYBE_UNUSED static rc_t rc_neg(rc_t a) { return -a; }
RENDER_MAYBE_UNUSED static rc_t rc_zero(void) { return NUM_ZERO; }
RENDER_MAYBE_UNUSED static bool rc_is_neg(rc_t a) { return a < 0; }
#endif
RENDER_MAYBE_UNUSED static rc_t rc_sub(rc_t a, rc_t b) { return rc_add(a, rc_neg(b)); }

/* Forms under construction: exact coefficients. */
typedef struct {
    rc_t c, x, y;
} rclin_t;
typedef struct {
    rc_t c, x, y, xx, xy, yy;
} rcquad_t;

#if FXRT_NUMBER == FXRT_Q16
static int render_bits32(uint32_t v) { return v ? 32 - __builtin_clz(v) : 0; }

/* Smallest right shift that keeps sum |coef[i]| * mult[i] below 2^target. */
static int rk_shift(const rc_t *coef, const uint32_t *mult, int n, int target)
{
    int need = 0;
    for (int i = 0; i < n; i++) {
        int b = fx128_bits(coef[i]);
        if (b)
            b += render_bits32(mult[i]);
        if (b > need)
            need = b;
    }
    need += 3; /* at most 6 terms */
    return need > target ? need - target : 0;
}
static render_k_t rk_of(rc_t c, int k) { return fx128_shr_round(c, k); }
#define RK_SHIFT(coefs, mults, n, target) rk_shift(coefs, mults, n, target)
#else
static render_k_t rk_of(rc_t c, int k) { (void)k; return c; }
#define RK_SHIFT(coefs, mults, n, target) 0
#endif

static render_lin_t rlin_scaled(rclin_t f, int k)
{
    render_lin_t r = {rk_of(f.c, k), rk_of(f.x, k), rk_of(f.y, k)};
    return r;
}

RENDER_MAYBE_UNUSED static render_quad_t rquad_scaled(rcquad_t f, int k)
{
    render_quad_t r = {rk_of(f.c, k), rk_of(f.x, k), rk_of(f.y, k), rk_of(f.xx, k), rk_of(f.xy, k), rk_of(f.yy, k)};
    return r;
}

/* Screen extents of ix and iy, for the scale bounds. */
typedef struct {
    uint32_t xm, ym;
} rext_t;

static int rlin_need(const rclin_t *f, rext_t ext, int target)
{
    rc_t c[3] = {f->c, f->x, f->y};
    uint32_t m[3] = {1, ext.xm, ext.ym};
    (void)c;
    (void)m;
    (void)target;
    return RK_SHIFT(c, m, 3, target);
}

#if FXRT_NUMBER == FXRT_Q16
RENDER_MAYBE_UNUSED static int rquad_need(const rcquad_t *f, rext_t ext, int target)
{
    rc_t c[6] = {f->c, f->x, f->y, f->xx, f->xy, f->yy};
    uint32_t m[6] = {1, ext.xm, ext.ym, ext.xm * ext.xm, ext.xm * ext.ym, ext.ym * ext.ym};
    (void)c;
    (void)m;
    (void)target;
    return RK_SHIFT(c, m, 6, target);
}
#endif

/* Linear forms get 61 bits: values, steps and sums stay inside int64. */
#define RENDER_LIN_BITS 61
/* The sphere's pieces get 62 bits; b^2 - a c is formed in 128 bits. */
#define RENDER_SPHERE_BITS 62

RENDER_MAYBE_UNUSED static render_lin_t rlin_make(rclin_t f, rext_t ext)
{
    return rlin_scaled(f, rlin_need(&f, ext, RENDER_LIN_BITS));
}

/* ---- evaluation ----------------------------------------------------------
 * Q16.16: in uint64, so that no intermediate can be signed overflow; every
 * final value is known to fit int64 (the scales above guarantee it). */
#if FXRT_NUMBER == FXRT_Q16
static inline render_k_t rlin_at(const render_lin_t *f, int32_t ix, int32_t iy)
{
    return (render_k_t)((uint64_t)f->c + (uint64_t)f->x * (uint64_t)(int64_t)ix + (uint64_t)f->y * (uint64_t)(int64_t)iy);
}
static inline render_k_t rquad_at(const render_quad_t *f, int32_t ix, int32_t iy)
{
    uint64_t x = (uint64_t)(int64_t)ix, y = (uint64_t)(int64_t)iy;
    return (render_k_t)((uint64_t)f->c + (uint64_t)f->x * x + (uint64_t)f->y * y + (uint64_t)f->xx * x * x +
                  (uint64_t)f->xy * x * y + (uint64_t)f->yy * y * y);
}
#else
static inline render_k_t rlin_at(const render_lin_t *f, int32_t ix, int32_t iy)
{
    return f->c + f->x * (num_t)ix + f->y * (num_t)iy;
}
static inline render_k_t rquad_at(const render_quad_t *f, int32_t ix, int32_t iy)
{
    num_t x = (num_t)ix, y = (num_t)iy;
    return f->c + f->x * x + f->y * y + f->xx * x * x + f->xy * x * y + f->yy * y * y;
}
#endif

/* The sphere's c and disc: 128-bit in Q16.16, num otherwise. */
#if FXRT_NUMBER == FXRT_Q16
typedef fx128_t rsw_t;
static inline bool rsw_neg(rsw_t v) { return v.hi < 0; }
#else
typedef render_k_t rsw_t;
static inline bool rsw_neg(rsw_t v) { return v < 0; }
#endif

static inline bool render_sphere_vals(render_k_t b, rsw_t c, rsw_t disc)
{
    return rsw_neg(c) || (b > 0 && !rsw_neg(disc));
}

/* c = k + px^2 + py^2 and disc = b^2 - a c at one pixel, exactly (Q16.16:
 * a is 1 in orthographic views and c is the constant k in perspective, so
 * a c is a single 64 x 64 product or none). */
static void render_sphere_cd(const render_obj_t *o, int32_t ix, int32_t iy, rsw_t *c_out, rsw_t *disc_out);

static inline bool render_flat_vals(render_k_t n, render_k_t d, const render_k_t *e, int edges)
{
    if (!((n > 0 && d > 0) || (n < 0 && d < 0)))
        return false;
    bool pos = false, neg = false;
    for (int i = 0; i < edges; i++) {
        pos |= e[i] > 0;
        neg |= e[i] < 0;
    }
    return !(pos && neg);
}

static bool render_flat_at(const render_flat_t *f, int32_t ix, int32_t iy)
{
    render_k_t e[4];
    for (int i = 0; i < f->edges; i++)
        e[i] = rlin_at(render_edge_k(f, i), ix, iy);
    return render_flat_vals(rlin_at(&f->n, ix, iy), rlin_at(&f->d, ix, iy), e, f->edges);
}

static void render_sphere_cd(const render_obj_t *o, int32_t ix, int32_t iy, rsw_t *c_out, rsw_t *disc_out)
{
    render_k_t a = rquad_at(o->u.sphere->a, ix, iy);
    render_k_t px = rlin_at(&o->u.sphere->px, ix, iy), py = rlin_at(&o->u.sphere->py, ix, iy),
         pz = rlin_at(&o->u.sphere->pz, ix, iy);
    bool ortho = o->u.sphere->ortho;
#if FXRT_NUMBER == FXRT_Q16
    fx128_t sq = fx128_add(fx128_add(fx128_mul(px, px), fx128_mul(py, py)), fx128_mul(pz, pz));
    /* Orthographic: a = 1 exactly and r2 may use all 128 bits. */
    fx128_t r2a = ortho ? o->u.sphere->r2 : fx128_mul(a, fx128_shr_round(o->u.sphere->r2, 0));
    *disc_out = fx128_sub(r2a, sq);
    *c_out = ortho ? fx128_add(o->u.sphere->k, sq) : o->u.sphere->k;
#else
    render_k_t sq = px * px + py * py + pz * pz;
    *disc_out = o->u.sphere->r2 * a - sq;
    *c_out = ortho ? o->u.sphere->k + sq : o->u.sphere->k;
#endif
}

/* Does object o cover the pixel? Every form evaluated from scratch. */
static bool render_covers(const render_obj_t *o, int32_t ix, int32_t iy)
{
    switch (o->kind) {
    case RENDER_ALL:
        return true;
    case RENDER_SPHERE: {
        render_k_t b = rlin_at(&o->u.sphere->b, ix, iy);
        rsw_t c, disc;
        render_sphere_cd(o, ix, iy, &c, &disc);
        return render_sphere_vals(b, c, disc);
    }
    case RENDER_FLAT:
    case RENDER_BOX:
        for (int i = 0; i < o->nflat; i++)
            if (render_flat_at(render_face(o, i), ix, iy))
                return true;
        return false;
    }
    return false;
}

/* ---- set-up of each object ------------------------------------------- */

RENDER_MAYBE_UNUSED static vec3_t render_to_cam(const cam_t *cam, vec3_t p)
{
    vec3_t q = vec3_sub(p, cam->e);
    return vec3_make(vec3_dot(q, cam->u), vec3_dot(q, cam->v), vec3_dot(q, cam->w));
}

RENDER_MAYBE_UNUSED static vec3_t render_dir_to_cam(const cam_t *cam, vec3_t d)
{
    return vec3_make(vec3_dot(d, cam->u), vec3_dot(d, cam->v), vec3_dot(d, cam->w));
}

RENDER_MAYBE_UNUSED static bool render_ortho(const cam_t *cam) { return cam->kind == CAM_ORTHOGRAPHIC; }

/* N = n.(A - o) and D = n.r for camera-space normal n and point a. */
RENDER_MAYBE_UNUSED static void render_flat_nd(const cam_t *cam, rext_t ext, vec3_t n, vec3_t a, render_flat_t *f)
{
    bool ortho = render_ortho(cam);
    num_t focal = ortho ? NUM_ONE : cam->focal;
    rclin_t nf = {rc_add(rc_add(rc_nn(n.x, a.x), rc_nn(n.y, a.y)), rc_nn(n.z, a.z)),
                  ortho ? rc_nw(num_neg(n.x), cam->step_u) : rc_zero(),
                  ortho ? rc_nw(num_neg(n.y), cam->step_v) : rc_zero()};
    rclin_t df = {rc_nn(n.z, num_neg(focal)), ortho ? rc_zero() : rc_n(n.x), ortho ? rc_zero() : rc_n(n.y)};
    int kn = rlin_need(&nf, ext, RENDER_LIN_BITS), kd = rlin_need(&df, ext, RENDER_LIN_BITS);
    f->n = rlin_scaled(nf, kn);
    f->d = rlin_scaled(df, kd);
    f->te = (int8_t)(kn - kd); /* N real = N 2^(kn - 48), D real = D 2^(kd - 48) */
    f->edges = 0;
    f->x0 = 0;
    f->x1 = (int16_t)(cam->width - 1);
    f->r0 = 0;
    f->r1 = (int16_t)(cam->height - 1);
}

/* Copy an object's bounds to (or from) a flat piece. */
RENDER_MAYBE_UNUSED static void render_flat_bounds_from(render_flat_t *f, const render_obj_t *o)
{
    f->x0 = o->x0;
    f->x1 = o->x1;
    f->r0 = o->r0;
    f->r1 = o->r1;
}

/* Edge form r.((P - o) x (Q - o)): which side of the plane through the ray
 * origin and the edge the ray passes. Formed with the edge in canonical
 * order and negated for the other, so that two faces sharing an edge get
 * exactly opposite forms: no ray slips between them (watertight). */
RENDER_MAYBE_UNUSED static render_lin_t render_edge(const cam_t *cam, rext_t ext, vec3_t p, vec3_t q)
{
    bool swap = geom_point_less(q, p);
    if (swap) {
        vec3_t t = p;
        p = q;
        q = t;
    }
    bool ortho = render_ortho(cam);
    num_t focal = ortho ? NUM_ONE : cam->focal;
    numw_t gx = numw_sub(numw_mul(p.y, q.z), numw_mul(p.z, q.y));
    numw_t gy = numw_sub(numw_mul(p.z, q.x), numw_mul(p.x, q.z));
    numw_t gz = numw_sub(numw_mul(p.x, q.y), numw_mul(p.y, q.x));
    rclin_t f;
    f.c = rc_nw(num_neg(focal), gz);
    if (ortho) {
        f.x = rc_nw(num_sub(q.y, p.y), cam->step_u);
        f.y = rc_nw(num_sub(p.x, q.x), cam->step_v);
    } else {
        f.x = rc_w(gx);
        f.y = rc_w(gy);
    }
    if (swap) {
        f.c = rc_neg(f.c);
        f.x = rc_neg(f.x);
        f.y = rc_neg(f.y);
    }
    return rlin_make(f, ext);
}

RENDER_MAYBE_UNUSED static int32_t render_floor(num_t v)
{
#if FXRT_NUMBER == FXRT_Q16
    return v >> FX_FRAC_BITS; /* arithmetic shift: floor */
#else
    if (v > NUM(1e6))
        return 1000000;
    if (v < NUM(-1e6))
        return -1000000;
    int32_t i = (int32_t)v;
    return (num_t)i > v ? i - 1 : i;
#endif
}

/* Pixel bounds from a camera-space point set, projected. */
typedef struct {
    num_t ix0, ix1, iy0, iy1;
    bool any;
} rbox_t;

RENDER_MAYBE_UNUSED static void render_bound_add(const cam_t *cam, rbox_t *b, vec3_t p)
{
    num_t ix, iy;
    if (render_ortho(cam)) {
        ix = numw_div(numw_from(p.x), cam->step_u);
        iy = numw_div(numw_from(p.y), cam->step_v);
    } else {
        numw_t z = numw_from(num_neg(p.z));
        ix = numw_div(numw_mul(p.x, cam->focal), z);
        iy = numw_div(numw_mul(p.y, cam->focal), z);
    }
    if (!b->any) {
        b->ix0 = b->ix1 = ix;
        b->iy0 = b->iy1 = iy;
        b->any = true;
        return;
    }
    b->ix0 = num_min(b->ix0, ix);
    b->ix1 = num_max(b->ix1, ix);
    b->iy0 = num_min(b->iy0, iy);
    b->iy1 = num_max(b->iy1, iy);
}

RENDER_MAYBE_UNUSED static int32_t render_clamp(int32_t v, int32_t lo, int32_t hi) { return v < lo ? lo : v > hi ? hi : v; }

/* floor(v / 2) for any sign. */
RENDER_MAYBE_UNUSED static int32_t render_half_floor(int32_t v) { return v >= 0 ? v / 2 : -((1 - v) / 2); }

RENDER_MAYBE_UNUSED static void render_set_full(const cam_t *cam, render_obj_t *o)
{
    o->x0 = 0;
    o->x1 = (int16_t)(cam->width - 1);
    o->r0 = 0;
    o->r1 = (int16_t)(cam->height - 1);
}

RENDER_MAYBE_UNUSED static void render_set_empty(render_obj_t *o)
{
    o->x0 = 1;
    o->x1 = 0;
    o->r0 = 1;
    o->r1 = 0;
}

/* Pixel rectangle of a projected bound, with a 2-pixel margin for the
 * rounding of the projection. A degenerate step (1-pixel axis) or a
 * saturated projection simply widens it to the screen. */
RENDER_MAYBE_UNUSED static void render_set_bounds(const cam_t *cam, const rbox_t *b, render_obj_t *o)
{
    int32_t w = cam->width, h = cam->height;
    int32_t x0 = render_half_floor(render_clamp(render_floor(b->ix0), -2 * w, 2 * w) + w - 1) - 2;
    int32_t x1 = render_half_floor(render_clamp(render_floor(b->ix1), -2 * w, 2 * w) + w - 1) + 3;
    int32_t y0 = render_half_floor(render_clamp(render_floor(b->iy0), -2 * h, 2 * h) + h - 1) - 2;
    int32_t y1 = render_half_floor(render_clamp(render_floor(b->iy1), -2 * h, 2 * h) + h - 1) + 3;
    if (render_ortho(cam) && w == 1) {
        x0 = 0;
        x1 = 0;
    }
    if (render_ortho(cam) && h == 1) {
        y0 = 0;
        y1 = 0;
    }
    if (x1 < 0 || x0 > w - 1 || y1 < 0 || y0 > h - 1) {
        render_set_empty(o);
        return;
    }
    o->x0 = (int16_t)render_clamp(x0, 0, w - 1);
    o->x1 = (int16_t)render_clamp(x1, 0, w - 1);
    o->r0 = (int16_t)(h - 1 - render_clamp(y1, 0, h - 1));
    o->r1 = (int16_t)(h - 1 - render_clamp(y0, 0, h - 1));
}

/* The depth range of an object inside the camera-space points p: a hit
 * at camera-space z has t = -z / F (orthographic: -z), so the points' z
 * range bounds t. A margin covers the rounding of the corners and of the
 * forms, so that every depth the forms give lies strictly inside. */
RENDER_MAYBE_UNUSED static void render_set_zrange(const cam_t *cam, const vec3_t *p, int n, render_obj_t *o)
{
    num_t zlo = p[0].z, zhi = p[0].z;
    for (int i = 1; i < n; i++) {
        zlo = num_min(zlo, p[i].z);
        zhi = num_max(zhi, p[i].z);
    }
    num_t f = render_ortho(cam) ? NUM_ONE : cam->focal;
#if FXRT_NUMBER == FXRT_Q16
    int64_t near = -(int64_t)zhi, far = -(int64_t)zlo;
    near -= 64 + (near > 0 ? near >> 12 : 0);
    far += 64 + (far > 0 ? far >> 12 : 0);
    o->tlo = render_depth_make(0, near > 0 ? (uint64_t)near : 0, (uint64_t)f, 0);
    o->thi = far > 0 ? render_depth_make(0, (uint64_t)far, (uint64_t)f, 0) : o->tlo;
#else
    num_t near = -zhi, far = -zlo;
    near = near - NUM(1e-3) - num_abs(near) * NUM(1e-3);
    far = far + NUM(1e-3) + num_abs(far) * NUM(1e-3);
    o->tlo.t = near > 0 ? near / f : NUM_ZERO;
    o->thi.t = far > 0 ? far / f : NUM_ZERO;
#endif
    o->ranged = true;
}

/* Bounds of camera-space points that are all in front in perspective;
 * straddling sets get the whole screen, sets wholly behind are empty. */
RENDER_MAYBE_UNUSED static void render_points_bounds(const cam_t *cam, const vec3_t *p, int n, render_obj_t *o)
{
    render_set_zrange(cam, p, n, o);
    int front = 0, behind = 0;
    for (int i = 0; i < n; i++) {
        if (p[i].z < NUM_ZERO)
            front++;
        else
            behind++;
    }
    if (front == 0) { /* no point with z < 0 can be on a ray (t > 0) */
        render_set_empty(o);
        return;
    }
    if (behind && !render_ortho(cam)) {
        render_set_full(cam, o);
        return;
    }
    rbox_t b = {NUM_ZERO, NUM_ZERO, NUM_ZERO, NUM_ZERO, false};
    for (int i = 0; i < n; i++)
        render_bound_add(cam, &b, p[i]);
    render_set_bounds(cam, &b, o);
}

#if FXRT_MAX_SPHERES > 0
static void render_setup_sphere(render_t *r, rext_t ext, const geom_sphere_t *s, render_obj_t *o)
{
    const cam_t *cam = r->cam;
    vec3_t c = render_to_cam(cam, s->center);
    num_t rad = s->radius;
    rc_t r2 = rc_w(s->radius2);
    rc_t cc = rc_sub(rc_add(rc_add(rc_nn(c.x, c.x), rc_nn(c.y, c.y)), rc_nn(c.z, c.z)), r2);
    rclin_t zero = {rc_zero(), rc_zero(), rc_zero()};
    rclin_t b = zero, px = zero, py = zero, pz = zero;
    rcquad_t a = {rc_zero(), rc_zero(), rc_zero(), rc_zero(), rc_zero(), rc_zero()};
    rc_t k;
    bool ortho = render_ortho(cam);
    (void)ext;
    o->kind = RENDER_SPHERE;
    o->u.sphere->ortho = ortho;
    if (ortho) {
        /* o = (su ix, sv iy, 0), r = (0, 0, -1): b = -cz, a = 1, the ray's
         * offset from the centre is (cx - su ix, cy - sv iy), so
         * disc = R^2 - px^2 - py^2 and c = cz^2 - R^2 + px^2 + py^2. */
        b.c = rc_n(num_neg(c.z));
        a.c = rc_n(NUM_ONE);
        px.c = rc_n(c.x);
        px.x = rc_neg(rc_w(cam->step_u));
        py.c = rc_n(c.y);
        py.y = rc_neg(rc_w(cam->step_v));
        k = rc_sub(rc_nn(c.z, c.z), r2);
    } else {
        /* o = 0, r = (ix, iy, -F): b = C.r, a = |r|^2, p = C x r =
         * (-cy F - cz iy, cz ix + cx F, cx iy - cy ix), c = |C|^2 - R^2. */
        num_t f = cam->focal;
        b.c = rc_nn(c.z, num_neg(f));
        b.x = rc_n(c.x);
        b.y = rc_n(c.y);
        px.c = rc_nn(c.y, num_neg(f));
        px.y = rc_n(num_neg(c.z));
        py.c = rc_nn(c.x, f);
        py.x = rc_n(c.z);
        pz.x = rc_n(num_neg(c.y));
        pz.y = rc_n(c.x);
        a.c = rc_nn(f, f);
        a.xx = rc_n(NUM_ONE);
        a.yy = rc_n(NUM_ONE);
        k = cc;
    }
#if FXRT_NUMBER == FXRT_Q16
    /* Scales: the p pieces share kp, so disc is in units of 2^(2 kp - 96)
     * and r2 is R^2 a brought to those units; b only matters by its sign. */
    rclin_t radl = {rc_n(rad), rc_zero(), rc_zero()};
    int kp = rlin_need(&px, ext, RENDER_SPHERE_BITS), n;
    n = rlin_need(&b, ext, RENDER_SPHERE_BITS); /* b + sqrt(disc) is formed for depth */
    kp = kp > n ? kp : n;
    n = rlin_need(&py, ext, RENDER_SPHERE_BITS);
    kp = kp > n ? kp : n;
    n = rlin_need(&pz, ext, RENDER_SPHERE_BITS);
    kp = kp > n ? kp : n;
    int ka = 48; /* orthographic: a = 1 exactly */
    if (ortho) {
        n = rlin_need(&radl, ext, RENDER_SPHERE_BITS);
        kp = kp > n ? kp : n;
    } else {
        ka = rquad_need(&a, ext, RENDER_SPHERE_BITS);
    }
    /* R^2 a in units of 2^(2 kp - 96): r2 = R2_48 * 2^(ka - 2 kp). In
     * perspective r2 multiplies a 64-bit a, so it must fit 62 bits too:
     * on tiny images the pieces' scales alone can leave it larger, and a
     * coarser kp (four times smaller r2 per step) fixes that. */
    int sr = 2 * kp - ka;
    o->u.sphere->r2 = sr >= 0 ? fx128_shr128(r2, sr) : fx128_shl(r2, -sr);
    while (!ortho && fx128_bits(o->u.sphere->r2) > RENDER_SPHERE_BITS) {
        kp++;
        sr += 2;
        o->u.sphere->r2 = sr >= 0 ? fx128_shr128(r2, sr) : fx128_shl(r2, -sr);
    }
    int sk = 2 * kp - 48;
    o->u.sphere->k = sk >= 0 ? fx128_shr128(k, sk) : fx128_shl(k, -sk);
    o->u.sphere->b = rlin_scaled(b, kp);
    r->sphere_a = rquad_scaled(a, ka); /* the same for every sphere */
    o->u.sphere->a = &r->sphere_a;
    /* b and sqrt(disc) are real * 2^(48 - kp), c is real * 2^(96 - 2 kp)
     * and a is real * 2^(48 - ka). */
    o->u.sphere->tc = (int8_t)(kp - 48);
    o->u.sphere->ta = (int8_t)(kp - ka);
    o->u.sphere->px = rlin_scaled(px, kp);
    o->u.sphere->py = rlin_scaled(py, kp);
    o->u.sphere->pz = rlin_scaled(pz, kp);
#else
    o->u.sphere->b = rlin_scaled(b, 0);
    r->sphere_a = rquad_scaled(a, 0);
    o->u.sphere->a = &r->sphere_a;
    o->u.sphere->px = rlin_scaled(px, 0);
    o->u.sphere->py = rlin_scaled(py, 0);
    o->u.sphere->pz = rlin_scaled(pz, 0);
    o->u.sphere->k = k;
    o->u.sphere->r2 = r2;
    o->u.sphere->tc = 0;
    o->u.sphere->ta = 0;
#endif
    /* Bounds. */
    if (!rc_is_neg(cc) && c.z >= rad) {
        render_set_empty(o); /* wholly at z >= 0: behind the eye */
        return;
    }
    if (rc_is_neg(cc)) {
        render_set_full(r->cam, o); /* eye inside */
        return;
    }
    vec3_t corner[8];
    for (int i = 0; i < 8; i++)
        corner[i] = vec3_make((i & 1) ? num_add(c.x, rad) : num_sub(c.x, rad),
                              (i & 2) ? num_add(c.y, rad) : num_sub(c.y, rad),
                              (i & 4) ? num_add(c.z, rad) : num_sub(c.z, rad));
    render_points_bounds(cam, corner, 8, o);
}
#endif

#if FXRT_MAX_PLANES > 0
static void render_setup_plane(render_t *r, rext_t ext, const geom_plane_t *p, render_obj_t *o)
{
    o->kind = RENDER_FLAT;
    o->nflat = 1;
    render_flat_nd(r->cam, ext, render_dir_to_cam(r->cam, p->n), render_to_cam(r->cam, p->a), render_face(o, 0));
    render_set_full(r->cam, o); /* rows beyond the horizon are skipped per row */
}
#endif

#if FXRT_MAX_TRIANGLES > 0
static void render_setup_triangle(render_t *r, rext_t ext, const geom_triangle_t *t, render_obj_t *o)
{
    const cam_t *cam = r->cam;
    vec3_t v[3] = {render_to_cam(cam, t->a), render_to_cam(cam, t->b), render_to_cam(cam, t->c)};
    o->kind = RENDER_FLAT;
    o->nflat = 1;
    if (t->degenerate) {
        o->nflat = 0;
        render_set_empty(o);
        return;
    }
    render_flat_t *f = render_face(o, 0);
    render_flat_nd(cam, ext, render_dir_to_cam(cam, t->n), v[0], f);
    for (int i = 0; i < 3; i++)
        f->e[i] = render_edge(cam, ext, v[i], v[(i + 1) % 3]);
    f->edges = 3;
    render_points_bounds(cam, v, 3, o);
    render_flat_bounds_from(f, o);
}
#endif

#if FXRT_MAX_BOXES > 0

static void render_setup_box(render_t *r, rext_t ext, const geom_box_t *b, render_obj_t *o)
{
    const cam_t *cam = r->cam;
    bool ortho = render_ortho(cam);
    vec3_t corner[8]; /* bit i of the index: max on axis i */
    for (int i = 0; i < 8; i++)
        corner[i] = render_to_cam(cam, vec3_make((i & 1) ? b->max.x : b->min.x, (i & 2) ? b->max.y : b->min.y,
                                                 (i & 4) ? b->max.z : b->min.z));
    /* A ray covers the box when it crosses one of its faces at t > 0 (the
     * entry face from outside, the exit face from inside), so the box's
     * coverage is the union of its faces' coverage, each with its own
     * front test. A perspective eye strictly outside can only reach the
     * faces turned towards it; strictly inside, every ray hits. */
    bool inside = !ortho, outside = false;
    int side_of[3];
    for (int axis = 0; axis < 3; axis++) {
        num_t e = geom_axis(cam->e, axis);
        num_t lo = geom_axis(b->min, axis), hi = geom_axis(b->max, axis);
        if (!(e > lo && e < hi))
            inside = false;
        side_of[axis] = e < lo ? 0 : (e > hi ? 1 : -1);
        if (side_of[axis] >= 0)
            outside = true;
    }
    o->kind = RENDER_BOX;
    o->nflat = 0;
    for (int axis = 0; axis < 3; axis++) {
        int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
        /* A face of zero area (a flat box seen from its side) covers
         * nothing: its edge forms would describe a line or the whole
         * screen instead. */
        if (geom_axis(b->min, a1) == geom_axis(b->max, a1) || geom_axis(b->min, a2) == geom_axis(b->max, a2))
            continue;
        for (int side = 0; side < 2; side++) {
            if (!ortho && outside && side != side_of[axis])
                continue; /* turned away from an eye outside */
            if ((ortho || !outside) && side == 1 && geom_axis(b->min, axis) == geom_axis(b->max, axis))
                continue; /* a flat box: both faces are one rectangle, keep one */
            vec3_t nw = vec3_make(axis == 0 ? NUM_ONE : NUM_ZERO, axis == 1 ? NUM_ONE : NUM_ZERO,
                                  axis == 2 ? NUM_ONE : NUM_ZERO);
            if (side == 0)
                nw = vec3_neg(nw);
            vec3_t nc = render_dir_to_cam(cam, nw);
            if (ortho && nc.z == NUM_ZERO)
                continue; /* parallel to every ray */
            /* The face's four corners, in order around it. */
            int base = side << axis;
            int idx[4] = {base, base | (1 << a1), base | (1 << a1) | (1 << a2), base | (1 << a2)};
            vec3_t q[4];
            for (int k = 0; k < 4; k++)
                q[k] = corner[idx[k]];
            if (o->u.face + o->nflat >= r->box_faces + FXRT_RENDER_BOX_FACES) {
                r->error = "more box faces than FXRT_RENDER_BOX_FACES";
                continue;
            }
            render_face_t *bf = &o->u.face[o->nflat++];
            render_flat_t *f = &bf->f;
            render_flat_nd(cam, ext, nc, q[0], f);
            for (int k = 0; k < 4; k++)
                *(k < 3 ? &f->e[k] : &bf->e4) = render_edge(cam, ext, q[k], q[(k + 1) % 4]);
            f->edges = 4;
            /* Each face gets its own bounds, so a pixel is mostly stepped
             * for one face rather than all of them. */
            render_obj_t tmp;
            render_points_bounds(cam, q, 4, &tmp);
            render_flat_bounds_from(f, &tmp);
        }
    }
    if (inside) {
        /* Every ray covers the box; its faces (all of them, from inside)
         * give the depth of the exit point. */
        o->kind = RENDER_ALL;
        render_set_full(cam, o);
        return;
    }
    if (o->nflat == 0) {
        render_set_empty(o);
        return;
    }
    render_points_bounds(cam, corner, 8, o);
}
#endif

/* (Re)compute object i's forms and bounds from its world object. */
static void render_setup_object(render_t *r, uint16_t i)
{
    const world_t *w = r->world;
    const cam_t *cam = r->cam;
    rext_t ext = {(uint32_t)(cam->width - 1), (uint32_t)(cam->height - 1)};
    render_obj_t *o = &r->obj[i];
    (void)ext;
    (void)w;
    switch (o->geom) {
    case GEOM_PLANE:
#if FXRT_MAX_PLANES > 0
        render_setup_plane(r, ext, &w->planes[o->index], o);
#endif
        break;
    case GEOM_SPHERE:
#if FXRT_MAX_SPHERES > 0
        render_setup_sphere(r, ext, &w->spheres[o->index], o);
#endif
        break;
    case GEOM_TRIANGLE:
#if FXRT_MAX_TRIANGLES > 0
        render_setup_triangle(r, ext, &w->triangles[o->index], o);
#endif
        break;
    case GEOM_BOX:
#if FXRT_MAX_BOXES > 0
        render_setup_box(r, ext, &w->boxes[o->index], o);
#endif
        break;
    }
}

/* Register an object of the world in scene-array order. */
static void render_add(render_t *r, geom_kind_t kind, uint16_t index, const geom_common_t *c)
{
    uint16_t i = r->count++;
    render_obj_t *o = &r->obj[i];
    o->geom = kind;
    o->index = index;
    o->id = c->id;
    o->rgb = c->rgb;
#if FXRT_PIXEL == FXRT_RGB565
    o->px = render_565(c->rgb);
#endif
    o->ranged = false;
    switch (kind) {
    case GEOM_PLANE:
#if FXRT_MAX_PLANES > 0
        o->u.flat = &r->flats[index];
#endif
        break;
    case GEOM_SPHERE:
#if FXRT_MAX_SPHERES > 0
        o->u.sphere = &r->spheres[index];
#endif
        break;
    case GEOM_TRIANGLE:
#if FXRT_MAX_TRIANGLES > 0
        o->u.flat = &r->flats[r->nplanes + index];
#endif
        break;
    case GEOM_BOX:
#if FXRT_MAX_BOXES > 0
        o->u.face = &r->box_faces[r->box_used]; /* boxes come last: the rest of the pool */
#endif
        break;
    }
    render_setup_object(r, i);
#if FXRT_MAX_BOXES > 0
    if (kind == GEOM_BOX)
        r->box_used = (uint16_t)(r->box_used + o->nflat);
#endif
}

bool render_setup(render_t *r, const world_t *w, const cam_t *cam)
{
    r->error = NULL;
    if (cam->width > FXRT_RENDER_MAX_WIDTH) {
        r->error = "image wider than FXRT_RENDER_MAX_WIDTH";
        return false;
    }
#if FXRT_MAX_BOXES > 0
    r->box_used = 0;
#endif
    r->world = w;
    r->cam = cam;
    r->count = 0;
    r->row_win = 0;
#if FXRT_MAX_PLANES > 0
    r->nplanes = w->n_planes;
#else
    r->nplanes = 0;
#endif
    for (int32_t x = 0; x < cam->width; x++)
        r->owner[x] = 0;
    r->stamp = 0;
#if FXRT_MAX_PLANES > 0
    for (uint16_t i = 0; i < w->n_planes; i++)
        render_add(r, GEOM_PLANE, i, &w->planes[i].obj);
#endif
#if FXRT_MAX_SPHERES > 0
    for (uint16_t i = 0; i < w->n_spheres; i++)
        render_add(r, GEOM_SPHERE, i, &w->spheres[i].obj);
#endif
#if FXRT_MAX_TRIANGLES > 0
    for (uint16_t i = 0; i < w->n_triangles; i++)
        render_add(r, GEOM_TRIANGLE, i, &w->triangles[i].obj);
#endif
#if FXRT_MAX_BOXES > 0
    for (uint16_t i = 0; i < w->n_boxes; i++)
        render_add(r, GEOM_BOX, i, &w->boxes[i].obj);
#endif
    return r->error == NULL;
}

/* ---- depth at pixels that several objects cover ------------------------
 * Depth is the ray parameter t of the camera-space ray r = (ix, iy, -F)
 * (orthographic: (0, 0, -1)), formed from the same forms that decide
 * coverage: a flat piece's t = N / D, a sphere's near root c / (b + s)
 * (s = sqrt(disc); the far root (b + s) / a from inside), so no ray is cast.
 * Q16.16: t is kept as n / d * 2^e with n and d normalised to 31 bits
 * (truncated: a deterministic function of the exact integer forms), and
 * two depths compare exactly by cross-multiplication in 64 bits. */

#if FXRT_NUMBER == FXRT_Q16
/* The top 24 bits of v > 0 (v < 2^128), their exponent added to *e. */
static uint32_t render_top24(uint64_t hi, uint64_t lo, int *e)
{
    int b = hi ? 128 - __builtin_clzll(hi) : (lo ? 64 - __builtin_clzll(lo) : 0);
    if (b == 0)
        return 0;
    *e += b - 24;
    if (b <= 24)
        return (uint32_t)(lo << (24 - b));
    int s = b - 24; /* truncating right shift by s (1..104) */
    if (s >= 64)
        return (uint32_t)(hi >> (s - 64));
    return (uint32_t)((lo >> s) | (hi << 1 << (63 - s)));
}

#define RENDER_DEPTH_ONE (1u << 23)
#define RENDER_DEPTH_EMAX 126 /* exponents clamp to +-126 (t beyond 2^+-126) */

static render_depth_t render_depth_pack(uint32_t n, uint32_t d, int e)
{
    render_depth_t t;
    e = e > RENDER_DEPTH_EMAX ? RENDER_DEPTH_EMAX : (e < -RENDER_DEPTH_EMAX ? -RENDER_DEPTH_EMAX : e);
    t.n = n;
    t.d = d;
    t.e = e;
    return t;
}

/* t = n / d * 2^e for n >= 0 and d > 0 (d = 0 cannot occur at a covered
 * pixel; it would give the far depth). */
static render_depth_t render_depth_make(uint64_t n_hi, uint64_t n_lo, uint64_t d, int e)
{
    int en = 0, ed = 0;
    uint32_t tn = render_top24(n_hi, n_lo, &en), td = render_top24(0, d, &ed);
    if (td == 0)
        return render_depth_pack(RENDER_DEPTH_ONE, RENDER_DEPTH_ONE, RENDER_DEPTH_EMAX);
    if (tn == 0)
        return render_depth_pack(0, RENDER_DEPTH_ONE, 0);
    return render_depth_pack(tn, td, e + en - ed);
}

/* Strictly nearer. n / d lies in (1/2, 2), so exponents two apart decide
 * alone; otherwise 24 x 24-bit products (below 2^49 after one doubling). */
static bool render_depth_less(render_depth_t a, render_depth_t b)
{
    if (a.n == 0 || b.n == 0)
        return a.n == 0 && b.n != 0;
    int32_t de = (int32_t)a.e - (int32_t)b.e;
    if (de >= 2)
        return false;
    if (de <= -2)
        return true;
    uint64_t l = (uint64_t)a.n * b.d, g = (uint64_t)b.n * a.d;
    if (de == 1)
        l <<= 1;
    else if (de == -1)
        g <<= 1;
    return l < g;
}

static const render_depth_t render_depth_far = {RENDER_DEPTH_ONE, RENDER_DEPTH_EMAX, RENDER_DEPTH_ONE};

static uint64_t render_uabs(render_k_t v) { return v < 0 ? 0 - (uint64_t)v : (uint64_t)v; }

static render_depth_t render_flat_depth(const render_flat_t *f, render_k_t n, render_k_t d)
{
    return render_depth_make(0, render_uabs(n), render_uabs(d), f->te);
}

/* floor(sqrt(v)) to about 32 significant bits, v >= 0 (v < 2^127). */
static uint64_t render_sqrt128(fx128_t v)
{
    if (v.hi < 0)
        return 0;
    int b = fx128_bits(v);
    if (b <= 64)
        return fx_isqrt64(v.lo);
    int s = (b - 63) & ~1; /* even */
    s = s < b - 64 ? s + 2 : s;
    uint64_t top = s >= 64 ? (uint64_t)v.hi >> (s - 64) : (v.lo >> s) | ((uint64_t)v.hi << (64 - s));
    return (uint64_t)fx_isqrt64(top) << (s / 2);
}

static render_depth_t render_sphere_depth(const render_obj_t *o, int32_t ix, int32_t iy, render_k_t b, rsw_t c, rsw_t disc)
{
    uint64_t s = render_sqrt128(disc);
    if (!rsw_neg(c)) /* outside: the near root, b > 0 */
        return render_depth_make((uint64_t)c.hi, c.lo, (uint64_t)b + s, o->u.sphere->tc);
    if (b < 0) { /* inside, looking away from the centre: (-c) / (s - b) */
        fx128_t nc = fx128_neg(c);
        return render_depth_make((uint64_t)nc.hi, nc.lo, s + (0 - (uint64_t)b), o->u.sphere->tc);
    }
    render_k_t a = o->u.sphere->ortho ? 1 : rquad_at(o->u.sphere->a, ix, iy);
    return render_depth_make(0, (uint64_t)b + s, (uint64_t)a, o->u.sphere->ta);
}
#else
static bool render_depth_less(render_depth_t a, render_depth_t b) { return a.t < b.t; }
static const render_depth_t render_depth_far = {NUM_MAX};
static render_depth_t render_flat_depth(const render_flat_t *f, render_k_t n, render_k_t d)
{
    (void)f;
    render_depth_t t = {num_div(n, d)};
    return t;
}
static render_depth_t render_sphere_depth(const render_obj_t *o, int32_t ix, int32_t iy, render_k_t b, rsw_t c, rsw_t disc)
{
    num_t s = num_sqrt(disc);
    render_depth_t t;
    if (!(c < 0))
        t.t = num_div(c, b + s);
    else if (b < 0)
        t.t = num_div(-c, s - b);
    else
        t.t = num_div(b + s, o->u.sphere->ortho ? NUM_ONE : rquad_at(o->u.sphere->a, ix, iy));
    return t;
}
#endif

/* Depth of object o at a pixel it covers, from its forms evaluated there. */
static render_depth_t render_depth_at(const render_obj_t *o, int32_t ix, int32_t iy)
{
    if (o->kind == RENDER_SPHERE) {
        rsw_t c, disc;
        render_sphere_cd(o, ix, iy, &c, &disc);
        return render_sphere_depth(o, ix, iy, rlin_at(&o->u.sphere->b, ix, iy), c, disc);
    }
    /* Flat pieces: the nearest face that covers the pixel. */
    render_depth_t best = render_depth_far;
    for (int i = 0; i < o->nflat; i++) {
        const render_flat_t *f = render_face(o, i);
        if (!render_flat_at(f, ix, iy))
            continue;
        render_depth_t t = render_flat_depth(f, rlin_at(&f->n, ix, iy), rlin_at(&f->d, ix, iy));
        if (render_depth_less(t, best))
            best = t;
    }
    return best;
}

/* Owner entries: stamp (15 bits) << 17 | depth-known bit << 16 | object. */
#define RENDER_DEPTH_KNOWN 0x10000u
#define RENDER_STAMP_SHIFT 17
#define RENDER_STAMP_LIMIT 0x8000u

/* How to get a newcomer's depth when it is needed: from the values the
 * scanline loop stepped (a flat piece's N and D, a sphere's b, c, disc) or
 * from its forms evaluated at the pixel. */
typedef struct {
    enum { RENDER_RAW_AT, RENDER_RAW_FLAT, RENDER_RAW_SPHERE } how;
    const render_flat_t *f;
    render_k_t n, d, b;
    rsw_t c, disc;
} render_raw_t;

static render_depth_t render_raw_depth(const render_obj_t *o, int32_t ix, int32_t iy, const render_raw_t *raw)
{
#if RENDER_STEPPED
    if (raw->how == RENDER_RAW_FLAT)
        return render_flat_depth(raw->f, raw->n, raw->d);
    if (raw->how == RENDER_RAW_SPHERE)
        return render_sphere_depth(o, ix, iy, raw->b, raw->c, raw->disc);
#else
    (void)raw;
#endif
    return render_depth_at(o, ix, iy);
}

/* Object oi also covers column x, owned so far by the entry cur: the
 * nearer keeps it (ties: lower scene id). A depth, once computed, is kept
 * next to the owner. Depths are only computed when the objects' depth
 * ranges (render_setup: from their camera-space z, with a margin) do not
 * already decide. Returns true when oi wins. */
static __attribute__((noinline)) bool render_settle(render_t *r, uint32_t cur, uint16_t oi, int32_t x, int32_t iy,
                                                    const render_raw_t *raw)
{
    uint16_t ci = (uint16_t)cur;
    const render_obj_t *a = &r->obj[ci], *b = &r->obj[oi];
    int32_t ix = 2 * x - r->cam->width + 1;
    uint32_t stamp = cur & ~0x1FFFFu;
    if (ci < 32 && ((r->row_win >> ci) & 1u)) { /* oi is nearer than plane ci all along this row */
        r->owner[x] = stamp | oi;
        return true;
    }
    bool known = (cur & RENDER_DEPTH_KNOWN) != 0;
    if (!FXRT_NO_ZRANGE && !known && a->ranged && b->ranged) {
        if (render_depth_less(a->thi, b->tlo))
            return false;
        if (render_depth_less(b->thi, a->tlo)) {
            r->owner[x] = stamp | oi;
            return true;
        }
    }
    render_depth_t ta, tb;
    if (known || FXRT_NO_ZRANGE || !a->ranged) {
        ta = known ? r->depth[x] : render_depth_at(a, ix, iy);
        if (!FXRT_NO_ZRANGE && b->ranged) {
            if (render_depth_less(ta, b->tlo)) {
                r->depth[x] = ta;
                r->owner[x] = stamp | RENDER_DEPTH_KNOWN | ci;
                return false;
            }
            if (render_depth_less(b->thi, ta)) {
                r->owner[x] = stamp | oi;
                return true;
            }
        }
        tb = render_raw_depth(b, ix, iy, raw);
    } else {
        tb = render_raw_depth(b, ix, iy, raw);
        if (render_depth_less(a->thi, tb))
            return false;
        if (render_depth_less(tb, a->tlo)) {
            r->depth[x] = tb;
            r->owner[x] = stamp | RENDER_DEPTH_KNOWN | oi;
            return true;
        }
        ta = render_depth_at(a, ix, iy);
    }
    bool win = render_depth_less(tb, ta) || (!render_depth_less(ta, tb) && b->id < a->id);
    r->depth[x] = win ? tb : ta;
    r->owner[x] = stamp | RENDER_DEPTH_KNOWN | (win ? oi : ci);
    return win;
}

/* The newcomer's depth from its forms evaluated at the pixel. */
static bool render_resolve(render_t *r, uint32_t cur, uint16_t oi, int32_t x, int32_t iy)
{
    render_raw_t raw;
    raw.how = RENDER_RAW_AT;
    return render_settle(r, cur, oi, x, iy, &raw);
}

#if RENDER_STEPPED
/* The newcomer's depth from the values the scanline loop stepped. */
static bool render_resolve_flat(render_t *r, uint32_t cur, uint16_t oi, int32_t x, int32_t iy, const render_flat_t *f,
                                render_k_t n, render_k_t d)
{
    render_raw_t raw;
    raw.how = RENDER_RAW_FLAT;
    raw.f = f;
    raw.n = n;
    raw.d = d;
    return render_settle(r, cur, oi, x, iy, &raw);
}
static bool render_resolve_sphere(render_t *r, uint32_t cur, uint16_t oi, int32_t x, int32_t iy, render_k_t b, rsw_t c,
                                  rsw_t disc)
{
    render_raw_t raw;
    raw.how = RENDER_RAW_SPHERE;
    raw.b = b;
    raw.c = c;
    raw.disc = disc;
    return render_settle(r, cur, oi, x, iy, &raw);
}
#endif

/* Claim column x for object oi: free columns are taken at once, a column
 * owned by another object goes to the nearer (RESOLVE, which may use cur_),
 * and the pixel is painted when oi wins. */
#define RENDER_COVER(r, oi, x, rgb, RESOLVE)                                         \
    do {                                                                         \
        uint32_t tag_ = (uint32_t)(r)->stamp << RENDER_STAMP_SHIFT, cur_ = (r)->owner[x]; \
        if ((cur_ & ~0x1FFFFu) != tag_)                                          \
            (r)->owner[x] = tag_ | (oi);                                         \
        else if ((uint16_t)cur_ == (oi) || !(RESOLVE))                           \
            break;                                                               \
        render_paint(r, oi, x, rgb);                                             \
    } while (0)

/* Paint column x in object oi's colour (the row's pixel format). */
#if FXRT_PIXEL == FXRT_RGB565
typedef uint16_t __attribute__((may_alias)) render_px16_t;
static inline void render_paint(const render_t *r, uint16_t oi, int32_t x, uint8_t *rgb)
{
    ((render_px16_t *)(void *)rgb)[x] = r->obj[oi].px;
}
#else
static inline void render_paint(const render_t *r, uint16_t oi, int32_t x, uint8_t *rgb)
{
    rgb8_t c = r->obj[oi].rgb;
    rgb[3 * x + 0] = c.r;
    rgb[3 * x + 1] = c.g;
    rgb[3 * x + 2] = c.b;
}
#endif

/* Record that object oi covers column x and paint it if it is the nearest
 * so far. The result does not depend on the order of calls (depth, then
 * id, order objects totally), so both loops agree. */
static inline void render_cover(render_t *r, uint16_t oi, int32_t x, int32_t iy, uint8_t *rgb)
{
    RENDER_COVER(r, oi, x, rgb, render_resolve(r, cur_, oi, x, iy));
}

/* A hit at column x: paint directly when the object is alone on the row
 * (no other object's bounds reach it, so no bookkeeping). */
#define RENDER_HIT(r, oi, x, iy, rgb, lone)                                    \
    do {                                                                       \
        if (lone)                                                              \
            render_paint(r, oi, x, rgb);                                       \
        else                                                                   \
            render_cover(r, oi, x, iy, rgb);                                   \
    } while (0)

/* Start a row: a new stamp (so every column is uncovered) and the
 * background in every pixel, with word stores where the row is aligned. */
static void render_begin_row(render_t *r, uint8_t *rgb)
{
    if (++r->stamp == RENDER_STAMP_LIMIT) {
        for (int32_t x = 0; x < r->cam->width; x++)
            r->owner[x] = 0;
        r->stamp = 1;
    }
    rgb8_t bg = r->world->background_rgb;
    typedef uint32_t __attribute__((may_alias)) word_t;
#if FXRT_PIXEL == FXRT_RGB565
    uint16_t v = render_565(bg);
    int32_t n = r->cam->width, i = 0;
    render_px16_t *p16 = (render_px16_t *)(void *)rgb;
    if (((uintptr_t)rgb & 3u) == 0) {
        word_t two = (uint32_t)v * 0x10001u, *p = (word_t *)(void *)rgb;
        for (; i + 2 <= n; i += 2)
            *p++ = two;
    }
    for (; i < n; i++)
        p16[i] = v;
#else
    uint8_t pat[12];
    for (int i = 0; i < 4; i++) {
        pat[3 * i + 0] = bg.r;
        pat[3 * i + 1] = bg.g;
        pat[3 * i + 2] = bg.b;
    }
    int32_t n = 3 * r->cam->width, i = 0;
    if (((uintptr_t)rgb & 3u) == 0) {
        /* Aligned rows (the firmware's framebuffer and bands): three word
         * stores per four pixels. may_alias: the buffer is bytes. */
        word_t w[3];
        __builtin_memcpy(w, pat, 12);
        word_t *p = (word_t *)(void *)rgb;
        for (; i + 12 <= n; i += 12, p += 3) {
            p[0] = w[0];
            p[1] = w[1];
            p[2] = w[2];
        }
    } else {
        for (; i + 12 <= n; i += 12)
            __builtin_memcpy(rgb + i, pat, 12);
    }
    for (; i < n; i++)
        rgb[i] = pat[i % 3];
#endif
}

void render_row_reference(render_t *r, int32_t row, uint8_t *rgb)
{
    int32_t w = r->cam->width, y = r->cam->height - 1 - row;
    int32_t iy = 2 * y - r->cam->height + 1;
    render_begin_row(r, rgb);
    r->row_win = 0;
    for (int32_t x = 0; x < w; x++) {
        int32_t ix = 2 * x - w + 1;
        for (uint16_t i = 0; i < r->count; i++) {
            if (FXRT_NO_HOIST)
                render_setup_object(r, i);
            if (render_covers(&r->obj[i], ix, iy))
                render_cover(r, i, x, iy, rgb);
        }
    }
}

/* ---- the fast loop ------------------------------------------------------ */

/* ---- spans -------------------------------------------------------------- */

/* Fill columns xa..xb with object oi's colour, with word stores where the
 * row is aligned (RGB888: three words per four pixels; RGB565: one word
 * per two). */
RENDER_MAYBE_UNUSED static void render_fill(const render_t *r, uint16_t oi, int32_t xa, int32_t xb, uint8_t *rgb)
{
    typedef uint32_t __attribute__((may_alias)) word_t;
    int32_t x = xa;
#if FXRT_PIXEL == FXRT_RGB565
    if (((uintptr_t)rgb & 3u) == 0) {
        for (; x <= xb && (x & 1); x++)
            render_paint(r, oi, x, rgb);
        word_t two = (uint32_t)r->obj[oi].px * 0x10001u, *p = (word_t *)(void *)rgb + x / 2;
        for (; x + 1 <= xb; x += 2)
            *p++ = two;
    }
#else
    if (((uintptr_t)rgb & 3u) == 0) {
        for (; x <= xb && (x & 3); x++)
            render_paint(r, oi, x, rgb);
        if (x + 3 <= xb) {
            rgb8_t c = r->obj[oi].rgb;
            uint8_t pat[12];
            for (int i = 0; i < 4; i++) {
                pat[3 * i + 0] = c.r;
                pat[3 * i + 1] = c.g;
                pat[3 * i + 2] = c.b;
            }
            word_t w[3], *p = (word_t *)(void *)(rgb + 3 * x);
            __builtin_memcpy(w, pat, 12);
            for (; x + 3 <= xb; x += 4, p += 3) {
                p[0] = w[0];
                p[1] = w[1];
                p[2] = w[2];
            }
        }
    }
#endif
    for (; x <= xb; x++)
        render_paint(r, oi, x, rgb);
}

#if FXRT_NUMBER == FXRT_Q16 && !FXRT_NO_STEP && !FXRT_NO_SPANS
/* Columns x0 + k, k in lo..hi (empty when lo > hi). */
typedef struct {
    int32_t lo, hi;
} render_iv_t;

static render_iv_t render_iv_and(render_iv_t a, render_iv_t b)
{
    render_iv_t r = {a.lo > b.lo ? a.lo : b.lo, a.hi < b.hi ? a.hi : b.hi};
    return r;
}

static int32_t render_kclamp(int64_t v, int32_t kmax) { return v < -1 ? -1 : (v > kmax + 1 ? kmax + 1 : (int32_t)v); }

/* Where along a row segment k = 0..kmax a linear form a + b k is > 0,
 * >= 0, < 0 and <= 0 (iv[0..3]), exactly: one floor division locates its
 * root, and the remainder says whether the root is a column. */
static void render_signs(int64_t a, int64_t b, int32_t kmax, render_iv_t iv[4])
{
    render_iv_t all = {0, kmax}, none = {1, 0};
    if (b == 0) {
        iv[0] = a > 0 ? all : none;
        iv[1] = a >= 0 ? all : none;
        iv[2] = a < 0 ? all : none;
        iv[3] = a <= 0 ? all : none;
        return;
    }
    bool flip = b < 0; /* then work with -(a + b k) */
    if (flip) {
        a = -a;
        b = -b;
    }
    int64_t q = -a / b, rem = -a % b; /* |a|, |b| < 2^62: no overflow */
    if (rem < 0)
        q--; /* floor(-a / b) */
    bool exact = rem == 0;
    render_iv_t pos = {render_kclamp(q + 1, kmax), kmax}, nonneg = {render_kclamp(exact ? q : q + 1, kmax), kmax};
    render_iv_t neg = {0, render_kclamp(exact ? q - 1 : q, kmax)}, nonpos = {0, render_kclamp(q, kmax)};
    iv[0] = flip ? neg : pos;
    iv[1] = flip ? nonpos : nonneg;
    iv[2] = flip ? pos : neg;
    iv[3] = flip ? nonneg : nonpos;
}

/* A flat piece's hits on columns x0..x1 as at most four runs (k from
 * x0, possibly overlapping), found exactly from its forms: the same sign
 * tests as the stepping loop (N and D of one strict sign, edges all >= 0
 * or all <= 0). Returns the number of runs. */
static int render_runs_flat(const render_t *r, const render_flat_t *f, int32_t x0, int32_t x1, int32_t iy,
                            render_iv_t run[4])
{
    int32_t ix0 = 2 * x0 - r->cam->width + 1, kmax = x1 - x0;
    render_iv_t n[4], d[4], e[4], ge = {0, kmax}, le = {0, kmax};
    render_signs(rlin_at(&f->n, ix0, iy), 2 * f->n.x, kmax, n);
    render_signs(rlin_at(&f->d, ix0, iy), 2 * f->d.x, kmax, d);
    render_iv_t front[2] = {render_iv_and(n[0], d[0]), render_iv_and(n[2], d[2])};
    for (int k = 0; k < f->edges; k++) {
        const render_lin_t *ek = render_edge_k(f, k);
        render_signs(rlin_at(ek, ix0, iy), 2 * ek->x, kmax, e);
        ge = render_iv_and(ge, e[1]);
        le = render_iv_and(le, e[3]);
    }
    int nrun = 0;
    for (int i = 0; i < 2; i++) {
        render_iv_t a = render_iv_and(front[i], ge), b = render_iv_and(front[i], le);
        if (a.lo <= a.hi)
            run[nrun++] = a;
        if (b.lo <= b.hi && f->edges)
            run[nrun++] = b;
    }
    return nrun;
}

/* A lone flat piece: its runs filled. */
static void render_span_flat(render_t *r, uint16_t oi, const render_flat_t *f, int32_t x0, int32_t x1, int32_t iy,
                             uint8_t *rgb)
{
    render_iv_t run[4];
    int nrun = render_runs_flat(r, f, x0, x1, iy, run);
    for (int k = 0; k < nrun; k++)
        render_fill(r, oi, x0 + run[k].lo, x0 + run[k].hi, rgb);
}
#endif

#if FXRT_NUMBER == FXRT_Q16 && !FXRT_NO_STEP
/* Step a flat piece across columns x0..x1: each form is linear, so one
 * exact 64-bit addition per form and pixel. */
static void render_scan_flat(render_t *r, uint16_t oi, const render_flat_t *f, int32_t x0, int32_t x1, int32_t iy,
                             uint8_t *rgb, bool lone)
{
    bool single = r->obj[oi].kind == RENDER_FLAT;
#if !FXRT_NO_SPANS
    /* Alone on the row and wide: runs located exactly, filled by words
     * (a division per form pays off from about 4 columns per form on the M3). */
    if (lone && x1 - x0 >= 4 * (1 + f->edges)) {
        render_span_flat(r, oi, f, x0, x1, iy, rgb);
        return;
    }
    /* A plane among others: its run located the same way, then each
     * column claimed (a depth, where one is needed, from the forms). */
    if (f->edges == 0 && x1 - x0 >= 8) {
        render_iv_t iv[4];
        int nrun = render_runs_flat(r, f, x0, x1, iy, iv);
        uint32_t tag = (uint32_t)r->stamp << RENDER_STAMP_SHIFT | oi;
        for (int k = 0; k < nrun; k++) {
            int32_t a = x0 + iv[k].lo, b = x0 + iv[k].hi;
            /* Columns no object has reached yet on this row: claimed and
             * filled without looking. */
            int32_t fa = a, fb = b < r->dirty_lo ? b : r->dirty_lo - 1;
            if (fa <= fb) {
                for (int32_t x = fa; x <= fb; x++)
                    r->owner[x] = tag;
                render_fill(r, oi, fa, fb, rgb);
                a = fb + 1;
            }
            fa = a > r->dirty_hi + 1 ? a : r->dirty_hi + 1;
            if (fa <= b) {
                for (int32_t x = fa; x <= b; x++)
                    r->owner[x] = tag;
                render_fill(r, oi, fa, b, rgb);
                b = fa - 1;
            }
            for (int32_t x = a; x <= b; x++)
                RENDER_COVER(r, oi, x, rgb, render_resolve(r, cur_, oi, x, iy));
        }
        return;
    }
#endif
    int32_t ix0 = 2 * x0 - r->cam->width + 1;
    uint64_t n = (uint64_t)rlin_at(&f->n, ix0, iy), d = (uint64_t)rlin_at(&f->d, ix0, iy);
    uint64_t sn = 2 * (uint64_t)f->n.x, sd = 2 * (uint64_t)f->d.x;
    int edges = f->edges;
    if (edges == 0) { /* a plane */
        for (int32_t x = x0; x <= x1; x++) {
            if (((render_k_t)n > 0 && (render_k_t)d > 0) || ((render_k_t)n < 0 && (render_k_t)d < 0)) {
                if (lone)
                    render_paint(r, oi, x, rgb);
                else
                    RENDER_COVER(r, oi, x, rgb, render_resolve_flat(r, cur_, oi, x, iy, f, (render_k_t)n, (render_k_t)d));
            }
            n += sn;
            d += sd;
        }
        return;
    }
    /* Three or four edges; a triangle's missing fourth edge is a zero form
     * (it never has a strict sign, so it changes nothing). Inside means no
     * two edges of opposite strict sign: all >= 0 (the sign bits of their
     * OR are clear) or all <= 0. */
    uint64_t e[4] = {0, 0, 0, 0}, se[4] = {0, 0, 0, 0};
    for (int k = 0; k < edges; k++) {
        const render_lin_t *ek = render_edge_k(f, k);
        e[k] = (uint64_t)rlin_at(ek, ix0, iy);
        se[k] = 2 * (uint64_t)ek->x;
    }
    for (int32_t x = x0; x <= x1; x++) {
        bool in = (render_k_t)(e[0] | e[1] | e[2] | e[3]) >= 0 ||
                  ((render_k_t)e[0] <= 0 && (render_k_t)e[1] <= 0 && (render_k_t)e[2] <= 0 && (render_k_t)e[3] <= 0);
        if (in && (((render_k_t)n > 0 && (render_k_t)d > 0) || ((render_k_t)n < 0 && (render_k_t)d < 0))) {
            if (lone)
                render_paint(r, oi, x, rgb);
            else if (single) /* a box's depth is the nearest of its faces there */
                RENDER_COVER(r, oi, x, rgb, render_resolve_flat(r, cur_, oi, x, iy, f, (render_k_t)n, (render_k_t)d));
            else
                render_cover(r, oi, x, iy, rgb);
        }
        n += sn;
        d += sd;
        e[0] += se[0];
        e[1] += se[1];
        e[2] += se[2];
        e[3] += se[3];
    }
}

/* Step a sphere, exactly: c and disc are quadratic along the row, so
 * their 128-bit forward differences (second difference constant) give
 * exactly the values render_sphere_cd computes from scratch. The test
 * c < 0 || (b > 0 && disc >= 0) splits by what is constant along the row:
 * in perspective c is, in orthographic b is, and c < 0 implies disc > 0. */
static void render_scan_sphere(render_t *r, uint16_t oi, const render_obj_t *o, int32_t x0, int32_t x1, int32_t iy,
                               uint8_t *rgb, bool lone)
{
    int32_t ix0 = 2 * x0 - r->cam->width + 1;
    fx128_t c[3], q[3];
    for (int k = 0; k < 3; k++)
        render_sphere_cd(o, ix0 + 2 * k, iy, &c[k], &q[k]);
    bool ortho = render_ortho(r->cam);
    if (!ortho && rsw_neg(c[0])) { /* eye inside: every pixel */
        for (int32_t x = x0; x <= x1; x++)
            RENDER_HIT(r, oi, x, iy, rgb, lone);
        return;
    }
    bool use_c = ortho && !(o->u.sphere->b.c > 0);
    fx128_t *f = use_c ? c : q;
    fx128_t v = f[0], d1 = fx128_sub(f[1], f[0]), d2 = fx128_add(fx128_sub(f[2], fx128_add(f[1], f[1])), f[0]);
    if (ortho) {
        /* c + disc = k + r2 along every ray (a = 1), and b is constant. */
        fx128_t kr = fx128_add(o->u.sphere->k, o->u.sphere->r2);
        render_k_t b = o->u.sphere->b.c;
        for (int32_t x = x0; x <= x1; x++, v = fx128_add(v, d1), d1 = fx128_add(d1, d2)) {
            if (!(use_c ? v.hi < 0 : v.hi >= 0))
                continue;
            if (lone)
                render_paint(r, oi, x, rgb);
            else
                RENDER_COVER(r, oi, x, rgb,
                             render_resolve_sphere(r, cur_, oi, x, iy, b, use_c ? v : fx128_sub(kr, v),
                                                   use_c ? fx128_sub(kr, v) : v));
        }
        return;
    }
    uint64_t b = (uint64_t)rlin_at(&o->u.sphere->b, ix0, iy), sb = 2 * (uint64_t)o->u.sphere->b.x;
    fx128_t k = o->u.sphere->k;
    for (int32_t x = x0; x <= x1; x++, b += sb, v = fx128_add(v, d1), d1 = fx128_add(d1, d2)) {
        if (!((render_k_t)b > 0 && v.hi >= 0))
            continue;
        if (lone)
            render_paint(r, oi, x, rgb);
        else
            RENDER_COVER(r, oi, x, rgb, render_resolve_sphere(r, cur_, oi, x, iy, (render_k_t)b, k, v));
    }
}
#endif

#if FXRT_NUMBER != FXRT_Q16 && FXRT_FLOAT_STEP && !FXRT_NO_STEP
/* FXRT_FLOAT_STEP: the float programmer's scanline. Each linear form is
 * evaluated directly at the segment's first pixel and then stepped by one
 * addition per pixel (the quadratic a by forward differences); rounding
 * accumulates along the segment, unlike the exact Q16.16 steps. */
static void render_scan_flat_f(render_t *r, uint16_t oi, const render_flat_t *f, int32_t x0, int32_t x1, int32_t iy,
                               uint8_t *rgb, bool lone)
{
    bool single = r->obj[oi].kind == RENDER_FLAT;
    int32_t ix0 = 2 * x0 - r->cam->width + 1;
    render_k_t n = rlin_at(&f->n, ix0, iy), d = rlin_at(&f->d, ix0, iy), sn = 2 * f->n.x, sd = 2 * f->d.x;
    render_k_t e[4] = {0, 0, 0, 0}, se[4] = {0, 0, 0, 0};
    int edges = f->edges;
    for (int k = 0; k < edges; k++) {
        const render_lin_t *ek = render_edge_k(f, k);
        e[k] = rlin_at(ek, ix0, iy);
        se[k] = 2 * ek->x;
    }
    for (int32_t x = x0; x <= x1; x++) {
        if (render_flat_vals(n, d, e, edges)) {
            if (lone)
                render_paint(r, oi, x, rgb);
            else if (single)
                RENDER_COVER(r, oi, x, rgb, render_resolve_flat(r, cur_, oi, x, iy, f, n, d));
            else
                render_cover(r, oi, x, iy, rgb);
        }
        n += sn;
        d += sd;
        for (int k = 0; k < edges; k++)
            e[k] += se[k];
    }
}

static void render_scan_sphere_f(render_t *r, uint16_t oi, const render_obj_t *o, int32_t x0, int32_t x1, int32_t iy,
                                 uint8_t *rgb, bool lone)
{
    const render_sphere_t *sp = o->u.sphere;
    int32_t ix0 = 2 * x0 - r->cam->width + 1;
    render_k_t b = rlin_at(&sp->b, ix0, iy), px = rlin_at(&sp->px, ix0, iy), py = rlin_at(&sp->py, ix0, iy),
         pz = rlin_at(&sp->pz, ix0, iy);
    render_k_t sb = 2 * sp->b.x, spx = 2 * sp->px.x, spy = 2 * sp->py.x, spz = 2 * sp->pz.x;
    render_k_t a0 = rquad_at(sp->a, ix0, iy), a1 = rquad_at(sp->a, ix0 + 2, iy), a2 = rquad_at(sp->a, ix0 + 4, iy);
    render_k_t a = a0, da = a1 - a0, dda = a2 - 2 * a1 + a0;
    for (int32_t x = x0; x <= x1; x++) {
        render_k_t sq = px * px + py * py + pz * pz;
        render_k_t disc = sp->r2 * (sp->ortho ? NUM_ONE : a) - sq;
        render_k_t c = sp->ortho ? sp->k + sq : sp->k;
        if (render_sphere_vals(b, c, disc)) {
            if (lone)
                render_paint(r, oi, x, rgb);
            else
                RENDER_COVER(r, oi, x, rgb, render_resolve_sphere(r, cur_, oi, x, iy, b, c, disc));
        }
        b += sb;
        px += spx;
        py += spy;
        pz += spz;
        a += da;
        da += dda;
    }
}
#endif

/* t scaled by about (1 + 2^-16) (up) or (1 - 2^-16): a margin for the
 * 24-bit truncation of depths between the ends of a segment. */
static render_depth_t render_depth_widen(render_depth_t t, bool up)
{
#if FXRT_NUMBER == FXRT_Q16
    uint32_t n = t.n;
    int e = t.e;
    if (n == 0)
        return t;
    if (up) {
        n += (n >> 16) + 1;
        if (n >= 2 * RENDER_DEPTH_ONE) {
            n >>= 1;
            e++;
        }
    } else {
        n -= (n >> 16) + 1;
        if (n < RENDER_DEPTH_ONE) {
            n <<= 1;
            e--;
        }
    }
    return render_depth_pack(n, t.d, e);
#else
    t.t = up ? t.t * NUM(1.0001) : t.t * NUM(0.9999);
    return t;
#endif
}

/* Depth range of plane p over columns x0..x1 of row iy when it covers both
 * ends with one sign of N and D: then it covers the whole segment and its
 * t = N / D is monotone there. */
static bool render_plane_range(const render_t *r, const render_obj_t *p, int32_t x0, int32_t x1, int32_t iy,
                               render_depth_t *lo, render_depth_t *hi)
{
    const render_flat_t *f = render_face(p, 0);
    int32_t w = r->cam->width;
    render_k_t na = rlin_at(&f->n, 2 * x0 - w + 1, iy), da = rlin_at(&f->d, 2 * x0 - w + 1, iy);
    render_k_t nb = rlin_at(&f->n, 2 * x1 - w + 1, iy), db = rlin_at(&f->d, 2 * x1 - w + 1, iy);
    if (!((na > 0 && da > 0 && nb > 0 && db > 0) || (na < 0 && da < 0 && nb < 0 && db < 0)))
        return false;
    render_depth_t ta = render_flat_depth(f, na, da), tb = render_flat_depth(f, nb, db);
    bool a_first = render_depth_less(ta, tb);
    *lo = render_depth_widen(a_first ? ta : tb, false);
    *hi = render_depth_widen(a_first ? tb : ta, true);
    return true;
}

static bool render_is_plane(const render_obj_t *o) { return o->kind == RENDER_FLAT && render_face(o, 0)->edges == 0; }

/* Depth order against the planes on this row, for object i over its
 * columns x0..x1: r->row_win gets bit j when i is nearer than plane j
 * wherever both cover (no depth needed there); returns false when a plane
 * covers the whole segment nearer than i (i is hidden on this row). */
static bool render_row_order(render_t *r, uint16_t i, int32_t x0, int32_t x1, int32_t iy)
{
    const render_obj_t *o = &r->obj[i];
    render_depth_t blo, bhi;
    r->row_win = 0;
    if (o->ranged) {
        blo = o->tlo;
        bhi = o->thi;
    } else if (!render_is_plane(o) || !render_plane_range(r, o, x0, x1, iy, &blo, &bhi)) {
        return true;
    }
    uint16_t n = r->nplanes < 32 ? r->nplanes : 32;
    for (uint16_t j = 0; j < n; j++) {
        render_depth_t plo, phi;
        const render_obj_t *p = &r->obj[j];
        if (j == i || p->r0 > p->r1 || !render_plane_range(r, p, x0, x1, iy, &plo, &phi))
            continue;
        if (render_depth_less(bhi, plo))
            r->row_win |= 1u << j;
        else if (render_depth_less(phi, blo))
            return false;
    }
    return true;
}

/* Is object i the only one whose bounds reach columns x0..x1 on this row?
 * Then nothing can compete for its pixels. (Only checked for small worlds;
 * a large one simply takes the owner path.) */
static bool render_alone(const render_t *r, uint16_t i, int32_t row)
{
    if (r->count > 16)
        return false;
    const render_obj_t *o = &r->obj[i];
    for (uint16_t j = 0; j < r->count; j++) {
        const render_obj_t *p = &r->obj[j];
        if (j != i && row >= p->r0 && row <= p->r1 && p->x0 <= o->x1 && p->x1 >= o->x0)
            return false;
    }
    return true;
}

void render_row(render_t *r, int32_t row, uint8_t *rgb)
{
    const cam_t *cam = r->cam;
    int32_t w = cam->width, y = cam->height - 1 - row;
    int32_t iy = 2 * y - cam->height + 1;
    render_begin_row(r, rgb);
    r->dirty_lo = (int16_t)w;
    r->dirty_hi = -1;
    for (uint16_t i = 0; i < r->count; i++) {
        const render_obj_t *o = &r->obj[i];
        if (!FXRT_NO_BOUNDS && (row < o->r0 || row > o->r1))
            continue;
        int32_t x0 = FXRT_NO_BOUNDS ? 0 : o->x0, x1 = FXRT_NO_BOUNDS ? w - 1 : o->x1;
        if (x0 > x1)
            continue;
        if (!FXRT_NO_BOUNDS && o->kind == RENDER_FLAT && render_face(o, 0)->edges == 0) {
            /* A plane: along a row its front test is one interval, so if
             * it fails at both ends the row is beyond the horizon. */
            if (!render_flat_at(render_face(o, 0), 2 * x0 - w + 1, iy) &&
                !render_flat_at(render_face(o, 0), 2 * x1 - w + 1, iy))
                continue;
        }
        bool lone = !FXRT_NO_LONE && render_alone(r, i, row);
        r->row_win = 0;
        if (!FXRT_NO_ZRANGE && !lone && r->nplanes && !render_row_order(r, i, x0, x1, iy))
            continue;
        /* After this object, columns x0..x1 may be claimed (the hull of
         * every object's columns so far on this row). */
        int32_t dlo = r->dirty_lo, dhi = r->dirty_hi;
        switch (o->kind) {
        case RENDER_ALL:
            for (int32_t x = x0; x <= x1; x++)
                RENDER_HIT(r, i, x, iy, rgb, lone);
            break;
#if FXRT_NUMBER == FXRT_Q16 && !FXRT_NO_STEP
        case RENDER_SPHERE:
            render_scan_sphere(r, i, o, x0, x1, iy, rgb, lone);
            break;
        case RENDER_FLAT:
        case RENDER_BOX:
            for (int k = 0; k < o->nflat; k++) {
                const render_flat_t *f = render_face(o, k);
                if (FXRT_NO_BOUNDS)
                    render_scan_flat(r, i, f, 0, w - 1, iy, rgb, lone);
                else if (row >= f->r0 && row <= f->r1)
                    render_scan_flat(r, i, f, f->x0, f->x1, iy, rgb, lone);
            }
            break;
#elif RENDER_STEPPED
        case RENDER_SPHERE:
            render_scan_sphere_f(r, i, o, x0, x1, iy, rgb, lone);
            break;
        case RENDER_FLAT:
        case RENDER_BOX:
            for (int k = 0; k < o->nflat; k++) {
                const render_flat_t *f = render_face(o, k);
                if (FXRT_NO_BOUNDS)
                    render_scan_flat_f(r, i, f, 0, w - 1, iy, rgb, lone);
                else if (row >= f->r0 && row <= f->r1)
                    render_scan_flat_f(r, i, f, f->x0, f->x1, iy, rgb, lone);
            }
            break;
#else
        default:
            /* Float and double (and FXRT_NO_STEP) evaluate every form directly: stepping by
             * additions would accumulate rounding error across the row. */
            for (int32_t x = x0, ix = 2 * x0 - w + 1; x <= x1; x++, ix += 2)
                if (render_covers(o, ix, iy))
                    RENDER_HIT(r, i, x, iy, rgb, lone);
            break;
#endif
        }
        r->dirty_lo = x0 < dlo ? x0 : dlo;
        r->dirty_hi = x1 > dhi ? x1 : dhi;
    }
}

/* ---- arbitrary rays ------------------------------------------------------ */

rgb8_t render_pixel(const world_t *w, const ray_t *ray)
{
    hit_t hit;
    if (world_hit(w, ray, &hit))
        return hit.obj->rgb;
    return w->background_rgb;
}
