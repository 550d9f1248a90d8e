/* The contact tracker's slots (track.h; docs/conventions.md, "rdisp, drdisp, drot"): a
 * contact's maximum kept once after it leaves, leaving beyond the tracking thickness and
 * between held contacts, history handed over across a smooth junction, the capacity's
 * error, two directions, drdisp(1), the local directions and contact point, the slots'
 * layouts, unordered contacts refused, and a block against one contact at a time.
 * Contacts are built by hand (track_fixture.h). */
#include "track_fixture.h"

/* A contact that disappears is emitted exactly once with 1e30 in every entry of rdisp,
 * drdisp and drot, then never again: after commit, and also when commit is skipped. */
static void test_maxval_once_after_leaving(void)
{
    fixture fx;
    fixture_init(&fx, 3);
    double n[3] = {0, 0, 1}, t1[3] = {1, 0, 0}, t2[3] = {0, 1, 0}, P[3] = {0, 0, 0};
    double x[3] = {0, 0, 0.0095}, zero[3] = {0, 0, 0};
    const int f = RS_FEATURE(RS_FEAT_FACE, 2);
    for (int with_commit = 0; with_commit < 2; with_commit++) {
        block_init(&fx.b, 1, &fx.tr);
        block_set(&fx.b, 0, x, zero, zero, 0.01);
        ENSURE(plane_call(&fx, NULL, NULL, 1e-3, f, x, P, n, t1, t2) == RS_OK);
        rs_track_commit(&fx.tr, &fx.o, NULL, NULL);
        fx.l.c.n = 0;
        ENSURE(track_call(&fx, NULL, NULL, 1e-3) == RS_OK);
        ENSURE(fx.o.n == 1);
        ENSURE(fx.o.point[0] == 0 && fx.o.feature[0] == f);
        for (int i = 0; i < 3; i++) {
            ENSURE(RS_A2(fx.o.rdisp, 3, i, 0) == 1.0e30);
            ENSURE(RS_A2(fx.o.drdisp, 3, i, 0) == 1.0e30);
        }
        for (int i = 0; i < 2; i++)
            for (int j = 0; j < 2; j++)
                ENSURE(RS_DROT(fx.o.drot, i, j, 0) == 1.0e30);
        ENSURE(*fx.o.dir[0] == RS_DIR_LEAVING(f) && fx.o.dir[0] == &fx.b.dir[0][0]);
        if (with_commit) {
            rs_track_commit(&fx.tr, &fx.o, NULL, NULL);
            ENSURE(fx.b.dir[0][0] == RS_DIR_EMPTY);
        }
        ENSURE(track_call(&fx, NULL, NULL, 1e-3) == RS_OK);
        ENSURE(fx.o.n == 0);
        for (int j = 0; j < CAP; j++)
            ENSURE(fx.b.dir[0][j] == RS_DIR_EMPTY);
    }
    fixture_free(&fx);
}

/* A contact whose gap exceeds the tracking thickness counts as gone. */
static void test_contact_beyond_tracking_leaves(void)
{
    fixture fx;
    fixture_init(&fx, 3);
    double n[3] = {0, 0, 1}, t1[3] = {1, 0, 0}, t2[3] = {0, 1, 0}, P[3] = {0, 0, 0};
    double x[3] = {0, 0, 0.0095}, zero[3] = {0, 0, 0};
    block_init(&fx.b, 1, &fx.tr);
    block_set(&fx.b, 0, x, zero, zero, 0.01);
    ENSURE(plane_call(&fx, NULL, NULL, 1e-3, 0, x, P, n, t1, t2) == RS_OK);
    rs_track_commit(&fx.tr, &fx.o, NULL, NULL);
    x[2] = 0.01 + 0.9e-3; /* gap 0.9e-3 <= tracking 1e-3: kept */
    ENSURE(plane_call(&fx, NULL, NULL, 1e-3, 0, x, P, n, t1, t2) == RS_OK);
    ENSURE(fx.o.n == 1 && RS_A2(fx.o.rdisp, 3, 0, 0) < 0 &&
           RS_A2(fx.o.rdisp, 3, 0, 0) > -1e-3);
    rs_track_commit(&fx.tr, &fx.o, NULL, NULL);
    x[2] = 0.01 + 1.1e-3; /* gap 1.1e-3 > tracking */
    ENSURE(plane_call(&fx, NULL, NULL, 1e-3, 0, x, P, n, t1, t2) == RS_OK);
    ENSURE(fx.o.n == 1 && RS_A2(fx.o.rdisp, 3, 0, 0) == RS_MAXVAL);
    fixture_free(&fx);
}

/* Three particles, one plane contact each; then the middle one's gap exceeds the
 * tracking thickness while its contact is still listed. That block has as many entries
 * as contacts (particle 1's contact is dropped, its slot leaves), but entry 1 is the
 * leaving slot, not contact 1: it gets RS_MAXVAL, and the others keep their own
 * penetration R - dist and the frame of their contact. */
