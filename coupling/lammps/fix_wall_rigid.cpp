/* fix wall/rigid in LAMMPS: the adapter over the rigidsurf wall (fix_wall_rigid.h). Its
 * lifecycle maps onto the wall's calls: the constructor makes the wall from the fix's words
 * (less the material keywords, wall_materials.h), init its run, setup its setup call,
 * initial_integrate its motion, post_force its step, final_integrate its servo; the atom
 * callbacks move its per-atom history. The group's ellipsoids and rounded polyhedra go to
 * the wall as convex bodies (bodies.h), in a run that asks every particle at every step.
 * Syntax, keywords and output: docs/fix_wall_rigid.md and, for what is LAMMPS's own,
 * docs/lammps.md. */
#include "fix_wall_rigid.h"
#include "fix_wall_rigid_force.h"
#include "lammps_law.h"

#include "adapter.h"

#include "atom.h"
#include "atom_vec_body.h"
#include "atom_vec_ellipsoid.h"
#include "body.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "input.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"
#include "variable.h"

#include <algorithm>
#include <climits>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

/* ---------------------------------------------------------------------------------- */
/* The host table: what only LAMMPS knows.                                            */

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

int FixWallRigid::material(const char *name, int i, int j, int required, const char *who,
                           double *value, rs_error *err)
{
    return materials_.lookup(name, i, j, info_->wall_type, required, who, value, err);
}

/* ---------------------------------------------------------------------------------- */

FixWallRigid::FixWallRigid(LAMMPS *lmp, int narg, char **arg)
    : RsWallAtoms<Fix>(lmp, narg, arg), avec_(nullptr), bvec_(nullptr), bodies_on_(false),
      model_(nullptr), reff_mode_(0), wallforce_clear_(true)
{
    std::memset(&model_desc_, 0, sizeof model_desc_);
    host_ = rs_adapter_host(this, comm->me, atom->ntypes, "lammps");
    std::vector<std::string> words(arg + 3, arg + narg);
    const std::string bad = materials_.take(words, atom->ntypes);
    if (!bad.empty())
        fail(bad);
    std::vector<const char *> w;
    for (const std::string &s : words)
        w.push_back(s.c_str());
    const int ncb = atom->nextra_grow;
    rs_error err;
    rs_error_clear(&err);
    if (rs_wall_create(id, group->names[igroup], w.data(), (int)w.size(), &host_, &wall_,
                       &err) != RS_OK)
        fail(err.msg);
    info_ = rs_wall_get_info(wall_);
    if (info_->conduction)
        fail("keyword 'conduction liggghts' is LIGGGHTS's wall conduction under fix "
             "heat/gran; LAMMPS keeps no per-atom temperature");
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
    array_atom = nullptr;
    maxexchange_dynamic = 1;

    grow_arrays(atom->nmax);
    /* law lammps's model is a FixWallGran, whose constructor registers the atom callbacks
     * of the fix being made, this one (LammpsWallModel); otherwise this fix does */
    if (atom->nextra_grow == ncb) {
        atom->add_callback(Atom::GROW);
        atom->add_callback(Atom::RESTART);
    }
}

FixWallRigid::~FixWallRigid()
{
    if (model_)
        model_->release_callbacks(id);
    else {
        atom->delete_callback(id, Atom::GROW);
        atom->delete_callback(id, Atom::RESTART);
    }
    delete model_;
    memory->destroy(array_atom);
    delete[] extlist;
    extlist = nullptr;
    rs_wall_free(wall_);
}

void FixWallRigid::fail(const std::string &msg)
{
    error->all(FLERR, std::string("Fix wall/rigid ") + id + ": " + msg);
}

/* Error::one prints on a rank's screen, which only rank 0 has: the others print the message
 * on their standard error first. */
