/* The law API: registry, property checks, the guarded block call (NaN guard naming
 * particle and feature), block defaults, and the default stiffness and conductance. */
#include "rs_test.h"
#include "test_law_fixture.h"

#include <math.h>
#include <string.h>

static law_fix F;

static void test_law_registry_finds_builtins_case_insensitive(void)
{
    ENSURE(rs_law_count() == 5);
    const char *names[] = {"bonded_interface", "linear_softening", "hertz", "hooke",
                           "coulomb"};
    for (int i = 0; i < 5; ++i) {
        const rs_law *law = rs_law_find(names[i]);
        ENSURE(law != NULL);
        ENSURE(strcmp(law->name, names[i]) == 0);
        ENSURE(law->update != NULL);
        ENSURE(law->prop_names != NULL);
        int found = 0;
        for (int j = 0; j < rs_law_count(); ++j) {
            found += rs_law_at(j) == law;
        }
        ENSURE(found == 1);
    }
    ENSURE(rs_law_find("HeRtZ") == rs_law_find("hertz"));
    ENSURE(rs_law_find("Bonded_Interface") == rs_law_find("bonded_interface"));
    ENSURE(rs_law_find("hertz2") == NULL);
    ENSURE(rs_law_find("hert") == NULL);
    ENSURE(rs_law_find(NULL) == NULL);
    ENSURE(rs_law_at(-1) == NULL);
    ENSURE(rs_law_at(rs_law_count()) == NULL);
    ENSURE(rs_law_find("bonded_interface")->nprops == 7);
    ENSURE(rs_law_find("bonded_interface")->nstatev == 3);
    ENSURE(rs_law_find("hertz")->nprops == 7);
}

static const double bonded_ok[7] = {0.01, 200.0, 0.3, 10.0, 20.0, 0.5, 2.0};
static const double hertz_ok[7] = {5e6, 0.45, 5e6, 0.3, 0.5, 0.4, 0.0};

static void test_law_props_wrong_count_names_law_and_props(void)
{
    rs_error err;
    rs_error_clear(&err);
    const rs_law *h = rs_law_find("hertz");
    ENSURE(rs_law_check_props(h, hertz_ok, 7, &err) == RS_OK);
    ENSURE(rs_law_check_props(h, hertz_ok, 6, &err) == RS_ERR_ARG);
    ENSURE(err.code == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "hertz") != NULL);
    ENSURE(strstr(err.msg, "expects 7") != NULL);
    ENSURE(strstr(err.msg, "got 6") != NULL);
    ENSURE(strstr(err.msg, "restitution") != NULL);
}

static void test_law_props_nonfinite_names_property(void)
{
    rs_error err;
    const rs_law *b = rs_law_find("bonded_interface");
    double p[7];
    memcpy(p, bonded_ok, sizeof p);
    ENSURE(rs_law_check_props(b, p, 7, &err) == RS_OK);
    p[1] = NAN;
    ENSURE(rs_law_check_props(b, p, 7, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "bonded_interface") != NULL);
    ENSURE(strstr(err.msg, "'E'") != NULL);
    p[1] = 200.0;
    p[6] = INFINITY;
    ENSURE(rs_law_check_props(b, p, 7, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "'conductivity'") != NULL);
}

static void test_law_props_sign_checks_name_property(void)
{
    rs_error err;
    const rs_law *b = rs_law_find("bonded_interface");
    double p[7];
    memcpy(p, bonded_ok, sizeof p);
    p[1] = -200.0;
    ENSURE(rs_law_check_props(b, p, 7, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "'E'") != NULL);
    ENSURE(strstr(err.msg, "-200") != NULL);
    p[1] = 200.0;
    p[5] = 0.0;
    ENSURE(rs_law_check_props(b, p, 7, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "'thickness'") != NULL);
    p[5] = 0.5;
    p[2] = 0.5;
    ENSURE(rs_law_check_props(b, p, 7, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "'nu'") != NULL);

    double h[7];
    memcpy(h, hertz_ok, sizeof h);
    h[4] = 0.0;
    ENSURE(rs_law_check_props(rs_law_find("hertz"), h, 7, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "'restitution'") != NULL);
    h[4] = 0.5;
    h[6] = 0.5;
    ENSURE(rs_law_check_props(rs_law_find("hertz"), h, 7, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "'curvature'") != NULL);
    double k = -1.0;
    ENSURE(rs_law_check_props(rs_law_find("linear_softening"), &k, 1, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "'k'") != NULL);
    double c[3] = {0.3, 1e6, -1e6};
    ENSURE(rs_law_check_props(rs_law_find("coulomb"), c, 3, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "'kn'") != NULL);
    double hk[5] = {1e4, 1e4, 0.5, -0.1, 0.3};
    ENSURE(rs_law_check_props(rs_law_find("hooke"), hk, 5, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "'zeta_t'") != NULL);
}

