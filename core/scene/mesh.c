/* mesh: the closed meshes of a world's triangles (see mesh.h). */
#include <stddef.h>

#include "scene/mesh.h"

#if FXRT_NUMBER == FXRT_Q16
/* Are the three components of a difference of coordinates in
 * [-2^20, 2^20)? */
static inline bool mesh_small(int64_t x, int64_t y, int64_t z)
{
    const uint64_t lim = (uint64_t)1 << 20;
    return (uint64_t)(x + (int64_t)lim) < 2 * lim && (uint64_t)(y + (int64_t)lim) < 2 * lim &&
           (uint64_t)(z + (int64_t)lim) < 2 * lim;
}
#endif

int mesh_side(const vec3_t *a, const vec3_t *b, const vec3_t *c, const vec3_t *p, mesh_vol_t *acc, bool flat)
{
#if FXRT_NUMBER == FXRT_Q16
    int64_t ux = (int64_t)b->x - a->x, uy = (int64_t)b->y - a->y, uz = (int64_t)b->z - a->z;
    int64_t vx = (int64_t)c->x - a->x, vy = (int64_t)c->y - a->y, vz = (int64_t)c->z - a->z;
    int64_t wx = (int64_t)p->x - a->x, wy = (int64_t)p->y - a->y, wz = (int64_t)p->z - a->z;
    if (!flat && mesh_small(ux, uy, uz) && mesh_small(vx, vy, vz) && mesh_small(wx, wy, wz)) {
        /* Differences of at most 2^20 (16.0): cross products of at most
         * 2^41, d of at most 3 * 2^61, exact in 64 bits with 32-bit
         * factors. */
        int64_t cx = (int64_t)(int32_t)uy * (int32_t)vz - (int64_t)(int32_t)uz * (int32_t)vy;
        int64_t cy = (int64_t)(int32_t)uz * (int32_t)vx - (int64_t)(int32_t)ux * (int32_t)vz;
        int64_t cz = (int64_t)(int32_t)ux * (int32_t)vy - (int64_t)(int32_t)uy * (int32_t)vx;
        int64_t d = cx * wx + cy * wy + cz * wz;
        if (acc)
            *acc = fx128_add(*acc, fx128_from64(d));
        return d < 0 ? -1 : (d > 0);
    }
    int64_t cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
    fx128_t d = fx128_add(fx128_add(fx128_mul(cx, wx), fx128_mul(cy, wy)), fx128_mul(cz, wz));
    if (acc)
        *acc = fx128_add(*acc, d);
    if (flat) {
        int64_t cs = (cx < 0 ? -cx : cx) + (cy < 0 ? -cy : cy) + (cz < 0 ? -cz : cz); /* < 2^63 */
        int64_t wm = wx < 0 ? -wx : wx, t;
        t = wy < 0 ? -wy : wy;
        wm = t > wm ? t : wm;
        t = wz < 0 ? -wz : wz;
        wm = t > wm ? t : wm;
        fx128_t lim = fx128_shr128(fx128_mul(cs, wm), 13), ad = d.hi < 0 ? fx128_neg(d) : d;
        fx128_t gap = fx128_sub(lim, ad);
        if (gap.hi >= 0)
            return 0;
    }
    return d.hi < 0 ? -1 : (d.hi == 0 && d.lo == 0 ? 0 : 1);
#else
    num_t ux = b->x - a->x, uy = b->y - a->y, uz = b->z - a->z, vx = c->x - a->x, vy = c->y - a->y, vz = c->z - a->z;
    num_t wx = p->x - a->x, wy = p->y - a->y, wz = p->z - a->z;
    num_t cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
    num_t d = cx * wx + cy * wy + cz * wz;
    num_t bound = (num_abs(uy * vz) + num_abs(uz * vy)) * num_abs(wx) + (num_abs(uz * vx) + num_abs(ux * vz)) * num_abs(wy) +
                  (num_abs(ux * vy) + num_abs(uy * vx)) * num_abs(wz);
    /* 64 units of rounding (float 2^-23, double 2^-52) */
    num_t eps = sizeof(num_t) == sizeof(float) ? NUM(7.6e-6) : NUM(1.5e-14);
    if (acc)
        *acc += d;
    if (flat && num_abs(d) <= bound * NUM(1.0 / 8192))
        return 0;
    return d > bound * eps ? 1 : (d < -bound * eps ? -1 : 0);
#endif
}

static bool mesh_eq(const vec3_t *p, const vec3_t *q) { return p->x == q->x && p->y == q->y && p->z == q->z; }

