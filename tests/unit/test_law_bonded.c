/* bonded_interface against hand-derived closed forms: elastic slope E, yield at the
 * yield stress with tangent modulus E H/(E+H), plastic work, elastic shear with
 * G = E/(2(1+nu)), conduction through the layer, bonding by initial gap, tension,
 * r_MaxVal. */
#include "rs_test.h"
#include "test_law_fixture.h"

#include <math.h>

static law_fix F;
static const double P[7] = {0.01, 200.0, 0.3, 10.0, 20.0, 0.5, 2.0};
#define CUT 0.01
#define E 200.0
#define NU 0.3
#define SY0 10.0
#define H 20.0
#define T 0.5
#define K 2.0

static const rs_law *law(void)
{
    return rs_law_find("bonded_interface");
}

static void setup_block(int n, int ndir, double rdisp1)
{
    law_fix_init(&F, law(), P, 7, n, ndir);
    for (int k = 0; k < n; ++k) {
        RS_A2(F.rdisp, ndir, 0, k) = rdisp1;
    }
}

/* One increment: every contact moves by du (normal, overclosure) and ds (t1, t2). */
static int step(double du, double ds1, double ds2)
{
    const int nd = F.b.nDir;
    for (int k = 0; k < F.b.nSlvNod; ++k) {
        RS_A2(F.rdisp, nd, 0, k) += du;
        RS_A2(F.drdisp, nd, 0, k) = du;
        RS_A2(F.rdisp, nd, 1, k) += ds1;
        RS_A2(F.drdisp, nd, 1, k) = ds1;
        if (nd == 3) {
            RS_A2(F.rdisp, nd, 2, k) += ds2;
            RS_A2(F.drdisp, nd, 2, k) = ds2;
        }
    }
    rs_error err;
    return rs_law_call(law(), &F.b, &err);
}

/* Uniaxial linear hardening from zero: sigma(eps) for monotonic loading. */
static double sigma_closed(double eps)
{
    const double ey = SY0 / E;
    if (fabs(eps) <= ey) {
        return E * eps;
    }
    return copysign(SY0 + E * H / (E + H) * (fabs(eps) - ey), eps);
}

static void test_bonded_normal_elastic_slope_is_E(void)
{
    setup_block(1, 3, -0.005);
    ENSURE(step(0.01, 0.0, 0.0) == RS_OK);
    ENSURE_RREL(F.stress[0], E * 0.01 / T, 1e-14);
    ENSURE_RREL(F.sed[0], 4.0 * 4.0 / (2.0 * E) * T, 1e-14);
    ENSURE(F.spd[0] == 0.0);
    ENSURE(F.statev[0] == 1.0 && F.statev[1] == 1.0 && F.statev[2] == SY0);
}

static void test_bonded_yields_at_yield_stress_with_hardening_slope(void)
{
    setup_block(1, 3, 0.0);
    const double du = 0.001;
    double eps = 0.0, work = 0.0, spd_sum = 0.0;
    for (int i = 0; i < 200; ++i) {
        const double s_old = F.stress[0];
        ENSURE(step(du, 0.0, 0.0) == RS_OK);
        eps += du / T;
        work += 0.5 * (s_old + F.stress[0]) * (du / T) * T;
        spd_sum += F.spd[0];
        ENSURE_NEAR(F.stress[0], sigma_closed(eps), 1e-9);
        ENSURE(F.stress[0] <= F.statev[2] + 1e-12);
    }
    const double s = F.stress[0];
    ENSURE(s > SY0 + 5.0); /* well past yield: 10 + 18.18 * 0.35 */
    ENSURE_NEAR(F.statev[2], s, 1e-9);
    /* Plastic work: sigma = sy0 + H eps_p, so int sigma deps_p = (sy0 + s)/2 eps_p. */
    const double eps_p = eps - s / E;
    ENSURE_RREL(spd_sum, 0.5 * (SY0 + s) * eps_p * T, 1e-9);
    /* Energy balance: external work = elastic energy + plastic dissipation. */
    ENSURE_RREL(work, F.sed[0] + spd_sum, 1e-9);
}

