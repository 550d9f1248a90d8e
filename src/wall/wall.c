/* The wall's life: made from words or from a definition, a run's setup (the tracking
 * thickness, the material properties, what may take the law's fused kernel), the setup
 * call's forces, the end of a run, its outputs; freed. The step itself: wall_step.c. */
#include "wall_impl.h"

#include "faceted/mesh_held.h"
#include "line_revolution.h"
#include "rigidsurf/vec.h"
#include "track_fused.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FAIL(...) return rs_error_set(err, RS_ERR_ARG, __VA_ARGS__)

static rs_wall *wall_new(const char *id, const char *group, const rs_wall_host *host)
{
    rs_wall *w = calloc(1, sizeof *w);
    if (!w)
        return NULL;
    if (host)
        w->host = *host;
    snprintf(w->id, sizeof w->id, "%s", id ? id : "VUINTER");
    snprintf(w->group, sizeof w->group, "%s", group ? group : "SLAVE");
    rs_motion_init(&w->motion_own);
    w->motion = &w->motion_own;
    w->capacity = 4;
    w->info.wall_type = 1;
    w->area_mode = WALL_AREA_NODE;
    w->area_const = 1.0;
    w->fused_given = 1;
    w->ivar_vel[0] = w->ivar_vel[1] = w->ivar_vel[2] = -1;
    w->ivar_disp[0] = w->ivar_disp[1] = w->ivar_disp[2] = -1;
    w->ivar_omega = w->ivar_spin = -1;
    w->servo.axis[2] = 1.0;
    w->servo.kp = 1e-2;
    w->servo.ivar = -1;
    w->rebuild = 1;
    rs_law_block_init(&w->blk);
    rs_law_requests_clear(&w->requests);
    return w;
}

/* What follows the words or the definition: the tracker, the wall's temperature, the
 * names the law sees, what the engine reads. */
static void finish(rs_wall *w)
{
    w->ndir = rs_surface_ndir(w->surf);
    w->tracker.capacity = w->capacity;
    w->tracker.nstatev = w->nstatev;
    w->tracker.drop = rs_law_drops(w->law);
    w->tracker.ndir = w->ndir;
    w->tracker.tracking = w->tracking;
    w->temp_mst[0] = w->temp_wall;
    w->dtemp_mst[0] = 0.0;
    if (w->store_force && !w->wallforce_id[0])
        snprintf(w->wallforce_id, sizeof w->wallforce_id, "force_%s", w->id);
    rs_wall_info *in = &w->info;
    in->moving = w->moving;
    in->servo = w->servo.on;
    in->peratom = w->peratom;
    in->store_force = w->store_force;
    in->store_force_id = w->wallforce_id;
    in->npred = w->npred;
    in->pred = (const char *const *)w->pred_names;
    in->vtk_every = w->vtk_every;
    in->temperature = w->temp_given;
    in->conduction = w->conduction;
    in->law = w->law;
    in->fused = w->fused_given;
}

int rs_wall_create(const char *id, const char *group, const char *const *words, int nwords,
                   const rs_wall_host *host, rs_wall **out, rs_error *err)
{
    *out = NULL;
    if (nwords < 1)
        FAIL("expected 'fix ID group wall/rigid surface FILE law LAW [keyword value ...]'");
    rs_wall *w = wall_new(id, group, host);
    if (!w)
        return rs_error_set(err, RS_ERR_NOMEM, "out of memory for the wall");
    const int rc = wall_parse(w, words, nwords, err);
    if (rc) {
        rs_wall_free(w);
        return rc;
    }
    snprintf(w->names[0], sizeof w->names[0], "%s", w->id);
    snprintf(w->names[1], sizeof w->names[1], "%s", w->group);
    snprintf(w->names[2], sizeof w->names[2], "%s",
             w->surf->name[0] ? w->surf->name : w->id);
    finish(w);
    *out = w;
    return RS_OK;
}

