/* Run-time loading of user laws with dlopen: C block laws, Fortran VUINTER, and the
 * point-wise Fortran UINTER and FRIC routines wrapped as block laws. A Fortran source
 * (rs_law_is_source) is built first, through the cache of law_build.c; then its
 * SUBROUTINE statement is checked against the argument lists the adapters call
 * (law_signature.c), and an older-list UINTER gets its adapter. Failures name the
 * library and the missing symbol with the dynamic loader's own message. */
#define _POSIX_C_SOURCE 200809L

#include "law_fortran.h"
#include "law_signature.h"
#include "rigidsurf/law.h"
#include "rigidsurf/law_build.h"

#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void loaded_destroy(rs_law *law)
{
    rs_loaded_law *ld = (rs_loaded_law *)law->ctx;
    if (!ld)
        return;
    if (ld->handle)
        dlclose(ld->handle);
    free(ld);
    law->ctx = NULL;
}

/* Opens lib. A Fortran source is built first, and the SUBROUTINE statement of routine
 * (VUINTER, UINTER, FRIC; NULL for a C law) is checked: the list it matches goes to
 * *list (0 for a library, whose list cannot be read). */
static int open_library(const char *lib, const char *routine, rs_loaded_law **out,
                        rs_arglist *list, rs_error *err)
{
    *out = NULL;
    if (list)
        *list = (rs_arglist)0;
    if (!lib || !lib[0])
        return rs_error_set(err, RS_ERR_ARG, "law library: no path given");
    char built[4096];
    const char *path = lib;
    const int source = rs_law_is_source(lib);
    if (source) {
        int rc = rs_law_build_cached(lib, built, sizeof built, err);
        if (!rc && routine)
            rc = rs_law_source_list(lib, routine, list, err);
        if (rc)
            return rc;
        path = built;
    }
    rs_loaded_law *ld = (rs_loaded_law *)calloc(1, sizeof *ld);
    if (!ld)
        return rs_error_set(err, RS_ERR_NOMEM, "law library %s: out of memory", lib);
    if (source) {
        char log[sizeof built + 8];
        snprintf(log, sizeof log, "%s.log", built);
        ld->from_source = 1;
        rs_law_build_read_warnings(log, &ld->warnings);
    }
    dlerror();
    ld->handle = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (!ld->handle) {
        const char *msg = dlerror();
        free(ld);
        return rs_error_set(err, RS_ERR_IO, "law library %s: cannot load: %s", lib,
                            msg ? msg : "unknown dlopen error");
    }
    *out = ld;
    return RS_OK;
}

/* Looks up the first of names[] that the library exports. On failure the message names
 * the library, every name tried and the loader's text for the first. */
static void *find_symbol(rs_loaded_law *ld, const char *lib, const char *const *names,
                         int count, const char **found, rs_error *err)
{
    char first_msg[256] = "";
    for (int i = 0; i < count; ++i) {
        dlerror();
        void *sym = dlsym(ld->handle, names[i]);
        const char *msg = dlerror();
        if (!msg && sym) {
            if (found)
                *found = names[i];
            return sym;
        }
        if (i == 0)
            snprintf(first_msg, sizeof first_msg, "%s", msg ? msg : "symbol is NULL");
    }
    char tried[160] = "";
    size_t used = 0;
    for (int i = 0; i < count && used < sizeof tried; ++i) {
        int w = snprintf(tried + used, sizeof tried - used, "%s%s", i ? "' or '" : "",
                         names[i]);
        if (w < 0)
            break;
        used += (size_t)w;
    }
    rs_error_set(err, RS_ERR_NOTFOUND, "law library %s: no symbol '%s' (%s)", lib, tried,
                 first_msg);
    return NULL;
}

static void fill_common(rs_law *out, rs_loaded_law *ld, const char *kind, const char *lib)
{
    const char *base = strrchr(lib, '/');
    base = base ? base + 1 : lib;
    snprintf(ld->name, sizeof ld->name, "%s(%s)", kind, base);
    memset(out, 0, sizeof *out);
    out->name = ld->name;
    out->nprops = -1;
    out->nstatev = 0;
    out->prop_names = NULL;
    out->ctx = ld;
    out->destroy = loaded_destroy;
}

