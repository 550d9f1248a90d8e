/* The SUBROUTINE statement of a user routine read from its Fortran source, and its
 * argument count against the lists the loaders call (law_signature.h).
 *
 * The source is cut into statements as the compiler does: comment lines and trailing
 * '!' comments dropped, continuation lines joined (fixed form: a character other than
 * blank or '0' in column 6, or a tab followed by a digit 1-9; free form: a trailing
 * '&', and a leading '&' on the next line), ';' separating statements. Blanks outside
 * character constants are dropped and letters outside them made upper case, so the
 * blank-insensitive fixed form and any spelling compare alike. INCLUDE lines (and cpp's
 * #include "...") are followed into the files of the source's folder, as the build's
 * hash follows them. */
#define _POSIX_C_SOURCE 200809L

#include "law_signature.h"
#include "rigidsurf/law_build.h"

#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The build compiles fixed form to column 132 (law_build.c). */
#define FIXED_COLUMNS 132
#define INCLUDE_DEPTH 8

typedef struct scan {
    const char *name; /* upper case */
    const char *file;
    int free_form, depth;
    rs_fsub *sub;
    rs_error *err;
    int rc;   /* RS_OK, or the first failure */
    int done; /* the statement was found, or a failure stops the scan */
    /* the statement being joined: upper case, no blanks outside character constants */
    char *st;
    size_t len, cap;
    int line;   /* the line it starts on */
    char quote; /* the open character constant's delimiter, 0 outside one */
    int cont;   /* free form: the last line ended with '&' */
} scan;

/* Ends the scan with rc (the message already set when rc is a failure). */
static void finish(scan *sc, int rc)
{
    sc->rc = rc;
    sc->done = 1;
}

static void put(scan *sc, char c)
{
    if (sc->len + 2 > sc->cap) {
        size_t cap = sc->cap ? 2 * sc->cap : 256;
        char *grown = (char *)realloc(sc->st, cap);
        if (!grown) {
            if (!sc->done)
                finish(sc,
                       rs_error_set(sc->err, RS_ERR_NOMEM, "%s: out of memory", sc->file));
            return;
        }
        sc->st = grown;
        sc->cap = cap;
    }
    sc->st[sc->len++] = c;
    sc->st[sc->len] = '\0';
}

static void add_char(scan *sc, char c)
{
    if (sc->quote) {
        put(sc, c == '\0' ? ' ' : c);
        if (c == sc->quote)
            sc->quote = 0; /* a doubled quote closes and opens again */
    } else if (c == '\'' || c == '"') {
        sc->quote = c;
        put(sc, c);
    } else if (c != ' ' && c != '\t' && c != '\r' && c != '\0') {
        put(sc, (char)toupper((unsigned char)c));
    }
}

static void scan_text(scan *sc, const char *text, size_t n);

/* The whole file, or NULL with errno. */
static char *read_text(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    char *text = NULL;
    size_t len = 0, cap = 0;
    for (;;) {
        if (len + 4096 > cap) {
            size_t grown_cap = cap ? 2 * cap : 16384;
            char *grown = (char *)realloc(text, grown_cap);
            if (!grown) {
                free(text);
                fclose(f);
                errno = ENOMEM;
                return NULL;
            }
            text = grown;
            cap = grown_cap;
        }
        size_t got = fread(text + len, 1, cap - len, f);
        len += got;
        if (got == 0)
            break;
    }
    const int failed = ferror(f);
    fclose(f);
    if (failed) {
        free(text);
        errno = EIO;
        return NULL;
    }
    *n = len;
    return text;
}

/* Reads the file an INCLUDE names, from the folder of the file that names it; a file
 * that is not there is left to the compiler's include path (ABA_PARAM.INC). */
static void follow_include(scan *sc, const char *name, size_t n)
{
    if (sc->depth + 1 >= INCLUDE_DEPTH || n == 0)
        return;
    char path[4096 + 256];
    const char *slash = strrchr(sc->file, '/');
    if (name[0] == '/' || !slash)
        snprintf(path, sizeof path, "%.*s", (int)n, name);
    else
        snprintf(path, sizeof path, "%.*s/%.*s", (int)(slash - sc->file), sc->file, (int)n,
                 name);
    size_t len = 0;
    char *text = read_text(path, &len);
    if (!text)
        return;
    scan in;
    memset(&in, 0, sizeof in);
    in.name = sc->name;
    in.file = path;
    in.free_form = sc->free_form;
    in.depth = sc->depth + 1;
    in.sub = sc->sub;
    in.err = sc->err;
    scan_text(&in, text, len);
    free(text);
    free(in.st);
    if (in.done) {
        sc->done = 1;
        sc->rc = in.rc;
    }
}

