/* rs_cblock_loads against the contact force written out by hand: F = w A (s1 n - s2 t1 -
 * s3 t2) at the contact point, its torque about the particle's centre, the wall's
 * force and moment, the energies and heat, and a leaving contact that carries none; in
 * 3D and for SEGMENTS (nDir 2, the contact point at the particle's z). */
#include "rigidsurf/contact_block.h"
#include "rigidsurf/vec.h"
#include "rs_test.h"

static void test_loads_in_3d(void)
{
    /* particle 0 at (1, 2, 3); contact 0 on it: n = z, t1 = x, t2 = y; contact 1
     * leaving; contact 2 on particle 1 at the origin: n = x, t1 = y, t2 = z */
    const double px[2] = {1, 0}, py[2] = {2, 0}, pz[2] = {3, 0};
    const rs_particle_block p = {.n = 2, .x = px, .y = py, .z = pz};
    double live = RS_DIR_LIVE(4), gone = RS_DIR_LEAVING(5);
    double *dir[3] = {&live, &gone, &live};
    int point[3] = {0, 0, 1};
    double alocal[27] = {0, 0, 1, 1, 0, 0, 0, 1, 0, /* leaving: any */ 0,
                         0, 1, 1, 0, 0, 0, 1, 0, 1, 0,
                         0, 0, 1, 0, 0, 0, 1};
    double coord[9] = {1, 2, 2.5, 0, 0, 0, 0.5, 0, 0};
    double rdisp[9] = {1e-3, 0, 0, 7, 0, 0, -1e-4, 0, 0};
    double share[3] = {0.5, 1, 1};
    rs_track_out o = {.n = 3,
                      .ndir = 3,
                      .point = point,
                      .dir = dir,
                      .rdisp = rdisp,
                      .alocaldir = alocal,
                      .coordslv = coord,
                      .share = share};
    double stress[9] = {10, 2, -3, 99, 99, 99, 4, 1, 0};
    double area[3] = {2, 2, 1}, sed[3] = {1, 50, 2}, sfd[3] = {0.5, 50, 0};
    double zero[3] = {0, 0, 0}, fs[3] = {3, 50, 1}, fm[3] = {-1, 50, 4};
    rs_contact_block cb = {.stress = stress,
                           .area = area,
                           .sed = sed,
                           .sfd = sfd,
                           .spd = zero,
                           .svd = zero,
                           .scd = zero,
                           .flux_slv = fs,
                           .flux_mst = fm};
    double f[9], t[9], q[3];
    rs_wall_load w;
    const double origin[3] = {0, 0, 1};
    rs_cblock_loads(&cb, &o, &p, origin, f, t, q, &w);
    /* contact 0: w A = 1; F = 10 z - 2 x + 3 y */
    const double F0[3] = {-2, 3, 10}, r0[3] = {0, 0, -0.5};
    double T0[3];
    rs_cross3(r0, F0, T0);
    for (int c = 0; c < 3; c++) {
        ENSURE_NEAR(f[c], F0[c], 1e-15);
        ENSURE_NEAR(t[c], T0[c], 1e-15);
        ENSURE_NEAR(f[3 + c], 0.0, 0.0);
        ENSURE_NEAR(t[3 + c], 0.0, 0.0);
    }
    /* contact 2: w A = 1; F = 4 x - 1 y */
    const double F2[3] = {4, -1, 0}, r2[3] = {0.5, 0, 0};
    double T2[3];
    rs_cross3(r2, F2, T2);
    for (int c = 0; c < 3; c++) {
        ENSURE_NEAR(f[6 + c], F2[c], 1e-15);
        ENSURE_NEAR(t[6 + c], T2[c], 1e-15);
        ENSURE_NEAR(w.force[c], -F0[c] - F2[c], 1e-14);
    }
    /* the wall's moment about (0, 0, 1): sum of (x_cp - o) x (-F) */
    const double a0[3] = {1, 2, 1.5}, a2[3] = {0.5, 0, -1};
    double m0[3], m2[3];
    rs_cross3(a0, F0, m0);
    rs_cross3(a2, F2, m2);
    for (int c = 0; c < 3; c++)
        ENSURE_NEAR(w.moment[c], -m0[c] - m2[c], 1e-14);
    ENSURE_NEAR(w.se, 1 * 1 + 1 * 2, 1e-15);
    ENSURE_NEAR(w.fd, 0.5, 1e-15);
    ENSURE_NEAR(w.flux_slv, 3 + 1, 1e-15);
    ENSURE_NEAR(w.flux_mst, -1 + 4, 1e-15);
    ENSURE_NEAR(q[0], 3, 1e-15);
    ENSURE_NEAR(q[1], 0, 0);
    ENSURE(w.ncontact == 1);
}

static void test_loads_of_segments(void)
{
    const double px[1] = {1}, py[1] = {1}, pz[1] = {0.25};
    const rs_particle_block p = {.n = 1, .x = px, .y = py, .z = pz};
    double live = RS_DIR_LIVE(0);
    double *dir[1] = {&live};
    int point[1] = {0};
    /* n = (0, 1), t1 = (1, 0) in the plane; the contact at (1, 0.5) */
    double alocal[4] = {0, 1, 1, 0}, coord[2] = {1, 0.5}, rdisp[2] = {1e-3, 0};
    double share[1] = {1};
    rs_track_out o = {.n = 1,
                      .ndir = 2,
                      .point = point,
                      .dir = dir,
                      .rdisp = rdisp,
                      .alocaldir = alocal,
                      .coordslv = coord,
                      .share = share};
    double stress[2] = {5, 1}, area[1] = {1}, zero[1] = {0};
    rs_contact_block cb = {.stress = stress,
                           .area = area,
                           .sed = zero,
                           .sfd = zero,
                           .spd = zero,
                           .svd = zero,
                           .scd = zero,
                           .flux_slv = zero,
                           .flux_mst = zero};
    double f[3], t[3];
    rs_wall_load w;
    const double origin[3] = {0, 0, 0};
    rs_cblock_loads(&cb, &o, &p, origin, f, t, NULL, &w);
    ENSURE_NEAR(f[0], -1, 1e-15);
    ENSURE_NEAR(f[1], 5, 1e-15);
    ENSURE_NEAR(f[2], 0, 0);
    /* r = (0, -0.5, 0): torque z = r_x F_y - r_y F_x = -0.5 */
    ENSURE_NEAR(t[0], 0, 0);
    ENSURE_NEAR(t[1], 0, 0);
    ENSURE_NEAR(t[2], -0.5, 1e-15);
    /* the wall's moment about the origin of -F at (1, 0.5, 0.25) */
    ENSURE_NEAR(w.moment[2], -(1 * 5 - 0.5 * -1), 1e-15);
}

int main(void)
{
    RS_RUN(test_loads_in_3d);
    RS_RUN(test_loads_of_segments);
    return rs_test_summary();
}
