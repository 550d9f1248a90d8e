/* A convex body against an analytic surface (SEGMENTS, CYLINDER, REVOLUTION): per
 * owning feature, the body's deepest point along the feature's normal, found as a fixed
 * point (convex.h, rs_body_surface_contacts; docs/conventions.md, "Convex bodies"). The
 * surface is asked through its point and sphere queries only, so no kind changes. */
#include "convex_internal.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { BODY_ITER_MAX = 100 };

/* The body's reach about its centre: the farthest corner of its bounding box. */
double rs_body_reach(const rs_body *b)
{
    double lo[3], hi[3], r2 = 0.0;
    rs_shape_bounds(b->shape, lo, hi);
    for (int c = 0; c < 8; c++) {
        const double v[3] = {(c & 1) ? hi[0] : lo[0], (c & 2) ? hi[1] : lo[1],
                             (c & 4) ? hi[2] : lo[2]};
        r2 = fmax(r2, rs_dot3(v, v));
    }
    return sqrt(r2);
}

/* The contacts of one slave with the surface, into c (emptied first): a point (radius
 * NULL) or a sphere at x, every penetration kept. */
static int query_one(const rs_surface *s, const rs_pose *pose, const double x[3],
                     const double *radius, double gap_max, rs_contacts *c, rs_error *err)
{
    const double px[1] = {x[0]}, py[1] = {x[1]}, pz[1] = {x[2]};
    rs_query q;
    memset(&q, 0, sizeof q);
    q.n = 1;
    q.slave.x = px, q.slave.y = py, q.slave.z = pz;
    q.slave.radius = radius;
    q.pose = pose;
    q.gap_max = gap_max;
    q.dist_min = -INFINITY;
    c->n = 0;
    return rs_surface_query(s, &q, c, err);
}

/* The contact of point p (a ball of radius r about it when r > 0) with the surface
 * that the feature base `want` owns, else the deepest contact p has (the owning feature
 * changed); -1 when p has none. */
int rs_body_point_contact(const rs_surface *s, const rs_pose *pose, const double p[3],
                          double r, double reach, int want, rs_contacts *c, rs_error *err,
                          int *rc)
{
    const double rad[1] = {r};
    *rc = query_one(s, pose, p, r > 0.0 ? rad : NULL, reach, c, err);
    if (*rc != RS_OK || c->n == 0)
        return -1;
    int best = 0;
    for (int k = 0; k < c->n; k++) {
        if (RS_FEATURE_BASE(c->feature[k]) == want)
            return k;
        if (c->dist[k] < c->dist[best])
            best = k;
    }
    return best;
}

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

int rs_body_surface_contacts(const rs_surface *s, const rs_pose *pose, const rs_body *b,
                             double gap_max, rs_body_contact *out, int cap, int *n,
                             rs_error *err)
{
    if (s && rs_surface_has_facets(s))
        return rs_body_mesh_contacts(s, pose, b, gap_max, out, cap, n, err);
    return rs_body_features(s, pose, b, gap_max, 0, out, cap, n, err);
}

int rs_body_check(const rs_surface *s, const rs_body *b, double gap_max,
                  const rs_body_contact *out, int cap, int *n, rs_error *err)
{
    if (!s || !b || !b->shape || !out || !n || cap < 1)
        return rs_error_set(err, RS_ERR_ARG, "body contacts: NULL argument or cap < 1");
    *n = 0;
    if (!(gap_max >= 0.0) || !isfinite(gap_max))
        return rs_error_set(err, RS_ERR_ARG,
                            "body contacts: gap_max = %g (expected a finite number >= 0)",
                            gap_max);
    for (int k = 0; k < 3; k++)
        if (!(fabs(b->x[k]) <= RS_CONVEX_COORD_MAX))
            return rs_error_set(err, RS_ERR_ARG, "body contacts: body position %g",
                                b->x[k]);
    return RS_OK;
}

int rs_body_features(const rs_surface *s, const rs_pose *pose, const rs_body *b,
                     double gap_max, int lenient, rs_body_contact *out, int cap, int *n,
                     rs_error *err)
{
    int rc = rs_body_check(s, b, gap_max, out, cap, n, err);
    if (rc != RS_OK)
        return rc;
    if (rs_surface_has_facets(s)) /* a fixed point on no MESH: nothing to settle */
        return rs_body_mesh_contacts(s, pose, b, gap_max, out, cap, n, err);
    const double reach = rs_body_reach(b);

    /* The features near the body: a sphere of its reach about its centre. */
    rs_contacts cand, pc;
    memset(&cand, 0, sizeof cand);
    memset(&pc, 0, sizeof pc);
    const double cr[1] = {reach};
    rc = query_one(s, pose, b->x, cr, gap_max, &cand, err);
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
        for (int j = 0; j < *n; j++)
            if (out[j].feature == got.feature)
                slot = j;
        if (slot >= 0 && out[slot].depth >= got.depth)
            continue;
        if (slot < 0) {
            if (*n == cap) {
                rc = rs_error_set(err, RS_ERR_CAPACITY,
                                  "body contacts: more than %d contacts with '%s'", cap,
                                  s->name);
                break;
            }
            slot = (*n)++;
        }
        out[slot] = got;
    }
    rs_contacts_free(&cand);
    rs_contacts_free(&pc);
    return rc;
}
