/* The surface kinds' operations beyond the query: bounds contain the surface (the
 * display triangulation's nodes) and are exact where the profile's box is (closed
 * forms), they are unbounded along an unbounded generator, the spin axis
 * of a surface of revolution is its axis (the distance is invariant about it), and every
 * analytic kind has its table with the convention of docs/conventions.md. */
#include "rigidsurf/surface.h"
#include "rigidsurf/vec.h"
#include "rs_test.h"

#include <math.h>
#include <string.h>

static const char *TXT =
    "*SURFACE, TYPE=SEGMENTS, NAME=seg\nSTART, -1, 1\nLINE, 0, 0\n"
    "CIRCL, 1, 0, 0.5, 1.2\n"
    "*SURFACE, TYPE=CYLINDER, NAME=cyl\n0.5,0,0, 1.5,0.5,0\n0,0.3,2\n"
    "START, 0.3, 0\nCIRCL, 0, 0.3, 0, 0\nCIRCL, -0.3, 0, 0, 0\n"
    "*SURFACE, TYPE=CYLINDER, NAME=cylb, EXTENT=-0.2, 0.7\n"
    "0,0,0, 1,0,0\n0,0,1\nSTART, -1, 0.5\nLINE, 1, 0.25\n"
    "*SURFACE, TYPE=CYLINDER, NAME=cylz\n"
    "0,0,0, 1,0,0\n0,0,1\nSTART, -1, 0.5\nLINE, 1, 0.25\n"
    "*SURFACE, TYPE=REVOLUTION, NAME=drum, FILLET RADIUS=0.01\n"
    "0,0,0, 0,0,1\nSTART, 0, -0.05\nLINE, 0.15, -0.05\nLINE, 0.15, 0.05\nLINE, 0, 0.05\n"
    "*SURFACE, TYPE=REVOLUTION, NAME=drum0\n"
    "0,0,0, 0,0,1\nSTART, 0, -0.05\nLINE, 0.15, -0.05\nLINE, 0.15, 0.05\nLINE, 0, 0.05\n"
    "*SURFACE, TYPE=REVOLUTION, NAME=rev\n"
    "0,0,1, 0.2,0.1,2\nSTART, 0, 0\nLINE, 1, 0\nLINE, 1, 2\nLINE, 0.5, 2.5\n";

static void surface_named(const char *name, rs_surface *s)
{
    rs_error e;
    ENSURE(rs_surface_parse(TXT, "ops", name, s, &e) == RS_OK);
}

/* Every node of the display triangulation (nodes lie on the surface) lies in the
 * bounds; where a direction is bounded, some node comes within slack of each face. */
static void check_bounds_against_nodes(const char *name, double slack)
{
    rs_surface s;
    surface_named(name, &s);
    double lo[3], hi[3];
    rs_surface_bounds(&s, lo, hi);
    rs_trimesh m;
    rs_error e;
    ENSURE(rs_surface_triangulate(&s, 3.0, 720, &m, &e) == RS_OK);
    double nlo[3] = {INFINITY, INFINITY, INFINITY},
           nhi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int v = 0; v < m.nvert; v++)
        for (int d = 0; d < 3; d++) {
            const double x = m.xyz[3 * v + d];
            ENSURE(x >= lo[d] - 1e-12 && x <= hi[d] + 1e-12);
            nlo[d] = fmin(nlo[d], x);
            nhi[d] = fmax(nhi[d], x);
        }
    for (int d = 0; d < 3; d++) {
        if (isfinite(lo[d]))
            ENSURE_SMALL(nlo[d] - lo[d], slack);
        if (isfinite(hi[d]))
            ENSURE_SMALL(hi[d] - nhi[d], slack);
    }
    rs_trimesh_free(&m);
    rs_surface_free(&s);
}

