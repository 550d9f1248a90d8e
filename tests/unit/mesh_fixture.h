/* The MESH unit tests' fixtures: polygon meshes made in code (a UV sphere, a torus of
 * planar quads, a box with rounded edges, a bumpy height field, a fan about an apex) and
 * written as OFF files in a scratch folder, read back as MESH surfaces; the closest point
 * of a triangle by projection and edge clamping, written here independently of the
 * library, and the nearest of all triangles by a scan; the FACETED convention's t1; a
 * query of points. Each test file makes its scratch folder first (mesh_fixture_begin) and
 * removes it last (mesh_fixture_end). */
#ifndef RS_TEST_MESH_FIXTURE_H
#define RS_TEST_MESH_FIXTURE_H

#include "rigidsurf/surface.h"
#include "rigidsurf/vec.h"
#include "rs_test.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char tmpdir[64];

/* ---- meshes written as OFF (polygons with outward winding) ------------------------ */

typedef struct poly_mesh {
    int np, nf;
    double *xyz;
    int *nc;     /* corners of each polygon */
    int *corner; /* 4 per polygon */
} poly_mesh;

static inline void pm_init(poly_mesh *m, int np, int nf)
{
    m->np = np;
    m->nf = 0;
    m->xyz = calloc(3 * (size_t)np, sizeof(double));
    m->nc = calloc((size_t)nf, sizeof(int));
    m->corner = calloc(4 * (size_t)nf, sizeof(int));
}

static inline void pm_add(poly_mesh *m, int n, int a, int b, int c, int d)
{
    m->nc[m->nf] = n;
    int *k = m->corner + 4 * m->nf++;
    k[0] = a;
    k[1] = b;
    k[2] = c;
    k[3] = d;
}

static inline void pm_free(poly_mesh *m)
{
    free(m->xyz);
    free(m->nc);
    free(m->corner);
}

static inline void write_off(const poly_mesh *m, const char *path)
{
    FILE *f = fopen(path, "w");
    fprintf(f, "OFF\n%d %d 0\n", m->np, m->nf);
    for (int i = 0; i < m->np; i++)
        fprintf(f, "%.17g %.17g %.17g\n", m->xyz[3 * i], m->xyz[3 * i + 1],
                m->xyz[3 * i + 2]);
    for (int k = 0; k < m->nf; k++) {
        fprintf(f, "%d", m->nc[k]);
        for (int j = 0; j < m->nc[k]; j++)
            fprintf(f, " %d", m->corner[4 * k + j]);
        fprintf(f, "\n");
    }
    fclose(f);
}

/* The triangles of the polygons (fans), as the brute force sees them. */
static inline int pm_triangles(const poly_mesh *m, double (*tri)[9])
{
    int nt = 0;
    for (int k = 0; k < m->nf; k++)
        for (int j = 1; j + 1 < m->nc[k]; j++) {
            const int v[3] = {m->corner[4 * k], m->corner[4 * k + j],
                              m->corner[4 * k + j + 1]};
            for (int a = 0; a < 3; a++)
                for (int d = 0; d < 3; d++)
                    tri[nt][3 * a + d] = m->xyz[3 * v[a] + d];
            nt++;
        }
    return nt;
}

static inline void uv_sphere(poly_mesh *m, int nlat, int nlon)
{
    pm_init(m, 2 + (nlat - 1) * nlon, 2 * nlat * nlon);
    double *x = m->xyz;
    x[2] = 1.0;
    x[3 * 1 + 2] = -1.0;
    for (int i = 1; i < nlat; i++)
        for (int j = 0; j < nlon; j++) {
            const double th = RS_PI * i / nlat, ph = 2 * RS_PI * j / nlon;
            double *p = x + 3 * (2 + (i - 1) * nlon + j);
            p[0] = sin(th) * cos(ph);
            p[1] = sin(th) * sin(ph);
            p[2] = cos(th);
        }
#define V(i, j) (2 + ((i)-1) * nlon + ((j) % nlon))
    for (int j = 0; j < nlon; j++) {
        pm_add(m, 3, 0, V(1, j), V(1, j + 1), 0);
        pm_add(m, 3, 1, V(nlat - 1, j + 1), V(nlat - 1, j), 0);
        for (int i = 1; i + 1 < nlat; i++) {
            pm_add(m, 3, V(i, j), V(i + 1, j), V(i + 1, j + 1), 0);
            pm_add(m, 3, V(i, j), V(i + 1, j + 1), V(i, j + 1), 0);
        }
    }
#undef V
}

