/* The UINTER and FRIC adapters in the explicit driver, against the built-ins:
 * - a node dropped on the 2D flat with the UINTER penalty hard contact follows the same
 *   trajectory as with linear_softening (round-off) and rebounds with its impact speed
 *   (a linear spring, to O((omega dt)^2));
 * - a node pressed onto the flat and dragged along it with FRIC Coulomb over
 *   linear_softening (kn = 1e6, from its equilibrium overlap) follows the built-in
 *   coulomb, and while slipping |tau| = mu p; the same with the FRIC given to the
 *   loader as its Fortran source (built into a fresh cache). */
#define _DEFAULT_SOURCE
#include "rigidsurf/driver.h"
#include "rs_test.h"

#include <stdlib.h>

#define NSTEP 800

static double ya[NSTEP], yb[NSTEP], ta[NSTEP], tb[NSTEP], pa[NSTEP], pb[NSTEP];

static int load_flat(rs_surface *s)
{
    rs_error err;
    char path[512];
    snprintf(path, sizeof path, "%s/flat2d.inp", RS_VUINTER_CASES_DIR);
    if (rs_surface_read(path, NULL, s, &err) != RS_OK) {
        fprintf(stderr, "%s\n", err.msg);
        return 0;
    }
    return 1;
}

typedef struct warn_count {
    int n;
} warn_count;

static void count_warning(void *ctx, const rs_law *law, int k, const char *msg)
{
    (void)law;
    (void)k;
    (void)msg;
    ((warn_count *)ctx)->n++;
}

