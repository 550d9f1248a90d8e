/* The effective mass of a convex body's contact points (docs/conventions.md, "Effective
 * mass of a body's contacts") in the standalone driver on the plane z = 0, against
 * closed forms:
 * - the mass a law sees at a tilted cube's lowest corner is 1 / (1/m + (r x n).I^-1
 *   (r x n)), and at each of the four corners of a cube lying flat m / 4;
 * - dropped without gravity, a body rebounds with the law's restitution whether one,
 *   two or four of its points touch: hertz e = 0.5, hooke exp(-zeta pi / sqrt(1 -
 *   zeta^2)) for zeta = 0.3 (the damping ratio of each point's spring on its mass); on a
 *   corner, the contact point's normal velocity is reversed times e and the body leaves
 *   with the impulse (1 + e) m_eff v0 at that corner;
 * - a sharp box on a slope with hooke zeta_t = 0.7 sticks while tan(theta) < mu and
 *   slides at g (sin(theta) - mu cos(theta)) beyond, up to 50 degrees;
 * - damped bodies bouncing under gravity never gain energy. */
#include "rigidsurf/driver.h"
#include "rigidsurf/vec.h"
#include "rs_test.h"

static const char *PLANE = "*SURFACE, TYPE=CYLINDER, NAME=floor\n"
                           "0, 0, 0, 1, 0, 0\n0, -1, 0\nSTART, -100, 0\nLINE, 100, 0\n";

/* hertz: Y_p, nu_p, Y_w, nu_w, restitution, friction, curvature; and stiffer, for an
 * impact short enough that the body hardly turns during it */
static const double HERTZ[2][7] = {{1e7, 0.3, 1e9, 0.3, 0.5, 0.0, 0.0},
                                   {1e10, 0.3, 1e12, 0.3, 0.5, 0.0, 0.0}};
/* hooke: kn, kt, zeta_n, zeta_t, mu */
static const double HOOKE[2][5] = {{1e5, 1e5, 0.3, 0.3, 0.0}, {1e8, 1e8, 0.3, 0.3, 0.0}};

/* A driver of one body on the plane, law hertz (law 0) or hooke (1), stiff or not. */
static int setup(rs_driver *d, rs_surface *s, int law, int stiff, const rs_shape *sh,
                 double dt)
{
    rs_error e;
    rs_error_clear(&e);
    const rs_law *l = rs_law_find(law ? "hooke" : "hertz");
    const double *props = law ? HOOKE[stiff] : HERTZ[stiff];
    if (rs_surface_parse(PLANE, "plane", NULL, s, &e) != RS_OK ||
        rs_driver_init(d, s, 1, &e) != RS_OK ||
        rs_driver_set_law(d, l, props, law ? 5 : 7, 2, &e) != RS_OK ||
        rs_driver_set_body(d, 0, sh, 1000.0, &e) != RS_OK) {
        fprintf(stderr, "setup: %s\n", e.msg);
        return 0;
    }
    d->dt = dt;
    d->tracking = 1e-4;
    return 1;
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

static void quat_axis(double angle, double x, double y, double z, double q[4])
{
    const double n = sqrt(x * x + y * y + z * z);
    q[0] = cos(0.5 * angle);
    q[1] = sin(0.5 * angle) * x / n;
    q[2] = sin(0.5 * angle) * y / n;
    q[3] = sin(0.5 * angle) * z / n;
}

/* The world inverse inertia of node i: R diag(1 / I) R^T. */
static void inverse_inertia(const rs_driver *d, int i, double J[9])
{
    double R[9];
    rs_quat_matrix(d->q + 4 * i, R);
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            J[3 * r + c] = 0.0;
            for (int k = 0; k < 3; k++)
                J[3 * r + c] += R[3 * r + k] * R[3 * c + k] / d->inertia[3 * i + k];
        }
}

/* A cube (half 0.03) turned so that one corner is lowest, that corner 1e-5 into the
 * plane: the law's mass is 1 / (1/m + u.I^-1 u), u = (x_cp - x) x n, from the tracker's
 * contact point; flat, each of its four corners gets m / 4. */
