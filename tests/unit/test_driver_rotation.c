/* The driver's rigid-body rotation (driver.h, step 5): a free asymmetric top keeps its
 * angular momentum, energy and unit quaternion; a free symmetric top's body-frame angular
 * velocity precesses at Euler's rate, with an error of second order in dt; a sphere
 * sliding under Coulomb friction gains spin at mu m g rho / I until it rolls at Newton's
 * 5/7 of its speed, and a sphere whose spin does not matter moves exactly as a node
 * without rotation. */
#include "rigidsurf/driver.h"
#include "rigidsurf/vec.h"
#include "rs_test.h"

static const char *flat = "*SURFACE, TYPE=SEGMENTS, NAME=FLAT\n"
                          "START, -100.0, 0.0\n"
                          "LINE, 100.0, 0.0\n";

/* The test's own rotation matrix of q = (w, x, y, z), body to world. */
static void rot(const double q[4], double R[3][3])
{
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    const double s = 2.0 / (w * w + x * x + y * y + z * z);
    R[0][0] = 1 - s * (y * y + z * z);
    R[0][1] = s * (x * y - w * z);
    R[0][2] = s * (x * z + w * y);
    R[1][0] = s * (x * y + w * z);
    R[1][1] = 1 - s * (x * x + z * z);
    R[1][2] = s * (y * z - w * x);
    R[2][0] = s * (x * z - w * y);
    R[2][1] = s * (y * z + w * x);
    R[2][2] = 1 - s * (x * x + y * y);
}

/* Body-frame angular velocity wb = R^T w and world-frame L = R I wb of node i. */
static void body_state(const rs_driver *d, int i, double wb[3], double L[3])
{
    double R[3][3];
    rot(d->q + 4 * i, R);
    const double w[3] = {d->wx[i], d->wy[i], d->wz[i]};
    const double *I = d->inertia + 3 * i;
    for (int a = 0; a < 3; a++)
        wb[a] = R[0][a] * w[0] + R[1][a] * w[1] + R[2][a] * w[2];
    for (int c = 0; c < 3; c++)
        L[c] = R[c][0] * I[0] * wb[0] + R[c][1] * I[1] * wb[1] + R[c][2] * I[2] * wb[2];
}

/* One node far above the flat wall, no forces: a free rigid body. */
static int free_body(rs_driver *d, rs_surface *s, const double I[3], const double q[4],
                     const double w[3], double dt)
{
    rs_error err;
    static const double k = 1e3;
    if (rs_surface_parse(flat, "flat", NULL, s, &err) != RS_OK ||
        rs_driver_init(d, s, 1, &err) != RS_OK ||
        rs_driver_set_law(d, rs_law_find("linear_softening"), &k, 1, 0, &err) != RS_OK)
        return 0;
    d->dt = dt;
    d->tracking = 0.01;
    d->y[0] = 50.0;
    const double qn = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (int c = 0; c < 4; c++)
        d->q[c] = q[c] / qn;
    for (int c = 0; c < 3; c++)
        d->inertia[c] = I[c];
    d->wx[0] = w[0];
    d->wy[0] = w[1];
    d->wz[0] = w[2];
    return 1;
}

/* The torque-free asymmetric top, I = (1, 2, 3), w0 off the principal axes (body frame
 * (1, 0.8, 0.6)), dt = 1e-3 (|w| dt = 1.4e-3), 1e5 increments (about 20 turns): the
 * world-frame angular momentum stays to 1e-9 of itself, the kinetic energy to 1e-6, |q| = 1
 * to 1e-12 at every increment; ALLKE is that energy. */
