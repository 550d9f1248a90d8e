/* The built-in hertz law's fused kernel (rs_track_fused, the usual block in one pass)
 * against the staged calls it stands for (rs_track_update, rs_track_load,
 * rs_cblock_inputs, rs_cblock_call with the built-in hertz law, rs_cblock_add_loads,
 * rs_track_commit), on a cylinder's mantle that turns about a tilted axis and translates:
 * the forces, torques, stored forces, per-atom rows, the wall's sums and every history
 * value, bit for bit, over increments in which contacts stick, slide and open, after one
 * in which they begin (the tracker's general pass, then the staged calls). A block that
 * does not qualify is left to the staged calls, and a NaN in the law's stress is reported
 * as rs_law_call reports it, with nothing written: the rows, the slots and the
 * directories are as before the call. */
#include "rigidsurf/contact_block.h"
#include "rigidsurf/law.h"
#include "rigidsurf/motion.h"
#include "rs_test.h"
#include "track_fused.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NP 100 /* three runs of the tracker and part of a fourth */
#define CAP 4
#define DT 1e-4
#define TRACK 1e-4

static const char *mantle = "*SURFACE, TYPE=REVOLUTION, NAME=cyl\n0, 0, 0, 0, 0, 1\n"
                            "START, 0.05, -0.1\nLINE, 0.05, 0.1\n";

/* Y_particle nu_particle Y_wall nu_wall restitution friction curvature */
static const double props[7] = {5e6, 0.3, 5e7, 0.25, 0.5, 0.3, 0.0};

/* One engine's state: the histories and the rows the loads add onto. */
typedef struct engine {
    double dir[NP][CAP], hist[NP][CAP * 8];
    double *dp[NP], *hp[NP];
    double f[NP][3], t[NP][3], fs[NP][3], o6[NP][6];
    rs_track_out out;
    rs_wall_load w;
} engine;

typedef struct scene {
    rs_surface s;
    rs_motion mo;
    rs_tracker tr;
    int n, id[NP];
    double x[NP], y[NP], z[NP], vx[NP], vy[NP], vz[NP], wx[NP], wy[NP], wz[NP], r[NP],
        m[NP];
    rs_contacts c;
} scene;

static void engine_init(engine *g, const rs_tracker *tr)
{
    memset(g, 0, sizeof *g);
    for (int i = 0; i < NP; i++) {
        g->dp[i] = g->dir[i];
        g->hp[i] = g->hist[i];
        rs_track_clear(tr, g->dir[i], g->hist[i], 0);
    }
}

static rs_particles block(scene *sc, engine *g)
{
    return (rs_particles){.n = sc->n,
                          .x = sc->x,
                          .y = sc->y,
                          .z = sc->z,
                          .vx = sc->vx,
                          .vy = sc->vy,
                          .vz = sc->vz,
                          .wx = sc->wx,
                          .wy = sc->wy,
                          .wz = sc->wz,
                          .radius = sc->r,
                          .id = sc->id,
                          .dir = g->dp,
                          .hist = g->hp,
                          .mass = sc->m};
}

/* Spheres against the inside of the mantle, some pressed in, some within the tracking
 * thickness but apart, with velocities and spins. */
static void scene_init(scene *sc)
{
    memset(sc, 0, sizeof *sc);
    ENSURE(rs_surface_parse(mantle, "mantle", NULL, &sc->s, NULL) == RS_OK);
    rs_motion_init(&sc->mo);
    const double axis[3] = {0.3, 0.2, 1.0}, centre[3] = {0.01, 0.0, 0.0},
                 vel[3] = {2e-3, -1e-3, 0.0};
    ENSURE(rs_motion_set_rotation(&sc->mo, centre, axis, 0.8, NULL) == RS_OK);
    rs_motion_set_translation(&sc->mo, vel);
    /* the slots hertz declares it reads: n, t1 and its 2 state variables */
    sc->tr = (rs_tracker){CAP, 2, 3, TRACK, rs_law_drops(rs_law_find("hertz"))};
    ENSURE(rs_track_slot_size(&sc->tr) == 8);
    sc->n = NP;
    srand(7);
    for (int i = 0; i < NP; i++) {
        const double u = (double)rand() / RAND_MAX, th = 2.0 * 3.14159265358979 * i / NP;
        sc->r[i] = 0.002 * (1.0 + 0.2 * u);
        sc->m[i] = 2500.0 * 4.18879 * pow(sc->r[i], 3);
        const double rho = 0.05 - sc->r[i] + (i % 5 == 0 ? -0.5e-4 : 0.6e-4 * u);
        sc->x[i] = rho * cos(th);
        sc->y[i] = rho * sin(th);
        sc->z[i] = 0.02 * (u - 0.5);
        sc->vx[i] = 0.02 * (u - 0.3) * cos(th);
        sc->vy[i] = 0.02 * (u - 0.3) * sin(th);
        sc->vz[i] = 0.05 * (0.5 - u);
        sc->wx[i] = 3.0 * u, sc->wy[i] = -2.0, sc->wz[i] = 10.0 * (u - 0.5);
        sc->id[i] = 1 + i;
    }
}

