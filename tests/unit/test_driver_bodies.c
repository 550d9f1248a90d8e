/* Convex bodies in the standalone driver (rs_driver_set_body, rs_body_query) against
 * closed forms of rigid-body mechanics on the plane z = 0, with the linear law hooke:
 * - an ellipsoid held in any orientation comes to rest at its support value along the
 *   normal, less the law's overlap;
 * - a cube dropped flat rests on its four corners (overlap v0 sqrt(m / 4 kn)) and
 *   rebounds at its speed without spin; dropped on an edge, it leaves with the velocity
 *   and spin of a frictionless elastic impact at that edge;
 * - elastic frictionless bodies bouncing under gravity keep their energy;
 * - a box on a slope (gravity turned by theta) sticks while tan(theta) < mu, slides at
 *   g (sin(theta) - mu cos(theta)) when it does not, and tips at tan(theta) = w / h;
 * - a cylinder, and a capsule on its cylindrical part, rolls down the slope at
 *   (2/3) g sin(theta);
 * - a rounded box at rest on its face stays at rest (no rocking);
 * - a sphere given as a body moves as the driver's sphere node;
 * - a polyhedron whose points' axes are not principal is turned into its principal axes
 *   (and bounces with the others in the energy test);
 * - a body in a drum given analytically and as a MESH moves alike, within the facets'
 *   angle, frictionless (keeping its energy on both) and rolling with friction;
 * - two runs of a hull of 500 points, each making its hull and its principal axes, end
 *   bit for bit alike. */
#include "rigidsurf/driver.h"
#include "rigidsurf/vec.h"
#include "rs_test.h"
#include "rs_test_driver.h"
#include "rs_test_geom.h"

/* One driver on the plane with n nodes and hooke (kn, kt, zeta_n, zeta_t, mu). */
static int setup(rs_driver *d, rs_surface *s, int n, const double hooke[5], double dt)
{
    return rs_test_driver_on_plane(d, s, n, hooke, dt);
}

static int step(rs_driver *d)
{
    rs_error e;
    rs_error_clear(&e);
    if (rs_driver_step(d, &e) != RS_OK) {
        fprintf(stderr, "step %d: %s\n", d->inc, e.msg);
        return 0;
    }
    return 1;
}

static void quat_axis(double angle, const double axis[3], double q[4])
{
    const double n = rs_norm3(axis);
    q[0] = cos(0.5 * angle);
    for (int k = 0; k < 3; k++)
        q[k + 1] = sin(0.5 * angle) * axis[k] / n;
}

/* The angle of node i's body z axis (column 2 of R(q)) from the world z axis. */
static double tilt_z(const rs_driver *d, int i)
{
    double R[9];
    rs_quat_matrix(d->q + 4 * i, R);
    return acos(fmin(1.0, fabs(R[8])));
}

static double norm_w(const rs_driver *d, int i)
{
    return sqrt(d->wx[i] * d->wx[i] + d->wy[i] * d->wy[i] + d->wz[i] * d->wz[i]);
}

/* A unit cube (half 0.5, mass 1) dropped flat at 1 m/s without gravity, kn = 1e5: four
 * corner contacts, each a spring kn, so the deepest overlap is v0 sqrt(m / (4 kn)); it
 * leaves at 1 m/s (the spring is elastic) and does not turn. */
static void test_cube_dropped_flat_rests_on_four_corners_and_rebounds(void)
{
    rs_surface s;
    rs_driver d;
    const double law[5] = {1e5, 1e5, 0.0, 0.0, 0.0};
    ENSURE(setup(&d, &s, 1, law, 1e-5));
    rs_shape cube;
    ENSURE(rs_shape_make_box(&cube, 0.5, 0.5, 0.5, 0.0, NULL) == RS_OK);
    ENSURE(rs_driver_set_body(&d, 0, &cube, 1.0, NULL) == RS_OK);
    ENSURE_NEAR(d.mass[0], 1.0, 1e-14);
    d.z[0] = 0.5 + 1e-4;
    d.vz[0] = -1.0;
    double zmin = 1.0;
    int most = 0;
    for (int k = 0; k < 20000 && !(d.z[0] > 0.5 + 2e-3); k++) {
        ENSURE(step(&d));
        zmin = fmin(zmin, d.z[0]);
        most = d.trk.n > most ? d.trk.n : most;
        ENSURE_SMALL(norm_w(&d, 0), 1e-12);
    }
    ENSURE(d.z[0] > 0.5 + 2e-3);
    ENSURE(most == 4);
    ENSURE_NEAR(0.5 - zmin, sqrt(1.0 / 4e5), 2e-3 * sqrt(1.0 / 4e5));
    /* central differences: a contact that starts and ends between steps costs or gives
     * energy of order (omega dt)^2 = 4e-5, omega^2 = 4 kn / m */
    ENSURE_NEAR(d.vz[0], 1.0, 1e-5);
    ENSURE_SMALL(d.vx[0], 1e-12);
    ENSURE_SMALL(d.vy[0], 1e-12);
    rs_driver_free(&d);
    rs_surface_free(&s);
}

