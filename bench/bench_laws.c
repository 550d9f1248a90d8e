/* Law microbenchmark: ns per contact of the built-in laws hertz and bonded_interface
 * over full blocks of RS_BLOCK contacts, through rs_law_call (block checks, the law,
 * and the NaN/Inf guard) and through the bare update function.
 * Repetitions interleave the laws; medians are reported. Every repetition restores the
 * same contact state first, so each measures the same work.
 *
 *   bench_laws [--calls N] [--reps R]
 *
 * Contacts: overlaps up to 1e-4 (radius 4 mm), random normal and tangential relative
 * velocities; about a quarter of the hertz contacts slide (friction cap). bonded: all
 * bonded, normal increments that take about half of them past yield. */
#define _POSIX_C_SOURCE 200809L
#include "rigidsurf/law.h"

#include "bench_clock.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench_rng.h"

#define N RS_BLOCK

typedef struct bench_block {
    rs_law_block b;
    const rs_law *law;
    int uid[N], fid[N];
    double rdisp[3 * N], drdisp[3 * N], drot[4 * N], stiff[N], cond[N];
    double coordSlv[3 * N], coordMst[3 * N], aloc[9 * N], props[8];
    double stress[3 * N], fluxSlv[N], fluxMst[N], sed[N], statev[3 * N];
    double sfd[N], scd[N], spd[N], svd[N];
    double radius[N], mass[N], vrel[3 * N], tslv[N], tmst[1];
    double stress0[3 * N], statev0[3 * N]; /* restored before each repetition */
} bench_block;

static void bench_block_init(bench_block *k, const char *name, const double *props, int np)
{
    memset(k, 0, sizeof *k);
    k->law = rs_law_find(name);
    rs_law_block *b = &k->b;
    rs_law_block_init(b);
    b->nSlvNod = N;
    b->nDir = 3;
    b->nSurfDir = 2;
    b->nProps = np;
    b->nStateVar = k->law->nstatev;
    b->dTimCur = 1e-5;
    memcpy(k->props, props, (size_t)np * sizeof *props);
    for (int c = 0; c < N; ++c) {
        k->uid[c] = c;
        k->fid[c] = 4 * c;
        k->drot[4 * c] = k->drot[4 * c + 3] = 1.0;
        k->radius[c] = 0.004;
        k->mass[c] = 2500.0 * 4.0 / 3.0 * 3.14159265358979 * 0.004 * 0.004 * 0.004;
        k->rdisp[3 * c] = 1e-4 * urand();
        for (int i = 0; i < 3; ++i) {
            k->vrel[3 * c + i] = urand() - 0.5;
            k->aloc[9 * c + 4 * i] = 1.0;
        }
        k->drdisp[3 * c] = -k->vrel[3 * c] * b->dTimCur;
        k->drdisp[3 * c + 1] = k->vrel[3 * c + 1] * b->dTimCur;
        k->drdisp[3 * c + 2] = k->vrel[3 * c + 2] * b->dTimCur;
        k->tslv[c] = 300.0 + 50.0 * urand();
    }
    k->tmst[0] = 330.0;
    b->jSlvUid = k->uid;
    b->jConMstid = k->fid;
    b->rdisp = k->rdisp;
    b->drdisp = k->drdisp;
    b->drot = k->drot;
    b->stiffDflt = k->stiff;
    b->condDflt = k->cond;
    b->coordSlv = k->coordSlv;
    b->coordMst = k->coordMst;
    b->alocaldir = k->aloc;
    b->props = k->props;
    b->tempSlv = k->tslv;
    b->tempMst = k->tmst;
    b->stress = k->stress;
    b->fluxSlv = k->fluxSlv;
    b->fluxMst = k->fluxMst;
    b->sed = k->sed;
    b->statev = k->statev;
    b->sfd = k->sfd;
    b->scd = k->scd;
    b->spd = k->spd;
    b->svd = k->svd;
    b->radius = k->radius;
    b->mass = k->mass;
    b->vrel = k->vrel;
}

/* One repetition: calls block calls from the saved state, ns per contact. */
static double time_calls(bench_block *k, int calls, int guarded)
{
    rs_error err;
    memcpy(k->stress, k->stress0, sizeof k->stress);
    memcpy(k->statev, k->statev0, sizeof k->statev);
    const double t0 = rs_bench_now();
    for (int i = 0; i < calls; ++i) {
        int rc = guarded ? rs_law_call(k->law, &k->b, &err)
                         : k->law->update(k->law, &k->b, &err);
        if (rc != RS_OK) {
            fprintf(stderr, "bench_laws: %s\n", err.msg);
            exit(1);
        }
    }
    return (rs_bench_now() - t0) * 1e9 / ((double)calls * N);
}

int main(int argc, char **argv)
{
    int calls = 2000, reps = 31;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (strcmp(argv[i], "--calls") == 0) {
            calls = atoi(argv[i + 1]);
        } else if (strcmp(argv[i], "--reps") == 0) {
            reps = atoi(argv[i + 1]);
        } else {
            fprintf(stderr, "usage: bench_laws [--calls N] [--reps R]\n");
            return 2;
        }
    }
    if (calls < 1 || reps < 1 || reps > 1001) {
        fprintf(stderr, "bench_laws: --calls >= 1 and 1 <= --reps <= 1001 expected\n");
        return 2;
    }
    static bench_block hz, bd;
    const double hp[7] = {5e6, 0.45, 7e10, 0.3, 0.5, 0.4, 0.0};
    const double bp[7] = {1e-3, 1e7, 0.3, 2e4, 1e6, 1e-3, 10.0};
    bench_block_init(&hz, "hertz", hp, 7);
    bench_block_init(&bd, "bonded_interface", bp, 7);
    for (int c = 0; c < N; ++c) {
        /* A quarter of the hertz contacts carry a shear history past the cap. */
        hz.statev0[2 * c] = c % 4 == 0 ? 1e-4 : 1e-8;
        /* bonded: already initialised and bonded; yield reached for half of them. */
        bd.statev0[3 * c] = 1.0;
        bd.statev0[3 * c + 1] = 1.0;
        bd.statev0[3 * c + 2] = bp[3];
        bd.stress0[3 * c] = c % 2 ? 0.99 * bp[3] : 0.2 * bp[3];
        bd.drdisp[3 * c] = 1e-9;
    }
    struct {
        const char *what;
        bench_block *k;
        int guarded;
        double t[1001];
    } runs[4] = {{"hertz, rs_law_call", &hz, 1, {0}},
                 {"hertz, update only", &hz, 0, {0}},
                 {"bonded_interface, rs_law_call", &bd, 1, {0}},
                 {"bonded_interface, update only", &bd, 0, {0}}};
    for (int r = 0; r < 4; ++r) {
        time_calls(runs[r].k, calls / 10 + 1, runs[r].guarded); /* warm-up */
    }
    for (int rep = 0; rep < reps; ++rep) {
        for (int r = 0; r < 4; ++r) {
            runs[r].t[rep] = time_calls(runs[r].k, calls, runs[r].guarded);
        }
    }
    printf(
        "bench_laws: %d calls x %d contacts per repetition, %d interleaved repetitions\n",
        calls, N, reps);
    printf("build: %s (%s)\n", RS_BUILD_TYPE, RS_BUILD_FLAGS);
    for (int r = 0; r < 4; ++r) {
        printf("  %-32s %7.2f ns/contact (median)\n", runs[r].what,
               rs_bench_median(runs[r].t, reps));
    }
    return 0;
}
