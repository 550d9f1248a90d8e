/* Rigid motion (motion.h): x(t) = C + D(t) + R(axis, phi(t)) (X - C). Every reference
 * answer here is an independent closed form: rotations by the quaternion formula
 * v' = v + 2 q0 (q x v) + 2 q x (q x v), q = axis sin(a/2), q0 = cos(a/2). */
#include "rigidsurf/motion.h"
#include "rs_test.h"
#include "rs_test_geom.h"

/* Rotates v about the unit axis by angle a (quaternion form). */
static void quat_rotate(const double axis[3], double a, const double v[3], double r[3])
{
    double q[3] = {axis[0] * sin(0.5 * a), axis[1] * sin(0.5 * a), axis[2] * sin(0.5 * a)};
    double q0 = cos(0.5 * a), qv[3], qqv[3];
    rs_cross3(q, v, qv);
    rs_cross3(q, qv, qqv);
    for (int i = 0; i < 3; i++)
        r[i] = v[i] + 2.0 * q0 * qv[i] + 2.0 * qqv[i];
}

/* Closed-form position of material point X: C + D + R(axis, phi)(X - C). */
static void closed_form(const double C[3], const double D[3], const double axis[3],
                        double phi, const double X[3], double x[3])
{
    double d[3] = {X[0] - C[0], X[1] - C[1], X[2] - C[2]}, r[3];
    quat_rotate(axis, phi, d, r);
    for (int i = 0; i < 3; i++)
        x[i] = C[i] + D[i] + r[i];
}

/* After 1e6 steps of a constant rotation (200 rad in all) the pose is the closed-form
 * rotation by omega t to 1e-12: phi is integrated without drift. */
static void test_motion_no_drift(void)
{
    rs_motion m;
    rs_error err;
    double axis[3] = {1.0, -2.0, 0.5}, C[3] = {0.3, -0.2, 0.5}, omega = 2.0, dt = 1e-4;
    const long N = 1000000;
    rs_motion_init(&m);
    ENSURE(rs_motion_set_rotation(&m, C, axis, omega, &err) == RS_OK);
    unit(axis);
    for (long k = 0; k < N; k++)
        ENSURE(rs_motion_advance(&m, dt, &err) == RS_OK);
    double t = (double)N * dt, zero[3] = {0, 0, 0};
    ENSURE_NEAR(m.t, t, 1e-12);
    /* Columns of R are the images of the basis vectors. */
    for (int j = 0; j < 3; j++) {
        double e[3] = {0, 0, 0}, r[3];
        e[j] = 1.0;
        quat_rotate(axis, omega * t, e, r);
        for (int i = 0; i < 3; i++)
            ENSURE_NEAR(m.pose.R[3 * i + j], r[i], 1e-12);
    }
    double X[3] = {1.0, 2.0, -0.7}, x[3], xr[3];
    rs_pose_to_global(&m.pose, X, x);
    closed_form(C, zero, axis, omega * t, X, xr);
    for (int i = 0; i < 3; i++)
        ENSURE_NEAR(x[i], xr[i], 1e-12);
}

/* v = V + omega axis x (p - (C + D)) equals the central difference of the pose's map of
 * the material point at p. */
static void test_motion_velocity_at(void)
{
    rs_motion m;
    rs_error err;
    double axis[3] = {0.2, 0.9, -0.4}, C[3] = {1.0, 0.5, -0.25}, V[3] = {0.3, -0.7, 1.1};
    rs_motion_init(&m);
    rs_motion_set_translation(&m, V);
    ENSURE(rs_motion_set_rotation(&m, C, axis, 1.7, &err) == RS_OK);
    for (int k = 0; k < 37; k++)
        ENSURE(rs_motion_advance(&m, 0.01, &err) == RS_OK);
    double p[3] = {0.4, -1.2, 2.0}, v[3], X[3], xa[3], xb[3];
    rs_motion_velocity_at(&m, p, v);
    rs_pose_to_local(&m.pose, p, X);
    const double h = 1e-5;
    rs_motion ma = m, mb = m;
    ENSURE(rs_motion_advance(&ma, h, &err) == RS_OK);
    ENSURE(rs_motion_advance(&mb, -h, &err) == RS_OK);
    rs_pose_to_global(&ma.pose, X, xa);
    rs_pose_to_global(&mb.pose, X, xb);
    for (int i = 0; i < 3; i++)
        ENSURE_NEAR(v[i], (xa[i] - xb[i]) / (2.0 * h), 1e-8);
}

