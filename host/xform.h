/* xform: the affine transforms of a scene's nodes (docs/SCENES.md,
 * "Nodes"), in doubles on the host: p -> M p + t. The scene loader applies
 * them to each object as it reads it, so every renderer build receives
 * the objects already transformed. */
#ifndef FXRT_HOST_XFORM_H
#define FXRT_HOST_XFORM_H

#include "scene.h" /* scene_vec_t */

typedef struct {
    double m[3][3]; /* linear part, row-major: p'[i] = sum_j m[i][j] p[j] + t[i] */
    double t[3];
} xform_t;

void xform_identity(xform_t *x);
/* The three steps a node line may hold, each as a transform of its own.
 * rotate: axis 0, 1, 2 for x, y, z; deg counter-clockwise seen from the
 * axis' positive side looking at the origin (right-handed). Multiples of
 * 90 degrees get exact 0 and +-1 entries. */
void xform_scale(xform_t *x, double sx, double sy, double sz);
void xform_rotate(xform_t *x, int axis, double deg);
void xform_translate(xform_t *x, double tx, double ty, double tz);
/* *r = a after b: r(p) = a(b(p)). r may alias a or b. */
void xform_after(xform_t *r, const xform_t *a, const xform_t *b);

scene_vec_t xform_point(const xform_t *x, scene_vec_t p);
/* A vector (an ellipsoid's semi-axis): the linear part alone. */
scene_vec_t xform_vector(const xform_t *x, scene_vec_t v);
/* A normal: the inverse transpose of the linear part times n, normalised.
 * 0, or -1 when the linear part is singular or n is zero. */
int xform_normal(const xform_t *x, scene_vec_t n, scene_vec_t *out);
/* 1 when the linear part is s R (R a rotation or reflection) to a relative
 * 1e-9, with *s > 0: a sphere stays a sphere of radius s r. */
int xform_similar(const xform_t *x, double *s);
/* 1 when the linear part maps each axis onto an axis (to a relative
 * 1e-12): an axis-aligned box stays axis-aligned. */
int xform_axis_aligned(const xform_t *x);

#endif
