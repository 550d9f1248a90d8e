/* The convex pair query (rs_convex_pair, rs_convex_triangle) against closed forms:
 * spheres as rounded points (exact), a sphere as an ellipsoid through libccd's MPR and
 * GJK against a triangle, a box face-down on a triangle and on another box, gaps. */
#include "rigidsurf/convex.h"
#include "rigidsurf/vec.h"
#include "rs_test.h"
#include "rs_test_geom.h"

static const double q_id[4] = {1.0, 0.0, 0.0, 0.0};

static int contact_ok(const rs_convex_contact *c, double depth, const double n[3],
                      double tol)
{
    if (!(fabs(c->depth - depth) <= tol))
        return fprintf(stderr, "depth %.17g, expected %.17g\n", c->depth, depth), 0;
    for (int k = 0; k < 3; k++)
        if (!(fabs(c->normal[k] - n[k]) <= tol))
            return fprintf(stderr, "normal[%d] %.17g, expected %.17g\n", k, c->normal[k],
                           n[k]),
                   0;
    for (int k = 0; k < 3; k++) /* pb - pa = -depth n */
        if (!(fabs(c->pb[k] - c->pa[k] + c->depth * c->normal[k]) <= tol))
            return fprintf(stderr, "witnesses apart by the wrong vector\n"), 0;
    return 1;
}

/* Two spheres (rounded points): depth Ra + Rb - |xb - xa|, normal along the centres,
 * witnesses on the spheres, to 1e-12, overlapping and apart. */
static void test_pair_sphere_sphere_exact(void)
{
    rs_shape sa, sb;
    ENSURE(rs_shape_make_sphere(&sa, 0.5, 0.0, NULL) == RS_OK);
    ENSURE(rs_shape_make_sphere(&sb, 0.3, 0.1, NULL) == RS_OK);
    for (int t = 0; t < 200; t++) {
        double xa[3], xb[3], d[3];
        for (int k = 0; k < 3; k++) {
            xa[k] = 2.0 * urand() - 1.0;
            d[k] = 2.0 * urand() - 1.0;
        }
        unit(d);
        const double dist = 0.2 + 1.4 * urand();
        for (int k = 0; k < 3; k++)
            xb[k] = xa[k] + dist * d[k];
        rs_body a, b;
        ENSURE(rs_body_init(&a, &sa, 1.0, xa, q_id, NULL) == RS_OK);
        ENSURE(rs_body_init(&b, &sb, 1.0, xb, q_id, NULL) == RS_OK);
        rs_convex_contact c;
        ENSURE(rs_convex_pair(&a, &b, 1.0, &c, NULL) == RS_OK);
        ENSURE(contact_ok(&c, 0.9 - dist, d, 1e-12));
        ENSURE(c.state == (dist < 0.9 ? RS_CONVEX_OVERLAP : RS_CONVEX_NEAR));
        for (int k = 0; k < 3; k++) {
            ENSURE_NEAR(c.pa[k], xa[k] + 0.5 * d[k], 1e-12);
            ENSURE_NEAR(c.pb[k], xb[k] - 0.4 * d[k], 1e-12);
        }
        if (dist > 0.9 + 1e-6) { /* gap_max just short of the gap */
            ENSURE(rs_convex_pair(&a, &b, dist - 0.9 - 1e-9, &c, NULL) == RS_OK);
            ENSURE(c.state == RS_CONVEX_APART);
        }
    }
}

/* A sphere against a triangle: the closed form is the distance from the centre to the
 * triangle's plane (centre above its inside) or to an edge. The sphere as a rounded
 * point to 1e-12; as an ellipsoid a = b = c (libccd's MPR on a curved core; GJK) to
 * 1e-9. The normal points from the sphere to the triangle. */
