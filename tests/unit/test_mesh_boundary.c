/* A MESH's open boundary as reading reports it (src/faceted/mesh_boundary.c): the rim of
 * an open surface (a plate, a box without its lid) is one line of s->info and no
 * warning; holes in a surface that otherwise closes (a box missing a small facet or two,
 * each narrower than RS_HOLE_FRACTION of the mesh) are a warning with their number and
 * the widest's width; a closed box reports nothing. */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */

#include "rigidsurf/surface.h"
#include "rs_test.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static char tmpdir[64];

enum { N = 10 }; /* quads along each side of a face */

/* The unit cube, each face a grid of N x N quads wound outward, less the quads listed
 * (face * N * N + row * N + column) and less the whole faces listed, as OFF; read. */
static int box(const int *skip, int nskip, const int *skip_face, int nfaces, rs_surface *s)
{
    char path[128];
    snprintf(path, sizeof path, "%s/box.off", tmpdir);
    FILE *f = fopen(path, "w");
    const int nq = 6 * N * N;
    char *keep = malloc((size_t)nq);
    int left = 0;
    for (int q = 0; q < nq; q++) {
        keep[q] = 1;
        for (int k = 0; k < nskip; k++)
            keep[q] &= skip[k] != q;
        for (int k = 0; k < nfaces; k++)
            keep[q] &= skip_face[k] != q / (N * N);
        left += keep[q];
    }
    fprintf(f, "OFF\n%d %d 0\n", 4 * nq, left);
    for (int face = 0; face < 6; face++) {
        const int axis = face / 2, u = (axis + 1) % 3, v = (axis + 2) % 3;
        const double side = face % 2 ? 1.0 : 0.0;
        for (int r = 0; r < N; r++)
            for (int c = 0; c < N; c++) {
                const double cu[4] = {c, c + 1, c + 1, c}, cv[4] = {r, r, r + 1, r + 1};
                for (int k = 0; k < 4; k++) {
                    double p[3];
                    p[axis] = side;
                    p[u] = cu[k] / N;
                    p[v] = cv[k] / N;
                    fprintf(f, "%.17g %.17g %.17g\n", p[0], p[1], p[2]);
                }
            }
    }
    for (int q = 0; q < nq; q++) {
        if (!keep[q])
            continue;
        const int b = 4 * q;
        if ((q / (N * N)) % 2) /* the face at 1 along its axis: u x v = +axis */
            fprintf(f, "4 %d %d %d %d\n", b, b + 1, b + 2, b + 3);
        else
            fprintf(f, "4 %d %d %d %d\n", b, b + 3, b + 2, b + 1);
    }
    fclose(f);
    free(keep);
    char text[160];
    snprintf(text, sizeof text, "%s/box.inp", tmpdir);
    f = fopen(text, "w");
    fprintf(f, "*SURFACE, TYPE=MESH, NAME=box, FILE=box.off\n");
    fclose(f);
    rs_error e;
    const int rc = rs_surface_read(text, NULL, s, &e);
    if (rc)
        fprintf(stderr, "%s\n", e.msg);
    return rc;
}

static void closed_box_reports_nothing(void)
{
    rs_surface s;
    ENSURE(box(NULL, 0, NULL, 0, &s) == RS_OK);
    ENSURE(s.warning[0] == '\0' && s.info[0] == '\0');
    rs_surface_free(&s);
}

static void holes_are_a_warning(void)
{
    rs_surface s;
    const int one[1] = {37};
    ENSURE(box(one, 1, NULL, 0, &s) == RS_OK);
    ENSURE(strstr(s.warning, "4 open boundary edges around 1 hole in a surface that "
                             "otherwise closes, the widest 0.141 across") != NULL);
    ENSURE(s.info[0] == '\0');
    rs_surface_free(&s);
    const int two[2] = {37, N * N + 55};
    ENSURE(box(two, 2, NULL, 0, &s) == RS_OK);
    ENSURE(strstr(s.warning, "8 open boundary edges around 2 holes") != NULL);
    ENSURE(s.info[0] == '\0');
    rs_surface_free(&s);
}

static void rims_are_information(void)
{
    rs_surface s;
    const int lid[1] = {5};
    ENSURE(box(NULL, 0, lid, 1, &s) == RS_OK);
    ENSURE(strstr(s.info, "an open surface: 40 open boundary edges on 1 rim, the widest "
                          "1.41 across") != NULL);
    ENSURE(s.warning[0] == '\0');
    rs_surface_free(&s);
    /* a box without its lid and with a hole in its floor: the rim makes it open */
    const int floor_hole[1] = {4 * N * N + 44};
    ENSURE(box(floor_hole, 1, lid, 1, &s) == RS_OK);
    ENSURE(strstr(s.info, "44 open boundary edges on 2 rims") != NULL);
    ENSURE(s.warning[0] == '\0');
    rs_surface_free(&s);
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/rs_boundaryXXXXXX");
    if (!mkdtemp(tmpdir))
        return 1;
    RS_RUN(closed_box_reports_nothing);
    RS_RUN(holes_are_a_warning);
    RS_RUN(rims_are_information);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    if (system(cmd) != 0)
        return 1;
    return rs_test_summary();
}
