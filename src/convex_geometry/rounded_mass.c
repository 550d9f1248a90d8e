/* Volume moments of rounded solids, exactly or by quadratures stated in convex.h:
 * a rounded polytope (core, face slabs, edge wedges, vertex sectors), a rounded polygon
 * revolved about z (cylinders and cones), and a rounded ellipsoid (offset surface). */
#include "convex_internal.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static void add_outer(double ss[9], double w, const double a[3], const double b[3])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            ss[3 * i + j] += w * (a[i] * b[j] + b[i] * a[j]);
}

static void add_sym(double ss[9], double w, const double a[3])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            ss[3 * i + j] += w * a[i] * a[j];
}

static void sub3(const double a[3], const double b[3], double c[3])
{
    for (int k = 0; k < 3; k++)
        c[k] = a[k] - b[k];
}

static void unit3(double a[3])
{
    const double n = rs_norm3(a);
    for (int k = 0; k < 3; k++)
        a[k] /= n;
}

/* Moments m (about p0) moved to the origin. */
static void moments_shift(rs_moments *m, const double p0[3])
{
    double s[3] = {m->s[0], m->s[1], m->s[2]};
    add_outer(m->ss, 1.0, s, p0);
    add_sym(m->ss, m->v, p0);
    for (int k = 0; k < 3; k++)
        m->s[k] += m->v * p0[k];
}

/* ---- rounded polytope ---------------------------------------------------------------- */

/* The spherical polygon of unit normals n (k of them, in order around a vertex): its
 * area om, int u and int u u^T over it, through the Laplacian of u and u u^T on the
 * sphere and the boundary of great-circle arcs (either orientation). */
static void normal_cone(const double *n, int k, double *om, double m1[3], double m2[9])
{
    double c[3] = {0.0, 0.0, 0.0};
    for (int i = 0; i < k; i++)
        for (int j = 0; j < 3; j++)
            c[j] += n[3 * i + j];
    unit3(c);
    double area = 0.0, b1[3] = {0.0, 0.0, 0.0}, b2[9] = {0};
    for (int i = 0; i < k; i++) {
        const double *a = n + 3 * i, *b = n + 3 * ((i + 1) % k);
        double ab[3], cr[3];
        rs_cross3(a, b, ab);
        rs_cross3(a, b, cr);
        /* Van Oosterom and Strackee: the fan triangle (c, a, b) */
        area += 2.0 *
                atan2(rs_dot3(c, cr), 1.0 + rs_dot3(c, a) + rs_dot3(a, b) + rs_dot3(b, c));
        const double sn = rs_norm3(ab), cs = rs_dot3(a, b);
        if (sn == 0.0)
            continue;
        const double th = atan2(sn, cs);
        double m[3] = {ab[0] / sn, ab[1] / sn, ab[2] / sn}, t[3], arc[3];
        rs_cross3(m, a, t);
        for (int j = 0; j < 3; j++) {
            b1[j] += 0.5 * th * m[j];
            arc[j] = a[j] * sin(th) + t[j] * (1.0 - cos(th));
        }
        add_outer(b2, 1.0 / 6.0, m, arc);
    }
    const double sg = area < 0.0 ? -1.0 : 1.0;
    *om = sg * area;
    memset(m2, 0, 9 * sizeof *m2);
    for (int j = 0; j < 3; j++) {
        m1[j] = sg * b1[j];
        m2[4 * j] = *om / 3.0;
    }
    for (int j = 0; j < 9; j++)
        m2[j] += sg * b2[j];
}

typedef struct edge_key {
    int lo, hi, tri;
} edge_key;

static int edge_cmp(const void *x, const void *y)
{
    const edge_key *a = x, *b = y;
    if (a->lo != b->lo)
        return a->lo < b->lo ? -1 : 1;
    if (a->hi != b->hi)
        return a->hi < b->hi ? -1 : 1;
    return (a->tri > b->tri) - (a->tri < b->tri);
}

