/* A convex body's manifold on the analytic kinds with the kind's closed form for its
 * core points' balls (rs_surface_ops.body_face: the flat faces of an extruded profile,
 * analytic_surfaces/analytic_body.c) against the manifold whose every ball asks the
 * kind's sphere query (rs_body_manifold_with, no closed form): the same contacts bit for
 * bit, for bodies of every built-in shape in random orientations near profiles with
 * convex and concave corners, fillets, two sides, a bounded extent and a closed loop,
 * under the identity and a moved pose, pressed in, resting and beyond the gap. */
#include "convex_geometry/convex_internal.h"
#include "rigidsurf/convex.h"
#include "rigidsurf/surface.h"
#include "rigidsurf/vec.h"
#define RS_TEST_SEED 0x3C6EF372FE94F82Bull
#include "rs_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *PROFILES[] = {
    "*SURFACE, TYPE=CYLINDER, NAME=plane\n0, 0, 0, 1, 0, 0\n0, -1, 0\n"
    "START, -10, 0\nLINE, 10, 0\n",
    "*SURFACE, TYPE=CYLINDER, NAME=vee\n0, 0, 0, 1, 0, 0\n0, -1, 0\n"
    "START, -0.05, 0.05\nLINE, 0, 0\nLINE, 0.05, 0.05\n",
    "*SURFACE, TYPE=CYLINDER, NAME=step\n0, 0, 0, 1, 0, 0\n0, -1, 0\n"
    "START, -0.05, 0\nLINE, 0, 0\nLINE, 0, -0.05\nLINE, 0.05, -0.05\n",
    "*SURFACE, TYPE=CYLINDER, NAME=trough, FILLET RADIUS=0.005\n0, 0, 0, 1, 0, 0\n"
    "0, -1, 0\nSTART, -0.05, 0.03\nLINE, -0.02, 0\nLINE, 0.02, 0\nLINE, 0.05, 0.03\n",
    "*SURFACE, TYPE=CYLINDER, NAME=two, SIDES=2\n0, 0, 0, 1, 0, 0\n0, -1, 0\n"
    "START, -0.02, 0\nLINE, 0.02, 0\n",
    "*SURFACE, TYPE=CYLINDER, NAME=bounded, EXTENT=-0.01, 0.01\n0, 0, 0, 1, 0, 0\n"
    "0, -1, 0\nSTART, -10, 0\nLINE, 10, 0\n",
    "*SURFACE, TYPE=SEGMENTS, NAME=box\nSTART, -0.03, -0.03\nLINE, 0.03, -0.03\n"
    "LINE, 0.03, 0.03\nLINE, -0.03, 0.03\nLINE, -0.03, -0.03\n",
    "*SURFACE, TYPE=REVOLUTION, NAME=drum\n0, 0, 0, 0, 0, 1\n"
    "START, 0.05, -0.05\nLINE, 0.05, 0.05\n",
};
enum { NPROFILES = sizeof PROFILES / sizeof *PROFILES };

static double urange(double a, double b)
{
    return a + (b - a) * urand();
}

static void random_unit_quaternion(double q[4])
{
    double l = 0.0;
    do {
        l = 0.0;
        for (int k = 0; k < 4; k++) {
            q[k] = urange(-1.0, 1.0);
            l += q[k] * q[k];
        }
    } while (l < 1e-4 || l > 1.0);
    l = sqrt(l);
    for (int k = 0; k < 4; k++)
        q[k] /= l;
}

/* Contacts k of a and b, field by field. */
static int same_row(const rs_contacts *a, const rs_contacts *b, int k)
{
    int same = a->point[k] == b->point[k] && a->feature[k] == b->feature[k] &&
               a->dist[k] == b->dist[k] && a->curv[0][k] == b->curv[0][k] &&
               a->curv[1][k] == b->curv[1][k] && a->share[k] == b->share[k];
    for (int d = 0; d < 3; d++)
        same &= a->xm[d][k] == b->xm[d][k] && a->nrm[d][k] == b->nrm[d][k] &&
                a->t1[d][k] == b->t1[d][k] && a->t2[d][k] == b->t2[d][k] &&
                a->xs[d][k] == b->xs[d][k];
    return same;
}

static int make_shape(int kind, rs_shape *sh, rs_error *e)
{
    switch (kind) {
    case 0:
        return rs_shape_make_sphere(sh, 0.005, 0.0, e);
    case 1:
        return rs_shape_make_ellipsoid(sh, 0.006, 0.004, 0.003, 0.0, e);
    case 2:
        return rs_shape_make_box(sh, 0.005, 0.004, 0.003, 0.0, e);
    case 3:
        return rs_shape_make_box(sh, 0.004, 0.003, 0.002, 0.001, e);
    case 4:
        return rs_shape_make_capsule(sh, 0.003, 0.003, 0.0, e);
    case 5:
        return rs_shape_make_cylinder(sh, 0.004, 0.004, 0.0, e);
    default:
        return rs_shape_make_cone(sh, 0.004, 0.008, 0.0, e);
    }
}