/* A user law: writes NaN or Inf into one chosen output of one chosen contact. */
static int bad_contact = -1, bad_what = 0;
static int user_update(const rs_law *law, rs_law_block *b, rs_error *err)
{
    (void)law;
    (void)err;
    for (int k = 0; k < b->nSlvNod; ++k) {
        for (int i = 0; i < b->nDir; ++i) {
            RS_A2(b->stress, b->nDir, i, k) = 1.0;
        }
        b->fluxSlv[k] = 0.0;
        b->fluxMst[k] = 0.0;
    }
    if (bad_contact >= 0) {
        if (bad_what < 3) {
            RS_A2(b->stress, b->nDir, bad_what, bad_contact) = NAN;
        } else if (bad_what == 3) {
            b->fluxSlv[bad_contact] = INFINITY;
        } else {
            b->fluxMst[bad_contact] = -INFINITY;
        }
    }
    return RS_OK;
}
static const rs_law user_law = {.name = "my_law", .nprops = -1, .update = user_update};

static void test_law_props_user_law_accepts_any_count_but_not_nan(void)
{
    rs_error err;
    double p[3] = {1.0, 2.0, 3.0};
    ENSURE(rs_law_check_props(&user_law, p, 3, &err) == RS_OK);
    ENSURE(rs_law_check_props(&user_law, p, 0, &err) == RS_OK);
    p[2] = NAN;
    ENSURE(rs_law_check_props(&user_law, p, 3, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "my_law") != NULL);
    ENSURE(strstr(err.msg, "property 3") != NULL);
}

static void test_law_call_nan_guard_names_particle_and_feature(void)
{
    rs_error err;
    law_fix_init(&F, &user_law, NULL, 0, 10, 3);
    F.fid[6] = RS_FEATURE(RS_FEAT_EDGE, 9);
    bad_contact = -1;
    ENSURE(rs_law_call(&user_law, &F.b, &err) == RS_OK);

    bad_contact = 6;
    bad_what = 1;
    rs_error_clear(&err);
    ENSURE(rs_law_call(&user_law, &F.b, &err) == RS_ERR_NONFINITE);
    ENSURE(err.code == RS_ERR_NONFINITE);
    ENSURE(strstr(err.msg, "my_law") != NULL);
    ENSURE(strstr(err.msg, "particle 106") != NULL);
    char feat[64];
    snprintf(feat, sizeof feat, "feature %d (edge 9)", RS_FEATURE(RS_FEAT_EDGE, 9));
    ENSURE(strstr(err.msg, feat) != NULL);
    ENSURE(strstr(err.msg, "stress(2)") != NULL);

    bad_contact = 2;
    bad_what = 3;
    ENSURE(rs_law_call(&user_law, &F.b, &err) == RS_ERR_NONFINITE);
    ENSURE(strstr(err.msg, "particle 102") != NULL);
    ENSURE(strstr(err.msg, "fluxSlv") != NULL);
    bad_what = 4;
    ENSURE(rs_law_call(&user_law, &F.b, &err) == RS_ERR_NONFINITE);
    ENSURE(strstr(err.msg, "fluxMst") != NULL);

    /* stress(3) does not exist when nDir = 2: a NaN there is outside the block. */
    law_fix_init(&F, &user_law, NULL, 0, 10, 2);
    bad_contact = 9;
    bad_what = 0;
    ENSURE(rs_law_call(&user_law, &F.b, &err) == RS_ERR_NONFINITE);
    ENSURE(strstr(err.msg, "particle 109") != NULL);
    ENSURE(strstr(err.msg, "stress(1)") != NULL);
    bad_contact = -1;
}

