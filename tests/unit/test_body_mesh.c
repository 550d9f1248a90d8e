/* A convex body against a MESH (rs_body_surface_contacts) against independent answers:
 * a sphere given as a body against the mesh's own sphere query (a two-triangle floor, one
 * and two sides, a tessellated sphere and a tessellated cube), an ellipsoid and a rounded
 * box over the floor in several orientations and across its flat diagonal (one contact,
 * the closed-form depth), a box tilted on a table near its edge and one sunk through a
 * one-sided floor (the face's closed form alone), a box at a roof's ridge and a pyramid's
 * apex (the edge and the vertex, the depth from the box's corner or face), an ellipsoid
 * in a fine mesh of a drum against the analytic drum (within the sagitta), a moved pose
 * against the mesh placed there, and the capacity and refusals. */
#include "rigidsurf/convex.h"
#include "rigidsurf/motion.h"
#include "rigidsurf/vec.h"
#include "rs_test.h"
#include "rs_test_geom.h"

#include <stdlib.h>

/* A mesh under construction: vertices and triangles, duplicated points welded when the
 * surface is made. */
typedef struct soup {
    double *xyz;
    int *tri;
    int nv, nt, vcap, tcap;
} soup;

static int add_vertex(soup *m, double x, double y, double z)
{
    if (m->nv == m->vcap) {
        m->vcap = m->vcap ? 2 * m->vcap : 64;
        m->xyz = realloc(m->xyz, (size_t)m->vcap * 3 * sizeof *m->xyz);
    }
    m->xyz[3 * m->nv] = x, m->xyz[3 * m->nv + 1] = y, m->xyz[3 * m->nv + 2] = z;
    return m->nv++;
}

static void add_tri(soup *m, int a, int b, int c)
{
    if (m->nt == m->tcap) {
        m->tcap = m->tcap ? 2 * m->tcap : 64;
        m->tri = realloc(m->tri, (size_t)m->tcap * 3 * sizeof *m->tri);
    }
    m->tri[3 * m->nt] = a, m->tri[3 * m->nt + 1] = b, m->tri[3 * m->nt + 2] = c;
    m->nt++;
}

/* The quad a b c d (counter-clockwise seen from its front) as two triangles. */
static void add_quad(soup *m, const double a[3], const double b[3], const double c[3],
                     const double d[3])
{
    const int i = add_vertex(m, a[0], a[1], a[2]), j = add_vertex(m, b[0], b[1], b[2]);
    const int k = add_vertex(m, c[0], c[1], c[2]), l = add_vertex(m, d[0], d[1], d[2]);
    add_tri(m, i, j, k);
    add_tri(m, i, k, l);
}

static int make(soup *m, int sides, rs_surface *s)
{
    rs_mesh_def def = RS_MESH_DEF_INIT;
    def.sides = sides;
    const int rc = rs_surface_make_mesh(m->xyz, m->nv, m->tri, m->nt, &def, s, NULL);
    free(m->xyz);
    free(m->tri);
    memset(m, 0, sizeof *m);
    return rc;
}

/* The square [-1, 1]^2 at z = 0, two triangles joined along the diagonal y = x. */
static int floor_mesh(int sides, rs_surface *s)
{
    soup m = {0};
    const double a[3] = {-1, -1, 0}, b[3] = {1, -1, 0}, c[3] = {1, 1, 0}, d[3] = {-1, 1, 0};
    add_quad(&m, a, b, c, d);
    return make(&m, sides, s);
}

/* The cube [-0.5, 0.5]^3, each side an n x n grid of quads. */
static int cube_mesh(int n, rs_surface *s)
{
    soup m = {0};
    for (int ax = 0; ax < 3; ax++)
        for (int sg = -1; sg <= 1; sg += 2)
            for (int i = 0; i < n; i++)
                for (int j = 0; j < n; j++) {
                    const int u = (ax + 1) % 3, v = (ax + 2) % 3;
                    double p[4][3];
                    for (int k = 0; k < 4; k++) {
                        const int di = k == 1 || k == 2, dj = k >= 2;
                        p[k][ax] = 0.5 * sg;
                        p[k][u] = -0.5 + (double)(i + di) / n;
                        p[k][v] = -0.5 + (double)(j + (sg > 0 ? dj : 1 - dj)) / n;
                    }
                    add_quad(&m, p[0], p[1], p[2], p[3]);
                }
    return make(&m, 0, s);
}

