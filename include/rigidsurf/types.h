/* rigidsurf: rigid-wall contact for DEM with Abaqus VUINTER conventions.
 * Basic types, error reporting, feature ids and the Fortran-layout accessors. */
#ifndef RIGIDSURF_TYPES_H
#define RIGIDSURF_TYPES_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/// Abaqus r_MaxVal: marks a contact that left the tracking thickness (one call only).
#define RS_MAXVAL 1.0e30

/// Largest number of contacts handed to a law in one call (VUINTER nblock).
#define RS_BLOCK 128

/// Largest number of state variables per contact (laws, tracker, driver, fix).
#define RS_MAX_STATEV 1000

/// Return codes. Every failing call also fills an rs_error with a message.
enum rs_status {
    RS_OK = 0,
    RS_ERR_IO = 1,        ///< file missing or unreadable
    RS_ERR_PARSE = 2,     ///< malformed input text (message names file and line)
    RS_ERR_GEOMETRY = 3,  ///< degenerate or inconsistent geometry
    RS_ERR_ARG = 4,       ///< bad argument or property value
    RS_ERR_NOMEM = 5,     ///< allocation failed
    RS_ERR_NOTFOUND = 6,  ///< named surface, law or symbol not found
    RS_ERR_NONFINITE = 7, ///< a law produced NaN or Inf
    RS_ERR_CAPACITY = 8,  ///< per-particle contact capacity exceeded
    RS_ERR_HISTORY = 9    ///< contact history inconsistent (a feature in two slots)
};

/// Error record filled by failing calls. The library never prints and never exits.
typedef struct rs_error {
    int code;      ///< one of rs_status
    char msg[512]; ///< one line, "FILE:LINE: what was expected" for input errors
} rs_error;

/// Sets err (if not NULL) and returns code. printf-style message.
int rs_error_set(rs_error *err, int code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/// Clears err to RS_OK with an empty message.
void rs_error_clear(rs_error *err);

/* Feature ids. A feature is a profile segment or triangle face (FACE), a mesh edge
 * (EDGE), or a profile or mesh vertex (VERTEX). Profile vertex k is the start point
 * of segment k; the end point of the last segment of an open profile is vertex nseg. */
#define RS_FEAT_FACE 0
#define RS_FEAT_EDGE 1
#define RS_FEAT_VERTEX 2
#define RS_FEATURE(type, index) ((int)(index)*4 + (int)(type))
#define RS_FEATURE_TYPE(f) ((f)&3)
#define RS_FEATURE_INDEX(f) ((f) >> 2)
#define RS_FEATURE_NONE (-1)
/* A REVOLUTION surface's ring sector s (1 .. RS_RING_SECTORS - 1) of a profile feature
 * f: f + s * RS_SECTOR_STRIDE (docs/conventions.md, "Rings around the axis"). Type and
 * the equality of ids work as for any feature. */
#define RS_RING_SECTORS 4
#define RS_SECTOR_STRIDE (1 << 24)
#define RS_FEATURE_SECTOR(f) ((f) / RS_SECTOR_STRIDE)
#define RS_FEATURE_BASE(f) ((f) % RS_SECTOR_STRIDE)

/* Abaqus (column-major) layout. i, j are 0-based components, k the contact.
 *   a(nd, n):        RS_A2(a, nd, i, k)      e.g. stress, rdisp, coordSlv
 *   a(nd, nd, n):    RS_A3(a, nd, i, j, k)   component i of local direction j (alocaldir)
 *   drot(2, 2, n):   RS_DROT(a, i, j, k) */
#define RS_A2(a, nd, i, k) ((a)[(size_t)(k) * (size_t)(nd) + (size_t)(i)])
#define RS_A3(a, nd, i, j, k)                                                              \
    ((a)[((size_t)(k) * (size_t)(nd) + (size_t)(j)) * (size_t)(nd) + (size_t)(i)])
#define RS_DROT(a, i, j, k) ((a)[(size_t)(k)*4u + (size_t)(j)*2u + (size_t)(i)])

#ifdef __cplusplus
}
#endif
#endif
