/* Fortran laws loaded with dlopen, block by block, against the C built-ins and closed
 * forms: the VUINTER bonded interface against bonded_interface, the UINTER penalty
 * against linear_softening, the FRIC Coulomb (over linear_softening) against coulomb,
 * the LM = 1 / LM = 2 semantics, warnings for PNEWDT < 1 and unstable stiffness, setup
 * calls, and the VUINTER argument order probed from Fortran. */
#include "rigidsurf/law.h"
#define RS_TEST_SEED 88172645463325252ull
#include "rs_test.h"
#include "test_law_fixture.h"

static double rel_diff(double a, double b)
{
    return fabs(a - b) / fmax(1.0, fmax(fabs(a), fabs(b)));
}

/* Applies one increment to a fixture: drdisp given, rdisp accumulated, and the
 * previous shear rotated by drot as the tracker does. */
static void advance(law_fix *f, int k, const double *dr, const double drot[4])
{
    int nd = f->b.nDir;
    for (int i = 0; i < nd; ++i) {
        RS_A2(f->drdisp, nd, i, k) = dr[i];
    }
    for (int i = 0; i < 4; ++i) {
        f->drot[4 * k + i] = drot[i];
    }
    if (nd == 3) {
        double s0 = RS_A2(f->rdisp, 3, 1, k), s1 = RS_A2(f->rdisp, 3, 2, k);
        RS_A2(f->rdisp, 3, 1, k) =
            RS_DROT(f->drot, 0, 0, k) * s0 + RS_DROT(f->drot, 0, 1, k) * s1;
        RS_A2(f->rdisp, 3, 2, k) =
            RS_DROT(f->drot, 1, 0, k) * s0 + RS_DROT(f->drot, 1, 1, k) * s1;
        double t0 = RS_A2(f->stress, 3, 1, k), t1 = RS_A2(f->stress, 3, 2, k);
        RS_A2(f->stress, 3, 1, k) =
            RS_DROT(f->drot, 0, 0, k) * t0 + RS_DROT(f->drot, 0, 1, k) * t1;
        RS_A2(f->stress, 3, 2, k) =
            RS_DROT(f->drot, 1, 0, k) * t0 + RS_DROT(f->drot, 1, 1, k) * t1;
    }
    for (int i = 0; i < nd; ++i) {
        RS_A2(f->rdisp, nd, i, k) += dr[i];
    }
}

static void random_increment(int nd, double scale_n, double scale_t, double bias_n,
                             double *dr, double drot[4])
{
    dr[0] = bias_n + scale_n * (2.0 * urand() - 1.0);
    for (int i = 1; i < nd; ++i) {
        dr[i] = scale_t * (2.0 * urand() - 1.0);
    }
    double a = nd == 3 ? 0.2 * (2.0 * urand() - 1.0) : 0.0;
    drot[0] = cos(a);
    drot[1] = sin(a);
    drot[2] = -sin(a);
    drot[3] = cos(a);
}

static law_fix fa, fb; /* large: keep off the stack */

