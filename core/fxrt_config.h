/* fxrt build configuration: every option lives here, documented where it is
 * defined and in the README table. Override with -D or from a generated
 * scene header included before this one. */
#ifndef FXRT_CONFIG_H
#define FXRT_CONFIG_H

#include "port/port.h" /* the target's features, for the defaults below */

/* FXRT_NUMBER selects the renderer's number type:
 *   1 = FXRT_Q16    Q16.16 fixed point (the product)
 *   2 = FXRT_FLOAT  IEEE binary32 (what a user would otherwise write)
 *   3 = FXRT_DOUBLE IEEE binary64 (the reference) */
#define FXRT_Q16 1
#define FXRT_FLOAT 2
#define FXRT_DOUBLE 3
#ifndef FXRT_NUMBER
#define FXRT_NUMBER FXRT_Q16
#endif
FXRT_STATIC_ASSERT(FXRT_NUMBER == FXRT_Q16 || FXRT_NUMBER == FXRT_FLOAT || FXRT_NUMBER == FXRT_DOUBLE, "FXRT_NUMBER must be FXRT_Q16 (1), FXRT_FLOAT (2) or FXRT_DOUBLE (3)");

/* World capacity per primitive kind (a static array each). 0 removes the
 * kind from the build: its intersection code is not compiled. Triangles
 * get more room by default: meshes are made of them (an icosphere
 * subdivided once has 80 faces). The firmware sets each to the scene's
 * own count (fxrt-scenec). */
#ifndef FXRT_MAX_PLANES
#define FXRT_MAX_PLANES 64
#endif
#ifndef FXRT_MAX_SPHERES
#define FXRT_MAX_SPHERES 64
#endif
#ifndef FXRT_MAX_TRIANGLES
#define FXRT_MAX_TRIANGLES 128
#endif
#ifndef FXRT_MAX_BOXES
#define FXRT_MAX_BOXES 64
#endif
/* Models: placed meshes whose triangles stay in constant data behind a
 * BVH (scene/model.c, docs/MESHES.md). Each costs one record in RAM
 * whatever its triangle count. Default: 16 on the host, 0 on bare-metal
 * boards, where a firmware that draws meshes sets it (the scene compiler
 * sets it to the scene's count). */
#ifndef FXRT_MAX_MODELS
#define FXRT_MAX_MODELS FXRT_PORT_HOSTED(16)
#endif
/* Ellipsoids and parallelepipeds: spheres that a node scales unevenly
 * and boxes that a node turns (scene/ellipsoid.c, scene/parallelepiped.c),
 * a ray per pixel of their bounds. Default: 16 each on the host, 0 on
 * bare-metal boards (the scene compiler sets each to the scene's count). */
#ifndef FXRT_MAX_ELLIPSOIDS
#define FXRT_MAX_ELLIPSOIDS FXRT_PORT_HOSTED(16)
#endif
#ifndef FXRT_MAX_PARALLELEPIPEDS
#define FXRT_MAX_PARALLELEPIPEDS FXRT_PORT_HOSTED(16)
#endif

/* Smooth shading (a mesh's 'shading smooth', docs/SCENES.md "Meshes"): a
 * triangle may carry a unit normal per vertex (fxrt_object_t's .smooth
 * and .vn[]), interpolated across it at every hit (scene/smooth.c). 1 adds
 * the normals and a flag to every triangle record and to fxrt_object_t
 * (40 B in Q16.16); 0 compiles it out. Default: 1 on the host, 0 on
 * bare-metal boards (the scene compiler sets it to whether the scene has
 * a smooth triangle). Needs triangles (FXRT_MAX_TRIANGLES > 0). */
#ifndef FXRT_SMOOTH
#define FXRT_SMOOTH (!FXRT_PORT_BARE && FXRT_MAX_TRIANGLES > 0)
#endif
FXRT_STATIC_ASSERT(!FXRT_SMOOTH || FXRT_MAX_TRIANGLES > 0, "FXRT_SMOOTH must be 0, or 1 with FXRT_MAX_TRIANGLES > 0");

/* The documented input domain (scene units). Inside it, no intermediate of
 * the Q16.16 renderer overflows; scene loaders reject values outside it.
 *   FXRT_COORD_LIMIT   |coordinate| of any point, eye or corner
 *   FXRT_RADIUS_LIMIT  sphere radius, also the orthographic scale limit */
#ifndef FXRT_COORD_LIMIT
#define FXRT_COORD_LIMIT 8192
#endif
#ifndef FXRT_RADIUS_LIMIT
#define FXRT_RADIUS_LIMIT 4096
#endif

