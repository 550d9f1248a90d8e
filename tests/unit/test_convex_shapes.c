/* Convex shapes (convex.h): supports against brute force over sampled surfaces, the
 * ellipsoid's closed-form support, the rounding's Minkowski identity, bounds, the body's
 * world support through an independent rotation, canonical hulls (the same shape bit for
 * bit from the same points in any order, every call), and every bad shape named, a make
 * call that fails leaving no shape. */
#include "rigidsurf/convex.h"
#include "rigidsurf/motion.h"
#include "rigidsurf/vec.h"
#include "rs_test.h"
#include "rs_test_geom.h"

#include <stdlib.h>

enum { NS = 200000 };
static double pts[3 * NS];

static void rand_dir(double d[3])
{
    do {
        for (int k = 0; k < 3; k++)
            d[k] = 2.0 * urand() - 1.0;
    } while (rs_dot3(d, d) > 1.0 || rs_dot3(d, d) < 1e-4);
    unit(d);
}

/* Points on the surface of each built-in core (built-in frames; the cone's core with
 * its centroid at the origin). Returns how many. */
static int sample(const rs_shape *s)
{
    const double *h = s->dim;
    int n = 0;
    const int nu = 400, nw = 400;
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nw; j++) {
            const double u = RS_PI * (i + 0.5) / nu, w = 2.0 * RS_PI * j / nw;
            const double c[3] = {sin(u) * cos(w), sin(u) * sin(w), cos(u)};
            double *p = pts + 3 * n++;
            switch (s->kind) {
            case RS_SHAPE_ELLIPSOID:
                for (int k = 0; k < 3; k++)
                    p[k] = h[k] * c[k];
                break;
            case RS_SHAPE_SPHERE:
                for (int k = 0; k < 3; k++)
                    p[k] = h[0] * c[k];
                break;
            case RS_SHAPE_CAPSULE: /* two half-spheres and the mantle */
                for (int k = 0; k < 3; k++)
                    p[k] = h[0] * c[k];
                p[2] += c[2] >= 0.0 ? h[1] : -h[1];
                break;
            case RS_SHAPE_CYLINDER: /* the two rims */
                p[0] = h[0] * cos(w);
                p[1] = h[0] * sin(w);
                p[2] = (i & 1) ? h[1] : -h[1];
                break;
            case RS_SHAPE_CONE: /* rim and apex */
                p[0] = h[0] * cos(w);
                p[1] = h[0] * sin(w);
                p[2] = -0.25 * h[1];
                if (i == 0 && j == 0) {
                    p[0] = p[1] = 0.0;
                    p[2] = 0.75 * h[1];
                }
                break;
            case RS_SHAPE_BOX:
                for (int k = 0; k < 3; k++)
                    p[k] = ((i * nw + j) >> k & 1) ? h[k] : -h[k];
                break;
            default:
                break;
            }
        }
    return n;
}

/* support(d).d equals the largest d.p over the samples, to the sampling error tol */
static int check_support(const rs_shape *s, double tol)
{
    const int n = sample(s);
    for (int t = 0; t < 300; t++) {
        double d[3], sp[3];
        rand_dir(d);
        rs_shape_support(s, d, sp);
        double best = -INFINITY;
        for (int i = 0; i < n; i++)
            best = fmax(best, rs_dot3(pts + 3 * i, d));
        const double h = rs_dot3(sp, d);
        if (!(h >= best - 1e-12 && h - best <= tol)) {
            fprintf(stderr, "kind %d: support %.17g, samples %.17g\n", (int)s->kind, h,
                    best);
            return 0;
        }
    }
    return 1;
}

static void test_support_brute_force(void)
{
    rs_shape s;
    ENSURE(rs_shape_make_ellipsoid(&s, 1.0, 2.0, 0.5, 0.0, NULL) == RS_OK);
    ENSURE(check_support(&s, 2e-4));
    ENSURE(rs_shape_make_sphere(&s, 0.7, 0.0, NULL) == RS_OK);
    ENSURE(check_support(&s, 2e-4));
    ENSURE(rs_shape_make_box(&s, 1.0, 0.3, 2.0, 0.0, NULL) == RS_OK);
    ENSURE(check_support(&s, 1e-14));
    ENSURE(rs_shape_make_cylinder(&s, 0.8, 1.5, 0.0, NULL) == RS_OK);
    ENSURE(check_support(&s, 1e-4));
    ENSURE(rs_shape_make_capsule(&s, 0.4, 1.0, 0.0, NULL) == RS_OK);
    ENSURE(check_support(&s, 1e-4));
    ENSURE(rs_shape_make_cone(&s, 0.6, 2.0, 0.0, NULL) == RS_OK);
    ENSURE(check_support(&s, 1e-4));
}

