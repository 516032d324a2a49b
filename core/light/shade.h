/* shade: the lighting model, per hit point (docs/ACCURACY.md
 * "Shading" has its error bound).
 *
 * With hit point p, unit normal n turned towards the incoming ray (surfaces
 * are two-sided), e = -d towards the eye, surface colour c_d (1/255 units),
 * ambient c_a, and for each light its colour c_l and the unit vector l from
 * p towards it:
 *   flat     c = c_d (lights ignored)
 *   lambert  c = c_d (.) c_a + sum over lights that reach p of
 *                c_d (.) c_l * (n . l)
 *   phong    lambert + sum over the same lights of
 *                c_s (.) c_l * max(0, r . e)^k,   r = 2 (n . l) n - l
 * A light reaches p when n . l > 0, p is inside its cone (spot: (-l) . s >=
 * cos(angle), cosines compared, no acos) and, for a light with shadows on,
 * no object is hit along the ray from p towards it with 0 < t < distance
 * (any t > 0 for a directional light; light/shadow.c). Each channel is
 * summed unclamped; color_to_rgb8 clamps and rounds. No distance
 * attenuation. The double build is the reference: this code, in doubles.
 */
#ifndef FXRT_SHADE_H
#define FXRT_SHADE_H

#include <stddef.h>

#include "scene/cam.h"
#include "scene/world.h"

/* Shadow-ray culling (FXRT_SHADOW_CULL; light/shadow.c): for each point or
 * spot light and each bounded object (slot: spheres, then triangles, then
 * boxes, by index), the cone from the light that holds every shadow ray
 * the object's exact test could find blocked. A ray towards the light
 * along ldir (unit) from a point at distance dist skips the object when
 * dist <= d_cap and either dist <= d_near (the object lies beyond the
 * point, seen from the light) or ldir . u > lim (outside the cone). An
 * entry with d_cap < 0 culls nothing. For a directional light the rays
 * are parallel: an object is skipped when the point's projection along
 * ldir falls outside the object's (two exact cross-product forms). */
#define SHADOW_SLOT_CAP(K, k, ks, cap, solid, bounded, ...) +(bounded ? cap : 0)
#define SHADOW_CULL_SLOTS (0 FXRT_KINDS(SHADOW_SLOT_CAP))
/* Each bounded kind's first slot (SHADOW_SLOT_KIND): the capacities of the
 * bounded kinds before it, by the enumeration's running count. */
#define SHADOW_SLOT_ENUM(K, k, ks, cap, solid, bounded, ...)                                                  \
    SHADOW_SLOT_##K, SHADOW_SLOT_##K##_LAST = SHADOW_SLOT_##K + (bounded ? cap : 0) - 1,
enum { FXRT_KINDS(SHADOW_SLOT_ENUM) };
#undef SHADOW_SLOT_ENUM
#define SHADOW_CULL (FXRT_SHADOWS && FXRT_SHADOW_CULL && SHADOW_CULL_SLOTS > 0)
typedef union {
    struct {
        vec3_t u;     /* unit vector from the light towards the bounding sphere's centre (Q16.16: in Q2.30) */
        num_t lim;    /* -cos of the cone's half-angle, minus the margins (Q16.16: in Q18.14, rounded up) */
        num_t d_near; /* no blocking hit for dist <= d_near */
        num_t d_cap;  /* the entry holds for dist <= d_cap (< 0: never) */
    } pt;             /* point and spot lights */
    struct {
        numw_t c1, c2; /* the centre's projections (shadow.c, shadow_proj) */
        numw_t r;      /* bounding radius with margins */
    } dir;             /* directional lights */
} shadow_cull_t;
/* Fill t->cull[light * SHADOW_CULL_SLOTS + slot] for world w (every light:
 * a point or spot light's row holds cones, a directional light's the
 * objects' projections) and t->edges. Once per frame. */
struct shadow_table;
void shadow_cull_setup(const world_t *w, struct shadow_table *t);
#if FXRT_NUMBER == FXRT_Q16
/* A point or spot light's cone test, ldir . u > lim (shadow_culled_pt,
 * light/shadow.c). Q16.16 keeps u in Q2.30 and lim in Q18.14 rounded up,
 * so that the test needs only the high word of the Q18.46 dot: with S =
 * ldir . u 2^46 exact in int64, floor(S / 2^32) > lim14 gives S / 2^46 >=
 * (lim14 + 1) 2^-14 > lim. (Rounding lim up, by at most 3 2^-16, and
 * reading only the high word, at most 2^-14, cull a little less than the
 * exact test with lim would, never more; the margins are 2^-11.) */
