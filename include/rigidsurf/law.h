/* rigidsurf: interface laws (Abaqus VUINTER calling convention).
 *
 * A law is a descriptor (rs_law) with one vectorized function over a block of at most
 * RS_BLOCK contacts (rs_law_block). The block carries every VUINTER argument with its
 * Abaqus meaning, stored in Fortran (column-major) layout so a Fortran shim passes the
 * pointers on without copies (docs/conventions.md, "Memory layout"). Index with the
 * accessors of types.h: RS_A2(b->stress, b->nDir, i, k), RS_DROT(b->drot, i, j, k).
 *
 * Conventions (docs/conventions.md, "rdisp, drdisp, drot" and "Stress, flux, energy
 * signs"):
 * - rdisp(1) > 0 is overlap (penetration), < 0 a gap. rdisp(2:3) is the accumulated
 *   slip in (t1, t2); drdisp the increment. rdisp = drdisp = drot = RS_MAXVAL (1e30) on
 *   the one call after a contact leaves the tracking thickness: a law must then return
 *   zero stress and flux.
 * - On entry stress holds the values of the previous increment, with stress(2:3) and
 *   rdisp(2:3) already rotated by drot. Vector-valued state variables are the law's to
 *   rotate (s <- drot s).
 * - stress(1) > 0 is pressure on the master; stress(2:3) > 0 a traction on the master
 *   along +t1 / +t2. The force on the particle is F = areaSlv (s1 n - s2 t1 - s3 t2).
 * - fluxSlv, fluxMst > 0 is heat (per area and time) into that surface.
 * - sed is the elastic strain energy density (a total); sfd, scd, spd, svd are
 *   increments of frictional, creep, plastic and viscous dissipation density.
 *
 * Laws written for VUINTER ignore the DEM extension (radius ... setup). */
#ifndef RIGIDSURF_LAW_H
#define RIGIDSURF_LAW_H

#include "rigidsurf/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Length of the VUINTER surface-name strings (CHARACTER*80, blank-padded).
#define RS_LAW_NAMELEN 80

struct rs_law;

/// What user routines asked of the step that an explicit engine cannot grant, gathered
/// over the calls of a law (rs_law_block.requests). Clear with rs_law_requests_clear.
typedef struct rs_law_requests {
    long pnewdt_calls;   ///< calls that returned PNEWDT < 1
    double pnewdt_min;   ///< the smallest PNEWDT returned (1 when none was below 1)
    int pnewdt_particle; ///< particle id (jSlvUid) of the call with the smallest PNEWDT
    int pnewdt_feature;  ///< its feature id (jConMstid)
    /// The smallest critical step 2 sqrt(m / (k A)) of the stiffness k a routine returned
    /// (UINTER DDSDDR, FRIC DDTDDG, largest row sum) for a particle of mass m and contact
    /// area A; INFINITY when no routine returned a positive stiffness.
    double step_min;
    const char *step_what; ///< "DDSDDR" or "DDTDDG": the array that gave step_min
} rs_law_requests;

/// Empties r: no calls, pnewdt_min = 1, step_min = INFINITY.
void rs_law_requests_clear(rs_law_requests *r);

/// Adds the requests of src to dst (the smallest values, the sums of the counts).
void rs_law_requests_merge(rs_law_requests *dst, const rs_law_requests *src);