/* Which loop renders primary rays where a program picks one at compile
 * time (the firmware; the host tool picks at run time with --renderer):
 *   1 = FXRT_RENDERER_FAST       the scanline renderer (render_row)
 *   2 = FXRT_RENDERER_REFERENCE  every object's forms at every pixel
 *                                (render_row_reference), for before/after
 *   3 = FXRT_RENDERER_RAYCAST    a camera ray and a nearest-hit search per
 *                                pixel (raycast_row): the naive baseline */
#define FXRT_RENDERER_FAST 1
#define FXRT_RENDERER_REFERENCE 2
#define FXRT_RENDERER_RAYCAST 3
#ifndef FXRT_RENDERER
#define FXRT_RENDERER FXRT_RENDERER_FAST
#endif
FXRT_STATIC_ASSERT(1 <= FXRT_RENDERER && FXRT_RENDERER <= 3, "FXRT_RENDERER must be 1 (fast), 2 (reference) or 3 (raycast)");

/* Largest image width or height in pixels. */
#ifndef FXRT_MAX_DIM
#define FXRT_MAX_DIM 4096
#endif

/* Limits the types imply. Pixel columns and rows are stored as int16_t
 * (the renderer's per-object screen bounds), so an image side must fit
 * int16. Objects are counted and identified with uint16_t (world_t's
 * n_<kind>, scene ids, render_t's object indices), and 0xFFFF is the
 * "no object" sentinel (RAYCAST_MISS, the renderer's RO_NONE), so the
 * total capacity must stay below it. An image side of at most 16384
 * keeps every pixel offset (|ix| <= width + 4) below 2^15, the domain of
 * fx.h's small-factor products (fx_smul_small, fx_umul64_small: cam_ray
 * and the scanline forms' evaluation on the M0). */
FXRT_STATIC_ASSERT(1 <= FXRT_MAX_DIM && FXRT_MAX_DIM <= 16384, "FXRT_MAX_DIM must be in 1..16384: pixel offsets must stay below 2^15");
/* (The capacities' checks, each >= 0 and their total in 1..65535, are
 * made from the kinds table: scene/kinds.h.) */

/* Instruction-set features the fixed-point maths (math/fx.c, math/fx.h)
 * chooses its code paths by. The defaults follow the target: the
 * Cortex-M0 (ARMv6-M) has no divide, no CLZ and no 32x32->64 multiply; the
 * M3/M4 and the host have all three. Results are identical on every path
 * (the tests build the host with all three set to 0, see tests/fx.mk);
 * only speed and size change.
 *   FX_HAVE_UDIV   1: 32-bit `/` is an instruction (fx_div's digit
 *                  estimates use it); 0: a 256-byte reciprocal table
 *   FX_HAVE_CLZ    1: __builtin_clz is an instruction; 0: a binary search
 *   FX_HAVE_UMULL  1: (uint64_t)a * b is one instruction; 0: four 16-bit
 *                  products inline (instead of libgcc's __aeabi_lmul) */
#ifndef FX_HAVE_UDIV
#define FX_HAVE_UDIV (!FXRT_PORT_SMALL_ISA)
#endif
#ifndef FX_HAVE_CLZ
#define FX_HAVE_CLZ (!FXRT_PORT_SMALL_ISA)
#endif
#ifndef FX_HAVE_UMULL
#define FX_HAVE_UMULL (!FXRT_PORT_SMALL_ISA)
#endif

/* ---- the scanline renderer (render.h) ---------------------------------- */

/* Widest image a render_t can hold (one owner and depth entry per column). */
#ifndef FXRT_RENDER_MAX_WIDTH
#define FXRT_RENDER_MAX_WIDTH FXRT_MAX_DIM
#endif
FXRT_STATIC_ASSERT(1 <= FXRT_RENDER_MAX_WIDTH && FXRT_RENDER_MAX_WIDTH <= FXRT_MAX_DIM, "FXRT_RENDER_MAX_WIDTH must be 1..FXRT_MAX_DIM");

/* Objects a world holds, over every kind (the sum of the kinds table's
 * capacities, scene/kinds.h). */
#define FXRT_RENDER_MAX_OBJECTS (0 FXRT_KINDS(FXRT_KIND_CAPACITY))

/* Box faces the renderer can hold per frame, over all boxes. A box seen
 * from outside in perspective needs at most 3; from inside, from its
 * surface, or cut by an orthographic camera's plane, up to 6. A frame that
 * needs more fails in render_setup with a message. Default: 6 per box. */
#ifndef FXRT_RENDER_BOX_FACES
#define FXRT_RENDER_BOX_FACES (6 * FXRT_MAX_BOXES)
#endif
FXRT_STATIC_ASSERT(FXRT_MAX_BOXES == 0 || FXRT_RENDER_BOX_FACES >= 1, "FXRT_RENDER_BOX_FACES must be at least 1 when boxes are enabled");

