/* The convex hull of a point set through CGAL, behind a C interface (the polyhedral
 * convex shapes of include/rigidsurf/convex.h). C++ stays inside cgal_hull.cpp. */
#ifndef RS_CGAL_HULL_H
#define RS_CGAL_HULL_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/// The convex hull of the n points xyz (3 * n) with exact predicates (CGAL's
/// convex_hull_3 on the Epick kernel): its *nv vertices (*verts, 3 * nv, the extreme
/// points, sorted by x, then y, then z) and *nt triangles (*tris, 3 * nt indices into
/// verts, counter-clockwise seen from outside, so the right-hand normal points out; each
/// facet a fan from its least vertex, the triangles sorted): the same for the same points
/// in any order. Arrays are malloc'ed; the caller frees them. Returns 0, or -1 with a
/// one-line reason in msg: fewer than four points that are not coplanar (to the exact
/// tests, or to the hull's constructions in double precision), a non-finite coordinate,
/// or memory (nothing is left allocated).
int rs_cgal_convex_hull(const double *xyz, int n, double **verts, int *nv, int **tris,
                        int *nt, char *msg, size_t cap);

#ifdef __cplusplus
}
#endif
#endif
