/* rigidsurf: master surfaces and the closest-feature query.
 *
 * Conventions (docs/conventions.md, "Profiles and surfaces"):
 * - A profile is a chain of LINE, CIRCL and PARAB segments in a 2D plane (x, y). For
 *   CYLINDER that plane is the local (x, y) plane; for REVOLUTION it is (r, z).
 * - The outward normal lies to the left of travel: n2 = (-t_y, t_x). Particles live on
 *   the side n points to. A profile is one-sided unless SIDES=2; a MESH from STL, OBJ,
 *   OFF or PLY acts on both sides unless SIDES=1, an Abaqus rigid part on one.
 * - FILLET RADIUS rounds the corners between LINE and CIRCL segments with tangent arcs;
 *   a corner that touches a PARAB stays sharp.
 * - Frames:  SEGMENTS    t1 = (0,0,-1) x n  (= travel direction), t2 = (0,0,-1)
 *            CYLINDER    t1 = generator z^, t2 = n x t1
 *            REVOLUTION  t2 = hoop e_theta = z^ x e_r, t1 = t2 x n
 *            FACETED     t1 = global x projected on the tangent plane (global z when x is
 *                        within 0.1 deg of n), t2 = n x t1
 *   {n, t1, t2} is orthonormal and right-handed and turns with the master's rotation.
 * - One contact per (point, feature) that owns a local minimum of distance in its
 *   Voronoi region: a concave corner gives two segment contacts, a convex corner one
 *   vertex contact. No contact is counted twice and none goes missing. */
#ifndef RIGIDSURF_SURFACE_H
#define RIGIDSURF_SURFACE_H

#include "rigidsurf/motion.h"
#include "rigidsurf/types.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum rs_segment_type { RS_LINE = 1, RS_CIRCL = 2, RS_PARAB = 3 } rs_segment_type;

/// One profile segment in its plane.
typedef struct rs_segment {
    rs_segment_type type;
    double p0[2];  ///< start point
    double p1[2];  ///< end point
    double pm[2];  ///< CIRCL: centre; PARAB: middle point (on the curve, xi = 0)
    double radius; ///< CIRCL: radius
    double ang0;   ///< CIRCL: polar angle of p0 about the centre
    double sweep;  ///< CIRCL: signed sweep, |sweep| < pi (positive = counter-clockwise)
    double length; ///< arc length
    double s0;     ///< arc length of the profile at p0
} rs_segment;

/// How the profile turns at a vertex, seen from the particle side (the side n points to).
typedef enum rs_vertex_kind {
    RS_VTX_END = 0,     ///< first or last point of an open profile
    RS_VTX_CONVEX = 1,  ///< the wall bulges toward the particles: one vertex contact
    RS_VTX_CONCAVE = 2, ///< a pocket: the two segments each give a contact
    RS_VTX_SMOOTH = 3   ///< tangent-continuous (within 1e-9 rad): history carries over
} rs_vertex_kind;

typedef struct rs_profile {
    int nseg;
    rs_segment *seg; ///< nseg segments
    int closed;      ///< last end point coincides with the first start point
    int nvert;       ///< nseg + 1 (open) or nseg (closed)
    int *vkind;      ///< rs_vertex_kind for each vertex
} rs_profile;

/// Limits of a surface file's numbers, so that squares and products of coordinates and
/// lengths stay normal doubles: every number has |x| <= RS_COORD_MAX, and every segment
/// is at least RS_LENGTH_MIN long and at least RS_LENGTH_REL times the profile's size.
#define RS_COORD_MAX 1e100
#define RS_LENGTH_MIN 1e-100
#define RS_LENGTH_REL 1e-12

typedef enum rs_surface_kind {
    RS_SURF_SEGMENTS = 1,   ///< 2D profile in the global x-y plane, nDir = 2
    RS_SURF_CYLINDER = 2,   ///< profile extruded along the generator
    RS_SURF_REVOLUTION = 3, ///< profile in (r, z) revolved about the axis
    RS_SURF_FACETED = 4     ///< triangle mesh (TYPE=MESH)
} rs_surface_kind;

