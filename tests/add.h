/* add: the tests' shorthand for adding one object of each kind to a world
 * (world_add takes a description, scene/kinds.h's geom_desc_t). */
#ifndef FXRT_TESTS_ADD_H
#define FXRT_TESTS_ADD_H

#include "../core/scene/world.h"

static inline int32_t world_add_plane(world_t *w, vec3_t point, vec3_t normal, color_t color)
{
    geom_desc_t d = {.kind = GEOM_PLANE, .p = {point, normal}, .color = color};
    return world_add(w, &d);
}
static inline int32_t world_add_sphere(world_t *w, vec3_t center, num_t radius, color_t color)
{
    geom_desc_t d = {.kind = GEOM_SPHERE, .p = {center}, .radius = radius, .color = color};
    return world_add(w, &d);
}
static inline int32_t world_add_triangle(world_t *w, vec3_t a, vec3_t b, vec3_t c, color_t color)
{
    geom_desc_t d = {.kind = GEOM_TRIANGLE, .p = {a, b, c}, .color = color};
    return world_add(w, &d);
}
static inline int32_t world_add_box(world_t *w, vec3_t min, vec3_t max, color_t color)
{
    geom_desc_t d = {.kind = GEOM_BOX, .p = {min, max}, .color = color};
    return world_add(w, &d);
}

#endif
