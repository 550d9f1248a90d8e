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
#include "track_slots.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Below this value of 1 + a.b the normal has turned by ~180 deg and a.b x stops defining
 * an axis; the minimal rotation is then the half turn about the carried t1. */
#define RS_ANTIPARALLEL 1e-12

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

/* 1 when a directory of capacity 4 holds f in slot 0 and the other slots are free (bit
 * patterns compared, as in find_fast). */
RS_INLINE int dir_usual4(const double *d, double f)
{
    const double empty = RS_DIR_EMPTY;
    uint64_t u0, u1, u2, u3, fb, eb;
    memcpy(&u0, d, sizeof u0);
    memcpy(&u1, d + 1, sizeof u1);
    memcpy(&u2, d + 2, sizeof u2);
    memcpy(&u3, d + 3, sizeof u3);
    memcpy(&fb, &f, sizeof fb);
    memcpy(&eb, &empty, sizeof eb);
    return ((u0 ^ fb) | (u1 ^ eb) | (u2 ^ eb) | (u3 ^ eb)) == 0;
}

/* find_fast for capacity 4, first testing the usual directory at once: the contact (f
 * live) in slot 0 and the other slots free, or no contact (f = RS_DIR_EMPTY) and every
 * slot free. */
RS_INLINE int find_fast4(const double *d, double f)
{
    if (dir_usual4(d, f))
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
                !dir_usual4(d, RS_DIR_LIVE(cfeat[i])))
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

typedef struct master_rates {
    double Q[9], V[3], W[3], C[3];
    double U[3], Umag;  ///< surface velocity (rs_motion.belt) and its length
    int belt;           ///< U is not zero
    const rs_motion *m; ///< the motion these come from (NULL: a fixed master)
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
    rs_cross3(w, r, wr);
    rs_cross3(mr->W, rm, Wr);
    vr[0] = p->vx[i] + wr[0] - mr->V[0] - Wr[0];
    vr[1] = p->vy[i] + wr[1] - mr->V[1] - Wr[1];
    vr[2] = p->vz[i] + wr[2] - mr->V[2] - Wr[2];
}

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
    double so1[RS_TRACK_RUN], so2[RS_TRACK_RUN], rdo[RS_TRACK_RUN];
    /* computed */
    double rd1[RS_TRACK_RUN], drd1[RS_TRACK_RUN];
    double s1[RS_TRACK_RUN], s2[RS_TRACK_RUN], ds1[RS_TRACK_RUN], ds2[RS_TRACK_RUN];
    double vn[RS_TRACK_RUN], v1[RS_TRACK_RUN], v2[RS_TRACK_RUN];
    double px[RS_TRACK_RUN], py[RS_TRACK_RUN], pz[RS_TRACK_RUN];
    double d11[RS_TRACK_RUN], d21[RS_TRACK_RUN], md21[RS_TRACK_RUN]; ///< md21 = -d21
} track_run;

/* The history slot starts with the 9 values a run gathers and stores: n, t1, slip,
 * rdisp1, so two rows of 4 and one value. */
_Static_assert(RS_H_N == 0 && RS_H_T1 == 3 && RS_H_SLIP == 6 && RS_H_RDISP1 == 8,
               "the run's copies assume n, t1, slip, rdisp1 at the head of the slot");

/* Lane j of a run: the history in entry e's slot. */
RS_INLINE void run_gather1(track_run *restrict r, int j, const rs_track_out *o, int e)
{
    const double *h = o->slot[e];
    r->live[j] = RS_DIR_IS_LIVE(*o->dir[e]);
    r->on0[j] = h[RS_H_N];
    r->on1[j] = h[RS_H_N + 1];
    r->on2[j] = h[RS_H_N + 2];
    r->ot0[j] = h[RS_H_T1];
    r->ot1[j] = h[RS_H_T1 + 1];
    r->ot2[j] = h[RS_H_T1 + 2];
    r->so1[j] = h[RS_H_SLIP];
    r->so2[j] = h[RS_H_SLIP + 1];
    r->rdo[j] = h[RS_H_RDISP1];
}

/* The history of entries e0 .. e0+m-1 into the run's columns, 4 slots at a time. */
RS_INLINE void run_gather(track_run *restrict r, int m, const rs_track_out *o, int e0)
{
    int j = 0;
    for (; j + 4 <= m; j += 4) {
        double *const *h = o->slot + e0 + j;
        rs_transpose4(h[0], h[1], h[2], h[3], r->on0 + j, r->on1 + j, r->on2 + j,
                      r->ot0 + j);
        rs_transpose4(h[0] + 4, h[1] + 4, h[2] + 4, h[3] + 4, r->ot1 + j, r->ot2 + j,
                      r->so1 + j, r->so2 + j);
        for (int l = 0; l < 4; l++) {
            r->rdo[j + l] = h[l][RS_H_RDISP1];
            r->live[j + l] = RS_DIR_IS_LIVE(*o->dir[e0 + j + l]);
        }
    }
    for (; j < m; j++)
        run_gather1(r, j, o, e0 + j);
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
 * - s <- drot s + ds; a new contact starts with s = ds and drdisp(1) = -v_n dt.
 * Every lane computes every formula and selects at the end, so the loop has no
 * branches. nd = 2: t1 only, drot = I. */
RS_INLINE void run_kinematics(track_run *restrict r, int m, const master_rates *mr,
                              double dt, const rs_particles *p, int i0,
                              const rs_contacts *c, int k0, const int nd, const int belt,
                              const int wit)
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
            s1 = d11 * so1 - d21 * so2 + ds1;
            s2 = d21 * so1 + d11 * so2 + ds2;
        } else {
            s1 = (live ? r->so1[j] : 0.0) + ds1;
        }
        r->rd1[j] = rd1;
        r->drd1[j] = live ? rd1 - r->rdo[j] : -vn * dt;
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

