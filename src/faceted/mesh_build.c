/* Building a MESH surface from a polygon soup: placement, welding, elements, edges, a
 * consistent orientation, edge kinds, pseudo-normals and the AABB tree
 * (docs/conventions.md, "Faceted surfaces"). */
#include "cgal_mesh.h"
#include "mesh.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Appends a formatted piece to a bounded warning text. */
static void warn_add(char *warn, size_t cap, const char *piece)
{
    if (!warn || cap == 0)
        return;
    size_t used = strlen(warn);
    if (used + 1 >= cap)
        return;
    snprintf(warn + used, cap - used, "%s%s", used ? "; " : "", piece);
}

static void *xmalloc(size_t n, size_t size)
{
    if (n != 0 && size > SIZE_MAX / n)
        return NULL;
    return malloc(n * size + 1);
}

void rs_mesh_free(rs_mesh *m)
{
    if (!m)
        return;
    free(m->xyz);
    free(m->tri);
    free(m->tel);
    free(m->el_t0);
    free(m->el_nodes);
    free(m->el_nnode);
    free(m->tedge);
    free(m->edge_v);
    free(m->edge_f0);
    free(m->edge_f);
    free(m->edge_kind);
    free(m->vert_e0);
    free(m->vert_w);
    free(m->rec);
    free(m->vfirst);
    free(m->vconc);
    free(m->vflat);
    free(m->el_region);
    free(m->vpn);
    free(m->vlabel);
    free(m->vopen);
    if (m->tree)
        rs_cgal_tree_free(m->tree);
    free(m->zone_mem);
    free(m);
}

/* ---- welding ---------------------------------------------------------------------- */

static const double *g_sort_xyz;
static int cmp_x(const void *a, const void *b)
{
    const double xa = g_sort_xyz[3 * *(const int *)a], xb = g_sort_xyz[3 * *(const int *)b];
    if (xa < xb)
        return -1;
    if (xa > xb)
        return 1;
    return (*(const int *)a > *(const int *)b) - (*(const int *)a < *(const int *)b);
}

/* map[i]: the welded vertex of point i; returns the number of welded vertices, or -1. */
static int weld(int np, const double *xyz, double tol, int *map)
{
    int *ord = xmalloc((size_t)np, sizeof *ord);
    int *rep = xmalloc((size_t)np, sizeof *rep);
    if (!ord || !rep) {
        free(ord);
        free(rep);
        return -1;
    }
    for (int i = 0; i < np; i++) {
        ord[i] = i;
        rep[i] = -1;
    }
    g_sort_xyz = xyz;
    qsort(ord, (size_t)np, sizeof *ord, cmp_x);
    int nv = 0;
    for (int a = 0; a < np; a++) {
        const int i = ord[a];
        if (rep[i] >= 0)
            continue;
        rep[i] = i;
        map[i] = nv;
        for (int b = a + 1; b < np && xyz[3 * ord[b]] - xyz[3 * i] <= tol; b++) {
            const int j = ord[b];
            if (rep[j] < 0 && fabs(xyz[3 * j + 1] - xyz[3 * i + 1]) <= tol &&
                fabs(xyz[3 * j + 2] - xyz[3 * i + 2]) <= tol) {
                rep[j] = i;
                map[j] = nv;
            }
        }
        nv++;
    }
    free(ord);
    free(rep);
    return nv;
}

/* ---- edges ------------------------------------------------------------------------ */

typedef struct half {
    int a, b; /* nodes, a < b */
    int t, j; /* triangle and slot */
} half;

static int cmp_half(const void *x, const void *y)
{
    const half *p = x, *q = y;
    if (p->a != q->a)
        return p->a < q->a ? -1 : 1;
    if (p->b != q->b)
        return p->b < q->b ? -1 : 1;
    if (p->t != q->t)
        return p->t < q->t ? -1 : 1;
    return (p->j > q->j) - (p->j < q->j);
}