static inline void torus(poly_mesh *m, int nu, int nv, double R, double r)
{
    pm_init(m, nu * nv, nu * nv);
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            const double u = 2 * RS_PI * i / nu, v = 2 * RS_PI * j / nv;
            double *p = m->xyz + 3 * (i * nv + j);
            p[0] = (R + r * cos(v)) * cos(u);
            p[1] = (R + r * cos(v)) * sin(u);
            p[2] = r * sin(v);
        }
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            const int a = i * nv + j, b = ((i + 1) % nu) * nv + j,
                      c = ((i + 1) % nu) * nv + (j + 1) % nv, d = i * nv + (j + 1) % nv;
            pm_add(m, 4, a, b, c, d); /* planar trapezoids, outward */
        }
}

/* A box [-1,1]^3 with edges rounded at radius rr, from a grid of n x n on each face. */
static inline void rounded_box(poly_mesh *m, int n, double rr)
{
    pm_init(m, 6 * (n + 1) * (n + 1), 12 * n * n);
    const double core = 1.0 - rr;
    for (int f = 0; f < 6; f++) {
        const int ax = f / 2, sg = f % 2 ? 1 : -1;
        const int a1 = (ax + 1) % 3, a2 = (ax + 2) % 3;
        for (int i = 0; i <= n; i++)
            for (int j = 0; j <= n; j++) {
                double q[3];
                q[ax] = sg;
                q[a1] = -1.0 + 2.0 * i / n;
                q[a2] = -1.0 + 2.0 * j / n;
                double c[3], v[3];
                for (int d = 0; d < 3; d++) {
                    c[d] = fmax(-core, fmin(core, q[d]));
                    v[d] = q[d] - c[d];
                }
                const double l = rs_norm3(v);
                double *p = m->xyz + 3 * ((f * (n + 1) + i) * (n + 1) + j);
                for (int d = 0; d < 3; d++)
                    p[d] = c[d] + rr * v[d] / l;
            }
        for (int i = 0; i < n; i++)
            for (int j = 0; j < n; j++) {
                const int b0 = f * (n + 1) * (n + 1);
                const int a = b0 + i * (n + 1) + j, b = a + (n + 1), c = b + 1, d = a + 1;
                if (sg > 0) {
                    pm_add(m, 3, a, b, c, 0);
                    pm_add(m, 3, a, c, d, 0);
                } else {
                    pm_add(m, 3, a, c, b, 0);
                    pm_add(m, 3, a, d, c, 0);
                }
            }
    }
}

static inline void height_field(poly_mesh *m, int n, unsigned long long seed)
{
    pm_init(m, (n + 1) * (n + 1), 2 * n * n);
    for (int i = 0; i <= n; i++)
        for (int j = 0; j <= n; j++) {
            double *p = m->xyz + 3 * (i * (n + 1) + j);
            p[0] = -1.0 + 2.0 * i / n;
            p[1] = -1.0 + 2.0 * j / n;
            p[2] = 0.1 * sin(3 * p[0]) * cos(2 * p[1]) +
                   0.02 * ((double)(rs_test_xorshift(&seed) >> 11) / 9007199254740992.0);
        }
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            const int a = i * (n + 1) + j, b = a + (n + 1), c = b + 1, d = a + 1;
            pm_add(m, 3, a, b, c, 0);
            pm_add(m, 3, a, c, d, 0);
        }
}

/* n triangles from the origin to a ring of n nodes of radius r at height h (h = 0: a
 * flat fan), normals by the right-hand rule from the ring's counter-clockwise order. */
static inline void apex_fan(poly_mesh *m, int n, double r, double h)
{
    pm_init(m, n + 1, n);
    for (int k = 0; k < n; k++) {
        m->xyz[3 * (k + 1)] = r * cos(2 * RS_PI * k / n);
        m->xyz[3 * (k + 1) + 1] = r * sin(2 * RS_PI * k / n);
        m->xyz[3 * (k + 1) + 2] = h;
    }
    for (int k = 0; k < n; k++)
        pm_add(m, 3, 0, 1 + k, 1 + (k + 1) % n, 0);
}

/* ---- the independent answer ------------------------------------------------------- */

static inline void closest_on_segment(const double *a, const double *b, const double p[3],
                                      double c[3])
{
    double u[3], w[3];
    for (int d = 0; d < 3; d++) {
        u[d] = b[d] - a[d];
        w[d] = p[d] - a[d];
    }
    double t = rs_dot3(w, u) / rs_dot3(u, u);
    t = fmax(0.0, fmin(1.0, t));
    for (int d = 0; d < 3; d++)
        c[d] = a[d] + t * u[d];
}

static inline double dist3(const double a[3], const double b[3])
{
    const double d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    return rs_norm3(d);
}

/* Closest point of triangle T to p: the plane's projection when its barycentric
 * coordinates are all >= 0, else the nearest of the three edges' closest points. */
