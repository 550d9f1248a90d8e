/* The standalone explicit driver (driver.h) with built-in laws: the central-difference
 * update against its closed form, area-weighted energy totals, prescribed components,
 * and its argument errors. */
#include "rigidsurf/driver.h"
#include "rs_test.h"

#include <string.h>

static const char *flat = "*SURFACE, TYPE=SEGMENTS, NAME=FLAT\n"
                          "START, -10.0, 0.0\n"
                          "LINE, 10.0, 0.0\n";

/* Free flight under a constant force: v_{k+1/2} = v0 + (k+1) g dt and
 * x_k = x0 + k dt v0 + g dt^2 k (k+1) / 2 (central differences, exact). */
static void test_driver_central_difference_free_flight(void)
{
    rs_surface s;
    rs_driver d;
    rs_error err;
    ENSURE(rs_surface_parse(flat, "flat", NULL, &s, &err) == RS_OK);
    ENSURE(rs_driver_init(&d, &s, 1, &err) == RS_OK);
    double k[1] = {1e3};
    ENSURE(rs_driver_set_law(&d, rs_law_find("linear_softening"), k, 1, 0, &err) == RS_OK);
    d.dt = 1e-3;
    d.tracking = 0.01;
    d.mass[0] = 2.0;
    d.y[0] = 5.0;
    d.vx[0] = 0.5;
    d.vy[0] = 3.0;
    d.fext[1] = -2.0 * 9.81;
    int nk = 200;
    for (int i = 0; i < nk; ++i) {
        ENSURE(rs_driver_step(&d, &err) == RS_OK);
        ENSURE(d.trk.n == 0);
    }
    double dt = d.dt, g = -9.81;
    ENSURE_REL(d.vy[0], 3.0 + nk * g * dt, 1e-13);
    ENSURE_REL(d.y[0], 5.0 + nk * dt * 3.0 + g * dt * dt * nk * (nk + 1) / 2.0, 1e-13);
    ENSURE_REL(d.x[0], 0.5 * nk * dt, 1e-13);
    ENSURE_REL(d.t, nk * dt, 1e-15);
    ENSURE_REL(d.energy.allke, 0.5 * 2.0 * (0.25 + d.vy[0] * d.vy[0]), 1e-13);
    rs_driver_free(&d);
    rs_surface_free(&s);
}

/* ALLSE = sum over contacts of areaSlv sed; the contact force is areaSlv p n. */
static void test_driver_energy_totals_are_area_weighted(void)
{
    rs_surface s;
    rs_driver d;
    rs_error err;
    ENSURE(rs_surface_parse(flat, "flat", NULL, &s, &err) == RS_OK);
    ENSURE(rs_driver_init(&d, &s, 2, &err) == RS_OK);
    const double kn = 1e4;
    ENSURE(rs_driver_set_law(&d, rs_law_find("linear_softening"), &kn, 1, 0, &err) ==
           RS_OK);
    d.dt = 1e-4;
    d.tracking = 0.01;
    double h[2] = {1e-3, 2e-3}, a[2] = {2.0, 3.0};
    for (int i = 0; i < 2; ++i) {
        d.x[i] = i;
        d.y[i] = -h[i];
        d.area[i] = a[i];
        for (int c = 0; c < 3; ++c)
            d.fixed[3 * i + c] = 1;
    }
    ENSURE(rs_driver_step(&d, &err) == RS_OK);
    ENSURE(d.trk.n == 2);
    double se = 0.0;
    for (int i = 0; i < 2; ++i) {
        se += a[i] * 0.5 * kn * h[i] * h[i];
        ENSURE_REL(d.fcon[3 * i + 1], a[i] * kn * h[i], 1e-12);
        ENSURE_SMALL(d.fcon[3 * i], 1e-12);
    }
    ENSURE_REL(d.energy.allse, se, 1e-12);
    ENSURE(d.energy.allpd == 0.0 && d.energy.allfd == 0.0);
    rs_driver_free(&d);
    rs_surface_free(&s);
}

/* A law that writes the same stress and energies for every contact, a leaving one
 * (rdisp = RS_MAXVAL) too. */