/* Bodies of every built-in shape near each profile, in one block, with and without the
 * kind's closed form: the same contact list bit for bit. On the plane, bodies pressed
 * in the way the benchmark presses them (their lowest point 0.1 mm below it) rest on
 * more than one point, each from the closed form. */
static void test_closed_form_manifold_is_the_querys(void)
{
    enum { N = 300 };
    long contacts = 0, cores = 0;
    for (int p = 0; p < NPROFILES; p++) {
        rs_surface s;
        rs_error e;
        ENSURE(rs_surface_parse(PROFILES[p], "t", NULL, &s, &e) == RS_OK);
        const int seg = s.kind == RS_SURF_SEGMENTS, rev = s.kind == RS_SURF_REVOLUTION;
        for (int moved = 0; moved < 2; moved++) {
            /* the pose: a turn of 0.4 rad about a random axis and a shift */
            rs_pose pose;
            rs_pose_identity(&pose);
            if (moved) {
                double qp[4];
                random_unit_quaternion(qp);
                const double w = qp[0], x = qp[1], y = qp[2], z = qp[3];
                const double R[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),
                                     2 * (x * z + w * y),     2 * (x * y + w * z),
                                     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                                     2 * (x * z - w * y),     2 * (y * z + w * x),
                                     1 - 2 * (x * x + y * y)};
                memcpy(pose.R, R, sizeof R);
                pose.T[0] = 0.01, pose.T[1] = -0.02, pose.T[2] = 0.005;
            }
            rs_body_face face;
            ENSURE(s.ops->body_face != NULL);
            s.ops->body_face(&s, &pose, &face);
            ENSURE(rev == (face.fn == NULL));
            for (int kind = 0; kind < 7; kind++) {
                rs_shape sh;
                ENSURE(make_shape(kind, &sh, &e) == RS_OK);
                rs_body *b = malloc(N * sizeof *b);
                double *r = malloc(N * sizeof *r);
                ENSURE(b && r);
                for (int i = 0; i < N; i++) {
                    double q[4], X[3], x0[3];
                    random_unit_quaternion(q);
                    X[0] = urange(-0.045, 0.045);
                    X[1] = seg ? urange(-0.045, 0.045) : urange(-0.02, 0.02);
                    X[2] = seg ? urange(-0.05, 0.05) : urange(-0.012, 0.04);
                    if (rev) { /* inside the drum, near its mantle */
                        const double ph = urange(0, 2 * RS_PI), rho = urange(0.035, 0.05);
                        X[0] = rho * cos(ph), X[1] = rho * sin(ph),
                        X[2] = urange(-0.04, 0.04);
                    }
                    rs_pose_to_global(&pose, X, x0);
                    ENSURE(rs_body_init(b + i, &sh, 1000.0, x0, q, &e) == RS_OK);
                    r[i] = 0.005;
                    if (p == 0 && i % 2 == 0) { /* resting on the plane, 0.1 mm in */
                        /* the plane's normal: the turned local y, R (0, 0, 1) */
                        double down[3] = {-pose.R[2], -pose.R[5], -pose.R[8]}, low[3];
                        rs_body_support(b + i, down, low);
                        const double h = (low[0] - pose.T[0]) * pose.R[2] +
                                         (low[1] - pose.T[1]) * pose.R[5] +
                                         (low[2] - pose.T[2]) * pose.R[8];
                        for (int k = 0; k < 3; k++)
                            b[i].x[k] -= (h + 1e-4) * pose.R[3 * k + 2];
                    }
                }
                const double gap = 1e-3;
                rs_contacts ca, cb;
                memset(&ca, 0, sizeof ca);
                memset(&cb, 0, sizeof cb);
                ca.witness = cb.witness = 1;
                ENSURE(rs_body_manifold(&s, &pose, b, N, 0, r, gap, &ca, &e) == RS_OK);
                ENSURE(rs_body_manifold_with(&s, &pose, b, N, 0, r, gap, NULL, &cb, &e) ==
                       RS_OK);
                ENSURE(ca.n == cb.n);
                for (int k = 0; k < ca.n && k < cb.n; k++) {
                    ENSURE(same_row(&ca, &cb, k));
                    cores += ca.feature[k] >= RS_MANIFOLD_STRIDE;
                }
                contacts += ca.n;
                rs_contacts_free(&ca);
                rs_contacts_free(&cb);
                free(b), free(r);
                rs_shape_free(&sh);
            }
        }
        rs_surface_free(&s);
    }
    ENSURE(contacts > 10000 && cores > 5000);
}

int main(void)
{
    RS_RUN(test_closed_form_manifold_is_the_querys);
    return rs_test_summary();
}