/// Arguments of one law call. Arrays are Fortran layout; n means nSlvNod.
/// Fortran INTEGER is int (gfortran integer*4), REAL*8 is double.
typedef struct rs_law_block {
    /* VUINTER integers. */
    int kStep;     ///< step number (Abaqus: from 1)
    int kInc;      ///< increment number
    int nFacNod;   ///< master nodes per facet (1 here: jConMstid holds the feature id;
                   ///< a VUINTER on an analytic master sees 0, see analytic_master)
    int nSlvNod;   ///< contacts in this block, 0 <= n <= RS_BLOCK
    int nMstNod;   ///< entries of jMstUid
    int nSurfDir;  ///< tangent directions: nDir - 1
    int nDir;      ///< 2 (SEGMENTS) or 3
    int nStateVar; ///< state variables per contact
    int nProps;    ///< entries of props
    int nTemp;     ///< 1 if temperatures are passed, else 0
    int nPred;     ///< predefined field variables per node (the engine's fields, 0 without)
    int numDefTfv; ///< master nodes with temperature / field values (1: the wall)

    const int *jSlvUid;   ///< (n) particle id of each contact
    const int *jMstUid;   ///< (nMstNod) master ids (the surface index)
    const int *jConMstid; ///< (nFacNod, n) feature id (RS_FEATURE) of each contact

    double timStep; ///< step time at the start of the increment
    double timGlb;  ///< total time at the start of the increment
    double dTimCur; ///< time increment

    char surfInt[RS_LAW_NAMELEN]; ///< interaction name, blank-padded, no NUL
    char surfSlv[RS_LAW_NAMELEN]; ///< slave (particle group) name, blank-padded
    char surfMst[RS_LAW_NAMELEN]; ///< master (wall) name, blank-padded

    /* Read only. */
    const double *rdisp;      ///< (nDir, n) penetration and accumulated slip
    const double *drdisp;     ///< (nDir, n) their increments
    const double *drot;       ///< (2, 2, n) tangent-basis rotation increment
    const double *stiffDflt;  ///< (n) default penalty stiffness, rs_law_default_stiffness
    const double *condDflt;   ///< (n) default conductance, rs_law_default_conductance
    const double *shape;      ///< (nFacNod, n) master shape functions (1)
    const double *coordSlv;   ///< (nDir, n) contact point on the particle
    const double *coordMst;   ///< (nDir, n) closest master point (NULL for a law that
                              ///< skips it, RS_LAW_SKIPS_COORDMST)
    const double *alocaldir;  ///< (nDir, nDir, n) columns n, t1[, t2] (global)
    const double *props;      ///< (nProps) law properties
    const double *areaSlv;    ///< (n) area per contact (1: stress is force)
    const double *tempSlv;    ///< (n) particle temperature at the end of the increment
    const double *dtempSlv;   ///< (n) its increment
    const double *preDefSlv;  ///< (nPred, n) particle field variables
    const double *dpreDefSlv; ///< (nPred, n) their increments
    const double *tempMst;    ///< (numDefTfv) wall temperature: one (numDefTfv = 1)
                              ///< or one per contact (numDefTfv = n)
    const double *dtempMst;   ///< (numDefTfv) its increment
    const double *preDefMst;  ///< (nPred, numDefTfv) wall field variables
    const double *dpreDefMst; ///< (nPred, numDefTfv) their increments

    /* Read / write. */
    double *stress;  ///< (nDir, n) interface stress: previous on entry, new on exit
    double *fluxSlv; ///< (n) heat flux into the particle per area
    double *fluxMst; ///< (n) heat flux into the wall per area
    double *sed;     ///< (n) elastic strain energy per area
    double *statev;  ///< (nStateVar, n) law state

    /* Write only (increments per area). */
    double *sfd; ///< (n) frictional dissipation
    double *scd; ///< (n) creep dissipation
    double *spd; ///< (n) plastic dissipation
    double *svd; ///< (n) viscous (damping) dissipation

    /* DEM extension (not VUINTER; NULL where the engine has nothing to give). */
    const double *radius; ///< (n) particle radius R
    const double *mass;   ///< (n) the contact's mass: the particle's; a convex body's
                          ///< contact point's effective mass (docs/conventions.md)
    const double *reff;   ///< (n) effective radius from R and curv (R on a plane)
    const double *vrel;   ///< (nDir, n) velocity of the particle's contact point minus
                          ///< the wall's, in (n, t1[, t2]); vrel(1) > 0 separates
    const double *curv;   ///< (2, n) principal wall curvatures, > 0 convex toward the
                          ///< particle, 0 for a plane
    const int *slv_type;  ///< (n) particle material type (NULL: one material)
    const int *slvRow;    ///< (n) the engine's index of each contact's particle (NULL where
                          ///< the engine gives none)
    /// (3, n) a force law's force on the particle and (3, n) its torque about the
    /// particle's centre (RS_LAW_SETS_FORCE; NULL for other laws)
    double *force, *torque;
    int wall_type;       ///< wall material type
    int setup;           ///< nonzero on a setup call (LIGGGHTS setup, before step 1):
                         ///< compute forces but do not advance history (statev)
    int analytic_master; ///< nonzero: the master is an analytic surface (SEGMENTS,
                         ///< CYLINDER, REVOLUTION), which has no nodes: a Fortran
                         ///< VUINTER then sees nFacNod = nMstNod = 0

    /* A faceted master's facets under the contacts, VUINTER's facet arguments
     * (fac_nFacNod = 0: none; the engines fill them for laws that take them,
     * rs_law_takes_facets). */
    int fac_nFacNod;            ///< nodes per facet: 3, or 4 when the master has quads (a
                                ///< triangle then repeats its first node, with shape 0)
    int fac_nMstNod;            ///< the block's distinct facet nodes
    const int *fac_jConMstid;   ///< (fac_nFacNod, n) 1-based positions in fac_jMstUid
    const double *fac_shape;    ///< (fac_nFacNod, n) shape functions at the closest point
    const int *fac_jMstUid;     ///< (fac_nMstNod) the nodes' user numbers
    const double *fac_coordMst; ///< (nDir, fac_nMstNod) their coordinates, current pose

    /// Requests of user routines (PNEWDT < 1, the stiffness they return) are added here
    /// when it is set; the adapters then send no per-contact warning for them.
    rs_law_requests *requests;

    /* Warning channel (rs_law_block_init leaves it NULL: warnings are dropped). */
    /// Called by adapters for a condition an explicit step cannot honour (a UINTER or
    /// FRIC asking for a smaller increment with PNEWDT < 1, a returned stiffness above
    /// the stable limit for dt) when requests is NULL. k is the contact in the block; msg
    /// names the particle id and feature id. The law call itself still succeeds.
    void (*warn)(void *warn_ctx, const struct rs_law *law, int k, const char *msg);
    void *warn_ctx; ///< passed to warn
} rs_law_block;