static void test_pair_sphere_triangle(void)
{
    const double tri[9] = {-1.0, -1.0, 0.2, 2.0, -0.5, 0.2, 0.0, 1.5, 0.2};
    rs_shape pt, el;
    ENSURE(rs_shape_make_sphere(&pt, 0.4, 0.0, NULL) == RS_OK);
    ENSURE(rs_shape_make_ellipsoid(&el, 0.4, 0.4, 0.4, 0.0, NULL) == RS_OK);
    const double down[3] = {0.0, 0.0, -1.0};
    for (int t = 0; t < 100; t++) {
        /* the centre above the inside: overlapping by up to 0.35, or apart by up to 0.2 */
        const double x[3] = {-0.2 + 0.6 * urand(), -0.3 + 0.6 * urand(),
                             0.2 + 0.05 + 0.55 * urand()};
        const double depth = 0.4 - (x[2] - 0.2);
        rs_body b;
        rs_convex_contact c;
        ENSURE(rs_body_init(&b, &pt, 1.0, x, q_id, NULL) == RS_OK);
        ENSURE(rs_convex_triangle(&b, tri, 0.5, &c, NULL) == RS_OK);
        ENSURE(contact_ok(&c, depth, down, 1e-12));
        ENSURE_NEAR(c.pb[2], 0.2, 1e-12);
        ENSURE_NEAR(c.pb[0], x[0], 1e-12);
        ENSURE(rs_body_init(&b, &el, 1.0, x, q_id, NULL) == RS_OK);
        ENSURE(rs_convex_triangle(&b, tri, 0.5, &c, NULL) == RS_OK);
        ENSURE(contact_ok(&c, depth, down, 1e-9));
        ENSURE_NEAR(c.pa[2], x[2] - 0.4, 1e-9);
        ENSURE_NEAR(c.pa[1], x[1], 1e-6);
    }
    /* beside the edge from (2, -0.5) to (0, 1.5), apart: the distance to the edge */
    double e[3] = {-2.0, 2.0, 0.0}, m[3] = {1.0, 0.5, 0.2}, out[3] = {1.0, 1.0, 0.0};
    unit(e);
    unit(out);
    for (int t = 0; t < 20; t++) {
        const double s = 0.5 * urand(), h = 0.1 + 0.2 * urand(), up = 0.3 * urand();
        const double x[3] = {m[0] + (0.4 + h) * out[0] * cos(up) + s * e[0],
                             m[1] + (0.4 + h) * out[1] * cos(up) + s * e[1],
                             m[2] + (0.4 + h) * sin(up)};
        const double n[3] = {-out[0] * cos(up), -out[1] * cos(up), -sin(up)};
        rs_body b;
        rs_convex_contact c;
        ENSURE(rs_body_init(&b, &pt, 1.0, x, q_id, NULL) == RS_OK);
        ENSURE(rs_convex_triangle(&b, tri, 0.5, &c, NULL) == RS_OK);
        ENSURE(c.state == RS_CONVEX_NEAR);
        ENSURE(contact_ok(&c, -h, n, 1e-12));
        /* GJK on a curved core: the gap to 1e-10; its direction only to about the square
         * root of the gap's tolerance, here 1e-4 (docs/conventions.md, "Convex bodies") */
        ENSURE(rs_body_init(&b, &el, 1.0, x, q_id, NULL) == RS_OK);
        ENSURE(rs_convex_triangle(&b, tri, 0.5, &c, NULL) == RS_OK);
        ENSURE_NEAR(c.depth, -h, 1e-10);
        ENSURE(contact_ok(&c, -h, n, 1e-4));
    }
}

/* A box face-down on a large triangle, turned about z: depth hz - (z - z_plane), normal
 * -z; the witness on the box lies on its bottom face, the one on the triangle in its
 * plane. Then lifted off: the gap. A rounded box adds its rounding. */
static void test_pair_box_triangle_face_down(void)
{
    const double tri[9] = {-5.0, -4.0, 0.0, 6.0, -3.0, 0.0, -1.0, 7.0, 0.0};
    const double down[3] = {0.0, 0.0, -1.0};
    rs_shape box, rbox;
    ENSURE(rs_shape_make_box(&box, 0.5, 0.3, 0.2, 0.0, NULL) == RS_OK);
    ENSURE(rs_shape_make_box(&rbox, 0.5, 0.3, 0.2, 0.05, NULL) == RS_OK);
    for (int t = 0; t < 50; t++) {
        const double yaw = 2.0 * RS_PI * urand(), z = 0.2 + 0.1 * (2.0 * urand() - 1.0);
        const double q[4] = {cos(0.5 * yaw), 0.0, 0.0, sin(0.5 * yaw)};
        const double x[3] = {0.5 * urand(), 0.5 * urand(), z};
        rs_body b;
        rs_convex_contact c;
        ENSURE(rs_body_init(&b, &box, 1.0, x, q, NULL) == RS_OK);
        ENSURE(rs_convex_triangle(&b, tri, 0.2, &c, NULL) == RS_OK);
        ENSURE(contact_ok(&c, 0.2 - z, down, 1e-11));
        ENSURE_NEAR(c.pa[2], z - 0.2, 1e-12);
        ENSURE_NEAR(c.pb[2], 0.0, 1e-12);
        ENSURE(hypot(c.pa[0] - x[0], c.pa[1] - x[1]) <= hypot(0.5, 0.3) + 1e-12);
        ENSURE(rs_body_init(&b, &rbox, 1.0, x, q, NULL) == RS_OK);
        ENSURE(rs_convex_triangle(&b, tri, 0.2, &c, NULL) == RS_OK);
        ENSURE(contact_ok(&c, 0.25 - z, down, 1e-11));
        ENSURE_NEAR(c.pb[2], 0.0, 1e-12);
    }
}

/* Two boxes: one on the other, face to face, overlapping and apart; and a box far away
 * is APART with the lower bound of its gap. */
