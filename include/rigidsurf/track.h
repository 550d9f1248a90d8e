/* rigidsurf: the contact tracker.
 *
 * One contact is (particle, surface, feature). Each has a history slot that the caller
 * owns (per particle, a directory and `capacity` slots, below), so an engine can migrate
 * and restart it as plain doubles. The tracker turns the contacts of a query into the
 * VUINTER kinematics (docs/conventions.md, "rdisp, drdisp, drot"):
 * - rdisp(1) = R - (x_c - x_m).n, > 0 overlap. drdisp(1) = its change since the last call
 *   (for a new contact: -v_rel.n dt).
 * - The old frame is carried by the master's incremental rotation Q, then by the minimal
 *   rotation P taking Q n_old to n_new: tau_j = P Q t_j,old, drot(i,j) = t_i,new . tau_j.
 * - Slip: s <- drot s, then s += ds with ds_i = v_rel . t_i dt, where
 *   v_rel = v + w x (x_cp - x) - v_master(x_cp) and x_cp = x - (R - rdisp1/2) n.
 *   rdisp(2:3) = s, drdisp(2:3) = ds. nDir = 2 uses t1 only and drot = I.
 * - A new contact's first call carries this increment's motion: drdisp(2:3) = ds,
 *   rdisp(2:3) = ds, drdisp(1) = -v_rel.n dt, drot = I, and zero stress and statev in its
 *   slot (as LIGGGHTS's shear history starts with vt dt). Contacts with gap > tracking
 * count as gone.
 * - A contact whose feature is gone hands its history to an adjacent feature found
 *   this call (rs_surface_adjacent). Otherwise it is emitted once more with RS_MAXVAL in
 *   rdisp, drdisp and drot, then its slot is freed by rs_track_commit.
 * - A convex body's new contact that begins overlapping on a face across a concave fold
 *   from a held contact of the same manifold point (rs_surface_fold: the next facet of a
 *   drum it moves onto) starts from a copy of that contact's history, carried into its
 *   frame by drot like a held one's, with drdisp(1) = -v_rel.n dt as a new contact's
 *   (out->seeded lists these entries). */
#ifndef RIGIDSURF_TRACK_H
#define RIGIDSURF_TRACK_H

#include "rigidsurf/convex.h"
#include "rigidsurf/motion.h"
#include "rigidsurf/surface.h"
#include "rigidsurf/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/* History of one particle, in two parts the caller owns (plain doubles, so an engine can
 * migrate and restart them):
 * - its directory: `capacity` doubles, entry j for slot j: RS_DIR_LIVE(f) = f + 1 (>= 1)
 *   for the contact of feature f the slot holds, RS_DIR_EMPTY (0) when the slot is free,
 *   RS_DIR_LEAVING(f) = -(f + 1) (<= -1) while the contact of feature f is emitted once
 *   more as gone (rs_track_commit frees it). Zeroed memory is an empty directory. A
 *   feature may be held by one slot only: two are an error (RS_ERR_HISTORY);
 * - its slots: `capacity` of rs_track_slot_size(tracker) doubles, slot j at hist + j *
 *   stride (rs_particles.slot_stride). Slots may be contiguous per particle, or slot j of
 *   every particle may sit in one array, so that a particle with one contact touches its
 *   directory and one slot only.
 * A slot is the tracker's own fields (n, t1, slip, rdisp1), then what the law reads of
 * the contact's last call: its stress (3), its state variables (nstatev), its sed,
 * fluxSlv and fluxMst (3). A law that does not read some of them says so (rs_law.skips);
 * the tracker then drops them (rs_tracker.drop) and the slot is shorter. With nothing
 * dropped the offsets are the RS_H_ constants and the size RS_HIST_SIZE(nstatev); in
 * general rs_track_stress_at, rs_track_statev_at, rs_track_energy_at and
 * rs_track_slot_size give them (n and t1 always lead, and the slip and rdisp1 follow
 * at RS_H_SLIP and RS_H_RDISP1 unless RS_DROP_SLIP).
 * A slot's frame is n and t1; t2 = n x t1 (every 3D frame is right-handed). */
