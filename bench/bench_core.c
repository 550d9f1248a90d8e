/* Core microbenchmark: closest features + frame (rs_surface_query) + tracker
 * (rs_track_update and rs_track_commit) per contact on a REVOLUTION drum whose profile
 * has 1, 8 or 64 segments, against a bare closed-form cylinder distance on the same
 * points in the same run. The tracker pass is what fix wall/rigid runs around its law
 * call: rs_track_update, rs_track_load (previous stress, shear carried by drot) and
 * rs_track_commit. Repetitions are interleaved; medians are reported.
 *
 *   bench_core [--particles N] [--reps R] [--seed S] [--nseg 1|8|64] [--still 1] [--block
 * B]
 *
 * --still 1: the drum stands still and the tracker gets no motion (NULL), as for a
 * fixed wall in fix wall/rigid. --block B: B particles per block (default and largest
 * RS_BLOCK = 128, the block fix wall/rigid uses).
 *
 * Drum: axis z through the origin, radius RD, half-height H. 1 segment: the mantle
 * only. n >= 3 segments: bottom cap, n - 2 collinear mantle pieces, top cap. The
 * mantle travels +z, so n = (-t_z, t_r) points inward. Every particle overlaps the
 * mantle away from the caps, so every point yields exactly one contact. The drum turns
 * about its axis (the query gets its pose, the tracker its motion). As in fix wall/rigid,
 * the query keeps gap <= tracking and drops centres deeper than the particle radius
 * (dist_min = -radius). Times are thread CPU time (CLOCK_THREAD_CPUTIME_ID). */
#define _POSIX_C_SOURCE 200809L
#include "rigidsurf/motion.h"
#include "rigidsurf/surface.h"
#include "rigidsurf/track.h"

#include "bench_clock.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench_rng.h"

#define RD 0.15
#define H 0.05
#define RAD 0.004

typedef struct cloud {
    int n;
    double *x, *y, *z, *vx, *vy, *vz, *wx, *wy, *wz, *r;
    int *id;
    double **dp, **hp, *dir, *hist;
    ptrdiff_t stride;
} cloud;

static void *xmalloc(size_t bytes)
{
    void *p = malloc(bytes);
    if (!p) {
        fprintf(stderr, "bench_core: out of memory\n");
        exit(1);
    }
    return p;
}

static void cloud_make(cloud *c, int n, const rs_tracker *tr)
{
    const int hs = rs_track_slot_size(tr);
    double **cols[] = {&c->x,  &c->y,  &c->z,  &c->vx, &c->vy,
                       &c->vz, &c->wx, &c->wy, &c->wz, &c->r};
    c->n = n;
    for (size_t k = 0; k < sizeof cols / sizeof cols[0]; k++)
        *cols[k] = xmalloc((size_t)n * sizeof(double));
    c->id = xmalloc((size_t)n * sizeof(int));
    /* History as fix wall/rigid keeps it: the directories in one array, slot j of every
     * particle in one array (slot-major), so a particle with one contact touches its
     * directory and its slot 0 only. */
    c->dp = xmalloc((size_t)n * sizeof(double *));
    c->hp = xmalloc((size_t)n * sizeof(double *));
    c->dir = xmalloc((size_t)n * tr->capacity * sizeof(double));
    c->hist = xmalloc((size_t)n * tr->capacity * hs * sizeof(double));
    c->stride = (ptrdiff_t)n * hs;
    for (int i = 0; i < n; i++) {
        double a = 2.0 * 3.14159265358979323846 * urand();
        double pen = 0.1 * RAD * urand();
        double rho = RD - RAD + pen;
        c->x[i] = rho * cos(a);
        c->y[i] = rho * sin(a);
        c->z[i] = (H - 3.0 * RAD) * (2.0 * urand() - 1.0);
        c->vx[i] = 0.1 * (urand() - 0.5);
        c->vy[i] = 0.1 * (urand() - 0.5);
        c->vz[i] = 0.1 * (urand() - 0.5);
        c->wx[i] = urand() - 0.5;
        c->wy[i] = urand() - 0.5;
        c->wz[i] = urand() - 0.5;
        c->r[i] = RAD;
        c->id[i] = i + 1;
        c->dp[i] = c->dir + (size_t)i * tr->capacity;
        c->hp[i] = c->hist + (size_t)i * hs;
        rs_track_clear(tr, c->dp[i], c->hp[i], c->stride);
    }
}