static void tri_normal(const double *v, const int *t, double n[3], double *area)
{
    double e1[3], e2[3];
    sub3(v + 3 * t[1], v + 3 * t[0], e1);
    sub3(v + 3 * t[2], v + 3 * t[0], e2);
    rs_cross3(e1, e2, n);
    *area = 0.5 * rs_norm3(n);
    unit3(n);
}

/* The wedge about edge p-q between the face normals n1 and n2, radius r. */
static void edge_wedge(const double p[3], const double q[3], const double n1[3],
                       const double n2[3], double r, rs_moments *m)
{
    double e[3], w2[3];
    sub3(q, p, e);
    const double len = rs_norm3(e);
    unit3(e);
    const double cs = rs_dot3(n1, n2);
    for (int k = 0; k < 3; k++)
        w2[k] = n2[k] - cs * n1[k];
    const double sn = rs_norm3(w2);
    if (sn <= 1e-15)
        return;
    unit3(w2);
    const double al = atan2(sn, cs);
    const double i0 = r * r / 2.0, i1 = r * r * r / 3.0, i2 = r * r * r * r / 4.0;
    const double s0 = len, s1 = len * len / 2.0, s2 = len * len * len / 3.0;
    double u1[3], u2[9] = {0};
    for (int k = 0; k < 3; k++)
        u1[k] = sin(al) * n1[k] + (1.0 - cos(al)) * w2[k];
    add_sym(u2, al / 2.0 + sin(2.0 * al) / 4.0, n1);
    add_sym(u2, al / 2.0 - sin(2.0 * al) / 4.0, w2);
    add_outer(u2, sin(al) * sin(al) / 2.0, n1, w2);
    m->v += s0 * i0 * al;
    for (int k = 0; k < 3; k++)
        m->s[k] += s0 * i0 * al * p[k] + s1 * i0 * al * e[k] + s0 * i1 * u1[k];
    add_sym(m->ss, s0 * i0 * al, p);
    add_outer(m->ss, s1 * i0 * al, p, e);
    add_sym(m->ss, s2 * i0 * al, e);
    add_outer(m->ss, s0 * i1, p, u1);
    add_outer(m->ss, s1 * i1, e, u1);
    for (int k = 0; k < 9; k++)
        m->ss[k] += s0 * i2 * u2[k];
}

