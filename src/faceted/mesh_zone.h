/* The clear zone of a triangle's face (mesh_zone.c): the points near the face that no
 * other feature of the mesh owns within a distance, so that a hinted query (mesh_query.c)
 * gives a point held on the face its one contact from the face's own record, without its
 * candidates. Private to src/faceted/. */
#ifndef RS_FACETED_MESH_ZONE_H
#define RS_FACETED_MESH_ZONE_H

#include "mesh.h"
#include "mesh_regions.h"

#include <math.h>
#include <stdatomic.h>

/// Zone states: not made yet (zeroed memory), being made, made, none (the face has no
/// zone: a sliver, a fold too sharp, no memory).
enum { RS_ZONE_UNKNOWN = 0, RS_ZONE_BUSY = 1, RS_ZONE_READY = 2, RS_ZONE_NONE = 3 };

/// Triangle t's zone: the points p at height h = (p - a0).n over its plane with eps <=
/// |h| <= hmax whose side of each edge slot j (rs_mtri.e, the query's side_of) is at least
/// eps + kappa[j] |h|. Any feature other than t's face that owns such a point, by the
/// query's own tests, lies at least clear[0] from it when h >= 0 and clear[1] when h < 0
/// (0 where a side has no zone). With quad set, the zone of the planar quad of t and the
/// triangle t2 across its FLAT slot jd (the quad's diagonal): the points whose sides of
/// its four outer edges (slot[0], slot[1] of t, slot[2], slot[3] of t2) are at least
/// eps + kappa[k] |h|, h taken over the triangle whose face the query gives them
/// (rs_mzone_quad_face); the features other than the two faces, their edges and the
/// diagonal's nodes keep clear of them so. One cache line.
typedef struct rs_mzone {
    _Alignas(64) double eps;
    double hmax;
    double clear[2];
    float kappa[4];
    _Atomic int state;
    unsigned char quad;    ///< 1: the zone of the quad of t and the triangle across jd
    unsigned char jd;      ///< the diagonal's slot in t
    unsigned char first;   ///< t is the diagonal's first face (it takes points on it)
    unsigned char slot[4]; ///< the quad's outer edges, in turn around it
    int t2;                ///< the triangle across jd (with quad set)
} rs_mzone;
_Static_assert(sizeof(rs_mzone) == 64, "a zone is one cache line");

/// Makes triangle t's zone into *z (its state left to the caller); returns 1 when the
/// face has one, 0 when it has none or memory ran out.
int rs_mesh_zone_make(const rs_mesh *m, int t, rs_mzone *z);

/// Triangle t's zone, made the first time it is asked for; NULL when the face has none,
/// or while another thread makes it.
static inline const rs_mzone *rs_mesh_zone(const rs_mesh *m, int t)
{
    rs_mzone *z = m->zone + t;
    int st = atomic_load_explicit(&z->state, memory_order_acquire);
    if (st == RS_ZONE_READY)
        return z;
    if (st != RS_ZONE_UNKNOWN)
        return NULL;
    if (!atomic_compare_exchange_strong_explicit(
            &z->state, &st, RS_ZONE_BUSY, memory_order_acq_rel, memory_order_acquire))
        return st == RS_ZONE_READY ? z : NULL;
    const int ok = rs_mesh_zone_make(m, t, z);
    atomic_store_explicit(&z->state, ok ? RS_ZONE_READY : RS_ZONE_NONE,
                          memory_order_release);
    return ok ? z : NULL;
}

/// Does the point of height h and edge sides sd (tri_bound's, of the zone's triangle) lie
/// in zone z, where no other feature gives a contact within lim?
static inline int rs_mzone_holds(const rs_mzone *z, double h, const double sd[3],
                                 double lim)
{
    const double ah = fabs(h);
    return ah <= z->hmax && ah >= z->eps && lim < z->clear[h < 0.0] &&
           sd[0] >= z->eps + (double)z->kappa[0] * ah &&
           sd[1] >= z->eps + (double)z->kappa[1] * ah &&
           sd[2] >= z->eps + (double)z->kappa[2] * ah;
}

/// The triangle of the quad of zone z (quad set, made on triangle t and its coplanar
/// neighbour across slot jd) whose face the query gives p, where z holds p and no other
/// feature gives a contact within lim, with p's height over it in *h; -1 where z does not
/// hold p. The diagonal's side decides the triangle as the query does: t strictly inside
/// it, or on it where t is its first face (across a FLAT edge the second face's side is
/// exactly the first's negated).
static inline int rs_mzone_quad_face(const rs_mesh *m, const rs_mzone *z, int t,
                                     const double p[3], double lim, double *h)
{
    /* tri_bound's and side_of's expressions of the records' numbers, each side once */
    const int t2 = z->t2;
    const double sdd = side_of(m, t, z->jd, p);
    const int in0 = sdd > 0.0 || (sdd == 0.0 && z->first);
    const double hh = plane_height(m, in0 ? t : t2, p);
    *h = hh;
    const double ah = fabs(hh), eps = z->eps;
    const double s0 = side_of(m, t, z->slot[0], p), s1 = side_of(m, t, z->slot[1], p);
    const double s2 = side_of(m, t2, z->slot[2], p), s3 = side_of(m, t2, z->slot[3], p);
    const int ok =
        (ah <= z->hmax) & (ah >= eps) & (lim < z->clear[hh < 0.0]) &
        (s0 >= eps + (double)z->kappa[0] * ah) & (s1 >= eps + (double)z->kappa[1] * ah) &
        (s2 >= eps + (double)z->kappa[2] * ah) & (s3 >= eps + (double)z->kappa[3] * ah);
    return ok ? (in0 ? t : t2) : -1;
}

/// The triangle of face feature hint (an element's face) whose clear zone holds p, where
/// no other feature gives a contact within lim, with p's height over it in *h; -1 where
/// hint names no face of m or no zone of its triangles holds p.
static inline int rs_mesh_zone_face(const rs_mesh *m, const double p[3], int hint,
                                    double lim, double *h)
{
    if (hint < 0 || RS_FEATURE_TYPE(hint) != RS_FEAT_FACE)
        return -1;
    const int el = RS_FEATURE_INDEX(hint);
    if (el >= m->nel)
        return -1;
    const int t0 = m->el_t0[el];
    const rs_mzone *z = rs_mesh_zone(m, t0);
    /* an element's first triangle may hold the zone of its quad */
    if (z && z->quad)
        return rs_mzone_quad_face(m, z, t0, p, lim, h);
    for (int t = t0; t < m->el_t0[el + 1]; t++) {
        double sd[3];
        tri_bound(m, t, p, h, sd);
        if (t > t0)
            z = rs_mesh_zone(m, t);
        if (z && rs_mzone_holds(z, *h, sd, lim))
            return t;
    }
    return -1;
}

#endif
