/* Convex bodies in the standalone driver: a rounded-box tablet, a capsule and a die
 * (a rounded cube) tumbling in the main job's drum (examples/surfaces/drum.inp, a
 * REVOLUTION about z of radius 0.1 m, turned at 3 rad/s about its axis with gravity
 * along -y), law hooke with friction. The bodies meet the wall only (the driver has no
 * body-body contacts), so they sit at different depths along the axis.
 *
 *   convex_tumble DRUM.inp OUTDIR
 *
 * Writes OUTDIR/bodies.csv (per 0.01 s: time, and per body its centre, the angle of its
 * body z axis from the drum axis, its speed and contact count), VTK files of the wall and
 * the bodies (OUTDIR/post/, every 0.05 s) for ParaView, and checks that no body passes
 * the wall: every support point of every body stays within the drum (radius 0.1 m and
 * 0 <= z <= 0.06 m) to the contact's overlap. Exit status 1 on a failed check. */
#include "rigidsurf/convex.h"
#include "rigidsurf/driver.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { NB = 3, NLAT = 12, NLON = 24 };

static const char *NAMES[NB] = {"tablet", "capsule", "die"};

/* The body's surface for display: its support points along a latitude-longitude net of
 * directions, as quads split into triangles (a rounded shape's hull, finely enough). */
static void write_body(FILE *f, const rs_body *b, int *nbase)
{
    (void)nbase;
    for (int i = 0; i <= NLAT; i++) {
        const double th = RS_PI * i / NLAT;
        for (int j = 0; j < NLON; j++) {
            const double ph = 2.0 * RS_PI * j / NLON;
            const double d[3] = {sin(th) * cos(ph), sin(th) * sin(ph), cos(th)};
            double p[3];
            rs_body_support(b, d, p);
            fprintf(f, "%.9g %.9g %.9g\n", p[0], p[1], p[2]);
        }
    }
}

static int write_vtk(const char *dir, int frame, const rs_driver *d, const rs_trimesh *wall,
                     const rs_pose *pose)
{
    char path[512];
    snprintf(path, sizeof path, "%s/post/wall_%04d.vtk", dir, frame);
    FILE *f = fopen(path, "w");
    if (!f)
        return 0;
    fprintf(f,
            "# vtk DataFile Version 3.0\ndrum\nASCII\nDATASET POLYDATA\nPOINTS %d double\n",
            wall->nvert);
    for (int v = 0; v < wall->nvert; v++) {
        double x[3];
        rs_pose_to_global(pose, wall->xyz + 3 * v, x);
        fprintf(f, "%.9g %.9g %.9g\n", x[0], x[1], x[2]);
    }
    fprintf(f, "POLYGONS %d %d\n", wall->ntri, 4 * wall->ntri);
    for (int t = 0; t < wall->ntri; t++)
        fprintf(f, "3 %d %d %d\n", wall->tri[3 * t], wall->tri[3 * t + 1],
                wall->tri[3 * t + 2]);
    fclose(f);

    snprintf(path, sizeof path, "%s/post/bodies_%04d.vtk", dir, frame);
    f = fopen(path, "w");
    if (!f)
        return 0;
    const int per = (NLAT + 1) * NLON, quads = NLAT * NLON;
    fprintf(
        f,
        "# vtk DataFile Version 3.0\nbodies\nASCII\nDATASET POLYDATA\nPOINTS %d double\n",
        NB * per);
    for (int i = 0; i < NB; i++)
        write_body(f, &d->body[i], NULL);
    fprintf(f, "POLYGONS %d %d\n", NB * 2 * quads, NB * 2 * quads * 4);
    for (int i = 0; i < NB; i++)
        for (int a = 0; a < NLAT; a++)
            for (int b = 0; b < NLON; b++) {
                const int p00 = i * per + a * NLON + b,
                          p01 = i * per + a * NLON + (b + 1) % NLON;
                const int p10 = p00 + NLON, p11 = p01 + NLON;
                fprintf(f, "3 %d %d %d\n3 %d %d %d\n", p00, p10, p11, p00, p11, p01);
            }
    fprintf(f, "CELL_DATA %d\nSCALARS body int 1\nLOOKUP_TABLE default\n", NB * 2 * quads);
    for (int i = 0; i < NB; i++)
        for (int q = 0; q < 2 * quads; q++)
            fprintf(f, "%d\n", i);
    fclose(f);
    return 1;
}

/* The deepest excursion of body i beyond the drum's walls (0 inside): its support along
 * the outward radius and along -z and +z, in the drum's frame (the drum turns about its
 * own axis, which stays put). */