/* A UV sphere of radius rad: nlat bands, nlon sectors; its quads are planar. */
static int uv_sphere(double rad, int nlat, int nlon, rs_surface *s)
{
    soup m = {0};
    for (int i = 0; i < nlat; i++)
        for (int j = 0; j < nlon; j++) {
            double p[4][3];
            for (int k = 0; k < 4; k++) {
                const double th = RS_PI * (i + (k >= 2)) / nlat;
                const double ph = 2.0 * RS_PI * (j + (k == 1 || k == 2)) / nlon;
                p[k][0] = rad * sin(th) * cos(ph);
                p[k][1] = rad * sin(th) * sin(ph);
                p[k][2] = rad * cos(th);
            }
            const int a = add_vertex(&m, p[0][0], p[0][1], p[0][2]);
            const int b = add_vertex(&m, p[1][0], p[1][1], p[1][2]);
            const int c = add_vertex(&m, p[2][0], p[2][1], p[2][2]);
            const int d = add_vertex(&m, p[3][0], p[3][1], p[3][2]);
            if (i > 0)
                add_tri(&m, a, c, b);
            if (i < nlat - 1)
                add_tri(&m, a, d, c);
        }
    return make(&m, 0, s);
}

/* The contacts of a sphere of radius R at x by the mesh's sphere query. */
static int sphere_query(const rs_surface *s, const double x[3], double R, double gap,
                        rs_contacts *sc)
{
    const double px[1] = {x[0]}, py[1] = {x[1]}, pz[1] = {x[2]}, pr[1] = {R};
    rs_query q;
    memset(&q, 0, sizeof q);
    q.n = 1;
    q.slave.x = px, q.slave.y = py, q.slave.z = pz, q.slave.radius = pr;
    q.gap_max = gap;
    q.dist_min = -INFINITY;
    memset(sc, 0, sizeof *sc);
    return rs_surface_query(s, &q, sc, NULL);
}

/* The sphere of radius R at x as a body against the sphere query: the same features,
 * depth R - dist, normal and master point, to 1e-9; returns the contacts' count, -1 on a
 * mismatch. */
static int sphere_matches(const rs_surface *s, const double x[3], double R, double gap)
{
    rs_shape sh;
    rs_body b;
    const double q[4] = {1, 0, 0, 0};
    rs_body_contact c[16];
    int n = 0, ok = 1;
    rs_contacts sc;
    if (rs_shape_make_sphere(&sh, R, 0.0, NULL) || rs_body_init(&b, &sh, 1.0, x, q, NULL) ||
        rs_body_surface_contacts(s, NULL, &b, gap, c, 16, &n, NULL) ||
        sphere_query(s, x, R, gap, &sc))
        return -1;
    ok = n == sc.n;
    for (int k = 0; ok && k < sc.n; k++) {
        int j = -1;
        for (int i = 0; i < n; i++)
            if (c[i].feature == sc.feature[k])
                j = i;
        ok = j >= 0 && fabs(c[j].depth - (R - sc.dist[k])) <= 1e-9;
        for (int d = 0; ok && d < 3; d++)
            ok = fabs(c[j].normal[d] - sc.nrm[d][k]) <= 1e-9 &&
                 fabs(c[j].xm[d] - sc.xm[d][k]) <= 1e-9;
        if (ok) { /* the FACETED frame, flat */
            double t1[3], t2[3];
            rs_frame_faceted(c[j].normal, t1, t2);
            for (int d = 0; d < 3; d++)
                ok = ok && fabs(c[j].t1[d] - t1[d]) <= 1e-15 &&
                     fabs(c[j].t2[d] - t2[d]) <= 1e-15;
            ok = ok && c[j].curv[0] == 0.0 && c[j].curv[1] == 0.0 && c[j].iterations == 0;
        }
    }
    if (!ok)
        fprintf(stderr, "sphere at (%g, %g, %g): %d body contacts, %d sphere contacts\n",
                x[0], x[1], x[2], n, sc.n);
    rs_contacts_free(&sc);
    return ok ? n : -1;
}

