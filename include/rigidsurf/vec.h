/* rigidsurf: small 3-vector operations and constants shared by every layer.
 * Vectors are double[3]; matrices are row-major double[9]. Header-only. */
#ifndef RIGIDSURF_VEC_H
#define RIGIDSURF_VEC_H

#include <math.h>

#ifdef __cplusplus
extern "C" {
#endif

/// pi to double precision.
#define RS_PI 3.14159265358979323846

/// a . b
static inline double rs_dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// c = a x b (c may not alias a or b).
static inline void rs_cross3(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

/// |v|
static inline double rs_norm3(const double v[3])
{
    return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

/// r = Q v for a row-major 3 x 3 matrix Q (r may not alias v).
static inline void rs_matvec3(const double Q[9], const double v[3], double r[3])
{
    r[0] = Q[0] * v[0] + Q[1] * v[1] + Q[2] * v[2];
    r[1] = Q[3] * v[0] + Q[4] * v[1] + Q[5] * v[2];
    r[2] = Q[6] * v[0] + Q[7] * v[1] + Q[8] * v[2];
}

/// The rotation R(q) (row-major, x_world = R x_body) of the unit quaternion q = (w, x,
/// y, z).
static inline void rs_quat_matrix(const double q[4], double R[9])
{
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    R[0] = 1.0 - 2.0 * (y * y + z * z);
    R[1] = 2.0 * (x * y - w * z);
    R[2] = 2.0 * (x * z + w * y);
    R[3] = 2.0 * (x * y + w * z);
    R[4] = 1.0 - 2.0 * (x * x + z * z);
    R[5] = 2.0 * (y * z - w * x);
    R[6] = 2.0 * (x * z - w * y);
    R[7] = 2.0 * (y * z + w * x);
    R[8] = 1.0 - 2.0 * (x * x + y * y);
}

#ifdef __cplusplus
}
#endif
#endif
