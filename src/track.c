/* The contact tracker: contacts of a query -> VUINTER kinematics (rdisp, drdisp, drot)
 * with per-(particle, feature) history. Conventions: ARCHITECTURE.md, "rdisp, drdisp,
 * drot"; slot layout: track.h.
 *
 * rs_track_update runs in two passes so that an input or capacity error leaves history
 * untouched (bar freeing slots an uncommitted call left LEAVING): pass 1 assigns a slot
 * to every contact, lists the leaving slots and checks the block order, pass 2 computes
 * the kinematics and writes the history (frame, slip, rdisp1). rs_track_commit adds the
 * law's stress and statev and frees the leaving slots. */
#include "rigidsurf/track.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

void rs_track_out_free(rs_track_out *o)
{
    free(o->point);
    free(o->feature);
    free(o->slot);
    free(o->rdisp);
    free(o->drdisp);
    free(o->drot);
    free(o->alocaldir);
    free(o->coordslv);
    free(o->coordmst);
    free(o->vrel);
    free(o->curv);
    memset(o, 0, sizeof *o);
}

static int grow(void **p, size_t bytes)
{
    void *q = realloc(*p, bytes);
    if (!q)
        return 0;
    *p = q;
    return 1;
}

/* Arrays are sized for ndir = 3 so a change of ndir never needs a reallocation. */
static int out_reserve(rs_track_out *o, int n, rs_error *err)
{
    if (n <= o->cap)
        return RS_OK;
    size_t c = (size_t)n, d = sizeof(double);
    int ok =
        grow((void **)&o->point, c * sizeof(int)) &&
        grow((void **)&o->feature, c * sizeof(int)) &&
        grow((void **)&o->slot, c * sizeof(double *)) &&
        grow((void **)&o->rdisp, 3 * c * d) && grow((void **)&o->drdisp, 3 * c * d) &&
        grow((void **)&o->drot, 4 * c * d) && grow((void **)&o->alocaldir, 9 * c * d) &&
        grow((void **)&o->coordslv, 3 * c * d) && grow((void **)&o->coordmst, 3 * c * d) &&
        grow((void **)&o->vrel, 3 * c * d) && grow((void **)&o->curv, 2 * c * d);
    if (!ok)
        return rs_error_set(err, RS_ERR_NOMEM,
                            "rs_track_update: out of memory for %d contacts", n);
    o->cap = n;
    return RS_OK;
}

