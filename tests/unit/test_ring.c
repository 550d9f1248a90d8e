/* Rings around the axis of a REVOLUTION (docs/conventions.md): a sphere whose reach
 * contains the axis, in an outlet narrower than itself, touches the wall in every
 * sector, each contact at the 3D distance from the sphere's centre to that sector's
 * closest point (law of cosines for a pipe); where the surface closes on the axis (a
 * cap, a bowl) the sphere keeps its one contact; and a sphere's contacts within its
 * radius do not depend on how far beyond it the query reaches. */
#include "rs_test.h"
#include "rs_test_geom.h"

#include <math.h>

/* One sphere of radius Rs at (x, y, z), contacts within gap. */
static int sphere1(const rs_surface *s, double x, double y, double z, double Rs, double gap,
                   rs_contacts *c)
{
    rs_query q = {.n = 1,
                  .slave = {.x = &x, .y = &y, .z = &z, .radius = &Rs},
                  .pose = NULL,
                  .gap_max = gap,
                  .dist_min = -INFINITY};
    c->n = 0;
    return rs_surface_query(s, &q, c, NULL);
}

/* A pipe r = a about z (normal inward), a sphere of radius 1.5 a at distance e from the
 * axis along x: sector s (azimuth 2 pi s / K) has its contact at Q = a (cos, sin, 0) when
 * |P - Q| = sqrt(e^2 + a^2 - 2 e a cos) <= R + gap, normal (P - Q) / |P - Q|. */
