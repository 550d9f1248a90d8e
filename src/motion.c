/* Rigid motion of a master surface: x(t) = C + D(t) + R(axis, phi(t)) (X - C).
 * phi, D and t are accumulated with compensated summation and the pose
 * is rebuilt from phi each step, so a constant rotation does not drift. */
#include "rigidsurf/motion.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <string.h>

/* Rodrigues: R = I + sin(a) K + (1 - cos(a)) K^2 with K = [axis]x; 1 - cos(a) is taken
 * as 2 sin^2(a/2) so small angles keep full relative precision. */
void rs_rotation_matrix(const double axis[3], double angle, double R[9])
{
    double x = axis[0], y = axis[1], z = axis[2];
    double s = sin(angle), h = sin(0.5 * angle), c1 = 2.0 * h * h;
    R[0] = 1.0 - c1 * (y * y + z * z);
    R[1] = c1 * x * y - s * z;
    R[2] = c1 * x * z + s * y;
    R[3] = c1 * x * y + s * z;
    R[4] = 1.0 - c1 * (x * x + z * z);
    R[5] = c1 * y * z - s * x;
    R[6] = c1 * x * z - s * y;
    R[7] = c1 * y * z + s * x;
    R[8] = 1.0 - c1 * (x * x + y * y);
}

/* Exact sum a + b = *s + *e (Knuth's TwoSum). */
static void two_sum(double a, double b, double *s, double *e)
{
    double t = a + b, bv = t - a;
    *s = t;
    *e = (a - (t - bv)) + (b - bv);
}

/* Compensated accumulation: *sum is the correctly rounded running total and *err the
 * remainder below its last bit, so the public fields (t, phi, disp) do not drift. */
static void kahan_add(double *sum, double *err, double x)
{
    double s, e;
    two_sum(*sum, x, &s, &e);
    two_sum(s, *err + e, sum, err);
}

/* The pose of the motion without the spin; with it, x = P + S (X - P0), P the point P0
 * moved by that motion. */
static void motion_update_pose(rs_motion *m)
{
    double RC[3];
    rs_rotation_matrix(m->axis, m->phi, m->pose.R);
    rs_pose_rotate(&m->pose, m->center0, RC);
    for (int i = 0; i < 3; i++)
        m->pose.T[i] = m->center0[i] + m->disp[i] - RC[i];
    if (m->spin_on) {
        double P[3], SP[3];
        rs_pose_to_global(&m->pose, m->spin_point0, P);
        memcpy(m->pose.R, m->S, sizeof m->S);
        rs_matvec3(m->S, m->spin_point0, SP);
        for (int i = 0; i < 3; i++)
            m->pose.T[i] = P[i] - SP[i];
    }
}

/* c = a b, 3 x 3 row-major (c distinct from a and b). */
static void matmul3(const double a[9], const double b[9], double c[9])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            c[3 * i + j] =
                a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] + a[3 * i + 2] * b[6 + j];
}

/* The two axes are parallel (either sense): the rotations commute, and S has its closed
 * form. */
static int spin_parallel(const rs_motion *m)
{
    double c[3];
    rs_cross3(m->axis, m->spin_axis, c);
    return rs_dot3(c, c) < 1e-28;
}

void rs_motion_init(rs_motion *m)
{
    memset(m, 0, sizeof *m);
    m->axis[2] = 1.0;
    m->spin_axis[2] = 1.0;
    rs_pose_identity(&m->pose);
    m->dQ[0] = m->dQ[4] = m->dQ[8] = 1.0;
    m->S[0] = m->S[4] = m->S[8] = 1.0;
}

void rs_motion_set_surface_velocity(rs_motion *m, const double U[3])
{
    m->belt[0] = U[0];
    m->belt[1] = U[1];
    m->belt[2] = U[2];
}

