/* rigidsurf: linear spring-dashpot (Hooke) with Coulomb friction and tangential history.
 *   Fn = kn d - gn vn,  gn = 2 zeta_n sqrt(kn m)   (zeta_n = 1: critical damping of the
 *                                                    particle mass m on the spring kn)
 *   s <- drot s + drdisp(2:3); Ft = -kt s, capped at mu |Fn| with s reset to -Ft/kt,
 *   else Ft -= gt vt with gt = 2 zeta_t sqrt(kt m).
 * d = rdisp(1) > 0 (zero force when open), vn = vrel(1), vt = vrel(2:3). Fn is not
 * clamped at zero, as in LIGGGHTS's hooke model: with zeta_n < 1 the restitution
 * coefficient is then exp(-zeta_n pi / sqrt(1 - zeta_n^2)), independent of speed.
 * Stress is force per areaSlv: stress(1) = Fn/A, stress(2:3) = -Ft/A.
 * props: kn, kt (force per length), zeta_n, zeta_t (damping ratios), mu.
 * statev (2): the shear displacement s in (t1, t2), reset when the contact opens; not
 * advanced on a setup call. Energies per area: sed = (kn d^2 + kt |s|^2)/(2A),
 * svd = (gn vn^2 + gt |vt|^2) dt/A while sticking, sfd = mu |Fn| times the slip beyond
 * the elastic limit, /A. */
#include "builtin.h"

#include <math.h>

enum { P_KN, P_KT, P_ZN, P_ZT, P_MU, P_COUNT };

static const char *const rs_hooke_props[P_COUNT] = {"kn", "kt", "zeta_n", "zeta_t", "mu"};

static int rs_hooke_init(const rs_law *law, const double *p, int nprops, rs_error *err)
{
    (void)nprops;
    for (int i = 0; i < P_COUNT; ++i) {
        const int positive = i == P_KN;
        if (positive ? !(p[i] > 0.0) : !(p[i] >= 0.0)) {
            return rs_error_set(err, RS_ERR_ARG,
                                "law '%s': property '%s' must be %s, got %g", law->name,
                                rs_hooke_props[i], positive ? "> 0" : ">= 0", p[i]);
        }
    }
    return RS_OK;
}

static int rs_hooke_update(const rs_law *law, rs_law_block *b, rs_error *err)
{
    if (!b->mass || !b->vrel) {
        return rs_error_set(err, RS_ERR_ARG, "law '%s' needs the DEM extension: mass, vrel",
                            law->name);
    }
    const double *p = b->props;
    const double kn = p[P_KN], kt = p[P_KT], mu = p[P_MU];
    const double dt = b->dTimCur;
    const int nd = b->nDir, nsv = b->nStateVar, update = !b->setup;
    for (int c = 0; c < b->nSlvNod; ++c) {
        const double d = RS_A2(b->rdisp, nd, 0, c);
        double *sv = b->statev + (size_t)c * (size_t)nsv;
        if (rs_law_no_force(b, c, sv)) {
            continue;
        }
        const double m = b->mass[c];
        const double area = b->areaSlv[c];
        const double gn = 2.0 * p[P_ZN] * sqrt(kn * m);
        const double gt = 2.0 * p[P_ZT] * sqrt(kt * m);
        const double vn = RS_A2(b->vrel, nd, 0, c);
        const double fn = kn * d - gn * vn;

        double s[2] = {sv[0], nd == 3 ? sv[1] : 0.0};
        const double vt[2] = {RS_A2(b->vrel, nd, 1, c),
                              nd == 3 ? RS_A2(b->vrel, nd, 2, c) : 0.0};
        if (update) {
            rs_law_advance_slip(b, c, s);
        }
        double ft[2], slip_work, damp_power;
        if (kt > 0.0) {
            rs_law_tangential_history(kt, gt, mu, fn, vt, s, update, ft, &slip_work,
                                      &damp_power);
        } else {
            ft[0] = ft[1] = slip_work = damp_power = 0.0;
            s[0] = s[1] = 0.0;
        }

        rs_law_put_force(b, c, fn, ft, area);
        b->sed[c] = 0.5 * (kn * d * d + kt * (s[0] * s[0] + s[1] * s[1])) / area;
        if (update) {
            b->svd[c] = (gn * vn * vn + damp_power) * dt / area;
            b->sfd[c] = slip_work / area;
            rs_law_keep_shear(b, sv, s);
        }
    }
    return RS_OK;
}

/* kn and kt are forces per length. The tangential spring acts on a sphere's contact
 * point, whose effective mass with rotation is 2 m / 7: it counts as a stiffness 7 kt / 2
 * on m. */
static double rs_hooke_critical_step(const rs_law *law, const double *p, int np, double R,
                                     double m, double A)
{
    (void)law, (void)R, (void)A;
    const double K = np >= 2 ? fmax(p[0], 3.5 * p[1]) : 0.0;
    return K > 0.0 && m > 0.0 ? 2.0 * sqrt(m / K) : 0.0;
}

const rs_law rs_law_hooke = {
    .name = "hooke",
    .nprops = P_COUNT,
    .nstatev = 2,
    .prop_names = rs_hooke_props,
    .init = rs_hooke_init,
    .update = rs_hooke_update,
    .critical_step = rs_hooke_critical_step,
    .reach = rs_law_reach_touching,
};
