/* The MESH kind's closest features, by Voronoi regions of faces, edges and vertices
 * (docs/conventions.md, "Faceted surfaces"), and its table of operations.
 *
 * Every test that two features share is one expression of the shared data, evaluated the
 * same way whichever triangle asks: the side of an edge's plane p.m - c (c = m.a, a the
 * edge's lower node), and the position along an edge (p - v).(w - v) from either node.
 * Across a flat edge the two faces hold exactly -m and -c of one plane. So the regions of a
 * point tile space without overlap and without gaps: a point exactly above a shared edge or
 * vertex of a flat region gets one contact, never two. */
#define _POSIX_C_SOURCE 200809L /* stat */

#include "abaqus_part.h"
#include "cgal_mesh.h"
#include "mesh.h"
#include "rigidsurf/vec.h"
#include "rs_compiler.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* p's side of edge slot j of triangle t: p . m_j - c_j (rs_mtri.e), > 0 inside. */
static inline double side_of(const rs_mesh *m, int t, int j, const double p[3])
{
    const double *r = m->rec[t].e[j];
    return p[0] * r[0] + p[1] * r[1] + p[2] * r[2] - r[3];
}

/* (p - v).(w - v): the position of p along the edge of nodes v and w, seen from v. */
static inline double along(const rs_mesh *m, int v, int w, const double p[3])
{
    const double *pv = m->xyz + 3 * v, *pw = m->xyz + 3 * w;
    return (p[0] - pv[0]) * (pw[0] - pv[0]) + (p[1] - pv[1]) * (pw[1] - pv[1]) +
           (p[2] - pv[2]) * (pw[2] - pv[2]);
}

/* along for edge e seen from its node v. */
static double along_from(const rs_mesh *m, int e, int v, const double p[3])
{
    const int a = m->edge_v[2 * e], b = m->edge_v[2 * e + 1];
    return along(m, v, v == a ? b : a, p);
}

/* The nodes of the edge of slot j of triangle record r, lower index first as in edge_v:
 * from the record, without a look into edge_v. */
static inline void slot_nodes(const rs_mtri *r, int j, int *a, int *b)
{
    const int u = r->v[j], w = r->v[(j + 1) % 3];
    *a = u < w ? u : w;
    *b = u < w ? w : u;
}

/* Does edge e own p: strictly between its nodes, and outside each of its faces? */
static int edge_owns(const rs_mesh *m, int e, const double p[3])
{
    for (int k = m->edge_f0[e]; k < m->edge_f0[e + 1]; k++) {
        const int t = m->edge_f[k];
        int j = 0;
        while (m->tedge[3 * t + j] != e)
            j++;
        if (side_of(m, t, j, p) > 0.0)
            return 0;
    }
    const int a = m->edge_v[2 * e], b = m->edge_v[2 * e + 1];
    return along_from(m, e, a, p) > 0.0 && along_from(m, e, b, p) > 0.0;
}

/* Does vertex v own p: at or beyond v along each of its edges, (p - v).(w - v) <= 0 for
 * each neighbour w (the products of along_from)? With ext > 0: could it own a point
 * within ext of p, (p - v).(w - v) <= ext |w - v| for each w (may_own)? */
static int vertex_owns(const rs_mesh *m, int v, const double p[3], double ext)
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

/* A unit tangent normal to unit n. */
static void any_tangent(const double n[3], double t[3])
{
    const double ax = fabs(n[0]), ay = fabs(n[1]), az = fabs(n[2]);
    double g[3] = {0.0, 0.0, 0.0};
    g[ax <= ay && ax <= az ? 0 : ay <= az ? 1 : 2] = 1.0;
    rs_cross3(n, g, t);
    const double l = rs_norm3(t);
    for (int d = 0; d < 3; d++)
        t[d] /= l;
}

/* One contact of the point being queried, in the reference configuration. */
typedef struct hit {
    int feature;
    int tri;     /* a face contact's triangle, -1 otherwise */
    double x[3]; /* closest point */
    double n[3]; /* unit normal toward the point's side */
    double dist;
    double share;
} hit;

typedef struct scratch {
    int *ids;
    int cap;
    hit *hits;
    int nhit, hcap;
    int shares_due; /* the hits' shares hold weights (hit_weights) */
} scratch;

/* Appends a hit to s, its array grown as needed; -1 when out of memory. Hits are written
 * field by field, and mesh_closest_among reads them back so: a load of the whole struct
 * just after these stores would read it in pieces wider than the stores, and wait for
 * them. Only the filter behind a one-sided mesh (point_hits) copies whole hits. */
static int put_hit(scratch *s, int feature, int tri, const double x[3], const double n[3],
                   double dist)
{
    if (s->nhit == s->hcap) {
        int cap = s->hcap ? 2 * s->hcap : 16;
        hit *nh = realloc(s->hits, (size_t)cap * sizeof *nh);
        if (!nh)
            return -1;
        s->hits = nh;
        s->hcap = cap;
    }
    hit *c = &s->hits[s->nhit];
    c->feature = feature;
    c->tri = tri;
    c->dist = dist;
    for (int d = 0; d < 3; d++) {
        c->x[d] = x[d];
        c->n[d] = n[d];
    }
    s->nhit++;
    return 0;
}

/* A lower bound of the squared distance from p to triangle t, from its plane's distance
 * h and its edges' sides sd (side_of, unit normals: outside an edge by -sd at least). */
static inline double tri_bound(const rs_mesh *m, int t, const double p[3], double *h,
                               double sd[3])
{
    const rs_mtri *r = m->rec + t;
    *h = (p[0] - r->a0[0]) * r->n[0] + (p[1] - r->a0[1]) * r->n[1] +
         (p[2] - r->a0[2]) * r->n[2];
    double out = 0.0;
    for (int j = 0; j < 3; j++) {
        const double *rj = r->e[j];
        sd[j] = p[0] * rj[0] + p[1] * rj[1] + p[2] * rj[2] - rj[3];
        out = -sd[j] > out ? -sd[j] : out;
    }
    return *h * *h + out * out;
}

