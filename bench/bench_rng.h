/* The benchmarks' random stream: xorshift64*, a fixed and portable stream, so runs are
 * reproducible. A benchmark may reseed rng_state. */
#ifndef RS_BENCH_RNG_H
#define RS_BENCH_RNG_H

static unsigned long long rng_state = 0x9e3779b97f4a7c15ull;

/// Uniform in [0, 1).
static double urand(void)
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return (double)((rng_state * 2685821657736338717ull) >> 11) *
           (1.0 / 9007199254740992.0);
}

#endif