/* The ellipsoid's support is the point whose normal is d: x_i = a_i^2 d_i / |A d|, and
 * it lies on the surface. */
static void test_support_ellipsoid_closed_form(void)
{
    rs_shape s;
    const double a[3] = {3.0, 0.5, 1.25};
    ENSURE(rs_shape_make_ellipsoid(&s, a[0], a[1], a[2], 0.0, NULL) == RS_OK);
    for (int t = 0; t < 1000; t++) {
        double d[3], p[3];
        rand_dir(d);
        rs_shape_support(&s, d, p);
        const double ad = sqrt(a[0] * a[0] * d[0] * d[0] + a[1] * a[1] * d[1] * d[1] +
                               a[2] * a[2] * d[2] * d[2]);
        double on = 0.0;
        for (int k = 0; k < 3; k++) {
            ENSURE_NEAR(p[k], a[k] * a[k] * d[k] / ad, 1e-14);
            on += p[k] * p[k] / (a[k] * a[k]);
        }
        ENSURE_NEAR(on, 1.0, 1e-14);
    }
}

/* A support point lies on its shape: inside every bound and on one face or surface. */
static void test_support_on_shape(void)
{
    rs_shape box, cyl, cone;
    ENSURE(rs_shape_make_box(&box, 1.0, 0.3, 2.0, 0.0, NULL) == RS_OK);
    ENSURE(rs_shape_make_cylinder(&cyl, 0.8, 1.5, 0.0, NULL) == RS_OK);
    ENSURE(rs_shape_make_cone(&cone, 0.6, 2.0, 0.0, NULL) == RS_OK);
    for (int t = 0; t < 1000; t++) {
        double d[3], p[3];
        rand_dir(d);
        rs_shape_support(&box, d, p);
        for (int k = 0; k < 3; k++)
            ENSURE_NEAR(fabs(p[k]), box.dim[k], 0.0); /* a corner */
        rs_shape_support(&cyl, d, p);
        ENSURE_NEAR(hypot(p[0], p[1]), 0.8, 1e-15);
        ENSURE_NEAR(fabs(p[2]), 1.5, 0.0);
        rs_shape_support(&cone, d, p);
        const double rho = hypot(p[0], p[1]);
        ENSURE((fabs(rho - 0.6) < 1e-15 && p[2] == -0.5) || (rho == 0.0 && p[2] == 1.5));
    }
}

/* Rounding is a Minkowski sum with a ball: s_r(d) = s_0(d) + r d / |d|, for every kind,
 * and a sphere and a capsule are a point and a segment rounded by their radius. */
static void test_rounding_minkowski(void)
{
    const double r = 0.3;
    rs_shape a[6], b[6];
    ENSURE(rs_shape_make_ellipsoid(&a[0], 1.0, 2.0, 0.5, 0.0, NULL) == RS_OK);
    ENSURE(rs_shape_make_ellipsoid(&b[0], 1.0, 2.0, 0.5, r, NULL) == RS_OK);
    ENSURE(rs_shape_make_box(&a[1], 1.0, 0.3, 2.0, 0.0, NULL) == RS_OK);
    ENSURE(rs_shape_make_box(&b[1], 1.0, 0.3, 2.0, r, NULL) == RS_OK);
    ENSURE(rs_shape_make_cylinder(&a[2], 0.8, 1.5, 0.0, NULL) == RS_OK);
    ENSURE(rs_shape_make_cylinder(&b[2], 0.8, 1.5, r, NULL) == RS_OK);
    ENSURE(rs_shape_make_capsule(&a[3], 0.4, 1.0, 0.0, NULL) == RS_OK);
    ENSURE(rs_shape_make_capsule(&b[3], 0.4, 1.0, r, NULL) == RS_OK);
    ENSURE(rs_shape_make_sphere(&a[4], 0.4, 0.0, NULL) == RS_OK);
    ENSURE(rs_shape_make_sphere(&b[4], 0.4, r, NULL) == RS_OK);
    ENSURE(rs_shape_make_cone(&a[5], 0.6, 2.0, 0.0, NULL) == RS_OK);
    ENSURE(rs_shape_make_cone(&b[5], 0.6, 2.0, r, NULL) == RS_OK);
    for (int t = 0; t < 500; t++) {
        double d[3], p[3], q[3];
        rand_dir(d);
        for (int i = 0; i < 6; i++) {
            rs_shape_support(&a[i], d, p);
            rs_shape_support(&b[i], d, q);
            for (int k = 0; k < 3; k++) /* the rounded cone sits shifted in its frame */
                ENSURE_NEAR(q[k] + b[i].shift[k], p[k] + a[i].shift[k] + r * d[k], 1e-14);
        }
        /* a sphere: the radius along d; a capsule: an end centre plus the radius */
        rs_shape_support(&a[4], d, p);
        for (int k = 0; k < 3; k++)
            ENSURE_NEAR(p[k], 0.4 * d[k], 1e-15);
        rs_shape_support(&a[3], d, p);
        ENSURE_NEAR(p[2], (d[2] >= 0.0 ? 1.0 : -1.0) + 0.4 * d[2], 1e-15);
    }
}