static void test_free_asymmetric_top_conserves_momentum_energy_and_unit_quaternion(void)
{
    const double I[3] = {1.0, 2.0, 3.0}, q0[4] = {0.9, 0.1, -0.3, 0.2}, dt = 1e-3;
    const double wb0[3] = {1.0, 0.8, 0.6};
    double R0[3][3], w0[3];
    rot(q0, R0);
    for (int c = 0; c < 3; c++)
        w0[c] = R0[c][0] * wb0[0] + R0[c][1] * wb0[1] + R0[c][2] * wb0[2];
    rs_surface s;
    rs_driver d;
    rs_error err;
    ENSURE(free_body(&d, &s, I, q0, w0, dt));
    double wb[3], L0[3], L[3];
    body_state(&d, 0, wb, L0);
    const double E0 =
        0.5 * (I[0] * wb[0] * wb[0] + I[1] * wb[1] * wb[1] + I[2] * wb[2] * wb[2]);
    const double L0n = sqrt(L0[0] * L0[0] + L0[1] * L0[1] + L0[2] * L0[2]);
    /* off the axes: each body component carries a good part of the energy */
    for (int a = 0; a < 3; a++)
        ENSURE(0.5 * I[a] * wb[a] * wb[a] > 0.1 * E0);
    double dL = 0.0, dE = 0.0, dq = 0.0, dwb3 = 0.0;
    for (int k = 0; k < 100000; k++) {
        ENSURE(rs_driver_step(&d, &err) == RS_OK);
        body_state(&d, 0, wb, L);
        const double E =
            0.5 * (I[0] * wb[0] * wb[0] + I[1] * wb[1] * wb[1] + I[2] * wb[2] * wb[2]);
        const double *q = d.q;
        const double qq = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        dL = fmax(dL,
                  sqrt((L[0] - L0[0]) * (L[0] - L0[0]) + (L[1] - L0[1]) * (L[1] - L0[1]) +
                       (L[2] - L0[2]) * (L[2] - L0[2])));
        dE = fmax(dE, fabs(E - E0));
        dq = fmax(dq, fabs(qq - 1.0));
        dwb3 = fmax(dwb3, fabs(wb[2] - wb0[2]));
        if (k % 20000 == 0)
            ENSURE_REL(d.energy.allke, E, 1e-12);
    }
    printf("    asymmetric top, 1e5 increments: |dL|/|L| %.3g, |dE|/E %.3g, ||q|-1| %.3g\n",
           dL / L0n, dE / E0, dq);
    ENSURE(dL <= 1e-9 * L0n);
    ENSURE(dE <= 1e-6 * E0);
    ENSURE(dq <= 1e-12);
    /* and the top does tumble: the body-frame w moves far from where it started */
    ENSURE(dwb3 > 0.1);
    for (int c = 0; c < 3; c++)
        ENSURE(d.tcon[c] == 0.0);
    rs_driver_free(&d);
    rs_surface_free(&s);
}

/* Phase error after time T of a free symmetric top (I1 = I2 = 1, I3 = 2): by Euler's
 * equations its body-frame (w1, w2) turns about e3 at Omega = (I3 - I1) / I1 w3 while w3
 * and |(w1, w2)| stay. Returns the largest |w3 - w3(0)| and |w_perp| change in *drift. */
static double symmetric_top_phase_error(double dt, double T, double *drift)
{
    const double I[3] = {1.0, 1.0, 2.0}, q0[4] = {1, 0, 0, 0}, w0[3] = {0.6, 0.0, 1.0};
    const double Omega = (I[2] - I[0]) / I[0] * w0[2];
    rs_surface s;
    rs_driver d;
    rs_error err;
    if (!free_body(&d, &s, I, q0, w0, dt))
        return INFINITY;
    const int n = (int)lround(T / dt);
    double wb[3], L[3];
    *drift = 0.0;
    for (int k = 0; k < n; k++) {
        if (rs_driver_step(&d, &err) != RS_OK)
            return INFINITY;
        body_state(&d, 0, wb, L);
        *drift = fmax(*drift, fabs(wb[2] - w0[2]));
        *drift = fmax(*drift, fabs(hypot(wb[0], wb[1]) - w0[0]));
    }
    /* w_{k+1/2}: the angular velocity at the end of increment n */
    const double phase = atan2(wb[1], wb[0]), want = Omega * n * dt;
    rs_driver_free(&d);
    rs_surface_free(&s);
    return fabs(remainder(phase - want, 2.0 * RS_PI));
}

/* The symmetric top against Euler's closed form over T = 20 (about 6 precessions). The
 * splitting is of second order: its phase error is bounded by T |w|^3 dt^2 (a local error
 * of order dt^3 in the rates |w|, accumulated over T / dt increments), and halving dt
 * divides it by 4. */
