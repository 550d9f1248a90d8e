/* The wall's words for its surface and its law: `surface inline KIND ...` becomes the
 * keyword text of a surface file, which rs_surface_parse reads as it reads a file; `law
 * NAME ...` finds a built-in law, loads a user's (a C function, or a Fortran VUINTER,
 * UINTER or FRIC from a library or its source), or asks the engine for its own models. */
#include "wall_impl.h"

#include "rigidsurf/law_build.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FAIL(...) return rs_error_set(err, RS_ERR_ARG, __VA_ARGS__)

/* A growing string. */
typedef struct text {
    char *s;
    size_t n, cap;
    int oom;
} text;

static void put(text *t, const char *s)
{
    const size_t k = strlen(s);
    if (t->oom)
        return;
    if (t->n + k + 1 > t->cap) {
        size_t cap = t->cap ? 2 * t->cap : 256;
        while (cap < t->n + k + 1)
            cap *= 2;
        char *p = realloc(t->s, cap);
        if (!p) {
            t->oom = 1;
            return;
        }
        t->s = p;
        t->cap = cap;
    }
    memcpy(t->s + t->n, s, k + 1);
    t->n += k;
}

static void putg(text *t, double v)
{
    char buf[40];
    snprintf(buf, sizeof buf, "%.17g", v);
    put(t, buf);
}

/* The next word as a number (checked), kept as written; what names it for messages. */
static int num(const char *const *arg, int narg, int *i, const char *kind, const char *what,
               const char **out, rs_error *err)
{
    if (*i >= narg)
        FAIL("'surface inline %s' expects %s", kind, what);
    double v;
    const int rc = wall_number("surface inline", what, arg[*i], &v, err);
    if (rc)
        return rc;
    *out = arg[(*i)++];
    return RS_OK;
}

/* Three numbers, a point p, written "x, y, z" at full precision. */
static int point(const char *const *arg, int narg, int *i, const char *kind,
                 const char *what, double p[3], text *t, rs_error *err)
{
    for (int d = 0; d < 3; d++) {
        const char *s = NULL;
        const int rc = num(arg, narg, i, kind, what, &s, err);
        if (rc)
            return rc;
        p[d] = strtod(s, NULL);
    }
    putg(t, p[0]);
    put(t, ", ");
    putg(t, p[1]);
    put(t, ", ");
    putg(t, p[2]);
    return RS_OK;
}

static void upper(char *s)
{
    for (; *s; s++)
        *s = (char)toupper((unsigned char)*s);
}

/* surface inline mesh FILE [scale s] [place ax ay az bx by bz cx cy cz] [sides n] */
static int inline_mesh(rs_wall *w, const char *const *arg, int narg, int *iarg, text *head,
                       rs_error *err)
{
    int i = *iarg, rc = RS_OK;
    if (i >= narg || wall_is_keyword(arg[i]))
        FAIL("'surface inline mesh' expects a mesh FILE (.stl, .obj, .off or .ply)");
    const char *file = arg[i++];
    if (strpbrk(file, ",\n"))
        FAIL("'surface inline mesh': the file name '%s' holds a comma or a line break "
             "(expected a plain path)",
             file);
    const char *scale = NULL, *msides = NULL;
    text place = {0};
    while (i < narg) {
        const char *k = arg[i];
        if (strcmp(k, "scale") == 0) {
            i++;
            if ((rc = num(arg, narg, &i, "mesh", "scale s", &scale, err)))
                break;
        } else if (strcmp(k, "sides") == 0) {
            i++;
            if ((rc = num(arg, narg, &i, "mesh", "sides 1 or 2", &msides, err)))
                break;
        } else if (strcmp(k, "place") == 0) {
            i++;
            double p[3];
            place.n = 0;
            for (int c = 0; c < 3; c++) {
                if (c)
                    put(&place, ", ");
                if ((rc = point(arg, narg, &i, "mesh", "place ax ay az bx by bz cx cy cz",
                                p, &place, err)))
                    break;
            }
            if (rc)
                break;
        } else {
            break;
        }
        rc = RS_OK;
    }
    if (rc) {
        free(place.s);
        return rc;
    }
    put(head, "*SURFACE, TYPE=MESH, NAME=");
    put(head, w->id);
    put(head, ", FILE=");
    put(head, file);
    if (scale) {
        put(head, ", SCALE=");
        put(head, scale);
    }
    if (msides) {
        put(head, ", SIDES=");
        put(head, msides);
    }
    put(head, "\n");
    if (place.n) {
        put(head, place.s);
        put(head, "\n");
    }
    free(place.s);
    *iarg = i;
    return RS_OK;
}

/* The parameters of an analytic kind before its profile: head's options and the data
 * lines (its points). */
