/* The faceted surface kind MESH (docs/conventions.md, "Faceted surfaces"): a triangle
 * mesh in the reference configuration, its topology and the ownership data of its
 * faces, edges and vertices. Private to the geometry layer. */
#ifndef RS_FACETED_MESH_H
#define RS_FACETED_MESH_H

#include "rigidsurf/surface.h"

/// Dihedral angle below which two faces are coplanar (rad).
#define RS_MESH_FLAT_ANGLE 1e-9
/// Vertices closer than this fraction of the mesh's size are welded.
#define RS_MESH_WELD_REL 1e-9
/// Most triangles a mesh may have (feature ids stay ints).
#define RS_MESH_MAX_TRI (1 << 27)

enum rs_edge_kind {
    RS_EDGE_FLAT = 0,       ///< coplanar faces: the faces tile it
    RS_EDGE_CONVEX = 1,     ///< bulges toward the particles: owns its wedge in front
    RS_EDGE_CONCAVE = 2,    ///< a groove: owns its wedge behind a one-sided mesh
    RS_EDGE_BOUNDARY = 3,   ///< one face: owns the quarter space beyond it in front
    RS_EDGE_NONMANIFOLD = 4 ///< three faces or more: owns its wedge on either side
};

/// The query's record of a triangle: all it reads of a candidate triangle, in the three
/// cache lines of one 192-byte block, so that a candidate costs three lines from memory
/// on a mesh larger than the caches. Its integers repeat tri, tedge, tel and edge_kind of
/// the mesh.
typedef struct rs_mtri {
    _Alignas(64) double n[3]; ///< unit normal
    double a0[3];             ///< the first node
    double e[3][4];           ///< per edge slot j the unit in-plane normal m_j into the
                              ///< triangle, and c_j = m_j . (the edge's lower node): p's
                              ///< side of edge j is p . m_j - c_j (across a flat edge the
                              ///< second face holds exactly -m_j, -c_j of the first)
    int v[3];                 ///< nodes (tri)
    int edge[3];              ///< the edge of each slot (tedge)
    int nbr[3];               ///< across slot j, 3 t' + j' of the other face of a two-face
                              ///< edge, -1 at open and non-manifold edges
    int el;                   ///< element (tel)
    unsigned char first;      ///< bit j when the triangle is the first face of the edge of
                              ///< slot j (edge_f[edge_f0[e]]), bit 3 + j when it is vfirst
                              ///< of its node j: the query tests each edge and vertex from
                              ///< that triangle alone
    unsigned char kind[3];    ///< the kind of each slot's edge (rs_edge_kind)
    unsigned char rough;      ///< bit j when the edge of slot j is not FLAT, bit 3 + j when
                              ///< node j is not inside a coplanar region (vflat 0): what
                              ///< may keep a ball off the face alone
} rs_mtri;
_Static_assert(sizeof(rs_mtri) == 192, "a triangle's record spans three cache lines");

/// A mesh as the query uses it. Triangles of one element (a planar quad) are
/// consecutive; a face feature's index is its element.
typedef struct rs_mesh {
    int nv, nt, ne, nel;
    double *xyz;    ///< 3 nv, reference configuration
    int *tri;       ///< 3 nt, node order gives the outward normal
    int *tel;       ///< nt: element of each triangle
    int *el_t0;     ///< nel + 1: triangles of element k are el_t0[k] .. el_t0[k+1]-1
    int *el_nodes;  ///< 4 nel: the element's nodes (a triangle repeats its first)
    int *el_nnode;  ///< nel: 3 or 4
    int el_maxnode; ///< 4 when some element is a quad, else 3
    int *el_region; ///< nel: the element's coplanar region, the least element joined to it
                    ///< through FLAT edges
    int *tedge;     ///< 3 nt: edge of each slot
    int *edge_v;    ///< 2 ne: its nodes, lower index first
    int *edge_f0;   ///< ne + 1: faces of edge e are edge_f[edge_f0[e] ..]
    int *edge_f;
    unsigned char *edge_kind; ///< rs_edge_kind
    int *vert_e0;             ///< nv + 1: vertex v's edges lead to its neighbours
    int *vert_w;              ///< vert_w[vert_e0[v] .. vert_e0[v + 1]), one per edge
    rs_mtri *rec;             ///< nt: the query's records, 64-byte aligned
    int *vfirst;              ///< nv: the lowest-numbered triangle at each vertex
    double *vpn;              ///< 3 nv: angle-weighted pseudo-normal (unit)
    int *vlabel; ///< nv: user node number of each vertex (the label of its first point
                 ///< in the file), or NULL: the vertex's index + 1
    unsigned char *vopen; ///< nv: 1 on an open boundary or non-manifold edge
    unsigned char *vconc; ///< nv: 1 at the end of a CONCAVE edge
    unsigned char *vflat; ///< nv: 1 where every edge is FLAT (inside a coplanar region:
                          ///< the faces own what projects onto the vertex)
    double lo[3], hi[3];  ///< bounds
    double size;          ///< the bounds' diagonal
    void *tree;           ///< the AABB tree (cgal_mesh.h)
    struct rs_mzone *zone; ///< nt: each face's clear zone (mesh_zone.h), made when a
                           ///< hinted query first names the face; 64-byte aligned
    void *zone_mem;        ///< the zones' allocation
} rs_mesh;

