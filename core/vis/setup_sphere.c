/* setup_sphere: a sphere's forms (b, its offsets p, a = |r|^2, c), bounds
 * and depth range for the frame's camera. The set-up runs in three
 * out-of-line steps (exact forms, their scaling, the bounds), so that the
 * stack holds one step's temporaries at a time: on the Cortex-M0 the
 * 128-bit arithmetic inlined into one function took over 1 KB of stack
 * (the micro:bit reserves little). */
#include "vis/setup.h"

#if FXRT_MAX_SPHERES > 0
static void rquad_scaled(render_quad_t *r, const rcquad_t *f, int k)
{
    r->c = rk_round(&f->c, k);
    r->x = rk_round(&f->x, k);
    r->y = rk_round(&f->y, k);
    r->xx = rk_round(&f->xx, k);
    r->xy = rk_round(&f->xy, k);
    r->yy = rk_round(&f->yy, k);
}

#if FXRT_NUMBER == FXRT_Q16
static int rquad_need(const rcquad_t *f, rext_t ext, int target)
{
    int need = rk_lin_bits(&f->c, &f->x, &f->y, ext);
    need = rk_max(need, rk_max(rk_bits(&f->xx, ext.xm * ext.xm), rk_bits(&f->xy, ext.xm * ext.ym)));
    return rk_shift(rk_max(need, rk_bits(&f->yy, ext.ym * ext.ym)), target);
}

__attribute__((noinline)) static void render_sphere_scale(vis_t *r, rext_t ext, render_sphere_t *sp, num_t rad,
                                                          rc_t r2, rc_t k, const rclin_t *b, const rclin_t *px,
                                                          const rclin_t *py, const rclin_t *pz, const rcquad_t *a)
{
    bool ortho = sp->ortho;
    /* Scales: the p pieces share kp, so disc is in units of 2^(2 kp - 96)
     * and r2 is R^2 a brought to those units; b only matters by its sign. */
    rclin_t radl = {rc_from_num(rad), rc_zero(), rc_zero()};
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

void render_setup_sphere(vis_t *r, rext_t ext, const geom_sphere_t *s, render_obj_t *o)
{
    const cam_t *cam = r->cam;
    vec3_t c = render_to_cam(cam, s->center);
    num_t rad = s->radius;
    rc_t r2 = rc_from_wide(s->radius2);
    rc_t cc = rc_sub(rc_add(rc_add(rc_mul(c.x, c.x), rc_mul(c.y, c.y)), rc_mul(c.z, c.z)), r2);
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
        b.c = rc_from_num(num_neg(c.z));
        a.c = rc_from_num(NUM_ONE);
        px.c = rc_from_num(c.x);
        px.x = rc_neg(rc_from_wide(cam->step_u));
        py.c = rc_from_num(c.y);
        py.y = rc_neg(rc_from_wide(cam->step_v));
        k = rc_sub(rc_mul(c.z, c.z), r2);
    } else {
        /* o = 0, r = (ix, iy, -F): b = C.r, a = |r|^2, p = C x r =
         * (-cy F - cz iy, cz ix + cx F, cx iy - cy ix), c = |C|^2 - R^2. */
        num_t f = cam->focal;
        b.c = rc_mul(c.z, num_neg(f));
        b.x = rc_from_num(c.x);
        b.y = rc_from_num(c.y);
        px.c = rc_mul(c.y, num_neg(f));
        px.y = rc_from_num(num_neg(c.z));
        py.c = rc_mul(c.x, f);
        py.x = rc_from_num(c.z);
        pz.x = rc_from_num(num_neg(c.y));
        pz.y = rc_from_num(c.x);
        a.c = rc_mul(f, f);
        a.xx = rc_from_num(NUM_ONE);
        a.yy = rc_from_num(NUM_ONE);
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
