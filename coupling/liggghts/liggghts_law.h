/* fix wall/rigid, law liggghts: LIGGGHTS's own granular contact models (the words of a
 * `fix wall/gran` line: model, tangential, cohesion, rolling_friction, surface and their
 * settings) evaluated on rigidsurf's contacts.
 *
 * The model is LIGGGHTS's submodels (from its headers), chosen at run time and combined
 * as LIGGGHTS's run-time combination does: any normal x tangential x cohesion x rolling
 * model that LIGGGHTS 3.8 accepts for walls, with the settings and material properties
 * it reads.
 * rigidsurf gives it the geometry LIGGGHTS's walls give it: the sphere's radius, the
 * overlap, the vector from the master point to the centre, the velocities of the sphere
 * and of the wall's material at the master point, and the contact's history (the
 * model's own values, in the contact's slot as state variables). The model returns the
 * force and torque on the particle. */
#ifndef RIGIDSURF_LIGGGHTS_LAW_H
#define RIGIDSURF_LIGGGHTS_LAW_H

#include "contact_interface.h"
#include "lammps.h"

#include <string>
#include <vector>

namespace LAMMPS_NS
{

/// One contact of a sphere with the wall, as LIGGGHTS's walls describe it.
struct LiggghtsContact {
    int i;                ///< local atom index
    double radius;        ///< sphere radius
    double overlap;       ///< penetration (> 0 touching; < 0 apart)
    const double *normal; ///< unit normal from the wall toward the centre
    double *v;            ///< the sphere's velocity
    double *omega;        ///< the sphere's angular velocity
    double vwall[3];      ///< the wall material's velocity at the master point
    double *history;      ///< the model's history values (LiggghtsLaw::nhistory())
    int itype, jtype;     ///< particle type, wall type
    double mass;          ///< the sphere's mass
    bool update_history;  ///< false in a setup call (LIGGGHTS's shearupdate)
};

class LiggghtsLaw final : public LIGGGHTS::IContactHistorySetup
{
  public:
    /// words: the model words and settings, e.g. {"model", "hertz", "tangential",
    /// "history", "rolling_friction", "epsd2"}. Errors go through lmp->error (the
    /// message names the fix by fix_id).
    LiggghtsLaw(LAMMPS *lmp, const std::string &fix_id,
                const std::vector<std::string> &words);
    virtual ~LiggghtsLaw();

    /// Connects the model to the material properties (fix property/global), as
    /// `fix wall/gran` does in its init. Called from the fix's init().
    void init();

    /// History values per contact.
    int nhistory() const
    {
        return nhist_;
    }
    /// LIGGGHTS's contact distance factor: contacts apart by less than (factor - 1) R
    /// still call the model (cohesion through liquid bridges).
    double close_factor() const;
    /// The words as given, for messages ("model hertz tangential history ...").
    const std::string &description() const
    {
        return desc_;
    }

    /// What contact() found.
    enum Result {
        kNone,     ///< the model applies nothing; F and T are zero
        kForce,    ///< F and T are the model's
        kNotFinite ///< the model returned a value that is not finite: failure() says why
    };
    /// Evaluates one contact: the force and torque on the particle. kNone when the model
    /// applies nothing (apart beyond the contact distance, or a close contact whose model
    /// asked no force). A contact apart beyond the contact distance has its history
    /// cleared, as LIGGGHTS's walls clear it. A force, torque or history value that is
    /// not finite gives kNotFinite, and failure() names the particle, the overlap and the
    /// history the model started from.
    Result contact(const LiggghtsContact &c, double F[3], double T[3]);
    /// The message of the last kNotFinite.
    const std::string &failure() const
    {
        return failure_;
    }

    int add_history_value(std::string name, std::string newtonflag) override;

  private:
    /// atom->v and atom->omega with one row more, at atom->nmax, for the wall (see
    /// contact()); rebuilt when the atom arrays move or grow.
    void wall_rows();
    /// failure_ for a contact whose model returned a value that is not finite; h0: the
    /// history the call started from.
    void nonfinite(const LiggghtsContact &c, const double *h0, const double F[3],
                   const double T[3]);

    LAMMPS *lmp_;
    std::string desc_, failure_;
    std::vector<std::string> hist_names_; ///< the model's history values, by offset
    std::vector<double> hist_work_;       ///< 0, then the history the model works on
    struct Model;
    Model *model_;
    int nhist_;
    std::vector<double *> vrows_, wrows_;
    double **vsrc_ = nullptr, **wsrc_ = nullptr;
    int rows_nmax_ = -1;
    double wall_spin_[3] = {0.0, 0.0, 0.0};
};

} // namespace LAMMPS_NS

#endif
