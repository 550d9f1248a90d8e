/* The tracker's general pass 1 (track_slots.c), for rs_track_update (track.c). */
#ifndef RIGIDSURF_TRACK_SLOTS_H
#define RIGIDSURF_TRACK_SLOTS_H

#include "rigidsurf/track.h"

#include <stddef.h>

/// Pass 1 for one particle: slots for its contacts kb..ke-1 (written to out entries from
/// *ne on) and its leaving slots. out->point holds the contact index for a contact entry
/// and -1 - i for a leaving slot of particle i until pass 2 decodes it.
int rs_track_assign_slots(const rs_tracker *tr, const rs_surface *s, const rs_particles *p,
                          ptrdiff_t stride, const rs_contacts *c, int i, int kb, int ke,
                          rs_track_out *out, int *ne, rs_error *err);

#endif
