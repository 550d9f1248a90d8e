/* Vector helpers beyond include/rigidsurf/vec.h and a surface-parsing helper shared by
 * the unit tests. */
#ifndef RS_TEST_GEOM_H
#define RS_TEST_GEOM_H

#include "rigidsurf/surface.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/// Scales v to unit length.
static inline void unit(double v[3])
{
    double l = rs_norm3(v);
    v[0] /= l;
    v[1] /= l;
    v[2] /= l;
}

/// q = (a, b, c, d) / |(a, b, c, d)|: a unit quaternion (w, x, y, z).
static inline void unit_quat(double a, double b, double c, double d, double q[4])
{
    const double n = sqrt(a * a + b * b + c * c + d * d);
    q[0] = a / n, q[1] = b / n, q[2] = c / n, q[3] = d / n;
}

/// An ellipsoid of semi-axes D turned by R (row-major, body to world): v = R D^2 R^T ez,
/// so its lowest point along z is the centre less v / h, and h = sqrt(v_z), returned, is
/// the centre's height above that point.
static inline double ellipsoid_low(const double R[9], const double D[3], double v[3])
{
    for (int i = 0; i < 3; i++) {
        v[i] = 0.0;
        for (int j = 0; j < 3; j++)
            v[i] += R[3 * i + j] * D[j] * D[j] * R[6 + j];
    }
    return sqrt(v[2]);
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

/// A UV sphere of radius rad as a MESH seen from inside (nlat bands, nlon sectors; the
/// quads planar, split into two triangles, the poles' fans single triangles) into s.
/// Returns 1 when made.
static inline int uv_cavity(double rad, int nlat, int nlon, rs_surface *s)
{
    double *xyz = malloc(12 * (size_t)nlat * nlon * sizeof *xyz);
    int *tri = malloc(6 * (size_t)nlat * nlon * sizeof *tri);
    int nv = 0, nt = 0;
    if (!xyz || !tri) {
        free(xyz);
        free(tri);
        return 0;
    }
    for (int i = 0; i < nlat; i++)
        for (int j = 0; j < nlon; j++) {
            int id[4];
            for (int k = 0; k < 4; k++) {
                const double th = RS_PI * (i + (k >= 2)) / nlat;
                const double ph = 2.0 * RS_PI * (j + (k == 1 || k == 2)) / nlon;
                xyz[3 * nv] = rad * sin(th) * cos(ph);
                xyz[3 * nv + 1] = rad * sin(th) * sin(ph);
                xyz[3 * nv + 2] = rad * cos(th);
                id[k] = nv++;
            }
            const int q[6] = {id[0], id[2], id[1], id[0], id[3], id[2]};
            for (int l = i > 0 ? 0 : 3; l < (i < nlat - 1 ? 6 : 3); l++)
                tri[3 * nt + l % 3] = q[l], nt += l % 3 == 2;
        }
    const rs_mesh_def def = RS_MESH_DEF_INIT;
    const int rc = rs_surface_make_mesh(xyz, nv, tri, nt, &def, s, NULL);
    free(xyz);
    free(tri);
    return rc == RS_OK;
}

#endif
