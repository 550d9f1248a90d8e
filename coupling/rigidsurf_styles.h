/* rigidsurf: adds the rigidsurf styles to a LIGGGHTS instance. */
#ifndef RIGIDSURF_STYLES_H
#define RIGIDSURF_STYLES_H

namespace LAMMPS_NS
{
class LAMMPS;
}

/// Adds every rigidsurf fix style (wall/rigid) to lmp's style table. Call it after the
/// LAMMPS instance is constructed and before the input script runs.
void rigidsurf_register_styles(LAMMPS_NS::LAMMPS *lmp);

#endif
