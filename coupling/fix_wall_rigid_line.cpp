/* fix wall/rigid: a block on a revolved LINE (a cylinder's mantle, a cone) with the
 * built-in hertz law, in runs of spheres: each run gathered from LIGGGHTS's rows, its
 * face contacts computed per sphere (rs_line_revolution_faces) and the spheres that hold
 * just that contact passed to the one pass (rs_track_hertz_usual), so that no block-wide
 * column is written; the other spheres go through process_block afterwards. */
#include "fix_wall_rigid.h"
#include "rigidsurf/line_revolution.h"
#include "rigidsurf/track_hertz.h"

#include "atom.h"
#include "update.h"

#include <algorithm>
#include <cmath>

using namespace LAMMPS_NS;

void FixWallRigid::line_block(const int *idx, int n)
{
    const double *props = NULL;
    int nprops = 0;
    if (!block_props(atom->type[idx[0]], &props, &nprops) || nprops != law_->nprops ||
        !rs_track_hertz_takes(&tracker_, props)) {
        process_block(idx, n, false);
        return;
    }
    double **x = atom->x, **v = atom->v, **omega = atom->omega;
    const double *radius = atom->radius, *rmass = atom->rmass;
    const int *tag = atom->tag, *type = atom->type;
    const double dt = update->dt, gap_max = tracking_ + lookahead_;
    double origin[3];
    rs_pose_to_global(&motion_.pose, surf_.a, origin);
    const rs_motion *mp = moving_ || belt_ ? &motion_ : NULL;
    double *const *dirs = row_;
    const size_t ss = (size_t)slot_size();

    /* One run: the query's columns at every sphere, then the usual spheres' compacted
     * in place to the front (the one pass reads entries 0 .. nu-1). */
    enum { M = RS_TRACK_LINE_RUN };
    double px[M], py[M], pz[M], pvx[M], pvy[M], pvz[M], pwx[M], pwy[M], pwz[M], pr[M],
        pm[M];
    double *pd[M], *ph[M];
    int pid[M], pty[M], row[M], face[M];
    /* the frames, distances and features: what the one pass reads (no master points,
     * curvatures or shares: rs_line_revolution_faces leaves them out) */
    double cn[3][M], ct1[3][M], ct2[3][M], cd[M];
    int cpt[M], cft[M];
    rs_contacts c = rs_contacts();
    c.cap = M;
    for (int d = 0; d < 3; d++)
        c.nrm[d] = cn[d], c.t1[d] = ct1[d], c.t2[d] = ct2[d];
    c.dist = cd, c.point = cpt, c.feature = cft;
    rest_.clear();
    for (int b0 = 0; b0 < n; b0 += M) {
        const int m = std::min(n - b0, (int)M);
        for (int j = 0; j < m; j++) {
            const int i = idx[b0 + j];
            const double *xi = x[i], *vi = v[i], *wi = omega[i];
            px[j] = xi[0], py[j] = xi[1], pz[j] = xi[2];
            pvx[j] = vi[0], pvy[j] = vi[1], pvz[j] = vi[2];
            pwx[j] = wi[0], pwy[j] = wi[1], pwz[j] = wi[2];
            pr[j] = radius[i], pm[j] = rmass[i];
            pid[j] = tag[i], pty[j] = type[i];
            pd[j] = dirs[i], ph[j] = hist_ + (size_t)i * ss;
            row[j] = i;
        }
        rs_line_revolution_faces(&surf_, &motion_.pose, m, px, py, pz, pr, gap_max, &c,
                                 face);
        rs_frame_orient(surf_.ops->frame, &c, 0, m);
        /* Usual: the face contact within the tracking thickness (keep_tracked's test and
         * the tracker's), held in slot 0 and nothing else. */
        int nu = 0;
        for (int j = 0; j < m; j++) {
            const bool usual = face[j] && c.dist[j] <= tracking_ + pr[j] &&
                               !(c.dist[j] - pr[j] > tracker_.tracking) &&
                               rs_track_dir_usual(pd[j], capacity_, c.feature[j]);
            if (!usual) {
                rest_.push_back(row[j]);
                continue;
            }
            if (nu != j) {
                px[nu] = px[j], py[nu] = py[j], pz[nu] = pz[j];
                pvx[nu] = pvx[j], pvy[nu] = pvy[j], pvz[nu] = pvz[j];
                pwx[nu] = pwx[j], pwy[nu] = pwy[j], pwz[nu] = pwz[j];
                pr[nu] = pr[j], pm[nu] = pm[j], pid[nu] = pid[j], pty[nu] = pty[j];
                pd[nu] = pd[j], ph[nu] = ph[j], row[nu] = row[j];
                for (int d = 0; d < 3; d++)
                    cn[d][nu] = cn[d][j], ct1[d][nu] = ct1[d][j], ct2[d][nu] = ct2[d][j];
                cd[nu] = cd[j], cft[nu] = cft[j];
            }
            cpt[nu] = nu;
            nu++;
        }
        if (nu == 0)
            continue;
        c.n = nu;
        rs_particle_block p = rs_particle_block();
        p.n = nu;
        p.x = px, p.y = py, p.z = pz;
        p.vx = pvx, p.vy = pvy, p.vz = pvz;
        p.wx = pwx, p.wy = pwy, p.wz = pwz;
        p.radius = pr, p.mass = pm, p.id = pid, p.type = pty;
        p.dir = pd, p.hist = ph;
        p.slot_stride = slot_stride();
        const rs_load_rows rows = load_rows(row, false);
        rs_wall_load wl;
        rs_error err;
        rs_error_clear(&err);
        if (rs_track_hertz_usual(&tracker_, mp, dt, &p, &c, &tout_, props, origin, &rows,
                                 array_atom, &wl, &err) != RS_OK)
            fail_one(err.msg);
        add_wall_load(wl, false);
        if (bounds_ok_) /* each holds a contact within the tracking thickness */
            for (int j = 0; j < nu; j++) {
                /* written only when it changes: a held contact's line then stays clean */
                double &g = gapref_[row[j]];
                if (g != -INFINITY)
                    g = -INFINITY;
            }
    }
    /* The rest, in their order, in blocks as compute() forms them (one particle type). */
    for (size_t b0 = 0; b0 < rest_.size(); b0 += RS_BLOCK) {
        const int nb = (int)std::min(rest_.size() - b0, (size_t)RS_BLOCK);
        process_block(rest_.data() + b0, nb, false);
    }
}