/* Edges of the triangles: edge_v, edge_f0/edge_f (faces in increasing order), tedge. */
static int build_edges(rs_mesh *m)
{
    free(m->edge_v);
    free(m->edge_f0);
    free(m->edge_f);
    m->edge_v = m->edge_f0 = m->edge_f = NULL;
    const size_t nh = 3 * (size_t)m->nt;
    half *h = xmalloc(nh, sizeof *h);
    if (!h)
        return -1;
    for (int t = 0; t < m->nt; t++)
        for (int j = 0; j < 3; j++) {
            int u = m->tri[3 * t + j], w = m->tri[3 * t + (j + 1) % 3];
            half *e = &h[3 * (size_t)t + (size_t)j];
            e->a = u < w ? u : w;
            e->b = u < w ? w : u;
            e->t = t;
            e->j = j;
        }
    qsort(h, nh, sizeof *h, cmp_half);
    int ne = 0;
    for (size_t k = 0; k < nh; k++)
        if (k == 0 || h[k].a != h[k - 1].a || h[k].b != h[k - 1].b)
            ne++;
    m->ne = ne;
    m->edge_v = xmalloc(2 * (size_t)ne, sizeof(int));
    m->edge_f0 = xmalloc((size_t)ne + 1, sizeof(int));
    m->edge_f = xmalloc(nh, sizeof(int));
    if (!m->edge_v || !m->edge_f0 || !m->edge_f) {
        free(h);
        return -1;
    }
    int e = -1;
    for (size_t k = 0; k < nh; k++) {
        if (k == 0 || h[k].a != h[k - 1].a || h[k].b != h[k - 1].b) {
            e++;
            m->edge_v[2 * e] = h[k].a;
            m->edge_v[2 * e + 1] = h[k].b;
            m->edge_f0[e] = (int)k;
        }
        m->edge_f[k] = h[k].t;
        m->tedge[3 * h[k].t + h[k].j] = e;
    }
    m->edge_f0[ne] = (int)nh;
    free(h);
    return 0;
}

/* The node a triangle's slot j starts from under its current winding. */
static int slot_from(const rs_mesh *m, int t, int j)
{
    return m->tri[3 * t + j];
}

/* Orients every connected component consistently (across manifold edges), keeping the
 * winding of most of its faces; returns 1 when some component has no consistent
 * orientation, 0 otherwise, -1 when out of memory. */
