/* rigidsurf (private): compiler attributes of the hot loops (tracker, query). */
#ifndef RS_COMPILER_H
#define RS_COMPILER_H

/* Always inlined, so the constant arguments of each call site specialise the copy. */
#if defined(__GNUC__)
#define RS_INLINE static inline __attribute__((always_inline))
#else
#define RS_INLINE static inline
#endif

#if defined(__GNUC__)
#define RS_NOINLINE __attribute__((noinline))
#else
#define RS_NOINLINE
#endif

/* Asks for the cache line at address a ahead of its use, into the second-level cache
 * only: for lines asked for far ahead, many at a time. The level-2 cache tracks more
 * misses in flight than the first level, and the lines do not push out what the first
 * level holds meanwhile. An instruction of its own on x86-64: GCC deletes a loop whose
 * body is __builtin_prefetch alone, as a loop without effect. */
#if defined(__GNUC__) && defined(__x86_64__)
#define RS_PREFETCH_L2(a) __asm__ volatile("prefetcht1 %0" : : "m"(*(const char *)(a)))
#elif defined(__GNUC__)
#define RS_PREFETCH_L2(a) __builtin_prefetch((a), 0, 2)
#else
#define RS_PREFETCH_L2(a) ((void)(a))
#endif

/* Built three times, for x86-64-v4 (AVX-512), for AVX2 and for the baseline ISA; the
 * loader picks the one the CPU runs (GCC function multiversioning, x86-64). Loops written
 * to vectorise run 4 or 8 doubles wide, and with AVX-512's 32 vector registers the long
 * loops of the tracker keep more of their values in registers. No FMA: contraction stays
 * off (ISO C mode), so every copy rounds alike. */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define RS_MULTIVERSION __attribute__((target_clones("arch=x86-64-v4", "avx2", "default")))
#else
#define RS_MULTIVERSION
#endif

/* Keeps a loop rolled: a copy loop with a run-length trip count is otherwise unrolled
 * once per call site, which costs instruction cache the hot path needs. */
#if defined(__GNUC__) && !defined(__clang__)
#define RS_NO_UNROLL _Pragma("GCC unroll 1")
#else
#define RS_NO_UNROLL
#endif

/* The loop's arrays do not overlap: they are restrict parameters of an always-inlined
 * function, which GCC's vectoriser no longer sees as such once it is inlined. Without
 * it, a loop over many arrays needs more run-time overlap checks than GCC makes, and
 * stays scalar. (Clang's own pragma for this turns every copy it cannot vectorise, such
 * as a strided store with gaps, into a warning.) */
#if defined(__GNUC__) && !defined(__clang__)
#define RS_IVDEP _Pragma("GCC ivdep")
#else
#define RS_IVDEP
#endif

#endif
