/* fix wall/rigid: a rigidsurf master surface as a LIGGGHTS wall (docs/fix_wall_rigid.md).
 *
 * Each step the particles of the group near the surface are queried in blocks, their
 * contacts tracked (rs_track_update), handed to an interface law with the VUINTER
 * calling convention (rs_law_call), and the resulting interface stress applied:
 * F = A (s1 n - s2 t1 - s3 t2) at the contact point, the wall gets -F. The per-contact
 * history lives in a small per-atom row (the tracker's directory, previous fields) and
 * in slot-major slot arrays the fix owns (the tracker's slot, then the contact's sed);
 * both migrate with the atoms and go into restart files. */
#ifdef FIX_CLASS

FixStyle(wall / rigid, FixWallRigid)

#else

#ifndef RIGIDSURF_FIX_WALL_RIGID_H
#define RIGIDSURF_FIX_WALL_RIGID_H

#include "fix.h"

#include "rigidsurf/contact_block.h"
#include "rigidsurf/law.h"
#include "rigidsurf/motion.h"
#include "rigidsurf/surface.h"
#include "rigidsurf/track.h"

#include <cstddef>
#include <string>
#include <vector>

namespace LAMMPS_NS
{

class FixWallRigid : public Fix
{
  public:
    FixWallRigid(class LAMMPS *, int, char **);
    ~FixWallRigid();

    int setmask();
    void post_create();
    void pre_delete(bool unfixflag);
    void init();
    void setup(int);
    void initial_integrate(int);
    void pre_neighbor();
    void post_force(int);
    void end_of_step();
    void final_integrate();
    void post_run();

    double compute_vector(int);
    int min_type();
    int max_type();

    void write_restart(FILE *);
    void restart(char *);
    void grow_arrays(int);
    void copy_arrays(int, int, int);
    void set_arrays(int);
    int pack_exchange(int, double *);
    int unpack_exchange(int, double *);
    int pack_restart(int, double *);
    void unpack_restart(int, int);
    int size_restart(int);
    int maxsize_restart();
    double memory_usage();

    /// Used by the motion rates callback: the current values of the v_ variables.
    void motion_rates(double vel[3], double *omega);
    void spin_rate(double *omega);

  private:
    /* Global vector: 1-3 force on the wall, 4-6 moment on the wall about the surface
     * origin, 7 touching contacts, 8 ALLSE, 9 ALLFD, 10 ALLPD, 11 ALLVD, 12 ALLCD, 13
     * wall temperature, 14 heat into the wall, 15-17 the wall's translation since the
     * fix was defined, 18 its rotation angle about the rotation axis. */
    static const int kNout = 18;
    enum AreaMode { AREA_NODE, AREA_PROJECTED, AREA_CONSTANT };
    enum LawKind { LAW_BUILTIN, LAW_LOADED, LAW_LIGGGHTS };

    /* input */
    void parse(int narg, char **arg);
    int parse_surface(int narg, char **arg, int iarg);
    int parse_law(int narg, char **arg, int iarg);
    int parse_motion(int narg, char **arg, int iarg);
    double number(const char *keyword, const char *what, const char *s);
    double positive(const char *keyword, const char *what, const char *s);
    int integer(const char *keyword, const char *what, const char *s);
    bool is_keyword(const char *s) const;
    [[noreturn]] void fail(const std::string &msg);
    [[noreturn]] void fail_one(const std::string &msg);

    /* setup of the run */
    void init_material_props();
    void init_variables();
    void init_heat();
    void init_predef();
    void init_vtk_mesh();
    void check_step();

