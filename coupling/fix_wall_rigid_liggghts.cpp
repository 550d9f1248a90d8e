/* fix wall/rigid, law liggghts: one block's contacts through LIGGGHTS's contact model
 * (liggghts_law.h), in place of the law call and the loads from the stress. */
#include "fix_wall_rigid.h"
#include "liggghts_law.h"

#include "atom.h"
#include "update.h"

#include <algorithm>
#include <cstring>
#include <mpi.h>

using namespace LAMMPS_NS;

/* Each live contact: the model's force F and torque T on the particle, times the
 * contact's share (at a concave fold, docs/conventions.md); the wall gets -F and the
 * moment -((x - o) x F + T) about the surface origin, so the pair's angular momentum is
 * kept whatever torque the model gives (rolling friction). The stress the per-atom
 * output and the facets see is F in the contact's frame: F = s1 n - s2 t1 - s3 t2. The
 * model's history is the contact's state variables (cb_.statev, committed by the
 * caller). */
void FixWallRigid::liggghts_block(const int *idx, int n, int ne, bool setup_call)
{
    double **v = atom->v, **omega = atom->omega, **f = atom->f, **torque = atom->torque;
    const int nd = ndir_, ns = nstatev_;
    double origin[3];
    rs_pose_to_global(&motion_.pose, surf_.a, origin);
    if (area_w_.size() < (size_t)ne)
        area_w_.resize((size_t)ne);
    for (int k = 0; k < n; k++)
        deepest_[k] = -1;
    for (int e = 0; e < ne; e++) {
        const int k = tout_.point[e];
        const int i = idx[k];
        const char lv = RS_DIR_IS_LEAVING(*tout_.dir[e]);
        leaving_[e] = lv;
        area_w_[e] = tout_.share[e];
        double *s = cb_.stress + (size_t)e * nd;
        for (int d = 0; d < nd; d++)
            s[d] = 0.0;
        if (lv)
            continue;
        /* The frame in 3D: a SEGMENTS profile's plane is z = const, t2 = -ez. */
        const double *L = tout_.alocaldir + (size_t)e * nd * nd;
        const double *xm = tout_.coordmst + (size_t)e * nd;
        double nrm[3], t1[3], t2[3], xm3[3];
        if (nd == 3) {
            for (int d = 0; d < 3; d++)
                nrm[d] = L[d], t1[d] = L[3 + d], t2[d] = L[6 + d], xm3[d] = xm[d];
        } else {
            nrm[0] = L[0], nrm[1] = L[1], nrm[2] = 0.0;
            t1[0] = L[2], t1[1] = L[3], t1[2] = 0.0;
            t2[0] = 0.0, t2[1] = 0.0, t2[2] = -1.0;
            xm3[0] = xm[0], xm3[1] = xm[1], xm3[2] = bz_[k];
        }
        LiggghtsContact c;
        c.i = i;
        c.radius = brad_[k];
        c.overlap = tout_.rdisp[(size_t)e * nd];
        c.normal = nrm;
        c.v = v[i];
        c.omega = omega[i];
        c.vwall[0] = c.vwall[1] = c.vwall[2] = 0.0;
        if (moving_)
            rs_motion_velocity_at(&motion_, xm3, c.vwall);
        if (belt_) {
            double u[3];
            rs_motion_belt_at(&motion_, nrm, u);
            for (int d = 0; d < 3; d++)
                c.vwall[d] += u[d];
        }
        c.history = ns ? cb_.statev + (size_t)e * ns : NULL;
        c.itype = btype_[k];
        c.jtype = wall_type_;
        c.mass = bmass_[k];
        c.update_history = !setup_call;
        double F[3], T[3];
        const LiggghtsLaw::Result got = lig_->contact(c, F, T);
        if (got == LiggghtsLaw::kNotFinite)
            fail_one(lig_->failure());
        if (got == LiggghtsLaw::kNone)
            continue;
        s[0] = F[0] * nrm[0] + F[1] * nrm[1] + F[2] * nrm[2];
        s[1] = -(F[0] * t1[0] + F[1] * t1[1] + F[2] * t1[2]);
        if (nd == 3)
            s[2] = -(F[0] * t2[0] + F[1] * t2[1] + F[2] * t2[2]);
        const double w = area_w_[e];
        for (int d = 0; d < 3; d++)
            F[d] *= w, T[d] *= w;
        double *fi = f[i], *ti = torque[i];
        for (int d = 0; d < 3; d++)
            fi[d] += F[d], ti[d] += T[d], f_wall_[d] -= F[d];
        if (wallforce_)
            for (int d = 0; d < 3; d++)
                wallforce_[i][d] += F[d];
        const double r[3] = {bx_[k] - origin[0], by_[k] - origin[1], bz_[k] - origin[2]};
        m_wall_[0] -= r[1] * F[2] - r[2] * F[1] + T[0];
        m_wall_[1] -= r[2] * F[0] - r[0] * F[2] + T[1];
        m_wall_[2] -= r[0] * F[1] - r[1] * F[0] + T[2];
        ncontact_ += c.overlap > 0.0;
        const int dk = deepest_[k];
        if (dk < 0 || c.overlap > tout_.rdisp[(size_t)dk * nd])
            deepest_[k] = e;
    }
    load_area_ = area_w_.data();

    /* Per-atom output: the deepest contact that applied a force, zeros otherwise. */
    if (array_atom)
        put_outputs(idx, n, nd, deepest_.data(), NULL);
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
