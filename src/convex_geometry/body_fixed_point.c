/* A convex body against an analytic surface (SEGMENTS, CYLINDER, REVOLUTION), the analytic
 * kinds' body operation (rs_surface_ops.body): per owning feature, the body's deepest
 * point along the feature's normal, found as a fixed point (convex.h,
 * rs_body_surface_contacts; docs/conventions.md, "Convex bodies"). The surface is asked
 * through its own point and sphere query (closest) only. */
#include "convex_internal.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { BODY_ITER_MAX = 100 };

/* The contact of the query's entry j as a body contact with witness p. */
static void take(rs_body_contact *o, const rs_contacts *pc, int j, const double p[3],
                 int it)
{
    o->feature = pc->feature[j];
    o->depth = -pc->dist[j];
    o->iterations = it;
    for (int d = 0; d < 3; d++) {
        o->normal[d] = pc->nrm[d][j];
        o->xm[d] = pc->xm[d][j];
        o->xs[d] = p[d];
        o->t1[d] = pc->t1[d][j];
        o->t2[d] = pc->t2[d][j];
    }
    o->curv[0] = pc->curv[0][j];
    o->curv[1] = pc->curv[1][j];
}

int rs_body_fixed_point(const rs_surface *s, const rs_pose *pose, const rs_body *body,
                        double gap_max, int lenient, rs_body_contacts *out, rs_error *err)
{
    rs_body checked;
    int rc = rs_body_check(s, body, gap_max, &checked, err);
    if (rc != RS_OK)
        return rc;
    const rs_body *b = &checked;
    const double reach = rs_body_reach(b);
    const int n0 = out->n;

    /* The features near the body: a sphere of its reach about its centre. */
    rs_contacts cand, pc;
    memset(&cand, 0, sizeof cand);
    memset(&pc, 0, sizeof pc);
    const double cr[1] = {reach};
    rc = rs_body_closest(s, pose, b->x, cr, gap_max, &cand, err);
    for (int k = 0; rc == RS_OK && k < cand.n; k++) {
        double nrm[3] = {cand.nrm[0][k], cand.nrm[1][k], cand.nrm[2][k]};
        int want = RS_FEATURE_BASE(cand.feature[k]), found = -1, it = 0, conv = 0;
        double p[3];
        rs_body_contact best; /* the deepest iterate */
        best.depth = -INFINITY;
        for (; it < BODY_ITER_MAX && !conv; it++) {
            const double down[3] = {-nrm[0], -nrm[1], -nrm[2]};
            rs_body_support(b, down, p);
            found = rs_body_point_contact(s, pose, p, 0.0, 2.0 * reach + gap_max, want, &pc,
                                          err, &rc);
            if (rc != RS_OK || found < 0)
                break;
            if (-pc.dist[found] > best.depth)
                take(&best, &pc, found, p, -1);
            const double nn[3] = {pc.nrm[0][found], pc.nrm[1][found], pc.nrm[2][found]};
            const double turn =
                fabs(nn[0] - nrm[0]) + fabs(nn[1] - nrm[1]) + fabs(nn[2] - nrm[2]);
            conv = turn <= 1e-13 && RS_FEATURE_BASE(pc.feature[found]) == want;
            want = RS_FEATURE_BASE(pc.feature[found]);
            memcpy(nrm, nn, sizeof nrm);
        }
        if (rc != RS_OK || found < 0)
            continue; /* the body's deepest point has no contact: none here */
        rs_body_contact got;
        if (conv) {
            take(&got, &pc, found, p, it);
        } else if (lenient) {
            got = best;
        } else {
            rc = rs_error_set(err, RS_ERR_GEOMETRY,
                              "body contacts: the deepest point on feature %d of '%s' did "
                              "not settle in %d iterations (a wall curved more sharply "
                              "than the body?)",
                              want, s->name, BODY_ITER_MAX);
            break;
        }
        if (!(-got.depth <= gap_max))
            continue;
        /* one contact per owning feature: the deepest */
        int slot = -1;
        for (int j = n0; j < out->n; j++)
            if (out->c[j].feature == got.feature)
                slot = j;
        if (slot < 0)
            rc = rs_body_contacts_push(out, &got, err);
        else if (out->c[slot].depth < got.depth)
            out->c[slot] = got;
    }
    rs_contacts_free(&cand);
    rs_contacts_free(&pc);
    return rc;
}