/* The squared distance from x to the segment a b, and the distance. */
static double segment_distance2(const double a[3], const double b[3], const double x[3])
{
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double w[3] = {x[0] - a[0], x[1] - a[1], x[2] - a[2]};
    const double f = fmin(1.0, fmax(0.0, rs_dot3(w, u) / rs_dot3(u, u)));
    const double d[3] = {w[0] - f * u[0], w[1] - f * u[1], w[2] - f * u[2]};
    return rs_dot3(d, d);
}

static double segment_distance(const double a[3], const double b[3], const double x[3])
{
    return sqrt(segment_distance2(a, b, x));
}

/* The squared distance from p to triangle t: to its plane where p projects inside it,
 * else to the nearest of the edges it lies outside of. */
static double tri_distance2(const rs_mesh *m, int t, const double p[3])
{
    double h, sd[3];
    const double lb = tri_bound(m, t, p, &h, sd);
    if (sd[0] >= 0.0 && sd[1] >= 0.0 && sd[2] >= 0.0)
        return lb;
    double best = INFINITY;
    for (int j = 0; j < 3; j++) {
        if (sd[j] >= 0.0)
            continue;
        best = fmin(best, segment_distance2(m->xyz + 3 * m->rec[t].v[j],
                                            m->xyz + 3 * m->rec[t].v[(j + 1) % 3], p));
    }
    return best;
}

/* The triangles that meet the cube of half-width reach about p, and a few more near it
 * (rs_cgal_tree_box), into s->ids; returns their number, -1 when out of memory. Each
 * caller tests every triangle's distance. */
static int box_triangles(const rs_mesh *m, const double p[3], double reach, scratch *s)
{
    const double pad = reach + 1e-9 * m->size;
    const double lo[3] = {p[0] - pad, p[1] - pad, p[2] - pad};
    const double hi[3] = {p[0] + pad, p[1] + pad, p[2] + pad};
    int n = rs_cgal_tree_box(m->tree, lo, hi, s->ids, s->cap);
    if (n > s->cap) {
        int *ni = realloc(s->ids, (size_t)n * 2 * sizeof *ni);
        if (!ni)
            return -1;
        s->ids = ni;
        s->cap = 2 * n;
        n = rs_cgal_tree_box(m->tree, lo, hi, s->ids, s->cap);
    }
    return n;
}

/* The weights of the contacts s->hits of a sphere of radius R at p, into their share
 * (docs/conventions.md, "Shares at concave folds"; rs_contacts_patch_shares makes them
 * shares): the CONCAVE edges among triangles ids[0 .. n) that the sphere reaches (at
 * distance d_L < R, cutting them in a chord of half-length kappa = sqrt(R^2 - d_L^2)),
 * and their end vertices (at distance d_v < R, kappa = sqrt(R^2 - d_v^2)), are where a
 * contact may begin or end while the sphere overlaps it. A contact's weight is a^2 =
 * R^2 - dist^2 times the product over them of min(1, s / kappa), s the distance from its
 * foot to the edge or vertex, and at least 1e-300. Returns 1 when two or more contacts
 * overlap the sphere (the shares are due), else 0 with the shares left at 1. */
static int hit_weights(const rs_mesh *m, const double p[3], double R, const int *ids, int n,
                       scratch *s)
{
    int nfront = 0;
    for (int k = 0; k < s->nhit; k++) {
        const double d = s->hits[k].dist;
        nfront += d > 0.0 && d < R;
    }
    if (nfront < 2)
        return 0;
    const int nh = s->nhit < RS_SHARE_MAX ? s->nhit : RS_SHARE_MAX;
    for (int q = 0; q < n; q++) {
        const int t = ids[q];
        double h, sd[3];
        if (!(tri_bound(m, t, p, &h, sd) < R * R))
            continue; /* no edge or vertex of t within the sphere */
        const rs_mtri *r = m->rec + t;
        for (int j = 0; j < 3; j++) {
            if (!(r->first >> j & 1u) || r->kind[j] != RS_EDGE_CONCAVE)
                continue; /* each concave edge once, from its lowest face */
            int ia, ib;
            slot_nodes(r, j, &ia, &ib);
            const double *a = m->xyz + 3 * ia, *b = m->xyz + 3 * ib;
            const double dl = segment_distance(a, b, p), k2 = (R - dl) * (R + dl);
            if (!(k2 > 0.0))
                continue;
            const double kappa = sqrt(k2);
            for (int k = 0; k < nh; k++) {
                const double sf = segment_distance(a, b, s->hits[k].x);
                if (sf < kappa)
                    s->hits[k].share *= sf / kappa;
            }
        }
        for (int j = 0; j < 3; j++) {
            const int v = r->v[j];
            if (!(r->first >> (3 + j) & 1u) || !m->vconc[v])
                continue; /* each such vertex once, from its lowest triangle */
            const double *x = m->xyz + 3 * v;
            const double dv[3] = {p[0] - x[0], p[1] - x[1], p[2] - x[2]};
            const double k2 = R * R - rs_dot3(dv, dv);
            if (!(k2 > 0.0))
                continue;
            const double kappa = sqrt(k2);
            for (int k = 0; k < nh; k++) {
                const double *h = s->hits[k].x;
                const double dh[3] = {h[0] - x[0], h[1] - x[1], h[2] - x[2]};
                const double sv = rs_norm3(dh);
                if (sv < kappa)
                    s->hits[k].share *= sv / kappa;
            }
        }
    }
    for (int k = 0; k < nh; k++) {
        const double d = s->hits[k].dist;
        s->hits[k].share = fmax(s->hits[k].share * (R - d) * (R + d), 1e-300);
    }
    return 1;
}

/* The contacts of point p (reference configuration) among triangles ids[0 .. n), into
 * s->hits: those with dist <= gap_lim and dist >= dist_min. */
