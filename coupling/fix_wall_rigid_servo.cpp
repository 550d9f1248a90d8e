/* fix wall/rigid, keyword servo: the wall moves along an axis (or turns about it) so that
 * the particles' force (or torque) on it reaches a target, with the controller of
 * LIGGGHTS's `fix mesh/surface/stress/servo` (its PID with anti-windup, its `auto`
 * mode), so that a servo wall swapped for a wall/rigid one moves the same way.
 *
 * Order within a step, as LIGGGHTS's: initial_integrate moves the wall with the rate
 * the controller set at the end of the previous step; post_force computes the contacts;
 * final_integrate reads the wall's total force (torque about com) along the axis and
 * sets the rate for the next step. */
#include "fix_wall_rigid.h"
#include "rigidsurf/vec.h"

#include "atom.h"
#include "domain.h"
#include "input.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"
#include "variable.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <mpi.h>
#include <sstream>

using namespace LAMMPS_NS;

/* servo com X Y Z ctrlPV force|torque axis AX AY AZ target_val F|v_name vel_max V
 *       [kp K] [ki K] [kd K] [mode auto] [ratio R], LIGGGHTS's words in any order, up to
 *       the next keyword of wall/rigid. */
int FixWallRigid::parse_servo(int narg, char **arg, int iarg)
{
    Servo &s = servo_;
    s.on = true;
    bool have_com = false, have_pv = false, have_axis = false, have_target = false,
         have_vmax = false;
    auto num = [&](const char *kw, const char *what) -> double {
        if (iarg >= narg || is_keyword(arg[iarg]))
            fail(std::string("keyword 'servo ") + kw + "' expects " + what);
        return number((std::string("servo ") + kw).c_str(), what, arg[iarg++]);
    };
    while (iarg < narg && !is_keyword(arg[iarg])) {
        const std::string kw = arg[iarg++];
        if (kw == "com") {
            for (int d = 0; d < 3; d++)
                s.com[d] = num("com", "the coordinates X Y Z of the wall's centre");
            have_com = true;
        } else if (kw == "ctrlPV") {
            if (iarg >= narg)
                fail("keyword 'servo ctrlPV' expects 'force' or 'torque'");
            const std::string pv = arg[iarg++];
            if (pv != "force" && pv != "torque")
                fail("keyword 'servo ctrlPV' expects 'force' or 'torque', got '" + pv +
                     "'");
            s.torque = pv == "torque";
            have_pv = true;
        } else if (kw == "axis") {
            for (int d = 0; d < 3; d++)
                s.axis[d] = num("axis", "the axis components AX AY AZ");
            const double len = rs_norm3(s.axis);
            if (!(len > 0.0))
                fail("keyword 'servo axis' expects a non-zero axis");
            for (int d = 0; d < 3; d++)
                s.axis[d] /= len;
            have_axis = true;
        } else if (kw == "target_val") {
            if (iarg >= narg)
                fail("keyword 'servo target_val' expects a force or torque, or v_name");
            const char *t = arg[iarg];
            if (std::strncmp(t, "v_", 2) == 0 && t[2]) {
                s.target_var = t + 2;
                iarg++;
            } else {
                s.target = num("target_val", "a force or torque (non-zero), or v_name");
                if (s.target == 0.0)
                    fail("keyword 'servo target_val' expects a non-zero target");
            }
            have_target = true;
        } else if (kw == "vel_max") {
            s.vmax = num("vel_max", "the largest speed of the wall (> 0)");
            if (!(s.vmax > 0.0))
                fail("keyword 'servo vel_max' expects a speed > 0");
            have_vmax = true;
        } else if (kw == "kp" || kw == "ki" || kw == "kd") {
            const double k = num(kw.c_str(), "a controller gain >= 0");
            if (k < 0.0)
                fail("keyword 'servo " + kw + "' expects a gain >= 0");
            (kw == "kp" ? s.kp : kw == "ki" ? s.ki : s.kd) = k;
        } else if (kw == "mode") {
            if (iarg >= narg || std::strcmp(arg[iarg], "auto") != 0)
                fail("keyword 'servo mode' expects 'auto'");
            iarg++;
            s.auto_mode = true;
        } else if (kw == "ratio") {
            s.ratio = num("ratio", "the auto mode's step ratio (> 0)");
            if (!(s.ratio > 0.0))
                fail("keyword 'servo ratio' expects a ratio > 0");
        } else {
            fail("keyword 'servo': unknown word '" + kw +
                 "'; expected com, ctrlPV, axis, target_val, vel_max, kp, ki, kd, mode or "
                 "ratio");
        }
    }
    if (!have_com || !have_pv || !have_axis || !have_target || !have_vmax)
        fail("keyword 'servo' needs com X Y Z, ctrlPV force|torque, axis AX AY AZ, "
             "target_val F and vel_max V");
    if (s.auto_mode && !(s.ratio > 0.0))
        fail("keyword 'servo mode auto' needs 'ratio R'");
    if (!s.auto_mode && s.kp == 0.0 && s.ki == 0.0 && s.kd == 0.0)
        fail("keyword 'servo': kp, ki and kd are all zero");
    moving_ = true;
    if (s.torque) {
        rs_error err;
        rs_error_clear(&err);
        if (rs_motion_set_rotation(&motion_, s.com, s.axis, 0.0, &err) != RS_OK)
            fail(err.msg);
    }
    return iarg;
}

/* The run's constants: the target variable, the auto mode's slow speed (ratio times the
 * smallest radius per step), the largest rate; LIGGGHTS's limit vel_max < skin / (2 dt),
 * so that a neighbour list stays valid while the wall moves. */
