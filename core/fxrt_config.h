/* fxrt build configuration: every option lives here, documented where it is
 * defined and in the README table. Override with -D or from a generated
 * scene header included before this one. */
#ifndef FXRT_CONFIG_H
#define FXRT_CONFIG_H

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
#if FXRT_NUMBER != FXRT_Q16 && FXRT_NUMBER != FXRT_FLOAT && FXRT_NUMBER != FXRT_DOUBLE
#error "FXRT_NUMBER must be FXRT_Q16 (1), FXRT_FLOAT (2) or FXRT_DOUBLE (3)"
#endif

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
#if FXRT_RENDERER < 1 || FXRT_RENDERER > 3
#error "FXRT_RENDERER must be 1 (fast), 2 (reference) or 3 (raycast)"
#endif

/* Largest image width or height in pixels. */
#ifndef FXRT_MAX_DIM
#define FXRT_MAX_DIM 4096
#endif

/* Limits the types imply. Pixel columns and rows are stored as int16_t
 * (the renderer's per-object screen bounds), so an image side must fit
 * int16. Objects are counted and identified with uint16_t (world_t's
 * n_<kind>, scene ids, render_t's object indices), and 0xFFFF is the
 * "no object" sentinel (RAYCAST_MISS, the renderer's RO_NONE), so the
 * total capacity must stay below it. */
#if FXRT_MAX_DIM < 1 || FXRT_MAX_DIM > 32767
#error "FXRT_MAX_DIM must be in 1..32767: pixel indices are int16_t"
#endif
#if FXRT_MAX_PLANES < 0 || FXRT_MAX_SPHERES < 0 || FXRT_MAX_TRIANGLES < 0 || FXRT_MAX_BOXES < 0
#error "FXRT_MAX_<KIND> capacities must be >= 0"
#endif
#if FXRT_MAX_PLANES + FXRT_MAX_SPHERES + FXRT_MAX_TRIANGLES + FXRT_MAX_BOXES > 65535
#error "total object capacity (FXRT_MAX_PLANES + _SPHERES + _TRIANGLES + _BOXES) must be <= 65535: ids are uint16_t and 0xFFFF is the no-object sentinel"
#endif

/* Instruction-set features the fixed-point maths (core/fx.c, core/fx.h)
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
#if defined(__ARM_ARCH_6M__)
#define FXRT_ARCH_SMALL_ISA 1
#else
#define FXRT_ARCH_SMALL_ISA 0
#endif
#ifndef FX_HAVE_UDIV
#define FX_HAVE_UDIV (!FXRT_ARCH_SMALL_ISA)
#endif
#ifndef FX_HAVE_CLZ
#define FX_HAVE_CLZ (!FXRT_ARCH_SMALL_ISA)
#endif
#ifndef FX_HAVE_UMULL
#define FX_HAVE_UMULL (!FXRT_ARCH_SMALL_ISA)
#endif

#endif