static void test_the_law_sees_the_effective_mass_of_each_point(void)
{
    rs_shape cube;
    ENSURE(rs_shape_make_box(&cube, 0.03, 0.03, 0.03, 0.0, NULL) == RS_OK);
    for (int flat = 0; flat < 2; flat++) {
        rs_surface s;
        rs_driver d;
        ENSURE(setup(&d, &s, 1, 0, &cube, 1e-6));
        if (!flat)
            quat_axis(0.5, 1.0, 0.4, 0.0, d.q);
        double R[9], low = INFINITY;
        rs_quat_matrix(d.q, R);
        for (int c = 0; c < 8; c++) {
            const double p[3] = {(c & 1) ? 0.03 : -0.03, (c & 2) ? 0.03 : -0.03,
                                 (c & 4) ? 0.03 : -0.03};
            low = fmin(low, R[6] * p[0] + R[7] * p[1] + R[8] * p[2]);
        }
        d.z[0] = -low - 1e-5;
        ENSURE(step(&d));
        const double m = d.mass[0];
        ENSURE(d.trk.n == (flat ? 4 : 1));
        double J[9];
        inverse_inertia(&d, 0, J);
        for (int e = 0; e < d.trk.n; e++) {
            const double *xc = d.trk.coordslv + 3 * e;
            const double r[3] = {xc[0] - d.x[0], xc[1] - d.y[0], xc[2] - d.z[0]};
            const double n[3] = {0.0, 0.0, 1.0};
            double u[3], Ju[3];
            rs_cross3(r, n, u);
            rs_matvec3(J, u, Ju);
            const double alone = 1.0 / (1.0 / m + rs_dot3(u, Ju));
            ENSURE_NEAR(d.cb.mass[e], flat ? 0.25 * m : alone, 1e-12 * m);
        }
        rs_driver_free(&d);
        rs_surface_free(&s);
    }
    rs_shape_free(&cube);
}

/* Body which (0 a sphere, 1 a capsule on its side, 2 a cube flat, 3 a cylinder on its
 * end, 4 a cube on a corner, under the stiff laws) dropped at v0 = 1 m/s onto the plane
 * without gravity under law 0 (hertz) or 1 (hooke); returns the normal velocity of its
 * lowest contact point after the impact over that before, with the number of points that
 * touched at most, and the velocity and spin it leaves with. */
typedef struct drop_out {
    int points;
    double e, vz, w[3], r[3], m, I[3];
} drop_out;

static int drop(int which, int law, drop_out *o)
{
    rs_shape sh;
    double h = 0.0;
    switch (which) {
    case 0:
        rs_shape_make_sphere(&sh, 0.05, 0.0, NULL), h = 0.05;
        break;
    case 1:
        rs_shape_make_capsule(&sh, 0.02, 0.05, 0.0, NULL), h = 0.02;
        break;
    case 3:
        rs_shape_make_cylinder(&sh, 0.03, 0.04, 0.0, NULL), h = 0.04;
        break;
    default:
        rs_shape_make_box(&sh, 0.03, 0.03, 0.03, 0.0, NULL), h = 0.03;
        break;
    }
    rs_surface s;
    rs_driver d;
    const int stiff = which == 4;
    if (!setup(&d, &s, law, stiff, &sh, stiff ? 2e-8 : 2e-7))
        return 0;
    if (which == 1)
        quat_axis(0.5 * RS_PI, 1.0, 0.0, 0.0, d.q); /* its axis along y */
    double R[9];
    rs_quat_matrix(d.q, R);
    o->r[0] = o->r[1] = 0.0, o->r[2] = -h;
    if (which == 4) { /* the lowest corner of the cube turned by 0.5 about (1, 0.4, 0) */
        quat_axis(0.5, 1.0, 0.4, 0.0, d.q);
        rs_quat_matrix(d.q, R);
        double low = INFINITY;
        for (int c = 0; c < 8; c++) {
            const double p[3] = {(c & 1) ? h : -h, (c & 2) ? h : -h, (c & 4) ? h : -h};
            double w[3];
            rs_matvec3(R, p, w);
            if (w[2] < low)
                low = w[2], memcpy(o->r, w, sizeof o->r);
        }
        h = -low;
    }
    d.z[0] = h + 1e-5;
    d.vz[0] = -1.0;
    o->points = 0;
    int touched = 0;
    for (int k = 0; k < 2000000; k++) {
        if (!step(&d))
            return 0;
        o->points = d.trk.n > o->points ? d.trk.n : o->points;
        touched |= d.trk.n > 0;
        if (touched && d.trk.n == 0)
            break;
    }
    /* the contact point's normal velocity, v + w x r at the impact's lever arm */
    const double w[3] = {d.wx[0], d.wy[0], d.wz[0]};
    double wr[3];
    rs_cross3(w, o->r, wr);
    o->e = d.vz[0] + wr[2];
    o->vz = d.vz[0];
    memcpy(o->w, w, sizeof o->w);
    o->m = d.mass[0];
    memcpy(o->I, d.inertia, sizeof o->I);
    rs_driver_free(&d);
    rs_surface_free(&s);
    rs_shape_free(&sh);
    return touched;
}

