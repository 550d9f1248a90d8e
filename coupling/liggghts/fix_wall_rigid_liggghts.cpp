/* fix wall/rigid, law liggghts: LIGGGHTS's contact model (liggghts_law.h) as a force law of
 * the wall (RS_LAW_SETS_FORCE): each live contact of a block described as LIGGGHTS's walls
 * describe it, the model's force F and torque T on the particle as the law's force and
 * torque, which the wall applies times the contact's share (at a concave fold,
 * docs/conventions.md), with -F and the moment -((x - o) x F + T) on the wall, so the
 * pair's angular momentum is kept whatever torque the model gives (rolling friction). The
 * stress the outputs and the facets see is F in the contact's frame: F = s1 n - s2 t1 - s3
 * t2. The model's history is the contact's state variables. */
#include "fix_wall_rigid.h"
#include "liggghts_law.h"

#include "atom.h"

#include <algorithm>
#include <cstring>
#include <mpi.h>

using namespace LAMMPS_NS;

int FixWallRigid::liggghts_update(rs_law_block *b, rs_error *err)
{
    double **v = atom->v, **omega = atom->omega, **x = atom->x;
    const int nd = b->nDir, ns = b->nStateVar;
    const rs_motion *motion = rs_wall_motion(wall_);
    const bool belt =
        motion->belt[0] != 0.0 || motion->belt[1] != 0.0 || motion->belt[2] != 0.0;
    for (int e = 0; e < b->nSlvNod; e++) {
        double *s = b->stress + (size_t)e * nd, *F = b->force + 3 * (size_t)e,
               *T = b->torque + 3 * (size_t)e;
        for (int d = 0; d < nd; d++)
            s[d] = 0.0;
        for (int d = 0; d < 3; d++)
            F[d] = T[d] = 0.0;
        b->fluxSlv[e] = b->fluxMst[e] = b->sed[e] = 0.0;
        b->sfd[e] = b->scd[e] = b->spd[e] = b->svd[e] = 0.0;
        const double overlap = b->rdisp[(size_t)e * nd];
        if (overlap >= 0.5 * RS_MAXVAL) /* a leaving contact: nothing */
            continue;
        const int i = b->slvRow[e];
        /* The frame in 3D: a SEGMENTS profile's plane is z = const, t2 = -ez. */
        const double *L = b->alocaldir + (size_t)e * nd * nd;
        const double *xm = b->coordMst + (size_t)e * nd;
        double nrm[3], t1[3], t2[3], xm3[3];
        if (nd == 3) {
            for (int d = 0; d < 3; d++)
                nrm[d] = L[d], t1[d] = L[3 + d], t2[d] = L[6 + d], xm3[d] = xm[d];
        } else {
            nrm[0] = L[0], nrm[1] = L[1], nrm[2] = 0.0;
            t1[0] = L[2], t1[1] = L[3], t1[2] = 0.0;
            t2[0] = 0.0, t2[1] = 0.0, t2[2] = -1.0;
            xm3[0] = xm[0], xm3[1] = xm[1], xm3[2] = x[i][2];
        }
        LiggghtsContact c;
        c.i = i;
        c.radius = b->radius[e];
        c.overlap = overlap;
        c.normal = nrm;
        c.v = v[i];
        c.omega = omega[i];
        c.vwall[0] = c.vwall[1] = c.vwall[2] = 0.0;
        if (info_->moving)
            rs_motion_velocity_at(motion, xm3, c.vwall);
        if (belt) {
            double u[3];
            rs_motion_belt_at(motion, nrm, u);
            for (int d = 0; d < 3; d++)
                c.vwall[d] += u[d];
        }
        c.history = ns ? b->statev + (size_t)e * ns : NULL;
        c.itype = b->slv_type ? b->slv_type[e] : 1;
        c.jtype = b->wall_type;
        c.mass = b->mass[e];
        c.update_history = !b->setup;
        const LiggghtsLaw::Result got = lig_->contact(c, F, T);
        if (got == LiggghtsLaw::kNotFinite)
            return rs_error_set(err, RS_ERR_NONFINITE, "%s", lig_->failure().c_str());
        if (got == LiggghtsLaw::kNone)
            continue;
        s[0] = F[0] * nrm[0] + F[1] * nrm[1] + F[2] * nrm[2];
        s[1] = -(F[0] * t1[0] + F[1] * t1[1] + F[2] * t1[2]);
        if (nd == 3)
            s[2] = -(F[0] * t2[0] + F[1] * t2[1] + F[2] * t2[2]);
    }
    return RS_OK;
}

/* The default tracking thickness of law liggghts: LIGGGHTS calls its model for contacts
 * apart by less than (contact distance factor - 1) R (cohesion through liquid bridges),
 * else for touching ones only. R: the group's largest radius at init. */
double FixWallRigid::liggghts_reach() const
{
    const double cf = lig_->close_factor();
    if (!(cf > 1.0))
        return 0.0;
    double rmax = 0.0;
    const int *mask = atom->mask;
    for (int i = 0; i < atom->nlocal; i++)
        if (mask[i] & groupbit)
            rmax = std::max(rmax, atom->radius[i]);
    double rall = 0.0;
    MPI_Allreduce(&rmax, &rall, 1, MPI_DOUBLE, MPI_MAX, world);
    return (cf - 1.0) * rall;
}
