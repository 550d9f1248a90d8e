/* Surface load cost: the time and memory of rs_surface_parse (the profile, its
 * vertices and the proximity cache) for profiles of 10^3 to 10^6 segments, of shapes
 * that crowd the cache's buckets differently:
 *
 *   line     collinear LINE pieces (one smooth chain)
 *   polygon  a regular polygon (convex vertices; the pieces near x = +-R stand
 *            crowded along x)
 *   saw      a sawtooth of steep teeth (every tooth spans the whole height)
 *   spiral   an Archimedean spiral of LINE pieces (turns nest along both axes)
 *   arcs     a wave of CIRCL arcs (corners at the joints)
 *   drum     a REVOLUTION drum: a bottom cap, its mantle in collinear LINE pieces and a
 *            top cap
 *
 *   bench_load [--max N] [--shape NAME]
 *
 * Printed: seconds of thread CPU time to parse (best of 3 below 10^6 segments), the
 * heap bytes the surface holds per segment (glibc mallinfo2: bytes in use, mmap'ed
 * blocks included, after the parse minus before), and the query's ns per point: 20000
 * points, each at a random point of a random segment moved by up to h along each axis,
 * queried in one block at a reach (gap_max) of 2 h, the best of 3, where h is the
 * profile's larger bounding-box side over its segment count (the saw's teeth stand h
 * apart); "wide" the same at a reach of 50 h, beyond what the bucket lists of the stored
 * form serve (about 8 segment spacings), so its points walk the tree. Profiles of more than
 * 16384 segments keep the compact form of the query data (analytic_surfaces/profile.h).
 * Then the seconds of thread CPU time of rs_surface_triangulate with 16 points around the
 * hoop (a span of 1 for the extruded shapes): the display mesh of fix wall/rigid's vtk
 * output and rigidsurf-frames --vtk. */
#define _GNU_SOURCE
#include "bench_clock.h"
#include "rigidsurf/surface.h"

#include <malloc.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static char *text;
static size_t cap, len;

static void put(const char *fmt, double a, double b)
{
    if (len + 128 > cap) {
        cap = cap ? 2 * cap : 1 << 20;
        text = realloc(text, cap);
        if (!text) {
            fprintf(stderr, "bench_load: out of memory\n");
            exit(1);
        }
    }
    len += (size_t)snprintf(text + len, cap - len, fmt, a, b);
}

static void make(const char *shape, int n)
{
    len = 0;
    const double pi = 3.14159265358979323846;
    if (!strcmp(shape, "drum")) {
        put("*SURFACE, TYPE=REVOLUTION, NAME=p\n0, 0, 0, 0, 0, 1\nSTART, 0, %.17g%.0s\n",
            0.0, 0);
        put("LINE, %.17g, %.17g\n", 1.0, 0.0);
        for (int k = 1; k <= n - 2; k++)
            put("LINE, %.17g, %.17g\n", 1.0, (double)k / (n - 2));
        put("LINE, %.17g, %.17g\n", 0.0, 1.0);
        return;
    }
    put("*SURFACE, TYPE=SEGMENTS, NAME=p\n%.0s%.0s", 0, 0);
    if (!strcmp(shape, "line")) {
        put("START, %.17g, %.17g\n", 0.0, 0.0);
        for (int k = 1; k <= n; k++)
            put("LINE, %.17g, %.17g\n", (double)k / n, 0.0);
    } else if (!strcmp(shape, "polygon")) {
        put("START, %.17g, %.17g\n", 1.0, 0.0);
        for (int k = 1; k <= n; k++)
            put("LINE, %.17g, %.17g\n", cos(2 * pi * k / n), -sin(2 * pi * k / n));
    } else if (!strcmp(shape, "saw")) {
        put("START, %.17g, %.17g\n", 0.0, 0.0);
        for (int k = 1; k <= n; k++)
            put("LINE, %.17g, %.17g\n", (double)k / n, (k % 2) ? 1.0 : 0.0);
    } else if (!strcmp(shape, "spiral")) {
        const double turns = sqrt((double)n) / 4.0 + 1.0;
        put("START, %.17g, %.17g\n", 0.1, 0.0);
        for (int k = 1; k <= n; k++) {
            const double th = 2 * pi * turns * k / n, r = 0.1 + th / (2 * pi);
            put("LINE, %.17g, %.17g\n", r * cos(th), -r * sin(th));
        }
    } else { /* arcs: a wave of CIRCL arcs, centres alternately above and below */
        put("START, %.17g, %.17g\n", 0.0, 0.0);
        const double h = 1.0 / n;
        for (int k = 0; k < n; k++) {
            put("CIRCL, %.17g, %.17g, ", (k + 1) * h, 0.0);
            put("%.17g, %.17g\n", (k + 0.5) * h, (k % 2 ? -1.0 : 1.0) * h);
        }
    }
}

