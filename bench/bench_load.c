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
 *
 *   bench_load [--max N] [--shape NAME]
 *
 * Printed: seconds of thread CPU time to parse (best of 3 below 10^6 segments), and the
 * heap bytes the surface holds per segment (glibc mallinfo2: bytes in use, mmap'ed
 * blocks included, after the parse minus before). */
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
    put("*SURFACE, TYPE=SEGMENTS, NAME=p\n%.0s%.0s", 0, 0);
    const double pi = 3.14159265358979323846;
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
    printf("%-8s %9s %12s %14s\n", "shape", "segments", "load s", "bytes/segment");
    const char *shapes[] = {"line", "polygon", "saw", "spiral", "arcs"};
    for (int si = 0; si < 5; si++) {
        if (only && strcmp(only, shapes[si]))
            continue;
        for (int n = 1000; n <= nmax; n *= 10) {
            make(shapes[si], n);
            double best = INFINITY;
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
                rs_surface_free(&s);
                best = fmin(best, t);
            }
            printf("%-8s %9d %12.4f %14.0f\n", shapes[si], n, best, (double)bytes / n);
            fflush(stdout);
        }
    }
    free(text);
    return 0;
}
