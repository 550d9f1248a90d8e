/* rigidsurf: adds the rigidsurf styles to a LIGGGHTS instance. */
#ifndef RIGIDSURF_STYLES_H
#define RIGIDSURF_STYLES_H

namespace LAMMPS_NS
{
class LAMMPS;
}

/// Adds every rigidsurf fix style (wall/rigid) to lmp's style table, and makes lmp the
/// host of the Abaqus utility routines (messages to its screen and log, errors through
/// its error->one, its rank and rank count, the job name from -log or -in). Call it after
/// the LAMMPS instance is constructed and before the input script runs.
void rigidsurf_register_styles(LAMMPS_NS::LAMMPS *lmp);

#endif