    /* the step */
    void compute(bool setup_call);
    void init_scratch();
    void build_candidates();
    void sort_behind(int n, double dist_min); // fix_wall_rigid_sides.cpp
    void warn_behind();
    /// The rebuilds look behind the surface: it is one-sided and has not warned yet.
    bool looks_behind() const
    {
        return surf_.sides != 2 && !behind_warned_;
    }
    bool wall_moved_beyond_skin() const;
    double box_reach(const double c[3]) const;
    void process_block(const int *idx, int n, bool setup_call);
    void line_block(const int *idx, int n);
    void law_inputs(const int *idx, int n, int ne, bool setup_call);
    void liggghts_block(const int *idx, int n, int ne, bool setup_call);
    double liggghts_reach() const;
    /// A per-atom output row: rdisp and stress of the block's contact e (nd values each;
    /// the third 0 for nd = 2), zeros for e < 0 (no contact).
    static void put_output(double *__restrict o, int e, int nd,
                           const double *__restrict stress, const double *__restrict rdisp)
    {
        if (e < 0) {
            o[0] = o[1] = o[2] = o[3] = o[4] = o[5] = 0.0;
            return;
        }
        const double *s = stress + (size_t)e * nd, *rd = rdisp + (size_t)e * nd;
        o[0] = rd[0];
        o[1] = rd[1];
        o[2] = nd == 3 ? rd[2] : 0.0;
        o[3] = s[0];
        o[4] = s[1];
        o[5] = nd == 3 ? s[2] : 0.0;
    }
    /// put_output for each particle k of a block: its contact e[k] (e NULL: contact k,
    /// or none where leaving[k]).
    void put_outputs(const int *idx, int n, int nd, const int *e, const char *leaving);
    bool block_props(int t, const double **props, int *nprops) const;
    rs_load_rows load_rows(const int *idx, bool setup_call) const;
    void add_wall_load(const rs_wall_load &wl, bool setup_call);
    void write_vtk();
    void update_previous_fields();
    void begin_wallforce();

    /* facets of a MESH: stress and wear (fix_wall_rigid_facets.cpp) */
    void init_facets();
    void begin_facets();
    void facet_pass(const int *idx, int ne, bool setup_call);
    void reduce_facets(std::vector<double> &sn, std::vector<double> &st,
                       std::vector<double> &wear);

    /* per-atom row layout (doubles): tracker directory (capacity), previous temperature
     * (1), previous predefined fields (npred). The slots are in hist_, slot-major: atom
     * i's slot j at hist_ + (j * nmax_ + i) * slot_size(), so an atom with one contact
     * touches its row and the dense slot-0 array only. A slot is the tracker's, laid out
     * for the law (rs_track_slot_size: what the law reads of the contact's last call). */
    int slot_size() const
    {
        return rs_track_slot_size(&tracker_);
    }
    int tprev_offset() const
    {
        return capacity_;
    }
    int pred_offset() const
    {
        return tprev_offset() + 1;
    }
    int row_size() const
    {
        return pred_offset() + (int)predef_names_.size();
    }
    /// The most doubles one atom may carry through LIGGGHTS's exchange: LIGGGHTS 3.8
    /// packs a leaving atom into the slack of its send buffer (comm.cpp and
    /// irregular.cpp: BUFEXTRA, 1000 doubles, shared by the atom style and every fix).
    static const int kExchangeMax = 600;
    /// Doubles one atom's history takes: its row, then its slots. Exchange and restart
    /// carry one more, the capacity it was packed with, first.
    int atom_size() const
    {
        return row_size() + capacity_ * slot_size();
    }
    /// The largest capacity whose atoms still fit the exchange (kExchangeMax doubles
    /// with the leading capacity) and the tracker (RS_TRACK_MAX_CAPACITY).
    int max_capacity() const;
    /// Grows every atom's history to at least need slots (doubling), keeping what it
    /// holds; false when need exceeds max_capacity().
    bool grow_capacity(int need);
    ptrdiff_t slot_stride() const
    {
        return (ptrdiff_t)nmax_ * slot_size();
    }
    double *slot0(int i) const
    {
        return hist_ + (size_t)i * slot_size();
    }
    double *alloc_slots(size_t n);
    void clear_row(int i);
    void pack_atom(int i, double *buf) const;
    void unpack_atom(int i, const double *buf);
    int unpack_sized(int i, const double *buf); // capacity first; returns doubles read

    /* surface and motion */
    rs_surface surf_;
    std::string inline_text_; // keyword text of an inline surface
    bool surf_ok_;
    int ndir_;
    rs_motion motion_;
    bool moving_;
    bool belt_; // surface_vel: the tracker gets the motion even when the wall stays
    std::string var_vel_[3], var_omega_; // v_ names ("" = constant)
    int ivar_vel_[3], ivar_omega_;
    bool rot_by_period_;
    double period_;
    std::string var_spin_; // the spin's rate: v_ name ("" = constant), by period or not
    int ivar_spin_;
    bool spin_by_period_;
    double disp_at_build_[3], phi_at_build_, spin_at_build_;
    bool spin_invariant_; // spun about the surface's own spin axis (rs_surface_spin_axis)