/* An ellipsoid (semi-axes D) held in an orientation (no moments of inertia: it keeps its
 * zero spin) let down onto the plane under gravity, damped: it comes to rest with its
 * centre at the support value along the normal, h = sqrt(e_z^T R D^2 R^T e_z), less the
 * law's overlap m g / kn, in any orientation. */
static void test_ellipsoid_rests_at_its_support_height(void)
{
    const double D[3] = {0.02, 0.012, 0.01}, g = 9.81, kn = 1e5;
    const double law[5] = {kn, kn, 0.7, 0.7, 0.0};
    const double axes[4][4] = {{0.0, 1, 0, 0},
                               {0.7, 1, 0, 0},
                               {1.1, 0.3, -0.5, 0.8},
                               {2.5, -0.2, 0.9, 0.4}}; /* angle, axis */
    rs_shape ell;
    ENSURE(rs_shape_make_ellipsoid(&ell, D[0], D[1], D[2], 0.0, NULL) == RS_OK);
    for (int c = 0; c < 4; c++) {
        rs_surface s;
        rs_driver d;
        ENSURE(setup(&d, &s, 1, law, 2e-5));
        ENSURE(rs_driver_set_body(&d, 0, &ell, 1000.0, NULL) == RS_OK);
        quat_axis(axes[c][0], axes[c] + 1, d.q);
        double R[9];
        rs_quat_matrix(d.q, R);
        double v[3];
        const double h = ellipsoid_low(R, D, v);
        for (int k = 0; k < 3; k++)
            d.inertia[k] = 0.0;
        d.z[0] = h + 5e-5;
        d.fext[2] = -g * d.mass[0];
        for (int k = 0; k < 10000; k++)
            ENSURE(step(&d));
        const double delta = d.mass[0] * g / kn; /* about 1e-6 */
        ENSURE(d.trk.n == 1);
        ENSURE_NEAR(d.z[0], h - delta, 1e-6 * delta);
        ENSURE_SMALL(d.vz[0], 1e-9);
        rs_driver_free(&d);
        rs_surface_free(&s);
    }
}

/* A cube turned by phi about x dropped at v0 on its lowest edge, frictionless and
 * elastic: the edge is at lever arm r (horizontal offset y_e of the edge from the
 * centre), so the impulse is J = 2 v0 / (1/m + r^2 / I) and the cube leaves with
 * vz = J / m - v0 and wx = J r / I (the sign of the edge's side). */
static void test_cube_dropped_on_an_edge_leaves_with_the_impulse_about_it(void)
{
    rs_surface s;
    rs_driver d;
    const double law[5] = {1e7, 1e7, 0.0, 0.0, 0.0};
    ENSURE(setup(&d, &s, 1, law, 2e-6));
    rs_shape cube;
    ENSURE(rs_shape_make_box(&cube, 0.5, 0.5, 0.5, 0.0, NULL) == RS_OK);
    ENSURE(rs_driver_set_body(&d, 0, &cube, 1.0, NULL) == RS_OK);
    const double phi = 0.3, ax[3] = {1, 0, 0};
    quat_axis(phi, ax, d.q);
    /* the lowest edge: body (y, z) = (-0.5, -0.5) turned by phi about x */
    const double ye = -0.5 * cos(phi) + 0.5 * sin(phi),
                 ze = -0.5 * sin(phi) - 0.5 * cos(phi);
    d.z[0] = -ze + 1e-4;
    d.vz[0] = -1.0;
    const double I = d.inertia[0], m = d.mass[0];
    ENSURE_NEAR(I, 1.0 / 6.0, 1e-14);
    int touched = 0;
    for (int k = 0; k < 200000; k++) {
        ENSURE(step(&d));
        touched |= d.trk.n > 0;
        if (touched && d.trk.n == 0)
            break;
    }
    ENSURE(touched && d.trk.n == 0);
    /* the torque of an upward impulse at (ye, ze) about x: ye J */
    const double J = 2.0 / (1.0 / m + ye * ye / I);
    ENSURE_NEAR(d.vz[0], J / m - 1.0, 5e-3);
    ENSURE_NEAR(d.wx[0], ye * J / I, 5e-3 * fabs(ye * J / I));
    ENSURE_SMALL(d.vy[0], 1e-9);
    rs_driver_free(&d);
    rs_surface_free(&s);
}

