/* rigidsurf: the wall, one object with one step.
 *
 * An rs_wall is a rigid master surface with everything a DEM engine's wall needs: its law,
 * its motion (move, rotate, spin, servo, a belt's surface velocity), the contact history
 * of every particle, the candidate particles near it, its heat, its facets' stress and
 * wear, its outputs and restart records. It is made from the words of `fix wall/rigid`'s
 * arguments (docs/fix_wall_rigid.md), parsed once with the fix's messages, or from a
 * definition in memory (rs_wall_make). Per time step the engine makes one call,
 * rs_wall_step, over its particles: the candidates near the wall are queried in blocks,
 * their contacts tracked, the law called and the loads added onto the engine's rows, the
 * history committed; where the law has a fused kernel and the block qualifies, these run
 * in one pass (the choice is made here, once). Around it: rs_wall_setup (the forces before
 * the first step, no history advanced), rs_wall_advance (the wall's motion, before the
 * step), rs_wall_servo (after it), rs_wall_reneighbor (the engine's lists were rebuilt),
 * the per-particle history for migration and restart (rs_wall_grow, rs_wall_copy,
 * rs_wall_pack, rs_wall_unpack, rs_wall_unpack_restart) and the global restart record.
 *
 * What only the engine knows comes through a small host table (rs_wall_host): the value
 * of a variable, a material property per type, sums over ranks, warnings, the engine's
 * own contact models as a law. No MPI and no engine header is needed here.
 *
 * Particle i of the engine is index i of the arrays of rs_wall_block and rs_wall_rows; its
 * history lives in the wall at the same index (grown with rs_wall_grow, moved with
 * rs_wall_copy). Vectors are 3 doubles per particle (x[3 i + d]), as LIGGGHTS and LAMMPS
 * keep them. */
#ifndef RIGIDSURF_WALL_H
#define RIGIDSURF_WALL_H

#include "rigidsurf/contact_block.h"
#include "rigidsurf/convex.h"
#include "rigidsurf/law.h"
#include "rigidsurf/motion.h"
#include "rigidsurf/surface.h"
#include "rigidsurf/track.h"
#include "rigidsurf/types.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rs_wall rs_wall;

/// Reductions over the ranks (rs_wall_host.reduce).
enum { RS_REDUCE_SUM = 0, RS_REDUCE_MIN = 1, RS_REDUCE_MAX = 2 };

/// What rs_wall_host.variable_find says of a name.
enum { RS_VAR_MISSING = -1, RS_VAR_NOT_EQUAL = -2 };

/// Why rs_wall_host.variable_eval is called: a motion rate (before the step) or the
/// servo's target (after it).
enum { RS_VAR_MOTION = 0, RS_VAR_SERVO = 1 };

/// What only the engine knows. Every pointer may be NULL where the engine has nothing
/// of the kind: one rank, no variables, no material properties, no warnings or lines of
/// information, no law of its own.
typedef struct rs_wall_host {
    void *ctx;  ///< passed to every callback
    int rank;   ///< this process (0: writes files, prints warnings)
    int ntypes; ///< particle material types 1 .. ntypes (keyword type); 0: any
    /// v[0 .. n) replaced by its sum, smallest or largest value over the ranks
    /// (RS_REDUCE_*). Collective. NULL: one rank.
    void (*reduce)(void *ctx, double *v, int n, int op);
    /// The index of the equal-style variable name (>= 0), RS_VAR_MISSING or
    /// RS_VAR_NOT_EQUAL.
    int (*variable_find)(void *ctx, const char *name);
    /// The current value of variable index; why: RS_VAR_MOTION or RS_VAR_SERVO.
    double (*variable_eval)(void *ctx, int index, int why);
    /// Material property `name` of types i and j (1-based): per type (j = 0), per pair
    /// (i, j > 0), or a global scalar (i = j = 0). who names the asker for the engine's
    /// message. RS_OK with *value; when the engine has no such property: an error in err
    /// when required, else RS_ERR_NOTFOUND (err untouched).
    int (*material)(void *ctx, const char *name, int i, int j, int required,
                    const char *who, double *value, rs_error *err);
    /// A warning, on rank 0 (the wall calls it there only).
    void (*warning)(void *ctx, const char *msg);
    /// A line of information that asks nothing of the user, on rank 0 (the wall calls it
    /// there only); the engine prints it as `INFO: msg`.
    void (*info)(void *ctx, const char *msg);
    /// The engine's own contact models as a law (`law NAME words ...` with NAME =
    /// engine_law_name): the words up to the next keyword of the wall. The descriptor stays
    /// the engine's (it outlives the wall).
    int (*engine_law)(void *ctx, const char *const *words, int nwords, const rs_law **law,
                      rs_error *err);
    const char *engine_law_name; ///< the name of the engine's law ("liggghts"), or NULL
} rs_wall_host;

