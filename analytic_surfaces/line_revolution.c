/* The face contacts of spheres on a revolved LINE, per run of spheres
 * (line_revolution.h): the block query's own steps (rs_analytic_closest's frame, then per
 * sphere the bodies of its local coordinates, points_one_line's face and map_revolution's
 * mapping, revolution_point.h, and the shares of 1 of rs_contacts_fold_shares), on the run
 * alone and in one loop. */
#include "line_revolution.h"

#include "revolution_point.h"
#include "rs_compiler.h"

#include <string.h>

int rs_line_revolution(const rs_surface *s)
{
    if (!s || s->kind != RS_SURF_REVOLUTION || !s->ops ||
        s->ops->closest != rs_analytic_closest)
        return 0;
    const rs_pcache *pc = s->impl;
    return pc && pc->ps && pc->nseg == 1 && pc->ps[0].type == RS_LINE;
}

/* Spheres 0 .. m-1 into the columns of c at the same indices: each sphere's
 * profile-plane point, the LINE's face contact and its mapping to 3D in one loop (the
 * steps' per-point bodies, revolution_point.h), which vectorises. */
RS_INLINE void
faces_run(const rs_pcache *pc, const double *Fp, int m, const double *restrict x,
          const double *restrict y, const double *restrict z, const double *restrict radius,
          double gap_max, double rmax, double *restrict xm0, double *restrict xm1,
          double *restrict xm2, double *restrict n0, double *restrict n1, double *restrict n2,
          double *restrict a0, double *restrict a1, double *restrict a2, double *restrict b0,
          double *restrict b1, double *restrict b2, double *restrict dist, double *restrict k0,
          double *restrict k1, double *restrict share, int *restrict point,
          int *restrict feature, int *restrict face, const int all)
{
    const int feat = RS_FEATURE(RS_FEAT_FACE, 0);
    const double axis_tol = 1e-12 * pc->size;
    double F[12]; /* local copies, which the columns' stores cannot alias */
    memcpy(F, Fp, sizeof F);
    const rs_pseg s = pc->ps[0];
    const int two = pc->sides == 2;
    for (int k = 0; k < m; k++) {
        const double dh = gap_max + radius[k]; /* as reach_radius */
        double u, v, cx, cy, hx, hy, nx, ny, what;
        rs_revolution_local1(F, axis_tol, x[k], y[k], z[k], &u, &v, &cx, &cy);
        rs_line_face1(&s, two, -rmax, u, v, dh, &hx, &hy, &nx, &ny, &dist[k], &what);
        point[k] = k;
        feature[k] = feat;
        if (all) {
            k0[k] = 0.0;
            share[k] = 1.0;
        }
        /* a point within reach of the axis also takes the ring sectors (ring_sectors) */
        face[k] = what > 0.0 && !(u < dh);
        double X[3], N[3], A[3], B[3], K;
        rs_revolution_map1(F, axis_tol, cx, cy, hx, hy, nx, ny, X, N, A, B, &K);
        if (all) {
            xm0[k] = X[0], xm1[k] = X[1], xm2[k] = X[2];
            k1[k] = K;
        }
        n0[k] = N[0], n1[k] = N[1], n2[k] = N[2];
        a0[k] = A[0], a1[k] = A[1], a2[k] = A[2];
        b0[k] = B[0], b1[k] = B[1], b2[k] = B[2];
    }
}

/* faces_run with every column, or (all = 0) without the master points, curvatures and
 * shares, whose computations the compiler then leaves out. */
RS_MULTIVERSION static void faces_all(const rs_pcache *pc, const double *F, int m,
                                      const double *x, const double *y, const double *z,
                                      const double *radius, double gap_max, double rmax,
                                      rs_contacts *c, int *face)
{
    faces_run(pc, F, m, x, y, z, radius, gap_max, rmax, c->xm[0], c->xm[1], c->xm[2],
              c->nrm[0], c->nrm[1], c->nrm[2], c->t1[0], c->t1[1], c->t1[2], c->t2[0],
              c->t2[1], c->t2[2], c->dist, c->curv[0], c->curv[1], c->share, c->point,
              c->feature, face, 1);
}

RS_MULTIVERSION static void faces_frames(const rs_pcache *pc, const double *F, int m,
                                         const double *x, const double *y, const double *z,
                                         const double *radius, double gap_max, double rmax,
                                         rs_contacts *c, int *face)
{
    faces_run(pc, F, m, x, y, z, radius, gap_max, rmax, NULL, NULL, NULL, c->nrm[0],
              c->nrm[1], c->nrm[2], c->t1[0], c->t1[1], c->t1[2], c->t2[0], c->t2[1],
              c->t2[2], c->dist, NULL, NULL, NULL, c->point, c->feature, face, 0);
}

void rs_line_revolution_frame(const rs_surface *s, const rs_pose *pose, double F[12])
{
    rs_analytic_frame(s, pose, F);
}

void rs_line_revolution_faces(const rs_surface *s, const rs_pose *pose, int m,
                              const double *x, const double *y, const double *z,
                              const double *radius, double gap_max, rs_contacts *c,
                              int *face)
{
    double F[12];
    rs_analytic_frame(s, pose, F);
    rs_line_revolution_faces_in(s, F, m, x, y, z, radius, gap_max, c, face);
}

void rs_line_revolution_faces_in(const rs_surface *s, const double F[12], int m,
                                 const double *x, const double *y, const double *z,
                                 const double *radius, double gap_max, rs_contacts *c,
                                 int *face)
{
    /* the largest radius, in four lanes (which the compiler vectorises), then theirs */
    double rl[4] = {0.0, 0.0, 0.0, 0.0};
    int j = 0;
    for (; j + 4 <= m; j += 4)
        for (int l = 0; l < 4; l++)
            rl[l] = radius[j + l] > rl[l] ? radius[j + l] : rl[l];
    for (; j < m; j++)
        rl[0] = radius[j] > rl[0] ? radius[j] : rl[0];
    const double r01 = rl[1] > rl[0] ? rl[1] : rl[0], r23 = rl[3] > rl[2] ? rl[3] : rl[2];
    const double rmax = r23 > r01 ? r23 : r01;
    if (c->xm[0])
        faces_all(s->impl, F, m, x, y, z, radius, gap_max, rmax, c, face);
    else
        faces_frames(s->impl, F, m, x, y, z, radius, gap_max, rmax, c, face);
    c->n = m;
    c->shared = 0;
    c->witness = 0;
}