/// How a kind orients its tangents (docs/conventions.md, "Profiles and surfaces"). A kind's
/// closest-feature operation writes the principal frame of each contact: the normal n,
/// d1 and d2 = n x d1 in t1 and t2, with the curvatures along d1 and d2 in curv.
/// rs_frame_orient (src/frame.c) turns that into the kind's convention, in place.
typedef enum rs_frame_convention {
    /// t1 = d1, the profile's direction of travel; t2 = n x t1 (SEGMENTS: -z,
    /// REVOLUTION: the hoop direction). The principal frame is the contact frame.
    RS_FRAME_TRAVEL = 1,
    /// t1 = the generator, -d2; t2 = n x t1 = d1 (CYLINDER).
    RS_FRAME_GENERATOR = 2,
    /// t1 = global x projected on the tangent plane, global z when x is within 0.1 deg
    /// of n; t2 = n x t1 (FACETED). curv keeps the principal curvatures (along d1, d2).
    RS_FRAME_GLOBAL_X = 3
} rs_frame_convention;

struct rs_surface;
struct rs_query;
struct rs_contacts;
struct rs_trimesh;
struct rs_cands;
struct rs_body;
struct rs_body_contacts;
struct rs_body_work;

/// The operations of one surface kind: the seam through which every kind joins. The
/// table is chosen once, when the surface is made (rs_surface_read, rs_surface_parse),
/// and the contact core reaches the geometry only through it (src/surface.c).
typedef struct rs_surface_ops {
    const char *name;          ///< the kind's keyword, e.g. "REVOLUTION"
    int ndir;                  ///< local directions: 2 (a plane problem) or 3
    rs_frame_convention frame; ///< how t1 and t2 follow from the principal frame
    /// Appends the contacts of every query point to out, in the principal frame (see
    /// rs_frame_convention); contacts of one point are consecutive. A kind of the
    /// convention RS_FRAME_GLOBAL_X leaves t1 and t2: the frame follows from n alone.
    int (*closest)(const struct rs_surface *s, const struct rs_query *q,
                   struct rs_contacts *out, rs_error *err);
    /// 1 when a contact may hand its history from feature fa to feature fb (the normal
    /// is continuous across the junction), 0 otherwise.
    int (*adjacent)(const struct rs_surface *s, int fa, int fb);
    /// 1 when features fa and fb are faces that meet at a concave fold (a body's contact
    /// that begins on one beside its contact on the other continues its history), 0
    /// otherwise; NULL for kinds without such folds between features.
    int (*fold)(const struct rs_surface *s, int fa, int fb);
    /// Axis-aligned bounds in the reference configuration; +-INFINITY where unbounded.
    void (*bounds)(const struct rs_surface *s, double lo[3], double hi[3]);
    /// 1 with a point and a unit axis when the surface is invariant under rotation about
    /// that axis (a surface of revolution), 0 otherwise.
    int (*spin_axis)(const struct rs_surface *s, double origin[3], double axis[3]);
    /// A triangulation for display (see rs_surface_triangulate).
    int (*triangulate)(const struct rs_surface *s, double span, int nhoop,
                       struct rs_trimesh *m, rs_error *err);
    /// Frees what the kind owns (not the surface struct itself).
    void (*free)(struct rs_surface *s);
    /// 1 when closest and closest_among set each contact's share (rs_contacts.share)
    /// from the kind's own topology; 0: the dispatch sets them from the tangent planes of
    /// each sphere's contacts (docs/conventions.md, "Shares at concave folds").
    int shares;
    /// Optional (NULL: the kind searches its whole surface at every query): the
    /// candidates of each slave of q within its reach grown by extra, in kind-defined
    /// ids (MESH: triangles), so that an engine can keep them while its slaves and the
    /// master move less than extra in all.
    int (*candidates)(const struct rs_surface *s, const struct rs_query *q, double extra,
                      struct rs_cands *c, rs_error *err);
    /// With candidates: as closest, testing slave i against its ncand[i] candidates
    /// cand[i] only.
    int (*closest_among)(const struct rs_surface *s, const struct rs_query *q,
                         const int *const *cand, const int *ncand, struct rs_contacts *out,
                         rs_error *err);
    /// Optional (NULL: the kind has no facets, as the analytic kinds): the facet under a
    /// contact on feature f whose closest point is xm, both in the reference
    /// configuration: its node count nn (3 or 4; 0 when f names no facet), its nodes'
    /// user numbers (an Abaqus part's node labels; otherwise 1-based, in the file's
    /// order of the welded points), their coordinates xyz (3 x nn) and the shape
    /// functions at xm. An edge's or a vertex's facet is that of its lowest-numbered
    /// triangle.
    int (*facet)(const struct rs_surface *s, int f, const double xm[3], int nodes[4],
                 double xyz[12], double shape[4]);
    /// With facet: the most nodes a facet has (3, or 4 with quads); *nnode, the nodes.
    int (*facet_size)(const struct rs_surface *s, int *nnode);
    /// With facet: facet k's (0 <= k < facet_count) area and unit normal in the reference
    /// configuration; returns 0.
    int (*facet_area)(const struct rs_surface *s, int k, double *area, double n[3]);
    /// With facet: the index (0 .. count - 1) of the facet under a contact on feature f
    /// (an edge's or a vertex's: that of its lowest-numbered triangle), -1 for none.
    int (*facet_index)(const struct rs_surface *s, int f);
    /// With facet: the number of facets.
    int (*facet_count)(const struct rs_surface *s);
    /// The contacts of the n convex bodies b (convex.h) with the surface in pose (NULL: the
    /// reference configuration), one per owning feature with a gap of at most gap_max,
    /// appended to out[i] for body i in the principal frame, as closest writes a sphere's
    /// (docs/conventions.md, "Convex bodies"). With lenient != 0, a deepest point that does
    /// not settle (a wall curved more sharply than the body) gives the deepest of its
    /// iterates, with iterations -1, instead of RS_ERR_GEOMETRY. The bodies come checked
    /// (rs_body_check: rs_body_surface_contacts and rs_body_manifold check them first).
    /// NULL: the kind takes no bodies.
    int (*body)(const struct rs_surface *s, const rs_pose *pose, const struct rs_body *b,
                int n, double gap_max, int lenient, struct rs_body_contacts *out,
                rs_error *err);
    /// Optional (NULL: closest answers every point): the contact on feature f of a ball
    /// of the given radius about the point x (the world, pose as for closest), when the
    /// kind can tell in closed form that closest, asked for that ball with gap_max and
    /// dist_min = -depth_max, gives f exactly one contact, and f is flat (closest gives
    /// it curvatures 0): its dist, closest point xm and unit normal n, the same numbers
    /// closest writes, and where t1 and t2 are not NULL its frame as closest writes it
    /// (zeros where the kind's frame follows from n, RS_FRAME_GLOBAL_X, and closest
    /// leaves t1 and t2 unwritten).
    /// Returns 1 then, else 0 (ask closest). A body's manifold asks it for the core
    /// points on their feature.
    int (*feature_point)(const struct rs_surface *s, const rs_pose *pose, int f,
                         const double x[3], double radius, double gap_max, double depth_max,
                         double *dist, double xm[3], double n[3], double t1[3],
                         double t2[3]);
    /// How a surface file describes the kind: its parameters, data lines and the making
    /// of its surface (private to the geometry's reader; NULL: no surface file names it).
    const struct rs_surface_syntax *syntax;
    /// Optional (NULL: body): body for one run of a query's bodies, with their rotations
    /// given (R(q_i), row-major, at R + 9 i) and work arrays kept over the query's runs
    /// (private to the geometry); the same contacts as body.
    int (*body_run)(const struct rs_surface *s, const rs_pose *pose,
                    const struct rs_body *b, const double *R, int n, double gap_max,
                    int lenient, struct rs_body_contacts *out, struct rs_body_work *w,
                    rs_error *err);
} rs_surface_ops;

