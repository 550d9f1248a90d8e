/* The wall on a faceted master: per-facet stress and Finnie wear, as LIGGGHTS's `fix
 * mesh/surface/stress ... wear finnie` keeps them per triangle.
 *
 * - Stress: on the steps the VTK is written, the force every contact puts on the wall is
 *   summed per facet (the facet under the contact, rs_surface_facet_index); sigma_n =
 *   |f . n| / A and sigma_t = |f - (f . n) n| / A with the facet's area A and normal n.
 * - Wear (`wear finnie`): each step, a contact whose particle moves toward the wall (v_rel
 *   . (x_cp - x) >= 0, v_rel = the particle's centre velocity minus the wall's velocity at
 *   the contact point) adds 2 k |v_rel| |F| E(gamma) dt / A to its facet, with gamma the
 *   angle between v_rel and the facet's plane and Finnie's E = sin 2 gamma - 3 sin^2 gamma
 *   for tan gamma <= 1/3, cos^2 gamma / 3 beyond; k is the `k_finnie` of the particle and
 *   wall types (the engine's material property k_finnie, per type pair). The wear
 *   accumulates from the wall's making and goes into restart files.
 * Each rank sums its own contacts; totals are reduced for the VTK and the restart. */
#include "wall_impl.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Finnie's angle function E(gamma) of an impact at gamma to the surface's plane, from sin
 * gamma and cos gamma. */
static double finnie(double sg, double cg)
{
    if (3.0 * sg > cg) /* tan gamma > 1/3 */
        return cg * cg / 3.0;
    return 2.0 * sg * cg - 3.0 * sg * sg;
}

int wall_init_facets(rs_wall *w, rs_error *err)
{
    w->facets = rs_surface_has_facets(w->surf) && (w->vtk_every > 0 || w->wear);
    if (!w->facets)
        return RS_OK;
    const int nf = rs_surface_facet_count(w->surf);
    if (nf != w->nfacet) {
        const size_t n = nf > 0 ? (size_t)nf : 1;
        free(w->elem_area);
        free(w->elem_n);
        free(w->elem_f);
        w->elem_area = calloc(n, sizeof(double));
        w->elem_n = calloc(3 * n, sizeof(double));
        w->elem_f = calloc(3 * n, sizeof(double));
        if (!w->wear_el) /* the wear a restart file gave is kept */
            w->wear_el = calloc(n, sizeof(double));
        if (!w->elem_area || !w->elem_n || !w->elem_f || !w->wear_el)
            return rs_error_set(err, RS_ERR_NOMEM, "out of memory for %d facets", nf);
        w->nfacet = nf;
        for (int k = 0; k < nf; k++)
            rs_surface_facet_area(w->surf, k, &w->elem_area[k], &w->elem_n[3 * (size_t)k]);
    }
    if (w->wear) {
        const int nt = w->host.ntypes > 0 ? w->host.ntypes : 1, wt = w->info.wall_type;
        free(w->kfinnie);
        w->kfinnie = calloc((size_t)nt + 1, sizeof *w->kfinnie);
        if (!w->kfinnie)
            return rs_error_set(err, RS_ERR_NOMEM, "out of memory for k_finnie");
        if (!w->host.material)
            return rs_error_set(
                err, RS_ERR_ARG,
                "keyword 'wear finnie' reads the engine's k_finnie per type "
                "pair, which this engine does not give");
        for (int t = 1; t <= nt; t++) {
            const int rc =
                w->host.material(w->host.ctx, "k_finnie", wt, t, 1,
                                 "fix wall/rigid (wear finnie)", &w->kfinnie[t], err);
            if (rc == RS_ERR_NOTFOUND)
                continue;
            if (rc)
                return rc;
        }
    }
    return RS_OK;
}

/* At the start of a step's force computation: is this a step whose facet stresses the
 * VTK writes? Then the sums start from zero. */
void wall_begin_facets(rs_wall *w, long long step)
{
    w->stress_step = w->facets && w->vtk_every > 0 && step % w->vtk_every == 0;
    if (w->stress_step)
        memset(w->elem_f, 0, 3 * (size_t)w->nfacet * sizeof *w->elem_f);
}

/* The block's contacts [0, ne) after the law: their forces on the wall into the facets'
 * sums (stress steps) and their wear (not in a setup call, which is no increment). */