/* Elastic frictionless bodies (a tilted spinning box, capsule, cylinder and rounded
 * rock, a polyhedron whose points' axes are not principal) bouncing
 * under gravity: kinetic + potential + elastic energy stays at its start, to the
 * scheme's O(dt^2) and without a drift up. */
static void test_elastic_bodies_keep_their_energy(void)
{
    rs_surface s;
    rs_driver d;
    const double law[5] = {1e7, 1e7, 0.0, 0.0, 0.0}, g = 9.81;
    ENSURE(setup(&d, &s, 4, law, 2e-5));
    rs_shape sh[4];
    ENSURE(rs_shape_make_box(&sh[0], 0.3, 0.2, 0.1, 0.0, NULL) == RS_OK);
    ENSURE(rs_shape_make_capsule(&sh[1], 0.1, 0.2, 0.0, NULL) == RS_OK);
    ENSURE(rs_shape_make_cylinder(&sh[2], 0.15, 0.1, 0.02, NULL) == RS_OK);
    const double rock[18] = {0,   0,    0,   0.3, 0,   0,    0,     0.25, 0,
                             0.1, 0.05, 0.2, 0.2, 0.2, 0.15, -0.05, 0.1,  0.1};
    ENSURE(rs_shape_make_polyhedron(&sh[3], rock, 6, 0.01, NULL) == RS_OK);
    const double axes[4][3] = {{1, 2, 3}, {-1, 0.5, 0.2}, {0.3, -1, 1}, {0.2, 0.4, -1}};
    for (int i = 0; i < 4; i++) {
        ENSURE(rs_driver_set_body(&d, i, &sh[i], 1000.0, NULL) == RS_OK);
        quat_axis(0.4 + 0.3 * i, axes[i], d.q + 4 * i);
        d.x[i] = 3.0 * i;
        d.z[i] = 0.6;
        d.wx[i] = 2.0 - i;
        d.wy[i] = 1.0;
        d.fext[3 * i + 2] = -g * d.mass[i];
        d.vx[i] = 0.2;
    }
    double e0 = 0.0;
    int flights = 0;
    for (int k = 0; k < 60000; k++) {
        ENSURE(step(&d));
        double pe = 0.0;
        for (int i = 0; i < 4; i++)
            pe += d.mass[i] * g * d.z[i];
        const double e = d.energy.allke + d.energy.allse + pe;
        if (k == 0)
            e0 = e;
        /* in flight, where the kinetic energy of the half steps is the whole of it;
         * a bounce's error is of order (omega dt)^2 = 3e-4 (omega^2 = kn / m) */
        if (d.trk.n == 0) {
            ENSURE(e <= e0 * (1.0 + 5e-4));
            ENSURE(e >= e0 * (1.0 - 5e-4));
            flights++;
        }
    }
    ENSURE(flights > 30000);
    rs_shape_free(&sh[3]);
    rs_driver_free(&d);
    rs_surface_free(&s);
}

/* A box (w = 0.2 along the slope, h = 0.4 up, unit depth) resting on the plane under
 * gravity turned by theta about y: x is down the slope. Damped normal contact. Returns
 * the mean acceleration down the slope over [t1, t2] and the largest tilt. */