int rs_wall_make(const rs_wall_def *def, const rs_wall_host *host, rs_wall **out,
                 rs_error *err)
{
    *out = NULL;
    if (!def || !def->surface || !def->law)
        FAIL("wall: a surface and a law are needed");
    if (def->nstatev < def->law->nstatev || def->nstatev > RS_MAX_STATEV)
        FAIL("wall: %d state variables, the law '%s' needs %d (at most %d)", def->nstatev,
             def->law->name, def->law->nstatev, RS_MAX_STATEV);
    if (def->capacity < 0 || def->capacity > RS_TRACK_MAX_CAPACITY)
        FAIL("wall: a capacity of %d, expected 1..%d", def->capacity,
             RS_TRACK_MAX_CAPACITY);
    int rc = rs_law_check_props(def->law, def->props, def->nprops, err);
    if (rc)
        return rc;
    rs_wall *w = wall_new(def->interaction, def->slave, host);
    if (!w)
        return rs_error_set(err, RS_ERR_NOMEM, "out of memory for the wall");
    w->surf = def->surface;
    w->law = def->law;
    w->law_kind = WALL_LAW_BUILTIN;
    snprintf(w->law_name, sizeof w->law_name, "%s", def->law->name);
    if (def->nprops > 0) {
        w->props = malloc((size_t)def->nprops * sizeof *w->props);
        if (!w->props) {
            rs_wall_free(w);
            return rs_error_set(err, RS_ERR_NOMEM, "out of memory for the wall");
        }
        memcpy(w->props, def->props, (size_t)def->nprops * sizeof *w->props);
    }
    w->nprops = def->nprops;
    w->props_given = 1;
    w->nstatev = def->nstatev;
    if (def->capacity > 0)
        w->capacity = def->capacity;
    w->tracking = def->tracking;
    w->tracking_given = def->tracking >= 0.0;
    w->area_mode = def->area_mode == RS_AREA_CONSTANT    ? WALL_AREA_CONSTANT
                   : def->area_mode == RS_AREA_PROJECTED ? WALL_AREA_PROJECTED
                                                         : WALL_AREA_NODE;
    w->area_const = def->area_const;
    w->info.wall_type = def->wall_type;
    w->temp_wall = def->temperature;
    w->capacity_wall = def->heat_capacity;
    if (def->motion)
        w->motion = def->motion;
    w->moving = def->moving;
    w->warn = def->warn;
    w->warn_ctx = def->warn_ctx;
    snprintf(w->names[0], sizeof w->names[0], "%s", w->id);
    snprintf(w->names[1], sizeof w->names[1], "%s", w->group);
    snprintf(w->names[2], sizeof w->names[2], "%s",
             def->master ? def->master : def->surface->name);
    finish(w);
    *out = w;
    return RS_OK;
}

static void free_scratch(rs_wall *w)
{
    double **d[] = {&w->bx,    &w->by,    &w->bz,     &w->bvx,   &w->bvy,    &w->bvz,
                    &w->bwx,   &w->bwy,   &w->bwz,    &w->brad,  &w->bgap,   &w->bmass,
                    &w->bheat, &w->btemp, &w->bdtemp, &w->bpred, &w->bdpred, &w->barea};
    for (size_t k = 0; k < sizeof d / sizeof d[0]; k++) {
        free(*d[k]);
        *d[k] = NULL;
    }
    int **i[] = {&w->bid, &w->btype, &w->bidx, &w->deepest, &w->bncand, &w->bhint};
    for (size_t k = 0; k < sizeof i / sizeof i[0]; k++) {
        free(*i[k]);
        *i[k] = NULL;
    }
    free(w->bdir);
    free(w->bhist);
    free(w->bcand);
    free(w->leaving);
    free(w->take);
    free(w->area_w);
    free(w->bbody);
    free(w->saved_rows);
    w->bdir = w->bhist = NULL;
    w->bcand = NULL;
    w->leaving = w->take = NULL;
    w->area_w = NULL;
    w->bbody = NULL;
    w->saved_rows = NULL;
    w->bcap = 0;
}

