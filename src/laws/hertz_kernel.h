/* The hertz law's block loop (hertz.c), shared with the fused path of the usual block
 * (hertz_fused.c, the tracker, this law and the loads in one pass), so that both compute
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

/* One contact, every formula evaluated and the results selected at the end (no branch):
 * rdisp(1) d, the normal and tangential relative velocities vn, vt0, vt1, the kept shear
 * so0, so1, drot [[d11, d12], [d21, d22]] and the slip increments ds0, ds1 (drdisp(2:3)),
 * the radius rr, mass ms and area ar. Out: the stress st(nd), sed, on an update svd and
 * sfd, and the shear to keep sk0, sk1 (for nd = 2, sk1 is sv1 kept or forgotten). A
 * contact that is leaving (r_MaxVal) or open (rdisp(1) <= 0) gets zero outputs, and an
 * open one forgets its shear except on a setup call; that is rs_law_no_force,
 * rs_law_advance_slip, rs_law_put_force and rs_law_keep_shear (builtin.h) as one pass
 * around the shared tangential model, rs_law_tangential_history. nd and update are
 * constants in each inlined copy. */
RS_INLINE void hertz_one(double d, double vn, double vt0, double vt1, double so0, double so1,
                         double sv1, double d11, double d12, double d21, double d22,
                         double ds0, double ds1, double rr, double ms, double ar, double dt,
                         double Yeff, double Geff, double beta, double mu, const int nd,
                         const int update, double *st, double *sed, double *svd,
                         double *sfd, double *sk0, double *sk1)
{
    const double c56 = rs_sqrt_five_over_six;
    const int live = !RS_LAW_LEAVING(d) && d > 0.0;
    const int forget = !RS_LAW_LEAVING(d) && !(d > 0.0) && update;
    const double per_area = 1.0 / ar; /* one division for the six per-area values */
    const double sqrtval = sqrt(rr * d);
    const double Sn = 2. * Yeff * sqrtval;
    const double St = 8. * Geff * sqrtval;
    const double kn = 4. / 3. * Yeff * sqrtval;
    const double kt = St;
    const double gamman = -2. * c56 * beta * sqrt(Sn * ms);
    const double gammat = -2. * c56 * beta * sqrt(St * ms);
    const double Fn_damping = -gamman * vn;
    const double Fn_contact = kn * d;
    const double Fn = Fn_damping + Fn_contact;
    double s0 = so0, s1 = so1;
    if (update) {
        if (nd == 3) {
            s0 = d11 * so0 + d12 * so1;
            s1 = d21 * so0 + d22 * so1;
            s0 += ds0;
            s1 += ds1;
        } else {
            s0 += ds0;
            s1 = 0.0;
        }
    }
    const double vt[2] = {vt0, vt1};
    double sn[2] = {s0, s1}, ft[2], slip_work, damp_power;
    rs_law_tangential_history(kt, gammat, mu, Fn, vt, sn, update, ft, &slip_work,
                              &damp_power);
    const double ft0 = ft[0], ft1 = ft[1], sn0 = sn[0], sn1 = sn[1];

    st[0] = live ? Fn * per_area : 0.0;
    st[1] = live ? -ft0 * per_area : 0.0;
    if (nd == 3)
        st[2] = live ? -ft1 * per_area : 0.0;
    *sed = live ? (0.4 * kn * d * d + 0.5 * kt * (sn0 * sn0 + sn1 * sn1)) * per_area : 0.0;
    if (update) {
        *svd = live ? (Fn_damping * -vn + damp_power) * dt * per_area : 0.0;
        *sfd = live ? slip_work * per_area : 0.0;
        /* the kept shear goes through a product with 0 or 1, so that the store is not a
         * conditional one (which the vectoriser cannot make strided) */
        const double keep = (live || forget) ? 0.0 : 1.0;
        *sk0 = (live ? sn0 : 0.0) + keep * so0;
        if (nd == 3)
            *sk1 = (live ? sn1 : 0.0) + keep * so1;
        else
            *sk1 = (forget ? 0.0 : 1.0) * sv1;
    }
}

/* The contacts of a block in one branch-free loop (written to vectorise): hertz_one on
 * each, from and into the law block's arrays. */
RS_INLINE void hertz_block(int n, const int nsv, double dt, const double *restrict rd,
                           const double *restrict drd, const double *restrict dr,
                           const double *restrict vr, const double *restrict rr,
                           const double *restrict ms, const double *restrict ar,
                           double *restrict st, double *restrict sv, double *restrict sed,
                           double *restrict svd, double *restrict sfd, double Yeff,
                           double Geff, double beta, double mu, const int nd,
                           const int update)
{
    RS_IVDEP
    for (int c = 0; c < n; ++c) {
        const double so0 = sv[(size_t)nsv * c],
                     so1 = nd == 3 ? sv[(size_t)nsv * c + 1] : 0.0;
        const double vt0 = vr[nd * c + 1], vt1 = nd == 3 ? vr[nd * c + 2] : 0.0;
        const double d11 = nd == 3 ? dr[4 * c] : 1.0, d21 = nd == 3 ? dr[4 * c + 1] : 0.0;
        const double d12 = nd == 3 ? dr[4 * c + 2] : 0.0,
                     d22 = nd == 3 ? dr[4 * c + 3] : 1.0;
        const double ds0 = drd[nd * c + 1], ds1 = nd == 3 ? drd[nd * c + 2] : 0.0;
        double stc[3], sk0, sk1;
        hertz_one(rd[nd * c], vr[nd * c], vt0, vt1, so0, so1, sv[(size_t)nsv * c + 1], d11,
                  d12, d21, d22, ds0, ds1, rr[c], ms[c], ar[c], dt, Yeff, Geff, beta, mu, nd,
                  update, stc, &sed[c], &svd[c], &sfd[c], &sk0, &sk1);
        st[nd * c] = stc[0];
        st[nd * c + 1] = stc[1];
        if (nd == 3)
            st[nd * c + 2] = stc[2];
        if (update) {
            sv[(size_t)nsv * c] = sk0;
            sv[(size_t)nsv * c + 1] = sk1;
        }
    }
}

#endif
