/* The clear zone of a triangle's face (mesh_zone.h): the points near face t that no other
 * feature of the mesh owns within a distance, by the query's own tests (point_hits in
 * mesh_query.c), so that the query can give a point held on t its contact from t's
 * record alone, or from the record of the coplanar triangle t2 across t's longest FLAT
 * edge (the diagonal of the planar quad the two make) where the point's foot lies there.
 *
 * The zone is two convex pieces, in front of t's plane (eps <= h <= hmax) and behind it:
 * at height h, the inset triangle (or quad) whose side of each of its edges j is at least
 * eps + kappa_j |h| (kappa_j > 0 across a fold, so that the neighbour's face, whose
 * prism leans over t there, stays out; the base off the plane keeps out the face beyond
 * a right-angled convex edge). A quad's diagonal needs no inset: the query gives a point
 * on either side of it the face of the triangle that holds its foot, as the zone's test
 * does (rs_mzone_quad_face). It is made once per face (a quad's for both triangles), and
 * checked against every feature within hmax of it:
 *  - the edges of t (and t2) own no point of it: each needs the point outside each of
 *    its faces (a side <= 0); the zone keeps the outer edges' sides >= eps > 0, the very
 *    numbers the query computes (side_of and tri_bound evaluate one expression of one
 *    record), and a FLAT diagonal owns nothing;
 *  - t's own vertices (a quad's diagonal's two ends) own none: a point whose foot q lies
 *    in a triangle t' of the zone, at least eps from t''s outer edges, on one of which
 *    each node v of t' lies, has (q - v).(w - v) >= |q - v|^2 >= eps^2 for one of the two
 *    other nodes w of t' (q - v = s1 (w1 - v) + s2 (w2 - v) with s1, s2 >= 0 and
 *    s1 + s2 <= 1), far above the product's rounding (eps >= 1e-6 of the zone's size and
 *    height); a quad's two other corners are checked as any other vertex;
 *  - any other face, edge or vertex is out of a piece when one of the linear tests of
 *    its region (a side, a position along an edge, a product at a vertex) fails at each
 *    of the piece's corners by more than the rounding, for the test is linear in the
 *    point and fails over the whole piece; else the piece's clear distance is at most a
 *    lower bound of the distance between the piece and the feature's triangle (the
 *    largest gap between their projections on separating axes, mesh_zone_sat.c).
 * The pieces are checked grown by 4 delta on each side (delta = 1e-9 of the mesh's size
 * and coordinates), so that the query's rounding of h and of the sides stays inside
 * them. */
#include "mesh_zone.h"
#include "mesh_regions.h"
#include "mesh_zone_sat.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Most triangles a zone is checked against: a face crowded by more has none. */
#define RS_ZONE_MAX_NEAR 1024

/* The lines a zone is inset from, in turn around its polygon: triangle tri[k]'s edge slot
 * slot[k] (rs_mtri.e). */
typedef struct zlines {
    int tri[4], slot[4], n;
} zlines;

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* The inset polygon of lines L at height z over the plane of frame O, e1, e2 and normal n
 * whose side of line k is s[k]: its corners into c[0 .. L->n) (corner k between lines
 * k - 1 and k). 0 when the inset leaves no convex polygon. */
static int inset(const rs_mesh *m, const zlines *L, const double O[3], const double e1[3],
                 const double e2[3], const double n[3], const double s[4], double z,
                 double c[][3])
{
    const int nl = L->n;
    double g[4][2], rhs[4];
    for (int j = 0; j < nl; j++) {
        const double *e = m->rec[L->tri[j]].e[L->slot[j]];
        g[j][0] = dot3(e, e1);
        g[j][1] = dot3(e, e2);
        rhs[j] = s[j] - (dot3(e, O) - e[3]);
    }
    double q[4][2];
    for (int k = 0; k < nl; k++) {
        const int a = (k + nl - 1) % nl, b = k;
        const double det = g[a][0] * g[b][1] - g[a][1] * g[b][0];
        if (!(fabs(det) > 1e-12))
            return 0;
        q[k][0] = (rhs[a] * g[b][1] - rhs[b] * g[a][1]) / det;
        q[k][1] = (g[a][0] * rhs[b] - g[b][0] * rhs[a]) / det;
        /* strictly inside the other lines: else the polygon is inverted or not convex */
        for (int l = 0; l < nl; l++)
            if (l != a && l != b && !(g[l][0] * q[k][0] + g[l][1] * q[k][1] > rhs[l]))
                return 0;
    }
    for (int k = 0; k < nl; k++)
        for (int d = 0; d < 3; d++)
            c[k][d] = O[d] + q[k][0] * e1[d] + q[k][1] * e2[d] + z * n[d];
    return 1;
}