/* The polyhedron: support(d).d is the largest d.p over all the input points (interior
 * ones included), and the support is one of them (shifted to the body frame). */
static void test_support_polyhedron(void)
{
    enum { N = 500 };
    double xyz[3 * N];
    for (int i = 0; i < N; i++) {
        double d[3];
        rand_dir(d);
        const double r = (i % 3) ? 1.0 : 0.5 * urand();
        for (int k = 0; k < 3; k++)
            xyz[3 * i + k] = r * d[k] * (k == 2 ? 0.5 : 1.0) + (k == 0 ? 3.0 : 0.0);
    }
    rs_shape s;
    rs_error err;
    ENSURE(rs_shape_make_polyhedron(&s, xyz, N, 0.0, &err) == RS_OK);
    ENSURE(s.nv >= 4 && s.nv <= N && s.nt == 2 * s.nv - 4);
    for (int t = 0; t < 500; t++) {
        double d[3], p[3];
        rand_dir(d);
        rs_shape_support(&s, d, p);
        double best = -INFINITY, dmin = INFINITY;
        for (int i = 0; i < N; i++) {
            double q[3];
            for (int k = 0; k < 3; k++)
                q[k] = xyz[3 * i + k] - s.shift[k];
            best = fmax(best, rs_dot3(q, d));
            dmin = fmin(dmin, fabs(q[0] - p[0]) + fabs(q[1] - p[1]) + fabs(q[2] - p[2]));
        }
        ENSURE_NEAR(rs_dot3(p, d), best, 1e-14);
        ENSURE_SMALL(dmin, 1e-14);
    }
    rs_shape_free(&s);
}

/* A user's support: a box given through a callback behaves as the built-in box. */
static void box_support(const void *obj, const double d[3], double out[3])
{
    const double *h = obj;
    for (int k = 0; k < 3; k++)
        out[k] = d[k] < 0.0 ? -h[k] : h[k];
}

static void test_user_shape(void)
{
    static const double h[3] = {1.0, 0.3, 2.0};
    rs_shape u, b;
    ENSURE(rs_shape_make_user(&u, h, box_support, 0.2, NULL) == RS_OK);
    ENSURE(rs_shape_make_box(&b, 1.0, 0.3, 2.0, 0.2, NULL) == RS_OK);
    for (int t = 0; t < 200; t++) {
        double d[3], p[3], q[3];
        rand_dir(d);
        rs_shape_support(&u, d, p);
        rs_shape_support(&b, d, q);
        for (int k = 0; k < 3; k++)
            ENSURE_NEAR(p[k], q[k], 1e-15);
    }
    rs_mass_props mp;
    rs_error err;
    ENSURE(rs_shape_mass_props(&u, 1.0, &mp, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "user shape"));
}