static int fail_close(rs_loaded_law *ld, int code)
{
    if (ld->handle)
        dlclose(ld->handle);
    free(ld);
    return code;
}

/* Opens lib and finds the first of names in it (*ld, *sym); on failure nothing is left
 * open. routine and list as for open_library. */
static int open_with_symbol(const char *lib, const char *routine, const char *const *names,
                            int count, rs_loaded_law **ld, void **sym, rs_arglist *list,
                            rs_error *err)
{
    int rc = open_library(lib, routine, ld, list, err);
    if (rc)
        return rc;
    *sym = find_symbol(*ld, lib, names, count, NULL, err);
    return *sym ? RS_OK : fail_close(*ld, RS_ERR_NOTFOUND);
}

int rs_law_load_c(const char *lib, const char *symbol, rs_law *out, rs_error *err)
{
    if (!out)
        return rs_error_set(err, RS_ERR_ARG, "rs_law_load_c: out is NULL");
    if (!symbol || !symbol[0])
        return rs_error_set(err, RS_ERR_ARG, "law library %s: no symbol name given",
                            lib ? lib : "(null)");
    rs_loaded_law *ld;
    void *sym;
    const char *names[1] = {symbol};
    int rc = open_with_symbol(lib, NULL, names, 1, &ld, &sym, NULL, err);
    if (rc)
        return rc;
    ld->kind = RS_LOADED_C;
    ld->cfn = (rs_law_update_fn)sym;
    fill_common(out, ld, symbol, lib);
    out->update = ld->cfn;

    /* Optional descriptor: a `const rs_law <symbol>_law` gives the name, property
     * count, property names, state-variable count and property check. */
    char dname[200];
    snprintf(dname, sizeof dname, "%s_law", symbol);
    dlerror();
    const rs_law *desc = (const rs_law *)dlsym(ld->handle, dname);
    if (!dlerror() && desc) {
        if (desc->nstatev < 0 || desc->nstatev > RS_MAX_STATEV) {
            const int nsv = desc->nstatev;
            rs_law_unload(out);
            return rs_error_set(err, RS_ERR_ARG,
                                "%s: descriptor %s declares %d state variables (expected "
                                "0..%d)",
                                lib, dname, nsv, RS_MAX_STATEV);
        }
        if (desc->name && desc->name[0])
            snprintf(ld->name, sizeof ld->name, "%s", desc->name);
        out->nprops = desc->nprops;
        out->nstatev = desc->nstatev;
        out->prop_names = desc->prop_names;
        out->init = desc->init;
        if (desc->update)
            out->update = desc->update;
        out->critical_step = desc->critical_step;
        out->reach = desc->reach;
    }
    return RS_OK;
}

int rs_law_load_vuinter(const char *lib, rs_law *out, rs_error *err)
{
    if (!out)
        return rs_error_set(err, RS_ERR_ARG, "rs_law_load_vuinter: out is NULL");
    rs_loaded_law *ld;
    void *sym;
    static const char *const names[2] = {"vuinter_", "vuinter"};
    rs_arglist list;
    int rc = open_with_symbol(lib, "vuinter", names, 2, &ld, &sym, &list, err);
    if (rc)
        return rc;
    ld->kind = RS_LOADED_VUINTER;
    ld->vuinter = (rs_vuinter_fn)sym;
    fill_common(out, ld, "vuinter", lib);
    out->update = rs_law_vuinter_update;
    return RS_OK;
}

static int check_normal(const char *lib, const rs_law *normal, rs_error *err)
{
    if (!normal)
        return RS_OK;
    if (!normal->update)
        return rs_error_set(err, RS_ERR_ARG, "law library %s: the normal law has no update",
                            lib);
    if (normal->nprops < 0)
        return rs_error_set(err, RS_ERR_ARG,
                            "law library %s: the normal law '%s' must have a fixed "
                            "property count (its properties come first)",
                            lib, normal->name ? normal->name : "?");
    if (normal->nstatev < 0 || normal->nstatev > RS_ADAPTER_MAX_NORMAL_NSV)
        return rs_error_set(err, RS_ERR_ARG,
                            "law library %s: the normal law '%s' has %d state variables; "
                            "expected 0..%d",
                            lib, normal->name ? normal->name : "?", normal->nstatev,
                            RS_ADAPTER_MAX_NORMAL_NSV);
    return RS_OK;
}

