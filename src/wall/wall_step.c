/* The wall's step: the candidates refreshed when the engine's lists or the wall's motion
 * ask for it, those whose distance bound keeps them away skipped, the rest in blocks
 * (wall_block.c; wall_line.c on a revolved LINE with a fused law), then the wall's heat and
 * the fields kept for the next increment. */
#include "wall_impl.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The candidates this step: every particle of the group (every_particle), or those of the
 * last refresh less those whose distance bound keeps them beyond the tracking thickness (a
 * test as cheap as a primitive wall's; a particle that holds a contact has no bound); on
 * the line path all of them, which it tests as it goes (wall_line.c). */
static int step_list(rs_wall *w, const rs_wall_block *b, int setup, const int **list,
                     int *n, rs_error *err)
{
    if (w->run.every_particle) {
        int m = 0;
        if (w->cand_cap < b->n) {
            int *c = realloc(w->cand, (size_t)(b->n > 0 ? b->n : 1) * sizeof *c);
            if (!c)
                return rs_error_set(err, RS_ERR_NOMEM, "out of memory for %d candidates",
                                    b->n);
            w->cand = c;
            w->cand_cap = b->n;
        }
        for (int i = 0; i < b->n; i++)
            if (wall_in_group(b, i))
                w->cand[m++] = i;
        w->ncand = m;
        *list = w->cand;
        *n = m;
        return RS_OK;
    }
    *list = w->cand;
    *n = w->ncand;
    /* the line path tests the bounds of the particles it does not find usual itself */
    if (!(w->bounds_ok || w->list_bounds) || setup || w->line_pass)
        return RS_OK;
    const int *restrict cand = w->cand;
    int *restrict active = w->active;
    const int ncand = w->ncand;
    int na = 0;
    for (int c = 0; c < ncand; c++) {
        const int i = cand[c];
        if (!wall_kept_away(w, b->x, b->radius, i))
            active[na++] = i;
    }
    *list = w->active;
    *n = na;
    return RS_OK;
}

int wall_compute(rs_wall *w, const rs_wall_block *b, const rs_wall_rows *rows, double dt,
                 int setup, rs_error *err)
{
    if (!w->run_ok)
        return rs_error_set(err, RS_ERR_ARG, "wall: rs_wall_init was not called");
    if (b->n > w->nmax)
        return rs_error_set(err, RS_ERR_ARG,
                            "wall: %d particles but history for %d (rs_wall_grow)", b->n,
                            w->nmax);
    for (int d = 0; d < 3; d++)
        w->f_wall[d] = w->m_wall[d] = 0.0;
    w->se_now = 0.0;
    w->fd_step = w->pd_step = w->vd_step = w->cd_step = w->qs_step = 0.0;
    w->ncontact = 0;
    w->heat_step = 0.0;
    wall_begin_facets(w, b->step);
    int rc;

    /* Per-particle output: every candidate's row is written by its block each step, so
     * only the rows that may stop being candidates are zeroed here: all of them after a
     * reneighbouring (indices change), the old candidates' before a refresh the wall's
     * motion asks for. Between the two, indices and candidates are fixed. */
    if (!w->run.every_particle) {
        int refresh = w->rebuild || setup;
        double *out = rows->peratom;
        if (refresh) {
            if (out)
                memset(out, 0, 6 * (size_t)b->n * sizeof *out);
        } else if (wall_moved_beyond_skin(w)) {
            for (int c = 0; out && c < w->ncand; c++)
                memset(out + 6 * (size_t)w->cand[c], 0, 6 * sizeof *out);
            refresh = 1;
        }
        if (refresh) {
            if ((rc = wall_build_candidates(w, b, err)))
                return rc;
            if (wall_looks_behind(w))
                wall_warn_behind(w);
        }
    } else if (rows->peratom) {
        memset(rows->peratom, 0, 6 * (size_t)b->n * sizeof *rows->peratom);
    }
    const int *list = NULL;
    int nc = 0;
    if ((rc = step_list(w, b, setup, &list, &nc, err)))
        return rc;

    /* Blocks of at most bcap particles; with per-type properties a block holds one
     * particle type (the candidates are sorted by type). */
    const int per_type = wall_material_props(w) && b->type;
    const int *type = b->type;
    for (int b0 = 0; b0 < nc;) {
        int b1 = nc < b0 + w->bcap ? nc : b0 + w->bcap;
        if (per_type)
            for (int k = b0 + 1; k < b1; k++)
                if (type[list[k]] != type[list[b0]]) {
                    b1 = k;
                    break;
                }
        if (w->line_pass && !setup)
            rc = wall_line_block(w, b, rows, &list[b0], b1 - b0, dt, err);
        else
            rc = wall_block(w, b, rows, &list[b0], b1 - b0, dt, setup, err);
        if (rc)
            return rc;
        b0 = b1;
    }

    if (!setup) {
        /* Wall heat: a lumped capacity integrates the total flux into it. */
        const double q = w->heat_step;
        if (w->capacity_wall > 0.0) {
            const double qall = wall_reduce1(w, q, RS_REDUCE_SUM);
            w->dtemp_wall = qall * dt / w->capacity_wall;
            w->temp_wall += w->dtemp_wall;
        }
        w->heat_wall += q * dt;
        w->temp_mst[0] = w->temp_wall;
        w->dtemp_mst[0] = w->dtemp_wall;
        wall_update_previous_fields(w, b);
    }
    return RS_OK;
}

/* A block's loads into the wall's totals. */
void wall_add_load(rs_wall *w, const rs_wall_load *wl, int setup)
{
    for (int c = 0; c < 3; c++) {
        w->f_wall[c] += wl->force[c];
        w->m_wall[c] += wl->moment[c];
    }
    w->ncontact += wl->ncontact;
    w->se_now += wl->se;
    if (!setup) { /* a setup call's history is restored: it dissipates nothing */
        w->diss[0] += wl->fd;
        w->diss[1] += wl->pd;
        w->diss[2] += wl->vd;
        w->diss[3] += wl->cd;
        w->fd_step += wl->fd;
        w->pd_step += wl->pd;
        w->vd_step += wl->vd;
        w->cd_step += wl->cd;
        w->qs_step += wl->flux_slv;
        w->heat_step += wl->flux_mst;
    }
}
