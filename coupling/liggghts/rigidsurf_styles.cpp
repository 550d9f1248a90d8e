/* Registration of the rigidsurf fix styles, and LIGGGHTS as the host of the Abaqus
 * utility routines that user routines call (include/rigidsurf/abaqus_util.h).
 *
 * Modify keeps its style table (fix_map: style name -> creator) private and declares
 * `friend class Info`. The class below borrows that name (it is not LIGGGHTS's `info`
 * command, whose header is deliberately not included) to add entries to the table. Its
 * only member is a static function with a name the library does not define, so it
 * cannot clash with the library's own Info symbols. */
#include "rigidsurf_styles.h"

#include "fix_wall_rigid.h"

#include "adapter.h"

#include "comm.h"
#include "error.h"
#include "lammps.h"
#include "modify.h"

#include <map>
#include <string>

namespace LAMMPS_NS
{

class Info
{
  public:
    typedef Fix *(*FixCreator)(LAMMPS *, int, char **);

    /// Adds (or replaces) fix style `name` in modify's style table.
    static void rigidsurf_add_fix_style(Modify *modify, const char *name, FixCreator make)
    {
        (*modify->fix_map)[name] = make;
    }
};

} // namespace LAMMPS_NS

using namespace LAMMPS_NS;

template <typename T> static Fix *rigidsurf_make_fix(LAMMPS *lmp, int narg, char **arg)
{
    return new T(lmp, narg, arg);
}

void rigidsurf_register_styles(LAMMPS *lmp)
{
    Info::rigidsurf_add_fix_style(lmp->modify, "wall/rigid",
                                  &rigidsurf_make_fix<FixWallRigid>);
    rs_adapter_abaqus_host(lmp, "log.liggghts");
}
