/* Helpers shared by the microbenchmarks: a monotonic clock, a thread CPU-time clock,
 * the median of a set of repetitions (sorted in place), and the build description
 * (RS_BUILD_TYPE, RS_BUILD_FLAGS, set by bench/CMakeLists.txt) they print. */
#ifndef RS_BENCH_CLOCK_H
#define RS_BENCH_CLOCK_H

#include <stdlib.h>
#include <time.h>

#ifndef RS_BUILD_TYPE
#define RS_BUILD_TYPE "unknown"
#endif
#ifndef RS_BUILD_FLAGS
#define RS_BUILD_FLAGS ""
#endif

/// Seconds on the monotonic clock.
static inline double rs_bench_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/// Seconds of this thread's CPU time: time the scheduler gives other processes is not
/// counted, so the numbers hold on a shared machine (cache interference still shows).
static inline double rs_bench_thread_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static inline int rs_bench_cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/// Median of v[0..n-1]; sorts v.
static inline double rs_bench_median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, rs_bench_cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

#endif
