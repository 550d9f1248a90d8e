/* rigidsurf (private): profile geometry and the 2D closest-feature query shared by the
 * SEGMENTS, CYLINDER and REVOLUTION surfaces.
 *
 * Feature ownership in the profile plane (docs/conventions.md, "One contact"). For a point
 * P and a vertex v, let dA = (P - v).tA and dB = (P - v).tB with tA the end tangent of
 * the segment that ends at v and tB the start tangent of the one that starts there. A
 * SMOOTH vertex uses one shared tangent for both, so the two tests are one number.
 * - Segment k owns P when its closest point is interior: dB > 0 at its start vertex
 *   (dB >= 0 when that vertex is SMOOTH or CONCAVE) and dA < 0 at its end vertex. For
 *   LINE and CIRCL this is exactly the interior projection; for PARAB the same signs
 *   bracket the roots of the closest-point cubic, so both ends agree with the vertices.
 * - A CONVEX vertex owns dA >= 0 && dB <= 0 (the wedge in front), normal d/|d|.
 * - A CONCAVE vertex owns dA >= 0 && dB < 0. That wedge lies behind the wall; with
 *   SIDES=2 it is a convex vertex seen from the back (normal d/|d|, distance |d|), with
 *   one side it is a penetration (normal -d/|d|, distance -|d|), so an embedded point
 *   behind a pocket is never lost.
 * - END vertices own the quarter plane beyond the end on the particle side (the half
 *   plane with SIDES=2). A REVOLUTION end vertex on the axis hands the boundary ray
 *   dA = 0 (the axis itself) to its segment: the surface closes smoothly there.
 * - One side: behind a CONVEX vertex, when both faces project, only the face with the
 *   larger signed distance (smaller penetration) keeps its contact.
 * Fillets: FILLET RADIUS rounds corners between LINE and CIRCL segments only. A corner
 * that touches a PARAB stays sharp. */
#ifndef RS_PROFILE_H
#define RS_PROFILE_H

#include "rigidsurf/surface.h"
#include "rigidsurf/vec.h"

/* The analytic kinds' operations (analytic.c): the table of kind, NULL for other kinds,
 * and the parts that live in other files. */
const rs_surface_ops *rs_analytic_ops(rs_surface_kind kind);
int rs_analytic_closest(const rs_surface *s, const rs_query *q, rs_contacts *out,
                        rs_error *err);
/// The body operation (analytic_body.c): rs_body_fixed_point, its iterates on the flat
/// faces of CYLINDER and SEGMENTS in closed form.
int rs_analytic_body(const rs_surface *s, const rs_pose *pose, const struct rs_body *b,
                     int n, double gap_max, int lenient, struct rs_body_contacts *out,
                     rs_error *err);
/// rs_analytic_body with the bodies' rotations given and the query's work arrays kept
/// (rs_surface_ops.body_run).
int rs_analytic_body_run(const rs_surface *s, const rs_pose *pose, const struct rs_body *b,
                         const double *R, int n, double gap_max, int lenient,
                         struct rs_body_contacts *out, struct rs_body_work *w,
                         rs_error *err);
/// The feature_point of CYLINDER and SEGMENTS (analytic_body.c): a LINE's face of the
/// profile, where the profile's ownership rules give the point to it (rs_pcache_face),
/// with the contact rs_analytic_closest writes.
int rs_analytic_feature_point(const rs_surface *s, const rs_pose *pose, int f,
                              const double x[3], double radius, double gap_max,
                              double depth_max, double *dist, double xm[3], double n[3],
                              double t1[3], double t2[3]);
int rs_analytic_triangulate(const rs_surface *s, double span, int nhoop, rs_trimesh *m,
                            rs_error *err);
void rs_analytic_free(rs_surface *s);

/// Relative tolerance for tangent continuity (radians) and arc radius mismatch.
#define RS_SMOOTH_ANGLE 1e-9
#define RS_RADIUS_TOL 1e-9

