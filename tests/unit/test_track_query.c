/* The tracker fed by rs_surface_query on a REVOLUTION drum (docs/conventions.md, "rdisp,
 * drdisp, drot"): objectivity under the master's rigid motion, and history carried
 * across the tangent-continuous junctions of a filleted profile. Expected values are
 * closed forms of the drum geometry. */
#include "rigidsurf/track.h"
#include "rs_test.h"
#include "rs_test_geom.h"

#include <stdlib.h>

#define HS RS_HIST_SIZE(0)

/* Drum about local z through a = (0,0,0): bottom cap, mantle r = RD, top cap, corners
 * rounded with radius RF. Segments: 0 bottom cap, 1 fillet, 2 mantle, 3 fillet, 4 top. */
#define RD 0.15
#define HH 0.05
#define RF 0.02
static const char *drum_text = "*SURFACE, TYPE=REVOLUTION, NAME=drum, FILLET RADIUS=0.02\n"
                               "0, 0, 0, 0, 0, 1\n"
                               "START, 0, -0.05\n"
                               "LINE, 0.15, -0.05\n"
                               "LINE, 0.15, 0.05\n"
                               "LINE, 0, 0.05\n";

typedef struct one {
    double x, y, z, vx, vy, vz, wx, wy, wz, r;
    int id;
    double dir[4], hist[4 * HS];
    double *dp, *hp;
    rs_particles p;
    rs_query q;
} one;

static void one_init(one *o, const rs_tracker *tr, double radius)
{
    memset(o, 0, sizeof *o);
    o->r = radius;
    o->id = 7;
    o->dp = o->dir;
    o->hp = o->hist;
    rs_track_clear(tr, o->dir, o->hist, 0);
    o->p = (rs_particles){.n = 1,
                          .x = &o->x,
                          .y = &o->y,
                          .z = &o->z,
                          .vx = &o->vx,
                          .vy = &o->vy,
                          .vz = &o->vz,
                          .wx = &o->wx,
                          .wy = &o->wy,
                          .wz = &o->wz,
                          .radius = &o->r,
                          .id = &o->id,
                          .dir = &o->dp,
                          .hist = &o->hp};
    o->q = (rs_query){.n = 1,
                      .slave = {.x = &o->x, .y = &o->y, .z = &o->z, .radius = &o->r},
                      .pose = NULL,
                      .gap_max = tr->tracking,
                      .dist_min = -INFINITY};
}

/* The drum turns about an axis that is not its own and translates; the sphere sits on
 * the mantle and moves (and spins) with the master's material motion. Through the real
 * query and frame, drot = I to 1e-12 and no slip accumulates. */
