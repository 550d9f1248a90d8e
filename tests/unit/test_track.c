/* The contact tracker (track.h; docs/conventions.md, "rdisp, drdisp, drot"): drot under
 * rigid motions of the contact, by closed-form angles, carrying the previous stress;
 * slip as the integrated tangential velocity, rotated by drot before its increment.
 * Contacts are built by hand (track_fixture.h). The slots' life is in
 * test_track_slots.c. */
#include "track_fixture.h"

/* Plane master translating with V; the sphere rides along with it (x = x0 + V t): the
 * frame does not turn, so drot = I, no slip accumulates and the penetration stays. */
static void test_drot_identity_under_rigid_translation(void)
{
    fixture fx;
    fixture_init(&fx, 3);
    rs_motion m;
    double V[3] = {0.7, -1.3, 0.4}, P0[3] = {0.1, 0.2, 0.3}, nin[3] = {1, 2, 2};
    double hint[3] = {1, 0, 0}, n[3], t1[3], t2[3], zero[3] = {0, 0, 0};
    const double R = 0.01, pen = 2e-4, dt = 1e-3;
    make_frame(nin, hint, n, t1, t2);
    double x0[3];
    axpy(x0, R - pen, n, P0);
    rs_motion_init(&m);
    rs_motion_set_translation(&m, V);
    block_init(&fx.b, 1, &fx.tr);
    for (int step = 1; step <= 3000; step++) {
        ENSURE(rs_motion_advance(&m, dt, &fx.err) == RS_OK);
        double t = step * dt, x[3], P[3];
        axpy(x, t, V, x0);
        axpy(P, t, V, P0);
        block_set(&fx.b, 0, x, V, zero, R);
        ENSURE(plane_call(&fx, NULL, &m, dt, RS_FEATURE(RS_FEAT_FACE, 0), x, P, n, t1,
                          t2) == RS_OK);
        check_rigid_contact(&fx.o, pen);
        rs_track_commit(&fx.tr, &fx.o, NULL, NULL);
    }
    fixture_free(&fx);
}

/* Drum (cylinder) master rotating about an arbitrary axis through an arbitrary point
 * while translating; the sphere moves with the master's material motion and spins with
 * it. The analytic frame turns with the master, so drot = I to 1e-12 over many steps
 * and no slip accumulates (objectivity). */
static void test_drot_identity_under_rigid_rotation(void)
{
    fixture fx;
    fixture_init(&fx, 3);
    rs_motion m;
    double axis[3] = {0.3, -1.0, 0.6}, C[3] = {0.2, 0.1, -0.3}, V[3] = {0.05, 0.0, -0.02};
    double A0[3] = {0.0, 0.5, 0.1}, g0[3] = {0.2, 0.1, 1.0};
    const double omega = 3.0, dt = 1e-3, Rc = 0.5, R = 0.02, pen = 3e-4;
    unit(g0);
    rs_motion_init(&m);
    rs_motion_set_translation(&m, V);
    ENSURE(rs_motion_set_rotation(&m, C, axis, omega, &fx.err) == RS_OK);
    double ax[3] = {axis[0], axis[1], axis[2]};
    unit(ax);
    /* Reference particle centre: on the drum's inner side at depth pen. */
    double hint[3] = {1, 0, 0}, e0[3], e1[3], er[3], X0[3];
    make_frame(g0, hint, e0, er, e1); /* er: a unit vector normal to g0 */
    for (int i = 0; i < 3; i++)
        X0[i] = A0[i] + 0.3 * g0[i] + (Rc - R + pen) * er[i];
    block_init(&fx.b, 1, &fx.tr);
    for (int step = 1; step <= 2000; step++) {
        ENSURE(rs_motion_advance(&m, dt, &fx.err) == RS_OK);
        double x[3], A[3], g[3], c[3], v[3], w[3], r[3], wr[3];
        rs_pose_to_global(&m.pose, X0, x);
        rs_pose_to_global(&m.pose, A0, A);
        rs_matvec3(m.pose.R, g0, g);
        /* Material velocity of the master at x: V + omega axis x (x - (C + V t)). */
        double t = step * dt;
        for (int i = 0; i < 3; i++) {
            c[i] = C[i] + V[i] * t;
            r[i] = x[i] - c[i];
            w[i] = omega * ax[i];
        }
        rs_cross3(w, r, wr);
        for (int i = 0; i < 3; i++)
            v[i] = V[i] + wr[i];
        block_set(&fx.b, 0, x, v, w, R);
        ENSURE(drum_call(&fx, &m, dt, RS_FEATURE(RS_FEAT_FACE, 0), x, A, g, Rc) == RS_OK);
        check_rigid_contact(&fx.o, pen);
        rs_track_commit(&fx.tr, &fx.o, NULL, NULL);
    }
    fixture_free(&fx);
}

