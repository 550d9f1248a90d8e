/* Mass properties of convex shapes (rs_shape_mass_props) against the literature's closed
 * forms, hulls of point sets (a cube, a tetrahedron, points on a sphere), a rounded box
 * piece by piece, and Monte Carlo integration (fixed seed, tolerance from its standard
 * error) for the rounded shapes. */
#include "rigidsurf/convex.h"
#include "rigidsurf/vec.h"
#include "rs_test.h"
#include "rs_test_geom.h"

#include <stdlib.h>

static int diag_is(const rs_mass_props *mp, double m, double ixx, double iyy, double izz,
                   double rtol)
{
    const double want[9] = {ixx, 0, 0, 0, iyy, 0, 0, 0, izz};
    const double sc = fmax(ixx, fmax(iyy, izz));
    if (fabs(mp->mass - m) > rtol * m)
        return 0;
    for (int k = 0; k < 9; k++)
        if (!(fabs(mp->inertia[k] - want[k]) <= rtol * sc))
            return 0;
    for (int k = 0; k < 3; k++)
        if (!(fabs(mp->com[k]) <= rtol * 10.0))
            return 0;
    return 1;
}

/* Textbook solids (e.g. Meriam and Kraige, appendix B), about the centre of mass. */
static void test_mass_closed_forms(void)
{
    const double rho = 2500.0;
    rs_shape s;
    rs_mass_props mp;
    double m;
    ENSURE(rs_shape_make_sphere(&s, 0.5, 0.0, NULL) == RS_OK);
    ENSURE(rs_shape_mass_props(&s, rho, &mp, NULL) == RS_OK);
    m = rho * 4.0 / 3.0 * RS_PI * 0.125;
    ENSURE(diag_is(&mp, m, 0.4 * m * 0.25, 0.4 * m * 0.25, 0.4 * m * 0.25, 1e-14));
    ENSURE(rs_shape_make_ellipsoid(&s, 1.0, 2.0, 3.0, 0.0, NULL) == RS_OK);
    ENSURE(rs_shape_mass_props(&s, rho, &mp, NULL) == RS_OK);
    m = rho * 4.0 / 3.0 * RS_PI * 6.0;
    ENSURE(diag_is(&mp, m, m * 13.0 / 5.0, m * 10.0 / 5.0, m * 5.0 / 5.0, 1e-14));
    ENSURE(rs_shape_make_box(&s, 0.5, 1.0, 1.5, 0.0, NULL) == RS_OK);
    ENSURE(rs_shape_mass_props(&s, rho, &mp, NULL) == RS_OK);
    m = rho * 6.0; /* 1 x 2 x 3 */
    ENSURE(diag_is(&mp, m, m * 13.0 / 12.0, m * 10.0 / 12.0, m * 5.0 / 12.0, 1e-14));
    ENSURE(rs_shape_make_cylinder(&s, 0.5, 1.0, 0.0, NULL) == RS_OK);
    ENSURE(rs_shape_mass_props(&s, rho, &mp, NULL) == RS_OK);
    m = rho * RS_PI * 0.25 * 2.0; /* length L = 2 */
    ENSURE(diag_is(&mp, m, m * (3.0 * 0.25 + 4.0) / 12.0, m * (3.0 * 0.25 + 4.0) / 12.0,
                   m * 0.25 / 2.0, 1e-14));
    ENSURE(rs_shape_make_cone(&s, 0.5, 2.0, 0.0, NULL) == RS_OK);
    ENSURE(rs_shape_mass_props(&s, rho, &mp, NULL) == RS_OK);
    m = rho * RS_PI * 0.25 * 2.0 / 3.0;
    const double ic = m * (3.0 / 20.0 * 0.25 + 3.0 / 80.0 * 4.0);
    ENSURE(diag_is(&mp, m, ic, ic, 0.3 * m * 0.25, 1e-14));
    /* capsule: the cylinder plus two hemispheres, each (83/320) m R^2 about its own
     * centre of mass, 3R/8 from its flat face (parallel axes) */
    const double R = 0.5, L = 2.0;
    ENSURE(rs_shape_make_capsule(&s, 0.3, 1.0, 0.2, NULL) == RS_OK);
    ENSURE(rs_shape_mass_props(&s, rho, &mp, NULL) == RS_OK);
    const double mc = rho * RS_PI * R * R * L, mh = rho * 2.0 / 3.0 * RS_PI * R * R * R;
    const double dh = L / 2.0 + 3.0 * R / 8.0;
    const double ix = mc * (3.0 * R * R + L * L) / 12.0 +
                      2.0 * (83.0 / 320.0 * mh * R * R + mh * dh * dh);
    ENSURE(diag_is(&mp, mc + 2.0 * mh, ix, ix, mc * R * R / 2.0 + 2.0 * 0.4 * mh * R * R,
                   1e-14));
}

