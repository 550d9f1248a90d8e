/* Closest-feature query of the analytic surfaces: maps each point into the profile
 * plane of its kind (SEGMENTS: global x-y; CYLINDER: local x-y, extruded along ez;
 * REVOLUTION: (r, z)), asks the profile (closest.c) and maps the contacts back in their
 * principal frame: d1 the profile's direction of travel, d2 = n x d1 (rs_frame_orient
 * turns that into the kind's convention). A pose x = R X + T is applied by taking the
 * points to the reference configuration and rotating the results back, so the frame
 * turns with the master (docs/conventions.md, "Profiles and surfaces"). */
#include "profile.h"
#include "rs_compiler.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The frame F = {A, EX, EY, EZ} (12 numbers): local origin and axes in the current
 * configuration. */
enum { F_A = 0, F_X = 3, F_Y = 6, F_Z = 9 };

/* Upper distance bound per point: gap_max + radius. */
static void reach_radius(int m, double gap_max, const double *restrict rad,
                         double *restrict dh)
{
    for (int j = 0; j < m; j++)
        dh[j] = gap_max + rad[j];
}

/* REVOLUTION: the profile-plane point (r, z) of each point and its radial direction
 * (cx, cy) in the local x-y plane; on the axis (r <= axis_tol) the direction falls back
 * to the surface's fixed ex, (1, 0), never NaN. */
RS_MULTIVERSION static void
local_revolution(const double *F, double axis_tol, int m, const double *restrict x,
                 const double *restrict y, const double *restrict z, double *restrict u,
                 double *restrict v, double *restrict cxs, double *restrict cys)
{
    const double A0 = F[F_A], A1 = F[F_A + 1], A2 = F[F_A + 2];
    const double X0 = F[F_X], X1 = F[F_X + 1], X2 = F[F_X + 2];
    const double Y0 = F[F_Y], Y1 = F[F_Y + 1], Y2 = F[F_Y + 2];
    const double Z0 = F[F_Z], Z1 = F[F_Z + 1], Z2 = F[F_Z + 2];
    for (int j = 0; j < m; j++) {
        const double wx = x[j] - A0, wy = y[j] - A1, wz = z[j] - A2;
        const double lx = wx * X0 + wy * X1 + wz * X2;
        const double ly = wx * Y0 + wy * Y1 + wz * Y2;
        const double lz = wx * Z0 + wy * Z1 + wz * Z2;
        const double r = sqrt(lx * lx + ly * ly);
        /* the selects come before the divisions, which keeps the loop branch-free */
        const int off = isgreater(r, axis_tol);
        const double d = off ? r : 1.0;
        u[j] = r;
        v[j] = lz;
        cxs[j] = (off ? lx : 1.0) / d;
        cys[j] = (off ? ly : 0.0) / d;
    }
}

/* CYLINDER and SEGMENTS: local coordinates (u, v, w) of each point (z = NULL: 0). */
RS_MULTIVERSION static void local_extrusion(const double *F, int m,
                                            const double *restrict x,
                                            const double *restrict y,
                                            const double *restrict z, double *restrict u,
                                            double *restrict v, double *restrict w)
{
    const double A0 = F[F_A], A1 = F[F_A + 1], A2 = F[F_A + 2];
    const double X0 = F[F_X], X1 = F[F_X + 1], X2 = F[F_X + 2];
    const double Y0 = F[F_Y], Y1 = F[F_Y + 1], Y2 = F[F_Y + 2];
    const double Z0 = F[F_Z], Z1 = F[F_Z + 1], Z2 = F[F_Z + 2];
    for (int j = 0; j < m; j++) {
        const double wx = x[j] - A0, wy = y[j] - A1, wz = (z ? z[j] : 0.0) - A2;
        u[j] = wx * X0 + wy * X1 + wz * X2;
        v[j] = wx * Y0 + wy * Y1 + wz * Y2;
        w[j] = wx * Z0 + wy * Z1 + wz * Z2;
    }
}

/* REVOLUTION contacts [k0, k1) from profile-plane form (xm[0..1] = (r, z) of the closest
 * point, nrm[0..1] = (n_r, n_z)), with (cx, cy) the radial direction of point i0 + j in
 * the local x-y plane, to 3D, in place: e_r = cx EX + cy EY, n = n_r e_r + n_z EZ,
 * d1 = n_z e_r - n_r EZ (travel), d2 = n x d1 = hoop = EZ x e_r = cx EY - cy EX; hoop
 * curvature n_r / r at the contact point, 0 on the axis. */
