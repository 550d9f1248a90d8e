/* rigidsurf-frames: prints the contact frame of the globally closest feature of a
 * surface for each query point (the text of usage() says what it prints and writes).
 *
 * rdisp1 = -(x_s - x_m).n is the penetration of the point (> 0 behind the surface). A
 * point farther than --tracking in front of the surface (no limit by default), or owned
 * by no feature, prints 1e30 in every column. */
#include "rigidsurf/surface.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct frame_row {
    int found;
    double rdisp1, xm[3], n[3], t1[3], t2[3];
} frame_row;

typedef struct point_list {
    int n, cap;
    double *x, *y, *z;
} point_list;

/* The synopsis; with full (--help) what the program prints and writes. */
static void usage(FILE *f, int full)
{
    fprintf(f, "usage: rigidsurf-frames SURFACE_FILE [POINTS_FILE] [--name NAME] "
               "[--tracking D]\n"
               "                        [--vtk OUT.vtk]\n");
    if (!full)
        return;
    fprintf(
        f,
        "For each point (\"x y z\" a line, \"x y\" for SEGMENTS, '#' starts a comment;\n"
        "from POINTS_FILE or stdin) prints the frame of the surface's closest feature "
        "(%%.17g):\n"
        "  3D: rdisp1 xm ym zm n_x n_y n_z t1_x t1_y t1_z t2_x t2_y t2_z\n"
        "  2D: rdisp1 xm ym n_x n_y t1_x t1_y\n"
        "rdisp1 > 0 is a point behind the surface; (xm, ym, zm) is its closest point.\n"
        "  --name NAME    the surface NAME= of the file (default: the first)\n"
        "  --tracking D   a point more than D in front of the surface prints 1e30 in\n"
        "                 every column (default: no limit, every point gets a frame;\n"
        "                 a point behind it gets one at any depth)\n"
        "  --vtk OUT.vtk  also writes a legacy VTK polydata file: the surface's\n"
        "                 triangles (an arc a node per 5.625 degrees, 64 nodes around a\n"
        "                 REVOLUTION, a profile without EXTENT extruded to +-max(1, its\n"
        "                 largest coordinate)), and a vertex at the closest point of\n"
        "                 each point that got a frame, with the vectors n, t1, t2 as\n"
        "                 point data (zero on the surface's nodes)\n");
}

static int push_point(point_list *p, double x, double y, double z)
{
    if (p->n == p->cap) {
        int cap = p->cap ? 2 * p->cap : 256;
        double *nx = realloc(p->x, (size_t)cap * sizeof *nx);
        if (nx)
            p->x = nx;
        double *ny = realloc(p->y, (size_t)cap * sizeof *ny);
        if (ny)
            p->y = ny;
        double *nz = realloc(p->z, (size_t)cap * sizeof *nz);
        if (nz)
            p->z = nz;
        if (!nx || !ny || !nz)
            return -1;
        p->cap = cap;
    }
    p->x[p->n] = x;
    p->y[p->n] = y;
    p->z[p->n] = z;
    p->n++;
    return 0;
}

/* Reads whitespace-separated coordinates; ndim = 2 or 3. Returns 0 or prints an error
 * naming the source and line and returns 1. */
static int read_points(FILE *f, const char *origin, int ndim, point_list *pts)
{
    char line[4096];
    long lineno = 0;
    while (fgets(line, sizeof line, f)) {
        lineno++;
        size_t len = strlen(line);
        if (len == sizeof line - 1 && line[len - 1] != '\n' && !feof(f)) {
            fprintf(stderr, "rigidsurf-frames: %s:%ld: line longer than %zu characters\n",
                    origin, lineno, sizeof line - 2);
            return 1;
        }
        char *hash = strchr(line, '#');
        if (hash)
            *hash = '\0';
        double v[3] = {0.0, 0.0, 0.0};
        int nv = 0;
        char *s = line;
        for (;;) {
            while (isspace((unsigned char)*s))
                s++;
            if (!*s)
                break;
            if (nv == ndim) {
                fprintf(
                    stderr,
                    "rigidsurf-frames: %s:%ld: expected %d coordinates (%s), found more\n",
                    origin, lineno, ndim, ndim == 2 ? "x y" : "x y z");
                return 1;
            }
            char *end;
            errno = 0;
            double d = strtod(s, &end);
            if (end == s || (*end && !isspace((unsigned char)*end)) || !isfinite(d) ||
                fabs(d) > RS_COORD_MAX) {
                int w = 0;
                while (s[w] && !isspace((unsigned char)s[w]) && w < 40)
                    w++;
                fprintf(
                    stderr,
                    "rigidsurf-frames: %s:%ld: expected a finite number of magnitude at "
                    "most 1e100, got '%.*s'\n",
                    origin, lineno, w, s);
                return 1;
            }
            v[nv++] = d;
            s = end;
        }
        if (nv == 0)
            continue;
        if (nv != ndim) {
            fprintf(stderr,
                    "rigidsurf-frames: %s:%ld: expected %d coordinates (%s), found %d\n",
                    origin, lineno, ndim, ndim == 2 ? "x y" : "x y z", nv);
            return 1;
        }
        if (push_point(pts, v[0], v[1], v[2])) {
            fprintf(stderr, "rigidsurf-frames: out of memory reading %s\n", origin);
            return 1;
        }
    }
    if (ferror(f)) {
        fprintf(stderr, "rigidsurf-frames: %s: read error\n", origin);
        return 1;
    }
    return 0;
}

