/* An Abaqus rigid part as a polygon soup: *NODE and *ELEMENT, TYPE=R3D3 or R3D4 lines of
 * an input file and the files it names with *INCLUDE, INPUT=. Other keywords are skipped
 * with their data lines; an element of another type is an error, as is a node named
 * twice or an element naming a node that no *NODE defines. Keywords and parameters are
 * case-insensitive; "**" starts a comment line. Messages read "FILE:LINE: what was
 * expected". */
#define _POSIX_C_SOURCE 200809L
#include "abaqus_part.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_DEPTH 8
#define MAX_LINE 4096

typedef struct node_id {
    long id;
    int index;
} node_id;

typedef struct part {
    double *xyz;
    long *nid; /* node ids in file order */
    int np, pcap;
    long *eid;  /* element ids */
    int *elem;  /* 4 per element */
    int *enn;   /* nodes of each element: 3 or 4 */
    int *eline; /* line of each element, for messages */
    const char **efile;
    int ne, ecap;
    char *files[64]; /* names of the files read, for messages */
    int nfiles;
} part;

/* Grows arrays p[0..n) of element sizes size[0..n) to hold need entries. */
static int grow(void **p[], const size_t size[], int n, int *cap, int need)
{
    if (need <= *cap)
        return 0;
    int nc = *cap ? 2 * *cap : 64;
    for (int k = 0; k < n; k++) {
        void *q = realloc(*p[k], (size_t)nc * size[k]);
        if (!q)
            return -1;
        *p[k] = q;
    }
    *cap = nc;
    return 0;
}

/* Upper-case copy of s without blanks. */
static void normkey(const char *s, size_t n, char *out, size_t cap)
{
    size_t k = 0;
    for (size_t i = 0; i < n && k + 1 < cap; i++)
        if (!isspace((unsigned char)s[i]))
            out[k++] = (char)toupper((unsigned char)s[i]);
    out[k] = '\0';
}

/* The value of parameter NAME on keyword line ln ("" when absent), as written. */
static void param(const char *ln, const char *name, char *out, size_t cap)
{
    out[0] = '\0';
    const char *p = strchr(ln, ',');
    while (p) {
        const char *q = strchr(p + 1, ',');
        const char *end = q ? q : p + 1 + strlen(p + 1);
        const char *eq = memchr(p + 1, '=', (size_t)(end - p - 1));
        if (eq) {
            char key[64];
            normkey(p + 1, (size_t)(eq - p - 1), key, sizeof key);
            if (!strcmp(key, name)) {
                const char *v = eq + 1;
                while (v < end && isspace((unsigned char)*v))
                    v++;
                size_t n = (size_t)(end - v);
                while (n > 0 && isspace((unsigned char)v[n - 1]))
                    n--;
                if (n >= cap)
                    n = cap - 1;
                memcpy(out, v, n);
                out[n] = '\0';
                return;
            }
        }
        p = q;
    }
}

/* Splits a data line at commas into at most max fields; returns the count. */
static int fields(char *ln, char **f, int max)
{
    int n = 0;
    char *p = ln;
    while (n < max) {
        while (isspace((unsigned char)*p))
            p++;
        f[n++] = p;
        char *c = strchr(p, ',');
        if (!c)
            break;
        *c = '\0';
        p = c + 1;
    }
    for (int k = 0; k < n; k++) {
        size_t l = strlen(f[k]);
        while (l > 0 && isspace((unsigned char)f[k][l - 1]))
            f[k][--l] = '\0';
    }
    if (n == 1 && f[0][0] == '\0')
        return 0;
    return n;
}

static int fail(char *msg, size_t cap, const char *file, int line, const char *what)
{
    snprintf(msg, cap, "%s:%d: %s", file, line, what);
    return -1;
}

