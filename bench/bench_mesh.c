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
 *   cands  candidate triangles a sphere in its list (rs_surface_candidates)
 *   lists  ns per sphere of rs_surface_query_among with candidate lists (margin r/4),
 *          the step's cost in fix wall/rigid; the lists' own build in ns per sphere
 *   sorted the same two queries with the spheres in space-filling-curve (Morton) order,
 *          the order in which LIGGGHTS keeps its atoms (atom_modify sort, on by
 *          default) and so the order in which fix wall/rigid queries them
 *
 * Every query runs as fix wall/rigid runs it: in blocks of RS_BLOCK spheres, each into
 * the same contact list, emptied before the block.
 *
 * and last the growth of each query's cost from the smallest size to the largest.
 *
 *   bench_mesh [--max N] [--rounds R]
 *
 * Each time is the median of 7 repetitions in a round, and the table gives the least of
 * R rounds (5 by default). A round times every size in turn, so that each size meets the
 * host's quieter moments: on a shared machine other tenants' memory traffic only ever
 * adds time, and most to the largest meshes, whose records come from memory. The last
 * lines give the growth from these least times and from each size's median round. */
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

/* Morton code of a point of [-1, 1]^3 on a 1024^3 grid. */
static uint64_t morton(const double p[3])
{
    uint64_t code = 0;
    unsigned q[3];
    for (int k = 0; k < 3; k++) {
        double u = (p[k] + 1.0) * 512.0;
        q[k] = u < 0.0 ? 0u : u > 1023.0 ? 1023u : (unsigned)u;
    }
    for (int b = 9; b >= 0; b--)
        for (int k = 0; k < 3; k++)
            code = (code << 1) | ((q[k] >> b) & 1u);
    return code;
}

typedef struct keyed {
    uint64_t key;
    int i;
} keyed;

static int cmp_keyed(const void *a, const void *b)
{
    const uint64_t x = ((const keyed *)a)->key, y = ((const keyed *)b)->key;
    return x < y ? -1 : x > y;
}

/* Ends the run with the message of a failed call. */
static void check(int rc, const char *what, const rs_error *e)
{
    if (rc != RS_OK) {
        fprintf(stderr, "bench_mesh: %s: %s\n", what, e->msg);
        exit(1);
    }
}

/* q's spheres first .. first + n - 1, as the query of one block. */
static rs_query block_of(const rs_query *q, int first, int n)
{
    rs_query b = *q;
    b.n = n;
    b.slave.x += first;
    b.slave.y += first;
    b.slave.z += first;
    b.slave.radius += first;
    return b;
}

/* Times the tree query, the lists' build and the list query of q (ns per sphere), each in
 * blocks of RS_BLOCK spheres into one reused contact list, as fix wall/rigid calls them. */
static void time_queries(const rs_surface *s, const rs_query *q, double margin,
                         double *tree, double *lists_ns, double *build, int *hits,
                         double *cands)
{
    rs_contacts c;
    memset(&c, 0, sizeof c);
    rs_cands cd;
    memset(&cd, 0, sizeof cd);
    rs_error e;
    static int ids[16 * NQ], off[NQ + 1];
    double tt[REPS], tl[REPS], tb[REPS];
    for (int k = 0; k < REPS; k++) {
        *hits = 0;
        double t0 = rs_bench_thread_now();
        for (int b0 = 0; b0 < NQ; b0 += RS_BLOCK) {
            const int n = NQ - b0 < RS_BLOCK ? NQ - b0 : RS_BLOCK;
            const rs_query b = block_of(q, b0, n);
            c.n = 0;
            check(rs_surface_query(s, &b, &c, &e), "rs_surface_query", &e);
            *hits += c.n;
        }
        tt[k] = (rs_bench_thread_now() - t0) / NQ * 1e9;
        /* the lists, kept as the fix keeps them: one array of all blocks' ids */
        off[0] = 0;
        t0 = rs_bench_thread_now();
        for (int b0 = 0; b0 < NQ; b0 += RS_BLOCK) {
            const int n = NQ - b0 < RS_BLOCK ? NQ - b0 : RS_BLOCK;
            const rs_query b = block_of(q, b0, n);
            check(rs_surface_candidates(s, &b, margin, &cd, &e), "rs_surface_candidates",
                  &e);
            if (off[b0] + cd.off[n] > 16 * NQ) {
                fprintf(stderr, "bench_mesh: more than 16 candidates a sphere\n");
                exit(1);
            }
            memcpy(ids + off[b0], cd.ids, (size_t)cd.off[n] * sizeof *ids);
            for (int i = 0; i < n; i++)
                off[b0 + i + 1] = off[b0] + cd.off[i + 1];
        }
        tb[k] = (rs_bench_thread_now() - t0) / NQ * 1e9;
    }
    static const int *lists[NQ];
    static int counts[NQ];
    for (int i = 0; i < NQ; i++) {
        lists[i] = ids + off[i];
        counts[i] = off[i + 1] - off[i];
    }
    for (int k = 0; k < REPS; k++) {
        const double t0 = rs_bench_thread_now();
        for (int b0 = 0; b0 < NQ; b0 += RS_BLOCK) {
            const int n = NQ - b0 < RS_BLOCK ? NQ - b0 : RS_BLOCK;
            const rs_query b = block_of(q, b0, n);
            c.n = 0;
            check(rs_surface_query_among(s, &b, lists + b0, counts + b0, &c, &e),
                  "rs_surface_query_among", &e);
        }
        tl[k] = (rs_bench_thread_now() - t0) / NQ * 1e9;
    }
    *tree = rs_bench_median(tt, REPS);
    *lists_ns = rs_bench_median(tl, REPS);
    *build = rs_bench_median(tb, REPS);
    *cands = (double)off[NQ] / NQ;
    rs_cands_free(&cd);
    rs_contacts_free(&c);
}

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