typedef struct rs_law rs_law;
/// A contact as a force law's model sees it, and a run of them (wall.h).
struct rs_force_contact;
struct rs_force_run;

/// The reach of a law that acts only on touching contacts: 0.
double rs_law_reach_touching(const rs_law *law, const double *props, int nprops);

/// Rayleigh time of a sphere of radius R, mass m, Young's modulus Y and Poisson ratio
/// nu: pi R sqrt(rho / G) / (0.1631 nu + 0.8766), rho = 3 m / (4 pi R^3),
/// G = Y / (2 (1 + nu)). 0 when an argument is out of range.
double rs_rayleigh_time(double radius, double mass, double young, double poisson);

/// Validates props (count, sign, range). Optional (NULL: any finite values).
typedef int (*rs_law_init_fn)(const rs_law *law, const double *props, int nprops,
                              rs_error *err);

/// The critical time step of one contact under props, for a particle of radius R, mass
/// m and contact area A: Hertz's Rayleigh time for hertz, 2 sqrt(m / K) for a linear
/// normal stiffness K (force per length: kn, or a stiffness per area times A). Engines
/// warn when their step exceeds RS_STEP_FRACTION of it. Optional (NULL or a result <= 0:
/// no check).
typedef double (*rs_law_critical_step_fn)(const rs_law *law, const double *props,
                                          int nprops, double radius, double mass,
                                          double area);

/// The largest gap (-rdisp(1)) at which a law can give a force or change its state under
/// props: 0 for a law that acts only on touching contacts. Engines take it as the
/// default tracking thickness. Optional: NULL (or a negative result) for a law that may
/// act across a gap of its own, which then keeps the engine's default.
typedef double (*rs_law_reach_fn)(const rs_law *law, const double *props, int nprops);

/// The fraction of a law's critical step (rs_law_critical_step_fn) above which the
/// engines warn.
#define RS_STEP_FRACTION 0.2

/// One vectorized call over the block: reads the read-only arrays, updates stress,
/// fluxes, sed, statev and writes sfd, scd, spd, svd for every contact. Returns RS_OK
/// or fills err. A user C law loaded with rs_law_load_c has exactly this signature.
typedef int (*rs_law_update_fn)(const rs_law *law, rs_law_block *b, rs_error *err);

