/* Polygon soups for the MESH tests (triangles and planar quads, grown as they are
 * written; sp_free frees one), made into MESH surfaces (make), and two of them: the
 * benchmark's cylinder and a UV sphere. */
#ifndef RS_TEST_MESH_SOUP_H
#define RS_TEST_MESH_SOUP_H

#include "faceted/mesh.h"
#include "rigidsurf/surface.h"
#include "rigidsurf/vec.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct soup {
    int np, nf, cap_p, cap_f;
    double *xyz;
    int *off, *idx;
} soup;

static inline int sp_point(soup *s, double x, double y, double z)
{
    if (s->np == s->cap_p) {
        s->cap_p = s->cap_p ? 2 * s->cap_p : 256;
        s->xyz = realloc(s->xyz, 3 * (size_t)s->cap_p * sizeof *s->xyz);
    }
    s->xyz[3 * s->np] = x, s->xyz[3 * s->np + 1] = y, s->xyz[3 * s->np + 2] = z;
    return s->np++;
}

/* A polygon of n = 3 or 4 corners (the fourth ignored for 3). */
static inline void sp_poly(soup *s, int n, int a, int b, int c, int d)
{
    if (s->nf + 1 >= s->cap_f) {
        s->cap_f = s->cap_f ? 2 * s->cap_f : 256;
        s->off = realloc(s->off, ((size_t)s->cap_f + 1) * sizeof *s->off);
        s->idx = realloc(s->idx, 4 * (size_t)s->cap_f * sizeof *s->idx);
    }
    if (s->nf == 0)
        s->off[0] = 0;
    int *k = s->idx + s->off[s->nf];
    k[0] = a, k[1] = b, k[2] = c, k[3] = d;
    s->off[s->nf + 1] = s->off[s->nf] + n;
    s->nf++;
}

static inline void sp_free(soup *s)
{
    free(s->xyz);
    free(s->off);
    free(s->idx);
    memset(s, 0, sizeof *s);
}

/* The surface of soup sp, sides 1 or 2. */
static inline int make(const soup *sp, int sides, rs_surface *s)
{
    rs_soup so = {sp->np, sp->nf, sp->xyz, sp->off, sp->idx, NULL};
    const double frame[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    memset(s, 0, sizeof *s);
    s->sides = sides;
    rs_error e;
    const int rc = rs_mesh_surface_soup(s, &so, 1.0, frame, 2, "test", &e);
    if (rc)
        fprintf(stderr, "mesh: %s\n", e.msg);
    return rc;
}

/* The benchmark's cylinder (bench/liggghts/make_stl.py): nth x nz quads split in two
 * triangles (or kept as planar quads, quads set), nodes on the circle of radius
 * R / cos(pi / nth), wound toward the axis. */
static inline void cylinder(soup *s, int nth, int nz, double R, double zlo, double zhi,
                            int quads)
{
    const double rv = R / cos(RS_PI / nth);
    for (int k = 0; k <= nz; k++)
        for (int i = 0; i < nth; i++) {
            const double a = 2 * RS_PI * i / nth;
            sp_point(s, rv * cos(a), rv * sin(a), zlo + (zhi - zlo) * k / nz);
        }
    for (int i = 0; i < nth; i++)
        for (int k = 0; k < nz; k++) {
            const int a = k * nth + i, b = k * nth + (i + 1) % nth;
            const int c = (k + 1) * nth + (i + 1) % nth, d = (k + 1) * nth + i;
            if (quads) {
                sp_poly(s, 4, a, d, c, b);
                continue;
            }
            sp_poly(s, 3, a, d, c, 0);
            sp_poly(s, 3, a, c, b, 0);
        }
}

/* A UV sphere of radius 1, triangles, wound outward. */
static inline void uv_sphere(soup *s, int nlat, int nlon)
{
    const int north = sp_point(s, 0, 0, 1);
    for (int i = 1; i < nlat; i++)
        for (int j = 0; j < nlon; j++) {
            const double th = RS_PI * i / nlat, ph = 2 * RS_PI * j / nlon;
            sp_point(s, sin(th) * cos(ph), sin(th) * sin(ph), cos(th));
        }
    const int south = sp_point(s, 0, 0, -1);
    for (int j = 0; j < nlon; j++)
        sp_poly(s, 3, north, 1 + j, 1 + (j + 1) % nlon, 0);
    for (int i = 0; i + 2 < nlat; i++)
        for (int j = 0; j < nlon; j++) {
            const int a = 1 + i * nlon + j, b = 1 + i * nlon + (j + 1) % nlon;
            sp_poly(s, 3, a, a + nlon, b + nlon, 0);
            sp_poly(s, 3, a, b + nlon, b, 0);
        }
    const int last = 1 + (nlat - 2) * nlon;
    for (int j = 0; j < nlon; j++)
        sp_poly(s, 3, south, last + (j + 1) % nlon, last + j, 0);
}

#endif
