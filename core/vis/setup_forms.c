/* setup_forms: what each kind's set-up (vis/setup_KIND.c) builds its forms
 * and bounds with: the exact coefficients and their scaling, camera space,
 * edge forms, projections, screen bounds and depth ranges. */
#include "vis/setup.h"

/* The coefficients by pointer, the result into *r: on the M0 a 16-byte
 * value passed or returned by value is copied with memcpy. */
void rlin_scaled(render_lin_t *r, const rclin_t *f, int k)
{
    r->c = rk_round(&f->c, k);
    r->x = rk_round(&f->x, k);
    r->y = rk_round(&f->y, k);
}

int rlin_need(const rclin_t *f, rext_t ext, int target)
{
#if FXRT_NUMBER == FXRT_Q16
    return rk_shift(rk_lin_bits(&f->c, &f->x, &f->y, ext), target);
#else
    (void)f, (void)ext, (void)target;
    return 0;
#endif
}

/* ---- set-up of each object ------------------------------------------- */

vec3_t render_turn(const cam_t *cam, vec3_t v, const vec3_t *from)
{
    vec3_t q = from ? vec3_sub(v, *from) : v;
    return vec3_make(vec3_dot(q, cam->u), vec3_dot(q, cam->v), vec3_dot(q, cam->w));
}


/* N = n.(A - o) and D = n.r for camera-space normal n and point a. */
void render_flat_nd(const cam_t *cam, rext_t ext, vec3_t n, vec3_t a, render_flat_t *f)
{
    bool ortho = render_ortho(cam);
    num_t focal = ortho ? NUM_ONE : cam->focal;
    rclin_t nf = {rc_add(rc_add(rc_mul(n.x, a.x), rc_mul(n.y, a.y)), rc_mul(n.z, a.z)),
                  ortho ? rc_mul_wide(num_neg(n.x), cam->step_u) : rc_zero(),
                  ortho ? rc_mul_wide(num_neg(n.y), cam->step_v) : rc_zero()};
    rclin_t df = {rc_mul(n.z, num_neg(focal)), ortho ? rc_zero() : rc_from_num(n.x), ortho ? rc_zero() : rc_from_num(n.y)};
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
bool render_flat_eye(const cam_t *cam, vec3_t a, vec3_t n, render_flat_t *f)
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


/* Edge form r.((P - o) x (Q - o)): which side of the plane through the ray
 * origin and the edge the ray passes. Formed with the edge in canonical
 * order and negated for the other, so that two faces sharing an edge get
 * exactly opposite forms: no ray slips between them (watertight). */
void render_edge(render_lin_t *e, const cam_t *cam, rext_t ext, vec3_t p, vec3_t q)
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
    f.c = rc_mul_wide(num_neg(focal), gz);
    if (ortho) {
        f.x = rc_mul_wide(num_sub(q.y, p.y), cam->step_u);
        f.y = rc_mul_wide(num_sub(p.x, q.x), cam->step_v);
    } else {
        f.x = rc_from_wide(gx);
        f.y = rc_from_wide(gy);
    }
    if (swap) {
        f.c = rc_neg(f.c);
        f.x = rc_neg(f.x);
        f.y = rc_neg(f.y);
    }
    rlin_make(e, &f, ext);
}

static int32_t render_floor(num_t v)
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


/* The projections of points p[idx[0..n-1]] that *have (bit i: proj[i]
 * holds p[i]'s) lacks. A quotient already taken for an earlier point of
 * the set with the same x and z (ix), or y and z (iy), is reused: a
 * sphere's bounding cube takes 8 divisions instead of 16, a box's faces
 * and outline share their corners' (a division is a few hundred
 * instructions on the M0). The same values either way. */
static void render_project(const cam_t *cam, const vec3_t *p, const uint8_t *idx, int n, rproj_t *proj,
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

static void render_bound_add(rbox_t *b, rproj_t q)
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

static int32_t render_clamp(int32_t v, int32_t lo, int32_t hi) { return v < lo ? lo : v > hi ? hi : v; }

/* floor(v / 2) for any sign. */
static int32_t render_half_floor(int32_t v) { return v >= 0 ? v / 2 : -((1 - v) / 2); }



/* Pixel rectangle of a projected bound, with a 2-pixel margin for the
 * rounding of the projection. A degenerate step (1-pixel axis) or a
 * saturated projection simply widens it to the screen. */
static void render_set_bounds(const cam_t *cam, const rbox_t *b, render_obj_t *o)
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

const uint8_t render_idx8[8] = {0, 1, 2, 3, 4, 5, 6, 7};

/* The depth range of an object inside the camera-space points p[idx[0..n-1]]: a hit
 * at camera-space z has t = -z / F (orthographic: -z), so the points' z
 * range bounds t. A margin covers the rounding of the corners and of the
 * forms, so that every depth the forms give lies strictly inside. */
void render_set_zrange(const cam_t *cam, const vec3_t *p, const uint8_t *idx, int n,
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
void render_idx_bounds(const cam_t *cam, const vec3_t *p, const uint8_t *idx, int n,
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
