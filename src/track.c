/* The contact tracker: contacts of a query -> VUINTER kinematics (rdisp, drdisp, drot)
 * with per-(particle, feature) history. Conventions: docs/conventions.md, "rdisp, drdisp,
 * drot"; slot layout: track.h.
 *
 * rs_track_update runs in two passes so that an input or capacity error leaves history
 * untouched (bar freeing slots an uncommitted call left LEAVING): pass 1 assigns a slot
 * to every contact, lists the leaving slots and checks the block order, pass 2 computes
 * the kinematics and writes the history (frame, slip, rdisp1). rs_track_commit
 * (track_history.c) adds the law's stress and statev and frees the leaving slots. */
#include "rigidsurf/track.h"
#include "rigidsurf/vec.h"

#include "rs_compiler.h"
#include "rs_v4.h"
#include "track_out.h"
#include "track_run.h"
#include "track_slots.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Pass 1 for the common case, from the directory d alone: a particle with at most one
 * contact within the tracking thickness (entry f = RS_DIR_LIVE(feature), or RS_DIR_EMPTY
 * for none) whose slot already holds it, and no other slot in use. Returns that slot's
 * index, cap for no contact and no slot in use, or -1, having written nothing, for every
 * other case (new contacts, handovers, leaving slots, a feature held twice), which
 * rs_track_assign_slots (track_slots.c) handles. */
static RS_NOINLINE int find_fast(const double *d, int cap, double f)
{
    /* Directory entries and f are whole numbers as doubles, never -0 or NaN, so
     * equality is equality of the bit patterns (integer compares). */
    const double empty = RS_DIR_EMPTY;
    uint64_t fb, eb;
    memcpy(&fb, &f, sizeof fb);
    memcpy(&eb, &empty, sizeof eb);
    int js = cap;
    for (int j = 0; j < cap; j++) {
        uint64_t u;
        memcpy(&u, d + j, sizeof u);
        if (u == eb)
            continue;
        if (u != fb || js < cap)
            return -1;
        js = j;
    }
    return RS_DIR_IS_LIVE(f) ? (js < cap ? js : -1) : cap;
}

/* find_fast for capacity 4, first testing the usual directory at once: the contact (f
 * live) in slot 0 and the other slots free, or no contact (f = RS_DIR_EMPTY) and every
 * slot free. */
RS_INLINE int find_fast4(const double *d, double f)
{
    if (rs_track_dir_usual(d, 4, f))
        return RS_DIR_IS_LIVE(f) ? 0 : 4;
    return find_fast(d, 4, f);
}

/* Pass 1 from particle i on, for as long as every particle takes the fast path
 * (find_fast): at most one contact, already held, nothing else in its directory. Fills
 * the entries, advances *kp past the contacts and *ne past the entries taken, and
 * returns the first particle that needs rs_track_assign_slots (np when none does). */
RS_INLINE int pass1_fast(int i, int np, int *kp, int nc, const int *restrict cpoint,
                         const int *restrict cfeat, const double *restrict cdist,
                         const double *restrict prad, double tracking,
                         double *const *restrict hist, double *const *restrict dir, int cap,
                         ptrdiff_t stride, int *restrict opoint, double **restrict oslot,
                         double **restrict odir, int *ne)
{
    int k = *kp, e = *ne;
    for (; i < np; i++) {
        const int has = k < nc && cpoint[k] == i;
        if ((k + has < nc && cpoint[k + has] == i) || !hist[i] || !dir[i])
            break;
        double f = RS_DIR_EMPTY;
        if (has && !(cdist[k] - (prad ? prad[i] : 0.0) > tracking))
            f = RS_DIR_LIVE(cfeat[k]);
        const int js = cap == 4 ? find_fast4(dir[i], f) : find_fast(dir[i], cap, f);
        if (js < 0)
            break;
        if (js < cap) {
            opoint[e] = k;
            oslot[e] = hist[i] + js * stride;
            odir[e++] = dir[i] + js;
        }
        k += has;
    }
    *kp = k;
    *ne = e;
    return i;
}