static void bonded_vs_builtin(int nd)
{
    const rs_law *c = rs_law_find("bonded_interface");
    ENSURE(c != NULL);
    rs_law fl;
    rs_error err;
    ENSURE(rs_law_load_vuinter(RS_VUINTER_BONDED_LIB, &fl, &err) == RS_OK);
    /* gap cutoff, E, nu, yield stress, hardening, thickness, conductivity */
    double props[7] = {1e-4, 2e9, 0.3, 4e6, 5e8, 1e-3, 40.0};
    int n = 40;
    law_fix_init(&fa, c, props, 7, n, nd);
    law_fix_init(&fb, c, props, 7, n, nd);
    fb.b.nStateVar = 3;
    /* contact 0 starts beyond the cutoff and never bonds */
    for (int k = 0; k < n; ++k) {
        double g = k == 0 ? -2e-4 : -5e-5 * urand();
        RS_A2(fa.rdisp, nd, 0, k) = RS_A2(fb.rdisp, nd, 0, k) = g;
        fa.tempSlv[k] = fb.tempSlv[k] = 20.0 * urand();
    }
    fa.tempMst[0] = fb.tempMst[0] = 100.0;
    double spd_total = 0.0;
    for (int inc = 0; inc < 60; ++inc) {
        for (int k = 0; k < n; ++k) {
            double dr[3], drot[4];
            random_increment(nd, 2e-6, 2e-6, k % 2 ? 5e-7 : -5e-7, dr, drot);
            advance(&fa, k, dr, drot);
            advance(&fb, k, dr, drot);
        }
        /* contact 5 leaves the tracking thickness on increment 30 */
        if (inc == 30) {
            for (int i = 0; i < nd; ++i) {
                RS_A2(fa.rdisp, nd, i, 5) = RS_A2(fb.rdisp, nd, i, 5) = RS_MAXVAL;
                RS_A2(fa.drdisp, nd, i, 5) = RS_A2(fb.drdisp, nd, i, 5) = RS_MAXVAL;
            }
        }
        ENSURE(rs_law_call(c, &fa.b, &err) == RS_OK);
        ENSURE(rs_law_call(&fl, &fb.b, &err) == RS_OK);
        for (int k = 0; k < n; ++k) {
            for (int i = 0; i < nd; ++i) {
                ENSURE(rel_diff(RS_A2(fa.stress, nd, i, k), RS_A2(fb.stress, nd, i, k)) <
                       1e-12);
            }
            ENSURE(rel_diff(fa.sed[k], fb.sed[k]) < 1e-12);
            ENSURE(rel_diff(fa.spd[k], fb.spd[k]) < 1e-12);
            ENSURE(rel_diff(fa.fluxSlv[k], fb.fluxSlv[k]) < 1e-12);
            ENSURE(rel_diff(fa.fluxMst[k], fb.fluxMst[k]) < 1e-12);
            for (int i = 0; i < 3; ++i) {
                ENSURE(rel_diff(fa.statev[3 * k + i], fb.statev[3 * k + i]) < 1e-12);
            }
            spd_total += fb.spd[k];
        }
        if (inc >= 30) {
            for (int i = 0; i < nd; ++i) {
                RS_A2(fa.rdisp, nd, i, 5) = RS_A2(fb.rdisp, nd, i, 5) = 0.0;
            }
        }
    }
    /* the run must have exercised yield, the unbonded contact and the leaving one */
    ENSURE(spd_total > 0.0);
    ENSURE(fb.statev[3 * 0 + 1] == 0.0 && fb.statev[3 * 1 + 1] == 1.0);
    ENSURE(RS_A2(fb.stress, nd, 0, 0) == 0.0);
    rs_law_unload(&fl);
    ENSURE(fl.update == NULL && fl.ctx == NULL);
}

static void test_vuinter_bonded_matches_builtin_2d(void)
{
    bonded_vs_builtin(2);
}

static void test_vuinter_bonded_matches_builtin_3d(void)
{
    bonded_vs_builtin(3);
}

/* UINTER penalty: stress(1) = k h (linear_softening), LOPENCLOSE starts at -1,
 * LSTATE counts open -> closed changes; both kept per contact by the adapter. */