/* Back faces of closed meshes (scene/mesh.c, vis/cull.c): in
 * worlds of 4 to FXRT_MESH_MAX triangles (at most 255), each triangle is
 * matched edge to edge with the earlier ones as it is added
 * (world_add_triangle: about T^2 / 2 vertex compares for the world), and
 * a frame's set-up leaves out the triangles of a closed, consistently
 * wound, convex set of them that face away from an eye outside its
 * bounding box, in perspective (two exact side tests per triangle of such
 * a set). 2 B of world RAM per triangle up to FXRT_MESH_MAX, and 1 bit of
 * render_t per triangle; 0 turns it off. Default 128. */
#ifndef FXRT_MESH_MAX
#define FXRT_MESH_MAX 128
#endif
FXRT_STATIC_ASSERT(0 <= FXRT_MESH_MAX && FXRT_MESH_MAX <= 255, "FXRT_MESH_MAX must be 0..255");

/* A scene's mesh of at most FXRT_MESH_INLINE triangles becomes triangle
 * objects, drawn by the scanline pass's flat pieces (six times faster than
 * a model's rays for a cube in a node, docs/bench/models.md), where the
 * triangle capacity has room; a larger one, or one that does not fit,
 * becomes a model (scene/model.c). 0: every mesh a model. */
#ifndef FXRT_MESH_INLINE
#define FXRT_MESH_INLINE 32
#endif
FXRT_STATIC_ASSERT(FXRT_MESH_INLINE >= 0, "FXRT_MESH_INLINE must be >= 0");

/* Objects alone on their row (the fast renderer fills their spans without
 * the per-column owner bookkeeping) are looked for only in worlds of at
 * most FXRT_LONE_MAX objects: the test looks at every pair of objects on
 * each row. Default 16. */
#ifndef FXRT_LONE_MAX
#define FXRT_LONE_MAX 16
#endif
FXRT_STATIC_ASSERT(0 <= FXRT_LONE_MAX && FXRT_LONE_MAX <= 65535, "FXRT_LONE_MAX must be 0..65535");

/* The fast renderer visits the objects nearest first (render_setup sorts
 * them once per frame; FXRT_NO_ORDER below): in worlds of at most
 * FXRT_ORDER_MAX objects, larger ones keep scene order. The sort's
 * scratch is on the stack, 6 B per object: at most 1.5 KB with the
 * default 256 (and 6 B times the scene's objects where fewer can exist:
 * the firmware's capacities are the scene's counts). */
#ifndef FXRT_ORDER_MAX
#define FXRT_ORDER_MAX 256
#endif
FXRT_STATIC_ASSERT(0 <= FXRT_ORDER_MAX && FXRT_ORDER_MAX <= 4096, "FXRT_ORDER_MAX must be 0..4096");

/* Spheres that keep row-coherence state (fast Q16.16 renderer, about
 * 120 B each; FXRT_NO_COHERENCE below): the spheres with index 0 ..
 * FXRT_COHERENT_SPHERES - 1; the others find their runs from scratch. A
 * sphere alone on its row fills its runs from it; among others it takes
 * its row forms and runs from it too. Objects are alone only in worlds of
 * at most FXRT_LONE_MAX objects, so the default is the smaller of
 * FXRT_MAX_SPHERES and FXRT_LONE_MAX. fxrt-scenec writes the scene's
 * sphere count, or 0 for a scene of more than FXRT_LONE_MAX objects
 * (all of them with --sphere-rows, which the firmware uses on every board;
 * firmware/fit.sh compiles a scene whose row state does not fit RAM again
 * with 0). */
#ifndef FXRT_COHERENT_SPHERES
#define FXRT_COHERENT_SPHERES (FXRT_MAX_SPHERES < FXRT_LONE_MAX ? FXRT_MAX_SPHERES : FXRT_LONE_MAX)
#endif
FXRT_STATIC_ASSERT(0 <= FXRT_COHERENT_SPHERES && FXRT_COHERENT_SPHERES <= FXRT_MAX_SPHERES, "FXRT_COHERENT_SPHERES must be 0..FXRT_MAX_SPHERES");

