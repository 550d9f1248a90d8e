/* Convex bodies: the cost of one body-contact for each shape, against a sphere contact.
 *
 *   bench_convex [--bodies N] [--reps R] [--only K [--way W]]
 *
 * N bodies of each shape (about 1 cm across, random orientations) are pressed 0.1 mm
 * into the floor z = 0, given three ways: a CYLINDER plane and a MESH of two triangles
 * through rs_surface_query with the N bodies as one block (bodies as slaves: their
 * manifolds, what the driver asks), and one large triangle through rs_convex_triangle
 * alone (GJK, libccd's MPR and its refinement). The reference is the sphere's own path: the
 * same N spheres in one rs_surface_query block. Reported: ns per contact (median of the
 * repetitions, thread CPU time), the ratio to the sphere query, the contacts per body, and
 * on the MESH the calls of libccd's MPR and of our GJK per contact (the link wraps both and
 * counts).
 * --only K runs nothing but the plane's query of shape K (0 .. 8, the table's order; -1:
 * the sphere reference alone), R times, for an instruction count; --way W asks it the
 * MESH's (1) or the triangle's (2) way instead (the same bodies):
 *   valgrind --tool=callgrind --toggle-collect=rs_surface_query bench_convex --only K
 *       [--way W] */
#define _POSIX_C_SOURCE 200809L
#include "rigidsurf/convex.h"
#include "rigidsurf/vec.h"

#include "bench_clock.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_rng.h"
#include "gjk.h"

#include <ccd/ccd.h>

/* The calls of libccd's MPR and of rs_gjk_distance, counted (-Wl,--wrap). */
static long mpr_calls, gjk_calls;
int __real_ccdMPRPenetration(const void *o1, const void *o2, const ccd_t *ccd,
                             ccd_real_t *depth, ccd_vec3_t *dir, ccd_vec3_t *pos);
int __wrap_ccdMPRPenetration(const void *o1, const void *o2, const ccd_t *ccd,
                             ccd_real_t *depth, ccd_vec3_t *dir, ccd_vec3_t *pos);
int __wrap_ccdMPRPenetration(const void *o1, const void *o2, const ccd_t *ccd,
                             ccd_real_t *depth, ccd_vec3_t *dir, ccd_vec3_t *pos)
{
    mpr_calls++;
    return __real_ccdMPRPenetration(o1, o2, ccd, depth, dir, pos);
}
void __real_rs_gjk_distance(const rs_cvx *a, const rs_cvx *b, double stop, rs_gjk *res);
void __wrap_rs_gjk_distance(const rs_cvx *a, const rs_cvx *b, double stop, rs_gjk *res);
void __wrap_rs_gjk_distance(const rs_cvx *a, const rs_cvx *b, double stop, rs_gjk *res)
{
    gjk_calls++;
    __real_rs_gjk_distance(a, b, stop, res);
}

static const char *PLANE = "*SURFACE, TYPE=CYLINDER, NAME=floor\n"
                           "0, 0, 0, 1, 0, 0\n0, -1, 0\nSTART, -10, 0\nLINE, 10, 0\n";

static double urange(double a, double b)
{
    return a + (b - a) * urand();
}

