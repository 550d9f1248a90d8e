/* The convex pair query's private parts: a convex object in the world (a body's core or
 * a triangle) and GJK's distance between two of them. */
#ifndef RS_GJK_H
#define RS_GJK_H

#include "convex_internal.h"

/// A convex object in the world: a body's core (shape less its rounding, posed by R
/// and x) or, when shape is NULL, the triangle tri (9 world values).
typedef struct rs_cvx {
    const rs_shape *shape;
    double R[9];       ///< body rotation, row-major
    double x[3];       ///< body origin (centre of mass), or the triangle's centroid
    const double *tri; ///< the triangle's corners when shape is NULL
    double radius;     ///< the rounding around the core
    double size;       ///< a bound of the core's distance from x (the query's scale)
    int solid;         ///< 1 when the core has volume (not a point, segment or triangle)
} rs_cvx;

/// The core's support along the world direction d (any non-zero length), world point.
void rs_cvx_support(const rs_cvx *c, const double d[3], double out[3]);

/// GJK's answer for two cores.
typedef struct rs_gjk {
    int apart;           ///< 1: the distance exceeds stop (only bound is known)
    int overlap;         ///< 1: the cores overlap (or touch to rounding)
    double dist;         ///< the distance (apart: a lower bound of it)
    double pa[3], pb[3]; ///< the closest points of a's and b's cores (not when overlap)
} rs_gjk;

/// The distance of the cores a and b by GJK (Gilbert, Johnson and Keerthi, 1988, with
/// the closest point of each simplex by Voronoi regions), stopping once it is known to
/// exceed stop.
void rs_gjk_distance(const rs_cvx *a, const rs_cvx *b, double stop, rs_gjk *res);

#endif