/* Measurement builds: FXRT_ABLATE switches parts of the renderer off,
 * one bit each, to measure what each saves (make bench-ablation,
 * bench-lit-bound, cutoff), e.g.
 *   -DFXRT_ABLATE='(FXRT_ABLATE_STEP | FXRT_ABLATE_SPANS)'
 * 0 (default): everything on. The first eight change no Q16.16 pixel:
 *   FXRT_ABLATE_BOUNDS    step every object over the whole screen, and
 *                         test every bounded object against every
 *                         secondary ray
 *   FXRT_ABLATE_STEP      evaluate every form from scratch at each pixel
 *   FXRT_ABLATE_LONE      always go through the owner bookkeeping
 *   FXRT_ABLATE_SPANS     step a lone flat piece pixel by pixel instead of
 *                         locating its runs on the row and filling them
 *   FXRT_ABLATE_ZRANGE    decide every overlap by computing both depths
 *                         (no depth ranges, no per-row order against
 *                         planes)
 *   FXRT_ABLATE_COHERENCE find runs on each row from scratch (a lone
 *                         sphere: three 128-bit form evaluations and
 *                         binary searches, or stepping on Armv6-M; a flat
 *                         piece: a 64-bit division per form) instead of
 *                         stepping a sphere's forms down the rows and
 *                         searching from the row before's runs (RAM: 120 B
 *                         per coherent sphere, 12 B per flat piece)
 *   FXRT_ABLATE_HOIST     (reference loop) recompute each object's forms
 *                         at every pixel instead of once per frame
 *   FXRT_ABLATE_ORDER     visit the objects in scene order (kind after
 *                         kind) instead of nearest first
 *   FXRT_ABLATE_CUTOFF    trace every secondary ray up to the depth,
 *                         however small its weight (by default a ray
 *                         whose weight is below 1/512 in every channel is
 *                         not traced)
 *   FXRT_ABLATE_LIGHT_SUM every lit pixel still gets its camera ray, hit
 *                         point and normal, but its light sum stops before
 *                         the first light (the ambient term alone): what a
 *                         lit pixel costs before any light is summed; the
 *                         frames are not the renderer's (host keys still
 *                         get the full light loop)
 *   FXRT_ABLATE_SHADOW_ROWS no per-row shadow masks on planes: every
 *                         shadow ray from a plane takes the per-ray cull
 *                         and the exact tests (light/shadow.c), and no
 *                         run takes a plane's n . l from its forms where
 *                         a light casts shadows (light/shade.c)
 *   FXRT_ABLATE_FLAT_NUM  a plane's or triangle's hit numerator (a - e) . n
 *                         computed again at every lit pixel instead of
 *                         once per run of that object's pixels
 *                         (frame/render_shade.c), and every pixel shaded
 *                         on its own (no FXRT_SHADE_RUNS)
 *   FXRT_ABLATE_BVH_QUICK a model's boxes tested by their exact quotients
 *                         alone, without the quick test's reciprocals
 *                         (scene/bvh.c)
 * The renderer reads them as FXRT_NO_BOUNDS ... FXRT_NO_ORDER,
 * FXRT_NO_CUTOFF, FXRT_BOUND_NO_LIGHT_SUM, FXRT_NO_SHADOW_ROWS,
 * FXRT_NO_FLAT_NUM and FXRT_NO_BVH_QUICK (0 or 1). (The triangles' shadow
 * edges have their own switch, FXRT_SHADOW_EDGES, below.) */
#define FXRT_ABLATE_BOUNDS 0x001
#define FXRT_ABLATE_STEP 0x002
#define FXRT_ABLATE_LONE 0x004
#define FXRT_ABLATE_ZRANGE 0x008
#define FXRT_ABLATE_SPANS 0x010
#define FXRT_ABLATE_COHERENCE 0x020
#define FXRT_ABLATE_HOIST 0x040
#define FXRT_ABLATE_ORDER 0x080
#define FXRT_ABLATE_CUTOFF 0x100
#define FXRT_ABLATE_LIGHT_SUM 0x200
#define FXRT_ABLATE_SHADOW_ROWS 0x400
#define FXRT_ABLATE_FLAT_NUM 0x800
#define FXRT_ABLATE_BVH_QUICK 0x1000
#ifndef FXRT_ABLATE
#define FXRT_ABLATE 0
#endif
FXRT_STATIC_ASSERT(((FXRT_ABLATE) & ~0x1fff) == 0, "FXRT_ABLATE: an unknown bit (the FXRT_ABLATE_ names only)");
#define FXRT_NO_BOUNDS (((FXRT_ABLATE) & FXRT_ABLATE_BOUNDS) != 0)
#define FXRT_NO_STEP (((FXRT_ABLATE) & FXRT_ABLATE_STEP) != 0)
#define FXRT_NO_LONE (((FXRT_ABLATE) & FXRT_ABLATE_LONE) != 0)
#define FXRT_NO_ZRANGE (((FXRT_ABLATE) & FXRT_ABLATE_ZRANGE) != 0)
#define FXRT_NO_SPANS (((FXRT_ABLATE) & FXRT_ABLATE_SPANS) != 0)
#define FXRT_NO_COHERENCE (((FXRT_ABLATE) & FXRT_ABLATE_COHERENCE) != 0)
#define FXRT_NO_HOIST (((FXRT_ABLATE) & FXRT_ABLATE_HOIST) != 0)
#define FXRT_NO_ORDER (((FXRT_ABLATE) & FXRT_ABLATE_ORDER) != 0)
#define FXRT_NO_CUTOFF (((FXRT_ABLATE) & FXRT_ABLATE_CUTOFF) != 0)
#define FXRT_BOUND_NO_LIGHT_SUM (((FXRT_ABLATE) & FXRT_ABLATE_LIGHT_SUM) != 0)
#define FXRT_NO_SHADOW_ROWS (((FXRT_ABLATE) & FXRT_ABLATE_SHADOW_ROWS) != 0)
#define FXRT_NO_FLAT_NUM (((FXRT_ABLATE) & FXRT_ABLATE_FLAT_NUM) != 0)
#define FXRT_NO_BVH_QUICK (((FXRT_ABLATE) & FXRT_ABLATE_BVH_QUICK) != 0)


