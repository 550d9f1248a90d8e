/* The standalone explicit driver: central differences for slave nodes (points, spheres,
 * convex bodies) against one rigid master, the law called on the tracker's blocks
 * (driver.h). */
#include "rigidsurf/driver.h"
#include "driver_history.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static void *zalloc(size_t count, size_t size, int *ok)
{
    void *p = calloc(count ? count : 1, size);
    if (!p)
        *ok = 0;
    return p;
}

int rs_driver_init(rs_driver *d, const rs_surface *s, int n, rs_error *err)
{
    memset(d, 0, sizeof *d);
    if (!s || n < 1)
        return rs_error_set(err, RS_ERR_ARG,
                            "driver: need a surface and at least one node");
    d->n = n;
    d->surface = s;
    d->capacity = 4;
    rs_motion_init(&d->motion);
    rs_law_block_set_name(d->surfInt, "VUINTER");
    rs_law_block_set_name(d->surfSlv, "SLAVE");
    int ok = 1;
    size_t un = (size_t)n;
    d->x = zalloc(un, sizeof(double), &ok);
    d->y = zalloc(un, sizeof(double), &ok);
    d->z = zalloc(un, sizeof(double), &ok);
    d->vx = zalloc(un, sizeof(double), &ok);
    d->vy = zalloc(un, sizeof(double), &ok);
    d->vz = zalloc(un, sizeof(double), &ok);
    d->radius = zalloc(un, sizeof(double), &ok);
    d->mass = zalloc(un, sizeof(double), &ok);
    d->area = zalloc(un, sizeof(double), &ok);
    d->fext = zalloc(3 * un, sizeof(double), &ok);
    d->vpres = zalloc(3 * un, sizeof(double), &ok);
    d->fixed = zalloc(3 * un, sizeof(unsigned char), &ok);
    d->temp = zalloc(un, sizeof(double), &ok);
    d->heatcap = zalloc(un, sizeof(double), &ok);
    d->fcon = zalloc(3 * un, sizeof(double), &ok);
    d->q = zalloc(4 * un, sizeof(double), &ok);
    d->wx = zalloc(un, sizeof(double), &ok);
    d->wy = zalloc(un, sizeof(double), &ok);
    d->wz = zalloc(un, sizeof(double), &ok);
    d->inertia = zalloc(3 * un, sizeof(double), &ok);
    d->text = zalloc(3 * un, sizeof(double), &ok);
    d->tcon = zalloc(3 * un, sizeof(double), &ok);
    d->shape = zalloc(un, sizeof(const rs_shape *), &ok);
    d->owned = zalloc(un, sizeof(rs_shape), &ok);
    d->body = zalloc(un, sizeof(rs_body), &ok);
    d->temp_prev = zalloc(un, sizeof(double), &ok);
    d->dtemp = zalloc(un, sizeof(double), &ok);
    d->id = zalloc(un, sizeof(int), &ok);
    d->hist_ptr = zalloc(un, sizeof(double *), &ok);
    d->dir_ptr = zalloc(un, sizeof(double *), &ok);
    if (!ok) {
        rs_driver_free(d);
        return rs_error_set(err, RS_ERR_NOMEM, "driver: out of memory for %d nodes", n);
    }
    for (int i = 0; i < n; ++i) {
        d->mass[i] = 1.0;
        d->area[i] = 1.0;
        d->id[i] = i + 1;
        d->q[4 * i] = 1.0;
    }
    return RS_OK;
}

