/* rigidsurf (private): a LINE face of an extruded profile (CYLINDER, SEGMENTS) set up once
 * for the points of a query in one pose (a face kit): the segment's record, the frame of
 * the pose (rs_analytic_frame) and the face's normal and tangents in the world, made as
 * rs_analytic_closest makes them. A point's contact on the face (rs_flat_face_at) is then
 * that of face_at and rs_pcache_face, bit for bit, at a fraction of their cost: the
 * profile's ownership rules and window as rs_pcache_face applies them, the mapping back
 * as map_extrusion does it. Behind a one-sided face whose vertex is CONVEX (where the
 * profile's Voronoi pass may drop the face) the kit does not tell. */
#ifndef RS_FLAT_FACE_H
#define RS_FLAT_FACE_H

#include "profile.h"
#include "revolution_point.h"

typedef struct rs_flat_face {
    const rs_pseg *q;  ///< the LINE's record
    int k;             ///< its segment index
    int two;           ///< SIDES=2
    int drop;          ///< one side, a CONVEX end vertex: penetrations are not told
    int bounded;       ///< a CYLINDER's EXTENT
    double zmin, zmax; ///< its range along the generator
    double F[12];      ///< the frame in the pose (rs_analytic_frame)
    double n[2][3];    ///< the world normal, in front (0) and flipped behind (1, SIDES=2)
    double t1[2][3];   ///< likewise t1 (n_y EX - n_x EY)
    double t2[3];      ///< -EZ
} rs_flat_face;

/// Sets kit up for LINE k of s (a CYLINDER or SEGMENTS surface in its stored form) with
/// the frame F of its pose (rs_analytic_frame); 0 where k is not such a face (a curve, the
/// compact form), else 1.
int rs_flat_face_init(rs_flat_face *kit, const rs_surface *s, const double F[12], int k);

/// The contact of point p on the kit's face within [dlo, dhi], as face_at makes it: 1 with
/// its distance, closest point xm, normal n and frame (t1, t2: where not NULL), 0 where
/// the face does not own the point in the window, -1 where the kit does not tell (ask
/// face_at).
static inline int rs_flat_face_at(const rs_flat_face *restrict kit, const double p[3],
                                  double dlo, double dhi, double *dist, double *restrict xm,
                                  double *restrict n, double *restrict t1,
                                  double *restrict t2)
{
    const double *restrict F = kit->F;
    const double wx = p[0] - F[F_A], wy = p[1] - F[F_A + 1], wz = p[2] - F[F_A + 2];
    const double u = wx * F[F_X] + wy * F[F_X + 1] + wz * F[F_X + 2];
    const double v = wx * F[F_Y] + wy * F[F_Y + 1] + wz * F[F_Y + 2];
    const double lz = wx * F[F_Z] + wy * F[F_Z + 1] + wz * F[F_Z + 2];
    if (kit->bounded && !(lz >= kit->zmin && lz <= kit->zmax))
        return 0;
    double d, hx, hy;
    int flip;
    if (!rs_pseg_line_face(kit->q, kit->two, u, v, dlo, dhi, &d, &flip, &hx, &hy))
        return 0;
    if (kit->drop && d < 0.0)
        return -1;
    *dist = d;
    for (int j = 0; j < 3; j++)
        xm[j] = F[F_A + j] + hx * F[F_X + j] + hy * F[F_Y + j] + lz * F[F_Z + j];
    /* (each part by itself: no call to copy three numbers) */
    const double *kn = kit->n[flip];
    n[0] = kn[0], n[1] = kn[1], n[2] = kn[2];
    if (t1 && t2) {
        const double *k1 = kit->t1[flip];
        t1[0] = k1[0], t1[1] = k1[1], t1[2] = k1[2];
        t2[0] = kit->t2[0], t2[1] = kit->t2[1], t2[2] = kit->t2[2];
    }
    return 1;
}

#endif
