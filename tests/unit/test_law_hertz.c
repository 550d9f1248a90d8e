/* hertz against the LIGGGHTS Hertz wall formulas of docs/conventions.md, evaluated
 * independently here; restitution of an integrated 1-DOF impact; friction cap and
 * history reset; drot carrying the history; setup calls; r_MaxVal. */
#include "rs_test.h"
#include "test_law_fixture.h"

#include <math.h>

static law_fix F;

static const rs_law *law(void)
{
    return rs_law_find("hertz");
}

/* docs/conventions.md, "LIGGGHTS Hertz wall model", for one contact. */
typedef struct hertz_ref {
    double kn, kt, gn, gt, fn;
} hertz_ref;

static hertz_ref hertz_formulas(const double *p, double R, double m, double delta,
                                double vn)
{
    const double pi = acos(-1.0);
    const double ystar = 1.0 / ((1.0 - p[1] * p[1]) / p[0] + (1.0 - p[3] * p[3]) / p[2]);
    const double gstar = 1.0 / (2.0 * (2.0 - p[1]) * (1.0 + p[1]) / p[0] +
                                2.0 * (2.0 - p[3]) * (1.0 + p[3]) / p[2]);
    const double le = log(p[4]);
    const double beta = le / sqrt(le * le + pi * pi);
    const double root = sqrt(R * delta);
    const double Sn = 2.0 * ystar * root, St = 8.0 * gstar * root;
    hertz_ref r;
    r.kn = 4.0 / 3.0 * ystar * root;
    r.kt = St;
    r.gn = -2.0 * sqrt(5.0 / 6.0) * beta * sqrt(Sn * m);
    r.gt = -2.0 * sqrt(5.0 / 6.0) * beta * sqrt(St * m);
    r.fn = r.kn * delta - r.gn * vn;
    return r;
}

static const double P[7] = {5e6, 0.45, 7e7, 0.3, 0.6, 0.4, 0.0};

static void one_contact(const double *props, double delta, double vn)
{
    law_fix_init(&F, law(), props, 7, 1, 3);
    F.rdisp[0] = delta;
    F.vrel[0] = vn;
}

static void test_hertz_plane_step_matches_liggghts_formulas(void)
{
    const double R = 0.01, m = 1e-3, delta = 1e-4, vn = -0.3;
    one_contact(P, delta, vn);
    F.statev[0] = 2e-7;
    F.statev[1] = -1e-7;
    F.drdisp[1] = 1e-7;
    F.drdisp[2] = 3e-7;
    F.vrel[1] = 0.01;
    F.vrel[2] = 0.03;
    rs_error err;
    ENSURE(rs_law_call(law(), &F.b, &err) == RS_OK);
    const hertz_ref r = hertz_formulas(P, R, m, delta, vn);
    const double s1 = 3e-7, s2 = 2e-7;
    ENSURE(r.kt * sqrt(s1 * s1 + s2 * s2) < 0.4 * r.fn); /* this step sticks */
    ENSURE(r.gn > 0.0 && r.gt > 0.0);
    ENSURE_RREL(F.stress[0], r.fn, 1e-12);
    /* Ft = -kt s - gt vt on the particle; stress(2:3) = -Ft. */
    ENSURE_RREL(F.stress[1], r.kt * s1 + r.gt * 0.01, 1e-12);
    ENSURE_RREL(F.stress[2], r.kt * s2 + r.gt * 0.03, 1e-12);
    ENSURE_RREL(F.statev[0], s1, 1e-15);
    ENSURE_RREL(F.statev[1], s2, 1e-15);
    const double dt = F.b.dTimCur;
    ENSURE_RREL(F.svd[0], (r.gn * vn * vn + r.gt * (0.01 * 0.01 + 0.03 * 0.03)) * dt,
                1e-12);
    ENSURE_RREL(F.sed[0], 0.4 * r.kn * delta * delta + 0.5 * r.kt * (s1 * s1 + s2 * s2),
                1e-12);
    ENSURE(F.sfd[0] == 0.0 && F.fluxSlv[0] == 0.0);
    /* Hertz elastic energy: 2/5 kn d^2 = int_0^d 4/3 Y* sqrt(R x) x dx. */
    const double ystar = 3.0 * r.kn / (4.0 * sqrt(R * delta));
    ENSURE_RREL(0.4 * r.kn * delta * delta, 8.0 / 15.0 * ystar * sqrt(R) * pow(delta, 2.5),
                1e-12);
}