int rs_driver_set_law(rs_driver *d, const rs_law *law, const double *props, int nprops,
                      int nstatev, rs_error *err)
{
    if (!law)
        return rs_error_set(err, RS_ERR_ARG, "driver: no law given");
    if (nprops < 0 || nprops > (int)(sizeof d->props / sizeof d->props[0]))
        return rs_error_set(err, RS_ERR_ARG, "driver: %d properties, expected 0..%d",
                            nprops, (int)(sizeof d->props / sizeof d->props[0]));
    if (nstatev > RS_MAX_STATEV)
        return rs_error_set(err, RS_ERR_ARG,
                            "driver: %d state variables, expected at most %d", nstatev,
                            RS_MAX_STATEV);
    if (nstatev < law->nstatev)
        return rs_error_set(err, RS_ERR_ARG,
                            "driver: %d state variables, the law '%s' needs %d", nstatev,
                            law->name, law->nstatev);
    if (d->inc > 0)
        return rs_error_set(err, RS_ERR_ARG, "driver: the law is set before increment 1");
    int rc = rs_law_check_props(law, props, nprops, err);
    if (rc)
        return rc;
    d->law = law;
    d->nprops = nprops;
    if (nprops)
        memcpy(d->props, props, (size_t)nprops * sizeof(double));
    d->nstatev = nstatev;
    return RS_OK;
}

int rs_driver_set_body(rs_driver *d, int i, const rs_shape *shape, double density,
                       rs_error *err)
{
    if (!d || i < 0 || i >= d->n || !shape)
        return rs_error_set(err, RS_ERR_ARG, "driver: node %d of %d, or no shape", i,
                            d ? d->n : 0);
    if (d->inc > 0)
        return rs_error_set(err, RS_ERR_ARG, "driver: bodies are set before increment 1");
    rs_mass_props mp;
    int rc = rs_shape_mass_props(shape, density, &mp, err);
    if (rc)
        return rc;
    int principal = 1;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            principal &= mp.axes[3 * r + c] == (r == c ? 1.0 : 0.0);
    rs_shape_free(&d->owned[i]);
    if (!principal) {
        /* only a polyhedron has axes of its own: its hull turned into them, p' = A^T p */
        const int nv = shape->nv;
        double *pts = malloc(3 * (size_t)nv * sizeof *pts);
        if (!pts)
            return rs_error_set(err, RS_ERR_NOMEM, "driver: out of memory for node %d", i);
        for (int v = 0; v < nv; v++)
            for (int c = 0; c < 3; c++) {
                const double *p = shape->verts + 3 * v;
                pts[3 * v + c] =
                    mp.axes[c] * p[0] + mp.axes[3 + c] * p[1] + mp.axes[6 + c] * p[2];
            }
        rc = rs_shape_make_polyhedron(&d->owned[i], pts, nv, shape->rounding, err);
        free(pts);
        if (rc)
            return rc;
        shape = &d->owned[i];
    }
    d->shape[i] = shape;
    d->mass[i] = mp.mass;
    for (int k = 0; k < 3; k++)
        d->inertia[3 * i + k] = mp.principal[k];
    d->radius[i] = cbrt(3.0 * mp.volume / (4.0 * RS_PI));
    if (d->capacity < 16)
        d->capacity = 16;
    return RS_OK;
}

/* A slot as the tracker lays it out for the law (track.h): what the law reads of the
 * contact's last call, the energies included. */
static ptrdiff_t slot_stride(const rs_driver *d)
{
    return rs_track_slot_size(&d->tracker);
}

/* The nodes as one particle block, which the query, the tracker and the law's inputs
 * read (surface.h, rs_particle_block); the bodies in their pose of the increment. */
static rs_particle_block node_block(rs_driver *d)
{
    int bodies = 0;
    for (int i = 0; i < d->n; ++i) {
        rs_body *b = &d->body[i];
        b->shape = d->shape[i];
        if (!b->shape)
            continue;
        bodies = 1;
        b->x[0] = d->x[i], b->x[1] = d->y[i], b->x[2] = d->z[i];
        memcpy(b->q, d->q + 4 * (size_t)i, sizeof b->q);
        b->mass = d->mass[i];
        memcpy(b->inertia, d->inertia + 3 * (size_t)i, sizeof b->inertia);
        b->axes[0] = b->axes[4] = b->axes[8] = 1.0; /* a node's body axes are principal */
    }
    for (int i = 0; i < d->n; ++i)
        d->dtemp[i] = d->temp[i] - d->temp_prev[i];
    const rs_particle_block p = {.n = d->n,
                                 .x = d->x,
                                 .y = d->y,
                                 .z = d->z,
                                 .radius = d->radius,
                                 .body = bodies ? d->body : NULL,
                                 .vx = d->vx,
                                 .vy = d->vy,
                                 .vz = d->vz,
                                 .wx = d->wx,
                                 .wy = d->wy,
                                 .wz = d->wz,
                                 .id = d->id,
                                 .dir = d->dir_ptr,
                                 .hist = d->hist_ptr,
                                 .slot_stride = slot_stride(d),
                                 .mass = d->mass,
                                 .area = d->area,
                                 .heatcap = d->heatcap,
                                 .temp = d->temp,
                                 .dtemp = d->dtemp};
    return p;
}

