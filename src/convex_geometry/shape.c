/* Convex shapes: their making and checks, supports and bounds, and rigid bodies' poses
 * (include/rigidsurf/convex.h). */
#include "cgal_hull.h"
#include "convex_internal.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Lengths are bounded as coordinates are (RS_CONVEX_COORD_MAX): a shape's volume and
 * inertia stay finite; and from below (RS_CONVEX_LENGTH_MIN), so that their squares are
 * normal numbers (an ellipsoid's support divides by them). */
static int check_dim(const char *what, double x, rs_error *err)
{
    if (!(x >= RS_CONVEX_LENGTH_MIN && x <= RS_CONVEX_COORD_MAX))
        return rs_error_set(err, RS_ERR_ARG,
                            "%s = %g (expected a finite number > 0, at most %g); a shape's "
                            "lengths are at least %g",
                            what, x, RS_CONVEX_COORD_MAX, RS_CONVEX_LENGTH_MIN);
    return RS_OK;
}

static int check_rounding(double r, rs_error *err)
{
    if (!(r >= 0.0 && r <= RS_CONVEX_COORD_MAX))
        return rs_error_set(
            err, RS_ERR_ARG,
            "rounding radius = %g (expected a finite number >= 0, at most %g)", r,
            RS_CONVEX_COORD_MAX);
    return RS_OK;
}

/* A make call empties the shape first, so that one that fails leaves no shape
 * (rs_shape_check refuses it) rather than what was there. */
static int begin(rs_shape *s, rs_error *err)
{
    if (!s)
        return rs_error_set(err, RS_ERR_ARG, "shape: NULL argument");
    memset(s, 0, sizeof *s);
    return RS_OK;
}

/* The shape's body-frame bounds, and their farthest corner from its origin. */
static void set_reach(rs_shape *s)
{
    double *lo = s->box, *hi = s->box + 3, r2 = 0.0;
    rs_shape_bounds(s, lo, hi);
    for (int c = 0; c < 8; c++) {
        const double v[3] = {(c & 1) ? hi[0] : lo[0], (c & 2) ? hi[1] : lo[1],
                             (c & 4) ? hi[2] : lo[2]};
        r2 = fmax(r2, rs_dot3(v, v));
    }
    s->reach = sqrt(r2);
}

static void shape_init(rs_shape *s, rs_shape_kind kind, double d0, double d1, double d2,
                       double r)
{
    memset(s, 0, sizeof *s);
    s->kind = kind;
    s->dim[0] = d0;
    s->dim[1] = d1;
    s->dim[2] = d2;
    s->rounding = r;
}

int rs_shape_make_sphere(rs_shape *s, double radius, double rounding, rs_error *err)
{
    if (begin(s, err))
        return RS_ERR_ARG;
    int rc = check_dim("sphere radius", radius, err);
    if (rc || (rc = check_rounding(rounding, err)))
        return rc;
    shape_init(s, RS_SHAPE_SPHERE, radius, 0.0, 0.0, rounding);
    set_reach(s);
    return RS_OK;
}

int rs_shape_make_ellipsoid(rs_shape *s, double a, double b, double c, double rounding,
                            rs_error *err)
{
    if (begin(s, err))
        return RS_ERR_ARG;
    int rc = check_dim("ellipsoid semi-axis a", a, err);
    if (rc || (rc = check_dim("ellipsoid semi-axis b", b, err)) ||
        (rc = check_dim("ellipsoid semi-axis c", c, err)) ||
        (rc = check_rounding(rounding, err)))
        return rc;
    shape_init(s, RS_SHAPE_ELLIPSOID, a, b, c, rounding);
    set_reach(s);
    return RS_OK;
}

int rs_shape_make_box(rs_shape *s, double hx, double hy, double hz, double rounding,
                      rs_error *err)
{
    if (begin(s, err))
        return RS_ERR_ARG;
    int rc = check_dim("box half-extent x", hx, err);
    if (rc || (rc = check_dim("box half-extent y", hy, err)) ||
        (rc = check_dim("box half-extent z", hz, err)) ||
        (rc = check_rounding(rounding, err)))
        return rc;
    shape_init(s, RS_SHAPE_BOX, hx, hy, hz, rounding);
    set_reach(s);
    return RS_OK;
}

int rs_shape_make_cylinder(rs_shape *s, double radius, double half_height, double rounding,
                           rs_error *err)
{
    if (begin(s, err))
        return RS_ERR_ARG;
    int rc = check_dim("cylinder radius", radius, err);
    if (rc || (rc = check_dim("cylinder half-height", half_height, err)) ||
        (rc = check_rounding(rounding, err)))
        return rc;
    shape_init(s, RS_SHAPE_CYLINDER, radius, half_height, 0.0, rounding);
    set_reach(s);
    return RS_OK;
}

int rs_shape_make_capsule(rs_shape *s, double radius, double half_length, double rounding,
                          rs_error *err)
{
    if (begin(s, err))
        return RS_ERR_ARG;
    int rc = check_dim("capsule radius", radius, err);
    if (rc || (rc = check_dim("capsule half-length", half_length, err)) ||
        (rc = check_rounding(rounding, err)))
        return rc;
    shape_init(s, RS_SHAPE_CAPSULE, radius, half_length, 0.0, rounding);
    set_reach(s);
    return RS_OK;
}

int rs_shape_make_cone(rs_shape *s, double radius, double height, double rounding,
                       rs_error *err)
{
    if (begin(s, err))
        return RS_ERR_ARG;
    int rc = check_dim("cone radius", radius, err);
    if (rc || (rc = check_dim("cone height", height, err)) ||
        (rc = check_rounding(rounding, err)))
        return rc;
    shape_init(s, RS_SHAPE_CONE, radius, height, 0.0, rounding);
    if (rounding > 0.0) {
        /* the profile in (rho, z) about the core's centroid: axis foot, rim, apex */
        const double prof[6] = {0.0, -0.25 * height, radius, -0.25 * height,
                                0.0, 0.75 * height};
        rs_moments m;
        rs_revolved_moments(prof, 3, rounding, &m);
        s->shift[2] = m.s[2] / m.v;
    }
    set_reach(s);
    return RS_OK;
}

int rs_shape_make_polyhedron(rs_shape *s, const double *xyz, int n, double rounding,
                             rs_error *err)
{
    if (begin(s, err))
        return RS_ERR_ARG;
    char msg[256];
    int rc = check_rounding(rounding, err);
    if (rc)
        return rc;
    if (!xyz || n < 0)
        return rs_error_set(err, RS_ERR_ARG, "polyhedron: no points (expected n >= 4)");
    for (int i = 0; i < 3 * n; i++)
        if (!(fabs(xyz[i]) <= RS_CONVEX_COORD_MAX))
            return rs_error_set(err, RS_ERR_ARG,
                                "polyhedron point %d is not finite (expected finite "
                                "coordinates of magnitude at most %g)",
                                i / 3 + 1, RS_CONVEX_COORD_MAX);
    shape_init(s, RS_SHAPE_POLYHEDRON, 0.0, 0.0, 0.0, rounding);
    if (rs_cgal_convex_hull(xyz, n, &s->verts, &s->nv, &s->tris, &s->nt, msg, sizeof msg))
        return rs_error_set(err, strstr(msg, "memory") ? RS_ERR_NOMEM : RS_ERR_GEOMETRY,
                            "polyhedron: %s", msg);
    rs_moments m;
    if (rs_hull_adjacency(s) ||
        rs_polytope_moments(s->verts, s->tris, s->nt, rounding, &m)) {
        rs_shape_free(s);
        memset(s, 0, sizeof *s);
        return rs_error_set(err, RS_ERR_NOMEM, "polyhedron: out of memory");
    }
    if (!(m.v > 0.0)) {
        rs_shape_free(s);
        memset(s, 0, sizeof *s);
        return rs_error_set(
            err, RS_ERR_GEOMETRY,
            "polyhedron: the hull of the %d points has volume %g (expected a "
            "volume > 0: the points lie too close to one plane)",
            n, m.v);
    }
    for (int k = 0; k < 3; k++)
        s->shift[k] = m.s[k] / m.v;
    for (int i = 0; i < s->nv; i++)
        for (int k = 0; k < 3; k++)
            s->verts[3 * i + k] -= s->shift[k];
    rs_hull_hints(s);
    set_reach(s);
    return RS_OK;
}

int rs_shape_make_user(rs_shape *s, const void *obj, rs_support_fn support, double rounding,
                       rs_error *err)
{
    if (begin(s, err))
        return RS_ERR_ARG;
    int rc = check_rounding(rounding, err);
    if (rc)
        return rc;
    if (!support)
        return rs_error_set(err, RS_ERR_ARG,
                            "user shape: no support function (expected a callback)");
    shape_init(s, RS_SHAPE_USER, 0.0, 0.0, 0.0, rounding);
    s->obj = obj;
    s->support = support;
    set_reach(s);
    return RS_OK;
}

int rs_shape_check(const rs_shape *s, rs_error *err)
{
    if (!s)
        return rs_error_set(err, RS_ERR_ARG, "shape: NULL argument");
    static const int nd[8] = {1, 3, 3, 2, 2, 2, 0, 0}; /* dimensions of each kind */
    int ok = s->kind >= RS_SHAPE_SPHERE && s->kind <= RS_SHAPE_USER && s->rounding >= 0.0 &&
             s->rounding <= RS_CONVEX_COORD_MAX;
    for (int k = 0; ok && k < nd[s->kind]; k++)
        ok = s->dim[k] > 0.0 && s->dim[k] <= RS_CONVEX_COORD_MAX;
    if (ok && s->kind == RS_SHAPE_POLYHEDRON)
        ok = s->verts && s->tris && s->adj0 && s->adj && s->nv >= 4 && s->nt >= 4;
    if (ok && s->kind == RS_SHAPE_USER)
        ok = s->support != NULL;
    if (!ok)
        return rs_error_set(err, RS_ERR_ARG,
                            "shape: not one an rs_shape_make_* call made (a call that "
                            "fails leaves the shape empty)");
    return RS_OK;
}

void rs_shape_free(rs_shape *s)
{
    if (!s)
        return;
    free(s->verts);
    free(s->tris);
    free(s->adj0);
    free(s->adj);
    s->verts = NULL;
    s->tris = NULL;
    s->adj0 = s->adj = NULL;
    s->nv = s->nt = 0;
}

static double sign1(double x)
{
    return x < 0.0 ? -1.0 : 1.0;
}

void rs_shape_core_support(const rs_shape *s, const double dir[3], double out[3])
{
    double d[3] = {dir[0], dir[1], dir[2]};
    if (d[0] == 0.0 && d[1] == 0.0 && d[2] == 0.0)
        d[2] = 1.0;
    const double *h = s->dim;
    switch (s->kind) {
    case RS_SHAPE_SPHERE:
        out[0] = out[1] = out[2] = 0.0;
        return;
    case RS_SHAPE_ELLIPSOID: { /* along d made unit: no square of d's parts underflows */
        const double dl = rs_norm3(d);
        for (int i = 0; i < 3; i++)
            d[i] /= dl;
        const double e[3] = {h[0] * h[0] * d[0], h[1] * h[1] * d[1], h[2] * h[2] * d[2]};
        const double k = 1.0 / sqrt(rs_dot3(e, d));
        for (int i = 0; i < 3; i++)
            out[i] = k * e[i];
        return;
    }
    case RS_SHAPE_BOX:
        for (int i = 0; i < 3; i++)
            out[i] = sign1(d[i]) * h[i];
        return;
    case RS_SHAPE_CYLINDER:
    case RS_SHAPE_CONE: {
        const double rho = rs_norm2(d[0], d[1]);
        double rim[3] = {0.0, 0.0, 0.0};
        if (rho > 0.0) {
            rim[0] = h[0] * d[0] / rho;
            rim[1] = h[0] * d[1] / rho;
        }
        if (s->kind == RS_SHAPE_CYLINDER) {
            rim[2] = sign1(d[2]) * h[1];
        } else {
            rim[2] = -0.25 * h[1];
            if (0.75 * h[1] * d[2] > rs_dot3(rim, d)) {
                rim[0] = rim[1] = 0.0;
                rim[2] = 0.75 * h[1];
            }
            rim[2] -= s->shift[2];
        }
        out[0] = rim[0];
        out[1] = rim[1];
        out[2] = rim[2];
        return;
    }
    case RS_SHAPE_CAPSULE:
        out[0] = out[1] = 0.0;
        out[2] = sign1(d[2]) * h[1];
        return;
    case RS_SHAPE_POLYHEDRON: {
        const int best = rs_hull_support(s, d);
        for (int k = 0; k < 3; k++)
            out[k] = s->verts[3 * best + k];
        return;
    }
    case RS_SHAPE_USER:
        s->support(s->obj, d, out);
        return;
    }
}

void rs_shape_support(const rs_shape *s, const double dir[3], double out[3])
{
    double d[3] = {dir[0], dir[1], dir[2]};
    const double *h = s->dim;
    if (s->kind == RS_SHAPE_BOX && s->rounding == 0.0) {
        /* the corner, as below (d = 0 gives the corner of d = +z too) */
        for (int k = 0; k < 3; k++)
            out[k] = sign1(d[k]) * h[k];
        return;
    }
    double n = rs_norm3(d);
    if (n > 0.0 && s->kind != RS_SHAPE_POLYHEDRON && s->kind != RS_SHAPE_USER) {
        /* the built-in shapes as below, the core's support inline where it is short and
         * the rounding added where there is one: without it, out + 0 d is out bit for bit
         * (a part of out at 0 is a zero of the sign of d's part, or +0, which a zero
         * added leaves as it is) */
        switch (s->kind) {
        case RS_SHAPE_SPHERE:
            out[0] = out[1] = out[2] = 0.0;
            break;
        case RS_SHAPE_ELLIPSOID: { /* rs_shape_core_support's, d's norm being n */
            const double u[3] = {d[0] / n, d[1] / n, d[2] / n};
            const double e[3] = {h[0] * h[0] * u[0], h[1] * h[1] * u[1],
                                 h[2] * h[2] * u[2]};
            const double k = 1.0 / sqrt(rs_dot3(e, u));
            for (int i = 0; i < 3; i++)
                out[i] = k * e[i];
            break;
        }
        case RS_SHAPE_BOX:
            for (int k = 0; k < 3; k++)
                out[k] = sign1(d[k]) * h[k];
            break;
        case RS_SHAPE_CAPSULE:
            out[0] = out[1] = 0.0, out[2] = sign1(d[2]) * h[1];
            break;
        default: /* a cylinder, a cone */
            rs_shape_core_support(s, d, out);
            break;
        }
        const double rc = rs_shape_core_radius(s);
        if (rc != 0.0) {
            const double r = rc / n;
            for (int k = 0; k < 3; k++)
                out[k] += r * d[k];
        }
        return;
    }
    if (n == 0.0) {
        d[2] = 1.0;
        n = 1.0;
    }
    rs_shape_core_support(s, d, out);
    const double r = rs_shape_core_radius(s) / n;
    for (int k = 0; k < 3; k++)
        out[k] += r * d[k];
}

void rs_shape_bounds(const rs_shape *s, double lo[3], double hi[3])
{
    for (int k = 0; k < 3; k++) {
        double d[3] = {0.0, 0.0, 0.0}, p[3];
        d[k] = 1.0;
        rs_shape_support(s, d, p);
        hi[k] = p[k];
        d[k] = -1.0;
        rs_shape_support(s, d, p);
        lo[k] = p[k];
    }
}

int rs_body_init(rs_body *b, const rs_shape *shape, double density, const double x[3],
                 const double q[4], rs_error *err)
{
    if (!b || !shape || !x || !q)
        return rs_error_set(err, RS_ERR_ARG, "body: NULL argument");
    memset(b, 0, sizeof *b);
    int rc = rs_shape_check(shape, err);
    if (rc)
        return rc;
    for (int k = 0; k < 3; k++)
        if (!(fabs(x[k]) <= RS_CONVEX_COORD_MAX))
            return rs_error_set(
                err, RS_ERR_ARG,
                "body position x[%d] = %g (expected finite, of magnitude at "
                "most %g)",
                k, x[k], RS_CONVEX_COORD_MAX);
    for (int k = 0; k < 4; k++)
        if (!isfinite(q[k]))
            return rs_error_set(err, RS_ERR_ARG,
                                "body quaternion q[%d] = %g (expected finite)", k, q[k]);
    const double nq = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (!(fabs(nq - 1.0) <= 1e-12))
        return rs_error_set(err, RS_ERR_ARG,
                            "body quaternion (w, x, y, z) has norm %.17g (expected a unit "
                            "quaternion to 1e-12)",
                            nq);
    if (!isfinite(density) || density < 0.0)
        return rs_error_set(err, RS_ERR_ARG, "density = %g (expected a finite number >= 0)",
                            density);
    memcpy(b->x, x, sizeof b->x);
    memcpy(b->q, q, sizeof b->q);
    b->shape = shape;
    b->axes[0] = b->axes[4] = b->axes[8] = 1.0;
    if (density > 0.0) {
        rs_mass_props mp;
        rc = rs_shape_mass_props(shape, density, &mp, err);
        if (rc)
            return rc;
        int finite = isfinite(mp.mass);
        for (int k = 0; k < 3; k++)
            finite &= isfinite(mp.principal[k]);
        for (int k = 0; k < 9; k++)
            finite &= isfinite(mp.axes[k]);
        if (!finite)
            return rs_error_set(err, RS_ERR_ARG,
                                "body: the mass properties of the shape with density %g "
                                "are not finite (mass %g): too large a shape or density",
                                density, mp.mass);
        b->mass = mp.mass;
        memcpy(b->inertia, mp.principal, sizeof b->inertia);
        memcpy(b->axes, mp.axes, sizeof b->axes);
    }
    return RS_OK;
}

void rs_body_rotation(const rs_body *b, double R[9])
{
    rs_quat_matrix(b->q, R);
}

void rs_body_support(const rs_body *b, const double dir[3], double out[3])
{
    double R[9];
    rs_body_rotation(b, R);
    rs_body_support_at(b, R, dir, out);
}

void rs_body_support_at(const rs_body *b, const double R[9], const double dir[3],
                        double out[3])
{
    double d[3], p[3];
    for (int i = 0; i < 3; i++)
        d[i] = R[i] * dir[0] + R[3 + i] * dir[1] + R[6 + i] * dir[2];
    rs_shape_support(b->shape, d, p);
    rs_matvec3(R, p, out);
    for (int k = 0; k < 3; k++)
        out[k] += b->x[k];
}
