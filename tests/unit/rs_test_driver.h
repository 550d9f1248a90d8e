/* The standalone driver on the plane z = 0 with the linear law hooke, as the unit tests of
 * bodies in the driver set it up. */
#ifndef RS_TEST_DRIVER_H
#define RS_TEST_DRIVER_H

#include "rigidsurf/driver.h"

#include <stdio.h>

/// The plane z = 0, normal +z (a CYLINDER whose profile is one LINE).
static const char *const RS_TEST_PLANE = "*SURFACE, TYPE=CYLINDER, NAME=floor\n"
                                         "0, 0, 0, 1, 0, 0\n0, -1, 0\nSTART, -100, 0\n"
                                         "LINE, 100, 0\n";

/// One driver on the plane with n nodes, hooke (kn, kt, zeta_n, zeta_t, mu), time step dt
/// and a tracking thickness of 1 mm; 0 (and a message) when a call fails.
static inline int rs_test_driver_on_plane(rs_driver *d, rs_surface *s, int n,
                                          const double hooke[5], double dt)
{
    rs_error e;
    rs_error_clear(&e);
    if (rs_surface_parse(RS_TEST_PLANE, "plane", NULL, s, &e) != RS_OK ||
        rs_driver_init(d, s, n, &e) != RS_OK ||
        rs_driver_set_law(d, rs_law_find("hooke"), hooke, 5, 2, &e) != RS_OK) {
        fprintf(stderr, "setup: %s\n", e.msg);
        return 0;
    }
    d->dt = dt;
    d->tracking = 1e-3;
    return 1;
}

#endif