static void test_law_call_rejects_malformed_block(void)
{
    rs_error err;
    const rs_law *h = rs_law_find("hertz");
    law_fix_init(&F, h, hertz_ok, 7, 4, 3);
    ENSURE(rs_law_call(h, &F.b, &err) == RS_OK);
    F.b.nSlvNod = RS_BLOCK + 1;
    ENSURE(rs_law_call(h, &F.b, &err) == RS_ERR_ARG);
    F.b.nSlvNod = 4;
    F.b.nDir = 4;
    ENSURE(rs_law_call(h, &F.b, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "nDir") != NULL);
    F.b.nDir = 3;
    F.b.stress = NULL;
    ENSURE(rs_law_call(h, &F.b, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "stress") != NULL);
    F.b.stress = F.stress;
    F.b.nStateVar = 1;
    ENSURE(rs_law_call(h, &F.b, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "state variables") != NULL);
    F.b.nStateVar = 2;
    F.b.nProps = 6;
    ENSURE(rs_law_call(h, &F.b, &err) == RS_ERR_ARG);
    F.b.nProps = 7;
    F.b.mass = NULL;
    ENSURE(rs_law_call(h, &F.b, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "mass") != NULL);
}

static void test_law_call_zeroes_write_only_energies(void)
{
    rs_error err;
    law_fix_init(&F, &user_law, NULL, 0, 3, 3);
    for (int k = 0; k < 3; ++k) {
        F.sfd[k] = F.scd[k] = F.spd[k] = F.svd[k] = 7.0;
    }
    ENSURE(rs_law_call(&user_law, &F.b, &err) == RS_OK);
    for (int k = 0; k < 3; ++k) {
        ENSURE(F.sfd[k] == 0.0 && F.scd[k] == 0.0 && F.spd[k] == 0.0 && F.svd[k] == 0.0);
    }
}

/* A law that declares it sets every energy (RS_LAW_SETS_ENERGIES) gets them as they
 * were: the call does not zero them first. */
static int energies_update(const rs_law *law, rs_law_block *b, rs_error *err)
{
    (void)law, (void)err;
    for (int k = 0; k < b->nSlvNod; ++k) {
        for (int i = 0; i < b->nDir; ++i)
            RS_A2(b->stress, b->nDir, i, k) = 0.0;
        b->fluxSlv[k] = b->fluxMst[k] = 0.0;
        b->svd[k] += 1.0;
    }
    return RS_OK;
}

static void test_law_call_leaves_energies_to_a_law_that_sets_them(void)
{
    const rs_law sets = {.name = "sets_energies",
                         .nprops = -1,
                         .update = energies_update,
                         .sets = RS_LAW_SETS_ENERGIES};
    const rs_law plain = {.name = "plain", .nprops = -1, .update = energies_update};
    rs_error err;
    for (int v = 0; v < 2; v++) {
        law_fix_init(&F, v ? &sets : &plain, NULL, 0, 3, 3);
        for (int k = 0; k < 3; ++k)
            F.sfd[k] = F.scd[k] = F.spd[k] = F.svd[k] = 7.0;
        ENSURE(rs_law_call(v ? &sets : &plain, &F.b, &err) == RS_OK);
        for (int k = 0; k < 3; ++k) {
            const double kept = v ? 7.0 : 0.0;
            ENSURE(F.sfd[k] == kept && F.scd[k] == kept && F.spd[k] == kept);
            ENSURE(F.svd[k] == kept + 1.0);
        }
    }
}

/* An engine fills the stress before a call unless the law neither reads it on entry nor
 * leaves any of it unwritten; among the built-in laws, hertz and hooke. */
static void test_law_stress_in_follows_skips_and_sets(void)
{
    const rs_law skips = {.name = "skips",
                          .nprops = -1,
                          .update = energies_update,
                          .skips = RS_LAW_SKIPS_STRESS};
    const rs_law sets = {.name = "sets",
                         .nprops = -1,
                         .update = energies_update,
                         .sets = RS_LAW_SETS_STRESS};
    const rs_law both = {.name = "both",
                         .nprops = -1,
                         .update = energies_update,
                         .skips = RS_LAW_SKIPS_STRESS,
                         .sets = RS_LAW_SETS_STRESS};
    ENSURE(rs_law_stress_in(NULL) == 1);
    ENSURE(rs_law_stress_in(&skips) == 1);
    ENSURE(rs_law_stress_in(&sets) == 1);
    ENSURE(rs_law_stress_in(&both) == 0);
    const char *names[] = {"bonded_interface", "linear_softening", "hertz", "hooke",
                           "coulomb"};
    for (int i = 0; i < 5; ++i) {
        const int lean = !strcmp(names[i], "hertz") || !strcmp(names[i], "hooke");
        ENSURE(rs_law_stress_in(rs_law_find(names[i])) == !lean);
    }
}

