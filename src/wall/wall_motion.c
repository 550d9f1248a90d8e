/* The wall's motion: its keywords (move linear, move variable, rotate, its centre moving
 * or fixed, spin; docs/fix_wall_rigid.md, "Motion"), the rates (and a translation given as
 * such) of their variables evaluated every step through the host, and the motion advanced
 * before each step. */
#include "wall_impl.h"

#include "rigidsurf/vec.h"

#include <stdio.h>
#include <string.h>

#define FAIL(...) return rs_error_set(err, RS_ERR_ARG, __VA_ARGS__)

/* A variable's value, the period's rate (2 pi / P) when by_period; a zero period stops
 * the motion with a message (which: "rotate period"). */
static int rate_of(rs_wall *w, int ivar, const char *name, int by_period, const char *which,
                   double *out)
{
    double v = w->host.variable_eval(w->host.ctx, ivar, RS_VAR_MOTION);
    if (by_period) {
        if (v == 0.0) {
            rs_error_set(&w->rates_err, RS_ERR_ARG, "variable v_%s (%s) is zero", name,
                         which);
            return 1;
        }
        v = 2.0 * RS_PI / v;
    }
    *out = v;
    return 0;
}

static int rates_callback(double t, double vel[3], double *omega, void *ctx)
{
    (void)t;
    rs_wall *w = ctx;
    for (int d = 0; d < 3; d++)
        if (w->ivar_vel[d] >= 0)
            vel[d] = w->host.variable_eval(w->host.ctx, w->ivar_vel[d], RS_VAR_MOTION);
    if (w->ivar_omega >= 0)
        return rate_of(w, w->ivar_omega, w->var_omega, w->rot_by_period, "rotate period",
                       omega);
    return 0;
}

/* move variable: the translation D, its variables' values or its numbers. */
static int place_callback(double t, double disp[3], void *ctx)
{
    (void)t;
    rs_wall *w = ctx;
    for (int d = 0; d < 3; d++)
        disp[d] = w->ivar_disp[d] >= 0
                      ? w->host.variable_eval(w->host.ctx, w->ivar_disp[d], RS_VAR_MOTION)
                      : w->disp_given[d];
    return 0;
}

static int spin_callback(double t, double *omega, void *ctx)
{
    (void)t;
    rs_wall *w = ctx;
    if (w->ivar_spin < 0)
        return 0;
    return rate_of(w, w->ivar_spin, w->var_spin, w->spin_by_period, "spin period", omega);
}

/* A rate: a number, or v_NAME (var takes NAME, the value 0). */
static int value(const char *const *arg, int narg, int *i, const char *kw, const char *what,
                 char var[WALL_NAME], double *v, rs_error *err)
{
    if (*i >= narg)
        FAIL("keyword '%s' expects %s", kw, what);
    const char *s = arg[(*i)++];
    if (strncmp(s, "v_", 2) == 0 && s[2]) {
        snprintf(var, WALL_NAME, "%s", s + 2);
        *v = 0.0;
        return RS_OK;
    }
    var[0] = '\0';
    return wall_number(kw, what, s, v, err);
}

static int constant(const char *const *arg, int narg, int *i, const char *kw,
                    const char *what, double *v, rs_error *err)
{
    if (*i >= narg)
        FAIL("keyword '%s' expects %s", kw, what);
    return wall_number(kw, what, arg[(*i)++], v, err);
}

/* rotate|spin origin X Y Z axis AX AY AZ (omega W | period P) [centre moving|fixed] */
static int turn(rs_wall *w, const char *const *arg, int narg, int *iarg, int spin,
                rs_error *err)
{
    const char *kw = spin ? "spin" : "rotate";
    char k[32];
    int i = *iarg + 1, rc;
    double origin[3], axis[3], omega = 0.0;
    char *var = spin ? w->var_spin : w->var_omega;
    int *by_period = spin ? &w->spin_by_period : &w->rot_by_period;
    if (i >= narg || strcmp(arg[i], "origin") != 0)
        FAIL("keyword '%s' expects 'origin X Y Z axis AX AY AZ omega W' (or period P)", kw);
    i++;
    snprintf(k, sizeof k, "%s origin", kw);
    for (int d = 0; d < 3; d++)
        if ((rc = constant(arg, narg, &i, k, "a coordinate", &origin[d], err)))
            return rc;
    if (i >= narg || strcmp(arg[i], "axis") != 0)
        FAIL("keyword '%s' expects 'axis AX AY AZ' after the origin", kw);
    i++;
    snprintf(k, sizeof k, "%s axis", kw);
    for (int d = 0; d < 3; d++)
        if ((rc = constant(arg, narg, &i, k, "an axis component", &axis[d], err)))
            return rc;
    if (i >= narg)
        FAIL("keyword '%s' expects 'omega W' or 'period P' after the axis", kw);
    if (strcmp(arg[i], "omega") == 0) {
        i++;
        snprintf(k, sizeof k, "%s omega", kw);
        if ((rc = value(arg, narg, &i, k, "an angular speed in rad/time (number or v_name)",
                        var, &omega, err)))
            return rc;
        *by_period = 0;
    } else if (strcmp(arg[i], "period") == 0) {
        i++;
        snprintf(k, sizeof k, "%s period", kw);
        double period;
        if ((rc =
                 value(arg, narg, &i, k, "a period (number or v_name)", var, &period, err)))
            return rc;
        if (!var[0]) {
            if (period == 0.0)
                FAIL("keyword '%s period' expects a non-zero period", kw);
            omega = 2.0 * RS_PI / period;
        }
        if (!spin)
            w->period = period;
        *by_period = 1;
    } else {
        FAIL("keyword '%s' expects 'omega W' or 'period P', got '%s'", kw, arg[i]);
    }
    if (spin) {
        if (w->motion->spin_on)
            FAIL("keyword 'spin' is given once");
        if ((rc = rs_motion_set_spin(w->motion, origin, axis, omega, err)))
            return rc;
        if (var[0])
            w->motion->spin_rates = spin_callback;
    } else if ((rc = rs_motion_set_rotation(w->motion, origin, axis, omega, err))) {
        return rc;
    }
    if (!spin && i < narg && strcmp(arg[i], "centre") == 0 && w->motion->place)
        FAIL("keyword 'rotate ... centre' does not go with 'move variable', whose "
             "translation is given in space");
    if (!spin && i < narg && strcmp(arg[i], "centre") == 0) {
        i++;
        if (i < narg && strcmp(arg[i], "fixed") == 0)
            rs_motion_set_center_fixed(w->motion, 1);
        else if (i < narg && strcmp(arg[i], "moving") == 0)
            rs_motion_set_center_fixed(w->motion, 0);
        else
            FAIL("keyword 'rotate ... centre' expects 'moving' or 'fixed', got '%s'",
                 i < narg ? arg[i] : "(end of line)");
        i++;
    }
    *iarg = i;
    return RS_OK;
}