static inline bool shadow_cone_out64(const shadow_cull_t *e, const vec3_t *l)
{
    int64_t S = fx_smlal32(fx_smlal32(fx_smul32(l->x, e->pt.u.x), l->y, e->pt.u.y), l->z, e->pt.u.z);
    return (int32_t)(S >> 32) > e->pt.lim;
}
/* The same in 32-bit products (the M0's form; true only where the exact
 * dot is above lim14 too, which tests/test_shade.c checks on the host):
 * ldir . u from components in Q2.14 (ldir >> 2, u >> 16; |.| <= 2^14),
 * three products in Q4.28 (each at most 2^28). With x = 4a + r, y = 4b +
 * s (0 <= r, s <= 3), |xy - 16ab| = 4as + 4br + rs <= 393,225 2^-32, so
 * the three move the dot by at most 73,730 in Q4.28 (2.7e-4); the test
 * adds 2^17 (2^-11). */
static inline bool shadow_cone_out16(const shadow_cull_t *e, const vec3_t *l)
{
    int32_t dot = (l->x >> 2) * (e->pt.u.x >> 16) + (l->y >> 2) * (e->pt.u.y >> 16) + (l->z >> 2) * (e->pt.u.z >> 16);
    return dot > (int32_t)((uint32_t)e->pt.lim << 14) + (1 << 17);
}
#endif
typedef shadow_cull_t shadow_cull_row_t; /* a light's row of the table */

/* Shadow edges (light/shadow.c, shadow_edge_entry): for each point or spot
 * light and each triangle, the three planes through the light and one
 * edge each, as unit normals m facing the triangle's third vertex. A ray
 * that the exact test finds blocked meets the triangle (up to the
 * kernels' rounding) far enough from the light that ldir . m <= lim for
 * all three; a ray in the triangle's cone with ldir . m > lim for one of
 * them skips it (the cone's bounding sphere holds much more than the
 * triangle). Q16.16 keeps m and lim in Q2.14 (lim rounded up) and tests
 * in 32-bit products, adding 2^-11, as shadow_cone_out16; float and double
 * keep the values (lim with the same 2^-11). A lim of 2 or more never
 * skips. */
#define SHADOW_EDGES (SHADOW_CULL && FXRT_SHADOW_EDGES && FXRT_MAX_TRIANGLES > 0)
typedef struct {
    num_q14_t m[3][3];
    num_q14_t lim[3];
    num_q14_t cap; /* for dist < cap only (Q16.16: whole units) */
} shadow_edge_t;

/* Shadow rows (light/shadow.c, shadow_rows_setup): on an image row, the
 * points a plane shows lie on one line, and the shadow rays from them lie
 * in one plane, up to the rounding of the camera ray, the hit point and
 * the ray: through a point or spot light, or along a directional light's
 * direction. A bounded object
 * whose bounding sphere lies farther from that plane than those margins
 * blocks none of them: bit s of the row's mask (plane j, light i) skips
 * slot s's object for every pixel of plane j on the row (slots 0..30),
 * and SHADOW_ROW_CLEAR says that no object can block the light there at
 * all (every bounded object skipped, no other plane). Set per row by the
 * shading pass (frame/render_shade.c) for perspective views; zero
 * elsewhere. A mask only skips tests whose answer is "not blocked": the
 * frame is the same (tests/order.sh against FXRT_ABLATE_SHADOW_ROWS). */
#define SHADOW_ROWS (SHADOW_CULL && FXRT_MAX_PLANES > 0 && !FXRT_NO_SHADOW_ROWS)
#define SHADOW_ROW_SLOTS 31
#define SHADOW_ROW_CLEAR 0x80000000u
/* The frame's tables hold the planes' heights (shade_plane_heights). */
#define SHADE_HEIGHTS (SHADOW_CULL && FXRT_MAX_PLANES > 0)
/* What a Lambert plane's light sum keeps per light (shade_plane_height):
 * for a point or spot light its height h = n . (L - a) over the plane;
 * for a directional light n . l itself, which is the same at every point. */
typedef union {
    numw_mant_t h;
    numw_sticky_t ndl;
} shade_height_t;
/* What the frame keeps per plane and light, side by side, so that one
 * pointer finds a plane's (shade_flat_t): the current row's mask (row,
 * where SHADOW_ROWS; else 0) and the height (h, shade_plane_height, once
 * per frame: shade_plane_heights). */
