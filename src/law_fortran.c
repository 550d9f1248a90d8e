/* Fortran laws as block laws: the VUINTER shim and the point-wise UINTER and FRIC
 * adapters (Abaqus argument lists; see law_fortran.h for the ABI, docs/abaqus.md for
 * every argument and where it differs from Abaqus).
 *
 * Every call of a user routine is bracketed by rs_abq_call_begin / rs_abq_call_end
 * (abaqus_util.h): the utility routines (GETPARTINFO, RS_GETDEM, XPLB_ABQERR, ...) then
 * know the block and contact asked about, and an error a routine raised (severity -2)
 * ends the law call with RS_ERR_ARG after the state of a setup call is restored.
 *
 * Predefined fields: nPred is the engine's count (the `predef` fields), 0 without. The
 * DEM extension (radius, mass, effective radius, relative velocity, curvatures) reaches
 * a routine through the utility routine RS_GETDEM.
 *
 * Steps and times: KSTEP and KINC (kStep, kInc) are the engine's, KINC from 1 in each
 * step; the block's timStep and timGlb are at the start of the increment, and UINTER
 * and FRIC get TIME(1:2) at its end (plus dTimCur), as Abaqus/Standard passes them.
 *
 * State variables of the adapters, per contact: the routine's own NSTATV first (so
 * SDV1.. are the routine's), then the normal law's, then the adapter's slots. The
 * loaders set law->nstatev to the normal law's plus the adapter's slots; the caller adds
 * the routine's NSTATV, which the adapter recovers as nStateVar - law->nstatev.
 *
 * A setup call (b->setup) runs the routine but restores every state variable after it,
 * so history does not advance. A contact that left the tracking thickness (rdisp =
 * r_MaxVal) is not handed to UINTER or FRIC: its stress, fluxes and energies are 0.
 *
 * PNEWDT < 1 and the stiffness a routine returns go to b->requests when the engine
 * gathers them (one report per run), otherwise to b->warn contact by contact. */
#include "law_fortran.h"
#include "rigidsurf/abaqus_util.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define RS_FNAME_LEN ((size_t)RS_LAW_NAMELEN)
/// Largest nPred handed through the point-wise adapters.
#define RS_ADAPTER_MAX_NPRED 64
/// PNEWDT on entry (a large value, as Abaqus passes it): < 1 on return asks for a cut.
#define RS_PNEWDT_IN 1.0e36
/// Moment of inertia of the solid sphere the FRIC stick constraint assumes: I = 2/5 m R^2
/// (LIGGGHTS's sphere).
#define RS_SPHERE_INERTIA 0.4
/// Relative step of the finite difference that gives FRIC's DDPDDH.
#define RS_DDPDDH_STEP 1e-7

static const double rs_fzeros[RS_ADAPTER_MAX_NPRED * RS_BLOCK];

