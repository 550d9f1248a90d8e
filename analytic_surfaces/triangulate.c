/* Display triangulation of the analytic surfaces, reference configuration. The node
 * order of every triangle gives the outward normal n = z_local x t by the right-hand
 * rule. */
#include "profile.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Pieces of segment g in the polyline: an arc one per 2 pi / nh of its sweep, rounded up
 * (a sweep within 1e-9 of a whole number of pieces is that number), a parabola 16. */
static int seg_pieces(const rs_segment *g, int nh)
{
    if (g->type == RS_LINE)
        return 1;
    if (g->type == RS_PARAB)
        return 16;
    const int n = (int)ceil(fabs(g->sweep) * nh / (2.0 * RS_PI) - 1e-9);
    return n > 1 ? n : 1;
}

/* Profile polyline, seg_pieces pieces a segment, except that a run of LINE pieces joined
 * by SMOOTH vertices (collinear) is one piece: its inner vertices add nothing to the
 * picture. */
static int polyline(const rs_profile *p, int nh, double **out, int *count)
{
    int n = 1;
    for (int k = 0; k < p->nseg; k++)
        n += seg_pieces(&p->seg[k], nh);
    double *xy = malloc(2 * (size_t)n * sizeof *xy);
    if (!xy)
        return RS_ERR_NOMEM;
    int m = 0;
    xy[m++] = p->seg[0].p0[0];
    xy[m++] = p->seg[0].p0[1];
    for (int k = 0; k < p->nseg; k++) {
        const rs_segment *g = &p->seg[k];
        const int np = seg_pieces(g, nh);
        if (g->type == RS_LINE && k + 1 < p->nseg && p->seg[k + 1].type == RS_LINE &&
            p->vkind && p->vkind[k + 1] == RS_VTX_SMOOTH)
            continue; /* vertex k + 1 lies on the line through the run */
        for (int i = 1; i <= np; i++) {
            double x[2], t[2], kap;
            if (i == np) {
                x[0] = g->p1[0];
                x[1] = g->p1[1];
            } else {
                rs_segment_eval(g, (double)i / np, x, t, &kap);
            }
            xy[m++] = x[0];
            xy[m++] = x[1];
        }
    }
    *out = xy;
    *count = m / 2;
    return RS_OK;
}

