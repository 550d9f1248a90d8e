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
#include "rigidsurf/contact_block.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
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

int lammps_law_run(const rs_law *law, const rs_force_run *r, rs_error *)
{
    static_cast<FixWallRigid *>(law->ctx)->lammps_run(*r);
    return RS_OK;
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
    model_desc_.force_run = lammps_law_run;
    model_desc_.ctx = this;
    /* LAMMPS's models keep their shear in space and turn it themselves: no drot */
    model_desc_.skips = RS_LAW_SKIPS_STRESS | RS_LAW_SKIPS_ENERGY | RS_LAW_SKIPS_SLIP |
                        RS_LAW_SKIPS_DRDISP1 | RS_LAW_SKIPS_DROT;
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

namespace
{

/* What the model's calls on the contacts of a block or a run share: the model, the atoms'
 * arrays, and how the wall's radius of curvature is taken. */
struct ModelCall {
    LammpsWallModel &m;
    double **v, **omega;
    int ns;        // state variables per contact: the model's history, then reff if kept
    int reff_mode; // REFF_
    bool jkr, keep;

    ModelCall(LammpsWallModel &model, Atom *atom, int nstatev, int mode)
        : m(model), v(atom->v), omega(atom->omega), ns(nstatev), reff_mode(mode),
          jkr(model.jkr()), keep(nstatev > model.nhistory())
    {
    }

    /* The effective radius a new contact keeps: of the wall's curvatures k1, k2 (reff_c
     * where given, not NaN) in REFF_EXACT; of 2/k, k the most curved direction's, as
     * LAMMPS's region walls, in REFF_REGION; R on a plane. Out of line: once a contact. */
    __attribute__((noinline)) double first_reff(double R, double k1, double k2,
                                                double reff_c) const
    {
        if (reff_mode == REFF_EXACT)
            return std::isnan(reff_c) ? rs_effective_radius(R, k1, k2) : reff_c;
        const double k = std::fabs(k1) >= std::fabs(k2) ? k1 : k2;
        return k != 0.0 ? R * (2.0 / k) / (R + 2.0 / k) : R;
    }

    /* The contact of the sphere of row `row` (radius R, mass) at the wall's point of
     * normal n, r from it along n (the centre's distance, as LAMMPS's walls measure it:
     * R - overlap rounds otherwise), whose curvatures are *k1, *k2 (read for a new
     * contact only) and effective radius reff_c (NaN: from the curvatures,
     * rs_effective_radius), the wall's velocity there vwall and its history h:
     * LAMMPS's model STYLE (< 0: the model's own) adds its force and torque onto F and T
     * and gives 1; 0 where the model acts not, the history cleared. KEEP, NS: keep and ns
     * where known (< 0, 0: not). */
    template <int STYLE, int KEEP = -1, int NS = 0>
    int one(int row, double R, double mass, const double n[3], double r, const double *k1,
            const double *k2, double reff_c, double *vwall, double *h, double F[3],
            double T[3])
    {
        const double rsq = r * r;
        /* what a known model cannot be: JKR is a granular model's, a kept effective radius
         * a curved model's */
        const bool pull = (STYLE < 0 || STYLE == FixWallGran::GRANULAR) && jkr;
        const bool kept = (STYLE < 0 || STYLE == FixWallGran::HERTZ_HISTORY ||
                           STYLE == FixWallGran::GRANULAR) &&
                          (KEEP < 0 ? keep : KEEP != 0);
        const double rad = pull ? R + m.pulloff_distance(R) : R;
        if (rsq > rad * rad || (pull && h[0] == 0.0 && rsq > R * R)) {
            for (int k = 0; k < (NS ? NS : ns); k++)
                h[k] = 0.0;
            return 0;
        }
        /* The wall's radius of curvature as LAMMPS's models take it, rwall (0: a plane),
         * whose effective radius is R rwall / (R + rwall): the effective radius where the
         * contact began, which it keeps (its last state variable; 0 for a new contact).
         * LAMMPS's models take rwall as a constant of a contact: one that changed while
         * the contact lasts, as a sphere slides from a mantle onto a fillet, would make
         * the normal force do net work. */
        double rwall = 0.0;
        if (kept) {
            double &reff = h[(NS ? NS : ns) - 1];
            /* a new contact's is +0.0 (a cleared history), which its bits tell at once */
            std::uint64_t bits;
            std::memcpy(&bits, &reff, sizeof bits);
            if (bits == 0)
                reff = first_reff(R, *k1, *k2, reff_c);
            if (reff != R)
                rwall = R * reff / (R - reff);
        }
        m.contact_as(STYLE < 0 ? m.style() : STYLE, rsq, r * n[0], r * n[1], r * n[2],
                     vwall, rwall, v[row], F, omega[row], T, R, mass, h);
        return 1;
    }

    /* The contacts of run ru through the model STYLE, its force and torque added onto
     * the run's rows: the loop of run_as for whether the contacts keep their effective
     * radius and whether the wall's velocity is a column, constants of the loop. */
    template <int STYLE> void run(const rs_force_run &ru)
    {
        const bool vcol = ru.vwall[0] != nullptr;
        if (keep && STYLE == FixWallGran::HERTZ_HISTORY && ns == 4)
            vcol ? run_as<STYLE, 1, 1, 4>(ru) : run_as<STYLE, 1, 0, 4>(ru);
        else if (keep)
            vcol ? run_as<STYLE, 1, 1>(ru) : run_as<STYLE, 1, 0>(ru);
        else
            vcol ? run_as<STYLE, 0, 1>(ru) : run_as<STYLE, 0, 0>(ru);
    }

    template <int STYLE, int KEEP, int VCOL, int NS = 0> void run_as(const rs_force_run &ru)
    {
        double vw[3] = {ru.vwall0[0], ru.vwall0[1], ru.vwall0[2]};
        double *h = ru.history; /* contact j's: NULL without state variables */
        const double *const n0 = ru.nrm[0], *const n1 = ru.nrm[1], *const n2 = ru.nrm[2];
        const double *const rn = ru.rn, *const radius = ru.radius, *const mass = ru.mass;
        const int *const row = ru.row;
        int *const acts = ru.acts;
        double *F = ru.F, *T = ru.T; /* contact j's */
        const int nc = ru.n;
        for (int j = 0; j < nc; j++, h += (NS ? NS : ns), F += 3, T += 3) {
            const double n[3] = {n0[j], n1[j], n2[j]};
            if (VCOL)
                vw[0] = ru.vwall[0][j], vw[1] = ru.vwall[1][j], vw[2] = ru.vwall[2][j];
            acts[j] =
                one<STYLE, KEEP, NS>(row[j], radius[j], mass[j], n, rn[j], ru.curv[0] + j,
                                     ru.curv[1] + j, NAN, vw, h, F, T);
        }
    }
};

} // namespace

int FixWallRigid::lammps_one(rs_force_contact &c, double F[3], double T[3])
{
    model_->set_history_update(!c.setup);
    ModelCall k(*model_, atom, model_desc_.nstatev, reff_mode_);
    /* the distance of the centre from the wall's point along n, as rs_force_run.rn */
    const double *xi = atom->x[c.row];
    const double r = (xi[0] - c.xm[0]) * c.n[0] + (xi[1] - c.xm[1]) * c.n[1] +
                     (xi[2] - c.xm[2]) * c.n[2];
    return k.one<-1>(c.row, c.radius, c.mass, c.n, r, &c.curv[0], &c.curv[1], c.reff,
                     c.vwall, c.history, F, T);
}

void FixWallRigid::lammps_run(const rs_force_run &r)
{
    model_->set_history_update(!r.setup);
    ModelCall k(*model_, atom, model_desc_.nstatev, reff_mode_);
    switch (model_->style()) {
    case FixWallGran::HOOKE:
        k.run<FixWallGran::HOOKE>(r);
        break;
    case FixWallGran::HOOKE_HISTORY:
        k.run<FixWallGran::HOOKE_HISTORY>(r);
        break;
    case FixWallGran::HERTZ_HISTORY:
        k.run<FixWallGran::HERTZ_HISTORY>(r);
        break;
    default:
        k.run<FixWallGran::GRANULAR>(r);
    }
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
