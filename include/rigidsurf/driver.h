/* rigidsurf: a standalone explicit driver.
 *
 * Integrates a set of slave nodes (point masses, spheres with a radius, or rigid convex
 * bodies, rs_driver_set_body) against one
 * rigid master of any kind (analytic or faceted) with the explicit central-difference
 * scheme, and calls an interface law through rs_law_call on the blocks of the tracker,
 * as Abaqus/Explicit does for VUINTER. It reproduces the Abaqus VUINTER verification cases
 * without LIGGGHTS.
 *
 * Increment k (time t_k = k dt) of rs_driver_step:
 *  1. The master moves to t_k (rs_motion_advance; not on the first increment).
 *  2. The contacts of every node, at any depth, through the wall (rs_wall_step, one
 *     block of every node): query and tracker at the positions x_k with the velocities
 *     v_{k-1/2} and angular velocities w_{k-1/2} (without spin, the slip increment of the
 *     tracker is then exactly the displacement x_k - x_{k-1}). Spheres and points are
 *     queried in runs of consecutive nodes (rs_surface_query), a body alone in its pose
 *     q_k (rs_body_query: its manifold's contacts, each at its own witness point). A node
 *     that touches more features than its history slots has them grown.
 *  3. The law, in blocks of at most RS_BLOCK contacts. On entry stress is the previous
 *     increment's, its shear rotated by drot (law.h). Temperatures are those at t_k.
 *  4. Contact force on node i: F = areaSlv (s1 n - s2 t1 - s3 t2) summed over its
 *     contacts, and contact torque (x_cp - x) x F about its centre, x_cp the contact
 *     point (docs/conventions.md, "Stress, flux, energy signs"), by the wall's loads
 *     (rs_cblock_add_loads), which also give the master's force and moment (fwall,
 *     mwall). A contact that left (rdisp = RS_MAXVAL) applies nothing and counts in no
 *     energy total, whatever the law wrote for it. Then the law's results go into the
 *     history.
 *  5. v_{k+1/2} = v_{k-1/2} + dt (F + f_ext) / m for free components; prescribed
 *     components take vpres. x_{k+1} = x_k + dt v_{k+1/2}.
 *     Rotation (rs_rotation_step): the torque kicks the angular momentum, L_{k+1/2} =
 *     L_{k-1/2} + dt (T + t_ext), and the body turns freely over dt from q_k to q_{k+1}
 *     by the NO_SQUISH splitting (Miller et al., J. Chem. Phys. 116, 8649 (2002)): exact
 *     rotations about the body's principal axes in the order 3, 2, 1, 2, 3 (half, half,
 *     whole, half, half), which keep L and |q| to rounding and the energy to O(dt^2)
 *     without drift. An isotropic body (a sphere) turns exactly about w, which then
 *     changes only by the kicks. A node whose moments of inertia are not all > 0 (the
 *     default) keeps the angular velocity it is given (a prescribed spin, zero by
 *     default), and its orientation turns with it.
 *  6. Heat (forward Euler): T_i += dt sum(areaSlv fluxSlv) / C_i for nodes with a heat
 *     capacity C_i > 0; the master's temperature likewise with sum(areaSlv fluxMst) and
 *     its capacity (0: fixed temperature).
 * Energy totals (per the Abaqus output names) are areaSlv-weighted sums over contacts:
 * ALLSE = sum(sed A) at the current increment; ALLFD, ALLPD, ALLVD, ALLCD accumulate
 * sfd, spd, svd, scd times A. ALLKE = sum(m |v_{k+1/2}|^2 / 2) plus, for nodes with
 * inertia, the rotational sum(w_{k+1/2} . L_{k+1/2} / 2). */
#ifndef RIGIDSURF_DRIVER_H
#define RIGIDSURF_DRIVER_H

#include "rigidsurf/contact_block.h"
#include "rigidsurf/convex.h"
#include "rigidsurf/law.h"
#include "rigidsurf/motion.h"
#include "rigidsurf/surface.h"
#include "rigidsurf/track.h"
#include "rigidsurf/types.h"
#include "rigidsurf/wall.h"

