/* The contact of two convex shapes, or of a convex shape and a triangle
 * (rs_convex_pair, rs_convex_triangle): GJK's distance of the cores while they are
 * apart, libccd's MPR depth while they overlap, the roundings added analytically. */
#include "gjk.h"
#include "rigidsurf/vec.h"

#include <ccd/ccd.h>
#include <math.h>
#include <string.h>

/* libccd's callbacks: the core's support, or with full != 0 the rounded shape's. */
typedef struct ccd_obj {
    const rs_cvx *c;
    int full;
} ccd_obj;

static void ccd_support(const void *obj, const ccd_vec3_t *dir, ccd_vec3_t *out)
{
    const ccd_obj *o = obj;
    const double d[3] = {dir->v[0], dir->v[1], dir->v[2]};
    rs_cvx_support(o->c, d, out->v);
    if (o->full && o->c->radius > 0.0) {
        const double k = o->c->radius / rs_norm3(d);
        for (int i = 0; i < 3; i++)
            out->v[i] += k * d[i];
    }
}

static void ccd_center(const void *obj, ccd_vec3_t *center)
{
    const ccd_obj *o = obj;
    for (int i = 0; i < 3; i++)
        center->v[i] = o->c->x[i];
}

static int body_cvx(const rs_body *b, rs_cvx *c, rs_error *err)
{
    memset(c, 0, sizeof *c);
    if (!b || !b->shape)
        return rs_error_set(err, RS_ERR_ARG, "convex pair: NULL body or shape");
    for (int k = 0; k < 3; k++)
        if (!(fabs(b->x[k]) <= RS_CONVEX_COORD_MAX))
            return rs_error_set(err, RS_ERR_ARG,
                                "convex pair: body position %g (expected a finite "
                                "coordinate of magnitude at most %g)",
                                b->x[k], RS_CONVEX_COORD_MAX);
    const double nq =
        sqrt(b->q[0] * b->q[0] + b->q[1] * b->q[1] + b->q[2] * b->q[2] + b->q[3] * b->q[3]);
    if (!(fabs(nq - 1.0) <= 1e-12))
        return rs_error_set(err, RS_ERR_ARG,
                            "convex pair: body quaternion has norm %.17g (expected unit to "
                            "1e-12)",
                            nq);
    c->shape = b->shape;
    rs_body_rotation(b, c->R);
    memcpy(c->x, b->x, sizeof c->x);
    c->radius = rs_shape_core_radius(b->shape);
    const rs_shape_kind k = b->shape->kind;
    c->solid = k != RS_SHAPE_SPHERE && k != RS_SHAPE_CAPSULE;
    double lo[3], hi[3];
    rs_shape_bounds(b->shape, lo, hi);
    for (int i = 0; i < 3; i++)
        c->size = fmax(c->size, fmax(fabs(lo[i]), fabs(hi[i])));
    c->size = c->size * sqrt(3.0) - c->radius;
    return RS_OK;
}

static void set_contact(rs_convex_contact *out, double depth, const double n[3],
                        const double pa[3], const double pb[3], double gap_max)
{
    out->depth = depth;
    memcpy(out->normal, n, sizeof out->normal);
    memcpy(out->pa, pa, sizeof out->pa);
    memcpy(out->pb, pb, sizeof out->pb);
    out->state = depth > 0.0         ? RS_CONVEX_OVERLAP
                 : -depth <= gap_max ? RS_CONVEX_NEAR
                                     : RS_CONVEX_APART;
}

/* b moved by s: the core of b, translated (a copy of b with its origin moved). */
static void moved(const rs_cvx *b, const double s[3], rs_cvx *m, double tri[9])
{
    *m = *b;
    for (int k = 0; k < 3; k++)
        m->x[k] += s[k];
    if (!b->shape) {
        for (int i = 0; i < 9; i++)
            tri[i] = b->tri[i] + s[i % 3];
        m->tri = tri;
    }
}

/* libccd's MPR on the cores (full = 0) or the rounded shapes (full = 1), then its depth
 * and normal made exact where the contact is flat and witness points found: b is moved
 * by (depth + margin) along MPR's normal, GJK gives the small gap left and its closest
 * points, and the depth is the move less that gap along GJK's normal. Returns 0, or -1
 * when MPR finds no overlap. */
