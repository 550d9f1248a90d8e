/* One block of particles: gather, surface query, tracker, the law on the contact block
 * (rs_cblock_inputs, rs_cblock_call) and the loads onto the engine's rows
 * (rs_cblock_add_loads); where the law has a fused kernel and the block qualifies, the
 * tracker, the law and the loads in one pass (rs_track_fused). */
#include "wall_impl.h"

#include "track_fused.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The law's properties for a block of particle type t: the wall's, or type t's from the
 * engine's material properties (0 when they do not cover it). */
int wall_block_props(const rs_wall *w, int t, const double **props, int *nprops)
{
    if (!wall_material_props(w)) {
        *props = w->props;
        *nprops = w->nprops;
        return 1;
    }
    if (t < 0 || t >= w->ntype_props || !w->type_has[t])
        return 0;
    *props = w->type_props + (size_t)t * (size_t)w->tp_n;
    *nprops = w->tp_n;
    return 1;
}

/* The law's properties for particle type t, where the law's fused kernel takes them. */
int wall_fused_props(const rs_wall *w, int t, const double **props)
{
    int nprops = 0;
    return wall_block_props(w, t, props, &nprops) && nprops == w->law->nprops &&
           w->law->fused->takes(&w->tracker, *props, nprops);
}

/* The engine's rows the loads add onto: force, torque, the stored force and the heat
 * flow. */
rs_load_rows wall_load_rows(const rs_wall *w, const rs_wall_rows *rows, const int *idx,
                            int setup)
{
    (void)w;
    rs_load_rows r;
    memset(&r, 0, sizeof r);
    r.row = idx;
    r.f = rows->f;
    r.t = rows->torque;
    r.fstore = rows->fstore;
    r.q = !setup ? rows->heatflux : NULL;
    return r;
}

/* A per-particle output row: rdisp and stress of contact e (nd values each; the third 0
 * for nd = 2), zeros for e < 0 (no contact). */
static void put_output(double *restrict o, int e, int nd, const double *restrict stress,
                       const double *restrict rdisp)
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

/* put_output for each particle k of a block: its contact e[k] (e NULL: contact k, or none
 * where leaving[k]). */
static void put_outputs(rs_wall *w, double *out, const int *idx, int n, int nd,
                        const int *e, const char *leaving)
{
    const double *const stress = w->cb.stress, *const rdisp = w->tout.rdisp;
    if (e)
        for (int k = 0; k < n; k++)
            put_output(out + 6 * (size_t)idx[k], e[k], nd, stress, rdisp);
    else
        for (int k = 0; k < n; k++)
            put_output(out + 6 * (size_t)idx[k], leaving[k] ? -1 : k, nd, stress, rdisp);
}

/* With bounds, the query looked ahead beyond the tracking thickness, and behind the
 * surface to the largest candidate's radius plus the look-ahead: each particle's smallest
 * gap over the features it found becomes its distance bound. The contacts beyond the
 * thickness or deeper than dist_min leave the list (kept in order), so the tracker sees
 * what a query to the thickness gives; with behind none, so do those whose centre lies
 * behind a one-sided surface (dist < 0). */
static void keep_tracked(rs_wall *w, const rs_wall_block *b, const int *idx, int n,
                         double dist_min)
{
    double *restrict gmin = w->bgap;
    const double *restrict R = w->brad;
    const double tracking = w->tracking;
    const int bounds = w->bounds_ok, front = wall_front_only(w);
    if (bounds)
        for (int k = 0; k < n; k++)
            gmin[k] = tracking + w->lookahead;
    rs_contacts *c = &w->contacts;
    int m = 0;
    for (int e = 0; e < c->n; e++) {
        const int k = c->point[e];
        const double gap = c->dist[e] - R[k];
        if (bounds)
            gmin[k] = gap < gmin[k] ? gap : gmin[k];
        if (!(c->dist[e] <= tracking + R[k]) || c->dist[e] < dist_min ||
            (front && c->dist[e] < 0.0))
            continue; /* the query's own test with gap_max = tracking */
        if (m != e) {
            c->point[m] = c->point[e];
            c->feature[m] = c->feature[e];
            for (int d = 0; d < 3; d++) {
                c->xm[d][m] = c->xm[d][e];
                c->nrm[d][m] = c->nrm[d][e];
                c->t1[d][m] = c->t1[d][e];
                c->t2[d][m] = c->t2[d][e];
            }
            c->dist[m] = c->dist[e];
            c->curv[0][m] = c->curv[0][e];
            c->curv[1][m] = c->curv[1][e];
            c->share[m] = c->share[e];
        }
        m++;
    }
    c->n = m;
    if (bounds)
        wall_update_bounds(w, b, idx, n, gmin);
}