static void cloud_free(cloud *c)
{
    double *cols[] = {c->x, c->y, c->z, c->vx, c->vy, c->vz, c->wx, c->wy, c->wz, c->r};
    for (size_t k = 0; k < sizeof cols / sizeof cols[0]; k++)
        free(cols[k]);
    free(c->id);
    free(c->dp);
    free(c->hp);
    free(c->dir);
    free(c->hist);
}

static void drum_text(int nseg, char *buf, size_t len)
{
    int o = snprintf(buf, len, "*SURFACE, TYPE=REVOLUTION, NAME=drum%d\n0, 0, 0, 0, 0, 1\n",
                     nseg);
    if (nseg == 1) {
        snprintf(buf + o, len - (size_t)o, "START, %.17g, %.17g\nLINE, %.17g, %.17g\n", RD,
                 -H, RD, H);
        return;
    }
    o += snprintf(buf + o, len - (size_t)o, "START, 0, %.17g\nLINE, %.17g, %.17g\n", -H, RD,
                  -H);
    int nm = nseg - 2;
    for (int k = 1; k <= nm; k++)
        o += snprintf(buf + o, len - (size_t)o, "LINE, %.17g, %.17g\n", RD,
                      -H + 2.0 * H * k / nm);
    snprintf(buf + o, len - (size_t)o, "LINE, 0, %.17g\n", H);
}

/* The reference: a bare closed-form cylinder r = hypot(x, y), gap, inward normal. */
static double sink;
static void cylinder_baseline(const cloud *c, double *gap, double *nx, double *ny)
{
    for (int i = 0; i < c->n; i++) {
        double r = hypot(c->x[i], c->y[i]);
        gap[i] = RD - r - c->r[i];
        nx[i] = -c->x[i] / r;
        ny[i] = -c->y[i] / r;
    }
}

typedef struct pipe {
    rs_surface s;
    rs_tracker tr;
    rs_motion m;
    int nblock;
    rs_contacts c; /* the contacts of the current block */
    rs_track_out out;
    double *stress;
    long contacts; /* contacts of the last pass */
    int still;     /* fixed drum: the tracker gets no motion */
} pipe;

/* Particles per block (--block, at most RS_BLOCK). */
static int block = RS_BLOCK;

/* One step over the cloud in blocks of `block`, as fix wall/rigid runs it: each block
 * is queried (closest features and frame), then tracked (update, load, commit; no law)
 * while its contacts are fresh. The whole step is timed (*tt, query + tracker); a
 * second pass over the same pose runs the queries alone (*tq), so the tracker's share
 * is the difference. */
static int query_block(pipe *pp, const cloud *cl, int b, rs_error *err)
{
    int b0 = b * block, nb = cl->n - b0 < block ? cl->n - b0 : block;
    rs_query q = {
        .n = nb,
        .slave = {.x = cl->x + b0, .y = cl->y + b0, .z = cl->z + b0, .radius = cl->r + b0},
        .pose = &pp->m.pose,
        .gap_max = pp->tr.tracking,
        .dist_min = -RAD};
    pp->c.n = 0;
    int rc = rs_surface_query(&pp->s, &q, &pp->c, err);
    pp->contacts += pp->c.n;
    return rc;
}

