/* rigidsurf: Hertz contact with tangential history, as LIGGGHTS 3.8.0 computes it for
 * walls (normal_model_hertz.h, tangential_model_history.h, global_properties.cpp):
 *   Y* = 1/((1-nu_p^2)/Y_p + (1-nu_w^2)/Y_w)
 *   G* = 1/(2(2-nu_p)(1+nu_p)/Y_p + 2(2-nu_w)(1+nu_w)/Y_w)
 *   beta = ln e / sqrt(ln^2 e + pi^2)
 *   Sn = 2 Y* sqrt(R d), St = 8 G* sqrt(R d), kn = 4/3 Y* sqrt(R d), kt = St
 *   gn = -2 sqrt(5/6) beta sqrt(Sn m), gt likewise with St
 *   Fn = -gn vn + kn d            (no clamp: LIGGGHTS's limitForce is off by default)
 *   s <- drot s + drdisp(2:3); Ft = -kt s, capped at mu |Fn| with s reset to -Ft/kt,
 *   else Ft -= gt vt.
 * d = rdisp(1), vn = vrel(1), vt = vrel(2:3); R is the particle radius (or reff with the
 * curvature flag), m its mass. The operation order is LIGGGHTS's, so a plane contact
 * matches it bit for bit. Stress is force per areaSlv: stress(1) = Fn/A,
 * stress(2:3) = -Ft/A (the traction on the master).
 * statev (2): the shear displacement s in (t1, t2), reset when the contact opens.
 * On a setup call (b->setup) s is neither advanced nor written, as in LIGGGHTS.
 * Energies per area: sed = (2/5 kn d^2 + kt |s|^2/2)/A (Hertz elastic energy plus the
 * tangential spring at the current kt), svd = (gn vn^2 + gt |vt|^2) dt/A while sticking,
 * sfd = mu |Fn| times the slip beyond the elastic limit, /A. */
#include "builtin.h"

#include <math.h>

enum { P_YP, P_NUP, P_YW, P_NUW, P_E, P_MU, P_CURV, P_COUNT };

static const char *const rs_hertz_props[P_COUNT] = {"Y_particle", "nu_particle", "Y_wall",
                                                    "nu_wall",    "restitution", "friction",
                                                    "curvature"};

static const double rs_pi = 3.14159265358979323846;
static const double rs_sqrt_five_over_six = 0.91287092917527685576161630466800355658790782;

/* Checks lo < p[i] <= hi (open_lo) or lo <= p[i] <= hi. */
static int rs_check_range(const rs_law *law, const double *p, int i, double lo, int open_lo,
                          double hi, const char *expect, rs_error *err)
{
    if (!((open_lo ? p[i] > lo : p[i] >= lo) && p[i] <= hi)) {
        return rs_error_set(err, RS_ERR_ARG, "law '%s': property '%s' must be %s, got %g",
                            law->name, law->prop_names[i], expect, p[i]);
    }
    return RS_OK;
}

static int rs_hertz_init(const rs_law *law, const double *p, int nprops, rs_error *err)
{
    (void)nprops;
    int rc;
    if ((rc = rs_check_range(law, p, P_YP, 0.0, 1, HUGE_VAL, "> 0", err)) ||
        (rc = rs_check_range(law, p, P_NUP, 0.0, 0, 0.5, "in [0, 0.5]", err)) ||
        (rc = rs_check_range(law, p, P_YW, 0.0, 1, HUGE_VAL, "> 0", err)) ||
        (rc = rs_check_range(law, p, P_NUW, 0.0, 0, 0.5, "in [0, 0.5]", err)) ||
        (rc = rs_check_range(law, p, P_E, 0.0, 1, 1.0, "in (0, 1]", err)) ||
        (rc = rs_check_range(law, p, P_MU, 0.0, 0, HUGE_VAL, ">= 0", err))) {
        return rc;
    }
    if (p[P_CURV] != 0.0 && p[P_CURV] != 1.0) {
        return rs_error_set(err, RS_ERR_ARG,
                            "law '%s': property 'curvature' must be 0 or 1, got %g",
                            law->name, p[P_CURV]);
    }
    return RS_OK;
}

static int rs_hertz_update(const rs_law *law, rs_law_block *b, rs_error *err)
{
    const double *p = b->props;
    const int use_reff = p[P_CURV] != 0.0;
    if (!b->radius || !b->mass || !b->vrel || (use_reff && !b->reff)) {
        return rs_error_set(err, RS_ERR_ARG,
                            "law '%s' needs the DEM extension: radius, mass, vrel%s",
                            law->name, use_reff ? " and reff (curvature = 1)" : "");
    }
    const double Yp = p[P_YP], vp = p[P_NUP], Yw = p[P_YW], vw = p[P_NUW];
    const double Yeff = 1. / ((1. - pow(vp, 2.)) / Yp + (1. - pow(vw, 2.)) / Yw);
    const double Geff =
        1. / (2. * (2. - vp) * (1. + vp) / Yp + 2. * (2. - vw) * (1. + vw) / Yw);
    const double loge = log(p[P_E]);
    const double beta = loge / sqrt(pow(loge, 2.) + pow(rs_pi, 2.));
    const double mu = p[P_MU];
    const double dt = b->dTimCur;
    const int nd = b->nDir, nsv = b->nStateVar, update = !b->setup;
    for (int c = 0; c < b->nSlvNod; ++c) {
        const double d = RS_A2(b->rdisp, nd, 0, c);
        double *sv = b->statev + (size_t)c * (size_t)nsv;
        if (rs_law_no_force(b, c, sv)) {
            continue;
        }
        const double reff = use_reff ? b->reff[c] : b->radius[c];
        const double meff = b->mass[c];
        const double area = b->areaSlv[c];
        const double sqrtval = sqrt(reff * d);
        const double Sn = 2. * Yeff * sqrtval;
        const double St = 8. * Geff * sqrtval;
        const double kn = 4. / 3. * Yeff * sqrtval;
        const double kt = St;
        const double gamman = -2. * rs_sqrt_five_over_six * beta * sqrt(Sn * meff);
        const double gammat = -2. * rs_sqrt_five_over_six * beta * sqrt(St * meff);
        const double vn = RS_A2(b->vrel, nd, 0, c);
        const double Fn_damping = -gamman * vn;
        const double Fn_contact = kn * d;
        const double Fn = Fn_damping + Fn_contact;

        double s[2] = {sv[0], nd == 3 ? sv[1] : 0.0};
        const double vt[2] = {RS_A2(b->vrel, nd, 1, c),
                              nd == 3 ? RS_A2(b->vrel, nd, 2, c) : 0.0};
        if (update) {
            rs_law_advance_slip(b, c, s);
        }
        double ft[2], slip_work, damp_power;
        rs_law_tangential_history(kt, gammat, mu, Fn, vt, s, update, ft, &slip_work,
                                  &damp_power);

        rs_law_put_force(b, c, Fn, ft, area);
        b->sed[c] = (0.4 * kn * d * d + 0.5 * kt * (s[0] * s[0] + s[1] * s[1])) / area;
        if (update) {
            b->svd[c] = (Fn_damping * -vn + damp_power) * dt / area;
            b->sfd[c] = slip_work / area;
            rs_law_keep_shear(b, sv, s);
        }
    }
    return RS_OK;
}

const rs_law rs_law_hertz = {
    .name = "hertz",
    .nprops = P_COUNT,
    .nstatev = 2,
    .prop_names = rs_hertz_props,
    .init = rs_hertz_init,
    .update = rs_hertz_update,
};