/* Picks, for each point, the contact with the smallest unsigned distance. */
static void closest_rows(const rs_contacts *c, int npts, frame_row *rows)
{
    double *best = malloc((size_t)(npts > 0 ? npts : 1) * sizeof *best);
    for (int i = 0; i < npts; i++) {
        rows[i].found = 0;
        if (best)
            best[i] = INFINITY;
    }
    for (int k = 0; k < c->n; k++) {
        int i = c->point[k];
        double d = fabs(c->dist[k]);
        if (rows[i].found && best && !(d < best[i]))
            continue;
        if (best)
            best[i] = d;
        frame_row *r = &rows[i];
        r->found = 1;
        r->rdisp1 = -c->dist[k];
        for (int a = 0; a < 3; a++) {
            r->xm[a] = c->xm[a][k];
            r->n[a] = c->nrm[a][k];
            r->t1[a] = c->t1[a][k];
            r->t2[a] = c->t2[a][k];
        }
    }
    free(best);
}

static void print_rows(const frame_row *rows, int npts, int ndir)
{
    for (int i = 0; i < npts; i++) {
        const frame_row *r = &rows[i];
        int ncol = ndir == 2 ? 7 : 13;
        double v[13];
        if (!r->found) {
            for (int a = 0; a < ncol; a++)
                v[a] = 1.0e30;
        } else if (ndir == 2) {
            double w[7] = {r->rdisp1, r->xm[0], r->xm[1], r->n[0],
                           r->n[1],   r->t1[0], r->t1[1]};
            memcpy(v, w, sizeof w);
        } else {
            double w[13] = {r->rdisp1, r->xm[0], r->xm[1], r->xm[2], r->n[0],
                            r->n[1],   r->n[2],  r->t1[0], r->t1[1], r->t1[2],
                            r->t2[0],  r->t2[1], r->t2[2]};
            memcpy(v, w, sizeof w);
        }
        for (int a = 0; a < ncol; a++)
            printf(a ? " %.17g" : "%.17g", v[a]);
        printf("\n");
    }
}

/* Legacy VTK polydata: the surface triangles, then one vertex per closest point carrying
 * the vectors n, t1, t2 (zero on the surface nodes). */
static int write_vtk(const char *path, const rs_surface *s, const frame_row *rows,
                     const point_list *pts, rs_error *err)
{
    double span = 1.0;
    for (int i = 0; i < s->profile.nseg; i++) {
        const rs_segment *g = &s->profile.seg[i];
        span = fmax(span, fmax(fmax(fabs(g->p0[0]), fabs(g->p0[1])),
                               fmax(fabs(g->p1[0]), fabs(g->p1[1]))));
    }
    rs_trimesh m = {0};
    if (rs_surface_triangulate(s, span, 64, &m, err))
        return err->code;
    int nfound = 0;
    for (int i = 0; i < pts->n; i++)
        nfound += rows[i].found;
    FILE *f = fopen(path, "w");
    if (!f) {
        rs_trimesh_free(&m);
        return rs_error_set(err, RS_ERR_IO, "%s: cannot open for writing: %s", path,
                            strerror(errno));
    }
    fprintf(f,
            "# vtk DataFile Version 3.0\nrigidsurf surface %s and contact frames\n"
            "ASCII\nDATASET POLYDATA\nPOINTS %d double\n",
            s->name, m.nvert + nfound);
    for (int v = 0; v < m.nvert; v++)
        fprintf(f, "%.17g %.17g %.17g\n", m.xyz[3 * v], m.xyz[3 * v + 1], m.xyz[3 * v + 2]);
    for (int i = 0; i < pts->n; i++)
        if (rows[i].found)
            fprintf(f, "%.17g %.17g %.17g\n", rows[i].xm[0], rows[i].xm[1], rows[i].xm[2]);
    if (nfound) {
        fprintf(f, "VERTICES %d %d\n", nfound, 2 * nfound);
        for (int i = 0; i < nfound; i++)
            fprintf(f, "1 %d\n", m.nvert + i);
    }
    fprintf(f, "POLYGONS %d %d\n", m.ntri, 4 * m.ntri);
    for (int t = 0; t < m.ntri; t++)
        fprintf(f, "3 %d %d %d\n", m.tri[3 * t], m.tri[3 * t + 1], m.tri[3 * t + 2]);
    fprintf(f, "POINT_DATA %d\n", m.nvert + nfound);
    static const char *names[3] = {"n", "t1", "t2"};
    for (int a = 0; a < 3; a++) {
        fprintf(f, "VECTORS %s double\n", names[a]);
        for (int v = 0; v < m.nvert; v++)
            fprintf(f, "0 0 0\n");
        for (int i = 0; i < pts->n; i++) {
            if (!rows[i].found)
                continue;
            const double *e = a == 0 ? rows[i].n : a == 1 ? rows[i].t1 : rows[i].t2;
            fprintf(f, "%.17g %.17g %.17g\n", e[0], e[1], e[2]);
        }
    }
    rs_trimesh_free(&m);
    if (fclose(f) != 0)
        return rs_error_set(err, RS_ERR_IO, "%s: write failed: %s", path, strerror(errno));
    return RS_OK;
}

