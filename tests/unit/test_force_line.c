/* A force law with a model per contact (rs_law.force_one), and one that also has the
 * model's operation on a run of contacts in columns (rs_law.force_run), on the wall's line
 * path (src/wall/wall_force_line.c) against the staged calls (keyword fused no), through
 * the wall's public calls as an engine makes them (rs_wall_create with the engine's own
 * law, rs_wall_advance, rs_wall_step, rs_wall_reneighbor):
 * - a drum (a REVOLUTION of one LINE, r = 50 mm about z) turning at 3 rad/s with spheres
 *   of two radii tumbling in it under gravity along -y;
 * - a square plate of two triangles (an STL MESH) moving along x, with spheres sliding
 *   and rolling down it, some across the diagonal between its triangles.
 * Each case runs twice side by side, the particles integrated alike: every step's forces,
 * torques and per-particle outputs (peratom yes) are the same bit for bit, so the runs
 * stay identical, and the wall's sums agree to rounding. The model's one-contact calls
 * outside the block call show that the line path took most contacts in the first run
 * and none in the second; with the run operation, that the line path called it and not
 * the model per contact, and that its column rn is (x - xm).n bit for bit. The model,
 * written here for the test, is a spring-dashpot with a tangential spring kept in space and
 * capped by Coulomb, whose state variables hold that spring and the effective radius where
 * the contact began: it reads every field a force law is given (overlap, radius, mass,
 * effective radius, normal, master point, the wall's velocity there, the history). A model
 * that returns NaN stops the step with a message that names the law and the first value
 * that is not finite (stress(1), the force along n), on the line path as in the block call,
 * and leaves the engine's rows as they were. */
#define _POSIX_C_SOURCE 200809L /* getpid, unlink */
#include "rigidsurf/vec.h"
#include "rigidsurf/wall.h"
#include "rs_test.h"

#include <stdint.h>
#include <string.h>
#include <unistd.h>

enum { NP = 160 };
static const double DT = 2e-5, KN = 2e3, GN = 0.4, KT = 1.5e3, MU = 0.4, RHO = 2500.0;

/* One run: its particles, its wall and its model. */
typedef struct sim {
    double x[NP][3], v[NP][3], om[NP][3], f[NP][3], t[NP][3], out[NP][6];
    double r[NP], m[NP];
    int id[NP], type[NP];
    double g[3];
    rs_wall *w;
    rs_law law;
    int in_update; ///< inside the block call
    long direct;   ///< the model's calls outside the block call (the line path's)
    long calls;    ///< all its calls
    int nan_at;    ///< the particle (id) whose contact gives NaN from this step on; 0: none
    int inf_torque; ///< there an infinite torque(3), not a NaN force(2)
    int by_run;     ///< the law has the run operation (tf_run)
    long runs;      ///< its calls
    long rn_differ; ///< its contacts whose rn is not (x - xm).n bit for bit
    int skips_drot; ///< the law declares RS_LAW_SKIPS_DROT
    long k;         ///< the step
    /// each particle's last contact the model saw: its frame (n, t1) and step (-1: none)
    double seen_n[NP][3], seen_t1[NP][3];
    long seen_at[NP];
} sim;

