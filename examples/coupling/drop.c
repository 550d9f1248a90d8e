/* Spheres dropped on a floor that a DEM code holds as arrays: a DEM code of one's own with
 * a rigidsurf wall (docs/coupling.md). The floor z = 0 is a square of two triangles
 * (rs_surface_make_mesh); the wall on it, with the built-in hertz law, is made once
 * (rs_wall_make) and computes every step's contact forces in one call (rs_wall_step);
 * the spheres do not touch each other. Prints each sphere's rest height and overlap. */
#include <rigidsurf/wall.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

enum { N = 3 }; /* spheres */
static const double RHO = 2500.0, G = 9.81, DT = 1e-5, T_END = 0.6;
/* hertz: Y_particle nu_particle Y_wall nu_wall restitution friction curvature */
static const double PROPS[7] = {1e7, 0.3, 1e7, 0.3, 0.5, 0.4, 0.0};

static int fail(const rs_error *err)
{
    fprintf(stderr, "drop: %s\n", err->msg);
    return 1;
}

int main(void)
{
    const double xyz[12] = {-0.1, -0.1, 0, 0.1, -0.1, 0, 0.1, 0.1, 0, -0.1, 0.1, 0};
    const int tri[6] = {0, 1, 2, 0, 2, 3}; /* counter-clockwise seen from +z: n = +z */
    rs_surface floor;
    rs_error err;
    if (rs_surface_make_mesh(xyz, 4, tri, 2, NULL, &floor, &err) != RS_OK)
        return fail(&err);

    /* the spheres: centres, velocities, spins (3 per sphere), radii, masses, ids */
    double x[N][3], v[N][3] = {{0}}, w[N][3] = {{0}}, r[N], m[N];
    int id[N];
    for (int i = 0; i < N; i++) {
        r[i] = 0.004 + 0.001 * i;
        m[i] = RHO * 4.0 / 3.0 * 3.14159265358979324 * r[i] * r[i] * r[i];
        x[i][0] = -0.05 + 0.05 * i, x[i][1] = 0.0, x[i][2] = r[i] + 0.01 * (i + 1);
        v[i][0] = 0.05 * (i - 1); /* sliding and rolling too */
        id[i] = i + 1;
    }

    /* The wall: the floor with the hertz law (tracking -1: the law's reach). The run: its
     * time step; every sphere is a candidate at every step (a code without neighbour
     * lists; one with them gives its skin and calls rs_wall_reneighbor when it rebuilds).
     */
    const rs_law *hertz = rs_law_find("hertz");
    rs_wall_def def = {.surface = &floor,
                       .law = hertz,
                       .props = PROPS,
                       .nprops = 7,
                       .nstatev = hertz->nstatev,
                       .tracking = -1.0,
                       .area_mode = RS_AREA_NODE};
    rs_wall *wall;
    if (rs_wall_make(&def, NULL, &wall, &err) != RS_OK)
        return fail(&err);
    rs_wall_run run = {.dt = DT, .every_particle = 1};
    rs_wall_block b = {
        .n = N, .x = x[0], .v = v[0], .omega = w[0], .radius = r, .mass = m, .id = id};
    if (rs_wall_grow(wall, N, &err) != RS_OK || rs_wall_init(wall, &run, &b, &err) != RS_OK)
        return fail(&err);

    const int nstep = (int)(T_END / DT + 0.5);
    for (int step = 0; step < nstep; step++) {
        /* the floor's force and torque on each sphere at x_k, with v and w of k - 1/2 */
        double f[N][3] = {{0}}, t[N][3] = {{0}};
        rs_wall_rows rows = {.f = f[0], .torque = t[0]};
        b.step = step, b.inc = step + 1, b.time = step * DT, b.still = step == 0;
        if (rs_wall_step(wall, &b, &rows, DT, NULL, &err) != RS_OK)
            return fail(&err);
        /* the code's own integration (symplectic Euler), gravity along -z */
        for (int i = 0; i < N; i++) {
            const double I = 0.4 * m[i] * r[i] * r[i];
            for (int d = 0; d < 3; d++) {
                v[i][d] += DT * (f[i][d] / m[i] - (d == 2 ? G : 0.0));
                x[i][d] += DT * v[i][d];
                w[i][d] += DT * t[i][d] / I;
            }
        }
    }
    for (int i = 0; i < N; i++)
        printf("sphere %d R %.9g z %.12g overlap %.9e v %.9e\n", id[i], r[i], x[i][2],
               r[i] - x[i][2],
               sqrt(v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2]));
    rs_wall_free(wall);
    rs_surface_free(&floor);
    return 0;
}
