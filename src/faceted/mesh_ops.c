/* The MESH kind's table of operations (rs_mesh_ops) and the operations that are not the
 * query's, the candidate lists' or the facets': adjacency, bounds, spin axis, display. */
#include "mesh.h"

#include <stdlib.h>
#include <string.h>

/* Does an entry of element k's triangles in per-triangle table tab (3 entries a
 * triangle: m->tri for nodes, m->tedge for edges) equal x? */
static int element_has(const rs_mesh *m, int k, const int *tab, int x)
{
    for (int t = m->el_t0[k]; t < m->el_t0[k + 1]; t++)
        for (int j = 0; j < 3; j++)
            if (tab[3 * t + j] == x)
                return 1;
    return 0;
}

/* Do elements ia and ib share an edge of the given kind? */
static int faces_share(const rs_mesh *m, int ia, int ib, int kind)
{
    for (int t = m->el_t0[ia]; t < m->el_t0[ia + 1]; t++)
        for (int j = 0; j < 3; j++) {
            const int e = m->tedge[3 * t + j];
            if (m->edge_kind[e] == kind && element_has(m, ib, m->tedge, e))
                return 1;
        }
    return 0;
}

/* History passes where the contact normal is continuous: between faces of one coplanar
 * region (joined through flat edges), between a face and its own edges and vertices, and
 * between an edge and its nodes. */
static int mesh_adjacent(const rs_surface *s, int fa, int fb)
{
    if (fa == fb)
        return 1;
    const rs_mesh *m = s->impl;
    if (!m || fa < 0 || fb < 0)
        return 0;
    int ta = RS_FEATURE_TYPE(fa), tb = RS_FEATURE_TYPE(fb);
    int ia = RS_FEATURE_INDEX(fa), ib = RS_FEATURE_INDEX(fb);
    if (ta > tb) {
        int t = ta;
        ta = tb;
        tb = t;
        t = ia;
        ia = ib;
        ib = t;
    }
    if (ta == RS_FEAT_FACE && ia >= m->nel)
        return 0;
    if (ta == RS_FEAT_FACE && tb == RS_FEAT_FACE)
        return ib < m->nel && m->el_region[ia] == m->el_region[ib];
    if (ta == RS_FEAT_FACE && tb == RS_FEAT_EDGE)
        return ib < m->ne && element_has(m, ia, m->tedge, ib);
    if (ta == RS_FEAT_FACE && tb == RS_FEAT_VERTEX)
        return ib < m->nv && element_has(m, ia, m->tri, ib);
    if (ta == RS_FEAT_EDGE && tb == RS_FEAT_VERTEX)
        return ia < m->ne && ib < m->nv &&
               (m->edge_v[2 * ia] == ib || m->edge_v[2 * ia + 1] == ib);
    return 0;
}

/* Two faces that share a CONCAVE edge. */
static int mesh_fold(const rs_surface *s, int fa, int fb)
{
    const rs_mesh *m = s->impl;
    if (!m || fa < 0 || fb < 0 || fa == fb || RS_FEATURE_TYPE(fa) != RS_FEAT_FACE ||
        RS_FEATURE_TYPE(fb) != RS_FEAT_FACE)
        return 0;
    const int ia = RS_FEATURE_INDEX(fa), ib = RS_FEATURE_INDEX(fb);
    return ia < m->nel && ib < m->nel && faces_share(m, ia, ib, RS_EDGE_CONCAVE);
}

static void mesh_bounds(const rs_surface *s, double lo[3], double hi[3])
{
    const rs_mesh *m = s->impl;
    for (int d = 0; d < 3; d++) {
        lo[d] = m ? m->lo[d] : 0.0;
        hi[d] = m ? m->hi[d] : 0.0;
    }
}

static int mesh_spin_axis(const rs_surface *s, double origin[3], double axis[3])
{
    (void)s;
    (void)origin;
    (void)axis;
    return 0;
}

static int mesh_triangulate(const rs_surface *s, double span, int nhoop, rs_trimesh *tm,
                            rs_error *err)
{
    (void)span;
    (void)nhoop;
    const rs_mesh *m = s->impl;
    memset(tm, 0, sizeof *tm);
    tm->xyz = malloc(3 * (size_t)m->nv * sizeof(double));
    tm->tri = malloc(3 * (size_t)m->nt * sizeof(int));
    if (!tm->xyz || !tm->tri) {
        free(tm->xyz);
        free(tm->tri);
        memset(tm, 0, sizeof *tm);
        return rs_error_set(err, RS_ERR_NOMEM, "out of memory for the mesh's display");
    }
    memcpy(tm->xyz, m->xyz, 3 * (size_t)m->nv * sizeof(double));
    memcpy(tm->tri, m->tri, 3 * (size_t)m->nt * sizeof(int));
    tm->cell = malloc((size_t)m->nt * sizeof(int) + 1);
    if (!tm->cell) {
        rs_trimesh_free(tm);
        return rs_error_set(err, RS_ERR_NOMEM, "out of memory for the mesh's display");
    }
    memcpy(tm->cell, m->tel, (size_t)m->nt * sizeof(int));
    tm->nvert = m->nv;
    tm->ntri = m->nt;
    return RS_OK;
}

static void mesh_free(rs_surface *s)
{
    rs_mesh_free(s->impl);
    s->impl = NULL;
}

const rs_surface_ops rs_mesh_ops = {.name = "MESH",
                                    .ndir = 3,
                                    .frame = RS_FRAME_GLOBAL_X,
                                    .closest = rs_mesh_closest,
                                    .shares = 1,
                                    .adjacent = mesh_adjacent,
                                    .fold = mesh_fold,
                                    .bounds = mesh_bounds,
                                    .spin_axis = mesh_spin_axis,
                                    .triangulate = mesh_triangulate,
                                    .free = mesh_free,
                                    .candidates = rs_mesh_candidates,
                                    .closest_among = rs_mesh_closest_among,
                                    .facet = rs_mesh_facet,
                                    .facet_size = rs_mesh_facet_size,
                                    .facet_area = rs_mesh_facet_area,
                                    .facet_index = rs_mesh_facet_index,
                                    .facet_count = rs_mesh_facet_count,
                                    .body = rs_mesh_body,
                                    .body_run = rs_mesh_body_run,
                                    .feature_point = rs_mesh_feature_point,
                                    .syntax = &rs_mesh_syntax};
