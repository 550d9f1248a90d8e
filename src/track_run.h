/* The tracker's pass 2, shared by rs_track_update (track.c) and the laws' fused kernels
 * (track_fused.c, laws/hertz_fused.c): the master's rates over the increment and the
 * runs of live contacts (gather the history, the kinematics, the Abaqus-layout outputs,
 * the history's store). Internal to the library. */
#ifndef RIGIDSURF_TRACK_RUN_H
#define RIGIDSURF_TRACK_RUN_H

#include "rigidsurf/track.h"
#include "rigidsurf/vec.h"

#include "rs_compiler.h"
#include "rs_v4.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

/* Below this value of 1 + a.b the normal has turned by ~180 deg and a.b x stops defining
 * an axis; the minimal rotation is then the half turn about the carried t1. */
#define RS_ANTIPARALLEL 1e-12

typedef struct master_rates {
    double Q[9], V[3], W[3], C[3];
    double U[3], Umag;  ///< surface velocity (rs_motion.belt) and its length
    int belt;           ///< U is not zero
    const rs_motion *m; ///< the motion these come from (NULL: a fixed master)
} master_rates;

/* Pass 2 works on runs of live contacts: entries e0 .. e0+m-1 that name contacts k0 ..
 * k0+m-1 of particles i0 .. i0+m-1. The history values of a run are gathered into SoA
 * scratch; one branch-free loop (written to vectorize) reads them and the particles' and
 * contacts' own SoA arrays and computes the kinematics; simple loops write the
 * Abaqus-layout outputs and store the history. */
#define RS_TRACK_RUN 32

typedef struct track_run {
    double live[RS_TRACK_RUN]; ///< 1: the slot holds this contact's history, 0: new
    double on0[RS_TRACK_RUN], on1[RS_TRACK_RUN], on2[RS_TRACK_RUN];
    double ot0[RS_TRACK_RUN], ot1[RS_TRACK_RUN], ot2[RS_TRACK_RUN];
    /* the slot's values 6 and 7: the slip; in a slot without it (RS_DROP_SLIP), what
     * follows t1 there (the first two state variables of hertz's slot), or zeros */
    double so1[RS_TRACK_RUN], so2[RS_TRACK_RUN], rdo[RS_TRACK_RUN];
    /* computed */
    double rd1[RS_TRACK_RUN], drd1[RS_TRACK_RUN];
    double s1[RS_TRACK_RUN], s2[RS_TRACK_RUN], ds1[RS_TRACK_RUN], ds2[RS_TRACK_RUN];
    double vn[RS_TRACK_RUN], v1[RS_TRACK_RUN], v2[RS_TRACK_RUN];
    double px[RS_TRACK_RUN], py[RS_TRACK_RUN], pz[RS_TRACK_RUN];
    double d11[RS_TRACK_RUN], d21[RS_TRACK_RUN], md21[RS_TRACK_RUN]; ///< md21 = -d21
} track_run;

/* The history slot starts with the 9 values a run gathers and stores: n, t1, slip,
 * rdisp1, so two rows of 4 and one value; or, without the slip and rdisp1, with n and
 * t1, whose first 8 values are two rows of 4 when the slot has 8 or more. */
_Static_assert(RS_H_N == 0 && RS_H_T1 == 3 && RS_H_SLIP == 6 && RS_H_RDISP1 == 8,
               "the run's copies assume n, t1, slip, rdisp1 at the head of the slot");

/* Lane j of a run: the history in entry e's slot of hs values (lean: RS_DROP_SLIP). */
RS_INLINE void run_gather1(track_run *restrict r, int j, const rs_track_out *o, int e,
                           const int lean, const int hs)
{
    const double *h = o->slot[e];
    r->live[j] = RS_DIR_IS_LIVE(*o->dir[e]);
    r->on0[j] = h[RS_H_N];
    r->on1[j] = h[RS_H_N + 1];
    r->on2[j] = h[RS_H_N + 2];
    r->ot0[j] = h[RS_H_T1];
    r->ot1[j] = h[RS_H_T1 + 1];
    r->ot2[j] = h[RS_H_T1 + 2];
    r->so1[j] = hs >= 8 ? h[RS_H_SLIP] : 0.0;
    r->so2[j] = hs >= 8 ? h[RS_H_SLIP + 1] : 0.0;
    if (!lean)
        r->rdo[j] = h[RS_H_RDISP1];
}