/* What a zone leaves to its own tests: the faces of its triangles (the query gives a point
 * of the zone the face of the one that holds its foot), their edges (each a side the zone
 * keeps >= eps) and the nodes whose ownership the zone's eps excludes. */
typedef struct zown {
    int tri[2], nt;
    int edge[6], ne;
    int node[3], nn;
} zown;

static int owns_edge(const zown *o, int e)
{
    for (int k = 0; k < o->ne; k++)
        if (o->edge[k] == e)
            return 1;
    return 0;
}

/* How far the features of triangle tp other than the zone's own (o) keep from each piece
 * P[s] with live[s], into clear[s]: INFINITY when each owns no point of it, else the least
 * of lower bounds of the distances of those that may. Each feature's region is made once
 * for both pieces. Each edge and vertex is taken from its first triangle alone (which
 * touches it, so lies within the search when it does). */
static void near_features(const rs_mesh *m, const zown *o, int tp, const zpiece P[2],
                          const zaxes X[2], const int live[2], double delta, double scale,
                          double clear[2])
{
    const rs_mtri *r = m->rec + tp;
    const double margin = 2.0 * delta;
    clear[0] = clear[1] = INFINITY;
    region R;
    /* a region's rays are made only where its planes keep a piece in: the other tests
     * (rs_zone_axes_out) read them */
    int in[2];
    if (tp != o->tri[0] && (o->nt < 2 || tp != o->tri[1])) {
        rs_zone_face_region(m, tp, &R);
        for (int s = 0; s < 2; s++)
            in[s] = live[s] && !rs_zone_planes_out(&P[s], &R, margin);
        if (in[0] || in[1])
            rs_zone_face_rays(m, tp, &R);
        for (int s = 0; s < 2; s++)
            if (in[s] && !rs_zone_axes_out(&P[s], &X[s], &R, margin)) {
                const double *T[3] = {R.v[0], R.v[1], R.v[2]};
                clear[s] = fmin(clear[s], rs_zone_sep_bound(&P[s], &X[s], T, 3));
            }
    }
    for (int j = 0; j < 3; j++) {
        if (!(r->first >> j & 1u))
            continue;
        const int e = r->edge[j];
        if (owns_edge(o, e))
            continue; /* the zone's own edge: its side keeps it out */
        rs_zone_edge_region(m, e, scale, &R);
        for (int s = 0; s < 2; s++)
            in[s] = live[s] && !rs_zone_planes_out(&P[s], &R, margin);
        if (in[0] || in[1])
            rs_zone_edge_rays(m, e, &R);
        for (int s = 0; s < 2; s++)
            if (in[s] && !rs_zone_axes_out(&P[s], &X[s], &R, margin)) {
                const double *T[2] = {R.v[0], R.v[1]};
                clear[s] = fmin(clear[s], rs_zone_sep_bound(&P[s], &X[s], T, 2));
            }
    }
    for (int j = 0; j < 3; j++) {
        if (!(r->first >> (3 + j) & 1u))
            continue;
        const int v = r->v[j];
        int own = 0;
        for (int k = 0; k < o->nn; k++)
            own |= o->node[k] == v;
        if (own)
            continue; /* the zone's own node: eps keeps it out */
        const int ok = rs_zone_vertex_region(m, v, P, live, margin, &R);
        if (ok == 2)
            continue;
        for (int s = 0; s < 2; s++)
            if (live[s] && (!ok || !rs_zone_region_out(&P[s], &X[s], &R, margin))) {
                const double *T[1] = {m->xyz + 3 * v};
                clear[s] = fmin(clear[s], rs_zone_sep_bound(&P[s], &X[s], T, 1));
            }
    }
}

