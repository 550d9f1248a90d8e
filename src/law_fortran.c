/* Fortran laws as block laws: the VUINTER shim and the point-wise UINTER and FRIC
 * adapters (Abaqus argument lists; see law_fortran.h for the ABI).
 *
 * DEM extension as predefined fields. When the engine passes no field variables
 * (nPred = 0), every Fortran routine gets nPred = RS_DEM_NPRED fields per slave node,
 * named in vaba_param.inc / aba_param.inc:
 *   1 radius, 2 mass, 3 effective radius, 4-6 relative velocity of the contact point in
 *   (n, t1, t2) (vrel(1) > 0 separates; t2 = 0 in 2D), 7-8 wall curvatures along t1, t2.
 * Missing extension arrays read as 0. Their increments and the master's fields are 0.
 *
 * State variables of the adapters, per contact: the routine's own NSTATV first (so
 * SDV1.. are the routine's), then the normal law's, then the adapter's slots. The
 * loaders set law->nstatev to the normal law's plus the adapter's slots; the caller adds
 * the routine's NSTATV, which the adapter recovers as nStateVar - law->nstatev.
 *
 * A setup call (b->setup) runs the routine but restores every state variable after it,
 * so history does not advance. A contact that left the tracking thickness (rdisp =
 * r_MaxVal) is not handed to UINTER or FRIC: its stress, fluxes and energies are 0. */
#include "law_fortran.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define RS_DEM_NPRED 8
#define RS_FNAME_LEN ((size_t)RS_LAW_NAMELEN)
/// Largest nPred handed through the point-wise adapters.
#define RS_ADAPTER_MAX_NPRED 64
/// PNEWDT on entry (a large value, as Abaqus passes it): < 1 on return asks for a cut.
#define RS_PNEWDT_IN 1.0e36

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

/* The DEM extension of contact k as the RS_DEM_NPRED predefined fields. */
static void dem_fields(const rs_law_block *b, int k, double f[RS_DEM_NPRED])
{
    int nd = b->nDir;
    f[0] = b->radius ? b->radius[k] : 0.0;
    f[1] = b->mass ? b->mass[k] : 0.0;
    f[2] = b->reff ? b->reff[k] : 0.0;
    for (int i = 0; i < 3; ++i)
        f[3 + i] = (b->vrel && i < nd) ? RS_A2(b->vrel, nd, i, k) : 0.0;
    f[6] = b->curv ? b->curv[(size_t)k * 2u] : 0.0;
    f[7] = b->curv ? b->curv[(size_t)k * 2u + 1u] : 0.0;
}

/* The same for the whole block: predef(RS_DEM_NPRED, n), one contact's fields at a
 * time, missing arrays read from zeros so the loop has no branches. */