/* The shapes, each about 1 cm across. */
static int make_shape(int k, rs_shape *s, const char **name)
{
    static const char *names[] = {"sphere",      "ellipsoid",     "box",
                                  "rounded box", "capsule",       "cylinder",
                                  "cone",        "polyhedron 64", "polyhedron 10^4"};
    *name = names[k];
    switch (k) {
    case 0:
        return rs_shape_make_sphere(s, 0.005, 0.0, NULL);
    case 1:
        return rs_shape_make_ellipsoid(s, 0.006, 0.004, 0.003, 0.0, NULL);
    case 2:
        return rs_shape_make_box(s, 0.005, 0.004, 0.003, 0.0, NULL);
    case 3:
        return rs_shape_make_box(s, 0.004, 0.003, 0.002, 0.001, NULL);
    case 4:
        return rs_shape_make_capsule(s, 0.003, 0.003, 0.0, NULL);
    case 5:
        return rs_shape_make_cylinder(s, 0.004, 0.004, 0.0, NULL);
    case 6:
        return rs_shape_make_cone(s, 0.004, 0.008, 0.0, NULL);
    default: { /* points on a sphere of 5 mm */
        const int np = k == 7 ? 64 : 10000;
        static double xyz[3 * 10000];
        for (int i = 0; i < np; i++) {
            const double z = urange(-1, 1), ph = urange(0, 2 * RS_PI), r = sqrt(1 - z * z);
            xyz[3 * i] = 0.005 * r * cos(ph);
            xyz[3 * i + 1] = 0.005 * r * sin(ph);
            xyz[3 * i + 2] = 0.005 * z;
        }
        return rs_shape_make_polyhedron(s, xyz, np, 0.0, NULL);
    }
    }
}

