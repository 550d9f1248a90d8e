/* The Abaqus VUINTER verification cases for analytic rigid masters, run in the
 * standalone explicit driver, each twice: with the built-in bonded_interface and with
 * the Fortran VUINTER of tests/fortran/vuinter_bonded.f. Both must agree to round-off,
 * and each is checked against the closed form:
 *   _n  (2D SEGMENTS, 3D CYLINDER, 3D REVOLUTION): uniform elastic normal response,
 *       s1 = E rdisp1 / t, equal to linear_softening with k = E/t (the bonded layer's
 *       1D modulus is E, see src/laws/bonded_interface.c).
 *   _s  (2D, 3D CYLINDER along the generator, 3D REVOLUTION spun about its axis):
 *       uniform elastic shear, tau = G slip / t with slip = relative displacement.
 *   _pl (2D, 3D): a linearly varying normal displacement that yields at one end: the
 *       stress follows the linear-hardening curve and spd sums to the plastic work.
 *   _ht (2D, 3D): master at 100, slaves at 0 with matched heat capacities: both reach
 *       50 uniformly, along the closed form of the explicit update, and the heat
 *       balance closes to 1e-9.
 * Surface files: examples/vuinter_abaqus/. */
#include "rigidsurf/driver.h"
#include "rs_test.h"

#include <float.h>
#include <stdlib.h>

enum { GEO_FLAT2D, GEO_DRUM3D, GEO_SHELL3D };
enum { LOAD_NORMAL, LOAD_SHEAR, LOAD_PLASTIC, LOAD_HEAT };

#define NNODE 6
#define PI 3.14159265358979323846
#define MAXINC 2000

/* gap cutoff, E, nu, yield stress, hardening, thickness, conductivity */
static const double P_E = 2e8, P_NU = 0.3, P_SY = 1e6, P_H = 2e7, P_T = 1e-3, P_K = 0.5;
static const double DT = 1e-5;

typedef struct history {
    int ninc, nd;
    double s[MAXINC][NNODE][3]; /* stress */
    double r[MAXINC][NNODE][3]; /* rdisp */
    double spd[MAXINC][NNODE];  /* accumulated spd */
    double f[MAXINC][NNODE];    /* contact force along the inward normal */
    double temp[MAXINC][NNODE]; /* slave temperature after the increment */
    double tm[MAXINC];          /* master temperature after the increment */
    double allpd[MAXINC], allse[MAXINC], heat_slv[MAXINC], heat_mst[MAXINC];
    double t[MAXINC]; /* time of the increment's law call */
} history;

static history ha, hb, hc;
static rs_law fortran_bonded;
static int fortran_loaded;

static const char *geo_file(int geo)
{
    static char path[512];
    const char *name[3] = {"flat2d.inp", "drum3d.inp", "shell3d.inp"};
    snprintf(path, sizeof path, "%s/%s", RS_VUINTER_CASES_DIR, name[geo]);
    return path;
}

/* Node i of the geometry: position and the unit normal and first tangent there. */
static void node_at(int geo, int i, double x[3], double n[3], double t1[3])
{
    if (geo == GEO_FLAT2D) {
        x[0] = -0.8 + 1.6 * i / (NNODE - 1);
        x[1] = x[2] = 0.0;
        n[0] = 0.0, n[1] = 1.0, n[2] = 0.0;
        t1[0] = 1.0, t1[1] = 0.0, t1[2] = 0.0;
        return;
    }
    double th = geo == GEO_DRUM3D ? (10.0 + 70.0 * i / (NNODE - 1)) * PI / 180.0
                                  : 2.0 * PI * i / NNODE;
    x[0] = cos(th);
    x[1] = sin(th);
    x[2] = geo == GEO_DRUM3D ? 0.3 * i : -0.5 + (double)i / NNODE;
    n[0] = -cos(th), n[1] = -sin(th), n[2] = 0.0;
    t1[0] = 0.0, t1[1] = 0.0, t1[2] = 1.0; /* generator (cylinder), t2 x n (revolution) */
}

