/* render: the visibility pass of the scanline renderer (primary rays):
 * its per-frame records and state (vis_t) and its entry points.
 *
 * Whether the ray through pixel offsets (ix, iy) hits an object is the
 * sign of a few polynomials of degree <= 2 in (ix, iy) (a sphere's b, c
 * and disc; a flat piece's N, D and edge forms), set up once per frame
 * (render_vis_setup); depth is the camera-space ray parameter t formed from
 * the same forms (flat N / D, sphere c / (b + sqrt(disc))), compared
 * exactly in Q16.16, ties to the lower scene id. In Q16.16 the forms'
 * coefficients are integers, so stepping along a row is exact and the fast
 * loop is byte-identical to the reference loop (render_row_reference_vis).
 * docs/ARCHITECTURE.md, "The visibility pass in one page", has the method;
 * docs/RENDERER.md the details and their measurements. */
#ifndef FXRT_RENDER_H
#define FXRT_RENDER_H

#include "scene/cam.h"
#include "scene/world.h"

/* The number types of the forms: a coefficient (render_k_t), a sphere's
 * k and r2 (render_k2_t), and a depth (render_depth_t: Q16.16 keeps t = n
 * / d * 2^e with n, d in [2^23, 2^24) (n = 0: t = 0), in 8 bytes: n in
 * bits 0-23, e (signed) in bits 24-31, d in bits 32-55 (vis/depth.c packs
 * and reads them); an integer rather than a struct: the M0's compiler
 * copies an 8-byte struct with a memcpy call). */
#if FXRT_NUMBER == FXRT_Q16
typedef int64_t render_k_t; /* a scaled integer */
typedef fx128_t render_k2_t;
typedef uint64_t render_depth_t;
#else
typedef num_t render_k_t;
typedef num_t render_k2_t;
typedef struct {
    num_t t;
} render_depth_t;
#endif

/* c + x ix + y iy */
typedef struct {
    render_k_t c, x, y;
} render_lin_t;

/* c + x ix + y iy + xx ix^2 + xy ix iy + yy iy^2 (in this order: x, xx
 * and xy are the linear form x + xx ix + xy iy, rquad_at's first step) */
typedef struct {
    render_k_t x, xx, xy, y, yy, c;
} render_quad_t;

/* Row coherence (the fast Q16.16 loop, with spans, lone objects and
 * bounds): a lone sphere's forms step down the rows (r->srow) and its run
 * on a row is searched from the row before's. */
#define RENDER_COHERENT                                                                                  \
    (FXRT_NUMBER == FXRT_Q16 && !FXRT_NO_STEP && !FXRT_NO_SPANS && !FXRT_NO_LONE && !FXRT_NO_BOUNDS && \
     !FXRT_NO_COHERENCE)

/* Where division and CLZ are instructions (the M3, M4F and host), a flat
 * piece's run search starts from a quotient (vis/flat.c) and keeps
 * no guesses; on the M0 each flat piece keeps the row before's
 * (render_flat_t's hint). */
#define RENDER_DIV_GUESS (FX_HAVE_UDIV && FX_HAVE_CLZ)
#define RENDER_HINTS (RENDER_COHERENT && !RENDER_DIV_GUESS)
/* There, too, each edge form keeps where it changed sign on the row before
 * (render_estep_t), so that the next row's column is one exact step away
 * (vis/flat.c: render_split_edge). 32 bytes per edge: not on the
 * M0, whose micro:bit has 16 KB of RAM. */
#define RENDER_ESTEP (RENDER_COHERENT && RENDER_DIV_GUESS)

/* Where CLZ is an instruction (the M3, M4F and host), a row finds the
 * objects it can meet from a mask per block of rows (r->row_mask) instead
 * of asking every object: 2 bytes per object, not on the M0. */
#define RENDER_ROW_BLOCKS 16
#define RENDER_ROW_MASKS (FX_HAVE_CLZ && !FXRT_NO_BOUNDS)

/* Spheres with row-coherence state (r->srow). */
#define RENDER_SROWS (RENDER_COHERENT && FXRT_COHERENT_SPHERES > 0)
/* Spheres with index below this have it (1 where none has: a bound that
 * no test of RENDER_SROWS && index < RENDER_SROW_SLOTS then finds
 * always false). */
#define RENDER_SROW_SLOTS (RENDER_SROWS ? FXRT_COHERENT_SPHERES : 1)