/* A faceted master spun by theta about the contact normal keeps its tangent basis tied
 * to global x, so the basis does not move while the material under it turns by +theta:
 * Q t1 = c t1 + s t2, Q t2 = -s t1 + c t2, P = I, and drot(i,j) = t_i . Q t_j gives
 *     drot = [[c, -s], [s, c]]    (rotation by +theta).
 * The same spin seen with a fixed master and a basis turned by +theta
 * (t1' = c t1 + s t2, t2' = -s t1 + c t2, tau_j = t_j) gives drot(i,j) = t_i' . t_j =
 *     [[c, s], [-s, c]]           (rotation by -theta):
 * only the master's rotation relative to the basis counts. */
static void test_drot_is_rotation_by_theta(void)
{
    fixture fx;
    fixture_init(&fx, 3);
    rs_motion m;
    double nin[3] = {0.3, -0.4, 1.0}, hint[3] = {1, 0, 0}, n[3], t1[3], t2[3];
    double zero[3] = {0, 0, 0}, P[3] = {0.5, 0.5, 0.5}, x[3];
    const double R = 0.01, theta = 0.3, dt = 1e-3, c = cos(theta), s = sin(theta);
    make_frame(nin, hint, n, t1, t2);
    axpy(x, R - 1e-4, n, P);

    /* (a) Faceted master spun about n through the contact point. */
    rs_motion_init(&m);
    double xcp[3];
    axpy(xcp, -R, n, x);
    ENSURE(rs_motion_set_rotation(&m, xcp, n, theta / dt, &fx.err) == RS_OK);
    block_init(&fx.b, 1, &fx.tr);
    block_set(&fx.b, 0, x, zero, zero, R);
    ENSURE(plane_call(&fx, NULL, NULL, dt, RS_FEATURE(RS_FEAT_FACE, 3), x, P, n, t1, t2) ==
           RS_OK);
    rs_track_commit(&fx.tr, &fx.o, NULL, NULL);
    ENSURE(rs_motion_advance(&m, dt, &fx.err) == RS_OK);
    ENSURE(track_call(&fx, NULL, &m, dt) == RS_OK);
    ENSURE(fx.o.n == 1);
    ENSURE(drot_is(&fx.o, 0, c, -s, s, c, 1e-14));

    /* (b) Fixed master, basis turned by +theta about n. */
    block_init(&fx.b, 1, &fx.tr);
    block_set(&fx.b, 0, x, zero, zero, R);
    ENSURE(plane_call(&fx, NULL, NULL, dt, RS_FEATURE(RS_FEAT_FACE, 3), x, P, n, t1, t2) ==
           RS_OK);
    rs_track_commit(&fx.tr, &fx.o, NULL, NULL);
    double u1[3], u2[3];
    for (int i = 0; i < 3; i++) {
        u1[i] = c * t1[i] + s * t2[i];
        u2[i] = -s * t1[i] + c * t2[i];
    }
    ENSURE(plane_call(&fx, NULL, NULL, dt, RS_FEATURE(RS_FEAT_FACE, 3), x, P, n, u1, u2) ==
           RS_OK);
    ENSURE(fx.o.n == 1);
    ENSURE(drot_is(&fx.o, 0, c, s, -s, c, 1e-14));
    fixture_free(&fx);
}