/* The history of entries e0 .. e0+m-1 into the run's columns, 4 slots at a time (slots
 * of hs values; lean: the tracker drops the slip and rdisp1, RS_DROP_SLIP). */
RS_INLINE void run_gather(track_run *restrict r, int m, const rs_track_out *o, int e0,
                          const int lean, const int hs)
{
    int j = 0;
    if (hs >= 8)
        for (; j + 4 <= m; j += 4) {
            double *const *h = o->slot + e0 + j;
            rs_transpose4(h[0], h[1], h[2], h[3], r->on0 + j, r->on1 + j, r->on2 + j,
                          r->ot0 + j);
            rs_transpose4(h[0] + 4, h[1] + 4, h[2] + 4, h[3] + 4, r->ot1 + j, r->ot2 + j,
                          r->so1 + j, r->so2 + j);
            for (int l = 0; l < 4; l++) {
                if (!lean)
                    r->rdo[j + l] = h[l][RS_H_RDISP1];
                r->live[j + l] = RS_DIR_IS_LIVE(*o->dir[e0 + j + l]);
            }
        }
    for (; j < m; j++)
        run_gather1(r, j, o, e0 + j, lean, hs);
}

/* The kinematics of a run of m live contacts (docs/conventions.md):
 * - x_cp = x - arm n with arm = R - rdisp1/2; v_rel = v + w x (x_cp - x) - (V + W x
 *   (x_cp - C)) - u, with u the surface velocity U's tangential part scaled to |U|
 *   (belt != 0 only; rs_motion_belt_at, written out here so the loop vectorizes).
 * - a = Q n_old, q = Q t1_old; P v = cs v + w x v + w (w.v) / (1 + cs) with cs = a.n,
 *   w = a x n; tau1 = P q. Rotations keep cross products, so tau2 = n x tau1, and with
 *   t2 = n x t1 the matrix drot(i,j) = t_i . tau_j is [[d11, -d21], [d21, d11]]. P = I
 *   when the normal did not turn (a = n bit for bit); the half turn about q when
 *   1 + cs <= RS_ANTIPARALLEL (then tau1 = q as well).
 * - s <- drot s + ds; a new contact starts with s = ds and drdisp(1) = -v_n dt, and so
 *   does every contact when the slots keep neither (lean: RS_DROP_SLIP).
 * Every lane computes every formula and selects at the end, so the loop has no
 * branches. nd = 2: t1 only, drot = I. */
