/* The values of Abaqus-style keyword text (surface_file.h): tokens, numbers (a Fortran D
 * exponent allowed), and messages at the line being read. */
#include "surface_file.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int rs_sf_error(const parser *ps, int code, const char *fmt, const char *a, const char *b)
{
    char what[400];
    snprintf(what, sizeof what, fmt, a ? a : "", b ? b : "");
    return rs_error_set(ps->err, code, "%s:%d: %s", ps->origin, ps->line, what);
}

void rs_sf_normkey(const tok *t, char *out, size_t cap)
{
    size_t o = 0;
    for (int i = 0; i < t->len && o + 1 < cap; i++) {
        unsigned char ch = (unsigned char)t->p[i];
        if (!isspace(ch))
            out[o++] = (char)toupper(ch);
    }
    out[o] = '\0';
}

void rs_sf_showtok(const tok *t, char *out, size_t cap)
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

int rs_sf_number(const parser *ps, const tok *t, double *v)
{
    char buf[128], show[64];
    rs_sf_showtok(t, show, sizeof show);
    if (t->len <= 0)
        return rs_sf_error(ps, RS_ERR_PARSE, "expected a number, found an empty value%s%s",
                           NULL, NULL);
    if ((size_t)t->len >= sizeof buf)
        return rs_sf_error(ps, RS_ERR_PARSE, "expected a number, found '%s'%s", show, NULL);
    for (int i = 0; i < t->len; i++) {
        char ch = t->p[i];
        if (!(isdigit((unsigned char)ch) || ch == '+' || ch == '-' || ch == '.' ||
              ch == 'e' || ch == 'E' || ch == 'd' || ch == 'D'))
            return rs_sf_error(ps, RS_ERR_PARSE, "expected a number, found '%s'%s", show,
                               NULL);
        buf[i] = (ch == 'd' || ch == 'D') ? 'e' : ch;
    }
    buf[t->len] = '\0';
    char *end;
    errno = 0;
    double x = strtod(buf, &end);
    if (end != buf + t->len || end == buf)
        return rs_sf_error(ps, RS_ERR_PARSE, "expected a finite number, found '%s'%s", show,
                           NULL);
    int rc = rs_sf_value(ps, RS_ERR_PARSE, x, show);
    if (rc)
        return rc;
    *v = x;
    return RS_OK;
}

int rs_sf_value(const parser *ps, int code, double x, const char *show)
{
    char buf[32];
    if (!show) {
        snprintf(buf, sizeof buf, "%.17g", x);
        show = buf;
    }
    if (!isfinite(x))
        return rs_sf_error(ps, code, "expected a finite number, found '%s'%s", show, NULL);
    if (fabs(x) > RS_COORD_MAX)
        return rs_sf_error(ps, code,
                           "expected a number of magnitude at most 1e100, found '%s'%s",
                           show, NULL);
    return RS_OK;
}

int rs_sf_split(const char *s, int len, tok *t)
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
        if (n == RS_SF_MAXTOK)
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

int rs_sf_numbers(const parser *ps, const tok *t, int n, double *v)
{
    for (int i = 0; i < n; i++) {
        int rc = rs_sf_number(ps, &t[i], &v[i]);
        if (rc)
            return rc;
    }
    return RS_OK;
}

int rs_sf_commas(const parser *ps, const tok *t, const char *points)
{
    int w = 0;
    while (w < t[0].len && !isspace((unsigned char)t[0].p[w]))
        w++;
    if (w == t[0].len)
        return RS_OK;
    static const char *const form[][2] = {{"START", "START, x, y"},
                                          {"LINE", "LINE, x1, y1"},
                                          {"CIRCL", "CIRCL, x1, y1, xc, yc"},
                                          {"PARAB", "PARAB, xm, ym, x1, y1"}};
    char word[16], show[64];
    const tok head = {t[0].p, w};
    rs_sf_normkey(&head, word, sizeof word);
    const char *want = NULL;
    for (int i = 0; i < 4; i++)
        if (strcmp(word, form[i][0]) == 0)
            want = form[i][1];
    const char c0 = t[0].p[0];
    if (!want && (isdigit((unsigned char)c0) || c0 == '+' || c0 == '-' || c0 == '.'))
        want = points;
    if (!want)
        return RS_OK;
    rs_sf_showtok(&t[0], show, sizeof show);
    return rs_sf_error(ps, RS_ERR_PARSE, "expected commas between values: %s (found '%s')",
                       want, show);
}
