/* The arguments of the Fortran routines as the Abaqus manuals define them (issue 18,
 * section 2), read back from probe routines that write what they received into statev
 * (fric_probe.f, uinter_probe.f, vuinter_probe.f). One test per point:
 * - FRIC: LM on entry, the LM = 1 kinematic constraint, DGAM, DSLIP into SLIP, TIME,
 *   KSTEP, KINC, PRESS/DPRESS/DDPDDH, frictional heat;
 * - UINTER: shear and STATEV persist with a normal law, FLUX enters as the last
 *   increment's, TIME, KSTEP, KINC, NPRED;
 * - VUINTER in the driver: fluxSlv, fluxMst and sed enter as the last increment's,
 *   kInc from 1, timStep, nFacNod = nMstNod = 0 on an analytic master;
 * - all: PNEWDT < 1 and the returned stiffness gathered in rs_law_requests. */
#include "rigidsurf/driver.h"
#include "rigidsurf/law.h"
#define RS_TEST_SEED 5133377ull
#include "rs_test.h"
#include "test_law_fixture.h"

enum { FSV = 19, USV = 11, VSV = 27 };

static law_fix f;
static double sv[64 * RS_BLOCK];

/* Slot i (0-based) of the probe's statev of contact k. */
static double probe(int k, int i)
{
    return sv[(size_t)k * (size_t)f.b.nStateVar + (size_t)i];
}

/* A FRIC probe over linear_softening (p = kn h) on n contacts, nDir = nd. */
static void fric_setup(rs_law *fl, double kn, double mode, double shear, double sfd,
                       double pnewdt, double ddtddg, int n, int nd)
{
    rs_error err;
    ENSURE(rs_law_load_fric(RS_FRIC_PROBE_LIB, rs_law_find("linear_softening"), fl, &err) ==
           RS_OK);
    double props[6] = {kn, mode, shear, sfd, pnewdt, ddtddg};
    law_fix_init(&f, NULL, props, 6, n, nd);
    memset(sv, 0, sizeof sv);
    f.b.statev = sv;
    f.b.nStateVar = fl->nstatev + FSV;
}

/* One increment: rdisp(1) = h, drdisp = (h - h_prev, dt), rdisp(2:) += dt. */
static void step(int k, double h, const double *ds)
{
    int nd = f.b.nDir;
    RS_A2(f.drdisp, nd, 0, k) = h - RS_A2(f.rdisp, nd, 0, k);
    RS_A2(f.rdisp, nd, 0, k) = h;
    for (int i = 1; i < nd; ++i) {
        RS_A2(f.drdisp, nd, i, k) = ds[i - 1];
        RS_A2(f.rdisp, nd, i, k) += ds[i - 1];
    }
}

/* LM enters as the contact's state of the previous increment: 2 on its first call and
 * after it was open, 1 after the routine returned 1, 0 after it returned 0 or 2 while
 * the contact stayed closed. A FRIC that exits on LM = 2 then gives friction from the
 * second closed increment on. */
static void test_fric_lm_on_entry(void)
{
    const double hs[6] = {1e-6, 1e-6, 1e-6, -1e-6, 1e-6, 1e-6};
    const double ds[2] = {1e-7, 0.0};
    /* mode -1 (exit on LM = 2): LM in 2, 0, 0, -, 2, 0 */
    const double lm_exit[6] = {2, 0, 0, -1, 2, 0};
    const double lm_stick[6] = {2, 1, 1, -1, 2, 1};
    const double lm_free[6] = {2, 0, 0, -1, 2, 0};
    const double modes[3] = {-1.0, 1.0, 2.0};
    const double *expect[3] = {lm_exit, lm_stick, lm_free};
    for (int m = 0; m < 3; ++m) {
        rs_law fl;
        rs_error err;
        fric_setup(&fl, 1e5, modes[m], 0.02, 0.0, 0.0, 0.0, 1, 3);
        for (int inc = 0; inc < 6; ++inc) {
            double calls = probe(0, 18);
            step(0, hs[inc], ds);
            ENSURE(rs_law_call(&fl, &f.b, &err) == RS_OK);
            if (expect[m][inc] < 0.0) { /* open: FRIC is not called, no shear */
                ENSURE(probe(0, 18) == calls);
                ENSURE(RS_A2(f.stress, 3, 1, 0) == 0.0);
                continue;
            }
            ENSURE(probe(0, 18) == calls + 1.0);
            ENSURE(probe(0, 0) == expect[m][inc]);
            if (m == 0) /* exits on LM = 2 with no shear, else the shear 0.02 */
                ENSURE(RS_A2(f.stress, 3, 1, 0) == (expect[m][inc] == 2 ? 0.0 : 0.02));
        }
        rs_law_unload(&fl);
    }
}

