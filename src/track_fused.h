/* A law's fused kernel: the usual block in one pass. Particles that each hold one contact
 * with the wall, and a law that has such a kernel (rs_law.fused; the built-in hertz): the
 * tracker's kinematics, the law and the loads onto the engine's rows run together over
 * each run of contacts, whose values then stay in registers and the first-level cache,
 * instead of stage after stage over the block (track.h, contact_block.h, law.h). The same
 * numbers, bit for bit. Internal to the library: the wall (src/wall/) chooses it. */
#ifndef RIGIDSURF_TRACK_FUSED_H
#define RIGIDSURF_TRACK_FUSED_H

#include "rigidsurf/contact_block.h"
#include "rigidsurf/track.h"

#include "track_run.h"

/// The most entries one fused call takes: its outputs are held until every contact's law
/// has given finite values, so that a failing call writes nothing.
#define RS_FUSED_MAX RS_BLOCK

/// Spheres a caller hands to rs_track_fused_usual at once to keep its values in the
/// first-level cache (the kernel's own run).
#define RS_TRACK_LINE_RUN RS_TRACK_RUN

/// A law's fused kernel (rs_law.fused).
struct rs_law_fused {
    /// Whether a tracker and the law's properties take the kernel (the law's state in the
    /// tracker's slot, nDir, the properties' options).
    int (*takes)(const rs_tracker *tr, const double *props, int nprops);
    /// The ne entries of a usual block (entry e: contact e of particle e, each a sphere
    /// holding one contact, live or new) in one pass: the tracker, the law (props), the
    /// history, the loads onto rows and the wall's sums into *w. On error nothing is
    /// written: not the slots, nor the directories, nor the rows.
    int (*pass)(const rs_tracker *tr, const master_rates *mr, double dt,
                const rs_particles *p, const rs_contacts *c, rs_track_out *out, int ne,
                const double *props, const double origin[3], const rs_load_rows *rows,
                rs_wall_load *w, rs_error *err);
    /// Runs of spheres on a revolved LINE may take it (rs_track_fused_usual, the wall's
    /// line path).
    int line;
};

/// rs_track_update on the block; then, when the block qualifies, the law's fused kernel
/// and *done = 1: the same numbers, bit for bit, as rs_track_update, rs_track_load,
/// rs_cblock_inputs, rs_cblock_call, rs_cblock_add_loads (with unit areas) and
/// rs_track_commit in turn, with each particle's rdisp(1:3) and stress(1:3) into
/// rows->out6 (when set). The block qualifies when every particle has exactly one contact,
/// held or new (no leaving slot, no handover), at most RS_FUSED_MAX of them, the particles
/// are spheres (radius and mass given), the master has no surface velocity, every share is
/// 1 and the law's kernel takes the tracker and props. Otherwise *done = 0, out is what
/// rs_track_update gives, and the caller goes on with the staged calls. Errors:
/// rs_track_update's, and RS_ERR_NONFINITE, as rs_law_call, when the law returns a stress
/// that is NaN or Inf; then the call has written nothing.
int rs_track_fused(const rs_tracker *tr, const rs_law *law, const rs_surface *s,
                   const rs_motion *m, double dt, const rs_particles *p,
                   const rs_contacts *c, rs_track_out *out, const double *props,
                   const double origin[3], const rs_load_rows *rows, rs_wall_load *w,
                   int *done, rs_error *err);

/// rs_track_fused for a block its caller has found usual: particle k holds contact k
/// (c->point[k] = k, c->n = p->n <= RS_FUSED_MAX), within the tracking thickness and in
/// its slot 0 alone (rs_track_dir_usual), the particles are spheres, the master has no
/// surface velocity, and the law's kernel takes the tracker and props. Pass 1's search of
/// the directories is left out; the rest is rs_track_fused's, the same numbers bit for
/// bit. Errors: RS_ERR_ARG for a block that is not such a block as far as can be seen
/// without that search, and rs_track_fused's.
int rs_track_fused_usual(const rs_tracker *tr, const rs_law *law, const rs_motion *m,
                         double dt, const rs_particles *p, const rs_contacts *c,
                         rs_track_out *out, const double *props, const double origin[3],
                         const rs_load_rows *rows, rs_wall_load *w, rs_error *err);

#endif