static int tf_one(const rs_law *law, rs_force_contact *c, double F[3], double T[3],
                  rs_error *err)
{
    (void)err;
    sim *s = law->ctx;
    s->calls++;
    if (!s->in_update)
        s->direct++;
    memcpy(s->seen_n[c->row], c->n, sizeof c->n);
    memcpy(s->seen_t1[c->row], c->t1, sizeof c->t1);
    s->seen_at[c->row] = s->k;
    double *h = c->history;
    if (c->overlap <= 0.0) {
        h[0] = h[1] = h[2] = h[3] = 0.0;
        return 0;
    }
    if (h[3] == 0.0)
        h[3] = c->reff;
    const double *v = s->v[c->row], *w = s->om[c->row], *n = c->n;
    const double R = c->radius;
    /* the velocity of the particle's point at the wall relative to the wall's material */
    const double arm[3] = {-R * n[0], -R * n[1], -R * n[2]};
    double vr[3];
    for (int d = 0; d < 3; d++) {
        const int a = (d + 1) % 3, b = (d + 2) % 3;
        vr[d] = v[d] + (w[a] * arm[b] - w[b] * arm[a]) - c->vwall[d];
    }
    const double vn = vr[0] * n[0] + vr[1] * n[1] + vr[2] * n[2];
    const double kn = KN * sqrt(h[3] / R) * c->mass;
    double fn = kn * c->overlap - GN * sqrt(kn * c->mass) * vn;
    fn = fn > 0.0 ? fn : 0.0;
    double ft[3], lt = 0.0;
    for (int d = 0; d < 3; d++) {
        h[d] += (vr[d] - vn * n[d]) * DT;
        ft[d] = -KT * c->mass * h[d];
        lt += ft[d] * ft[d];
    }
    lt = sqrt(lt);
    if (lt > MU * fn) {
        const double k = MU * fn / lt;
        for (int d = 0; d < 3; d++) {
            ft[d] *= k;
            h[d] *= k;
        }
    }
    for (int d = 0; d < 3; d++)
        F[d] = fn * n[d] + ft[d];
    for (int d = 0; d < 3; d++) {
        const int a = (d + 1) % 3, b = (d + 2) % 3;
        T[d] = arm[a] * ft[b] - arm[b] * ft[a];
    }
    if (s->nan_at && s->id[c->row] == s->nan_at) {
        if (s->inf_torque)
            T[2] = INFINITY;
        else
            F[1] = NAN;
    }
    return 1;
}

/* The model on a run in columns (rs_law.force_run): each contact as rs_wall_force_contact
 * describes it (tf_update), from the run's columns. */
static int tf_run(const rs_law *law, const rs_force_run *r, rs_error *err)
{
    sim *s = law->ctx;
    s->runs++;
    for (int j = 0; j < r->n; j++) {
        rs_force_contact c;
        memset(&c, 0, sizeof c);
        c.row = r->row[j];
        c.overlap = r->overlap[j];
        c.radius = r->radius[j];
        c.mass = r->mass[j];
        c.curv[0] = r->curv[0][j];
        c.curv[1] = r->curv[1][j];
        c.reff = rs_effective_radius(c.radius, c.curv[0], c.curv[1]);
        for (int d = 0; d < 3; d++) {
            c.n[d] = r->nrm[d][j], c.t1[d] = r->t1[d][j], c.t2[d] = r->t2[d][j];
            c.xm[d] = r->xm[d][j];
            c.vwall[d] = r->vwall[0] ? r->vwall[d][j] : r->vwall0[d];
        }
        /* the centre's distance from the master point along n, as the run gives it */
        const double *x = s->x[c.row];
        const double rn = (x[0] - c.xm[0]) * c.n[0] + (x[1] - c.xm[1]) * c.n[1] +
                          (x[2] - c.xm[2]) * c.n[2];
        if (memcmp(&rn, &r->rn[j], sizeof rn) != 0)
            s->rn_differ++;
        c.history = r->history + (size_t)j * (size_t)r->nstatev;
        c.type = r->type ? r->type[c.row] : 1;
        c.wall_type = r->wall_type;
        c.setup = r->setup;
        double F[3] = {0.0, 0.0, 0.0}, T[3] = {0.0, 0.0, 0.0};
        const int acts = tf_one(law, &c, F, T, err);
        if (acts < 0)
            return -acts;
        r->acts[j] = acts;
        for (int d = 0; d < 3; d++)
            r->F[3 * j + d] = F[d], r->T[3 * j + d] = T[d];
    }
    return RS_OK;
}

static int tf_update(const rs_law *law, rs_law_block *b, rs_error *err)
{
    sim *s = law->ctx;
    s->in_update = 1;
    rs_wall_force_begin(b);
    for (int e = 0; e < b->nSlvNod; e++) {
        rs_force_contact c;
        if (!rs_wall_force_contact(s->w, b, e, s->x[0], &c))
            continue;
        double F[3] = {0.0, 0.0, 0.0}, T[3] = {0.0, 0.0, 0.0};
        if (tf_one(law, &c, F, T, err))
            rs_wall_force_result(b, e, &c, F, T);
    }
    s->in_update = 0;
    return RS_OK;
}

