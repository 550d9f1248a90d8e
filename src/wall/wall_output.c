/* The wall's outputs: the surface's VTK file in its current pose (with a mesh's facet
 * stress and wear as cell data), and the per-particle fields kept from the previous
 * increment (the temperature and the predefined fields whose increments the law gets). */
#define _POSIX_C_SOURCE 200809L /* stat, access */
#include "wall_impl.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define FAIL(...) return rs_error_set(err, RS_ERR_ARG, __VA_ARGS__)

void wall_update_previous_fields(rs_wall *w, const rs_wall_block *b)
{
    const int npred = b->pred ? w->npred : 0;
    if (!b->temp && npred == 0)
        return;
    const int tp = wall_tprev_at(w), pd = wall_pred_at(w);
    for (int i = 0; i < b->n; i++) {
        if (!wall_in_group(b, i))
            continue;
        double *r = wall_row(w, i);
        if (b->temp)
            r[tp] = b->temp[i];
        for (int a = 0; a < npred; a++)
            r[pd + a] = b->pred[a][i];
    }
}

/* The display mesh, and the VTK file's folder: rank 0 writes the files, so their folder
 * must exist and take files, and the name must not be a folder. Found there, every rank
 * stops with the same message. Collective. */
int wall_init_vtk(rs_wall *w, rs_error *err)
{
    const double *lo = w->run.box_lo, *hi = w->run.box_hi;
    const double span =
        sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
             (hi[2] - lo[2]) * (hi[2] - lo[2]));
    int rc = rs_surface_triangulate(w->surf, span, 72, &w->vtk_mesh, err);
    if (rc) {
        char msg[sizeof err->msg];
        snprintf(msg, sizeof msg, "%s", err->msg);
        return rs_error_set(err, rc, "keyword 'vtk': %s", msg);
    }
    w->vtk_mesh_ok = 1;
    int bad = 0;
    if (w->host.rank == 0) {
        const char *slash = strrchr(w->vtk_file, '/');
        char dir[4096];
        if (slash)
            snprintf(dir, sizeof dir, "%.*s", (int)(slash - w->vtk_file + 1), w->vtk_file);
        else
            snprintf(dir, sizeof dir, ".");
        struct stat st;
        errno = 0;
        if (stat(w->vtk_file, &st) == 0 && S_ISDIR(st.st_mode))
            bad = EISDIR;
        else if (access(dir, W_OK) != 0)
            bad = errno ? errno : EACCES;
    }
    bad = (int)wall_reduce1(w, bad, RS_REDUCE_MAX);
    if (bad)
        FAIL("keyword 'vtk': cannot write '%s': %s", w->vtk_file, strerror(bad));
    return RS_OK;
}

/* Legacy VTK polydata of the surface in its current pose; '*' in the name becomes the
 * step. Written by rank 0 (every rank holds the same surface and pose); a mesh's facets
 * carry their stress (and wear) as cell data, reduced first by every rank. */
int wall_write_vtk(rs_wall *w, long long step, rs_error *err)
{
    if (!w->vtk_mesh_ok)
        return RS_OK;
    const rs_trimesh *m = &w->vtk_mesh;
    const int cells = w->facets && m->cell, nf = w->nfacet;
    double *data = NULL;
    if (cells) {
        data = calloc(3 * (size_t)(nf > 0 ? nf : 1), sizeof *data);
        if (!data)
            return rs_error_set(err, RS_ERR_NOMEM, "out of memory for %d facets' stresses",
                                nf);
        const int rc = wall_reduce_facets(w, data, data + nf, data + 2 * (size_t)nf, err);
        if (rc) {
            free(data);
            return rc;
        }
    }
    if (w->host.rank != 0) {
        free(data);
        return RS_OK;
    }
    char name[4096];
    const char *star = strchr(w->vtk_file, '*');
    if (star)
        snprintf(name, sizeof name, "%.*s%lld%s", (int)(star - w->vtk_file), w->vtk_file,
                 step, star + 1);
    else
        snprintf(name, sizeof name, "%s", w->vtk_file);
    FILE *fp = fopen(name, "w");
    if (!fp) {
        free(data);
        return rs_error_set(err, RS_ERR_IO,
                            "keyword 'vtk': cannot open '%s' for writing: %s", name,
                            strerror(errno));
    }
    fprintf(fp,
            "# vtk DataFile Version 2.0\nfix wall/rigid %s step %lld\nASCII\nDATASET "
            "POLYDATA\nPOINTS %d double\n",
            w->id, step, m->nvert);
    for (int v = 0; v < m->nvert; v++) {
        double X[3];
        rs_pose_to_global(&w->motion->pose, &m->xyz[3 * v], X);
        fprintf(fp, "%.10g %.10g %.10g\n", X[0], X[1], X[2]);
    }
    fprintf(fp, "POLYGONS %d %d\n", m->ntri, 4 * m->ntri);
    for (int t = 0; t < m->ntri; t++)
        fprintf(fp, "3 %d %d %d\n", m->tri[3 * t], m->tri[3 * t + 1], m->tri[3 * t + 2]);
    if (cells) {
        fprintf(fp, "CELL_DATA %d\n", m->ntri);
        const char *names[3] = {"sigma_n", "sigma_t", "wear"};
        for (int a = 0; a < (w->wear ? 3 : 2); a++) {
            fprintf(fp, "SCALARS %s double 1\nLOOKUP_TABLE default\n", names[a]);
            for (int t = 0; t < m->ntri; t++)
                fprintf(fp, "%.17g\n", data[(size_t)a * nf + (size_t)m->cell[t]]);
        }
    }
    const int bad = ferror(fp);
    if (fclose(fp) != 0 || bad) {
        free(data);
        return rs_error_set(err, RS_ERR_IO, "keyword 'vtk': writing '%s' failed: %s", name,
                            strerror(errno));
    }
    free(data);
    return RS_OK;
}
