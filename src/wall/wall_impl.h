/* The wall's state (include/rigidsurf/wall.h) and the functions its files share. Internal
 * to the library. */
#ifndef RIGIDSURF_WALL_IMPL_H
#define RIGIDSURF_WALL_IMPL_H

#include "rigidsurf/wall.h"

#include <stddef.h>
#include <stdint.h>
#include <string.h>

/* What a law is to the wall: a built-in one (hertz and hooke may read the engine's
 * material properties), one loaded from a library or a Fortran source (owned), or the
 * engine's own models (the host's). */
enum { WALL_LAW_BUILTIN, WALL_LAW_LOADED, WALL_LAW_ENGINE };
enum { WALL_AREA_NODE, WALL_AREA_PROJECTED, WALL_AREA_CONSTANT };
enum { WALL_CAREA_OVERLAP, WALL_CAREA_PROJECTION, WALL_CAREA_CONSTANT };

/// Names of a motion's variables: the v_NAME of a rate, "" for a constant.
#define WALL_NAME 128

/* The servo: the wall's rate set so that its force (torque) along an axis reaches a
 * target, with LIGGGHTS's mesh/surface/stress/servo controller (wall_servo.c). */
typedef struct wall_servo {
    int on, torque, auto_mode;
    double com[3], axis[3];
    double target; ///< target_val
    char target_var[WALL_NAME];
    int ivar;
    double vmax, kp, ki, kd, ratio;
    double sp;             ///< set point: -target
    double op_max, op_min; ///< largest rate; the auto mode's slow rate
    double sum_err, old_pv;
} wall_servo;

struct rs_wall {
    rs_wall_host host;
    rs_wall_info info;
    char id[WALL_NAME], group[WALL_NAME];
    rs_wall_run run;
    int run_ok; ///< rs_wall_init has run

    /* surface */
    rs_surface surf_own;
    const rs_surface *surf;
    char *inline_text; ///< keyword text of an inline surface
    int ndir;

    /* motion */
    rs_motion motion_own;
    rs_motion *motion;
    int moving, belt; ///< belt: surface_vel, the tracker gets the motion even at rest
    char var_vel[3][WALL_NAME], var_omega[WALL_NAME], var_spin[WALL_NAME];
    int ivar_vel[3], ivar_omega, ivar_spin;
    char var_disp[3][WALL_NAME]; ///< move variable: the translation's variables
    int ivar_disp[3];
    double disp_given[3]; ///< move variable: the translation's numbers
    int rot_by_period, spin_by_period;
    double period;
    rs_error rates_err; ///< why a rates callback stopped the motion
    double disp_at_build[3], phi_at_build, spin_at_build;
    int spin_invariant; ///< spun about the surface's own spin axis

    /* law */
    int law_kind;
    const rs_law *law;
    rs_law loaded;
    int loaded_ok;
    char law_name[WALL_NAME];
    char law_words[512]; ///< an engine law's words, for messages
    double *props;
    int nprops, props_given;
    int hertz, hooke;
    int fused_ok;       ///< the law's fused kernel may take this wall's usual blocks
    int line_pass;      ///< ... and on a revolved LINE or a MESH, per run of spheres
                        ///< (wall_line.c)
    int line_mesh;      ///< the line path on a MESH: the held faces' clear zones
    int line_force;     ///< the line path calls the force law's model on its runs
                        ///< (rs_law.force_run or force_one; wall_force_line.c)
    double *type_props; ///< per type (ntypes + 1 rows of tp_n): hertz's or hooke's props
    char *type_has;     ///< per type: its row is set
    int tp_n, ntype_props;
    int nstatev, statev_given, user_statev;
    int curvature, curvature_given;

    /* contact settings */
    int capacity;
    double tracking;
    int tracking_given;
    int area_mode;
    double area_const;
    rs_tracker tracker;
    int fused_given; ///< keyword fused: 0 forces the staged calls

    wall_servo servo;

