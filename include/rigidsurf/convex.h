/* rigidsurf: convex slaves. A convex slave is a rigid body whose shape is given in its
 * body frame by a support function: a built-in shape (sphere, ellipsoid, box, cylinder,
 * capsule, cone, the convex hull of a point set) or the user's own, each optionally
 * rounded by a radius (a Minkowski sum with a sphere). Pairs of convex shapes, and a
 * convex shape against a triangle, are answered through libccd (docs/conventions.md,
 * "Convex bodies").
 *
 * Frames. A shape is described in its body frame. Every built-in shape has its centre
 * of mass (uniform density, rounding included) at the body frame's origin; the
 * symmetric ones have their axes along the body axes (a cylinder, capsule or cone along
 * body z). A body's pose maps the body frame to the world: x_world = x + R(q) x_body. */
#ifndef RIGIDSURF_CONVEX_H
#define RIGIDSURF_CONVEX_H

#include "rigidsurf/motion.h"
#include "rigidsurf/surface.h"
#include "rigidsurf/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/// The kinds of shape.
typedef enum rs_shape_kind {
    RS_SHAPE_SPHERE = 0,     ///< dim[0] = radius (a point rounded by the radius)
    RS_SHAPE_ELLIPSOID = 1,  ///< dim = semi-axes a, b, c along body x, y, z
    RS_SHAPE_BOX = 2,        ///< dim = half-extents along body x, y, z
    RS_SHAPE_CYLINDER = 3,   ///< dim[0] = radius, dim[1] = half-height along body z
    RS_SHAPE_CAPSULE = 4,    ///< dim[0] = radius, dim[1] = half-length of the axis segment
    RS_SHAPE_CONE = 5,       ///< dim[0] = base radius, dim[1] = height; apex towards +z
    RS_SHAPE_POLYHEDRON = 6, ///< the convex hull of a point set
    RS_SHAPE_USER = 7        ///< the user's support function
} rs_shape_kind;

/// Directions along which a polyhedron keeps its extreme vertex (rs_shape.hint).
/// A polyhedron's start vertices for its support's climb: one per cell of a cube's faces,
/// RS_HULL_CELLS x RS_HULL_CELLS cells a face.
#define RS_HULL_CELLS 8
#define RS_HULL_HINTS (6 * RS_HULL_CELLS * RS_HULL_CELLS)

/// A support function: writes to out the point of the shape farthest along dir (any
/// length, not zero), both in the shape's body frame. The shape is convex and bounded.
typedef void (*rs_support_fn)(const void *obj, const double dir[3], double out[3]);

/// A convex shape in its body frame (a tagged struct; make it with rs_shape_make_*).
typedef struct rs_shape {
    rs_shape_kind kind;
    double dim[3];   ///< the kind's dimensions (length), as rs_shape_kind lists them
    double rounding; ///< rounding radius r >= 0 (length): the shape is core + ball(r)
    double shift[3]; ///< the body frame's origin in the frame the shape was described
                     ///< in (length): body point = described point - shift. Zero but
                     ///< for a rounded cone and a polyhedron
    int nv;          ///< polyhedron: number of hull vertices
    int nt;          ///< polyhedron: number of hull triangles
    double *verts;   ///< polyhedron: hull vertices (3 * nv), body frame
    int *tris;       ///< polyhedron: triangles (3 * nt), counter-clockwise from outside
    int *adj0;       ///< polyhedron: vertex v's neighbours on the hull are
    int *adj;        ///< adj[adj0[v] .. adj0[v + 1]) (adj0: nv + 1 entries)
    int hint[RS_HULL_HINTS]; ///< polyhedron: its extreme vertex along the centre of each
                             ///< cell of a cube's faces (where a support's climb starts)
    double box[6];           ///< its body-frame bounds, lo then hi (rs_shape_bounds; set by
                             ///< the make call)
    double reach;          ///< the farthest corner of those bounds from the origin (length)
    const void *obj;       ///< user: the object passed to support
    rs_support_fn support; ///< user: the support function of the core (without rounding)
} rs_shape;