int rs_polytope_moments(const double *v0, const int *t, int nt, double r, rs_moments *m)
{
    memset(m, 0, sizeof *m);
    int rc = -1;
    int nv = 0;
    for (int i = 0; i < 3 * nt; i++)
        nv = t[i] + 1 > nv ? t[i] + 1 : nv;
    /* about the vertices' mean, against cancellation */
    double p0[3] = {0.0, 0.0, 0.0};
    for (int i = 0; i < nv; i++)
        for (int k = 0; k < 3; k++)
            p0[k] += v0[3 * i + k] / nv;
    double *v = malloc((size_t)nv * 3 * sizeof *v);
    double *nrm = malloc((size_t)nt * 3 * sizeof *nrm);
    edge_key *ek = malloc((size_t)nt * 3 * sizeof *ek);
    int *deg = calloc((size_t)nv + 1, sizeof *deg);
    int *inc = malloc((size_t)nt * 3 * sizeof *inc);
    double *cone = malloc((size_t)nt * 3 * sizeof *cone);
    if (!v || !nrm || !ek || !deg || !inc || !cone)
        goto done;
    for (int i = 0; i < nv; i++)
        sub3(v0 + 3 * i, p0, v + 3 * i);
    for (int f = 0; f < nt; f++) {
        const double *a = v + 3 * t[3 * f], *b = v + 3 * t[3 * f + 1],
                     *c = v + 3 * t[3 * f + 2];
        double bc[3], sum[3], area;
        rs_cross3(b, c, bc);
        const double vol = rs_dot3(a, bc) / 6.0; /* tetrahedron (0, a, b, c) */
        for (int k = 0; k < 3; k++)
            sum[k] = a[k] + b[k] + c[k];
        m->v += vol;
        for (int k = 0; k < 3; k++)
            m->s[k] += vol * sum[k] / 4.0;
        add_sym(m->ss, vol / 20.0, a);
        add_sym(m->ss, vol / 20.0, b);
        add_sym(m->ss, vol / 20.0, c);
        add_sym(m->ss, vol / 20.0, sum);
        tri_normal(v, t + 3 * f, nrm + 3 * f, &area);
        if (r > 0.0) { /* the face's slab: the triangle swept r along its normal */
            const double *n = nrm + 3 * f;
            m->v += area * r;
            for (int k = 0; k < 3; k++)
                m->s[k] += r * area * sum[k] / 3.0 + r * r / 2.0 * area * n[k];
            const double w = r * area / 12.0;
            add_sym(m->ss, w, a);
            add_sym(m->ss, w, b);
            add_sym(m->ss, w, c);
            add_sym(m->ss, w, sum);
            double cen[3] = {sum[0] / 3.0, sum[1] / 3.0, sum[2] / 3.0};
            add_outer(m->ss, r * r / 2.0 * area, cen, n);
            add_sym(m->ss, r * r * r / 3.0 * area, n);
        }
        for (int j = 0; j < 3; j++) {
            const int i0 = t[3 * f + j], i1 = t[3 * f + (j + 1) % 3];
            ek[3 * f + j] = (edge_key){i0 < i1 ? i0 : i1, i0 < i1 ? i1 : i0, f};
            deg[i0 + 1]++;
        }
    }
    if (r > 0.0) {
        qsort(ek, (size_t)nt * 3, sizeof *ek, edge_cmp);
        for (int i = 0; i + 1 < 3 * nt; i++) {
            if (ek[i].lo != ek[i + 1].lo || ek[i].hi != ek[i + 1].hi)
                continue;
            const int f1 = ek[i].tri, f2 = ek[i + 1].tri, p = ek[i].lo, q = ek[i].hi;
            edge_wedge(v + 3 * p, v + 3 * q, nrm + 3 * f1, nrm + 3 * f2, r, m);
            i++;
        }
        /* vertex sectors: each vertex's faces in order around it */
        for (int i = 0; i < nv; i++)
            deg[i + 1] += deg[i];
        int *fill = calloc((size_t)nv, sizeof *fill);
        if (!fill)
            goto done;
        for (int f = 0; f < nt; f++)
            for (int j = 0; j < 3; j++) {
                const int a = t[3 * f + j];
                inc[deg[a] + fill[a]++] = 3 * f + j;
            }
        free(fill);
        for (int a = 0; a < nv; a++) {
            const int k = deg[a + 1] - deg[a];
            if (k < 3)
                continue;
            int *list = inc + deg[a];
            /* corner 3f + j of face f: its next corner's vertex leads to the next face */
            for (int s = 0; s + 1 < k; s++) {
                const int cf = list[s] / 3, cj = list[s] % 3;
                const int nb = t[3 * cf + (cj + 2) % 3];
                for (int u = s + 1; u < k; u++) {
                    const int uf = list[u] / 3, uj = list[u] % 3;
                    if (t[3 * uf + (uj + 1) % 3] == nb) {
                        const int tmp = list[s + 1];
                        list[s + 1] = list[u];
                        list[u] = tmp;
                        break;
                    }
                }
            }
            for (int s = 0; s < k; s++)
                memcpy(cone + 3 * s, nrm + 3 * (list[s] / 3), 3 * sizeof *cone);
            double om, m1[3], m2[9];
            normal_cone(cone, k, &om, m1, m2);
            const double *x = v + 3 * a;
            const double r3 = r * r * r / 3.0, r4 = r * r * r * r / 4.0,
                         r5 = r * r * r * r * r / 5.0;
            m->v += om * r3;
            for (int j = 0; j < 3; j++)
                m->s[j] += om * r3 * x[j] + r4 * m1[j];
            add_sym(m->ss, om * r3, x);
            add_outer(m->ss, r4, x, m1);
            for (int j = 0; j < 9; j++)
                m->ss[j] += r5 * m2[j];
        }
    }
    moments_shift(m, p0);
    rc = 0;
done:
    free(v);
    free(nrm);
    free(ek);
    free(deg);
    free(inc);
    free(cone);
    if (rc)
        memset(m, 0, sizeof *m);
    return rc;
}