static int pipeline(pipe *pp, const cloud *cl, double dt, double *tq, double *tt,
                    rs_error *err)
{
    pp->contacts = 0;
    double t0 = rs_bench_thread_now();
    for (int b = 0; b < pp->nblock; b++) {
        int b0 = b * block, nb = cl->n - b0 < block ? cl->n - b0 : block;
        int rc = query_block(pp, cl, b, err);
        if (rc)
            return rc;
        rs_particles p = {.n = nb,
                          .x = cl->x + b0,
                          .y = cl->y + b0,
                          .z = cl->z + b0,
                          .vx = cl->vx + b0,
                          .vy = cl->vy + b0,
                          .vz = cl->vz + b0,
                          .wx = cl->wx + b0,
                          .wy = cl->wy + b0,
                          .wz = cl->wz + b0,
                          .radius = cl->r + b0,
                          .id = cl->id + b0,
                          .dir = cl->dp + b0,
                          .hist = cl->hp + b0,
                          .slot_stride = cl->stride};
        rc = rs_track_update(&pp->tr, &pp->s, pp->still ? NULL : &pp->m, dt, &p, &pp->c,
                             &pp->out, err);
        if (rc)
            return rc;
        if (pp->out.n > 4 * RS_BLOCK) {
            fprintf(stderr, "bench_core: %d tracker entries in a block\n", pp->out.n);
            return 1;
        }
        rs_track_load(&pp->tr, &pp->out, pp->stress, NULL);
        rs_track_commit(&pp->tr, &pp->out, pp->stress, NULL);
    }
    double t1 = rs_bench_thread_now();
    long nc = pp->contacts;
    for (int b = 0; b < pp->nblock; b++) {
        int rc = query_block(pp, cl, b, err);
        if (rc)
            return rc;
    }
    double t2 = rs_bench_thread_now();
    if (pp->contacts != 2 * nc) {
        fprintf(stderr, "bench_core: the query-only pass found %ld contacts, not %ld\n",
                pp->contacts - nc, nc);
        return 1;
    }
    pp->contacts = nc;
    *tt = t1 - t0;
    *tq = t2 - t1;
    return 0;
}

