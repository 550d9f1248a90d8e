/* The MESH kind's files: a mesh file (STL, OBJ, OFF, PLY through CGAL, or an Abaqus rigid
 * part) read, checked, placed and built into a surface (rs_mesh_surface_load), and the
 * MESH surface in a surface file (rs_mesh_syntax: FILE=, SCALE=, its placement line). */
#define _POSIX_C_SOURCE 200809L /* stat */

#include "abaqus_part.h"
#include "cgal_mesh.h"
#include "mesh.h"
#include "rigidsurf/vec.h"
#include "surface_file.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* STL checks the reader leaves out: an ASCII STL (it starts with "solid" and reads as
 * text) ends with "endsolid", so a file cut short is an error and not a smaller mesh; a
 * binary STL is exactly 84 + 50 n bytes for its n facets, and its coordinates are finite
 * (the reader merges equal points, and a NaN would merge with anything). */
static int stl_check(const char *file, const char *where, rs_error *err)
{
    const char *dot = strrchr(file, '.');
    if (!dot || strlen(dot) != 4 || tolower((unsigned char)dot[1]) != 's' ||
        tolower((unsigned char)dot[2]) != 't' || tolower((unsigned char)dot[3]) != 'l')
        return RS_OK;
    FILE *f = fopen(file, "rb");
    if (!f)
        return RS_OK; /* reported by the reader */
    unsigned char head[84];
    const size_t nh = fread(head, 1, sizeof head, f);
    long size = -1;
    if (fseek(f, 0, SEEK_END) == 0)
        size = ftell(f);
    int text = nh >= 5 && memcmp(head, "solid", 5) == 0;
    for (size_t k = 0; k < nh && text; k++)
        text = head[k] != 0;
    int rc = RS_OK;
    if (text) {
        char tail[256];
        size_t nt = 0;
        const long from = size > (long)sizeof tail - 1 ? size - (long)sizeof tail + 1 : 0;
        if (size > 0 && fseek(f, from, SEEK_SET) == 0)
            nt = fread(tail, 1, sizeof tail - 1, f);
        tail[nt] = '\0';
        if (!memchr(tail, '\0', nt) && !strstr(tail, "endsolid"))
            rc = rs_error_set(err, RS_ERR_PARSE,
                              "%s: %s: ASCII STL ends without 'endsolid' (broken or "
                              "truncated)",
                              where, file);
    } else if (nh == sizeof head) {
        const unsigned long n = (unsigned long)head[80] | (unsigned long)head[81] << 8 |
                                (unsigned long)head[82] << 16 |
                                (unsigned long)head[83] << 24;
        if (size < 0 || (unsigned long)size != 84ul + 50ul * n)
            rc = rs_error_set(
                err, RS_ERR_PARSE,
                "%s: %s: binary STL of %ld bytes announces %lu facets (expected "
                "84 + 50 x %lu = %lu bytes: broken or truncated)",
                where, file, size, n, n, 84ul + 50ul * n);
        unsigned char rec[50];
        if (!rc && fseek(f, 84, SEEK_SET) == 0)
            for (unsigned long k = 0; k < n && !rc && fread(rec, 1, 50, f) == 50; k++)
                for (int j = 3; j < 12 && !rc; j++) { /* the three vertices */
                    float v;
                    memcpy(&v, rec + 4 * j, 4);
                    if (!isfinite(v))
                        rc = rs_error_set(err, RS_ERR_GEOMETRY,
                                          "%s: %s: facet %lu has coordinate %g (expected "
                                          "finite coordinates)",
                                          where, file, k + 1, (double)v);
                }
    }
    fclose(f);
    return rc;
}

int rs_mesh_placement(int placed, const double abc[9], const char *where,
                      double frame[4][3], rs_error *err)
{
    double *a = frame[0], *ex = frame[1], *ey = frame[2], *ez = frame[3];
    for (int d = 0; d < 3; d++) {
        a[d] = 0.0;
        ex[d] = d == 0;
        ey[d] = d == 1;
        ez[d] = d == 2;
    }
    if (!placed)
        return RS_OK;
    const double *pa = abc, *pb = abc + 3, *pc = abc + 6;
    double u[3] = {pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]};
    double w[3] = {pc[0] - pa[0], pc[1] - pa[1], pc[2] - pa[2]};
    double scl = 0.0;
    for (int i = 0; i < 9; i++)
        scl = fmax(scl, fabs(abc[i]));
    const double lu = rs_norm3(u), lw = rs_norm3(w);
    if (!(lu > 1e-12 * scl) || !isfinite(lu) || !isfinite(lw))
        return rs_error_set(err, RS_ERR_GEOMETRY,
                            "%s: points a and b coincide (expected distinct points a, b "
                            "placing the mesh)",
                            where);
    for (int d = 0; d < 3; d++)
        ex[d] = u[d] / lu;
    const double along = rs_dot3(w, ex);
    double y[3] = {w[0] - along * ex[0], w[1] - along * ex[1], w[2] - along * ex[2]};
    const double ly = rs_norm3(y);
    if (!(lw > 1e-12 * scl) || !(ly > 1e-9 * lw))
        return rs_error_set(err, RS_ERR_GEOMETRY,
                            "%s: point c coincides with a or lies on the line a-b "
                            "(expected c off the mesh's local x axis)",
                            where);
    for (int d = 0; d < 3; d++)
        ey[d] = y[d] / ly;
    rs_cross3(ex, ey, ez);
    memcpy(a, pa, 3 * sizeof *a);
    return RS_OK;
}

