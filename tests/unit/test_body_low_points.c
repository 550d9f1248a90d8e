/* A box's, a cylinder's and a cone's manifold on a plane against their core points'
 * heights computed here: the manifold holds exactly the core points within the gap
 * (the RS_MANIFOLD_MAX deepest), each at its depth to rounding, for bodies lying nearly
 * flat on a face, an end or a side, tilted by 1e-7 to 0.03 rad, so that the points
 * beside the lowest lie just inside, at and just outside the gap, and for bodies in
 * random orientations. The manifold passes over points clearly out of reach without
 * measuring them (body_manifold.c, low_points): none it keeps may go missing. A block of
 * bodies, whose runs share the manifold's work arrays, gives each body's contacts as it
 * alone does. */
#include "rigidsurf/convex.h"
#include "rigidsurf/surface.h"
#include "rigidsurf/vec.h"
#define RS_TEST_SEED 0xBB67AE8584CAA73Bull
#include "rs_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *PLANE = "*SURFACE, TYPE=CYLINDER, NAME=floor\n"
                           "0, 0, 0, 1, 0, 0\n0, -1, 0\nSTART, -10, 0\nLINE, 10, 0\n";

/* q = a * b (w, x, y, z). */
static void qmul(const double a[4], const double b[4], double q[4])
{
    q[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    q[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    q[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
    q[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
}

/* The core points of the shape (kind 0 box, 1 cylinder, 2 cone) in the body frame for
 * the body-frame direction d into the wall, with their ids (convex.h, RS_MANIFOLD_IDS):
 * a box's corners; a cylinder's and a cone's rim points from the rim's lowest in
 * quarter turns, a cone's apex. */
static int core(int kind, const rs_shape *sh, const double d[3], double p[][3], int *id)
{
    const double *h = sh->dim;
    if (kind == 0) {
        for (int v = 0; v < 8; v++) {
            p[v][0] = (v & 1) ? h[0] : -h[0];
            p[v][1] = (v & 2) ? h[1] : -h[1];
            p[v][2] = (v & 4) ? h[2] : -h[2];
            id[v] = 1 + v;
        }
        return 8;
    }
    const double rho = hypot(d[0], d[1]);
    const double c0 = rho > 0.0 ? d[0] / rho : 1.0, s0 = rho > 0.0 ? d[1] / rho : 0.0;
    const double cs[4][2] = {{c0, s0}, {-s0, c0}, {-c0, -s0}, {s0, -c0}};
    int n = 0;
    for (int e = 0; e < (kind == 1 ? 2 : 1); e++)
        for (int k = 0; k < 4; k++, n++) {
            p[n][0] = h[0] * cs[k][0];
            p[n][1] = h[0] * cs[k][1];
            p[n][2] = kind == 1 ? (e ? -h[1] : h[1]) : -0.25 * h[1] - sh->shift[2];
            id[n] = 1 + 4 * e + k;
        }
    if (kind == 2) {
        p[n][0] = p[n][1] = 0.0;
        p[n][2] = 0.75 * h[1] - sh->shift[2];
        id[n++] = 5;
    }
    return n;
}

static void test_manifold_on_a_plane_is_the_core_points_within_the_gap(void)
{
    rs_surface s;
    rs_error e;
    ENSURE(rs_surface_parse(PLANE, "t", NULL, &s, &e) == RS_OK);
    const double gap = 1e-3;
    long trials = 0, several = 0, beside = 0;
    for (int kind = 0; kind < 3; kind++) {
        rs_shape sh;
        ENSURE((kind == 0   ? rs_shape_make_box(&sh, 0.005, 0.004, 0.003, 0.0, &e)
                : kind == 1 ? rs_shape_make_cylinder(&sh, 0.004, 0.004, 0.0, &e)
                            : rs_shape_make_cone(&sh, 0.004, 0.008, 0.0, &e)) == RS_OK);
        for (int it = 0; it < 6000; it++) {
            /* a quarter-turn orientation (a face, an end or a side down) tilted a little
             * about a random axis, or (one in six) a random one */
            static const double Q[6][4] = {
                {1, 0, 0, 0},
                {0.70710678118654752, 0.70710678118654752, 0, 0},
                {0.70710678118654752, 0, 0.70710678118654752, 0},
                {0, 1, 0, 0},
                {0.70710678118654752, -0.70710678118654752, 0, 0},
                {0.70710678118654752, 0, -0.70710678118654752, 0}};
            double q[4], ax[3], la = 0.0;
            for (int k = 0; k < 3; k++) {
                ax[k] = urange(-1, 1);
                la += ax[k] * ax[k];
            }
            la = sqrt(la);
            const double th = it % 6 == 5 ? urange(0, RS_PI) : pow(10.0, urange(-7, -1.5));
            const double tilt[4] = {cos(th / 2), sin(th / 2) * ax[0] / la,
                                    sin(th / 2) * ax[1] / la, sin(th / 2) * ax[2] / la};
            qmul(tilt, Q[it % 6], q);
            const double nq = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
            for (int k = 0; k < 4; k++)
                q[k] /= nq;
            const double x0[3] = {urange(-1, 1), urange(-1, 1), 0.0};
            rs_body b;
            ENSURE(rs_body_init(&b, &sh, 1000.0, x0, q, &e) == RS_OK);
            double R[9];
            rs_body_rotation(&b, R);
            /* the body-frame direction into the wall, d = R^T (0, 0, -1) */
            const double d[3] = {-R[6], -R[7], -R[8]};
            double p[9][3];
            int id[9];
            const int np = core(kind, &sh, d, p, id);
            double lz[9], low = INFINITY;
            for (int j = 0; j < np; j++) {
                lz[j] = R[6] * p[j][0] + R[7] * p[j][1] + R[8] * p[j][2];
                low = fmin(low, lz[j]);
            }
            b.x[2] = -low - urange(1e-5, 1e-4);
            /* each point's depth; the expected: those within the gap, the deepest first
             * (ties by id), at most RS_MANIFOLD_MAX; a point within rounding of the gap's
             * edge leaves the trial undecided */
            double dep[9];
            int order[9], m = 0, edge = 0;
            for (int j = 0; j < np; j++) {
                dep[j] = -(b.x[2] + lz[j]);
                edge |= fabs(dep[j] + gap) < 1e-12;
                if (dep[j] >= -gap)
                    order[m++] = j;
            }
            if (edge)
                continue;
            for (int a = 1; a < m; a++)
                for (int c = a; c > 0; c--) {
                    const int u = order[c - 1], v = order[c];
                    if (dep[u] > dep[v] || (dep[u] == dep[v] && id[u] < id[v]))
                        break;
                    order[c - 1] = v, order[c] = u;
                }
            /* points tied in depth to rounding may come in either order: compare as sets
             * when the RS_MANIFOLD_MAX-th and the next are that close */
            if (m > RS_MANIFOLD_MAX &&
                dep[order[RS_MANIFOLD_MAX - 1]] - dep[order[RS_MANIFOLD_MAX]] < 1e-12)
                continue;
            const int want = m < RS_MANIFOLD_MAX ? m : RS_MANIFOLD_MAX;
            rs_contacts c;
            memset(&c, 0, sizeof c);
            c.witness = 1;
            ENSURE(rs_body_query(&s, NULL, &b, 0, 0.0, gap, &c, &e) == RS_OK);
            ENSURE(c.n == want);
            for (int k = 0; k < want && k < c.n; k++) {
                const int j = order[k];
                int at = -1;
                for (int l = 0; l < c.n; l++)
                    if (c.feature[l] / RS_MANIFOLD_STRIDE == id[j])
                        at = l;
                ENSURE(at >= 0);
                if (at >= 0)
                    ENSURE_NEAR(-c.dist[at], dep[j], 1e-15);
                beside += k > 0 && dep[j] < -0.5 * gap;
            }
            several += want > 1;
            trials++;
            rs_contacts_free(&c);
        }
        rs_shape_free(&sh);
    }
    rs_surface_free(&s);
    ENSURE(trials > 15000 && several > 3000 && beside > 300);
}

/* A block of 1000 bodies, a shape a run, in one rs_surface_query, whose runs share
 * work arrays kept over the block, against each body alone through rs_body_query: the
 * same contacts bit for bit, on a plane and a filleted trough. */
static void test_a_block_is_its_bodies_alone(void)
{
    static const char *TROUGH =
        "*SURFACE, TYPE=CYLINDER, NAME=trough, FILLET RADIUS=0.005\n0, 0, 0, 1, 0, 0\n"
        "0, -1, 0\nSTART, -0.05, 0.03\nLINE, -0.02, 0\nLINE, 0.02, 0\nLINE, 0.05, 0.03\n";
    enum { N = 1000 };
    rs_shape sh[4];
    rs_error e;
    ENSURE(rs_shape_make_box(&sh[0], 0.005, 0.004, 0.003, 0.0, &e) == RS_OK);
    ENSURE(rs_shape_make_cylinder(&sh[1], 0.004, 0.004, 0.0, &e) == RS_OK);
    ENSURE(rs_shape_make_cone(&sh[2], 0.004, 0.008, 0.0, &e) == RS_OK);
    ENSURE(rs_shape_make_ellipsoid(&sh[3], 0.006, 0.004, 0.003, 0.0, &e) == RS_OK);
    rs_body *b = malloc(N * sizeof *b);
    double *x = malloc(4 * N * sizeof *x), *y = x + N, *z = y + N, *r = z + N;
    ENSURE(b && x);
    long total = 0;
    for (int p = 0; p < 2; p++) {
        rs_surface s;
        ENSURE(rs_surface_parse(p ? TROUGH : PLANE, "t", NULL, &s, &e) == RS_OK);
        for (int i = 0; i < N; i++) {
            double q[4], l = 0.0;
            for (int k = 0; k < 4; k++) {
                q[k] = urange(-1, 1);
                l += q[k] * q[k];
            }
            l = sqrt(l);
            for (int k = 0; k < 4; k++)
                q[k] /= l;
            /* a shape a run of RS_BLOCK bodies (as rs_surface_query cuts them), each
             * in front of the wall: a body's windows (its run's largest reach) are then
             * its own */
            const rs_shape *shape = &sh[(i / RS_BLOCK + p) % 4];
            const double x0[3] = {urange(-0.02, 0.02), urange(-0.02, 0.02),
                                  urange(0.0, 0.01)};
            ENSURE(rs_body_init(b + i, shape, 1000.0, x0, q, &e) == RS_OK);
            x[i] = x0[0], y[i] = x0[1], z[i] = x0[2], r[i] = 0.005;
        }
        rs_query qy;
        memset(&qy, 0, sizeof qy);
        qy.n = N;
        qy.slave.x = x, qy.slave.y = y, qy.slave.z = z, qy.slave.radius = r;
        qy.slave.body = b;
        qy.gap_max = 1e-3;
        qy.dist_min = -INFINITY;
        rs_contacts all, one;
        memset(&all, 0, sizeof all);
        memset(&one, 0, sizeof one);
        all.witness = one.witness = 1;
        ENSURE(rs_surface_query(&s, &qy, &all, &e) == RS_OK);
        int k = 0;
        for (int i = 0; i < N; i++) {
            one.n = 0;
            ENSURE(rs_body_query(&s, NULL, b + i, i, 0.005, 1e-3, &one, &e) == RS_OK);
            for (int j = 0; j < one.n; j++, k++) {
                ENSURE(k < all.n);
                if (k >= all.n)
                    break;
                int same = all.point[k] == i && all.feature[k] == one.feature[j] &&
                           all.dist[k] == one.dist[j] && all.share[k] == one.share[j] &&
                           all.curv[0][k] == one.curv[0][j] &&
                           all.curv[1][k] == one.curv[1][j];
                for (int d = 0; d < 3; d++)
                    same &= all.xm[d][k] == one.xm[d][j] &&
                            all.nrm[d][k] == one.nrm[d][j] &&
                            all.t1[d][k] == one.t1[d][j] && all.t2[d][k] == one.t2[d][j] &&
                            all.xs[d][k] == one.xs[d][j];
                ENSURE(same);
            }
        }
        ENSURE(k == all.n);
        total += all.n;
        rs_contacts_free(&all);
        rs_contacts_free(&one);
        rs_surface_free(&s);
    }
    ENSURE(total > 400);
    free(b), free(x);
    for (int k = 0; k < 4; k++)
        rs_shape_free(&sh[k]);
}

int main(void)
{
    RS_RUN(test_manifold_on_a_plane_is_the_core_points_within_the_gap);
    RS_RUN(test_a_block_is_its_bodies_alone);
    return rs_test_summary();
}