/// A law descriptor. Built-ins are static and const (rs_law_find); loaded laws are
/// filled by the rs_law_load_* functions and released with rs_law_unload.
struct rs_law {
    const char *name;              ///< registry name (case-insensitive)
    int nprops;                    ///< property count; -1 = any count (user laws)
    int nstatev;                   ///< state variables per contact (user laws: caller)
    const char *const *prop_names; ///< nprops names, in order (NULL for user laws)
    rs_law_init_fn init;           ///< optional property check
    rs_law_update_fn update;       ///< the block call (required)
    void *ctx;                     ///< loader data (library handle, wrapped routines)
    void (*destroy)(rs_law *law);  ///< optional: releases ctx
    rs_law_critical_step_fn critical_step; ///< optional: the time-step check
    rs_law_reach_fn reach;                 ///< optional: the default tracking thickness
    unsigned skips; ///< RS_LAW_SKIPS_ flags: inputs the law never reads (0: it reads all)
    unsigned sets;  ///< RS_LAW_SETS_ flags: what the law writes of every contact's
                    ///< outputs (0: nothing is promised)
    /// A built-in law's fused kernel: the tracker, the law and the loads of a block of
    /// particles that each hold one contact, in one pass, with the numbers of the staged
    /// calls (internal to the library; NULL for every other law).
    const struct rs_law_fused *fused;
    /// A force law's (RS_LAW_SETS_FORCE) model on one contact, optional: c describes the
    /// contact as rs_wall_force_contact does (wall.h; its history is the contact's state
    /// variables, which the model updates); where the model acts it writes its force F on
    /// the particle and torque T about the particle's centre and returns 1, elsewhere it
    /// returns 0 (the contact gives zeros, as a contact the block call skips); a model
    /// that cannot go on fills err and returns its negated code (-RS_ERR_...). With it the
    /// wall takes runs of particles that each hold one contact on its line path, without
    /// the block call (src/wall/wall_force_line.c): the update function must then give,
    /// contact by contact, what this gives.
    int (*force_one)(const rs_law *law, struct rs_force_contact *c, double F[3],
                     double T[3], rs_error *err);
    /// The same model on a run of such contacts in columns (rs_force_run, wall.h; the
    /// forces and torques out as rows of 3), optional: for each contact j what force_one
    /// gives (its F and T onto the run's zeros, acts[j]; zeros and 0 where the model acts
    /// not), bit for bit, in one call; the
    /// model chosen once for the run, not per contact. RS_OK, or a model that cannot
    /// go on fills err and returns its code. The wall's line path takes it where the law
    /// has it (a force_one is then not needed there).
    int (*force_run)(const rs_law *law, const struct rs_force_run *r, rs_error *err);
};

/* What a law declares it does not read on entry, so that the contact's history need not
 * keep it (the tracker's slot layout follows, rs_law_drops): the stress of the last call
 * (the law computes its stress from its own state variables), and the sed, fluxSlv and
 * fluxMst of the last call. A law that skips one gets zeros there. A law that skips
 * coordMst gets NULL there, and the tracker does not compute it. A law that skips both
 * the accumulated slip rdisp(2:nDir) and drdisp(1) (it reads rdisp(1), drdisp(2:nDir)
 * and drot, as DEM's incremental tangential models do) gets the slip increment there and
 * -v_rel.n dt (RS_DROP_SLIP), and its slots keep neither the slip nor rdisp(1); one that
 * skips only one of them is handed both as usual. Loaded laws read everything. */
#define RS_LAW_SKIPS_STRESS 1u
#define RS_LAW_SKIPS_ENERGY 2u
#define RS_LAW_SKIPS_COORDMST 4u
#define RS_LAW_SKIPS_SLIP 8u
#define RS_LAW_SKIPS_DRDISP1 16u
/* A law that reads neither drot nor the frame of a contact's call after it leaves (the
 * inputs that come from the frame its slot keeps of the last call), because it keeps any
 * tangential state of its own in space and turns it itself, as LAMMPS's wall models do,
 * declares RS_LAW_SKIPS_DROT. Its slot keeps the frame all the same (the layout does not
 * change), but the wall's line path for force laws (src/wall/wall_force_line.c) does not
 * store the frame there each step: the slot's frame is that of the contact's last call
 * through the block call, and the drot and leaving frame made from it are of no use to
 * the law. Every other law gets its slot's frame stored on every call. */
#define RS_LAW_SKIPS_DROT 32u