    /* law */
    LawKind law_kind_;
    const rs_law *law_;
    rs_law loaded_;
    bool loaded_ok_;
    std::string law_name_;
    std::vector<double> props_;
    bool props_given_;
    bool hertz_, hooke_;
    bool one_pass_;  // the built-in hertz on unit areas, nothing reading the staged arrays:
                     // a usual block runs in one pass (rs_track_hertz)
    bool line_pass_; // and on a revolved LINE, a block runs per run of spheres (line_block)
    std::vector<int> rest_; // line_block's spheres that are not usual
    /* law liggghts: LIGGGHTS's contact model, and the descriptor law_ points to */
    class LiggghtsLaw *lig_;
    rs_law lig_desc_;
    /// Properties per particle type from LIGGGHTS's material properties (hertz or hooke
    /// without props).
    bool material_props() const
    {
        return (hertz_ || hooke_) && !props_given_;
    }
    std::vector<std::vector<double>> type_props_; // hertz: props per particle type
    int nstatev_;
    bool statev_given_;

    /* contact settings */
    int wall_type_;
    int capacity_;
    double tracking_;
    bool tracking_given_;
    AreaMode area_mode_;
    double area_const_;
    rs_tracker tracker_;

    /* servo: the wall's rate set so that its force (torque) along an axis reaches a
     * target, with LIGGGHTS's mesh/surface/stress/servo controller
     * (fix_wall_rigid_servo.cpp) */
    struct Servo {
        bool on = false, torque = false, auto_mode = false;
        double com[3] = {0.0, 0.0, 0.0}, axis[3] = {0.0, 0.0, 1.0};
        double target = 0.0; // target_val
        std::string target_var;
        int ivar = -1;
        double vmax = 0.0, kp = 1e-2, ki = 0.0, kd = 0.0, ratio = 0.0;
        double sp = 0.0;                   // set point: -target
        double op_max = 0.0, op_min = 0.0; // largest rate; the auto mode's slow rate
        double sum_err = 0.0, old_pv = 0.0;
    } servo_;
    int parse_servo(int narg, char **arg, int iarg);
    void init_servo();
    double servo_reach();

    /* heat */
    bool temp_given_;
    double temp_wall_, dtemp_wall_;
    double capacity_wall_; // 0: fixed temperature
    double heat_wall_;     // accumulated heat into the wall (energy), this rank
    double heat_step_;     // heat flow into the wall this step (power), this rank
    class FixPropertyAtom *fix_temp_, *fix_heatflux_;
    class FixPropertyGlobal *fix_heatcap_;
    /* conduction liggghts: LIGGGHTS's wall conduction (fix_wall_gran.cpp, addHeatFlux)
     * between the wall at its temperature and each touching particle
     * (fix_wall_rigid_heat.cpp) */
    bool conduction_;
    /* conduction's contact area, LIGGGHTS's contact_area: pi (R^2 - (R - delta)^2),
     * pi R^2 or a constant */
    enum { CAREA_OVERLAP, CAREA_PROJECTION, CAREA_CONSTANT } carea_mode_;
    double carea_const_;
    bool carea_given_;
    bool conduct_ready_;    // a setup call has been made: LIGGGHTS's walls conduct in later
                            // ones
    const double *th_cond_; // thermalConductivity per atom type
    double const *const *deltan_ratio_; // heat/gran/conduction's area correction, or NULL
    void init_conduction();
    void conduct(const int *idx, int ne, bool setup_call);

    /* store_force yes: the wall's force on each particle this step, in the per-atom
     * vector force_ID of a fix property/atom of that ID, as fix wall/gran keeps it;
     * store_force into W: in force_W, shared by the wall/rigid fixes that name it (the
     * meshes of one wall/gran); the first of them in the fix list clears it each step */
    bool store_force_;
    /// `peratom yes`: the per-atom array (rdisp and stress of each atom's deepest contact)
    /// is kept, array_atom; otherwise array_atom is NULL and nothing writes it.
    bool peratom_;
    std::string wallforce_id_;
    bool wallforce_clear_;
    double **wallforce_; // its array this step, or NULL
    bool shares_wallforce(const FixWallRigid *other) const;

    /* predefined fields */
    std::vector<std::string> predef_names_;
    std::vector<class FixPropertyAtom *> predef_fix_;

    /* vtk */
    std::string vtk_file_;
    int vtk_every_;
    rs_trimesh vtk_mesh_;
    bool vtk_mesh_ok_;

    /* facets: `wear finnie`, and the facet stresses of the VTK steps */
    bool wear_;        // wear finnie
    bool facets_;      // a MESH with vtk or wear: the facet arrays are kept
    bool stress_step_; // this step's facet forces are summed (a VTK step)
    int nfacet_;
    std::vector<double> elem_area_, elem_n_; // reference area and unit normal per facet
    std::vector<double> elem_f_;             // 3 per facet: this step's force on the wall
    std::vector<double> wear_el_;            // per facet: this rank's share of the wear
    std::vector<double> kfinnie_;            // k_finnie with the wall type, per atom type
    bool step_checked_; ///< the time step was checked against the law's critical step