/* A rounded box piece by piece: the box, 6 slabs, 12 quarter-cylinders, 8 octants; the
 * second moments int x^2, int y^2, int z^2 of each about the centre. */
static void rounded_box_moments(const double h[3], double r, double *v, double mom[3])
{
    *v = 8.0 * h[0] * h[1] * h[2] + 8.0 * r * (h[0] * h[1] + h[1] * h[2] + h[2] * h[0]) +
         2.0 * RS_PI * r * r * (h[0] + h[1] + h[2]) + 4.0 / 3.0 * RS_PI * r * r * r;
    for (int i = 0; i < 3; i++) {
        const double a = h[i], b = h[(i + 1) % 3], c = h[(i + 2) % 3];
        double s = 8.0 * h[0] * h[1] * h[2] * a * a / 3.0;
        /* slabs across axis i (two), across the others (four) */
        s += 2.0 * 4.0 * b * c * (pow(a + r, 3) - a * a * a) / 3.0;
        s += 2.0 * (r * 2.0 * c) * (2.0 * a * a * a / 3.0);
        s += 2.0 * (r * 2.0 * b) * (2.0 * a * a * a / 3.0);
        /* quarter-cylinders along the other two axes (8) touch x_i = +-a; along axis i
         * (4) their section is a quarter-disc away from the axis */
        const double qoff = a * a * RS_PI / 4.0 * r * r + 2.0 * a * r * r * r / 3.0 +
                            RS_PI / 16.0 * r * r * r * r;
        s += 4.0 * 2.0 * b * qoff + 4.0 * 2.0 * c * qoff;
        s += 4.0 * (RS_PI * r * r / 4.0) * (2.0 * a * a * a / 3.0);
        /* octants */
        s += 8.0 * (a * a * RS_PI * r * r * r / 6.0 +
                    2.0 * a * r * r * r * r / 4.0 * RS_PI / 4.0 +
                    r * r * r * r * r / 5.0 * RS_PI / 6.0);
        mom[i] = s;
    }
}

static void test_mass_rounded_box_pieces(void)
{
    const double h[3] = {0.5, 1.0, 1.5}, r = 0.3, rho = 7.0;
    double v, mom[3];
    rounded_box_moments(h, r, &v, mom);
    rs_shape s;
    rs_mass_props mp;
    ENSURE(rs_shape_make_box(&s, h[0], h[1], h[2], r, NULL) == RS_OK);
    ENSURE(rs_shape_mass_props(&s, rho, &mp, NULL) == RS_OK);
    ENSURE_REL(mp.volume, v, 1e-14);
    ENSURE(diag_is(&mp, rho * v, rho * (mom[1] + mom[2]), rho * (mom[0] + mom[2]),
                   rho * (mom[0] + mom[1]), 1e-13));
}

/* Hulls of point sets: a cube with points inside, the corner tetrahedron (Tonon 2004:
 * volume 1/6, centroid (1/4, 1/4, 1/4), I_xx = m/10... here with density 1: I_xx = 1/80,
 * products 1/480), and its principal axes ((1,1,1) with 1/60). */