RS_INLINE void run_kinematics(track_run *restrict r, int m, const master_rates *mr,
                              double dt, const rs_particles *p, int i0,
                              const rs_contacts *c, int k0, const int nd, const int belt,
                              const int wit, const int lean)
{
    static const double zero[RS_TRACK_RUN];
    const double *prad = p->radius ? p->radius + i0 : zero;
    const double *pxc = p->x + i0, *pyc = p->y + i0, *pzc = p->z + i0;
    const double *pvx = p->vx + i0, *pvy = p->vy + i0, *pvz = p->vz + i0;
    const double *pwx = p->wx ? p->wx + i0 : zero, *pwy = p->wx ? p->wy + i0 : zero,
                 *pwz = p->wx ? p->wz + i0 : zero;
    const double Q0 = mr->Q[0], Q1 = mr->Q[1], Q2 = mr->Q[2], Q3 = mr->Q[3], Q4 = mr->Q[4],
                 Q5 = mr->Q[5], Q6 = mr->Q[6], Q7 = mr->Q[7], Q8 = mr->Q[8];
    const double V0 = mr->V[0], V1 = mr->V[1], V2 = mr->V[2];
    const double W0 = mr->W[0], W1 = mr->W[1], W2 = mr->W[2];
    const double C0 = mr->C[0], C1 = mr->C[1], C2 = mr->C[2];
    const double U0 = mr->U[0], U1 = mr->U[1], U2 = mr->U[2], Um = mr->Umag;
    const double *cnx = c->nrm[0] + k0, *cny = c->nrm[1] + k0, *cnz = c->nrm[2] + k0;
    const double *cax = c->t1[0] + k0, *cay = c->t1[1] + k0, *caz = c->t1[2] + k0;
    const double *cbx = c->t2[0] + k0, *cby = c->t2[1] + k0, *cbz = c->t2[2] + k0;
    const double *cd = c->dist + k0;
    const double *csx = wit ? c->xs[0] + k0 : zero, *csy = wit ? c->xs[1] + k0 : zero,
                 *csz = wit ? c->xs[2] + k0 : zero;
    for (int j = 0; j < m; j++) {
        const double nx = cnx[j], ny = cny[j], nz = cnz[j];
        const double ax = cax[j], ay = cay[j], az = caz[j];
        const double rad = prad[j], rd1 = rad - cd[j], arm = rad - 0.5 * rd1;
        /* a body: from the centre to its witness point, then half the overlap out */
        const double rx = wit ? csx[j] - pxc[j] + 0.5 * rd1 * nx : -arm * nx;
        const double ry = wit ? csy[j] - pyc[j] + 0.5 * rd1 * ny : -arm * ny;
        const double rz = wit ? csz[j] - pzc[j] + 0.5 * rd1 * nz : -arm * nz;
        const double px = pxc[j] + rx, py = pyc[j] + ry, pz = pzc[j] + rz;
        const double wx = pwx[j], wy = pwy[j], wz = pwz[j];
        const double mx = px - C0, my = py - C1, mz = pz - C2;
        double vx = pvx[j] + (wy * rz - wz * ry) - V0 - (W1 * mz - W2 * my);
        double vy = pvy[j] + (wz * rx - wx * rz) - V1 - (W2 * mx - W0 * mz);
        double vz = pvz[j] + (wx * ry - wy * rx) - V2 - (W0 * my - W1 * mx);
        if (belt) {
            const double un = U0 * nx + U1 * ny + U2 * nz;
            const double ux = U0 - un * nx, uy = U1 - un * ny, uz = U2 - un * nz;
            const double lu = sqrt(ux * ux + uy * uy + uz * uz);
            const double sc = lu > 0.0 ? Um / lu : 0.0;
            vx -= sc * ux;
            vy -= sc * uy;
            vz -= sc * uz;
        }
        const double vn = vx * nx + vy * ny + vz * nz;
        const double v1 = vx * ax + vy * ay + vz * az;
        const int live = r->live[j] != 0.0;
        const double ds1 = v1 * dt;
        double s1, s2 = 0.0, ds2 = 0.0, v2 = 0.0, d11 = 1.0, d21 = 0.0;
        if (nd == 3) {
            const double bx = cbx[j], by = cby[j], bz = cbz[j];
            const double n0 = r->on0[j], n1 = r->on1[j], n2 = r->on2[j];
            const double t0 = r->ot0[j], t1 = r->ot1[j], t2 = r->ot2[j];
            const double a0 = Q0 * n0 + Q1 * n1 + Q2 * n2;
            const double a1 = Q3 * n0 + Q4 * n1 + Q5 * n2;
            const double a2 = Q6 * n0 + Q7 * n1 + Q8 * n2;
            const double q0 = Q0 * t0 + Q1 * t1 + Q2 * t2;
            const double q1 = Q3 * t0 + Q4 * t1 + Q5 * t2;
            const double q2 = Q6 * t0 + Q7 * t1 + Q8 * t2;
            const double cs = a0 * nx + a1 * ny + a2 * nz, den = 1.0 + cs;
            const double w0 = a1 * nz - a2 * ny, w1 = a2 * nx - a0 * nz,
                         w2 = a0 * ny - a1 * nx;
            const int turn = !(a0 == nx && a1 == ny && a2 == nz) && den > RS_ANTIPARALLEL;
            const double f = (w0 * q0 + w1 * q1 + w2 * q2) / (turn ? den : 1.0);
            const double u0 = turn ? cs * q0 + (w1 * q2 - w2 * q1) + f * w0 : q0;
            const double u1 = turn ? cs * q1 + (w2 * q0 - w0 * q2) + f * w1 : q1;
            const double u2 = turn ? cs * q2 + (w0 * q1 - w1 * q0) + f * w2 : q2;
            d11 = live ? ax * u0 + ay * u1 + az * u2 : 1.0;
            d21 = live ? bx * u0 + by * u1 + bz * u2 : 0.0;
            v2 = vx * bx + vy * by + vz * bz;
            ds2 = v2 * dt;
            const double so1 = live ? r->so1[j] : 0.0, so2 = live ? r->so2[j] : 0.0;
            s1 = lean ? ds1 : d11 * so1 - d21 * so2 + ds1;
            s2 = lean ? ds2 : d21 * so1 + d11 * so2 + ds2;
        } else {
            s1 = lean ? ds1 : (live ? r->so1[j] : 0.0) + ds1;
        }
        r->rd1[j] = rd1;
        r->drd1[j] = live && !lean ? rd1 - r->rdo[j] : -vn * dt;
        r->s1[j] = s1;
        r->s2[j] = s2;
        r->ds1[j] = ds1;
        r->ds2[j] = ds2;
        r->vn[j] = vn;
        r->v1[j] = v1;
        r->v2[j] = v2;
        r->px[j] = px;
        r->py[j] = py;
        r->pz[j] = pz;
        r->d11[j] = d11;
        r->d21[j] = d21;
        r->md21[j] = -d21;
    }
}