/* LM = 1: no relative tangential motion at the contact point. The shear stress is the
 * force that cancels the contact point's tangential velocity vt in one increment: a
 * solid sphere (I = 2/5 m R^2) pushed at its contact point (lever Rc = R - h/2) by
 * F = -A tau along t ends the increment with a contact-point velocity of zero along t,
 * which is checked here by integrating v and omega, with TAULM = that stress. */
static void test_fric_lm1_is_kinematic_constraint(void)
{
    for (int nd = 2; nd <= 3; ++nd) {
        rs_law fl;
        rs_error err;
        int n = 4;
        fric_setup(&fl, 1e5, 1.0, 0.0, 0.0, 0.0, 0.0, n, nd);
        const double dt = 2e-5;
        f.b.dTimCur = dt;
        for (int k = 0; k < n; ++k) {
            f.radius[k] = 0.002 * (k + 1);
            f.mass[k] = 3e-4 * (k + 1);
            f.area[k] = k == 2 ? 3.0 : 1.0;
            RS_A2(f.vrel, nd, 1, k) = 0.05 * (k + 1);
            if (nd == 3)
                RS_A2(f.vrel, nd, 2, k) = -0.03;
        }
        const double ds[2] = {0.0, 0.0};
        for (int inc = 0; inc < 3; ++inc) {
            for (int k = 0; k < n; ++k)
                step(k, 1e-5 * (1 + inc), ds);
            ENSURE(rs_law_call(&fl, &f.b, &err) == RS_OK);
            for (int k = 0; k < n; ++k) {
                const double m = f.mass[k], R = f.radius[k], A = f.area[k];
                const double h = RS_A2(f.rdisp, nd, 0, k), Rc = R - 0.5 * h;
                const double I = 0.4 * m * R * R;
                /* the sphere above a wall with normal +z, t1 = +x, t2 = +y */
                double v[3] = {RS_A2(f.vrel, nd, 1, k),
                               nd == 3 ? RS_A2(f.vrel, nd, 2, k) : 0.0, 0.0};
                double w[3] = {0.0, 0.0, 0.0};
                const double Ft[3] = {-A * RS_A2(f.stress, nd, 1, k),
                                      nd == 3 ? -A * RS_A2(f.stress, nd, 2, k) : 0.0, 0.0};
                const double r[3] = {0.0, 0.0, -Rc};
                for (int c = 0; c < 3; ++c)
                    v[c] += Ft[c] * dt / m;
                const double tq[3] = {r[1] * Ft[2] - r[2] * Ft[1],
                                      r[2] * Ft[0] - r[0] * Ft[2],
                                      r[0] * Ft[1] - r[1] * Ft[0]};
                for (int c = 0; c < 3; ++c)
                    w[c] += tq[c] * dt / I;
                const double vcp[2] = {v[0] + (w[1] * r[2] - w[2] * r[1]),
                                       v[1] + (w[2] * r[0] - w[0] * r[2])};
                ENSURE_SMALL(vcp[0], 1e-14);
                ENSURE_SMALL(vcp[1], 1e-14);
                /* 1/m_eff = 3.5/m at zero overlap: the stress is close to it */
                ENSURE_RREL(RS_A2(f.stress, nd, 1, k),
                            m / 3.5 * RS_A2(f.vrel, nd, 1, k) / (A * dt), 2e-2);
                /* TAULM is the constraint stress; no slip, no elastic energy */
                ENSURE(probe(k, 3) == RS_A2(f.stress, nd, 1, k));
                ENSURE(probe(k, 8) == 0.0 && f.sfd[k] == 0.0);
                ENSURE_RREL(f.sed[k], 0.5 * 1e5 * h * h, 1e-12);
                if (inc > 0)
                    ENSURE(probe(k, 0) == 1.0);
            }
        }
        /* without the DEM extension the constraint cannot be made: a clear error */
        f.b.mass = NULL;
        ENSURE(rs_law_call(&fl, &f.b, &err) == RS_ERR_ARG);
        ENSURE(strstr(err.msg, "LM = 1") && strstr(err.msg, "mass"));
        rs_law_unload(&fl);
    }
}

