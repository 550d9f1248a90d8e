/* The contact block: per-contact law inputs from the tracker's output and the block's
 * particles, and the law called on it slice by slice (contact_block.h). */
#include "rigidsurf/contact_block.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

double rs_effective_radius(double R, double k1, double k2)
{
    if (k1 == 0.0 && k2 == 0.0)
        return R;
    const double floor_c = 1e-6 / R;
    const double c1 = fmax(1.0 / R + k1, floor_c), c2 = fmax(1.0 / R + k2, floor_c);
    return 1.0 / sqrt(c1 * c2);
}

enum { NDOUBLE = 19 };

/* The double arrays of cb, each with its length for n contacts. */
static void double_arrays(rs_contact_block *cb, size_t n, double **p[NDOUBLE],
                          size_t len[NDOUBLE])
{
    const size_t ns = cb->nstatev > 0 ? (size_t)cb->nstatev : 1,
                 np = cb->npred > 0 ? (size_t)cb->npred : 1,
                 nd = cb->ndir > 0 ? (size_t)cb->ndir : 3;
    double **const a[NDOUBLE] = {&cb->stiff,    &cb->cond,     &cb->area,   &cb->radius,
                                 &cb->mass,     &cb->reff,     &cb->temp,   &cb->dtemp,
                                 &cb->pred,     &cb->dpred,    &cb->stress, &cb->statev,
                                 &cb->flux_slv, &cb->flux_mst, &cb->sed,    &cb->sfd,
                                 &cb->scd,      &cb->spd,      &cb->svd};
    for (int i = 0; i < NDOUBLE; i++) {
        p[i] = a[i];
        len[i] = n;
    }
    len[8] = len[9] = n * np; /* pred, dpred */
    len[10] = n * nd;         /* stress */
    len[11] = n * ns;         /* statev */
}

void rs_cblock_free(rs_contact_block *cb)
{
    double **p[NDOUBLE];
    size_t len[NDOUBLE];
    double_arrays(cb, 0, p, len);
    for (int i = 0; i < NDOUBLE; i++)
        free(*p[i]);
    free(cb->uid);
    free(cb->type);
    memset(cb, 0, sizeof *cb);
}

int rs_cblock_reserve(rs_contact_block *cb, int cap, rs_error *err)
{
    if (cap < 1 || cb->ndir < 2 || cb->ndir > 3 || cb->nstatev < 0 || cb->npred < 0)
        return rs_error_set(err, RS_ERR_ARG,
                            "contact block: %d contacts, nDir %d, %d state variables, %d "
                            "predefined fields (expected >= 1, 2 or 3, >= 0, >= 0)",
                            cap, cb->ndir, cb->nstatev, cb->npred);
    const rs_contact_block keep = *cb;
    rs_cblock_free(cb);
    cb->area_mode = keep.area_mode;
    cb->area_const = keep.area_const;
    cb->ndir = keep.ndir;
    cb->nstatev = keep.nstatev;
    cb->npred = keep.npred;

    const size_t n = (size_t)cap;
    double **p[NDOUBLE];
    size_t len[NDOUBLE];
    double_arrays(cb, n, p, len);
    int ok = (cb->uid = calloc(n, sizeof(int))) && (cb->type = calloc(n, sizeof(int)));
    for (int i = 0; ok && i < NDOUBLE; i++)
        ok = (*p[i] = calloc(len[i], sizeof(double))) != NULL;
    if (!ok) {
        rs_cblock_free(cb);
        return rs_error_set(err, RS_ERR_NOMEM,
                            "contact block: out of memory for %d contacts", cap);
    }
    cb->cap = cap;
    return RS_OK;
}

static double mode_area(const rs_contact_block *cb, double R)
{
    return cb->area_mode == RS_AREA_CONSTANT    ? cb->area_const
           : cb->area_mode == RS_AREA_PROJECTED ? RS_PI * R * R
                                                : 1.0;
}