static int point_hits(const rs_mesh *m, int sides, const double p[3], double radius,
                      const int *ids, int n, double gap_lim, double dist_min, scratch *s)
{
    s->nhit = 0;
    /* no feature of a triangle is nearer than tri_bound */
    const double lim = fmax(gap_lim, -dist_min);
    const int one_sided = sides != 2;
    for (int k = 0; k < n; k++) {
        const int t = ids[k];
        const rs_mtri *r = m->rec + t;
        const int *tv = r->v;
        const double *nt = r->n;
        double h, sd[3];
        if (!(tri_bound(m, t, p, &h, sd) <= lim * lim))
            continue;
        /* An edge can own p only where its triangle leaves p outside across it, and a
         * vertex only where its triangle leaves p outside across one of its two edges
         * there (inside both, p's projection lies in the angle at the vertex, or is the
         * vertex itself, with both sides 0): the sides found here decide which edges and
         * vertices are tested. */
        if (sd[0] > 0.0 && sd[1] > 0.0 && sd[2] > 0.0) {
            const double sg = (!one_sided && h < 0.0) ? -1.0 : 1.0;
            const double dist = sg * h;
            if (!(dist <= gap_lim && dist >= dist_min))
                continue;
            const double x[3] = {p[0] - h * nt[0], p[1] - h * nt[1], p[2] - h * nt[2]};
            const double n[3] = {sg * nt[0], sg * nt[1], sg * nt[2]};
            if (put_hit(s, RS_FEATURE(RS_FEAT_FACE, r->el), t, x, n, dist))
                return -1;
            continue;
        }
        for (int j = 0; j < 3; j++) {
            if (sd[j] > 0.0)
                continue;
            /* an edge is tested from its lowest-numbered face: within reach, so is it */
            if (!(r->first >> j & 1u))
                continue;
            const int e = r->edge[j];
            int ia, ib;
            slot_nodes(r, j, &ia, &ib);
            /* a two-face edge: this face leaves p outside (sd[j] <= 0), the other too? */
            const int nb = r->nbr[j];
            const int owns = nb >= 0 ? !(side_of(m, nb / 3, nb % 3, p) > 0.0) &&
                                           along(m, ia, ib, p) > 0.0 &&
                                           along(m, ib, ia, p) > 0.0
                                     : edge_owns(m, e, p);
            if (owns) {
                const double *a = m->xyz + 3 * ia, *b = m->xyz + 3 * ib;
                const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
                const double f = along(m, ia, ib, p) / rs_dot3(u, u);
                double x[3], dv[3], n[3];
                for (int d = 0; d < 3; d++) {
                    x[d] = a[d] + f * u[d];
                    dv[d] = p[d] - x[d];
                }
                const double L = rs_norm3(dv);
                const int f0 = m->edge_f0[e], nf = m->edge_f0[e + 1] - f0;
                double pn[3] = {0.0, 0.0, 0.0}; /* the faces' mean normal */
                for (int q = 0; q < nf && q < 2; q++)
                    for (int d = 0; d < 3; d++)
                        pn[d] += m->rec[m->edge_f[f0 + q]].n[d];
                double sg = 1.0;
                if (one_sided && nf <= 2) {
                    if (rs_dot3(dv, pn) < 0.0) {
                        if (nf == 1)
                            continue; /* behind an open edge: nothing */
                        sg = -1.0;    /* behind a groove: a penetration */
                    }
                }
                const double lp = rs_norm3(pn);
                for (int d = 0; d < 3; d++)
                    n[d] = L > 0.0 ? sg * dv[d] / L : (lp > 0.0 ? pn[d] / lp : 0.0);
                if (!(L > 0.0) && !(lp > 0.0))
                    any_tangent(u, n);
                const double dist = sg * L;
                if (dist <= gap_lim && dist >= dist_min &&
                    put_hit(s, RS_FEATURE(RS_FEAT_EDGE, e), -1, x, n, dist))
                    return -1;
            }
        }
        for (int j = 0; j < 3; j++) {
            if (sd[j] > 0.0 && sd[(j + 2) % 3] > 0.0)
                continue; /* vertex j lies between slots j - 1 and j */
            if (!(r->first >> (3 + j) & 1u))
                continue; /* tested from its lowest-numbered triangle */
            const int v = tv[j];
            /* its two edges in this triangle first (the same products as vertex_owns) */
            const double *pv = m->xyz + 3 * v;
            const double w0[3] = {p[0] - pv[0], p[1] - pv[1], p[2] - pv[2]};
            int beyond = 0;
            for (int o = 1; o < 3 && !beyond; o++) {
                const double *pw = m->xyz + 3 * tv[(j + o) % 3];
                beyond = w0[0] * (pw[0] - pv[0]) + w0[1] * (pw[1] - pv[1]) +
                             w0[2] * (pw[2] - pv[2]) >
                         0.0;
            }
            if (!beyond && vertex_owns(m, v, p, 0.0)) {
                const double *x = m->xyz + 3 * v, *pn = m->vpn + 3 * v;
                double dv[3] = {p[0] - x[0], p[1] - x[1], p[2] - x[2]};
                const double L = rs_norm3(dv);
                double sg = 1.0;
                if (one_sided && rs_dot3(dv, pn) < 0.0) {
                    if (m->vopen[v])
                        continue; /* behind an open boundary: nothing */
                    sg = -1.0;    /* behind a pocket: a penetration */
                }
                double n[3];
                for (int d = 0; d < 3; d++)
                    n[d] = L > 0.0 ? sg * dv[d] / L : pn[d];
                const double dist = sg * L;
                if (dist <= gap_lim && dist >= dist_min &&
                    put_hit(s, RS_FEATURE(RS_FEAT_VERTEX, v), -1, x, n, dist))
                    return -1;
            }
        }
    }
    /* Behind a one-sided mesh, where a point projects into faces around a convex edge
     * or vertex, only the face with the smallest penetration gives a contact. */
    if (one_sided && s->nhit > 1) {
        int w = 0;
        for (int k = 0; k < s->nhit; k++) {
            const hit *c = &s->hits[k];
            int drop = 0;
            for (int q = 0; q < s->nhit && !drop && c->tri >= 0 && c->dist < 0.0; q++) {
                const hit *o = &s->hits[q];
                if (q == k || o->tri < 0 || !(o->dist < 0.0))
                    continue;
                if (!(o->dist > c->dist || (o->dist == c->dist && o->feature < c->feature)))
                    continue;
                const int *tc = m->rec[c->tri].v, *to = m->rec[o->tri].v;
                for (int i = 0; i < 3 && !drop; i++)
                    for (int j = 0; j < 3; j++)
                        if (tc[i] == to[j])
                            drop = 1;
            }
            if (!drop) {
                if (w != k)
                    s->hits[w] = *c;
                w++;
            }
        }
        s->nhit = w;
    }
    for (int k = 0; k < s->nhit; k++)
        s->hits[k].share = 1.0;
    s->shares_due = s->nhit >= 2 && radius > 0.0 && hit_weights(m, p, radius, ids, n, s);
    return 0;
}