/* rs_track_load: the previous shear traction is a vector fixed in space on a fixed
 * master; with the tangent basis turned by theta about n its components in the new basis
 * are T . u_i, T = s2 t1 + s3 t2. The pressure and statev come back unchanged. */
static void test_previous_stress_shear_carried_by_drot(void)
{
    fixture fx;
    fixture_init(&fx, 3);
    double nin[3] = {-0.2, 0.7, 0.4}, hint[3] = {0, 0, 1}, n[3], t1[3], t2[3];
    double zero[3] = {0, 0, 0}, P[3] = {0.1, 0.2, 0.3}, x[3];
    const double R = 0.02, theta = -0.7, dt = 1e-3, c = cos(theta), s = sin(theta);
    make_frame(nin, hint, n, t1, t2);
    axpy(x, R - 1e-4, n, P);
    block_init(&fx.b, 1, &fx.tr);
    block_set(&fx.b, 0, x, zero, zero, R);
    ENSURE(plane_call(&fx, NULL, NULL, dt, RS_FEATURE(RS_FEAT_FACE, 0), x, P, n, t1, t2) ==
           RS_OK);
    const double stress[3] = {3.5, 2.0, -1.0}, statev[NS] = {4, 5};
    rs_track_commit(&fx.tr, &fx.o, stress, statev);

    double u1[3], u2[3], T[3];
    for (int i = 0; i < 3; i++) {
        u1[i] = c * t1[i] + s * t2[i];
        u2[i] = -s * t1[i] + c * t2[i];
        T[i] = stress[1] * t1[i] + stress[2] * t2[i];
    }
    ENSURE(plane_call(&fx, NULL, NULL, dt, RS_FEATURE(RS_FEAT_FACE, 0), x, P, n, u1, u2) ==
           RS_OK);
    ENSURE(fx.o.n == 1);
    double sl[3], sv[NS];
    rs_track_load(&fx.tr, &fx.o, sl, sv);
    ENSURE(sl[0] == stress[0]);
    ENSURE_NEAR(sl[1], rs_dot3(T, u1), 1e-14);
    ENSURE_NEAR(sl[2], rs_dot3(T, u2), 1e-14);
    ENSURE(sv[0] == statev[0] && sv[1] == statev[1]);
    rs_track_commit(&fx.tr, &fx.o, sl, sv);

    /* Leaving: the stored stress comes back as it is (drot holds 1e30). */
    rs_test_clist_init(&fx.l);
    ENSURE(track_call(&fx, NULL, NULL, dt) == RS_OK);
    ENSURE(fx.o.n == 1 && RS_DROT(fx.o.drot, 0, 0, 0) == RS_MAXVAL);
    double sl2[3];
    rs_track_load(&fx.tr, &fx.o, sl2, NULL);
    ENSURE(sl2[0] == sl[0] && sl2[1] == sl[1] && sl2[2] == sl[2]);
    fixture_free(&fx);
}

/* Sliding along a fixed drum's generator: n and t1 = generator do not change, so
 * drot = I and the slip is the distance slid along t1. */