static void test_bounds_contain_the_surface(void)
{
    /* The bounds are those of the profile's box (an arc's box may exceed the arc by its
     * sagitta, a revolution's end discs take the largest radius): the slack is at most
     * the fillet radius 0.01 for the drum, the profile's radial extent 1 for rev. */
    check_bounds_against_nodes("drum", 0.01);
    check_bounds_against_nodes("rev", 1.0);
    check_bounds_against_nodes("cylb", 1e-9);
    check_bounds_against_nodes("drum0", 1e-5);
}

static void test_bounds_closed_forms(void)
{
    rs_surface s;
    double lo[3], hi[3];
    /* a drum about z: |x|, |y| <= 0.15, z in [-0.05, 0.05] */
    surface_named("drum0", &s);
    rs_surface_bounds(&s, lo, hi);
    const double elo[3] = {-0.15, -0.15, -0.05}, ehi[3] = {0.15, 0.15, 0.05};
    for (int d = 0; d < 3; d++) {
        ENSURE_SMALL(lo[d] - elo[d], 1e-9);
        ENSURE_SMALL(hi[d] - ehi[d], 1e-9);
    }
    rs_surface_free(&s);
    /* a bounded plate: x in [-1, 1], y in [0.25, 0.5], z in [-0.2, 0.7] */
    surface_named("cylb", &s);
    rs_surface_bounds(&s, lo, hi);
    const double plo[3] = {-1, 0.25, -0.2}, phi[3] = {1, 0.5, 0.7};
    for (int d = 0; d < 3; d++) {
        ENSURE_SMALL(lo[d] - plo[d], 1e-9);
        ENSURE_SMALL(hi[d] - phi[d], 1e-9);
    }
    rs_surface_free(&s);
    /* without EXTENT the plate is unbounded along its generator z only; SEGMENTS are
     * unbounded along z */
    surface_named("cylz", &s);
    rs_surface_bounds(&s, lo, hi);
    for (int d = 0; d < 2; d++) {
        ENSURE_SMALL(lo[d] - plo[d], 1e-9);
        ENSURE_SMALL(hi[d] - phi[d], 1e-9);
    }
    ENSURE(lo[2] == -INFINITY && hi[2] == INFINITY);
    rs_surface_free(&s);
    surface_named("seg", &s);
    rs_surface_bounds(&s, lo, hi);
    ENSURE_SMALL(lo[0] + 1.0, 1e-9);
    ENSURE(isfinite(hi[0]) && isfinite(lo[1]) && isfinite(hi[1]));
    ENSURE(lo[2] == -INFINITY && hi[2] == INFINITY);
    rs_surface_free(&s);
}

