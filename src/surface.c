/* Surface dispatch: the contact core reaches every surface kind through its table of
 * operations (rs_surface_ops), chosen when the surface was made; a convex body through
 * the kind's body operation, its contacts turned into the kind's frame convention. */
#include "rigidsurf/surface.h"
#include "convex_geometry/convex_internal.h"
#include "rigidsurf/convex.h"

#include <string.h>

int rs_surface_ndir(const rs_surface *s)
{
    return s && s->ops ? s->ops->ndir : 0;
}

/* A sphere's or point's witness point, x - R n, for contacts [k0, n) of q's block. */
static int sphere_witness(const rs_query *q, rs_contacts *out, int k0, rs_error *err)
{
    int rc = rs_contacts_reserve(out, out->n, err);
    for (int k = k0; rc == RS_OK && k < out->n; k++) {
        const int i = out->point[k];
        const double R = q->slave.radius ? q->slave.radius[i] : 0.0;
        out->xs[0][k] = q->slave.x[i] - R * out->nrm[0][k];
        out->xs[1][k] = q->slave.y[i] - R * out->nrm[1][k];
        out->xs[2][k] = q->slave.z[i] - R * out->nrm[2][k];
    }
    return rc;
}

/* The kind's own query of a block of spheres and points. */
static int query_spheres(const rs_surface *s, const rs_query *q, rs_contacts *out,
                         rs_error *err)
{
    const int k0 = out->n;
    int rc = s->ops->closest(s, q, out, err);
    if (rc == RS_OK) {
        rs_frame_orient(s->ops->frame, out, k0, out->n);
        if (!s->ops->shares)
            rs_contacts_fold_shares(q, out, k0);
        if (out->witness)
            rc = sphere_witness(q, out, k0, err);
    }
    return rc;
}

int rs_body_surface_contacts(const rs_surface *s, const rs_pose *pose, const rs_body *b,
                             double gap_max, rs_body_contact *out, int cap, int *n,
                             rs_error *err)
{
    if (!out || !n || cap < 1)
        return rs_error_set(err, RS_ERR_ARG, "body contacts: NULL argument or cap < 1");
    *n = 0;
    if (!s || !s->ops || !s->ops->body)
        return rs_error_set(err, RS_ERR_ARG,
                            "body contacts: no surface, or one whose kind takes no bodies");
    rs_body checked;
    int rc = rs_body_check(s, b, gap_max, &checked, err);
    if (rc != RS_OK)
        return rc;
    rs_body_contacts l = {0, cap, out, 1}; /* the caller's array while it has room */
    rc = s->ops->body(s, pose, &checked, 1, gap_max, 0, &l, err);
    if (rc == RS_OK && l.n > cap)
        rc = rs_error_set(err, RS_ERR_CAPACITY,
                          "body contacts: %d contacts with '%s', room for %d", l.n, s->name,
                          cap);
    for (int k = 0; rc == RS_OK && k < l.n; k++)
        rs_frame_orient_one(s->ops->frame, out[k].normal, out[k].t1, out[k].t2,
                            out[k].curv);
    if (rc == RS_OK)
        *n = l.n;
    rs_body_contacts_free(&l);
    return rc;
}

int rs_body_query(const rs_surface *s, const rs_pose *pose, const rs_body *b, int point,
                  double radius, double gap_max, rs_contacts *c, rs_error *err)
{
    const int k0 = c ? c->n : 0;
    const int rc = rs_body_manifold(s, pose, b, 1, point, &radius, gap_max, c, err);
    if (rc == RS_OK)
        rs_frame_orient(s->ops->frame, c, k0, c->n);
    return rc;
}

/* A block with bodies: runs of spheres and points by the kind, runs of bodies by
 * rs_body_manifold, each in the kind's frame convention. */
static int query_bodies(const rs_surface *s, const rs_query *q, rs_contacts *out,
                        rs_error *err)
{
    if (!out->witness)
        return rs_error_set(err, RS_ERR_ARG,
                            "rs_surface_query: a block with bodies needs a contact list "
                            "that keeps witness points (rs_contacts.witness)");
    int rc = RS_OK;
    rs_body_work w; /* the runs' work arrays, made once */
    memset(&w, 0, sizeof w);
    for (int i = 0; i < q->n && rc == RS_OK;) {
        int j = i;
        if (q->slave.body[i].shape) { /* a run of bodies, asked in one block */
            static const double zero[RS_BLOCK];
            while (j < q->n && q->slave.body[j].shape && j - i < RS_BLOCK)
                j++;
            for (int k = i; q->near && k < j; k++)
                q->near[k] = 0.0;
            const int k0 = out->n;
            rc = rs_body_manifold_in(s, q->pose, q->slave.body + i, j - i, i,
                                     q->slave.radius ? q->slave.radius + i : zero,
                                     q->gap_max, &w, out, err);
            if (rc == RS_OK)
                rs_frame_orient(s->ops->frame, out, k0, out->n);
            i = j;
            continue;
        }
        while (j < q->n && !q->slave.body[j].shape)
            j++;
        rs_query run = *q;
        run.n = j - i;
        run.slave.x = q->slave.x + i;
        run.slave.y = q->slave.y + i;
        run.slave.z = q->slave.z + i;
        run.slave.radius = q->slave.radius ? q->slave.radius + i : NULL;
        run.slave.body = NULL;
        run.hint = q->hint ? q->hint + i : NULL;
        run.near = q->near ? q->near + i : NULL;
        const int k0 = out->n;
        rc = query_spheres(s, &run, out, err);
        for (int k = k0; rc == RS_OK && k < out->n; k++)
            out->point[k] += i;
        i = j;
    }
    rs_body_work_free(&w);
    return rc;
}

