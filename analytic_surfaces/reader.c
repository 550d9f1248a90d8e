/* Surface files: Abaqus-style keyword text (docs/conventions.md, "Profiles and surfaces").
 *
 *   ** comment
 *   *SURFACE, TYPE=SEGMENTS|CYLINDER|REVOLUTION, NAME=name [, FILLET RADIUS=r]
 *             [, SIDES=2] [, EXTENT=zmin, zmax]        (EXTENT: CYLINDER only)
 *   ax, ay, az, bx, by, bz                              (CYLINDER, REVOLUTION)
 *   cx, cy, cz                                          (CYLINDER)
 *   START, x, y
 *   LINE, x1, y1
 *   CIRCL, x1, y1, xc, yc
 *   PARAB, xm, ym, x1, y1
 *   *SURFACE, TYPE=MESH, NAME=name [, FILE=part.stl] [, SCALE=s] [, SIDES=1|2]
 *   ax, ay, az, bx, by, bz, cx, cy, cz                  (MESH, optional placement)
 *   *NODE, *ELEMENT, TYPE=R3D3|R3D4, *INCLUDE           (a MESH without FILE= is the
 *                                                        rigid part of this file)
 *
 * Keywords, parameters and profile words are case-insensitive and blanks inside them are
 * ignored (Abaqus rules); values are comma-separated; numbers may use a Fortran D
 * exponent. Every surface of the file is checked; the one named (or the first) is
 * returned. Messages read "ORIGIN:LINE: what was expected". */
#define _POSIX_C_SOURCE 200809L /* fileno, fstat */

#include "mesh.h"
#include "profile.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define MAXTOK 16

typedef struct tok {
    const char *p;
    int len;
} tok;

typedef struct parser {
    const char *origin;
    int line;
    rs_error *err;
    int from_file; /* origin is the path of the file being read */
} parser;

/* A surface being read. */
typedef struct draft {
    int active;
    int kline; /* line of its *SURFACE */
    rs_surface_kind kind;
    char name[80];
    int sides;
    double fillet;
    int bounded;
    double zmin, zmax;
    int ncoord; /* coordinate lines read */
    double ab[6], c[3];
    int started;
    double cur[2];
    int start_line;
    char file[4096]; /* MESH: FILE= as written */
    double scale;    /* MESH: SCALE= */
    int placed;      /* MESH: the placement line was read */
    int self;        /* MESH: its elements are in this file (no FILE=) */
    double abc[9];
    rs_segment *seg;
    int *segline;
    int nseg, cap;
} draft;

static void draft_free(draft *d)
{
    free(d->seg);
    free(d->segline);
    memset(d, 0, sizeof *d);
}

static int perr(const parser *ps, int code, const char *fmt, const char *a, const char *b)
{
    char what[400];
    snprintf(what, sizeof what, fmt, a ? a : "", b ? b : "");
    return rs_error_set(ps->err, code, "%s:%d: %s", ps->origin, ps->line, what);
}

/* Upper-cased token without blanks, truncated to cap - 1 characters. */
static void normkey(const tok *t, char *out, size_t cap)
{
    size_t o = 0;
    for (int i = 0; i < t->len && o + 1 < cap; i++) {
        unsigned char ch = (unsigned char)t->p[i];
        if (!isspace(ch))
            out[o++] = (char)toupper(ch);
    }
    out[o] = '\0';
}

/* Printable copy of a token for messages. */
static void showtok(const tok *t, char *out, size_t cap)
{
    size_t o = 0;
    for (int i = 0; i < t->len && o + 4 < cap; i++) {
        unsigned char ch = (unsigned char)t->p[i];
        out[o++] = isprint(ch) ? (char)ch : '?';
    }
    if ((size_t)t->len + 4 >= cap && o + 4 <= cap) {
        out[o++] = '.';
        out[o++] = '.';
        out[o++] = '.';
    }
    out[o] = '\0';
}