static void test_leaving_slot_between_held_contacts(void)
{
    fixture fx;
    fixture_init(&fx, 3);
    double n[3] = {0, 0, 1}, t1[3] = {1, 0, 0}, t2[3] = {0, 1, 0}, P[3] = {0, 0, 0};
    double zero[3] = {0, 0, 0};
    const double R = 0.01, z[3] = {0.0095, 0.0097, 0.0099};
    block_init(&fx.b, 3, &fx.tr);
    for (int step = 0; step < 3; step++) {
        rs_test_clist_init(&fx.l);
        for (int i = 0; i < 3; i++) {
            /* step 2: particle 1 at gap 1.1e-3 > tracking 1e-3 */
            double x[3] = {0.1 * i, 0, step == 2 && i == 1 ? R + 1.1e-3 : z[i]};
            block_set(&fx.b, i, x, zero, zero, R);
            add_plane(&fx.l, i, RS_FEATURE(RS_FEAT_FACE, 0), x, P, n, t1, t2);
        }
        ENSURE(track_call(&fx, NULL, NULL, 1e-3) == RS_OK);
        ENSURE(fx.o.n == 3);
        for (int e = 0; e < 3; e++) {
            ENSURE(fx.o.point[e] == e);
            if (step == 2 && e == 1) {
                ENSURE(*fx.o.dir[e] == RS_DIR_LEAVING(RS_FEATURE(RS_FEAT_FACE, 0)));
                for (int a = 0; a < 3; a++)
                    ENSURE(RS_A2(fx.o.rdisp, 3, a, e) == RS_MAXVAL);
                continue;
            }
            ENSURE(fabs(RS_A2(fx.o.rdisp, 3, 0, e) - (R - z[e])) <= 1e-15);
            for (int a = 0; a < 3; a++) {
                ENSURE(RS_A3(fx.o.alocaldir, 3, a, 0, e) == n[a]);
                ENSURE(RS_A3(fx.o.alocaldir, 3, a, 1, e) == t1[a]);
            }
        }
        ENSURE(fx.o.nleave == (step == 2));
        rs_track_commit(&fx.tr, &fx.o, NULL, NULL);
    }
    fixture_free(&fx);
}

/* Fixture surface kind: features FACE 0 and FACE 1 meet tangentially; FACE 2 does not. */
static int fixture_adjacent(const rs_surface *s, int fa, int fb)
{
    (void)s;
    int a = RS_FEATURE(RS_FEAT_FACE, 0), b = RS_FEATURE(RS_FEAT_FACE, 1);
    return (fa == a && fb == b) || (fa == b && fb == a);
}

static const rs_surface_ops fixture_ops = {
    .name = "fixture", .ndir = 3, .frame = RS_FRAME_GLOBAL_X, .adjacent = fixture_adjacent};

/* History (slot, slip, stress, statev) carries across a smooth junction; across a sharp
 * one the old contact leaves (1e30) and the new one starts from zero. */
static void test_history_handover_across_smooth_junction(void)
{
    fixture fx;
    fixture_init(&fx, 3);
    rs_surface surf;
    memset(&surf, 0, sizeof surf);
    surf.kind = RS_SURF_FACETED;
    surf.ops = &fixture_ops;
    double n[3] = {0, 0, 1}, t1[3] = {1, 0, 0}, t2[3] = {0, 1, 0}, P[3] = {0, 0, 0};
    double x[3] = {0, 0, 0.0099}, v[3] = {0.2, 0.1, 0}, zero[3] = {0, 0, 0};
    const double dt = 1e-3;
    const int fa = RS_FEATURE(RS_FEAT_FACE, 0), fb = RS_FEATURE(RS_FEAT_FACE, 1),
              fc = RS_FEATURE(RS_FEAT_FACE, 2);
    const double stress[3] = {5, 6, 7}, statev[NS] = {8, 9};

    for (int sharp = 0; sharp < 2; sharp++) {
        block_init(&fx.b, 1, &fx.tr);
        block_set(&fx.b, 0, x, v, zero, 0.01);
        for (int call = 0; call < 3; call++) {
            ENSURE(plane_call(&fx, &surf, NULL, dt, fa, x, P, n, t1, t2) == RS_OK);
            ENSURE(fx.o.n == 1);
            rs_track_commit(&fx.tr, &fx.o, stress, statev);
        }
        double *slot = fx.o.slot[0];
        ENSURE(plane_call(&fx, &surf, NULL, dt, sharp ? fc : fb, x, P, n, t1, t2) == RS_OK);
        if (!sharp) {
            ENSURE(fx.o.n == 1);
            ENSURE(fx.o.slot[0] == slot && fx.o.feature[0] == fb);
            ENSURE(*fx.o.dir[0] == RS_DIR_LIVE(fb));
            ENSURE_NEAR(RS_A2(fx.o.rdisp, 3, 1, 0), 4 * 0.2 * dt, 1e-15);
            ENSURE_NEAR(RS_A2(fx.o.rdisp, 3, 2, 0), 4 * 0.1 * dt, 1e-15);
            ENSURE(slot[RS_H_STRESS] == 5 && slot[RS_H_STRESS + 2] == 7);
            ENSURE(slot[RS_H_STATEV] == 8 && slot[RS_H_STATEV + 1] == 9);
        } else {
            ENSURE(fx.o.n == 2);
            ENSURE(fx.o.feature[0] == fc && fx.o.slot[0] != slot);
            /* fresh history: the slip is this call's increment only */
            ENSURE_NEAR(RS_A2(fx.o.rdisp, 3, 1, 0), 0.2 * dt, 1e-15);
            ENSURE_NEAR(RS_A2(fx.o.rdisp, 3, 2, 0), 0.1 * dt, 1e-15);
            ENSURE(fx.o.slot[0][RS_H_STRESS] == 0 && fx.o.slot[0][RS_H_STATEV + 1] == 0);
            ENSURE(fx.o.feature[1] == fa && fx.o.slot[1] == slot);
            ENSURE(RS_A2(fx.o.rdisp, 3, 0, 1) == RS_MAXVAL);
        }
    }
    fixture_free(&fx);
}