/* What a law declares it writes for every contact of a call (rs_law.sets):
 * - RS_LAW_SETS_ENERGIES: sfd, scd, spd and svd, so rs_law_call does not zero them
 *   first (a law without it may set only the energies it has);
 * - RS_LAW_SETS_NO_HEAT: fluxSlv = fluxMst = 0, and RS_LAW_SETS_NO_CREEP_PLASTIC: scd =
 *   spd = 0 (the law writes the zeros), so the engine's sums leave them out
 *   (rs_cblock_add_loads);
 * - RS_LAW_SETS_STRESS: stress(1:nDir), so that a law that also skips the stress on
 *   entry (RS_LAW_SKIPS_STRESS) gets the array as it is, not zeroed (rs_law_stress_in).
 * Loaded laws promise nothing. */
#define RS_LAW_SETS_ENERGIES 1u
#define RS_LAW_SETS_NO_HEAT 2u
#define RS_LAW_SETS_NO_CREEP_PLASTIC 4u
#define RS_LAW_SETS_STRESS 8u
/* A force law (RS_LAW_SETS_FORCE) is a DEM contact model that gives each contact's force
 * on the particle and torque about its centre itself (rs_law_block.force, .torque; an
 * engine's own models, whose torque may hold more than the force's lever, a rolling
 * resistance): the engine applies those, times the contact's area and share, and the wall
 * takes -F and the moment -((x - o) x F + T) about its origin o, so that the pair's angular
 * momentum is kept. Its stress is F in the contact's frame, F = s1 n - s2 t1 - s3 t2, for
 * the outputs. */
#define RS_LAW_SETS_FORCE 16u

/// The tracker's RS_DROP_ flags for law (track.h): what its contacts' slots need not keep.
unsigned rs_law_drops(const rs_law *law);

/// Whether an engine fills the law's stress array before a call: the last call's stress
/// or zeros (rs_track_load). 0 for a law that neither reads it on entry nor leaves any of
/// it unwritten (RS_LAW_SKIPS_STRESS and RS_LAW_SETS_STRESS); 1 otherwise, and for NULL.
int rs_law_stress_in(const rs_law *law);

/* Registry of built-in laws (props in order; statev count; src/laws/ documents each):
 *   bonded_interface  gap_cutoff E nu yield_stress hardening thickness conductivity; 3
 *   linear_softening  k; 0
 *   hertz             Y_particle nu_particle Y_wall nu_wall restitution friction
 *                     curvature (0: R, 1: reff); 2. Needs radius, mass, vrel (reff).
 *   hooke             kn kt zeta_n zeta_t mu, or the LIGGGHTS material form Y_particle
 *                     nu_particle Y_wall nu_wall restitution friction
 *                     characteristic_velocity (then also needs radius); 2. Needs mass,
 *                     vrel.
 *   coulomb           mu k_stick kn; 2 (self-contained: p = kn h).
 * hertz and hooke give force (stress times areaSlv); the others stress. */

/// Built-in law by name (case-insensitive), or NULL.
const rs_law *rs_law_find(const char *name);

/// Number of built-in laws.
int rs_law_count(void);

/// Built-in law i (0 <= i < rs_law_count()), or NULL.
const rs_law *rs_law_at(int i);

/* Calling a law. */

/// Checks props against the descriptor: the count (unless law->nprops == -1), that every
/// value is finite, then law->init. Messages name the law and the property by name.
int rs_law_check_props(const rs_law *law, const double *props, int nprops, rs_error *err);

/// Calls law->update on b, then checks stress(1:nDir), fluxSlv and fluxMst of every
/// contact. The first non-finite value gives RS_ERR_NONFINITE naming the law, the
/// particle id (jSlvUid), the feature id (jConMstid) and the output. Also rejects a
/// malformed block (n outside 0..RS_BLOCK, nDir not 2 or 3, missing required arrays)
/// with RS_ERR_ARG before calling the law. sfd, scd, spd and svd are zeroed before the
/// call, so a law writes only the energies it has.
int rs_law_call(const rs_law *law, rs_law_block *b, rs_error *err);

/// Default penalty stiffness (stress per length) for a contact of a particle of mass m
/// and contact area A in an explicit step dt: k = 0.1 * 4 m / (A dt^2). A point mass on
/// a spring of stiffness k A is stable in central differences for dt < 2 sqrt(m / (k A)),
/// i.e. k A < 4 m / dt^2; the default sits ten times under that limit. Returns 0 if an
/// argument is not positive.
double rs_law_default_stiffness(double mass, double area, double dt);