static void test_mass_hull_cube_tetrahedron(void)
{
    double cube[3 * 20];
    for (int i = 0; i < 8; i++)
        for (int k = 0; k < 3; k++)
            cube[3 * i + k] = ((i >> k) & 1) ? 2.0 : 0.0;
    for (int i = 8; i < 20; i++)
        for (int k = 0; k < 3; k++)
            cube[3 * i + k] = 0.1 + 1.8 * urand();
    rs_shape s;
    rs_mass_props mp;
    ENSURE(rs_shape_make_polyhedron(&s, cube, 20, 0.0, NULL) == RS_OK);
    ENSURE(s.nv == 8);
    for (int k = 0; k < 3; k++)
        ENSURE_NEAR(s.shift[k], 1.0, 1e-15);
    ENSURE(rs_shape_mass_props(&s, 3.0, &mp, NULL) == RS_OK);
    ENSURE(
        diag_is(&mp, 24.0, 24.0 * 8.0 / 12.0, 24.0 * 8.0 / 12.0, 24.0 * 8.0 / 12.0, 1e-14));
    rs_shape_free(&s);

    const double tet[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    ENSURE(rs_shape_make_polyhedron(&s, tet, 4, 0.0, NULL) == RS_OK);
    ENSURE(rs_shape_mass_props(&s, 1.0, &mp, NULL) == RS_OK);
    ENSURE_NEAR(mp.volume, 1.0 / 6.0, 1e-16);
    for (int k = 0; k < 3; k++) {
        ENSURE_NEAR(s.shift[k], 0.25, 1e-16);
        ENSURE_SMALL(mp.com[k], 1e-16);
        for (int j = 0; j < 3; j++)
            ENSURE_NEAR(mp.inertia[3 * k + j], j == k ? 1.0 / 80.0 : 1.0 / 480.0, 1e-17);
    }
    /* principal moments 1/96, 1/96, 1/60; the last about (1, 1, 1) */
    int big = 0;
    for (int k = 0; k < 3; k++)
        if (fabs(mp.principal[k] - 1.0 / 60.0) < 1e-16)
            big = k + 1;
        else
            ENSURE_NEAR(mp.principal[k], 1.0 / 96.0, 1e-16);
    ENSURE(big);
    for (int j = 0; j < 3; j++)
        ENSURE_NEAR(fabs(mp.axes[3 * j + big - 1]), 1.0 / sqrt(3.0), 1e-14);
    /* the axes are a right-handed rotation that diagonalises the tensor */
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++) {
            double d = 0.0;
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    d += mp.axes[3 * i + a] * mp.inertia[3 * i + j] * mp.axes[3 * j + b];
            ENSURE_NEAR(d, a == b ? mp.principal[a] : 0.0, 1e-17);
        }
    rs_shape_free(&s);
}

/* The hull of n points spread on the unit sphere (Fibonacci lattice) tends to the ball:
 * its volume and moments lie below the ball's by O(1/n). */
static void test_mass_hull_sphere_converges(void)
{
    double prev = 1.0;
    for (int n = 100; n <= 10000; n *= 10) {
        double *p = malloc(3 * (size_t)n * sizeof *p);
        ENSURE(p);
        for (int i = 0; i < n; i++) {
            const double z = 1.0 - (2.0 * i + 1.0) / n, rr = sqrt(1.0 - z * z);
            const double ph = i * RS_PI * (3.0 - sqrt(5.0));
            p[3 * i] = rr * cos(ph);
            p[3 * i + 1] = rr * sin(ph);
            p[3 * i + 2] = z;
        }
        rs_shape s;
        rs_mass_props mp;
        rs_error err;
        int rc = rs_shape_make_polyhedron(&s, p, n, 0.0, &err);
        free(p);
        ENSURE(rc == RS_OK);
        ENSURE(rs_shape_mass_props(&s, 1.0, &mp, NULL) == RS_OK);
        rs_shape_free(&s);
        const double v = 4.0 / 3.0 * RS_PI, dv = (v - mp.volume) / v;
        ENSURE(dv > 0.0 && dv < 20.0 / n);
        for (int k = 0; k < 3; k++)
            ENSURE_REL(mp.principal[k], 0.4 * v, 25.0 / n);
        ENSURE(dv < 0.2 * prev);
        prev = dv;
    }
}