typedef struct rs_surface {
    const rs_surface_ops *ops; ///< the kind's operations
    rs_surface_kind kind;
    char name[80];
    int sides;            ///< 1 or 2
    double fillet_radius; ///< 0 when no fillets were requested
    rs_profile profile;
    /* Local frame in the reference configuration. CYLINDER: a, ex = (b-a)/|b-a|,
     * ez = (c-a) orthogonalised to ex, ey = ez x ex. REVOLUTION: a, ez = (b-a)/|b-a|,
     * ex a fixed unit vector normal to ez (the on-axis fallback for e_r), ey = ez x ex.
     * SEGMENTS: a = 0 and the global axes. */
    double a[3], ex[3], ey[3], ez[3];
    int bounded;       ///< CYLINDER: EXTENT given
    double zmin, zmax; ///< CYLINDER: extent along the generator, local z
    void *impl;        ///< the kind's query data
    char warning[512]; ///< what reading repaired or found doubtful (MESH: dropped facets,
                       ///< non-manifold edges, holes in a surface that otherwise
                       ///< closes), empty when nothing
    char info[256];    ///< what reading found that asks nothing of the user (MESH: the
                       ///< rim of an open surface), empty when nothing
} rs_surface;

/// Number of local directions: 2 for SEGMENTS, 3 otherwise, 0 for a surface without a
/// kind (zeroed or freed).
int rs_surface_ndir(const rs_surface *s);

