/* Private parts of the convex geometry shared by its files and the kinds' body operations:
 * the core's support (the shape less its rounding), a body's checks, reach and contact
 * list, the moments of a solid, and the rounded solids' moments. */
#ifndef RS_CONVEX_INTERNAL_H
#define RS_CONVEX_INTERNAL_H

#include "rigidsurf/convex.h"

#include <math.h>

/// RS_ERR_ARG unless s is a shape an rs_shape_make_* call made (kind, dimensions,
/// rounding, a polyhedron's hull, a user shape's support).
int rs_shape_check(const rs_shape *s, rs_error *err);
/// The core's support along d (body frame, no rounding); d need not be unit, zero is +z.
void rs_shape_core_support(const rs_shape *s, const double d[3], double out[3]);
/// Hulls of at most this many vertices are scanned; larger ones walked (hull_walk.c).
#define RS_HULL_SCAN 64
/// Most vertices rs_hull_farthest gives.
#define RS_HULL_FARTHEST_MAX 32
/// The vertex adjacency of polyhedron s (adj0, adj) from its triangles. 0, -1 when out
/// of memory.
int rs_hull_adjacency(rs_shape *s);
/// The climbs' starts of polyhedron s (rs_shape.hint): its extreme vertex along the
/// centre of each cell of a cube's faces (RS_HULL_CELLS x RS_HULL_CELLS a face).
void rs_hull_hints(rs_shape *s);
/// The index of polyhedron s's vertex farthest along d (body frame): by a scan of its
/// vertices (the first of ties), or for more than RS_HULL_SCAN by hill climbing over its
/// adjacency from the hint of the cell d points through.
int rs_hull_support(const rs_shape *s, const double d[3]);
/// The cap (<= RS_HULL_FARTHEST_MAX) vertices of s farthest along d, farthest first (ties:
/// the lower index), into out; returns how many.
int rs_hull_farthest(const rs_shape *s, const double d[3], int cap, int *out);
/// rs_body_support with the body's rotation R (rs_body_rotation) given.
void rs_body_support_at(const rs_body *b, const double R[9], const double dir[3],
                        double out[3]);
/// The rounding around the core: the shape's rounding, plus the radius of a sphere or
/// a capsule (whose cores are a point and a segment).
static inline double rs_shape_core_radius(const rs_shape *s)
{
    if (s->kind == RS_SHAPE_SPHERE || s->kind == RS_SHAPE_CAPSULE)
        return s->rounding + s->dim[0];
    return s->rounding;
}

/// |(x, y)|: sqrt(x^2 + y^2) where neither square can overflow nor the larger underflow
/// (the larger part between 2^-480 and 2^480: a direction, a body-frame point), hypot
/// elsewhere; within an ulp or so of hypot, at a fraction of its cost.
static inline double rs_norm2(double x, double y)
{
    const double ax = fabs(x), ay = fabs(y), m = ax > ay ? ax : ay;
    if (m > 0x1p-480 && m < 0x1p480)
        return sqrt(x * x + y * y);
    return hypot(x, y);
}

/// rs_body_check's checks of b's pose alone (its shape and the gap checked before, as
/// for a body of the same shape): into *checked, its quaternion normalised.
int rs_body_check_pose(const rs_body *b, rs_body *checked, rs_error *err);
/// rs_body_check's checks but those of the pose (rs_body_check_norm).
int rs_body_check_shape(const rs_surface *s, const rs_body *b, double gap_max,
                        rs_error *err);
