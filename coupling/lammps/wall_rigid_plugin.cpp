/* The rigidsurf fix styles for LAMMPS (wall/rigid and the stored force of its store_force,
 * wall/rigid/force), registered through LAMMPS's plugin interface: this file is the
 * plugin's entry point in wallrigidplugin.so (`plugin load wallrigidplugin.so` in a LAMMPS
 * built with PLUGIN) and the registration lmp-rigidsurf makes before the input runs. It
 * also makes the LAMMPS instance the host of the Abaqus utility routines that user
 * routines call. A plugin is built for one LAMMPS version: LAMMPS has no stable C++ ABI. */
#include "fix_wall_rigid.h"
#include "fix_wall_rigid_force.h"

#include "adapter.h"

#include "comm.h"
#include "error.h"
#include "lammps.h"
#include "lammpsplugin.h"
#include "version.h"

using namespace LAMMPS_NS;

namespace
{

/* A fix style's creator, of the type LAMMPS calls it by (Modify::FixCreator). */
template <class T> Fix *make_fix(LAMMPS *lmp, int narg, char **arg)
{
    return new T(lmp, narg, arg);
}

} // namespace

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
    const lammpsplugin_regfunc add = (lammpsplugin_regfunc)regfunc;
    lammpsplugin_t plugin;
    plugin.version = LAMMPS_VERSION;
    plugin.style = "fix";
    plugin.author = "rigidsurf";
    plugin.handle = handle;
    plugin.name = "wall/rigid";
    plugin.info = "fix wall/rigid: rigidsurf's exact walls (profiles, revolutions, meshes)";
    plugin.creator.v2 = (lammpsplugin_factory2 *)&make_fix<FixWallRigid>;
    (*add)(&plugin, lmp);
    plugin.name = "wall/rigid/force";
    plugin.info = "fix wall/rigid/force: the stored force of fix wall/rigid's store_force";
    plugin.creator.v2 = (lammpsplugin_factory2 *)&make_fix<FixWallRigidForce>;
    (*add)(&plugin, lmp);
    rs_adapter_abaqus_host(static_cast<LAMMPS *>(lmp), "log.lammps");
}
