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

static void faces_run(const rs_pcache *pc, const double *F, int m, const double *x,
                      const double *y, const double *z, const double *radius,
                      double gap_max, double rmax, rs_contacts *c, int *face)
{
    const int feat = RS_FEATURE(RS_FEAT_FACE, 0);
    const double axis_tol = 1e-12 * pc->size;
    double u[RUN], v[RUN], cx[RUN], cy[RUN], dh[RUN], what[RUN];
    for (int j = 0; j < m; j++)
        dh[j] = gap_max + radius[j]; /* as reach_radius */
    rs_local_revolution(F, axis_tol, m, x, y, z, u, v, cx, cy);
    rs_line_faces(&pc->ps[0], pc->sides == 2, -rmax, m, u, v, dh, c->xm[0], c->xm[1],
                  c->nrm[0], c->nrm[1], c->dist, what);
    for (int j = 0; j < m; j++) {
        c->point[j] = j;
        c->feature[j] = feat;
        c->curv[0][j] = 0.0;
        c->share[j] = 1.0;
        /* a point within reach of the axis also takes the ring sectors (ring_sectors) */
        face[j] = what[j] > 0.0 && !(u[j] < dh[j]);
    }
    rs_map_revolution(F, axis_tol, 0, m, c->point, 0, cx, cy, c->xm[0], c->xm[1], c->xm[2],
                      c->nrm[0], c->nrm[1], c->nrm[2], c->t1[0], c->t1[1], c->t1[2],
                      c->t2[0], c->t2[1], c->t2[2], c->curv[1]);
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
    for (int i0 = 0; i0 < m; i0 += RUN) {
        const int mr = m - i0 < RUN ? m - i0 : RUN;
        rs_contacts ci = *c; /* the columns from i0 on */
        for (int d = 0; d < 3; d++) {
            ci.xm[d] += i0, ci.nrm[d] += i0, ci.t1[d] += i0, ci.t2[d] += i0;
        }
        ci.dist += i0, ci.curv[0] += i0, ci.curv[1] += i0, ci.share += i0;
        ci.point += i0, ci.feature += i0;
        faces_run(s->impl, F, mr, x + i0, y + i0, z + i0, radius + i0, gap_max, rmax, &ci,
                  face + i0);
        for (int j = 0; j < mr; j++)
            c->point[i0 + j] = i0 + j;
    }
    c->n = m;
    c->shared = 0;
    c->witness = 0;
}
