/* The wall's candidates. On the engine's reneighbouring, or when the wall moved half a
 * skin (wall_moved_beyond_skin), the particles within tracking + skin of the surface
 * (wall_build_candidates); for a kind with candidate lists, each one's triangles within
 * the step's reach plus a margin (build_candidate_lists); on a wall that stays in place,
 * each one's distance bound (wall_update_bounds), by which the step skips those that stay
 * beyond the tracking thickness. Particles behind a one-sided surface are counted on the
 * way (wall_sides.c). */
#include "wall_impl.h"

#include "faceted/mesh_held.h"

#include "rigidsurf/vec.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The largest distance from c to a corner of the domain: how far a point of it lies from
 * c at most. */
static double box_reach(const rs_wall *w, const double c[3])
{
    double rmax2 = 0.0;
    const double *lo = w->run.box_lo, *hi = w->run.box_hi;
    for (int k = 0; k < 8; k++) {
        const double p[3] = {(k & 1) ? hi[0] : lo[0], (k & 2) ? hi[1] : lo[1],
                             (k & 4) ? hi[2] : lo[2]};
        double r2 = 0.0;
        for (int d = 0; d < 3; d++)
            r2 += (p[d] - c[d]) * (p[d] - c[d]);
        rmax2 = fmax(rmax2, r2);
    }
    return sqrt(rmax2);
}

/* The wall may have moved since the candidates were chosen: every point of the domain
 * moved by at most |dD| + |dphi| * (largest distance of a domain corner from the rotation
 * centre). Beyond half the skin the list is refreshed, as the engine reneighbours when a
 * particle moved half the skin. */
int wall_moved_beyond_skin(const rs_wall *w)
{
    if (!w->moving)
        return 0;
    const rs_motion *m = w->motion;
    double dd = 0.0;
    for (int d = 0; d < 3; d++)
        dd += (m->disp[d] - w->disp_at_build[d]) * (m->disp[d] - w->disp_at_build[d]);
    double bound = sqrt(dd);
    const double dphi = fabs(m->phi - w->phi_at_build);
    if (dphi > 0.0 && !w->spin_invariant) {
        /* a material point at x moved by (R' R^T - I)(x - C - D) besides D' - D, for
         * either centre (motion.h) */
        double c[3];
        for (int d = 0; d < 3; d++)
            c[d] = m->center0[d] + m->disp[d];
        bound += dphi * box_reach(w, c);
    }
    const double dspin = fabs(m->spin_phi - w->spin_at_build);
    if (m->spin_on && (dspin > 0.0 || dphi > 0.0)) {
        /* x = P + S (X - P0): P moved as a point of the motion without the spin, by at
         * most |D' - D| + dphi |P - C - D|, and x - P turned by at most dphi + dspin */
        double P[3], pc2 = 0.0;
        rs_pose_to_global(&m->pose, m->spin_point0, P);
        for (int d = 0; d < 3; d++) {
            const double r = P[d] - m->center0[d] - m->disp[d];
            pc2 += r * r;
        }
        bound = sqrt(dd) + dphi * sqrt(pc2) + (dphi + dspin) * box_reach(w, P);
    }
    return bound > 0.5 * w->run.skin;
}

/* A query of particles idx[0 .. n) as spheres, gathered into the block scratch, against
 * the wall in its current pose; the caller sets gap_max and dist_min. */
static rs_query sphere_query(rs_wall *w, const rs_wall_block *b, const int *idx, int n)
{
    for (int k = 0; k < n; k++) {
        const double *xi = b->x + 3 * (size_t)idx[k];
        w->bx[k] = xi[0];
        w->by[k] = xi[1];
        w->bz[k] = xi[2];
        w->brad[k] = b->radius[idx[k]];
    }
    rs_query q;
    memset(&q, 0, sizeof q);
    q.n = n;
    q.slave.n = n;
    q.slave.x = w->bx;
    q.slave.y = w->by;
    q.slave.z = w->bz;
    q.slave.radius = w->brad;
    q.pose = &w->motion->pose;
    return q;
}