void rs_motion_belt_at(const rs_motion *m, const double n[3], double u[3])
{
    const double *U = m->belt;
    const double un = U[0] * n[0] + U[1] * n[1] + U[2] * n[2];
    for (int b = 0; b < 3; b++)
        u[b] = U[b] - un * n[b];
    const double lu = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    const double lU = sqrt(U[0] * U[0] + U[1] * U[1] + U[2] * U[2]);
    const double sc = lu > 0.0 ? lU / lu : 0.0;
    for (int b = 0; b < 3; b++)
        u[b] *= sc;
}

void rs_motion_set_translation(rs_motion *m, const double vel[3])
{
    m->vel[0] = vel[0];
    m->vel[1] = vel[1];
    m->vel[2] = vel[2];
}

/* A rotation's axis, point and speed checked (fn and point: the caller's names for the
 * error), the axis normalised into unit. */
static int turn_checked(const char *fn, const char *point, const double axis[3],
                        const double p[3], double omega, double unit[3], rs_error *err)
{
    double len = sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    if (!isfinite(len) || len == 0.0)
        return rs_error_set(err, RS_ERR_ARG,
                            "%s: axis (%g, %g, %g) must be a finite non-zero vector", fn,
                            axis[0], axis[1], axis[2]);
    if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2]) || !isfinite(omega))
        return rs_error_set(err, RS_ERR_ARG, "%s: %s and angular speed must be finite", fn,
                            point);
    for (int i = 0; i < 3; i++)
        unit[i] = axis[i] / len;
    return RS_OK;
}

int rs_motion_set_rotation(rs_motion *m, const double center[3], const double axis[3],
                           double omega, rs_error *err)
{
    const int rc =
        turn_checked("rs_motion_set_rotation", "centre", axis, center, omega, m->axis, err);
    if (rc != RS_OK)
        return rc;
    for (int i = 0; i < 3; i++)
        m->center0[i] = center[i];
    m->omega = omega;
    motion_update_pose(m);
    return RS_OK;
}

/* What a rates callback (which: its name) gave at tmid: RS_OK, or why the run stops. */
static int rates_checked(int rc, int finite, const char *which, double tmid, rs_error *err)
{
    if (rc != 0)
        return rs_error_set(err, RS_ERR_ARG,
                            "rs_motion_advance: %s callback stopped the run at t = %g "
                            "(returned %d)",
                            which, tmid, rc);
    if (!finite)
        return rs_error_set(err, RS_ERR_NONFINITE,
                            "rs_motion_advance: %s callback returned a non-finite rate at "
                            "t = %g",
                            which, tmid);
    return RS_OK;
}

int rs_motion_set_spin(rs_motion *m, const double point0[3], const double axis[3],
                       double omega, rs_error *err)
{
    const int rc =
        turn_checked("rs_motion_set_spin", "point", axis, point0, omega, m->spin_axis, err);
    if (rc != RS_OK)
        return rc;
    for (int i = 0; i < 3; i++)
        m->spin_point0[i] = point0[i];
    m->spin_omega = omega;
    m->spin_phi = m->spin_phi_err = 0.0;
    m->spin_on = 0;
    motion_update_pose(m); /* the orientation so far, without the spin */
    memcpy(m->S, m->pose.R, sizeof m->S);
    m->spin_on = 1;
    motion_update_pose(m);
    return RS_OK;
}