/* The law's per-contact inputs (rs_cblock_inputs) from the block's particles, with their
 * heat capacities, temperatures and predefined fields; then each contact's sed from its
 * slot, the leaving flags (for the heat and the facets) and whether contact e is particle
 * e's, one each (ident). */
static void law_inputs(rs_wall *w, const rs_wall_block *b, const int *idx, int n, int ne,
                       double dt, int setup)
{
    double *const *restrict bd = w->bdir;
    rs_particle_block *p = &w->pblk; /* the block's, with its heat and predefined fields */
    if (b->heatcap) {
        for (int k = 0; k < n; k++)
            w->bheat[k] = b->heatcap[idx[k]];
        p->heatcap = w->bheat;
    } else if (w->heatcap_type) {
        for (int k = 0; k < n; k++)
            w->bheat[k] = w->bmass[k] * w->heatcap_type[w->btype[k]];
        p->heatcap = w->bheat;
    }
    if (b->temp) {
        const int tp0 = wall_tprev_at(w);
        for (int k = 0; k < n; k++) {
            const int i = idx[k];
            const double Tp = bd[k][tp0];
            w->btemp[k] = b->temp[i];
            w->bdtemp[k] = (setup || isnan(Tp)) ? 0.0 : b->temp[i] - Tp;
        }
        p->temp = w->btemp;
        p->dtemp = w->bdtemp;
    }
    const int npred = w->npred;
    if (npred && b->pred) {
        const int pd0 = wall_pred_at(w);
        for (int k = 0; k < n; k++) {
            const int i = idx[k];
            for (int a = 0; a < npred; a++) {
                const double val = b->pred[a][i];
                const double prev = bd[k][pd0 + a];
                w->bpred[(size_t)k * npred + a] = val;
                w->bdpred[(size_t)k * npred + a] =
                    (setup || isnan(prev)) ? 0.0 : val - prev;
            }
        }
        p->pred = w->bpred;
        p->dpred = w->bdpred;
    }
    rs_cblock_inputs(&w->cb, &w->tout, p, dt);

    /* sed, fluxSlv and fluxMst of the last increment, from the tracker's slot */
    rs_track_load_energy(&w->tracker, &w->tout, w->cb.sed, w->cb.flux_slv, w->cb.flux_mst);
    const int *restrict pt = w->tout.point;
    double *const *restrict dir = w->tout.dir;
    char *restrict leaving = w->leaving;
    int ident = ne == n;
    for (int e = 0; e < ne; e++) {
        leaving[e] = RS_DIR_IS_LEAVING(*dir[e]);
        ident &= pt[e] == e;
    }
    w->ident = ident;
}

/* The particles idx[0 .. n) into the block's columns and the particle block the query,
 * the tracker and the law's inputs read; returns the block's largest radius. */
