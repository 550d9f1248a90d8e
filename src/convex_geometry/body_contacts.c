/* What the kinds' body operations share (convex_internal.h): a body's checks and reach,
 * the list its contacts grow in, and the contact of one of its points through the kind's
 * own closest-feature query. */
#include "convex_internal.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int rs_body_check(const rs_surface *s, const rs_body *b, double gap_max, rs_body *checked,
                  rs_error *err)
{
    const int rc = rs_body_check_shape(s, b, gap_max, err);
    return rc ? rc : rs_body_check_pose(b, checked, err);
}

int rs_body_check_shape(const rs_surface *s, const rs_body *b, double gap_max,
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
    return RS_OK;
}

int rs_body_pose_error(const rs_body *b, double nq, rs_error *err)
{
    const double *q = b->q;
    for (int k = 0; k < 3; k++)
        if (!(fabs(b->x[k]) <= RS_CONVEX_COORD_MAX))
            return rs_error_set(err, RS_ERR_ARG, "body contacts: body position %g",
                                b->x[k]);
    if (!isfinite(q[0]) || !isfinite(q[1]) || !isfinite(q[2]) || !isfinite(q[3]))
        return rs_error_set(
            err, RS_ERR_ARG,
            "body contacts: body quaternion (w, x, y, z) = (%g, %g, %g, %g) "
            "(expected finite values)",
            q[0], q[1], q[2], q[3]);
    return rs_error_set(err, RS_ERR_ARG,
                        "body contacts: body quaternion (w, x, y, z) has norm %.17g "
                        "(expected a unit quaternion to 1e-6)",
                        nq);
}

int rs_body_check_pose(const rs_body *b, rs_body *checked, rs_error *err)
{
    double nq;
    const int rc = rs_body_check_norm(b, &nq, err);
    if (rc)
        return rc;
    *checked = *b;
    if (fabs(nq - 1.0) > 1e-12)
        for (int k = 0; k < 4; k++)
            checked->q[k] = b->q[k] / nq;
    return RS_OK;
}

int rs_body_contacts_grow(rs_body_contacts *l, rs_error *err)
{
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

int rs_body_closest(const rs_surface *s, const rs_pose *pose, int n, const double *x,
                    const double *y, const double *z, const double *radius, double gap_max,
                    double depth_max, rs_contacts *c, rs_error *err)
{
    rs_query q;
    memset(&q, 0, sizeof q);
    q.n = n;
    q.slave.x = x, q.slave.y = y, q.slave.z = z;
    q.slave.radius = radius;
    q.pose = pose;
    q.gap_max = gap_max;
    q.dist_min = -depth_max;
    c->n = 0;
    return n > 0 ? s->ops->closest(s, &q, c, err) : RS_OK;
}

void rs_contacts_offsets(const rs_contacts *c, int n, int *off)
{
    int k = 0;
    for (int i = 0; i < n; i++) {
        off[i] = k;
        while (k < c->n && c->point[k] == i)
            k++;
    }
    off[n] = k;
}

int rs_contacts_pick(const rs_contacts *c, int k0, int k1, int want, double lo, double hi)
{
    int best = -1;
    for (int k = k0; k < k1; k++) {
        if (!(c->dist[k] >= lo && c->dist[k] <= hi))
            continue; /* outside the slave's own window, tested as closest tests it */
        if (RS_FEATURE_BASE(c->feature[k]) == want)
            return k;
        if (best < 0 || c->dist[k] < c->dist[best])
            best = k;
    }
    return best;
}