/* Run mode of the sampling pass (core/frame/render_sample.c): the coherent loop
 * can describe a fine row as runs of one owner each instead of one owner
 * per column. */
#define RENDER_RUNS (FXRT_MAX_SAMPLES > 1 && RENDER_COHERENT)

/* Back-face culling of closed meshes (render_cull_meshes), from the
 * world's mesh links (mesh.h, WORLD_MESH): a bit per triangle. */
#define RENDER_MESH WORLD_MESH

/* An edge form G (the form, negated where it falls along the row, so G
 * rises by step = 2 |x| a column) on row iy: col is the first column with
 * G >= 0 (anywhere, not only on the piece's columns) and val = G(col), in
 * [0, step). From a row to the next (iy - 2) G changes by a constant R:
 * col + dk, val + jump with dk = floor(-R / step) and jump = R + dk step
 * in (-step, 0], then one column more where val < 0. dk and jump hold for
 * the frame once two rows in a row have given them. */
typedef struct {
    int64_t val, jump;
    int32_t col, iy; /* iy RENDER_ESTEP_NONE: no column */
    int32_t dk;      /* RENDER_ESTEP_NONE: no step yet */
    int16_t next;    /* iy - 2 when col, dk and jump give that row's column, else RENDER_ESTEP_NO_ROW */
    bool fall;       /* the form falls along the row (with col) */
} render_estep_t;
#define RENDER_ESTEP_NONE INT32_MIN
#define RENDER_ESTEP_NO_ROW INT16_MIN /* (pixel offsets lie within +-2^15: FXRT_MAX_DIM) */

/* The visibility pass's records, by the form each kind takes (FORM and
 * EDGES in scene/kinds.h): flat pieces of their own (RENDER_FLATS),
 * spheres' forms (RENDER_ROUNDS), faces from the box-face pool
 * (FXRT_RENDER_BOX_FACES, when RENDER_FACE_KINDS > 0), and the edge forms'
 * row states (RENDER_EDGES: a flat piece's, then 4 per face). */
#define RENDER_CAP_FLAT(K, k, ks, cap, solid, bounded, form, edges, ...) RENDER_CAP_FLAT_##form(cap)
#define RENDER_CAP_FLAT_FLAT(cap) +(cap)
#define RENDER_CAP_FLAT_ROUND(cap)
#define RENDER_CAP_FLAT_FACES(cap)
#define RENDER_CAP_FLAT_RAYS(cap)
#define RENDER_CAP_ROUND(K, k, ks, cap, solid, bounded, form, edges, ...) RENDER_CAP_ROUND_##form(cap)
#define RENDER_CAP_ROUND_FLAT(cap)
#define RENDER_CAP_ROUND_ROUND(cap) +(cap)
#define RENDER_CAP_ROUND_FACES(cap)
#define RENDER_CAP_ROUND_RAYS(cap)
#define RENDER_CAP_FACES(K, k, ks, cap, solid, bounded, form, edges, ...) RENDER_CAP_FACES_##form(cap)
#define RENDER_CAP_FACES_FLAT(cap)
#define RENDER_CAP_FACES_ROUND(cap)
#define RENDER_CAP_FACES_FACES(cap) +(cap)
#define RENDER_CAP_FACES_RAYS(cap)
#define RENDER_CAP_EDGES(K, k, ks, cap, solid, bounded, form, edges, ...) +(edges) * (cap)
#define RENDER_FLATS (0 FXRT_KINDS(RENDER_CAP_FLAT))
#define RENDER_ROUNDS (0 FXRT_KINDS(RENDER_CAP_ROUND))
#define RENDER_FACE_KINDS (0 FXRT_KINDS(RENDER_CAP_FACES))
#define RENDER_EDGES (0 FXRT_KINDS(RENDER_CAP_EDGES) + (RENDER_FACE_KINDS > 0 ? 4 * FXRT_RENDER_BOX_FACES : 0))

/* A flat piece: a plane (no edges), a triangle (3) or a box face (4). */
typedef struct {
    render_lin_t n, d;  /* N and D: the hit is in front when they share a strict sign */
    render_lin_t e[3];  /* edge forms (a box face's fourth: render_face_t) */
    uint8_t edges;
    int8_t te;    /* Q16.16: t = N / D * 2^te (N, D carry their own scales) */
    bool front;   /* Q16.16: N and D share one strict sign at every pixel of its bounds, so
                   * the edges alone decide its coverage there (render_setup_object) */
#if RENDER_HINTS
    int16_t hint[6]; /* row coherence: where each form (N, D, edges) changed sign on the row before */
#endif
#if RENDER_ESTEP
    render_estep_t *es; /* row coherence: its edges' columns (r->estep; a plane: NULL) */
#endif
} render_flat_t;

