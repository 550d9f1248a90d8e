/* The line path's pass for a force law (RS_LAW_SETS_FORCE) with a model per contact
 * (rs_law.force_one): a run of spheres that each hold their one contact, their face
 * contacts given (wall_line.c), in one pass. Per contact the model on the contact as
 * rs_wall_force_contact describes it, with the contact's state variables taken from its
 * slot; once every contact's force and torque are finite, the slots (frame and state
 * variables), the loads onto the engine's rows, the wall's sums and the per-particle
 * rows, with the operations of the staged calls (rs_track_update, rs_track_load,
 * rs_cblock_inputs, the law's block call, rs_cblock_add_loads, rs_track_commit), so that
 * every number is theirs. A force, torque or stress that is NaN or Inf stops the call
 * before anything is written. */
#include "wall_impl.h"

#include "laws/builtin.h"
#include "load_contact.h"
#include "track_fused.h"
#include "track_run.h"

#include "rigidsurf/vec.h"

#include <math.h>
#include <string.h>

int wall_force_line_takes(const rs_wall *w)
{
    const rs_tracker *tr = &w->tracker;
    /* a slot of the frame and the state variables alone (the slip, the stress and the
     * energies dropped), as the force laws' skips give it */
    const unsigned lean = RS_DROP_STRESS | RS_DROP_ENERGY | RS_DROP_SLIP;
    return (w->law->sets & RS_LAW_SETS_FORCE) && tr->ndir == 3 &&
           (tr->drop & lean) == lean && !(tr->drop & RS_DROP_COORDMST) &&
           tr->nstatev <= RS_FORCE_LINE_STATEV;
}

/* What a run holds until every contact's model is through. */
typedef struct force_run {
    double F[3][RS_TRACK_LINE_RUN], T[3][RS_TRACK_LINE_RUN], S[3][RS_TRACK_LINE_RUN];
    int acts[RS_TRACK_LINE_RUN];
    double hist[RS_TRACK_LINE_RUN * RS_FORCE_LINE_STATEV];
} force_run;

/* The first NaN or Inf of contact j's stress (wall_force_stress where the model acted, as
 * rs_wall_force_result gives it), force and torque, in the order rs_law_call looks for
 * them, or RS_OK. */
static int check_contact(const rs_wall *w, const force_run *fr, int j, const int *row,
                         const int *tag, const rs_contacts *c, int m, rs_error *err)
{
    static const char *const sname[3] = {"stress(1)", "stress(2)", "stress(3)"};
    static const char *const fname[6] = {"force(1)",  "force(2)",  "force(3)",
                                         "torque(1)", "torque(2)", "torque(3)"};
    const int id = tag ? tag[row[j]] : row[j] + 1;
    const double F[3] = {fr->F[0][j], fr->F[1][j], fr->F[2][j]};
    const double n[3] = {c->nrm[0][j], c->nrm[1][j], c->nrm[2][j]};
    const double a[3] = {c->t1[0][j], c->t1[1][j], c->t1[2][j]};
    const double b[3] = {c->t2[0][j], c->t2[1][j], c->t2[2][j]};
    double S[3] = {0.0, 0.0, 0.0};
    if (fr->acts[j])
        wall_force_stress(F, n, a, b, S);
    for (int i = 0; i < 3; i++)
        if (!isfinite(S[i]))
            return rs_law_nonfinite_error(w->law, id, c->feature[j], j, m, sname[i], S[i],
                                          err);
    for (int i = 0; i < 6; i++) {
        const double v = i < 3 ? F[i] : fr->T[i - 3][j];
        if (!isfinite(v))
            return rs_law_nonfinite_error(w->law, id, c->feature[j], j, m, fname[i], v,
                                          err);
    }
    return RS_OK;
}