/* DGAM is this increment's slip increment when LM was 0 on entry, zero otherwise; the
 * DSLIP the routine returns (here DGAM) accumulates into SLIP. */
static void test_fric_dgam_and_slip(void)
{
    const double modes[2] = {0.0, 1.0};
    for (int m = 0; m < 2; ++m) {
        rs_law fl;
        rs_error err;
        fric_setup(&fl, 1e5, modes[m], 0.01, 0.0, 0.0, 0.0, 2, 3);
        double sum[2] = {0.0, 0.0};
        for (int inc = 0; inc < 5; ++inc) {
            const double ds[2] = {1e-7 * (inc + 1), -3e-8};
            double slip_in[2] = {sum[0], sum[1]};
            step(0, 1e-6, ds);
            step(1, 1e-6, ds);
            ENSURE(rs_law_call(&fl, &f.b, &err) == RS_OK);
            const int slipping = m == 0 && inc > 0; /* LM = 0 on entry */
            for (int k = 0; k < 2; ++k) {
                ENSURE(probe(k, 1) == (slipping ? ds[0] : 0.0));
                ENSURE(probe(k, 2) == (slipping ? ds[1] : 0.0));
                ENSURE_NEAR(probe(k, 8), slip_in[0], 1e-20);
                ENSURE_NEAR(probe(k, 9), slip_in[1], 1e-20);
            }
            if (slipping) {
                sum[0] += ds[0];
                sum[1] += ds[1];
            }
        }
        rs_law_unload(&fl);
    }
}

/* TIME is at the end of the increment; KSTEP and KINC are the engine's. */
static void test_fric_time_kstep_kinc(void)
{
    rs_law fl;
    rs_error err;
    fric_setup(&fl, 1e5, 0.0, 0.0, 0.0, 0.0, 0.0, 1, 2);
    f.b.kStep = 3;
    f.b.kInc = 17;
    f.b.timStep = 0.25;
    f.b.timGlb = 1.75;
    f.b.dTimCur = 1e-5;
    const double ds[1] = {0.0};
    step(0, 1e-6, ds);
    ENSURE(rs_law_call(&fl, &f.b, &err) == RS_OK);
    ENSURE(probe(0, 10) == 3.0 && probe(0, 11) == 17.0);
    ENSURE(probe(0, 12) == 0.25 + 1e-5 && probe(0, 13) == 1.75 + 1e-5);
    ENSURE(probe(0, 17) == 1e-5);
    ENSURE(probe(0, 14) == 0.0); /* NPRED: no fields */
    rs_law_unload(&fl);
}

/* PRESS and DPRESS from the normal law, DDPDDH its current stiffness: over Hertz
 * (p = 4/3 Y* sqrt(R) h^(3/2) with the wall at rest), dp/dh = 2 Y* sqrt(R h), which
 * differs from the secant over the increment. */