int main(int argc, char **argv)
{
    const char *surface_file = NULL, *points_file = NULL, *name = NULL, *vtk = NULL;
    double tracking = INFINITY;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            usage(stdout, 1);
            return 0;
        } else if (!strcmp(a, "--name") || !strcmp(a, "--tracking") ||
                   !strcmp(a, "--vtk")) {
            if (i + 1 >= argc) {
                fprintf(stderr, "rigidsurf-frames: %s expects a value\n", a);
                return 2;
            }
            const char *v = argv[++i];
            if (!strcmp(a, "--name")) {
                name = v;
            } else if (!strcmp(a, "--vtk")) {
                vtk = v;
            } else {
                char *end;
                tracking = strtod(v, &end);
                if (end == v || *end || !(tracking >= 0.0) || !(tracking <= RS_COORD_MAX)) {
                    fprintf(
                        stderr,
                        "rigidsurf-frames: --tracking expects a number from 0 to 1e100, "
                        "got '%s'\n",
                        v);
                    return 2;
                }
            }
        } else if (a[0] == '-' && a[1] == '-') {
            fprintf(stderr, "rigidsurf-frames: unknown option '%s'\n", a);
            usage(stderr, 0);
            return 2;
        } else if (!surface_file) {
            surface_file = a;
        } else if (!points_file) {
            points_file = a;
        } else {
            fprintf(stderr, "rigidsurf-frames: unexpected argument '%s'\n", a);
            usage(stderr, 0);
            return 2;
        }
    }
    if (!surface_file) {
        usage(stderr, 0);
        return 2;
    }

    rs_error err;
    rs_error_clear(&err);
    rs_surface s;
    if (rs_surface_read(surface_file, name, &s, &err)) {
        fprintf(stderr, "rigidsurf-frames: %s\n", err.msg);
        return 1;
    }
    if (s.warning[0])
        fprintf(stderr, "rigidsurf-frames: warning: %s\n", s.warning);
    if (s.info[0])
        fprintf(stderr, "rigidsurf-frames: info: %s\n", s.info);
    int ndir = rs_surface_ndir(&s);

    point_list pts = {0};
    int rc;
    if (points_file) {
        FILE *f = fopen(points_file, "r");
        if (!f) {
            fprintf(stderr, "rigidsurf-frames: %s: cannot open: %s\n", points_file,
                    strerror(errno));
            rs_surface_free(&s);
            return 1;
        }
        rc = read_points(f, points_file, ndir, &pts);
        fclose(f);
    } else {
        rc = read_points(stdin, "<stdin>", ndir, &pts);
    }

    rs_contacts c = {0};
    frame_row *rows = NULL;
    if (rc == 0 && pts.n > 0) {
        rows = malloc((size_t)pts.n * sizeof *rows);
        rs_query q = {.n = pts.n,
                      .slave = {.x = pts.x, .y = pts.y, .z = pts.z, .radius = NULL},
                      .pose = NULL,
                      .gap_max = tracking,
                      .dist_min = -INFINITY};
        if (!rows || rs_contacts_reserve(&c, pts.n, &err) ||
            rs_surface_query(&s, &q, &c, &err)) {
            fprintf(stderr, "rigidsurf-frames: %s\n", rows ? err.msg : "out of memory");
            rc = 1;
        } else {
            closest_rows(&c, pts.n, rows);
            print_rows(rows, pts.n, ndir);
        }
    }
    if (rc == 0 && vtk && write_vtk(vtk, &s, rows, &pts, &err)) {
        fprintf(stderr, "rigidsurf-frames: %s\n", err.msg);
        rc = 1;
    }
    if (fflush(stdout) != 0 && rc == 0) {
        fprintf(stderr, "rigidsurf-frames: write error on standard output\n");
        rc = 1;
    }
    free(rows);
    rs_contacts_free(&c);
    free(pts.x);
    free(pts.y);
    free(pts.z);
    rs_surface_free(&s);
    return rc;
}
