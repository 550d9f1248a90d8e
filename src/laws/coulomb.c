/* rigidsurf: Coulomb friction in the style of Abaqus FRIC, self-contained: the normal
 * pressure comes from a linear penalty in the same law.
 *   p = kn h for the overclosure h = rdisp(1) > 0, zero when open.
 *   Stick: tau = k_stick s_e, with the elastic slip s_e <- drot s_e + drdisp(2:3).
 *   Slip:  when |tau| > mu p, tau is scaled to mu p, s_e = tau / k_stick, and the slip
 *          beyond the elastic limit is dslip = (|tau_trial| - mu p) / k_stick.
 * stress(1) = p, stress(2:3) = tau (the traction on the master: a slave sliding along +t1
 * drags the master along +t1). sfd = mu p dslip (= tau . dslip), sed = kn h^2/2 +
 * |tau|^2/(2 k_stick). Stresses are per area (areaSlv is not used).
 * props: mu, k_stick (stress per length, > 0), kn (stress per length, > 0).
 * statev (2): the elastic slip s_e in (t1, t2), reset when the contact opens; not
 * advanced on a setup call. */
#include "builtin.h"

#include <math.h>

enum { P_MU, P_KS, P_KN, P_COUNT };

static const char *const rs_coulomb_props[P_COUNT] = {"mu", "k_stick", "kn"};

static int rs_coulomb_init(const rs_law *law, const double *p, int nprops, rs_error *err)
{
    (void)nprops;
    if (!(p[P_MU] >= 0.0)) {
        return rs_error_set(err, RS_ERR_ARG, "law '%s': property 'mu' must be >= 0, got %g",
                            law->name, p[P_MU]);
    }
    for (int i = P_KS; i <= P_KN; ++i) {
        if (!(p[i] > 0.0)) {
            return rs_error_set(err, RS_ERR_ARG,
                                "law '%s': property '%s' must be > 0, got %g", law->name,
                                rs_coulomb_props[i], p[i]);
        }
    }
    return RS_OK;
}

static int rs_coulomb_update(const rs_law *law, rs_law_block *b, rs_error *err)
{
    (void)law;
    (void)err;
    const double mu = b->props[P_MU], ks = b->props[P_KS], kn = b->props[P_KN];
    const int nd = b->nDir, nsv = b->nStateVar, update = !b->setup;
    for (int c = 0; c < b->nSlvNod; ++c) {
        const double h = RS_A2(b->rdisp, nd, 0, c);
        double *sv = b->statev + (size_t)c * (size_t)nsv;
        if (rs_law_no_force(b, c, sv)) {
            continue;
        }
        const double pn = kn * h;
        double s[2] = {sv[0], nd == 3 ? sv[1] : 0.0};
        if (update) {
            rs_law_advance_slip(b, c, s);
        }
        double tau[2] = {ks * s[0], ks * s[1]};
        const double mag = sqrt(tau[0] * tau[0] + tau[1] * tau[1]);
        const double limit = mu * pn;
        if (mag > limit) {
            const double ratio = limit / mag;
            tau[0] *= ratio;
            tau[1] *= ratio;
            s[0] = tau[0] / ks;
            s[1] = tau[1] / ks;
            if (update) {
                b->sfd[c] = limit * (mag - limit) / ks;
            }
        }
        RS_A2(b->stress, nd, 0, c) = pn;
        RS_A2(b->stress, nd, 1, c) = tau[0];
        if (nd == 3) {
            RS_A2(b->stress, nd, 2, c) = tau[1];
        }
        b->sed[c] = 0.5 * kn * h * h + (tau[0] * tau[0] + tau[1] * tau[1]) / (2.0 * ks);
        if (update) {
            rs_law_keep_shear(b, sv, s);
        }
    }
    return RS_OK;
}

/* p = kn h: a stiffness kn A; the sticking spring k_stick A acts on the contact point,
 * of effective mass 2 m / 7 for a sphere (as in hooke). */
static double rs_coulomb_critical_step(const rs_law *law, const double *p, int np,
                                       double R, double m, double A)
{
    (void)law, (void)R;
    const double K = np >= 3 ? fmax(p[P_KN], 3.5 * p[P_KS]) * A : 0.0;
    return K > 0.0 && m > 0.0 ? 2.0 * sqrt(m / K) : 0.0;
}

const rs_law rs_law_coulomb = {
    .name = "coulomb",
    .nprops = P_COUNT,
    .nstatev = 2,
    .prop_names = rs_coulomb_props,
    .init = rs_coulomb_init,
    .update = rs_coulomb_update,
    .critical_step = rs_coulomb_critical_step,
    .reach = rs_law_reach_touching,
    .skips = RS_LAW_SKIPS_COORDMST,
};