int main(int argc, char **argv)
{
    int np = 8192, reps = 101, only = 0, still = 0;
    unsigned long long seed = 12345;
    for (int a = 1; a < argc; a += 2) {
        char *end = NULL;
        long v = 0;
        if (a + 1 < argc)
            v = strtol(argv[a + 1], &end, 10);
        int ok = a + 1 < argc && end && *end == '\0' && v > 0;
        if (ok && !strcmp(argv[a], "--particles"))
            np = (int)v;
        else if (ok && !strcmp(argv[a], "--reps"))
            reps = (int)v;
        else if (ok && !strcmp(argv[a], "--seed"))
            seed = (unsigned long long)v;
        else if (ok && !strcmp(argv[a], "--nseg") && (v == 1 || v == 8 || v == 64))
            only = (int)v;
        else if (ok && !strcmp(argv[a], "--still") && v == 1)
            still = 1;
        else if (ok && !strcmp(argv[a], "--block") && v <= RS_BLOCK)
            block = (int)v;
        else {
            fprintf(
                stderr,
                "bench_core: bad argument '%s'; expected --particles N, --reps R, "
                "--seed S (positive integers), --nseg 1, 8 or 64, --still 1, or --block B "
                "(1 to %d)\n",
                argv[a], RS_BLOCK);
            return 2;
        }
    }
    printf("command:");
    for (int a = 0; a < argc; a++)
        printf(" %s", argv[a]);
    printf("\nbuild: %s %s\n", RS_BUILD_TYPE, RS_BUILD_FLAGS);
    printf("particles %d, repetitions %d (interleaved; medians), block %d, drum R = %g, "
           "particle radius %g\n",
           np, reps, block, RD, RAD);
    printf("%6s %10s %12s %12s %12s %12s %10s\n", "nseg", "contacts", "cyl ns/pt",
           "query ns/c", "track ns/c", "total ns/c", "ratio");

    const int nsegs[3] = {1, 8, 64};
    double *gap = xmalloc((size_t)np * sizeof(double));
    double *nx = xmalloc((size_t)np * sizeof(double));
    double *ny = xmalloc((size_t)np * sizeof(double));
    double *tb = xmalloc((size_t)reps * sizeof(double));
    double *tq = xmalloc((size_t)reps * sizeof(double));
    double *tt = xmalloc((size_t)reps * sizeof(double));
    double *ts = xmalloc((size_t)reps * sizeof(double));
    char text[8192];
    rs_error err;
    const double dt = 1e-5, omega = still ? 0.0 : 2.0;

    for (int is = 0; is < 3; is++) {
        if (only && nsegs[is] != only)
            continue;
        pipe pp;
        memset(&pp, 0, sizeof pp);
        pp.still = still;
        /* the slot of earlier figures: the stress kept, no energies */
        pp.tr = (rs_tracker){4, 0, 3, 0.1 * RAD, RS_DROP_ENERGY};
        drum_text(nsegs[is], text, sizeof text);
        if (rs_surface_parse(text, "bench_core", NULL, &pp.s, &err)) {
            fprintf(stderr, "bench_core: %s\n", err.msg);
            return 1;
        }
        double zero[3] = {0, 0, 0}, zaxis[3] = {0, 0, 1};
        rs_motion_init(&pp.m);
        pp.nblock = (np + block - 1) / block;
        if (rs_motion_set_rotation(&pp.m, zero, zaxis, omega, &err) ||
            rs_contacts_reserve(&pp.c, 4 * RS_BLOCK, &err)) {
            fprintf(stderr, "bench_core: %s\n", err.msg);
            return 1;
        }
        pp.stress = xmalloc((size_t)4 * RS_BLOCK * 3 * sizeof(double));
        for (int k = 0; k < 4 * RS_BLOCK * 3; k++)
            pp.stress[k] = 1.0;
        rng_state = seed * 0x9E3779B97F4A7C15ULL + 1;
        cloud cl;
        cloud_make(&cl, np, &pp.tr);

        /* Warm-up: opens every contact, so the timed passes see live history. */
        double dq, dtr;
        for (int w = 0; w < 3; w++)
            if (rs_motion_advance(&pp.m, dt, &err) ||
                pipeline(&pp, &cl, dt, &dq, &dtr, &err)) {
                fprintf(stderr, "bench_core: %s\n", err.msg);
                return 1;
            }
        long nc = pp.contacts;
        if (nc < np) {
            fprintf(stderr, "bench_core: only %ld contacts for %d particles\n", nc, np);
            return 1;
        }
        for (int r = 0; r < reps; r++) {
            double t0 = rs_bench_thread_now();
            cylinder_baseline(&cl, gap, nx, ny);
            double t1 = rs_bench_thread_now();
            sink += gap[r % np] + nx[r % np] + ny[r % np];
            if (rs_motion_advance(&pp.m, dt, &err) ||
                pipeline(&pp, &cl, dt, &dq, &dtr, &err)) {
                fprintf(stderr, "bench_core: %s\n", err.msg);
                return 1;
            }
            if (pp.contacts != nc) {
                fprintf(stderr, "bench_core: contact count changed (%ld, was %ld)\n",
                        pp.contacts, nc);
                return 1;
            }
            tb[r] = t1 - t0;
            tq[r] = dq;
            tt[r] = dtr - dq;
            ts[r] = dtr;
        }
        double mb = rs_bench_median(tb, reps) / np * 1e9;
        double mq = rs_bench_median(tq, reps) / (double)nc * 1e9;
        double mt = rs_bench_median(tt, reps) / (double)nc * 1e9;
        double ms = rs_bench_median(ts, reps) / (double)nc * 1e9;
        printf("%6d %10ld %12.2f %12.2f %12.2f %12.2f %10.2f\n", nsegs[is], nc, mb, mq, mt,
               ms, ms / mb);
        cloud_free(&cl);
        free(pp.stress);
        rs_track_out_free(&pp.out);
        rs_contacts_free(&pp.c);
        rs_surface_free(&pp.s);
    }
    printf("cyl ns/pt: closed-form cylinder distance and normal per point (hypot).\n"
           "query ns/c: rs_surface_query (closest features + frame) per contact.\n"
           "track ns/c: rs_track_update + rs_track_load + rs_track_commit per contact.\n"
           "total ns/c: query + frame + tracker per contact (median of the per-repetition\n"
           "  sums, so not exactly query + track); ratio = total / cyl.\n"
           "Times: thread CPU time of whole passes over the cloud.\n");
    if (sink == 12345.678)
        printf("%g\n", sink);
    free(gap);
    free(nx);
    free(ny);
    free(tb);
    free(tq);
    free(tt);
    free(ts);
    return 0;
}