int rs_analytic_triangulate(const rs_surface *s, double span, int nhoop, rs_trimesh *mesh,
                            rs_error *err)
{
    memset(mesh, 0, sizeof *mesh);
    if (s->profile.nseg < 1)
        return rs_error_set(err, RS_ERR_ARG,
                            "surface '%s': triangulation is for analytic profiles",
                            s->name);
    if (nhoop < 3)
        return rs_error_set(err, RS_ERR_ARG, "expected nhoop >= 3, got %d", nhoop);
    int need_span =
        s->kind == RS_SURF_SEGMENTS || (s->kind == RS_SURF_CYLINDER && !s->bounded);
    if (need_span && !(span > 0.0 && isfinite(span)))
        return rs_error_set(err, RS_ERR_ARG, "expected a finite span > 0, got %g", span);
    double *xy;
    int np;
    if (polyline(&s->profile, nhoop, &xy, &np))
        return rs_error_set(err, RS_ERR_NOMEM, "out of memory");
    int closed = s->profile.closed;
    int nodes = closed ? np - 1 : np; /* the closing node is node 0 */
    int nv, nt;
    const double axis_tol = 1e-12 * rs_profile_size(&s->profile);
    if (s->kind == RS_SURF_REVOLUTION) {
        nv = 0;
        for (int i = 0; i < nodes; i++)
            nv += fabs(xy[2 * i]) <= axis_tol ? 1 : nhoop;
        nt = 2 * (np - 1) * nhoop;
    } else {
        nv = 2 * nodes;
        nt = 2 * (np - 1);
    }
    mesh->xyz = malloc(3 * (size_t)nv * sizeof(double));
    mesh->tri = malloc(3 * (size_t)nt * sizeof(int));
    int *base = malloc((size_t)nodes * sizeof(int));
    if (!mesh->xyz || !mesh->tri || !base) {
        free(xy);
        free(base);
        rs_trimesh_free(mesh);
        return rs_error_set(err, RS_ERR_NOMEM, "out of memory");
    }
    const double *a = s->a, *ex = s->ex, *ey = s->ey, *ez = s->ez;
    int v = 0, t = 0;
    if (s->kind == RS_SURF_REVOLUTION) {
        int *ring = malloc((size_t)nodes * sizeof(int));
        if (!ring) {
            free(xy);
            free(base);
            rs_trimesh_free(mesh);
            return rs_error_set(err, RS_ERR_NOMEM, "out of memory");
        }
        for (int i = 0; i < nodes; i++) {
            double r = xy[2 * i], z = xy[2 * i + 1];
            base[i] = v;
            ring[i] = fabs(r) <= axis_tol ? 1 : nhoop;
            for (int j = 0; j < ring[i]; j++) {
                double th = 2.0 * RS_PI * j / nhoop, c = cos(th), sn = sin(th);
                for (int d = 0; d < 3; d++)
                    mesh->xyz[3 * v + d] = a[d] + r * (c * ex[d] + sn * ey[d]) + z * ez[d];
                v++;
            }
        }
        for (int i = 0; i + 1 < np; i++) {
            int i0 = i, i1 = (i + 1) % nodes;
            for (int j = 0; j < nhoop; j++) {
                int jn = (j + 1) % nhoop;
                int A0 = base[i0] + (ring[i0] > 1 ? j : 0),
                    A1 = base[i0] + (ring[i0] > 1 ? jn : 0);
                int B0 = base[i1] + (ring[i1] > 1 ? j : 0),
                    B1 = base[i1] + (ring[i1] > 1 ? jn : 0);
                /* (r, z) step x hoop = n: (A0, B0, A1) and (B0, B1, A1) */
                int tr[2][3] = {{A0, B0, A1}, {B0, B1, A1}};
                for (int q = 0; q < 2; q++) {
                    if (tr[q][0] == tr[q][1] || tr[q][1] == tr[q][2] ||
                        tr[q][0] == tr[q][2])
                        continue;
                    memcpy(mesh->tri + 3 * t, tr[q], sizeof tr[q]);
                    t++;
                }
            }
        }
        free(ring);
    } else {
        double z0 = -span, z1 = span;
        if (s->kind == RS_SURF_CYLINDER && s->bounded) {
            z0 = s->zmin;
            z1 = s->zmax;
        }
        for (int i = 0; i < nodes; i++) {
            double x = xy[2 * i], y = xy[2 * i + 1];
            base[i] = v;
            for (int h = 0; h < 2; h++) {
                double z = h ? z1 : z0;
                for (int d = 0; d < 3; d++)
                    mesh->xyz[3 * v + d] = s->kind == RS_SURF_SEGMENTS
                                               ? (d == 0   ? x
                                                  : d == 1 ? y
                                                           : z)
                                               : a[d] + x * ex[d] + y * ey[d] + z * ez[d];
                v++;
            }
        }
        for (int i = 0; i + 1 < np; i++) {
            int A0 = base[i], A1 = base[i] + 1;
            int B0 = base[(i + 1) % nodes], B1 = B0 + 1;
            /* (z x t) = n: (A0, A1, B0) and (B0, A1, B1) */
            int tr[2][3] = {{A0, A1, B0}, {B0, A1, B1}};
            for (int q = 0; q < 2; q++) {
                memcpy(mesh->tri + 3 * t, tr[q], sizeof tr[q]);
                t++;
            }
        }
    }
    free(xy);
    free(base);
    mesh->nvert = v;
    mesh->ntri = t;
    return RS_OK;
}

void rs_trimesh_free(rs_trimesh *m)
{
    free(m->xyz);
    free(m->tri);
    free(m->cell);
    memset(m, 0, sizeof *m);
}
