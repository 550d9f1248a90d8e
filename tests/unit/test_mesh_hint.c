/* The MESH query with hints (rs_query.hint): a sphere held on a face and inside that
 * face's clear zone (src/faceted/mesh_zone.c) gets its contact from the face alone, or
 * from the coplanar face across the diagonal of the planar quad the zone covers. The
 * contacts must be those of the query without hints, value for value: on a tessellated
 * cylinder seen from inside (concave folds, the benchmark's; its quads split in triangles
 * as in an STL, and kept as planar quads), where the quads' zones take nearly half the
 * points held on a face, a UV sphere from both sides
 * (convex and concave folds, vertices of many faces), a bumpy height field (valleys,
 * ridges, saddles), a box of quads (right-angled convex edges, two-triangle elements) and
 * a thin slab (the other sheet within reach), one- and two-sided, with the tree and with
 * candidate lists, at random points biased to edges and vertices, under right and wrong
 * hints. Where the hint gave the contact, it is the brute-force nearest point of all
 * triangles (closest points written here); the lists' distance bound (rs_query.near)
 * never exceeds the distance to a triangle that can give a contact. The wall's held faces
 * (rs_mesh_held_faces, one sphere at a time) are the hinted query's contacts, value for
 * value, in the reference configuration and under a pose, for every sphere the zone
 * takes, and flag every other; and at the diagonals and folds of the cylinder's quads,
 * against the query without hints. */
#include "faceted/cgal_mesh.h"
#include "faceted/mesh.h"
#include "faceted/mesh_held.h"
#include "faceted/mesh_regions.h"
#include "faceted/mesh_zone.h"
#include "mesh_soup.h"
#include "rigidsurf/motion.h"
#include "rigidsurf/surface.h"
#include "rigidsurf/vec.h"
#include "rs_test.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* An open height field over [0, 1]^2 of n x n cells, z random in [0, amp], each cell
 * two triangles along a random diagonal; wound upward. */
static void height_field(soup *s, int n, double amp, unsigned long long seed)
{
    for (int j = 0; j <= n; j++)
        for (int i = 0; i <= n; i++)
            sp_point(s, (double)i / n, (double)j / n, amp * rs_test_urand(&seed));
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            const int a = j * (n + 1) + i, b = a + 1, c = b + n + 1, d = a + n + 1;
            if (rs_test_urand(&seed) < 0.5) {
                sp_poly(s, 3, a, b, c, 0);
                sp_poly(s, 3, a, c, d, 0);
            } else {
                sp_poly(s, 3, a, b, d, 0);
                sp_poly(s, 3, b, c, d, 0);
            }
        }
}

/* A box [0, lx] x [0, ly] x [0, lz], each face a grid of n x n planar quads, wound
 * outward. */
static void box(soup *s, int n, double lx, double ly, double lz)
{
    const double L[3] = {lx, ly, lz};
    for (int ax = 0; ax < 3; ax++)
        for (int hi = 0; hi < 2; hi++) {
            const int u = (ax + 1) % 3, v = (ax + 2) % 3, base = s->np;
            for (int j = 0; j <= n; j++)
                for (int i = 0; i <= n; i++) {
                    double p[3];
                    p[ax] = hi ? L[ax] : 0.0;
                    p[u] = L[u] * i / n;
                    p[v] = L[v] * j / n;
                    sp_point(s, p[0], p[1], p[2]);
                }
            for (int j = 0; j < n; j++)
                for (int i = 0; i < n; i++) {
                    const int a = base + j * (n + 1) + i, b = a + 1, c = b + n + 1,
                              d = a + n + 1;
                    if (hi) /* u x v along +ax */
                        sp_poly(s, 4, a, b, c, d);
                    else
                        sp_poly(s, 4, a, d, c, b);
                }
        }
}

/* ---- brute force: the closest point of a triangle ---------------------------------- */

static double dist3(const double a[3], const double b[3])
{
    const double d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    return rs_norm3(d);
}