static void test_symmetric_top_precesses_at_euler_rate(void)
{
    const double T = 20.0, wmag = hypot(0.6, 1.0);
    double drift1, drift2;
    const double e1 = symmetric_top_phase_error(2e-3, T, &drift1);
    const double e2 = symmetric_top_phase_error(1e-3, T, &drift2);
    printf("    symmetric top, T = 20: phase error %.3g (dt 2e-3), %.3g (dt 1e-3), ratio "
           "%.3f; drift of w3, |w_perp| %.3g, %.3g\n",
           e1, e2, e2 / e1, drift1, drift2);
    ENSURE(e1 <= T * wmag * wmag * wmag * 2e-3 * 2e-3);
    ENSURE(e2 / e1 > 0.23 && e2 / e1 < 0.27);
    ENSURE(drift1 <= wmag * wmag * 2e-3 && drift2 <= wmag * wmag * 1e-3);
}

/* A sphere (I = 2/5 m R^2) launched sliding along the flat wall at v0 without spin, under
 * gravity and Coulomb friction mu (law coulomb), resting at its static overlap h = m g /
 * kn. The friction mu m g at the contact point x_cp = x - (R - h/2) n gives the torque
 * (x_cp - x) x F of arm rho = R - h/2 (R to h / (2R) = 5e-5): while it slides,
 * dw/dt = -mu m g rho / I (about z, negative for a roll towards +x) and dv/dt = -mu g.
 * Friction's line passes through the contact point, so the angular momentum about that
 * line, I w - m rho v, is kept; the slide ends when v + w rho = 0, at
 * v* = v0 m rho^2 / (I + m rho^2) (5/7 v0 for rho = R). Rolling, the law's stick spring
 * k_stick, loaded with mu m g when the slide ends and undamped, swings between +-mu m g
 * at omega_t = sqrt(k_stick / m_t), 1/m_t = 1/m + rho^2/I: v about v* by mu g / omega_t
 * at most, the contact point's slip speed by mu m g / (m_t omega_t). */
static void test_sliding_sphere_spins_up_and_rolls(void)
{
    const double m = 1.0, R = 0.1, g = 9.81, mu = 0.3, kn = 1e6, ks = 1e6, v0 = 1.0;
    const double I = 0.4 * m * R * R, dt = 1e-5, h = m * g / kn, rho = R - 0.5 * h;
    rs_surface s;
    rs_driver d;
    rs_error err;
    ENSURE(rs_surface_parse(flat, "flat", NULL, &s, &err) == RS_OK);
    ENSURE(rs_driver_init(&d, &s, 1, &err) == RS_OK);
    const double props[3] = {mu, ks, kn};
    ENSURE(rs_driver_set_law(&d, rs_law_find("coulomb"), props, 3, 2, &err) == RS_OK);
    d.dt = dt;
    d.tracking = 1e-3;
    d.radius[0] = R;
    d.mass[0] = m;
    d.y[0] = R - h;
    d.vx[0] = v0;
    d.fext[1] = -m * g;
    for (int c = 0; c < 3; c++)
        d.inertia[c] = I;
    const double Lp0 = -m * rho * v0;
    const int k1 = 100, k2 = 5000; /* both well before the roll, t* = 2 v0 / (7 mu g) */
    double w1 = 0, v1 = 0, dLp = 0.0;
    for (int k = 1; k <= 15000; k++) {
        ENSURE(rs_driver_step(&d, &err) == RS_OK);
        ENSURE(d.trk.n == 1);
        dLp = fmax(dLp, fabs(I * d.wz[0] - m * rho * d.vx[0] - Lp0));
        if (k == k1) {
            w1 = d.wz[0];
            v1 = d.vx[0];
            /* the torque is the friction force times the arm, about -z */
            ENSURE_REL(d.tcon[2], -mu * m * g * rho, 1e-9);
            ENSURE_REL(d.fcon[0], -mu * m * g, 1e-9);
            ENSURE(d.tcon[0] == 0.0 && d.tcon[1] == 0.0);
        }
        if (k == k2) {
            const double t = (k2 - k1) * dt;
            ENSURE_REL((d.wz[0] - w1) / t, -mu * m * g * rho / I, 1e-9);
            ENSURE_REL((d.wz[0] - w1) / t, -mu * m * g * R / I, h / R);
            ENSURE_REL((d.vx[0] - v1) / t, -mu * g, 1e-9);
            ENSURE(d.vx[0] + d.wz[0] * rho > 0.1); /* still sliding */
        }
    }
    const double vstar = v0 * m * rho * rho / (I + m * rho * rho);
    printf("    sliding sphere: |d(I w - m rho v)| %.3g; at t = 0.15 v %.9f (v* %.9f, "
           "5/7 v0 %.9f), slip speed %.3g; mu g / omega_t %.3g\n",
           dLp, d.vx[0], vstar, 5.0 / 7.0 * v0, d.vx[0] + d.wz[0] * rho,
           mu * g / sqrt(ks * (1.0 / m + rho * rho / I)));
    ENSURE(dLp <= 1e-12 * m * rho * v0);
    /* rolling: the contact point's slip speed is the stick spring's small oscillation */
    const double mt = 1.0 / (1.0 / m + rho * rho / I), omt = sqrt(ks / mt);
    ENSURE(fabs(d.vx[0] + d.wz[0] * rho) <= 1.01 * mu * m * g / (mt * omt));
    ENSURE(fabs(d.vx[0] - vstar) <= 1.01 * mu * g / omt);
    ENSURE_REL(vstar, 5.0 / 7.0 * v0, h / R);
    rs_driver_free(&d);
    rs_surface_free(&s);
}

