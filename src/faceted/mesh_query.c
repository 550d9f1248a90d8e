/* The MESH kind's closest features, by Voronoi regions of faces, edges and vertices
 * (docs/conventions.md, "Faceted surfaces"): the list query and the tree query.
 *
 * Every test that two features share is one expression of the shared data, evaluated the
 * same way whichever triangle asks: the side of an edge's plane p.m - c (c = m.a, a the
 * edge's lower node), and the position along an edge (p - v).(w - v) from either node.
 * Across a flat edge the two faces hold exactly -m and -c of one plane. So the regions of a
 * point tile space without overlap and without gaps: a point exactly above a shared edge or
 * vertex of a flat region gets one contact, never two. */

#include "mesh.h"
#include "mesh_regions.h"
#include "mesh_zone.h"
#include "rigidsurf/vec.h"
#include "rs_compiler.h"
#include "shares.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* along for edge e seen from its node v. */
static double along_from(const rs_mesh *m, int e, int v, const double p[3])
{
    const int a = m->edge_v[2 * e], b = m->edge_v[2 * e + 1];
    return along(m, v, v == a ? b : a, p);
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
    double near2;   /* the least tri_bound of the triangles point_hits was given */
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

/* The weights of the contacts s->hits of a sphere of radius R at p, into their share
 * (shares.h; rs_contacts_patch_shares makes them shares): the CONCAVE edges among triangles
 * ids[0 .. n) that the sphere reaches (at distance d_L < R, cutting them in a chord of
 * half-length kappa = sqrt(R^2 - d_L^2)), and their end vertices (at distance d_v < R,
 * kappa = sqrt(R^2 - d_v^2)), are where a contact may begin or end while the sphere
 * overlaps it. A contact's weight is a^2 = R^2 - dist^2 times the product over them of
 * min(1, s / kappa), s the distance from its foot to the edge or vertex, and at least
 * 1e-300. Returns 1 when two or more contacts overlap the sphere (the shares are due), else
 * 0 with the shares left at 1. */
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
            for (int k = 0; k < nh; k++)
                rs_fold_cut(&s->hits[k].share, segment_distance(a, b, s->hits[k].x), kappa);
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
                rs_fold_cut(&s->hits[k].share, rs_norm3(dh), kappa);
            }
        }
    }
    for (int k = 0; k < nh; k++) {
        const double d = s->hits[k].dist;
        s->hits[k].share = fmax(s->hits[k].share * (R - d) * (R + d), 1e-300);
    }
    return 1;
}

/* Does triangle t own a point on its border across FLAT edges only (its sides sd, >= 0,
 * 0 on those edges)? A FLAT edge and a vertex inside a coplanar region own nothing: on
 * one FLAT edge, the edge's first face takes the point; at a vertex whose edges are all
 * FLAT, the vertex's first triangle. */
static int flat_tie(const rs_mesh *m, int t, const double sd[3])
{
    const rs_mtri *r = m->rec + t;
    int zero = 0, nz = 0;
    for (int j = 0; j < 3; j++) {
        if (sd[j] > 0.0)
            continue;
        if (sd[j] < 0.0 || r->kind[j] != RS_EDGE_FLAT)
            return 0;
        zero = j;
        nz++;
    }
    if (nz == 1)
        return r->first >> zero & 1u;
    /* on two: at the vertex between them (slots j - 1 and j meet at vertex j) */
    const int v = r->v[sd[0] > 0.0 ? 2 : sd[1] > 0.0 ? 0 : 1];
    return nz == 2 && m->vflat[v] && m->vfirst[v] == t;
}

/* The contact of p on the face of triangle t, which holds p in its prism at height h,
 * into s->hits when dist <= gap_lim and dist >= dist_min; -1 when out of memory. */
static inline int face_hit(const rs_mesh *m, int t, int one_sided, const double p[3],
                           double h, double gap_lim, double dist_min, scratch *s)
{
    double x[3], n[3];
    const double dist = face_contact(m, t, one_sided, p, h, x, n);
    if (!(dist <= gap_lim && dist >= dist_min))
        return 0;
    return put_hit(s, RS_FEATURE(RS_FEAT_FACE, m->rec[t].el), t, x, n, dist);
}

/* The contacts of point p (reference configuration) among triangles ids[0 .. n), into
 * s->hits: those with dist <= gap_lim and dist >= dist_min. s->near2 gets the least
 * tri_bound of them. */