static int slope_run(double theta, double mu, double t1, double t2, double *acc,
                     double *tilt)
{
    rs_surface s;
    rs_driver d;
    const double law[5] = {1e6, 1e6, 0.5, 0.5, mu}, g = 9.81;
    if (!setup(&d, &s, 1, law, 1e-5))
        return 0;
    rs_shape box;
    if (rs_shape_make_box(&box, 0.1, 0.5, 0.2, 0.0, NULL) != RS_OK ||
        rs_driver_set_body(&d, 0, &box, 1.0, NULL) != RS_OK)
        return 0;
    const double m = d.mass[0];
    d.z[0] = 0.2 - g * cos(theta) * m / 4e6; /* at rest on its four corners */
    d.fext[0] = m * g * sin(theta);
    d.fext[2] = -m * g * cos(theta);
    double v1 = 0.0;
    *tilt = 0.0;
    const int k1 = (int)lround(t1 / d.dt), k2 = (int)lround(t2 / d.dt);
    for (int k = 0; k <= k2; k++) {
        if (!step(&d))
            return 0;
        if (k == k1)
            v1 = d.vx[0];
        *tilt = fmax(*tilt, tilt_z(&d, 0));
    }
    *acc = (d.vx[0] - v1) / ((k2 - k1) * d.dt);
    rs_driver_free(&d);
    rs_surface_free(&s);
    return 1;
}

static void test_box_on_a_slope_sticks_slides_and_tips(void)
{
    const double g = 9.81;
    double a, tilt;
    /* w / h = 0.5: with mu = 0.2 it slides at tan(theta) = 0.3 */
    const double th = atan(0.3);
    ENSURE(slope_run(th, 0.2, 0.1, 0.3, &a, &tilt));
    ENSURE_NEAR(a, g * (sin(th) - 0.2 * cos(th)), 5e-3 * g);
    ENSURE_SMALL(tilt, 1e-2);
    /* mu = 0.4 > tan(theta) = 0.3: it sticks */
    ENSURE(slope_run(th, 0.4, 0.1, 0.3, &a, &tilt));
    ENSURE_SMALL(a, 1e-3 * g);
    /* mu = 0.8 > w / h: it tips once tan(theta) > w / h = 0.5, not before */
    ENSURE(slope_run(atan(0.45), 0.8, 0.1, 0.5, &a, &tilt));
    ENSURE_SMALL(tilt, 1e-2);
    ENSURE(slope_run(atan(0.6), 0.8, 0.1, 0.5, &a, &tilt));
    ENSURE(tilt > 0.3);
}

/* A body with its axis (body z) along world y rolling down the slope (gravity turned
 * by theta about y) without slip: a = g sin(theta) / (1 + I / (m r^2)), 2/3 g sin(theta)
 * for a solid cylinder; a capsule on its cylindrical part rolls as its core cylinder
 * with its own I and m. Returns the acceleration over [0.1, 0.3] s. */
static int roll_run(const rs_shape *sh, double r, double theta, double *acc, double *pred)
{
    rs_surface s;
    rs_driver d;
    const double law[5] = {1e6, 1e6, 0.5, 0.5, 0.8}, g = 9.81;
    if (!setup(&d, &s, 1, law, 1e-5))
        return 0;
    if (rs_driver_set_body(&d, 0, sh, 1000.0, NULL) != RS_OK)
        return 0;
    const double ax[3] = {1, 0, 0};
    quat_axis(-0.5 * RS_PI, ax, d.q); /* body z to world y */
    const double m = d.mass[0];
    d.z[0] = r - g * cos(theta) * m / 2e6; /* at rest on the two ends of its line */
    d.fext[0] = m * g * sin(theta);
    d.fext[2] = -m * g * cos(theta);
    /* the moment of inertia about the rolling axis, the body's z */
    *pred = g * sin(theta) / (1.0 + d.inertia[2] / (m * r * r));
    double v1 = 0.0;
    for (int k = 0; k <= 30000; k++) {
        if (!step(&d))
            return 0;
        if (k == 10000)
            v1 = d.vx[0];
    }
    *acc = (d.vx[0] - v1) / (20000 * d.dt);
    rs_driver_free(&d);
    rs_surface_free(&s);
    return 1;
}

static void test_cylinder_and_capsule_roll_at_two_thirds_g_sin(void)
{
    const double g = 9.81, th = 0.3;
    double a, pred;
    rs_shape cyl, cap;
    ENSURE(rs_shape_make_cylinder(&cyl, 0.05, 0.1, 0.0, NULL) == RS_OK);
    ENSURE(roll_run(&cyl, 0.05, th, &a, &pred));
    ENSURE_NEAR(pred, 2.0 / 3.0 * g * sin(th), 1e-12);
    ENSURE_NEAR(a, pred, 5e-3 * pred);
    /* a capsule rests on its cylindrical part: a = g sin / (1 + I/(m r^2)) */
    ENSURE(rs_shape_make_capsule(&cap, 0.05, 0.1, 0.0, NULL) == RS_OK);
    ENSURE(roll_run(&cap, 0.05, th, &a, &pred));
    ENSURE_NEAR(a, pred, 5e-3 * pred);
}