typedef struct {
    uint32_t row;
    shade_height_t h;
} shade_plane_light_t;
/* The frame's shadow-ray tables: the cull table, and per plane and light
 * (pl[plane * FXRT_MAX_LIGHTS + light]) the row's mask and the height. */
typedef struct shadow_table {
    shadow_cull_t cull[SHADOW_CULL ? FXRT_MAX_LIGHTS * SHADOW_CULL_SLOTS : 1];
    shade_plane_light_t pl[SHADE_HEIGHTS ? FXRT_MAX_PLANES * FXRT_MAX_LIGHTS : 1];
    /* edges[light * FXRT_MAX_TRIANGLES + triangle] (shadow edges above);
     * none at all without them (a GNU zero-length array, last: a scene
     * that cannot use them pays no byte, not even an element's padding) */
    __extension__ shadow_edge_t edges[SHADOW_EDGES ? FXRT_MAX_LIGHTS * FXRT_MAX_TRIANGLES : 0];
} shadow_table_t;
/* The masks of image row y (counted from the bottom) of a perspective
 * camera cam, for every plane and light of w; all zero for another view.
 * shadow_rows_clear zeroes them. */
void shadow_rows_setup(const world_t *w, const cam_t *cam, int32_t y, shadow_table_t *t);
void shadow_rows_clear(shadow_table_t *t);
/* A Lambert plane's light sum takes n . l = h / |L - p|, with
 * h = n . (L - a) from shade_plane_height (light/shade.c), or, for a
 * directional light, n . l as it is; the frame's tables keep them per
 * plane and light (shade_plane_heights, at set-up). */
shade_height_t shade_plane_height(const world_t *w, uint16_t index, const light_t *L);
void shade_plane_heights(const world_t *w, shadow_table_t *t);

/* What the light sum needs of one object that does not change within a
 * frame, computed once per frame and object (render_setup) instead of at
 * every pixel: the ambient term c_d (.) c_a and, per light, the diffuse
 * colour c_d (.) c_l and the specular colour c_s (.) c_l in 1/255 units. */
typedef struct {
    color_t ambient;
    color_t kd[FXRT_MAX_LIGHTS > 0 ? FXRT_MAX_LIGHTS : 1];
#if FXRT_PHONG
    color_t ks[FXRT_MAX_LIGHTS];
#endif
#if SHADOW_CULL
    const shadow_table_t *cull; /* the frame's shadow-ray tables (NULL: none) */
/* SHADE_IF_CULL(...): its arguments where the field above exists. */
#define SHADE_IF_CULL(...) __VA_ARGS__
#else
#define SHADE_IF_CULL(...)
#endif
} shade_k_t;

/* Fill k for object obj of world w (k->cull: NULL). */
void shade_consts(const world_t *w, const geom_common_t *obj, shade_k_t *k);

/* The colour (1/255 units, unclamped) of object `index` of `kind` seen
 * along `ray` (a camera ray: d unit, not a bounce ray's), which the
 * caller has found to meet it (the renderer's visibility pass, or
 * world_hit): the hit point and normal come from the
 * object's geom_<kind>_surface (a model's walks its tree again;
 * shade_model_k below takes the triangle met), the light sum from
 * shade_point. With cam not NULL, ray is cam's ray as cam_ray_raw makes
 * it (d not yet normalised), and cam_ray_unit normalises it here, in
 * place, where it is needed: an object of a FLAT form whose light sum
 * needs no unit direction takes its hit point from the raw direction
 * (light/hit.c, shade_flat_point). With cam NULL, ray->d is unit (any
 * ray). When mask
 * is not NULL it receives the lights that reach the hit point (bit i for
 * light i), also for a flat material; without it a flat object costs
 * nothing but its colour. */
color_t shade_object(const world_t *w, geom_kind_t kind, uint16_t index, ray_t *ray, const cam_t *cam,
                     uint8_t *mask);
/* The same with the object's per-frame constants (NULL: computed here). */
color_t shade_object_k(const world_t *w, geom_kind_t kind, uint16_t index, ray_t *ray, const cam_t *cam,
                       const shade_k_t *k, uint8_t *mask);

/* An object of a FLAT form (scene/kinds.h: a plane, a triangle) seen
 * from o: its common part, unit normal n, and geom_flat_num(a, n, o) of
 * its plane's point a, prepared for division (num) and for a ratio
 * (ratio), which the shading pass keeps while the object and o stay the
 * same. shade_flat_k is shade_object_k for it along a pinhole camera's
 * ray from o, given as cam_ray_raw makes it (d not normalised): the same
 * value, without the numerator's products. */