    /* per-atom storage */
    double **row_;
    double *hist_; // capacity * nmax_ slots, slot-major
    int nmax_;

    /* candidates: local atom indices near the surface, bucketed by type for hertz */
    std::vector<int> cand_;
    bool rebuild_;
    /* Distance bounds: a candidate queried at x_ref with radius R_ref had gap >= gap_ref
     * to every feature (the query looks ahead by lookahead_ beyond tracking). While its
     * radius is R_ref, |x - x_ref| < gap_ref - tracking and it holds no contact, it
     * cannot come within the tracking thickness: the step skips it. Per local atom (x,
     * y, z, R in xref_), reset with the candidates; only for a wall that stays in
     * place. */
    std::vector<double> xref_, gapref_;
    std::vector<int> active_;
    double lookahead_;
    double rglob_; ///< the largest radius of the candidates (their depth limit with bounds)
    bool bounds_ok_;
    bool list_bounds_;         // the candidate lists give the bounds (a static MESH)
    std::vector<double> bgap_; // per particle of a block: its smallest gap
    void update_bounds(const int *idx, int n, const double *gmin);
    void keep_tracked(const int *idx, int n, double dist_min);

    /* candidate lists of surfaces that give them (MESH: triangles), made with the
     * candidates for every candidate atom i: cids_[cfirst_[i] .. + cnum_[i]) */
    rs_cands cands_;
    std::vector<int> cfirst_, cnum_, cids_;
    std::vector<const int *> bcand_;
    std::vector<int> bncand_;
    void build_candidate_lists();
    rs_query sphere_query(const int *idx, int n);

    /* scratch of one block, sized once in init() (init_scratch) */
    rs_contacts contacts_;
    rs_track_out tout_;
    std::vector<double> bx_, by_, bz_, bvx_, bvy_, bvz_, bwx_, bwy_, bwz_, brad_;
    std::vector<int> bid_, bidx_;
    std::vector<double *> bdir_, bhist_;
    std::vector<double> saved_rows_; // setup call: each particle's row, then its slots
    std::vector<char> leaving_, take_;
    std::vector<int> deepest_;
    bool ident_ = false; // the block's contact e is particle e's only contact, for all e
    std::vector<double> area_w_; // the block's areas times shares, when shared
    const double *load_area_ =
        nullptr; // each contact's area times its share, for the facets: cb_.area or area_w_
    rs_law_block blk_; // the law block's fields that stay for the run
    /* per particle of a block: mass, type, heat capacity, temperature and its
     * increment, predefined fields and their increments (npred per particle) */
    std::vector<double> bmass_, bheat_, btemp_, bdtemp_, bpred_, bdpred_;
    rs_particle_block pblk_; // the block's arrays as the library's calls read them
    std::vector<int> btype_;
    rs_contact_block cb_; // per contact of a block (RS_BLOCK * capacity): law inputs

    /* per step, local sums; accumulated totals */
    double f_wall_[3], m_wall_[3], se_now_;
    int ncontact_;
    double diss_[4]; // ALLFD, ALLPD, ALLVD, ALLCD (this rank's share since the start)
    double out_[kNout];
    bigint out_step_;
    bool out_valid_;
    double temp_mst_[1], dtemp_mst_[1];

    /* Abaqus step and increment: kstep_ counts the runs (setup calls) from 1; KINC is
     * the step's increment from 1 (update->ntimestep - update->firststep); step time
     * restarts at run_time0_, the total time at the start of the run. */
    int kstep_;
    double run_time0_;
    /* What the law's user routines asked this run (PNEWDT < 1, the stiffness they
     * returned), this rank; reported in post_run. pnewdt_stop_: keyword 'pnewdt stop'. */
    rs_law_requests requests_;
    bool pnewdt_stop_;
    bool routine_step_warned_; ///< the routine-stiffness step warning was printed
    /* Particles found behind a one-sided surface on this rank's rebuilds since the last
     * check, and whether the warning was printed (then the rebuilds look no more). */
    long behind_;
    bool behind_warned_;
    void report_requests();
    /* The layout version of the restart file this fix read its global record from (0:
     * none); unpack_restart converts the per-atom records of an older version. */
    double restart_version_ = 0.0;
};

} // namespace LAMMPS_NS

#endif
#endif