static double gather(rs_wall *w, const rs_wall_block *b, const rs_wall_rows *rows,
                     const int *idx, int n)
{
    const double *x = b->x, *v = b->v, *om = b->omega;
    const double *radius = b->radius, *rmass = b->mass;
    const int *tag = b->id, *type = b->type;
    double *restrict qx = w->bx, *restrict qy = w->by, *restrict qz = w->bz;
    double *restrict qvx = w->bvx, *restrict qvy = w->bvy, *restrict qvz = w->bvz;
    double *restrict qwx = w->bwx, *restrict qwy = w->bwy, *restrict qwz = w->bwz;
    double *restrict qr = w->brad, *restrict qm = w->bmass;
    int *restrict qid = w->bid, *restrict qt = w->btype;
    double **restrict qd = w->bdir, **restrict qh = w->bhist;
    double *const rowbase = w->rows;
    double *const hist = w->hist;
    const size_t rs = (size_t)wall_row_size(w), ss = (size_t)wall_slot_size(w);
    /* the values of a slot the tracker's run gathers: n, t1, then slip and rdisp1 or the
     * law's first values (track_run.h) */
    const size_t head = ss < 9 ? ss : 9;
    double *const out = rows->peratom;
    double rmax = radius[idx[0]];
    const int full = om && type && tag; /* the engines' case */
    for (int k = 0; k < n; k++) {
        const int i = idx[k];
        const double *xi = x + 3 * (size_t)i, *vi = v + 3 * (size_t)i;
        const double R = radius[i];
        qx[k] = xi[0], qy[k] = xi[1], qz[k] = xi[2];
        qvx[k] = vi[0], qvy[k] = vi[1], qvz[k] = vi[2];
        if (full) {
            const double *wi = om + 3 * (size_t)i;
            qwx[k] = wi[0], qwy[k] = wi[1], qwz[k] = wi[2];
            qt[k] = type[i];
            qid[k] = tag[i];
        } else {
            qwx[k] = om ? om[3 * (size_t)i] : 0.0;
            qwy[k] = om ? om[3 * (size_t)i + 1] : 0.0;
            qwz[k] = om ? om[3 * (size_t)i + 2] : 0.0;
            qt[k] = type ? type[i] : 1;
            qid[k] = tag ? tag[i] : i + 1;
        }
        qr[k] = R;
        qm[k] = rmass[i];
        double *const d = rowbase + (size_t)i * rs, *const h = hist + (size_t)i * ss;
        qd[k] = d;
        qh[k] = h;
        rmax = rmax > R ? rmax : R;
        /* asked for now, read after the query: the directory and the slot's head (its
         * first line and the line of its last value the tracker gathers) by the tracker,
         * the output row by the loads */
        __builtin_prefetch(d, 0, 3);
        __builtin_prefetch(h, 0, 3);
        __builtin_prefetch(h + head - 1, 0, 3);
        if (out)
            __builtin_prefetch(out + 6 * (size_t)i, 1, 3);
    }

    /* The block as the query, the tracker and the law's inputs read it. */
    rs_particle_block *p = &w->pblk;
    memset(p, 0, sizeof *p);
    p->n = n;
    p->x = qx, p->y = qy, p->z = qz;
    p->vx = qvx, p->vy = qvy, p->vz = qvz;
    p->wx = qwx, p->wy = qwy, p->wz = qwz;
    p->radius = qr;
    p->id = qid;
    p->dir = qd;
    p->hist = qh;
    p->slot_stride = wall_slot_stride(w);
    p->mass = qm;
    p->type = qt;
    p->row = idx;
    if (b->area) {
        for (int k = 0; k < n; k++)
            w->barea[k] = b->area[idx[k]];
        p->area = w->barea;
    }
    if (b->body) {
        int bodies = 0;
        for (int k = 0; k < n; k++) {
            w->bbody[k] = b->body[idx[k]];
            bodies |= w->bbody[k].shape != NULL;
        }
        if (bodies)
            p->body = w->bbody;
    }
    return rmax;
}

/* The query of the block: against the candidate lists of the last refresh on a kind that
 * keeps them; with bounds, looking ahead and keeping only what the tracker sees. */