/* FXRT_SPHERE_SEARCH: how the fast Q16.16 renderer finds the run of a
 * sphere alone on its row (the frame is the same either way):
 *   1 = binary searches with exact evaluations of the row's quadratic
 *       (64-bit multiplies: cheap where 32 x 32 -> 64 is one instruction)
 *   0 = stepping along the row by forward differences (additions only)
 * Default: 0 on Armv6-M (Cortex-M0 has no long multiply), else 1. */
#ifndef FXRT_SPHERE_SEARCH
#define FXRT_SPHERE_SEARCH (!FXRT_PORT_SMALL_ISA)
#endif
FXRT_STATIC_ASSERT(FXRT_SPHERE_SEARCH == 0 || FXRT_SPHERE_SEARCH == 1, "FXRT_SPHERE_SEARCH must be 0 or 1");

/* FXRT_SHADE_RUNS: how the shading pass (frame/render_shade.c) takes the
 * lit pixels of a pinhole camera's rows, in a frame without pixel keys
 * (the frame is the same either way):
 *   1 = a run of one object's pixels at once (not a model's): a Lambert
 *       plane's in one call (light/shade.c, shade_flat_plane_run; under
 *       point lights without a shadow ray, n . l from the run's forms,
 *       shade_plane_forms, with no hit point),
 *       another's in a loop without the tests each pixel otherwise takes
 *   0 = every pixel through those tests
 * Default: 1, except in double on Armv6-M, the soft-float reference: its
 * deepest lit scene (course-phong-directional) uses 1,512 B of the
 * micro:bit's 2,048 B stack, and the runs make the row loop's frame 64 B
 * larger (the run's arguments, the loop's locals): past the asserted
 * 512 B margin. */
#ifndef FXRT_SHADE_RUNS
#define FXRT_SHADE_RUNS (!(FXRT_PORT_SMALL_ISA && FXRT_NUMBER == FXRT_DOUBLE))
#endif
FXRT_STATIC_ASSERT(FXRT_SHADE_RUNS == 0 || FXRT_SHADE_RUNS == 1, "FXRT_SHADE_RUNS must be 0 or 1");

/* FXRT_FLOAT_STEP (float and double builds only; Q16.16 always steps,
 * exactly):
 *   0 = evaluate every form directly at every pixel (default)
 *   1 = step forms by forward differences along the row, restarted from a
 *       direct evaluation at the start of every object's row segment: what
 *       a careful float programmer would write. Drift makes it differ from
 *       the double reference; see docs/BENCHMARKS.md. */
#ifndef FXRT_FLOAT_STEP
#define FXRT_FLOAT_STEP 0
#endif
FXRT_STATIC_ASSERT(FXRT_FLOAT_STEP == 0 || FXRT_FLOAT_STEP == 1, "FXRT_FLOAT_STEP must be 0 or 1");

/* Pixel format of the rows render_row writes:
 *   1 = FXRT_RGB888  3 bytes per pixel, R, G, B (default)
 *   2 = FXRT_RGB565  one uint16_t per pixel in native byte order,
 *                    R in bits 15..11, G in 10..5, B in 4..0, each the
 *                    8-bit value's top bits (truncated) */
#define FXRT_RGB888 1
#define FXRT_RGB565 2
#ifndef FXRT_PIXEL
#define FXRT_PIXEL FXRT_RGB888
#endif
FXRT_STATIC_ASSERT(FXRT_PIXEL == FXRT_RGB888 || FXRT_PIXEL == FXRT_RGB565, "FXRT_PIXEL must be FXRT_RGB888 (1) or FXRT_RGB565 (2)");

