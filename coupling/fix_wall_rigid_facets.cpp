/* fix wall/rigid on a faceted master: per-facet stress and Finnie wear, as LIGGGHTS's
 * `fix mesh/surface/stress ... wear finnie` keeps them per triangle.
 *
 * - Stress: on the steps the VTK is written, the force every contact puts on the wall
 *   is summed per facet (the facet under the contact, rs_surface_facet_index); sigma_n
 *   = |f . n| / A and sigma_t = |f - (f . n) n| / A with the facet's area A and normal n.
 * - Wear (`wear finnie`): each step, a contact whose particle moves toward the wall
 *   (v_rel . (x_cp - x) >= 0, v_rel = the particle's centre velocity minus the wall's
 *   velocity at the contact point) adds 2 k |v_rel| |F| E(gamma) dt / A to its facet,
 *   with gamma the angle between v_rel and the facet's plane and Finnie's
 *   E = sin 2 gamma - 3 sin^2 gamma for tan gamma <= 1/3, cos^2 gamma / 3 beyond; k is
 *   the `k_finnie` of the particle and wall types (fix property/global k_finnie
 *   peratomtypepair). The wear accumulates from the fix's definition and is written to
 *   restart files.
 * Each rank sums its own contacts; totals are reduced for the VTK and the restart. */
#include "fix_wall_rigid.h"

#include "atom.h"
#include "comm.h"
#include "fix_property_global.h"
#include "force.h"
#include "modify.h"
#include "update.h"

#include <cmath>
#include <cstring>
#include <sstream>

using namespace LAMMPS_NS;

/* Finnie's angle function E(gamma) of an impact at gamma to the surface's plane, from
 * sin gamma and cos gamma. */
static double finnie(double sg, double cg)
{
    if (3.0 * sg > cg) /* tan gamma > 1/3 */
        return cg * cg / 3.0;
    return 2.0 * sg * cg - 3.0 * sg * sg;
}

void FixWallRigid::init_facets()
{
    facets_ = rs_surface_has_facets(&surf_) && (vtk_every_ > 0 || wear_);
    if (!facets_)
        return;
    const int nf = rs_surface_facet_count(&surf_);
    if (nf != nfacet_) {
        nfacet_ = nf;
        elem_area_.assign((size_t)nf, 0.0);
        elem_n_.assign(3 * (size_t)nf, 0.0);
        elem_f_.assign(3 * (size_t)nf, 0.0);
        if (wear_el_.size() != (size_t)nf)
            wear_el_.assign((size_t)nf, 0.0);
        for (int k = 0; k < nf; k++)
            rs_surface_facet_area(&surf_, k, &elem_area_[k], &elem_n_[3 * (size_t)k]);
    }
    if (wear_) {
        const int max_type = force->registry.max_type();
        FixPropertyGlobal *kf = static_cast<FixPropertyGlobal *>(
            modify->find_fix_property("k_finnie", "property/global", "peratomtypepair",
                                      max_type, max_type, "fix wall/rigid (wear finnie)"));
        kfinnie_.assign((size_t)atom->ntypes + 1, 0.0);
        for (int t = 1; t <= atom->ntypes && t <= max_type; t++)
            kfinnie_[t] = kf->compute_array(wall_type_ - 1, t - 1);
    }
}

/* At the start of a step's force computation: is this a step whose facet stresses the
 * VTK writes? Then the sums start from zero. */
void FixWallRigid::begin_facets()
{
    stress_step_ = facets_ && vtk_every_ > 0 && update->ntimestep % vtk_every_ == 0;
    if (stress_step_)
        std::fill(elem_f_.begin(), elem_f_.end(), 0.0);
}

/* The block's contacts [0, ne) after the law: their forces on the wall into the facets'
 * sums (stress steps) and their wear (not in a setup call, which is no increment). */
