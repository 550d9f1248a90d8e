/* The unit tests' bodies of every kind: the seven built-in shapes and two hulls of points
 * on an ellipsoid, one scanned for its support (64 points) and one climbed (1500), from
 * the test's random stream (rs_test.h). */
#ifndef RS_TEST_SHAPES_H
#define RS_TEST_SHAPES_H

#include "rigidsurf/convex.h"
#include "rigidsurf/vec.h"
#include "rs_test.h"

#include <math.h>
#include <stdlib.h>

enum { TEST_NSHAPE = 9, TEST_HULL64 = 7, TEST_HULL1500 = 8 };

static inline int test_make_shape(int k, rs_shape *s)
{
    switch (k) {
    case 0:
        return rs_shape_make_sphere(s, 0.005, 0.0, NULL);
    case 1:
        return rs_shape_make_ellipsoid(s, 0.006, 0.004, 0.003, 0.0, NULL);
    case 2:
        return rs_shape_make_box(s, 0.005, 0.004, 0.003, 0.0, NULL);
    case 3:
        return rs_shape_make_box(s, 0.004, 0.003, 0.002, 0.001, NULL);
    case 4:
        return rs_shape_make_capsule(s, 0.003, 0.003, 0.0, NULL);
    case 5:
        return rs_shape_make_cylinder(s, 0.004, 0.004, 0.0, NULL);
    case 6:
        return rs_shape_make_cone(s, 0.004, 0.008, 0.0, NULL);
    default: {
        const int np = k == TEST_HULL64 ? 64 : 1500;
        double *xyz = malloc(3 * (size_t)np * sizeof *xyz);
        if (!xyz)
            return RS_ERR_NOMEM;
        for (int i = 0; i < np; i++) {
            const double z = urange(-1, 1), ph = urange(0, 2 * RS_PI), r = sqrt(1 - z * z);
            xyz[3 * i] = 0.005 * r * cos(ph);
            xyz[3 * i + 1] = 0.004 * r * sin(ph);
            xyz[3 * i + 2] = 0.003 * z;
        }
        const int rc =
            rs_shape_make_polyhedron(s, xyz, np, k == TEST_HULL1500 ? 5e-4 : 0.0, NULL);
        free(xyz);
        return rc;
    }
    }
}

#endif