static void test_bonded_unloading_is_elastic_with_slope_E(void)
{
    setup_block(1, 3, 0.0);
    ENSURE(step(0.05, 0.0, 0.0) == RS_OK); /* eps = 0.1, past yield */
    const double s1 = F.stress[0], sy1 = F.statev[2];
    ENSURE_NEAR(s1, sigma_closed(0.1), 1e-12);
    ENSURE(step(-0.004, 0.0, 0.0) == RS_OK);
    ENSURE_RREL(F.stress[0], s1 - E * 0.008, 1e-13);
    ENSURE(F.spd[0] == 0.0);
    ENSURE(F.statev[2] == sy1);
}

static void test_bonded_stays_bonded_in_tension(void)
{
    setup_block(1, 3, -0.005);
    ENSURE(step(-0.004, 0.0, 0.0) == RS_OK);
    ENSURE_RREL(F.stress[0], -E * 0.008, 1e-14);
    ENSURE(F.statev[1] == 1.0);
    /* Pulled one unit away in one increment: eps = -2, hardened tensile yield. */
    ENSURE(step(-0.996, 0.0, 0.0) == RS_OK);
    ENSURE(RS_A2(F.rdisp, 3, 0, 0) < -0.99);
    ENSURE_RREL(F.stress[0], sigma_closed(-2.0), 1e-12);
    ENSURE(F.stress[0] < 0.0);
    ENSURE(F.statev[1] == 1.0);
}

static void test_bonded_shear_elastic_with_G(void)
{
    setup_block(1, 3, 0.0);
    const double G = E / (2.0 * (1.0 + NU));
    ENSURE(step(0.0, 0.01, -0.02) == RS_OK);
    ENSURE_RREL(F.stress[1], G * 0.01 / T, 1e-14);
    ENSURE_RREL(F.stress[2], -G * 0.02 / T, 1e-14);
    ENSURE(F.stress[0] == 0.0);
    ENSURE(step(0.0, 0.01, 0.0) == RS_OK);
    ENSURE_RREL(F.stress[1], G * 0.02 / T, 1e-14);
    ENSURE_RREL(F.stress[2], -G * 0.02 / T, 1e-14);
    const double tau2 = F.stress[1] * F.stress[1] + F.stress[2] * F.stress[2];
    ENSURE_RREL(F.sed[0], tau2 / (2.0 * G) * T, 1e-14);
    /* Shear beyond the normal yield stress stays elastic. */
    ENSURE(step(0.0, 1.0, 0.0) == RS_OK);
    ENSURE_RREL(F.stress[1], G * 1.02 / T, 1e-14);
    ENSURE(F.spd[0] == 0.0);

    setup_block(1, 2, 0.0);
    ENSURE(step(0.0, 0.01, 0.0) == RS_OK);
    ENSURE_RREL(F.stress[1], G * 0.01 / T, 1e-14);
}

static void test_bonded_heat_flux_through_layer(void)
{
    setup_block(2, 3, 0.0);
    F.tempSlv[0] = 300.0;
    F.tempSlv[1] = 420.0;
    F.tempMst[0] = 350.0;
    ENSURE(step(0.0, 0.0, 0.0) == RS_OK);
    ENSURE_RREL(F.fluxSlv[0], K * 50.0 / T, 1e-14);
    ENSURE_RREL(F.fluxMst[0], -K * 50.0 / T, 1e-14);
    ENSURE_RREL(F.fluxSlv[1], -K * 70.0 / T, 1e-14);
    ENSURE_RREL(F.fluxMst[1], K * 70.0 / T, 1e-14);
    /* One wall temperature per contact (numDefTfv = n). */
    F.b.numDefTfv = 2;
    F.tempMst[1] = 400.0;
    ENSURE(step(0.0, 0.0, 0.0) == RS_OK);
    ENSURE_RREL(F.fluxSlv[1], -K * 20.0 / T, 1e-14);
    /* No temperatures: no flux. */
    F.b.nTemp = 0;
    ENSURE(step(0.0, 0.0, 0.0) == RS_OK);
    ENSURE(F.fluxSlv[0] == 0.0 && F.fluxMst[1] == 0.0);
}

