/* rigidsurf: the face contacts of spheres on a revolved LINE (a cylinder's mantle, a
 * cone, a flat annulus), one sphere at a time, without the block query's columns: the
 * numbers of rs_surface_query for the spheres whose only contact is the face, and a flag
 * for every other sphere, which the block query then takes. */
#ifndef RIGIDSURF_LINE_REVOLUTION_H
#define RIGIDSURF_LINE_REVOLUTION_H

#include "rigidsurf/surface.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Whether s is a REVOLUTION whose profile is one LINE, with its query data stored
/// (rs_line_revolution_faces applies).
int rs_line_revolution(const rs_surface *s);

/// For m spheres (centres x, y, z, radii radius) on a surface of rs_line_revolution
/// under pose (NULL: the reference configuration), sphere j's face contact as
/// rs_surface_query gives it with gap_max and any dist_min <= -(the largest radius of the
/// m spheres), bit for bit, at index j of c: point j, the face's feature, its master
/// point, principal frame (rs_frame_orient then gives the kind's convention, as in
/// rs_surface_query), distance and curvatures, share 1; face[j] = 1. face[j] = 0 for a
/// sphere whose contacts that query decides otherwise: none within reach, a vertex's, one
/// deeper than that dist_min, or the ring sectors of a sphere within reach of the axis.
/// c's columns (xm, nrm, t1, t2, dist, curv, share, point, feature) must hold m; c->n is
/// set to m, c->shared and c->witness to 0. With c->xm, c->curv and c->share NULL the
/// master points, curvatures and shares are left out (the frame, distance, point and
/// feature are all a law's fused kernel reads, rs_track_fused_usual). Internal to the
/// library: the wall's line path (src/wall/wall_line.c) calls it.
void rs_line_revolution_faces(const rs_surface *s, const rs_pose *pose, int m,
                              const double *x, const double *y, const double *z,
                              const double *radius, double gap_max, rs_contacts *c,
                              int *face);

/// The frame of s under pose that rs_line_revolution_faces_in takes (12 doubles).
void rs_line_revolution_frame(const rs_surface *s, const rs_pose *pose, double F[12]);

/// rs_line_revolution_faces with s's frame F under the pose (rs_line_revolution_frame)
/// given: what a caller of many runs under one pose (the wall's line path, whose pose is
/// the step's) computes once.
void rs_line_revolution_faces_in(const rs_surface *s, const double F[12], int m,
                                 const double *x, const double *y, const double *z,
                                 const double *radius, double gap_max, rs_contacts *c,
                                 int *face);

#ifdef __cplusplus
}
#endif
#endif