static void test_law_block_init_sets_abaqus_defaults(void)
{
    rs_law_block b;
    memset(&b, 0x5a, sizeof b);
    rs_law_block_init(&b);
    ENSURE(b.nFacNod == 1 && b.nTemp == 1 && b.numDefTfv == 1 && b.nPred == 0);
    ENSURE(b.kStep == 1 && b.setup == 0 && b.nSlvNod == 0);
    for (int k = 0; k < RS_BLOCK; ++k) {
        ENSURE(b.shape[k] == 1.0 && b.areaSlv[k] == 1.0);
        ENSURE(b.tempSlv[k] == 0.0 && b.dtempSlv[k] == 0.0);
    }
    ENSURE(b.tempMst[0] == 0.0);
    ENSURE(b.stress == NULL && b.rdisp == NULL && b.radius == NULL && b.warn == NULL);
    for (int i = 0; i < RS_LAW_NAMELEN; ++i) {
        ENSURE(b.surfInt[i] == ' ' && b.surfMst[i] == ' ');
    }
    rs_law_block_set_name(b.surfMst, "DRUM");
    ENSURE(memcmp(b.surfMst, "DRUM ", 5) == 0 && b.surfMst[RS_LAW_NAMELEN - 1] == ' ');
}

/* Central differences on m x'' = -k A x: bounded at the default k, growing once k A
 * exceeds the 4 m / dt^2 limit (the default sits ten times under it). */
static double spring_amplitude(double m, double kA, double dt, int steps)
{
    double x = 1.0, v = 0.0, amax = 0.0;
    for (int i = 0; i < steps; ++i) {
        v += -kA * x / m * dt;
        x += v * dt;
        amax = fmax(amax, fabs(x));
    }
    return amax;
}

static void test_law_default_stiffness_ten_times_under_stability_limit(void)
{
    const double m = 2e-3, A = 0.5, dt = 1e-5;
    const double k = rs_law_default_stiffness(m, A, dt);
    ENSURE_RREL(k, 0.4 * m / (A * dt * dt), 1e-14);
    /* dt is sqrt(10) times under the critical 2 sqrt(m/(kA)). */
    ENSURE_RREL(2.0 * sqrt(m / (k * A)) / dt, sqrt(10.0), 1e-14);
    ENSURE(spring_amplitude(m, k * A, dt, 10000) < 1.5);
    ENSURE(spring_amplitude(m, 9.0 * k * A, dt, 10000) < 10.0);
    ENSURE(spring_amplitude(m, 11.0 * k * A, dt, 10000) > 1e6);
    ENSURE(rs_law_default_stiffness(0.0, A, dt) == 0.0);
    ENSURE(rs_law_default_stiffness(m, -1.0, dt) == 0.0);
    ENSURE(rs_law_default_stiffness(m, A, NAN) == 0.0);
}

static void test_law_default_conductance_keeps_explicit_heat_step_monotone(void)
{
    const double C = 0.8 * 500.0, A = 0.01, dt = 1e-4, Tw = 400.0;
    const double h = rs_law_default_conductance(C, A, dt);
    ENSURE_RREL(h * A * dt / C, 0.1, 1e-14);
    double T = 300.0, prev = T;
    for (int i = 0; i < 50; ++i) {
        T += h * A * (Tw - T) / C * dt;
        ENSURE(T > prev && T < Tw);
        prev = T;
    }
    /* Closed form of the recursion: Tw - T_n = (Tw - T_0) 0.9^n. */
    ENSURE_RREL(Tw - T, 100.0 * pow(0.9, 50), 1e-10);
    ENSURE(rs_law_default_conductance(C, 0.0, dt) == 0.0);
}

int main(void)
{
    RS_RUN(test_law_registry_finds_builtins_case_insensitive);
    RS_RUN(test_law_props_wrong_count_names_law_and_props);
    RS_RUN(test_law_props_nonfinite_names_property);
    RS_RUN(test_law_props_sign_checks_name_property);
    RS_RUN(test_law_props_user_law_accepts_any_count_but_not_nan);
    RS_RUN(test_law_call_nan_guard_names_particle_and_feature);
    RS_RUN(test_law_call_rejects_malformed_block);
    RS_RUN(test_law_call_zeroes_write_only_energies);
    RS_RUN(test_law_call_leaves_energies_to_a_law_that_sets_them);
    RS_RUN(test_law_stress_in_follows_skips_and_sets);
    RS_RUN(test_law_block_init_sets_abaqus_defaults);
    RS_RUN(test_law_default_stiffness_ten_times_under_stability_limit);
    RS_RUN(test_law_default_conductance_keeps_explicit_heat_step_monotone);
    return rs_test_summary();
}