/// LINE from p0 to p1. RS_ERR_GEOMETRY when it has zero length. where prefixes messages.
int rs_segment_line(rs_segment *g, const double p0[2], const double p1[2],
                    const char *where, rs_error *err);
/// CIRCL about centre c from p0 to p1, the short way, under 180 degrees.
int rs_segment_circl(rs_segment *g, const double p0[2], const double p1[2],
                     const double c[2], const char *where, rs_error *err);
/// PARAB through p0, pm (xi = 0) and p1.
int rs_segment_parab(rs_segment *g, const double p0[2], const double pm[2],
                     const double p1[2], const char *where, rs_error *err);

/// Unit tangent (direction of travel) at the start (at_end = 0) or the end of the
/// segment, straight from its defining points (no trigonometry for CIRCL).
void rs_segment_end_tangent(const rs_segment *g, int at_end, double t[2]);

/// Point, unit tangent (direction of travel) and signed curvature (> 0 turning left,
/// toward n) at parameter u in [0, 1] along the segment (CIRCL: angle fraction, PARAB:
/// xi = 2u - 1, LINE: length fraction).
void rs_segment_eval(const rs_segment *g, double u, double x[2], double t[2], double *k);

/// Lengths and s0, closed flag, nvert and vertex kinds. vkind is (re)allocated. When
/// smooth is not NULL, vertices with smooth[j] != 0 are SMOOTH by construction.
int rs_profile_finish(rs_profile *p, const unsigned char *smooth, rs_error *err);

/// Largest coordinate extent of the profile (bounding box size or distance from the
/// origin, whichever is larger); the scale of relative tolerances.
double rs_profile_size(const rs_profile *p);

/// Rounds the corners between LINE/CIRCL segments with tangent arcs of radius r.
/// line[k] is the input line of segment k (for messages); it is updated to the new
/// segment list. RS_ERR_GEOMETRY naming the vertex when a fillet does not fit.
int rs_profile_fillet(rs_profile *p, double r, int **line, const char *origin,
                      rs_error *err);

/// Frees what the profile owns and zeroes it.
void rs_profile_free(rs_profile *p);

/* Query data, built once per surface (kept in rs_surface.impl for the analytic kinds). */
typedef struct rs_pseg {
    int type;             ///< rs_segment_type
    int start_incl;       ///< start vertex SMOOTH, CONCAVE or on a revolution axis: dB >= 0
    int end_incl;         ///< end vertex on a revolution axis: dA <= 0
    int vtx_start;        ///< the start vertex can own a contact (it is not SMOOTH)
    int vtx_end;          ///< the end vertex closes an open profile (vertex nseg)
    int self;             ///< its index k
    double v0[2], tb0[2]; ///< start vertex and its start tangent (the vertex's tb)
    double v1[2], ta1[2]; ///< end vertex and its end tangent (the vertex's ta)
    double box[4];        ///< bounding box xmin, xmax, ymin, ymax (grown by a tolerance)
    double o[2];          ///< LINE: p0; CIRCL: centre; PARAB: middle point
    double rad;           ///< CIRCL: radius
    double t[2];          ///< LINE: unit tangent
    double nl[2];         ///< LINE: unit normal (-t[1], t[0])
    double e[2];          ///< LINE: p1 - p0
    double inv_len2;      ///< LINE: 1 / |p1 - p0|^2
    double sgn;           ///< CIRCL: sign of the sweep
    double B[2], C[2];    ///< PARAB: X(xi) = pm + xi B + xi^2 C
} rs_pseg;

/* The offsets dB, dA of (px, py) along segment q's start and end tangents from its
 * start and end vertices (see the top of this file); q's slab is dB > 0 and dA < 0. */
