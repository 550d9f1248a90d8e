/* fix wall/rigid in LIGGGHTS: the adapter over the rigidsurf wall (fix_wall_rigid.h). Its
 * lifecycle maps onto the wall's calls: the constructor makes the wall from the fix's
 * words, init its run, setup its setup call, initial_integrate its motion, post_force its
 * step, final_integrate its servo; the atom callbacks move its per-atom history. Syntax,
 * keywords and output: docs/fix_wall_rigid.md. */
#include "fix_wall_rigid.h"
#include "liggghts_law.h"

#include "adapter.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_property_atom.h"
#include "fix_property_global.h"
#include "force.h"
#include "group.h"
#include "input.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"
#include "variable.h"

#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mpi.h>
#include <unistd.h>

using namespace LAMMPS_NS;
using namespace FixConst;

/* ---------------------------------------------------------------------------------- */
/* The host table: what only LIGGGHTS knows.                                          */

namespace
{

int liggghts_law_update(const rs_law *law, rs_law_block *b, rs_error *err)
{
    return static_cast<FixWallRigid *>(law->ctx)->liggghts_update(b, err);
}

int liggghts_law_one(const rs_law *law, rs_force_contact *c, double F[3], double T[3],
                     rs_error *err)
{
    return static_cast<FixWallRigid *>(law->ctx)->liggghts_one(*c, F, T, err);
}

double liggghts_law_reach(const rs_law *law, const double *, int)
{
    return static_cast<FixWallRigid *>(law->ctx)->liggghts_reach();
}

} // namespace

void FixWallRigid::reduce(double *v, int n, int op)
{
    rs_adapter_reduce(world, v, n, op);
}

int FixWallRigid::variable_find(const char *name)
{
    return rs_adapter_variable_find(lmp, name);
}

double FixWallRigid::variable_eval(int index, int why)
{
    return rs_adapter_variable_eval(lmp, index, why);
}

void FixWallRigid::warning(const char *msg)
{
    error->warning(FLERR, msg);
}

void FixWallRigid::info(const char *msg)
{
    rs_adapter_info(screen, logfile, msg);
}

/* LIGGGHTS's material properties (fix property/global), looked up as fix wall/gran looks
 * them up (global_properties.cpp): per type and per type pair over the registry's largest
 * type, the characteristic velocity a scalar; heat/gran/conduction's area correction, the
 * overlap ratio it keeps in youngsModulusOriginal's modified array. */
int FixWallRigid::material(const char *name, int i, int j, int required, const char *who,
                           double *value, rs_error *err)
{
    (void)err; /* a missing required property ends the run with LIGGGHTS's message */
    const int max_type = force->registry.max_type();
    if (std::strcmp(name, "deltan_ratio") == 0) {
        Fix *ymo = modify->find_fix_property("youngsModulusOriginal", "property/global",
                                             "peratomtype", 0, 0, style, false);
        if (!ymo || modify->n_fixes_style("heat/gran/conduction") == 0)
            return RS_ERR_NOTFOUND;
        *value = static_cast<FixPropertyGlobal *>(ymo)->get_array_modified()[i - 1][j - 1];
        return RS_OK;
    }
    const char *kind = i == 0 ? "scalar" : j == 0 ? "peratomtype" : "peratomtypepair";
    /* thermalConductivity is looked up as fix wall/gran does, without a length */
    const int len1 = i == 0 || std::strcmp(name, "thermalConductivity") == 0 ? 0 : max_type;
    const int len2 = j == 0 ? 0 : max_type;
    FixPropertyGlobal *p = static_cast<FixPropertyGlobal *>(modify->find_fix_property(
        name, "property/global", kind, len1, len2, who, required != 0));
    if (!p)
        return RS_ERR_NOTFOUND;
    if (i == 0) {
        *value = p->compute_scalar();
    } else if (j == 0) {
        if (len1 && i > max_type)
            return RS_ERR_NOTFOUND;
        *value = p->compute_vector(i - 1);
    } else {
        if (i > max_type || j > max_type)
            return RS_ERR_NOTFOUND;
        *value = p->compute_array(i - 1, j - 1);
    }
    return RS_OK;
}

/* law liggghts: LIGGGHTS's own words, up to the next keyword of wall/rigid; the model
 * reads the overlap, the frame and its own history only, and gives a force and torque. */
