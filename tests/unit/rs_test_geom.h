/* Vector helpers beyond include/rigidsurf/vec.h and a surface-parsing helper shared by
 * the unit tests. */
#ifndef RS_TEST_GEOM_H
#define RS_TEST_GEOM_H

#include "rigidsurf/surface.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <stdio.h>

/// Scales v to unit length.
static inline void unit(double v[3])
{
    double l = rs_norm3(v);
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