void FixWallRigid::facet_pass(const int *idx, int ne, bool setup_call)
{
    const bool wear = wear_ && !setup_call;
    if (!stress_step_ && !wear)
        return;
    const int nd = ndir_;
    const double dt = update->dt;
    const int *type = atom->type;
    for (int e = 0; e < ne; e++) {
        if (leaving_[e])
            continue;
        const int el = rs_surface_facet_index(&surf_, tout_.feature[e]);
        if (el < 0)
            continue;
        const int k = tout_.point[e];
        const double A = load_area_[e]; // area times share
        const double *s = cb_.stress + (size_t)e * nd;
        const double *L = tout_.alocaldir + (size_t)e * nd * nd; // columns n, t1, t2
        double F[3];                                             // on the particle
        for (int d = 0; d < 3; d++)
            F[d] = A * (s[0] * L[d] - s[1] * L[3 + d] - s[2] * L[6 + d]);
        if (stress_step_)
            for (int d = 0; d < 3; d++)
                elem_f_[3 * (size_t)el + d] -= F[d];
        if (!wear)
            continue;
        const double *xc = tout_.coordslv + (size_t)e * nd;
        double vw[3] = {0.0, 0.0, 0.0}, belt[3];
        if (moving_)
            rs_motion_velocity_at(&motion_, xc, vw);
        if (belt_) {
            rs_motion_belt_at(&motion_, L, belt);
            for (int d = 0; d < 3; d++)
                vw[d] += belt[d];
        }
        const double vr[3] = {bvx_[k] - vw[0], bvy_[k] - vw[1], bvz_[k] - vw[2]};
        const double c[3] = {xc[0] - bx_[k], xc[1] - by_[k], xc[2] - bz_[k]};
        if (c[0] * vr[0] + c[1] * vr[1] + c[2] * vr[2] < 0.0)
            continue; /* moving away from the wall */
        const double vmag = std::sqrt(vr[0] * vr[0] + vr[1] * vr[1] + vr[2] * vr[2]);
        if (!(vmag > 0.0))
            continue;
        double n[3];
        rs_pose_rotate(&motion_.pose, &elem_n_[3 * (size_t)el], n);
        const double vn = vr[0] * n[0] + vr[1] * n[1] + vr[2] * n[2];
        const double cx[3] = {vr[1] * n[2] - vr[2] * n[1], vr[2] * n[0] - vr[0] * n[2],
                              vr[0] * n[1] - vr[1] * n[0]};
        const double sg = std::fmin(1.0, std::fabs(vn) / vmag);
        const double cg =
            std::fmin(1.0, std::sqrt(cx[0] * cx[0] + cx[1] * cx[1] + cx[2] * cx[2]) / vmag);
        const double fmag = std::sqrt(F[0] * F[0] + F[1] * F[1] + F[2] * F[2]);
        const double kf = kfinnie_[type[idx[k]]];
        wear_el_[el] += 2.0 * kf * vmag * fmag * finnie(sg, cg) * dt / elem_area_[el];
    }
}

/* The facets' sigma_n, sigma_t and wear over all ranks, on rank 0 (collective). */
void FixWallRigid::reduce_facets(std::vector<double> &sn, std::vector<double> &st,
                                 std::vector<double> &wear)
{
    const int nf = nfacet_;
    std::vector<double> f(3 * (size_t)nf, 0.0);
    MPI_Reduce(elem_f_.data(), f.data(), 3 * nf, MPI_DOUBLE, MPI_SUM, 0, world);
    if (wear_) {
        wear.assign((size_t)nf, 0.0);
        MPI_Reduce(wear_el_.data(), wear.data(), nf, MPI_DOUBLE, MPI_SUM, 0, world);
    }
    if (comm->me != 0)
        return;
    sn.assign((size_t)nf, 0.0);
    st.assign((size_t)nf, 0.0);
    for (int k = 0; k < nf; k++) {
        double n[3];
        rs_pose_rotate(&motion_.pose, &elem_n_[3 * (size_t)k], n);
        const double *fk = &f[3 * (size_t)k];
        const double fn = fk[0] * n[0] + fk[1] * n[1] + fk[2] * n[2];
        const double ft[3] = {fk[0] - fn * n[0], fk[1] - fn * n[1], fk[2] - fn * n[2]};
        sn[k] = std::fabs(fn) / elem_area_[k];
        st[k] = std::sqrt(ft[0] * ft[0] + ft[1] * ft[1] + ft[2] * ft[2]) / elem_area_[k];
    }
}