int FixWallRigid::engine_law(const char *const *words, int nwords, const rs_law **law,
                             rs_error *err)
{
    (void)err; /* LIGGGHTS's own messages end the run (LiggghtsLaw) */
    lig_ = new LiggghtsLaw(lmp, id, std::vector<std::string>(words, words + nwords));
    std::memset(&lig_desc_, 0, sizeof lig_desc_);
    lig_desc_.name = "liggghts";
    lig_desc_.nprops = 0;
    lig_desc_.nstatev = lig_->nhistory();
    lig_desc_.update = liggghts_law_update;
    lig_desc_.reach = liggghts_law_reach;
    lig_desc_.force_one = liggghts_law_one;
    lig_desc_.ctx = this;
    lig_desc_.skips = RS_LAW_SKIPS_STRESS | RS_LAW_SKIPS_ENERGY | RS_LAW_SKIPS_SLIP |
                      RS_LAW_SKIPS_DRDISP1;
    lig_desc_.sets = RS_LAW_SETS_FORCE | RS_LAW_SETS_ENERGIES | RS_LAW_SETS_NO_HEAT |
                     RS_LAW_SETS_NO_CREEP_PLASTIC | RS_LAW_SETS_STRESS;
    *law = &lig_desc_;
    return RS_OK;
}

/* ---------------------------------------------------------------------------------- */

FixWallRigid::FixWallRigid(LAMMPS *lmp, int narg, char **arg)
    : RsWallAtoms<Fix>(lmp, narg, arg), lig_(NULL), fix_temp_(NULL), fix_heatflux_(NULL),
      wallforce_clear_(true), wallforce_(NULL)
{
    std::memset(&lig_desc_, 0, sizeof lig_desc_);
    host_ = rs_adapter_host(this, comm->me, atom->ntypes, "liggghts");
    rs_error err;
    rs_error_clear(&err);
    if (rs_wall_create(id, group->names[igroup], arg + 3, narg - 3, &host_, &wall_, &err) !=
        RS_OK)
        fail(err.msg);
    info_ = rs_wall_get_info(wall_);
    wallforce_id_ = info_->store_force_id;

    restart_global = 1;
    restart_peratom = 1;
    create_attribute = 1;
    time_depend = info_->moving ? 1 : 0;
    vector_flag = 1;
    size_vector = RS_WALL_NVEC;
    global_freq = 1;
    extvector = -1;
    extlist = new int[RS_WALL_NVEC];
    for (int d = 0; d < RS_WALL_NVEC; d++)
        extlist[d] = 1;
    for (int d = 12; d < RS_WALL_NVEC; d++)
        if (d != 13)
            extlist[d] = 0; // wall temperature, the wall's displacement: intensive
    peratom_flag = info_->peratom ? 1 : 0;
    size_peratom_cols = info_->peratom ? 6 : 0;
    peratom_freq = 1;
    array_atom = NULL;

    grow_arrays(atom->nmax);
    atom->add_callback(0);
    atom->add_callback(1);
}

FixWallRigid::~FixWallRigid()
{
    atom->delete_callback(id, 0);
    atom->delete_callback(id, 1);
    memory->destroy(array_atom);
    delete[] extlist;
    extlist = NULL;
    rs_wall_free(wall_);
    delete lig_;
}

void FixWallRigid::fail(const std::string &msg)
{
    std::string m = std::string("Fix wall/rigid ") + id + ": " + msg;
    error->all(FLERR, m.c_str());
    std::abort(); // not reached: error->all ends the run
}

/* Error::one ends with MPI_Abort, which drops whatever stdio still buffers: on a pipe or a
 * file the message and the last thermo lines would be lost. They are flushed here, and the
 * message written to the log, before Error::one runs. */
void FixWallRigid::fail_one(const std::string &msg)
{
    std::string m = std::string("Fix wall/rigid ") + id + ": " + msg;
    if (screen) {
        std::fflush(screen);
        if (!isatty(fileno(screen))) {
            std::fprintf(screen, "ERROR on proc %d: %s (%s:%d)\n", comm->me, m.c_str(),
                         __FILE__, __LINE__);
            std::fflush(screen);
        }
    }
    if (logfile) {
        std::fprintf(logfile, "ERROR on proc %d: %s (%s:%d)\n", comm->me, m.c_str(),
                     __FILE__, __LINE__);
        std::fflush(logfile);
    }
    error->one(FLERR, m.c_str());
    std::abort();
}

