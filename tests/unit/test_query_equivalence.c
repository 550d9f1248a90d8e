/* The block query against an independent brute-force distance to the profile, on blocks
 * larger than the query's internal chunk, with a pose, radii and points on the axis; a
 * block answers exactly as its points queried one at a time; and the compact form of
 * the query data (profile.h) answers exactly as the stored one, also through the whole
 * query of a REVOLUTION of one LINE, whose per-sphere face contacts
 * (rs_line_revolution_faces) are the block query's. */
#include "profile.h"
#include "line_revolution.h"
#include "rigidsurf/motion.h"
#include "rigidsurf/surface.h"
#define RS_TEST_SEED 0x2545F4914F6CDD1Dull
#include "rs_test.h"
#include "rs_test_geom.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Distance from (u, v) to segment g of the profile, written from the segment's end
 * points and centre only: LINE by the clamped projection, CIRCL by the radial
 * projection when its direction lies inside the sweep, else the nearer end. */
static double seg_distance(const rs_segment *g, double u, double v)
{
    if (g->type == RS_LINE) {
        double ex = g->p1[0] - g->p0[0], ey = g->p1[1] - g->p0[1];
        double t = ((u - g->p0[0]) * ex + (v - g->p0[1]) * ey) / (ex * ex + ey * ey);
        t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
        return hypot(u - (g->p0[0] + t * ex), v - (g->p0[1] + t * ey));
    }
    double c[2] = {g->pm[0], g->pm[1]};
    double a0 = atan2(g->p0[1] - c[1], g->p0[0] - c[0]);
    double a1 = atan2(g->p1[1] - c[1], g->p1[0] - c[0]);
    double sw = remainder(a1 - a0, 2.0 * RS_PI); /* arcs are under 180 degrees */
    double rad = hypot(g->p0[0] - c[0], g->p0[1] - c[1]);
    double rho = hypot(u - c[0], v - c[1]);
    double d0 = hypot(u - g->p0[0], v - g->p0[1]), d1 = hypot(u - g->p1[0], v - g->p1[1]);
    double best = d0 < d1 ? d0 : d1;
    if (rho > 0.0) {
        double a = remainder(atan2(v - c[1], u - c[0]) - a0, 2.0 * RS_PI);
        if (sw > 0.0 ? (a >= 0.0 && a <= sw) : (a <= 0.0 && a >= sw))
            best = fabs(rho - rad) < best ? fabs(rho - rad) : best;
    }
    return best;
}

static double profile_distance(const rs_surface *s, double u, double v)
{
    double best = INFINITY;
    for (int k = 0; k < s->profile.nseg; k++) {
        double d = seg_distance(&s->profile.seg[k], u, v);
        best = d < best ? d : best;
    }
    return best;
}

/* A random rotation (unit quaternion) and translation. */
static void random_pose(rs_pose *p, double scale)
{
    double q[4], l = 0.0;
    for (int j = 0; j < 4; j++) {
        q[j] = urand() - 0.5;
        l += q[j] * q[j];
    }
    l = sqrt(l);
    double w = q[0] / l, a = q[1] / l, b = q[2] / l, c = q[3] / l;
    double R[9] = {
        1 - 2 * (b * b + c * c), 2 * (a * b - c * w),     2 * (a * c + b * w),
        2 * (a * b + c * w),     1 - 2 * (a * a + c * c), 2 * (b * c - a * w),
        2 * (a * c - b * w),     2 * (b * c + a * w),     1 - 2 * (a * a + b * b)};
    memcpy(p->R, R, sizeof R);
    for (int d = 0; d < 3; d++)
        p->T[d] = scale * (urand() - 0.5);
}

/* The point of local coordinates L (along the surface's ex, ey, ez from a) in the
 * current configuration of pose. */
static void to_world(const rs_surface *s, const rs_pose *pose, const double L[3], double *x,
                     double *y, double *z)
{
    double X[3];
    for (int d = 0; d < 3; d++)
        X[d] = s->a[d] + L[0] * s->ex[d] + L[1] * s->ey[d] + L[2] * s->ez[d];
    *x = pose->R[0] * X[0] + pose->R[1] * X[1] + pose->R[2] * X[2] + pose->T[0];
    *y = pose->R[3] * X[0] + pose->R[4] * X[1] + pose->R[5] * X[2] + pose->T[1];
    *z = pose->R[6] * X[0] + pose->R[7] * X[1] + pose->R[8] * X[2] + pose->T[2];
}

/* Every point of a block of 1000 (several internal chunks) gets its contacts, in block
 * order, the smallest |dist| of a point's contacts is its brute-force distance to the
 * profile, and each contact's xm lies |dist| from the point. */
