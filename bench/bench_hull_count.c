/* A program for an instruction count of a 10^4-point hull's body path: 1000 bodies of a
 * hull of 10^4 points on a sphere of 5 mm, in random orientations, 0.1 mm into the floor
 * z = 0, asked in one rs_surface_query of the two-triangle floor MESH (way 1) or the
 * CYLINDER plane (way 0), as bench_convex asks them. CGAL's hull does not run under
 * valgrind, so the hull is made by a native run and read back under it:
 *   bench_hull_count make hull.bin
 *   valgrind --tool=callgrind --toggle-collect=rs_surface_query \
 *       bench_hull_count read hull.bin 1 */
#include "convex_internal.h"
#include "rigidsurf/convex.h"
#include "rigidsurf/surface.h"
#include "rigidsurf/vec.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_rng.h"

static double urange(double a, double b)
{
    return a + (b - a) * urand();
}

int main(int argc, char **argv)
{
    if (argc < 3 || (strcmp(argv[1], "make") && (strcmp(argv[1], "read") || argc < 4))) {
        fprintf(stderr,
                "usage: bench_hull_count make FILE | read FILE WAY(0 plane, 1 mesh)\n");
        return 2;
    }
    rs_shape s;
    rs_error e;
    rs_error_clear(&e);
    if (!strcmp(argv[1], "make")) {
        static double xyz[3 * 10000];
        for (int i = 0; i < 10000; i++) {
            const double z = urange(-1, 1), ph = urange(0, 2 * RS_PI), r = sqrt(1 - z * z);
            xyz[3 * i] = 0.005 * r * cos(ph);
            xyz[3 * i + 1] = 0.005 * r * sin(ph);
            xyz[3 * i + 2] = 0.005 * z;
        }
        if (rs_shape_make_polyhedron(&s, xyz, 10000, 0.0, &e) != RS_OK) {
            fprintf(stderr, "bench_hull_count: %s\n", e.msg);
            return 1;
        }
        FILE *f = fopen(argv[2], "wb");
        const int ok =
            f && fwrite(&s, sizeof s, 1, f) == 1 &&
            fwrite(s.verts, sizeof *s.verts, 3 * (size_t)s.nv, f) == 3 * (size_t)s.nv &&
            fwrite(s.tris, sizeof *s.tris, 3 * (size_t)s.nt, f) == 3 * (size_t)s.nt;
        if (f)
            fclose(f);
        rs_shape_free(&s);
        return ok ? 0 : 1;
    }
    FILE *f = fopen(argv[2], "rb");
    if (!f || fread(&s, sizeof s, 1, f) != 1) {
        fprintf(stderr, "bench_hull_count: cannot read %s\n", argv[2]);
        return 1;
    }
    s.verts = malloc(3 * (size_t)s.nv * sizeof *s.verts);
    s.tris = malloc(3 * (size_t)s.nt * sizeof *s.tris);
    s.adj0 = s.adj = NULL;
    if (!s.verts || !s.tris ||
        fread(s.verts, sizeof *s.verts, 3 * (size_t)s.nv, f) != 3 * (size_t)s.nv ||
        fread(s.tris, sizeof *s.tris, 3 * (size_t)s.nt, f) != 3 * (size_t)s.nt ||
        rs_hull_adjacency(&s)) {
        fprintf(stderr, "bench_hull_count: cannot read %s\n", argv[2]);
        return 1;
    }
    fclose(f);
    rs_hull_hints(&s);
    enum { N = 1000 };
    static rs_body b[N];
    static double zero[N], r[N];
    for (int i = 0; i < N; i++) {
        double q[4] = {urange(-1, 1), urange(-1, 1), urange(-1, 1), urange(-1, 1)};
        const double l = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        for (int k = 0; k < 4; k++)
            q[k] /= l;
        const double x0[3] = {urange(-1, 1), urange(-1, 1), 0.0}, down[3] = {0, 0, -1};
        double low[3];
        if (rs_body_init(&b[i], &s, 0.0, x0, q, &e) != RS_OK) {
            fprintf(stderr, "bench_hull_count: %s\n", e.msg);
            return 1;
        }
        rs_body_support(&b[i], down, low);
        b[i].x[2] = -low[2] - 1e-4;
        r[i] = 0.005;
    }
    rs_surface floor;
    const int mesh = atoi(argv[3]);
    const double fxyz[12] = {-10, -10, 0, 10, -10, 0, 10, 10, 0, -10, 10, 0};
    const int ftri[6] = {0, 1, 2, 0, 2, 3};
    const rs_mesh_def def = RS_MESH_DEF_INIT;
    if ((mesh ? rs_surface_make_mesh(fxyz, 4, ftri, 2, &def, &floor, &e)
              : rs_surface_parse("*SURFACE, TYPE=CYLINDER, NAME=floor\n0, 0, 0, 1, 0, 0\n"
                                 "0, -1, 0\nSTART, -10, 0\nLINE, 10, 0\n",
                                 "bench", NULL, &floor, &e)) != RS_OK) {
        fprintf(stderr, "bench_hull_count: %s\n", e.msg);
        return 1;
    }
    rs_query q;
    memset(&q, 0, sizeof q);
    q.n = N;
    q.slave.x = q.slave.y = q.slave.z = zero;
    q.slave.radius = r;
    q.slave.body = b;
    q.dist_min = -INFINITY;
    rs_contacts c;
    memset(&c, 0, sizeof c);
    c.witness = 1;
    const int rc = rs_surface_query(&floor, &q, &c, &e);
    printf("%s: rc %d, %d contacts (%.2f a body)\n", mesh ? "MESH" : "plane", rc, c.n,
           c.n / (double)N);
    rs_contacts_free(&c);
    rs_surface_free(&floor);
    free(s.verts), free(s.tris), free(s.adj0), free(s.adj);
    return rc != RS_OK;
}