/// What is wrong with b's pose, whose quaternion has norm nq, as rs_body_check_norm says
/// it (RS_ERR_ARG).
int rs_body_pose_error(const rs_body *b, double nq, rs_error *err);
/// rs_body_check_pose's checks without the copy: *nq, the quaternion's norm (b is used as
/// it is where |nq - 1| <= 1e-12, else normalised).
static inline int rs_body_check_norm(const rs_body *b, double *nq, rs_error *err)
{
    const double *q = b->q;
    *nq = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    /* the position and the norm at once (a unit norm has finite parts) */
    if (fabs(b->x[0]) <= RS_CONVEX_COORD_MAX && fabs(b->x[1]) <= RS_CONVEX_COORD_MAX &&
        fabs(b->x[2]) <= RS_CONVEX_COORD_MAX && fabs(*nq - 1.0) <= 1e-6)
        return RS_OK;
    return rs_body_pose_error(b, *nq, err);
}
/// A body's reach about its centre: the farthest corner of its bounding box.
static inline double rs_body_reach(const rs_body *b)
{
    return b->shape->reach;
}
/// Doubles l's room (at least 16), moving a borrowed array to the heap; RS_ERR_NOMEM.
int rs_body_contacts_grow(rs_body_contacts *l, rs_error *err);
/// Appends o to l; RS_ERR_NOMEM when it cannot grow.
static inline int rs_body_contacts_push(rs_body_contacts *l, const rs_body_contact *o,
                                        rs_error *err)
{
    if (l->n == l->cap) {
        const int rc = rs_body_contacts_grow(l, err);
        if (rc)
            return rc;
    }
    l->c[l->n++] = *o;
    return RS_OK;
}
/// The contacts of n slaves with surface s, into c (emptied first): points (radius NULL)
/// or spheres at (x, y, z) with a gap of at most gap_max whose centres lie at most
/// depth_max behind the surface (a body's points are sought no deeper than twice its
/// reach: a body deeper than that lies behind the wall), by the kind's closest operation
/// in one block (principal frame).
int rs_body_closest(const rs_surface *s, const rs_pose *pose, int n, const double *x,
                    const double *y, const double *z, const double *radius, double gap_max,
                    double depth_max, rs_contacts *c, rs_error *err);
/// Where slave i's contacts start in c (off[i]; off[n] = c->n): a query's contacts of
/// one slave are consecutive, in block order.
void rs_contacts_offsets(const rs_contacts *c, int n, int *off);
/// Among contacts [k0, k1) of one slave whose distance lies in [lo, hi], the one of
/// feature base want, else the deepest (the first of ties); -1 for none. [lo, hi] is the
/// slave's own window (dist_min, gap_max + radius): a block's slaves whose windows differ
/// are asked at once over the widest, and each picks within its own what a query of its
/// own window gives it (the kinds' closest operations filter each slave's contacts by
/// its window), so that a body's contacts do not depend on the others in its block.
int rs_contacts_pick(const rs_contacts *c, int k0, int k1, int want, double lo, double hi);

/// Does body b hold the world point p, to tol (length): is p within the rounding plus tol
/// of its core (GJK)? 0 for a body rs_convex_pair refuses.
int rs_body_holds(const rs_body *b, const double p[3], double tol);
/// A kind's own answer for one iterate of the fixed point: when feature want is among
/// the contacts its closest operation gives the world point p (a point, gap_max = gap,
/// dist_min = -gap), that contact (feature, depth = -dist, normal, xm, t1, t2, curv, all
/// as closest writes them) into *o and 1; else 0 (then closest is asked).
typedef int (*rs_body_face_fn)(const void *ctx, int want, const double p[3], double gap,
                               rs_body_contact *o);
/// rs_body_fixed_point with a kind's answer for the iterates (face(ctx, ...); NULL: every
/// iterate by the closest operation); the same contacts either way.
int rs_body_fixed_point_with(const rs_surface *s, const rs_pose *pose, const rs_body *b,
                             int n, double gap_max, int lenient, rs_body_face_fn face,
                             const void *ctx, rs_body_contacts *out, rs_error *err);