/* How far the faces of edge e lean over each other's prisms per unit of height: the
 * tangent of the largest angle between their normals (either way round, for a mesh
 * without a consistent orientation); 0 for a fold of more than 84 degrees, which no
 * slope keeps out (the zone's base off the plane keeps out the face beyond a convex
 * right angle). */
static double fold_slope(const rs_mesh *m, int e)
{
    double slope = 0.0;
    const int f0 = m->edge_f0[e], f1 = m->edge_f0[e + 1];
    for (int a = f0; a < f1; a++)
        for (int b = a + 1; b < f1; b++) {
            const double *na = m->rec[m->edge_f[a]].n, *nb = m->rec[m->edge_f[b]].n;
            double c[3];
            rs_cross3(na, nb, c);
            const double cs = fabs(dot3(na, nb));
            if (cs > 0.1)
                slope = fmax(slope, rs_norm3(c) / cs);
        }
    return slope;
}

/* The triangles whose tree boxes meet [lo, hi] into *ids (room for *cap, grown): their
 * number, or -1 when out of memory or more than RS_ZONE_MAX_NEAR. */
static int near_triangles(const rs_mesh *m, const double lo[3], const double hi[3],
                          int **ids, int *cap)
{
    int n = rs_cgal_tree_box(m->tree, lo, hi, *ids, *cap);
    if (n > *cap) {
        if (n > RS_ZONE_MAX_NEAR)
            return -1;
        int *ni = realloc(*ids, (size_t)n * sizeof *ni);
        if (!ni)
            return -1;
        *ids = ni;
        *cap = n;
        n = rs_cgal_tree_box(m->tree, lo, hi, *ids, *cap);
    }
    return n >= 0 && n <= *cap ? n : -1;
}

/* The lines of the zone of triangle t: its three slots; or, with pair, the four outer
 * edges of the planar quad of t and the triangle across its FLAT slot jd, in turn. The
 * zone's own features into *o. 0 where the pair forms no quad. */
static int zone_lines(const rs_mesh *m, int t, int pair, int jd, zlines *L, zown *o)
{
    const rs_mtri *r = m->rec + t;
    o->tri[0] = t;
    o->nt = 1;
    o->ne = 3;
    for (int j = 0; j < 3; j++)
        o->edge[j] = r->edge[j];
    if (!pair) {
        L->n = 3;
        o->nn = 3;
        for (int j = 0; j < 3; j++) {
            L->tri[j] = t;
            L->slot[j] = j;
            o->node[j] = r->v[j];
        }
        return 1;
    }
    const int t2 = r->nbr[jd] / 3, j2 = r->nbr[jd] % 3;
    const rs_mtri *r2 = m->rec + t2;
    /* t's outer slots from the diagonal's second node round to its first, then t2's from
     * that node (v[jd]) round to the diagonal's second */
    L->n = 4;
    L->tri[0] = L->tri[1] = t;
    L->slot[0] = (jd + 1) % 3;
    L->slot[1] = (jd + 2) % 3;
    const int a = (j2 + 1) % 3, b = (j2 + 2) % 3;
    const int va = r->v[jd]; /* t2's slot k joins its nodes k and k + 1 */
    const int a_has = r2->v[a] == va || r2->v[(a + 1) % 3] == va;
    L->tri[2] = L->tri[3] = t2;
    L->slot[2] = a_has ? a : b;
    L->slot[3] = a_has ? b : a;
    o->tri[1] = t2;
    o->nt = 2;
    for (int j = 0; j < 3; j++)
        o->edge[3 + j] = r2->edge[j];
    o->ne = 6;
    o->nn = 2; /* each node of the diagonal lies on an outer edge of either triangle */
    o->node[0] = r->v[jd];
    o->node[1] = r->v[(jd + 1) % 3];
    return 1;
}

