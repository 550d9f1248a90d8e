/* Small vector helpers and a surface-parsing helper shared by the unit tests. They are
 * written out here, apart from the library, so tests do not check the library with its
 * own arithmetic. */
#ifndef RS_TEST_GEOM_H
#define RS_TEST_GEOM_H

#include "rigidsurf/surface.h"

#include <math.h>
#include <stdio.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

static inline double dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline void cross(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

/// Scales v to unit length.
static inline void unit(double v[3])
{
    double l = sqrt(dot(v, v));
    v[0] /= l;
    v[1] /= l;
    v[2] /= l;
}

/// Parses the first surface of txt; prints the error message on failure.
static inline int parse(const char *txt, rs_surface *s)
{
    rs_error e;
    int rc = rs_surface_parse(txt, "test", NULL, s, &e);
    if (rc)
        fprintf(stderr, "parse: %s\n", e.msg);
    return rc;
}

#endif
