/* The face contacts of spheres on a revolved LINE, per run of spheres
 * (line_revolution.h): the block query's own steps (rs_analytic_closest's frame and
 * local coordinates, points_one_line's face, map_revolution's mapping and the shares of
 * 1 of rs_contacts_fold_shares), on the run alone. */
#include "rigidsurf/line_revolution.h"

#include "profile.h"

int rs_line_revolution(const rs_surface *s)
{
    if (!s || s->kind != RS_SURF_REVOLUTION || !s->ops ||
        s->ops->closest != rs_analytic_closest)
        return 0;
    const rs_pcache *pc = s->impl;
    return pc && pc->ps && pc->nseg == 1 && pc->ps[0].type == RS_LINE;
}

/* Spheres per pass of the steps (their scratch stays in the first-level cache). */
enum { RUN = 64 };

/* Spheres i0 .. i0+m-1 (m <= RUN) into the columns of c at the same indices. */
static void faces_run(const rs_pcache *pc, const double *F, int i0, int m, const double *x,
                      const double *y, const double *z, const double *radius,
                      double gap_max, double rmax, rs_contacts *c, int *face)
{
    const int feat = RS_FEATURE(RS_FEAT_FACE, 0);
    const double axis_tol = 1e-12 * pc->size;
    double u[RUN], v[RUN], cx[RUN], cy[RUN], dh[RUN], what[RUN];
    for (int j = 0; j < m; j++)
        dh[j] = gap_max + radius[i0 + j]; /* as reach_radius */
    rs_local_revolution(F, axis_tol, m, x + i0, y + i0, z + i0, u, v, cx, cy);
    rs_line_faces(&pc->ps[0], pc->sides == 2, -rmax, m, u, v, dh, c->xm[0] + i0,
                  c->xm[1] + i0, c->nrm[0] + i0, c->nrm[1] + i0, c->dist + i0, what);
    for (int j = 0; j < m; j++) {
        const int k = i0 + j;
        c->point[k] = k;
        c->feature[k] = feat;
        c->curv[0][k] = 0.0;
        c->share[k] = 1.0;
        /* a point within reach of the axis also takes the ring sectors (ring_sectors) */
        face[k] = what[j] > 0.0 && !(u[j] < dh[j]);
    }
    rs_map_revolution(F, axis_tol, i0, i0 + m, c->point, i0, cx, cy, c->xm[0], c->xm[1],
                      c->xm[2], c->nrm[0], c->nrm[1], c->nrm[2], c->t1[0], c->t1[1],
                      c->t1[2], c->t2[0], c->t2[1], c->t2[2], c->curv[1]);
}

void rs_line_revolution_faces(const rs_surface *s, const rs_pose *pose, int m,
                              const double *x, const double *y, const double *z,
                              const double *radius, double gap_max, rs_contacts *c,
                              int *face)
{
    double F[12];
    rs_analytic_frame(s, pose, F);
    double rmax = 0.0;
    for (int j = 0; j < m; j++)
        rmax = radius[j] > rmax ? radius[j] : rmax;
    for (int i0 = 0; i0 < m; i0 += RUN)
        faces_run(s->impl, F, i0, m - i0 < RUN ? m - i0 : RUN, x, y, z, radius, gap_max,
                  rmax, c, face);
    c->n = m;
    c->shared = 0;
    c->witness = 0;
}