    /* heat */
    int temp_given;
    double temp_wall, dtemp_wall;
    double capacity_wall; ///< 0: fixed temperature
    double heat_wall;     ///< accumulated heat into the wall (energy), this rank
    double heat_step;     ///< heat flow into the wall this step (power), this rank
    double *heatcap_type; ///< thermalCapacity per type (ntypes + 1), or NULL
    int conduction, carea_mode, carea_given;
    double carea_const;
    int conduct_ready; ///< a setup call has been made: LIGGGHTS's walls conduct after
    double *th_cond;   ///< thermalConductivity per type (ntypes + 1)
    double
        *deltan_ratio; ///< heat/gran/conduction's area correction, (ntypes + 1)^2, or NULL
    double temp_mst[1], dtemp_mst[1];

    /* outputs */
    int store_force, peratom;
    char wallforce_id[WALL_NAME + 8];
    char **pred_names;
    int npred;
    char *vtk_file;
    int vtk_every;
    rs_trimesh vtk_mesh;
    int vtk_mesh_ok;

    /* facets of a MESH: stress and wear (wall_facets.c) */
    int wear, facets, stress_step, nfacet;
    double *elem_area, *elem_n, *elem_f, *wear_el, *kfinnie;
    int step_checked;

    /* per-particle storage: rows (row_size each: directory, previous temperature,
     * previous fields) and slot-major slots: particle i's slot j at hist + (j nmax + i)
     * slot_size */
    double *rows;
    double *hist;
    /* per particle, what its directory holds in short: f + 1 when its one contact is
     * feature f's in slot 0 and the other slots are free (rs_track_dir_usual), else 0;
     * the line path reads it instead of the row (wall_line.c, wall_usual_of) */
    int *usual;
    int nmax;

    /* candidates */
    int *cand, ncand, cand_cap;
    int rebuild;
    double *xref, *gapref; ///< distance bounds per particle (wall_candidates.c)
    /** on the line path of a MESH, per particle the ball its held face's zone test left
     * (rs_mesh_held_balls; wall_candidates.c) */
    struct rs_mesh_held_ball *hball;
    int nref;
    int *active;
    double lookahead, rglob;
    int bounds_ok, list_bounds;
    rs_cands cands;
    int *cfirst, *cnum, *cids;
    int ncids, cids_cap;

    /* scratch of one block (wall_scratch) */
    int bcap; ///< particles a block holds
    rs_contacts contacts;
    rs_track_out tout;
    double *bx, *by, *bz, *bvx, *bvy, *bvz, *bwx, *bwy, *bwz, *brad, *bgap;
    double *bmass, *bheat, *btemp, *bdtemp, *bpred, *bdpred, *barea;
    int *bid, *btype, *bidx, *deepest;
    double **bdir, **bhist;
    const int **bcand;
    int *bncand, *bhint;
    double *saved_rows;
    char *leaving, *take;
    double *area_w;
    const double *load_area;
    int ident;
    rs_law_block blk;
    rs_particle_block pblk;
    rs_contact_block cb;
    rs_body *bbody;
    int cbcap; ///< contacts the contact block holds

    /* per step, local sums; accumulated totals */
    double f_wall[3], m_wall[3], se_now;
    double fd_step, pd_step, vd_step, cd_step, qs_step;
    int ncontact;
    double diss[4]; ///< ALLFD, ALLPD, ALLVD, ALLCD (this rank's share since the start)

    /* Abaqus step and increment: kstep counts the runs (setup calls) from 1 */
    int kstep;
    double run_time0;
    rs_law_requests requests;
    int pnewdt_stop;
    int routine_step_warned;
    long behind;
    int behind_warned;
    int behind_none; ///< behind none: a one-sided surface leaves alone the particles behind
                     ///< it
    double restart_version;
    void (*warn)(void *warn_ctx, const rs_law *law, int k, const char *msg);
    void *warn_ctx;
    char names[3][WALL_NAME]; ///< surfInt, surfSlv, surfMst (the law sees 80 characters)
};