/* Where spin does not matter (no friction), a sphere with inertia and spin moves exactly
 * as the same node without rotation, increment by increment, and its spin stays. */
static void test_isotropic_sphere_without_friction_keeps_translation(void)
{
    const double m = 0.2, R = 0.05, g = 9.81, dt = 2e-5;
    const double props[3] = {0.0, 1e5, 1e5};
    rs_surface s;
    rs_driver a, b;
    rs_error err;
    ENSURE(rs_surface_parse(flat, "flat", NULL, &s, &err) == RS_OK);
    rs_driver *dv[2] = {&a, &b};
    for (int j = 0; j < 2; j++) {
        rs_driver *d = dv[j];
        ENSURE(rs_driver_init(d, &s, 1, &err) == RS_OK);
        ENSURE(rs_driver_set_law(d, rs_law_find("coulomb"), props, 3, 2, &err) == RS_OK);
        d->dt = dt;
        d->tracking = 1e-3;
        d->radius[0] = R;
        d->mass[0] = m;
        d->y[0] = R + 0.01;
        d->vx[0] = 0.7;
        d->vy[0] = -1.0;
        d->fext[1] = -m * g;
    }
    for (int c = 0; c < 3; c++)
        a.inertia[c] = 0.4 * m * R * R;
    a.wz[0] = 30.0;
    a.wx[0] = -4.0;
    int touched = 0;
    for (int k = 0; k < 2000; k++) {
        ENSURE(rs_driver_step(&a, &err) == RS_OK);
        ENSURE(rs_driver_step(&b, &err) == RS_OK);
        touched |= a.trk.n > 0;
        ENSURE(a.x[0] == b.x[0] && a.y[0] == b.y[0] && a.z[0] == b.z[0]);
        ENSURE(a.vx[0] == b.vx[0] && a.vy[0] == b.vy[0] && a.vz[0] == b.vz[0]);
    }
    ENSURE(touched && a.vy[0] > 0.0); /* it bounced */
    ENSURE(a.wz[0] == 30.0 && a.wx[0] == -4.0 && a.wy[0] == 0.0);
    rs_driver_free(&a);
    rs_driver_free(&b);
    rs_surface_free(&s);
}

int main(void)
{
    RS_RUN(test_free_asymmetric_top_conserves_momentum_energy_and_unit_quaternion);
    RS_RUN(test_symmetric_top_precesses_at_euler_rate);
    RS_RUN(test_sliding_sphere_spins_up_and_rolls);
    RS_RUN(test_isotropic_sphere_without_friction_keeps_translation);
    return rs_test_summary();
}