static inline void rs_pseg_offsets(const rs_pseg *q, double px, double py, double *dB,
                                   double *dA)
{
    *dB = (px - q->v0[0]) * q->tb0[0] + (py - q->v0[1]) * q->tb0[1];
    *dA = (px - q->v1[0]) * q->ta1[0] + (py - q->v1[1]) * q->ta1[1];
}

/* The ownership test of segment q (see the top of this file): the point is past its
 * start vertex (in_start: dB > 0, or dB = 0 where the start is inclusive) and before
 * its end vertex (in_end: dA < 0, or dA = 0 where the end is inclusive); q owns it when
 * both hold. */
static inline void rs_pseg_owns(const rs_pseg *q, double px, double py, int *in_start,
                                int *in_end)
{
    double dB, dA;
    rs_pseg_offsets(q, px, py, &dB, &dA);
    *in_start = q->start_incl ? dB >= 0.0 : dB > 0.0;
    *in_end = q->end_incl ? dA <= 0.0 : dA < 0.0;
}

/* The contact of profile-plane point (px, py) on LINE q's face within [dlo, dhi] (two:
 * SIDES=2, where a point behind the face meets its flipped side): 1 with the distance
 * (*dist), whether the side is the flipped one (*flip) and the foot (hx, hy); 0 where the
 * point is beyond reach, not owned by q, or outside the window. The test the profile's
 * cache makes of a LINE's face (rs_pcache_face) and a flat face's kit (flat_face.h). */
static inline int rs_pseg_line_face(const rs_pseg *q, int two, double px, double py,
                                    double dlo, double dhi, double *dist, int *flip,
                                    double *hx, double *hy)
{
    const double reach = (two || dhi > -dlo) ? dhi : -dlo;
    if (!(reach >= 0.0) || dlo > dhi || q->box[0] - px > reach || px - q->box[1] > reach ||
        q->box[2] - py > reach || py - q->box[3] > reach)
        return 0;
    const double wx = px - q->o[0], wy = py - q->o[1];
    const double nx = -q->t[1], ny = q->t[0], sd = wx * nx + wy * ny;
    int in_start, in_end;
    rs_pseg_owns(q, px, py, &in_start, &in_end);
    if (fabs(sd) > reach || !(in_start && in_end))
        return 0;
    const int f = two && sd < 0.0;
    const double d = f ? -sd : sd;
    if (!(d >= dlo && d <= dhi))
        return 0;
    double tau = (wx * q->e[0] + wy * q->e[1]) * q->inv_len2;
    tau = tau < 0.0 ? 0.0 : tau > 1.0 ? 1.0 : tau;
    *dist = d, *flip = f;
    *hx = q->o[0] + tau * q->e[0], *hy = q->o[1] + tau * q->e[1];
    return 1;
}

typedef struct rs_pvert {
    double v[2];
    double ta[2], tb[2]; ///< end tangent of segment sa, start tangent of segment sb
    double na[2], nb[2]; ///< the matching normals
    double nfb[2];       ///< normal used when the point sits exactly on the vertex
    int kind;            ///< rs_vertex_kind
    int sa, sb;          ///< segment before / after, -1 when none
    int seg_owns_edge;   ///< END on a revolution axis: the segment owns dA = 0 / dB = 0
} rs_pvert;

/* The index of a profile's query data, in one of two forms, both with a tree of
 * bounding boxes over runs of RS_PC_LEAF consecutive segments: level 0 boxes the runs,
 * each box of level l + 1 the two boxes 2i, 2i + 1 of level l. A depth-first walk, first
 * child first, meets the segments in profile order. The tree costs about 4 doubles per
 * RS_PC_LEAF / 2 segments and serves any reach.
 *
 * Stored records (profiles of up to RS_PC_LARGE segments): every segment's rs_pseg and
 * every vertex's rs_pvert, and a 1D bucket index along one profile axis (the one that
 * spreads the segments best). Bucket b covers [lo + b w, lo + (b + 1) w). Level l
 * lists, in profile order, the segments whose bounding box comes within margin[l] of
 * the bucket, so a point within reach <= margin[l] of a segment finds it in its own
 * bucket's list at level l. Reaches beyond the last level walk the tree, or scan every
 * segment in a profile of at most RS_PC_SCAN.
 *
 * Compact (larger profiles): no per-segment records and no buckets. A query walks the
 * tree and makes the records of the segments it meets from the profile
 * (rs_pcache_segment, rs_pcache_vertex). */