static void test_sphere_on_floor(void)
{
    const double R = 0.1, gap = 0.02;
    const double xs[8][3] = {
        {0.3, -0.4, 0.08},     /* over the first face */
        {-0.5, 0.2, 0.095},    /* over the second */
        {0.2, 0.2013, 0.09},   /* just off the diagonal */
        {1.05, 0.3, 0.05},     /* beyond the boundary edge x = 1 */
        {1.04, 1.03, 0.02},    /* beyond the corner */
        {0.1, -0.3, -0.07},    /* under the floor */
        {-0.98, 0.6, 0.115},   /* within the gap */
        {0.97, -0.999, 0.099}, /* over the face near a corner */
    };
    for (int sides = 1; sides <= 2; sides++) {
        rs_surface s;
        ENSURE(floor_mesh(sides, &s) == RS_OK);
        for (int t = 0; t < 8; t++) {
            ENSURE(sphere_matches(&s, xs[t], R, gap) == 1);
        }
        rs_surface_free(&s);
    }
}

/* A sphere about closed tessellations: faces, flat diagonals, convex edges and vertices. */
static void test_sphere_on_closed_meshes(void)
{
    rs_surface s;
    ENSURE(uv_sphere(0.5, 24, 48, &s) == RS_OK);
    for (int t = 0; t < 40; t++) {
        const double th = 0.2 + 2.7 * t / 40.0, ph = 0.37 + 2.3 * t;
        const double r = 0.5 + 0.1 - 0.03 * (t % 5) / 4.0;
        const double x[3] = {r * sin(th) * cos(ph), r * sin(th) * sin(ph), r * cos(th)};
        ENSURE(sphere_matches(&s, x, 0.1, 0.01) >= 1);
    }
    rs_surface_free(&s);
    ENSURE(cube_mesh(4, &s) == RS_OK);
    const double xs[6][3] = {{0.1, 0.2, 0.58},    {0.55, 0.55, 0.1},   {0.54, 0.53, 0.56},
                             {0.125, 0.3, -0.59}, {-0.56, 0.02, 0.53}, {0.3, 0.31, 0.57}};
    for (int t = 0; t < 6; t++)
        ENSURE(sphere_matches(&s, xs[t], 0.1, 0.01) == 1);
    rs_surface_free(&s);
}

/* An ellipsoid and a rounded box over the floor in several orientations, some across
 * the diagonal: one contact, the closed-form depth (the lowest point's, as
 * test_body_surface's plane). */
static void test_bodies_across_the_diagonal(void)
{
    rs_surface s;
    ENSURE(floor_mesh(0, &s) == RS_OK);
    const double D[3] = {0.3, 0.12, 0.05}, hx = 0.2, hy = 0.1, hz = 0.05, r = 0.01;
    rs_shape el, bx;
    ENSURE(rs_shape_make_ellipsoid(&el, D[0], D[1], D[2], 0.0, NULL) == RS_OK);
    ENSURE(rs_shape_make_box(&bx, hx, hy, hz, r, NULL) == RS_OK);
    const double quats[5][4] = {{1, 0, 0, 0},
                                {0.9, 0.3, -0.2, 0.1},
                                {0.2, 0.7, 0.5, -0.4},
                                {0.5, -0.5, 0.5, 0.5},
                                {cos(0.3), 0, 0, sin(0.3)}};
    const double at[4][2] = {{0.0, 0.0}, {0.05, -0.02}, {-0.3, 0.31}, {0.4, -0.5}};
    for (int t = 0; t < 5; t++)
        for (int p = 0; p < 4; p++) {
            double q[4], R[9];
            unit_quat(quats[t][0], quats[t][1], quats[t][2], quats[t][3], q);
            rs_quat_matrix(q, R);
            double v[3];
            const double h = ellipsoid_low(R, D, v); /* its lowest point at z - h */
            const double x[3] = {at[p][0], at[p][1], h - 0.01};
            rs_body b;
            rs_body_contact c[4];
            int n = 0;
            ENSURE(rs_body_init(&b, &el, 1000.0, x, q, NULL) == RS_OK);
            ENSURE(rs_body_surface_contacts(&s, NULL, &b, 0.005, c, 4, &n, NULL) == RS_OK);
            ENSURE(n == 1);
            ENSURE_NEAR(c[0].depth, 0.01, 1e-9);
            ENSURE_NEAR(c[0].normal[2], 1.0, 1e-12);
            ENSURE(RS_FEATURE_TYPE(c[0].feature) == RS_FEAT_FACE);
            for (int d = 0; d < 3; d++)
                ENSURE_NEAR(c[0].xs[d], x[d] - v[d] / h, 1e-9);
            ENSURE_NEAR(c[0].xm[2], 0.0, 1e-12);
            /* the rounded box: its lowest corner's height less the rounding */
            double zlow = 1e300;
            for (int k = 0; k < 8; k++) {
                const double u[3] = {(k & 1) ? hx : -hx, (k & 2) ? hy : -hy,
                                     (k & 4) ? hz : -hz};
                double w[3];
                rs_matvec3(R, u, w);
                zlow = fmin(zlow, w[2]);
            }
            const double y[3] = {at[p][0], at[p][1], -zlow + r - 0.007};
            ENSURE(rs_body_init(&b, &bx, 1000.0, y, q, NULL) == RS_OK);
            ENSURE(rs_body_surface_contacts(&s, NULL, &b, 0.005, c, 4, &n, NULL) == RS_OK);
            ENSURE(n == 1);
            ENSURE_NEAR(c[0].depth, 0.007, 1e-9);
            ENSURE_NEAR(c[0].normal[2], 1.0, 1e-12);
            ENSURE(RS_FEATURE_TYPE(c[0].feature) == RS_FEAT_FACE);
        }
    rs_shape_free(&el);
    rs_shape_free(&bx);
    rs_surface_free(&s);
}