static void check_block_against_brute_force(const char *deck, int revolution)
{
    rs_surface s;
    ENSURE(parse(deck, &s) == 0);
    enum { N = 1000 };
    static double x[N], y[N], z[N], r[N], pu[N], pv[N];
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int k = 0; k < s.profile.nseg; k++)
        for (int a = 0; a < 2; a++) {
            lo[a] = fmin(lo[a], fmin(s.profile.seg[k].p0[a], s.profile.seg[k].p1[a]));
            hi[a] = fmax(hi[a], fmax(s.profile.seg[k].p0[a], s.profile.seg[k].p1[a]));
        }
    double size = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    rs_pose pose;
    random_pose(&pose, size);
    for (int i = 0; i < N; i++) {
        double u = lo[0] - 0.2 * size + (hi[0] - lo[0] + 0.4 * size) * urand();
        double v = lo[1] - 0.2 * size + (hi[1] - lo[1] + 0.4 * size) * urand();
        double L[3];
        if (revolution) {
            u = fabs(u);
            if (i % 17 == 0)
                u = 0.0; /* on the axis */
            double th = 2.0 * RS_PI * urand();
            L[0] = u * cos(th);
            L[1] = u * sin(th);
            L[2] = v;
        } else {
            L[0] = u;
            L[1] = v;
            L[2] = urand() - 0.5;
        }
        pu[i] = u;
        pv[i] = v;
        to_world(&s, &pose, L, x + i, y + i, z + i);
        r[i] = 0.01 * size * urand();
    }
    /* gap_max beyond the sampling box: every point reaches its closest feature */
    rs_query q = {.n = N,
                  .slave = {.x = x, .y = y, .z = z, .radius = r},
                  .pose = &pose,
                  .gap_max = 2.0 * size,
                  .dist_min = -INFINITY};
    rs_contacts c = {0};
    ENSURE(rs_surface_query(&s, &q, &c, NULL) == 0);
    int k = 0;
    for (int i = 0; i < N; i++) {
        ENSURE(k < c.n && c.point[k] == i);
        double best = INFINITY;
        for (; k < c.n && c.point[k] == i; k++) {
            double P[3] = {x[i], y[i], z[i]};
            double dx = P[0] - c.xm[0][k], dy = P[1] - c.xm[1][k], dz = P[2] - c.xm[2][k];
            ENSURE_NEAR(sqrt(dx * dx + dy * dy + dz * dz), fabs(c.dist[k]), 1e-12 * size);
            best = fabs(c.dist[k]) < best ? fabs(c.dist[k]) : best;
        }
        ENSURE_NEAR(best, profile_distance(&s, pu[i], pv[i]), 1e-12 * size);
    }
    ENSURE(k == c.n);

    /* the same block point by point: the same contacts, value for value */
    rs_contacts c1 = {0};
    k = 0;
    for (int i = 0; i < N; i++) {
        rs_query q1 = {.n = 1,
                       .slave = {.x = x + i, .y = y + i, .z = z + i, .radius = r + i},
                       .pose = &pose,
                       .gap_max = 2.0 * size,
                       .dist_min = -INFINITY};
        c1.n = 0;
        ENSURE(rs_surface_query(&s, &q1, &c1, NULL) == 0);
        for (int h = 0; h < c1.n; h++, k++) {
            ENSURE(k < c.n && c.point[k] == i && c.feature[k] == c1.feature[h]);
            for (int d = 0; d < 3; d++) {
                ENSURE(c.xm[d][k] == c1.xm[d][h] && c.nrm[d][k] == c1.nrm[d][h]);
                ENSURE(c.t1[d][k] == c1.t1[d][h] && c.t2[d][k] == c1.t2[d][h]);
            }
            ENSURE(c.dist[k] == c1.dist[h]);
            ENSURE(c.curv[0][k] == c1.curv[0][h] && c.curv[1][k] == c1.curv[1][h]);
        }
    }
    ENSURE(k == c.n);
    rs_contacts_free(&c1);
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* A drum with filleted rims seen from both sides (faces, arcs, the axis). */
static void test_query_block_revolution_two_sides_is_brute_force_closest(void)
{
    check_block_against_brute_force("*SURFACE, TYPE=REVOLUTION, NAME=d, SIDES=2, FILLET "
                                    "RADIUS=0.02\n0,0,0, 0,0,1\nSTART, 0, -0.05\n"
                                    "LINE, 0.15, -0.05\nLINE, 0.15, 0.05\nLINE, 0, 0.05\n",
                                    1);
}

/* A closed one-sided profile with convex and concave corners: points inside the solid
 * take the Voronoi rule, the start vertex of the closed profile its wrap-around. */
static void test_query_block_closed_one_side_is_brute_force_closest(void)
{
    check_block_against_brute_force("*SURFACE, TYPE=CYLINDER, NAME=c\n0,0,0, 1,0,0\n0,0,1\n"
                                    "START, 0, 0\nLINE, 2, 0\nLINE, 2, 2\nLINE, 1, 0.8\n"
                                    "LINE, 0, 2\nLINE, 0, 0\n",
                                    0);
}

