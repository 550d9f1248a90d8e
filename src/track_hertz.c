/* The usual block in one pass (track_hertz.h): rs_track_update's pass 1, then per run of
 * contacts the tracker's kinematics and history (track_run.h), the hertz law on each
 * contact (hertz_one, laws/hertz_kernel.h) and its force, torque and moment in one loop,
 * its state into the slots, and the loads onto the engine's rows, the wall's sums and the
 * per-atom rows, in the order and with the operations of the staged calls
 * (rs_track_update, rs_track_load, rs_cblock_inputs, rs_cblock_call, rs_cblock_add_loads,
 * rs_track_commit), so that every number is theirs. */
#include "rigidsurf/track_hertz.h"

#include "laws/hertz_kernel.h"
#include "load_contact.h"
#include "track_run.h"

_Static_assert(RS_TRACK_LINE_RUN == RS_TRACK_RUN,
               "a caller's run is one run of the one pass");

/* The slot of a tracker that takes the one pass: n, t1, then the law's 2 state variables
 * at the slip's place (RS_DROP_SLIP, RS_DROP_STRESS, RS_DROP_ENERGY). */
#define HERTZ_SLOT 8
_Static_assert(RS_H_N == 0 && RS_H_T1 == 3 && RS_H_SLIP == 6,
               "hertz's slot: n, t1, statev");

int rs_track_hertz_takes(const rs_tracker *tr, const double *props)
{
    const unsigned hertz_drop = RS_DROP_STRESS | RS_DROP_ENERGY | RS_DROP_SLIP;
    return tr->ndir == 3 && tr->nstatev == 2 && (tr->drop & hertz_drop) == hertz_drop &&
           props[P_CURV] == 0.0;
}

/* Whether the block takes the one pass: see track_hertz.h. */
static int qualifies(const rs_tracker *tr, const master_rates *mr, const rs_particles *p,
                     const rs_contacts *c, const rs_track_out *out, const double *props,
                     int ident)
{
    return ident && rs_track_hertz_takes(tr, props) && !mr->belt && p->radius && p->mass &&
           !p->body && !(c->witness && c->xs[0]) && !out->shared && out->nseeded == 0;
}

/* The wall's sums over the block, in entry order (rs_cblock_add_loads's). */
typedef struct wall_sums {
    rs_wall_acc fm;
    double se, fd, vd;
    int ncontact;
} wall_sums;

/* A run's law outputs and loads, by column. */
typedef struct run_law {
    double sv[2][RS_TRACK_RUN]; ///< the law's state: in, then out
    double st[3][RS_TRACK_RUN], sed[RS_TRACK_RUN], svd[RS_TRACK_RUN], sfd[RS_TRACK_RUN];
    double F[3][RS_TRACK_RUN], T[3][RS_TRACK_RUN], M[3][RS_TRACK_RUN];
} run_law;

/* The law and the loads of a run's m contacts, entries e0 .. e0+m-1 (contact and particle
 * e), in one loop (which vectorises): hertz's block loop on the run's kinematics, as the
 * law block's arrays would hand them to it (rdisp = (rd1, s1, s2), drdisp = (drd1, ds1,
 * ds2), drot = [[d11, -d21], [d21, d11]], vrel = (vn, v1, v2), unit areas), and the force
 * of its stress, its torque and its moment about the origin as rs_cblock_add_loads's
 * kernel computes them for nDir 3. */
