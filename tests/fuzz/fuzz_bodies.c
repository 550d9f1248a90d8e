/* The fuzz target's third reading of an input: its bytes as convex bodies (convex.h): a
 * shape of every kind with its dimensions and rounding, a pose, then a second body or a
 * triangle, or a plane, a drum or that drum's MESH the body meets as a slave
 * (rs_body_query). Either a
 * maker or rs_body_init refuses with a code and a message, or the pair query answers
 * with a state and finite values: the depth always, and the normal (unit) and witness
 * points of a contact within reach; the wall's contacts are finite throughout. */
#include "fuzz_bytes.h"
#include "fuzz_surface.h"

#include "rigidsurf/convex.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

long rs_fuzz_bodies_queried;

static int refused(int rc, const rs_error *e, const char *what)
{
    if (e->code != rc || e->msg[0] == '\0') {
        fprintf(stderr, "fuzz_bodies: %s refused without a message (code %d)\n", what, rc);
        return 1;
    }
    return 0;
}

/* A user shape: the core of a box of the half-extents obj points to. */
static void box_support(const void *obj, const double d[3], double out[3])
{
    const double *h = (const double *)obj;
    for (int k = 0; k < 3; k++)
        out[k] = d[k] >= 0.0 ? h[k] : -h[k];
}

/* A shape of the kind the next byte picks, from the bytes; 0 made, 1 a failure of the
 * target, 2 refused as it should be. */
static int shape(bytes *b, rs_shape *s, double user_h[3])
{
    const unsigned kind = next(b) % 8;
    double d0 = value(b), d1 = value(b), d2 = value(b), r = value(b);
    if (next(b) % 4) { /* mostly lengths a shape may have, now and then any */
        d0 = fabs(d0), d1 = fabs(d1), d2 = fabs(d2), r = fabs(r);
    }
    if (next(b) % 2) /* half of them not rounded */
        r = 0.0;
    rs_error e;
    rs_error_clear(&e);
    int rc;
    switch (kind) {
    case RS_SHAPE_SPHERE:
        rc = rs_shape_make_sphere(s, d0, r, &e);
        break;
    case RS_SHAPE_ELLIPSOID:
        rc = rs_shape_make_ellipsoid(s, d0, d1, d2, r, &e);
        break;
    case RS_SHAPE_BOX:
        rc = rs_shape_make_box(s, d0, d1, d2, r, &e);
        break;
    case RS_SHAPE_CYLINDER:
        rc = rs_shape_make_cylinder(s, d0, d1, r, &e);
        break;
    case RS_SHAPE_CAPSULE:
        rc = rs_shape_make_capsule(s, d0, d1, r, &e);
        break;
    case RS_SHAPE_CONE:
        rc = rs_shape_make_cone(s, d0, d1, r, &e);
        break;
    case RS_SHAPE_POLYHEDRON: {
        enum { MAXP = 12 };
        double xyz[3 * MAXP];
        const int n = 1 + (int)(next(b) % MAXP);
        for (int i = 0; i < 3 * n; i++)
            xyz[i] = value(b);
        rc = rs_shape_make_polyhedron(s, xyz, n, r, &e);
        break;
    }
    default:
        user_h[0] = fabs(d0), user_h[1] = fabs(d1), user_h[2] = fabs(d2);
        rc = rs_shape_make_user(s, user_h, box_support, r, &e);
        break;
    }
    if (rc != RS_OK)
        return refused(rc, &e, "a shape") ? 1 : 2;
    return 0;
}

/* A pose: a position and a quaternion, mostly made unit, now and then left as read. */
static int body(bytes *b, const rs_shape *s, rs_body *out)
{
    double x[3], q[4];
    for (int k = 0; k < 3; k++)
        x[k] = value(b);
    for (int k = 0; k < 4; k++)
        q[k] = value(b);
    const double nq = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (next(b) % 8 != 0 && nq > 0.0 && isfinite(nq))
        for (int k = 0; k < 4; k++)
            q[k] /= nq;
    rs_error e;
    rs_error_clear(&e);
    const int rc = rs_body_init(out, s, 1000.0, x, q, &e);
    if (rc != RS_OK)
        return refused(rc, &e, "a body") ? 1 : 2;
    return 0;
}

static int check(int rc, const rs_error *e, const rs_convex_contact *c, const char *what)
{
    if (rc != RS_OK)
        return refused(rc, e, what);
    rs_fuzz_bodies_queried++;
    int bad = !(c->state == RS_CONVEX_APART || c->state == RS_CONVEX_NEAR ||
                c->state == RS_CONVEX_OVERLAP) ||
              isnan(c->depth);
    if (!bad && c->state != RS_CONVEX_APART) {
        const double n2 = c->normal[0] * c->normal[0] + c->normal[1] * c->normal[1] +
                          c->normal[2] * c->normal[2];
        bad |= !isfinite(c->depth) || !(fabs(n2 - 1.0) < 1e-9);
        for (int k = 0; k < 3; k++)
            bad |= !isfinite(c->pa[k]) || !isfinite(c->pb[k]);
    }
    if (bad)
        fprintf(
            stderr,
            "fuzz_bodies: %s: state %d, depth %g, normal (%g, %g, %g), pa (%g, %g, %g)\n",
            what, c->state, c->depth, c->normal[0], c->normal[1], c->normal[2], c->pa[0],
            c->pa[1], c->pa[2]);
    return bad;
}

