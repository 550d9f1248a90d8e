/* The face contacts of spheres held on a MESH's faces (mesh_held.h): the hinted query's
 * own steps (slave_local, rs_mesh_zone_face, face_contact and the pose's mapping back, as
 * rs_mesh_closest_among takes them), so that the numbers are the query's bit for bit. A
 * sphere within the ball its zone's test left (rs_mesh_held_ball) takes the ball's answer,
 * which is the test's: only the limit on the other features' contacts is tested again;
 * the test itself runs out of the run's loop. */
#include "mesh_held.h"

#include "mesh.h"
#include "mesh_regions.h"
#include "mesh_zone.h"
#include "rigidsurf/vec.h"
#include "rs_compiler.h"

#include <math.h>
#include <string.h>

int rs_mesh_held(const rs_surface *s)
{
    const rs_mesh *m = s && s->ops == &rs_mesh_ops ? s->impl : NULL;
    return m && m->zone;
}

/* The ball about p in which every point passes zone z's test as p did (the numbers the
 * test compared at p: its height h, its sides s of ns edges with their slopes kappa, its
 * side diag of a quad's diagonal toward its triangle, +inf for one triangle). Each number
 * changes by at most the distance moved (heights and sides are distances along unit
 * normals), the bound eps + kappa |h| of a side by kappa times it; less a margin far above
 * their rounding, at p and at the point tested later (scale: p's and the mesh's size),
 * and rounded down into a float. 0 where none is left. */
static float ball_reach(const rs_mzone *z, double h, const double *s, int ns, double diag,
                        double scale)
{
    const double eps = z->eps, ah = fabs(h);
    double r = diag;
    r = ah - eps < r ? ah - eps : r;
    r = z->hmax - ah < r ? z->hmax - ah : r;
    for (int k = 0; k < ns; k++) {
        const double kap = (double)z->kappa[k];
        const double rk = (s[k] - (eps + kap * ah)) / (1.0 + kap);
        r = rk < r ? rk : r;
    }
    r = (r - 1e-12 * scale) * (1.0 - 1e-9);
    if (!(r > 0.0))
        return 0.0f;
    float f = (float)r;
    if ((double)f > r)
        f = nextafterf(f, 0.0f);
    return f;
}

/* Ball b about p for face feature face (its zone z, p at height h over the triangle tri
 * the zone gives): reach, and z's clear distance on p's side rounded down; none where
 * the reach is 0. */
static void put_ball(rs_mesh_held_ball *b, const double p[3], int face, float reach,
                     int tri, const rs_mzone *z, double h)
{
    if (!(reach > 0.0f)) {
        b->face = -1;
        return;
    }
    const double clear = z->clear[h < 0.0];
    float cf = (float)clear;
    if ((double)cf > clear)
        cf = nextafterf(cf, -INFINITY);
    b->x[0] = p[0], b->x[1] = p[1], b->x[2] = p[2];
    b->reach = reach;
    b->clear = cf;
    b->face = face;
    b->tri = tri;
}

/* The scale of the numbers the zone's tests round at p. */
static inline double round_scale(const rs_mesh *m, const double p[3])
{
    return fabs(p[0]) + fabs(p[1]) + fabs(p[2]) + m->size;
}

/* The triangle whose zone holds p for face feature hint (of element el, first triangle t0,
 * zone zq) and limit lim, as rs_mesh_zone_face gives it (-1: none), with p's height over
 * it in *h, where p lies outside its ball b (NULL: none): the ball made anew where p
 * passes the test of a made quad's zone or a one-triangle face's. Out of line: the run's
 * loop holds the balls' test alone. */
