/* fix wall/rigid in LAMMPS: a rigidsurf wall (include/rigidsurf/wall.h) as a LAMMPS wall
 * (docs/lammps.md, docs/fix_wall_rigid.md). The wall is the library's; this adapter hands
 * it LAMMPS's atom arrays each step (rs_wall_step), answers what only LAMMPS knows
 * (variables, sums over ranks, warnings, the material properties given on the fix line,
 * its own contact models as `law lammps`), keeps the per-atom outputs LAMMPS dumps, and
 * moves the wall's per-atom history through LAMMPS's exchange and restart callbacks. Its
 * particles are spheres (atom_style sphere), ellipsoids (atom_style ellipsoid) and rounded
 * polyhedra (atom_style body rounded/polyhedron), the last two as convex bodies (bodies.h).
 */
#ifndef RIGIDSURF_LAMMPS_FIX_WALL_RIGID_H
#define RIGIDSURF_LAMMPS_FIX_WALL_RIGID_H

#include "fix.h"

#include "bodies.h"
#include "rigidsurf/wall.h"
#include "wall_atoms.h"
#include "wall_materials.h"

#include <string>
#include <vector>

namespace LAMMPS_NS
{

class FixWallRigid : public RsWallAtoms<Fix>
{
  public:
    FixWallRigid(class LAMMPS *, int, char **);
    ~FixWallRigid() override;

    int setmask() override;
    void post_constructor() override;
    void init() override;
    void setup(int) override;
    void initial_integrate(int) override;
    void pre_neighbor() override;
    void post_force(int) override;
    void final_integrate() override;
    void post_run() override;
    void reset_dt() override;

    /* The host table's answers (rs_adapter_host). */
    void reduce(double *v, int n, int op);
    int variable_find(const char *name);
    double variable_eval(int index, int why);
    void warning(const char *msg);
    void info(const char *msg);
    int material(const char *name, int i, int j, int required, const char *who,
                 double *value, rs_error *err);
    int engine_law(const char *const *words, int nwords, const rs_law **law, rs_error *err);
    /// law lammps: one block of contacts through LAMMPS's contact model (lammps_law.cpp).
    int lammps_update(rs_law_block *b, rs_error *err);
    /// law lammps: one contact through LAMMPS's contact model (rs_law.force_one).
    int lammps_one(rs_force_contact &c, double F[3], double T[3]);
    /// law lammps: a run of contacts through LAMMPS's contact model (rs_law.force_run).
    void lammps_run(const rs_force_run &r);
    /// law lammps: its default tracking thickness.
    double lammps_reach();

  private:
    [[noreturn]] void fail(const std::string &msg) override;
    [[noreturn]] void fail_one(const std::string &msg) override;
    /// maxexchange follows the slots an atom carries
    void exchanged() override
    {
        exchange_size();
    }
    rs_wall_block block(bool setup);
    rs_wall_rows rows();
    void exchange_size();
    void check_particles();
    void fill_bodies();

    rs_wall_host host_;
    WallMaterials materials_;

    /* atom_style ellipsoid and body rounded/polyhedron: their shapes and orientations, the
     * group's ellipsoids and polyhedra as the wall's bodies; bodies_on_: the group holds
     * bodies in this run (the wall asks every particle at every step) */
    class AtomVecEllipsoid *avec_;
    class AtomVecBody *bvec_;
    RsBodies bodies_;
    bool bodies_on_;

    /* law lammps: LAMMPS's wall contact model, and the descriptor the wall calls */
    class LammpsWallModel *model_;
    rs_law model_desc_;
    int reff_mode_;

    /* predef: the custom per-atom vectors (fix property/atom d_NAME) handed to the law */
    std::vector<int> pred_index_;
    std::vector<const double *> pred_;

    /* store_force: the wall's force on each particle, the per-atom array of the fix
     * wall/rigid/force of ID force_ID (force_W with 'into W', shared by the wall/rigid
     * fixes that name it; the first of them in the fix list clears it each step) */
    std::string wallforce_id_;
    bool wallforce_clear_;
};

} // namespace LAMMPS_NS

#endif
