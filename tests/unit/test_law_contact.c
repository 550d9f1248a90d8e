/* linear_softening, hooke and coulomb against closed forms: p = k h, critical damping
 * and the spring-dashpot restitution exp(-zeta pi / sqrt(1 - zeta^2)), the Coulomb
 * stick/slip threshold and sfd = tau . dslip. */
#include "rs_test.h"
#include "test_law_fixture.h"

#include <math.h>

static law_fix F;

static void test_softening_pressure_is_k_times_overclosure(void)
{
    const rs_law *law = rs_law_find("linear_softening");
    const double k = 3e5;
    law_fix_init(&F, law, &k, 1, 4, 3);
    const double h[4] = {2e-4, 0.0, -1e-3, RS_MAXVAL};
    for (int c = 0; c < 4; ++c) {
        RS_A2(F.rdisp, 3, 0, c) = h[c];
        RS_A2(F.stress, 3, 1, c) = 9.0; /* stale shear must not survive */
    }
    rs_error err;
    ENSURE(rs_law_call(law, &F.b, &err) == RS_OK);
    ENSURE_RREL(F.stress[0], k * 2e-4, 1e-15);
    ENSURE_RREL(F.sed[0], 0.5 * k * 4e-8, 1e-15);
    for (int c = 1; c < 4; ++c) {
        ENSURE(RS_A2(F.stress, 3, 0, c) == 0.0 && F.sed[c] == 0.0);
    }
    for (int c = 0; c < 4; ++c) {
        ENSURE(RS_A2(F.stress, 3, 1, c) == 0.0 && RS_A2(F.stress, 3, 2, c) == 0.0);
        ENSURE(F.fluxSlv[c] == 0.0 && F.fluxMst[c] == 0.0);
    }
}

static const double HK[5] = {1e4, 5e3, 1.0, 0.5, 0.3};

static void test_hooke_critical_damping_from_particle_mass(void)
{
    const rs_law *law = rs_law_find("hooke");
    law_fix_init(&F, law, HK, 5, 2, 3);
    F.mass[1] = 4e-3;
    for (int c = 0; c < 2; ++c) {
        RS_A2(F.rdisp, 3, 0, c) = 1e-4;
        RS_A2(F.vrel, 3, 0, c) = -0.2;
        RS_A2(F.drdisp, 3, 1, c) = 1e-6;
        RS_A2(F.vrel, 3, 1, c) = 0.1;
    }
    rs_error err;
    ENSURE(rs_law_call(law, &F.b, &err) == RS_OK);
    for (int c = 0; c < 2; ++c) {
        const double m = F.mass[c];
        const double ccrit = 2.0 * sqrt(HK[0] * m); /* critical damping of m on kn */
        ENSURE_RREL(RS_A2(F.stress, 3, 0, c), HK[0] * 1e-4 + ccrit * 0.2, 1e-13);
        const double gt = HK[3] * 2.0 * sqrt(HK[1] * m);
        ENSURE_RREL(RS_A2(F.stress, 3, 1, c), HK[1] * 1e-6 + gt * 0.1, 1e-13);
        ENSURE_RREL(F.sed[c], 0.5 * (HK[0] * 1e-8 + HK[1] * 1e-12), 1e-13);
    }
}

/* hooke declares that it writes every contact's stress (rs_law.sets), and it skips the
 * stress on entry: an engine then gives it the array as it is (rs_law_stress_in). Called
 * directly on a block of a sticking, a sliding, an open and a leaving contact with NaN
 * stress before the call, in an increment and in a setup call, every stress is written,
 * and the force of the two touching contacts is there. */
static void test_hooke_sets_every_stress(void)
{
    const rs_law *law = rs_law_find("hooke");
    ENSURE(law->sets == RS_LAW_SETS_STRESS);
    ENSURE(rs_law_stress_in(law) == 0);
    for (int setup = 0; setup < 2; ++setup) {
        law_fix_init(&F, law, HK, 5, 4, 3);
        F.b.setup = setup;
        const double h[4] = {1e-4, 2e-4, -1e-4, RS_MAXVAL};
        for (int c = 0; c < 4; ++c) {
            RS_A2(F.rdisp, 3, 0, c) = h[c];
            RS_A2(F.drdisp, 3, 1, c) = c == 1 ? 1e-2 : 1e-7; /* contact 1 slides */
            RS_A2(F.vrel, 3, 1, c) = 0.1;
            for (int i = 0; i < 3; ++i)
                RS_A2(F.stress, 3, i, c) = NAN;
        }
        rs_error err;
        ENSURE(law->update(law, &F.b, &err) == RS_OK);
        for (int c = 0; c < 4; ++c)
            for (int i = 0; i < 3; ++i)
                ENSURE(isfinite(RS_A2(F.stress, 3, i, c)));
        ENSURE(RS_A2(F.stress, 3, 0, 0) > 0.0 && RS_A2(F.stress, 3, 0, 1) > 0.0);
        for (int c = 2; c < 4; ++c)
            for (int i = 0; i < 3; ++i)
                ENSURE(RS_A2(F.stress, 3, i, c) == 0.0);
    }
}

/* 1-DOF impact on hooke (velocity Verlet); returns the exit over entry speed, or 0 when
 * the particle has not left after 'periods' undamped periods. */