/* Runs one case with law (nstatev state variables) and records it in h. */
static void run_case(int geo, int load, const rs_law *law, const double *props, int nprops,
                     int nstatev, int ninc, history *h, int *ok)
{
    *ok = 0;
    rs_error err;
    rs_surface s;
    if (rs_surface_read(geo_file(geo), NULL, &s, &err) != RS_OK) {
        fprintf(stderr, "%s\n", err.msg);
        return;
    }
    rs_driver d;
    if (rs_driver_init(&d, &s, NNODE, &err) != RS_OK ||
        rs_driver_set_law(&d, law, props, nprops, nstatev, &err) != RS_OK) {
        fprintf(stderr, "%s\n", err.msg);
        rs_surface_free(&s);
        return;
    }
    d.dt = DT;
    d.tracking = 1e-3;
    const double vn = 1e-3, vt = 2e-3, vmax = 3.75e-3, omega = 0.5;
    for (int i = 0; i < NNODE; ++i) {
        double x[3], n[3], t1[3];
        node_at(geo, i, x, n, t1);
        d.x[i] = x[0], d.y[i] = x[1], d.z[i] = x[2];
        for (int c = 0; c < 3; ++c) {
            d.fixed[3 * i + c] = 1;
            if (load == LOAD_NORMAL)
                d.vpres[3 * i + c] = -vn * n[c];
            else if (load == LOAD_PLASTIC)
                d.vpres[3 * i + c] = -vmax * (i + 1.0) / NNODE * n[c];
            else if (load == LOAD_SHEAR && geo != GEO_SHELL3D)
                d.vpres[3 * i + c] = vt * t1[c];
        }
        if (load == LOAD_HEAT) {
            d.temp[i] = 0.0;
            d.heatcap[i] = 1.0;
        }
    }
    if (load == LOAD_HEAT) {
        d.tmaster = 100.0;
        d.heatcap_master = NNODE;
    }
    if (load == LOAD_SHEAR && geo == GEO_SHELL3D) {
        const double c0[3] = {0.0, 0.0, 0.0}, ax[3] = {0.0, 0.0, 1.0};
        rs_motion_set_rotation(&d.motion, c0, ax, omega, &err);
        d.moving = 1;
    }
    h->ninc = ninc;
    h->nd = rs_surface_ndir(&s);
    double spd[NNODE] = {0};
    for (int k = 0; k < ninc; ++k) {
        h->t[k] = d.t;
        if (rs_driver_step(&d, &err) != RS_OK) {
            fprintf(stderr, "increment %d: %s\n", k, err.msg);
            goto done;
        }
        if (d.trk.n != NNODE) {
            fprintf(stderr, "increment %d: %d contacts, expected %d\n", k, d.trk.n, NNODE);
            goto done;
        }
        for (int e = 0; e < d.trk.n; ++e) {
            int i = d.trk.point[e], nd = h->nd;
            double x[3], n[3], t1[3];
            node_at(geo, i, x, n, t1);
            for (int c = 0; c < 3; ++c) {
                h->s[k][i][c] = c < nd ? RS_A2(d.cb.stress, nd, c, e) : 0.0;
                h->r[k][i][c] = c < nd ? RS_A2(d.trk.rdisp, nd, c, e) : 0.0;
            }
            spd[i] += d.cb.spd[e] * d.area[i];
            h->spd[k][i] = spd[i];
            h->f[k][i] =
                d.fcon[3 * i] * n[0] + d.fcon[3 * i + 1] * n[1] + d.fcon[3 * i + 2] * n[2];
        }
        for (int i = 0; i < NNODE; ++i)
            h->temp[k][i] = d.temp[i];
        h->tm[k] = d.tmaster;
        h->allpd[k] = d.energy.allpd;
        h->allse[k] = d.energy.allse;
        h->heat_slv[k] = d.energy.heat_slv;
        h->heat_mst[k] = d.energy.heat_mst;
    }
    *ok = 1;
done:
    rs_driver_free(&d);
    rs_surface_free(&s);
}

static const double bonded_props[7] = {1e-4, 2e8, 0.3, 1e6, 2e7, 1e-3, 0.5};

/* Runs the case with the built-in (ha) and the Fortran VUINTER (hb); they must agree
 * to round-off. */
static int run_both(int geo, int load, int ninc)
{
    int ok_a, ok_b;
    rs_error err;
    if (!fortran_loaded) {
        if (rs_law_load_vuinter(RS_VUINTER_BONDED_LIB, &fortran_bonded, &err) != RS_OK) {
            fprintf(stderr, "%s\n", err.msg);
            return 0;
        }
        fortran_loaded = 1;
    }
    run_case(geo, load, rs_law_find("bonded_interface"), bonded_props, 7, 3, ninc, &ha,
             &ok_a);
    run_case(geo, load, &fortran_bonded, bonded_props, 7, 3, ninc, &hb, &ok_b);
    if (!ok_a || !ok_b)
        return 0;
    for (int k = 0; k < ninc; ++k) {
        for (int i = 0; i < NNODE; ++i) {
            for (int c = 0; c < 3; ++c) {
                double a = ha.s[k][i][c], b = hb.s[k][i][c];
                if (!(fabs(a - b) <= 1e-12 * fmax(1.0, fabs(a)))) {
                    fprintf(stderr,
                            "C and Fortran differ: inc %d node %d s%d: %.17g %.17g\n", k, i,
                            c + 1, a, b);
                    return 0;
                }
            }
            if (!(fabs(ha.spd[k][i] - hb.spd[k][i]) <= 1e-12 * fmax(1.0, ha.spd[k][i])) ||
                !(fabs(ha.temp[k][i] - hb.temp[k][i]) <= 1e-12 * 100.0)) {
                fprintf(stderr, "C and Fortran differ: inc %d node %d spd/temp\n", k, i);
                return 0;
            }
        }
    }
    return 1;
}

