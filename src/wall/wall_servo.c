/* Keyword servo: the wall moves along an axis (or turns about it) so that the particles'
 * force (or torque) on it reaches a target, with the controller of LIGGGHTS's `fix
 * mesh/surface/stress/servo` (its PID with anti-windup, its `auto` mode), so that a servo
 * wall swapped for a wall/rigid one moves the same way.
 *
 * Order within a step, as LIGGGHTS's: rs_wall_advance moves the wall with the rate the
 * controller set at the end of the previous step; rs_wall_step computes the contacts;
 * rs_wall_servo reads the wall's total force (torque about com) along the axis and sets
 * the rate for the next step. */
#include "wall_impl.h"

#include "rigidsurf/vec.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define FAIL(...) return rs_error_set(err, RS_ERR_ARG, __VA_ARGS__)

/* The next word as a number of servo keyword kw. */
static int num(const char *const *arg, int narg, int *i, const char *kw, const char *what,
               double *v, rs_error *err)
{
    if (*i >= narg || wall_is_keyword(arg[*i]))
        FAIL("keyword 'servo %s' expects %s", kw, what);
    char k[48];
    snprintf(k, sizeof k, "servo %s", kw);
    return wall_number(k, what, arg[(*i)++], v, err);
}

/* servo com X Y Z ctrlPV force|torque axis AX AY AZ target_val F|v_name vel_max V
 *       [kp K] [ki K] [kd K] [mode auto] [ratio R], LIGGGHTS's words in any order, up to
 *       the next keyword of the wall. */
int wall_parse_servo(rs_wall *w, const char *const *arg, int narg, int *iarg, rs_error *err)
{
    wall_servo *s = &w->servo;
    s->on = 1;
    int have_com = 0, have_pv = 0, have_axis = 0, have_target = 0, have_vmax = 0, rc;
    int i = *iarg;
    while (i < narg && !wall_is_keyword(arg[i])) {
        const char *kw = arg[i++];
        if (strcmp(kw, "com") == 0) {
            for (int d = 0; d < 3; d++)
                if ((rc = num(arg, narg, &i, "com",
                              "the coordinates X Y Z of the wall's centre", &s->com[d],
                              err)))
                    return rc;
            have_com = 1;
        } else if (strcmp(kw, "ctrlPV") == 0) {
            if (i >= narg)
                FAIL("keyword 'servo ctrlPV' expects 'force' or 'torque'");
            const char *pv = arg[i++];
            if (strcmp(pv, "force") != 0 && strcmp(pv, "torque") != 0)
                FAIL("keyword 'servo ctrlPV' expects 'force' or 'torque', got '%s'", pv);
            s->torque = strcmp(pv, "torque") == 0;
            have_pv = 1;
        } else if (strcmp(kw, "axis") == 0) {
            for (int d = 0; d < 3; d++)
                if ((rc = num(arg, narg, &i, "axis", "the axis components AX AY AZ",
                              &s->axis[d], err)))
                    return rc;
            const double len = rs_norm3(s->axis);
            if (!(len > 0.0))
                FAIL("keyword 'servo axis' expects a non-zero axis");
            for (int d = 0; d < 3; d++)
                s->axis[d] /= len;
            have_axis = 1;
        } else if (strcmp(kw, "target_val") == 0) {
            if (i >= narg)
                FAIL("keyword 'servo target_val' expects a force or torque, or v_name");
            const char *t = arg[i];
            if (strncmp(t, "v_", 2) == 0 && t[2]) {
                snprintf(s->target_var, sizeof s->target_var, "%s", t + 2);
                i++;
            } else {
                if ((rc = num(arg, narg, &i, "target_val",
                              "a force or torque (non-zero), or v_name", &s->target, err)))
                    return rc;
                if (s->target == 0.0)
                    FAIL("keyword 'servo target_val' expects a non-zero target");
            }
            have_target = 1;
        } else if (strcmp(kw, "vel_max") == 0) {
            if ((rc = num(arg, narg, &i, "vel_max", "the largest speed of the wall (> 0)",
                          &s->vmax, err)))
                return rc;
            if (!(s->vmax > 0.0))
                FAIL("keyword 'servo vel_max' expects a speed > 0");
            have_vmax = 1;
        } else if (strcmp(kw, "kp") == 0 || strcmp(kw, "ki") == 0 ||
                   strcmp(kw, "kd") == 0) {
            double k;
            if ((rc = num(arg, narg, &i, kw, "a controller gain >= 0", &k, err)))
                return rc;
            if (k < 0.0)
                FAIL("keyword 'servo %s' expects a gain >= 0", kw);
            *(kw[1] == 'p' ? &s->kp : kw[1] == 'i' ? &s->ki : &s->kd) = k;
        } else if (strcmp(kw, "mode") == 0) {
            if (i >= narg || strcmp(arg[i], "auto") != 0)
                FAIL("keyword 'servo mode' expects 'auto'");
            i++;
            s->auto_mode = 1;
        } else if (strcmp(kw, "ratio") == 0) {
            if ((rc = num(arg, narg, &i, "ratio", "the auto mode's step ratio (> 0)",
                          &s->ratio, err)))
                return rc;
            if (!(s->ratio > 0.0))
                FAIL("keyword 'servo ratio' expects a ratio > 0");
        } else {
            FAIL("keyword 'servo': unknown word '%s'; expected com, ctrlPV, axis, "
                 "target_val, vel_max, kp, ki, kd, mode or ratio",
                 kw);
        }
    }
    if (!have_com || !have_pv || !have_axis || !have_target || !have_vmax)
        FAIL("keyword 'servo' needs com X Y Z, ctrlPV force|torque, axis AX AY AZ, "
             "target_val F and vel_max V");
    if (s->auto_mode && !(s->ratio > 0.0))
        FAIL("keyword 'servo mode auto' needs 'ratio R'");
    if (!s->auto_mode && s->kp == 0.0 && s->ki == 0.0 && s->kd == 0.0)
        FAIL("keyword 'servo': kp, ki and kd are all zero");
    w->moving = 1;
    if (s->torque && (rc = rs_motion_set_rotation(w->motion, s->com, s->axis, 0.0, err)))
        return rc;
    *iarg = i;
    return RS_OK;
}