static RS_NOINLINE int zone_test(const rs_mesh *msh, const rs_mzone *zq, int t0, int el,
                                 double px, double py, double pz, int hint, double lim,
                                 rs_mesh_held_ball *b, double *h)
{
    const double p[3] = {px, py, pz};
    if (atomic_load_explicit(&zq->state, memory_order_acquire) != RS_ZONE_READY)
        return rs_mesh_zone_face(msh, p, hint, lim, h);
    if (zq->quad) { /* rs_mesh_zone_face's own steps for a quad's zone */
        rs_mzone_at a;
        rs_mzone_quad_at(msh, zq, t0, p, &a);
        *h = a.h;
        if (!rs_mzone_quad_holds(zq, &a, lim))
            return -1;
        const int t = a.in0 ? t0 : zq->t2;
        if (b)
            put_ball(
                b, p, hint,
                ball_reach(zq, a.h, a.s, 4, a.in0 ? a.sdd : -a.sdd, round_scale(msh, p)), t,
                zq, a.h);
        return t;
    }
    if (msh->el_t0[el + 1] == t0 + 1) { /* and for a one-triangle face's */
        double sd[3];
        tri_bound(msh, t0, p, h, sd);
        if (!rs_mzone_holds(zq, *h, sd, lim))
            return -1;
        if (b)
            put_ball(b, p, hint, ball_reach(zq, *h, sd, 3, INFINITY, round_scale(msh, p)),
                     t0, zq, *h);
        return t0;
    }
    return rs_mesh_zone_face(msh, p, hint, lim, h);
}

/* The m spheres of a run: the triangle whose zone holds each (its ball's, or the test's)
 * for the limit max(gap_max + radius[j], deep), its height over it, and the face contact
 * from that triangle's record (face_contact, the pose's mapping back). lean: balls given,
 * no master points asked for, the reference configuration (the wall's line path). */
RS_INLINE void held_run(const rs_mesh *msh, const rs_pose *moved, const int two_sided,
                        const int lean, int m, const double *x, const double *y,
                        const double *z, const double *radius, const int *held,
                        double gap_max, double deep, rs_mesh_held_ball *balls,
                        const int *row, rs_contacts *c, int *restrict face)
{
    /* the zone's limit fmax(gap_lim, -dist_min), without a call: a NaN is ignored */
    const int no_deep = deep != deep;
    const int nel = msh->nel;
    const int *const el_t0 = msh->el_t0;
    const rs_mzone *const zone = msh->zone;
    const rs_mtri *const rec = msh->rec;
    /* the columns, read once: the stores below cannot move them */
    int *restrict const feature = c->feature;
    double *restrict const dist = c->dist;
    double *restrict const n0 = c->nrm[0], *restrict const n1 = c->nrm[1],
                           *restrict const n2 = c->nrm[2];
    double *restrict const xm0 = lean ? NULL : c->xm[0], *restrict const xm1 = c->xm[1],
                           *restrict const xm2 = c->xm[2];
    for (int j = 0; j < m; j++) {
        double p[3];
        if (moved) { /* slave_local: X = R^T (x - T) */
            const double w[3] = {x[j] - moved->T[0], y[j] - moved->T[1],
                                 z[j] - moved->T[2]};
            for (int d = 0; d < 3; d++)
                p[d] = moved->R[d] * w[0] + moved->R[3 + d] * w[1] + moved->R[6 + d] * w[2];
        } else {
            p[0] = x[j], p[1] = y[j], p[2] = z[j];
        }
        const double r = radius[j], gap_lim = gap_max + r;
        const double lim = no_deep || gap_lim > deep ? gap_lim : deep;
        const int hint = held[j];
        int t = -1;
        double h = 0.0;
        rs_mesh_held_ball *b = lean || balls ? balls + row[j] : NULL;
        double dx = 0.0, dy = 0.0, dz = 0.0, rb = 0.0;
        if (b && b->face == hint && hint >= 0) {
            dx = p[0] - b->x[0], dy = p[1] - b->x[1], dz = p[2] - b->x[2];
            rb = (double)b->reach;
        }
        if (dx * dx + dy * dy + dz * dz < rb * rb && lim < (double)b->clear) {
            /* within the ball and its limit: the zone's own answer */
            t = b->tri;
            h = plane_height(msh, t, p);
        } else if (hint >= 0 && RS_FEATURE_TYPE(hint) == RS_FEAT_FACE &&
                   RS_FEATURE_INDEX(hint) < nel) {
            const int el = RS_FEATURE_INDEX(hint), t0 = el_t0[el];
            t = zone_test(msh, zone + t0, t0, el, p[0], p[1], p[2], hint, lim, b, &h);
        }
        /* face_contact */
        const rs_mtri *rt = rec;
        double sg = 1.0, d = 0.0;
        int ok = 0;
        if (t >= 0) {
            rt = rec + t;
            sg = (two_sided && h < 0.0) ? -1.0 : 1.0;
            d = sg * h;
            ok = d <= gap_lim && d >= -r;
        }
        face[j] = ok;
        if (!ok) { /* a unit normal, so that the frame stays finite */
            feature[j] = RS_FEATURE_NONE;
            dist[j] = INFINITY;
            n0[j] = n1[j] = 0.0;
            n2[j] = 1.0;
            if (xm0)
                xm0[j] = xm1[j] = xm2[j] = 0.0;
            continue;
        }
        const double *nt = rt->n;
        const double nl[3] = {sg * nt[0], sg * nt[1], sg * nt[2]};
        feature[j] = RS_FEATURE(RS_FEAT_FACE, rt->el);
        dist[j] = d;
        if (moved) { /* x = R X + T */
            double nw[3];
            rs_matvec3(moved->R, nl, nw);
            n0[j] = nw[0], n1[j] = nw[1], n2[j] = nw[2];
        } else {
            n0[j] = nl[0], n1[j] = nl[1], n2[j] = nl[2];
        }
        if (xm0) { /* the foot */
            double xl[3], xw[3];
            for (int e = 0; e < 3; e++)
                xl[e] = p[e] - h * nt[e];
            if (moved) {
                rs_matvec3(moved->R, xl, xw);
                for (int e = 0; e < 3; e++)
                    xw[e] += moved->T[e];
            } else {
                memcpy(xw, xl, sizeof xw);
            }
            xm0[j] = xw[0], xm1[j] = xw[1], xm2[j] = xw[2];
        }
    }
}