/* ns per point of one block query around the profile (see the top of this file). */
static double query_ns(const rs_surface *s, double reach_h)
{
    enum { NP = 20000 };
    static double x[NP], y[NP], z[NP];
    const rs_profile *p = &s->profile;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int k = 0; k < p->nseg; k++)
        for (int a = 0; a < 2; a++) {
            lo[a] = fmin(lo[a], fmin(p->seg[k].p0[a], p->seg[k].p1[a]));
            hi[a] = fmax(hi[a], fmax(p->seg[k].p0[a], p->seg[k].p1[a]));
        }
    const double h = fmax(hi[0] - lo[0], hi[1] - lo[1]) / p->nseg;
    unsigned long long st = 0x9E3779B97F4A7C15ull;
    for (int i = 0; i < NP; i++) {
        double u[4];
        for (int j = 0; j < 4; j++) {
            st = st * 6364136223846793005ull + 1442695040888963407ull;
            u[j] = (double)(st >> 11) * 0x1.0p-53;
        }
        const rs_segment *g = &p->seg[(int)(u[0] * p->nseg) % p->nseg];
        x[i] = g->p0[0] + u[1] * (g->p1[0] - g->p0[0]) + 2.0 * h * (u[2] - 0.5);
        y[i] = g->p0[1] + u[1] * (g->p1[1] - g->p0[1]) + 2.0 * h * (u[3] - 0.5);
        z[i] = 0.0;
        if (s->kind == RS_SURF_REVOLUTION) { /* (r, z) in the x-z plane, r >= 0 */
            x[i] = fabs(x[i]);
            z[i] = y[i];
            y[i] = 0.0;
        }
    }
    rs_query q = {.n = NP,
                  .slave = {.x = x, .y = y, .z = z},
                  .pose = NULL,
                  .gap_max = reach_h * h,
                  .dist_min = -reach_h * h};
    rs_contacts c = {0};
    double best = INFINITY;
    for (int r = 0; r < 3; r++) {
        c.n = 0;
        const double t0 = rs_bench_thread_now();
        if (rs_surface_query(s, &q, &c, NULL) != RS_OK || c.n < NP / 4) {
            fprintf(stderr, "bench_load: the query failed (%d contacts)\n", c.n);
            exit(1);
        }
        best = fmin(best, rs_bench_thread_now() - t0);
    }
    rs_contacts_free(&c);
    return 1e9 * best / NP;
}

/* Seconds to triangulate the surface for display (see the top of this file). */
static double triangulate_s(const rs_surface *s)
{
    rs_trimesh m;
    rs_error e;
    const double t0 = rs_bench_thread_now();
    if (rs_surface_triangulate(s, 1.0, 16, &m, &e) != RS_OK) {
        fprintf(stderr, "bench_load: the triangulation failed: %s\n", e.msg);
        exit(1);
    }
    const double t = rs_bench_thread_now() - t0;
    rs_trimesh_free(&m);
    return t;
}

int main(int argc, char **argv)
{
    int nmax = 1000000;
    const char *only = NULL;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!strcmp(argv[i], "--max"))
            nmax = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--shape"))
            only = argv[i + 1];
        else {
            fprintf(stderr, "bench_load: unknown option %s (expected --max N, --shape S)\n",
                    argv[i]);
            return 2;
        }
    }
    printf("build: %s %s\n", RS_BUILD_TYPE, RS_BUILD_FLAGS);
    printf("%-8s %9s %12s %14s %14s %12s %14s\n", "shape", "segments", "load s",
           "bytes/segment", "query ns/pt", "wide ns/pt", "triangulate s");
    const char *shapes[] = {"line", "polygon", "saw", "spiral", "arcs", "drum"};
    for (int si = 0; si < 6; si++) {
        if (only && strcmp(only, shapes[si]))
            continue;
        for (int n = 1000; n <= nmax; n *= 10) {
            make(shapes[si], n);
            double best = INFINITY, qbest = INFINITY, wbest = INFINITY, tbest = INFINITY;
            size_t bytes = 0;
            const int reps = n < 1000000 ? 3 : 1;
            for (int r = 0; r < reps; r++) {
                rs_surface s;
                rs_error e;
                const struct mallinfo2 m0 = mallinfo2();
                const double t0 = rs_bench_thread_now();
                int rc = rs_surface_parse(text, "bench", NULL, &s, &e);
                const double t = rs_bench_thread_now() - t0;
                if (rc != RS_OK) {
                    fprintf(stderr, "bench_load: %s, %d segments: %s\n", shapes[si], n,
                            e.msg);
                    return 1;
                }
                const struct mallinfo2 m1 = mallinfo2();
                bytes = (m1.uordblks + m1.hblkhd) - (m0.uordblks + m0.hblkhd);
                qbest = fmin(qbest, query_ns(&s, 2.0));
                wbest = fmin(wbest, query_ns(&s, 50.0));
                tbest = fmin(tbest, triangulate_s(&s));
                rs_surface_free(&s);
                best = fmin(best, t);
            }
            printf("%-8s %9d %12.4f %14.0f %14.0f %12.0f %14.4f\n", shapes[si], n, best,
                   (double)bytes / n, qbest, wbest, tbest);
            fflush(stdout);
        }
    }
    free(text);
    return 0;
}