static int analytic_params(rs_wall *w, const char *kind, const char *const *arg, int narg,
                           int *iarg, text *data, const char **fillet, const char **sides,
                           text *extent, rs_error *err)
{
    (void)w;
    int i = *iarg, rc = RS_OK;
    text a = {0}, b = {0}, c = {0};
    double pa[3], pb[3], pc[3];
    const int rev = strcmp(kind, "revolution") == 0, cyl = strcmp(kind, "cylinder") == 0;
    while (!rc && i < narg && strcmp(arg[i], "profile") != 0) {
        const char *k = arg[i++];
        if (rev && strcmp(k, "origin") == 0) {
            a.n = 0;
            rc = point(arg, narg, &i, kind, "origin x y z", pa, &a, err);
        } else if (rev && strcmp(k, "axis") == 0) {
            b.n = 0;
            rc = point(arg, narg, &i, kind, "axis ax ay az", pb, &b, err);
        } else if (cyl && strcmp(k, "a") == 0) {
            a.n = 0;
            rc = point(arg, narg, &i, kind, "a x y z (origin)", pa, &a, err);
        } else if (cyl && strcmp(k, "b") == 0) {
            b.n = 0;
            rc = point(arg, narg, &i, kind, "b x y z (on the local x axis)", pb, &b, err);
        } else if (cyl && strcmp(k, "c") == 0) {
            c.n = 0;
            rc = point(arg, narg, &i, kind,
                       "c x y z (off the local x axis, on the generator's side)", pc, &c,
                       err);
        } else if (cyl && strcmp(k, "extent") == 0) {
            const char *lo = NULL, *hi = NULL;
            if (!(rc = num(arg, narg, &i, kind, "extent zmin zmax", &lo, err)) &&
                !(rc = num(arg, narg, &i, kind, "extent zmin zmax", &hi, err))) {
                extent->n = 0;
                put(extent, lo);
                put(extent, ", ");
                put(extent, hi);
            }
        } else if (strcmp(k, "fillet") == 0) {
            rc = num(arg, narg, &i, kind, "a fillet radius", fillet, err);
        } else if (strcmp(k, "sides") == 0) {
            rc = num(arg, narg, &i, kind, "sides 1 or 2", sides, err);
        } else if (rev) {
            rc = rs_error_set(err, RS_ERR_ARG,
                              "'surface inline revolution' expects origin, axis, fillet, "
                              "sides or profile, got '%s'",
                              k);
        } else if (cyl) {
            rc = rs_error_set(err, RS_ERR_ARG,
                              "'surface inline cylinder' expects a, b, c, extent, fillet, "
                              "sides or profile, got '%s'",
                              k);
        } else {
            rc = rs_error_set(err, RS_ERR_ARG,
                              "'surface inline segments' expects fillet, sides or profile, "
                              "got '%s'",
                              k);
        }
    }
    if (!rc && rev && (!a.n || !b.n))
        rc =
            rs_error_set(err, RS_ERR_ARG,
                         "'surface inline revolution' needs 'origin x y z' and 'axis ax ay "
                         "az'");
    if (!rc && cyl && (!a.n || !b.n || !c.n))
        rc = rs_error_set(
            err, RS_ERR_ARG,
            "'surface inline cylinder' needs points 'a x y z', 'b x y z', 'c x "
            "y z'");
    if (!rc && rev) {
        /* The file gives a second point on the axis: origin + axis. */
        put(data, a.s);
        put(data, ", ");
        putg(data, pa[0] + pb[0]);
        put(data, ", ");
        putg(data, pa[1] + pb[1]);
        put(data, ", ");
        putg(data, pa[2] + pb[2]);
        put(data, "\n");
    } else if (!rc && cyl) {
        put(data, a.s);
        put(data, ", ");
        put(data, b.s);
        put(data, "\n");
        put(data, c.s);
        put(data, "\n");
    }
    free(a.s);
    free(b.s);
    free(c.s);
    *iarg = i;
    return rc;
}

/* The profile ITEMS ... end, one line each. */
static int profile_items(const char *kind, const char *const *arg, int narg, int *iarg,
                         text *prof, rs_error *err)
{
    int i = *iarg, ended = 0;
    while (i < narg) {
        const char *k = arg[i++];
        char K[16];
        snprintf(K, sizeof K, "%s", k);
        upper(K);
        if (strlen(k) < sizeof K && strcmp(K, "END") == 0) {
            ended = 1;
            break;
        }
        int nv;
        if (strlen(k) >= sizeof K)
            nv = -1;
        else if (strcmp(K, "START") == 0 || strcmp(K, "LINE") == 0)
            nv = 2;
        else if (strcmp(K, "CIRCL") == 0 || strcmp(K, "PARAB") == 0)
            nv = 4;
        else
            nv = -1;
        if (nv < 0)
            FAIL("'surface inline' profile expects START, LINE, CIRCL, PARAB or end, got "
                 "'%s'",
                 k);
        put(prof, K);
        for (int v = 0; v < nv; v++) {
            const char *s = NULL;
            const int rc = num(arg, narg, &i, kind, "profile coordinates", &s, err);
            if (rc)
                return rc;
            put(prof, ", ");
            put(prof, s);
        }
        put(prof, "\n");
    }
    if (!ended)
        FAIL("'surface inline' profile is not closed by 'end'");
    *iarg = i;
    return RS_OK;
}