int rs_surface_query(const rs_surface *s, const rs_query *q, rs_contacts *out,
                     rs_error *err)
{
    if (!s || !q || !out)
        return rs_error_set(err, RS_ERR_ARG, "rs_surface_query: NULL argument");
    if (!s->ops)
        return rs_error_set(err, RS_ERR_ARG, "surface '%s' has no kind", s->name);
    if (out->n == 0)
        out->shared = 0;
    return q->slave.body ? query_bodies(s, q, out, err) : query_spheres(s, q, out, err);
}

int rs_surface_has_candidates(const rs_surface *s)
{
    return s && s->ops && s->ops->candidates && s->ops->closest_among;
}

int rs_surface_candidates(const rs_surface *s, const rs_query *q, double extra, rs_cands *c,
                          rs_error *err)
{
    if (!rs_surface_has_candidates(s) || !q || !c)
        return rs_error_set(err, RS_ERR_ARG, "rs_surface_candidates: no candidate lists");
    return s->ops->candidates(s, q, extra, c, err);
}

int rs_surface_query_among(const rs_surface *s, const rs_query *q, const int *const *cand,
                           const int *ncand, rs_contacts *out, rs_error *err)
{
    if (!cand || !ncand || !rs_surface_has_candidates(s))
        return rs_surface_query(s, q, out, err);
    if (!q || !out)
        return rs_error_set(err, RS_ERR_ARG, "rs_surface_query_among: NULL argument");
    const int k0 = out->n;
    if (k0 == 0)
        out->shared = 0;
    if (q->slave.body)
        return rs_error_set(err, RS_ERR_ARG,
                            "rs_surface_query_among: candidate lists take spheres and "
                            "points (a block with bodies: rs_surface_query)");
    int rc = s->ops->closest_among(s, q, cand, ncand, out, err);
    if (rc == RS_OK) {
        rs_frame_orient(s->ops->frame, out, k0, out->n);
        if (!s->ops->shares)
            rs_contacts_fold_shares(q, out, k0);
        if (out->witness)
            rc = sphere_witness(q, out, k0, err);
    }
    return rc;
}

int rs_surface_has_facets(const rs_surface *s)
{
    return s && s->ops && s->ops->facet && s->ops->facet_count;
}

int rs_surface_facet(const rs_surface *s, int f, const double xm[3], int nodes[4],
                     double xyz[12], double shape[4])
{
    if (!s || !s->ops || !s->ops->facet)
        return 0;
    return s->ops->facet(s, f < 0 ? f : RS_FEATURE_OWNER(f), xm, nodes, xyz, shape);
}

int rs_surface_facet_size(const rs_surface *s, int *nnode)
{
    if (nnode)
        *nnode = 0;
    if (!s || !s->ops || !s->ops->facet_size)
        return 0;
    return s->ops->facet_size(s, nnode);
}

int rs_surface_facet_count(const rs_surface *s)
{
    if (!rs_surface_has_facets(s))
        return 0;
    return s->ops->facet_count(s);
}

int rs_surface_facet_area(const rs_surface *s, int k, double *area, double n[3])
{
    if (!rs_surface_has_facets(s) || !s->ops->facet_area || k < 0 ||
        k >= rs_surface_facet_count(s))
        return -1;
    return s->ops->facet_area(s, k, area, n);
}

int rs_surface_facet_index(const rs_surface *s, int f)
{
    if (!s || !s->ops || !s->ops->facet_index)
        return -1;
    return s->ops->facet_index(s, f < 0 ? f : RS_FEATURE_OWNER(f));
}

int rs_surface_adjacent(const rs_surface *s, int fa, int fb)
{
    if (!s || !s->ops || !s->ops->adjacent)
        return 0;
    /* a body's manifold point passes its history to the same point on the next feature */
    if (fa / RS_MANIFOLD_STRIDE != fb / RS_MANIFOLD_STRIDE)
        return 0;
    return s->ops->adjacent(s, RS_FEATURE_OWNER(fa), RS_FEATURE_OWNER(fb));
}

int rs_surface_fold(const rs_surface *s, int fa, int fb)
{
    if (!s || !s->ops || !s->ops->fold ||
        fa / RS_MANIFOLD_STRIDE != fb / RS_MANIFOLD_STRIDE)
        return 0;
    return s->ops->fold(s, RS_FEATURE_OWNER(fa), RS_FEATURE_OWNER(fb));
}

void rs_surface_bounds(const rs_surface *s, double lo[3], double hi[3])
{
    if (!s || !s->ops || !s->ops->bounds) {
        for (int d = 0; d < 3; d++)
            lo[d] = hi[d] = 0.0;
        return;
    }
    s->ops->bounds(s, lo, hi);
}

int rs_surface_spin_axis(const rs_surface *s, double origin[3], double axis[3])
{
    if (!s || !s->ops || !s->ops->spin_axis)
        return 0;
    return s->ops->spin_axis(s, origin, axis);
}

int rs_surface_triangulate(const rs_surface *s, double span, int nhoop, rs_trimesh *m,
                           rs_error *err)
{
    memset(m, 0, sizeof *m);
    if (!s->ops)
        return rs_error_set(err, RS_ERR_ARG, "surface '%s' has no kind", s->name);
    return s->ops->triangulate(s, span, nhoop, m, err);
}

void rs_surface_free(rs_surface *s)
{
    if (!s)
        return;
    if (s->ops)
        s->ops->free(s);
    memset(s, 0, sizeof *s);
}