static void test_restitution_does_not_depend_on_how_many_points_touch(void)
{
    const double zeta = HOOKE[0][2];
    const double closed[2] = {HERTZ[0][4], exp(-zeta * RS_PI / sqrt(1.0 - zeta * zeta))};
    const int points[5] = {1, 2, 4, 4, 1};
    for (int law = 0; law < 2; law++)
        for (int which = 0; which < 5; which++) {
            drop_out o;
            ENSURE(drop(which, law, &o));
            ENSURE(o.points == points[which]);
            /* measured: 2e-6 to 3.5e-5 (the body's mass once per point would give 0.366
             * and 0.223 for hertz e = 0.5 on two and four points); on the corner 2.1e-3
             * and 1.1e-3, the lever arm turning by a few mrad during the impact */
            ENSURE_NEAR(o.e, closed[law], which == 4 ? 5e-3 : 1e-4);
            if (which < 4)
                continue;
            /* the corner's impulse J = (1 + e) m_eff v0 along z, m_eff from the lever arm
             * (the cube's inertia is isotropic: I^-1 = 1/I) */
            const double I = o.I[0], u2 = o.r[0] * o.r[0] + o.r[1] * o.r[1];
            const double meff = 1.0 / (1.0 / o.m + u2 / I);
            const double J = (1.0 + closed[law]) * meff;
            ENSURE_NEAR(o.vz, J / o.m - 1.0, 2e-3);
            ENSURE_NEAR(o.w[0], J * o.r[1] / I, 2e-3 * fabs(J * o.r[1] / I));
            ENSURE_NEAR(o.w[1], -J * o.r[0] / I, 2e-3 * fabs(J * o.r[0] / I));
        }
}

/* A sharp cube (half 0.01, 8 g) on the plane under gravity turned by theta, hooke
 * kn = kt = 2e4, zeta_n = zeta_t = 0.7 (the examples' damping), friction mu: the mean
 * acceleration down the slope over [0.1, 0.3] s. */