void rs_wall_free(rs_wall *w)
{
    if (!w)
        return;
    free_scratch(w);
    rs_contacts_free(&w->contacts);
    rs_cands_free(&w->cands);
    rs_track_out_free(&w->tout);
    rs_cblock_free(&w->cb);
    rs_trimesh_free(&w->vtk_mesh);
    if (w->loaded_ok)
        rs_law_unload(&w->loaded);
    if (w->surf == &w->surf_own)
        rs_surface_free(&w->surf_own);
    for (int a = 0; a < w->npred; a++)
        free(w->pred_names[a]);
    free(w->pred_names);
    double *arrays[] = {w->props,        w->type_props, w->heatcap_type, w->th_cond,
                        w->deltan_ratio, w->elem_area,  w->elem_n,       w->elem_f,
                        w->wear_el,      w->kfinnie,    w->xref,         w->gapref};
    for (size_t k = 0; k < sizeof arrays / sizeof arrays[0]; k++)
        free(arrays[k]);
    free(w->type_has);
    free(w->inline_text);
    free(w->vtk_file);
    free(w->rows);
    free(w->hist);
    free(w->usual);
    free(w->hball);
    free(w->cand);
    free(w->active);
    free(w->cfirst);
    free(w->cnum);
    free(w->cids);
    free(w);
}

const rs_wall_info *rs_wall_get_info(const rs_wall *w)
{
    return &w->info;
}

/* ---------------------------------------------------------------------------------- */
/* A run                                                                              */

/* hertz or hooke without props: the engine's material properties of the particle type
 * and the wall type, looked up as fix wall/gran looks them up (global_properties.cpp):
 * hertz's last property is the curvature flag, hooke's the characteristic velocity. */
static int init_material_props(rs_wall *w, rs_error *err)
{
    const double curv = w->nprops ? w->props[0] : 0.0;
    const char *who =
        w->hooke ? "fix wall/rigid (law hooke)" : "fix wall/rigid (law hertz)";
    const int nt = w->host.ntypes > 0 ? w->host.ntypes : 1, wt = w->info.wall_type;
    int rc;
    double last = curv;
    if (!w->host.material)
        FAIL("law %s without 'props' reads the engine's material properties "
             "(youngsModulus, poissonsRatio, coefficientRestitution, coefficientFriction), "
             "which this engine does not give",
             w->law->name);
    w->tp_n = 7;
    free(w->type_props);
    free(w->type_has);
    w->type_props = calloc((size_t)(nt + 1) * 7, sizeof *w->type_props);
    w->type_has = calloc((size_t)nt + 1, 1);
    double *one = realloc(w->props, sizeof *w->props);
    if (!w->type_props || !w->type_has || !one)
        return rs_error_set(err, RS_ERR_NOMEM, "out of memory for the material properties");
    w->props = one;
    w->ntype_props = nt + 1;
    for (int t = 1; t <= nt; t++) {
        double *v = w->type_props + 7 * (size_t)t;
        struct {
            const char *name;
            int i, j;
        } q[6] = {{"youngsModulus", t, 0},           {"poissonsRatio", t, 0},
                  {"youngsModulus", wt, 0},          {"poissonsRatio", wt, 0},
                  {"coefficientRestitution", t, wt}, {"coefficientFriction", t, wt}};
        int have = 1;
        for (int k = 0; k < 6 && have; k++) {
            rc = w->host.material(w->host.ctx, q[k].name, q[k].i, q[k].j, 1, who, &v[k],
                                  err);
            if (rc == RS_ERR_NOTFOUND)
                have = 0; /* beyond the types the properties cover */
            else if (rc)
                return rc;
        }
        /* hooke: the characteristic velocity of LIGGGHTS's hooke model, a global scalar */
        if (t == 1 && w->hooke &&
            (rc = w->host.material(w->host.ctx, "characteristicVelocity", 0, 0, 1, who,
                                   &last, err)))
            return rc;
        if (!have)
            continue;
        v[6] = last;
        rs_error e;
        rs_error_clear(&e);
        if (rs_law_check_props(w->law, v, 7, &e) != RS_OK)
            FAIL("material properties of particle type %d against wall type %d: %s", t, wt,
                 e.msg);
        w->type_has[t] = 1;
    }
    w->nprops = 1;
    w->props[0] = curv;
    return RS_OK;
}