static int tf_engine_law(void *ctx, const char *const *words, int nwords,
                         const rs_law **law, rs_error *err)
{
    (void)words, (void)nwords, (void)err;
    sim *s = ctx;
    memset(&s->law, 0, sizeof s->law);
    s->law.name = "test";
    s->law.nstatev = 4;
    s->law.update = tf_update;
    s->law.force_one = tf_one;
    s->law.force_run = s->by_run ? tf_run : NULL;
    s->law.ctx = s;
    s->law.skips = RS_LAW_SKIPS_STRESS | RS_LAW_SKIPS_ENERGY | RS_LAW_SKIPS_SLIP |
                   RS_LAW_SKIPS_DRDISP1 | (s->skips_drot ? RS_LAW_SKIPS_DROT : 0u);
    s->law.sets = RS_LAW_SETS_FORCE | RS_LAW_SETS_ENERGIES | RS_LAW_SETS_NO_HEAT |
                  RS_LAW_SETS_NO_CREEP_PLASTIC | RS_LAW_SETS_STRESS;
    *law = &s->law;
    return RS_OK;
}

static rs_wall_block block_of(sim *s)
{
    rs_wall_block b;
    memset(&b, 0, sizeof b);
    b.n = NP;
    b.x = s->x[0], b.v = s->v[0], b.omega = s->om[0];
    b.radius = s->r, b.mass = s->m, b.type = s->type, b.id = s->id;
    b.inc = 1;
    return b;
}

/* The wall of words (then "fused no" where staged) over s's particles. */
static int make(sim *s, const char *const *words, int nwords, int staged, rs_error *err)
{
    const char *all[64];
    int n = 0;
    for (int k = 0; k < nwords; k++)
        all[n++] = words[k];
    const char *tail[] = {"law", "test", "peratom", "yes", "fused", "no"};
    for (int k = 0; k < (staged ? 6 : 4); k++)
        all[n++] = tail[k];
    rs_wall_host host;
    memset(&host, 0, sizeof host);
    host.ctx = s;
    host.ntypes = 2;
    host.engine_law = tf_engine_law;
    host.engine_law_name = "test";
    int rc = rs_wall_create("w", "all", all, n, &host, &s->w, err);
    if (rc)
        return rc;
    rs_wall_run run;
    memset(&run, 0, sizeof run);
    run.dt = DT;
    run.skin = 2e-3;
    for (int d = 0; d < 3; d++)
        run.box_lo[d] = -0.2, run.box_hi[d] = 0.2;
    rs_wall_block b = block_of(s);
    if ((rc = rs_wall_grow(s->w, NP, err)))
        return rc;
    return rs_wall_init(s->w, &run, &b, err);
}

/* One step of s: the wall's loads, then the particles moved (symplectic Euler; a solid
 * sphere's moment of inertia). */
static int step(sim *s, long k, rs_wall_load *load, rs_error *err)
{
    memset(s->f, 0, sizeof s->f);
    memset(s->t, 0, sizeof s->t);
    memset(s->out, 0, sizeof s->out);
    s->k = k;
    int rc = rs_wall_advance(s->w, DT, err);
    if (rc)
        return rc;
    if (k % 10 == 0)
        rs_wall_reneighbor(s->w);
    rs_wall_block b = block_of(s);
    b.step = k;
    b.inc = (int)k + 1;
    b.time = (double)k * DT;
    b.still = k == 0;
    rs_wall_rows rows;
    memset(&rows, 0, sizeof rows);
    rows.f = s->f[0], rows.torque = s->t[0], rows.peratom = s->out[0];
    if ((rc = rs_wall_step(s->w, &b, &rows, DT, load, err)))
        return rc;
    for (int i = 0; i < NP; i++) {
        const double I = 0.4 * s->m[i] * s->r[i] * s->r[i];
        for (int d = 0; d < 3; d++) {
            s->v[i][d] += DT * (s->f[i][d] / s->m[i] + s->g[d]);
            s->x[i][d] += DT * s->v[i][d];
            s->om[i][d] += DT * s->t[i][d] / I;
        }
    }
    return RS_OK;
}

static int same_bits(const void *a, const void *b, size_t n)
{
    return memcmp(a, b, n) == 0;
}