static int push_cand(rs_wall *w, int i, rs_error *err)
{
    if (w->ncand == w->cand_cap) {
        const int cap = w->cand_cap ? 2 * w->cand_cap : 1024;
        int *c = realloc(w->cand, (size_t)cap * sizeof *c);
        int *a = realloc(w->active, (size_t)cap * sizeof *a);
        if (c)
            w->cand = c;
        if (a)
            w->active = a;
        if (!c || !a)
            return rs_error_set(err, RS_ERR_NOMEM, "out of memory for %d candidates", cap);
        w->cand_cap = cap;
    }
    w->cand[w->ncand++] = i;
    return RS_OK;
}

/* A block of particles idx[0 .. n) of the group: those within tracking + skin, and every
 * one that still holds a contact (it must see its contact leave), join the candidates;
 * with behind none, also those within tracking + skin behind a one-sided surface's back
 * side, which may come through to its front before the next refresh. */
static int flush(rs_wall *w, const rs_wall_block *b, int n, int look_behind, rs_error *err)
{
    if (n == 0)
        return RS_OK;
    double rmax = 0.0;
    for (int k = 0; k < n; k++) {
        const int i = w->bidx[k];
        rmax = rmax < b->radius[i] ? b->radius[i] : rmax;
        const double *d = wall_row(w, i);
        char held = 0;
        for (int j = 0; j < w->capacity; j++)
            held |= d[j] != RS_DIR_EMPTY;
        w->take[k] = held;
    }
    rs_query q = sphere_query(w, b, w->bidx, n);
    q.gap_max = w->tracking + w->run.skin;
    q.dist_min = look_behind || wall_front_only(w) ? -(rmax + q.gap_max) : -rmax;
    w->contacts.n = 0;
    int rc = rs_surface_query(w->surf, &q, &w->contacts, err);
    if (rc) {
        char msg[sizeof err->msg];
        snprintf(msg, sizeof msg, "%s", err->msg);
        return rs_error_set(err, rc, "surface query: %s", msg);
    }
    if (look_behind)
        wall_sort_behind(w, n, -rmax);
    else
        for (int c = 0; c < w->contacts.n; c++)
            w->take[w->contacts.point[c]] = 1;
    for (int k = 0; k < n; k++)
        if (w->take[k] && (rc = push_cand(w, w->bidx[k], err)))
            return rc;
    return RS_OK;
}

/* Each candidate's list of surface candidates within the step's reach (the tracking
 * thickness and look-ahead, down to the deepest penetration a step asks for) grown by a
 * margin, what particle and wall may move before the next refresh. The refresh comes
 * before the wall has moved half a skin. Where the engine builds its lists as soon as a
 * particle has moved half a skin (rs_wall_run.half_skin), a wall that stays in place needs
 * half a skin; otherwise the margin is the skin. */
static int build_candidate_lists(rs_wall *w, const rs_wall_block *b, rs_error *err)
{
    const int half = !w->moving && w->run.half_skin;
    const double margin = half ? 0.5 * w->run.skin : w->run.skin;
    const int nlocal = b->n;
    int *f = realloc(w->cfirst, (size_t)(nlocal > 0 ? nlocal : 1) * sizeof *f);
    if (f)
        w->cfirst = f;
    int *u = realloc(w->cnum, (size_t)(nlocal > 0 ? nlocal : 1) * sizeof *u);
    if (u)
        w->cnum = u;
    if (!f || !u)
        return rs_error_set(err, RS_ERR_NOMEM, "out of memory for the candidate lists");
    w->ncids = 0;
    const int nc = w->ncand;
    for (int b0 = 0; b0 < nc; b0 += w->bcap) {
        const int n = nc - b0 < w->bcap ? nc - b0 : w->bcap;
        rs_query q = sphere_query(w, b, w->cand + b0, n);
        q.gap_max = w->tracking + w->lookahead;
        q.dist_min = -(w->rglob + w->lookahead);
        int rc = rs_surface_candidates(w->surf, &q, margin, &w->cands, err);
        if (rc) {
            char msg[sizeof err->msg];
            snprintf(msg, sizeof msg, "%s", err->msg);
            return rs_error_set(err, rc, "surface candidates: %s", msg);
        }
        const int add = w->cands.off[n];
        if (w->ncids + add > w->cids_cap) {
            int cap = w->cids_cap ? w->cids_cap : 4096;
            while (cap < w->ncids + add)
                cap *= 2;
            int *ids = realloc(w->cids, (size_t)cap * sizeof *ids);
            if (!ids)
                return rs_error_set(err, RS_ERR_NOMEM,
                                    "out of memory for the candidate lists");
            w->cids = ids;
            w->cids_cap = cap;
        }
        const int base = w->ncids;
        memcpy(w->cids + base, w->cands.ids, (size_t)add * sizeof *w->cids);
        w->ncids += add;
        for (int k = 0; k < n; k++) {
            const int i = w->cand[b0 + k];
            w->cfirst[i] = base + w->cands.off[k];
            w->cnum[i] = w->cands.off[k + 1] - w->cands.off[k];
        }
        if (w->list_bounds) { /* each one's smallest gap: the nearest candidate's */
            double *g = w->bgap;
            for (int k = 0; k < n; k++)
                g[k] = w->cands.near[k] - w->brad[k];
            wall_update_bounds(w, b, w->cand + b0, n, g);
        }
    }
    return RS_OK;
}

