/* What a body's query on a MESH asks of a candidate triangle before any pair query
 * (src/faceted/mesh_body.c), against brute force written here: whether the triangle is
 * plain for a ball (rs_mesh_triangle_plain: no edge but a FLAT one, no node but one
 * inside a coplanar region, within the radius of its centre; the distances to every edge
 * and node measured here), and the coplanar regions of a list of triangles
 * (rs_mesh_flat_regions: components through FLAT edges between triangles of the list,
 * each labelled by its least index; found here by a flood over every pair that shares
 * two nodes). On the benchmark's floor of two triangles, a bumpy height field (open
 * borders, valleys, ridges), a cylinder of planar quads split in two (flat diagonals)
 * and a UV sphere, at random points biased to edges and nodes, and on lists of 1 to 40
 * triangles (the two-triangle case, the scan of a few, the sorted search of many). And
 * the body query's answer on plain triangles (their planes, asked only where a region
 * needs them): one face contact, the depth of the body's support below the plane, and
 * for a sphere and a box the closed form (R - h; the lowest of the eight corners), to
 * 1e-12 of the body's reach: every shape in random poses over the floor and over a flat
 * grid of 128 triangles (a region of many), one- and two-sided, in place and moved. */
#include "convex_geometry/convex_internal.h"
#include "faceted/mesh.h"
#include "faceted/mesh_regions.h"
#include "mesh_soup.h"
#include "rigidsurf/convex.h"
#include "rigidsurf/motion.h"
#include "rigidsurf/surface.h"
#include "rigidsurf/vec.h"
#include "rs_test.h"
#include "test_bodies.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { NCASE = 4 };

static void make_case(int k, soup *sp)
{
    if (k == 0) { /* the benchmark's floor */
        sp_point(sp, -10, -10, 0), sp_point(sp, 10, -10, 0);
        sp_point(sp, 10, 10, 0), sp_point(sp, -10, 10, 0);
        sp_poly(sp, 3, 0, 1, 2, 0);
        sp_poly(sp, 3, 0, 2, 3, 0);
    } else if (k == 1) { /* a height field of 6 x 6 cells, flat in its left half */
        const int n = 6;
        for (int j = 0; j <= n; j++)
            for (int i = 0; i <= n; i++)
                sp_point(sp, (double)i / n, (double)j / n,
                         i <= n / 2 ? 0.0 : urange(0, 0.2));
        for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++) {
                const int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
                if (urand() < 0.5)
                    sp_poly(sp, 3, a, b, c, 0), sp_poly(sp, 3, a, c, d, 0);
                else
                    sp_poly(sp, 3, a, b, d, 0), sp_poly(sp, 3, b, c, d, 0);
            }
    } else if (k == 2) {
        cylinder(sp, 12, 3, 1.0, 0.0, 1.0, 0);
    } else {
        uv_sphere(sp, 6, 8);
    }
}

static double segment_dist(const double *a, const double *b, const double p[3])
{
    double u[3], w[3];
    for (int d = 0; d < 3; d++)
        u[d] = b[d] - a[d], w[d] = p[d] - a[d];
    double f = rs_dot3(w, u) / rs_dot3(u, u);
    f = f < 0.0 ? 0.0 : f > 1.0 ? 1.0 : f;
    double e = 0.0;
    for (int d = 0; d < 3; d++)
        e += (w[d] - f * u[d]) * (w[d] - f * u[d]);
    return sqrt(e);
}

/* The least distance from c to an edge of t not FLAT or a node of t not inside a
 * coplanar region (every edge of a node counted: a node is plain where all its edges
 * are FLAT); INFINITY for none. */
