/* rigidsurf: the contact block, the per-contact inputs of a law call assembled from the
 * tracker's output and the particles of one block, and the law called on it in slices
 * of at most RS_BLOCK contacts. The standalone driver and fix wall/rigid both use it, so
 * a law sees the same inputs in either. */
#ifndef RIGIDSURF_CONTACT_BLOCK_H
#define RIGIDSURF_CONTACT_BLOCK_H

#include "rigidsurf/law.h"
#include "rigidsurf/track.h"
#include "rigidsurf/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Effective radius of a sphere of radius R on a wall with principal curvatures k1, k2
/// (> 0 convex toward the particle): the equivalent radius of Hertz's elliptical contact,
/// Re = sqrt(R' R'') with 1/R' = 1/R + k1 and 1/R'' = 1/R + k2 (docs/conventions.md,
/// "Effective radius"). A plane gives R exactly; each relative curvature is floored at
/// 1e-6 / R, so a sphere in a conforming pocket keeps a finite radius.
double rs_effective_radius(double R, double k1, double k2);

/// How the area of a contact (areaSlv) follows from its particle.
typedef enum rs_area_mode {
    RS_AREA_NODE = 0,      ///< 1: stress is force (a node-based surface)
    RS_AREA_PROJECTED = 1, ///< pi R^2
    RS_AREA_CONSTANT = 2   ///< a given constant
} rs_area_mode;

/// The law inputs' view of a block (surface.h, rs_particle_block; index k as in
/// rs_track_out.point): n, radius, mass, id, type, area, heatcap, temp, dtemp, pred,
/// dpred.
typedef rs_particle_block rs_block_particles;

/// Per-contact arrays of a block (capacity cap contacts), in the law's layout.
typedef struct rs_contact_block {
    /* settings, set before rs_cblock_reserve */
    rs_area_mode area_mode; ///< when the particles give no area
    double area_const;      ///< RS_AREA_CONSTANT: the area
    int ndir, nstatev, npred;

    int cap;
    int *uid, *type, *row;
    double *stiff, *cond, *area, *radius, *mass, *reff, *temp, *dtemp, *pred, *dpred;
    double *stress, *statev, *flux_slv, *flux_mst, *sed, *sfd, *scd, *spd, *svd;
    double *force, *torque; ///< (3, cap) each: a force law's force and torque
                            ///< (RS_LAW_SETS_FORCE), which the loads then apply
    unsigned law_sets; ///< rs_law.sets of the law of the last rs_cblock_call: the loads
                       ///< leave out the outputs it declares zero
    int has_type, has_temp, has_row; ///< the last rs_cblock_inputs had types,
                                     ///< temperatures, the engine's indices
    /* Contacts [0, uni_n) hold the values of the key (R, m, A, k1, k2, dt) of a block
     * whose contacts all share it (a monodisperse bed on one feature): the next block
     * with that key refills only past them. */
    double uni_key[6];
    int uni_n;
    /* Facets (rs_cblock_facets): per contact its facet's node numbers, shape functions
     * and node coordinates in the current pose, nfac per contact (0: none); and one
     * slice's VUINTER facet arrays, made in rs_cblock_call. */
    int nfac, fac_cap;
    int *fac_node;     ///< (nfac, n) user node numbers
    double *fac_shape; ///< (nfac, n)
    double *fac_xyz;   ///< (3, nfac, n)
    int *sl_conn;      ///< (nfac, RS_BLOCK) 1-based positions in sl_uid
    int *sl_uid;       ///< (nfac RS_BLOCK) the slice's distinct nodes
    double *sl_xyz;    ///< (3, nfac RS_BLOCK) their coordinates
    int *sl_hash;      ///< open addressing over sl_uid
} rs_contact_block;

/// Sizes the arrays for cap contacts (cb's settings must be set). Keeps nothing.
int rs_cblock_reserve(rs_contact_block *cb, int cap, rs_error *err);
/// Frees the arrays and zeroes cb.
void rs_cblock_free(rs_contact_block *cb);

/// Fills the per-contact inputs of the contacts of o: ids, types, area, radius, mass,
/// default stiffness and conductance (rs_law_default_stiffness, _conductance),
/// effective radius (rs_effective_radius of the contact's curvatures), temperatures and
/// predefined fields; fluxSlv, fluxMst and sed enter at zero. Stress and statev are
/// the tracker's to load (rs_track_load into cb->stress, cb->statev).
void rs_cblock_inputs(rs_contact_block *cb, const rs_track_out *o,
                      const rs_block_particles *p, double dt);