/* An open profile of lines and arcs seen from both sides: END vertices at both ends own
 * the half planes beyond them. */
static void test_query_block_open_lines_and_arcs_is_brute_force_closest(void)
{
    check_block_against_brute_force(
        "*SURFACE, TYPE=CYLINDER, NAME=o, SIDES=2\n0.1,0.2,0.3, "
        "1.1,0.2,0.3\n0.1,0.2,1.3\nSTART, -1, 0\nLINE, 0, 0\n"
        "CIRCL, 1, 1, 0, 1\nLINE, 1, 2\nCIRCL, 2, 3, 2, 2\n",
        0);
}

/* A profile of nseg segments, turned by 30 degrees in its plane: tall teeth, collinear
 * runs (LINE chains) and arcs, queried one-sided at a reach of a few segment lengths,
 * and with SIDES=2 at a reach of 1200, or 6000 in the compact form, where points meet
 * more segments than its first scratch holds (one-sided, a point far behind an open end is
 * nearest to that end, which owns only the particle side). Each point near the profile
 * gets, as its nearest contact, its brute-force distance over all segments; a point beyond
 * reach gets none. */
static void check_large_profile(int nseg, int sides)
{
    enum { N = 4000, MAXSEG = 24000 };
    static char deck[MAXSEG * 80 + 256];
    ENSURE(nseg <= MAXSEG);
    const double h = 1.0 / nseg, c30 = cos(RS_PI / 6), s30 = sin(RS_PI / 6);
    size_t o = (size_t)snprintf(deck, sizeof deck,
                                "*SURFACE, TYPE=SEGMENTS, NAME=big%s\nSTART, 0, 0\n",
                                sides == 2 ? ", SIDES=2" : "");
    for (int k = 1; k <= nseg; k++) {
        const int part = (k / 1000) % 3;
        double P[2] = {k * h, part == 0 && k % 2 ? 4.0 * h : 0.0},
               C[2] = {(k - 0.5) * h, (k % 2 ? 1.0 : -1.0) * h};
        const double X = c30 * P[0] - s30 * P[1], Y = s30 * P[0] + c30 * P[1];
        if (part < 2) /* teeth, then a collinear run */
            o += (size_t)snprintf(deck + o, sizeof deck - o, "LINE, %.17g, %.17g\n", X, Y);
        else /* arcs, alternately bulging up and down */
            o += (size_t)snprintf(deck + o, sizeof deck - o,
                                  "CIRCL, %.17g, %.17g, %.17g, %.17g\n", X, Y,
                                  c30 * C[0] - s30 * C[1], s30 * C[0] + c30 * C[1]);
    }
    rs_surface s;
    ENSURE(parse(deck, &s) == 0);
    ENSURE(s.profile.nseg == nseg);
    ENSURE((((const rs_pcache *)s.impl)->ps == NULL) == (nseg > RS_PC_LARGE));
    for (int far = sides - 1; far < sides; far++) {
        const double reach = (far ? (nseg > RS_PC_LARGE ? 6000.0 : 1200.0) : 3.0) * h;
        const int m = far ? 300 : N;
        static double x[N], y[N], z[N];
        for (int i = 0; i < m; i++) {
            const double u = urand(),
                         v = (far ? 3000.0 * urand() - 1000.0 : 8.0 * urand() - 2.0) * h;
            x[i] = c30 * u - s30 * v;
            y[i] = s30 * u + c30 * v;
            z[i] = 0.0;
        }
        rs_query q = {.n = m,
                      .slave = {.x = x, .y = y, .z = z},
                      .pose = NULL,
                      .gap_max = reach,
                      .dist_min = -reach};
        rs_contacts c = {0};
        ENSURE(rs_surface_query(&s, &q, &c, NULL) == 0);
        int k = 0, checked = 0;
        for (int i = 0; i < m; i++) {
            double best = INFINITY;
            for (; k < c.n && c.point[k] == i; k++)
                best = fabs(c.dist[k]) < best ? fabs(c.dist[k]) : best;
            const double d = profile_distance(&s, x[i], y[i]);
            if (d <= 0.99 * reach) {
                ENSURE_NEAR(best, d, 1e-12);
                checked++;
            } else if (d > 1.01 * reach) {
                ENSURE(best == INFINITY);
            }
        }
        ENSURE(k == c.n);
        ENSURE(checked > m / 2);
        rs_contacts_free(&c);
    }
    rs_surface_free(&s);
}

/* The compact form (more than RS_PC_LARGE segments), and the stored form at 3000
 * segments, whose bucket lists serve reaches up to a few segment lengths: the reach of
 * 1200 walks its tree. */
static void test_query_large_profile_is_brute_force_closest(void)
{
    check_large_profile(24000, 1);
    check_large_profile(24000, 2);
    check_large_profile(3000, 2);
}

