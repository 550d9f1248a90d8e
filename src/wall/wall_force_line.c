/* The line path's pass for a force law (RS_LAW_SETS_FORCE) with a model on a run of
 * contacts (rs_law.force_run) or per contact (rs_law.force_one): a run of spheres that
 * each hold their one contact, their face contacts given (wall_line.c), in one pass. The
 * run's contacts in columns (rs_force_run), their state variables copied out of the slots,
 * handed to the law's run operation, or to its model contact by contact as
 * rs_wall_force_contact describes a contact; the wall's sums; once every contact's force
 * and torque are finite, the slots (state variables, and the frame unless the law reads
 * none of what it gives, RS_LAW_SKIPS_DROT), the loads onto the engine's rows and the
 * per-particle rows, with the operations of the staged calls (rs_track_update,
 * rs_track_load, rs_cblock_inputs, the law's block call, rs_cblock_add_loads,
 * rs_track_commit), so that every number is theirs (the wall's sums, added in another
 * order, to rounding). A force, torque or stress that is NaN or Inf stops the call
 * before anything is written. */
#include "wall_impl.h"

#include "laws/builtin.h"
#include "load_contact.h"
#include "rs_v4.h"
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

/* What a run holds until every contact's model is through: the forces and torques as
 * rows of 3 (rs_force_run.F, T), then the stresses in columns. */
typedef struct force_run {
    double FT[2][3 * RS_TRACK_LINE_RUN];
    double S[3][RS_TRACK_LINE_RUN];
    double vw[3][RS_TRACK_LINE_RUN], rn[RS_TRACK_LINE_RUN];
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
    const double *F = fr->FT[0] + 3 * j, *T = fr->FT[1] + 3 * j;
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
        const double v = i < 3 ? F[i] : T[i - 3];
        if (!isfinite(v))
            return rs_law_nonfinite_error(w->law, id, c->feature[j], j, m, fname[i], v,
                                          err);
    }
    return RS_OK;
}

/* The state variables of m contacts, ns each, between the slots (at offset sv) and the
 * run's copy h: into h (in) or back (!in); the usual four without a loop's overhead. */
RS_INLINE void copy_statev(double *restrict h, double *const *slot, int sv, int ns, int m,
                           const int in)
{
    if (ns == 4) {
        /* four contacts an iteration */
        int j = 0;
        for (; j + 4 <= m; j += 4) {
            double *const *sl = slot + j;
            double *hj = h + 4 * j;
#ifdef RS_HAVE_V4
            rs_v4 v0, v1, v2, v3;
            if (in) {
                rs_v4_load(&v0, sl[0] + sv);
                rs_v4_load(&v1, sl[1] + sv);
                rs_v4_load(&v2, sl[2] + sv);
                rs_v4_load(&v3, sl[3] + sv);
                rs_v4_store(hj, &v0);
                rs_v4_store(hj + 4, &v1);
                rs_v4_store(hj + 8, &v2);
                rs_v4_store(hj + 12, &v3);
            } else {
                rs_v4_load(&v0, hj);
                rs_v4_load(&v1, hj + 4);
                rs_v4_load(&v2, hj + 8);
                rs_v4_load(&v3, hj + 12);
                rs_v4_store(sl[0] + sv, &v0);
                rs_v4_store(sl[1] + sv, &v1);
                rs_v4_store(sl[2] + sv, &v2);
                rs_v4_store(sl[3] + sv, &v3);
            }
#else
            for (int l = 0; l < 4; l++) {
                double *restrict d = in ? hj + 4 * l : sl[l] + sv;
                const double *restrict s = in ? sl[l] + sv : hj + 4 * l;
                d[0] = s[0], d[1] = s[1], d[2] = s[2], d[3] = s[3];
            }
#endif
        }
        for (; j < m; j++) {
            double *restrict d = in ? h + 4 * j : slot[j] + sv;
            const double *restrict s = in ? slot[j] + sv : h + 4 * j;
            d[0] = s[0], d[1] = s[1], d[2] = s[2], d[3] = s[3];
        }
        return;
    }
    for (int j = 0; j < m; j++) {
        double *restrict d = in ? h + (size_t)j * ns : slot[j] + sv;
        const double *restrict s = in ? slot[j] + sv : h + (size_t)j * ns;
        for (int k = 0; k < ns; k++)
            d[k] = s[k];
    }
}