typedef struct {
    numw_dividend_t num;
    numw_ratio_num_t ratio;
    const geom_common_t *obj;
    const vec3_t *n;
    uint16_t index;
    uint8_t kind;
    /* A plane with constants (shade_flat_prep): pls points to its entries
     * of the frame's tables (NULL: the frame keeps none), and flags has
     * SHADE_FLAT_LAMBERT for a Lambert plane, which the shading pass
     * takes to shade_flat_plane (shade_flat_k's value), and
     * SHADE_FLAT_DIRECTIONAL when every light of the world is
     * directional, SHADE_FLAT_SPOTS for a Lambert or Phong plane when
     * every light is a spot (shade_flat_spot_blocks), and
     * SHADE_FLAT_PHONG_DIR for a Phong plane (in Q16.16 of exponent k >
     * 12) when every light is directional (shade_flat_phong_span), and
     * SHADE_FLAT_PHONG_POINT for a Phong plane when no light is
     * directional (shade_flat_phong_blocks). */
    uint8_t flags;
    const shade_plane_light_t *pls;
} shade_flat_t;
enum {
    SHADE_FLAT_LAMBERT = 1,
    SHADE_FLAT_DIRECTIONAL = 2,
    SHADE_FLAT_SPOTS = 4,
    SHADE_FLAT_PHONG_DIR = 8,
    SHADE_FLAT_PHONG_POINT = 16
};
color_t shade_flat_k(const world_t *w, const shade_flat_t *f, ray_t *ray, const shade_k_t *k, uint8_t *mask);
/* Set f->flags and f->pls for f's object with constants k (NULL: none);
 * all_directional, all_spots: every light of the world is directional, or
 * a spot, and there is one; no_directional: no light is directional (the
 * shading pass finds them once per frame). */
void shade_flat_prep(shade_flat_t *f, bool all_directional, bool all_spots, bool no_directional, const shade_k_t *k);
/* shade_flat_k's value for a Lambert plane (SHADE_FLAT_LAMBERT, k its constants)
 * along a camera ray: its hit point, then shade_lights_plane's light sum
 * (and mask), with what the light sum needs of the frame found once per
 * plane (shade_flat_prep) instead of at every pixel. Under directional
 * lights only, where no light needs a shadow ray on this row (each has
 * shadows off, its row mask SHADOW_ROW_CLEAR, or lies behind the side
 * seen: light/shade_sum.h, shade_plane_row_unshadowed), nothing in the
 * sum depends on the point, and shade_flat_plane_dir makes no hit point. */
color_t shade_flat_plane(const world_t *w, const shade_flat_t *f, const shade_k_t *k, const ray_t *ray,
                         uint8_t *mask);
/* shade_flat_plane's value for a plane with SHADE_FLAT_DIRECTIONAL too:
 * without a hit point where no light needs a shadow ray on this row, else
 * shade_flat_plane's own (a tail call: no frame deeper). */
color_t shade_flat_plane_dir(const world_t *w, const shade_flat_t *f, const shade_k_t *k, const ray_t *ray,
                             uint8_t *mask);

/* The pixels x .. end - 1 of a direct row (cam_row_t) that all show the
 * Lambert plane f, with constants k, in a frame without keys: each
 * pixel's camera ray from ray->o along cam_row_dir(row, u, fwd,
 * 2 x - width + 1) (left in *ray), its colour shade_flat_plane's (or
 * shade_flat_plane_dir's, by f->flags), written to pixel x of the row
 * rgb (color_put_pixel). The same values as one call per pixel; one call
 * per run of pixels keeps f's and k's values, and the loop's, in
 * registers. */
void shade_flat_plane_run(const world_t *w, const shade_flat_t *f, const shade_k_t *k, const cam_row_t *row,
                          const vec3_t *u, const vec3_t *fwd, int32_t width, int32_t x, int32_t end, ray_t *ray,
                          uint8_t *rgb);
/* For a plane with SHADE_FLAT_PHONG_DIR, from column x of a run that ends
 * before end, as shade_flat_spot_blocks: where the run keeps one side and
 * no light needs a shadow ray on the row, writes the diffuse sum's colour
 * (made once; shade_flat_k's value there) to the leading pixels whose
 * specular terms are all surely 0 (Q16.16: numw_pow_zero_at, stepped
 * exactly along the run; float and double: r . e < 0 surely), and
 * returns the first column not written; the caller shades it and the
 * columns after it up to *stop (where the terms are 0 again) with
 * shade_flat_k, and calls again from *stop while it is below end. The
 * caller's deep calls run outside this frame (the M0's 2 KB stack). */