#define RS_H_N 0       ///< normal at the last call (3)
#define RS_H_T1 3      ///< t1 at the last call (3)
#define RS_H_SLIP 6    ///< accumulated slip in (t1, t2) (2)
#define RS_H_RDISP1 8  ///< rdisp(1) at the last call
#define RS_H_STRESS 9  ///< stress(1:3) returned by the law at the last call (3)
#define RS_H_STATEV 12 ///< law state variables (nstatev), with the stress kept
#define RS_HIST_SIZE(nstatev) (15 + (nstatev)) ///< a slot that keeps everything

/// What a tracker does not keep in its slots (rs_tracker.drop): the stress of the last
/// call (the law's stress on entry is then zero), the sed, fluxSlv and fluxMst of the
/// last call (zero on entry), the accumulated slip and rdisp(1) of the last call
/// (RS_DROP_SLIP: each call's rdisp(2:3) is then that call's slip increment, drdisp(2:3),
/// and drdisp(1) = -v_rel.n dt, as for a new contact); and what it does not write at all:
/// the closest master points (rs_track_out.coordmst is left as it was).
#define RS_DROP_STRESS 1u
#define RS_DROP_ENERGY 2u
#define RS_DROP_COORDMST 4u
#define RS_DROP_SLIP 8u

#define RS_DIR_EMPTY 0.0                       ///< a free slot (zeroed memory)
#define RS_DIR_LIVE(f) ((double)(f) + 1.0)     ///< the slot holds feature f (f >= 0)
#define RS_DIR_LEAVING(f) (-1.0 - (double)(f)) ///< feature f emitted as gone this call
#define RS_DIR_IS_LIVE(d) ((d) > 0.0)
#define RS_DIR_IS_LEAVING(d) ((d) < 0.0)
/// The feature id of a live or leaving entry.
#define RS_DIR_FEATURE(d) ((d) > 0.0 ? (int)(d)-1 : (int)(-(d)) - 1)

/// Largest per-particle capacity rs_track_update accepts.
#define RS_TRACK_MAX_CAPACITY 64

typedef struct rs_tracker {
    int capacity;    ///< history slots per particle per surface (default 4)
    int nstatev;     ///< law state variables per contact
    int ndir;        ///< 2 (SEGMENTS) or 3
    double tracking; ///< contacts are kept while gap <= tracking
    unsigned drop;   ///< RS_DROP_ flags: what the slots do not keep (0: everything)
} rs_tracker;

/// The offset of the last call's stress in a slot (meaningful unless RS_DROP_STRESS).
static inline int rs_track_stress_at(const rs_tracker *tr)
{
    return (tr->drop & RS_DROP_SLIP) ? RS_H_SLIP : RS_H_STRESS;
}
/// The offset of the state variables in a slot.
static inline int rs_track_statev_at(const rs_tracker *tr)
{
    return rs_track_stress_at(tr) + ((tr->drop & RS_DROP_STRESS) ? 0 : 3);
}
/// The offset of sed, fluxSlv, fluxMst in a slot (meaningful unless RS_DROP_ENERGY).
static inline int rs_track_energy_at(const rs_tracker *tr)
{
    return rs_track_statev_at(tr) + tr->nstatev;
}
/// Doubles of one slot.
static inline int rs_track_slot_size(const rs_tracker *tr)
{
    return rs_track_energy_at(tr) + ((tr->drop & RS_DROP_ENERGY) ? 0 : 3);
}

/// The tracker's view of a block (surface.h, rs_particle_block): n, x, y, z, v, w,
/// radius, id, dir, hist, slot_stride and body. The query points of the same block are
/// its centres.
typedef rs_particle_block rs_particles;

