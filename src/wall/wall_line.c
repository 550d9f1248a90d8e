/* The wall's line path: the step's candidates on a revolved LINE (a cylinder's mantle, a
 * cone), or on a MESH whose faces have clear zones, with a law whose fused kernel takes
 * them or a force law with a model per contact, in runs of spheres of one type: the
 * spheres whose directory is usual (rs_wall.usual: one contact, in slot 0) gathered from
 * the engine's arrays, their face contacts computed (on the LINE,
 * rs_line_revolution_faces; on the MESH, rs_mesh_held_faces, from the face each holds,
 * where it lies in that face's clear zone) and those that still hold just that contact
 * passed to the kernel (rs_track_fused_usual) or to the force law's model contact by
 * contact (wall_force_line.c), so that no block-wide column is written, no directory row
 * read and no candidate list walked; the other spheres go through wall_blocks afterwards,
 * but those whose distance bound keeps them away. */
#include "wall_impl.h"

#include "faceted/mesh_held.h"
#include "line_revolution.h"
#include "rs_compiler.h"
#include "track_fused.h"

#include <math.h>
#include <string.h>

/* What a sphere's distance bound is tested with (wall_kept_away_at). */
typedef struct {
    const double *gapref, *xref, *x, *radius;
    double tracking;
} line_bounds;

/* The candidates idx[k] .. that are not usual, up to the first that is (returned; n if
 * none): each joins the rest (rest[*nrest]) unless its distance bound (kb, if any) keeps
 * it away. A loop of its own, with only its own values in registers: on a bouncing bed
 * most candidates pass through it alone. */
static RS_NOINLINE int line_unusual(const int *idx, int k, int n, const int *usual,
                                    const line_bounds *kb, int *rest, int *nrest)
{
    int nr = *nrest;
    if (kb) {
        const double *const gapref = kb->gapref, *const xref = kb->xref, *const x = kb->x,
                            *const radius = kb->radius;
        const double tracking = kb->tracking;
        const int *p = idx + k, *const end = idx + n;
        for (; p < end; p++) {
            const int i = *p;
            if (usual[i])
                break;
            if (!wall_kept_away_at(gapref, xref, tracking, x, radius, i))
                rest[nr++] = i;
        }
        k = (int)(p - idx);
    } else {
        for (; k < n && !usual[idx[k]]; k++)
            rest[nr++] = idx[k];
    }
    *nrest = nr;
    return k;
}