/* The profile-plane contacts of every point of pts through pc (the loop of query.c). */
static void plane_contacts(const rs_pcache *pc, const rs_ppoints *pts, rs_contacts *c)
{
    rs_pscratch sc;
    ENSURE(rs_pscratch_init(&sc, pc, NULL, 0) == 0);
    c->n = 0;
    for (int i = 0;;) {
        int need = 0;
        i = rs_pcache_points(pc, pts, i, c, &sc, &need);
        if (i >= pts->n)
            break;
        ENSURE(need > 0 && rs_contacts_reserve(c, 2 * (c->n + need) + 64, NULL) == 0);
    }
    rs_pscratch_free(&sc);
}

/* The stored and the compact form of one profile's query data give the same contacts,
 * value for value, in the same order, for points around the profile at reaches from
 * zero to a third of its size, with and without a lower distance limit. */
static void check_compact_is_stored(const char *deck, double reach_frac)
{
    rs_surface s;
    ENSURE(parse(deck, &s) == 0);
    rs_pcache *st = NULL, *cp = NULL;
    ENSURE(rs_pcache_build_as(&s, 0, &st, NULL) == 0 && st->ps && st->pv);
    ENSURE(rs_pcache_build_as(&s, 1, &cp, NULL) == 0 && !cp->ps && !cp->pv);
    for (int i = 0; i < 4; i++)
        ENSURE(st->box[i] == cp->box[i]);
    enum { N = 3000 };
    static double u[N], v[N], dh[N];
    const double *b = st->box, size = fmax(b[1] - b[0], b[3] - b[2]);
    for (int pass = 0; pass < 2; pass++) {
        for (int i = 0; i < N; i++) {
            u[i] = b[0] - 0.1 * size + (b[1] - b[0] + 0.2 * size) * urand();
            v[i] = b[2] - 0.1 * size + (b[3] - b[2] + 0.2 * size) * urand();
            if (s.kind == RS_SURF_REVOLUTION)
                u[i] = fabs(u[i]);
            dh[i] = i % 97 == 0 ? NAN : reach_frac * size * urand();
        }
        const rs_ppoints pts = {N, u, v, dh, pass ? -0.01 * size : -INFINITY, 0};
        rs_contacts a = {0}, c = {0};
        plane_contacts(st, &pts, &a);
        plane_contacts(cp, &pts, &c);
        ENSURE(a.n == c.n && a.n > N / 4);
        for (int k = 0; k < a.n; k++) {
            ENSURE(a.point[k] == c.point[k] && a.feature[k] == c.feature[k]);
            ENSURE(a.xm[0][k] == c.xm[0][k] && a.xm[1][k] == c.xm[1][k]);
            ENSURE(a.nrm[0][k] == c.nrm[0][k] && a.nrm[1][k] == c.nrm[1][k]);
            ENSURE(a.dist[k] == c.dist[k] && a.curv[0][k] == c.curv[0][k]);
        }
        rs_contacts_free(&a);
        rs_contacts_free(&c);
    }
    free(st);
    free(cp);
    rs_surface_free(&s);
}

static void test_query_compact_form_is_stored_form(void)
{
    /* the three decks above: fillets on a two-sided drum, a closed one-sided profile
     * with a pocket, an open profile of lines and arcs */
    check_compact_is_stored("*SURFACE, TYPE=REVOLUTION, NAME=d, SIDES=2, FILLET "
                            "RADIUS=0.02\n0,0,0, 0,0,1\nSTART, 0, -0.05\n"
                            "LINE, 0.15, -0.05\nLINE, 0.15, 0.05\nLINE, 0, 0.05\n",
                            0.3);
    check_compact_is_stored("*SURFACE, TYPE=CYLINDER, NAME=c\n0,0,0, 1,0,0\n0,0,1\n"
                            "START, 0, 0\nLINE, 2, 0\nLINE, 2, 2\nLINE, 1, 0.8\n"
                            "LINE, 0, 2\nLINE, 0, 0\n",
                            0.3);
    check_compact_is_stored("*SURFACE, TYPE=CYLINDER, NAME=o, SIDES=2\n0.1,0.2,0.3, "
                            "1.1,0.2,0.3\n0.1,0.2,1.3\nSTART, -1, 0\nLINE, 0, 0\n"
                            "CIRCL, 1, 1, 0, 1\nLINE, 1, 2\nCIRCL, 2, 3, 2, 2\n",
                            0.3);
    /* a hopper of parabolas and lines, one-sided, open at the axis */
    check_compact_is_stored("*SURFACE, TYPE=REVOLUTION, NAME=h\n0,0,0, 0,0,1\n"
                            "START, 0, 0\nLINE, 0.1, 0\nPARAB, 0.25, 0.1, 0.3, 0.3\n"
                            "LINE, 0.3, 0.6\nPARAB, 0.2, 0.7, 0.1, 0.72\n",
                            0.3);
    /* a random closed polygon of 300 LINE and CIRCL pieces (a star: convex and
     * concave corners, smooth runs), one side and two */
    for (int sides = 1; sides <= 2; sides++) {
        static char deck[300 * 90 + 256];
        size_t o = (size_t)snprintf(deck, sizeof deck,
                                    "*SURFACE, TYPE=SEGMENTS, NAME=star%s\nSTART, 1, 0\n",
                                    sides == 2 ? ", SIDES=2" : "");
        double X0 = 1.0, Y0 = 0.0;
        for (int k = 1; k <= 300; k++) {
            const double th = 2.0 * RS_PI * k / 300,
                         r = k == 300 ? 1.0 : 0.8 + 0.4 * urand();
            const double X = r * cos(th), Y = -r * sin(th);
            if (k % 3 == 0 && k != 300) {
                /* the centre off the chord's middle, either side: a bulge or a dent */
                const double c = (urand() < 0.5 ? -1.0 : 1.0) * (0.3 + 0.7 * urand());
                o += (size_t)snprintf(
                    deck + o, sizeof deck - o, "CIRCL, %.17g, %.17g, %.17g, %.17g\n", X, Y,
                    0.5 * (X0 + X) - c * (Y - Y0), 0.5 * (Y0 + Y) + c * (X - X0));
            } else {
                o += (size_t)snprintf(deck + o, sizeof deck - o, "LINE, %.17g, %.17g\n", X,
                                      Y);
            }
            X0 = X;
            Y0 = Y;
        }
        check_compact_is_stored(deck, 0.05);
    }
}

