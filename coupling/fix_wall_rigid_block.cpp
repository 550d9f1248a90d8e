/* fix wall/rigid: one block of particles per call: gather, surface query, tracker, the
 * law on the contact block (rs_cblock_inputs, rs_cblock_call), the loads onto the
 * particles (rs_cblock_add_loads); for the built-in hertz law's usual block, the tracker,
 * the law and the loads in one pass (rs_track_hertz). */
#include "fix_wall_rigid.h"
#include "rigidsurf/track_hertz.h"
#include "rigidsurf/vec.h"

#include "atom.h"
#include "error.h"
#include "fix_property_atom.h"
#include "fix_property_global.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>

using namespace LAMMPS_NS;

void FixWallRigid::process_block(const int *idx, int n, bool setup_call)
{
    double **x = atom->x, **v = atom->v, **omega = atom->omega;
    const double *radius = atom->radius, *rmass = atom->rmass;
    const int *tag = atom->tag, *type = atom->type;
    const int nd = ndir_, ns = nstatev_, as = atom_size();
    const double dt = update->dt;
    rs_error err;
    rs_error_clear(&err);

    /* Gather; the extremes of R and m tell whether the block is monodisperse. */
    double *__restrict qx = bx_.data(), *__restrict qy = by_.data(),
                       *__restrict qz = bz_.data();
    double *__restrict qvx = bvx_.data(), *__restrict qvy = bvy_.data(),
                       *__restrict qvz = bvz_.data();
    double *__restrict qwx = bwx_.data(), *__restrict qwy = bwy_.data(),
                       *__restrict qwz = bwz_.data();
    double *__restrict qr = brad_.data();
    int *__restrict qid = bid_.data();
    double **__restrict qd = bdir_.data();
    double **__restrict qh = bhist_.data();
    double *__restrict qm = bmass_.data();
    int *__restrict qt = btype_.data();
    /* The members the loop reads, as locals: its stores through double * could alias
     * them, so the compiler would load them again for every particle. */
    double *const *__restrict dirs = row_;
    double *const hist = hist_;
    const size_t ss = (size_t)slot_size();
    /* the values of a slot the tracker's run gathers: n, t1, then slip and rdisp1 or the
     * law's first values (track_run.h) */
    const size_t head = std::min(ss, (size_t)9);
    double *const *__restrict out_rows = array_atom;
    double rmax = radius[idx[0]];
    for (int k = 0; k < n; k++) {
        const int i = idx[k];
        const double *xi = x[i], *vi = v[i], *wi = omega[i];
        const double R = radius[i], m = rmass[i];
        qx[k] = xi[0], qy[k] = xi[1], qz[k] = xi[2];
        qvx[k] = vi[0], qvy[k] = vi[1], qvz[k] = vi[2];
        qwx[k] = wi[0], qwy[k] = wi[1], qwz[k] = wi[2];
        qr[k] = R;
        qm[k] = m;
        qt[k] = type[i];
        qid[k] = tag[i];
        double *const d = dirs[i], *const h = hist + (size_t)i * ss;
        qd[k] = d;
        qh[k] = h;
        rmax = std::max(rmax, R);
        /* asked for now, read after the query: the directory and the slot's head (its
         * first line and the line of its last value the tracker gathers) by the tracker,
         * the output row by the loads */
        __builtin_prefetch(d, 0, 3);
        __builtin_prefetch(h, 0, 3);
        __builtin_prefetch(h + head - 1, 0, 3);
        if (out_rows)
            __builtin_prefetch(out_rows[i], 1, 3);
    }
    if (setup_call) {
        saved_rows_.resize((size_t)n * as);
        for (int k = 0; k < n; k++)
            pack_atom(idx[k], &saved_rows_[(size_t)k * as]);
    }

    /* The block as the query, the tracker and the law's inputs read it. LIGGGHTS 3.8.0's
     * particles are spheres: no bodies. */
    rs_particle_block &p = pblk_;
    p = rs_particle_block();
    p.n = n;
    p.x = qx, p.y = qy, p.z = qz;
    p.vx = qvx, p.vy = qvy, p.vz = qvz;
    p.wx = qwx, p.wy = qwy, p.wz = qwz;
    p.radius = qr;
    p.id = qid;
    p.dir = qd;
    p.hist = qh;
    p.slot_stride = slot_stride();
    p.mass = qm;
    p.type = qt;

    rs_query q = rs_query();
    q.n = n;
    q.slave = p;
    q.pose = &motion_.pose;
    q.gap_max = tracking_ + lookahead_;
    /* With bounds, the depth limit is that of the largest candidate plus the look-ahead:
     * a particle deeper than that could not become a contact in any block before it
     * moves by the look-ahead. */
    q.dist_min = bounds_ok_ ? -(std::max(rmax, rglob_) + lookahead_) : -rmax;
    contacts_.n = 0;
    const int *const *cand = NULL;
    const int *ncand = NULL;
    if (rs_surface_has_candidates(&surf_)) { /* the lists of the last refresh */
        bcand_.resize(n);
        bncand_.resize(n);
        for (int k = 0; k < n; k++) {
            bcand_[k] = cids_.data() + cfirst_[idx[k]];
            bncand_[k] = cnum_[idx[k]];
        }
        cand = bcand_.data();
        ncand = bncand_.data();
    }
    if (rs_surface_query_among(&surf_, &q, cand, ncand, &contacts_, &err) != RS_OK)
        fail_one(std::string("surface query: ") + err.msg);
    if (bounds_ok_)
        keep_tracked(idx, n, -rmax);

    /* A setup call has no increment: no slip, no master rotation. */
    rs_motion still;
    const rs_motion *mp = moving_ || belt_ ? &motion_ : NULL;
    if (setup_call && moving_) {
        still = motion_;
        for (int a = 0; a < 9; a++)
            still.dQ[a] = (a % 4 == 0) ? 1.0 : 0.0;
        mp = &still;
    }
    /* The usual block of the built-in hertz law in one pass (rs_track_hertz), else the
     * tracker and the stages below. */
    int nprops1 = 0;
    const double *props1 = NULL;
    if (!(one_pass_ && !setup_call && block_props(type[idx[0]], &props1, &nprops1) &&
          nprops1 == law_->nprops))
        props1 = NULL;
    int done = 0, rc;
    rs_wall_load wl1;
    if (props1) {
        double origin[3];
        rs_pose_to_global(&motion_.pose, surf_.a, origin);
        const rs_load_rows rows = load_rows(idx, setup_call);
        rc = rs_track_hertz(&tracker_, &surf_, mp, dt, &p, &contacts_, &tout_, props1,
                            origin, &rows, array_atom, &wl1, &done, &err);
    } else {
        rc = rs_track_update(&tracker_, &surf_, mp, setup_call ? 0.0 : dt, &p, &contacts_,
                             &tout_, &err);
    }
    if (rc != RS_OK) {
        /* More contacts than slots: the tracker changed nothing, so the slots grow and
         * the block runs again (a sphere in a mesh's pocket holds one per face). */
        if (err.code == RS_ERR_CAPACITY) {
            if (grow_capacity(capacity_ + 1)) {
                process_block(idx, n, setup_call);
                return;
            }
            std::ostringstream o;
            o << err.msg << "; the slots cannot grow past " << max_capacity()
              << ", the most LIGGGHTS's atom exchange carries with " << nstatev_
              << " state variables";
            fail_one(o.str());
        }
        fail_one(err.msg);
    }
    if (done) {
        add_wall_load(wl1, setup_call);
        return;
    }

    const int ne = tout_.n;
    if (ne > cb_.cap) // not reached: at most capacity contacts per particle
        fail_one("internal: block has more contacts than its scratch");
    if (ne == 0) {
        for (int k = 0; array_atom && k < n; k++)
            for (int c = 0; c < 6; c++)
                array_atom[idx[k]][c] = 0.0;
        if (setup_call)
            for (int k = 0; k < n; k++)
                unpack_atom(idx[k], &saved_rows_[(size_t)k * as]);
        return;
    }
    /* Stress of the previous increment in this increment's basis (none for a law that
     * neither reads it nor leaves any unwritten), and the law state. */
    rs_track_load(&tracker_, &tout_, rs_law_stress_in(law_) ? cb_.stress : NULL,
                  ns ? cb_.statev : NULL);
    if (lig_) {
        liggghts_block(idx, n, ne, setup_call);
        if (conduction_)
            conduct(idx, ne, setup_call);
        if (facets_)
            facet_pass(idx, ne, setup_call);
        if (setup_call) {
            for (int k = 0; k < n; k++)
                unpack_atom(idx[k], &saved_rows_[(size_t)k * as]);
            /* LIGGGHTS's walls keep what the model writes into a contact's history in
             * the setup call of a run (shearupdate 0). Most models write nothing then;
             * rolling_friction luding adds its torque increment regardless. A contact
             * that existed before the call (its slot is still in the directory) keeps
             * the model's values, as on wall/gran. */
            if (ns)
                for (int e = 0; e < ne; e++)
                    if (!leaving_[e] && *tout_.dir[e] != RS_DIR_EMPTY &&
                        !RS_DIR_IS_LEAVING(*tout_.dir[e]))
                        std::memcpy(tout_.slot[e] + rs_track_statev_at(&tracker_),
                                    cb_.statev + (size_t)e * ns, sizeof(double) * ns);
            return;
        }
        rs_track_commit(&tracker_, &tout_, cb_.stress, ns ? cb_.statev : NULL);
        return;
    }
    law_inputs(idx, n, ne, setup_call);

    /* The law, in slices of at most RS_BLOCK contacts. */
    const double *Temp = fix_temp_ ? fix_temp_->vector_atom : NULL;
    int nprops = 0;
    const double *props = NULL;
    if (!block_props(type[idx[0]], &props, &nprops)) {
        std::ostringstream o;
        o << "law " << law_->name << ": no material properties for particle type "
          << type[idx[0]]
          << " (youngsModulus, poissonsRatio, coefficientRestitution, "
             "coefficientFriction must cover it)";
        fail_one(o.str());
    }
    /* The Abaqus step is the run (kstep_), the increment counts from 1 within it; the
     * setup call is increment 1 with no motion. Times are at the start of the increment:
     * the step time since the run began, the total time since step 0. */
    const double time_end = update->atime + (update->ntimestep - update->atimestep) * dt;
    const double t_start = setup_call ? time_end : time_end - dt;
    rs_law_block b = blk_;
    b.kStep = kstep_ > 0 ? kstep_ : 1;
    b.kInc = setup_call ? 1 : (int)(update->ntimestep - update->firststep);
    b.nProps = nprops;
    b.nTemp = (Temp || temp_given_) ? 1 : 0;
    b.timStep = t_start - run_time0_;
    b.timGlb = t_start;
    b.dTimCur = dt;
    b.props = nprops ? props : NULL;
    b.setup = setup_call ? 1 : 0;
    rs_law_requests req;
    rs_law_requests_clear(&req);
    b.requests = &req;
    if (rs_surface_has_facets(&surf_) && rs_law_takes_facets(law_) &&
        rs_cblock_facets(&cb_, &tout_, &surf_, &motion_.pose, &err) != RS_OK)
        fail_one(err.msg);
    if (rs_cblock_call(&cb_, law_, &b, &tout_, &err) != RS_OK)
        fail_one(err.msg);
    if (!setup_call && req.pnewdt_calls > 0) {
        if (pnewdt_stop_) {
            std::ostringstream o;
            o << "law '" << law_->name << "': the user routine asked for a smaller "
              << "increment (PNEWDT = " << req.pnewdt_min << ") at particle "
              << req.pnewdt_particle << ", feature " << req.pnewdt_feature << " on step "
              << update->ntimestep << ", which suggests a time step of "
              << dt * req.pnewdt_min
              << "; an explicit step cannot repeat an increment (keyword 'pnewdt stop')";
            fail_one(o.str());
        }
    }
    if (!setup_call)
        rs_law_requests_merge(&requests_, &req);

    /* Forces and torques onto LIGGGHTS's rows, the wall's totals, energies and heat, in
     * one pass (rs_cblock_add_loads); where contacts share a patch at a concave fold,
     * each applies w A (docs/conventions.md). */
    double origin[3];
    rs_pose_to_global(&motion_.pose, surf_.a, origin);
    rs_load_rows rows = load_rows(idx, setup_call);
    /* the deepest contact of each particle, for the per-atom output (ident_: contact k is
     * particle k's) */
    rows.deepest = ident_ || !array_atom ? NULL : deepest_.data();
    rs_wall_load wl;
    rs_cblock_add_loads(&cb_, &tout_, &pblk_, origin, &rows, &wl);
    add_wall_load(wl, setup_call);
    /* Per-atom output: the deepest live contact of each particle with this wall, zeros
     * for a particle without one. */
    if (array_atom && ident_)
        put_outputs(idx, n, nd, NULL, leaving_.data());
    else if (array_atom)
        put_outputs(idx, n, nd, deepest_.data(), NULL);

    /* the facets' loads take each contact's area times its share */
    load_area_ = cb_.area;
    if (facets_ && tout_.shared) {
        if (area_w_.size() < (size_t)ne)
            area_w_.resize((size_t)ne);
        for (int e = 0; e < ne; e++)
            area_w_[e] = cb_.area[e] * tout_.share[e];
        load_area_ = area_w_.data();
    }
    if (conduction_)
        conduct(idx, ne, setup_call);
    if (facets_)
        facet_pass(idx, ne, setup_call);

    if (setup_call) {
        for (int k = 0; k < n; k++)
            unpack_atom(idx[k], &saved_rows_[(size_t)k * as]);
        return;
    }
    rs_track_commit_energy(&tracker_, &tout_, cb_.sed, cb_.flux_slv, cb_.flux_mst);
    rs_track_commit(&tracker_, &tout_, cb_.stress, ns ? cb_.statev : NULL);
}

