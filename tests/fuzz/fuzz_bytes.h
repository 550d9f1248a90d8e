/* The fuzz inputs read as a stream of bytes (fuzz_arrays.c, fuzz_bodies.c). */
#ifndef RS_FUZZ_BYTES_H
#define RS_FUZZ_BYTES_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

/* The input read as a stream of bytes, from its start again once it runs out. */
typedef struct bytes {
    const uint8_t *p;
    size_t n, i;
} bytes;

static inline unsigned next(bytes *b)
{
    return b->n ? b->p[b->i++ % b->n] : 0u;
}

/* A coordinate: a point of a grid of sixteenths, or now and then a value no surface may
 * hold (NaN, infinite, huge) or one at the edge of the doubles (denormal, zero). */
static inline double value(bytes *b)
{
    const unsigned c = next(b);
    switch (c) {
    case 0xff:
        return NAN;
    case 0xfe:
        return -INFINITY;
    case 0xfd:
        return 1e300;
    case 0xfc:
        return 4.9e-324;
    case 0xfb:
        return 0.0;
    default:
        return ((int)c - 128) / 16.0;
    }
}

#endif