static void test_drot_identity_sliding_along_generator(void)
{
    fixture fx;
    fixture_init(&fx, 3);
    double A[3] = {1, -1, 0.5}, g[3] = {1, 1, 1}, hint[3] = {1, 0, 0}, er[3], e0[3], e1[3];
    const double Rc = 0.4, R = 0.05, u = 0.8, dt = 1e-3;
    unit(g);
    make_frame(g, hint, e0, er, e1);
    double x0[3], v[3] = {u * g[0], u * g[1], u * g[2]}, zero[3] = {0, 0, 0};
    for (int i = 0; i < 3; i++)
        x0[i] = A[i] + (Rc - R + 1e-4) * er[i];
    block_init(&fx.b, 1, &fx.tr);
    const int N = 500;
    for (int step = 0; step < N; step++) {
        double x[3];
        axpy(x, u * step * dt, g, x0);
        block_set(&fx.b, 0, x, v, zero, R);
        ENSURE(drum_call(&fx, NULL, dt, RS_FEATURE(RS_FEAT_FACE, 0), x, A, g, Rc) == RS_OK);
        ENSURE(fx.o.n == 1);
        ENSURE(drot_is(&fx.o, 0, 1, 0, 0, 1, 1e-14));
        rs_track_commit(&fx.tr, &fx.o, NULL, NULL);
    }
    /* N increments of u dt along t1: a new contact's first call carries its increment. */
    ENSURE_NEAR(RS_A2(fx.o.rdisp, 3, 1, 0), N * u * dt, 1e-12);
    ENSURE_SMALL(RS_A2(fx.o.rdisp, 3, 2, 0), 1e-14);
    fixture_free(&fx);
}

/* Sliding around a fixed drum along the hoop: n turns about the generator by da per call
 * and t2 = n x t1 turns with it. The minimal rotation P (about the generator) carries
 * the old basis onto the new one, so drot = I; the slip grows along t2 only. */
static void test_drot_identity_sliding_around_drum_hoop(void)
{
    fixture fx;
    fixture_init(&fx, 3);
    double A[3] = {0.2, 0.1, -0.4}, g[3] = {0.5, -1, 0.3}, hint[3] = {1, 0, 0};
    double e0[3], ea[3], eb[3], zero[3] = {0, 0, 0};
    const double Rc = 0.3, R = 0.02, pen = 2e-4, u = 1.2, dt = 1e-3;
    const double rho = Rc - R + pen, om = u / rho;
    unit(g);
    make_frame(g, hint, e0, ea, eb); /* ea, eb, g right-handed */
    block_init(&fx.b, 1, &fx.tr);
    const int N = 300;
    for (int step = 0; step < N; step++) {
        double a = om * step * dt, x[3], v[3];
        for (int i = 0; i < 3; i++) {
            double er = cos(a) * ea[i] + sin(a) * eb[i],
                   et = -sin(a) * ea[i] + cos(a) * eb[i];
            x[i] = A[i] + 0.1 * g[i] + rho * er;
            v[i] = u * et;
        }
        block_set(&fx.b, 0, x, v, zero, R);
        ENSURE(drum_call(&fx, NULL, dt, RS_FEATURE(RS_FEAT_FACE, 0), x, A, g, Rc) == RS_OK);
        ENSURE(fx.o.n == 1);
        ENSURE(drot_is(&fx.o, 0, 1, 0, 0, 1, 1e-14));
        rs_track_commit(&fx.tr, &fx.o, NULL, NULL);
    }
    /* t2 = n x g = -e_r x g = e_theta, since (e_r, e_theta, g) is right-handed. */
    ENSURE_SMALL(RS_A2(fx.o.rdisp, 3, 1, 0), 1e-14);
    ENSURE_NEAR(RS_A2(fx.o.rdisp, 3, 2, 0), N * u * dt, 1e-12);
    fixture_free(&fx);
}

/* A normal that flips (n_new = -Q n_old) has no unique minimal rotation; the tracker takes
 * the half turn about the carried t1: tau1 = t1, tau2 = -t2. With the new basis
 * (t1, -t2) that is drot = I, finite and deterministic. */
static void test_drot_antiparallel_normal_is_half_turn_about_t1(void)
{
    fixture fx;
    fixture_init(&fx, 3);
    double n[3] = {0, 0, 1}, t1[3] = {1, 0, 0}, t2[3] = {0, 1, 0}, P[3] = {0, 0, 0};
    double nf[3] = {0, 0, -1}, t2f[3] = {0, -1, 0}, x[3] = {0, 0, 0.0099}, zero[3] = {0};
    block_init(&fx.b, 1, &fx.tr);
    block_set(&fx.b, 0, x, zero, zero, 0.01);
    ENSURE(plane_call(&fx, NULL, NULL, 1e-3, 0, x, P, n, t1, t2) == RS_OK);
    rs_track_commit(&fx.tr, &fx.o, NULL, NULL);
    double xf[3] = {0, 0, -0.0099};
    block_set(&fx.b, 0, xf, zero, zero, 0.01);
    ENSURE(plane_call(&fx, NULL, NULL, 1e-3, 0, xf, P, nf, t1, t2f) == RS_OK);
    ENSURE(fx.o.n == 1);
    ENSURE(drot_is(&fx.o, 0, 1, 0, 0, 1, 0.0));
    fixture_free(&fx);
}