/* The contacts of every node at x_k: one query of the block (driver.h, step 2). A list
 * with bodies keeps the witness points. */
static int query_nodes(rs_driver *d, const rs_particle_block *p, rs_error *err)
{
    rs_query q;
    memset(&q, 0, sizeof q);
    q.n = d->n;
    q.slave = *p;
    q.pose = &d->motion.pose;
    q.gap_max = d->tracking;
    q.dist_min = -INFINITY;
    d->contacts.n = 0;
    d->contacts.witness = p->body != NULL;
    return rs_surface_query(d->surface, &q, &d->contacts, err);
}

/* History storage, allocated on the first increment (capacity and nstatev are known):
 * per node its directory (capacity), then its slots. */
static int alloc_history(rs_driver *d, rs_error *err)
{
    d->tracker.capacity = d->capacity;
    d->tracker.nstatev = d->nstatev;
    d->tracker.ndir = rs_surface_ndir(d->surface);
    d->tracker.tracking = d->tracking;
    d->tracker.drop = rs_law_drops(d->law);
    const ptrdiff_t stride = slot_stride(d);
    size_t per = (size_t)d->capacity * (size_t)(1 + stride);
    free(d->hist); /* a first increment that failed and is tried again */
    d->hist = (double *)calloc((size_t)d->n * per, sizeof(double));
    if (!d->hist)
        return rs_error_set(err, RS_ERR_NOMEM, "driver: out of memory for contact history");
    for (int i = 0; i < d->n; ++i) {
        d->dir_ptr[i] = d->hist + (size_t)i * per;
        d->hist_ptr[i] = d->dir_ptr[i] + d->capacity;
        rs_track_clear(&d->tracker, d->dir_ptr[i], d->hist_ptr[i], stride);
        d->temp_prev[i] = d->temp[i];
    }
    d->tmaster_prev = d->tmaster;
    return RS_OK;
}

static int grow_contacts(rs_driver *d, int nc, int nd, rs_error *err)
{
    if (nc <= d->cb.cap && d->cb.ndir == nd)
        return RS_OK;
    int cap = d->cb.cap ? d->cb.cap : 64;
    while (cap < nc)
        cap *= 2;
    d->cb.area_mode = RS_AREA_NODE;
    d->cb.ndir = nd;
    d->cb.nstatev = d->nstatev;
    d->cb.npred = 0;
    return rs_cblock_reserve(&d->cb, cap, err);
}

/* The law on the tracker's contacts: previous stress and state from history
 * (rs_track_load), the per-contact inputs from the nodes (rs_cblock_inputs). */
