/* What one call's contacts do (rs_cblock_loads): each contact's force and torque on its
 * particle, the wall's force and moment, and the energies and heat, from the law's
 * stress in the tracker's frame; the engine then only scatters them. */
#include "rigidsurf/contact_block.h"
#include "rigidsurf/vec.h"

#include <string.h>

void rs_cblock_loads(const rs_contact_block *cb, const rs_track_out *o,
                     const rs_particle_block *p, const double origin[3], double *f,
                     double *t, double *q, rs_wall_load *w)
{
    memset(w, 0, sizeof *w);
    const int nd = o->ndir;
    for (int e = 0; e < o->n; e++) {
        double *fe = f + 3 * (size_t)e, *te = t + 3 * (size_t)e;
        fe[0] = fe[1] = fe[2] = te[0] = te[1] = te[2] = 0.0;
        if (q)
            q[e] = 0.0;
        if (RS_DIR_IS_LEAVING(*o->dir[e]))
            continue;
        const int i = o->point[e];
        const double a = cb->area[e] * o->share[e]; /* the contact's share of its area */
        const double *s = cb->stress + (size_t)e * nd;
        const double *L = o->alocaldir + (size_t)e * nd * nd; /* columns n, t1[, t2] */
        const double *xc = o->coordslv + (size_t)e * nd;
        double x[3] = {xc[0], xc[1], nd == 3 ? xc[2] : p->z[i]};
        for (int c = 0; c < nd; c++) {
            double fc = s[0] * L[c];
            for (int j = 1; j < nd; j++)
                fc -= s[j] * L[j * nd + c];
            fe[c] = a * fc;
        }
        const double r[3] = {x[0] - p->x[i], x[1] - p->y[i], x[2] - p->z[i]};
        rs_cross3(r, fe, te);
        const double rw[3] = {x[0] - origin[0], x[1] - origin[1], x[2] - origin[2]};
        double mw[3];
        rs_cross3(rw, fe, mw);
        for (int c = 0; c < 3; c++) {
            w->force[c] -= fe[c];
            w->moment[c] -= mw[c];
        }
        if (q)
            q[e] = a * cb->flux_slv[e];
        w->flux_slv += a * cb->flux_slv[e];
        w->flux_mst += a * cb->flux_mst[e];
        w->se += a * cb->sed[e];
        w->fd += a * cb->sfd[e];
        w->pd += a * cb->spd[e];
        w->vd += a * cb->svd[e];
        w->cd += a * cb->scd[e];
        w->ncontact += RS_A2(o->rdisp, nd, 0, e) > 0.0;
    }
}