/* A failed step: law liggghts's full account of a model's non-finite output (its history
 * by name) when that is what failed, else the wall's message. */
void FixWallRigid::step_failed(const rs_error &err)
{
    if (lig_ && err.code == RS_ERR_NONFINITE && !lig_->failure().empty())
        fail_one(lig_->failure());
    fail_one(err.msg);
    std::abort(); // not reached: fail_one ends the run
}

int FixWallRigid::setmask()
{
    int mask = PRE_NEIGHBOR | POST_FORCE;
    if (info_->moving)
        mask |= INITIAL_INTEGRATE;
    if (info_->servo)
        mask |= FINAL_INTEGRATE;
    return mask;
}

/* store_force: the per-atom vector LIGGGHTS's fix wall/gran registers for it
 * (FixWallGran::post_create): a fix property/atom of ID and name force_ID (force_W with
 * 'into W'), 3 columns, neither restarted nor communicated; made by the first fix that
 * names it. */
void FixWallRigid::post_create()
{
    if (!info_->store_force || modify->find_fix(wallforce_id_.c_str()) >= 0)
        return;
    const char *fixarg[11] = {wallforce_id_.c_str(),
                              "all",
                              "property/atom",
                              wallforce_id_.c_str(),
                              "vector",
                              "no",
                              "no",
                              "no",
                              "0.",
                              "0.",
                              "0."};
    modify->add_fix(11, const_cast<char **>(fixarg));
}

bool FixWallRigid::shares_wallforce(const FixWallRigid *other) const
{
    return other != this && other->info_->store_force &&
           other->wallforce_id_ == wallforce_id_;
}

/* unfix: the stored force goes with the last fix that stores into it, when it comes after
 * that fix in the fix list (as after the fix that made it): Modify::delete_fix deletes the
 * fix at the index it had before pre_delete. */
void FixWallRigid::pre_delete(bool unfixflag)
{
    if (!unfixflag || !info_->store_force ||
        modify->find_fix(wallforce_id_.c_str()) < modify->find_fix(id))
        return;
    for (int i = 0; i < modify->nfix; i++)
        if (std::strcmp(modify->fix[i]->style, "wall/rigid") == 0 &&
            shares_wallforce(static_cast<FixWallRigid *>(modify->fix[i])))
            return;
    modify->delete_fix(wallforce_id_.c_str());
}

int FixWallRigid::min_type()
{
    return info_->wall_type;
}

int FixWallRigid::max_type()
{
    return info_->wall_type;
}

void FixWallRigid::init()
{
    if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
        fail("needs per-atom radius, mass, omega and torque (atom_style granular or "
             "sphere)");
    if (std::strstr(update->integrate_style, "respa"))
        fail("run_style respa is not supported; use verlet");
    if (lig_)
        lig_->init();
    fix_temp_ = static_cast<FixPropertyAtom *>(
        modify->find_fix_property("Temp", "property/atom", "scalar", 0, 0, style, false));
    fix_heatflux_ = static_cast<FixPropertyAtom *>(modify->find_fix_property(
        "heatFlux", "property/atom", "scalar", 0, 0, style, false));
    predef_fix_.clear();
    for (int a = 0; a < info_->npred; a++) {
        FixPropertyAtom *f = static_cast<FixPropertyAtom *>(modify->find_fix_property(
            info_->pred[a], "property/atom", "scalar", 0, 0, style, false));
        if (!f)
            fail(std::string("keyword 'predef': no fix property/atom holding a per-atom "
                             "scalar named '") +
                 info_->pred[a] + "'");
        predef_fix_.push_back(f);
    }
    wallforce_clear_ = true;
    for (int i = 0; info_->store_force && i < modify->nfix && modify->fix[i] != this; i++)
        if (std::strcmp(modify->fix[i]->style, "wall/rigid") == 0 &&
            shares_wallforce(static_cast<FixWallRigid *>(modify->fix[i])))
            wallforce_clear_ = false;

    /* LIGGGHTS 3.8 packs a leaving atom into the slack of its send buffer (comm.cpp and
     * irregular.cpp: BUFEXTRA, 1000 doubles, shared by the atom style and every fix): 600
     */
    rs_wall_run run = rs_adapter_run(
        update->dt, neighbor->skin, neighbor->delay, neighbor->every, neighbor->dist_check,
        neighbor->build_once, domain->boxlo, domain->boxhi, 600);
    run.has_temp = fix_temp_ != NULL;
    run.has_heatflux = fix_heatflux_ != NULL;
    const rs_wall_block b = block(true);
    rs_error err;
    rs_error_clear(&err);
    if (rs_wall_init(wall_, &run, &b, &err) != RS_OK)
        fail(err.msg);
}