/* move linear VX VY VZ | move variable DX DY DZ VX VY VZ | rotate ... | spin ...: a value
 * may be v_NAME, an equal-style variable evaluated every step. */
int wall_parse_motion(rs_wall *w, const char *const *arg, int narg, int *iarg,
                      rs_error *err)
{
    int i = *iarg, rc;
    if (strcmp(arg[i], "move") == 0) {
        i++;
        if (i >= narg || (strcmp(arg[i], "linear") != 0 && strcmp(arg[i], "variable") != 0))
            FAIL(
                "keyword 'move' expects 'linear VX VY VZ' or 'variable DX DY DZ VX VY VZ'");
        if (w->motion->place || w->var_vel[0][0] || w->var_vel[1][0] || w->var_vel[2][0])
            FAIL("keyword 'move' is given once");
        const int given = strcmp(arg[i++], "variable") == 0;
        const char *mkw = given ? "move variable" : "move linear";
        if (given) {
            if (w->motion->center_fixed)
                FAIL("keyword 'move variable' gives the translation in space: it does not "
                     "go with 'rotate ... centre fixed'");
            for (int d = 0; d < 3; d++)
                if ((rc = value(arg, narg, &i, "move variable",
                                "a displacement component (number or v_name)",
                                w->var_disp[d], &w->disp_given[d], err)))
                    return rc;
            w->motion->place = place_callback;
        }
        double vel[3];
        for (int d = 0; d < 3; d++)
            if ((rc = value(arg, narg, &i, mkw, "a velocity component (number or v_name)",
                            w->var_vel[d], &vel[d], err)))
                return rc;
        rs_motion_set_translation(w->motion, vel);
    } else if ((rc = turn(w, arg, narg, &i, strcmp(arg[i], "spin") == 0, err))) {
        return rc;
    }
    w->moving = 1;
    int vars = w->var_omega[0] != '\0';
    for (int d = 0; d < 3; d++)
        vars = vars || w->var_vel[d][0];
    if (vars)
        w->motion->rates = rates_callback;
    w->motion->ctx = w;
    *iarg = i;
    return RS_OK;
}

/* The motion's variables, found once per run. */
int wall_init_variables(rs_wall *w, rs_error *err)
{
    const char *names[8] = {w->var_vel[0], w->var_vel[1],  w->var_vel[2],  w->var_omega,
                            w->var_spin,   w->var_disp[0], w->var_disp[1], w->var_disp[2]};
    int *index[8] = {&w->ivar_vel[0], &w->ivar_vel[1],  &w->ivar_vel[2],  &w->ivar_omega,
                     &w->ivar_spin,   &w->ivar_disp[0], &w->ivar_disp[1], &w->ivar_disp[2]};
    for (int k = 0; k < 8; k++) {
        *index[k] = -1;
        if (!names[k][0])
            continue;
        const int iv = w->host.variable_find ? w->host.variable_find(w->host.ctx, names[k])
                                             : RS_VAR_MISSING;
        if (iv == RS_VAR_NOT_EQUAL)
            FAIL("variable v_%s (motion) must be equal-style", names[k]);
        if (iv < 0)
            FAIL("variable v_%s (motion) does not exist", names[k]);
        *index[k] = iv;
    }
    return RS_OK;
}

int rs_wall_advance(rs_wall *w, double dt, rs_error *err)
{
    rs_error_clear(&w->rates_err);
    const int rc = rs_motion_advance(w->motion, dt, err);
    if (rc == RS_OK)
        return RS_OK;
    if (w->rates_err.code)
        return rs_error_set(err, w->rates_err.code, "%s", w->rates_err.msg);
    char msg[sizeof err->msg];
    snprintf(msg, sizeof msg, "%s", err->msg);
    return rs_error_set(err, rc, "motion: %s", msg);
}

rs_motion *rs_wall_motion(rs_wall *w)
{
    return w->motion;
}