/// Tracker output: one entry per live or leaving contact, in Abaqus layout with
/// stride ndir. Arrays grow as needed.
typedef struct rs_track_out {
    int n, cap, ndir;
    int nleave;        ///< entries that are leaving contacts (RS_DIR_IS_LEAVING)
    int *point;        ///< particle index in the block
    int *feature;      ///< feature id
    double **slot;     ///< the contact's history slot
    double **dir;      ///< the directory entry of that slot
    double *rdisp;     ///< rdisp(ndir, n)
    double *drdisp;    ///< drdisp(ndir, n)
    double *drot;      ///< drot(2, 2, n)
    double *alocaldir; ///< alocaldir(ndir, ndir, n): columns n, t1[, t2]
    double *coordslv;  ///< contact point x_cp (ndir, n)
    double *coordmst;  ///< closest master point x_m (ndir, n); not written when the
                       ///< tracker drops it (RS_DROP_COORDMST)
    double *vrel;      ///< relative velocity of x_cp in (n, t1[, t2]) (ndir, n)
    double *curv;      ///< principal curvatures (2, n)
    double *share;     ///< the contact's share (rs_contacts.share; 1 when leaving): the
                       ///< engine applies share times what the law returns
    int shared;        ///< nonzero when a share may differ from 1 (rs_contacts.shared)
    int *seeded;       ///< the entries (ascending) of a body's contacts that began beside
                       ///< a live contact of the same manifold point on an adjacent
                       ///< feature, their slots seeded with its history (nseeded of them)
    int nseeded;
} rs_track_out;

void rs_track_out_free(rs_track_out *o);

/// Matches the contacts c (from rs_surface_query on the same block, with gap_max =
/// tr->tracking) to history, and fills out (out->n is reset). dt is the increment,
/// m the master's motion after its advance (m->dQ is the increment's rotation), NULL
/// for a fixed master. Returns RS_ERR_CAPACITY naming the particle when it has more
/// contacts than slots, and RS_ERR_HISTORY naming the particle and the feature when its
/// directory holds one feature in two slots (history storage corrupted or not cleared).
int rs_track_update(const rs_tracker *tr, const rs_surface *s, const rs_motion *m,
                    double dt, const rs_particles *p, const rs_contacts *c,
                    rs_track_out *out, rs_error *err);

/// Fills the law's read/write inputs from history, before the law call: stress(ndir, n)
/// of the previous increment with its shear carried into this increment's basis
/// (s(2:3) <- drot s(2:3); leaving contacts keep theirs unrotated) and statev(nstatev,
/// n). Either may be NULL. New contacts read zeros.
void rs_track_load(const rs_tracker *tr, const rs_track_out *out, double *stress,
                   double *statev);

/// Stores the law's results in history: stress(ndir, n) and statev(nstatev, n) for the
/// live contacts (either may be NULL), and frees the slots of leaving contacts.
void rs_track_commit(const rs_tracker *tr, rs_track_out *out, const double *stress,
                     const double *statev);

/// The sed, fluxSlv and fluxMst of each entry's last call, from its slot (zeros for a
/// new contact, and for every contact when the tracker drops them), before the law call.
void rs_track_load_energy(const rs_tracker *tr, const rs_track_out *out, double *sed,
                          double *flux_slv, double *flux_mst);

/// Keeps the live entries' sed, fluxSlv and fluxMst in their slots for the next call
/// (nothing when the tracker drops them). Called before rs_track_commit.
void rs_track_commit_energy(const rs_tracker *tr, const rs_track_out *out,
                            const double *sed, const double *flux_slv,
                            const double *flux_mst);

/// One slot in tr's layout (dst, rs_track_slot_size(tr) values) from one written by a
/// tracker with tr's nstatev that dropped `from` (RS_DROP_ flags; src): the fields both
/// keep are copied, those only tr keeps are zero (an engine's restart file written under
/// another layout).
void rs_track_slot_convert(const rs_tracker *tr, unsigned from, const double *src,
                           double *dst);

/// Marks every slot of one particle empty and zeroes the slots (stride as in
/// rs_particles.slot_stride; 0: contiguous).
void rs_track_clear(const rs_tracker *tr, double *dir, double *hist, ptrdiff_t stride);

#ifdef __cplusplus
}
#endif
#endif
