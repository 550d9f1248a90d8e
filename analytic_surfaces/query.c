/* Closest-feature query of the analytic surfaces: maps each point into the profile
 * plane of its kind (SEGMENTS: global x-y; CYLINDER: local x-y, extruded along ez;
 * REVOLUTION: (r, z)), asks the profile (closest.c) and maps the contacts back in their
 * principal frame: d1 the profile's direction of travel, d2 = n x d1 (rs_frame_orient
 * turns that into the kind's convention). A pose x = R X + T is applied by taking the
 * points to the reference configuration and rotating the results back, so the frame
 * turns with the master (docs/conventions.md, "Profiles and surfaces"). */
#include "profile.h"
#include "revolution_point.h"
#include "rigidsurf/vec.h"
#include "rs_compiler.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Upper distance bound per point: gap_max + radius. */
static void reach_radius(int m, double gap_max, const double *restrict rad,
                         double *restrict dh)
{
    for (int j = 0; j < m; j++)
        dh[j] = gap_max + rad[j];
}

/* REVOLUTION: the profile-plane point (r, z) of each point and its radial direction
 * (cx, cy) in the local x-y plane (rs_revolution_local1). */
RS_MULTIVERSION static void
local_revolution(const double *F, double axis_tol, int m, const double *restrict x,
                 const double *restrict y, const double *restrict z, double *restrict u,
                 double *restrict v, double *restrict cxs, double *restrict cys)
{
    for (int j = 0; j < m; j++)
        rs_revolution_local1(F, axis_tol, x[j], y[j], z[j], &u[j], &v[j], &cxs[j], &cys[j]);
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
 * the local x-y plane, to 3D, in place (rs_revolution_map1). */
RS_MULTIVERSION static void map_revolution(
    const double *F, double axis_tol, int k0, int k1, const int *restrict point, int i0,
    const double *restrict cxs, const double *restrict cys, double *restrict x0,
    double *restrict x1, double *restrict x2, double *restrict n0, double *restrict n1,
    double *restrict n2, double *restrict a0, double *restrict a1, double *restrict a2,
    double *restrict b0, double *restrict b1, double *restrict b2, double *restrict c1)
{
    for (int k = k0; k < k1; k++) {
        const int j = point[k] - i0;
        double x[3], n[3], a[3], b[3];
        rs_revolution_map1(F, axis_tol, cxs[j], cys[j], x0[k], x1[k], n0[k], n1[k], x, n, a,
                           b, &c1[k]);
        x0[k] = x[0], x1[k] = x[1], x2[k] = x[2];
        n0[k] = n[0], n1[k] = n[1], n2[k] = n[2];
        a0[k] = a[0], a1[k] = a[1], a2[k] = a[2];
        b0[k] = b[0], b1[k] = b[1], b2[k] = b[2];
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

/* Profile contacts of 2D points pts into tmp (emptied first), growing it as needed. */
static int profile_contacts(const rs_pcache *pc, const rs_ppoints *pts, rs_contacts *tmp,
                            rs_pscratch *sc, rs_error *err)
{
    tmp->n = 0;
    for (int i = 0;;) {
        int need = 0;
        i = rs_pcache_points(pc, pts, i, tmp, sc, &need);
        if (i >= pts->n)
            return RS_OK;
        if (need < 0)
            return rs_error_set(err, RS_ERR_NOMEM, "out of memory for the query scratch");
        int rc = rs_contacts_reserve(tmp, 2 * (tmp->n + need) + 64, err);
        if (rc)
            return rc;
    }
}

/* Appends contact k of src to dst (room reserved by the caller). */
static void copy_contact(rs_contacts *dst, const rs_contacts *src, int k)
{
    const int m = dst->n++;
    dst->point[m] = src->point[k];
    dst->feature[m] = src->feature[k];
    for (int d = 0; d < 3; d++) {
        dst->xm[d][m] = src->xm[d][k];
        dst->nrm[d][m] = src->nrm[d][k];
        dst->t1[d][m] = src->t1[d][k];
        dst->t2[d][m] = src->t2[d][k];
    }
    dst->dist[m] = src->dist[k];
    dst->curv[0][m] = src->curv[0][k];
    dst->curv[1][m] = src->curv[1][k];
}

/* Rings around the axis (REVOLUTION, spheres; docs/conventions.md). A sphere whose
 * reach contains the axis may touch the surface all around it, as in an outlet narrower
 * than the sphere. The ring closes when, in the half-plane opposite the sphere's own
 * azimuth, the profile's closest point (at any distance) lies off the axis. Then the
 * half-planes at the azimuths theta + 2 pi s / RS_RING_SECTORS, s = 1 .. RS_RING_SECTORS
 * - 1, each give the contacts of their closest profile points Q off the axis, with the
 * 3D distance |P - Q|, the normal along P - Q and the feature f + s RS_SECTOR_STRIDE.
 * In the chunk's contacts [k0, out->n) they follow each point's own, in sector order. */
static int ring_sectors(const rs_pcache *pc, const double *F, double axis_tol, int i0,
                        int m, const double *pu, const double *pv, const double *dh,
                        const double *cxs, const double *cys, const rs_query *q, int sides,
                        int k0, rs_contacts *out, rs_contacts *tmp, rs_contacts *extra,
                        rs_pscratch *sc, rs_error *err)
{
    enum { CH = 128 };
    const int K = RS_RING_SECTORS;
    int idx[CH], ring[CH], map[CH], n = 0, nring = 0;
    double su[CH], sv[CH], sd[CH];
    for (int j = 0; j < m; j++)
        if (pu[j] < dh[j])
            idx[n++] = j;
    if (n == 0)
        return RS_OK;
    /* The gate: whether the opposite half-plane's closest profile point lies off the
     * axis. Sector s queries the point (u cos a, v) of its half-plane, within u (1 + cos
     * a) <= 2 u of the mirror point (-u, v); so when a sector has a contact within the
     * reach dh, the mirror point has a profile point within 2 u + dh, and its nearest
     * contact within that reach is its nearest of all. When it has none there, no
     * sector has a contact, and the ring is left out. */
    {
        double r[CH], best[CH], dlo = 0.0;
        for (int a = 0; a < n; a++) {
            const int j = idx[a];
            su[a] = -pu[j];
            sv[a] = pv[j];
            sd[a] = r[a] = 2.0 * pu[j] + dh[j];
            dlo = fmin(dlo, -r[a]);
            best[a] = INFINITY;
            ring[a] = 0;
        }
        const rs_ppoints pts = {n, su, sv, sd, dlo, 0};
        int rc = profile_contacts(pc, &pts, tmp, sc, err);
        if (rc)
            return rc;
        for (int k = 0; k < tmp->n; k++) {
            /* within the point's own reach only (one side, the batch's depth limit is the
             * deepest point's, and a contact found deeper could hide a nearer one) */
            const int a = tmp->point[k];
            if (fabs(tmp->dist[k]) <= r[a] && fabs(tmp->dist[k]) < best[a]) {
                best[a] = fabs(tmp->dist[k]);
                ring[a] = tmp->xm[0][k] > axis_tol;
            }
        }
        for (int a = 0; a < n; a++)
            nring += ring[a];
    }
    extra->n = 0;
    for (int s = 1; s < K && nring > 0; s++) {
        const double ang = 2.0 * RS_PI * s / K, ca = cos(ang), sa = sin(ang);
        int nn = 0;
        for (int a = 0; a < n; a++) {
            if (!ring[a])
                continue;
            const int j = idx[a];
            su[nn] = pu[j] * ca;
            sv[nn] = pv[j];
            sd[nn] = dh[j]; /* the in-plane distance is at most the 3D one */
            map[nn++] = a;
        }
        /* Below, a contact counts only where its 3D distance d3 >= |in-plane distance|
         * passes: one side, on the particle side (in-plane distance >= 0); two sides,
         * d3 <= dh. So the profile query needs no penetration deeper than that. */
        const rs_ppoints pts = {nn, su, sv, sd, sides == 2 ? -INFINITY : 0.0, 0};
        int rc = profile_contacts(pc, &pts, tmp, sc, err);
        if (rc)
            return rc;
        if ((rc = rs_contacts_reserve(extra, extra->n + tmp->n + 1, err)) != RS_OK)
            return rc;
        for (int k = 0; k < tmp->n; k++) {
            const double qr = tmp->xm[0][k], qz = tmp->xm[1][k];
            if (!(qr > axis_tol))
                continue; /* on the axis: the surface closes there */
            const int j = idx[map[tmp->point[k]]], i = i0 + j;
            const double cx = cxs[j] * ca - cys[j] * sa, cy = cxs[j] * sa + cys[j] * ca;
            double er[3], Q[3], w[3];
            const double P[3] = {q->slave.x[i], q->slave.y[i], q->slave.z[i]};
            for (int d = 0; d < 3; d++) {
                er[d] = cx * F[3 + d] + cy * F[6 + d];
                Q[d] = F[d] + qr * er[d] + qz * F[9 + d];
                w[d] = P[d] - Q[d];
            }
            const double nr = tmp->nrm[0][k], nz = tmp->nrm[1][k], d3 = rs_norm3(w);
            /* the side of the profile the point is on, as the profile query found it */
            const double side = tmp->dist[k] < 0.0 ? -1.0 : 1.0, dist = side * d3;
            if ((sides != 2 && dist < 0.0) || !(dist <= q->gap_max + q->slave.radius[i]) ||
                !(dist >= q->dist_min))
                continue;
            double n3[3], d1[3], d2[3], dot = 0.0;
            for (int d = 0; d < 3; d++)
                n3[d] =
                    d3 > 1e-12 * pc->size ? side * w[d] / d3 : nr * er[d] + nz * F[9 + d];
            /* d1: the profile's travel in this half-plane, made normal to n */
            for (int d = 0; d < 3; d++) {
                d1[d] = nz * er[d] - nr * F[9 + d];
                dot += d1[d] * n3[d];
            }
            for (int d = 0; d < 3; d++)
                d1[d] -= dot * n3[d];
            const double l1 = rs_norm3(d1);
            for (int d = 0; d < 3; d++)
                d1[d] /= l1;
            rs_cross3(n3, d1, d2);
            const int e = extra->n++;
            extra->point[e] = i;
            extra->feature[e] = tmp->feature[k] + s * RS_SECTOR_STRIDE;
            for (int d = 0; d < 3; d++) {
                extra->xm[d][e] = Q[d];
                extra->nrm[d][e] = n3[d];
                extra->t1[d][e] = d1[d];
                extra->t2[d][e] = d2[d];
            }
            extra->dist[e] = dist;
            extra->curv[0][e] = tmp->curv[0][k];
            extra->curv[1][e] = nr / qr;
        }
    }
    if (extra->n == 0)
        return RS_OK;
    /* merge: each point's own contacts, then its ring contacts (already in sector
     * order, as they were made sector by sector) */
    const int nown = out->n - k0;
    int rc = rs_contacts_reserve(tmp, nown + 1, err);
    if (rc)
        return rc;
    tmp->n = 0;
    for (int k = k0; k < out->n; k++)
        copy_contact(tmp, out, k);
    if ((rc = rs_contacts_reserve(out, k0 + nown + extra->n + 1, err)) != RS_OK)
        return rc;
    out->n = k0;
    for (int j = 0, a = 0; j < m; j++) {
        const int i = i0 + j;
        for (; a < tmp->n && tmp->point[a] == i; a++)
            copy_contact(out, tmp, a);
        for (int e = 0; e < extra->n; e++)
            if (extra->point[e] == i)
                copy_contact(out, extra, e);
    }
    return RS_OK;
}

void rs_analytic_frame(const rs_surface *s, const rs_pose *pose, double F[12])
{
    static const double I[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const double *a0 = s->a, *x0 = s->ex, *y0 = s->ey, *z0 = s->ez;
    const double zero[3] = {0.0, 0.0, 0.0};
    if (s->kind == RS_SURF_SEGMENTS) {
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

    const rs_pcache *pc = s->impl;
    if (!pc) /* made when the surface is read (rs_pcache_build) */
        return rs_error_set(err, RS_ERR_ARG, "surface '%s' has no proximity cache",
                            s->name);
    double stack[2048];
    rs_pscratch sc;
    if (rs_pscratch_init(&sc, pc, stack, sizeof stack)) {
        return rs_error_set(err, RS_ERR_NOMEM, "out of memory for the query scratch");
    }

    /* One transform per block: the local axes and origin in the current configuration,
     * EX = R ex, ..., A = R a + T (SEGMENTS: the global axes about the origin), so a
     * point's local coordinates are EX.(x - A), ... and results map back along them. */
    double F[12];
    rs_analytic_frame(s, q->pose, F);
    const double axis_tol = 1e-12 * pc->size;
    int rc = RS_OK;
    rs_contacts tmp, extra; /* the ring sectors' scratch */
    memset(&tmp, 0, sizeof tmp);
    memset(&extra, 0, sizeof extra);
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
            if (need < 0) {
                out->n = k0;
                rc = rs_error_set(err, RS_ERR_NOMEM, "out of memory for the query scratch");
                goto done;
            }
            if ((rc = rs_contacts_reserve(out, 2 * (out->n + need) + 64, err)) != RS_OK) {
                out->n = k0; /* no contact of this chunk is left half mapped */
                goto done;
            }
        }
        if (kind == RS_SURF_REVOLUTION) {
            map_revolution(F, axis_tol, k0, out->n, out->point, i0, cxs, cys, out->xm[0],
                           out->xm[1], out->xm[2], out->nrm[0], out->nrm[1], out->nrm[2],
                           out->t1[0], out->t1[1], out->t1[2], out->t2[0], out->t2[1],
                           out->t2[2], out->curv[1]);
            if (q->slave.radius &&
                (rc = ring_sectors(pc, F, axis_tol, i0, m, pu, pv, dh, cxs, cys, q,
                                   s->sides, k0, out, &tmp, &extra, &sc, err)) != RS_OK) {
                out->n = k0;
                goto done;
            }
        } else
            map_extrusion(F, k0, out->n, out->point, i0, pw, out->xm[0], out->xm[1],
                          out->xm[2], out->nrm[0], out->nrm[1], out->nrm[2], out->t1[0],
                          out->t1[1], out->t1[2], out->t2[0], out->t2[1], out->t2[2],
                          out->curv[1]);
    }
done:
    if (tmp.cap)
        rs_contacts_free(&tmp);
    if (extra.cap)
        rs_contacts_free(&extra);
    rs_pscratch_free(&sc);
    return rc;
}