RS_MULTIVERSION static void map_revolution(
    const double *F, double axis_tol, int k0, int k1, const int *restrict point, int i0,
    const double *restrict cxs, const double *restrict cys, double *restrict x0,
    double *restrict x1, double *restrict x2, double *restrict n0, double *restrict n1,
    double *restrict n2, double *restrict a0, double *restrict a1, double *restrict a2,
    double *restrict b0, double *restrict b1, double *restrict b2, double *restrict c1)
{
    const double A0 = F[F_A], A1 = F[F_A + 1], A2 = F[F_A + 2];
    const double X0 = F[F_X], X1 = F[F_X + 1], X2 = F[F_X + 2];
    const double Y0 = F[F_Y], Y1 = F[F_Y + 1], Y2 = F[F_Y + 2];
    const double Z0 = F[F_Z], Z1 = F[F_Z + 1], Z2 = F[F_Z + 2];
    for (int k = k0; k < k1; k++) {
        const int j = point[k] - i0;
        const double cx = cxs[j], cy = cys[j];
        const double er0 = cx * X0 + cy * Y0, er1 = cx * X1 + cy * Y1,
                     er2 = cx * X2 + cy * Y2;
        const double hx = x0[k], hy = x1[k], nx = n0[k], ny = n1[k];
        x0[k] = A0 + hx * er0 + hy * Z0;
        x1[k] = A1 + hx * er1 + hy * Z1;
        x2[k] = A2 + hx * er2 + hy * Z2;
        n0[k] = nx * er0 + ny * Z0;
        n1[k] = nx * er1 + ny * Z1;
        n2[k] = nx * er2 + ny * Z2;
        a0[k] = ny * er0 - nx * Z0;
        a1[k] = ny * er1 - nx * Z1;
        a2[k] = ny * er2 - nx * Z2;
        b0[k] = cx * Y0 - cy * X0;
        b1[k] = cx * Y1 - cy * X1;
        b2[k] = cx * Y2 - cy * X2;
        const int off = isgreater(hx, axis_tol);
        c1[k] = (off ? nx : 0.0) / (off ? hx : 1.0);
    }
}

/* CYLINDER and SEGMENTS contacts [k0, k1) from profile-plane form (xm[0..1], nrm[0..1],
 * curv[0] = profile curvature), with lz the local z of point i0 + j, to 3D, in place:
 * d1 = n_y EX - n_x EY (travel), d2 = n x d1 = -EZ, curvatures (kappa, 0). */
RS_MULTIVERSION static void
map_extrusion(const double *F, int k0, int k1, const int *restrict point, int i0,
              const double *restrict lzs, double *restrict x0, double *restrict x1,
              double *restrict x2, double *restrict n0, double *restrict n1,
              double *restrict n2, double *restrict a0, double *restrict a1,
              double *restrict a2, double *restrict b0, double *restrict b1,
              double *restrict b2, double *restrict c1)
{
    const double A0 = F[F_A], A1 = F[F_A + 1], A2 = F[F_A + 2];
    const double X0 = F[F_X], X1 = F[F_X + 1], X2 = F[F_X + 2];
    const double Y0 = F[F_Y], Y1 = F[F_Y + 1], Y2 = F[F_Y + 2];
    const double Z0 = F[F_Z], Z1 = F[F_Z + 1], Z2 = F[F_Z + 2];
    for (int k = k0; k < k1; k++) {
        const double lz = lzs[point[k] - i0];
        const double hx = x0[k], hy = x1[k], nx = n0[k], ny = n1[k];
        x0[k] = A0 + hx * X0 + hy * Y0 + lz * Z0;
        x1[k] = A1 + hx * X1 + hy * Y1 + lz * Z1;
        x2[k] = A2 + hx * X2 + hy * Y2 + lz * Z2;
        n0[k] = nx * X0 + ny * Y0;
        n1[k] = nx * X1 + ny * Y1;
        n2[k] = nx * X2 + ny * Y2;
        a0[k] = ny * X0 - nx * Y0;
        a1[k] = ny * X1 - nx * Y1;
        a2[k] = ny * X2 - nx * Y2;
        b0[k] = -Z0;
        b1[k] = -Z1;
        b2[k] = -Z2;
        c1[k] = 0.0;
    }
}