static int read_file(part *pt, const char *path, int depth, char *msg, size_t cap)
{
    if (depth > MAX_DEPTH)
        return fail(msg, cap, path, 0,
                    "*INCLUDE nested too deep (expected at most 8 levels)");
    FILE *f = fopen(path, "r");
    if (!f) {
        snprintf(msg, cap, "%s: cannot open: %s", path, strerror(errno));
        return -1;
    }
    if (pt->nfiles == 64) {
        fclose(f);
        return fail(msg, cap, path, 0, "too many included files (expected at most 64)");
    }
    char *fname = strdup(path);
    if (!fname) {
        fclose(f);
        snprintf(msg, cap, "out of memory");
        return -1;
    }
    pt->files[pt->nfiles++] = fname;
    enum { SKIP, NODES, ELEMS } mode = SKIP;
    int nn = 0; /* corners of the current element type */
    char ln[MAX_LINE + 2], buf[256];
    int line = 0, rc = 0;
    while (fgets(ln, sizeof ln, f)) {
        line++;
        size_t l = strlen(ln);
        if (l == sizeof ln - 1 && ln[l - 1] != '\n') {
            rc = fail(msg, cap, fname, line, "line longer than 4096 characters");
            break;
        }
        while (l > 0 && isspace((unsigned char)ln[l - 1]))
            ln[--l] = '\0';
        char *s = ln;
        while (isspace((unsigned char)*s))
            s++;
        if (!*s || (s[0] == '*' && s[1] == '*'))
            continue;
        if (s[0] == '*') {
            const char *c = strchr(s, ',');
            char key[64];
            normkey(s + 1, c ? (size_t)(c - s - 1) : strlen(s + 1), key, sizeof key);
            mode = SKIP;
            if (!strcmp(key, "NODE")) {
                mode = NODES;
            } else if (!strcmp(key, "ELEMENT")) {
                char type[64], t[64];
                param(s, "TYPE", t, sizeof t);
                normkey(t, strlen(t), type, sizeof type);
                if (!strcmp(type, "R3D3"))
                    nn = 3;
                else if (!strcmp(type, "R3D4"))
                    nn = 4;
                else {
                    snprintf(buf, sizeof buf,
                             "*ELEMENT, TYPE=%s is not a rigid surface element (expected "
                             "TYPE=R3D3 or R3D4)",
                             type[0] ? type : "(none)");
                    rc = fail(msg, cap, fname, line, buf);
                    break;
                }
                mode = ELEMS;
            } else if (!strcmp(key, "INCLUDE")) {
                char inc[1024], full[2048];
                param(s, "INPUT", inc, sizeof inc);
                if (!inc[0]) {
                    rc = fail(msg, cap, fname, line, "expected *INCLUDE, INPUT=file");
                    break;
                }
                const char *slash = strrchr(fname, '/');
                if (inc[0] != '/' && slash)
                    snprintf(full, sizeof full, "%.*s/%s", (int)(slash - fname), fname,
                             inc);
                else
                    snprintf(full, sizeof full, "%s", inc);
                if ((rc = read_file(pt, full, depth + 1, msg, cap)) != 0)
                    break;
            }
            continue;
        }
        if (mode == SKIP)
            continue;
        char *fv[8];
        const int nf = fields(s, fv, 8);
        char *end;
        const long id = strtol(fv[0], &end, 10);
        if (nf < 1 || *end || end == fv[0]) {
            snprintf(buf, sizeof buf, "expected a %s number first, found '%.40s'",
                     mode == NODES ? "node" : "element", nf ? fv[0] : "");
            rc = fail(msg, cap, fname, line, buf);
            break;
        }
        if (mode == NODES) {
            if (nf < 3 || nf > 4) {
                rc = fail(msg, cap, fname, line, "expected a node line: number, x, y[, z]");
                break;
            }
            void **arr[2] = {(void **)&pt->xyz, (void **)&pt->nid};
            const size_t sz[2] = {3 * sizeof(double), sizeof(long)};
            if (grow(arr, sz, 2, &pt->pcap, pt->np + 1)) {
                snprintf(msg, cap, "out of memory");
                rc = -1;
                break;
            }
            for (int d = 0; d < 3; d++) {
                double v = 0.0;
                if (d + 1 < nf) {
                    v = strtod(fv[d + 1], &end);
                    if (*end || end == fv[d + 1]) {
                        snprintf(buf, sizeof buf, "expected a coordinate, found '%.40s'",
                                 fv[d + 1]);
                        rc = fail(msg, cap, fname, line, buf);
                        break;
                    }
                }
                pt->xyz[3 * pt->np + d] = v;
            }
            if (rc)
                break;
            pt->nid[pt->np++] = id;
        } else {
            if (nf != nn + 1) {
                snprintf(buf, sizeof buf,
                         "expected an R3D%d line: number and %d nodes, found "
                         "%d values",
                         nn, nn, nf);
                rc = fail(msg, cap, fname, line, buf);
                break;
            }
            void **arr[5] = {(void **)&pt->elem, (void **)&pt->enn, (void **)&pt->eid,
                             (void **)&pt->eline, (void **)&pt->efile};
            const size_t sz[5] = {4 * sizeof(int), sizeof(int), sizeof(long), sizeof(int),
                                  sizeof(char *)};
            if (grow(arr, sz, 5, &pt->ecap, pt->ne + 1)) {
                snprintf(msg, cap, "out of memory");
                rc = -1;
                break;
            }
            int *e = pt->elem + 4 * pt->ne;
            pt->enn[pt->ne] = nn;
            for (int k = 0; k < nn; k++) {
                const long n = strtol(fv[k + 1], &end, 10);
                if (*end || end == fv[k + 1]) {
                    snprintf(buf, sizeof buf, "expected a node number, found '%.40s'",
                             fv[k + 1]);
                    rc = fail(msg, cap, fname, line, buf);
                    break;
                }
                if (n < -2147483647L || n > 2147483647L) {
                    rc = fail(msg, cap, fname, line, "node number out of range");
                    break;
                }
                e[k] = (int)n;
            }
            if (rc)
                break;
            pt->eid[pt->ne] = id;
            pt->eline[pt->ne] = line;
            pt->efile[pt->ne] = fname;
            pt->ne++;
        }
    }
    if (!rc && ferror(f)) {
        snprintf(msg, cap, "%s: read error", fname);
        rc = -1;
    }
    fclose(f);
    return rc;
}

