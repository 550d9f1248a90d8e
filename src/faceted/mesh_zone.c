/* The clear zone of a triangle's face (mesh_zone.h): the points near face t that no other
 * feature of the mesh owns within a distance, by the query's own tests (point_hits in
 * mesh_query.c), so that the query can give a point held on t its contact from t's
 * record alone.
 *
 * The zone is two convex pieces, in front of t's plane (eps <= h <= hmax) and behind it:
 * at height h, the inset triangle whose side of each edge slot j is at least
 * eps + kappa_j |h| (kappa_j > 0 across a fold, so that the neighbour's face, whose
 * prism leans over t there, stays out; the base off the plane keeps out the face beyond
 * a right-angled convex edge). It is made once per face, and checked against
 * every feature within hmax of it:
 *  - t's own edges own no point of it: each needs the point outside t across it (a side
 *    <= 0), where the zone keeps every side >= eps > 0, the very numbers the query
 *    computes (side_of and tri_bound evaluate one expression of one record);
 *  - t's own vertices own none: a point whose foot q lies in t, at least eps from its
 *    edges, has (q - v).(w - v) >= |q - v|^2 >= eps^2 for one of the two other nodes w of
 *    t (q - v = s1 (w1 - v) + s2 (w2 - v) with s1, s2 >= 0 and s1 + s2 <= 1), far above
 *    the product's rounding (eps >= 1e-6 of the triangle's size and height);
 *  - any other face, edge or vertex is out of a piece when one of the linear tests of
 *    its region (a side, a position along an edge, a product at a vertex) fails at each
 *    of the piece's six corners by more than the rounding, for the test is linear in the
 *    point and fails over the whole piece; else the piece's clear distance is at most a
 *    lower bound of the distance between the piece and the feature's triangle (the
 *    largest gap between their projections on separating axes).
 * The pieces are checked grown by 4 delta on each side (delta = 1e-9 of the mesh's size
 * and coordinates), so that the query's rounding of h and of the sides stays inside
 * them. */
#include "mesh_zone.h"
#include "mesh_regions.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Most triangles a zone is checked against: a face crowded by more has none. */
#define RS_ZONE_MAX_NEAR 1024

/* One piece: corners 0 .. 2 at its base (the plane's side), 3 .. 5 at its top, corner k
 * and 3 + k near node k of the triangle. */
typedef struct zpiece {
    double c[6][3];
} zpiece;

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* The inset triangle of t at height z (times the normal n) whose side of slot j is s[j]:
 * its corners into c[0 .. 2] (corner k between slots k - 1 and k, near node k). 0 when
 * the inset leaves no triangle. O, e1, e2: t's plane frame. */
static int inset(const rs_mtri *r, const double O[3], const double e1[3],
                 const double e2[3], const double s[3], double z, double c[3][3])
{
    double g[3][2], rhs[3];
    for (int j = 0; j < 3; j++) {
        g[j][0] = dot3(r->e[j], e1);
        g[j][1] = dot3(r->e[j], e2);
        rhs[j] = s[j] - (dot3(r->e[j], O) - r->e[j][3]);
    }
    double q[3][2];
    for (int k = 0; k < 3; k++) {
        const int a = (k + 2) % 3, b = k, l = (k + 1) % 3;
        const double det = g[a][0] * g[b][1] - g[a][1] * g[b][0];
        if (!(fabs(det) > 1e-12))
            return 0;
        q[k][0] = (rhs[a] * g[b][1] - rhs[b] * g[a][1]) / det;
        q[k][1] = (g[a][0] * rhs[b] - g[b][0] * rhs[a]) / det;
        /* inside the third slot's inset line: else the inset triangle is inverted */
        if (!(g[l][0] * q[k][0] + g[l][1] * q[k][1] > rhs[l]))
            return 0;
    }
    for (int k = 0; k < 3; k++)
        for (int d = 0; d < 3; d++)
            c[k][d] = O[d] + q[k][0] * e1[d] + q[k][1] * e2[d] + z * r->n[d];
    return 1;
}