int rs_analytic_closest(const rs_surface *s, const rs_query *q, rs_contacts *out,
                        rs_error *err)
{
    if (q->n <= 0)
        return RS_OK;
    int kind = s->kind;
    if (kind != RS_SURF_SEGMENTS && kind != RS_SURF_CYLINDER && kind != RS_SURF_REVOLUTION)
        return rs_error_set(err, RS_ERR_ARG, "surface '%s': kind %d has no analytic query",
                            s->name, (int)kind);
    if (!q->slave.x || !q->slave.y || (kind != RS_SURF_SEGMENTS && !q->slave.z))
        return rs_error_set(err, RS_ERR_ARG, "rs_surface_query: missing coordinates");

    rs_pcache *own = NULL;
    const rs_pcache *pc = s->impl;
    if (!pc) {
        int rc = rs_pcache_build(s, &own, err);
        if (rc)
            return rc;
        pc = own;
    }
    double stack[2048];
    rs_pscratch sc;
    if (rs_pscratch_init(&sc, pc, stack, sizeof stack)) {
        free(own);
        return rs_error_set(err, RS_ERR_NOMEM, "out of memory for the query scratch");
    }

    /* One transform per block: the local axes and origin in the current configuration,
     * EX = R ex, ..., A = R a + T (SEGMENTS: the global axes about the origin), so a
     * point's local coordinates are EX.(x - A), ... and results map back along them. */
    const rs_pose *pose = q->pose;
    double F[12];
    {
        static const double I[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        const double *a0 = s->a, *x0 = s->ex, *y0 = s->ey, *z0 = s->ez;
        const double zero[3] = {0.0, 0.0, 0.0};
        if (kind == RS_SURF_SEGMENTS) {
            a0 = zero;
            x0 = I[0];
            y0 = I[1];
            z0 = I[2];
        }
        for (int d = 0; d < 3; d++) {
            if (pose) {
                const double *R = pose->R + 3 * d;
                F[F_A + d] = R[0] * a0[0] + R[1] * a0[1] + R[2] * a0[2] + pose->T[d];
                F[F_X + d] = R[0] * x0[0] + R[1] * x0[1] + R[2] * x0[2];
                F[F_Y + d] = R[0] * y0[0] + R[1] * y0[1] + R[2] * y0[2];
                F[F_Z + d] = R[0] * z0[0] + R[1] * z0[1] + R[2] * z0[2];
            } else {
                F[F_A + d] = a0[d];
                F[F_X + d] = x0[d];
                F[F_Y + d] = y0[d];
                F[F_Z + d] = z0[d];
            }
        }
    }
    const double axis_tol = 1e-12 * pc->size;
    int rc = RS_OK;
    /* Per chunk of points, in three passes: the local coordinates of every point, the
     * profile contacts (written in profile-plane form into out, with the values the
     * mapping needs carried along), then each contact mapped to 3D in place. */
    enum { CH = 128 };
    double pu[CH], pv[CH], dh[CH], pw[CH], cxs[CH], cys[CH];
    for (int i0 = 0; i0 < q->n; i0 += CH) {
        const int m = q->n - i0 < CH ? q->n - i0 : CH;
        if (q->slave.radius)
            reach_radius(m, q->gap_max, q->slave.radius + i0, dh);
        else
            for (int j = 0; j < m; j++)
                dh[j] = q->gap_max + 0.0;
        if (kind == RS_SURF_REVOLUTION) {
            local_revolution(F, axis_tol, m, q->slave.x + i0, q->slave.y + i0,
                             q->slave.z + i0, pu, pv, cxs, cys);
        } else {
            local_extrusion(F, m, q->slave.x + i0, q->slave.y + i0,
                            q->slave.z ? q->slave.z + i0 : NULL, pu, pv, pw);
            if (kind == RS_SURF_CYLINDER && s->bounded)
                for (int j = 0; j < m; j++)
                    if (!(pw[j] >= s->zmin && pw[j] <= s->zmax))
                        dh[j] = NAN;
        }
        const rs_ppoints pts = {m, pu, pv, dh, q->dist_min, i0};
        const int k0 = out->n;
        for (int i = 0;;) {
            int need = 0;
            i = rs_pcache_points(pc, &pts, i, out, &sc, &need);
            if (i >= m)
                break;
            if ((rc = rs_contacts_reserve(out, 2 * (out->n + need) + 64, err)) != RS_OK) {
                out->n = k0; /* no contact of this chunk is left half mapped */
                goto done;
            }
        }
        if (kind == RS_SURF_REVOLUTION)
            map_revolution(F, axis_tol, k0, out->n, out->point, i0, cxs, cys, out->xm[0],
                           out->xm[1], out->xm[2], out->nrm[0], out->nrm[1], out->nrm[2],
                           out->t1[0], out->t1[1], out->t1[2], out->t2[0], out->t2[1],
                           out->t2[2], out->curv[1]);
        else
            map_extrusion(F, k0, out->n, out->point, i0, pw, out->xm[0], out->xm[1],
                          out->xm[2], out->nrm[0], out->nrm[1], out->nrm[2], out->t1[0],
                          out->t1[1], out->t1[2], out->t2[0], out->t2[1], out->t2[2],
                          out->curv[1]);
    }
done:
    rs_pscratch_free(&sc);
    free(own);
    return rc;
}