/* dst(nd, m) from the SoA columns a, b (and c when nd = 3), one loop per array. */
RS_INLINE void put_cols(double *restrict dst, int m, const int nd, const double *a,
                        const double *b, const double *c)
{
    int j = 0;
    if (nd == 3) {
        for (; j + 4 <= m; j += 4)
            rs_cols3_to_rows4(a + j, b + j, c + j, dst + 3 * j);
        RS_NO_UNROLL
        for (; j < m; j++) {
            dst[3 * j] = a[j];
            dst[3 * j + 1] = b[j];
            dst[3 * j + 2] = c[j];
        }
    } else {
        for (; j + 4 <= m; j += 4)
            rs_cols2_to_rows4(a + j, b + j, dst + 2 * j);
        RS_NO_UNROLL
        for (; j < m; j++) {
            dst[2 * j] = a[j];
            dst[2 * j + 1] = b[j];
        }
    }
}

/* The Abaqus-layout outputs of a run at entries e0 .. e0+m-1 (coordmst unless xm is 0). */
RS_INLINE void run_outputs(const track_run *restrict r, int m, const rs_contacts *c, int k0,
                           rs_track_out *o, int e0, const int nd, const int xm)
{
    const size_t e = (size_t)e0;
    put_cols(o->rdisp + e * nd, m, nd, r->rd1, r->s1, r->s2);
    put_cols(o->drdisp + e * nd, m, nd, r->drd1, r->ds1, r->ds2);
    put_cols(o->vrel + e * nd, m, nd, r->vn, r->v1, r->v2);
    put_cols(o->coordslv + e * nd, m, nd, r->px, r->py, r->pz);
    if (xm)
        put_cols(o->coordmst + e * nd, m, nd, c->xm[0] + k0, c->xm[1] + k0, c->xm[2] + k0);
    put_cols(o->curv + 2 * e, m, 2, c->curv[0] + k0, c->curv[1] + k0, NULL);
    if (c->share)
        memcpy(o->share + e, c->share + k0, (size_t)m * sizeof(double));
    else /* a list made by hand, without shares */
        for (int j = 0; j < m; j++)
            o->share[e + (size_t)j] = 1.0;
    /* drot(2, 2) = [[d11, -d21], [d21, d11]], column-major. */
    double *restrict dr = o->drot + 4 * e;
    const double *nd21 = r->md21;
    int j = 0;
    for (; j + 4 <= m; j += 4)
        rs_transpose4(r->d11 + j, r->d21 + j, nd21 + j, r->d11 + j, dr + 4 * j,
                      dr + 4 * j + 4, dr + 4 * j + 8, dr + 4 * j + 12);
    RS_NO_UNROLL
    for (; j < m; j++) {
        dr[4 * j] = r->d11[j];
        dr[4 * j + 1] = r->d21[j];
        dr[4 * j + 2] = nd21[j];
        dr[4 * j + 3] = r->d11[j];
    }
    /* alocaldir(nd, nd): columns n, t1 (, t2) of each entry. */
    const double *n0 = c->nrm[0] + k0, *n1 = c->nrm[1] + k0, *n2 = c->nrm[2] + k0;
    const double *a0 = c->t1[0] + k0, *a1 = c->t1[1] + k0, *a2 = c->t1[2] + k0;
    const double *b0 = c->t2[0] + k0, *b1 = c->t2[1] + k0, *b2 = c->t2[2] + k0;
    double *restrict al = o->alocaldir + e * nd * nd;
    j = 0;
    if (nd == 3)
        for (; j + 4 <= m; j += 4) {
            double *a = al + 9 * (size_t)j;
            rs_transpose4(n0 + j, n1 + j, n2 + j, a0 + j, a, a + 9, a + 18, a + 27);
            rs_transpose4(a1 + j, a2 + j, b0 + j, b1 + j, a + 4, a + 13, a + 22, a + 31);
            for (int l = 0; l < 4; l++)
                a[9 * l + 8] = b2[j + l];
        }
    for (; j < m; j++) {
        double *a = al + (size_t)j * nd * nd;
        a[0] = n0[j];
        a[1] = n1[j];
        a[nd] = a0[j];
        a[nd + 1] = a1[j];
        if (nd == 3) {
            a[2] = n2[j];
            a[5] = a2[j];
            a[6] = b0[j];
            a[7] = b1[j];
            a[8] = b2[j];
        }
    }
}