static int constant_update(const rs_law *law, rs_law_block *b, rs_error *err)
{
    (void)law, (void)err;
    for (int k = 0; k < b->nSlvNod; ++k) {
        for (int c = 0; c < b->nDir; ++c)
            b->stress[k * b->nDir + c] = c == 0 ? 7.0 : 0.0;
        b->sed[k] = 1.0;
        b->sfd[k] = 0.5;
        b->fluxSlv[k] = b->fluxMst[k] = 0.0;
    }
    return RS_OK;
}

/* A contact that leaves applies nothing in the increment that reports it, whatever the
 * law writes for it, and counts in no energy total, as in the LIGGGHTS fix
 * (docs/coupling.md); the increments before it apply the law's stress. */
static void test_driver_leaving_contact_applies_nothing(void)
{
    rs_surface s;
    rs_driver d;
    rs_error err;
    ENSURE(rs_surface_parse(flat, "flat", NULL, &s, &err) == RS_OK);
    ENSURE(rs_driver_init(&d, &s, 1, &err) == RS_OK);
    rs_law law;
    memset(&law, 0, sizeof law);
    law.name = "constant";
    law.update = constant_update;
    ENSURE(rs_driver_set_law(&d, &law, NULL, 0, 0, &err) == RS_OK);
    d.dt = 1e-3;
    d.tracking = 0.01;
    d.y[0] = -1e-3;
    d.vy[0] = d.vpres[1] = 2.0; /* away from the floor, 2 mm an increment */
    for (int c = 0; c < 3; ++c)
        d.fixed[c] = 1;
    int live = 0, left = 0;
    double fd_before = 0.0;
    for (int i = 0; i < 12; ++i) {
        fd_before = d.energy.allfd;
        ENSURE(rs_driver_step(&d, &err) == RS_OK);
        if (d.trk.n == 0)
            continue;
        ENSURE(d.trk.n == 1);
        if (d.trk.nleave == 0) {
            live++;
            ENSURE(d.fcon[1] == 7.0 && d.energy.allse == 1.0);
        } else {
            left++;
            ENSURE(d.fcon[0] == 0.0 && d.fcon[1] == 0.0 && d.fcon[2] == 0.0);
            ENSURE(d.fwall[1] == 0.0 && d.energy.allse == 0.0);
            ENSURE(d.energy.allfd == fd_before);
        }
    }
    ENSURE(live >= 3 && left == 1);
    rs_driver_free(&d);
    rs_surface_free(&s);
}

static void test_driver_rejects_bad_setup(void)
{
    rs_surface s;
    rs_driver d;
    rs_error err;
    ENSURE(rs_surface_parse(flat, "flat", NULL, &s, &err) == RS_OK);
    ENSURE(rs_driver_init(&d, NULL, 1, &err) == RS_ERR_ARG);
    ENSURE(rs_driver_init(&d, &s, 0, &err) == RS_ERR_ARG);
    ENSURE(rs_driver_init(&d, &s, 1, &err) == RS_OK);
    ENSURE(rs_driver_step(&d, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "no law") != NULL);
    double bp[7] = {1e-4, 2e8, 0.3, 1e6, 2e7, 1e-3, 0.5};
    const rs_law *b = rs_law_find("bonded_interface");
    ENSURE(rs_driver_set_law(&d, b, bp, 7, 2, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "needs 3") != NULL);
    bp[1] = -1.0;
    ENSURE(rs_driver_set_law(&d, b, bp, 7, 3, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "'E'") != NULL);
    bp[1] = 2e8;
    ENSURE(rs_driver_set_law(&d, b, bp, 7, 3, &err) == RS_OK);
    ENSURE(rs_driver_step(&d, &err) == RS_ERR_ARG); /* dt not set */
    ENSURE(strstr(err.msg, "dt") != NULL);
    rs_driver_free(&d);
    rs_surface_free(&s);
}

int main(void)
{
    RS_RUN(test_driver_central_difference_free_flight);
    RS_RUN(test_driver_energy_totals_are_area_weighted);
    RS_RUN(test_driver_rejects_bad_setup);
    RS_RUN(test_driver_leaving_contact_applies_nothing);
    return rs_test_summary();
}
