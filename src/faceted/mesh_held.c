/* The face contacts of spheres held on a MESH's faces (mesh_held.h): the hinted query's
 * own steps (slave_local, rs_mesh_zone_face, face_contact and the pose's mapping back, as
 * rs_mesh_closest_among takes them), one sphere at a time, so that the numbers are the
 * query's bit for bit. */
#include "mesh_held.h"

#include "mesh.h"
#include "mesh_regions.h"
#include "mesh_zone.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <string.h>

int rs_mesh_held(const rs_surface *s)
{
    const rs_mesh *m = s && s->ops == &rs_mesh_ops ? s->impl : NULL;
    return m && m->zone;
}

void rs_mesh_held_faces(const rs_surface *s, const rs_pose *pose, int m, const double *x,
                        const double *y, const double *z, const double *radius,
                        const int *held, double gap_max, double dist_min, rs_contacts *c,
                        int *face)
{
    const rs_mesh *msh = s->impl;
    rs_query q;
    memset(&q, 0, sizeof q);
    q.n = m;
    q.slave.x = x, q.slave.y = y, q.slave.z = z;
    q.pose = pose;
    const rs_pose *moved = moved_pose(&q);
    const int one_sided = s->sides != 2;
    for (int j = 0; j < m; j++) {
        const double r = radius[j];
        const double gap_lim = gap_max + r;
        double p[3], h = 0.0, xl[3] = {0.0, 0.0, 0.0}, nl[3] = {0.0, 0.0, 1.0};
        slave_local(&q, moved, j, p);
        const int t = rs_mesh_zone_face(msh, p, held[j], fmax(gap_lim, -dist_min), &h);
        double dist = INFINITY;
        if (t >= 0)
            dist = face_contact(msh, t, one_sided, p, h, xl, nl);
        face[j] = t >= 0 && dist <= gap_lim && dist >= -r;
        c->point[j] = j;
        if (!face[j]) { /* a unit normal, so that the frame stays finite */
            c->feature[j] = RS_FEATURE_NONE;
            c->dist[j] = INFINITY;
            c->nrm[0][j] = c->nrm[1][j] = 0.0;
            c->nrm[2][j] = 1.0;
            if (c->xm[0])
                c->xm[0][j] = c->xm[1][j] = c->xm[2][j] = 0.0;
        } else {
            double xm[3], n[3];
            if (moved) { /* x = R X + T */
                rs_matvec3(moved->R, xl, xm);
                rs_matvec3(moved->R, nl, n);
                for (int d = 0; d < 3; d++)
                    xm[d] += moved->T[d];
            } else {
                for (int d = 0; d < 3; d++) {
                    xm[d] = xl[d];
                    n[d] = nl[d];
                }
            }
            c->feature[j] = RS_FEATURE(RS_FEAT_FACE, msh->rec[t].el);
            c->dist[j] = dist;
            for (int d = 0; d < 3; d++) {
                c->nrm[d][j] = n[d];
                if (c->xm[0])
                    c->xm[d][j] = xm[d];
            }
        }
        if (c->curv[0])
            c->curv[0][j] = c->curv[1][j] = 0.0;
        if (c->share)
            c->share[j] = 1.0;
    }
    c->n = m;
    c->shared = 0;
    c->witness = 0;
}