/* Slip = sum of [(v + w x (x_cp - x)) - v_master]_t dt. Plane with basis (t1, t2, n);
 * particle u = 0.3 t1 - 0.1 t2 + 0.05 n, spin w = t1 + 2 t2 + 3 n, master V = 0.1 t1 +
 * 0.2 t2 + 0.05 n (same normal speed: constant penetration d = 1e-3). With
 * x_cp - x = -a n, a = R - d/2 = 0.0095: w x (-a n) = -a (t1 x n + 2 t2 x n) = a t2 - 2a
 * t1. So v_rel,t = (0.3 - 0.1 - 0.019, -0.1 - 0.2 + 0.0095) = (0.181, -0.2905), and after N
 * calls (the first opens the contact with its first increment) slip = N dt (0.181,
 * -0.2905). */
static void test_slip_equals_integrated_tangential_velocity(void)
{
    fixture fx;
    fixture_init(&fx, 3);
    rs_motion m;
    double nin[3] = {-1, 0.5, 2}, hint[3] = {0, 1, 0}, n[3], t1[3], t2[3];
    const double R = 0.01, d = 1e-3, dt = 2e-4;
    make_frame(nin, hint, n, t1, t2);
    double u[3], w[3], V[3], P0[3] = {0.2, -0.1, 0.4}, x0[3];
    for (int i = 0; i < 3; i++) {
        u[i] = 0.3 * t1[i] - 0.1 * t2[i] + 0.05 * n[i];
        w[i] = 1.0 * t1[i] + 2.0 * t2[i] + 3.0 * n[i];
        V[i] = 0.1 * t1[i] + 0.2 * t2[i] + 0.05 * n[i];
    }
    axpy(x0, R - d, n, P0);
    rs_motion_init(&m);
    rs_motion_set_translation(&m, V);
    block_init(&fx.b, 1, &fx.tr);
    const int N = 1000;
    for (int step = 1; step <= N; step++) {
        ENSURE(rs_motion_advance(&m, dt, &fx.err) == RS_OK);
        double x[3], P[3];
        axpy(x, step * dt, u, x0);
        axpy(P, step * dt, V, P0);
        block_set(&fx.b, 0, x, u, w, R);
        ENSURE(plane_call(&fx, NULL, &m, dt, RS_FEATURE(RS_FEAT_FACE, 0), x, P, n, t1,
                          t2) == RS_OK);
        ENSURE(fx.o.n == 1);
        ENSURE_NEAR(RS_A2(fx.o.drdisp, 3, 1, 0), 0.181 * dt, 1e-13);
        ENSURE_NEAR(RS_A2(fx.o.drdisp, 3, 2, 0), -0.2905 * dt, 1e-13);
        ENSURE_NEAR(RS_A2(fx.o.vrel, 3, 0, 0), 0.0, 1e-12);
        ENSURE_NEAR(RS_A2(fx.o.vrel, 3, 1, 0), 0.181, 1e-12);
        ENSURE_NEAR(RS_A2(fx.o.vrel, 3, 2, 0), -0.2905, 1e-12);
        rs_track_commit(&fx.tr, &fx.o, NULL, NULL);
    }
    ENSURE_NEAR(RS_A2(fx.o.rdisp, 3, 1, 0), N * dt * 0.181, 1e-11);
    ENSURE_NEAR(RS_A2(fx.o.rdisp, 3, 2, 0), N * dt * -0.2905, 1e-11);
    ENSURE_NEAR(RS_A2(fx.o.rdisp, 3, 0, 0), d, 1e-12);
    fixture_free(&fx);
}