int32_t shade_flat_phong_span(const world_t *w, const shade_flat_t *f, const shade_k_t *k, const cam_row_t *row,
                              const vec3_t *u, const vec3_t *fwd, int32_t width, int32_t x, int32_t end, ray_t *ray,
                              uint8_t *rgb, int32_t *stop);
/* For a plane with SHADE_FLAT_SPOTS, from column x of a run that ends
 * before end: writes the ambient term, the light sum's value there, to
 * the leading blocks of SHADE_SPOT_BLOCK pixels that no spot reaches
 * (shade_spot_block_out), and returns the first column not written; the
 * caller shades that column's block, up to *stop, pixel by pixel
 * (shade_flat_plane_run's or shade_flat_k's values), and calls again from
 * *stop while it is below end. */
int32_t shade_flat_spot_blocks(const world_t *w, const shade_flat_t *f, const shade_k_t *k, const cam_row_t *row,
                               const vec3_t *u, const vec3_t *fwd, int32_t width, int32_t x, int32_t end, ray_t *ray,
                               uint8_t *rgb, int32_t *stop);

/* For a plane with SHADE_FLAT_PHONG_POINT (a Phong plane under point and
 * spot lights), from column x of a run that ends before end, in blocks
 * of SHADE_SPOT_BLOCK pixels: writes the ambient term to the leading
 * blocks that no light reaches (shade_spot_block_out, as
 * shade_flat_spot_blocks), then returns the first column not written and
 * in *stop the end of the blocks that follow it of one kind: with
 * *lambert, blocks where every light's specular term is surely 0
 * (shade_phong_block_zero), which the caller shades with
 * shade_flat_plane_pixels (the Lambert sum, the same value); without,
 * blocks that need the term, which it shades pixel by pixel
 * (shade_flat_k). The caller calls again from *stop while it is below
 * end; the deep calls run outside this frame (the M0's 2 KB stack). */
int32_t shade_flat_phong_blocks(const world_t *w, const shade_flat_t *f, const shade_k_t *k, const cam_row_t *row,
                                const vec3_t *u, const vec3_t *fwd, int32_t width, int32_t x, int32_t end, ray_t *ray,
                                uint8_t *rgb, int32_t *stop, bool *lambert);
/* Pixels x .. end - 1 of a run on plane f, each with the Lambert light sum
 * of shade_flat_plane (no specular term), written as
 * shade_flat_plane_run writes them. */
void shade_flat_plane_pixels(const world_t *w, const shade_flat_t *f, const shade_k_t *k, const cam_row_t *row,
                             const vec3_t *u, const vec3_t *fwd, int32_t width, int32_t x, int32_t end, ray_t *ray,
                             uint8_t *rgb);

/* A camera ray's point on the plane of a FLAT form's object with unit
 * normal n, from the ray's origin o and its direction r of any length
 * (cam_ray_raw's, not normalised): o + (num / (r . n)) r with num =
 * (a - o) . n prepared as a ratio (geom_flat_num); *rn gets r . n. Without
 * the unit direction's rounding (its 0.5 LSB per component, times t) the
 * point is within 0.5 LSB + 2^-29 |p - o| per component in Q16.16. */
static inline __attribute__((always_inline)) vec3_t shade_flat_point(const numw_ratio_num_t *num, const vec3_t *o,
                                                                     const vec3_t *r, const vec3_t *n, numw_t *rn)
{
    *rn = vec3_dotw_unit(*r, *n);
    numw_ratio_t q = numw_ratio_by(num, *rn);
    return vec3_add(*o, vec3_make(num_ratio_mul(&q, r->x), num_ratio_mul(&q, r->y), num_ratio_mul(&q, r->z)));
}


/* shade_object_k for model `index` along a camera ray whose nearest
 * triangle tri is known (the visibility pass found it): that triangle is
 * intersected alone, the same t and weights as the walk's. */
color_t shade_model_k(const world_t *w, uint16_t index, const ray_t *ray, uint32_t tri, const shade_k_t *k,
                      uint8_t *mask);

/* The light sum at hit point p of object (kind, index) with geometric unit
 * normal n_geo (not yet turned) for a ray of unit direction d; part, where
 * models are compiled in: the part of a model met (NULL for other kinds). */