static double spoiler_dist(const rs_mesh *m, int t, const double c[3])
{
    double best = INFINITY;
    for (int j = 0; j < 3; j++) {
        const int v = m->tri[3 * t + j], w = m->tri[3 * t + (j + 1) % 3];
        const double *a = m->xyz + 3 * v, *b = m->xyz + 3 * w;
        if (m->edge_kind[m->tedge[3 * t + j]] != RS_EDGE_FLAT)
            best = fmin(best, segment_dist(a, b, c));
        int all_flat = 1;
        for (int e = 0; e < m->ne; e++)
            if ((m->edge_v[2 * e] == v || m->edge_v[2 * e + 1] == v) &&
                m->edge_kind[e] != RS_EDGE_FLAT)
                all_flat = 0;
        if (!all_flat) {
            double d2 = 0.0;
            for (int d = 0; d < 3; d++)
                d2 += (c[d] - a[d]) * (c[d] - a[d]);
            best = fmin(best, sqrt(d2));
        }
    }
    return best;
}

/* Case k's soup and its MESH of two sides. */
static int case_mesh(int k, soup *sp, rs_surface *s)
{
    memset(sp, 0, sizeof *sp);
    make_case(k, sp);
    return make(sp, 2, s);
}

static void triangle_plain_is_the_brute_force(void)
{
    int plain = 0, spoiled = 0;
    for (int k = 0; k < NCASE; k++) {
        soup sp;
        rs_surface s;
        ENSURE(case_mesh(k, &sp, &s) == RS_OK);
        const rs_mesh *m = s.impl;
        const double scale = k == 0 ? 20.0 : 1.0;
        for (int i = 0; i < 20000; i++) {
            const int t = (int)(urand() * m->nt);
            /* a point of t (or beyond it), near an edge or a node one time in three each,
             * lifted off its plane */
            double w[3] = {urand(), urand(), urand()};
            const int bias = i % 3;
            if (bias)
                w[(int)(urand() * 3)] = urange(-0.02, 0.02);
            if (bias == 2)
                w[(int)(urand() * 3)] = urange(-0.02, 0.02);
            const double sw = w[0] + w[1] + w[2];
            double c[3];
            for (int d = 0; d < 3; d++) {
                c[d] = 0.0;
                for (int j = 0; j < 3; j++)
                    c[d] += w[j] / sw * m->xyz[3 * m->tri[3 * t + j] + d];
                c[d] += urange(-0.05, 0.05) * scale * m->rec[t].n[d];
            }
            const double r = urange(0.0, 0.3) * scale * (i % 5 ? 0.1 : 1.0);
            const double dist = spoiler_dist(m, t, c);
            if (fabs(dist - r) <= 1e-9 * scale)
                continue; /* a tie within the rounding */
            const int want = !(dist <= r);
            ENSURE(rs_mesh_triangle_plain(&s, t, c, r) == want);
            plain += want, spoiled += !want;
        }
        rs_surface_free(&s);
        sp_free(&sp);
    }
    ENSURE(plain > 10000 && spoiled > 10000);
}

/* Do triangles t and u share an edge (two nodes)? Its edge, or -1. */
static int shared_edge(const rs_mesh *m, int t, int u)
{
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 3; i++)
            if (m->tedge[3 * t + j] == m->tedge[3 * u + i])
                return m->tedge[3 * t + j];
    return -1;
}

