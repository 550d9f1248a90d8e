/* fix wall/rigid: its candidates. On reneighbouring, or when the wall moved half a skin
 * (wall_moved_beyond_skin), the particles within tracking + skin of the surface
 * (build_candidates); for a kind with candidate lists, each one's triangles within the
 * step's reach plus a margin (build_candidate_lists); on a wall that stays in place, each
 * one's distance bound (update_bounds), by which the step skips those that stay beyond
 * the tracking thickness. */
#include "fix_wall_rigid.h"

#include "atom.h"
#include "domain.h"
#include "neighbor.h"

#include <algorithm>
#include <cmath>
#include <string>

using namespace LAMMPS_NS;

/* The largest distance from c to a corner of the box: how far a point of the box lies
 * from c at most. */
double FixWallRigid::box_reach(const double c[3]) const
{
    double rmax2 = 0.0;
    for (int k = 0; k < 8; k++) {
        const double p[3] = {(k & 1) ? domain->boxhi[0] : domain->boxlo[0],
                             (k & 2) ? domain->boxhi[1] : domain->boxlo[1],
                             (k & 4) ? domain->boxhi[2] : domain->boxlo[2]};
        double r2 = 0.0;
        for (int d = 0; d < 3; d++)
            r2 += (p[d] - c[d]) * (p[d] - c[d]);
        rmax2 = std::max(rmax2, r2);
    }
    return std::sqrt(rmax2);
}

bool FixWallRigid::wall_moved_beyond_skin() const
{
    if (!moving_)
        return false;
    double dd = 0.0;
    for (int d = 0; d < 3; d++)
        dd += (motion_.disp[d] - disp_at_build_[d]) * (motion_.disp[d] - disp_at_build_[d]);
    double bound = std::sqrt(dd);
    const double dphi = std::fabs(motion_.phi - phi_at_build_);
    if (dphi > 0.0 && !spin_invariant_) {
        /* a material point at x moved by (R' R^T - I)(x - C - D) besides D' - D, for
         * either centre (motion.h) */
        double c[3];
        for (int d = 0; d < 3; d++)
            c[d] = motion_.center0[d] + motion_.disp[d];
        bound += dphi * box_reach(c);
    }
    const double dspin = std::fabs(motion_.spin_phi - spin_at_build_);
    if (motion_.spin_on && (dspin > 0.0 || dphi > 0.0)) {
        /* x = P + S (X - P0): P moved as a point of the motion without the spin, by at
         * most |D' - D| + dphi |P - C - D|, and x - P turned by at most dphi + dspin */
        double P[3], pc2 = 0.0;
        rs_pose_to_global(&motion_.pose, motion_.spin_point0, P);
        for (int d = 0; d < 3; d++) {
            const double r = P[d] - motion_.center0[d] - motion_.disp[d];
            pc2 += r * r;
        }
        bound = std::sqrt(dd) + dphi * std::sqrt(pc2) + (dphi + dspin) * box_reach(P);
    }
    return bound > 0.5 * neighbor->skin;
}

/* Candidates: group atoms whose gap to the surface is within tracking + skin, and every
 * atom that still holds a contact (it must see its contact leave). */
void FixWallRigid::build_candidates()
{
    cand_.clear();
    const int nlocal = atom->nlocal;
    const int *mask = atom->mask;
    const double *radius = atom->radius;
    rs_error err;
    rs_error_clear(&err);
    /* On a one-sided wall the query also reaches behind it, as far as in front. */
    const bool look_behind = looks_behind();

    int n = 0;
    auto flush = [&]() {
        if (n == 0)
            return;
        double rmax = 0.0;
        for (int k = 0; k < n; k++) {
            const int i = bidx_[k];
            rmax = std::max(rmax, radius[i]);
            char held = 0;
            for (int j = 0; j < capacity_; j++)
                held |= row_[i][j] != RS_DIR_EMPTY;
            take_[k] = held;
        }
        rs_query q = sphere_query(bidx_.data(), n);
        q.gap_max = tracking_ + neighbor->skin;
        q.dist_min = look_behind ? -(rmax + q.gap_max) : -rmax;
        contacts_.n = 0;
        if (rs_surface_query(&surf_, &q, &contacts_, &err) != RS_OK)
            fail_one(std::string("surface query: ") + err.msg);
        if (look_behind)
            sort_behind(n, -rmax);
        else
            for (int c = 0; c < contacts_.n; c++)
                take_[contacts_.point[c]] = 1;
        for (int k = 0; k < n; k++)
            if (take_[k])
                cand_.push_back(bidx_[k]);
        n = 0;
    };
    for (int i = 0; i < nlocal; i++) {
        if (!(mask[i] & groupbit))
            continue;
        bidx_[n++] = i;
        if (n == RS_BLOCK)
            flush();
    }
    flush();

    if (material_props()) {
        const int *type = atom->type;
        std::stable_sort(cand_.begin(), cand_.end(),
                         [type](int a, int b) { return type[a] < type[b]; });
    }
    for (int d = 0; d < 3; d++)
        disp_at_build_[d] = motion_.disp[d];
    phi_at_build_ = motion_.phi;
    spin_at_build_ = motion_.spin_phi;
    rebuild_ = false;
    rglob_ = 0.0;
    for (int i : cand_)
        rglob_ = std::max(rglob_, radius[i]);
    /* No bound yet: every candidate is queried on its next step. */
    if ((int)gapref_.size() < nlocal) {
        gapref_.resize(nlocal);
        xref_.resize(4 * (size_t)nlocal);
    }
    std::fill(gapref_.begin(), gapref_.begin() + nlocal, -INFINITY);
    if (rs_surface_has_candidates(&surf_))
        build_candidate_lists();
}