/* pass1_fast for a dense block: contact i names particle i for every i, one each.
 * Returns the first particle that needs rs_track_assign_slots (np when none does); *ne as
 * in pass1_fast, and the contacts taken are those of the particles before it. Out of line:
 * inlined into rs_track_update, its loop state would live on the stack. */
static RS_NOINLINE int
pass1_dense(int i, int np, const int *restrict cfeat, const double *restrict cdist,
            const double *restrict prad, double tracking, double *const *restrict hist,
            double *const *restrict dir, int cap, ptrdiff_t stride, int *restrict opoint,
            double **restrict oslot, double **restrict odir, int *ne)
{
    int e = *ne;
    if (cap == 4 && prad) {
        /* The usual call, in its own loop: held contact in slot 0, the others free. */
        for (; i < np; i++) {
            double *h = hist[i], *d = dir[i];
            if (!h || !d || cdist[i] - prad[i] > tracking ||
                !rs_track_dir_usual(d, 4, RS_DIR_LIVE(cfeat[i])))
                break;
            opoint[e] = i;
            oslot[e] = h;
            odir[e++] = d;
        }
    }
    for (; i < np; i++) {
        double *h = hist[i], *d = dir[i];
        if (!h || !d)
            break;
        const double f = cdist[i] - (prad ? prad[i] : 0.0) > tracking
                             ? RS_DIR_EMPTY
                             : RS_DIR_LIVE(cfeat[i]);
        const int js = cap == 4 ? find_fast4(d, f) : find_fast(d, cap, f);
        if (js < 0)
            break;
        if (js < cap) {
            opoint[e] = i;
            oslot[e] = h + js * stride;
            odir[e++] = d + js;
        }
    }
    *ne = e;
    return i;
}

static void put_frame(rs_track_out *o, int nd, int e, const double n[3], const double t1[3],
                      const double t2[3])
{
    for (int a = 0; a < nd; a++) {
        RS_A3(o->alocaldir, nd, a, 0, e) = n[a];
        RS_A3(o->alocaldir, nd, a, 1, e) = t1[a];
        if (nd == 3)
            RS_A3(o->alocaldir, nd, a, 2, e) = t2[a];
    }
}

/* Velocity of the particle's material point at xcp relative to the master's there. */
static inline void rel_velocity(const rs_particles *p, int i, const master_rates *mr,
                                const double xc[3], const double xcp[3], double vr[3])
{
    double r[3] = {xcp[0] - xc[0], xcp[1] - xc[1], xcp[2] - xc[2]};
    double rm[3] = {xcp[0] - mr->C[0], xcp[1] - mr->C[1], xcp[2] - mr->C[2]};
    double w[3] = {0, 0, 0}, wr[3], Wr[3];
    if (p->wx) {
        w[0] = p->wx[i];
        w[1] = p->wy[i];
        w[2] = p->wz[i];
    }
    rs_cross3(w, r, wr);
    rs_cross3(mr->W, rm, Wr);
    vr[0] = p->vx[i] + wr[0] - mr->V[0] - Wr[0];
    vr[1] = p->vy[i] + wr[1] - mr->V[1] - Wr[1];
    vr[2] = p->vz[i] + wr[2] - mr->V[2] - Wr[2];
}

/* A slot whose feature is gone: RS_MAXVAL in rdisp, drdisp and drot; the frame is the
 * stored one carried by Q (t2 = n x t1), the contact point the particle's surface point
 * along -n. */
