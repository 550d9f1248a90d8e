/* MESH surfaces (src/faceted/): the query against a brute-force scan of every triangle
 * (closest point by projection and edge clamping, written here independently), on a UV
 * sphere, a torus of planar quads, a box with rounded edges and a bumpy open height
 * field; frames by the FACETED convention from their definition; one contact on flat
 * regions, exactly above shared vertices and edges; a contact per face in a concave
 * apex; edge and vertex contacts of a box; placement and scale; a continuous resultant
 * along paths through tessellated cylinders, a bumpy field and a concave polyline, every
 * change of the contact set bisected (shares at concave folds); and the errors for bad
 * files. */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */
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

static void pm_init(poly_mesh *m, int np, int nf)
{
    m->np = np;
    m->nf = 0;
    m->xyz = calloc(3 * (size_t)np, sizeof(double));
    m->nc = calloc((size_t)nf, sizeof(int));
    m->corner = calloc(4 * (size_t)nf, sizeof(int));
}

static void pm_add(poly_mesh *m, int n, int a, int b, int c, int d)
{
    m->nc[m->nf] = n;
    int *k = m->corner + 4 * m->nf++;
    k[0] = a;
    k[1] = b;
    k[2] = c;
    k[3] = d;
}

static void pm_free(poly_mesh *m)
{
    free(m->xyz);
    free(m->nc);
    free(m->corner);
}

static void write_off(const poly_mesh *m, const char *path)
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
static int pm_triangles(const poly_mesh *m, double (*tri)[9])
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

static void uv_sphere(poly_mesh *m, int nlat, int nlon)
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

static void torus(poly_mesh *m, int nu, int nv, double R, double r)
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
static void rounded_box(poly_mesh *m, int n, double rr)
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

static void height_field(poly_mesh *m, int n, unsigned long long seed)
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
static void apex_fan(poly_mesh *m, int n, double r, double h)
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