static void test_hertz_stress_is_force_per_area(void)
{
    one_contact(P, 1e-4, 0.0);
    F.area[0] = 4.0;
    rs_error err;
    ENSURE(rs_law_call(law(), &F.b, &err) == RS_OK);
    ENSURE_RREL(F.stress[0] * 4.0, hertz_formulas(P, 0.01, 1e-3, 1e-4, 0.0).fn, 1e-12);
}

static void test_hertz_friction_cap_resets_shear_to_limit(void)
{
    const double delta = 1e-4, vn = 0.05;
    one_contact(P, delta, vn);
    F.statev[0] = 3e-4;
    F.statev[1] = -4e-4;
    F.vrel[1] = 1.0; /* sliding: no tangential damping once capped */
    rs_error err;
    ENSURE(rs_law_call(law(), &F.b, &err) == RS_OK);
    const hertz_ref r = hertz_formulas(P, 0.01, 1e-3, delta, vn);
    const double mag = 5e-4, lim = 0.4 * fabs(r.fn);
    ENSURE(r.kt * mag > lim);
    ENSURE_RREL(hypot(F.stress[1], F.stress[2]), lim, 1e-12);
    ENSURE_RREL(F.stress[1] / F.stress[2], -0.75, 1e-12);
    ENSURE(F.stress[1] > 0.0); /* drags the master along the slip */
    ENSURE_RREL(hypot(F.statev[0], F.statev[1]), lim / r.kt, 1e-12);
    ENSURE_RREL(F.statev[0] / F.statev[1], -0.75, 1e-12);
    ENSURE_RREL(F.sfd[0], lim * (mag - lim / r.kt), 1e-12);
    ENSURE_RREL(F.svd[0], r.gn * vn * vn * F.b.dTimCur, 1e-12);
}

static void test_hertz_drot_carries_shear_history(void)
{
    one_contact(P, 1e-4, 0.0);
    F.statev[0] = 1e-7;
    F.statev[1] = 0.0;
    /* Tangent basis turned by +90 deg: old t1 is new t2. drot(i,j) = t_i,new . tau_j. */
    RS_DROT(F.drot, 0, 0, 0) = 0.0;
    RS_DROT(F.drot, 1, 1, 0) = 0.0;
    RS_DROT(F.drot, 1, 0, 0) = 1.0;
    RS_DROT(F.drot, 0, 1, 0) = -1.0;
    rs_error err;
    ENSURE(rs_law_call(law(), &F.b, &err) == RS_OK);
    const hertz_ref r = hertz_formulas(P, 0.01, 1e-3, 1e-4, 0.0);
    ENSURE_SMALL(F.stress[1], 1e-20);
    ENSURE_RREL(F.stress[2], r.kt * 1e-7, 1e-12);
    ENSURE_SMALL(F.statev[0], 1e-22);
    ENSURE_RREL(F.statev[1], 1e-7, 1e-15);
}

static void test_hertz_curvature_flag_uses_reff(void)
{
    double p[7];
    memcpy(p, P, sizeof p);
    p[6] = 1.0;
    one_contact(p, 1e-4, 0.0);
    F.reff[0] = 0.25 * F.radius[0];
    rs_error err;
    ENSURE(rs_law_call(law(), &F.b, &err) == RS_OK);
    const double f_reff = F.stress[0];
    one_contact(P, 1e-4, 0.0);
    F.reff[0] = 0.25 * F.radius[0];
    ENSURE(rs_law_call(law(), &F.b, &err) == RS_OK);
    ENSURE_RREL(f_reff / F.stress[0], 0.5, 1e-14); /* sqrt(reff / R) */
    p[6] = 1.0;
    one_contact(p, 1e-4, 0.0);
    F.b.reff = NULL;
    ENSURE(rs_law_call(law(), &F.b, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "reff") != NULL);
}

static void test_hertz_open_contact_clears_history(void)
{
    one_contact(P, -1e-5, -0.1);
    F.statev[0] = 1e-6;
    F.statev[1] = 1e-6;
    rs_error err;
    ENSURE(rs_law_call(law(), &F.b, &err) == RS_OK);
    ENSURE(F.stress[0] == 0.0 && F.stress[1] == 0.0 && F.stress[2] == 0.0);
    ENSURE(F.statev[0] == 0.0 && F.statev[1] == 0.0);
}