/* May triangle t give a contact to some point within ext of p, or take part in the
 * shares of a sphere of radius R there? Each test by which point_hits lets t's face, or
 * an edge or vertex it tests, own a point is the sign of a side p . m - c with unit m, or
 * of a product (p - v).(w - v) over the length |w - v|: neither moves by more than ext
 * when p moves by ext. So a feature whose test fails at p by more than ext (and a
 * rounding margin) owns no point within ext, and a triangle whose features all fail
 * gives no contact there. hit_weights reads the concave edges and vertices that a
 * triangle tests, where they are nearer than R: such a triangle is kept while they are
 * nearer than R + ext. */
static int may_own(const rs_mesh *m, int t, const double p[3], double ext, double R)
{
    const rs_mtri *r = m->rec + t;
    const unsigned fl = r->first;
    const int *tv = r->v;
    for (int j = 0; j < 3; j++) {
        if ((fl >> j & 1u) && r->kind[j] == RS_EDGE_CONCAVE) {
            int a, b;
            slot_nodes(r, j, &a, &b);
            if (segment_distance(m->xyz + 3 * a, m->xyz + 3 * b, p) < R + ext)
                return 1;
        }
        if ((fl >> (3 + j) & 1u) && m->vconc[tv[j]]) {
            const double *x = m->xyz + 3 * tv[j];
            const double dv[3] = {p[0] - x[0], p[1] - x[1], p[2] - x[2]};
            if (rs_norm3(dv) < R + ext)
                return 1;
        }
    }
    double h, sd[3];
    tri_bound(m, t, p, &h, sd);
    if (sd[0] > -ext && sd[1] > -ext && sd[2] > -ext)
        return 1; /* its face */
    for (int j = 0; j < 3; j++) {
        if (!(fl >> j & 1u) || sd[j] > ext)
            continue; /* edge j is tested only where p is outside across it */
        const int nb = r->nbr[j];
        if (nb >= 0 && side_of(m, nb / 3, nb % 3, p) > ext)
            continue; /* inside the other face */
        int a, b;
        slot_nodes(r, j, &a, &b);
        const double *pa = m->xyz + 3 * a, *pb = m->xyz + 3 * b;
        const double u[3] = {pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]};
        const double L = rs_norm3(u);
        if (along(m, a, b, p) > -ext * L && along(m, b, a, p) > -ext * L)
            return 1;
    }
    for (int j = 0; j < 3; j++)
        if ((fl >> (3 + j) & 1u) && vertex_owns(m, tv[j], p, ext))
            return 1;
    return 0;
}

/* The query's pose, NULL where it is the identity (a mesh in its reference
 * configuration): its points and results then need no transform. */
static const rs_pose *moved_pose(const rs_query *q)
{
    const rs_pose *p = q->pose;
    if (!p)
        return NULL;
    for (int a = 0; a < 9; a++)
        if (p->R[a] != (a % 4 == 0 ? 1.0 : 0.0))
            return p;
    return p->T[0] != 0.0 || p->T[1] != 0.0 || p->T[2] != 0.0 ? p : NULL;
}

/* p, slave i of q, in the reference configuration (pose: moved_pose(q)). */
static void slave_local(const rs_query *q, const rs_pose *pose, int i, double p[3])
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

/* The triangles within reach + extra of each slave that may give it a contact from
 * anywhere within extra: the tree's boxes, less those farther (tri_distance2) and those
 * whose features own no point within extra (may_own). near is the nearest of all within
 * reach. */