/* The largest and smallest of u.c over the corners of piece P. */
static void span(const zpiece *P, const double u[3], double *lo, double *hi)
{
    *lo = INFINITY;
    *hi = -INFINITY;
    for (int k = 0; k < 6; k++) {
        const double v = dot3(u, P->c[k]);
        *lo = fmin(*lo, v);
        *hi = fmax(*hi, v);
    }
}

/* A piece's face normals (its base and top, its three sides) and edge directions (three
 * along its base, three from base to top), the axes the separating-axis tests take. */
typedef struct zaxes {
    double fn[4][3], ed[6][3];
} zaxes;

static void piece_axes(const zpiece *P, const double n[3], zaxes *x)
{
    for (int k = 0; k < 3; k++)
        for (int d = 0; d < 3; d++) {
            x->ed[k][d] = P->c[(k + 1) % 3][d] - P->c[k][d];
            x->ed[3 + k][d] = P->c[3 + k][d] - P->c[k][d];
        }
    for (int d = 0; d < 3; d++)
        x->fn[0][d] = n[d];
    for (int k = 0; k < 3; k++)
        rs_cross3(x->ed[k], x->ed[3 + k], x->fn[1 + k]);
}

/* The most rays and planes a region keeps: a node of more neighbours is not tested (its
 * distance bounds the zone instead). */
#define RS_ZONE_MAX_W 24
#define RS_ZONE_MAX_RAYS 64

/* A convex region where a feature owns points, by the query's tests, closed: the hull of
 * its points (a node, an edge's two nodes, a triangle's three) plus the cone of its rays,
 * bounded by the half-spaces g.x <= c (g[k][0 .. 2], c = g[k][3]). */
typedef struct region {
    double v[3][3];
    int nv;
    double ray[RS_ZONE_MAX_RAYS][3];
    int nray;
    double g[RS_ZONE_MAX_W + 2][4];
    double gl[RS_ZONE_MAX_W + 2]; /* |g[k][0 .. 2]| */
    int ng;
} region;

/* The lengths of R's plane normals, once its planes are set. */
static void plane_norms(region *R)
{
    for (int k = 0; k < R->ng; k++)
        R->gl[k] = rs_norm3(R->g[k]);
}

/* Adds the ray of unit direction u (and -u with both) where every plane's normal has
 * g.u <= tol |g| (the cone holds it). */
static void add_ray(region *R, const double u[3], int both)
{
    for (int s = 0; s < (both ? 2 : 1); s++) {
        const double sg = s ? -1.0 : 1.0;
        int in = 1;
        for (int k = 0; k < R->ng && in; k++)
            in = sg * dot3(R->g[k], u) <= 1e-12 * R->gl[k];
        if (in && R->nray < RS_ZONE_MAX_RAYS) {
            for (int d = 0; d < 3; d++)
                R->ray[R->nray][d] = sg * u[d];
            R->nray++;
        }
    }
}

/* Unit u along a, 0 when a is too short against scale. */
static int unit_of(const double a[3], double scale, double u[3])
{
    const double l = rs_norm3(a);
    if (!(l > 1e-9 * scale))
        return 0;
    for (int d = 0; d < 3; d++)
        u[d] = a[d] / l;
    return 1;
}

/* Is region R apart from piece P by more than margin? Some plane separates them: a plane
 * of R, a face of P, or one along an edge of each (the separating-axis test of two convex
 * polyhedra, R's edges its rays and its points' edges). Along an axis a, R reaches
 * max a.v over its points, or without bound where a ray has a.r > 0. */