/* The history of a run: directory entry, frame, slip and rdisp1 (lean: frame only, the
 * tracker drops the slip and rdisp1, RS_DROP_SLIP); a new contact's stress and statev
 * start at zero. Also the entries' particle and feature ids. live, rd1, s1, s2: the run's
 * columns of those names (track_run; rd1, s1 and s2 are read unless lean). x6, x7 (lean,
 * slots of 8 or more values): the columns to store at the slot's values 6 and 7, which
 * then are not zeroed for a new contact; NULL for none. */
RS_INLINE void run_store(const double *restrict live, const double *restrict rd1,
                         const double *restrict s1, const double *restrict s2, int m,
                         const rs_tracker *tr, const rs_contacts *c, int k0,
                         rs_track_out *o, int e0, const int lean, const double *x6,
                         const double *x7)
{
    const double *n0 = c->nrm[0] + k0, *n1 = c->nrm[1] + k0, *n2 = c->nrm[2] + k0;
    const double *a0 = c->t1[0] + k0, *a1 = c->t1[1] + k0, *a2 = c->t1[2] + k0;
    double *const *slot = o->slot + e0;
    const int hs = rs_track_slot_size(tr);
    const int rows = !lean || x6; /* values 4 to 7 are one row of 4 */
    const double *c6 = lean ? x6 : s1, *c7 = lean ? x7 : s2;
    int j = 0;
    for (; j + 4 <= m; j += 4) {
        double *const *h = slot + j;
        rs_transpose4(n0 + j, n1 + j, n2 + j, a0 + j, h[0], h[1], h[2], h[3]);
        if (rows)
            rs_transpose4(a1 + j, a2 + j, c6 + j, c7 + j, h[0] + 4, h[1] + 4, h[2] + 4,
                          h[3] + 4);
        else
            for (int l = 0; l < 4; l++)
                h[l][RS_H_T1 + 1] = a1[j + l], h[l][RS_H_T1 + 2] = a2[j + l];
    }
    for (; j < m; j++) {
        double *h = slot[j];
        h[RS_H_N] = n0[j];
        h[RS_H_N + 1] = n1[j];
        h[RS_H_N + 2] = n2[j];
        h[RS_H_T1] = a0[j];
        h[RS_H_T1 + 1] = a1[j];
        h[RS_H_T1 + 2] = a2[j];
        if (rows) {
            h[RS_H_SLIP] = c6[j];
            h[RS_H_SLIP + 1] = c7[j];
        }
    }
    /* a new contact's slot from here on starts at zero */
    const int z = !lean ? RS_H_RDISP1 + 1 : x6 ? RS_H_SLIP + 2 : RS_H_SLIP;
    for (j = 0; j < m; j++) {
        const int k = k0 + j, e = e0 + j;
        double *h = slot[j];
        if (live[j] == 0.0)
            for (int b = z; b < hs; b++)
                h[b] = 0.0;
        if (!lean)
            h[RS_H_RDISP1] = rd1[j];
        /* Stored only when it changes (a new contact, a handover): a held contact's entry
         * already names its feature, and its directory's line then stays clean, which
         * saves writing it back to memory in a large bed. */
        const double live = RS_DIR_LIVE(c->feature[k]);
        if (*o->dir[e] != live)
            *o->dir[e] = live;
    }
    int *restrict op = o->point + e0, *restrict of = o->feature + e0;
    for (j = 0; j < m; j++) {
        op[j] = c->point[k0 + j];
        of[j] = c->feature[k0 + j];
    }
}

