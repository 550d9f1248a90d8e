/* A flat floor given as a MESH of any triangulation acts as the plane it lies in
 * (docs/conventions.md, "Faceted surfaces" and "Convex bodies"):
 * - a point above a FLAT edge or above a vertex inside the coplanar region (every edge
 *   FLAT) has one contact, a face's, at its height;
 * - a square box resting with its centre on a vertex and its corners on the diagonals
 *   keeps its four corners, each on a face, at the closed-form height h - m g / (4 kn),
 *   and does not turn;
 * - the box sliding with friction across the floor moves exactly as on the analytic
 *   plane z = 0, its four contacts kept from step to step (no history lost at the
 *   triangles' edges), on two triangles split either way, a grid of squares split by
 *   alternating diagonals and that grid with its inner vertices moved in the plane. */
#include "rigidsurf/driver.h"
#include "rigidsurf/vec.h"
#include "rs_test.h"

static const char *PLANE = "*SURFACE, TYPE=CYLINDER, NAME=floor\n"
                           "0, 0, 0, 1, 0, 0\n0, -1, 0\nSTART, -100, 0\nLINE, 100, 0\n";

/* The square [-1, 1]^2 at z = 0 as n x n squares, each split by a diagonal: pattern 0
 * all from the lower left, 1 all from the lower right, 2 alternating; the inner
 * vertices moved in the plane by up to jit / 2 of a square. */
static int make_floor(int n, int pattern, double jit, rs_surface *s)
{
    const int nv = (n + 1) * (n + 1);
    double *xyz = malloc(3 * (size_t)nv * sizeof *xyz);
    int *tri = malloc(6 * (size_t)n * n * sizeof *tri);
    if (!xyz || !tri)
        return 0;
    unsigned long long seed = 7;
    for (int j = 0; j <= n; j++)
        for (int i = 0; i <= n; i++) {
            double x = -1.0 + 2.0 * i / n, y = -1.0 + 2.0 * j / n;
            if (i > 0 && i < n && j > 0 && j < n) {
                x += jit *
                     ((double)(rs_test_xorshift(&seed) >> 11) / 9007199254740992.0 - 0.5) *
                     2.0 / n;
                y += jit *
                     ((double)(rs_test_xorshift(&seed) >> 11) / 9007199254740992.0 - 0.5) *
                     2.0 / n;
            }
            const int v = j * (n + 1) + i;
            xyz[3 * v] = x, xyz[3 * v + 1] = y, xyz[3 * v + 2] = 0.0;
        }
    int t = 0;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            const int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
            const int q[2][6] = {{a, b, c, a, c, d}, {a, b, d, b, c, d}};
            const int *k = q[pattern == 2 ? (i + j) & 1 : pattern];
            for (int l = 0; l < 6; l++)
                tri[3 * t + l] = k[l];
            t += 2;
        }
    const rs_mesh_def def = RS_MESH_DEF_INIT;
    rs_error e;
    const int rc = rs_surface_make_mesh(xyz, nv, tri, t, &def, s, &e);
    if (rc)
        fprintf(stderr, "floor: %s\n", e.msg);
    free(xyz);
    free(tri);
    return rc == RS_OK;
}

/* The floors: two triangles split either way, an 8 x 8 grid alternating, and a 20 x 20
 * grid alternating with its inner vertices moved. */
enum { NFLOOR = 4 };
static int floor_at(int k, rs_surface *s)
{
    const int n[NFLOOR] = {1, 1, 8, 20}, pat[NFLOOR] = {0, 1, 2, 2};
    return make_floor(n[k], pat[k], k == 3 ? 0.6 : 0.0, s);
}

static void test_no_flat_edge_or_inner_vertex_owns_a_point(void)
{
    rs_surface s;
    ENSURE(make_floor(8, 2, 0.0, &s));
    rs_contacts c;
    memset(&c, 0, sizeof c);
    const double h = 0.0123;
    /* per square of the grid (side 0.25): its lower left vertex, the midpoints of its
     * lower and left sides and its centre (on its diagonal); then points anywhere */
    unsigned long long seed = 11;
    for (int k = 0; k < 4 * 64 + 2000; k++) {
        double x, y;
        if (k < 4 * 64) {
            const int sq = k / 4, at = k % 4;
            x = -1.0 + 0.25 * (sq % 8) + ((at & 1) ? 0.125 : 0.0);
            y = -1.0 + 0.25 * (sq / 8) + ((at & 2) ? 0.125 : 0.0);
        } else {
            x = 1.8 * (double)(rs_test_xorshift(&seed) >> 11) / 9007199254740992.0 - 0.9;
            y = 1.8 * (double)(rs_test_xorshift(&seed) >> 11) / 9007199254740992.0 - 0.9;
        }
        if (fabs(x) >= 1.0 || fabs(y) >= 1.0)
            continue; /* the open border's edges and corners own points beyond it */
        const double z = h, r = 0.05;
        rs_query q = {.n = 1,
                      .slave = {.x = &x, .y = &y, .z = &z, .radius = &r},
                      .gap_max = 0.1,
                      .dist_min = -INFINITY};
        c.n = 0;
        ENSURE(rs_surface_query(&s, &q, &c, NULL) == RS_OK);
        ENSURE(c.n == 1);
        ENSURE(RS_FEATURE_TYPE(c.feature[0]) == RS_FEAT_FACE);
        ENSURE_NEAR(c.dist[0], h, 1e-15);
        ENSURE_NEAR(c.nrm[2][0], 1.0, 1e-15);
    }
    rs_contacts_free(&c);
    rs_surface_free(&s);
}

