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
 * Or the LIGGGHTS material form, as `fix wall/gran model hooke tangential history`
 * computes it for a sphere of radius R and mass m on a wall (its normal_model_hooke.h,
 * tangential damping on): Y_particle, nu_particle, Y_wall, nu_wall, restitution e,
 * friction mu, characteristic velocity V; per contact
 *   Y* = 1 / ((1 - nu_p^2) / Y_p + (1 - nu_w^2) / Y_w),
 *   kn = 16/15 sqrt(R) Y* (15 m V^2 / (16 sqrt(R) Y*))^(1/5),  kt = kn,
 *   gn = gt = sqrt(4 m kn ln(e)^2 / (ln(e)^2 + pi^2)).
 * statev (2): the shear displacement s in (t1, t2), reset when the contact opens; not
 * advanced on a setup call. Energies per area: sed = (kn d^2 + kt |s|^2)/(2A),
 * svd = (gn vn^2 + gt |vt|^2) dt/A while sticking, sfd = mu |Fn| times the slip beyond
 * the elastic limit, /A. */
#include "builtin.h"
#include "rigidsurf/vec.h"

#include <math.h>

enum { P_KN, P_KT, P_ZN, P_ZT, P_MU, P_COUNT };
enum { M_YP, M_NUP, M_YW, M_NUW, M_E, M_MU, M_V, M_COUNT };

static const char *const rs_hooke_props[P_COUNT] = {"kn", "kt", "zeta_n", "zeta_t", "mu"};
static const char *const rs_hooke_mprops[M_COUNT] = {"Y_particle",
                                                     "nu_particle",
                                                     "Y_wall",
                                                     "nu_wall",
                                                     "restitution",
                                                     "friction",
                                                     "characteristic_velocity"};

static int rs_hooke_material_init(const rs_law *law, const double *p, rs_error *err)
{
    for (int i = 0; i < M_COUNT; ++i) {
        const int ok = i == M_NUP || i == M_NUW ? p[i] > -1.0 && p[i] < 0.5
                       : i == M_E               ? p[i] > 0.0 && p[i] <= 1.0
                       : i == M_MU              ? p[i] >= 0.0
                                                : p[i] > 0.0;
        if (!ok) {
            return rs_error_set(err, RS_ERR_ARG,
                                "law '%s': property '%s' must be %s, got %g", law->name,
                                rs_hooke_mprops[i],
                                i == M_NUP || i == M_NUW ? "in (-1, 0.5)"
                                : i == M_E               ? "in (0, 1]"
                                : i == M_MU              ? ">= 0"
                                                         : "> 0",
                                p[i]);
        }
    }
    return RS_OK;
}

static int rs_hooke_init(const rs_law *law, const double *p, int nprops, rs_error *err)
{
    if (nprops == M_COUNT)
        return rs_hooke_material_init(law, p, err);
    if (nprops != P_COUNT)
        return rs_error_set(err, RS_ERR_ARG,
                            "law '%s' expects 5 properties (kn, kt, zeta_n, zeta_t, mu) or "
                            "7 material properties (Y_particle, nu_particle, Y_wall, "
                            "nu_wall, restitution, friction, characteristic_velocity), "
                            "got %d",
                            law->name, nprops);
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

/* The material form's stiffnesses and dampings for a sphere of radius R and mass m. */
static void rs_hooke_material(const double *p, double R, double m, double *kn, double *kt,
                              double *gn, double *gt)
{
    const double ystar = 1.0 / ((1.0 - p[M_NUP] * p[M_NUP]) / p[M_YP] +
                                (1.0 - p[M_NUW] * p[M_NUW]) / p[M_YW]);
    const double sq = sqrt(R), V = p[M_V];
    *kn = 16.0 / 15.0 * sq * ystar * pow(15.0 * m * V * V / (16.0 * sq * ystar), 0.2);
    *kt = *kn;
    const double le = log(p[M_E]), le2 = le * le;
    *gn = sqrt(4.0 * m * *kn * le2 / (le2 + RS_PI * RS_PI));
    *gt = *gn;
}

static int rs_hooke_update(const rs_law *law, rs_law_block *b, rs_error *err)
{
    const int material = b->nProps == M_COUNT;
    if (!b->mass || !b->vrel || (material && !b->radius)) {
        return rs_error_set(err, RS_ERR_ARG,
                            "law '%s' needs the DEM extension: mass, vrel%s", law->name,
                            material ? ", radius" : "");
    }
    const double *p = b->props;
    double kn = p[P_KN], kt = p[P_KT];
    const double mu = material ? p[M_MU] : p[P_MU];
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
        double gn, gt;
        if (material) {
            rs_hooke_material(p, b->radius[c], m, &kn, &kt, &gn, &gt);
        } else {
            gn = 2.0 * p[P_ZN] * sqrt(kn * m);
            gt = 2.0 * p[P_ZT] * sqrt(kt * m);
        }
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
    (void)law, (void)A;
    double kn = np >= 2 ? p[P_KN] : 0.0, kt = np >= 2 ? p[P_KT] : 0.0, gn, gt;
    if (np == M_COUNT && R > 0.0 && m > 0.0)
        rs_hooke_material(p, R, m, &kn, &kt, &gn, &gt);
    const double K = fmax(kn, 3.5 * kt);
    return K > 0.0 && m > 0.0 ? 2.0 * sqrt(m / K) : 0.0;
}

const rs_law rs_law_hooke = {
    .name = "hooke",
    .nprops = -1, /* 5, or the 7 of the material form (rs_hooke_init) */
    .nstatev = 2,
    .prop_names = rs_hooke_props,
    .init = rs_hooke_init,
    .update = rs_hooke_update,
    .critical_step = rs_hooke_critical_step,
    .reach = rs_law_reach_touching,
    .skips = RS_LAW_SKIPS_STRESS | RS_LAW_SKIPS_ENERGY | RS_LAW_SKIPS_COORDMST |
             RS_LAW_SKIPS_SLIP | RS_LAW_SKIPS_DRDISP1,
    .sets = RS_LAW_SETS_STRESS,
};
