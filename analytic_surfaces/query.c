/* Closest-feature query of the analytic surfaces: maps each point into the profile
 * plane of its kind (SEGMENTS: global x-y; CYLINDER: local x-y, extruded along ez;
 * REVOLUTION: (r, z)), asks the profile (closest.c) and maps the contacts back with the
 * frame convention of the kind. A pose x = R X + T is applied by taking the points to
 * the reference configuration and rotating the results back, so the frame turns with
 * the master (ARCHITECTURE.md, "Profiles and surfaces"). */
#include "profile.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int rs_surface_query(const rs_surface *s, const rs_query *q, rs_contacts *out,
                     rs_error *err)
{
    if (!s || !q || !out)
        return rs_error_set(err, RS_ERR_ARG, "rs_surface_query: NULL argument");
    if (s->klass) {
        if (!s->klass->query)
            return rs_error_set(err, RS_ERR_ARG, "surface '%s': class %s has no query",
                                s->name, s->klass->name ? s->klass->name : "?");
        return s->klass->query(s, q, out, err);
    }
    if (q->n <= 0)
        return RS_OK;
    int kind = s->kind;
    if (kind != RS_SURF_SEGMENTS && kind != RS_SURF_CYLINDER && kind != RS_SURF_REVOLUTION)
        return rs_error_set(err, RS_ERR_ARG, "surface '%s': kind %d has no analytic query",
                            s->name, (int)kind);
    if (!q->x || !q->y || (kind != RS_SURF_SEGMENTS && !q->z))
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
    double A[3], EX[3], EY[3], EZ[3];
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
                A[d] = R[0] * a0[0] + R[1] * a0[1] + R[2] * a0[2] + pose->T[d];
                EX[d] = R[0] * x0[0] + R[1] * x0[1] + R[2] * x0[2];
                EY[d] = R[0] * y0[0] + R[1] * y0[1] + R[2] * y0[2];
                EZ[d] = R[0] * z0[0] + R[1] * z0[1] + R[2] * z0[2];
            } else {
                A[d] = a0[d];
                EX[d] = x0[d];
                EY[d] = y0[d];
                EZ[d] = z0[d];
            }
        }
    }
    const double axis_tol = 1e-12 * pc->size;
    const double *qz = q->z;
    int rc = RS_OK;
    for (int i = 0; i < q->n; i++) {
        const double wx = q->x[i] - A[0], wy = q->y[i] - A[1],
                     wz = (qz ? qz[i] : 0.0) - A[2];
        const double lx = wx * EX[0] + wy * EX[1] + wz * EX[2];
        const double ly = wx * EY[0] + wy * EY[1] + wz * EY[2];
        const double lz = wx * EZ[0] + wy * EZ[1] + wz * EZ[2];
        /* REVOLUTION: the radial and hoop directions, e_theta = ez x e_r; on the axis
         * e_r falls back to the surface's fixed ex, never NaN */
        double u = lx, v = ly, er[3] = {EX[0], EX[1], EX[2]}, hp[3] = {EY[0], EY[1], EY[2]};
        if (kind == RS_SURF_REVOLUTION) {
            double r = sqrt(lx * lx + ly * ly);
            if (r > axis_tol) {
                double cx = lx / r, cy = ly / r;
                er[0] = cx * EX[0] + cy * EY[0];
                er[1] = cx * EX[1] + cy * EY[1];
                er[2] = cx * EX[2] + cy * EY[2];
                hp[0] = cx * EY[0] - cy * EX[0];
                hp[1] = cx * EY[1] - cy * EX[1];
                hp[2] = cx * EY[2] - cy * EX[2];
            }
            u = r;
            v = lz;
        } else if (kind == RS_SURF_CYLINDER && s->bounded &&
                   !(lz >= s->zmin && lz <= s->zmax)) {
            continue;
        }
        double rad = q->radius ? q->radius[i] : 0.0;
        int nh = rs_pcache_hits(pc, u, v, q->dist_min, q->gap_max + rad, &sc);
        if (out->n + nh > out->cap &&
            (rc = rs_contacts_reserve(out, 2 * (out->n + nh) + 64, err)) != RS_OK)
            goto done;
        for (int h = 0; h < nh; h++) {
            const rs_hit2 *ht = &sc.hits[h];
            const double hx = ht->x[0], hy = ht->x[1], nx = ht->n[0], ny = ht->n[1];
            int k = out->n++;
            out->point[k] = i;
            out->feature[k] = ht->feature;
            out->dist[k] = ht->dist;
            if (kind == RS_SURF_REVOLUTION) {
                /* n = n_r e_r + n_z ez; t2 = hoop, t1 = t2 x n = n_z e_r - n_r ez */
#define RS_REV_OUT(d)                                                                      \
    do {                                                                                   \
        out->xm[d][k] = A[d] + hx * er[d] + hy * EZ[d];                                    \
        out->nrm[d][k] = nx * er[d] + ny * EZ[d];                                          \
        out->t1[d][k] = ny * er[d] - nx * EZ[d];                                           \
        out->t2[d][k] = hp[d];                                                             \
    } while (0)
                RS_REV_OUT(0);
                RS_REV_OUT(1);
                RS_REV_OUT(2);
#undef RS_REV_OUT
                out->curv[0][k] = ht->kappa;
                /* hoop curvature n_r / r at the contact point, 0 on the axis */
                out->curv[1][k] = hx > axis_tol ? nx / hx : 0.0;
            } else {
                /* CYLINDER: t1 = ez, t2 = n x ez = n_y ex - n_x ey. SEGMENTS: t1 =
                 * (0,0,-1) x n = n_y ex - n_x ey, t2 = -ez. */
                const int cyl = kind == RS_SURF_CYLINDER;
                for (int d = 0; d < 3; d++) {
                    double tr = ny * EX[d] - nx * EY[d];
                    out->xm[d][k] = A[d] + hx * EX[d] + hy * EY[d] + lz * EZ[d];
                    out->nrm[d][k] = nx * EX[d] + ny * EY[d];
                    out->t1[d][k] = cyl ? EZ[d] : tr;
                    out->t2[d][k] = cyl ? tr : -EZ[d];
                }
                out->curv[0][k] = cyl ? 0.0 : ht->kappa;
                out->curv[1][k] = cyl ? ht->kappa : 0.0;
            }
        }
    }
done:
    rs_pscratch_free(&sc);
    free(own);
    return rc;
}