/* Translation and rotation superpose: x = C + V t + R(axis, omega t)(X - C); the centre
 * is C + V t and dQ is the rotation by omega dt. */
static void test_motion_superposed_translation_rotation(void)
{
    rs_motion m;
    rs_error err;
    double axis[3] = {-1.0, 0.5, 2.0}, C[3] = {0.1, 0.2, 0.3}, V[3] = {2.0, -1.0, 0.5};
    double omega = -3.0, dt = 2e-3;
    const int N = 5000;
    rs_motion_init(&m);
    rs_motion_set_translation(&m, V);
    ENSURE(rs_motion_set_rotation(&m, C, axis, omega, &err) == RS_OK);
    unit(axis);
    for (int k = 0; k < N; k++)
        ENSURE(rs_motion_advance(&m, dt, &err) == RS_OK);
    double t = N * dt, D[3] = {V[0] * t, V[1] * t, V[2] * t}, c[3];
    rs_motion_center(&m, c);
    for (int i = 0; i < 3; i++)
        ENSURE_NEAR(c[i], C[i] + D[i], 1e-12);
    const double pts[3][3] = {{0, 0, 0}, {1.5, -2.5, 0.5}, {-3, 1, 4}};
    for (int q = 0; q < 3; q++) {
        double x[3], xr[3];
        rs_pose_to_global(&m.pose, pts[q], x);
        closed_form(C, D, axis, omega * t, pts[q], xr);
        for (int i = 0; i < 3; i++)
            ENSURE_NEAR(x[i], xr[i], 1e-11);
        double X[3];
        rs_pose_to_local(&m.pose, x, X);
        for (int i = 0; i < 3; i++)
            ENSURE_NEAR(X[i], pts[q][i], 1e-12);
    }
    for (int j = 0; j < 3; j++) {
        double e[3] = {0, 0, 0}, r[3];
        e[j] = 1.0;
        quat_rotate(axis, omega * dt, e, r);
        for (int i = 0; i < 3; i++)
            ENSURE_NEAR(m.dQ[3 * i + j], r[i], 1e-15);
    }
}

/* A rotation about a centre fixed in space with a translation after it, as LIGGGHTS
 * moves a mesh whose rotate mover comes before its linear mover: each step every node
 * turns by omega dt about C where it stands, then moves by V dt. The pose after N steps
 * equals that node update, iterated here point by point with the quaternion formula,
 * to 1e-11; its centre stays at C, and the velocity is V + omega axis x (x - V dt -
 * C), the rotation's velocity taken on the wall as turned, before the step's
 * translation (the node velocities LIGGGHTS gives such a mesh). The
 * translation made so far turns with the wall: as dt -> 0 the motion is the screw about
 * the axis through C' = C + (W x V)/|W|^2 with W = omega axis, x(t) = C' + V_par t +
 * R(omega t)(X - C'), which the discrete motion meets to O(omega dt). */
