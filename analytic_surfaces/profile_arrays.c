/* The analytic kinds from arrays in memory (rs_surface_make_profile): the parameters and
 * points of a *SURFACE and its profile lines, put into the reader's draft and made into
 * a surface by the kind's syntax (profile_file.c), so that the checks and messages are
 * those of the same surface written as keyword text. */
#include "profile.h"
#include "surface_file.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The *SURFACE line's parameters, at line 1. */
static int put_params(const parser *ps, const rs_profile_def *def, draft *d)
{
    const rs_surface_ops *ops = NULL;
    if (def->kind == RS_SURF_SEGMENTS || def->kind == RS_SURF_CYLINDER ||
        def->kind == RS_SURF_REVOLUTION)
        ops = rs_analytic_ops(def->kind);
    if (!ops || !ops->syntax) {
        char found[32];
        snprintf(found, sizeof found, "%d", (int)def->kind);
        return rs_sf_error(
            ps, RS_ERR_ARG,
            "unknown kind %s (expected RS_SURF_SEGMENTS, RS_SURF_CYLINDER or "
            "RS_SURF_REVOLUTION)%s",
            found, NULL);
    }
    d->active = 1;
    d->kline = ps->line;
    d->kind = def->kind;
    d->syntax = ops->syntax;
    d->scale = 1.0;
    const char *name = def->name ? def->name : "";
    const size_t len = strlen(name);
    if (len >= sizeof d->name)
        return rs_sf_error(ps, RS_ERR_ARG, "expected NAME= with 1 to 79 characters%s%s",
                           NULL, NULL);
    for (size_t c = 0; c < len; c++)
        if (!isprint((unsigned char)name[c]))
            return rs_sf_error(ps, RS_ERR_ARG, "expected a printable NAME=%s%s", NULL,
                               NULL);
    memcpy(d->name, name, len + 1);
    if (def->sides < 0 || def->sides > 2)
        return rs_sf_error(ps, RS_ERR_ARG,
                           "expected SIDES=1 or SIDES=2 (0: the default)%s%s", NULL, NULL);
    d->sides = def->sides;
    if (def->fillet != 0.0) {
        int rc = rs_sf_value(ps, RS_ERR_ARG, def->fillet, NULL);
        if (rc)
            return rc;
        if (!(def->fillet > 0.0))
            return rs_sf_error(ps, RS_ERR_ARG, "expected FILLET RADIUS > 0 (0: none)%s%s",
                               NULL, NULL);
        d->fillet = def->fillet;
    }
    if (def->bounded) {
        if (!(d->syntax->params & RS_SF_EXTENT))
            return rs_sf_error(ps, RS_ERR_ARG, "EXTENT is only for TYPE=CYLINDER%s%s", NULL,
                               NULL);
        int rc;
        if ((rc = rs_sf_value(ps, RS_ERR_ARG, def->zmin, NULL)) ||
            (rc = rs_sf_value(ps, RS_ERR_ARG, def->zmax, NULL)))
            return rc;
        if (!(def->zmax > def->zmin))
            return rs_sf_error(ps, RS_ERR_ARG, "expected EXTENT with zmin < zmax%s%s", NULL,
                               NULL);
        d->bounded = 1;
        d->zmin = def->zmin;
        d->zmax = def->zmax;
    }
    return RS_OK;
}

/* The coordinate lines: a, b at line 2, c at line 3 (CYLINDER). */
static int put_points(parser *ps, const rs_profile_def *def, draft *d)
{
    const int need = d->kind == RS_SURF_CYLINDER     ? 2
                     : d->kind == RS_SURF_REVOLUTION ? 1
                                                     : 0;
    const double *pts[3] = {def->a, def->b, def->c};
    for (int k = 0; k < (need ? need + 1 : 0); k++) {
        ps->line = d->kline + (k < 2 ? 1 : 2);
        for (int i = 0; i < 3; i++) {
            int rc = rs_sf_value(ps, RS_ERR_ARG, pts[k][i], NULL);
            if (rc)
                return rc;
        }
    }
    memcpy(d->ab, def->a, sizeof def->a);
    memcpy(d->ab + 3, def->b, sizeof def->b);
    if (need == 2)
        memcpy(d->c, def->c, sizeof def->c);
    d->ncoord = need;
    return RS_OK;
}

int rs_surface_make_profile(const rs_profile_def *def, const rs_profile_item *items,
                            int nitems, rs_surface *s, rs_error *err)
{
    if (!s)
        return rs_error_set(err, RS_ERR_ARG, "rs_surface_make_profile: NULL surface");
    memset(s, 0, sizeof *s);
    if (!def)
        return rs_error_set(err, RS_ERR_ARG,
                            "rs_surface_make_profile: NULL definition (expected the "
                            "surface's kind, parameters and points)");
    parser ps = {def->origin ? def->origin : "<arrays>", 1, err, 0};
    if (nitems < 0 || (nitems > 0 && !items)) {
        char found[48];
        snprintf(found, sizeof found, "%s and nitems = %d", items ? "items" : "NULL items",
                 nitems);
        return rs_sf_error(&ps, RS_ERR_ARG,
                           "expected an array of nitems >= 0 profile items, found %s%s",
                           found, NULL);
    }
    draft d;
    memset(&d, 0, sizeof d);
    int rc = put_params(&ps, def, &d);
    if (!rc)
        rc = put_points(&ps, def, &d);
    const int first = d.kline + 1 + d.ncoord;
    static const char *const names[] = {"START", "LINE", "CIRCL", "PARAB"};
    for (int k = 0; k < nitems && !rc; k++) {
        const rs_profile_item *it = &items[k];
        ps.line = first + k;
        if ((int)it->word < RS_WORD_START || (int)it->word > RS_WORD_PARAB) {
            char show[32];
            snprintf(show, sizeof show, "%d", (int)it->word);
            rc = rs_sf_error(&ps, RS_ERR_ARG,
                             "unknown profile word %s (expected RS_WORD_START, "
                             "RS_WORD_LINE, RS_WORD_CIRCL or RS_WORD_PARAB)%s",
                             show, NULL);
            break;
        }
        const int nv = it->word == RS_WORD_START || it->word == RS_WORD_LINE ? 2 : 4;
        for (int i = 0; i < nv && !rc; i++) {
            char show[64];
            snprintf(show, sizeof show, "%.17g in %s", it->v[i], names[it->word]);
            rc = rs_sf_value(&ps, RS_ERR_ARG, it->v[i], show);
        }
        if (!rc)
            rc = rs_sf_profile_item(&ps, &d, it->word, it->v);
    }
    if (!rc) {
        ps.line = first + nitems;
        rc = d.syntax->build(&ps, &d, s);
    }
    free(d.seg);
    free(d.segline);
    if (rc)
        memset(s, 0, sizeof *s);
    else
        rs_error_clear(err);
    return rc;
}