/* ---- Monte Carlo --------------------------------------------------------------------- */

/* distance of p from the ellipsoid of semi-axes a (outside; 0 inside), through the root
 * of sum (a_i p_i / (a_i^2 + t))^2 = 1 by bisection */
static double ellipsoid_dist(const double a[3], const double p[3])
{
    double f0 = 0.0;
    for (int k = 0; k < 3; k++)
        f0 += p[k] * p[k] / (a[k] * a[k]);
    if (f0 <= 1.0)
        return 0.0;
    double lo = 0.0, hi = 1.0;
    for (;;) {
        double f = 0.0;
        for (int k = 0; k < 3; k++)
            f += pow(a[k] * p[k] / (a[k] * a[k] + hi), 2);
        if (f < 1.0)
            break;
        hi *= 2.0;
    }
    for (int it = 0; it < 200; it++) {
        const double t = 0.5 * (lo + hi);
        double f = 0.0;
        for (int k = 0; k < 3; k++)
            f += pow(a[k] * p[k] / (a[k] * a[k] + t), 2);
        if (f > 1.0)
            lo = t;
        else
            hi = t;
    }
    double d2 = 0.0;
    for (int k = 0; k < 3; k++) {
        const double y = a[k] * a[k] * p[k] / (a[k] * a[k] + lo);
        d2 += (p[k] - y) * (p[k] - y);
    }
    return sqrt(d2);
}

/* distance in the (rho, z) plane from the segment a-b */
static double seg_dist2(const double a[2], const double b[2], double x, double z)
{
    const double ex = b[0] - a[0], ez = b[1] - a[1];
    double t = ((x - a[0]) * ex + (z - a[1]) * ez) / (ex * ex + ez * ez);
    t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    return hypot(x - a[0] - t * ex, z - a[1] - t * ez);
}

typedef struct mc_shape {
    int kind; /* 0 ellipsoid, 1 cylinder, 2 cone, 3 box, 4 tetrahedron-ish polytope */
    double d[3], r;
    double half[3]; /* sampling box half-widths about the core's origin */
} mc_shape;

static int inside(const mc_shape *m, const double p[3])
{
    const double r = m->r;
    switch (m->kind) {
    case 0:
        return ellipsoid_dist(m->d, p) <= r;
    case 1: {
        const double rho = hypot(p[0], p[1]);
        const double dx = fmax(rho - m->d[0], 0.0), dz = fmax(fabs(p[2]) - m->d[1], 0.0);
        return dx * dx + dz * dz <= r * r;
    }
    case 2: { /* triangle (0,-h/4), (R,-h/4), (0,3h/4) in (rho, z) */
        const double rho = hypot(p[0], p[1]), R = m->d[0], h = m->d[1];
        const double A[2] = {0.0, -0.25 * h}, B[2] = {R, -0.25 * h}, C[2] = {0.0, 0.75 * h};
        const int in = p[2] >= -0.25 * h && rho * h + R * (p[2] - 0.75 * h) <= 0.0;
        return in || seg_dist2(A, B, rho, p[2]) <= r || seg_dist2(B, C, rho, p[2]) <= r;
    }
    case 3: {
        double d2 = 0.0;
        for (int k = 0; k < 3; k++) {
            const double e = fmax(fabs(p[k]) - m->d[k], 0.0);
            d2 += e * e;
        }
        return d2 <= r * r;
    }
    }
    return 0;
}

/* Monte Carlo over the sampling box: volume, centre of mass z and the second moments'
 * diagonal, each with its standard error; checked against mp within 4.5 of them. */