#define RS_PC_MAXLEVEL 12
/* Buckets per segment: fine enough that most buckets along a chain of collinear pieces
 * lie inside one piece (rs_pcache_build gives those an owner). */
#define RS_PC_BUCKETS_PER_SEG 4
#define RS_PC_LARGE 16384
#define RS_PC_LEAF 8
#define RS_PC_SCAN 64
#define RS_PC_MAXDEPTH 40
typedef struct rs_pcache {
    int nseg, nvert, closed, sides;
    int revolution; ///< a REVOLUTION profile (END vertices on the axis: seg_owns_edge)
    double size;
    double box[4]; ///< the profile's bounding box (the segments' boxes' union)
    const rs_segment *seg;
    unsigned char *vk; ///< nvert: each vertex's rs_vertex_kind
    rs_pseg *ps;       ///< stored records, or NULL (compact)
    rs_pvert *pv;      ///< stored records, or NULL (compact)
    int axis;          ///< 0: buckets along x (or r), 1: along y (or z)
    int nbucket, nlevel;
    double lo, inv_w;              ///< bucket of coordinate c: floor((c - lo) inv_w)
    double margin[RS_PC_MAXLEVEL]; ///< increasing
    int *bstart;                   ///< level l, bucket b: [l (nbucket + 1) + b], into boff
    int *bchain; ///< level l, bucket b: [l nbucket + b]: 0, 1 for a LINE chain, 2 + k
                 ///< for a chain whose points within the level's margin segment k owns
    int *boff;   ///< the levels' lists, then every segment (from all_at: the list of a
                 ///< reach beyond the last level), as byte offsets into ps
    int all_at;
    double *tree; ///< the boxes (xmin, xmax, ymin, ymax) of the tree's every level
    int ntlev;    ///< levels of the tree; level l starts at box tlev[l]
    int tlev[RS_PC_MAXDEPTH + 1];
} rs_pcache;

/// The segment index of a byte offset into ps.
static inline int rs_pcache_seg(int off)
{
    return off / (int)sizeof(rs_pseg);
}

/// Segment k's bounding box (xmin, xmax, ymin, ymax), grown by the query's tolerance:
/// the box of its record.
void rs_pcache_box(const rs_pcache *pc, int k, double box[4]);
/// Vertex j's record, made from the profile (what the stored form keeps in pv[j]).
void rs_pcache_vertex(const rs_pcache *pc, int j, rs_pvert *v);
/// Segment k's record from its vertices' records v0 (vertex k) and v1 (vertex k + 1, or
/// 0 when the profile closes there): what the stored form keeps in ps[k].
void rs_pcache_segment(const rs_pcache *pc, int k, const rs_pvert *v0, const rs_pvert *v1,
                       rs_pseg *q);

/// Builds the query data of an analytic surface's profile (one malloc'ed block), compact
/// when the profile has more than RS_PC_LARGE segments.
int rs_pcache_build(const rs_surface *s, rs_pcache **out, rs_error *err);
/// The same in the form asked for (compact != 0: no stored records, the tree).
int rs_pcache_build_as(const rs_surface *s, int compact, rs_pcache **out, rs_error *err);

/// One contact in the profile plane.
typedef struct rs_hit2 {
    int feature;  ///< RS_FEATURE(type, index)
    double x[2];  ///< closest point
    double n[2];  ///< unit normal toward the point's side (one side: the outward normal)
    double dist;  ///< signed distance along n (SIDES=2: >= 0)
    double kappa; ///< profile curvature, > 0 convex toward the point; 0 at vertices
} rs_hit2;

