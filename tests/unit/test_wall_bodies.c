/* Convex bodies through the wall's one call (rs_wall_step):
 * - in a run that asks every particle at every step, a cube resting flat on a plane beside
 *   a sphere: the cube gets kn d at each of its four corners (4 kn d, no torque), the
 *   sphere kn d, as Hooke's law gives each point of overlap d;
 * - in a run of candidate lists and distance bounds (an engine's), a block with a body is
 *   refused with a message that names the particle, and the engine's rows are untouched. */
#include "rigidsurf/wall.h"
#include "rs_test.h"

#include <string.h>

static const char *PLANE = "*SURFACE, TYPE=CYLINDER, NAME=floor\n"
                           "0, 0, 0, 1, 0, 0\n0, -1, 0\nSTART, -1, 0\nLINE, 1, 0\n";

enum { N = 2 };
static const double H = 0.01, D = 1e-5, KN = 1e4;

/* A wall of hooke (kn = kt = KN, no damping, mu 0.3) on the plane z = 0, its run
 * every_particle; particle 0 a cube of half-side H, particle 1 a sphere of radius H, each
 * overlapping the plane by D; the step's forces and torques into f, t, its code into *rc
 * (-1: the set-up failed). */
static void step(int every_particle, double f[N][3], double t[N][3], int *rc, rs_error *err)
{
    *rc = -1;
    rs_surface s;
    rs_shape cube;
    ENSURE(rs_surface_parse(PLANE, "plane", NULL, &s, NULL) == RS_OK);
    ENSURE(rs_shape_make_box(&cube, H, H, H, 0.0, NULL) == RS_OK);
    const double props[5] = {KN, KN, 0.0, 0.0, 0.3};
    const rs_law *law = rs_law_find("hooke");
    rs_wall_def def;
    memset(&def, 0, sizeof def);
    def.surface = &s;
    def.law = law;
    def.props = props;
    def.nprops = 5;
    def.nstatev = law->nstatev;
    def.capacity = 16;
    def.tracking = 1e-4;
    def.area_mode = RS_AREA_NODE;
    rs_wall *w = NULL;
    ENSURE(rs_wall_make(&def, NULL, &w, NULL) == RS_OK);
    double x[N][3] = {{0.0, 0.0, H - D}, {0.1, 0.0, H - D}}, v[N][3] = {{0}},
           om[N][3] = {{0}};
    double r[N] = {H, H}, m[N] = {8.0, 4.0};
    int id[N] = {11, 12};
    rs_body body[N];
    memset(body, 0, sizeof body);
    const double q[4] = {1.0, 0.0, 0.0, 0.0};
    ENSURE(rs_body_init(&body[0], &cube, 1000.0, x[0], q, NULL) == RS_OK);
    m[0] = body[0].mass;
    rs_wall_run run;
    memset(&run, 0, sizeof run);
    run.dt = 1e-6;
    run.skin = 1e-3;
    run.every_particle = every_particle;
    rs_surface_bounds(&s, run.box_lo, run.box_hi);
    rs_wall_block b;
    memset(&b, 0, sizeof b);
    b.n = N;
    b.x = x[0], b.v = v[0], b.omega = om[0], b.radius = r, b.mass = m, b.id = id;
    b.body = body;
    b.inc = 1;
    b.still = 1;
    ENSURE(rs_wall_grow(w, N, NULL) == RS_OK);
    ENSURE(rs_wall_init(w, &run, &b, NULL) == RS_OK);
    rs_wall_rows rows;
    memset(&rows, 0, sizeof rows);
    rows.f = f[0];
    rows.torque = t[0];
    *rc = rs_wall_step(w, &b, &rows, run.dt, NULL, err);
    rs_wall_free(w);
    rs_shape_free(&cube);
    rs_surface_free(&s);
}

static void test_bodies_and_spheres_in_one_call(void)
{
    double f[N][3] = {{0}}, t[N][3] = {{0}};
    rs_error e;
    int rc;
    step(1, f, t, &rc, &e);
    ENSURE(rc == RS_OK);
    ENSURE_NEAR(f[0][2], 4.0 * KN * D, 1e-9 * KN * D);
    ENSURE_NEAR(f[1][2], KN * D, 1e-9 * KN * D);
    for (int k = 0; k < N; k++)
        for (int d = 0; d < 3; d++) {
            if (d < 2)
                ENSURE(fabs(f[k][d]) <= 1e-12 * KN * D);
            ENSURE(fabs(t[k][d]) <= 1e-9 * KN * D * H);
        }
}

static void test_a_body_in_an_engine_run_refused(void)
{
    double f[N][3] = {{7.0, 7.0, 7.0}, {7.0, 7.0, 7.0}}, t[N][3] = {{0}};
    rs_error e;
    int rc;
    step(0, f, t, &rc, &e);
    ENSURE(rc == RS_ERR_ARG);
    ENSURE(strstr(e.msg, "particle 11") && strstr(e.msg, "every_particle"));
    for (int k = 0; k < N; k++)
        for (int d = 0; d < 3; d++)
            ENSURE(f[k][d] == 7.0 && t[k][d] == 0.0);
}

int main(void)
{
    RS_RUN(test_bodies_and_spheres_in_one_call);
    RS_RUN(test_a_body_in_an_engine_run_refused);
    return rs_test_summary();
}