static void test_motion_center_fixed(void)
{
    rs_motion m;
    rs_error err;
    double axis[3] = {0.3, -1.0, 0.6}, C[3] = {0.4, -0.2, 0.1}, V[3] = {0.7, 0.2, -0.5};
    const double omega = 2.5, dt = 1e-4;
    const int N = 4000;
    rs_motion_init(&m);
    rs_motion_set_translation(&m, V);
    ENSURE(rs_motion_set_rotation(&m, C, axis, omega, &err) == RS_OK);
    rs_motion_set_center_fixed(&m, 1);
    unit(axis);
    const double pts[3][3] = {{0, 0, 0}, {1.5, -2.5, 0.5}, {-3, 1, 4}};
    double node[3][3];
    memcpy(node, pts, sizeof node);
    for (int k = 0; k < N; k++) {
        ENSURE(rs_motion_advance(&m, dt, &err) == RS_OK);
        for (int q = 0; q < 3; q++) {
            double d[3] = {node[q][0] - C[0], node[q][1] - C[1], node[q][2] - C[2]}, r[3];
            quat_rotate(axis, omega * dt, d, r);
            for (int i = 0; i < 3; i++)
                node[q][i] = C[i] + r[i] + V[i] * dt;
        }
    }
    double c[3];
    rs_motion_center(&m, c);
    for (int i = 0; i < 3; i++)
        ENSURE_NEAR(c[i], C[i] + V[i] * dt, 1e-16);
    const double t = N * dt, W[3] = {omega * axis[0], omega * axis[1], omega * axis[2]};
    double WxV[3], Cs[3], Vpar[3];
    rs_cross3(W, V, WxV);
    const double va = rs_dot3(V, axis);
    for (int i = 0; i < 3; i++) {
        Cs[i] = C[i] + WxV[i] / (omega * omega);
        Vpar[i] = va * axis[i] * t;
    }
    for (int q = 0; q < 3; q++) {
        double x[3], xs[3], v[3], r[3];
        rs_pose_to_global(&m.pose, pts[q], x);
        for (int i = 0; i < 3; i++)
            ENSURE_NEAR(x[i], node[q][i], 1e-11);
        closed_form(Cs, Vpar, axis, omega * t, pts[q], xs);
        for (int i = 0; i < 3; i++) /* the screw, to the steps' O(omega dt) |V| t */
            ENSURE_NEAR(x[i], xs[i], 2.0 * omega * dt * rs_norm3(V) * t);
        rs_motion_velocity_at(&m, x, v);
        const double rel[3] = {x[0] - V[0] * dt - C[0], x[1] - V[1] * dt - C[1],
                               x[2] - V[2] * dt - C[2]};
        rs_cross3(W, rel, r);
        for (int i = 0; i < 3; i++)
            ENSURE_NEAR(v[i], V[i] + r[i], 1e-14);
    }
    /* the default keeps the centre moving with the translation */
    rs_motion_set_center_fixed(&m, 0);
    rs_motion_center(&m, c);
    ENSURE(fabs(c[0] - C[0]) > 1e-3);
}

/* The spin: a second rotation about an axis of fixed direction through a point of the
 * wall that the first rotation carries, applied after it each step (LIGGGHTS's second
 * rotate mover of a mesh). Parallel axes, a planetary mixer's blade: the closed form
 * P(t) = C + R(w1 t)(P0 - C), x = P + R((w1 + w2) t)(X - P0), and its time derivative
 * v = w1 a x (P - C) + (w1 + w2) a x (x - P), to 1e-11 after 2e5 steps (no drift: both
 * angles are accumulated). Crossed axes: the nodes moved as LIGGGHTS moves them, each
 * step turned by w1 dt about C (the first mover's point, put back each step), the spin
 * point with them, then by w2 dt about the spin point, iterated here with the quaternion
 * formula, to 1e-11. */
