/* A user interface law in C for `law user ./libmylaw.so my_coulomb`: Coulomb friction
 * with a linear penalty in the normal direction, written to give exactly what the
 * built-in law `coulomb` gives (same operations in the same order).
 *   p   = kn h for the overclosure h = rdisp(1) > 0; open contacts carry nothing.
 *   s_e <- drot s_e + drdisp(2:3)               elastic slip, kept in statev(1:2)
 *   tau = k_stick s_e; if |tau| > mu p: tau <- mu p tau/|tau|, s_e = tau / k_stick
 * stress(1) = p (pressure on the wall), stress(2:3) = tau (traction on the wall: a
 * particle slipping along +t1 drags the wall along +t1). sfd = mu p (|tau_trial| - mu p)
 * / k_stick, the work of the slip beyond the elastic limit; sed = kn h^2/2 + |tau|^2 /
 * (2 k_stick). props: mu, k_stick, kn. Build:
 *   gcc -O2 -shared -fPIC -I<rigidsurf>/include mylaw.c -o libmylaw.so */
#include "rigidsurf/law.h"

#include <math.h>

int my_coulomb(const rs_law *law, rs_law_block *b, rs_error *err);

int my_coulomb(const rs_law *law, rs_law_block *b, rs_error *err)
{
    (void)law;
    (void)err;
    const double mu = b->props[0], ks = b->props[1], kn = b->props[2];
    const int nd = b->nDir, nsv = b->nStateVar;
    for (int k = 0; k < b->nSlvNod; ++k) {
        const double h = RS_A2(b->rdisp, nd, 0, k);
        double *sv = b->statev + (size_t)k * (size_t)nsv;
        for (int i = 0; i < nd; ++i)
            RS_A2(b->stress, nd, i, k) = 0.0;
        b->fluxSlv[k] = b->fluxMst[k] = b->sed[k] = 0.0;
        if (h >= 0.5 * RS_MAXVAL) // the call after the contact left: nothing to carry
            continue;
        if (!(h > 0.0)) {
            if (!b->setup)
                sv[0] = sv[1] = 0.0;
            continue;
        }
        const double pn = kn * h;
        double s0 = sv[0], s1 = nd == 3 ? sv[1] : 0.0;
        if (!b->setup) {
            if (nd == 3) {
                const double r0 =
                    RS_DROT(b->drot, 0, 0, k) * s0 + RS_DROT(b->drot, 0, 1, k) * s1;
                const double r1 =
                    RS_DROT(b->drot, 1, 0, k) * s0 + RS_DROT(b->drot, 1, 1, k) * s1;
                s0 = r0 + RS_A2(b->drdisp, 3, 1, k);
                s1 = r1 + RS_A2(b->drdisp, 3, 2, k);
            } else {
                s0 += RS_A2(b->drdisp, 2, 1, k);
            }
        }
        double t0 = ks * s0, t1 = ks * s1;
        const double mag = sqrt(t0 * t0 + t1 * t1);
        const double limit = mu * pn;
        if (mag > limit) {
            const double ratio = limit / mag;
            t0 *= ratio;
            t1 *= ratio;
            s0 = t0 / ks;
            s1 = t1 / ks;
            if (!b->setup)
                b->sfd[k] = limit * (mag - limit) / ks;
        }
        RS_A2(b->stress, nd, 0, k) = pn;
        RS_A2(b->stress, nd, 1, k) = t0;
        if (nd == 3)
            RS_A2(b->stress, nd, 2, k) = t1;
        b->sed[k] = 0.5 * kn * h * h + (t0 * t0 + t1 * t1) / (2.0 * ks);
        if (!b->setup) {
            sv[0] = s0;
            if (nd == 3)
                sv[1] = s1;
        }
    }
    return RS_OK;
}

static int my_coulomb_init(const rs_law *law, const double *p, int nprops, rs_error *err)
{
    (void)nprops;
    if (!(p[0] >= 0.0))
        return rs_error_set(err, RS_ERR_ARG, "law '%s': mu must be >= 0, got %g", law->name,
                            p[0]);
    if (!(p[1] > 0.0) || !(p[2] > 0.0))
        return rs_error_set(err, RS_ERR_ARG, "law '%s': k_stick and kn must be > 0",
                            law->name);
    return RS_OK;
}

static const char *const my_coulomb_props[3] = {"mu", "k_stick", "kn"};

/// The descriptor the loader looks for (<symbol>_law): three properties, two state
/// variables (the elastic slip in t1, t2).
const rs_law my_coulomb_law = {
    .name = "my_coulomb",
    .nprops = 3,
    .nstatev = 2,
    .prop_names = my_coulomb_props,
    .init = my_coulomb_init,
    .update = my_coulomb,
};
