/* paint: the visibility pass's writes to a column: its owner and, where
 * the column's object wins, the pixel (private to vis/). */
#ifndef FXRT_VIS_PAINT_H
#define FXRT_VIS_PAINT_H

#include "vis/render_int.h"

/* Is a column with owner entry cur (tag: this row's stamp) free for any
 * newcomer: not reached yet on this row, or owned by a plane that the
 * newcomer is nearer than all along it (render_row_order)? */
static inline bool render_free(const vis_t *r, uint32_t tag, uint32_t cur)
{
    uint16_t ci = (uint16_t)cur;
    return (cur & ~0x1FFFFu) != tag || (ci < 32 && (r->row_win >> ci) & 1u);
}

/* Claim column x for object oi: free columns are taken at once, so are
 * columns owned by a plane that oi is nearer than all along this row
 * (r->row_win, render_row_order), a column owned by another object goes
 * to the nearer (RESOLVE, which may use cur_), and the pixel is painted
 * when oi wins. */
#define RENDER_COVER(r, oi, x, rgb, RESOLVE)                                         \
    do {                                                                         \
        uint32_t tag_ = (uint32_t)(r)->stamp << RENDER_STAMP_SHIFT, cur_ = (r)->owner[x]; \
        if (render_free(r, tag_, cur_))                                          \
            (r)->owner[x] = tag_ | (oi);                                         \
        else if ((uint16_t)cur_ == (oi) || !(RESOLVE))                           \
            break;                                                               \
        render_paint(r, oi, x, rgb);                                             \
    } while (0)

/* Paint column x in object oi's colour (the row's pixel format). */
#if FXRT_PIXEL == FXRT_RGB565
static inline void render_paint(vis_t *r, uint16_t oi, int32_t x, uint8_t *rgb)
{
    render_mark(r, x, oi);
    ((color_px16_t *)(void *)rgb)[x] = r->obj[oi].px;
}
#else
static inline void render_paint(vis_t *r, uint16_t oi, int32_t x, uint8_t *rgb)
{
    render_mark(r, x, oi);
    rgb8_t c = r->obj[oi].rgb;
    rgb[3 * x + 0] = c.r;
    rgb[3 * x + 1] = c.g;
    rgb[3 * x + 2] = c.b;
}
#endif

/* Record that object oi covers column x and paint it if it is the nearest
 * so far. The result does not depend on the order of calls (depth, then
 * id, order objects totally), so both loops agree. */
static inline void render_cover(vis_t *r, uint16_t oi, int32_t x, int32_t iy, uint8_t *rgb)
{
    RENDER_COVER(r, oi, x, rgb, render_resolve(r, cur_, oi, x, iy));
}

/* A hit at column x: paint directly when the object is alone on the row
 * (no other object's bounds reach it, so no bookkeeping). */
#define RENDER_HIT(r, oi, x, iy, rgb, lone)                                    \
    do {                                                                       \
        if (lone)                                                              \
            render_paint(r, oi, x, rgb);                                       \
        else                                                                   \
            render_cover(r, oi, x, iy, rgb);                                   \
    } while (0)

#endif
