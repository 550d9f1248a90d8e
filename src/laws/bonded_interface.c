/* rigidsurf: bonded interface, after the Abaqus VUINTER example.
 *
 * A slave whose initial gap -rdisp(1) is below the cutoff bonds on its first call and
 * stays bonded, in compression and in tension. The bond is a layer of the given
 * thickness t:
 * - Normal: strain increment drdisp(1)/t, elastic-plastic with linear isotropic
 *   hardening. The 1D modulus is E, as in the Abaqus example (a uniaxial-stress layer,
 *   nu enters only through G). Trial s = s_old + E de; if |s| > sy the return mapping
 *   gives de_p = (|s| - sy)/(E + H), s -= sign(s) E de_p, sy += H de_p.
 * - Shear: elastic, tau += G drdisp(2:3)/t with G = E/(2(1 + nu)).
 * - Heat: conduction through the layer, fluxSlv = k (T_mst - T_slv)/t, fluxMst = -fluxSlv.
 * - spd = plastic work per area over the increment, (sy_old + sy_new)/2 de_p t, exact for
 *   linear hardening. sed = (s^2/(2E) + tau^2/(2G)) t.
 * Unbonded slaves are not in contact: zero stress and flux. Contacts passed with
 * r_MaxVal (leaving) get zero stress and flux and keep their state.
 * props: gap_cutoff, E, nu, yield_stress, hardening, thickness, conductivity.
 * statev: (1) 1 once initialised, (2) bonded flag, (3) current yield stress. */
#include "builtin.h"

#include <math.h>

enum { P_CUTOFF, P_E, P_NU, P_SY0, P_H, P_T, P_K, P_COUNT };
enum { S_INIT, S_BONDED, S_YIELD, S_COUNT };

static const char *const rs_bonded_props[P_COUNT] = {
    "gap_cutoff", "E", "nu", "yield_stress", "hardening", "thickness", "conductivity"};

static int rs_bonded_init(const rs_law *law, const double *p, int nprops, rs_error *err)
{
    (void)nprops;
    const char *name = law->name;
    if (!(p[P_CUTOFF] >= 0.0)) {
        return rs_error_set(err, RS_ERR_ARG,
                            "law '%s': property 'gap_cutoff' must be >= 0, got %g", name,
                            p[P_CUTOFF]);
    }
    if (!(p[P_E] > 0.0)) {
        return rs_error_set(err, RS_ERR_ARG, "law '%s': property 'E' must be > 0, got %g",
                            name, p[P_E]);
    }
    if (!(p[P_NU] > -1.0 && p[P_NU] < 0.5)) {
        return rs_error_set(err, RS_ERR_ARG,
                            "law '%s': property 'nu' must be in (-1, 0.5), got %g", name,
                            p[P_NU]);
    }
    if (!(p[P_SY0] > 0.0)) {
        return rs_error_set(err, RS_ERR_ARG,
                            "law '%s': property 'yield_stress' must be > 0, got %g", name,
                            p[P_SY0]);
    }
    if (!(p[P_H] >= 0.0)) {
        return rs_error_set(err, RS_ERR_ARG,
                            "law '%s': property 'hardening' must be >= 0, got %g", name,
                            p[P_H]);
    }
    if (!(p[P_T] > 0.0)) {
        return rs_error_set(err, RS_ERR_ARG,
                            "law '%s': property 'thickness' must be > 0, got %g", name,
                            p[P_T]);
    }
    if (!(p[P_K] >= 0.0)) {
        return rs_error_set(err, RS_ERR_ARG,
                            "law '%s': property 'conductivity' must be >= 0, got %g", name,
                            p[P_K]);
    }
    return RS_OK;
}

static int rs_bonded_update(const rs_law *law, rs_law_block *b, rs_error *err)
{
    (void)law;
    (void)err;
    const double *p = b->props;
    const double E = p[P_E], H = p[P_H], t = p[P_T], k = p[P_K];
    const double G = E / (2.0 * (1.0 + p[P_NU]));
    const int nd = b->nDir, nsv = b->nStateVar;
    const int per_contact_tmst = b->numDefTfv > 1 && b->numDefTfv == b->nSlvNod;
    for (int c = 0; c < b->nSlvNod; ++c) {
        const double h = RS_A2(b->rdisp, nd, 0, c);
        if (RS_LAW_LEAVING(h)) {
            rs_law_zero_contact(b, c);
            continue;
        }
        double *sv = b->statev + (size_t)c * (size_t)nsv;
        double init = sv[S_INIT], bonded = sv[S_BONDED], sy = sv[S_YIELD];
        if (init == 0.0) {
            init = 1.0;
            bonded = -h < p[P_CUTOFF] ? 1.0 : 0.0;
            sy = p[P_SY0];
        }
        double old[3] = {0.0, 0.0, 0.0};
        for (int i = 0; i < nd; ++i) {
            old[i] = RS_A2(b->stress, nd, i, c);
        }
        rs_law_zero_contact(b, c);
        if (bonded != 0.0) {
            const double trial = old[0] + E * RS_A2(b->drdisp, nd, 0, c) / t;
            const double f = fabs(trial) - sy;
            double s = trial, dep = 0.0, sy_new = sy;
            if (f > 0.0) {
                dep = f / (E + H);
                s = trial - copysign(E * dep, trial);
                sy_new = sy + H * dep;
            }
            RS_A2(b->stress, nd, 0, c) = s;
            b->spd[c] = 0.5 * (sy + sy_new) * dep * t;
            double tau2 = 0.0;
            for (int i = 1; i < nd; ++i) {
                const double tau = old[i] + G * RS_A2(b->drdisp, nd, i, c) / t;
                RS_A2(b->stress, nd, i, c) = tau;
                tau2 += tau * tau;
            }
            b->sed[c] = (s * s / (2.0 * E) + tau2 / (2.0 * G)) * t;
            if (b->nTemp > 0) {
                const double tm = b->tempMst[per_contact_tmst ? c : 0];
                const double q = k * (tm - b->tempSlv[c]) / t;
                b->fluxSlv[c] = q;
                b->fluxMst[c] = -q;
            }
            sy = sy_new;
        }
        if (!b->setup) {
            sv[S_INIT] = init;
            sv[S_BONDED] = bonded;
            sv[S_YIELD] = sy;
        }
    }
    return RS_OK;
}

/* The bonded layer in compression: s = E h / t, a stiffness E A / t. */
static double rs_bonded_critical_step(const rs_law *law, const double *p, int np, double R,
                                      double m, double A)
{
    (void)law, (void)R;
    const double K = np >= P_COUNT && p[P_T] > 0.0 ? p[P_E] * A / p[P_T] : 0.0;
    return K > 0.0 && m > 0.0 ? 2.0 * sqrt(m / K) : 0.0;
}

const rs_law rs_law_bonded_interface = {
    .name = "bonded_interface",
    .nprops = P_COUNT,
    .nstatev = S_COUNT,
    .prop_names = rs_bonded_props,
    .init = rs_bonded_init,
    .update = rs_bonded_update,
    .critical_step = rs_bonded_critical_step,
    .skips = RS_LAW_SKIPS_COORDMST,
};