static void closest_on_segment(const double *a, const double *b, const double p[3],
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

static double dist3(const double a[3], const double b[3])
{
    const double d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    return rs_norm3(d);
}

/* Closest point of triangle T to p: the plane's projection when its barycentric
 * coordinates are all >= 0, else the nearest of the three edges' closest points. */
static double closest_on_triangle(const double T[9], const double p[3], double c[3])
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
static double nearest_of_all(const double (*T)[9], int nt, const double p[3], double cb[3])
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

static void faceted_t1(const double n[3], double t1[3])
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
static void write_text(const char *name, const char *text)
{
    char path[160];
    snprintf(path, sizeof path, "%s/%s", tmpdir, name);
    FILE *f = fopen(path, "w");
    fputs(text, f);
    fclose(f);
}

static int load(const char *text, rs_surface *s, rs_error *e)
{
    char path[128];
    write_text("s.inp", text);
    snprintf(path, sizeof path, "%s/s.inp", tmpdir);
    return rs_surface_read(path, NULL, s, e);
}

/* Writes m as NAME.off, frees it and reads it as surface NAME, one- or two-sided. */
static int load_pm_sides(poly_mesh *m, const char *name, int sides, rs_surface *s)
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
static int load_pm(poly_mesh *m, const char *name, rs_surface *s)
{
    return load_pm_sides(m, name, 1, s);
}

static void query(const rs_surface *s, int n, const double *x, const double *y,
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

/* Contacts with shares below 1 among those the list checks of brute_force_case met. */
static int lists_shared;

/* Every point near mesh pm (file name, sides): the nearest contact is the brute-force
 * closest point of all triangles to 1e-12, its normal points from it to the point, and
 * its frame is the FACETED one; every contact is a local minimum (no triangle at its
 * closest point comes nearer), and no feature is counted twice. */
static int brute_force_case(const poly_mesh *pm, const char *name, int sides, double spread,
                            int npts, unsigned long long seed)
{
    char path[128], text[256];
    snprintf(path, sizeof path, "%s/%s.off", tmpdir, name);
    write_off(pm, path);
    snprintf(text, sizeof text, "*SURFACE, TYPE=MESH, NAME=%s, FILE=%s.off%s\n", name, name,
             sides == 2 ? ", SIDES=2" : ", SIDES=1");
    rs_surface s;
    rs_error e;
    if (load(text, &s, &e) != RS_OK) {
        fprintf(stderr, "%s\n", e.msg);
        return 0;
    }
    double(*T)[9] = malloc((size_t)pm->nf * 2 * sizeof *T);
    const int nt = pm_triangles(pm, T);
    int ok = 1;
    rs_contacts c;
    memset(&c, 0, sizeof c);
    for (int k = 0; k < npts && ok; k++) {
        /* a point near a random node */
        const int v = (int)(rs_test_xorshift(&seed) % (unsigned long long)pm->np);
        double p[3];
        for (int d = 0; d < 3; d++)
            p[d] = pm->xyz[3 * v + d] +
                   spread *
                       (2.0 * (double)(rs_test_xorshift(&seed) >> 11) / 9007199254740992.0 -
                        1.0);
        double cb[3];
        const double best = nearest_of_all((const double(*)[9])T, nt, p, cb);
        query(&s, 1, p, p + 1, p + 2, NULL, 1.0, &c);
        /* candidate lists with a margin of 0.05, taken 0.047 away and taken all but the
         * margin away in a random direction, give here the contacts of the whole mesh,
         * for a sphere of radius 0.15 (so with their shares at concave folds) */
        const double rr = 0.15;
        rs_contacts c3;
        memset(&c3, 0, sizeof c3);
        query(&s, 1, p, p + 1, p + 2, &rr, 1.0 - rr, &c3);
        for (int i = 0; i < c3.n; i++)
            lists_shared += c3.share[i] < 1.0;
        double dir[3], l2 = 0.0;
        for (int d = 0; d < 3; d++) {
            dir[d] =
                2.0 * (double)(rs_test_xorshift(&seed) >> 11) / 9007199254740992.0 - 1.0;
            l2 += dir[d] * dir[d];
        }
        const double away[2][3] = {{0.03, -0.03, 0.02},
                                   {0.04999 * dir[0] / sqrt(l2),
                                    0.04999 * dir[1] / sqrt(l2),
                                    0.04999 * dir[2] / sqrt(l2)}};
        for (int w = 0; w < 2 && ok; w++) {
            rs_query q;
            memset(&q, 0, sizeof q);
            const double p0[3] = {p[0] + away[w][0], p[1] + away[w][1], p[2] + away[w][2]};
            q.n = 1;
            q.slave.x = p0;
            q.slave.y = p0 + 1;
            q.slave.z = p0 + 2;
            q.slave.radius = &rr;
            q.gap_max = 1.0 - rr;
            q.dist_min = -INFINITY;
            rs_cands cd;
            memset(&cd, 0, sizeof cd);
            rs_contacts c2;
            memset(&c2, 0, sizeof c2);
            int same = rs_surface_candidates(&s, &q, 0.05, &cd, &e) == RS_OK;
            q.slave.x = p, q.slave.y = p + 1, q.slave.z = p + 2;
            const int *lst = cd.ids, nl = same ? cd.off[1] : 0;
            same = same && rs_surface_query_among(&s, &q, &lst, &nl, &c2, &e) == RS_OK;
            same = same && c2.n == c3.n;
            for (int i = 0; same && i < c3.n; i++) {
                same = c2.feature[i] == c3.feature[i] && c2.dist[i] == c3.dist[i] &&
                       c2.share[i] == c3.share[i];
                for (int d = 0; d < 3; d++)
                    same = same && c2.xm[d][i] == c3.xm[d][i];
            }
            rs_contacts_free(&c2);
            rs_cands_free(&cd);
            if (!same) {
                fprintf(stderr,
                        "%s: point %d: candidate lists taken %s change the contacts\n",
                        name, k, w ? "at the margin" : "0.047 away");
                ok = 0;
            }
        }
        rs_contacts_free(&c3);
        int kbest = -1;
        for (int i = 0; i < c.n; i++) {
            if (kbest < 0 || fabs(c.dist[i]) < fabs(c.dist[kbest]))
                kbest = i;
            for (int j = 0; j < i; j++)
                if (c.feature[i] == c.feature[j]) {
                    fprintf(stderr, "%s: point %d: feature %d twice\n", name, k,
                            c.feature[i]);
                    ok = 0;
                }
            /* each contact: |dist| = |p - xm|, n along p - xm, a local minimum */
            const double xm[3] = {c.xm[0][i], c.xm[1][i], c.xm[2][i]};
            const double n[3] = {c.nrm[0][i], c.nrm[1][i], c.nrm[2][i]};
            const double dd = dist3(p, xm);
            if (!(fabs(dd - fabs(c.dist[i])) <= 1e-12)) {
                fprintf(stderr, "%s: point %d: |p - xm| %.17g, dist %.17g\n", name, k, dd,
                        c.dist[i]);
                ok = 0;
            }
            for (int d = 0; d < 3 && dd > 1e-9; d++)
                if (!(fabs(c.dist[i] * n[d] - (p[d] - xm[d])) <= 1e-12)) {
                    fprintf(stderr, "%s: point %d: normal off p - xm\n", name, k);
                    ok = 0;
                    break;
                }
            for (int t = 0; t < nt; t++) {
                double cp[3];
                if (closest_on_triangle(T[t], xm, cp) > 1e-12)
                    continue; /* triangles at the contact point */
                if (closest_on_triangle(T[t], p, cp) < dd - 1e-12) {
                    fprintf(stderr,
                            "%s: point %d: contact %d at %.17g is no local minimum "
                            "(triangle %d at %.17g)\n",
                            name, k, c.feature[i], dd, t, dist3(p, cp));
                    ok = 0;
                    break;
                }
            }
        }
        if (best > 1.0)
            continue; /* beyond the query's reach */
        if (kbest < 0) {
            fprintf(stderr, "%s: point %d at %.17g from the mesh: no contact\n", name, k,
                    best);
            ok = 0;
            break;
        }
        if (!(fabs(fabs(c.dist[kbest]) - best) <= 1e-12)) {
            fprintf(stderr, "%s: point %d: nearest contact %.17g, brute force %.17g\n",
                    name, k, c.dist[kbest], best);
            ok = 0;
        }
        const double n[3] = {c.nrm[0][kbest], c.nrm[1][kbest], c.nrm[2][kbest]};
        double t1[3], t2[3];
        faceted_t1(n, t1);
        rs_cross3(n, t1, t2);
        for (int d = 0; d < 3; d++)
            if (!(fabs(c.t1[d][kbest] - t1[d]) <= 1e-12 &&
                  fabs(c.t2[d][kbest] - t2[d]) <= 1e-12)) {
                fprintf(stderr, "%s: point %d: frame differs from FACETED\n", name, k);
                ok = 0;
                break;
            }
    }
    rs_contacts_free(&c);
    rs_surface_free(&s);
    free(T);
    return ok;
}

/* The four meshes, each queried two-sided and, where closed, one-sided as well. */
static void brute_force_meshes(void)
{
    static const struct {
        const char *name;
        int sides;
        double spread;
        unsigned long long seed;
    } cases[] = {{"sphere", 2, 0.3, 11}, {"torus", 2, 0.25, 12}, {"torus1", 1, 0.25, 16},
                 {"rbox", 2, 0.3, 13},   {"rbox1", 1, 0.3, 17},  {"hfield", 2, 0.3, 15}};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        poly_mesh m;
        const char c = cases[k].name[1];
        if (c == 'p')
            uv_sphere(&m, 16, 32);
        else if (c == 'o')
            torus(&m, 32, 16, 1.0, 0.3);
        else if (c == 'b')
            rounded_box(&m, 8, 0.3);
        else
            height_field(&m, 20, 14);
        const int ok = brute_force_case(&m, cases[k].name, cases[k].sides, cases[k].spread,
                                        600, cases[k].seed);
        pm_free(&m);
        ENSURE(ok);
    }
    ENSURE(lists_shared > 0);
}

/* Candidate lists keep the concave folds that shorten the shares of a sphere anywhere
 * within their margin: a sphere of radius 0.15 placed 0.9 of its radius from each node
 * of a bumpy height field (two-sided; valleys, ridges and saddles), on either side, with
 * its list taken all but the margin (0.05) farther from the node, gets the contacts and
 * the shares of the tree query, value for value. */
static void lists_keep_the_folds_of_shares(void)
{
    poly_mesh pm;
    height_field(&pm, 20, 14);
    const int np = pm.np;
    double *node = malloc(3 * (size_t)np * sizeof *node);
    memcpy(node, pm.xyz, 3 * (size_t)np * sizeof *node);
    rs_surface s;
    rs_error e;
    if (load_pm_sides(&pm, "folds", 2, &s) != RS_OK) {
        free(node);
        ENSURE(0);
        return;
    }
    const double R = 0.15, margin = 0.05;
    unsigned long long seed = 29;
    int shared = 0, bad = 0;
    rs_contacts ct, cl;
    memset(&ct, 0, sizeof ct);
    memset(&cl, 0, sizeof cl);
    rs_cands cd;
    memset(&cd, 0, sizeof cd);
    for (int v = 0; v < np; v++)
        for (int side = -1; side <= 1; side += 2) {
            double u[3];
            for (int d = 0; d < 3; d++)
                u[d] = 2.0 * (double)(rs_test_xorshift(&seed) >> 11) / 9007199254740992.0 -
                       1.0;
            u[2] = side * (1.0 + fabs(u[2]));
            const double l = rs_norm3(u);
            double p[3], p0[3];
            for (int d = 0; d < 3; d++) {
                p[d] = node[3 * v + d] + 0.9 * R * u[d] / l;
                p0[d] = p[d] + 0.99998 * margin * u[d] / l;
            }
            rs_query q;
            memset(&q, 0, sizeof q);
            q.n = 1;
            q.slave.x = p0, q.slave.y = p0 + 1, q.slave.z = p0 + 2;
            q.slave.radius = &R;
            q.gap_max = 0.05;
            q.dist_min = -R;
            int ok = rs_surface_candidates(&s, &q, margin, &cd, &e) == RS_OK;
            q.slave.x = p, q.slave.y = p + 1, q.slave.z = p + 2;
            ct.n = cl.n = 0;
            const int *lst = cd.ids, nl = ok ? cd.off[1] : 0;
            ok = ok && rs_surface_query(&s, &q, &ct, &e) == RS_OK &&
                 rs_surface_query_among(&s, &q, &lst, &nl, &cl, &e) == RS_OK &&
                 cl.n == ct.n;
            for (int k = 0; ok && k < ct.n; k++)
                ok = cl.feature[k] == ct.feature[k] && cl.dist[k] == ct.dist[k] &&
                     cl.share[k] == ct.share[k];
            for (int k = 0; k < ct.n; k++)
                shared += ct.share[k] < 1.0;
            if (!ok) {
                fprintf(stderr, "node %d, side %d: the lists change the contacts\n", v,
                        side);
                bad++;
            }
        }
    ENSURE(bad == 0);
    ENSURE(shared > 50);
    free(node);
    rs_cands_free(&cd);
    rs_contacts_free(&ct);
    rs_contacts_free(&cl);
    rs_surface_free(&s);
}

/* A mesh large enough that the list query fetches its candidates' records ahead
 * (mesh_query.c, RS_MESH_PREFETCH_MIN) and 4000 spheres in one query: through candidate
 * lists the contacts are those of the tree query, value for value, and the nearest of
 * each of the first 300 is the brute-force closest point of all triangles. */
static void large_mesh_lists_are_the_tree(void)
{
    poly_mesh pm;
    uv_sphere(&pm, 130, 130); /* 33800 triangles */
    double(*T)[9] = malloc((size_t)pm.nf * 2 * sizeof *T);
    const int ntri = pm_triangles(&pm, T);
    ENSURE(ntri >= 32768);
    rs_surface s;
    if (load_pm(&pm, "large", &s) != RS_OK) {
        ENSURE(0);
        free(T);
        return;
    }
    enum { NP = 4000 };
    static double x[NP], y[NP], z[NP], r[NP];
    unsigned long long seed = 41;
    for (int i = 0; i < NP; i++) {
        double d[3], l2 = 0.0;
        for (int k = 0; k < 3; k++) {
            d[k] = 2.0 * (double)(rs_test_xorshift(&seed) >> 11) / 9007199254740992.0 - 1.0;
            l2 += d[k] * d[k];
        }
        const double u = (double)(rs_test_xorshift(&seed) >> 11) / 9007199254740992.0;
        const double rho = (0.97 + 0.06 * u) / sqrt(l2); /* inside and outside */
        x[i] = rho * d[0], y[i] = rho * d[1], z[i] = rho * d[2];
        r[i] = 0.02;
    }
    rs_query q;
    memset(&q, 0, sizeof q);
    q.n = NP;
    q.slave.x = x, q.slave.y = y, q.slave.z = z, q.slave.radius = r;
    q.gap_max = 0.01;
    q.dist_min = -0.05;
    rs_contacts ct, cl;
    memset(&ct, 0, sizeof ct);
    memset(&cl, 0, sizeof cl);
    rs_cands cd;
    memset(&cd, 0, sizeof cd);
    rs_error e;
    ENSURE(rs_surface_query(&s, &q, &ct, &e) == RS_OK);
    ENSURE(rs_surface_candidates(&s, &q, 0.005, &cd, &e) == RS_OK);
    const int **lists = malloc(NP * sizeof *lists);
    int *counts = malloc(NP * sizeof *counts);
    for (int i = 0; i < NP; i++) {
        lists[i] = cd.ids + cd.off[i];
        counts[i] = cd.off[i + 1] - cd.off[i];
    }
    ENSURE(rs_surface_query_among(&s, &q, lists, counts, &cl, &e) == RS_OK);
    ENSURE(ct.n > NP / 2);
    ENSURE(cl.n == ct.n);
    int same = cl.n == ct.n;
    for (int k = 0; same && k < ct.n; k++) {
        same = cl.point[k] == ct.point[k] && cl.feature[k] == ct.feature[k] &&
               cl.dist[k] == ct.dist[k] && cl.share[k] == ct.share[k];
        for (int d = 0; d < 3; d++)
            same = same && cl.xm[d][k] == ct.xm[d][k] && cl.nrm[d][k] == ct.nrm[d][k];
    }
    ENSURE(same);
    /* the nearest contact of each of the first 300 spheres against all triangles */
    int k = 0, bad = 0;
    for (int i = 0; i < 300; i++) {
        const double p[3] = {x[i], y[i], z[i]};
        double cb[3] = {0, 0, 0};
        const double best = nearest_of_all((const double(*)[9])T, ntri, p, cb);
        int kbest = -1;
        for (; k < cl.n && cl.point[k] == i; k++)
            if (kbest < 0 || fabs(cl.dist[k]) < fabs(cl.dist[kbest]))
                kbest = k;
        if (kbest < 0) { /* none only outside, beyond the gap limit */
            bad += !(sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) > 1.0 &&
                     best >= r[i] + q.gap_max - 1e-9);
            continue;
        }
        const double xm[3] = {cl.xm[0][kbest], cl.xm[1][kbest], cl.xm[2][kbest]};
        if (!(fabs(fabs(cl.dist[kbest]) - best) <= 1e-12 && dist3(xm, cb) <= 1e-9))
            bad++;
    }
    ENSURE(bad == 0);
    free(lists);
    free(counts);
    free(T);
    rs_cands_free(&cd);
    rs_contacts_free(&ct);
    rs_contacts_free(&cl);
    rs_surface_free(&s);
}