static void test_motion_spin(void)
{
    rs_motion m;
    rs_error err;
    double a[3] = {0.0, 0.0, 2.0}, C[3] = {0.1, -0.2, 0.0}, P0[3] = {0.4, 0.1, 0.3};
    const double w1 = 1.3, w2 = -4.1, dt = 1e-5;
    const int N = 200000;
    rs_motion_init(&m);
    ENSURE(rs_motion_set_rotation(&m, C, a, w1, &err) == RS_OK);
    ENSURE(rs_motion_set_spin(&m, P0, a, w2, &err) == RS_OK);
    unit(a);
    for (int k = 0; k < N; k++)
        ENSURE(rs_motion_advance(&m, dt, &err) == RS_OK);
    const double t = N * dt, zero[3] = {0, 0, 0};
    double P[3];
    closed_form(C, zero, a, w1 * t, P0, P);
    const double pts[3][3] = {{0, 0, 0}, {1.5, -2.5, 0.5}, {-3, 1, 4}};
    for (int q = 0; q < 3; q++) {
        double x[3], xr[3], v[3], r1[3], r2[3], w1a[3], wa[3];
        rs_pose_to_global(&m.pose, pts[q], x);
        const double d[3] = {0, 0, 0};
        closed_form(P0, d, a, (w1 + w2) * t, pts[q], xr);
        for (int i = 0; i < 3; i++)
            ENSURE_NEAR(x[i], xr[i] + P[i] - P0[i], 1e-11);
        rs_motion_velocity_at(&m, x, v);
        const double pc[3] = {P[0] - C[0], P[1] - C[1], P[2] - C[2]};
        const double xp[3] = {x[0] - P[0], x[1] - P[1], x[2] - P[2]};
        for (int i = 0; i < 3; i++) {
            w1a[i] = w1 * a[i];
            wa[i] = (w1 + w2) * a[i];
        }
        rs_cross3(w1a, pc, r1);
        rs_cross3(wa, xp, r2);
        for (int i = 0; i < 3; i++)
            ENSURE_NEAR(v[i], r1[i] + r2[i], 1e-12);
    }

    /* crossed axes */
    double b[3] = {1.0, 0.2, 0.0}, c2[3] = {0.0, 0.3, 1.0};
    const int M = 20000;
    rs_motion_init(&m);
    ENSURE(rs_motion_set_rotation(&m, C, b, w1, &err) == RS_OK);
    ENSURE(rs_motion_set_spin(&m, P0, c2, w2, &err) == RS_OK);
    unit(b);
    unit(c2);
    double node[3][3], ref[3];
    memcpy(node, pts, sizeof node);
    memcpy(ref, P0, sizeof ref);
    for (int k = 0; k < M; k++) {
        /* the spin starts halfway, so the steps' increments differ and their order
         * counts */
        const double ws = k < M / 2 ? 0.0 : w2;
        m.spin_omega = ws;
        ENSURE(rs_motion_advance(&m, dt, &err) == RS_OK);
        double r[3], dd[3];
        for (int q = 0; q < 4; q++) {
            double *y = q < 3 ? node[q] : ref;
            for (int i = 0; i < 3; i++)
                dd[i] = y[i] - C[i];
            quat_rotate(b, w1 * dt, dd, r);
            for (int i = 0; i < 3; i++)
                y[i] = C[i] + r[i];
        }
        for (int q = 0; q < 3; q++) {
            for (int i = 0; i < 3; i++)
                dd[i] = node[q][i] - ref[i];
            quat_rotate(c2, ws * dt, dd, r);
            for (int i = 0; i < 3; i++)
                node[q][i] = ref[i] + r[i];
        }
    }
    for (int q = 0; q < 3; q++) {
        double x[3];
        rs_pose_to_global(&m.pose, pts[q], x);
        for (int i = 0; i < 3; i++)
            ENSURE_NEAR(x[i], node[q][i], 1e-11);
    }
    /* this step's increment: the spin's rotation after the first one's */
    for (int j = 0; j < 3; j++) {
        double e[3] = {0, 0, 0}, r[3], r2[3];
        e[j] = 1.0;
        quat_rotate(b, w1 * dt, e, r);
        quat_rotate(c2, w2 * dt, r, r2);
        for (int i = 0; i < 3; i++)
            ENSURE_NEAR(m.dQ[3 * i + j], r2[i], 1e-15);
    }
    ENSURE(rs_motion_set_spin(&m, P0, zero, 1.0, &err) == RS_ERR_ARG);
}

/* Rates from a callback are taken at mid-step, which integrates linear rates exactly:
 * omega = a + b t gives phi = a t + b t^2 / 2; V = (c t, 0, 0) gives D = (c t^2 / 2, 0, 0).
 */
typedef struct rates_log {
    int calls;
    double last_t;
} rates_log;

static int linear_rates(double t, double vel[3], double *omega, void *ctx)
{
    rates_log *log = (rates_log *)ctx;
    log->calls++;
    log->last_t = t;
    vel[0] = 0.8 * t;
    vel[1] = 0.0;
    vel[2] = 0.0;
    *omega = 1.5 - 0.4 * t;
    return 0;
}

static int stop_rates(double t, double vel[3], double *omega, void *ctx)
{
    (void)vel;
    (void)omega;
    (void)ctx;
    return t > 0.05;
}