/* A box tilted on a gridded cube's top near its edge, its centre and lowest corner over
 * the top: the top's contact at the closed-form depth, and none from the side face it
 * reaches across (at most the top edge's, no deeper). */
static void test_box_at_a_table_edge(void)
{
    rs_surface s;
    ENSURE(cube_mesh(8, &s) == RS_OK);
    const double hx = 0.12, hy = 0.08, hz = 0.05;
    rs_shape bx;
    ENSURE(rs_shape_make_box(&bx, hx, hy, hz, 0.0, NULL) == RS_OK);
    int tried = 0;
    for (int k = 0; k < 300; k++) {
        double q[4], R[9], low[3] = {0, 0, 1e300};
        unit_quat(sin(1.1 * k + 0.3), cos(2.3 * k), sin(0.37 * k + 1), cos(0.91 * k + 2),
                  q);
        rs_quat_matrix(q, R);
        for (int c = 0; c < 8; c++) {
            const double v[3] = {(c & 1) ? hx : -hx, (c & 2) ? hy : -hy,
                                 (c & 4) ? hz : -hz};
            double w[3];
            rs_matvec3(R, v, w);
            if (w[2] < low[2])
                memcpy(low, w, sizeof low);
        }
        const double want = 0.0005 * (1 + k % 20);
        const double x[3] = {0.44 + 0.06 * sin(0.7 * k), 0.3 * cos(1.3 * k),
                             0.5 - low[2] - want};
        if (!(x[0] < 0.5 && x[0] + low[0] < 0.5 && fabs(x[1] + low[1]) < 0.5))
            continue; /* the centre or the lowest corner off the top */
        tried++;
        rs_body b;
        rs_body_contact c[8];
        int n = 0, top = 0;
        ENSURE(rs_body_init(&b, &bx, 1000.0, x, q, NULL) == RS_OK);
        ENSURE(rs_body_surface_contacts(&s, NULL, &b, 0.0, c, 8, &n, NULL) == RS_OK);
        for (int i = 0; i < n; i++) {
            if (RS_FEATURE_TYPE(c[i].feature) == RS_FEAT_FACE) {
                top++;
                ENSURE_NEAR(c[i].depth, want, 1e-9);
                ENSURE_NEAR(c[i].normal[2], 1.0, 1e-12);
            } else {
                ENSURE(RS_FEATURE_TYPE(c[i].feature) == RS_FEAT_EDGE);
                ENSURE(c[i].depth <= want + 1e-9);
            }
        }
        ENSURE(top == 1);
    }
    ENSURE(tried >= 100);
    rs_shape_free(&bx);
    rs_surface_free(&s);
}

/* A box sunk halfway through a one-sided floor, in several orientations: the floor's
 * contact at the closed-form depth (its lowest point's), none at the floor's far borders
 * (a thin plate's way out sideways is no contact of the mesh's). */