/* The slip vector S (a global vector, fixed master) is re-expressed in the new basis
 * before the increment is added: s_new = (S . t1', S . t2') + dt (v . t1', v . t2'). */
static void test_slip_rotated_by_drot_before_increment(void)
{
    fixture fx;
    fixture_init(&fx, 3);
    double nin[3] = {0, 0, 1}, hint[3] = {1, 0.2, 0}, n[3], t1[3], t2[3],
           zero[3] = {0, 0, 0};
    double P[3] = {0, 0, 0}, x[3];
    const double R = 0.01, dt = 1e-3, theta = 0.9, c = cos(theta), s = sin(theta);
    make_frame(nin, hint, n, t1, t2);
    axpy(x, R - 1e-4, n, P);
    double v1[3], v2[3];
    for (int i = 0; i < 3; i++) {
        v1[i] = 0.5 * t1[i] - 0.25 * t2[i];
        v2[i] = -0.3 * t1[i] + 0.7 * t2[i];
    }
    block_init(&fx.b, 1, &fx.tr);
    block_set(&fx.b, 0, x, v1, zero, R);
    ENSURE(plane_call(&fx, NULL, NULL, dt, RS_FEATURE(RS_FEAT_FACE, 0), x, P, n, t1, t2) ==
           RS_OK);
    rs_track_commit(&fx.tr, &fx.o, NULL, NULL);
    ENSURE(track_call(&fx, NULL, NULL, dt) == RS_OK);
    rs_track_commit(&fx.tr, &fx.o, NULL, NULL);
    /* slip vector after two calls, each adding v1 dt */
    double S[3] = {2 * v1[0] * dt, 2 * v1[1] * dt, 2 * v1[2] * dt};
    ENSURE_NEAR(RS_A2(fx.o.rdisp, 3, 1, 0), rs_dot3(S, t1), 1e-15);
    ENSURE_NEAR(RS_A2(fx.o.rdisp, 3, 2, 0), rs_dot3(S, t2), 1e-15);

    double u1[3], u2[3];
    for (int i = 0; i < 3; i++) {
        u1[i] = c * t1[i] + s * t2[i];
        u2[i] = -s * t1[i] + c * t2[i];
    }
    block_set(&fx.b, 0, x, v2, zero, R);
    ENSURE(plane_call(&fx, NULL, NULL, dt, RS_FEATURE(RS_FEAT_FACE, 0), x, P, n, u1, u2) ==
           RS_OK);
    ENSURE(fx.o.n == 1);
    ENSURE_NEAR(RS_A2(fx.o.rdisp, 3, 1, 0), rs_dot3(S, u1) + dt * rs_dot3(v2, u1), 1e-15);
    ENSURE_NEAR(RS_A2(fx.o.rdisp, 3, 2, 0), rs_dot3(S, u2) + dt * rs_dot3(v2, u2), 1e-15);
    ENSURE_NEAR(RS_A2(fx.o.drdisp, 3, 1, 0), dt * rs_dot3(v2, u1), 1e-15);
    ENSURE_NEAR(RS_A2(fx.o.drdisp, 3, 2, 0), dt * rs_dot3(v2, u2), 1e-15);
    fixture_free(&fx);
}

int main(void)
{
    RS_RUN(test_drot_identity_under_rigid_translation);
    RS_RUN(test_drot_identity_under_rigid_rotation);
    RS_RUN(test_drot_is_rotation_by_theta);
    RS_RUN(test_previous_stress_shear_carried_by_drot);
    RS_RUN(test_drot_identity_sliding_along_generator);
    RS_RUN(test_drot_identity_sliding_around_drum_hoop);
    RS_RUN(test_drot_antiparallel_normal_is_half_turn_about_t1);
    RS_RUN(test_slip_equals_integrated_tangential_velocity);
    RS_RUN(test_slip_rotated_by_drot_before_increment);
    return rs_test_summary();
}