/// What a run of the engine is (rs_wall_init).
typedef struct rs_wall_run {
    double dt;   ///< time step
    double skin; ///< the engine's neighbour skin: the candidates' reach beyond the
                 ///< tracking thickness, the refresh when the wall moved half of it, the
                 ///< default tracking thickness of a law without a reach of its own
    /// 1: the engine rebuilds its neighbour lists as soon as a particle has moved half a
    /// skin (LIGGGHTS: neigh_modify delay 0 every 1 check yes), so a wall that stays in
    /// place refreshes the candidates' lists with half a skin of margin
    int half_skin;
    double box_lo[3], box_hi[3]; ///< the domain: its diagonal sizes the analytic kinds'
                                 ///< display meshes, its corners bound the wall's sweep
    /// The most doubles one particle's record may take (rs_wall_pack; LIGGGHTS's atom
    /// exchange: 600), 0 for no limit (RS_TRACK_MAX_CAPACITY slots still).
    int exchange_max;
    /// 1: every particle of the group is a candidate at every step, in one block, and
    /// its contacts at any depth (a standalone driver); 0: the candidates are those within
    /// the tracking thickness and a skin, refreshed on rs_wall_reneighbor, in blocks of
    /// RS_BLOCK.
    int every_particle;
    /// The engine keeps per-particle temperatures (rs_wall_block.temp) and heat flows
    /// (rs_wall_rows.heatflux), as LIGGGHTS under fix heat/gran.
    int has_temp, has_heatflux;
} rs_wall_run;

/// The engine's particles at one call. Arrays are indexed by the engine's particle
/// index i; vectors hold 3 doubles per particle.
typedef struct rs_wall_block {
    int n;                     ///< particles: indices 0 .. n-1 (the engine's local ones)
    const double *x;           ///< positions (3, n)
    const double *v;           ///< velocities (3, n)
    const double *omega;       ///< angular velocities (3, n); NULL: zero
    const double *radius;      ///< radii (n); a body's characteristic length
    const double *mass;        ///< masses (n)
    const int *type;           ///< material types 1 .. ntypes (n); NULL: 1
    const int *id;             ///< ids, for messages and the law's jSlvUid (n); NULL: i + 1
    const int *mask;           ///< group bits (n); the wall acts on mask[i] & groupbit
    int groupbit;              ///< (mask NULL: every particle)
    const double *temp;        ///< temperatures at the end of the increment (n), or NULL
    const double *heatcap;     ///< heat capacities (n); NULL: m times the type's
                               ///< thermalCapacity where the engine has it
    const double *area;        ///< contact areas areaSlv (n); NULL: the wall's `area`
    const double *const *pred; ///< the `predef` fields, one array (n) per name; or NULL
    const rs_body *body; ///< per particle its convex body (n; shape NULL: a sphere), or
                         ///< NULL for spheres only; bodies need a run that asks every
                         ///< particle (rs_wall_run.every_particle)
    long long step;      ///< the engine's step number (VTK names, messages)
    int inc;             ///< this call's increment within the run, from 1 (kInc)
    double time;         ///< the time at the start of this call's increment (at a
                         ///< setup call: now)
    int still;           ///< nonzero: no motion lies behind this call (the tracker
                         ///< takes dt 0; the history advances): a run's first call
                         ///< without rs_wall_setup
} rs_wall_block;

/// Where the loads go, per engine particle (NULL: not wanted).
typedef struct rs_wall_rows {
    double *f;        ///< force (3, n): += F
    double *torque;   ///< torque (3, n): += (x_cp - x) x F
    double *fstore;   ///< stored force (3, n): += F (keyword store_force), or NULL
    double *heatflux; ///< heat flow into the particle (n): += w A fluxSlv, and LIGGGHTS's
                      ///< wall conduction; or NULL
    double *peratom;  ///< (6, n): rdisp(1:3) and stress(1:3) of the particle's deepest
                      ///< contact, zeros for none (keyword peratom); or NULL
} rs_wall_rows;