/* ---- sizes of the per-particle storage (wall_history.c) ---- */
static inline int wall_slot_size(const rs_wall *w)
{
    return rs_track_slot_size(&w->tracker);
}
static inline int wall_tprev_at(const rs_wall *w)
{
    return w->capacity;
}
static inline int wall_pred_at(const rs_wall *w)
{
    return w->capacity + 1;
}
static inline int wall_row_size(const rs_wall *w)
{
    return w->capacity + 1 + w->npred;
}
/// Doubles one particle's history takes: its row, then its slots.
static inline int wall_atom_size(const rs_wall *w)
{
    return wall_row_size(w) + w->capacity * wall_slot_size(w);
}
static inline ptrdiff_t wall_slot_stride(const rs_wall *w)
{
    return (ptrdiff_t)w->nmax * wall_slot_size(w);
}
static inline double *wall_row(const rs_wall *w, int i)
{
    return w->rows + (size_t)i * (size_t)wall_row_size(w);
}
static inline double *wall_slot0(const rs_wall *w, int i)
{
    return w->hist + (size_t)i * (size_t)wall_slot_size(w);
}
/// Whether particle i's distance bound keeps it beyond the tracking thickness this step:
/// it has one (no contact held, set at its last query) and has moved less than the room
/// the bound leaves, with the radius it had then.
/// The test on the bounds' arrays themselves (gapref, xref, tracking), for loops that keep
/// them in registers.
static inline int wall_kept_away_at(const double *gapref, const double *xref,
                                    double tracking, const double *x, const double *radius,
                                    int i)
{
    const double room = gapref[i] - tracking;
    const double *xr = &xref[4 * (size_t)i], *xi = x + 3 * (size_t)i;
    /* the radius the bound was made with, the same bit for bit */
    uint64_t r_now, r_then;
    memcpy(&r_now, &radius[i], sizeof r_now);
    memcpy(&r_then, &xr[3], sizeof r_then);
    if (!(room > 0.0) || r_now != r_then)
        return 0;
    const double dx = xi[0] - xr[0], dy = xi[1] - xr[1], dz = xi[2] - xr[2];
    return dx * dx + dy * dy + dz * dz < room * room;
}
static inline int wall_kept_away(const rs_wall *w, const double *x, const double *radius,
                                 int i)
{
    return wall_kept_away_at(w->gapref, w->xref, w->tracking, x, radius, i);
}
/// What a directory row holds in short (rs_wall.usual): f + 1 when slot 0 holds feature
/// f's contact alone, else 0.
static inline int wall_usual_of(const rs_wall *w, const double *d)
{
    if (!RS_DIR_IS_LIVE(d[0]))
        return 0;
    for (int j = 1; j < w->capacity; j++)
        if (d[j] != RS_DIR_EMPTY)
            return 0;
    return (int)d[0];
}
/// The law's properties come per particle type from the engine's material properties.
static inline int wall_material_props(const rs_wall *w)
{
    return (w->hertz || w->hooke) && !w->props_given;
}
static inline int wall_in_group(const rs_wall_block *b, int i)
{
    return !b->mask || (b->mask[i] & b->groupbit);
}
/// The rebuilds look behind the surface: it is one-sided, pushes those behind it through
/// (behind push) and has not warned yet.
static inline int wall_looks_behind(const rs_wall *w)
{
    return w->surf->sides != 2 && !w->behind_warned && !w->behind_none;
}
/// behind none on a one-sided surface: a particle touches it only with its centre in
/// front (dist >= 0); one behind it is left alone until it comes through.
static inline int wall_front_only(const rs_wall *w)
{
    return w->behind_none && w->surf->sides != 2;
}

/* wall_words.c, wall_law_words.c, wall_motion.c, wall_servo.c: the words */
int wall_parse(rs_wall *w, const char *const *arg, int narg, rs_error *err);
int wall_parse_surface(rs_wall *w, const char *const *arg, int narg, int *iarg,
                       rs_error *err);
int wall_parse_law(rs_wall *w, const char *const *arg, int narg, int *iarg, rs_error *err);
int wall_parse_motion(rs_wall *w, const char *const *arg, int narg, int *iarg,
                      rs_error *err);
int wall_parse_servo(rs_wall *w, const char *const *arg, int narg, int *iarg,
                     rs_error *err);
int wall_is_keyword(const char *s);
int wall_number(const char *keyword, const char *what, const char *s, double *v,
                rs_error *err);
int wall_positive(const char *keyword, const char *what, const char *s, double *v,
                  rs_error *err);
