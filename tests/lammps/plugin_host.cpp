/* A LAMMPS that loads a plugin as `plugin load FILE` does in a LAMMPS built with PLUGIN
 * (LAMMPS 29Sep2021, src/PLUGIN/plugin.cpp): the file opened with RTLD_NOW | RTLD_GLOBAL,
 * its lammpsplugin_init called with the instance, the handle and a registration function
 * that puts each fix style's creator into the fix style table. Debian's lmp has no PLUGIN;
 * this program stands in for it in the tests of wallrigidplugin.so.
 * Usage: plugin_host PLUGIN.so [the arguments of lmp] */
#include "input.h"
#include "lammps.h"
#include "lammpsplugin.h"
#include "modify.h"

#include <cstdio>
#include <cstring>
#include <dlfcn.h>
#include <mpi.h>

using namespace LAMMPS_NS;

static void plugin_register(lammpsplugin_t *plugin, void *ptr)
{
    LAMMPS *lmp = static_cast<LAMMPS *>(ptr);
    if (std::strcmp(plugin->style, "fix") == 0)
        (*lmp->modify->fix_map)[plugin->name] = (Modify::FixCreator)plugin->creator.v2;
    std::printf("plugin_host: %s style %s from a plugin for LAMMPS %s\n", plugin->style,
                plugin->name, plugin->version);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: plugin_host PLUGIN.so [lmp's arguments]\n");
        return 2;
    }
    MPI_Init(&argc, &argv);
    void *dso = dlopen(argv[1], RTLD_NOW | RTLD_GLOBAL);
    void *init = dso ? dlsym(dso, "lammpsplugin_init") : nullptr;
    if (!init) {
        std::fprintf(stderr, "plugin_host: %s\n", dlerror());
        MPI_Abort(MPI_COMM_WORLD, 1);
    }
    argv[1] = argv[0];
    LAMMPS *lmp = new LAMMPS(argc - 1, argv + 1, MPI_COMM_WORLD);
    (*(lammpsplugin_initfunc)init)(lmp, dso, (void *)&plugin_register);
    lmp->input->file();
    delete lmp;
    MPI_Finalize();
    return 0;
}