/* ---- lighting (scene/light.h, light/shade.c, light/shadow.c) -------------- */

/* Lights a world can hold (0..8). 0 compiles lighting out: every object is
 * drawn in its flat colour, material and light calls return
 * FXRT_ERR_MATERIAL / FXRT_ERR_FULL, and no shading code is linked. The
 * firmware sets it from the scene (fxrt-scenec: 0 when every material is
 * flat). At most 8: a pixel's key holds one bit per light. */
#ifndef FXRT_MAX_LIGHTS
#define FXRT_MAX_LIGHTS 8
#endif
FXRT_STATIC_ASSERT(0 <= FXRT_MAX_LIGHTS && FXRT_MAX_LIGHTS <= 8, "FXRT_MAX_LIGHTS must be in 0..8");
/* FXRT_IF_LIGHTS(...): its arguments where lights are compiled in. */
#define FXRT_IF_LIGHTS(...) FXRT_IF_NONZERO(FXRT_MAX_LIGHTS, __VA_ARGS__)
FXRT_STATIC_ASSERT((FXRT_MAX_LIGHTS > 0) == (0 FXRT_IF_LIGHTS(+1)), "FXRT_MAX_LIGHTS must be a plain decimal number");
/* FXRT_SHADOWS 0 compiles shadow rays out (every light then reaches every
 * surface that faces it, whatever its shadows setting); 1 (default) casts
 * them for lights with shadows on. The scene compiler emits 0 when no
 * light casts shadows. */
#ifndef FXRT_SHADOWS
#define FXRT_SHADOWS (FXRT_MAX_LIGHTS > 0)
#endif
FXRT_STATIC_ASSERT(FXRT_SHADOWS == 0 || FXRT_SHADOWS == 1, "FXRT_SHADOWS must be 0 or 1");
/* FXRT_PHONG 0 compiles the specular term out (phong materials are then
 * refused with FXRT_ERR_MATERIAL); 1 (default) keeps it. The scene
 * compiler emits 0 when no object is phong. */
#ifndef FXRT_PHONG
#define FXRT_PHONG (FXRT_MAX_LIGHTS > 0)
#endif
FXRT_STATIC_ASSERT(FXRT_PHONG == 0 || FXRT_PHONG == 1, "FXRT_PHONG must be 0 or 1");
/* FXRT_SHADOW_CULL 1 (default) gives each point and spot light, once per
 * frame, a cone around every bounded object (sphere, triangle, box) as
 * seen from the light, with a margin for every rounding: a shadow ray
 * outside the cone, or ending before the object, skips that object's
 * exact test (light/shadow.c; docs/ACCURACY.md, "Shadow-ray culling"). It
 * changes no decision of an exact kernel that is right (and skips some
 * that are not); 0 compiles it out. */
#ifndef FXRT_SHADOW_CULL
#define FXRT_SHADOW_CULL 1
#endif
FXRT_STATIC_ASSERT(FXRT_SHADOW_CULL == 0 || FXRT_SHADOW_CULL == 1, "FXRT_SHADOW_CULL must be 0 or 1");
/* FXRT_SHADOW_EDGES 1 (default; with FXRT_SHADOW_CULL) also gives each
 * point and spot light a triangle's three edge planes, once per frame: a
 * shadow ray inside the triangle's cone but outside one of them skips its
 * exact test too (light/shadow.c; the same frames). 26 bytes of RAM per
 * light and triangle in Q16.16. The scene compiler emits 0 for a scene
 * without a triangle or without a point or spot light with shadows, and
 * firmware/fit.sh builds a scene that does not fit RAM again with 0. */
#ifndef FXRT_SHADOW_EDGES
#define FXRT_SHADOW_EDGES 1
#endif
FXRT_STATIC_ASSERT(FXRT_SHADOW_EDGES == 0 || FXRT_SHADOW_EDGES == 1, "FXRT_SHADOW_EDGES must be 0 or 1");
FXRT_STATIC_ASSERT(FXRT_MAX_LIGHTS > 0 || (!FXRT_SHADOWS && !FXRT_PHONG), "FXRT_SHADOWS and FXRT_PHONG need FXRT_MAX_LIGHTS > 0");
/* FXRT_STATS 1 counts the shading work (core/math/stats.h) for tests;
 * 0 (default) compiles the counters out. */
#ifndef FXRT_STATS
#define FXRT_STATS 0
#endif

/* Largest Phong exponent (the scene format allows 1..1024). */
#define FXRT_PHONG_MAX_EXPONENT 1024

/* ---- secondary rays and supersampling (light/trace.c, render_sample.c) -- */

