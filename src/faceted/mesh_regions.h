/* What the MESH kind's query (mesh_query.c) and its candidate lists (mesh_candidates.c)
 * share: the tests of the Voronoi regions of faces, edges and vertices, each one
 * expression of the shared data (mesh_query.c), the pose, and the tree's triangles in a
 * box. Static inline, so that the query's hot loops inline them as before. Private to
 * src/faceted/. */
#ifndef RS_FACETED_MESH_REGIONS_H
#define RS_FACETED_MESH_REGIONS_H

#include "cgal_mesh.h"
#include "mesh.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* p's side of edge slot j of triangle t: p . m_j - c_j (rs_mtri.e), > 0 inside. */
static inline double side_of(const rs_mesh *m, int t, int j, const double p[3])
{
    const double *r = m->rec[t].e[j];
    return p[0] * r[0] + p[1] * r[1] + p[2] * r[2] - r[3];
}

/* Does x, a point of t's plane, lie in triangle t: on the inner side of each of its
 * edges' planes, ties included (rs_mesh_triangle_holds)? */
static inline int tri_holds(const rs_mesh *m, int t, const double x[3])
{
    return side_of(m, t, 0, x) >= 0.0 && side_of(m, t, 1, x) >= 0.0 &&
           side_of(m, t, 2, x) >= 0.0;
}

/* (p - v).(w - v): the position of p along the edge of nodes v and w, seen from v. */
static inline double along(const rs_mesh *m, int v, int w, const double p[3])
{
    const double *pv = m->xyz + 3 * v, *pw = m->xyz + 3 * w;
    return (p[0] - pv[0]) * (pw[0] - pv[0]) + (p[1] - pv[1]) * (pw[1] - pv[1]) +
           (p[2] - pv[2]) * (pw[2] - pv[2]);
}

/* The nodes of the edge of slot j of triangle record r, lower index first as in edge_v:
 * from the record, without a look into edge_v. */
static inline void slot_nodes(const rs_mtri *r, int j, int *a, int *b)
{
    const int u = r->v[j], w = r->v[(j + 1) % 3];
    *a = u < w ? u : w;
    *b = u < w ? w : u;
}

/* Does vertex v own p: at or beyond v along each of its edges, (p - v).(w - v) <= 0 for
 * each neighbour w (the products of along_from)? With ext > 0: could it own a point
 * within ext of p, (p - v).(w - v) <= ext |w - v| for each w (may_own)? */
static inline int vertex_owns(const rs_mesh *m, int v, const double p[3], double ext)
{
    const double *pv = m->xyz + 3 * v;
    const double w[3] = {p[0] - pv[0], p[1] - pv[1], p[2] - pv[2]};
    for (int k = m->vert_e0[v]; k < m->vert_e0[v + 1]; k++) {
        const double *pw = m->xyz + 3 * m->vert_w[k];
        const double u[3] = {pw[0] - pv[0], pw[1] - pv[1], pw[2] - pv[2]};
        if (rs_dot3(w, u) > (ext > 0.0 ? ext * rs_norm3(u) : 0.0))
            return 0;
    }
    return 1;
}

/* p's height over the plane of triangle t, (p - a0).n: the one expression of it. */
static inline double plane_height(const rs_mesh *m, int t, const double p[3])
{
    const rs_mtri *r = m->rec + t;
    return (p[0] - r->a0[0]) * r->n[0] + (p[1] - r->a0[1]) * r->n[1] +
           (p[2] - r->a0[2]) * r->n[2];
}

/* A lower bound of the squared distance from p to triangle t, from its plane's distance
 * h and its edges' sides sd (side_of, unit normals: outside an edge by -sd at least). */
