/* fix wall/rigid/force: the stored force of fix wall/rigid (fix_wall_rigid_force.h). */
#include "fix_wall_rigid_force.h"

#include "atom.h"
#include "error.h"
#include "memory.h"

using namespace LAMMPS_NS;

FixWallRigidForce::FixWallRigidForce(LAMMPS *lmp, int narg, char **arg)
    : Fix(lmp, narg, arg), nmax_(0)
{
    if (narg != 3)
        error->all(FLERR, "Illegal fix wall/rigid/force command: it takes no arguments "
                          "(fix wall/rigid ... store_force yes makes it)");
    peratom_flag = 1;
    size_peratom_cols = 3;
    peratom_freq = 1;
    create_attribute = 1;
    maxexchange = 3;
    array_atom = nullptr;
    grow_arrays(atom->nmax);
    atom->add_callback(Atom::GROW);
}

FixWallRigidForce::~FixWallRigidForce()
{
    atom->delete_callback(id, Atom::GROW);
    memory->destroy(array_atom);
}

double *FixWallRigidForce::rows(bool clear)
{
    for (int i = 0; clear && i < atom->nlocal; i++)
        array_atom[i][0] = array_atom[i][1] = array_atom[i][2] = 0.0;
    return array_atom ? array_atom[0] : nullptr;
}

void FixWallRigidForce::grow_arrays(int nmax)
{
    if (nmax <= nmax_)
        return;
    memory->grow(array_atom, nmax, 3, "wall/rigid/force:array_atom");
    for (int i = nmax_; i < nmax; i++)
        array_atom[i][0] = array_atom[i][1] = array_atom[i][2] = 0.0;
    nmax_ = nmax;
}

void FixWallRigidForce::copy_arrays(int i, int j, int)
{
    for (int c = 0; c < 3; c++)
        array_atom[j][c] = array_atom[i][c];
}

void FixWallRigidForce::set_arrays(int i)
{
    array_atom[i][0] = array_atom[i][1] = array_atom[i][2] = 0.0;
}

int FixWallRigidForce::pack_exchange(int i, double *buf)
{
    for (int c = 0; c < 3; c++)
        buf[c] = array_atom[i][c];
    return 3;
}

int FixWallRigidForce::unpack_exchange(int nlocal, double *buf)
{
    for (int c = 0; c < 3; c++)
        array_atom[nlocal][c] = buf[c];
    return 3;
}

double FixWallRigidForce::memory_usage()
{
    return 3.0 * nmax_ * sizeof(double);
}