#ifdef __cplusplus
extern "C" {
#endif

struct rs_driver;

/// Optional boundary-condition update, called at the start of every increment with the
/// time t_k; it may change vpres, fixed, fext or the master's motion rates. Return 0, or
/// non-zero to stop (fill err).
typedef int (*rs_driver_bc_fn)(struct rs_driver *d, double t, void *ctx, rs_error *err);

/// Energy totals (energy units; the Abaqus whole-model output names).
typedef struct rs_driver_energy {
    double allse;    ///< elastic strain energy in the interface (current)
    double allfd;    ///< frictional dissipation (accumulated)
    double allpd;    ///< plastic dissipation (accumulated)
    double allvd;    ///< viscous dissipation (accumulated)
    double allcd;    ///< creep dissipation (accumulated)
    double allke;    ///< kinetic energy of the slave nodes
    double heat_slv; ///< heat into the slave nodes, sum(areaSlv fluxSlv dt) (accumulated)
    double heat_mst; ///< heat into the master, sum(areaSlv fluxMst dt) (accumulated)
} rs_driver_energy;

typedef struct rs_driver {
    /* Set with rs_driver_init and rs_driver_set_law; then fill the node arrays. */
    int n;                     ///< slave nodes
    const rs_surface *surface; ///< the rigid master (not owned)
    rs_motion motion;          ///< its rigid motion (rs_motion_init: fixed)
    int moving;                ///< 1: pass the motion to the tracker (set it when the
                               ///< master moves)
    const rs_law *law;         ///< not owned
    double props[64];          ///< law properties
    int nprops;
    int nstatev;     ///< state variables per contact (>= law->nstatev)
    double dt;       ///< time increment (> 0)
    double tracking; ///< tracking thickness: contacts kept while gap <= it
    int capacity;    ///< contacts per node (tracker slots) to begin with, default 4; the
                     ///< wall's slots double (up to RS_TRACK_MAX_CAPACITY) when a node has
                     ///< more
    char surfInt[RS_LAW_NAMELEN], surfSlv[RS_LAW_NAMELEN]; ///< names passed to the law

    /* Node data (SoA, n each), allocated and zeroed by rs_driver_init. */
    double *x, *y, *z;    ///< positions (z unused for SEGMENTS)
    double *vx, *vy, *vz; ///< velocities, v_{k-1/2} between increments
    double *radius;       ///< sphere radius, 0 for a point node
    double *mass;         ///< mass (default 1)
    double *area;         ///< areaSlv (default 1)
    double *fext;         ///< applied force (3, n)
    double *vpres;        ///< prescribed velocity (3, n)
    unsigned char *fixed; ///< (3, n): 1 = component prescribed by vpres
    double *temp;         ///< temperature
    double *heatcap;      ///< heat capacity C (energy per kelvin); 0: fixed temperature
    double *fcon;         ///< contact force of the last increment (3, n)
    double *q;            ///< orientation (4, n): unit quaternion (w, x, y, z), body to
                          ///< world, x_world = x + R(q) x_body; at t_k (default 1, 0, 0, 0)
    double *wx, *wy, *wz; ///< angular velocity in the world frame (rad per time unit),
                          ///< w_{k-1/2} between increments, as v
    double *inertia;      ///< principal moments of inertia (3, n) about the body axes
                          ///< (mass length^2); 0 (default): the node keeps its w
    double *text;         ///< applied torque (3, n), world frame
    double *tcon;         ///< contact torque of the last increment (3, n), world frame,
                          ///< about the node's position
    const rs_shape **shape; ///< per node its convex shape (not owned), NULL for a sphere
                            ///< or a point (rs_driver_set_body)
    double fwall[3];        ///< force of the last increment's contacts on the master
    double mwall[3];        ///< its moment about the master's point a (its origin)
    double tmaster;         ///< master temperature
    double heatcap_master;  ///< master heat capacity; 0: fixed temperature

    rs_driver_bc_fn bc; ///< optional, see rs_driver_bc_fn
    void *bc_ctx;
    void (*warn)(void *warn_ctx, const rs_law *law, int k,
                 const char *msg); ///< law warnings
    void *warn_ctx;

    /* State and results (read only). */
    double t; ///< time t_k of the next increment
    int inc;  ///< increments done
    rs_driver_energy energy;
    rs_track_out trk;     ///< contacts of the last increment (kinematics; the wall's, valid
                          ///< until the next increment)
    rs_contact_block cb;  ///< their law inputs and results: stress (nDir, trk.n),
                          ///< statev, sed, sfd, spd, svd, scd, flux_slv, flux_mst
    struct rs_wall *wall; ///< the wall that computes each increment's contacts
                          ///< (rs_wall_step; made on the first increment)

    /* Internal storage. */
    int *id;
    double tmaster_prev;
    rs_body *body;   ///< the bodies in their pose of the increment (n)
    rs_shape *owned; ///< polyhedra turned into their principal axes (n, unused: zero)
    double *xv;      ///< the nodes' positions, velocities and angular velocities as the
                     ///< wall reads them (3, n each), and their heat flows (n)
} rs_driver;

/// Allocates n nodes on surface s (not owned): positions and velocities 0, mass 1,
/// areaSlv 1, no prescribed components, temperatures 0, a fixed master, capacity 4,
/// tracking thickness 0 (set it). Returns RS_ERR_ARG or RS_ERR_NOMEM.
int rs_driver_init(rs_driver *d, const rs_surface *s, int n, rs_error *err);

/// Sets the law and its properties (checked with rs_law_check_props) and the state
/// variables per contact, nstatev >= law->nstatev. Call before the first increment.
int rs_driver_set_law(rs_driver *d, const rs_law *law, const double *props, int nprops,
                      int nstatev, rs_error *err);

/// Makes node i a rigid convex body of the given shape (not owned; it outlives d):
/// its mass and principal moments from the shape at density (rs_shape_mass_props),
/// its radius, the characteristic length the tracker and the laws see (Hertz's radius),
/// that of the sphere of equal volume, and a capacity of at least 16 history slots per
/// node to begin with (a manifold has up to RS_MANIFOLD_MAX points per feature; the
/// slots grow as a step needs them). Its contacts come
/// from rs_body_query. The node's q is the orientation of the body's principal axes:
/// those of every built-in shape are its body axes; a polyhedron whose inertia is not
/// diagonal in its points' axes is turned once into its principal axes A (the columns
/// of rs_mass_props.axes; the driver keeps the turned copy), so that its points' frame
/// has the orientation q A^T. Set q after this call. RS_ERR_ARG for a bad node, shape
/// or density, or a user shape (it has no mass of its own).
int rs_driver_set_body(rs_driver *d, int i, const rs_shape *shape, double density,
                       rs_error *err);

/// One increment (see the file comment). Returns the first error of the query, the
/// tracker, the law or the boundary-condition callback.
int rs_driver_step(rs_driver *d, rs_error *err);

/// One increment of a rigid body's rotation (the file comment, step 5): the orientation q
/// (w, x, y, z; body to world) at t_k and the world-frame angular velocity w at t_{k-1/2}
/// become q at t_{k+1} and w at t_{k+1/2}, under the world-frame torque tau of t_k.
/// inertia: principal moments about the body axes; unless all three are > 0, w is kept
/// and q turns with it.
void rs_rotation_step(double q[4], double w[3], const double inertia[3],
                      const double tau[3], double dt);

/// Rotational kinetic energy w . L / 2 of a body with orientation q, world-frame angular
/// velocity w and principal moments inertia.
double rs_rotation_energy(const double q[4], const double w[3], const double inertia[3]);

/// Frees everything rs_driver_init and the increments allocated, and zeroes d.
void rs_driver_free(rs_driver *d);

#ifdef __cplusplus
}
#endif
#endif
