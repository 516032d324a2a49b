/* order: the order in which the row loop visits a frame's objects
 * (nearest first) and the row blocks' object masks. */
#include "vis/setup.h"

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
void render_order(vis_t *r)
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
void render_row_masks(vis_t *r)
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