static void query(scene *sc)
{
    rs_query q = {.n = sc->n,
                  .slave = {.x = sc->x, .y = sc->y, .z = sc->z, .radius = sc->r},
                  .pose = &sc->mo.pose,
                  .gap_max = TRACK,
                  .dist_min = -INFINITY};
    sc->c.n = 0;
    ENSURE(rs_surface_query(&sc->s, &q, &sc->c, NULL) == RS_OK);
}

static void clear_rows(engine *g)
{
    memset(g->f, 0, sizeof g->f);
    memset(g->t, 0, sizeof g->t);
    memset(g->fs, 0, sizeof g->fs);
    memset(g->o6, 0, sizeof g->o6);
}

/* The engine's rows; the fused kernel also writes each particle's rdisp and stress into
 * o6 (the staged calls write them below, as the wall does). */
static rs_load_rows rows_of(engine *g)
{
    return (rs_load_rows){.f = g->f[0], .t = g->t[0], .fstore = g->fs[0], .out6 = g->o6[0]};
}

/* The staged calls, as the LIGGGHTS fix makes them; continue_only: the tracker ran. */
static int staged(scene *sc, engine *g, rs_contact_block *cb, int continue_only,
                  rs_error *err)
{
    const rs_law *hertz = rs_law_find("hertz");
    rs_particles p = block(sc, g);
    int rc;
    if (!continue_only &&
        (rc = rs_track_update(&sc->tr, &sc->s, &sc->mo, DT, &p, &sc->c, &g->out, err)))
        return rc;
    rs_track_load(&sc->tr, &g->out, rs_law_stress_in(hertz) ? cb->stress : NULL,
                  cb->statev);
    rs_cblock_inputs(cb, &g->out, &p, DT);
    rs_track_load_energy(&sc->tr, &g->out, cb->sed, cb->flux_slv, cb->flux_mst);
    rs_law_block b;
    rs_law_block_init(&b);
    b.nDir = 3, b.nSurfDir = 2, b.nStateVar = 2, b.nProps = 7, b.props = props;
    b.dTimCur = DT, b.kInc = 2;
    if ((rc = rs_cblock_call(cb, hertz, &b, &g->out, err)))
        return rc;
    const rs_load_rows rows = rows_of(g);
    rs_cblock_add_loads(cb, &g->out, &p, sc->s.a, &rows, &g->w);
    for (int e = 0; e < g->out.n; e++) {
        const int k = g->out.point[e];
        for (int d = 0; d < 3; d++) {
            g->o6[k][d] = g->out.rdisp[3 * e + d];
            g->o6[k][3 + d] = cb->stress[3 * e + d];
        }
    }
    rs_track_commit(&sc->tr, &g->out, cb->stress, cb->statev);
    return RS_OK;
}

static int same_engines(const engine *a, const engine *b)
{
    return !memcmp(a->dir, b->dir, sizeof a->dir) &&
           !memcmp(a->hist, b->hist, sizeof a->hist) && !memcmp(a->f, b->f, sizeof a->f) &&
           !memcmp(a->t, b->t, sizeof a->t) && !memcmp(a->fs, b->fs, sizeof a->fs) &&
           !memcmp(a->o6, b->o6, sizeof a->o6) &&
           !memcmp(a->w.force, b->w.force, sizeof a->w.force) &&
           !memcmp(a->w.moment, b->w.moment, sizeof a->w.moment) && a->w.se == b->w.se &&
           a->w.fd == b->w.fd && a->w.vd == b->w.vd && a->w.pd == b->w.pd &&
           a->w.cd == b->w.cd && a->w.flux_slv == b->w.flux_slv &&
           a->w.flux_mst == b->w.flux_mst && a->w.ncontact == b->w.ncontact;
}

