/* models: what the mesh tests share (tests/test_bvh.c, tests/test_model.c):
 * a random stream, closed models written as OBJ text (an icosphere, a
 * torus, a cube), a rotation, and the world position the queries give a
 * mesh-space point of an instance (its inverse map, inverted in double). */
#ifndef FXRT_TESTS_MODELS_H
#define FXRT_TESTS_MODELS_H

#include "check.h"
#include "scene/bvh.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FX_PI_D 3.14159265358979323846

static uint64_t rng __attribute__((unused)) = 0x9E3779B97F4A7C15u;
static inline double urand(void) { return (double)(check_rng_next(&rng) >> 11) / 9007199254740992.0; }
static inline double srand_(double a, double b) { return a + (b - a) * urand(); }

/* ---- models as OBJ text -------------------------------------------------- */

typedef struct {
    char *s;
    size_t n, cap;
} buf_t;

static inline void bprintf(buf_t *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static inline void bprintf(buf_t *b, const char *fmt, ...)
{
    va_list ap;
    if (!b->s) {
        b->cap = 4096;
        b->s = malloc(b->cap);
    }
    for (;;) {
        va_start(ap, fmt);
        int k = vsnprintf(b->s + b->n, b->cap - b->n, fmt, ap);
        va_end(ap);
        if ((size_t)k < b->cap - b->n) {
            b->n += (size_t)k;
            return;
        }
        b->cap = 2 * b->cap + 256;
        b->s = realloc(b->s, b->cap);
    }
}

/* An icosphere of 20 * 4^level triangles, radius 1 (shared vertices). */
static inline void icosphere(buf_t *b, int level, double scale)
{
    double p = (1 + sqrt(5)) / 2;
    double v[6000][3];
    int f[20 * 256][3], nv = 12, nf = 20;
    double base[12][3] = {{-1, p, 0}, {1, p, 0}, {-1, -p, 0}, {1, -p, 0}, {0, -1, p}, {0, 1, p},
                          {0, -1, -p}, {0, 1, -p}, {p, 0, -1}, {p, 0, 1}, {-p, 0, -1}, {-p, 0, 1}};
    int bf[20][3] = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                     {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                     {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
    memcpy(v, base, sizeof base);
    memcpy(f, bf, sizeof bf);
    for (int l = 0; l < level; l++) {
        int nf2 = 0;
        static int g[20 * 256][3];
        for (int i = 0; i < nf; i++) {
            int m[3];
            for (int k = 0; k < 3; k++) {
                int a = f[i][k], c = f[i][(k + 1) % 3];
                double x[3];
                for (int j = 0; j < 3; j++)
                    x[j] = (v[a][j] + v[c][j]) / 2;
                int found = -1;
                for (int q = 12; q < nv && found < 0; q++)
                    if (v[q][0] == x[0] && v[q][1] == x[1] && v[q][2] == x[2])
                        found = q;
                if (found < 0) {
                    memcpy(v[nv], x, sizeof x);
                    found = nv++;
                }
                m[k] = found;
            }
            int t4[4][3] = {{f[i][0], m[0], m[2]}, {f[i][1], m[1], m[0]}, {f[i][2], m[2], m[1]}, {m[0], m[1], m[2]}};
            memcpy(&g[nf2], t4, sizeof t4);
            nf2 += 4;
        }
        memcpy(f, g, (size_t)nf2 * sizeof f[0]);
        nf = nf2;
    }
    for (int i = 0; i < nv; i++) {
        double l = sqrt(v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2]);
        bprintf(b, "v %.17g %.17g %.17g\n", v[i][0] / l * scale, v[i][1] / l * scale, v[i][2] / l * scale);
    }
    for (int i = 0; i < nf; i++)
        bprintf(b, "f %d %d %d\n", f[i][0] + 1, f[i][1] + 1, f[i][2] + 1);
}

/* A torus: tube radius r around a circle of radius 1 in the xz plane,
 * nu x nv quads (each two triangles), closed. */
#define TORUS_R 0.35
static inline void torus(buf_t *b, int nu, int nv)
{
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            double u = 2 * FX_PI_D * i / nu, w = 2 * FX_PI_D * j / nv;
            bprintf(b, "v %.17g %.17g %.17g\n", (1 + TORUS_R * cos(w)) * cos(u), TORUS_R * sin(w),
                    (1 + TORUS_R * cos(w)) * sin(u));
        }
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            int a = i * nv + j + 1, c = ((i + 1) % nu) * nv + j + 1, d = ((i + 1) % nu) * nv + (j + 1) % nv + 1,
                e = i * nv + (j + 1) % nv + 1;
            bprintf(b, "f %d %d %d %d\n", a, e, d, c);
        }
}

static const char *const cube_obj __attribute__((unused)) = "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
                              "f 5 6 7 8\nf 2 1 4 3\nf 6 2 3 7\nf 1 5 8 4\nf 8 7 3 4\nf 1 2 6 5\n";

static inline void rot(double r[3][3], double ax, double ay, double az)
{
    double cx = cos(ax), sx = sin(ax), cy = cos(ay), sy = sin(ay), cz = cos(az), sz = sin(az);
    double x[3][3] = {{1, 0, 0}, {0, cx, -sx}, {0, sx, cx}}, y[3][3] = {{cy, 0, sy}, {0, 1, 0}, {-sy, 0, cy}},
           z[3][3] = {{cz, -sz, 0}, {sz, cz, 0}, {0, 0, 1}}, t[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            t[i][j] = 0;
            for (int k = 0; k < 3; k++)
                t[i][j] += y[i][k] * x[k][j];
        }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            r[i][j] = 0;
            for (int k = 0; k < 3; k++)
                r[i][j] += z[i][k] * t[k][j];
        }
}

/* The world point of mesh-space point q under instance in, as the queries
 * see it: the inverse of q = m 2^-e (w - T), in double. */
static inline void model_world(const bvh_inst_t *in, const double q[3], double w[3])
{
    double m[3][3], inv[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            m[i][j] = ldexp(in->m[i][j], -in->e);
    double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                 m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
            inv[i][j] = (m[i1][j1] * m[i2][j2] - m[i1][j2] * m[i2][j1]) / det;
        }
    double t[3] = {(double)num_to_q16(in->t.x) / 65536, (double)num_to_q16(in->t.y) / 65536,
                   (double)num_to_q16(in->t.z) / 65536};
    for (int i = 0; i < 3; i++)
        w[i] = t[i] + inv[i][0] * q[0] + inv[i][1] * q[1] + inv[i][2] * q[2];
}

#endif
