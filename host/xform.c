/* xform: node transforms in doubles (xform.h). */
#include "xform.h"

#include <math.h>
#include <string.h>

void xform_identity(xform_t *x)
{
    memset(x, 0, sizeof *x);
    x->m[0][0] = x->m[1][1] = x->m[2][2] = 1.0;
}

void xform_scale(xform_t *x, double sx, double sy, double sz)
{
    xform_identity(x);
    x->m[0][0] = sx;
    x->m[1][1] = sy;
    x->m[2][2] = sz;
}

void xform_translate(xform_t *x, double tx, double ty, double tz)
{
    xform_identity(x);
    x->t[0] = tx;
    x->t[1] = ty;
    x->t[2] = tz;
}

void xform_rotate(xform_t *x, int axis, double deg)
{
    /* The axes after `axis` in cyclic order: rotating about z takes x to
     * y, about x takes y to z, about y takes z to x. */
    int i = (axis + 1) % 3, j = (axis + 2) % 3;
    double r = fmod(deg, 360.0), c, s;

    if (r < 0)
        r += 360.0;
    if (r == 0.0) {
        c = 1, s = 0;
    } else if (r == 90.0) {
        c = 0, s = 1;
    } else if (r == 180.0) {
        c = -1, s = 0;
    } else if (r == 270.0) {
        c = 0, s = -1;
    } else {
        double a = deg * (3.14159265358979323846 / 180.0);
        c = cos(a);
        s = sin(a);
    }
    xform_identity(x);
    x->m[i][i] = c;
    x->m[i][j] = -s;
    x->m[j][i] = s;
    x->m[j][j] = c;
}

void xform_after(xform_t *r, const xform_t *a, const xform_t *b)
{
    xform_t o;
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++)
            o.m[i][j] = a->m[i][0] * b->m[0][j] + a->m[i][1] * b->m[1][j] + a->m[i][2] * b->m[2][j];
        o.t[i] = a->m[i][0] * b->t[0] + a->m[i][1] * b->t[1] + a->m[i][2] * b->t[2] + a->t[i];
    }
    *r = o;
}

scene_vec_t xform_point(const xform_t *x, scene_vec_t p)
{
    scene_vec_t r;
    r.x = x->m[0][0] * p.x + x->m[0][1] * p.y + x->m[0][2] * p.z + x->t[0];
    r.y = x->m[1][0] * p.x + x->m[1][1] * p.y + x->m[1][2] * p.z + x->t[1];
    r.z = x->m[2][0] * p.x + x->m[2][1] * p.y + x->m[2][2] * p.z + x->t[2];
    return r;
}

scene_vec_t xform_vector(const xform_t *x, scene_vec_t v)
{
    xform_t l = *x;
    l.t[0] = l.t[1] = l.t[2] = 0.0;
    return xform_point(&l, v);
}

int xform_normal(const xform_t *x, scene_vec_t n, scene_vec_t *out)
{
    const double(*m)[3] = x->m;
    /* The inverse transpose is the cofactor matrix over the determinant. */
    double c[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            c[i][j] = m[i1][j1] * m[i2][j2] - m[i1][j2] * m[i2][j1];
        }
    double det = m[0][0] * c[0][0] + m[0][1] * c[0][1] + m[0][2] * c[0][2];
    if (det == 0.0 || !isfinite(det))
        return -1;
    scene_vec_t r;
    r.x = (c[0][0] * n.x + c[0][1] * n.y + c[0][2] * n.z) / det;
    r.y = (c[1][0] * n.x + c[1][1] * n.y + c[1][2] * n.z) / det;
    r.z = (c[2][0] * n.x + c[2][1] * n.y + c[2][2] * n.z) / det;
    double len = sqrt(r.x * r.x + r.y * r.y + r.z * r.z);
    if (!(len > 0.0) || !isfinite(len))
        return -1;
    out->x = r.x / len;
    out->y = r.y / len;
    out->z = r.z / len;
    return 0;
}

int xform_similar(const xform_t *x, double *s)
{
    double g[3][3], tr = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            g[i][j] = x->m[0][i] * x->m[0][j] + x->m[1][i] * x->m[1][j] + x->m[2][i] * x->m[2][j];
    tr = (g[0][0] + g[1][1] + g[2][2]) / 3.0;
    if (!(tr > 0.0) || !isfinite(tr))
        return 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            if (!(fabs(g[i][j] - (i == j ? tr : 0.0)) <= 1e-9 * tr))
                return 0;
    *s = sqrt(tr);
    return 1;
}

int xform_axis_aligned(const xform_t *x)
{
    double big = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            big = fmax(big, fabs(x->m[i][j]));
    if (!(big > 0.0))
        return 0;
    /* Each row and each column: exactly one entry above the tolerance. */
    for (int i = 0; i < 3; i++) {
        int in_row = 0, in_col = 0;
        for (int j = 0; j < 3; j++) {
            in_row += fabs(x->m[i][j]) > 1e-12 * big;
            in_col += fabs(x->m[j][i]) > 1e-12 * big;
        }
        if (in_row != 1 || in_col != 1)
            return 0;
    }
    return 1;
}