static void uinter_vs_linear(const char *lib, int v6)
{
    const rs_law *lin = rs_law_find("linear_softening");
    ENSURE(lin != NULL);
    rs_law fl;
    rs_error err;
    int rc = v6 ? rs_law_load_uinter_v6(lib, NULL, &fl, &err)
                : rs_law_load_uinter(lib, NULL, &fl, &err);
    ENSURE(rc == RS_OK);
    ENSURE(fl.nstatev == 4); /* LOPENCLOSE, LSTATE, FLUX(1:2) */
    double k = 3e5;
    double lp[1] = {k}, up[3] = {k, 0.0, 0.0};
    int n = 16, nd = 3;
    law_fix_init(&fa, lin, lp, 1, n, nd);
    law_fix_init(&fb, NULL, up, 3, n, nd);
    fb.b.nStateVar = fl.nstatev + 2; /* the routine's NSTATV = 2 */
    ENSURE(rs_law_check_props(&fl, up, 3, &err) == RS_OK);
    int closings[RS_BLOCK] = {0}, was_closed[RS_BLOCK] = {0};
    for (int inc = 0; inc < 50; ++inc) {
        for (int kk = 0; kk < n; ++kk) {
            double h = 1e-4 * sin(0.37 * inc + kk);
            RS_A2(fa.rdisp, nd, 0, kk) = RS_A2(fb.rdisp, nd, 0, kk) = h;
            int closed = h > 0.0;
            if (closed && (!was_closed[kk] || inc == 0)) {
                closings[kk]++;
            }
            was_closed[kk] = closed;
        }
        ENSURE(rs_law_call(lin, &fa.b, &err) == RS_OK);
        ENSURE(rs_law_call(&fl, &fb.b, &err) == RS_OK);
        for (int kk = 0; kk < n; ++kk) {
            const double *sv = fb.statev + (size_t)kk * (size_t)fb.b.nStateVar;
            ENSURE(rel_diff(RS_A2(fa.stress, nd, 0, kk), RS_A2(fb.stress, nd, 0, kk)) <
                   1e-15);
            ENSURE(RS_A2(fb.stress, nd, 1, kk) == 0.0 &&
                   RS_A2(fb.stress, nd, 2, kk) == 0.0);
            ENSURE(rel_diff(fa.sed[kk], fb.sed[kk]) < 1e-15);
            ENSURE(sv[0] == (double)closings[kk]);
            if (inc == 0) {
                ENSURE(sv[1] == -1.0); /* LOPENCLOSE on the first call */
            } else {
                double h_prev = 1e-4 * sin(0.37 * (inc - 1) + kk);
                ENSURE(sv[1] == (h_prev > 0.0 ? 1.0 : 0.0));
            }
        }
    }
    rs_law_unload(&fl);
}

static void test_uinter_penalty_matches_linear_softening(void)
{
    uinter_vs_linear(RS_UINTER_PENALTY_LIB, 0);
}

static void test_uinter_v6_argument_list(void)
{
    uinter_vs_linear(RS_UINTER_V6_PENALTY_LIB, 1);
}

/* With a normal law, its props come first and the UINTER that leaves STRESS(1) alone
 * keeps the normal law's pressure; the UINTER's conduction flux is its own. */
static void test_uinter_normal_law_props_first(void)
{
    const rs_law *lin = rs_law_find("linear_softening");
    rs_law fl;
    rs_error err;
    ENSURE(rs_law_load_uinter(RS_UINTER_PENALTY_LIB, lin, &fl, &err) == RS_OK);
    double kn = 7e4, hc = 250.0;
    double props[4] = {kn, 0.0, 0.0, hc};
    ENSURE(rs_law_check_props(&fl, props, 4, &err) == RS_OK);
    double bad[4] = {-1.0, 0.0, 0.0, hc};
    ENSURE(rs_law_check_props(&fl, bad, 4, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "linear_softening") != NULL);
    int n = 4, nd = 2;
    law_fix_init(&fb, NULL, props, 4, n, nd);
    fb.b.nStateVar = fl.nstatev;
    fb.tempMst[0] = 80.0;
    for (int k = 0; k < n; ++k) {
        RS_A2(fb.rdisp, nd, 0, k) = 1e-5 * (k + 1);
        fb.tempSlv[k] = 10.0 * k;
    }
    ENSURE(rs_law_call(&fl, &fb.b, &err) == RS_OK);
    for (int k = 0; k < n; ++k) {
        ENSURE_REL(RS_A2(fb.stress, nd, 0, k), kn * 1e-5 * (k + 1), 1e-15);
        ENSURE_REL(fb.fluxSlv[k], hc * (80.0 - 10.0 * k), 1e-15);
        ENSURE_REL(fb.fluxMst[k], -hc * (80.0 - 10.0 * k), 1e-15);
    }
    rs_law_unload(&fl);
}

