/* The geometry a face's clear zone is checked with (mesh_zone_sat.h): the separating-axis
 * tests between a zone's convex piece and the regions where the mesh's features own
 * points, and a lower bound of their distance. */
#include "mesh_zone_sat.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <string.h>

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* The largest and smallest of u.c over the corners of piece P. */
static void span(const zpiece *P, const double u[3], double *lo, double *hi)
{
    *lo = INFINITY;
    *hi = -INFINITY;
    for (int k = 0; k < 2 * P->nc; k++) {
        const double v = dot3(u, P->c[k]);
        *lo = v < *lo ? v : *lo; /* the corners are finite */
        *hi = v > *hi ? v : *hi;
    }
}

void rs_zone_piece_axes(const zpiece *P, const double n[3], zaxes *x)
{
    const int nc = P->nc;
    for (int k = 0; k < nc; k++)
        for (int d = 0; d < 3; d++) {
            x->ed[k][d] = P->c[(k + 1) % nc][d] - P->c[k][d];
            x->ed[nc + k][d] = P->c[nc + k][d] - P->c[k][d];
        }
    for (int d = 0; d < 3; d++)
        x->fn[0][d] = n[d];
    for (int k = 0; k < nc; k++)
        rs_cross3(x->ed[k], x->ed[nc + k], x->fn[1 + k]);
    x->nf = 1 + nc;
    x->ne = 2 * nc;
}

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
int rs_zone_planes_out(const zpiece *P, const region *R, double margin)
{
    for (int k = 0; k < R->ng; k++) { /* P beyond one of R's planes */
        const double l = R->gl[k];
        if (!(l > 0.0))
            continue;
        /* (v - c) / l > margin at every corner: at the lowest, for the expression grows
         * with v; the first corner that fails decides */
        const double *g = R->g[k];
        int c = 0;
        while (c < 2 * P->nc && (dot3(g, P->c[c]) - g[3]) / l > margin)
            c++;
        if (c == 2 * P->nc)
            return 1;
    }
    return 0;
}

int rs_zone_region_out(const zpiece *P, const zaxes *X, const region *R, double margin)
{
    return rs_zone_planes_out(P, R, margin) || rs_zone_axes_out(P, X, R, margin);
}

int rs_zone_axes_out(const zpiece *P, const zaxes *X, const region *R, double margin)
{
    double dirs[RS_ZONE_MAX_RAYS + 3][3];
    int nd = 0;
    for (int k = 0; k < R->nray; k++, nd++)
        for (int d = 0; d < 3; d++)
            dirs[nd][d] = R->ray[k][d];
    for (int i = 0; i < R->nv; i++)
        for (int j = i + 1; j < R->nv; j++, nd++)
            for (int d = 0; d < 3; d++)
                dirs[nd][d] = R->v[j][d] - R->v[i][d];
    const int nax = X->nf + X->ne * nd;
    for (int a = 0; a < nax; a++) {
        double ax[3];
        if (a < X->nf) {
            for (int d = 0; d < 3; d++)
                ax[d] = X->fn[a][d];
        } else {
            rs_cross3(X->ed[(a - X->nf) % X->ne], dirs[(a - X->nf) / X->ne], ax);
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
double rs_zone_sep_bound(const zpiece *P, const zaxes *X, const double *const *T, int nt)
{
    double ax[5 + 1 + 1 + 24][3];
    int na = 0;
    for (int k = 0; k < X->nf; k++, na++)
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
    for (int k = 0; k < 2 * P->nc; k++)
        for (int d = 0; d < 3; d++)
            cp[d] += P->c[k][d] / (2.0 * P->nc);
    for (int k = 0; k < nt; k++)
        for (int d = 0; d < 3; d++)
            ct[d] += T[k][d] / nt;
    for (int d = 0; d < 3; d++)
        ax[na][d] = ct[d] - cp[d];
    na++;
    for (int k = 0; k < X->ne; k++)
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
void rs_zone_face_region(const rs_mesh *m, int tp, region *R)
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
}

void rs_zone_face_rays(const rs_mesh *m, int tp, region *R)
{
    add_ray(R, m->rec[tp].n, 1);
}

/* The region of edge e: outside each of its faces (sides <= 0), between its ends. */
void rs_zone_edge_region(const rs_mesh *m, int e, double scale, region *R)
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
    for (int d = 0; d < 3; d++) {
        R->g[R->ng][d] = -u[d];
        R->g[R->ng + 1][d] = u[d];
    }
    R->g[R->ng][3] = -dot3(u, pa);
    R->g[R->ng + 1][3] = dot3(u, pb);
    R->ng += 2;
    plane_norms(R);
    (void)scale;
}

void rs_zone_edge_rays(const rs_mesh *m, int e, region *R)
{
    const int nf = R->ng - 2;
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
}

/* The region of node v: (p - v).(w - v) <= 0 for each neighbour w. 0 when it has more
 * neighbours than a region keeps, or they lie on one line; 2, without its rays, when its
 * planes alone keep every piece P[s] with live[s] out by margin. */
int rs_zone_vertex_region(const rs_mesh *m, int v, const zpiece P[2], const int live[2],
                          double margin, region *R)
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
    int out = 1;
    for (int s = 0; s < 2 && out; s++)
        out = !live[s] || rs_zone_planes_out(&P[s], R, margin);
    if (out)
        return 2;
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
    return R->nray < RS_ZONE_MAX_RAYS;
}
