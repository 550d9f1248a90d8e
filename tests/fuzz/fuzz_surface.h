/* The fuzz target of the surface reader and the query: one input, one verdict. */
#ifndef RS_FUZZ_SURFACE_H
#define RS_FUZZ_SURFACE_H

#include <stddef.h>
#include <stdint.h>

/// Parses data as a surface file; when it is accepted, queries points and spheres over
/// and around its bounds and triangulates it. Returns 0 when every result is finite (or
/// the input was rejected with a code and a message); otherwise prints what failed to
/// stderr and returns 1.
int rs_fuzz_surface_one(const uint8_t *data, size_t size);

/// Inputs accepted as surfaces so far.
extern long rs_fuzz_accepted;

#endif