static inline double tri_bound(const rs_mesh *m, int t, const double p[3], double *h,
                               double sd[3])
{
    const rs_mtri *r = m->rec + t;
    *h = plane_height(m, t, p);
    double out = 0.0;
    for (int j = 0; j < 3; j++) {
        const double *rj = r->e[j];
        sd[j] = p[0] * rj[0] + p[1] * rj[1] + p[2] * rj[2] - rj[3];
        out = -sd[j] > out ? -sd[j] : out;
    }
    return *h * *h + out * out;
}

/* The contact of p on the face of triangle t, p at height h over its plane: its foot x,
 * its unit normal n toward p's side (behind a one-sided mesh, the face's own) and its
 * signed distance, returned (< 0 behind a one-sided mesh). */
static inline double face_contact(const rs_mesh *m, int t, int one_sided, const double p[3],
                                  double h, double x[3], double n[3])
{
    const double *nt = m->rec[t].n;
    const double sg = (!one_sided && h < 0.0) ? -1.0 : 1.0;
    for (int d = 0; d < 3; d++) {
        x[d] = p[d] - h * nt[d];
        n[d] = sg * nt[d];
    }
    return sg * h;
}

/* The squared distance from x to the segment a b, and the distance. */
static inline double segment_distance2(const double a[3], const double b[3],
                                       const double x[3])
{
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double w[3] = {x[0] - a[0], x[1] - a[1], x[2] - a[2]};
    const double f = fmin(1.0, fmax(0.0, rs_dot3(w, u) / rs_dot3(u, u)));
    const double d[3] = {w[0] - f * u[0], w[1] - f * u[1], w[2] - f * u[2]};
    return rs_dot3(d, d);
}

static inline double segment_distance(const double a[3], const double b[3],
                                      const double x[3])
{
    return sqrt(segment_distance2(a, b, x));
}

/* The triangles that meet the cube of half-width reach about p, and a few more near it
 * (rs_cgal_tree_box), into *ids (room for *cap, grown as needed); returns their number, -1
 * when out of memory. Each caller tests every triangle's distance. */
static inline int box_triangles(const rs_mesh *m, const double p[3], double reach,
                                int **ids, int *cap)
{
    const double pad = reach + 1e-9 * m->size;
    const double lo[3] = {p[0] - pad, p[1] - pad, p[2] - pad};
    const double hi[3] = {p[0] + pad, p[1] + pad, p[2] + pad};
    int n = rs_cgal_tree_box(m->tree, lo, hi, *ids, *cap);
    if (n > *cap) {
        int *ni = realloc(*ids, (size_t)n * 2 * sizeof *ni);
        if (!ni)
            return -1;
        *ids = ni;
        *cap = 2 * n;
        n = rs_cgal_tree_box(m->tree, lo, hi, *ids, *cap);
    }
    return n;
}

/* A pose, NULL where it is the identity (a mesh in its reference configuration): its
 * points and results then need no transform. */
static inline const rs_pose *pose_moved(const rs_pose *p)
{
    if (!p)
        return NULL;
    for (int a = 0; a < 9; a++)
        if (p->R[a] != (a % 4 == 0 ? 1.0 : 0.0))
            return p;
    return p->T[0] != 0.0 || p->T[1] != 0.0 || p->T[2] != 0.0 ? p : NULL;
}

/* The query's pose, NULL where it is the identity. */
static inline const rs_pose *moved_pose(const rs_query *q)
{
    return pose_moved(q->pose);
}

/* p, slave i of q, in the reference configuration (pose: moved_pose(q)). */
static inline void slave_local(const rs_query *q, const rs_pose *pose, int i, double p[3])
{
    const double x[3] = {q->slave.x[i], q->slave.y[i], q->slave.z[i]};
    if (pose) { /* X = R^T (x - T) */
        const double w[3] = {x[0] - pose->T[0], x[1] - pose->T[1], x[2] - pose->T[2]};
        for (int d = 0; d < 3; d++)
            p[d] = pose->R[d] * w[0] + pose->R[3 + d] * w[1] + pose->R[6 + d] * w[2];
    } else {
        memcpy(p, x, 3 * sizeof(double));
    }
}

#endif
