/* fix wall/rigid: a rigidsurf master surface as a LIGGGHTS wall. Its lifecycle and the
 * step: construction, init, setup, the step hooks and blocks. Syntax, keywords and
 * output: docs/fix_wall_rigid.md. Conventions: docs/conventions.md. Arguments:
 * fix_wall_rigid_args.cpp; candidates: fix_wall_rigid_candidates.cpp; a block's gather,
 * law and loads: fix_wall_rigid_block.cpp; per-atom state, exchange and restart:
 * fix_wall_rigid_state.cpp; outputs: fix_wall_rigid_output.cpp. */
#include "fix_wall_rigid.h"
#include "liggghts_law.h"
#include "rigidsurf/line_revolution.h"
#include "rigidsurf/vec.h"

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

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

using namespace LAMMPS_NS;
using namespace FixConst;

/* ---------------------------------------------------------------------------------- */

FixWallRigid::FixWallRigid(LAMMPS *lmp, int narg, char **arg)
    : Fix(lmp, narg, arg), surf_ok_(false), ndir_(3), moving_(false), belt_(false),
      ivar_omega_(-1), rot_by_period_(false), period_(0.0), ivar_spin_(-1),
      spin_by_period_(false), phi_at_build_(0.0), spin_at_build_(0.0),
      spin_invariant_(false), law_kind_(LAW_BUILTIN), law_(NULL), loaded_ok_(false),
      props_given_(false), hertz_(false), hooke_(false), one_pass_(false),
      line_pass_(false), lig_(NULL), nstatev_(0), statev_given_(false), wall_type_(1),
      capacity_(4), tracking_(0.0), tracking_given_(false), area_mode_(AREA_NODE),
      area_const_(1.0), temp_given_(false), temp_wall_(0.0), dtemp_wall_(0.0),
      capacity_wall_(0.0), heat_wall_(0.0), heat_step_(0.0), fix_temp_(NULL),
      fix_heatflux_(NULL), fix_heatcap_(NULL), conduction_(false),
      carea_mode_(CAREA_OVERLAP), carea_const_(0.0), carea_given_(false),
      conduct_ready_(false), th_cond_(NULL), deltan_ratio_(NULL), store_force_(false),
      peratom_(false), wallforce_clear_(true), wallforce_(NULL), vtk_every_(0), vtk_mesh_ok_(false),
      wear_(false), facets_(false), stress_step_(false), nfacet_(0), step_checked_(false),
      row_(NULL), hist_(NULL), nmax_(0), rebuild_(true), lookahead_(0.0), rglob_(0.0),
      bounds_ok_(false), list_bounds_(false), se_now_(0.0), ncontact_(0), out_step_(-1),
      out_valid_(false), kstep_(0), run_time0_(0.0), pnewdt_stop_(false),
      routine_step_warned_(false), behind_(0), behind_warned_(false)
{
    std::memset(&surf_, 0, sizeof surf_);
    std::memset(&loaded_, 0, sizeof loaded_);
    std::memset(&lig_desc_, 0, sizeof lig_desc_);
    std::memset(&contacts_, 0, sizeof contacts_);
    std::memset(&cands_, 0, sizeof cands_);
    std::memset(&tout_, 0, sizeof tout_);
    std::memset(&cb_, 0, sizeof cb_);
    std::memset(&vtk_mesh_, 0, sizeof vtk_mesh_);
    std::memset(&tracker_, 0, sizeof tracker_);
    rs_law_block_init(&blk_);
    rs_law_requests_clear(&requests_);
    rs_motion_init(&motion_);
    for (int d = 0; d < 3; d++) {
        ivar_vel_[d] = -1;
        disp_at_build_[d] = 0.0;
        f_wall_[d] = m_wall_[d] = 0.0;
    }
    for (int d = 0; d < 4; d++)
        diss_[d] = 0.0;
    for (int d = 0; d < kNout; d++)
        out_[d] = 0.0;

    parse(narg, arg);

    ndir_ = rs_surface_ndir(&surf_);
    tracker_.capacity = capacity_;
    tracker_.nstatev = nstatev_;
    tracker_.drop = rs_law_drops(law_);
    tracker_.ndir = ndir_;
    tracker_.tracking = tracking_;
    temp_mst_[0] = temp_wall_;
    dtemp_mst_[0] = 0.0;

    restart_global = 1;
    restart_peratom = 1;
    create_attribute = 1;
    time_depend = moving_ ? 1 : 0;

    vector_flag = 1;
    size_vector = kNout;
    global_freq = 1;
    extvector = -1;
    extlist = new int[kNout];
    for (int d = 0; d < kNout; d++)
        extlist[d] = 1;
    for (int d = 12; d < kNout; d++)
        if (d != 13)
            extlist[d] = 0; // wall temperature, the wall's displacement: intensive

    peratom_flag = peratom_ ? 1 : 0;
    size_peratom_cols = peratom_ ? 6 : 0;
    peratom_freq = 1;
    array_atom = NULL;

    if (vtk_every_ > 0)
        nevery = vtk_every_;

    grow_arrays(atom->nmax);
    atom->add_callback(0);
    atom->add_callback(1);
    for (int i = 0; i < atom->nlocal; i++)
        clear_row(i);
}