int wall_line_block(rs_wall *w, const rs_wall_block *b, const rs_wall_rows *rows,
                    const int *idx, int n, double dt, rs_error *err)
{
    if (b->still || b->body || n == 0)
        return wall_blocks(w, b, rows, idx, n, dt, 0, err);
    /* a run holds one particle type where the properties are per type */
    const int *const type = wall_material_props(w) ? b->type : NULL;
    int run_t = type ? type[idx[0]] : 1;
    const double *props = NULL;
    /* a force law's model takes any run (wall_force_line.c); a fused kernel the runs
     * whose type's properties it takes */
    const int force = w->line_force;
    /* the particles' velocities and ids: what a fused kernel's tracker reads, and the
     * force pass's for the per-particle rows' slip (wall_force_line.c) */
    const int kin = !force || rows->peratom;
    int run_ok = force || wall_fused_props(w, run_t, &props);
    const double *x = b->x, *v = b->v, *om = b->omega;
    const double *radius = b->radius, *rmass = b->mass;
    const int *tag = b->id;
    const double gap_max = w->tracking + w->lookahead;
    double origin[3];
    rs_pose_to_global(&w->motion->pose, w->surf->a, origin);
    const rs_motion *mp = w->moving || w->belt ? w->motion : NULL;
    const size_t ss = (size_t)wall_slot_size(w);
    double *const hist = w->hist;

    /* One run: the query's columns at every sphere, then those of the spheres still usual
     * compacted in place to the front (the kernel reads entries 0 .. nu-1). */
    enum { M = RS_TRACK_LINE_RUN };
    double px[M], py[M], pz[M], pvx[M], pvy[M], pvz[M], pwx[M], pwy[M], pwz[M], pr[M],
        pm[M];
    double *ph[M];
    int pid[M], row[M], face[M], held[M];
    /* the frames, distances and features: what the kernel reads (no master points,
     * curvatures or shares: rs_line_revolution_faces leaves them out); for a force law's
     * model also the master points and curvatures (and shares, which the faces give) */
    double cn[3][M], ct1[3][M], ct2[3][M], cd[M], cxm[3][M], ck[2][M], csh[M];
    int cpt[M], cft[M];
    rs_contacts c;
    memset(&c, 0, sizeof c);
    c.cap = M;
    for (int d = 0; d < 3; d++)
        c.nrm[d] = cn[d], c.t1[d] = ct1[d], c.t2[d] = ct2[d];
    c.dist = cd, c.point = cpt, c.feature = cft;
    if (force) {
        for (int d = 0; d < 3; d++)
            c.xm[d] = cxm[d];
        c.curv[0] = ck[0], c.curv[1] = ck[1], c.share = csh;
    }
    /* the rest, in the active list, which the line path leaves unused (its capacity is
     * the candidates'): from the front those that were not usual, in the candidates'
     * order; from the back those that were but whose face contact the run could not give
     * (a mesh's sphere outside its face's zone), which go first, in blocks of their own
     * that the law's fused kernel can take whole */
    int *const rest = w->active;
    int nrest = 0, nheld = 0;
    const int *const usual = w->usual;
    const line_bounds kb = {w->gapref, w->xref, x, radius, w->tracking};
    const int bounds = w->bounds_ok || w->list_bounds;
    double live[M];
    double *pl[M];
    double lineF[12] = {0.0}; /* a revolved LINE's frame under the step's pose */
    if (!w->line_mesh)
        rs_line_revolution_frame(w->surf, &w->motion->pose, lineF);
    int next = 0;
    while (next < n) {
        /* The next run: particles of one type whose directory is usual (their one contact
         * in slot 0, which the kernel takes if it is still the face's); the others join
         * the rest, but those whose distance bound keeps them away. */
        int m = 0;
        for (; next < n; next++) {
            int i = idx[next];
            if (!usual[i]) {
                next = line_unusual(idx, next, n, usual, bounds ? &kb : NULL, rest, &nrest);
                if (next == n)
                    break;
                i = idx[next];
            }
            if (type && type[i] != run_t) {
                if (m > 0)
                    break;
                run_t = type[i];
                run_ok = force || wall_fused_props(w, run_t, &props);
            }
            if (!run_ok) {
                rest[nrest++] = i;
                continue;
            }
            /* the run's sphere m, gathered as it joins */
            const double *xi = x + 3 * (size_t)i;
            px[m] = xi[0], py[m] = xi[1], pz[m] = xi[2];
            pr[m] = radius[i], pm[m] = rmass[i];
            ph[m] = hist + (size_t)i * ss;
            row[m] = i;
            if (++m == M) {
                next++;
                break;
            }
        }
        if (m == 0)
            continue;
        if (kin) {
            for (int j = 0; j < m; j++) {
                const int i = row[j];
                const double *vi = v + 3 * (size_t)i;
                pvx[j] = vi[0], pvy[j] = vi[1], pvz[j] = vi[2];
                pid[j] = tag ? tag[i] : i + 1;
            }
            if (om)
                for (int j = 0; j < m; j++) {
                    const double *wi = om + 3 * (size_t)row[j];
                    pwx[j] = wi[0], pwy[j] = wi[1], pwz[j] = wi[2];
                }
            else
                for (int j = 0; j < m; j++)
                    pwx[j] = pwy[j] = pwz[j] = 0.0;
        }
        if (w->line_mesh) {
            /* the face each holds; the depth limit of any block's query (wall_block.c) */
            double rmax = w->rglob;
            for (int j = 0; j < m; j++) {
                held[j] = usual[row[j]] - 1;
                rmax = rmax > pr[j] ? rmax : pr[j];
            }
            rs_mesh_held_balls(w->surf, &w->motion->pose, m, px, py, pz, pr, held, gap_max,
                               -rmax, w->hball, row, &c, face);
        } else {
            rs_line_revolution_faces_in(w->surf, lineF, m, px, py, pz, pr, gap_max, &c,
                                        face);
        }
        rs_frame_orient(w->surf->ops->frame, &c, 0, m);
        /* Usual still: the face contact within the tracking thickness (keep_tracked's
         * test and the tracker's), the feature the directory holds. A one-sided LINE's
         * face takes only centres in front of it (rs_line_face1), so a sphere behind it
         * goes to the rest, where behind none leaves it alone (keep_tracked). */
        int nu = 0;
        const double wall_tracking = w->tracking, track_tracking = w->tracker.tracking;
        for (int j = 0; j < m; j++) {
            /* every test made (no branch between them): rows and features are valid */
            const int still_usual = (face[j] != 0) & (c.dist[j] <= wall_tracking + pr[j]) &
                                    !(c.dist[j] - pr[j] > track_tracking) &
                                    (usual[row[j]] == c.feature[j] + 1);
            if (!still_usual) {
                rest[n - 1 - nheld++] = row[j];
                continue;
            }
            if (nu != j) {
                px[nu] = px[j], py[nu] = py[j], pz[nu] = pz[j];
                if (kin) {
                    pvx[nu] = pvx[j], pvy[nu] = pvy[j], pvz[nu] = pvz[j];
                    pwx[nu] = pwx[j], pwy[nu] = pwy[j], pwz[nu] = pwz[j];
                    pid[nu] = pid[j];
                }
                pr[nu] = pr[j], pm[nu] = pm[j];
                ph[nu] = ph[j], row[nu] = row[j];
                for (int d = 0; d < 3; d++)
                    cn[d][nu] = cn[d][j], ct1[d][nu] = ct1[d][j], ct2[d][nu] = ct2[d][j];
                cd[nu] = cd[j], cft[nu] = cft[j];
                if (force) {
                    for (int d = 0; d < 3; d++)
                        cxm[d][nu] = cxm[d][j];
                    ck[0][nu] = ck[0][j], ck[1][nu] = ck[1][j], csh[nu] = csh[j];
                }
            }
            /* the directory entry the kernel reads: the one the row holds */
            live[nu] = RS_DIR_LIVE(cft[nu]);
            pl[nu] = &live[nu];
            cpt[nu] = nu;
            nu++;
        }
        if (nu == 0)
            continue;
        c.n = nu;
        rs_particle_block p;
        memset(&p, 0, sizeof p);
        p.n = nu;
        p.x = px, p.y = py, p.z = pz;
        p.vx = pvx, p.vy = pvy, p.vz = pvz;
        p.wx = pwx, p.wy = pwy, p.wz = pwz;
        p.radius = pr, p.mass = pm, p.id = pid, p.row = row;
        p.dir = pl, p.hist = ph;
        p.slot_stride = wall_slot_stride(w);
        rs_load_rows lr = wall_load_rows(w, rows, row, 0);
        lr.out6 = rows->peratom;
        rs_wall_load wl;
        const int rc =
            force ? wall_force_line_run(w, b, mp, dt, &p, &c, origin, &lr, &wl, err)
                  : rs_track_fused_usual(&w->tracker, w->law, mp, dt, &p, &c, &w->tout,
                                         props, origin, &lr, &wl, err);
        if (rc)
            return rc;
        wall_add_load(w, &wl, 0);
    }
    /* The rest through wall_blocks (one particle type, at most bcap each): first those
     * that held one contact, then the others, in their order. */
    const int rc = wall_blocks(w, b, rows, rest + n - nheld, nheld, dt, 0, err);
    return rc ? rc : wall_blocks(w, b, rows, rest, nrest, dt, 0, err);
}
