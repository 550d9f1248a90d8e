/* An engine's non-spherical particles as the wall's convex bodies (rs_body,
 * include/rigidsurf/convex.h), free of any engine's header. Each particle of a call is a
 * sphere (its radius and angular velocity as the engine keeps them), an ellipsoid or a
 * rounded polyhedron, both given as an engine with rotational momentum keeps them (LAMMPS's
 * atom_style ellipsoid and atom_style body rounded/polyhedron: the body frame's shape, a
 * quaternion body to world, the mass and the angular momentum in the world frame).
 *
 * An ellipsoid becomes an rs_body whose shape is made once per distinct half-axis triple (a
 * triple first met in a later call is made then) and kept for the adapter's life; its
 * principal moments are those of a uniform solid ellipsoid, m/5 (b^2 + c^2), m/5 (a^2 +
 * c^2), m/5 (a^2 + b^2) about its body axes.
 *
 * A rounded polyhedron (body_polyhedron.cpp) is the convex hull of its vertices (given in
 * its principal axes, as displacements from its centre of mass) rounded by its rounding
 * radius: one shape per distinct body (vertices, faces and rounding), kept in the body
 * frame as given (its origin the engine's centre of mass, not the uniform hull's), made
 * once it is checked to be convex; its principal moments are the engine's.
 *
 * Either body's angular velocity is w = R I^-1 R^T L (a zero moment gives a zero
 * component), and its characteristic length (the radius a law sees) that of the sphere of
 * equal volume, as the standalone driver takes it: (a b c)^(1/3) for an ellipsoid. */
#ifndef RIGIDSURF_COUPLING_BODIES_H
#define RIGIDSURF_COUPLING_BODIES_H

#include "rigidsurf/convex.h"

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

class RsBodies
{
  public:
    RsBodies() = default;
    RsBodies(const RsBodies &) = delete;
    RsBodies &operator=(const RsBodies &) = delete;
    ~RsBodies();

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

    /// Particle i a rounded polyhedron: nv vertices verts (3 nv, in its principal axes, the
    /// displacements from its centre of mass x), nf faces of face_size vertex indices each
    /// (a negative index ends a shorter face), rounding radius rounding >= 0, turned by the
    /// unit quaternion q, of mass m, principal moments I and world-frame angular momentum
    /// L. The body must be convex: every vertex on the boundary of the vertices' hull (one
    /// the hull's making leaves outside it is refused as well), every
    /// face's vertices in one plane with the whole body on one side of it, its centre of
    /// mass inside the hull (RS_ERR_GEOMETRY naming what fails, to 1e-9 of its size);
    /// RS_ERR_ARG for fewer than 4 vertices, a bad index or rounding.
    int polyhedron(int i, const double *verts, int nv, const double *faces, int nf,
                   int face_size, double rounding, const double x[3], const double q[4],
                   double m, const double I[3], const double L[3], rs_error *err);

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
    /// The shapes made so far (one per distinct half-axis triple or polyhedron).
    int nshapes() const
    {
        return (int)(shapes_.size() + polyhedra_.size());
    }

  private:
    struct Polyhedron {
        rs_shape shape;
        double radius; // the sphere of equal volume's
    };
    void spin(int i, const double L[3]);
    static int check_convex(const rs_shape &s, const double *verts, int nv,
                            const double *faces, int nf, int face_size, rs_error *err);

    std::map<std::array<double, 3>, std::unique_ptr<rs_shape>> shapes_;
    std::map<std::vector<double>, std::unique_ptr<Polyhedron>> polyhedra_;
    std::vector<rs_body> body_;
    std::vector<double> radius_, omega_;
};

#endif