static void fric_vs_coulomb(int nd)
{
    const rs_law *coul = rs_law_find("coulomb");
    const rs_law *lin = rs_law_find("linear_softening");
    ENSURE(coul && lin);
    rs_law fl;
    rs_error err;
    ENSURE(rs_law_load_fric(RS_FRIC_COULOMB_LIB, lin, &fl, &err) == RS_OK);
    double mu = 0.4, ks = 2e6, kn = 5e6;
    double cp[3] = {mu, ks, kn};
    double fp[5] = {kn, mu, ks, 0.0, 0.0};
    int n = 32;
    law_fix_init(&fa, coul, cp, 3, n, nd);
    law_fix_init(&fb, NULL, fp, 5, n, nd);
    fb.b.nStateVar = fl.nstatev + 1;
    int nsv = fb.b.nStateVar;
    ENSURE(rs_law_check_props(&fl, fp, 5, &err) == RS_OK);
    for (int k = 0; k < n; ++k) {
        fb.stiff[k] = 1e7;
    }
    double sfd_total = 0.0;
    int saw_open = 0, saw_slip = 0, closed0[RS_BLOCK];
    for (int inc = 0; inc < 80; ++inc) {
        for (int k = 0; k < n; ++k) {
            double dr[3], drot[4];
            random_increment(nd, 3e-7, 4e-7, 0.0, dr, drot);
            double h = 2e-6 * sin(0.11 * inc + 0.7 * k) + 1e-6;
            dr[0] = h - RS_A2(fb.rdisp, nd, 0, k);
            /* FRIC gets DGAM = 0 when the contact was open the increment before (LM = 2
             * on entry); coulomb has no such state, so those increments do not slide */
            if (inc == 0 || !(RS_A2(fb.rdisp, nd, 0, k) > 0.0))
                for (int i = 1; i < nd; ++i)
                    dr[i] = 0.0;
            advance(&fa, k, dr, drot);
            advance(&fb, k, dr, drot);
            saw_open |= h <= 0.0;
            if (inc == 0) {
                closed0[k] = h > 0.0;
            }
        }
        ENSURE(rs_law_call(coul, &fa.b, &err) == RS_OK);
        ENSURE(rs_law_call(&fl, &fb.b, &err) == RS_OK);
        for (int k = 0; k < n; ++k) {
            for (int i = 0; i < nd; ++i) {
                ENSURE_NEAR(RS_A2(fa.stress, nd, i, k), RS_A2(fb.stress, nd, i, k),
                            1e-9 * (1.0 + fabs(RS_A2(fa.stress, nd, i, k))));
            }
            ENSURE_NEAR(fa.sfd[k], fb.sfd[k], 1e-12 * (1.0 + fabs(fa.sfd[k])) + 1e-20);
            ENSURE_NEAR(fa.sed[k], fb.sed[k], 1e-12 * (1.0 + fabs(fa.sed[k])) + 1e-20);
            sfd_total += fb.sfd[k];
            saw_slip |= fb.sfd[k] > 0.0;
            if (inc == 0 && closed0[k]) {
                ENSURE(fb.statev[(size_t)k * nsv] == 2.0); /* LM = 2 on a first call */
            }
        }
    }
    ENSURE(saw_open && saw_slip && sfd_total > 0.0);
    rs_law_unload(&fl);
}

static void test_fric_coulomb_matches_builtin_2d(void)
{
    fric_vs_coulomb(2);
}

static void test_fric_coulomb_matches_builtin_3d(void)
{
    fric_vs_coulomb(3);
}

