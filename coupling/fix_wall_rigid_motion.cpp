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

} // namespace

/* move linear VX VY VZ | rotate origin X Y Z axis AX AY AZ (omega W | period P)
 * [centre moving|fixed]. A value may be v_NAME, an equal-style variable evaluated every
 * step. */
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
        iarg++;
        double origin[3], axis[3], omega = 0.0;
        if (iarg >= narg || std::strcmp(arg[iarg], "origin") != 0)
            fail("keyword 'rotate' expects 'origin X Y Z axis AX AY AZ omega W' (or period "
                 "P)");
        iarg++;
        for (int d = 0; d < 3; d++)
            origin[d] = constant("rotate origin", "a coordinate");
        if (iarg >= narg || std::strcmp(arg[iarg], "axis") != 0)
            fail("keyword 'rotate' expects 'axis AX AY AZ' after the origin");
        iarg++;
        for (int d = 0; d < 3; d++)
            axis[d] = constant("rotate axis", "an axis component");
        if (iarg >= narg)
            fail("keyword 'rotate' expects 'omega W' or 'period P' after the axis");
        if (std::strcmp(arg[iarg], "omega") == 0) {
            iarg++;
            omega = value("rotate omega", "an angular speed in rad/time (number or v_name)",
                          var_omega_);
            rot_by_period_ = false;
        } else if (std::strcmp(arg[iarg], "period") == 0) {
            iarg++;
            period_ = value("rotate period", "a period (number or v_name)", var_omega_);
            if (var_omega_.empty()) {
                if (period_ == 0.0)
                    fail("keyword 'rotate period' expects a non-zero period");
                omega = 2.0 * RS_PI / period_;
            }
            rot_by_period_ = true;
        } else {
            fail(std::string("keyword 'rotate' expects 'omega W' or 'period P', got '") +
                 arg[iarg] + "'");
        }
        rs_error err;
        rs_error_clear(&err);
        if (rs_motion_set_rotation(&motion_, origin, axis, omega, &err) != RS_OK)
            fail(err.msg);
        if (iarg < narg && std::strcmp(arg[iarg], "centre") == 0) {
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
    if (vars) {
        motion_.rates = rates_callback;
        motion_.ctx = this;
    }
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