/* One-sided, from outside a closed convex mesh: exactly one contact at every point, the
 * brute-force closest point. */
static void one_contact_outside_convex(void)
{
    poly_mesh m;
    uv_sphere(&m, 12, 24);
    const int ok = brute_force_case(&m, "sphere1", 1, 0.0, 0, 1);
    rs_surface s;
    rs_error e;
    ENSURE(ok);
    ENSURE(load("*SURFACE, TYPE=MESH, NAME=s, FILE=sphere1.off, SIDES=1\n", &s, &e) ==
           RS_OK);
    unsigned long long seed = 5;
    rs_contacts c;
    memset(&c, 0, sizeof c);
    int bad = 0;
    for (int k = 0; k < 2000; k++) {
        double dir[3];
        for (int d = 0; d < 3; d++)
            dir[d] =
                2.0 * (double)(rs_test_xorshift(&seed) >> 11) / 9007199254740992.0 - 1.0;
        const double l = rs_norm3(dir);
        const double rad = 1.02 + 0.2 * k / 2000.0;
        double p[3] = {rad * dir[0] / l, rad * dir[1] / l, rad * dir[2] / l};
        query(&s, 1, p, p + 1, p + 2, NULL, 1.0, &c);
        bad += c.n != 1 || !(c.dist[0] > 0.0);
    }
    rs_contacts_free(&c);
    rs_surface_free(&s);
    pm_free(&m);
    ENSURE(bad == 0);
}

/* Six coplanar triangles around a vertex: a point exactly above the vertex, above each
 * shared edge and anywhere above the fan has one contact, n = +z, dist = height,
 * exactly as on the plane. */