static int slope(double theta, double mu, double *acc)
{
    rs_shape cube;
    rs_surface s;
    rs_driver d;
    rs_error e;
    const double law[5] = {2e4, 2e4, 0.7, 0.7, mu}, g = 9.81;
    if (rs_shape_make_box(&cube, 0.01, 0.01, 0.01, 0.0, NULL) != RS_OK ||
        rs_surface_parse(PLANE, "plane", NULL, &s, &e) != RS_OK ||
        rs_driver_init(&d, &s, 1, &e) != RS_OK ||
        rs_driver_set_law(&d, rs_law_find("hooke"), law, 5, 2, &e) != RS_OK ||
        rs_driver_set_body(&d, 0, &cube, 8000.0, &e) != RS_OK)
        return 0;
    d.dt = 1e-5;
    d.tracking = 1e-5;
    const double m = d.mass[0];
    d.z[0] = 0.01 - g * cos(theta) * m / (4.0 * law[0]);
    d.fext[0] = m * g * sin(theta);
    d.fext[2] = -m * g * cos(theta);
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

static void test_sharp_box_with_zeta_t_0_7_slides_when_it_should(void)
{
    const double g = 9.81, mu = 0.5;
    for (int deg = 20; deg <= 50; deg += 10) {
        const double th = deg * RS_PI / 180.0;
        double a;
        ENSURE(slope(th, mu, &a));
        /* measured: sticks to 1e-15 g at 20 degrees, slides at the closed form to 1e-10
         * (the body's mass once per point would keep it stuck up to 40 degrees, and give
         * 1.4 m/s^2 instead of 4.4 at 50) */
        if (tan(th) < mu)
            ENSURE_SMALL(a, 1e-6 * g);
        else
            ENSURE_NEAR(a, g * (sin(th) - mu * cos(th)), 1e-4 * g);
    }
}

/* Bodies with hertz e = 0.5 and friction bouncing under gravity (a box, a capsule and a
 * cylinder, tilted and spinning): their kinetic, potential and elastic energy never rises
 * above any earlier value, to the scheme's O(dt^2), and the bounces die out. */
static void test_damped_bodies_never_gain_energy(void)
{
    rs_surface s;
    rs_driver d;
    rs_error e;
    const double law[7] = {1e7, 0.3, 1e9, 0.3, 0.5, 0.4, 0.0}, g = 9.81;
    ENSURE(rs_surface_parse(PLANE, "plane", NULL, &s, &e) == RS_OK);
    ENSURE(rs_driver_init(&d, &s, 3, &e) == RS_OK);
    ENSURE(rs_driver_set_law(&d, rs_law_find("hertz"), law, 7, 2, &e) == RS_OK);
    rs_shape sh[3];
    ENSURE(rs_shape_make_box(&sh[0], 0.03, 0.02, 0.01, 0.0, NULL) == RS_OK);
    ENSURE(rs_shape_make_capsule(&sh[1], 0.01, 0.02, 0.0, NULL) == RS_OK);
    ENSURE(rs_shape_make_cylinder(&sh[2], 0.015, 0.01, 0.002, NULL) == RS_OK);
    for (int i = 0; i < 3; i++) {
        ENSURE(rs_driver_set_body(&d, i, &sh[i], 1000.0, &e) == RS_OK);
        quat_axis(0.3 + 0.4 * i, 1.0, 0.5 * i, 0.2, d.q + 4 * i);
        d.x[i] = 0.2 * i;
        d.z[i] = 0.06;
        d.wx[i] = 3.0 - i;
        d.vx[i] = 0.1;
        d.fext[3 * i + 2] = -g * d.mass[i];
    }
    d.dt = 2e-6;
    d.tracking = 1e-4;
    double e0 = 0.0, emin = INFINITY, rise = 0.0, kemax = 0.0;
    for (int k = 0; k < 250000; k++) {
        ENSURE(step(&d));
        double pe = 0.0;
        for (int i = 0; i < 3; i++)
            pe += d.mass[i] * g * d.z[i];
        const double en = d.energy.allke + d.energy.allse + pe;
        if (k == 0)
            e0 = en;
        rise = fmax(rise, en - emin);
        emin = fmin(emin, en);
        kemax = fmax(kemax, d.energy.allke);
    }
    /* measured: a rise of 5.7e-6 of the energy lost, the kinetic energy 1e-3 of its
     * largest */
    ENSURE(rise <= 1e-4 * (e0 - emin));
    ENSURE(d.energy.allke < 0.01 * kemax);
    rs_driver_free(&d);
    rs_surface_free(&s);
}

int main(void)
{
    RS_RUN(test_the_law_sees_the_effective_mass_of_each_point);
    RS_RUN(test_restitution_does_not_depend_on_how_many_points_touch);
    RS_RUN(test_sharp_box_with_zeta_t_0_7_slides_when_it_should);
    RS_RUN(test_damped_bodies_never_gain_energy);
    return rs_test_summary();
}
