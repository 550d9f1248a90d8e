/* The usual block in one pass (track_hertz.h): rs_track_update's pass 1, then per run of
 * contacts the tracker's kinematics and history (track_run.h), the hertz law's block loop
 * (laws/hertz_kernel.h) on the run, its state into the slots, and the loads onto the
 * engine's rows, the wall's sums and the per-atom rows, in the order and with the
 * operations of the staged calls (rs_track_update, rs_track_load, rs_cblock_inputs,
 * rs_cblock_call, rs_cblock_add_loads, rs_track_commit), so that every number is
 * theirs. */
#include "rigidsurf/track_hertz.h"

#include "laws/hertz_kernel.h"
#include "load_contact.h"
#include "track_run.h"

_Static_assert(RS_TRACK_LINE_RUN == RS_TRACK_RUN, "a caller's run is one run of the one pass");

int rs_track_hertz_takes(const rs_tracker *tr, const double *props)
{
    const unsigned hertz_drop = RS_DROP_STRESS | RS_DROP_ENERGY;
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

/* One run's law inputs in the law block's layout: rdisp(3, m), drdisp(3, m), drot(2, 2,
 * m), vrel(3, m), as run_outputs writes them. */
RS_INLINE void run_law_inputs(const track_run *restrict r, int m, double *restrict rd,
                              double *restrict drd, double *restrict dr,
                              double *restrict vr)
{
    put_cols(rd, m, 3, r->rd1, r->s1, r->s2);
    put_cols(drd, m, 3, r->drd1, r->ds1, r->ds2);
    put_cols(vr, m, 3, r->vn, r->v1, r->v2);
    for (int j = 0; j < m; j++) {
        dr[4 * j] = r->d11[j];
        dr[4 * j + 1] = r->d21[j];
        dr[4 * j + 2] = r->md21[j];
        dr[4 * j + 3] = r->d11[j];
    }
}

/* The wall's sums over the block, in entry order (rs_cblock_add_loads's). */
typedef struct wall_sums {
    rs_wall_acc fm;
    double se, fd, vd;
    int ncontact;
} wall_sums;

/* The loads of a run's m contacts, entries e0 .. e0+m-1 (contact and particle e): as
 * rs_cblock_add_loads's kernel computes them for nDir 3, unit areas, no leaving contact
 * and a law without heat, creep or plastic dissipation. Each contact's force, torque and
 * moment about the origin first, in a loop of its own (which vectorises); then, in entry
 * order, the wall's sums and the engine's and the per-atom rows. */
RS_INLINE void run_loads(const track_run *restrict r, int m, int e0, const rs_contacts *c,
                         const rs_particles *p, const double origin[3],
                         const rs_load_rows *rows, double *const *out6,
                         const double *restrict rd, const double *restrict st,
                         const double *restrict sed, const double *restrict sfd,
                         const double *restrict svd, wall_sums *ws)
{
    const double A = 1.0; /* the unit area's products, as the kernel's UNIT copy has them */
    double F[3][RS_TRACK_RUN], T[3][RS_TRACK_RUN], M[3][RS_TRACK_RUN];
    for (int j = 0; j < m; j++) {
        const int k = e0 + j;
        const double L[9] = {c->nrm[0][k], c->nrm[1][k], c->nrm[2][k],
                             c->t1[0][k],  c->t1[1][k],  c->t1[2][k],
                             c->t2[0][k],  c->t2[1][k],  c->t2[2][k]};
        double Fj[3], Tj[3], Mj[3];
        rs_load_force3(A, st + 3 * (size_t)j, L, Fj);
        const double x[3] = {r->px[j], r->py[j], r->pz[j]};
        const double ctr[3] = {p->x[k], p->y[k], p->z[k]};
        rs_load_torques(Fj, x, ctr, origin, Tj, Mj);
        for (int d = 0; d < 3; d++)
            F[d][j] = Fj[d], T[d][j] = Tj[d], M[d][j] = Mj[d];
    }
    const int *row = rows->row;
    for (int j = 0; j < m; j++) {
        const int k = e0 + j;
        const double Fj[3] = {F[0][j], F[1][j], F[2][j]};
        const double Tj[3] = {T[0][j], T[1][j], T[2][j]};
        const double Mj[3] = {M[0][j], M[1][j], M[2][j]};
        rs_wall_acc_take(&ws->fm, Fj, Mj);
        const int rk = row ? row[k] : k;
        rs_load_onto_row(rows, rk, Fj, Tj);
        ws->se += A * sed[j];
        ws->fd += A * sfd[j];
        ws->vd += A * svd[j];
        const double *rdj = rd + 3 * (size_t)j;
        ws->ncontact += rdj[0] > 0.0;
        if (rows->deepest)
            rows->deepest[k] = k;
        if (out6) {
            const double *s = st + 3 * (size_t)j;
            double *o = out6[rk];
            o[0] = rdj[0], o[1] = rdj[1], o[2] = rdj[2];
            o[3] = s[0], o[4] = s[1], o[5] = s[2];
        }
    }
}

/* The first NaN or Inf of a run's stress(3, m) as rs_law_call reports it, or RS_OK: one
 * branch-free pass over the run, and the search only when it finds one. */
static int check_stress(const double *st, int m, int e0, const rs_particles *p,
                        const rs_contacts *c, int ne, rs_error *err)
{
    uint64_t acc = 0;
    for (int i = 0; i < 3 * m; i++)
        acc |= rs_nonfinite_bit(st[i]);
    if (!(acc >> 63))
        return RS_OK;
    static const char *const sname[3] = {"stress(1)", "stress(2)", "stress(3)"};
    for (int j = 0; j < m; j++)
        for (int i = 0; i < 3; i++)
            if (!isfinite(st[3 * j + i])) {
                const int k = e0 + j;
                return rs_law_nonfinite_error(&rs_law_hertz, p->id ? p->id[k] : k,
                                              c->feature[k], k, ne, sname[i], st[3 * j + i],
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
    const int sv0 = rs_track_statev_at(tr);
    static const double unit[RS_TRACK_RUN] = {
        1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0,
        1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0};
    _Static_assert(RS_TRACK_RUN == 32, "unit holds one run of areas");
    wall_sums ws = {{0.0, 0.0, 0.0, 0.0, 0.0, 0.0}, 0.0, 0.0, 0.0, 0};
    track_run r;
    double rd[3 * RS_TRACK_RUN], drd[3 * RS_TRACK_RUN], dr[4 * RS_TRACK_RUN],
        vr[3 * RS_TRACK_RUN], st[3 * RS_TRACK_RUN], sv[2 * RS_TRACK_RUN];
    double sed[RS_TRACK_RUN], svd[RS_TRACK_RUN], sfd[RS_TRACK_RUN];
    out->nleave = 0;
    for (int e0 = 0; e0 < ne; e0 += RS_TRACK_RUN) {
        const int m = ne - e0 < RS_TRACK_RUN ? ne - e0 : RS_TRACK_RUN;
        /* the tracker (emit_all's run: entry, contact and particle e) */
        run_gather(&r, m, out, e0);
        run_kinematics(&r, m, mr, dt, p, e0, c, e0, 3, 0, 0);
        run_store(&r, m, tr, c, e0, out, e0);
        /* the law on the run, its state from the slots (zeros for a new contact) */
        run_law_inputs(&r, m, rd, drd, dr, vr);
        for (int j = 0; j < m; j++) {
            const double *h = out->slot[e0 + j] + sv0;
            sv[2 * j] = h[0];
            sv[2 * j + 1] = h[1];
        }
        hertz_block(m, 2, dt, rd, drd, dr, vr, p->radius + e0, p->mass + e0, unit, st, sv,
                    sed, svd, sfd, Yeff, Geff, beta, mu, 3, 1);
        const int rc = check_stress(st, m, e0, p, c, ne, err);
        if (rc)
            return rc;
        for (int j = 0; j < m; j++) {
            double *h = out->slot[e0 + j] + sv0;
            h[0] = sv[2 * j];
            h[1] = sv[2 * j + 1];
        }
        run_loads(&r, m, e0, c, p, origin, rows, out6, rd, st, sed, sfd, svd, &ws);
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
