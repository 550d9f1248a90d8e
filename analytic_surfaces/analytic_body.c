/* The analytic kinds' body operations (rs_surface_ops.body, body_face): the fixed point
 * of src/convex_geometry/body_fixed_point.c, each of whose iterates on a flat face of a
 * CYLINDER or SEGMENTS surface (a LINE of the profile, extruded) is measured in closed
 * form: the body's deepest point p along -n lies at the signed distance (p - p0).n from
 * the face's plane, its closest point is its foot, and the face keeps it where the
 * profile's ownership rules give it to the face (rs_pcache_face); elsewhere, and on a
 * REVOLUTION, the iterate asks the kind's point query. Both give the same contact. The
 * manifold's core points (body_manifold.c) are balls measured by the same closed form. */
#include "convex_internal.h"
#include "profile.h"
#include "revolution_point.h"

#include <string.h>

/* rs_body_face_fn of an extruded profile: the contact of the sphere of radius radius
 * about p on face want, as rs_analytic_closest maps it (local_extrusion, the profile's
 * contact of the centre within gap + radius, map_extrusion). */
static int extruded_face(const rs_body_face *c, int want, const double p[3], double gap,
                         double radius, rs_body_contact *o)
{
    if (RS_FEATURE_TYPE(want) != RS_FEAT_FACE)
        return 0;
    const rs_surface *s = c->s;
    const double *F = c->F;
    const double A0 = F[F_A], A1 = F[F_A + 1], A2 = F[F_A + 2];
    const double X0 = F[F_X], X1 = F[F_X + 1], X2 = F[F_X + 2];
    const double Y0 = F[F_Y], Y1 = F[F_Y + 1], Y2 = F[F_Y + 2];
    const double Z0 = F[F_Z], Z1 = F[F_Z + 1], Z2 = F[F_Z + 2];
    const double wx = p[0] - A0, wy = p[1] - A1, wz = p[2] - A2;
    const double u = wx * X0 + wy * X1 + wz * X2;
    const double v = wx * Y0 + wy * Y1 + wz * Y2;
    const double lz = wx * Z0 + wy * Z1 + wz * Z2;
    if (s->kind == RS_SURF_CYLINDER && s->bounded && !(lz >= s->zmin && lz <= s->zmax))
        return 0;
    rs_hit2 h;
    if (rs_pcache_face(c->data, RS_FEATURE_INDEX(want), u, v, -gap, gap + radius, &h) != 1)
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

void rs_analytic_body_face(const rs_surface *s, const rs_pose *pose, rs_body_face *f)
{
    memset(f, 0, sizeof *f);
    if (!s->impl || (s->kind != RS_SURF_CYLINDER && s->kind != RS_SURF_SEGMENTS))
        return;
    f->fn = extruded_face;
    f->s = s;
    f->data = s->impl;
    rs_analytic_frame(s, pose, f->F);
}

int rs_analytic_body(const rs_surface *s, const rs_pose *pose, const rs_body *b, int n,
                     double gap_max, int lenient, rs_body_contacts *out, rs_error *err)
{
    rs_body_face f;
    rs_analytic_body_face(s, pose, &f);
    return rs_body_fixed_point_with(s, pose, b, n, gap_max, lenient, &f, out, err);
}
