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

#include "rigidsurf/abaqus_util.h"

#include "comm.h"
#include "error.h"
#include "lammps.h"
#include "modify.h"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

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

/* A user routine's information lines and warnings: the screen and the log of rank 0;
 * another rank has neither and prints on its standard output. */
static void abaqus_message(void *ctx, int, const char *text)
{
    LAMMPS *lmp = static_cast<LAMMPS *>(ctx);
    if (lmp->screen)
        std::fprintf(lmp->screen, "%s\n", text);
    if (lmp->logfile)
        std::fprintf(lmp->logfile, "%s\n", text);
    if (!lmp->screen && !lmp->logfile) {
        std::fprintf(stdout, "%s\n", text);
        std::fflush(stdout);
    }
}

/* An error that ends the run now: LIGGGHTS's error->one (this rank's message, then the
 * abort of every rank). */
static void abaqus_fatal(void *ctx, const char *text)
{
    LAMMPS *lmp = static_cast<LAMMPS *>(ctx);
    lmp->error->one(FLERR, text);
}

/* The job name of GETJOBNAME: the log file's name (-log, -l) without its folder and
 * suffix; with -log none the input script's (-in, -i); LIGGGHTS's default log.liggghts
 * gives "log". */
static std::string job_name()
{
    std::ifstream in("/proc/self/cmdline", std::ios::binary);
    std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<std::string> args;
    for (size_t i = 0; i < all.size();) {
        size_t j = all.find('\0', i);
        if (j == std::string::npos)
            j = all.size();
        args.push_back(all.substr(i, j - i));
        i = j + 1;
    }
    std::string log = "log.liggghts", input;
    for (size_t i = 0; i + 1 < args.size(); i++) {
        if (args[i] == "-log" || args[i] == "-l")
            log = args[i + 1];
        else if (args[i] == "-in" || args[i] == "-i")
            input = args[i + 1];
    }
    std::string name = log == "none" ? input : log;
    size_t slash = name.rfind('/');
    if (slash != std::string::npos)
        name = name.substr(slash + 1);
    size_t dot = name.rfind('.');
    if (dot != std::string::npos && dot > 0)
        name = name.substr(0, dot);
    return name.empty() ? std::string("liggghts") : name;
}

void rigidsurf_register_styles(LAMMPS *lmp)
{
    Info::rigidsurf_add_fix_style(lmp->modify, "wall/rigid",
                                  &rigidsurf_make_fix<FixWallRigid>);
    const std::string job = job_name();
    rs_abq_host host;
    std::memset(&host, 0, sizeof host);
    host.message = abaqus_message;
    host.fatal = abaqus_fatal;
    host.ctx = lmp;
    host.jobname = job.c_str();
    host.outdir = NULL;
    host.rank = lmp->comm->me;
    host.ncpus = lmp->comm->nprocs;
    rs_abq_set_host(&host);
}