static void test_spin_axis_of_a_revolution(void)
{
    rs_surface s;
    surface_named("rev", &s);
    double o[3], ax[3];
    ENSURE(rs_surface_spin_axis(&s, o, ax) == 1);
    /* a = (0, 0, 1), b = (0.2, 0.1, 2): the axis is (b - a) / |b - a| */
    const double b[3] = {0.2, 0.1, 1.0}, lb = rs_norm3(b);
    for (int d = 0; d < 3; d++) {
        ENSURE_SMALL(o[d] - (d == 2 ? 1.0 : 0.0), 1e-15);
        ENSURE_SMALL(ax[d] - b[d] / lb, 1e-15);
    }
    /* the distance of a point is invariant when it turns about that axis */
    unsigned long long st = 7;
    rs_contacts c0 = {0}, c1 = {0};
    rs_error e;
    for (int i = 0; i < 200; i++) {
        double p[3], r[3], q[3];
        for (int d = 0; d < 3; d++)
            p[d] = 3.0 * rs_test_urand(&st) - 1.5 + o[d];
        const double th = 2.0 * RS_PI * rs_test_urand(&st);
        /* Rodrigues: r = p' cos + (ax x p') sin + ax (ax . p') (1 - cos), p' = p - o */
        const double pp[3] = {p[0] - o[0], p[1] - o[1], p[2] - o[2]};
        double axp[3];
        rs_cross3(ax, pp, axp);
        const double ap = rs_dot3(ax, pp);
        for (int d = 0; d < 3; d++) {
            r[d] = o[d] + pp[d] * cos(th) + axp[d] * sin(th) + ax[d] * ap * (1.0 - cos(th));
            q[d] = p[d];
        }
        rs_query qa = {.n = 1,
                       .slave = {.x = q, .y = q + 1, .z = q + 2},
                       .pose = NULL,
                       .gap_max = 10.0,
                       .dist_min = -10.0};
        rs_query qb = {.n = 1,
                       .slave = {.x = r, .y = r + 1, .z = r + 2},
                       .pose = NULL,
                       .gap_max = 10.0,
                       .dist_min = -10.0};
        c0.n = c1.n = 0;
        ENSURE(rs_surface_query(&s, &qa, &c0, &e) == RS_OK);
        ENSURE(rs_surface_query(&s, &qb, &c1, &e) == RS_OK);
        ENSURE(c0.n == c1.n);
        for (int k = 0; k < c0.n && k < c1.n; k++) {
            ENSURE(c0.feature[k] == c1.feature[k]);
            ENSURE_SMALL(c0.dist[k] - c1.dist[k], 1e-12);
        }
    }
    rs_contacts_free(&c0);
    rs_contacts_free(&c1);
    rs_surface_free(&s);
    const char *others[3] = {"seg", "cyl", "cylb"};
    for (int i = 0; i < 3; i++) {
        surface_named(others[i], &s);
        ENSURE(rs_surface_spin_axis(&s, o, ax) == 0);
        rs_surface_free(&s);
    }
}

/* docs/conventions.md, "Frames": the kind's name, its local directions and its frame
 * convention. */
static void test_each_kind_has_its_table(void)
{
    const struct {
        const char *surf, *name;
        int ndir;
        rs_frame_convention conv;
    } want[3] = {{"seg", "SEGMENTS", 2, RS_FRAME_TRAVEL},
                 {"cyl", "CYLINDER", 3, RS_FRAME_GENERATOR},
                 {"rev", "REVOLUTION", 3, RS_FRAME_TRAVEL}};
    for (int i = 0; i < 3; i++) {
        rs_surface s;
        surface_named(want[i].surf, &s);
        ENSURE(s.ops != NULL);
        ENSURE(strcmp(s.ops->name, want[i].name) == 0);
        ENSURE(s.ops->ndir == want[i].ndir && rs_surface_ndir(&s) == want[i].ndir);
        ENSURE(s.ops->frame == want[i].conv);
        rs_surface_free(&s);
        ENSURE(s.ops == NULL);
    }
}

/* A surface without a kind (zeroed, or freed by rs_surface_free) answers every operation
 * of the dispatch with an error or a neutral value: no local directions, no hand-over, an
 * empty box at the origin, no spin axis. */
static void test_a_surface_without_kind_answers_neutrally(void)
{
    rs_surface s;
    memset(&s, 0, sizeof s);
    for (int freed = 0; freed < 2; freed++) {
        if (freed) {
            surface_named("rev", &s);
            rs_surface_free(&s);
        }
        ENSURE(rs_surface_ndir(&s) == 0);
        const int f = RS_FEATURE(RS_FEAT_FACE, 0);
        ENSURE(rs_surface_adjacent(&s, f, f) == 0);
        double lo[3] = {1, 1, 1}, hi[3] = {-1, -1, -1}, o[3], ax[3];
        rs_surface_bounds(&s, lo, hi);
        for (int d = 0; d < 3; d++)
            ENSURE(lo[d] == 0.0 && hi[d] == 0.0);
        ENSURE(rs_surface_spin_axis(&s, o, ax) == 0);
        rs_trimesh m;
        rs_error err;
        ENSURE(rs_surface_triangulate(&s, 1.0, 8, &m, &err) == RS_ERR_ARG);
        rs_contacts c;
        memset(&c, 0, sizeof c);
        const double x = 0.0;
        const rs_query q = {.n = 1,
                            .slave = {.x = &x, .y = &x, .z = &x},
                            .pose = NULL,
                            .gap_max = 1.0,
                            .dist_min = -INFINITY};
        ENSURE(rs_surface_query(&s, &q, &c, &err) == RS_ERR_ARG);
    }
    ENSURE(rs_surface_ndir(NULL) == 0 && rs_surface_spin_axis(NULL, NULL, NULL) == 0);
}