static void test_box_through_a_floor(void)
{
    rs_surface s;
    ENSURE(floor_mesh(1, &s) == RS_OK);
    const double hx = 0.1, hy = 0.07, hz = 0.05, r = 0.01;
    rs_shape bx;
    ENSURE(rs_shape_make_box(&bx, hx, hy, hz, r, NULL) == RS_OK);
    for (int k = 0; k < 40; k++) {
        double q[4], R[9], zlow = 1e300;
        unit_quat(sin(1.7 * k + 0.2), cos(0.9 * k), sin(2.1 * k + 1), cos(0.5 * k + 2), q);
        rs_quat_matrix(q, R);
        for (int c = 0; c < 8; c++) {
            const double v[3] = {(c & 1) ? hx : -hx, (c & 2) ? hy : -hy,
                                 (c & 4) ? hz : -hz};
            double w[3];
            rs_matvec3(R, v, w);
            zlow = fmin(zlow, w[2]);
        }
        const double x[3] = {-0.47 + 0.02 * sin(k), 0.26 - 0.5 * cos(k),
                             0.01 * sin(3.0 * k)};
        rs_body b;
        rs_body_contact c[8];
        int n = 0;
        ENSURE(rs_body_init(&b, &bx, 1000.0, x, q, NULL) == RS_OK);
        ENSURE(rs_body_surface_contacts(&s, NULL, &b, 0.01, c, 8, &n, NULL) == RS_OK);
        ENSURE(n == 1);
        ENSURE(RS_FEATURE_TYPE(c[0].feature) == RS_FEAT_FACE);
        ENSURE_NEAR(c[0].depth, -(x[2] + zlow - r), 1e-9);
        ENSURE_NEAR(c[0].normal[2], 1.0, 1e-12);
    }
    rs_shape_free(&bx);
    rs_surface_free(&s);
}

/* The roof z = -|x| tan(20 deg) over y in [-1, 1]: its ridge is the y axis. */
static int roof_mesh(double sg, rs_surface *s)
{
    soup m = {0};
    const double t = sg * tan(20.0 * RS_PI / 180.0);
    const double a[3] = {-1, -1, -t}, b[3] = {0, -1, 0}, c[3] = {0, 1, 0},
                 d[3] = {-1, 1, -t};
    const double e[3] = {1, -1, -t}, f[3] = {1, 1, -t};
    add_quad(&m, a, b, c, d);
    add_quad(&m, b, e, f, c);
    return make(&m, 0, s);
}

/* A quaternion that turns body direction (1, 1, 1) to world +z (a cube's corner down). */
static void corner_down(double q[4])
{
    const double th = acos(1.0 / sqrt(3.0));
    const double k[3] = {1.0 / sqrt(2.0), -1.0 / sqrt(2.0), 0.0};
    q[0] = cos(th / 2), q[1] = sin(th / 2) * k[0], q[2] = sin(th / 2) * k[1];
    q[3] = sin(th / 2) * k[2];
}

/* A cube's corner above the ridge at a gap, a box's face pressed onto the ridge, and the
 * same at a pyramid's apex: the edge or the vertex, the depth from the corner or face. */
