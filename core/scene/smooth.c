/* smooth: triangles with a normal per vertex (smooth shading, a mesh's
 * 'shading smooth'). The visibility pass, shadows and secondary rays see
 * the flat triangle; only shading asks for the normal at the hit point
 * (light/shade.c), which interpolates the vertex normals there. */
#include "scene/kinds.h"

#if FXRT_SMOOTH
fxrt_err_t geom_smooth_check(const geom_desc_t *d)
{
    if (!d->smooth)
        return FXRT_OK;
    if (d->kind != GEOM_TRIANGLE)
        return FXRT_ERR_KIND;
    fxrt_err_t e = FXRT_OK;
    for (int k = 0; k < 3 && e == FXRT_OK; k++)
        e = geom_check_dir(d->vn[k]);
    return e;
}

void geom_smooth_set(geom_triangle_t *t, const geom_desc_t *d)
{
    t->smooth = d->smooth;
    for (int k = 0; k < 3; k++) {
        t->vn[k] = d->vn[k];
        if (d->smooth)
            (void)vec3_normalize(&t->vn[k]); /* nonzero: geom_smooth_check */
    }
}

/* Twice the signed area of (p, q, r) projected along the axis `drop`:
 * exact in Q16.16 (vec3_det2w of differences within the domain). */
static numw_t smooth_area2(vec3_t p, vec3_t q, vec3_t r, int drop)
{
    vec3_t u = vec3_sub(q, p), v = vec3_sub(r, p);
    if (drop == 0)
        return vec3_det2w(u.y, v.z, u.z, v.y);
    if (drop == 1)
        return vec3_det2w(u.z, v.x, u.x, v.z);
    return vec3_det2w(u.x, v.y, u.y, v.x);
}

bool geom_smooth_normal(const geom_triangle_t *t, vec3_t p, vec3_t *n)
{
    if (!t->smooth || t->degenerate)
        return false;
    /* The barycentric weights are ratios of areas, which a projection
     * along any axis keeps; along the normal's largest component the
     * projected triangle is largest. Each is an exact 2 x 2 determinant in
     * Q16.16; their common divisor (the whole triangle's area) is left
     * out, since the sum is normalised: only its sign is taken. */
    num_t ax = num_abs(t->n.x), ay = num_abs(t->n.y), az = num_abs(t->n.z);
    int drop = ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2;
    numw_t w[3] = {smooth_area2(p, t->b, t->c, drop), smooth_area2(p, t->c, t->a, drop),
                   smooth_area2(p, t->a, t->b, drop)};
    numw_t whole = smooth_area2(t->a, t->b, t->c, drop);
    if (whole < 0)
        for (int k = 0; k < 3; k++)
            w[k] = numw_neg_fits(w[k]);
    /* The weights to 30 significant bits (Q16.16: an integer scale; float
     * and double: as they are), then sum_k w_k n_k, exact in Q16.16. */
    int shift = numw_direction_shift(w);
    num_t s[3] = {numw_direction_part(w[0], shift), numw_direction_part(w[1], shift),
                  numw_direction_part(w[2], shift)};
    numw_t c[3];
    c[0] = numw_add_exact(numw_add_exact(numw_mul(s[0], t->vn[0].x), numw_mul(s[1], t->vn[1].x)), numw_mul(s[2], t->vn[2].x));
    c[1] = numw_add_exact(numw_add_exact(numw_mul(s[0], t->vn[0].y), numw_mul(s[1], t->vn[1].y)), numw_mul(s[2], t->vn[2].y));
    c[2] = numw_add_exact(numw_add_exact(numw_mul(s[0], t->vn[0].z), numw_mul(s[1], t->vn[1].z)), numw_mul(s[2], t->vn[2].z));
    shift = numw_direction_shift(c);
    vec3_t m = vec3_make(numw_direction_part(c[0], shift), numw_direction_part(c[1], shift),
                         numw_direction_part(c[2], shift));
    if (!vec3_normalize(&m))
        return false;
    *n = m;
    return true;
}
#endif