/// A sphere of the given radius: a point rounded by radius + rounding. RS_ERR_ARG for a
/// radius that is not finite and > 0 or a rounding that is not finite and >= 0.
int rs_shape_make_sphere(rs_shape *s, double radius, double rounding, rs_error *err);
/// An ellipsoid of semi-axes a, b, c (along body x, y, z), rounded by rounding.
/// RS_ERR_ARG for non-finite or non-positive semi-axes, or a negative rounding.
int rs_shape_make_ellipsoid(rs_shape *s, double a, double b, double c, double rounding,
                            rs_error *err);
/// A box of half-extents hx, hy, hz, rounded by rounding (edges and corners become
/// quarter-cylinders and sphere octants). Errors as rs_shape_make_ellipsoid.
int rs_shape_make_box(rs_shape *s, double hx, double hy, double hz, double rounding,
                      rs_error *err);
/// A circular cylinder of the given radius, its axis along body z from -half_height to
/// +half_height, rounded by rounding (a tablet). Errors as rs_shape_make_ellipsoid.
int rs_shape_make_cylinder(rs_shape *s, double radius, double half_height, double rounding,
                           rs_error *err);
/// A capsule: the segment from (0, 0, -half_length) to (0, 0, +half_length) rounded by
/// radius + rounding. Errors as rs_shape_make_ellipsoid.
int rs_shape_make_capsule(rs_shape *s, double radius, double half_length, double rounding,
                          rs_error *err);
/// A right circular cone of base radius and height along body z, apex towards +z,
/// rounded by rounding. Described with its core's centroid at the origin (base at
/// z = -height/4, apex at z = 3 height/4); the body origin is the rounded solid's
/// centre of mass, shift = (0, 0, its z in that description). Errors as
/// rs_shape_make_ellipsoid.
int rs_shape_make_cone(rs_shape *s, double radius, double height, double rounding,
                       rs_error *err);
/// The convex hull of n points xyz (3 * n), built once with CGAL, rounded by rounding.
/// The body frame is the points' frame moved to the rounded hull's centre of mass
/// (axes kept): a body point is an input point less shift. The hull is canonical: its
/// vertices the extreme points sorted by x, y, z, each facet a fan from its least vertex,
/// the triangles sorted; the same points in any order give the same shape bit for bit.
/// RS_ERR_GEOMETRY for fewer than four points that are not coplanar or a hull whose
/// volume is lost to rounding; RS_ERR_ARG for a non-finite coordinate or a bad rounding;
/// RS_ERR_NOMEM. Free with rs_shape_free. Every rs_shape_make_* call first empties s,
/// so one that fails leaves no shape (rs_shape_mass_props and rs_body_init refuse it).
int rs_shape_make_polyhedron(rs_shape *s, const double *xyz, int n, double rounding,
                             rs_error *err);
/// The user's convex shape: support (not NULL) gives its core in the body frame,
/// obj is passed to it and must outlive the shape, rounding is added around it. It has
/// no mass properties of its own (rs_shape_mass_props refuses it).
int rs_shape_make_user(rs_shape *s, const void *obj, rs_support_fn support, double rounding,
                       rs_error *err);
/// Frees a polyhedron's arrays (nothing for the other kinds); s may be NULL.
void rs_shape_free(rs_shape *s);

/// The support point of the shape along dir (body frame, any non-zero length), rounding
/// included: s(d) = s_core(d) + r d / |d|. A zero dir is taken as +z.
void rs_shape_support(const rs_shape *s, const double dir[3], double out[3]);
/// The shape's axis-aligned bounding box in the body frame (exact: the supports along
/// the six axis directions).
void rs_shape_bounds(const rs_shape *s, double lo[3], double hi[3]);

/// Mass properties of a uniform solid.
typedef struct rs_mass_props {
    double volume;     ///< length^3
    double mass;       ///< density * volume
    double com[3];     ///< centre of mass, body frame (zero for the built-in shapes)
    double inertia[9]; ///< inertia tensor about com in body axes, row-major (mass length^2)
    double principal[3]; ///< principal moments, the eigenvalues of inertia
    double axes[9];      ///< row-major rotation whose column k is the axis of principal[k]
                         ///< in the body frame; the identity when inertia is diagonal
} rs_mass_props;