static void test_box_at_ridge_and_apex(void)
{
    rs_surface s;
    ENSURE(roof_mesh(1.0, &s) == RS_OK);
    const double h = 0.1, g = 0.005;
    rs_shape cube, slab;
    ENSURE(rs_shape_make_box(&cube, h, h, h, 0.0, NULL) == RS_OK);
    ENSURE(rs_shape_make_box(&slab, 0.3, 0.2, 0.1, 0.0, NULL) == RS_OK);
    double q[4];
    corner_down(q);
    const double x[3] = {0.0, 0.1, h * sqrt(3.0) + g};
    rs_body b;
    rs_body_contact c[4];
    int n = 0;
    ENSURE(rs_body_init(&b, &cube, 1000.0, x, q, NULL) == RS_OK);
    ENSURE(rs_body_surface_contacts(&s, NULL, &b, 0.01, c, 4, &n, NULL) == RS_OK);
    ENSURE(n == 1);
    ENSURE(RS_FEATURE_TYPE(c[0].feature) == RS_FEAT_EDGE);
    ENSURE_NEAR(c[0].depth, -g, 1e-12);
    ENSURE_NEAR(c[0].normal[2], 1.0, 1e-12);
    ENSURE_NEAR(c[0].xm[0], 0.0, 1e-12);
    ENSURE_NEAR(c[0].xm[1], 0.1, 1e-9);
    const double q0[4] = {1, 0, 0, 0}, d = 0.01, y[3] = {0.05, 0.1, 0.1 - d};
    ENSURE(rs_body_init(&b, &slab, 1000.0, y, q0, NULL) == RS_OK);
    ENSURE(rs_body_surface_contacts(&s, NULL, &b, 0.0, c, 4, &n, NULL) == RS_OK);
    ENSURE(n == 1);
    ENSURE(RS_FEATURE_TYPE(c[0].feature) == RS_FEAT_EDGE);
    ENSURE_NEAR(c[0].depth, d, 1e-9);
    ENSURE_NEAR(c[0].normal[2], 1.0, 1e-9);
    rs_surface_free(&s);

    /* the pyramid of apex (0, 0, 0.2) over the square [-1, 1]^2 */
    soup m = {0};
    const int apex = add_vertex(&m, 0, 0, 0.2);
    const double sq[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int k = 0; k < 4; k++) {
        const int i = add_vertex(&m, sq[k][0], sq[k][1], 0.0);
        const int j = add_vertex(&m, sq[(k + 1) % 4][0], sq[(k + 1) % 4][1], 0.0);
        add_tri(&m, i, j, apex);
    }
    ENSURE(make(&m, 0, &s) == RS_OK);
    const double xa[3] = {0.0, 0.0, 0.2 + h * sqrt(3.0) + g};
    ENSURE(rs_body_init(&b, &cube, 1000.0, xa, q, NULL) == RS_OK);
    ENSURE(rs_body_surface_contacts(&s, NULL, &b, 0.01, c, 4, &n, NULL) == RS_OK);
    ENSURE(n == 1);
    ENSURE(RS_FEATURE_TYPE(c[0].feature) == RS_FEAT_VERTEX);
    ENSURE_NEAR(c[0].depth, -g, 1e-12);
    ENSURE_NEAR(c[0].normal[2], 1.0, 1e-12);
    const double ya[3] = {0.03, -0.02, 0.2 + 0.1 - d};
    ENSURE(rs_body_init(&b, &slab, 1000.0, ya, q0, NULL) == RS_OK);
    ENSURE(rs_body_surface_contacts(&s, NULL, &b, 0.0, c, 4, &n, NULL) == RS_OK);
    ENSURE(n == 1);
    ENSURE(RS_FEATURE_TYPE(c[0].feature) == RS_FEAT_VERTEX);
    ENSURE_NEAR(c[0].depth, d, 1e-9);
    ENSURE_NEAR(c[0].normal[2], 1.0, 1e-9);
    rs_surface_free(&s);
    rs_shape_free(&cube);
    rs_shape_free(&slab);
}

/* An ellipsoid inside a drum's mantle (radius 0.5, nsec facets round): the mesh lies
 * inside the cylinder by at most the sagitta 0.5 (1 - cos(pi / nsec)), so its deepest
 * contact is the analytic depth to within it. */