/* The per-column owner array of the shading and sampling passes exists
 * when some pass reads it. */
#define RENDER_VIS (FXRT_MAX_LIGHTS > 0 || FXRT_MAX_SAMPLES > 1)

/* Fine columns a..b (inclusive) of one fine row belong to object oi. */
typedef struct {
    int16_t a, b;
    uint16_t oi;
} render_run_t;

/* Output columns with samples > 1 (at most half the fine columns). */
#define RENDER_OUT_COLS ((FXRT_RENDER_MAX_WIDTH + 1) / 2)

/* A sphere on one row from a column x0 (vis/sphere.c): the test
 * c < 0 || (b > 0 && disc >= 0) splits by what is constant along the
 * row: in perspective c is, in orthographic b is, and c < 0 implies
 * disc > 0. v, d1, d2: the form that decides (c, when use_c, or disc) at
 * x0, its first difference there and its (constant) second difference. */
typedef struct {
    fx128_t v, d1, d2;
    bool ortho, inside, use_c; /* inside: the eye is (every pixel covered) */
} render_srow_t;

/* The row forms of the sphere scanned last among others on the current
 * row (object oi, from pixel offset ix0 on row iy): a depth the sphere's
 * owner columns need later (render_depth_at) comes from them by a direct
 * evaluation at the column instead of from the sphere's forms. */
typedef struct {
    render_srow_t s;
    int32_t ix0, iy;
    uint16_t oi;
    /* The last disc computed for a sphere among others on this row
     * (vis/depth.c; disc_obj is reset at each row): sphere disc_obj's
     * disc q(disc_k) and, when disc_stepped, its step q(disc_k + 1) -
     * q(disc_k), so the next column's is two additions. */
    uint16_t disc_obj;
    bool disc_stepped;
    int32_t disc_k;
    fx128_t disc, disc_step;
#if RENDER_DIV_GUESS
    /* The last sphere depth range's first column (render_sphere_span:
     * sphere span_obj's depth span_t at column span_x, on this row;
     * span_obj is reset at each row), which a stretch halved starts from
     * again. */
    uint16_t span_obj;
    int32_t span_x;
    render_depth_t span_t;
#endif
} render_sphere_cache_t;

/* A sphere's forms. disc = r2 a - (px^2 + py^2 + pz^2) and c: with the
 * eye at o, centre C and direction r, disc = R^2 |r|^2 - |(C - o) x r|^2
 * (the same as b^2 - a c, without its cancellation).
 * Perspective: p = C x r, a = |r|^2 (one form for every sphere), c = k =
 * |C|^2 - R^2. Orthographic: p = the offsets of the ray from the centre
 * across the view, pz = 0, a = 1, c = k + px^2 + py^2.
 * Q16.16: pieces below 2^62, squares and sums exact in 128 bits. */
typedef struct {
    render_lin_t b, px, py, pz; /* b shares the p pieces' scale */
    const render_quad_t *a;
    bool ortho;
    int8_t tc, ta; /* Q16.16: t = c / (b + s) * 2^tc = (b + s) / a * 2^ta */
    /* (k and r2 last: on a 32-bit target the small fields above fill the
     * padding before them) */
    render_k2_t k, r2;
} render_sphere_t;

/* A box face: a flat piece with a fourth edge and its own pixel bounds
 * (render_flat_t first, so a pointer to f is a pointer to the face). A
 * plane's or triangle's bounds are its object's. */
typedef struct {
    render_flat_t f;
    render_lin_t e4;
    int16_t x0, x1, r0, r1;
} render_face_t;

/* What the row loop makes of an object: a sphere, one flat piece, a box
 * seen from outside (its front faces), a box with the eye inside (every
 * pixel: its nearest exit face), or an object of the RAYS form (a model,
 * an ellipsoid, a parallelepiped: a ray per pixel of its bounds,
 * vis/rays.c). */