static int parse_number(const parser *ps, const tok *t, double *v)
{
    char buf[128], show[64];
    showtok(t, show, sizeof show);
    if (t->len <= 0)
        return perr(ps, RS_ERR_PARSE, "expected a number, found an empty value%s%s", NULL,
                    NULL);
    if ((size_t)t->len >= sizeof buf)
        return perr(ps, RS_ERR_PARSE, "expected a number, found '%s'%s", show, NULL);
    for (int i = 0; i < t->len; i++) {
        char ch = t->p[i];
        if (!(isdigit((unsigned char)ch) || ch == '+' || ch == '-' || ch == '.' ||
              ch == 'e' || ch == 'E' || ch == 'd' || ch == 'D'))
            return perr(ps, RS_ERR_PARSE, "expected a number, found '%s'%s", show, NULL);
        buf[i] = (ch == 'd' || ch == 'D') ? 'e' : ch;
    }
    buf[t->len] = '\0';
    char *end;
    errno = 0;
    double x = strtod(buf, &end);
    if (end != buf + t->len || end == buf || !isfinite(x))
        return perr(ps, RS_ERR_PARSE, "expected a finite number, found '%s'%s", show, NULL);
    if (fabs(x) > RS_COORD_MAX)
        return perr(ps, RS_ERR_PARSE,
                    "expected a number of magnitude at most 1e100, found '%s'%s", show,
                    NULL);
    *v = x;
    return RS_OK;
}

/* Splits a line at commas; tokens are trimmed. Returns the count or -1 beyond MAXTOK. */
static int split(const char *s, int len, tok *t)
{
    int n = 0, i = 0;
    for (;;) {
        int b = i;
        while (i < len && s[i] != ',')
            i++;
        int e = i;
        while (b < e && isspace((unsigned char)s[b]))
            b++;
        while (e > b && isspace((unsigned char)s[e - 1]))
            e--;
        if (n == MAXTOK)
            return -1;
        t[n].p = s + b;
        t[n].len = e - b;
        n++;
        if (i >= len)
            break;
        i++;
    }
    /* Abaqus allows trailing empty fields */
    while (n > 1 && t[n - 1].len == 0)
        n--;
    return n;
}

static int parse_numbers(const parser *ps, const tok *t, int n, double *v)
{
    for (int i = 0; i < n; i++) {
        int rc = parse_number(ps, &t[i], &v[i]);
        if (rc)
            return rc;
    }
    return RS_OK;
}

