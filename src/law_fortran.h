/* rigidsurf (private): Fortran calling conventions and the data of loaded laws, shared
 * by the dlopen loaders (law_load.c) and the shims and adapters (law_fortran.c).
 *
 * gfortran ABI: every argument is passed by reference; each CHARACTER argument adds a
 * hidden length (size_t since GCC 8) at the END of the argument list, in the order of
 * the character arguments. INTEGER is int, REAL*8 is double. */
#ifndef RIGIDSURF_LAW_FORTRAN_H
#define RIGIDSURF_LAW_FORTRAN_H

#include "rigidsurf/law.h"
#include "rigidsurf/law_build.h"

#include <stddef.h>

/// Abaqus/Explicit VUINTER.
typedef void (*rs_vuinter_fn)(
    double *sfd, double *scd, double *spd, double *svd, double *stress, double *fluxSlv,
    double *fluxMst, double *sed, double *statev, const int *kStep, const int *kInc,
    const int *nFacNod, const int *nSlvNod, const int *nMstNod, const int *nSurfDir,
    const int *nDir, const int *nStateVar, const int *nProps, const int *nTemp,
    const int *nPred, const int *numDefTfv, const int *jSlvUid, const int *jMstUid,
    const int *jConMstid, const double *timStep, const double *timGlb,
    const double *dTimCur, const char *surfInt, const char *surfSlv, const char *surfMst,
    const double *rdisp, const double *drdisp, const double *drot, const double *stiffDflt,
    const double *condDflt, const double *shape, const double *coordSlv,
    const double *coordMst, const double *alocaldir, const double *props,
    const double *areaSlv, const double *tempSlv, const double *dtempSlv,
    const double *preDefSlv, const double *dpreDefSlv, const double *tempMst,
    const double *dtempMst, const double *preDefMst, const double *dpreDefMst,
    size_t lsurfInt, size_t lsurfSlv, size_t lsurfMst);

/// Abaqus/Standard UINTER, current form (DVISCOUS, DSTRUCTURAL after DDSDDR and FREQR
/// after DTIME).
typedef void (*rs_uinter_fn)(
    double *stress, double *ddsddr, double *dviscous, double *dstructural, double *flux,
    double *ddfddt, double *ddsddt, double *ddfddr, double *statev, double *sed,
    double *sfd, double *spd, double *svd, double *scd, double *pnewdt, const double *rdisp,
    const double *drdisp, const double *temp, const double *dtemp, const double *predef,
    const double *dpred, const double *time, const double *dtime, const double *freqr,
    const char *ciname, const char *slname, const char *msname, const double *props,
    const double *coords, const double *alocaldir, const double *drot, const double *area,
    const double *chrlngth, const int *node, const int *ndir, const int *nstatv,
    const int *npred, const int *nprops, const int *mcrd, const int *kstep, const int *kinc,
    const int *kit, const int *linper, int *lopenclose, int *lstate, int *lsdi,
    const int *lprint, size_t lciname, size_t lslname, size_t lmsname);

/// Abaqus/Standard UINTER, the older form without DVISCOUS, DSTRUCTURAL and FREQR.
typedef void (*rs_uinter_v6_fn)(
    double *stress, double *ddsddr, double *flux, double *ddfddt, double *ddsddt,
    double *ddfddr, double *statev, double *sed, double *sfd, double *spd, double *svd,
    double *scd, double *pnewdt, const double *rdisp, const double *drdisp,
    const double *temp, const double *dtemp, const double *predef, const double *dpred,
    const double *time, const double *dtime, const char *ciname, const char *slname,
    const char *msname, const double *props, const double *coords, const double *alocaldir,
    const double *drot, const double *area, const double *chrlngth, const int *node,
    const int *ndir, const int *nstatv, const int *npred, const int *nprops,
    const int *mcrd, const int *kstep, const int *kinc, const int *kit, const int *linper,
    int *lopenclose, int *lstate, int *lsdi, const int *lprint, size_t lciname,
    size_t lslname, size_t lmsname);

/// Abaqus/Standard FRIC.
typedef void (*rs_fric_fn)(
    int *lm, double *tau, double *ddtddg, double *ddtddp, double *dslip, double *sed,
    double *sfd, double *ddtddt, double *pnewdt, double *statev, const double *dgam,
    const double *taulm, const double *press, const double *dpress, const double *ddpddh,
    const double *slip, const int *kstep, const int *kinc, const double *time,
    const double *dtime, const int *noel, const char *ciname, const char *slname,
    const char *msname, const int *npt, const int *node, const int *npatch,
    const double *coords, const double *rcoord, const double *drot, const double *temp,
    const double *predef, const int *nfdir, const int *mcrd, const int *npred,
    const int *nstatv, const double *chrlngth, const double *props, const int *nprops,
    size_t lciname, size_t lslname, size_t lmsname);

typedef enum rs_loaded_kind {
    RS_LOADED_C = 1,
    RS_LOADED_VUINTER = 2,
    RS_LOADED_UINTER = 3,
    RS_LOADED_UINTER_V6 = 4,
    RS_LOADED_FRIC = 5
} rs_loaded_kind;

/// Largest state-variable count of a normal law wrapped by the UINTER/FRIC adapters.
#define RS_ADAPTER_MAX_NORMAL_NSV 32

/// Adapter slots kept after the normal law's state variables (see law_fortran.c).
#define RS_UINTER_OWN_NSV 4 ///< LOPENCLOSE, LSTATE, FLUX(1:2) of the last increment
#define RS_FRIC_OWN_NSV 4   ///< SLIP(1:2), LM on entry of the next call, FRIC's SED

/// ctx of a loaded law.
typedef struct rs_loaded_law {
    rs_loaded_kind kind;
    void *handle;         ///< dlopen handle
    char name[160];       ///< law->name points here
    rs_law_update_fn cfn; ///< RS_LOADED_C: the user's function
    rs_vuinter_fn vuinter;
    rs_uinter_fn uinter;
    rs_uinter_v6_fn uinter_v6;
    rs_fric_fn fric;
    const rs_law *normal; ///< UINTER/FRIC: law run first for the normal response
    int own_nsv;          ///< adapter slots (normal law's + own)
    int from_source;      ///< 1 when built from a Fortran source (then warnings is set)
    rs_build_warnings warnings; ///< the compiler's warnings of that build
} rs_loaded_law;

/* Block functions of the loaded kinds (law->update), in law_fortran.c. */
int rs_law_vuinter_update(const rs_law *law, rs_law_block *b, rs_error *err);
int rs_law_uinter_update(const rs_law *law, rs_law_block *b, rs_error *err);
int rs_law_fric_update(const rs_law *law, rs_law_block *b, rs_error *err);
/// Property check of the adapters: the wrapped normal law's leading properties.
int rs_law_adapter_init(const rs_law *law, const double *props, int nprops, rs_error *err);

#endif
