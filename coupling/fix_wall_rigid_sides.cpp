/* fix wall/rigid: particles behind a one-sided wall. A one-sided surface holds particles
 * only on the side its normal points to (left of travel along a profile, the winding's
 * side on an Abaqus part or a mesh given SIDES=1); one that reaches it from behind is
 * pushed through. Where that happens a deck has most likely drawn its profile the other
 * way, so the fix says so once, collectively, on a candidate rebuild. */
#include "fix_wall_rigid.h"

#include "comm.h"
#include "error.h"

#include <sstream>
#include <string>

using namespace LAMMPS_NS;

/* After a rebuild query of points [0, n) of a block whose depth limit was widened to
 * the back side's reach: the candidates are those with a contact no deeper than
 * dist_min, as without the check; a point counts as behind when every contact it has
 * lies behind the surface (dist < 0: its centre is on the back side). */
void FixWallRigid::sort_behind(int n, double dist_min)
{
    char front[RS_BLOCK] = {0}, near[RS_BLOCK] = {0};
    for (int c = 0; c < contacts_.n; c++) {
        const int k = contacts_.point[c];
        const double d = contacts_.dist[c];
        near[k] = 1;
        if (d >= 0.0)
            front[k] = 1;
        if (d >= dist_min)
            take_[k] = 1;
    }
    for (int k = 0; k < n; k++)
        behind_ += near[k] && !front[k];
}

/* Over all ranks, after a rebuild: one warning, the first time particles are found
 * behind a one-sided surface. */
void FixWallRigid::warn_behind()
{
    double mine = (double)behind_, all = 0.0;
    behind_ = 0;
    MPI_Allreduce(&mine, &all, 1, MPI_DOUBLE, MPI_SUM, world);
    if (!(all > 0.0))
        return;
    behind_warned_ = true;
    if (comm->me != 0)
        return;
    std::ostringstream o;
    o << "Fix wall/rigid " << id << ": " << (long long)all << " particle(s) within reach "
      << "of the back of the one-sided surface '" << (surf_.name[0] ? surf_.name : id)
      << "', which holds particles only on the side its normal points to (left of the "
      << "profile's travel, or the side a mesh's winding gives) and pushes those behind "
      << "it through; reversing the profile (or the winding) or giving SIDES=2 "
      << "(sides 2) would hold them";
    error->warning(FLERR, o.str().c_str());
}
