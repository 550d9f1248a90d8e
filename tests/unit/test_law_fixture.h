/* Test fixture for law tests: one block with its own storage, filled with VUINTER
 * defaults (drot = I, areaSlv = 1, particle ids 100 + k, feature ids face k). */
#ifndef RS_TEST_LAW_FIXTURE_H
#define RS_TEST_LAW_FIXTURE_H

#include "rigidsurf/law.h"

#include <math.h>
#include <string.h>

#define LF_MAXSV 8

/// |a - b| <= rtol |b|: a true relative check, also for values far below 1.
#define ENSURE_RREL(a, b, rtol) ENSURE_NEAR(a, b, (rtol)*fabs((double)(b)))

typedef struct law_fix {
    rs_law_block b;
    int uid[RS_BLOCK], fid[RS_BLOCK];
    double rdisp[3 * RS_BLOCK], drdisp[3 * RS_BLOCK], drot[4 * RS_BLOCK];
    double stiff[RS_BLOCK], cond[RS_BLOCK], area[RS_BLOCK];
    double coordSlv[3 * RS_BLOCK], coordMst[3 * RS_BLOCK], aloc[9 * RS_BLOCK];
    double props[16];
    double tempSlv[RS_BLOCK], tempMst[RS_BLOCK];
    double stress[3 * RS_BLOCK], fluxSlv[RS_BLOCK], fluxMst[RS_BLOCK], sed[RS_BLOCK];
    double statev[LF_MAXSV * RS_BLOCK];
    double sfd[RS_BLOCK], scd[RS_BLOCK], spd[RS_BLOCK], svd[RS_BLOCK];
    double radius[RS_BLOCK], mass[RS_BLOCK], reff[RS_BLOCK], vrel[3 * RS_BLOCK];
    double curv[2 * RS_BLOCK];
} law_fix;

/// Fresh block of n contacts with nDir = ndir for law (props copied), dt = 1e-5.
static inline void law_fix_init(law_fix *f, const rs_law *law, const double *props,
                                int nprops, int n, int ndir)
{
    memset(f, 0, sizeof *f);
    rs_law_block *b = &f->b;
    rs_law_block_init(b);
    b->nSlvNod = n;
    b->nDir = ndir;
    b->nSurfDir = ndir - 1;
    b->nStateVar = law && law->nstatev > 0 ? law->nstatev : 0;
    b->nProps = nprops;
    b->dTimCur = 1e-5;
    for (int i = 0; i < nprops; ++i) {
        f->props[i] = props[i];
    }
    for (int k = 0; k < RS_BLOCK; ++k) {
        f->uid[k] = 100 + k;
        f->fid[k] = RS_FEATURE(RS_FEAT_FACE, k);
        RS_DROT(f->drot, 0, 0, k) = 1.0;
        RS_DROT(f->drot, 1, 1, k) = 1.0;
        f->area[k] = 1.0;
        f->radius[k] = 0.01;
        f->reff[k] = 0.01;
        f->mass[k] = 1e-3;
        for (int j = 0; j < ndir; ++j) {
            RS_A3(f->aloc, ndir, j, j, k) = 1.0;
        }
    }
    b->jSlvUid = f->uid;
    b->jConMstid = f->fid;
    b->rdisp = f->rdisp;
    b->drdisp = f->drdisp;
    b->drot = f->drot;
    b->stiffDflt = f->stiff;
    b->condDflt = f->cond;
    b->areaSlv = f->area;
    b->coordSlv = f->coordSlv;
    b->coordMst = f->coordMst;
    b->alocaldir = f->aloc;
    b->props = f->props;
    b->tempSlv = f->tempSlv;
    b->tempMst = f->tempMst;
    b->stress = f->stress;
    b->fluxSlv = f->fluxSlv;
    b->fluxMst = f->fluxMst;
    b->sed = f->sed;
    b->statev = f->statev;
    b->sfd = f->sfd;
    b->scd = f->scd;
    b->spd = f->spd;
    b->svd = f->svd;
    b->radius = f->radius;
    b->mass = f->mass;
    b->reff = f->reff;
    b->vrel = f->vrel;
    b->curv = f->curv;
}

#endif
