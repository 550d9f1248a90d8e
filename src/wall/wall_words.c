/* The wall's words: the arguments of `fix ID group wall/rigid ...` (docs/fix_wall_rigid.md,
 * "Syntax"), parsed once, with messages that name the keyword and what it expects. The
 * surface's and the law's words: wall_law_words.c; the motion's: wall_motion.c; the
 * servo's: wall_servo.c. */
#include "wall_impl.h"

#include "rigidsurf/vec.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FAIL(...) return rs_error_set(err, RS_ERR_ARG, __VA_ARGS__)

static int is_number(const char *s)
{
    if (!s || !*s)
        return 0;
    char *end = NULL;
    errno = 0;
    strtod(s, &end);
    return end && *end == '\0' && errno == 0;
}

int wall_number(const char *keyword, const char *what, const char *s, double *v,
                rs_error *err)
{
    if (!is_number(s))
        FAIL("keyword '%s' expects %s, got '%s'", keyword, what, s ? s : "(end of line)");
    *v = strtod(s, NULL);
    if (!isfinite(*v))
        FAIL("keyword '%s' expects %s, got '%s' (not a finite number)", keyword, what, s);
    if (fabs(*v) > RS_COORD_MAX)
        FAIL("keyword '%s' expects %s, got '%s' (magnitude above 1e100)", keyword, what, s);
    return RS_OK;
}

/* A number > 0 (what says so): wall_number's errors, or "expects WHAT, got S" for one
 * <= 0. */
int wall_positive(const char *keyword, const char *what, const char *s, double *v,
                  rs_error *err)
{
    const int rc = wall_number(keyword, what, s, v, err);
    if (rc)
        return rc;
    if (!(*v > 0.0))
        FAIL("keyword '%s' expects %s, got %s", keyword, what, s);
    return RS_OK;
}

static int integer(const char *keyword, const char *what, const char *s, int *v,
                   rs_error *err)
{
    char *end = NULL;
    long x = s ? strtol(s, &end, 10) : 0;
    if (!s || !*s || *end != '\0' || x < -2147483647L || x > 2147483647L)
        FAIL("keyword '%s' expects %s, got '%s'", keyword, what, s ? s : "(end of line)");
    *v = (int)x;
    return RS_OK;
}

int wall_is_keyword(const char *s)
{
    static const char *const kw[] = {
        "surface",     "name",         "law",    "props",    "type",
        "statev",      "tracking",     "area",   "contacts", "move",
        "rotate",      "temperature",  "predef", "vtk",      "curvature",
        "pnewdt",      "surface_vel",  "wear",   "servo",    "conduction",
        "store_force", "contact_area", "spin",   "peratom",  "fused",
        "behind"};
    for (size_t k = 0; k < sizeof kw / sizeof kw[0]; k++)
        if (strcmp(s, kw[k]) == 0)
            return 1;
    return 0;
}