typedef enum { RENDER_SPHERE, RENDER_FLAT, RENDER_BOX, RENDER_INSIDE_BOX, RENDER_RAYS } render_kind_t;
/* Kinds of the RAYS form are compiled in (models, ellipsoids,
 * parallelepipeds): the row
 * loop's and depth's RENDER_RAYS paths. */
#define RENDER_CAP_RAYS(K, k, ks, cap, solid, bounded, form, edges, ...) RENDER_CAP_RAYS_##form(cap)
#define RENDER_CAP_RAYS_FLAT(cap)
#define RENDER_CAP_RAYS_ROUND(cap)
#define RENDER_CAP_RAYS_FACES(cap)
#define RENDER_CAP_RAYS_RAYS(cap) +(cap)
#define RENDER_RAY_KINDS (0 FXRT_KINDS(RENDER_CAP_RAYS) > 0)

/* A model's footprint on the screen (vis/rays.c): the bounds of
 * RENDER_CUT nodes of its tree that together hold every triangle (unused
 * ones empty); a row's columns outside all of them cannot meet it, and
 * its camera rays there are not cast. */
#define RENDER_CUT 16
typedef struct {
    int16_t x0, x1, r0, r1;
} render_rect_t;

typedef struct {
    render_depth_t tlo, thi; /* first: 8-byte aligned in Q16.16, no padding before them */
    uint8_t kind;      /* render_kind_t */
    uint8_t geom;      /* geom_kind_t: which world array */
    uint8_t nflat;     /* RENDER_FLAT: 1, RENDER_BOX and RENDER_INSIDE_BOX: faces */
    bool ranged;       /* tlo, thi bound its depth (not for planes) */
    uint16_t index;    /* index there */
    uint16_t id;       /* scene order, for ties */
    rgb8_t rgb;
    bool flat;         /* its material is flat: rgb is every sample (no light sum) */
#if FXRT_PIXEL == FXRT_RGB565
    uint16_t px;       /* rgb as an RGB565 pixel */
#endif
    int16_t x0, x1;    /* columns that may be covered, inclusive */
    int16_t r0, r1;    /* output rows (0 = top) that may be covered */
    union {
        render_sphere_t *sphere; /* RENDER_SPHERE */
        render_flat_t *flat;     /* RENDER_FLAT: a plane or triangle */
        render_face_t *face;     /* RENDER_BOX and RENDER_INSIDE_BOX: nflat faces */
    } u;
} render_obj_t;

/* An object's render kind, as the row loop, depth and span code dispatch
 * on it: a kind that this build cannot hold (its kinds' capacities 0) is
 * assumed away, so that its code is not linked: a plane-only image has no
 * sphere or box scan. Set-up makes only the kinds the build holds. */
static inline uint8_t render_kind(const render_obj_t *o) /* a render_kind_t */
{
    uint8_t k = o->kind;
    PORT_ASSUME(RENDER_ROUNDS > 0 || k != RENDER_SPHERE);
    PORT_ASSUME(RENDER_FLATS > 0 || k != RENDER_FLAT);
    PORT_ASSUME(RENDER_FACE_KINDS > 0 || (k != RENDER_BOX && k != RENDER_INSIDE_BOX));
    PORT_ASSUME(RENDER_RAY_KINDS || k != RENDER_RAYS);
    return k;
}

