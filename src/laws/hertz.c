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
#include "hertz_kernel.h"
#include "rigidsurf/vec.h"
#include "rs_compiler.h"

#include <math.h>

static const char *const rs_hertz_props[P_COUNT] = {"Y_particle", "nu_particle", "Y_wall",
                                                    "nu_wall",    "restitution", "friction",
                                                    "curvature"};

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

/* Two state variables (the law's own) get their own copy, which vectorises. */
RS_INLINE void hertz_run(rs_law_block *b, const double *rr, double Yeff, double Geff,
                         double beta, double mu, const int nd, const int update)
{
    if (b->nStateVar == 2)
        hertz_block(b->nSlvNod, 2, b->dTimCur, b->rdisp, b->drdisp, b->drot, b->vrel, rr,
                    b->mass, b->areaSlv, b->stress, b->statev, b->sed, b->svd, b->sfd, Yeff,
                    Geff, beta, mu, nd, update);
    else
        hertz_block(b->nSlvNod, b->nStateVar, b->dTimCur, b->rdisp, b->drdisp, b->drot,
                    b->vrel, rr, b->mass, b->areaSlv, b->stress, b->statev, b->sed, b->svd,
                    b->sfd, Yeff, Geff, beta, mu, nd, update);
}

RS_MULTIVERSION
static int rs_hertz_update(const rs_law *law, rs_law_block *b, rs_error *err)
{
    const double *p = b->props;
    const int use_reff = p[P_CURV] != 0.0;
    if (!b->radius || !b->mass || !b->vrel || (use_reff && !b->reff)) {
        return rs_error_set(err, RS_ERR_ARG,
                            "law '%s' needs the DEM extension: radius, mass, vrel%s",
                            law->name, use_reff ? " and reff (curvature = 1)" : "");
    }
    double Yeff, Geff, beta, mu;
    rs_hertz_constants(p, &Yeff, &Geff, &beta, &mu);
    const double *rr = use_reff ? b->reff : b->radius;
    if (b->nDir == 3 && !b->setup)
        hertz_run(b, rr, Yeff, Geff, beta, mu, 3, 1);
    else if (b->nDir == 3)
        hertz_run(b, rr, Yeff, Geff, beta, mu, 3, 0);
    else if (!b->setup)
        hertz_run(b, rr, Yeff, Geff, beta, mu, 2, 1);
    else
        hertz_run(b, rr, Yeff, Geff, beta, mu, 2, 0);
    /* fluxes, and the energies this law never has, are zero for every contact */
    for (int c = 0; c < b->nSlvNod; ++c) {
        b->fluxSlv[c] = 0.0;
        b->fluxMst[c] = 0.0;
        b->scd[c] = 0.0;
        b->spd[c] = 0.0;
        if (b->setup) {
            b->svd[c] = 0.0;
            b->sfd[c] = 0.0;
        }
    }
    return RS_OK;
}

/* The particle's Rayleigh time (LIGGGHTS's criterion for its granular models). */
static double rs_hertz_critical_step(const rs_law *law, const double *p, int np, double R,
                                     double m, double A)
{
    (void)law, (void)A;
    return np >= 2 ? rs_rayleigh_time(R, m, p[0], p[1]) : 0.0;
}

const rs_law rs_law_hertz = {
    .name = "hertz",
    .nprops = P_COUNT,
    .nstatev = 2,
    .prop_names = rs_hertz_props,
    .init = rs_hertz_init,
    .update = rs_hertz_update,
    .critical_step = rs_hertz_critical_step,
    .reach = rs_law_reach_touching,
    .skips = RS_LAW_SKIPS_STRESS | RS_LAW_SKIPS_ENERGY | RS_LAW_SKIPS_COORDMST |
             RS_LAW_SKIPS_SLIP | RS_LAW_SKIPS_DRDISP1,
    .sets = RS_LAW_SETS_ENERGIES | RS_LAW_SETS_NO_HEAT | RS_LAW_SETS_NO_CREEP_PLASTIC |
            RS_LAW_SETS_STRESS,
    .fused = &rs_hertz_fused,
};
