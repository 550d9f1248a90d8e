/* Shares at concave folds (shares.h): the weights of the contacts of a sphere from the
 * fold lines of their tangent planes, for the kinds that do not set them, and the shares
 * from the weights (rs_contacts_patch_shares), which every kind uses. */
#include "shares.h"

#include "rigidsurf/surface.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <string.h>

/* The distance from x to the line through y0 along unit u. */
static double line_distance(const double y0[3], const double u[3], const double x[3])
{
    const double w[3] = {x[0] - y0[0], x[1] - y0[1], x[2] - y0[2]};
    const double t = rs_dot3(w, u);
    const double d[3] = {w[0] - t * u[0], w[1] - t * u[1], w[2] - t * u[2]};
    return rs_norm3(d);
}

/* Shares at concave folds (docs/conventions.md, "Shares at concave folds"), for kinds
 * that do not set them: the patch rule of the faceted kind (src/faceted/mesh_query.c,
 * hit_weights, with the cut rs_fold_cut of shares.h), with the fold lines of the contacts'
 * tangent planes as the places where a contact may begin or end while the sphere overlaps
 * it. Two contacts i, j of one sphere (radius R, centre P = x_k + d_k n_k, both in front)
 * whose feet each lie on their own side of the line L where their tangent planes meet form
 * a concave fold; a sphere at distance d_L < R from L cuts it in a chord of half-length
 * kappa = sqrt(R^2 - d_L^2). Contact k's weight is a_k^2 (a_k = sqrt(R^2 - d_k^2), the
 * radius of the disc where the sphere cuts its tangent plane) times the product over those
 * lines of min(1, s / kappa), s the distance from its foot to L; rs_contacts_patch_shares
 * makes the weights shares. */
static void group_shares(rs_contacts *c, int a, int m, const double *P, double R)
{
    double v[RS_SHARE_MAX], rad[RS_SHARE_MAX];
    int nfront = 0;
    for (int k = 0; k < m; k++) {
        const double d = c->dist[a + k];
        v[k] = 1.0;
        rad[k] = d > 0.0 && d < R ? sqrt((R - d) * (R + d)) : 0.0;
        nfront += rad[k] > 0.0;
    }
    if (nfront < 2)
        return;
    for (int i = 0; i + 1 < m; i++)
        for (int j = i + 1; j < m; j++) {
            if (!(rad[i] > 0.0 && rad[j] > 0.0))
                continue;
            const int ci = a + i, cj = a + j;
            const double ni[3] = {c->nrm[0][ci], c->nrm[1][ci], c->nrm[2][ci]};
            const double nj[3] = {c->nrm[0][cj], c->nrm[1][cj], c->nrm[2][cj]};
            const double xi[3] = {c->xm[0][ci], c->xm[1][ci], c->xm[2][ci]};
            const double dx[3] = {xi[0] - c->xm[0][cj], xi[1] - c->xm[1][cj],
                                  xi[2] - c->xm[2][cj]};
            double u[3];
            rs_cross3(ni, nj, u);
            const double sn = rs_norm3(u);
            if (!(sn > 1e-12))
                continue; /* parallel planes: no fold line */
            const double si = rs_dot3(dx, nj) / sn, sj = -rs_dot3(dx, ni) / sn;
            const double tol = 1e-12 * R;
            if (!(si > -tol && sj > -tol) || !(si + sj > 0.0))
                continue; /* not a concave fold between the feet */
            for (int d = 0; d < 3; d++)
                u[d] /= sn;
            /* the point of L nearest x_i: x_i + s_i m_i, m_i = n_i x u in i's plane */
            double mi[3];
            rs_cross3(ni, u, mi);
            const double y0[3] = {xi[0] + si * mi[0], xi[1] + si * mi[1],
                                  xi[2] + si * mi[2]};
            /* a body's centre for the pair: the midpoint of the centres of the spheres of
             * radius R on its two witness points (a sphere's own centre for a sphere) */
            double Pb[3];
            for (int d = 0; P == NULL && d < 3; d++)
                Pb[d] = 0.5 *
                        (xi[d] + c->dist[ci] * ni[d] + c->xm[d][cj] + c->dist[cj] * nj[d]);
            const double dl = line_distance(y0, u, P ? P : Pb), k2 = (R - dl) * (R + dl);
            if (!(k2 > 0.0))
                continue; /* the sphere does not reach the fold line */
            const double kappa = sqrt(k2);
            for (int k = 0; k < m; k++) {
                if (!(rad[k] > 0.0))
                    continue;
                const double x[3] = {c->xm[0][a + k], c->xm[1][a + k], c->xm[2][a + k]};
                const double sk = k == i   ? fmax(si, 0.0)
                                  : k == j ? fmax(sj, 0.0)
                                           : line_distance(y0, u, x);
                rs_fold_cut(&v[k], sk, kappa);
            }
        }
    for (int k = 0; k < m; k++)
        c->share[a + k] = fmax(v[k] * rad[k] * rad[k], 1e-300);
    rs_contacts_patch_shares(c, a, m, R);
}

