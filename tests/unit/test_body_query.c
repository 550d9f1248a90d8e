/* A convex body as a slave (rs_body_query): its manifold against closed forms.
 * - A rounded box tilted a little over a plane: its four lowest corners, each rounded
 *   toward the plane, with their own depths (corner height less the rounding), ids 1 + v
 *   and witness points on the body.
 * - A capsule beside the drum's fillet of its own radius, on the mantle: the fixed point
 *   of the deepest point does not settle there (rs_body_surface_contacts says so); the
 *   manifold answers with the capsule's ends, each with the depth of its end sphere
 *   against the fillet, the mantle or the cap, in the drum's profile plane.
 * - A polyhedron of 10^4 points on a sphere, within its hull's sagitta of the sphere.
 * - One query of a block of spheres, points and bodies.
 * - A body's query answers every owning feature: a ball nearly filling a faceted cavity
 *   meets more than 32 faces, the faces and depths of its sphere query.
 * - Every kind checks a body's pose: a quaternion that is not finite or not of norm 1
 *   to 1e-6 is refused with a message; one within 1e-6 is taken normalised.
 * - The refusals. */
#include "rigidsurf/convex.h"
#include "rigidsurf/vec.h"
#include "rs_test.h"
#include "rs_test_geom.h"

#include <stdlib.h>

static const char *PLANE = "*SURFACE, TYPE=CYLINDER, NAME=floor\n"
                           "0, 0, 0, 1, 0, 0\n0, -1, 0\nSTART, -10, 0\nLINE, 10, 0\n";

/* examples/surfaces/drum.inp: radius 0.1 about z, caps at z = 0 and 0.06, fillets 0.005 */
static const char *DRUM = "*SURFACE, TYPE=REVOLUTION, NAME=drum, FILLET RADIUS=0.005\n"
                          "0, 0, 0,  0, 0, 1\nSTART, 0, 0\nLINE, 0.1, 0\nLINE, 0.1, 0.06\n"
                          "LINE, 0, 0.06\n";

