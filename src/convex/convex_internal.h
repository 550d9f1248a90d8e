/* Private parts of the convex shapes shared by their files: the core's support (the
 * shape less its rounding), the moments of a solid, and the rounded solids' moments. */
#ifndef RS_CONVEX_INTERNAL_H
#define RS_CONVEX_INTERNAL_H

#include "rigidsurf/convex.h"

/// The core's support along d (body frame, no rounding); d need not be unit, zero is +z.
void rs_shape_core_support(const rs_shape *s, const double d[3], double out[3]);
/// The rounding around the core: the shape's rounding, plus the radius of a sphere or
/// a capsule (whose cores are a point and a segment).
double rs_shape_core_radius(const rs_shape *s);

/// A body's reach about its centre: the farthest corner of its bounding box.
double rs_body_reach(const rs_body *b);
/// The contact of point p, or of the ball of radius r > 0 about it, with surface s whose
/// feature base is want, else p's deepest contact, from a query with gap reach into c;
/// -1 when p has none (*rc: the query's status).
int rs_body_point_contact(const rs_surface *s, const rs_pose *pose, const double p[3],
                          double r, double reach, int want, rs_contacts *c, rs_error *err,
                          int *rc);

/// Does body b hold the world point p, to tol (length): is p within the rounding plus tol
/// of its core (GJK)? 0 for a body rs_convex_pair refuses.
int rs_body_holds(const rs_body *b, const double p[3], double tol);
/// The checks of rs_body_surface_contacts' arguments (RS_ERR_ARG); sets *n = 0.
int rs_body_check(const rs_surface *s, const rs_body *b, double gap_max,
                  const rs_body_contact *out, int cap, int *n, rs_error *err);
/// rs_body_surface_contacts on a MESH (body_mesh.c): the triangles whose tree boxes meet
/// the body's box (its body-frame bounds placed, taken to the mesh's reference
/// configuration and widened by gap_max), each answered by the body's support along its
/// normal where its face owns the body's deepest point, else by rs_convex_triangle and
/// the feature that owns the pair's normal at its witness (rs_mesh_direction_owner); one
/// contact per owning feature and per coplanar region, the deepest.
int rs_body_mesh_contacts(const rs_surface *s, const rs_pose *pose, const rs_body *b,
                          double gap_max, rs_body_contact *out, int cap, int *n,
                          rs_error *err);
/// rs_body_surface_contacts on the analytic kinds; with lenient != 0 a fixed point that
/// does not settle (a wall curved more sharply than the body) gives the deepest of its
/// iterates, with iterations = -1, instead of RS_ERR_GEOMETRY.
int rs_body_features(const rs_surface *s, const rs_pose *pose, const rs_body *b,
                     double gap_max, int lenient, rs_body_contact *out, int cap, int *n,
                     rs_error *err);

/// Volume moments of a solid about the frame's origin: v = int dV, s = int x dV,
/// ss = int x x^T dV (row-major).
typedef struct rs_moments {
    double v;
    double s[3];
    double ss[9];
} rs_moments;

/// The moments of the convex polytope (vertices v, outward triangles t) rounded by
/// r >= 0, exactly: core, face slabs, edge wedges and vertex sectors.
void rs_polytope_moments(const double *v, const int *t, int nt, double r, rs_moments *m);
/// The moments of the rounded polygon prof (n (rho, z) vertices, counter-clockwise,
/// one edge on the axis rho = 0) revolved about body z, rounded by r >= 0.
void rs_revolved_moments(const double *prof, int n, double r, rs_moments *m);
/// The moments of the ellipsoid of semi-axes a, b, c rounded by r >= 0.
void rs_ellipsoid_moments(double a, double b, double c, double r, rs_moments *m);

#endif