void wall_facet_pass(rs_wall *w, const rs_wall_block *b, const int *idx, int ne, double dt,
                     int setup)
{
    const int wear = w->wear && !setup;
    if (!w->stress_step && !wear)
        return;
    const int nd = w->ndir;
    const rs_track_out *o = &w->tout;
    for (int e = 0; e < ne; e++) {
        if (w->leaving[e])
            continue;
        const int el = rs_surface_facet_index(w->surf, o->feature[e]);
        if (el < 0)
            continue;
        const int k = o->point[e];
        const double A = w->load_area[e]; /* area times share */
        const double *s = w->cb.stress + (size_t)e * nd;
        const double *L = o->alocaldir + (size_t)e * nd * nd; /* columns n, t1, t2 */
        double F[3];                                          /* on the particle */
        for (int d = 0; d < 3; d++)
            F[d] = A * (s[0] * L[d] - s[1] * L[3 + d] - s[2] * L[6 + d]);
        if (w->stress_step)
            for (int d = 0; d < 3; d++)
                w->elem_f[3 * (size_t)el + d] -= F[d];
        if (!wear)
            continue;
        const double *xc = o->coordslv + (size_t)e * nd;
        double vw[3] = {0.0, 0.0, 0.0}, belt[3];
        if (w->moving)
            rs_motion_velocity_at(w->motion, xc, vw);
        if (w->belt) {
            rs_motion_belt_at(w->motion, L, belt);
            for (int d = 0; d < 3; d++)
                vw[d] += belt[d];
        }
        const double vr[3] = {w->bvx[k] - vw[0], w->bvy[k] - vw[1], w->bvz[k] - vw[2]};
        const double c[3] = {xc[0] - w->bx[k], xc[1] - w->by[k], xc[2] - w->bz[k]};
        if (c[0] * vr[0] + c[1] * vr[1] + c[2] * vr[2] < 0.0)
            continue; /* moving away from the wall */
        const double vmag = sqrt(vr[0] * vr[0] + vr[1] * vr[1] + vr[2] * vr[2]);
        if (!(vmag > 0.0))
            continue;
        double n[3];
        rs_pose_rotate(&w->motion->pose, &w->elem_n[3 * (size_t)el], n);
        const double vn = vr[0] * n[0] + vr[1] * n[1] + vr[2] * n[2];
        const double cx[3] = {vr[1] * n[2] - vr[2] * n[1], vr[2] * n[0] - vr[0] * n[2],
                              vr[0] * n[1] - vr[1] * n[0]};
        const double sg = fmin(1.0, fabs(vn) / vmag);
        const double cg =
            fmin(1.0, sqrt(cx[0] * cx[0] + cx[1] * cx[1] + cx[2] * cx[2]) / vmag);
        const double fmag = sqrt(F[0] * F[0] + F[1] * F[1] + F[2] * F[2]);
        const int t = b->type ? b->type[idx[k]] : 1;
        const double kf = w->kfinnie[t];
        w->wear_el[el] += 2.0 * kf * vmag * fmag * finnie(sg, cg) * dt / w->elem_area[el];
    }
}

/* The facets' sigma_n, sigma_t and wear over all ranks (collective; sn, st and wear hold
 * nfacet values each, wear only with `wear finnie`). */
int wall_reduce_facets(rs_wall *w, double *sn, double *st, double *wear, rs_error *err)
{
    const int nf = w->nfacet;
    double *f = malloc(3 * (size_t)(nf > 0 ? nf : 1) * sizeof *f);
    if (!f)
        return rs_error_set(err, RS_ERR_NOMEM, "out of memory for %d facets' stresses", nf);
    memcpy(f, w->elem_f, 3 * (size_t)nf * sizeof *f);
    if (w->host.reduce)
        w->host.reduce(w->host.ctx, f, 3 * nf, RS_REDUCE_SUM);
    if (w->wear) {
        memcpy(wear, w->wear_el, (size_t)nf * sizeof *wear);
        if (w->host.reduce)
            w->host.reduce(w->host.ctx, wear, nf, RS_REDUCE_SUM);
    }
    for (int k = 0; k < nf; k++) {
        double n[3];
        rs_pose_rotate(&w->motion->pose, &w->elem_n[3 * (size_t)k], n);
        const double *fk = &f[3 * (size_t)k];
        const double fn = fk[0] * n[0] + fk[1] * n[1] + fk[2] * n[2];
        const double ft[3] = {fk[0] - fn * n[0], fk[1] - fn * n[1], fk[2] - fn * n[2]};
        sn[k] = fabs(fn) / w->elem_area[k];
        st[k] = sqrt(ft[0] * ft[0] + ft[1] * ft[1] + ft[2] * ft[2]) / w->elem_area[k];
    }
    free(f);
    return RS_OK;
}