void FixWallRigid::init_servo()
{
    Servo &s = servo_;
    if (!s.target_var.empty()) {
        s.ivar = input->variable->find(const_cast<char *>(s.target_var.c_str()));
        if (s.ivar < 0 || !input->variable->equalstyle(s.ivar))
            fail("servo target_val: v_" + s.target_var + " is not an equal-style variable");
    } else {
        s.sp = -s.target; // the particles' force on the wall opposes the target
    }
    const double dt = update->dt;
    if (s.vmax >= neighbor->skin / (2.0 * dt)) {
        std::ostringstream o;
        o << "servo vel_max " << s.vmax
          << " must stay below skin / (2 dt) = " << neighbor->skin / (2.0 * dt);
        fail(o.str());
    }
    double rmin = 1e300;
    for (int i = 0; i < atom->nlocal; i++)
        rmin = std::min(rmin, atom->radius[i]);
    double rall = rmin;
    MPI_Allreduce(&rmin, &rall, 1, MPI_DOUBLE, MPI_MIN, world);
    const double vmin = s.ratio * rall / dt;
    double rmax = 1.0; // torque: speeds are angular, over the wall's farthest point
    if (s.torque) {
        rmax = servo_reach();
        if (!(rmax > 0.0))
            fail("servo ctrlPV torque: every point of the surface lies on the axis");
    }
    s.op_max = s.vmax / rmax;
    s.op_min = vmin / rmax;
}

/* The controller, after the step's forces: the process value (force on the wall along
 * the axis, or torque about com along it), its error against the set point, and the
 * wall's next rate. */
void FixWallRigid::final_integrate()
{
    if (!servo_.on)
        return;
    Servo &s = servo_;
    const double dt = update->dt;
    if (s.ivar >= 0) {
        modify->clearstep_compute();
        s.sp = -input->variable->compute_equal(s.ivar);
        if (s.sp == 0.0)
            fail("servo target_val v_" + s.target_var + " is 0; the target must not be 0");
        modify->addstep_compute(update->ntimestep + 1);
    }
    const double spinv = 1.0 / std::fabs(s.sp);
    double F[3], M[3];
    for (int d = 0; d < 3; d++) {
        F[d] = compute_vector(d);
        M[d] = compute_vector(3 + d);
    }
    const int ncontact = (int)compute_vector(6);
    double pv;
    if (s.torque) {
        /* the moment about com: about the origin o, plus (o - com) x F */
        double o[3], r[3], rxF[3];
        rs_pose_to_global(&motion_.pose, surf_.a, o);
        for (int d = 0; d < 3; d++)
            r[d] = o[d] - s.com[d];
        rs_cross3(r, F, rxF);
        pv = 0.0;
        for (int d = 0; d < 3; d++)
            pv += (M[d] + rxF[d]) * s.axis[d];
    } else {
        pv = F[0] * s.axis[0] + F[1] * s.axis[1] + F[2] * s.axis[2];
    }
    double op; // the rate along the axis
    if (s.auto_mode) {
        const double err = (s.sp - pv) * spinv;
        const double lo = 0.9, hi = 1.0, scale = 0.1;
        double k;
        if (ncontact == 0)
            k = s.op_max;
        else if (std::fabs(err) <= lo)
            k = scale * s.op_min;
        else if (std::fabs(err) >= hi)
            k = s.op_min;
        else
            k = scale * s.op_min +
                (1.0 - scale) * s.op_min * (std::fabs(err) - lo) / (hi - lo);
        op = -k * err;
        const double cap = ncontact > 0 ? s.op_min : s.op_max;
        if (std::fabs(op) > cap && op != 0.0)
            op *= cap / std::fabs(op);
    } else {
        const double err = s.sp - pv;
        s.sum_err += err * dt;
        const double dfdt = -(pv - s.old_pv) / dt;
        op = -s.op_max * (err * s.kp + s.sum_err * s.ki + dfdt * s.kd) * spinv;
        s.old_pv = pv;
        if (std::fabs(op) > s.op_max && op != 0.0) {
            op *= s.op_max / std::fabs(op);
            /* anti-windup: the integral that gives the saturated output */
            if (s.ki > 0.0)
                s.sum_err = (-(op > 0.0 ? 1.0 : -1.0) * s.sp - err * s.kp) / s.ki;
        }
    }
    if (s.torque) {
        motion_.omega = op;
    } else {
        double v[3];
        for (int d = 0; d < 3; d++)
            v[d] = op * s.axis[d];
        rs_motion_set_translation(&motion_, v);
    }
}

/* The largest distance of the surface's display points from the servo axis. */
double FixWallRigid::servo_reach()
{
    rs_trimesh m;
    std::memset(&m, 0, sizeof m);
    rs_error err;
    rs_error_clear(&err);
    const double span =
        std::sqrt(domain->xprd * domain->xprd + domain->yprd * domain->yprd +
                  domain->zprd * domain->zprd);
    if (rs_surface_triangulate(&surf_, span, 72, &m, &err) != RS_OK)
        fail(std::string("servo: ") + err.msg);
    double rmax = 0.0;
    for (int v = 0; v < m.nvert; v++) {
        double X[3], x[3], r[3], c[3];
        for (int d = 0; d < 3; d++)
            X[d] = m.xyz[3 * v + d];
        rs_pose_to_global(&motion_.pose, X, x);
        for (int d = 0; d < 3; d++)
            r[d] = x[d] - servo_.com[d];
        rs_cross3(servo_.axis, r, c);
        rmax = std::max(rmax, rs_norm3(c));
    }
    rs_trimesh_free(&m);
    return rmax;
}