/* rs_line_revolution_faces on the points of q, in runs of 32 as the fix calls it: every
 * sphere it flags holds exactly one contact in the block query's list a (q's dist_min is
 * below minus the largest radius), and that contact is its own, value for value; and it
 * flags a good part of the points. Called on a list without master points, curvatures
 * and shares (NULL), it gives the same flags, frames, distances, points and features. */
static void check_line_faces(const rs_surface *s, const rs_query *q, const rs_contacts *a)
{
    ENSURE(rs_line_revolution(s));
    enum { RUN = 32 };
    rs_contacts f = {0}, g = {0};
    ENSURE(rs_contacts_reserve(&f, RUN, NULL) == 0);
    ENSURE(rs_contacts_reserve(&g, RUN, NULL) == 0);
    double *keep[6] = {g.xm[0], g.xm[1], g.xm[2], g.curv[0], g.curv[1], g.share};
    for (int d = 0; d < 3; d++)
        g.xm[d] = NULL;
    g.curv[0] = g.curv[1] = g.share = NULL;
    int face[RUN], gface[RUN], nface = 0, same = 1, lean = 1;
    for (int i0 = 0; i0 < q->n; i0 += RUN) {
        const int m = q->n - i0 < RUN ? q->n - i0 : RUN;
        rs_line_revolution_faces(s, q->pose, m, q->slave.x + i0, q->slave.y + i0,
                                 q->slave.z + i0, q->slave.radius + i0, q->gap_max, &f,
                                 face);
        ENSURE(f.n == m);
        rs_frame_orient(s->ops->frame, &f, 0, m);
        rs_line_revolution_faces(s, q->pose, m, q->slave.x + i0, q->slave.y + i0,
                                 q->slave.z + i0, q->slave.radius + i0, q->gap_max, &g,
                                 gface);
        ENSURE(g.n == m);
        rs_frame_orient(s->ops->frame, &g, 0, m);
        for (int j = 0; j < m; j++) {
            lean &= gface[j] == face[j] && g.point[j] == f.point[j] &&
                    g.feature[j] == f.feature[j] && g.dist[j] == f.dist[j];
            for (int d = 0; d < 3; d++)
                lean &= g.nrm[d][j] == f.nrm[d][j] && g.t1[d][j] == f.t1[d][j] &&
                        g.t2[d][j] == f.t2[d][j];
        }
        for (int j = 0; j < m; j++) {
            if (!face[j])
                continue;
            nface++;
            int hits = 0, k = -1;
            for (int e = 0; e < a->n; e++)
                if (a->point[e] == i0 + j)
                    hits++, k = e;
            same &= hits == 1 && f.point[j] == j;
            if (hits != 1)
                continue;
            same &= a->feature[k] == f.feature[j];
            for (int d = 0; d < 3; d++)
                same &= a->xm[d][k] == f.xm[d][j] && a->nrm[d][k] == f.nrm[d][j] &&
                        a->t1[d][k] == f.t1[d][j] && a->t2[d][k] == f.t2[d][j];
            same &= a->dist[k] == f.dist[j] && a->curv[0][k] == f.curv[0][j] &&
                    a->curv[1][k] == f.curv[1][j] &&
                    (a->share ? a->share[k] : 1.0) == f.share[j];
        }
    }
    ENSURE(same);
    ENSURE(lean);
    ENSURE(nface > q->n / 8);
    rs_contacts_free(&f);
    for (int d = 0; d < 3; d++)
        g.xm[d] = keep[d];
    g.curv[0] = keep[3], g.curv[1] = keep[4], g.share = keep[5];
    rs_contacts_free(&g);
}