void FixWallRigid::put_outputs(const int *idx, int n, int nd, const int *e,
                               const char *leaving)
{
    double *const *__restrict out = array_atom;
    const double *const stress = cb_.stress, *const rdisp = tout_.rdisp;
    if (e)
        for (int k = 0; k < n; k++)
            put_output(out[idx[k]], e[k], nd, stress, rdisp);
    else
        for (int k = 0; k < n; k++)
            put_output(out[idx[k]], leaving[k] ? -1 : k, nd, stress, rdisp);
}

/* The query looked ahead beyond the tracking thickness, and behind the surface to the
 * largest candidate's radius plus the look-ahead: each particle's smallest gap over the
 * features it found becomes its distance bound. The contacts beyond the thickness or deeper
 * than dist_min leave the list (kept in order), so the tracker sees what a query to the
 * thickness gives. */
void FixWallRigid::keep_tracked(const int *idx, int n, double dist_min)
{
    double *__restrict gmin = bgap_.data();
    const double *__restrict R = brad_.data();
    for (int k = 0; k < n; k++)
        gmin[k] = tracking_ + lookahead_;
    rs_contacts &c = contacts_;
    int m = 0;
    for (int e = 0; e < c.n; e++) {
        const int k = c.point[e];
        const double gap = c.dist[e] - R[k];
        gmin[k] = std::min(gmin[k], gap);
        if (!(c.dist[e] <= tracking_ + R[k]) || c.dist[e] < dist_min)
            continue; /* the query's own test with gap_max = tracking */
        if (m != e) {
            c.point[m] = c.point[e];
            c.feature[m] = c.feature[e];
            for (int d = 0; d < 3; d++) {
                c.xm[d][m] = c.xm[d][e];
                c.nrm[d][m] = c.nrm[d][e];
                c.t1[d][m] = c.t1[d][e];
                c.t2[d][m] = c.t2[d][e];
            }
            c.dist[m] = c.dist[e];
            c.curv[0][m] = c.curv[0][e];
            c.curv[1][m] = c.curv[1][e];
            c.share[m] = c.share[e];
        }
        m++;
    }
    c.n = m;
    update_bounds(idx, n, gmin);
}

