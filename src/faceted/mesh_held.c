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
    /* the zone's limit fmax(gap_lim, -dist_min), without a call: a NaN is ignored */
    const double deep = -dist_min;
    const int no_deep = deep != deep;
    /* the columns, read once: the stores below cannot move them */
    int *restrict const point = c->point, *restrict const feature = c->feature;
    double *restrict const dist = c->dist;
    double *restrict const n0 = c->nrm[0], *restrict const n1 = c->nrm[1],
                           *restrict const n2 = c->nrm[2];
    double *restrict const xm0 = c->xm[0], *restrict const xm1 = c->xm[1],
                           *restrict const xm2 = c->xm[2];
    double *restrict const k0 = c->curv[0], *restrict const k1 = c->curv[1];
    double *restrict const share = c->share;
    for (int j = 0; j < m; j++) {
        const double r = radius[j];
        const double gap_lim = gap_max + r;
        double p[3], h = 0.0, xl[3] = {0.0, 0.0, 0.0}, nl[3] = {0.0, 0.0, 1.0};
        slave_local(&q, moved, j, p);
        const double lim = no_deep || gap_lim > deep ? gap_lim : deep;
        const int t = rs_mesh_zone_face(msh, p, held[j], lim, &h);
        double d = INFINITY;
        if (t >= 0)
            d = face_contact(msh, t, one_sided, p, h, xl, nl);
        const int ok = t >= 0 && d <= gap_lim && d >= -r;
        face[j] = ok;
        point[j] = j;
        if (!ok) { /* a unit normal, so that the frame stays finite */
            feature[j] = RS_FEATURE_NONE;
            dist[j] = INFINITY;
            n0[j] = n1[j] = 0.0;
            n2[j] = 1.0;
            if (xm0)
                xm0[j] = xm1[j] = xm2[j] = 0.0;
        } else {
            double xw[3], nw[3];
            if (moved) { /* x = R X + T */
                rs_matvec3(moved->R, xl, xw);
                rs_matvec3(moved->R, nl, nw);
                for (int e = 0; e < 3; e++)
                    xw[e] += moved->T[e];
            } else {
                for (int e = 0; e < 3; e++) {
                    xw[e] = xl[e];
                    nw[e] = nl[e];
                }
            }
            feature[j] = RS_FEATURE(RS_FEAT_FACE, msh->rec[t].el);
            dist[j] = d;
            n0[j] = nw[0], n1[j] = nw[1], n2[j] = nw[2];
            if (xm0)
                xm0[j] = xw[0], xm1[j] = xw[1], xm2[j] = xw[2];
        }
        if (k0)
            k0[j] = k1[j] = 0.0;
        if (share)
            share[j] = 1.0;
    }
    c->n = m;
    c->shared = 0;
    c->witness = 0;
}