/* The pair slot of t: its longest FLAT edge of two faces, -1 where it has none. */
static int pair_slot(const rs_mesh *m, int t)
{
    const rs_mtri *r = m->rec + t;
    int best = -1;
    double lbest = 0.0;
    for (int j = 0; j < 3; j++) {
        if (r->kind[j] != RS_EDGE_FLAT || r->nbr[j] < 0)
            continue;
        const double *a = m->xyz + 3 * r->v[j], *b = m->xyz + 3 * r->v[(j + 1) % 3];
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const double l = rs_norm3(u);
        if (l > lbest) {
            lbest = l;
            best = j;
        }
    }
    return best;
}

/* Makes the zone of lines L (own features o) on t's plane into *z, its nodes' folds
 * weighed by kfac (1 or 2); returns 1 when the zone has a side, 0 otherwise. */
static int zone_build(const rs_mesh *m, int t, const zlines *L, const zown *o, double kfac,
                      rs_mzone *z)
{
    const rs_mtri *r = m->rec + t;
    const int nl = L->n;
    /* the polygon's corners: corner k the node that lines k - 1 and k share */
    double V[4][3];
    int vid[4];
    for (int k = 0; k < nl; k++) {
        const rs_mtri *rk = m->rec + L->tri[k];
        const int a = rk->v[L->slot[k]], b = rk->v[(L->slot[k] + 1) % 3];
        const rs_mtri *rn = m->rec + L->tri[(k + 1) % nl];
        const int c = rn->v[L->slot[(k + 1) % nl]],
                  d = rn->v[(L->slot[(k + 1) % nl] + 1) % 3];
        vid[(k + 1) % nl] = (a == c || a == d) ? a : b;
    }
    for (int k = 0; k < nl; k++)
        for (int d = 0; d < 3; d++)
            V[k][d] = m->xyz[3 * vid[k] + d];
    double coord = 0.0;
    for (int d = 0; d < 3; d++)
        coord = fmax(coord, fmax(fabs(m->lo[d]), fabs(m->hi[d])));
    const double delta = 1e-9 * (m->size + coord);
    /* the polygon's size, and its inradius (a triangle's) or the least distance of its
     * centroid from its edges (a quad's) */
    double lmax = 0.0, per = 0.0, cen[3] = {0.0, 0.0, 0.0};
    for (int k = 0; k < nl; k++) {
        for (int l = k + 1; l < nl; l++) {
            const double u[3] = {V[l][0] - V[k][0], V[l][1] - V[k][1], V[l][2] - V[k][2]};
            lmax = fmax(lmax, rs_norm3(u));
        }
        const double *w = V[(k + 1) % nl];
        const double u[3] = {w[0] - V[k][0], w[1] - V[k][1], w[2] - V[k][2]};
        per += rs_norm3(u);
        for (int d = 0; d < 3; d++)
            cen[d] += V[k][d] / nl;
    }
    double rin;
    if (nl == 3) {
        const double ab[3] = {V[1][0] - V[0][0], V[1][1] - V[0][1], V[1][2] - V[0][2]};
        const double ac[3] = {V[2][0] - V[0][0], V[2][1] - V[0][1], V[2][2] - V[0][2]};
        double cr[3];
        rs_cross3(ab, ac, cr);
        rin = rs_norm3(cr) / per;
    } else {
        rin = INFINITY;
        for (int k = 0; k < nl; k++) {
            const double *e = m->rec[L->tri[k]].e[L->slot[k]];
            rin = fmin(rin, dot3(e, cen) - e[3]);
        }
    }
    const double g = 4.0 * delta;
    double lo[3], hi[3];
    for (int d = 0; d < 3; d++) {
        lo[d] = INFINITY;
        hi[d] = -INFINITY;
        for (int k = 0; k < nl; k++) {
            lo[d] = fmin(lo[d], V[k][d] - g);
            hi[d] = fmax(hi[d], V[k][d] + g);
        }
    }
    /* The triangles that touch the polygon, for the folds at its nodes. */
    int cap = 64, *ids = malloc((size_t)cap * sizeof *ids);
    if (!ids)
        return 0;
    int n = near_triangles(m, lo, hi, &ids, &cap);
    /* kappa: how each line's inset grows with |h|, so that the faces beyond the folds of
     * its edges and nodes, whose prisms lean over the zone by their slope times h, stay
     * out: a line's own fold's slope, and kfac times the steepest fold at either of its
     * nodes (twice keeps a triangle's corners that far from the node) */
    double kappa[4] = {0.0, 0.0, 0.0, 0.0}, kv[4] = {0.0, 0.0, 0.0, 0.0};
    for (int k = 0; k < n; k++) {
        const rs_mtri *rp = m->rec + ids[k];
        for (int jj = 0; jj < 3; jj++) {
            const int a = rp->v[jj], b = rp->v[(jj + 1) % 3];
            const double sl =
                rp->kind[jj] == RS_EDGE_FLAT || rp->kind[jj] == RS_EDGE_BOUNDARY
                    ? 0.0
                    : fold_slope(m, rp->edge[jj]);
            for (int j = 0; j < nl; j++)
                if (vid[j] == a || vid[j] == b)
                    kv[j] = fmax(kv[j], sl);
        }
    }
    for (int j = 0; j < nl; j++) {
        const rs_mtri *rj = m->rec + L->tri[j];
        const int sj = L->slot[j];
        if (rj->kind[sj] != RS_EDGE_FLAT && rj->kind[sj] != RS_EDGE_BOUNDARY)
            kappa[j] = fold_slope(m, rj->edge[sj]);
        /* line j joins corners j and j + 1 */
        kappa[j] = fmax(kappa[j], kfac * fmax(kv[j], kv[(j + 1) % nl]));
        /* stored as a float, rounded up: the pieces are made of what the test reads */
        float kf = (float)kappa[j];
        if ((double)kf < kappa[j])
            kf = nextafterf(kf, INFINITY);
        kappa[j] = kf;
    }
    const double kmax = fmax(fmax(kappa[0], kappa[1]), fmax(kappa[2], kappa[3]));
    double hmax = fmin(4.0 * rin, lmax);
    if (kmax > 0.0)
        hmax = fmin(hmax, 0.5 * rin / kmax);
    const double eps = fmax(1e-6 * (lmax + hmax), 1e3 * delta);
    if (n < 0 || !(hmax > 1e3 * delta) || !(eps < 0.25 * rin)) {
        free(ids);
        return 0;
    }
    /* the plane's frame and the two pieces, grown by g = 4 delta */
    const double O[3] = {r->a0[0], r->a0[1], r->a0[2]};
    const double *B = m->xyz + 3 * r->v[1];
    double e1[3] = {B[0] - O[0], B[1] - O[1], B[2] - O[2]}, e2[3];
    const double l1 = rs_norm3(e1);
    for (int d = 0; d < 3; d++)
        e1[d] /= l1;
    rs_cross3(r->n, e1, e2);
    const double hb = eps - g, ht = hmax + g;
    double sb[4], st[4];
    for (int j = 0; j < nl; j++) {
        sb[j] = eps - g + kappa[j] * hb;
        st[j] = eps - g + kappa[j] * ht;
    }
    zpiece P[2];
    for (int d = 0; d < 3; d++) {
        lo[d] = INFINITY;
        hi[d] = -INFINITY;
    }
    for (int side = 0; side < 2; side++) {
        const double sg = side ? -1.0 : 1.0;
        P[side].nc = nl;
        if (!inset(m, L, O, e1, e2, r->n, sb, sg * hb, P[side].c) ||
            !inset(m, L, O, e1, e2, r->n, st, sg * ht, P[side].c + nl)) {
            free(ids);
            return 0;
        }
        for (int k = 0; k < 2 * nl; k++)
            for (int d = 0; d < 3; d++) {
                lo[d] = fmin(lo[d], P[side].c[k][d]);
                hi[d] = fmax(hi[d], P[side].c[k][d]);
            }
    }
    zaxes X[2];
    rs_zone_piece_axes(&P[0], r->n, &X[0]);
    rs_zone_piece_axes(&P[1], r->n, &X[1]);
    /* every triangle within hmax of the pieces: beyond, each feature lies farther */
    for (int d = 0; d < 3; d++) {
        lo[d] -= hmax + g;
        hi[d] += hmax + g;
    }
    n = near_triangles(m, lo, hi, &ids, &cap);
    if (n < 0) {
        free(ids);
        return 0;
    }
    double clear[2] = {hmax, hmax};
    for (int k = 0; k < n; k++) {
        const int tp = ids[k];
        /* t's face and edges are the zone's own, and a triangle's nodes; a quad's corners
         * off its diagonal are checked, from t too */
        const int live[2] = {clear[0] > 0.0, clear[1] > 0.0};
        if (!live[0] && !live[1])
            break;
        double nf[2];
        near_features(m, o, tp, P, X, live, delta, m->size + coord, nf);
        for (int side = 0; side < 2; side++)
            if (live[side])
                clear[side] = fmin(clear[side], nf[side] - 2.0 * delta);
    }
    free(ids);
    z->eps = eps;
    for (int j = 0; j < 4; j++)
        z->kappa[j] = (float)(j < nl ? kappa[j] : 0.0);
    z->hmax = hmax;
    z->clear[0] = fmax(clear[0], 0.0);
    z->clear[1] = fmax(clear[1], 0.0);
    return clear[0] > 0.0 || clear[1] > 0.0;
}

