/* MESH surfaces (src/faceted/): a continuous resultant along paths through tessellated
 * cylinders, a bumpy field and a concave polyline, every change of the contact set
 * bisected, and the shares at concave folds (docs/conventions.md, "Shares at concave
 * folds"). */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */
#include "mesh_fixture.h"

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

int main(void)
{
    if (!mesh_fixture_begin("mesh_continuity"))
        return 1;
    RS_RUN(no_force_jump_at_edges);
    RS_RUN(no_force_jump_along_paths);
    RS_RUN(shares_at_folds);
    rs_contacts_free(&res_k);
    if (!mesh_fixture_end())
        return 1;
    return rs_test_summary();
}
