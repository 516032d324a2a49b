/* render_setup: per-frame set-up of every object's camera-space coverage
 * forms, screen bounds and depth range. See render.h for the method. */
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
static rc_t rc_shl64(int64_t v, int s)
{
    rc_t r;
    r.lo = (uint64_t)v << s;
    r.hi = v >> (64 - s); /* arithmetic: the sign fills the top */
    return r;
}
RENDER_MAYBE_UNUSED __attribute__((noinline)) static rc_t rc_n(num_t a) { return rc_shl64(a, 32); }
RENDER_MAYBE_UNUSED static rc_t rc_w(numw_t w) { return rc_shl64(w, 16); }
RENDER_MAYBE_UNUSED __attribute__((noinline)) static rc_t rc_nn(num_t a, num_t b) { return rc_shl64(fx_smul32(a, b), 16); }
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

/* Bits of |coef| * mult (0 for a zero coefficient). */
static int rk_bits(const rc_t *coef, uint32_t mult)
{
    int b = fx128_bits(*coef);
    return b ? b + render_bits32(mult) : 0;
}
static int rk_max(int a, int b) { return a > b ? a : b; }
/* Smallest right shift that keeps a sum of at most 6 terms, each below
 * 2^need, below 2^target. */
static int rk_shift(int need, int target)
{
    need += 3;
    return need > target ? need - target : 0;
}
static render_k_t rk_of(const rc_t *c, int k) { return fx128_shr_round(*c, k); }
#else
static render_k_t rk_of(const rc_t *c, int k) { (void)k; return *c; }
#endif

/* The coefficients by pointer, the result into *r: on the M0 a 16-byte
 * value passed or returned by value is copied with memcpy. */
static void rlin_scaled(render_lin_t *r, const rclin_t *f, int k)
{
    r->c = rk_of(&f->c, k);
    r->x = rk_of(&f->x, k);
    r->y = rk_of(&f->y, k);
}

RENDER_MAYBE_UNUSED static void rquad_scaled(render_quad_t *r, const rcquad_t *f, int k)
{
    r->c = rk_of(&f->c, k);
    r->x = rk_of(&f->x, k);
    r->y = rk_of(&f->y, k);
    r->xx = rk_of(&f->xx, k);
    r->xy = rk_of(&f->xy, k);
    r->yy = rk_of(&f->yy, k);
}

/* Screen extents of ix and iy, for the scale bounds. */
typedef struct {
    uint32_t xm, ym;
} rext_t;

/* Smallest right shift that keeps the form's value over the screen below
 * 2^target (Q16.16; 0 in float and double). */
#if FXRT_NUMBER == FXRT_Q16
/* Bits of the largest of |c|, |x| xm and |y| ym: the linear terms. */
static int rk_lin_bits(const rc_t *c, const rc_t *x, const rc_t *y, rext_t ext)
{
    return rk_max(rk_bits(c, 1), rk_max(rk_bits(x, ext.xm), rk_bits(y, ext.ym)));
}
#endif

static int rlin_need(const rclin_t *f, rext_t ext, int target)
{
#if FXRT_NUMBER == FXRT_Q16
    return rk_shift(rk_lin_bits(&f->c, &f->x, &f->y, ext), target);
#else
    (void)f, (void)ext, (void)target;
    return 0;
#endif
}

#if FXRT_NUMBER == FXRT_Q16
RENDER_MAYBE_UNUSED static int rquad_need(const rcquad_t *f, rext_t ext, int target)
{
    int need = rk_lin_bits(&f->c, &f->x, &f->y, ext);
    need = rk_max(need, rk_max(rk_bits(&f->xx, ext.xm * ext.xm), rk_bits(&f->xy, ext.xm * ext.ym)));
    return rk_shift(rk_max(need, rk_bits(&f->yy, ext.ym * ext.ym)), target);
}
#endif

/* Linear forms get 61 bits: values, steps and sums stay inside int64. */
#define RENDER_LIN_BITS 61
/* The sphere's pieces get 62 bits; b^2 - a c is formed in 128 bits. */
#define RENDER_SPHERE_BITS 62

RENDER_MAYBE_UNUSED static void rlin_make(render_lin_t *r, const rclin_t *f, rext_t ext)
{
    rlin_scaled(r, f, rlin_need(f, ext, RENDER_LIN_BITS));
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
    rlin_scaled(&f->n, &nf, kn);
    rlin_scaled(&f->d, &df, kd);
    f->te = (int8_t)(kn - kd); /* N real = N 2^(kn - 48), D real = D 2^(kd - 48) */
    f->edges = 0;
}

/* Perspective: every ray starts at the eye, so the kernels' numerator
 * n.(A - e) (geom_flat_t, in the same numbers) is one value for the whole
 * frame: the side of the plane the eye is on. A plane through the eye (0)
 * is never hit at t > 0, whatever the direction: returns false and N is
 * set to 0, which covers no pixel. Where the camera-space rounding gave
 * N the other sign (the plane within a rounding of the eye), N takes the
 * kernels' sign at the smallest magnitude (t ~ 0). Orthographic rays
 * start on a plane: nothing to do. */