static int cmp_node(const void *a, const void *b)
{
    const node_id *x = a, *y = b;
    return (x->id > y->id) - (x->id < y->id);
}

int rs_abaqus_read_soup(const char *path, rs_soup *soup, char *msg, size_t cap)
{
    memset(soup, 0, sizeof *soup);
    part pt;
    memset(&pt, 0, sizeof pt);
    int rc = read_file(&pt, path, 0, msg, cap);
    node_id *map = NULL;
    if (!rc && (pt.np == 0 || pt.ne == 0)) {
        snprintf(msg, cap,
                 "%s: %d nodes and %d R3D3/R3D4 elements (expected a rigid part: "
                 "*NODE and *ELEMENT, TYPE=R3D3 or R3D4)",
                 path, pt.np, pt.ne);
        rc = -1;
    }
    if (!rc) {
        map = malloc((size_t)pt.np * sizeof *map);
        soup->xyz = malloc((size_t)pt.np * 3 * sizeof(double));
        soup->off = malloc((size_t)(pt.ne + 1) * sizeof(int));
        soup->idx = malloc((size_t)pt.ne * 4 * sizeof(int));
        if (!map || !soup->xyz || !soup->off || !soup->idx) {
            snprintf(msg, cap, "out of memory");
            rc = -1;
        }
    }
    if (!rc) {
        for (int i = 0; i < pt.np; i++) {
            map[i].id = pt.nid[i];
            map[i].index = i;
        }
        qsort(map, (size_t)pt.np, sizeof *map, cmp_node);
        for (int i = 1; i < pt.np; i++)
            if (map[i].id == map[i - 1].id) {
                snprintf(msg, cap,
                         "%s: node %ld defined twice (expected unique node numbers)", path,
                         map[i].id);
                rc = -1;
                break;
            }
    }
    if (!rc) {
        memcpy(soup->xyz, pt.xyz, (size_t)pt.np * 3 * sizeof(double));
        soup->np = pt.np;
        /* the node numbers, when every one fits an INTEGER (VUINTER's jMstUid) */
        soup->label = malloc((size_t)pt.np * sizeof(int));
        for (int i = 0; soup->label && i < pt.np; i++) {
            if (pt.nid[i] < 1 || pt.nid[i] > INT_MAX) {
                free(soup->label);
                soup->label = NULL;
                break;
            }
            soup->label[i] = (int)pt.nid[i];
        }
        int k = 0;
        for (int e = 0; e < pt.ne && !rc; e++) {
            soup->off[e] = k;
            for (int c = 0; c < pt.enn[e] && !rc; c++) {
                const node_id key = {pt.elem[4 * e + c], 0};
                const node_id *hit =
                    bsearch(&key, map, (size_t)pt.np, sizeof *map, cmp_node);
                if (!hit) {
                    snprintf(msg, cap,
                             "%s:%d: element %ld names node %d, which no *NODE "
                             "defines (expected defined nodes)",
                             pt.efile[e], pt.eline[e], pt.eid[e], pt.elem[4 * e + c]);
                    rc = -1;
                    break;
                }
                soup->idx[k++] = hit->index;
            }
        }
        soup->off[pt.ne] = k;
        soup->nf = pt.ne;
    }
    free(map);
    free(pt.xyz);
    free(pt.nid);
    free(pt.eid);
    free(pt.elem);
    free(pt.enn);
    free(pt.eline);
    free(pt.efile);
    for (int i = 0; i < pt.nfiles; i++)
        free(pt.files[i]);
    if (rc)
        rs_soup_free(soup);
    return rc;
}