#define NSIZE 5 /* 10^2 .. 10^6 triangles */
#define NCOL 6  /* tree, lists, build; the same sorted */

int main(int argc, char **argv)
{
    int nmax = 1000000, rounds = 5;
    for (int i = 1; i + 1 < argc; i++) {
        if (!strcmp(argv[i], "--max"))
            nmax = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--rounds"))
            rounds = atoi(argv[++i]);
    }
    if (rounds < 1 || rounds > 64) {
        fprintf(stderr, "bench_mesh: --rounds takes 1 to 64\n");
        return 1;
    }
    printf("# bench_mesh: %s build (%s), %d rounds\n", RS_BUILD_TYPE, RS_BUILD_FLAGS,
           rounds);
    static double dir[NQ][3];
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
    /* the same directions in Morton order */
    static keyed order[NQ];
    static double sdir[NQ][3];
    for (int i = 0; i < NQ; i++) {
        order[i].key = morton(dir[i]);
        order[i].i = i;
    }
    qsort(order, NQ, sizeof order[0], cmp_keyed);
    for (int i = 0; i < NQ; i++)
        memcpy(sdir[i], dir[order[i].i], sizeof sdir[i]);

    /* every size's mesh, read once */
    static double pts[NSIZE][7][NQ]; /* x, y, z, r; sorted x, y, z (same r) */
    static rs_surface surf[NSIZE];
    static rs_query q[NSIZE], qs[NSIZE];
    int ntri[NSIZE], hits[NSIZE];
    double tload[NSIZE], bytes[NSIZE], cands[NSIZE], margin[NSIZE];
    int nsize = 0;
    for (int n = 100; n <= nmax && nsize < NSIZE; n *= 10, nsize++) {
        const int k = nsize;
        const double h = sqrt(4.0 * 3.14159265358979323846 / n), rad = 0.5 * h;
        double *x = pts[k][0], *y = pts[k][1], *z = pts[k][2], *r = pts[k][3];
        double *sx = pts[k][4], *sy = pts[k][5], *sz = pts[k][6];
        for (int i = 0; i < NQ; i++) {
            r[i] = rad;
            x[i] = (1.0 + rad) * dir[i][0];
            y[i] = (1.0 + rad) * dir[i][1];
            z[i] = (1.0 + rad) * dir[i][2];
            sx[i] = (1.0 + rad) * sdir[i][0];
            sy[i] = (1.0 + rad) * sdir[i][1];
            sz[i] = (1.0 + rad) * sdir[i][2];
        }
        memset(&q[k], 0, sizeof q[k]);
        q[k].n = NQ;
        q[k].slave.x = x, q[k].slave.y = y, q[k].slave.z = z, q[k].slave.radius = r;
        q[k].gap_max = h;
        q[k].dist_min = -rad;
        qs[k] = q[k];
        qs[k].slave.x = sx, qs[k].slave.y = sy, qs[k].slave.z = sz; /* the same radii */
        margin[k] = 0.25 * rad;
        write_sphere("bench_mesh.stl", n);
        FILE *f = fopen("bench_mesh.inp", "w");
        if (!f) {
            perror("bench_mesh.inp");
            return 1;
        }
        fputs("*SURFACE, TYPE=MESH, NAME=s, FILE=bench_mesh.stl\n", f);
        fclose(f);
        rs_error e;
        struct mallinfo2 m0 = mallinfo2();
        const double t0 = rs_bench_thread_now();
        if (rs_surface_read("bench_mesh.inp", NULL, &surf[k], &e) != RS_OK) {
            fprintf(stderr, "bench_mesh: %s\n", e.msg);
            return 1;
        }
        tload[k] = rs_bench_thread_now() - t0;
        struct mallinfo2 m1 = mallinfo2();
        rs_trimesh tm;
        rs_surface_triangulate(&surf[k], 1.0, 1, &tm, &e);
        ntri[k] = tm.ntri;
        rs_trimesh_free(&tm);
        bytes[k] =
            (double)((m1.uordblks + m1.hblkhd) - (m0.uordblks + m0.hblkhd)) / ntri[k];
    }
    remove("bench_mesh.stl");
    remove("bench_mesh.inp");

    /* the rounds, each over every size in turn */
    static double t[NSIZE][64][NCOL];
    for (int round = 0; round < rounds; round++)
        for (int k = 0; k < nsize; k++) {
            double *row = t[k][round];
            int hs;
            double cs;
            time_queries(&surf[k], &q[k], margin[k], &row[0], &row[1], &row[2], &hits[k],
                         &cands[k]);
            time_queries(&surf[k], &qs[k], margin[k], &row[3], &row[4], &row[5], &hs, &cs);
            if (hs != hits[k]) {
                fprintf(stderr,
                        "bench_mesh: %d contacts in Morton order, %d in random order\n", hs,
                        hits[k]);
                return 1;
            }
        }
    /* per size and column: the least time over the rounds, and the median round's */
    double best[NSIZE][NCOL], med[NSIZE][NCOL];
    for (int k = 0; k < nsize; k++)
        for (int c = 0; c < NCOL; c++) {
            double v[64];
            best[k][c] = INFINITY;
            for (int round = 0; round < rounds; round++) {
                v[round] = t[k][round][c];
                best[k][c] = fmin(best[k][c], v[round]);
            }
            med[k][c] = rs_bench_median(v, rounds);
        }
    printf("# %10s %10s %8s %8s %6s %10s %10s %10s %10s %10s\n", "triangles", "load s",
           "B/tri", "hits", "cands", "tree ns", "lists ns", "build ns", "tree srt",
           "lists srt");
    for (int k = 0; k < nsize; k++)
        printf("  %10d %10.3f %8.0f %8d %6.2f %10.1f %10.1f %10.1f %10.1f %10.1f\n",
               ntri[k], tload[k], bytes[k], hits[k], cands[k], best[k][0], best[k][1],
               best[k][2], best[k][3], best[k][4]);
    if (nsize > 1) {
        const int a = 0, b = nsize - 1;
        printf("# the median round, lists ns: ");
        for (int k = 0; k < nsize; k++)
            printf("%.1f%s", med[k][1], k + 1 < nsize ? " " : "; sorted: ");
        for (int k = 0; k < nsize; k++)
            printf("%.1f%s", med[k][4], k + 1 < nsize ? " " : "\n");
        printf("# from %d to %d triangles the cost grows (least times): tree %.2f x, lists "
               "%.2f x, sorted: tree %.2f x, lists %.2f x (target: at most 3 x)\n",
               ntri[a], ntri[b], best[b][0] / best[a][0], best[b][1] / best[a][1],
               best[b][3] / best[a][3], best[b][4] / best[a][4]);
        printf(
            "# from %d to %d triangles the cost grows (median rounds): tree %.2f x, lists "
            "%.2f x, sorted: tree %.2f x, lists %.2f x\n",
            ntri[a], ntri[b], med[b][0] / med[a][0], med[b][1] / med[a][1],
            med[b][3] / med[a][3], med[b][4] / med[a][4]);
    }
    for (int k = 0; k < nsize; k++)
        rs_surface_free(&surf[k]);
    return 0;
}