/* d[0..2] += s[0..2]: the first two as one pair (the same additions). */
RS_INLINE void add3(double *restrict d, const double *restrict s)
{
#if defined(__GNUC__)
    typedef double pair __attribute__((vector_size(16)));
    pair a, b;
    memcpy(&a, d, sizeof a);
    memcpy(&b, s, sizeof b);
    a += b;
    memcpy(d, &a, sizeof a);
#else
    d[0] += s[0], d[1] += s[1];
#endif
    d[2] += s[2];
}

/* The frames (n, t1) of the run's contacts into their slots (unless the law reads none of
 * what they give: frame 0, RS_LAW_SKIPS_DROT), and the tracker's entries' features (their
 * points, j for contact j of sphere j, rs_track_match_usual gave): what run_store
 * (track_run.h) does for a slot of the frame and the state variables (RS_DROP_SLIP) whose
 * contact is held, as every contact of the run is, and whose directory entry already
 * names its feature, so that nothing else changes. */
RS_INLINE void store_frames(const rs_contacts *c, int m, rs_track_out *o, const int frame)
{
    memcpy(o->feature, c->feature, (size_t)m * sizeof *o->feature);
    if (!frame)
        return;
    const double *n0 = c->nrm[0], *n1 = c->nrm[1], *n2 = c->nrm[2];
    const double *a0 = c->t1[0], *a1 = c->t1[1], *a2 = c->t1[2];
    double *const *slot = o->slot;
    int j = 0;
    for (; j + 4 <= m; j += 4) {
        double *const *h = slot + j;
        rs_transpose4(n0 + j, n1 + j, n2 + j, a0 + j, h[0], h[1], h[2], h[3]);
        for (int l = 0; l < 4; l++)
            h[l][RS_H_T1 + 1] = a1[j + l], h[l][RS_H_T1 + 2] = a2[j + l];
    }
    for (; j < m; j++) {
        double *h = slot[j];
        h[RS_H_N] = n0[j], h[RS_H_N + 1] = n1[j], h[RS_H_N + 2] = n2[j];
        h[RS_H_T1] = a0[j], h[RS_H_T1 + 1] = a1[j], h[RS_H_T1 + 2] = a2[j];
    }
}

/* The wall's sums of a run's m contacts, -F and the moment -((x - o) x F + T) of each
 * about the wall's origin o, x the particle's centre (rs_load_force_law's, unit area), as
 * -(sum F) and -(sum (x - o) x F + sum T): four contacts at a time, the sums of F and T
 * over their rows as they lie, the moments from F's columns. */
