/* The hertz law's fused kernel (rs_law.fused; track_fused.h): a usual block, each sphere
 * holding one contact, in one pass. Per run of contacts the tracker's kinematics and
 * history (track_run.h) and the law on each contact (hertz_one, laws/hertz_kernel.h); once
 * every run's stress is finite, per run the history's store, each contact's force, torque
 * and moment in one loop, and the loads onto the engine's rows, the wall's sums and the
 * per-particle rows, in the order and with the operations of the staged calls
 * (rs_track_update, rs_track_load, rs_cblock_inputs, rs_cblock_call, rs_cblock_add_loads,
 * rs_track_commit), so that every number is theirs. A stress that is NaN or Inf stops the
 * call before anything is written. */
#include "hertz_kernel.h"
#include "load_contact.h"
#include "track_fused.h"

/* The slot of a tracker that takes the kernel: n, t1, then the law's 2 state variables at
 * the slip's place (RS_DROP_SLIP, RS_DROP_STRESS, RS_DROP_ENERGY). */
#define HERTZ_SLOT 8
_Static_assert(RS_H_N == 0 && RS_H_T1 == 3 && RS_H_SLIP == 6,
               "hertz's slot: n, t1, statev");

/* Runs a call holds until its laws are through. */
#define RUNS (RS_FUSED_MAX / RS_TRACK_RUN)
_Static_assert(RUNS *RS_TRACK_RUN == RS_FUSED_MAX, "whole runs");

static int hertz_takes(const rs_tracker *tr, const double *props, int nprops)
{
    const unsigned hertz_drop = RS_DROP_STRESS | RS_DROP_ENERGY | RS_DROP_SLIP;
    return nprops == P_COUNT && tr->ndir == 3 && tr->nstatev == 2 &&
           (tr->drop & hertz_drop) == hertz_drop && props[P_CURV] == 0.0;
}

/* The wall's sums over the block, in entry order (rs_cblock_add_loads's). */
typedef struct wall_sums {
    rs_wall_acc fm;
    double se, fd, vd;
    int ncontact;
} wall_sums;

/* What a run's store and loads read once the block's laws are through: of the law, its
 * state (in, then out), stress and energies; of the tracker, its columns live, rd1, s1, s2
 * and the contact points, in its run itself when the call is one run, else copied. */
typedef struct run_law_out {
    double sv[2][RS_TRACK_RUN], st[3][RS_TRACK_RUN];
    double sed[RS_TRACK_RUN], svd[RS_TRACK_RUN], sfd[RS_TRACK_RUN];
} run_law_out;

typedef struct run_kin {
    double live[RS_TRACK_RUN], rd1[RS_TRACK_RUN], s1[RS_TRACK_RUN], s2[RS_TRACK_RUN];
    double px[RS_TRACK_RUN], py[RS_TRACK_RUN], pz[RS_TRACK_RUN];
} run_kin;

typedef struct kin_cols {
    const double *live, *rd1, *s1, *s2, *px, *py, *pz;
} kin_cols;

/* The law on a run's m contacts, entries e0 .. e0+m-1 (contact and particle e), in one
 * loop (which vectorises): hertz's block loop on the run's kinematics, as the law block's
 * arrays would hand them to it (rdisp = (rd1, s1, s2), drdisp = (drd1, ds1, ds2), drot =
 * [[d11, -d21], [d21, d11]], vrel = (vn, v1, v2), unit areas). */
RS_INLINE void run_law(const track_run *restrict r, int m, int e0, const rs_particles *p,
                       double dt, double Yeff, double Geff, double beta, double mu,
                       run_law_out *restrict h)
{
    const double A = 1.0; /* the unit area's products, as the kernel's UNIT copy has them */
    const double *rad = p->radius + e0, *mass = p->mass + e0;
    for (int j = 0; j < m; j++) {
        double st[3], sk0, sk1;
        hertz_one(r->rd1[j], r->vn[j], r->v1[j], r->v2[j], h->sv[0][j], h->sv[1][j],
                  h->sv[1][j], r->d11[j], r->md21[j], r->d21[j], r->d11[j], r->ds1[j],
                  r->ds2[j], rad[j], mass[j], A, dt, Yeff, Geff, beta, mu, 3, 1, st,
                  &h->sed[j], &h->svd[j], &h->sfd[j], &sk0, &sk1);
        h->sv[0][j] = sk0, h->sv[1][j] = sk1;
        for (int d = 0; d < 3; d++)
            h->st[d][j] = st[d];
    }
}

