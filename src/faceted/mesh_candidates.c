/* The MESH kind's candidate lists: the triangles near each slave that may give it a
 * contact from anywhere within a margin, kept by an engine while slaves and master move
 * less than the margin (rs_surface_candidates). */
#include "mesh.h"
#include "mesh_regions.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The squared distance from p to triangle t: to its plane where p projects inside it,
 * else to the nearest of the edges it lies outside of. */
static double tri_distance2(const rs_mesh *m, int t, const double p[3])
{
    double h, sd[3];
    const double lb = tri_bound(m, t, p, &h, sd);
    if (sd[0] >= 0.0 && sd[1] >= 0.0 && sd[2] >= 0.0)
        return lb;
    double best = INFINITY;
    for (int j = 0; j < 3; j++) {
        if (sd[j] >= 0.0)
            continue;
        best = fmin(best, segment_distance2(m->xyz + 3 * m->rec[t].v[j],
                                            m->xyz + 3 * m->rec[t].v[(j + 1) % 3], p));
    }
    return best;
}

/* May triangle t give a contact to some point within ext of p, or take part in the
 * shares of a sphere of radius R there? Each test by which point_hits lets t's face, or
 * an edge or vertex it tests, own a point is the sign of a side p . m - c with unit m, or
 * of a product (p - v).(w - v) over the length |w - v|: neither moves by more than ext
 * when p moves by ext. So a feature whose test fails at p by more than ext (and a
 * rounding margin) owns no point within ext, and a triangle whose features all fail
 * gives no contact there. hit_weights reads the concave edges and vertices that a
 * triangle tests, where they are nearer than R: such a triangle is kept while they are
 * nearer than R + ext. */
static int may_own(const rs_mesh *m, int t, const double p[3], double ext, double R)
{
    const rs_mtri *r = m->rec + t;
    const unsigned fl = r->first;
    const int *tv = r->v;
    for (int j = 0; j < 3; j++) {
        if ((fl >> j & 1u) && r->kind[j] == RS_EDGE_CONCAVE) {
            int a, b;
            slot_nodes(r, j, &a, &b);
            if (segment_distance(m->xyz + 3 * a, m->xyz + 3 * b, p) < R + ext)
                return 1;
        }
        if ((fl >> (3 + j) & 1u) && m->vconc[tv[j]]) {
            const double *x = m->xyz + 3 * tv[j];
            const double dv[3] = {p[0] - x[0], p[1] - x[1], p[2] - x[2]};
            if (rs_norm3(dv) < R + ext)
                return 1;
        }
    }
    double h, sd[3];
    tri_bound(m, t, p, &h, sd);
    if (sd[0] > -ext && sd[1] > -ext && sd[2] > -ext)
        return 1; /* its face */
    for (int j = 0; j < 3; j++) {
        if (!(fl >> j & 1u) || sd[j] > ext)
            continue; /* edge j is tested only where p is outside across it */
        const int nb = r->nbr[j];
        if (nb >= 0 && side_of(m, nb / 3, nb % 3, p) > ext)
            continue; /* inside the other face */
        int a, b;
        slot_nodes(r, j, &a, &b);
        const double *pa = m->xyz + 3 * a, *pb = m->xyz + 3 * b;
        const double u[3] = {pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]};
        const double L = rs_norm3(u);
        if (along(m, a, b, p) > -ext * L && along(m, b, a, p) > -ext * L)
            return 1;
    }
    for (int j = 0; j < 3; j++)
        if ((fl >> (3 + j) & 1u) && vertex_owns(m, tv[j], p, ext))
            return 1;
    return 0;
}

/* The triangles within reach + extra of each slave that may give it a contact from
 * anywhere within extra: the tree's boxes, less those farther (tri_distance2) and those
 * whose features own no point within extra (may_own). near is the nearest of all within
 * reach. */
int rs_mesh_candidates(const rs_surface *s, const rs_query *q, double extra, rs_cands *c,
                       rs_error *err)
{
    const rs_mesh *m = s->impl;
    if (!m || !q->slave.x || !q->slave.y || !q->slave.z)
        return rs_error_set(err, RS_ERR_ARG, "rs_surface_candidates: missing data");
    if (c->offcap < q->n + 1) {
        int *no = realloc(c->off, (size_t)(q->n + 1) * sizeof *no);
        if (no)
            c->off = no;
        double *nn = realloc(c->near, (size_t)(q->n + 1) * sizeof *nn);
        if (nn)
            c->near = nn;
        if (!no || !nn)
            return rs_error_set(err, RS_ERR_NOMEM, "out of memory for candidate lists");
        c->offcap = q->n + 1;
    }
    const rs_pose *pose = moved_pose(q);
    struct {
        int *ids, cap;
    } sc = {NULL, 0};
    int rc = RS_OK, nid = 0;
    c->n = q->n;
    for (int i = 0; i < q->n && rc == RS_OK; i++) {
        c->off[i] = nid;
        c->near[i] = 0.0;
        const double r = q->slave.radius ? q->slave.radius[i] : 0.0;
        double p[3];
        slave_local(q, pose, i, p);
        /* as the query's reach (rs_mesh_closest_among), from anywhere within extra */
        double lim = q->gap_max + r;
        if (-q->dist_min > lim)
            lim = isfinite(q->dist_min)
                      ? -q->dist_min
                      : fmax(lim, rs_cgal_tree_nearest(m->tree, p) + extra);
        lim += extra;
        if (!(lim >= 0.0) || !isfinite(lim))
            continue;
        const int n = box_triangles(m, p, lim, &sc.ids, &sc.cap);
        if (n < 0) {
            rc = rs_error_set(err, RS_ERR_NOMEM, "out of memory for candidate lists");
            break;
        }
        if (nid + n > c->idcap) {
            const int cap = 2 * (nid + n) + 64;
            int *ni = realloc(c->ids, (size_t)cap * sizeof *ni);
            if (!ni) {
                rc = rs_error_set(err, RS_ERR_NOMEM, "out of memory for candidate lists");
                break;
            }
            c->ids = ni;
            c->idcap = cap;
        }
        double near2 = lim * lim;
        /* extra and a margin for the rounding of the tests at p */
        const double ext =
            extra + 1e-9 * (m->size + fabs(p[0]) + fabs(p[1]) + fabs(p[2]) + lim);
        for (int k = 0; k < n; k++) {
            const double d2 = tri_distance2(m, sc.ids[k], p);
            if (d2 <= lim * lim) {
                near2 = fmin(near2, d2);
                if (may_own(m, sc.ids[k], p, ext, r))
                    c->ids[nid++] = sc.ids[k];
            }
        }
        c->near[i] = sqrt(near2);
    }
    c->off[q->n] = nid;
    free(sc.ids);
    return rc;
}