/* Gives the triangle across zone z's diagonal (z made on t) the same zone, seen from its
 * side, unless its zone is made or being made: the quad, its pieces and the features they
 * keep clear of are the same. */
static void mirror_zone(const rs_mesh *m, int t, const rs_mzone *z)
{
    const int nb = m->rec[t].nbr[z->jd], t2 = nb / 3, j2 = nb % 3;
    rs_mzone *z2 = m->zone + t2;
    int st = RS_ZONE_UNKNOWN;
    if (!atomic_compare_exchange_strong_explicit(
            &z2->state, &st, RS_ZONE_BUSY, memory_order_acq_rel, memory_order_acquire))
        return;
    z2->eps = z->eps;
    z2->hmax = z->hmax;
    z2->clear[0] = z->clear[0];
    z2->clear[1] = z->clear[1];
    for (int k = 0; k < 4; k++) {
        z2->kappa[k] = z->kappa[(k + 2) % 4];
        z2->slot[k] = z->slot[(k + 2) % 4];
    }
    z2->quad = 1;
    z2->t2 = t;
    z2->jd = (unsigned char)j2;
    z2->first = (unsigned char)(m->rec[t2].first >> j2 & 1u);
    atomic_store_explicit(&z2->state, RS_ZONE_READY, memory_order_release);
}

int rs_mesh_zone_make(const rs_mesh *m, int t, rs_mzone *z)
{
    zlines L;
    zown o;
    z->quad = 0;
    /* the zone of the quad across t's longest FLAT edge where no feature comes within its
     * height on either side, its nodes' folds weighed once, then twice; else the
     * triangle's, its nodes' folds weighed twice */
    const int jd = pair_slot(m, t);
    if (jd >= 0 && zone_lines(m, t, 1, jd, &L, &o)) {
        for (int f = 1; f <= 2; f++)
            if (zone_build(m, t, &L, &o, (double)f, z) && z->clear[0] >= z->hmax &&
                z->clear[1] >= z->hmax) {
                const rs_mtri *r = m->rec + t;
                z->quad = 1;
                z->t2 = r->nbr[jd] / 3;
                z->jd = (unsigned char)jd;
                z->first = (unsigned char)(r->first >> jd & 1u);
                for (int k = 0; k < 4; k++)
                    z->slot[k] = (unsigned char)L.slot[k];
                mirror_zone(m, t, z);
                return 1;
            }
    }
    zone_lines(m, t, 0, 0, &L, &o);
    return zone_build(m, t, &L, &o, 2.0, z);
}
