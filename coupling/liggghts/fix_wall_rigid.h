/* fix wall/rigid: a rigidsurf wall (include/rigidsurf/wall.h) as a LIGGGHTS wall
 * (docs/fix_wall_rigid.md). The wall is the library's; this adapter hands it LIGGGHTS's
 * atom arrays each step (rs_wall_step), answers what only LIGGGHTS knows (variables,
 * material properties, sums over ranks, warnings, its own contact models as `law
 * liggghts`), keeps the per-atom outputs LIGGGHTS dumps, and moves the wall's per-atom
 * history through LIGGGHTS's exchange and restart callbacks. */
#ifdef FIX_CLASS

FixStyle(wall / rigid, FixWallRigid)

#else

#ifndef RIGIDSURF_FIX_WALL_RIGID_H
#define RIGIDSURF_FIX_WALL_RIGID_H

#include "fix.h"

#include "rigidsurf/wall.h"
#include "wall_atoms.h"

#include <string>
#include <vector>

namespace LAMMPS_NS
{

class FixWallRigid : public RsWallAtoms<Fix>
{
  public:
    FixWallRigid(class LAMMPS *, int, char **);
    ~FixWallRigid();

    int setmask();
    void post_create();
    void pre_delete(bool unfixflag);
    void init();
    void setup(int);
    void initial_integrate(int);
    void pre_neighbor();
    void post_force(int);
    void final_integrate();
    void post_run();

    int min_type();
    int max_type();

    /* The host table's answers (fix_wall_rigid.cpp, rs_adapter_host). */
    void reduce(double *v, int n, int op);
    int variable_find(const char *name);
    double variable_eval(int index, int why);
    void warning(const char *msg);
    void info(const char *msg);
    int material(const char *name, int i, int j, int required, const char *who,
                 double *value, rs_error *err);
    int engine_law(const char *const *words, int nwords, const rs_law **law, rs_error *err);
    /// law liggghts: one block of contacts through LIGGGHTS's contact model.
    int liggghts_update(rs_law_block *b, rs_error *err);
    /// law liggghts: one contact through LIGGGHTS's model (rs_law.force_one): 1 where it
    /// gives a force, 0 where it gives none, -RS_ERR_NONFINITE where it cannot go on.
    int liggghts_one(rs_force_contact &c, double F[3], double T[3], rs_error *err);
    /// law liggghts: its default tracking thickness.
    double liggghts_reach() const;

  private:
    [[noreturn]] void fail(const std::string &msg) override;
    [[noreturn]] void fail_one(const std::string &msg) override;
    [[noreturn]] void step_failed(const rs_error &err);
    rs_wall_block block(bool setup) const;
    rs_wall_rows rows();
    void begin_wallforce();
    bool shares_wallforce(const FixWallRigid *other) const;

    rs_wall_host host_;

    /* law liggghts: LIGGGHTS's contact model, and the descriptor the wall calls */
    class LiggghtsLaw *lig_;
    rs_law lig_desc_;

    /* the per-atom fields of LIGGGHTS the wall reads and writes */
    class FixPropertyAtom *fix_temp_, *fix_heatflux_;
    std::vector<class FixPropertyAtom *> predef_fix_;
    mutable std::vector<const double *> pred_;

    /* store_force: the wall's force on each particle this step, in the per-atom vector
     * force_ID of a fix property/atom of that ID, as fix wall/gran keeps it; store_force
     * into W: in force_W, shared by the wall/rigid fixes that name it (the meshes of one
     * wall/gran); the first of them in the fix list clears it each step */
    std::string wallforce_id_;
    bool wallforce_clear_;
    double **wallforce_; // its array this step, or NULL
};

} // namespace LAMMPS_NS

#endif
#endif