/* A REVOLUTION whose profile is one LINE (a cylinder's mantle, a cone) answers through
 * the stored form's one-LINE path (closest.c, points_one_line) exactly as through the
 * compact form, which takes each point alone (rs_pcache_hits): the whole query (rings
 * about the axis, frames, shares), value for value. Blocks of points near the line only
 * (every point of a run a face contact), of points half of them beyond reach, and of
 * points all around (end vertices, behind a one-sided face, the axis), in a pose. */
static void check_one_line(const char *deck)
{
    rs_surface s;
    ENSURE(parse(deck, &s) == 0);
    ENSURE(s.profile.nseg == 1 && s.profile.seg[0].type == RS_LINE);
    rs_pcache *cp = NULL;
    ENSURE(rs_pcache_build_as(&s, 1, &cp, NULL) == 0 && !cp->ps);
    const rs_segment *g = &s.profile.seg[0];
    const double size = hypot(g->p1[0] - g->p0[0], g->p1[1] - g->p0[1]);
    enum { N = 700 };
    static double x[N], y[N], z[N], r[N];
    for (int kind = 0; kind < 3; kind++) {
        rs_pose pose;
        random_pose(&pose, size);
        for (int i = 0; i < N; i++) {
            double u, v;
            const double tau = kind == 2 ? 1.4 * urand() - 0.2 : 0.05 + 0.9 * urand();
            /* a point off the line along its normal, within its reach or (kind 1, every
             * other point) beyond it */
            const double ex = (g->p1[0] - g->p0[0]) / size,
                         ey = (g->p1[1] - g->p0[1]) / size;
            const double off = kind == 2   ? 0.6 * size * (urand() - 0.5)
                               : kind == 1 ? (i % 2 ? 0.01 : 0.2) * size * urand()
                                           : 0.01 * size * urand();
            u = fabs(g->p0[0] + tau * (g->p1[0] - g->p0[0]) - off * ey);
            v = g->p0[1] + tau * (g->p1[1] - g->p0[1]) + off * ex;
            if (kind == 2 && i % 17 == 0)
                u = 0.0; /* on the axis */
            const double th = 2.0 * RS_PI * urand();
            const double L[3] = {u * cos(th), u * sin(th), v};
            to_world(&s, &pose, L, x + i, y + i, z + i);
            r[i] = 0.02 * size * (0.5 + urand());
        }
        rs_query q = {.n = N,
                      .slave = {.x = x, .y = y, .z = z, .radius = r},
                      .pose = &pose,
                      .gap_max = (kind == 2 ? 0.3 : 0.01) * size,
                      .dist_min = -(kind == 2 ? 0.3 : 0.05) * size};
        rs_contacts a = {0}, c = {0};
        ENSURE(rs_surface_query(&s, &q, &a, NULL) == 0);
        void *stored = s.impl;
        s.impl = cp;
        ENSURE(rs_surface_query(&s, &q, &c, NULL) == 0);
        s.impl = stored;
        ENSURE(a.n == c.n && a.n > N / 4);
        int same = 1;
        for (int k = 0; k < a.n && k < c.n; k++) {
            same &= a.point[k] == c.point[k] && a.feature[k] == c.feature[k];
            for (int d = 0; d < 3; d++)
                same &= a.xm[d][k] == c.xm[d][k] && a.nrm[d][k] == c.nrm[d][k] &&
                        a.t1[d][k] == c.t1[d][k] && a.t2[d][k] == c.t2[d][k];
            same &= a.dist[k] == c.dist[k] && a.curv[0][k] == c.curv[0][k] &&
                    a.curv[1][k] == c.curv[1][k];
            same &= (a.share ? a.share[k] : 1.0) == (c.share ? c.share[k] : 1.0);
        }
        ENSURE(same);
        check_line_faces(&s, &q, &a);
        rs_contacts_free(&a);
        rs_contacts_free(&c);
    }
    free(cp);
    rs_surface_free(&s);
}

static void test_query_one_line_revolution_is_compact_form(void)
{
    /* a cylinder's mantle seen from inside, from both sides, and in a pose of its own */
    check_one_line("*SURFACE, TYPE=REVOLUTION, NAME=m\n0,0,0, 0,0,1\n"
                   "START, 0.15, 0.05\nLINE, 0.15, -0.05\n");
    check_one_line("*SURFACE, TYPE=REVOLUTION, NAME=m, SIDES=2\n0,0,0, 0,0,1\n"
                   "START, 0.15, 0.05\nLINE, 0.15, -0.05\n");
    check_one_line("*SURFACE, TYPE=REVOLUTION, NAME=m\n0.1,-0.2,0.3, 0.6,0,0.8\n"
                   "START, 0.15, 0.05\nLINE, 0.15, -0.05\n");
    /* a cone, and a cone from the axis (a funnel's tip) */
    check_one_line("*SURFACE, TYPE=REVOLUTION, NAME=c\n0,0,0, 0,0,1\n"
                   "START, 0.2, 0.1\nLINE, 0.05, -0.1\n");
    check_one_line("*SURFACE, TYPE=REVOLUTION, NAME=c, SIDES=2\n0,0,0, 0,0,1\n"
                   "START, 0.2, 0.1\nLINE, 0, -0.1\n");
}