static int keyword_line(const parser *ps, const tok *t, int nt, draft *d)
{
    char key[64], show[64];
    tok first = {t[0].p + 1, t[0].len - 1};
    normkey(&first, key, sizeof key);
    if (strcmp(key, "SURFACE") != 0) {
        showtok(&first, show, sizeof show);
        return perr(ps, RS_ERR_PARSE, "unknown keyword '*%s' (expected *SURFACE)%s", show,
                    NULL);
    }
    memset(d, 0, sizeof *d);
    d->active = 1;
    d->kline = ps->line;
    d->scale = 1.0; /* sides 0: the kind's default, set when the surface is made */
    int have_type = 0, have_name = 0, have_fillet = 0, have_sides = 0, have_extent = 0;
    int have_file = 0, have_scale = 0;
    for (int i = 1; i < nt; i++) {
        const char *eq = memchr(t[i].p, '=', (size_t)t[i].len);
        if (!eq) {
            showtok(&t[i], show, sizeof show);
            return perr(ps, RS_ERR_PARSE,
                        "unknown parameter '%s' (expected TYPE=, NAME=, FILLET RADIUS=, "
                        "SIDES=, EXTENT=, FILE= or SCALE=)%s",
                        show, NULL);
        }
        tok k = {t[i].p, (int)(eq - t[i].p)};
        tok v = {eq + 1, t[i].len - (int)(eq - t[i].p) - 1};
        while (v.len > 0 && isspace((unsigned char)v.p[0])) {
            v.p++;
            v.len--;
        }
        normkey(&k, key, sizeof key);
        char val[96];
        normkey(&v, val, sizeof val);
        int dup = 0;
        if (strcmp(key, "TYPE") == 0) {
            dup = have_type++;
            if (!dup) {
                if (strcmp(val, "SEGMENTS") == 0)
                    d->kind = RS_SURF_SEGMENTS;
                else if (strcmp(val, "CYLINDER") == 0)
                    d->kind = RS_SURF_CYLINDER;
                else if (strcmp(val, "REVOLUTION") == 0)
                    d->kind = RS_SURF_REVOLUTION;
                else if (strcmp(val, "MESH") == 0)
                    d->kind = RS_SURF_FACETED;
                else {
                    showtok(&v, show, sizeof show);
                    return perr(ps, RS_ERR_PARSE,
                                "unknown TYPE=%s (expected SEGMENTS, CYLINDER, REVOLUTION "
                                "or MESH)%s",
                                show, NULL);
                }
            }
        } else if (strcmp(key, "NAME") == 0) {
            dup = have_name++;
            if (!dup) {
                if (v.len <= 0 || (size_t)v.len >= sizeof d->name)
                    return perr(ps, RS_ERR_PARSE,
                                "expected NAME= with 1 to 79 characters%s%s", NULL, NULL);
                for (int c = 0; c < v.len; c++) {
                    if (!isprint((unsigned char)v.p[c]))
                        return perr(ps, RS_ERR_PARSE, "expected a printable NAME=%s%s",
                                    NULL, NULL);
                    d->name[c] = v.p[c];
                }
                d->name[v.len] = '\0';
            }
        } else if (strcmp(key, "FILLETRADIUS") == 0) {
            dup = have_fillet++;
            if (!dup) {
                int rc = parse_number(ps, &v, &d->fillet);
                if (rc)
                    return rc;
                if (!(d->fillet > 0.0))
                    return perr(ps, RS_ERR_PARSE, "expected FILLET RADIUS > 0%s%s", NULL,
                                NULL);
            }
        } else if (strcmp(key, "SIDES") == 0) {
            dup = have_sides++;
            if (!dup) {
                if (strcmp(val, "1") == 0)
                    d->sides = 1;
                else if (strcmp(val, "2") == 0)
                    d->sides = 2;
                else
                    return perr(ps, RS_ERR_PARSE, "expected SIDES=1 or SIDES=2%s%s", NULL,
                                NULL);
            }
        } else if (strcmp(key, "EXTENT") == 0) {
            dup = have_extent++;
            if (!dup) {
                int rc = parse_number(ps, &v, &d->zmin);
                if (rc)
                    return rc;
                if (i + 1 >= nt || memchr(t[i + 1].p, '=', (size_t)t[i + 1].len))
                    return perr(ps, RS_ERR_PARSE,
                                "expected EXTENT=zmin, zmax (two values)%s%s", NULL, NULL);
                rc = parse_number(ps, &t[++i], &d->zmax);
                if (rc)
                    return rc;
                if (!(d->zmax > d->zmin))
                    return perr(ps, RS_ERR_PARSE, "expected EXTENT with zmin < zmax%s%s",
                                NULL, NULL);
                d->bounded = 1;
            }
        } else if (strcmp(key, "FILE") == 0) {
            dup = have_file++;
            if (!dup) {
                int len = v.len;
                while (len > 0 && isspace((unsigned char)v.p[len - 1]))
                    len--;
                if (len <= 0 || (size_t)len >= sizeof d->file)
                    return perr(ps, RS_ERR_PARSE,
                                "expected FILE= with a file name of 1 to 4095 "
                                "characters%s%s",
                                NULL, NULL);
                memcpy(d->file, v.p, (size_t)len);
                d->file[len] = '\0';
            }
        } else if (strcmp(key, "SCALE") == 0) {
            dup = have_scale++;
            if (!dup) {
                int rc = parse_number(ps, &v, &d->scale);
                if (rc)
                    return rc;
                if (!(d->scale > 0.0) || !(d->scale <= RS_COORD_MAX))
                    return perr(ps, RS_ERR_PARSE,
                                "expected SCALE > 0 (a finite number)%s%s", NULL, NULL);
            }
        } else {
            showtok(&k, show, sizeof show);
            return perr(
                ps, RS_ERR_PARSE,
                "unknown parameter '%s' (expected TYPE, NAME, FILLET RADIUS, SIDES, "
                "EXTENT, FILE or SCALE)%s",
                show, NULL);
        }
        if (dup) {
            showtok(&k, show, sizeof show);
            return perr(ps, RS_ERR_PARSE, "parameter '%s' given twice%s", show, NULL);
        }
    }
    if (!have_type)
        return perr(ps, RS_ERR_PARSE,
                    "expected TYPE=SEGMENTS, CYLINDER, REVOLUTION or MESH on *SURFACE%s%s",
                    NULL, NULL);
    if (have_extent && d->kind != RS_SURF_CYLINDER)
        return perr(ps, RS_ERR_PARSE, "EXTENT is only for TYPE=CYLINDER%s%s", NULL, NULL);
    if (d->kind == RS_SURF_FACETED) {
        if (!have_file && !ps->from_file)
            return perr(ps, RS_ERR_PARSE, "expected FILE= on *SURFACE, TYPE=MESH%s%s", NULL,
                        NULL);
        d->self = !have_file; /* the *NODE and *ELEMENT lines of this file */
        if (have_fillet)
            return perr(ps, RS_ERR_PARSE, "FILLET RADIUS is not for TYPE=MESH%s%s", NULL,
                        NULL);
    } else if (have_file || have_scale) {
        return perr(ps, RS_ERR_PARSE, "FILE= and SCALE= are only for TYPE=MESH%s%s", NULL,
                    NULL);
    }
    return RS_OK;
}

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
    char word[16], show[64], where[300];
    if (!d->active)
        return perr(ps, RS_ERR_PARSE, "expected *SURFACE before data lines%s%s", NULL,
                    NULL);
    /* values separated by blanks, not commas: a first field with a blank inside that
     * starts with a profile word, or with a number where points are expected */
    int w = 0;
    while (w < t[0].len && !isspace((unsigned char)t[0].p[w]))
        w++;
    if (w < t[0].len) {
        static const char *const form[][2] = {{"START", "START, x, y"},
                                              {"LINE", "LINE, x1, y1"},
                                              {"CIRCL", "CIRCL, x1, y1, xc, yc"},
                                              {"PARAB", "PARAB, xm, ym, x1, y1"}};
        const char *want = NULL;
        tok head = {t[0].p, w};
        normkey(&head, word, sizeof word);
        for (int i = 0; i < 4; i++)
            if (strcmp(word, form[i][0]) == 0)
                want = form[i][1];
        const char c0 = t[0].p[0];
        if (!want && (isdigit((unsigned char)c0) || c0 == '+' || c0 == '-' || c0 == '.')) {
            if (d->kind == RS_SURF_FACETED && !d->placed)
                want = "ax, ay, az, bx, by, bz, cx, cy, cz";
            else if (d->kind == RS_SURF_CYLINDER && d->ncoord == 1)
                want = "cx, cy, cz";
            else if (d->kind != RS_SURF_FACETED && d->kind != RS_SURF_SEGMENTS &&
                     d->ncoord == 0)
                want = "ax, ay, az, bx, by, bz";
        }
        if (want) {
            showtok(&t[0], show, sizeof show);
            return perr(ps, RS_ERR_PARSE, "expected commas between values: %s (found '%s')",
                        want, show);
        }
    }
    if (d->kind == RS_SURF_FACETED) {
        if (d->placed)
            return perr(ps, RS_ERR_PARSE,
                        "a MESH takes one data line, its placement a, b, c (found a "
                        "second)%s%s",
                        NULL, NULL);
        if (nt != 9) {
            char cnt[16];
            snprintf(cnt, sizeof cnt, "%d", nt);
            return perr(
                ps, RS_ERR_PARSE,
                "expected the placement a, b, c (9 numbers: ax, ay, az, bx, by, bz, "
                "cx, cy, cz), found %s values%s",
                cnt, NULL);
        }
        int rc = parse_numbers(ps, t, nt, d->abc);
        if (rc)
            return rc;
        d->placed = 1;
        return RS_OK;
    }
    int ncoord_needed = d->kind == RS_SURF_CYLINDER     ? 2
                        : d->kind == RS_SURF_REVOLUTION ? 1
                                                        : 0;
    if (d->ncoord < ncoord_needed) {
        int want = d->ncoord == 0 ? 6 : 3;
        const char *what = d->ncoord == 0
                               ? "the points a, b (6 numbers: ax, ay, az, bx, by, bz)"
                               : "the point c (3 numbers: cx, cy, cz)";
        normkey(&t[0], word, sizeof word);
        if (strcmp(word, "START") == 0 || strcmp(word, "LINE") == 0 ||
            strcmp(word, "CIRCL") == 0 || strcmp(word, "PARAB") == 0)
            return perr(ps, RS_ERR_PARSE, "expected %s before the profile, found %s", what,
                        word);
        if (nt != want) {
            char cnt[16];
            snprintf(cnt, sizeof cnt, "%d", nt);
            return perr(ps, RS_ERR_PARSE, "expected %s, found %s values", what, cnt);
        }
        int rc = parse_numbers(ps, t, nt, d->ncoord == 0 ? d->ab : d->c);
        if (rc)
            return rc;
        d->ncoord++;
        return RS_OK;
    }
    normkey(&t[0], word, sizeof word);
    int want;
    if (strcmp(word, "START") == 0 || strcmp(word, "LINE") == 0)
        want = 2;
    else if (strcmp(word, "CIRCL") == 0 || strcmp(word, "PARAB") == 0)
        want = 4;
    else {
        showtok(&t[0], show, sizeof show);
        return perr(ps, RS_ERR_PARSE,
                    "unknown profile line '%s' (expected START, LINE, CIRCL or PARAB)%s",
                    show, NULL);
    }
    if (nt - 1 != want) {
        char msg[64];
        snprintf(msg, sizeof msg, "%d values, found %d", want, nt - 1);
        return perr(ps, RS_ERR_PARSE, "%s takes %s", word, msg);
    }
    double v[4];
    int rc = parse_numbers(ps, t + 1, want, v);
    if (rc)
        return rc;
    if (strcmp(word, "START") == 0) {
        if (d->started)
            return perr(ps, RS_ERR_PARSE,
                        "START must be the first profile line (found a second START)%s%s",
                        NULL, NULL);
        d->started = 1;
        d->start_line = ps->line;
        d->cur[0] = v[0];
        d->cur[1] = v[1];
        return RS_OK;
    }
    if (!d->started)
        return perr(ps, RS_ERR_PARSE, "expected START before %s%s", word, NULL);
    snprintf(where, sizeof where, "%s:%d", ps->origin, ps->line);
    rs_segment g;
    if (word[0] == 'L')
        rc = rs_segment_line(&g, d->cur, v, where, ps->err);
    else if (word[0] == 'C')
        rc = rs_segment_circl(&g, d->cur, v, v + 2, where, ps->err);
    else
        rc = rs_segment_parab(&g, d->cur, v, v + 2, where, ps->err);
    if (rc)
        return rc;
    return push_segment(ps, d, &g);
}

