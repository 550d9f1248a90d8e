/* The effective mass of a convex body's contact points (effective_mass.h;
 * docs/conventions.md, "Effective mass of a body's contacts"). */
#include "effective_mass.h"

#include "rigidsurf/convex.h"
#include "rigidsurf/vec.h"

#include <math.h>

/* The inverse inertia tensor of body b in the world, R A diag(1/I) A^T R^T (row-major); a
 * moment that is not > 0 (a body that keeps the spin it is given) adds nothing. */
static void world_inverse_inertia(const rs_body *b, double J[9])
{
    double R[9], RA[9];
    rs_quat_matrix(b->q, R);
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            RA[3 * r + c] = R[3 * r] * b->axes[c] + R[3 * r + 1] * b->axes[3 + c] +
                            R[3 * r + 2] * b->axes[6 + c];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            double s = 0.0;
            for (int k = 0; k < 3; k++)
                if (b->inertia[k] > 0.0)
                    s += RA[3 * r + k] * RA[3 * c + k] / b->inertia[k];
            J[3 * r + c] = s;
        }
}

/* Entry e's normal n and the moment arm's cross product u = (x_cp - x) x n of particle
 * i; nDir 2 works in the plane (z parts zero). */
static void normal_and_arm(const rs_track_out *o, const rs_block_particles *p, int i, int e,
                           double n[3], double u[3])
{
    const int nd = o->ndir;
    const double *xc = o->coordslv + (size_t)e * nd,
                 *a = o->alocaldir + (size_t)e * nd * nd;
    const double r[3] = {xc[0] - p->x[i], xc[1] - p->y[i], nd == 3 ? xc[2] - p->z[i] : 0.0};
    n[0] = a[0], n[1] = a[1], n[2] = nd == 3 ? a[2] : 0.0;
    rs_cross3(r, n, u);
}

/* Does entry e push (a live contact that overlaps)? */
static int acting(const rs_track_out *o, int e)
{
    const double d = o->rdisp[(size_t)e * o->ndir];
    return d > 0.0 && d < 0.5 * RS_MAXVAL;
}

/* The entries [e0, e1) of body particle i. */
static void body_masses(rs_contact_block *cb, const rs_track_out *o,
                        const rs_block_particles *p, int i, int e0, int e1)
{
    const double m = p->mass[i];
    if (!(m > 0.0))
        return;
    double J[9], N[3] = {0.0, 0.0, 0.0}, U[3] = {0.0, 0.0, 0.0};
    world_inverse_inertia(&p->body[i], J);
    int nact = 0;
    for (int e = e0; e < e1; e++) {
        if (!acting(o, e))
            continue;
        double n[3], u[3];
        normal_and_arm(o, p, i, e, n, u);
        const double w = o->share ? o->share[e] : 1.0;
        for (int k = 0; k < 3; k++) {
            N[k] += w * n[k];
            U[k] += w * u[k];
        }
        nact++;
    }
    double JU[3];
    rs_matvec3(J, U, JU);
    for (int e = e0; e < e1; e++) {
        double n[3], u[3], Ju[3];
        normal_and_arm(o, p, i, e, n, u);
        rs_matvec3(J, u, Ju);
        const double alone = 1.0 / m + rs_dot3(u, Ju); /* W_ee */
        double s = alone;
        if (acting(o, e)) {
            /* the row sum over the points that push: n.N / m + u.J U, at least the
             * point's own share of its value alone */
            const double w = o->share ? o->share[e] : 1.0;
            const double least = w * alone / nact;
            s = rs_dot3(n, N) / m + rs_dot3(u, JU);
            if (!(s > least))
                s = least;
            if (!(s > 0.0))
                s = alone;
        }
        cb->mass[e] = 1.0 / s;
    }
}

void rs_cblock_body_masses(rs_contact_block *cb, const rs_track_out *o,
                           const rs_block_particles *p)
{
    if (!p->body)
        return;
    /* the tracker lists a particle's entries together (its contacts, then its leaving
     * slots) */
    for (int e0 = 0, e1; e0 < o->n; e0 = e1) {
        const int i = o->point[e0];
        for (e1 = e0 + 1; e1 < o->n && o->point[e1] == i;)
            e1++;
        if (i >= 0 && p->body[i].shape)
            body_masses(cb, o, p, i, e0, e1);
    }
}