/* The particles' heat capacities per type (thermalCapacity), where the engine keeps
 * temperatures and has them. */
static int init_heat(rs_wall *w, rs_error *err)
{
    free(w->heatcap_type);
    w->heatcap_type = NULL;
    if (!w->run.has_temp || !w->host.material)
        return RS_OK;
    const int nt = w->host.ntypes > 0 ? w->host.ntypes : 1;
    double v;
    int rc =
        w->host.material(w->host.ctx, "thermalCapacity", 1, 0, 0, "wall/rigid", &v, err);
    if (rc == RS_ERR_NOTFOUND)
        return RS_OK;
    if (rc)
        return rc;
    w->heatcap_type = calloc((size_t)nt + 1, sizeof *w->heatcap_type);
    if (!w->heatcap_type)
        return rs_error_set(err, RS_ERR_NOMEM, "out of memory for the heat capacities");
    for (int t = 1; t <= nt; t++) {
        rc = w->host.material(w->host.ctx, "thermalCapacity", t, 0, 0, "wall/rigid",
                              &w->heatcap_type[t], err);
        if (rc && rc != RS_ERR_NOTFOUND)
            return rc;
    }
    return RS_OK;
}

/* A surface of revolution spun about its own axis keeps its shape in space: the rotation
 * then never moves it toward a particle. */
static int spun_in_place(const rs_wall *w)
{
    double sa_origin[3], sa_axis[3];
    if (!w->moving || !rs_surface_spin_axis(w->surf, sa_origin, sa_axis))
        return 0;
    const rs_motion *m = w->motion;
    double ax[3], r[3], rx[3];
    rs_cross3(m->axis, sa_axis, ax);
    for (int d = 0; d < 3; d++)
        r[d] = m->center0[d] - sa_origin[d];
    rs_cross3(r, sa_axis, rx);
    double l2 = 0.0;
    for (int d = 0; d < 3; d++)
        l2 += (w->run.box_hi[d] - w->run.box_lo[d]) * (w->run.box_hi[d] - w->run.box_lo[d]);
    const double scale = fmax(1.0, sqrt(l2));
    return rs_norm3(ax) < 1e-12 && rs_norm3(rx) < 1e-12 * scale && !m->spin_on;
}