/* The law's per-contact inputs (rs_cblock_inputs) from the block's particles, with their
 * heat capacities, temperatures and predefined fields; then each contact's sed from its
 * slot, the leaving flags (for the heat and the facets) and whether contact e is
 * particle e's, one each (ident_). */
void FixWallRigid::law_inputs(const int *idx, int n, int ne, bool setup_call)
{
    const double *cp = fix_heatcap_ ? fix_heatcap_->get_values() : NULL;
    double *const *__restrict bd = bdir_.data();
    rs_particle_block &p = pblk_; /* the block's, with its heat and predefined fields */
    if (cp) {
        for (int k = 0; k < n; k++)
            bheat_[k] = bmass_[k] * cp[btype_[k] - 1];
        p.heatcap = bheat_.data();
    }
    const double *Temp = fix_temp_ ? fix_temp_->vector_atom : NULL;
    if (Temp) {
        const int tp0 = tprev_offset();
        for (int k = 0; k < n; k++) {
            const int i = idx[k];
            const double Tp = bd[k][tp0];
            btemp_[k] = Temp[i];
            bdtemp_[k] = (setup_call || std::isnan(Tp)) ? 0.0 : Temp[i] - Tp;
        }
        p.temp = btemp_.data();
        p.dtemp = bdtemp_.data();
    }
    const int npred = (int)predef_names_.size();
    if (npred) {
        const int pd0 = pred_offset();
        for (int k = 0; k < n; k++) {
            const int i = idx[k];
            for (int a = 0; a < npred; a++) {
                const double val = predef_fix_[a]->vector_atom[i];
                const double prev = bd[k][pd0 + a];
                bpred_[(size_t)k * npred + a] = val;
                bdpred_[(size_t)k * npred + a] =
                    (setup_call || std::isnan(prev)) ? 0.0 : val - prev;
            }
        }
        p.pred = bpred_.data();
        p.dpred = bdpred_.data();
    }
    rs_cblock_inputs(&cb_, &tout_, &p, update->dt);

    /* sed, fluxSlv and fluxMst of the last increment, from the tracker's slot */
    rs_track_load_energy(&tracker_, &tout_, cb_.sed, cb_.flux_slv, cb_.flux_mst);
    const int *__restrict pt = tout_.point;
    double *const *__restrict dir = tout_.dir;
    char *__restrict leaving = leaving_.data();
    bool ident = ne == n;
    for (int e = 0; e < ne; e++) {
        leaving[e] = RS_DIR_IS_LEAVING(*dir[e]);
        ident &= pt[e] == e;
    }
    ident_ = ident;
}