static inline double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline void cross3(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

static inline void matvec(const double Q[9], const double v[3], double r[3])
{
    r[0] = Q[0] * v[0] + Q[1] * v[1] + Q[2] * v[2];
    r[1] = Q[3] * v[0] + Q[4] * v[1] + Q[5] * v[2];
    r[2] = Q[6] * v[0] + Q[7] * v[1] + Q[8] * v[2];
}

#if defined(__GNUC__)
#define RS_INLINE static inline __attribute__((always_inline))
#else
#define RS_INLINE static inline
#endif

/* Below this value of 1 + a.b the normal has turned by ~180 deg and a.b x stops defining
 * an axis; the minimal rotation is then the half turn about the carried t1. */
#define RS_ANTIPARALLEL 1e-12

/* Pass 1 for one particle: slots for its contacts kb..ke-1 (written to out entries from
 * *ne on) and its leaving slots. out->point holds the contact index for a contact entry
 * and -1 - i for a leaving slot of particle i until pass 2 decodes it. */
static int assign_slots(const rs_tracker *tr, const rs_surface *s, const rs_particles *p,
                        const rs_contacts *c, int i, int kb, int ke, rs_track_out *out,
                        int *ne, rs_error *err)
{
    const int cap = tr->capacity, hs = RS_HIST_SIZE(tr->nstatev);
    double *h = p->hist[i];
    if (!h)
        return rs_error_set(err, RS_ERR_ARG,
                            "rs_track_update: particle %d has no history storage",
                            p->id ? p->id[i] : i);
    const double rad = p->radius ? p->radius[i] : 0.0;
    int kk[RS_TRACK_MAX_CAPACITY], sl[RS_TRACK_MAX_CAPACITY], fe[RS_TRACK_MAX_CAPACITY];
    int nk = 0, unmatched = 0;
    uint64_t active = 0, used = 0;

    /* One look at the slots: live features (fe[j] is valid where active has bit j);
     * slots left LEAVING by an uncommitted call are freed (they were emitted once). */
    for (int j = 0; j < cap; j++) {
        double *hj = h + (size_t)j * hs;
        if (hj[RS_H_STATE] == RS_HSTATE_ACTIVE) {
            active |= (uint64_t)1 << j;
            fe[j] = (int)hj[RS_H_FEATURE];
        } else if (hj[RS_H_STATE] == RS_HSTATE_LEAVING) {
            hj[RS_H_STATE] = RS_HSTATE_EMPTY;
            hj[RS_H_FEATURE] = RS_FEATURE_NONE;
        }
    }

    for (int k = kb; k < ke; k++) {
        if (c->dist[k] - rad > tr->tracking)
            continue;
        if (nk == cap)
            goto full;
        int f = c->feature[k], js = -1;
        for (int j = 0; j < cap; j++)
            if (((active & ~used) >> j & 1u) && fe[j] == f) {
                js = j;
                used |= (uint64_t)1 << j;
                break;
            }
        unmatched += js < 0;
        kk[nk] = k;
        sl[nk++] = js;
    }

    if (unmatched) {
        /* Handover: an orphan slot whose feature is adjacent to the new one. */
        for (int q = 0; q < nk && s; q++) {
            if (sl[q] >= 0)
                continue;
            for (int j = 0; j < cap; j++)
                if (((active & ~used) >> j & 1u) &&
                    rs_surface_adjacent(s, fe[j], c->feature[kk[q]])) {
                    sl[q] = j;
                    used |= (uint64_t)1 << j;
                    break;
                }
        }
        /* New contacts take free slots; orphans keep theirs for the leaving call. */
        for (int q = 0; q < nk; q++) {
            if (sl[q] >= 0)
                continue;
            int js = -1;
            for (int j = 0; j < cap && js < 0; j++)
                if (!((active | used) >> j & 1u))
                    js = j;
            if (js < 0)
                goto full;
            sl[q] = js;
            used |= (uint64_t)1 << js;
        }
    }

    for (int q = 0; q < nk; q++) {
        out->point[*ne] = kk[q];
        out->slot[*ne] = h + (size_t)sl[q] * hs;
        (*ne)++;
    }
    uint64_t leaving = active & ~used;
    for (int j = 0; leaving && j < cap; j++)
        if (leaving >> j & 1u) {
            out->point[*ne] = -1 - i;
            out->slot[*ne] = h + (size_t)j * hs;
            (*ne)++;
        }
    return RS_OK;

full:
    return rs_error_set(err, RS_ERR_CAPACITY,
                        "rs_track_update: particle %d touches surface '%s' at more "
                        "features than its history capacity %d (raise the capacity)",
                        p->id ? p->id[i] : i, s ? s->name : "", cap);
}

typedef struct master_rates {
    double Q[9], V[3], W[3], C[3];
} master_rates;

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
    cross3(w, r, wr);
    cross3(mr->W, rm, Wr);
    vr[0] = p->vx[i] + wr[0] - mr->V[0] - Wr[0];
    vr[1] = p->vy[i] + wr[1] - mr->V[1] - Wr[1];
    vr[2] = p->vz[i] + wr[2] - mr->V[2] - Wr[2];
}

/* One live contact, straight-line scalar code (the hot loop). nd and fixed are
 * constants in each inlined copy; fixed: the master does not move (Q = I, V = W = 0), so
 * Q n_old = n_old, and P = I where n_new equals n_old bit for bit. */
