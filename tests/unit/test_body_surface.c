/* A convex body against the analytic kinds (rs_body_surface_contacts) against closed
 * forms: an ellipsoid and a box in any orientation over a plane (their lowest point is
 * known), a sphere given as a body against the sphere query of a filleted drum (the same
 * features, depths, normals), an ellipsoid inside a REVOLUTION cylinder (its deepest
 * point along the radius, found by a dense scan of its surface), and the refusals. */
#include "rigidsurf/convex.h"
#include "rigidsurf/vec.h"
#include "rs_test.h"
#include "rs_test_geom.h"

#include <stdlib.h>

/* the plane z = 0, normal +z (a CYLINDER whose profile is one LINE) */
static const char *PLANE = "*SURFACE, TYPE=CYLINDER, NAME=floor\n"
                           "0, 0, 0, 1, 0, 0\n0, -1, 0\nSTART, -10, 0\nLINE, 10, 0\n";

/* the inside of a drum of radius 0.5 about z, capped at z = -0.3 with a fillet (the
 * profile runs out along the cap, then up the mantle: its normals point inside) */
static const char *DRUM = "*SURFACE, TYPE=REVOLUTION, NAME=drum, FILLET RADIUS=0.05\n"
                          "0, 0, 0, 0, 0, 1\nSTART, 0, -0.3\nLINE, 0.5, -0.3\n"
                          "LINE, 0.5, 0.3\n";

/* An ellipsoid of semi-axes D over the plane: its lowest point has height
 * z - sqrt(n^T R D^2 R^T n) with n = ez, at x - R D^2 R^T n / sqrt(...). */
static void test_ellipsoid_on_plane(void)
{
    rs_surface s;
    ENSURE(parse(PLANE, &s) == RS_OK);
    const double D[3] = {0.3, 0.12, 0.05};
    rs_shape sh;
    ENSURE(rs_shape_make_ellipsoid(&sh, D[0], D[1], D[2], 0.0, NULL) == RS_OK);
    const double quats[4][4] = {
        {1, 0, 0, 0}, {0.9, 0.3, -0.2, 0.1}, {0.2, 0.7, 0.5, -0.4}, {0.5, -0.5, 0.5, 0.5}};
    for (int t = 0; t < 4; t++) {
        double q[4], R[9];
        unit_quat(quats[t][0], quats[t][1], quats[t][2], quats[t][3], q);
        rs_quat_matrix(q, R);
        double v[3]; /* R D^2 R^T ez */
        const double h = ellipsoid_low(R, D, v);
        const double x[3] = {0.1, -0.2, h - 0.01}; /* 1 cm into the floor */
        rs_body b;
        ENSURE(rs_body_init(&b, &sh, 1000.0, x, q, NULL) == RS_OK);
        rs_body_contact c[4];
        int n = 0;
        rs_error e;
        rs_error_clear(&e);
        ENSURE(rs_body_surface_contacts(&s, NULL, &b, 0.0, c, 4, &n, &e) == RS_OK);
        ENSURE(n == 1);
        ENSURE_NEAR(c[0].depth, 0.01, 1e-13);
        ENSURE_NEAR(c[0].normal[2], 1.0, 1e-15);
        for (int d = 0; d < 3; d++)
            ENSURE_NEAR(c[0].xs[d], x[d] - v[d] / h, 1e-12);
        ENSURE_NEAR(c[0].xm[2], 0.0, 1e-15);
    }
    rs_shape_free(&sh);
    rs_surface_free(&s);
}

/* A rounded box tilted over the plane: its depth is the lowest corner's depth plus the
 * rounding. */