typedef struct {
    const world_t *world;
    const cam_t *cam;
    uint16_t count;
    /* The world's samples are more than 1: rows are the sampler's fine
     * rows, whose pixels it reads from painted[], not from the row (false
     * with FXRT_MAX_SAMPLES 1; the byte sits in count's padding, so it
     * costs no RAM in any build). */
    bool sampled;
    render_obj_t obj[FXRT_RENDER_MAX_OBJECTS];
    /* The records, by form (scene/kinds.h), sized by the capacities of the
     * kinds of each form; *_used: how many this frame's objects took. */
#if RENDER_ROUNDS > 0
    render_sphere_t spheres[RENDER_ROUNDS];
    render_quad_t sphere_a; /* a = |r|^2, shared by every sphere */
#endif
#if RENDER_FLATS > 0
    render_flat_t flats[RENDER_FLATS]; /* one per plane or triangle */
#endif
#if RENDER_FACE_KINDS > 0
    render_face_t box_faces[FXRT_RENDER_BOX_FACES]; /* the faces a box can be hit through, box after box */
#endif
    uint16_t flats_used, spheres_used, box_used, estep_used;
#if RENDER_ESTEP && RENDER_EDGES > 0
    /* The edges' row states: a flat piece's (a triangle's 3), then 4 per box face. */
    render_estep_t estep[RENDER_EDGES];
#endif
    const char *error; /* why render_setup failed, or NULL */
    /* Per column: stamp << 17 | depth-known << 16 | object (index into
     * obj) of the nearest cover so far. A column whose stamp is not the
     * current row's is uncovered, so rows need no clearing pass. Columns
     * painted by an object alone on its row are not recorded. One entry
     * more: render_claim_run's sentinel past its last column. */
    uint32_t owner[FXRT_RENDER_MAX_WIDTH + 1];
    /* Per column: the owner's depth, where a second object has asked. */
    render_depth_t depth[FXRT_RENDER_MAX_WIDTH];
    uint16_t stamp;
    uint16_t nplanes;  /* objects 0 .. nplanes - 1 are the planes */
    uint32_t row_win;  /* this row, the object being scanned: planes it is nearer than */
#if RENDER_ROW_MASKS
    /* Bit i % 32 of word i / 32 of block b: object i's rows r0..r1 meet
     * rows b << row_shift .. ((b + 1) << row_shift) - 1. */
    uint32_t row_mask[RENDER_ROW_BLOCKS][(FXRT_RENDER_MAX_OBJECTS + 31) / 32];
    uint8_t row_shift;
#endif
#if FXRT_NUMBER == FXRT_Q16
    render_sphere_cache_t *sphere_cache; /* during render_row_vis: on its stack (else NULL) */
#endif
#if RENDER_MESH
    /* Bit i % 8 of byte i / 8: triangle i is a back face of a closed mesh
     * this frame (render_cull_meshes, before the objects are set up;
     * render_setup_triangle leaves it empty). */
    uint8_t mesh_culled[(FXRT_MAX_TRIANGLES + 7) / 8];
#endif
#if RENDER_VIS
    /* Shading and sampling passes: per column of the current row, the
     * object (index into obj) painted last, RENDER_VIS_NONE where none,
     * recorded when track is set (some object is lit, or samples > 1) or
     * keys are wanted. */
    uint16_t painted[FXRT_RENDER_MAX_WIDTH];
    bool track;
    /* Per column the model painter's triangle (vis/rays.c), which the
     * shading pass intersects alone instead of walking the model again. */
    FXRT_IF_MODEL(uint32_t model_tri[FXRT_RENDER_MAX_WIDTH];)
#endif
    FXRT_IF_MODEL(render_rect_t model_cut[FXRT_MAX_MODELS][RENDER_CUT];)
#if RENDER_SROWS
    /* Row coherence, per sphere (index < FXRT_COHERENT_SPHERES): the
     * deciding form at its first column x0 is quadratic in the (fine) row,
     * exactly in 128 bits. cur holds it on fine row vrow (v, d1, d2 as
     * render_srow_t); dvk = v(next row) - v; ddv and dd1, how dvk and d1
     * change per row. plo..phi: its run of f >= 0 on fine row prow
     * (columns from x0), which guesses the next row's; pk, the column of
     * f's peak last found. */
    struct {
        render_srow_t cur; /* v, d1, d2 on fine row vrow */
        fx128_t dvk, ddv, dd1;
        int32_t vrow, prow;
        int16_t plo, phi, pk;
    } srow[FXRT_COHERENT_SPHERES];
#endif
    /* Set by the frame (frame/render.h): a key is wanted for every pixel
     * of the row, so vis[] is recorded whatever track says. */
    bool want_keys;
    int16_t dirty_lo, dirty_hi; /* this row: columns outside have no owner yet */
} vis_t;

#if RENDER_MESH
/* Is triangle i a back face of a closed mesh in this frame? */
static inline bool render_mesh_culled(const vis_t *r, uint16_t i) { return (r->mesh_culled[i >> 3] >> (i & 7)) & 1u; }
#endif

/* Per-frame set-up of the visibility pass: camera-space forms and screen
 * bounds of every object, for camera cam (the sampler's fine camera when
 * the world's samples are more than 1). The world and camera must outlive
 * r. Returns NULL, or why the frame cannot be set up (the boxes need more
 * faces than FXRT_RENDER_BOX_FACES, or the camera is wider than
 * FXRT_RENDER_MAX_WIDTH). */
const char *render_vis_setup(vis_t *r, const world_t *w, const cam_t *cam);

#endif