/* The shares of the m contacts from a of one slave of radius R (P its centre, NULL for
 * a body's), whose shares hold 1: group_shares over at most RS_SHARE_MAX of them, the
 * list marked shared where one differs from 1. */
static void slave_shares(rs_contacts *c, int a, int m, const double *P, double R)
{
    if (m > RS_SHARE_MAX)
        m = RS_SHARE_MAX;
    if (m < 2 || !(R > 0.0))
        return;
    group_shares(c, a, m, P, R);
    for (int k = a; k < a + m; k++)
        c->shared |= c->share[k] != 1.0;
}

void rs_contacts_fold_shares(const rs_query *q, rs_contacts *c, int k0)
{
    const int n = c->n;
    const int *pt = c->point;
    double *sh = c->share; /* group_shares writes them through c too: no restrict */
    int multi = 0;
    for (int k = k0; k < n; k++)
        sh[k] = 1.0;
    for (int k = k0 + 1; k < n; k++)
        multi |= pt[k] == pt[k - 1];
    if (!multi || !q->slave.radius)
        return;
    for (int a = k0; a < n;) {
        int b = a + 1;
        while (b < n && pt[b] == pt[a])
            b++;
        const int i = pt[a];
        const double R = q->slave.radius[i];
        const double P[3] = {q->slave.x[i], q->slave.y[i], q->slave.z[i]};
        slave_shares(c, a, b - a, P, R);
        a = b;
    }
}

void rs_contacts_body_shares(rs_contacts *c, int a, int m, double R)
{
    for (int k = a; k < a + m; k++)
        c->share[k] = 1.0;
    slave_shares(c, a, m, NULL, R);
}

void rs_contacts_patch_shares(rs_contacts *c, int a, int m, double R)
{
    if (m > RS_SHARE_MAX)
        m = RS_SHARE_MAX;
    const double *v = c->share + a; /* written below through c: no restrict */
    double rad[RS_SHARE_MAX], w[RS_SHARE_MAX];
    for (int i = 0; i < m; i++) {
        const double d = c->dist[a + i];
        rad[i] = d > 0.0 && d < R ? sqrt((R - d) * (R + d)) : 0.0;
    }
    for (int i = 0; i < m; i++) {
        w[i] = 1.0;
        if (!(rad[i] > 0.0))
            continue;
        double den = v[i];
        for (int j = 0; j < m; j++) {
            if (j == i || !(rad[j] > 0.0))
                continue;
            const double as = rad[i] + rad[j];
            const double dx[3] = {c->xm[0][a + i] - c->xm[0][a + j],
                                  c->xm[1][a + i] - c->xm[1][a + j],
                                  c->xm[2][a + i] - c->xm[2][a + j]};
            const double D2 = rs_dot3(dx, dx);
            double cp = 1.0;
            if (D2 > as * as) {
                const double q2 = as * as / D2, q4 = q2 * q2, q8 = q4 * q4;
                cp = q8 * q8;
            }
            den += cp * v[j];
        }
        w[i] = v[i] / den;
    }
    memcpy(c->share + a, w, (size_t)m * sizeof *w);
}
