/* rigidsurf: the face contacts of spheres held on a MESH's faces, one sphere at a time,
 * without the block query's columns: where a sphere lies in the clear zone of the face it
 * holds (mesh_zone.h), the numbers of rs_surface_query with that face as its hint, and a
 * flag for every other sphere, which the block query then takes. Internal to the library:
 * the wall's line path (src/wall/wall_line.c) calls it. */
#ifndef RIGIDSURF_MESH_HELD_H
#define RIGIDSURF_MESH_HELD_H

#include "rigidsurf/surface.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Whether s is a MESH whose faces have clear zones (rs_mesh_held_faces applies).
int rs_mesh_held(const rs_surface *s);

/// What a sphere's test in a face's clear zone leaves for the next step's
/// (rs_mesh_held_balls): a ball about a point of the reference configuration within which
/// every point passes the zone's test for face feature `face` as that point did, with the
/// same triangle, whichever sphere asks (only the limit on the other features' contacts,
/// which comes with the sphere, is compared again, with the zone's clear distance on the
/// ball's side). A fact about the mesh alone, so that a ball left by another particle, or
/// from another step, is as true as one's own. 40 bytes.
typedef struct rs_mesh_held_ball {
    double x[3]; ///< the centre
    float reach; ///< the radius (> 0)
    float clear; ///< the zone's clear distance on the ball's side, rounded down
    int face;    ///< the face feature, -1: no ball
    int tri;     ///< the triangle whose face the zone gives within the ball
} rs_mesh_held_ball;

/// For m spheres (centres x, y, z, radii radius) on a surface of rs_mesh_held under pose
/// (NULL: the reference configuration), each holding the feature held[j]: where held[j] is
/// a face and the sphere lies in the clear zone of one of its triangles for the limit
/// max(gap_max + radius[j], -dist_min), its one contact as rs_surface_query gives it with
/// gap_max, hint held[j] and any depth limit from dist_min to -radius[j], value for value,
/// at index j of c: point j, the feature of the face the zone gives (the held face, or the
/// coplanar one across the diagonal of the planar quad its zone covers, where the sphere's
/// foot lies there), its master point, normal (rs_frame_orient
/// then gives t1 and t2 by the FACETED convention, as in rs_surface_query), distance,
/// curvatures 0 and share 1; face[j] = 1. face[j] = 0 for every other sphere: a hint that
/// is no face, a point outside the zones (the query's candidates decide), a contact beyond
/// gap_max or deeper than -radius[j]. c's columns (xm, nrm, t1, t2, dist, curv, share,
/// point, feature) must hold m; c->n is set to m, c->shared and c->witness to 0. With
/// c->xm, c->curv and c->share NULL the master points, curvatures and shares are left out
/// (the frame, distance, point and feature are all a law's fused kernel reads,
/// rs_track_fused_usual).
void rs_mesh_held_faces(const rs_surface *s, const rs_pose *pose, int m, const double *x,
                        const double *y, const double *z, const double *radius,
                        const int *held, double gap_max, double dist_min, rs_contacts *c,
                        int *face);

/// rs_mesh_held_faces with a ball for each sphere, sphere j's at balls[row[j]] (face -1
/// before a first call): where the sphere lies within its ball for the face it holds, the
/// zone's test is that ball's (only the limit on the other features' contacts is tested
/// again); where it passes the test of a quad's zone or a one-triangle face's, its ball is
/// made anew; else it is left as it was. The numbers are rs_mesh_held_faces's.
void rs_mesh_held_balls(const rs_surface *s, const rs_pose *pose, int m, const double *x,
                        const double *y, const double *z, const double *radius,
                        const int *held, double gap_max, double dist_min,
                        rs_mesh_held_ball *balls, const int *row, rs_contacts *c,
                        int *face);

#ifdef __cplusplus
}
#endif
#endif