/* The law's properties for a block of particle type t: the fix's, or type t's from
 * LIGGGHTS's material properties (false when they do not cover it). */
bool FixWallRigid::block_props(int t, const double **props, int *nprops) const
{
    if (!material_props()) {
        *props = props_.data();
        *nprops = (int)props_.size();
        return true;
    }
    if (t >= (int)type_props_.size() || type_props_[t].empty())
        return false;
    *props = type_props_[t].data();
    *nprops = (int)type_props_[t].size();
    return true;
}

/* LIGGGHTS's rows the loads add onto: force, torque, store_force's and the heat flow. */
rs_load_rows FixWallRigid::load_rows(const int *idx, bool setup_call) const
{
    rs_load_rows rows = rs_load_rows();
    rows.row = idx;
    rows.f = atom->f;
    rows.t = atom->torque;
    rows.fstore = wallforce_;
    rows.q = !setup_call && fix_heatflux_ ? fix_heatflux_->vector_atom : NULL;
    return rows;
}

/* A block's loads into the wall's totals. */
void FixWallRigid::add_wall_load(const rs_wall_load &wl, bool setup_call)
{
    for (int c = 0; c < 3; c++) {
        f_wall_[c] += wl.force[c];
        m_wall_[c] += wl.moment[c];
    }
    ncontact_ += wl.ncontact;
    se_now_ += wl.se;
    if (!setup_call) { /* a setup call's history is restored: it dissipates nothing */
        diss_[0] += wl.fd;
        diss_[1] += wl.pd;
        diss_[2] += wl.vd;
        diss_[3] += wl.cd;
        heat_step_ += wl.flux_mst;
    }
}