static void test_motion_rates_callback(void)
{
    rs_motion m;
    rs_error err;
    rates_log log = {0, 0.0};
    double axis[3] = {0, 0, 1}, C[3] = {0.5, 0, 0};
    rs_motion_init(&m);
    ENSURE(rs_motion_set_rotation(&m, C, axis, 0.0, &err) == RS_OK);
    m.rates = linear_rates;
    m.ctx = &log;
    const int N = 400;
    const double dt = 0.01;
    for (int k = 0; k < N; k++)
        ENSURE(rs_motion_advance(&m, dt, &err) == RS_OK);
    double t = N * dt;
    ENSURE(log.calls == N);
    ENSURE_NEAR(log.last_t, t - 0.5 * dt, 1e-12);
    ENSURE_NEAR(m.phi, 1.5 * t - 0.2 * t * t, 1e-12);
    double X[3] = {1.5, 0.0, 0.0}, x[3], xr[3], D[3] = {0.4 * t * t, 0, 0};
    rs_pose_to_global(&m.pose, X, x);
    closed_form(C, D, axis, 1.5 * t - 0.2 * t * t, X, xr);
    for (int i = 0; i < 3; i++)
        ENSURE_NEAR(x[i], xr[i], 1e-12);

    /* A callback that stops the run makes advance fail. */
    rs_motion s;
    rs_motion_init(&s);
    s.rates = stop_rates;
    int rc = RS_OK;
    for (int k = 0; k < 20 && rc == RS_OK; k++)
        rc = rs_motion_advance(&s, 0.01, &err);
    ENSURE(rc != RS_OK);
    ENSURE(err.code == rc);
    ENSURE(strstr(err.msg, "rates") != NULL);
}

/* A translation given as such (place): D is the callback's at each step, not the sum of
 * V dt, while V stays the rates' (a wall at A (1 - cos w t) with velocity A w sin w t, as
 * LAMMPS's wiggling wall); a rotation about C carried along turns about C + D; a
 * non-finite translation stops the run. */
typedef struct {
    double A, w, t;
} wiggle;

static int wiggle_place(double t, double disp[3], void *ctx)
{
    wiggle *g = ctx;
    g->t = t;
    disp[0] = 0.0;
    disp[1] = 0.0;
    disp[2] = g->A - g->A * cos(g->w * t);
    return 0;
}

static int wiggle_rates(double t, double vel[3], double *omega, void *ctx)
{
    const wiggle *g = ctx;
    vel[0] = vel[1] = 0.0;
    vel[2] = g->A * g->w * sin(g->w * t);
    *omega = 0.5;
    return 0;
}

static int nan_place(double t, double disp[3], void *ctx)
{
    (void)t, (void)ctx;
    disp[0] = disp[1] = 0.0;
    disp[2] = NAN;
    return 0;
}

static void test_motion_place(void)
{
    rs_motion m;
    rs_error err;
    wiggle g = {0.003, 2.0 * 3.141592653589793 / 0.01, 0.0};
    double axis[3] = {0, 0, 1}, C[3] = {0.1, 0.0, 0.0};
    rs_motion_init(&m);
    ENSURE(rs_motion_set_rotation(&m, C, axis, 0.0, &err) == RS_OK);
    m.rates = wiggle_rates;
    m.place = wiggle_place;
    m.ctx = &g;
    const double dt = 1e-4;
    for (int k = 1; k <= 137; k++) {
        ENSURE(rs_motion_advance(&m, dt, &err) == RS_OK);
        const double tm = g.t; /* the callbacks' time: mid-step */
        ENSURE_NEAR(tm, (k - 0.5) * dt, 1e-15);
        ENSURE(m.disp[2] == g.A - g.A * cos(g.w * tm));
        ENSURE(m.vel[2] == g.A * g.w * sin(g.w * tm));
    }
    double X[3] = {0.3, 0.2, -0.1}, x[3], xr[3], D[3] = {0.0, 0.0, m.disp[2]};
    rs_pose_to_global(&m.pose, X, x);
    closed_form(C, D, axis, 0.5 * 137 * dt, X, xr);
    for (int i = 0; i < 3; i++)
        ENSURE_NEAR(x[i], xr[i], 1e-14);
    double v[3], c[3];
    rs_motion_velocity_at(&m, X, v);
    rs_motion_center(&m, c);
    ENSURE(c[2] == m.disp[2]);
    ENSURE_NEAR(v[2], g.A * g.w * sin(g.w * 136.5 * dt), 1e-15);

    rs_motion s;
    rs_motion_init(&s);
    s.place = nan_place;
    ENSURE(rs_motion_advance(&s, dt, &err) != RS_OK);
    ENSURE(strstr(err.msg, "translation") != NULL);
}