static int call_law(rs_driver *d, const rs_particle_block *p, int nd, rs_error *err)
{
    const int ns = d->nstatev;
    rs_track_load(&d->tracker, &d->trk, rs_law_stress_in(d->law) ? d->cb.stress : NULL,
                  ns ? d->cb.statev : NULL);
    rs_cblock_inputs(&d->cb, &d->trk, p, d->dt);
    rs_track_load_energy(&d->tracker, &d->trk, d->cb.sed, d->cb.flux_slv, d->cb.flux_mst);

    /* One Abaqus step per driver; its increments count from 1, the call at t_k being
     * increment k + 1 from t_k to t_k + dt. */
    const double dtm = d->tmaster - d->tmaster_prev;
    rs_law_block b;
    rs_law_block_init(&b);
    b.kStep = 1;
    b.kInc = d->inc + 1;
    b.analytic_master = !rs_surface_has_facets(d->surface);
    b.nDir = nd;
    b.nSurfDir = nd - 1;
    b.nStateVar = ns;
    b.nProps = d->nprops;
    b.timStep = b.timGlb = d->t;
    b.dTimCur = d->dt;
    memcpy(b.surfInt, d->surfInt, RS_LAW_NAMELEN);
    memcpy(b.surfSlv, d->surfSlv, RS_LAW_NAMELEN);
    rs_law_block_set_name(b.surfMst, d->surface->name);
    b.props = d->props;
    b.tempMst = &d->tmaster;
    b.dtempMst = &dtm;
    b.warn = d->warn;
    b.warn_ctx = d->warn_ctx;
    if (!b.analytic_master && rs_law_takes_facets(d->law)) {
        const int rc = rs_cblock_facets(&d->cb, &d->trk, d->surface, &d->motion.pose, err);
        if (rc)
            return rc;
    }
    return rs_cblock_call(&d->cb, d->law, &b, &d->trk, err);
}

