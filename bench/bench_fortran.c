/* Fortran VUINTER shim overhead: the bonded interface as the built-in C law and as the
 * Fortran VUINTER tests/fortran/vuinter_bonded.f loaded with rs_law_load_vuinter, on the
 * same block of RS_BLOCK contacts (nDir = 3), both through rs_law_call. Repetitions
 * interleave the two; medians are reported with their ratio (Fortran / C).
 *
 *   bench_fortran [--calls N] [--reps R]
 *
 * Each repetition restores the same contact state; calls alternate +drdisp / -drdisp so
 * the work stays the same (all contacts bonded and elastic, with heat conduction). The
 * shim's own work is the hidden-length call and filling the DEM predefined fields. */
#define _POSIX_C_SOURCE 200809L
#include "law_fortran.h"
#include "rigidsurf/law.h"

#include <dlfcn.h>

#include "bench_clock.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define N RS_BLOCK

typedef struct blk {
    rs_law_block b;
    int uid[N], fid[N];
    double rdisp[3 * N], dplus[3 * N], dminus[3 * N], drot[4 * N], stiff[N], cond[N];
    double cs[3 * N], cm[3 * N], aloc[9 * N], props[7], tslv[N], tmst[1];
    double stress[3 * N], fs[N], fm[N], sed[N], statev[3 * N];
    double sfd[N], scd[N], spd[N], svd[N];
    double radius[N], mass[N], reff[N], vrel[3 * N], curv[2 * N];
    double stress0[3 * N], statev0[3 * N];
} blk;

static void blk_init(blk *k)
{
    memset(k, 0, sizeof *k);
    rs_law_block *b = &k->b;
    rs_law_block_init(b);
    b->nSlvNod = N;
    b->nDir = 3;
    b->nSurfDir = 2;
    b->nStateVar = 3;
    b->nProps = 7;
    b->dTimCur = 1e-6;
    const double p[7] = {1e-4, 2e8, 0.3, 1e6, 2e7, 1e-3, 0.5};
    memcpy(k->props, p, sizeof p);
    unsigned long long s = 0x2545F4914F6CDD1Dull;
    for (int j = 0; j < N; ++j) {
        k->uid[j] = j;
        k->fid[j] = RS_FEATURE(RS_FEAT_FACE, j % 7);
        k->drot[4 * j] = k->drot[4 * j + 3] = 1.0;
        for (int i = 0; i < 3; ++i) {
            s ^= s << 13, s ^= s >> 7, s ^= s << 17;
            double u = (double)(s >> 11) * (1.0 / 9007199254740992.0);
            k->dplus[3 * j + i] = 1e-9 * (u - 0.5);
            k->dminus[3 * j + i] = -k->dplus[3 * j + i];
            k->aloc[9 * j + 4 * i] = 1.0;
        }
        k->rdisp[3 * j] = 1e-7;
        k->tslv[j] = 20.0 + (j % 5);
        k->radius[j] = k->reff[j] = 1e-3;
        k->mass[j] = 1e-5;
        k->statev0[3 * j] = 1.0;     /* initialised */
        k->statev0[3 * j + 1] = 1.0; /* bonded */
        k->statev0[3 * j + 2] = 1e6; /* yield stress */
        k->stress0[3 * j] = 1e5;
    }
    k->tmst[0] = 80.0;
    b->jSlvUid = k->uid;
    b->jConMstid = k->fid;
    b->rdisp = k->rdisp;
    b->drot = k->drot;
    b->stiffDflt = k->stiff;
    b->condDflt = k->cond;
    b->coordSlv = k->cs;
    b->coordMst = k->cm;
    b->alocaldir = k->aloc;
    b->props = k->props;
    b->tempSlv = k->tslv;
    b->tempMst = k->tmst;
    b->stress = k->stress;
    b->fluxSlv = k->fs;
    b->fluxMst = k->fm;
    b->sed = k->sed;
    b->statev = k->statev;
    b->sfd = k->sfd;
    b->scd = k->scd;
    b->spd = k->spd;
    b->svd = k->svd;
    b->radius = k->radius;
    b->mass = k->mass;
    b->reff = k->reff;
    b->vrel = k->vrel;
    b->curv = k->curv;
}

/* ns per contact of `calls` block calls from the saved state. */
static double time_law(const rs_law *law, blk *k, int calls)
{
    memcpy(k->stress, k->stress0, sizeof k->stress);
    memcpy(k->statev, k->statev0, sizeof k->statev);
    rs_error err;
    double t0 = rs_bench_now();
    for (int c = 0; c < calls; ++c) {
        k->b.drdisp = (c & 1) ? k->dminus : k->dplus;
        if (rs_law_call(law, &k->b, &err) != RS_OK) {
            fprintf(stderr, "bench_fortran: %s\n", err.msg);
            exit(1);
        }
    }
    return (rs_bench_now() - t0) * 1e9 / ((double)calls * N);
}