static void warnf(rs_law_block *b, const rs_law *law, int k, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

static void warnf(rs_law_block *b, const rs_law *law, int k, const char *fmt, ...)
{
    if (!b->warn)
        return;
    char msg[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    b->warn(b->warn_ctx, law, k, msg);
}

static int particle_id(const rs_law_block *b, int k)
{
    return b->jSlvUid ? b->jSlvUid[k] : k;
}

static int feature_id(const rs_law_block *b, int k)
{
    return b->jConMstid ? b->jConMstid[(size_t)k * (size_t)b->nFacNod] : -1;
}

static int is_leaving(const rs_law_block *b, int k)
{
    return RS_A2(b->rdisp, b->nDir, 0, k) >= 0.5 * RS_MAXVAL;
}

/* Largest eigenvalue bound (Gershgorin: largest absolute row sum) of an m x m
 * column-major matrix. */
static double stiffness_bound(const double *a, int m)
{
    double kmax = 0.0;
    for (int i = 0; i < m; ++i) {
        double row = 0.0;
        for (int j = 0; j < m; ++j)
            row += fabs(a[j * m + i]);
        kmax = fmax(kmax, row);
    }
    return kmax;
}

/* Central differences are stable for a point mass m on a spring k A when
 * dt < 2 sqrt(m / (k A)). The critical step of the stiffness a routine returned goes to
 * b->requests (the engine compares it with its step), or a warning when dt exceeds it. */
static void check_stable(rs_law_block *b, const rs_law *law, int k, double kstiff,
                         const char *what)
{
    if (b->setup || !b->mass || !(b->mass[k] > 0.0) || !(kstiff > 0.0))
        return;
    double area = b->areaSlv ? b->areaSlv[k] : 1.0;
    if (!(area > 0.0))
        return;
    double dtmax = 2.0 * sqrt(b->mass[k] / (kstiff * area));
    if (b->requests) {
        if (dtmax < b->requests->step_min) {
            b->requests->step_min = dtmax;
            b->requests->step_what = what;
        }
    } else if (b->dTimCur > dtmax) {
        warnf(b, law, k,
              "law '%s': %s stiffness %g with area %g and mass %g at particle %d, "
              "feature %d is stable only for dt < 2 sqrt(m/(k A)) = %g; dt = %g",
              law->name, what, kstiff, area, b->mass[k], particle_id(b, k),
              feature_id(b, k), dtmax, b->dTimCur);
    }
}

/* PNEWDT < 1: an explicit increment cannot be repeated with a smaller step. Gathered in
 * b->requests (the engine reports once per run), or a warning naming the contact. */
static void check_pnewdt(rs_law_block *b, const rs_law *law, int k, double pnewdt,
                         const char *routine)
{
    if (b->setup || !(pnewdt < 1.0))
        return;
    rs_law_requests *r = b->requests;
    if (r) {
        if (r->pnewdt_calls == 0 || pnewdt < r->pnewdt_min) {
            r->pnewdt_min = pnewdt;
            r->pnewdt_particle = particle_id(b, k);
            r->pnewdt_feature = feature_id(b, k);
        }
        r->pnewdt_calls++;
        return;
    }
    warnf(b, law, k,
          "law '%s': %s asked for a smaller increment (PNEWDT = %g) at particle %d, "
          "feature %d; an explicit step cannot repeat the increment",
          law->name, routine, pnewdt, particle_id(b, k), feature_id(b, k));
}

/* Saves every state variable of the block before a setup call. */
static int setup_save(const rs_law *law, const rs_law_block *b, double **saved,
                      rs_error *err)
{
    *saved = NULL;
    if (!b->setup || b->nStateVar <= 0 || b->nSlvNod <= 0 || !b->statev)
        return RS_OK;
    size_t count = (size_t)b->nStateVar * (size_t)b->nSlvNod;
    *saved = (double *)malloc(count * sizeof(double));
    if (!*saved)
        return rs_error_set(err, RS_ERR_NOMEM, "law '%s': out of memory", law->name);
    memcpy(*saved, b->statev, count * sizeof(double));
    return RS_OK;
}

static void setup_restore(const rs_law_block *b, double *saved)
{
    if (!saved)
        return;
    memcpy(b->statev, saved, (size_t)b->nStateVar * (size_t)b->nSlvNod * sizeof(double));
    free(saved);
}

/* ---------------------------------------------------------------- VUINTER */

/* The block is already the VUINTER argument list in Fortran layout: the pointers go
 * straight through, plus the three hidden CHARACTER*80 lengths. An analytic master has
 * no nodes: nFacNod = nMstNod = 0 (the block keeps the feature id in jConMstid for the
 * engine's own messages). A faceted master's facets come from the block's fac_ fields:
 * nFacNod, nMstNod, jConMstid, shape, jMstUid and coordMst of the facet nodes. nPred is
 * the engine's; numDefTfv = 1 (one wall temperature). */
int rs_law_vuinter_update(const rs_law *law, rs_law_block *b, rs_error *err)
{
    const rs_loaded_law *ld = (const rs_loaded_law *)law->ctx;
    int n = b->nSlvNod;
    if (n <= 0)
        return RS_OK;
    /* sfd, scd, spd, svd start at zero: rs_law_call clears them */
    const int facets = !b->analytic_master && b->fac_nFacNod > 0;
    const int nfac = b->analytic_master ? 0 : facets ? b->fac_nFacNod : b->nFacNod;
    const int nmst = b->analytic_master ? 0 : facets ? b->fac_nMstNod : b->nMstNod;
    const int *jmst = facets ? b->fac_jMstUid : b->jMstUid;
    const int *jcon = facets ? b->fac_jConMstid : b->jConMstid;
    const double *shape = facets ? b->fac_shape : b->shape;
    const double *cmst = facets ? b->fac_coordMst : b->coordMst;
    const double *pred = b->nPred > 0 ? b->preDefSlv : rs_fzeros;
    const double *dpred = b->nPred > 0 ? b->dpreDefSlv : rs_fzeros;
    const double *predm = b->nPred > 0 ? b->preDefMst : rs_fzeros;
    const double *dpredm = b->nPred > 0 ? b->dpreDefMst : rs_fzeros;
    double sv_dummy[1] = {0.0};
    double *statev = b->statev ? b->statev : sv_dummy;
    const double *props = b->props ? b->props : rs_fzeros;

    double *saved;
    int rc = setup_save(law, b, &saved, err);
    if (rc)
        return rc;
    rs_abq_call_begin(b, -1, "VUINTER");
    ld->vuinter(b->sfd, b->scd, b->spd, b->svd, b->stress, b->fluxSlv, b->fluxMst, b->sed,
                statev, &b->kStep, &b->kInc, &nfac, &b->nSlvNod, &nmst, &b->nSurfDir,
                &b->nDir, &b->nStateVar, &b->nProps, &b->nTemp, &b->nPred, &b->numDefTfv,
                b->jSlvUid, jmst, jcon, &b->timStep, &b->timGlb, &b->dTimCur, b->surfInt,
                b->surfSlv, b->surfMst, b->rdisp, b->drdisp, b->drot, b->stiffDflt,
                b->condDflt, shape, b->coordSlv, cmst, b->alocaldir, props, b->areaSlv,
                b->tempSlv, b->dtempSlv, pred, dpred, b->tempMst, b->dtempMst, predm,
                dpredm, RS_FNAME_LEN, RS_FNAME_LEN, RS_FNAME_LEN);
    rc = rs_abq_call_end(err);
    setup_restore(b, saved);
    return rc;
}

/* ---------------------------------------------------- shared adapter parts */

/* Runs the normal law over the whole block. Its state variables sit at offset off in
 * each contact's column; they are gathered into a block of their own stride. */
static int run_normal(const rs_law *normal, rs_law_block *b, int off, rs_error *err)
{
    int n = b->nSlvNod, nN = normal->nstatev, nsv = b->nStateVar;
    double buf[RS_ADAPTER_MAX_NORMAL_NSV * RS_BLOCK + 1];
    for (int k = 0; k < n; ++k)
        for (int i = 0; i < nN; ++i)
            buf[k * nN + i] = b->statev[(size_t)k * (size_t)nsv + (size_t)(off + i)];
    rs_law_block nb = *b;
    nb.nStateVar = nN;
    nb.statev = buf;
    nb.nProps = normal->nprops;
    int rc = rs_law_call(normal, &nb, err);
    if (rc)
        return rc;
    for (int k = 0; k < n; ++k)
        for (int i = 0; i < nN; ++i)
            b->statev[(size_t)k * (size_t)nsv + (size_t)(off + i)] = buf[k * nN + i];
    return RS_OK;
}

/* Splits nStateVar and nProps between the routine, the normal law and the adapter. */
static int adapter_layout(const rs_law *law, const rs_law_block *b, int *nuser, int *npuser,
                          rs_error *err)
{
    const rs_loaded_law *ld = (const rs_loaded_law *)law->ctx;
    int npn = ld->normal ? ld->normal->nprops : 0;
    *nuser = b->nStateVar - ld->own_nsv;
    *npuser = b->nProps - npn;
    if (*nuser < 0)
        return rs_error_set(err, RS_ERR_ARG,
                            "law '%s': nStateVar = %d; expected at least %d (the adapter's "
                            "slots) plus the routine's NSTATV",
                            law->name, b->nStateVar, ld->own_nsv);
    if (*npuser < 0)
        return rs_error_set(err, RS_ERR_ARG,
                            "law '%s': nProps = %d; the normal law '%s' alone needs %d",
                            law->name, b->nProps, ld->normal->name, npn);
    if (b->nSlvNod > 0 && !b->statev && b->nStateVar > 0)
        return rs_error_set(err, RS_ERR_ARG, "law '%s': statev is NULL", law->name);
    if (b->nPred > RS_ADAPTER_MAX_NPRED)
        return rs_error_set(err, RS_ERR_ARG, "law '%s': nPred = %d; at most %d supported",
                            law->name, b->nPred, RS_ADAPTER_MAX_NPRED);
    return RS_OK;
}

int rs_law_adapter_init(const rs_law *law, const double *props, int nprops, rs_error *err)
{
    const rs_loaded_law *ld = (const rs_loaded_law *)law->ctx;
    if (!ld || !ld->normal)
        return RS_OK;
    if (nprops < ld->normal->nprops)
        return rs_error_set(err, RS_ERR_ARG,
                            "law '%s': %d properties given; the normal law '%s' needs the "
                            "first %d",
                            law->name, nprops, ld->normal->name, ld->normal->nprops);
    return rs_law_check_props(ld->normal, props, ld->normal->nprops, err);
}

/* PREDEF(2, NPRED) of contact k: row 1 the slave, row 2 the master; nPred is the
 * engine's (0 without fields: the arrays hold one zero column). */
static int point_predef(const rs_law_block *b, int k, double *predef, double *dpred)
{
    int np = b->nPred;
    predef[0] = predef[1] = dpred[0] = dpred[1] = 0.0;
    for (int i = 0; i < np; ++i) {
        predef[2 * i] = RS_A2(b->preDefSlv, np, i, k);
        predef[2 * i + 1] = b->preDefMst[i];
        dpred[2 * i] = RS_A2(b->dpreDefSlv, np, i, k);
        dpred[2 * i + 1] = b->dpreDefMst[i];
    }
    return np;
}

static double point_chrlngth(const rs_law_block *b, int k)
{
    if (b->radius && b->radius[k] > 0.0)
        return b->radius[k];
    double a = b->areaSlv ? b->areaSlv[k] : 1.0;
    return a > 0.0 ? sqrt(a) : 0.0;
}

/* ------------------------------------------------------------------ UINTER */

/* UINTER point by point. Inputs of contact k:
 *   STRESS: the values of the last increment (shear rotated by drot); with a normal law,
 *   STRESS(1) is the normal law's result for this increment and STRESS(2:NDIR) stay the
 *   last increment's (the routine's shear persists). FLUX(1:2): the values the routine
 *   returned last increment (0 on a contact's first call), kept in the adapter's slots.
 *   SED: the normal law's, else the last increment's. RDISP, DRDISP, DROT, COORDS: the
 *   block's; TEMP: slave and wall temperatures at the start of the increment, DTEMP
 *   their increments; TIME = (step time, total time) at the end of the increment;
 *   KSTEP, KINC: the block's; ALOCALDIR(3,3) holds the block's local directions in its
 *   leading nDir x nDir part (zeros elsewhere); MCRD = NDIR; AREA = areaSlv; CHRLNGTH =
 *   the particle radius (sqrt(areaSlv) for a point); NODE = particle id; KIT = 1;
 *   LINPER = 0; LPRINT = 0; FREQR = 0; PREDEF(2, NPRED): the engine's fields.
 * Flags, as far as an explicit step can honour them:
 *   LOPENCLOSE: in, the value the routine returned for this contact last increment (-1
 *     on its first call); kept per contact, it does not change the solution.
 *   LSTATE: in, the value returned last increment (0 at first); kept per contact.
 *   LSDI: in 0. A returned 1 (a severe-discontinuity iteration) cannot be granted: an
 *     explicit increment is never repeated; the new state acts from the next increment.
 *   PNEWDT: in 1e36; a returned value < 1 is reported (check_pnewdt).
 * DDSDDR is used only for the explicit step: its largest row sum k against the particle
 * mass m gives the critical step 2 sqrt(m / (k A)) (check_stable). DVISCOUS,
 * DSTRUCTURAL, DDFDDT, DDSDDT and DDFDDR are not used (implicit Jacobians and
 * frequency-domain damping). */
int rs_law_uinter_update(const rs_law *law, rs_law_block *b, rs_error *err)
{
    const rs_loaded_law *ld = (const rs_loaded_law *)law->ctx;
    int n = b->nSlvNod;
    if (n <= 0)
        return RS_OK;
    int nuser, npuser;
    int rc = adapter_layout(law, b, &nuser, &npuser, err);
    if (rc)
        return rc;
    int nd = b->nDir, nsv = b->nStateVar;
    int nN = ld->normal ? ld->normal->nstatev : 0;
    int own = nuser + nN;

    double *saved;
    rc = setup_save(law, b, &saved, err);
    if (rc)
        return rc;
    if (ld->normal) {
        /* the normal law gives STRESS(1); the shear stays the routine's */
        double shear[2 * RS_BLOCK];
        for (int k = 0; k < n; ++k)
            for (int a = 1; a < nd; ++a)
                shear[2 * k + a - 1] = RS_A2(b->stress, nd, a, k);
        rc = run_normal(ld->normal, b, nuser, err);
        if (rc) {
            setup_restore(b, saved);
            return rc;
        }
        for (int k = 0; k < n; ++k)
            for (int a = 1; a < nd; ++a)
                RS_A2(b->stress, nd, a, k) = shear[2 * k + a - 1];
    } else {
        for (int k = 0; k < n; ++k)
            b->sfd[k] = b->scd[k] = b->spd[k] = b->svd[k] = 0.0;
    }
    const double *props = b->props ? b->props : rs_fzeros;
    const double *uprops = props + (ld->normal ? ld->normal->nprops : 0);
    double sv_dummy[1] = {0.0};

    for (int k = 0; k < n; ++k) {
        double *sv = nsv > 0 ? b->statev + (size_t)k * (size_t)nsv : sv_dummy;
        if (is_leaving(b, k)) {
            for (int i = 0; i < nd; ++i)
                RS_A2(b->stress, nd, i, k) = 0.0;
            b->fluxSlv[k] = b->fluxMst[k] = b->sed[k] = 0.0;
            sv[own + 2] = sv[own + 3] = 0.0;
            continue;
        }
        double stress[3], rdisp[3], drdisp[3], coords[3];
        for (int i = 0; i < nd; ++i) {
            stress[i] = RS_A2(b->stress, nd, i, k);
            rdisp[i] = RS_A2(b->rdisp, nd, i, k);
            drdisp[i] = RS_A2(b->drdisp, nd, i, k);
            coords[i] = RS_A2(b->coordSlv, nd, i, k);
        }
        double ddsddr[9] = {0}, dvisc[9] = {0}, dstruc[9] = {0};
        double ddfddt[4] = {0}, ddsddt[6] = {0}, ddfddr[6] = {0};
        double flux[2] = {sv[own + 2], sv[own + 3]};
        double sed = b->sed[k], sfd = 0.0, spd = 0.0, svd = 0.0, scd = 0.0;
        double pnewdt = RS_PNEWDT_IN;
        double temp[2] = {0.0, 0.0}, dtemp[2] = {0.0, 0.0};
        if (b->nTemp > 0) {
            dtemp[0] = b->dtempSlv[k];
            dtemp[1] = b->dtempMst[0];
            temp[0] = b->tempSlv[k] - dtemp[0];
            temp[1] = b->tempMst[0] - dtemp[1];
        }
        double predef[2 * RS_ADAPTER_MAX_NPRED + 2], dpred[2 * RS_ADAPTER_MAX_NPRED + 2];
        int npred = point_predef(b, k, predef, dpred);
        double time[2] = {b->timStep + b->dTimCur, b->timGlb + b->dTimCur};
        double dtime = b->dTimCur, freqr = 0.0;
        double aloc[9] = {0};
        for (int j = 0; j < nd; ++j)
            for (int i = 0; i < nd; ++i)
                aloc[j * 3 + i] = RS_A3(b->alocaldir, nd, i, j, k);
        double drot[4];
        for (int i = 0; i < 4; ++i)
            drot[i] = b->drot[(size_t)k * 4u + (size_t)i];
        double area = b->areaSlv[k], chr = point_chrlngth(b, k);
        int node = particle_id(b, k), mcrd = nd, kit = 1, linper = 0, lprint = 0;
        int lopen = (int)sv[own] - 2, lstate = (int)sv[own + 1], lsdi = 0;
        if (lopen < -1)
            lopen = -1;

        rs_abq_call_begin(b, k, "UINTER");
        if (ld->kind == RS_LOADED_UINTER)
            ld->uinter(stress, ddsddr, dvisc, dstruc, flux, ddfddt, ddsddt, ddfddr, sv,
                       &sed, &sfd, &spd, &svd, &scd, &pnewdt, rdisp, drdisp, temp, dtemp,
                       predef, dpred, time, &dtime, &freqr, b->surfInt, b->surfSlv,
                       b->surfMst, uprops, coords, aloc, drot, &area, &chr, &node, &nd,
                       &nuser, &npred, &npuser, &mcrd, &b->kStep, &b->kInc, &kit, &linper,
                       &lopen, &lstate, &lsdi, &lprint, RS_FNAME_LEN, RS_FNAME_LEN,
                       RS_FNAME_LEN);
        else
            ld->uinter_v6(stress, ddsddr, flux, ddfddt, ddsddt, ddfddr, sv, &sed, &sfd,
                          &spd, &svd, &scd, &pnewdt, rdisp, drdisp, temp, dtemp, predef,
                          dpred, time, &dtime, b->surfInt, b->surfSlv, b->surfMst, uprops,
                          coords, aloc, drot, &area, &chr, &node, &nd, &nuser, &npred,
                          &npuser, &mcrd, &b->kStep, &b->kInc, &kit, &linper, &lopen,
                          &lstate, &lsdi, &lprint, RS_FNAME_LEN, RS_FNAME_LEN,
                          RS_FNAME_LEN);
        rc = rs_abq_call_end(err);
        if (rc) {
            setup_restore(b, saved);
            return rc;
        }

        for (int i = 0; i < nd; ++i)
            RS_A2(b->stress, nd, i, k) = stress[i];
        b->fluxSlv[k] = flux[0];
        b->fluxMst[k] = flux[1];
        b->sed[k] = sed;
        b->sfd[k] += sfd;
        b->spd[k] += spd;
        b->svd[k] += svd;
        b->scd[k] += scd;
        sv[own] = (double)(lopen + 2);
        sv[own + 1] = (double)lstate;
        sv[own + 2] = flux[0];
        sv[own + 3] = flux[1];
        check_pnewdt(b, law, k, pnewdt, "UINTER");
        check_stable(b, law, k, stiffness_bound(ddsddr, nd), "DDSDDR");
    }
    setup_restore(b, saved);
    return RS_OK;
}

/* -------------------------------------------------------------------- FRIC */

/* DDPDDH of the block: the normal law's current stiffness d stress(1) / d rdisp(1), a
 * forward difference. The normal law runs once more on a copy of the block with rdisp(1)
 * and drdisp(1) moved by delta = RS_DDPDDH_STEP max(|h|, 1e-3 R) from the state it had
 * before this increment (stress0, statev0); that call's results are dropped. Viscous
 * terms (vrel) are the same in both calls, so this is the elastic tangent. */
static int normal_stiffness(const rs_law *normal, const rs_law_block *b, int off,
                            const double *stress0, const double *statev0, double *ddpddh,
                            rs_error *err)
{
    const int n = b->nSlvNod, nd = b->nDir;
    const size_t nsv = (size_t)b->nStateVar;
    double rd[3 * RS_BLOCK], drd[3 * RS_BLOCK], st[3 * RS_BLOCK], delta[RS_BLOCK];
    double fs[RS_BLOCK] = {0}, fm[RS_BLOCK] = {0}, se[RS_BLOCK] = {0}, e1[RS_BLOCK],
           e2[RS_BLOCK], e3[RS_BLOCK], e4[RS_BLOCK];
    memcpy(rd, b->rdisp, (size_t)(nd * n) * sizeof(double));
    memcpy(drd, b->drdisp, (size_t)(nd * n) * sizeof(double));
    memcpy(st, stress0, (size_t)(nd * n) * sizeof(double));
    for (int k = 0; k < n; ++k) {
        const double h = RS_A2(b->rdisp, nd, 0, k);
        const double R = b->radius ? b->radius[k] : 0.0;
        delta[k] = 0.0;
        if (is_leaving(b, k))
            continue;
        double d = RS_DDPDDH_STEP * fmax(fabs(h), 1e-3 * R);
        if (!(d > 0.0))
            d = RS_DDPDDH_STEP * 1e-9;
        delta[k] = d;
        RS_A2(rd, nd, 0, k) = h + d;
        RS_A2(drd, nd, 0, k) += d;
        fs[k] = b->fluxSlv[k];
        fm[k] = b->fluxMst[k];
        se[k] = b->sed[k];
    }
    double *sv = NULL;
    if (nsv > 0) {
        sv = (double *)malloc(nsv * (size_t)n * sizeof(double));
        if (!sv)
            return rs_error_set(err, RS_ERR_NOMEM, "law '%s': out of memory", normal->name);
        memcpy(sv, statev0, nsv * (size_t)n * sizeof(double));
    }
    rs_law_block nb = *b;
    nb.rdisp = rd;
    nb.drdisp = drd;
    nb.stress = st;
    nb.statev = sv;
    nb.fluxSlv = fs;
    nb.fluxMst = fm;
    nb.sed = se;
    nb.sfd = e1;
    nb.scd = e2;
    nb.spd = e3;
    nb.svd = e4;
    nb.requests = NULL;
    nb.warn = NULL;
    int rc = run_normal(normal, &nb, off, err);
    free(sv);
    if (rc)
        return rc;
    for (int k = 0; k < n; ++k)
        ddpddh[k] = delta[k] > 0.0
                        ? (RS_A2(st, nd, 0, k) - RS_A2(b->stress, nd, 0, k)) / delta[k]
                        : 0.0;
    return RS_OK;
}

/* FRIC point by point after the normal law has set stress(1) for the block.
 * FRIC is called only for a closed contact: PRESS = stress(1) > 0 or rdisp(1) > 0.
 * An open contact carries no shear, keeps its slip and enters its next call with LM = 2.
 * Inputs of contact k:
 *   LM: the contact's state in the previous increment: 2 when it was open (and on its
 *     first call), 1 when the routine returned 1, 0 otherwise (a closed contact whose
 *     routine returned 0 or 2 was sliding).
 *   TAU: the shear stress(2:nDir) at the start of the increment (already rotated by
 *     drot). DGAM = drdisp(2:nDir) when LM = 0 on entry, else 0 (no slip was possible).
 *     SLIP: the accumulated slip (sum of DSLIP, rotated by drot like any vector state).
 *     PRESS = stress(1) of this increment, DPRESS = its change over the increment,
 *     DDPDDH = the normal law's current stiffness d stress(1) / d rdisp(1)
 *     (normal_stiffness).
 *   TAULM: the stick stress of this increment (see LM = 1).
 *   TIME = (step time, total time) at the end of the increment; KSTEP, KINC: the block's.
 *   TEMP(2), PREDEF(2,*): slave and wall values at the end of the increment (the
 *     engine's fields; NPRED = nPred).
 *   NOEL = 0, NPT = 0 (no contact elements); NODE = particle id; NPATCH = feature id;
 *   COORDS = the contact point; RCOORD = the closest wall point (current
 *   configuration); CHRLNGTH as for UINTER; SED = FRIC's elastic energy density of
 *   the last increment.
 * Returned LM:
 *   0: slip or elastic stick: shear = TAU, SLIP += DSLIP.
 *   1: no relative tangential motion at the contact point, an explicit kinematic
 *      constraint: the tangential force on the particle cancels its contact point's
 *      tangential velocity vt = vrel(2:nDir) in one increment, F_t = -m_eff vt / dt, so
 *      shear = TAULM = m_eff vt / (areaSlv dt). m_eff is the particle's effective mass
 *      at the contact, translation and rotation: 1/m_eff = 1/m + Rc^2 / I, Rc = R -
 *      rdisp(1)/2 the lever arm of the contact point and I = 2/5 m R^2, a solid sphere
 *      (1/m_eff = 3.5/m at zero overlap; m_eff = m for a point, R = 0). Needs the DEM
 *      extension (mass, radius, vrel). No slip, no elastic energy.
 *   2: frictionless: shear = 0 and SLIP += drdisp(2:nDir).
 *   Anything else is an error naming the contact.
 * Dissipation and heat: sfd += SFD when the routine sets it (nonzero), else DSLIP.TAU.
 * With temperatures (nTemp = 1) that energy per area over dt is heat, half into the
 * particle (fluxSlv) and half into the wall (fluxMst), on top of the normal law's (which
 * starts each increment from zero fluxes).
 * The block's sed is the normal law's plus FRIC's; PNEWDT < 1 and the DDTDDG of LM = 0
 * go to check_pnewdt and check_stable. */
int rs_law_fric_update(const rs_law *law, rs_law_block *b, rs_error *err)
{
    const rs_loaded_law *ld = (const rs_loaded_law *)law->ctx;
    int n = b->nSlvNod;
    if (n <= 0)
        return RS_OK;
    int nuser, npuser;
    int rc = adapter_layout(law, b, &nuser, &npuser, err);
    if (rc)
        return rc;
    int nd = b->nDir, nsv = b->nStateVar, nf = nd - 1;
    int nN = ld->normal->nstatev;
    int own = nuser + nN;

    double stress0[3 * RS_BLOCK];
    for (int k = 0; k < n; ++k) {
        for (int i = 0; i < nd; ++i)
            stress0[k * nd + i] = RS_A2(b->stress, nd, i, k);
        /* the normal law sees its own elastic energy, and computes its fluxes afresh
         * (the last increment's hold FRIC's frictional heat) */
        b->sed[k] -= b->statev[(size_t)k * (size_t)nsv + (size_t)own + 3u];
        b->fluxSlv[k] = b->fluxMst[k] = 0.0;
    }
    double *saved;
    rc = setup_save(law, b, &saved, err);
    if (rc)
        return rc;
    double *statev0 = saved;
    if (!statev0 && nsv > 0) { /* not a setup call: the state before the normal law */
        statev0 = (double *)malloc((size_t)nsv * (size_t)n * sizeof(double));
        if (!statev0)
            return rs_error_set(err, RS_ERR_NOMEM, "law '%s': out of memory", law->name);
        memcpy(statev0, b->statev, (size_t)nsv * (size_t)n * sizeof(double));
    }
    double ddpddh[RS_BLOCK];
    rc = run_normal(ld->normal, b, nuser, err);
    if (!rc)
        rc = normal_stiffness(ld->normal, b, nuser, stress0, statev0, ddpddh, err);
    if (statev0 != saved)
        free(statev0);
    if (rc) {
        setup_restore(b, saved);
        return rc;
    }
    const double *props = b->props ? b->props : rs_fzeros;
    const double *fprops = props + ld->normal->nprops;
    double sv_dummy[1] = {0.0};

    for (int k = 0; k < n; ++k) {
        double *sv = b->statev + (size_t)k * (size_t)nsv;
        double *slip = sv + own;
        if (is_leaving(b, k)) {
            for (int i = 0; i < nd; ++i)
                RS_A2(b->stress, nd, i, k) = 0.0;
            b->fluxSlv[k] = b->fluxMst[k] = b->sed[k] = 0.0;
            continue;
        }
        if (nd == 3) {
            double s0 = slip[0], s1 = slip[1];
            slip[0] = RS_DROT(b->drot, 0, 0, k) * s0 + RS_DROT(b->drot, 0, 1, k) * s1;
            slip[1] = RS_DROT(b->drot, 1, 0, k) * s0 + RS_DROT(b->drot, 1, 1, k) * s1;
        }
        double press = RS_A2(b->stress, nd, 0, k);
        double h = RS_A2(b->rdisp, nd, 0, k);
        if (!(press > 0.0 || h > 0.0)) {
            for (int a = 0; a < nf; ++a)
                RS_A2(b->stress, nd, 1 + a, k) = 0.0;
            sv[own + 2] = 3.0; /* LM = 2 on entry next time, stored + 1 */
            sv[own + 3] = 0.0;
            continue;
        }
        /* stored LM + 1; 0: the contact's first call */
        int lm_in = sv[own + 2] > 0.0 ? (int)sv[own + 2] - 1 : 2;
        int lm = lm_in;
        double tau[2] = {0.0, 0.0}, dgam[2] = {0.0, 0.0}, taulm[2] = {0.0, 0.0};
        double area = b->areaSlv[k], dt = b->dTimCur;
        int have_dem =
            b->mass && b->radius && b->vrel && b->mass[k] > 0.0 && area > 0.0 && dt > 0.0;
        if (have_dem) {
            const double m = b->mass[k], R = b->radius[k];
            const double rc_arm = R > 0.0 ? fmax(R - 0.5 * h, 0.0) : 0.0;
            const double inv =
                1.0 / m +
                (R > 0.0 ? rc_arm * rc_arm / (RS_SPHERE_INERTIA * m * R * R) : 0.0);
            for (int a = 0; a < nf; ++a)
                taulm[a] = RS_A2(b->vrel, nd, 1 + a, k) / (inv * area * dt);
        }
        for (int a = 0; a < nf; ++a) {
            tau[a] = stress0[k * nd + 1 + a];
            dgam[a] = lm_in == 0 ? RS_A2(b->drdisp, nd, 1 + a, k) : 0.0;
        }
        double ddtddg[4] = {0}, ddtddp[2] = {0}, dslip[2] = {0}, ddtddt[4] = {0};
        double sedf = sv[own + 3], sfd = 0.0, pnewdt = RS_PNEWDT_IN;
        double dpress = press - stress0[k * nd];
        double slip_in[2] = {slip[0], slip[1]};
        double time[2] = {b->timStep + b->dTimCur, b->timGlb + b->dTimCur};
        double dtime = b->dTimCur;
        int noel = 0, npt = 0, node = particle_id(b, k), npatch = feature_id(b, k);
        double coords[3], rcoord[3];
        for (int i = 0; i < nd; ++i) {
            coords[i] = RS_A2(b->coordSlv, nd, i, k);
            rcoord[i] = RS_A2(b->coordMst, nd, i, k);
        }
        double temp[2] = {0.0, 0.0};
        if (b->nTemp > 0) {
            temp[0] = b->tempSlv[k];
            temp[1] = b->tempMst[0];
        }
        double predef[2 * RS_ADAPTER_MAX_NPRED + 2], dpred[2 * RS_ADAPTER_MAX_NPRED + 2];
        int npred = point_predef(b, k, predef, dpred);
        int mcrd = nd;
        double chr = point_chrlngth(b, k);
        double *usv = nuser > 0 ? sv : sv_dummy;

        rs_abq_call_begin(b, k, "FRIC");
        ld->fric(&lm, tau, ddtddg, ddtddp, dslip, &sedf, &sfd, ddtddt, &pnewdt, usv, dgam,
                 taulm, &press, &dpress, &ddpddh[k], slip_in, &b->kStep, &b->kInc, time,
                 &dtime, &noel, b->surfInt, b->surfSlv, b->surfMst, &npt, &node, &npatch,
                 coords, rcoord, b->drot + (size_t)k * 4u, temp, predef, &nf, &mcrd, &npred,
                 &nuser, &chr, fprops, &npuser, RS_FNAME_LEN, RS_FNAME_LEN, RS_FNAME_LEN);
        rc = rs_abq_call_end(err);
        if (rc) {
            setup_restore(b, saved);
            return rc;
        }

        double diss = sfd;
        if (lm == 0) {
            double work = 0.0;
            for (int a = 0; a < nf; ++a) {
                RS_A2(b->stress, nd, 1 + a, k) = tau[a];
                slip[a] += dslip[a];
                work += dslip[a] * tau[a];
            }
            if (sfd == 0.0)
                diss = work;
            check_stable(b, law, k, stiffness_bound(ddtddg, nf), "DDTDDG");
        } else if (lm == 1) {
            if (!have_dem) {
                setup_restore(b, saved);
                return rs_error_set(
                    err, RS_ERR_ARG,
                    "law '%s': FRIC returned LM = 1 (stick) at particle %d, "
                    "feature %d; the stick constraint needs the particle's "
                    "mass, radius and relative velocity (the DEM extension), "
                    "a positive area and dt",
                    law->name, node, npatch);
            }
            for (int a = 0; a < nf; ++a)
                RS_A2(b->stress, nd, 1 + a, k) = taulm[a];
            sedf = 0.0;
        } else if (lm == 2) {
            for (int a = 0; a < nf; ++a) {
                RS_A2(b->stress, nd, 1 + a, k) = 0.0;
                slip[a] += RS_A2(b->drdisp, nd, 1 + a, k);
            }
            sedf = 0.0;
        } else {
            setup_restore(b, saved);
            return rs_error_set(err, RS_ERR_ARG,
                                "law '%s': FRIC returned LM = %d at particle %d, feature "
                                "%d; expected 0 (slip), 1 (stick) or 2 (frictionless)",
                                law->name, lm, node, npatch);
        }
        b->sfd[k] += diss;
        if (b->nTemp > 0 && dt > 0.0) {
            b->fluxSlv[k] += 0.5 * diss / dt;
            b->fluxMst[k] += 0.5 * diss / dt;
        }
        sv[own + 2] = lm == 1 ? 2.0 : 1.0; /* LM on entry next time (1 or 0), + 1 */
        sv[own + 3] = sedf;
        b->sed[k] += sedf;
        check_pnewdt(b, law, k, pnewdt, "FRIC");
    }
    setup_restore(b, saved);
    return RS_OK;
}