/* Bounds: a rounded box's box, a cylinder's, an ellipsoid's semi-axes plus rounding. */
static void test_bounds(void)
{
    rs_shape s;
    double lo[3], hi[3];
    ENSURE(rs_shape_make_box(&s, 1.0, 0.3, 2.0, 0.1, NULL) == RS_OK);
    rs_shape_bounds(&s, lo, hi);
    ENSURE_NEAR(hi[0], 1.1, 1e-15);
    ENSURE_NEAR(lo[1], -0.4, 1e-15);
    ENSURE_NEAR(hi[2], 2.1, 1e-15);
    ENSURE(rs_shape_make_ellipsoid(&s, 1.0, 2.0, 0.5, 0.25, NULL) == RS_OK);
    rs_shape_bounds(&s, lo, hi);
    ENSURE_NEAR(hi[0], 1.25, 1e-15);
    ENSURE_NEAR(lo[1], -2.25, 1e-15);
    ENSURE_NEAR(hi[2], 0.75, 1e-15);
    ENSURE(rs_shape_make_cone(&s, 0.6, 2.0, 0.0, NULL) == RS_OK);
    rs_shape_bounds(&s, lo, hi);
    ENSURE_NEAR(lo[2], -0.5, 1e-15);
    ENSURE_NEAR(hi[2], 1.5, 1e-15);
    ENSURE_NEAR(hi[0], 0.6, 1e-15);
}

/* The body's support in the world: x + R s(R^T d), R from the quaternion
 * (cos(a/2), sin(a/2) axis) compared with Rodrigues' matrix for the same rotation. */
static void test_body_support_world(void)
{
    rs_shape s;
    ENSURE(rs_shape_make_box(&s, 1.0, 0.3, 2.0, 0.1, NULL) == RS_OK);
    double axis[3] = {1.0, -2.0, 0.5};
    unit(axis);
    const double ang = 0.7, x[3] = {1.0, 2.0, -3.0};
    const double q[4] = {cos(0.5 * ang), sin(0.5 * ang) * axis[0], sin(0.5 * ang) * axis[1],
                         sin(0.5 * ang) * axis[2]};
    rs_body b;
    rs_error err;
    ENSURE(rs_body_init(&b, &s, 2.0, x, q, &err) == RS_OK);
    double R[9], Rb[9];
    rs_rotation_matrix(axis, ang, R);
    rs_body_rotation(&b, Rb);
    for (int k = 0; k < 9; k++)
        ENSURE_NEAR(Rb[k], R[k], 1e-15);
    for (int t = 0; t < 100; t++) {
        double d[3], db[3], p[3], w[3];
        rand_dir(d);
        for (int i = 0; i < 3; i++)
            db[i] = R[i] * d[0] + R[3 + i] * d[1] + R[6 + i] * d[2];
        rs_shape_support(&s, db, p);
        rs_body_support(&b, d, w);
        for (int i = 0; i < 3; i++)
            ENSURE_NEAR(w[i],
                        x[i] + R[3 * i] * p[0] + R[3 * i + 1] * p[1] + R[3 * i + 2] * p[2],
                        1e-14);
    }
}

#define ENSURE_ERR(call, want, text)                                                       \
    do {                                                                                   \
        rs_error e_;                                                                       \
        rs_error_clear(&e_);                                                               \
        ENSURE((call) == (want));                                                          \
        ENSURE(e_.code == (want));                                                         \
        if (!strstr(e_.msg, text)) {                                                       \
            fprintf(stderr, "message '%s' lacks '%s'\n", e_.msg, text);                    \
            ENSURE(0);                                                                     \
        }                                                                                  \
    } while (0)

