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

/// What the test of quad zone z (quad set, made on triangle t and its coplanar neighbour
/// z->t2 across slot jd) compares at p, each side once, by the records' own expressions
/// (tri_bound's and side_of's): the diagonal's side sdd, whether the query gives p the
/// face of t (in0: t strictly inside the diagonal, or on it where t is its first face;
/// across a FLAT edge the second face's side is exactly the first's negated, else of t2),
/// p's height h over that triangle and its sides s of the quad's four outer edges.
typedef struct rs_mzone_at {
    double sdd, h, s[4];
    int in0;
} rs_mzone_at;

static inline void rs_mzone_quad_at(const rs_mesh *m, const rs_mzone *z, int t,
                                    const double p[3], rs_mzone_at *a)
{
    const int t2 = z->t2;
    a->sdd = side_of(m, t, z->jd, p);
    a->in0 = a->sdd > 0.0 || (a->sdd == 0.0 && z->first);
    a->h = plane_height(m, a->in0 ? t : t2, p);
    a->s[0] = side_of(m, t, z->slot[0], p);
    a->s[1] = side_of(m, t, z->slot[1], p);
    a->s[2] = side_of(m, t2, z->slot[2], p);
    a->s[3] = side_of(m, t2, z->slot[3], p);
}

/// Does quad zone z hold the point of a (rs_mzone_quad_at), where no other feature gives
/// a contact within lim?
static inline int rs_mzone_quad_holds(const rs_mzone *z, const rs_mzone_at *a, double lim)
{
    const double ah = fabs(a->h), eps = z->eps;
    return (ah <= z->hmax) & (ah >= eps) & (lim < z->clear[a->h < 0.0]) &
           (a->s[0] >= eps + (double)z->kappa[0] * ah) &
           (a->s[1] >= eps + (double)z->kappa[1] * ah) &
           (a->s[2] >= eps + (double)z->kappa[2] * ah) &
           (a->s[3] >= eps + (double)z->kappa[3] * ah);
}

/// The triangle of the quad of zone z (quad set, made on triangle t and its coplanar
/// neighbour across slot jd) whose face the query gives p, where z holds p and no other
/// feature gives a contact within lim, with p's height over it in *h; -1 where z does not
/// hold p (rs_mzone_quad_at, rs_mzone_quad_holds).
static inline int rs_mzone_quad_face(const rs_mesh *m, const rs_mzone *z, int t,
                                     const double p[3], double lim, double *h)
{
    rs_mzone_at a;
    rs_mzone_quad_at(m, z, t, p, &a);
    *h = a.h;
    return rs_mzone_quad_holds(z, &a, lim) ? (a.in0 ? t : z->t2) : -1;
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
