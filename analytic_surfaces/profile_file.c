/* The analytic kinds in surface files (SEGMENTS, CYLINDER, REVOLUTION): their coordinate
 * lines and profile lines (START, LINE, CIRCL, PARAB), and the making of the surface: its
 * local frame, the profile's checks, fillets and proximity cache. */
#include "profile.h"
#include "surface_file.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int push_segment(const parser *ps, draft *d, const rs_segment *g)
{
    if (d->nseg == d->cap) {
        int cap = d->cap ? 2 * d->cap : 8;
        rs_segment *ns = realloc(d->seg, (size_t)cap * sizeof *ns);
        if (!ns)
            return rs_error_set(ps->err, RS_ERR_NOMEM, "out of memory");
        d->seg = ns;
        int *nl = realloc(d->segline, (size_t)cap * sizeof *nl);
        if (!nl)
            return rs_error_set(ps->err, RS_ERR_NOMEM, "out of memory");
        d->segline = nl;
        d->cap = cap;
    }
    d->segline[d->nseg] = ps->line;
    d->seg[d->nseg++] = *g;
    d->cur[0] = g->p1[0];
    d->cur[1] = g->p1[1];
    return RS_OK;
}

static int data_line(const parser *ps, tok *t, int nt, draft *d)
{
    char word[16], show[64];
    int ncoord_needed = d->kind == RS_SURF_CYLINDER     ? 2
                        : d->kind == RS_SURF_REVOLUTION ? 1
                                                        : 0;
    const char *points = d->ncoord >= ncoord_needed ? NULL
                         : d->ncoord == 0           ? "ax, ay, az, bx, by, bz"
                                                    : "cx, cy, cz";
    int rc = rs_sf_commas(ps, t, points);
    if (rc)
        return rc;
    if (d->ncoord < ncoord_needed) {
        int want = d->ncoord == 0 ? 6 : 3;
        const char *what = d->ncoord == 0
                               ? "the points a, b (6 numbers: ax, ay, az, bx, by, bz)"
                               : "the point c (3 numbers: cx, cy, cz)";
        rs_sf_normkey(&t[0], word, sizeof word);
        if (strcmp(word, "START") == 0 || strcmp(word, "LINE") == 0 ||
            strcmp(word, "CIRCL") == 0 || strcmp(word, "PARAB") == 0)
            return rs_sf_error(ps, RS_ERR_PARSE, "expected %s before the profile, found %s",
                               what, word);
        if (nt != want) {
            char cnt[16];
            snprintf(cnt, sizeof cnt, "%d", nt);
            return rs_sf_error(ps, RS_ERR_PARSE, "expected %s, found %s values", what, cnt);
        }
        rc = rs_sf_numbers(ps, t, nt, d->ncoord == 0 ? d->ab : d->c);
        if (rc)
            return rc;
        d->ncoord++;
        return RS_OK;
    }
    rs_sf_normkey(&t[0], word, sizeof word);
    rs_profile_word w;
    int want = 4;
    if (strcmp(word, "START") == 0 || strcmp(word, "LINE") == 0) {
        w = word[0] == 'S' ? RS_WORD_START : RS_WORD_LINE;
        want = 2;
    } else if (strcmp(word, "CIRCL") == 0) {
        w = RS_WORD_CIRCL;
    } else if (strcmp(word, "PARAB") == 0) {
        w = RS_WORD_PARAB;
    } else {
        rs_sf_showtok(&t[0], show, sizeof show);
        return rs_sf_error(
            ps, RS_ERR_PARSE,
            "unknown profile line '%s' (expected START, LINE, CIRCL or PARAB)%s", show,
            NULL);
    }
    if (nt - 1 != want) {
        char msg[64];
        snprintf(msg, sizeof msg, "%d values, found %d", want, nt - 1);
        return rs_sf_error(ps, RS_ERR_PARSE, "%s takes %s", word, msg);
    }
    double v[4] = {0, 0, 0, 0};
    rc = rs_sf_numbers(ps, t + 1, want, v);
    if (rc)
        return rc;
    return rs_sf_profile_item(ps, d, w, v);
}