int rs_motion_advance(rs_motion *m, double dt, rs_error *err)
{
    if (!isfinite(dt))
        return rs_error_set(err, RS_ERR_ARG, "rs_motion_advance: dt = %g is not finite",
                            dt);
    const double tmid = m->t + 0.5 * dt;
    if (m->rates) {
        double vel[3], omega = m->omega;
        memcpy(vel, m->vel, sizeof vel);
        const int rc = m->rates(tmid, vel, &omega, m->ctx);
        const int finite =
            isfinite(vel[0]) && isfinite(vel[1]) && isfinite(vel[2]) && isfinite(omega);
        const int ok = rates_checked(rc, finite, "rates", tmid, err);
        if (ok != RS_OK)
            return ok;
        memcpy(m->vel, vel, sizeof vel);
        m->omega = omega;
    }
    if (m->spin_on && m->spin_rates) {
        double omega = m->spin_omega;
        const int rc = m->spin_rates(tmid, &omega, m->ctx);
        const int ok = rates_checked(rc, isfinite(omega), "spin rate", tmid, err);
        if (ok != RS_OK)
            return ok;
        m->spin_omega = omega;
    }
    double dphi = m->omega * dt;
    kahan_add(&m->phi, &m->phi_err, dphi);
    rs_rotation_matrix(m->axis, dphi, m->dQ);
    if (m->center_fixed && dphi != 0.0) { /* the translation so far turns about C */
        double d[3], e[3];
        rs_matvec3(m->dQ, m->disp, d);
        rs_matvec3(m->dQ, m->disp_err, e);
        memcpy(m->disp, d, sizeof d);
        memcpy(m->disp_err, e, sizeof e);
    }
    if (m->place) { /* the translation as given: D(t), not the sum of V dt */
        double D[3];
        const int rc = m->place(tmid, D, m->ctx);
        const int ok = rates_checked(rc, isfinite(D[0]) && isfinite(D[1]) && isfinite(D[2]),
                                     "translation", tmid, err);
        if (ok != RS_OK)
            return ok;
        for (int i = 0; i < 3; i++) {
            m->step_disp[i] = D[i] - m->disp[i];
            m->disp[i] = D[i];
            m->disp_err[i] = 0.0;
        }
    } else {
        for (int i = 0; i < 3; i++) {
            m->step_disp[i] = m->vel[i] * dt;
            kahan_add(&m->disp[i], &m->disp_err[i], m->step_disp[i]);
        }
    }
    kahan_add(&m->t, &m->t_err, dt);
    if (m->spin_on) { /* then the spin: dQ = R_s dQ, S = dQ S */
        const double dphi2 = m->spin_omega * dt;
        double R2[9], dQ[9];
        kahan_add(&m->spin_phi, &m->spin_phi_err, dphi2);
        rs_rotation_matrix(m->spin_axis, dphi2, R2);
        matmul3(R2, m->dQ, dQ);
        memcpy(m->dQ, dQ, sizeof dQ);
        if (spin_parallel(m)) {
            double Rs[9], Rb[9];
            rs_rotation_matrix(m->spin_axis, m->spin_phi, Rs);
            rs_rotation_matrix(m->axis, m->phi, Rb);
            matmul3(Rs, Rb, m->S);
        } else {
            double S[9];
            matmul3(dQ, m->S, S);
            memcpy(m->S, S, sizeof S);
        }
    }
    motion_update_pose(m);
    return RS_OK;
}

void rs_motion_set_center_fixed(rs_motion *m, int fixed)
{
    m->center_fixed = fixed != 0;
}

void rs_motion_center(const rs_motion *m, double c[3])
{
    for (int i = 0; i < 3; i++)
        c[i] = m->center0[i] + (m->center_fixed ? m->step_disp[i] : m->disp[i]);
}

void rs_motion_field(const rs_motion *m, double V[3], double W[3], double C[3])
{
    rs_motion_center(m, C);
    for (int i = 0; i < 3; i++) {
        V[i] = m->vel[i];
        W[i] = m->omega * m->axis[i];
    }
    if (!m->spin_on)
        return;
    /* about the spin's point P: the motion without the spin moves P with V + W x (P - C) */
    double P[3], r[3], wr[3];
    rs_pose_to_global(&m->pose, m->spin_point0, P);
    for (int i = 0; i < 3; i++)
        r[i] = P[i] - C[i];
    rs_cross3(W, r, wr);
    for (int i = 0; i < 3; i++) {
        V[i] += wr[i];
        W[i] += m->spin_omega * m->spin_axis[i];
        C[i] = P[i];
    }
}

void rs_motion_velocity_at(const rs_motion *m, const double p[3], double v[3])
{
    double V[3], W[3], C[3], r[3], wr[3];
    rs_motion_field(m, V, W, C);
    for (int i = 0; i < 3; i++)
        r[i] = p[i] - C[i];
    rs_cross3(W, r, wr);
    for (int i = 0; i < 3; i++)
        v[i] = V[i] + wr[i];
}
