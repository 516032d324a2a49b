/* meshemit: a mesh as C (see meshemit.h). */
#include "meshemit.h"

static void emit_i16(FILE *f, const int16_t (*a)[3], uint32_t n)
{
    for (uint32_t i = 0; i < n; i++)
        fprintf(f, "%s{%d, %d, %d},%s", i % 4 ? " " : "    ", a[i][0], a[i][1], a[i][2], i % 4 == 3 || i + 1 == n ? "\n" : "");
}

void meshemit_arrays(FILE *f, const meshbuild_t *mb, const char *name)
{
    const bvh_mesh_t *m = &mb->mesh;
    fprintf(f, "static const int16_t %s_v[%u][3] = {\n", name, m->n_vertices);
    emit_i16(f, m->v, m->n_vertices);
    fprintf(f, "};\n");
    if (m->vn) {
        fprintf(f, "static const int16_t %s_vn[%u][3] = {\n", name, m->n_vertices);
        emit_i16(f, m->vn, m->n_vertices);
        fprintf(f, "};\n");
    }
    fprintf(f, "static const %s %s_tri[%u][3] = {\n", m->tri16 ? "uint16_t" : "uint32_t", name, m->n_triangles);
    for (uint32_t i = 0; i < m->n_triangles; i++) {
        uint32_t v[3];
        bvh_tri(m, i, v);
        fprintf(f, "%s{%u, %u, %u},%s", i % 4 ? " " : "    ", v[0], v[1], v[2], i % 4 == 3 || i + 1 == m->n_triangles ? "\n" : "");
    }
    fprintf(f, "};\n");
    fprintf(f, "static const fxrt_mesh_node_t %s_node[%u] = {\n", name, m->n_nodes);
    for (uint32_t i = 0; i < m->n_nodes; i++) {
        const bvh_node_t *n = &m->node[i];
        fprintf(f, "    {{%d, %d, %d}, {%d, %d, %d}, 0x%xu},\n", n->lo[0], n->lo[1], n->lo[2], n->hi[0], n->hi[1], n->hi[2],
                n->link);
    }
    fprintf(f, "};\n");
}

void meshemit_header(FILE *f, const meshbuild_t *mb, const char *name, const char *header, bool normals,
                     const char *storage)
{
    const bvh_mesh_t *m = &mb->mesh;
    bool vn = normals && m->vn;
    fprintf(f, "%sconst fxrt_mesh_t %s = {%u, %u, %u, %s_v, %s%s, %s%s, %s%s, %s_node};\n", storage, header,
            m->n_vertices, m->n_triangles, m->n_nodes, name, vn ? name : "NULL", vn ? "_vn" : "",
            m->tri16 ? name : "NULL", m->tri16 ? "_tri" : "", m->tri16 ? "NULL" : name, m->tri16 ? "" : "_tri", name);
}

void meshemit_instance(FILE *f, const char *storage, const char *name, const char *mesh, const meshbuild_map_t *m)
{
    fprintf(f, "%sconst fxrt_instance_t %s = {&%s,\n    {", storage, name, mesh);
    for (int r = 0; r < 3; r++)
        fprintf(f, "%s{%ld, %ld, %ld}", r ? ", " : "", (long)m->m[r][0], (long)m->m[r][1], (long)m->m[r][2]);
    fprintf(f, "}, %ld,\n    {FXRT_NUM(%a), FXRT_NUM(%a), FXRT_NUM(%a)},\n    {", (long)m->e, m->t16[0] / 65536.0,
            m->t16[1] / 65536.0, m->t16[2] / 65536.0);
    for (int r = 0; r < 3; r++)
        fprintf(f, "%s{%ld, %ld, %ld}", r ? ", " : "", (long)m->f[r][0], (long)m->f[r][1], (long)m->f[r][2]);
    fprintf(f, "}, %ld};\n", (long)m->fe);
}

int meshemit_c(FILE *f, const meshbuild_t *mb, const char *name, const char *src)
{
    const bvh_mesh_t *m = &mb->mesh;
    fprintf(f, "/* %s: the mesh of %s, written by fxrt-scenec --mesh (host/meshemit.c).\n", name, src);
    fprintf(f, " * %u triangles, %u vertices, %u nodes (depth %d), %zu bytes of constant data.\n", m->n_triangles,
            m->n_vertices, m->n_nodes, mb->depth, meshbuild_bytes(mb));
    fprintf(f, " * A model point is origin + step q: origin (%.17g, %.17g, %.17g), step %.17g. */\n", mb->origin[0],
            mb->origin[1], mb->origin[2], mb->step);
    fprintf(f, "#include \"fxrt.h\"\n\n");
    meshemit_arrays(f, mb, name);
    meshemit_header(f, mb, name, name, true, "");
    return ferror(f) ? -1 : 0;
}

void meshemit_summary(FILE *f, const meshbuild_t *mb, const char *src)
{
    const bvh_mesh_t *m = &mb->mesh;
    size_t bytes = meshbuild_bytes(mb);
    fprintf(f, "mesh=%s triangles=%u vertices=%u nodes=%u depth=%d bytes=%zu bytes_per_triangle=%.2f index_bits=%d "
               "dropped=%zu normals=%s\n",
            src, m->n_triangles, m->n_vertices, m->n_nodes, mb->depth, bytes, (double)bytes / m->n_triangles,
            m->tri16 ? 16 : 32, mb->dropped, m->vn ? "smooth" : mb->face_normals ? "flat(the_faces'_own)" : "flat");
}
