/* fix wall/rigid in LAMMPS, law lammps: LAMMPS's wall contact models (lammps_law.h) as a
 * force law of the wall (RS_LAW_SETS_FORCE): each live contact of a block described as
 * LAMMPS's walls describe it (rs_wall_force_contact), the model's force F and torque T on
 * the particle (its lever arm is the sphere's radius R, as on LAMMPS's walls) as the law's
 * force and torque, which the wall applies times the contact's share, with -F and the
 * moment
 * -((x - o) x F + T) on the wall. Which contacts the model sees follows LAMMPS's wall loop
 * (FixWallGran::post_force): touching ones, and for JKR those within its pull-off distance
 * of a contact that has touched; a contact beyond has its history cleared. */
#include "lammps_law.h"
#include "fix_wall_rigid.h"

#include "atom.h"
#include "comm.h"
#include "group.h"
#include "memory.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <mpi.h>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

LammpsWallModel::LammpsWallModel(LAMMPS *lmp, int narg, char **arg)
    : FixWallGran(lmp, narg, arg)
{
    /* the wall keeps the history, per contact */
    memory->destroy(history_one);
    history_one = nullptr;
}

void LammpsWallModel::release_callbacks(const char *fix_id)
{
    delete[] id;
    id = utils::strdup(fix_id);
}

void LammpsWallModel::contact(double rsq, double dx, double dy, double dz, double *vwall,
                              double rwall, double *v, double *F, double *omega, double *T,
                              double radius, double meff, double *history)
{
    switch (pairstyle) {
    case HOOKE:
        hooke(rsq, dx, dy, dz, vwall, v, F, omega, T, radius, meff, nullptr);
        break;
    case HOOKE_HISTORY:
        hooke_history(rsq, dx, dy, dz, vwall, v, F, omega, T, radius, meff, history,
                      nullptr);
        break;
    case HERTZ_HISTORY:
        hertz_history(rsq, dx, dy, dz, vwall, rwall, v, F, omega, T, radius, meff, history,
                      nullptr);
        break;
    default:
        granular(rsq, dx, dy, dz, vwall, rwall, v, F, omega, T, radius, meff, history,
                 nullptr);
    }
}

namespace
{

int lammps_law_update(const rs_law *law, rs_law_block *b, rs_error *err)
{
    return static_cast<FixWallRigid *>(law->ctx)->lammps_update(b, err);
}

int lammps_law_one(const rs_law *law, rs_force_contact *c, double F[3], double T[3],
                   rs_error *)
{
    return static_cast<FixWallRigid *>(law->ctx)->lammps_one(*c, F, T);
}

double lammps_law_reach(const rs_law *law, const double *, int)
{
    return static_cast<FixWallRigid *>(law->ctx)->lammps_reach();
}

/* Words of fix wall/gran that give its wall, not its model: the surface gives the wall. */
const char *const kWallWords[] = {"xplane", "yplane", "zplane", "zcylinder",
                                  "region", "wiggle", "shear",  "contacts"};

} // namespace

/* law lammps [reff exact|region|flat] MODEL WORDS...: fix wall/gran's model words, up to
 * the next keyword of wall/rigid. */
int FixWallRigid::engine_law(const char *const *words, int nwords, const rs_law **law,
                             rs_error *err)
{
    const char *usage = "law lammps expects the model words of fix wall/gran: hooke, "
                        "hooke/history or hertz/history with kn kt gamma_n gamma_t xmu "
                        "dampflag [limit_damping], or granular with its models";
    if (!atom->sphere_flag)
        return rs_error_set(err, RS_ERR_ARG,
                            "law lammps needs atom_style sphere, as fix "
                            "wall/gran does");
    std::vector<std::string> model;
    for (int k = 0; k < nwords; k++) {
        if (std::strcmp(words[k], "reff") == 0) {
            const char *m = k + 1 < nwords ? words[k + 1] : "";
            if (std::strcmp(m, "exact") == 0)
                reff_mode_ = REFF_EXACT;
            else if (std::strcmp(m, "region") == 0)
                reff_mode_ = REFF_REGION;
            else if (std::strcmp(m, "flat") == 0)
                reff_mode_ = REFF_FLAT;
            else
                return rs_error_set(err, RS_ERR_ARG,
                                    "law lammps: 'reff' expects exact, region or flat, got "
                                    "'%s'",
                                    k + 1 < nwords ? m : "(end of line)");
            k++;
            continue;
        }
        for (const char *w : kWallWords)
            if (std::strcmp(words[k], w) == 0)
                return rs_error_set(err, RS_ERR_ARG,
                                    "law lammps takes fix wall/gran's model words; '%s' "
                                    "belongs to its wall, which 'surface' gives here",
                                    w);
        model.push_back(words[k]);
    }
    static const char *const kModels[] = {"hooke", "hooke/history", "hertz/history",
                                          "granular"};
    const bool known =
        !model.empty() && std::any_of(std::begin(kModels), std::end(kModels),
                                      [&](const char *m) { return model[0] == m; });
    if (!known)
        return rs_error_set(err, RS_ERR_ARG, "%s; got '%s'", usage,
                            model.empty() ? "(nothing)" : model[0].c_str());
    if (model[0] != "granular") {
        size_t nnum = model.size() - 1;
        if (nnum == 7 && model.back() == "limit_damping")
            nnum = 6;
        if (nnum < 6)
            return rs_error_set(err, RS_ERR_ARG,
                                "law lammps %s expects kn kt gamma_n gamma_t xmu dampflag "
                                "[limit_damping], got %d words after it",
                                model[0].c_str(), (int)model.size() - 1);
        if (nnum > 6)
            return rs_error_set(err, RS_ERR_ARG,
                                "law lammps %s expects kn kt gamma_n gamma_t xmu dampflag "
                                "[limit_damping]; after them, '%s' is neither that nor a "
                                "keyword of wall/rigid",
                                model[0].c_str(), model[7].c_str());
    }

    std::vector<std::string> args = {std::string(id) + "_lammps", group->names[igroup],
                                     "wall/gran"};
    args.insert(args.end(), model.begin(), model.end());
    args.push_back("region");
    args.push_back("rigidsurf");
    std::vector<char *> argv;
    for (std::string &s : args)
        argv.push_back(&s[0]);
    model_ = new LammpsWallModel(lmp, (int)argv.size(), argv.data());

    model_desc_.name = "lammps";
    model_desc_.nprops = 0;
    /* after the model's history, the effective radius a curved model's contact keeps */
    model_desc_.nstatev =
        model_->nhistory() + (model_->curved() && reff_mode_ != REFF_FLAT);
    model_desc_.update = lammps_law_update;
    model_desc_.reach = lammps_law_reach;
    model_desc_.force_one = lammps_law_one;
    model_desc_.ctx = this;
    model_desc_.skips = RS_LAW_SKIPS_STRESS | RS_LAW_SKIPS_ENERGY | RS_LAW_SKIPS_SLIP |
                        RS_LAW_SKIPS_DRDISP1;
    model_desc_.sets = RS_LAW_SETS_FORCE | RS_LAW_SETS_ENERGIES | RS_LAW_SETS_NO_HEAT |
                       RS_LAW_SETS_NO_CREEP_PLASTIC | RS_LAW_SETS_STRESS;
    *law = &model_desc_;
    return RS_OK;
}

