/* ref_geom: the double-precision reference geometry shared by the tests
 * that check shading and tracing against an oracle written in the test
 * (tests/test_shade.c, tests/test_trace.c): an object as data, and the
 * nearest hit of a ray with its unit normal, from the textbook formulas
 * (not the core's kernels). Include after the core's headers. */
#ifndef FXRT_TESTS_REF_GEOM_H
#define FXRT_TESTS_REF_GEOM_H

#include <math.h>
#include <stdbool.h>
#include <string.h>

typedef struct {
    geom_kind_t kind;
    double p[3][3];
    double radius;
    double color[3];      /* fractions */
    int material;         /* MATERIAL_* */
    double specular[3];   /* fractions */
    int exponent;
    double reflection[3]; /* fractions */
    double index;
} obj_t;

static double dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
static void unit(double a[3])
{
    double l = sqrt(dot(a, a));
    for (int i = 0; i < 3; i++)
        a[i] /= l;
}

/* Nearest t > tmin of object o along (org, d); its outward (or stored)
 * unit normal in n. */
static bool ref_hit(const obj_t *o, const double org[3], const double d[3], double tmin, double *t, double n[3])
{
    switch (o->kind) {
    case GEOM_PLANE: {
        double nn[3] = {o->p[1][0], o->p[1][1], o->p[1][2]}, ao[3];
        unit(nn);
        for (int i = 0; i < 3; i++)
            ao[i] = o->p[0][i] - org[i];
        double den = dot(d, nn);
        if (den == 0)
            return false;
        *t = dot(ao, nn) / den;
        memcpy(n, nn, sizeof nn);
        return *t > tmin;
    }
    case GEOM_SPHERE: {
        double oc[3];
        for (int i = 0; i < 3; i++)
            oc[i] = org[i] - o->p[0][i];
        double b = dot(oc, d), c = dot(oc, oc) - o->radius * o->radius, disc = b * b - c;
        if (disc < 0)
            return false;
        double h = sqrt(disc), t0 = -b - h, t1 = -b + h;
        *t = t0 > tmin ? t0 : t1;
        if (!(*t > tmin))
            return false;
        for (int i = 0; i < 3; i++)
            n[i] = (org[i] + *t * d[i] - o->p[0][i]) / o->radius;
        return true;
    }
    case GEOM_TRIANGLE: {
        const double *a = o->p[0], *b = o->p[1], *c = o->p[2];
        double e1[3], e2[3], nn[3], pv[3], tv[3], qv[3];
        for (int i = 0; i < 3; i++) {
            e1[i] = b[i] - a[i];
            e2[i] = c[i] - a[i];
        }
        nn[0] = e1[1] * e2[2] - e1[2] * e2[1];
        nn[1] = e1[2] * e2[0] - e1[0] * e2[2];
        nn[2] = e1[0] * e2[1] - e1[1] * e2[0];
        unit(nn);
        /* Moller-Trumbore */
        pv[0] = d[1] * e2[2] - d[2] * e2[1];
        pv[1] = d[2] * e2[0] - d[0] * e2[2];
        pv[2] = d[0] * e2[1] - d[1] * e2[0];
        double det = dot(e1, pv);
        if (fabs(det) < 1e-14)
            return false;
        for (int i = 0; i < 3; i++)
            tv[i] = org[i] - a[i];
        double u = dot(tv, pv) / det;
        if (u < 0 || u > 1)
            return false;
        qv[0] = tv[1] * e1[2] - tv[2] * e1[1];
        qv[1] = tv[2] * e1[0] - tv[0] * e1[2];
        qv[2] = tv[0] * e1[1] - tv[1] * e1[0];
        double v = dot(d, qv) / det;
        if (v < 0 || u + v > 1)
            return false;
        *t = dot(e2, qv) / det;
        memcpy(n, nn, sizeof nn);
        return *t > tmin;
    }
    default: {
        double tn = -INFINITY, tf = INFINITY;
        int fn = 0, ff = 0;
        for (int i = 0; i < 3; i++) {
            if (d[i] == 0) {
                if (org[i] < o->p[0][i] || org[i] > o->p[1][i])
                    return false;
                continue;
            }
            double t1 = (o->p[0][i] - org[i]) / d[i], t2 = (o->p[1][i] - org[i]) / d[i];
            int f1 = 2 * i, f2 = 2 * i + 1;
            if (d[i] < 0) { /* by d's sign: a flat box has t1 == t2 */
                double x = t1;
                t1 = t2;
                t2 = x;
                f1 = 2 * i + 1;
                f2 = 2 * i;
            }
            if (t1 > tn) {
                tn = t1;
                fn = f1;
            }
            if (t2 < tf) {
                tf = t2;
                ff = f2;
            }
        }
        if (tn > tf || !(tf > tmin))
            return false;
        int f = tn > tmin ? fn : ff;
        *t = tn > tmin ? tn : tf;
        n[0] = n[1] = n[2] = 0;
        n[f / 2] = (f & 1) ? 1 : -1;
        return true;
    }
    }
}

/* Build numbers from doubles and back (Q16.16: rounded to 2^-16). */
static num_t N(double x)
{
#if FXRT_NUMBER == FXRT_Q16
    return (num_t)lround(x * 65536.0);
#else
    return (num_t)x;
#endif
}
static double D(num_t x)
{
#if FXRT_NUMBER == FXRT_Q16
    return (double)x / 65536.0;
#else
    return (double)x;
#endif
}
static vec3_t V(const double v[3])
{
    return vec3_make(N(v[0]), N(v[1]), N(v[2]));
}
/* The colour the scene loader stores: 255 x rounded to Q16.16. */
static double chan(double x)
{
    return round(x * 255.0 * 65536.0) / 65536.0;
}

#endif