RS_INLINE void run_law_loads(const track_run *restrict r, int m, int e0,
                             const rs_contacts *c, const rs_particles *p,
                             const double origin[3], double dt, double Yeff, double Geff,
                             double beta, double mu, run_law *restrict q)
{
    const double A = 1.0; /* the unit area's products, as the kernel's UNIT copy has them */
    const double *rad = p->radius + e0, *mass = p->mass + e0;
    for (int j = 0; j < m; j++) {
        const int k = e0 + j;
        double st[3], sk0, sk1;
        hertz_one(r->rd1[j], r->vn[j], r->v1[j], r->v2[j], q->sv[0][j], q->sv[1][j],
                  q->sv[1][j], r->d11[j], r->md21[j], r->d21[j], r->d11[j], r->ds1[j],
                  r->ds2[j], rad[j], mass[j], A, dt, Yeff, Geff, beta, mu, 3, 1, st,
                  &q->sed[j], &q->svd[j], &q->sfd[j], &sk0, &sk1);
        q->sv[0][j] = sk0, q->sv[1][j] = sk1;
        const double L[9] = {c->nrm[0][k], c->nrm[1][k], c->nrm[2][k],
                             c->t1[0][k],  c->t1[1][k],  c->t1[2][k],
                             c->t2[0][k],  c->t2[1][k],  c->t2[2][k]};
        double F[3], T[3], M[3];
        rs_load_force3(A, st, L, F);
        const double x[3] = {r->px[j], r->py[j], r->pz[j]};
        const double ctr[3] = {p->x[k], p->y[k], p->z[k]};
        rs_load_torques(F, x, ctr, origin, T, M);
        for (int d = 0; d < 3; d++)
            q->st[d][j] = st[d], q->F[d][j] = F[d], q->T[d][j] = T[d], q->M[d][j] = M[d];
    }
}

/* The wall's sums of a run, in entry order, and its loads onto the engine's and the
 * per-atom rows (rdisp(1:3) and stress(1:3)), as rs_cblock_add_loads's kernel adds them
 * (no leaving contact, a law without heat, creep or plastic dissipation). */
RS_INLINE void run_sums(const track_run *restrict r, int m, int e0,
                        const rs_load_rows *rows, double *const *out6,
                        const run_law *restrict q, wall_sums *ws)
{
    const double A = 1.0;
    const int *row = rows->row;
    for (int j = 0; j < m; j++) {
        const int k = e0 + j;
        const double F[3] = {q->F[0][j], q->F[1][j], q->F[2][j]};
        const double T[3] = {q->T[0][j], q->T[1][j], q->T[2][j]};
        const double M[3] = {q->M[0][j], q->M[1][j], q->M[2][j]};
        rs_wall_acc_take(&ws->fm, F, M);
        const int rk = row ? row[k] : k;
        rs_load_onto_row(rows, rk, F, T);
        ws->se += A * q->sed[j];
        ws->fd += A * q->sfd[j];
        ws->vd += A * q->svd[j];
        ws->ncontact += r->rd1[j] > 0.0;
        if (rows->deepest)
            rows->deepest[k] = k;
        if (out6) {
            double *o = out6[rk];
            o[0] = r->rd1[j], o[1] = r->s1[j], o[2] = r->s2[j];
            o[3] = q->st[0][j], o[4] = q->st[1][j], o[5] = q->st[2][j];
        }
    }
}

/* The first NaN or Inf of a run's stress as rs_law_call reports it (contact by contact,
 * stress(1) to stress(3)), or RS_OK: one branch-free pass over the run, and the search
 * only when it finds one. */
static int check_stress(const run_law *q, int m, int e0, const rs_particles *p,
                        const rs_contacts *c, int ne, rs_error *err)
{
    uint64_t acc = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < m; j++)
            acc |= rs_nonfinite_bit(q->st[i][j]);
    if (!(acc >> 63))
        return RS_OK;
    static const char *const sname[3] = {"stress(1)", "stress(2)", "stress(3)"};
    for (int j = 0; j < m; j++)
        for (int i = 0; i < 3; i++)
            if (!isfinite(q->st[i][j])) {
                const int k = e0 + j;
                return rs_law_nonfinite_error(&rs_law_hertz, p->id ? p->id[k] : k,
                                              c->feature[k], k, ne, sname[i], q->st[i][j],
                                              err);
            }
    return RS_OK;
}