/* A contact's state variables, n of them (the usual few without a loop's overhead). */
RS_INLINE void copy_statev(double *restrict d, const double *restrict s, int n)
{
    if (n == 4) {
        d[0] = s[0], d[1] = s[1], d[2] = s[2], d[3] = s[3];
        return;
    }
    for (int k = 0; k < n; k++)
        d[k] = s[k];
}

RS_MULTIVERSION
int wall_force_line_run(rs_wall *w, const rs_wall_block *b, const rs_motion *mp, double dt,
                        const rs_particle_block *p, const rs_contacts *c,
                        const double origin[3], const rs_load_rows *rows, rs_wall_load *wl,
                        rs_error *err)
{
    const int m = p->n;
    if (m > RS_TRACK_LINE_RUN || c->n != m || !c->xm[0] || !c->curv[0])
        return rs_error_set(err, RS_ERR_ARG,
                            "the line path's force pass: a run of %d spheres and %d "
                            "contacts with their master points and curvatures, at most %d",
                            m, c->n, RS_TRACK_LINE_RUN);
    const rs_tracker *tr = &w->tracker;
    rs_track_out *out = &w->tout;
    master_rates mr;
    int rc = rs_track_match_usual(tr, mp, p, out, &mr, err);
    if (rc)
        return rc;
    const int hs = rs_track_slot_size(tr), sv = rs_track_statev_at(tr), ns = tr->nstatev;
    double *const out6 = rows->out6;
    /* The tracker's kinematics, for the per-particle rows' rdisp(1:3) (the slip
     * increments of a slot without the slip); without those rows rdisp(1) alone. Every
     * contact is held (its slot is live). */
    track_run r;
    if (out6) {
        run_gather(&r, m, out, 0, 1, hs);
        run_kinematics(&r, m, &mr, dt, p, 0, c, 0, 3, 0, 0, 1);
    } else {
        for (int j = 0; j < m; j++)
            r.rd1[j] = p->radius[j] - c->dist[j];
    }
    for (int j = 0; j < m; j++)
        r.live[j] = 1.0;

    /* the model on each contact, its state in the run's copy of the slots */
    force_run fr;
    const rs_law *law = w->law;
    const int *type = b->type;
    rs_force_contact fc;
    fc.vwall[0] = fc.vwall[1] = fc.vwall[2] = 0.0;
    fc.wall_type = w->info.wall_type;
    fc.setup = 0;
    /* the wall's velocity at xm, V + W x (xm - C), as rs_motion_velocity_at gives it */
    const int moving = w->moving;
    /* the effective radius, computed again where the radius or the curvatures change
     * from the last contact's (rs_cblock_inputs's) */
    double last_R = NAN, last_k1 = NAN, last_k2 = NAN, reff = 0.0;
    uint64_t acc = 0;
    for (int j = 0; j < m; j++) {
        double *h = fr.hist + (size_t)j * (size_t)ns;
        copy_statev(h, out->slot[j] + sv, ns);
        fc.history = ns ? h : NULL;
        fc.row = p->row[j];
        fc.overlap = r.rd1[j];
        fc.radius = p->radius[j];
        fc.mass = p->mass[j];
        fc.curv[0] = c->curv[0][j];
        fc.curv[1] = c->curv[1][j];
        if (!(fc.radius == last_R && fc.curv[0] == last_k1 && fc.curv[1] == last_k2)) {
            reff = rs_effective_radius(fc.radius, fc.curv[0], fc.curv[1]);
            last_R = fc.radius, last_k1 = fc.curv[0], last_k2 = fc.curv[1];
        }
        fc.reff = reff;
        fc.n[0] = c->nrm[0][j], fc.n[1] = c->nrm[1][j], fc.n[2] = c->nrm[2][j];
        fc.t1[0] = c->t1[0][j], fc.t1[1] = c->t1[1][j], fc.t1[2] = c->t1[2][j];
        fc.t2[0] = c->t2[0][j], fc.t2[1] = c->t2[1][j], fc.t2[2] = c->t2[2][j];
        fc.xm[0] = c->xm[0][j], fc.xm[1] = c->xm[1][j], fc.xm[2] = c->xm[2][j];
        if (moving) {
            const double rc3[3] = {fc.xm[0] - mr.C[0], fc.xm[1] - mr.C[1],
                                   fc.xm[2] - mr.C[2]};
            double wr[3];
            rs_cross3(mr.W, rc3, wr);
            for (int d = 0; d < 3; d++)
                fc.vwall[d] = mr.V[d] + wr[d];
        }
        fc.type = type ? type[fc.row] : 1;
        double F[3] = {0.0, 0.0, 0.0}, T[3] = {0.0, 0.0, 0.0};
        const int acts = law->force_one(law, &fc, F, T, err);
        if (acts < 0)
            return -acts;
        fr.acts[j] = acts;
        fr.F[0][j] = F[0], fr.F[1][j] = F[1], fr.F[2][j] = F[2];
        fr.T[0][j] = T[0], fr.T[1][j] = T[1], fr.T[2][j] = T[2];
        acc |= rs_nonfinite_bit(F[0]) | rs_nonfinite_bit(F[1]) | rs_nonfinite_bit(F[2]) |
               rs_nonfinite_bit(T[0]) | rs_nonfinite_bit(T[1]) | rs_nonfinite_bit(T[2]);
        /* the stress as rs_wall_force_result gives it (wall_force_stress); zeros where the
         * model acts not */
        if (out6) {
            double S[3] = {0.0, 0.0, 0.0};
            if (acts)
                wall_force_stress(F, fc.n, fc.t1, fc.t2, S);
            for (int d = 0; d < 3; d++) {
                fr.S[d][j] = S[d];
                acc |= rs_nonfinite_bit(S[d]);
            }
        }
    }
    for (int j = 0; (acc >> 63) && j < m; j++)
        if ((rc = check_contact(w, &fr, j, p->row, b->id, c, m, err)))
            return rc;

    /* every value is finite: the slots, the loads and the sums */
    out->nleave = 0;
    run_store(r.live, r.rd1, r.s1, r.s2, m, tr, c, 0, out, 0, 1, NULL, NULL);
    for (int j = 0; j < m; j++)
        copy_statev(out->slot[j] + sv, fr.hist + (size_t)j * (size_t)ns, ns);
    out->n = m;
    rs_wall_acc fm = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    int ncontact = 0;
    for (int j = 0; j < m; j++) {
        const double f[3] = {fr.F[0][j], fr.F[1][j], fr.F[2][j]};
        const double t[3] = {fr.T[0][j], fr.T[1][j], fr.T[2][j]};
        const double ctr[3] = {p->x[j], p->y[j], p->z[j]};
        double Fo[3], To[3], M[3];
        rs_load_force_law(1.0, f, t, ctr, origin, Fo, To, M);
        rs_wall_acc_take(&fm, Fo, M);
        const int rk = rows->row ? rows->row[j] : j;
        rs_load_onto_row(rows, rk, Fo, To);
        ncontact += r.rd1[j] > 0.0;
        if (rows->deepest)
            rows->deepest[j] = j;
        if (out6) {
            double *o = out6 + 6 * (size_t)rk;
            o[0] = r.rd1[j], o[1] = r.s1[j], o[2] = r.s2[j];
            o[3] = fr.S[0][j], o[4] = fr.S[1][j], o[5] = fr.S[2][j];
        }
    }
    wl->force[0] = fm.fw0, wl->force[1] = fm.fw1, wl->force[2] = fm.fw2;
    wl->moment[0] = fm.mw0, wl->moment[1] = fm.mw1, wl->moment[2] = fm.mw2;
    wl->se = wl->fd = wl->pd = wl->vd = wl->cd = 0.0;
    wl->flux_slv = wl->flux_mst = 0.0;
    wl->ncontact = ncontact;
    return RS_OK;
}