static int region_out(const zpiece *P, const zaxes *X, const region *R, double margin)
{
    for (int k = 0; k < R->ng; k++) { /* P beyond one of R's planes */
        const double l = R->gl[k];
        if (!(l > 0.0))
            continue;
        double lo, hi;
        span(P, R->g[k], &lo, &hi);
        if ((lo - R->g[k][3]) / l > margin)
            return 1;
    }
    double dirs[RS_ZONE_MAX_RAYS + 3][3];
    int nd = 0;
    for (int k = 0; k < R->nray; k++, nd++)
        for (int d = 0; d < 3; d++)
            dirs[nd][d] = R->ray[k][d];
    for (int i = 0; i < R->nv; i++)
        for (int j = i + 1; j < R->nv; j++, nd++)
            for (int d = 0; d < 3; d++)
                dirs[nd][d] = R->v[j][d] - R->v[i][d];
    const int nax = 4 + 6 * nd;
    for (int a = 0; a < nax; a++) {
        double ax[3];
        if (a < 4) {
            for (int d = 0; d < 3; d++)
                ax[d] = X->fn[a][d];
        } else {
            rs_cross3(X->ed[(a - 4) % 6], dirs[(a - 4) / 6], ax);
        }
        const double l = rs_norm3(ax);
        if (!(l > 0.0))
            continue;
        for (int d = 0; d < 3; d++)
            ax[d] /= l;
        double plo, phi;
        span(P, ax, &plo, &phi);
        for (int s = 0; s < 2; s++) {
            const double sg = s ? -1.0 : 1.0;
            int bounded = 1;
            for (int k = 0; k < R->nray && bounded; k++)
                bounded = sg * dot3(ax, R->ray[k]) <= 1e-12;
            if (!bounded)
                continue;
            double rmax = -INFINITY;
            for (int i = 0; i < R->nv; i++)
                rmax = fmax(rmax, sg * dot3(ax, R->v[i]));
            if ((s ? -phi : plo) - rmax > margin)
                return 1;
        }
    }
    return 0;
}

/* A lower bound of the distance between piece P and the hull of points T[0 .. nt): the
 * largest gap between their projections on the axes of the separating-axis test (the
 * piece's faces, the points' plane, the line of their centres and the cross products of
 * their edges). */
static double sep_bound(const zpiece *P, const zaxes *X, const double *const *T, int nt)
{
    double ax[4 + 1 + 1 + 18][3];
    int na = 0;
    for (int k = 0; k < 4; k++, na++)
        for (int d = 0; d < 3; d++)
            ax[na][d] = X->fn[k][d];
    double te[3][3];
    int ne = 0;
    for (int i = 0; i < nt; i++)
        for (int j = i + 1; j < nt; j++, ne++)
            for (int d = 0; d < 3; d++)
                te[ne][d] = T[j][d] - T[i][d];
    if (nt == 3)
        rs_cross3(te[0], te[1], ax[na++]);
    double cp[3] = {0, 0, 0}, ct[3] = {0, 0, 0};
    for (int k = 0; k < 6; k++)
        for (int d = 0; d < 3; d++)
            cp[d] += P->c[k][d] / 6.0;
    for (int k = 0; k < nt; k++)
        for (int d = 0; d < 3; d++)
            ct[d] += T[k][d] / nt;
    for (int d = 0; d < 3; d++)
        ax[na][d] = ct[d] - cp[d];
    na++;
    for (int k = 0; k < 6; k++)
        for (int l = 0; l < ne; l++, na++)
            rs_cross3(X->ed[k], te[l], ax[na]);
    double best = 0.0;
    for (int a = 0; a < na; a++) {
        const double len = rs_norm3(ax[a]);
        if (!(len > 0.0))
            continue;
        const double u[3] = {ax[a][0] / len, ax[a][1] / len, ax[a][2] / len};
        double plo, phi, tlo = INFINITY, thi = -INFINITY;
        span(P, u, &plo, &phi);
        for (int k = 0; k < nt; k++) {
            const double v = dot3(u, T[k]);
            tlo = fmin(tlo, v);
            thi = fmax(thi, v);
        }
        best = fmax(best, fmax(plo - thi, tlo - phi));
    }
    return best;
}

