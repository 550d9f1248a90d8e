/* The analytic kinds' body operation (rs_surface_ops.body): the fixed point of
 * src/convex_geometry/body_fixed_point.c, each of whose iterates on a flat face of a
 * CYLINDER or SEGMENTS surface (a LINE of the profile, extruded) is measured in closed
 * form: the body's deepest point p along -n lies at the signed distance (p - p0).n from
 * the face's plane, its closest point is its foot, and the face keeps it where the
 * profile's ownership rules give it to the face (rs_pcache_face); elsewhere, and on a
 * REVOLUTION, the iterate asks the kind's point query. Both give the same contact. */
#include "convex_internal.h"
#include "profile.h"
#include "revolution_point.h"

#include <string.h>

/* A query's set-up for the iterates: the surface, its profile's data and the frame of
 * its pose (rs_analytic_frame). */
typedef struct face_ctx {
    const rs_surface *s;
    const rs_pcache *pc;
    double F[12];
} face_ctx;

/* rs_body_face_fn of an extruded profile: the contact of point p on face want, as
 * rs_analytic_closest maps it (local_extrusion, the profile's contact, map_extrusion). */
static int extruded_face(const void *ctx, int want, const double p[3], double gap,
                         rs_body_contact *o)
{
    const face_ctx *c = ctx;
    if (RS_FEATURE_TYPE(want) != RS_FEAT_FACE)
        return 0;
    const double *F = c->F;
    const double A0 = F[F_A], A1 = F[F_A + 1], A2 = F[F_A + 2];
    const double X0 = F[F_X], X1 = F[F_X + 1], X2 = F[F_X + 2];
    const double Y0 = F[F_Y], Y1 = F[F_Y + 1], Y2 = F[F_Y + 2];
    const double Z0 = F[F_Z], Z1 = F[F_Z + 1], Z2 = F[F_Z + 2];
    const double wx = p[0] - A0, wy = p[1] - A1, wz = p[2] - A2;
    const double u = wx * X0 + wy * X1 + wz * X2;
    const double v = wx * Y0 + wy * Y1 + wz * Y2;
    const double lz = wx * Z0 + wy * Z1 + wz * Z2;
    if (c->s->kind == RS_SURF_CYLINDER && c->s->bounded &&
        !(lz >= c->s->zmin && lz <= c->s->zmax))
        return 0;
    rs_hit2 h;
    if (rs_pcache_face(c->pc, RS_FEATURE_INDEX(want), u, v, -gap, gap, &h) != 1)
        return 0;
    const double hx = h.x[0], hy = h.x[1], nx = h.n[0], ny = h.n[1];
    o->feature = h.feature;
    o->depth = -h.dist;
    o->xm[0] = A0 + hx * X0 + hy * Y0 + lz * Z0;
    o->xm[1] = A1 + hx * X1 + hy * Y1 + lz * Z1;
    o->xm[2] = A2 + hx * X2 + hy * Y2 + lz * Z2;
    o->normal[0] = nx * X0 + ny * Y0;
    o->normal[1] = nx * X1 + ny * Y1;
    o->normal[2] = nx * X2 + ny * Y2;
    o->t1[0] = ny * X0 - nx * Y0;
    o->t1[1] = ny * X1 - nx * Y1;
    o->t1[2] = ny * X2 - nx * Y2;
    o->t2[0] = -Z0;
    o->t2[1] = -Z1;
    o->t2[2] = -Z2;
    o->curv[0] = h.kappa;
    o->curv[1] = 0.0;
    return 1;
}

int rs_analytic_body_run(const rs_surface *s, const rs_pose *pose, const rs_body *b,
                         const double *R, int n, double gap_max, int lenient,
                         rs_body_contacts *out, rs_body_work *w, rs_error *err)
{
    if (!s->impl || (s->kind != RS_SURF_CYLINDER && s->kind != RS_SURF_SEGMENTS))
        return rs_body_fixed_point_run(s, pose, b, R, n, gap_max, lenient, NULL, NULL, out,
                                       &w->fp, err);
    face_ctx c;
    c.s = s;
    c.pc = s->impl;
    rs_analytic_frame(s, pose, c.F);
    return rs_body_fixed_point_run(s, pose, b, R, n, gap_max, lenient, extruded_face, &c,
                                   out, &w->fp, err);
}

int rs_analytic_body(const rs_surface *s, const rs_pose *pose, const rs_body *b, int n,
                     double gap_max, int lenient, rs_body_contacts *out, rs_error *err)
{
    rs_body_work w;
    memset(&w, 0, sizeof w);
    const int rc =
        rs_analytic_body_run(s, pose, b, NULL, n, gap_max, lenient, out, &w, err);
    rs_body_work_free(&w);
    return rc;
}

int rs_analytic_feature_point(const rs_surface *s, const rs_pose *pose, int f,
                              const double x[3], double radius, double gap_max,
                              double depth_max, double *dist, double xm[3], double n[3],
                              double t1[3], double t2[3])
{
    const rs_pcache *pc = s->impl;
    if (!pc || (s->kind != RS_SURF_CYLINDER && s->kind != RS_SURF_SEGMENTS) ||
        RS_FEATURE_TYPE(f) != RS_FEAT_FACE || f != RS_FEATURE_BASE(f))
        return 0;
    double F[12];
    rs_analytic_frame(s, pose, F);
    /* the point's local coordinates and reach as rs_analytic_closest takes them
     * (local_extrusion, reach_radius, the bounded extrusion's range) */
    const double wx = x[0] - F[F_A], wy = x[1] - F[F_A + 1], wz = x[2] - F[F_A + 2];
    const double u = wx * F[F_X] + wy * F[F_X + 1] + wz * F[F_X + 2];
    const double v = wx * F[F_Y] + wy * F[F_Y + 1] + wz * F[F_Y + 2];
    const double lz = wx * F[F_Z] + wy * F[F_Z + 1] + wz * F[F_Z + 2];
    if (s->kind == RS_SURF_CYLINDER && s->bounded && !(lz >= s->zmin && lz <= s->zmax))
        return 0;
    rs_hit2 h;
    if (rs_pcache_face(pc, RS_FEATURE_INDEX(f), u, v, -depth_max, gap_max + radius, &h) !=
        1)
        return 0;
    /* its contact in 3D as map_extrusion writes it: d1 = n_y EX - n_x EY, d2 = -EZ */
    const double hx = h.x[0], hy = h.x[1], nx = h.n[0], ny = h.n[1];
    *dist = h.dist;
    for (int d = 0; d < 3; d++) {
        xm[d] = F[F_A + d] + hx * F[F_X + d] + hy * F[F_Y + d] + lz * F[F_Z + d];
        n[d] = nx * F[F_X + d] + ny * F[F_Y + d];
    }
    for (int d = 0; t1 && t2 && d < 3; d++) {
        t1[d] = ny * F[F_X + d] - nx * F[F_Y + d];
        t2[d] = -F[F_Z + d];
    }
    return 1;
}