/* Stable sort of the candidates by particle type (the blocks of per-type properties). */
static void sort_by_type(rs_wall *w, const int *type)
{
    int *a = w->cand, *tmp = w->active;
    const int n = w->ncand;
    for (int width = 1; width < n; width *= 2) {
        for (int lo = 0; lo < n; lo += 2 * width) {
            const int mid = lo + width < n ? lo + width : n;
            const int hi = lo + 2 * width < n ? lo + 2 * width : n;
            int i = lo, j = mid, k = lo;
            while (i < mid && j < hi)
                tmp[k++] = type[a[j]] < type[a[i]] ? a[j++] : a[i++];
            while (i < mid)
                tmp[k++] = a[i++];
            while (j < hi)
                tmp[k++] = a[j++];
        }
        int *t = a;
        a = tmp;
        tmp = t;
    }
    if (a != w->cand)
        memcpy(w->cand, a, (size_t)n * sizeof *a);
}

/* Candidates: particles of the group whose gap to the surface is within tracking + skin,
 * and every particle that still holds a contact (it must see its contact leave). */
int wall_build_candidates(rs_wall *w, const rs_wall_block *b, rs_error *err)
{
    w->ncand = 0;
    /* On a one-sided wall the query also reaches behind it, as far as in front. */
    const int look_behind = wall_looks_behind(w);
    int n = 0, rc;
    for (int i = 0; i < b->n; i++) {
        if (!wall_in_group(b, i))
            continue;
        w->bidx[n++] = i;
        if (n == w->bcap) {
            if ((rc = flush(w, b, n, look_behind, err)))
                return rc;
            n = 0;
        }
    }
    if ((rc = flush(w, b, n, look_behind, err)))
        return rc;
    if (wall_material_props(w) && b->type)
        sort_by_type(w, b->type);
    const rs_motion *m = w->motion;
    for (int d = 0; d < 3; d++)
        w->disp_at_build[d] = m->disp[d];
    w->phi_at_build = m->phi;
    w->spin_at_build = m->spin_phi;
    w->rebuild = 0;
    double rglob = 0.0;
    for (int c = 0; c < w->ncand; c++)
        rglob = rglob < b->radius[w->cand[c]] ? b->radius[w->cand[c]] : rglob;
    w->rglob = rglob;
    /* No bound yet: every candidate is queried on its next step. */
    if (w->nref < b->n) {
        const int nr = b->n;
        double *g = realloc(w->gapref, (size_t)nr * sizeof *g);
        if (g)
            w->gapref = g;
        double *x = realloc(w->xref, 4 * (size_t)nr * sizeof *x);
        if (x)
            w->xref = x;
        rs_mesh_held_ball *hb = w->hball;
        const int hb0 = hb ? w->nref : 0; /* the balls' rows defined before */
        if (w->line_mesh && (hb = realloc(w->hball, (size_t)nr * sizeof *hb)))
            w->hball = hb;
        if (!g || !x || (w->line_mesh && !hb))
            return rs_error_set(err, RS_ERR_NOMEM, "out of memory for the distance bounds");
        /* defined from the start: the bound's test may read a reference position before
         * its room (wall_kept_away_at), whose result does not depend on it then */
        memset(w->xref + 4 * (size_t)w->nref, 0, 4 * (size_t)(nr - w->nref) * sizeof *x);
        /* no ball yet (a ball is true of the mesh alone: those of particles since
         * renumbered stay) */
        for (int i = hb0; w->line_mesh && i < nr; i++)
            w->hball[i].face = -1;
        w->nref = nr;
    }
    for (int i = 0; i < b->n; i++)
        w->gapref[i] = -INFINITY;
    if (rs_surface_has_candidates(w->surf))
        return build_candidate_lists(w, b, err);
    return RS_OK;
}