static void check_normal(int geo)
{
    int ninc = 400;
    ENSURE(run_both(geo, LOAD_NORMAL, ninc));
    const double k = P_E / P_T;
    double kp[1] = {k};
    int ok;
    run_case(geo, LOAD_NORMAL, rs_law_find("linear_softening"), kp, 1, 0, ninc, &hc, &ok);
    ENSURE(ok);
    double smax = 0.0;
    for (int kk = 1; kk < ninc; ++kk) {
        for (int i = 0; i < NNODE; ++i) {
            double s = ha.s[kk][i][0], h = ha.r[kk][i][0];
            ENSURE_REL(s, hc.s[kk][i][0], 1e-6);  /* linear_softening, k = E/t */
            ENSURE_REL(s, k * h, 1e-6);           /* closed form */
            ENSURE_REL(h, 1e-3 * ha.t[kk], 1e-9); /* rdisp1 = vn t */
            /* uniform: positions carry ~1e-16 m of round-off per increment, times E/t */
            ENSURE_NEAR(s, ha.s[kk][0][0], 1e-7 * P_SY);
            ENSURE_REL(ha.f[kk][i], s, 1e-9); /* F = A s1 n: pushes the node out along n */
            ENSURE_SMALL(ha.s[kk][i][1], 1e-9 * fabs(s) + 1e-9);
            ENSURE_SMALL(ha.s[kk][i][2], 1e-9 * fabs(s) + 1e-9);
            ENSURE(ha.spd[kk][i] == 0.0);
            smax = fmax(smax, s);
        }
    }
    ENSURE(smax > 0.5 * P_SY && smax < P_SY); /* elastic, and well loaded */
}

static void test_vuinter_n_2d_segments(void)
{
    check_normal(GEO_FLAT2D);
}

static void test_vuinter_n_3d_cylinder(void)
{
    check_normal(GEO_DRUM3D);
}

static void test_vuinter_n_3d_revolution(void)
{
    check_normal(GEO_SHELL3D);
}

/* Shear: tau = G slip / t. SEGMENTS and CYLINDER slide along t1 (x, the generator);
 * the REVOLUTION master spins at omega about its axis under fixed nodes, a slip along
 * t2 (hoop) of -omega R t. */
static void check_shear(int geo)
{
    int ninc = 400;
    ENSURE(run_both(geo, LOAD_SHEAR, ninc));
    const double G = P_E / (2.0 * (1.0 + P_NU));
    int dir = geo == GEO_SHELL3D ? 2 : 1;
    double rate = geo == GEO_SHELL3D ? -0.5 * 1.0 : 2e-3;
    for (int kk = 1; kk < ninc; ++kk) {
        for (int i = 0; i < NNODE; ++i) {
            double slip = ha.r[kk][i][dir];
            ENSURE_REL(slip, rate * ha.t[kk], 1e-9);
            ENSURE_REL(ha.s[kk][i][dir], G * slip / P_T, 1e-9);
            ENSURE_REL(ha.s[kk][i][dir], ha.s[kk][0][dir], 1e-9); /* uniform */
            ENSURE_SMALL(ha.s[kk][i][0], 1e-9 * fabs(ha.s[kk][i][dir]) + 1e-6);
            ENSURE_SMALL(ha.s[kk][i][3 - dir], 1e-9 * fabs(ha.s[kk][i][dir]) + 1e-6);
        }
    }
}

static void test_vuinter_s_2d_segments(void)
{
    check_shear(GEO_FLAT2D);
}

static void test_vuinter_s_3d_cylinder(void)
{
    check_shear(GEO_DRUM3D);
}

static void test_vuinter_s_3d_revolution_spinning(void)
{
    check_shear(GEO_SHELL3D);
}

/* Linear hardening under monotone loading, strain e = rdisp1 / t:
 *   s = E e (e <= sy/E);  s = sy + E H/(E + H) (e - sy/E) beyond;
 *   plastic strain ep = (s - sy)/H, plastic work per area t (sy ep + H ep^2 / 2). */