/// The slaves of a query block (SoA, global coordinates, current configuration) are
/// points, spheres where radius is set, and convex bodies where body is set: a body's
/// contacts come from rs_body_query, through the kind's body operation and its sphere
/// query.

/// One block of particles as every call of the contact core reads it (SoA, n each): the
/// query (rs_query.slave), the tracker (rs_particles) and the law's inputs
/// (rs_block_particles) take the same struct, so an engine fills it once a step. Each
/// call reads the fields it names; what it does not read, and what the engine does not
/// have, may be NULL (zero-initialise the struct).
typedef struct rs_particle_block {
    int n;                      ///< particles (the query reads rs_query.n)
    const double *x, *y, *z;    ///< centres (z ignored for SEGMENTS)
    const double *radius;       ///< sphere radii, NULL for points; a body's
                                ///< characteristic length, the radius the laws see
    const struct rs_body *body; ///< per particle its convex body (convex.h), or NULL:
                                ///< where body[i].shape is set, particle i is that body,
                                ///< its contacts rs_body_query's; a leaving contact's
                                ///< point is its support along -n
    const double *vx, *vy, *vz; ///< velocities (tracker)
    const double *wx, *wy, *wz; ///< angular velocities (tracker; NULL: zero)
    const int *id;              ///< ids, for messages and the law's jSlvUid (NULL: index)
    const int *row;             ///< the engine's index of each particle (the law's
                                ///< slvRow), optional
    double **dir;               ///< tracker: per particle its directory (capacity doubles)
    double **hist;              ///< tracker: per particle its slot 0
    ptrdiff_t slot_stride;      ///< tracker: doubles from slot j to slot j + 1 (0:
                                ///< rs_track_slot_size)
    const double *mass;         ///< masses (law inputs)
    const int *type;            ///< material types (slv_type), optional
    const double *area;         ///< contact areas, optional: else the block's area mode
    const double *heatcap;      ///< heat capacities m c, optional: else conductance 0
    const double *temp;         ///< temperatures at the end of the increment, optional
    const double *dtemp;        ///< their increments (with temp)
    const double *pred;         ///< predefined fields (npred, n), optional
    const double *dpred;        ///< their increments (with pred)
} rs_particle_block;

/// The query's view of a block: x, y, z, radius, body.
typedef rs_particle_block rs_slaves;