static int mpr(const rs_cvx *a, const rs_cvx *b, int full, double gap_max,
               rs_convex_contact *out)
{
    ccd_t ccd;
    CCD_INIT(&ccd);
    ccd.support1 = ccd_support;
    ccd.support2 = ccd_support;
    ccd.center1 = ccd_center;
    ccd.center2 = ccd_center;
    ccd.max_iterations = 500;
    /* MPR's tolerance is a length: the portal's progress along its normal */
    const double scale = a->size + b->size + a->radius + b->radius;
    ccd.mpr_tolerance = 1e-14 * scale;
    ccd.epa_tolerance = ccd.mpr_tolerance;
    ccd.dist_tolerance = ccd.mpr_tolerance;
    const ccd_obj oa = {a, full}, ob = {b, full};
    ccd_real_t depth;
    ccd_vec3_t dir, pos;
    if (ccdMPRPenetration(&oa, &ob, &ccd, &depth, &dir, &pos) != 0)
        return -1;
    double n[3] = {dir.v[0], dir.v[1], dir.v[2]};
    const double nn = rs_norm3(n);
    if (!(nn > 0.0) || !isfinite(depth))
        return -1;
    const double rr = a->radius + b->radius;
    double pa[3], pb[3], tri[9];
    for (int k = 0; k < 3; k++)
        n[k] /= nn;
    /* up to four rounds: each moves b along the last normal, so that an oblique first
     * normal (MPR follows the ray between the centres) turns to the contact's */
    int found = 0;
    double d = depth + (full ? 0.0 : rr);
    for (int round = 0; round < 4; round++) {
        const double move = d - rr + 1e-2 * scale + 0.01 * fabs(d);
        double sh[3], m[3];
        for (int k = 0; k < 3; k++)
            sh[k] = move * n[k];
        rs_cvx mb;
        moved(b, sh, &mb, tri);
        rs_gjk g;
        rs_gjk_distance(a, &mb, INFINITY, &g);
        if (g.overlap || !(g.dist > 0.0))
            break;
        /* the direction of the closest points' difference, where its length is GJK's
         * distance (not where rounding parted the two: MPR's answer then stands) */
        for (int k = 0; k < 3; k++)
            m[k] = g.pb[k] - g.pa[k];
        const double ml = rs_norm3(m);
        if (!(fabs(ml - g.dist) <= 1e-9 * fmax(g.dist, scale)))
            break;
        for (int k = 0; k < 3; k++)
            m[k] /= ml;
        d = move * rs_dot3(n, m) - g.dist + rr;
        for (int k = 0; k < 3; k++) {
            pa[k] = g.pa[k] + a->radius * m[k];
            pb[k] = pa[k] - d * m[k];
        }
        const double turn = fabs(m[0] - n[0]) + fabs(m[1] - n[1]) + fabs(m[2] - n[2]);
        memcpy(n, m, sizeof n);
        found = 1;
        if (turn <= 1e-13)
            break;
    }
    if (found) {
        set_contact(out, d, n, pa, pb, gap_max);
        return 0;
    }
    /* MPR's own answer (libccd's pos mixes the centres in): the witness on a is its
     * support along the normal */
    const double dd = full ? depth : depth + rr;
    ccd_support(&oa, &dir, &pos);
    for (int k = 0; k < 3; k++) {
        pa[k] = pos.v[k] + (full ? 0.0 : a->radius * n[k]);
        pb[k] = pa[k] - dd * n[k];
    }
    set_contact(out, dd, n, pa, pb, gap_max);
    return 0;
}