/* A rounded box at rest on its face under gravity, damped: its four corners hold it,
 * and it does not rock. */
static void test_rounded_box_at_rest_does_not_rock(void)
{
    rs_surface s;
    rs_driver d;
    const double law[5] = {1e5, 1e5, 0.7, 0.7, 0.5}, g = 9.81;
    ENSURE(setup(&d, &s, 1, law, 1e-4));
    rs_shape box;
    ENSURE(rs_shape_make_box(&box, 0.2, 0.1, 0.05, 0.01, NULL) == RS_OK);
    ENSURE(rs_driver_set_body(&d, 0, &box, 1000.0, NULL) == RS_OK);
    const double m = d.mass[0];
    d.x[0] = 0.3;
    d.y[0] = -0.2;
    d.z[0] = 0.06 - 0.9 * g * m / 4e5;
    d.fext[2] = -m * g;
    double wmax = 0.0;
    for (int k = 0; k < 100000; k++) {
        ENSURE(step(&d));
        wmax = fmax(wmax, norm_w(&d, 0));
        if (k > 1000)
            ENSURE(d.trk.n == 4);
    }
    ENSURE_SMALL(wmax, 1e-9);
    ENSURE_NEAR(d.z[0], 0.06 - g * m / 4e5, 1e-9);
    rs_driver_free(&d);
    rs_surface_free(&s);
}

/* Node 0 a sphere, node 1 the same sphere as a body: dropped spinning and sliding with
 * friction, they move alike. */
static void test_sphere_body_moves_as_the_sphere_node(void)
{
    rs_surface s;
    rs_driver d;
    const double law[5] = {1e5, 5e4, 0.3, 0.3, 0.4}, g = 9.81;
    ENSURE(setup(&d, &s, 2, law, 1e-5));
    rs_shape ball;
    ENSURE(rs_shape_make_sphere(&ball, 0.1, 0.0, NULL) == RS_OK);
    ENSURE(rs_driver_set_body(&d, 1, &ball, 2000.0, NULL) == RS_OK);
    ENSURE_NEAR(d.radius[1], 0.1, 1e-15);
    d.radius[0] = 0.1;
    d.mass[0] = d.mass[1];
    for (int k = 0; k < 3; k++)
        d.inertia[k] = d.inertia[3 + k];
    for (int i = 0; i < 2; i++) {
        d.x[i] = 2.0 * i;
        d.z[i] = 0.12;
        d.vx[i] = 1.0;
        d.wy[i] = -3.0;
        d.wz[i] = 2.0;
        d.fext[3 * i + 2] = -d.mass[i] * g;
    }
    for (int k = 0; k < 50000; k++) {
        ENSURE(step(&d));
        ENSURE_NEAR(d.x[1] - 2.0, d.x[0], 1e-9);
        ENSURE_NEAR(d.y[1], d.y[0], 1e-9);
        ENSURE_NEAR(d.z[1], d.z[0], 1e-9);
        ENSURE_NEAR(d.wx[1], d.wx[0], 1e-9);
        ENSURE_NEAR(d.wy[1], d.wy[0], 1e-9);
        ENSURE_NEAR(d.wz[1], d.wz[0], 1e-9);
    }
    rs_driver_free(&d);
    rs_surface_free(&s);
}

static void test_bad_bodies_are_refused(void)
{
    rs_surface s;
    rs_driver d;
    const double law[5] = {1e5, 1e5, 0.0, 0.0, 0.0};
    ENSURE(setup(&d, &s, 2, law, 1e-5));
    rs_shape box;
    ENSURE(rs_shape_make_box(&box, 0.1, 0.1, 0.1, 0.0, NULL) == RS_OK);
    rs_error e;
    ENSURE(rs_driver_set_body(&d, 2, &box, 1.0, &e) == RS_ERR_ARG);
    ENSURE(rs_driver_set_body(&d, 0, NULL, 1.0, &e) == RS_ERR_ARG);
    ENSURE(rs_driver_set_body(&d, 0, &box, -1.0, &e) == RS_ERR_ARG);
    rs_shape_free(&box);
    rs_driver_free(&d);
    rs_surface_free(&s);
}

