/* One sphere with prescribed velocity against a surface, through the standalone driver
 * (rs_driver) and law hertz: prints, for every increment k (the sphere at
 * x0 + k dt v), the law's stress s1 s2 s3 of its deepest contact and rdisp1 (zeros
 * without a contact). Used by test_driver_equivalence.py against fix wall/rigid.
 *
 *   driver_hertz SURFACE NAME R MASS X0 Y0 Z0 VX VY VZ DT STEPS TRACKING
 *                Y_P NU_P Y_W NU_W RESTITUTION FRICTION CURVATURE */
#include "rigidsurf/driver.h"

#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    if (argc != 21) {
        fprintf(stderr, "usage: driver_hertz SURFACE NAME R MASS X0 Y0 Z0 VX VY VZ DT STEPS "
                        "TRACKING Y_P NU_P Y_W NU_W RESTITUTION FRICTION CURVATURE\n");
        return 2;
    }
    double a[18];
    for (int i = 0; i < 18; i++) {
        char *end;
        a[i] = strtod(argv[3 + i], &end);
        if (*end) {
            fprintf(stderr, "driver_hertz: argument %d '%s' is not a number\n", 3 + i,
                    argv[3 + i]);
            return 2;
        }
    }
    rs_error err;
    rs_surface s;
    rs_driver d;
    if (rs_surface_read(argv[1], argv[2], &s, &err)) {
        fprintf(stderr, "driver_hertz: %s\n", err.msg);
        return 1;
    }
    const double props[7] = {a[11], a[12], a[13], a[14], a[15], a[16], a[17]};
    if (rs_driver_init(&d, &s, 1, &err) ||
        rs_driver_set_law(&d, rs_law_find("hertz"), props, 7, 2, &err)) {
        fprintf(stderr, "driver_hertz: %s\n", err.msg);
        rs_surface_free(&s);
        return 1;
    }
    d.radius[0] = a[0];
    d.mass[0] = a[1];
    d.x[0] = a[2], d.y[0] = a[3], d.z[0] = a[4];
    for (int c = 0; c < 3; c++) {
        d.fixed[c] = 1;
        d.vpres[c] = a[5 + c];
    }
    d.vx[0] = a[5], d.vy[0] = a[6], d.vz[0] = a[7];
    d.dt = a[8];
    d.tracking = a[10];
    const int steps = (int)a[9];
    int rc = 0;
    for (int k = 0; k <= steps && !rc; k++) {
        if ((rc = rs_driver_step(&d, &err)) != RS_OK) {
            fprintf(stderr, "driver_hertz: %s\n", err.msg);
            break;
        }
        int best = -1;
        const int nd = d.trk.ndir;
        for (int e = 0; e < d.trk.n; e++)
            if (best < 0 || d.trk.rdisp[e * nd] > d.trk.rdisp[best * nd])
                best = e;
        if (best < 0 || d.trk.rdisp[best * nd] >= RS_MAXVAL)
            printf("%d 0 0 0 0\n", k);
        else
            printf("%d %.17g %.17g %.17g %.17g\n", k, d.cb.stress[best * nd],
                   d.cb.stress[best * nd + 1], d.cb.stress[best * nd + 2],
                   d.trk.rdisp[best * nd]);
    }
    rs_driver_free(&d);
    rs_surface_free(&s);
    return rc ? 1 : 0;
}
