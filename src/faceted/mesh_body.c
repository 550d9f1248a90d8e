/* What a convex body's query against a MESH asks of the mesh (mesh_body_query.c;
 * docs/conventions.md, "Convex bodies"): the triangles near a box, whether a triangle
 * holds a point or meets a ball at its face only, the feature that owns a direction at a
 * point of a triangle (the Voronoi rules of the point query, mesh_query.c) and the
 * coplanar regions of a set of triangles. All in the reference configuration. */
#include "mesh.h"
#include "mesh_regions.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A point of a triangle lies on its edge j where its side is within this fraction of the
 * triangle's longest edge: the witness points of the pair queries carry their rounding. */
#define RS_BODY_ON_EDGE 1e-8
/* A direction lies in a feature's normal cone where it leaves the cone by at most this
 * (the cosine of its angle to a bounding plane). */
#define RS_BODY_CONE_TOL 1e-12

int rs_mesh_box_candidates(const rs_surface *s, const double lo[3], const double hi[3],
                           int *ids, int cap)
{
    const rs_mesh *m = s->impl;
    const double pad = 1e-9 * m->size;
    const double l[3] = {lo[0] - pad, lo[1] - pad, lo[2] - pad};
    const double h[3] = {hi[0] + pad, hi[1] + pad, hi[2] + pad};
    return rs_cgal_tree_box(m->tree, l, h, ids, cap);
}

int rs_mesh_feature_point(const rs_surface *s, const rs_pose *pose, int f,
                          const double x[3], double radius, double gap_max,
                          double depth_max, double *dist, double xm[3], double n[3],
                          double t1[3], double t2[3])
{
    const rs_mesh *m = s->impl;
    const int el = RS_FEATURE_INDEX(f);
    if (!m || RS_FEATURE_TYPE(f) != RS_FEAT_FACE || f != RS_FEATURE_BASE(f) || el < 0 ||
        el >= m->nel || m->el_t0[el + 1] != m->el_t0[el] + 1)
        return 0; /* a face of one triangle: closest's only contact of that face */
    const int t = m->el_t0[el];
    pose = pose_moved(pose);
    double p[3]; /* the point in the reference configuration, as slave_local maps it */
    if (pose) {
        const double w[3] = {x[0] - pose->T[0], x[1] - pose->T[1], x[2] - pose->T[2]};
        for (int d = 0; d < 3; d++)
            p[d] = pose->R[d] * w[0] + pose->R[3 + d] * w[1] + pose->R[6 + d] * w[2];
    } else {
        memcpy(p, x, sizeof p);
    }
    /* point_hits' face test: inside every edge of t (its sides, tri_bound's products),
     * its plane within the query's reach, the distance within its limits */
    for (int j = 0; j < 3; j++)
        if (!(side_of(m, t, j, p) > 0.0))
            return 0;
    const double gap_lim = gap_max + radius, dist_min = -depth_max;
    const double lim = gap_lim > -dist_min ? gap_lim : -dist_min, h = plane_height(m, t, p);
    if (!(gap_lim >= 0.0) || !(h * h <= lim * lim))
        return 0;
    const int one_sided = s->sides != 2;
    double X[3], N[3];
    const double d = face_contact(m, t, one_sided, p, h, X, N);
    /* behind a one-sided mesh a face's penetration may give way to a neighbour's */
    if (!(d <= gap_lim && d >= dist_min) || (one_sided && d < 0.0))
        return 0;
    *dist = d;
    if (t1 && t2)
        for (int k = 0; k < 3; k++)
            t1[k] = t2[k] = 0.0;
    if (pose) {
        rs_matvec3(pose->R, X, xm);
        rs_matvec3(pose->R, N, n);
        for (int k = 0; k < 3; k++)
            xm[k] += pose->T[k];
    } else {
        memcpy(xm, X, sizeof X);
        memcpy(n, N, sizeof N);
    }
    return 1;
}

int rs_mesh_triangle_holds(const rs_surface *s, int t, const double x[3])
{
    return tri_holds(s->impl, t, x);
}

/* Is x clearly farther than r from the segment ab: outside the segment's box grown by r
 * and a margin far above the rounding of segment_distance2, on some axis? */
static int clear_of_segment(const double a[3], const double b[3], const double x[3],
                            double r)
{
    for (int d = 0; d < 3; d++) {
        const double lo = a[d] < b[d] ? a[d] : b[d], hi = a[d] < b[d] ? b[d] : a[d];
        const double g = r + 1e-9 * (r + hi - lo) + 1e-300;
        if (x[d] < lo - g || x[d] > hi + g)
            return 1;
    }
    return 0;
}

