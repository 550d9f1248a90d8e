/* Closest points, normals, distances and curvatures of the analytic surfaces against
 * closed forms: a cylinder (CYLINDER of four arcs, REVOLUTION of one line), a cone, a
 * sphere of arcs, and a parabola (known closest points and a brute-force search). */
#include "rigidsurf/surface.h"
#define RS_TEST_SEED 88172645463325252ull
#include "rs_test.h"
#include "rs_test_geom.h"

#include <math.h>
#include <stdlib.h>

static int query1(const rs_surface *s, double x, double y, double z, double gap,
                  rs_contacts *c)
{
    rs_query q = {.n = 1,
                  .slave = {.x = &x, .y = &y, .z = &z},
                  .pose = NULL,
                  .gap_max = gap,
                  .dist_min = -INFINITY};
    c->n = 0;
    return rs_surface_query(s, &q, c, NULL);
}

static const double R = 0.75;

/* CYLINDER of radius R about the z axis (four 90-degree arcs, counter-clockwise: the
 * normal points to the axis, particles inside). */
static void test_cylinder_of_arcs_closest_point_is_radial(void)
{
    rs_surface s;
    ENSURE(parse("*SURFACE, TYPE=CYLINDER, NAME=c\n"
                 "0,0,0, 1,0,0\n0,0,1\n"
                 "START, 0.75, 0\n"
                 "CIRCL, 0, 0.75, 0, 0\nCIRCL, -0.75, 0, 0, 0\n"
                 "CIRCL, 0, -0.75, 0, 0\nCIRCL, 0.75, 0, 0, 0\n",
                 &s) == 0);
    ENSURE(s.profile.closed == 1);
    for (int j = 0; j < s.profile.nvert; j++)
        ENSURE(s.profile.vkind[j] == RS_VTX_SMOOTH);
    rs_contacts c = {0};
    for (int it = 0; it < 20000; it++) {
        double rho = R * (0.01 + 1.98 * urand()), phi = 2.0 * RS_PI * urand();
        double z = 10.0 * (urand() - 0.5);
        double x = rho * cos(phi), y = rho * sin(phi);
        ENSURE(query1(&s, x, y, z, INFINITY, &c) == 0);
        ENSURE(c.n == 1);
        ENSURE(RS_FEATURE_TYPE(c.feature[0]) == RS_FEAT_FACE);
        ENSURE_REL(c.xm[0][0], R * x / rho, 1e-12);
        ENSURE_REL(c.xm[1][0], R * y / rho, 1e-12);
        ENSURE_REL(c.xm[2][0], z, 1e-12);
        ENSURE_REL(c.nrm[0][0], -x / rho, 1e-12);
        ENSURE_REL(c.nrm[1][0], -y / rho, 1e-12);
        ENSURE_SMALL(c.nrm[2][0], 1e-15);
        ENSURE_REL(c.dist[0], R - rho, 1e-12);
        ENSURE(c.curv[0][0] == 0.0);               /* along the generator */
        ENSURE_REL(c.curv[1][0], -1.0 / R, 1e-12); /* concave toward the particle */
    }
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* The same cylinder as a REVOLUTION of the line r = R: identical answers, and the
 * frames agree (t1 = axis, t2 = hoop). Hoop curvature n_r / r = -1/R. */
static void test_revolution_line_equals_cylinder_of_arcs(void)
{
    rs_surface cyl, rev;
    ENSURE(parse("*SURFACE, TYPE=CYLINDER, NAME=c\n"
                 "0,0,0, 1,0,0\n0,0,1\n"
                 "START, 0.75, 0\n"
                 "CIRCL, 0, 0.75, 0, 0\nCIRCL, -0.75, 0, 0, 0\n"
                 "CIRCL, 0, -0.75, 0, 0\nCIRCL, 0.75, 0, 0, 0\n",
                 &cyl) == 0);
    ENSURE(parse("*SURFACE, TYPE=REVOLUTION, NAME=r\n0,0,0, 0,0,1\n"
                 "START, 0.75, -20\nLINE, 0.75, 20\n",
                 &rev) == 0);
    rs_contacts a = {0}, b = {0};
    for (int it = 0; it < 20000; it++) {
        double rho = R * (0.01 + 1.98 * urand()), phi = 2.0 * RS_PI * urand();
        double z = 10.0 * (urand() - 0.5);
        double x = rho * cos(phi), y = rho * sin(phi);
        ENSURE(query1(&cyl, x, y, z, INFINITY, &a) == 0);
        ENSURE(query1(&rev, x, y, z, INFINITY, &b) == 0);
        ENSURE(a.n == 1 && b.n == 1);
        for (int d = 0; d < 3; d++) {
            ENSURE_REL(a.xm[d][0], b.xm[d][0], 1e-12);
            ENSURE_SMALL(a.nrm[d][0] - b.nrm[d][0], 1e-12);
            ENSURE_SMALL(a.t1[d][0] - b.t1[d][0], 1e-12);
            ENSURE_SMALL(a.t2[d][0] - b.t2[d][0], 1e-12);
        }
        ENSURE_SMALL(b.t1[0][0], 1e-15);
        ENSURE_SMALL(b.t1[1][0], 1e-15);
        ENSURE_NEAR(b.t1[2][0], 1.0, 1e-15);
        ENSURE_REL(b.dist[0], R - rho, 1e-12);
        ENSURE(b.curv[0][0] == 0.0);
        ENSURE_REL(b.curv[1][0], -1.0 / R, 1e-12);
    }
    rs_contacts_free(&a);
    rs_contacts_free(&b);
    rs_surface_free(&cyl);
    rs_surface_free(&rev);
}

/* A funnel: REVOLUTION of the line (r0, 0) -> (R1, H). In the meridian plane the
 * distance is the distance to that line; the hoop curvature is n_r / r at xm. */
static void test_revolution_cone_distance_and_hoop_curvature(void)
{
    const double r0 = 0.2, R1 = 1.0, H = 1.5;
    rs_surface s;
    ENSURE(parse("*SURFACE, TYPE=REVOLUTION, NAME=funnel\n1,2,3, 1,2,4\n"
                 "START, 0.2, 0\nLINE, 1.0, 1.5\n",
                 &s) == 0);
    double L = hypot(R1 - r0, H), t[2] = {(R1 - r0) / L, H / L}, n[2] = {-t[1], t[0]};
    rs_contacts c = {0};
    int seen = 0;
    for (int it = 0; it < 20000; it++) {
        double r = 1.3 * urand(), z = 2.0 * urand() - 0.2, phi = 2.0 * RS_PI * urand();
        double tau = ((r - r0) * t[0] + z * t[1]) / L;
        if (!(tau > 1e-9 && tau < 1.0 - 1e-9) || r < 1e-6)
            continue;
        double dist = (r - r0) * n[0] + z * n[1];
        if (dist < -0.1)
            continue; /* stay out of the other faces' business */
        double x = 1.0 + r * cos(phi), y = 2.0 + r * sin(phi), zz = 3.0 + z;
        ENSURE(query1(&s, x, y, zz, INFINITY, &c) == 0);
        ENSURE(c.n == 1);
        ENSURE(c.feature[0] == RS_FEATURE(RS_FEAT_FACE, 0));
        double rm = r - dist * n[0], zm = z - dist * n[1];
        ENSURE_REL(c.dist[0], dist, 1e-12);
        ENSURE_REL(c.xm[0][0], 1.0 + rm * cos(phi), 1e-12);
        ENSURE_REL(c.xm[1][0], 2.0 + rm * sin(phi), 1e-12);
        ENSURE_REL(c.xm[2][0], 3.0 + zm, 1e-12);
        ENSURE_REL(c.nrm[0][0], n[0] * cos(phi), 1e-12);
        ENSURE_REL(c.nrm[1][0], n[0] * sin(phi), 1e-12);
        ENSURE_REL(c.nrm[2][0], n[1], 1e-12);
        ENSURE(c.curv[0][0] == 0.0);
        ENSURE_REL(c.curv[1][0], n[0] / rm, 1e-12);
        seen++;
    }
    ENSURE(seen > 5000);
    /* below the outlet, inside: the outlet rim is an END vertex, a ring edge */
    ENSURE(query1(&s, 1.0 + 0.1, 2.0, 3.0 - 0.1, INFINITY, &c) == 0);
    ENSURE(c.n == 1 && c.feature[0] == RS_FEATURE(RS_FEAT_VERTEX, 0));
    ENSURE_REL(c.dist[0], hypot(0.1, 0.1), 1e-12);
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* A spherical container: two quarter arcs from the south pole to the north pole. For
 * P inside: xm = R P/|P|, n = -P/|P|, dist = R - |P|, both curvatures -1/R. On the
 * axis the frame is finite and deterministic. */
static void test_revolution_sphere_of_arcs(void)
{
    rs_surface s;
    ENSURE(parse("*SURFACE, TYPE=REVOLUTION, NAME=ball\n0,0,0, 0,0,1\n"
                 "START, 0, -0.75\nCIRCL, 0.75, 0, 0, 0\nCIRCL, 0, 0.75, 0, 0\n",
                 &s) == 0);
    rs_contacts c = {0};
    for (int it = 0; it < 20000; it++) {
        double P[3], pl;
        do {
            for (int d = 0; d < 3; d++)
                P[d] = 2.0 * R * (urand() - 0.5);
            pl = sqrt(P[0] * P[0] + P[1] * P[1] + P[2] * P[2]);
        } while (pl > 0.98 * R || pl < 0.01 * R || hypot(P[0], P[1]) < 1e-3);
        ENSURE(query1(&s, P[0], P[1], P[2], INFINITY, &c) == 0);
        ENSURE(c.n == 1);
        for (int d = 0; d < 3; d++) {
            ENSURE_NEAR(c.xm[d][0], R * P[d] / pl, 1e-12 * R);
            ENSURE_NEAR(c.nrm[d][0], -P[d] / pl, 1e-12);
        }
        ENSURE_REL(c.dist[0], R - pl, 1e-12);
        ENSURE_REL(c.curv[0][0], -1.0 / R, 1e-12);
        ENSURE_REL(c.curv[1][0], -1.0 / R, 1e-11);
    }
    /* on the axis: one contact, the pole, no NaN, the same frame every time */
    for (int it = 0; it < 3; it++) {
        ENSURE(query1(&s, 0.0, 0.0, 0.3, INFINITY, &c) == 0);
        ENSURE(c.n == 1);
        ENSURE_NEAR(c.xm[2][0], R, 1e-15);
        ENSURE_NEAR(c.dist[0], R - 0.3, 1e-15);
        ENSURE_NEAR(c.nrm[2][0], -1.0, 1e-15);
        ENSURE(isfinite(c.t1[0][0]) && isfinite(c.t2[1][0]));
        ENSURE_NEAR(c.t2[0][0] * c.t2[0][0] + c.t2[1][0] * c.t2[1][0] +
                        c.t2[2][0] * c.t2[2][0],
                    1.0, 1e-15);
        ENSURE(c.curv[1][0] == 0.0); /* hoop curvature is 0 on the axis */
    }
    ENSURE(query1(&s, 0.0, 0.0, -0.5, INFINITY, &c) == 0);
    ENSURE(c.n == 1);
    ENSURE_NEAR(c.xm[2][0], -R, 1e-15);
    ENSURE_NEAR(c.nrm[2][0], 1.0, 1e-15);
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* y = x^2 as PARAB (-1,1) (0,0) (1,1): X(xi) = (xi, xi^2). A point on the normal at
 * x0 within half the radius of curvature has x0 as its closest point. */
static void test_parab_closest_on_normal_line(void)
{
    rs_surface s;
    ENSURE(parse("*SURFACE, TYPE=SEGMENTS, NAME=p\nSTART, -1, 1\nPARAB, 0, 0, 1, 1\n",
                 &s) == 0);
    rs_contacts c = {0};
    for (int it = 0; it < 20000; it++) {
        double x0 = 1.9 * (urand() - 0.5);
        double sp = sqrt(1.0 + 4.0 * x0 * x0);
        double n[2] = {-2.0 * x0 / sp, 1.0 / sp};
        double rc = sp * sp * sp / 2.0;
        /* the convex side up to half the radius of curvature; the pocket side only a
         * little, where the far branch of the curve cannot be closer */
        double lam = -0.5 * rc * urand();
        if (it % 2)
            lam = 0.2 * urand();
        double px = x0 + lam * n[0], py = x0 * x0 + lam * n[1];
        ENSURE(query1(&s, px, py, 0.0, INFINITY, &c) == 0);
        ENSURE(c.n >= 1);
        ENSURE(c.feature[0] == RS_FEATURE(RS_FEAT_FACE, 0));
        ENSURE_NEAR(c.xm[0][0], x0, 1e-12);
        ENSURE_NEAR(c.xm[1][0], x0 * x0, 1e-12);
        ENSURE_NEAR(c.dist[0], lam, 1e-12 * fmax(1.0, fabs(lam)));
        ENSURE_NEAR(c.nrm[0][0], n[0], 1e-12);
        ENSURE_NEAR(c.nrm[1][0], n[1], 1e-12);
        /* curvature 2/sp^3, turning toward n: concave toward the particle */
        ENSURE_REL(c.curv[0][0], -1.0 / rc, 1e-12);
    }
    /* on the axis below the focus-evolute point (0, 1/2): the vertex (0, 0) */
    ENSURE(query1(&s, 0.0, 0.3, 0.0, INFINITY, &c) == 0);
    ENSURE(c.n == 1);
    ENSURE_NEAR(c.dist[0], 0.3, 1e-15);
    /* above it: closest points x = +-sqrt(h - 1/2) */
    ENSURE(query1(&s, 0.0, 0.8, 0.0, INFINITY, &c) == 0);
    ENSURE(c.n >= 1);
    ENSURE_NEAR(fabs(c.xm[0][0]), sqrt(0.3), 1e-12);
    ENSURE_NEAR(c.dist[0], sqrt(0.3 + (0.3 - 0.8) * (0.3 - 0.8)), 1e-12);
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* Brute force: sample the curve finely, refine the best sample by golden section. */
static double brute_parab(const double X0[2], const double Xm[2], const double X1[2],
                          double px, double py)
{
    double best = INFINITY, bxi = 0.0;
    const int N = 4000;
    for (int i = 0; i <= N; i++) {
        double xi = -1.0 + 2.0 * i / N;
        double x =
            xi * (xi - 1) / 2 * X0[0] + (1 - xi * xi) * Xm[0] + xi * (xi + 1) / 2 * X1[0];
        double y =
            xi * (xi - 1) / 2 * X0[1] + (1 - xi * xi) * Xm[1] + xi * (xi + 1) / 2 * X1[1];
        double d = hypot(x - px, y - py);
        if (d < best) {
            best = d;
            bxi = xi;
        }
    }
    double lo = fmax(-1.0, bxi - 2.0 / N), hi = fmin(1.0, bxi + 2.0 / N);
    const double g = 0.5 * (sqrt(5.0) - 1.0);
    for (int it = 0; it < 200; it++) {
        double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
        double fa, fb;
        {
            double xi = a;
            double x = xi * (xi - 1) / 2 * X0[0] + (1 - xi * xi) * Xm[0] +
                       xi * (xi + 1) / 2 * X1[0];
            double y = xi * (xi - 1) / 2 * X0[1] + (1 - xi * xi) * Xm[1] +
                       xi * (xi + 1) / 2 * X1[1];
            fa = hypot(x - px, y - py);
        }
        {
            double xi = b;
            double x = xi * (xi - 1) / 2 * X0[0] + (1 - xi * xi) * Xm[0] +
                       xi * (xi + 1) / 2 * X1[0];
            double y = xi * (xi - 1) / 2 * X0[1] + (1 - xi * xi) * Xm[1] +
                       xi * (xi + 1) / 2 * X1[1];
            fb = hypot(x - px, y - py);
        }
        if (fa < fb)
            hi = b;
        else
            lo = a;
        best = fmin(best, fmin(fa, fb));
    }
    return best;
}

/* A skewed PARAB, two-sided: the smallest contact distance equals the distance to the
 * curve found by brute force, for points all around it. */
static void test_parab_matches_brute_force(void)
{
    const double X0[2] = {0.3, -0.2}, Xm[2] = {1.1, 0.9}, X1[2] = {2.4, 0.4};
    rs_surface s;
    ENSURE(parse("*SURFACE, TYPE=SEGMENTS, NAME=p, SIDES=2\nSTART, 0.3, -0.2\n"
                 "PARAB, 1.1, 0.9, 2.4, 0.4\n",
                 &s) == 0);
    rs_contacts c = {0};
    for (int it = 0; it < 3000; it++) {
        double px = -1.0 + 4.5 * urand(), py = -1.5 + 3.5 * urand();
        ENSURE(query1(&s, px, py, 0.0, INFINITY, &c) == 0);
        ENSURE(c.n >= 1);
        double dmin = INFINITY;
        for (int k = 0; k < c.n; k++) {
            /* each contact is a true distance along its normal */
            ENSURE_NEAR(hypot(px - c.xm[0][k], py - c.xm[1][k]), c.dist[k], 1e-12);
            ENSURE_NEAR(c.xm[0][k] + c.dist[k] * c.nrm[0][k], px, 1e-12);
            ENSURE_NEAR(c.xm[1][k] + c.dist[k] * c.nrm[1][k], py, 1e-12);
            dmin = fmin(dmin, c.dist[k]);
        }
        double bf = brute_parab(X0, Xm, X1, px, py);
        ENSURE_NEAR(dmin, bf, 1e-12 * fmax(1.0, bf));
    }
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* EXTENT bounds the generator: points outside [zmin, zmax] get no contact. */
static void test_cylinder_extent_bounds_the_generator(void)
{
    rs_surface s;
    ENSURE(parse("*SURFACE, TYPE=CYLINDER, NAME=plane, EXTENT=-1, 2\n"
                 "0,0,0, 1,0,0\n0,0,1\nSTART, -5, 0\nLINE, 5, 0\n",
                 &s) == 0);
    rs_contacts c = {0};
    ENSURE(query1(&s, 0.5, 0.2, -1.0, INFINITY, &c) == 0 && c.n == 1);
    ENSURE(query1(&s, 0.5, 0.2, 2.0, INFINITY, &c) == 0 && c.n == 1);
    ENSURE(query1(&s, 0.5, 0.2, -1.0 - 1e-12, INFINITY, &c) == 0 && c.n == 0);
    ENSURE(query1(&s, 0.5, 0.2, 2.0 + 1e-12, INFINITY, &c) == 0 && c.n == 0);
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* gap = dist - radius <= gap_max and dist >= dist_min select the contacts. */
static void test_query_gap_and_depth_filters(void)
{
    rs_surface s;
    ENSURE(parse("*SURFACE, TYPE=SEGMENTS, NAME=floor\nSTART, -5, 0\nLINE, 5, 0\n", &s) ==
           0);
    double x[4] = {0, 0, 0, 0}, y[4] = {0.35, 0.25, -0.5, -2.0},
           rad[4] = {0.3, 0.3, 0.3, 0.3};
    rs_query q = {.n = 4,
                  .slave = {.x = x, .y = y, .radius = rad},
                  .pose = NULL,
                  .gap_max = 0.0,
                  .dist_min = -1.0};
    rs_contacts c = {0};
    ENSURE(rs_surface_query(&s, &q, &c, NULL) == 0);
    ENSURE(c.n == 2);
    ENSURE(c.point[0] == 1 && c.point[1] == 2);
    ENSURE_NEAR(c.dist[0], 0.25, 1e-15);
    ENSURE_NEAR(c.dist[1], -0.5, 1e-15);
    q.gap_max = 0.05;
    c.n = 0;
    ENSURE(rs_surface_query(&s, &q, &c, NULL) == 0);
    ENSURE(c.n == 3 && c.point[0] == 0);
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

int main(void)
{
    RS_RUN(test_cylinder_of_arcs_closest_point_is_radial);
    RS_RUN(test_revolution_line_equals_cylinder_of_arcs);
    RS_RUN(test_revolution_cone_distance_and_hoop_curvature);
    RS_RUN(test_revolution_sphere_of_arcs);
    RS_RUN(test_parab_closest_on_normal_line);
    RS_RUN(test_parab_matches_brute_force);
    RS_RUN(test_cylinder_extent_bounds_the_generator);
    RS_RUN(test_query_gap_and_depth_filters);
    return rs_test_summary();
}