/* Bad shapes, each with its message. */
static void test_bad_shapes(void)
{
    rs_shape s;
    ENSURE_ERR(rs_shape_make_sphere(&s, NAN, 0.0, &e_), RS_ERR_ARG, "sphere radius = nan");
    ENSURE_ERR(rs_shape_make_sphere(&s, 0.0, 0.0, &e_), RS_ERR_ARG,
               "expected a finite number > 0");
    ENSURE_ERR(rs_shape_make_ellipsoid(&s, 1.0, -2.0, 1.0, 0.0, &e_), RS_ERR_ARG,
               "ellipsoid semi-axis b = -2");
    ENSURE_ERR(rs_shape_make_box(&s, 1.0, 1.0, INFINITY, 0.0, &e_), RS_ERR_ARG,
               "box half-extent z = inf");
    ENSURE_ERR(rs_shape_make_cylinder(&s, 1.0, 0.0, 0.0, &e_), RS_ERR_ARG,
               "cylinder half-height = 0");
    ENSURE_ERR(rs_shape_make_capsule(&s, -1.0, 1.0, 0.0, &e_), RS_ERR_ARG,
               "capsule radius = -1");
    ENSURE_ERR(rs_shape_make_cone(&s, 1.0, NAN, 0.0, &e_), RS_ERR_ARG, "cone height = nan");
    ENSURE_ERR(rs_shape_make_box(&s, 1.0, 1.0, 1.0, -0.1, &e_), RS_ERR_ARG,
               "rounding radius = -0.1 (expected a finite number >= 0, at most 1e+100)");
    /* lengths beyond any coordinate the queries take */
    ENSURE_ERR(rs_shape_make_cone(&s, 1e300, 2.0, 0.0, &e_), RS_ERR_ARG,
               "cone radius = 1e+300 (expected a finite number > 0, at most 1e+100)");
    ENSURE_ERR(rs_shape_make_sphere(&s, 1.0, 1e101, &e_), RS_ERR_ARG, "rounding radius");
    /* a length whose square is not a normal number: an ellipsoid's support along its
     * axis was NaN (tests/fuzz/corpus/body_triangle_nan_witness.bin) */
    ENSURE_ERR(
        rs_shape_make_ellipsoid(&s, 7.5625, 3.0625, 4.9406564584124654e-324, 0.0, &e_),
        RS_ERR_ARG, "lengths are at least 1e-100");
    ENSURE(rs_shape_make_ellipsoid(&s, 1e100, 1.0, 1e-100, 0.0, NULL) == RS_OK);
    const double dirs[4][3] = {{0, 0, 1}, {0, 0, 1e-300}, {1e-300, 0, -1e-300}, {1, 1, 1}};
    for (int k = 0; k < 4; k++) {
        double p[3];
        rs_shape_support(&s, dirs[k], p);
        ENSURE(isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2]));
        ENSURE(rs_dot3(p, dirs[k]) >= 0.0);
    }
    ENSURE_ERR(rs_shape_make_user(&s, NULL, NULL, 0.0, &e_), RS_ERR_ARG,
               "no support function");
    /* points in one plane, too few points, a non-finite point */
    const double flat[15] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0.5, 0.2, 0};
    ENSURE_ERR(rs_shape_make_polyhedron(&s, flat, 5, 0.0, &e_), RS_ERR_GEOMETRY,
               "lie in one plane (expected at least 4 that are not coplanar)");
    const double three[9] = {0, 0, 0, 1, 0, 0, 0, 1, 1};
    ENSURE_ERR(rs_shape_make_polyhedron(&s, three, 3, 0.0, &e_), RS_ERR_GEOMETRY,
               "3 points (expected at least 4");
    const double line[12] = {0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3};
    ENSURE_ERR(rs_shape_make_polyhedron(&s, line, 4, 0.0, &e_), RS_ERR_GEOMETRY,
               "one plane");
    const double bad[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, NAN};
    ENSURE_ERR(rs_shape_make_polyhedron(&s, bad, 4, 0.0, &e_), RS_ERR_ARG,
               "point 4 is not finite");
    /* a quaternion that is not unit to 1e-12, a bad density */
    rs_body b;
    ENSURE(rs_shape_make_sphere(&s, 1.0, 0.0, NULL) == RS_OK);
    const double x[3] = {0, 0, 0}, q[4] = {1.0 + 1e-11, 0, 0, 0}, q1[4] = {1.0, 0, 0, 0};
    ENSURE_ERR(rs_body_init(&b, &s, 1.0, x, q, &e_), RS_ERR_ARG,
               "expected a unit quaternion to 1e-12");
    const double qn[4] = {0.6, 0.8 + 5e-13, 0, 0};
    ENSURE(rs_body_init(&b, &s, 1.0, x, qn, NULL) == RS_OK);
    ENSURE_ERR(rs_body_init(&b, &s, -1.0, x, q1, &e_), RS_ERR_ARG, "density = -1");
    ENSURE_ERR(rs_shape_mass_props(&s, 0.0, &(rs_mass_props){0}, &e_), RS_ERR_ARG,
               "density = 0");
    /* a body whose mass properties overflow: a box of 1e100 a side */
    rs_shape big;
    ENSURE(rs_shape_make_box(&big, 1e100, 1e100, 1e100, 0.0, NULL) == RS_OK);
    ENSURE_ERR(rs_body_init(&b, &big, 1000.0, x, q1, &e_), RS_ERR_ARG,
               "mass properties of the shape with density 1000 are not finite");
    const double far[3] = {0, 1e101, 0};
    ENSURE_ERR(rs_body_init(&b, &s, 1.0, far, q1, &e_), RS_ERR_ARG,
               "body position x[1] = 1e+101");
}