/* LM = 2: no shear, the slip slot accumulates every slip increment. */
static void test_fric_lm2_is_frictionless_and_slips(void)
{
    const rs_law *lin = rs_law_find("linear_softening");
    rs_law fl;
    rs_error err;
    ENSURE(rs_law_load_fric(RS_FRIC_COULOMB_LIB, lin, &fl, &err) == RS_OK);
    double fp[5] = {1e5, 0.3, 1e6, 2.0, 0.0};
    int n = 3, nd = 3;
    law_fix_init(&fb, NULL, fp, 5, n, nd);
    fb.b.nStateVar = fl.nstatev; /* the routine keeps no statev */
    double sum[2] = {0.0, 0.0};
    double ident[4] = {1.0, 0.0, 0.0, 1.0};
    for (int inc = 0; inc < 20; ++inc) {
        double dr[3] = {inc == 0 ? 1e-6 : 0.0, 1e-7 * (1 + inc % 3), -2e-7};
        for (int k = 0; k < n; ++k) {
            advance(&fb, k, dr, ident);
        }
        sum[0] += dr[1];
        sum[1] += dr[2];
        ENSURE(rs_law_call(&fl, &fb.b, &err) == RS_OK);
        for (int k = 0; k < n; ++k) {
            const double *slot = fb.statev + (size_t)k * (size_t)fb.b.nStateVar;
            ENSURE(fb.sfd[k] == 0.0);
            ENSURE(RS_A2(fb.stress, nd, 1, k) == 0.0);
            ENSURE(RS_A2(fb.stress, nd, 2, k) == 0.0);
            ENSURE_REL(slot[0], sum[0], 1e-12);
            ENSURE_REL(slot[1], sum[1], 1e-12);
            ENSURE_REL(RS_A2(fb.stress, nd, 0, k), 1e5 * 1e-6, 1e-12);
        }
    }
    rs_law_unload(&fl);
}

typedef struct warn_log {
    int count;
    int last_k;
    char last[400];
} warn_log;

static void log_warning(void *ctx, const rs_law *law, int k, const char *msg)
{
    (void)law;
    warn_log *w = (warn_log *)ctx;
    w->count++;
    w->last_k = k;
    snprintf(w->last, sizeof w->last, "%s", msg);
}

static void test_pnewdt_below_one_warns_naming_contact(void)
{
    const rs_law *lin = rs_law_find("linear_softening");
    rs_law fl, ul;
    rs_error err;
    ENSURE(rs_law_load_fric(RS_FRIC_COULOMB_LIB, lin, &fl, &err) == RS_OK);
    ENSURE(rs_law_load_uinter(RS_UINTER_PENALTY_LIB, NULL, &ul, &err) == RS_OK);
    /* FRIC: PNEWDT = 0.5 when the pressure exceeds pmax = 50 */
    double fp[5] = {1e6, 0.3, 1e6, 0.0, 50.0};
    law_fix_init(&fb, NULL, fp, 5, 3, 3);
    fb.b.nStateVar = fl.nstatev;
    warn_log w = {0, -1, ""};
    fb.b.warn = log_warning;
    fb.b.warn_ctx = &w;
    RS_A2(fb.rdisp, 3, 0, 0) = 1e-5; /* p = 10: no warning */
    RS_A2(fb.rdisp, 3, 0, 1) = 1e-4; /* p = 100: warning */
    RS_A2(fb.rdisp, 3, 0, 2) = -1e-4;
    ENSURE(rs_law_call(&fl, &fb.b, &err) == RS_OK);
    ENSURE(w.count == 1 && w.last_k == 1);
    ENSURE(strstr(w.last, "PNEWDT") && strstr(w.last, "particle 101"));
    ENSURE(strstr(w.last, "feature 4") && strstr(w.last, "FRIC"));

    /* UINTER: PNEWDT = 0.5 when h > hmax = 2e-5 */
    double up[3] = {1e3, 2e-5, 0.0};
    law_fix_init(&fb, NULL, up, 3, 3, 2);
    fb.b.nStateVar = ul.nstatev;
    w.count = 0;
    fb.b.warn = log_warning;
    fb.b.warn_ctx = &w;
    RS_A2(fb.rdisp, 2, 0, 2) = 3e-5;
    ENSURE(rs_law_call(&ul, &fb.b, &err) == RS_OK);
    ENSURE(w.count == 1 && w.last_k == 2);
    ENSURE(strstr(w.last, "UINTER") && strstr(w.last, "particle 102"));
    rs_law_unload(&fl);
    rs_law_unload(&ul);
}

