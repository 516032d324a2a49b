/* meshq_gen: the inputs of the mesh-query program (firmware/meshq.c) for
 * one OBJ model: OUTDIR/mesh.c (the model as constant data, written as
 * fxrt-scenec --mesh writes it) and OUTDIR/meshq_data.h (an instance that
 * places the model 4 units wide, turned, in front of the origin, and
 * NRAYS rays in Q16.16 from viewpoints around it towards points in its
 * box, a third of them with a tmax). The same inputs go to the host build
 * and to every board, whose results must match byte for byte.
 *
 *   meshq_gen OBJ OUTDIR NRAYS [--flat] */
#include "meshbuild.h"
#include "meshemit.h"
#include "obj.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define M_PI_ 3.14159265358979323846

static uint64_t rng = 0x243F6A8885A308D3u;
static double urand(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (double)(rng >> 11) / 9007199254740992.0;
}

static int32_t q16(double x) { return (int32_t)lrint(x * 65536); }

int main(int argc, char **argv)
{
    if (argc < 4 || (argc == 5 && strcmp(argv[4], "--flat")) || argc > 5) {
        fprintf(stderr, "usage: meshq_gen OBJ OUTDIR NRAYS [--flat]\n");
        return 2;
    }
    const char *objp = argv[1], *dir = argv[2];
    int nrays = atoi(argv[3]);
    static obj_t o;
    static meshbuild_t mb;
    char err[512], path[1024];
    if (obj_load(objp, &o, err, sizeof err) || meshbuild(&o, argc == 4, &mb, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        return 2;
    }
    /* 4 units wide, turned 30 degrees about y and 10 about x, at (0.5, -0.25, -6) */
    double w = 2 * 32767 * mb.step, s = 4 / w, ay = 30 * M_PI_ / 180, ax = 10 * M_PI_ / 180;
    double ry[3][3] = {{cos(ay), 0, sin(ay)}, {0, 1, 0}, {-sin(ay), 0, cos(ay)}},
           rx[3][3] = {{1, 0, 0}, {0, cos(ax), -sin(ax)}, {0, sin(ax), cos(ax)}}, a[3][3];
    double b[3] = {0.5, -0.25, -6};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            a[i][j] = 0;
            for (int k = 0; k < 3; k++)
                a[i][j] += ry[i][k] * rx[k][j] * s;
        }
    bvh_inst_t in;
    if (meshbuild_instance(&mb, a, b, &in, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        return 2;
    }
    snprintf(path, sizeof path, "%s/mesh.c", dir);
    FILE *f = fopen(path, "w");
    if (!f || meshemit_c(f, &mb, "meshq_mesh", objp) || fclose(f)) {
        fprintf(stderr, "meshq_gen: cannot write %s\n", path);
        return 2;
    }
    snprintf(path, sizeof path, "%s/meshq_data.h", dir);
    f = fopen(path, "w");
    if (!f)
        return 2;
    fprintf(f, "/* Written by tests/meshq_gen.c from %s. */\n", objp);
    fprintf(f, "extern const fxrt_mesh_t meshq_mesh;\n#define MESHQ_RAYS %d\n#define MESHQ_TRIANGLES %u\n", nrays,
            mb.mesh.n_triangles);
    fprintf(f, "#define MESHQ_BYTES %zu\n", meshbuild_bytes(&mb));
    fprintf(f, "static const int32_t meshq_m[3][3] = {{%d, %d, %d}, {%d, %d, %d}, {%d, %d, %d}};\n", in.m[0][0],
            in.m[0][1], in.m[0][2], in.m[1][0], in.m[1][1], in.m[1][2], in.m[2][0], in.m[2][1], in.m[2][2]);
    fprintf(f, "#define MESHQ_E %d\nstatic const int32_t meshq_t[3] = {%d, %d, %d};\n", in.e, num_to_q16(in.t.x),
            num_to_q16(in.t.y), num_to_q16(in.t.z));
    fprintf(f, "static const int32_t meshq_f[3][3] = {{%d, %d, %d}, {%d, %d, %d}, {%d, %d, %d}};\n#define MESHQ_FE %d\n",
            in.f[0][0], in.f[0][1], in.f[0][2], in.f[1][0], in.f[1][1], in.f[1][2], in.f[2][0], in.f[2][1], in.f[2][2],
            in.fe);
    fprintf(f, "/* per ray: origin, unit direction, tmax (0: none), in Q16.16 */\n");
    fprintf(f, "static const int32_t meshq_rays[%d][7] = {\n", nrays);
    for (int i = 0; i < nrays; i++) {
        double e[3], g[3], d[3], l = 0;
        double r = 6 + 10 * urand(), th = 2 * M_PI_ * urand(), ph = (urand() - 0.5) * 2.4;
        e[0] = b[0] + r * cos(ph) * cos(th);
        e[1] = b[1] + r * sin(ph);
        e[2] = b[2] + r * cos(ph) * sin(th);
        for (int j = 0; j < 3; j++) {
            g[j] = b[j] + (urand() - 0.5) * 2.4;
            d[j] = g[j] - e[j];
            l += d[j] * d[j];
        }
        l = sqrt(l);
        double tmax = urand() < 1.0 / 3 ? l * (0.5 + urand()) : 0;
        fprintf(f, "    {%d, %d, %d, %d, %d, %d, %d},\n", q16(e[0]), q16(e[1]), q16(e[2]), q16(d[0] / l), q16(d[1] / l),
                q16(d[2] / l), q16(tmax));
    }
    fprintf(f, "};\n");
    if (fclose(f))
        return 2;
    meshemit_summary(stdout, &mb, objp);
    obj_free(&o);
    meshbuild_free(&mb);
    return 0;
}