/* The same calls straight into vuinter_ (no rs_law_call, no shim, no DEM fields). */
static rs_vuinter_fn raw;
static int raw_update(const rs_law *law, rs_law_block *b, rs_error *err)
{
    (void)law;
    (void)err;
    static const double z[8 * N];
    int npred = 8;
    raw(b->sfd, b->scd, b->spd, b->svd, b->stress, b->fluxSlv, b->fluxMst, b->sed,
        b->statev, &b->kStep, &b->kInc, &b->nFacNod, &b->nSlvNod, &b->nMstNod, &b->nSurfDir,
        &b->nDir, &b->nStateVar, &b->nProps, &b->nTemp, &npred, &b->numDefTfv, b->jSlvUid,
        b->jMstUid, b->jConMstid, &b->timStep, &b->timGlb, &b->dTimCur, b->surfInt,
        b->surfSlv, b->surfMst, b->rdisp, b->drdisp, b->drot, b->stiffDflt, b->condDflt,
        b->shape, b->coordSlv, b->coordMst, b->alocaldir, b->props, b->areaSlv, b->tempSlv,
        b->dtempSlv, z, z, b->tempMst, b->dtempMst, z, z, 80, 80, 80);
    return RS_OK;
}

int main(int argc, char **argv)
{
    int calls = 500, reps = 201;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!strcmp(argv[i], "--calls"))
            calls = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--reps"))
            reps = atoi(argv[i + 1]);
    }
    if (calls < 2 || reps < 1 || reps > 1001) {
        fprintf(stderr, "usage: bench_fortran [--calls N>=2] [--reps 1..1001]\n");
        return 2;
    }
    rs_law fl;
    rs_error err;
    if (rs_law_load_vuinter(RS_VUINTER_BONDED_LIB, &fl, &err) != RS_OK) {
        fprintf(stderr, "bench_fortran: %s\n", err.msg);
        return 1;
    }
    const rs_law *cl = rs_law_find("bonded_interface");
    raw = ((const rs_loaded_law *)fl.ctx)->vuinter;
    rs_law rl = {.name = "raw", .nprops = -1, .update = raw_update};
    static blk k;
    blk_init(&k);
    static double tc[1001], tf[1001], tr[1001], ratio[1001], rraw[1001];
    time_law(cl, &k, calls); /* warm-up */
    time_law(&fl, &k, calls);
    for (int r = 0; r < reps; ++r) {
        if (r & 1) {
            tf[r] = time_law(&fl, &k, calls);
            tc[r] = time_law(cl, &k, calls);
        } else {
            tc[r] = time_law(cl, &k, calls);
            tf[r] = time_law(&fl, &k, calls);
        }
        tr[r] = time_law(&rl, &k, calls);
        ratio[r] = tf[r] / tc[r];
        rraw[r] = tf[r] / tr[r];
    }
    double mc = rs_bench_median(tc, reps), mf = rs_bench_median(tf, reps),
           mr = rs_bench_median(ratio, reps);
    double mraw = rs_bench_median(tr, reps), mshim = rs_bench_median(rraw, reps);
    double minc = tc[0], minf = tf[0], minr = tr[0];
    for (int r = 1; r < reps; ++r) {
        minc = fmin(minc, tc[r]);
        minf = fmin(minf, tf[r]);
        minr = fmin(minr, tr[r]);
    }
    printf("bench_fortran (%s): bonded interface, blocks of %d contacts, %d calls x %d "
           "interleaved repetitions\n",
           RS_BUILD_TYPE, N, calls, reps);
    printf("  C built-in bonded_interface  %7.1f ns/contact\n", mc);
    printf("  Fortran VUINTER through shim %7.1f ns/contact\n", mf);
    printf("  Fortran VUINTER called raw     %7.1f ns/contact (rs_law_call, no shim)\n",
           mraw);
    printf("  shim alone: shim/raw %.3f (%+.1f%%)\n", mshim, 100.0 * (mshim - 1.0));
    printf("  ratio Fortran/C (median of per-repetition ratios) %.3f  (overhead %+.1f%%)\n",
           mr, 100.0 * (mr - 1.0));
    printf(
        "  fastest repetitions: C %.1f, Fortran %.1f, raw %.1f ns/contact: Fortran/C %.3f "
        "(%+.1f%%), shim/raw %.3f\n",
        minc, minf, minr, minf / minc, 100.0 * (minf / minc - 1.0), minf / minr);
    rs_law_unload(&fl);
    return 0;
}