/* A tetrahedron whose inertia is not diagonal in its points' axes: the driver turns it
 * into its principal axes A (rs_mass_props.axes), so that the node's moments are the
 * principal ones and its body point A^T (p - c) for each point p (c the centre of
 * mass): with q = 1, its support along each world axis is the extreme of those. */
static void test_polyhedron_turned_into_its_principal_axes(void)
{
    rs_surface s;
    rs_driver d;
    const double law[5] = {1e5, 1e5, 0.0, 0.0, 0.0};
    ENSURE(setup(&d, &s, 1, law, 1e-5));
    const double pts[12] = {0, 0, 0, 1, 0, 0, 0, 2, 0, 0.3, 0.1, 1.5};
    rs_shape tet;
    rs_error e;
    ENSURE(rs_shape_make_polyhedron(&tet, pts, 4, 0.0, &e) == RS_OK);
    rs_mass_props mp;
    ENSURE(rs_shape_mass_props(&tet, 1.0, &mp, &e) == RS_OK);
    ENSURE(fabs(mp.axes[1]) > 1e-3 || fabs(mp.axes[2]) > 1e-3 || fabs(mp.axes[5]) > 1e-3);
    ENSURE(rs_driver_set_body(&d, 0, &tet, 1.0, &e) == RS_OK);
    ENSURE(d.shape[0] != &tet);
    for (int k = 0; k < 3; k++)
        ENSURE_NEAR(d.inertia[k], mp.principal[k], 1e-15 * mp.principal[k]);
    ENSURE_NEAR(d.mass[0], mp.mass, 1e-15);
    /* the centre of mass of the points: the body frame's origin of tet, -shift */
    for (int axis = 0; axis < 3; axis++) {
        double hi = -INFINITY, lo = INFINITY;
        for (int v = 0; v < 4; v++) {
            double p[3];
            for (int c = 0; c < 3; c++)
                p[c] = pts[3 * v + c] - tet.shift[c];
            const double a =
                mp.axes[axis] * p[0] + mp.axes[3 + axis] * p[1] + mp.axes[6 + axis] * p[2];
            hi = fmax(hi, a);
            lo = fmin(lo, a);
        }
        double dir[3] = {0, 0, 0}, out[3];
        dir[axis] = 1.0;
        rs_shape_support(d.shape[0], dir, out);
        ENSURE_NEAR(out[axis], hi, 1e-12);
        dir[axis] = -1.0;
        rs_shape_support(d.shape[0], dir, out);
        ENSURE_NEAR(out[axis], lo, 1e-12);
    }
    rs_shape_free(&tet);
    rs_driver_free(&d);
    rs_surface_free(&s);
}

/* One body in a drum given analytically (a REVOLUTION) and as a MESH of its display
 * triangulation (nhoop facets around): an ellipsoid let go on the mantle slides (or
 * rolls, with friction mu) down and up the other side, rocking. A facet's normal is off
 * the drum's by up to pi / nhoop, so the two paths part by about that angle times the
 * distance travelled, and less on a finer mesh. Returns the largest distance between the
 * two paths, with the length of the analytic one and, for each surface, the spread of
 * the total energy (kinetic, elastic, potential) and its potential energy's range;
 * a negative number on an error. */
typedef struct drum_run {
    double length, spread[2], range[2];
} drum_run;

