/* fix wall/rigid, law liggghts: LIGGGHTS's granular contact models on rigidsurf's
 * contacts (liggghts_law.h). The contact's description follows what LIGGGHTS's walls
 * give the model (fix_wall_gran_base.h, Granular::compute_force, LIGGGHTS 3.8), so that
 * a wall/rigid contact and a wall/gran contact of the same geometry get the same force. */
#include "liggghts_law.h"

#include <algorithm>

#include "atom.h"
#include "contact_models.h"
#include "error.h"
#include "force.h"
#include "neighbor.h"
#include "settings.h"

#include <cmath>
#include <cstring>
#include <sstream>

using namespace LAMMPS_NS;
namespace LCM = LIGGGHTS::ContactModels;

namespace
{

/* One submodel, created with its concrete type and deleted as such: LIGGGHTS's model base
 * classes have no virtual destructor. */
template <class Base> struct Owned {
    Base *p = nullptr;
    void (*del)(Base *) = nullptr;
    ~Owned()
    {
        if (p)
            del(p);
    }
};
template <class Derived, class Base> void delete_as(Base *p)
{
    delete static_cast<Derived *>(p);
}

} // namespace

/* LIGGGHTS's five submodels of one contact model, chosen at run time from the ids of
 * its selector, each behind its base class and called in the order of LIGGGHTS's own
 * combination (contact_models.h): surface, normal, cohesion, tangential, rolling (the
 * order in which they register their history, so the offsets are LIGGGHTS's). Each is
 * LIGGGHTS's code from its headers; only the combination is ours, which owns and frees
 * its submodels. */
struct LiggghtsLaw::Model : public LCM::ContactModelBase {
    Owned<LCM::SurfaceModelBase> surface;
    Owned<LCM::NormalModelBase> normal;
    Owned<LCM::CohesionModelBase> cohesion;
    Owned<LCM::TangentialModelBase> tangential;
    Owned<LCM::RollingModelBase> rolling;