/// Mass properties of the shape at the given density (mass / length^3, finite > 0), in
/// closed form: sphere, ellipsoid, box, cylinder, capsule and cone by the textbook
/// formulas; a polyhedron by the divergence theorem over its hull's triangles; a rounded
/// box or polyhedron exactly, as the core plus a slab on each face, a cylindrical wedge
/// on each edge and a spherical sector at each vertex; a rounded cylinder or cone
/// as a solid of revolution of the rounded profile (polygon and edge strips by a Gauss
/// rule exact for them, corner sectors with 24 Gauss points in their angle); a rounded
/// ellipsoid as the ellipsoid plus its offset shell, dV = (1 + k1 t)(1 + k2 t) dA dt over
/// the surface (curvatures k1, k2) and t in [0, r], integrated with 48 Gauss-Legendre
/// points in the polar angle, 96 equal steps in azimuth and 3 Gauss points in t (exact in
/// t; 1e-13 for equal semi-axes, Monte Carlo-checked otherwise). RS_ERR_ARG for a bad
/// density or a user shape.
int rs_shape_mass_props(const rs_shape *s, double density, rs_mass_props *mp,
                        rs_error *err);

/// A rigid body: pose, mass and shape.
typedef struct rs_body {
    double x[3];           ///< centre of mass (the body frame's origin), world (length)
    double q[4];           ///< orientation, unit quaternion in the order (w, x, y, z):
                           ///< x_world = x + R(q) x_body
    double mass;           ///< mass
    double inertia[3];     ///< principal moments of inertia (mass length^2)
    double axes[9];        ///< principal axes in the body frame (columns, row-major); the
                           ///< identity for every built-in shape but a polyhedron
    const rs_shape *shape; ///< body-frame shape, not owned
} rs_body;

/// Sets a body: its shape, pose and, for density > 0, mass and inertia from
/// rs_shape_mass_props (density 0 leaves them zero for the caller to set, as a user
/// shape needs). q must be unit to 1e-12 (|q| - 1); it is not normalised here.
/// RS_ERR_ARG for a non-finite x or q, a q that is not unit, or a bad density.
int rs_body_init(rs_body *b, const rs_shape *shape, double density, const double x[3],
                 const double q[4], rs_error *err);
/// The rotation matrix R(q) (row-major) of the body's quaternion.
void rs_body_rotation(const rs_body *b, double R[9]);
/// The support point of the body along the world direction dir, in the world.
void rs_body_support(const rs_body *b, const double dir[3], double out[3]);

/// What a pair query found.
typedef enum rs_convex_state {
    RS_CONVEX_APART = 0,  ///< farther apart than gap_max: only depth < -gap_max is known
    RS_CONVEX_NEAR = 1,   ///< a gap in [0, gap_max]: depth = -gap
    RS_CONVEX_OVERLAP = 2 ///< the shapes overlap: depth > 0
} rs_convex_state;

/// The contact of two convex shapes a and b (world frame).
typedef struct rs_convex_contact {
    int state;        ///< rs_convex_state
    double depth;     ///< penetration (length): > 0 overlap, < 0 gap, as rdisp(1)
    double normal[3]; ///< unit normal from a towards b: moving b by depth along it
                      ///< makes them touch
    double pa[3];     ///< witness point on a's surface
    double pb[3];     ///< witness point on b's surface: pb - pa = -depth normal
} rs_convex_contact;

/// The largest magnitude of a coordinate the pair queries take (length), as the
/// numbers of a surface file or a fix line.
#define RS_CONVEX_COORD_MAX 1e100
/// The smallest length of a shape (its dimensions; as a surface's RS_LENGTH_MIN).
#define RS_CONVEX_LENGTH_MIN 1e-100

