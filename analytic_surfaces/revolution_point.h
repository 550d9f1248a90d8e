/* One point of the analytic query's steps on a REVOLUTION (query.c, closest.c): its
 * profile-plane coordinates, the face contact of one LINE and the mapping back to 3D, as
 * inline bodies, so that the steps' loops over a run of points and the fused loop of
 * rs_line_revolution_faces (line_revolution.c) compute each point with the same
 * operations. Internal to analytic_surfaces. */
#ifndef RIGIDSURF_REVOLUTION_POINT_H
#define RIGIDSURF_REVOLUTION_POINT_H

#include "profile.h"
#include "rs_compiler.h"

#include <math.h>

/* The frame F = {A, EX, EY, EZ} of rs_analytic_frame: its offsets. */
enum { F_A = 0, F_X = 3, F_Y = 6, F_Z = 9 };

/* The profile-plane point (u, v) = (r, z) of (x, y, z) and its radial direction (cx, cy)
 * in the local x-y plane; on the axis (r <= axis_tol) the direction falls back to the
 * surface's fixed ex, (1, 0), never NaN. */
RS_INLINE void rs_revolution_local1(const double *F, double axis_tol, double x, double y,
                                    double z, double *u, double *v, double *cx, double *cy)
{
    const double wx = x - F[F_A], wy = y - F[F_A + 1], wz = z - F[F_A + 2];
    const double lx = wx * F[F_X] + wy * F[F_X + 1] + wz * F[F_X + 2];
    const double ly = wx * F[F_Y] + wy * F[F_Y + 1] + wz * F[F_Y + 2];
    const double lz = wx * F[F_Z] + wy * F[F_Z + 1] + wz * F[F_Z + 2];
    const double r = sqrt(lx * lx + ly * ly);
    /* the selects come before the divisions, which keeps a loop branch-free */
    const int off = isgreater(r, axis_tol);
    const double d = off ? r : 1.0;
    *u = r;
    *v = lz;
    *cx = (off ? lx : 1.0) / d;
    *cy = (off ? ly : 0.0) / d;
}

/* The face contact of the LINE segment s (a local copy) for the profile-plane point (px,
 * py) within [dlo, dhi]: master point (fx0, fx1), normal (fn0, fn1), distance fd, and
 * what = 1 a contact, 0 owned but out of [dlo, dhi], -1 not owned. two: SIDES=2. */
RS_INLINE void rs_line_face1(const rs_pseg *s, int two, double dlo, double px, double py,
                             double dhi, double *fx0, double *fx1, double *fn0, double *fn1,
                             double *fd, double *what)
{
    const double wx = px - s->o[0], wy = py - s->o[1];
    const double sd = wx * s->nl[0] + wy * s->nl[1];
    int in_start, in_end;
    rs_pseg_owns(s, px, py, &in_start, &in_end);
    const int own = in_start & in_end & (two | (sd >= 0.0));
    const int flip = two & (sd < 0.0);
    const double dist = flip ? -sd : sd;
    double tau = (wx * s->e[0] + wy * s->e[1]) * s->inv_len2;
    tau = tau < 0.0 ? 0.0 : tau > 1.0 ? 1.0 : tau;
    *fx0 = s->o[0] + tau * s->e[0];
    *fx1 = s->o[1] + tau * s->e[1];
    *fn0 = flip ? -s->nl[0] : s->nl[0];
    *fn1 = flip ? -s->nl[1] : s->nl[1];
    *fd = dist;
    *what = own ? (double)((dist >= dlo) & (dist <= dhi)) : -1.0;
}

/* A REVOLUTION contact from profile-plane form (master point (hx, hy) = (r, z), normal
 * (nx, ny) = (n_r, n_z)), with (cx, cy) its point's radial direction in the local x-y
 * plane, to 3D: e_r = cx EX + cy EY, master point x, n = n_r e_r + n_z EZ, d1 = n_z e_r -
 * n_r EZ (travel), d2 = n x d1 = hoop = EZ x e_r = cx EY - cy EX; hoop curvature k = n_r /
 * r at the contact point, 0 on the axis. */
RS_INLINE void rs_revolution_map1(const double *F, double axis_tol, double cx, double cy,
                                  double hx, double hy, double nx, double ny, double x[3],
                                  double n[3], double a[3], double b[3], double *k)
{
    const double er0 = cx * F[F_X] + cy * F[F_Y], er1 = cx * F[F_X + 1] + cy * F[F_Y + 1],
                 er2 = cx * F[F_X + 2] + cy * F[F_Y + 2];
    x[0] = F[F_A] + hx * er0 + hy * F[F_Z];
    x[1] = F[F_A + 1] + hx * er1 + hy * F[F_Z + 1];
    x[2] = F[F_A + 2] + hx * er2 + hy * F[F_Z + 2];
    n[0] = nx * er0 + ny * F[F_Z];
    n[1] = nx * er1 + ny * F[F_Z + 1];
    n[2] = nx * er2 + ny * F[F_Z + 2];
    a[0] = ny * er0 - nx * F[F_Z];
    a[1] = ny * er1 - nx * F[F_Z + 1];
    a[2] = ny * er2 - nx * F[F_Z + 2];
    b[0] = cx * F[F_Y] - cy * F[F_X];
    b[1] = cx * F[F_Y + 1] - cy * F[F_X + 1];
    b[2] = cx * F[F_Y + 2] - cy * F[F_X + 2];
    const int off = isgreater(hx, axis_tol);
    *k = (off ? nx : 0.0) / (off ? hx : 1.0);
}

#endif
