/* Convex bodies down a faceted chute in the standalone driver: the bodies of tumble.c
 * (a rounded-box tablet lying flat, a die, a capsule across the slope) on a plate of
 * two triangles held as arrays (rs_surface_make_mesh, a MESH) inclined at 30 degrees,
 * law hooke with friction 0.3. The tablet and the die slide at g (sin - mu cos); the
 * capsule rolls without slipping at g sin / (1 + I / (m r^2)).
 *
 *   convex_chute OUTDIR
 *
 * Writes OUTDIR/chute.csv (per 0.005 s: time and each body's distance down the slope)
 * and OUTDIR/post/chute_*.vtk (the plate and the bodies, every 0.05 s), prints the
 * measured accelerations against the closed forms and checks them to 1 %. */
#include "rigidsurf/convex.h"
#include "rigidsurf/driver.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <stdio.h>

enum { NB = 3, NLAT = 12, NLON = 24 };

static const char *NAMES[NB] = {"tablet", "die", "capsule"};

static int write_vtk(const char *dir, int frame, const rs_driver *d, const double *xyz)
{
    char path[512];
    snprintf(path, sizeof path, "%s/post/chute_%04d.vtk", dir, frame);
    FILE *f = fopen(path, "w");
    if (!f)
        return 0;
    const int per = (NLAT + 1) * NLON, quads = NLAT * NLON;
    fprintf(
        f, "# vtk DataFile Version 3.0\nchute\nASCII\nDATASET POLYDATA\nPOINTS %d double\n",
        4 + NB * per);
    for (int v = 0; v < 4; v++)
        fprintf(f, "%.9g %.9g %.9g\n", xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);
    for (int i = 0; i < NB; i++)
        for (int a = 0; a <= NLAT; a++)
            for (int b = 0; b < NLON; b++) {
                const double th = RS_PI * a / NLAT, ph = 2.0 * RS_PI * b / NLON;
                const double dd[3] = {sin(th) * cos(ph), sin(th) * sin(ph), cos(th)};
                double p[3];
                rs_body_support(&d->body[i], dd, p);
                fprintf(f, "%.9g %.9g %.9g\n", p[0], p[1], p[2]);
            }
    fprintf(f, "POLYGONS %d %d\n3 0 1 2\n3 0 2 3\n", 2 + NB * 2 * quads,
            8 + NB * 8 * quads);
    for (int i = 0; i < NB; i++)
        for (int a = 0; a < NLAT; a++)
            for (int b = 0; b < NLON; b++) {
                const int p00 = 4 + i * per + a * NLON + b;
                const int p01 = 4 + i * per + a * NLON + (b + 1) % NLON;
                fprintf(f, "3 %d %d %d\n3 %d %d %d\n", p00, p00 + NLON, p01 + NLON, p00,
                        p01 + NLON, p01);
            }
    fclose(f);
    return 1;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: %s OUTDIR\n", argv[0]);
        return 2;
    }
    const double th = 30.0 * RS_PI / 180.0, mu = 0.3, g = 9.81, L = 1.0, W = 0.2;
    /* the plate: down the slope along s = (cos, 0, -sin), across along y */
    const double s[3] = {cos(th), 0.0, -sin(th)}, up[3] = {sin(th), 0.0, cos(th)};
    double xyz[12];
    const double corners[4][2] = {{0, -W}, {L, -W}, {L, W}, {0, W}};
    for (int v = 0; v < 4; v++)
        for (int c = 0; c < 3; c++)
            xyz[3 * v + c] = corners[v][0] * s[c] + (c == 1 ? corners[v][1] : 0.0);
    const int tri[6] = {0, 1, 2, 0, 2, 3};
    rs_error err;
    rs_error_clear(&err);
    rs_surface plate;
    const rs_mesh_def def = RS_MESH_DEF_INIT;
    rs_shape shape[NB];
    rs_driver d;
    int rc = rs_surface_make_mesh(xyz, 4, tri, 2, &def, &plate, &err);
    if (!rc)
        rc = rs_shape_make_box(&shape[0], 0.010, 0.006, 0.002, 0.002, &err);
    if (!rc)
        rc = rs_shape_make_box(&shape[1], 0.006, 0.006, 0.006, 0.002, &err);
    if (!rc)
        rc = rs_shape_make_capsule(&shape[2], 0.005, 0.008, 0.0, &err);
    if (!rc)
        rc = rs_driver_init(&d, &plate, NB, &err);
    const double law[5] = {2e4, 2e4, 0.7, 0.7, mu};
    if (!rc)
        rc = rs_driver_set_law(&d, rs_law_find("hooke"), law, 5, 2, &err);
    for (int i = 0; i < NB && !rc; i++)
        rc = rs_driver_set_body(&d, i, &shape[i], 1500.0, &err);
    if (rc) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    d.dt = 1e-5;
    d.tracking = 2e-4;
    /* each body at rest on the plate (its lowest point on it), its body z along the
     * plate's normal; the capsule's axis (body z) across the slope, along y */
    const double half[NB] = {0.004, 0.008, 0.005}, across[NB] = {-0.1, 0.0, 0.1};
    for (int i = 0; i < NB; i++) {
        /* tablet and die: body z turned about y onto the plate's normal; capsule: body z
         * turned about x onto y */
        const double ax[3] = {0, 1, 0}, ax2[3] = {1, 0, 0};
        const double a = i == 2 ? -0.5 * RS_PI : th;
        const double *axis = i == 2 ? ax2 : ax;
        d.q[4 * i] = cos(0.5 * a);
        for (int k = 0; k < 3; k++)
            d.q[4 * i + 1 + k] = sin(0.5 * a) * axis[k];
        const double s0 = 0.05, lift = half[i] - g * cos(th) * d.mass[i] / (4.0 * law[0]);
        d.x[i] = s0 * s[0] + lift * up[0];
        d.y[i] = across[i];
        d.z[i] = s0 * s[2] + lift * up[2];
        d.fext[3 * i + 2] = -g * d.mass[i];
    }
    char path[512];
    snprintf(path, sizeof path, "%s/chute.csv", argv[1]);
    FILE *csv = fopen(path, "w");
    if (!csv) {
        fprintf(stderr, "%s: cannot write\n", path);
        return 1;
    }
    fprintf(csv, "t,%s,%s,%s\n", NAMES[0], NAMES[1], NAMES[2]);
    const int steps = 40000; /* 0.4 s */
    double v1[NB], v0[NB];
    int frame = 0;
    for (int k = 0; k <= steps; k++) {
        if (rs_driver_step(&d, &err) != RS_OK) {
            fprintf(stderr, "step %d: %s\n", k, err.msg);
            return 1;
        }
        if (k % 500 == 0) {
            fprintf(csv, "%.4f", d.t);
            for (int i = 0; i < NB; i++)
                fprintf(csv, ",%.9g", d.x[i] * s[0] + d.z[i] * s[2]);
            fprintf(csv, "\n");
        }
        if (k % 5000 == 0 && !write_vtk(argv[1], frame++, &d, xyz)) {
            fprintf(stderr, "%s/post: cannot write\n", argv[1]);
            return 1;
        }
        for (int i = 0; i < NB; i++) {
            const double v = d.vx[i] * s[0] + d.vz[i] * s[2];
            if (k == 10000)
                v0[i] = v;
            if (k == steps)
                v1[i] = v;
        }
    }
    fclose(csv);
    int ok = 1;
    const double slide = g * (sin(th) - mu * cos(th));
    for (int i = 0; i < NB; i++) {
        const double a = (v1[i] - v0[i]) / ((steps - 10000) * d.dt);
        const double r = 0.005, roll = g * sin(th) /
                                       (1.0 + d.inertia[3 * i + 2] / (d.mass[i] * r * r));
        const double want = i == 2 ? roll : slide;
        const int good = fabs(a - want) <= 0.01 * want;
        ok &= good;
        printf("%-8s %s at %.4f m/s^2, closed form %.4f (%s): %s\n", NAMES[i],
               i == 2 ? "rolls" : "slides", a, want,
               i == 2 ? "g sin / (1 + I / m r^2)" : "g (sin - mu cos)",
               good ? "PASS" : "FAIL");
    }
    rs_driver_free(&d);
    for (int i = 0; i < NB; i++)
        rs_shape_free(&shape[i]);
    rs_surface_free(&plate);
    return ok ? 0 : 1;
}