/// The contact of bodies a and b (each body's origin inside its shape). Their cores (the
/// shapes less their rounding) are apart: the gap is their distance (GJK) less the
/// roundings, exact for rounded points and segments. Their cores overlap: libccd's MPR
/// depth and normal (of the cores plus the roundings, or of the rounded shapes when a
/// core has no volume), corrected by GJK with b moved apart along the normal: exact on
/// flat contacts. gap_max >= 0 (length) bounds the gaps that are resolved. RS_ERR_ARG for
/// a NULL or non-finite argument, a position beyond RS_CONVEX_COORD_MAX or a quaternion
/// that is not unit.
int rs_convex_pair(const rs_body *a, const rs_body *b, double gap_max,
                   rs_convex_contact *out, rs_error *err);
/// The contact of body a and the triangle tri (three world points, 9 values) as a thin
/// convex shape: b is the triangle, so normal points from a towards the triangle.
int rs_convex_triangle(const rs_body *a, const double tri[9], double gap_max,
                       rs_convex_contact *out, rs_error *err);

/// One contact of a convex body with a surface.
typedef struct rs_body_contact {
    int feature;      ///< the master feature that owns it (RS_FEATURE)
    double depth;     ///< penetration (length): > 0 overlap, < 0 gap, as rdisp(1)
    double normal[3]; ///< the master's unit normal at xm, toward the body
    double xm[3];     ///< the master's witness point: the closest point to xs
    double xs[3];     ///< the body's witness point: its deepest point along -normal
    double t1[3];     ///< the master's first tangent at xm, by the kind's convention
    double t2[3];     ///< the second tangent, normal x t1
    double curv[2];   ///< the master's principal curvatures at xm (rs_contacts.curv)
    int iterations;   ///< the fixed point's iterations
} rs_body_contact;

/// A body's contacts as a kind's body operation appends them (rs_surface_ops.body): the
/// array grows as needed. Zero-initialise it, or give it an array of the caller's (c, cap,
/// borrowed = 1: used until it is full, then copied to the heap); free with
/// rs_body_contacts_free.
typedef struct rs_body_contacts {
    int n, cap;
    rs_body_contact *c;
    int borrowed; ///< c is the caller's (not freed)
} rs_body_contacts;

/// Frees the array and zeroes l.
void rs_body_contacts_free(rs_body_contacts *l);

/// The contacts of body b with surface s in the pose pose (NULL: its reference pose), one
/// per owning feature, with a gap at most gap_max.
/// - An analytic surface (SEGMENTS, CYLINDER, REVOLUTION): for each feature near the body
///   (a sphere query of the body's reach about its centre) the normal n is iterated to a
///   fixed point: xs = the body's support along -n, n = the normal of the feature's
///   closest point to xs, until n turns by at most 1e-13; then depth = -(xs - xm).n. A
///   fixed point not reached in 100 iterations (a wall curved more sharply than the body
///   where they meet) is RS_ERR_GEOMETRY naming the feature, never a contact.
/// - A MESH: the triangles whose tree boxes meet the body's bounding box (widened by
///   gap_max), each within gap_max of the body by rs_convex_triangle. Each coplanar region
///   (triangles joined by flat edges) answers by the body's support along its normal
///   where the foot of it lies on the region (and so does the foot of the body's centre,
///   or the pair's normal on one of its triangles is within 60 degrees of the region's):
///   the depth in closed form, the feature the face under the foot; else each triangle by
///   its pair's witness, owned by the face, edge or vertex whose Voronoi cone holds the
///   pair's normal there (the mesh's point query's rules, ties to the face; an overlap's
///   witness must lie in the body, to a tenth of the depth). One contact
///   per feature and per coplanar region, the deepest (the support's first); the mesh's
///   sides as its sphere query takes them; t1, t2 by the FACETED convention, curvatures 0,
///   iterations 0.
/// out holds cap contacts, *n gets their count (RS_ERR_CAPACITY beyond). Every kind
/// refuses (RS_ERR_ARG) a body whose position or quaternion is not finite, or whose
/// quaternion's norm is off 1 by more than 1e-6; one within 1e-6 is taken normalised.
int rs_body_surface_contacts(const rs_surface *s, const rs_pose *pose, const rs_body *b,
                             double gap_max, rs_body_contact *out, int cap, int *n,
                             rs_error *err);