static int is_name(const char *a, size_t n)
{
    if (n == 1 && a[0] == '*') /* an alternate return */
        return 1;
    if (n == 0 || !isalpha((unsigned char)a[0]))
        return 0;
    for (size_t i = 1; i < n; ++i)
        if (!isalnum((unsigned char)a[i]) && a[i] != '_' && a[i] != '$')
            return 0;
    return 1;
}

static void found(scan *sc, int nargs)
{
    snprintf(sc->sub->file, sizeof sc->sub->file, "%s", sc->file);
    sc->sub->line = sc->line;
    sc->sub->nargs = nargs;
    finish(sc, RS_OK);
}

/* Counts the dummy arguments of the list that opens at p ('('). */
static void count_arguments(scan *sc, const char *p)
{
    int nargs = 0;
    const char *arg = p + 1;
    for (const char *r = p + 1;; ++r) {
        if (*r == '\0') {
            finish(sc,
                   rs_error_set(sc->err, RS_ERR_PARSE,
                                "%s:%d: SUBROUTINE %s: the argument list is not closed "
                                "by ')' after %d arguments (a continuation mark "
                                "missing?)",
                                sc->file, sc->line, sc->name, nargs + (r > arg ? 1 : 0)));
            return;
        }
        if (*r != ',' && *r != ')')
            continue;
        const size_t n = (size_t)(r - arg);
        if (*r == ')' && nargs == 0 && n == 0)
            break; /* NAME() */
        if (!is_name(arg, n)) {
            char what[64];
            snprintf(what, sizeof what, "'%.*s'", (int)(n < 40 ? n : 40), arg);
            finish(sc, rs_error_set(sc->err, RS_ERR_PARSE,
                                    "%s:%d: SUBROUTINE %s: argument %d, %s, is not a name",
                                    sc->file, sc->line, sc->name, nargs + 1,
                                    n ? what : "empty"));
            return;
        }
        ++nargs;
        if (*r == ')')
            break;
        arg = r + 1;
    }
    found(sc, nargs);
}

static int starts(const char *p, const char *word)
{
    return strncmp(p, word, strlen(word)) == 0;
}

/* A finished statement: the routine's SUBROUTINE statement, or an INCLUDE. */
static void examine(scan *sc)
{
    const char *p = sc->st;
    if (!p || sc->done)
        return;
    while (isdigit((unsigned char)*p)) /* a free-form label */
        ++p;
    if (starts(p, "INCLUDE") && (p[7] == '\'' || p[7] == '"')) {
        const char *end = strchr(p + 8, p[7]);
        if (end)
            follow_include(sc, p + 8, (size_t)(end - p - 8));
        return;
    }
    static const char *const prefixes[] = {"RECURSIVE", "NON_RECURSIVE", "PURE",
                                           "IMPURE",    "ELEMENTAL",     "MODULE"};
    while (!starts(p, "SUBROUTINE")) {
        size_t i = 0;
        while (i < sizeof prefixes / sizeof *prefixes && !starts(p, prefixes[i]))
            ++i;
        if (i == sizeof prefixes / sizeof *prefixes)
            return;
        p += strlen(prefixes[i]);
    }
    p += strlen("SUBROUTINE");
    if (!starts(p, sc->name))
        return;
    p += strlen(sc->name);
    if (*p == '(') {
        count_arguments(sc, p);
    } else if (*p == '\0') {
        found(sc, 0);
    }
}

static void end_statement(scan *sc)
{
    if (sc->len > 0)
        examine(sc);
    sc->len = 0;
    if (sc->st)
        sc->st[0] = '\0';
    sc->quote = 0;
}

static void begin_statement(scan *sc, int line)
{
    end_statement(sc);
    sc->line = line;
}

/* The statement text [b, e) of one line: '!' outside a character constant starts a
 * comment, ';' ends the statement. */