/* More contacts than slots: RS_ERR_CAPACITY naming the particle's id and the capacity,
 * and history untouched. A leaving contact still holds its slot on that call. */
static void test_capacity_error_names_particle(void)
{
    fixture fx;
    fixture_init(&fx, 3);
    fx.tr.capacity = 2;
    double n[3] = {0, 0, 1}, t1[3] = {1, 0, 0}, t2[3] = {0, 1, 0}, P[3] = {0, 0, 0};
    double x[3] = {0, 0, 0.0099}, zero[3] = {0, 0, 0};
    block_init(&fx.b, 2, &fx.tr);
    fx.b.id[1] = 4711;
    block_set(&fx.b, 0, x, zero, zero, 0.01);
    block_set(&fx.b, 1, x, zero, zero, 0.01);
    rs_test_clist_init(&fx.l);
    add_plane(&fx.l, 0, 0, x, P, n, t1, t2);
    add_plane(&fx.l, 1, 0, x, P, n, t1, t2);
    ENSURE(track_call(&fx, NULL, NULL, 1e-3) == RS_OK);
    rs_track_commit(&fx.tr, &fx.o, NULL, NULL);

    double before[2][CAP * HS], dbefore[2][CAP];
    memcpy(before, fx.b.hist, sizeof before);
    memcpy(dbefore, fx.b.dir, sizeof dbefore);
    /* Particle 4711: feature 0 leaves, features 4 and 8 arrive: 3 slots needed, 2 held. */
    rs_test_clist_init(&fx.l);
    add_plane(&fx.l, 0, 0, x, P, n, t1, t2);
    add_plane(&fx.l, 1, 4, x, P, n, t1, t2);
    add_plane(&fx.l, 1, 8, x, P, n, t1, t2);
    ENSURE(track_call(&fx, NULL, NULL, 1e-3) == RS_ERR_CAPACITY);
    ENSURE(fx.err.code == RS_ERR_CAPACITY);
    ENSURE(strstr(fx.err.msg, "4711") != NULL);
    ENSURE(strstr(fx.err.msg, "capacity 2") != NULL);
    ENSURE(memcmp(before, fx.b.hist, sizeof before) == 0);
    ENSURE(memcmp(dbefore, fx.b.dir, sizeof dbefore) == 0);

    /* Three new contacts at once for a fresh particle. */
    block_init(&fx.b, 1, &fx.tr);
    fx.b.id[0] = 99;
    block_set(&fx.b, 0, x, zero, zero, 0.01);
    rs_test_clist_init(&fx.l);
    for (int f = 0; f < 3; f++)
        add_plane(&fx.l, 0, RS_FEATURE(RS_FEAT_FACE, f), x, P, n, t1, t2);
    ENSURE(track_call(&fx, NULL, NULL, 1e-3) == RS_ERR_CAPACITY);
    ENSURE(strstr(fx.err.msg, "99") != NULL);
    fixture_free(&fx);
}

/* nDir = 2 (SEGMENTS): a disc rolling-free sliding inside a fixed circular wall in the
 * x-y plane. The normal turns with the position but drot = I; t1 = (0,0,-1) x n = e_theta,
 * so a counter-clockwise speed u slides +u dt per call; alocaldir is 2x2 (n, t1). */
