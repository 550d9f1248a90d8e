/* A corpus-driven fuzzer for builds without libFuzzer (GCC, the sanitizer build):
 *
 *   fuzz_surface SECONDS SEED DIR [DIR ...]
 *
 * Reads every file of the DIRs as seeds, checks each as it is, then mutates them for
 * SECONDS of CPU time: byte flips, inserts and deletions, lines dropped, doubled or
 * spliced in from another seed, and numbers replaced by extreme values (overflowing,
 * denormal, huge, tiny, zero, NaN). Exit 1 at the first failing input, which is written
 * to fuzz-failure.inp in the current folder. */
#define _POSIX_C_SOURCE 200809L /* dirent */

#include "fuzz_surface.h"

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { MAXSEED = 256, MAXLEN = 1 << 16 };

static unsigned long long rng = 0x9E3779B97F4A7C15ull;
static unsigned rnd(unsigned n)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return n ? (unsigned)((rng >> 11) % n) : 0;
}

typedef struct {
    char *p;
    size_t n;
} buf;

static buf seeds[MAXSEED];
static int nseed;

static void read_dir(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d) {
        fprintf(stderr, "fuzz_surface: cannot open corpus folder %s\n", dir);
        exit(2);
    }
    struct dirent *de;
    while ((de = readdir(d)) && nseed < MAXSEED) {
        if (de->d_name[0] == '.')
            continue;
        char path[4096];
        snprintf(path, sizeof path, "%s/%s", dir, de->d_name);
        FILE *f = fopen(path, "rb");
        if (!f)
            continue;
        char *p = malloc(MAXLEN);
        size_t n = p ? fread(p, 1, MAXLEN, f) : 0;
        fclose(f);
        if (!p || n == 0) {
            free(p);
            continue;
        }
        seeds[nseed].p = p;
        seeds[nseed].n = n;
        nseed++;
    }
    closedir(d);
}

static const char *const extremes[] = {
    "1e308",     "-1e308",       "2e154", "-1e154", "1e100", "1.0000001e100", "1e-310",
    "-4.9e-324", "1e-13",        "0",     "-0",     "nan",   "inf",           "1e-100",
    "1e-99",     "123456789012", "1d300", ""};

/* One mutation of in (n bytes) into out; returns the new length. */
static size_t mutate(const char *in, size_t n, char *out)
{
    size_t m = 0;
    const unsigned op = rnd(7);
    const size_t at = n ? rnd((unsigned)n) : 0;
    if (op == 0 && n) { /* flip a byte */
        memcpy(out, in, n);
        out[at] = (char)(rnd(256));
        return n;
    }
    if (op == 1) { /* insert a few bytes */
        memcpy(out, in, at);
        m = at;
        const unsigned k = 1 + rnd(8);
        for (unsigned i = 0; i < k; i++)
            out[m++] = "*,=.-e\n 0123456789LINECIRCLPARABSTART"[rnd(36)];
        memcpy(out + m, in + at, n - at);
        return m + n - at;
    }
    if (op == 2 && n) { /* delete a run */
        const size_t k = 1 + rnd(16), end = at + k < n ? at + k : n;
        memcpy(out, in, at);
        memcpy(out + at, in + end, n - end);
        return n - (end - at);
    }
    /* line operations: find the line around at */
    size_t b = at, e = at;
    while (b > 0 && in[b - 1] != '\n')
        b--;
    while (e < n && in[e] != '\n')
        e++;
    if (e < n)
        e++; /* with its newline */
    memcpy(out, in, b);
    m = b;
    if (op == 3) {        /* drop the line */
    } else if (op == 4) { /* double it */
        memcpy(out + m, in + b, e - b);
        m += e - b;
        memcpy(out + m, in + b, e - b);
        m += e - b;
    } else if (op == 5 && nseed > 0) { /* a line of another seed */
        const buf *o = &seeds[rnd((unsigned)nseed)];
        size_t ob = o->n ? rnd((unsigned)o->n) : 0, oe = ob;
        while (ob > 0 && o->p[ob - 1] != '\n')
            ob--;
        while (oe < o->n && o->p[oe] != '\n')
            oe++;
        memcpy(out + m, o->p + ob, oe - ob);
        m += oe - ob;
        out[m++] = '\n';
        memcpy(out + m, in + b, e - b);
        m += e - b;
    } else { /* a number of the line replaced by an extreme value */
        size_t i = b;
        unsigned skip = rnd(6);
        while (i < e) {
            if (in[i] == ',' && skip-- == 0)
                break;
            out[m++] = in[i++];
        }
        if (i < e) {
            out[m++] = in[i++];
            const char *x = extremes[rnd(sizeof extremes / sizeof extremes[0])];
            memcpy(out + m, x, strlen(x));
            m += strlen(x);
            while (i < e && in[i] != ',' && in[i] != '\n')
                i++;
        }
        memcpy(out + m, in + i, e - i);
        m += e - i;
    }
    memcpy(out + m, in + e, n - e);
    return m + n - e;
}

static void keep_failure(const char *p, size_t n)
{
    FILE *f = fopen("fuzz-failure.inp", "wb");
    if (f) {
        fwrite(p, 1, n, f);
        fclose(f);
    }
    fprintf(stderr, "fuzz_surface: failing input written to fuzz-failure.inp\n");
}

int main(int argc, char **argv)
{
    if (argc < 4) {
        fprintf(stderr, "usage: fuzz_surface SECONDS SEED DIR [DIR ...]\n");
        return 2;
    }
    const double seconds = atof(argv[1]);
    rng ^= strtoull(argv[2], NULL, 10) * 0x2545F4914F6CDD1Dull;
    for (int i = 3; i < argc; i++)
        read_dir(argv[i]);
    if (nseed == 0) {
        fprintf(stderr, "fuzz_surface: no seed files\n");
        return 2;
    }
    for (int i = 0; i < nseed; i++)
        if (rs_fuzz_surface_one((const uint8_t *)seeds[i].p, seeds[i].n)) {
            keep_failure(seeds[i].p, seeds[i].n);
            return 1;
        }
    static char cur[4 * MAXLEN], next[4 * MAXLEN];
    long runs = 0;
    const clock_t t0 = clock();
    while ((double)(clock() - t0) / CLOCKS_PER_SEC < seconds) {
        const buf *s = &seeds[rnd((unsigned)nseed)];
        size_t n = s->n;
        memcpy(cur, s->p, n);
        const unsigned depth = 1 + rnd(6);
        for (unsigned d = 0; d < depth; d++) {
            if (n > 2 * MAXLEN)
                break;
            n = mutate(cur, n, next);
            memcpy(cur, next, n);
        }
        runs++;
        if (rs_fuzz_surface_one((const uint8_t *)cur, n)) {
            keep_failure(cur, n);
            return 1;
        }
    }
    printf("fuzz_surface: %d seeds, %ld mutated inputs (%ld surfaces accepted, %ld of them "
           "from arrays; %ld convex pair queries), no failure\n",
           nseed, runs, rs_fuzz_accepted, rs_fuzz_arrays_accepted, rs_fuzz_bodies_queried);
    for (int i = 0; i < nseed; i++)
        free(seeds[i].p);
    return 0;
}
