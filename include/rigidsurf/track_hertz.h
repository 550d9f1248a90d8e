/* rigidsurf: the usual block in one pass. Spheres, each with one contact with the wall,
 * and the built-in hertz law: the tracker's kinematics, the law and the loads onto the
 * engine's rows run together over each run of contacts, whose values then stay in
 * registers and the first-level cache, instead of stage after stage over the block
 * (track.h, contact_block.h, law.h). The same numbers, bit for bit. */
#ifndef RIGIDSURF_TRACK_HERTZ_H
#define RIGIDSURF_TRACK_HERTZ_H

#include "rigidsurf/contact_block.h"
#include "rigidsurf/track.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Spheres a caller hands to rs_track_hertz_usual at once to keep its values in the
/// first-level cache (the one pass's own run).
#define RS_TRACK_LINE_RUN 32

/// rs_track_update on the block; then, when the block qualifies, the built-in hertz law
/// (props: its 7 properties; areaSlv 1), the law's state into the slots (rs_track_commit)
/// and the loads onto rows (rs_cblock_add_loads with unit areas and shares) and into *w,
/// with each particle's per-atom row (out6, by the rows' index: rdisp(1:3) and stress(1:3);
/// NULL for none), and *done = 1: the same numbers, bit for bit, as those calls in turn
/// (rs_track_load, rs_cblock_inputs and rs_cblock_call between them). The block qualifies
/// when every particle has exactly one contact, held or new (no leaving slot, no
/// handover), nDir is 3, the particles are spheres (radius and mass given), the master
/// has no surface velocity, every share is 1, the tracker keeps the slots of hertz (2 state
/// variables, RS_DROP_STRESS, RS_DROP_ENERGY and RS_DROP_SLIP) and the curvature flag is 0.
/// Otherwise *done = 0, out is what rs_track_update gives, and the caller goes on with the
/// staged calls. Errors: rs_track_update's, and RS_ERR_NONFINITE, as rs_law_call, when the
/// law returns a stress that is NaN or Inf.
int rs_track_hertz(const rs_tracker *tr, const rs_surface *s, const rs_motion *m, double dt,
                   const rs_particles *p, const rs_contacts *c, rs_track_out *out,
                   const double *props, const double origin[3], const rs_load_rows *rows,
                   double *const *out6, rs_wall_load *w, int *done, rs_error *err);

/// rs_track_hertz for a block its caller has found usual: particle k holds contact k
/// (c->point[k] = k, c->n = p->n), within the tracking thickness and in its slot 0 alone
/// (rs_track_dir_usual), the particles are spheres (radius and mass given), the master
/// has no surface velocity, and the tracker and props take the one pass
/// (rs_track_hertz_takes). Pass 1's search of the directories is left out; the rest is
/// rs_track_hertz's one pass, the same numbers bit for bit. Errors: RS_ERR_ARG for a block
/// that is not such a block as far as can be seen without that search (contacts of other
/// particles, a surface velocity, no radius or mass, bodies or witness points, a tracker
/// or props that do not take the one pass), and rs_track_hertz's.
int rs_track_hertz_usual(const rs_tracker *tr, const rs_motion *m, double dt,
                         const rs_particles *p, const rs_contacts *c, rs_track_out *out,
                         const double *props, const double origin[3],
                         const rs_load_rows *rows, double *const *out6, rs_wall_load *w,
                         rs_error *err);

/// Whether a tracker and the hertz law's properties props take the one pass: nDir 3, the
/// law's 2 state variables, RS_DROP_STRESS, RS_DROP_ENERGY and RS_DROP_SLIP, curvature flag
/// 0. A block of spheres without a surface velocity, each with one held contact
/// (rs_track_dir_usual), then always does (*done = 1, or an error).
int rs_track_hertz_takes(const rs_tracker *tr, const double *props);

/// Whether the directory dir (capacity entries) holds the contact of feature f in slot 0
/// and nothing else: the entry that rs_track_hertz's one pass takes.
static inline int rs_track_dir_usual(const double *dir, int capacity, int f)
{
    int ok = dir[0] == RS_DIR_LIVE(f);
    for (int j = 1; j < capacity; j++)
        ok &= dir[j] == RS_DIR_EMPTY;
    return ok;
}

#ifdef __cplusplus
}
#endif
#endif