static void test_ndir2_drot_identity(void)
{
    fixture fx;
    fixture_init(&fx, 2);
    const double Rw = 1.0, R = 0.05, pen = 1e-4, u = 0.6, dt = 1e-3;
    const double rho = Rw - R + pen, om = u / rho, mz[3] = {0, 0, -1}, zero[3] = {0, 0, 0};
    block_init(&fx.b, 1, &fx.tr);
    const int N = 800;
    for (int step = 0; step < N; step++) {
        double a = om * step * dt, er[3] = {cos(a), sin(a), 0};
        double x[3] = {rho * er[0], rho * er[1], 0}, v[3] = {-u * er[1], u * er[0], 0};
        double n[3] = {-er[0], -er[1], 0}, t1[3], xm[3] = {Rw * er[0], Rw * er[1], 0};
        rs_cross3(mz, n, t1);
        block_set(&fx.b, 0, x, v, zero, R);
        rs_test_clist_init(&fx.l);
        rs_test_clist_add(&fx.l, 0, RS_FEATURE(RS_FEAT_FACE, 0), xm, n, t1, mz, Rw - rho);
        ENSURE(track_call(&fx, NULL, NULL, dt) == RS_OK);
        ENSURE(fx.o.n == 1 && fx.o.ndir == 2);
        ENSURE(drot_is(&fx.o, 0, 1, 0, 0, 1, 0.0));
        ENSURE_NEAR(RS_A3(fx.o.alocaldir, 2, 0, 0, 0), n[0], 1e-15);
        ENSURE_NEAR(RS_A3(fx.o.alocaldir, 2, 1, 0, 0), n[1], 1e-15);
        ENSURE_NEAR(RS_A3(fx.o.alocaldir, 2, 0, 1, 0), -er[1], 1e-15);
        ENSURE_NEAR(RS_A3(fx.o.alocaldir, 2, 1, 1, 0), er[0], 1e-15);
        ENSURE_NEAR(RS_A2(fx.o.rdisp, 2, 0, 0), pen, 1e-12);
        ENSURE_NEAR(RS_A2(fx.o.rdisp, 2, 1, 0), (step + 1) * u * dt, 1e-12);
        ENSURE_NEAR(RS_A2(fx.o.coordmst, 2, 0, 0), xm[0], 1e-15);
        ENSURE_NEAR(RS_A2(fx.o.coordmst, 2, 1, 0), xm[1], 1e-15);
        rs_track_commit(&fx.tr, &fx.o, NULL, NULL);
    }
    fixture_free(&fx);
}

/* drdisp(1) is the change of rdisp(1) since the last call; on the first call it is
 * -v_rel.n dt. Particle at -0.2 n, plane moving +0.3 n: penetration grows 0.5 per time. */
static void test_drdisp1_is_change_of_penetration(void)
{
    fixture fx;
    fixture_init(&fx, 3);
    rs_motion m;
    double nin[3] = {1, 1, 1}, hint[3] = {0, 0, 1}, n[3], t1[3], t2[3], zero[3] = {0, 0, 0};
    const double R = 0.02, d0 = 1e-4, dt = 1e-4;
    make_frame(nin, hint, n, t1, t2);
    double P0[3] = {0.1, 0.1, 0.1}, x0[3], u[3], V[3];
    axpy(x0, R - d0, n, P0);
    for (int i = 0; i < 3; i++) {
        u[i] = -0.2 * n[i] + 0.05 * t2[i];
        V[i] = 0.3 * n[i];
    }
    rs_motion_init(&m);
    rs_motion_set_translation(&m, V);
    block_init(&fx.b, 1, &fx.tr);
    for (int step = 1; step <= 50; step++) {
        ENSURE(rs_motion_advance(&m, dt, &fx.err) == RS_OK);
        double x[3], P[3];
        axpy(x, step * dt, u, x0);
        axpy(P, step * dt, V, P0);
        block_set(&fx.b, 0, x, u, zero, R);
        ENSURE(plane_call(&fx, NULL, &m, dt, 0, x, P, n, t1, t2) == RS_OK);
        ENSURE(fx.o.n == 1);
        ENSURE_NEAR(RS_A2(fx.o.rdisp, 3, 0, 0), d0 + 0.5 * step * dt, 1e-14);
        ENSURE_NEAR(RS_A2(fx.o.drdisp, 3, 0, 0), 0.5 * dt, 1e-14);
        ENSURE_NEAR(RS_A2(fx.o.vrel, 3, 0, 0), -0.5, 1e-14);
        rs_track_commit(&fx.tr, &fx.o, NULL, NULL);
    }
    fixture_free(&fx);
}

/* alocaldir columns are n, t1, t2 (component i of direction j at RS_A3(a, 3, i, j, k));
 * coordslv is x_cp = x - (R - rdisp1/2) n and coordmst the master point; curvatures are
 * copied. Two particles, the first with two contacts (a concave corner). */
