/* The unit tests' bodies of every kind (the seven built-in shapes and two hulls of points
 * on an ellipsoid, one scanned for its support (64 points) and one climbed (1500), from
 * the test's random stream, rs_test.h) and the check that two paths give a block of them
 * the same contacts, bit for bit. */
#ifndef RS_TEST_BODIES_H
#define RS_TEST_BODIES_H

#include "rigidsurf/convex.h"
#include "rigidsurf/vec.h"
#include "rs_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

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

static inline int test_same_bits(double a, double b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

/* Two contact lists alike in every field, bit for bit. */
static inline void test_same_contacts(const rs_contacts *ca, const rs_contacts *cb)
{
    ENSURE(ca->n == cb->n);
    for (int j = 0; j < ca->n && j < cb->n; j++) {
        ENSURE(ca->point[j] == cb->point[j] && ca->feature[j] == cb->feature[j]);
        ENSURE(test_same_bits(ca->dist[j], cb->dist[j]));
        ENSURE(test_same_bits(ca->share[j], cb->share[j]));
        for (int d = 0; d < 3; d++) {
            ENSURE(test_same_bits(ca->nrm[d][j], cb->nrm[d][j]));
            ENSURE(test_same_bits(ca->xm[d][j], cb->xm[d][j]));
            ENSURE(test_same_bits(ca->xs[d][j], cb->xs[d][j]));
            ENSURE(test_same_bits(ca->t1[d][j], cb->t1[d][j]));
            ENSURE(test_same_bits(ca->t2[d][j], cb->t2[d][j]));
        }
        ENSURE(test_same_bits(ca->curv[0][j], cb->curv[0][j]));
        ENSURE(test_same_bits(ca->curv[1][j], cb->curv[1][j]));
    }
}

#endif
