/* MESH query cost against the mesh's size: a sphere of radius 1 tessellated as a UV
 * sphere of 10^2 to 10^6 triangles (written as a binary STL and read through the
 * surface file), queried by 20000 spheres at the same random places, each of radius
 * half the facets' size h = sqrt(4 pi / triangles) and touching the unit sphere, with a
 * gap limit of h (beyond the facets' sag inside the unit sphere), so that each meets
 * about as many facets at every size. Printed per size:
 *
 *   load   seconds to read the STL and build the mesh and its tree (thread CPU time)
 *   B/tri  heap bytes the surface holds per triangle (glibc mallinfo2, after - before)
 *   tree   ns per sphere of rs_surface_query (the AABB tree at every query)
 *   hits   contacts found (of 20000 spheres)
 *   lists  ns per sphere of rs_surface_query_among with candidate lists (margin r/4),
 *          the step's cost in fix wall/rigid; the lists' own build in ns per sphere
 *
 *   bench_mesh [--max N]
 *
 * Each time is the median of 7 repetitions. */
#define _GNU_SOURCE
#include "bench_clock.h"
#include "rigidsurf/surface.h"

#include <malloc.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NQ 20000
#define REPS 7

/* A UV sphere of about ntri triangles as a binary STL at path. */
static void write_sphere(const char *path, int ntri)
{
    const int nlon = (int)fmax(4.0, sqrt((double)ntri));
    const int nlat = ntri / (2 * nlon) + 1;
    FILE *f = fopen(path, "wb");
    if (!f) {
        perror(path);
        exit(1);
    }
    char head[80];
    memset(head, 0, sizeof head);
    snprintf(head, sizeof head, "bench_mesh uv sphere");
    fwrite(head, 1, 80, f);
    const uint32_t n = (uint32_t)(2 * nlon * (nlat - 1));
    fwrite(&n, 4, 1, f);
    const double pi = 3.14159265358979323846;
    for (int i = 0; i < nlat; i++)
        for (int j = 0; j < nlon; j++) {
            float p[4][3];
            for (int c = 0; c < 4; c++) {
                const int ii = i + (c == 1 || c == 2), jj = j + (c >= 2);
                const double th = pi * ii / nlat, ph = 2 * pi * jj / nlon;
                p[c][0] = (float)(sin(th) * cos(ph));
                p[c][1] = (float)(sin(th) * sin(ph));
                p[c][2] = (float)cos(th);
            }
            /* outward: (a, b, c) and (a, c, d), skipping the pole's degenerate halves */
            const int tri[2][3] = {{0, 1, 2}, {0, 2, 3}};
            for (int k = 0; k < 2; k++) {
                if ((i == 0 && k == 1) || (i == nlat - 1 && k == 0))
                    continue;
                float rec[12] = {0, 0, 0};
                for (int c = 0; c < 3; c++)
                    memcpy(rec + 3 + 3 * c, p[tri[k][c]], sizeof p[0]);
                const uint16_t attr = 0;
                fwrite(rec, 4, 12, f);
                fwrite(&attr, 2, 1, f);
            }
        }
    fclose(f);
}

