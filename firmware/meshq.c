/* meshq: mesh queries on a model in constant data (flash on a board),
 * the same program on the host and on every board (firmware/meshq.mk).
 * Its inputs come from tests/meshq_gen.c: the mesh (mesh.c), an instance
 * and MESHQ_RAYS rays (meshq_data.h). It checks the instance (bvh_check),
 * then runs every ray's nearest hit and its any-hit (below its tmax, if
 * any), and reports
 *   meshq rays=N hits=H anys=A fnv=HEX
 * where fnv is FNV-1a over every result (triangle, t, weights, any): the
 * host's and each board's must be equal. On a board it also reports the
 * ticks of each loop and of the check (instructions: firmware/meshq.sh),
 * the stack and the RAM:
 *   meshq_ticks check=T nearest=T any=T empty=T stack=B ram=B */
#include "fxrt.h"

#include "meshq_data.h"

#ifdef MESHQ_HOST
#include <stdio.h>
#define MESHQ_PUTS(s) fputs(s, stdout)
#else
#include "board.h"
#include "semihost.h"
#define MESHQ_PUTS(s) semihost_puts(s)
#endif

static uint64_t fnv = 0xcbf29ce484222325u;
static void fnv_add(uint32_t v)
{
    for (int k = 0; k < 4; k++) {
        fnv ^= (v >> (8 * k)) & 0xFFu;
        fnv *= 0x100000001b3u;
    }
}

static void put_u64(char *buf, uint64_t v)
{
    char tmp[24];
    int n = 0;
    do {
        tmp[n++] = (char)('0' + v % 10);
        v /= 10;
    } while (v);
    while (n)
        *buf++ = tmp[--n];
    *buf = 0;
}

static void say(const char *key, uint64_t v, const char *end)
{
    char num[24];
    put_u64(num, v);
    MESHQ_PUTS(key);
    MESHQ_PUTS(num);
    MESHQ_PUTS(end);
}

static ray_t meshq_ray(int i, num_t *tmax)
{
    const int32_t *r = meshq_rays[i];
    ray_t ray = {vec3_make(num_from_q16(r[0]), num_from_q16(r[1]), num_from_q16(r[2])),
                 vec3_make(num_from_q16(r[3]), num_from_q16(r[4]), num_from_q16(r[5]))};
    *tmax = r[6] ? num_from_q16(r[6]) : NUM_MAX;
    return ray;
}

/* (volatile: the loops are not merged or dropped) */
static volatile uint32_t sink;

/* A marker between the loops: make bench-mesh prices the instructions
 * between its executions (firmware/cycles.awk's segments). */
__attribute__((noinline)) void meshq_mark(void);
__attribute__((noinline)) void meshq_mark(void) { sink = sink + 1; }

int main(void)
{
    bvh_inst_t in = {&meshq_mesh, {{0}}, MESHQ_E, vec3_make(num_from_q16(meshq_t[0]), num_from_q16(meshq_t[1]), num_from_q16(meshq_t[2])),
                     {{0}}, MESHQ_FE};
    for (int j = 0; j < 3; j++)
        for (int k = 0; k < 3; k++) {
            in.m[j][k] = meshq_m[j][k];
            in.f[j][k] = meshq_f[j][k];
        }
#ifndef MESHQ_HOST
    counter_start();
    uint64_t t0 = counter_ticks();
#endif
    bool ok = bvh_check(&in);
#ifndef MESHQ_HOST
    uint64_t t1 = counter_ticks();
#endif
    if (!ok) {
        MESHQ_PUTS("meshq: bvh_check refused the mesh\n");
        return 1;
    }
    uint32_t hits = 0, anys = 0;
    meshq_mark();
    for (int i = 0; i < MESHQ_RAYS; i++) {
        num_t tmax;
        ray_t ray = meshq_ray(i, &tmax);
        bvh_hit_t h;
        bool hit = bvh_nearest(&in, &ray, tmax, BVH_NONE, &h);
        hits += hit;
        fnv_add(hit ? h.tri : 0xFFFFFFFFu);
        if (hit) {
            fnv_add((uint32_t)num_to_q16(h.t));
            for (int k = 0; k < 3; k++)
                fnv_add((uint32_t)num_to_q16(h.w[k]));
        }
    }
#ifndef MESHQ_HOST
    uint64_t t2 = counter_ticks();
#endif
    meshq_mark();
    for (int i = 0; i < MESHQ_RAYS; i++) {
        num_t tmax;
        ray_t ray = meshq_ray(i, &tmax);
        bool any = bvh_any(&in, &ray, tmax, BVH_NONE);
        anys += any;
        fnv_add(any);
    }
    meshq_mark();
#ifndef MESHQ_HOST
    uint64_t t3 = counter_ticks();
    for (int i = 0; i < MESHQ_RAYS; i++) { /* the loops' own cost: the rays alone */
        num_t tmax;
        ray_t ray = meshq_ray(i, &tmax);
        sink = sink + (uint32_t)ray.d.x + (uint32_t)tmax;
    }
    uint64_t t4 = counter_ticks();
#endif
    say("meshq rays=", MESHQ_RAYS, " ");
    say("hits=", hits, " ");
    say("anys=", anys, " fnv=");
    char hex[17];
    for (int k = 0; k < 16; k++)
        hex[k] = "0123456789abcdef"[(fnv >> (60 - 4 * k)) & 15u];
    hex[16] = 0;
    MESHQ_PUTS(hex);
    MESHQ_PUTS("\n");
#ifndef MESHQ_HOST
    say("meshq_ticks check=", t1 - t0, " ");
    say("nearest=", t2 - t1, " ");
    say("any=", t3 - t2, " ");
    say("empty=", t4 - t3, " ");
    say("stack=", board_stack_used(), " ");
    say("ram=", board_ram_static(), "\n");
    semihost_exit(0);
#endif
    return 0;
}
