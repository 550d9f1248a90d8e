/* Frame conventions (docs/conventions.md, "Profiles and surfaces"): {n, t1, t2} orthonormal
 * and right-handed; SEGMENTS t1 = (0,0,-1) x n; CYLINDER t1 = generator; REVOLUTION
 * t2 = hoop; FACETED t1 = global x on the tangent plane; the frame turns with the
 * master under a pose. */
#include "rigidsurf/surface.h"
#define RS_TEST_SEED 0x9E3779B97F4A7C15ull
#include "rs_test.h"
#include "rs_test_geom.h"

#include <math.h>
#include <stdlib.h>

/* Rotation by angle about a unit axis, written out here (Rodrigues), row-major. */
static void rotation(const double ax[3], double ang, double R[9])
{
    double c = cos(ang), s = sin(ang), C = 1.0 - c;
    double x = ax[0], y = ax[1], z = ax[2];
    double M[9] = {c + x * x * C,     x * y * C - z * s, x * z * C + y * s,
                   y * x * C + z * s, c + y * y * C,     y * z * C - x * s,
                   z * x * C - y * s, z * y * C + x * s, c + z * z * C};
    for (int i = 0; i < 9; i++)
        R[i] = M[i];
}

static void get(const rs_contacts *c, double *const v[3], int k, double out[3])
{
    (void)c;
    out[0] = v[0][k];
    out[1] = v[1][k];
    out[2] = v[2][k];
}

/* Checks every contact's frame: unit, orthogonal, n x t1 = t2. Returns 0 on failure. */
static int frames_orthonormal(const rs_contacts *c)
{
    for (int k = 0; k < c->n; k++) {
        double n[3], t1[3], t2[3], x[3];
        get(c, c->nrm, k, n);
        get(c, c->t1, k, t1);
        get(c, c->t2, k, t2);
        if (!(fabs(rs_dot3(n, n) - 1.0) <= 1e-12 && fabs(rs_dot3(t1, t1) - 1.0) <= 1e-12 &&
              fabs(rs_dot3(t2, t2) - 1.0) <= 1e-12))
            return 0;
        if (!(fabs(rs_dot3(n, t1)) <= 1e-12 && fabs(rs_dot3(n, t2)) <= 1e-12 &&
              fabs(rs_dot3(t1, t2)) <= 1e-12))
            return 0;
        rs_cross3(n, t1, x);
        for (int d = 0; d < 3; d++)
            if (!(fabs(x[d] - t2[d]) <= 1e-12))
                return 0;
    }
    return 1;
}

#define NPTS 100000

static const char *SEGMENTS_TXT = "*SURFACE, TYPE=SEGMENTS, NAME=s\n"
                                  "START, -2, 1\nLINE, -1, 0\nCIRCL, 1, 0, 0, -1\n"
                                  "PARAB, 1.5, -0.2, 2, 0.5\nLINE, 3, 0.5\n";
static const char *CYLINDER_TXT = "*SURFACE, TYPE=CYLINDER, NAME=c, SIDES=2\n"
                                  "1, 2, 3, 2, 2.5, 3.2\n0.7, 2.3, 4.1\n"
                                  "START, -1, 0\nLINE, 0, 0.5\nCIRCL, 1, 0.5, 0.5, 1.2\n";
static const char *REVOLUTION_TXT = "*SURFACE, TYPE=REVOLUTION, NAME=r, FILLET RADIUS=0.1\n"
                                    "0.5, -1, 2, 1.1, -0.2, 2.9\n"
                                    "START, 0, 0\nLINE, 1, 0\nLINE, 1, 2\nLINE, 0.3, 3\n";

static void random_points(double *x, double *y, double *z, double span)
{
    for (int i = 0; i < NPTS; i++) {
        x[i] = span * (2.0 * urand() - 1.0);
        y[i] = span * (2.0 * urand() - 1.0);
        z[i] = span * (2.0 * urand() - 1.0);
    }
}