    Model(LAMMPS *lmp, LIGGGHTS::IContactHistorySetup *h, int64_t hash)
        : LCM::ContactModelBase(lmp, true /* a wall */)
    {
        const int idNormal = (int)(hash & 63), idTangential = (int)((hash >> 6) & 63),
                  idCohesion = (int)((hash >> 12) & 63),
                  idRolling = (int)((hash >> 18) & 63),
                  idSurface = (int)((hash >> 24) & 63);
        using namespace LCM;
#define RS_MAKE(SLOT, TEMPLATE, BASE, ID)                                                  \
    {                                                                                      \
        SLOT.p = new TEMPLATE<ID>(lmp, h, this);                                           \
        SLOT.del = &delete_as<TEMPLATE<ID>, BASE>;                                         \
    }
        if (false) {
        }
#define SURFACE_MODEL(SCLASS, NAME, ID)                                                    \
    else if (ID == idSurface) RS_MAKE(surface, SurfaceModel, SurfaceModelBase, SCLASS)
#include "style_surface_model.h"
#undef SURFACE_MODEL
        if (idNormal == NORMAL_OFF)
            RS_MAKE(normal, NormalModel, NormalModelBase, NORMAL_OFF)
#define NORMAL_MODEL(NCLASS, NAME, ID)                                                     \
    else if (ID == idNormal) RS_MAKE(normal, NormalModel, NormalModelBase, NCLASS)
#include "style_normal_model.h"
#undef NORMAL_MODEL
        if (idCohesion == COHESION_OFF)
            RS_MAKE(cohesion, CohesionModel, CohesionModelBase, COHESION_OFF)
#define COHESION_MODEL(CCLASS, NAME, ID)                                                   \
    else if (ID == idCohesion) RS_MAKE(cohesion, CohesionModel, CohesionModelBase, CCLASS)
#include "style_cohesion_model.h"
#undef COHESION_MODEL
        if (idTangential == TANGENTIAL_OFF)
            RS_MAKE(tangential, TangentialModel, TangentialModelBase, TANGENTIAL_OFF)
#define TANGENTIAL_MODEL(TCLASS, NAME, ID)                                                 \
    else if (ID == idTangential)                                                           \
        RS_MAKE(tangential, TangentialModel, TangentialModelBase, TCLASS)
#include "style_tangential_model.h"
#undef TANGENTIAL_MODEL
        if (idRolling == ROLLING_OFF)
            RS_MAKE(rolling, RollingModel, RollingModelBase, ROLLING_OFF)
#define ROLLING_MODEL(RCLASS, NAME, ID)                                                    \
    else if (ID == idRolling) RS_MAKE(rolling, RollingModel, RollingModelBase, RCLASS)
#include "style_rolling_model.h"
#undef ROLLING_MODEL
#undef RS_MAKE
    }
    bool complete() const
    {
        return surface.p && normal.p && cohesion.p && tangential.p && rolling.p;
    }
    void tally_pp(double val, int i, int j, int index)
    {
        surface.p->tally_pp(val, i, j, index);
    }
    void tally_pw(double val, int i, int j, int index)
    {
        surface.p->tally_pw(val, i, j, index);
    }
    void registerSettings(Settings &settings)
    {
        surface.p->registerSettings(settings);
        normal.p->registerSettings(settings);
        cohesion.p->registerSettings(settings);
        tangential.p->registerSettings(settings);
        rolling.p->registerSettings(settings);
    }
    void postSettings(LIGGGHTS::IContactHistorySetup *h)
    {
        surface.p->postSettings(h, this);
        normal.p->postSettings(h, this);
        cohesion.p->postSettings(h, this);
        tangential.p->postSettings(h, this);
        rolling.p->postSettings(h, this);
    }
    void connectToProperties(PropertyRegistry &registry)
    {
        surface.p->connectToProperties(registry);
        normal.p->connectToProperties(registry);
        cohesion.p->connectToProperties(registry);
        tangential.p->connectToProperties(registry);
        rolling.p->connectToProperties(registry);
    }
    void surfacesIntersect(LCM::SurfacesIntersectData &sd, LCM::ForceData &fi,
                           LCM::ForceData &fj)
    {
        surface.p->surfacesIntersect(sd, fi, fj);
        normal.p->surfacesIntersect(sd, fi, fj);
        cohesion.p->surfacesIntersect(sd, fi, fj);
        tangential.p->surfacesIntersect(sd, fi, fj);
        rolling.p->surfacesIntersect(sd, fi, fj);
    }
    void endSurfacesIntersect(LCM::SurfacesIntersectData &sd, LCM::ForceData &fi,
                              LCM::ForceData &fj)
    {
        surface.p->endSurfacesIntersect(sd, NULL, fi.delta_F);
        cohesion.p->endSurfacesIntersect(sd, fi, fj);
    }
    void surfacesClose(LCM::SurfacesCloseData &sd, LCM::ForceData &fi, LCM::ForceData &fj)
    {
        surface.p->surfacesClose(sd, fi, fj);
        normal.p->surfacesClose(sd, fi, fj);
        cohesion.p->surfacesClose(sd, fi, fj);
        tangential.p->surfacesClose(sd, fi, fj);
        rolling.p->surfacesClose(sd, fi, fj);
    }
};

namespace
{

/* Settings whose LIGGGHTS implementation reads the mesh of a `fix mesh/surface` (its
 * global velocity) for the wall's share of the energy: wall/rigid has no such mesh. */
const char *const kMeshOnlySettings[] = {"computeElasticPotential",
                                         "computeDissipatedEnergy"};

} // namespace