/* The region of the face of triangle tp: its prism, sides >= 0. */
static void face_region(const rs_mesh *m, int tp, region *R)
{
    const rs_mtri *r = m->rec + tp;
    R->nv = 3;
    R->nray = 0;
    R->ng = 3;
    for (int j = 0; j < 3; j++) {
        for (int d = 0; d < 3; d++) {
            R->v[j][d] = m->xyz[3 * r->v[j] + d];
            R->g[j][d] = -r->e[j][d];
        }
        R->g[j][3] = -r->e[j][3];
    }
    plane_norms(R);
    add_ray(R, r->n, 1);
}

/* The region of edge e: outside each of its faces (sides <= 0), between its ends. */
static void edge_region(const rs_mesh *m, int e, double scale, region *R)
{
    const int a = m->edge_v[2 * e], b = m->edge_v[2 * e + 1];
    const double *pa = m->xyz + 3 * a, *pb = m->xyz + 3 * b;
    const double u[3] = {pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]};
    R->nv = 2;
    R->nray = 0;
    R->ng = 0;
    for (int d = 0; d < 3; d++) {
        R->v[0][d] = pa[d];
        R->v[1][d] = pb[d];
    }
    for (int f = m->edge_f0[e]; f < m->edge_f0[e + 1] && R->ng < RS_ZONE_MAX_W; f++) {
        const int t = m->edge_f[f];
        int j = 0;
        while (m->tedge[3 * t + j] != e)
            j++;
        for (int d = 0; d < 4; d++)
            R->g[R->ng][d] = m->rec[t].e[j][d];
        R->ng++;
    }
    const int nf = R->ng;
    for (int d = 0; d < 3; d++) {
        R->g[R->ng][d] = -u[d];
        R->g[R->ng + 1][d] = u[d];
    }
    R->g[R->ng][3] = -dot3(u, pa);
    R->g[R->ng + 1][3] = dot3(u, pb);
    R->ng += 2;
    plane_norms(R);
    /* the cone across the edge: the faces' normals, where the others' sides allow, and
     * outward from a lone face */
    for (int f = m->edge_f0[e]; f < m->edge_f0[e + 1]; f++) {
        const double *nn = m->rec[m->edge_f[f]].n;
        add_ray(R, nn, 1);
        if (nf == 1) {
            double o[3] = {-R->g[0][0], -R->g[0][1], -R->g[0][2]};
            if (unit_of(o, 1.0, o))
                add_ray(R, o, 0);
        }
    }
    (void)scale;
}

/* The region of node v: (p - v).(w - v) <= 0 for each neighbour w. 0 when it has more
 * neighbours than a region keeps, or they lie on one line. */
static int vertex_region(const rs_mesh *m, int v, double scale, region *R)
{
    const double *pv = m->xyz + 3 * v;
    const int nw = m->vert_e0[v + 1] - m->vert_e0[v];
    if (nw > RS_ZONE_MAX_W)
        return 0;
    R->nv = 1;
    R->nray = 0;
    R->ng = nw;
    for (int d = 0; d < 3; d++)
        R->v[0][d] = pv[d];
    for (int k = 0; k < nw; k++) {
        const double *pw = m->xyz + 3 * m->vert_w[m->vert_e0[v] + k];
        for (int d = 0; d < 3; d++)
            R->g[k][d] = pw[d] - pv[d];
        R->g[k][3] = dot3(R->g[k], pv);
    }
    plane_norms(R);
    /* extreme rays: along the meeting line of two planes; where the planes all hold one
     * line l, that line both ways and, within the plane normal to it, the lines normal
     * to l and to a plane's normal */
    double l[3] = {0, 0, 0}, lbest = 0.0;
    int rank3 = 0;
    for (int i = 0; i < nw; i++)
        for (int j = i + 1; j < nw; j++) {
            double c[3], u[3];
            rs_cross3(R->g[i], R->g[j], c);
            if (!unit_of(c, R->gl[i] * R->gl[j], u))
                continue;
            add_ray(R, u, 1);
            const double lc = rs_norm3(c) / (R->gl[i] * R->gl[j]);
            if (lc > lbest) {
                lbest = lc;
                memcpy(l, u, sizeof l);
            }
        }
    if (!(lbest > 0.0))
        return 0; /* the neighbours on one line */
    for (int k = 0; k < nw && !rank3; k++)
        rank3 = fabs(dot3(l, R->g[k])) > 1e-9 * R->gl[k];
    if (!rank3)
        for (int k = 0; k < nw; k++) {
            double c[3], u[3];
            rs_cross3(l, R->g[k], c);
            if (unit_of(c, R->gl[k], u))
                add_ray(R, u, 1);
        }
    (void)scale;
    return R->nray < RS_ZONE_MAX_RAYS;
}