/// Default conductance per area (heat flux per area per kelvin) for a particle of heat
/// capacity C = m c (energy per kelvin) and contact area A in an explicit step dt:
/// h = 0.1 * C / (A dt). Forward-Euler heat exchange with a wall at fixed temperature,
/// dT = -(h A / C) (T - Tw) dt, is monotone for h A dt / C <= 1 and stable below 2; the
/// default sits ten times under the monotone limit. Returns 0 if an argument is not
/// positive.
double rs_law_default_conductance(double heat_capacity, double area, double dt);

/// Zero-fills b and sets the Abaqus defaults: nFacNod = 1, nTemp = 1, numDefTfv = 1,
/// nMstNod = 1, nPred = 0, kStep = 1, kInc = 1, blank surface names, and points the
/// optional read-only arrays (shape, areaSlv, tempSlv, dtempSlv, preDefSlv, dpreDefSlv,
/// tempMst, dtempMst, preDefMst, dpreDefMst, jMstUid) at library constants (ones for shape
/// and areaSlv, zeros for the rest), valid for up to RS_BLOCK contacts. The engine still
/// sets nSlvNod, nDir, nSurfDir, the counts, jSlvUid, jConMstid, rdisp, drdisp, drot,
/// stiffDflt, condDflt, props and every writable array.
void rs_law_block_init(rs_law_block *b);

/// Copies s into an 80-character VUINTER name, blank-padded, no NUL.
void rs_law_block_set_name(char dst[RS_LAW_NAMELEN], const char *s);

/* Loading user laws with dlopen (src/law_load.c). */

/// Loads a C law: symbol is a function with the rs_law_update_fn signature in the
/// shared library lib. out->nprops = -1 and out->nstatev = 0 (the caller sets it).
/// If lib also exports `const rs_law <symbol>_law`, its name, nprops, nstatev,
/// prop_names, init (and update, if set) are taken from it.
/// A missing library gives RS_ERR_IO, a missing symbol RS_ERR_NOTFOUND; both messages
/// name the library and the symbol with the dynamic loader's text.
int rs_law_load_c(const char *lib, const char *symbol, rs_law *out, rs_error *err);

/// Loads a Fortran VUINTER (symbol vuinter_, built against vaba_param.inc) as a law.
/// For these loaders lib may be a Fortran source (rs_law_is_source): it is built
/// (rs_law_build_cached), then its SUBROUTINE statement's argument count is checked
/// against the lists the adapter calls; another count is RS_ERR_ARG naming the file,
/// the line and the counts (docs/abaqus.md, "Argument lists").
int rs_law_load_vuinter(const char *lib, rs_law *out, rs_error *err);

/// 1 when law reads a faceted master's facets (the fac_ fields of its block: a loaded
/// VUINTER), else 0.
int rs_law_takes_facets(const rs_law *law);

/// Loads a Fortran UINTER (point-wise, symbol uinter_) as a block law. normal (may be
/// NULL) supplies the normal response when the routine leaves it to the engine.
/// The argument list is Abaqus's current one (DVISCOUS, DSTRUCTURAL after DDSDDR, FREQR
/// after DTIME); a source with the older list is called with that one. For the UINTER and
/// FRIC adapters props are the normal law's first, then the routine's; out->nstatev counts
/// the normal law's and the adapter's slots, and the caller adds the routine's NSTATV
/// (which sit first in each contact's statev).
int rs_law_load_uinter(const char *lib, const rs_law *normal, rs_law *out, rs_error *err);

/// As rs_law_load_uinter, for a library whose UINTER has the older argument list (no
/// DVISCOUS, DSTRUCTURAL, FREQR); a source is called with the list it has.
int rs_law_load_uinter_v6(const char *lib, const rs_law *normal, rs_law *out,
                          rs_error *err);

/// Loads a Fortran FRIC (symbol fric_, LM = 0/1/2 semantics) as a block law. normal
/// supplies the pressure stress(1) before FRIC computes the shear.
int rs_law_load_fric(const char *lib, const rs_law *normal, rs_law *out, rs_error *err);

/// Releases a loaded law (calls destroy, closes the library) and zeroes it.
void rs_law_unload(rs_law *law);

#ifdef __cplusplus
}
#endif
#endif