/* Runs a and b (the same particles; a on the line path, b staged) for nsteps; every
 * step's rows bit for bit and the wall's sums to rounding. */
static void lockstep(sim *a, sim *b, long nsteps, long *contacts)
{
    *contacts = 0;
    for (long k = 0; k < nsteps; k++) {
        rs_wall_load la, lb;
        rs_error e;
        ENSURE(step(a, k, &la, &e) == RS_OK);
        ENSURE(step(b, k, &lb, &e) == RS_OK);
        if (!same_bits(a->f, b->f, sizeof a->f) || !same_bits(a->t, b->t, sizeof a->t) ||
            !same_bits(a->out, b->out, sizeof a->out))
            fprintf(stderr, "step %ld: the line path and the staged calls differ\n", k);
        ENSURE(same_bits(a->f, b->f, sizeof a->f));
        ENSURE(same_bits(a->t, b->t, sizeof a->t));
        ENSURE(same_bits(a->out, b->out, sizeof a->out));
        ENSURE(la.ncontact == lb.ncontact);
        double scale = 1e-30;
        for (int d = 0; d < 3; d++)
            scale += fabs(lb.force[d]);
        for (int d = 0; d < 3; d++)
            ENSURE_SMALL(la.force[d] - lb.force[d], 1e-12 * scale);
        *contacts += la.ncontact;
    }
    ENSURE(same_bits(a->x, b->x, sizeof a->x));
    ENSURE(same_bits(a->v, b->v, sizeof a->v));
}

/* Runs a and b (made: a on the line path, b staged) in lockstep for nsteps, frees their
 * walls, and checks that they touched more than min_contacts times over the run and that
 * the line path took most of a's contacts and none of b's. */
static void check_pair(sim *a, sim *b, const char *name, long nsteps, long min_contacts)
{
    long contacts = 0;
    lockstep(a, b, nsteps, &contacts);
    const int ok = !rs_test_current_failed;
    printf("%s%s: %ld contacts over the run; the model called %ld times on the line path "
           "of %ld (staged run: %ld of %ld), the run operation %ld times\n",
           name, a->by_run ? " (run operation)" : "", contacts, a->direct, a->calls,
           b->direct, b->calls, a->runs);
    rs_wall_free(a->w);
    rs_wall_free(b->w);
    ENSURE(ok);
    ENSURE(contacts > min_contacts);
    ENSURE(a->direct > a->calls / 2 && b->direct == 0 && b->calls == a->calls);
    ENSURE(a->by_run ? a->runs > 0 : a->runs == 0);
    ENSURE(a->rn_differ == 0);
    ENSURE(b->runs == 0);
}

/* A sphere per place of a grid over the drum's lower half, alternating radii 2 and 1.5
 * mm and types 1 and 2, each at rest 0.1 mm into the mantle or above it. */
static void drum_particles(sim *s)
{
    memset(s, 0, sizeof *s);
    const double RC = 0.05;
    for (int i = 0; i < NP; i++) {
        const double R = i % 2 ? 0.0015 : 0.002;
        const double a = (i % 40 - 19.5) * 0.035; /* from the lowest point */
        const double rr = RC - R + (i / 40 == 0 ? 1e-4 : -(double)(i / 40) * 0.0045);
        s->x[i][0] = rr * sin(a);
        s->x[i][1] = -rr * cos(a);
        s->x[i][2] = ((i % 7) - 3) * 0.004;
        s->r[i] = R;
        s->m[i] = RHO * 4.0 / 3.0 * RS_PI * R * R * R;
        s->id[i] = i + 1;
        s->type[i] = 1 + i % 2;
    }
    s->g[1] = -9.81;
}

static const char *const DRUM[] = {
    "surface", "inline", "revolution", "origin",  "0",      "0",    "0",     "axis",
    "0",       "0",      "1",          "profile", "START",  "0.05", "-0.05", "LINE",
    "0.05",    "0.05",   "end",        "rotate",  "origin", "0",    "0",     "0",
    "axis",    "0",      "0",          "1",       "omega",  "3"};

