/* Profile geometry: arc lengths against closed forms, vertex kinds seen from the
 * particle side, fillets tangent to both neighbours (line-line, line-arc, arc-arc), and
 * corners touching a PARAB left sharp. */
#include "profile.h"
#include "rigidsurf/surface.h"
#include "rs_test.h"
#include "rs_test_geom.h"

#include <math.h>
#include <stdlib.h>

/* End tangent of a segment from its defining points (independent of the library). */
static void tangent(const rs_segment *g, int at_end, double t[2])
{
    if (g->type == RS_LINE) {
        double l = hypot(g->p1[0] - g->p0[0], g->p1[1] - g->p0[1]);
        t[0] = (g->p1[0] - g->p0[0]) / l;
        t[1] = (g->p1[1] - g->p0[1]) / l;
        return;
    }
    if (g->type == RS_CIRCL) {
        const double *p = at_end ? g->p1 : g->p0;
        double r[2] = {p[0] - g->pm[0], p[1] - g->pm[1]}, l = hypot(r[0], r[1]);
        double s = g->sweep > 0 ? 1.0 : -1.0;
        t[0] = -s * r[1] / l;
        t[1] = s * r[0] / l;
        return;
    }
    /* PARAB: X'(xi) = (p1 - p0)/2 + xi (p0 + p1 - 2 pm) */
    double xi = at_end ? 1.0 : -1.0, d[2];
    for (int i = 0; i < 2; i++)
        d[i] = 0.5 * (g->p1[i] - g->p0[i]) + xi * (g->p0[i] + g->p1[i] - 2.0 * g->pm[i]);
    double l = hypot(d[0], d[1]);
    t[0] = d[0] / l;
    t[1] = d[1] / l;
}

static void test_profile_arc_lengths(void)
{
    rs_surface s;
    ENSURE(parse("*SURFACE, TYPE=SEGMENTS, NAME=a\nSTART, 0, 0\nLINE, 3, 4\n"
                 "CIRCL, 5, 2, 5, 4\nPARAB, 6, 1, 7, 2\n",
                 &s) == 0);
    ENSURE(s.profile.nseg == 3);
    ENSURE_REL(s.profile.seg[0].length, 5.0, 1e-15);
    /* CIRCL about (5, 4) from (3, 4) to (5, 2): a quarter turn of radius 2 */
    ENSURE_REL(s.profile.seg[1].length, RS_PI, 1e-14);
    ENSURE_REL(fabs(s.profile.seg[1].sweep), 0.5 * RS_PI, 1e-15);
    /* the parabola y - 1 = (x - 6)^2 from x = 5 to 7: sqrt(5) + asinh(2)/2 */
    ENSURE_REL(s.profile.seg[2].length, sqrt(5.0) + 0.5 * asinh(2.0), 1e-14);
    ENSURE(s.profile.seg[0].s0 == 0.0);
    ENSURE_REL(s.profile.seg[1].s0, 5.0, 1e-15);
    ENSURE_REL(s.profile.seg[2].s0, 5.0 + RS_PI, 1e-14);
    ENSURE(s.profile.closed == 0 && s.profile.nvert == 4);
    rs_surface_free(&s);
}

/* Counter-clockwise square: every turn is to the left, toward n, so from the particle
 * side (inside) every corner is a pocket. Clockwise: every corner an edge. */
static void test_profile_vertex_kinds_seen_from_particle_side(void)
{
    rs_surface s;
    ENSURE(parse("*SURFACE, TYPE=SEGMENTS, NAME=a\nSTART, 0, 0\nLINE, 1, 0\nLINE, 1, 1\n"
                 "LINE, 0, 1\nLINE, 0, 0\n",
                 &s) == 0);
    ENSURE(s.profile.closed == 1 && s.profile.nvert == 4);
    for (int j = 0; j < 4; j++)
        ENSURE(s.profile.vkind[j] == RS_VTX_CONCAVE);
    rs_surface_free(&s);
    ENSURE(parse("*SURFACE, TYPE=SEGMENTS, NAME=a\nSTART, 0, 0\nLINE, 0, 1\nLINE, 1, 1\n"
                 "LINE, 1, 0\nLINE, 0, 0\n",
                 &s) == 0);
    for (int j = 0; j < 4; j++)
        ENSURE(s.profile.vkind[j] == RS_VTX_CONVEX);
    rs_surface_free(&s);
    /* LINE tangent into a CIRCL: smooth; open ends: END */
    ENSURE(parse("*SURFACE, TYPE=SEGMENTS, NAME=a\nSTART, -1, 0\nLINE, 0, 0\n"
                 "CIRCL, 1, 1, 0, 1\n",
                 &s) == 0);
    ENSURE(s.profile.vkind[0] == RS_VTX_END && s.profile.vkind[1] == RS_VTX_SMOOTH &&
           s.profile.vkind[2] == RS_VTX_END);
    rs_surface_free(&s);
}