static void test_hertz_maxval_contact_gets_zero_force(void)
{
    one_contact(P, RS_MAXVAL, 0.0);
    for (int i = 0; i < 3; ++i) {
        F.rdisp[i] = F.drdisp[i] = RS_MAXVAL;
    }
    for (int i = 0; i < 4; ++i) {
        F.drot[i] = RS_MAXVAL;
    }
    F.stress[0] = 5.0;
    F.statev[0] = 1e-6;
    F.statev[1] = -2e-6;
    rs_error err;
    ENSURE(rs_law_call(law(), &F.b, &err) == RS_OK);
    ENSURE(F.stress[0] == 0.0 && F.stress[1] == 0.0 && F.stress[2] == 0.0);
    ENSURE(F.sed[0] == 0.0 && F.svd[0] == 0.0);
    /* a leaving contact keeps its shear: only an open one forgets it */
    ENSURE(F.statev[0] == 1e-6 && F.statev[1] == -2e-6);
}

/* The inputs of contact k of the mixed block below: sticking, capped by friction, open,
 * leaving, with turned frames, other radii, masses and areas. */
static void mixed_contact(law_fix *f, int slot, int k)
{
    const int kind = k % 4; /* 0 sticking, 1 capped, 2 open, 3 leaving */
    const double a = 0.1 * (k + 1);
    f->rdisp[3 * slot] = kind == 2 ? -1e-5 * (k + 1) : 1e-5 * (k + 2);
    f->drdisp[3 * slot + 1] = 1e-7 * cos(a);
    f->drdisp[3 * slot + 2] = 1e-7 * sin(a);
    f->vrel[3 * slot] = -0.1 * a;
    f->vrel[3 * slot + 1] = 0.02 * a;
    f->vrel[3 * slot + 2] = -0.01 * a;
    f->statev[2 * slot] = kind == 1 ? 4e-4 : 2e-7 * (k + 1);
    f->statev[2 * slot + 1] = kind == 1 ? -3e-4 : -1e-7 * k;
    RS_DROT(f->drot, 0, 0, slot) = RS_DROT(f->drot, 1, 1, slot) = cos(0.01 * k);
    RS_DROT(f->drot, 1, 0, slot) = sin(0.01 * k);
    RS_DROT(f->drot, 0, 1, slot) = -sin(0.01 * k);
    f->radius[slot] = 0.01 + 1e-3 * k;
    f->mass[slot] = 1e-3 * (1.0 + 0.1 * k);
    f->area[slot] = 1.0 + 0.5 * k;
    if (kind == 3)
        for (int i = 0; i < 3; ++i)
            f->rdisp[3 * slot + i] = f->drdisp[3 * slot + i] = RS_MAXVAL;
}

/* A block of contacts gives each the values it gets alone, bit for bit: the block loop
 * runs several contacts at once (vectorized) and the rest one at a time, and both must
 * be the law of one contact. */
static void test_hertz_block_equals_contacts_one_by_one(void)
{
    enum { N = 11 };
    static law_fix B;
    law_fix_init(&B, law(), P, 7, N, 3);
    for (int k = 0; k < N; ++k)
        mixed_contact(&B, k, k);
    rs_error err;
    ENSURE(rs_law_call(law(), &B.b, &err) == RS_OK);
    int capped = 0;
    for (int k = 0; k < N; ++k) {
        law_fix_init(&F, law(), P, 7, 1, 3);
        mixed_contact(&F, 0, k);
        ENSURE(rs_law_call(law(), &F.b, &err) == RS_OK);
        for (int i = 0; i < 3; ++i)
            ENSURE(B.stress[3 * k + i] == F.stress[i]);
        ENSURE(B.statev[2 * k] == F.statev[0] && B.statev[2 * k + 1] == F.statev[1]);
        ENSURE(B.sed[k] == F.sed[0] && B.svd[k] == F.svd[0] && B.sfd[k] == F.sfd[0]);
        capped += F.sfd[0] > 0.0;
        if (k % 4 == 2) /* open: forgets */
            ENSURE(F.statev[0] == 0.0 && F.statev[1] == 0.0 && F.stress[0] == 0.0);
        if (k % 4 == 3) /* leaving: keeps */
            ENSURE(F.statev[0] == 2e-7 * (k + 1) && F.statev[1] == -1e-7 * k);
    }
    ENSURE(capped >= 2); /* the capped contacts slip */
}

static void test_hertz_setup_call_does_not_advance_history(void)
{
    one_contact(P, 1e-4, 0.0);
    F.statev[0] = 1e-7;
    F.drdisp[1] = 5e-7;
    F.vrel[1] = 0.05;
    F.b.setup = 1;
    rs_error err;
    ENSURE(rs_law_call(law(), &F.b, &err) == RS_OK);
    const hertz_ref r = hertz_formulas(P, 0.01, 1e-3, 1e-4, 0.0);
    ENSURE(F.statev[0] == 1e-7 && F.statev[1] == 0.0);
    ENSURE_RREL(F.stress[1], r.kt * 1e-7 + r.gt * 0.05, 1e-12);
    ENSURE(F.svd[0] == 0.0 && F.sfd[0] == 0.0);
}

