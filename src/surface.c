/* Surface dispatch: the contact core reaches every surface kind through its table of
 * operations (rs_surface_ops), chosen when the surface was made. */
#include "rigidsurf/surface.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <string.h>

int rs_surface_ndir(const rs_surface *s)
{
    return s && s->ops ? s->ops->ndir : 0;
}

/* The distance from x to the line through y0 along unit u. */
static double line_distance(const double y0[3], const double u[3], const double x[3])
{
    const double w[3] = {x[0] - y0[0], x[1] - y0[1], x[2] - y0[2]};
    const double t = rs_dot3(w, u);
    const double d[3] = {w[0] - t * u[0], w[1] - t * u[1], w[2] - t * u[2]};
    return rs_norm3(d);
}

/* Shares at concave folds (docs/conventions.md, "Shares at concave folds"), for kinds
 * that do not set them: the patch rule of the faceted kind (src/faceted/mesh_query.c,
 * hit_weights), with the fold lines of the contacts' tangent planes as the places where a
 * contact may begin or end while the sphere overlaps it. Two contacts i, j of one sphere
 * (radius R, centre P = x_k + d_k n_k, both in front) whose feet each lie on their own
 * side of the line L where their tangent planes meet form a concave fold; a sphere at
 * distance d_L < R from L cuts it in a chord of half-length kappa = sqrt(R^2 - d_L^2).
 * Contact k's weight is a_k^2 (a_k = sqrt(R^2 - d_k^2), the radius of the disc where the
 * sphere cuts its tangent plane) times the product over those lines of min(1, s / kappa),
 * s the distance from its foot to L; rs_contacts_patch_shares makes the weights shares. */
static void group_shares(rs_contacts *c, int a, int m, const double P[3], double R)
{
    double v[RS_SHARE_MAX], rad[RS_SHARE_MAX];
    int nfront = 0;
    for (int k = 0; k < m; k++) {
        const double d = c->dist[a + k];
        v[k] = 1.0;
        rad[k] = d > 0.0 && d < R ? sqrt((R - d) * (R + d)) : 0.0;
        nfront += rad[k] > 0.0;
    }
    if (nfront < 2)
        return;
    for (int i = 0; i + 1 < m; i++)
        for (int j = i + 1; j < m; j++) {
            if (!(rad[i] > 0.0 && rad[j] > 0.0))
                continue;
            const int ci = a + i, cj = a + j;
            const double ni[3] = {c->nrm[0][ci], c->nrm[1][ci], c->nrm[2][ci]};
            const double nj[3] = {c->nrm[0][cj], c->nrm[1][cj], c->nrm[2][cj]};
            const double xi[3] = {c->xm[0][ci], c->xm[1][ci], c->xm[2][ci]};
            const double dx[3] = {xi[0] - c->xm[0][cj], xi[1] - c->xm[1][cj],
                                  xi[2] - c->xm[2][cj]};
            double u[3];
            rs_cross3(ni, nj, u);
            const double sn = rs_norm3(u);
            if (!(sn > 1e-12))
                continue; /* parallel planes: no fold line */
            const double si = rs_dot3(dx, nj) / sn, sj = -rs_dot3(dx, ni) / sn;
            const double tol = 1e-12 * R;
            if (!(si > -tol && sj > -tol) || !(si + sj > 0.0))
                continue; /* not a concave fold between the feet */
            for (int d = 0; d < 3; d++)
                u[d] /= sn;
            /* the point of L nearest x_i: x_i + s_i m_i, m_i = n_i x u in i's plane */
            double mi[3];
            rs_cross3(ni, u, mi);
            const double y0[3] = {xi[0] + si * mi[0], xi[1] + si * mi[1],
                                  xi[2] + si * mi[2]};
            const double dl = line_distance(y0, u, P), k2 = (R - dl) * (R + dl);
            if (!(k2 > 0.0))
                continue; /* the sphere does not reach the fold line */
            const double kappa = sqrt(k2);
            for (int k = 0; k < m; k++) {
                if (!(rad[k] > 0.0))
                    continue;
                const double x[3] = {c->xm[0][a + k], c->xm[1][a + k], c->xm[2][a + k]};
                const double sk = k == i   ? fmax(si, 0.0)
                                  : k == j ? fmax(sj, 0.0)
                                           : line_distance(y0, u, x);
                if (sk < kappa)
                    v[k] *= sk / kappa;
            }
        }
    for (int k = 0; k < m; k++)
        c->share[a + k] = fmax(v[k] * rad[k] * rad[k], 1e-300);
    rs_contacts_patch_shares(c, a, m, R);
}

static void contact_shares(const rs_query *q, rs_contacts *c, int k0)
{
    const int n = c->n;
    const int *pt = c->point;
    double *sh = c->share; /* group_shares writes them through c too: no restrict */
    int multi = 0;
    for (int k = k0; k < n; k++)
        sh[k] = 1.0;
    for (int k = k0 + 1; k < n; k++)
        multi |= pt[k] == pt[k - 1];
    if (!multi || !q->slave.radius)
        return;
    for (int a = k0; a < n;) {
        int b = a + 1;
        while (b < n && pt[b] == pt[a])
            b++;
        const int i = pt[a];
        const double R = q->slave.radius[i];
        if (b - a >= 2 && R > 0.0) {
            const double P[3] = {q->slave.x[i], q->slave.y[i], q->slave.z[i]};
            const int m = b - a < RS_SHARE_MAX ? b - a : RS_SHARE_MAX;
            group_shares(c, a, m, P, R);
            for (int k = a; k < a + m; k++)
                c->shared |= sh[k] != 1.0;
        }
        a = b;
    }
}

int rs_surface_query(const rs_surface *s, const rs_query *q, rs_contacts *out,
                     rs_error *err)
{
    if (!s || !q || !out)
        return rs_error_set(err, RS_ERR_ARG, "rs_surface_query: NULL argument");
    if (!s->ops)
        return rs_error_set(err, RS_ERR_ARG, "surface '%s' has no kind", s->name);
    const int k0 = out->n;
    if (k0 == 0)
        out->shared = 0;
    int rc = s->ops->closest(s, q, out, err);
    if (rc == RS_OK) {
        rs_frame_orient(s->ops->frame, out, k0, out->n);
        if (!s->ops->shares)
            contact_shares(q, out, k0);
    }
    return rc;
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
    int rc = s->ops->closest_among(s, q, cand, ncand, out, err);
    if (rc == RS_OK) {
        rs_frame_orient(s->ops->frame, out, k0, out->n);
        if (!s->ops->shares)
            contact_shares(q, out, k0);
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
    return s->ops->facet(s, f, xm, nodes, xyz, shape);
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
    return s->ops->facet_index(s, f);
}

int rs_surface_adjacent(const rs_surface *s, int fa, int fb)
{
    if (!s || !s->ops || !s->ops->adjacent)
        return 0;
    return s->ops->adjacent(s, fa, fb);
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