static void check_pipe(double e)
{
    const double a = 0.01, Rs = 1.5 * a;
    const int K = RS_RING_SECTORS;
    rs_surface s;
    ENSURE(parse("*SURFACE, TYPE=REVOLUTION, NAME=pipe\n0,0,0, 0,0,1\n"
                 "START, 0.01, -1\nLINE, 0.01, 1\n",
                 &s) == 0);
    rs_contacts c = {0};
    ENSURE(sphere1(&s, e, 0.0, 0.0, Rs, 0.0, &c) == 0);
    int k = 0;
    double sum[3] = {0, 0, 0};
    for (int sec = 0; sec < K; sec++) {
        const double ang = 2.0 * RS_PI * sec / K, ca = cos(ang), sa = sin(ang);
        const double d = sqrt(e * e + a * a - 2.0 * e * a * ca);
        if (d > Rs)
            continue; /* beyond reach: no contact in this sector */
        ENSURE(k < c.n);
        ENSURE(c.feature[k] == RS_FEATURE(RS_FEAT_FACE, 0) + sec * RS_SECTOR_STRIDE);
        ENSURE_NEAR(c.dist[k], d, 1e-15);
        ENSURE_NEAR(c.xm[0][k], a * ca, 1e-15);
        ENSURE_NEAR(c.xm[1][k], a * sa, 1e-15);
        ENSURE_NEAR(c.xm[2][k], 0.0, 1e-15);
        const double n[3] = {(e - a * ca) / d, -a * sa / d, 0.0};
        for (int x = 0; x < 3; x++) {
            ENSURE_NEAR(c.nrm[x][k], n[x], 1e-12);
            sum[x] += c.nrm[x][k] * (Rs - c.dist[k]);
        }
        /* an orthonormal frame */
        ENSURE_NEAR(rs_dot3((double[3]){c.t1[0][k], c.t1[1][k], c.t1[2][k]}, n), 0.0,
                    1e-12);
        ENSURE_NEAR(rs_dot3((double[3]){c.t2[0][k], c.t2[1][k], c.t2[2][k]}, n), 0.0,
                    1e-12);
        k++;
    }
    ENSURE(k == c.n);
    if (e == 0.0) {
        ENSURE(c.n == K);
        /* on the axis the overlaps weighted by the normals cancel to rounding */
        for (int x = 0; x < 3; x++)
            ENSURE_NEAR(sum[x], 0.0, 1e-17);
    } else {
        /* off the axis they push the sphere back to it */
        ENSURE(sum[0] < 0.0);
        ENSURE_NEAR(sum[1], 0.0, 1e-17);
    }
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

static void test_ring_sphere_on_the_axis_of_a_narrow_pipe(void)
{
    check_pipe(0.0);
}

static void test_ring_sphere_off_the_axis_keeps_the_sectors_in_reach(void)
{
    check_pipe(0.002);
    check_pipe(0.006); /* the opposite sector is out of reach, its neighbours are not */
}

/* A disc z = 0 facing +z and a bowl (a quarter circle from the axis): the surface
 * closes on the axis, the sphere near it has one contact. */
static void test_ring_none_where_the_surface_closes_on_the_axis(void)
{
    rs_surface s;
    rs_contacts c = {0};
    ENSURE(parse("*SURFACE, TYPE=REVOLUTION, NAME=disc\n0,0,0, 0,0,1\n"
                 "START, 0, 0\nLINE, 1, 0\n",
                 &s) == 0);
    ENSURE(sphere1(&s, 0.001, 0.0, 0.009, 0.01, 0.0, &c) == 0);
    ENSURE(c.n == 1 && c.feature[0] == RS_FEATURE(RS_FEAT_FACE, 0));
    ENSURE_NEAR(c.dist[0], 0.009, 1e-15);
    rs_surface_free(&s);
    ENSURE(parse("*SURFACE, TYPE=REVOLUTION, NAME=bowl\n0,0,0, 0,0,1\n"
                 "START, 0, 0\nCIRCL, 1, 1, 0, 1\n",
                 &s) == 0);
    ENSURE(sphere1(&s, 0.05, 0.0, 0.19, 0.2, 0.0, &c) == 0);
    ENSURE(c.n == 1 && c.feature[0] == RS_FEATURE(RS_FEAT_FACE, 0));
    ENSURE_NEAR(c.dist[0], 1.0 - hypot(0.05, 1.0 - 0.19), 1e-15);
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* A point query (no radius) is never a ring. */
static void test_ring_points_have_one_contact(void)
{
    rs_surface s;
    ENSURE(parse("*SURFACE, TYPE=REVOLUTION, NAME=pipe\n0,0,0, 0,0,1\n"
                 "START, 0.01, -1\nLINE, 0.01, 1\n",
                 &s) == 0);
    double x = 0.0, y = 0.0, z = 0.0;
    rs_query q = {.n = 1,
                  .slave = {.x = &x, .y = &y, .z = &z},
                  .pose = NULL,
                  .gap_max = 0.02,
                  .dist_min = -INFINITY};
    rs_contacts c = {0};
    ENSURE(rs_surface_query(&s, &q, &c, NULL) == 0);
    ENSURE(c.n == 1);
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* The query is monotone in its reach: spheres at random near the axis of hoppers with an
 * outlet narrower than they are (one side and two) get, with gap_max = 0, exactly the
 * contacts they get with a gap_max of 10 sphere radii that lie within their radius, ring
 * sectors included, value for value and in the same order. */
static void test_ring_contacts_do_not_depend_on_the_reach(void)
{
    static const char *decks[] = {
        "*SURFACE, TYPE=REVOLUTION, NAME=h\n0,0,0, 0,0,1\nSTART, 0.003, 0\n"
        "LINE, 0.05, 0.05\nLINE, 0.05, 0.2\n",
        "*SURFACE, TYPE=REVOLUTION, NAME=h2, SIDES=2\n0,0,0, 0,0,1\nSTART, 0.003, 0\n"
        "LINE, 0.05, 0.05\nLINE, 0.05, 0.2\n",
        "*SURFACE, TYPE=REVOLUTION, NAME=p\n0,0,0, 0,0,1\nSTART, 0.002, 0\n"
        "PARAB, 0.01, 0.02, 0.03, 0.05\nLINE, 0.03, 0.1\n"};
    enum { N = 2000 };
    static double x[N], y[N], z[N], r[N];
    int rings = 0;
    for (int d = 0; d < 3; d++) {
        rs_surface s;
        ENSURE(parse(decks[d], &s) == 0);
        for (int i = 0; i < N; i++) {
            const double R = 0.001 + 0.01 * urand(), rr = 1.2 * R * urand();
            const double th = 2.0 * RS_PI * urand();
            x[i] = rr * cos(th);
            y[i] = rr * sin(th);
            z[i] = -0.02 + 0.15 * urand();
            r[i] = R;
        }
        rs_contacts near = {0}, far = {0};
        rs_query q0 = {.n = N,
                       .slave = {.x = x, .y = y, .z = z, .radius = r},
                       .pose = NULL,
                       .gap_max = 0.0,
                       .dist_min = -INFINITY};
        rs_query q1 = {.n = N,
                       .slave = {.x = x, .y = y, .z = z, .radius = r},
                       .pose = NULL,
                       .gap_max = 0.1,
                       .dist_min = -INFINITY};
        ENSURE(rs_surface_query(&s, &q0, &near, NULL) == 0);
        ENSURE(rs_surface_query(&s, &q1, &far, NULL) == 0);
        int k = 0;
        for (int e = 0; e < far.n; e++) {
            if (!(far.dist[e] <= r[far.point[e]]))
                continue;
            ENSURE(k < near.n && near.point[k] == far.point[e]);
            ENSURE(near.feature[k] == far.feature[e] && near.dist[k] == far.dist[e]);
            for (int a = 0; a < 3; a++)
                ENSURE(near.xm[a][k] == far.xm[a][e] && near.nrm[a][k] == far.nrm[a][e]);
            rings += near.feature[k] >= RS_SECTOR_STRIDE;
            k++;
        }
        ENSURE(k == near.n);
        rs_contacts_free(&near);
        rs_contacts_free(&far);
        rs_surface_free(&s);
    }
    ENSURE(rings > 100);
}

int main(void)
{
    RS_RUN(test_ring_sphere_on_the_axis_of_a_narrow_pipe);
    RS_RUN(test_ring_sphere_off_the_axis_keeps_the_sectors_in_reach);
    RS_RUN(test_ring_none_where_the_surface_closes_on_the_axis);
    RS_RUN(test_ring_points_have_one_contact);
    RS_RUN(test_ring_contacts_do_not_depend_on_the_reach);
    return rs_test_summary();
}
