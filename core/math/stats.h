/* fxrt_stats: optional work counters (FXRT_STATS 1), for the tests that
 * prove the renderer skips what a scene does not need (tests/test_skip.c):
 * how many shadow rays, per-pixel light-vector normalisations, normal
 * normalisations, Phong power products and spot cosines a frame took.
 * With FXRT_STATS 0 (the default) the counters compile to nothing. */
#ifndef FXRT_STATS_H
#define FXRT_STATS_H

#include <stdint.h>

#include "fxrt_config.h"

typedef struct {
    uint32_t shaded;       /* shade_point calls */
    uint32_t shadow_rays;  /* shadow_blocked calls */
    uint32_t l_normalised; /* per-pixel normalisations of a light vector (its length taken) */
    uint32_t l_units;      /* of those, unit vectors l made (a lambert plane's: only for a shadow ray) */
    uint32_t n_normalised; /* per-pixel normalisations of a surface normal */
    uint32_t phong;        /* Phong powers evaluated */
    uint32_t pow_products; /* products inside those powers */
    uint32_t cosines;      /* cosines computed (spot cones) */
    uint32_t secondary_rays; /* reflected and transmitted rays traced (light/trace.c) */
    uint32_t bounds_skips;   /* of those, rays that missed the bounds box */
    uint32_t flat_nums;      /* hit numerators (a - e) . n of planes and triangles (frame/render_shade.c) */
    uint32_t d_normalised;   /* camera rays normalised by the shading pass (light/hit.c) */
    uint32_t plane_points;   /* hit points the shading pass made for planes and triangles (light/shade.c, light/hit.c) */
    uint32_t dir_sums;       /* a plane's light sums under directional lights only (light/shade.c: per pixel, or per run) */
    uint32_t spot_blocks;    /* blocks of a plane's run that no spot reaches (light/shade.c: shade_plane_spots_out) */
    uint32_t phong_blocks;   /* blocks of a Phong plane's run without a specular term (light/shade.c: shade_flat_phong_blocks) */
    uint32_t plane_forms;    /* plane pixels whose n . l came from the run's forms, without a hit point (light/shade.c: shade_plane_forms) */
    uint32_t raw_roots;      /* 1 / |d| made for a Phong term along a raw direction (light/shade.c) */
} fxrt_stats_t;
extern fxrt_stats_t fxrt_stats; /* (defined always; unused and dropped by the linker unless FXRT_STATS) */
#if FXRT_STATS
#define FXRT_COUNT(field) ((void)(fxrt_stats.field++))
#else
#define FXRT_COUNT(field) ((void)0)
#endif

#endif
