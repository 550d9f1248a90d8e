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
#include "rigidsurf/vec.h"
#include "rs_compiler.h"

#include <math.h>

enum { P_YP, P_NUP, P_YW, P_NUW, P_E, P_MU, P_CURV, P_COUNT };

static const char *const rs_hertz_props[P_COUNT] = {"Y_particle", "nu_particle", "Y_wall",
                                                    "nu_wall",    "restitution", "friction",
                                                    "curvature"};

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

/* The contacts of a block in one branch-free loop (written to vectorise): every lane
 * evaluates every formula in the order above and selects at the end. A contact that is
 * leaving (r_MaxVal) or open (rdisp(1) <= 0) gets zero outputs, and an open one forgets
 * its shear except on a setup call; that is rs_law_no_force, rs_law_advance_slip,
 * rs_law_put_force and rs_law_keep_shear (builtin.h) as one pass around the shared
 * tangential model, rs_law_tangential_history. nd and update are constants in each
 * inlined copy. */
RS_INLINE void hertz_block(int n, const int nsv, double dt, const double *restrict rd,
                           const double *restrict drd, const double *restrict dr,
                           const double *restrict vr, const double *restrict rr,
                           const double *restrict ms, const double *restrict ar,
                           double *restrict st, double *restrict sv, double *restrict sed,
                           double *restrict svd, double *restrict sfd, double Yeff,
                           double Geff, double beta, double mu, const int nd,
                           const int update)
{
    const double c56 = rs_sqrt_five_over_six;
    RS_IVDEP
    for (int c = 0; c < n; ++c) {
        const double d = rd[nd * c];
        const int live = !RS_LAW_LEAVING(d) && d > 0.0;
        const int forget = !RS_LAW_LEAVING(d) && !(d > 0.0) && update;
        const double per_area = 1.0 / ar[c]; /* one division for the six per-area values */
        const double sqrtval = sqrt(rr[c] * d);
        const double Sn = 2. * Yeff * sqrtval;
        const double St = 8. * Geff * sqrtval;
        const double kn = 4. / 3. * Yeff * sqrtval;
        const double kt = St;
        const double gamman = -2. * c56 * beta * sqrt(Sn * ms[c]);
        const double gammat = -2. * c56 * beta * sqrt(St * ms[c]);
        const double vn = vr[nd * c];
        const double Fn_damping = -gamman * vn;
        const double Fn_contact = kn * d;
        const double Fn = Fn_damping + Fn_contact;
        const double so0 = sv[(size_t)nsv * c],
                     so1 = nd == 3 ? sv[(size_t)nsv * c + 1] : 0.0;
        const double vt0 = vr[nd * c + 1], vt1 = nd == 3 ? vr[nd * c + 2] : 0.0;
        double s0 = so0, s1 = so1;
        if (update) {
            if (nd == 3) {
                s0 = dr[4 * c] * so0 + dr[4 * c + 2] * so1;
                s1 = dr[4 * c + 1] * so0 + dr[4 * c + 3] * so1;
                s0 += drd[3 * c + 1];
                s1 += drd[3 * c + 2];
            } else {
                s0 += drd[2 * c + 1];
                s1 = 0.0;
            }
        }
        const double vt[2] = {vt0, vt1};
        double sn[2] = {s0, s1}, ft[2], slip_work, damp_power;
        rs_law_tangential_history(kt, gammat, mu, Fn, vt, sn, update, ft, &slip_work,
                                  &damp_power);
        const double ft0 = ft[0], ft1 = ft[1], sn0 = sn[0], sn1 = sn[1];

        st[nd * c] = live ? Fn * per_area : 0.0;
        st[nd * c + 1] = live ? -ft0 * per_area : 0.0;
        if (nd == 3)
            st[nd * c + 2] = live ? -ft1 * per_area : 0.0;
        sed[c] =
            live ? (0.4 * kn * d * d + 0.5 * kt * (sn0 * sn0 + sn1 * sn1)) * per_area : 0.0;
        if (update) {
            svd[c] = live ? (Fn_damping * -vn + damp_power) * dt * per_area : 0.0;
            sfd[c] = live ? slip_work * per_area : 0.0;
            /* the kept shear goes through a product with 0 or 1, so that the store is
             * not a conditional one (which the vectoriser cannot make strided) */
            const double keep = (live || forget) ? 0.0 : 1.0;
            sv[(size_t)nsv * c] = (live ? sn0 : 0.0) + keep * so0;
            if (nd == 3)
                sv[(size_t)nsv * c + 1] = (live ? sn1 : 0.0) + keep * so1;
            else
                sv[(size_t)nsv * c + 1] = (forget ? 0.0 : 1.0) * sv[(size_t)nsv * c + 1];
        }
    }
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
    const double Yp = p[P_YP], vp = p[P_NUP], Yw = p[P_YW], vw = p[P_NUW];
    const double Yeff = 1. / ((1. - pow(vp, 2.)) / Yp + (1. - pow(vw, 2.)) / Yw);
    const double Geff =
        1. / (2. * (2. - vp) * (1. + vp) / Yp + 2. * (2. - vw) * (1. + vw) / Yw);
    const double loge = log(p[P_E]);
    const double beta = loge / sqrt(pow(loge, 2.) + pow(RS_PI, 2.));
    const double mu = p[P_MU];
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
    .skips = RS_LAW_SKIPS_STRESS | RS_LAW_SKIPS_ENERGY | RS_LAW_SKIPS_COORDMST,
    .sets = RS_LAW_SETS_ENERGIES | RS_LAW_SETS_NO_HEAT | RS_LAW_SETS_NO_CREEP_PLASTIC |
            RS_LAW_SETS_STRESS,
};