int rs_driver_step(rs_driver *d, rs_error *err)
{
    if (!d->law)
        return rs_error_set(err, RS_ERR_ARG, "driver: no law set");
    if (!(d->dt > 0.0))
        return rs_error_set(err, RS_ERR_ARG, "driver: dt = %g, expected > 0", d->dt);
    int rc;
    const int n = d->n, nd = rs_surface_ndir(d->surface);
    if (d->inc == 0) {
        rc = alloc_history(d, err);
        if (rc)
            return rc;
    } else {
        rc = rs_motion_advance(&d->motion, d->dt, err);
        if (rc)
            return rc;
    }
    if (d->bc) {
        rc = d->bc(d, d->t, d->bc_ctx, err);
        if (rc)
            return rc;
    }

    /* query and tracker at x_k with v_{k-1/2} */
    const rs_particle_block p = node_block(d);
    rc = query_nodes(d, &p, err);
    if (rc)
        return rc;
    /* The first call sees the initial state: no increment of motion lies behind it. */
    rc = rs_track_update(&d->tracker, d->surface, d->moving ? &d->motion : NULL,
                         d->inc == 0 ? 0.0 : d->dt, &p, &d->contacts, &d->trk, err);
    while (rc == RS_ERR_CAPACITY && d->capacity < RS_TRACK_MAX_CAPACITY) {
        /* the slots double, as an engine's do (the tracker changed nothing) */
        rc = rs_driver_grow_history(d, err);
        if (rc == RS_OK)
            rc = rs_track_update(&d->tracker, d->surface, d->moving ? &d->motion : NULL,
                                 d->inc == 0 ? 0.0 : d->dt, &p, &d->contacts, &d->trk, err);
    }
    if (rc)
        return rc;
    rc = grow_contacts(d, d->trk.n, nd, err);
    if (rc)
        return rc;
    rc = call_law(d, &p, nd, err);
    if (rc)
        return rc;
    const rs_contact_block *cb = &d->cb;

    /* contact forces and torques, heat and energies (rs_cblock_loads), scattered; before
     * the commit, which frees the slots of leaving contacts (they apply nothing) */
    const int ne = d->trk.n;
    if (ne > d->load_cap) {
        double *grown = realloc(d->load, 7 * (size_t)ne * sizeof(double));
        if (!grown)
            return rs_error_set(err, RS_ERR_NOMEM, "driver: out of memory for %d contacts",
                                ne);
        d->load = grown;
        d->load_cap = ne;
    }
    double *lf = d->load, *lt = lf + 3 * (size_t)ne, *lq = lt + 3 * (size_t)ne;
    double origin[3];
    rs_pose_to_global(&d->motion.pose, d->surface->a, origin);
    rs_wall_load wl;
    rs_cblock_loads(cb, &d->trk, &p, origin, lf, lt, lq, &wl);
    rs_track_commit_energy(&d->tracker, &d->trk, cb->sed, cb->flux_slv, cb->flux_mst);
    rs_track_commit(&d->tracker, &d->trk, cb->stress, d->nstatev ? cb->statev : NULL);
    memset(d->fcon, 0, 3 * (size_t)n * sizeof(double));
    memset(d->tcon, 0, 3 * (size_t)n * sizeof(double));
    double *qslv = d->temp_prev; /* reused below after the old temperatures are saved */
    for (int i = 0; i < n; ++i)
        qslv[i] = 0.0;
    for (int e = 0; e < ne; ++e) {
        const int i = d->trk.point[e];
        for (int c = 0; c < 3; ++c) {
            d->fcon[3 * i + c] += lf[3 * e + c];
            d->tcon[3 * i + c] += lt[3 * e + c];
        }
        qslv[i] += lq[e];
    }
    rs_driver_energy *en = &d->energy;
    en->allse = wl.se;
    en->allfd += wl.fd;
    en->allpd += wl.pd;
    en->allvd += wl.vd;
    en->allcd += wl.cd;
    en->heat_mst += wl.flux_mst * d->dt;
    const double qmst = wl.flux_mst;
    memcpy(d->fwall, wl.force, sizeof d->fwall);
    memcpy(d->mwall, wl.moment, sizeof d->mwall);

    /* central differences */
    double ke = 0.0;
    double *v[3] = {d->vx, d->vy, d->vz}, *x[3] = {d->x, d->y, d->z};
    for (int i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c) {
            double vc = v[c][i];
            if (d->fixed[3 * i + c])
                vc = d->vpres[3 * i + c];
            else if (d->mass[i] > 0.0)
                vc += d->dt * (d->fcon[3 * i + c] + d->fext[3 * i + c]) / d->mass[i];
            v[c][i] = vc;
            x[c][i] += d->dt * vc;
            ke += 0.5 * d->mass[i] * vc * vc;
        }
        double w[3] = {d->wx[i], d->wy[i], d->wz[i]}, tau[3];
        for (int c = 0; c < 3; ++c)
            tau[c] = d->tcon[3 * i + c] + d->text[3 * i + c];
        rs_rotation_step(d->q + 4 * i, w, d->inertia + 3 * i, tau, d->dt);
        d->wx[i] = w[0];
        d->wy[i] = w[1];
        d->wz[i] = w[2];
        ke += rs_rotation_energy(d->q + 4 * i, w, d->inertia + 3 * i);
    }
    en->allke = ke;

    /* heat, forward Euler */
    for (int i = 0; i < n; ++i) {
        const double qi = qslv[i] * d->dt;
        en->heat_slv += qi;
        qslv[i] = d->temp[i]; /* temp_prev now holds T_k */
        if (d->heatcap[i] > 0.0)
            d->temp[i] += qi / d->heatcap[i];
    }
    d->tmaster_prev = d->tmaster;
    if (d->heatcap_master > 0.0)
        d->tmaster += qmst * d->dt / d->heatcap_master;

    d->inc++;
    d->t = d->inc * d->dt;
    return RS_OK;
}

void rs_driver_free(rs_driver *d)
{
    if (!d)
        return;
    free(d->x);
    free(d->y);
    free(d->z);
    free(d->vx);
    free(d->vy);
    free(d->vz);
    free(d->radius);
    free(d->mass);
    free(d->area);
    free(d->fext);
    free(d->vpres);
    free(d->fixed);
    free(d->temp);
    free(d->heatcap);
    free(d->fcon);
    free(d->q);
    free(d->wx);
    free(d->wy);
    free(d->wz);
    free(d->inertia);
    free(d->text);
    free(d->tcon);
    free((void *)d->shape);
    for (int i = 0; d->owned && i < d->n; i++)
        rs_shape_free(&d->owned[i]);
    free(d->owned);
    free(d->body);
    free(d->temp_prev);
    free(d->id);
    free(d->hist_ptr);
    free(d->dir_ptr);
    free(d->hist);
    free(d->dtemp);
    free(d->load);
    rs_cblock_free(&d->cb);
    rs_track_out_free(&d->trk);
    rs_contacts_free(&d->contacts);
    memset(d, 0, sizeof *d);
}