void wall_warn(const rs_wall *w, const char *fmt, ...)
{
    if (w->host.rank != 0 || !w->host.warning)
        return;
    char msg[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    w->host.warning(w->host.ctx, msg);
}

double wall_reduce1(const rs_wall *w, double v, int op)
{
    if (w->host.reduce)
        w->host.reduce(w->host.ctx, &v, 1, op);
    return v;
}

static char *dup(const char *s)
{
    const size_t n = strlen(s) + 1;
    char *d = malloc(n);
    if (d)
        memcpy(d, s, n);
    return d;
}

static int push_prop(rs_wall *w, double v, rs_error *err)
{
    double *p = realloc(w->props, (size_t)(w->nprops + 1) * sizeof *p);
    if (!p)
        return rs_error_set(err, RS_ERR_NOMEM, "out of memory for the law's properties");
    w->props = p;
    w->props[w->nprops++] = v;
    return RS_OK;
}

/* A keyword of two values: 1 for on, 0 for off, else an error. */
static int either(const char *const *arg, int narg, int *iarg, const char *on,
                  const char *off, int *v, rs_error *err)
{
    const char *kw = arg[*iarg];
    if (*iarg + 1 >= narg)
        FAIL("keyword '%s' expects '%s' or '%s'", kw, on, off);
    const char *val = arg[*iarg + 1];
    if (strcmp(val, on) != 0 && strcmp(val, off) != 0)
        FAIL("keyword '%s' expects '%s' or '%s', got '%s'", kw, on, off, val);
    *iarg += 2;
    *v = strcmp(val, on) == 0;
    return RS_OK;
}

/* One keyword at arg[*iarg] (not surface, law, motion or servo): its values into w. */
static int keyword(rs_wall *w, const char *const *arg, int narg, int *iarg, rs_error *err)
{
    const char *kw = arg[*iarg];
    int rc = RS_OK, i = *iarg;
#define NEED(n, what)                                                                      \
    if (i + (n) >= narg)                                                                   \
    FAIL("keyword '%s' expects %s", kw, what)
    if (strcmp(kw, "props") == 0) {
        i++;
        w->nprops = 0;
        while (i < narg && !wall_is_keyword(arg[i])) {
            double v;
            if ((rc = wall_number("props", "numbers", arg[i], &v, err)) ||
                (rc = push_prop(w, v, err)))
                return rc;
            i++;
        }
        if (w->nprops == 0)
            FAIL("keyword 'props' expects at least one number");
        w->props_given = 1;
    } else if (strcmp(kw, "type") == 0) {
        NEED(1, "a wall material type (integer >= 1)");
        if ((rc = integer("type", "a wall material type (integer >= 1)", arg[i + 1],
                          &w->info.wall_type, err)))
            return rc;
        if (w->info.wall_type < 1 ||
            (w->host.ntypes > 0 && w->info.wall_type > w->host.ntypes))
            FAIL("keyword 'type' expects a material type in 1..%d (create_box), got %d",
                 w->host.ntypes, w->info.wall_type);
        i += 2;
    } else if (strcmp(kw, "statev") == 0) {
        NEED(1, "a number of state variables (integer >= 0)");
        if ((rc = integer("statev", "a number of state variables (integer >= 0)",
                          arg[i + 1], &w->user_statev, err)))
            return rc;
        if (w->user_statev < 0 || w->user_statev > RS_MAX_STATEV)
            FAIL("keyword 'statev' expects a number of state variables in 0..%d, got %d",
                 RS_MAX_STATEV, w->user_statev);
        w->statev_given = 1;
        i += 2;
    } else if (strcmp(kw, "tracking") == 0) {
        NEED(1, "a tracking thickness (length >= 0)");
        if ((rc = wall_number("tracking", "a tracking thickness (length >= 0)", arg[i + 1],
                              &w->tracking, err)))
            return rc;
        if (w->tracking < 0.0)
            FAIL("keyword 'tracking' expects a length >= 0, got %s", arg[i + 1]);
        w->tracking_given = 1;
        i += 2;
    } else if (strcmp(kw, "area") == 0) {
        NEED(1, "'node', 'projected' or a constant area > 0");
        if (strcmp(arg[i + 1], "node") == 0) {
            w->area_mode = WALL_AREA_NODE;
        } else if (strcmp(arg[i + 1], "projected") == 0) {
            w->area_mode = WALL_AREA_PROJECTED;
        } else {
            w->area_mode = WALL_AREA_CONSTANT;
            if ((rc = wall_number("area", "'node', 'projected' or a constant area > 0",
                                  arg[i + 1], &w->area_const, err)))
                return rc;
            if (!(w->area_const > 0.0))
                FAIL("keyword 'area' expects a constant area > 0, got %s", arg[i + 1]);
        }
        i += 2;
    } else if (strcmp(kw, "contacts") == 0) {
        NEED(1, "a per-particle contact capacity");
        if ((rc = integer("contacts", "a per-particle contact capacity", arg[i + 1],
                          &w->capacity, err)))
            return rc;
        if (w->capacity < 1 || w->capacity > RS_TRACK_MAX_CAPACITY)
            FAIL("keyword 'contacts' expects a capacity in 1..%d, got %d",
                 RS_TRACK_MAX_CAPACITY, w->capacity);
        i += 2;
    } else if (strcmp(kw, "wear") == 0) {
        rc = either(arg, narg, &i, "finnie", "off", &w->wear, err);
    } else if (strcmp(kw, "surface_vel") == 0) {
        NEED(3, "a surface velocity VX VY VZ");
        double u[3];
        for (int d = 0; d < 3; d++)
            if ((rc = wall_number("surface_vel", "a surface velocity component VX VY VZ",
                                  arg[i + 1 + d], &u[d], err)))
                return rc;
        rs_motion_set_surface_velocity(w->motion, u);
        w->belt = u[0] != 0.0 || u[1] != 0.0 || u[2] != 0.0;
        i += 4;
    } else if (strcmp(kw, "temperature") == 0) {
        NEED(1, "a wall temperature");
        if ((rc = wall_number("temperature", "a wall temperature", arg[i + 1],
                              &w->temp_wall, err)))
            return rc;
        w->temp_given = 1;
        i += 2;
        if (i < narg && strcmp(arg[i], "capacity") == 0) {
            if (i + 1 >= narg)
                FAIL("keyword 'capacity' expects a wall heat capacity > 0 (energy per "
                     "kelvin)");
            if ((rc = wall_positive("capacity", "a wall heat capacity > 0", arg[i + 1],
                                    &w->capacity_wall, err)))
                return rc;
            i += 2;
        }
    } else if (strcmp(kw, "conduction") == 0) {
        NEED(1, "'liggghts' or 'off'");
        if (strcmp(arg[i + 1], "liggghts") == 0)
            w->conduction = 1;
        else if (strcmp(arg[i + 1], "off") == 0)
            w->conduction = 0;
        else
            FAIL("keyword 'conduction' expects 'liggghts' or 'off', got '%s'", arg[i + 1]);
        i += 2;
    } else if (strcmp(kw, "contact_area") == 0) {
        NEED(1, "'overlap', 'projection' or 'constant A'");
        const char *m = arg[i + 1];
        if (strcmp(m, "overlap") == 0) {
            w->carea_mode = WALL_CAREA_OVERLAP;
        } else if (strcmp(m, "projection") == 0) {
            w->carea_mode = WALL_CAREA_PROJECTION;
        } else if (strcmp(m, "constant") == 0) {
            NEED(2, "'constant A' with an area A > 0");
            if ((rc = wall_positive("contact_area constant", "an area > 0", arg[i + 2],
                                    &w->carea_const, err)))
                return rc;
            w->carea_mode = WALL_CAREA_CONSTANT;
            i++;
        } else {
            FAIL("keyword 'contact_area' expects 'overlap', 'projection' or 'constant A', "
                 "got '%s'",
                 m);
        }
        w->carea_given = 1;
        i += 2;
    } else if (strcmp(kw, "store_force") == 0) {
        NEED(1, "'yes', 'no' or 'into ID'");
        w->wallforce_id[0] = '\0';
        if (strcmp(arg[i + 1], "yes") == 0) {
            w->store_force = 1;
        } else if (strcmp(arg[i + 1], "no") == 0) {
            w->store_force = 0;
        } else if (strcmp(arg[i + 1], "into") == 0) {
            NEED(2, "'into ID': the ID W of the per-atom vector force_W");
            w->store_force = 1;
            snprintf(w->wallforce_id, sizeof w->wallforce_id, "force_%s", arg[i + 2]);
            i++;
        } else {
            FAIL("keyword 'store_force' expects 'yes', 'no' or 'into ID', got '%s'",
                 arg[i + 1]);
        }
        i += 2;
    } else if (strcmp(kw, "peratom") == 0) {
        rc = either(arg, narg, &i, "yes", "no", &w->peratom, err);
    } else if (strcmp(kw, "predef") == 0) {
        i++;
        while (i < narg && !wall_is_keyword(arg[i])) {
            char **p = realloc(w->pred_names, (size_t)(w->npred + 1) * sizeof *p);
            if (!p || !(p[w->npred] = dup(arg[i]))) {
                if (p)
                    w->pred_names = p;
                return rs_error_set(err, RS_ERR_NOMEM, "out of memory for 'predef'");
            }
            w->pred_names = p;
            w->npred++;
            i++;
        }
        if (w->npred == 0)
            FAIL("keyword 'predef' expects the names of fix property/atom scalars");
    } else if (strcmp(kw, "vtk") == 0) {
        NEED(2, "a file name and an output interval N > 0");
        free(w->vtk_file);
        if (!(w->vtk_file = dup(arg[i + 1])))
            return rs_error_set(err, RS_ERR_NOMEM, "out of memory for 'vtk'");
        if ((rc = integer("vtk", "an output interval N > 0", arg[i + 2], &w->vtk_every,
                          err)))
            return rc;
        if (w->vtk_every < 1)
            FAIL("keyword 'vtk' expects an output interval N > 0, got %s", arg[i + 2]);
        i += 3;
    } else if (strcmp(kw, "curvature") == 0) {
        rc = either(arg, narg, &i, "yes", "no", &w->curvature, err);
        w->curvature_given = 1;
    } else if (strcmp(kw, "pnewdt") == 0) {
        int warn = 1;
        rc = either(arg, narg, &i, "warn", "stop", &warn, err);
        w->pnewdt_stop = !warn;
    } else if (strcmp(kw, "fused") == 0) {
        rc = either(arg, narg, &i, "yes", "no", &w->fused_given, err);
    } else if (strcmp(kw, "behind") == 0) {
        rc = either(arg, narg, &i, "none", "push", &w->behind_none, err);
    } else {
        FAIL("unknown keyword '%s'; expected surface, name, law, props, type, statev, "
             "tracking, area, contacts, move, rotate, spin, servo, surface_vel, "
             "temperature, conduction, contact_area, predef, vtk, curvature, wear, "
             "store_force, peratom, fused, behind or pnewdt",
             kw);
    }
#undef NEED
    *iarg = i;
    return rc;
}

/* The state variables per contact: the law's, a user routine's ('statev'), or both (an
 * adapter's own first, then the routine's). */
static int state_variables(rs_wall *w, rs_error *err)
{
    const int law_nsv = w->law->nstatev, user = w->user_statev;
    if (w->law_kind == WALL_LAW_ENGINE) {
        /* the engine's model: its history, material properties and force; the
         * interface keywords of stress laws do not apply */
        if (w->statev_given && user != law_nsv)
            FAIL("law %s %s keeps %d history values per contact; 'statev %d' does not "
                 "match",
                 w->law_name, w->law_words, law_nsv, user);
        if (w->props_given)
            FAIL("law %s takes its coefficients as the engine's walls take them (its "
                 "words, the engine's material properties); 'props' does not apply",
                 w->law_name);
        if (w->area_mode != WALL_AREA_NODE)
            FAIL("law %s gives a force, not a stress; 'area' does not apply", w->law_name);
        if ((w->temp_given && !w->conduction) || w->npred)
            FAIL("law %s conducts no heat and reads no predefined fields; 'temperature' "
                 "applies to the interface laws and to 'conduction liggghts', 'predef' to "
                 "the interface laws",
                 w->law_name);
        if (w->curvature_given)
            FAIL("keyword 'curvature' applies to law hertz only");
        w->nstatev = law_nsv;
    } else if (w->law_kind == WALL_LAW_BUILTIN) {
        if (w->statev_given && user != law_nsv)
            FAIL("law '%s' has %d state variables; 'statev %d' does not match",
                 w->law->name, law_nsv, user);
        w->nstatev = law_nsv;
    } else if (strcmp(w->law_name, "uinter") == 0 || strcmp(w->law_name, "fric") == 0) {
        w->nstatev = law_nsv + user; /* the adapter's own first, then the routine's */
    } else {
        if (law_nsv > 0 && w->statev_given && user != law_nsv)
            FAIL("law '%s' declares %d state variables; 'statev %d' does not match",
                 w->law->name, law_nsv, user);
        w->nstatev = law_nsv > 0 ? law_nsv : user;
    }
    if (w->nstatev > RS_MAX_STATEV)
        FAIL("law '%s' with 'statev %d' needs %d state variables per contact, more than %d",
             w->law->name, user, w->nstatev, RS_MAX_STATEV);
    return RS_OK;
}

/* The law's properties: given, or (hertz and hooke without props) the engine's material
 * properties, looked up at rs_wall_init. */
static int properties(rs_wall *w, rs_error *err)
{
    if (w->law_kind == WALL_LAW_ENGINE)
        return RS_OK;
    if (w->curvature_given && !w->hertz)
        FAIL("keyword 'curvature' applies to law hertz only");
    int rc;
    if (w->hertz) {
        if (w->props_given) {
            /* Explicit Hertz properties override the engine's material properties. */
            if ((rc = rs_law_check_props(w->law, w->props, w->nprops, err))) {
                char msg[sizeof err->msg];
                snprintf(msg, sizeof msg, "%s", err->msg);
                return rs_error_set(err, rc, "keyword 'props': %s", msg);
            }
            if (w->curvature_given)
                FAIL("law hertz with 'props': give the curvature flag as the 7th property");
        } else {
            w->nprops = 0; /* remembered until rs_wall_init */
            if ((rc = push_prop(w, w->curvature ? 1.0 : 0.0, err)))
                return rc;
        }
    } else if (w->hooke && !w->props_given) {
        w->nprops = 0; /* the engine's material properties, looked up at rs_wall_init */
    } else if ((rc = rs_law_check_props(w->law, w->props, w->nprops, err))) {
        char msg[sizeof err->msg];
        snprintf(msg, sizeof msg, "%s", err->msg);
        return rs_error_set(err, rc, "keyword 'props': %s", msg);
    }
    return RS_OK;
}

int wall_parse(rs_wall *w, const char *const *arg, int narg, rs_error *err)
{
    const char *surf_file = NULL, *surf_name = NULL;
    int have_surface = 0, have_law = 0, is_inline = 0, rc;
    int i = 0;
    while (i < narg) {
        const char *kw = arg[i];
        if (strcmp(kw, "surface") == 0) {
            if (i + 1 >= narg)
                FAIL("keyword 'surface' expects a surface file name or 'inline'");
            if (have_surface)
                FAIL("keyword 'surface' given twice");
            have_surface = 1;
            if (strcmp(arg[i + 1], "inline") == 0) {
                i += 2;
                if ((rc = wall_parse_surface(w, arg, narg, &i, err)))
                    return rc;
                is_inline = 1;
            } else {
                surf_file = arg[i + 1];
                i += 2;
            }
        } else if (strcmp(kw, "name") == 0) {
            if (i + 1 >= narg)
                FAIL("keyword 'name' expects the name of a surface in the surface file");
            surf_name = arg[i + 1];
            i += 2;
        } else if (strcmp(kw, "law") == 0) {
            if (i + 1 >= narg) {
                const char *engine = w->host.engine_law ? w->host.engine_law_name : NULL;
                FAIL("keyword 'law' expects a law name (hertz, hooke, bonded_interface, "
                     "linear_softening, coulomb, user, vuinter, uinter, fric%s%s)",
                     engine ? ", " : "", engine ? engine : "");
            }
            if (have_law)
                FAIL("keyword 'law' given twice");
            have_law = 1;
            i++;
            if ((rc = wall_parse_law(w, arg, narg, &i, err)))
                return rc;
        } else if (strcmp(kw, "servo") == 0) {
            if (w->moving || w->servo.on)
                FAIL("keyword 'servo' moves the wall itself; it takes no 'move', 'rotate' "
                     "or 'spin' and is given once");
            i++;
            if ((rc = wall_parse_servo(w, arg, narg, &i, err)))
                return rc;
        } else if (strcmp(kw, "move") == 0 || strcmp(kw, "rotate") == 0 ||
                   strcmp(kw, "spin") == 0) {
            if (w->servo.on)
                FAIL("keyword 'servo' moves the wall itself; it takes no 'move', 'rotate' "
                     "or 'spin'");
            if ((rc = wall_parse_motion(w, arg, narg, &i, err)))
                return rc;
        } else if ((rc = keyword(w, arg, narg, &i, err))) {
            return rc;
        }
    }

    if (!have_surface)
        FAIL("missing 'surface FILE' (or 'surface inline ...')");
    if (w->conduction && !w->temp_given)
        FAIL("keyword 'conduction liggghts' needs the wall's 'temperature T'");
    if (w->carea_given && !w->conduction)
        FAIL("keyword 'contact_area' sets the area of 'conduction liggghts', which is not "
             "given");
    if (!have_law)
        FAIL("missing 'law LAW'");

    /* The surface: one parser for files and inline definitions. */
    if (is_inline) {
        if (surf_name)
            FAIL("keyword 'name' selects a surface in a file; an inline surface has none");
        rc = rs_surface_parse(w->inline_text, "inline surface", NULL, &w->surf_own, err);
    } else {
        rc = rs_surface_read(surf_file, surf_name, &w->surf_own, err);
    }
    if (rc != RS_OK) {
        char msg[sizeof err->msg];
        snprintf(msg, sizeof msg, "%s", err->msg);
        return rs_error_set(err, rc, "keyword 'surface': %s", msg);
    }
    w->surf = &w->surf_own;
    if (w->wear && !rs_surface_has_facets(w->surf))
        FAIL("keyword 'wear' needs a mesh surface (TYPE=MESH or 'surface inline mesh'): "
             "the wear is kept per facet");
    if (w->surf->warning[0])
        wall_warn(w, "fix wall/rigid: surface: %s", w->surf->warning);
    if (w->surf->info[0] && w->host.rank == 0 && w->host.info) {
        char msg[sizeof w->surf->info + 2 * WALL_NAME];
        snprintf(msg, sizeof msg, "fix wall/rigid %s: surface: %s", w->id, w->surf->info);
        w->host.info(w->host.ctx, msg);
    }
    if ((rc = state_variables(w, err)))
        return rc;
    return properties(w, err);
}