/* ---- Gauss rules --------------------------------------------------------------------- */

/* The n-point Gauss-Legendre rule on [lo, hi] (n <= 64), by Newton's method on P_n. */
static void gauss_legendre(int n, double lo, double hi, double *x, double *w)
{
    for (int i = 0; i < n; i++) {
        double z = cos(RS_PI * (i + 0.75) / (n + 0.5)), dp = 1.0;
        for (int it = 0; it < 100; it++) {
            double p0 = 1.0, p1 = z;
            for (int k = 2; k <= n; k++) {
                const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = n * (z * p1 - p0) / (z * z - 1.0);
            const double dz = p1 / dp;
            z -= dz;
            if (fabs(dz) < 1e-16)
                break;
        }
        x[i] = 0.5 * (lo + hi) + 0.5 * (hi - lo) * z;
        w[i] = (hi - lo) / ((1.0 - z * z) * dp * dp);
    }
}

/* ---- rounded polygon revolved about z ------------------------------------------------ */

/* The 2D moments int rho, rho z, rho z^2, rho^3 dA, accumulated in q[4]. */
static void acc2(double q[4], double w, double rho, double z)
{
    q[0] += w * rho;
    q[1] += w * rho * z;
    q[2] += w * rho * z * z;
    q[3] += w * rho * rho * rho;
}

/* Triangle a, b, c: the collapsed 3 x 3 Gauss rule, exact to degree 3. */
static void tri2(double q[4], const double a[2], const double b[2], const double c[2])
{
    static const double g[3] = {0.11270166537925831, 0.5, 0.88729833462074169};
    static const double gw[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
    const double det = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            const double u = g[i], s = (1.0 - u) * g[j];
            acc2(q, fabs(det) * (1.0 - u) * gw[i] * gw[j],
                 a[0] + u * (b[0] - a[0]) + s * (c[0] - a[0]),
                 a[1] + u * (b[1] - a[1]) + s * (c[1] - a[1]));
        }
}

/* Circular sector about c, radius r, angles [p1, p2]: 3 Gauss points in radius (exact),
 * 24 in angle (a trigonometric polynomial of degree 3 over less than pi). */
static void sector2(double q[4], const double c[2], double r, double p1, double p2)
{
    static const double g[3] = {0.11270166537925831, 0.5, 0.88729833462074169};
    static const double gw[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
    double x[24], w[24];
    if (p2 <= p1)
        return;
    gauss_legendre(24, p1, p2, x, w);
    for (int i = 0; i < 24; i++)
        for (int j = 0; j < 3; j++) {
            const double s = r * g[j];
            acc2(q, w[i] * r * gw[j] * s, c[0] + s * cos(x[i]), c[1] + s * sin(x[i]));
        }
}

void rs_revolved_moments(const double *prof, int n, double r, rs_moments *m)
{
    double q[4] = {0.0, 0.0, 0.0, 0.0};
    for (int i = 1; i + 1 < n; i++)
        tri2(q, prof, prof + 2 * i, prof + 2 * i + 2);
    for (int i = 0; r > 0.0 && i < n; i++) {
        const double *a = prof + 2 * i, *b = prof + 2 * ((i + 1) % n);
        const double *z = prof + 2 * ((i + n - 1) % n);
        const double len = hypot(b[0] - a[0], b[1] - a[1]);
        const double nb[2] = {(b[1] - a[1]) / len, -(b[0] - a[0]) / len};
        const double la = hypot(a[0] - z[0], a[1] - z[1]);
        const double na[2] = {(a[1] - z[1]) / la, -(a[0] - z[0]) / la};
        if (!(a[0] == 0.0 && b[0] == 0.0)) { /* the strip outside edge a-b */
            const double a2[2] = {a[0] + r * nb[0], a[1] + r * nb[1]};
            const double b2[2] = {b[0] + r * nb[0], b[1] + r * nb[1]};
            tri2(q, a, b, b2);
            tri2(q, a, b2, a2);
        }
        /* the corner at a: normals from na to nb, the part with rho >= 0 on the axis */
        const double p1 = atan2(na[1], na[0]);
        const double p2 =
            p1 + atan2(na[0] * nb[1] - na[1] * nb[0], na[0] * nb[0] + na[1] * nb[1]);
        if (a[0] > 0.0) {
            sector2(q, a, r, p1, p2);
        } else {
            sector2(q, a, r, fmax(p1, -0.5 * RS_PI), fmin(p2, 0.5 * RS_PI));
            sector2(q, a, r, fmax(p1, 1.5 * RS_PI), fmin(p2, 2.5 * RS_PI));
        }
    }
    memset(m, 0, sizeof *m);
    m->v = 2.0 * RS_PI * q[0];
    m->s[2] = 2.0 * RS_PI * q[1];
    m->ss[0] = m->ss[4] = RS_PI * q[3];
    m->ss[8] = 2.0 * RS_PI * q[2];
}

/* ---- rounded ellipsoid --------------------------------------------------------------- */

enum { ELL_NT = 48, ELL_NP = 96 };

void rs_ellipsoid_moments(double a, double b, double c, double r, rs_moments *m)
{
    static const double g[3] = {0.11270166537925831, 0.5, 0.88729833462074169};
    static const double gw[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
    memset(m, 0, sizeof *m);
    m->v = 4.0 / 3.0 * RS_PI * a * b * c;
    m->ss[0] = m->v * a * a / 5.0;
    m->ss[4] = m->v * b * b / 5.0;
    m->ss[8] = m->v * c * c / 5.0;
    if (r <= 0.0)
        return;
    double th[ELL_NT], wt[ELL_NT];
    gauss_legendre(ELL_NT, 0.0, RS_PI, th, wt);
    const double a2 = a * a, b2 = b * b, c2 = c * c;
    for (int i = 0; i < ELL_NT; i++)
        for (int j = 0; j < ELL_NP; j++) {
            const double ph = 2.0 * RS_PI * j / ELL_NP, st = sin(th[i]), ct = cos(th[i]);
            const double sp = sin(ph), cp = cos(ph);
            const double p[3] = {a * st * cp, b * st * sp, c * ct};
            const double pt[3] = {a * ct * cp, b * ct * sp, -c * st};
            const double pp[3] = {-a * st * sp, b * st * cp, 0.0};
            double cr[3];
            rs_cross3(pt, pp, cr);
            const double da = rs_norm3(cr) * wt[i] * (2.0 * RS_PI / ELL_NP);
            double n[3] = {p[0] / a2, p[1] / b2, p[2] / c2};
            const double h = rs_norm3(n);
            for (int k = 0; k < 3; k++)
                n[k] /= h;
            /* the ellipsoid's Gauss and mean curvatures */
            const double kg = 1.0 / (a2 * b2 * c2 * h * h * h * h);
            const double hm =
                (a2 + b2 + c2 - rs_dot3(p, p)) / (2.0 * a2 * b2 * c2 * h * h * h);
            for (int k = 0; k < 3; k++) {
                const double t = r * g[k];
                const double w = da * r * gw[k] * (1.0 + 2.0 * hm * t + kg * t * t);
                const double x[3] = {p[0] + t * n[0], p[1] + t * n[1], p[2] + t * n[2]};
                m->v += w;
                for (int l = 0; l < 3; l++)
                    m->s[l] += w * x[l];
                add_sym(m->ss, w, x);
            }
        }
}
