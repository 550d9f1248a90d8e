/* The rotation of the driver's rigid nodes (driver.h): one increment of the NO_SQUISH
 * splitting of Miller, Eleftheriou, Pattnaik, Ndirango, Newns and Martyna, J. Chem.
 * Phys. 116, 8649 (2002), in the central-difference form of the driver's translation.
 *
 * With R = R(q) (body to world), the body-frame angular momentum is pi = I R^T w. The
 * torque of t_k kicks it, pi += dt R^T tau (the two half kicks of the velocity-Verlet form
 * merged, as v_{k+1/2} = v_{k-1/2} + dt F/m), then the free rotation over dt is split
 * into the exact flows of T_k = pi_k^2 / (2 I_k) in the order 3 (dt/2), 2 (dt/2), 1 (dt),
 * 2 (dt/2), 3 (dt/2). The flow of T_k turns the body about its axis k by
 * phi = h pi_k / I_k (q <- q (cos phi/2, sin phi/2 e_k)) and pi about e_k by -phi, so
 * each step is a rotation: |pi| and the world-frame L = R pi are kept to rounding, the
 * map is symplectic and time-reversible (second order), and the energy error stays
 * bounded, O(dt^2), without drift. Then w = R pi / I at the new orientation.
 *
 * w is the state between increments (as v), so each increment maps it to pi and back. That
 * round trip is exact only for an orthogonal R: q is brought back to unit norm after each
 * increment, so its rounding does not accumulate (unnormalised, |q| - 1 wanders by about
 * 1e-14 in 1e5 increments, and each round trip then scales w by it: |L| of the asymmetric
 * top of test_driver_rotation drifted by 4e-9 there; normalised, by 1e-11). */
#include "rigidsurf/driver.h"
#include "rigidsurf/vec.h"

#include <math.h>

/* q / |q|. */
static void quat_normalize(double q[4])
{
    const double m = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (int c = 0; c < 4; c++)
        q[c] /= m;
}

/* a <- a b (Hamilton product). */
static void quat_mul_right(double a[4], const double b[4])
{
    const double w = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    const double x = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    const double y = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
    const double z = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
    a[0] = w;
    a[1] = x;
    a[2] = y;
    a[3] = z;
}

/* b <- a b. */
static void quat_mul_left(const double a[4], double b[4])
{
    double t[4] = {a[0], a[1], a[2], a[3]};
    quat_mul_right(t, b);
    for (int c = 0; c < 4; c++)
        b[c] = t[c];
}

/* The world-frame rotation by the angle |w| h about w, applied to q. */
static void turn_world(double q[4], const double w[3], double h)
{
    const double m = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    if (m == 0.0)
        return;
    const double s = sin(0.5 * m * h) / m;
    const double d[4] = {cos(0.5 * m * h), s * w[0], s * w[1], s * w[2]};
    quat_mul_left(d, q);
    quat_normalize(q);
}

/* The exact flow of T_k = pi_k^2 / (2 I_k) over h. */
static void free_flow(double q[4], double pi[3], const double inertia[3], int k, double h)
{
    const double phi = h * pi[k] / inertia[k];
    const double c = cos(phi), s = sin(phi);
    double d[4] = {cos(0.5 * phi), 0.0, 0.0, 0.0};
    d[1 + k] = sin(0.5 * phi);
    quat_mul_right(q, d);
    const int a = (k + 1) % 3, b = (k + 2) % 3; /* (a, b, k) is a cyclic order */
    const double pa = pi[a], pb = pi[b];
    pi[a] = c * pa + s * pb;
    pi[b] = -s * pa + c * pb;
}

void rs_rotation_step(double q[4], double w[3], const double inertia[3],
                      const double tau[3], double dt)
{
    if (!(inertia[0] > 0.0 && inertia[1] > 0.0 && inertia[2] > 0.0)) {
        turn_world(q, w, dt); /* a prescribed spin */
        return;
    }
    if (inertia[0] == inertia[1] && inertia[1] == inertia[2]) {
        /* isotropic: w = L / I is constant between kicks, and the turn is exact */
        for (int c = 0; c < 3; c++)
            w[c] += dt * tau[c] / inertia[0];
        turn_world(q, w, dt);
        return;
    }
    double R[9], pi[3];
    rs_quat_matrix(q, R);
    for (int a = 0; a < 3; a++) {
        const double wb = R[a] * w[0] + R[3 + a] * w[1] + R[6 + a] * w[2];
        const double tb = R[a] * tau[0] + R[3 + a] * tau[1] + R[6 + a] * tau[2];
        pi[a] = inertia[a] * wb + dt * tb;
    }
    free_flow(q, pi, inertia, 2, 0.5 * dt);
    free_flow(q, pi, inertia, 1, 0.5 * dt);
    free_flow(q, pi, inertia, 0, dt);
    free_flow(q, pi, inertia, 1, 0.5 * dt);
    free_flow(q, pi, inertia, 2, 0.5 * dt);
    quat_normalize(q);
    rs_quat_matrix(q, R);
    for (int c = 0; c < 3; c++)
        w[c] = R[3 * c] * pi[0] / inertia[0] + R[3 * c + 1] * pi[1] / inertia[1] +
               R[3 * c + 2] * pi[2] / inertia[2];
}

double rs_rotation_energy(const double q[4], const double w[3], const double inertia[3])
{
    double R[9], e = 0.0;
    rs_quat_matrix(q, R);
    for (int a = 0; a < 3; a++) {
        const double wb = R[a] * w[0] + R[3 + a] * w[1] + R[6 + a] * w[2];
        e += 0.5 * inertia[a] * wb * wb;
    }
    return e;
}