static void test_tilted_rounded_box_rests_on_its_four_lowest_corners(void)
{
    rs_surface s;
    rs_error e;
    ENSURE(rs_surface_parse(PLANE, "t", NULL, &s, &e) == RS_OK);
    rs_shape sh;
    const double h[3] = {0.2, 0.1, 0.05}, r = 0.01;
    ENSURE(rs_shape_make_box(&sh, h[0], h[1], h[2], r, NULL) == RS_OK);
    const double a = 0.005; /* about the body x + y diagonal */
    const double q[4] = {cos(0.5 * a), sin(0.5 * a) / sqrt(2.0), sin(0.5 * a) / sqrt(2.0),
                         0};
    const double x[3] = {0.3, -0.1, 0.058};
    rs_body b;
    ENSURE(rs_body_init(&b, &sh, 1000.0, x, q, &e) == RS_OK);
    rs_contacts c;
    memset(&c, 0, sizeof c);
    c.witness = 1;
    ENSURE(rs_body_query(&s, NULL, &b, 7, 0.05, 1e-3, &c, &e) == RS_OK);
    ENSURE(c.n == 4);
    double R[9];
    rs_quat_matrix(q, R);
    for (int k = 0; k < c.n; k++) {
        const int j = c.feature[k] / RS_MANIFOLD_STRIDE, v = j - 1;
        ENSURE(j >= 1 && j <= 4); /* the corners with body z = -h */
        ENSURE(RS_FEATURE_OWNER(c.feature[k]) == c.feature[k] % RS_MANIFOLD_STRIDE);
        const double bc[3] = {(v & 1) ? h[0] : -h[0], (v & 2) ? h[1] : -h[1], -h[2]};
        double w[3];
        rs_matvec3(R, bc, w);
        const double depth = -(x[2] + w[2] - r); /* the rounding sphere's lowest point */
        ENSURE(c.point[k] == 7);
        ENSURE_NEAR(0.05 - c.dist[k], depth, 1e-14);
        ENSURE_NEAR(c.xs[0][k], x[0] + w[0], 1e-14);
        ENSURE_NEAR(c.xs[1][k], x[1] + w[1], 1e-14);
        ENSURE_NEAR(c.xs[2][k], x[2] + w[2] - r, 1e-14);
        ENSURE_NEAR(c.nrm[2][k], 1.0, 1e-15);
        /* corners apart by far more than their patches: shares 1 but for ((a_i + a_j) /
         * D)^16 */
        ENSURE_NEAR(c.share[k], 1.0, 1e-12);
    }
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* The same tilted rounded box over a MESH floor of two triangles whose diagonal runs
 * under it: the four corners, each on the face under it, one plane. */
static void test_box_across_a_mesh_floor_rests_on_its_four_corners(void)
{
    const double xyz[12] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
    const int tri[6] = {0, 1, 2, 0, 2, 3};
    const rs_mesh_def def = RS_MESH_DEF_INIT;
    rs_surface s;
    rs_error e;
    ENSURE(rs_surface_make_mesh(xyz, 4, tri, 2, &def, &s, &e) == RS_OK);
    rs_shape sh;
    const double h[3] = {0.2, 0.1, 0.05}, r = 0.01;
    ENSURE(rs_shape_make_box(&sh, h[0], h[1], h[2], r, NULL) == RS_OK);
    const double a = 0.005;
    const double q[4] = {cos(0.5 * a), sin(0.5 * a) / sqrt(2.0), sin(0.5 * a) / sqrt(2.0),
                         0};
    const double x[3] = {0.01, -0.02, 0.058};
    rs_body b;
    ENSURE(rs_body_init(&b, &sh, 1000.0, x, q, &e) == RS_OK);
    rs_contacts c;
    memset(&c, 0, sizeof c);
    c.witness = 1;
    ENSURE(rs_body_query(&s, NULL, &b, 0, 0.05, 1e-3, &c, &e) == RS_OK);
    ENSURE(c.n == 4);
    double R[9];
    rs_quat_matrix(q, R);
    int faces[2] = {0, 0};
    for (int k = 0; k < c.n; k++) {
        const int j = c.feature[k] / RS_MANIFOLD_STRIDE, v = j - 1;
        ENSURE(j >= 1 && j <= 4);
        const double bc[3] = {(v & 1) ? h[0] : -h[0], (v & 2) ? h[1] : -h[1], -h[2]};
        double w[3];
        rs_matvec3(R, bc, w);
        ENSURE_NEAR(0.05 - c.dist[k], -(x[2] + w[2] - r), 1e-14);
        ENSURE_NEAR(c.nrm[2][k], 1.0, 1e-15);
        /* the face under the corner: triangle 0 below the diagonal y = x */
        const int t = (x[1] + w[1]) > (x[0] + w[0]) ? 1 : 0;
        ENSURE(RS_FEATURE_OWNER(c.feature[k]) == RS_FEATURE(RS_FEAT_FACE, 0) ||
               RS_FEATURE_OWNER(c.feature[k]) == RS_FEATURE(RS_FEAT_FACE, 1));
        faces[t]++;
    }
    ENSURE(faces[0] > 0 && faces[1] > 0); /* the corners lie over both triangles */
    rs_contacts_free(&c);
    rs_shape_free(&sh);
    rs_surface_free(&s);
}

/* The depth of a sphere (centre rho, z in the profile plane, radius rs) in the drum:
 * against the fillet at the top corner (centre 0.095, 0.055) where the centre lies in
 * its quarter, else against the mantle or the top cap. */
static double drum_depth(double rho, double z, double rs, int *fillet)
{
    *fillet = rho > 0.095 && z > 0.055;
    if (*fillet)
        return rs - (0.005 - hypot(rho - 0.095, z - 0.055));
    return fmax(rho + rs - 0.1, z + rs - 0.06);
}

static void test_capsule_in_a_fillet_of_its_own_radius_rests_on_its_ends(void)
{
    rs_surface s;
    rs_error e;
    ENSURE(rs_surface_parse(DRUM, "t", NULL, &s, &e) == RS_OK);
    rs_shape sh;
    ENSURE(rs_shape_make_capsule(&sh, 0.005, 0.008, 0.0, NULL) == RS_OK);
    /* a pose of examples/convex where the deepest point did not settle */
    const double x[3] = {0.068748541070068295, -0.065104750225140437, 0.052727723272117527};
    const double q[4] = {-0.6733699418012018, 0.16103842546321814, -0.59332658599922727,
                         -0.41061308959831666};
    rs_body b;
    ENSURE(rs_body_init(&b, &sh, 1000.0, x, q, &e) == RS_OK);
    rs_body_contact bc[8];
    int nb = 0;
    ENSURE(rs_body_surface_contacts(&s, NULL, &b, 5e-4, bc, 8, &nb, &e) == RS_ERR_GEOMETRY);
    ENSURE(strstr(e.msg, "did not settle") != NULL);

    rs_contacts c;
    memset(&c, 0, sizeof c);
    c.witness = 1;
    ENSURE(rs_body_query(&s, NULL, &b, 0, 0.0, 5e-4, &c, &e) == RS_OK);
    ENSURE(c.n >= 1);
    double R[9];
    rs_quat_matrix(q, R);
    for (int k = 0; k < c.n; k++) {
        const int j = c.feature[k] / RS_MANIFOLD_STRIDE;
        ENSURE(j == 1 || j == 2); /* an end, never an unsettled deepest point */
        const double end[3] = {x[0] + (j == 1 ? 1 : -1) * 0.008 * R[2],
                               x[1] + (j == 1 ? 1 : -1) * 0.008 * R[5],
                               x[2] + (j == 1 ? 1 : -1) * 0.008 * R[8]};
        int fil;
        const double depth = drum_depth(hypot(end[0], end[1]), end[2], 0.005, &fil);
        (void)fil;
        ENSURE_NEAR(-c.dist[k], depth, 1e-12);
        /* its witness point is on the end's sphere */
        const double d[3] = {c.xs[0][k] - end[0], c.xs[1][k] - end[1], c.xs[2][k] - end[2]};
        ENSURE_NEAR(rs_norm3(d), 0.005, 1e-12);
    }
    rs_contacts_free(&c);
    rs_shape_free(&sh);
    rs_surface_free(&s);
}

/* A polyhedron of 10^4 points on a sphere of radius R (a Fibonacci lattice) over a
 * plane, in several orientations: its deepest contact lies within the hull's sagitta
 * of the sphere's, R - z, and no contact is deeper. The sagitta is R less the nearest
 * plane of a hull face to the centre. */
static void test_fine_polyhedron_agrees_with_its_sphere_within_the_sagitta(void)
{
    rs_surface s;
    rs_error e;
    ENSURE(rs_surface_parse(PLANE, "t", NULL, &s, &e) == RS_OK);
    enum { N = 10000 };
    const double R = 0.05, golden = RS_PI * (3.0 - sqrt(5.0));
    double *xyz = malloc(3 * N * sizeof *xyz);
    ENSURE(xyz != NULL);
    for (int i = 0; i < N; i++) {
        const double z = 1.0 - (2.0 * i + 1.0) / N, r = sqrt(1.0 - z * z);
        xyz[3 * i] = R * r * cos(golden * i);
        xyz[3 * i + 1] = R * r * sin(golden * i);
        xyz[3 * i + 2] = R * z;
    }
    rs_shape sh;
    ENSURE(rs_shape_make_polyhedron(&sh, xyz, N, 0.0, &e) == RS_OK);
    free(xyz);
    ENSURE(sh.nv == N);
    double inner = INFINITY;
    for (int t = 0; t < sh.nt; t++) {
        const double *a = sh.verts + 3 * sh.tris[3 * t],
                     *b = sh.verts + 3 * sh.tris[3 * t + 1],
                     *c = sh.verts + 3 * sh.tris[3 * t + 2];
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        double n[3];
        rs_cross3(u, v, n);
        inner = fmin(inner, fabs(rs_dot3(n, a) + rs_dot3(n, sh.shift)) / rs_norm3(n));
    }
    const double sag = R - inner;
    ENSURE(sag > 0.0 && sag < 1e-3 * R);
    const double quats[3][4] = {{1, 0, 0, 0}, {0.9, 0.3, -0.2, 0.1}, {0.2, 0.7, 0.5, -0.4}};
    for (int k = 0; k < 3; k++) {
        double q[4];
        const double nq = sqrt(quats[k][0] * quats[k][0] + quats[k][1] * quats[k][1] +
                               quats[k][2] * quats[k][2] + quats[k][3] * quats[k][3]);
        for (int j = 0; j < 4; j++)
            q[j] = quats[k][j] / nq;
        const double x[3] = {0.01 * k, 0.0, R - 1e-4};
        rs_body b;
        /* the body frame is the points' frame less the centre of mass (shift) */
        ENSURE(rs_body_init(&b, &sh, 1000.0, x, q, &e) == RS_OK);
        rs_contacts c;
        memset(&c, 0, sizeof c);
        c.witness = 1;
        ENSURE(rs_body_query(&s, NULL, &b, 0, R, 1e-3, &c, &e) == RS_OK);
        ENSURE(c.n >= 1 && c.n <= RS_MANIFOLD_MAX);
        double deepest = -INFINITY;
        for (int j = 0; j < c.n; j++)
            deepest = fmax(deepest, R - c.dist[j]);
        /* the sphere of radius R about the points' centre, which is the body's x + R(q)
         * (-shift): within the sagitta of 1e-4 */
        double R9[9], off[3];
        rs_quat_matrix(q, R9);
        const double ms[3] = {-sh.shift[0], -sh.shift[1], -sh.shift[2]};
        rs_matvec3(R9, ms, off);
        const double sphere = R - (x[2] + off[2]);
        ENSURE(deepest <= sphere + 1e-15);
        ENSURE(deepest >= sphere - sag);
        rs_contacts_free(&c);
    }
    rs_shape_free(&sh);
    rs_surface_free(&s);
}

/* One query of a block of a sphere, a body, a point and a body: the spheres' and the
 * points' contacts are the kind's own (with the witness x - R n), the bodies' are
 * rs_body_query's, all in block order; without witness points the block is refused. */
static void test_a_block_of_spheres_and_bodies_is_one_query(void)
{
    rs_surface s;
    rs_error e;
    ENSURE(rs_surface_parse(PLANE, "t", NULL, &s, &e) == RS_OK);
    rs_shape box, cap;
    ENSURE(rs_shape_make_box(&box, 0.1, 0.1, 0.1, 0.0, NULL) == RS_OK);
    ENSURE(rs_shape_make_capsule(&cap, 0.05, 0.1, 0.0, NULL) == RS_OK);
    const double x[4] = {0, 1, 2, 3}, y[4] = {0, 0, 0, 0},
                 z[4] = {0.049, 0.099, -0.001, 0.0};
    const double r[4] = {0.05, 0.1, 0.0, 0.05};
    rs_body bodies[4];
    memset(bodies, 0, sizeof bodies);
    const double q0[4] = {1, 0, 0, 0}, q1[4] = {sqrt(0.5), sqrt(0.5), 0, 0};
    const double xb[3] = {1, 0, 0.099}, xc[3] = {3, 0, 0.0499};
    ENSURE(rs_body_init(&bodies[1], &box, 1.0, xb, q0, &e) == RS_OK);
    ENSURE(rs_body_init(&bodies[3], &cap, 1.0, xc, q1, &e) == RS_OK);
    rs_query q = {.n = 4,
                  .slave = {.x = x, .y = y, .z = z, .radius = r, .body = bodies},
                  .pose = NULL,
                  .gap_max = 1e-3,
                  .dist_min = -INFINITY};
    rs_contacts c;
    memset(&c, 0, sizeof c);
    ENSURE(rs_surface_query(&s, &q, &c, &e) == RS_ERR_ARG);
    ENSURE(strstr(e.msg, "witness") != NULL);
    c.witness = 1;
    c.n = 0;
    ENSURE(rs_surface_query(&s, &q, &c, &e) == RS_OK);
    /* the sphere: one contact, depth 1e-3; the box: its four lower corners, 1e-3; the
     * point: depth 1e-3; the capsule on its side: its two ends, 1e-4 */
    int count[4] = {0, 0, 0, 0};
    for (int k = 0; k < c.n; k++) {
        const int i = c.point[k];
        ENSURE(i >= 0 && i < 4 && (k == 0 || i >= c.point[k - 1]));
        count[i]++;
        const double depth = r[i] - c.dist[k];
        ENSURE_NEAR(depth, i == 3 ? 1e-4 : 1e-3, 1e-15);
        ENSURE_NEAR(c.xs[2][k], i == 2 ? -1e-3 : i == 3 ? -1e-4 : -1e-3, 1e-15);
        if (i == 0 || i == 2) {
            ENSURE_NEAR(c.xs[0][k], x[i], 0.0);
            ENSURE(c.feature[k] < RS_MANIFOLD_STRIDE);
        }
    }
    ENSURE(count[0] == 1 && count[1] == 4 && count[2] == 1 && count[3] == 2);
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* A list that keeps witness points and then, grown without them, keeps them again has
 * them as long as its other arrays (the sanitizer build checks the writes). */
static void test_witness_points_follow_the_list(void)
{
    rs_contacts c;
    memset(&c, 0, sizeof c);
    c.witness = 1;
    ENSURE(rs_contacts_reserve(&c, 4, NULL) == RS_OK);
    ENSURE(c.xs[0] != NULL);
    c.witness = 0;
    ENSURE(rs_contacts_reserve(&c, 100, NULL) == RS_OK);
    ENSURE(c.xs[0] == NULL);
    c.witness = 1;
    ENSURE(rs_contacts_reserve(&c, 100, NULL) == RS_OK);
    ENSURE(c.xs[0] != NULL && c.cap >= 100);
    for (int d = 0; d < 3; d++)
        c.xs[d][c.cap - 1] = 1.0;
    rs_contacts_free(&c);
}

/* A ball of radius 0.018 inside a cavity of radius 0.02 (32 x 64 facets), against its
 * side: within 3e-5 of 34 faces, more than the 32 a body could once answer; as a body
 * it has the contacts of its sphere query (one per face, the same depths). */
static void test_a_body_answers_every_owning_feature(void)
{
    rs_surface s;
    ENSURE(uv_cavity(0.02, 32, 64, &s));
    rs_shape ball;
    ENSURE(rs_shape_make_sphere(&ball, 0.018, 0.0, NULL) == RS_OK);
    const double x[3] = {0.002 + 1e-6, 0.0, 3e-4}, q[4] = {1, 0, 0, 0}, R = 0.018;
    rs_body b;
    ENSURE(rs_body_init(&b, &ball, 1000.0, x, q, NULL) == RS_OK);
    rs_contacts c, n;
    memset(&c, 0, sizeof c);
    memset(&n, 0, sizeof n);
    c.witness = 1;
    rs_error e;
    ENSURE(rs_body_query(&s, NULL, &b, 0, R, 3e-5, &c, &e) == RS_OK);
    rs_query sq = {.n = 1,
                   .slave = {.x = x, .y = x + 1, .z = x + 2, .radius = &R},
                   .gap_max = 3e-5,
                   .dist_min = -INFINITY};
    ENSURE(rs_surface_query(&s, &sq, &n, &e) == RS_OK);
    ENSURE(c.n > 32);
    ENSURE(c.n == n.n);
    for (int k = 0; k < c.n; k++) {
        int j = 0;
        while (j < n.n && n.feature[j] != c.feature[k])
            j++;
        ENSURE(j < n.n);
        ENSURE_NEAR(c.dist[k], n.dist[j], 1e-15);
    }
    rs_contacts_free(&c);
    rs_contacts_free(&n);
    rs_surface_free(&s);
}

/* Each kind (SEGMENTS, CYLINDER, REVOLUTION, MESH): a box's quaternion with a NaN, of
 * norm 0.5 or 1 + 2e-6 is refused by rs_body_query and rs_body_surface_contacts, naming
 * the quaternion (not answered with no contact and no error, a body falling through); of
 * norm 1 + 1e-7 it is taken normalised: the contacts of the unit quaternion. */
static void test_every_kind_checks_the_pose(void)
{
    static const char *SEG = "*SURFACE, TYPE=SEGMENTS, NAME=line\nSTART, -1, 0\n"
                             "LINE, 1, 0\n";
    rs_surface s[4];
    ENSURE(rs_surface_parse(SEG, "seg", NULL, &s[0], NULL) == RS_OK);
    ENSURE(rs_surface_parse(PLANE, "plane", NULL, &s[1], NULL) == RS_OK);
    ENSURE(rs_surface_parse(DRUM, "drum", NULL, &s[2], NULL) == RS_OK);
    const double xyz[12] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
    const int tri[6] = {0, 1, 2, 0, 2, 3};
    const rs_mesh_def def = RS_MESH_DEF_INIT;
    ENSURE(rs_surface_make_mesh(xyz, 4, tri, 2, &def, &s[3], NULL) == RS_OK);
    rs_shape box;
    ENSURE(rs_shape_make_box(&box, 0.02, 0.01, 0.005, 0.0, NULL) == RS_OK);
    const double pos[4][3] = {
        {0.1, 0.0105, 0.0}, {0.1, 0.0, 0.0072}, {0.09, 0.0, 0.03}, {0.1, 0.2, 0.0072}};
    const double tilt = 0.3, q[4] = {cos(0.5 * tilt), sin(0.5 * tilt), 0.0, 0.0};
    for (int k = 0; k < 4; k++) {
        rs_body b;
        ENSURE(rs_body_init(&b, &box, 1000.0, pos[k], q, NULL) == RS_OK);
        rs_contacts ref, c;
        memset(&ref, 0, sizeof ref);
        memset(&c, 0, sizeof c);
        ref.witness = c.witness = 1;
        rs_error e;
        ENSURE(rs_body_query(&s[k], NULL, &b, 0, 0.02, 1e-3, &ref, &e) == RS_OK);
        ENSURE(ref.n > 0);
        const double bad[3] = {NAN, 0.5, 1.0 + 2e-6};
        for (int j = 0; j < 3; j++) {
            rs_body w = b;
            for (int i = 0; i < 4; i++)
                w.q[i] = j == 0 && i == 2 ? NAN : q[i] * bad[j];
            c.n = 0;
            ENSURE(rs_body_query(&s[k], NULL, &w, 0, 0.02, 1e-3, &c, &e) == RS_ERR_ARG);
            ENSURE(strstr(e.msg, "quaternion") != NULL);
            rs_body_contact bc[16];
            int nb = -1;
            ENSURE(rs_body_surface_contacts(&s[k], NULL, &w, 1e-3, bc, 16, &nb, &e) ==
                   RS_ERR_ARG);
            ENSURE(strstr(e.msg, "quaternion") != NULL && nb == 0);
        }
        rs_body w = b;
        for (int i = 0; i < 4; i++)
            w.q[i] = q[i] * (1.0 + 1e-7);
        c.n = 0;
        ENSURE(rs_body_query(&s[k], NULL, &w, 0, 0.02, 1e-3, &c, &e) == RS_OK);
        ENSURE(c.n == ref.n);
        for (int i = 0; i < c.n; i++) {
            ENSURE(c.feature[i] == ref.feature[i]);
            ENSURE_NEAR(c.dist[i], ref.dist[i], 1e-15);
        }
        rs_contacts_free(&ref);
        rs_contacts_free(&c);
        rs_surface_free(&s[k]);
    }
}

static void test_refusals(void)
{
    rs_surface s;
    rs_error e;
    ENSURE(rs_surface_parse(PLANE, "t", NULL, &s, &e) == RS_OK);
    rs_shape sh;
    ENSURE(rs_shape_make_box(&sh, 0.1, 0.1, 0.1, 0.0, NULL) == RS_OK);
    const double x[3] = {0, 0, 0.1}, q[4] = {1, 0, 0, 0};
    rs_body b;
    ENSURE(rs_body_init(&b, &sh, 1000.0, x, q, &e) == RS_OK);
    rs_contacts c;
    memset(&c, 0, sizeof c);
    ENSURE(rs_body_query(&s, NULL, &b, 0, 0.1, 1e-3, &c, &e) == RS_ERR_ARG);
    ENSURE(strstr(e.msg, "witness") != NULL);
    c.witness = 1;
    ENSURE(rs_body_query(&s, NULL, &b, 0, NAN, 1e-3, &c, &e) == RS_ERR_ARG);
    ENSURE(rs_body_query(&s, NULL, &b, 0, 0.1, -1.0, &c, &e) == RS_ERR_ARG);
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

int main(void)
{
    RS_RUN(test_tilted_rounded_box_rests_on_its_four_lowest_corners);
    RS_RUN(test_box_across_a_mesh_floor_rests_on_its_four_corners);
    RS_RUN(test_capsule_in_a_fillet_of_its_own_radius_rests_on_its_ends);
    RS_RUN(test_fine_polyhedron_agrees_with_its_sphere_within_the_sagitta);
    RS_RUN(test_a_block_of_spheres_and_bodies_is_one_query);
    RS_RUN(test_witness_points_follow_the_list);
    RS_RUN(test_a_body_answers_every_owning_feature);
    RS_RUN(test_every_kind_checks_the_pose);
    RS_RUN(test_refusals);
    return rs_test_summary();
}
