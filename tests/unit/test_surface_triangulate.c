/* Display triangulation: every node lies on the surface and the node order of every
 * triangle gives the outward normal (the side the particles live on); a run of
 * collinear LINE pieces shows as one piece. */
#include "rigidsurf/surface.h"
#include "rigidsurf/vec.h"
#include "rs_test.h"

#include <math.h>
#include <stdlib.h>

static const char *TXT =
    "*SURFACE, TYPE=SEGMENTS, NAME=seg\nSTART, -1, 1\nLINE, 0, 0\n"
    "CIRCL, 1, 0, 0.5, 1.2\nPARAB, 1.5, 0.6, 2, 0.4\n"
    "*SURFACE, TYPE=CYLINDER, NAME=cyl\n0.5,0,0, 1.5,0.5,0\n0,0.3,2\n"
    "START, 0.3, 0\nCIRCL, 0, 0.3, 0, 0\nCIRCL, -0.3, 0, 0, 0\n"
    "CIRCL, 0, -0.3, 0, 0\nCIRCL, 0.3, 0, 0, 0\n"
    "*SURFACE, TYPE=CYLINDER, NAME=cylb, EXTENT=-0.2, 0.7\n"
    "0,0,0, 1,0,0\n0,0,1\nSTART, -1, 0\nLINE, 1, 0\n"
    "*SURFACE, TYPE=REVOLUTION, NAME=rev, FILLET RADIUS=0.1\n"
    "0,0,1, 0.2,0.1,2\nSTART, 0, 0\nLINE, 1, 0\nLINE, 1, 2\nLINE, 0, 2\n";

static void check(const char *name)
{
    rs_surface s;
    rs_error e;
    ENSURE(rs_surface_parse(TXT, "tri", name, &s, &e) == 0);
    rs_trimesh m;
    ENSURE(rs_surface_triangulate(&s, 1.5, 24, &m, &e) == 0);
    ENSURE(m.nvert > 0 && m.ntri > 0);
    rs_contacts c = {0};
    for (int v = 0; v < m.nvert; v++) {
        double *p = m.xyz + 3 * v;
        rs_query q = {.n = 1,
                      .slave = {.x = p, .y = p + 1, .z = p + 2},
                      .pose = NULL,
                      .gap_max = 1e-6,
                      .dist_min = -1e-6};
        c.n = 0;
        ENSURE(rs_surface_query(&s, &q, &c, &e) == 0);
        double dmin = INFINITY;
        for (int k = 0; k < c.n; k++)
            dmin = fmin(dmin, fabs(c.dist[k]));
        ENSURE(dmin <= 1e-12 * 4.0);
    }
    int checked = 0;
    for (int t = 0; t < m.ntri; t++) {
        const double *a = m.xyz + 3 * m.tri[3 * t], *b = m.xyz + 3 * m.tri[3 * t + 1],
                     *d = m.xyz + 3 * m.tri[3 * t + 2];
        double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        double w[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
        double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                       u[0] * w[1] - u[1] * w[0]};
        double nl = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        ENSURE(nl > 0.0);
        double g[3];
        for (int i = 0; i < 3; i++)
            g[i] = (a[i] + b[i] + d[i]) / 3.0 + 0.02 * n[i] / nl; /* beyond the sagitta */
        rs_query q = {.n = 1,
                      .slave = {.x = g, .y = g + 1, .z = g + 2},
                      .pose = NULL,
                      .gap_max = 0.1,
                      .dist_min = -0.1};
        c.n = 0;
        ENSURE(rs_surface_query(&s, &q, &c, &e) == 0);
        int best = -1;
        for (int k = 0; k < c.n; k++)
            if (best < 0 || fabs(c.dist[k]) < fabs(c.dist[best]))
                best = k;
        ENSURE(best >= 0);
        /* a point just off the triangle on its normal side is on the particle side */
        ENSURE(c.dist[best] > 0.0);
        double dp =
            (c.nrm[0][best] * n[0] + c.nrm[1][best] * n[1] + c.nrm[2][best] * n[2]) / nl;
        ENSURE(dp > 0.9);
        checked++;
    }
    ENSURE(checked == m.ntri);
    rs_contacts_free(&c);
    rs_trimesh_free(&m);
    rs_surface_free(&s);
}

static void test_surface_triangulate_segments_outward(void)
{
    check("seg");
}

static void test_surface_triangulate_cylinder_outward(void)
{
    check("cyl");
}

static void test_surface_triangulate_bounded_cylinder_outward(void)
{
    check("cylb");
}

static void test_surface_triangulate_revolution_outward(void)
{
    check("rev");
}

static void test_surface_triangulate_bad_arguments(void)
{
    rs_surface s;
    rs_error e;
    rs_trimesh m;
    ENSURE(rs_surface_parse(TXT, "tri", "seg", &s, &e) == 0);
    ENSURE(rs_surface_triangulate(&s, 1.0, 2, &m, &e) == RS_ERR_ARG);
    ENSURE(rs_surface_triangulate(&s, 0.0, 8, &m, &e) == RS_ERR_ARG);
    ENSURE(m.xyz == NULL && m.tri == NULL);
    rs_surface_free(&s);
}

