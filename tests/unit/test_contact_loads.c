/* rs_cblock_loads against the contact force written out by hand: F = w A (s1 n - s2 t1 -
 * s3 t2) at the contact point, its torque about the particle's centre, the wall's
 * force and moment, the energies and heat, and a leaving contact that carries none; in
 * 3D and for SEGMENTS (nDir 2, the contact point at the particle's z). rs_cblock_add_loads
 * against rs_cblock_loads summed per particle by hand, bit for bit, onto rows in another
 * order, with unit and given areas. */
#include "rigidsurf/contact_block.h"
#include "rigidsurf/law.h"
#include "rigidsurf/vec.h"
#include "rs_test.h"

/* The tracker's output of n contacts as the loads read it. */
static rs_track_out track_out(int n, int ndir, int nleave, int *point, double **dir,
                              double *rdisp, double *alocal, double *coord, double *share)
{
    const rs_track_out o = {.n = n,
                            .ndir = ndir,
                            .nleave = nleave,
                            .shared = 1,
                            .point = point,
                            .dir = dir,
                            .rdisp = rdisp,
                            .alocaldir = alocal,
                            .coordslv = coord,
                            .share = share};
    return o;
}

/* The law's results the loads read: e[0 .. 6] are sed, sfd, spd, svd, scd, fluxSlv and
 * fluxMst per contact. */
static rs_contact_block law_results(double *stress, double *area, double *const e[7])
{
    const rs_contact_block cb = {.stress = stress,
                                 .area = area,
                                 .sed = e[0],
                                 .sfd = e[1],
                                 .spd = e[2],
                                 .svd = e[3],
                                 .scd = e[4],
                                 .flux_slv = e[5],
                                 .flux_mst = e[6]};
    return cb;
}

