/* The analytic kinds' body operation (rs_surface_ops.body): the fixed point of
 * src/convex_geometry/body_fixed_point.c, each of whose iterates on a flat face of a
 * CYLINDER or SEGMENTS surface (a LINE of the profile, extruded) is measured in closed
 * form: the body's deepest point p along -n lies at the signed distance (p - p0).n from
 * the face's plane, its closest point is its foot, and the face keeps it where the
 * profile's ownership rules give it to the face (rs_pcache_face); elsewhere, and on a
 * REVOLUTION, the iterate asks the kind's point query. Both give the same contact. */
#include "convex_internal.h"
#include "flat_face.h"
#include "profile.h"
#include "revolution_point.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Faces of a run set up at once (rs_flat_face), the first met; the others by face_at. */
enum { FACE_KITS = 8 };

/* A query's set-up for the iterates and the core points: the surface, its profile's data,
 * the frame of its pose (rs_analytic_frame) and the kits of the faces met so far (kit
 * -1: k is no LINE's face of the stored form). */
typedef struct face_ctx {
    const rs_surface *s;
    const rs_pcache *pc;
    double F[12];
    int nkit, kit_k[FACE_KITS], kit_ok[FACE_KITS];
    rs_flat_face kit[FACE_KITS];
} face_ctx;

/* The kit of LINE k's face, set up on first use; NULL where there is none (a curve, no
 * room left). */
static const rs_flat_face *kit_of(face_ctx *c, int k)
{
    for (int j = 0; j < c->nkit; j++)
        if (c->kit_k[j] == k)
            return c->kit_ok[j] ? c->kit + j : NULL;
    if (c->nkit == FACE_KITS)
        return NULL;
    const int j = c->nkit++;
    c->kit_k[j] = k;
    c->kit_ok[j] = rs_flat_face_init(c->kit + j, c->s, c->F, k);
    return c->kit_ok[j] ? c->kit + j : NULL;
}

/* The contact of point p on LINE k's face of an extruded profile, with the surface's frame
 * F in its pose (rs_analytic_frame), as rs_analytic_closest makes it: the point's local
 * coordinates (local_extrusion), the bounded extrusion's range, the profile's contact
 * within [dlo, dhi] where its ownership rules give the point to the face
 * (rs_pcache_face), and the contact in 3D (map_extrusion: d1 = n_y EX - n_x EY, d2 =
 * -EZ; t1 and t2 where not NULL). 1 with the profile's contact in *h, else 0. */