/* After filleting: consecutive segments share end points exactly and their tangents
 * agree; every fillet has radius r. */
static int check_tangent_chain(const rs_surface *s, double r)
{
    const rs_profile *p = &s->profile;
    for (int k = 0; k + 1 < p->nseg + (p->closed ? 1 : 0); k++) {
        const rs_segment *a = &p->seg[k], *b = &p->seg[(k + 1) % p->nseg];
        if (a->p1[0] != b->p0[0] || a->p1[1] != b->p0[1])
            return 0;
        double ta[2], tb[2];
        tangent(a, 1, ta);
        tangent(b, 0, tb);
        if (!(fabs(ta[0] - tb[0]) <= 1e-12 && fabs(ta[1] - tb[1]) <= 1e-12))
            return 0;
    }
    for (int j = 0; j < p->nvert; j++)
        if (p->vkind[j] != RS_VTX_SMOOTH && p->vkind[j] != RS_VTX_END)
            return 0;
    int fillets = 0;
    for (int k = 0; k < p->nseg; k++)
        if (p->seg[k].type == RS_CIRCL && fabs(p->seg[k].radius - r) <= 1e-12 * r)
            fillets++;
    return fillets;
}

static void test_profile_fillet_line_line(void)
{
    rs_surface s;
    ENSURE(parse("*SURFACE, TYPE=SEGMENTS, NAME=a, FILLET RADIUS=0.2\nSTART, -2, 0\n"
                 "LINE, 0, 0\nLINE, 1, 1\nLINE, 2, -3\n",
                 &s) == 0);
    ENSURE(s.profile.nseg == 5);
    ENSURE(check_tangent_chain(&s, 0.2) == 2);
    /* the first fillet's centre lies at distance r from the floor y = 0 (on the n side:
     * the corner turns left) and from the line y = x */
    const rs_segment *f = &s.profile.seg[1];
    ENSURE_NEAR(f->pm[1], 0.2, 1e-14);
    ENSURE_NEAR(fabs(f->pm[0] - f->pm[1]) / sqrt(2.0), 0.2, 1e-14);
    /* tangent length r tan(theta/2) with theta = 45 degrees */
    ENSURE_NEAR(s.profile.seg[0].p1[0], -0.2 * tan(RS_PI / 8.0), 1e-14);
    rs_surface_free(&s);
}

static void test_profile_fillet_line_arc_and_arc_arc(void)
{
    rs_surface s;
    /* a line along +x into an arc about (1, 0) that leaves (0, 0) going up: a left
     * turn of 90 degrees */
    ENSURE(parse("*SURFACE, TYPE=SEGMENTS, NAME=a, FILLET RADIUS=0.1\nSTART, -2, 0\n"
                 "LINE, 0, 0\nCIRCL, 1, 1, 1, 0\n",
                 &s) == 0);
    ENSURE(s.profile.nseg == 3);
    ENSURE(check_tangent_chain(&s, 0.1) >= 1);
    const rs_segment *f = &s.profile.seg[1];
    /* tangent to the line y = 0 and to the circle |X - (1,0)| = 1 */
    ENSURE_NEAR(fabs(f->pm[1]), 0.1, 1e-13);
    double dc = hypot(f->pm[0] - 1.0, f->pm[1]);
    ENSURE(fabs(dc - 0.9) <= 1e-13 || fabs(dc - 1.1) <= 1e-13);
    rs_surface_free(&s);

    /* two arcs meeting at (0, 0): about (-1, 0) arriving upward, about (0, 1) leaving
     * along +x, a right turn of 90 degrees */
    ENSURE(parse("*SURFACE, TYPE=SEGMENTS, NAME=a, FILLET RADIUS=0.1\nSTART, -1, -1\n"
                 "CIRCL, 0, 0, -1, 0\nCIRCL, 1, 1, 0, 1\n",
                 &s) == 0);
    ENSURE(s.profile.nseg == 3);
    ENSURE(check_tangent_chain(&s, 0.1) >= 1);
    f = &s.profile.seg[1];
    double d1 = hypot(f->pm[0] + 1.0, f->pm[1]), d2 = hypot(f->pm[0], f->pm[1] - 1.0);
    ENSURE(fabs(d1 - 0.9) <= 1e-13 || fabs(d1 - 1.1) <= 1e-13);
    ENSURE(fabs(d2 - 0.9) <= 1e-13 || fabs(d2 - 1.1) <= 1e-13);
    rs_surface_free(&s);
}