void rs_cblock_inputs(rs_contact_block *cb, const rs_track_out *o,
                      const rs_block_particles *p, double dt)
{
    const int ne = o->n;
    const int *restrict pt = o->point;
    const double *restrict curv = o->curv;
    const double *restrict radius = p->radius, *restrict mass = p->mass;
    int *restrict uid = cb->uid, *restrict ctype = cb->type;
    cb->has_type = p->type != NULL;
    cb->has_temp = p->temp != NULL;

    /* Do all contacts share one key (R, m, A, k1, k2)? */
    int uniform = ne > 0 && !p->area && !p->heatcap;
    const double R0 = ne > 0 ? radius[pt[0]] : 0.0, m0 = ne > 0 ? mass[pt[0]] : 0.0;
    const double k10 = ne > 0 ? curv[0] : 0.0, k20 = ne > 0 ? curv[1] : 0.0;
    for (int e = 0; e < ne; e++) {
        const int k = pt[e];
        uid[e] = p->id[k];
        uniform &= (radius[k] == R0) & (mass[k] == m0) & (curv[2 * e] == k10) &
                   (curv[2 * e + 1] == k20);
    }
    if (p->type)
        for (int e = 0; e < ne; e++)
            ctype[e] = p->type[pt[e]];

    double *restrict area = cb->area, *restrict crad = cb->radius,
                     *restrict cmass = cb->mass, *restrict stiffa = cb->stiff,
                     *restrict conda = cb->cond, *restrict reffa = cb->reff;
    if (uniform) {
        const double A = mode_area(cb, R0);
        const double key[6] = {R0, m0, A, k10, k20, dt};
        int same = cb->uni_n > 0;
        for (int a = 0; a < 6; a++)
            same = same && key[a] == cb->uni_key[a];
        if (!same) {
            cb->uni_n = 0;
            for (int a = 0; a < 6; a++)
                cb->uni_key[a] = key[a];
        }
        if (cb->uni_n < ne) {
            const double stiff = rs_law_default_stiffness(m0, A, dt);
            const double reff = rs_effective_radius(R0, k10, k20);
            for (int e = cb->uni_n; e < ne; e++) {
                area[e] = A;
                crad[e] = R0;
                cmass[e] = m0;
                stiffa[e] = stiff;
                conda[e] = 0.0;
                reffa[e] = reff;
            }
            cb->uni_n = ne;
        }
    } else {
        /* each value is recomputed when its inputs differ from the previous contact's */
        cb->uni_n = 0;
        double last_m = NAN, last_mA = NAN, stiff = 0.0;
        double last_C = NAN, last_CA = NAN, cond = 0.0;
        double last_R = NAN, last_k1 = NAN, last_k2 = NAN, reff = 0.0;
        for (int e = 0; e < ne; e++) {
            const int k = pt[e];
            const double R = radius[k], m = mass[k];
            const double A = p->area ? p->area[k] : mode_area(cb, R);
            area[e] = A;
            crad[e] = R;
            cmass[e] = m;
            const double k1 = curv[2 * e], k2 = curv[2 * e + 1];
            if (!(R == last_R && k1 == last_k1 && k2 == last_k2)) {
                reff = rs_effective_radius(R, k1, k2);
                last_R = R, last_k1 = k1, last_k2 = k2;
            }
            reffa[e] = reff;
            if (!(m == last_m && A == last_mA)) {
                stiff = rs_law_default_stiffness(m, A, dt);
                last_m = m, last_mA = A;
            }
            stiffa[e] = stiff;
            if (p->heatcap) {
                const double C = p->heatcap[k];
                if (!(C == last_C && A == last_CA)) {
                    cond = rs_law_default_conductance(C, A, dt);
                    last_C = C, last_CA = A;
                }
                conda[e] = cond;
            } else {
                conda[e] = 0.0;
            }
        }
    }

    for (int e = 0; e < ne; e++) {
        cb->flux_slv[e] = 0.0;
        cb->flux_mst[e] = 0.0;
        cb->sed[e] = 0.0;
    }
    if (p->temp)
        for (int e = 0; e < ne; e++) {
            cb->temp[e] = p->temp[pt[e]];
            cb->dtemp[e] = p->dtemp[pt[e]];
        }
    const int np = cb->npred;
    if (np && p->pred)
        for (int e = 0; e < ne; e++)
            for (int a = 0; a < np; a++) {
                cb->pred[(size_t)e * np + a] = p->pred[(size_t)pt[e] * np + a];
                cb->dpred[(size_t)e * np + a] = p->dpred[(size_t)pt[e] * np + a];
            }
}

int rs_cblock_call(rs_contact_block *cb, const rs_law *law, const rs_law_block *tmpl,
                   const rs_track_out *o, rs_error *err)
{
    const int nd = cb->ndir, ns = cb->nstatev, np = cb->npred;
    for (int k0 = 0; k0 < o->n; k0 += RS_BLOCK) {
        const int nk = o->n - k0 < RS_BLOCK ? o->n - k0 : RS_BLOCK;
        const size_t u0 = (size_t)k0;
        rs_law_block b = *tmpl;
        b.nSlvNod = nk;
        b.jSlvUid = cb->uid + u0;
        b.jConMstid = o->feature + u0;
        b.rdisp = o->rdisp + u0 * nd;
        b.drdisp = o->drdisp + u0 * nd;
        b.drot = o->drot + u0 * 4;
        b.coordSlv = o->coordslv + u0 * nd;
        b.coordMst = o->coordmst + u0 * nd;
        b.alocaldir = o->alocaldir + u0 * nd * nd;
        b.vrel = o->vrel + u0 * nd;
        b.curv = o->curv + u0 * 2;
        b.stiffDflt = cb->stiff + u0;
        b.condDflt = cb->cond + u0;
        b.areaSlv = cb->area + u0;
        b.radius = cb->radius + u0;
        b.mass = cb->mass + u0;
        b.reff = cb->reff + u0;
        if (cb->has_temp) { /* otherwise the template's: zeros */
            b.tempSlv = cb->temp + u0;
            b.dtempSlv = cb->dtemp + u0;
        }
        if (np) {
            b.preDefSlv = cb->pred + u0 * np;
            b.dpreDefSlv = cb->dpred + u0 * np;
        }
        b.slv_type = cb->has_type ? cb->type + u0 : NULL;
        b.stress = cb->stress + u0 * nd;
        b.statev = ns ? cb->statev + u0 * ns : NULL;
        b.fluxSlv = cb->flux_slv + u0;
        b.fluxMst = cb->flux_mst + u0;
        b.sed = cb->sed + u0;
        b.sfd = cb->sfd + u0;
        b.scd = cb->scd + u0;
        b.spd = cb->spd + u0;
        b.svd = cb->svd + u0;
        const int rc = rs_law_call(law, &b, err);
        if (rc)
            return rc;
    }
    return RS_OK;
}
