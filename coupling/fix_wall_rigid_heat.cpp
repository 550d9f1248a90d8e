/* fix wall/rigid, conduction liggghts: LIGGGHTS's conduction between a wall at its
 * temperature and the particles that touch it, as fix wall/gran computes it under fix
 * heat/gran (fix_wall_gran.cpp, init_heattransfer and addHeatFlux). */
#include "fix_wall_rigid.h"

#include "atom.h"
#include "fix_property_atom.h"
#include "fix_property_global.h"
#include "modify.h"

#include <cmath>

using namespace LAMMPS_NS;

/* The properties fix wall/gran reads: thermalConductivity per atom type (an error when it
 * is missing, as LIGGGHTS's), and heat/gran/conduction's area correction, the overlap
 * ratio it keeps in youngsModulusOriginal's modified array (NULL unless both exist;
 * LIGGGHTS takes the pointer at init, as here). */
void FixWallRigid::init_conduction()
{
    th_cond_ = NULL;
    deltan_ratio_ = NULL;
    if (!conduction_)
        return;
    if (!fix_temp_ || !fix_heatflux_)
        fail("keyword 'conduction liggghts' needs fix heat/gran (the per-atom Temp and "
             "heatFlux it keeps)");
    th_cond_ = static_cast<FixPropertyGlobal *>(
                   modify->find_fix_property("thermalConductivity", "property/global",
                                             "peratomtype", 0, 0, style))
                   ->get_values();
    Fix *ymo = modify->find_fix_property("youngsModulusOriginal", "property/global",
                                         "peratomtype", 0, 0, style, false);
    if (ymo && modify->n_fixes_style("heat/gran/conduction") > 0)
        deltan_ratio_ = static_cast<FixPropertyGlobal *>(ymo)->get_array_modified();
}

/* Each touching contact of the block (overlap delta >= 0, not leaving): the contact area
 * A = pi (R^2 - (R - delta)^2), delta times the area correction of the particle and wall
 * types (contact_area overlap, the default), or pi R^2 (projection), or the constant
 * given; the conductance h = 4 k_p k_w / (k_p + k_w) sqrt(A) (0 when either
 * conductivity is below 1e-12); the heat flow w h (T_wall - T_p) into the particle's
 * heatFlux (w: the contact's share, 1 but at a concave fold), and its opposite into the
 * wall (not in a setup call, whose heat is not accumulated). LIGGGHTS's wall starts to
 * conduct at the end of its first setup (FixWallGran::setup calls init_heattransfer after
 * its forces), so it adds the flow to heatFlux in the setup calls of later runs only;
 * fix heat/gran clears heatFlux before the step. */
void FixWallRigid::conduct(const int *idx, int ne, bool setup_call)
{
    if (setup_call && !conduct_ready_)
        return;
    const int nd = ndir_;
    const int *type = atom->type;
    const double *Temp = fix_temp_->vector_atom;
    double *heatflux = fix_heatflux_->vector_atom;
    const double tcowall = th_cond_[wall_type_ - 1];
    const double small = 1e-12;
    double into_wall = 0.0;
    for (int e = 0; e < ne; e++) {
        const double delta0 = tout_.rdisp[(size_t)e * nd];
        if (leaving_[e] || !(delta0 >= 0.0))
            continue;
        const int k = tout_.point[e];
        const int i = idx[k];
        const int itype = type[i];
        const double ri = brad_[k];
        double area;
        if (carea_mode_ == CAREA_OVERLAP) {
            double delta = delta0;
            if (deltan_ratio_)
                delta *= deltan_ratio_[itype - 1][wall_type_ - 1];
            const double r = ri - delta;
            area = (ri * ri - r * r) * M_PI * 1.0;
        } else if (carea_mode_ == CAREA_PROJECTION) {
            area = M_PI * ri * ri;
        } else {
            area = carea_const_;
        }
        const double tcop = th_cond_[itype - 1];
        double hc;
        if (std::fabs(tcop) < small || std::fabs(tcowall) < small)
            hc = 0.0;
        else
            hc = 4. * tcop * tcowall / (tcop + tcowall) * std::sqrt(area);
        const double hf = (temp_wall_ - Temp[i]) * hc * tout_.share[e];
        heatflux[i] += hf;
        into_wall -= hf;
    }
    if (!setup_call)
        heat_step_ += into_wall;
}