static double hooke_restitution(double zeta, double periods)
{
    const rs_law *law = rs_law_find("hooke");
    double p[5];
    memcpy(p, HK, sizeof p);
    p[2] = zeta;
    law_fix_init(&F, law, p, 5, 1, 3);
    const double m = F.mass[0];
    const double period = 2.0 * acos(-1.0) * sqrt(m / p[0]);
    const double dt = period / 20000.0, v0 = 0.5;
    F.b.dTimCur = dt;
    double delta = 0.0, v = -v0, f = 0.0;
    rs_error err;
    const int steps = (int)(periods * 20000.0);
    for (int i = 0; i < steps; ++i) {
        v += 0.5 * dt * f / m;
        const double dnew = delta - v * dt;
        F.rdisp[0] = dnew;
        F.drdisp[0] = dnew - delta;
        F.vrel[0] = v;
        delta = dnew;
        if (rs_law_call(law, &F.b, &err) != RS_OK) {
            return NAN;
        }
        f = F.stress[0];
        v += 0.5 * dt * f / m;
        if (delta <= 0.0 && i > 0) {
            return v / v0;
        }
    }
    return 0.0;
}

static void test_hooke_restitution_of_spring_dashpot(void)
{
    const double zetas[] = {0.05, 0.2, 0.5};
    for (int i = 0; i < 3; ++i) {
        const double z = zetas[i];
        const double e = exp(-z * acos(-1.0) / sqrt(1.0 - z * z));
        ENSURE_RREL(hooke_restitution(z, 2.0), e, 2e-3);
    }
    /* Critically damped: x = v0 t exp(-w t) never returns to zero, no rebound. */
    ENSURE(hooke_restitution(1.0, 20.0) == 0.0);
    ENSURE(F.rdisp[0] > 0.0);
}

static const double CP[3] = {0.4, 2e6, 5e6}; /* mu, k_stick, kn */

static void test_coulomb_sticks_below_mu_p_and_slips_above(void)
{
    const rs_law *law = rs_law_find("coulomb");
    law_fix_init(&F, law, CP, 3, 3, 3);
    const double h = 1e-4, p = CP[2] * h, lim = CP[0] * p;
    const double ds[3] = {0.5 * lim / CP[1], 0.999 * lim / CP[1], 3.0 * lim / CP[1]};
    for (int c = 0; c < 3; ++c) {
        RS_A2(F.rdisp, 3, 0, c) = h;
        RS_A2(F.drdisp, 3, 1, c) = 0.6 * ds[c];
        RS_A2(F.drdisp, 3, 2, c) = -0.8 * ds[c];
    }
    rs_error err;
    ENSURE(rs_law_call(law, &F.b, &err) == RS_OK);
    for (int c = 0; c < 3; ++c) {
        ENSURE_RREL(RS_A2(F.stress, 3, 0, c), p, 1e-14);
        const double tau = hypot(RS_A2(F.stress, 3, 1, c), RS_A2(F.stress, 3, 2, c));
        ENSURE_RREL(RS_A2(F.stress, 3, 1, c) / RS_A2(F.stress, 3, 2, c), -0.75, 1e-12);
        ENSURE(RS_A2(F.stress, 3, 1, c) > 0.0);
        if (c < 2) {
            ENSURE_RREL(tau, CP[1] * ds[c], 1e-12);
            ENSURE(F.sfd[c] == 0.0);
        } else {
            ENSURE_RREL(tau, lim, 1e-12);
            /* slip beyond the elastic limit: 3 lim/k - lim/k */
            ENSURE_RREL(F.sfd[c], lim * 2.0 * lim / CP[1], 1e-12);
            ENSURE_RREL(hypot(F.statev[4], F.statev[5]), lim / CP[1], 1e-12);
        }
        ENSURE_RREL(F.sed[c], 0.5 * CP[2] * h * h + tau * tau / (2.0 * CP[1]), 1e-12);
    }
}

static void test_coulomb_steady_sliding_dissipates_mu_p_times_slip(void)
{
    const rs_law *law = rs_law_find("coulomb");
    law_fix_init(&F, law, CP, 3, 1, 2);
    const double h = 2e-4, p = CP[2] * h, lim = CP[0] * p, ds = 1e-6;
    F.rdisp[0] = h;
    F.drdisp[1] = ds;
    double sfd = 0.0;
    rs_error err;
    const int n = 1000; /* total slip 5 times the elastic limit lim / k_stick */
    for (int i = 0; i < n; ++i) {
        ENSURE(rs_law_call(law, &F.b, &err) == RS_OK);
        sfd += F.sfd[0];
        ENSURE(F.stress[1] <= lim * (1.0 + 1e-14));
    }
    ENSURE_RREL(F.stress[1], lim, 1e-14);
    /* Total slip n ds; the elastic part lim / k_stick is stored, the rest dissipated. */
    ENSURE_RREL(sfd, lim * (n * ds - lim / CP[1]), 1e-9);
    /* Reversal: the first step back is elastic with the stick stiffness. */
    F.drdisp[1] = -ds;
    ENSURE(rs_law_call(law, &F.b, &err) == RS_OK);
    ENSURE_RREL(F.stress[1], lim - CP[1] * ds, 1e-12);
    ENSURE(F.sfd[0] == 0.0);
    /* Opening clears the stick history. */
    F.rdisp[0] = -1e-6;
    ENSURE(rs_law_call(law, &F.b, &err) == RS_OK);
    ENSURE(F.stress[0] == 0.0 && F.stress[1] == 0.0 && F.statev[0] == 0.0);
}

int main(void)
{
    RS_RUN(test_softening_pressure_is_k_times_overclosure);
    RS_RUN(test_hooke_critical_damping_from_particle_mass);
    RS_RUN(test_hooke_sets_every_stress);
    RS_RUN(test_hooke_restitution_of_spring_dashpot);
    RS_RUN(test_coulomb_sticks_below_mu_p_and_slips_above);
    RS_RUN(test_coulomb_steady_sliding_dissipates_mu_p_times_slip);
    return rs_test_summary();
}
