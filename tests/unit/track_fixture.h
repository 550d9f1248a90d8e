/* The tracker's unit tests' fixtures (test_track.c, test_track_slots.c): a block of
 * particles and hand-built contact lists of closed-form planes, cylinders and circles, so
 * that every expected value is independent of the surface query; a tracker, its call on a
 * plane and a drum, and the checks of a rigid contact and of drot. */
#ifndef RS_TEST_TRACK_FIXTURE_H
#define RS_TEST_TRACK_FIXTURE_H

#include "rigidsurf/track.h"
#include "rs_test.h"
#include "rs_test_contacts.h"
#include "rs_test_geom.h"

#include <stdlib.h>

#define NS 2 /* state variables per contact in these tests */
#define HS RS_HIST_SIZE(NS)
#define CAP 4
#define MAXC RS_TEST_MAXC

/* ---- small vector helpers (the test's own) ---- */
static inline void axpy(double *y, double a, const double x[3], const double b[3])
{
    for (int i = 0; i < 3; i++)
        y[i] = b[i] + a * x[i];
}
/* A right-handed orthonormal frame n, t1, t2 = n x t1 from a normal and a hint. */
static inline void make_frame(const double nin[3], const double hint[3], double n[3],
                              double t1[3], double t2[3])
{
    for (int i = 0; i < 3; i++)
        n[i] = nin[i];
    unit(n);
    double h = rs_dot3(hint, n);
    for (int i = 0; i < 3; i++)
        t1[i] = hint[i] - h * n[i];
    unit(t1);
    rs_cross3(n, t1, t2);
}

/* ---- fixtures: a block of particles and a hand-built contact list ---- */
typedef struct block {
    double x[4], y[4], z[4], vx[4], vy[4], vz[4], wx[4], wy[4], wz[4], r[4];
    int id[4];
    double dir[4][CAP];
    double hist[4][CAP * HS];
    double *dp[4], *hp[4];
    rs_particles p;
} block;

static inline void block_init(block *b, int n, const rs_tracker *tr)
{
    memset(b, 0, sizeof *b);
    for (int i = 0; i < 4; i++) {
        b->dp[i] = b->dir[i];
        b->hp[i] = b->hist[i];
        b->id[i] = 100 + i;
        rs_track_clear(tr, b->dir[i], b->hist[i], 0);
    }
    b->p = (rs_particles){.n = n,
                          .x = b->x,
                          .y = b->y,
                          .z = b->z,
                          .vx = b->vx,
                          .vy = b->vy,
                          .vz = b->vz,
                          .wx = b->wx,
                          .wy = b->wy,
                          .wz = b->wz,
                          .radius = b->r,
                          .id = b->id,
                          .dir = b->dp,
                          .hist = b->hp};
}

static inline void block_set(block *b, int i, const double x[3], const double v[3],
                             const double w[3], double r)
{
    b->x[i] = x[0];
    b->y[i] = x[1];
    b->z[i] = x[2];
    b->vx[i] = v[0];
    b->vy[i] = v[1];
    b->vz[i] = v[2];
    b->wx[i] = w[0];
    b->wy[i] = w[1];
    b->wz[i] = w[2];
    b->r[i] = r;
}

/* Contact of a sphere centre x with the plane through P with unit normal n. */
static inline void add_plane(rs_test_clist *l, int point, int feature, const double x[3],
                             const double P[3], const double n[3], const double t1[3],
                             const double t2[3])
{
    double d[3] = {x[0] - P[0], x[1] - P[1], x[2] - P[2]}, xm[3];
    double dist = rs_dot3(d, n);
    axpy(xm, -dist, n, x);
    rs_test_clist_add(l, point, feature, xm, n, t1, t2, dist);
}

/* Contact of a point x inside a drum: cylinder through A along unit g, radius Rc. The
 * normal points inward (-e_r); CYLINDER frame t1 = g, t2 = n x t1. */