int FixWallRigid::lammps_update(rs_law_block *b, rs_error *)
{
    rs_wall_force_begin(b);
    for (int e = 0; e < b->nSlvNod; e++) {
        rs_force_contact c;
        if (!rs_wall_force_contact(wall_, b, e, atom->x[0], &c))
            continue;
        double F[3] = {0.0, 0.0, 0.0}, T[3] = {0.0, 0.0, 0.0};
        if (lammps_one(c, F, T))
            rs_wall_force_result(b, e, &c, F, T);
    }
    return RS_OK;
}

int FixWallRigid::lammps_one(rs_force_contact &c, double F[3], double T[3])
{
    LammpsWallModel &m = *model_;
    m.set_history_update(!c.setup);
    const int nh = m.nhistory(), ns = model_desc_.nstatev;
    const bool jkr = m.jkr(), keep = ns > nh;
    /* r: the distance of the centre from the wall's point along n, as LAMMPS's walls
     * measure it (R - overlap rounds otherwise) */
    const double *xi = atom->x[c.row];
    const double R = c.radius;
    const double r = (xi[0] - c.xm[0]) * c.n[0] + (xi[1] - c.xm[1]) * c.n[1] +
                     (xi[2] - c.xm[2]) * c.n[2];
    const double rsq = r * r;
    const double rad = jkr ? R + m.pulloff_distance(R) : R;
    if (rsq > rad * rad || (jkr && c.history[0] == 0.0 && rsq > R * R)) {
        for (int h = 0; h < ns; h++)
            c.history[h] = 0.0;
        return 0;
    }
    /* The wall's radius of curvature as LAMMPS's models take it, rwall (0: a plane),
     * whose effective radius is R rwall / (R + rwall): the effective radius where the
     * contact began, which it keeps (its last state variable; 0 for a new contact).
     * LAMMPS's models take rwall as a constant of a contact: one that changed while
     * the contact lasts, as a sphere slides from a mantle onto a fillet, would make
     * the normal force do net work. */
    double rwall = 0.0;
    if (keep) {
        double &reff = c.history[ns - 1];
        if (reff == 0.0) {
            reff = R;
            if (reff_mode_ == REFF_EXACT) {
                reff = c.reff;
            } else {
                const double k =
                    std::fabs(c.curv[0]) >= std::fabs(c.curv[1]) ? c.curv[0] : c.curv[1];
                if (k != 0.0)
                    reff = R * (2.0 / k) / (R + 2.0 / k);
            }
        }
        if (reff != R)
            rwall = R * reff / (R - reff);
    }
    m.contact(rsq, r * c.n[0], r * c.n[1], r * c.n[2], c.vwall, rwall, atom->v[c.row], F,
              atom->omega[c.row], T, R, c.mass, c.history);
    return 1;
}

/* The default tracking thickness of law lammps: JKR acts within its pull-off distance of
 * the group's spheres (the largest over their radii, at init), the other models on
 * touching contacts only. */
double FixWallRigid::lammps_reach()
{
    if (!model_->jkr())
        return 0.0;
    double reach = 0.0;
    for (int i = 0; i < atom->nlocal; i++)
        if (atom->mask[i] & groupbit)
            reach = std::max(reach, model_->pulloff_distance(atom->radius[i]));
    double all = 0.0;
    MPI_Allreduce(&reach, &all, 1, MPI_DOUBLE, MPI_MAX, world);
    return all;
}