static int face_at(const rs_surface *s, const rs_pcache *pc, const double *restrict F,
                   int k, const double p[3], double dlo, double dhi, rs_hit2 *h,
                   double *restrict xm, double *restrict n, double *restrict t1,
                   double *restrict t2)
{
    const double wx = p[0] - F[F_A], wy = p[1] - F[F_A + 1], wz = p[2] - F[F_A + 2];
    const double u = wx * F[F_X] + wy * F[F_X + 1] + wz * F[F_X + 2];
    const double v = wx * F[F_Y] + wy * F[F_Y + 1] + wz * F[F_Y + 2];
    const double lz = wx * F[F_Z] + wy * F[F_Z + 1] + wz * F[F_Z + 2];
    if (s->kind == RS_SURF_CYLINDER && s->bounded && !(lz >= s->zmin && lz <= s->zmax))
        return 0;
    if (rs_pcache_face(pc, k, u, v, dlo, dhi, h) != 1)
        return 0;
    const double hx = h->x[0], hy = h->x[1], nx = h->n[0], ny = h->n[1];
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

/* rs_body_face_fn of an extruded profile: the contact of point p on face want (its kit,
 * else face_at). */
static int extruded_face(const void *ctx, int want, const double p[3], double gap,
                         rs_body_contact *o)
{
    face_ctx *c = (face_ctx *)ctx; /* (its kits made on first use) */
    if (RS_FEATURE_TYPE(want) != RS_FEAT_FACE)
        return 0;
    const int k = RS_FEATURE_INDEX(want);
    const rs_flat_face *kit = kit_of(c, k);
    double dist;
    const int got =
        kit ? rs_flat_face_at(kit, p, -gap, gap, &dist, o->xm, o->normal, o->t1, o->t2)
            : -1;
    if (got == 0)
        return 0;
    if (got == 1) {
        o->feature = RS_FEATURE(RS_FEAT_FACE, k);
        o->depth = -dist;
        o->curv[0] = o->curv[1] = 0.0;
        return 1;
    }
    rs_hit2 h;
    if (!face_at(c->s, c->pc, c->F, k, p, -gap, gap, &h, o->xm, o->normal, o->t1, o->t2))
        return 0;
    o->feature = h.feature;
    o->depth = -h.dist;
    o->curv[0] = h.kappa;
    o->curv[1] = 0.0;
    return 1;
}

/* rs_body_kit_fn of an extruded profile: the kit of LINE face f (kit_of). */
static const rs_flat_face *extruded_kit(const void *ctx, int f)
{
    if (RS_FEATURE_TYPE(f) != RS_FEAT_FACE || f != RS_FEATURE_BASE(f))
        return NULL;
    return kit_of((face_ctx *)ctx, RS_FEATURE_INDEX(f));
}

/* rs_body_point_fn of an extruded profile (rs_analytic_feature_point on the run's kits):
 * a core point's ball on LINE face f. */
static int extruded_point(const void *ctx, int f, const double x[3], double radius,
                          double gap_max, double depth_max, double *dist, double xm[3],
                          double n[3], double t1[3], double t2[3])
{
    face_ctx *c = (face_ctx *)ctx;
    if (RS_FEATURE_TYPE(f) != RS_FEAT_FACE || f != RS_FEATURE_BASE(f))
        return 0;
    const int k = RS_FEATURE_INDEX(f);
    const rs_flat_face *kit = kit_of(c, k);
    const int got =
        kit ? rs_flat_face_at(kit, x, -depth_max, gap_max + radius, dist, xm, n, t1, t2)
            : -1;
    if (got >= 0)
        return got;
    rs_hit2 h;
    if (!face_at(c->s, c->pc, c->F, k, x, -depth_max, gap_max + radius, &h, xm, n, t1, t2))
        return 0;
    *dist = h.dist;
    return 1;
}

/* The bodies whose one feature near them is a LINE's face set up in c (a kit), settled
 * at the fixed point's first step: each body's reach sphere asked in one block as the
 * fixed point asks it (rs_body_fixed_point_run), and where its only feature within its
 * window is such a face, the body's support along the face's normal answered by the kit
 * with that normal again (the fixed point's test of a settled step); that contact, with
 * one iteration, into out[i] where within the gap, and settled[i] = 1, as for a body with
 * no feature within its window (no contact). The others are left to the fixed point
 * (settled[i] = 0): the same contacts either way. */
static int settle_flat(face_ctx *c, const rs_pose *pose, const rs_body *b, const double *R,
                       int n, double gap_max, double *mem, unsigned char *settled,
                       rs_body_contacts *out, rs_contacts *pc, rs_error *err)
{
    double *reach = mem, *x = reach + n, *y = x + n, *z = y + n, *win = z + n;
    double far = gap_max;
    for (int i = 0; i < n; i++) {
        reach[i] = rs_body_reach(b + i);
        x[i] = b[i].x[0], y[i] = b[i].x[1], z[i] = b[i].x[2];
        const double wi = 2.0 * reach[i] + gap_max;
        win[i] = wi > gap_max ? wi : gap_max;
        far = win[i] > far ? win[i] : far;
        settled[i] = 1; /* (no feature within its window: no contact, as the fixed point) */
    }
    int rc = rs_contacts_reserve(pc, 2 * n + 64, err);
    if (rc == RS_OK)
        rc = rs_body_closest(c->s, pose, n, x, y, z, reach, gap_max, far, pc, err);
    for (int k = 0; rc == RS_OK && k < pc->n;) {
        const int i = pc->point[k];
        int one = -1, many = 0;
        for (; k < pc->n && pc->point[k] == i; k++)
            if (pc->dist[k] >= -win[i])
                many += one >= 0, one = one >= 0 ? one : k;
        if (one < 0)
            continue;
        settled[i] = 0; /* (unless it settles below) */
        if (many || RS_FEATURE_TYPE(pc->feature[one]) != RS_FEAT_FACE)
            continue;
        const int want = RS_FEATURE_BASE(pc->feature[one]);
        const rs_flat_face *kit = kit_of(c, RS_FEATURE_INDEX(want));
        if (!kit)
            continue;
        const double nrm[3] = {pc->nrm[0][one], pc->nrm[1][one], pc->nrm[2][one]};
        const double down[3] = {-nrm[0], -nrm[1], -nrm[2]};
        rs_body_contact o;
        rs_body_support_at(b + i, R + 9 * i, down, o.xs);
        double dist;
        if (rs_flat_face_at(kit, o.xs, -win[i], win[i], &dist, o.xm, o.normal, o.t1,
                            o.t2) != 1)
            continue;
        const double turn = fabs(o.normal[0] - nrm[0]) + fabs(o.normal[1] - nrm[1]) +
                            fabs(o.normal[2] - nrm[2]);
        if (!(turn <= 1e-13))
            continue;
        settled[i] = 1;
        o.feature = RS_FEATURE(RS_FEAT_FACE, kit->k);
        o.depth = -dist;
        o.iterations = 1;
        o.curv[0] = o.curv[1] = 0.0;
        if (-o.depth <= gap_max)
            rc = rs_body_contacts_push(out + i, &o, err);
    }
    return rc;
}

int rs_analytic_body_run(const rs_surface *s, const rs_pose *pose, const rs_body *b,
                         const double *R, int n, double gap_max, int lenient,
                         rs_body_contacts *out, rs_body_work *w, rs_error *err)
{
    if (!s->impl || (s->kind != RS_SURF_CYLINDER && s->kind != RS_SURF_SEGMENTS))
        return rs_body_fixed_point_run(s, pose, b, R, n, gap_max, lenient, NULL, NULL, out,
                                       &w->fp, err);
    /* the run's set-up, kept in the work for its core points (rs_body_work.point), and
     * with rotations given, each body's reach, centre and window and whether it settled
     * on a flat face (settle_flat) */
    const size_t nb = (size_t)(n > 0 ? n : 0);
    const size_t bytes = sizeof(face_ctx) + (R ? 5 * nb * sizeof(double) + nb : 0);
    if (w->kind_bytes < bytes) {
        free(w->kind_mem);
        w->kind_bytes = 0;
        if (!(w->kind_mem = malloc(bytes)))
            return rs_error_set(err, RS_ERR_NOMEM, "body contacts: out of memory");
        w->kind_bytes = bytes;
    }
    face_ctx *c = w->kind_mem;
    c->s = s;
    c->pc = s->impl;
    c->nkit = 0;
    rs_analytic_frame(s, pose, c->F);
    if (s->ops->feature_point) { /* (a kind's table without it: every point asked) */
        w->point = extruded_point;
        w->point_ctx = c;
        w->kit = extruded_kit;
    }
    if (!R || !s->ops->feature_point) /* (a kind's table without it: the fixed point) */
        return rs_body_fixed_point_run(s, pose, b, R, n, gap_max, lenient, extruded_face, c,
                                       out, &w->fp, err);
    double *mem = (double *)(c + 1);
    unsigned char *settled = (unsigned char *)(mem + 5 * nb);
    int rc = settle_flat(c, pose, b, R, n, gap_max, mem, settled, out, &w->fp.pc, err);
    /* the rest by the fixed point, a run of unsettled bodies at a time */
    for (int i = 0; rc == RS_OK && i < n;) {
        if (settled[i]) {
            i++;
            continue;
        }
        int j = i;
        while (j < n && !settled[j])
            j++;
        rc = rs_body_fixed_point_run(s, pose, b + i, R + 9 * (size_t)i, j - i, gap_max,
                                     lenient, extruded_face, c, out + i, &w->fp, err);
        i = j;
    }
    return rc;
}

int rs_analytic_body(const rs_surface *s, const rs_pose *pose, const rs_body *b, int n,
                     double gap_max, int lenient, rs_body_contacts *out, rs_error *err)
{
    rs_body_work w;
    memset(&w, 0, sizeof w);
    /* the bodies' rotations made here, as the manifold makes them for body_run */
    double *R = n > 0 ? malloc(9 * (size_t)n * sizeof *R) : NULL;
    if (n > 0 && !R)
        return rs_error_set(err, RS_ERR_NOMEM, "body contacts: out of memory");
    for (int i = 0; i < n; i++)
        rs_body_rotation(b + i, R + 9 * i);
    const int rc = rs_analytic_body_run(s, pose, b, R, n, gap_max, lenient, out, &w, err);
    free(R);
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
    /* the ball's reach as rs_analytic_closest takes it (reach_radius) */
    rs_hit2 h;
    if (!face_at(s, pc, F, RS_FEATURE_INDEX(f), x, -depth_max, gap_max + radius, &h, xm, n,
                 t1, t2))
        return 0;
    *dist = h.dist;
    return 1;
}