/// Builds the mesh of a polygon soup: scale and placement (rot row-major columns ex, ey,
/// ez and origin a: x = a + s (X ex + Y ey + Z ez)), welding, elements, edges, a
/// consistent orientation per connected component, edge kinds and the tree. Warnings
/// (dropped degenerate triangles, non-manifold edges, holes, no consistent orientation)
/// go to warn, the open boundary of an open surface to info (rs_mesh_boundary_report);
/// *two_sided is set where no consistent orientation exists. origin names the file in
/// messages.
struct rs_soup;
int rs_mesh_build(const struct rs_soup *soup, double scale, const double a[3],
                  const double ex[3], const double ey[3], const double ez[3],
                  const char *origin, rs_mesh **out, int *two_sided, char *warn,
                  size_t warncap, char *info, size_t infocap, rs_error *err);

/// A loop of open edges narrower than this fraction of the mesh's size (its bounds'
/// diagonal) is a hole; a wider one the rim of an open surface.
#define RS_HOLE_FRACTION 0.1
/// Appends the report of m's open boundary edges, if any: to warn when every loop of them
/// is a hole (a surface that otherwise closes: particles that fit through them leave it),
/// else to info (the rim of an open surface). Returns -1 when out of memory, else 0.
int rs_mesh_boundary_report(const rs_mesh *m, const char *origin, char *warn,
                            size_t warncap, char *info, size_t infocap);
void rs_mesh_free(rs_mesh *m);

/// The frame of a mesh's placement a, b, c (abc): frame[0] the origin a, frame[1 .. 3]
/// ex toward b, ey toward c in the a-b-c plane, ez = ex x ey; the identity when placed
/// is 0. RS_ERR_GEOMETRY prefixed by where when a, b, c span no plane.
int rs_mesh_placement(int placed, const double abc[9], const char *where,
                      double frame[4][3], rs_error *err);

/// Builds the mesh of a polygon soup (rs_mesh_build, origin naming it in messages) into
/// surface s (kind MESH, its table of operations set) with the scale and placement frame
/// of rs_mesh_placement. s->sides is the SIDES= asked for, 0 for default_sides; both
/// sides act where the facets have no consistent orientation.
struct rs_soup;
int rs_mesh_surface_soup(rs_surface *s, const struct rs_soup *soup, double scale,
                         const double frame[4][3], int default_sides, const char *origin,
                         rs_error *err);

/// Reads a mesh file into surface s (kind MESH, its table of operations set). s->sides is
/// the SIDES= asked for, 0 for the default: both sides for STL, OBJ, OFF and PLY (as
/// LIGGGHTS's mesh walls act), one side for an Abaqus rigid part (.inp, as in Abaqus).
int rs_mesh_surface_load(rs_surface *s, const char *file, double scale, int placed,
                         const double abc[9], const char *where, rs_error *err);

/// The MESH kind's table (mesh_ops.c) and the operations it lists from the other files:
/// the query (mesh_query.c), the candidate lists (mesh_candidates.c), the facets
/// (mesh_facets.c).
extern const rs_surface_ops rs_mesh_ops;
/// The MESH surface in a surface file (mesh_file.c, surface_file.h).
extern const struct rs_surface_syntax rs_mesh_syntax;
int rs_mesh_closest(const rs_surface *s, const rs_query *q, rs_contacts *out,
                    rs_error *err);
int rs_mesh_closest_among(const rs_surface *s, const rs_query *q, const int *const *cand,
                          const int *ncand, rs_contacts *out, rs_error *err);
