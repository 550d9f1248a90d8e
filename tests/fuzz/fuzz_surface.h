/* The fuzz target of the surface reader and the query: one input, one verdict. */
#ifndef RS_FUZZ_SURFACE_H
#define RS_FUZZ_SURFACE_H

#include <stddef.h>
#include <stdint.h>

/// Parses data as a surface file; when it is accepted, queries points and spheres over
/// and around its bounds and triangulates it; then reads data as arrays
/// (rs_fuzz_arrays_one) and as convex bodies (rs_fuzz_bodies_one). Returns 0 when every result is finite (or
/// the input was rejected with a code and a message); otherwise prints what failed to
/// stderr and returns 1.
int rs_fuzz_surface_one(const uint8_t *data, size_t size);

/// The same bytes read as arrays (fuzz_arrays.c): a mesh's vertices and triangles or a
/// profile's items and frame, built with rs_surface_make_mesh or rs_surface_make_profile
/// and checked as a parsed surface is. Returns 0 or 1 as rs_fuzz_surface_one.
int rs_fuzz_arrays_one(const uint8_t *data, size_t size);

/// The same bytes read as convex bodies (fuzz_bodies.c): shapes of every kind, poses,
/// and a pair query with a second body or a triangle. Returns 0 or 1 as
/// rs_fuzz_surface_one.
int rs_fuzz_bodies_one(const uint8_t *data, size_t size);

/// Queries points and spheres over and around the bounds of an accepted surface and
/// triangulates it: 0 when every result is finite, else 1 with what failed on stderr.
struct rs_surface;
int rs_fuzz_check_surface(const struct rs_surface *s);

/// Inputs accepted as surfaces so far.
extern long rs_fuzz_accepted;
/// Those of them built from arrays.
extern long rs_fuzz_arrays_accepted;
/// Convex pair queries answered.
extern long rs_fuzz_bodies_queried;

#endif