static void advance(scene *sc)
{
    ENSURE(rs_motion_advance(&sc->mo, DT, NULL) == RS_OK);
    for (int i = 0; i < sc->n; i++) {
        sc->x[i] += DT * sc->vx[i];
        sc->y[i] += DT * sc->vy[i];
        sc->z[i] += DT * sc->vz[i];
    }
}

/* One increment of both engines: A staged, B in one pass where the block qualifies
 * (else the staged calls after its tracker); *done: whether B took the one pass. */
static void step_both(scene *sc, engine *A, engine *B, rs_contact_block *cb, int *done)
{
    query(sc);
    clear_rows(A);
    clear_rows(B);
    rs_error err;
    ENSURE(staged(sc, A, cb, 0, &err) == RS_OK);
    rs_particles p = block(sc, B);
    const rs_load_rows rows = rows_of(B);
    *done = -1;
    ENSURE(rs_track_fused(&sc->tr, rs_law_find("hertz"), &sc->s, &sc->mo, DT, &p, &sc->c,
                          &B->out, props, sc->s.a, &rows, &B->w, done, &err) == RS_OK);
    if (!*done)
        ENSURE(staged(sc, B, cb, 1, &err) == RS_OK);
}

/* The scene, two engines on it and the staged calls' contact block. */
static void setup(scene *sc, engine *A, engine *B, rs_contact_block *cb)
{
    scene_init(sc);
    engine_init(A, &sc->tr);
    engine_init(B, &sc->tr);
    memset(cb, 0, sizeof *cb);
    cb->ndir = 3, cb->nstatev = 2, cb->area_mode = RS_AREA_NODE;
    ENSURE(rs_cblock_reserve(cb, NP * CAP, NULL) == RS_OK);
}

static void test_one_pass_is_the_staged_calls(void)
{
    static scene sc;
    static engine A, B;
    rs_contact_block cb;
    setup(&sc, &A, &B, &cb);
    int open = 0, slide = 0, press = 0, all_same = 1, fused = 0;
    for (int step = 0; step < 12; step++) {
        if (step > 0)
            advance(&sc);
        int done;
        step_both(&sc, &A, &B, &cb, &done);
        fused += done == 1;
        ENSURE(sc.c.n == NP && B.out.n == NP);
        all_same &= same_engines(&A, &B);
        for (int e = 0; e < NP; e++) {
            const double d = A.out.rdisp[3 * e], *s = cb.stress + 3 * e;
            open += !(d > 0.0);
            press += d > 0.0;
            /* sliding: the shear force at the Coulomb limit */
            slide += d > 0.0 && fabs(hypot(s[1], s[2]) - 0.3 * s[0]) < 1e-9 * s[0];
        }
    }
    ENSURE(all_same);
    /* the first increment's contacts are new (the general pass); the others are held */
    ENSURE(fused == 11);
    /* the increments had contacts of every kind */
    ENSURE(open > 0 && press > 0 && slide > 0);

    /* A block that does not qualify (a sphere beyond the tracking thickness: its contact
     * leaves) is left to the staged calls with the tracker's output; so is the next, in
     * which it comes back (a new contact), and the one after takes the one pass again. */
    const double x3 = sc.x[3], y3 = sc.y[3];
    sc.x[3] *= 0.5, sc.y[3] *= 0.5;
    int done;
    step_both(&sc, &A, &B, &cb, &done);
    ENSURE(done == 0 && sc.c.n == NP - 1);
    ENSURE(same_engines(&A, &B));
    sc.x[3] = x3, sc.y[3] = y3;
    step_both(&sc, &A, &B, &cb, &done);
    ENSURE(done == 0);
    ENSURE(same_engines(&A, &B));
    step_both(&sc, &A, &B, &cb, &done);
    ENSURE(done == 1);
    ENSURE(same_engines(&A, &B));

    /* A NaN velocity: the law's stress is NaN, reported as rs_law_call reports it; the
     * sphere is the last one pressed into the wall, in the block's last run, so that the
     * runs before it hold finite stresses: the call writes nothing, not the rows, nor the
     * slots, nor the directories. */
    int kn = NP - 1; /* a sphere pressed into the wall */
    while (kn > 0 && !(A.out.rdisp[3 * kn] > 0.0))
        kn--;
    ENSURE(kn >= 3 * 32);
    sc.vx[kn] = NAN;
    query(&sc);
    clear_rows(&B);
    for (int i = 0; i < NP; i++)
        for (int d = 0; d < 3; d++)
            B.f[i][d] = 0.25 * i + d, B.o6[i][d] = -1.0 - i;
    static engine before;
    memcpy(&before, &B, sizeof B);
    rs_error ea, eb;
    ENSURE(staged(&sc, &A, &cb, 0, &ea) == RS_ERR_NONFINITE);
    rs_particles p = block(&sc, &B);
    const rs_load_rows rows = rows_of(&B);
    done = 1;
    ENSURE(rs_track_fused(&sc.tr, rs_law_find("hertz"), &sc.s, &sc.mo, DT, &p, &sc.c,
                          &B.out, props, sc.s.a, &rows, &B.w, &done,
                          &eb) == RS_ERR_NONFINITE);
    ENSURE(done == 0);
    char who[32];
    snprintf(who, sizeof who, "particle %d,", sc.id[kn]);
    ENSURE(strcmp(ea.msg, eb.msg) == 0 && strstr(ea.msg, who) != NULL);
    ENSURE(!memcmp(before.dir, B.dir, sizeof B.dir));
    ENSURE(!memcmp(before.hist, B.hist, sizeof B.hist));
    ENSURE(!memcmp(before.f, B.f, sizeof B.f) && !memcmp(before.t, B.t, sizeof B.t));
    ENSURE(!memcmp(before.fs, B.fs, sizeof B.fs) && !memcmp(before.o6, B.o6, sizeof B.o6));

    rs_cblock_free(&cb);
    rs_track_out_free(&A.out);
    rs_track_out_free(&B.out);
    rs_contacts_free(&sc.c);
    rs_surface_free(&sc.s);
}

