/* The contact list a closest-feature query fills (rs_contacts, SoA). */
#include "rigidsurf/surface.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int rs_contacts_reserve(rs_contacts *c, int cap, rs_error *err)
{
    if (cap < 1)
        cap = 1;
    if (cap <= c->cap)
        return RS_OK;
    size_t nd = (size_t)cap * sizeof(double), ni = (size_t)cap * sizeof(int);
    size_t keep_d = (size_t)c->n * sizeof(double), keep_i = (size_t)c->n * sizeof(int);
    enum { ND = 16 };
    double **dv[ND] = {&c->xm[0],  &c->xm[1],   &c->xm[2],   &c->nrm[0],
                       &c->nrm[1], &c->nrm[2],  &c->t1[0],   &c->t1[1],
                       &c->t1[2],  &c->t2[0],   &c->t2[1],   &c->t2[2],
                       &c->dist,   &c->curv[0], &c->curv[1], &c->share};
    double *nd_[ND] = {0};
    int *np = malloc(ni), *nf = malloc(ni);
    int ok = np && nf;
    for (int i = 0; i < ND && ok; i++)
        ok = (nd_[i] = malloc(nd)) != NULL;
    if (!ok) {
        free(np);
        free(nf);
        for (int i = 0; i < ND; i++)
            free(nd_[i]);
        return rs_error_set(err, RS_ERR_NOMEM, "out of memory for %d contacts", cap);
    }
    if (c->n > 0) {
        memcpy(np, c->point, keep_i);
        memcpy(nf, c->feature, keep_i);
        for (int i = 0; i < ND; i++)
            memcpy(nd_[i], *dv[i], keep_d);
    }
    free(c->point);
    free(c->feature);
    c->point = np;
    c->feature = nf;
    for (int i = 0; i < ND; i++) {
        free(*dv[i]);
        *dv[i] = nd_[i];
    }
    c->cap = cap;
    return RS_OK;
}

void rs_contacts_free(rs_contacts *c)
{
    free(c->point);
    free(c->feature);
    for (int d = 0; d < 3; d++) {
        free(c->xm[d]);
        free(c->nrm[d]);
        free(c->t1[d]);
        free(c->t2[d]);
    }
    free(c->dist);
    free(c->curv[0]);
    free(c->curv[1]);
    free(c->share);
    memset(c, 0, sizeof *c);
}

void rs_cands_free(rs_cands *c)
{
    free(c->off);
    free(c->ids);
    free(c->near);
    memset(c, 0, sizeof *c);
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
