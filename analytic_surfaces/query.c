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

static int grow(rs_contacts *out, rs_error *err)
{
    int cap = out->cap > 0 ? 2 * out->cap : 64;
    return rs_contacts_reserve(out, cap, err);
}

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

    const rs_pose *pose = q->pose;
    const double *a = s->a, *ex = s->ex, *ey = s->ey, *ez = s->ez;
    double axis_tol = 1e-12 * pc->size;
    int rc = RS_OK;
    for (int i = 0; i < q->n; i++) {
        double P[3] = {q->x[i], q->y[i], q->z ? q->z[i] : 0.0};
        if (pose) {
            double w[3] = {P[0] - pose->T[0], P[1] - pose->T[1], P[2] - pose->T[2]};
            const double *R = pose->R;
            P[0] = R[0] * w[0] + R[3] * w[1] + R[6] * w[2];
            P[1] = R[1] * w[0] + R[4] * w[1] + R[7] * w[2];
            P[2] = R[2] * w[0] + R[5] * w[1] + R[8] * w[2];
        }
        double u, v, zz = 0.0, er[3] = {0.0, 0.0, 0.0};
        if (kind == RS_SURF_SEGMENTS) {
            u = P[0];
            v = P[1];
            zz = P[2];
        } else {
            double w[3] = {P[0] - a[0], P[1] - a[1], P[2] - a[2]};
            zz = w[0] * ez[0] + w[1] * ez[1] + w[2] * ez[2];
            if (kind == RS_SURF_CYLINDER) {
                if (s->bounded && !(zz >= s->zmin && zz <= s->zmax))
                    continue;
                u = w[0] * ex[0] + w[1] * ex[1] + w[2] * ex[2];
                v = w[0] * ey[0] + w[1] * ey[1] + w[2] * ey[2];
            } else {
                double rv[3] = {w[0] - zz * ez[0], w[1] - zz * ez[1], w[2] - zz * ez[2]};
                double r = sqrt(rv[0] * rv[0] + rv[1] * rv[1] + rv[2] * rv[2]);
                if (r > axis_tol) {
                    double inv = 1.0 / r;
                    er[0] = rv[0] * inv;
                    er[1] = rv[1] * inv;
                    er[2] = rv[2] * inv;
                } else {
                    /* on the axis: the surface's fixed ex, never NaN */
                    er[0] = ex[0];
                    er[1] = ex[1];
                    er[2] = ex[2];
                }
                u = r;
                v = zz;
            }
        }
        double rad = q->radius ? q->radius[i] : 0.0;
        int nh = rs_pcache_hits(pc, u, v, q->dist_min, q->gap_max + rad, &sc);
        for (int h = 0; h < nh; h++) {
            const rs_hit2 *ht = &sc.hits[h];
            if (out->n >= out->cap && (rc = grow(out, err)) != RS_OK)
                goto done;
            double xm[3], n[3], t1[3], t2[3], c0, c1;
            switch (kind) {
            case RS_SURF_SEGMENTS:
                xm[0] = ht->x[0];
                xm[1] = ht->x[1];
                xm[2] = zz;
                n[0] = ht->n[0];
                n[1] = ht->n[1];
                n[2] = 0.0;
                rs_frame_segments(n, t1, t2);
                c0 = ht->kappa;
                c1 = 0.0;
                break;
            case RS_SURF_CYLINDER:
                for (int d = 0; d < 3; d++) {
                    xm[d] = a[d] + ht->x[0] * ex[d] + ht->x[1] * ey[d] + zz * ez[d];
                    n[d] = ht->n[0] * ex[d] + ht->n[1] * ey[d];
                }
                rs_frame_cylinder(n, ez, t1, t2);
                c0 = 0.0;
                c1 = ht->kappa;
                break;
            default: {
                double hoop[3] = {ez[1] * er[2] - ez[2] * er[1],
                                  ez[2] * er[0] - ez[0] * er[2],
                                  ez[0] * er[1] - ez[1] * er[0]};
                for (int d = 0; d < 3; d++) {
                    xm[d] = a[d] + ht->x[0] * er[d] + ht->x[1] * ez[d];
                    n[d] = ht->n[0] * er[d] + ht->n[1] * ez[d];
                }
                rs_frame_revolution(n, hoop, t1, t2);
                c0 = ht->kappa;
                /* hoop curvature n_r / r at the contact point, 0 on the axis */
                c1 = ht->x[0] > axis_tol ? ht->n[0] / ht->x[0] : 0.0;
                break;
            }
            }
            int k = out->n++;
            out->point[k] = i;
            out->feature[k] = ht->feature;
            if (pose) {
                const double *R = pose->R;
                double *vin[4] = {xm, n, t1, t2};
                double **vout[4] = {out->xm, out->nrm, out->t1, out->t2};
                for (int m = 0; m < 4; m++) {
                    const double *w = vin[m];
                    double off = m == 0 ? 1.0 : 0.0;
                    for (int d = 0; d < 3; d++)
                        vout[m][d][k] = R[3 * d] * w[0] + R[3 * d + 1] * w[1] +
                                        R[3 * d + 2] * w[2] + off * pose->T[d];
                }
            } else {
                for (int d = 0; d < 3; d++) {
                    out->xm[d][k] = xm[d];
                    out->nrm[d][k] = n[d];
                    out->t1[d][k] = t1[d];
                    out->t2[d][k] = t2[d];
                }
            }
            out->dist[k] = ht->dist;
            out->curv[0][k] = c0;
            out->curv[1][k] = c1;
        }
    }
done:
    rs_pscratch_free(&sc);
    free(own);
    return rc;
}