/* The entry for a caller that has found the block usual (the wall's line path): the same
 * numbers as the staged calls, and an error, not a silent result, for a block it cannot
 * take. */
static void test_usual_entry_is_the_staged_calls(void)
{
    static scene sc;
    static engine A, C;
    rs_contact_block cb;
    setup(&sc, &A, &C, &cb);
    const rs_law *hertz = rs_law_find("hertz");
    rs_error err;
    int all_same = 1;
    for (int step = 0; step < 12; step++) {
        if (step > 0)
            advance(&sc);
        query(&sc);
        clear_rows(&A);
        clear_rows(&C);
        ENSURE(staged(&sc, &A, &cb, 0, &err) == RS_OK);
        if (step == 0) { /* new contacts: the general pass */
            ENSURE(staged(&sc, &C, &cb, 0, &err) == RS_OK);
        } else {
            rs_particles p = block(&sc, &C);
            const rs_load_rows rows = rows_of(&C);
            ENSURE(rs_track_fused_usual(&sc.tr, hertz, &sc.mo, DT, &p, &sc.c, &C.out, props,
                                        sc.s.a, &rows, &C.w, &err) == RS_OK);
        }
        all_same &= same_engines(&A, &C);
    }
    ENSURE(all_same);

    /* Blocks it cannot take without pass 1's search: an error each, not a result. */
    query(&sc);
    rs_particles p = block(&sc, &C);
    const rs_load_rows rows = rows_of(&C);
    sc.c.point[2] = 3; /* contact 2 names another particle */
    ENSURE(rs_track_fused_usual(&sc.tr, hertz, &sc.mo, DT, &p, &sc.c, &C.out, props, sc.s.a,
                                &rows, &C.w, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "rs_track_fused_usual") != NULL);
    sc.c.point[2] = 2;
    p.mass = NULL; /* not spheres with masses */
    ENSURE(rs_track_fused_usual(&sc.tr, hertz, &sc.mo, DT, &p, &sc.c, &C.out, props, sc.s.a,
                                &rows, &C.w, &err) == RS_ERR_ARG);
    p = block(&sc, &C);
    const double belt[3] = {0.0, 0.0, 0.1}; /* a surface velocity */
    memcpy(sc.mo.belt, belt, sizeof belt);
    ENSURE(rs_track_fused_usual(&sc.tr, hertz, &sc.mo, DT, &p, &sc.c, &C.out, props, sc.s.a,
                                &rows, &C.w, &err) == RS_ERR_ARG);

    rs_cblock_free(&cb);
    rs_track_out_free(&A.out);
    rs_track_out_free(&C.out);
    rs_contacts_free(&sc.c);
    rs_surface_free(&sc.s);
}

int main(void)
{
    RS_RUN(test_one_pass_is_the_staged_calls);
    RS_RUN(test_usual_entry_is_the_staged_calls);
    return rs_test_summary();
}