/* Each candidate's list of surface candidates within the step's reach (the tracking
 * thickness and look-ahead, down to the deepest penetration a step asks for) grown by
 * a margin, what particle and wall may move before the next refresh. The refresh comes
 * before the wall has moved half a skin. Where LIGGGHTS checks every step and builds as
 * soon as a particle has moved half a skin (neigh_modify delay 0 every 1 check yes once
 * no), a wall that stays in place needs half a skin; otherwise the margin is the skin. */
void FixWallRigid::build_candidate_lists()
{
    const int nlocal = atom->nlocal;
    const bool half_skin = !moving_ && neighbor->delay == 0 && neighbor->every == 1 &&
                           neighbor->dist_check && !neighbor->build_once;
    const double margin = half_skin ? 0.5 * neighbor->skin : neighbor->skin;
    cfirst_.resize(nlocal);
    cnum_.resize(nlocal);
    cids_.clear();
    rs_error err;
    rs_error_clear(&err);
    const int nc = (int)cand_.size();
    for (int b0 = 0; b0 < nc; b0 += RS_BLOCK) {
        const int n = std::min(nc - b0, (int)RS_BLOCK);
        rs_query q = sphere_query(cand_.data() + b0, n);
        q.gap_max = tracking_ + lookahead_;
        q.dist_min = -(rglob_ + lookahead_);
        if (rs_surface_candidates(&surf_, &q, margin, &cands_, &err) != RS_OK)
            fail_one(std::string("surface candidates: ") + err.msg);
        const size_t base = cids_.size();
        cids_.insert(cids_.end(), cands_.ids, cands_.ids + cands_.off[n]);
        for (int k = 0; k < n; k++) {
            const int i = cand_[b0 + k];
            cfirst_[i] = (int)base + cands_.off[k];
            cnum_[i] = cands_.off[k + 1] - cands_.off[k];
        }
        if (list_bounds_) { /* each one's smallest gap: the nearest candidate's */
            double *g = bgap_.data();
            for (int k = 0; k < n; k++)
                g[k] = cands_.near[k] - brad_[k];
            update_bounds(cand_.data() + b0, n, g);
        }
    }
}

/* After a block's query: the bound of each particle without a contact within the
 * tracking thickness and without a contact in its history, its smallest gap (gmin, the
 * look-ahead where nothing is within it) at its position now. Every other particle gets
 * none (-inf), so the step's filter (compute) passes it without looking further: one
 * with a contact within the tracking thickness holds it; one that holds a contact from
 * before (a refresh's lists, a setup call, whose history is put back afterwards) must be
 * queried to see it leave. */
void FixWallRigid::update_bounds(const int *idx, int n, const double *gmin)
{
    double **x = atom->x;
    const double *radius = atom->radius;
    for (int k = 0; k < n; k++) {
        const int i = idx[k];
        bool unheld = gmin[k] > tracking_;
        for (int j = 0; unheld && j < capacity_; j++)
            unheld = row_[i][j] == RS_DIR_EMPTY;
        if (!unheld) {
            gapref_[i] = -INFINITY;
            continue;
        }
        gapref_[i] = gmin[k] - 1e-9 * radius[i]; /* a margin for the rounding of the gap */
        double *xr = &xref_[4 * (size_t)i];
        xr[0] = x[i][0];
        xr[1] = x[i][1];
        xr[2] = x[i][2];
        xr[3] = radius[i];
    }
}