static void test_ellipsoid_in_mesh_drum(void)
{
    const int nsec = 256, nz = 6;
    soup m = {0};
    for (int j = 0; j < nsec; j++)
        for (int i = 0; i < nz; i++) {
            const double p0 = 2.0 * RS_PI * j / nsec, p1 = 2.0 * RS_PI * (j + 1) / nsec;
            const double z0 = -0.3 + 0.6 * i / nz, z1 = -0.3 + 0.6 * (i + 1) / nz;
            const double a[3] = {0.5 * cos(p0), 0.5 * sin(p0), z0};
            const double b[3] = {0.5 * cos(p0), 0.5 * sin(p0), z1};
            const double c[3] = {0.5 * cos(p1), 0.5 * sin(p1), z1};
            const double d[3] = {0.5 * cos(p1), 0.5 * sin(p1), z0};
            add_quad(&m, a, b, c, d); /* normals toward the axis */
        }
    rs_surface mesh, drum;
    ENSURE(make(&m, 0, &mesh) == RS_OK);
    rs_error e;
    rs_error_clear(&e);
    ENSURE(rs_surface_parse("*SURFACE, TYPE=REVOLUTION, NAME=mantle\n"
                            "0, 0, 0, 0, 0, 1\nSTART, 0.5, -0.3\nLINE, 0.5, 0.3\n",
                            "test", NULL, &drum, &e) == RS_OK);
    const double sag = 0.5 * (1.0 - cos(RS_PI / nsec));
    rs_shape sh;
    ENSURE(rs_shape_make_ellipsoid(&sh, 0.1, 0.06, 0.04, 0.0, NULL) == RS_OK);
    const double quats[3][4] = {{0.9, 0.1, 0.3, 0.2}, {1, 0, 0, 0}, {0.3, -0.6, 0.2, 0.7}};
    const double xs[3][3] = {{0.43, 0.05, 0.0}, {-0.1, -0.43, 0.1}, {0.335, -0.335, -0.05}};
    for (int t = 0; t < 3; t++) {
        double q[4];
        unit_quat(quats[t][0], quats[t][1], quats[t][2], quats[t][3], q);
        rs_body b;
        ENSURE(rs_body_init(&b, &sh, 1000.0, xs[t], q, NULL) == RS_OK);
        rs_body_contact ca[4], cm[16];
        int na = 0, nm = 0;
        ENSURE(rs_body_surface_contacts(&drum, NULL, &b, 0.0, ca, 4, &na, NULL) == RS_OK);
        ENSURE(na == 1 && ca[0].depth > 0.0);
        ENSURE(rs_body_surface_contacts(&mesh, NULL, &b, 0.0, cm, 16, &nm, NULL) == RS_OK);
        ENSURE(nm >= 1);
        double deepest = -INFINITY;
        for (int k = 0; k < nm; k++) {
            deepest = fmax(deepest, cm[k].depth);
            ENSURE(RS_FEATURE_TYPE(cm[k].feature) == RS_FEAT_FACE);
        }
        ENSURE(deepest >= ca[0].depth - 1e-12);
        ENSURE(deepest <= ca[0].depth + sag + 1e-12);
    }
    rs_shape_free(&sh);
    rs_surface_free(&mesh);
    rs_surface_free(&drum);
}

/* The roof in a moved pose against the roof's vertices placed there: the same features,
 * depths, normals and points. */
static void test_moved_pose(void)
{
    rs_surface ref;
    ENSURE(roof_mesh(1.0, &ref) == RS_OK);
    double qp[4], R[9];
    unit_quat(0.8, 0.3, -0.4, 0.2, qp);
    rs_quat_matrix(qp, R);
    rs_pose pose;
    memcpy(pose.R, R, sizeof R);
    pose.T[0] = 0.3, pose.T[1] = -1.2, pose.T[2] = 2.0;
    soup m = {0};
    const double t = tan(20.0 * RS_PI / 180.0);
    const double P[6][3] = {{-1, -1, -t}, {0, -1, 0},  {0, 1, 0},
                            {-1, 1, -t},  {1, -1, -t}, {1, 1, -t}};
    double W[6][3];
    for (int k = 0; k < 6; k++)
        rs_pose_to_global(&pose, P[k], W[k]);
    add_quad(&m, W[0], W[1], W[2], W[3]);
    add_quad(&m, W[1], W[4], W[5], W[2]);
    rs_surface placed;
    ENSURE(make(&m, 0, &placed) == RS_OK);
    rs_shape sh;
    ENSURE(rs_shape_make_box(&sh, 0.15, 0.1, 0.05, 0.01, NULL) == RS_OK);
    const double quats[3][4] = {{0.9, 0.1, 0.3, 0.2}, {0.3, -0.6, 0.2, 0.7}, {1, 0, 0, 0}};
    const double at[3][3] = {{0.02, 0.3, 0.04}, {-0.3, -0.2, -0.02}, {0.25, 0.1, -0.04}};
    for (int k = 0; k < 3; k++) {
        double q[4], qw[4], xw[3];
        unit_quat(quats[k][0], quats[k][1], quats[k][2], quats[k][3], q);
        /* the body placed with the roof: x = R X + T, orientation qp q */
        qw[0] = qp[0] * q[0] - qp[1] * q[1] - qp[2] * q[2] - qp[3] * q[3];
        qw[1] = qp[0] * q[1] + qp[1] * q[0] + qp[2] * q[3] - qp[3] * q[2];
        qw[2] = qp[0] * q[2] - qp[1] * q[3] + qp[2] * q[0] + qp[3] * q[1];
        qw[3] = qp[0] * q[3] + qp[1] * q[2] - qp[2] * q[1] + qp[3] * q[0];
        rs_pose_to_global(&pose, at[k], xw);
        rs_body b;
        ENSURE(rs_body_init(&b, &sh, 1000.0, xw, qw, NULL) == RS_OK);
        rs_body_contact c1[8], c2[8];
        int n1 = 0, n2 = 0;
        ENSURE(rs_body_surface_contacts(&ref, &pose, &b, 0.02, c1, 8, &n1, NULL) == RS_OK);
        ENSURE(rs_body_surface_contacts(&placed, NULL, &b, 0.02, c2, 8, &n2, NULL) ==
               RS_OK);
        ENSURE(n1 >= 1 && n1 == n2);
        for (int i = 0; i < n1; i++) {
            int j = -1;
            for (int l = 0; l < n2; l++)
                if (c2[l].feature == c1[i].feature)
                    j = l;
            ENSURE(j >= 0);
            ENSURE_NEAR(c1[i].depth, c2[j].depth, 1e-9);
            /* the witness points are one point where the body's deepest point is, and
             * on one plane where it is not (a box's edge parallel to the face, as k = 2:
             * the two corners tie, and rounding picks either) */
            double dm = 0.0;
            for (int d = 0; d < 3; d++) {
                ENSURE_NEAR(c1[i].normal[d], c2[j].normal[d], 1e-9);
                ENSURE_NEAR(c1[i].t1[d], c2[j].t1[d], 1e-9);
                dm += (c1[i].xm[d] - c2[j].xm[d]) * c1[i].normal[d];
            }
            ENSURE_NEAR(dm, 0.0, 1e-9);
            if (k < 2)
                for (int d = 0; d < 3; d++)
                    ENSURE_NEAR(c1[i].xm[d], c2[j].xm[d], 1e-9);
        }
    }
    rs_shape_free(&sh);
    rs_surface_free(&ref);
    rs_surface_free(&placed);
}