void FixWallRigid::fail_one(const std::string &msg)
{
    const std::string m = std::string("Fix wall/rigid ") + id + ": " + msg;
    if (!screen) {
        std::fprintf(stderr, "ERROR on proc %d: %s\n", comm->me, m.c_str());
        std::fflush(stderr);
    }
    error->one(FLERR, m);
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

/* store_force: the per-atom array fix wall/rigid/force of ID force_ID (force_W for 'into
 * W'), made with the fix unless it exists. */
void FixWallRigid::post_constructor()
{
    if (info_->store_force && modify->find_fix(wallforce_id_) < 0)
        modify->add_fix(wallforce_id_ + " all wall/rigid/force");
}

void FixWallRigid::init()
{
    if (atom->line_flag || atom->tri_flag)
        fail(std::string("atom_style ") + atom->atom_style +
             " is not supported: the fix takes spheres (atom_style sphere), ellipsoids "
             "(atom_style ellipsoid) and rounded polyhedra (atom_style body "
             "rounded/polyhedron)");
    avec_ = atom->ellipsoid_flag
                ? dynamic_cast<AtomVecEllipsoid *>(atom->style_match("ellipsoid"))
                : nullptr;
    bvec_ =
        atom->body_flag ? dynamic_cast<AtomVecBody *>(atom->style_match("body")) : nullptr;
    if (atom->body_flag &&
        (!bvec_ || std::strcmp(bvec_->bptr->style, "rounded/polyhedron") != 0))
        fail("atom_style body: the fix takes rounded/polyhedron bodies only, not " +
             std::string(bvec_ ? bvec_->bptr->style : "those of this hybrid style"));
    if ((avec_ || bvec_) && (!atom->rmass_flag || !atom->angmom_flag || !atom->torque_flag))
        fail("ellipsoids and bodies need per-atom mass, angmom and torque (atom_style "
             "ellipsoid, body), as fix nve/asphere and nve/body read them");
    if (!avec_ && !bvec_ &&
        (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag ||
         !atom->torque_flag))
        fail("needs per-atom radius, mass, omega and torque (atom_style sphere), or "
             "ellipsoids (atom_style ellipsoid) or bodies (atom_style body)");
    check_particles();
    if (std::strstr(update->integrate_style, "respa"))
        fail("run_style respa is not supported; use verlet");
    if (model_)
        model_->init();
    pred_index_.clear();
    for (int a = 0; a < info_->npred; a++) {
        int flag = -1, cols = -1;
        const int k = atom->find_custom(info_->pred[a], flag, cols);
        if (k < 0 || flag != 1 || cols != 0)
            fail(std::string("keyword 'predef': no per-atom floating-point vector d_") +
                 info_->pred[a] + " (fix property/atom d_" + info_->pred[a] + ")");
        pred_index_.push_back(k);
    }
    if (info_->store_force && modify->find_fix(wallforce_id_) < 0)
        fail("store_force: fix " + wallforce_id_ + " (the stored force) was deleted");
    /* store_force into W: the first wall/rigid in the fix list that stores into W clears it
     * each step */
    wallforce_clear_ = true;
    for (int i = 0; info_->store_force && i < modify->nfix && modify->fix[i] != this; i++)
        if (std::strcmp(modify->fix[i]->style, "wall/rigid") == 0 &&
            static_cast<FixWallRigid *>(modify->fix[i])->wallforce_id_ == wallforce_id_)
            wallforce_clear_ = false;

    const rs_wall_run run = rs_adapter_run(
        update->dt, neighbor->skin, neighbor->delay, neighbor->every, neighbor->dist_check,
        neighbor->build_once, domain->boxlo, domain->boxhi, 0);
    rs_wall_run r = run;
    r.every_particle = bodies_on_ ? 1 : 0;
    const rs_wall_block b = block(true);
    rs_error err;
    rs_error_clear(&err);
    if (rs_wall_init(wall_, &r, &b, &err) != RS_OK)
        fail(err.msg);
    exchange_size();
}

/* The most doubles an atom's history takes through LAMMPS's exchange: the wall's record,
 * which grows with its slots (maxexchange_dynamic). */
void FixWallRigid::exchange_size()
{
    maxexchange = rs_wall_pack_size(wall_);
}

/* The group's particles at a run's start: each a body (an ellipsoid or a rounded
 * polyhedron) or a sphere (a particle of atom_style ellipsoid or body without a shape or
 * body is neither); bodies_on_ when a body is among them on any rank. */
void FixWallRigid::check_particles()
{
    double v[2] = {0.0, 1e300}; // the ellipsoids, the smallest id of a particle of neither
    for (int i = 0; i < atom->nlocal; i++) {
        if (!(atom->mask[i] & groupbit))
            continue;
        if ((avec_ && atom->ellipsoid[i] >= 0) || (bvec_ && atom->body[i] >= 0))
            v[0] += 1.0;
        else if (!atom->radius_flag || !atom->omega_flag)
            v[1] = std::min(v[1], (double)atom->tag[i]);
    }
    reduce(&v[0], 1, RS_REDUCE_SUM);
    reduce(&v[1], 1, RS_REDUCE_MIN);
    if (v[1] < 1e300)
        fail("particle " + std::to_string((long long)v[1]) + " of group " +
             group->names[igroup] +
             " is neither a body, an ellipsoid nor a sphere: give it a shape (set ... "
             "shape, or a body in the data file) or use atom_style hybrid for spheres");
    bodies_on_ = v[0] > 0.0;
    if (bodies_on_ && model_)
        fail(
            "law lammps runs LAMMPS's sphere-wall models, which take a sphere's centre and "
            "radius; ellipsoids and bodies take rigidsurf's laws (hertz, hooke, coulomb, "
            "...) or a "
            "user's law");
}

/* atom_style ellipsoid and body: each ellipsoid of the group as the wall's body (its
 * half-axes and quaternion from LAMMPS's bonus data, its angular velocity from angmom),
 * each rounded polyhedron from its bonus data as body_rounded_polyhedron.cpp keeps it
 * (ivalue: vertices, edges, faces; dvalue: the vertices in its principal axes, the edges'
 * ends, 4 vertex indices a face, the enclosing and the rounded radius; the bonus's
 * principal moments), each sphere with its radius and omega. */
void FixWallRigid::fill_bodies()
{
    const int n = atom->nlocal, FACE = 4;
    bodies_.resize(n);
    rs_error err;
    rs_error_clear(&err);
    for (int i = 0; i < n; i++) {
        const int e = avec_ ? atom->ellipsoid[i] : -1, k = bvec_ ? atom->body[i] : -1;
        if (e < 0 && k < 0) {
            bodies_.sphere(i, atom->radius ? atom->radius[i] : 0.0,
                           atom->omega ? atom->omega[i] : nullptr);
            continue;
        }
        if (!(atom->mask[i] & groupbit))
            continue;
        const std::string who = "particle " + std::to_string((long long)atom->tag[i]);
        if (!bodies_on_)
            fail_one(who + " of group " + group->names[igroup] +
                     " became a body during a run that began without bodies in it; the "
                     "wall takes it from the next run on");
        int rc;
        if (e >= 0) {
            const AtomVecEllipsoid::Bonus &bo = avec_->bonus[e];
            rc = bodies_.ellipsoid(i, bo.shape, atom->x[i], bo.quat, atom->rmass[i],
                                   atom->angmom[i], &err);
        } else {
            const AtomVecBody::Bonus &bo = bvec_->bonus[k];
            const int nv = bo.ivalue[0], ne = nv < 3 ? 0 : bo.ivalue[1],
                      nf = nv < 3 ? 0 : bo.ivalue[2];
            const double *d = bo.dvalue;
            rc = bodies_.polyhedron(i, d, nv, d + 3 * nv + 2 * ne, nf, FACE,
                                    d[bo.ndouble - 1], atom->x[i], bo.quat, atom->rmass[i],
                                    bo.inertia, atom->angmom[i], &err);
        }
        if (rc != RS_OK)
            fail_one(who + ": " + err.msg);
    }
}

/* The atoms as the wall reads them: LAMMPS's arrays, contiguous rows of 3; with
 * atom_style ellipsoid, the radii, angular velocities and bodies of fill_bodies. */
rs_wall_block FixWallRigid::block(bool setup)
{
    rs_wall_block b;
    std::memset(&b, 0, sizeof b);
    b.n = atom->nlocal;
    b.x = atom->x ? atom->x[0] : nullptr;
    b.v = atom->v ? atom->v[0] : nullptr;
    b.omega = atom->omega ? atom->omega[0] : nullptr;
    b.radius = atom->radius;
    if (avec_ || bvec_) {
        fill_bodies();
        b.omega = bodies_.omega();
        b.radius = bodies_.radius();
        b.body = bodies_on_ ? bodies_.bodies() : nullptr;
    }
    b.mass = atom->rmass;
    b.type = atom->type;
    b.id = atom->tag;
    b.mask = atom->mask;
    b.groupbit = groupbit;
    pred_.resize(pred_index_.size());
    for (size_t a = 0; a < pred_index_.size(); a++)
        pred_[a] = atom->dvector[pred_index_[a]];
    b.pred = pred_.empty() ? nullptr : pred_.data();
    b.step = update->ntimestep;
    b.inc = (int)(update->ntimestep - update->firststep);
    b.time = rs_adapter_time(update->atime, update->atimestep, update->ntimestep,
                             update->dt, setup);
    return b;
}

/* Where the wall's loads go: LAMMPS's force and torque, the stored force, the per-atom
 * array. */
rs_wall_rows FixWallRigid::rows()
{
    rs_wall_rows r;
    std::memset(&r, 0, sizeof r);
    r.f = atom->f ? atom->f[0] : nullptr;
    r.torque = atom->torque ? atom->torque[0] : nullptr;
    r.peratom = array_atom ? array_atom[0] : nullptr;
    if (info_->store_force) {
        const int ifix = modify->find_fix(wallforce_id_);
        if (ifix < 0)
            fail_one("store_force: fix " + wallforce_id_ +
                     " (the stored force) was deleted");
        r.fstore =
            static_cast<FixWallRigidForce *>(modify->fix[ifix])->rows(wallforce_clear_);
    }
    return r;
}

/* The forces before the first step, with the history frozen, as LAMMPS's walls compute
 * their setup forces. */
void FixWallRigid::setup(int)
{
    const rs_wall_block b = block(true);
    const rs_wall_rows r = rows();
    rs_error err;
    rs_error_clear(&err);
    if (rs_wall_setup(wall_, &b, &r, nullptr, &err) != RS_OK)
        fail_one(err.msg);
    exchange_size();
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
    if (rs_wall_step(wall_, &b, &r, update->dt, nullptr, &err) != RS_OK)
        fail_one(err.msg);
    exchange_size();
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

void FixWallRigid::reset_dt()
{
    if (model_)
        model_->reset_dt();
}