int rs_wall_init(rs_wall *w, const rs_wall_run *run, const rs_wall_block *b, rs_error *err)
{
    w->run = *run;
    int rc;
    /* Default tracking: the law's reach (0 for a law of touching contacts), else the
     * neighbour skin. */
    if (!w->tracking_given) {
        const double reach =
            w->law->reach ? w->law->reach(w->law, w->nprops ? w->props : NULL, w->nprops)
                          : -1.0;
        w->tracking = reach >= 0.0 ? reach : run->skin;
    }
    w->tracker.tracking = w->tracking;
    w->spin_invariant = spun_in_place(w);
    /* Distance bounds hold while the surface stays where it is in space: at rest, or spun
     * about its own axis without translation. A kind with candidate lists (MESH) takes
     * them from its lists instead: the query's look-ahead would widen every list by a
     * skin. */
    const rs_motion *m = w->motion;
    int translates =
        w->var_vel[0][0] || w->var_vel[1][0] || w->var_vel[2][0] || m->place != NULL;
    for (int d = 0; d < 3; d++)
        translates = translates || m->vel[d] != 0.0;
    const int still = !w->moving || (w->spin_invariant && !translates && !w->servo.on);
    const int lists = rs_surface_has_candidates(w->surf);
    w->bounds_ok = still && !lists && !run->every_particle;
    w->list_bounds = still && lists && !run->every_particle;
    w->lookahead = w->bounds_ok ? run->skin : 0.0;
    if (wall_material_props(w) && (rc = init_material_props(w, err)))
        return rc;
    if ((rc = wall_init_variables(w, err)))
        return rc;
    if (w->servo.on && (rc = wall_init_servo(w, b, err)))
        return rc;
    if ((rc = init_heat(w, err)) || (rc = wall_init_conduction(w, err)))
        return rc;
    if (w->vtk_every > 0 && !w->vtk_mesh_ok && (rc = wall_init_vtk(w, err)))
        return rc;
    if ((rc = wall_init_facets(w, err)))
        return rc;
    /* The law's fused kernel on the usual blocks: a law that has one, on unit areas, with
     * nothing that reads the staged arrays afterwards (conduction, a mesh's facets), and
     * not switched off (keyword fused). */
    const int fusable = w->fused_given && !w->conduction && !w->facets &&
                        (w->area_mode == WALL_AREA_NODE ||
                         (w->area_mode == WALL_AREA_CONSTANT && w->area_const == 1.0));
    w->fused_ok = fusable && w->law->fused;
    /* ... or a force law's model on a run of contacts or per contact (rs_law.force_run,
     * force_one), whose contacts' slots keep the frame and the state variables alone
     * (wall_force_line.c) ... */
    w->line_force = fusable && !w->law->fused && (w->law->force_run || w->law->force_one) &&
                    wall_force_line_takes(w);
    /* ... and on a revolved LINE, or on a MESH from the faces its spheres hold (with its
     * candidate lists for the rest), per run of spheres without the block's columns. */
    w->line_mesh = lists && rs_mesh_held(w->surf);
    w->line_pass = ((w->fused_ok && w->law->fused->line) || w->line_force) && !w->belt &&
                   ((rs_line_revolution(w->surf) && !lists) || w->line_mesh) &&
                   !run->every_particle;
    if (run->exchange_max > 0 && 1 + wall_atom_size(w) > run->exchange_max)
        FAIL("each atom would carry %d doubles of contact history (%d contacts x (%d + %d "
             "state variables) and %d more) through the engine's atom exchange, whose "
             "buffer leaves room for %d; lower 'contacts' or the state variables",
             1 + wall_atom_size(w), w->capacity, wall_slot_size(w) - w->nstatev, w->nstatev,
             1 + wall_row_size(w), run->exchange_max);
    /* A run that asks every particle takes them in one block, at least RS_BLOCK wide: an
     * engine's rank that starts with few or none may receive many later. */
    const int bcap = run->every_particle && b->n > RS_BLOCK ? b->n : RS_BLOCK;
    if ((rc = wall_scratch(w, bcap, err)))
        return rc;
    w->rebuild = 1;
    w->run_ok = 1;
    return RS_OK;
}

/* The block's per-contact scratch, for bcap particles of capacity contacts each (the
 * tracker never emits more: a particle with more contacts than slots is an error), and
 * the setup call's saved histories; made again when the capacity grows. */