/// The fixed point's work arrays, kept over the runs of bodies of one query (zero it first;
/// rs_body_fixed_work_free).
typedef struct rs_body_fixed_work {
    rs_contacts pc; ///< the reach spheres' and the iterates' contacts
    void *mem;      ///< the bodies' rotations (where not given), reach, centres, windows
    size_t bytes;
    void *fx; ///< the fixed points and their iterates' queries
    size_t fxbytes;
} rs_body_fixed_work;
/// rs_body_fixed_point_with on the work arrays w, grown as needed and kept, with the
/// bodies' rotations R(q_i) at R + 9 i (rs_body_rotation; NULL: made here).
int rs_body_fixed_point_run(const rs_surface *s, const rs_pose *pose, const rs_body *b,
                            const double *R, int n, double gap_max, int lenient,
                            rs_body_face_fn face, const void *ctx, rs_body_contacts *out,
                            rs_body_fixed_work *w, rs_error *err);
void rs_body_fixed_work_free(rs_body_fixed_work *w);
/// The fixed point of rs_body_fixed_point_with over the kind's point query only: for
/// each feature near each of the n bodies (a sphere query of its reach about its centre)
/// the normal iterated to a fixed point through the kind's point query, the bodies in one
/// block; one contact per owning feature, the deepest, into out[i] for body i.
int rs_body_fixed_point(const rs_surface *s, const rs_pose *pose, const rs_body *b, int n,
                        double gap_max, int lenient, rs_body_contacts *out, rs_error *err);

/// A kind's closed form of a core point's ball on a flat feature f for one run of bodies
/// (the arguments and answer of rs_surface_ops.feature_point, the pose the run's), on
/// the context its body_run set up (rs_body_work.point).
typedef int (*rs_body_point_fn)(const void *ctx, int f, const double x[3], double radius,
                                double gap_max, double depth_max, double *dist,
                                double xm[3], double n[3], double t1[3], double t2[3]);
/// A core point of a body's manifold (body_manifold.c): its body-frame point and id
/// (1 .. RS_MANIFOLD_IDS - 1).
typedef struct rs_core_cand {
    double p[3];
    int id;
} rs_core_cand;
/// Room for a body's core points (its deepest point, then the rest).
#define RS_CORE_CANDS (1 + RS_MANIFOLD_IDS)
/// The core points of shape s that can touch a wall under it, d the body-frame direction
/// into the wall (unit, dn its length before): those whose height above the deepest
/// point, -dn d.p + nx - rr - nxs, is at most clear, in their order (a box's corners, a
/// cylinder's and a cone's rim points and apex, a capsule's ends, a polyhedron's cap
/// vertices farthest first; none for a smooth shape), at most cap; returns how many.
int rs_body_low_points(const rs_shape *s, const double d[3], double dn, double nx,
                       double rr, double nxs, double clear, rs_core_cand *c, int cap);

/// A body's manifold on one flat feature answered in closed form (body_flat.c): its
/// points as the manifold keeps them, in order, each with its id, depth and contact.
typedef struct rs_flat_manifold {
    int n;
    int id[RS_MANIFOLD_MAX];
    double depth[RS_MANIFOLD_MAX];
    double xm[RS_MANIFOLD_MAX][3], nrm[RS_MANIFOLD_MAX][3], t1[RS_MANIFOLD_MAX][3],
        t2[RS_MANIFOLD_MAX][3], xs[RS_MANIFOLD_MAX][3], curv[RS_MANIFOLD_MAX][2];
} rs_flat_manifold;
/// The manifold of body b (rotation R, reach, window win: rs_body_manifold_in's) on its
/// one feature o, a flat face set up as kit (flat_face.h): the same points and contacts
/// as rs_body_manifold_in makes through the kind's closed form, into *m, and 1; 0 where
/// the kit does not answer a core point (the block's query tells).
struct rs_flat_face;
int rs_body_flat_manifold(const rs_body *b, const double R[9], const rs_body_contact *o,
                          double reach, double win, double gap_max,
                          const struct rs_flat_face *kit, rs_flat_manifold *m);