int rs_mesh_triangle_plain(const rs_surface *s, int t, const double c[3], double r)
{
    const rs_mesh *m = s->impl;
    const rs_mtri *rec = m->rec + t;
    /* the edges and nodes that may spoil it: those not FLAT, those not inside a coplanar
     * region */
    const unsigned rough = rec->rough;
    if (!rough)
        return 1;
    /* c clearly farther than r from the plane of edge j (through it, normal to t) is
     * farther from the edge and its two nodes: those need no distance (a margin far above
     * the rounding of side_of and of the distances) */
    const double g =
        r + 1e-9 * (r + m->size + fabs(c[0]) + fabs(c[1]) + fabs(c[2])) + 1e-300;
    int far[3];
    for (int j = 0; j < 3; j++)
        far[j] = fabs(side_of(m, t, j, c)) > g;
    for (int j = 0; j < 3; j++) {
        if (far[j])
            continue;
        const double *a = m->xyz + 3 * rec->v[j];
        if (rough >> j & 1u) {
            const double *b = m->xyz + 3 * rec->v[(j + 1) % 3];
            if (!clear_of_segment(a, b, c, r) && segment_distance2(a, b, c) <= r * r)
                return 0;
        }
        const double d[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        if ((rough >> (3 + j) & 1u) && !far[(j + 2) % 3] && rs_dot3(d, d) <= r * r)
            return 0;
    }
    return 1;
}

int rs_mesh_beyond_concave(const rs_surface *s, int t, const double x[3])
{
    const rs_mesh *m = s->impl;
    const rs_mtri *r = m->rec + t;
    for (int j = 0; j < 3; j++) {
        if (r->kind[j] != RS_EDGE_CONCAVE || !(side_of(m, t, j, x) < 0.0))
            continue;
        const int v = r->v[j], w = r->v[(j + 1) % 3];
        const double *pv = m->xyz + 3 * v, *pw = m->xyz + 3 * w;
        const double u[3] = {pw[0] - pv[0], pw[1] - pv[1], pw[2] - pv[2]};
        const double a = along(m, v, w, x);
        if (a >= 0.0 && a <= rs_dot3(u, u))
            return 1;
    }
    return 0;
}

/* Does vertex v own direction n strictly: n.(w - v) < -tol |w - v| for each neighbour w
 * (the products of vertex_owns at v + n, away from the cone's border)? */
static int vertex_cone(const rs_mesh *m, int v, const double n[3])
{
    const double *pv = m->xyz + 3 * v;
    for (int k = m->vert_e0[v]; k < m->vert_e0[v + 1]; k++) {
        const double *pw = m->xyz + 3 * m->vert_w[k];
        const double u[3] = {pw[0] - pv[0], pw[1] - pv[1], pw[2] - pv[2]};
        if (!(rs_dot3(n, u) < -RS_BODY_CONE_TOL * rs_norm3(u)))
            return 0;
    }
    return 1;
}

/* Does edge e own direction n: outside each of its faces' edge planes, n.m <= tol (the
 * tests of edge_owns at a point of the edge moved along n)? *face gets the face feature
 * of a face whose normal n is (the cone's border: the face keeps it), else
 * RS_FEATURE_NONE; pn the mean of its first two faces' normals, as point_hits reads it. */
static int edge_cone(const rs_mesh *m, int e, const double n[3], int *face, int *tri,
                     double pn[3])
{
    *face = RS_FEATURE_NONE;
    pn[0] = pn[1] = pn[2] = 0.0;
    for (int k = m->edge_f0[e]; k < m->edge_f0[e + 1]; k++) {
        const int f = m->edge_f[k];
        int j = 0;
        while (m->tedge[3 * f + j] != e)
            j++;
        if (rs_dot3(n, m->rec[f].e[j]) > RS_BODY_CONE_TOL)
            return 0;
        if (*face == RS_FEATURE_NONE &&
            fabs(rs_dot3(n, m->rec[f].n)) >= 1.0 - RS_BODY_CONE_TOL)
            *face = RS_FEATURE(RS_FEAT_FACE, m->rec[f].el), *tri = f;
        if (k - m->edge_f0[e] < 2)
            for (int d = 0; d < 3; d++)
                pn[d] += m->rec[f].n[d];
    }
    return 1;
}

int rs_mesh_direction_owner(const rs_surface *s, int t, const double x[3],
                            const double n[3], int *tri)
{
    *tri = t;
    const rs_mesh *m = s->impl;
    const rs_mtri *r = m->rec + t;
    const int face = RS_FEATURE(RS_FEAT_FACE, r->el);
    const int one_sided = s->sides != 2;
    double len = 0.0;
    for (int j = 0; j < 3; j++) {
        const double *a = m->xyz + 3 * r->v[j], *b = m->xyz + 3 * r->v[(j + 1) % 3];
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        len = fmax(len, rs_norm3(u));
    }
    int on[3];
    for (int j = 0; j < 3; j++)
        on[j] = side_of(m, t, j, x) <= RS_BODY_ON_EDGE * len;
    /* inside t, or t's own normal on its border (flat edges and the vertices inside a
     * coplanar region have no other) */
    if ((!on[0] && !on[1] && !on[2]) || fabs(rs_dot3(n, r->n)) >= 1.0 - RS_BODY_CONE_TOL)
        return face;
    *tri = -1;
    /* a vertex (between slots j - 1 and j) where n is inside its cone; none inside a
     * coplanar region */
    for (int j = 0; j < 3; j++) {
        const int v = r->v[j];
        if (!on[j] || !on[(j + 2) % 3] || m->vflat[v] || !vertex_cone(m, v, n))
            continue;
        if (one_sided && rs_dot3(n, m->vpn + 3 * v) < 0.0)
            return RS_FEATURE_NONE; /* behind: the faces answer */
        return RS_FEATURE(RS_FEAT_VERTEX, v);
    }
    /* an edge whose cone holds n, or a face of it whose normal n is; at an end of the
     * edge, n does not point beyond that end (the along tests of edge_owns); a FLAT edge
     * owns nothing */
    for (int j = 0; j < 3; j++) {
        double pn[3];
        int f, ft;
        if (!on[j] || r->kind[j] == RS_EDGE_FLAT ||
            !edge_cone(m, r->edge[j], n, &f, &ft, pn))
            continue;
        const double *a = m->xyz + 3 * r->v[j], *b = m->xyz + 3 * r->v[(j + 1) % 3];
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const double lu = rs_norm3(u), nu = rs_dot3(n, u);
        if ((on[(j + 2) % 3] && nu < -RS_BODY_CONE_TOL * lu) ||
            (on[(j + 1) % 3] && nu > RS_BODY_CONE_TOL * lu))
            continue;
        if (f != RS_FEATURE_NONE) {
            *tri = ft;
            return f;
        }
        if (one_sided && rs_dot3(n, pn) < 0.0)
            return RS_FEATURE_NONE;
        return RS_FEATURE(RS_FEAT_EDGE, r->edge[j]);
    }
    return RS_FEATURE_NONE;
}

static int find_root(int *parent, int k)
{
    while (parent[k] != k) {
        parent[k] = parent[parent[k]];
        k = parent[k];
    }
    return k;
}

static int cmp_int(const void *a, const void *b)
{
    const int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

/* The position of id among sorted[0 .. n), -1 if absent: a binary search. */
static int find_sorted(const int *sorted, int n, int id)
{
    const int *hit = bsearch(&id, sorted, (size_t)n, sizeof *sorted, cmp_int);
    return hit ? (int)(hit - sorted) : -1;
}

void rs_mesh_flat_regions(const rs_surface *s, const int *ids, int n, int *label,
                          int *sorted)
{
    const rs_mesh *m = s->impl;
    for (int k = 0; k < n; k++)
        label[k] = k;
    if (n == 2) { /* one region where a flat edge joins the two */
        const rs_mtri *r = m->rec + ids[0];
        for (int j = 0; j < 3; j++)
            if (r->kind[j] == RS_EDGE_FLAT && r->nbr[j] >= 0 && r->nbr[j] / 3 == ids[1])
                label[1] = 0;
        return;
    }
    if (n <= 16) { /* few: each flat edge's other face looked up in ids */
        for (int k = 0; k < n; k++) {
            const rs_mtri *r = m->rec + ids[k];
            for (int j = 0; j < 3; j++) {
                const int o = r->nbr[j] / 3; /* each edge once, from its lower face */
                if (r->kind[j] != RS_EDGE_FLAT || r->nbr[j] < 0 || o < ids[k])
                    continue;
                int at = 0;
                while (at < n && ids[at] != o)
                    at++;
                if (at == n)
                    continue; /* not among the candidates */
                const int a = find_root(label, k), b = find_root(label, at);
                if (a != b)
                    label[a > b ? a : b] = a < b ? a : b;
            }
        }
        for (int k = 0; k < n; k++)
            label[k] = find_root(label, k);
        return;
    }
    int *pos = sorted + n;
    for (int k = 0; k < n; k++)
        sorted[k] = ids[k];
    qsort(sorted, (size_t)n, sizeof *sorted, cmp_int);
    /* pos[i]: the index in ids of sorted[i] */
    for (int k = 0; k < n; k++)
        pos[find_sorted(sorted, n, ids[k])] = k;
    for (int k = 0; k < n; k++) {
        const rs_mtri *r = m->rec + ids[k];
        for (int j = 0; j < 3; j++) {
            if (r->kind[j] != RS_EDGE_FLAT || r->nbr[j] < 0)
                continue;
            const int at = find_sorted(sorted, n, r->nbr[j] / 3);
            if (at < 0)
                continue; /* not among the candidates */
            const int a = find_root(label, k), b = find_root(label, pos[at]);
            if (a != b)
                label[a > b ? a : b] = a < b ? a : b;
        }
    }
    for (int k = 0; k < n; k++)
        label[k] = find_root(label, k);
}