/// A block of query slaves against a surface in its current pose.
typedef struct rs_query {
    int n;               ///< slaves in the block
    rs_slaves slave;     ///< where they are and what they are
    const rs_pose *pose; ///< current pose of the master, NULL for identity
    double gap_max;      ///< keep contacts with gap = dist - radius <= gap_max
    double dist_min;     ///< drop contacts whose centre lies deeper than this signed
                         ///< distance (use -INFINITY to keep every penetration)
    const int *hint;     ///< optional (NULL: none): per slave a feature it held, or
                         ///< RS_FEATURE_NONE. A MESH gives a slave whose hint is a face,
                         ///< and that lies where that face alone can own it, its contact
                         ///< from the face's own record without its candidates; the
                         ///< contacts are the same with or without hints
    double *near;        ///< optional output (NULL: none), kinds with candidate lists: per
                         ///< slave a lower bound of its distance to every feature that can
                         ///< give it a contact while the lists hold (slave i's
                         ///< candidates'; without lists, those within its reach, or the
                         ///< reach); 0 where a hint gave its contact
} rs_query;

/// Contacts found by a query (SoA, global coordinates). Arrays grow as needed.
typedef struct rs_contacts {
    int n, cap;
    int *point;      ///< index of the query point in its block
    int *feature;    ///< RS_FEATURE(type, index)
    double *xm[3];   ///< closest point on the master
    double *nrm[3];  ///< outward unit normal (toward the point's side)
    double *t1[3];   ///< first tangent, by the kind's convention
    double *t2[3];   ///< second tangent, t2 = n x t1 (SEGMENTS: (0,0,-1))
    double *dist;    ///< signed distance of the point from the surface along n
                     ///< (> 0 on the particle side); rdisp1 = radius - dist
    double *curv[2]; ///< principal curvatures at xm, along t1 and t2 where the frame is
                     ///< principal (the profile kinds), > 0 where the wall is convex
                     ///< toward the particle; 0 at sharp vertices
    double *share;   ///< the contact's share of what it exchanges, in [0, 1]: 1 except
                     ///< where two contacts of one sphere overlap it across a concave
                     ///< fold (docs/conventions.md, "Shares at concave folds"); set by
                     ///< rs_surface_query for every kind. NULL in a list made by hand:
                     ///< every share 1
    int shared;      ///< nonzero when a share may differ from 1 (kept over appends;
                     ///< reset by a query into an empty list)
    int witness;     ///< set before the first reserve: the list keeps xs, for a block
                     ///< that holds convex bodies (the queries of spheres and points do
                     ///< not fill it: the engine sets their xs = x - R n)
    double *xs[3];   ///< the slave's witness point (witness lists only): a body's
                     ///< deepest point along -n; the tracker's contact point is then
                     ///< xs + rdisp1 n / 2 instead of x - (R - rdisp1 / 2) n
} rs_contacts;

/// Allocates room for cap contacts (cap >= 1). Returns RS_ERR_NOMEM on failure.
int rs_contacts_reserve(rs_contacts *c, int cap, rs_error *err);

/// Most contacts of one sphere that take part in its shares; more keep share 1.
#define RS_SHARE_MAX 64
/// The shares of contacts a .. a + m - 1, all of one sphere of radius R, from their
/// weights, which share[a ..] holds on entry (docs/conventions.md, "Shares at concave
/// folds"): w_i = v_i / sum_j c_ij v_j over the contacts that overlap the sphere (0 <
/// dist < R), with c_ii = 1, c_ij = 1 where the discs the sphere cuts from the two
/// tangent planes (radii a = sqrt(R^2 - dist^2)) meet, D <= a_i + a_j for feet D apart,
/// else ((a_i + a_j) / D)^16. The others get share 1.
void rs_contacts_patch_shares(rs_contacts *c, int a, int m, double R);
/// The shares of contacts k0 .. c->n - 1 of the spheres of q from the fold lines of their
/// tangent planes (docs/conventions.md, "Shares at concave folds"), for a kind whose
/// closest operation does not set them (rs_surface_ops.shares = 0).
void rs_contacts_fold_shares(const rs_query *q, rs_contacts *c, int k0);
/// The shares of contacts a .. a + m - 1, all of one convex body of characteristic
/// radius R (docs/conventions.md, "Convex bodies"): the fold rule of
/// rs_contacts_fold_shares, each contact taken as the sphere of radius R on its witness
/// point (centre xm + dist n), a fold line reached from the midpoint of the two
/// contacts' centres.
void rs_contacts_body_shares(rs_contacts *c, int a, int m, double R);
/// Frees the arrays and zeroes c.
void rs_contacts_free(rs_contacts *c);