RS_INLINE void emit_contact(const rs_tracker *tr, const master_rates *mr, double dt,
                            const rs_particles *p, const rs_contacts *c, int k,
                            rs_track_out *o, int e, const int nd, const int fixed)
{
    const int i = c->point[k];
    double *h = o->slot[e];
    const double rad = p->radius ? p->radius[i] : 0.0;
    const double nx = c->nrm[0][k], ny = c->nrm[1][k], nz = c->nrm[2][k];
    const double ax = c->t1[0][k], ay = c->t1[1][k], az = c->t1[2][k];
    const double bx = c->t2[0][k], by = c->t2[1][k], bz = c->t2[2][k];
    const double rd1 = rad - c->dist[k], arm = rad - 0.5 * rd1;

    /* x_cp = x - arm n; v_rel = v + w x (x_cp - x) - (V + W x (x_cp - C)). */
    const double rx = -arm * nx, ry = -arm * ny, rz = -arm * nz;
    const double px = p->x[i] + rx, py = p->y[i] + ry, pz = p->z[i] + rz;
    double wx = 0.0, wy = 0.0, wz = 0.0;
    if (p->wx) {
        wx = p->wx[i];
        wy = p->wy[i];
        wz = p->wz[i];
    }
    double vx = p->vx[i] + (wy * rz - wz * ry);
    double vy = p->vy[i] + (wz * rx - wx * rz);
    double vz = p->vz[i] + (wx * ry - wy * rx);
    if (!fixed) {
        const double mx = px - mr->C[0], my = py - mr->C[1], mz = pz - mr->C[2];
        const double *W = mr->W;
        vx = vx - mr->V[0] - (W[1] * mz - W[2] * my);
        vy = vy - mr->V[1] - (W[2] * mx - W[0] * mz);
        vz = vz - mr->V[2] - (W[0] * my - W[1] * mx);
    }
    const double vn = vx * nx + vy * ny + vz * nz;
    const double v1 = vx * ax + vy * ay + vz * az;
    const double v2 = nd == 3 ? vx * bx + vy * by + vz * bz : 0.0;
    double d11 = 1.0, d12 = 0.0, d21 = 0.0, d22 = 1.0, s1, s2, ds1, ds2, drd1;

    if (h[RS_H_STATE] == RS_HSTATE_ACTIVE) {
        if (nd == 3) {
            /* a = Q n_old, q = Q t1_old; P v = cs v + w x v + w (w.v) / (1 + cs) with
             * cs = a.n, w = a x n; tau1 = P q. Rotations keep cross products, so
             * tau2 = P Q (n_old x t1_old) = n x tau1, and with t2 = n x t1 the matrix
             * drot(i,j) = t_i . tau_j is [[d11, -d21], [d21, d11]]. */
            const double *Q = mr->Q, *ho = h + RS_H_N;
            double a[3], q[3], u[3];
            if (fixed) {
                for (int r = 0; r < 3; r++) {
                    a[r] = ho[r];
                    q[r] = ho[3 + r];
                }
            } else {
                /* Written out: GCC at -O2 keeps the row loop rolled. */
                const double n0 = ho[0], n1 = ho[1], n2 = ho[2];
                const double t0 = ho[3], t1 = ho[4], t2 = ho[5];
                a[0] = Q[0] * n0 + Q[1] * n1 + Q[2] * n2;
                q[0] = Q[0] * t0 + Q[1] * t1 + Q[2] * t2;
                a[1] = Q[3] * n0 + Q[4] * n1 + Q[5] * n2;
                q[1] = Q[3] * t0 + Q[4] * t1 + Q[5] * t2;
                a[2] = Q[6] * n0 + Q[7] * n1 + Q[8] * n2;
                q[2] = Q[6] * t0 + Q[7] * t1 + Q[8] * t2;
            }
            const double cs = a[0] * nx + a[1] * ny + a[2] * nz;
            if (fixed && a[0] == nx && a[1] == ny && a[2] == nz) {
                /* The normal did not turn: P = I. */
                u[0] = q[0];
                u[1] = q[1];
                u[2] = q[2];
            } else if (1.0 + cs > RS_ANTIPARALLEL) {
                const double w0 = a[1] * nz - a[2] * ny, w1 = a[2] * nx - a[0] * nz,
                             w2 = a[0] * ny - a[1] * nx;
                const double f = (w0 * q[0] + w1 * q[1] + w2 * q[2]) / (1.0 + cs);
                u[0] = cs * q[0] + (w1 * q[2] - w2 * q[1]) + f * w0;
                u[1] = cs * q[1] + (w2 * q[0] - w0 * q[2]) + f * w1;
                u[2] = cs * q[2] + (w0 * q[1] - w1 * q[0]) + f * w2;
            } else {
                /* Half turn about q (orthogonal to a): tau1 = q. */
                u[0] = q[0];
                u[1] = q[1];
                u[2] = q[2];
            }
            d11 = ax * u[0] + ay * u[1] + az * u[2];
            d21 = bx * u[0] + by * u[1] + bz * u[2];
            d12 = -d21;
            d22 = d11;
        }
        const double so1 = h[RS_H_SLIP], so2 = nd == 3 ? h[RS_H_SLIP + 1] : 0.0;
        ds1 = v1 * dt;
        ds2 = v2 * dt;
        s1 = d11 * so1 + d12 * so2 + ds1;
        s2 = d21 * so1 + d22 * so2 + ds2;
        drd1 = rd1 - h[RS_H_RDISP1];
    } else {
        /* The first increment of a new contact: its slip and approach over this dt. */
        ds1 = v1 * dt;
        ds2 = v2 * dt;
        s1 = ds1;
        s2 = ds2;
        drd1 = -vn * dt;
        for (int b = 0; b < 3 + tr->nstatev; b++)
            h[RS_H_STRESS + b] = 0.0;
    }

    h[RS_H_FEATURE] = c->feature[k];
    h[RS_H_STATE] = RS_HSTATE_ACTIVE;
    h[RS_H_N] = nx;
    h[RS_H_N + 1] = ny;
    h[RS_H_N + 2] = nz;
    h[RS_H_T1] = ax;
    h[RS_H_T1 + 1] = ay;
    h[RS_H_T1 + 2] = az;
    h[RS_H_T2] = bx;
    h[RS_H_T2 + 1] = by;
    h[RS_H_T2 + 2] = bz;
    h[RS_H_SLIP] = s1;
    h[RS_H_SLIP + 1] = s2;
    h[RS_H_RDISP1] = rd1;

    o->point[e] = i;
    o->feature[e] = c->feature[k];
    RS_DROT(o->drot, 0, 0, e) = d11;
    RS_DROT(o->drot, 1, 0, e) = d21;
    RS_DROT(o->drot, 0, 1, e) = d12;
    RS_DROT(o->drot, 1, 1, e) = d22;
    RS_A2(o->curv, 2, 0, e) = c->curv[0][k];
    RS_A2(o->curv, 2, 1, e) = c->curv[1][k];
    RS_A2(o->rdisp, nd, 0, e) = rd1;
    RS_A2(o->rdisp, nd, 1, e) = s1;
    RS_A2(o->drdisp, nd, 0, e) = drd1;
    RS_A2(o->drdisp, nd, 1, e) = ds1;
    RS_A2(o->vrel, nd, 0, e) = vn;
    RS_A2(o->vrel, nd, 1, e) = v1;
    RS_A3(o->alocaldir, nd, 0, 0, e) = nx;
    RS_A3(o->alocaldir, nd, 1, 0, e) = ny;
    RS_A3(o->alocaldir, nd, 0, 1, e) = ax;
    RS_A3(o->alocaldir, nd, 1, 1, e) = ay;
    RS_A2(o->coordslv, nd, 0, e) = px;
    RS_A2(o->coordslv, nd, 1, e) = py;
    RS_A2(o->coordmst, nd, 0, e) = c->xm[0][k];
    RS_A2(o->coordmst, nd, 1, e) = c->xm[1][k];
    if (nd == 3) {
        RS_A2(o->rdisp, nd, 2, e) = s2;
        RS_A2(o->drdisp, nd, 2, e) = ds2;
        RS_A2(o->vrel, nd, 2, e) = v2;
        RS_A3(o->alocaldir, nd, 2, 0, e) = nz;
        RS_A3(o->alocaldir, nd, 2, 1, e) = az;
        RS_A3(o->alocaldir, nd, 0, 2, e) = bx;
        RS_A3(o->alocaldir, nd, 1, 2, e) = by;
        RS_A3(o->alocaldir, nd, 2, 2, e) = bz;
        RS_A2(o->coordslv, nd, 2, e) = pz;
        RS_A2(o->coordmst, nd, 2, e) = c->xm[2][k];
    }
}