static int mc_check(const mc_shape *m, const rs_mass_props *mp, double zshift, int n)
{
    unsigned long long st = 0x2545F4914F6CDD1Dull + (unsigned long long)m->kind;
    double sum[5] = {0}, sq[5] = {0};
    double vb = 8.0 * m->half[0] * m->half[1] * m->half[2];
    for (int i = 0; i < n; i++) {
        double p[3];
        for (int k = 0; k < 3; k++)
            p[k] = m->half[k] * (2.0 * rs_test_urand(&st) - 1.0);
        if (!inside(m, p))
            continue;
        const double f[5] = {1.0, p[2], p[0] * p[0], p[1] * p[1], p[2] * p[2]};
        for (int j = 0; j < 5; j++) {
            sum[j] += f[j];
            sq[j] += f[j] * f[j];
        }
    }
    double est[5], se[5];
    for (int j = 0; j < 5; j++) {
        const double mean = sum[j] / n, var = sq[j] / n - mean * mean;
        est[j] = vb * mean;
        se[j] = vb * sqrt(var / n);
    }
    /* the library's values in the core's frame: its second moments about the origin */
    const double v = mp->volume, zc = zshift;

    const double cxx =
        (mp->inertia[4] + mp->inertia[8] - mp->inertia[0]) / 2.0 * v / mp->mass;
    const double cyy =
        (mp->inertia[0] + mp->inertia[8] - mp->inertia[4]) / 2.0 * v / mp->mass;
    const double czz =
        (mp->inertia[0] + mp->inertia[4] - mp->inertia[8]) / 2.0 * v / mp->mass +
        v * zc * zc;
    const double lib[5] = {v, v * zc, cxx, cyy, czz};
    for (int j = 0; j < 5; j++)
        if (!(fabs(lib[j] - est[j]) <= 4.5 * se[j] + 1e-12)) {
            fprintf(stderr, "kind %d moment %d: %.10g vs Monte Carlo %.10g +- %.3g\n",
                    m->kind, j, lib[j], est[j], se[j]);
            return 0;
        }
    return 1;
}

static void test_mass_rounded_monte_carlo(void)
{
    const int n = 2000000;
    rs_shape s;
    rs_mass_props mp;
    const mc_shape ell = {0, {1.0, 0.6, 0.3}, 0.25, {1.3, 0.9, 0.6}};
    ENSURE(rs_shape_make_ellipsoid(&s, 1.0, 0.6, 0.3, 0.25, NULL) == RS_OK);
    ENSURE(rs_shape_mass_props(&s, 3.0, &mp, NULL) == RS_OK);
    ENSURE(mc_check(&ell, &mp, 0.0, n));
    const mc_shape cyl = {1, {0.5, 0.2, 0}, 0.15, {0.7, 0.7, 0.4}};
    ENSURE(rs_shape_make_cylinder(&s, 0.5, 0.2, 0.15, NULL) == RS_OK);
    ENSURE(rs_shape_mass_props(&s, 3.0, &mp, NULL) == RS_OK);
    ENSURE(mc_check(&cyl, &mp, 0.0, n));
    const mc_shape cone = {2, {0.5, 1.2, 0}, 0.2, {0.75, 0.75, 1.15}};
    ENSURE(rs_shape_make_cone(&s, 0.5, 1.2, 0.2, NULL) == RS_OK);
    ENSURE(rs_shape_mass_props(&s, 3.0, &mp, NULL) == RS_OK);
    ENSURE(fabs(s.shift[2]) > 1e-3);
    ENSURE(mc_check(&cone, &mp, s.shift[2], n));
    const mc_shape box = {3, {0.5, 0.3, 0.2}, 0.2, {0.75, 0.55, 0.45}};
    ENSURE(rs_shape_make_box(&s, 0.5, 0.3, 0.2, 0.2, NULL) == RS_OK);
    ENSURE(rs_shape_mass_props(&s, 3.0, &mp, NULL) == RS_OK);
    ENSURE(mc_check(&box, &mp, 0.0, n));
}