static void test_alocaldir_columns_and_contact_point(void)
{
    fixture fx;
    fixture_init(&fx, 3);
    double na[3] = {0, 0, 1}, nb[3] = {1, 0, 0}, hint[3] = {0, 1, 0}, zero[3] = {0, 0, 0};
    double fr[2][3][3], P[3] = {0, 0, 0};
    make_frame(na, hint, fr[0][0], fr[0][1], fr[0][2]);
    make_frame(nb, hint, fr[1][0], fr[1][1], fr[1][2]);
    const double R = 0.01, x0[3] = {0.0098, 0.3, 0.0097}, x1[3] = {0.5, 0.5, 0.0095};
    block_init(&fx.b, 2, &fx.tr);
    block_set(&fx.b, 0, x0, zero, zero, R);
    block_set(&fx.b, 1, x1, zero, zero, R);
    rs_test_clist_init(&fx.l);
    add_plane(&fx.l, 0, 0, x0, P, fr[0][0], fr[0][1], fr[0][2]);
    add_plane(&fx.l, 0, 4, x0, P, fr[1][0], fr[1][1], fr[1][2]);
    add_plane(&fx.l, 1, 0, x1, P, fr[0][0], fr[0][1], fr[0][2]);
    fx.l.curv[0][1] = -2.0;
    fx.l.curv[1][1] = 0.5;
    ENSURE(track_call(&fx, NULL, NULL, 1e-3) == RS_OK);
    ENSURE(fx.o.n == 3);
    const int fk[3] = {0, 1, 0};
    const double *xs[3] = {x0, x0, x1};
    const double pen[3] = {R - x0[2], R - x0[0], R - x1[2]};
    for (int e = 0; e < 3; e++) {
        ENSURE_NEAR(RS_A2(fx.o.rdisp, 3, 0, e), pen[e], 1e-15);
        for (int j = 0; j < 3; j++)
            for (int i = 0; i < 3; i++)
                ENSURE(RS_A3(fx.o.alocaldir, 3, i, j, e) == fr[fk[e]][j][i]);
        for (int i = 0; i < 3; i++) {
            double xcp = xs[e][i] - (R - 0.5 * pen[e]) * fr[fk[e]][0][i];
            double xm = xs[e][i] - (R - pen[e]) * fr[fk[e]][0][i];
            ENSURE_NEAR(RS_A2(fx.o.coordslv, 3, i, e), xcp, 1e-15);
            ENSURE_NEAR(RS_A2(fx.o.coordmst, 3, i, e), xm, 1e-15);
        }
    }
    ENSURE(fx.o.point[0] == 0 && fx.o.point[1] == 0 && fx.o.point[2] == 1);
    ENSURE(RS_A2(fx.o.curv, 2, 0, 1) == -2.0 && RS_A2(fx.o.curv, 2, 1, 1) == 0.5);
    ENSURE(fx.o.slot[0] != fx.o.slot[1]);
    /* A new contact's history starts at zero stress and statev. */
    ENSURE(fx.o.slot[2][RS_H_STRESS] == 0 && fx.o.slot[2][RS_H_STATEV] == 0);
    fixture_free(&fx);
}

/* The slots may sit anywhere the caller likes (rs_particles.slot_stride): slot j of every
 * particle in one array gives, step for step, the same outputs, loads and stored history
 * as slots kept together per particle, and a particle that never holds two contacts at
 * once never touches its slots 1 .. capacity-1 (they keep a NaN pattern written by the
 * test). Random contacts open, move, turn and leave over 60 steps. */