/* Largest bounce depth a world may ask for (world_set_depth, the scene's
 * 'depth', 0..16). The bounce loop's stack of pending rays has this many
 * entries (light/trace.h). 0 compiles bounces out: reflective materials
 * keep their Phong term, transparent ones show black, and no bounce code
 * is linked. The scene compiler emits the scene's own depth, or 0 when no
 * object is reflective or transparent. */
#ifndef FXRT_MAX_DEPTH
#if FXRT_MAX_LIGHTS > 0 /* (a literal number: fxrt.h's FXRT_CONFIG_SYMBOL pastes it) */
#define FXRT_MAX_DEPTH 16
#else
#define FXRT_MAX_DEPTH 0
#endif
#endif
FXRT_STATIC_ASSERT(0 <= FXRT_MAX_DEPTH && FXRT_MAX_DEPTH <= 16, "FXRT_MAX_DEPTH must be in 0..16");
FXRT_STATIC_ASSERT(FXRT_MAX_DEPTH == 0 || FXRT_MAX_LIGHTS > 0, "FXRT_MAX_DEPTH > 0 needs FXRT_MAX_LIGHTS > 0 (reflective and transparent materials)");
/* FXRT_IF_DEPTH(...): its arguments where bounces are compiled in. */
#define FXRT_IF_DEPTH(...) FXRT_IF_NONZERO(FXRT_MAX_DEPTH, __VA_ARGS__)
FXRT_STATIC_ASSERT((FXRT_MAX_DEPTH > 0) == (0 FXRT_IF_DEPTH(+1)), "FXRT_MAX_DEPTH must be a plain decimal number");
/* Largest N of 'samples N' (N x N rays per pixel, 1..16). 1 compiles
 * supersampling out. The visibility pass then works on a camera N times
 * as wide, so N * width must stay within FXRT_RENDER_MAX_WIDTH. */
#ifndef FXRT_MAX_SAMPLES
#define FXRT_MAX_SAMPLES 16
#endif
FXRT_STATIC_ASSERT(1 <= FXRT_MAX_SAMPLES && FXRT_MAX_SAMPLES <= 16, "FXRT_MAX_SAMPLES must be in 1..16");
/* FXRT_IF_SAMPLES(...): its arguments where supersampling is compiled in. */
#define FXRT_IF_SAMPLES(...) FXRT_IF_ABOVE1(FXRT_MAX_SAMPLES, __VA_ARGS__)
FXRT_STATIC_ASSERT((FXRT_MAX_SAMPLES > 1) == (0 FXRT_IF_SAMPLES(+1)), "FXRT_MAX_SAMPLES must be a plain decimal number");
/* FXRT_SAMPLE_RUNS: the runs (one owner each) that the fast Q16.16
 * sampling pass may hold for the N fine rows of one output row when it
 * works from spans (core/frame/render_sample.c, "run mode": every object on
 * those rows flat and alone on its row). An output row with more runs,
 * a lit object or objects that overlap takes the per-sample pass instead
 * (the same image). 6 bytes each; default 8 per fine row. */
#ifndef FXRT_SAMPLE_RUNS
#define FXRT_SAMPLE_RUNS (8 * FXRT_MAX_SAMPLES)
#endif
FXRT_STATIC_ASSERT(1 <= FXRT_SAMPLE_RUNS && FXRT_SAMPLE_RUNS <= 4096, "FXRT_SAMPLE_RUNS must be in 1..4096");
/* FXRT_ADAPTIVE 1 allows 'samples N adaptive' (one ray per pixel where
 * the pixel's 3x3 neighbourhood has one key); 0 compiles it out. */
#ifndef FXRT_ADAPTIVE
#if FXRT_MAX_SAMPLES > 1 /* (a literal number, as FXRT_MAX_DEPTH) */
#define FXRT_ADAPTIVE 1
#else
#define FXRT_ADAPTIVE 0
#endif
#endif
FXRT_STATIC_ASSERT(FXRT_ADAPTIVE == 0 || FXRT_ADAPTIVE == 1, "FXRT_ADAPTIVE must be 0 or 1");
FXRT_STATIC_ASSERT(!FXRT_ADAPTIVE || FXRT_MAX_SAMPLES > 1, "FXRT_ADAPTIVE needs FXRT_MAX_SAMPLES > 1");
/* Refraction index range ('index', transparent materials). */
#define FXRT_INDEX_MIN 0.01
#define FXRT_INDEX_MAX 100

/* ---- the board program (firmware/main.c) ------------------------------- */

/* Frame mode of the firmware (make qemu FB=full|stream):
 *   1 = FXRT_FB_FULL    the whole frame in a static framebuffer, sent
 *                       after the render (default)
 *   2 = FXRT_FB_STREAM  FXRT_BAND_ROWS rows at a time, each band sent as
 *                       soon as it is rendered: RAM does not grow with the
 *                       image height (the micro:bit's default) */