static int pair(const rs_cvx *a, const rs_cvx *b, double gap_max, rs_convex_contact *out,
                rs_error *err)
{
    if (!out)
        return rs_error_set(err, RS_ERR_ARG, "convex pair: NULL result");
    if (!isfinite(gap_max) || gap_max < 0.0)
        return rs_error_set(err, RS_ERR_ARG, "gap_max = %g (expected a finite number >= 0)",
                            gap_max);
    memset(out, 0, sizeof *out);
    const double rr = a->radius + b->radius;
    rs_gjk g;
    rs_gjk_distance(a, b, gap_max + rr, &g);
    if (g.apart) {
        out->state = RS_CONVEX_APART;
        out->depth = rr - g.dist;
        return RS_OK;
    }
    /* Apart: the normal along the witnesses' difference, when it is one (its length the
     * distance); a difference lost to rounding (touching cores, or coordinates far
     * beyond the shapes' size) leaves it to the overlap's methods below. */
    double gd[3];
    for (int k = 0; k < 3; k++)
        gd[k] = g.pb[k] - g.pa[k];
    const double gl = rs_norm3(gd);
    if (!g.overlap && gl > 0.0 &&
        fabs(gl - g.dist) <= 1e-9 * fmax(g.dist, a->size + b->size)) {
        double n[3], pa[3], pb[3];
        for (int k = 0; k < 3; k++)
            n[k] = gd[k] / gl;
        for (int k = 0; k < 3; k++) {
            pa[k] = g.pa[k] + a->radius * n[k];
            pb[k] = g.pb[k] - b->radius * n[k];
        }
        set_contact(out, rr - g.dist, n, pa, pb, gap_max);
        return RS_OK;
    }
    /* the cores overlap: their MPR depth plus the roundings, or, for cores without
     * volume (points, segments, triangles), MPR on the rounded shapes */
    if (a->solid && b->solid && mpr(a, b, 0, gap_max, out) == 0)
        return RS_OK;
    if (mpr(a, b, 1, gap_max, out) == 0)
        return RS_OK;
    /* touching cores MPR cannot resolve: the roundings' depth along the centres */
    double n[3];
    for (int k = 0; k < 3; k++)
        n[k] = b->x[k] - a->x[k];
    const double nn = rs_norm3(n);
    if (nn > 0.0)
        for (int k = 0; k < 3; k++)
            n[k] /= nn;
    else
        n[2] = 1.0;
    double pa[3], pb[3], c[3];
    rs_cvx_support(a, n, c);
    for (int k = 0; k < 3; k++) {
        pa[k] = c[k] + a->radius * n[k];
        pb[k] = c[k] - b->radius * n[k];
    }
    set_contact(out, rr, n, pa, pb, gap_max);
    return RS_OK;
}

int rs_convex_pair(const rs_body *a, const rs_body *b, double gap_max,
                   rs_convex_contact *out, rs_error *err)
{
    rs_cvx ca, cb;
    int rc = body_cvx(a, &ca, err);
    if (rc || (rc = body_cvx(b, &cb, err)))
        return rc;
    return pair(&ca, &cb, gap_max, out, err);
}

int rs_convex_triangle(const rs_body *a, const double tri[9], double gap_max,
                       rs_convex_contact *out, rs_error *err)
{
    rs_cvx ca, cb;
    int rc = body_cvx(a, &ca, err);
    if (rc)
        return rc;
    if (!tri)
        return rs_error_set(err, RS_ERR_ARG, "convex triangle: NULL triangle");
    memset(&cb, 0, sizeof cb);
    for (int i = 0; i < 9; i++)
        if (!(fabs(tri[i]) <= RS_CONVEX_COORD_MAX))
            return rs_error_set(
                err, RS_ERR_ARG,
                "triangle corner %d is not finite or has a coordinate beyond "
                "%g (got %g)",
                i / 3 + 1, RS_CONVEX_COORD_MAX, tri[i]);
    cb.tri = tri;
    for (int k = 0; k < 3; k++)
        cb.x[k] = (tri[k] + tri[3 + k] + tri[6 + k]) / 3.0;
    for (int i = 0; i < 3; i++) {
        double d[3];
        for (int k = 0; k < 3; k++)
            d[k] = tri[3 * i + k] - cb.x[k];
        cb.size = fmax(cb.size, rs_norm3(d));
    }
    return pair(&ca, &cb, gap_max, out, err);
}

int rs_body_holds(const rs_body *b, const double p[3], double tol)
{
    rs_cvx ca, cb;
    if (body_cvx(b, &ca, NULL) != RS_OK)
        return 0;
    const double tri[9] = {p[0], p[1], p[2], p[0], p[1], p[2], p[0], p[1], p[2]};
    memset(&cb, 0, sizeof cb);
    cb.tri = tri;
    memcpy(cb.x, p, sizeof cb.x);
    rs_gjk g;
    rs_gjk_distance(&ca, &cb, ca.radius + tol, &g);
    return !g.apart && (g.overlap || g.dist <= ca.radius + tol);
}
