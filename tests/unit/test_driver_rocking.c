/* Convex bodies that rock and roll on the plane z = 0 in the standalone driver, with the
 * linear law hooke (kn = kt = 1e5, zeta 0.7, mu 0.5), against the mechanics of a rigid
 * body on a rigid plane:
 * - a prolate ellipsoid (semi-axes 40, 20, 20 mm) released at rest with its long axis
 *   tilted by 0.6 rad rolls without slipping, which does no work: its energy stays that of
 *   the release, so it rocks between tilts of +-0.6 rad (where the centre's height
 *   sqrt(a^2 sin^2 + c^2 cos^2) is the release's), period after period. The contacts'
 *   damping acts only on the small normal speed of the rolling contact point: over 3 s
 *   (8 periods) the turning tilt stays within 0.005 rad of 0.6, the mechanical energy
 *   (kinetic, potential and the contact's elastic energy) never rises above the first
 *   step's by more than 1e-6 of m g a (the energy the leapfrog's half-step velocities
 *   misstate), and no frictional work is done (no slip). A tilted ellipsoid that rocks on
 *   is this closed form, not a gain of energy;
 * - a hull of 10^4 points on a sphere of radius 50 mm, dropped from 50 mm, lands on its
 *   facets and then rocks on them: from the first contact on, its mechanical energy never
 *   rises above the value at that contact (by more than 1e-6 of m g r): any spin it takes
 *   and keeps comes from its own fall onto its facets, not from the contacts. */
#include "rigidsurf/driver.h"
#include "rigidsurf/vec.h"
#include "rs_test.h"
#include "rs_test_driver.h"

static const double G = 9.81, KN = 1e5;

static int setup(rs_driver *d, rs_surface *s, double dt)
{
    const double law[5] = {KN, KN, 0.7, 0.7, 0.5};
    return rs_test_driver_on_plane(d, s, 1, law, dt);
}

/* Node 0's kinetic and potential energy and the contacts' elastic energy. */
static double energy(const rs_driver *d)
{
    double R[9];
    rs_quat_matrix(d->q, R);
    const double w[3] = {d->wx[0], d->wy[0], d->wz[0]};
    double ke = 0.5 * d->mass[0] *
                (d->vx[0] * d->vx[0] + d->vy[0] * d->vy[0] + d->vz[0] * d->vz[0]);
    for (int k = 0; k < 3; k++) {
        const double wb = R[k] * w[0] + R[3 + k] * w[1] + R[6 + k] * w[2];
        ke += 0.5 * d->inertia[k] * wb * wb;
    }
    return ke + d->mass[0] * G * d->z[0] + d->energy.allse;
}

static void test_tilted_ellipsoid_rocks_between_its_release_tilts(void)
{
    rs_surface s;
    rs_driver d;
    ENSURE(setup(&d, &s, 2e-5));
    const double a = 0.04, c = 0.02, th0 = 0.6;
    rs_shape ell;
    ENSURE(rs_shape_make_ellipsoid(&ell, a, c, c, 0.0, NULL) == RS_OK);
    ENSURE(rs_driver_set_body(&d, 0, &ell, 1000.0, NULL) == RS_OK);
    /* the long (body x) axis tilted by th0 about y; at rest on its support point, pressed
     * by its weight */
    d.q[0] = cos(0.5 * th0), d.q[2] = sin(0.5 * th0);
    const double m = d.mass[0];
    const double h0 = sqrt(a * a * sin(th0) * sin(th0) + c * c * cos(th0) * cos(th0));
    d.z[0] = h0 - m * G / KN;
    d.fext[2] = -m * G;
    rs_error err;
    double e0 = 0.0, emax = -INFINITY, turn_min = INFINITY, tilt_max = 0.0;
    int turns = 0, rising = 0;
    double last = th0;
    for (int k = 0; k < 150000; k++) {
        ENSURE(rs_driver_step(&d, &err) == RS_OK);
        const double e = energy(&d);
        if (k == 0)
            e0 = e;
        emax = fmax(emax, e);
        double R[9];
        rs_quat_matrix(d.q, R);
        const double tilt = asin(fmin(1.0, fabs(R[6])));
        tilt_max = fmax(tilt_max, tilt);
        /* a turning point: |tilt| stops growing */
        if (rising && tilt < last) {
            turns++;
            turn_min = fmin(turn_min, last);
        }
        rising = tilt > last;
        last = tilt;
    }
    printf("ellipsoid: %d turning points, the lowest at tilt %.5f rad (released at %.2f), "
           "energy at most %.3g J above the first step's, frictional work %.3g J\n",
           turns, turn_min, th0, emax - e0, d.energy.allfd);
    rs_driver_free(&d);
    rs_shape_free(&ell);
    rs_surface_free(&s);
    ENSURE(turns >= 8);
    ENSURE(turn_min >= th0 - 5e-3 && tilt_max <= th0 + 1e-4);
    ENSURE(emax - e0 <= 1e-6 * m * G * a);
    ENSURE(d.energy.allfd <= 1e-9 * m * G * a);
}

static void test_hull_gains_no_energy_as_it_settles(void)
{
    enum { NPTS = 10000 };
    static double p[3 * NPTS];
    const double r = 0.05;
    /* points on the sphere, from a fixed sequence (a 64-bit LCG) */
    unsigned long long st = 88172645463325252ull;
    for (int k = 0; k < NPTS;) {
        double u[3];
        for (int c = 0; c < 3; c++) {
            st = st * 6364136223846793005ull + 1442695040888963407ull;
            u[c] = 2.0 * (double)(st >> 11) / 9007199254740992.0 - 1.0;
        }
        const double n2 = rs_dot3(u, u);
        if (n2 > 1.0 || n2 < 1e-4)
            continue;
        for (int c = 0; c < 3; c++)
            p[3 * k + c] = r * u[c] / sqrt(n2);
        k++;
    }
    rs_shape hull;
    ENSURE(rs_shape_make_polyhedron(&hull, p, NPTS, 0.0, NULL) == RS_OK);
    rs_surface s;
    rs_driver d;
    ENSURE(setup(&d, &s, 1e-5));
    ENSURE(rs_driver_set_body(&d, 0, &hull, 1000.0, NULL) == RS_OK);
    const double m = d.mass[0];
    d.z[0] = 2.0 * r;
    d.fext[2] = -m * G;
    rs_error err;
    double e_touch = NAN, excess = -INFINITY, wmax = 0.0;
    for (int k = 0; k < 60000; k++) {
        ENSURE(rs_driver_step(&d, &err) == RS_OK);
        const double e = energy(&d);
        if (isnan(e_touch) && d.trk.n > 0)
            e_touch = e;
        if (!isnan(e_touch)) {
            excess = fmax(excess, e - e_touch);
            wmax =
                fmax(wmax, sqrt(d.wx[0] * d.wx[0] + d.wy[0] * d.wy[0] + d.wz[0] * d.wz[0]));
        }
    }
    printf("hull: energy at most %.3g J above the first contact's (m g r = %.3g J), spin "
           "at most %.4f rad/s\n",
           excess, m * G * r, wmax);
    rs_driver_free(&d);
    rs_shape_free(&hull);
    rs_surface_free(&s);
    ENSURE(!isnan(e_touch));
    ENSURE(excess <= 1e-6 * m * G * r);
}

int main(void)
{
    RS_RUN(test_tilted_ellipsoid_rocks_between_its_release_tilts);
    RS_RUN(test_hull_gains_no_energy_as_it_settles);
    return rs_test_summary();
}