static void test_drum_line_path_and_staged_bit_for_bit(void)
{
    for (int by_run = 0; by_run < 2; by_run++) {
        static sim a, b;
        drum_particles(&a);
        drum_particles(&b);
        a.by_run = b.by_run = by_run;
        rs_error e;
        const int n = (int)(sizeof DRUM / sizeof DRUM[0]);
        ENSURE(make(&a, DRUM, n, 0, &e) == RS_OK);
        ENSURE(make(&b, DRUM, n, 1, &e) == RS_OK);
        check_pair(&a, &b, "drum", 3000, 3000 * 40);
    }
}

/* The drum with a model that keeps its tangential spring in space and so reads no drot:
 * declared (RS_LAW_SKIPS_DROT) or not, its forces on the line path are the staged calls'
 * bit for bit. Undeclared, the slot of each particle's contact holds the frame of the
 * model's last call on it (what the next step's drot is made from), on the line path as
 * in the block call; declared, the line path leaves the slot's frame as the block call
 * stored it, so most contacts' slots (they move round with the drum) hold an older
 * frame. */
static void test_drum_frames_unless_the_law_skips_drot(void)
{
    for (int skips = 0; skips < 2; skips++) {
        static sim a, b;
        drum_particles(&a);
        drum_particles(&b);
        a.by_run = b.by_run = 1;
        a.skips_drot = skips;
        for (int i = 0; i < NP; i++)
            a.seen_at[i] = -1;
        rs_error e;
        const int n = (int)(sizeof DRUM / sizeof DRUM[0]);
        ENSURE(make(&a, DRUM, n, 0, &e) == RS_OK);
        ENSURE(make(&b, DRUM, n, 1, &e) == RS_OK);
        const long nsteps = 600;
        long contacts = 0;
        lockstep(&a, &b, nsteps, &contacts);
        /* a particle's record: its capacity, its row, its slots of n, t1 and the 4 state
         * variables */
        const int size = rs_wall_pack_size(a.w), hs = 6 + 4;
        double buf[1024];
        ENSURE(size <= 1024);
        int touched = 0, current = 0;
        for (int i = 0; i < NP && size <= 1024; i++) {
            if (a.seen_at[i] != nsteps - 1)
                continue;
            touched++;
            ENSURE(rs_wall_pack(a.w, i, buf) == size);
            const int cap = (int)buf[0], rs = size - 1 - cap * hs;
            for (int j = 0; j < cap; j++) {
                const double *h = buf + 1 + rs + j * hs;
                if (same_bits(h, a.seen_n[i], sizeof a.seen_n[i]) &&
                    same_bits(h + 3, a.seen_t1[i], sizeof a.seen_t1[i])) {
                    current++;
                    break;
                }
            }
        }
        printf(
            "drum, %s RS_LAW_SKIPS_DROT: %ld contacts, the line path's %ld calls of "
            "%ld; at the last step %d particles touch, %d slots hold that step's frame\n",
            skips ? "with" : "without", contacts, a.direct, a.calls, touched, current);
        rs_wall_free(a.w);
        rs_wall_free(b.w);
        ENSURE(contacts > nsteps * 30 && a.direct > a.calls / 2);
        ENSURE(touched >= 30);
        if (skips)
            ENSURE(current < touched / 2);
        else
            ENSURE(current == touched);
    }
}

/* A square plate z = 0 of side 0.1 m, two triangles along its diagonal, into path. */
static int write_plate(char *path, size_t cap)
{
    snprintf(path, cap, "/tmp/rs_test_force_line_%ld.stl", (long)getpid());
    FILE *f = fopen(path, "w");
    if (!f)
        return 0;
    fprintf(f, "solid plate\n");
    const double P[4][2] = {{-0.05, -0.05}, {0.05, -0.05}, {0.05, 0.05}, {-0.05, 0.05}};
    const int T[2][3] = {{0, 1, 2}, {0, 2, 3}};
    for (int t = 0; t < 2; t++) {
        fprintf(f, "facet normal 0 0 1\nouter loop\n");
        for (int k = 0; k < 3; k++)
            fprintf(f, "vertex %.17g %.17g 0\n", P[T[t][k]][0], P[T[t][k]][1]);
        fprintf(f, "endloop\nendfacet\n");
    }
    fprintf(f, "endsolid plate\n");
    return fclose(f) == 0;
}