/// Appends the contacts of every query point to out (out->n grows; call with
/// out->n = 0 for a fresh list), each in the kind's frame convention. Contacts of one
/// point are consecutive. A list that keeps witness points (out->witness) gets a
/// sphere's or point's as x - R n. A block with bodies (q->slave.body) needs such a list
/// (RS_ERR_ARG otherwise): its spheres and points are asked in runs between the bodies,
/// each body by rs_body_query (every penetration of a body is kept: dist_min is the
/// spheres'), all in block order.
int rs_surface_query(const rs_surface *s, const rs_query *q, rs_contacts *out,
                     rs_error *err);

/// Candidate lists of a block of slaves: slave i's are ids[off[i] .. off[i + 1]).
/// Arrays grow as needed.
typedef struct rs_cands {
    int n;        ///< slaves
    int *off;     ///< n + 1
    int *ids;     ///< off[n]
    double *near; ///< n: a lower bound of each slave's distance to the surface (its
                  ///< nearest candidate's, or the lists' reach when it has none)
    int offcap, idcap;
} rs_cands;

/// 1 when the surface's kind gives candidate lists (rs_surface_candidates), else 0.
int rs_surface_has_candidates(const rs_surface *s);
/// The candidates of every slave of q within its reach (radius + gap_max, and down to
/// dist_min) grown by extra, less any that can give it no contact from anywhere within
/// extra: valid while slaves and master move less than extra in all.
int rs_surface_candidates(const rs_surface *s, const rs_query *q, double extra, rs_cands *c,
                          rs_error *err);
/// rs_surface_query testing slave i against its candidates cand[i][0 .. ncand[i]) only;
/// kinds without candidate lists answer as rs_surface_query.
int rs_surface_query_among(const rs_surface *s, const rs_query *q, const int *const *cand,
                           const int *ncand, rs_contacts *out, rs_error *err);
/// Frees the lists' arrays and zeroes c.
void rs_cands_free(rs_cands *c);

/// 1 when history may pass from feature fa to feature fb (see rs_surface_ops); 0 for a
/// surface without a kind.
int rs_surface_adjacent(const rs_surface *s, int fa, int fb);
/// 1 when fa and fb are contacts of one manifold point (RS_FEATURE_MANIFOLD) on two faces
/// that meet at a concave fold (see rs_surface_ops); 0 otherwise.
int rs_surface_fold(const rs_surface *s, int fa, int fb);

/// 1 when the surface's kind has facets (rs_surface_ops.facet and facet_count: a faceted
/// master, whose facets' nodes a VUINTER sees), else 0 (the analytic kinds).
int rs_surface_has_facets(const rs_surface *s);

/// The facet under a contact (rs_surface_ops.facet): its node count (0 for a kind without
/// facets or a feature that names none), its nodes' user numbers, their reference
/// coordinates and the shape functions at the closest point xm (reference configuration).
int rs_surface_facet(const rs_surface *s, int f, const double xm[3], int nodes[4],
                     double xyz[12], double shape[4]);

/// The most nodes a facet of s has (0 for a kind without facets); *nnode (may be NULL)
/// gets the surface's node count.
int rs_surface_facet_size(const rs_surface *s, int *nnode);

/// The number of facets of s (0 for a kind without facets).
int rs_surface_facet_count(const rs_surface *s);

