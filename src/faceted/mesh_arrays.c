/* The MESH kind from arrays in memory (rs_surface_make_mesh): a DEM code's own vertices
 * and triangles, checked as arguments, then placed and built as a mesh file's polygon
 * soup is (mesh_file.c, mesh_build.c). */
#include "cgal_mesh.h"
#include "mesh.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The definition's parameters, as the *SURFACE line's are checked. */
static int check_def(const rs_mesh_def *def, const char *origin, rs_error *err)
{
    const char *name = def->name ? def->name : "";
    const size_t len = strlen(name);
    if (len >= sizeof((rs_surface *)0)->name)
        return rs_error_set(err, RS_ERR_ARG, "%s: expected NAME= with 1 to 79 characters",
                            origin);
    for (size_t c = 0; c < len; c++)
        if (!isprint((unsigned char)name[c]))
            return rs_error_set(err, RS_ERR_ARG, "%s: expected a printable NAME=", origin);
    if (def->sides < 0 || def->sides > 2)
        return rs_error_set(err, RS_ERR_ARG,
                            "%s: sides = %d (expected SIDES=1 or SIDES=2, 0: the default)",
                            origin, def->sides);
    if (!(def->scale > 0.0) || !(def->scale <= RS_COORD_MAX))
        return rs_error_set(err, RS_ERR_ARG,
                            "%s: scale = %g (expected SCALE > 0, a finite number)", origin,
                            def->scale);
    if (def->placed)
        for (int i = 0; i < 9; i++)
            if (!(fabs(def->abc[i]) <= RS_COORD_MAX))
                return rs_error_set(err, RS_ERR_ARG,
                                    "%s: placement abc[%d] = %g (expected a finite number "
                                    "of magnitude at most 1e100)",
                                    origin, i, def->abc[i]);
    return RS_OK;
}

int rs_surface_make_mesh(const double *xyz, int nv, const int *tri, int nt,
                         const rs_mesh_def *def, rs_surface *s, rs_error *err)
{
    if (!s)
        return rs_error_set(err, RS_ERR_ARG, "rs_surface_make_mesh: NULL surface");
    memset(s, 0, sizeof *s);
    const rs_mesh_def dflt = RS_MESH_DEF_INIT;
    if (!def)
        def = &dflt;
    const char *origin = def->origin ? def->origin : "<arrays>";
    int rc = check_def(def, origin, err);
    if (rc)
        return rc;
    if (!xyz || !tri)
        return rs_error_set(err, RS_ERR_ARG, "%s: NULL %s array (expected %s)", origin,
                            !xyz ? "vertex" : "triangle",
                            !xyz ? "3 nv coordinates x, y, z" : "3 nt vertex indices");
    if (nv < 3)
        return rs_error_set(err, RS_ERR_ARG, "%s: nv = %d vertices (expected at least 3)",
                            origin, nv);
    if (nt < 1 || nt > RS_MESH_MAX_TRI)
        return rs_error_set(err, RS_ERR_ARG, "%s: nt = %d triangles (expected 1 to %d)",
                            origin, nt, RS_MESH_MAX_TRI);
    for (long k = 0; k < 3l * nt; k++)
        if (tri[k] < 0 || tri[k] >= nv)
            return rs_error_set(err, RS_ERR_ARG,
                                "%s: triangle %ld has vertex index %d (expected 0 to %d, "
                                "an index into the nv = %d vertices)",
                                origin, k / 3 + 1, tri[k], nv - 1, nv);
    double frame[4][3];
    rc = rs_mesh_placement(def->placed, def->abc, origin, frame, err);
    if (rc)
        return rc;
    /* The soup points at the caller's arrays, which rs_mesh_build only reads (it takes
     * the soup const); each polygon is one triangle. */
    rs_soup soup = {nv,         nt,  (double *)xyz, malloc(((size_t)nt + 1) * sizeof(int)),
                    (int *)tri, NULL};
    if (!soup.off)
        return rs_error_set(err, RS_ERR_NOMEM, "%s: out of memory building the mesh",
                            origin);
    for (int f = 0; f <= nt; f++)
        soup.off[f] = 3 * f;
    snprintf(s->name, sizeof s->name, "%s", def->name ? def->name : "");
    s->sides = def->sides;
    rc = rs_mesh_surface_soup(s, &soup, def->scale, (const double(*)[3])frame, 2, origin,
                              err);
    free(soup.off);
    if (rc)
        memset(s, 0, sizeof *s);
    else
        rs_error_clear(err);
    return rc;
}