/* A drum whose mantle is 500 collinear LINE pieces shows as the drum of one mantle LINE:
 * the same nodes and triangles (the pieces' inner vertices lie on the mantle). */
static void test_surface_triangulate_collinear_run_is_one_piece(void)
{
    enum { NP = 500 };
    static char deck[NP * 48 + 256];
    int o = snprintf(deck, sizeof deck,
                     "*SURFACE, TYPE=REVOLUTION, NAME=d\n0,0,0, 0,0,1\nSTART, 0, 0\n"
                     "LINE, 0.15, 0\n");
    for (int k = 1; k <= NP; k++)
        o += snprintf(deck + o, sizeof deck - (size_t)o, "LINE, 0.15, %.17g\n",
                      0.1 * k / NP);
    snprintf(deck + o, sizeof deck - (size_t)o, "LINE, 0, 0.1\n");
    const char *one = "*SURFACE, TYPE=REVOLUTION, NAME=d\n0,0,0, 0,0,1\nSTART, 0, 0\n"
                      "LINE, 0.15, 0\nLINE, 0.15, 0.1\nLINE, 0, 0.1\n";
    rs_surface s[2];
    rs_trimesh m[2];
    rs_error e;
    ENSURE(rs_surface_parse(deck, "tri", NULL, &s[0], &e) == 0 &&
           s[0].profile.nseg == NP + 2);
    ENSURE(rs_surface_parse(one, "tri", NULL, &s[1], &e) == 0);
    for (int i = 0; i < 2; i++)
        ENSURE(rs_surface_triangulate(&s[i], 1.0, 24, &m[i], &e) == 0);
    ENSURE(m[0].nvert == m[1].nvert && m[0].ntri == m[1].ntri);
    for (int v = 0; v < 3 * m[0].nvert; v++)
        ENSURE_NEAR(m[0].xyz[v], m[1].xyz[v], 1e-15);
    for (int t = 0; t < 3 * m[0].ntri; t++)
        ENSURE(m[0].tri[t] == m[1].tri[t]);
    for (int i = 0; i < 2; i++) {
        rs_trimesh_free(&m[i]);
        rs_surface_free(&s[i]);
    }
}

/* An arc is drawn with one piece per 360 / nhoop degrees of its sweep, rounded up: a
 * SEGMENTS profile of pieces P shows as 2 P triangles (its extrusion along z). */
static int triangles_of(const char *text, int nhoop)
{
    rs_surface s;
    rs_error e;
    rs_trimesh m;
    if (rs_surface_parse(text, "tri", NULL, &s, &e) != 0)
        return -1;
    int nt = rs_surface_triangulate(&s, 1.0, nhoop, &m, &e) == 0 ? m.ntri : -1;
    rs_trimesh_free(&m);
    rs_surface_free(&s);
    return nt;
}

static void test_surface_triangulate_arc_pieces_per_sweep(void)
{
    /* sweep (degrees), points around the full turn, pieces = ceil(sweep / (360 / nh)) */
    static const struct {
        double deg;
        int nh, pieces;
    } CASE[] = {{35.0, 72, 7}, {90.0, 72, 18},  {3.0, 72, 1},
                {5.5, 72, 2},  {170.0, 24, 12}, {45.0, 64, 8}};
    for (size_t i = 0; i < sizeof CASE / sizeof CASE[0]; i++) {
        const double th = CASE[i].deg * RS_PI / 180.0;
        char text[256];
        snprintf(text, sizeof text,
                 "*SURFACE, TYPE=SEGMENTS, NAME=arc\nSTART, 1, 0\n"
                 "CIRCL, %.17g, %.17g, 0, 0\n",
                 cos(th), sin(th));
        ENSURE(triangles_of(text, CASE[i].nh) == 2 * CASE[i].pieces);
    }
    /* a fillet of 35 degrees between two LINEs: 1 + 7 + 1 pieces at 5 degrees a node */
    const double th = 35.0 * RS_PI / 180.0;
    char text[256];
    snprintf(text, sizeof text,
             "*SURFACE, TYPE=SEGMENTS, NAME=f, FILLET RADIUS=0.1\nSTART, -1, 0\n"
             "LINE, 0, 0\nLINE, %.17g, %.17g\n",
             cos(th), sin(th));
    ENSURE(triangles_of(text, 72) == 2 * 9);
}

int main(void)
{
    RS_RUN(test_surface_triangulate_segments_outward);
    RS_RUN(test_surface_triangulate_cylinder_outward);
    RS_RUN(test_surface_triangulate_bounded_cylinder_outward);
    RS_RUN(test_surface_triangulate_revolution_outward);
    RS_RUN(test_surface_triangulate_bad_arguments);
    RS_RUN(test_surface_triangulate_collinear_run_is_one_piece);
    RS_RUN(test_surface_triangulate_arc_pieces_per_sweep);
    return rs_test_summary();
}
