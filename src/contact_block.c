/* The contact block: per-contact law inputs from the tracker's output and the block's
 * particles, and the law called on it slice by slice (contact_block.h). */
#include "rigidsurf/contact_block.h"
#include "effective_mass.h"
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

enum { NDOUBLE = 21 };

/// Slots of a slice's node table: a power of two above twice its most nodes.
#define RS_FACET_HASH 2048

/* The double arrays of cb, each with its length for n contacts. */
static void double_arrays(rs_contact_block *cb, size_t n, double **p[NDOUBLE],
                          size_t len[NDOUBLE])
{
    const size_t ns = cb->nstatev > 0 ? (size_t)cb->nstatev : 1,
                 np = cb->npred > 0 ? (size_t)cb->npred : 1,
                 nd = cb->ndir > 0 ? (size_t)cb->ndir : 3;
    double **const a[NDOUBLE] = {
        &cb->stiff,    &cb->cond,     &cb->area,  &cb->radius, &cb->mass,   &cb->reff,
        &cb->temp,     &cb->dtemp,    &cb->pred,  &cb->dpred,  &cb->stress, &cb->statev,
        &cb->flux_slv, &cb->flux_mst, &cb->sed,   &cb->sfd,    &cb->scd,    &cb->spd,
        &cb->svd,      &cb->force,    &cb->torque};
    for (int i = 0; i < NDOUBLE; i++) {
        p[i] = a[i];
        len[i] = n;
    }
    len[8] = len[9] = n * np;  /* pred, dpred */
    len[10] = n * nd;          /* stress */
    len[11] = n * ns;          /* statev */
    len[19] = len[20] = 3 * n; /* force, torque */
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
    free(cb->row);
    free(cb->fac_node);
    free(cb->fac_shape);
    free(cb->fac_xyz);
    free(cb->sl_conn);
    free(cb->sl_uid);
    free(cb->sl_xyz);
    free(cb->sl_hash);
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
    int ok = (cb->uid = calloc(n, sizeof(int))) && (cb->type = calloc(n, sizeof(int))) &&
             (cb->row = calloc(n, sizeof(int)));
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

    /* Do all contacts share one key (R, m, A, k1, k2)? (A body's contacts have masses of
     * their own.) */
    int uniform = ne > 0 && !p->area && !p->heatcap && !p->body;
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
    cb->has_row = p->row != NULL;
    if (p->row)
        for (int e = 0; e < ne; e++)
            cb->row[e] = p->row[pt[e]];

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

    rs_cblock_body_masses(cb, o, p);
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

/* Room for the facets of n contacts (and one slice's arrays). */
static int facet_room(rs_contact_block *cb, int n, rs_error *err)
{
    if (!cb->sl_hash) { /* all four or none, so that a later call starts afresh */
        int *conn = malloc(4 * RS_BLOCK * sizeof(int));
        int *uid = malloc(4 * RS_BLOCK * sizeof(int));
        double *sxyz = malloc(12 * RS_BLOCK * sizeof(double));
        int *hash = malloc(RS_FACET_HASH * sizeof(int));
        if (!conn || !uid || !sxyz || !hash) {
            free(conn);
            free(uid);
            free(sxyz);
            free(hash);
            return rs_error_set(err, RS_ERR_NOMEM,
                                "contact block: out of memory for facets");
        }
        cb->sl_conn = conn;
        cb->sl_uid = uid;
        cb->sl_xyz = sxyz;
        cb->sl_hash = hash;
    }
    if (n <= cb->fac_cap)
        return RS_OK;
    const int cap = n > 2 * cb->fac_cap ? n : 2 * cb->fac_cap;
    int *node = realloc(cb->fac_node, 4 * (size_t)cap * sizeof(int));
    if (node)
        cb->fac_node = node;
    double *shape = realloc(cb->fac_shape, 4 * (size_t)cap * sizeof(double));
    if (shape)
        cb->fac_shape = shape;
    double *xyz = realloc(cb->fac_xyz, 12 * (size_t)cap * sizeof(double));
    if (xyz)
        cb->fac_xyz = xyz;
    if (!node || !shape || !xyz)
        return rs_error_set(err, RS_ERR_NOMEM,
                            "contact block: out of memory for the facets of %d contacts",
                            n);
    cb->fac_cap = cap;
    return RS_OK;
}

int rs_cblock_facets(rs_contact_block *cb, const rs_track_out *o, const rs_surface *s,
                     const rs_pose *pose, rs_error *err)
{
    cb->nfac = rs_surface_facet_size(s, NULL);
    if (cb->nfac == 0 || o->n == 0)
        return RS_OK;
    const int rc = facet_room(cb, o->n, err);
    if (rc)
        return rc;
    const int nf = cb->nfac, nd = o->ndir;
    for (int k = 0; k < o->n; k++) {
        int node[4] = {0, 0, 0, 0};
        double xyz[12] = {0}, shape[4] = {0, 0, 0, 0}, xm[3] = {0, 0, 0}, X[3];
        const int leaving = RS_A2(o->rdisp, nd, 0, k) >= 0.5 * RS_MAXVAL;
        for (int d = 0; d < nd; d++)
            xm[d] = leaving ? 0.0 : RS_A2(o->coordmst, nd, d, k);
        if (pose)
            rs_pose_to_local(pose, xm, X);
        else
            memcpy(X, xm, sizeof X);
        const int nn = rs_surface_facet(s, o->feature[k], X, node, xyz, shape);
        for (int i = nn; i < nf; i++) { /* a triangle among quads: its first node again */
            node[i] = node[0];
            shape[i] = 0.0;
            memcpy(xyz + 3 * i, xyz, 3 * sizeof(double));
        }
        for (int i = 0; i < nf; i++) {
            const size_t j = (size_t)k * (size_t)nf + (size_t)i;
            cb->fac_node[j] = node[i];
            cb->fac_shape[j] = leaving || nn == 0 ? 0.0 : shape[i];
            if (pose)
                rs_pose_to_global(pose, xyz + 3 * i, cb->fac_xyz + 3 * j);
            else
                memcpy(cb->fac_xyz + 3 * j, xyz + 3 * i, 3 * sizeof(double));
        }
    }
    return RS_OK;
}

/* The facet arguments of the slice [k0, k0 + nk): the distinct nodes (sl_uid, sl_xyz)
 * and each contact's positions among them (sl_conn). */
static void facet_slice(rs_contact_block *cb, int k0, int nk, int nd, rs_law_block *b)
{
    const int nf = cb->nfac;
    int nm = 0;
    for (int h = 0; h < RS_FACET_HASH; h++)
        cb->sl_hash[h] = -1;
    for (int j = 0; j < nk * nf; j++) {
        const size_t g = (size_t)k0 * (size_t)nf + (size_t)j;
        const int uid = cb->fac_node[g];
        unsigned h = ((unsigned)uid * 2654435761u) & (RS_FACET_HASH - 1);
        while (cb->sl_hash[h] >= 0 && cb->sl_uid[cb->sl_hash[h]] != uid)
            h = (h + 1) & (RS_FACET_HASH - 1);
        if (cb->sl_hash[h] < 0) {
            cb->sl_hash[h] = nm;
            cb->sl_uid[nm] = uid;
            for (int d = 0; d < nd; d++)
                cb->sl_xyz[(size_t)nm * (size_t)nd + (size_t)d] =
                    cb->fac_xyz[3 * g + (size_t)d];
            nm++;
        }
        cb->sl_conn[j] = cb->sl_hash[h] + 1;
    }
    b->fac_nFacNod = nf;
    b->fac_nMstNod = nm;
    b->fac_jConMstid = cb->sl_conn;
    b->fac_shape = cb->fac_shape + (size_t)k0 * (size_t)nf;
    b->fac_jMstUid = cb->sl_uid;
    b->fac_coordMst = cb->sl_xyz;
}

int rs_cblock_call(rs_contact_block *cb, const rs_law *law, const rs_law_block *tmpl,
                   const rs_track_out *o, rs_error *err)
{
    const int nd = cb->ndir, ns = cb->nstatev, np = cb->npred;
    const int xm_dropped = (rs_law_drops(law) & RS_DROP_COORDMST) != 0;
    cb->law_sets = law ? law->sets : 0u;
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
        b.coordMst = xm_dropped ? NULL : o->coordmst + u0 * nd;
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
        b.slvRow = cb->has_row ? cb->row + u0 : NULL;
        if (cb->law_sets & RS_LAW_SETS_FORCE) {
            b.force = cb->force + u0 * 3;
            b.torque = cb->torque + u0 * 3;
        }
        b.stress = cb->stress + u0 * nd;
        b.statev = ns ? cb->statev + u0 * ns : NULL;
        b.fluxSlv = cb->flux_slv + u0;
        b.fluxMst = cb->flux_mst + u0;
        b.sed = cb->sed + u0;
        b.sfd = cb->sfd + u0;
        b.scd = cb->scd + u0;
        b.spd = cb->spd + u0;
        b.svd = cb->svd + u0;
        if (cb->nfac > 0)
            facet_slice(cb, k0, nk, nd, &b);
        const int rc = rs_law_call(law, &b, err);
        if (rc)
            return rc;
    }
    return RS_OK;
}