/* The hull of 500 points made five times, and from the points shuffled and doubled:
 * the same arrays bit for bit (CGAL's own order changes from call to call); its
 * vertices sorted (x, then y, then z), each an input point, and extreme: no input point
 * beyond a triangle's plane, and three planes or more at each vertex; a grid of 5^3
 * points gives the cube's 8 corners and 12 triangles, a square pyramid with points on
 * its edges and faces its 5 corners and 6 triangles. */
static void test_hulls_are_canonical(void)
{
    enum { N = 500 };
    static double xyz[3 * N], mixed[6 * N];
    for (int i = 0; i < N; i++) {
        double d[3];
        rand_dir(d);
        const double r = (i % 4) ? 1.0 : urand();
        for (int k = 0; k < 3; k++)
            xyz[3 * i + k] = r * d[k];
    }
    for (int i = 0; i < 2 * N; i++) { /* every point twice, in another order */
        const int j = (i * 337) % N;
        memcpy(mixed + 3 * i, xyz + 3 * j, 3 * sizeof *xyz);
    }
    rs_shape ref;
    ENSURE(rs_shape_make_polyhedron(&ref, xyz, N, 0.0, NULL) == RS_OK);
    for (int rep = 0; rep < 6; rep++) {
        rs_shape s;
        ENSURE(rs_shape_make_polyhedron(&s, rep < 5 ? xyz : mixed, rep < 5 ? N : 2 * N, 0.0,
                                        NULL) == RS_OK);
        ENSURE(s.nv == ref.nv && s.nt == ref.nt);
        ENSURE(!memcmp(s.verts, ref.verts, 3 * (size_t)s.nv * sizeof *s.verts));
        ENSURE(!memcmp(s.tris, ref.tris, 3 * (size_t)s.nt * sizeof *s.tris));
        ENSURE(!memcmp(s.shift, ref.shift, sizeof s.shift));
        rs_shape_free(&s);
    }
    for (int v = 0; v < ref.nv; v++) {
        const double *p = ref.verts + 3 * v;
        if (v > 0) {
            const double *o = p - 3;
            ENSURE(o[0] < p[0] ||
                   (o[0] == p[0] && (o[1] < p[1] || (o[1] == p[1] && o[2] < p[2]))));
        }
        int input = 0, planes = 0;
        double seen[64][3];
        for (int i = 0; i < N && !input; i++)
            input = xyz[3 * i] - ref.shift[0] == p[0] &&
                    xyz[3 * i + 1] - ref.shift[1] == p[1] &&
                    xyz[3 * i + 2] - ref.shift[2] == p[2];
        ENSURE(input);
        for (int t = 0; t < ref.nt; t++) {
            const int *tv = ref.tris + 3 * t;
            if (tv[0] != v && tv[1] != v && tv[2] != v)
                continue;
            double e1[3], e2[3], n[3];
            for (int k = 0; k < 3; k++) {
                e1[k] = ref.verts[3 * tv[1] + k] - ref.verts[3 * tv[0] + k];
                e2[k] = ref.verts[3 * tv[2] + k] - ref.verts[3 * tv[0] + k];
            }
            rs_cross3(e1, e2, n);
            unit(n);
            int known = 0;
            for (int q = 0; q < planes; q++)
                known |= rs_dot3(n, seen[q]) > 1.0 - 1e-12;
            if (!known && planes < 64)
                memcpy(seen[planes++], n, sizeof n);
        }
        ENSURE(planes >= 3);
    }
    for (int t = 0; t < ref.nt; t++) {
        const int *tv = ref.tris + 3 * t;
        double e1[3], e2[3], n[3];
        for (int k = 0; k < 3; k++) {
            e1[k] = ref.verts[3 * tv[1] + k] - ref.verts[3 * tv[0] + k];
            e2[k] = ref.verts[3 * tv[2] + k] - ref.verts[3 * tv[0] + k];
        }
        rs_cross3(e1, e2, n);
        unit(n);
        for (int i = 0; i < N; i++) {
            double w[3];
            for (int k = 0; k < 3; k++)
                w[k] = xyz[3 * i + k] - ref.shift[k] - ref.verts[3 * tv[0] + k];
            ENSURE(rs_dot3(w, n) <= 1e-14);
        }
    }
    rs_shape_free(&ref);
    /* degenerate sets: points on the faces and edges */
    double grid[3 * 125], pyr[3 * 64];
    int ng = 0, np = 0;
    for (int i = 0; i < 5; i++)
        for (int j = 0; j < 5; j++)
            for (int k = 0; k < 5; k++, ng++)
                grid[3 * ng] = 0.25 * i, grid[3 * ng + 1] = 0.25 * j,
                         grid[3 * ng + 2] = 0.25 * k;
    for (int i = 0; i <= 4; i++) /* the square base's grid and the apex's edges */
        for (int j = 0; j <= 4; j++, np++)
            pyr[3 * np] = 0.5 * i, pyr[3 * np + 1] = 0.5 * j, pyr[3 * np + 2] = 0.0;
    for (int c = 0; c < 4; c++)
        for (int k = 1; k <= 4; k++, np++) {
            const double f = 0.25 * k, bx = (c & 1) ? 2.0 : 0.0, by = (c & 2) ? 2.0 : 0.0;
            pyr[3 * np] = bx + f * (1.0 - bx), pyr[3 * np + 1] = by + f * (1.0 - by);
            pyr[3 * np + 2] = f;
        }
    rs_shape cube, py;
    ENSURE(rs_shape_make_polyhedron(&cube, grid, ng, 0.0, NULL) == RS_OK);
    ENSURE(cube.nv == 8 && cube.nt == 12);
    ENSURE(rs_shape_make_polyhedron(&py, pyr, np, 0.0, NULL) == RS_OK);
    ENSURE(py.nv == 5 && py.nt == 6);
    rs_mass_props mp;
    ENSURE(rs_shape_mass_props(&cube, 1.0, &mp, NULL) == RS_OK);
    ENSURE_NEAR(mp.volume, 1.0, 1e-15);
    rs_shape_free(&cube);
    rs_shape_free(&py);
}