static inline void add_drum(rs_test_clist *l, int point, int feature, const double x[3],
                            const double A[3], const double g[3], double Rc)
{
    double d[3] = {x[0] - A[0], x[1] - A[1], x[2] - A[2]}, rad[3], n[3], t2[3], xm[3];
    double h = rs_dot3(d, g);
    axpy(rad, -h, g, d);
    double r = sqrt(rs_dot3(rad, rad));
    for (int i = 0; i < 3; i++) {
        n[i] = -rad[i] / r;
        xm[i] = A[i] + h * g[i] + Rc * rad[i] / r;
    }
    rs_cross3(n, g, t2);
    rs_test_clist_add(l, point, feature, xm, n, g, t2, Rc - r);
}

static inline rs_tracker tracker(int ndir)
{
    rs_tracker tr = {CAP, NS, ndir, 1e-3, 0};
    return tr;
}

static inline int drot_is(const rs_track_out *o, int e, double a, double b, double c,
                          double d, double tol)
{
    return fabs(RS_DROT(o->drot, 0, 0, e) - a) <= tol &&
           fabs(RS_DROT(o->drot, 0, 1, e) - b) <= tol &&
           fabs(RS_DROT(o->drot, 1, 0, e) - c) <= tol &&
           fabs(RS_DROT(o->drot, 1, 1, e) - d) <= tol;
}

/* The usual set-up of a test: a tracker (capacity CAP, NS state variables, tracking
 * 1e-3), a block of particles, a contact list and the tracker's output. */
typedef struct fixture {
    rs_tracker tr;
    block b;
    rs_test_clist l;
    rs_track_out o;
    rs_error err;
} fixture;

static inline void fixture_init(fixture *f, int ndir)
{
    memset(f, 0, sizeof *f);
    f->tr = tracker(ndir);
}

static inline void fixture_free(fixture *f)
{
    rs_track_out_free(&f->o);
}

/* One call of the tracker on the fixture's block and contact list. */
static inline int track_call(fixture *fx, const rs_surface *s, const rs_motion *m,
                             double dt)
{
    return rs_track_update(&fx->tr, s, m, dt, &fx->b.p, &fx->l.c, &fx->o, &fx->err);
}

/* Objectivity under rigid motion (docs/conventions.md, "drot"): one contact, drot = I,
 * no slip, the penetration kept. */
static inline void check_rigid_contact(const rs_track_out *o, double pen)
{
    ENSURE(o->n == 1);
    ENSURE(drot_is(o, 0, 1, 0, 0, 1, 1e-12));
    ENSURE_SMALL(RS_A2(o->rdisp, 3, 1, 0), 1e-12);
    ENSURE_SMALL(RS_A2(o->rdisp, 3, 2, 0), 1e-12);
    ENSURE_NEAR(RS_A2(o->rdisp, 3, 0, 0), pen, 1e-12);
}

/* One call with particle 0 inside the drum through A along unit g, radius Rc, as its only
 * contact, feature f: the contact list is rebuilt, the tracker run. */
static inline int drum_call(fixture *fx, const rs_motion *m, double dt, int feature,
                            const double x[3], const double A[3], const double g[3],
                            double Rc)
{
    rs_test_clist_init(&fx->l);
    add_drum(&fx->l, 0, feature, x, A, g, Rc);
    return track_call(fx, NULL, m, dt);
}

/* One call with particle 0 against the plane through P (normal n, tangents t1, t2) as
 * its only contact, feature f: the contact list is rebuilt, the tracker run. */
static inline int plane_call(fixture *fx, const rs_surface *s, const rs_motion *m,
                             double dt, int feature, const double x[3], const double P[3],
                             const double n[3], const double t1[3], const double t2[3])
{
    rs_test_clist_init(&fx->l);
    add_plane(&fx->l, 0, feature, x, P, n, t1, t2);
    return track_call(fx, s, m, dt);
}

#endif
