/* rigidsurf (private): the tracker's copies between its SoA working set and the
 * Abaqus-layout outputs and the per-contact history slots, 4 contacts at a time: 4 x 4
 * transposes between columns and rows, and interleaves of 3 or 2 columns into rows. With
 * GCC or clang these are vector-extension shuffles (unpcklpd/unpckhpd, vshufpd, vblendpd
 * and vperm2f128 under AVX2, pairs of SSE2 shuffles otherwise); elsewhere plain copies.
 * Pure data movement: the values are copied bit for bit either way. */
#ifndef RS_V4_H
#define RS_V4_H

#include "rs_compiler.h"

#include <string.h>

#if defined(__GNUC__) && (defined(__clang__) || __GNUC__ >= 12)
#define RS_HAVE_V4 1
typedef double rs_v4 __attribute__((vector_size(32)));

/* Vectors pass by pointer: a 32-byte vector argument or return value has a different
 * ABI with and without AVX, which GCC warns about in the baseline build. */
RS_INLINE void rs_v4_load(rs_v4 *v, const double *p)
{
    memcpy(v, p, sizeof *v);
}

RS_INLINE void rs_v4_store(double *p, const rs_v4 *v)
{
    memcpy(p, v, sizeof *v);
}

/* (a, b, c, d) <- their transpose, each a row of the 4 x 4 matrix. */
RS_INLINE void rs_v4_transpose(rs_v4 *a, rs_v4 *b, rs_v4 *c, rs_v4 *d)
{
    const rs_v4 ab0 = __builtin_shufflevector(*a, *b, 0, 4, 2, 6);
    const rs_v4 ab1 = __builtin_shufflevector(*a, *b, 1, 5, 3, 7);
    const rs_v4 cd0 = __builtin_shufflevector(*c, *d, 0, 4, 2, 6);
    const rs_v4 cd1 = __builtin_shufflevector(*c, *d, 1, 5, 3, 7);
    *a = __builtin_shufflevector(ab0, cd0, 0, 1, 4, 5);
    *b = __builtin_shufflevector(ab1, cd1, 0, 1, 4, 5);
    *c = __builtin_shufflevector(ab0, cd0, 2, 3, 6, 7);
    *d = __builtin_shufflevector(ab1, cd1, 2, 3, 6, 7);
}
#endif

/* The 12 doubles (a0 b0 c0 a1 b1 c1 ... c3) at dst <- the columns a, b, c (4 each). */
RS_INLINE void rs_cols3_to_rows4(const double *a, const double *b, const double *c,
                                 double *dst)
{
#ifdef RS_HAVE_V4
    rs_v4 x, y, z;
    rs_v4_load(&x, a);
    rs_v4_load(&y, b);
    rs_v4_load(&z, c);
    const rs_v4 t0 = __builtin_shufflevector(x, y, 0, 4, 2, 6);  /* a0 b0 a2 b2 */
    const rs_v4 t1 = __builtin_shufflevector(x, y, 1, 5, 3, 7);  /* a1 b1 a3 b3 */
    const rs_v4 u = __builtin_shufflevector(z, t1, 0, 4, 2, 6);  /* c0 a1 c2 a3 */
    const rs_v4 v = __builtin_shufflevector(t1, z, 1, 5, 3, 7);  /* b1 c1 b3 c3 */
    const rs_v4 r0 = __builtin_shufflevector(t0, u, 0, 1, 4, 5); /* a0 b0 c0 a1 */
    const rs_v4 r1 = __builtin_shufflevector(v, t0, 0, 1, 6, 7); /* b1 c1 a2 b2 */
    const rs_v4 r2 = __builtin_shufflevector(u, v, 2, 3, 6, 7);  /* c2 a3 b3 c3 */
    rs_v4_store(dst, &r0);
    rs_v4_store(dst + 4, &r1);
    rs_v4_store(dst + 8, &r2);
#else
    for (int l = 0; l < 4; l++) {
        dst[3 * l] = a[l];
        dst[3 * l + 1] = b[l];
        dst[3 * l + 2] = c[l];
    }
#endif
}

/* The 8 doubles (a0 b0 a1 b1 ... b3) at dst <- the columns a, b (4 each). */
RS_INLINE void rs_cols2_to_rows4(const double *a, const double *b, double *dst)
{
#ifdef RS_HAVE_V4
    rs_v4 x, y;
    rs_v4_load(&x, a);
    rs_v4_load(&y, b);
    const rs_v4 t0 = __builtin_shufflevector(x, y, 0, 4, 2, 6); /* a0 b0 a2 b2 */
    const rs_v4 t1 = __builtin_shufflevector(x, y, 1, 5, 3, 7); /* a1 b1 a3 b3 */
    const rs_v4 r0 = __builtin_shufflevector(t0, t1, 0, 1, 4, 5);
    const rs_v4 r1 = __builtin_shufflevector(t0, t1, 2, 3, 6, 7);
    rs_v4_store(dst, &r0);
    rs_v4_store(dst + 4, &r1);
#else
    for (int l = 0; l < 4; l++) {
        dst[2 * l] = a[l];
        dst[2 * l + 1] = b[l];
    }
#endif
}

/* The 4 x 4 matrix whose rows are at s0..s3 (4 doubles each), transposed into rows at
 * d0..d3: d_l[k] = s_k[l]. Columns to rows and rows to columns alike. */
RS_INLINE void rs_transpose4(const double *s0, const double *s1, const double *s2,
                             const double *s3, double *d0, double *d1, double *d2,
                             double *d3)
{
#ifdef RS_HAVE_V4
    rs_v4 a, b, c, d;
    rs_v4_load(&a, s0);
    rs_v4_load(&b, s1);
    rs_v4_load(&c, s2);
    rs_v4_load(&d, s3);
    rs_v4_transpose(&a, &b, &c, &d);
    rs_v4_store(d0, &a);
    rs_v4_store(d1, &b);
    rs_v4_store(d2, &c);
    rs_v4_store(d3, &d);
#else
    const double *s[4] = {s0, s1, s2, s3};
    double *d[4] = {d0, d1, d2, d3}, t[4][4];
    for (int l = 0; l < 4; l++)
        for (int k = 0; k < 4; k++)
            t[l][k] = s[k][l];
    for (int l = 0; l < 4; l++)
        memcpy(d[l], t[l], sizeof t[l]);
#endif
}

#endif