/// The checks of every body query (RS_ERR_ARG with what was expected): a surface with a
/// kind, a body with a shape an rs_shape_make_* call made, a finite position within
/// RS_CONVEX_COORD_MAX, a finite quaternion of norm 1 to 1e-6, gap_max finite and >= 0.
/// *checked gets the body, its quaternion normalised where its norm is off 1 by more than
/// 1e-12 (rs_body_init's tolerance). A kind's body operation takes checked bodies.
int rs_body_check(const rs_surface *s, const rs_body *b, double gap_max, rs_body *checked,
                  rs_error *err);

/// Most points of one body's manifold on one feature.
#define RS_MANIFOLD_MAX 4
/// The ids of a feature's manifold points: 0 for the body's deepest point, 1 .. 30 for
/// the points of its core (a box's corner v is 1 + v, a cylinder's rim point k of rim e
/// (top 0, bottom 1) 1 + 4 e + k, a cone's rim 1 .. 4 and apex 5, a capsule's ends 1, 2,
/// a polyhedron's vertex i 1 + i mod 30).
#define RS_MANIFOLD_IDS 31
/// A manifold point's contact id: the owning feature f (below RS_MANIFOLD_STRIDE) and
/// the point's id j, f + j RS_MANIFOLD_STRIDE. Type, ring sector and RS_FEATURE_BASE
/// read as f's.
#define RS_MANIFOLD_STRIDE (1 << 26)
#define RS_FEATURE_MANIFOLD(f, j) ((f) + (j)*RS_MANIFOLD_STRIDE)
/// The owning feature of a contact id (itself for a sphere's contact).
#define RS_FEATURE_OWNER(f) ((f) % RS_MANIFOLD_STRIDE)

/// rs_body_query for the n bodies b[0 .. n), slave numbers point0 .. point0 + n - 1 and
/// radii radius[0 .. n), asked of the surface in one block, and each contact in the
/// principal frame (n, d1, d2 and the curvatures along d1 and d2), as a kind's closest
/// operation writes a sphere's (surface.h, rs_frame_convention): rs_body_query is this
/// call for one body, and rs_frame_orient.
int rs_body_manifold(const rs_surface *s, const rs_pose *pose, const rs_body *b, int n,
                     int point0, const double *radius, double gap_max, rs_contacts *c,
                     rs_error *err);

/// A convex body as a slave of the contact core: its contacts with surface s in pose
/// (NULL: reference) appended to c, a list that keeps witness points (c->witness), as
/// slave number point of its block. For each owning feature of rs_body_surface_contacts
/// (as many as there are), the feature's manifold: the body's deepest point
/// and the points of its core that rest on the feature within gap_max (a box's corners,
/// a cylinder's or cone's rim points a quarter turn apart from the lowest, a cone's
/// apex, a capsule's ends; none for a sphere, an ellipsoid or a user shape), each with
/// its rounding ball measured by the surface's own sphere query on that feature; the
/// deepest point stands for itself only where no core point is as deep. Where the
/// deepest point does not settle (a wall curved more sharply than the body), the core
/// points stand for it, or for a body without them the deepest of its iterates. The
/// RS_MANIFOLD_MAX deepest points are kept, each a contact with share 1, contact id
/// RS_FEATURE_MANIFOLD(feature, point id), xs its point on the body and dist = radius -
/// depth (radius: the body's characteristic length as the tracker and the law see it,
/// so that rdisp1 is the depth), t1 and t2 by the kind's convention. RS_ERR_ARG for a list
/// without witness points or a bad radius; the errors of rs_body_surface_contacts.
int rs_body_query(const rs_surface *s, const rs_pose *pose, const rs_body *b, int point,
                  double radius, double gap_max, rs_contacts *c, rs_error *err);

#ifdef __cplusplus
}
#endif
#endif