/// The wall's global vector (rs_wall_vector), 1-based as the fix's f_ID[i]: 1-3 force on
/// the wall, 4-6 moment on the wall about the surface origin, 7 touching contacts, 8
/// ALLSE, 9 ALLFD, 10 ALLPD, 11 ALLVD, 12 ALLCD, 13 wall temperature, 14 heat into the
/// wall, 15-17 the wall's translation since the start, 18 its rotation angle.
#define RS_WALL_NVEC 18

/// What the engine reads of a wall after rs_wall_create.
typedef struct rs_wall_info {
    int wall_type;              ///< material type of the wall (keyword type)
    int moving;                 ///< the wall moves: rs_wall_advance before each step
    int servo;                  ///< rs_wall_servo after each step
    int peratom;                ///< keyword peratom yes: rows.peratom is written
    int store_force;            ///< keyword store_force: rows.fstore is written
    const char *store_force_id; ///< its vector's ID ("force_" + the fix ID or W)
    int npred;                  ///< the predef names
    const char *const *pred;    ///< npred names of per-particle fields
    int vtk_every;              ///< keyword vtk: its interval (0: none)
    int temperature;            ///< keyword temperature was given
    int conduction;             ///< keyword conduction liggghts
    const rs_law *law;          ///< the law
    int fused;                  ///< keyword fused: 1 (default) the fused kernel where it
                                ///< applies, 0 the staged calls everywhere
} rs_wall_info;

/* ---- Making and ending a wall ---------------------------------------------------- */

/// A wall from the words of `fix ID group wall/rigid WORDS...` (docs/fix_wall_rigid.md):
/// id names the interaction (surfInt, an inline surface) and group the slaves (surfSlv).
/// Errors name the keyword and what it expects, as the fix's. *out is NULL on error.
int rs_wall_create(const char *id, const char *group, const char *const *words, int nwords,
                   const rs_wall_host *host, rs_wall **out, rs_error *err);

/// A wall from what a program holds: the surface and law (not owned; they outlive the
/// wall), the law's properties and state variables, the history's capacity, the
/// tracking thickness (< 0: the law's reach, else the run's skin), how a contact's area
/// follows (RS_AREA_*, with area_const), the wall's material type and temperature (with
/// its heat capacity; 0 keeps it fixed), and the names the law sees.
typedef struct rs_wall_def {
    const rs_surface *surface;
    const rs_law *law;
    const double *props;
    int nprops;
    int nstatev;
    int capacity;    ///< history slots a particle starts with (0: 4)
    double tracking; ///< tracking thickness (< 0: the law's reach, else the skin)
    rs_area_mode area_mode;
    double area_const;
    int wall_type; ///< the law's wall_type (0: no material type)
    double temperature;
    double heat_capacity;
    const char *interaction, *slave, *master; ///< surfInt, surfSlv, surfMst (NULL: the
                                              ///< defaults VUINTER, SLAVE, the surface's)
    /// The wall's motion, which the engine advances itself (not owned), or NULL: the
    /// wall's own (fixed unless rs_wall_motion(w) is set up and rs_wall_advance called).
    rs_motion *motion;
    int moving; ///< the tracker sees the motion (a moving or belt-carrying wall)
    /// Per-contact warnings of user routines (law.h, rs_law_block.warn); NULL: gathered
    /// into one warning per run.
    void (*warn)(void *warn_ctx, const rs_law *law, int k, const char *msg);
    void *warn_ctx;
} rs_wall_def;

/// A wall from a definition (rs_wall_def). *out is NULL on error.
int rs_wall_make(const rs_wall_def *def, const rs_wall_host *host, rs_wall **out,
                 rs_error *err);

/// Frees the wall and everything it owns (the surface and law it made).
void rs_wall_free(rs_wall *w);

/// What the engine reads of the wall (valid while it lives).
const rs_wall_info *rs_wall_get_info(const rs_wall *w);

/* ---- A run ------------------------------------------------------------------------ */