static int load_uinter_kind(const char *lib, const rs_law *normal, rs_law *out,
                            rs_loaded_kind kind, rs_error *err)
{
    if (!out)
        return rs_error_set(err, RS_ERR_ARG, "rs_law_load_uinter: out is NULL");
    int rc = check_normal(lib ? lib : "(null)", normal, err);
    if (rc)
        return rc;
    rs_loaded_law *ld;
    void *sym;
    static const char *const names[2] = {"uinter_", "uinter"};
    rs_arglist list;
    rc = open_with_symbol(lib, "uinter", names, 2, &ld, &sym, &list, err);
    if (rc)
        return rc;
    /* a source's own list decides the adapter */
    if (list == RS_ARGS_UINTER)
        kind = RS_LOADED_UINTER;
    else if (list == RS_ARGS_UINTER_OLDER)
        kind = RS_LOADED_UINTER_V6;
    ld->kind = kind;
    if (kind == RS_LOADED_UINTER)
        ld->uinter = (rs_uinter_fn)sym;
    else
        ld->uinter_v6 = (rs_uinter_v6_fn)sym;
    ld->normal = normal;
    ld->own_nsv = (normal ? normal->nstatev : 0) + RS_UINTER_OWN_NSV;
    fill_common(out, ld, kind == RS_LOADED_UINTER ? "uinter" : "uinter_v6", lib);
    out->nstatev = ld->own_nsv;
    out->init = rs_law_adapter_init;
    out->update = rs_law_uinter_update;
    return RS_OK;
}

int rs_law_load_uinter(const char *lib, const rs_law *normal, rs_law *out, rs_error *err)
{
    return load_uinter_kind(lib, normal, out, RS_LOADED_UINTER, err);
}

int rs_law_load_uinter_v6(const char *lib, const rs_law *normal, rs_law *out, rs_error *err)
{
    return load_uinter_kind(lib, normal, out, RS_LOADED_UINTER_V6, err);
}

int rs_law_load_fric(const char *lib, const rs_law *normal, rs_law *out, rs_error *err)
{
    if (!out)
        return rs_error_set(err, RS_ERR_ARG, "rs_law_load_fric: out is NULL");
    if (!normal)
        return rs_error_set(err, RS_ERR_ARG,
                            "law library %s: FRIC needs a normal law for the pressure",
                            lib ? lib : "(null)");
    int rc = check_normal(lib ? lib : "(null)", normal, err);
    if (rc)
        return rc;
    rs_loaded_law *ld;
    void *sym;
    static const char *const names[2] = {"fric_", "fric"};
    rs_arglist list;
    rc = open_with_symbol(lib, "fric", names, 2, &ld, &sym, &list, err);
    if (rc)
        return rc;
    ld->kind = RS_LOADED_FRIC;
    ld->fric = (rs_fric_fn)sym;
    ld->normal = normal;
    ld->own_nsv = normal->nstatev + RS_FRIC_OWN_NSV;
    fill_common(out, ld, "fric", lib);
    out->nstatev = ld->own_nsv;
    out->init = rs_law_adapter_init;
    out->update = rs_law_fric_update;
    return RS_OK;
}

const rs_build_warnings *rs_law_warnings(const rs_law *law)
{
    if (!law || !law->ctx || law->destroy != loaded_destroy)
        return NULL;
    const rs_loaded_law *ld = (const rs_loaded_law *)law->ctx;
    return ld->from_source ? &ld->warnings : NULL;
}

int rs_law_takes_facets(const rs_law *law)
{
    return law && law->update == rs_law_vuinter_update;
}

void rs_law_unload(rs_law *law)
{
    if (!law)
        return;
    if (law->destroy)
        law->destroy(law);
    memset(law, 0, sizeof *law);
}