/* DDSDDR = k; a point mass m on k A is stable in central differences only for
 * dt < 2 sqrt(m / (k A)). Fixture: m = 1e-3, A = 1, dt = 1e-5: limit k = 4e7. */
static void test_uinter_stiffness_above_stable_limit_warns(void)
{
    rs_law ul;
    rs_error err;
    ENSURE(rs_law_load_uinter(RS_UINTER_PENALTY_LIB, NULL, &ul, &err) == RS_OK);
    warn_log w = {0, -1, ""};
    double ks[2] = {3.9e7, 4.1e7};
    for (int t = 0; t < 2; ++t) {
        double up[3] = {ks[t], 0.0, 0.0};
        law_fix_init(&fb, NULL, up, 3, 1, 3);
        fb.b.nStateVar = ul.nstatev;
        fb.b.warn = log_warning;
        fb.b.warn_ctx = &w;
        RS_A2(fb.rdisp, 3, 0, 0) = 1e-6;
        w.count = 0;
        ENSURE(rs_law_call(&ul, &fb.b, &err) == RS_OK);
        ENSURE(w.count == t);
    }
    ENSURE(strstr(w.last, "DDSDDR") && strstr(w.last, "particle 100"));
    ENSURE(strstr(w.last, "2 sqrt(m/(k A))"));
    rs_law_unload(&ul);
}

/* A setup call computes stress but leaves every state variable as it was. */
static void test_setup_call_does_not_advance_statev(void)
{
    rs_law ul, vl;
    rs_error err;
    ENSURE(rs_law_load_uinter(RS_UINTER_PENALTY_LIB, NULL, &ul, &err) == RS_OK);
    double up[3] = {1e3, 0.0, 0.0};
    law_fix_init(&fb, NULL, up, 3, 2, 3);
    fb.b.nStateVar = ul.nstatev + 2;
    fb.b.setup = 1;
    RS_A2(fb.rdisp, 3, 0, 0) = 1e-4;
    ENSURE(rs_law_call(&ul, &fb.b, &err) == RS_OK);
    ENSURE_REL(RS_A2(fb.stress, 3, 0, 0), 0.1, 1e-15);
    for (int i = 0; i < 2 * fb.b.nStateVar; ++i) {
        ENSURE(fb.statev[i] == 0.0);
    }
    rs_law_unload(&ul);

    ENSURE(rs_law_load_vuinter(RS_VUINTER_BONDED_LIB, &vl, &err) == RS_OK);
    double bp[7] = {1e-4, 2e9, 0.3, 4e6, 5e8, 1e-3, 40.0};
    law_fix_init(&fb, NULL, bp, 7, 2, 3);
    fb.b.nStateVar = 3;
    fb.b.setup = 1;
    RS_A2(fb.drdisp, 3, 0, 0) = 1e-7;
    ENSURE(rs_law_call(&vl, &fb.b, &err) == RS_OK);
    ENSURE_REL(RS_A2(fb.stress, 3, 0, 0), 2e9 * 1e-7 / 1e-3, 1e-15);
    for (int i = 0; i < 6; ++i) {
        ENSURE(fb.statev[i] == 0.0);
    }
    rs_law_unload(&vl);
}