/* The history of a run: directory entry, frame, slip and rdisp1; a new contact's stress
 * and statev start at zero. Also the entries' particle and feature ids. */
RS_INLINE void run_store(const track_run *restrict r, int m, const rs_tracker *tr,
                         const rs_contacts *c, int k0, rs_track_out *o, int e0)
{
    const double *n0 = c->nrm[0] + k0, *n1 = c->nrm[1] + k0, *n2 = c->nrm[2] + k0;
    const double *a0 = c->t1[0] + k0, *a1 = c->t1[1] + k0, *a2 = c->t1[2] + k0;
    double *const *slot = o->slot + e0;
    const int hs = rs_track_slot_size(tr);
    int j = 0;
    for (; j + 4 <= m; j += 4) {
        double *const *h = slot + j;
        rs_transpose4(n0 + j, n1 + j, n2 + j, a0 + j, h[0], h[1], h[2], h[3]);
        rs_transpose4(a1 + j, a2 + j, r->s1 + j, r->s2 + j, h[0] + 4, h[1] + 4, h[2] + 4,
                      h[3] + 4);
    }
    for (; j < m; j++) {
        double *h = slot[j];
        h[RS_H_N] = n0[j];
        h[RS_H_N + 1] = n1[j];
        h[RS_H_N + 2] = n2[j];
        h[RS_H_T1] = a0[j];
        h[RS_H_T1 + 1] = a1[j];
        h[RS_H_T1 + 2] = a2[j];
        h[RS_H_SLIP] = r->s1[j];
        h[RS_H_SLIP + 1] = r->s2[j];
    }
    for (j = 0; j < m; j++) {
        const int k = k0 + j, e = e0 + j;
        double *h = slot[j];
        if (r->live[j] == 0.0)
            for (int b = RS_H_RDISP1 + 1; b < hs; b++)
                h[b] = 0.0;
        h[RS_H_RDISP1] = r->rd1[j];
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

/* Pass 2 over the ne entries of pass 1: runs of live contacts, leaving slots as they
 * come. ident: entry e is contact e of particle e for every e (no leaving slot), so the
 * runs are known without looking. */
RS_INLINE void emit_all(const rs_tracker *tr, const master_rates *mr, double dt,
                        const rs_particles *p, const rs_contacts *c, rs_track_out *out,
                        int ne, int ident, const int nd)
{
    track_run r;
    int e = 0, sc = 0; /* sc: the next of out->seeded */
    const int nseeded = out->nseeded, *const seeded = out->seeded;
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
        run_gather(&r, m, out, e0);
        const int s0 = sc; /* seeded entries of this run: live, from the copied slot */
        if (nseeded)
            for (; sc < nseeded && seeded[sc] < e0 + m; sc++)
                r.live[seeded[sc] - e0] = 1.0;
        if (c->witness && c->xs[0])
            run_kinematics(&r, m, mr, dt, p, i0, c, k0, nd, mr->belt, 1);
        else if (mr->belt)
            run_kinematics(&r, m, mr, dt, p, i0, c, k0, nd, 1, 0);
        else
            run_kinematics(&r, m, mr, dt, p, i0, c, k0, nd, 0, 0);
        for (int q = s0; q < sc; q++) { /* its own normal increment, as a new contact's */
            const int j = seeded[q] - e0;
            r.drd1[j] = -r.vn[j] * dt;
        }
        run_outputs(&r, m, c, k0, out, e0, nd, !(tr->drop & RS_DROP_COORDMST));
        run_store(&r, m, tr, c, k0, out, e0);
    }
}

RS_MULTIVERSION
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
    if (tr->nstatev < 0 || tr->nstatev > RS_MAX_STATEV)
        return rs_error_set(err, RS_ERR_ARG,
                            "rs_track_update: nstatev = %d, expected 0 to %d", tr->nstatev,
                            RS_MAX_STATEV);
    const int nc = c ? c->n : 0;
    int rc = rs_track_out_reserve(out, nc + p->n * tr->capacity, err);
    if (rc)
        return rc;

    out->n = 0;
    out->nleave = 0;
    out->nseeded = 0;
    out->ndir = tr->ndir;
    out->shared = c && c->share && c->shared;
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
    const int ident = dense && nslow == 0 && ne == nc;
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
        rs_motion_field(m, mr.V, mr.W, mr.C);
        for (int b = 0; b < 3; b++)
            mr.U[b] = m->belt[b];
        mr.Umag = sqrt(rs_dot3(mr.U, mr.U));
        mr.belt = mr.Umag > 0.0;
        mr.m = m;
    } else {
        mr.Q[0] = mr.Q[4] = mr.Q[8] = 1.0;
    }

    out->nleave = 0;
    if (tr->ndir == 3)
        emit_all(tr, &mr, dt, p, c, out, ne, ident, 3);
    else
        emit_all(tr, &mr, dt, p, c, out, ne, ident, 2);
    out->n = ne;
    return RS_OK;
}