static void test_box_on_plane(void)
{
    rs_surface s;
    ENSURE(parse(PLANE, &s) == RS_OK);
    const double hx = 0.2, hy = 0.1, hz = 0.05, r = 0.01;
    rs_shape sh;
    ENSURE(rs_shape_make_box(&sh, hx, hy, hz, r, NULL) == RS_OK);
    double q[4], R[9];
    unit_quat(0.8, 0.2, 0.5, -0.1, q);
    rs_quat_matrix(q, R);
    const double x[3] = {0.0, 0.0, 0.12};
    double zlow = 1e300;
    for (int c = 0; c < 8; c++) {
        const double v[3] = {(c & 1) ? hx : -hx, (c & 2) ? hy : -hy, (c & 4) ? hz : -hz};
        double w[3];
        rs_matvec3(R, v, w);
        zlow = fmin(zlow, x[2] + w[2]);
    }
    rs_body b;
    ENSURE(rs_body_init(&b, &sh, 1000.0, x, q, NULL) == RS_OK);
    rs_body_contact c[4];
    int n = 0;
    ENSURE(rs_body_surface_contacts(&s, NULL, &b, 0.0, c, 4, &n, NULL) == RS_OK);
    ENSURE(n == 1);
    ENSURE_NEAR(c[0].depth, r - zlow, 1e-13);
    rs_shape_free(&sh);
    rs_surface_free(&s);
}

/* A sphere given as a body against the drum's sphere query: the same owning features,
 * and depth R - dist, normal and master point equal, at the mantle, in the fillet and
 * on the cap. */
static void test_sphere_as_body(void)
{
    rs_surface s;
    ENSURE(parse(DRUM, &s) == RS_OK);
    const double R = 0.04;
    rs_shape sh;
    ENSURE(rs_shape_make_sphere(&sh, R, 0.0, NULL) == RS_OK);
    const double xs[4][3] = {
        {0.47, 0.0, 0.0}, {0.3, 0.35, -0.26}, {0.1, -0.2, -0.27}, {-0.43, 0.1, -0.27}};
    for (int t = 0; t < 4; t++) {
        const double q[4] = {1, 0, 0, 0};
        rs_body b;
        ENSURE(rs_body_init(&b, &sh, 1000.0, xs[t], q, NULL) == RS_OK);
        rs_body_contact c[8];
        int n = 0;
        ENSURE(rs_body_surface_contacts(&s, NULL, &b, 0.0, c, 8, &n, NULL) == RS_OK);
        const double px[1] = {xs[t][0]}, py[1] = {xs[t][1]}, pz[1] = {xs[t][2]},
                     pr[1] = {R};
        rs_query qq;
        memset(&qq, 0, sizeof qq);
        qq.n = 1;
        qq.slave.x = px, qq.slave.y = py, qq.slave.z = pz, qq.slave.radius = pr;
        qq.gap_max = 0.0;
        qq.dist_min = -INFINITY;
        rs_contacts sc;
        memset(&sc, 0, sizeof sc);
        ENSURE(rs_surface_query(&s, &qq, &sc, NULL) == RS_OK);
        ENSURE(n >= 1 && n == sc.n);
        for (int k = 0; k < sc.n; k++) {
            int j = -1;
            for (int i = 0; i < n; i++)
                if (c[i].feature == sc.feature[k])
                    j = i;
            ENSURE(j >= 0);
            if (j < 0)
                continue;
            ENSURE_NEAR(c[j].depth, R - sc.dist[k], 1e-12);
            for (int d = 0; d < 3; d++) {
                ENSURE_NEAR(c[j].normal[d], sc.nrm[d][k], 1e-12);
                ENSURE_NEAR(c[j].xm[d], sc.xm[d][k], 1e-12);
            }
        }
        rs_contacts_free(&sc);
    }
    rs_shape_free(&sh);
    rs_surface_free(&s);
}

/* An ellipsoid inside the drum's mantle, tilted: its depth is the largest radial
 * distance of its surface less 0.5, found independently by a dense scan of the
 * ellipsoid's parametrised surface (to the scan's resolution). */