static void test_bonded_initial_gap_beyond_cutoff_never_bonds(void)
{
    law_fix_init(&F, law(), P, 7, 4, 3);
    const double gap[4] = {0.0, 0.5 * CUT, 1.5 * CUT, 10.0 * CUT};
    for (int k = 0; k < 4; ++k) {
        RS_A2(F.rdisp, 3, 0, k) = -gap[k];
        F.tempSlv[k] = 300.0;
    }
    F.tempMst[0] = 310.0;
    ENSURE(step(0.001, 0.001, 0.0) == RS_OK);
    for (int k = 0; k < 4; ++k) {
        const int bonded = gap[k] < CUT;
        ENSURE(F.statev[3 * k] == 1.0);
        ENSURE(F.statev[3 * k + 1] == (bonded ? 1.0 : 0.0));
        ENSURE((RS_A2(F.stress, 3, 0, k) != 0.0) == bonded);
        ENSURE((F.fluxSlv[k] != 0.0) == bonded);
    }
    /* Later overclosure does not bond an unbonded slave. */
    ENSURE(step(0.2, 0.0, 0.0) == RS_OK);
    ENSURE(RS_A2(F.rdisp, 3, 0, 3) > 0.0);
    ENSURE(F.statev[3 * 3 + 1] == 0.0);
    ENSURE(RS_A2(F.stress, 3, 0, 3) == 0.0 && RS_A2(F.stress, 3, 1, 3) == 0.0);
}

static void test_bonded_maxval_contact_gets_zero_stress_and_flux(void)
{
    setup_block(1, 3, 0.0);
    F.tempMst[0] = 500.0;
    ENSURE(step(0.01, 0.01, 0.0) == RS_OK);
    ENSURE(F.stress[0] != 0.0 && F.fluxSlv[0] != 0.0);
    for (int i = 0; i < 3; ++i) {
        F.rdisp[i] = RS_MAXVAL;
        F.drdisp[i] = RS_MAXVAL;
    }
    for (int i = 0; i < 4; ++i) {
        F.drot[i] = RS_MAXVAL;
    }
    rs_error err;
    ENSURE(rs_law_call(law(), &F.b, &err) == RS_OK);
    ENSURE(F.stress[0] == 0.0 && F.stress[1] == 0.0 && F.stress[2] == 0.0);
    ENSURE(F.fluxSlv[0] == 0.0 && F.fluxMst[0] == 0.0 && F.sed[0] == 0.0);
    ENSURE(F.statev[1] == 1.0);
}

static void test_bonded_setup_call_keeps_state(void)
{
    setup_block(1, 3, -2.0 * CUT);
    F.b.setup = 1;
    ENSURE(step(0.0, 0.0, 0.0) == RS_OK);
    ENSURE(F.statev[0] == 0.0 && F.statev[1] == 0.0 && F.statev[2] == 0.0);
}

int main(void)
{
    RS_RUN(test_bonded_normal_elastic_slope_is_E);
    RS_RUN(test_bonded_yields_at_yield_stress_with_hardening_slope);
    RS_RUN(test_bonded_unloading_is_elastic_with_slope_E);
    RS_RUN(test_bonded_stays_bonded_in_tension);
    RS_RUN(test_bonded_shear_elastic_with_G);
    RS_RUN(test_bonded_heat_flux_through_layer);
    RS_RUN(test_bonded_initial_gap_beyond_cutoff_never_bonds);
    RS_RUN(test_bonded_maxval_contact_gets_zero_stress_and_flux);
    RS_RUN(test_bonded_setup_call_keeps_state);
    return rs_test_summary();
}
