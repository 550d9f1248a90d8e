/* fix wall/rigid, law liggghts: LIGGGHTS's contact model (liggghts_law.h) as a force law of
 * the wall (RS_LAW_SETS_FORCE): each live contact of a block described as LIGGGHTS's walls
 * describe it (rs_wall_force_contact), the model's force F and torque T on the particle as
 * the law's force and torque, which the wall applies times the contact's share (at a
 * concave fold, docs/conventions.md), with -F and the moment -((x - o) x F + T) on the
 * wall, so the pair's angular momentum is kept whatever torque the model gives (rolling
 * friction). The stress the outputs and the facets see is F in the contact's frame: F = s1
 * n - s2 t1 - s3 t2. The model's history is the contact's state variables. */
#include "fix_wall_rigid.h"
#include "liggghts_law.h"

#include "atom.h"

#include <algorithm>
#include <cstring>
#include <mpi.h>

using namespace LAMMPS_NS;

int FixWallRigid::liggghts_update(rs_law_block *b, rs_error *err)
{
    rs_wall_force_begin(b);
    for (int e = 0; e < b->nSlvNod; e++) {
        rs_force_contact c;
        if (!rs_wall_force_contact(wall_, b, e, atom->x[0], &c))
            continue;
        double F[3], T[3];
        const int got = liggghts_one(c, F, T, err);
        if (got < 0)
            return -got;
        if (got)
            rs_wall_force_result(b, e, &c, F, T);
    }
    return RS_OK;
}

int FixWallRigid::liggghts_one(rs_force_contact &c, double F[3], double T[3], rs_error *err)
{
    LiggghtsContact lc;
    lc.i = c.row;
    lc.radius = c.radius;
    lc.overlap = c.overlap;
    lc.normal = c.n;
    lc.v = atom->v[c.row];
    lc.omega = atom->omega[c.row];
    for (int d = 0; d < 3; d++)
        lc.vwall[d] = c.vwall[d];
    lc.history = c.history;
    lc.itype = c.type;
    lc.jtype = c.wall_type;
    lc.mass = c.mass;
    lc.update_history = !c.setup;
    const LiggghtsLaw::Result got = lig_->contact(lc, F, T);
    if (got == LiggghtsLaw::kNotFinite)
        return -rs_error_set(err, RS_ERR_NONFINITE, "%s", lig_->failure().c_str());
    return got == LiggghtsLaw::kForce;
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
