/* model: a mesh in constant data, placed in the world (scene/bvh.h has the
 * data and the queries; docs/MESHES.md the layout). The record holds the
 * placement and a box around it; every test walks the mesh's tree. */
#include "scene/kinds.h"

#if FXRT_MAX_MODELS > 0
static bool geom_model_node_box(const bvh_inst_t *in, const bvh_node_t *nd, vec3_t *lo, vec3_t *hi);

bool geom_model_box(const bvh_inst_t *in, vec3_t *lo, vec3_t *hi)
{
    /* m f = 2^(e + fe) (I + E) with |E| <= 2^-12 per entry: then the
     * forward map is the queries' (the inverse of m 2^-e) times (I + E),
     * and a point it places is off by at most 3 2^-12 of the sum of |f q|
     * over the axes, which the padding below (2^-10 of it) covers. Each
     * product is below 2^60, a sum of three below 2^62. */
    int s = in->e + in->fe;
    if (s > 61)
        return false;
    int64_t one = (int64_t)1 << s, tol = s >= 12 ? (int64_t)1 << (s - 12) : 0;
    for (int j = 0; j < 3; j++)
        for (int l = 0; l < 3; l++) {
            int64_t v = 0;
            for (int k = 0; k < 3; k++)
                v += (int64_t)in->m[j][k] * in->f[k][l];
            v -= j == l ? one : 0;
            if (v > tol || v < -tol)
                return false;
        }
    return geom_model_node_box(in, &in->mesh->node[0], lo, hi);
}

/* The box of node nd (the root: the model's), as geom_model_box says,
 * with the maps checked. */
static bool geom_model_node_box(const bvh_inst_t *in, const bvh_node_t *nd, vec3_t *lo, vec3_t *hi)
{
    const num_t t[3] = {in->t.x, in->t.y, in->t.z};
    num_t out_lo[3], out_hi[3];
    for (int i = 0; i < 3; i++) {
        /* sum over j of f_ij q_j for q in the node's box: its least and
         * greatest value, and the padding (below 3 2^45 each) */
        int64_t a = 0, b = 0, pad = 0;
        for (int j = 0; j < 3; j++) {
            int64_t p = (int64_t)in->f[i][j] * nd->lo[j], q = (int64_t)in->f[i][j] * nd->hi[j];
            a += p < q ? p : q;
            b += p < q ? q : p;
            int64_t ap = p < 0 ? -p : p, aq = q < 0 ? -q : q;
            pad += ap > aq ? ap : aq;
        }
        pad = (pad >> 10) + 1;
        a -= pad;
        b += pad;
        if (NUM_EXACT) {
            /* raw Q16.16: the sum 2^(16 - fe), rounded outward, plus T and
             * one LSB each side */
            int sh = 16 - in->fe;
            int64_t ra = sh >= 0 ? a * ((int64_t)1 << sh) : (sh <= -62 ? (a < 0 ? -1 : 0) : a >> -sh);
            int64_t rb = sh >= 0 ? b * ((int64_t)1 << sh) : (sh <= -62 ? (b > 0 ? 1 : 0) : -((-b) >> -sh));
            ra += (int64_t)num_to_q16(t[i]) - 1;
            rb += (int64_t)num_to_q16(t[i]) + 1;
            const int64_t lim = (int64_t)FXRT_COORD_LIMIT << 16;
            if (ra < -lim || rb > lim)
                return false;
            out_lo[i] = num_from_q16((int32_t)ra);
            out_hi[i] = num_from_q16((int32_t)rb);
        } else {
            num_t sc = bvh_unscale(in->fe), lim = num_from_int(FXRT_COORD_LIMIT);
            num_t fa = t[i] + (num_t)a * sc, fb = t[i] + (num_t)b * sc;
            /* the arithmetic's own rounding: 2^-20 of the magnitudes */
            num_t r = (num_abs(t[i]) + (num_t)(b - a) * sc) * (num_t)(1.0 / 1048576) + (num_t)(1.0 / 65536);
            fa = fa - r;
            fb = fb + r;
            if (!(fa >= -lim && fb <= lim))
                return false;
            out_lo[i] = fa;
            out_hi[i] = fb;
        }
    }
    *lo = vec3_make(out_lo[0], out_lo[1], out_lo[2]);
    *hi = vec3_make(out_hi[0], out_hi[1], out_hi[2]);
    return true;
}

fxrt_err_t geom_model_check(const bvh_inst_t *inst, color_t color)
{
    vec3_t lo, hi;
    if (!inst)
        return FXRT_ERR_NULL;
    if (!bvh_check(inst) || !geom_model_box(inst, &lo, &hi))
        return FXRT_ERR_MESH;
    return geom_check_color(color);
}

