/* Rigid poses, x = R X + T (motion.h): the maps between a master's reference
 * configuration and the world, which the geometry's queries and the core's motion share. */
#include "rigidsurf/motion.h"

#include <string.h>

void rs_pose_identity(rs_pose *p)
{
    memset(p, 0, sizeof *p);
    p->R[0] = p->R[4] = p->R[8] = 1.0;
}

void rs_pose_to_global(const rs_pose *p, const double X[3], double x[3])
{
    double r[3];
    rs_pose_rotate(p, X, r);
    x[0] = r[0] + p->T[0];
    x[1] = r[1] + p->T[1];
    x[2] = r[2] + p->T[2];
}

void rs_pose_to_local(const rs_pose *p, const double x[3], double X[3])
{
    double d[3] = {x[0] - p->T[0], x[1] - p->T[1], x[2] - p->T[2]};
    rs_pose_unrotate(p, d, X);
}

void rs_pose_rotate(const rs_pose *p, const double V[3], double v[3])
{
    const double *R = p->R;
    double a = V[0], b = V[1], c = V[2];
    v[0] = R[0] * a + R[1] * b + R[2] * c;
    v[1] = R[3] * a + R[4] * b + R[5] * c;
    v[2] = R[6] * a + R[7] * b + R[8] * c;
}

void rs_pose_unrotate(const rs_pose *p, const double v[3], double V[3])
{
    const double *R = p->R;
    double a = v[0], b = v[1], c = v[2];
    V[0] = R[0] * a + R[3] * b + R[6] * c;
    V[1] = R[1] * a + R[4] * b + R[7] * c;
    V[2] = R[2] * a + R[5] * b + R[8] * c;
}