static void test_slot_major_layout_matches_contiguous(void)
{
    enum { NP = 3 };
    const ptrdiff_t stride = (ptrdiff_t)NP * HS;
    rs_tracker tr = tracker(3);
    block a, b;
    double dirb[NP][CAP], histb[CAP * NP * HS], nanpat[HS];
    double *dpb[NP], *hpb[NP];
    memset(nanpat, 0xff, sizeof nanpat);
    block_init(&a, NP, &tr);
    block_init(&b, NP, &tr);
    for (int i = 0; i < NP; i++) {
        dpb[i] = dirb[i];
        hpb[i] = histb + (size_t)i * HS;
        rs_track_clear(&tr, dpb[i], hpb[i], stride);
        for (int j = 1; j < CAP; j++)
            memcpy(hpb[i] + j * stride, nanpat, sizeof nanpat);
    }
    b.p.dir = dpb;
    b.p.hist = hpb;
    b.p.slot_stride = stride;
    rs_track_out oa = {0}, ob = {0};
    rs_error err;
    unsigned long long rng = 0x5eed1234abcdULL;
    int mismatch = 0, steps_with_contacts = 0, leaving_seen = 0;
    for (int step = 0; step < 60; step++) {
        rs_test_clist l;
        rs_test_clist_init(&l);
        for (int i = 0; i < NP; i++) {
            /* particle 0: feature 2 on or off; the others up to three of 0, 2, 4, 6 */
            int nf = 0, feats[3];
            if (i == 0) {
                if (rs_test_urand(&rng) < 0.7)
                    feats[nf++] = 2;
            } else {
                for (int f = 0; f < 8 && nf < 3; f += 2)
                    if (rs_test_urand(&rng) < 0.5)
                        feats[nf++] = f;
            }
            double x[3] = {0.1 * i, 0.01 * step, 0.0095}, v[3], w[3];
            for (int d = 0; d < 3; d++) {
                v[d] = rs_test_urand(&rng) - 0.5;
                w[d] = 10.0 * (rs_test_urand(&rng) - 0.5);
            }
            block_set(&a, i, x, v, w, 0.01);
            block_set(&b, i, x, v, w, 0.01);
            for (int q = 0; q < nf; q++) {
                double nin[3] = {0.2 * (rs_test_urand(&rng) - 0.5),
                                 0.2 * (rs_test_urand(&rng) - 0.5), 1.0};
                const double hint[3] = {1, 0, 0}, P[3] = {0, 0, 0};
                double n[3], t1[3], t2[3];
                make_frame(nin, hint, n, t1, t2);
                add_plane(&l, i, feats[q], x, P, n, t1, t2);
            }
        }
        ENSURE(rs_track_update(&tr, NULL, NULL, 1e-3, &a.p, &l.c, &oa, &err) == RS_OK);
        ENSURE(rs_track_update(&tr, NULL, NULL, 1e-3, &b.p, &l.c, &ob, &err) == RS_OK);
        ENSURE(oa.n == ob.n);
        const size_t n = (size_t)oa.n;
        steps_with_contacts += n > 0;
        mismatch += memcmp(oa.point, ob.point, n * sizeof(int)) != 0;
        mismatch += memcmp(oa.feature, ob.feature, n * sizeof(int)) != 0;
        mismatch += memcmp(oa.rdisp, ob.rdisp, 3 * n * sizeof(double)) != 0;
        mismatch += memcmp(oa.drdisp, ob.drdisp, 3 * n * sizeof(double)) != 0;
        mismatch += memcmp(oa.drot, ob.drot, 4 * n * sizeof(double)) != 0;
        mismatch += memcmp(oa.alocaldir, ob.alocaldir, 9 * n * sizeof(double)) != 0;
        mismatch += memcmp(oa.coordslv, ob.coordslv, 3 * n * sizeof(double)) != 0;
        mismatch += memcmp(oa.vrel, ob.vrel, 3 * n * sizeof(double)) != 0;
        for (size_t e = 0; e < n; e++) {
            /* the same slot index in both layouts */
            const int i = oa.point[e];
            mismatch += (oa.dir[e] - a.dir[i]) != (ob.dir[e] - dirb[i]);
            leaving_seen += RS_DIR_IS_LEAVING(*oa.dir[e]);
        }
        double sa[3 * MAXC], sb[3 * MAXC], va[NS * MAXC], vb[NS * MAXC];
        rs_track_load(&tr, &oa, sa, va);
        rs_track_load(&tr, &ob, sb, vb);
        mismatch += memcmp(sa, sb, 3 * n * sizeof(double)) != 0;
        mismatch += memcmp(va, vb, NS * n * sizeof(double)) != 0;
        /* a law's answer: new stress and state from the loaded ones */
        for (size_t e = 0; e < n; e++) {
            for (int d = 0; d < 3; d++)
                sa[3 * e + d] +=
                    RS_A2(oa.rdisp, 3, d, e) < 1e29 ? RS_A2(oa.rdisp, 3, d, e) : 0.0;
            for (int d = 0; d < NS; d++)
                va[NS * e + d] += 1.0 + d;
        }
        rs_track_commit(&tr, &oa, sa, va);
        rs_track_commit(&tr, &ob, sa, va);
        for (int i = 0; i < NP; i++)
            for (int j = 0; j < CAP; j++) {
                mismatch += memcmp(&a.dir[i][j], &dirb[i][j], sizeof(double)) != 0;
                if (a.dir[i][j] != RS_DIR_EMPTY)
                    mismatch += memcmp(a.hist[i] + j * HS, hpb[i] + j * stride,
                                       HS * sizeof(double)) != 0;
            }
    }
    ENSURE(mismatch == 0);
    ENSURE(steps_with_contacts > 50 && leaving_seen > 10);
    for (int j = 1; j < CAP; j++)
        ENSURE(memcmp(hpb[0] + j * stride, nanpat, sizeof nanpat) == 0);
    rs_track_out_free(&oa);
    rs_track_out_free(&ob);
}

/* Contacts must come in block order with valid point indices: a clear error otherwise. */
static void test_rejects_unordered_contacts(void)
{
    fixture fx;
    fixture_init(&fx, 3);
    double n[3] = {0, 0, 1}, t1[3] = {1, 0, 0}, t2[3] = {0, 1, 0}, P[3] = {0, 0, 0};
    double x[3] = {0, 0, 0.0099};
    block_init(&fx.b, 2, &fx.tr);
    rs_test_clist_init(&fx.l);
    add_plane(&fx.l, 1, 0, x, P, n, t1, t2);
    add_plane(&fx.l, 0, 0, x, P, n, t1, t2);
    ENSURE(track_call(&fx, NULL, NULL, 1e-3) == RS_ERR_ARG);
    ENSURE(strstr(fx.err.msg, "block order") != NULL);
    rs_test_clist_init(&fx.l);
    add_plane(&fx.l, 2, 0, x, P, n, t1, t2);
    ENSURE(track_call(&fx, NULL, NULL, 1e-3) == RS_ERR_ARG);
    fixture_free(&fx);
}