RENDER_MAYBE_UNUSED static bool render_flat_eye(const cam_t *cam, vec3_t a, vec3_t n, render_flat_t *f)
{
    if (render_ortho(cam))
        return true;
    numw_t k = vec3_dotw(vec3_sub(a, cam->e), n);
    if (k == 0) {
        f->n.c = 0;
        return false;
    }
    bool neg = k < 0;
    if (f->n.c == 0 || (f->n.c < 0) != neg) {
#if FXRT_NUMBER == FXRT_Q16
        f->n.c = neg ? -1 : 1;
#else
        f->n.c = (render_k_t)k;
        if (f->n.c == 0)
            f->n.c = (render_k_t)(neg ? -1e-30 : 1e-30);
#endif
    }
    return true;
}

/* Copy bounds to a box face. */
RENDER_MAYBE_UNUSED static void render_face_bounds_from(render_face_t *f, const render_obj_t *o)
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
RENDER_MAYBE_UNUSED static void render_edge(render_lin_t *e, const cam_t *cam, rext_t ext, vec3_t p, vec3_t q)
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
    rlin_make(e, &f, ext);
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

/* A camera-space point's projection, in pixel offsets. */
typedef struct {
    num_t ix, iy;
} rproj_t;

/* The projections of points p[idx[0..n-1]] that *have (bit i: proj[i]
 * holds p[i]'s) lacks. A quotient already taken for an earlier point of
 * the set with the same x and z (ix), or y and z (iy), is reused: a
 * sphere's bounding cube takes 8 divisions instead of 16, a box's faces
 * and outline share their corners' (a division is a few hundred
 * instructions on the M0). The same values either way. */
RENDER_MAYBE_UNUSED static void render_project(const cam_t *cam, const vec3_t *p, const uint8_t *idx, int n, rproj_t *proj,
                                               uint8_t *have)
{
    bool ortho = render_ortho(cam);
    for (int k = 0; k < n; k++) {
        int i = idx[k];
        if (*have & (1u << i))
            continue;
        bool gx = false, gy = false;
        for (int m = 0; m < k && !(gx && gy); m++) { /* the set's points before it: projected now */
            int j = idx[m];
            if (!ortho && p[j].z != p[i].z)
                continue;
            if (!gx && p[j].x == p[i].x) {
                proj[i].ix = proj[j].ix;
                gx = true;
            }
            if (!gy && p[j].y == p[i].y) {
                proj[i].iy = proj[j].iy;
                gy = true;
            }
        }
        if (ortho) {
            if (!gx)
                proj[i].ix = numw_div(numw_from(p[i].x), cam->step_u);
            if (!gy)
                proj[i].iy = numw_div(numw_from(p[i].y), cam->step_v);
        } else {
            numw_t z = numw_from(num_neg(p[i].z));
            if (!gx)
                proj[i].ix = numw_div(numw_mul(p[i].x, cam->focal), z);
            if (!gy)
                proj[i].iy = numw_div(numw_mul(p[i].y, cam->focal), z);
        }
        *have |= (uint8_t)(1u << i);
    }
}