static void test_pair_box_box(void)
{
    rs_shape box;
    ENSURE(rs_shape_make_box(&box, 0.5, 0.3, 0.2, 0.0, NULL) == RS_OK);
    const double up[3] = {0.0, 0.0, 1.0};
    for (int t = 0; t < 50; t++) {
        const double yaw = 0.3 * (2.0 * urand() - 1.0), gap = 0.1 * (2.0 * urand() - 1.0);
        const double q[4] = {cos(0.5 * yaw), 0.0, 0.0, sin(0.5 * yaw)};
        const double xa[3] = {0.0, 0.0, 0.0},
                     xb[3] = {0.1 * urand(), 0.1 * urand(), 0.4 + gap};
        rs_body a, b;
        rs_convex_contact c;
        ENSURE(rs_body_init(&a, &box, 1.0, xa, q_id, NULL) == RS_OK);
        ENSURE(rs_body_init(&b, &box, 1.0, xb, q, NULL) == RS_OK);
        ENSURE(rs_convex_pair(&a, &b, 0.2, &c, NULL) == RS_OK);
        ENSURE(contact_ok(&c, -gap, up, 1e-11));
        ENSURE(c.state == (gap < 0.0 ? RS_CONVEX_OVERLAP : RS_CONVEX_NEAR));
    }
    const double xa[3] = {0.0, 0.0, 0.0}, xb[3] = {3.0, 0.0, 0.0};
    rs_body a, b;
    rs_convex_contact c;
    ENSURE(rs_body_init(&a, &box, 1.0, xa, q_id, NULL) == RS_OK);
    ENSURE(rs_body_init(&b, &box, 1.0, xb, q_id, NULL) == RS_OK);
    ENSURE(rs_convex_pair(&a, &b, 0.5, &c, NULL) == RS_OK);
    ENSURE(c.state == RS_CONVEX_APART);
    ENSURE(c.depth < -0.5 && c.depth >= -2.0 - 1e-12);
    ENSURE(rs_convex_pair(&a, &b, 3.0, &c, NULL) == RS_OK);
    ENSURE(c.state == RS_CONVEX_NEAR);
    ENSURE(contact_ok(&c, -2.0, (double[3]){1.0, 0.0, 0.0}, 1e-12));
}

/* An ellipsoid a = b = c against a rounded-point sphere, overlapping (MPR on the rounded
 * shapes) and apart (GJK), to 1e-9. */
static void test_pair_ellipsoid_sphere_overlap(void)
{
    rs_shape el, sp;
    ENSURE(rs_shape_make_ellipsoid(&el, 0.5, 0.5, 0.5, 0.0, NULL) == RS_OK);
    ENSURE(rs_shape_make_sphere(&sp, 0.3, 0.0, NULL) == RS_OK);
    for (int t = 0; t < 50; t++) {
        double d[3];
        for (int k = 0; k < 3; k++)
            d[k] = 2.0 * urand() - 1.0;
        unit(d);
        const double dist = 0.55 + 0.4 * urand();
        const double xa[3] = {0.1, 0.2, 0.3};
        const double xb[3] = {xa[0] + dist * d[0], xa[1] + dist * d[1],
                              xa[2] + dist * d[2]};
        rs_body a, b;
        rs_convex_contact c;
        ENSURE(rs_body_init(&a, &el, 1.0, xa, q_id, NULL) == RS_OK);
        ENSURE(rs_body_init(&b, &sp, 1.0, xb, q_id, NULL) == RS_OK);
        ENSURE(rs_convex_pair(&a, &b, 0.2, &c, NULL) == RS_OK);
        ENSURE(contact_ok(&c, 0.8 - dist, d, 1e-9));
    }
}

/* Bad arguments. */
static void test_pair_bad_arguments(void)
{
    rs_shape sp;
    ENSURE(rs_shape_make_sphere(&sp, 0.3, 0.0, NULL) == RS_OK);
    rs_body a;
    const double x[3] = {0, 0, 0};
    ENSURE(rs_body_init(&a, &sp, 1.0, x, q_id, NULL) == RS_OK);
    rs_convex_contact c;
    rs_error err;
    ENSURE(rs_convex_pair(&a, &a, -1.0, &c, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "gap_max = -1"));
    const double tri[9] = {0, 0, 0, 1, 0, 0, 0, NAN, 0};
    ENSURE(rs_convex_triangle(&a, tri, 0.1, &c, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "triangle corner 3 is not finite"));
    /* a corner far beyond any length the queries resolve against the body */
    const double far[9] = {0, 0, 0, 1, 0, 0, 0, 1, 1e300};
    ENSURE(rs_convex_triangle(&a, far, 0.1, &c, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "triangle corner 3 is not finite or has a coordinate beyond"));
    a.q[0] = 0.5;
    ENSURE(rs_convex_pair(&a, &a, 0.1, &c, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "quaternion"));
}

int main(void)
{
    RS_RUN(test_pair_sphere_sphere_exact);
    RS_RUN(test_pair_sphere_triangle);
    RS_RUN(test_pair_box_triangle_face_down);
    RS_RUN(test_pair_box_box);
    RS_RUN(test_pair_ellipsoid_sphere_overlap);
    RS_RUN(test_pair_bad_arguments);
    return rs_test_summary();
}