static int mesh_candidates(const rs_surface *s, const rs_query *q, double extra,
                           rs_cands *c, rs_error *err)
{
    const rs_mesh *m = s->impl;
    if (!m || !q->slave.x || !q->slave.y || !q->slave.z)
        return rs_error_set(err, RS_ERR_ARG, "rs_surface_candidates: missing data");
    if (c->offcap < q->n + 1) {
        int *no = realloc(c->off, (size_t)(q->n + 1) * sizeof *no);
        if (no)
            c->off = no;
        double *nn = realloc(c->near, (size_t)(q->n + 1) * sizeof *nn);
        if (nn)
            c->near = nn;
        if (!no || !nn)
            return rs_error_set(err, RS_ERR_NOMEM, "out of memory for candidate lists");
        c->offcap = q->n + 1;
    }
    const rs_pose *pose = moved_pose(q);
    scratch sc;
    memset(&sc, 0, sizeof sc);
    int rc = RS_OK, nid = 0;
    c->n = q->n;
    for (int i = 0; i < q->n && rc == RS_OK; i++) {
        c->off[i] = nid;
        c->near[i] = 0.0;
        const double r = q->slave.radius ? q->slave.radius[i] : 0.0;
        double p[3];
        slave_local(q, pose, i, p);
        /* as the query's reach (mesh_closest_among), from anywhere within extra */
        double lim = q->gap_max + r;
        if (-q->dist_min > lim)
            lim = isfinite(q->dist_min)
                      ? -q->dist_min
                      : fmax(lim, rs_cgal_tree_nearest(m->tree, p) + extra);
        lim += extra;
        if (!(lim >= 0.0) || !isfinite(lim))
            continue;
        const int n = box_triangles(m, p, lim, &sc);
        if (n < 0) {
            rc = rs_error_set(err, RS_ERR_NOMEM, "out of memory for candidate lists");
            break;
        }
        if (nid + n > c->idcap) {
            const int cap = 2 * (nid + n) + 64;
            int *ni = realloc(c->ids, (size_t)cap * sizeof *ni);
            if (!ni) {
                rc = rs_error_set(err, RS_ERR_NOMEM, "out of memory for candidate lists");
                break;
            }
            c->ids = ni;
            c->idcap = cap;
        }
        double near2 = lim * lim;
        /* extra and a margin for the rounding of the tests at p */
        const double ext =
            extra + 1e-9 * (m->size + fabs(p[0]) + fabs(p[1]) + fabs(p[2]) + lim);
        for (int k = 0; k < n; k++) {
            const double d2 = tri_distance2(m, sc.ids[k], p);
            if (d2 <= lim * lim) {
                near2 = fmin(near2, d2);
                if (may_own(m, sc.ids[k], p, ext, r))
                    c->ids[nid++] = sc.ids[k];
            }
        }
        c->near[i] = sqrt(near2);
    }
    c->off[q->n] = nid;
    free(sc.ids);
    return rc;
}

/* How far ahead of the slave queried its successors' candidates are fetched, into the
 * second-level cache: the records indexed by triangle RS_MESH_AHEAD slaves ahead, the
 * nodes' coordinates (found through the triangles' nodes, fetched before)
 * RS_MESH_AHEAD_NODES ahead. On a mesh larger than the caches most candidates' records
 * come from memory, and the query of one slave would wait for each in turn. */
#define RS_MESH_AHEAD 8
#define RS_MESH_AHEAD_NODES 4
/* Meshes of fewer triangles (about 15 MB in all) are left to the caches: fetching
 * ahead costs the instructions and gains nothing where the records stay cached. */
#define RS_MESH_PREFETCH_MIN 32768

/* Asks for what the query reads of each triangle of ids[0 .. n): its record, three cache
 * lines (stage 0); or its nodes' coordinates, found through the record fetched before
 * (stage 1), which the tests of its edges and vertices read. A vertex's neighbours
 * (vert_e0, vert_w) are left to be read when they are needed: on a fine mesh a sphere
 * tests a vertex's ownership about once in twenty queries. */
static void prefetch_candidates(const rs_mesh *m, const int *ids, int n, int stage)
{
    for (int k = 0; k < n; k++) {
        const rs_mtri *r = m->rec + ids[k];
        if (stage == 1) {
            for (int j = 0; j < 3; j++)
                RS_PREFETCH_L2(m->xyz + 3 * (size_t)r->v[j]);
            continue;
        }
        const char *c = (const char *)r;
        RS_PREFETCH_L2(c);
        RS_PREFETCH_L2(c + 64);
        RS_PREFETCH_L2(c + 128);
    }
}

static int mesh_closest_among(const rs_surface *s, const rs_query *q,
                              const int *const *cand, const int *ncand, rs_contacts *out,
                              rs_error *err)
{
    const rs_mesh *m = s->impl;
    if (!m)
        return rs_error_set(err, RS_ERR_ARG, "rs_surface_query: mesh '%s' has no data",
                            s->name);
    if (!q->slave.x || !q->slave.y || !q->slave.z)
        return rs_error_set(err, RS_ERR_ARG, "rs_surface_query: missing coordinates");
    const rs_pose *pose = moved_pose(q);
    scratch sc;
    memset(&sc, 0, sizeof sc);
    int rc = RS_OK;
    sc.ids = malloc(256 * sizeof *sc.ids);
    if (!sc.ids)
        return rs_error_set(err, RS_ERR_NOMEM, "out of memory for the mesh query");
    sc.cap = 256;
    const int ahead = cand && m->nt >= RS_MESH_PREFETCH_MIN;
    for (int i = 0; i < q->n; i++) {
        if (ahead) {
            const int ia = i + RS_MESH_AHEAD, ib = i + RS_MESH_AHEAD_NODES;
            if (ia < q->n)
                prefetch_candidates(m, cand[ia], ncand[ia], 0);
            if (ib < q->n)
                prefetch_candidates(m, cand[ib], ncand[ib], 1);
        }
        const double r = q->slave.radius ? q->slave.radius[i] : 0.0;
        const double gap_lim = q->gap_max + r;
        if (!(gap_lim >= 0.0))
            continue;
        double p[3];
        slave_local(q, pose, i, p);
        /* The box reaches the gap limit and, behind a one-sided mesh, the penetrations
         * down to dist_min; without that bound, down to the nearest triangle. */
        double reach = gap_lim;
        if (-q->dist_min > reach) {
            if (isfinite(q->dist_min))
                reach = -q->dist_min;
            else
                reach = fmax(reach, rs_cgal_tree_nearest(m->tree, p));
        }
        const int *ids = sc.ids;
        int nt;
        if (cand) { /* the slave's candidate triangles (mesh_candidates) */
            ids = cand[i];
            nt = ncand[i];
        } else {
            nt = box_triangles(m, p, reach, &sc);
            ids = sc.ids;
        }
        /* without a depth limit, penetrations reach down to the nearest triangle: the
         * same contacts with and without candidate lists */
        const double depth = isfinite(q->dist_min) ? q->dist_min : -reach;
        if (nt < 0 || point_hits(m, s->sides, p, r, ids, nt, gap_lim, depth, &sc)) {
            rc = rs_error_set(err, RS_ERR_NOMEM, "out of memory in the mesh query");
            break;
        }
        if (out->n + sc.nhit > out->cap &&
            (rc = rs_contacts_reserve(out, 2 * (out->n + sc.nhit) + 64, err)) != RS_OK)
            break;
        const int o0 = out->n;
        for (int k = 0; k < sc.nhit; k++) {
            const hit *c = &sc.hits[k];
            const int o = out->n++;
            double xm[3], n[3];
            if (pose) { /* x = R X + T */
                rs_matvec3(pose->R, c->x, xm);
                rs_matvec3(pose->R, c->n, n);
                for (int d = 0; d < 3; d++)
                    xm[d] += pose->T[d];
            } else {
                for (int d = 0; d < 3; d++) {
                    xm[d] = c->x[d];
                    n[d] = c->n[d];
                }
            }
            out->point[o] = i;
            out->feature[o] = c->feature;
            out->dist[o] = c->dist;
            out->share[o] = c->share;
            /* flat: no curvature; t1 and t2 follow from n (RS_FRAME_GLOBAL_X,
             * rs_frame_orient) */
            out->curv[0][o] = out->curv[1][o] = 0.0;
            for (int d = 0; d < 3; d++) {
                out->xm[d][o] = xm[d];
                out->nrm[d][o] = n[d];
            }
        }
        if (sc.shares_due) { /* the same in the reference and the current pose */
            rs_contacts_patch_shares(out, o0, sc.nhit, r);
            out->shared = 1;
        }
    }
    free(sc.ids);
    free(sc.hits);
    return rc;
}

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