static void check_plastic(int geo)
{
    int ninc = 400;
    ENSURE(run_both(geo, LOAD_PLASTIC, ninc));
    double ey = P_SY / P_E;
    int yielded = 0, elastic = 0;
    for (int kk = 1; kk < ninc; ++kk) {
        double wp_total = 0.0;
        for (int i = 0; i < NNODE; ++i) {
            double e = ha.r[kk][i][0] / P_T;
            double s = e <= ey ? P_E * e : P_SY + P_E * P_H / (P_E + P_H) * (e - ey);
            double ep = s > P_SY ? (s - P_SY) / P_H : 0.0;
            double wp = P_T * (P_SY * ep + 0.5 * P_H * ep * ep);
            /* rdisp(1) of a node on a curved master carries the round-off of its position,
             * a few ulp of the radius (1), and stress = E/t sum drdisp(1) carries it
             * times E/t: that absolute floor adds to the 1e-9 relative bound. */
            ENSURE_NEAR(ha.s[kk][i][0], s, 1e-9 * fabs(s) + 8 * DBL_EPSILON * P_E / P_T);
            ENSURE_NEAR(ha.spd[kk][i], wp, 1e-9 * fmax(wp, P_SY * P_T * ey));
            wp_total += wp;
        }
        ENSURE_NEAR(ha.allpd[kk], wp_total, 1e-9 * fmax(wp_total, P_SY * P_T * ey));
    }
    for (int i = 0; i < NNODE; ++i) {
        double e = ha.r[ninc - 1][i][0] / P_T;
        yielded += e > ey;
        elastic += e < ey;
    }
    ENSURE(yielded >= 2 && elastic >= 2); /* one end yields, the other stays elastic */
}

static void test_vuinter_pl_2d_segments(void)
{
    check_plastic(GEO_FLAT2D);
}

static void test_vuinter_pl_3d_cylinder(void)
{
    check_plastic(GEO_DRUM3D);
}

/* Heat: each slave (C = 1) exchanges q = k (Tm - Ts)/t with the master (C = NNODE).
 * The explicit update gives D_k = Tm - Ts = 100 (1 - lambda dt)^k exactly, with
 * lambda = (k A / t)(1/C_s + NNODE/C_m); the heat content is conserved. */
static void check_heat(int geo)
{
    int ninc = 2000;
    ENSURE(run_both(geo, LOAD_HEAT, ninc));
    double lambda = P_K / P_T * (1.0 + NNODE / (double)NNODE);
    double decay = 1.0;
    for (int kk = 0; kk < ninc; ++kk) {
        decay *= 1.0 - lambda * DT;
        double ts = 50.0 - 50.0 * decay, tm = 50.0 + 50.0 * decay;
        double content = ha.tm[kk] * NNODE;
        for (int i = 0; i < NNODE; ++i) {
            ENSURE_NEAR(ha.temp[kk][i], ts, 1e-9);
            content += ha.temp[kk][i] * 1.0;
        }
        ENSURE_NEAR(ha.tm[kk], tm, 1e-9);
        ENSURE_NEAR(content, 100.0 * NNODE, 1e-9 * 100.0 * NNODE);
        ENSURE_NEAR(ha.heat_slv[kk], -ha.heat_mst[kk], 1e-9 * 100.0 * NNODE);
    }
    for (int i = 0; i < NNODE; ++i) {
        ENSURE_NEAR(ha.temp[ninc - 1][i], 50.0, 1e-6);
    }
    ENSURE_NEAR(ha.tm[ninc - 1], 50.0, 1e-6);
}

static void test_vuinter_ht_2d_segments(void)
{
    check_heat(GEO_FLAT2D);
}

static void test_vuinter_ht_3d_revolution(void)
{
    check_heat(GEO_SHELL3D);
}

int main(void)
{
    RS_RUN(test_vuinter_n_2d_segments);
    RS_RUN(test_vuinter_n_3d_cylinder);
    RS_RUN(test_vuinter_n_3d_revolution);
    RS_RUN(test_vuinter_s_2d_segments);
    RS_RUN(test_vuinter_s_3d_cylinder);
    RS_RUN(test_vuinter_s_3d_revolution_spinning);
    RS_RUN(test_vuinter_pl_2d_segments);
    RS_RUN(test_vuinter_pl_3d_cylinder);
    RS_RUN(test_vuinter_ht_2d_segments);
    RS_RUN(test_vuinter_ht_3d_revolution);
    if (fortran_loaded)
        rs_law_unload(&fortran_bonded);
    return rs_test_summary();
}