color_t shade_point(const world_t *w, geom_kind_t kind, uint16_t index GEOM_PART_PARAM, vec3_t p, vec3_t n_geo,
                    vec3_t d, uint8_t *mask);
color_t shade_point_k(const world_t *w, geom_kind_t kind, uint16_t index GEOM_PART_PARAM, vec3_t p, vec3_t n_geo,
                      vec3_t d, const shade_k_t *k, uint8_t *mask);

/* Shadow ray (FXRT_SHADOWS 1): is light `l`, in unit direction ldir at
 * distance dist (NUM_MAX for a directional light) from p, blocked? p lies
 * on object (kind, index), seen from its back (inside) or front.
 * Self-shadowing policy (no offset, no epsilon): every primitive is
 * convex, so a ray leaving its surface towards the side the normal faces
 * never meets it again, except a solid (sphere, box) seen from inside,
 * where the ray crosses the interior and leaves it: that object then
 * blocks the light exactly when the light is outside it (always for a
 * directional light). Every other object is tested with the world-space
 * kernels, t limited to (0, dist), stopping at the first hit. */
/* A model is not convex: a ray from its surface leaves out only the
 * triangle it starts on (part), and tests the model's others with its
 * other objects (self-shadowing). obj: world_common(w, kind, index).
 * cull: the light's row of the cull table, or NULL (no culling). */
/* skip: the row's mask for (plane, light) (shadow rows above), or 0.
 * edges: with cull, the light's row of the shadow edges (or NULL). */
bool shadow_blocked(const world_t *w, geom_kind_t kind, uint16_t index GEOM_PART_PARAM, const geom_common_t *obj,
                    bool inside, const vec3_t *p, const light_t *l, const vec3_t *ldir, num_t dist, const shadow_cull_row_t *cull,
                    uint32_t skip, const shadow_edge_t *edges);

/* Q16.16: a point or spot light at a distance of at least SHADE_FAR_DIST
 * from p may lie beyond the range (shade_lights computes |v| within 0.5
 * LSB + 2^-24 relative, so |v| >= 32768 gives at least 129 LSB below
 * NUM_MAX). shadow_blocked then casts the ray from the light towards p,
 * t in (0, NUM_MAX - 1): every bounded object is within 32,474 of a light
 * in the domain, so no occluder between them is missed but a plane met
 * beyond 32767 from the light (a far hit, docs/ACCURACY.md). */
#define SHADE_FAR_DIST (NUM_MAX - 256)

/* The light sum's side of a hit (light/shade_sum.h, `facing`): whether
 * the geometric normal faces away from the ray (d . n_geo > 0: 1) or not
 * (0), where the caller has d . n_geo already (a flat object's hit
 * divisor); SHADE_FACING_UNKNOWN: the light sum computes it. Or'ed with
 * SHADE_FACING_RAW where d is a camera ray's raw direction (the object's
 * light sum needs no unit direction, shade_needs_unit): in Q16.16 a
 * Phong term then takes r . e from it as it is (light/shade.c,
 * shade_specular). */
#define SHADE_FACING_UNKNOWN (-1)
#define SHADE_FACING_RAW 2
/* Is the point p surely outside spot light L's cone (v = L's position -
 * p)? A cheap exact test that the light loop makes before normalising v:
 * true only where the cone test with v's normalised length would reject
 * p too, so it changes no frame (tests/test_shade.c checks this near the
 * cone's edge). False for |v_i| >= 16384 (the full test decides). */
bool shade_spot_surely_out(const light_t *L, vec3_t v);
/* The pixels of a block of a plane's run under spots only
 * (shade_flat_spot_blocks; 12 took the fewest instructions of 4 to 24 on
 * the course's spot scenes). */
#define SHADE_SPOT_BLOCK 12
/* Does spot L reach no pixel of a block of a plane's run, whose exact hit
 * points lie on the segment between those of pa's and pb's pixels (pa, pb
 * as shade_flat_point gives them, from eye o; slack, in num units, the
 * pixels' own hit points' error beyond shade_flat_point's: 0 for a Lambert
 * plane and for a Phong one in Q16.16, negative for none)? True only where the light sum's own cone
 * test would reject every pixel of the block; false where it cannot show
 * that, near the cone's edge or far away. The proof is in light/shade.c. */
bool shade_spot_block_out(const light_t *L, const vec3_t *o, const vec3_t *pa, const vec3_t *pb, num_t slack);

#endif