/// Facet k's area and unit outward normal in the reference configuration; 0, or -1 when
/// k names no facet.
int rs_surface_facet_area(const rs_surface *s, int k, double *area, double n[3]);

/// The facet under a contact on feature f, or -1 (no facets, or none under f).
int rs_surface_facet_index(const rs_surface *s, int f);

/// Axis-aligned bounds of the surface in its reference configuration (+-INFINITY where
/// it is unbounded; an empty box at the origin for a surface without a kind).
void rs_surface_bounds(const rs_surface *s, double lo[3], double hi[3]);

/// 1 with origin and unit axis when the surface is invariant under rotation about that
/// axis (reference configuration), 0 otherwise (and for a surface without a kind).
int rs_surface_spin_axis(const rs_surface *s, double origin[3], double axis[3]);

/// Reads surface NAME (NULL: the first) from an Abaqus-style keyword file.
int rs_surface_read(const char *path, const char *name, rs_surface *s, rs_error *err);
/// Parses surface NAME (NULL: the first) from text; origin names the text in messages.
int rs_surface_parse(const char *text, const char *origin, const char *name, rs_surface *s,
                     rs_error *err);
/// A word of a profile built from arrays (rs_surface_make_profile): the keyword text's
/// START, LINE, CIRCL and PARAB.
typedef enum rs_profile_word {
    RS_WORD_START = 0,        ///< v = x, y: the first point
    RS_WORD_LINE = RS_LINE,   ///< v = x1, y1
    RS_WORD_CIRCL = RS_CIRCL, ///< v = x1, y1, xc, yc: under 180 deg, the short way
    RS_WORD_PARAB = RS_PARAB  ///< v = xm, ym, x1, y1: the middle point on the curve
} rs_profile_word;

/// One line of a profile in its plane (CYLINDER: local x, y; REVOLUTION: r, z).
typedef struct rs_profile_item {
    rs_profile_word word;
    double v[4]; ///< its values in the order of the keyword text; unused ones ignored
} rs_profile_item;

/// What the *SURFACE line and the coordinate lines of an analytic surface say, for
/// rs_surface_make_profile. Zeroed: unnamed, one side, no fillet, unbounded.
typedef struct rs_profile_def {
    rs_surface_kind kind; ///< RS_SURF_SEGMENTS, RS_SURF_CYLINDER or RS_SURF_REVOLUTION
    const char *name;     ///< NAME= (NULL or "": unnamed), at most 79 printable characters
    const char *origin;   ///< names the arrays in messages (NULL: "<arrays>")
    int sides;            ///< SIDES=: 0 (the default, one side), 1 or 2
    double fillet;        ///< FILLET RADIUS= (0: none)
    double a[3];          ///< CYLINDER, REVOLUTION: a, the origin
    double b[3];          ///< CYLINDER: b on the local x axis; REVOLUTION: b on the axis
    double c[3];          ///< CYLINDER: c on the generator (local z)
    int bounded;          ///< CYLINDER: 1 for EXTENT=zmin, zmax along the generator
    double zmin, zmax;    ///< with bounded: zmin < zmax
} rs_profile_def;

/// Builds an analytic surface from arrays in memory: def's parameters and points, and
/// nitems profile lines, the first of them START. It is the surface that the same
/// *SURFACE written as keyword text gives (rs_surface_parse), through the same checks:
/// errors read "ORIGIN:LINE: what was expected", LINE counted as in that text (1: the
/// *SURFACE line with def's parameters; then a, b and, for CYLINDER, c; then items[0],
/// items[1], ... one a line). A value that is not finite or exceeds RS_COORD_MAX, a bad
/// parameter or a NULL pointer is RS_ERR_ARG; a degenerate profile or frame
/// RS_ERR_GEOMETRY. On error s is zeroed.
int rs_surface_make_profile(const rs_profile_def *def, const rs_profile_item *items,
                            int nitems, rs_surface *s, rs_error *err);