/* A contact passed with r_MaxVal is not handed to UINTER or FRIC: zero stress. */
static void test_adapters_zero_leaving_contacts(void)
{
    const rs_law *lin = rs_law_find("linear_softening");
    rs_law ul, fl;
    rs_error err;
    ENSURE(rs_law_load_uinter(RS_UINTER_PENALTY_LIB, NULL, &ul, &err) == RS_OK);
    ENSURE(rs_law_load_fric(RS_FRIC_COULOMB_LIB, lin, &fl, &err) == RS_OK);
    const rs_law *laws[2] = {&ul, &fl};
    double props[2][5] = {{1e3, 0.0, 5.0, 0, 0}, {1e3, 0.3, 1e6, 0.0, 0.0}};
    int np[2] = {3, 5};
    for (int l = 0; l < 2; ++l) {
        law_fix_init(&fb, NULL, props[l], np[l], 2, 3);
        fb.b.nStateVar = laws[l]->nstatev;
        for (int i = 0; i < 3; ++i) {
            RS_A2(fb.rdisp, 3, i, 1) = RS_A2(fb.drdisp, 3, i, 1) = RS_MAXVAL;
            RS_A2(fb.stress, 3, i, 1) = 7.0;
        }
        fb.fluxSlv[1] = 3.0;
        RS_A2(fb.rdisp, 3, 0, 0) = 1e-5;
        ENSURE(rs_law_call(laws[l], &fb.b, &err) == RS_OK);
        for (int i = 0; i < 3; ++i) {
            ENSURE(RS_A2(fb.stress, 3, i, 1) == 0.0);
        }
        ENSURE(fb.fluxSlv[1] == 0.0 && fb.sed[1] == 0.0);
        ENSURE(RS_A2(fb.stress, 3, 0, 0) > 0.0);
    }
    rs_law_unload(&ul);
    rs_law_unload(&fl);
}

/* The VUINTER argument order, the hidden CHARACTER*80 lengths, the Abaqus integers of
 * an analytic master (no nodes: nFacNod = nMstNod = 0, numDefTfv = 1), nPred = 0
 * without fields, and the DEM extension through RS_GETDEM, read back from Fortran. */
static void test_vuinter_probe_argument_order_and_dem_fields(void)
{
    rs_law vl;
    rs_error err;
    ENSURE(rs_law_load_vuinter(RS_VUINTER_PROBE_LIB, &vl, &err) == RS_OK);
    double props[3] = {0.0, 0.0, 42.0};
    int n = 5, nd = 3;
    enum { NSV = 27 };
    static double sv[NSV * RS_BLOCK];
    for (int analytic = 0; analytic < 2; ++analytic) {
        law_fix_init(&fb, NULL, props, 3, n, nd);
        memset(sv, 0, sizeof sv);
        fb.b.statev = sv;
        fb.b.nStateVar = NSV;
        fb.b.dTimCur = 2.5e-6;
        fb.b.analytic_master = analytic;
        rs_law_block_set_name(fb.b.surfInt, "INTER-1");
        rs_law_block_set_name(fb.b.surfMst, "DRUM");
        fb.tempMst[0] = 321.0;
        for (int k = 0; k < n; ++k) {
            fb.radius[k] = 0.001 * (k + 1);
            fb.mass[k] = 0.01 * (k + 1);
            fb.reff[k] = 0.002 * (k + 1);
            for (int i = 0; i < nd; ++i) {
                RS_A2(fb.vrel, nd, i, k) = 10.0 * k + i;
                RS_A2(fb.rdisp, nd, i, k) = 0.1 * k - 0.01 * i;
            }
            fb.curv[2 * k] = 5.0 + k;
            fb.curv[2 * k + 1] = -3.0 - k;
            fb.stiff[k] = 1e6 + k;
            fb.area[k] = 0.5 + k;
        }
        ENSURE(rs_law_call(&vl, &fb.b, &err) == RS_OK);
        for (int k = 0; k < n; ++k) {
            const double *s = sv + NSV * k;
            ENSURE(s[26] == 0.0); /* RS_GETDEM's jrcd */
            ENSURE(s[0] == fb.radius[k] && s[1] == fb.mass[k] && s[2] == fb.reff[k]);
            ENSURE(s[3] == 10.0 * k && s[4] == 10.0 * k + 1 && s[5] == 10.0 * k + 2);
            ENSURE(s[6] == 5.0 + k && s[7] == -3.0 - k);
            ENSURE(s[8] == 7.0 && s[9] == 80.0);
            ENSURE(s[10] == 0.0); /* nPred: no fields */
            ENSURE(s[11] == 2.5e-6 && s[12] == 1e6 + k && s[13] == 321.0);
            ENSURE(s[14] == 100.0 + k);
            ENSURE(s[15] == (analytic ? 0.0 : 1.0)); /* nFacNod */
            ENSURE(s[16] == (analytic ? 0.0 : 1.0)); /* nMstNod */
            ENSURE(s[17] == 1.0);                    /* numDefTfv */
            for (int i = 0; i < nd; ++i) {
                ENSURE(RS_A2(fb.stress, nd, i, k) == RS_A2(fb.rdisp, nd, i, k));
            }
            ENSURE(fb.sfd[k] == 0.5 + k && fb.svd[k] == 42.0);
        }
    }
    rs_law_unload(&vl);
}