/* mode 0: drop; mode 1: pressed and dragged. Records y, shear and pressure. */
static int run(const rs_law *law, const double *props, int nprops, int nstatev, int mode,
               double *y, double *tau, double *p, double *vy_end, int *warnings)
{
    rs_surface s;
    if (!load_flat(&s))
        return 0;
    rs_driver d;
    rs_error err;
    warn_count wc = {0};
    int ok = 0;
    if (rs_driver_init(&d, &s, 1, &err) ||
        rs_driver_set_law(&d, law, props, nprops, nstatev, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        goto done;
    }
    d.dt = 1e-5;
    d.tracking = 1e-3;
    d.mass[0] = 1e-3;
    d.warn = count_warning;
    d.warn_ctx = &wc;
    if (mode == 0) {
        d.y[0] = 2e-5;
        d.vy[0] = -0.1;
    } else {
        d.fext[1] = -5.0; /* pressed with 5 N, from its equilibrium overlap 5 N / kn:
                           * closed from the first call on, so FRIC's LM enters as 0
                           * (sliding) from the second, as coulomb's slip advances */
        d.y[0] = -5e-6;
        d.fixed[0] = 1;
        d.vpres[0] = 0.05;
    }
    for (int k = 0; k < NSTEP; ++k) {
        if (rs_driver_step(&d, &err)) {
            fprintf(stderr, "%s\n", err.msg);
            goto done;
        }
        y[k] = d.y[0];
        tau[k] = d.trk.n ? RS_A2(d.cb.stress, 2, 1, 0) : 0.0;
        p[k] = d.trk.n ? RS_A2(d.cb.stress, 2, 0, 0) : 0.0;
    }
    *vy_end = d.vy[0];
    *warnings = wc.n;
    ok = 1;
done:
    rs_driver_free(&d);
    rs_surface_free(&s);
    return ok;
}

static void test_uinter_penalty_drop_matches_linear_softening(void)
{
    rs_law ul;
    rs_error err;
    ENSURE(rs_law_load_uinter(RS_UINTER_PENALTY_LIB, NULL, &ul, &err) == RS_OK);
    const double k = 1e5;
    double lp[1] = {k}, up[3] = {k, 0.0, 0.0};
    double va, vb;
    int wa, wb;
    ENSURE(run(rs_law_find("linear_softening"), lp, 1, 0, 0, ya, ta, pa, &va, &wa));
    ENSURE(run(&ul, up, 3, ul.nstatev + 2, 0, yb, tb, pb, &vb, &wb));
    int contact_steps = 0;
    for (int i = 0; i < NSTEP; ++i) {
        ENSURE_NEAR(ya[i], yb[i], 1e-15);
        ENSURE_NEAR(pa[i], pb[i], 1e-12 * (1.0 + fabs(pa[i])));
        contact_steps += pa[i] > 0.0;
    }
    /* omega = sqrt(k A / m) = 1e4: contact lasts pi/omega = 31 increments */
    ENSURE(contact_steps >= 30 && contact_steps <= 33);
    ENSURE_REL(va, 0.1, 1e-2);
    ENSURE(va == vb && wa == 0 && wb == 0);
    rs_law_unload(&ul);
}

/* The same drop with a penalty ten times above the stable limit for dt is reported. */
static void test_uinter_unstable_penalty_is_reported(void)
{
    rs_law ul;
    rs_error err;
    ENSURE(rs_law_load_uinter(RS_UINTER_PENALTY_LIB, NULL, &ul, &err) == RS_OK);
    double up[3] = {4e8, 0.0, 0.0}; /* limit: 4 m / dt^2 = 4e7 */
    double v;
    int w;
    ENSURE(run(&ul, up, 3, ul.nstatev, 0, yb, tb, pb, &v, &w));
    ENSURE(w > 0);
    rs_law_unload(&ul);
}

static void fric_coulomb_drag(const char *lib)
{
    rs_law fl;
    rs_error err;
    const rs_law *lin = rs_law_find("linear_softening");
    const int rc = rs_law_load_fric(lib, lin, &fl, &err);
    if (rc)
        fprintf(stderr, "%s\n", err.msg);
    ENSURE(rc == RS_OK);
    const double mu = 0.3, ks = 2e6, kn = 1e6;
    double cp[3] = {mu, ks, kn}, fp[5] = {kn, mu, ks, 0.0, 0.0};
    double va, vb;
    int wa, wb;
    ENSURE(run(rs_law_find("coulomb"), cp, 3, 2, 1, ya, ta, pa, &va, &wa));
    ENSURE(run(&fl, fp, 5, fl.nstatev, 1, yb, tb, pb, &vb, &wb));
    int slipping = 0;
    for (int i = 0; i < NSTEP; ++i) {
        ENSURE_NEAR(ya[i], yb[i], 1e-12 * (1.0 + fabs(ya[i])));
        ENSURE_NEAR(pa[i], pb[i], 1e-9 * (1.0 + fabs(pa[i])));
        ENSURE_NEAR(ta[i], tb[i], 1e-9 * (1.0 + fabs(ta[i])));
        ENSURE(fabs(tb[i]) <= mu * pb[i] * (1.0 + 1e-12));
        if (fabs(fabs(tb[i]) - mu * pb[i]) <= 1e-12 * mu * pb[i] && pb[i] > 0.0)
            slipping++;
    }
    /* the drag outruns the stick spring: most increments slip at |tau| = mu p, and the
     * traction on the master points along the drag (+t1) */
    ENSURE(slipping > NSTEP / 2);
    ENSURE(tb[NSTEP - 1] > 0.0);
    rs_law_unload(&fl);
}

static void test_fric_coulomb_drag_matches_builtin(void)
{
    fric_coulomb_drag(RS_FRIC_COULOMB_LIB);
}

static void test_fric_from_source_in_driver(void)
{
    char cache[] = "/tmp/rs_driver_cache_XXXXXX";
    ENSURE(mkdtemp(cache) != NULL);
    setenv("RIGIDSURF_CACHE", cache, 1);
    fric_coulomb_drag(RS_FORTRAN_SRC_DIR "/fric_coulomb.f");
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", cache);
    ENSURE(system(cmd) == 0);
}

int main(void)
{
    RS_RUN(test_uinter_penalty_drop_matches_linear_softening);
    RS_RUN(test_uinter_unstable_penalty_is_reported);
    RS_RUN(test_fric_coulomb_drag_matches_builtin);
    RS_RUN(test_fric_from_source_in_driver);
    return rs_test_summary();
}