/// Scratch for rs_pcache_hits, sized by the profile: its every segment in the stored
/// form; in the compact form RS_PSCRATCH_CAP at first, grown (rs_pscratch_grow) when
/// more segments come within a point's reach. Stack storage covers small profiles.
#define RS_PSCRATCH_CAP 4096
typedef struct rs_pscratch {
    int cap;              ///< near segments it holds
    int full;             ///< the last walk met more than cap
    int *near;            ///< nseg: the segments within reach, in profile order
    unsigned char *state; ///< nseg: per near entry, hit / drop flags
    rs_hit2 *cand;        ///< nseg: per near entry, its candidate contact
    rs_hit2 *hits;        ///< nseg + nvert
    void *heap;
} rs_pscratch;

int rs_pscratch_init(rs_pscratch *sc, const rs_pcache *pc, void *stack, size_t stack_bytes);
/// A larger scratch (4 times, at most every segment) on the heap; RS_ERR_NOMEM leaves sc.
int rs_pscratch_grow(rs_pscratch *sc, const rs_pcache *pc);
void rs_pscratch_free(rs_pscratch *sc);
/// Bytes of scratch a profile needs.
size_t rs_pscratch_bytes(const rs_pcache *pc);

/// Candidate contact of CIRCL or PARAB segment q at point (px, py), before the side and
/// distance filters: 1 when the segment owns the point (curves.c).
int rs_pseg_curve(const rs_pcache *pc, const rs_pseg *q, double px, double py, rs_hit2 *h);

/// Whether LINE segment k's face is among the contacts rs_pcache_hits gives point
/// (px, py) for [dlo, dhi] (owned, within reach and range, not dropped by the Voronoi
/// pass behind a one-sided face), without the walk over the other segments: 1 with its
/// contact in *h, as rs_pcache_hits writes it; 0 when it is not; -1 when this does not
/// tell (a curve, the compact form).
int rs_pcache_face(const rs_pcache *pc, int k, double px, double py, double dlo, double dhi,
                   rs_hit2 *h);
/// Contacts of point (px, py) whose distance lies in [dlo, dhi] (dhi = gap_max + radius,
/// dlo = dist_min), in profile order (vertex k before segment k). Returns the count;
/// the hits are in sc->hits. -1: out of memory for a larger scratch.
int rs_pcache_hits(const rs_pcache *pc, double px, double py, double dlo, double dhi,
                   rs_pscratch *sc);

/// Points of a block in the profile plane (SoA).
typedef struct rs_ppoints {
    int n;
    const double *u, *v; ///< profile-plane coordinates
    const double *dhi;   ///< per point: gap_max + radius; NaN skips the point
    double dlo;          ///< dist_min
    int base;            ///< index of point 0 in the query block (for out->point)
} rs_ppoints;

/// The contacts of points [i, pts->n), as rs_pcache_hits finds them, appended to out in
/// profile-plane form: xm[0..1] the closest point, nrm[0..1] the normal, dist, curv[0]
/// the profile curvature, feature and point (base + index); the other arrays are left
/// for the caller. Returns pts->n when done; it stops before a point for which out may
/// lack room, returning that point's index with *need set to the room it asks for, or
/// to -1 when the scratch could not grow (out of memory).
int rs_pcache_points(const rs_pcache *pc, const rs_ppoints *pts, int i, rs_contacts *out,
                     rs_pscratch *sc, int *need);

/* The frame F = {A, EX, EY, EZ} (12 numbers: local origin and axes) of s under pose
 * (NULL: the reference configuration), as the analytic query (query.c) and
 * rs_line_revolution_faces (line_revolution.c) compute it. */
void rs_analytic_frame(const rs_surface *s, const rs_pose *pose, double F[12]);

#endif