static void test_drot_identity_rigid_motion_through_revolution_query(void)
{
    rs_tracker tr = {4, 0, 3, 1e-3, 0};
    rs_surface s;
    rs_contacts c = {0};
    rs_track_out out = {0};
    rs_motion m;
    rs_error err;
    one o;
    ENSURE(rs_surface_parse(drum_text, "test_track_query", NULL, &s, &err) == RS_OK);
    ENSURE(rs_contacts_reserve(&c, 4, &err) == RS_OK);
    double axis[3] = {0.4, -0.3, 0.8}, C[3] = {0.05, -0.1, 0.02},
           V[3] = {0.02, 0.01, -0.03};
    const double omega = 2.5, dt = 1e-3, R = 0.004, pen = 1e-4;
    rs_motion_init(&m);
    rs_motion_set_translation(&m, V);
    ENSURE(rs_motion_set_rotation(&m, C, axis, omega, &err) == RS_OK);
    double al = sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    double W[3] = {omega * axis[0] / al, omega * axis[1] / al, omega * axis[2] / al};
    /* Reference centre: on the mantle at azimuth 0.7, height 0.01, depth pen. */
    const double rho = RD - R + pen;
    double X0[3] = {rho * cos(0.7), rho * sin(0.7), 0.01};
    one_init(&o, &tr, R);
    o.q.pose = &m.pose;
    for (int step = 1; step <= 1500; step++) {
        ENSURE(rs_motion_advance(&m, dt, &err) == RS_OK);
        double x[3], d[3], wd[3], t = step * dt;
        rs_pose_to_global(&m.pose, X0, x);
        for (int i = 0; i < 3; i++)
            d[i] = x[i] - (C[i] + V[i] * t);
        rs_cross3(W, d, wd);
        o.x = x[0];
        o.y = x[1];
        o.z = x[2];
        o.vx = V[0] + wd[0];
        o.vy = V[1] + wd[1];
        o.vz = V[2] + wd[2];
        o.wx = W[0];
        o.wy = W[1];
        o.wz = W[2];
        c.n = 0;
        ENSURE(rs_surface_query(&s, &o.q, &c, &err) == RS_OK);
        ENSURE(c.n == 1 && c.feature[0] == RS_FEATURE(RS_FEAT_FACE, 2));
        ENSURE(rs_track_update(&tr, &s, &m, dt, &o.p, &c, &out, &err) == RS_OK);
        ENSURE(out.n == 1);
        for (int i = 0; i < 2; i++)
            for (int j = 0; j < 2; j++)
                ENSURE_NEAR(RS_DROT(out.drot, i, j, 0), i == j, 1e-12);
        ENSURE_SMALL(RS_A2(out.rdisp, 3, 1, 0), 1e-12);
        ENSURE_SMALL(RS_A2(out.rdisp, 3, 2, 0), 1e-12);
        ENSURE_NEAR(RS_A2(out.rdisp, 3, 0, 0), pen, 1e-12);
        rs_track_commit(&tr, &out, NULL, NULL);
    }
    rs_track_out_free(&out);
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* Centre of a sphere at depth pen sliding along the drum's bottom cap, round the fillet
 * and up the mantle, at arc length sc along the centre path; tangent (tr, tz) in (r, z).
 * The centre path is offset d = R - pen inward: cap z = -HH + d; fillet about
 * (RD - RF, -HH + RF) with radius RF - d; mantle r = RD - d. */
static void path_point(double sc, double d, double *r, double *z, double *tr, double *tz)
{
    const double r0 = 0.1, L1 = (RD - RF) - r0,
                 L2 = (RF - d) * 0.5 * 3.14159265358979323846;
    if (sc < L1) {
        *r = r0 + sc;
        *z = -HH + d;
        *tr = 1.0;
        *tz = 0.0;
    } else if (sc < L1 + L2) {
        double phi = (sc - L1) / (RF - d);
        *r = RD - RF + (RF - d) * sin(phi);
        *z = -HH + RF - (RF - d) * cos(phi);
        *tr = cos(phi);
        *tz = sin(phi);
    } else {
        *r = RD - d;
        *z = -HH + RF + (sc - L1 - L2);
        *tr = 0.0;
        *tz = 1.0;
    }
}

/* Sliding over cap -> fillet -> mantle: the contact's feature changes FACE 0 -> 1 -> 2
 * across SMOOTH vertices, the slot and its history stay, nothing leaves (no 1e30), drot
 * = I (the normal turns about the hoop direction, and P follows it), and the slip is the
 * whole distance slid: t1 = t2 x n is the direction of travel along the profile, so
 * v . t1 = u and slip = (N - 1) u dt after N calls (the first opens the contact). */
static void test_history_handover_across_fillet(void)
{
    rs_tracker tr = {4, 0, 3, 1e-3, 0};
    rs_surface s;
    rs_contacts c = {0};
    rs_track_out out = {0};
    rs_error err;
    one o;
    ENSURE(rs_surface_parse(drum_text, "test_track_query", NULL, &s, &err) == RS_OK);
    ENSURE(rs_contacts_reserve(&c, 4, &err) == RS_OK);
    const double R = 0.004, pen = 2e-4, d = R - pen, u = 0.5, dt = 1e-4, th = 1.1;
    one_init(&o, &tr, R);
    const int N = 1600; /* 0.08 of path: 0.03 cap, 0.0254 fillet, 0.0246 mantle */
    double *slot = NULL;
    int seen = 0;
    for (int step = 0; step < N; step++) {
        double r, z, tr_, tz;
        path_point(step * u * dt, d, &r, &z, &tr_, &tz);
        o.x = r * cos(th);
        o.y = r * sin(th);
        o.z = z;
        o.vx = u * tr_ * cos(th);
        o.vy = u * tr_ * sin(th);
        o.vz = u * tz;
        c.n = 0;
        ENSURE(rs_surface_query(&s, &o.q, &c, &err) == RS_OK);
        ENSURE(c.n == 1);
        int f = c.feature[0];
        ENSURE(f == RS_FEATURE(RS_FEAT_FACE, 0) || f == RS_FEATURE(RS_FEAT_FACE, 1) ||
               f == RS_FEATURE(RS_FEAT_FACE, 2));
        seen |= 1 << RS_FEATURE_INDEX(f);
        ENSURE(rs_track_update(&tr, &s, NULL, dt, &o.p, &c, &out, &err) == RS_OK);
        ENSURE(out.n == 1 && out.feature[0] == f);
        if (!slot)
            slot = out.slot[0];
        ENSURE(out.slot[0] == slot);
        ENSURE(RS_A2(out.rdisp, 3, 0, 0) < 1.0);
        for (int i = 0; i < 2; i++)
            for (int j = 0; j < 2; j++)
                ENSURE_NEAR(RS_DROT(out.drot, i, j, 0), i == j, 1e-12);
        ENSURE_NEAR(RS_A2(out.rdisp, 3, 0, 0), pen, 1e-12);
        ENSURE_NEAR(RS_A2(out.rdisp, 3, 1, 0), (step + 1) * u * dt, 1e-12);
        ENSURE_SMALL(RS_A2(out.rdisp, 3, 2, 0), 1e-12);
        rs_track_commit(&tr, &out, NULL, NULL);
    }
    ENSURE(seen == 7);
    rs_track_out_free(&out);
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

int main(void)
{
    RS_RUN(test_drot_identity_rigid_motion_through_revolution_query);
    RS_RUN(test_history_handover_across_fillet);
    return rs_test_summary();
}