/* A rounded polyhedron: the rounded box given as its 8 corners agrees with the box's
 * pieces, and a rounded ellipsoid with equal semi-axes is the ball of radius a + r. */
static void test_mass_rounded_polyhedron_and_ball(void)
{
    const double h[3] = {0.5, 1.0, 1.5}, r = 0.3;
    double c[24], v, mom[3];
    for (int i = 0; i < 8; i++)
        for (int k = 0; k < 3; k++)
            c[3 * i + k] = (((i >> k) & 1) ? h[k] : -h[k]) + 1.0;
    rs_shape s;
    rs_mass_props mp;
    ENSURE(rs_shape_make_polyhedron(&s, c, 8, r, NULL) == RS_OK);
    ENSURE(rs_shape_mass_props(&s, 1.0, &mp, NULL) == RS_OK);
    rounded_box_moments(h, r, &v, mom);
    ENSURE_REL(mp.volume, v, 1e-14);
    for (int k = 0; k < 3; k++)
        ENSURE_NEAR(s.shift[k], 1.0, 1e-14);
    ENSURE(diag_is(&mp, v, mom[1] + mom[2], mom[0] + mom[2], mom[0] + mom[1], 1e-13));
    rs_shape_free(&s);
    /* a rounded tetrahedron: Steiner's volume V + S r + M r^2 + 4/3 pi r^3 with M the
     * sum over edges of length times exterior angle over 2 */
    const double tet[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    ENSURE(rs_shape_make_polyhedron(&s, tet, 4, r, NULL) == RS_OK);
    ENSURE(rs_shape_mass_props(&s, 1.0, &mp, NULL) == RS_OK);
    rs_shape_free(&s);
    const double area = 1.5 + sqrt(3.0) / 2.0;
    const double ext_axis = RS_PI / 2.0, ext_diag = RS_PI - acos(1.0 / sqrt(3.0));
    const double mcurv = 0.5 * (3.0 * 1.0 * ext_axis + 3.0 * sqrt(2.0) * ext_diag);
    ENSURE_REL(mp.volume,
               1.0 / 6.0 + area * r + mcurv * r * r + 4.0 / 3.0 * RS_PI * r * r * r, 1e-14);
    ENSURE(rs_shape_make_ellipsoid(&s, 0.7, 0.7, 0.7, 0.3, NULL) == RS_OK);
    ENSURE(rs_shape_mass_props(&s, 1.0, &mp, NULL) == RS_OK);
    const double vb = 4.0 / 3.0 * RS_PI;
    ENSURE(diag_is(&mp, vb, 0.4 * vb, 0.4 * vb, 0.4 * vb, 1e-13));
    /* a rounded cylinder: Pappus: the cylinder of radius R + r, the end slabs and the
     * two rims (a quarter-disc at distance R + 4r/(3 pi) from the axis) */
    ENSURE(rs_shape_make_cylinder(&s, 0.5, 0.2, 0.15, NULL) == RS_OK);
    ENSURE(rs_shape_mass_props(&s, 1.0, &mp, NULL) == RS_OK);
    const double rc = 0.5, hc = 0.2, rr = 0.15;
    const double vc =
        RS_PI * (rc + rr) * (rc + rr) * 2.0 * hc + RS_PI * rc * rc * 2.0 * rr +
        4.0 * RS_PI * (RS_PI * rr * rr / 4.0) * (rc + 4.0 * rr / (3.0 * RS_PI));
    ENSURE_REL(mp.volume, vc, 1e-14);
}

int main(void)
{
    RS_RUN(test_mass_closed_forms);
    RS_RUN(test_mass_rounded_box_pieces);
    RS_RUN(test_mass_hull_cube_tetrahedron);
    RS_RUN(test_mass_hull_sphere_converges);
    RS_RUN(test_mass_rounded_monte_carlo);
    RS_RUN(test_mass_rounded_polyhedron_and_ball);
    return rs_test_summary();
}