int rs_mesh_candidates(const rs_surface *s, const rs_query *q, double extra, rs_cands *c,
                       rs_error *err);
int rs_mesh_facet(const rs_surface *s, int f, const double xm[3], int nodes[4],
                  double xyz[12], double shape[4]);
int rs_mesh_facet_size(const rs_surface *s, int *nnode);
int rs_mesh_facet_count(const rs_surface *s);
int rs_mesh_facet_area(const rs_surface *s, int k, double *area, double n[3]);
int rs_mesh_facet_index(const rs_surface *s, int f);

/// The MESH kind's body operation (rs_surface_ops.body, mesh_body_query.c).
struct rs_body;
struct rs_body_contacts;
int rs_mesh_body(const rs_surface *s, const rs_pose *pose, const struct rs_body *b, int n,
                 double gap_max, int lenient, struct rs_body_contacts *out, rs_error *err);
/// rs_mesh_body with the bodies' rotations given (rs_surface_ops.body_run).
int rs_mesh_body_run(const rs_surface *s, const rs_pose *pose, const struct rs_body *b,
                     const double *R, int n, double gap_max, int lenient,
                     struct rs_body_contacts *out, struct rs_body_work *w, rs_error *err);

/// The MESH kind's feature_point (rs_surface_ops.feature_point, mesh_body.c): a face of
/// one triangle whose triangle holds the ball's centre strictly inside its edges, in
/// front of it on a one-sided mesh: the face contact of the point query (mesh_query.c),
/// t1 and t2 (where asked) zeros: the frame follows from n.
int rs_mesh_feature_point(const rs_surface *s, const rs_pose *pose, int f,
                          const double x[3], double radius, double gap_max,
                          double depth_max, double *dist, double xm[3], double n[3],
                          double t1[3], double t2[3]);

/* What the body operation asks of a MESH s (mesh_body.c), all in the reference
 * configuration. */
/// The triangles whose tree boxes meet the box [lo, hi]: every triangle that meets it,
/// and a few more near it, into ids (room for cap). Returns their number; when it is
/// more than cap, only cap were written (ask again with room for all).
int rs_mesh_box_candidates(const rs_surface *s, const double lo[3], const double hi[3],
                           int *ids, int cap);
/// Does x, a point of t's plane, lie in triangle t (on the inner side of each of its
/// edges' planes, ties included)?
int rs_mesh_triangle_holds(const rs_surface *s, int t, const double x[3]);
/// 1 when no edge of triangle t but a FLAT one, and no vertex but one inside a coplanar
/// region, comes within r of the point c: a body within r of c meets t at its face. An
/// edge whose plane (through it, normal to t) c is clearly farther than r from needs no
/// distance, nor do its nodes.
int rs_mesh_triangle_plain(const rs_surface *s, int t, const double c[3], double r);
/// Does x, a point of t's plane, lie beyond a CONCAVE edge of t: outside its line, and
/// between the perpendiculars at its ends?
int rs_mesh_beyond_concave(const rs_surface *s, int t, const double x[3]);
/// The feature that owns the unit direction n (from the mesh toward a body) at the point
/// x of triangle t, by the point query's Voronoi rules at x + n, ties to the face: x
/// within 1e-8 of t's longest edge from an edge's plane lies on that edge. x inside t, or
/// n along t's normal, is t's face (so are a flat edge and a vertex inside a coplanar
/// region); else a vertex at x when n is inside its cone, n.(w - v) < 0 for each
/// neighbour w; else an edge at x when n.m <= 0 for each of its faces' in-plane normals m
/// and n does not point beyond an end of the edge that x is at, or its face when n is
/// that face's normal (each to 1e-12). Behind a one-sided mesh (n against the edge's or
/// vertex's pseudo-normal), and where nothing owns n, RS_FEATURE_NONE. *tri gets the
/// triangle of a face, -1 for an edge, a vertex or none.
int rs_mesh_direction_owner(const rs_surface *s, int t, const double x[3],
                            const double n[3], int *tri);
/// The coplanar regions among triangles ids[0 .. n): label[k] is the least index in ids
/// of the triangles joined to ids[k] through flat edges between triangles of the list
/// (two: one look at the first's flat edges; up to 16: each flat edge's other face
/// looked up in the list; more: in a sorted copy). scratch: room for 2 n ints.
void rs_mesh_flat_regions(const rs_surface *s, const int *ids, int n, int *label,
                          int *scratch);

#endif