/* How far the features of triangle tp other than those of t keep from each piece P[s]
 * with live[s], into clear[s]: INFINITY when each owns no point of it, else the least of
 * lower bounds of the distances of those that may. Each feature's region is made once for
 * both pieces. Each edge and vertex is taken from its first triangle alone (which touches
 * it, so lies within the search when it does). */
static void near_features(const rs_mesh *m, int t, int tp, const zpiece P[2],
                          const zaxes X[2], const int live[2], double delta, double scale,
                          double clear[2])
{
    const rs_mtri *r = m->rec + tp, *rt = m->rec + t;
    const double margin = 2.0 * delta;
    clear[0] = clear[1] = INFINITY;
    region R;
    face_region(m, tp, &R);
    for (int s = 0; s < 2; s++)
        if (live[s] && !region_out(&P[s], &X[s], &R, margin)) {
            const double *T[3] = {R.v[0], R.v[1], R.v[2]};
            clear[s] = fmin(clear[s], sep_bound(&P[s], &X[s], T, 3));
        }
    for (int j = 0; j < 3; j++) {
        if (!(r->first >> j & 1u))
            continue;
        const int e = r->edge[j];
        if (e == rt->edge[0] || e == rt->edge[1] || e == rt->edge[2])
            continue; /* t's own edge: t's side keeps it out */
        edge_region(m, e, scale, &R);
        for (int s = 0; s < 2; s++)
            if (live[s] && !region_out(&P[s], &X[s], &R, margin)) {
                const double *T[2] = {R.v[0], R.v[1]};
                clear[s] = fmin(clear[s], sep_bound(&P[s], &X[s], T, 2));
            }
    }
    for (int j = 0; j < 3; j++) {
        if (!(r->first >> (3 + j) & 1u))
            continue;
        const int v = r->v[j];
        if (v == rt->v[0] || v == rt->v[1] || v == rt->v[2])
            continue; /* t's own node: eps keeps it out */
        const int ok = vertex_region(m, v, scale, &R);
        for (int s = 0; s < 2; s++)
            if (live[s] && (!ok || !region_out(&P[s], &X[s], &R, margin))) {
                const double *T[1] = {m->xyz + 3 * v};
                clear[s] = fmin(clear[s], sep_bound(&P[s], &X[s], T, 1));
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

int rs_mesh_zone_make(const rs_mesh *m, int t, rs_mzone *z)
{
    const rs_mtri *r = m->rec + t;
    const double *A = m->xyz + 3 * r->v[0], *B = m->xyz + 3 * r->v[1],
                 *C = m->xyz + 3 * r->v[2];
    double coord = 0.0;
    for (int d = 0; d < 3; d++)
        coord = fmax(coord, fmax(fabs(m->lo[d]), fabs(m->hi[d])));
    const double delta = 1e-9 * (m->size + coord);
    /* the triangle's size and inradius */
    const double ab[3] = {B[0] - A[0], B[1] - A[1], B[2] - A[2]};
    const double ac[3] = {C[0] - A[0], C[1] - A[1], C[2] - A[2]};
    const double bc[3] = {C[0] - B[0], C[1] - B[1], C[2] - B[2]};
    double cr[3];
    rs_cross3(ab, ac, cr);
    const double lab = rs_norm3(ab), lac = rs_norm3(ac), lbc = rs_norm3(bc);
    const double lmax = fmax(lab, fmax(lac, lbc)), rin = rs_norm3(cr) / (lab + lac + lbc);
    /* The triangles that touch t, for the folds at its nodes. */
    int cap = 64, *ids = malloc((size_t)cap * sizeof *ids);
    if (!ids)
        return 0;
    const double g = 4.0 * delta;
    double lo[3], hi[3];
    for (int d = 0; d < 3; d++) {
        lo[d] = fmin(A[d], fmin(B[d], C[d])) - g;
        hi[d] = fmax(A[d], fmax(B[d], C[d])) + g;
    }
    int n = near_triangles(m, lo, hi, &ids, &cap);
    /* kappa: how each slot's inset grows with |h|, so that the faces beyond the folds of
     * t's edges and nodes, whose prisms lean over t by their slope times h, stay out: a
     * slot's own fold's slope, and twice the steepest fold at either of its nodes (which
     * keeps t's corners that far from the node) */
    double kappa[3] = {0.0, 0.0, 0.0}, kv[3] = {0.0, 0.0, 0.0};
    for (int k = 0; k < n; k++) {
        const rs_mtri *rp = m->rec + ids[k];
        for (int jj = 0; jj < 3; jj++) {
            const int a = rp->v[jj], b = rp->v[(jj + 1) % 3];
            const double sl =
                rp->kind[jj] == RS_EDGE_FLAT || rp->kind[jj] == RS_EDGE_BOUNDARY
                    ? 0.0
                    : fold_slope(m, rp->edge[jj]);
            for (int j = 0; j < 3; j++)
                if (r->v[j] == a || r->v[j] == b)
                    kv[j] = fmax(kv[j], sl);
        }
    }
    for (int j = 0; j < 3; j++) {
        if (r->kind[j] != RS_EDGE_FLAT && r->kind[j] != RS_EDGE_BOUNDARY)
            kappa[j] = fold_slope(m, r->edge[j]);
        kappa[j] = fmax(kappa[j], 2.0 * fmax(kv[j], kv[(j + 1) % 3]));
    }
    const double kmax = fmax(kappa[0], fmax(kappa[1], kappa[2]));
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
    double e1[3] = {ab[0] / lab, ab[1] / lab, ab[2] / lab}, e2[3];
    rs_cross3(r->n, e1, e2);
    const double hb = eps - g, ht = hmax + g;
    double sb[3], st[3];
    for (int j = 0; j < 3; j++) {
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
        if (!inset(r, O, e1, e2, sb, sg * hb, P[side].c) ||
            !inset(r, O, e1, e2, st, sg * ht, P[side].c + 3)) {
            free(ids);
            return 0;
        }
        for (int k = 0; k < 6; k++)
            for (int d = 0; d < 3; d++) {
                lo[d] = fmin(lo[d], P[side].c[k][d]);
                hi[d] = fmax(hi[d], P[side].c[k][d]);
            }
    }
    zaxes X[2];
    piece_axes(&P[0], r->n, &X[0]);
    piece_axes(&P[1], r->n, &X[1]);
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
        if (tp == t)
            continue;
        const int live[2] = {clear[0] > 0.0, clear[1] > 0.0};
        if (!live[0] && !live[1])
            break;
        double nf[2];
        near_features(m, t, tp, P, X, live, delta, m->size + coord, nf);
        for (int side = 0; side < 2; side++)
            if (live[side])
                clear[side] = fmin(clear[side], nf[side] - 2.0 * delta);
    }
    free(ids);
    z->eps = eps;
    for (int j = 0; j < 3; j++)
        z->kappa[j] = kappa[j];
    z->hmax = hmax;
    z->clear[0] = fmax(clear[0], 0.0);
    z->clear[1] = fmax(clear[1], 0.0);
    return clear[0] > 0.0 || clear[1] > 0.0;
}
