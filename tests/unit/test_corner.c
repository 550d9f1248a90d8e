/* Corners (docs/conventions.md, "One contact = (particle, surface, feature)"): a sphere in
 * a concave corner gets two contacts, at a convex corner one vertex contact (never two
 * faces, never none); fillets make the normal continuous; a point sweeping along the
 * wall sees rdisp1 change by no more than the step (distance is 1-Lipschitz). */
#include "rigidsurf/surface.h"
#include "rs_test.h"
#include "rs_test_geom.h"

#include <math.h>
#include <stdlib.h>

static int query(const rs_surface *s, double x, double y, double rad, double gap,
                 rs_contacts *c)
{
    double z = 0.0;
    rs_query q = {.n = 1,
                  .slave = {.x = &x, .y = &y, .z = &z, .radius = &rad},
                  .pose = NULL,
                  .gap_max = gap,
                  .dist_min = -INFINITY};
    c->n = 0;
    return rs_surface_query(s, &q, c, NULL);
}

/* distance from P to the segment a-b */
static double seg_dist(const double a[2], const double b[2], double px, double py)
{
    double e[2] = {b[0] - a[0], b[1] - a[1]};
    double t = ((px - a[0]) * e[0] + (py - a[1]) * e[1]) / (e[0] * e[0] + e[1] * e[1]);
    t = fmin(1.0, fmax(0.0, t));
    return hypot(px - a[0] - t * e[0], py - a[1] - t * e[1]);
}

