/* fix wall/rigid, law liggghts: LIGGGHTS's granular contact models on rigidsurf's
 * contacts (liggghts_law.h). The contact's description follows what LIGGGHTS's walls
 * give the model (fix_wall_gran_base.h, Granular::compute_force, LIGGGHTS 3.8), so that
 * a wall/rigid contact and a wall/gran contact of the same geometry get the same force. */
#include "liggghts_law.h"

#include "contact_models.h"
#include "error.h"
#include "force.h"
#include "neighbor.h"
#include "settings.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
namespace LCM = LIGGGHTS::ContactModels;

/* LIGGGHTS's combination chosen at run time: each submodel behind its base class. */
struct LiggghtsLaw::Model {
    LCM::ContactModel<LCM::GranStyle<>> cm;
    Model(LAMMPS *lmp, LIGGGHTS::IContactHistorySetup *h, int64_t hash)
        : cm(lmp, h, true /* a wall */, hash)
    {
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

    Settings settings(lmp);
    model_->cm.registerSettings(settings);
    narg -= 1; // the closing word is not a setting
    const bool ok = settings.parseArguments(narg, args);
    if (!ok)
        lmp->error->all(FLERR, (where + settings.error_message).c_str());
    model_->cm.postSettings(this);
}

LiggghtsLaw::~LiggghtsLaw()
{
    delete model_;
}

int LiggghtsLaw::add_history_value(std::string, std::string)
{
    return nhist_++;
}

void LiggghtsLaw::init()
{
    model_->cm.connectToProperties(lmp_->force->registry);
}

double LiggghtsLaw::close_factor() const
{
    return lmp_->neighbor->contactDistanceFactor;
}

bool LiggghtsLaw::contact(const LiggghtsContact &c, double F[3], double T[3])
{
    F[0] = F[1] = F[2] = T[0] = T[1] = T[2] = 0.0;
    const double gap = -c.overlap;
    const bool touching = gap <= 0.0;
    if (!touching && !(gap < (close_factor() - 1.0) * c.radius)) {
        for (int h = 0; h < nhist_; h++)
            c.history[h] = 0.0;
        return false;
    }
    LCM::SurfacesIntersectData sd;
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
    sd.i = c.i;
    sd.j = -c.jtype; /* a wall without triangles, as LIGGGHTS's primitive walls */
    sd.itype = c.itype;
    sd.jtype = c.jtype;
    sd.contact_flags = NULL;
    sd.contact_history = nhist_ ? c.history : NULL;
    sd.v_i = c.v;
    sd.v_j = const_cast<double *>(c.vwall);
    sd.omega_i = c.omega;
    sd.meff = sd.mi = c.mass;
    sd.radsum = sd.radi;
    sd.computeflag = 1;
    sd.shearupdate = c.update_history ? 1 : 0;

    LCM::ForceData fi, fj;
    if (touching) {
        model_->cm.surfacesIntersect(sd, fi, fj);
        model_->cm.endSurfacesIntersect(sd, NULL, fi, fj);
        sd.has_force_update = true;
    } else {
        sd.has_force_update = false;
        model_->cm.surfacesClose(sd, fi, fj);
    }
    if (!sd.has_force_update)
        return false;
    for (int d = 0; d < 3; d++) {
        F[d] = fi.delta_F[d];
        T[d] = fi.delta_torque[d];
    }
    return true;
}