/* A hull of 10^4 points (on an ellipsoid, and a third of them inside): its support, found
 * by climbing the hull's vertex graph, is a vertex with the largest d.v of all the
 * points, along 2000 directions and the axes (ties on a flat face included: a box's
 * corners among its surface's points). */
static void test_large_hull_support_climbs_to_the_top(void)
{
    enum { N = 10000 };
    static double xyz[3 * N];
    for (int i = 0; i < N; i++) {
        double d[3];
        rand_dir(d);
        const double r = (i % 3) ? 1.0 : urand();
        xyz[3 * i] = 2.0 * r * d[0], xyz[3 * i + 1] = r * d[1],
                xyz[3 * i + 2] = 0.5 * r * d[2];
    }
    for (int pass = 0; pass < 2; pass++) {
        if (pass) /* a box: points on its faces, many of them on a face's plane */
            for (int i = 0; i < N; i++) {
                const int f = i % 6;
                for (int k = 0; k < 3; k++)
                    xyz[3 * i + k] =
                        k == f / 2 ? (f & 1 ? 1.0 : -1.0) : 2.0 * urand() - 1.0;
            }
        rs_shape s;
        ENSURE(rs_shape_make_polyhedron(&s, xyz, N, 0.0, NULL) == RS_OK);
        ENSURE(s.nv > 64);
        for (int t = 0; t < 2006; t++) {
            double d[3] = {0, 0, 0}, p[3];
            if (t < 6)
                d[t / 2] = t & 1 ? -1.0 : 1.0;
            else
                rand_dir(d);
            rs_shape_support(&s, d, p);
            double best = -INFINITY;
            for (int i = 0; i < N; i++) {
                double q[3];
                for (int k = 0; k < 3; k++)
                    q[k] = xyz[3 * i + k] - s.shift[k];
                best = fmax(best, rs_dot3(q, d));
            }
            ENSURE(rs_dot3(p, d) >= best - 1e-15 * fmax(1.0, fabs(best)));
        }
        rs_shape_free(&s);
    }
}

/* A make call that fails leaves no shape: the mass properties and a body refuse it by
 * name; a hull whose volume is lost to rounding is a geometry error, not "out of
 * memory"; so are points that span a volume to the exact tests only by a denormal
 * coordinate, which CGAL's hull constructions in doubles take for a plane (a fuzz input,
 * tests/fuzz/corpus/body_hull_denormal_plane.bin: its polygon was read past its end). */