RENDER_MAYBE_UNUSED static void render_bound_add(rbox_t *b, rproj_t q)
{
    if (!b->any) {
        b->ix0 = b->ix1 = q.ix;
        b->iy0 = b->iy1 = q.iy;
        b->any = true;
        return;
    }
    b->ix0 = num_min(b->ix0, q.ix);
    b->ix1 = num_max(b->ix1, q.ix);
    b->iy0 = num_min(b->iy0, q.iy);
    b->iy1 = num_max(b->iy1, q.iy);
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

/* Indices 0..7: a point set taken whole. */
RENDER_MAYBE_UNUSED static const uint8_t render_idx8[8] = {0, 1, 2, 3, 4, 5, 6, 7};

/* The depth range of an object inside the camera-space points p[idx[0..n-1]]: a hit
 * at camera-space z has t = -z / F (orthographic: -z), so the points' z
 * range bounds t. A margin covers the rounding of the corners and of the
 * forms, so that every depth the forms give lies strictly inside. */
RENDER_MAYBE_UNUSED static void render_set_zrange(const cam_t *cam, const vec3_t *p, const uint8_t *idx, int n,
                                                  render_obj_t *o)
{
    num_t zlo = p[idx[0]].z, zhi = p[idx[0]].z;
    for (int k = 1; k < n; k++) {
        zlo = num_min(zlo, p[idx[k]].z);
        zhi = num_max(zhi, p[idx[k]].z);
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

/* Bounds of camera-space points p[idx[0..n-1]] (at most 8, indices below
 * 8) that are all in front in perspective; straddling sets get the whole
 * screen, sets wholly behind are empty. proj and *have: the points'
 * projections so far (render_project), shared by calls on one point set. */
RENDER_MAYBE_UNUSED static void render_idx_bounds(const cam_t *cam, const vec3_t *p, const uint8_t *idx, int n,
                                                  rproj_t *proj, uint8_t *have, render_obj_t *o)
{
    int front = 0, behind = 0;
    for (int k = 0; k < n; k++) {
        if (p[idx[k]].z < NUM_ZERO)
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
    render_project(cam, p, idx, n, proj, have);
    rbox_t b = {NUM_ZERO, NUM_ZERO, NUM_ZERO, NUM_ZERO, false};
    for (int k = 0; k < n; k++)
        render_bound_add(&b, proj[idx[k]]);
    render_set_bounds(cam, &b, o);
}

/* Bounds and depth range of camera-space points p[0..n-1] (n <= 8). */
RENDER_MAYBE_UNUSED static void render_points_bounds(const cam_t *cam, const vec3_t *p, int n, render_obj_t *o)
{
    render_set_zrange(cam, p, render_idx8, n, o);
    rproj_t proj[8];
    uint8_t have = 0;
    render_idx_bounds(cam, p, render_idx8, n, proj, &have, o);
}

#if FXRT_MAX_SPHERES > 0
/* The sphere's set-up in three out-of-line steps (exact forms, their
 * scaling, the bounds), so that the stack holds one step's temporaries at
 * a time: on the Cortex-M0 the 128-bit arithmetic inlined into one
 * function took over 1 KB of stack (the micro:bit reserves little). */
#if FXRT_NUMBER == FXRT_Q16
__attribute__((noinline)) static void render_sphere_scale(vis_t *r, rext_t ext, render_sphere_t *sp, num_t rad,
                                                          rc_t r2, rc_t k, const rclin_t *b, const rclin_t *px,
                                                          const rclin_t *py, const rclin_t *pz, const rcquad_t *a)
{
    bool ortho = sp->ortho;
    /* Scales: the p pieces share kp, so disc is in units of 2^(2 kp - 96)
     * and r2 is R^2 a brought to those units; b only matters by its sign. */
    rclin_t radl = {rc_n(rad), rc_zero(), rc_zero()};
    int kp = rlin_need(px, ext, RENDER_SPHERE_BITS), n;
    n = rlin_need(b, ext, RENDER_SPHERE_BITS); /* b + sqrt(disc) is formed for depth */
    kp = kp > n ? kp : n;
    n = rlin_need(py, ext, RENDER_SPHERE_BITS);
    kp = kp > n ? kp : n;
    n = rlin_need(pz, ext, RENDER_SPHERE_BITS);
    kp = kp > n ? kp : n;
    int ka = 48; /* orthographic: a = 1 exactly */
    if (ortho) {
        n = rlin_need(&radl, ext, RENDER_SPHERE_BITS);
        kp = kp > n ? kp : n;
    } else {
        ka = rquad_need(a, ext, RENDER_SPHERE_BITS);
    }
    /* R^2 a in units of 2^(2 kp - 96): r2 = R2_48 * 2^(ka - 2 kp). In
     * perspective r2 multiplies a 64-bit a, so it must fit 62 bits too:
     * on tiny images the pieces' scales alone can leave it larger, and a
     * coarser kp (four times smaller r2 per step) fixes that. */
    int sr = 2 * kp - ka;
    sp->r2 = sr >= 0 ? fx128_shr128(r2, sr) : fx128_shl(r2, -sr);
    while (!ortho && fx128_bits(sp->r2) > RENDER_SPHERE_BITS) {
        kp++;
        sr += 2;
        sp->r2 = sr >= 0 ? fx128_shr128(r2, sr) : fx128_shl(r2, -sr);
    }
    int sk = 2 * kp - 48;
    sp->k = sk >= 0 ? fx128_shr128(k, sk) : fx128_shl(k, -sk);
    rlin_scaled(&sp->b, b, kp);
    rquad_scaled(&r->sphere_a, a, ka); /* the same for every sphere */
    sp->a = &r->sphere_a;
    /* b and sqrt(disc) are real * 2^(48 - kp), c is real * 2^(96 - 2 kp)
     * and a is real * 2^(48 - ka). */
    sp->tc = (int8_t)(kp - 48);
    sp->ta = (int8_t)(kp - ka);
    rlin_scaled(&sp->px, px, kp);
    rlin_scaled(&sp->py, py, kp);
    rlin_scaled(&sp->pz, pz, kp);
}
#endif

/* From an eye outside, every hit is a near root, on the cap of the sphere
 * that faces the eye: the points c + R m (m a unit vector) with
 * m.w >= R / L, where L = |c| and w = -c / L. Over that cap m_z lies
 * within rho w_z -+ sqrt(1 - rho^2) sqrt(1 - w_z^2) (rho = R / L; the top,
 * m_z = 1, where w_z >= rho), a tighter depth range than the bounding
 * box's z (the far half of the sphere is never seen). Only for a clear
 * margin outside (rho <= 1 - 2^-6), and widened by R / 2048 for the
 * rounding of these few operations (m_z within about 2^-13). */
static void render_sphere_cap(const cam_t *cam, vec3_t c, num_t rad, render_obj_t *o)
{
    vec3_t u;
    num_t len;
    if (render_ortho(cam) || !o->ranged || !vec3_unit_len(c, &u, &len))
        return;
    num_t rho = num_div(rad, len);
    if (rho > NUM_ONE - NUM(1.0 / 64))
        return;
    num_t wz = num_neg(u.z);
    num_t s1 = num_sqrt(num_mul(num_sub(NUM_ONE, rho), num_add(NUM_ONE, rho)));
    num_t s2 = num_sqrt(num_add(num_mul(u.x, u.x), num_mul(u.y, u.y))); /* sqrt(1 - w_z^2) */
    num_t mid = num_mul(rho, wz), half = num_mul(s1, s2);
    num_t mlo = num_sub(mid, half), mhi = wz >= rho ? NUM_ONE : num_add(mid, half);
    num_t slack = num_add(num_mul(rad, NUM(1.0 / 2048)), NUM(4.0 / 65536));
    vec3_t p[2];
    p[0] = vec3_make(NUM_ZERO, NUM_ZERO, num_min(num_add(c.z, rad), num_add(num_add(c.z, num_mul(rad, mhi)), slack)));
    p[1] = vec3_make(NUM_ZERO, NUM_ZERO, num_max(num_sub(c.z, rad), num_sub(num_add(c.z, num_mul(rad, mlo)), slack)));
    render_set_zrange(cam, p, render_idx8, 2, o);
}

__attribute__((noinline)) static void render_sphere_bounds(const cam_t *cam, vec3_t c, num_t rad, rc_t cc,
                                                           render_obj_t *o)
{
    if (!rc_is_neg(cc) && c.z >= rad) {
        render_set_empty(o); /* wholly at z >= 0: behind the eye */
        return;
    }
    if (rc_is_neg(cc)) {
        render_set_full(cam, o); /* eye inside */
        return;
    }
    vec3_t corner[8];
    for (int i = 0; i < 8; i++)
        corner[i] = vec3_make((i & 1) ? num_add(c.x, rad) : num_sub(c.x, rad),
                              (i & 2) ? num_add(c.y, rad) : num_sub(c.y, rad),
                              (i & 4) ? num_add(c.z, rad) : num_sub(c.z, rad));
    render_points_bounds(cam, corner, 8, o);
    render_sphere_cap(cam, c, rad, o);
}

__attribute__((noinline)) static void render_setup_sphere(vis_t *r, rext_t ext, const geom_sphere_t *s, render_obj_t *o)
{
    const cam_t *cam = r->cam;
    vec3_t c = render_to_cam(cam, s->center);
    num_t rad = s->radius;
    rc_t r2 = rc_w(s->radius2);
    rc_t cc = rc_sub(rc_add(rc_add(rc_nn(c.x, c.x), rc_nn(c.y, c.y)), rc_nn(c.z, c.z)), r2);
    static const rclin_t zero; /* all coefficients 0 (static: no stack copy) */
    static const rcquad_t zero_q;
    rclin_t b = zero, px = zero, py = zero, pz = zero;
    rcquad_t a = zero_q;
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
    render_sphere_scale(r, ext, o->u.sphere, rad, r2, k, &b, &px, &py, &pz, &a);
#else
    rlin_scaled(&o->u.sphere->b, &b, 0);
    rquad_scaled(&r->sphere_a, &a, 0);
    o->u.sphere->a = &r->sphere_a;
    rlin_scaled(&o->u.sphere->px, &px, 0);
    rlin_scaled(&o->u.sphere->py, &py, 0);
    rlin_scaled(&o->u.sphere->pz, &pz, 0);
    o->u.sphere->k = k;
    o->u.sphere->r2 = r2;
    o->u.sphere->tc = 0;
    o->u.sphere->ta = 0;
#endif
    render_sphere_bounds(cam, c, rad, cc, o);
}
#endif

#if FXRT_MAX_PLANES > 0
/* Does plane f cover a pixel of the row of pixel offset iy? Along a row
 * N and D are linear, so their front test (one strict sign) holds on one
 * interval of columns, which is empty when it fails at both ends. */
static bool render_plane_on_row(const cam_t *cam, const render_flat_t *f, int32_t iy)
{
    return render_flat_at(f, 1 - cam->width, iy) || render_flat_at(f, cam->width - 1, iy);
}

/* A plane's rows: those where it covers a pixel (render_plane_on_row),
 * exactly. One of N and D is constant (N in perspective, D in
 * orthographic views) and the other linear, with one slope down the rows
 * at both ends of a row, so the test holds at each end on a half-line of
 * rows pointing the same way, and on their union: a run of rows from the
 * top or the bottom, whose end a bisection finds. (A plane whose forms
 * both vary keeps every row.) */
static void render_plane_rows(const cam_t *cam, const render_flat_t *f, render_obj_t *o)
{
    if (!((f->n.x == 0 && f->n.y == 0) || (f->d.x == 0 && f->d.y == 0)))
        return;
    int32_t h = cam->height;
    bool top = render_plane_on_row(cam, f, h - 1), bottom = render_plane_on_row(cam, f, 1 - h);
    if (top && bottom)
        return;
    if (!top && !bottom) {
        render_set_empty(o);
        return;
    }
    int32_t lo = 0, hi = h - 1; /* rows: the test at lo is top's, at hi bottom's */
    while (hi - lo > 1) {
        int32_t mid = lo + (hi - lo) / 2;
        if (render_plane_on_row(cam, f, h - 1 - 2 * mid) == top)
            lo = mid;
        else
            hi = mid;
    }
    if (top)
        o->r1 = (int16_t)lo;
    else
        o->r0 = (int16_t)hi;
}

__attribute__((noinline)) static void render_setup_plane(vis_t *r, rext_t ext, const geom_plane_t *p, render_obj_t *o)
{
    o->kind = RENDER_FLAT;
    o->nflat = 1;
    render_flat_nd(r->cam, ext, render_dir_to_cam(r->cam, p->n), render_to_cam(r->cam, p->a), render_face(o, 0));
    render_set_full(r->cam, o);
    if (!render_flat_eye(r->cam, p->a, p->n, render_face(o, 0)))
        render_set_empty(o); /* the eye on the plane */
    else
        render_plane_rows(r->cam, render_face(o, 0), o); /* rows beyond the horizon left out */
}
#endif

#if FXRT_MAX_TRIANGLES > 0
__attribute__((noinline)) static void render_setup_triangle(vis_t *r, rext_t ext, const geom_triangle_t *t, render_obj_t *o)
{
    const cam_t *cam = r->cam;
    o->kind = RENDER_FLAT;
    o->nflat = 1;
#if RENDER_MESH
    if (t->degenerate || render_mesh_culled(r, o->index)) { /* culled: a back face of a closed mesh */
#else
    if (t->degenerate) {
#endif
        o->nflat = 0;
        render_set_empty(o);
        return;
    }
    vec3_t v[3] = {render_to_cam(cam, t->a), render_to_cam(cam, t->b), render_to_cam(cam, t->c)};
    render_flat_t *f = render_face(o, 0);
    render_flat_nd(cam, ext, render_dir_to_cam(cam, t->n), v[0], f);
    for (int i = 0; i < 3; i++)
        render_edge(&f->e[i], cam, ext, v[i], v[(i + 1) % 3]);
    f->edges = 3;
    render_points_bounds(cam, v, 3, o);
    if (!render_flat_eye(cam, t->a, t->n, f))
        render_set_empty(o); /* the eye in the triangle's plane */
}
#endif

#if FXRT_MAX_BOXES > 0

__attribute__((noinline)) static void render_setup_box(vis_t *r, rext_t ext, const geom_box_t *b, render_obj_t *o)
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
    unsigned used = 0; /* bit i: corner i belongs to a face set up */
    rproj_t proj[8]; /* corner i's projection, once bit i of have is set */
    uint8_t have = 0;
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
            if (!ortho && geom_axis(cam->e, axis) == geom_axis(side ? b->max : b->min, axis))
                continue; /* the eye on this face's plane: no ray crosses it at t > 0 (the
                           * kernels' rule; rays that leave the box at once miss it) */
            vec3_t nw = vec3_make(axis == 0 ? NUM_ONE : NUM_ZERO, axis == 1 ? NUM_ONE : NUM_ZERO,
                                  axis == 2 ? NUM_ONE : NUM_ZERO);
            if (side == 0)
                nw = vec3_neg(nw);
            vec3_t nc = render_dir_to_cam(cam, nw);
            if (ortho && nc.z == NUM_ZERO)
                continue; /* parallel to every ray */
            /* The face's four corners, in order around it. */
            int base = side << axis;
            uint8_t idx[4] = {(uint8_t)base, (uint8_t)(base | (1 << a1)), (uint8_t)(base | (1 << a1) | (1 << a2)),
                              (uint8_t)(base | (1 << a2))};
            for (int k = 0; k < 4; k++)
                used |= 1u << idx[k];
            if (o->u.face + o->nflat >= r->box_faces + FXRT_RENDER_BOX_FACES) {
                r->error = "more box faces than FXRT_RENDER_BOX_FACES";
                continue;
            }
            render_face_t *bf = &o->u.face[o->nflat++];
            render_flat_t *f = &bf->f;
            render_flat_nd(cam, ext, nc, corner[idx[0]], f);
            for (int k = 0; k < 4; k++)
                render_edge(k < 3 ? &f->e[k] : &bf->e4, cam, ext, corner[idx[k]], corner[idx[(k + 1) % 4]]);
            f->edges = 4;
            /* Each face gets its own bounds, so a pixel is mostly stepped
             * for one face rather than all of them; each corner is
             * projected once for the faces and the box. */
            render_obj_t tmp;
            render_idx_bounds(cam, corner, idx, 4, proj, &have, &tmp);
            render_face_bounds_from(bf, &tmp);
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
    /* Bounds and depth range of the faces set up: from outside in
     * perspective the front faces, whose corners leave out the far ones. */
    uint8_t pidx[8];
    int n = 0;
    for (int i = 0; i < 8; i++)
        if (used & (1u << i))
            pidx[n++] = (uint8_t)i;
    render_set_zrange(cam, corner, pidx, n, o);
    render_idx_bounds(cam, corner, pidx, n, proj, &have, o);
}
#endif

#if RENDER_MESH
/* ---- back faces of closed meshes ------------------------------------------
 * A ray from an eye outside a closed surface enters it before it can leave
 * it, and it leaves through the triangles that face away from the eye: a
 * triangle whose plane has the eye on its inner side is never the first
 * hit (except where it ties with the front face it meets on a silhouette
 * edge). So such triangles of a closed mesh (mesh.h; the world links them
 * as they are added) are left out of the frame: of a mesh that is closed,
 * convex, whose outside is known, and seen in perspective from outside
 * its bounding box. Both loops (fast and reference) and every number type
 * use the same objects, so they still agree. Per frame: one exact side
 * test per triangle of a closed mesh (the eye's), and a second only in a
 * mesh with an edge within mesh_side's flat margin (its volume). */

/* The side of component k's triangles (mesh.h) that the sum of the sides
 * of one of its vertices takes: -1, 0 or 1. For a closed mesh this is the
 * sign of its signed volume. */
static int render_mesh_volume(const world_t *w, uint16_t k)
{
    mesh_vol_t vol = MESH_VOL_ZERO;
    const vec3_t *ref = &w->triangles[k].a;
    for (uint16_t i = 0; i < w->n_triangles; i++) {
        const geom_triangle_t *t = &w->triangles[i];
        if (mesh_root(w->mesh_up, (uint8_t)i) == k)
            (void)mesh_side(&t->a, &t->b, &t->c, ref, &vol, false);
    }
#if FXRT_NUMBER == FXRT_Q16
    return vol.hi < 0 ? -1 : (vol.hi == 0 && vol.lo == 0 ? 0 : 1);
#else
    return vol < 0 ? -1 : (vol > 0 ? 1 : 0);
#endif
}

__attribute__((noinline)) static void render_cull_meshes(vis_t *r)
{
    const world_t *w = r->world;
    uint16_t n = w->n_triangles;
    const uint8_t *up = w->mesh_up, *bits = w->mesh_bits;
    for (uint16_t i = 0; i < (FXRT_MAX_TRIANGLES + 7) / 8; i++)
        r->mesh_culled[i] = 0;
    if (n < 4 || n > FXRT_MESH_MAX || w->mesh_n != n || render_ortho(r->cam))
        return;
    const vec3_t *e = &r->cam->e;
    for (uint16_t k = 0; k < n; k++) {
        if (up[k] != k || (bits[k] & MESH_EDGES) != 3)
            continue; /* not a root, or its own edges are not matched once each */
        /* One component: closed, convex, its outside, its bounding box. */
        bool closed = true;
        uint8_t sides = 0;
        vec3_t lo = w->triangles[k].a, hi = lo;
        for (uint16_t i = 0; i < n && closed; i++) {
            if (mesh_root(up, (uint8_t)i) != k)
                continue;
            const geom_triangle_t *t = &w->triangles[i];
            closed = (bits[i] & (MESH_EDGES | MESH_BAD)) == 3;
            sides |= bits[i] & (MESH_POS | MESH_NEG | MESH_FLAT);
            const vec3_t *v[3] = {&t->a, &t->b, &t->c};
            for (int m = 0; m < 3; m++) {
                lo = vec3_make(num_min(lo.x, v[m]->x), num_min(lo.y, v[m]->y), num_min(lo.z, v[m]->z));
                hi = vec3_make(num_max(hi.x, v[m]->x), num_max(hi.y, v[m]->y), num_max(hi.z, v[m]->z));
            }
        }
        /* The outside. Where every neighbour's far vertex lies strictly on
         * one side of each triangle's plane, that side is the inner one: the
         * mesh is the boundary of a convex body, which holds its vertices.
         * Otherwise (an edge within mesh_side's flat margin) the signed
         * volume decides: a reference point on the inner side of every face
         * of an outward-wound mesh makes the sum of sides negative. */
        int out = sides == MESH_NEG ? -1 : (sides == MESH_POS ? 1 : 0);
        if (closed && out == 0 && !(sides & MESH_POS && sides & MESH_NEG))
            out = render_mesh_volume(w, k);
        bool outside = e->x < lo.x || e->x > hi.x || e->y < lo.y || e->y > hi.y || e->z < lo.z || e->z > hi.z;
        uint8_t convex = out < 0 ? MESH_POS : MESH_NEG; /* the side no far vertex may be on */
        if (!closed || out == 0 || (sides & convex) || !outside)
            continue;
        for (uint16_t i = 0; i < n; i++) {
            if (mesh_root(up, (uint8_t)i) != k)
                continue;
            const geom_triangle_t *t = &w->triangles[i];
            if (mesh_side(&t->a, &t->b, &t->c, e, NULL, false) == out) /* the eye on its inner side */
                r->mesh_culled[i >> 3] |= (uint8_t)(1u << (i & 7));
        }
    }
}
#endif

#if FXRT_NUMBER == FXRT_Q16
/* Do N and D share one strict sign over columns x0..x1 of output rows
 * r0..r1? Both are linear in the pixel offsets, so their signs at the
 * rectangle's four corners (exact integer values) decide for every pixel
 * inside it. */
static bool render_flat_front(const cam_t *cam, const render_flat_t *f, int32_t x0, int32_t x1, int32_t r0, int32_t r1)
{
    if (FXRT_NO_BOUNDS || x0 > x1 || r0 > r1)
        return false; /* (without bounds every pixel is scanned) */
    int pos = 0, neg = 0;
    for (int k = 0; k < 4; k++) {
        int32_t ix = 2 * ((k & 1) ? x1 : x0) - cam->width + 1, iy = cam->height - 1 - 2 * ((k & 2) ? r1 : r0);
        render_k_t n = rlin_at(&f->n, ix, iy), d = rlin_at(&f->d, ix, iy);
        pos += n > 0 && d > 0;
        neg += n < 0 && d < 0;
    }
    return pos == 4 || neg == 4;
}
#endif

/* (Re)compute object i's forms and bounds from its world object. */
void render_setup_object(vis_t *r, uint16_t i)
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
    for (int k = 0; k < o->nflat && (o->kind == RENDER_FLAT || o->kind == RENDER_BOX); k++) {
        render_flat_t *f = render_face(o, k);
        f->front = false;
#if FXRT_NUMBER == FXRT_Q16
        if (o->kind == RENDER_FLAT)
            f->front = render_flat_front(cam, f, o->x0, o->x1, o->r0, o->r1);
        else
            f->front = render_flat_front(cam, f, o->u.face[k].x0, o->u.face[k].x1, o->u.face[k].r0, o->u.face[k].r1);
#endif
    }
}

/* Register an object of the world in scene-array order. */
static void render_add(vis_t *r, geom_kind_t kind, uint16_t index, const geom_common_t *c)
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
#if FXRT_MAX_LIGHTS > 0
    o->flat = c->mat.kind == MATERIAL_FLAT;
#else
    o->flat = true;
#endif
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
#if RENDER_SROWS
    if (kind == GEOM_SPHERE && index < FXRT_COHERENT_SPHERES)
        render_srow_setup(r, i);
#endif
#if RENDER_HINTS
    if (o->kind == RENDER_FLAT || o->kind == RENDER_BOX) /* row coherence's guesses: a fixed start each frame */
        for (int k = 0; k < o->nflat; k++)
            for (int j = 0; j < 6; j++)
                render_face(o, k)->hint[j] = 0;
#endif
#if RENDER_ESTEP
    /* The edges' row states (a triangle's 3, a box face's 4, a plane's
     * none), without columns yet this frame. */
    if (o->kind != RENDER_SPHERE) {
        render_estep_t *es = NULL;
        int ne = 0;
#if FXRT_MAX_TRIANGLES > 0
        if (kind == GEOM_TRIANGLE)
            es = &r->estep[3 * index], ne = 3;
#endif
#if FXRT_MAX_BOXES > 0
        if (kind == GEOM_BOX)
            es = &r->estep[3 * FXRT_MAX_TRIANGLES + 4 * r->box_used], ne = 4;
#endif
        for (int k = 0; k < o->nflat; k++, es = es ? es + ne : NULL) {
            render_face(o, k)->es = es;
            for (int j = 0; j < ne; j++) {
                es[j].iy = RENDER_ESTEP_NONE;
                es[j].dk = RENDER_ESTEP_NONE;
                es[j].next = RENDER_ESTEP_NO_ROW;
            }
        }
    }
#endif
#if FXRT_MAX_BOXES > 0
    if (kind == GEOM_BOX)
        r->box_used = (uint16_t)(r->box_used + o->nflat);
#endif
}

#if !FXRT_NO_ORDER
/* Visiting order, nearest first. The image does not depend on the order
 * in which objects claim columns (depth, then scene id, decides), but the
 * work does: an object that comes after a nearer one loses the columns
 * they share, mostly a whole stretch at a time by depth ranges, without
 * painting them; in the other order it paints them and the nearer one
 * paints them again. So the objects are sorted once per frame, stably, by
 * a key from their near depth bound (render_depth_key): the planes stay
 * first (render_row_order and row_win take objects 0 .. nplanes - 1 for
 * the planes), then objects without a depth range, then the rest,
 * nearest first. The triangles of one mesh (mesh_up: joined by shared
 * edges) share the key of their nearest one and so stay together, in
 * their scene order: a closed mesh's front faces never overlap, and
 * neighbours that come one after another find their columns free on a
 * row (render_claim_free) more often than a mesh sorted face by face.
 * Cost: a key per object and an insertion sort of the keys (a compare
 * per object where they come in order), then each record moved once,
 * along the permutation's cycles. Worlds of more than FXRT_ORDER_MAX
 * objects keep scene order (the scratch is on the stack). */
#define RENDER_ORDER_N (FXRT_RENDER_MAX_OBJECTS < FXRT_ORDER_MAX ? FXRT_RENDER_MAX_OBJECTS : FXRT_ORDER_MAX)
static void render_order(vis_t *r)
{
    int32_t key[RENDER_ORDER_N > 0 ? RENDER_ORDER_N : 1];
    uint16_t ord[RENDER_ORDER_N > 0 ? RENDER_ORDER_N : 1], n = r->count;
    if (n > RENDER_ORDER_N)
        return; /* scene order */
    for (uint16_t i = 0; i < n; i++) {
        const render_obj_t *o = &r->obj[i];
        if (i < r->nplanes)
            key[i] = INT32_MIN;
        else if (o->r0 > o->r1 || o->x0 > o->x1)
            key[i] = INT32_MAX; /* on no row: placed below */
        else
            key[i] = o->ranged ? render_depth_key(o->tlo) : INT32_MIN + 1;
    }
#if RENDER_MESH
    const world_t *w = r->world;
    if (w->mesh_n == w->n_triangles) {
        /* Objects are still in kind order here: triangle j is object
         * base + j. A mesh's key is first gathered at its root, then
         * given to every triangle of it that is on some row. */
        uint16_t base = 0;
        while (base < n && r->obj[base].geom != GEOM_TRIANGLE)
            base++;
        for (uint16_t i = base; i < base + w->n_triangles; i++) {
            uint16_t k = (uint16_t)(base + mesh_root(w->mesh_up, (uint8_t)(i - base)));
            ord[i] = k; /* (ord is free until the sort) */
            if (key[i] != INT32_MAX && key[i] < key[k])
                key[k] = key[i];
        }
        for (uint16_t i = base; i < base + w->n_triangles; i++)
            if (key[i] != INT32_MAX)
                key[i] = key[ord[i]];
    }
#endif
    /* A stable insertion sort: a compare per object where the keys are
     * already in order. Objects on no row are skipped wherever they are,
     * so each keeps its place after the objects before it (it takes the
     * largest key so far: no move). */
    bool moved = false;
    for (uint16_t i = 0; i < n; i++) {
        int32_t k = key[i] == INT32_MAX && i > 0 ? key[i - 1] : key[i];
        uint16_t j = i;
        for (; j > 0 && key[j - 1] > k; j--) {
            key[j] = key[j - 1];
            ord[j] = ord[j - 1];
        }
        moved |= j != i;
        key[j] = k;
        ord[j] = i;
    }
    if (!moved)
        return;
    /* obj[p] becomes the old obj[ord[p]]; ord[p] = p marks a place done. */
    for (uint16_t p = 0; p < n; p++) {
        if (ord[p] == p)
            continue;
        render_obj_t t = r->obj[p];
        uint16_t q = p;
        while (ord[q] != p) {
            uint16_t nx = ord[q];
            r->obj[q] = r->obj[nx];
            ord[q] = q;
            q = nx;
        }
        r->obj[q] = t;
        ord[q] = q;
    }
}
#endif

#if RENDER_ROW_MASKS
/* The row blocks' object masks (vis_t's row_mask): blocks of the
 * fewest rows, a power of two, that RENDER_ROW_BLOCKS blocks cover the
 * frame's rows with. */
static void render_row_masks(vis_t *r)
{
    uint8_t s = 0;
    while ((int32_t)RENDER_ROW_BLOCKS << s < r->cam->height)
        s++;
    r->row_shift = s;
    for (int b = 0; b < RENDER_ROW_BLOCKS; b++)
        for (int k = 0; k < (FXRT_RENDER_MAX_OBJECTS + 31) / 32; k++)
            r->row_mask[b][k] = 0;
    for (uint16_t i = 0; i < r->count; i++) {
        const render_obj_t *o = &r->obj[i];
        if (o->r0 > o->r1)
            continue; /* on no row (a culled back face, say) */
        for (int32_t b = o->r0 >> s; b <= o->r1 >> s; b++)
            r->row_mask[b][i >> 5] |= 1u << (i & 31);
    }
}
#endif

const char *render_vis_setup(vis_t *r, const world_t *w, const cam_t *cam)
{
    r->error = NULL;
    if (cam->width > FXRT_RENDER_MAX_WIDTH)
        return r->error = "image wider than FXRT_RENDER_MAX_WIDTH";
#if FXRT_MAX_BOXES > 0
    r->box_used = 0;
#endif
    r->world = w;
    r->cam = cam;
    r->count = 0;
    r->row_win = 0;
#if FXRT_NUMBER == FXRT_Q16
    r->scache = NULL;
#endif
    r->want_keys = false;
#if FXRT_MAX_SAMPLES > 1
    r->sampled = world_samples(w) > 1;
#endif
#if RENDER_VIS
    r->track = world_samples(w) > 1;
#if FXRT_MAX_LIGHTS > 0
    r->track = r->track || w->n_lit > 0;
#endif
#endif
#if FXRT_MAX_PLANES > 0
    r->nplanes = w->n_planes;
#else
    r->nplanes = 0;
#endif
    for (int32_t x = 0; x < cam->width; x++)
        r->owner[x] = 0;
    r->stamp = 0;
#if RENDER_MESH
    render_cull_meshes(r); /* before the triangles are set up: culled ones are not */
#endif
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
#if !FXRT_NO_ORDER
    render_order(r);
#endif
#if RENDER_ROW_MASKS
    render_row_masks(r);
#endif
    return r->error;
}