/* surface inline KIND ... profile ITEMS end: the keyword text a surface file holds, which
 * rs_surface_parse reads (w->inline_text). */
int wall_parse_surface(rs_wall *w, const char *const *arg, int narg, int *iarg,
                       rs_error *err)
{
    int i = *iarg, rc;
    if (i >= narg)
        FAIL("'surface inline' expects 'revolution', 'cylinder', 'segments' or 'mesh'");
    const char *kind = arg[i++];
    text head = {0}, data = {0}, prof = {0}, extent = {0};
    if (strcmp(kind, "mesh") == 0) {
        rc = inline_mesh(w, arg, narg, &i, &head, err);
    } else if (strcmp(kind, "revolution") && strcmp(kind, "cylinder") &&
               strcmp(kind, "segments")) {
        rc =
            rs_error_set(err, RS_ERR_ARG,
                         "'surface inline' expects 'revolution', 'cylinder', 'segments' or "
                         "'mesh', got '%s'",
                         kind);
    } else {
        const char *fillet = NULL, *sides = NULL;
        rc = analytic_params(w, kind, arg, narg, &i, &data, &fillet, &sides, &extent, err);
        if (!rc && i >= narg)
            rc = rs_error_set(err, RS_ERR_ARG,
                              "'surface inline %s' expects 'profile START x y ... end'",
                              kind);
        if (!rc) {
            i++; /* profile */
            rc = profile_items(kind, arg, narg, &i, &prof, err);
        }
        if (!rc) {
            char KIND[16];
            snprintf(KIND, sizeof KIND, "%s", kind);
            upper(KIND);
            put(&head, "*SURFACE, TYPE=");
            put(&head, KIND);
            put(&head, ", NAME=");
            put(&head, w->id);
            if (fillet) {
                put(&head, ", FILLET RADIUS=");
                put(&head, fillet);
            }
            if (sides) {
                put(&head, ", SIDES=");
                put(&head, sides);
            }
            if (extent.n) {
                put(&head, ", EXTENT=");
                put(&head, extent.s);
            }
            put(&head, "\n");
            if (data.n)
                put(&head, data.s);
            if (prof.n)
                put(&head, prof.s);
        }
    }
    const int oom = head.oom || data.oom || prof.oom || extent.oom;
    free(data.s);
    free(prof.s);
    free(extent.s);
    if (!rc && oom)
        rc = rs_error_set(err, RS_ERR_NOMEM, "out of memory for 'surface inline'");
    if (rc) {
        free(head.s);
        return rc;
    }
    free(w->inline_text);
    w->inline_text = head.s;
    *iarg = i;
    return RS_OK;
}

/* The next word as a library or source name of law w->law_name. */
static int lib_arg(rs_wall *w, const char *const *arg, int narg, int *i, const char *what,
                   const char **out, rs_error *err)
{
    if (*i >= narg || wall_is_keyword(arg[*i]))
        FAIL("keyword 'law': law %s expects %s", w->law_name, what);
    *out = arg[(*i)++];
    return RS_OK;
}

/* 'normal LAW', a built-in law giving the contact pressure (required or not). */
static int normal_arg(rs_wall *w, const char *const *arg, int narg, int *i, int required,
                      const rs_law **out, rs_error *err)
{
    *out = NULL;
    if (*i + 1 < narg && strcmp(arg[*i], "normal") == 0) {
        const rs_law *n = rs_law_find(arg[*i + 1]);
        if (!n)
            FAIL("keyword 'law': law %s: 'normal %s' is not a built-in law (hertz, hooke, "
                 "bonded_interface, linear_softening, coulomb)",
                 w->law_name, arg[*i + 1]);
        *i += 2;
        *out = n;
        return RS_OK;
    }
    if (required)
        FAIL("keyword 'law': law %s expects 'normal LAW' (a built-in law giving the "
             "contact pressure)",
             w->law_name);
    return RS_OK;
}