int rs_sf_profile_item(const parser *ps, draft *d, rs_profile_word word, const double v[4])
{
    static const char *const names[] = {"START", "LINE", "CIRCL", "PARAB"};
    char where[300];
    if (word == RS_WORD_START) {
        if (d->started)
            return rs_sf_error(
                ps, RS_ERR_PARSE,
                "START must be the first profile line (found a second START)%s%s", NULL,
                NULL);
        d->started = 1;
        d->start_line = ps->line;
        d->cur[0] = v[0];
        d->cur[1] = v[1];
        return RS_OK;
    }
    if (!d->started)
        return rs_sf_error(ps, RS_ERR_PARSE, "expected START before %s%s", names[word],
                           NULL);
    snprintf(where, sizeof where, "%s:%d", ps->origin, ps->line);
    rs_segment g;
    int rc;
    if (word == RS_WORD_LINE)
        rc = rs_segment_line(&g, d->cur, v, where, ps->err);
    else if (word == RS_WORD_CIRCL)
        rc = rs_segment_circl(&g, d->cur, v, v + 2, where, ps->err);
    else
        rc = rs_segment_parab(&g, d->cur, v, v + 2, where, ps->err);
    if (rc)
        return rc;
    return push_segment(ps, d, &g);
}

/* Local frame of the surface from a, b (and c). */
static int build_frame(parser *ps, const draft *d, rs_surface *s)
{
    double scale = 0.0;
    for (int i = 0; i < 6; i++)
        scale = fmax(scale, fabs(d->ab[i]));
    for (int i = 0; i < 3; i++)
        scale = fmax(scale, fabs(d->c[i]));
    const double *a = d->ab, *b = d->ab + 3;
    double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    double lab = rs_norm3(ab);
    if (d->kind == RS_SURF_SEGMENTS) {
        memset(s->a, 0, sizeof s->a);
        double I[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        memcpy(s->ex, I[0], sizeof s->ex);
        memcpy(s->ey, I[1], sizeof s->ey);
        memcpy(s->ez, I[2], sizeof s->ez);
        return RS_OK;
    }
    ps->line = d->kline + 1;
    if (!isfinite(lab) || !isfinite(rs_norm3(d->c)) || !isfinite(rs_norm3(d->ab)))
        return rs_error_set(ps->err, RS_ERR_GEOMETRY,
                            "%s:%d: coordinates too large (expected finite a, b, c)",
                            ps->origin, d->kline + 1);
    if (!(lab > 1e-12 * scale) || lab == 0.0)
        return rs_error_set(
            ps->err, RS_ERR_GEOMETRY,
            "%s:%d: points a and b coincide (expected distinct points a, b)", ps->origin,
            d->kline + 1);
    memcpy(s->a, a, sizeof s->a);
    if (d->kind == RS_SURF_CYLINDER) {
        double ac[3] = {d->c[0] - a[0], d->c[1] - a[1], d->c[2] - a[2]};
        double lac = rs_norm3(ac);
        for (int i = 0; i < 3; i++)
            s->ex[i] = ab[i] / lab;
        double along = ac[0] * s->ex[0] + ac[1] * s->ex[1] + ac[2] * s->ex[2];
        double z[3] = {ac[0] - along * s->ex[0], ac[1] - along * s->ex[1],
                       ac[2] - along * s->ex[2]};
        double lz = rs_norm3(z);
        if (!(lac > 1e-12 * scale) || !(lz > 1e-9 * lac))
            return rs_error_set(ps->err, RS_ERR_GEOMETRY,
                                "%s:%d: point c coincides with a or lies on the line a-b "
                                "(expected c off the local x axis)",
                                ps->origin, d->kline + 2);
        for (int i = 0; i < 3; i++)
            s->ez[i] = z[i] / lz;
        rs_cross3(s->ez, s->ex, s->ey);
        return RS_OK;
    }
    for (int i = 0; i < 3; i++)
        s->ez[i] = ab[i] / lab;
    /* ex: the global axis least aligned with ez, made normal to it */
    int m = 0;
    for (int i = 1; i < 3; i++)
        if (fabs(s->ez[i]) < fabs(s->ez[m]))
            m = i;
    double g[3] = {0, 0, 0};
    g[m] = 1.0;
    double gz = s->ez[m];
    double x[3] = {g[0] - gz * s->ez[0], g[1] - gz * s->ez[1], g[2] - gz * s->ez[2]};
    double lx = rs_norm3(x);
    for (int i = 0; i < 3; i++)
        s->ex[i] = x[i] / lx;
    rs_cross3(s->ez, s->ex, s->ey);
    return RS_OK;
}

/* Smallest r reached by a segment (for REVOLUTION). */
static double seg_rmin(const rs_segment *g)
{
    double r = fmin(g->p0[0], g->p1[0]);
    if (g->type == RS_CIRCL) {
        /* the arc passes the leftmost point of its circle when angle pi is inside */
        double off = remainder(RS_PI - g->ang0, 2.0 * RS_PI);
        double f = off / g->sweep;
        if (f > 0.0 && f < 1.0)
            r = fmin(r, g->pm[0] - g->radius);
    } else if (g->type == RS_PARAB) {
        double B = 0.5 * (g->p1[0] - g->p0[0]);
        double C = 0.5 * (g->p0[0] + g->p1[0]) - g->pm[0];
        if (C > 0.0) {
            double xi = -B / (2.0 * C);
            if (xi > -1.0 && xi < 1.0)
                r = fmin(r, g->pm[0] + xi * B + xi * xi * C);
        }
    }
    return r;
}

/* Turns a complete draft into a surface. */
static int finish_draft(parser *ps, draft *d, rs_surface *s)
{
    int rc;
    int need = d->kind == RS_SURF_CYLINDER ? 2 : d->kind == RS_SURF_REVOLUTION ? 1 : 0;
    if (d->ncoord < need)
        return rs_error_set(ps->err, RS_ERR_PARSE,
                            "%s:%d: surface '%s' ends before its coordinate lines "
                            "(expected %s)",
                            ps->origin, d->kline, d->name,
                            d->kind == RS_SURF_CYLINDER ? "a, b and c" : "a, b");
    if (d->nseg == 0)
        return rs_error_set(
            ps->err, RS_ERR_PARSE,
            "%s:%d: surface '%s' has an empty profile (expected START and at "
            "least one LINE, CIRCL or PARAB)",
            ps->origin, d->kline, d->name);
    s->kind = d->kind;
    s->ops = rs_analytic_ops(d->kind);
    memcpy(s->name, d->name, sizeof s->name);
    s->sides = d->sides ? d->sides : 1;
    s->fillet_radius = d->fillet;
    s->bounded = d->bounded;
    s->zmin = d->zmin;
    s->zmax = d->zmax;
    if ((rc = build_frame(ps, d, s)) != RS_OK)
        return rc;
    s->profile.seg = d->seg;
    s->profile.nseg = d->nseg;
    d->seg = NULL;
    const double size = rs_profile_size(&s->profile);
    for (int k = 0; k < s->profile.nseg; k++) {
        const double len = s->profile.seg[k].length;
        if (!(len >= RS_LENGTH_REL * size && len >= RS_LENGTH_MIN)) {
            rc = rs_error_set(ps->err, RS_ERR_GEOMETRY,
                              "%s:%d: segment of length %g in a profile of size %g "
                              "(expected a length of at least %g of the profile's size "
                              "and at least %g)",
                              ps->origin, d->segline[k], len, size, RS_LENGTH_REL,
                              RS_LENGTH_MIN);
            goto fail;
        }
    }
    if ((rc = rs_profile_finish(&s->profile, NULL, ps->err)) != RS_OK)
        goto fail;
    if (d->fillet > 0.0 && (rc = rs_profile_fillet(&s->profile, d->fillet, &d->segline,
                                                   ps->origin, ps->err)) != RS_OK)
        goto fail;
    if (s->profile.nseg > RS_SECTOR_STRIDE / 4 - 2) {
        rc = rs_error_set(ps->err, RS_ERR_GEOMETRY,
                          "%s:%d: surface '%s' has %d segments (expected at most %d)",
                          ps->origin, d->kline, d->name, s->profile.nseg,
                          RS_SECTOR_STRIDE / 4 - 2);
        goto fail;
    }
    if (s->kind == RS_SURF_REVOLUTION) {
        double tol = 1e-12 * rs_profile_size(&s->profile);
        for (int k = 0; k < s->profile.nseg; k++) {
            double r = seg_rmin(&s->profile.seg[k]);
            if (r < -tol) {
                rc = rs_error_set(ps->err, RS_ERR_GEOMETRY,
                                  "%s:%d: REVOLUTION profile reaches r = %g < 0 (expected "
                                  "the profile on the side r >= 0 of the axis)",
                                  ps->origin, d->segline[k], r);
                goto fail;
            }
        }
    }
    rs_pcache *pc;
    if ((rc = rs_pcache_build(s, &pc, ps->err)) != RS_OK)
        goto fail;
    s->impl = pc;
    return RS_OK;
fail:
    rs_analytic_free(s);
    memset(s, 0, sizeof *s);
    return rc;
}

const rs_surface_syntax rs_segments_syntax = {RS_SURF_SEGMENTS, RS_SF_FILLET, NULL,
                                              data_line, finish_draft};
const rs_surface_syntax rs_cylinder_syntax = {RS_SURF_CYLINDER, RS_SF_FILLET | RS_SF_EXTENT,
                                              NULL, data_line, finish_draft};
const rs_surface_syntax rs_revolution_syntax = {RS_SURF_REVOLUTION, RS_SF_FILLET, NULL,
                                                data_line, finish_draft};