LiggghtsLaw::LiggghtsLaw(LAMMPS *lmp, const std::string &fix_id,
                         const std::vector<std::string> &words)
    : lmp_(lmp), model_(NULL), nhist_(0)
{
    for (size_t k = 0; k < words.size(); k++)
        desc_ += (k ? " " : "") + words[k];
    const std::string where = "Fix wall/rigid " + fix_id + ": law liggghts: ";
    for (size_t k = 0; k + 1 < words.size(); k++)
        for (const char *s : kMeshOnlySettings)
            if (words[k] == s && words[k + 1] == "on")
                lmp->error->all(FLERR, (where + "'" + s +
                                        " on' needs a LIGGGHTS mesh wall (fix "
                                        "mesh/surface); it is not available on wall/rigid")
                                           .c_str());

    /* LIGGGHTS's selector consumes 'model X [tangential Y] [cohesion Z]
     * [rolling_friction W] [surface S]' and leaves the settings. It steps past a pair
     * only when more words follow, so the list ends with a word of no meaning. */
    std::vector<std::vector<char>> store(words.size() + 1);
    std::vector<char *> argv;
    for (size_t k = 0; k <= words.size(); k++) {
        const std::string w = k < words.size() ? words[k] : std::string("end");
        store[k].assign(w.begin(), w.end());
        store[k].push_back('\0');
        argv.push_back(store[k].data());
    }
    /* A surface model other than the default reads what only LIGGGHTS's own walls keep:
     * multicontact the expanded radii of fix multicontact/halfspace, superquadric the
     * particles' shapes. */
    for (size_t k = 0; k + 1 < words.size(); k++)
        if (words[k] == "surface" && words[k + 1] != "default")
            lmp->error->all(FLERR, (where + "'surface " + words[k + 1] +
                                    "' needs LIGGGHTS's own walls (fix wall/gran); law "
                                    "liggghts takes the default surface model")
                                       .c_str());
    if (words.empty() || words[0] != "model")
        lmp->error->all(FLERR, (where + "expects LIGGGHTS's model words, 'model NORMAL "
                                        "[tangential T] [cohesion C] [rolling_friction R] "
                                        "[surface S]' and their settings")
                                   .c_str());
    int narg = (int)words.size() + 1;
    char **args = argv.data();
    const int64_t hash =
        LCM::Factory::select(narg, args, lmp->force->custom_contact_models);
    if (hash < 0)
        lmp->error->all(FLERR, (where + "'" + desc_ +
                                "': a model name LIGGGHTS does not know (liggghts -h lists "
                                "them)")
                                   .c_str());
    model_ = new Model(lmp, this, hash);
    if (!model_->complete())
        lmp->error->all(
            FLERR,
            (where + "'" + desc_ + "': a model this LIGGGHTS build does not hold").c_str());

    Settings settings(lmp);
    model_->registerSettings(settings);
    narg -= 1; // the closing word is not a setting
    const bool ok = settings.parseArguments(narg, args);
    if (!ok)
        lmp->error->all(FLERR, (where + settings.error_message).c_str());
    model_->postSettings(this);
}

LiggghtsLaw::~LiggghtsLaw()
{
    delete model_;
}

int LiggghtsLaw::add_history_value(std::string name, std::string)
{
    hist_names_.push_back(name);
    return nhist_++;
}

void LiggghtsLaw::init()
{
    model_->connectToProperties(lmp_->force->registry);
}

double LiggghtsLaw::close_factor() const
{
    return lmp_->neighbor->contactDistanceFactor;
}

void LiggghtsLaw::wall_rows()
{
    Atom *atom = lmp_->atom;
    if (atom->v == vsrc_ && atom->omega == wsrc_ && atom->nmax == rows_nmax_)
        return;
    vsrc_ = atom->v;
    wsrc_ = atom->omega;
    rows_nmax_ = atom->nmax;
    vrows_.assign(vsrc_, vsrc_ + rows_nmax_);
    wrows_.assign(wsrc_, wsrc_ + rows_nmax_);
    vrows_.push_back(NULL);
    wrows_.push_back(wall_spin_);
}