/* A REVOLUTION profile about z: a cap from the axis to (r0, -H), npc collinear LINE
 * pieces to (r1, H), a cap back to the axis. */
static void parse_chain(int sides, double r0, double r1, double H, int npc, rs_surface *s)
{
    char deck[4096];
    int o = snprintf(deck, sizeof deck,
                     "*SURFACE, TYPE=REVOLUTION, NAME=chain%s\n0,0,0, 0,0,1\n"
                     "START, 0, %.17g\nLINE, %.17g, %.17g\n",
                     sides == 2 ? ", SIDES=2" : "", -H, r0, -H);
    for (int k = 1; k <= npc; k++)
        o += snprintf(deck + o, sizeof deck - (size_t)o, "LINE, %.17g, %.17g\n",
                      r0 + (r1 - r0) * k / npc, -H + 2.0 * H * k / npc);
    snprintf(deck + o, sizeof deck - (size_t)o, "LINE, 0, %.17g\n", H);
    ENSURE(parse(deck, s) == 0);
}

/* The verdict of a chain check: no bad contact, every contact read, and more than a
 * quarter of the n points with a contact (40 % lie within reach). */
static void chain_verdict(int bad, int k, int seen, int n, rs_contacts *c, rs_surface *s)
{
    ENSURE(bad == 0);
    ENSURE(k == c->n);
    ENSURE(seen > n / 4);
    rs_contacts_free(c);
    rs_surface_free(s);
}

/* A drum whose mantle is npc collinear LINE pieces from z = -H to H at r = R, between
 * two caps, with a reach (gap_max = -dist_min = h) far below a piece's length, so the
 * points see a chain of pieces. Expected, from the line alone: a point whose projection
 * lies inside a piece (and away from the caps) has exactly one contact, that piece's
 * face, with dist = R - r (SIDES=1: any |R - r| <= h; SIDES=2: dist = |R - r| <= h),
 * and none when |R - r| > h. */
static void check_collinear_chain(int sides, int npc)
{
    const double R = 0.15, H = 0.05, h = 0.004;
    rs_surface s;
    parse_chain(sides, R, R, H, npc, &s);
    enum { N = 2000 };
    static double x[N], y[N], z[N];
    for (int i = 0; i < N; i++) {
        const double rr = R + 2.5 * h * (2.0 * urand() - 1.0), th = 2.0 * RS_PI * urand();
        x[i] = rr * cos(th);
        y[i] = rr * sin(th);
        z[i] = (H - 2.0 * h) * (2.0 * urand() - 1.0);
    }
    rs_query q = {.n = N,
                  .slave = {.x = x, .y = y, .z = z},
                  .pose = NULL,
                  .gap_max = h,
                  .dist_min = -h};
    rs_contacts c = {0};
    ENSURE(rs_surface_query(&s, &q, &c, NULL) == 0);
    int k = 0, bad = 0, seen = 0;
    for (int i = 0; i < N; i++) {
        const double rr = hypot(x[i], y[i]), sd = R - rr, dist = sides == 2 ? fabs(sd) : sd;
        /* the piece: pieces 1..npc of the profile (0 is the bottom cap) */
        const double f = (z[i] + H) / (2.0 * H) * npc;
        const int piece = 1 + (int)f;
        const int near_joint = fabs(f - floor(f + 0.5)) < 1e-9;
        int nk = 0;
        for (; k < c.n && c.point[k] == i; k++, nk++) {
            bad += c.feature[k] != RS_FEATURE(RS_FEAT_FACE, piece) && !near_joint;
            bad += fabs(c.dist[k] - dist) > 1e-12;
            bad += fabs(c.xm[2][k] - z[i]) > 1e-12;
        }
        bad += nk != (fabs(sd) <= h ? 1 : 0);
        seen += nk;
    }
    chain_verdict(bad, k, seen, N, &c, &s);
}

/* Collinear pieces of a drum's mantle, one- and two-sided, few and many. */
static void test_query_collinear_chain_gives_one_face_contact(void)
{
    check_collinear_chain(1, 6);
    check_collinear_chain(2, 6);
    check_collinear_chain(1, 62);
    check_collinear_chain(2, 3);
}