static void test_ellipsoid_in_drum(void)
{
    rs_surface s;
    ENSURE(parse(DRUM, &s) == RS_OK);
    const double D[3] = {0.1, 0.06, 0.04};
    rs_shape sh;
    ENSURE(rs_shape_make_ellipsoid(&sh, D[0], D[1], D[2], 0.0, NULL) == RS_OK);
    double q[4], R[9];
    unit_quat(0.9, 0.1, 0.3, 0.2, q);
    rs_quat_matrix(q, R);
    const double x[3] = {0.43, 0.05, 0.0};
    double rmax = 0.0;
    const int N = 1200;
    for (int i = 0; i <= N; i++) {
        const double th = RS_PI * i / N;
        for (int j = 0; j < 2 * N; j++) {
            const double ph = RS_PI * j / N;
            const double v[3] = {D[0] * sin(th) * cos(ph), D[1] * sin(th) * sin(ph),
                                 D[2] * cos(th)};
            double w[3];
            rs_matvec3(R, v, w);
            rmax = fmax(rmax, hypot(x[0] + w[0], x[1] + w[1]));
        }
    }
    ENSURE(rmax > 0.51); /* the ellipsoid reaches a centimetre into the mantle */
    rs_body b;
    ENSURE(rs_body_init(&b, &sh, 1000.0, x, q, NULL) == RS_OK);
    rs_body_contact c[8];
    int n = 0;
    ENSURE(rs_body_surface_contacts(&s, NULL, &b, 0.0, c, 8, &n, NULL) == RS_OK);
    ENSURE(n == 1);
    /* the scan's points lie on the surface, so its maximum is below the true one by at
     * most the sagitta of its step, D (pi / N)^2 / 2 */
    const double sag = D[0] * (RS_PI / N) * (RS_PI / N);
    ENSURE(c[0].depth >= rmax - 0.5 - 1e-15);
    ENSURE(c[0].depth <= rmax - 0.5 + sag);
    ENSURE_NEAR(hypot(c[0].xs[0], c[0].xs[1]) - 0.5, c[0].depth, 1e-12);
    rs_shape_free(&sh);
    rs_surface_free(&s);
}

static void test_refusals(void)
{
    rs_surface s;
    ENSURE(parse(PLANE, &s) == RS_OK);
    rs_shape sh;
    ENSURE(rs_shape_make_sphere(&sh, 0.1, 0.0, NULL) == RS_OK);
    const double x[3] = {0, 0, 0.05}, q[4] = {1, 0, 0, 0};
    rs_body b;
    ENSURE(rs_body_init(&b, &sh, 1000.0, x, q, NULL) == RS_OK);
    rs_body_contact c[1];
    int n = 0;
    rs_error e;
    rs_error_clear(&e);
    ENSURE(rs_body_surface_contacts(&s, NULL, &b, -1.0, c, 1, &n, &e) == RS_ERR_ARG);
    ENSURE(strstr(e.msg, "gap_max"));
    ENSURE(rs_body_surface_contacts(&s, NULL, &b, 0.0, c, 0, &n, &e) == RS_ERR_ARG);
    rs_surface m;
    const double xyz[9] = {-1, -1, 0, 1, -1, 0, 0, 1, 0};
    const int tri[3] = {0, 1, 2};
    ENSURE(rs_surface_make_mesh(xyz, 3, tri, 1, NULL, &m, NULL) == RS_OK);
    /* a MESH is answered by its triangles (test_body_mesh) */
    ENSURE(rs_body_surface_contacts(&m, NULL, &b, 0.0, c, 1, &n, &e) == RS_OK);
    ENSURE(n == 1);
    ENSURE_NEAR(c[0].depth, 0.05, 1e-12);
    rs_surface_free(&m);
    rs_shape_free(&sh);
    rs_surface_free(&s);
}

int main(void)
{
    RS_RUN(test_ellipsoid_on_plane);
    RS_RUN(test_box_on_plane);
    RS_RUN(test_sphere_as_body);
    RS_RUN(test_ellipsoid_in_drum);
    RS_RUN(test_refusals);
    return rs_test_summary();
}