static void emit_leaving(const rs_tracker *tr, const master_rates *mr,
                         const rs_particles *p, int i, rs_track_out *o, int e)
{
    const int nd = tr->ndir;
    double *h = o->slot[e];
    const double rad = p->radius ? p->radius[i] : 0.0;
    const double xc[3] = {p->x[i], p->y[i], p->z[i]};
    double n[3], t1[3], t2[3], xcp[3], vr[3];
    rs_matvec3(mr->Q, h + RS_H_N, n);
    rs_matvec3(mr->Q, h + RS_H_T1, t1);
    rs_cross3(n, t1, t2);
    if (p->body && p->body[i].shape) {
        const double down[3] = {-n[0], -n[1], -n[2]};
        rs_body_support(&p->body[i], down, xcp);
    } else {
        for (int b = 0; b < 3; b++)
            xcp[b] = xc[b] - rad * n[b];
    }
    rel_velocity(p, i, mr, xc, xcp, vr);

    if (mr->belt) {
        double u[3];
        rs_motion_belt_at(mr->m, n, u);
        for (int b = 0; b < 3; b++)
            vr[b] -= u[b];
    }

    const int f = RS_DIR_FEATURE(*o->dir[e]);
    *o->dir[e] = RS_DIR_LEAVING(f);
    o->point[e] = i;
    o->feature[e] = f;
    for (int b = 0; b < nd; b++) {
        RS_A2(o->rdisp, nd, b, e) = RS_MAXVAL;
        RS_A2(o->drdisp, nd, b, e) = RS_MAXVAL;
        RS_A2(o->coordslv, nd, b, e) = xcp[b];
        if (!(tr->drop & RS_DROP_COORDMST))
            RS_A2(o->coordmst, nd, b, e) = xcp[b];
    }
    for (int b = 0; b < 4; b++)
        o->drot[(size_t)e * 4 + b] = RS_MAXVAL;
    RS_A2(o->vrel, nd, 0, e) = rs_dot3(vr, n);
    RS_A2(o->vrel, nd, 1, e) = rs_dot3(vr, t1);
    if (nd == 3)
        RS_A2(o->vrel, nd, 2, e) = rs_dot3(vr, t2);
    put_frame(o, nd, e, n, t1, t2);
    RS_A2(o->curv, 2, 0, e) = 0.0;
    RS_A2(o->curv, 2, 1, e) = 0.0;
    o->share[e] = 1.0;
}

/* One run of pass 2: the m live contacts of entries e0 .. (contacts k0 .. of particles
 * i0 ..), their history, kinematics, outputs and stored history; sc: the next of
 * out->seeded, returned past this run's. */
RS_INLINE int emit_run(const rs_tracker *tr, const master_rates *mr, double dt,
                       const rs_particles *p, const rs_contacts *c, rs_track_out *out,
                       track_run *r, int e0, int m, int k0, int i0, int sc, const int nd,
                       const int lean, const int hs)
{
    const int nseeded = out->nseeded, *const seeded = out->seeded;
    run_gather(r, m, out, e0, lean, hs);
    const int s0 = sc; /* seeded entries of this run: live, from the copied slot */
    if (nseeded)
        for (; sc < nseeded && seeded[sc] < e0 + m; sc++)
            r->live[seeded[sc] - e0] = 1.0;
    if (c->witness && c->xs[0])
        run_kinematics(r, m, mr, dt, p, i0, c, k0, nd, mr->belt, 1, lean);
    else if (mr->belt)
        run_kinematics(r, m, mr, dt, p, i0, c, k0, nd, 1, 0, lean);
    else
        run_kinematics(r, m, mr, dt, p, i0, c, k0, nd, 0, 0, lean);
    for (int q = s0; q < sc; q++) { /* its own normal increment, as a new contact's */
        const int j = seeded[q] - e0;
        r->drd1[j] = -r->vn[j] * dt;
    }
    run_outputs(r, m, c, k0, out, e0, nd, !(tr->drop & RS_DROP_COORDMST));
    run_store(r->live, r->rd1, r->s1, r->s2, m, tr, c, k0, out, e0, lean, NULL, NULL);
    return sc;
}

/* Pass 2 over the ne entries of pass 1: runs of live contacts, leaving slots as they
 * come. ident: entry e is contact e of particle e for every e (no leaving slot), so the
 * runs are known without looking. */
