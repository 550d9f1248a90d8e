/* What the kinds' body operations share (convex_internal.h): a body's checks and reach,
 * the list its contacts grow in, and the contact of one of its points through the kind's
 * own closest-feature query. */
#include "convex_internal.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

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

int rs_body_check(const rs_surface *s, const rs_body *b, double gap_max, rs_body *checked,
                  rs_error *err)
{
    if (!s || !s->ops || !b || !b->shape)
        return rs_error_set(err, RS_ERR_ARG,
                            "body contacts: NULL argument (a surface with a kind and a "
                            "body with a shape expected)");
    int rc = rs_shape_check(b->shape, err);
    if (rc)
        return rc;
    if (!(gap_max >= 0.0) || !isfinite(gap_max))
        return rs_error_set(err, RS_ERR_ARG,
                            "body contacts: gap_max = %g (expected a finite number >= 0)",
                            gap_max);
    for (int k = 0; k < 3; k++)
        if (!(fabs(b->x[k]) <= RS_CONVEX_COORD_MAX))
            return rs_error_set(err, RS_ERR_ARG, "body contacts: body position %g",
                                b->x[k]);
    const double *q = b->q;
    if (!isfinite(q[0]) || !isfinite(q[1]) || !isfinite(q[2]) || !isfinite(q[3]))
        return rs_error_set(
            err, RS_ERR_ARG,
            "body contacts: body quaternion (w, x, y, z) = (%g, %g, %g, %g) "
            "(expected finite values)",
            q[0], q[1], q[2], q[3]);
    const double nq = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (!(fabs(nq - 1.0) <= 1e-6))
        return rs_error_set(err, RS_ERR_ARG,
                            "body contacts: body quaternion (w, x, y, z) has norm %.17g "
                            "(expected a unit quaternion to 1e-6)",
                            nq);
    *checked = *b;
    if (fabs(nq - 1.0) > 1e-12)
        for (int k = 0; k < 4; k++)
            checked->q[k] = q[k] / nq;
    return RS_OK;
}

int rs_body_contacts_push(rs_body_contacts *l, const rs_body_contact *o, rs_error *err)
{
    if (l->n == l->cap) {
        const int cap = l->cap ? 2 * l->cap : 16;
        rs_body_contact *nc = realloc(l->borrowed ? NULL : l->c, (size_t)cap * sizeof *nc);
        if (!nc)
            return rs_error_set(err, RS_ERR_NOMEM,
                                "body contacts: out of memory for %d contacts", cap);
        if (l->borrowed)
            memcpy(nc, l->c, (size_t)l->n * sizeof *nc);
        l->c = nc;
        l->cap = cap;
        l->borrowed = 0;
    }
    l->c[l->n++] = *o;
    return RS_OK;
}

void rs_body_contacts_free(rs_body_contacts *l)
{
    if (!l)
        return;
    if (!l->borrowed)
        free(l->c);
    memset(l, 0, sizeof *l);
}

int rs_body_closest(const rs_surface *s, const rs_pose *pose, const double x[3],
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
    return s->ops->closest(s, &q, c, err);
}

int rs_body_point_contact(const rs_surface *s, const rs_pose *pose, const double p[3],
                          double r, double reach, int want, rs_contacts *c, rs_error *err,
                          int *rc)
{
    const double rad[1] = {r};
    *rc = rs_body_closest(s, pose, p, r > 0.0 ? rad : NULL, reach, c, err);
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
