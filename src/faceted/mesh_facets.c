/* The MESH kind's facets: the facet under a contact (an element: a triangle, or a planar
 * quad as Abaqus's R3D4), its nodes and its shape functions at the closest point, and
 * each facet's area and normal (rs_surface_facet). */
#include "mesh.h"
#include "rigidsurf/vec.h"

#include <math.h>

/* Shape functions of a triangle at p (its plane): the barycentric coordinates. */
static void tri_shape(const double *x0, const double *x1, const double *x2,
                      const double p[3], double shape[3])
{
    double e1[3], e2[3], nrm[3];
    for (int d = 0; d < 3; d++) {
        e1[d] = x1[d] - x0[d];
        e2[d] = x2[d] - x0[d];
    }
    nrm[0] = e1[1] * e2[2] - e1[2] * e2[1];
    nrm[1] = e1[2] * e2[0] - e1[0] * e2[2];
    nrm[2] = e1[0] * e2[1] - e1[1] * e2[0];
    const double nn = nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2];
    const double *x[3] = {x0, x1, x2};
    for (int i = 0; i < 3; i++) {
        const double *a = x[(i + 1) % 3], *b = x[(i + 2) % 3];
        double u[3], v[3];
        for (int d = 0; d < 3; d++) {
            u[d] = a[d] - p[d];
            v[d] = b[d] - p[d];
        }
        const double c[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                             u[0] * v[1] - u[1] * v[0]};
        shape[i] = (c[0] * nrm[0] + c[1] * nrm[1] + c[2] * nrm[2]) / nn;
    }
}

/* Shape functions of a planar quad (bilinear, as Abaqus's R3D4) at p: the local
 * coordinates (xi, eta) in [-1, 1]^2 by Gauss-Newton on x(xi, eta) = p. */
static void quad_shape(const double *xq, const double p[3], double shape[4])
{
    static const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    double xi = 0.0, eta = 0.0;
    for (int it = 0; it < 50; it++) {
        double r[3] = {-p[0], -p[1], -p[2]}, jx[3] = {0, 0, 0}, jy[3] = {0, 0, 0};
        for (int i = 0; i < 4; i++) {
            const double n = 0.25 * (1 + sx[i] * xi) * (1 + sy[i] * eta);
            const double nx = 0.25 * sx[i] * (1 + sy[i] * eta);
            const double ny = 0.25 * sy[i] * (1 + sx[i] * xi);
            for (int d = 0; d < 3; d++) {
                r[d] += n * xq[3 * i + d];
                jx[d] += nx * xq[3 * i + d];
                jy[d] += ny * xq[3 * i + d];
            }
        }
        const double a = jx[0] * jx[0] + jx[1] * jx[1] + jx[2] * jx[2];
        const double b = jx[0] * jy[0] + jx[1] * jy[1] + jx[2] * jy[2];
        const double c = jy[0] * jy[0] + jy[1] * jy[1] + jy[2] * jy[2];
        const double gx = jx[0] * r[0] + jx[1] * r[1] + jx[2] * r[2];
        const double gy = jy[0] * r[0] + jy[1] * r[1] + jy[2] * r[2];
        const double det = a * c - b * b;
        if (!(det > 0.0))
            break;
        const double dxi = (c * gx - b * gy) / det, deta = (a * gy - b * gx) / det;
        xi -= dxi;
        eta -= deta;
        if (fabs(dxi) + fabs(deta) < 1e-15)
            break;
    }
    for (int i = 0; i < 4; i++)
        shape[i] = 0.25 * (1 + sx[i] * xi) * (1 + sy[i] * eta);
}

/* The element under feature f: a face's own, an edge's or a vertex's lowest triangle's. */
static int facet_element(const rs_mesh *m, int f)
{
    if (!m || f < 0)
        return -1;
    const int idx = RS_FEATURE_INDEX(f);
    int el = -1;
    switch (RS_FEATURE_TYPE(f)) {
    case RS_FEAT_FACE:
        el = idx;
        break;
    case RS_FEAT_EDGE:
        if (idx < m->ne && m->edge_f0[idx] < m->edge_f0[idx + 1])
            el = m->tel[m->edge_f[m->edge_f0[idx]]];
        break;
    case RS_FEAT_VERTEX:
        if (idx < m->nv && m->vfirst[idx] >= 0)
            el = m->tel[m->vfirst[idx]];
        break;
    default:
        break;
    }
    return el >= 0 && el < m->nel ? el : -1;
}

int rs_mesh_facet_index(const rs_surface *s, int f)
{
    return facet_element(s->impl, f);
}

int rs_mesh_facet_count(const rs_surface *s)
{
    const rs_mesh *m = s->impl;
    return m ? m->nel : 0;
}

/* Area and normal of element k: the sum of its triangles' (a planar quad's two). */
int rs_mesh_facet_area(const rs_surface *s, int k, double *area, double n[3])
{
    const rs_mesh *m = s->impl;
    if (!m || k < 0 || k >= m->nel)
        return -1;
    double a = 0.0;
    for (int t = m->el_t0[k]; t < m->el_t0[k + 1]; t++) {
        const double *p0 = m->xyz + 3 * (size_t)m->tri[3 * t],
                     *p1 = m->xyz + 3 * (size_t)m->tri[3 * t + 1],
                     *p2 = m->xyz + 3 * (size_t)m->tri[3 * t + 2];
        double e1[3], e2[3], c[3];
        for (int d = 0; d < 3; d++) {
            e1[d] = p1[d] - p0[d];
            e2[d] = p2[d] - p0[d];
        }
        rs_cross3(e1, e2, c);
        a += 0.5 * rs_norm3(c);
    }
    const double *tn = m->rec[m->el_t0[k]].n;
    *area = a;
    n[0] = tn[0];
    n[1] = tn[1];
    n[2] = tn[2];
    return 0;
}

int rs_mesh_facet(const rs_surface *s, int f, const double xm[3], int nodes[4],
                  double xyz[12], double shape[4])
{
    const rs_mesh *m = s->impl;
    const int el = facet_element(m, f);
    if (el < 0)
        return 0;
    const int nn = m->el_nnode[el];
    for (int i = 0; i < nn; i++) {
        const int v = m->el_nodes[4 * el + i];
        nodes[i] = m->vlabel ? m->vlabel[v] : v + 1;
        for (int d = 0; d < 3; d++)
            xyz[3 * i + d] = m->xyz[3 * (size_t)v + d];
    }
    if (nn == 3)
        tri_shape(xyz, xyz + 3, xyz + 6, xm, shape);
    else
        quad_shape(xyz, xm, shape);
    return nn;
}

int rs_mesh_facet_size(const rs_surface *s, int *nnode)
{
    const rs_mesh *m = s->impl;
    if (nnode)
        *nnode = m ? m->nv : 0;
    return m ? m->el_maxnode : 0;
}