static void test_fric_press_and_ddpddh_from_normal_law(void)
{
    const rs_law *hz = rs_law_find("hertz");
    ENSURE(hz != NULL);
    rs_law fl;
    rs_error err;
    ENSURE(rs_law_load_fric(RS_FRIC_PROBE_LIB, hz, &fl, &err) == RS_OK);
    const double Yp = 5e7, np = 0.3, Yw = 2e8, nw = 0.25;
    double props[12] = {Yp, np, Yw, nw, 0.5, 0.4, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    law_fix_init(&f, NULL, props, 12, 2, 3);
    memset(sv, 0, sizeof sv);
    f.b.statev = sv;
    f.b.nStateVar = fl.nstatev + FSV;
    const double ys = 1.0 / ((1 - np * np) / Yp + (1 - nw * nw) / Yw);
    const double ds[2] = {0.0, 0.0};
    double p_prev[2] = {0.0, 0.0};
    for (int inc = 0; inc < 3; ++inc) {
        for (int k = 0; k < 2; ++k)
            step(k, 1e-6 * (k + 1) * (inc + 1), ds);
        ENSURE(rs_law_call(&fl, &f.b, &err) == RS_OK);
        for (int k = 0; k < 2; ++k) {
            const double R = f.radius[k], h = 1e-6 * (k + 1) * (inc + 1);
            const double p = 4.0 / 3.0 * ys * sqrt(R) * pow(h, 1.5);
            ENSURE_RREL(probe(k, 5), p, 1e-12);
            ENSURE_RREL(probe(k, 6), p - p_prev[k], 1e-9);
            ENSURE_RREL(probe(k, 7), 2.0 * ys * sqrt(R * h), 1e-6);
            p_prev[k] = p;
        }
    }
    rs_law_unload(&fl);
}

/* Frictional heat with temperatures on: SFD when the routine sets it, else DSLIP.TAU,
 * per area over dt, half into the particle and half into the wall; none without
 * temperatures. The dissipation sfd is the same energy. */
static void test_fric_frictional_heat(void)
{
    const double dt = 1e-5, tau = 0.02, dg = 1e-7, sfd_set = 3e-9;
    for (int c = 0; c < 3; ++c) {
        rs_law fl;
        rs_error err;
        /* c = 0: SFD set; 1: SFD = 0, so DSLIP.TAU; 2: as 0, temperatures off */
        fric_setup(&fl, 1e5, 0.0, tau, c == 1 ? 0.0 : sfd_set, 0.0, 0.0, 1, 2);
        f.b.dTimCur = dt;
        f.b.nTemp = c == 2 ? 0 : 1;
        const double ds[1] = {dg};
        step(0, 1e-6, ds);
        ENSURE(rs_law_call(&fl, &f.b, &err) == RS_OK); /* LM = 2 on entry: DGAM = 0 */
        step(0, 1e-6, ds);
        ENSURE(rs_law_call(&fl, &f.b, &err) == RS_OK);
        const double q = c == 1 ? tau * dg : sfd_set;
        ENSURE_RREL(f.sfd[0], q, 1e-12);
        ENSURE_RREL(f.fluxSlv[0], c == 2 ? 0.0 : 0.5 * q / dt, 1e-12);
        ENSURE_RREL(f.fluxMst[0], c == 2 ? 0.0 : 0.5 * q / dt, 1e-12);
        rs_law_unload(&fl);
    }
}

/* PNEWDT < 1 and the stiffness returned go to rs_law_requests when it is set: the
 * smallest PNEWDT with its contact and the count of calls, the smallest critical step
 * 2 sqrt(m / (k A)); no warning per contact. */
static int warned;

static void count_warning(void *ctx, const rs_law *law, int k, const char *msg)
{
    (void)ctx, (void)law, (void)k, (void)msg;
    warned++;
}

static void test_requests_gather_pnewdt_and_stiffness(void)
{
    rs_law fl;
    rs_error err;
    const double kt = 5e6;
    fric_setup(&fl, 1e5, 0.0, 0.0, 0.0, 0.4, kt, 4, 3);
    rs_law_requests req;
    rs_law_requests_clear(&req);
    ENSURE(req.pnewdt_calls == 0 && req.pnewdt_min == 1.0 && isinf(req.step_min));
    f.b.requests = &req;
    f.b.warn = count_warning;
    warned = 0;
    const double ds[2] = {1e-8, 0.0};
    for (int k = 0; k < 4; ++k) {
        f.mass[k] = 1e-3 * (k + 1);
        f.area[k] = 1.0;
        step(k, k == 3 ? -1e-6 : 1e-6, ds); /* contact 3 open: not called */
    }
    ENSURE(rs_law_call(&fl, &f.b, &err) == RS_OK);
    ENSURE(req.pnewdt_calls == 3 && req.pnewdt_min == 0.4);
    ENSURE(req.pnewdt_particle == 100 && req.pnewdt_feature == RS_FEATURE(RS_FEAT_FACE, 0));
    ENSURE_RREL(req.step_min, 2.0 * sqrt(1e-3 / kt), 1e-12);
    ENSURE(strcmp(req.step_what, "DDTDDG") == 0);
    ENSURE(warned == 0);
    /* merged with another block's */
    rs_law_requests other;
    rs_law_requests_clear(&other);
    other.pnewdt_calls = 2;
    other.pnewdt_min = 0.1;
    other.pnewdt_particle = 7;
    rs_law_requests_merge(&req, &other);
    ENSURE(req.pnewdt_calls == 5 && req.pnewdt_min == 0.1 && req.pnewdt_particle == 7);
    /* a setup call is not an increment: nothing is gathered */
    rs_law_requests_clear(&req);
    f.b.setup = 1;
    ENSURE(rs_law_call(&fl, &f.b, &err) == RS_OK);
    ENSURE(req.pnewdt_calls == 0 && isinf(req.step_min));
    rs_law_unload(&fl);
}

/* A UINTER probe, optionally over a normal law. */
static void uinter_setup(rs_law *ul, const rs_law *normal, const double *props, int nprops,
                         int n, int nd)
{
    rs_error err;
    ENSURE(rs_law_load_uinter(RS_UINTER_PROBE_LIB, normal, ul, &err) == RS_OK);
    law_fix_init(&f, NULL, props, nprops, n, nd);
    memset(sv, 0, sizeof sv);
    f.b.statev = sv;
    f.b.nStateVar = ul->nstatev + USV;
}

/* With a normal law, STRESS(1) is the normal law's and the shear STRESS(2:NDIR) the
 * routine returned last increment, so an elastic shear spring k_s on the slip grows as
 * k_s times the accumulated slip; STATEV persists (the call counter). */
static void test_uinter_shear_and_statev_persist_with_normal_law(void)
{
    const double kn = 2e5, ks = 3e6, dsl = 2e-8;
    double props[4] = {kn, ks, 0.0, 0.0};
    rs_law ul;
    rs_error err;
    uinter_setup(&ul, rs_law_find("linear_softening"), props, 4, 2, 3);
    for (int inc = 1; inc <= 6; ++inc) {
        const double ds[2] = {dsl, -dsl};
        step(0, 1e-6, ds);
        step(1, 2e-6, ds);
        ENSURE(rs_law_call(&ul, &f.b, &err) == RS_OK);
        for (int k = 0; k < 2; ++k) {
            ENSURE_RREL(RS_A2(f.stress, 3, 0, k), kn * 1e-6 * (k + 1), 1e-12);
            ENSURE_RREL(RS_A2(f.stress, 3, 1, k), ks * dsl * inc, 1e-12);
            ENSURE_RREL(RS_A2(f.stress, 3, 2, k), -ks * dsl * inc, 1e-12);
            ENSURE_RREL(probe(k, 1), ks * dsl * (inc - 1), 1e-12); /* STRESS(2) in */
            ENSURE(probe(k, 10) == (double)inc);
        }
    }
    rs_law_unload(&ul);
}

/* FLUX(1:2) enter as the values the routine returned last increment (0 at first). */
static void test_uinter_flux_enters_as_previous(void)
{
    const double q = 7.5;
    double props[3] = {0.0, q, 0.0};
    rs_law ul;
    rs_error err;
    uinter_setup(&ul, NULL, props, 3, 1, 2);
    const double ds[1] = {0.0};
    for (int inc = 1; inc <= 4; ++inc) {
        f.fluxSlv[0] = f.fluxMst[0] = 0.0; /* what an engine without fluxes passes */
        step(0, 1e-6, ds);
        ENSURE(rs_law_call(&ul, &f.b, &err) == RS_OK);
        ENSURE(probe(0, 3) == q * (inc - 1) && probe(0, 4) == -q * (inc - 1));
        ENSURE(f.fluxSlv[0] == q * inc && f.fluxMst[0] == -q * inc);
    }
    rs_law_unload(&ul);
}

/* KSTEP, KINC and TIME (end of the increment) as for FRIC; NPRED the engine's. */
static void test_uinter_time_kstep_kinc_npred(void)
{
    double props[3] = {0.0, 0.0, 0.0};
    rs_law ul;
    rs_error err;
    uinter_setup(&ul, NULL, props, 3, 1, 3);
    f.b.kStep = 2;
    f.b.kInc = 9;
    f.b.timStep = 0.5;
    f.b.timGlb = 3.0;
    f.b.dTimCur = 2e-5;
    const double ds[2] = {0.0, 0.0};
    step(0, 1e-6, ds);
    ENSURE(rs_law_call(&ul, &f.b, &err) == RS_OK);
    ENSURE(probe(0, 5) == 2.0 && probe(0, 6) == 9.0);
    ENSURE(probe(0, 7) == 0.5 + 2e-5 && probe(0, 8) == 3.0 + 2e-5);
    ENSURE(probe(0, 9) == 0.0);
    static double pred[2 * RS_BLOCK], dpred[2 * RS_BLOCK];
    f.b.nPred = 2;
    f.b.preDefSlv = pred;
    f.b.dpreDefSlv = dpred;
    ENSURE(rs_law_call(&ul, &f.b, &err) == RS_OK);
    ENSURE(probe(0, 9) == 2.0);
    rs_law_unload(&ul);
}

/* The VUINTER probe in the driver on an analytic flat: fluxSlv, fluxMst and sed enter
 * as the last increment's (the probe adds props(1) and props(2) each call), kInc counts
 * from 1 in the driver's one step, timStep = timGlb = (kInc - 1) dt, and the master has
 * no nodes (nFacNod = nMstNod = 0). */
static void test_vuinter_driver_arguments(void)
{
    rs_surface s;
    rs_error err;
    char path[512];
    snprintf(path, sizeof path, "%s/flat2d.inp", RS_VUINTER_CASES_DIR);
    ENSURE(rs_surface_read(path, NULL, &s, &err) == RS_OK);
    rs_law vl;
    ENSURE(rs_law_load_vuinter(RS_VUINTER_PROBE_LIB, &vl, &err) == RS_OK);
    rs_driver d;
    const double q = 2.0, e = 0.5, dt = 1e-5;
    double props[3] = {q, e, 0.0};
    ENSURE(rs_driver_init(&d, &s, 1, &err) == RS_OK);
    ENSURE(rs_driver_set_law(&d, &vl, props, 3, VSV, &err) == RS_OK);
    d.dt = dt;
    d.tracking = 1e-3;
    d.fixed[0] = d.fixed[1] = d.fixed[2] = 1; /* held 1e-4 above the flat */
    d.y[0] = 1e-4;
    for (int inc = 1; inc <= 5; ++inc) {
        ENSURE(rs_driver_step(&d, &err) == RS_OK);
        ENSURE(d.trk.n == 1);
        const double *p = d.cb.statev;
        ENSURE(p[18] == q * (inc - 1) && p[19] == -q * (inc - 1));
        ENSURE(p[20] == e * (inc - 1));
        ENSURE(p[21] == 1.0 && p[22] == (double)inc);
        ENSURE_NEAR(p[23], (inc - 1) * dt, 1e-18);
        ENSURE_NEAR(p[24], (inc - 1) * dt, 1e-18);
        ENSURE(p[15] == 0.0 && p[16] == 0.0 && p[17] == 1.0);
    }
    rs_driver_free(&d);
    rs_law_unload(&vl);
    rs_surface_free(&s);
}

int main(void)
{
    RS_RUN(test_fric_lm_on_entry);
    RS_RUN(test_fric_lm1_is_kinematic_constraint);
    RS_RUN(test_fric_dgam_and_slip);
    RS_RUN(test_fric_time_kstep_kinc);
    RS_RUN(test_fric_press_and_ddpddh_from_normal_law);
    RS_RUN(test_fric_frictional_heat);
    RS_RUN(test_requests_gather_pnewdt_and_stiffness);
    RS_RUN(test_uinter_shear_and_statev_persist_with_normal_law);
    RS_RUN(test_uinter_flux_enters_as_previous);
    RS_RUN(test_uinter_time_kstep_kinc_npred);
    RS_RUN(test_vuinter_driver_arguments);
    return rs_test_summary();
}
