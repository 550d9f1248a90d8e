/* rigidsurf: the built-in law descriptors (src/laws/) and helpers they share. */
#ifndef RIGIDSURF_LAWS_BUILTIN_H
#define RIGIDSURF_LAWS_BUILTIN_H

#include "rigidsurf/law.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

extern const rs_law rs_law_bonded_interface;
extern const rs_law rs_law_linear_softening;
extern const rs_law rs_law_hertz;
extern const rs_law rs_law_hooke;
extern const rs_law rs_law_coulomb;
/// hertz's fused kernel (hertz_fused.c, track_fused.h).
extern const struct rs_law_fused rs_hertz_fused;

/// rs_law_call's error for a law that returned a NaN or Inf (what = "stress(1)", ...,
/// value) for contact k of n, on particle pid and feature f (law.c); an engine that calls
/// a built-in law's kernel itself (hertz_fused.c) reports it the same way.
int rs_law_nonfinite_error(const rs_law *law, int pid, int f, int k, int n, const char *what,
                           double value, rs_error *err);

/// Bit 63 set exactly when x is NaN or Inf (exponent bits all set: adding one to the
/// exponent field carries into the sign bit), so that a block's outputs are checked by one
/// branch-free OR over them and the first offender looked for only when it is set.
static inline uint64_t rs_nonfinite_bit(double x)
{
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    return (u & 0x7ff0000000000000ULL) + 0x0010000000000000ULL;
}

/// A contact that left the tracking thickness carries r_MaxVal in rdisp (Abaqus).
#define RS_LAW_LEAVING(rdisp1) ((rdisp1) >= 0.5 * RS_MAXVAL)

/// Zeroes the outputs of contact k: stress, fluxes and every energy density.
static inline void rs_law_zero_contact(rs_law_block *b, int k)
{
    for (int i = 0; i < b->nDir; ++i) {
        RS_A2(b->stress, b->nDir, i, k) = 0.0;
    }
    b->fluxSlv[k] = 0.0;
    b->fluxMst[k] = 0.0;
    b->sed[k] = 0.0;
    b->sfd[k] = 0.0;
    b->scd[k] = 0.0;
    b->spd[k] = 0.0;
    b->svd[k] = 0.0;
}

/// Starts contact k of a penalty law that keeps a shear vector in sv(1:2): zeroes the
/// contact's outputs and returns 1 when it carries no force, that is when it is leaving
/// (r_MaxVal) or open (rdisp(1) <= 0). An open contact also forgets its shear, except on
/// a setup call.
static inline int rs_law_no_force(rs_law_block *b, int k, double *sv)
{
    const double d = RS_A2(b->rdisp, b->nDir, 0, k);
    rs_law_zero_contact(b, k);
    if (RS_LAW_LEAVING(d)) {
        return 1;
    }
    if (!(d > 0.0)) {
        if (!b->setup) {
            sv[0] = 0.0;
            sv[1] = 0.0;
        }
        return 1;
    }
    return 0;
}

/// Carries the tangent vector s(1:nDir-1) of contact k into this increment's basis,
/// s <- drot s (docs/conventions.md, "rdisp, drdisp, drot"), then adds the slip increment
/// drdisp(2:nDir). With nDir = 2, s[1] stays 0.
static inline void rs_law_advance_slip(const rs_law_block *b, int k, double s[2])
{
    if (b->nDir == 3) {
        const double s1 = s[0], s2 = s[1];
        s[0] = RS_DROT(b->drot, 0, 0, k) * s1 + RS_DROT(b->drot, 0, 1, k) * s2;
        s[1] = RS_DROT(b->drot, 1, 0, k) * s1 + RS_DROT(b->drot, 1, 1, k) * s2;
        s[0] += RS_A2(b->drdisp, 3, 1, k);
        s[1] += RS_A2(b->drdisp, 3, 2, k);
    } else {
        s[0] += RS_A2(b->drdisp, 2, 1, k);
        s[1] = 0.0;
    }
}

/// Writes contact k's stress from the normal force fn and tangential force ft on the
/// particle: stress(1) = fn / area, stress(2:nDir) = -ft / area (the traction on the
/// master, docs/conventions.md, "Stress, flux, energy signs").
static inline void rs_law_put_force(rs_law_block *b, int k, double fn, const double ft[2],
                                    double area)
{
    const int nd = b->nDir;
    RS_A2(b->stress, nd, 0, k) = fn / area;
    RS_A2(b->stress, nd, 1, k) = -ft[0] / area;
    if (nd == 3) {
        RS_A2(b->stress, nd, 2, k) = -ft[1] / area;
    }
}

/// Stores the tangent vector s(1:nDir-1) in the state variables sv of one contact.
static inline void rs_law_keep_shear(const rs_law_block *b, double *sv, const double s[2])
{
    sv[0] = s[0];
    if (b->nDir == 3) {
        sv[1] = s[1];
    }
}

/// The LIGGGHTS history tangential model (tangential_model_history.h) in the local
/// (t1, t2) frame: ft = -kt s; if kt |s| > mu |fn| then ft is scaled to mu |fn| and, when
/// update, s is reset to -ft / kt; otherwise ft -= gt vt. ft is the force on the
/// particle. *slip_work = mu |fn| times the slip beyond the elastic limit (0 without
/// update); *damp_power = gt |vt|^2 while sticking. Operation order follows LIGGGHTS so
/// a plane contact matches it bit for bit. Every formula is evaluated and the branch is
/// a select at the end, so that a block loop that inlines it vectorises (hertz.c); a
/// capped force divides by kt.
static inline void rs_law_tangential_history(double kt, double gt, double mu, double fn,
                                             const double vt[2], double s[2], int update,
                                             double ft[2], double *slip_work,
                                             double *damp_power)
{
    const double s0 = s[0], s1 = s[1];
    const double shrmag = sqrt(s0 * s0 + s1 * s1);
    const double f0 = -(kt * s0), f1 = -(kt * s1);
    const double ft_shear = kt * shrmag;
    const double ft_friction = mu * fabs(fn);
    const int cap = ft_shear > ft_friction;
    const double ratio = ft_friction / (cap ? ft_shear : 1.0);
    const double fc0 = f0 * ratio, fc1 = f1 * ratio;
    const double fd0 = f0 - gt * vt[0], fd1 = f1 - gt * vt[1];
    ft[0] = cap ? fc0 : fd0;
    ft[1] = cap ? fc1 : fd1;
    s[0] = cap && update ? -fc0 / kt : s0;
    s[1] = cap && update ? -fc1 / kt : s1;
    /* the slip beyond the elastic limit ft_friction / kt = ratio shrmag */
    *slip_work = cap && update ? ft_friction * (shrmag - ratio * shrmag) : 0.0;
    const double damp = gt * (vt[0] * vt[0] + vt[1] * vt[1]);
    *damp_power = cap ? 0.0 : damp;
}

#endif
