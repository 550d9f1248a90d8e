/* rigidsurf: rigid motion of a master surface.
 *
 * The master moves rigidly: x = R X + T maps a reference-configuration point X to its
 * current position x. The motion is a translation with velocity V and a rotation with
 * angular speed omega about a fixed unit axis through a point C that moves with the
 * translation. Both are superposed:
 *     x(t) = C + D(t) + R(axis, phi(t)) (X - C),   D' = V,   phi' = omega.
 * With the centre fixed in space (rs_motion_set_center_fixed) the rotation turns the
 * wall about C where it stands, translation included, and the translation is added
 * after it (LIGGGHTS's rotation made before a translation of the same mesh): the same
 * pose with D' = omega axis x D + V, each step D <- dQ D + V dt.
 * A second rotation, the spin (rs_motion_set_spin), turns the wall after that each step
 * about an axis of fixed direction through a point P of the wall that the motion above
 * carries (LIGGGHTS's rotation made while another rotation of the same mesh runs): with
 * P0 the point in the reference configuration and S the wall's orientation,
 *     x = P(t) + S (X - P0),   P(t) = the motion above applied to P0,
 *     S <- R(spin axis, omega_s dt) dQ S each step (dQ the motion above's increment);
 * S = R(spin axis, phi_s) R(axis, phi) when the two axes are parallel.
 * Rotations are integrated through the accumulated angle phi, so a constant rotation
 * has no drift however long the run. Rates can change in time through a callback. */
#ifndef RIGIDSURF_MOTION_H
#define RIGIDSURF_MOTION_H

#include "rigidsurf/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/// A rigid pose: x = R X + T. R is row-major (R[3*i + j] = R_ij).
typedef struct rs_pose {
    double R[9];
    double T[3];
} rs_pose;

/// Sets the identity pose.
void rs_pose_identity(rs_pose *p);
/// x = R X + T.
void rs_pose_to_global(const rs_pose *p, const double X[3], double x[3]);
/// X = R^T (x - T).
void rs_pose_to_local(const rs_pose *p, const double x[3], double X[3]);
/// v = R V (a direction, no translation).
void rs_pose_rotate(const rs_pose *p, const double V[3], double v[3]);
/// V = R^T v.
void rs_pose_unrotate(const rs_pose *p, const double v[3], double V[3]);

/// Row-major rotation matrix for a rotation by angle (radians) about unit axis (Rodrigues).
void rs_rotation_matrix(const double axis[3], double angle, double R[9]);

/// Optional time-varying rates: fill vel[3] and *omega at time t. Return 0 on success,
/// non-zero to stop the run (err filled by the callback's owner).
typedef int (*rs_motion_rates_fn)(double t, double vel[3], double *omega, void *ctx);
/// The spin's angular speed at time t, likewise.
typedef int (*rs_motion_spin_fn)(double t, double *omega, void *ctx);
/// A translation given as such: fill disp[3], D at time t, likewise.
typedef int (*rs_motion_place_fn)(double t, double disp[3], void *ctx);

typedef struct rs_motion {
    double t;                 ///< current time
    double vel[3];            ///< translation velocity V (length/time)
    double omega;             ///< angular speed about axis (rad/time), right-hand rule
    double axis[3];           ///< unit rotation axis
    double center0[3];        ///< a point on the axis, reference configuration
    double disp[3];           ///< accumulated translation D
    double phi;               ///< accumulated rotation angle
    rs_motion_rates_fn rates; ///< NULL for constant rates
    void *ctx;                ///< passed to rates
    rs_pose pose;             ///< current pose
    double belt[3]; ///< surface velocity U: the wall's material moves in its tangent plane
                    ///< while its shape stays (a conveyor belt); see rs_motion_belt_at
    double dQ[9];   ///< incremental rotation of the last rs_motion_advance (row-major)
    double t_err, phi_err,
        disp_err[3];     ///< compensated-summation remainders of t, phi, disp
    int center_fixed;    ///< nonzero: the rotation's centre stays at C in space
    double step_disp[3]; ///< V dt of the last rs_motion_advance
    int spin_on;         ///< nonzero: the spin below turns the wall after the motion above
    double spin_axis[3]; ///< unit, fixed in space
    double spin_omega;   ///< angular speed of the spin (rad/time)
    double spin_point0[3];         ///< P0: the spin axis's point, reference configuration
    double spin_phi, spin_phi_err; ///< accumulated spin angle and its remainder
    double S[9];                   ///< the wall's orientation with the spin (row-major)
    rs_motion_spin_fn spin_rates;  ///< NULL for a constant spin (ctx as rates)
    rs_motion_place_fn place; ///< NULL: D is the sum of V dt; else D(t) as it gives it (ctx
                              ///< as rates), V still the rates' (not with the centre fixed)
} rs_motion;

/// No motion: identity pose, zero rates, axis = z, centre at the origin.
void rs_motion_init(rs_motion *m);

/// Sets the surface velocity U (global axes), added to the rigid motion's velocity at
/// every contact as rs_motion_belt_at gives it. Zero: none.
void rs_motion_set_surface_velocity(rs_motion *m, const double U[3]);

/// The surface velocity at a contact of unit normal n: U's part in the tangent plane,
/// scaled to the length of U (as LIGGGHTS's surface_vel), zero when U is along n.
void rs_motion_belt_at(const rs_motion *m, const double n[3], double u[3]);
/// Sets a constant translation velocity.
void rs_motion_set_translation(rs_motion *m, const double vel[3]);
/// Sets the rotation axis (normalised here; must be non-zero), a point on it, and the
/// angular speed. Returns RS_ERR_ARG for a zero or non-finite axis.
int rs_motion_set_rotation(rs_motion *m, const double center[3], const double axis[3],
                           double omega, rs_error *err);
/// fixed != 0: the rotation's centre C stays where it is in space while the wall
/// translates, so D turns with the rotation (D' = omega axis x D + V); 0 (the default):
/// C moves with the translation (D' = V).
void rs_motion_set_center_fixed(rs_motion *m, int fixed);
/// Adds the spin: angular speed omega about the unit axis direction (normalised here,
/// fixed in space) through the wall's point P0 (reference configuration). RS_ERR_ARG for
/// a zero or non-finite axis or a non-finite point or speed.
int rs_motion_set_spin(rs_motion *m, const double point0[3], const double axis[3],
                       double omega, rs_error *err);
/// The wall's rigid velocity field: v(p) = V + W x (p - C), with the spin's part.
void rs_motion_field(const rs_motion *m, double V[3], double W[3], double C[3]);
/// Advances time by dt: rates are taken at mid-step (t + dt/2), then phi and D are
/// integrated and pose and dQ updated; with the centre fixed, D turns by this step's
/// rotation before this step's translation is added. With place, D is place's at
/// mid-step instead of the sum.
int rs_motion_advance(rs_motion *m, double dt, rs_error *err);
/// Current velocity of the master material point at spatial point p:
/// v = V + omega axis x (p - c), c the centre (rs_motion_center), plus the spin's
/// omega_s spin_axis x (p - P) (rs_motion_field).
void rs_motion_velocity_at(const rs_motion *m, const double p[3], double v[3]);
/// The point about which the current velocity field turns: C + D; with the centre
/// fixed in space, C + V dt of the last step (the rotation's velocity is that of the
/// wall as turned, before the step's translation moved it, as LIGGGHTS takes a rotating
/// mesh's node velocities when a translation comes after the rotation).
void rs_motion_center(const rs_motion *m, double c[3]);

#ifdef __cplusplus
}
#endif
#endif