/* The force of each contact's stress, its torque and its moment about the origin, as
 * rs_cblock_add_loads's kernel computes them for nDir 3 (one loop, which vectorises). */
RS_INLINE void run_forces(const kin_cols *k, const run_law_out *restrict h, int m, int e0,
                          const rs_contacts *c, const rs_particles *p,
                          const double origin[3], double F[3][RS_TRACK_RUN],
                          double T[3][RS_TRACK_RUN], double M[3][RS_TRACK_RUN])
{
    const double A = 1.0;
    const double *restrict px = k->px, *restrict py = k->py, *restrict pz = k->pz;
    for (int j = 0; j < m; j++) {
        const int e = e0 + j;
        const double L[9] = {c->nrm[0][e], c->nrm[1][e], c->nrm[2][e],
                             c->t1[0][e],  c->t1[1][e],  c->t1[2][e],
                             c->t2[0][e],  c->t2[1][e],  c->t2[2][e]};
        const double st[3] = {h->st[0][j], h->st[1][j], h->st[2][j]};
        double f[3], t[3], mo[3];
        rs_load_force3(A, st, L, f);
        const double x[3] = {px[j], py[j], pz[j]};
        const double ctr[3] = {p->x[e], p->y[e], p->z[e]};
        rs_load_torques(f, x, ctr, origin, t, mo);
        for (int d = 0; d < 3; d++)
            F[d][j] = f[d], T[d][j] = t[d], M[d][j] = mo[d];
    }
}

/* The wall's sums of a run, in entry order, and its loads onto the engine's and the
 * per-particle rows (rdisp(1:3) and stress(1:3)), as rs_cblock_add_loads's kernel adds
 * them (no leaving contact, a law without heat, creep or plastic dissipation). */
RS_INLINE void run_sums(const kin_cols *k, const run_law_out *restrict h, int m, int e0,
                        const rs_load_rows *rows, double F[3][RS_TRACK_RUN],
                        double T[3][RS_TRACK_RUN], double M[3][RS_TRACK_RUN], wall_sums *ws)
{
    const double A = 1.0;
    const int *row = rows->row;
    double *const out6 = rows->out6;
    for (int j = 0; j < m; j++) {
        const int e = e0 + j;
        const double f[3] = {F[0][j], F[1][j], F[2][j]};
        const double t[3] = {T[0][j], T[1][j], T[2][j]};
        const double mo[3] = {M[0][j], M[1][j], M[2][j]};
        rs_wall_acc_take(&ws->fm, f, mo);
        const int rk = row ? row[e] : e;
        rs_load_onto_row(rows, rk, f, t);
        ws->se += A * h->sed[j];
        ws->fd += A * h->sfd[j];
        ws->vd += A * h->svd[j];
        ws->ncontact += k->rd1[j] > 0.0;
        if (rows->deepest)
            rows->deepest[e] = e;
        if (out6) {
            double *o = out6 + 6 * (size_t)rk;
            o[0] = k->rd1[j], o[1] = k->s1[j], o[2] = k->s2[j];
            o[3] = h->st[0][j], o[4] = h->st[1][j], o[5] = h->st[2][j];
        }
    }
}

/* The first NaN or Inf of a run's stress as rs_law_call reports it (contact by contact,
 * stress(1) to stress(3)), or RS_OK: one branch-free pass over the run, and the search
 * only when it finds one. */
static int check_stress(const run_law_out *h, int m, int e0, const rs_particles *p,
                        const rs_contacts *c, int ne, rs_error *err)
{
    uint64_t acc = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < m; j++)
            acc |= rs_nonfinite_bit(h->st[i][j]);
    if (!(acc >> 63))
        return RS_OK;
    static const char *const sname[3] = {"stress(1)", "stress(2)", "stress(3)"};
    for (int j = 0; j < m; j++)
        for (int i = 0; i < 3; i++)
            if (!isfinite(h->st[i][j])) {
                const int k = e0 + j;
                return rs_law_nonfinite_error(&rs_law_hertz, p->id ? p->id[k] : k,
                                              c->feature[k], k, ne, sname[i], h->st[i][j],
                                              err);
            }
    return RS_OK;
}

