/* What one call's contacts do: each contact's force and torque on its particle, the
 * wall's force and moment, and the energies and heat, from the law's stress in the
 * tracker's frame. rs_cblock_loads gives them per contact; rs_cblock_add_loads adds them
 * onto the engine's per-particle rows in the same pass. One kernel (loads) does both. */
#include "rigidsurf/contact_block.h"
#include "rigidsurf/vec.h"

#include "load_contact.h"
#include "rs_compiler.h"

#include <string.h>

/* Every contact's area is 1 and every share 1: the products with w A are dropped (they
 * are exact). */
static int unit_area(const rs_contact_block *cb, const rs_track_out *o,
                     const rs_particle_block *p)
{
    return !(o->shared && o->share) && !p->area &&
           (cb->area_mode == RS_AREA_NODE ||
            (cb->area_mode == RS_AREA_CONSTANT && cb->area_const == 1.0));
}

/* The law of the last call wrote zero heat flows and zero creep and plastic dissipation
 * for every contact (rs_law.sets): their sums are zero without reading them. */
static int lean_law(const rs_contact_block *cb)
{
    const unsigned both = RS_LAW_SETS_NO_HEAT | RS_LAW_SETS_NO_CREEP_PLASTIC;
    return (cb->law_sets & both) == both;
}

/* The kernel: ND the tracker's ndir (2: the plane z = const, t2 = -ez, the contact point
 * keeps the particle's z); LEAVE: some contacts are leaving (they apply nothing); UNIT:
 * unit_area; LEAN: lean_law (fluxSlv, fluxMst, scd, spd are zero and not read); ROWS:
 * add onto rows (else write per contact into f, t, q). Each is a constant in each
 * copy. */
RS_INLINE void loads(const rs_contact_block *cb, const rs_track_out *o,
                     const rs_particle_block *p, const double origin[3], double *f,
                     double *t, double *q, const rs_load_rows *rows, rs_wall_load *w,
                     const int ND, const int LEAVE, const int UNIT, const int LEAN,
                     const int ROWS, const int FORCE)
{
    const int ne = o->n;
    const int *restrict pt = o->point;
    const double *restrict px = p->x, *restrict py = p->y, *restrict pz = p->z;
    const double *restrict L0 = o->alocaldir, *restrict X0 = o->coordslv,
                           *restrict rdisp = o->rdisp, *restrict stress = cb->stress;
    const double *restrict area = cb->area, *restrict share = o->share;
    const double *restrict sed = cb->sed, *restrict sfd = cb->sfd, *restrict spd = cb->spd,
                           *restrict svd = cb->svd, *restrict scd = cb->scd,
                           *restrict fslv = cb->flux_slv, *restrict fmst = cb->flux_mst;
    const int *restrict row = ROWS ? rows->row : NULL;
    double *restrict qr = ROWS ? rows->q : NULL;
    int *restrict deepest = ROWS ? rows->deepest : NULL;
    if (deepest)
        for (int k = 0; k < p->n; k++)
            deepest[k] = -1;
    rs_wall_acc acc = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    double se = 0.0, fd = 0.0, pd = 0.0, vd = 0.0, cd = 0.0, qs = 0.0, qm = 0.0;
    int ncontact = 0;
    for (int e = 0; e < ne; e++) {
        if (LEAVE && RS_DIR_IS_LEAVING(*o->dir[e])) {
            if (!ROWS) {
                double *fe = f + 3 * (size_t)e, *te = t + 3 * (size_t)e;
                fe[0] = fe[1] = fe[2] = te[0] = te[1] = te[2] = 0.0;
                if (q)
                    q[e] = 0.0;
            }
            continue;
        }
        const int k = pt[e];
        const double A = UNIT ? 1.0 : area[e] * share[e]; /* its share of its area */
        const double *s = stress + (size_t)e * ND;
        const double *L = L0 + (size_t)e * ND * ND; /* columns n, t1[, t2] */
        const double *xc = X0 + (size_t)e * ND;
        double F[3], x[3], T[3], M[3];
        const double c[3] = {px[k], py[k], pz[k]};
        if (FORCE) {
            rs_load_force_law(A, cb->force + 3 * (size_t)e, cb->torque + 3 * (size_t)e, c,
                              origin, F, T, M);
        } else {
            if (ND == 3) {
                rs_load_force3(A, s, L, F);
                x[0] = xc[0], x[1] = xc[1], x[2] = xc[2];
            } else {
                F[0] = A * (s[0] * L[0] - s[1] * L[2]);
                F[1] = A * (s[0] * L[1] - s[1] * L[3]);
                F[2] = 0.0;
                x[0] = xc[0], x[1] = xc[1], x[2] = pz[k];
            }
            rs_load_torques(F, x, c, origin, T, M);
        }
        rs_wall_acc_take(&acc, F, M);
        const double qe = LEAN ? 0.0 : A * fslv[e];
        if (ROWS) {
            const int rk = row ? row[k] : k;
            rs_load_onto_row(rows, rk, F, T);
            if (!LEAN && qr)
                qr[rk] += qe;
        } else {
            double *fe = f + 3 * (size_t)e, *te = t + 3 * (size_t)e;
            fe[0] = F[0], fe[1] = F[1], fe[2] = F[2];
            te[0] = T[0], te[1] = T[1], te[2] = T[2];
            if (q)
                q[e] = qe;
        }
        se += A * sed[e];
        fd += A * sfd[e];
        vd += A * svd[e];
        if (!LEAN) {
            pd += A * spd[e];
            cd += A * scd[e];
            qs += qe;
            qm += A * fmst[e];
        }
        const double rd1 = rdisp[(size_t)e * ND];
        ncontact += rd1 > 0.0;
        if (deepest) {
            const int d = deepest[k];
            if (d < 0 || rd1 > rdisp[(size_t)d * ND])
                deepest[k] = e;
        }
    }
    w->force[0] = acc.fw0, w->force[1] = acc.fw1, w->force[2] = acc.fw2;
    w->moment[0] = acc.mw0, w->moment[1] = acc.mw1, w->moment[2] = acc.mw2;
    w->se = se, w->fd = fd, w->pd = pd, w->vd = vd, w->cd = cd;
    w->flux_slv = qs, w->flux_mst = qm;
    w->ncontact = ncontact;
}