/// What a mesh file's *SURFACE line and placement say, for rs_surface_make_mesh. Zeroed
/// except scale = 1 (RS_MESH_DEF_INIT): unnamed, both sides, in place.
typedef struct rs_mesh_def {
    const char *name;   ///< NAME= (NULL or "": unnamed), at most 79 printable characters
    const char *origin; ///< names the arrays in messages (NULL: "<arrays>")
    int sides;          ///< SIDES=: 0 (the default of CAD meshes: both sides), 1 or 2
    double scale;       ///< SCALE= (> 0): x = a + scale (X ex + Y ey + Z ez)
    int placed;         ///< 1: the placement abc below; 0: the vertices as given
    double abc[9];      ///< the placement a, b, c: origin a, local x toward b, c in the
                        ///< local x-y plane (as a surface file's placement line)
} rs_mesh_def;

/// An rs_mesh_def with its defaults.
/* clang-format off */
#define RS_MESH_DEF_INIT {NULL, NULL, 0, 1.0, 0, {0, 0, 0, 0, 0, 0, 0, 0, 0}}
/* clang-format on */

/// Builds a MESH surface from arrays in memory: nv vertices xyz (3 nv doubles, x y z of
/// each) and nt triangles tri (3 nt vertex indices from 0, the node order giving the
/// normal by the right-hand rule). def may be NULL (RS_MESH_DEF_INIT). It is the surface
/// a mesh file of these points and triangles gives (TYPE=MESH, FILE=), through the same
/// building and checks: points closer than 1e-9 of the mesh's size are welded, degenerate
/// triangles dropped with a warning (s->warning), each component oriented consistently
/// (both sides act where none exists). Messages and warnings number points and facets
/// from 1, as for a file. NULL arrays, nv < 3, nt < 1, an index outside 0 .. nv - 1 or a
/// bad parameter is RS_ERR_ARG; a coordinate that is not finite (or exceeds RS_COORD_MAX
/// after scale), a degenerate placement or a mesh without a triangle of non-zero area
/// RS_ERR_GEOMETRY, as for a file. On error s is zeroed.
int rs_surface_make_mesh(const double *xyz, int nv, const int *tri, int nt,
                         const rs_mesh_def *def, rs_surface *s, rs_error *err);

/// Frees what a surface owns and zeroes it.
void rs_surface_free(rs_surface *s);

/// A triangulation of the surface for display, in the reference configuration.
/// Extrusions without EXTENT and revolutions are cut at +-span along their axis or
/// drawn over the full turn with nhoop facets. Arrays are malloc'ed; free with free().
typedef struct rs_trimesh {
    int nvert, ntri;
    double *xyz; ///< 3 * nvert
    int *tri;    ///< 3 * ntri, node order gives the outward normal (right-hand rule)
    int *cell;   ///< ntri: the facet each triangle shows (rs_surface_facet_index), or NULL
                 ///< for a kind without facets
} rs_trimesh;
int rs_surface_triangulate(const rs_surface *s, double span, int nhoop, rs_trimesh *m,
                           rs_error *err);
void rs_trimesh_free(rs_trimesh *m);

/// Turns contacts [k0, k1) of c from the principal frame a kind's closest operation
/// writes into the frame convention conv (t1, t2 and the curvatures along them; a list
/// without curvatures, c->curv[0] NULL, only its frames).
void rs_frame_orient(rs_frame_convention conv, rs_contacts *c, int k0, int k1);

/// The FACETED tangents of unit normal n: t1 = global x on the tangent plane (global z
/// when x is within 0.1 deg of n), t2 = n x t1.
void rs_frame_faceted(const double n[3], double t1[3], double t2[3]);

/// rs_frame_orient for one contact of unit normal n: t1, t2 and the curvatures curv
/// along them, in place.
void rs_frame_orient_one(rs_frame_convention conv, const double n[3], double t1[3],
                         double t2[3], double curv[2]);

#ifdef __cplusplus
}
#endif
#endif