static void flat_fan_one_contact(void)
{
    poly_mesh m;
    apex_fan(&m, 6, 1.0, 0.0);
    rs_surface s;
    ENSURE(load_pm(&m, "fan", &s) == RS_OK);
    rs_contacts c;
    memset(&c, 0, sizeof c);
    const double h = 0.0123;
    double x = 0, y = 0, z = h;
    query(&s, 1, &x, &y, &z, NULL, 0.1, &c);
    ENSURE(c.n == 1);
    ENSURE(c.dist[0] == h && c.nrm[2][0] == 1.0 && c.xm[2][0] == 0.0);
    /* above each shared edge, at several places along it */
    for (int k = 0; k < 6; k++)
        for (int j = 1; j < 5; j++) {
            x = 0.2 * j * cos(RS_PI * k / 3.0);
            y = 0.2 * j * sin(RS_PI * k / 3.0);
            query(&s, 1, &x, &y, &z, NULL, 0.1, &c);
            ENSURE(c.n == 1);
            ENSURE_NEAR(c.dist[0], h, 1e-15);
            ENSURE_NEAR(c.nrm[2][0], 1.0, 1e-15);
        }
    unsigned long long seed = 3;
    for (int k = 0; k < 5000; k++) {
        x = 1.6 * (double)(rs_test_xorshift(&seed) >> 11) / 9007199254740992.0 - 0.8;
        y = 1.6 * (double)(rs_test_xorshift(&seed) >> 11) / 9007199254740992.0 - 0.8;
        if (hypot(x, y) > 0.85)
            continue;
        query(&s, 1, &x, &y, &z, NULL, 0.1, &c);
        ENSURE(c.n == 1);
        ENSURE_NEAR(c.dist[0], h, 1e-15);
    }
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* Inside the apex of a 12-facet cone (half angle 30 deg), a point on the axis has one
 * contact per facet, each at its closed-form distance z sin(30 deg) (apex at the
 * origin, the point at height z). */
static void cone_apex_contact_per_face(void)
{
    poly_mesh m;
    apex_fan(&m, 12, tan(RS_PI / 6.0), 1.0); /* normals toward the inside (the axis) */
    rs_surface s;
    ENSURE(load_pm(&m, "cone", &s) == RS_OK);
    rs_contacts c;
    memset(&c, 0, sizeof c);
    double x = 0, y = 0, z = 0.3, r = 0.2;
    query(&s, 1, &x, &y, &z, &r, 0.0, &c);
    ENSURE(c.n == 12);
    /* a facet's plane is at angle 30 deg to the axis only at its middle; its distance
     * from the axis point is z sin(a) with tan(a) = tan(30 deg) cos(15 deg) */
    const double a = atan(tan(RS_PI / 6.0) * cos(RS_PI / 12.0));
    for (int k = 0; k < 12; k++) {
        ENSURE(RS_FEATURE_TYPE(c.feature[k]) == RS_FEAT_FACE);
        ENSURE_NEAR(c.dist[k], z * sin(a), 1e-14);
    }
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* A unit cube of quads: at a convex edge one edge contact, beyond a corner one vertex
 * contact, above a face one face contact; inside near an edge only the shallower face
 * (a penetration). */
static void cube_edges_and_corners(void)
{
    const char *cube =
        "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
        "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 1 2 6 5\n4 0 4 7 3\n";
    write_text("cube.off", cube);
    rs_surface s;
    rs_error e;
    ENSURE(load("*SURFACE, TYPE=MESH, NAME=cube, FILE=cube.off, SIDES=1\n", &s, &e) ==
           RS_OK);
    rs_contacts c;
    memset(&c, 0, sizeof c);
    double x = 1.1, y = 0.4, z = 1.2; /* beyond the edge x = 1, z = 1 */
    query(&s, 1, &x, &y, &z, NULL, 1.0, &c);
    ENSURE(c.n == 1 && RS_FEATURE_TYPE(c.feature[0]) == RS_FEAT_EDGE);
    ENSURE_NEAR(c.dist[0], hypot(0.1, 0.2), 1e-15);
    /* the edge x = 1, z = 1 belongs to elements 2 (top) and 5 (x = 1): its facet is one
     * of them */
    {
        const int k = rs_surface_facet_index(&s, c.feature[0]);
        ENSURE(k == 1 || k == 4);
    }
    x = 1.1, y = 1.2, z = 1.3; /* beyond the corner (1, 1, 1) */
    query(&s, 1, &x, &y, &z, NULL, 1.0, &c);
    ENSURE(c.n == 1 && RS_FEATURE_TYPE(c.feature[0]) == RS_FEAT_VERTEX);
    ENSURE_NEAR(c.dist[0], sqrt(0.01 + 0.04 + 0.09), 1e-15);
    x = 0.3, y = 0.6, z = 1.05; /* above the top face, off its diagonal */
    query(&s, 1, &x, &y, &z, NULL, 1.0, &c);
    ENSURE(c.n == 1 && RS_FEATURE_TYPE(c.feature[0]) == RS_FEAT_FACE);
    ENSURE_NEAR(c.dist[0], 0.05, 1e-15);
    x = 0.98, y = 0.5, z = 0.95; /* inside, nearer the side x = 1 */
    query(&s, 1, &x, &y, &z, NULL, 0.0, &c);

    ENSURE(c.n == 1 && RS_FEATURE_TYPE(c.feature[0]) == RS_FEAT_FACE);
    ENSURE_NEAR(c.dist[0], -0.02, 1e-15);
    ENSURE_NEAR(c.nrm[0][0], 1.0, 1e-15);
    { /* the same with every face within reach: the deeper faces give no contact */
        rs_query q;
        memset(&q, 0, sizeof q);
        q.n = 1;
        q.slave.x = &x;
        q.slave.y = &y;
        q.slave.z = &z;
        q.gap_max = 0.0;
        q.dist_min = -1.5;
        c.n = 0;
        ENSURE(rs_surface_query(&s, &q, &c, &e) == RS_OK);
        ENSURE(c.n == 1);
        ENSURE_NEAR(c.dist[0], -0.02, 1e-15);
    }
    /* history passes from a face to its own edge, not to a far one */
    const int f0 = c.feature[0];
    x = 1.1, y = 0.4, z = 1.2;
    query(&s, 1, &x, &y, &z, NULL, 1.0, &c);
    ENSURE(rs_surface_adjacent(&s, f0, c.feature[0]) == 1);
    x = -0.1, y = 0.4, z = -0.2;
    query(&s, 1, &x, &y, &z, NULL, 1.0, &c);
    ENSURE(c.n == 1 && rs_surface_adjacent(&s, f0, c.feature[0]) == 0);
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* SCALE and the placement line: a unit quad scaled by 2 and placed with its x axis along
 * global y at (1, 2, 3) gives the plane x = 1 with normal +x... from its winding. */
static void scale_and_placement(void)
{
    const char *quad = "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";
    write_text("quad.off", quad);
    rs_surface s;
    rs_error e;
    /* a = (1,2,3); local x along global y; local y along global z: local z = global x */
    ENSURE(load("*SURFACE, TYPE=MESH, NAME=q, FILE=quad.off, SCALE=2, SIDES=1\n"
                "1, 2, 3, 1, 3, 3, 1, 2, 4\n",
                &s, &e) == RS_OK);
    double lo[3], hi[3];
    rs_surface_bounds(&s, lo, hi);
    ENSURE(lo[0] == 1.0 && hi[0] == 1.0 && lo[1] == 2.0 && hi[1] == 4.0 && lo[2] == 3.0 &&
           hi[2] == 5.0);
    rs_contacts c;
    memset(&c, 0, sizeof c);
    double x = 1.5, y = 3.0, z = 4.0;
    query(&s, 1, &x, &y, &z, NULL, 1.0, &c);
    ENSURE(c.n == 1);
    ENSURE_NEAR(c.dist[0], 0.5, 1e-15);
    ENSURE_NEAR(c.nrm[0][0], 1.0, 1e-15);
    /* the FACETED frame: x is the normal, so t1 = global z projected, t2 = n x t1 */
    ENSURE_NEAR(c.t1[2][0], 1.0, 1e-15);
    ENSURE_NEAR(c.t2[1][0], -1.0, 1e-15);
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* A pose moves the mesh rigidly: the query of a moved point against the moved mesh is
 * the reference query moved. */
static void pose_moves_the_mesh(void)
{
    poly_mesh m;
    torus(&m, 16, 8, 1.0, 0.3);
    char path[128];
    snprintf(path, sizeof path, "%s/tp.off", tmpdir);
    write_off(&m, path);
    pm_free(&m);
    rs_surface s;
    rs_error e;
    ENSURE(load("*SURFACE, TYPE=MESH, NAME=t, FILE=tp.off, SIDES=1\n", &s, &e) == RS_OK);
    rs_pose pose;
    const double ax[3] = {0.3, -0.5, 0.8};
    const double l = rs_norm3(ax);
    const double u[3] = {ax[0] / l, ax[1] / l, ax[2] / l};
    rs_rotation_matrix(u, 0.7, pose.R);
    pose.T[0] = 0.4;
    pose.T[1] = -1.0;
    pose.T[2] = 2.0;
    const double X[3] = {1.25, 0.1, 0.2};
    double x[3];
    rs_pose_to_global(&pose, X, x);
    rs_contacts c0, c1;
    memset(&c0, 0, sizeof c0);
    memset(&c1, 0, sizeof c1);
    query(&s, 1, X, X + 1, X + 2, NULL, 1.0, &c0);
    rs_query q;
    memset(&q, 0, sizeof q);
    q.n = 1;
    q.slave.x = x;
    q.slave.y = x + 1;
    q.slave.z = x + 2;
    q.pose = &pose;
    q.gap_max = 1.0;
    q.dist_min = -INFINITY;
    ENSURE(rs_surface_query(&s, &q, &c1, &e) == RS_OK);
    ENSURE(c0.n >= 1 && c0.n == c1.n);
    for (int k = 0; k < c0.n; k++) {
        ENSURE(c0.feature[k] == c1.feature[k]);
        ENSURE_NEAR(c0.dist[k], c1.dist[k], 1e-14);
        const double xm0[3] = {c0.xm[0][k], c0.xm[1][k], c0.xm[2][k]};
        const double n0[3] = {c0.nrm[0][k], c0.nrm[1][k], c0.nrm[2][k]};
        double xm[3], n[3];
        rs_pose_to_global(&pose, xm0, xm);
        rs_pose_rotate(&pose, n0, n);
        for (int d = 0; d < 3; d++) {
            ENSURE_NEAR(c1.xm[d][k], xm[d], 1e-14);
            ENSURE_NEAR(c1.nrm[d][k], n[d], 1e-14);
        }
    }
    rs_contacts_free(&c0);
    rs_contacts_free(&c1);
    rs_surface_free(&s);
}

/* The Hertz-like resultant sum(w delta^1.5 n) of a sphere's contacts, delta = radius -
 * dist, w the contact's share; the sorted features into feat (up to 64) when not NULL.
 * Returns the number of contacts. */
static rs_contacts res_k; /* resultant_of's contacts, kept between calls */

static int resultant_of(const rs_surface *s, const double c[3], double r, double F[3],
                        int *feat)
{
    rs_contacts k = res_k;
    query(s, 1, c, c + 1, c + 2, &r, 0.0, &k);
    res_k = k;
    F[0] = F[1] = F[2] = 0.0;
    for (int i = 0; i < k.n; i++) {
        const double d = r - k.dist[i];
        for (int a = 0; a < 3; a++)
            F[a] += k.share[i] * (d > 0.0 ? pow(d, 1.5) : 0.0) * k.nrm[a][i];
    }
    const int n = k.n < 64 ? k.n : 64;
    for (int i = 0; feat && i < n; i++) { /* insertion sort */
        int j = i;
        for (; j > 0 && feat[j - 1] > k.feature[i]; j--)
            feat[j] = feat[j - 1];
        feat[j] = k.feature[i];
    }
    return n;
}

static void resultant(const rs_surface *s, const double c[3], double r, double F[3])
{
    resultant_of(s, c, r, F, NULL);
}

/* |F(b) - F(a)| / |F(a)| for the resultant at sphere centres a and b; infinite where
 * the sphere at a has no force (the case then tests nothing). */
static double jump_across(const rs_surface *s, double r, const double a[3],
                          const double b[3])
{
    double Fa[3], Fb[3];
    resultant(s, a, r, Fa);
    resultant(s, b, r, Fb);
    const double d[3] = {Fb[0] - Fa[0], Fb[1] - Fa[1], Fb[2] - Fa[2]};
    return rs_norm3(Fa) > 0.0 ? rs_norm3(d) / rs_norm3(Fa) : INFINITY;
}

/* The cylinder of nh x nz planar quads of radius 1, |z| <= 1, normals toward the axis
 * (inside) or away from it. */
static void cylinder_quads(poly_mesh *m, int nh, int nz, int inside)
{
    pm_init(m, nh * (nz + 1), nh * nz);
    for (int i = 0; i < nh; i++)
        for (int k = 0; k <= nz; k++) {
            double *p = m->xyz + 3 * (i * (nz + 1) + k);
            p[0] = cos(2 * RS_PI * i / nh);
            p[1] = sin(2 * RS_PI * i / nh);
            p[2] = -1.0 + 2.0 * k / nz;
        }
    for (int i = 0; i < nh; i++)
        for (int k = 0; k < nz; k++) {
            const int a = i * (nz + 1) + k, b = ((i + 1) % nh) * (nz + 1) + k;
            if (inside)
                pm_add(m, 4, a, a + 1, b + 1, b);
            else
                pm_add(m, 4, a, b, b + 1, a + 1);
        }
}

/* No force jumps at edges: a sphere pressed on a cylinder of 64 x 8 planar quads, from
 * outside (convex hoop edges: face, edge and face contacts) and from inside (concave:
 * one and two face contacts), at every hoop edge and across the flat edges along the
 * axis. The resultant of Hertz-like forces 1e-12 before and after each edge differs
 * by less than 1e-9 of itself, where the faces' normals differ by 5.6 degrees. */
static void no_force_jump_at_edges(void)
{
    const int nh = 64, nz = 8;
    for (int inside = 0; inside < 2; inside++) {
        poly_mesh m;
        cylinder_quads(&m, nh, nz, inside);
        rs_surface s;
        ENSURE(load_pm(&m, inside ? "cyl_in" : "cyl_out", &s) == RS_OK);
        const double r = 0.2, rc = inside ? 1.0 - r + 0.01 : 1.0 + r - 0.01;
        double worst = 0.0;
        for (int i = 0; i < nh; i++) {
            const double th = 2 * RS_PI * i / nh, e = 1e-12;
            /* across the hoop edge at th */
            const double z = 0.1 + 0.01 * i / nh;
            const double ha[3] = {rc * cos(th - e), rc * sin(th - e), z};
            const double hb[3] = {rc * cos(th + e), rc * sin(th + e), z};
            worst = fmax(worst, jump_across(&s, r, ha, hb));
            /* across the flat edge z = 0.25 along the axis, mid-face in the hoop */
            const double t = th + RS_PI / nh;
            const double za[3] = {rc * cos(t), rc * sin(t), 0.25 - e};
            const double zb[3] = {rc * cos(t), rc * sin(t), 0.25 + e};
            worst = fmax(worst, jump_across(&s, r, za, zb));
        }
        rs_surface_free(&s);
        if (!(worst < 1e-9))
            fprintf(stderr, "%s: largest relative jump %.3g\n",
                    inside ? "inside" : "outside", worst);
        ENSURE(worst < 1e-9);
    }
}

/* ---- force continuity along paths --------------------------------------------------- */

typedef struct path_scan {
    double worst; /* the largest jump of the resultant, relative to the path's largest */
    double fmax;  /* the path's largest resultant */
    int changes;  /* changes of the contact set found and bisected */
    int births;   /* of them, contacts that enter while the sphere already overlaps them */
} path_scan;

/* Along the polyline p[0 .. n) (the sphere's centres), wherever the set of contacts
 * changes between two points the change is bisected to 1e-11 of the step, and the
 * resultants either side are compared (relative to the largest resultant on the path).
 * A contact that appears with a positive overlap, where it is the whole change, counts as
 * a birth: without shares the force would jump there. */
static void scan_path(const rs_surface *s, double r, const double (*p)[3], int n,
                      path_scan *ps)
{
    int fa[64], fb[64], fm[64];
    double Fa[3], Fb[3], Fm[3];
    int na = resultant_of(s, p[0], r, Fa, fa);
    ps->fmax = fmax(ps->fmax, rs_norm3(Fa));
    double jumps = 0.0;
    for (int k = 1; k < n; k++) {
        const int nb = resultant_of(s, p[k], r, Fb, fb);
        ps->fmax = fmax(ps->fmax, rs_norm3(Fb));
        int same = na == nb;
        for (int i = 0; same && i < na; i++)
            same = fa[i] == fb[i];
        if (!same) {
            double lo = 0.0, hi = 1.0, Flo[3], Fhi[3];
            int nlo = na, nhi = nb, flo[64], fhi[64];
            memcpy(Flo, Fa, sizeof Flo);
            memcpy(Fhi, Fb, sizeof Fhi);
            memcpy(flo, fa, sizeof flo);
            memcpy(fhi, fb, sizeof fhi);
            while (hi - lo > 1e-11) {
                const double t = 0.5 * (lo + hi);
                double x[3];
                for (int d = 0; d < 3; d++)
                    x[d] = p[k - 1][d] + t * (p[k][d] - p[k - 1][d]);
                const int nm = resultant_of(s, x, r, Fm, fm);
                int as_lo = nm == nlo;
                for (int i = 0; as_lo && i < nm; i++)
                    as_lo = fm[i] == flo[i];
                if (as_lo) {
                    lo = t;
                    memcpy(Flo, Fm, sizeof Flo);
                } else {
                    hi = t;
                    nhi = nm;
                    memcpy(Fhi, Fm, sizeof Fhi);
                    memcpy(fhi, fm, sizeof fhi);
                }
            }
            const double d[3] = {Fhi[0] - Flo[0], Fhi[1] - Flo[1], Fhi[2] - Flo[2]};
            jumps = fmax(jumps, rs_norm3(d));
            ps->changes++;
            /* a birth: the contact set grew by one, which overlaps the sphere */
            if (nhi == nlo + 1) {
                double x[3];
                for (int d2 = 0; d2 < 3; d2++)
                    x[d2] = p[k - 1][d2] + hi * (p[k][d2] - p[k - 1][d2]);
                rs_contacts c;
                memset(&c, 0, sizeof c);
                query(s, 1, x, x + 1, x + 2, &r, 0.0, &c);
                for (int i = 0; i < c.n; i++) {
                    int old = 0;
                    for (int j = 0; j < nlo; j++)
                        old |= flo[j] == c.feature[i];
                    if (!old && c.dist[i] < r - 1e-9 * r)
                        ps->births++;
                }
                rs_contacts_free(&c);
            }
        }
        na = nb;
        memcpy(fa, fb, sizeof fa);
        memcpy(Fa, Fb, sizeof Fa);
    }
    ps->worst = fmax(ps->worst, jumps);
}

/* Path p[0 .. n) of a sphere of radius r over s (scan_path): its largest jump is below
 * 1e-9 of its largest resultant; its changes and births are added to *tot. what and
 * index name the path when it fails. */
static void check_path(const rs_surface *s, double r, const double (*p)[3], int n,
                       const char *what, double index, path_scan *tot)
{
    path_scan one = {0.0, 0.0, 0, 0};
    scan_path(s, r, p, n, &one);
    tot->changes += one.changes;
    tot->births += one.births;
    if (!(one.worst < 1e-9 * one.fmax))
        fprintf(stderr, "%s %g: jump %.3g of %.3g\n", what, index, one.worst, one.fmax);
    ENSURE(one.worst < 1e-9 * one.fmax);
}

/* The cylinder of nh x nz planar quads of radius 1, |z| <= 1, normals toward the axis,
 * read as surface NAME. */
static int inner_cylinder(int nh, int nz, const char *name, rs_surface *s)
{
    poly_mesh m;
    cylinder_quads(&m, nh, nz, 1);
    return load_pm(&m, name, s);
}

/* The resultant is continuous everywhere along paths that cross concave folds (where
 * a face's contact begins while the sphere already overlaps it: shares), flat and convex
 * edges, and vertices: inside tessellated cylinders (5.6 and 1.4 degree folds, paths
 * around the hoop at three depths and oblique ones), over a random bumpy height field,
 * along a concave polyline profile (SEGMENTS) and over a polyline bowl (REVOLUTION). Each
 * change of the contact set is bisected; the jump there is below 1e-9 of the path's force.
 * The cases are built to contain births, where the force would jump by the new contact's
 * whole force without shares. */
static void no_force_jump_along_paths(void)
{
    enum { NP = 600 };
    static double p[NP][3];
    path_scan ps = {0.0, 0.0, 0, 0};
    const double r = 0.2;
    for (int c = 0; c < 2; c++) {
        const int nh = c ? 256 : 64;
        rs_surface s;
        ENSURE(inner_cylinder(nh, 4, c ? "cyl256" : "cyl64", &s) == RS_OK);
        for (int depth = 0; depth < 3; depth++) {
            const double pen = depth == 0 ? 0.01 : depth == 1 ? 1e-3 : 1e-4;
            /* around the hoop, then a helix that also crosses the flat edges in z */
            for (int h = 0; h < 2; h++) {
                for (int k = 0; k < NP; k++) {
                    const double t = (double)k / (NP - 1);
                    const double th = 0.013 + t * 5.0 * 2 * RS_PI / nh;
                    const double rc = 1.0 - r + pen;
                    p[k][0] = rc * cos(th);
                    p[k][1] = rc * sin(th);
                    p[k][2] = h ? -0.9 + 1.8 * t : 0.1;
                }
                check_path(&s, r, (const double(*)[3])p, NP,
                           nh == 64 ? "64-facet cylinder, overlap"
                                    : "256-facet cylinder, overlap",
                           pen, &ps);
            }
        }
        rs_surface_free(&s);
    }
    /* a random bumpy height field (saddles, concave and convex folds), the sphere riding
     * 0.002, 0.01 and 0.03 into its smooth part along 15 random paths each */
    {
        poly_mesh m;
        height_field(&m, 16, 7);
        rs_surface s;
        ENSURE(load_pm(&m, "bumps", &s) == RS_OK);
        unsigned long long seed = 99;
        const double pens[3] = {0.002, 0.01, 0.03};
        for (int path = 0; path < 45; path++) {
            const double pen = pens[path % 3];
            const double x0 = -0.7 + 1.4 * rs_test_urand(&seed),
                         y0 = -0.7 + 1.4 * rs_test_urand(&seed);
            const double x1 = -0.7 + 1.4 * rs_test_urand(&seed),
                         y1 = -0.7 + 1.4 * rs_test_urand(&seed);
            for (int k = 0; k < NP; k++) {
                const double t = (double)k / (NP - 1);
                const double x = x0 + t * (x1 - x0), y = y0 + t * (y1 - y0);
                p[k][0] = x;
                p[k][1] = y;
                p[k][2] = 0.1 * sin(3 * x) * cos(2 * y) + 0.01 + r - pen;
            }
            check_path(&s, r, (const double(*)[3])p, NP, "height field path", path, &ps);
        }
        rs_surface_free(&s);
    }
    /* a concave polyline: 36 LINEs around the inside of the unit circle, 10 degrees each */
    {
        char text[4096];
        int len = snprintf(text, sizeof text,
                           "*SURFACE, TYPE=SEGMENTS, NAME=ring\nSTART, 1, 0\n");
        for (int k = 1; k <= 36; k++)
            len += snprintf(text + len, sizeof text - (size_t)len, "LINE, %.17g, %.17g\n",
                            cos(2 * RS_PI * k / 36), sin(2 * RS_PI * k / 36));
        rs_surface s;
        rs_error e;
        ENSURE(load(text, &s, &e) == RS_OK);
        for (int depth = 0; depth < 2; depth++) {
            const double rc = 1.0 - r + (depth ? 1e-3 : 0.01);
            for (int k = 0; k < NP; k++) {
                const double th = 0.05 + 6.0 * (double)k / (NP - 1);
                p[k][0] = rc * cos(th);
                p[k][1] = rc * sin(th);
                p[k][2] = 0.0;
            }
            check_path(&s, r, (const double(*)[3])p, NP, "polyline, overlap",
                       depth ? 1e-3 : 0.01, &ps);
        }
        rs_surface_free(&s);
    }
    /* a REVOLUTION bowl whose profile is a polyline (LINEs of 1 to 5 degrees' slope
     * change, closed on the axis): 20 random straight paths over it, the sphere riding
     * 2e-4 or 1e-3 into it (measured vertically from the profile under its centre) */
    {
        const double rr = 0.05; /* this case's sphere, on a bowl of radius 0.24 */
        static const double prof[7][2] = {{0.0, 0.0},    {0.04, 0.001}, {0.08, 0.004},
                                          {0.12, 0.009}, {0.16, 0.016}, {0.20, 0.025},
                                          {0.24, 0.036}};
        char text[1024];
        int len = snprintf(text, sizeof text,
                           "*SURFACE, TYPE=REVOLUTION, NAME=bowl\n0, 0, 0, 0, 0, 1\n"
                           "START, 0, 0\n");
        for (int k = 1; k < 7; k++)
            len += snprintf(text + len, sizeof text - (size_t)len, "LINE, %.17g, %.17g\n",
                            prof[k][0], prof[k][1]);
        rs_surface s;
        rs_error e;
        ENSURE(load(text, &s, &e) == RS_OK);
        unsigned long long seed = 5;
        for (int path = 0; path < 20; path++) {
            const double pen = path % 2 ? 1e-3 : 2e-4;
            double a[2], b[2];
            for (int d = 0; d < 2; d++) {
                a[d] = -0.14 + 0.28 * rs_test_urand(&seed);
                b[d] = -0.14 + 0.28 * rs_test_urand(&seed);
            }
            for (int k = 0; k < NP; k++) {
                const double t = (double)k / (NP - 1);
                p[k][0] = a[0] + t * (b[0] - a[0]);
                p[k][1] = a[1] + t * (b[1] - a[1]);
                const double rho = hypot(p[k][0], p[k][1]);
                int j = 0;
                while (j < 5 && rho > prof[j + 1][0])
                    j++;
                const double f = (rho - prof[j][0]) / (prof[j + 1][0] - prof[j][0]);
                p[k][2] = prof[j][1] + f * (prof[j + 1][1] - prof[j][1]) + rr - pen;
            }
            check_path(&s, rr, (const double(*)[3])p, NP, "revolution bowl path", path,
                       &ps);
        }
        rs_surface_free(&s);
    }
    /* the paths did cross changes, births among them */
    ENSURE(ps.changes > 100);
    ENSURE(ps.births > 20);
}

/* Shares at a fold: in a shallow concave fold that the sphere straddles (a 1.4 degree
 * fold of the 256-quad cylinder, the sphere exactly above the edge), the two shares are
 * 1/2 each by symmetry; in a pocket whose fold lines the sphere does not reach (a corner
 * of a cube, 1e-3 to 3e-3 overlap on its faces) every share is 1 but for the coupling
 * ((a_i + a_j) / D)^16 of distant patches, below 1e-8 here. */
static void shares_at_folds(void)
{
    rs_surface s;
    ENSURE(inner_cylinder(256, 4, "cyl256s", &s) == RS_OK);
    const double r = 0.2, rc = 1.0 - r + 1e-3, th = 2 * RS_PI * 3 / 256;
    const double x = rc * cos(th), y = rc * sin(th), z = 0.3;
    rs_contacts c;
    memset(&c, 0, sizeof c);
    query(&s, 1, &x, &y, &z, &r, 0.0, &c);
    ENSURE(c.n == 2);
    for (int i = 0; i < c.n; i++)
        ENSURE_NEAR(c.share[i], 0.5, 1e-9);
    rs_surface_free(&s);
    /* the cube [0, 1]^3 seen from inside: a sphere in its corner at the origin */
    poly_mesh m;
    pm_init(&m, 8, 6);
    for (int v = 0; v < 8; v++) {
        m.xyz[3 * v] = v & 1;
        m.xyz[3 * v + 1] = (v >> 1) & 1;
        m.xyz[3 * v + 2] = (v >> 2) & 1;
    }
    /* winding with normals toward the inside */
    pm_add(&m, 4, 0, 1, 3, 2); /* z = 0 */
    pm_add(&m, 4, 4, 6, 7, 5); /* z = 1 */
    pm_add(&m, 4, 0, 4, 5, 1); /* y = 0 */
    pm_add(&m, 4, 2, 3, 7, 6); /* y = 1 */
    pm_add(&m, 4, 0, 2, 6, 4); /* x = 0 */
    pm_add(&m, 4, 1, 5, 7, 3); /* x = 1 */
    ENSURE(load_pm(&m, "incube", &s) == RS_OK);
    /* 1e-3, 2e-3 and 3e-3 into the faces x = 0, y = 0, z = 0 (off the quads' diagonals) */
    const double P[3] = {r - 1e-3, r - 2e-3, r - 3e-3};
    query(&s, 1, P, P + 1, P + 2, &r, 0.0, &c);
    ENSURE(c.n == 3);
    for (int i = 0; i < c.n; i++) {
        ENSURE(RS_FEATURE_TYPE(c.feature[i]) == RS_FEAT_FACE);
        int axis = 0;
        for (int d = 1; d < 3; d++)
            if (fabs(c.nrm[d][i]) > fabs(c.nrm[axis][i]))
                axis = d;
        ENSURE_NEAR(c.dist[i], P[axis], 1e-14);
        /* the sphere reaches no edge (they are 0.28 away), so contact k's weight is a_k^2
         * and its share a_k^2 / (a_k^2 + sum_j ((a_k + a_j) / D_kj)^16 a_j^2) over the
         * two other faces' feet */
        double foot[3][3], a[3], den = 0.0;
        for (int k = 0; k < 3; k++) {
            for (int d = 0; d < 3; d++)
                foot[k][d] = d == k ? 0.0 : P[d];
            a[k] = sqrt(r * r - P[k] * P[k]);
        }
        for (int k = 0; k < 3; k++) {
            const double D = dist3(foot[axis], foot[k]);
            den += (k == axis ? 1.0 : pow((a[axis] + a[k]) / D, 16)) * a[k] * a[k];
        }
        ENSURE_NEAR(c.share[i], a[axis] * a[axis] / den, 1e-15);
        ENSURE(c.share[i] > 1.0 - 1e-8);
    }
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* Bad files: each error names the file and what is wrong. */
static void expect_error(const char *file, const char *content, size_t len, const char *inp,
                         const char *want)
{
    char path[160];
    if (file) {
        snprintf(path, sizeof path, "%s/%s", tmpdir, file);
        FILE *f = fopen(path, "wb");
        if (len)
            fwrite(content, 1, len, f);
        fclose(f);
    }
    rs_surface s;
    rs_error e;
    const int rc = load(inp, &s, &e);
    if (rc == RS_OK || !strstr(e.msg, want)) {
        fprintf(stderr, "expected an error with '%s', got %d: %s\n", want, rc, e.msg);
        rs_test_current_failed = 1;
        if (rc == RS_OK)
            rs_surface_free(&s);
    }
}

static void bad_mesh_files(void)
{
    expect_error("empty.stl", "", 0, "*SURFACE, TYPE=MESH, NAME=a, FILE=empty.stl\n",
                 "empty.stl is empty");
    const char *broken = "solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n"
                         "   vertex 1 0\n";
    expect_error("broken.stl", broken, strlen(broken),
                 "*SURFACE, TYPE=MESH, NAME=a, FILE=broken.stl\n", "broken.stl");
    /* a binary STL announcing 10 facets that holds 1 */
    char bin[84 + 50];
    memset(bin, 0, sizeof bin);
    bin[80] = 10;
    expect_error("trunc.stl", bin, sizeof bin,
                 "*SURFACE, TYPE=MESH, NAME=a, FILE=trunc.stl\n", "trunc.stl");
    const char *nanoff = "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n";
    expect_error("nan.off", nanoff, strlen(nanoff),
                 "*SURFACE, TYPE=MESH, NAME=a, FILE=nan.off\n", "nan.off");
    expect_error(NULL, NULL, 0, "*SURFACE, TYPE=MESH, NAME=a, FILE=missing.stl\n",
                 "missing.stl");
    expect_error(NULL, NULL, 0, "*SURFACE, TYPE=MESH, NAME=a, FILE=.\n", "directory");
    const char *tri = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    expect_error("tri.off", tri, strlen(tri),
                 "*SURFACE, TYPE=MESH, NAME=a, FILE=tri.off, SCALE=-1\n", "SCALE > 0");
    expect_error(NULL, NULL, 0, "*SURFACE, TYPE=MESH, NAME=a, FILE=tri.off, SCALE=nan\n",
                 "s.inp:1");
    /* without FILE=, the surface file's own rigid part, here none */
    expect_error(NULL, NULL, 0, "*SURFACE, TYPE=MESH, NAME=a\n", "expected a rigid part");
    { /* text that is no file has no rigid part: FILE= is needed */
        rs_surface s;
        rs_error e;
        ENSURE(rs_surface_parse("*SURFACE, TYPE=MESH, NAME=a\n", "text", NULL, &s, &e) ==
               RS_ERR_PARSE);
        ENSURE(strstr(e.msg, "expected FILE=") != NULL);
    }
    expect_error("tri.xyz", tri, strlen(tri), "*SURFACE, TYPE=MESH, NAME=a, FILE=tri.xyz\n",
                 "unknown mesh format");
    const char *flat = "OFF\n3 1 0\n0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n";
    expect_error("flat.off", flat, strlen(flat),
                 "*SURFACE, TYPE=MESH, NAME=a, FILE=flat.off\n",
                 "every facet is degenerate");
    expect_error(NULL, NULL, 0, "*SURFACE, TYPE=MESH, NAME=a, FILE=tri.off\n1, 2, 3\n",
                 "placement");
}

/* An Abaqus rigid part: a unit cube of R3D4 elements whose nodes (numbered from 101)
 * come from an included file answers as the same cube read from OFF; an element naming
 * a missing node, another element type and a node defined twice are errors that name
 * file and line. */
static void abaqus_rigid_part(void)
{
    write_text("cube_nodes.inp",
               "** the nodes\n*NODE, NSET=all\n101, 0, 0, 0\n102, 1, 0, 0\n"
               "103, 1, 1, 0\n104, 0, 1, 0\n105, 0, 0, 1\n106, 1, 0, 1\n"
               "107, 1, 1, 1\n108, 0, 1, 1\n");
    write_text("cube.inp", "*HEADING\nrigid cube\n*INCLUDE, INPUT=cube_nodes.inp\n"
                           "*element, type=r3d4, elset=box\n1, 101, 104, 103, 102\n"
                           "2, 105, 106, 107, 108\n3, 101, 102, 106, 105\n"
                           "4, 103, 104, 108, 107\n5, 102, 103, 107, 106\n"
                           "6, 101, 105, 108, 104\n");
    rs_surface s;
    rs_error e;
    ENSURE(load("*SURFACE, TYPE=MESH, NAME=cube, FILE=cube.inp\n", &s, &e) == RS_OK);
    ENSURE(s.warning[0] == '\0'); /* closed and consistently wound */
    rs_contacts c;
    memset(&c, 0, sizeof c);
    double x = 1.1, y = 0.4, z = 1.2;
    query(&s, 1, &x, &y, &z, NULL, 1.0, &c);
    ENSURE(c.n == 1 && RS_FEATURE_TYPE(c.feature[0]) == RS_FEAT_EDGE);
    ENSURE_NEAR(c.dist[0], hypot(0.1, 0.2), 1e-15);
    x = 0.3, y = 0.6, z = 1.05;
    query(&s, 1, &x, &y, &z, NULL, 1.0, &c);
    ENSURE(c.n == 1 && c.feature[0] == RS_FEATURE(RS_FEAT_FACE, 1)); /* element 2 */
    ENSURE_NEAR(c.dist[0], 0.05, 1e-15);
    /* its facet: the part's node labels, and the unit square's bilinear shape functions
     * (1-x)(1-y), x(1-y), xy, (1-x)y at (0.3, 0.6) */
    {
        const double xm[3] = {c.xm[0][0], c.xm[1][0], c.xm[2][0]};
        int nodes[4];
        double xyz[12], sh[4];
        ENSURE(rs_surface_facet(&s, c.feature[0], xm, nodes, xyz, sh) == 4);
        ENSURE(nodes[0] == 105 && nodes[1] == 106 && nodes[2] == 107 && nodes[3] == 108);
        const double want[4] = {0.7 * 0.4, 0.3 * 0.4, 0.3 * 0.6, 0.7 * 0.6};
        for (int i = 0; i < 4; i++)
            ENSURE_NEAR(sh[i], want[i], 1e-15);
        ENSURE(xyz[3 * 2] == 1.0 && xyz[3 * 2 + 1] == 1.0 && xyz[3 * 2 + 2] == 1.0);
        /* six unit quads with outward axis normals; the contact's facet is element 2 */
        ENSURE(rs_surface_facet_count(&s) == 6);
        ENSURE(rs_surface_facet_index(&s, c.feature[0]) == 1);
        for (int k = 0; k < 6; k++) {
            double a, n[3];
            ENSURE(rs_surface_facet_area(&s, k, &a, n) == 0);
            ENSURE_NEAR(a, 1.0, 1e-15);
            ENSURE_NEAR(fabs(n[0]) + fabs(n[1]) + fabs(n[2]), 1.0, 1e-15);
        }
        double a, n[3];
        ENSURE(rs_surface_facet_area(&s, 1, &a, n) == 0 && n[2] == 1.0); /* the top */
        ENSURE(rs_surface_facet_area(&s, 6, &a, n) == -1);
        /* the display's triangles show their quads: each element twice */
        rs_trimesh tm;
        ENSURE(rs_surface_triangulate(&s, 1.0, 1, &tm, &e) == RS_OK);
        int seen[6] = {0, 0, 0, 0, 0, 0};
        ENSURE(tm.ntri == 12 && tm.cell != NULL);
        for (int t = 0; t < tm.ntri; t++)
            if (tm.cell[t] >= 0 && tm.cell[t] < 6)
                seen[tm.cell[t]]++;
        for (int k = 0; k < 6; k++)
            ENSURE(seen[k] == 2);
        rs_trimesh_free(&tm);
    }
    rs_contacts_free(&c);
    rs_surface_free(&s);
    /* the rigid part in the surface file itself, after its *SURFACE */
    ENSURE(load("*SURFACE, TYPE=MESH, NAME=plate, SIDES=2\n*NODE\n1, 0, 0, 0\n2, 2, 0, 0\n"
                "3, 2, 2, 0\n4, 0, 2, 0\n*ELEMENT, TYPE=R3D4, ELSET=plate\n1, 1, 2, 3, 4\n",
                &s, &e) == RS_OK);
    memset(&c, 0, sizeof c);
    x = 1.5, y = 0.5, z = -0.25;
    query(&s, 1, &x, &y, &z, NULL, 1.0, &c);
    ENSURE(c.n == 1 && c.feature[0] == RS_FEATURE(RS_FEAT_FACE, 0));
    ENSURE_NEAR(c.dist[0], 0.25, 1e-15);
    ENSURE_NEAR(c.nrm[2][0], -1.0, 1e-15);
    rs_contacts_free(&c);
    rs_surface_free(&s);
    write_text("miss.inp", "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 1, 1, 0\n"
                           "*ELEMENT, TYPE=R3D4\n7, 1, 2, 3, 999\n");
    ENSURE(load("*SURFACE, TYPE=MESH, NAME=m, FILE=miss.inp\n", &s, &e) != RS_OK);
    ENSURE(strstr(e.msg, "miss.inp:6: element 7 names node 999") != NULL);
    write_text("solid.inp", "*NODE\n1, 0, 0, 0\n*ELEMENT, TYPE=C3D8\n");
    ENSURE(load("*SURFACE, TYPE=MESH, NAME=m, FILE=solid.inp\n", &s, &e) != RS_OK);
    ENSURE(strstr(e.msg, "solid.inp:3:") && strstr(e.msg, "TYPE=C3D8"));
    write_text("twice.inp", "*NODE\n1, 0, 0, 0\n1, 1, 0, 0\n2, 0, 1, 0\n"
                            "*ELEMENT, TYPE=R3D3\n1, 1, 2, 1\n");
    ENSURE(load("*SURFACE, TYPE=MESH, NAME=m, FILE=twice.inp\n", &s, &e) != RS_OK);
    ENSURE(strstr(e.msg, "node 1 defined twice") != NULL);
}

/* Repairs are reported: a degenerate facet is dropped by its number, the open edges of a
 * sheet are counted (as information: tests/unit/test_mesh_boundary.c), and a surface
 * without a consistent orientation acts on both sides. */
static void repairs_are_reported(void)
{
    const char *txt = "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n2 0 0\n1 1 0\n"
                      "3 0 1 2\n3 0 1 3\n3 1 4 2\n";
    write_text("rep.off", txt);
    rs_surface s;
    rs_error e;
    ENSURE(load("*SURFACE, TYPE=MESH, NAME=r, FILE=rep.off\n", &s, &e) == RS_OK);
    ENSURE(strstr(s.warning, "dropped 1 degenerate facet (facet 2)") != NULL);
    ENSURE(strstr(s.info, "4 open boundary edges") != NULL);
    rs_surface_free(&s);
    /* a Moebius band: eight quads around a circle, the last joined with a half twist */
    char path[128];
    snprintf(path, sizeof path, "%s/mob.off", tmpdir);
    FILE *f = fopen(path, "w");
    fprintf(f, "OFF\n16 16 0\n");
    for (int i = 0; i < 8; i++)
        for (int k = 0; k < 2; k++) {
            const double u = 2 * RS_PI * i / 8, w = k ? 0.3 : -0.3;
            fprintf(f, "%.17g %.17g %.17g\n", (1 + w * cos(u / 2)) * cos(u),
                    (1 + w * cos(u / 2)) * sin(u), w * sin(u / 2));
        }
    for (int i = 0; i < 8; i++) {
        const int a = 2 * i, b = 2 * i + 1;
        const int c = i < 7 ? 2 * (i + 1) : 1, d = i < 7 ? 2 * (i + 1) + 1 : 0;
        fprintf(f, "3 %d %d %d\n3 %d %d %d\n", a, c, d, a, d, b);
    }
    fclose(f);
    ENSURE(load("*SURFACE, TYPE=MESH, NAME=m, FILE=mob.off\n", &s, &e) == RS_OK);
    ENSURE(s.sides == 2 && strstr(s.warning, "no consistent orientation") != NULL);
    rs_surface_free(&s);
}

/* The facet under each contact (rs_surface_facet): its nodes interpolated with the
 * shape functions give the contact's closest point, the shapes sum to 1 and are not
 * negative, a face's nodes lie in its tangent plane, an edge's facet has two nodes with
 * weight and a vertex's one, at the closest point. Quads (the torus) have 4 nodes,
 * triangles (the rounded box) 3. */
static int facet_case(poly_mesh *pm, const char *name, int want_nn, int nodes_in_file)
{
    rs_surface s;
    if (load_pm(pm, name, &s) != RS_OK)
        return 0;
    int nnode = -1, ok = 1;
    ok &= rs_surface_facet_size(&s, &nnode) == want_nn;
    ok &= nnode == nodes_in_file;
    enum { NP = 400 };
    double x[NP], y[NP], z[NP], r[NP];
    for (int i = 0; i < NP; i++) {
        x[i] = 2.6 * (2 * urand() - 1);
        y[i] = 2.6 * (2 * urand() - 1);
        z[i] = 1.6 * (2 * urand() - 1);
        r[i] = 0.05;
    }
    rs_contacts c;
    rs_error e;
    memset(&c, 0, sizeof c);
    rs_contacts_reserve(&c, 64, &e);
    query(&s, NP, x, y, z, r, 0.4, &c);
    int counted[3] = {0, 0, 0};
    for (int k = 0; k < c.n && ok; k++) {
        const double xm[3] = {c.xm[0][k], c.xm[1][k], c.xm[2][k]};
        const double n[3] = {c.nrm[0][k], c.nrm[1][k], c.nrm[2][k]};
        int nodes[4];
        double xyz[12], sh[4];
        const int nn = rs_surface_facet(&s, c.feature[k], xm, nodes, xyz, sh);
        const int type = RS_FEATURE_TYPE(c.feature[k]);
        counted[type]++;
        if (nn != want_nn) {
            fprintf(stderr, "%s: contact %d: %d nodes\n", name, k, nn);
            ok = 0;
            break;
        }
        double sum = 0.0, p[3] = {0, 0, 0};
        int weighted = 0;
        for (int i = 0; i < nn; i++) {
            ok &= nodes[i] >= 1 && nodes[i] <= nnode;
            ok &= sh[i] >= -1e-12;
            sum += sh[i];
            weighted += sh[i] > 1e-12;
            for (int d = 0; d < 3; d++)
                p[d] += sh[i] * xyz[3 * i + d];
            if (type == RS_FEAT_FACE) {
                const double off = (xyz[3 * i] - xm[0]) * n[0] +
                                   (xyz[3 * i + 1] - xm[1]) * n[1] +
                                   (xyz[3 * i + 2] - xm[2]) * n[2];
                ok &= fabs(off) < 1e-12;
            }
        }
        ok &= fabs(sum - 1.0) < 1e-12;
        ok &= dist3(p, xm) < 1e-12;
        if (type == RS_FEAT_EDGE)
            ok &= weighted <= 2;
        if (type == RS_FEAT_VERTEX)
            ok &= weighted == 1;
        if (!ok)
            fprintf(stderr,
                    "%s: contact %d (type %d): sum %.17g, |N x - xm| %.3g, %d weighted\n",
                    name, k, type, sum, dist3(p, xm), weighted);
    }
    /* every kind of feature was met */
    ok &= counted[0] > 0 && counted[1] > 0 && counted[2] > 0;
    if (!ok)
        fprintf(stderr, "%s: faces %d, edges %d, vertices %d\n", name, counted[0],
                counted[1], counted[2]);
    rs_contacts_free(&c);
    rs_surface_free(&s);
    return ok;
}

static void facets_under_contacts(void)
{
    poly_mesh m;
    torus(&m, 32, 16, 1.0, 0.3);
    ENSURE(facet_case(&m, "ftorus", 4, 32 * 16));
    rounded_box(&m, 8, 0.3);
    const int shared =
        6 * 9 * 9 - 12 * 9 + 8; /* the faces' grids share edges and corners */
    ENSURE(facet_case(&m, "fbox", 3, shared));
    /* the analytic kinds have no facets */
    rs_surface s;
    rs_error e;
    ENSURE(load("*SURFACE, TYPE=CYLINDER, NAME=p\n0, 0, 0, 1, 0, 0\n0, -1, 0\n"
                "START, -1, 0\nLINE, 1, 0\n",
                &s, &e) == RS_OK);
    int nodes[4];
    double xyz[12], sh[4], xm[3] = {0, 0, 0};
    ENSURE(rs_surface_facet_size(&s, NULL) == 0);
    ENSURE(rs_surface_facet(&s, RS_FEATURE(RS_FEAT_FACE, 0), xm, nodes, xyz, sh) == 0);
    ENSURE(rs_surface_facet_count(&s) == 0);
    ENSURE(rs_surface_facet_index(&s, RS_FEATURE(RS_FEAT_FACE, 0)) == -1);
    rs_surface_free(&s);
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/rs_test_mesh_XXXXXX");
    if (!mkdtemp(tmpdir))
        return 1;
    RS_RUN(brute_force_meshes);
    RS_RUN(large_mesh_lists_are_the_tree);
    RS_RUN(lists_keep_the_folds_of_shares);
    RS_RUN(one_contact_outside_convex);
    RS_RUN(flat_fan_one_contact);
    RS_RUN(cone_apex_contact_per_face);
    RS_RUN(cube_edges_and_corners);
    RS_RUN(scale_and_placement);
    RS_RUN(pose_moves_the_mesh);
    RS_RUN(bad_mesh_files);
    RS_RUN(repairs_are_reported);
    RS_RUN(abaqus_rigid_part);
    RS_RUN(no_force_jump_at_edges);
    RS_RUN(no_force_jump_along_paths);
    RS_RUN(shares_at_folds);
    RS_RUN(facets_under_contacts);
    rs_contacts_free(&res_k);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    if (system(cmd) != 0)
        return 1;
    return rs_test_summary();
}