/* The engine's own models: its words up to the next keyword of the wall. */
static int engine_law(rs_wall *w, const char *const *arg, int narg, int *iarg,
                      rs_error *err)
{
    int i = *iarg;
    const int first = i;
    size_t used = 0;
    w->law_words[0] = '\0';
    while (i < narg && !wall_is_keyword(arg[i])) {
        const int k = snprintf(w->law_words + used, sizeof w->law_words - used, "%s%s",
                               i > first ? " " : "", arg[i]);
        if (k > 0 && used + (size_t)k < sizeof w->law_words)
            used += (size_t)k;
        i++;
    }
    const int rc = w->host.engine_law(w->host.ctx, arg + first, i - first, &w->law, err);
    if (rc)
        return rc;
    w->law_kind = WALL_LAW_ENGINE;
    *iarg = i;
    return RS_OK;
}

/* law NAME | user LIB SYMBOL | vuinter LIB | uinter LIB [normal LAW] | fric LIB normal LAW
 * | the engine's law with its words. A Fortran LIB (FILE.f, .f90, ...) is built first
 * (rs_law_build_cached). */
int wall_parse_law(rs_wall *w, const char *const *arg, int narg, int *iarg, rs_error *err)
{
    int i = *iarg, rc = RS_OK;
    snprintf(w->law_name, sizeof w->law_name, "%s", arg[i++]);
    const char *lib = NULL, *sym = NULL;
    const rs_law *normal = NULL;
    if (w->host.engine_law && w->host.engine_law_name &&
        strcmp(w->law_name, w->host.engine_law_name) == 0) {
        *iarg = i;
        return engine_law(w, arg, narg, iarg, err);
    }
    if (strcmp(w->law_name, "user") == 0) {
        if ((rc =
                 lib_arg(w, arg, narg, &i,
                         "a shared library and a symbol: user LIB.so SYMBOL", &lib, err)) ||
            (rc = lib_arg(w, arg, narg, &i,
                          "a symbol after the library: user LIB.so SYMBOL", &sym, err)))
            return rc;
        rc = rs_law_load_c(lib, sym, &w->loaded, err);
    } else if (strcmp(w->law_name, "vuinter") == 0) {
        if ((rc = lib_arg(w, arg, narg, &i,
                          "a shared library or Fortran file holding vuinter: vuinter "
                          "LIB.so|FILE.f",
                          &lib, err)))
            return rc;
        rc = rs_law_load_vuinter(lib, &w->loaded, err);
    } else if (strcmp(w->law_name, "uinter") == 0) {
        if ((rc = lib_arg(w, arg, narg, &i,
                          "a shared library or Fortran file holding uinter: uinter "
                          "LIB.so|FILE.f",
                          &lib, err)) ||
            (rc = normal_arg(w, arg, narg, &i, 0, &normal, err)))
            return rc;
        rc = rs_law_load_uinter(lib, normal, &w->loaded, err);
    } else if (strcmp(w->law_name, "fric") == 0) {
        if ((rc = lib_arg(
                 w, arg, narg, &i,
                 "a shared library or Fortran file holding fric: fric LIB.so|FILE.f "
                 "normal LAW",
                 &lib, err)) ||
            (rc = normal_arg(w, arg, narg, &i, 1, &normal, err)))
            return rc;
        rc = rs_law_load_fric(lib, normal, &w->loaded, err);
    } else {
        w->law = rs_law_find(w->law_name);
        if (!w->law) {
            char known[256] = "";
            size_t used = 0;
            for (int k = 0; k < rs_law_count() && used < sizeof known; k++) {
                const int n = snprintf(known + used, sizeof known - used, "%s%s",
                                       k ? ", " : "", rs_law_at(k)->name);
                if (n > 0)
                    used += (size_t)n;
            }
            const char *engine = w->host.engine_law ? w->host.engine_law_name : NULL;
            FAIL("keyword 'law': unknown law '%s'; expected one of %s, user, vuinter, "
                 "uinter, fric%s%s",
                 w->law_name, known, engine ? " or " : "", engine ? engine : "");
        }
        w->law_kind = WALL_LAW_BUILTIN;
        w->hertz = strcmp(w->law->name, "hertz") == 0;
        w->hooke = strcmp(w->law->name, "hooke") == 0;
        *iarg = i;
        return RS_OK;
    }
    if (rc != RS_OK) {
        char msg[sizeof err->msg];
        snprintf(msg, sizeof msg, "%s", err->msg);
        return rs_error_set(err, rc, "keyword 'law': %s", msg);
    }
    w->law_kind = WALL_LAW_LOADED;
    w->loaded_ok = 1;
    w->law = &w->loaded;
    /* A routine built from source: the compiler's warnings, as one line on rank 0. */
    const rs_build_warnings *bw = rs_law_warnings(&w->loaded);
    if (bw && bw->count > 0)
        wall_warn(w,
                  "fix wall/rigid: law %s: the Fortran compiler gave %d %s; the first: %s "
                  "(all of them: %s)",
                  w->loaded.name, bw->count, bw->count == 1 ? "warning" : "warnings",
                  bw->first, bw->log);
    *iarg = i;
    return RS_OK;
}