int wall_scratch_contacts(rs_wall *w, rs_error *err)
{
    const size_t nc = (size_t)w->bcap * (size_t)w->capacity;
    free(w->leaving);
    free(w->area_w);
    free(w->saved_rows);
    w->leaving = calloc(nc, sizeof *w->leaving);
    w->area_w = calloc(nc, sizeof *w->area_w);
    w->saved_rows = calloc((size_t)w->bcap * (size_t)wall_atom_size(w), sizeof(double));
    if (!w->leaving || !w->area_w || !w->saved_rows)
        return rs_error_set(err, RS_ERR_NOMEM, "out of memory for a block of %d particles",
                            w->bcap);
    w->cb.area_mode = w->area_mode == WALL_AREA_CONSTANT    ? RS_AREA_CONSTANT
                      : w->area_mode == WALL_AREA_PROJECTED ? RS_AREA_PROJECTED
                                                            : RS_AREA_NODE;
    w->cb.area_const = w->area_const;
    w->cb.ndir = w->ndir;
    w->cb.nstatev = w->nstatev;
    w->cb.npred = w->npred;
    const int rc = rs_cblock_reserve(&w->cb, (int)nc, err);
    if (rc)
        return rc;
    w->cbcap = (int)nc;
    return RS_OK;
}

/* Scratch of one block, sized for np particles, so the step itself allocates and fills
 * nothing it does not need; and the law block's fields that stay for the run. */
int wall_scratch(rs_wall *w, int np, rs_error *err)
{
    if (np < 1)
        np = 1;
    const size_t n = (size_t)np;
    const size_t npred = w->npred > 0 ? (size_t)w->npred : 1;
    free_scratch(w);
    int ok = 1;
#define ALLOC(p, count) ok = ok && ((p) = calloc((count), sizeof *(p))) != NULL
    ALLOC(w->bx, n);
    ALLOC(w->by, n);
    ALLOC(w->bz, n);
    ALLOC(w->bvx, n);
    ALLOC(w->bvy, n);
    ALLOC(w->bvz, n);
    ALLOC(w->bwx, n);
    ALLOC(w->bwy, n);
    ALLOC(w->bwz, n);
    ALLOC(w->brad, n);
    ALLOC(w->bgap, n);
    ALLOC(w->bmass, n);
    ALLOC(w->bheat, n);
    ALLOC(w->btemp, n);
    ALLOC(w->bdtemp, n);
    ALLOC(w->barea, n);
    ALLOC(w->bpred, n * npred);
    ALLOC(w->bdpred, n * npred);
    ALLOC(w->bid, n);
    ALLOC(w->btype, n);
    ALLOC(w->bidx, n);
    ALLOC(w->deepest, n);
    ALLOC(w->bncand, n);
    ALLOC(w->bhint, n);
    ALLOC(w->bdir, n);
    ALLOC(w->bhist, n);
    ALLOC(w->bcand, n);
    ALLOC(w->take, n);
    ALLOC(w->bbody, n);
#undef ALLOC
    if (!ok) {
        free_scratch(w);
        return rs_error_set(err, RS_ERR_NOMEM, "out of memory for a block of %d particles",
                            np);
    }
    w->bcap = np;
    const int rc = wall_scratch_contacts(w, err);
    if (rc)
        return rc;

    /* The law block's fields that stay for the run. */
    rs_law_block *blk = &w->blk;
    rs_law_block_init(blk);
    blk->kStep = 1;
    blk->nSurfDir = w->ndir - 1;
    blk->nDir = w->ndir;
    blk->nStateVar = w->nstatev;
    blk->nPred = w->npred;
    rs_law_block_set_name(blk->surfInt, w->names[0]);
    rs_law_block_set_name(blk->surfSlv, w->names[1]);
    rs_law_block_set_name(blk->surfMst, w->names[2]);
    blk->tempMst = w->temp_mst;
    blk->dtempMst = w->dtemp_mst;
    blk->wall_type = w->info.wall_type;
    blk->analytic_master = !rs_surface_has_facets(w->surf);
    blk->warn = w->warn;
    blk->warn_ctx = w->warn_ctx;
    return RS_OK;
}

/* Once per wall, as LIGGGHTS checks its own contact models: a warning when the time step
 * exceeds RS_STEP_FRACTION of the law's critical step (rs_law_critical_step_fn) for the
 * smallest value over the group's particles. A law without one is not checked. */
