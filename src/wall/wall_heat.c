/* Keyword conduction liggghts: LIGGGHTS's conduction between a wall at its temperature and
 * the particles that touch it, as its fix wall/gran computes it under fix heat/gran
 * (fix_wall_gran.cpp, init_heattransfer and addHeatFlux), from the engine's per-type
 * thermalConductivity and, under heat/gran/conduction, its area correction. */
#include "wall_impl.h"

#include "rigidsurf/vec.h"

#include <math.h>
#include <stdlib.h>

#define FAIL(...) return rs_error_set(err, RS_ERR_ARG, __VA_ARGS__)

/* thermalConductivity per type (an error from the engine when it is missing, as
 * LIGGGHTS's wall gives). */
int wall_init_conduction(rs_wall *w, rs_error *err)
{
    free(w->th_cond);
    w->th_cond = NULL;
    if (!w->conduction)
        return RS_OK;
    if (!w->run.has_temp || !w->run.has_heatflux)
        FAIL("keyword 'conduction liggghts' needs fix heat/gran (the per-atom Temp and "
             "heatFlux it keeps)");
    if (!w->host.material)
        FAIL("keyword 'conduction liggghts' reads the engine's thermalConductivity per "
             "type, which this engine does not give");
    const int nt = w->host.ntypes > 0 ? w->host.ntypes : 1;
    w->th_cond = calloc((size_t)nt + 1, sizeof *w->th_cond);
    if (!w->th_cond)
        return rs_error_set(err, RS_ERR_NOMEM, "out of memory for the conductivities");
    for (int t = 1; t <= nt; t++) {
        const int rc = w->host.material(w->host.ctx, "thermalConductivity", t, 0, 1,
                                        "wall/rigid", &w->th_cond[t], err);
        if (rc && rc != RS_ERR_NOTFOUND)
            return rc;
    }
    return RS_OK;
}

/* heat/gran/conduction's area correction per type pair, where the engine has one
 * ("deltan_ratio": LIGGGHTS's youngsModulusOriginal's modified array, which that fix
 * fills in its init; read at each run's setup call, after every fix's init). */
int wall_conduction_ratios(rs_wall *w, rs_error *err)
{
    free(w->deltan_ratio);
    w->deltan_ratio = NULL;
    if (!w->conduction || !w->host.material)
        return RS_OK;
    const int nt = w->host.ntypes > 0 ? w->host.ntypes : 1, wt = w->info.wall_type;
    double v;
    int rc = w->host.material(w->host.ctx, "deltan_ratio", 1, wt, 0, "wall/rigid", &v, err);
    if (rc == RS_ERR_NOTFOUND)
        return RS_OK;
    if (rc)
        return rc;
    w->deltan_ratio = calloc((size_t)nt + 1, sizeof *w->deltan_ratio);
    if (!w->deltan_ratio)
        return rs_error_set(err, RS_ERR_NOMEM, "out of memory for the area corrections");
    for (int t = 1; t <= nt; t++) {
        rc = w->host.material(w->host.ctx, "deltan_ratio", t, wt, 0, "wall/rigid",
                              &w->deltan_ratio[t], err);
        if (rc && rc != RS_ERR_NOTFOUND)
            return rc;
    }
    return RS_OK;
}

/* Each touching contact of the block (overlap delta >= 0, not leaving): the contact area
 * A = pi (R^2 - (R - delta)^2), delta times the area correction of the particle and wall
 * types (contact_area overlap, the default), or pi R^2 (projection), or the constant
 * given; the conductance h = 4 k_p k_w / (k_p + k_w) sqrt(A) (0 when either conductivity
 * is below 1e-12); the heat flow w h (T_wall - T_p) into the particle's heat flow (w: the
 * contact's share, 1 but at a concave fold), and its opposite into the wall (not in a
 * setup call, whose heat is not accumulated). LIGGGHTS's wall starts to conduct at the end
 * of its first setup (FixWallGran::setup calls init_heattransfer after its forces), so it
 * adds the flow in the setup calls of later runs only; fix heat/gran clears heatFlux
 * before the step. */
void wall_conduct(rs_wall *w, const rs_wall_block *b, const rs_wall_rows *rows,
                  const int *idx, int ne, int setup)
{
    if ((setup && !w->conduct_ready) || !rows->heatflux || !b->temp)
        return;
    const int nd = w->ndir, wt = w->info.wall_type;
    const rs_track_out *o = &w->tout;
    double *heatflux = rows->heatflux;
    const double tcowall = w->th_cond[wt];
    const double small = 1e-12;
    double into_wall = 0.0;
    for (int e = 0; e < ne; e++) {
        const double delta0 = o->rdisp[(size_t)e * nd];
        if (w->leaving[e] || !(delta0 >= 0.0))
            continue;
        const int k = o->point[e];
        const int i = idx[k];
        const int itype = b->type ? b->type[i] : 1;
        const double ri = w->brad[k];
        double area;
        if (w->carea_mode == WALL_CAREA_OVERLAP) {
            double delta = delta0;
            if (w->deltan_ratio)
                delta *= w->deltan_ratio[itype];
            const double r = ri - delta;
            area = (ri * ri - r * r) * RS_PI * 1.0;
        } else if (w->carea_mode == WALL_CAREA_PROJECTION) {
            area = RS_PI * ri * ri;
        } else {
            area = w->carea_const;
        }
        const double tcop = w->th_cond[itype];
        double hc;
        if (fabs(tcop) < small || fabs(tcowall) < small)
            hc = 0.0;
        else
            hc = 4. * tcop * tcowall / (tcop + tcowall) * sqrt(area);
        const double hf = (w->temp_wall - b->temp[i]) * hc * o->share[e];
        heatflux[i] += hf;
        into_wall -= hf;
    }
    if (!setup)
        w->heat_step += into_wall;
}