static int point_hits(const rs_mesh *m, int sides, const double p[3], double radius,
                      const int *ids, int n, double gap_lim, double dist_min, scratch *s)
{
    s->nhit = 0;
    /* no feature of a triangle is nearer than tri_bound */
    const double lim = fmax(gap_lim, -dist_min);
    const int one_sided = sides != 2;
    double near2 = INFINITY;
    for (int k = 0; k < n; k++) {
        const int t = ids[k];
        const rs_mtri *r = m->rec + t;
        const int *tv = r->v;
        double h, sd[3];
        const double b2 = tri_bound(m, t, p, &h, sd);
        near2 = b2 < near2 ? b2 : near2;
        if (!(b2 <= lim * lim))
            continue;
        /* An edge can own p only where its triangle leaves p outside across it, and a
         * vertex only where its triangle leaves p outside across one of its two edges
         * there (inside both, p's projection lies in the angle at the vertex, or is the
         * vertex itself, with both sides 0): the sides found here decide which edges and
         * vertices are tested. */
        if ((sd[0] > 0.0 && sd[1] > 0.0 && sd[2] > 0.0) || flat_tie(m, t, sd)) {
            if (face_hit(m, t, one_sided, p, h, gap_lim, dist_min, s))
                return -1;
            continue;
        }
        for (int j = 0; j < 3; j++) {
            if (sd[j] > 0.0)
                continue;
            /* an edge is tested from its lowest-numbered face: within reach, so is it; a
             * FLAT edge owns nothing (flat_tie) */
            if (!(r->first >> j & 1u) || r->kind[j] == RS_EDGE_FLAT)
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
            if (!(r->first >> (3 + j) & 1u) || m->vflat[tv[j]])
                continue; /* tested from its lowest-numbered triangle; inside a coplanar
                           * region its faces own what projects onto it (flat_tie) */
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
    s->near2 = near2;
    return 0;
}

/* The contacts of p from the face its hint names, where p lies in the clear zone of one
 * of the face's triangles (mesh_zone.h; a quad's zone gives the face of the triangle of
 * the quad that holds p's foot): there no other feature gives a contact within lim, so
 * that face's own contact, as point_hits computes it, is all of them. Returns 1
 * with s->hits set (that contact, or none beyond the limits), 0 where the candidates
 * decide, -1 when out of memory. */
static int hinted_hits(const rs_mesh *m, int sides, const double p[3], int hint,
                       double gap_lim, double dist_min, scratch *s)
{
    double h;
    const int t = rs_mesh_zone_face(m, p, hint, fmax(gap_lim, -dist_min), &h);
    if (t < 0)
        return 0;
    s->nhit = 0;
    s->shares_due = 0;
    if (face_hit(m, t, sides != 2, p, h, gap_lim, dist_min, s))
        return -1;
    if (s->nhit)
        s->hits[0].share = 1.0;
    return 1;
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

int rs_mesh_closest_among(const rs_surface *s, const rs_query *q, const int *const *cand,
                          const int *ncand, rs_contacts *out, rs_error *err)
{
    const rs_mesh *m = s->impl;
    if (!m)
        return rs_error_set(err, RS_ERR_ARG, "rs_surface_query: mesh '%s' has no data",
                            s->name);
    if (!q->slave.x || !q->slave.y || !q->slave.z)
        return rs_error_set(err, RS_ERR_ARG, "rs_surface_query: missing coordinates");
    const rs_pose *pose = moved_pose(q);
    const int *hint = m->zone ? q->hint : NULL;
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
        if (!(gap_lim >= 0.0)) {
            if (q->near)
                q->near[i] = 0.0;
            continue;
        }
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
        /* a slave held on a face, in that face's clear zone: its contact from the face
         * alone (with a depth limit; without one, the reach is the nearest triangle's) */
        int fast = 0;
        if (hint && isfinite(q->dist_min) &&
            (fast = hinted_hits(m, s->sides, p, hint[i], gap_lim, q->dist_min, &sc)) < 0) {
            rc = rs_error_set(err, RS_ERR_NOMEM, "out of memory in the mesh query");
            break;
        }
        if (fast) {
            if (q->near)
                q->near[i] = 0.0;
        } else {
            const int *ids = sc.ids;
            int nt;
            if (cand) { /* the slave's candidate triangles (rs_mesh_candidates) */
                ids = cand[i];
                nt = ncand[i];
            } else {
                nt = box_triangles(m, p, reach, &sc.ids, &sc.cap);
                ids = sc.ids;
            }
            /* without a depth limit, penetrations reach down to the nearest triangle: the
             * same contacts with and without candidate lists */
            const double depth = isfinite(q->dist_min) ? q->dist_min : -reach;
            if (nt < 0 || point_hits(m, s->sides, p, r, ids, nt, gap_lim, depth, &sc)) {
                rc = rs_error_set(err, RS_ERR_NOMEM, "out of memory in the mesh query");
                break;
            }
            /* the nearest candidate's distance; without lists, triangles beyond the
             * box lie farther than the reach */
            if (q->near)
                q->near[i] = cand ? sqrt(sc.near2) : fmin(sqrt(sc.near2), reach);
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

int rs_mesh_closest(const rs_surface *s, const rs_query *q, rs_contacts *out, rs_error *err)
{
    return rs_mesh_closest_among(s, q, NULL, NULL, out, err);
}