/// Before a run (the engine's init): the run's settings, the material properties, the
/// variables, the display mesh and the VTK folder, the servo's constants from the
/// particles in b (their smallest radius), the tracking thickness. Collective.
int rs_wall_init(rs_wall *w, const rs_wall_run *run, const rs_wall_block *b, rs_error *err);

/// The forces before the first step of a run, without advancing any history (an Abaqus
/// step starts here: its step time restarts; the law sees increment 1 with setup set):
/// the loads onto rows and the wall's sums into *out (this rank's). Warns once when the
/// time step exceeds RS_STEP_FRACTION of the law's critical step. Collective.
int rs_wall_setup(rs_wall *w, const rs_wall_block *b, const rs_wall_rows *rows,
                  rs_wall_load *out, rs_error *err);

/// The wall's motion over the next step (before the step's forces): its rates (their
/// variables evaluated), its pose.
int rs_wall_advance(rs_wall *w, double dt, rs_error *err);

/// One step: the contacts of the group's particles near the wall, their history, the
/// law and the loads added onto rows; the wall's sums of this rank into *out; on the
/// steps of keyword vtk, the surface's VTK file. On error nothing of the engine's rows
/// nor of the history has changed. Collective (candidate refreshes, heat, VTK).
int rs_wall_step(rs_wall *w, const rs_wall_block *b, const rs_wall_rows *rows, double dt,
                 rs_wall_load *out, rs_error *err);

/// After the step's forces (keyword servo): the controller reads the wall's force or
/// torque along its axis and sets the wall's rate for the next step. Collective.
int rs_wall_servo(rs_wall *w, double dt, rs_error *err);

/// The engine rebuilt its neighbour lists (particle indices may have changed): the
/// candidates are found again at the next call.
void rs_wall_reneighbor(rs_wall *w);

/// After a run: one warning with what the law's user routines asked that an explicit
/// step cannot grant (PNEWDT < 1, the stiffness they returned). Collective.
void rs_wall_end_run(rs_wall *w);

/// The global vector (RS_WALL_NVEC values, see there), summed over the ranks.
/// Collective.
void rs_wall_vector(rs_wall *w, double v[RS_WALL_NVEC]);

/// The wall's motion: its pose, rates and velocity field.
rs_motion *rs_wall_motion(rs_wall *w);

/// The contacts of the last block a call handled (the tracker's output and the law's
/// block; shallow copies, valid until the next call).
void rs_wall_last(const rs_wall *w, rs_track_out *trk, rs_contact_block *cb);

/// Sets the wall's temperature and its increment over the last step (a program that
/// integrates the wall's heat itself).
void rs_wall_set_temperature(rs_wall *w, double temperature, double dtemperature);

/* ---- An engine's own contact models as a force law -------------------------------- */

/// One live contact of a force law's block (RS_LAW_SETS_FORCE) as the engines' walls
/// describe a sphere's contact to their contact models.
typedef struct rs_force_contact {
    int row;        ///< the engine's index of the particle
    double overlap; ///< rdisp(1): > 0 touching, < 0 apart
    double radius;  ///< the particle's radius R
    double mass;    ///< its mass
    double reff;    ///< the effective radius from R and the wall's curvatures
    double curv[2]; ///< the wall's principal curvatures (> 0 convex toward the particle)
    double n[3];    ///< unit normal from the wall toward the particle's centre
    double t1[3];   ///< the contact's t1, and t2 (a SEGMENTS wall: t2 = -z)
    double t2[3];
    double xm[3];    ///< the master point (a SEGMENTS wall: at the particle's z)
    double vwall[3]; ///< the velocity of the wall's material at xm (motion and belt)
    double *history; ///< the contact's state variables (the model's history), or NULL
    int type;        ///< the particle's material type
    int wall_type;   ///< the wall's
    int setup;       ///< a setup call: the history is not advanced
} rs_force_contact;