static int orient(rs_mesh *m)
{
    signed char *flip = calloc((size_t)m->nt + 1, 1);
    int *comp = xmalloc((size_t)m->nt, sizeof(int));
    int *queue = xmalloc((size_t)m->nt, sizeof(int));
    if (!flip || !comp || !queue) {
        free(flip);
        free(comp);
        free(queue);
        return -1;
    }
    for (int t = 0; t < m->nt; t++)
        comp[t] = -1;
    int bad = 0;
    for (int seed = 0; seed < m->nt; seed++) {
        if (comp[seed] >= 0)
            continue;
        int qh = 0, qt = 0, nflip = 0;
        comp[seed] = seed;
        queue[qt++] = seed;
        while (qh < qt) {
            const int t = queue[qh++];
            for (int j = 0; j < 3; j++) {
                const int e = m->tedge[3 * t + j];
                if (m->edge_f0[e + 1] - m->edge_f0[e] != 2)
                    continue;
                const int o = m->edge_f[m->edge_f0[e]] == t ? m->edge_f[m->edge_f0[e] + 1]
                                                            : m->edge_f[m->edge_f0[e]];
                if (o == t)
                    continue;
                int jo = 0;
                while (jo < 3 && m->tedge[3 * o + jo] != e)
                    jo++;
                /* consistent windings run along the shared edge in opposite senses */
                const int from_t =
                    flip[t] ? m->tri[3 * t + (j + 1) % 3] : slot_from(m, t, j);
                const int from_o_raw = slot_from(m, o, jo);
                const int same_raw = from_o_raw == from_t;
                if (comp[o] < 0) {
                    comp[o] = seed;
                    flip[o] = (signed char)same_raw;
                    nflip += flip[o];
                    queue[qt++] = o;
                } else {
                    const int from_o = flip[o] ? m->tri[3 * o + (jo + 1) % 3] : from_o_raw;
                    if (from_o == from_t)
                        bad = 1;
                }
            }
        }
        if (2 * nflip > qt) /* keep the winding most of the component's faces had */
            for (int k = 0; k < qt; k++)
                flip[queue[k]] = (signed char)!flip[queue[k]];
    }
    for (int t = 0; t < m->nt; t++)
        if (flip[t]) {
            int tmp = m->tri[3 * t + 1];
            m->tri[3 * t + 1] = m->tri[3 * t + 2];
            m->tri[3 * t + 2] = tmp;
        }
    /* an element follows its triangles */
    for (int k = 0; k < m->nel; k++)
        if (flip[m->el_t0[k]]) {
            int *nd = m->el_nodes + 4 * k;
            if (m->el_nnode[k] == 4) {
                int tmp = nd[1];
                nd[1] = nd[3];
                nd[3] = tmp;
            } else {
                int tmp = nd[1];
                nd[1] = nd[2];
                nd[2] = tmp;
                nd[3] = nd[0];
            }
        }
    free(flip);
    free(comp);
    free(queue);
    return bad;
}

static void tri_normal(const double *xyz, const int *v, double n[3], double *twice_area)
{
    const double *a = xyz + 3 * v[0], *b = xyz + 3 * v[1], *c = xyz + 3 * v[2];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    rs_cross3(u, w, n);
    const double l = rs_norm3(n);
    *twice_area = l;
    if (l > 0.0)
        for (int d = 0; d < 3; d++)
            n[d] /= l;
}

static double longest_edge(const double *xyz, const int *v)
{
    double L = 0.0;
    for (int j = 0; j < 3; j++) {
        const double *a = xyz + 3 * v[j], *b = xyz + 3 * v[(j + 1) % 3];
        const double d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        L = fmax(L, rs_norm3(d));
    }
    return L;
}

/* Is triangle v degenerate: an edge shorter than RS_LENGTH_REL of the mesh, or a height
 * below RS_LENGTH_REL of its longest edge (its normal would not be a normal)? */
static int degenerate(const double *xyz, const int *v, double size)
{
    if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0])
        return 1;
    double n[3], a2;
    tri_normal(xyz, v, n, &a2);
    const double L = longest_edge(xyz, v);
    for (int j = 0; j < 3; j++) {
        const double *a = xyz + 3 * v[j], *b = xyz + 3 * v[(j + 1) % 3];
        const double d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        if (!(rs_norm3(d) >= RS_LENGTH_REL * size && rs_norm3(d) >= RS_LENGTH_MIN))
            return 1;
    }
    return !(a2 > RS_LENGTH_REL * L * L);
}

/* Dihedral classification, in-plane edge normals (flat edges shared exactly) and the
 * vertices' pseudo-normals and edge lists. */
static int region_root(int *parent, int k)
{
    while (parent[k] != k) {
        parent[k] = parent[parent[k]];
        k = parent[k];
    }
    return k;
}

/* Each element's coplanar region (el_region): the least element joined to it through
 * FLAT edges. Returns 0, -1 when out of memory. */
static int flat_regions(rs_mesh *m)
{
    int *g = m->el_region = xmalloc((size_t)m->nel + 1, sizeof(int));
    if (!g)
        return -1;
    for (int k = 0; k < m->nel; k++)
        g[k] = k;
    for (int e = 0; e < m->ne; e++) {
        if (m->edge_kind[e] != RS_EDGE_FLAT)
            continue;
        const int a = region_root(g, m->tel[m->edge_f[m->edge_f0[e]]]),
                  b = region_root(g, m->tel[m->edge_f[m->edge_f0[e] + 1]]);
        g[a > b ? a : b] = a < b ? a : b;
    }
    for (int k = 0; k < m->nel; k++)
        g[k] = region_root(g, k);
    return 0;
}