/* Closed profile: the fillet at vertex 0 closes the loop; a rounded square. */
static void test_profile_fillet_closed_square(void)
{
    rs_surface s;
    ENSURE(parse("*SURFACE, TYPE=SEGMENTS, NAME=a, FILLET RADIUS=0.25\nSTART, 0, 0\n"
                 "LINE, 1, 0\nLINE, 1, 1\nLINE, 0, 1\nLINE, 0, 0\n",
                 &s) == 0);
    ENSURE(s.profile.closed && s.profile.nseg == 8);
    ENSURE(check_tangent_chain(&s, 0.25) == 4);
    double total = 0.0;
    for (int k = 0; k < 8; k++)
        total += s.profile.seg[k].length;
    ENSURE_REL(total, 4.0 - 8 * 0.25 + 2.0 * RS_PI * 0.25, 1e-14);
    rs_surface_free(&s);
}

static void test_profile_parab_corner_stays_sharp(void)
{
    rs_surface s;
    ENSURE(parse("*SURFACE, TYPE=SEGMENTS, NAME=a, FILLET RADIUS=0.1\nSTART, -2, 0\n"
                 "LINE, 0, 0\nPARAB, 0.5, 0.75, 1, 2\nLINE, 3, 2\n",
                 &s) == 0);
    ENSURE(s.profile.nseg == 3);
    ENSURE(s.profile.vkind[1] == RS_VTX_CONCAVE);
    ENSURE(s.profile.vkind[2] == RS_VTX_CONVEX);
    rs_surface_free(&s);
}

/* A fillet elsewhere in the profile leaves a PARAB the parabola it was: the same three
 * points, passing through its middle point at xi = 0. */
static void test_profile_fillet_keeps_parab(void)
{
    rs_surface s;
    ENSURE(parse("*SURFACE, TYPE=SEGMENTS, NAME=a, FILLET RADIUS=0.1\nSTART, -3, 1\n"
                 "LINE, -2, 0\nLINE, 0, 0\nPARAB, 0.5, 0.75, 1, 2\nLINE, 3, 2\n",
                 &s) == 0);
    ENSURE(s.profile.nseg == 5); /* one fillet, at (-2, 0) */
    const rs_segment *g = &s.profile.seg[3];
    ENSURE(s.profile.seg[1].type == RS_CIRCL && g->type == RS_PARAB);
    ENSURE(g->p0[0] == 0.0 && g->p0[1] == 0.0 && g->p1[0] == 1.0 && g->p1[1] == 2.0);
    double x[2], t[2], k;
    rs_segment_eval(g, 0.5, x, t, &k);
    ENSURE_SMALL(x[0] - 0.5, 1e-15);
    ENSURE_SMALL(x[1] - 0.75, 1e-15);
    rs_surface_free(&s);
}

int main(void)
{
    RS_RUN(test_profile_arc_lengths);
    RS_RUN(test_profile_vertex_kinds_seen_from_particle_side);
    RS_RUN(test_profile_fillet_line_line);
    RS_RUN(test_profile_fillet_line_arc_and_arc_arc);
    RS_RUN(test_profile_fillet_closed_square);
    RS_RUN(test_profile_parab_corner_stays_sharp);
    RS_RUN(test_profile_fillet_keeps_parab);
    return rs_test_summary();
}