/* A slot whose feature is gone: RS_MAXVAL in rdisp, drdisp and drot; the frame is the
 * stored one carried by Q, the contact point the particle's surface point along -n. */
static void emit_leaving(const rs_tracker *tr, const master_rates *mr,
                         const rs_particles *p, int i, rs_track_out *o, int e)
{
    const int nd = tr->ndir;
    double *h = o->slot[e];
    const double rad = p->radius ? p->radius[i] : 0.0;
    const double xc[3] = {p->x[i], p->y[i], p->z[i]};
    double n[3], t1[3], t2[3], xcp[3], vr[3];
    matvec(mr->Q, h + RS_H_N, n);
    matvec(mr->Q, h + RS_H_T1, t1);
    matvec(mr->Q, h + RS_H_T2, t2);
    for (int b = 0; b < 3; b++)
        xcp[b] = xc[b] - rad * n[b];
    rel_velocity(p, i, mr, xc, xcp, vr);

    h[RS_H_STATE] = RS_HSTATE_LEAVING;
    o->point[e] = i;
    o->feature[e] = (int)h[RS_H_FEATURE];
    for (int b = 0; b < nd; b++) {
        RS_A2(o->rdisp, nd, b, e) = RS_MAXVAL;
        RS_A2(o->drdisp, nd, b, e) = RS_MAXVAL;
        RS_A2(o->coordslv, nd, b, e) = xcp[b];
        RS_A2(o->coordmst, nd, b, e) = xcp[b];
    }
    for (int b = 0; b < 4; b++)
        o->drot[(size_t)e * 4 + b] = RS_MAXVAL;
    RS_A2(o->vrel, nd, 0, e) = dot3(vr, n);
    RS_A2(o->vrel, nd, 1, e) = dot3(vr, t1);
    if (nd == 3)
        RS_A2(o->vrel, nd, 2, e) = dot3(vr, t2);
    put_frame(o, nd, e, n, t1, t2);
    RS_A2(o->curv, 2, 0, e) = 0.0;
    RS_A2(o->curv, 2, 1, e) = 0.0;
}