void rs_mesh_held_balls(const rs_surface *s, const rs_pose *pose, int m, const double *x,
                        const double *y, const double *z, const double *radius,
                        const int *held, double gap_max, double dist_min,
                        rs_mesh_held_ball *balls, const int *row, rs_contacts *c, int *face)
{
    const rs_mesh *msh = s->impl;
    const rs_pose *moved = pose_moved(pose);
    /* the pose and the sides as constants of each copy of the run's loop, and the wall's
     * case (balls, no master points) in place */
    const double dm = -dist_min;
    const int two = s->sides == 2, lean = balls && !c->xm[0] && !moved;
    if (lean && two)
        held_run(msh, NULL, 1, 1, m, x, y, z, radius, held, gap_max, dm, balls, row, c,
                 face);
    else if (lean)
        held_run(msh, NULL, 0, 1, m, x, y, z, radius, held, gap_max, dm, balls, row, c,
                 face);
    else if (moved && two)
        held_run(msh, moved, 1, 0, m, x, y, z, radius, held, gap_max, dm, balls, row, c,
                 face);
    else if (moved)
        held_run(msh, moved, 0, 0, m, x, y, z, radius, held, gap_max, dm, balls, row, c,
                 face);
    else if (two)
        held_run(msh, NULL, 1, 0, m, x, y, z, radius, held, gap_max, dm, balls, row, c,
                 face);
    else
        held_run(msh, NULL, 0, 0, m, x, y, z, radius, held, gap_max, dm, balls, row, c,
                 face);
    for (int j = 0; j < m; j++)
        c->point[j] = j;
    if (c->curv[0])
        for (int j = 0; j < m; j++)
            c->curv[0][j] = c->curv[1][j] = 0.0;
    if (c->share)
        for (int j = 0; j < m; j++)
            c->share[j] = 1.0;
    c->n = m;
    c->shared = 0;
    c->witness = 0;
}

void rs_mesh_held_faces(const rs_surface *s, const rs_pose *pose, int m, const double *x,
                        const double *y, const double *z, const double *radius,
                        const int *held, double gap_max, double dist_min, rs_contacts *c,
                        int *face)
{
    rs_mesh_held_balls(s, pose, m, x, y, z, radius, held, gap_max, dist_min, NULL, NULL, c,
                       face);
}