int main(int argc, char **argv)
{
    int nmax = 1000000;
    for (int i = 1; i + 1 < argc; i++)
        if (!strcmp(argv[i], "--max"))
            nmax = atoi(argv[++i]);
    printf("# bench_mesh: %s build (%s)\n", RS_BUILD_TYPE, RS_BUILD_FLAGS);
    printf("# %10s %10s %8s %8s %10s %10s %10s\n", "triangles", "load s", "B/tri", "hits",
           "tree ns", "lists ns", "build ns");
    static double dir[NQ][3], x[NQ], y[NQ], z[NQ], r[NQ];
    unsigned long long seed = 88172645463325252ull;
    for (int i = 0; i < NQ; i++) {
        for (int k = 0; k < 3; k++) {
            seed ^= seed << 13, seed ^= seed >> 7, seed ^= seed << 17;
            dir[i][k] = (double)(seed >> 11) / 9007199254740992.0 * 2.0 - 1.0;
        }
        const double l =
            sqrt(dir[i][0] * dir[i][0] + dir[i][1] * dir[i][1] + dir[i][2] * dir[i][2]);
        for (int k = 0; k < 3; k++)
            dir[i][k] /= l;
    }
    rs_query q;
    memset(&q, 0, sizeof q);
    q.n = NQ;
    q.slave.x = x, q.slave.y = y, q.slave.z = z, q.slave.radius = r;
    for (int n = 100; n <= nmax; n *= 10) {
        const double h = sqrt(4.0 * 3.14159265358979323846 / n), rad = 0.5 * h;
        for (int i = 0; i < NQ; i++) {
            r[i] = rad;
            x[i] = (1.0 + rad) * dir[i][0];
            y[i] = (1.0 + rad) * dir[i][1];
            z[i] = (1.0 + rad) * dir[i][2];
        }
        q.gap_max = h;
        q.dist_min = -rad;
        write_sphere("bench_mesh.stl", n);
        FILE *f = fopen("bench_mesh.inp", "w");
        fputs("*SURFACE, TYPE=MESH, NAME=s, FILE=bench_mesh.stl\n", f);
        fclose(f);
        rs_surface s;
        rs_error e;
        struct mallinfo2 m0 = mallinfo2();
        double t0 = rs_bench_thread_now();
        if (rs_surface_read("bench_mesh.inp", NULL, &s, &e) != RS_OK) {
            fprintf(stderr, "bench_mesh: %s\n", e.msg);
            return 1;
        }
        const double tload = rs_bench_thread_now() - t0;
        struct mallinfo2 m1 = mallinfo2();
        double lo[3], hi[3];
        rs_surface_bounds(&s, lo, hi);
        rs_trimesh tm;
        rs_surface_triangulate(&s, 1.0, 1, &tm, &e);
        const int ntri = tm.ntri;
        rs_trimesh_free(&tm);
        const double bytes =
            (double)((m1.uordblks + m1.hblkhd) - (m0.uordblks + m0.hblkhd)) / ntri;
        rs_contacts c;
        memset(&c, 0, sizeof c);
        double tt[REPS], tl[REPS], tb[REPS];
        rs_cands cd;
        memset(&cd, 0, sizeof cd);
        int hits = 0;
        for (int k = 0; k < REPS; k++) {
            c.n = 0;
            t0 = rs_bench_thread_now();
            rs_surface_query(&s, &q, &c, &e);
            tt[k] = (rs_bench_thread_now() - t0) / NQ * 1e9;
            hits = c.n;
            t0 = rs_bench_thread_now();
            rs_surface_candidates(&s, &q, 0.25 * rad, &cd, &e);
            tb[k] = (rs_bench_thread_now() - t0) / NQ * 1e9;
        }
        static const int *lists[NQ];
        static int counts[NQ];
        for (int i = 0; i < NQ; i++) {
            lists[i] = cd.ids + cd.off[i];
            counts[i] = cd.off[i + 1] - cd.off[i];
        }
        for (int k = 0; k < REPS; k++) {
            c.n = 0;
            t0 = rs_bench_thread_now();
            rs_surface_query_among(&s, &q, lists, counts, &c, &e);
            tl[k] = (rs_bench_thread_now() - t0) / NQ * 1e9;
        }
        printf("  %10d %10.3f %8.0f %8d %10.1f %10.1f %10.1f\n", ntri, tload, bytes, hits,
               rs_bench_median(tt, REPS), rs_bench_median(tl, REPS),
               rs_bench_median(tb, REPS));
        fflush(stdout);
        rs_cands_free(&cd);
        rs_contacts_free(&c);
        rs_surface_free(&s);
    }
    remove("bench_mesh.stl");
    remove("bench_mesh.inp");
    return 0;
}