static void add_text(scan *sc, const char *b, const char *e, int line)
{
    for (const char *p = b; p < e && !sc->done; ++p) {
        if (!sc->quote && *p == '!')
            return;
        if (!sc->quote && *p == ';') {
            begin_statement(sc, line);
            continue;
        }
        add_char(sc, *p);
    }
}

/* cpp's #include "FILE" (in .F, .fpp, .F90 sources). */
static void cpp_line(scan *sc, const char *b, const char *e)
{
    const char *p = b + 1;
    while (p < e && (*p == ' ' || *p == '\t'))
        ++p;
    if ((size_t)(e - p) < 8 || strncmp(p, "include", 7) != 0)
        return;
    p += 7;
    while (p < e && (*p == ' ' || *p == '\t'))
        ++p;
    if (p >= e || *p != '"')
        return;
    const char *q = memchr(p + 1, '"', (size_t)(e - p - 1));
    if (q)
        follow_include(sc, p + 1, (size_t)(q - p - 1));
}

static void fixed_line(scan *sc, const char *b, const char *e, int line)
{
    if (b == e || *b == 'C' || *b == 'c' || *b == '*' || *b == '!')
        return;
    if (*b == '#') {
        cpp_line(sc, b, e);
        return;
    }
    /* columns 1-5 the label, 6 the continuation mark; a tab in them ends the label,
     * and a digit 1-9 right after it marks a continuation (DEC's tab form) */
    const char *p = b;
    int col = 0, cont = 0;
    while (p < e && col < 6) {
        if (*p == '\t') {
            ++p;
            if (p < e && *p >= '1' && *p <= '9') {
                cont = 1;
                ++p;
            }
            break;
        }
        if (col == 5) {
            cont = *p != ' ' && *p != '0';
            ++p;
            break;
        }
        if (*p == '!')
            return; /* a comment in the label field */
        ++p;
        ++col;
    }
    const char *end = e - p > FIXED_COLUMNS - 6 ? p + (FIXED_COLUMNS - 6) : e;
    if (!cont) {
        const char *q = p;
        while (q < end && (*q == ' ' || *q == '\t' || *q == '\r'))
            ++q;
        if (q == end || *q == '!')
            return; /* a blank or comment line continues nothing and ends nothing */
        begin_statement(sc, line);
    } else if (sc->line == 0) {
        sc->line = line;
    }
    add_text(sc, p, end, line);
}

static void free_line(scan *sc, const char *b, const char *e, int line)
{
    if (b < e && *b == '#') {
        cpp_line(sc, b, e);
        return;
    }
    const char *p = b;
    while (p < e && (*p == ' ' || *p == '\t' || *p == '\r'))
        ++p;
    if (p == e || *p == '!')
        return;
    if (sc->cont) {
        if (*p == '&')
            ++p;
    } else {
        begin_statement(sc, line);
    }
    /* the end of the statement text: a comment, then a trailing '&' */
    const char *end = e;
    char q = sc->quote;
    for (const char *r = p; r < e; ++r) {
        if (q) {
            if (*r == q)
                q = 0;
        } else if (*r == '\'' || *r == '"') {
            q = *r;
        } else if (*r == '!') {
            end = r;
            break;
        }
    }
    while (end > p && (end[-1] == ' ' || end[-1] == '\t' || end[-1] == '\r'))
        --end;
    sc->cont = end > p && end[-1] == '&';
    if (sc->cont)
        --end;
    add_text(sc, p, end, line);
}

static void scan_text(scan *sc, const char *text, size_t n)
{
    const char *p = text, *e = text + n;
    int line = 0;
    while (p < e && !sc->done) {
        const char *nl = memchr(p, '\n', (size_t)(e - p));
        const char *le = nl ? nl : e;
        ++line;
        if (sc->free_form)
            free_line(sc, p, le, line);
        else
            fixed_line(sc, p, le, line);
        p = nl ? nl + 1 : e;
    }
    end_statement(sc);
}