static double drum_paths(int nhoop, double mu, double zeta, drum_run *out)
{
    static const char *DRUM = "*SURFACE, TYPE=REVOLUTION, NAME=drum\n0, 0, 0, 0, 0, 1\n"
                              "START, 0, -0.05\nLINE, 0.1, -0.05\nLINE, 0.1, 0.05\n"
                              "LINE, 0, 0.05\n";
    rs_surface s[2];
    rs_error e;
    if (rs_surface_parse(DRUM, "drum", NULL, &s[0], &e) != RS_OK)
        return -1.0;
    rs_trimesh tm;
    memset(&tm, 0, sizeof tm);
    const rs_mesh_def def = RS_MESH_DEF_INIT;
    if (rs_surface_triangulate(&s[0], 0.1, nhoop, &tm, &e) != RS_OK ||
        rs_surface_make_mesh(tm.xyz, tm.nvert, tm.tri, tm.ntri, &def, &s[1], &e) != RS_OK)
        return -1.0;
    rs_trimesh_free(&tm);
    rs_shape ell;
    if (rs_shape_make_ellipsoid(&ell, 0.02, 0.012, 0.01, 0.0, NULL) != RS_OK)
        return -1.0;
    const double law[5] = {1e4, 1e4, zeta, zeta, mu}, g = 9.81, a = 0.8;
    rs_driver d[2];
    for (int k = 0; k < 2; k++) {
        if (rs_driver_init(&d[k], &s[k], 1, &e) != RS_OK ||
            rs_driver_set_law(&d[k], rs_law_find("hooke"), law, 5, 2, &e) != RS_OK ||
            rs_driver_set_body(&d[k], 0, &ell, 1000.0, &e) != RS_OK)
            return -1.0;
        d[k].dt = 2e-5;
        d[k].tracking = 1e-3;
        /* its shortest axis (z) along the drum's radius, resting on the mantle */
        const double ax[3] = {cos(a), sin(a), 0}; /* turns body z to the radius */
        quat_axis(0.5 * RS_PI, ax, d[k].q);
        d[k].x[0] = (0.1 - 0.01) * sin(a);
        d[k].y[0] = -(0.1 - 0.01) * cos(a);
        d[k].fext[1] = -g * d[k].mass[0];
    }
    double worst = 0.0, prev[3] = {d[0].x[0], d[0].y[0], d[0].z[0]};
    double elo[2] = {INFINITY, INFINITY}, ehi[2] = {-INFINITY, -INFINITY};
    double ylo[2] = {INFINITY, INFINITY}, yhi[2] = {-INFINITY, -INFINITY};
    out->length = 0.0;
    for (int step = 0; step < 15000; step++) {
        for (int k = 0; k < 2; k++) {
            if (rs_driver_step(&d[k], &e) != RS_OK) {
                fprintf(stderr, "drum %d: %s\n", k, e.msg);
                return -1.0;
            }
            /* the velocities lag half a step: from the first contact's settling on */
            const double E =
                d[k].energy.allke + d[k].energy.allse + g * d[k].mass[0] * d[k].y[0];
            if (step >= 100) {
                elo[k] = fmin(elo[k], E);
                ehi[k] = fmax(ehi[k], E);
            }
            ylo[k] = fmin(ylo[k], d[k].y[0]);
            yhi[k] = fmax(yhi[k], d[k].y[0]);
        }
        const double dx = d[1].x[0] - d[0].x[0], dy = d[1].y[0] - d[0].y[0],
                     dz = d[1].z[0] - d[0].z[0];
        worst = fmax(worst, sqrt(dx * dx + dy * dy + dz * dz));
        const double cur[3] = {d[0].x[0], d[0].y[0], d[0].z[0]};
        out->length += sqrt((cur[0] - prev[0]) * (cur[0] - prev[0]) +
                            (cur[1] - prev[1]) * (cur[1] - prev[1]) +
                            (cur[2] - prev[2]) * (cur[2] - prev[2]));
        memcpy(prev, cur, sizeof prev);
    }
    for (int k = 0; k < 2; k++) {
        out->spread[k] = ehi[k] - elo[k];
        out->range[k] = g * d[k].mass[0] * (yhi[k] - ylo[k]);
        rs_driver_free(&d[k]);
        rs_surface_free(&s[k]);
    }
    return worst;
}

/* Frictionless and elastic, the meshed drum keeps the energy as the analytic one does
 * (the facets' shares ramp a contact in and out where it begins and ends at a fold). */
static void test_body_in_a_meshed_drum_keeps_the_energy(void)
{
    drum_run r0;
    const double w0 = drum_paths(256, 0.0, 0.0, &r0);
    ENSURE(w0 >= 0.0);
    ENSURE(r0.length > 0.1); /* it went down and up the other side */
    ENSURE(w0 <= RS_PI / 256 * r0.length);
    for (int k = 0; k < 2; k++) /* measured 2.0e-4 (analytic) and 4.5e-4 (mesh) */
        ENSURE(r0.spread[k] <= 1e-3 * r0.range[k]);
}