FixWallRigid::~FixWallRigid()
{
    atom->delete_callback(id, 0);
    atom->delete_callback(id, 1);
    memory->destroy(row_);
    std::free(hist_);
    memory->destroy(array_atom);
    delete[] extlist;
    extlist = NULL;
    rs_contacts_free(&contacts_);
    rs_cands_free(&cands_);
    rs_track_out_free(&tout_);
    rs_cblock_free(&cb_);
    rs_trimesh_free(&vtk_mesh_);
    if (loaded_ok_)
        rs_law_unload(&loaded_);
    delete lig_;
    if (surf_ok_)
        rs_surface_free(&surf_);
}

/* ---------------------------------------------------------------------------------- */
/* Run setup                                                                          */

int FixWallRigid::setmask()
{
    int mask = 0;
    mask |= PRE_NEIGHBOR;
    mask |= POST_FORCE;
    if (moving_)
        mask |= INITIAL_INTEGRATE;
    if (servo_.on)
        mask |= FINAL_INTEGRATE;
    if (vtk_every_ > 0)
        mask |= END_OF_STEP;
    return mask;
}

/* store_force: the per-atom vector LIGGGHTS's fix wall/gran registers for it
 * (FixWallGran::post_create): a fix property/atom of ID and name force_ID (force_W with
 * 'into W'), 3 columns, neither restarted nor communicated; made by the first fix that
 * names it. */
void FixWallRigid::post_create()
{
    if (!store_force_)
        return;
    if (wallforce_id_.empty())
        wallforce_id_ = std::string("force_") + id;
    if (modify->find_fix(wallforce_id_.c_str()) >= 0)
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
    return other != this && other->store_force_ && other->wallforce_id_ == wallforce_id_;
}

/* unfix: the stored force goes with the last fix that stores into it, when it comes
 * after that fix in the fix list (as after the fix that made it): Modify::delete_fix
 * deletes the fix at the index it had before pre_delete. */