/* A key that equal vertices share (and unequal ones rarely): one number
 * from the three coordinates. */
#if FXRT_NUMBER == FXRT_Q16
typedef uint32_t mesh_key_t;
static inline mesh_key_t mesh_key(const vec3_t *p) { return (uint32_t)p->x + ((uint32_t)p->y << 3) + ((uint32_t)p->z << 6); }
#else
typedef num_t mesh_key_t; /* (+0 and -0 give one key, as they compare equal) */
static inline mesh_key_t mesh_key(const vec3_t *p) { return p->x + NUM(3.0) * p->y + NUM(7.0) * p->z; }
#endif

/* The first of the triangles t..end-1 whose a or b has one of the keys
 * of a triangle's vertices (a pair with fewer has fewer than two vertices
 * in common), else end. Its own loop: few registers. */
static const geom_triangle_t *mesh_next(const geom_triangle_t *t, const geom_triangle_t *end, const mesh_key_t key[3])
{
    mesh_key_t x0 = key[0], x1 = key[1], x2 = key[2];
    for (; t < end; t++) {
        mesh_key_t y0 = mesh_key(&t->a), y1 = mesh_key(&t->b);
        if (y0 == x0 || y0 == x1 || y0 == x2 || y1 == x0 || y1 == x1 || y1 == x2)
            return t;
    }
    return end;
}

/* The root of i, halving the path on the way. */
static uint8_t mesh_find(uint8_t *up, uint8_t i)
{
    while (up[i] != i) {
        up[i] = up[up[i]];
        i = up[i];
    }
    return i;
}

static void mesh_edge(uint8_t *bits, uint16_t i)
{
    if ((bits[i] & MESH_EDGES) != MESH_EDGES)
        bits[i]++;
}

/* Edges: matched pairs join their triangles; the far vertex of each
 * neighbour tells the side of the dihedral angle. A pair shares an edge
 * only where two of their vertices are equal: the vertices' keys first
 * (most pairs share none), then the 3 x 3 vertex equalities. Each pair
 * (i, j), i < j, is looked at once, when j comes, with i's triangle
 * first, so the result is that of any order of the pairs. */
void mesh_link(const geom_triangle_t *t, uint16_t j, uint8_t *up, uint8_t *bits)
{
    static const uint8_t next[3] = {1, 2, 0};
    const geom_triangle_t *tj = &t[j];
    const vec3_t *vj[3] = {&tj->a, &tj->b, &tj->c};
    up[j] = (uint8_t)j;
    bits[j] = tj->degenerate ? MESH_BAD : 0;
    mesh_key_t key[3] = {mesh_key(&tj->a), mesh_key(&tj->b), mesh_key(&tj->c)};
    for (const geom_triangle_t *ti = mesh_next(t, tj, key); ti < tj; ti = mesh_next(ti + 1, tj, key)) {
        uint16_t i = (uint16_t)(ti - t);
        const vec3_t *vi[3] = {&ti->a, &ti->b, &ti->c};
        unsigned eq = 0, neq = 0; /* bit 3 ei + ej: vertex ei of i is vertex ej of j */
        for (int ei = 0; ei < 3; ei++)
            for (int ej = 0; ej < 3; ej++)
                if (mesh_eq(vi[ei], vj[ej])) {
                    eq |= 1u << (3 * ei + ej);
                    neq++;
                }
        if (neq < 2)
            continue;
        for (int ei = 0; ei < 3; ei++)
            for (int ej = 0; ej < 3; ej++) {
                int ei1 = next[ei], ej1 = next[ej];
                if ((eq >> (3 * ei + ej) & 1u) && (eq >> (3 * ei1 + ej1) & 1u)) {
                    bits[i] |= MESH_BAD; /* the same directed edge twice */
                    bits[j] |= MESH_BAD;
                } else if ((eq >> (3 * ei + ej1) & 1u) && (eq >> (3 * ei1 + ej) & 1u)) {
                    mesh_edge(bits, i);
                    mesh_edge(bits, j);
                    int si = mesh_side(vi[0], vi[1], vi[2], vj[next[ej1]], NULL, true);
                    int sj = mesh_side(vj[0], vj[1], vj[2], vi[next[ei1]], NULL, true);
                    bits[i] |= si > 0 ? MESH_POS : (si < 0 ? MESH_NEG : MESH_FLAT);
                    bits[j] |= sj > 0 ? MESH_POS : (sj < 0 ? MESH_NEG : MESH_FLAT);
                    up[mesh_find(up, (uint8_t)i)] = mesh_find(up, (uint8_t)j);
                }
            }
    }
}