/* With friction, a body's contact on the facet it moves onto continues the history of
 * its contact on the facet it leaves, so a rolling body does not slip at each fold and
 * the finer mesh is the closer (without it the paths part by 0.7 and 1.5 mm). */
static void test_body_rolls_in_a_meshed_drum_as_in_the_analytic_one(void)
{
    drum_run r1, r2;
    const double w1 = drum_paths(256, 0.5, 0.3, &r1), w2 = drum_paths(1024, 0.5, 0.3, &r2);
    ENSURE(w1 >= 0.0 && w2 >= 0.0);
    ENSURE(r1.length > 0.1);
    ENSURE(w1 <= RS_PI / 256 * r1.length);
    ENSURE(w2 <= RS_PI / 1024 * r2.length);
    ENSURE(w2 < 0.25 * w1); /* the finer mesh, the closer */
}

/* A hull of 500 points (not in principal axes: the driver turns it) dropped tumbling onto
 * the plane with friction: one run, then another from the same points, each making its
 * own hulls, end in the same state bit for bit. */
static int hull_run(double out[7])
{
    enum { N = 500 };
    static double xyz[3 * N];
    unsigned long long seed = 9;
    for (int i = 0; i < N; i++) {
        double d[3], l;
        do {
            for (int k = 0; k < 3; k++)
                d[k] = 2.0 * (double)(rs_test_xorshift(&seed) >> 11) / 9007199254740992.0 -
                       1.0;
            l = rs_norm3(d);
        } while (l > 1.0 || l < 1e-3);
        for (int k = 0; k < 3; k++) /* an uneven rock about 2 cm across */
            xyz[3 * i + k] = 0.01 * (k == 0 ? 1.3 : k == 1 ? 0.9 : 0.7) * d[k] / l;
    }
    rs_shape rock;
    rs_surface s;
    rs_driver d;
    const double law[5] = {1e4, 1e4, 0.3, 0.3, 0.5};
    if (rs_shape_make_polyhedron(&rock, xyz, N, 0.0, NULL) != RS_OK ||
        !setup(&d, &s, 1, law, 1e-5) ||
        rs_driver_set_body(&d, 0, &rock, 2500.0, NULL) != RS_OK)
        return 0;
    d.z[0] = 0.02;
    d.vx[0] = 0.2;
    d.wx[0] = 5.0;
    d.wy[0] = -3.0;
    d.fext[2] = -9.81 * d.mass[0];
    for (int k = 0; k < 20000; k++)
        if (!step(&d))
            return 0;
    const double o[7] = {d.x[0], d.y[0], d.z[0], d.q[0], d.q[1], d.q[2], d.q[3]};
    memcpy(out, o, sizeof o);
    rs_driver_free(&d);
    rs_surface_free(&s);
    rs_shape_free(&rock);
    return 1;
}

static void test_two_runs_of_a_hull_end_alike(void)
{
    double a[7], b[7];
    ENSURE(hull_run(a) && hull_run(b));
    ENSURE(a[2] < 0.01); /* it landed */
    for (int k = 0; k < 7; k++)
        ENSURE(a[k] == b[k]);
}

/* CTest runs this file in three shards (RS_TEST_SHARD, tests/CMakeLists.txt): the order
 * below puts the two drum runs, the longest, in shards of their own. */
int main(void)
{
    RS_RUN(test_cube_dropped_flat_rests_on_four_corners_and_rebounds);
    RS_RUN(test_cube_dropped_on_an_edge_leaves_with_the_impulse_about_it);
    RS_RUN(test_ellipsoid_rests_at_its_support_height);
    RS_RUN(test_elastic_bodies_keep_their_energy);
    RS_RUN(test_box_on_a_slope_sticks_slides_and_tips);
    RS_RUN(test_cylinder_and_capsule_roll_at_two_thirds_g_sin);
    RS_RUN(test_rounded_box_at_rest_does_not_rock);
    RS_RUN(test_sphere_body_moves_as_the_sphere_node);
    RS_RUN(test_bad_bodies_are_refused);
    RS_RUN(test_polyhedron_turned_into_its_principal_axes);
    RS_RUN(test_body_in_a_meshed_drum_keeps_the_energy);
    RS_RUN(test_body_rolls_in_a_meshed_drum_as_in_the_analytic_one);
    RS_RUN(test_two_runs_of_a_hull_end_alike);
    return rs_test_summary();
}