static void test_frame_segments_t1_is_minus_z_cross_n(void)
{
    rs_surface s;
    ENSURE(parse(SEGMENTS_TXT, &s) == 0);
    ENSURE(rs_surface_ndir(&s) == 2);
    double *x = malloc(3 * NPTS * sizeof *x), *y = x + NPTS, *z = y + NPTS;
    random_points(x, y, z, 3.0);
    rs_query q = {.n = NPTS,
                  .slave = {.x = x, .y = y, .z = z},
                  .pose = NULL,
                  .gap_max = INFINITY,
                  .dist_min = -INFINITY};
    rs_contacts c = {0};
    int rc = rs_surface_query(&s, &q, &c, NULL);
    ENSURE(rc == 0 && c.n >= NPTS / 2);
    ENSURE(frames_orthonormal(&c));
    const double mz[3] = {0, 0, -1};
    for (int k = 0; k < c.n; k++) {
        double n[3], t1[3];
        get(&c, c.nrm, k, n);
        rs_cross3(mz, n, t1);
        ENSURE(n[2] == 0.0);
        for (int d = 0; d < 3; d++) {
            ENSURE_SMALL(c.t1[d][k] - t1[d], 1e-15);
            ENSURE(c.t2[d][k] == mz[d]);
        }
        ENSURE(c.xm[2][k] == z[c.point[k]]); /* xm keeps the point's z */
    }
    free(x);
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

static void test_frame_cylinder_t1_is_generator(void)
{
    rs_surface s;
    ENSURE(parse(CYLINDER_TXT, &s) == 0);
    ENSURE(rs_surface_ndir(&s) == 3);
    /* generator: c - a made orthogonal to b - a, computed here */
    double a[3] = {1, 2, 3}, ab[3] = {1, 0.5, 0.2}, ac[3] = {-0.3, 0.3, 1.1}, gen[3];
    unit(ab);
    double k = rs_dot3(ac, ab);
    for (int d = 0; d < 3; d++)
        gen[d] = ac[d] - k * ab[d];
    unit(gen);
    double *x = malloc(3 * NPTS * sizeof *x), *y = x + NPTS, *z = y + NPTS;
    random_points(x, y, z, 3.0);
    for (int i = 0; i < NPTS; i++) {
        x[i] += a[0];
        y[i] += a[1];
        z[i] += a[2];
    }
    rs_query q = {.n = NPTS,
                  .slave = {.x = x, .y = y, .z = z},
                  .pose = NULL,
                  .gap_max = INFINITY,
                  .dist_min = -INFINITY};
    rs_contacts c = {0};
    ENSURE(rs_surface_query(&s, &q, &c, NULL) == 0 && c.n >= NPTS);
    ENSURE(frames_orthonormal(&c));
    for (int m = 0; m < c.n; m++) {
        double n[3];
        get(&c, c.nrm, m, n);
        ENSURE_SMALL(rs_dot3(n, gen), 1e-12);
        for (int d = 0; d < 3; d++)
            ENSURE_SMALL(c.t1[d][m] - gen[d], 1e-12);
        /* two-sided: n points to the point's side, dist >= 0 */
        int i = c.point[m];
        double w[3] = {x[i] - c.xm[0][m], y[i] - c.xm[1][m], z[i] - c.xm[2][m]};
        ENSURE(c.dist[m] >= 0.0);
        ENSURE_NEAR(rs_dot3(w, n), c.dist[m], 1e-12 * 4.0);
    }
    free(x);
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

static void test_frame_revolution_t2_is_hoop(void)
{
    rs_surface s;
    ENSURE(parse(REVOLUTION_TXT, &s) == 0);
    double a[3] = {0.5, -1, 2}, ez[3] = {0.6, 0.8, 0.9};
    unit(ez);
    double *x = malloc(3 * NPTS * sizeof *x), *y = x + NPTS, *z = y + NPTS;
    random_points(x, y, z, 3.0);
    for (int i = 0; i < NPTS; i++) {
        x[i] += a[0];
        y[i] += a[1];
        z[i] += a[2];
    }
    rs_query q = {.n = NPTS,
                  .slave = {.x = x, .y = y, .z = z},
                  .pose = NULL,
                  .gap_max = INFINITY,
                  .dist_min = -INFINITY};
    rs_contacts c = {0};
    ENSURE(rs_surface_query(&s, &q, &c, NULL) == 0 && c.n >= NPTS / 2);
    ENSURE(frames_orthonormal(&c));
    for (int m = 0; m < c.n; m++) {
        int i = c.point[m];
        double w[3] = {x[i] - a[0], y[i] - a[1], z[i] - a[2]}, er[3], hoop[3];
        double zz = rs_dot3(w, ez);
        for (int d = 0; d < 3; d++)
            er[d] = w[d] - zz * ez[d];
        double r = sqrt(rs_dot3(er, er));
        if (r < 1e-6)
            continue;
        unit(er);
        rs_cross3(ez, er, hoop);
        for (int d = 0; d < 3; d++)
            ENSURE_SMALL(c.t2[d][m] - hoop[d], 1e-12);
        double n[3], t1[3], t2[3];
        get(&c, c.nrm, m, n);
        get(&c, c.t2, m, t2);
        rs_cross3(t2, n, t1);
        for (int d = 0; d < 3; d++)
            ENSURE_SMALL(c.t1[d][m] - t1[d], 1e-12);
    }
    free(x);
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* Points on the axis get a finite frame, the same for every such point, never NaN. */
static void test_frame_revolution_axis_is_finite_and_deterministic(void)
{
    rs_surface s;
    ENSURE(parse(REVOLUTION_TXT, &s) == 0);
    double a[3] = {0.5, -1, 2}, ez[3] = {0.6, 0.8, 0.9};
    unit(ez);
    double x[8], y[8], z[8];
    for (int i = 0; i < 8; i++) {
        double h = 0.2 + 0.3 * i;
        x[i] = a[0] + h * ez[0];
        y[i] = a[1] + h * ez[1];
        z[i] = a[2] + h * ez[2];
    }
    rs_query q = {.n = 8,
                  .slave = {.x = x, .y = y, .z = z},
                  .pose = NULL,
                  .gap_max = INFINITY,
                  .dist_min = -INFINITY};
    rs_contacts c = {0};
    ENSURE(rs_surface_query(&s, &q, &c, NULL) == 0);
    ENSURE(c.n >= 8);
    ENSURE(frames_orthonormal(&c));
    for (int m = 0; m < c.n; m++) {
        for (int d = 0; d < 3; d++) {
            ENSURE(isfinite(c.xm[d][m]) && isfinite(c.nrm[d][m]));
            ENSURE(isfinite(c.t1[d][m]) && isfinite(c.t2[d][m]));
            ENSURE(c.t2[d][m] == c.t2[d][0]); /* the same hoop for every axis point */
        }
        ENSURE(isfinite(c.curv[0][m]) && isfinite(c.curv[1][m]));
    }
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* A REVOLUTION's local x, the direction e_r takes on its axis, is the global axis least
 * aligned with the symmetry axis (the first of x, y, z on a tie), made normal to it: for
 * an axis along z or y, global x; along x, global y. A point on the axis of a disc facing
 * +z_local has t2 = z_local x e_r, t1 = t2 x n. */
static void test_frame_revolution_local_x_on_the_axis(void)
{
    static const struct {
        double axis[3], ex[3];
    } CASE[] = {{{0, 0, 1}, {1, 0, 0}},
                {{0, 2, 0}, {1, 0, 0}},
                {{3, 0, 0}, {0, 1, 0}},
                {{0, 0, -1}, {1, 0, 0}},
                {{1, 1, 1}, {2, -1, -1}}};
    for (size_t i = 0; i < sizeof CASE / sizeof CASE[0]; i++) {
        char txt[200];
        const double *b = CASE[i].axis;
        snprintf(txt, sizeof txt,
                 "*SURFACE, TYPE=REVOLUTION, NAME=d\n0, 0, 0, %g, %g, %g\n"
                 "START, 0, 0\nLINE, 1, 0\n",
                 b[0], b[1], b[2]);
        rs_surface s;
        ENSURE(parse(txt, &s) == 0);
        double ez[3] = {b[0], b[1], b[2]},
               ex[3] = {CASE[i].ex[0], CASE[i].ex[1], CASE[i].ex[2]};
        unit(ez);
        unit(ex);
        double x = 0.5 * ez[0], y = 0.5 * ez[1], z = 0.5 * ez[2], t2[3], t1[3];
        rs_cross3(ez, ex, t2);
        rs_cross3(t2, ez, t1); /* n = +z_local */
        rs_query q = {.n = 1,
                      .slave = {.x = &x, .y = &y, .z = &z},
                      .pose = NULL,
                      .gap_max = INFINITY,
                      .dist_min = -INFINITY};
        rs_contacts c = {0};
        ENSURE(rs_surface_query(&s, &q, &c, NULL) == 0 && c.n == 1);
        for (int d = 0; d < 3; d++) {
            ENSURE_SMALL(s.ex[d] - ex[d], 1e-15);
            ENSURE_SMALL(c.t1[d][0] - t1[d], 1e-15);
            ENSURE_SMALL(c.t2[d][0] - t2[d], 1e-15);
        }
        rs_contacts_free(&c);
        rs_surface_free(&s);
    }
}

/* Under a pose x = R X + T the contacts of x are the rotated contacts of X. */
static void pose_check(const char *txt, int planar)
{
    rs_surface s;
    ENSURE(parse(txt, &s) == 0);
    double ax[3] = {0.3, -0.5, 0.8};
    if (planar) {
        ax[0] = ax[1] = 0.0;
        ax[2] = 1.0;
    }
    unit(ax);
    rs_pose pose;
    rotation(ax, 0.7, pose.R);
    pose.T[0] = 0.4;
    pose.T[1] = -1.2;
    pose.T[2] = 2.5;
    enum { N = 20000 };
    static double X[N], Y[N], Z[N], x[N], y[N], z[N];
    for (int i = 0; i < N; i++) {
        X[i] = 3.0 * (2.0 * urand() - 1.0);
        Y[i] = 3.0 * (2.0 * urand() - 1.0);
        Z[i] = 3.0 * (2.0 * urand() - 1.0);
        double P[3] = {X[i], Y[i], Z[i]};
        const double *R = pose.R;
        x[i] = R[0] * P[0] + R[1] * P[1] + R[2] * P[2] + pose.T[0];
        y[i] = R[3] * P[0] + R[4] * P[1] + R[5] * P[2] + pose.T[1];
        z[i] = R[6] * P[0] + R[7] * P[1] + R[8] * P[2] + pose.T[2];
    }
    rs_query q0 = {.n = N,
                   .slave = {.x = X, .y = Y, .z = Z},
                   .pose = NULL,
                   .gap_max = 0.5,
                   .dist_min = -INFINITY};
    rs_query q1 = {.n = N,
                   .slave = {.x = x, .y = y, .z = z},
                   .pose = &pose,
                   .gap_max = 0.5,
                   .dist_min = -INFINITY};
    rs_contacts c0 = {0}, c1 = {0};
    ENSURE(rs_surface_query(&s, &q0, &c0, NULL) == 0);
    ENSURE(rs_surface_query(&s, &q1, &c1, NULL) == 0);
    ENSURE(c0.n > 100 && c0.n == c1.n);
    ENSURE(frames_orthonormal(&c1));
    for (int k = 0; k < c0.n; k++) {
        ENSURE(c0.point[k] == c1.point[k] && c0.feature[k] == c1.feature[k]);
        ENSURE_NEAR(c0.dist[k], c1.dist[k], 1e-12);
        double *const *v0[4] = {c0.xm, c0.nrm, c0.t1, c0.t2};
        double *const *v1[4] = {c1.xm, c1.nrm, c1.t1, c1.t2};
        for (int m = 0; m < 4; m++) {
            double a[3] = {v0[m][0][k], v0[m][1][k], v0[m][2][k]};
            for (int d = 0; d < 3; d++) {
                double r = pose.R[3 * d] * a[0] + pose.R[3 * d + 1] * a[1] +
                           pose.R[3 * d + 2] * a[2] + (m == 0 ? pose.T[d] : 0.0);
                ENSURE_NEAR(v1[m][d][k], r, 1e-12 * 8.0);
            }
        }
    }
    rs_contacts_free(&c0);
    rs_contacts_free(&c1);
    rs_surface_free(&s);
}

static void test_frame_turns_with_the_master_segments(void)
{
    pose_check(SEGMENTS_TXT, 1);
}

static void test_frame_turns_with_the_master_cylinder(void)
{
    pose_check(CYLINDER_TXT, 0);
}

static void test_frame_turns_with_the_master_revolution(void)
{
    pose_check(REVOLUTION_TXT, 0);
}

/* FACETED: t1 = global x projected on the tangent plane; global z within 0.1 degree. */
static void test_frame_faceted_t1_is_projected_global_x(void)
{
    for (int it = 0; it < NPTS; it++) {
        double n[3] = {2 * urand() - 1, 2 * urand() - 1, 2 * urand() - 1}, t1[3], t2[3],
               x[3];
        if (rs_dot3(n, n) < 1e-6)
            continue;
        unit(n);
        rs_frame_faceted(n, t1, t2);
        double g[3] = {1, 0, 0};
        if (fabs(n[0]) >= cos(0.1 * RS_PI / 180.0)) {
            g[0] = 0;
            g[2] = 1;
        }
        double p[3], k = rs_dot3(g, n);
        for (int d = 0; d < 3; d++)
            p[d] = g[d] - k * n[d];
        unit(p);
        rs_cross3(n, t1, x);
        for (int d = 0; d < 3; d++) {
            ENSURE_SMALL(t1[d] - p[d], 1e-12);
            ENSURE_SMALL(t2[d] - x[d], 1e-12);
        }
        ENSURE_SMALL(rs_dot3(t1, n), 1e-12);
    }
    /* the switch: x within 0.1 degree of n */
    double a = 0.099 * RS_PI / 180.0, n[3] = {cos(a), sin(a), 0}, t1[3], t2[3];
    rs_frame_faceted(n, t1, t2);
    ENSURE_NEAR(t1[2], 1.0, 1e-12);
    a = 0.101 * RS_PI / 180.0;
    double m[3] = {cos(a), sin(a), 0};
    rs_frame_faceted(m, t1, t2);
    ENSURE_SMALL(t1[2], 1e-12);
    ENSURE_NEAR(t1[1], -cos(a), 1e-12); /* (sin a, -cos a, 0) */
}

/* rs_frame_orient turns the principal frame {n, d1, d2 = n x d1} with curvatures
 * (k1, k2) into each convention, on contacts [k0, k1) only: TRAVEL keeps it, GENERATOR
 * gives t1 = -d2, t2 = d1, curvatures (k2, k1), GLOBAL_X the FACETED tangents with the
 * principal curvatures kept. */
static void test_frame_orient_conventions_from_the_principal_frame(void)
{
    enum { N = 16 };
    rs_contacts c = {0};
    rs_error e;
    ENSURE(rs_contacts_reserve(&c, N, &e) == RS_OK);
    double nn[N][3], d1[N][3], d2[N][3], kk[N][2];
    const rs_frame_convention convs[3] = {RS_FRAME_TRAVEL, RS_FRAME_GENERATOR,
                                          RS_FRAME_GLOBAL_X};
    for (int ic = 0; ic < 3; ic++) {
        c.n = N;
        for (int k = 0; k < N; k++) {
            double a[3] = {2 * urand() - 1, 2 * urand() - 1, 2 * urand() - 1};
            double n[3] = {2 * urand() - 1, 2 * urand() - 1, 2 * urand() - 1};
            unit(n);
            const double an = rs_dot3(a, n);
            for (int d = 0; d < 3; d++)
                a[d] -= an * n[d];
            unit(a);
            rs_cross3(n, a, d2[k]);
            for (int d = 0; d < 3; d++) {
                nn[k][d] = c.nrm[d][k] = n[d];
                d1[k][d] = c.t1[d][k] = a[d];
                c.t2[d][k] = d2[k][d];
            }
            kk[k][0] = c.curv[0][k] = urand();
            kk[k][1] = c.curv[1][k] = -urand();
        }
        rs_frame_orient(convs[ic], &c, 3, 11);
        for (int k = 0; k < N; k++) {
            const int in = k >= 3 && k < 11;
            double t1[3], t2[3], f1[3], f2[3];
            for (int d = 0; d < 3; d++) {
                t1[d] = c.t1[d][k];
                t2[d] = c.t2[d][k];
            }
            if (in && convs[ic] == RS_FRAME_GENERATOR) {
                for (int d = 0; d < 3; d++) {
                    ENSURE(t1[d] == -d2[k][d]);
                    ENSURE(t2[d] == d1[k][d]);
                }
                ENSURE(c.curv[0][k] == kk[k][1] && c.curv[1][k] == kk[k][0]);
            } else if (in && convs[ic] == RS_FRAME_GLOBAL_X) {
                rs_frame_faceted(nn[k], f1, f2);
                for (int d = 0; d < 3; d++) {
                    ENSURE(t1[d] == f1[d]);
                    ENSURE(t2[d] == f2[d]);
                }
                ENSURE(c.curv[0][k] == kk[k][0] && c.curv[1][k] == kk[k][1]);
            } else {
                for (int d = 0; d < 3; d++) {
                    ENSURE(t1[d] == d1[k][d]);
                    ENSURE(t2[d] == d2[k][d]);
                }
                ENSURE(c.curv[0][k] == kk[k][0] && c.curv[1][k] == kk[k][1]);
            }
            /* whatever the convention, the frame stays right-handed: n x t1 = t2 */
            double x[3];
            rs_cross3(nn[k], t1, x);
            for (int d = 0; d < 3; d++)
                ENSURE_SMALL(x[d] - t2[d], 1e-12);
        }
    }
    rs_contacts_free(&c);
}

int main(void)
{
    RS_RUN(test_frame_segments_t1_is_minus_z_cross_n);
    RS_RUN(test_frame_cylinder_t1_is_generator);
    RS_RUN(test_frame_revolution_t2_is_hoop);
    RS_RUN(test_frame_revolution_axis_is_finite_and_deterministic);
    RS_RUN(test_frame_revolution_local_x_on_the_axis);
    RS_RUN(test_frame_turns_with_the_master_segments);
    RS_RUN(test_frame_turns_with_the_master_cylinder);
    RS_RUN(test_frame_turns_with_the_master_revolution);
    RS_RUN(test_frame_faceted_t1_is_projected_global_x);
    RS_RUN(test_frame_orient_conventions_from_the_principal_frame);
    return rs_test_summary();
}