/* The surfaces a body meets: a plane, the main job's drum (fillets) and, third, that
 * drum's display triangulation as a MESH (concave folds between its facets). */
static const char *const WALLS[2] = {
    "*SURFACE, TYPE=CYLINDER, NAME=floor\n0, 0, 0, 1, 0, 0\n0, -1, 0\nSTART, -10, 0\n"
    "LINE, 10, 0\n",
    "*SURFACE, TYPE=REVOLUTION, NAME=drum, FILLET RADIUS=0.005\n0, 0, 0,  0, 0, 1\n"
    "START, 0, 0\nLINE, 0.1, 0\nLINE, 0.1, 0.06\nLINE, 0, 0.06\n"};

/* The body as a slave (rs_body_query) of one of WALLS: refused with a message, or
 * contacts whose values are all finite, normals unit, shares in (0, 1]. */
static int wall_contacts(const rs_body *a, unsigned which, double gap_max)
{
    static rs_surface walls[3];
    static int made[3];
    rs_error e;
    rs_error_clear(&e);
    if (!made[which]) {
        int rc = rs_surface_parse(WALLS[which % 2], "fuzz", NULL, &walls[which], &e);
        if (rc == RS_OK && which == 2) {
            rs_surface drum = walls[which];
            rs_trimesh tm;
            const rs_mesh_def def = RS_MESH_DEF_INIT;
            rc = rs_surface_triangulate(&drum, 0.02, 24, &tm, &e);
            if (rc == RS_OK)
                rc = rs_surface_make_mesh(tm.xyz, tm.nvert, tm.tri, tm.ntri, &def,
                                          &walls[which], &e);
            rs_trimesh_free(&tm);
            rs_surface_free(&drum);
        }
        if (rc != RS_OK) {
            fprintf(stderr, "fuzz_bodies: wall %u: %s\n", which, e.msg);
            return 1;
        }
        made[which] = 1;
    }
    rs_contacts c;
    memset(&c, 0, sizeof c);
    c.witness = 1;
    const int rc = rs_body_query(&walls[which], NULL, a, 0, 0.01, gap_max, &c, &e);
    int bad = 0;
    if (rc != RS_OK) {
        bad = refused(rc, &e, "a body against a wall");
    } else {
        rs_fuzz_bodies_queried++;
        for (int k = 0; k < c.n && !bad; k++) {
            double n2 = 0.0;
            for (int d = 0; d < 3; d++) {
                n2 += c.nrm[d][k] * c.nrm[d][k];
                bad |= !isfinite(c.xs[d][k]) || !isfinite(c.xm[d][k]);
            }
            bad |= !isfinite(c.dist[k]) || !(fabs(n2 - 1.0) < 1e-9) ||
                   !(c.share[k] > 0.0 && c.share[k] <= 1.0) || c.point[k] != 0;
            if (bad)
                fprintf(stderr, "fuzz_bodies: wall %u contact %d: dist %g, |n|^2 %g\n",
                        which, k, c.dist[k], n2);
        }
    }
    rs_contacts_free(&c);
    return bad;
}

int rs_fuzz_bodies_one(const uint8_t *data, size_t size)
{
    bytes b = {data, size, 0};
    rs_shape sa, sb;
    memset(&sa, 0, sizeof sa);
    memset(&sb, 0, sizeof sb);
    double ha[3], hb[3];
    int fail = 0, r = shape(&b, &sa, ha);
    if (r != 0)
        return r == 1;
    rs_body a, other;
    r = body(&b, &sa, &a);
    if (r == 0) {
        const double gap_max = fabs(value(&b));
        rs_convex_contact c;
        rs_error e;
        rs_error_clear(&e);
        const unsigned pick = next(&b) % 5;
        if (pick >= 2) {
            fail = wall_contacts(&a, pick - 2, gap_max);
        } else if (pick) {
            double tri[9];
            for (int k = 0; k < 9; k++)
                tri[k] = value(&b);
            fail = check(rs_convex_triangle(&a, tri, gap_max, &c, &e), &e, &c, "triangle");
        } else if ((r = shape(&b, &sb, hb)) == 0) {
            r = body(&b, &sb, &other);
            if (r == 0)
                fail = check(rs_convex_pair(&a, &other, gap_max, &c, &e), &e, &c, "pair");
            fail |= r == 1;
        } else {
            fail = r == 1;
        }
    } else {
        fail = r == 1;
    }
    rs_shape_free(&sa);
    rs_shape_free(&sb);
    return fail;
}
