/* Small test macros in the Box2D style. A test is a void function; a failing check
 * prints where and why and ends that test. main() runs the tests with RS_RUN and
 * returns rs_test_summary(), which prints "N passed, N failed". */
#ifndef RS_TEST_H
#define RS_TEST_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int rs_test_passed, rs_test_failed, rs_test_current_failed;

#define ENSURE(c)                                                                          \
    do {                                                                                   \
        if (!(c)) {                                                                        \
            fprintf(stderr, "%s:%d: ENSURE(%s) failed\n", __FILE__, __LINE__, #c);         \
            rs_test_current_failed = 1;                                                    \
            return;                                                                        \
        }                                                                                  \
    } while (0)

/// |x| <= tol (NaN fails).
#define ENSURE_SMALL(x, tol)                                                               \
    do {                                                                                   \
        double rs_x_ = (double)(x), rs_t_ = (double)(tol);                                 \
        if (!(fabs(rs_x_) <= rs_t_)) {                                                     \
            fprintf(stderr, "%s:%d: ENSURE_SMALL(%s, %s) failed: %.17g\n", __FILE__,       \
                    __LINE__, #x, #tol, rs_x_);                                            \
            rs_test_current_failed = 1;                                                    \
            return;                                                                        \
        }                                                                                  \
    } while (0)

/// |a - b| <= tol (NaN fails).
#define ENSURE_NEAR(a, b, tol)                                                             \
    do {                                                                                   \
        double rs_a_ = (double)(a), rs_b_ = (double)(b), rs_t_ = (double)(tol);            \
        if (!(fabs(rs_a_ - rs_b_) <= rs_t_)) {                                             \
            fprintf(stderr, "%s:%d: ENSURE_NEAR(%s, %s, %s) failed: %.17g vs %.17g\n",     \
                    __FILE__, __LINE__, #a, #b, #tol, rs_a_, rs_b_);                       \
            rs_test_current_failed = 1;                                                    \
            return;                                                                        \
        }                                                                                  \
    } while (0)

/// |a - b| <= rtol * max(|a|, |b|, 1).
#define ENSURE_REL(a, b, rtol)                                                             \
    do {                                                                                   \
        double rs_a_ = (double)(a), rs_b_ = (double)(b);                                   \
        double rs_s_ = fmax(1.0, fmax(fabs(rs_a_), fabs(rs_b_)));                          \
        if (!(fabs(rs_a_ - rs_b_) <= (double)(rtol)*rs_s_)) {                              \
            fprintf(stderr, "%s:%d: ENSURE_REL(%s, %s, %s) failed: %.17g vs %.17g\n",      \
                    __FILE__, __LINE__, #a, #b, #rtol, rs_a_, rs_b_);                      \
            rs_test_current_failed = 1;                                                    \
            return;                                                                        \
        }                                                                                  \
    } while (0)

/* A file whose tests take long runs in shards: with RS_TEST_SHARD=K/N in the environment
 * (0 <= K < N), test number i of main (counting from 0) runs when i mod N == K. */
static inline int rs_test_in_shard(void)
{
    static int index = -1, k = 0, n = 0;
    if (index < 0) {
        const char *v = getenv("RS_TEST_SHARD");
        char end;
        if (!v) {
            k = 0, n = 1;
        } else if (sscanf(v, "%d/%d%c", &k, &n, &end) != 2 || n < 1 || k < 0 || k >= n) {
            fprintf(stderr, "RS_TEST_SHARD=%s: expected K/N with 0 <= K < N\n", v);
            exit(2);
        }
    }
    index++;
    return index % n == k;
}

#define RS_RUN(fn)                                                                         \
    do {                                                                                   \
        if (!rs_test_in_shard())                                                           \
            break;                                                                         \
        rs_test_current_failed = 0;                                                        \
        fn();                                                                              \
        if (rs_test_current_failed) {                                                      \
            rs_test_failed++;                                                              \
            printf("FAIL %s\n", #fn);                                                      \
        } else {                                                                           \
            rs_test_passed++;                                                              \
            printf("ok   %s\n", #fn);                                                      \
        }                                                                                  \
    } while (0)

/// One xorshift64 step of *state: a fixed, portable stream per seed.
static inline unsigned long long rs_test_xorshift(unsigned long long *state)
{
    *state ^= *state << 13;
    *state ^= *state >> 7;
    *state ^= *state << 17;
    return *state;
}

/// Uniform in [0, 1) from the xorshift64 stream *state.
static inline double rs_test_urand(unsigned long long *state)
{
    return (double)(rs_test_xorshift(state) >> 11) * (1.0 / 9007199254740992.0);
}

/* The test file's own stream: a file sets RS_TEST_SEED before including this header
 * to have a stream of its own. */
#ifndef RS_TEST_SEED
#define RS_TEST_SEED 0x9E3779B97F4A7C15ull
#endif
/// Uniform in [0, 1) from the test file's stream.
static inline double urand(void)
{
    static unsigned long long state = RS_TEST_SEED;
    return rs_test_urand(&state);
}
/// Uniform in [a, b) from the test file's stream.
static inline double urange(double a, double b)
{
    return a + (b - a) * urand();
}
/// A unit quaternion (w, x, y, z) uniform over rotations: a point of the 4-ball by
/// rejection from the test file's stream, scaled to unit length.
static inline void random_unit_quaternion(double q[4])
{
    double l;
    do {
        l = 0.0;
        for (int k = 0; k < 4; k++) {
            q[k] = urange(-1.0, 1.0);
            l += q[k] * q[k];
        }
    } while (l < 1e-4 || l > 1.0);
    l = sqrt(l);
    for (int k = 0; k < 4; k++)
        q[k] /= l;
}

static inline int rs_test_summary(void)
{
    printf("%d passed, %d failed\n", rs_test_passed, rs_test_failed);
    return rs_test_failed || rs_test_passed == 0 ? 1 : 0; /* an empty shard fails */
}

#endif