int rs_mesh_surface_soup(rs_surface *s, const rs_soup *soup, double scale,
                         const double frame[4][3], int default_sides, const char *origin,
                         rs_error *err)
{
    rs_mesh *m = NULL;
    int two = 0;
    int rc =
        rs_mesh_build(soup, scale, frame[0], frame[1], frame[2], frame[3], origin, &m, &two,
                      s->warning, sizeof s->warning, s->info, sizeof s->info, err);
    if (rc)
        return rc;
    s->impl = m;
    s->ops = &rs_mesh_ops;
    s->kind = RS_SURF_FACETED;
    if (two) /* no consistent orientation: both sides act, whatever was asked */
        s->sides = 2;
    else if (s->sides == 0)
        s->sides = default_sides;
    /* the placement is in the nodes: the reference configuration is global */
    const double I[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    memset(s->a, 0, sizeof s->a);
    memcpy(s->ex, I[0], sizeof s->ex);
    memcpy(s->ey, I[1], sizeof s->ey);
    memcpy(s->ez, I[2], sizeof s->ez);
    return RS_OK;
}

int rs_mesh_surface_load(rs_surface *s, const char *file, double scale, int placed,
                         const double abc[9], const char *where, rs_error *err)
{
    double frame[4][3];
    int rc = rs_mesh_placement(placed, abc, where, frame, err);
    if (rc)
        return rc;
    struct stat st;
    if (stat(file, &st) != 0)
        return rs_error_set(err, RS_ERR_IO, "%s: cannot open mesh file %s: %s", where, file,
                            strerror(errno));
    if (!S_ISREG(st.st_mode))
        return rs_error_set(err, RS_ERR_IO, "%s: %s is %s (expected a mesh file)", where,
                            file,
                            S_ISDIR(st.st_mode) ? "a directory" : "not a regular file");
    FILE *f = fopen(file, "rb");
    if (!f)
        return rs_error_set(err, RS_ERR_IO, "%s: cannot open mesh file %s: %s", where, file,
                            strerror(errno));
    const int empty = fgetc(f) == EOF;
    fclose(f);
    if (empty)
        return rs_error_set(err, RS_ERR_PARSE, "%s: %s is empty (expected a mesh)", where,
                            file);
    rc = stl_check(file, where, err);
    if (rc)
        return rc;
    rs_soup soup;
    char msg[300];
    const char *ext = strrchr(file, '.');
    const int inp = ext && strlen(ext) == 4 && tolower((unsigned char)ext[1]) == 'i' &&
                    tolower((unsigned char)ext[2]) == 'n' &&
                    tolower((unsigned char)ext[3]) == 'p';
    if (inp) { /* an Abaqus rigid part: its messages name file and line */
        if (rs_abaqus_read_soup(file, &soup, msg, sizeof msg))
            return rs_error_set(err, RS_ERR_PARSE, "%s: %s", where, msg);
    } else if (rs_cgal_read_soup(file, &soup, msg, sizeof msg)) {
        return rs_error_set(err, RS_ERR_PARSE, "%s: %s: %s", where, file, msg);
    }
    rc = rs_mesh_surface_soup(s, &soup, scale, (const double(*)[3])frame, inp ? 1 : 2, file,
                              err);
    rs_soup_free(&soup);
    return rc;
}

/* FILE= names the mesh, unless the surface file itself holds its elements (*NODE,
 * *ELEMENT). */
static int mesh_head(const parser *ps, draft *d, int have_file)
{
    if (!have_file && !ps->from_file)
        return rs_sf_error(ps, RS_ERR_PARSE, "expected FILE= on *SURFACE, TYPE=MESH%s%s",
                           NULL, NULL);
    d->self = !have_file; /* the *NODE and *ELEMENT lines of this file */
    return RS_OK;
}

/* A MESH's one data line: its placement a, b, c. */
static int mesh_line(const parser *ps, tok *t, int nt, draft *d)
{
    int rc = rs_sf_commas(ps, t, d->placed ? NULL : "ax, ay, az, bx, by, bz, cx, cy, cz");
    if (rc)
        return rc;
    if (d->placed)
        return rs_sf_error(ps, RS_ERR_PARSE,
                           "a MESH takes one data line, its placement a, b, c (found a "
                           "second)%s%s",
                           NULL, NULL);
    if (nt != 9) {
        char cnt[16];
        snprintf(cnt, sizeof cnt, "%d", nt);
        return rs_sf_error(
            ps, RS_ERR_PARSE,
            "expected the placement a, b, c (9 numbers: ax, ay, az, bx, by, bz, "
            "cx, cy, cz), found %s values%s",
            cnt, NULL);
    }
    rc = rs_sf_numbers(ps, t, nt, d->abc);
    if (rc)
        return rc;
    d->placed = 1;
    return RS_OK;
}

/* A MESH: its FILE is relative to the folder of the surface file. */
static int mesh_build(parser *ps, draft *d, rs_surface *s)
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

const rs_surface_syntax rs_mesh_syntax = {RS_SURF_FACETED, RS_SF_FILE, mesh_head, mesh_line,
                                          mesh_build};