/* A cone (REVOLUTION) whose mantle is npc collinear LINE pieces from (r, z) = (r0, -H)
 * to (r1, H), closed by caps to the axis: the chain runs oblique to both profile axes,
 * so its pieces' slabs cross the buckets at an angle. Expected, from the line alone:
 * with t the unit direction of the line and n = (-t_z, t_r) its normal, a point whose
 * projection s lies inside the mantle, away from the caps, has one contact when its
 * distance sd = (p - p0).n is within the reach h (SIDES=1: -h <= sd <= h, dist = sd;
 * SIDES=2: dist = |sd|), the face of the piece that holds s (either piece within 1e-9
 * of a joint), at the projection; none when |sd| > h. */
static void check_oblique_chain(int sides, int npc)
{
    const double r0 = 0.05, r1 = 0.15, H = 0.1, h = 0.004;
    rs_surface s;
    parse_chain(sides, r0, r1, H, npc, &s);
    const double L = hypot(r1 - r0, 2.0 * H), tr = (r1 - r0) / L, tz = 2.0 * H / L;
    const double nr = -tz, nz = tr;
    enum { N = 4000 };
    static double x[N], y[N], z[N], sp[N], dp[N];
    for (int i = 0; i < N; i++) {
        /* every fourth point projects within 1e-12 of a joint; all project inside
         * [0.1, 0.9] L, farther than 2.5 h from the caps */
        double sj = (0.1 + 0.8 * urand()) * L;
        if (i % 4 == 0) {
            const double jlo = fmax(1.0, ceil(0.1 * npc)),
                         jhi = fmin(npc - 1.0, floor(0.9 * npc));
            const double jn = fmin(fmax(floor(sj / L * npc + 0.5), jlo), jhi);
            sj = L * jn / npc + 1e-12 * L * (2.0 * urand() - 1.0);
        }
        const double d = 2.5 * h * (2.0 * urand() - 1.0), th = 2.0 * RS_PI * urand();
        const double rr = r0 + sj * tr + d * nr;
        x[i] = rr * cos(th);
        y[i] = rr * sin(th);
        z[i] = -H + sj * tz + d * nz;
        sp[i] = sj;
        dp[i] = d;
    }
    rs_query q = {.n = N,
                  .slave = {.x = x, .y = y, .z = z},
                  .pose = NULL,
                  .gap_max = h,
                  .dist_min = -h};
    rs_contacts c = {0};
    ENSURE(rs_surface_query(&s, &q, &c, NULL) == 0);
    int k = 0, bad = 0, seen = 0;
    for (int i = 0; i < N; i++) {
        const double u = hypot(x[i], y[i]);
        const double sd = (u - r0) * nr + (z[i] + H) * nz;
        const double sproj = (u - r0) * tr + (z[i] + H) * tz;
        const double dist = sides == 2 ? fabs(sd) : sd;
        const double f = sproj / L * npc;
        const int piece = 1 + (int)f;
        const int near_joint = fabs(f - floor(f + 0.5)) < 1e-9 * npc;
        int nk = 0;
        for (; k < c.n && c.point[k] == i; k++, nk++) {
            const int fe = c.feature[k];
            bad +=
                fe != RS_FEATURE(RS_FEAT_FACE, piece) &&
                !(near_joint && (fe == RS_FEATURE(RS_FEAT_FACE, (int)floor(f + 0.5)) ||
                                 fe == RS_FEATURE(RS_FEAT_FACE, (int)floor(f + 0.5) + 1)));
            bad += fabs(c.dist[k] - dist) > 1e-12;
            const double ur = r0 + sproj * tr, uz = -H + sproj * tz;
            bad += fabs(hypot(c.xm[0][k], c.xm[1][k]) - ur) > 1e-12;
            bad += fabs(c.xm[2][k] - uz) > 1e-12;
        }
        bad += nk != (fabs(sd) <= h ? 1 : 0);
        seen += nk;
        bad += fabs(sd - dp[i]) > 1e-12 || fabs(sproj - sp[i]) > 1e-12;
    }
    chain_verdict(bad, k, seen, N, &c, &s);
}

/* Collinear pieces of a cone's mantle, oblique to the profile axes, one- and two-sided,
 * few and many. */
static void test_query_oblique_chain_gives_one_face_contact(void)
{
    check_oblique_chain(1, 7);
    check_oblique_chain(2, 7);
    check_oblique_chain(1, 40);
    check_oblique_chain(2, 3);
}

int main(void)
{
    RS_RUN(test_query_block_revolution_two_sides_is_brute_force_closest);
    RS_RUN(test_query_block_closed_one_side_is_brute_force_closest);
    RS_RUN(test_query_block_open_lines_and_arcs_is_brute_force_closest);
    RS_RUN(test_query_large_profile_is_brute_force_closest);
    RS_RUN(test_query_compact_form_is_stored_form);
    RS_RUN(test_query_one_line_revolution_is_compact_form);
    RS_RUN(test_query_collinear_chain_gives_one_face_contact);
    RS_RUN(test_query_oblique_chain_gives_one_face_contact);
    return rs_test_summary();
}
