/* A convex body's manifold on one flat face that the kind answers in closed form (an
 * extruded profile's LINE face): the manifold of body_manifold.c for that case in one
 * pass, with no list of core points and no query of their balls: the deepest point the
 * kind's body operation found, each core point low enough (rs_body_low_points) measured
 * by the kind's closed form of its ball, and the points kept as the manifold keeps them
 * (the deepest first, one an id, at most RS_MANIFOLD_MAX; a core point as deep as the
 * deepest point stands for it). Where the closed form does not answer a core point the
 * manifold's general path measures the body. */
#include "convex_internal.h"
#include "flat_face.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <string.h>

/* A point the manifold may keep: id, depth, and where its contact is (c < 0: the deepest
 * point's, else core point c's). */
typedef struct fpoint {
    int id, c;
    double depth;
} fpoint;

/* The manifold's order: the deeper first, ties the lower id (by_depth). */
static int before(const fpoint *a, const fpoint *b)
{
    return a->depth > b->depth || (a->depth == b->depth && a->id < b->id);
}

int rs_body_flat_manifold(const rs_body *b, const double R[9], const rs_body_contact *o,
                          double reach, double win, double gap_max, const rs_flat_face *kit,
                          rs_flat_manifold *m)
{
    const rs_shape *sh = b->shape;
    const double rr = rs_shape_core_radius(sh);
    double d[3];
    for (int k = 0; k < 3; k++)
        d[k] = -(R[k] * o->normal[0] + R[3 + k] * o->normal[1] + R[6 + k] * o->normal[2]);
    const double dn = rs_norm3(d);
    for (int k = 0; k < 3; k++)
        d[k] /= dn;
    /* the manifold's bounds on a flat wall (rs_body_manifold_in): above the deepest point
     * by more than the depth and the gap, a point does not reach it; a core point's ball
     * is lifted out by the depth */
    const double above = o->depth + gap_max + 1e-9 * reach;
    const double lift = (o->depth > 0.0 ? o->depth : 0.0) + 1e-9 * reach;
    const double nx = rs_dot3(o->normal, b->x), nxs = rs_dot3(o->normal, o->xs);
    const double clear = above + 1e-12 * (reach + fabs(nx) + fabs(nxs));
    rs_core_cand cp[RS_CORE_CANDS];
    const int ncp =
        rs_body_low_points(sh, d, dn, nx, rr, nxs, clear, cp, RS_CORE_CANDS - 1);
    /* the points: the deepest (0), then the core points within the gap */
    fpoint p[RS_CORE_CANDS];
    double cxm[RS_CORE_CANDS][3], cn[RS_CORE_CANDS][3], ct1[RS_CORE_CANDS][3],
        ct2[RS_CORE_CANDS][3], cxs[RS_CORE_CANDS][3];
    int np = 1, deep_is_core = o->iterations < 0;
    p[0].id = 0, p[0].c = -1, p[0].depth = o->depth;
    for (int k = 0; k < ncp; k++) {
        double cw[3];
        rs_matvec3(R, cp[k].p, cw);
        for (int j = 0; j < 3; j++)
            cw[j] += b->x[j];
        const double h = rs_dot3(o->normal, cw) - rr - rs_dot3(o->normal, o->xs);
        if (h > above)
            continue;
        const double cl[3] = {cw[0] + lift * o->normal[0], cw[1] + lift * o->normal[1],
                              cw[2] + lift * o->normal[2]};
        double dist;
        /* the kind's closed form of the ball (rs_surface_ops.feature_point's window) */
        if (rs_flat_face_at(kit, cl, -win, win + rr + lift, &dist, cxm[np], cn[np], ct1[np],
                            ct2[np]) != 1)
            return 0; /* (the block's query tells: another face may hold it) */
        const double depth = rr + lift - dist;
        if (!(-depth <= gap_max))
            continue;
        if (depth >= o->depth - 1e-12 * reach)
            deep_is_core = 1;
        for (int j = 0; j < 3; j++)
            cxs[np][j] = cw[j] - rr * cn[np][j];
        p[np].id = cp[k].id, p[np].c = np, p[np].depth = depth;
        np++;
    }
    /* the kept points: the deepest first, one an id, at most RS_MANIFOLD_MAX */
    const fpoint *keep = deep_is_core ? p + 1 : p;
    const int count = deep_is_core ? np - 1 : np;
    unsigned char taken[RS_CORE_CANDS];
    memset(taken, 0, (size_t)count);
    m->n = 0;
    for (int round = 0; round < count && m->n < RS_MANIFOLD_MAX; round++) {
        int next = -1;
        for (int k = 0; k < count; k++)
            if (!taken[k] && (next < 0 || before(keep + k, keep + next)))
                next = k;
        taken[next] = 1;
        int dup = 0;
        for (int q = 0; q < m->n; q++)
            dup |= m->id[q] == keep[next].id;
        if (dup)
            continue;
        const int k = m->n++, c = keep[next].c;
        m->id[k] = keep[next].id;
        m->depth[k] = keep[next].depth;
        for (int j = 0; j < 3; j++) {
            m->xm[k][j] = c < 0 ? o->xm[j] : cxm[c][j];
            m->nrm[k][j] = c < 0 ? o->normal[j] : cn[c][j];
            m->t1[k][j] = c < 0 ? o->t1[j] : ct1[c][j];
            m->t2[k][j] = c < 0 ? o->t2[j] : ct2[c][j];
            m->xs[k][j] = c < 0 ? o->xs[j] : cxs[c][j];
        }
        m->curv[k][0] = c < 0 ? o->curv[0] : 0.0;
        m->curv[k][1] = c < 0 ? o->curv[1] : 0.0;
    }
    return 1;
}
