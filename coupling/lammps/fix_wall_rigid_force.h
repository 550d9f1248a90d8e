/* fix wall/rigid/force in LAMMPS: keyword store_force of fix wall/rigid, the wall's force
 * on each particle at this step, a per-atom array of 3 columns (f_force_ID[1] .. [3] in a
 * dump or compute), as LIGGGHTS's fix wall/gran keeps it (a per-atom vector of 3 named
 * force_ID). Made by the fix wall/rigid that stores into it (its post_constructor); zeroed
 * each step by the first of the wall/rigid fixes that store into it; moved with the atoms,
 * not written to restart files. */
#ifndef RIGIDSURF_LAMMPS_FIX_WALL_RIGID_FORCE_H
#define RIGIDSURF_LAMMPS_FIX_WALL_RIGID_FORCE_H

#include "fix.h"

namespace LAMMPS_NS
{

class FixWallRigidForce : public Fix
{
  public:
    FixWallRigidForce(class LAMMPS *, int, char **);
    ~FixWallRigidForce() override;
    int setmask() override
    {
        return 0;
    }
    /// The array as rows of 3 doubles per atom, its local atoms zeroed when clear.
    double *rows(bool clear);

    void grow_arrays(int) override;
    void copy_arrays(int, int, int) override;
    void set_arrays(int) override;
    int pack_exchange(int, double *) override;
    int unpack_exchange(int, double *) override;
    double memory_usage() override;

  private:
    int nmax_;
};

} // namespace LAMMPS_NS

#endif