/* The kernel's copies for leaving and unit area, for one ND and LEAN (one loop for both
 * kinds of block, testing for leaving contacts, executes an eighth more in the fix). */
RS_INLINE void by_leave_unit(const rs_contact_block *cb, const rs_track_out *o,
                             const rs_particle_block *p, const double origin[3], double *f,
                             double *t, double *q, const rs_load_rows *rows,
                             rs_wall_load *w, const int ND, const int LEAN, const int ROWS,
                             const int FORCE)
{
    const int unit = unit_area(cb, o, p);
    if (o->nleave > 0) {
        if (unit)
            loads(cb, o, p, origin, f, t, q, rows, w, ND, 1, 1, LEAN, ROWS, FORCE);
        else
            loads(cb, o, p, origin, f, t, q, rows, w, ND, 1, 0, LEAN, ROWS, FORCE);
    } else {
        if (unit)
            loads(cb, o, p, origin, f, t, q, rows, w, ND, 0, 1, LEAN, ROWS, FORCE);
        else
            loads(cb, o, p, origin, f, t, q, rows, w, ND, 0, 0, LEAN, ROWS, FORCE);
    }
}

/* ...and for each ndir and (3D) lean law. */
RS_INLINE void dispatch(const rs_contact_block *cb, const rs_track_out *o,
                        const rs_particle_block *p, const double origin[3], double *f,
                        double *t, double *q, const rs_load_rows *rows, rs_wall_load *w,
                        const int ROWS)
{
    if (cb->law_sets & RS_LAW_SETS_FORCE) /* the force law's own F and T, any nDir */
        by_leave_unit(cb, o, p, origin, f, t, q, rows, w, o->ndir == 2 ? 2 : 3, 0, ROWS, 1);
    else if (o->ndir == 2)
        by_leave_unit(cb, o, p, origin, f, t, q, rows, w, 2, 0, ROWS, 0);
    else if (lean_law(cb))
        by_leave_unit(cb, o, p, origin, f, t, q, rows, w, 3, 1, ROWS, 0);
    else
        by_leave_unit(cb, o, p, origin, f, t, q, rows, w, 3, 0, ROWS, 0);
}

void rs_cblock_loads(const rs_contact_block *cb, const rs_track_out *o,
                     const rs_particle_block *p, const double origin[3], double *f,
                     double *t, double *q, rs_wall_load *w)
{
    dispatch(cb, o, p, origin, f, t, q, NULL, w, 0);
}

void rs_cblock_add_loads(const rs_contact_block *cb, const rs_track_out *o,
                         const rs_particle_block *p, const double origin[3],
                         const rs_load_rows *rows, rs_wall_load *w)
{
    dispatch(cb, o, p, origin, NULL, NULL, NULL, rows, w, 1);
}