static double excursion(const rs_body *b)
{
    double p[3], worst = 0.0;
    const double rho = hypot(b->x[0], b->x[1]);
    const double out[3] = {rho > 0 ? b->x[0] / rho : 1.0, rho > 0 ? b->x[1] / rho : 0.0,
                           0.0};
    rs_body_support(b, out, p);
    worst = fmax(worst, hypot(p[0], p[1]) - 0.1);
    const double down[3] = {0, 0, -1}, up[3] = {0, 0, 1};
    rs_body_support(b, down, p);
    worst = fmax(worst, -p[2]);
    rs_body_support(b, up, p);
    worst = fmax(worst, p[2] - 0.06);
    return worst;
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: %s DRUM.inp OUTDIR\n", argv[0]);
        return 2;
    }
    rs_error err;
    rs_error_clear(&err);
    rs_surface drum;
    if (rs_surface_read(argv[1], NULL, &drum, &err) != RS_OK) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    rs_shape shape[NB];
    int rc = rs_shape_make_box(&shape[0], 0.010, 0.006, 0.002, 0.002, &err);
    if (!rc)
        rc = rs_shape_make_capsule(&shape[1], 0.005, 0.008, 0.0, &err);
    if (!rc)
        rc = rs_shape_make_box(&shape[2], 0.006, 0.006, 0.006, 0.002, &err);
    rs_driver d;
    if (!rc)
        rc = rs_driver_init(&d, &drum, NB, &err);
    /* hooke: kn, kt (N/m), damping ratios, friction */
    const double law[5] = {2e4, 2e4, 0.3, 0.3, 0.5};
    if (!rc)
        rc = rs_driver_set_law(&d, rs_law_find("hooke"), law, 5, 2, &err);
    const double omega = 3.0, g = 9.81, axis[3] = {0, 0, 1}, centre[3] = {0, 0, 0};
    if (!rc)
        rc = rs_motion_set_rotation(&d.motion, centre, axis, omega, &err);
    for (int i = 0; i < NB && !rc; i++)
        rc = rs_driver_set_body(&d, i, &shape[i], 1500.0, &err);
    if (rc) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    d.moving = 1;
    d.dt = 2e-5;
    d.tracking = 5e-4;
    for (int i = 0; i < NB; i++) {
        d.x[i] = -0.03 + 0.03 * i;
        d.y[i] = -0.06;
        d.z[i] = 0.012 + 0.018 * i;
        const double a = 0.7 * (i + 1), ax[3] = {1.0, 0.5 * i, 0.3};
        const double n = rs_norm3(ax);
        d.q[4 * i] = cos(0.5 * a);
        for (int k = 0; k < 3; k++)
            d.q[4 * i + 1 + k] = sin(0.5 * a) * ax[k] / n;
        d.fext[3 * i + 1] = -g * d.mass[i];
    }
    rs_trimesh wall;
    memset(&wall, 0, sizeof wall);
    if (rs_surface_triangulate(&drum, 0.005, 48, &wall, &err) != RS_OK) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    char path[512];
    snprintf(path, sizeof path, "%s/bodies.csv", argv[2]);
    FILE *csv = fopen(path, "w");
    if (!csv) {
        fprintf(stderr, "%s: cannot write\n", path);
        return 1;
    }
    fprintf(csv, "t");
    for (int i = 0; i < NB; i++)
        fprintf(csv, ",%s_x,%s_y,%s_z,%s_tilt,%s_speed,%s_contacts", NAMES[i], NAMES[i],
                NAMES[i], NAMES[i], NAMES[i], NAMES[i]);
    fprintf(csv, "\n");
    const int steps = 300000, every = 500, vtk_every = 2500; /* 6 s */
    double worst = 0.0;
    int frame = 0, ncon[NB];
    for (int k = 0; k <= steps; k++) {
        if (rs_driver_step(&d, &err) != RS_OK) {
            fprintf(stderr, "step %d: %s\n", k, err.msg);
            return 1;
        }
        memset(ncon, 0, sizeof ncon);
        for (int e = 0; e < d.trk.n; e++)
            ncon[d.trk.point[e]]++;
        for (int i = 0; i < NB; i++)
            worst = fmax(worst, excursion(&d.body[i]));
        if (k % every == 0) {
            fprintf(csv, "%.4f", d.t);
            for (int i = 0; i < NB; i++) {
                double R[9];
                rs_quat_matrix(d.q + 4 * i, R);
                const double v =
                    sqrt(d.vx[i] * d.vx[i] + d.vy[i] * d.vy[i] + d.vz[i] * d.vz[i]);
                fprintf(csv, ",%.6g,%.6g,%.6g,%.6g,%.6g,%d", d.x[i], d.y[i], d.z[i],
                        acos(fmin(1.0, fabs(R[8]))) * 180.0 / RS_PI, v, ncon[i]);
            }
            fprintf(csv, "\n");
        }
        if (k % vtk_every == 0 && !write_vtk(argv[2], frame++, &d, &wall, &d.motion.pose)) {
            fprintf(stderr, "%s/post: cannot write\n", argv[2]);
            return 1;
        }
    }
    fclose(csv);
    printf("%d steps, %.2f s of a drum turning at %.1f rad/s; %d VTK frames\n", steps, d.t,
           omega, frame);
    printf("deepest excursion of a body beyond the wall: %.3g m (contact overlap)\n",
           worst);
    const int ok = worst < 2e-3;
    printf("%s: the bodies stay inside the drum\n", ok ? "PASS" : "FAIL");
    rs_trimesh_free(&wall);
    rs_driver_free(&d);
    for (int i = 0; i < NB; i++)
        rs_shape_free(&shape[i]);
    rs_surface_free(&drum);
    return ok ? 0 : 1;
}
