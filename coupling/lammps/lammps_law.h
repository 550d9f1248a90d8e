/* fix wall/rigid in LAMMPS, law lammps: LAMMPS's own wall contact models (the words of a
 * `fix wall/gran` line: hooke, hooke/history, hertz/history, granular with its normal,
 * damping, tangential, rolling and twisting models) evaluated on rigidsurf's contacts.
 *
 * In LAMMPS 29Sep2021 these models are FixWallGran's per-contact member functions (hooke,
 * hooke_history, hertz_history, granular); the model here is a FixWallGran made from the
 * words, whose functions the law calls for each contact, so the force is LAMMPS's own code.
 * rigidsurf gives them what LAMMPS's walls give them: the vector from the wall's contact
 * point to the sphere's centre, the velocities of the sphere and of the wall's material
 * there, the wall's radius of curvature (rwall) and the contact's history; they return the
 * force and the torque on the sphere. */
#ifndef RIGIDSURF_LAMMPS_LAW_H
#define RIGIDSURF_LAMMPS_LAW_H

#include "fix_wall_gran.h"

namespace LAMMPS_NS
{

/// The effective radius law lammps gives LAMMPS's models (word `reff` of the law):
/// REFF_EXACT from the wall's principal curvatures (the default), REFF_REGION as LAMMPS's
/// region walls (2/k of the wall's most curved direction: 2 Rc in a cylinder), REFF_FLAT
/// the sphere's radius, as on LAMMPS's plane walls.
enum { REFF_EXACT = 0, REFF_REGION = 1, REFF_FLAT = 2 };

class LammpsWallModel : public FixWallGran
{
  public:
    /// arg: "ID group wall/gran MODEL WORDS... region NAME", as fix wall/gran takes them
    /// (its messages are LAMMPS's). Its constructor registers the atom callbacks of the
    /// fix being constructed, the wall/rigid that makes it.
    LammpsWallModel(LAMMPS *lmp, int narg, char **arg);

    /// Before the model is deleted: its destructor takes off the atom callbacks of the fix
    /// named fix_id, the wall/rigid that owns it, which it registered.
    void release_callbacks(const char *fix_id);

    /// The model: HOOKE, HOOKE_HISTORY, HERTZ_HISTORY or GRANULAR.
    int style() const
    {
        return pairstyle;
    }
    /// History values per contact.
    int nhistory() const
    {
        return use_history ? size_history : 0;
    }
    /// The model takes the wall's radius of curvature (hertz/history, granular).
    bool curved() const
    {
        return pairstyle == HERTZ_HISTORY || pairstyle == GRANULAR;
    }
    /// The granular model's JKR normal model: it acts within a pull-off distance.
    bool jkr() const
    {
        return pairstyle == GRANULAR && normal_model == JKR;
    }
    /// Whether the call advances the history (not in a setup call).
    void set_history_update(bool on)
    {
        history_update = on ? 1 : 0;
    }
    /// One contact: rsq = r^2, (dx, dy, dz) = r n from the wall's point to the centre,
    /// the wall's velocity there, its radius of curvature rwall (0: flat, < 0 concave),
    /// the sphere's v, omega, R, mass and history; F and T are added to.
    void contact(double rsq, double dx, double dy, double dz, double *vwall, double rwall,
                 double *v, double *F, double *omega, double *T, double radius, double meff,
                 double *history)
    {
        contact_as(pairstyle, rsq, dx, dy, dz, vwall, rwall, v, F, omega, T, radius, meff,
                   history);
    }
    /// The same as the model style (style()), which a caller that knows it gives as a
    /// constant, so that the choice is made once for a run of contacts.
    void contact_as(int style, double rsq, double dx, double dy, double dz, double *vwall,
                    double rwall, double *v, double *F, double *omega, double *T,
                    double radius, double meff, double *history)
    {
        switch (style) {
        case HOOKE:
            hooke(rsq, dx, dy, dz, vwall, v, F, omega, T, radius, meff, nullptr);
            break;
        case HOOKE_HISTORY:
            hooke_history(rsq, dx, dy, dz, vwall, v, F, omega, T, radius, meff, history,
                          nullptr);
            break;
        case HERTZ_HISTORY:
            hertz_history(rsq, dx, dy, dz, vwall, rwall, v, F, omega, T, radius, meff,
                          history, nullptr);
            break;
        default:
            granular(rsq, dx, dy, dz, vwall, rwall, v, F, omega, T, radius, meff, history,
                     nullptr);
        }
    }
};

} // namespace LAMMPS_NS

#endif