RS_MULTIVERSION
static int one_pass(const rs_tracker *tr, const master_rates *mr, double dt,
                    const rs_particles *p, const rs_contacts *c, rs_track_out *out, int ne,
                    const double *props, const double origin[3], const rs_load_rows *rows,
                    double *const *out6, rs_wall_load *w, rs_error *err)
{
    double Yeff, Geff, beta, mu;
    rs_hertz_constants(props, &Yeff, &Geff, &beta, &mu);
    wall_sums ws = {{0.0, 0.0, 0.0, 0.0, 0.0, 0.0}, 0.0, 0.0, 0.0, 0};
    track_run r;
    run_law q;
    out->nleave = 0;
    for (int e0 = 0; e0 < ne; e0 += RS_TRACK_RUN) {
        const int m = ne - e0 < RS_TRACK_RUN ? ne - e0 : RS_TRACK_RUN;
        /* the tracker (emit_all's run: entry, contact and particle e); the slot is n, t1
         * and the law's 2 state variables (RS_DROP_SLIP, RS_DROP_STRESS, RS_DROP_ENERGY:
         * rs_track_hertz_takes), whose state the gather brings along in so1, so2 */
        run_gather(&r, m, out, e0, 1, HERTZ_SLOT);
        run_kinematics(&r, m, mr, dt, p, e0, c, e0, 3, 0, 0, 1);
        /* the law's state (zeros for a new contact, as run_store leaves its slot), the
         * law and the loads */
        for (int j = 0; j < m; j++) {
            const int live = r.live[j] != 0.0;
            q.sv[0][j] = live ? r.so1[j] : 0.0;
            q.sv[1][j] = live ? r.so2[j] : 0.0;
        }
        run_law_loads(&r, m, e0, c, p, origin, dt, Yeff, Geff, beta, mu, &q);
        const int rc = check_stress(&q, m, e0, p, c, ne, err);
        if (rc)
            return rc;
        run_store(&r, m, tr, c, e0, out, e0, 1, q.sv[0], q.sv[1]);
        run_sums(&r, m, e0, rows, out6, &q, &ws);
    }
    out->n = ne;
    w->force[0] = ws.fm.fw0, w->force[1] = ws.fm.fw1, w->force[2] = ws.fm.fw2;
    w->moment[0] = ws.fm.mw0, w->moment[1] = ws.fm.mw1, w->moment[2] = ws.fm.mw2;
    w->se = ws.se, w->fd = ws.fd, w->pd = 0.0, w->vd = ws.vd, w->cd = 0.0;
    w->flux_slv = 0.0, w->flux_mst = 0.0;
    w->ncontact = ws.ncontact;
    return RS_OK;
}

int rs_track_hertz(const rs_tracker *tr, const rs_surface *s, const rs_motion *m, double dt,
                   const rs_particles *p, const rs_contacts *c, rs_track_out *out,
                   const double *props, const double origin[3], const rs_load_rows *rows,
                   double *const *out6, rs_wall_load *w, int *done, rs_error *err)
{
    *done = 0;
    master_rates mr;
    int ne = 0, ident = 0;
    int rc = rs_track_match(tr, s, m, p, c, out, &mr, &ne, &ident, err);
    if (rc)
        return rc;
    if (!c || !qualifies(tr, &mr, p, c, out, props, ident)) {
        rs_track_emit(tr, &mr, dt, p, c, out, ne, ident);
        return RS_OK;
    }
    rc = one_pass(tr, &mr, dt, p, c, out, ne, props, origin, rows, out6, w, err);
    if (rc == RS_OK)
        *done = 1;
    return rc;
}

int rs_track_hertz_usual(const rs_tracker *tr, const rs_motion *m, double dt,
                         const rs_particles *p, const rs_contacts *c, rs_track_out *out,
                         const double *props, const double origin[3],
                         const rs_load_rows *rows, double *const *out6, rs_wall_load *w,
                         rs_error *err)
{
    if (!tr || !p || !c || !out || !props || c->n != p->n)
        return rs_error_set(err, RS_ERR_ARG,
                            "rs_track_hertz_usual: expected a block with one contact per "
                            "particle");
    int off = 0;
    for (int k = 0; k < c->n; k++)
        off |= c->point[k] ^ k;
    if (off)
        return rs_error_set(err, RS_ERR_ARG,
                            "rs_track_hertz_usual: contact k must name particle k");
    master_rates mr;
    int rc = rs_track_match_usual(tr, m, p, out, &mr, err);
    if (rc)
        return rc;
    if (!qualifies(tr, &mr, p, c, out, props, 1))
        return rs_error_set(err, RS_ERR_ARG,
                            "rs_track_hertz_usual: the block does not take the one pass "
                            "(a surface velocity, bodies, no radius or mass, or a tracker "
                            "or properties other than hertz's)");
    return one_pass(tr, &mr, dt, p, c, out, p->n, props, origin, rows, out6, w, err);
}