/* With predefined fields of its own, the engine's count is nPred and preDefSlv holds
 * them. */
static void test_vuinter_npred_is_the_engine_fields(void)
{
    rs_law vl;
    rs_error err;
    ENSURE(rs_law_load_vuinter(RS_VUINTER_PROBE_LIB, &vl, &err) == RS_OK);
    double props[3] = {0.0, 0.0, 1.0};
    enum { NSV = 27, NP = 2 };
    static double sv[NSV * RS_BLOCK], pred[NP * RS_BLOCK], dpred[NP * RS_BLOCK];
    int n = 3;
    law_fix_init(&fb, NULL, props, 3, n, 3);
    memset(sv, 0, sizeof sv);
    fb.b.statev = sv;
    fb.b.nStateVar = NSV;
    fb.b.nPred = NP;
    for (int k = 0; k < n; ++k) {
        pred[NP * k] = 7.0 + k;
        pred[NP * k + 1] = -1.0;
    }
    fb.b.preDefSlv = pred;
    fb.b.dpreDefSlv = dpred;
    ENSURE(rs_law_call(&vl, &fb.b, &err) == RS_OK);
    for (int k = 0; k < n; ++k) {
        ENSURE(sv[NSV * k + 10] == (double)NP);
        ENSURE(sv[NSV * k + 25] == 7.0 + k);
    }
    rs_law_unload(&vl);
}

int main(void)
{
    RS_RUN(test_vuinter_bonded_matches_builtin_2d);
    RS_RUN(test_vuinter_bonded_matches_builtin_3d);
    RS_RUN(test_uinter_penalty_matches_linear_softening);
    RS_RUN(test_uinter_v6_argument_list);
    RS_RUN(test_uinter_normal_law_props_first);
    RS_RUN(test_fric_coulomb_matches_builtin_2d);
    RS_RUN(test_fric_coulomb_matches_builtin_3d);
    RS_RUN(test_fric_lm2_is_frictionless_and_slips);
    RS_RUN(test_pnewdt_below_one_warns_naming_contact);
    RS_RUN(test_uinter_stiffness_above_stable_limit_warns);
    RS_RUN(test_setup_call_does_not_advance_statev);
    RS_RUN(test_adapters_zero_leaving_contacts);
    RS_RUN(test_vuinter_probe_argument_order_and_dem_fields);
    RS_RUN(test_vuinter_npred_is_the_engine_fields);
    return rs_test_summary();
}