/* Whether the directory d (cap entries) holds f in slot 0 and nothing else: f =
 * RS_DIR_LIVE(feature), a held contact alone in slot 0 (the usual particle); f =
 * RS_DIR_EMPTY, every slot free. Entries and f are whole numbers as doubles, never -0 or
 * NaN, so equality is that of the bit patterns, compared as integers (the capacity 4 of
 * most walls unrolled). */
RS_INLINE int rs_track_dir_usual(const double *d, int cap, double f)
{
    const double empty = RS_DIR_EMPTY;
    uint64_t fb, eb, u;
    memcpy(&fb, &f, sizeof fb);
    memcpy(&eb, &empty, sizeof eb);
    if (cap == 4) {
        uint64_t u0, u1, u2, u3;
        memcpy(&u0, d, sizeof u0);
        memcpy(&u1, d + 1, sizeof u1);
        memcpy(&u2, d + 2, sizeof u2);
        memcpy(&u3, d + 3, sizeof u3);
        return ((u0 ^ fb) | (u1 ^ eb) | (u2 ^ eb) | (u3 ^ eb)) == 0;
    }
    memcpy(&u, d, sizeof u);
    uint64_t acc = u ^ fb;
    for (int j = 1; j < cap; j++) {
        memcpy(&u, d + j, sizeof u);
        acc |= u ^ eb;
    }
    return acc == 0;
}

/// Pass 1 of rs_track_update (the contacts matched to their slots, the leaving slots
/// listed, the block order checked) and the master's rates mr over the increment. On
/// RS_OK, *ne entries are listed (out->point[e]: the contact, or -1 - i for particle i's
/// leaving slot) and *ident says that entry e is contact e of particle e for every e.
int rs_track_match(const rs_tracker *tr, const rs_surface *s, const rs_motion *m,
                   const rs_particles *p, const rs_contacts *c, rs_track_out *out,
                   master_rates *mr, int *ne, int *ident, rs_error *err);

/// rs_track_match for a block whose particle e holds contact e in its slot 0 alone,
/// within the tracking thickness (rs_track_dir_usual), as the caller has checked: entry
/// e is contact e of particle e, and mr the master's rates. Errors: out of memory.
int rs_track_match_usual(const rs_tracker *tr, const rs_motion *m, const rs_particles *p,
                         rs_track_out *out, master_rates *mr, rs_error *err);

/// Pass 2 of rs_track_update over the ne entries of rs_track_match; sets out->n.
void rs_track_emit(const rs_tracker *tr, const master_rates *mr, double dt,
                   const rs_particles *p, const rs_contacts *c, rs_track_out *out, int ne,
                   int ident);

#endif
