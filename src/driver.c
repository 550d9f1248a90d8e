/* The standalone explicit driver: central differences for slave nodes (points, spheres,
 * convex bodies) against one rigid master, the law called on the tracker's blocks
 * (driver.h). */
#include "rigidsurf/driver.h"
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
    d->id = zalloc(un, sizeof(int), &ok);
    d->xv = zalloc(10 * un, sizeof(double), &ok);
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

/* The bodies in their pose of the increment; 1 when a node is one. */
static int pose_bodies(rs_driver *d)
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
    return bodies;
}

/* The nodes as the wall reads them at x_k with v_{k-1/2}: every node in one block. */
static rs_wall_block node_block(rs_driver *d)
{
    const int n = d->n;
    double *x = d->xv, *v = x + 3 * (size_t)n, *w = v + 3 * (size_t)n;
    for (int i = 0; i < n; ++i) {
        x[3 * i] = d->x[i], x[3 * i + 1] = d->y[i], x[3 * i + 2] = d->z[i];
        v[3 * i] = d->vx[i], v[3 * i + 1] = d->vy[i], v[3 * i + 2] = d->vz[i];
        w[3 * i] = d->wx[i], w[3 * i + 1] = d->wy[i], w[3 * i + 2] = d->wz[i];
    }
    rs_wall_block b;
    memset(&b, 0, sizeof b);
    b.n = n;
    b.x = x;
    b.v = v;
    b.omega = w;
    b.radius = d->radius;
    b.mass = d->mass;
    b.id = d->id;
    b.temp = d->temp;
    b.heatcap = d->heatcap;
    b.area = d->area;
    b.body = pose_bodies(d) ? d->body : NULL;
    b.step = d->inc;
    b.inc = d->inc + 1;
    b.time = d->t;
    /* The first call sees the initial state: no increment of motion lies behind it. */
    b.still = d->inc == 0;
    return b;
}

/* A name the law sees, blank-padded to RS_LAW_NAMELEN, as a string. */
static void law_name(const char src[RS_LAW_NAMELEN], char dst[RS_LAW_NAMELEN + 1])
{
    int k = RS_LAW_NAMELEN;
    while (k > 0 && src[k - 1] == ' ')
        k--;
    memcpy(dst, src, (size_t)k);
    dst[k] = '\0';
}

/* The wall over the master, made on the first increment (the law, capacity and tracking
 * thickness are known): every node a candidate at every step, its contacts at any depth,
 * one Abaqus step whose increments count from 1. */
static int make_wall(rs_driver *d, rs_error *err)
{
    char inter[RS_LAW_NAMELEN + 1], slave[RS_LAW_NAMELEN + 1];
    law_name(d->surfInt, inter);
    law_name(d->surfSlv, slave);
    rs_wall_def def;
    memset(&def, 0, sizeof def);
    def.surface = d->surface;
    def.law = d->law;
    def.props = d->props;
    def.nprops = d->nprops;
    def.nstatev = d->nstatev;
    def.capacity = d->capacity;
    def.tracking = d->tracking;
    def.area_mode = RS_AREA_NODE;
    def.area_const = 1.0;
    def.temperature = d->tmaster;
    def.interaction = inter;
    def.slave = slave;
    def.master = d->surface->name;
    def.motion = &d->motion;
    def.moving = d->moving;
    def.warn = d->warn;
    def.warn_ctx = d->warn_ctx;
    int rc = rs_wall_make(&def, NULL, &d->wall, err);
    if (rc)
        return rc;
    rs_wall_run run;
    memset(&run, 0, sizeof run);
    run.dt = d->dt;
    run.every_particle = 1;
    run.has_temp = run.has_heatflux = 1;
    rs_surface_bounds(d->surface, run.box_lo, run.box_hi);
    if ((rc = rs_wall_grow(d->wall, d->n, err)))
        return rc;
    const rs_wall_block b = node_block(d);
    if ((rc = rs_wall_init(d->wall, &run, &b, err)))
        return rc;
    d->tmaster_prev = d->tmaster;
    return RS_OK;
}

int rs_driver_step(rs_driver *d, rs_error *err)
{
    if (!d->law)
        return rs_error_set(err, RS_ERR_ARG, "driver: no law set");
    if (!(d->dt > 0.0))
        return rs_error_set(err, RS_ERR_ARG, "driver: dt = %g, expected > 0", d->dt);
    int rc;
    const int n = d->n;
    if (d->inc == 0 && !d->wall) {
        rc = make_wall(d, err);
        if (rc) { /* a retry starts from no wall */
            rs_wall_free(d->wall);
            d->wall = NULL;
            return rc;
        }
    } else if (d->inc > 0) {
        rc = rs_motion_advance(&d->motion, d->dt, err);
        if (rc)
            return rc;
    }
    if (d->bc) {
        rc = d->bc(d, d->t, d->bc_ctx, err);
        if (rc)
            return rc;
    }

    /* the contacts at x_k with v_{k-1/2}, their law and loads; the master's temperature
     * and its change over the last increment */
    const rs_wall_block b = node_block(d);
    double *qslv = d->xv + 9 * (size_t)n;
    memset(d->fcon, 0, 3 * (size_t)n * sizeof(double));
    memset(d->tcon, 0, 3 * (size_t)n * sizeof(double));
    memset(qslv, 0, (size_t)n * sizeof(double));
    rs_wall_rows rows;
    memset(&rows, 0, sizeof rows);
    rows.f = d->fcon;
    rows.torque = d->tcon;
    rows.heatflux = qslv;
    rs_wall_set_temperature(d->wall, d->tmaster, d->tmaster - d->tmaster_prev);
    rs_wall_load wl;
    rc = rs_wall_step(d->wall, &b, &rows, d->dt, &wl, err);
    if (rc)
        return rc;
    rs_wall_last(d->wall, &d->trk, &d->cb);
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
    free(d->id);
    free(d->xv);
    rs_wall_free(d->wall); /* and with it the contacts of d->trk and d->cb */
    memset(d, 0, sizeof *d);
}