static void test_loads_in_3d(void)
{
    /* particle 0 at (1, 2, 3); contact 0 on it: n = z, t1 = x, t2 = y; contact 1
     * leaving; contact 2 on particle 1 at the origin: n = x, t1 = y, t2 = z */
    const double px[2] = {1, 0}, py[2] = {2, 0}, pz[2] = {3, 0};
    const double pa[2] = {2, 1}; /* areas: 2 on particle 0, 1 on particle 1 */
    const rs_particle_block p = {.n = 2, .x = px, .y = py, .z = pz, .area = pa};
    double live = RS_DIR_LIVE(4), gone = RS_DIR_LEAVING(5);
    double *dir[3] = {&live, &gone, &live};
    int point[3] = {0, 0, 1};
    double alocal[27] = {0, 0, 1, 1, 0, 0, 0, 1, 0, /* leaving: any */ 0,
                         0, 1, 1, 0, 0, 0, 1, 0, 1, 0,
                         0, 0, 1, 0, 0, 0, 1};
    double coord[9] = {1, 2, 2.5, 0, 0, 0, 0.5, 0, 0};
    double rdisp[9] = {1e-3, 0, 0, 7, 0, 0, -1e-4, 0, 0};
    double share[3] = {0.5, 1, 1};
    rs_track_out o = track_out(3, 3, 1, point, dir, rdisp, alocal, coord, share);
    double stress[9] = {10, 2, -3, 99, 99, 99, 4, 1, 0};
    double area[3] = {2, 2, 1}, sed[3] = {1, 50, 2}, sfd[3] = {0.5, 50, 0};
    double zero[3] = {0, 0, 0}, fs[3] = {3, 50, 1}, fm[3] = {-1, 50, 4};
    double *const e[7] = {sed, sfd, zero, zero, zero, fs, fm};
    rs_contact_block cb = law_results(stress, area, e);
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
    rs_track_out o = track_out(1, 2, 0, point, dir, rdisp, alocal, coord, share);
    double stress[2] = {5, 1}, area[1] = {1}, zero[1] = {0};
    double *const e[7] = {zero, zero, zero, zero, zero, zero, zero};
    rs_contact_block cb = law_results(stress, area, e);
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

/* Three particles, rows in reverse order; particle 0 has two live contacts (shares 0.6
 * and 0.4) and a leaving one, particle 1 none, particle 2 one. Each row gets the sum of
 * rs_cblock_loads's contacts added onto what it held, in the contacts' order. */
static void add_loads_case(int unit)
{
    const double px[3] = {1, 5, 0}, py[3] = {2, 5, 0}, pz[3] = {3, 5, 0};
    const double pa[3] = {2, 1, 3};
    const rs_particle_block p = {
        .n = 3, .x = px, .y = py, .z = pz, .area = unit ? NULL : pa};
    double live = RS_DIR_LIVE(4), gone = RS_DIR_LEAVING(5);
    double *dir[4] = {&live, &gone, &live, &live};
    int point[4] = {0, 0, 0, 2};
    double alocal[36] = {0,   0, 1, 1, 0, 0,   0,    1, 0, /* leaving */ 9,
                         9,   9, 9, 9, 9, 9,   9,    9, 0, 0.6,
                         0.8, 1, 0, 0, 0, 0.8, -0.6, 1, 0, 0,
                         0,   1, 0, 0, 0, 1};
    double coord[12] = {1, 2, 2.5, 9, 9, 9, 1.1, 2.3, 2.6, 0.5, 0, 0};
    double rdisp[12] = {1e-3, 0, 0, 7, 0, 0, 2e-3, 0, 0, -1e-4, 0, 0};
    double share[4] = {0.6, 1, 0.4, 1};
    rs_track_out o = track_out(4, 3, 1, point, dir, rdisp, alocal, coord, share);
    o.shared = !unit;
    double stress[12] = {10, 2, -3, 99, 99, 99, 7, -1, 0.5, 4, 1, 0};
    double area[4] = {2, 2, 2, 3}, one[4] = {1, 1, 1, 1};
    double sed[4] = {1, 50, 3, 2}, sfd[4] = {0.5, 50, 0.25, 0}, spd[4] = {0, 9, 1, 2};
    double svd[4] = {3, 9, 0, 1}, scd[4] = {0, 9, 0, 0.5};
    double fs[4] = {3, 50, 2, 1}, fm[4] = {-1, 50, 0.5, 4};
    double *const e[7] = {sed, sfd, spd, svd, scd, fs, fm};
    rs_contact_block cb = law_results(stress, unit ? one : area, e);
    const double origin[3] = {0, 0, 1};
    double f[12], t[12], q[4];
    rs_wall_load w, wa;
    rs_cblock_loads(&cb, &o, &p, origin, f, t, q, &w);

    /* rows: particle k at row 2 - k, each row starting from its own values */
    double F[3][3], T[3][3], S[3][3], Q[3], Fh[3][3], Th[3][3], Sh[3][3], Qh[3];
    for (int r = 0; r < 3; r++) {
        for (int c = 0; c < 3; c++) {
            F[r][c] = Fh[r][c] = 0.1 * r + c;
            T[r][c] = Th[r][c] = -0.2 * r + c;
            S[r][c] = Sh[r][c] = 0.3 * r - c;
        }
        Q[r] = Qh[r] = r;
    }
    const int row[3] = {2, 1, 0};
    for (int e = 0; e < 4; e++) { /* by hand: the contacts' order, leaving ones add 0 */
        if (e == 1)
            continue;
        const int r = row[point[e]];
        for (int c = 0; c < 3; c++) {
            Fh[r][c] += f[3 * e + c];
            Th[r][c] += t[3 * e + c];
            Sh[r][c] += f[3 * e + c];
        }
        Qh[r] += q[e];
    }
    int deepest[3];
    const rs_load_rows rows = {
        .row = row, .f = F[0], .t = T[0], .fstore = S[0], .q = Q, .deepest = deepest};
    rs_cblock_add_loads(&cb, &o, &p, origin, &rows, &wa);
    for (int r = 0; r < 3; r++) {
        for (int c = 0; c < 3; c++) {
            ENSURE(F[r][c] == Fh[r][c]);
            ENSURE(T[r][c] == Th[r][c]);
            ENSURE(S[r][c] == Sh[r][c]);
        }
        ENSURE(Q[r] == Qh[r]);
    }
    ENSURE(deepest[0] == 2 && deepest[1] == -1 && deepest[2] == 3);
    for (int c = 0; c < 3; c++) {
        ENSURE(wa.force[c] == w.force[c]);
        ENSURE(wa.moment[c] == w.moment[c]);
    }
    ENSURE(wa.se == w.se && wa.fd == w.fd && wa.pd == w.pd && wa.vd == w.vd &&
           wa.cd == w.cd && wa.flux_slv == w.flux_slv && wa.flux_mst == w.flux_mst &&
           wa.ncontact == w.ncontact && w.ncontact == 2);
    /* and the sums themselves, written out: w A per contact */
    const double wA[4] = {unit ? 1 : 1.2, 0, unit ? 1 : 0.8, unit ? 1 : 3};
    double se = 0, qm = 0;
    for (int e = 0; e < 4; e++) {
        se += wA[e] * sed[e];
        qm += wA[e] * fm[e];
    }
    ENSURE_NEAR(w.se, se, 1e-14);
    ENSURE_NEAR(w.flux_mst, qm, 1e-14);
}

static void test_add_loads_onto_rows(void)
{
    add_loads_case(0);
    add_loads_case(1);
}

/* The loads of a law that declares zero heat flows and zero creep and plastic
 * dissipation (rs_law.sets, recorded by rs_cblock_call in cb.law_sets): the same rows
 * and totals, bit for bit, as the full sums over those zeros, and the four arrays are
 * not read (what they hold does not matter). */
static void lean_loads(rs_contact_block *cb, const rs_track_out *o,
                       const rs_particle_block *p, double rows_out[12], rs_wall_load *w)
{
    double F[2][3] = {{1, 2, 3}, {4, 5, 6}}, T[2][3] = {{0}}, Q[2] = {0.5, -0.5};
    const int row[2] = {1, 0};
    const rs_load_rows rows = {.row = row, .f = F[0], .t = T[0], .q = Q};
    const double origin[3] = {0, 0, 1};
    rs_cblock_add_loads(cb, o, p, origin, &rows, w);
    for (int r = 0; r < 2; r++)
        for (int c = 0; c < 3; c++) {
            rows_out[6 * r + c] = F[r][c];
            rows_out[6 * r + 3 + c] = T[r][c];
        }
    ENSURE(Q[0] == 0.5 && Q[1] == -0.5); /* no heat */
}

static void test_loads_of_a_lean_law(void)
{
    const double px[2] = {1, 0}, py[2] = {2, 0}, pz[2] = {3, 0};
    const rs_particle_block p = {.n = 2, .x = px, .y = py, .z = pz};
    double live = RS_DIR_LIVE(4), gone = RS_DIR_LEAVING(5);
    double *dir[3] = {&live, &gone, &live};
    int point[3] = {0, 0, 1};
    double alocal[27] = {0, 0, 1, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0,
                         0, 0, 1, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    double coord[9] = {1, 2, 2.5, 0, 0, 0, 0.5, 0, 0};
    double rdisp[9] = {1e-3, 0, 0, 7, 0, 0, 2e-4, 0, 0};
    double share[3] = {1, 1, 1};
    for (int nleave = 0; nleave < 2; nleave++) {
        double alive = RS_DIR_LIVE(5);
        dir[1] = nleave ? &gone : &alive;
        rs_track_out o = track_out(3, 3, nleave, point, dir, rdisp, alocal, coord, share);
        o.shared = 0;
        double stress[9] = {10, 2, -3, 5, 1, 1, 4, 1, 0.5};
        double area[3] = {1, 1, 1}, sed[3] = {1, 50, 2}, sfd[3] = {0.5, 50, 0};
        double svd[3] = {3, 9, 0.25}, zero[4][3] = {{0}};
        double *const e[7] = {sed, sfd, zero[0], svd, zero[1], zero[2], zero[3]};
        rs_contact_block full = law_results(stress, area, e), lean = full;
        full.area_mode = lean.area_mode = RS_AREA_NODE;
        lean.law_sets = RS_LAW_SETS_NO_HEAT | RS_LAW_SETS_NO_CREEP_PLASTIC;
        double rf[12], rl[12];
        rs_wall_load wf, wl;
        lean_loads(&full, &o, &p, rf, &wf);
        for (int k = 0; k < 4; k++) /* not read by the lean loads */
            for (int c = 0; c < 3; c++)
                zero[k][c] = 1e3 * (k + 1) + c;
        lean_loads(&lean, &o, &p, rl, &wl);
        for (int k = 0; k < 12; k++)
            ENSURE(rl[k] == rf[k]);
        for (int c = 0; c < 3; c++)
            ENSURE(wl.force[c] == wf.force[c] && wl.moment[c] == wf.moment[c]);
        ENSURE(wl.se == wf.se && wl.fd == wf.fd && wl.vd == wf.vd);
        ENSURE(wl.pd == 0.0 && wl.cd == 0.0 && wl.flux_slv == 0.0 && wl.flux_mst == 0.0);
        ENSURE(wf.pd == 0.0 && wf.cd == 0.0 && wf.flux_slv == 0.0 && wf.flux_mst == 0.0);
        ENSURE(wl.ncontact == wf.ncontact && wf.ncontact == 3 - nleave);
        ENSURE(wf.se != 0.0 && wf.vd != 0.0);
    }
}

int main(void)
{
    RS_RUN(test_loads_in_3d);
    RS_RUN(test_loads_of_segments);
    RS_RUN(test_add_loads_onto_rows);
    RS_RUN(test_loads_of_a_lean_law);
    return rs_test_summary();
}