/* The largest distance of the surface's display points from the servo axis. */
static int servo_reach(rs_wall *w, double *rmax, rs_error *err)
{
    rs_trimesh m;
    memset(&m, 0, sizeof m);
    const double *lo = w->run.box_lo, *hi = w->run.box_hi;
    const double span =
        sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
             (hi[2] - lo[2]) * (hi[2] - lo[2]));
    const int rc = rs_surface_triangulate(w->surf, span, 72, &m, err);
    if (rc) {
        char msg[sizeof err->msg];
        snprintf(msg, sizeof msg, "%s", err->msg);
        return rs_error_set(err, rc, "servo: %s", msg);
    }
    *rmax = 0.0;
    for (int v = 0; v < m.nvert; v++) {
        double x[3], r[3], c[3];
        rs_pose_to_global(&w->motion->pose, &m.xyz[3 * v], x);
        for (int d = 0; d < 3; d++)
            r[d] = x[d] - w->servo.com[d];
        rs_cross3(w->servo.axis, r, c);
        *rmax = fmax(*rmax, rs_norm3(c));
    }
    rs_trimesh_free(&m);
    return RS_OK;
}

/* The run's constants: the target variable, the auto mode's slow speed (ratio times the
 * smallest radius per step), the largest rate; LIGGGHTS's limit vel_max < skin / (2 dt),
 * so that a neighbour list stays valid while the wall moves. */