int wall_init_variables(rs_wall *w, rs_error *err);
int wall_init_servo(rs_wall *w, const rs_wall_block *b, rs_error *err);
void wall_warn(const rs_wall *w, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
double wall_reduce1(const rs_wall *w, double v, int op);

/* wall.c */
int wall_scratch(rs_wall *w, int np, rs_error *err);
int wall_scratch_contacts(rs_wall *w, rs_error *err);

/* wall_step.c, wall_block.c, wall_line.c */
int wall_compute(rs_wall *w, const rs_wall_block *b, const rs_wall_rows *rows, double dt,
                 int setup, rs_error *err);
int wall_block(rs_wall *w, const rs_wall_block *b, const rs_wall_rows *rows, const int *idx,
               int n, double dt, int setup, rs_error *err);
int wall_blocks(rs_wall *w, const rs_wall_block *b, const rs_wall_rows *rows,
                const int *list, int n, double dt, int setup, rs_error *err);
int wall_line_block(rs_wall *w, const rs_wall_block *b, const rs_wall_rows *rows,
                    const int *list, int n, double dt, rs_error *err);

/* wall_force_line.c: the line path's pass for a force law's model on runs of contacts */
/// The most state variables a contact of the force pass keeps (in the run's copy).
#define RS_FORCE_LINE_STATEV 16
int wall_force_line_takes(const rs_wall *w);
/// A force law's stress: its force F on the particle in the contact's frame, s = (F.n,
/// -F.t1, -F.t2), so that F = s1 n - s2 t1 - s3 t2 (docs/conventions.md).
static inline void wall_force_stress(const double F[3], const double n[3],
                                     const double t1[3], const double t2[3], double s[3])
{
    s[0] = F[0] * n[0] + F[1] * n[1] + F[2] * n[2];
    s[1] = -(F[0] * t1[0] + F[1] * t1[1] + F[2] * t1[2]);
    s[2] = -(F[0] * t2[0] + F[1] * t2[1] + F[2] * t2[2]);
}
/// A run of spheres p, each holding the one contact of c that its directory entry names
/// (the line path's usual spheres), through the force law's model.
int wall_force_line_run(rs_wall *w, const rs_wall_block *b, const rs_motion *mp, double dt,
                        const rs_particle_block *p, const rs_contacts *c,
                        const double origin[3], const rs_load_rows *rows, rs_wall_load *wl,
                        rs_error *err);
int wall_block_props(const rs_wall *w, int t, const double **props, int *nprops);
int wall_fused_props(const rs_wall *w, int t, const double **props);
void wall_add_load(rs_wall *w, const rs_wall_load *wl, int setup);
rs_load_rows wall_load_rows(const rs_wall *w, const rs_wall_rows *rows, const int *idx,
                            int setup);

/* wall_candidates.c, wall_sides.c */
int wall_moved_beyond_skin(const rs_wall *w);
int wall_build_candidates(rs_wall *w, const rs_wall_block *b, rs_error *err);
void wall_update_bounds(rs_wall *w, const rs_wall_block *b, const int *idx, int n,
                        const double *gmin);
void wall_sort_behind(rs_wall *w, int n, double dist_min);
void wall_warn_behind(rs_wall *w);

/* wall_history.c */
int wall_grow_capacity(rs_wall *w, int need, rs_error *err);
int wall_max_capacity(const rs_wall *w);
void wall_pack_atom(const rs_wall *w, int i, double *buf);
void wall_unpack_atom(rs_wall *w, int i, const double *buf);
void wall_clear_row(rs_wall *w, int i);
double *wall_alloc_slots(size_t n);
void wall_advise_huge(void *p, size_t bytes);

/* wall_facets.c, wall_heat.c, wall_output.c */
int wall_init_facets(rs_wall *w, rs_error *err);
void wall_begin_facets(rs_wall *w, long long step);
void wall_facet_pass(rs_wall *w, const rs_wall_block *b, const int *idx, int ne, double dt,
                     int setup);
int wall_reduce_facets(rs_wall *w, double *sn, double *st, double *wear, rs_error *err);
int wall_init_conduction(rs_wall *w, rs_error *err);
int wall_conduction_ratios(rs_wall *w, rs_error *err);
void wall_conduct(rs_wall *w, const rs_wall_block *b, const rs_wall_rows *rows,
                  const int *idx, int ne, int setup);
int wall_init_vtk(rs_wall *w, rs_error *err);
int wall_write_vtk(rs_wall *w, long long step, rs_error *err);
void wall_update_previous_fields(rs_wall *w, const rs_wall_block *b);

#endif