/* A sphere in a V-groove touches both faces (R - its distance to each plane); one slot
 * is too few. */
static void test_capacity_and_refusals(void)
{
    rs_surface s;
    ENSURE(roof_mesh(-1.0, &s) == RS_OK);
    const double R = 0.1, a = 20.0 * RS_PI / 180.0;
    rs_shape sh;
    ENSURE(rs_shape_make_sphere(&sh, R, 0.0, NULL) == RS_OK);
    const double x[3] = {0.01, 0.2, 0.09 / cos(a)}, q[4] = {1, 0, 0, 0};
    rs_body b;
    ENSURE(rs_body_init(&b, &sh, 1000.0, x, q, NULL) == RS_OK);
    rs_body_contact c[2];
    int n = 0;
    rs_error e;
    rs_error_clear(&e);
    ENSURE(rs_body_surface_contacts(&s, NULL, &b, 0.0, c, 2, &n, &e) == RS_OK);
    ENSURE(n == 2);
    for (int k = 0; k < 2; k++) {
        /* the face of normal (-+sin a, 0, cos a) through the ridge's line */
        const double sx = c[k].normal[0] < 0.0 ? -1.0 : 1.0;
        const double dist = sx * sin(a) * x[0] + cos(a) * x[2];
        ENSURE_NEAR(c[k].depth, R - dist, 1e-12);
        ENSURE_NEAR(c[k].normal[0], sx * sin(a), 1e-12);
    }
    ENSURE(rs_body_surface_contacts(&s, NULL, &b, 0.0, c, 1, &n, &e) == RS_ERR_CAPACITY);
    ENSURE(strstr(e.msg, "room for 1"));
    ENSURE(rs_body_surface_contacts(&s, NULL, &b, -1.0, c, 2, &n, &e) == RS_ERR_ARG);
    ENSURE(rs_body_surface_contacts(&s, NULL, &b, 0.0, c, 0, &n, &e) == RS_ERR_ARG);
    rs_shape_free(&sh);
    rs_surface_free(&s);
}

int main(void)
{
    RS_RUN(test_sphere_on_floor);
    RS_RUN(test_sphere_on_closed_meshes);
    RS_RUN(test_bodies_across_the_diagonal);
    RS_RUN(test_box_at_a_table_edge);
    RS_RUN(test_box_through_a_floor);
    RS_RUN(test_box_at_ridge_and_apex);
    RS_RUN(test_ellipsoid_in_mesh_drum);
    RS_RUN(test_moved_pose);
    RS_RUN(test_capacity_and_refusals);
    return rs_test_summary();
}
