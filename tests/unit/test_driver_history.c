/* The standalone driver's history storage:
 * - a node that touches the wall at more features than it has slots gets more (the
 *   wall's slots double, as an engine's do), its contacts' history kept: a ball in a
 *   faceted cavity that comes to touch more than 32 faces moves bit for bit as one given
 *   64 slots from the start;
 * - a first increment that fails and is tried again allocates its history once (the
 *   sanitizer build's leak check) and goes on as one that never failed. */
#include "rigidsurf/driver.h"
#include "rigidsurf/vec.h"
#include "rs_test.h"
#include "rs_test_geom.h"

/* A ball (radius 0.018) as a body in a cavity of radius 0.02, pressed against its side
 * by gravity along +x while it slides along z with friction; capacity slots to begin
 * with. Its state after the steps into out (x, z, vx, vz, wy), its most entries in one
 * increment and its capacity at the end. */
static int ball_run(const rs_surface *s, int capacity, int steps, double out[5], int *most,
                    int *cap)
{
    rs_driver d;
    rs_error e;
    rs_shape ball;
    const double law[5] = {1e3, 1e3, 0.3, 0.3, 0.3}, g = 9.81;
    if (rs_shape_make_sphere(&ball, 0.018, 0.0, NULL) != RS_OK ||
        rs_driver_init(&d, s, 1, &e) != RS_OK ||
        rs_driver_set_law(&d, rs_law_find("hooke"), law, 5, 2, &e) != RS_OK ||
        rs_driver_set_body(&d, 0, &ball, 1000.0, &e) != RS_OK)
        return 0;
    d.capacity = capacity;
    d.x[0] = 0.002 - 2e-5;
    d.z[0] = 3e-4;
    d.vz[0] = 0.01;
    d.fext[0] = g * d.mass[0];
    d.dt = 1e-5;
    d.tracking = 3e-5;
    *most = 0;
    for (int k = 0; k < steps; k++) {
        if (rs_driver_step(&d, &e) != RS_OK) {
            fprintf(stderr, "capacity %d, step %d: %s\n", capacity, k, e.msg);
            return 0;
        }
        *most = d.trk.n > *most ? d.trk.n : *most;
    }
    const double o[5] = {d.x[0], d.z[0], d.vx[0], d.vz[0], d.wy[0]};
    memcpy(out, o, sizeof o);
    *cap = rs_wall_pack_size(d.wall); /* the capacity, then the node's history */
    rs_driver_free(&d);
    return 1;
}

static void test_slots_grow_and_keep_their_history(void)
{
    rs_surface s;
    ENSURE(uv_cavity(0.02, 32, 64, &s));
    double a[5], b[5];
    int most_a, most_b, cap_a, cap_b;
    ENSURE(ball_run(&s, 16, 400, a, &most_a, &cap_a));
    ENSURE(ball_run(&s, 64, 400, b, &most_b, &cap_b));
    /* 26 entries at the start (16 slots grow to 32), 36 after about 300 steps (to 64) */
    ENSURE(most_a > 32 && most_a == most_b);
    ENSURE(cap_a == cap_b);     /* grown to the 64 slots b began with */
    ENSURE(a[1] > 3e-4 + 1e-5); /* it slid, under friction */
    for (int k = 0; k < 5; k++)
        ENSURE(a[k] == b[k]);
    rs_surface_free(&s);
}

static int fail_once(rs_driver *d, double t, void *ctx, rs_error *err)
{
    (void)d, (void)t;
    int *calls = ctx;
    return (*calls)++ == 0 ? rs_error_set(err, RS_ERR_ARG, "the first call fails") : RS_OK;
}

/* A cube on the plane under gravity: the boundary condition's first call fails the
 * first increment after its history is allocated; tried again, the driver goes on as
 * one whose callback never failed. */
static void test_a_failed_first_increment_tried_again(void)
{
    static const char *PLANE = "*SURFACE, TYPE=CYLINDER, NAME=floor\n"
                               "0, 0, 0, 1, 0, 0\n0, -1, 0\nSTART, -1, 0\nLINE, 1, 0\n";
    rs_surface s;
    ENSURE(rs_surface_parse(PLANE, "plane", NULL, &s, NULL) == RS_OK);
    rs_shape cube;
    ENSURE(rs_shape_make_box(&cube, 0.01, 0.01, 0.01, 0.0, NULL) == RS_OK);
    const double law[5] = {1e4, 1e4, 0.3, 0.3, 0.5};
    rs_driver d[2];
    int calls[2] = {0, 1};
    for (int k = 0; k < 2; k++) {
        ENSURE(rs_driver_init(&d[k], &s, 1, NULL) == RS_OK);
        ENSURE(rs_driver_set_law(&d[k], rs_law_find("hooke"), law, 5, 2, NULL) == RS_OK);
        ENSURE(rs_driver_set_body(&d[k], 0, &cube, 1000.0, NULL) == RS_OK);
        d[k].bc = fail_once;
        d[k].bc_ctx = &calls[k];
        d[k].dt = 1e-5;
        d[k].tracking = 1e-4;
        d[k].z[0] = 0.01 - 1e-6;
        d[k].vx[0] = 0.1;
        d[k].fext[2] = -9.81 * d[k].mass[0];
    }
    rs_error e;
    ENSURE(rs_driver_step(&d[0], &e) == RS_ERR_ARG);
    ENSURE(d[0].inc == 0);
    for (int i = 0; i < 500; i++)
        for (int k = 0; k < 2; k++)
            ENSURE(rs_driver_step(&d[k], &e) == RS_OK);
    ENSURE(d[0].x[0] == d[1].x[0] && d[0].z[0] == d[1].z[0] && d[0].vx[0] == d[1].vx[0]);
    for (int k = 0; k < 2; k++)
        rs_driver_free(&d[k]);
    rs_surface_free(&s);
}

int main(void)
{
    RS_RUN(test_slots_grow_and_keep_their_history);
    RS_RUN(test_a_failed_first_increment_tried_again);
    return rs_test_summary();
}