static void check_step(rs_wall *w, const rs_wall_block *b)
{
    w->step_checked = 1;
    if (!w->law->critical_step)
        return;
    double tmin = INFINITY;
    for (int i = 0; i < b->n; i++) {
        if (!wall_in_group(b, i))
            continue;
        const double R = b->radius[i];
        const double A = w->area_mode == WALL_AREA_CONSTANT    ? w->area_const
                         : w->area_mode == WALL_AREA_PROJECTED ? RS_PI * R * R
                                                               : 1.0;
        const double *pv = w->props;
        int np = w->nprops;
        const int t = b->type ? b->type[i] : 1;
        if (wall_material_props(w) && t < w->ntype_props) {
            pv = w->type_props + (size_t)t * (size_t)w->tp_n;
            np = w->tp_n;
        }
        const double s = w->law->critical_step(w->law, pv, np, R, b->mass[i], A);
        if (s > 0.0)
            tmin = fmin(tmin, s);
    }
    const double tall = wall_reduce1(w, tmin, RS_REDUCE_MIN), dt = w->run.dt;
    if (isfinite(tall) && dt > RS_STEP_FRACTION * tall)
        wall_warn(w,
                  "Fix wall/rigid %s: time step %g is %g of the critical step %g of law "
                  "'%s'%s; contacts with the wall may be unstable above %g",
                  w->id, dt, dt / tall, tall, w->law->name,
                  w->hertz ? " (Rayleigh time)" : " (2 sqrt(m/k))", RS_STEP_FRACTION);
}

/* Forces without history: DEM walls compute setup forces with the shear history frozen.
 * Each run is an Abaqus step: the setup starts step kstep and its step time. The law
 * sees the setup call as increment 1 of the step (a user routine never gets KINC = 0);
 * what it asks of the step there (PNEWDT) is not counted, as the call is not an
 * increment. */
int rs_wall_setup(rs_wall *w, const rs_wall_block *b, const rs_wall_rows *rows,
                  rs_wall_load *out, rs_error *err)
{
    w->kstep++;
    w->run_time0 = b->time;
    rs_law_requests_clear(&w->requests);
    if (!w->step_checked)
        check_step(w, b);
    int rc = wall_conduction_ratios(w, err);
    if (rc)
        return rc;
    rc = wall_compute(w, b, rows, w->run.dt, 1, err);
    if (rc)
        return rc;
    w->conduct_ready = 1;
    if (w->vtk_every > 0 && b->step % w->vtk_every == 0 &&
        (rc = wall_write_vtk(w, b->step, err)))
        return rc;
    if (out) {
        memset(out, 0, sizeof *out);
        for (int d = 0; d < 3; d++)
            out->force[d] = w->f_wall[d], out->moment[d] = w->m_wall[d];
        out->se = w->se_now;
        out->ncontact = w->ncontact;
    }
    return RS_OK;
}

int rs_wall_step(rs_wall *w, const rs_wall_block *b, const rs_wall_rows *rows, double dt,
                 rs_wall_load *out, rs_error *err)
{
    int rc = wall_compute(w, b, rows, dt, 0, err);
    if (rc)
        return rc;
    if (w->vtk_every > 0 && b->step % w->vtk_every == 0 &&
        (rc = wall_write_vtk(w, b->step, err)))
        return rc;
    if (out) {
        for (int d = 0; d < 3; d++)
            out->force[d] = w->f_wall[d], out->moment[d] = w->m_wall[d];
        out->se = w->se_now;
        out->fd = w->fd_step, out->pd = w->pd_step, out->vd = w->vd_step;
        out->cd = w->cd_step;
        out->flux_slv = w->qs_step;
        out->flux_mst = w->heat_step;
        out->ncontact = w->ncontact;
    }
    return RS_OK;
}

void rs_wall_reneighbor(rs_wall *w)
{
    w->rebuild = 1;
}