static int finish_topology(rs_mesh *m, int two_sided)
{
    /* the faces' unit normals and, for edge slot j of triangle t (nodes j, j + 1), its
     * unit in-plane normal into t: the records' ingredients */
    double *tn = xmalloc(3 * (size_t)m->nt, sizeof(double));
    double *tm = xmalloc(9 * (size_t)m->nt, sizeof(double));
    int rc = -1;
    m->edge_kind = xmalloc((size_t)m->ne, 1);
    m->vert_e0 = calloc((size_t)m->nv + 2, sizeof(int));
    m->vert_w = xmalloc(2 * (size_t)m->ne, sizeof(int));
    m->vpn = calloc(3 * (size_t)m->nv + 1, sizeof(double));
    m->vopen = calloc((size_t)m->nv + 1, 1);
    if (!tn || !tm || !m->edge_kind || !m->vert_e0 || !m->vert_w || !m->vpn || !m->vopen)
        goto done;
    for (int t = 0; t < m->nt; t++) {
        double a2;
        tri_normal(m->xyz, m->tri + 3 * t, tn + 3 * t, &a2);
        for (int j = 0; j < 3; j++) {
            const double *a = m->xyz + 3 * m->tri[3 * t + j],
                         *b = m->xyz + 3 * m->tri[3 * t + (j + 1) % 3];
            const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
            double *mm = tm + 9 * t + 3 * j;
            rs_cross3(tn + 3 * t, u, mm);
            const double l = rs_norm3(mm);
            for (int d = 0; d < 3; d++)
                mm[d] /= l;
        }
    }
    for (int e = 0; e < m->ne; e++) {
        const int nf = m->edge_f0[e + 1] - m->edge_f0[e];
        if (nf == 1) {
            m->edge_kind[e] = RS_EDGE_BOUNDARY;
            m->vopen[m->edge_v[2 * e]] = m->vopen[m->edge_v[2 * e + 1]] = 1;
            continue;
        }
        if (nf > 2) {
            m->edge_kind[e] = RS_EDGE_NONMANIFOLD;
            m->vopen[m->edge_v[2 * e]] = m->vopen[m->edge_v[2 * e + 1]] = 1;
            continue;
        }
        const int A = m->edge_f[m->edge_f0[e]], B = m->edge_f[m->edge_f0[e] + 1];
        const double *nA = tn + 3 * A, *nB = tn + 3 * B;
        double c[3];
        rs_cross3(nA, nB, c);
        const double cosang = rs_dot3(nA, nB);
        const double ang = atan2(rs_norm3(c), two_sided ? fabs(cosang) : cosang);
        int jA = 0, jB = 0;
        while (m->tedge[3 * A + jA] != e)
            jA++;
        while (m->tedge[3 * B + jB] != e)
            jB++;
        if (ang <= RS_MESH_FLAT_ANGLE) {
            m->edge_kind[e] = RS_EDGE_FLAT;
            for (int d = 0; d < 3; d++) /* one plane between the two faces, exactly */
                tm[9 * B + 3 * jB + d] = -tm[9 * A + 3 * jA + d];
            continue;
        }
        const double *a = m->xyz + 3 * m->tri[3 * A + jA],
                     *b = m->xyz + 3 * m->tri[3 * A + (jA + 1) % 3];
        const double eA[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        m->edge_kind[e] = rs_dot3(c, eA) > 0.0 ? RS_EDGE_CONVEX : RS_EDGE_CONCAVE;
    }
    /* the neighbours of each vertex, one per edge */
    for (int e = 0; e < m->ne; e++) {
        m->vert_e0[m->edge_v[2 * e] + 1]++;
        m->vert_e0[m->edge_v[2 * e + 1] + 1]++;
    }
    for (int v = 0; v < m->nv; v++)
        m->vert_e0[v + 1] += m->vert_e0[v];
    int *fill = xmalloc((size_t)m->nv, sizeof(int));
    if (!fill)
        goto done;
    memcpy(fill, m->vert_e0, (size_t)m->nv * sizeof(int));
    for (int e = 0; e < m->ne; e++) {
        const int a = m->edge_v[2 * e], b = m->edge_v[2 * e + 1];
        m->vert_w[fill[a]++] = b;
        m->vert_w[fill[b]++] = a;
    }
    free(fill);
    /* angle-weighted pseudo-normals */
    for (int t = 0; t < m->nt; t++)
        for (int j = 0; j < 3; j++) {
            const int v = m->tri[3 * t + j];
            const double *p = m->xyz + 3 * v, *q = m->xyz + 3 * m->tri[3 * t + (j + 1) % 3],
                         *r = m->xyz + 3 * m->tri[3 * t + (j + 2) % 3];
            const double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
            const double w[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
            double c[3];
            rs_cross3(u, w, c);
            const double ang = atan2(rs_norm3(c), rs_dot3(u, w));
            for (int d = 0; d < 3; d++)
                m->vpn[3 * v + d] += ang * tn[3 * t + d];
        }
    for (int v = 0; v < m->nv; v++) {
        const double l = rs_norm3(m->vpn + 3 * v);
        for (int d = 0; d < 3; d++)
            m->vpn[3 * v + d] = l > 0.0 ? m->vpn[3 * v + d] / l : 0.0;
    }
    /* the query's per-triangle records and each vertex's first triangle */
    if ((size_t)m->nt + 1 > SIZE_MAX / sizeof(rs_mtri))
        goto done;
    m->rec = aligned_alloc(_Alignof(rs_mtri), ((size_t)m->nt + 1) * sizeof(rs_mtri));
    m->vfirst = xmalloc((size_t)m->nv, sizeof(int));
    if (!m->rec || !m->vfirst)
        goto done;
    memset(m->rec, 0, ((size_t)m->nt + 1) * sizeof(rs_mtri));
    for (int t = 0; t < m->nt; t++)
        for (int j = 0; j < 3; j++) {
            const int e = m->tedge[3 * t + j];
            rs_mtri *r = m->rec + t;
            r->nbr[j] = -1;
            if (m->edge_f0[e + 1] - m->edge_f0[e] != 2)
                continue;
            const int o = m->edge_f[m->edge_f0[e]] == t ? m->edge_f[m->edge_f0[e] + 1]
                                                        : m->edge_f[m->edge_f0[e]];
            for (int jo = 0; jo < 3; jo++)
                if (m->tedge[3 * o + jo] == e)
                    r->nbr[j] = 3 * o + jo;
        }
    /* vertices at the end of a concave edge, where contacts may begin or end while a
     * sphere overlaps them (the query's shares) */
    m->vconc = xmalloc((size_t)m->nv, 1);
    m->vflat = xmalloc((size_t)m->nv, 1);
    if (!m->vconc || !m->vflat)
        goto done;
    memset(m->vconc, 0, (size_t)m->nv);
    memset(m->vflat, 1, (size_t)m->nv);
    for (int e = 0; e < m->ne; e++) {
        if (m->edge_kind[e] == RS_EDGE_CONCAVE)
            m->vconc[m->edge_v[2 * e]] = m->vconc[m->edge_v[2 * e + 1]] = 1;
        if (m->edge_kind[e] != RS_EDGE_FLAT) /* vertices inside a coplanar region */
            m->vflat[m->edge_v[2 * e]] = m->vflat[m->edge_v[2 * e + 1]] = 0;
    }
    for (int v = 0; v < m->nv; v++)
        m->vfirst[v] = -1;
    for (int t = m->nt - 1; t >= 0; t--)
        for (int j = 0; j < 3; j++)
            m->vfirst[m->tri[3 * t + j]] = t;
    for (int t = 0; t < m->nt; t++) {
        rs_mtri *r = m->rec + t;
        unsigned bits = 0, rough = 0;
        for (int j = 0; j < 3; j++) {
            const int e = m->tedge[3 * t + j];
            bits |= (unsigned)(m->edge_f[m->edge_f0[e]] == t) << j;
            bits |= (unsigned)(m->vfirst[m->tri[3 * t + j]] == t) << (3 + j);
            r->v[j] = m->tri[3 * t + j];
            r->edge[j] = e;
            r->kind[j] = m->edge_kind[e];
            rough |= (unsigned)(m->edge_kind[e] != RS_EDGE_FLAT) << j;
            rough |= (unsigned)!m->vflat[r->v[j]] << (3 + j);
        }
        r->first = (unsigned char)bits;
        r->rough = (unsigned char)rough;
        r->el = m->tel[t];
        for (int d = 0; d < 3; d++) {
            r->n[d] = tn[3 * t + d];
            r->a0[d] = m->xyz[3 * m->tri[3 * t] + d];
        }
        for (int j = 0; j < 3; j++) {
            const double *mm = tm + 9 * t + 3 * j;
            const double *a = m->xyz + 3 * m->edge_v[2 * m->tedge[3 * t + j]];
            for (int d = 0; d < 3; d++)
                r->e[j][d] = mm[d];
            r->e[j][3] = a[0] * mm[0] + a[1] * mm[1] + a[2] * mm[2];
        }
    }
    if (flat_regions(m) == 0)
        rc = 0;
done:
    free(tn);
    free(tm);
    return rc;
}

int rs_mesh_build(const rs_soup *soup, double scale, const double a[3], const double ex[3],
                  const double ey[3], const double ez[3], const char *origin, rs_mesh **out,
                  int *two_sided, char *warn, size_t warncap, char *info, size_t infocap,
                  rs_error *err)
{
    *out = NULL;
    *two_sided = 0;
    if (warn && warncap)
        warn[0] = '\0';
    for (int i = 0; i < 3 * soup->np; i++) {
        const double x = soup->xyz[i];
        if (!(fabs(x) <= RS_COORD_MAX) || !(fabs(x * scale) <= RS_COORD_MAX))
            return rs_error_set(err, RS_ERR_GEOMETRY,
                                "%s: point %d has coordinate %g (expected finite "
                                "coordinates with |x| <= %g after SCALE)",
                                origin, i / 3 + 1, x, RS_COORD_MAX);
    }
    if (soup->np < 3 || soup->nf < 1)
        return rs_error_set(
            err, RS_ERR_GEOMETRY,
            "%s: no triangle: %d points and %d facets (expected a mesh with "
            "at least one triangle)",
            origin, soup->np, soup->nf);
    /* count the triangles of the fan-split polygons */
    size_t ntri = 0;
    for (int f = 0; f < soup->nf; f++) {
        const int n = soup->off[f + 1] - soup->off[f];
        if (n >= 3)
            ntri += (size_t)(n - 2);
    }
    if (ntri > RS_MESH_MAX_TRI)
        return rs_error_set(err, RS_ERR_GEOMETRY, "%s: %zu triangles (expected at most %d)",
                            origin, ntri, RS_MESH_MAX_TRI);
    rs_mesh *m = calloc(1, sizeof *m);
    double *pts = xmalloc(3 * (size_t)soup->np, sizeof(double));
    int *map = xmalloc((size_t)soup->np, sizeof(int));
    int *src = xmalloc(ntri, sizeof(int)); /* the polygon of each triangle */
    if (!m || !pts || !map || !src)
        goto nomem;
    for (int i = 0; i < soup->np; i++) {
        const double *X = soup->xyz + 3 * i;
        for (int d = 0; d < 3; d++)
            pts[3 * i + d] = a[d] + scale * (X[0] * ex[d] + X[1] * ey[d] + X[2] * ez[d]);
    }
    double lo[3] = {INFINITY, INFINITY, INFINITY},
           hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < soup->np; i++)
        for (int d = 0; d < 3; d++) {
            lo[d] = fmin(lo[d], pts[3 * i + d]);
            hi[d] = fmax(hi[d], pts[3 * i + d]);
        }
    const double diag[3] = {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
    const double size = rs_norm3(diag);
    if (!(size > 0.0) || !isfinite(size)) {
        rs_mesh_free(m);
        free(pts);
        free(map);
        free(src);
        return rs_error_set(err, RS_ERR_GEOMETRY,
                            "%s: every point coincides (expected a mesh of non-zero size)",
                            origin);
    }
    const int nv = weld(soup->np, pts, RS_MESH_WELD_REL * size, map);
    if (nv < 0)
        goto nomem;
    m->nv = nv;
    m->xyz = xmalloc(3 * (size_t)nv, sizeof(double));
    m->tri = xmalloc(3 * ntri, sizeof(int));
    m->tel = xmalloc(ntri, sizeof(int));
    m->el_t0 = xmalloc(ntri + 1, sizeof(int));
    m->el_nodes = xmalloc(4 * ntri, sizeof(int));
    m->el_nnode = xmalloc(ntri, sizeof(int));
    m->tedge = xmalloc(3 * ntri, sizeof(int));
    if (!m->xyz || !m->tri || !m->tel || !m->el_t0 || !m->el_nodes || !m->el_nnode ||
        !m->tedge)
        goto nomem;
    for (int i = 0; i < soup->np; i++)
        memcpy(m->xyz + 3 * map[i], pts + 3 * i, 3 * sizeof(double));
    if (soup->label) {
        /* a welded vertex keeps the label of its first point */
        m->vlabel = xmalloc((size_t)nv, sizeof(int));
        if (!m->vlabel)
            goto nomem;
        for (int i = soup->np - 1; i >= 0; i--)
            m->vlabel[map[i]] = soup->label[i];
    }
    /* triangles and elements; degenerate ones are dropped and reported */
    int nt = 0, nel = 0, ndeg = 0;
    char degs[160] = "";
    for (int f = 0; f < soup->nf; f++) {
        const int *c = soup->idx + soup->off[f];
        const int n = soup->off[f + 1] - soup->off[f];
        const int t_first = nt;
        for (int k = 1; k + 1 < n; k++) {
            int v[3] = {map[c[0]], map[c[k]], map[c[k + 1]]};
            if (degenerate(m->xyz, v, size)) {
                if (ndeg++ < 8) {
                    size_t u = strlen(degs);
                    snprintf(degs + u, sizeof degs - u, "%s%d", u ? ", " : "", f + 1);
                }
                continue;
            }
            memcpy(m->tri + 3 * nt, v, sizeof v);
            src[nt] = f;
            nt++;
        }
        if (n < 3 && ndeg++ < 8) {
            size_t u = strlen(degs);
            snprintf(degs + u, sizeof degs - u, "%s%d", u ? ", " : "", f + 1);
        }
        /* a planar quad whose two triangles survive is one element */
        int quad = 0;
        if (n == 4 && nt - t_first == 2) {
            double n0[3], n1[3], a0, a1, c3[3];
            tri_normal(m->xyz, m->tri + 3 * t_first, n0, &a0);
            tri_normal(m->xyz, m->tri + 3 * (t_first + 1), n1, &a1);
            rs_cross3(n0, n1, c3);
            quad = atan2(rs_norm3(c3), rs_dot3(n0, n1)) <= RS_MESH_FLAT_ANGLE;
        }
        if (quad) {
            m->el_t0[nel] = t_first;
            m->el_nnode[nel] = 4;
            m->el_maxnode = 4;
            for (int j = 0; j < 4; j++)
                m->el_nodes[4 * nel + j] = map[c[j]];
            m->tel[t_first] = m->tel[t_first + 1] = nel;
            nel++;
        } else {
            for (int t = t_first; t < nt; t++) {
                m->el_t0[nel] = t;
                m->el_nnode[nel] = 3;
                for (int j = 0; j < 3; j++)
                    m->el_nodes[4 * nel + j] = m->tri[3 * t + j];
                m->el_nodes[4 * nel + 3] = m->tri[3 * t];
                m->tel[t] = nel;
                nel++;
            }
        }
    }
    m->nt = nt;
    m->nel = nel;
    m->el_t0[nel] = nt;
    if (m->el_maxnode != 4)
        m->el_maxnode = 3;
    if (ndeg) {
        char piece[256];
        snprintf(piece, sizeof piece, "%s: dropped %d degenerate facet%s (facet %s%s)",
                 origin, ndeg, ndeg > 1 ? "s" : "", degs, ndeg > 8 ? ", ..." : "");
        warn_add(warn, warncap, piece);
    }
    if (nt == 0) {
        rs_mesh_free(m);
        free(pts);
        free(map);
        free(src);
        return rs_error_set(err, RS_ERR_GEOMETRY,
                            "%s: every facet is degenerate (expected at least one triangle "
                            "of non-zero area)",
                            origin);
    }
    free(pts);
    pts = NULL;
    free(map);
    map = NULL;
    free(src);
    src = NULL;
    if (build_edges(m))
        goto nomem;
    const int bad = orient(m);
    if (bad < 0)
        goto nomem;
    if (bad) {
        *two_sided = 1;
        char piece[200];
        snprintf(piece, sizeof piece,
                 "%s: no consistent orientation of the facets (both sides of the mesh act)",
                 origin);
        warn_add(warn, warncap, piece);
    }
    if (build_edges(m) || finish_topology(m, *two_sided))
        goto nomem;
    int nnm = 0;
    for (int e = 0; e < m->ne; e++)
        nnm += m->edge_kind[e] == RS_EDGE_NONMANIFOLD;
    if (nnm) {
        char piece[200];
        snprintf(piece, sizeof piece, "%s: %d non-manifold edge%s", origin, nnm,
                 nnm == 1 ? "" : "s");
        warn_add(warn, warncap, piece);
    }
    for (int d = 0; d < 3; d++) {
        m->lo[d] = INFINITY;
        m->hi[d] = -INFINITY;
    }
    for (int v = 0; v < m->nv; v++)
        for (int d = 0; d < 3; d++) {
            m->lo[d] = fmin(m->lo[d], m->xyz[3 * v + d]);
            m->hi[d] = fmax(m->hi[d], m->xyz[3 * v + d]);
        }
    m->size = size;
    if (rs_mesh_boundary_report(m, origin, warn, warncap, info, infocap))
        goto nomem;
    m->tree = rs_cgal_tree_new(m->nt, m->xyz, m->tri);
    if (!m->tree)
        goto nomem;
    /* the faces' clear zones, zeroed (none made yet); pages untouched until a hinted
     * query names their faces */
    m->zone_mem = calloc((size_t)m->nt + 1, 64);
    if (!m->zone_mem)
        goto nomem;
    m->zone = (struct rs_mzone *)(((uintptr_t)m->zone_mem + 63) & ~(uintptr_t)63);
    *out = m;
    return RS_OK;
nomem:
    rs_mesh_free(m);
    free(pts);
    free(map);
    free(src);
    return rs_error_set(err, RS_ERR_NOMEM, "%s: out of memory building the mesh", origin);
}