/* History passes where the contact normal is continuous: between faces across a flat
 * edge, between a face and its own edges and vertices, and between an edge and its
 * nodes. */
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
    if (ta == RS_FEAT_FACE && tb == RS_FEAT_FACE) {
        if (ib >= m->nel)
            return 0;
        for (int t = m->el_t0[ia]; t < m->el_t0[ia + 1]; t++)
            for (int j = 0; j < 3; j++) {
                const int e = m->tedge[3 * t + j];
                if (m->edge_kind[e] == RS_EDGE_FLAT && element_has(m, ib, m->tedge, e))
                    return 1;
            }
        return 0;
    }
    if (ta == RS_FEAT_FACE && tb == RS_FEAT_EDGE)
        return ib < m->ne && element_has(m, ia, m->tedge, ib);
    if (ta == RS_FEAT_FACE && tb == RS_FEAT_VERTEX)
        return ib < m->nv && element_has(m, ia, m->tri, ib);
    if (ta == RS_FEAT_EDGE && tb == RS_FEAT_VERTEX)
        return ia < m->ne && ib < m->nv &&
               (m->edge_v[2 * ia] == ib || m->edge_v[2 * ia + 1] == ib);
    return 0;
}

static int mesh_closest(const rs_surface *s, const rs_query *q, rs_contacts *out,
                        rs_error *err)
{
    return mesh_closest_among(s, q, NULL, NULL, out, err);
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

/* Shape functions of a triangle at p (its plane): the barycentric coordinates. */
static void tri_shape(const double *x0, const double *x1, const double *x2,
                      const double p[3], double shape[3])
{
    double e1[3], e2[3], nrm[3];
    for (int d = 0; d < 3; d++) {
        e1[d] = x1[d] - x0[d];
        e2[d] = x2[d] - x0[d];
    }
    nrm[0] = e1[1] * e2[2] - e1[2] * e2[1];
    nrm[1] = e1[2] * e2[0] - e1[0] * e2[2];
    nrm[2] = e1[0] * e2[1] - e1[1] * e2[0];
    const double nn = nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2];
    const double *x[3] = {x0, x1, x2};
    for (int i = 0; i < 3; i++) {
        const double *a = x[(i + 1) % 3], *b = x[(i + 2) % 3];
        double u[3], v[3];
        for (int d = 0; d < 3; d++) {
            u[d] = a[d] - p[d];
            v[d] = b[d] - p[d];
        }
        const double c[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                             u[0] * v[1] - u[1] * v[0]};
        shape[i] = (c[0] * nrm[0] + c[1] * nrm[1] + c[2] * nrm[2]) / nn;
    }
}

/* Shape functions of a planar quad (bilinear, as Abaqus's R3D4) at p: the local
 * coordinates (xi, eta) in [-1, 1]^2 by Gauss-Newton on x(xi, eta) = p. */
static void quad_shape(const double *xq, const double p[3], double shape[4])
{
    static const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    double xi = 0.0, eta = 0.0;
    for (int it = 0; it < 50; it++) {
        double r[3] = {-p[0], -p[1], -p[2]}, jx[3] = {0, 0, 0}, jy[3] = {0, 0, 0};
        for (int i = 0; i < 4; i++) {
            const double n = 0.25 * (1 + sx[i] * xi) * (1 + sy[i] * eta);
            const double nx = 0.25 * sx[i] * (1 + sy[i] * eta);
            const double ny = 0.25 * sy[i] * (1 + sx[i] * xi);
            for (int d = 0; d < 3; d++) {
                r[d] += n * xq[3 * i + d];
                jx[d] += nx * xq[3 * i + d];
                jy[d] += ny * xq[3 * i + d];
            }
        }
        const double a = jx[0] * jx[0] + jx[1] * jx[1] + jx[2] * jx[2];
        const double b = jx[0] * jy[0] + jx[1] * jy[1] + jx[2] * jy[2];
        const double c = jy[0] * jy[0] + jy[1] * jy[1] + jy[2] * jy[2];
        const double gx = jx[0] * r[0] + jx[1] * r[1] + jx[2] * r[2];
        const double gy = jy[0] * r[0] + jy[1] * r[1] + jy[2] * r[2];
        const double det = a * c - b * b;
        if (!(det > 0.0))
            break;
        const double dxi = (c * gx - b * gy) / det, deta = (a * gy - b * gx) / det;
        xi -= dxi;
        eta -= deta;
        if (fabs(dxi) + fabs(deta) < 1e-15)
            break;
    }
    for (int i = 0; i < 4; i++)
        shape[i] = 0.25 * (1 + sx[i] * xi) * (1 + sy[i] * eta);
}