RS_INLINE void emit_all(const rs_tracker *tr, const master_rates *mr, double dt,
                        const rs_particles *p, const rs_contacts *c, rs_track_out *out,
                        int ne, int ident, const int nd)
{
    track_run r;
    const int lean = (tr->drop & RS_DROP_SLIP) != 0, hs = rs_track_slot_size(tr);
    int e = 0, sc = 0; /* sc: the next of out->seeded */
    while (e < ne) {
        const int k0 = out->point[e];
        if (k0 < 0) {
            emit_leaving(tr, mr, p, -1 - k0, out, e);
            out->nleave++;
            e++;
            continue;
        }
        const int e0 = e, i0 = c->point[k0];
        int m = 0;
        if (ident) {
            m = ne - e < RS_TRACK_RUN ? ne - e : RS_TRACK_RUN;
            e += m;
        } else {
            while (e < ne && m < RS_TRACK_RUN && out->point[e] == k0 + m &&
                   c->point[k0 + m] == i0 + m) {
                m++;
                e++;
            }
        }
        /* a run of one (a sphere at a fold holds two contacts, each a run) in a copy of
         * its own, its loops gone */
        if (m == 1)
            sc = emit_run(tr, mr, dt, p, c, out, &r, e0, 1, k0, i0, sc, nd, lean, hs);
        else
            sc = emit_run(tr, mr, dt, p, c, out, &r, e0, m, k0, i0, sc, nd, lean, hs);
    }
}

/* out empty, with room for n entries. */
static int out_begin(rs_track_out *out, const rs_tracker *tr, int n, int shared,
                     rs_error *err)
{
    int rc = rs_track_out_reserve(out, n, err);
    if (rc)
        return rc;
    out->n = 0;
    out->nleave = 0;
    out->nseeded = 0;
    out->ndir = tr->ndir;
    out->shared = shared;
    return RS_OK;
}

/* The master's rates over the increment (m NULL: a fixed master). */
static void master_rates_of(const rs_motion *m, master_rates *mr)
{
    memset(mr, 0, sizeof *mr);
    if (m) {
        memcpy(mr->Q, m->dQ, sizeof mr->Q);
        rs_motion_field(m, mr->V, mr->W, mr->C);
        for (int b = 0; b < 3; b++)
            mr->U[b] = m->belt[b];
        mr->Umag = sqrt(rs_dot3(mr->U, mr->U));
        mr->belt = mr->Umag > 0.0;
        mr->m = m;
    } else {
        mr->Q[0] = mr->Q[4] = mr->Q[8] = 1.0;
    }
}