/* A block answers as its particles one at a time. rs_track_update copies a run of
 * contacts 4 at a time between its working columns and the Abaqus-layout outputs and the
 * history slots, and the rest of a run one at a time; a block of one particle takes only
 * the latter. 37 particles inside a turning drum, tracked as one block and one by one,
 * give bit-identical outputs, loads and history over 7 increments: some touch the end
 * cap too (a second contact, new from increment 2 for some), some lose a contact (leaving
 * entries), and the last 3 increments have one held contact per particle, the block's
 * fast path. For ndir 3 and 2. */
enum { NB = 37 };

typedef struct cloud37 {
    double x[NB], y[NB], z[NB], vx[NB], vy[NB], vz[NB], wx[NB], wy[NB], wz[NB], r[NB];
    double dir[NB][CAP], hist[NB][CAP * HS];
    double *dp[NB], *hp[NB];
} cloud37;

/* Particle i's contacts at increment step, appended with point index pt. */
static void contacts37(rs_test_clist *l, const cloud37 *cl, int pt, int i, int step)
{
    const double A[3] = {0, 0, 0}, g[3] = {0, 0, 1}, P[3] = {0, 0, 0};
    const double n[3] = {0, 0, 1}, t1[3] = {1, 0, 0}, t2[3] = {0, 1, 0};
    const double x[3] = {cl->x[i], cl->y[i], cl->z[i]};
    if (i % 7 != 3 || step < 2)
        add_drum(l, pt, 1, x, A, g, 0.1);
    const int cap = step < 4 && ((i % 5 == 0 && !(step == 3 && i % 10 == 0)) ||
                                 (i % 5 == 2 && step >= 2));
    if (cap)
        add_plane(l, pt, 2, x, P, n, t1, t2);
}