/* Frees a surface this reader made and zeroes it. */
static void surface_free(rs_surface *s)
{
    if (s->ops && s->ops->free)
        s->ops->free(s);
    else
        rs_analytic_free(s);
    memset(s, 0, sizeof *s);
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

/* A MESH: its FILE is relative to the folder of the surface file. */
static int finish_mesh(parser *ps, draft *d, rs_surface *s)
{
    char path[8192], where[400];
    const char *slash = strrchr(ps->origin, '/');
    if (d->self)
        snprintf(path, sizeof path, "%s", ps->origin);
    else if (d->file[0] != '/' && slash && ps->from_file)
        snprintf(path, sizeof path, "%.*s/%s", (int)(slash - ps->origin), ps->origin,
                 d->file);
    else
        snprintf(path, sizeof path, "%s", d->file);
    snprintf(where, sizeof where, "%s:%d", ps->origin, d->kline);
    memcpy(s->name, d->name, sizeof s->name);
    s->sides = d->sides;
    int rc = rs_mesh_surface_load(s, path, d->scale, d->placed, d->abc, where, ps->err);
    if (rc) {
        if (s->ops && s->ops->free)
            s->ops->free(s);
        memset(s, 0, sizeof *s);
    }
    return rc;
}

/* Turns a complete draft into a surface. */
static int finish_draft(parser *ps, draft *d, rs_surface *s)
{
    int rc;
    memset(s, 0, sizeof *s);
    if (d->kind == RS_SURF_FACETED)
        return finish_mesh(ps, d, s);
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
    surface_free(s);
    return rc;
}

static int name_eq(const char *a, const char *b)
{
    for (; *a && *b; a++, b++)
        if (toupper((unsigned char)*a) != toupper((unsigned char)*b))
            return 0;
    return *a == *b;
}

/* Appends name to the comma-separated list in buf, bounded by size; once a name does not
 * fit, the list ends in "..." and *full is set. */
static void names_add(char *buf, size_t size, int *full, const char *name)
{
    if (*full)
        return;
    const size_t used = strlen(buf);
    const char *sep = used ? ", " : "";
    if (used + strlen(sep) + strlen(name) + sizeof ", ..." <= size) {
        snprintf(buf + used, size - used, "%s%s", sep, name);
    } else {
        snprintf(buf + used, size - used, "%s...", sep);
        *full = 1;
    }
}

/* Abaqus keywords of a rigid part that a surface file may hold for its MESH surfaces
 * (src/faceted/abaqus_part.c reads them): skipped here with their data lines. */
static int part_keyword(const char *key)
{
    return !strcmp(key, "NODE") || !strcmp(key, "ELEMENT") || !strcmp(key, "INCLUDE") ||
           !strcmp(key, "HEADING");
}

static int parse_text(const char *text, const char *origin, const char *name, rs_surface *s,
                      rs_error *err, int from_file)
{
    parser ps = {origin ? origin : "<text>", 0, err, from_file};
    int skipping = 0; /* in the data lines of a part keyword */
    draft d;
    rs_surface cur;
    int found = 0, nsurf = 0, rc = RS_OK;
    char names[200] = "";
    int names_full = 0;
    struct seen_name {
        char name[80];
        int line;
    } *seen = NULL;
    int nseen = 0, seencap = 0;
    memset(&d, 0, sizeof d);
    if (!s)
        return rs_error_set(err, RS_ERR_ARG, "rs_surface_parse: NULL surface");
    memset(s, 0, sizeof *s);
    if (!text)
        return rs_error_set(err, RS_ERR_ARG, "rs_surface_parse: NULL text");
    const char *p = text;
    for (;;) {
        int at_end = *p == '\0';
        const char *e = p;
        if (!at_end) {
            ps.line++;
            while (*e && *e != '\n')
                e++;
        }
        int len = (int)(e - p);
        while (len > 0 && isspace((unsigned char)p[len - 1]))
            len--;
        int b = 0;
        while (b < len && isspace((unsigned char)p[b]))
            b++;
        const char *ln = p + b;
        len -= b;
        int is_kw = len > 0 && ln[0] == '*' && !(len > 1 && ln[1] == '*');
        if (is_kw) {
            /* an unknown keyword is reported at its own line, before the surface that
             * it ends is checked */
            const char *c = memchr(ln, ',', (size_t)len);
            tok kw = {ln, (int)((c ? c : ln + len) - ln)};
            tok bare = {ln + 1, kw.len - 1};
            char key[16];
            normkey(&bare, key, sizeof key);
            if (strcmp(key, "SURFACE") != 0 && !part_keyword(key)) {
                rc = keyword_line(&ps, &kw, 1, &d);
                goto out;
            }
            skipping = part_keyword(key);
        }
        if ((at_end || is_kw) && d.active) {
            /* a surface ends here: check it whole */
            int saved = ps.line;
            rc = finish_draft(&ps, &d, &cur);
            ps.line = saved;
            if (rc)
                goto out;
            nsurf++;
            names_add(names, sizeof names, &names_full,
                      cur.name[0] ? cur.name : "(unnamed)");
            if (!found && (!name || name_eq(name, cur.name))) {
                *s = cur;
                found = 1;
            } else {
                surface_free(&cur);
            }
            draft_free(&d);
        }
        if (at_end)
            break;
        if (len > 0 && !(len > 1 && ln[0] == '*' && ln[1] == '*') && !skipping) {
            tok t[MAXTOK];
            int nt = split(ln, len, t);
            if (nt < 0) {
                rc =
                    perr(&ps, RS_ERR_PARSE,
                         "too many values on one line (expected at most %s)%s", "15", NULL);
                goto out;
            }
            if (is_kw) {
                rc = keyword_line(&ps, t, nt, &d);
                if (rc)
                    goto out;
                if (d.name[0]) {
                    for (int i = 0; i < nseen; i++) {
                        if (name_eq(seen[i].name, d.name)) {
                            char first[32];
                            snprintf(first, sizeof first, " (first at line %d)",
                                     seen[i].line);
                            rc = perr(&ps, RS_ERR_PARSE, "surface NAME=%s defined twice%s",
                                      d.name, first);
                            goto out;
                        }
                    }
                    if (nseen == seencap) {
                        int nc = seencap ? 2 * seencap : 8;
                        struct seen_name *ns = realloc(seen, (size_t)nc * sizeof *ns);
                        if (!ns) {
                            rc = rs_error_set(err, RS_ERR_NOMEM, "out of memory");
                            goto out;
                        }
                        seen = ns;
                        seencap = nc;
                    }
                    memcpy(seen[nseen].name, d.name, sizeof d.name);
                    seen[nseen++].line = ps.line;
                }
            } else {
                rc = data_line(&ps, t, nt, &d);
                if (rc)
                    goto out;
            }
        }
        p = *e ? e + 1 : e;
    }
    if (!found) {
        if (name)
            rc =
                rs_error_set(err, RS_ERR_NOTFOUND, "%s: surface '%s' not found (found: %s)",
                             ps.origin, name, names[0] ? names : "no *SURFACE");
        else
            rc = rs_error_set(err, RS_ERR_NOTFOUND,
                              "%s: no *SURFACE found (expected at least one surface)",
                              ps.origin);
    }
out:
    draft_free(&d);
    free(seen);
    if (rc && found)
        surface_free(s);
    if (!rc)
        rs_error_clear(err);
    return rc;
}

int rs_surface_parse(const char *text, const char *origin, const char *name, rs_surface *s,
                     rs_error *err)
{
    return parse_text(text, origin, name, s, err, 0);
}

int rs_surface_read(const char *path, const char *name, rs_surface *s, rs_error *err)
{
    if (!s || !path)
        return rs_error_set(err, RS_ERR_ARG, "rs_surface_read: NULL argument");
    memset(s, 0, sizeof *s);
    FILE *f = fopen(path, "rb");
    if (!f)
        return rs_error_set(err, RS_ERR_IO, "%s: cannot open surface file: %s", path,
                            strerror(errno));
    struct stat st;
    if (fstat(fileno(f), &st) == 0 && S_ISDIR(st.st_mode)) {
        fclose(f);
        return rs_error_set(err, RS_ERR_IO, "%s: is a directory (expected a surface file)",
                            path);
    }
    size_t cap = 4096, n = 0;
    char *buf = malloc(cap);
    int rc = RS_OK;
    errno = 0;
    while (buf) {
        if (n + 1 >= cap) {
            char *nb = realloc(buf, cap * 2);
            if (!nb) {
                free(buf);
                buf = NULL;
                break;
            }
            buf = nb;
            cap *= 2;
        }
        size_t got = fread(buf + n, 1, cap - 1 - n, f);
        n += got;
        if (got == 0)
            break;
    }
    const int rerr = ferror(f) ? (errno ? errno : EIO) : 0;
    fclose(f);
    if (!buf)
        return rs_error_set(err, RS_ERR_NOMEM, "%s: out of memory reading the file", path);
    if (rerr) {
        free(buf);
        return rs_error_set(err, RS_ERR_IO, "%s: read error: %s", path, strerror(rerr));
    }
    buf[n] = '\0';
    if (memchr(buf, '\0', n)) {
        int line = 1;
        for (const char *q = buf; *q; q++)
            line += *q == '\n';
        free(buf);
        return rs_error_set(err, RS_ERR_PARSE, "%s:%d: unexpected NUL byte (expected text)",
                            path, line);
    }
    rc = parse_text(buf, path, name, s, err, 1);
    free(buf);
    return rc;
}