int rs_track_update(const rs_tracker *tr, const rs_surface *s, const rs_motion *m,
                    double dt, const rs_particles *p, const rs_contacts *c,
                    rs_track_out *out, rs_error *err)
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
    if (tr->nstatev < 0)
        return rs_error_set(err, RS_ERR_ARG, "rs_track_update: nstatev = %d is negative",
                            tr->nstatev);
    const int nc = c ? c->n : 0;
    int rc = out_reserve(out, nc + p->n * tr->capacity, err);
    if (rc)
        return rc;

    out->n = 0;
    out->ndir = tr->ndir;
    /* Pass 1, grouping the contacts by particle: it takes every contact exactly when
     * they name points 0..n-1 in block order (checked here, not in a separate pass). */
    int ne = 0, k = 0;
    for (int i = 0; i < p->n; i++) {
        int kb = k;
        while (k < nc && c->point[k] == i)
            k++;
        rc = assign_slots(tr, s, p, c, i, kb, k, out, &ne, err);
        if (rc)
            return rc;
    }
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

    master_rates mr;
    memset(&mr, 0, sizeof mr);
    if (m) {
        memcpy(mr.Q, m->dQ, sizeof mr.Q);
        for (int b = 0; b < 3; b++) {
            mr.V[b] = m->vel[b];
            mr.W[b] = m->omega * m->axis[b];
        }
        rs_motion_center(m, mr.C);
    } else {
        mr.Q[0] = mr.Q[4] = mr.Q[8] = 1.0;
    }

    /* A master at rest (or none): exactly Q = I and V = W = 0. */
    int fixed = mr.V[0] == 0.0 && mr.V[1] == 0.0 && mr.V[2] == 0.0 && mr.W[0] == 0.0 &&
                mr.W[1] == 0.0 && mr.W[2] == 0.0;
    for (int b = 0; b < 9; b++)
        fixed = fixed && mr.Q[b] == (b % 4 == 0 ? 1.0 : 0.0);