static void dem_block(const rs_law_block *b, double *restrict predef)
{
    const int n = b->nSlvNod, nd = b->nDir;
    const double *restrict rad = b->radius ? b->radius : rs_fzeros;
    const double *restrict mass = b->mass ? b->mass : rs_fzeros;
    const double *restrict reff = b->reff ? b->reff : rs_fzeros;
    const double *restrict vrel = b->vrel ? b->vrel : rs_fzeros;
    const double *restrict curv = b->curv ? b->curv : rs_fzeros;
    const double t2 = nd == 3 ? 1.0 : 0.0; /* 2D: no t2 component */
    const int i2 = nd == 3 ? 2 : 1;
    for (int k = 0; k < n; ++k) {
        double *restrict p = predef + (size_t)k * RS_DEM_NPRED;
        const double *restrict v = vrel + (size_t)k * (size_t)nd;
        p[0] = rad[k];
        p[1] = mass[k];
        p[2] = reff[k];
        p[3] = v[0];
        p[4] = v[1];
        p[5] = t2 * v[i2];
        p[6] = curv[2 * k];
        p[7] = curv[2 * k + 1];
    }
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
 * dt < 2 sqrt(m / (k A)). Warns when the returned stiffness breaks that. */
static void check_stable(rs_law_block *b, const rs_law *law, int k, double kstiff,
                         const char *what)
{
    if (!b->mass || !(b->mass[k] > 0.0) || !(kstiff > 0.0))
        return;
    double area = b->areaSlv ? b->areaSlv[k] : 1.0;
    if (!(area > 0.0))
        return;
    double dtmax = 2.0 * sqrt(b->mass[k] / (kstiff * area));
    if (b->dTimCur > dtmax)
        warnf(b, law, k,
              "law '%s': %s stiffness %g with area %g and mass %g at particle %d, "
              "feature %d is stable only for dt < 2 sqrt(m/(k A)) = %g; dt = %g",
              law->name, what, kstiff, area, b->mass[k], particle_id(b, k),
              feature_id(b, k), dtmax, b->dTimCur);
}

static void check_pnewdt(rs_law_block *b, const rs_law *law, int k, double pnewdt,
                         const char *routine)
{
    if (pnewdt < 1.0)
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
 * straight through, plus the three hidden CHARACTER*80 lengths. */
int rs_law_vuinter_update(const rs_law *law, rs_law_block *b, rs_error *err)
{
    const rs_loaded_law *ld = (const rs_loaded_law *)law->ctx;
    int n = b->nSlvNod;
    if (n <= 0)
        return RS_OK;
    /* sfd, scd, spd, svd start at zero: rs_law_call clears them */
    int npred = b->nPred;
    const double *pred = b->preDefSlv, *dpred = b->dpreDefSlv;
    const double *predm = b->preDefMst, *dpredm = b->dpreDefMst;
    double dem[RS_DEM_NPRED * RS_BLOCK];
    if (npred == 0 && b->numDefTfv <= RS_BLOCK) {
        npred = RS_DEM_NPRED;
        dem_block(b, dem);
        pred = dem;
        dpred = predm = dpredm = rs_fzeros;
    }
    double sv_dummy[1] = {0.0};
    double *statev = b->statev ? b->statev : sv_dummy;
    const double *props = b->props ? b->props : rs_fzeros;

    double *saved;
    int rc = setup_save(law, b, &saved, err);
    if (rc)
        return rc;
    ld->vuinter(b->sfd, b->scd, b->spd, b->svd, b->stress, b->fluxSlv, b->fluxMst, b->sed,
                statev, &b->kStep, &b->kInc, &b->nFacNod, &b->nSlvNod, &b->nMstNod,
                &b->nSurfDir, &b->nDir, &b->nStateVar, &b->nProps, &b->nTemp, &npred,
                &b->numDefTfv, b->jSlvUid, b->jMstUid, b->jConMstid, &b->timStep,
                &b->timGlb, &b->dTimCur, b->surfInt, b->surfSlv, b->surfMst, b->rdisp,
                b->drdisp, b->drot, b->stiffDflt, b->condDflt, b->shape, b->coordSlv,
                b->coordMst, b->alocaldir, props, b->areaSlv, b->tempSlv, b->dtempSlv, pred,
                dpred, b->tempMst, b->dtempMst, predm, dpredm, RS_FNAME_LEN, RS_FNAME_LEN,
                RS_FNAME_LEN);
    setup_restore(b, saved);
    return RS_OK;
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

/* PREDEF(2, NPRED) of contact k: row 1 the slave, row 2 the master. */
static int point_predef(const rs_law_block *b, int k, double *predef, double *dpred)
{
    if (b->nPred == 0) {
        double f[RS_DEM_NPRED];
        dem_fields(b, k, f);
        for (int i = 0; i < RS_DEM_NPRED; ++i) {
            predef[2 * i] = f[i];
            predef[2 * i + 1] = 0.0;
            dpred[2 * i] = dpred[2 * i + 1] = 0.0;
        }
        return RS_DEM_NPRED;
    }
    int np = b->nPred;
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
 *   STRESS, FLUX, SED: the values at the start of the increment (with a normal law: its
 *   results for this increment); RDISP, DRDISP, DROT, COORDS: the block's; TEMP: slave
 *   and wall temperatures at the start of the increment, DTEMP their increments;
 *   TIME = (step time, total time) at the start; ALOCALDIR(3,3) holds the block's local
 *   directions in its leading nDir x nDir part (zeros elsewhere); MCRD = NDIR;
 *   AREA = areaSlv; CHRLNGTH = the particle radius (sqrt(areaSlv) for a point);
 *   NODE = particle id; KIT = 1; LINPER = 0; LPRINT = 0; FREQR = 0.
 * Flags, as far as an explicit step can honour them:
 *   LOPENCLOSE: in, the value the routine returned for this contact last increment (-1
 *     on its first call); kept per contact, it does not change the solution.
 *   LSTATE: in, the value returned last increment (0 at first); kept per contact.
 *   LSDI: in 0. A returned 1 (a severe-discontinuity iteration) cannot be granted: an
 *     explicit increment is never repeated; the new state acts from the next increment.
 *   PNEWDT: in 1e36; a returned value < 1 is reported through b->warn.
 * DDSDDR is used only to check the explicit step: its largest row sum k against the
 * particle mass m gives the limit dt < 2 sqrt(m / (k A)); a larger dt is reported.
 * DVISCOUS, DSTRUCTURAL, DDFDDT, DDSDDT and DDFDDR are not used (implicit Jacobians and
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
        rc = run_normal(ld->normal, b, nuser, err);
        if (rc) {
            setup_restore(b, saved);
            return rc;
        }
    } else {
        for (int k = 0; k < n; ++k)
            b->sfd[k] = b->scd[k] = b->spd[k] = b->svd[k] = 0.0;
    }
    const double *props = b->props ? b->props : rs_fzeros;
    const double *uprops = props + (ld->normal ? ld->normal->nprops : 0);
    double sv_dummy[1] = {0.0};

    for (int k = 0; k < n; ++k) {
        if (is_leaving(b, k)) {
            for (int i = 0; i < nd; ++i)
                RS_A2(b->stress, nd, i, k) = 0.0;
            b->fluxSlv[k] = b->fluxMst[k] = b->sed[k] = 0.0;
            continue;
        }
        double *sv = nsv > 0 ? b->statev + (size_t)k * (size_t)nsv : sv_dummy;
        double stress[3], rdisp[3], drdisp[3], coords[3];
        for (int i = 0; i < nd; ++i) {
            stress[i] = RS_A2(b->stress, nd, i, k);
            rdisp[i] = RS_A2(b->rdisp, nd, i, k);
            drdisp[i] = RS_A2(b->drdisp, nd, i, k);
            coords[i] = RS_A2(b->coordSlv, nd, i, k);
        }
        double ddsddr[9] = {0}, dvisc[9] = {0}, dstruc[9] = {0};
        double ddfddt[4] = {0}, ddsddt[6] = {0}, ddfddr[6] = {0};
        double flux[2] = {b->fluxSlv[k], b->fluxMst[k]};
        double sed = b->sed[k], sfd = 0.0, spd = 0.0, svd = 0.0, scd = 0.0;
        double pnewdt = RS_PNEWDT_IN;
        double temp[2] = {0.0, 0.0}, dtemp[2] = {0.0, 0.0};
        if (b->nTemp > 0) {
            dtemp[0] = b->dtempSlv[k];
            dtemp[1] = b->dtempMst[0];
            temp[0] = b->tempSlv[k] - dtemp[0];
            temp[1] = b->tempMst[0] - dtemp[1];
        }
        double predef[2 * RS_ADAPTER_MAX_NPRED], dpred[2 * RS_ADAPTER_MAX_NPRED];
        int npred = point_predef(b, k, predef, dpred);
        double time[2] = {b->timStep, b->timGlb};
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
        check_pnewdt(b, law, k, pnewdt, "UINTER");
        check_stable(b, law, k, stiffness_bound(ddsddr, nd), "DDSDDR");
    }
    setup_restore(b, saved);
    return RS_OK;
}

/* -------------------------------------------------------------------- FRIC */

/* FRIC point by point after the normal law has set stress(1) for the block.
 * FRIC is called only for a closed contact: PRESS = stress(1) > 0 or rdisp(1) > 0.
 * An open contact carries no shear, keeps its slip and gets LM = 2.
 * Inputs of contact k:
 *   LM: the value returned last increment; 2 (open) for a contact's first call.
 *   TAU: the shear stress(2:nDir) at the start of the increment (already rotated by
 *     drot). DGAM = drdisp(2:nDir). SLIP: the accumulated slip (sum of DSLIP, rotated
 *     by drot like any vector state). PRESS = stress(1) of this increment,
 *     DPRESS = its change, DDPDDH = the secant d stress(1) / d rdisp(1) over the
 *     increment (stress(1)/rdisp(1) when rdisp(1) did not change; 0 when open).
 *   TAULM: the stick stress TAU + k_s DGAM with k_s = stiffDflt (see LM = 1).
 *   TEMP(2), PREDEF(2,*): slave and wall values at the end of the increment.
 *   NOEL = 0, NPT = 0 (no contact elements); NODE = particle id; NPATCH = feature id;
 *   COORDS = the contact point; RCOORD = the closest wall point (current
 *   configuration); CHRLNGTH as for UINTER; SED = FRIC's elastic energy density of
 *   the last increment.
 * Returned LM:
 *   0: slip or elastic stick: shear = TAU, SLIP += DSLIP, sfd += SFD, SED kept.
 *   1: rigid stick. There are no Lagrange multipliers in an explicit step; the stick is
 *      a penalty spring of stiffness k_s = stiffDflt: shear = TAULM, no slip, no
 *      dissipation, elastic energy |shear|^2 / (2 k_s).
 *   2: frictionless: shear = 0 and SLIP += DGAM.
 *   Anything else is an error naming the contact.
 * The block's sed is the normal law's plus FRIC's; PNEWDT < 1 and a DDTDDG above the
 * stable limit for dt (LM = 0) are reported through b->warn. */
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

    double tau_old[2 * RS_BLOCK], p_old[RS_BLOCK];
    for (int k = 0; k < n; ++k) {
        p_old[k] = RS_A2(b->stress, nd, 0, k);
        for (int a = 0; a < nf; ++a)
            tau_old[2 * k + a] = RS_A2(b->stress, nd, 1 + a, k);
        /* the normal law sees its own elastic energy */
        b->sed[k] -= b->statev[(size_t)k * (size_t)nsv + (size_t)own + 3u];
    }
    double *saved;
    rc = setup_save(law, b, &saved, err);
    if (rc)
        return rc;
    rc = run_normal(ld->normal, b, nuser, err);
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
            sv[own + 2] = 3.0; /* LM = 2, stored + 1 */
            sv[own + 3] = 0.0;
            continue;
        }
        int lm = sv[own + 2] > 0.0 ? (int)sv[own + 2] - 1 : 2;
        double tau[2] = {0.0, 0.0}, dgam[2] = {0.0, 0.0}, taulm[2] = {0.0, 0.0};
        double ks = b->stiffDflt ? b->stiffDflt[k] : 0.0;
        for (int a = 0; a < nf; ++a) {
            tau[a] = tau_old[2 * k + a];
            dgam[a] = RS_A2(b->drdisp, nd, 1 + a, k);
            taulm[a] = tau[a] + ks * dgam[a];
        }
        double ddtddg[4] = {0}, ddtddp[2] = {0}, dslip[2] = {0}, ddtddt[4] = {0};
        double sedf = sv[own + 3], sfd = 0.0, pnewdt = RS_PNEWDT_IN;
        double dpress = press - p_old[k];
        double dh = RS_A2(b->drdisp, nd, 0, k);
        double ddpddh = fabs(dh) > 0.0 ? dpress / dh : (h > 0.0 ? press / h : 0.0);
        double slip_in[2] = {slip[0], slip[1]};
        double time[2] = {b->timStep, b->timGlb}, dtime = b->dTimCur;
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
        double predef[2 * RS_ADAPTER_MAX_NPRED], dpred[2 * RS_ADAPTER_MAX_NPRED];
        int npred = point_predef(b, k, predef, dpred);
        int mcrd = nd;
        double chr = point_chrlngth(b, k);
        double *usv = nuser > 0 ? sv : sv_dummy;

        ld->fric(&lm, tau, ddtddg, ddtddp, dslip, &sedf, &sfd, ddtddt, &pnewdt, usv, dgam,
                 taulm, &press, &dpress, &ddpddh, slip_in, &b->kStep, &b->kInc, time,
                 &dtime, &noel, b->surfInt, b->surfSlv, b->surfMst, &npt, &node, &npatch,
                 coords, rcoord, b->drot + (size_t)k * 4u, temp, predef, &nf, &mcrd, &npred,
                 &nuser, &chr, fprops, &npuser, RS_FNAME_LEN, RS_FNAME_LEN, RS_FNAME_LEN);

        if (lm == 0) {
            for (int a = 0; a < nf; ++a) {
                RS_A2(b->stress, nd, 1 + a, k) = tau[a];
                slip[a] += dslip[a];
            }
            b->sfd[k] += sfd;
            check_stable(b, law, k, stiffness_bound(ddtddg, nf), "DDTDDG");
        } else if (lm == 1) {
            double e = 0.0;
            for (int a = 0; a < nf; ++a) {
                RS_A2(b->stress, nd, 1 + a, k) = taulm[a];
                e += taulm[a] * taulm[a];
            }
            sedf = ks > 0.0 ? 0.5 * e / ks : 0.0;
        } else if (lm == 2) {
            for (int a = 0; a < nf; ++a) {
                RS_A2(b->stress, nd, 1 + a, k) = 0.0;
                slip[a] += dgam[a];
            }
            sedf = 0.0;
        } else {
            setup_restore(b, saved);
            return rs_error_set(err, RS_ERR_ARG,
                                "law '%s': FRIC returned LM = %d at particle %d, feature "
                                "%d; expected 0 (slip), 1 (stick) or 2 (frictionless)",
                                law->name, lm, node, npatch);
        }
        sv[own + 2] = (double)(lm + 1);
        sv[own + 3] = sedf;
        b->sed[k] += sedf;
        check_pnewdt(b, law, k, pnewdt, "FRIC");
    }
    setup_restore(b, saved);
    return RS_OK;
}
