/* fix wall/rigid in LAMMPS: the material properties its laws read (law hertz and law hooke
 * without props, wear finnie). LAMMPS has no fix property/global: as its walls take their
 * coefficients on their own line, these come on the fix line, one value per atom type
 * (docs/lammps.md, "Materials"):
 *
 *   youngsModulus Y1 .. YN, poissonsRatio nu1 .. nuN      per type; the wall's is the value
 *                                                         of its `type`
 *   coefficientRestitution e1 .. eN, coefficientFriction mu1 .. muN, k_finnie k1 .. kN
 *                                                         each type against the wall
 *   characteristicVelocity V                              one value (law hooke)
 *
 * N is the number of atom types (create_box). No engine header here. */
#ifndef RIGIDSURF_LAMMPS_WALL_MATERIALS_H
#define RIGIDSURF_LAMMPS_WALL_MATERIALS_H

#include "rigidsurf/types.h"

#include <map>
#include <string>
#include <vector>

class WallMaterials
{
  public:
    /// Takes the material keywords and their values out of words (the fix's arguments
    /// after the style), keeping the other words in order; ntypes: the atom types. Returns
    /// an error message, or "".
    std::string take(std::vector<std::string> &words, int ntypes);

    /// The wall's host table's answer (rs_wall_host.material): property name of types i
    /// and j, the wall being of type wall_type. A property not given: an error in err
    /// naming the keyword when required, else RS_ERR_NOTFOUND.
    int lookup(const char *name, int i, int j, int wall_type, int required, const char *who,
               double *value, rs_error *err) const;

  private:
    std::map<std::string, std::vector<double>> values_;
    int ntypes_ = 0;
};

#endif