static void test_motion_rejects_zero_axis(void)
{
    rs_motion m;
    rs_error err;
    double zero[3] = {0, 0, 0}, bad[3] = {NAN, 0, 1};
    rs_motion_init(&m);
    ENSURE(rs_motion_set_rotation(&m, zero, zero, 1.0, &err) == RS_ERR_ARG);
    ENSURE(strstr(err.msg, "axis") != NULL);
    ENSURE(rs_motion_set_rotation(&m, zero, bad, 1.0, &err) == RS_ERR_ARG);
    /* The failed calls left the default axis z. */
    ENSURE(m.axis[2] == 1.0);
}

/* Rodrigues matrix against the quaternion rotation for a few axes and angles. */
static void test_rotation_matrix_matches_quaternion(void)
{
    const double axes[3][3] = {{0, 0, 1}, {1, 1, 1}, {-0.3, 0.8, 0.1}};
    const double angles[4] = {1e-9, 0.7, -2.9, 3.14159};
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 4; b++) {
            double ax[3] = {axes[a][0], axes[a][1], axes[a][2]}, R[9];
            unit(ax);
            rs_rotation_matrix(ax, angles[b], R);
            for (int j = 0; j < 3; j++) {
                double e[3] = {0, 0, 0}, r[3];
                e[j] = 1.0;
                quat_rotate(ax, angles[b], e, r);
                for (int i = 0; i < 3; i++)
                    ENSURE_NEAR(R[3 * i + j], r[i], 1e-15);
            }
        }
}

/* The surface velocity at a contact: U's tangential part scaled to |U| (LIGGGHTS's
 * surface_vel rule), zero along the normal, and U itself in the tangent plane. */
static void test_surface_velocity(void)
{
    rs_motion m;
    rs_motion_init(&m);
    double u[3];
    const double nz[3] = {0, 0, 1};
    rs_motion_belt_at(&m, nz, u);
    ENSURE(u[0] == 0.0 && u[1] == 0.0 && u[2] == 0.0); /* none set */
    const double U[3] = {0.3, 0.0, 0.4};
    rs_motion_set_surface_velocity(&m, U);
    rs_motion_belt_at(&m, nz, u);
    ENSURE_NEAR(u[0], 0.5, 1e-15); /* (0.3, 0, 0) scaled to |U| = 0.5 */
    ENSURE(u[1] == 0.0 && u[2] == 0.0);
    const double nU[3] = {0.6, 0.0, 0.8}; /* along U: nothing tangential */
    rs_motion_belt_at(&m, nU, u);
    ENSURE_SMALL(rs_norm3(u), 1e-15);
    /* a tilted normal: u is tangent, |u| = |U| */
    const double c = cos(0.3), sn = sin(0.3);
    const double n2[3] = {sn, 0.0, c};
    rs_motion_belt_at(&m, n2, u);
    ENSURE_SMALL(rs_dot3(u, n2), 1e-15);
    ENSURE_NEAR(rs_norm3(u), 0.5, 1e-15);
    ENSURE(u[0] > 0.0);
}

int main(void)
{
    RS_RUN(test_motion_no_drift);
    RS_RUN(test_motion_velocity_at);
    RS_RUN(test_motion_superposed_translation_rotation);
    RS_RUN(test_motion_center_fixed);
    RS_RUN(test_motion_spin);
    RS_RUN(test_motion_rates_callback);
    RS_RUN(test_motion_place);
    RS_RUN(test_motion_rejects_zero_axis);
    RS_RUN(test_rotation_matrix_matches_quaternion);
    RS_RUN(test_surface_velocity);
    return rs_test_summary();
}