/* The atoms as the wall reads them: LIGGGHTS's arrays, contiguous rows of 3. */
rs_wall_block FixWallRigid::block(bool setup) const
{
    rs_wall_block b;
    std::memset(&b, 0, sizeof b);
    b.n = atom->nlocal;
    b.x = atom->x ? atom->x[0] : NULL;
    b.v = atom->v ? atom->v[0] : NULL;
    b.omega = atom->omega ? atom->omega[0] : NULL;
    b.radius = atom->radius;
    b.mass = atom->rmass;
    b.type = atom->type;
    b.id = atom->tag;
    b.mask = atom->mask;
    b.groupbit = groupbit;
    b.temp = fix_temp_ ? fix_temp_->vector_atom : NULL;
    pred_.resize(predef_fix_.size());
    for (size_t a = 0; a < predef_fix_.size(); a++)
        pred_[a] = predef_fix_[a]->vector_atom;
    b.pred = pred_.empty() ? NULL : pred_.data();
    b.step = update->ntimestep;
    b.inc = (int)(update->ntimestep - update->firststep);
    b.time = rs_adapter_time(update->atime, update->atimestep, update->ntimestep,
                             update->dt, setup);
    return b;
}

/* store_force: this step's array of the per-atom vector, zeroed for the local atoms by the
 * first fix that stores into it; the wall adds each contact's force on its particle (as
 * fix wall/gran does, in setup calls too). */
void FixWallRigid::begin_wallforce()
{
    wallforce_ = NULL;
    if (!info_->store_force)
        return;
    const int ifix = modify->find_fix(wallforce_id_.c_str());
    if (ifix < 0)
        fail("store_force: fix " + wallforce_id_ + " (the stored force) was deleted");
    wallforce_ = static_cast<FixPropertyAtom *>(modify->fix[ifix])->array_atom;
    if (!wallforce_clear_)
        return;
    for (int i = 0; i < atom->nlocal; i++)
        wallforce_[i][0] = wallforce_[i][1] = wallforce_[i][2] = 0.0;
}

/* Where the wall's loads go: LIGGGHTS's force and torque, the stored force, the heat flow
 * of fix heat/gran, the per-atom array. */
rs_wall_rows FixWallRigid::rows()
{
    begin_wallforce();
    rs_wall_rows r;
    std::memset(&r, 0, sizeof r);
    r.f = atom->f ? atom->f[0] : NULL;
    r.torque = atom->torque ? atom->torque[0] : NULL;
    r.fstore = wallforce_ ? wallforce_[0] : NULL;
    r.heatflux = fix_heatflux_ ? fix_heatflux_->vector_atom : NULL;
    r.peratom = array_atom ? array_atom[0] : NULL;
    return r;
}

/* The forces before the first step, with the history frozen, as LIGGGHTS's walls compute
 * their setup forces. */
void FixWallRigid::setup(int)
{
    const rs_wall_block b = block(true);
    const rs_wall_rows r = rows();
    rs_error err;
    rs_error_clear(&err);
    if (rs_wall_setup(wall_, &b, &r, NULL, &err) != RS_OK)
        step_failed(err);
}

void FixWallRigid::initial_integrate(int)
{
    rs_error err;
    rs_error_clear(&err);
    if (rs_wall_advance(wall_, update->dt, &err) != RS_OK)
        fail(err.msg);
}

void FixWallRigid::pre_neighbor()
{
    rs_wall_reneighbor(wall_);
}

void FixWallRigid::post_force(int)
{
    const rs_wall_block b = block(false);
    const rs_wall_rows r = rows();
    rs_error err;
    rs_error_clear(&err);
    if (rs_wall_step(wall_, &b, &r, update->dt, NULL, &err) != RS_OK)
        step_failed(err);
}

void FixWallRigid::final_integrate()
{
    rs_error err;
    rs_error_clear(&err);
    if (rs_wall_servo(wall_, update->dt, &err) != RS_OK)
        fail(err.msg);
}

void FixWallRigid::post_run()
{
    rs_wall_end_run(wall_);
}
