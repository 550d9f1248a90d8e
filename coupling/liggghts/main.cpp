/* liggghts-rigidsurf: Debian's `liggghts` with the rigidsurf fix styles added.
 *
 * Same command line (-in, -var, -echo, -log, -screen, ...) and same output as
 * `liggghts`: the signal handlers, MPI start-up, LAMMPS instance and input loop are the
 * ones LIGGGHTS 3.8.0 uses in its own main. The only difference is that the rigidsurf
 * styles are added to the instance before the input script runs. */
#include "rigidsurf_styles.h"

#include "input.h"
#include "lammps.h"
#include "signal_handling.h"

#include <mpi.h>
#include <signal.h>
#include <string.h>

using namespace LAMMPS_NS;

int main(int argc, char **argv)
{
    // SIGINT and SIGTERM ask LIGGGHTS to stop cleanly (OpenMPI turns a SIGINT to mpirun
    // into SIGTERM for its children); SIGUSR1 asks for a restart file.
    struct sigaction stop_action, restart_action;
    memset(&stop_action, 0, sizeof stop_action);
    memset(&restart_action, 0, sizeof restart_action);
    stop_action.sa_handler = SignalHandler::int_handler;
    restart_action.sa_handler = SignalHandler::usr1_handler;
    sigaction(SIGINT, &stop_action, NULL);
    sigaction(SIGTERM, &stop_action, NULL);
    sigaction(SIGUSR1, &restart_action, NULL);

    MPI_Init(&argc, &argv);

    LAMMPS *lmp = new LAMMPS(argc, argv, MPI_COMM_WORLD);
    rigidsurf_register_styles(lmp);
    lmp->input->file();
    delete lmp;

    MPI_Finalize();
    return 0;
}