int rs_track_match(const rs_tracker *tr, const rs_surface *s, const rs_motion *m,
                   const rs_particles *p, const rs_contacts *c, rs_track_out *out,
                   master_rates *mr, int *ne_out, int *ident_out, rs_error *err)
{
    if (!tr || !p || !out)
        return rs_error_set(err, RS_ERR_ARG,
                            "rs_track_update: tracker, particles and "
                            "output must not be NULL");
    if (tr->ndir != 2 && tr->ndir != 3)
        return rs_error_set(err, RS_ERR_ARG, "rs_track_update: ndir = %d, expected 2 or 3",
                            tr->ndir);
    if (tr->capacity < 1 || tr->capacity > RS_TRACK_MAX_CAPACITY)
        return rs_error_set(err, RS_ERR_ARG,
                            "rs_track_update: capacity = %d, expected 1 to %d",
                            tr->capacity, RS_TRACK_MAX_CAPACITY);
    if (tr->nstatev < 0 || tr->nstatev > RS_MAX_STATEV)
        return rs_error_set(err, RS_ERR_ARG,
                            "rs_track_update: nstatev = %d, expected 0 to %d", tr->nstatev,
                            RS_MAX_STATEV);
    const int nc = c ? c->n : 0;
    int rc = out_begin(out, tr, nc + p->n * tr->capacity, c && c->share && c->shared, err);
    if (rc)
        return rc;
    /* Pass 1, grouping the contacts by particle: it takes every contact exactly when
     * they name points 0..n-1 in block order (checked here, not in a separate pass). */
    int ne = 0, k = 0;
    const int np = p->n, cap = tr->capacity;
    const ptrdiff_t stride = p->slot_stride ? p->slot_stride : rs_track_slot_size(tr);
    const double tracking = tr->tracking, *prad = p->radius;
    const int *cpoint = c ? c->point : NULL, *cfeat = c ? c->feature : NULL;
    const double *cdist = c ? c->dist : NULL;
    double *const *hist = p->hist, *const *dir = p->dir;
    /* The usual block: contact k names particle k, one each. */
    int dense = nc == np;
    if (dense) {
        int off = 0;
        for (int t = 0; t < nc; t++)
            off |= cpoint[t] ^ t;
        dense = off == 0;
    }
    int nslow = 0; /* particles rs_track_assign_slots took */
    for (int i = 0; i < np; i++) {
        if (dir && dense) {
            i = pass1_dense(i, np, cfeat, cdist, prad, tracking, hist, dir, cap, stride,
                            out->point, out->slot, out->dir, &ne);
            k = i;
        } else if (dir) {
            i = pass1_fast(i, np, &k, nc, cpoint, cfeat, cdist, prad, tracking, hist, dir,
                           cap, stride, out->point, out->slot, out->dir, &ne);
        }
        if (i == np)
            break;
        const int kb = k;
        while (k < nc && cpoint[k] == i)
            k++;
        rc = rs_track_assign_slots(tr, s, p, stride, c, i, kb, k, out, &ne, err);
        if (rc)
            return rc;
        nslow++;
    }
    /* Every particle on the fast path with its one contact: entry e is contact e. */
    *ident_out = dense && nslow == 0 && ne == nc;
    *ne_out = ne;
    if (k < nc) {
        for (k = 0; k < nc; k++) {
            int i = c->point[k];
            if (i < 0 || i >= p->n || (k > 0 && i < c->point[k - 1]))
                break;
        }
        return rs_error_set(err, RS_ERR_ARG,
                            "rs_track_update: contact %d names point %d; expected "
                            "points in 0..%d in block order",
                            k, c->point[k], p->n - 1);
    }

    master_rates_of(m, mr);
    return RS_OK;
}

int rs_track_match_usual(const rs_tracker *tr, const rs_motion *m, const rs_particles *p,
                         rs_track_out *out, master_rates *mr, rs_error *err)
{
    const int np = p->n;
    int rc = out_begin(out, tr, np, 0, err);
    if (rc)
        return rc;
    memcpy(out->slot, p->hist, (size_t)np * sizeof *out->slot);
    memcpy(out->dir, p->dir, (size_t)np * sizeof *out->dir);
    for (int e = 0; e < np; e++)
        out->point[e] = e;
    master_rates_of(m, mr);
    return RS_OK;
}

RS_MULTIVERSION
void rs_track_emit(const rs_tracker *tr, const master_rates *mr, double dt,
                   const rs_particles *p, const rs_contacts *c, rs_track_out *out, int ne,
                   int ident)
{
    out->nleave = 0;
    if (tr->ndir == 3)
        emit_all(tr, mr, dt, p, c, out, ne, ident, 3);
    else
        emit_all(tr, mr, dt, p, c, out, ne, ident, 2);
    out->n = ne;
}

int rs_track_update(const rs_tracker *tr, const rs_surface *s, const rs_motion *m,
                    double dt, const rs_particles *p, const rs_contacts *c,
                    rs_track_out *out, rs_error *err)
{
    master_rates mr;
    int ne = 0, ident = 0;
    const int rc = rs_track_match(tr, s, m, p, c, out, &mr, &ne, &ident, err);
    if (rc)
        return rc;
    rs_track_emit(tr, &mr, dt, p, c, out, ne, ident);
    return RS_OK;
}