int main(int argc, char **argv)
{
    int n = 2000, reps = 7, only = -2, only_way = 0; /* -2: everything */
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!strcmp(argv[i], "--bodies"))
            n = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--reps"))
            reps = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--only"))
            only = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--way"))
            only_way = atoi(argv[i + 1]);
    }
    if (n < 1 || reps < 1 || only < -2 || only > 8 || only_way < 0 || only_way > 2) {
        fprintf(stderr,
                "usage: bench_convex [--bodies N] [--reps R] [--only K [--way W]]\n");
        return 2;
    }
    printf("# bench_convex: %d bodies a shape, %d repetitions (%s, %s)\n", n, reps,
           RS_BUILD_TYPE, RS_BUILD_FLAGS);
    rs_surface plane;
    rs_error e;
    rs_error_clear(&e);
    if (rs_surface_parse(PLANE, "bench", NULL, &plane, &e) != RS_OK) {
        fprintf(stderr, "bench_convex: %s\n", e.msg);
        return 1;
    }
    const double tri[9] = {-10, -10, 0, 10, -10, 0, 0, 10, 0};
    double *t = malloc((size_t)reps * sizeof *t);
    rs_body *b = malloc((size_t)n * sizeof *b);
    double *x = malloc((size_t)n * sizeof *x), *y = malloc((size_t)n * sizeof *y),
           *z = malloc((size_t)n * sizeof *z), *r = malloc((size_t)n * sizeof *r);
    if (!t || !b || !x || !y || !z || !r)
        return 1;

    /* the sphere path: n spheres of 5 mm, 0.1 mm into the floor, one block */
    rs_contacts c;
    memset(&c, 0, sizeof c);
    for (int i = 0; i < n; i++)
        x[i] = urange(-1, 1), y[i] = urange(-1, 1), z[i] = 0.005 - 1e-4, r[i] = 0.005;
    rs_query q;
    memset(&q, 0, sizeof q);
    q.n = n;
    q.slave.x = x, q.slave.y = y, q.slave.z = z, q.slave.radius = r;
    q.gap_max = 0.0;
    q.dist_min = -INFINITY;
    for (int k = 0; k < (only < 0 ? reps : 0); k++) {
        const double t0 = rs_bench_thread_now();
        c.n = 0;
        rs_surface_query(&plane, &q, &c, NULL);
        t[k] = (rs_bench_thread_now() - t0) / c.n;
    }
    const double sphere_ns = only < 0 ? 1e9 * rs_bench_median(t, reps) : 1.0;
    printf("sphere query (rs_surface_query, a block of %d): %.1f ns per contact\n", n,
           sphere_ns);
    const double fxyz[12] = {-10, -10, 0, 10, -10, 0, 10, 10, 0, -10, 10, 0};
    const int ftri[6] = {0, 1, 2, 0, 2, 3};
    const rs_mesh_def def = RS_MESH_DEF_INIT;
    rs_surface floor_mesh;
    if (rs_surface_make_mesh(fxyz, 4, ftri, 2, &def, &floor_mesh, &e) != RS_OK) {
        fprintf(stderr, "bench_convex: %s\n", e.msg);
        return 1;
    }
    printf("%-14s %9s %6s %6s %9s %6s %6s %6s %6s %9s %6s\n", "shape", "plane ns", "ratio",
           "c/body", "mesh ns", "ratio", "c/body", "MPR/c", "GJK/c", "tri ns", "ratio");

    rs_contacts bq;
    memset(&bq, 0, sizeof bq);
    bq.witness = 1;
    /* the bodies as one block (radius 5 mm, the laws' radius), as the driver asks */
    rs_query bqry = q;
    bqry.slave.body = b;
    for (int s = 0; s < (only == -2 ? 9 : only + 1); s++) {
        rs_shape sh;
        const char *name;
        if (make_shape(s, &sh, &name) != RS_OK)
            return 1;
        /* random orientations, each body's lowest point 0.1 mm below the floor */
        for (int i = 0; i < n; i++) {
            double qq[4] = {urange(-1, 1), urange(-1, 1), urange(-1, 1), urange(-1, 1)};
            const double nq =
                sqrt(qq[0] * qq[0] + qq[1] * qq[1] + qq[2] * qq[2] + qq[3] * qq[3]);
            for (int k = 0; k < 4; k++)
                qq[k] /= nq;
            double x0[3] = {urange(-1, 1), urange(-1, 1), 0.0}, low[3];
            rs_body_init(&b[i], &sh, 1000.0, x0, qq, NULL);
            const double down[3] = {0, 0, -1};
            rs_body_support(&b[i], down, low);
            b[i].x[2] = -low[2] - 1e-4;
        }
        double med[3] = {0.0, 0.0, 0.0};
        long found[3] = {0, 0, 0}, mpr = 0, gjk = 0;
        for (int way = 0; way < 3; way++) {
            if (only != -2 && (only != s || way != only_way))
                continue;
            for (int k = 0; k < reps; k++) {
                long m = 0;
                mpr_calls = gjk_calls = 0;
                const double t0 = rs_bench_thread_now();
                if (way < 2) {
                    bq.n = 0;
                    rs_surface_query(way ? &floor_mesh : &plane, &bqry, &bq, NULL);
                    m = bq.n;
                }
                for (int i = 0; way == 2 && i < n; i++) {
                    rs_convex_contact cc;
                    rs_convex_triangle(&b[i], tri, 0.0, &cc, NULL);
                    m += cc.state == RS_CONVEX_OVERLAP;
                }
                t[k] = (rs_bench_thread_now() - t0) / (double)(m ? m : 1);
                found[way] = m;
                if (way == 1)
                    mpr = mpr_calls, gjk = gjk_calls;
            }
            med[way] = 1e9 * rs_bench_median(t, reps);
        }
        const double cm = found[1] ? (double)found[1] : 1.0;
        if (only >= 0 && s != only) {
            rs_shape_free(&sh);
            continue;
        }
        printf("%-14s %9.1f %6.1f %6.3f %9.1f %6.1f %6.3f %6.2f %6.2f %9.1f %6.1f%s\n",
               name, med[0], med[0] / sphere_ns, (double)found[0] / n, med[1],
               med[1] / sphere_ns, (double)found[1] / n, mpr / cm, gjk / cm, med[2],
               med[2] / sphere_ns, found[2] == n || only != -2 ? "" : " (!)");
        rs_shape_free(&sh);
    }
    rs_contacts_free(&bq);
    rs_surface_free(&floor_mesh);
    printf(
        "c/body: contacts a body (its manifold); (!): not every body met the triangle\n");
    rs_contacts_free(&c);
    rs_surface_free(&plane);
    free(t), free(b), free(x), free(y), free(z), free(r);
    return 0;
}
