/* An engine's ellipsoids as the wall's convex bodies (rs_body, include/rigidsurf/convex.h),
 * free of any engine's header: each particle of a call is a sphere (its radius and angular
 * velocity as the engine keeps them) or an ellipsoid given as an engine with rotational
 * momentum keeps it (LAMMPS's atom_style ellipsoid: half-axes, a quaternion, the mass and
 * the angular momentum in the world frame). An ellipsoid becomes an rs_body whose shape is
 * made once per distinct half-axis triple (a triple first met in a later call is made
 * then) and kept for the adapter's life; its principal moments are those of a uniform solid
 * ellipsoid, m/5 (b^2 + c^2), m/5 (a^2 + c^2), m/5 (a^2 + b^2) about its body axes, its
 * angular velocity w = R I^-1 R^T L (a zero moment gives a zero component), and its
 * characteristic length (the radius a law sees) that of the sphere of equal volume,
 * (a b c)^(1/3), as the standalone driver takes it. */
#ifndef RIGIDSURF_COUPLING_ELLIPSOIDS_H
#define RIGIDSURF_COUPLING_ELLIPSOIDS_H

#include "rigidsurf/convex.h"

#include <array>
#include <map>
#include <memory>
#include <vector>

class RsEllipsoids
{
  public:
    RsEllipsoids() = default;
    RsEllipsoids(const RsEllipsoids &) = delete;
    RsEllipsoids &operator=(const RsEllipsoids &) = delete;
    ~RsEllipsoids();

    /// Arrays for particles 0 .. n-1 of a call, each a point (no shape, radius and angular
    /// velocity zero) until it is set.
    void resize(int n);
    /// Particle i a sphere of radius r and angular velocity w (3; NULL: zero).
    void sphere(int i, double r, const double *w);
    /// Particle i an ellipsoid of half-axes half (along its body x, y, z; finite, > 0)
    /// centred at x, turned by the unit quaternion q (w, x, y, z; body to world), of mass
    /// m and world-frame angular momentum L. RS_ERR_ARG (a bad half-axis) or RS_ERR_NOMEM
    /// from the shape's making.
    int ellipsoid(int i, const double half[3], const double x[3], const double q[4],
                  double m, const double L[3], rs_error *err);

    const rs_body *bodies() const
    {
        return body_.data();
    }
    const double *radius() const
    {
        return radius_.data();
    }
    const double *omega() const
    {
        return omega_.data();
    }
    /// The shapes made so far (one per distinct half-axis triple).
    int nshapes() const
    {
        return (int)shapes_.size();
    }

  private:
    std::map<std::array<double, 3>, std::unique_ptr<rs_shape>> shapes_;
    std::vector<rs_body> body_;
    std::vector<double> radius_, omega_;
};

#endif