#define RS_EMIT_ALL(ND, FIXED)                                                             \
    for (int e = 0; e < ne; e++) {                                                         \
        int ke = out->point[e];                                                            \
        if (ke >= 0)                                                                       \
            emit_contact(tr, &mr, dt, p, c, ke, out, e, ND, FIXED);                        \
        else                                                                               \
            emit_leaving(tr, &mr, p, -1 - ke, out, e);                                     \
    }
    if (tr->ndir == 3 && fixed)
        RS_EMIT_ALL(3, 1)
    else if (tr->ndir == 3)
        RS_EMIT_ALL(3, 0)
    else if (fixed)
        RS_EMIT_ALL(2, 1)
    else
        RS_EMIT_ALL(2, 0)
#undef RS_EMIT_ALL
    out->n = ne;
    return RS_OK;
}

void rs_track_load(const rs_tracker *tr, const rs_track_out *out, double *stress,
                   double *statev)
{
    const int nd = out->ndir, ns = tr->nstatev;
    for (int e = 0; e < out->n; e++) {
        const double *h = out->slot[e];
        if (stress) {
            RS_A2(stress, nd, 0, e) = h[RS_H_STRESS];
            if (nd == 2) {
                RS_A2(stress, nd, 1, e) = h[RS_H_STRESS + 1];
            } else if (h[RS_H_STATE] == RS_HSTATE_LEAVING) {
                RS_A2(stress, nd, 1, e) = h[RS_H_STRESS + 1];
                RS_A2(stress, nd, 2, e) = h[RS_H_STRESS + 2];
            } else {
                /* The shear traction is carried into this increment's basis, as the slip.
                 */
                const double s2 = h[RS_H_STRESS + 1], s3 = h[RS_H_STRESS + 2];
                RS_A2(stress, nd, 1, e) =
                    RS_DROT(out->drot, 0, 0, e) * s2 + RS_DROT(out->drot, 0, 1, e) * s3;
                RS_A2(stress, nd, 2, e) =
                    RS_DROT(out->drot, 1, 0, e) * s2 + RS_DROT(out->drot, 1, 1, e) * s3;
            }
        }
        if (statev)
            for (int b = 0; b < ns; b++)
                RS_A2(statev, ns, b, e) = h[RS_H_STATEV + b];
    }
}

void rs_track_commit(const rs_tracker *tr, rs_track_out *out, const double *stress,
                     const double *statev)
{
    const int nd = out->ndir, ns = tr->nstatev;
    for (int e = 0; e < out->n; e++) {
        double *h = out->slot[e];
        if (h[RS_H_STATE] == RS_HSTATE_LEAVING) {
            h[RS_H_STATE] = RS_HSTATE_EMPTY;
            h[RS_H_FEATURE] = RS_FEATURE_NONE;
            continue;
        }
        if (stress) {
            const double *se = stress + (size_t)nd * e;
            h[RS_H_STRESS] = se[0];
            h[RS_H_STRESS + 1] = se[1];
            h[RS_H_STRESS + 2] = nd == 3 ? se[2] : 0.0;
        }
        if (statev)
            for (int b = 0; b < ns; b++)
                h[RS_H_STATEV + b] = RS_A2(statev, ns, b, e);
    }
}

void rs_track_clear(const rs_tracker *tr, double *hist)
{
    const int hs = RS_HIST_SIZE(tr->nstatev);
    memset(hist, 0, (size_t)tr->capacity * hs * sizeof *hist);
    for (int j = 0; j < tr->capacity; j++) {
        hist[(size_t)j * hs + RS_H_FEATURE] = RS_FEATURE_NONE;
        hist[(size_t)j * hs + RS_H_STATE] = RS_HSTATE_EMPTY;
    }
}