/* The proximity cache is made once, when the surface is read: a query of an analytic
 * surface without one is an error, not a cache built and freed at every query. */
static void test_query_without_proximity_cache_is_an_error(void)
{
    rs_surface s;
    surface_named("rev", &s);
    void *pc = s.impl;
    s.impl = NULL;
    rs_contacts c;
    memset(&c, 0, sizeof c);
    const double x = 0.1, y = 0.2, z = 0.3, r = 0.05;
    const rs_query q = {.n = 1,
                        .slave = {.x = &x, .y = &y, .z = &z, .radius = &r},
                        .pose = NULL,
                        .gap_max = 1.0,
                        .dist_min = -INFINITY};
    rs_error err;
    ENSURE(rs_surface_query(&s, &q, &c, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "proximity cache") != NULL && c.n == 0);
    s.impl = pc;
    ENSURE(rs_surface_query(&s, &q, &c, &err) == RS_OK);
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* The capability of facets is the table's, whatever the kind's number: a second faceted
 * kind (here a fixture of two facets) has facets, each counted by facet_count and read by
 * facet_area; the analytic kinds have none. */
static int two_facet(const rs_surface *s, int f, const double xm[3], int nodes[4],
                     double xyz[12], double shape[4])
{
    (void)s, (void)xm, (void)xyz, (void)shape;
    nodes[0] = nodes[1] = nodes[2] = 1;
    return f >= 0 ? 3 : 0;
}

static int two_count(const rs_surface *s)
{
    (void)s;
    return 2;
}

static int two_area(const rs_surface *s, int k, double *area, double n[3])
{
    (void)s;
    *area = k + 1.0;
    n[0] = n[1] = 0.0;
    n[2] = 1.0;
    return 0;
}

static void test_facets_are_a_capability_of_the_table(void)
{
    static const rs_surface_ops two = {.name = "TWO",
                                       .ndir = 3,
                                       .facet = two_facet,
                                       .facet_area = two_area,
                                       .facet_count = two_count};
    rs_surface s;
    memset(&s, 0, sizeof s);
    s.ops = &two;
    s.kind = RS_SURF_SEGMENTS;
    ENSURE(rs_surface_has_facets(&s) && rs_surface_facet_count(&s) == 2);
    double a = 0.0, n[3];
    ENSURE(rs_surface_facet_area(&s, 1, &a, n) == 0 && a == 2.0 && n[2] == 1.0);
    ENSURE(rs_surface_facet_area(&s, 2, &a, n) == -1 &&
           rs_surface_facet_area(&s, -1, &a, n) == -1);
    const char *names[3] = {"seg", "cyl", "rev"};
    for (int i = 0; i < 3; i++) {
        surface_named(names[i], &s);
        ENSURE(!rs_surface_has_facets(&s) && rs_surface_facet_count(&s) == 0);
        rs_surface_free(&s);
    }
    ENSURE(!rs_surface_has_facets(&s) && !rs_surface_has_facets(NULL));
}

int main(void)
{
    RS_RUN(test_bounds_contain_the_surface);
    RS_RUN(test_bounds_closed_forms);
    RS_RUN(test_spin_axis_of_a_revolution);
    RS_RUN(test_each_kind_has_its_table);
    RS_RUN(test_a_surface_without_kind_answers_neutrally);
    RS_RUN(test_query_without_proximity_cache_is_an_error);
    RS_RUN(test_facets_are_a_capability_of_the_table);
    return rs_test_summary();
}
