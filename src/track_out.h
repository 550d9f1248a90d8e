/* The tracker's output arrays (rs_track_out): their growth and release. */
#ifndef RIGIDSURF_TRACK_OUT_H
#define RIGIDSURF_TRACK_OUT_H

#include "rigidsurf/track.h"

/// Room for n entries (every array sized for ndir = 3, so a change of ndir never
/// reallocates). Returns RS_ERR_NOMEM, out keeping what it held.
int rs_track_out_reserve(rs_track_out *o, int n, rs_error *err);

#endif