RS_INLINE void wall_sums(const double *restrict F, const double *restrict T,
                         const double *restrict x, const double *restrict y,
                         const double *restrict z, const double o[3], int m,
                         rs_wall_acc *acc)
{
    const double o0 = o[0], o1 = o[1], o2 = o[2];
    double f[3] = {0.0, 0.0, 0.0}, t[3] = {0.0, 0.0, 0.0}, mo[3] = {0.0, 0.0, 0.0};
    int j = 0;
#ifdef RS_HAVE_V4
    const rs_v4 zero = {0.0, 0.0, 0.0, 0.0};
    rs_v4 sf[3] = {zero, zero, zero}, st[3] = {zero, zero, zero};
    rs_v4 sm0 = zero, sm1 = zero, sm2 = zero;
    for (; j + 4 <= m; j += 4) {
        /* rows (a0 b0 c0 a1) (b1 c1 a2 b2) (c2 a3 b3 c3) of F and T */
        rs_v4 r0, r1, r2, q;
        rs_v4_load(&r0, F + 3 * j);
        rs_v4_load(&r1, F + 3 * j + 4);
        rs_v4_load(&r2, F + 3 * j + 8);
        sf[0] += r0, sf[1] += r1, sf[2] += r2;
        for (int k = 0; k < 3; k++) {
            rs_v4_load(&q, T + 3 * j + 4 * k);
            st[k] += q;
        }
        const rs_v4 u = __builtin_shufflevector(r0, r1, 0, 3, 6, 5);   /* a0 a1 a2 c1 */
        const rs_v4 v = __builtin_shufflevector(r0, r1, 1, 4, 7, 2);   /* b0 b1 b2 c0 */
        const rs_v4 fx = __builtin_shufflevector(u, r2, 0, 1, 2, 5);   /* a0 a1 a2 a3 */
        const rs_v4 fy = __builtin_shufflevector(v, r2, 0, 1, 2, 6);   /* b0 b1 b2 b3 */
        const rs_v4 fz = __builtin_shufflevector(v, u, 3, 7, 0, 0);    /* c0 c1 */
        const rs_v4 fzz = __builtin_shufflevector(fz, r2, 0, 1, 4, 7); /* c0 c1 c2 c3 */
        rs_v4 rx, ry, rz;
        rs_v4_load(&rx, x + j);
        rs_v4_load(&ry, y + j);
        rs_v4_load(&rz, z + j);
        rx -= o0, ry -= o1, rz -= o2;
        sm0 += ry * fzz - rz * fy;
        sm1 += rz * fx - rx * fzz;
        sm2 += rx * fy - ry * fx;
    }
    /* a row's position p in its 12 holds component p mod 3 */
    f[0] = (sf[0][0] + sf[0][3]) + (sf[1][2] + sf[2][1]);
    f[1] = (sf[0][1] + sf[1][0]) + (sf[1][3] + sf[2][2]);
    f[2] = (sf[0][2] + sf[1][1]) + (sf[2][0] + sf[2][3]);
    t[0] = (st[0][0] + st[0][3]) + (st[1][2] + st[2][1]);
    t[1] = (st[0][1] + st[1][0]) + (st[1][3] + st[2][2]);
    t[2] = (st[0][2] + st[1][1]) + (st[2][0] + st[2][3]);
    mo[0] = (sm0[0] + sm0[1]) + (sm0[2] + sm0[3]);
    mo[1] = (sm1[0] + sm1[1]) + (sm1[2] + sm1[3]);
    mo[2] = (sm2[0] + sm2[1]) + (sm2[2] + sm2[3]);
#endif
    for (; j < m; j++) {
        const double *fj = F + 3 * j, *tj = T + 3 * j;
        const double r0 = x[j] - o0, r1 = y[j] - o1, r2 = z[j] - o2;
        f[0] += fj[0], f[1] += fj[1], f[2] += fj[2];
        t[0] += tj[0], t[1] += tj[1], t[2] += tj[2];
        mo[0] += r1 * fj[2] - r2 * fj[1];
        mo[1] += r2 * fj[0] - r0 * fj[2];
        mo[2] += r0 * fj[1] - r1 * fj[0];
    }
    acc->fw0 = -f[0], acc->fw1 = -f[1], acc->fw2 = -f[2];
    acc->mw0 = -(mo[0] + t[0]), acc->mw1 = -(mo[1] + t[1]), acc->mw2 = -(mo[2] + t[2]);
}

/* The run through a model per contact (rs_law.force_one), each contact described as
 * rs_wall_force_contact describes it. */