RS_MULTIVERSION
static int hertz_pass(const rs_tracker *tr, const master_rates *mr, double dt,
                      const rs_particles *p, const rs_contacts *c, rs_track_out *out,
                      int ne, const double *props, const double origin[3],
                      const rs_load_rows *rows, rs_wall_load *w, rs_error *err)
{
    if (ne > RS_FUSED_MAX)
        return rs_error_set(err, RS_ERR_ARG,
                            "hertz's fused kernel: %d contacts, at most %d in one call", ne,
                            RS_FUSED_MAX);
    double Yeff, Geff, beta, mu;
    rs_hertz_constants(props, &Yeff, &Geff, &beta, &mu);
    track_run r;
    run_law_out law[RUNS];
    run_kin kin[RUNS]; /* the tracker's columns of a call of more runs than one */
    kin_cols cols[RUNS];
    const int one = ne <= RS_TRACK_RUN;
    /* the tracker and the law of every run: nothing written yet */
    for (int e0 = 0, q = 0; e0 < ne; e0 += RS_TRACK_RUN, q++) {
        const int m = ne - e0 < RS_TRACK_RUN ? ne - e0 : RS_TRACK_RUN;
        run_law_out *h = &law[q];
        /* the tracker (emit_all's run: entry, contact and particle e); the slot is n, t1
         * and the law's 2 state variables, whose state the gather brings along in so1,
         * so2 */
        run_gather(&r, m, out, e0, 1, HERTZ_SLOT);
        run_kinematics(&r, m, mr, dt, p, e0, c, e0, 3, 0, 0, 1);
        /* the law's state (zeros for a new contact, as run_store leaves its slot) */
        for (int j = 0; j < m; j++) {
            const int live = r.live[j] != 0.0;
            h->sv[0][j] = live ? r.so1[j] : 0.0;
            h->sv[1][j] = live ? r.so2[j] : 0.0;
        }
        run_law(&r, m, e0, p, dt, Yeff, Geff, beta, mu, h);
        const int rc = check_stress(h, m, e0, p, c, ne, err);
        if (rc)
            return rc;
        if (one) {
            cols[q] = (kin_cols){r.live, r.rd1, r.s1, r.s2, r.px, r.py, r.pz};
            continue;
        }
        run_kin *k = &kin[q];
        const size_t bytes = (size_t)m * sizeof(double);
        memcpy(k->live, r.live, bytes);
        memcpy(k->rd1, r.rd1, bytes);
        memcpy(k->s1, r.s1, bytes);
        memcpy(k->s2, r.s2, bytes);
        memcpy(k->px, r.px, bytes);
        memcpy(k->py, r.py, bytes);
        memcpy(k->pz, r.pz, bytes);
        cols[q] = (kin_cols){k->live, k->rd1, k->s1, k->s2, k->px, k->py, k->pz};
    }
    /* every stress is finite: the history, the loads and the sums, run by run */
    wall_sums ws = {{0.0, 0.0, 0.0, 0.0, 0.0, 0.0}, 0.0, 0.0, 0.0, 0};
    double F[3][RS_TRACK_RUN], T[3][RS_TRACK_RUN], M[3][RS_TRACK_RUN];
    out->nleave = 0;
    for (int e0 = 0, q = 0; e0 < ne; e0 += RS_TRACK_RUN, q++) {
        const int m = ne - e0 < RS_TRACK_RUN ? ne - e0 : RS_TRACK_RUN;
        const run_law_out *h = &law[q];
        const kin_cols *k = &cols[q];
        run_forces(k, h, m, e0, c, p, origin, F, T, M);
        run_store(k->live, k->rd1, k->s1, k->s2, m, tr, c, e0, out, e0, 1, h->sv[0],
                  h->sv[1]);
        run_sums(k, h, m, e0, rows, F, T, M, &ws);
    }
    out->n = ne;
    w->force[0] = ws.fm.fw0, w->force[1] = ws.fm.fw1, w->force[2] = ws.fm.fw2;
    w->moment[0] = ws.fm.mw0, w->moment[1] = ws.fm.mw1, w->moment[2] = ws.fm.mw2;
    w->se = ws.se, w->fd = ws.fd, w->pd = 0.0, w->vd = ws.vd, w->cd = 0.0;
    w->flux_slv = 0.0, w->flux_mst = 0.0;
    w->ncontact = ws.ncontact;
    return RS_OK;
}

const struct rs_law_fused rs_hertz_fused = {hertz_takes, hertz_pass, 1};