/* Spheres on the plate, 0.05 mm into it, in a grid across the diagonal, under gravity
 * tilted by 25 degrees along x (they slide and roll), with spins. */
static void plate_particles(sim *s)
{
    memset(s, 0, sizeof *s);
    for (int i = 0; i < NP; i++) {
        const double R = i % 2 ? 0.0015 : 0.002;
        s->x[i][0] = -0.04 + (i % 16) * 0.005;
        s->x[i][1] = -0.04 + (i / 16) * 0.008;
        s->x[i][2] = R - 5e-5;
        s->om[i][2] = (i % 5 - 2) * 3.0;
        s->r[i] = R;
        s->m[i] = RHO * 4.0 / 3.0 * RS_PI * R * R * R;
        s->id[i] = i + 1;
        s->type[i] = 1 + i % 2;
    }
    s->g[0] = 9.81 * sin(25.0 * RS_PI / 180.0);
    s->g[2] = -9.81 * cos(25.0 * RS_PI / 180.0);
}

static void test_mesh_line_path_and_staged_bit_for_bit(void)
{
    char path[128];
    ENSURE(write_plate(path, sizeof path));
    const char *words[] = {"surface", "inline", "mesh", path, "move",
                           "linear",  "0.2",    "0",    "0"};
    for (int by_run = 0; by_run < 2; by_run++) {
        static sim a, b;
        plate_particles(&a);
        plate_particles(&b);
        a.by_run = b.by_run = by_run;
        rs_error e;
        const int ma = make(&a, words, 9, 0, &e), mb = make(&b, words, 9, 1, &e);
        ENSURE(ma == RS_OK && mb == RS_OK);
        if (ma == RS_OK && mb == RS_OK)
            check_pair(&a, &b, "plate", 1500, 1500 * NP / 2);
    }
    unlink(path);
}

/* A model that returns NaN for one particle: the step fails with the law's name, the
 * particle and what was not finite, and the engine's rows are as they were; likewise an
 * infinite torque alone. */
static void test_nan_stops_the_step(void)
{
    for (int v = 0; v < 5; v++) {
        /* the line path with the model per contact, with the run operation; staged; then
         * the infinite torque on the line path with the run operation, and staged */
        const int staged = v == 2 || v == 4;
        static sim s;
        drum_particles(&s);
        s.by_run = v == 1 || v == 3;
        s.inf_torque = v >= 3;
        rs_error e;
        const int n = (int)(sizeof DRUM / sizeof DRUM[0]);
        ENSURE(make(&s, DRUM, n, staged, &e) == RS_OK);
        rs_wall_load load;
        int rc = RS_OK;
        for (long k = 0; k < 50 && rc == RS_OK; k++)
            rc = step(&s, k, &load, &e);
        s.nan_at = 3;
        double f0[NP][3];
        for (int i = 0; i < NP; i++)
            for (int d = 0; d < 3; d++)
                f0[i][d] = s.f[i][d] = 7.0;
        rs_wall_block b = block_of(&s);
        rs_wall_rows rows;
        memset(&rows, 0, sizeof rows);
        rows.f = s.f[0], rows.torque = s.t[0];
        const long direct = s.direct, runs = s.runs;
        if (rc == RS_OK)
            rc = rs_wall_advance(s.w, DT, &e);
        const int step_rc = rc == RS_OK ? rs_wall_step(s.w, &b, &rows, DT, &load, &e) : rc;
        rs_wall_free(s.w);
        ENSURE(step_rc == RS_ERR_NONFINITE);
        ENSURE(strstr(e.msg, "law 'test'") && strstr(e.msg, "particle 3") &&
               strstr(e.msg, s.inf_torque ? "torque(3)" : "stress(1)"));
        ENSURE(same_bits(f0, s.f, sizeof f0));
        ENSURE(staged ? s.direct == direct : s.direct > direct);
        ENSURE(s.by_run ? s.runs > runs : s.runs == 0);
    }
}

int main(void)
{
    RS_RUN(test_drum_line_path_and_staged_bit_for_bit);
    RS_RUN(test_drum_frames_unless_the_law_skips_drot);
    RS_RUN(test_mesh_line_path_and_staged_bit_for_bit);
    RS_RUN(test_nan_stops_the_step);
    return rs_test_summary();
}
