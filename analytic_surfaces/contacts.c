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
    if (cap <= c->cap && (!c->witness || c->xs[0]))
        return RS_OK;
    if (cap < c->cap)
        cap = c->cap;
    size_t nd = (size_t)cap * sizeof(double), ni = (size_t)cap * sizeof(int);
    size_t keep_d = (size_t)c->n * sizeof(double), keep_i = (size_t)c->n * sizeof(int);
    enum { ND = 19 };
    double **dv[ND] = {&c->xm[0],  &c->xm[1], &c->xm[2], &c->nrm[0],  &c->nrm[1],
                       &c->nrm[2], &c->t1[0], &c->t1[1], &c->t1[2],   &c->t2[0],
                       &c->t2[1],  &c->t2[2], &c->dist,  &c->curv[0], &c->curv[1],
                       &c->share,  &c->xs[0], &c->xs[1], &c->xs[2]};
    const int nd_used = c->witness ? ND : ND - 3;
    double *nd_[ND] = {0};
    int *np = malloc(ni), *nf = malloc(ni);
    int ok = np && nf;
    for (int i = 0; i < nd_used && ok; i++)
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
        for (int i = 0; i < nd_used; i++)
            if (*dv[i]) /* xs of a list that had none: filled by its owner */
                memcpy(nd_[i], *dv[i], keep_d);
    }
    free(c->point);
    free(c->feature);
    c->point = np;
    c->feature = nf;
    for (int i = 0; i < ND; i++) { /* xs of a list without witness points: dropped, so
                                    * that xs is either absent or as long as the rest */
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
        free(c->xs[d]);
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