static int query(rs_wall *w, const rs_wall_block *b, const int *idx, int n, double rmax,
                 rs_error *err)
{
    rs_query q;
    memset(&q, 0, sizeof q);
    q.n = n;
    q.slave = w->pblk;
    q.pose = &w->motion->pose;
    q.gap_max = w->tracking + w->lookahead;
    /* With bounds, the depth limit is that of the largest candidate plus the look-ahead:
     * a particle deeper than that could not become a contact in any block before it moves
     * by the look-ahead. A driver keeps contacts at any depth. */
    q.dist_min = w->run.every_particle ? -INFINITY
                 : w->bounds_ok ? -((rmax > w->rglob ? rmax : w->rglob) + w->lookahead)
                                : -rmax;
    w->contacts.n = 0;
    w->contacts.witness = w->pblk.body != NULL;
    const int *const *cand = NULL;
    const int *ncand = NULL;
    if (rs_surface_has_candidates(w->surf) && !w->run.every_particle) {
        /* each one's lists, and the feature it held last (slot 0's), whose own tests
         * may give its contact without the lists */
        for (int k = 0; k < n; k++) {
            w->bcand[k] = w->cids + w->cfirst[idx[k]];
            w->bncand[k] = w->cnum[idx[k]];
            const double d0 = w->bdir[k][0];
            w->bhint[k] = RS_DIR_IS_LIVE(d0) ? RS_DIR_FEATURE(d0) : RS_FEATURE_NONE;
        }
        cand = w->bcand;
        ncand = w->bncand;
        q.hint = w->bhint;
        q.near = w->list_bounds ? w->bgap : NULL;
    }
    const int rc = rs_surface_query_among(w->surf, &q, cand, ncand, &w->contacts, err);
    if (rc) {
        char msg[sizeof err->msg];
        snprintf(msg, sizeof msg, "%s", err->msg);
        return rs_error_set(err, rc, "surface query: %s", msg);
    }
    if (w->bounds_ok || w->behind_none)
        keep_tracked(w, b, idx, n, -rmax);
    if (!w->bounds_ok && q.near) { /* the lists' bounds, as at their refresh */
        for (int k = 0; k < n; k++)
            w->bgap[k] -= w->brad[k];
        wall_update_bounds(w, b, idx, n, w->bgap);
    }
    return RS_OK;
}

/* The law on the block's contacts, in slices of at most RS_BLOCK, with the engine's
 * scalars: the Abaqus step is the run (kstep), the increment counts from 1 within it; the
 * setup call is increment 1 with no motion. Times are at the start of the increment. */
static int call_law(rs_wall *w, const rs_wall_block *b, const int *idx, double dt,
                    int setup, rs_error *err)
{
    int nprops = 0;
    const double *props = NULL;
    if (!wall_block_props(w, w->btype[0], &props, &nprops))
        return rs_error_set(err, RS_ERR_ARG,
                            "law %s: no material properties for particle type %d "
                            "(youngsModulus, poissonsRatio, coefficientRestitution, "
                            "coefficientFriction must cover it)",
                            w->law->name, b->type ? b->type[idx[0]] : 1);
    const double t_start = b->time;
    rs_law_block lb = w->blk;
    lb.kStep = w->kstep > 0 ? w->kstep : 1;
    lb.kInc = setup ? 1 : b->inc;
    lb.nProps = nprops;
    lb.nTemp = (b->temp || w->temp_given) ? 1 : 0;
    lb.timStep = t_start - w->run_time0;
    lb.timGlb = t_start;
    lb.dTimCur = dt;
    lb.props = nprops ? props : NULL;
    lb.setup = setup ? 1 : 0;
    rs_law_requests req;
    rs_law_requests_clear(&req);
    lb.requests = w->warn ? NULL : &req;
    int rc;
    if (rs_surface_has_facets(w->surf) && rs_law_takes_facets(w->law) &&
        (rc = rs_cblock_facets(&w->cb, &w->tout, w->surf, &w->motion->pose, err)))
        return rc;
    if ((rc = rs_cblock_call(&w->cb, w->law, &lb, &w->tout, err)))
        return rc;
    if (!setup && req.pnewdt_calls > 0 && w->pnewdt_stop)
        return rs_error_set(err, RS_ERR_ARG,
                            "law '%s': the user routine asked for a smaller increment "
                            "(PNEWDT = %g) at particle %d, feature %d on step %lld, which "
                            "suggests a time step of %g; an explicit step cannot repeat an "
                            "increment (keyword 'pnewdt stop')",
                            w->law->name, req.pnewdt_min, req.pnewdt_particle,
                            req.pnewdt_feature, b->step, dt * req.pnewdt_min);
    if (!setup)
        rs_law_requests_merge(&w->requests, &req);
    return RS_OK;
}