static void flat_regions_are_the_flood(void)
{
    int lists = 0, joined = 0;
    for (int k = 0; k < NCASE; k++) {
        soup sp;
        rs_surface s;
        ENSURE(case_mesh(k, &sp, &s) == RS_OK);
        const rs_mesh *m = s.impl;
        for (int rep = 0; rep < 400; rep++) {
            int n = 1 + (int)(urand() * 40);
            n = rep % 4 == 0 ? 2 : n;
            n = n > m->nt ? m->nt : n;
            /* n distinct triangles in random order; the first two neighbours one time in
             * two */
            int ids[40], label[40], scratch[80], want[40];
            int *pick = calloc((size_t)m->nt, sizeof *pick);
            for (int a = 0; a < n;) {
                const int t = (int)(urand() * m->nt);
                if (!pick[t])
                    pick[t] = 1, ids[a++] = t;
            }
            if (n >= 2 && rep % 2 == 0) {
                const int nb = m->rec[ids[0]].nbr[(int)(urand() * 3)];
                if (nb >= 0 && !pick[nb / 3]) {
                    pick[ids[1]] = 0;
                    ids[1] = nb / 3, pick[nb / 3] = 1;
                }
            }
            free(pick);
            /* the flood: the least index of each component */
            for (int a = 0; a < n; a++)
                want[a] = -1;
            for (int a = 0; a < n; a++) {
                if (want[a] >= 0)
                    continue;
                want[a] = a;
                for (int grew = 1; grew;) {
                    grew = 0;
                    for (int x = 0; x < n; x++)
                        for (int y = 0; y < n; y++) {
                            if (want[x] != a || want[y] >= 0)
                                continue;
                            const int e = shared_edge(m, ids[x], ids[y]);
                            if (e >= 0 && m->edge_kind[e] == RS_EDGE_FLAT)
                                want[y] = a, grew = 1;
                        }
                }
            }
            rs_mesh_flat_regions(&s, ids, n, label, scratch);
            for (int a = 0; a < n; a++) {
                ENSURE(label[a] == want[a]);
                joined += label[a] != a;
            }
            lists++;
        }
        rs_surface_free(&s);
        sp_free(&sp);
    }
    ENSURE(lists == 1600 && joined > 200);
}

/* A flat grid of 8 x 8 cells over [-0.02, 0.02]^2 in the plane z = 0.05 x + 0.02 y, each
 * cell two triangles along a random diagonal. */
static void tilted_grid(soup *sp)
{
    const int n = 8;
    for (int j = 0; j <= n; j++)
        for (int i = 0; i <= n; i++) {
            const double x = -0.02 + 0.04 * i / n, y = -0.02 + 0.04 * j / n;
            sp_point(sp, x, y, 0.05 * x + 0.02 * y);
        }
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            const int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
            if (urand() < 0.5)
                sp_poly(sp, 3, a, b, c, 0), sp_poly(sp, 3, a, c, d, 0);
            else
                sp_poly(sp, 3, a, b, d, 0), sp_poly(sp, 3, b, c, d, 0);
        }
}

