/* fix wall/rigid: its motion keywords (move linear, rotate; docs/fix_wall_rigid.md,
 * "Motion") and the rates of their v_ variables, evaluated every step. */
#include "fix_wall_rigid.h"
#include "rigidsurf/vec.h"

#include "input.h"
#include "variable.h"

#include <cstring>
#include <string>

using namespace LAMMPS_NS;

namespace
{

int rates_callback(double t, double vel[3], double *omega, void *ctx)
{
    (void)t;
    static_cast<FixWallRigid *>(ctx)->motion_rates(vel, omega);
    return 0;
}

int spin_callback(double t, double *omega, void *ctx)
{
    (void)t;
    static_cast<FixWallRigid *>(ctx)->spin_rate(omega);
    return 0;
}

} // namespace

/* move linear VX VY VZ | rotate origin X Y Z axis AX AY AZ (omega W | period P)
 * [centre moving|fixed] | spin origin X Y Z axis AX AY AZ (omega W | period P). A value
 * may be v_NAME, an equal-style variable evaluated every step. */
int FixWallRigid::parse_motion(int narg, char **arg, int iarg)
{
    auto value = [&](const char *kw, const char *what, std::string &var) -> double {
        if (iarg >= narg)
            fail(std::string("keyword '") + kw + "' expects " + what);
        const char *s = arg[iarg++];
        if (std::strncmp(s, "v_", 2) == 0 && s[2]) {
            var = s + 2;
            return 0.0;
        }
        var.clear();
        return number(kw, what, s);
    };
    auto constant = [&](const char *kw, const char *what) -> double {
        if (iarg >= narg)
            fail(std::string("keyword '") + kw + "' expects " + what);
        return number(kw, what, arg[iarg++]);
    };
    if (std::strcmp(arg[iarg], "move") == 0) {
        iarg++;
        if (iarg >= narg || std::strcmp(arg[iarg], "linear") != 0)
            fail("keyword 'move' expects 'linear VX VY VZ'");
        iarg++;
        double vel[3];
        for (int d = 0; d < 3; d++)
            vel[d] = value("move linear", "a velocity component (number or v_name)",
                           var_vel_[d]);
        rs_motion_set_translation(&motion_, vel);
    } else {
        const bool spin = std::strcmp(arg[iarg], "spin") == 0;
        const std::string kw = spin ? "spin" : "rotate";
        iarg++;
        double origin[3], axis[3], omega = 0.0;
        std::string &var = spin ? var_spin_ : var_omega_;
        bool &by_period = spin ? spin_by_period_ : rot_by_period_;
        if (iarg >= narg || std::strcmp(arg[iarg], "origin") != 0)
            fail("keyword '" + kw + "' expects 'origin X Y Z axis AX AY AZ omega W' (or " +
                 "period P)");
        iarg++;
        for (int d = 0; d < 3; d++)
            origin[d] = constant((kw + " origin").c_str(), "a coordinate");
        if (iarg >= narg || std::strcmp(arg[iarg], "axis") != 0)
            fail("keyword '" + kw + "' expects 'axis AX AY AZ' after the origin");
        iarg++;
        for (int d = 0; d < 3; d++)
            axis[d] = constant((kw + " axis").c_str(), "an axis component");
        if (iarg >= narg)
            fail("keyword '" + kw + "' expects 'omega W' or 'period P' after the axis");
        if (std::strcmp(arg[iarg], "omega") == 0) {
            iarg++;
            omega = value((kw + " omega").c_str(),
                          "an angular speed in rad/time (number or v_name)", var);
            by_period = false;
        } else if (std::strcmp(arg[iarg], "period") == 0) {
            iarg++;
            const double period =
                value((kw + " period").c_str(), "a period (number or v_name)", var);
            if (var.empty()) {
                if (period == 0.0)
                    fail("keyword '" + kw + " period' expects a non-zero period");
                omega = 2.0 * RS_PI / period;
            }
            if (!spin)
                period_ = period;
            by_period = true;
        } else {
            fail("keyword '" + kw + "' expects 'omega W' or 'period P', got '" + arg[iarg] +
                 "'");
        }
        rs_error err;
        rs_error_clear(&err);
        if (spin) {
            if (motion_.spin_on)
                fail("keyword 'spin' is given once");
            if (rs_motion_set_spin(&motion_, origin, axis, omega, &err) != RS_OK)
                fail(err.msg);
            if (!var.empty())
                motion_.spin_rates = spin_callback;
        } else {
            if (rs_motion_set_rotation(&motion_, origin, axis, omega, &err) != RS_OK)
                fail(err.msg);
        }
        if (!spin && iarg < narg && std::strcmp(arg[iarg], "centre") == 0) {
            iarg++;
            if (iarg < narg && std::strcmp(arg[iarg], "fixed") == 0)
                rs_motion_set_center_fixed(&motion_, 1);
            else if (iarg < narg && std::strcmp(arg[iarg], "moving") == 0)
                rs_motion_set_center_fixed(&motion_, 0);
            else
                fail(std::string("keyword 'rotate ... centre' expects 'moving' or 'fixed', "
                                 "got '") +
                     (iarg < narg ? arg[iarg] : "(end of line)") + "'");
            iarg++;
        }
    }
    moving_ = true;
    bool vars = !var_omega_.empty();
    for (int d = 0; d < 3; d++)
        vars = vars || !var_vel_[d].empty();
    if (vars)
        motion_.rates = rates_callback;
    motion_.ctx = this;
    return iarg;
}

void FixWallRigid::motion_rates(double vel[3], double *omega)
{
    for (int d = 0; d < 3; d++)
        if (ivar_vel_[d] >= 0)
            vel[d] = input->variable->compute_equal(ivar_vel_[d]);
    if (ivar_omega_ >= 0) {
        double v = input->variable->compute_equal(ivar_omega_);
        if (rot_by_period_) {
            if (v == 0.0)
                fail("variable v_" + var_omega_ + " (rotate period) is zero");
            v = 2.0 * RS_PI / v;
        }
        *omega = v;
    }
}

void FixWallRigid::spin_rate(double *omega)
{
    if (ivar_spin_ < 0)
        return;
    double v = input->variable->compute_equal(ivar_spin_);
    if (spin_by_period_) {
        if (v == 0.0)
            fail("variable v_" + var_spin_ + " (spin period) is zero");
        v = 2.0 * RS_PI / v;
    }
    *omega = v;
}