LiggghtsLaw::Result LiggghtsLaw::contact(const LiggghtsContact &c, double F[3], double T[3])
{
    F[0] = F[1] = F[2] = T[0] = T[1] = T[2] = 0.0;
    const double gap = -c.overlap;
    const bool touching = gap <= 0.0;
    if (!touching && !(gap < (close_factor() - 1.0) * c.radius)) {
        for (int h = 0; h < nhist_; h++)
            c.history[h] = 0.0;
        return kNone;
    }
    LCM::SurfacesIntersectData sd;
    /* What a model reads that another sets, zero until set: a rolling model reads kn,
     * which thornton_ning leaves unset (LIGGGHTS's constructor leaves these values
     * undefined). */
    sd.kt = sd.kn = sd.gammat = sd.gamman = sd.vn = 0.0;
    sd.cri = sd.crj = sd.wr1 = sd.wr2 = sd.wr3 = sd.vtr1 = sd.vtr2 = sd.vtr3 = 0.0;
    sd.mj = sd.P_diss = 0.0;
    sd.omega_j = NULL;
    sd.is_wall = true;
    sd.radi = c.radius;
    sd.deltan = c.overlap;
    sd.r = sd.radi - sd.deltan;
    sd.rsq = sd.r * sd.r;
    sd.rinv = 1.0 / sd.r;
    for (int d = 0; d < 3; d++) {
        sd.delta[d] = sd.r * c.normal[d];
        sd.en[d] = c.normal[d];
    }
    sd.area_ratio = 1.0;
    /* The wall is j, a row past the atoms that holds its velocity and no spin: the close
     * branches of the capillary bridges (easo, washino) read the wall's velocity as
     * atom->v[j] and atom->omega[j]. (LIGGGHTS's primitive walls pass j = -type, which
     * reads before those arrays; its mesh walls pass the triangle's index, which reads
     * the velocity of the atom of that number.) */
    wall_rows();
    vrows_[rows_nmax_] = const_cast<double *>(c.vwall);
    sd.i = c.i;
    sd.j = rows_nmax_;
    sd.itype = c.itype;
    sd.jtype = c.jtype;
    sd.contact_flags = NULL;
    /* The model works on a copy of the history that one value 0 precedes: LIGGGHTS's
     * rolling model luding reads its cohesion model's kc and fo at offset -1 of the
     * history when that model keeps neither (get_history_offset's answer for a name it
     * lacks), which would read whatever lies before the history in memory. */
    hist_work_.assign(1, 0.0);
    hist_work_.insert(hist_work_.end(), c.history, c.history + nhist_);
    sd.contact_history = nhist_ ? hist_work_.data() + 1 : NULL;
    sd.v_i = c.v;
    sd.v_j = const_cast<double *>(c.vwall);
    sd.omega_i = c.omega;
    sd.meff = sd.mi = c.mass;
    sd.radsum = sd.radi;
    sd.computeflag = 1;
    sd.shearupdate = c.update_history ? 1 : 0;

    LCM::ForceData fi, fj;
    Atom *atom = lmp_->atom;
    atom->v = vrows_.data();
    atom->omega = wrows_.data();
    if (touching) {
        model_->surfacesIntersect(sd, fi, fj);
        model_->endSurfacesIntersect(sd, fi, fj);
        sd.has_force_update = true;
    } else {
        sd.has_force_update = false;
        model_->surfacesClose(sd, fi, fj);
    }
    atom->v = vsrc_;
    atom->omega = wsrc_;
    /* c.history holds the history the call started from until the model's is finite */
    bool finite = true;
    for (int h = 1; h <= nhist_; h++)
        finite = finite && std::isfinite(hist_work_[h]);
    for (int d = 0; d < 3; d++)
        finite =
            finite && std::isfinite(fi.delta_F[d]) && std::isfinite(fi.delta_torque[d]);
    if (!finite) {
        nonfinite(c, c.history, fi.delta_F, fi.delta_torque);
        return kNotFinite;
    }
    std::copy(hist_work_.begin() + 1, hist_work_.end(), c.history);
    if (!sd.has_force_update)
        return kNone;
    for (int d = 0; d < 3; d++) {
        F[d] = fi.delta_F[d];
        T[d] = fi.delta_torque[d];
    }
    return kForce;
}

/* LIGGGHTS's models have no answer outside the states they were written for, and return
 * NaN there (stock LIGGGHTS then loses the particle and ends with a segmentation fault).
 * The message gives what the model started from. thornton_ning (Thornton and Ning's JKR
 * model) takes the square root of F + fc, with F its last normal force and fc = 3/2 pi
 * gamma R the pull-off force, which it keeps in its history as 'fo': a contact whose
 * force fell below -fc within one step (the whole adhesive branch unloaded at once)
 * cannot go on. */
void LiggghtsLaw::nonfinite(const LiggghtsContact &c, const double *h0, const double F[3],
                            const double T[3])
{
    std::ostringstream o;
    o.precision(6);
    o << "law liggghts " << desc_ << ": LIGGGHTS's model gives particle "
      << lmp_->atom->tag[c.i] << " (overlap " << c.overlap << ") a force (" << F[0] << ", "
      << F[1] << ", " << F[2] << ") and torque (" << T[0] << ", " << T[1] << ", " << T[2]
      << ") that are not finite, from the contact's history";
    int fold = -1, fo = -1;
    for (int h = 0; h < nhist_; h++) {
        o << (h ? ", " : " ") << hist_names_[h] << " = " << h0[h];
        if (hist_names_[h] == "force_old")
            fold = h;
        else if (hist_names_[h] == "fo")
            fo = h;
    }
    if (fold >= 0 && fo >= 0 && h0[fold] < -std::fabs(h0[fo]))
        o << ". Its last normal force " << h0[fold]
          << " lies below the pull-off force -fc = " << -std::fabs(h0[fo])
          << " (fc = 3/2 pi surfaceEnergy R), where thornton_ning's JKR branch ends: the "
             "contact unloaded past its whole adhesive branch within one time step. A time "
             "step small enough that the force changes by a fraction of fc per step "
             "follows the branch";
    failure_ = o.str();
}