static void plane_answer_is_the_closed_form(void)
{
    int checked = 0, closed = 0;
    double worst = 0.0;
    for (int k = 0; k < 2; k++)
        for (int sides = 1; sides <= 2; sides++) {
            soup sp;
            memset(&sp, 0, sizeof sp);
            if (k == 0)
                make_case(0, &sp);
            else
                tilted_grid(&sp);
            rs_surface s;
            ENSURE(make(&sp, sides, &s) == RS_OK);
            const rs_mesh *m = s.impl;
            /* the plane's unit normal and a point of it (reference configuration) */
            const double *N = m->rec[0].n, *A0 = m->rec[0].a0;
            for (int moved = 0; moved < 2; moved++) {
                rs_pose pose;
                rs_pose_identity(&pose);
                if (moved) {
                    const double a = 0.4;
                    pose.R[0] = cos(a), pose.R[2] = sin(a), pose.R[6] = -sin(a);
                    pose.R[8] = cos(a), pose.T[0] = 0.003, pose.T[2] = -0.001;
                }
                double n[3], a0[3];
                rs_pose_rotate(&pose, N, n);
                rs_pose_to_global(&pose, A0, a0);
                for (int sh = 0; sh < TEST_NSHAPE; sh++) {
                    rs_shape shape;
                    ENSURE(test_make_shape(sh, &shape) == RS_OK);
                    for (int i = 0; i < 60; i++) {
                        /* a body over the middle of the mesh, its lowest point a little
                         * below or above the plane */
                        double q[4],
                            X[3] = {urange(-0.012, 0.012), urange(-0.012, 0.012), 0};
                        X[2] =
                            A0[2] + (N[0] * (A0[0] - X[0]) + N[1] * (A0[1] - X[1])) / N[2];
                        double x[3];
                        rs_pose_to_global(&pose, X, x);
                        random_unit_quaternion(q);
                        rs_body b;
                        ENSURE(rs_body_init(&b, &shape, 1000.0, x, q, NULL) == RS_OK);
                        const double down[3] = {-n[0], -n[1], -n[2]};
                        double low[3];
                        rs_body_support(&b, down, low);
                        const double lift =
                            urange(-1e-3, 8e-4) - rs_dot3(n, low) + rs_dot3(n, a0);
                        for (int d = 0; d < 3; d++)
                            b.x[d] += lift * n[d];
                        const double gap = 5e-4;
                        rs_body_contact bc[8];
                        int nc = 0;
                        rs_error e;
                        rs_error_clear(&e);
                        ENSURE(rs_body_surface_contacts(&s, moved ? &pose : NULL, &b, gap,
                                                        bc, 8, &nc, &e) == RS_OK);
                        /* the body's deepest point below the plane, over the mesh */
                        rs_body_support(&b, down, low);
                        const double h = rs_dot3(n, low) - rs_dot3(n, a0);
                        double foot[3], F[3];
                        for (int d = 0; d < 3; d++)
                            foot[d] = low[d] - h * n[d];
                        rs_pose_to_local(&pose, foot, F);
                        int t = -1;
                        for (int u = 0; u < m->nt && t < 0; u++)
                            if (rs_mesh_triangle_holds(&s, u, F))
                                t = u;
                        ENSURE(t >= 0);
                        if (!(h <= gap)) { /* beyond the gap */
                            ENSURE(nc == 0);
                            continue;
                        }
                        ENSURE(nc == 1);
                        if (nc != 1)
                            continue;
                        const double reach = rs_body_reach(&b);
                        ENSURE(RS_FEATURE_TYPE(bc[0].feature) == RS_FEAT_FACE);
                        /* the depth of the body's support below the plane */
                        ENSURE(fabs(bc[0].depth + h) <= 1e-12 * reach);
                        for (int d = 0; d < 3; d++)
                            ENSURE(fabs(bc[0].normal[d] - n[d]) <= 1e-12);
                        double want = NAN;
                        if (sh == 0) /* the sphere: R - (x - a0).n */
                            want = shape.dim[0] - rs_dot3(n, b.x) + rs_dot3(n, a0);
                        if (sh == 2) { /* the box: its lowest corner */
                            double R[9], lo = INFINITY;
                            rs_body_rotation(&b, R);
                            for (int c = 0; c < 8; c++) {
                                const double v[3] = {shape.box[(c & 1) ? 3 : 0],
                                                     shape.box[(c & 2) ? 4 : 1],
                                                     shape.box[(c & 4) ? 5 : 2]};
                                double w[3];
                                rs_matvec3(R, v, w);
                                lo = fmin(lo, rs_dot3(n, w) + rs_dot3(n, b.x));
                            }
                            want = rs_dot3(n, a0) - lo;
                        }
                        if (sh == 0 || sh == 2) {
                            const double dd = fabs(bc[0].depth - want) / reach;
                            ENSURE(dd <= 1e-12);
                            worst = fmax(worst, dd);
                            closed++;
                        }
                        checked++;
                    }
                    rs_shape_free(&shape);
                }
            }
            rs_surface_free(&s);
            sp_free(&sp);
        }
    printf("     %d bodies, %d against a closed form (worst |d depth| / reach %.1e)\n",
           checked, closed, worst);
    ENSURE(checked > 3000 && closed > 600);
}

int main(void)
{
    RS_RUN(triangle_plain_is_the_brute_force);
    RS_RUN(flat_regions_are_the_flood);
    RS_RUN(plane_answer_is_the_closed_form);
    return rs_test_summary();
}