/* The element under feature f: a face's own, an edge's or a vertex's lowest triangle's. */
static int facet_element(const rs_mesh *m, int f)
{
    if (!m || f < 0)
        return -1;
    const int idx = RS_FEATURE_INDEX(f);
    int el = -1;
    switch (RS_FEATURE_TYPE(f)) {
    case RS_FEAT_FACE:
        el = idx;
        break;
    case RS_FEAT_EDGE:
        if (idx < m->ne && m->edge_f0[idx] < m->edge_f0[idx + 1])
            el = m->tel[m->edge_f[m->edge_f0[idx]]];
        break;
    case RS_FEAT_VERTEX:
        if (idx < m->nv && m->vfirst[idx] >= 0)
            el = m->tel[m->vfirst[idx]];
        break;
    default:
        break;
    }
    return el >= 0 && el < m->nel ? el : -1;
}

static int mesh_facet_index(const rs_surface *s, int f)
{
    return facet_element(s->impl, f);
}

static int mesh_facet_count(const rs_surface *s)
{
    const rs_mesh *m = s->impl;
    return m ? m->nel : 0;
}

/* Area and normal of element k: the sum of its triangles' (a planar quad's two). */
static int mesh_facet_area(const rs_surface *s, int k, double *area, double n[3])
{
    const rs_mesh *m = s->impl;
    if (!m || k < 0 || k >= m->nel)
        return -1;
    double a = 0.0;
    for (int t = m->el_t0[k]; t < m->el_t0[k + 1]; t++) {
        const double *p0 = m->xyz + 3 * (size_t)m->tri[3 * t],
                     *p1 = m->xyz + 3 * (size_t)m->tri[3 * t + 1],
                     *p2 = m->xyz + 3 * (size_t)m->tri[3 * t + 2];
        double e1[3], e2[3], c[3];
        for (int d = 0; d < 3; d++) {
            e1[d] = p1[d] - p0[d];
            e2[d] = p2[d] - p0[d];
        }
        rs_cross3(e1, e2, c);
        a += 0.5 * rs_norm3(c);
    }
    const double *tn = m->rec[m->el_t0[k]].n;
    *area = a;
    n[0] = tn[0];
    n[1] = tn[1];
    n[2] = tn[2];
    return 0;
}

static int mesh_facet(const rs_surface *s, int f, const double xm[3], int nodes[4],
                      double xyz[12], double shape[4])
{
    const rs_mesh *m = s->impl;
    const int el = facet_element(m, f);
    if (el < 0)
        return 0;
    const int nn = m->el_nnode[el];
    for (int i = 0; i < nn; i++) {
        const int v = m->el_nodes[4 * el + i];
        nodes[i] = m->vlabel ? m->vlabel[v] : v + 1;
        for (int d = 0; d < 3; d++)
            xyz[3 * i + d] = m->xyz[3 * (size_t)v + d];
    }
    if (nn == 3)
        tri_shape(xyz, xyz + 3, xyz + 6, xm, shape);
    else
        quad_shape(xyz, xm, shape);
    return nn;
}

static int mesh_facet_size(const rs_surface *s, int *nnode)
{
    const rs_mesh *m = s->impl;
    if (nnode)
        *nnode = m ? m->nv : 0;
    return m ? m->el_maxnode : 0;
}

static void mesh_free(rs_surface *s)
{
    rs_mesh_free(s->impl);
    s->impl = NULL;
}

const rs_surface_ops rs_mesh_ops = {.name = "MESH",
                                    .ndir = 3,
                                    .frame = RS_FRAME_GLOBAL_X,
                                    .closest = mesh_closest,
                                    .shares = 1,
                                    .adjacent = mesh_adjacent,
                                    .bounds = mesh_bounds,
                                    .spin_axis = mesh_spin_axis,
                                    .triangulate = mesh_triangulate,
                                    .free = mesh_free,
                                    .candidates = mesh_candidates,
                                    .closest_among = mesh_closest_among,
                                    .facet = mesh_facet,
                                    .facet_size = mesh_facet_size,
                                    .facet_area = mesh_facet_area,
                                    .facet_index = mesh_facet_index,
                                    .facet_count = mesh_facet_count};

/* STL checks the reader leaves out: an ASCII STL (it starts with "solid" and reads as
 * text) ends with "endsolid", so a file cut short is an error and not a smaller mesh; a
 * binary STL is exactly 84 + 50 n bytes for its n facets, and its coordinates are finite
 * (the reader merges equal points, and a NaN would merge with anything). */
