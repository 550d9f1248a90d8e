/* lmp-rigidsurf: Debian's `lmp` with the rigidsurf fix styles added.
 *
 * Same command line (-in, -var, -echo, -log, -screen, ...) and same output as `lmp`: the
 * MPI start-up, LAMMPS instance, input loop and end are those of LAMMPS 29Sep2021's own
 * main (built without exceptions). The only difference is that the styles of
 * wallrigidplugin.so (wall_rigid_plugin.cpp) are added to the instance before the input
 * script runs, as `plugin load` would add them in a LAMMPS built with PLUGIN. */
#include "input.h"
#include "lammps.h"
#include "lammpsplugin.h"
#include "lmppython.h"
#include "modify.h"

#include "fmt/format.h"

#include <cstdio>
#include <cstdlib>
#include <mpi.h>

using namespace LAMMPS_NS;

/* What LAMMPS's plugin loader does with a fix style of a plugin: its creator in the fix
 * style table (Modify::fix_map is public in LAMMPS). */
static void add_fix_style(lammpsplugin_t *plugin, void *ptr)
{
    LAMMPS *lmp = static_cast<LAMMPS *>(ptr);
    (*lmp->modify->fix_map)[plugin->name] = (Modify::FixCreator)plugin->creator.v2;
}

int main(int argc, char **argv)
{
    MPI_Init(&argc, &argv);
    MPI_Comm comm = MPI_COMM_WORLD;
    try {
        LAMMPS *lammps = new LAMMPS(argc, argv, comm);
        lammpsplugin_init(lammps, nullptr, (void *)&add_fix_style);
        lammps->input->file();
        delete lammps;
    } catch (fmt::format_error &fe) {
        std::fprintf(stderr, "fmt::format_error: %s\n", fe.what());
        Python::finalize();
        MPI_Abort(MPI_COMM_WORLD, 1);
        std::exit(1);
    }
    Python::finalize();
    MPI_Barrier(comm);
    MPI_Finalize();
}