/* After geom_model_check (world_add calls it first): its bvh_check walks
 * the whole mesh, once per model added, not twice. */
bool geom_model_make(geom_model_t *m, const bvh_inst_t *inst, color_t color, uint16_t id)
{
    m->in = *inst;
    geom_common_init(&m->obj, color, id);
    return geom_model_box(inst, &m->lo, &m->hi);
}

bool geom_model_hit(const geom_model_t *o, const ray_t *ray, num_t *t)
{
    return geom_model_hit_from(o, ray, BVH_NONE, t, NULL);
}

bool geom_model_hit_from(const geom_model_t *o, const ray_t *ray, uint32_t skip, num_t *t, uint32_t *tri)
{
    bvh_hit_t h;
    if (!bvh_first(&o->in, ray, NUM_MAX, skip, &h))
        return false;
    *t = h.t;
    if (tri)
        *tri = h.tri;
    return true;
}

bool geom_model_occludes(const geom_model_t *o, const ray_t *ray, num_t tmax)
{
    return bvh_any(&o->in, ray, tmax, BVH_NONE);
}

bool geom_model_occludes_from(const geom_model_t *o, const ray_t *ray, num_t tmax, uint32_t skip)
{
    return bvh_any(&o->in, ray, tmax, skip);
}

/* The winding normal (b - a) x (c - a) of the triangle met, as the
 * geometric normal; where the mesh has vertex normals, the smooth one too.
 * A ray that the renderer found to meet the model meets it again here:
 * the same query on the same ray (a camera ray), or the triangle its
 * search met alone (the visibility pass's, a secondary ray's), the same
 * t and weights; should it not, t = 0 and n = -d. */
void geom_model_surface_part(const geom_model_t *o, const ray_t *ray, uint32_t known, num_t *t, vec3_t *n,
                             geom_part_t *part)
{
    bvh_hit_t h;
    part->tri = BVH_NONE;
    part->smooth = false;
    bool met = known != BVH_NONE ? bvh_hit_tri(&o->in, ray, known, &h) : bvh_nearest(&o->in, ray, NUM_MAX, BVH_NONE, &h);
    if (!met || !bvh_normal(&o->in, &h, false, n)) {
        *t = NUM_ZERO;
        *n = vec3_neg(ray->d);
        return;
    }
    *t = h.t;
    part->tri = h.tri;
    part->smooth = o->in.mesh->vn && bvh_normal(&o->in, &h, true, &part->ns);
}

void geom_model_surface(const geom_model_t *o, const ray_t *ray, num_t *t, vec3_t *n)
{
    geom_part_t part;
    geom_model_surface_part(o, ray, BVH_NONE, t, n, &part);
}

int geom_model_cut(const geom_model_t *o, uint32_t node[], int n)
{
    const bvh_mesh_t *m = o->in.mesh;
    int count = 1;
    node[0] = 0;
    /* Split the inner node of the widest box (summed edges, mesh units)
     * until there are n nodes or only leaves. */
    while (count < n) {
        int best = -1;
        int32_t widest = -1;
        for (int i = 0; i < count; i++) {
            const bvh_node_t *nd = &m->node[node[i]];
            if ((nd->link & 15u) != 0 || (nd->link >> 4) + 1 >= m->n_nodes)
                continue; /* a leaf (its link counts triangles) */
            int32_t wd = 0;
            for (int k = 0; k < 3; k++)
                wd += (int32_t)nd->hi[k] - nd->lo[k];
            if (wd > widest) {
                widest = wd;
                best = i;
            }
        }
        if (best < 0)
            break;
        uint32_t first = m->node[node[best]].link >> 4;
        node[best] = first;
        node[count++] = first + 1;
    }
    return count;
}

bool geom_model_cut_box(const geom_model_t *o, uint32_t node, vec3_t *lo, vec3_t *hi)
{
    return geom_model_node_box(&o->in, &o->in.mesh->node[node], lo, hi);
}

void geom_model_bounds(const geom_model_t *o, vec3_t *lo, vec3_t *hi)
{
    *lo = o->lo;
    *hi = o->hi;
}

/* The sphere around the box, as a box's (scene/box.c). */
void geom_model_around(const geom_model_t *o, vec3_t *c, num_t *r)
{
    *c = vec3_make(num_half(num_add(o->lo.x, o->hi.x)), num_half(num_add(o->lo.y, o->hi.y)),
                   num_half(num_add(o->lo.z, o->hi.z)));
    *r = num_max(vec3_len(vec3_sub(o->hi, *c)), vec3_len(vec3_sub(*c, o->lo)));
}
#endif
