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

#include "surface_file.h"

#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static void draft_free(draft *d)
{
    free(d->seg);
    free(d->segline);
    memset(d, 0, sizeof *d);
}

/* The names of the kinds that take the parameters params (0: every kind), as messages
 * list them: "A, B or C". */
static const char *kind_list(unsigned params, char *buf, size_t size)
{
    const rs_surface_ops *ops;
    int n = 0, j = 0;
    for (int k = 0; (ops = rs_surface_kind_at(k)) != NULL; k++)
        n += ops->syntax && (ops->syntax->params & params) == params;
    buf[0] = '\0';
    for (int k = 0; (ops = rs_surface_kind_at(k)) != NULL; k++) {
        if (!ops->syntax || (ops->syntax->params & params) != params)
            continue;
        const size_t used = strlen(buf);
        snprintf(buf + used, size - used, "%s%s",
                 j == 0       ? ""
                 : j == n - 1 ? " or "
                              : ", ",
                 ops->name);
        j++;
    }
    return buf;
}

static int keyword_line(const parser *ps, const tok *t, int nt, draft *d)
{
    char key[64], show[64], kinds[160];
    const char *val_type = "";
    tok first = {t[0].p + 1, t[0].len - 1};
    rs_sf_normkey(&first, key, sizeof key);
    if (strcmp(key, "SURFACE") != 0) {
        rs_sf_showtok(&first, show, sizeof show);
        return rs_sf_error(ps, RS_ERR_PARSE, "unknown keyword '*%s' (expected *SURFACE)%s",
                           show, NULL);
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
            rs_sf_showtok(&t[i], show, sizeof show);
            return rs_sf_error(
                ps, RS_ERR_PARSE,
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
        rs_sf_normkey(&k, key, sizeof key);
        char val[96];
        rs_sf_normkey(&v, val, sizeof val);
        int dup = 0;
        if (strcmp(key, "TYPE") == 0) {
            dup = have_type++;
            if (!dup) {
                const rs_surface_ops *ops = NULL;
                for (int k = 0; (ops = rs_surface_kind_at(k)) != NULL; k++)
                    if (ops->syntax && strcmp(val, ops->name) == 0)
                        break;
                if (!ops) {
                    rs_sf_showtok(&v, show, sizeof show);
                    return rs_sf_error(ps, RS_ERR_PARSE, "unknown TYPE=%s (expected %s)",
                                       show, kind_list(0, kinds, sizeof kinds));
                }
                d->syntax = ops->syntax;
                d->kind = d->syntax->kind;
                val_type = ops->name;
            }
        } else if (strcmp(key, "NAME") == 0) {
            dup = have_name++;
            if (!dup) {
                if (v.len <= 0 || (size_t)v.len >= sizeof d->name)
                    return rs_sf_error(ps, RS_ERR_PARSE,
                                       "expected NAME= with 1 to 79 characters%s%s", NULL,
                                       NULL);
                for (int c = 0; c < v.len; c++) {
                    if (!isprint((unsigned char)v.p[c]))
                        return rs_sf_error(ps, RS_ERR_PARSE,
                                           "expected a printable NAME=%s%s", NULL, NULL);
                    d->name[c] = v.p[c];
                }
                d->name[v.len] = '\0';
            }
        } else if (strcmp(key, "FILLETRADIUS") == 0) {
            dup = have_fillet++;
            if (!dup) {
                int rc = rs_sf_number(ps, &v, &d->fillet);
                if (rc)
                    return rc;
                if (!(d->fillet > 0.0))
                    return rs_sf_error(ps, RS_ERR_PARSE, "expected FILLET RADIUS > 0%s%s",
                                       NULL, NULL);
            }
        } else if (strcmp(key, "SIDES") == 0) {
            dup = have_sides++;
            if (!dup) {
                if (strcmp(val, "1") == 0)
                    d->sides = 1;
                else if (strcmp(val, "2") == 0)
                    d->sides = 2;
                else
                    return rs_sf_error(ps, RS_ERR_PARSE, "expected SIDES=1 or SIDES=2%s%s",
                                       NULL, NULL);
            }
        } else if (strcmp(key, "EXTENT") == 0) {
            dup = have_extent++;
            if (!dup) {
                int rc = rs_sf_number(ps, &v, &d->zmin);
                if (rc)
                    return rc;
                if (i + 1 >= nt || memchr(t[i + 1].p, '=', (size_t)t[i + 1].len))
                    return rs_sf_error(ps, RS_ERR_PARSE,
                                       "expected EXTENT=zmin, zmax (two values)%s%s", NULL,
                                       NULL);
                rc = rs_sf_number(ps, &t[++i], &d->zmax);
                if (rc)
                    return rc;
                if (!(d->zmax > d->zmin))
                    return rs_sf_error(ps, RS_ERR_PARSE,
                                       "expected EXTENT with zmin < zmax%s%s", NULL, NULL);
                d->bounded = 1;
            }
        } else if (strcmp(key, "FILE") == 0) {
            dup = have_file++;
            if (!dup) {
                int len = v.len;
                while (len > 0 && isspace((unsigned char)v.p[len - 1]))
                    len--;
                if (len <= 0 || (size_t)len >= sizeof d->file)
                    return rs_sf_error(ps, RS_ERR_PARSE,
                                       "expected FILE= with a file name of 1 to 4095 "
                                       "characters%s%s",
                                       NULL, NULL);
                memcpy(d->file, v.p, (size_t)len);
                d->file[len] = '\0';
            }
        } else if (strcmp(key, "SCALE") == 0) {
            dup = have_scale++;
            if (!dup) {
                int rc = rs_sf_number(ps, &v, &d->scale);
                if (rc)
                    return rc;
                if (!(d->scale > 0.0) || !(d->scale <= RS_COORD_MAX))
                    return rs_sf_error(ps, RS_ERR_PARSE,
                                       "expected SCALE > 0 (a finite number)%s%s", NULL,
                                       NULL);
            }
        } else {
            rs_sf_showtok(&k, show, sizeof show);
            return rs_sf_error(
                ps, RS_ERR_PARSE,
                "unknown parameter '%s' (expected TYPE, NAME, FILLET RADIUS, SIDES, "
                "EXTENT, FILE or SCALE)%s",
                show, NULL);
        }
        if (dup) {
            rs_sf_showtok(&k, show, sizeof show);
            return rs_sf_error(ps, RS_ERR_PARSE, "parameter '%s' given twice%s", show,
                               NULL);
        }
    }
    if (!have_type)
        return rs_sf_error(ps, RS_ERR_PARSE, "expected TYPE=%s on *SURFACE%s",
                           kind_list(0, kinds, sizeof kinds), NULL);
    const rs_surface_syntax *sx = d->syntax;
    if (have_extent && !(sx->params & RS_SF_EXTENT))
        return rs_sf_error(ps, RS_ERR_PARSE, "EXTENT is only for TYPE=%s%s",
                           kind_list(RS_SF_EXTENT, kinds, sizeof kinds), NULL);
    int rc = sx->head ? sx->head(ps, d, have_file) : RS_OK;
    if (rc)
        return rc;
    if (have_fillet && !(sx->params & RS_SF_FILLET))
        return rs_sf_error(ps, RS_ERR_PARSE, "FILLET RADIUS is not for TYPE=%s%s", val_type,
                           NULL);
    if ((have_file || have_scale) && !(sx->params & RS_SF_FILE))
        return rs_sf_error(ps, RS_ERR_PARSE, "FILE= and SCALE= are only for TYPE=%s%s",
                           kind_list(RS_SF_FILE, kinds, sizeof kinds), NULL);
    return RS_OK;
}

static int data_line(const parser *ps, tok *t, int nt, draft *d)
{
    if (!d->active)
        return rs_sf_error(ps, RS_ERR_PARSE, "expected *SURFACE before data lines%s%s",
                           NULL, NULL);
    return d->syntax->line(ps, t, nt, d);
}

/* Frees a surface this reader made and zeroes it. */
static void surface_free(rs_surface *s)
{
    if (s->ops && s->ops->free)
        s->ops->free(s);
    memset(s, 0, sizeof *s);
}

/* Turns a complete draft into a surface, by its kind's syntax. */
static int finish_draft(parser *ps, draft *d, rs_surface *s)
{
    memset(s, 0, sizeof *s);
    return d->syntax->build(ps, d, s);
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
            rs_sf_normkey(&bare, key, sizeof key);
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
            tok t[RS_SF_MAXTOK];
            int nt = rs_sf_split(ln, len, t);
            if (nt < 0) {
                rc = rs_sf_error(&ps, RS_ERR_PARSE,
                                 "too many values on one line (expected at most %s)%s",
                                 "15", NULL);
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
                            rc = rs_sf_error(&ps, RS_ERR_PARSE,
                                             "surface NAME=%s defined twice%s", d.name,
                                             first);
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