#define FXRT_FB_FULL 1
#define FXRT_FB_STREAM 2
#ifndef FXRT_FB_MODE
#define FXRT_FB_MODE FXRT_FB_FULL
#endif
FXRT_STATIC_ASSERT(FXRT_FB_MODE == FXRT_FB_FULL || FXRT_FB_MODE == FXRT_FB_STREAM, "FXRT_FB_MODE must be FXRT_FB_FULL (1) or FXRT_FB_STREAM (2)");
/* Rows per band in streaming mode (1..any; RAM: 3 * width bytes a row). */
#ifndef FXRT_BAND_ROWS
#define FXRT_BAND_ROWS 1
#endif
FXRT_STATIC_ASSERT(FXRT_BAND_ROWS >= 1, "FXRT_BAND_ROWS must be at least 1");
/* Bytes of the reserved stack (STACK_SIZE in linker/BOARD.ld) that a
 * firmware run must leave unused, read from the painted stack at the end
 * of the run: firmware/main.c and tests/onboard_main.c fail the run (exit
 * 2) otherwise, so every make qemu, test and bench run checks that the
 * reservation covers what the run used, with this margin to spare. */
#ifndef FXRT_STACK_MARGIN
#define FXRT_STACK_MARGIN 512
#endif
/* Bytes the boards reserve on top of STACK_SIZE for the bounce loop and
 * the adaptive key pass when they are compiled in: trace_bounces' frame
 * with its FXRT_MAX_DEPTH pending rays (40 B each) and the shading below
 * it (FXRT_MAX_DEPTH > 0), and 256 B for the one-sample key pass under the
 * sampling pass (FXRT_ADAPTIVE). The firmware puts this many bytes in the
 * .stack_extra section, which linker/sections.ld places inside the stack;
 * firmware/fit.sh counts it. Measured on the micro:bit (M0, 2 KB
 * STACK_SIZE): the reflection scene (depth 4, 160x120, samples 2) uses
 * 2,136 B of stack, the parallel mirrors (depth 16) 2,596 B, a lit scene
 * at samples 4 adaptive 1,572 B; other scenes are unchanged. */
#ifndef FXRT_STACK_EXTRA
/* The per-pixel ray caster (FXRT_RENDERER_RAYCAST, a benchmark baseline)
 * shades a lit hit from deeper in its own loop: 1,692 B on the micro:bit
 * for scenes/lit/coloured-lights.scene, over the 2 KB stack's margin;
 * 256 B more for it. */
#define FXRT_STACK_RAYCAST (256 * (FXRT_RENDERER == FXRT_RENDERER_RAYCAST && FXRT_MAX_LIGHTS > 0))
/* A model's BVH walk (scene/bvh.c) takes about 850 B of stack on the M0
 * below the visibility pass or a shadow ray (1,648 B in all for a flat
 * icosphere on the micro:bit, over the 2 KB stack's margin): 1 KB more
 * where models are compiled in. */
#define FXRT_STACK_MODELS (1024 * (FXRT_MAX_MODELS > 0))
#define FXRT_STACK_EXTRA                                                                                     \
    ((FXRT_MAX_DEPTH > 0 ? 1024 + 48 * FXRT_MAX_DEPTH : 0) + 256 * FXRT_ADAPTIVE + FXRT_STACK_RAYCAST + FXRT_STACK_MODELS)
#endif
FXRT_STATIC_ASSERT(FXRT_STACK_EXTRA >= 0 && FXRT_STACK_EXTRA % 8 == 0, "FXRT_STACK_EXTRA must be a multiple of 8, >= 0");
/* 1: the core reserves those FXRT_STACK_EXTRA bytes itself (frame/api.c's
 * fxrt_stack_extra, in the section .stack_extra), and refers to the symbol
 * fxrt_stack_extra_needs_linker_script_keep, which a linker script
 * defines where it keeps .stack_extra at the bottom of the stack
 * (linker/sections.ld does). A firmware whose script does not fails to
 * link with that name, instead of running out of stack at its first
 * bounce (docs/EMBEDDING.md, "Stack"). Default: on bare-metal Arm when
 * FXRT_STACK_EXTRA > 0; 0 for a program that reserves the stack itself. */
#ifndef FXRT_STACK_RESERVE
#define FXRT_STACK_RESERVE (FXRT_PORT_BARE && FXRT_STACK_EXTRA > 0)
#endif
FXRT_STATIC_ASSERT(FXRT_FB_MODE != FXRT_FB_STREAM || FXRT_PIXEL == FXRT_RGB888, "streaming mode sends RGB888 rows; FXRT_RGB565 is for the full framebuffer");

#endif
