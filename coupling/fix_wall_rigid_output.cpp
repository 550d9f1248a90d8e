/* fix wall/rigid: outputs: the global vector (collective), the wall's VTK file, and the
 * per-atom fields kept from the previous increment. */
#include "fix_wall_rigid.h"
#include "rigidsurf/vec.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_property_atom.h"
#include "modify.h"
#include "update.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>

using namespace LAMMPS_NS;

void FixWallRigid::update_previous_fields()
{
    const int nlocal = atom->nlocal;
    const int *mask = atom->mask;
    const double *Temp = fix_temp_ ? fix_temp_->vector_atom : NULL;
    const int npred = (int)predef_fix_.size();
    if (!Temp && npred == 0)
        return;
    for (int i = 0; i < nlocal; i++) {
        if (!(mask[i] & groupbit))
            continue;
        if (Temp)
            row_[i][tprev_offset()] = Temp[i];
        for (int a = 0; a < npred; a++)
            row_[i][pred_offset() + a] = predef_fix_[a]->vector_atom[i];
    }
}

/* store_force: this step's array of the per-atom vector, zeroed for the local atoms by
 * the first fix that stores into it; the blocks add each contact's force on its particle
 * (as fix wall/gran does, in setup calls too). */
void FixWallRigid::begin_wallforce()
{
    wallforce_ = NULL;
    if (!store_force_)
        return;
    const int ifix = modify->find_fix(wallforce_id_.c_str());
    if (ifix < 0)
        fail("store_force: fix " + wallforce_id_ + " (the stored force) was deleted");
    wallforce_ = static_cast<FixPropertyAtom *>(modify->fix[ifix])->array_atom;
    if (!wallforce_clear_)
        return;
    const int nlocal = atom->nlocal;
    for (int i = 0; i < nlocal; i++)
        wallforce_[i][0] = wallforce_[i][1] = wallforce_[i][2] = 0.0;
}

/* Legacy VTK polydata of the surface in its current pose; '*' in the name becomes the
 * step. Written by rank 0 (every rank holds the same surface and pose). */
void FixWallRigid::write_vtk()
{
    if (!vtk_mesh_ok_)
        return;
    /* a MESH's facets carry their stress (and wear) as cell data: reduced first, by
     * every rank */
    std::vector<double> sn, st, wear;
    const bool cells = facets_ && vtk_mesh_.cell;
    if (cells)
        reduce_facets(sn, st, wear);
    if (comm->me != 0)
        return;
    std::string name = vtk_file_;
    const size_t star = name.find('*');
    if (star != std::string::npos) {
        std::ostringstream o;
        o << update->ntimestep;
        name.replace(star, 1, o.str());
    }
    FILE *fp = std::fopen(name.c_str(), "w");
    if (!fp)
        fail_one("keyword 'vtk': cannot open '" + name +
                 "' for writing: " + std::strerror(errno));
    std::fprintf(fp,
                 "# vtk DataFile Version 2.0\nfix wall/rigid %s step " BIGINT_FORMAT
                 "\nASCII\nDATASET POLYDATA\nPOINTS %d double\n",
                 id, update->ntimestep, vtk_mesh_.nvert);
    for (int v = 0; v < vtk_mesh_.nvert; v++) {
        double X[3];
        rs_pose_to_global(&motion_.pose, &vtk_mesh_.xyz[3 * v], X);
        std::fprintf(fp, "%.10g %.10g %.10g\n", X[0], X[1], X[2]);
    }
    std::fprintf(fp, "POLYGONS %d %d\n", vtk_mesh_.ntri, 4 * vtk_mesh_.ntri);
    for (int t = 0; t < vtk_mesh_.ntri; t++)
        std::fprintf(fp, "3 %d %d %d\n", vtk_mesh_.tri[3 * t], vtk_mesh_.tri[3 * t + 1],
                     vtk_mesh_.tri[3 * t + 2]);
    if (cells) {
        std::fprintf(fp, "CELL_DATA %d\n", vtk_mesh_.ntri);
        const std::vector<double> *data[3] = {&sn, &st, &wear};
        const char *names[3] = {"sigma_n", "sigma_t", "wear"};
        for (int a = 0; a < (wear_ ? 3 : 2); a++) {
            std::fprintf(fp, "SCALARS %s double 1\nLOOKUP_TABLE default\n", names[a]);
            for (int t = 0; t < vtk_mesh_.ntri; t++)
                std::fprintf(fp, "%.17g\n", (*data[a])[(size_t)vtk_mesh_.cell[t]]);
        }
    }
    std::fclose(fp);
}

/* ---------------------------------------------------------------------------------- */
/* Output                                                                             */

double FixWallRigid::compute_vector(int n)
{
    if (!out_valid_ || out_step_ != update->ntimestep) {
        double loc[13], all[13];
        for (int d = 0; d < 3; d++) {
            loc[d] = f_wall_[d];
            loc[3 + d] = m_wall_[d];
        }
        loc[6] = ncontact_;
        loc[7] = se_now_;
        for (int d = 0; d < 4; d++)
            loc[8 + d] = diss_[d];
        loc[12] = heat_wall_;
        MPI_Allreduce(loc, all, 13, MPI_DOUBLE, MPI_SUM, world);
        for (int d = 0; d < 12; d++)
            out_[d] = all[d];
        out_[12] = temp_wall_;
        out_[13] = all[12];
        for (int d = 0; d < 3; d++)
            out_[14 + d] = motion_.disp[d];
        out_[17] = motion_.phi;
        out_valid_ = true;
        out_step_ = update->ntimestep;
    }
    return (n >= 0 && n < kNout) ? out_[n] : 0.0;
}