/// A run of live contacts of a force law (RS_LAW_SETS_FORCE), one a particle, as columns
/// of n entries (entry j of each column is contact j), for the law's operation on a whole
/// run (rs_law.force_run): what rs_force_contact holds of one contact, less what a model
/// finds from the rest. The effective radius of contact j is rs_effective_radius(radius,
/// curv[0], curv[1]) (contact_block.h), as rs_force_contact.reff. The law writes its force
/// and torque of every contact into F and T, which the wall gives zeroed (the engines'
/// models add theirs onto them, as onto a particle's rows), writes acts and updates the
/// history.
typedef struct rs_force_run {
    int n;                 ///< contacts in the run, at most RS_BLOCK
    const int *row;        ///< the engine's index of each particle
    const double *overlap; ///< rdisp(1)
    const double *radius;  ///< the particle's radius R
    const double *mass;    ///< its mass
    const double *curv[2]; ///< the wall's principal curvatures
    const double *nrm[3];  ///< unit normal from the wall toward the particle's centre
    const double *t1[3];   ///< the contact's t1 and t2
    const double *t2[3];
    const double *xm[3]; ///< the master point
    /// The distance of the particle's centre x from xm along n, (x - xm).n (x - xm
    /// summed component by component), as the engines' walls measure it (R - overlap
    /// rounds otherwise)
    const double *rn;
    /// The velocity of the wall's material at xm, per contact; NULL (vwall[0]) where the
    /// wall's velocity is vwall0 at every contact (a wall that does not move: zeros).
    const double *vwall[3];
    double vwall0[3];
    double *history; ///< the state variables, contact j's at history + j nstatev
    int nstatev;     ///< state variables per contact (history NULL when 0)
    const int *type; ///< the engine's particle types, by row (NULL: all type 1)
    int wall_type;   ///< the wall's material type
    int setup;       ///< a setup call: the history is not advanced
    /* out */
    double *F; ///< the model's force on the particle, contact j's at F + 3 j
    double *T; ///< its torque about the particle's centre, at T + 3 j
    int *acts; ///< 1 where the model acts; 0 where not (F, T left at 0)
} rs_force_run;

/// The outputs of a force law's block b zeroed (stress, force, torque, heat, energies):
/// what a contact the law skips, or one leaving, gives. First in the law's call.
void rs_wall_force_begin(rs_law_block *b);

/// Contact e of a force law's block b: for a live contact, describes it in *c and returns
/// 1; a contact leaving the tracking thickness returns 0 (it applies nothing). x: the
/// engine's positions (3, n).
int rs_wall_force_contact(const rs_wall *w, const rs_law_block *b, int e, const double *x,
                          rs_force_contact *c);

/// The model's force F on the particle and its torque T about the particle's centre for
/// contact e of c: the law's force and torque, and its stress F in the contact's frame.
void rs_wall_force_result(rs_law_block *b, int e, const rs_force_contact *c,
                          const double F[3], const double T[3]);

/* ---- Per-particle history: migration and restart ---------------------------------- */

/// Storage for particles 0 .. nmax-1 (the engine's nmax); what they hold is kept.
int rs_wall_grow(rs_wall *w, int nmax, rs_error *err);
/// Particle j takes particle i's history.
void rs_wall_copy(rs_wall *w, int i, int j);
/// Particle i has no history (a new particle).
void rs_wall_clear(rs_wall *w, int i);
/// Doubles rs_wall_pack writes: the capacity, then the particle's history.
int rs_wall_pack_size(const rs_wall *w);
/// Particle i's history into buf (rs_wall_pack_size doubles); returns their count.
int rs_wall_pack(const rs_wall *w, int i, double *buf);
/// Particle i's history from a record of rs_wall_pack (of any rank: the slots grow to its
/// capacity); returns the doubles read, or -1 with err.
int rs_wall_unpack(rs_wall *w, int i, const double *buf, rs_error *err);
/// Particle i's history from a restart file's record of n doubles (rs_wall_pack's,
/// written by this or an earlier layout version, which rs_wall_read_restart told).
int rs_wall_unpack_restart(rs_wall *w, int i, const double *rec, int n, rs_error *err);
/// Bytes of the per-particle storage.
double rs_wall_memory(const rs_wall *w);

/// Doubles of the global restart record.
int rs_wall_restart_size(rs_wall *w);
/// The global restart record (motion, heat, energy totals, wear, servo;
/// rs_wall_restart_size doubles). Collective: the totals are summed over the ranks.
void rs_wall_write_restart(rs_wall *w, double *buf);
/// The global record read back; the totals go to rank 0.
int rs_wall_read_restart(rs_wall *w, const double *buf, int n, rs_error *err);

#ifdef __cplusplus
}
#endif
#endif