static inline double closest_on_triangle(const double T[9], const double p[3], double c[3])
{
    const double *a = T, *b = T + 3, *cc = T + 6;
    double u[3], v[3], n[3];
    for (int d = 0; d < 3; d++) {
        u[d] = b[d] - a[d];
        v[d] = cc[d] - a[d];
    }
    rs_cross3(u, v, n);
    const double nn = rs_dot3(n, n);
    double w[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
    const double h = rs_dot3(w, n) / nn;
    double q[3];
    for (int d = 0; d < 3; d++)
        q[d] = w[d] - h * n[d];
    double c1[3], c2[3];
    rs_cross3(q, v, c1);
    rs_cross3(u, q, c2);
    const double beta = rs_dot3(c1, n) / nn, gamma = rs_dot3(c2, n) / nn;
    if (beta >= 0 && gamma >= 0 && beta + gamma <= 1) {
        for (int d = 0; d < 3; d++)
            c[d] = a[d] + q[d];
        return dist3(p, c);
    }
    double best = INFINITY, e[3];
    const double *P[3] = {a, b, cc};
    for (int k = 0; k < 3; k++) {
        closest_on_segment(P[k], P[(k + 1) % 3], p, e);
        const double dd = dist3(p, e);
        if (dd < best) {
            best = dd;
            memcpy(c, e, sizeof e);
        }
    }
    return best;
}

/* FACETED tangents from the definition: global x on the tangent plane, global z when x is
 * within 0.1 degree of n. */
/* Brute force: the distance from p to the nearest of triangles T[0 .. nt) and its
 * closest point cb. */
static inline double nearest_of_all(const double (*T)[9], int nt, const double p[3],
                                    double cb[3])
{
    double best = INFINITY;
    for (int t = 0; t < nt; t++) {
        double cp[3];
        const double dd = closest_on_triangle(T[t], p, cp);
        if (dd < best) {
            best = dd;
            memcpy(cb, cp, sizeof cp);
        }
    }
    return best;
}

static inline void faceted_t1(const double n[3], double t1[3])
{
    const double x[3] = {1, 0, 0}, z[3] = {0, 0, 1};
    const double *g = fabs(rs_dot3(n, x)) > cos(0.1 * RS_PI / 180.0) ? z : x;
    const double gn = rs_dot3(g, n);
    for (int d = 0; d < 3; d++)
        t1[d] = g[d] - gn * n[d];
    const double l = rs_norm3(t1);
    for (int d = 0; d < 3; d++)
        t1[d] /= l;
}

/* Writes text to file name in the scratch folder. */
static inline void write_text(const char *name, const char *text)
{
    char path[160];
    snprintf(path, sizeof path, "%s/%s", tmpdir, name);
    FILE *f = fopen(path, "w");
    fputs(text, f);
    fclose(f);
}

static inline int load(const char *text, rs_surface *s, rs_error *e)
{
    char path[128];
    write_text("s.inp", text);
    snprintf(path, sizeof path, "%s/s.inp", tmpdir);
    return rs_surface_read(path, NULL, s, e);
}

/* Writes m as NAME.off, frees it and reads it as surface NAME, one- or two-sided. */
static inline int load_pm_sides(poly_mesh *m, const char *name, int sides, rs_surface *s)
{
    char path[128], text[160];
    snprintf(path, sizeof path, "%s/%s.off", tmpdir, name);
    write_off(m, path);
    pm_free(m);
    snprintf(text, sizeof text, "*SURFACE, TYPE=MESH, NAME=%s, FILE=%s.off%s\n", name, name,
             sides == 2 ? ", SIDES=2" : ", SIDES=1");
    rs_error e;
    const int rc = load(text, s, &e);
    if (rc)
        fprintf(stderr, "%s\n", e.msg);
    return rc;
}

/* The same, one-sided. */
static inline int load_pm(poly_mesh *m, const char *name, rs_surface *s)
{
    return load_pm_sides(m, name, 1, s);
}

static inline void query(const rs_surface *s, int n, const double *x, const double *y,
                         const double *z, const double *r, double gap, rs_contacts *c)
{
    rs_query q;
    memset(&q, 0, sizeof q);
    q.n = n;
    q.slave.x = x;
    q.slave.y = y;
    q.slave.z = z;
    q.slave.radius = r;
    q.gap_max = gap;
    q.dist_min = -INFINITY;
    c->n = 0;
    rs_error e;
    if (rs_surface_query(s, &q, c, &e) != RS_OK)
        fprintf(stderr, "query: %s\n", e.msg);
}

/* The scratch folder /tmp/rs_test_TAG_XXXXXX; 0 when it could not be made. */
static inline int mesh_fixture_begin(const char *tag)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/rs_test_%s_XXXXXX", tag);
    return mkdtemp(tmpdir) != NULL;
}

/* The scratch folder removed; 0 when it could not be. */
static inline int mesh_fixture_end(void)
{
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    return system(cmd) == 0;
}

#endif