static int run_by_one(const rs_law *law, const rs_force_run *r, rs_error *err)
{
    rs_force_contact fc;
    fc.wall_type = r->wall_type;
    fc.setup = r->setup;
    const int ns = r->nstatev;
    /* the effective radius, computed again where the radius or the curvatures change
     * from the last contact's (rs_cblock_inputs's) */
    double last_R = NAN, last_k1 = NAN, last_k2 = NAN, reff = 0.0;
    for (int j = 0; j < r->n; j++) {
        fc.history = ns ? r->history + (size_t)j * (size_t)ns : NULL;
        fc.row = r->row[j];
        fc.overlap = r->overlap[j];
        fc.radius = r->radius[j];
        fc.mass = r->mass[j];
        fc.curv[0] = r->curv[0][j];
        fc.curv[1] = r->curv[1][j];
        if (!(fc.radius == last_R && fc.curv[0] == last_k1 && fc.curv[1] == last_k2)) {
            reff = rs_effective_radius(fc.radius, fc.curv[0], fc.curv[1]);
            last_R = fc.radius, last_k1 = fc.curv[0], last_k2 = fc.curv[1];
        }
        fc.reff = reff;
        for (int d = 0; d < 3; d++) {
            fc.n[d] = r->nrm[d][j], fc.t1[d] = r->t1[d][j], fc.t2[d] = r->t2[d][j];
            fc.xm[d] = r->xm[d][j];
            fc.vwall[d] = r->vwall[0] ? r->vwall[d][j] : r->vwall0[d];
        }
        fc.type = r->type ? r->type[fc.row] : 1;
        const int acts = law->force_one(law, &fc, r->F + 3 * j, r->T + 3 * j, err);
        if (acts < 0)
            return -acts;
        r->acts[j] = acts;
    }
    return RS_OK;
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
    int ncontact = 0;
    if (out6) {
        run_gather(&r, m, out, 0, 1, hs);
        run_kinematics(&r, m, &mr, dt, p, 0, c, 0, 3, 0, 0, 1);
        for (int j = 0; j < m; j++)
            ncontact += r.rd1[j] > 0.0;
    } else {
        for (int j = 0; j < m; j++) {
            const double rd1 = p->radius[j] - c->dist[j];
            r.rd1[j] = rd1;
            ncontact += rd1 > 0.0;
        }
    }

    /* the model on the run, its state in the run's copy of the slots */
    force_run fr;
    const rs_law *law = w->law;
    copy_statev(fr.hist, out->slot, sv, ns, m, 1);
    memset(fr.FT[0], 0, 3 * (size_t)m * sizeof fr.FT[0][0]);
    memset(fr.FT[1], 0, 3 * (size_t)m * sizeof fr.FT[1][0]);
    rs_force_run fx;
    fx.n = m;
    fx.row = p->row;
    fx.overlap = r.rd1;
    fx.radius = p->radius;
    fx.mass = p->mass;
    for (int d = 0; d < 3; d++) {
        fx.nrm[d] = c->nrm[d], fx.t1[d] = c->t1[d], fx.t2[d] = c->t2[d];
        fx.xm[d] = c->xm[d];
        fx.vwall[d] = NULL;
        fx.vwall0[d] = 0.0;
    }
    fx.curv[0] = c->curv[0], fx.curv[1] = c->curv[1];
    for (int j = 0; j < m; j++)
        fr.rn[j] = (p->x[j] - c->xm[0][j]) * c->nrm[0][j] +
                   (p->y[j] - c->xm[1][j]) * c->nrm[1][j] +
                   (p->z[j] - c->xm[2][j]) * c->nrm[2][j];
    fx.rn = fr.rn;
    /* the wall's velocity at xm, V + W x (xm - C), as rs_motion_velocity_at gives it */
    if (w->moving) {
        for (int j = 0; j < m; j++) {
            const double rc3[3] = {c->xm[0][j] - mr.C[0], c->xm[1][j] - mr.C[1],
                                   c->xm[2][j] - mr.C[2]};
            double wr[3];
            rs_cross3(mr.W, rc3, wr);
            for (int d = 0; d < 3; d++)
                fr.vw[d][j] = mr.V[d] + wr[d];
        }
        for (int d = 0; d < 3; d++)
            fx.vwall[d] = fr.vw[d];
    }
    fx.history = ns ? fr.hist : NULL;
    fx.nstatev = ns;
    fx.type = b->type;
    fx.wall_type = w->info.wall_type;
    fx.setup = 0;
    fx.F = fr.FT[0], fx.T = fr.FT[1];
    fx.acts = fr.acts;
    rc = law->force_run ? law->force_run(law, &fx, err) : run_by_one(law, &fx, err);
    if (rc)
        return rc;
    /* The wall's sums (each contact's moment about the wall's origin as rs_load_force_law
     * gives it, unit area), which also tell whether any force or torque is NaN or Inf:
     * a sum over values one of which is not finite is not finite (a finite sum that
     * overflows only makes the contacts be looked at one by one). Then the stresses as
     * rs_wall_force_result gives them (wall_force_stress; zeros where the model acts
     * not). */
    const double *const F = fr.FT[0], *const T = fr.FT[1];
    rs_wall_acc fm;
    wall_sums(F, T, p->x, p->y, p->z, origin, m, &fm);
    uint64_t acc = rs_nonfinite_bit(fm.fw0) | rs_nonfinite_bit(fm.fw1) |
                   rs_nonfinite_bit(fm.fw2) | rs_nonfinite_bit(fm.mw0) |
                   rs_nonfinite_bit(fm.mw1) | rs_nonfinite_bit(fm.mw2);
    if (out6)
        for (int j = 0; j < m; j++) {
            const double n[3] = {c->nrm[0][j], c->nrm[1][j], c->nrm[2][j]};
            const double a[3] = {c->t1[0][j], c->t1[1][j], c->t1[2][j]};
            const double t[3] = {c->t2[0][j], c->t2[1][j], c->t2[2][j]};
            double S[3] = {0.0, 0.0, 0.0};
            if (fr.acts[j])
                wall_force_stress(fr.FT[0] + 3 * j, n, a, t, S);
            for (int d = 0; d < 3; d++) {
                fr.S[d][j] = S[d];
                acc |= rs_nonfinite_bit(S[d]);
            }
        }
    for (int j = 0; (acc >> 63) && j < m; j++)
        if ((rc = check_contact(w, &fr, j, p->row, b->id, c, m, err)))
            return rc;

    /* every value is finite: the slots, the loads and the sums */
    out->nleave = 0;
    store_frames(c, m, out, !(law->skips & RS_LAW_SKIPS_DROT));
    copy_statev(fr.hist, out->slot, sv, ns, m, 0);
    out->n = m;
    /* the loads onto the engine's rows */
    const rs_load_rows lr = *rows;
    /* the engine's row of each contact: rows->row, or the run's own order */
    int idn[RS_TRACK_LINE_RUN];
    const int *rk = lr.row;
    if (!rk) {
        for (int j = 0; j < m; j++)
            idn[j] = j;
        rk = idn;
    }
    {
        int j = 0; /* two contacts an iteration, in their order */
        for (; j + 2 <= m; j += 2) {
            const size_t r0 = 3 * (size_t)rk[j], r1 = 3 * (size_t)rk[j + 1];
            add3(lr.f + r0, F + 3 * j);
            add3(lr.t + r0, T + 3 * j);
            add3(lr.f + r1, F + 3 * j + 3);
            add3(lr.t + r1, T + 3 * j + 3);
        }
        if (j < m) {
            add3(lr.f + 3 * (size_t)rk[j], F + 3 * j);
            add3(lr.t + 3 * (size_t)rk[j], T + 3 * j);
        }
    }
    if (lr.fstore)
        for (int j = 0; j < m; j++) {
            double *si = lr.fstore + 3 * (size_t)rk[j];
            const double *f = F + 3 * j;
            si[0] += f[0], si[1] += f[1], si[2] += f[2];
        }
    if (lr.deepest)
        for (int j = 0; j < m; j++)
            lr.deepest[j] = j;
    if (out6)
        for (int j = 0; j < m; j++) {
            double *o = out6 + 6 * (size_t)rk[j];
            o[0] = r.rd1[j], o[1] = r.s1[j], o[2] = r.s2[j];
            o[3] = fr.S[0][j], o[4] = fr.S[1][j], o[5] = fr.S[2][j];
        }
    wl->force[0] = fm.fw0, wl->force[1] = fm.fw1, wl->force[2] = fm.fw2;
    wl->moment[0] = fm.mw0, wl->moment[1] = fm.mw1, wl->moment[2] = fm.mw2;
    wl->se = wl->fd = wl->pd = wl->vd = wl->cd = 0.0;
    wl->flux_slv = wl->flux_mst = 0.0;
    wl->ncontact = ncontact;
    return RS_OK;
}