/* A square box (half 0.05 x 0.05 x 0.02, 200 g) on surface s under gravity, hooke kn =
 * kt = 1e5, zeta 0.7, friction mu; yaw about z, velocity (vx, vy); after steps, its
 * pose and spin into out (x, y, z, q0, q3, wx, wy, wz), and how many steps had other
 * than four tracker entries (a contact lost, or a fifth). */
static int box_run(const rs_surface *s, double mu, double yaw, double vx, double vy,
                   int steps, double out[8], int *odd)
{
    rs_driver d;
    rs_error e;
    rs_shape box;
    const double law[5] = {1e5, 1e5, 0.7, 0.7, mu}, g = 9.81;
    if (rs_shape_make_box(&box, 0.05, 0.05, 0.02, 0.0, NULL) != RS_OK ||
        rs_driver_init(&d, s, 1, &e) != RS_OK ||
        rs_driver_set_law(&d, rs_law_find("hooke"), law, 5, 2, &e) != RS_OK ||
        rs_driver_set_body(&d, 0, &box, 2000.0, &e) != RS_OK)
        return 0;
    const double m = d.mass[0];
    d.q[0] = cos(0.5 * yaw);
    d.q[3] = sin(0.5 * yaw);
    d.z[0] = 0.02 - m * g / (4.0 * law[0]);
    d.vx[0] = vx;
    d.vy[0] = vy;
    d.fext[2] = -m * g;
    d.dt = 1e-5;
    d.tracking = 1e-3;
    *odd = 0;
    for (int k = 0; k < steps; k++) {
        if (rs_driver_step(&d, &e) != RS_OK) {
            fprintf(stderr, "step %d: %s\n", k, e.msg);
            return 0;
        }
        *odd += d.trk.n != 4;
        for (int j = 0; j < d.trk.n; j++)
            *odd += RS_FEATURE_TYPE(d.trk.feature[j]) != RS_FEAT_FACE;
    }
    const double o[8] = {d.x[0], d.y[0], d.z[0], d.q[0], d.q[3], d.wx[0], d.wy[0], d.wz[0]};
    memcpy(out, o, sizeof o);
    rs_driver_free(&d);
    return 1;
}

static void test_box_keeps_its_four_corners_on_any_triangulation(void)
{
    const double zc = 0.02 - 0.8 * 9.81 / 4e5; /* m = 2000 * 0.1 * 0.1 * 0.04 */
    for (int k = 0; k < NFLOOR; k++) {
        rs_surface s;
        ENSURE(floor_at(k, &s));
        double o[8];
        int odd;
        /* centred on a vertex, its corners on the diagonals of the grids */
        ENSURE(box_run(&s, 0.5, 0.0, 0.0, 0.0, 2000, o, &odd));
        ENSURE(odd == 0);
        ENSURE_NEAR(o[2], zc, 1e-12);
        ENSURE_SMALL(o[0], 1e-15);
        ENSURE_SMALL(o[1], 1e-15);
        for (int j = 5; j < 8; j++)
            ENSURE_SMALL(o[j], 1e-12);
        rs_surface_free(&s);
    }
}

static void test_sliding_box_moves_as_on_the_analytic_plane(void)
{
    rs_surface plane;
    ENSURE(rs_surface_parse(PLANE, "plane", NULL, &plane, NULL) == RS_OK);
    for (int yaw = 0; yaw < 2; yaw++) {
        double ref[8];
        int odd;
        ENSURE(box_run(&plane, 0.3, 0.3 * yaw, 1.0, 0.3, 10000, ref, &odd));
        ENSURE(odd == 0);
        ENSURE(ref[0] > 0.08); /* it crossed edges of the grids */
        for (int k = 0; k < NFLOOR; k++) {
            rs_surface s;
            ENSURE(floor_at(k, &s));
            double o[8];
            ENSURE(box_run(&s, 0.3, 0.3 * yaw, 1.0, 0.3, 10000, o, &odd));
            ENSURE(odd == 0);
            /* measured: equal bit for bit */
            for (int j = 0; j < 8; j++)
                ENSURE_NEAR(o[j], ref[j], 1e-12);
            rs_surface_free(&s);
        }
    }
    rs_surface_free(&plane);
}

int main(void)
{
    RS_RUN(test_no_flat_edge_or_inner_vertex_owns_a_point);
    RS_RUN(test_box_keeps_its_four_corners_on_any_triangulation);
    RS_RUN(test_sliding_box_moves_as_on_the_analytic_plane);
    return rs_test_summary();
}