/* Floor (-2,0)-(0,0) then wall (0,0)-(0,2): a left turn, a pocket for the particles. */
static void test_corner_concave_gives_two_contacts(void)
{
    rs_surface s;
    ENSURE(parse("*SURFACE, TYPE=SEGMENTS, NAME=pocket\nSTART, -2, 0\nLINE, 0, 0\n"
                 "LINE, 0, 2\n",
                 &s) == 0);
    ENSURE(s.profile.vkind[1] == RS_VTX_CONCAVE);
    const double rho = 0.3;
    rs_contacts c = {0};
    int twos = 0;
    for (int i = 0; i <= 160; i++) {
        for (int j = 0; j <= 160; j++) {
            double x = -1.0 + 0.01 * i + 0.0013, y = -0.6 + 0.01 * j + 0.0017;
            ENSURE(query(&s, x, y, rho, 0.0, &c) == 0);
            /* expected, feature by feature */
            int want_floor = x > -2.0 && x < 0.0 && y - rho <= 0.0;
            int want_wall = y >= 0.0 && y < 2.0 && -x - rho <= 0.0;
            int want_vertex = x >= 0.0 && y < 0.0; /* behind the pocket: embedded */
            int want = want_floor + want_wall + want_vertex;
            ENSURE(c.n == want);
            int m = 0;
            if (want_vertex) {
                ENSURE(c.feature[m] == RS_FEATURE(RS_FEAT_VERTEX, 1));
                ENSURE_NEAR(c.dist[m], -hypot(x, y), 1e-15);
                m++;
            }
            if (want_floor) {
                ENSURE(c.feature[m] == RS_FEATURE(RS_FEAT_FACE, 0));
                ENSURE_NEAR(c.dist[m], y, 1e-15);
                m++;
            }
            if (want_wall) {
                ENSURE(c.feature[m] == RS_FEATURE(RS_FEAT_FACE, 1));
                ENSURE_NEAR(c.dist[m], -x, 1e-15);
            }
            twos += want_floor && want_wall && x < 0.0 && y > 0.0;
        }
    }
    ENSURE(twos > 100);
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* Floor (-2,0)-(0,0) then wall (0,0)-(0,-2): a right turn, an edge. Outside the solid a
 * sphere touching the wall has exactly one contact at the true distance; inside the
 * solid exactly one contact, the face with the smaller penetration. */
static void test_corner_convex_gives_one_contact(void)
{
    rs_surface s;
    ENSURE(parse("*SURFACE, TYPE=SEGMENTS, NAME=edge\nSTART, -2, 0\nLINE, 0, 0\n"
                 "LINE, 0, -2\n",
                 &s) == 0);
    ENSURE(s.profile.vkind[1] == RS_VTX_CONVEX);
    const double rho = 0.3, A[2] = {-2, 0}, O[2] = {0, 0}, B[2] = {0, -2};
    rs_contacts c = {0};
    int vtx = 0;
    for (int i = 0; i <= 200; i++) {
        for (int j = 0; j <= 200; j++) {
            double x = -1.0 + 0.01 * i + 0.0013, y = -1.0 + 0.01 * j + 0.0017;
            ENSURE(query(&s, x, y, rho, 0.0, &c) == 0);
            if (x < 0.0 && y < 0.0) {
                ENSURE(c.n == 1);
                ENSURE_NEAR(c.dist[0], fmax(x, y), 1e-15);
                ENSURE(RS_FEATURE_TYPE(c.feature[0]) == RS_FEAT_FACE);
                continue;
            }
            double d = fmin(seg_dist(A, O, x, y), seg_dist(O, B, x, y));
            ENSURE(c.n == (d <= rho ? 1 : 0));
            if (c.n) {
                ENSURE_NEAR(c.dist[0], d, 1e-15);
                int is_vertex = x >= 0.0 && y >= 0.0;
                ENSURE(c.feature[0] == (is_vertex
                                            ? RS_FEATURE(RS_FEAT_VERTEX, 1)
                                            : RS_FEATURE(RS_FEAT_FACE, x < 0.0 ? 0 : 1)));
                vtx += is_vertex;
            }
        }
    }
    ENSURE(vtx > 100);
    /* the sphere centre exactly on the corner: one vertex contact, bisector normal */
    ENSURE(query(&s, 0.0, 0.0, rho, 0.0, &c) == 0);
    ENSURE(c.n == 1 && c.feature[0] == RS_FEATURE(RS_FEAT_VERTEX, 1));
    ENSURE_NEAR(c.nrm[0][0], sqrt(0.5), 1e-15);
    ENSURE_NEAR(c.nrm[1][0], sqrt(0.5), 1e-15);
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* SIDES=2: behind the edge is a pocket (two contacts); the vertex owns its wedge. */
static void test_corner_two_sided_mirror(void)
{
    rs_surface s;
    ENSURE(parse("*SURFACE, TYPE=SEGMENTS, NAME=edge, SIDES=2\nSTART, -2, 0\nLINE, 0, 0\n"
                 "LINE, 0, -2\n",
                 &s) == 0);
    rs_contacts c = {0};
    ENSURE(query(&s, -0.1, -0.2, 0.3, 0.0, &c) == 0);
    ENSURE(c.n == 2);
    ENSURE_NEAR(c.dist[0], 0.2, 1e-15);
    ENSURE_NEAR(c.nrm[1][0], -1.0, 1e-15);
    ENSURE_NEAR(c.dist[1], 0.1, 1e-15);
    ENSURE_NEAR(c.nrm[0][1], -1.0, 1e-15);
    ENSURE(query(&s, 0.1, 0.2, 0.3, 0.0, &c) == 0);
    ENSURE(c.n == 1 && c.feature[0] == RS_FEATURE(RS_FEAT_VERTEX, 1));
    ENSURE_NEAR(c.dist[0], hypot(0.1, 0.2), 1e-15);
    /* beyond the open end: the end vertex owns the whole half plane */
    ENSURE(query(&s, -2.1, -0.05, 0.3, 0.0, &c) == 0);
    ENSURE(c.n == 1 && c.feature[0] == RS_FEATURE(RS_FEAT_VERTEX, 0));
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* The same edge with FILLET RADIUS=0.2: a point kept at offset h from the rounded wall
 * has one contact at distance h everywhere, the normal turns continuously, and every
 * change of feature is between adjacent features. */
static void test_corner_fillet_normal_is_continuous(void)
{
    rs_surface s;
    ENSURE(parse("*SURFACE, TYPE=SEGMENTS, NAME=edge, FILLET RADIUS=0.2\nSTART, -2, 0\n"
                 "LINE, 0, 0\nLINE, 0, -2\n",
                 &s) == 0);
    ENSURE(s.profile.nseg == 3);
    for (int j = 0; j < s.profile.nvert; j++)
        ENSURE(s.profile.vkind[j] == RS_VTX_SMOOTH || s.profile.vkind[j] == RS_VTX_END);
    const double h = 0.15, rf = 0.2, C[2] = {-0.2, -0.2};
    rs_contacts c = {0};
    int prev = -1;
    double pn[2] = {0, 1};
    const int N = 3000;
    double total = 1.0 + 0.5 * RS_PI * (rf + h) + 1.0, ds = total / N;
    for (int i = 0; i <= N; i++) {
        double sarc = i * ds, x, y;
        if (sarc < 1.0) {
            x = -1.2 + sarc;
            y = h;
        } else if (sarc < 1.0 + 0.5 * RS_PI * (rf + h)) {
            double th = 0.5 * RS_PI - (sarc - 1.0) / (rf + h);
            x = C[0] + (rf + h) * cos(th);
            y = C[1] + (rf + h) * sin(th);
        } else {
            x = h;
            y = -0.2 - (sarc - 1.0 - 0.5 * RS_PI * (rf + h));
        }
        ENSURE(query(&s, x, y, 0.0, 0.5, &c) == 0);
        ENSURE(c.n == 1);
        ENSURE_NEAR(c.dist[0], h, 1e-12);
        double n[2] = {c.nrm[0][0], c.nrm[1][0]};
        /* the normal turns at most by the arc step / (rf + h) */
        double turn = acos(fmin(1.0, n[0] * pn[0] + n[1] * pn[1]));
        ENSURE(turn <= ds / (rf + h) * (1.0 + 1e-9) + 1e-12);
        if (prev >= 0 && c.feature[0] != prev)
            ENSURE(rs_surface_adjacent(&s, prev, c.feature[0]) == 1);
        prev = c.feature[0];
        pn[0] = n[0];
        pn[1] = n[1];
    }
    ENSURE(prev == RS_FEATURE(RS_FEAT_FACE, 2));
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* A hopper cross-section: mantle, funnel (concave corner), outlet lip (convex corner).
 * Along lines through the inside, the nearest contact sits at the true distance to
 * the polyline (brute force), so rdisp1 = R - dist moves by at most the step. */
static void test_corner_sweep_rdisp1_is_lipschitz(void)
{
    rs_surface s;
    ENSURE(parse("*SURFACE, TYPE=SEGMENTS, NAME=hopper\nSTART, -1, 3\nLINE, -1, 1\n"
                 "LINE, -0.2, 0\nLINE, -0.2, -0.5\n",
                 &s) == 0);
    const double P[4][2] = {{-1, 3}, {-1, 1}, {-0.2, 0}, {-0.2, -0.5}}, R = 0.25;
    rs_contacts c = {0};
    for (int line = 0; line < 40; line++) {
        /* horizontal lines above the funnel, vertical lines through the outlet */
        double x0, y0, dx, dy;
        int N = 2000;
        if (line < 20) {
            y0 = 0.05 + 0.1 * line;
            x0 = (y0 < 1.0 ? -0.2 - 0.8 * y0 : -1.0) + 0.01;
            dx = (0.8 - x0) / N;
            dy = 0.0;
        } else {
            x0 = -0.19 + 0.02 * (line - 20);
            y0 = 2.5;
            dx = 0.0;
            dy = -(2.5 + 0.45) / N;
        }
        double prev = NAN;
        for (int i = 0; i <= N; i++) {
            double x = x0 + i * dx, y = y0 + i * dy;
            if (x < -0.2 && y < 0.0)
                continue;
            if (y < 1.0 && x < -0.2 - 0.8 * y)
                continue;
            ENSURE(query(&s, x, y, R, INFINITY, &c) == 0);
            ENSURE(c.n >= 1);
            double dmin = INFINITY;
            for (int k = 0; k < c.n; k++)
                dmin = fmin(dmin, c.dist[k]);
            double bf = INFINITY;
            for (int k = 0; k < 3; k++)
                bf = fmin(bf, seg_dist(P[k], P[k + 1], x, y));
            ENSURE_NEAR(dmin, bf, 1e-14);
            double rdisp1 = R - dmin;
            if (!isnan(prev))
                ENSURE(fabs(rdisp1 - prev) <= hypot(dx, dy) * (1.0 + 1e-9));
            prev = rdisp1;
        }
    }
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* A closed rounded square (counter-clockwise, particles inside), FILLET RADIUS=0.25:
 * the nearest contact matches the closed-form distance to a rounded rectangle. */
static void test_corner_rounded_box_distance(void)
{
    rs_surface s;
    ENSURE(parse("*SURFACE, TYPE=SEGMENTS, NAME=box, FILLET RADIUS=0.25\nSTART, 0, 0\n"
                 "LINE, 2, 0\nLINE, 2, 1\nLINE, 0, 1\nLINE, 0, 0\n",
                 &s) == 0);
    ENSURE(s.profile.closed && s.profile.nseg == 8);
    rs_contacts c = {0};
    unsigned long long st = 12345;
    for (int it = 0; it < 20000; it++) {
        st = st * 6364136223846793005ull + 1442695040888963407ull;
        double x = 2.0 * (double)(st >> 11) / 9007199254740992.0;
        st = st * 6364136223846793005ull + 1442695040888963407ull;
        double y = (double)(st >> 11) / 9007199254740992.0;
        const double rf = 0.25;
        double cx = fmin(fmax(x, rf), 2.0 - rf), cy = fmin(fmax(y, rf), 1.0 - rf);
        double want;
        if (cx != x && cy != y)
            want = rf - hypot(x - cx, y - cy); /* a corner square */
        else
            want = fmin(fmin(x, 2.0 - x), fmin(y, 1.0 - y));
        if (want < 0.0)
            continue; /* outside the rounded corner */
        ENSURE(query(&s, x, y, 0.0, INFINITY, &c) == 0);
        ENSURE(c.n >= 1);
        double dmin = INFINITY;
        for (int k = 0; k < c.n; k++)
            dmin = fmin(dmin, c.dist[k]);
        ENSURE_NEAR(dmin, want, 1e-13);
    }
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* A REVOLUTION drum with fillets: a sphere rolling along the mantle into the end cap
 * keeps exactly one contact, the history passes through adjacent features only. */
static void test_corner_drum_fillet_sweep(void)
{
    rs_surface s;
    ENSURE(parse("*SURFACE, TYPE=REVOLUTION, NAME=drum, FILLET RADIUS=0.1\n"
                 "0,0,0, 0,0,1\nSTART, 0, 0\nLINE, 0.5, 0\nLINE, 0.5, 1\nLINE, 0, 1\n",
                 &s) == 0);
    rs_contacts c = {0};
    const double R = 0.05;
    int prev = -1;
    for (int i = 0; i <= 4000; i++) {
        /* the centre path: r = 0.5 - R until the fillet, then around it, then the cap */
        double sarc = i * (0.8 + 0.5 * RS_PI * 0.05 + 0.3) / 4000.0, r, z;
        if (sarc < 0.8) {
            r = 0.45;
            z = 0.1 + sarc;
        } else if (sarc < 0.8 + 0.5 * RS_PI * 0.05) {
            double th = (sarc - 0.8) / 0.05;
            r = 0.4 + 0.05 * cos(th);
            z = 0.9 + 0.05 * sin(th);
        } else {
            r = 0.4 - (sarc - 0.8 - 0.5 * RS_PI * 0.05);
            z = 0.95;
        }
        double x = r * cos(0.3), y = r * sin(0.3), zz = z;
        rs_query q = {.n = 1,
                      .slave = {.x = &x, .y = &y, .z = &zz, .radius = &R},
                      .pose = NULL,
                      .gap_max = 1e-9,
                      .dist_min = -INFINITY};
        c.n = 0;
        ENSURE(rs_surface_query(&s, &q, &c, NULL) == 0);
        ENSURE(c.n == 1);
        ENSURE_NEAR(c.dist[0], R, 1e-12);
        if (prev >= 0 && prev != c.feature[0])
            ENSURE(rs_surface_adjacent(&s, prev, c.feature[0]));
        prev = c.feature[0];
    }
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* History hand-over: faces across a SMOOTH vertex and a face with its own vertex; not
 * across a sharp corner, not to another segment's vertex. */
static void test_corner_adjacency_for_history(void)
{
    rs_surface s;
    ENSURE(parse("*SURFACE, TYPE=SEGMENTS, NAME=pocket\nSTART, -2, 0\nLINE, 0, 0\n"
                 "LINE, 0, 2\nLINE, 1, 3\n",
                 &s) == 0);
    int f0 = RS_FEATURE(RS_FEAT_FACE, 0), f1 = RS_FEATURE(RS_FEAT_FACE, 1);
    ENSURE(rs_surface_adjacent(&s, f0, f1) == 0);
    ENSURE(rs_surface_adjacent(&s, f0, RS_FEATURE(RS_FEAT_VERTEX, 1)) == 1);
    ENSURE(rs_surface_adjacent(&s, RS_FEATURE(RS_FEAT_VERTEX, 0), f0) == 1);
    ENSURE(rs_surface_adjacent(&s, f0, RS_FEATURE(RS_FEAT_VERTEX, 2)) == 0);
    ENSURE(rs_surface_adjacent(&s, f1, RS_FEATURE(RS_FEAT_VERTEX, 2)) == 1); /* convex */
    ENSURE(rs_surface_adjacent(&s, f0, RS_FEATURE(RS_FEAT_FACE, 2)) == 0);
    rs_surface_free(&s);
    ENSURE(parse("*SURFACE, TYPE=SEGMENTS, NAME=pocket, FILLET RADIUS=0.5\nSTART, -2, 0\n"
                 "LINE, 0, 0\nLINE, 0, 2\n",
                 &s) == 0);
    ENSURE(s.profile.nseg == 3);
    ENSURE(rs_surface_adjacent(&s, f0, f1) == 1);
    ENSURE(rs_surface_adjacent(&s, f1, RS_FEATURE(RS_FEAT_FACE, 2)) == 1);
    ENSURE(rs_surface_adjacent(&s, f1, RS_FEATURE(RS_FEAT_VERTEX, 1)) == 0); /* smooth */
    rs_surface_free(&s);
}

int main(void)
{
    RS_RUN(test_corner_concave_gives_two_contacts);
    RS_RUN(test_corner_convex_gives_one_contact);
    RS_RUN(test_corner_two_sided_mirror);
    RS_RUN(test_corner_fillet_normal_is_continuous);
    RS_RUN(test_corner_sweep_rdisp1_is_lipschitz);
    RS_RUN(test_corner_rounded_box_distance);
    RS_RUN(test_corner_drum_fillet_sweep);
    RS_RUN(test_corner_adjacency_for_history);
    return rs_test_summary();
}