/* The closest point c of segment a b to p. */
static void on_segment(const double *a, const double *b, const double p[3], double c[3])
{
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double w[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
    const double f = fmin(1.0, fmax(0.0, rs_dot3(w, u) / rs_dot3(u, u)));
    for (int d = 0; d < 3; d++)
        c[d] = a[d] + f * u[d];
}

/* The distance from p to triangle a b c, its closest point in cp: the foot on the plane
 * where it lies inside, else the nearest of the edges' closest points. */
static double on_triangle(const double *a, const double *b, const double *c,
                          const double p[3], double cp[3])
{
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double n[3];
    rs_cross3(u, v, n);
    const double nn = rs_dot3(n, n);
    const double w[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
    double cw[3], cv[3];
    rs_cross3(w, v, cw);
    rs_cross3(u, w, cv);
    const double s = rs_dot3(cw, n) / nn, t = rs_dot3(cv, n) / nn;
    if (s >= 0.0 && t >= 0.0 && s + t <= 1.0) {
        for (int d = 0; d < 3; d++)
            cp[d] = a[d] + s * u[d] + t * v[d];
        return dist3(p, cp);
    }
    const double *e[3][2] = {{a, b}, {b, c}, {c, a}};
    double best = INFINITY;
    for (int k = 0; k < 3; k++) {
        double q[3];
        on_segment(e[k][0], e[k][1], p, q);
        const double dq = dist3(p, q);
        if (dq < best) {
            best = dq;
            memcpy(cp, q, sizeof q);
        }
    }
    return best;
}

static double nearest_of_all(const rs_mesh *m, const double p[3], double cp[3])
{
    double best = INFINITY;
    for (int t = 0; t < m->nt; t++) {
        const int *v = m->rec[t].v;
        double c[3];
        const double d =
            on_triangle(m->xyz + 3 * v[0], m->xyz + 3 * v[1], m->xyz + 3 * v[2], p, c);
        if (d < best) {
            best = d;
            memcpy(cp, c, sizeof c);
        }
    }
    return best;
}

/* ---- the comparison ---------------------------------------------------------------- */

/* Are lists a and b the same, value for value? */
static int same_contacts(const rs_contacts *a, const rs_contacts *b)
{
    if (a->n != b->n || a->shared != b->shared)
        return 0;
    for (int k = 0; k < a->n; k++) {
        if (a->point[k] != b->point[k] || a->feature[k] != b->feature[k] ||
            a->dist[k] != b->dist[k] || a->share[k] != b->share[k])
            return 0;
        for (int d = 0; d < 3; d++)
            if (a->xm[d][k] != b->xm[d][k] || a->nrm[d][k] != b->nrm[d][k] ||
                a->t1[d][k] != b->t1[d][k] || a->t2[d][k] != b->t2[d][k])
                return 0;
    }
    return 1;
}

enum { NB = 64 }; /* points a query */

typedef struct tally {
    int points, hinted, fast, contacts, held, bad;
} tally;

/* The held faces of the NB spheres x, y, z, r holding hint under pose (NULL: none) against
 * the hinted query's contacts q of the same spheres, value for value: a sphere whose held
 * face is flagged has that one contact (frame by the FACETED convention), and a sphere the
 * zone takes (fast[i]) whose contact lies no deeper than its radius is flagged. Returns
 * the number of flagged spheres, -1 on a mismatch. */
static int held_against(const rs_surface *s, const rs_pose *pose, const double *x,
                        const double *y, const double *z, const double *r, const int *hint,
                        double gap_max, double rmax, const int *fast, const rs_contacts *q)
{
    rs_contacts c;
    memset(&c, 0, sizeof c);
    rs_error e;
    if (rs_contacts_reserve(&c, NB, &e) != RS_OK)
        return -1;
    int face[NB], nface = 0, bad = 0;
    rs_mesh_held_faces(s, pose, NB, x, y, z, r, hint, gap_max, -rmax, &c, face);
    rs_frame_orient(s->ops->frame, &c, 0, c.n);
    for (int i = 0; i < NB && !bad; i++) {
        int k = -1, nk = 0;
        for (int a = 0; a < q->n; a++)
            if (q->point[a] == i)
                k = a, nk++;
        const int kept = fast[i] && nk == 1 && q->dist[k] >= -r[i];
        bad |= face[i] != kept;
        if (!face[i] || bad)
            continue;
        nface++;
        bad |= c.point[i] != i || c.feature[i] != q->feature[k] ||
               c.dist[i] != q->dist[k] || c.share[i] != 1.0 || q->share[k] != 1.0 ||
               c.curv[0][i] != 0.0 || c.curv[1][i] != 0.0;
        for (int d = 0; d < 3; d++)
            bad |= c.xm[d][i] != q->xm[d][k] || c.nrm[d][i] != q->nrm[d][k] ||
                   c.t1[d][i] != q->t1[d][k] || c.t2[d][i] != q->t2[d][k];
        if (bad)
            fprintf(stderr,
                    "held face of sphere %d: %d at %.17g, the query's %d at %.17g\n", i,
                    c.feature[i], c.dist[i], q->feature[k], q->dist[k]);
    }
    rs_contacts_free(&c);
    return bad ? -1 : nface;
}

/* Does the hint of point p send it through its face's zone (mesh_query.c's own test)? */
static int takes_zone(const rs_mesh *m, const double p[3], int hint, double lim)
{
    double h;
    return rs_mesh_zone_face(m, p, hint, lim, &h) >= 0;
}

/* Is face feature f the face of element el or of a triangle across a FLAT edge of one of
 * el's triangles (the other half of a planar quad whose zone el's triangle holds)? */
static int face_or_flat_neighbour(const rs_mesh *m, int el, int f)
{
    if (f == RS_FEATURE(RS_FEAT_FACE, el))
        return 1;
    for (int t = m->el_t0[el]; t < m->el_t0[el + 1]; t++)
        for (int j = 0; j < 3; j++)
            if (m->rec[t].kind[j] == RS_EDGE_FLAT && m->rec[t].nbr[j] >= 0 &&
                f == RS_FEATURE(RS_FEAT_FACE, m->rec[m->rec[t].nbr[j] / 3].el))
                return 1;
    return 0;
}

/* The point of triangle t's plane at height h whose sides of the edges of records ra
 * (slot a) and rb (slot b) are sa and sb (three planes met: Cramer's rule). */
static void meet(const rs_mesh *m, int t, double h, const rs_mtri *ra, int a, double sa,
                 const rs_mtri *rb, int b, double sb, double x[3])
{
    const rs_mtri *r = m->rec + t;
    const double *g[3] = {r->n, ra->e[a], rb->e[b]};
    const double rhs[3] = {rs_dot3(r->n, r->a0) + h, ra->e[a][3] + sa, rb->e[b][3] + sb};
    double c12[3], c20[3], c01[3];
    rs_cross3(g[1], g[2], c12);
    rs_cross3(g[2], g[0], c20);
    rs_cross3(g[0], g[1], c01);
    const double det = rs_dot3(g[0], c12);
    for (int d = 0; d < 3; d++)
        x[d] = (rhs[0] * c12[d] + rhs[1] * c20[d] + rhs[2] * c01[d]) / det;
}

/* A point at the border of triangle t's clear zone, seen from inside: at a random height
 * within it, near a corner or on an edge of the inset triangle (or quad) there, moved
 * toward its middle by a fraction 10^-12 .. 10^-2 of its size. 0 when t has no zone. */
static int zone_border(const rs_mesh *m, int t, unsigned long long *seed, double p[3])
{
    const rs_mzone *z = rs_mesh_zone(m, t);
    if (!z)
        return 0;
    const int side =
        z->clear[0] > 0.0 && (z->clear[1] <= 0.0 || rs_test_urand(seed) < 0.5) ? 1 : -1;
    const double ah = z->eps + (z->hmax - z->eps) * rs_test_urand(seed), h = side * ah;
    /* the zone's lines: its triangle's slots, or the quad's outer edges in turn */
    const int nl = z->quad ? 4 : 3;
    const rs_mtri *lr[4];
    int ls[4];
    for (int k = 0; k < nl; k++) {
        const int t2 = z->quad ? m->rec[t].nbr[z->jd] / 3 : t;
        lr[k] = m->rec + (k < 2 ? t : t2);
        ls[k] = z->quad ? z->slot[k] : k;
    }
    double c[4][3], mid[3] = {0, 0, 0};
    for (int k = 0; k < nl; k++) {
        const int a = (k + nl - 1) % nl, b = k;
        meet(m, t, h, lr[a], ls[a], z->eps + z->kappa[a] * ah, lr[b], ls[b],
             z->eps + z->kappa[b] * ah, c[k]);
        for (int d = 0; d < 3; d++)
            mid[d] += c[k][d] / nl;
    }
    const int k = (int)(rs_test_xorshift(seed) % (unsigned long long)nl);
    const double w = rs_test_urand(seed), f = pow(10.0, -2.0 - 10.0 * rs_test_urand(seed));
    for (int d = 0; d < 3; d++) {
        const double q = rs_test_urand(seed) < 0.5
                             ? c[k][d]
                             : (1.0 - w) * c[k][d] + w * c[(k + 1) % nl][d];
        p[d] = q + f * (mid[d] - q);
    }
    return 1;
}

/* npts random points near the surface, in queries of NB: spheres of radii r0 / 2 .. r0 at
 * heights up to 1.5 r0 on either side of a random triangle, a quarter of them within
 * 10^-1 .. 10^-12 of one of its edges, a quarter of one of its nodes, and a quarter at
 * the border of its clear zone. Each query with hints against the query without, through
 * the tree and through candidate lists made with margin extra (at the points, and from
 * points moved by up to the margin). */
static void run_case(const char *name, const rs_surface *s, double r0, double gap_max,
                     double extra, int npts, unsigned long long seed, tally *ty)
{
    const rs_mesh *m = s->impl;
    double x[NB], y[NB], z[NB], r[NB], x0[NB], y0[NB], z0[NB], near_t[NB], near_h[NB],
        near_l[NB];
    int hint[NB];
    rs_contacts ct, ch, cl, clh, chp;
    memset(&chp, 0, sizeof chp);
    memset(&ct, 0, sizeof ct);
    memset(&ch, 0, sizeof ch);
    memset(&cl, 0, sizeof cl);
    memset(&clh, 0, sizeof clh);
    rs_cands cd;
    memset(&cd, 0, sizeof cd);
    rs_error e;
    for (int b0 = 0; b0 < npts; b0 += NB) {
        double rmax = 0.0;
        for (int i = 0; i < NB; i++) {
            const int t = (int)(rs_test_xorshift(&seed) % (unsigned long long)m->nt);
            const rs_mtri *rt = m->rec + t;
            double w[3] = {rs_test_urand(&seed), rs_test_urand(&seed),
                           rs_test_urand(&seed)};
            const int mode = (int)(rs_test_xorshift(&seed) % 4), j = (int)(seed % 3);
            const double tiny = pow(10.0, -1.0 - 11.0 * rs_test_urand(&seed));
            if (mode == 1)
                w[j] = tiny * (w[0] + w[1] + w[2]); /* near the edge opposite node j */
            else if (mode == 2)
                w[(j + 1) % 3] = w[(j + 2) % 3] = tiny * w[j]; /* near node j */
            const double sw = w[0] + w[1] + w[2];
            const double hgt = (2.0 * rs_test_urand(&seed) - 1.0) * 1.5 * r0;
            double p[3];
            if (mode != 3 || !zone_border(m, t, &seed, p))
                for (int d = 0; d < 3; d++) {
                    p[d] = hgt * rt->n[d];
                    for (int k = 0; k < 3; k++)
                        p[d] += w[k] / sw * m->xyz[3 * rt->v[k] + d];
                }
            x[i] = p[0], y[i] = p[1], z[i] = p[2];
            r[i] = r0 * (0.5 + 0.5 * rs_test_urand(&seed));
            rmax = fmax(rmax, r[i]);
            /* mostly the face under it; else another face, one of its edges or nodes, or
             * none */
            const double u = rs_test_urand(&seed);
            const int other = (int)(rs_test_xorshift(&seed) % (unsigned long long)m->nt);
            hint[i] = u < 0.8    ? RS_FEATURE(RS_FEAT_FACE, rt->el)
                      : u < 0.88 ? RS_FEATURE(RS_FEAT_FACE, m->rec[other].el)
                      : u < 0.92 ? RS_FEATURE(RS_FEAT_EDGE, rt->edge[j])
                      : u < 0.96 ? RS_FEATURE(RS_FEAT_VERTEX, rt->v[j])
                      : u < 0.98 ? RS_FEATURE_NONE
                                 : RS_FEATURE(RS_FEAT_FACE, m->nel + 7);
            /* the lists' points: moved by up to the margin */
            double dv[3] = {rs_test_urand(&seed) - 0.5, rs_test_urand(&seed) - 0.5,
                            rs_test_urand(&seed) - 0.5};
            const double l = rs_norm3(dv), f = b0 % (2 * NB) ? 0.0 : 0.999 * extra;
            x0[i] = x[i] + f * dv[0] / l, y0[i] = y[i] + f * dv[1] / l;
            z0[i] = z[i] + f * dv[2] / l;
        }
        rs_query q;
        memset(&q, 0, sizeof q);
        q.n = NB;
        q.slave.x = x0, q.slave.y = y0, q.slave.z = z0, q.slave.radius = r;
        q.gap_max = gap_max;
        q.dist_min = -rmax;
        int ok = rs_surface_candidates(s, &q, extra, &cd, &e) == RS_OK;
        const int *lists[NB];
        int counts[NB];
        for (int i = 0; ok && i < NB; i++) {
            lists[i] = cd.ids + cd.off[i];
            counts[i] = cd.off[i + 1] - cd.off[i];
        }
        q.slave.x = x, q.slave.y = y, q.slave.z = z;
        ct.n = ch.n = cl.n = clh.n = 0;
        q.near = near_t;
        ok = ok && rs_surface_query(s, &q, &ct, &e) == RS_OK;
        q.near = near_l;
        ok = ok && rs_surface_query_among(s, &q, lists, counts, &cl, &e) == RS_OK;
        q.hint = hint;
        q.near = near_h;
        ok = ok && rs_surface_query(s, &q, &ch, &e) == RS_OK &&
             rs_surface_query_among(s, &q, lists, counts, &clh, &e) == RS_OK;
        if (!ok) {
            fprintf(stderr, "%s: query: %s\n", name, e.msg);
            ty->bad++;
            break;
        }
        if (!same_contacts(&ct, &ch) || !same_contacts(&cl, &clh) ||
            !same_contacts(&ct, &cl)) {
            fprintf(stderr, "%s: points %d .. %d: the hints change the contacts\n", name,
                    b0, b0 + NB - 1);
            ty->bad++;
        }
        /* the held faces: in place, then under a pose that turns the points with it */
        int fastv[NB];
        for (int i = 0; i < NB; i++) {
            const double p[3] = {x[i], y[i], z[i]};
            fastv[i] = takes_zone(m, p, hint[i], fmax(gap_max + r[i], rmax));
        }
        const int held = held_against(s, NULL, x, y, z, r, hint, gap_max, rmax, fastv, &ch);
        const double ang = 0.3 + 0.1 * (b0 / NB), ca = cos(ang), sa = sin(ang);
        const rs_pose pose = {{ca, sa, 0.0, -sa, ca, 0.0, 0.0, 0.0, 1.0},
                              {0.25, -0.5, 0.125}};
        double gx[NB], gy[NB], gz[NB];
        for (int i = 0; i < NB; i++) {
            const double X[3] = {x[i], y[i], z[i]};
            double g[3];
            rs_pose_to_global(&pose, X, g);
            gx[i] = g[0], gy[i] = g[1], gz[i] = g[2];
        }
        rs_query qp = q;
        qp.slave.x = gx, qp.slave.y = gy, qp.slave.z = gz;
        qp.pose = &pose;
        qp.near = NULL;
        chp.n = 0;
        int held_posed = -1;
        if (rs_surface_query(s, &qp, &chp, &e) == RS_OK) {
            /* the points the zone takes after the turn, as the query sees them */
            int fastp[NB];
            for (int i = 0; i < NB; i++) {
                double X[3];
                slave_local(&qp, &pose, i, X);
                fastp[i] = takes_zone(m, X, hint[i], fmax(gap_max + r[i], rmax));
            }
            held_posed =
                held_against(s, &pose, gx, gy, gz, r, hint, gap_max, rmax, fastp, &chp);
        }
        if (held < 0 || held_posed < 0) {
            fprintf(stderr, "%s: points %d .. %d: the held faces differ from the query\n",
                    name, b0, b0 + NB - 1);
            ty->bad++;
        }
        ty->held += held > 0 ? held : 0;
        for (int i = 0; i < NB; i++) {
            const double p[3] = {x[i], y[i], z[i]};
            const int fast = fastv[i];
            ty->points++;
            ty->hinted += hint[i] >= 0 && RS_FEATURE_TYPE(hint[i]) == RS_FEAT_FACE;
            ty->fast += fast;
            double cp[3] = {0.0, 0.0, 0.0};
            const double best = nearest_of_all(m, p, cp);
            /* no triangle nearer than the bounds */
            if (!(near_t[i] <= best + 1e-12)) {
                fprintf(stderr,
                        "%s: point %d: bound %.17g beyond the nearest triangle %.17g\n",
                        name, b0 + i, near_t[i], best);
                ty->bad++;
            }
            double lbest = INFINITY;
            for (int k = 0; k < counts[i]; k++) {
                const int *v = m->rec[lists[i][k]].v;
                double c[3];
                lbest = fmin(lbest, on_triangle(m->xyz + 3 * v[0], m->xyz + 3 * v[1],
                                                m->xyz + 3 * v[2], p, c));
            }
            if (!(near_l[i] <= lbest + 1e-12)) {
                fprintf(stderr,
                        "%s: point %d: bound %.17g beyond its nearest candidate "
                        "%.17g\n",
                        name, b0 + i, near_l[i], lbest);
                ty->bad++;
            }
            if (fast && near_h[i] != 0.0) {
                fprintf(stderr, "%s: point %d: a bound where the hint gave the contact\n",
                        name, b0 + i);
                ty->bad++;
            }
            if (!fast)
                continue;
            /* the face's contact, where there is one, is the nearest point of the mesh */
            for (int k = 0; k < ch.n; k++) {
                if (ch.point[k] != i)
                    continue;
                ty->contacts++;
                const double xm[3] = {ch.xm[0][k], ch.xm[1][k], ch.xm[2][k]};
                if (!face_or_flat_neighbour(m, RS_FEATURE_INDEX(hint[i]), ch.feature[k]) ||
                    !(fabs(fabs(ch.dist[k]) - best) <= 1e-12) || !(dist3(xm, cp) <= 1e-9)) {
                    fprintf(stderr,
                            "%s: point %d: hinted contact %d at %.17g, brute force "
                            "%.17g\n",
                            name, b0 + i, ch.feature[k], ch.dist[k], best);
                    ty->bad++;
                }
            }
        }
    }
    rs_contacts_free(&ct);
    rs_contacts_free(&ch);
    rs_contacts_free(&cl);
    rs_contacts_free(&clh);
    rs_contacts_free(&chp);
    rs_cands_free(&cd);
}

/* One mesh, one- and two-sided. */
static void mesh_case(const char *name, soup *sp, double r0, double gap_max, double extra,
                      int npts, unsigned long long seed, double fast_min)
{
    for (int sides = 1; sides <= 2; sides++) {
        rs_surface s;
        if (make(sp, sides, &s) != RS_OK) {
            rs_test_current_failed = 1;
            return;
        }
        tally ty = {0, 0, 0, 0, 0, 0};
        run_case(name, &s, r0, gap_max, extra, npts, seed + (unsigned)sides, &ty);
        printf("  %s, %d side%s: %d points, %d hinted faces, %d from the zone (%d "
               "contacts, %d held faces)\n",
               name, sides, sides == 1 ? "" : "s", ty.points, ty.hinted, ty.fast,
               ty.contacts, ty.held);
        rs_surface_free(&s);
        ENSURE(ty.bad == 0);
        ENSURE(ty.points == npts);
        /* the zones take a good share of the points held on their faces */
        ENSURE(ty.fast >= fast_min * ty.hinted);
        ENSURE(fast_min == 0.0 || ty.contacts > 0);
        /* the held faces give those contacts */
        ENSURE(fast_min == 0.0 || ty.held > 0);
    }
}

static void cylinder_from_inside(void)
{
    soup sp;
    memset(&sp, 0, sizeof sp);
    cylinder(&sp, 200, 10, 0.05, -0.002, 0.317, 0);
    mesh_case("cylinder", &sp, 0.001, 0.0, 0.00025, 4096, 101, 0.45);
    sp_free(&sp);
    cylinder(&sp, 200, 10, 0.05, -0.002, 0.317, 1);
    mesh_case("cylinder of quads", &sp, 0.001, 0.0, 0.00025, 4096, 102, 0.45);
    sp_free(&sp);
}

/* The held faces at the places a quad's zone decides most: spheres touching the
 * benchmark's cylinder (triangles, as in its STL) across the diagonals of its quads, a
 * fraction 10^-12 .. 10^-1 of the quad's width to either side, and near its folds, the
 * quads' outer edges, 10^-4 .. 10^-1 of it inside (where the zones' insets end). Each
 * flagged sphere's contact must be the query's without hints (the tree's, every feature
 * tested), value for value; the zone of a quad names the triangle across its diagonal
 * (rs_mzone.t2) as the records do, and that triangle's zone is the same quad seen from it.
 */
static void quad_diagonals_and_folds(void)
{
    soup sp;
    memset(&sp, 0, sizeof sp);
    cylinder(&sp, 200, 10, 0.05, -0.002, 0.317, 0);
    for (int sides = 1; sides <= 2; sides++) {
        rs_surface s;
        if (make(&sp, sides, &s) != RS_OK) {
            rs_test_current_failed = 1;
            break;
        }
        const rs_mesh *m = s.impl;
        const double r0 = 0.001;
        unsigned long long seed = 909 + (unsigned)sides;
        rs_contacts hc, gc;
        memset(&hc, 0, sizeof hc);
        memset(&gc, 0, sizeof gc);
        rs_error e;
        int points = 0, flagged = 0, across = 0, own = 0, at_fold = 0, bad = 0;
        ENSURE(rs_contacts_reserve(&hc, NB, &e) == RS_OK);
        for (int b0 = 0; b0 < 4096 && !bad; b0 += NB) {
            double x[NB], y[NB], z[NB], r[NB];
            int hint[NB], tri[NB], fold[NB];
            for (int i = 0; i < NB; i++) {
                int t = -1;
                const rs_mzone *zn = NULL;
                while (!zn) {
                    t = (int)(rs_test_xorshift(&seed) % (unsigned long long)m->nt);
                    zn = rs_mesh_zone(m, t);
                    zn = zn && zn->quad ? zn : NULL;
                }
                const rs_mtri *rt = m->rec + t;
                const int t2 = rt->nbr[zn->jd] / 3;
                const rs_mzone *z2 = rs_mesh_zone(m, t2);
                if (zn->t2 != t2 || !z2 || !z2->quad || z2->t2 != t ||
                    m->rec[t2].nbr[z2->jd] / 3 != t)
                    bad++;
                /* on the diagonal (slot jd of t) or on an outer edge of either triangle */
                const int k = (int)(rs_test_xorshift(&seed) % 5);
                const rs_mtri *re = k == 4 ? rt : m->rec + (k < 2 ? t : t2);
                const int slot = k == 4 ? zn->jd : zn->slot[k];
                const double *a = m->xyz + 3 * re->v[slot];
                const double *bb = m->xyz + 3 * re->v[(slot + 1) % 3];
                const double w = rs_test_urand(&seed);
                /* the width across the edge: the distance to the far node */
                const double *c = m->xyz + 3 * re->v[(slot + 2) % 3];
                const double width = rs_dot3(re->e[slot], c) - re->e[slot][3];
                const double off =
                    width * pow(10.0, -1.0 - (k == 4 ? 11.0 : 3.0) * rs_test_urand(&seed));
                /* into the triangle, or, across the diagonal, to either side */
                const double sg = k == 4 && rs_test_urand(&seed) < 0.5 ? -1.0 : 1.0;
                r[i] = r0 * (0.5 + 0.5 * rs_test_urand(&seed));
                const double hs = sides == 2 && rs_test_urand(&seed) < 0.25 ? -1.0 : 1.0;
                const double h = hs * r[i] * (0.8 + 0.2 * rs_test_urand(&seed));
                double p[3];
                for (int d = 0; d < 3; d++)
                    p[d] = a[d] + w * (bb[d] - a[d]) + sg * off * re->e[slot][d] +
                           h * re->n[d];
                x[i] = p[0], y[i] = p[1], z[i] = p[2];
                hint[i] = RS_FEATURE(RS_FEAT_FACE, rt->el);
                tri[i] = t;
                fold[i] = k < 4;
            }
            double rmax = 0.0;
            for (int i = 0; i < NB; i++)
                rmax = fmax(rmax, r[i]);
            int face[NB];
            rs_mesh_held_faces(&s, NULL, NB, x, y, z, r, hint, 0.0, -rmax, &hc, face);
            rs_frame_orient(s.ops->frame, &hc, 0, hc.n);
            rs_query q;
            memset(&q, 0, sizeof q);
            q.n = NB;
            q.slave.x = x, q.slave.y = y, q.slave.z = z, q.slave.radius = r;
            q.gap_max = 0.0;
            q.dist_min = -rmax;
            gc.n = 0;
            if (rs_surface_query(&s, &q, &gc, &e) != RS_OK) {
                fprintf(stderr, "query: %s\n", e.msg);
                bad++;
                break;
            }
            for (int i = 0; i < NB; i++) {
                points++;
                if (!face[i])
                    continue;
                flagged++;
                int kk = -1, nk = 0;
                for (int a = 0; a < gc.n; a++)
                    if (gc.point[a] == i)
                        kk = a, nk++;
                int same = nk == 1 && hc.point[i] == i && hc.feature[i] == gc.feature[kk] &&
                           hc.dist[i] == gc.dist[kk] && gc.share[kk] == 1.0 &&
                           hc.curv[0][i] == 0.0 && hc.curv[1][i] == 0.0 &&
                           hc.share[i] == 1.0;
                for (int d = 0; d < 3; d++)
                    same = same && hc.xm[d][i] == gc.xm[d][kk] &&
                           hc.nrm[d][i] == gc.nrm[d][kk] && hc.t1[d][i] == gc.t1[d][kk] &&
                           hc.t2[d][i] == gc.t2[d][kk];
                if (!same) {
                    fprintf(stderr,
                            "%d sides, sphere %d: held face %d at %.17g, the query's %d "
                            "contacts, %d at %.17g\n",
                            sides, b0 + i, hc.feature[i], hc.dist[i], nk,
                            kk >= 0 ? gc.feature[kk] : -1, kk >= 0 ? gc.dist[kk] : 0.0);
                    bad++;
                }
                const int mine =
                    hc.feature[i] == RS_FEATURE(RS_FEAT_FACE, m->rec[tri[i]].el);
                own += mine;
                across += !mine;
                at_fold += fold[i];
            }
        }
        printf("  cylinder, %d side%s: %d spheres at diagonals and folds, %d held (%d on "
               "the held triangle, %d across the diagonal, %d near a fold)\n",
               sides, sides == 1 ? "" : "s", points, flagged, own, across, at_fold);
        rs_contacts_free(&hc);
        rs_contacts_free(&gc);
        rs_surface_free(&s);
        ENSURE(bad == 0);
        ENSURE(points == 4096);
        /* the zones take most spheres off the folds, on both sides of the diagonals */
        ENSURE(flagged >= points / 4);
        ENSURE(own > 0 && across > 0 && at_fold > 0);
    }
    sp_free(&sp);
}

static void sphere_both_sides(void)
{
    soup sp;
    memset(&sp, 0, sizeof sp);
    uv_sphere(&sp, 24, 48);
    mesh_case("sphere", &sp, 0.02, 0.005, 0.005, 4096, 202, 0.2);
    sp_free(&sp);
}

/* Bumps of up to 25 degrees, and steep ones (slopes up to 2, where few faces have a
 * zone for these spheres). */
static void bumpy_fields(void)
{
    soup sp;
    memset(&sp, 0, sizeof sp);
    height_field(&sp, 24, 0.02, 77);
    mesh_case("field", &sp, 0.004, 0.001, 0.002, 4096, 303, 0.1);
    sp_free(&sp);
    height_field(&sp, 24, 0.08, 78);
    mesh_case("steep field", &sp, 0.004, 0.001, 0.002, 4096, 304, 0.0);
    sp_free(&sp);
}

static void box_of_quads(void)
{
    soup sp;
    memset(&sp, 0, sizeof sp);
    box(&sp, 6, 1.0, 0.8, 0.6);
    mesh_case("box", &sp, 0.03, 0.0, 0.01, 4096, 404, 0.3);
    sp_free(&sp);
}

/* Two sheets 0.02 apart: spheres of radius up to 0.008 within reach of one reach the
 * other's back (a one-sided slab's penetrations), and of radius up to 0.03 its front. */
static void thin_slab(void)
{
    soup sp;
    memset(&sp, 0, sizeof sp);
    box(&sp, 4, 1.0, 1.0, 0.02);
    mesh_case("slab", &sp, 0.008, 0.0, 0.004, 4096, 505, 0.25);
    mesh_case("slab, large spheres", &sp, 0.03, 0.0, 0.01, 4096, 506, 0.0);
    sp_free(&sp);
}

int main(void)
{
    RS_RUN(cylinder_from_inside);
    RS_RUN(quad_diagonals_and_folds);
    RS_RUN(sphere_both_sides);
    RS_RUN(bumpy_fields);
    RS_RUN(box_of_quads);
    RS_RUN(thin_slab);
    return rs_test_summary();
}