static void block_vs_single(int nd)
{
    rs_tracker tr = tracker(nd);
    static cloud37 a, b;
    rs_track_out oa = {0}, ob = {0};
    rs_motion m;
    rs_error err;
    const double zero[3] = {0, 0, 0}, zax[3] = {0, 0, 1}, dt = 1e-3, rad = 0.004;
    unsigned long long rng = 0x37b10c4ULL;
    memset(&a, 0, sizeof a);
    for (int i = 0; i < NB; i++) {
        a.dp[i] = a.dir[i];
        a.hp[i] = a.hist[i];
        rs_track_clear(&tr, a.dir[i], a.hist[i], 0);
    }
    b = a;
    for (int i = 0; i < NB; i++) {
        b.dp[i] = b.dir[i];
        b.hp[i] = b.hist[i];
    }
    rs_motion_init(&m);
    ENSURE(rs_motion_set_rotation(&m, zero, zax, 2.0, &err) == RS_OK);
    int mismatch = 0, leaving = 0, twin = 0, entries = 0;
    for (int step = 0; step < 7; step++) {
        ENSURE(rs_motion_advance(&m, dt, &err) == RS_OK);
        for (int i = 0; i < NB; i++) {
            const double th =
                2.0 * RS_PI * i / NB + 2.0 * dt * step + 1e-3 * step * (i % 3);
            const double rr = 0.1 - rad + 1e-4 * (1 + (i + step) % 4);
            a.x[i] = rr * cos(th);
            a.y[i] = rr * sin(th);
            a.z[i] = rad - 1e-4 * (1 + i % 3);
            a.vx[i] = rs_test_urand(&rng) - 0.5;
            a.vy[i] = rs_test_urand(&rng) - 0.5;
            a.vz[i] = rs_test_urand(&rng) - 0.5;
            a.wx[i] = 10.0 * (rs_test_urand(&rng) - 0.5);
            a.wy[i] = 10.0 * (rs_test_urand(&rng) - 0.5);
            a.wz[i] = 10.0 * (rs_test_urand(&rng) - 0.5);
            a.r[i] = rad;
        }
        memcpy(b.x, a.x, sizeof a.x);
        memcpy(b.y, a.y, sizeof a.y);
        memcpy(b.z, a.z, sizeof a.z);
        memcpy(b.vx, a.vx, sizeof a.vx);
        memcpy(b.vy, a.vy, sizeof a.vy);
        memcpy(b.vz, a.vz, sizeof a.vz);
        memcpy(b.wx, a.wx, sizeof a.wx);
        memcpy(b.wy, a.wy, sizeof a.wy);
        memcpy(b.wz, a.wz, sizeof a.wz);
        memcpy(b.r, a.r, sizeof a.r);

        rs_test_clist l;
        rs_test_clist_init(&l);
        for (int i = 0; i < NB; i++)
            contacts37(&l, &a, i, i, step);
        rs_particles pa = {.n = NB,
                           .x = a.x,
                           .y = a.y,
                           .z = a.z,
                           .vx = a.vx,
                           .vy = a.vy,
                           .vz = a.vz,
                           .wx = a.wx,
                           .wy = a.wy,
                           .wz = a.wz,
                           .radius = a.r,
                           .dir = a.dp,
                           .hist = a.hp};
        ENSURE(rs_track_update(&tr, NULL, &m, dt, &pa, &l.c, &oa, &err) == RS_OK);
        double sa[3 * MAXC], va[NS * MAXC], sa0[3 * MAXC], va0[NS * MAXC];
        rs_track_load(&tr, &oa, sa0, va0);
        memcpy(sa, sa0, sizeof sa);
        memcpy(va, va0, sizeof va);
        for (int e = 0; e < oa.n; e++) {
            for (int d = 0; d < nd; d++)
                sa[nd * e + d] +=
                    RS_A2(oa.rdisp, nd, d, e) < 1e29 ? RS_A2(oa.rdisp, nd, d, e) : 0.0;
            for (int d = 0; d < NS; d++)
                va[NS * e + d] += 1.0 + d;
        }
        entries += oa.n;
        leaving += oa.nleave;
        for (int e = 1; e < oa.n; e++)
            twin += oa.point[e] == oa.point[e - 1];

        for (int i = 0, ea = 0; i < NB; i++) {
            rs_test_clist li;
            rs_test_clist_init(&li);
            contacts37(&li, &b, 0, i, step);
            rs_particles pb = {.n = 1,
                               .x = b.x + i,
                               .y = b.y + i,
                               .z = b.z + i,
                               .vx = b.vx + i,
                               .vy = b.vy + i,
                               .vz = b.vz + i,
                               .wx = b.wx + i,
                               .wy = b.wy + i,
                               .wz = b.wz + i,
                               .radius = b.r + i,
                               .dir = b.dp + i,
                               .hist = b.hp + i};
            ENSURE(rs_track_update(&tr, NULL, &m, dt, &pb, &li.c, &ob, &err) == RS_OK);
            double sb[3 * CAP], vb[NS * CAP];
            rs_track_load(&tr, &ob, sb, vb);
            /* particle i's entries in the block: ob.n of them from ea on */
            for (int e = 0; e < ob.n; e++, ea++) {
                const size_t x = (size_t)ea, y = (size_t)e, n2 = (size_t)nd;
                if (ea >= oa.n || oa.point[ea] != i) {
                    mismatch++;
                    break;
                }
                mismatch += oa.feature[ea] != ob.feature[e];
                mismatch += (oa.dir[ea] - a.dir[i]) != (ob.dir[e] - b.dir[i]);
                mismatch += memcmp(oa.rdisp + n2 * x, ob.rdisp + n2 * y, n2 * 8) != 0;
                mismatch += memcmp(oa.drdisp + n2 * x, ob.drdisp + n2 * y, n2 * 8) != 0;
                mismatch += memcmp(oa.drot + 4 * x, ob.drot + 4 * y, 4 * 8) != 0;
                mismatch += memcmp(oa.alocaldir + n2 * n2 * x, ob.alocaldir + n2 * n2 * y,
                                   n2 * n2 * 8) != 0;
                mismatch += memcmp(oa.coordslv + n2 * x, ob.coordslv + n2 * y, n2 * 8) != 0;
                mismatch += memcmp(oa.coordmst + n2 * x, ob.coordmst + n2 * y, n2 * 8) != 0;
                mismatch += memcmp(oa.vrel + n2 * x, ob.vrel + n2 * y, n2 * 8) != 0;
                mismatch += memcmp(oa.curv + 2 * x, ob.curv + 2 * y, 2 * 8) != 0;
                mismatch += memcmp(sa0 + n2 * x, sb + n2 * y, n2 * 8) != 0;
                mismatch += memcmp(va0 + NS * x, vb + NS * y, NS * 8) != 0;
                /* the same law answer */
                memcpy(sb + n2 * y, sa + n2 * x, n2 * 8);
                memcpy(vb + NS * y, va + NS * x, NS * 8);
            }
            if (i == NB - 1)
                mismatch += ea != oa.n;
            rs_track_commit(&tr, &ob, sb, vb);
        }
        rs_track_commit(&tr, &oa, sa, va);
        mismatch += memcmp(a.dir, b.dir, sizeof a.dir) != 0;
        mismatch += memcmp(a.hist, b.hist, sizeof a.hist) != 0;
    }
    rs_track_out_free(&oa);
    rs_track_out_free(&ob);
    ENSURE(leaving >= 4 && twin >= 8 && entries > 7 * NB);
    ENSURE(mismatch == 0);
}

static void test_block_matches_one_at_a_time(void)
{
    block_vs_single(3);
    block_vs_single(2);
}

int main(void)
{
    RS_RUN(test_maxval_once_after_leaving);
    RS_RUN(test_contact_beyond_tracking_leaves);
    RS_RUN(test_leaving_slot_between_held_contacts);
    RS_RUN(test_history_handover_across_smooth_junction);
    RS_RUN(test_capacity_error_names_particle);
    RS_RUN(test_ndir2_drot_identity);
    RS_RUN(test_drdisp1_is_change_of_penetration);
    RS_RUN(test_alocaldir_columns_and_contact_point);
    RS_RUN(test_rejects_unordered_contacts);
    RS_RUN(test_slot_major_layout_matches_contiguous);
    RS_RUN(test_block_matches_one_at_a_time);
    return rs_test_summary();
}