/// Appends point k of m, a manifold on feature f, to c as the manifold appends its points
/// (the witness kept, share 1) for slave point of the given radius; RS_ERR_NOMEM.
static inline int rs_body_flat_append(rs_contacts *c, int point, double radius, int f,
                                      const rs_flat_manifold *m, int k, rs_error *err)
{
    if (c->n >= c->cap || !c->xs[0]) {
        const int rc =
            rs_contacts_reserve(c, c->n < c->cap ? c->n + 1 : 2 * c->n + 64, err);
        if (rc)
            return rc;
    }
    const int j = c->n++;
    c->point[j] = point;
    c->feature[j] = RS_FEATURE_MANIFOLD(f, m->id[k]);
    for (int d = 0; d < 3; d++) {
        c->xm[d][j] = m->xm[k][d];
        c->nrm[d][j] = m->nrm[k][d];
        c->t1[d][j] = m->t1[k][d];
        c->t2[d][j] = m->t2[k][d];
        c->xs[d][j] = m->xs[k][d];
    }
    c->dist[j] = radius - m->depth[k];
    c->curv[0][j] = m->curv[k][0];
    c->curv[1][j] = m->curv[k][1];
    c->share[j] = 1.0;
    return RS_OK;
}
/// The kit of flat feature f (flat_face.h) the kind's body_run set up for the run, on the
/// context it keeps (rs_body_work.point_ctx); NULL where it has none.
typedef const struct rs_flat_face *(*rs_body_kit_fn)(const void *ctx, int f);

/// rs_body_manifold's work arrays, kept over the runs of bodies of one query (zero it
/// first; rs_body_work_free).
typedef struct rs_body_work {
    rs_contacts pc; ///< the core points' contacts
    void *mem;      ///< the bodies' features, checked copies, reach and lists
    size_t bytes;
    void *q;   ///< the core points' queries
    double *x; ///< their balls
    int cap;
    int *off; ///< where each ball's contacts start
    int noff;
    double *rot; ///< the bodies' rotations (rs_surface_ops.body_run)
    int nrot;
    rs_body_fixed_work fp; ///< the kind's (rs_surface_ops.body_run)
    /// The kind's closed form of the run's core points on flat features, set by its
    /// body_run (NULL: rs_surface_ops.feature_point where the manifold asks it), on the
    /// context point_ctx it keeps in kind_mem (kind_bytes; freed with the work).
    rs_body_point_fn point;
    const void *point_ctx;
    rs_body_kit_fn kit; ///< with point: the kits of its flat faces (NULL: none)
    void *kind_mem;
    size_t kind_bytes;
    rs_flat_manifold *flat; ///< the run's manifolds answered in closed form
    int *flat_at;           ///< each body's there, -1 for none
    int nflat;              ///< room for bodies in both
} rs_body_work;
/// rs_body_manifold on the work arrays w, grown as needed and kept.
int rs_body_manifold_in(const rs_surface *s, const rs_pose *pose, const rs_body *body,
                        int n, int point0, const double *radius, double gap_max,
                        rs_body_work *w, rs_contacts *c, rs_error *err);
void rs_body_work_free(rs_body_work *w);

/// Volume moments of a solid about the frame's origin: v = int dV, s = int x dV,
/// ss = int x x^T dV (row-major).
typedef struct rs_moments {
    double v;
    double s[3];
    double ss[9];
} rs_moments;

/// The moments of the convex polytope (vertices v, outward triangles t) rounded by
/// r >= 0, exactly: core, face slabs, edge wedges and vertex sectors. Returns 0, -1 when
/// out of memory (m zero).
int rs_polytope_moments(const double *v, const int *t, int nt, double r, rs_moments *m);
/// The moments of the rounded polygon prof (n (rho, z) vertices, counter-clockwise,
/// one edge on the axis rho = 0) revolved about body z, rounded by r >= 0.
void rs_revolved_moments(const double *prof, int n, double r, rs_moments *m);
/// The moments of the ellipsoid of semi-axes a, b, c rounded by r >= 0.
void rs_ellipsoid_moments(double a, double b, double c, double r, rs_moments *m);

#endif