void FixWallRigid::pre_delete(bool unfixflag)
{
    if (!unfixflag || !store_force_ ||
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
    return wall_type_;
}

int FixWallRigid::max_type()
{
    return wall_type_;
}

void FixWallRigid::init()
{
    if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
        fail("needs per-atom radius, mass, omega and torque (atom_style granular or "
             "sphere)");
    if (std::strstr(update->integrate_style, "respa"))
        fail("run_style respa is not supported; use verlet");
    /* Default tracking: the law's reach (0 for a law of touching contacts), else the
     * neighbor skin. */
    if (lig_)
        lig_->init();
    if (!tracking_given_ && lig_) {
        tracking_ = liggghts_reach();
    } else if (!tracking_given_) {
        const double *pv = props_.empty() ? NULL : props_.data();
        const double reach = law_->reach ? law_->reach(law_, pv, (int)props_.size()) : -1.0;
        tracking_ = reach >= 0.0 ? reach : neighbor->skin;
    }
    tracker_.tracking = tracking_;

    /* A surface of revolution spun about its own axis keeps its shape in space: the
     * rotation then never moves it toward a particle. */
    spin_invariant_ = false;
    double sa_origin[3], sa_axis[3];
    if (moving_ && rs_surface_spin_axis(&surf_, sa_origin, sa_axis)) {
        double ax[3], r[3], rx[3];
        rs_cross3(motion_.axis, sa_axis, ax);
        for (int d = 0; d < 3; d++)
            r[d] = motion_.center0[d] - sa_origin[d];
        rs_cross3(r, sa_axis, rx);
        const double scale = std::max(1.0, std::sqrt(domain->xprd * domain->xprd +
                                                     domain->yprd * domain->yprd +
                                                     domain->zprd * domain->zprd));
        spin_invariant_ =
            rs_norm3(ax) < 1e-12 && rs_norm3(rx) < 1e-12 * scale && !motion_.spin_on;
    }
    /* Distance bounds hold while the surface stays where it is in space: at rest, or
     * spun about its own axis without translation. A kind with candidate lists (MESH)
     * takes them from its lists instead (build_candidate_lists): the query's look-ahead
     * would widen every list by a skin. */
    bool translates = !var_vel_[0].empty() || !var_vel_[1].empty() || !var_vel_[2].empty();
    for (int d = 0; d < 3; d++)
        translates = translates || motion_.vel[d] != 0.0;
    const bool still = !moving_ || (spin_invariant_ && !translates && !servo_.on);
    bounds_ok_ = still && !rs_surface_has_candidates(&surf_);
    list_bounds_ = still && rs_surface_has_candidates(&surf_);
    lookahead_ = bounds_ok_ ? neighbor->skin : 0.0;
    if (material_props())
        init_material_props();
    init_variables();
    if (servo_.on)
        init_servo();
    init_heat();
    init_conduction();
    wallforce_clear_ = true;
    for (int i = 0; store_force_ && i < modify->nfix && modify->fix[i] != this; i++)
        if (std::strcmp(modify->fix[i]->style, "wall/rigid") == 0 &&
            shares_wallforce(static_cast<FixWallRigid *>(modify->fix[i])))
            wallforce_clear_ = false;
    init_predef();
    if (vtk_every_ > 0 && !vtk_mesh_ok_)
        init_vtk_mesh();
    init_facets();
    /* The usual block in one pass: the built-in hertz law on unit areas, with nothing
     * that reads the staged arrays afterwards (conduction, a mesh's facets). */
    one_pass_ =
        hertz_ && law_kind_ == LAW_BUILTIN && !lig_ && !conduction_ && !facets_ &&
        (area_mode_ == AREA_NODE || (area_mode_ == AREA_CONSTANT && area_const_ == 1.0));
    /* ... and on a revolved LINE, per run of spheres without the block's columns. */
    line_pass_ = one_pass_ && !belt_ && rs_line_revolution(&surf_) &&
                 !rs_surface_has_candidates(&surf_);
    if (1 + atom_size() > kExchangeMax) {
        std::ostringstream o;
        o << "each atom would carry " << 1 + atom_size() << " doubles of contact history ("
          << capacity_ << " contacts x (" << slot_size() - nstatev_ << " + " << nstatev_
          << " state variables) and " << 1 + row_size()
          << " more) through LIGGGHTS's atom exchange, whose buffer leaves room for "
          << kExchangeMax << "; lower 'contacts' or the state variables";
        fail(o.str());
    }
    init_scratch();
    rebuild_ = true;
}

/* law hertz or hooke without props: the LIGGGHTS material properties of the particle type
 * and the wall type, looked up as fix wall/gran looks them up (global_properties.cpp):
 * hertz's last property is the curvature flag, hooke's the characteristic velocity. */
void FixWallRigid::init_material_props()
{
    const double curv = props_.empty() ? 0.0 : props_[0];
    const int max_type = force->registry.max_type();
    const char *cs = hooke_ ? "fix wall/rigid (law hooke)" : "fix wall/rigid (law hertz)";
    FixPropertyGlobal *Y = static_cast<FixPropertyGlobal *>(modify->find_fix_property(
        "youngsModulus", "property/global", "peratomtype", max_type, 0, cs));
    FixPropertyGlobal *nu = static_cast<FixPropertyGlobal *>(modify->find_fix_property(
        "poissonsRatio", "property/global", "peratomtype", max_type, 0, cs));
    FixPropertyGlobal *e = static_cast<FixPropertyGlobal *>(
        modify->find_fix_property("coefficientRestitution", "property/global",
                                  "peratomtypepair", max_type, max_type, cs));
    FixPropertyGlobal *mu = static_cast<FixPropertyGlobal *>(
        modify->find_fix_property("coefficientFriction", "property/global",
                                  "peratomtypepair", max_type, max_type, cs));
    /* hooke: the characteristic velocity of LIGGGHTS's hooke model, a global scalar */
    double last = curv;
    if (hooke_) {
        FixPropertyGlobal *cv = static_cast<FixPropertyGlobal *>(modify->find_fix_property(
            "characteristicVelocity", "property/global", "scalar", 0, 0, cs));
        last = cv->compute_scalar();
    }
    const int w = wall_type_ - 1;
    type_props_.assign(atom->ntypes + 1, std::vector<double>());
    for (int t = 1; t <= max_type && t <= atom->ntypes; t++) {
        const int p = t - 1;
        std::vector<double> v = {Y->compute_vector(p),
                                 nu->compute_vector(p),
                                 Y->compute_vector(w),
                                 nu->compute_vector(w),
                                 e->compute_array(p, w),
                                 mu->compute_array(p, w),
                                 last};
        rs_error err;
        rs_error_clear(&err);
        if (rs_law_check_props(law_, v.data(), (int)v.size(), &err) != RS_OK) {
            std::ostringstream o;
            o << "material properties of particle type " << t << " against wall type "
              << wall_type_ << ": " << err.msg;
            fail(o.str());
        }
        type_props_[t] = v;
    }
    props_.assign(1, curv);
}

void FixWallRigid::init_variables()
{
    auto find = [&](const std::string &name) {
        int iv = input->variable->find(const_cast<char *>(name.c_str()));
        if (iv < 0)
            fail("variable v_" + name + " (motion) does not exist");
        if (!input->variable->equalstyle(iv))
            fail("variable v_" + name + " (motion) must be equal-style");
        return iv;
    };
    for (int d = 0; d < 3; d++)
        ivar_vel_[d] = var_vel_[d].empty() ? -1 : find(var_vel_[d]);
    ivar_omega_ = var_omega_.empty() ? -1 : find(var_omega_);
    ivar_spin_ = var_spin_.empty() ? -1 : find(var_spin_);
}

void FixWallRigid::init_heat()
{
    fix_temp_ = static_cast<FixPropertyAtom *>(
        modify->find_fix_property("Temp", "property/atom", "scalar", 0, 0, style, false));
    fix_heatflux_ = static_cast<FixPropertyAtom *>(modify->find_fix_property(
        "heatFlux", "property/atom", "scalar", 0, 0, style, false));
    fix_heatcap_ = NULL;
    if (fix_temp_) {
        const int max_type = force->registry.max_type();
        fix_heatcap_ = static_cast<FixPropertyGlobal *>(
            modify->find_fix_property("thermalCapacity", "property/global", "peratomtype",
                                      max_type, 0, style, false));
    }
}

void FixWallRigid::init_predef()
{
    predef_fix_.clear();
    for (const std::string &name : predef_names_) {
        FixPropertyAtom *f = static_cast<FixPropertyAtom *>(modify->find_fix_property(
            name.c_str(), "property/atom", "scalar", 0, 0, style, false));
        if (!f)
            fail(
                "keyword 'predef': no fix property/atom holding a per-atom scalar named '" +
                name + "'");
        predef_fix_.push_back(f);
    }
}

void FixWallRigid::init_vtk_mesh()
{
    const double span =
        std::sqrt(domain->xprd * domain->xprd + domain->yprd * domain->yprd +
                  domain->zprd * domain->zprd);
    rs_error err;
    rs_error_clear(&err);
    if (rs_surface_triangulate(&surf_, span, 72, &vtk_mesh_, &err) != RS_OK)
        fail(std::string("keyword 'vtk': ") + err.msg);
    vtk_mesh_ok_ = true;

    /* Rank 0 writes the files: their folder must exist and take files, and the name must
     * not be a folder. Found here, every rank stops with the same message. */
    int bad = 0;
    if (comm->me == 0) {
        const size_t slash = vtk_file_.rfind('/');
        const std::string dir =
            slash == std::string::npos ? "." : vtk_file_.substr(0, slash + 1);
        struct stat st;
        if (stat(vtk_file_.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
            bad = EISDIR;
        else if (access(dir.c_str(), W_OK) != 0)
            bad = errno ? errno : EACCES;
    }
    MPI_Bcast(&bad, 1, MPI_INT, 0, world);
    if (bad)
        fail("keyword 'vtk': cannot write '" + vtk_file_ + "': " + std::strerror(bad));
}

/* Once per fix, as LIGGGHTS checks its own contact models: a warning when the time step
 * exceeds RS_STEP_FRACTION of the law's critical step (rs_law_critical_step_fn) for the
 * smallest value over the group's particles. A law without one is not checked. */
void FixWallRigid::check_step()
{
    step_checked_ = true;
    if (!law_->critical_step)
        return;
    const double *radius = atom->radius, *rmass = atom->rmass;
    const int *mask = atom->mask, *type = atom->type;
    double tmin = INFINITY;
    for (int i = 0; i < atom->nlocal; i++) {
        if (!(mask[i] & groupbit))
            continue;
        const double R = radius[i];
        const double A = area_mode_ == AREA_CONSTANT    ? area_const_
                         : area_mode_ == AREA_PROJECTED ? RS_PI * R * R
                                                        : 1.0;
        const std::vector<double> *pv = &props_;
        if (material_props() && type[i] < (int)type_props_.size())
            pv = &type_props_[type[i]];
        const double t =
            law_->critical_step(law_, pv->data(), (int)pv->size(), R, rmass[i], A);
        if (t > 0.0)
            tmin = std::min(tmin, t);
    }
    double tall = INFINITY;
    MPI_Allreduce(&tmin, &tall, 1, MPI_DOUBLE, MPI_MIN, world);
    const double dt = update->dt;
    if (comm->me == 0 && std::isfinite(tall) && dt > RS_STEP_FRACTION * tall) {
        std::ostringstream o;
        o.precision(6);
        o << "Fix wall/rigid " << id << ": time step " << dt << " is " << dt / tall
          << " of the critical step " << tall << " of law '" << law_->name << "'"
          << (hertz_ ? " (Rayleigh time)" : " (2 sqrt(m/k))")
          << "; contacts with the wall may be unstable above " << RS_STEP_FRACTION;
        error->warning(FLERR, o.str().c_str());
    }
}

/* ---------------------------------------------------------------------------------- */
/* The step                                                                           */

/* Forces without history: LIGGGHTS walls compute setup forces with the shear history
 * frozen. Here the history rows of each block are saved, the tracker is run with a zero
 * increment and no master rotation, the law with b->setup = 1, and the rows restored.
 * Each run is an Abaqus step: the setup starts step kstep_ and its step time. The law
 * sees the setup call as increment 1 of the step (a user routine never gets KINC = 0);
 * what it asks of the step there (PNEWDT) is not counted, as the call is not an
 * increment. */
void FixWallRigid::setup(int vflag)
{
    (void)vflag;
    kstep_++;
    run_time0_ = update->atime + (update->ntimestep - update->atimestep) * update->dt;
    rs_law_requests_clear(&requests_);
    if (!step_checked_)
        check_step();
    compute(true);
    conduct_ready_ = true;
    if (vtk_every_ > 0 && update->ntimestep % vtk_every_ == 0)
        write_vtk();
}

void FixWallRigid::initial_integrate(int vflag)
{
    (void)vflag;
    rs_error err;
    rs_error_clear(&err);
    if (rs_motion_advance(&motion_, update->dt, &err) != RS_OK)
        fail(std::string("motion: ") + err.msg);
}

void FixWallRigid::pre_neighbor()
{
    rebuild_ = true;
}

void FixWallRigid::post_force(int vflag)
{
    (void)vflag;
    compute(false);
}

void FixWallRigid::end_of_step()
{
    write_vtk();
}

void FixWallRigid::post_run()
{
    report_requests();
}

/* At the end of a run, over all ranks: one warning with the smallest PNEWDT < 1 the
 * law's user routine returned, the step it suggests (dt PNEWDT) and how many calls
 * asked; and once per fix, as check_step, a warning when the time step exceeds
 * RS_STEP_FRACTION of the critical step 2 sqrt(m / (k A)) of the stiffness the routine
 * returned (DDSDDR, DDTDDG). */
void FixWallRigid::report_requests()
{
    const rs_law_requests &r = requests_;
    struct {
        double value;
        int rank;
    } mine = {r.pnewdt_calls > 0 ? r.pnewdt_min : INFINITY, comm->me}, least;
    MPI_Allreduce(&mine, &least, 1, MPI_DOUBLE_INT, MPI_MINLOC, world);
    double calls = (double)r.pnewdt_calls, all_calls = 0.0;
    MPI_Allreduce(&calls, &all_calls, 1, MPI_DOUBLE, MPI_SUM, world);
    int where[2] = {r.pnewdt_particle, r.pnewdt_feature};
    if (all_calls > 0.0)
        MPI_Bcast(where, 2, MPI_INT, least.rank, world);
    double step = r.step_min, step_all = INFINITY;
    MPI_Allreduce(&step, &step_all, 1, MPI_DOUBLE, MPI_MIN, world);
    const double dt = update->dt;
    if (comm->me == 0 && all_calls > 0.0) {
        std::ostringstream o;
        o.precision(6);
        o << "Fix wall/rigid " << id << ": law '" << law_->name << "': " << all_calls
          << " call(s) of the user routine asked for a smaller increment this run "
          << "(PNEWDT < 1), the smallest PNEWDT = " << least.value << " at particle "
          << where[0] << ", feature " << where[1] << ", which suggests a time step of "
          << dt * least.value << "; an explicit step cannot repeat an increment "
          << "(keyword 'pnewdt stop' makes this an error)";
        error->warning(FLERR, o.str().c_str());
    }
    if (!routine_step_warned_ && std::isfinite(step_all) &&
        dt > RS_STEP_FRACTION * step_all) {
        routine_step_warned_ = true;
        if (comm->me == 0) {
            std::ostringstream o;
            o.precision(6);
            o << "Fix wall/rigid " << id << ": time step " << dt << " is " << dt / step_all
              << " of the critical step " << step_all << " of law '" << law_->name
              << "' (2 sqrt(m/(k A)) of the stiffness its routine returned"
              << (r.step_what ? std::string(", ") + r.step_what : std::string())
              << "); contacts with the wall may be unstable above " << RS_STEP_FRACTION;
            error->warning(FLERR, o.str().c_str());
        }
    }
    rs_law_requests_clear(&requests_);
}

/* Scratch of one block, sized once for RS_BLOCK particles and RS_BLOCK * capacity
 * contacts (the tracker never emits more: a particle with more contacts than slots is an
 * error), so the step itself allocates and fills nothing it does not need. */
void FixWallRigid::init_scratch()
{
    const size_t np = RS_BLOCK, nc = (size_t)RS_BLOCK * capacity_, nd = ndir_;
    const size_t npred = std::max((int)predef_names_.size(), 1);
    for (std::vector<double> *a :
         {&bx_, &by_, &bz_, &bvx_, &bvy_, &bvz_, &bwx_, &bwy_, &bwz_, &brad_})
        a->resize(np);
    bid_.resize(np), bdir_.resize(np), bhist_.resize(np), bidx_.resize(np);
    take_.resize(np);
    deepest_.resize(np);
    for (std::vector<double> *a : {&bmass_, &bheat_, &btemp_, &bdtemp_, &bgap_})
        a->resize(np);
    btype_.resize(np);
    bpred_.resize(np * npred), bdpred_.resize(np * npred);
    leaving_.resize(nc);
    cb_.area_mode = area_mode_ == AREA_CONSTANT    ? RS_AREA_CONSTANT
                    : area_mode_ == AREA_PROJECTED ? RS_AREA_PROJECTED
                                                   : RS_AREA_NODE;
    cb_.area_const = area_const_;
    cb_.ndir = (int)nd;
    cb_.nstatev = nstatev_;
    cb_.npred = (int)predef_names_.size();
    rs_error err;
    if (rs_cblock_reserve(&cb_, (int)nc, &err) != RS_OK)
        fail(err.msg);

    /* The law block's fields that stay for the run. */
    rs_law_block_init(&blk_);
    blk_.kStep = 1;
    blk_.nSurfDir = ndir_ - 1;
    blk_.nDir = ndir_;
    blk_.nStateVar = nstatev_;
    blk_.nPred = (int)predef_names_.size();
    rs_law_block_set_name(blk_.surfInt, id);
    rs_law_block_set_name(blk_.surfSlv, group->names[igroup]);
    rs_law_block_set_name(blk_.surfMst, surf_.name[0] ? surf_.name : id);
    blk_.tempMst = temp_mst_;
    blk_.dtempMst = dtemp_mst_;
    blk_.wall_type = wall_type_;
    blk_.analytic_master = !rs_surface_has_facets(&surf_);
}

/* A query of atoms idx[0 .. n) as spheres, gathered into the block scratch, against the
 * wall in its current pose; the caller sets gap_max and dist_min. */
rs_query FixWallRigid::sphere_query(const int *idx, int n)
{
    double **x = atom->x;
    const double *radius = atom->radius;
    for (int k = 0; k < n; k++) {
        const int i = idx[k];
        bx_[k] = x[i][0];
        by_[k] = x[i][1];
        bz_[k] = x[i][2];
        brad_[k] = radius[i];
    }
    rs_query q = rs_query(); // LIGGGHTS 3.8.0's particles are spheres: no bodies
    q.n = n;
    q.slave.n = n;
    q.slave.x = bx_.data();
    q.slave.y = by_.data();
    q.slave.z = bz_.data();
    q.slave.radius = brad_.data();
    q.pose = &motion_.pose;
    q.gap_max = 0.0;
    q.dist_min = 0.0;
    return q;
}

void FixWallRigid::compute(bool setup_call)
{
    for (int d = 0; d < 3; d++)
        f_wall_[d] = m_wall_[d] = 0.0;
    se_now_ = 0.0;
    ncontact_ = 0;
    out_valid_ = false;
    heat_step_ = 0.0;
    begin_facets();
    begin_wallforce();

    /* Per-atom output: every candidate's row is written by its block each step, so only
     * the rows that may stop being candidates are zeroed here: all of them after a
     * reneighbouring (local indices change), the old candidates' before a refresh the
     * wall's motion asks for. Between the two, indices and candidates are fixed. */
    bool refresh = rebuild_ || setup_call;
    if (refresh) {
        const int nlocal = array_atom ? atom->nlocal : 0;
        for (int i = 0; i < nlocal; i++)
            for (int c = 0; c < 6; c++)
                array_atom[i][c] = 0.0;
    } else if (wall_moved_beyond_skin()) {
        if (array_atom)
            for (int i : cand_)
                for (int c = 0; c < 6; c++)
                    array_atom[i][c] = 0.0;
        refresh = true;
    }
    if (refresh) {
        build_candidates();
        if (looks_behind())
            warn_behind();
    }

    /* The candidates this step: all of them, less those whose distance bound keeps them
     * beyond the tracking thickness (a test as cheap as a primitive wall's; a particle
     * that holds a contact has no bound, update_bounds). */
    const int *list = cand_.data();
    int nc = (int)cand_.size();
    if ((bounds_ok_ || list_bounds_) && !setup_call) {
        double **x = atom->x;
        const double *radius = atom->radius;
        active_.resize(cand_.size());
        int na = 0;
        for (int c = 0; c < nc; c++) {
            const int i = cand_[c];
            const double room = gapref_[i] - tracking_;
            const double *xr = &xref_[4 * (size_t)i];
            if (room > 0.0 && radius[i] == xr[3]) {
                const double dx = x[i][0] - xr[0], dy = x[i][1] - xr[1],
                             dz = x[i][2] - xr[2];
                if (dx * dx + dy * dy + dz * dz < room * room)
                    continue;
            }
            active_[na++] = i;
        }
        list = active_.data();
        nc = na;
    }

    /* Blocks of at most RS_BLOCK particles; with per-type properties a block holds one
     * particle type (the candidates are sorted by type). */
    const bool per_type = material_props();
    const int *type = atom->type;
    for (int b0 = 0; b0 < nc;) {
        int b1 = std::min(nc, b0 + RS_BLOCK);
        if (per_type)
            for (int k = b0 + 1; k < b1; k++)
                if (type[list[k]] != type[list[b0]]) {
                    b1 = k;
                    break;
                }
        if (line_pass_ && !setup_call)
            line_block(&list[b0], b1 - b0);
        else
            process_block(&list[b0], b1 - b0, setup_call);
        b0 = b1;
    }

    if (!setup_call) {
        /* Wall heat: a lumped capacity integrates the total flux into it. */
        double q = heat_step_;
        if (capacity_wall_ > 0.0) {
            double qall = 0.0;
            MPI_Allreduce(&q, &qall, 1, MPI_DOUBLE, MPI_SUM, world);
            dtemp_wall_ = qall * update->dt / capacity_wall_;
            temp_wall_ += dtemp_wall_;
        }
        heat_wall_ += q * update->dt;
        temp_mst_[0] = temp_wall_;
        dtemp_mst_[0] = dtemp_wall_;
        update_previous_fields();
    }
}