/* The law's fused kernel on the block, where the wall and the block allow it: *done = 1
 * when it took the block, else the tracker's output is ready for the staged calls. */
static int tracker(rs_wall *w, const rs_wall_block *b, const rs_wall_rows *rows,
                   const int *idx, const rs_motion *mp, double dt, int setup, int *done,
                   rs_error *err)
{
    *done = 0;
    const double tdt = setup || b->still ? 0.0 : dt;
    const double *props = NULL;
    if (w->fused_ok && !setup && wall_fused_props(w, w->btype[0], &props)) {
        double origin[3];
        rs_pose_to_global(&w->motion->pose, w->surf->a, origin);
        rs_load_rows lr = wall_load_rows(w, rows, idx, setup);
        lr.out6 = rows->peratom;
        rs_wall_load wl;
        const int rc =
            rs_track_fused(&w->tracker, w->law, w->surf, mp, tdt, &w->pblk, &w->contacts,
                           &w->tout, props, origin, &lr, &wl, done, err);
        if (rc == RS_OK && *done)
            wall_add_load(w, &wl, setup);
        return rc;
    }
    return rs_track_update(&w->tracker, w->surf, mp, tdt, &w->pblk, &w->contacts, &w->tout,
                           err);
}

static int block_pass(rs_wall *w, const rs_wall_block *b, const rs_wall_rows *rows,
                      const int *idx, int n, double dt, int setup, rs_error *err)
{
    const int nd = w->ndir, ns = w->nstatev, as = wall_atom_size(w);
    const double rmax = gather(w, b, rows, idx, n);
    if (setup)
        for (int k = 0; k < n; k++)
            wall_pack_atom(w, idx[k], &w->saved_rows[(size_t)k * as]);
    int rc = query(w, b, idx, n, rmax, err);
    if (rc)
        return rc;

    /* A setup call has no increment: no slip, no master rotation. */
    rs_motion still;
    const rs_motion *mp = w->moving || w->belt ? w->motion : NULL;
    if (setup && w->moving) {
        still = *w->motion;
        for (int a = 0; a < 9; a++)
            still.dQ[a] = (a % 4 == 0) ? 1.0 : 0.0;
        mp = &still;
    }
    int done = 0;
    rc = tracker(w, b, rows, idx, mp, dt, setup, &done, err);
    if (rc != RS_OK) {
        /* More contacts than slots: the tracker changed nothing, so the slots grow and the
         * block runs again (a sphere in a mesh's pocket holds one per face). */
        if (err->code == RS_ERR_CAPACITY) {
            rs_error e2;
            if (wall_grow_capacity(w, w->capacity + 1, &e2) == RS_OK)
                return block_pass(w, b, rows, idx, n, dt, setup, err);
            if (e2.code != RS_ERR_CAPACITY)
                return rs_error_set(err, e2.code, "%s", e2.msg);
            char msg[sizeof err->msg];
            snprintf(msg, sizeof msg, "%s", err->msg);
            return rs_error_set(err, RS_ERR_CAPACITY,
                                "%s; the slots cannot grow past %d, the most the engine's "
                                "atom exchange carries with %d state variables",
                                msg, wall_max_capacity(w), ns);
        }
        return rc;
    }
    if (done)
        return RS_OK;

    const int ne = w->tout.n;
    double *const out = rows->peratom;
    if (ne > w->cbcap)
        return rs_error_set(err, RS_ERR_CAPACITY,
                            "internal: block has more contacts than its scratch");
    if (ne == 0) {
        for (int k = 0; out && k < n; k++)
            memset(out + 6 * (size_t)idx[k], 0, 6 * sizeof *out);
        if (setup)
            for (int k = 0; k < n; k++)
                wall_unpack_atom(w, idx[k], &w->saved_rows[(size_t)k * as]);
        return RS_OK;
    }
    /* Stress of the previous increment in this increment's basis (none for a law that
     * neither reads it nor leaves any unwritten), and the law state. */
    rs_track_load(&w->tracker, &w->tout, rs_law_stress_in(w->law) ? w->cb.stress : NULL,
                  ns ? w->cb.statev : NULL);
    law_inputs(w, b, idx, n, ne, dt, setup);
    if ((rc = call_law(w, b, idx, dt, setup, err)))
        return rc;

    /* Forces and torques onto the engine's rows, the wall's totals, energies and heat, in
     * one pass (rs_cblock_add_loads); where contacts share a patch at a concave fold, each
     * applies w A (docs/conventions.md). */
    double origin[3];
    rs_pose_to_global(&w->motion->pose, w->surf->a, origin);
    rs_load_rows lr = wall_load_rows(w, rows, idx, setup);
    /* the deepest contact of each particle, for the per-particle output (ident: contact k
     * is particle k's) */
    lr.deepest = w->ident || !out ? NULL : w->deepest;
    rs_wall_load wl;
    rs_cblock_add_loads(&w->cb, &w->tout, &w->pblk, origin, &lr, &wl);
    wall_add_load(w, &wl, setup);
    /* Per-particle output: the deepest live contact of each particle with this wall,
     * zeros for a particle without one. */
    if (out && w->ident)
        put_outputs(w, out, idx, n, nd, NULL, w->leaving);
    else if (out)
        put_outputs(w, out, idx, n, nd, w->deepest, NULL);

    /* the facets' loads take each contact's area times its share */
    w->load_area = w->cb.area;
    if (w->facets && w->tout.shared) {
        for (int e = 0; e < ne; e++)
            w->area_w[e] = w->cb.area[e] * w->tout.share[e];
        w->load_area = w->area_w;
    }
    if (w->conduction)
        wall_conduct(w, b, rows, idx, ne, setup);
    if (w->facets)
        wall_facet_pass(w, b, idx, ne, dt, setup);

    if (setup) {
        for (int k = 0; k < n; k++)
            wall_unpack_atom(w, idx[k], &w->saved_rows[(size_t)k * as]);
        /* An engine's own models keep what they write into a contact's history in the
         * setup call of a run (LIGGGHTS: shearupdate 0; most models write nothing then,
         * rolling_friction luding adds its torque increment regardless). A contact that
         * existed before the call (its slot is still in the directory) keeps the model's
         * values, as on wall/gran. */
        if (ns && w->law_kind == WALL_LAW_ENGINE)
            for (int e = 0; e < ne; e++)
                if (!w->leaving[e] && *w->tout.dir[e] != RS_DIR_EMPTY &&
                    !RS_DIR_IS_LEAVING(*w->tout.dir[e]))
                    memcpy(w->tout.slot[e] + rs_track_statev_at(&w->tracker),
                           w->cb.statev + (size_t)e * ns, sizeof(double) * ns);
        return RS_OK;
    }
    rs_track_commit_energy(&w->tracker, &w->tout, w->cb.sed, w->cb.flux_slv,
                           w->cb.flux_mst);
    rs_track_commit(&w->tracker, &w->tout, w->cb.stress, ns ? w->cb.statev : NULL);
    return RS_OK;
}

int wall_block(rs_wall *w, const rs_wall_block *b, const rs_wall_rows *rows, const int *idx,
               int n, double dt, int setup, rs_error *err)
{
    const int rc = block_pass(w, b, rows, idx, n, dt, setup, err);
    /* the rows' summaries after what the tracker (or a setup call's restore) left */
    for (int k = 0; k < n; k++)
        w->usual[idx[k]] = wall_usual_of(w, wall_row(w, idx[k]));
    return rc;
}