int rs_fsub_scan(const char *text, size_t n, int free_form, const char *file,
                 const char *name, rs_fsub *sub, rs_error *err)
{
    if (!sub || !name || !name[0] || (!text && n))
        return rs_error_set(err, RS_ERR_ARG, "rs_fsub_scan: no text, routine or result");
    char upper[64];
    size_t ln = strlen(name);
    if (ln >= sizeof upper)
        return rs_error_set(err, RS_ERR_ARG, "rs_fsub_scan: routine name '%s' too long",
                            name);
    for (size_t i = 0; i <= ln; ++i)
        upper[i] = (char)toupper((unsigned char)name[i]);
    memset(sub, 0, sizeof *sub);
    scan sc;
    memset(&sc, 0, sizeof sc);
    sc.name = upper;
    sc.file = file ? file : "(text)";
    sc.free_form = free_form;
    sc.sub = sub;
    sc.err = err;
    scan_text(&sc, text, n);
    free(sc.st);
    if (sc.done)
        return sc.rc;
    return rs_error_set(err, RS_ERR_NOTFOUND,
                        "%s: no SUBROUTINE %s statement (nor in the files it INCLUDEs)",
                        sc.file, upper);
}

int rs_fsub_read(const char *path, const char *name, rs_fsub *sub, rs_error *err)
{
    const int form = rs_law_source_form(path);
    if (!form)
        return rs_error_set(err, RS_ERR_ARG, "%s: not a Fortran source",
                            path ? path : "(null)");
    size_t n = 0;
    char *text = read_text(path, &n);
    if (!text) {
        const int e = errno;
        return rs_error_set(err, RS_ERR_IO, "%s: cannot read: %s", path, strerror(e));
    }
    const int rc = rs_fsub_scan(text, n, form == RS_FORM_FREE, path, name, sub, err);
    free(text);
    return rc;
}

/* The lists the adapters of law_fortran.h call, by routine. */
static const struct {
    const char *routine;
    rs_arglist list;
    int nargs;
    const char *what;
} lists[] = {
    {"VUINTER", RS_ARGS_VUINTER, 49, "Abaqus/Explicit's list, SFD, SCD, SPD, SVD, ..."},
    {"UINTER", RS_ARGS_UINTER, 47,
     "Abaqus's current list, DVISCOUS and DSTRUCTURAL after DDSDDR, FREQR after DTIME"},
    {"UINTER", RS_ARGS_UINTER_OLDER, 44,
     "the older list, without DVISCOUS, DSTRUCTURAL and FREQR"},
    {"FRIC", RS_ARGS_FRIC, 39, "Abaqus's list, LM, TAU, DDTDDG, ..."},
};
enum { NLISTS = sizeof lists / sizeof *lists };

int rs_law_source_list(const char *src, const char *routine, rs_arglist *list,
                       rs_error *err)
{
    if (!routine || !list)
        return rs_error_set(err, RS_ERR_ARG, "rs_law_source_list: no routine or result");
    char upper[16];
    snprintf(upper, sizeof upper, "%s", routine);
    for (char *c = upper; *c; ++c)
        *c = (char)toupper((unsigned char)*c);
    int known = 0;
    for (int i = 0; i < NLISTS; ++i)
        known += strcmp(lists[i].routine, upper) == 0;
    if (!known)
        return rs_error_set(err, RS_ERR_ARG,
                            "rs_law_source_list: '%s' is not VUINTER, UINTER or FRIC",
                            routine);
    rs_fsub sub;
    int rc = rs_fsub_read(src, upper, &sub, err);
    if (rc)
        return rc;
    char expected[400] = "";
    size_t used = 0;
    int nexp = 0;
    for (int i = 0; i < NLISTS; ++i) {
        if (strcmp(lists[i].routine, upper) != 0)
            continue;
        if (lists[i].nargs == sub.nargs) {
            *list = lists[i].list;
            return RS_OK;
        }
        int w = snprintf(expected + used, sizeof expected - used, "%s%d (%s)",
                         nexp ? " or " : "", lists[i].nargs, lists[i].what);
        if (w > 0 && (size_t)w < sizeof expected - used)
            used += (size_t)w;
        ++nexp;
    }
    return rs_error_set(
        err, RS_ERR_ARG,
        "%s:%d: SUBROUTINE %s has %d arguments; rigidsurf calls %s with %s. "
        "Names are free, the number and order of the arguments are not "
        "(abaqus.md)",
        sub.file, sub.line, upper, sub.nargs, upper, expected);
}