/// The facets under the contacts of o on the faceted master s in pose (NULL: the
/// reference configuration), for a law that takes them (rs_law_takes_facets): fills
/// cb's facet arrays, which rs_cblock_call hands to each slice as VUINTER's facet
/// arguments. For a kind without facets cb->nfac = 0 and nothing is filled.
int rs_cblock_facets(rs_contact_block *cb, const rs_track_out *o, const rs_surface *s,
                     const rs_pose *pose, rs_error *err);

/// Calls law on the contacts of o in slices of at most RS_BLOCK: each slice is tmpl
/// (the engine's scalars: kStep, kInc, times, names, props, wall temperature, setup,
/// warnings) with the slice's arrays from o and cb.
int rs_cblock_call(rs_contact_block *cb, const rs_law *law, const rs_law_block *tmpl,
                   const rs_track_out *o, rs_error *err);

/// What the contacts of one call do to the wall (rs_cblock_loads); each sum over the
/// live contacts e with weight w_e A_e (share times area).
typedef struct rs_wall_load {
    double force[3];       ///< the force on the wall, the sum of -F_e
    double moment[3];      ///< its moment about the given origin
    double se;             ///< elastic energy of the interface now, the sum of sed (ALLSE)
    double fd, pd, vd, cd; ///< this call's frictional, plastic, viscous and creep
                           ///< dissipation, the sums of sfd, spd, svd, scd
    double flux_slv;       ///< heat flow into the particles, the sum of fluxSlv
    double flux_mst;       ///< heat flow into the wall, the sum of fluxMst
    int ncontact;          ///< contacts that overlap (rdisp1 > 0)
} rs_wall_load;

/// The loads of the contacts of o after the law (cb's stress, energies and fluxes):
/// for each live contact e on particle i = o->point[e], F_e = w A (s1 n - s2 t1 - s3
/// t2) at its contact point x_cp (docs/conventions.md, "Stress, flux, energy signs"; w
/// its share, A its area), into f (3, o->n), its torque (x_cp - x_i) x F_e about the
/// particle's centre (p's x, y, z) into t (3, o->n), and its heat flow w A fluxSlv into q
/// (o->n; NULL: not wanted); a leaving contact gets zeros. SEGMENTS (nDir 2): the
/// contact point keeps the particle's z, F has no z part. A force law
/// (RS_LAW_SETS_FORCE) gives F_e = w A force_e and T_e = w A torque_e itself, and the
/// wall's moment is -((x_i - o) x F_e + T_e). The wall's totals, with the moment about
/// origin, into *w. The engine adds f, t and q onto its particles.
void rs_cblock_loads(const rs_contact_block *cb, const rs_track_out *o,
                     const rs_particle_block *p, const double origin[3], double *f,
                     double *t, double *q, rs_wall_load *w);

/// Where rs_cblock_add_loads puts each particle's loads: the engine's own per-particle
/// arrays (3 doubles a row for vectors: LIGGGHTS's and LAMMPS's atom->f[0],
/// atom->torque[0]), particle k of the block at row[k].
typedef struct rs_load_rows {
    const int *row; ///< per block particle, its row (NULL: row k for particle k)
    double *f;      ///< forces, 3 a row: += F
    double *t;      ///< torques, 3 a row: += (x_cp - x_i) x F
    double *fstore; ///< NULL, or stored forces, 3 a row, that also take += F
    double *q;      ///< NULL, or heat flow per row: += w A fluxSlv
    int *deepest;   ///< NULL, or per block particle (p->n) its live contact entry of
                    ///< largest rdisp1, -1 for none
    double *out6;   ///< NULL, or 6 a row: rdisp(1:3) and stress(1:3) of the particle's
                    ///< contact, which a law's fused kernel writes (rs_cblock_add_loads
                    ///< leaves it)
} rs_load_rows;

/// rs_cblock_loads in one pass onto the engine's rows: each live contact's F and torque
/// (and heat flow) added onto its particle's rows, the wall's totals into *w (which it
/// sets, as rs_cblock_loads does). The same numbers, bit for bit.
void rs_cblock_add_loads(const rs_contact_block *cb, const rs_track_out *o,
                         const rs_particle_block *p, const double origin[3],
                         const rs_load_rows *rows, rs_wall_load *w);

#ifdef __cplusplus
}
#endif
#endif