/* At the end of a run, over all ranks: one warning with the smallest PNEWDT < 1 the law's
 * user routine returned, the step it suggests (dt PNEWDT) and how many calls asked; and
 * once per wall, as check_step, a warning when the time step exceeds RS_STEP_FRACTION of
 * the critical step 2 sqrt(m / (k A)) of the stiffness the routine returned (DDSDDR,
 * DDTDDG). */
void rs_wall_end_run(rs_wall *w)
{
    const rs_law_requests *r = &w->requests;
    const double mine = r->pnewdt_calls > 0 ? r->pnewdt_min : INFINITY;
    const double least = wall_reduce1(w, mine, RS_REDUCE_MIN);
    const double all_calls = wall_reduce1(w, (double)r->pnewdt_calls, RS_REDUCE_SUM);
    /* where: the lowest rank that holds the smallest value says its particle and feature */
    const double me = mine == least ? (double)w->host.rank : INFINITY;
    const double owner = wall_reduce1(w, me, RS_REDUCE_MIN);
    double where[2] = {-INFINITY, -INFINITY};
    if ((double)w->host.rank == owner)
        where[0] = r->pnewdt_particle, where[1] = r->pnewdt_feature;
    if (all_calls > 0.0 && w->host.reduce)
        w->host.reduce(w->host.ctx, where, 2, RS_REDUCE_MAX);
    const double step_all = wall_reduce1(w, r->step_min, RS_REDUCE_MIN), dt = w->run.dt;
    if (all_calls > 0.0)
        wall_warn(w,
                  "Fix wall/rigid %s: law '%s': %.6g call(s) of the user routine asked for "
                  "a smaller increment this run (PNEWDT < 1), the smallest PNEWDT = %g at "
                  "particle %d, feature %d, which suggests a time step of %g; an explicit "
                  "step cannot repeat an increment (keyword 'pnewdt stop' makes this an "
                  "error)",
                  w->id, w->law->name, all_calls, least, (int)where[0], (int)where[1],
                  dt * least);
    if (!w->routine_step_warned && isfinite(step_all) && dt > RS_STEP_FRACTION * step_all) {
        w->routine_step_warned = 1;
        char what[64] = "";
        if (r->step_what)
            snprintf(what, sizeof what, ", %s", r->step_what);
        wall_warn(
            w,
            "Fix wall/rigid %s: time step %g is %g of the critical step %g of law "
            "'%s' (2 sqrt(m/(k A)) of the stiffness its routine returned%s); contacts "
            "with the wall may be unstable above %g",
            w->id, dt, dt / step_all, step_all, w->law->name, what, RS_STEP_FRACTION);
    }
    rs_law_requests_clear(&w->requests);
}

void rs_wall_vector(rs_wall *w, double v[RS_WALL_NVEC])
{
    double loc[13];
    for (int d = 0; d < 3; d++) {
        loc[d] = w->f_wall[d];
        loc[3 + d] = w->m_wall[d];
    }
    loc[6] = w->ncontact;
    loc[7] = w->se_now;
    for (int d = 0; d < 4; d++)
        loc[8 + d] = w->diss[d];
    loc[12] = w->heat_wall;
    if (w->host.reduce)
        w->host.reduce(w->host.ctx, loc, 13, RS_REDUCE_SUM);
    for (int d = 0; d < 12; d++)
        v[d] = loc[d];
    v[12] = w->temp_wall;
    v[13] = loc[12];
    for (int d = 0; d < 3; d++)
        v[14 + d] = w->motion->disp[d];
    v[17] = w->motion->phi;
}

void rs_wall_last(const rs_wall *w, rs_track_out *trk, rs_contact_block *cb)
{
    if (trk)
        *trk = w->tout;
    if (cb)
        *cb = w->cb;
}

void rs_wall_set_temperature(rs_wall *w, double temperature, double dtemperature)
{
    w->temp_wall = temperature;
    w->dtemp_wall = dtemperature;
    w->temp_mst[0] = temperature;
    w->dtemp_mst[0] = dtemperature;
}