/* Normal impact of a sphere on a plane, integrated with velocity Verlet as LIGGGHTS
 * does (nve/sphere): the exit speed over the entry speed is the restitution. */
static double measured_restitution(double e, double v0)
{
    double p[7];
    memcpy(p, P, sizeof p);
    p[4] = e;
    law_fix_init(&F, law(), p, 7, 1, 3);
    const double m = F.mass[0], dt = 1e-6;
    F.b.dTimCur = dt;
    double delta = 0.0, v = -v0, f = 0.0;
    rs_error err;
    for (int i = 0; i < 1000000; ++i) {
        v += 0.5 * dt * f / m;
        const double dnew = delta - v * dt;
        F.rdisp[0] = dnew;
        F.drdisp[0] = dnew - delta;
        F.vrel[0] = v;
        delta = dnew;
        if (rs_law_call(law(), &F.b, &err) != RS_OK) {
            return NAN;
        }
        f = F.stress[0] * F.area[0];
        v += 0.5 * dt * f / m;
        if (delta <= 0.0 && i > 0) {
            return v / v0;
        }
    }
    return NAN;
}

static void test_hertz_restitution_matches_input(void)
{
    const double es[] = {0.3, 0.5, 0.7, 0.9};
    for (int i = 0; i < 4; ++i) {
        ENSURE_NEAR(measured_restitution(es[i], 1.0) / es[i], 1.0, 0.01);
        ENSURE_NEAR(measured_restitution(es[i], 0.2) / es[i], 1.0, 0.01);
    }
}

/* hertz declares that it writes every contact's stress, sfd, scd, spd and svd, and zeros
 * for fluxSlv, fluxMst, scd and spd (rs_law.sets): called directly, past rs_law_call's
 * zeroing, on a block of every kind of contact, with NaN in those outputs before the
 * call, in an increment and in a setup call. */
static void test_hertz_sets_what_it_declares(void)
{
    const rs_law *h = law();
    ENSURE(h->sets == (RS_LAW_SETS_ENERGIES | RS_LAW_SETS_NO_HEAT |
                       RS_LAW_SETS_NO_CREEP_PLASTIC | RS_LAW_SETS_STRESS));
    ENSURE(rs_law_stress_in(h) == 0);
    enum { N = 11 };
    static law_fix B;
    for (int setup = 0; setup < 2; setup++) {
        law_fix_init(&B, h, P, 7, N, 3);
        B.b.setup = setup;
        for (int k = 0; k < N; ++k) {
            mixed_contact(&B, k, k);
            B.sfd[k] = B.scd[k] = B.spd[k] = B.svd[k] = NAN;
            B.fluxSlv[k] = B.fluxMst[k] = NAN;
            B.stress[3 * k] = B.stress[3 * k + 1] = B.stress[3 * k + 2] = NAN;
        }
        rs_error err;
        ENSURE(h->update(h, &B.b, &err) == RS_OK);
        int set = 1, zero = 1, some = 0;
        for (int k = 0; k < N; ++k) {
            set &= isfinite(B.sfd[k]) && isfinite(B.svd[k]);
            for (int i = 0; i < 3; ++i)
                set &= isfinite(B.stress[3 * k + i]);
            zero &= B.scd[k] == 0.0 && B.spd[k] == 0.0;
            zero &= B.fluxSlv[k] == 0.0 && B.fluxMst[k] == 0.0;
            some += B.svd[k] > 0.0 || B.sfd[k] > 0.0;
        }
        ENSURE(set);
        ENSURE(zero);
        ENSURE(setup ? some == 0 : some > 0);
    }
}

int main(void)
{
    RS_RUN(test_hertz_plane_step_matches_liggghts_formulas);
    RS_RUN(test_hertz_stress_is_force_per_area);
    RS_RUN(test_hertz_friction_cap_resets_shear_to_limit);
    RS_RUN(test_hertz_drot_carries_shear_history);
    RS_RUN(test_hertz_curvature_flag_uses_reff);
    RS_RUN(test_hertz_open_contact_clears_history);
    RS_RUN(test_hertz_maxval_contact_gets_zero_force);
    RS_RUN(test_hertz_setup_call_does_not_advance_history);
    RS_RUN(test_hertz_block_equals_contacts_one_by_one);
    RS_RUN(test_hertz_restitution_matches_input);
    RS_RUN(test_hertz_sets_what_it_declares);
    return rs_test_summary();
}