static void test_a_failed_make_leaves_no_shape(void)
{
    rs_shape s;
    ENSURE(rs_shape_make_box(&s, 1.0, 1.0, 1.0, 0.0, NULL) == RS_OK);
    ENSURE(rs_shape_make_box(&s, -1.0, 1.0, 1.0, 0.0, NULL) == RS_ERR_ARG);
    rs_mass_props mp;
    ENSURE_ERR(rs_shape_mass_props(&s, 1.0, &mp, &e_), RS_ERR_ARG,
               "not one an rs_shape_make_* call made");
    rs_body b;
    const double x[3] = {0, 0, 0}, q[4] = {1, 0, 0, 0};
    ENSURE_ERR(rs_body_init(&b, &s, 0.0, x, q, &e_), RS_ERR_ARG, "rs_shape_make_*");
    const double flat[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
    ENSURE(rs_shape_make_polyhedron(&s, flat, 4, 0.0, NULL) == RS_ERR_GEOMETRY);
    ENSURE_ERR(rs_shape_mass_props(&s, 1.0, &mp, &e_), RS_ERR_ARG, "rs_shape_make_*");
    const double tiny[12] = {0, 0, 0, 1e-110, 0, 0, 0, 1e-110, 0, 0, 0, 1e-110};
    ENSURE_ERR(rs_shape_make_polyhedron(&s, tiny, 4, 0.0, &e_), RS_ERR_GEOMETRY,
               "has volume 0 (expected a volume > 0");
    ENSURE(s.verts == NULL);
    const double h = 4.6875, dn = 4.9406564584124654e-324;
    const double denormal[15] = {h, h, h, h, h, 0, 0, dn, -7.5, -8, -8, -8, -8, -8, -8};
    ENSURE_ERR(rs_shape_make_polyhedron(&s, denormal, 5, 0.0, &e_), RS_ERR_GEOMETRY,
               "too close to one plane");
    ENSURE(s.verts == NULL);
}

/* A slender hull keeps every extreme point: a right prism of 24 sides, radius 0.5 and
 * length 10 (a rod-like rounded body's core), has its 48 corners as vertices and
 * 2 * 48 - 4 triangles (CGAL's triangle-set output of the hull kept 40 of them), each
 * corner within rounding of the hull (its support along the corner's own direction is
 * the corner), and its centre of mass on the axis. */
static void test_slender_hull_keeps_every_corner(void)
{
    enum { NSIDE = 24 };
    double xyz[3 * 2 * NSIDE];
    for (int e = 0; e < 2; e++)
        for (int k = 0; k < NSIDE; k++) {
            double *p = xyz + 3 * (e * NSIDE + k);
            const double a = 2.0 * acos(-1.0) * k / NSIDE;
            p[0] = 0.5 * cos(a);
            p[1] = e ? 5.0 : -5.0;
            p[2] = 0.5 * sin(a);
        }
    rs_shape s;
    ENSURE(rs_shape_make_polyhedron(&s, xyz, 2 * NSIDE, 0.0, NULL) == RS_OK);
    ENSURE(s.nv == 2 * NSIDE);
    ENSURE(s.nt == 4 * NSIDE - 4);
    for (int d = 0; d < 3; d++)
        ENSURE(fabs(s.shift[d]) < 1e-14);
    for (int i = 0; i < 2 * NSIDE; i++) {
        const double *p = xyz + 3 * i;
        double out[3];
        rs_shape_support(&s, p, out);
        ENSURE(fabs(out[0] - p[0]) + fabs(out[1] - p[1]) + fabs(out[2] - p[2]) < 1e-14);
    }
    rs_shape_free(&s);
}

int main(void)
{
    RS_RUN(test_support_brute_force);
    RS_RUN(test_support_ellipsoid_closed_form);
    RS_RUN(test_support_on_shape);
    RS_RUN(test_rounding_minkowski);
    RS_RUN(test_support_polyhedron);
    RS_RUN(test_user_shape);
    RS_RUN(test_bounds);
    RS_RUN(test_body_support_world);
    RS_RUN(test_bad_shapes);
    RS_RUN(test_hulls_are_canonical);
    RS_RUN(test_large_hull_support_climbs_to_the_top);
    RS_RUN(test_a_failed_make_leaves_no_shape);
    RS_RUN(test_slender_hull_keeps_every_corner);
    return rs_test_summary();
}
