/* The hertz law's block loop (hertz.c), shared with the fused path of the usual block
 * (track_hertz.c, the tracker, this law and the loads in one pass), so that both compute
 * every contact with the same operations: its property order, its constants and
 * hertz_block. Internal to the library. */
#ifndef RIGIDSURF_HERTZ_KERNEL_H
#define RIGIDSURF_HERTZ_KERNEL_H

#include "builtin.h"
#include "rigidsurf/vec.h"
#include "rs_compiler.h"

#include <math.h>

enum { P_YP, P_NUP, P_YW, P_NUW, P_E, P_MU, P_CURV, P_COUNT };

static const double rs_sqrt_five_over_six = 0.91287092917527685576161630466800355658790782;

/* Y*, G*, beta and mu of the properties p (hertz.c's formulas). */
static inline void rs_hertz_constants(const double *p, double *Yeff, double *Geff,
                                      double *beta, double *mu)
{
    const double Yp = p[P_YP], vp = p[P_NUP], Yw = p[P_YW], vw = p[P_NUW];
    *Yeff = 1. / ((1. - pow(vp, 2.)) / Yp + (1. - pow(vw, 2.)) / Yw);
    *Geff = 1. / (2. * (2. - vp) * (1. + vp) / Yp + 2. * (2. - vw) * (1. + vw) / Yw);
    const double loge = log(p[P_E]);
    *beta = loge / sqrt(pow(loge, 2.) + pow(RS_PI, 2.));
    *mu = p[P_MU];
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

#endif