/* After a block's query: the bound of each particle without a contact within the
 * tracking thickness and without a contact in its history, its smallest gap (gmin, the
 * look-ahead where nothing is within it) at its position now. Every other particle gets
 * none (-inf), so the step's filter passes it without looking further: one with a contact
 * within the tracking thickness holds it; one that holds a contact from before (a
 * refresh's lists, a setup call, whose history is put back afterwards) must be queried to
 * see it leave. */
void wall_update_bounds(rs_wall *w, const rs_wall_block *b, const int *idx, int n,
                        const double *gmin)
{
    for (int k = 0; k < n; k++) {
        const int i = idx[k];
        int unheld = gmin[k] > w->tracking;
        const double *d = wall_row(w, i);
        for (int j = 0; unheld && j < w->capacity; j++)
            unheld = d[j] == RS_DIR_EMPTY;
        if (!unheld) {
            w->gapref[i] = -INFINITY;
            continue;
        }
        const double *xi = b->x + 3 * (size_t)i;
        w->gapref[i] = gmin[k] - 1e-9 * b->radius[i]; /* a margin for the gap's rounding */
        double *xr = &w->xref[4 * (size_t)i];
        xr[0] = xi[0];
        xr[1] = xi[1];
        xr[2] = xi[2];
        xr[3] = b->radius[i];
    }
}

/* After a rebuild query of points [0, n) of a block whose depth limit was widened to the
 * back side's reach: the candidates are those with a contact no deeper than dist_min, as
 * without the check; a point counts as behind when every contact it has lies behind the
 * surface (dist < 0: its centre is on the back side). */
void wall_sort_behind(rs_wall *w, int n, double dist_min)
{
    char *seen = w->leaving; /* per point: 1 near the surface, 2 in front of it */
    memset(seen, 0, (size_t)n);
    for (int c = 0; c < w->contacts.n; c++) {
        const int k = w->contacts.point[c];
        const double d = w->contacts.dist[c];
        seen[k] |= d >= 0.0 ? 3 : 1;
        if (d >= dist_min)
            w->take[k] = 1;
    }
    for (int k = 0; k < n; k++)
        w->behind += seen[k] == 1;
}

/* Over all ranks, after a rebuild: one warning, the first time particles are found behind
 * a one-sided surface. A one-sided surface holds particles only on the side its normal
 * points to (left of travel along a profile, the winding's side on an Abaqus part or a
 * mesh given SIDES=1); one that reaches it from behind is pushed through. Where that
 * happens a deck has most likely drawn its profile the other way. */
void wall_warn_behind(rs_wall *w)
{
    const double all = wall_reduce1(w, (double)w->behind, RS_REDUCE_SUM);
    w->behind = 0;
    if (!(all > 0.0))
        return;
    w->behind_warned = 1;
    wall_warn(
        w,
        "Fix wall/rigid %s: %lld particle(s) within reach of the back of the one-sided "
        "surface '%s', which holds particles only on the side its normal points to "
        "(left of the profile's travel, or the side a mesh's winding gives) and pushes "
        "those behind it through; reversing the profile (or the winding) or giving "
        "SIDES=2 (sides 2) would hold them",
        w->id, (long long)all, w->surf->name[0] ? w->surf->name : w->id);
}