static int stl_check(const char *file, const char *where, rs_error *err)
{
    const char *dot = strrchr(file, '.');
    if (!dot || strlen(dot) != 4 || tolower((unsigned char)dot[1]) != 's' ||
        tolower((unsigned char)dot[2]) != 't' || tolower((unsigned char)dot[3]) != 'l')
        return RS_OK;
    FILE *f = fopen(file, "rb");
    if (!f)
        return RS_OK; /* reported by the reader */
    unsigned char head[84];
    const size_t nh = fread(head, 1, sizeof head, f);
    long size = -1;
    if (fseek(f, 0, SEEK_END) == 0)
        size = ftell(f);
    int text = nh >= 5 && memcmp(head, "solid", 5) == 0;
    for (size_t k = 0; k < nh && text; k++)
        text = head[k] != 0;
    int rc = RS_OK;
    if (text) {
        char tail[256];
        size_t nt = 0;
        const long from = size > (long)sizeof tail - 1 ? size - (long)sizeof tail + 1 : 0;
        if (size > 0 && fseek(f, from, SEEK_SET) == 0)
            nt = fread(tail, 1, sizeof tail - 1, f);
        tail[nt] = '\0';
        if (!memchr(tail, '\0', nt) && !strstr(tail, "endsolid"))
            rc = rs_error_set(err, RS_ERR_PARSE,
                              "%s: %s: ASCII STL ends without 'endsolid' (broken or "
                              "truncated)",
                              where, file);
    } else if (nh == sizeof head) {
        const unsigned long n = (unsigned long)head[80] | (unsigned long)head[81] << 8 |
                                (unsigned long)head[82] << 16 |
                                (unsigned long)head[83] << 24;
        if (size < 0 || (unsigned long)size != 84ul + 50ul * n)
            rc = rs_error_set(
                err, RS_ERR_PARSE,
                "%s: %s: binary STL of %ld bytes announces %lu facets (expected "
                "84 + 50 x %lu = %lu bytes: broken or truncated)",
                where, file, size, n, n, 84ul + 50ul * n);
        unsigned char rec[50];
        if (!rc && fseek(f, 84, SEEK_SET) == 0)
            for (unsigned long k = 0; k < n && !rc && fread(rec, 1, 50, f) == 50; k++)
                for (int j = 3; j < 12 && !rc; j++) { /* the three vertices */
                    float v;
                    memcpy(&v, rec + 4 * j, 4);
                    if (!isfinite(v))
                        rc = rs_error_set(err, RS_ERR_GEOMETRY,
                                          "%s: %s: facet %lu has coordinate %g (expected "
                                          "finite coordinates)",
                                          where, file, k + 1, (double)v);
                }
    }
    fclose(f);
    return rc;
}

int rs_mesh_surface_load(rs_surface *s, const char *file, double scale, int placed,
                         const double abc[9], const char *where, rs_error *err)
{
    double a[3] = {0, 0, 0}, ex[3] = {1, 0, 0}, ey[3] = {0, 1, 0}, ez[3] = {0, 0, 1};
    if (placed) {
        const double *pa = abc, *pb = abc + 3, *pc = abc + 6;
        double u[3] = {pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]};
        double w[3] = {pc[0] - pa[0], pc[1] - pa[1], pc[2] - pa[2]};
        double scl = 0.0;
        for (int i = 0; i < 9; i++)
            scl = fmax(scl, fabs(abc[i]));
        const double lu = rs_norm3(u), lw = rs_norm3(w);
        if (!(lu > 1e-12 * scl) || !isfinite(lu) || !isfinite(lw))
            return rs_error_set(
                err, RS_ERR_GEOMETRY,
                "%s: points a and b coincide (expected distinct points a, b "
                "placing the mesh)",
                where);
        for (int d = 0; d < 3; d++)
            ex[d] = u[d] / lu;
        const double along = rs_dot3(w, ex);
        double y[3] = {w[0] - along * ex[0], w[1] - along * ex[1], w[2] - along * ex[2]};
        const double ly = rs_norm3(y);
        if (!(lw > 1e-12 * scl) || !(ly > 1e-9 * lw))
            return rs_error_set(err, RS_ERR_GEOMETRY,
                                "%s: point c coincides with a or lies on the line a-b "
                                "(expected c off the mesh's local x axis)",
                                where);
        for (int d = 0; d < 3; d++)
            ey[d] = y[d] / ly;
        rs_cross3(ex, ey, ez);
        memcpy(a, pa, sizeof a);
    }
    struct stat st;
    if (stat(file, &st) != 0)
        return rs_error_set(err, RS_ERR_IO, "%s: cannot open mesh file %s: %s", where, file,
                            strerror(errno));
    if (!S_ISREG(st.st_mode))
        return rs_error_set(err, RS_ERR_IO, "%s: %s is %s (expected a mesh file)", where,
                            file,
                            S_ISDIR(st.st_mode) ? "a directory" : "not a regular file");
    FILE *f = fopen(file, "rb");
    if (!f)
        return rs_error_set(err, RS_ERR_IO, "%s: cannot open mesh file %s: %s", where, file,
                            strerror(errno));
    const int empty = fgetc(f) == EOF;
    fclose(f);
    if (empty)
        return rs_error_set(err, RS_ERR_PARSE, "%s: %s is empty (expected a mesh)", where,
                            file);
    int rc = stl_check(file, where, err);
    if (rc)
        return rc;
    rs_soup soup;
    char msg[300];
    const char *ext = strrchr(file, '.');
    const int inp = ext && strlen(ext) == 4 && tolower((unsigned char)ext[1]) == 'i' &&
                    tolower((unsigned char)ext[2]) == 'n' &&
                    tolower((unsigned char)ext[3]) == 'p';
    if (inp) { /* an Abaqus rigid part: its messages name file and line */
        if (rs_abaqus_read_soup(file, &soup, msg, sizeof msg))
            return rs_error_set(err, RS_ERR_PARSE, "%s: %s", where, msg);
    } else if (rs_cgal_read_soup(file, &soup, msg, sizeof msg)) {
        return rs_error_set(err, RS_ERR_PARSE, "%s: %s: %s", where, file, msg);
    }
    rs_mesh *m = NULL;
    int two = 0;
    rc = rs_mesh_build(&soup, scale, a, ex, ey, ez, file, &m, &two, s->warning,
                       sizeof s->warning, err);
    rs_soup_free(&soup);
    if (rc)
        return rc;
    s->impl = m;
    s->ops = &rs_mesh_ops;
    s->kind = RS_SURF_FACETED;
    if (two) /* no consistent orientation: both sides act, whatever was asked */
        s->sides = 2;
    else if (s->sides == 0)
        s->sides = inp ? 1 : 2;
    /* the placement is in the nodes: the reference configuration is global */
    const double I[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    memset(s->a, 0, sizeof s->a);
    memcpy(s->ex, I[0], sizeof s->ex);
    memcpy(s->ey, I[1], sizeof s->ey);
    memcpy(s->ez, I[2], sizeof s->ez);
    return RS_OK;
}