int wall_init_servo(rs_wall *w, const rs_wall_block *b, rs_error *err)
{
    wall_servo *s = &w->servo;
    if (s->target_var[0]) {
        s->ivar = w->host.variable_find ? w->host.variable_find(w->host.ctx, s->target_var)
                                        : RS_VAR_MISSING;
        if (s->ivar < 0)
            FAIL("servo target_val: v_%s is not an equal-style variable", s->target_var);
    } else {
        s->ivar = -1;
        s->sp = -s->target; /* the particles' force on the wall opposes the target */
    }
    const double dt = w->run.dt, skin = w->run.skin;
    if (s->vmax >= skin / (2.0 * dt))
        FAIL("servo vel_max %g must stay below skin / (2 dt) = %g", s->vmax,
             skin / (2.0 * dt));
    double rmin = 1e300;
    for (int i = 0; i < b->n; i++)
        rmin = fmin(rmin, b->radius[i]);
    const double rall = wall_reduce1(w, rmin, RS_REDUCE_MIN);
    const double vmin = s->ratio * rall / dt;
    double rmax = 1.0; /* torque: speeds are angular, over the wall's farthest point */
    if (s->torque) {
        const int rc = servo_reach(w, &rmax, err);
        if (rc)
            return rc;
        if (!(rmax > 0.0))
            FAIL("servo ctrlPV torque: every point of the surface lies on the axis");
    }
    s->op_max = s->vmax / rmax;
    s->op_min = vmin / rmax;
    return RS_OK;
}

/* The controller, after the step's forces: the process value (force on the wall along
 * the axis, or torque about com along it), its error against the set point, and the
 * wall's next rate. */
int rs_wall_servo(rs_wall *w, double dt, rs_error *err)
{
    wall_servo *s = &w->servo;
    if (!s->on)
        return RS_OK;
    if (s->ivar >= 0) {
        s->sp = -w->host.variable_eval(w->host.ctx, s->ivar, RS_VAR_SERVO);
        if (s->sp == 0.0)
            FAIL("servo target_val v_%s is 0; the target must not be 0", s->target_var);
    }
    const double spinv = 1.0 / fabs(s->sp);
    double v[RS_WALL_NVEC];
    rs_wall_vector(w, v);
    const double *F = v, *M = v + 3;
    const int ncontact = (int)v[6];
    double pv;
    if (s->torque) {
        /* the moment about com: about the origin o, plus (o - com) x F */
        double o[3], r[3], rxF[3];
        rs_pose_to_global(&w->motion->pose, w->surf->a, o);
        for (int d = 0; d < 3; d++)
            r[d] = o[d] - s->com[d];
        rs_cross3(r, F, rxF);
        pv = 0.0;
        for (int d = 0; d < 3; d++)
            pv += (M[d] + rxF[d]) * s->axis[d];
    } else {
        pv = F[0] * s->axis[0] + F[1] * s->axis[1] + F[2] * s->axis[2];
    }
    double op; /* the rate along the axis */
    if (s->auto_mode) {
        const double e = (s->sp - pv) * spinv;
        const double lo = 0.9, hi = 1.0, scale = 0.1;
        double k;
        if (ncontact == 0)
            k = s->op_max;
        else if (fabs(e) <= lo)
            k = scale * s->op_min;
        else if (fabs(e) >= hi)
            k = s->op_min;
        else
            k = scale * s->op_min + (1.0 - scale) * s->op_min * (fabs(e) - lo) / (hi - lo);
        op = -k * e;
        const double cap = ncontact > 0 ? s->op_min : s->op_max;
        if (fabs(op) > cap && op != 0.0)
            op *= cap / fabs(op);
    } else {
        const double e = s->sp - pv;
        s->sum_err += e * dt;
        const double dfdt = -(pv - s->old_pv) / dt;
        op = -s->op_max * (e * s->kp + s->sum_err * s->ki + dfdt * s->kd) * spinv;
        s->old_pv = pv;
        if (fabs(op) > s->op_max && op != 0.0) {
            op *= s->op_max / fabs(op);
            /* anti-windup: the integral that gives the saturated output */
            if (s->ki > 0.0)
                s->sum_err = (-(op > 0.0 ? 1.0 : -1.0) * s->sp - e * s->kp) / s->ki;
        }
    }
    if (s->torque) {
        w->motion->omega = op;
    } else {
        double vel[3];
        for (int d = 0; d < 3; d++)
            vel[d] = op * s->axis[d];
        rs_motion_set_translation(w->motion, vel);
    }
    return RS_OK;
}
